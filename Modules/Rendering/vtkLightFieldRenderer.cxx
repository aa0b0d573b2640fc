#include "vtkLightFieldRenderer.h"

#include "lfdRequestGuard.h"

#include "lfdCylinderSampling.h"
#include "lfdLimits.h"
#include "lfdPinholeCamera.h"
#include "lfdRenderView.h"
#include "lfdTessellation.h"
#include "lfdTwoPlaneSampling.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldTexelSource.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScanlineSplit.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLightFieldRenderer);
vtkCxxSetObjectMacro(vtkLightFieldRenderer, Camera, vtkCamera);

namespace
{
/**
 * The side of the label hull's screen tiles (lfd::LabelHull::ScreenTiles) in
 * tiles of the frame cage (lfd::FrameCage::DefaultTileSize): the cage's
 * finer tiles list fewer boxes per ray, while the hull's test per tile costs
 * more than finer tiles skip.
 */
constexpr int MaskTileScale = 2;

/**
 * An lfd::RangeLoop over every thread (vtkSMPTools::For): the frame cage's
 * loops over boxes and tile-box pairs, the depth stack's over views. A
 * loop of a few iterations runs where it is (the bent 100-slab fish's
 * cage took 0.84 ms on one thread, most of it its 6 500 tile-box pairs).
 */
void EveryThread(std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (n < 64)
  {
    body(0, n);
    return;
  }
  vtkSMPTools::For(0,
    static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    { body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end)); });
}

/**
 * The boxes of a cage grid as RENDER_VIEW takes them, untessellated. False
 * (with an error on `self` naming the box) when a cell is not a hexahedron of
 * existing points or its label is outside 1..255.
 */
bool ReadBoxes(vtkObject* self, vtkDeformationCage* cage, std::vector<lfd::RenderBox>& boxes)
{
  const vtkIdType count = cage->GetNumberOfBoxes();
  boxes.resize(count);
  for (vtkIdType b = 0; b < count; ++b)
  {
    double rest[24], deformed[24];
    if (!cage->GetRestCorners(b, rest) || !cage->GetDeformedCorners(b, deformed))
    {
      vtkErrorWithObjectMacro(
        self, "Cage cell " << b << " is not a hexahedron of 8 existing points.");
      return false;
    }
    const int label = cage->GetBoxLabel(b);
    if (label < 1 || label > 255)
    {
      vtkErrorWithObjectMacro(
        self, "Box " << b << " has label " << label << "; labels are 1..255.");
      return false;
    }
    boxes[b] =
      lfd::MakeRenderBox(lfd::HexahedronFromArray(rest), lfd::HexahedronFromArray(deformed), label);
  }
  return true;
}

/**
 * The length that `pixels` pixels of `eye`'s image span at the deformed box
 * `box`: at its nearest corner, or at the box's own size when the eye is
 * nearer than that (an eye inside a box would ask for no error at all).
 */
double PixelLength(const lfd::PinholeCamera& eye, const lfd::Hexahedron& box, double pixels)
{
  double nearest = lfd::BoxSize(box);
  double distance = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& corner : box.Corners)
  {
    distance = std::min(distance, glm::distance(corner, eye.Center()));
  }
  const double focal = std::max(eye.K[0][0], eye.K[1][1]);
  return pixels * std::max(distance, nearest) / focal;
}

/**
 * The k of every box: `subdivision`, or with 0 (auto) lfd::AutomaticSubdivision
 * for a warp deviation of `tolerance` pixels of `eye` at the box, lowered to
 * fit lfd::MaximumSubBoxes. False (with an error on `self`) when the
 * tessellation is over that budget.
 */
bool ChooseSubdivisions(vtkObject* self,
  const std::vector<lfd::RenderBox>& boxes,
  int subdivision,
  double tolerance,
  const lfd::PinholeCamera& eye,
  std::vector<int>& ks)
{
  ks.assign(boxes.size(), subdivision);
  if (subdivision == 0)
  {
    for (std::size_t b = 0; b < boxes.size(); ++b)
    {
      ks[b] = lfd::AutomaticSubdivision(
        boxes[b].Rest, boxes[b].Deformed, PixelLength(eye, boxes[b].Deformed, tolerance));
    }
    lfd::FitSubdivisionBudget(ks, lfd::MaximumSubBoxes);
  }
  const long long subBoxes = lfd::CountSubBoxes(ks);
  if (subBoxes > lfd::MaximumSubBoxes)
  {
    vtkErrorWithObjectMacro(self,
      "Subdivision " << (subdivision ? std::to_string(subdivision) : std::string("auto"))
                     << " (render.subdivision) splits the cage's " << boxes.size() << " boxes into "
                     << subBoxes << " sub-boxes, above the budget of " << lfd::MaximumSubBoxes
                     << " (every ray tests every sub-box): "
                     << (subdivision > 1 ? "lower it" : "use fewer boxes") << ".");
    return false;
  }
  return true;
}

/**
 * The boxes of a cage grid, each tessellated into subdivision^3 sub-boxes
 * (subdivision 0: chosen per box, see ChooseSubdivisions; the k of each box
 * into `ks`). False (with an
 * error on `self`) when the subdivision is out of range, the grid is
 * malformed or the tessellation is over the budget of lfdLimits.h.
 */
bool CollectBoxes(vtkObject* self,
  vtkDeformationCage* cage,
  int subdivision,
  double tolerance,
  const lfd::PinholeCamera& eye,
  std::vector<int>& ks,
  std::vector<lfd::RenderBox>& boxes)
{
  if (subdivision < 0 || subdivision > lfd::MaximumSubdivision)
  {
    vtkErrorWithObjectMacro(self,
      "Subdivision " << subdivision << " (render.subdivision) is outside [1, "
                     << lfd::MaximumSubdivision << "] (0 = auto): one box at k "
                     << lfd::MaximumSubdivision << " already makes " << lfd::MaximumSubBoxes
                     << " sub-boxes, the budget of a cage (lfd::MaximumSubBoxes).");
    return false;
  }
  std::vector<lfd::RenderBox> whole;
  if (!ReadBoxes(self, cage, whole) ||
    !ChooseSubdivisions(self, whole, subdivision, tolerance, eye, ks))
  {
    return false;
  }
  boxes.reserve(static_cast<std::size_t>(lfd::CountSubBoxes(ks)));
  for (std::size_t b = 0; b < whole.size(); ++b)
  {
    lfd::Tessellate(whole[b], ks[b], boxes);
  }
  return true;
}

/// One ray per pixel through lfd::RenderView (paper Sec. 6), rows in parallel,
/// the light field looked up through `Lookup` (ring or two-plane).
template<typename Lookup>
struct RenderRows
{
  const Lookup& Light;
  const lfd::FrameCage& Cage; // the eye, its pixels' rays and the boxes they may meet
  const lfd::RenderViewSettings& Settings;
  bool Accelerated; // through Cage, or every ray through every box
  int Width;
  int Height;
  std::uint8_t Background[3];
  std::uint8_t* Radiance; // output, VTK row order
  std::uint8_t* Labels;
  float* Depths;
  // The scratch space of the rays of a batch (lfd::RenderWalks), reused
  // from batch to batch by each thread.
  mutable vtkSMPThreadLocal<std::array<lfd::FrameRayScratch, lfd::MaximumPlainBatch>> Scratch;
  // The screen-tile mask (lfd::LabelHull::ScreenTiles over the tiles of
  // Cage, FrameCage::TileSize pixels, row after row): a tile marked 0 is
  // background without generating its rays. Empty: every ray is generated.
  std::vector<std::uint8_t> Tiles;
  // Width pixels of Background, RGB (WriteBackground).
  std::vector<std::uint8_t> BackgroundRow;

  /**
   * The rows [begin, end), tile by tile: tiles that are all background are
   * written as such without a ray, each run of them along the row at once
   * (the mask's tiles, and with RenderViewSettings::AllOwned those that
   * list no box); a tile that lists no box has all its rays batched; the
   * rays of consecutive tiles that list one go to lfd::RenderWalks up to
   * lfd::MaximumPlainBatch at once, and those whose walk finds no box are
   * batched. Tile by tile, a pixel costs no division or test of its own
   * (the 3-box swim's frame 154.3 -> 142.8 M instructions, the fish at rest
   * 98.5 -> 94.6 M).
   */
  void operator()(vtkIdType begin, vtkIdType end) const
  {
    std::array<lfd::FrameRayScratch, lfd::MaximumPlainBatch>& scratch = this->Scratch.Local();
    const int tileSize = this->Cage.TileSize;
    // Rays that no box may claim go through lfd::RenderPlainViews in
    // batches: all of them in a frame without boxes (or labels), else those
    // of the tiles that list no box and those whose walk finds none.
    const bool plain = !this->Settings.UseLabels || this->Cage.Boxes->empty();
    // (They are background when every part has a box.)
    const bool owned = !plain && this->Settings.AllOwned;
    int batch[lfd::MaximumPlainBatch];
    lfd::ViewSample batchSeen[lfd::MaximumPlainBatch];
    int walks[lfd::MaximumPlainBatch];
    lfd::ViewSample walkSeen[lfd::MaximumPlainBatch];
    bool walked[lfd::MaximumPlainBatch];
    for (vtkIdType j = begin; j < end; ++j)
    {
      const int y = static_cast<int>(this->Height - 1 - j); // OpenCV row
      const vtkIdType row = j * this->Width;
      const std::uint8_t* tiles =
        this->Tiles.empty() ? nullptr : this->Tiles.data() + (y / tileSize) * this->Cage.TilesX;
      int batched = 0;
      const auto renderBatch = [&]
      {
        lfd::RenderPlainViews(
          this->Cage, batch, y, batched, this->Light, this->Settings, batchSeen);
        for (int i = 0; i < batched; ++i)
        {
          this->Write(row + batch[i], batchSeen[i]);
        }
        batched = 0;
      };
      const auto addToBatch = [&](int x)
      {
        batch[batched++] = x;
        if (batched == lfd::MaximumPlainBatch)
        {
          renderBatch();
        }
      };
      // The rays of consecutive tiles that list a box, walked in batches of
      // up to lfd::MaximumPlainBatch (a tile row at a time, a batch held at
      // most 8 rays: its first lookups were aimed in half-empty vectors);
      // those whose walk finds no box join the plain batch, in order.
      int walking = 0;
      const auto renderWalks = [&]
      {
        if (walking == 0)
        {
          return;
        }
        lfd::RenderWalks(this->Cage,
          walks,
          y,
          walking,
          this->Light,
          this->Settings,
          scratch.data(),
          walkSeen,
          walked);
        for (int i = 0; i < walking; ++i)
        {
          if (walked[i])
          {
            this->Write(row + walks[i], walkSeen[i]);
          }
          else
          {
            addToBatch(walks[i]);
          }
        }
        walking = 0;
      };
      // (A call per tile wrote 8 pixels through three library calls: about
      // 1 M instructions of the 3-box swim's frame.)
      int background = -1; // the first pixel of the run of background tiles before x0
      const auto writeBackground = [&](int x1)
      {
        if (background >= 0)
        {
          this->WriteBackground(row + background, x1 - background);
          background = -1;
        }
      };
      for (int x0 = 0, tile = 0; x0 < this->Width; x0 += tileSize, ++tile)
      {
        const int x1 = std::min(x0 + tileSize, this->Width);
        const bool boxes = !plain && (!this->Accelerated || this->Cage.CountCandidates(x0, y) > 0);
        if ((tiles && !tiles[tile]) || (owned && !boxes))
        {
          background = background < 0 ? x0 : background;
          continue;
        }
        writeBackground(x0);
        if (!boxes)
        {
          renderWalks(); // (the plain batch takes its rays in ascending order)
          for (int x = x0; x < x1; ++x)
          {
            addToBatch(x);
          }
          continue;
        }
        if (!this->Accelerated)
        {
          for (int x = x0; x < x1; ++x)
          {
            this->Write(row + x,
              lfd::RenderView(this->Cage.Eye,
                this->Cage.Direction(x, y),
                *this->Cage.Boxes,
                this->Light,
                this->Settings,
                scratch[0].Segments));
          }
          continue;
        }
        for (int x = x0; x < x1; ++x)
        {
          walks[walking++] = x;
          if (walking == lfd::MaximumPlainBatch)
          {
            renderWalks();
          }
        }
      }
      writeBackground(this->Width);
      renderWalks();
      renderBatch();
    }
  }

  /// Writes what the ray of pixel `id` (VTK order) sees.
  void Write(vtkIdType id, const lfd::ViewSample& seen) const
  {
    std::uint8_t* rgb = this->Radiance + 3 * id;
    this->Labels[id] = static_cast<std::uint8_t>(std::max(seen.Label, 0));
    const bool background = seen.Label < 0 || (this->Settings.UseLabels && seen.Label == 0);
    // A ray's camera z is 1, so the ray parameter of the seen point is its depth.
    this->Depths[id] = background ? 0.0f : static_cast<float>(seen.Depth);
    if (background && seen.Coverage == 0.0)
    {
      // Byte by byte: std::copy of 3 bytes became a memcpy call per
      // background pixel (4 M instructions of a 512x512 frame).
      rgb[0] = this->Background[0];
      rgb[1] = this->Background[1];
      rgb[2] = this->Background[2];
      return;
    }
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = static_cast<std::uint8_t>(lfd::RoundHalfAway(std::clamp(seen.Color[c], 0.0, 255.0)));
    }
  }

  /// Writes background, as Write() does for a ray that shows it, into the
  /// `count` <= Width pixels from `id` (VTK order), copied from BackgroundRow.
  void WriteBackground(vtkIdType id, int count) const
  {
    std::fill_n(this->Labels + id, count, std::uint8_t{ 0 });
    std::fill_n(this->Depths + id, count, 0.0f);
    std::copy_n(this->BackgroundRow.data(), 3 * count, this->Radiance + 3 * id);
  }
};

/// What holds the pass `pass` of `lightField`: its array, or else the
/// texel source serving it (out of core); the key of what the renderer
/// caches per pass (proxy extent, label hull).
vtkObject* PassHolder(vtkLightField* lightField, int pass)
{
  vtkObject* array = lightField->GetPass(pass);
  return array ? array : lightField->GetTexelSource();
}

/// The pass `pass` of `lightField` (values of type T, `components`
/// components) as the samplers read it: its array, or else its texels
/// through the light field's texel source (out of core); not Present() when
/// it has neither.
template<typename T>
lfd::ViewStack<T> PassStack(vtkLightField* lightField, int pass, int components)
{
  lfd::ViewStack<T> stack{ nullptr, lightField->GetWidth(), lightField->GetHeight(), components };
  auto* array = vtkAOSDataArrayTemplate<T>::FastDownCast(lightField->GetPass(pass));
  if (array && array->GetNumberOfComponents() == components)
  {
    stack.Data = array->GetPointer(0);
  }
  else if (vtkLightFieldTexelSource* source = lightField->GetTexelSource())
  {
    stack.Source = source->GetTexels(pass);
  }
  return stack;
}

/// The input's RGB uint8 Coaxial pass when the input can be rendered (its
/// rig has a camera per view); not Present() after an error on `self`.
lfd::ViewStack<std::uint8_t> RenderableRadiance(vtkObject* self, vtkLightField* input)
{
  if (!input)
  {
    vtkErrorWithObjectMacro(self, "The input is not a vtkLightField.");
    return {};
  }
  const lfd::ViewStack<std::uint8_t> radiance =
    PassStack<std::uint8_t>(input, vtkLightField::COAXIAL, 3);
  if (!radiance.Present())
  {
    vtkErrorWithObjectMacro(
      self, "The light field has no RGB uint8 'Coaxial' pass to render from.");
    return {};
  }
  vtkCameraRig* rig = input->GetRig();
  const int views = input->GetNumberOfViews();
  if (!rig || rig->GetNumberOfViews() != views)
  {
    vtkErrorWithObjectMacro(self,
      "The light field has " << views << " views but its rig has "
                             << (rig ? rig->GetNumberOfViews() : 0) << " cameras.");
    return {};
  }
  return radiance;
}

/// The cage on port 1 as a vtkDeformationCage (a plain grid, or one without
/// rest positions, is a cage at rest); nullptr after an error on `self`.
vtkSmartPointer<vtkDeformationCage> ReadCage(vtkObject* self, vtkUnstructuredGrid* grid)
{
  const std::string refused = vtkDeformationCage::CheckGridArrays(grid);
  if (!refused.empty())
  {
    vtkErrorWithObjectMacro(self, "Input port 1: " << refused << ".");
    return nullptr;
  }
  // A plain grid (or one without rest positions: at rest) is read as a cage.
  vtkSmartPointer<vtkDeformationCage> cage = vtkDeformationCage::SafeDownCast(grid);
  if (!cage || !cage->GetRestPositions())
  {
    cage = vtkSmartPointer<vtkDeformationCage>::New();
    cage->InitializeFromGrid(grid);
  }
  return cage;
}

/// True when every label that `lightField` holds has a box.
bool OwnsEveryPart(const lfd::RenderViewSettings& settings, vtkLightField* lightField)
{
  for (int label = 1; label < 256; ++label)
  {
    if (!settings.Owned[label] && lightField->HasLabel(label))
    {
      return false;
    }
  }
  return true;
}

/// What a frame is rendered with, besides the light field and the cage,
/// and into which arrays.
struct FrameSettings
{
  bool Accelerated; // through the frame cage, or every ray through every box
  int Width;
  int Height;
  std::uint8_t Background[3];
  std::uint8_t* Radiance; // Width x Height RGB, VTK row order
  std::uint8_t* Labels;
  float* Depths;
};

/**
 * `array` (the renderer's array of one output pass, named `name`) sized for
 * `tuples` pixels of `components` values and marked modified: the previous
 * frame's when nothing but the renderer and `output` still holds it,
 * otherwise a new array. A frame's arrays are 2 MB at 512x512, and glibc
 * gives blocks that large back to the kernel when they are freed (mmap, or
 * the top of the heap trimmed): allocated anew, they faulted in 480 fresh
 * pages every other frame, about 5 of a 512x512 frame's 20 ms of CPU on a
 * virtual machine (README, Benchmarks). Every pixel is written (RenderRows),
 * so the previous frame's values never show.
 */
template<typename ArrayT>
ArrayT* FrameArray(vtkSmartPointer<ArrayT>& array,
  vtkImageData* output,
  const char* name,
  int components,
  vtkIdType tuples)
{
  // vtkImageData::PrepareForNewData keeps the output's scalars, and drops
  // its other arrays, before the request.
  const bool outputHolds = output->GetPointData()->GetAbstractArray(name) == array.Get();
  if (!array || array->GetReferenceCount() != (outputHolds ? 2 : 1))
  {
    array = vtkSmartPointer<ArrayT>::New();
    array->SetName(name);
  }
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  array->Modified();
  return array;
}

/// Renders `frame`'s arrays through `cage`, one ray per pixel looked up
/// through `lookup` (ring or two-plane), rows in parallel.
template<typename Lookup>
void RenderFrame(const Lookup& lookup,
  const lfd::FrameCage& cage,
  const lfd::RenderViewSettings& settings,
  const FrameSettings& frame,
  std::vector<std::uint8_t> tiles = {})
{
  RenderRows<Lookup> functor{ lookup,
    cage,
    settings,
    frame.Accelerated,
    frame.Width,
    frame.Height,
    { frame.Background[0], frame.Background[1], frame.Background[2] },
    frame.Radiance,
    frame.Labels,
    frame.Depths,
    {},
    std::move(tiles) };
  functor.BackgroundRow.resize(3 * static_cast<std::size_t>(frame.Width));
  for (std::size_t i = 0; i < functor.BackgroundRow.size(); ++i)
  {
    functor.BackgroundRow[i] = frame.Background[i % 3];
  }
  vtkSMPTools::For(0, frame.Height, functor);
}
}

//------------------------------------------------------------------------------
struct vtkLightFieldRenderer::RigViews
{
  lfd::TwoPlaneLayout Plane;
  lfd::RingLayout Ring; // (empty with a two-plane grid)
  std::vector<lfd::PinholeCamera> Cameras;
  std::vector<lfd::ProjectionMatrix> Projections;
};

//------------------------------------------------------------------------------
vtkLightFieldRenderer::vtkLightFieldRenderer()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer::~vtkLightFieldRenderer()
{
  this->SetCamera(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetPinhole(const double K[9], const double R[9], const double t[3])
{
  std::copy(K, K + 9, this->PinholeK);
  std::copy(R, R + 9, this->PinholeR);
  std::copy(t, t + 3, this->PinholeT);
  this->SetCamera(nullptr);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::AddExcludedView(int view)
{
  this->ExcludedViews.push_back(view);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::RemoveAllExcludedViews()
{
  if (!this->ExcludedViews.empty())
  {
    this->ExcludedViews.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::GetNumberOfExcludedViews() const
{
  return static_cast<int>(this->ExcludedViews.size());
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldRenderer::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Camera)
  {
    mtime = std::max(mtime, this->Camera->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetCageData(vtkUnstructuredGrid* cage)
{
  this->SetInputDataInternal(1, cage);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::SetCageConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  if (this->Width < 1 || this->Width > lfd::MaximumRenderSize || this->Height < 1 ||
    this->Height > lfd::MaximumRenderSize)
  {
    vtkErrorMacro("Output size " << this->Width << " x " << this->Height
                                 << " is outside the render size limits: width and height in [1, "
                                 << lfd::MaximumRenderSize << "] (lfd::MaximumRenderSize).");
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Any view may be sampled: ask for the whole light field.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
    6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  const lfd::ViewStack<std::uint8_t> radiance = RenderableRadiance(this, input);
  if (!radiance.Present())
  {
    return 0;
  }
  vtkCameraRig* rig = input->GetRig();
  const RigViews& views = this->GetRigViews(rig);
  const lfd::TwoPlaneLayout& plane = views.Plane;
  const lfd::RingLayout& layout = views.Ring;
  if (plane.Empty() && layout.Rows.empty())
  {
    vtkErrorMacro("No cylinder could be fitted to the rig, or every view is excluded.");
    return 0;
  }
  if (!plane.Empty() &&
    std::all_of(plane.View.begin(), plane.View.end(), [](int v) { return v < 0; }))
  {
    vtkErrorMacro("Every view of the two-plane grid is excluded.");
    return 0;
  }
  double K[9], R[9], t[3];
  this->GetEyePinhole(K, R, t);
  const lfd::PinholeCamera eye = lfd::PinholeCamera::FromRowMajor(K, R, t);
  std::vector<lfd::RenderBox> boxes;
  this->LastSubdivisions.clear();
  vtkLightField* lightField = input; // the input, or its one-part split
  if (vtkUnstructuredGrid* grid = vtkUnstructuredGrid::GetData(inputVector[1]))
  {
    vtkSmartPointer<vtkDeformationCage> cage = ReadCage(this, grid);
    if (!cage ||
      !CollectBoxes(this,
        cage,
        this->Subdivision,
        this->SubdivisionTolerance,
        eye,
        this->LastSubdivisions,
        boxes))
    {
      return 0;
    }
    lightField = this->LightFieldOfCage(input, cage, boxes.empty() ? 0 : boxes.front().Label);
    if (!lightField)
    {
      return 0;
    }
  }
  const std::vector<lfd::PinholeCamera>& cameras = views.Cameras;
  const std::vector<lfd::ProjectionMatrix>& projections = views.Projections;
  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Projections = projections.empty() ? nullptr : projections.data();
  sampler.Radiance = radiance;
  const lfd::ViewStack<std::uint8_t> labels =
    PassStack<std::uint8_t>(lightField, vtkLightField::LABEL, 1);
  lfd::RenderViewSettings settings;
  settings.UseLabels = this->UseLabels && labels.Present();
  if (settings.UseLabels)
  {
    sampler.Labels = labels;
  }
  sampler.FocalDistance = this->FocalDistance;
  const lfd::ViewStack<float> depth = PassStack<float>(input, vtkLightField::DEPTH, 1);
  if (this->FocalSurface == FOCAL_PROXY && !depth.Present())
  {
    vtkErrorMacro("The focal surface is the proxy (render.focal: proxy) but the light field has "
                  "no float Depth pass: compute one with `lfd proxy`.");
    return 0;
  }
  std::vector<glm::dvec3> centers;
  if (this->FocalSurface != FOCAL_PLANE && depth.Present())
  {
    sampler.Depth = depth;
    const std::vector<double>& extent =
      this->GetProxyExtent(PassHolder(input, vtkLightField::DEPTH), depth, rig, cameras);
    sampler.DepthRange = extent.data() + 6;
    sampler.SurfaceLow = glm::dvec3(extent[0], extent[1], extent[2]);
    sampler.SurfaceHigh = glm::dvec3(extent[3], extent[4], extent[5]);
    sampler.DepthTiles = this->ProxyTiles.get();
    sampler.ProxyViews = this->ProxyViews;
    std::transform(cameras.begin(),
      cameras.end(),
      std::back_inserter(centers),
      [](const lfd::PinholeCamera& camera) { return camera.Center(); });
    sampler.CameraCenters = centers.data();
  }
  // With labels, the hull skips the rays that can meet no part, through the
  // plane and through the proxy alike (lfd::LightFieldSampler::Gather).
  if (settings.UseLabels && plane.Empty())
  {
    sampler.Hull = &this->GetLabelHull(
      PassHolder(lightField, vtkLightField::LABEL), labels, rig, layout, cameras);
  }
  // Without a proxy a ring lookup samples every line at its focal cylinder:
  // runs of a moved part's intervals are looked up from their focal piece.
  settings.FocalBeforeLookup = plane.Empty() && !sampler.Depth.Present();
  settings.WidenedSearch = this->WidenedSearch > 0;
  settings.AntiAliasing = this->AntiAliasing;
  settings.Owned = lfd::OwnedLabels(boxes);
  // With a cage, a ray that no box claims shows the parts without a box;
  // when every part of the light field has one, it shows background.
  settings.AllOwned = settings.UseLabels && !boxes.empty() && OwnsEveryPart(settings, lightField);

  lfd::PlaceEye(boxes, eye.Center());
  lfd::FrameCage cage;
  // (The cage's loops on every thread, as the frame's rows.)
  cage.Build(boxes,
    eye.Center(),
    eye.PixelToDirection(),
    this->Width,
    this->Height,
    lfd::FrameCage::DefaultTileSize,
    EveryThread);
  this->AllocateOutput(vtkImageData::GetData(outputVector));
  FrameSettings frame{ this->CageAcceleration,
    this->Width,
    this->Height,
    {},
    this->FrameRadiance->GetPointer(0),
    this->FrameLabels->GetPointer(0),
    this->FrameDepths->GetPointer(0) };
  for (int c = 0; c < 3; ++c)
  {
    frame.Background[c] =
      static_cast<std::uint8_t>(std::clamp(std::lround(255.0 * this->Background[c]), 0L, 255L));
    settings.Background[c] = frame.Background[c];
  }
  if (!plane.Empty())
  {
    const lfd::TwoPlaneSampler twoPlane{
      &plane, cameras.data(), sampler.Radiance, sampler.Labels, this->FocalDepth, this->Aperture
    };
    RenderFrame(lfd::TwoPlaneLookup{ twoPlane, eye.Forward() }, cage, settings, frame);
  }
  else
  {
    // Undeformed, every ray is the view ray itself: the tiles whose rays the
    // hull skips all are background. Deformed, so is every ray of a tile
    // that lists no box (the frame cage's tiles are the same): it meets no
    // box, and is looked up undeformed, or is background when every label
    // has its box (RenderViewSettings::AllOwned). The 3-box swim then
    // generates 116 000 of its 262 000 rays (226.9 -> 208.1 M instructions).
    std::vector<std::uint8_t> tiles;
    if (sampler.Hull)
    {
      // The hull's tiles are MaskTileScale x MaskTileScale of the cage's.
      const int side = MaskTileScale * cage.TileSize;
      const std::vector<std::uint8_t>& mask =
        this->GetHullTiles(*sampler.Hull, layout, eye, sampler, side);
      const int maskColumns = (this->Width + side - 1) / side;
      tiles.resize(static_cast<std::size_t>(cage.TilesX) * cage.TilesY);
      for (std::size_t t = 0; t < tiles.size(); ++t)
      {
        const int tx = static_cast<int>(t) % cage.TilesX, ty = static_cast<int>(t) / cage.TilesX;
        tiles[t] = mask[(ty / MaskTileScale) * maskColumns + tx / MaskTileScale] |
          (cage.TileStart[t] != cage.TileStart[t + 1]);
      }
    }
    RenderFrame(lfd::SamplerLookup{ sampler, this->WidenedSearch, eye.Forward() },
      cage,
      settings,
      frame,
      std::move(tiles));
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::GetLastSubdivision(int box) const
{
  return box >= 0 && box < static_cast<int>(this->LastSubdivisions.size())
    ? this->LastSubdivisions[box]
    : 0;
}

//------------------------------------------------------------------------------
int vtkLightFieldRenderer::GetLastMaximumSubdivision() const
{
  return this->LastSubdivisions.empty()
    ? 0
    : *std::max_element(this->LastSubdivisions.begin(), this->LastSubdivisions.end());
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::GetEyePinhole(double K[9], double R[9], double t[3])
{
  if (this->Camera)
  {
    vtkCameraRig::CameraToPinhole(this->Camera, this->Width, this->Height, K, R, t);
    return;
  }
  std::copy(this->PinholeK, this->PinholeK + 9, K);
  std::copy(this->PinholeR, this->PinholeR + 9, R);
  std::copy(this->PinholeT, this->PinholeT + 3, t);
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::AllocateOutput(vtkImageData* output)
{
  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  const vtkIdType pixels = static_cast<vtkIdType>(this->Width) * this->Height;
  output->GetPointData()->SetScalars(
    FrameArray(this->FrameRadiance, output, "Radiance", 3, pixels));
  output->GetPointData()->AddArray(FrameArray(this->FrameLabels, output, "Label", 1, pixels));
  output->GetPointData()->AddArray(FrameArray(this->FrameDepths, output, "Depth", 1, pixels));
}

//------------------------------------------------------------------------------
const std::vector<double>& vtkLightFieldRenderer::GetProxyExtent(vtkObject* holder,
  const lfd::ViewStack<float>& stack,
  vtkCameraRig* rig,
  const std::vector<lfd::PinholeCamera>& cameras)
{
  if (holder != this->ProxyExtentArray || holder->GetMTime() > this->ProxyExtentTime ||
    rig->GetMTime() > this->ProxyExtentTime)
  {
    const int views = static_cast<int>(cameras.size());
    glm::dvec3 low, high;
    if (!lfd::DepthBounds(stack, cameras.data(), views, low, high, EveryThread))
    {
      low = high = glm::dvec3(0.0); // no surface: every ray misses it
    }
    this->ProxyExtent = { low.x, low.y, low.z, high.x, high.y, high.z };
    const std::vector<double> ranges = lfd::DepthRanges(stack, views, EveryThread);
    this->ProxyExtent.insert(this->ProxyExtent.end(), ranges.begin(), ranges.end());
    this->ProxyTiles = std::make_unique<lfd::NearestDepthTiles>();
    this->ProxyTiles->Build(stack, views, EveryThread);
    this->ProxyExtentArray = holder;
    this->ProxyExtentTime.Modified();
  }
  return this->ProxyExtent;
}

//------------------------------------------------------------------------------
const lfd::LabelHull& vtkLightFieldRenderer::GetLabelHull(vtkObject* holder,
  const lfd::ViewStack<std::uint8_t>& labels,
  vtkCameraRig* rig,
  const lfd::RingLayout& layout,
  const std::vector<lfd::PinholeCamera>& cameras)
{
  if (!this->Hull || holder != this->HullArray || holder->GetMTime() > this->HullTime ||
    rig->GetMTime() > this->HullTime || this->ExcludedViews != this->HullExcludedViews)
  {
    this->Hull = std::make_unique<lfd::LabelHull>();
    if (this->Hull->Initialize(layout, cameras.data(), labels.Width, labels.Height))
    {
      lfd::LabelBlocks blocks;
      const std::vector<glm::ivec4> rects =
        lfd::LabelRectangles(labels, static_cast<int>(cameras.size()), &blocks);
      lfd::LabelHull& hull = *this->Hull;
      vtkSMPTools::For(0,
        lfd::LabelHull::Sectors,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType sector = begin; sector < end; ++sector)
          {
            hull.MarkSector(static_cast<int>(sector), layout, cameras.data(), rects, &blocks);
          }
        });
      hull.Unite();
    }
    this->HullArray = holder;
    this->HullExcludedViews = this->ExcludedViews;
    this->HullTime.Modified();
  }
  return *this->Hull;
}

//------------------------------------------------------------------------------
const vtkLightFieldRenderer::RigViews& vtkLightFieldRenderer::GetRigViews(vtkCameraRig* rig)
{
  // (FitCylinder() fits a rig without modifying it: HasCylinder() says so.)
  if (!this->Views || rig != this->ViewsRig || rig->GetMTime() > this->ViewsTime ||
    rig->HasCylinder() != this->ViewsFitted || this->ExcludedViews != this->ViewsExcluded)
  {
    this->Views = std::make_unique<RigViews>();
    RigViews& views = *this->Views;
    // The rig says how the light field is parameterised: a grid on a plane
    // (two-plane) or else a ring (cylinder).
    views.Plane = rig->GetTwoPlaneLayout(this->ExcludedViews);
    if (views.Plane.Empty())
    {
      views.Ring = rig->GetRingLayout(this->ExcludedViews);
    }
    views.Cameras.resize(rig->GetNumberOfViews());
    for (int v = 0; v < rig->GetNumberOfViews(); ++v)
    {
      views.Cameras[v] = rig->GetCamera(v);
    }
    // The lookup projects with the cameras' 3x4 matrices, unless a lens
    // distortion needs the camera's own projection.
    if (std::none_of(views.Cameras.begin(),
          views.Cameras.end(),
          [](const lfd::PinholeCamera& camera) { return camera.Lens.Active; }))
    {
      views.Projections.reserve(views.Cameras.size());
      for (const lfd::PinholeCamera& camera : views.Cameras)
      {
        views.Projections.emplace_back(camera);
      }
    }
    this->ViewsRig = rig;
    this->ViewsFitted = rig->HasCylinder();
    this->ViewsExcluded = this->ExcludedViews;
    this->ViewsTime.Modified();
  }
  return *this->Views;
}

//------------------------------------------------------------------------------
const std::vector<std::uint8_t>& vtkLightFieldRenderer::GetHullTiles(const lfd::LabelHull& hull,
  const lfd::RingLayout& layout,
  const lfd::PinholeCamera& eye,
  const lfd::LightFieldSampler& sampler,
  int side)
{
  // No surface box without a proxy (the sampler's default bounds are unbounded).
  const bool proxy = sampler.Depth.Present();
  const glm::dvec3 low =
    proxy ? sampler.SurfaceLow : glm::dvec3(std::numeric_limits<double>::infinity());
  const glm::dvec3 high =
    proxy ? sampler.SurfaceHigh : glm::dvec3(-std::numeric_limits<double>::infinity());
  const glm::dvec3 center = eye.Center();
  const glm::dmat3 toDirection = eye.PixelToDirection();
  // (Every input but the hull and its layout, which GetLabelHull stamps.)
  std::vector<double> key = { static_cast<double>(this->HullTime.GetMTime()),
    static_cast<double>(this->Width),
    static_cast<double>(this->Height),
    static_cast<double>(side),
    sampler.FocalDistance };
  key.insert(key.end(), &center.x, &center.x + 3);
  key.insert(key.end(), &toDirection[0][0], &toDirection[0][0] + 9);
  key.insert(key.end(), &low.x, &low.x + 3);
  key.insert(key.end(), &high.x, &high.x + 3);
  if (key != this->HullTilesKey)
  {
    this->HullTiles = hull.ScreenTiles(layout,
      center,
      toDirection,
      this->Width,
      this->Height,
      sampler.FocalDistance,
      side,
      low,
      high);
    this->HullTilesKey = std::move(key);
  }
  return this->HullTiles;
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldRenderer::LightFieldOfCage(vtkLightField* input,
  vtkDeformationCage* cage,
  int label)
{
  if (!this->UseLabels || label == 0 || input->HasPass(vtkLightField::LABEL))
  {
    return input;
  }
  const std::string why = cage->ValidateLabels(input);
  if (!why.empty())
  {
    vtkErrorMacro(<< why);
    return nullptr;
  }
  return this->OnePart(input, label);
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldRenderer::OnePart(vtkLightField* input, int label)
{
  if (this->Parts && this->PartsInput == input && input->GetMTime() <= this->PartsTime &&
    this->PartsLabel == label && this->PartsThreshold == this->ObjectThreshold)
  {
    return this->Parts;
  }
  // A scan-line split without boundaries is one band: every object pixel
  // gets band 0's label. It runs on a shallow copy, so the input's pipeline
  // and arrays stay as they are.
  vtkNew<vtkLightField> copy;
  copy->ShallowCopy(input);
  vtkNew<vtkScanlineSplit> split;
  split->SetInputData(copy);
  split->SetBandLabel(0, label);
  split->SetThreshold(this->ObjectThreshold);
  // The split's error is said once, as the renderer's own.
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(split);
  split->Update();
  if (split->GetErrorCode() != 0)
  {
    vtkErrorMacro(<< errors->GetErrorMessage());
    this->Parts = nullptr;
    return nullptr;
  }
  this->Parts = split->GetOutput();
  this->PartsInput = input;
  this->PartsLabel = label;
  this->PartsThreshold = this->ObjectThreshold;
  this->PartsTime.Modified();
  return this->Parts;
}

//------------------------------------------------------------------------------
void vtkLightFieldRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  if (!this->Camera)
  {
    os << indent << "Pinhole K:";
    for (double k : this->PinholeK)
    {
      os << " " << k;
    }
    os << "\n" << indent << "Pinhole R:";
    for (double r : this->PinholeR)
    {
      os << " " << r;
    }
    os << "\n"
       << indent << "Pinhole t: " << this->PinholeT[0] << " " << this->PinholeT[1] << " "
       << this->PinholeT[2] << "\n";
  }
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "FocalDepth: " << this->FocalDepth << "\n";
  os << indent << "Aperture: " << this->Aperture << "\n";
  static const char* const surfaces[] = { "automatic", "plane", "proxy" };
  os << indent << "FocalSurface: " << surfaces[this->FocalSurface] << "\n";
  os << indent << "ProxyViews: " << this->ProxyViews << "\n";
  os << indent << "Background: " << this->Background[0] << " " << this->Background[1] << " "
     << this->Background[2] << "\n";
  os << indent << "UseLabels: " << this->UseLabels << "\n";
  os << indent << "Subdivision: " << this->Subdivision << (this->Subdivision ? "" : " (auto)")
     << "\n";
  os << indent << "SubdivisionTolerance: " << this->SubdivisionTolerance << "\n";
  os << indent << "CageAcceleration: " << (this->CageAcceleration ? "On" : "Off") << "\n";
  os << indent << "WidenedSearch: " << this->WidenedSearch << "\n";
  os << indent << "AntiAliasing: " << (this->AntiAliasing ? "On" : "Off") << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "ExcludedViews:";
  for (int v : this->ExcludedViews)
  {
    os << " " << v;
  }
  os << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkLightFieldRenderer);

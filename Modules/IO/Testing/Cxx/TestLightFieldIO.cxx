// Round trip of a light-field dataset through vtkLightFieldWriter and
// vtkLightFieldReader: every pass with exact pixel values and the row
// order checked against VTK's own PNG reader, the rig (with a lens
// distortion, written only where it is not zero), names, palette,
// projectors with their masks and provenance; pass selection and progress events; atomic
// replacement of an existing dataset.
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldWriter.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <utility>

namespace TestLightFieldIOHelpers
{
using lfdtest::Check;
using lfdtest::CheckEqual;

constexpr int Width = 7;
constexpr int Height = 5;
constexpr int Views = 3;

// Distinct, position-dependent values: a flipped row or swapped view shows.
double PassValue(int pass, int view, int x, int y, int c)
{
  switch (pass)
  {
    case vtkLightField::COAXIAL:
      return (view * 61 + x * 7 + y * 29 + c * 3) % 256;
    case vtkLightField::CODED:
      return (view * 17 + x * 31 + y * 5 + c * 101) % 256;
    case vtkLightField::FLOOD:
      return 255 - (view * 11 + x * 3 + y * 37 + c) % 256;
    case vtkLightField::LABEL:
      return (x + 2 * y + view) % 5;
    default:
      // Not representable in 8 bits nor as a short decimal: float exactness.
      return 0.1f * view + 1.0f / 3.0f * x + 1000.125f * y + 1e-7f;
  }
}

class ProgressCounter : public vtkCommand
{
public:
  static ProgressCounter* New() { return new ProgressCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Events;
    this->Last = *static_cast<double*>(data);
  }
  int Events = 0;
  double Last = -1.0;
};

vtkSmartPointer<vtkLightField> MakeLightField()
{
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->SetLayout(Width, Height, Views);
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    vtkDataArray* array = lightField->AllocatePass(pass);
    for (int v = 0; v < Views; ++v)
    {
      for (int y = 0; y < Height; ++y)
      {
        for (int x = 0; x < Width; ++x)
        {
          for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          {
            array->SetComponent(lightField->GetPointIndex(v, x, y), c, PassValue(pass, v, x, y, c));
          }
        }
      }
    }
  }
  vtkNew<vtkCameraRig> rig;
  const double center[3] = { 0.125, -0.3, 2.0 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double height = 0.0;
  rig->MakeCylinder(center, axis, 0.7, Views, 1, &height, Width, Height, 35.0);
  // Doubles that need all 17 digits to round-trip.
  double K[9];
  rig->GetIntrinsics(1, K);
  K[2] += 1.0 / 3.0;
  K[1] = 1e-9 / 7.0;
  double R[9], t[3];
  rig->GetRotation(1, R);
  rig->GetTranslation(1, t);
  t[0] += std::sqrt(2.0) * 1e-5;
  rig->SetView(1, K, R, t);
  const double lens[5] = { -0.2, 0.05 / 3.0, 1e-3, -5e-4, std::sqrt(2.0) * 1e-4 };
  rig->SetDistortion(2, lens);
  rig->SetViewName(0, "front");
  rig->SetViewName(1, "side \"quoted\"");
  lightField->SetRig(rig);
  lightField->SetProvenance("{\"generator\":\"TestLightFieldIO\",\"seed\":42}");
  vtkNew<vtkUnsignedCharArray> palette;
  palette->SetName("LabelPalette");
  palette->SetNumberOfComponents(3);
  const unsigned char colours[5][3] = {
    { 0, 0, 0 }, { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 }, { 12, 34, 56 }
  };
  for (const auto& colour : colours)
  {
    palette->InsertNextTypedTuple(colour);
  }
  lightField->SetPalette(palette);

  // Two projectors of 4 x 3 pixels with distinct mask colours.
  vtkNew<vtkCameraRig> projectors;
  rig->GetIntrinsics(0, K);
  projectors->SetNumberOfViews(2);
  projectors->SetImageSize(4, 3);
  for (int p = 0; p < 2; ++p)
  {
    rig->GetRotation(p, R);
    rig->GetTranslation(p, t);
    projectors->SetView(p, K, R, t);
  }
  lightField->SetProjectors(projectors);
  vtkNew<vtkImageData> masks;
  masks->SetDimensions(4, 3, 2);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("Mask");
  mask->SetNumberOfComponents(3);
  mask->SetNumberOfTuples(masks->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mask->GetNumberOfValues(); ++i)
  {
    mask->SetValue(i, static_cast<unsigned char>((7 * i) % 256));
  }
  masks->GetPointData()->SetScalars(mask);
  lightField->SetProjectorMasks(masks);
  return lightField;
}

int CountMismatches(vtkLightField* a, vtkLightField* b, int pass)
{
  vtkDataArray* x = a->GetPass(pass);
  vtkDataArray* y = b->GetPass(pass);
  if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues() ||
    x->GetDataType() != y->GetDataType())
  {
    return -1;
  }
  int mismatches = 0;
  for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
  {
    mismatches += x->GetVariantValue(i) == y->GetVariantValue(i) ? 0 : 1;
  }
  return mismatches;
}
// Writes the dataset: files, no temporary siblings, progress events.
void CheckWrite(vtkLightFieldWriter* writer, vtkLightField* original, const std::string& folder)
{
  const std::string dataset = folder + "/fish.lf";
  vtkNew<ProgressCounter> writeProgress;
  writer->AddObserver(vtkCommand::ProgressEvent, writeProgress);
  vtkNew<vtkLightFieldErrorObserver> writeErrors;
  writeErrors->Observe(writer);
  writer->SetInputData(original);
  writer->SetDirectory(dataset.c_str());
  Check(writer->Write() == 1, "vtkLightFieldWriter::Write returns 1");
  CheckEqual(std::string(writeErrors->GetErrorMessage()), std::string(), "writer error message");
  Check(std::filesystem::exists(dataset + "/lightfield.json"), "lightfield.json exists");
  Check(std::filesystem::exists(dataset + "/coaxial/view_0002.png"), "coaxial/view_0002.png");
  Check(std::filesystem::exists(dataset + "/depth/view_0000.exr"), "depth/view_0000.exr");
  CheckEqual(lfdtest::CountEntries(folder, "fish.lf."), 0, "temporary siblings left");
  Check(writeProgress->Events >= Views * vtkLightField::NUMBER_OF_PASSES,
    "writer progress events: " + std::to_string(writeProgress->Events));
  CheckEqual(writeProgress->Last, 1.0, "last writer progress");
  writer->RemoveObservers(vtkCommand::ProgressEvent);
}

// Row order of the files, checked with VTK's PNG reader (which also puts
// the bottom row first): view 2 of the coaxial pass must be identical, and
// the top-left pixel of the file must be OpenCV (0, 0).
void CheckRowOrder(const std::string& dataset)
{
  vtkNew<vtkPNGReader> png;
  png->SetFileName((dataset + "/coaxial/view_0002.png").c_str());
  png->Update();
  vtkDataArray* pngScalars = png->GetOutput()->GetPointData()->GetScalars();
  int pngMismatches = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double file = pngScalars->GetComponent((Height - 1 - y) * Width + x, c);
        pngMismatches += file == PassValue(vtkLightField::COAXIAL, 2, x, y, c) ? 0 : 1;
      }
    }
  }
  CheckEqual(pngMismatches, 0, "coaxial/view_0002.png vs. expected (file top row = y 0)");
}

// The calibration, bit for bit, the lens distortion only where it was set,
// and the view names.
void CheckRig(vtkCameraRig* a, vtkCameraRig* b, const std::string& dataset)
{
  CheckEqual(b->GetNumberOfViews(), Views, "rig views");
  CheckEqual(b->GetImageSize()[0], Width, "rig image width");
  CheckEqual(b->GetImageSize()[1], Height, "rig image height");
  int rigMismatches = 0;
  for (int i = 0; i < Views; ++i)
  {
    double Ka[9], Kb[9], Ra[9], Rb[9], ta[3], tb[3], da[5], db[5];
    a->GetIntrinsics(i, Ka);
    b->GetIntrinsics(i, Kb);
    a->GetRotation(i, Ra);
    b->GetRotation(i, Rb);
    a->GetTranslation(i, ta);
    b->GetTranslation(i, tb);
    a->GetDistortion(i, da);
    b->GetDistortion(i, db);
    for (int k = 0; k < 9; ++k)
    {
      rigMismatches += (Ka[k] == Kb[k] ? 0 : 1) + (Ra[k] == Rb[k] ? 0 : 1);
    }
    for (int k = 0; k < 3; ++k)
    {
      rigMismatches += ta[k] == tb[k] ? 0 : 1;
    }
    for (int k = 0; k < 5; ++k)
    {
      rigMismatches += da[k] == db[k] ? 0 : 1;
    }
  }
  CheckEqual(rigMismatches, 0, "rig values differing (bitwise) after the round trip");
  Check(b->HasDistortion(), "the read rig has the lens distortion");
  const nlohmann::json views =
    nlohmann::json::parse(lfdtest::ReadText(dataset + "/lightfield.json"))["views"];
  Check(!views[0].contains("distortion") && !views[1].contains("distortion") &&
      views[2]["distortion"].size() == 5,
    "lightfield.json has \"distortion\" in view 2 only (none written when zero)");
  CheckEqual(std::string(b->GetViewName(0)), std::string("front"), "view 0 name");
  CheckEqual(std::string(b->GetViewName(1)), std::string("side \"quoted\""), "view 1 name");
}

// Provenance, palette, projectors and their masks.
void CheckExtras(vtkLightField* original, vtkLightField* read)
{
  CheckEqual(std::string(read->GetProvenance() ? read->GetProvenance() : ""),
    std::string("{\"generator\":\"TestLightFieldIO\",\"seed\":42}"),
    "provenance");
  vtkUnsignedCharArray* palette =
    vtkUnsignedCharArray::SafeDownCast(read->GetFieldData()->GetAbstractArray("LabelPalette"));
  Check(palette != nullptr, "LabelPalette read");
  if (palette)
  {
    CheckEqual(palette->GetNumberOfTuples(), vtkIdType(5), "palette entries");
    CheckEqual(static_cast<int>(palette->GetTypedComponent(4, 1)), 34, "palette[4].g");
  }
  CheckEqual(read->GetProjectors()->GetNumberOfViews(), 2, "projectors read");
  CheckEqual(read->GetProjectors()->GetImageSize()[0], 4, "projector width");
  Check(read->GetProjectorMasks() != nullptr, "projector masks read");
  if (vtkImageData* masks = read->GetProjectorMasks())
  {
    vtkDataArray* mask = masks->GetPointData()->GetArray("Mask");
    vtkDataArray* written = original->GetProjectorMasks()->GetPointData()->GetArray("Mask");
    int maskMismatches = mask ? 0 : -1;
    for (vtkIdType i = 0; mask && i < mask->GetNumberOfValues(); ++i)
    {
      maskMismatches +=
        mask->GetComponent(i / 3, i % 3) == written->GetComponent(i / 3, i % 3) ? 0 : 1;
    }
    CheckEqual(maskMismatches, 0, "mask values differing after the round trip");
    CheckEqual(masks->GetDimensions()[2], 2, "masks");
  }
}

// Reads the whole dataset back: every pass, the rig and the extras.
void CheckRead(vtkLightFieldReader* reader, vtkLightField* original, const std::string& dataset)
{
  vtkNew<ProgressCounter> readProgress;
  reader->AddObserver(vtkCommand::ProgressEvent, readProgress);
  reader->SetFileName(dataset.c_str());
  reader->Update();
  vtkLightField* read = reader->GetOutput();
  CheckEqual(reader->GetErrorCode(), 0ul, "reader error code");
  CheckEqual(read->GetWidth(), Width, "width");
  CheckEqual(read->GetHeight(), Height, "height");
  CheckEqual(read->GetNumberOfViews(), Views, "views");
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    CheckEqual(CountMismatches(original, read, pass),
      0,
      std::string("mismatching values in pass ") + vtkLightField::GetPassName(pass));
  }
  // (The images are decoded a block at a time, an image a thread.)
  Check(readProgress->Events >=
      Views * vtkLightField::NUMBER_OF_PASSES / vtkSMPTools::GetEstimatedNumberOfThreads(),
    "reader progress events: " + std::to_string(readProgress->Events));
  reader->RemoveObservers(vtkCommand::ProgressEvent);
  const float depth =
    read->GetPass(vtkLightField::DEPTH)->GetComponent(read->GetPointIndex(2, 6, 4), 0);
  CheckEqual(depth,
    static_cast<float>(PassValue(vtkLightField::DEPTH, 2, 6, 4, 0)),
    "depth at view 2, (6, 4)");
  CheckRig(original->GetRig(), read->GetRig(), dataset);
  CheckExtras(original, read);
}

// Only the Label pass.
void CheckPassSelection(vtkLightField* original, const std::string& dataset)
{
  vtkNew<vtkLightFieldReader> labelsOnly;
  labelsOnly->SetFileName((dataset + "/lightfield.json").c_str());
  labelsOnly->ReadNoPasses();
  labelsOnly->SetReadPass(vtkLightField::LABEL, true);
  labelsOnly->Update();
  int held = 0;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    held += labelsOnly->GetOutput()->GetPass(pass) ? 1 : 0;
  }
  CheckEqual(held, 1, "passes read when only Label is selected");
  CheckEqual(CountMismatches(original, labelsOnly->GetOutput(), vtkLightField::LABEL),
    0,
    "label mismatches (Label only)");
  CheckEqual(labelsOnly->GetOutput()->GetRig()->GetNumberOfViews(), Views, "rig (Label only)");
}

// Pieces of the views (the processes of `mpirun lfd animate`): the piece's
// views as written, every other view zero, every pass allocated whole.
void CheckPieces(vtkLightField* original, const std::string& dataset)
{
  int range[2];
  vtkLightFieldReader::GetPieceViews(3, 0, 2, range);
  Check(range[0] == 0 && range[1] == 1, "piece 0 of 2 of 3 views: [0, 1)");
  vtkLightFieldReader::GetPieceViews(3, 1, 2, range);
  Check(range[0] == 1 && range[1] == 3, "piece 1 of 2 of 3 views: [1, 3)");
  vtkLightFieldReader::GetPieceViews(3, 0, 4, range);
  Check(range[0] == 0 && range[1] == 0, "piece 0 of 4 of 3 views: empty");
  vtkLightFieldReader::GetPieceViews(3, 5, 4, range);
  Check(range[0] == 3 && range[1] == 3, "piece 5 of 4 of 3 views: empty");
  for (const auto& piece : { std::make_pair(1, 2), std::make_pair(0, 4), std::make_pair(2, 4) })
  {
    vtkNew<vtkLightFieldReader> reader;
    reader->SetFileName(dataset.c_str());
    reader->SetPiece(piece.first);
    reader->SetNumberOfPieces(piece.second);
    reader->Update();
    const std::string name =
      "piece " + std::to_string(piece.first) + " of " + std::to_string(piece.second);
    CheckEqual(reader->GetErrorCode(), 0ul, name + ": reader error code");
    vtkLightFieldReader::GetPieceViews(Views, piece.first, piece.second, range);
    int mismatches = 0;
    for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
    {
      vtkDataArray* expected = original->GetPass(pass);
      vtkDataArray* read = reader->GetOutput()->GetPass(pass);
      if (!read || read->GetNumberOfValues() != expected->GetNumberOfValues())
      {
        ++mismatches;
        continue;
      }
      const vtkIdType viewValues = read->GetNumberOfValues() / Views;
      for (vtkIdType i = 0; i < read->GetNumberOfValues(); ++i)
      {
        const int view = static_cast<int>(i / viewValues);
        const double value =
          view >= range[0] && view < range[1] ? expected->GetVariantValue(i).ToDouble() : 0.0;
        mismatches += read->GetVariantValue(i).ToDouble() == value ? 0 : 1;
      }
    }
    CheckEqual(mismatches, 0, name + ": values differing from the piece's views and zeros");
  }
}
}

int TestLightFieldIO(int, char*[])
{
  using namespace TestLightFieldIOHelpers;
  const std::string folder = lfdtest::ScratchFolder("TestLightFieldIO");
  const std::string dataset = folder + "/fish.lf";
  vtkSmartPointer<vtkLightField> original = MakeLightField();
  vtkNew<vtkLightFieldWriter> writer;
  CheckWrite(writer, original, folder);
  CheckRowOrder(dataset);
  vtkNew<vtkLightFieldReader> reader;
  CheckRead(reader, original, dataset);
  CheckPassSelection(original, dataset);
  CheckPieces(original, dataset);

  // Replacing the dataset: a light field with only two passes replaces the
  // five-pass one completely.
  vtkNew<vtkLightField> smaller;
  smaller->DeepCopy(original);
  smaller->GetPointData()->RemoveArray("Coded");
  smaller->GetPointData()->RemoveArray("Flood");
  smaller->GetPointData()->RemoveArray("Depth");
  smaller->GetPointData()->RemoveArray("Confidence");
  writer->SetInputData(smaller);
  Check(writer->Write() == 1, "rewrite over an existing dataset");
  Check(!std::filesystem::exists(dataset + "/depth"), "the old depth folder is gone");
  CheckEqual(lfdtest::CountEntries(folder, "fish.lf."), 0, "siblings left after the rewrite");
  reader->Modified();
  reader->Update();
  CheckEqual(reader->GetOutput()->GetPointData()->GetNumberOfArrays(),
    2,
    "arrays after reading the rewritten dataset");
  return lfdtest::Result();
}

/**
 * @class   vtkLightFieldRenderer
 * @brief   renders a new view of a cylindrical or two-plane light field on the CPU
 *
 * vtkLightFieldRenderer takes a vtkLightField on its input and produces the
 * image a pinhole camera would see: one ray per pixel, each ray looked up in
 * the light field by cylindrical sampling (Chen, Ofek, Shum and Levoy,
 * "Interactive Deformation of Light Fields", I3D 2005, Sec. 6.2; see
 * lfdCylinderSampling.h): the two views around the ray's azimuth in the one
 * or two rows around its height, the ray's focal point projected through each
 * view's real calibration, 16 rays interpolated quadrilinearly.
 *
 * When the rig is a two-plane one (vtkCameraRig::IsTwoPlane(): a grid of
 * cameras on a plane, parallel optical axes), rays are looked up by
 * two-plane sampling instead (Levoy and Hanrahan 1996, lfdTwoPlaneSampling.h):
 * the cameras around the point where the ray crosses the camera plane, its
 * point on a focal plane FocalDepth in front of that plane, weighted over an
 * Aperture (refocusing and synthetic aperture). Everything else (labels,
 * cages, tessellation) is the same RENDER_VIEW; the widened search is the
 * ring's only.
 *
 * When the light field has a `Label` pass the colour of a ray is the mean of
 * the samples that carry the winning label only (labels are never averaged),
 * and rays whose winning label is 0 (background) get the Background colour.
 *
 * A light field without a `Label` pass is one part (the paper's Fig. 1: one
 * box over a whole statue, no split). Under a cage, its object pixels (found
 * as the split commands find them: vtkScanlineSplit without boundaries,
 * brightness above ObjectThreshold and its clean-up) carry the one label of
 * the cage's boxes, background pixels label 0. That Label pass is derived
 * once and reused while the input is unmodified; the input itself is not
 * changed. Boxes of several labels on such a light field are refused
 * (vtkDeformationCage::ValidateLabels): split it first.
 *
 * The camera is either a vtkCamera rendered into a Width x Height image (as
 * a vtkRenderer of that size would show it) or an explicit OpenCV pinhole
 * (SetPinhole), which is how a captured view is re-rendered for leave-one-out
 * evaluation. Views can be excluded from the sampling (with their
 * near-duplicates, see vtkCameraRig).
 *
 * The output is a Width x Height vtkImageData in VTK row order (bottom row
 * first) with the point arrays `Radiance` (RGB uint8, the active scalars)
 * `Label` (uint8, the winning label; 0 also where no view sees the ray) and
 * `Depth` (float, camera z of the seen point: on the proxy surface with
 * FocalSurface proxy; with the plane approximate, the middle of the accepted
 * segment inside its box, or the focal point; 0 on background).
 * With AntiAliasing (default) the silhouettes of moved parts are soft in
 * `Radiance`: a pixel next to one may show part of the object over
 * Background while its `Label` is 0.
 * Rendering runs in parallel over image rows with vtkSMPTools.
 *
 * @sa vtkLightField vtkCameraRig vtkLeaveOneOutEvaluator
 */
#ifndef vtkLightFieldRenderer_h
#define vtkLightFieldRenderer_h

#include "lfdRenderingModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkTimeStamp.h"    // For vtkTimeStamp

#include <memory> // For std::unique_ptr
#include <vector> // For std::vector

namespace lfd
{
struct NearestDepthTiles;
struct PinholeCamera;
struct LabelHull;
struct LightFieldSampler;
struct RingLayout;
template<typename T>
struct ViewStack;
}

class vtkCamera;
class vtkCameraRig;
class vtkDataArray;
class vtkDeformationCage;
class vtkFloatArray;
class vtkImageData;
class vtkLightField;
class vtkUnsignedCharArray;
class vtkUnstructuredGrid;

class LFDRENDERING_EXPORT vtkLightFieldRenderer : public vtkImageAlgorithm
{
public:
  static vtkLightFieldRenderer* New();
  vtkTypeMacro(vtkLightFieldRenderer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's request; a C++ exception thrown by it becomes this
   * algorithm's error (error code UnknownError), see lfdRequestGuard.h.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * The camera to render from (a vtkRenderer's camera, for instance).
   * Setting a camera replaces a pinhole set with SetPinhole().
   */
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  /**
   * Renders from an explicit OpenCV pinhole (row-major K and R, and t) instead
   * of a vtkCamera; removes the camera. The image size still comes from
   * Width and Height.
   */
  void SetPinhole(const double K[9], const double R[9], const double t[3]);

  ///@{
  /**
   * Output image size in pixels, each in [1, lfd::MaximumRenderSize] (16384,
   * lfdLimits.h); a size outside is refused when the pipeline updates.
   * Default 512 x 512.
   */
  vtkSetMacro(Width, int);
  vtkGetMacro(Width, int);
  vtkSetMacro(Height, int);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * Focal distance d of the paper: the focal plane is orthogonal to each ray
   * and lies d in front of (towards the viewer from) the point where the ray
   * passes closest to the rig axis. Default 0: the plane contains the axis.
   */
  vtkSetMacro(FocalDistance, double);
  vtkGetMacro(FocalDistance, double);
  ///@}

  /// Where a ray is focused (see SetFocalSurface).
  enum FocalSurfaceType
  {
    FOCAL_AUTOMATIC = 0,
    FOCAL_PLANE,
    FOCAL_PROXY
  };

  ///@{
  /**
   * The focal surface. FOCAL_PLANE: the paper's plane at FocalDistance
   * (Sec. 6.2), 4 ring neighbours blended quadrilinearly. FOCAL_PROXY (beyond
   * the paper): the light field's `Depth` pass is a geometric proxy; a ray is
   * focused where it meets that surface (per pixel, Gortler et al. 1996) and
   * blended from the ProxyViews cameras nearest to it in angle that see the
   * point (Buehler et al. 2001); rays that meet no surface use the plane.
   * The rendered Depth is then the surface's (through the warp: the rest
   * depth mapped into the deformed box), so VTK actors composite correctly
   * with the object. FOCAL_AUTOMATIC (default): the proxy when the light
   * field has a Depth pass (a synthetic capture, or `lfd proxy`), else the
   * plane. FOCAL_PROXY on a light field without a Depth pass is an error.
   * See lfd::LightFieldSampler::GatherOnSurface.
   */
  vtkSetClampMacro(FocalSurface, int, FOCAL_AUTOMATIC, FOCAL_PROXY);
  vtkGetMacro(FocalSurface, int);
  void SetFocalSurfaceToAutomatic() { this->SetFocalSurface(FOCAL_AUTOMATIC); }
  void SetFocalSurfaceToPlane() { this->SetFocalSurface(FOCAL_PLANE); }
  void SetFocalSurfaceToProxy() { this->SetFocalSurface(FOCAL_PROXY); }
  ///@}

  ///@{
  /**
   * Cameras blended per ray on the proxy surface (k nearest in angle that
   * see the point), 1..4. Default 3.
   */
  vtkSetClampMacro(ProxyViews, int, 1, 4);
  vtkGetMacro(ProxyViews, int);
  ///@}

  ///@{
  /**
   * Two-plane light fields only (see above): the depth of the focal plane
   * in front of the camera plane, world units along the cameras' optical
   * axis; 0 (default) puts it at infinity, where views that share one K
   * have zero disparity (an imported Stanford-style grid is rectified so).
   * Points at the focal depth are sharp; a point at depth z spreads over
   * f |du| |1/z - 1/FocalDepth| pixels for the cameras du apart.
   */
  vtkSetClampMacro(FocalDepth, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FocalDepth, double);
  ///@}

  ///@{
  /**
   * Two-plane light fields only: the synthetic aperture, a half-width in
   * world units on the camera plane. Every camera closer than it along both
   * axes of the grid contributes, weighted by a tent (1 - |du|/a)(1 - |dv|/a);
   * below the grid spacing (default 0) the 4 nearest cameras are blended
   * bilinearly (Levoy and Hanrahan's quadrilinear interpolation). A wider
   * aperture blurs whatever lies off the focal plane (lfdTwoPlaneSampling.h).
   */
  vtkSetClampMacro(Aperture, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Aperture, double);
  ///@}

  ///@{
  /**
   * Colour (RGB in [0, 1]) of rays that see background (label 0) or no view.
   * Default black.
   */
  vtkSetVector3Macro(Background, double);
  vtkGetVector3Macro(Background, double);
  ///@}

  ///@{
  /**
   * Use the Label pass (when present) for label-aware blending. Default on.
   */
  vtkSetMacro(UseLabels, bool);
  vtkGetMacro(UseLabels, bool);
  vtkBooleanMacro(UseLabels, bool);
  ///@}

  ///@{
  /**
   * Tessellation of the cage's boxes (DESIGN.md 4.4): each box is split into
   * k x k x k sub-boxes with the same deformation, which makes the warped
   * rays piecewise linear and closer to the true, curved inverse images of
   * the view rays. Subdivision k >= 1 (default 1: the paper's single straight
   * warped ray per box); 0 = automatic: per box, the smallest k (up to 8)
   * whose measured warp deviation (lfd::WarpDeviation: how far the straight
   * warped rays of the sub-boxes stray from the exact, curved rest-space
   * images of view rays) is at most SubdivisionTolerance pixels of this
   * camera's image at the box (default 0.5 pixel). A box at rest, or moved
   * by an affine map, gets k = 1; a strong twist more.
   *
   * A ray tests the sub-boxes that CageAcceleration leaves it (all of them at
   * worst), so the cost is bounded (lfdLimits.h): k
   * above lfd::MaximumSubdivision (16), or boxes x k^3 above
   * lfd::MaximumSubBoxes (4096), is refused with an error naming the
   * subdivision, the number of boxes and the sub-boxes it would make. The
   * automatic choice lowers the largest k until the cage fits the budget.
   */
  vtkSetMacro(Subdivision, int);
  vtkGetMacro(Subdivision, int);
  vtkSetClampMacro(SubdivisionTolerance, double, 1e-6, 100.0);
  vtkGetMacro(SubdivisionTolerance, double);
  ///@}

  ///@{
  /**
   * The k each box of the cage was split with in the last update (the
   * automatic choice, or Subdivision), by box index (0 for an index out of
   * range or without a cage), and the largest of them.
   */
  int GetLastSubdivision(int box) const;
  int GetLastMaximumSubdivision() const;
  ///@}

  ///@{
  /**
   * Per-frame acceleration of the cage (lfd::FrameCage): the warp's per-box
   * terms are computed once per frame; the image is cut into tiles of 16 x
   * 16 pixels and each box listed in the tiles its projected bounds overlap,
   * so a ray only tests the boxes it can meet; a ray walks its boxes front
   * to back and stops warping them at the interval that gives its pixel.
   * The pixels are exactly those without it, where every ray tests and warps
   * every box (lfd::RenderView over all boxes); it only changes the cost: a
   * cage of 100 boxes over the fish costs a small multiple of 3 boxes (README,
   * Results). On by default; off is the reference it is compared with.
   */
  vtkSetMacro(CageAcceleration, bool);
  vtkGetMacro(CageAcceleration, bool);
  vtkBooleanMacro(CageAcceleration, bool);
  ///@}

  ///@{
  /**
   * Widened camera search (paper Sec. 8) for regions a deformation uncovers:
   * when no segment of a view ray matched and the cameras around a moved
   * box's warped ray saw another part there (it hid this one before the
   * deformation), up to WidenedSearch views on each side of the ray are
   * asked what points along the warped segment project onto (see
   * lfd::LightFieldSampler::Widen: background refuses a point, the part
   * votes for it, another part has no say); the most photo-consistent point
   * gives the pixel. It runs only after every segment failed, so it fills
   * holes and never overrides a match; boxes at rest never use it (a cage
   * at rest renders exactly the undeformed light field). 0 turns it off.
   * Default 2 (fish swim: 25.40 -> 25.56 dB, IoU 0.985 -> 0.986; wider
   * reaches do not help more).
   */
  vtkSetClampMacro(WidenedSearch, int, 0, 64);
  vtkGetMacro(WidenedSearch, int);
  ///@}

  ///@{
  /**
   * Anti-aliased silhouettes of moved parts (lfd::RenderViewSettings::
   * AntiAliasing): an interval of a moved box is as opaque as the share of
   * its warped ray's samples that carry the box's label, and the intervals
   * are composited front to back, so a silhouette blends the part with what
   * lies behind it (another part, the undeformed light field, Background)
   * over about a source pixel instead of a staircase. The Label and Depth
   * arrays still follow the label vote. Boxes at rest are unchanged (a cage
   * at rest renders exactly the undeformed light field). Default on.
   */
  vtkSetMacro(AntiAliasing, bool);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Brightness (mean of RGB, 0..255) above which a pixel of a light field
   * without a Label pass is the object when a cage deforms it (see above;
   * vtkScanlineSplit::SetThreshold, whose default it shares). Raise it when
   * the background is not black (templeRing: 60, for the cloth behind it).
   * Default 10.
   */
  vtkSetClampMacro(ObjectThreshold, double, 0.0, 255.0);
  vtkGetMacro(ObjectThreshold, double);
  ///@}

  ///@{
  /**
   * Views left out of the sampling, with their near-duplicates
   * (leave-one-out evaluation).
   */
  void AddExcludedView(int view);
  void RemoveAllExcludedViews();
  int GetNumberOfExcludedViews() const;
  ///@}

  ///@{
  /**
   * The deformation cage (optional input port 1): a vtkDeformationCage, or
   * any vtkUnstructuredGrid it reads (vtkDeformationCage::CheckGridArrays(),
   * InitializeFromGrid()): boxes with deformed and rest corners and a label.
   * With a cage the renderer draws the deformed light field (paper Sec. 6);
   * validate the cage first (vtkDeformationCage::Validate).
   */
  void SetCageData(vtkUnstructuredGrid* cage);
  void SetCageConnection(vtkAlgorithmOutput* output);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkLightFieldRenderer();
  ~vtkLightFieldRenderer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkCamera* Camera = nullptr;
  double PinholeK[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double PinholeR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double PinholeT[3] = { 0, 0, 0 };
  int Width = 512;
  int Height = 512;
  double FocalDistance = 0.0;
  double FocalDepth = 0.0;
  double Aperture = 0.0;
  int FocalSurface = FOCAL_AUTOMATIC;
  int ProxyViews = 3;
  double Background[3] = { 0.0, 0.0, 0.0 };
  bool UseLabels = true;
  int Subdivision = 1;
  bool CageAcceleration = true;
  int WidenedSearch = 2;
  bool AntiAliasing = true;
  double SubdivisionTolerance = 0.5;
  double ObjectThreshold = 10.0;
  std::vector<int> ExcludedViews;

private:
  vtkLightFieldRenderer(const vtkLightFieldRenderer&) = delete;

  void operator=(const vtkLightFieldRenderer&) = delete;

  /// The camera that renders the output: Camera at Width x Height, or the pinhole.
  void GetEyePinhole(double K[9], double R[9], double t[3]);

  /**
   * The light field to sample under `cage`, whose first box owns `label` (0:
   * the cage has no box): the input, or when labels are used and the input
   * has none, its one-part split (OnePart) once the cage is checked to have
   * one label. nullptr after an error.
   */
  vtkLightField* LightFieldOfCage(vtkLightField* input, vtkDeformationCage* cage, int label);

  /**
   * `input` with a Label pass that makes its object pixels part `label`
   * (cached while the input, the label and ObjectThreshold are unchanged),
   * or nullptr after an error.
   */
  vtkLightField* OnePart(vtkLightField* input, int label);

  std::vector<int> LastSubdivisions; // the k of each box in the last update
#ifndef __VTK_WRAP__
  /**
   * The proxy's extent: the bounds of its surface points (6 values, low
   * then high, lfd::DepthBounds), then per view the smallest and largest
   * depth (lfd::DepthRanges); with ProxyTiles, the coarse level of the
   * depth walk (lfd::NearestDepthTiles), each computed over the views on
   * every thread; cached while `holder` (the Depth pass's array, or the
   * image cache that serves `depth`) and the rig are unchanged.
   */
  const std::vector<double>& GetProxyExtent(vtkObject* holder,
    const lfd::ViewStack<float>& depth,
    vtkCameraRig* rig,
    const std::vector<lfd::PinholeCamera>& cameras);
#endif

#ifndef __VTK_WRAP__
  /**
   * The lfd::LabelHull of the Label pass `labels` over `layout` (no grid
   * when a camera has lens distortion), so that focal-plane rays that can
   * meet no part skip their lookup; cached while `holder` (the pass's array,
   * or the image cache serving it), the rig and the excluded views are
   * unchanged.
   */
  const lfd::LabelHull& GetLabelHull(vtkObject* holder,
    const lfd::ViewStack<std::uint8_t>& labels,
    vtkCameraRig* rig,
    const lfd::RingLayout& layout,
    const std::vector<lfd::PinholeCamera>& cameras);
#endif

#ifndef __VTK_WRAP__
  /**
   * The label hull's screen tiles (lfd::LabelHull::ScreenTiles) of tiles of
   * `side` pixels seen from `eye` through the focal `sampler`'s plane and
   * its proxy's bounds: cached while the hull (GetLabelHull), the eye and
   * the frame are unchanged, as when a cage is edited under a still camera.
   */
  const std::vector<std::uint8_t>& GetHullTiles(const lfd::LabelHull& hull,
    const lfd::RingLayout& layout,
    const lfd::PinholeCamera& eye,
    const lfd::LightFieldSampler& sampler,
    int side);
#endif

  struct RigViews;
#ifndef __VTK_WRAP__
  /**
   * The rig's views as the lookup reads them: its two-plane grid, or else
   * its ring, less ExcludedViews; its cameras, and their 3x4 projections
   * (none when a camera has a lens distortion). Cached while the rig (and
   * its fit: vtkCameraRig::HasCylinder) and the excluded views are unchanged.
   */
  const RigViews& GetRigViews(vtkCameraRig* rig);
#endif
  std::unique_ptr<RigViews> Views;
  vtkObject* ViewsRig = nullptr; // compared, never dereferenced
  bool ViewsFitted = false;
  std::vector<int> ViewsExcluded;
  vtkTimeStamp ViewsTime;

  std::unique_ptr<lfd::LabelHull> Hull;
  vtkObject* HullArray = nullptr; // compared, never dereferenced
  std::vector<int> HullExcludedViews;
  vtkTimeStamp HullTime;
  std::vector<double> HullTilesKey; // what HullTiles was computed from (GetHullTiles)
  std::vector<std::uint8_t> HullTiles;

  std::vector<double> ProxyExtent;
  std::unique_ptr<lfd::NearestDepthTiles> ProxyTiles;
  vtkObject* ProxyExtentArray = nullptr; // compared, never dereferenced
  vtkTimeStamp ProxyExtentTime;

  /**
   * Gives `output` its Width x Height Radiance, Label and Depth arrays: the
   * last frame's (FrameRadiance, FrameLabels, FrameDepths) when nothing else
   * holds them, so that a frame's memory is not handed back to the kernel
   * and faulted in again by the next (FrameArray in the .cxx); otherwise new
   * ones, which become the renderer's.
   */
  void AllocateOutput(vtkImageData* output);

  vtkSmartPointer<vtkUnsignedCharArray> FrameRadiance;
  vtkSmartPointer<vtkUnsignedCharArray> FrameLabels;
  vtkSmartPointer<vtkFloatArray> FrameDepths;

  vtkSmartPointer<vtkLightField> Parts; // the derived light field of OnePart()
  vtkLightField* PartsInput = nullptr;  // compared, never dereferenced
  vtkTimeStamp PartsTime;
  int PartsLabel = 0;
  double PartsThreshold = -1.0;
};

#endif

/**
 * @class   vtkCameraRig
 * @brief   the calibrated cameras of a light field and the cylinder they lie on
 *
 * vtkCameraRig holds one pinhole camera per view in the OpenCV convention
 * `x ~ K [R | t] X` (pixel origin at the centre of the top-left pixel, y
 * down), all views sharing one image size. Matrices are passed as row-major
 * arrays of 9 doubles.
 *
 * FitCylinder() fits the ring (or stack of rings) the camera centres lie on,
 * once, explicitly, when the rig is built or read: MakeCylinder() ends with
 * it, and so do vtkLightFieldReader, vtkMiddleburyImporter (FitRigCylinder)
 * and vtkLightFieldCapture; a rig set up view by view calls it when done.
 * The fit is cached by the rig's modification time: any later change (a
 * view, the image size, a tolerance) makes HasCylinder() false until the
 * next FitCylinder(). Nothing that reads a rig fits it (GetRingLayout() and
 * the renderers only read the fit), so no filter modifies its input's rig.
 *
 * the axis is the principal direction of the centres whose spread stands
 * apart from the other two (for a ring, the normal of the plane fitted by
 * SVD; for a stack of rings taller than wide, the long direction), oriented
 * like most views' image "up" (or towards +Y when they do not agree, as on
 * rigs whose cameras are rolled by 90 degrees), the centre and radius come
 * from a least-squares circle fit in the plane orthogonal to the axis. Each
 * view then gets an azimuth about the axis, a height along it and a row.
 * Rows are found from the heights themselves: sorted heights are split at
 * the gaps that are at least RowGapRatio times wider than the widest row's
 * own spread of heights (and at least MinimumRowGap x radius), so that rows
 * of any spacing are told apart while the noise of a real ring does not
 * split it. Views of a row whose centres are closer than DuplicateTolerance
 * x radius and look the same way are near-duplicates: the first of them (by
 * index) is kept, the others report it in GetDuplicateOf() and are left out
 * of the sampling layout.
 *
 * Real rings are not perfect cylinders (templeRing is tilted and has a gap):
 * the cylinder is only used to choose neighbouring views; rays are always
 * projected with each view's own calibration.
 *
 * @sa vtkLightField
 */
#ifndef vtkCameraRig_h
#define vtkCameraRig_h

#include "lfdCoreModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkCamera;
class vtkIdList;

#ifndef __VTK_WRAP__
namespace lfd
{
struct PinholeCamera;
struct RingLayout;
struct TwoPlaneLayout;
}
#endif

class LFDCORE_EXPORT vtkCameraRig : public vtkObject
{
public:
  static vtkCameraRig* New();
  vtkTypeMacro(vtkCameraRig, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of views. Resizing keeps the first views and gives new ones an
   * identity camera; the cylinder fit becomes stale.
   */
  void SetNumberOfViews(int n);
  int GetNumberOfViews() const;
  ///@}

  ///@{
  /**
   * Image size in pixels, shared by all views.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  /**
   * Sets view `i`: intrinsics K and rotation R (row-major 3x3) and the
   * translation t. The cylinder fit becomes stale.
   */
  void SetView(int i, const double K[9], const double R[9], const double t[3]);

  ///@{
  /**
   * Per-view calibration, row-major.
   */
  void GetIntrinsics(int i, double K[9]) const;
  void GetRotation(int i, double R[9]) const;
  void GetTranslation(int i, double t[3]) const;
  ///@}

  ///@{
  /**
   * Per-view lens distortion, OpenCV's (k1, k2, p1, p2, k3)
   * (lfdLensDistortion.h); none (all 0) by default and after SetView().
   * Project() and every pixel-to-ray conversion of the kernels apply it;
   * ApplyToCamera() cannot (a vtkCamera is an ideal pinhole).
   * HasDistortion() is true when any view has a non-zero coefficient.
   */
  void SetDistortion(int i, const double coefficients[5]);
  void GetDistortion(int i, double coefficients[5]) const;
  bool HasDistortion() const;
  ///@}

  ///@{
  /**
   * Optional per-view name (e.g. the image file a view was imported from).
   */
  void SetViewName(int i, const char* name);
  const char* GetViewName(int i) const;
  ///@}

  ///@{
  /**
   * Camera centre `-R^T t`, unit viewing direction and unit image "up"
   * (camera -y) of view `i` in world space.
   */
  void GetCameraCenter(int i, double center[3]) const;
  void GetViewDirection(int i, double direction[3]) const;
  void GetViewUp(int i, double up[3]) const;
  ///@}

  /**
   * Projects a world point into view `i` (OpenCV pixel coordinates).
   * Returns false when the point is behind the camera.
   */
  bool Project(int i, const double point[3], double pixel[2]) const;

  /**
   * Points `camera` (position, focal point, view up, view angle, window
   * centre) to reproduce view `i` in a vtkRenderer of the rig's image size.
   * The vertical focal length fy sets the view angle; VTK cameras have square
   * pixels, so fx is not represented (it is for synthetic rigs, fx = fy).
   */
  void ApplyToCamera(int i, vtkCamera* camera) const;

  /**
   * Vertical field of view of view `i` in degrees, from fy and the image
   * height (the view angle ApplyToCamera() sets).
   */
  double GetViewAngle(int i) const;

  /**
   * The pinhole (K, R, t, row-major) that a vtkCamera renders into a
   * `width` x `height` window: the inverse of ApplyToCamera().
   */
  static void CameraToPinhole(vtkCamera* camera,
    int width,
    int height,
    double K[9],
    double R[9],
    double t[3]);

  /**
   * Builds a cylindrical rig around an axis: `rows` rings of
   * `viewsPerRing` cameras at `radius` from the axis (through `center`),
   * rows at the given heights along the axis, every camera looking at the
   * axis point of its own height, image "up" along the axis, vertical field
   * of view `viewAngle` degrees and the given image size. The first camera
   * of a ring sits at azimuth 0, on `center + radius * reference` where the
   * reference is the axis-orthogonal part of +Z (or +X when the axis is Z).
   * Ends with FitCylinder() when a ring has at least 3 views.
   */
  void MakeCylinder(const double center[3],
    const double axis[3],
    double radius,
    int viewsPerRing,
    int rows,
    const double* heights,
    int width,
    int height,
    double viewAngle);

  /**
   * Builds a two-plane rig (Levoy and Hanrahan 1996): `columns` x `rows`
   * cameras `spacing` apart on the plane through `center` orthogonal to
   * `forward`, the grid centred on `center`, every camera looking along
   * `forward` with its image "up" as close to `up` as the plane allows,
   * vertical field of view `viewAngle` degrees and the given image size.
   * View `r * columns + c` is row r (the top row first) and column c (the
   * left column first), named "rRR_cCC".
   */
  void MakePlaneGrid(const double center[3],
    const double forward[3],
    const double up[3],
    int columns,
    int rows,
    double spacing,
    int width,
    int height,
    double viewAngle);

  /**
   * True when the rig is a two-plane one: every view looks along one axis
   * and the camera centres lie on a plane orthogonal to it
   * (lfd::BuildTwoPlaneLayout, lfdTwoPlaneSampling.h, gives the tolerances).
   * vtkLightFieldRenderer then samples by two-plane interpolation instead of
   * the cylinder. Computed from the views each time, nothing is cached.
   */
  bool IsTwoPlane() const;

  ///@{
  /**
   * Tolerances of FitCylinder(). Views of one row closer than
   * DuplicateTolerance x radius (and looking the same way within 5 degrees)
   * are duplicates (default 0.01); views of two rows never are. Neighbouring heights start a new
   * row when their gap is at least RowGapRatio times the largest spread of heights within a row
   * (default 4) and at least MinimumRowGap x radius (default 0.001, far
   * below any row spacing a capture uses; it keeps rounding noise of an
   * exact ring from counting as rows). Among the splits that qualify the
   * one with the largest ratio is kept; none qualifies on a single ring.
   */
  vtkSetClampMacro(DuplicateTolerance, double, 0.0, 1.0);
  vtkGetMacro(DuplicateTolerance, double);
  vtkSetClampMacro(MinimumRowGap, double, 0.0, 10.0);
  vtkGetMacro(MinimumRowGap, double);
  vtkSetClampMacro(RowGapRatio, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RowGapRatio, double);
  ///@}

  /**
   * Fits the cylinder, azimuths, heights, rows and duplicates: the axis (see
   * above), a circle fit in the plane orthogonal to it (algebraic start,
   * Gauss-Newton on the geometric distance), each view located on the
   * cylinder, near-duplicates, then rows clustered by the gaps between
   * heights (see MinimumRowGap). Returns false
   * (with an error) when there are fewer than 3 distinct camera centres or
   * they are collinear.
   */
  bool FitCylinder();

  /**
   * True when the cylinder fit is current: FitCylinder() succeeded and the
   * rig has not been modified since.
   */
  bool HasCylinder() const;

  ///@{
  /**
   * Results of FitCylinder(). The axis is a unit vector (see above for its
   * orientation); the centre is on the axis at the mean
   * height of the cameras. FitResidual is the RMS distance of the camera
   * centres from the fitted cylinder.
   */
  vtkGetVector3Macro(Axis, double);
  vtkGetVector3Macro(Center, double);
  vtkGetMacro(Radius, double);
  vtkGetMacro(FitResidual, double);
  ///@}

  ///@{
  /**
   * Per-view cylinder coordinates after FitCylinder(): azimuth in radians
   * [0, 2 pi) about the axis, height along it, row index (rows are numbered
   * by increasing height), and the index of the view this one duplicates
   * (-1 for a view that duplicates none).
   */
  double GetAzimuth(int i) const;
  double GetHeight(int i) const;
  int GetRow(int i) const;
  int GetDuplicateOf(int i) const;
  ///@}

  /**
   * Unit directions of azimuth 0 (towards view 0, orthogonal to the axis)
   * and azimuth pi/2 (Axis x the first), after FitCylinder().
   */
  void GetAzimuthFrame(double zero[3], double quarter[3]) const;

  ///@{
  /**
   * Rows found by FitCylinder() and their mean heights.
   */
  int GetNumberOfRows() const;
  double GetRowHeight(int row) const;
  ///@}

  /**
   * Number of views that duplicate another one.
   */
  int GetNumberOfDuplicates() const;

  /**
   * View indices sorted by row, then azimuth (after FitCylinder()).
   */
  void GetSortedViews(vtkIdList* views) const;

  ///@{
  /**
   * Whether a view from `eye` extrapolates outside the captured views, in
   * one line ("" when it does not, or when the rig has no fitted cylinder).
   * The renderer looks a ray up where it enters the rig cylinder on the
   * eye's side (Chen et al. 2005, Sec. 6.2) and clamps heights beyond the
   * outermost rows to them; so the rays from `eye` to the 8 corners and the
   * centre of `bounds` (xmin, xmax, ymin, ymax, zmin, zmax: what the view
   * looks at, e.g. the deformed cage) are followed to the cylinder, and the
   * line says how far the farthest one lands above the highest row or below
   * the lowest one (by more than 1 % of the radius), or that one lands in
   * a gap of the ring (an azimuth step more than twice the row's median
   * step, as on templeRing). Without `bounds` the view is taken to look at
   * the axis between the lowest and the highest row.
   */
  std::string DescribeExtrapolation(const double eye[3], const double bounds[6]) const;
  std::string DescribeExtrapolation(const double eye[3]) const;
  ///@}

  /**
   * Deep copy of another rig (calibration, names and fit).
   */
  void DeepCopy(vtkCameraRig* source);

#ifndef __VTK_WRAP__
  ///@{
  /**
   * The pinhole camera of view `i` (kernel type). Setting it makes the
   * cylinder fit stale.
   */
  void SetView(int i, const lfd::PinholeCamera& camera);
  const lfd::PinholeCamera& GetCamera(int i) const;
  ///@}

  /**
   * FitCylinder() without reporting an error: on failure returns false with
   * the reason in `problem` (for readers, to which a rig no cylinder fits is
   * not an error).
   */
  bool FitCylinder(std::string& problem);

  /**
   * The sampling layout over the views that are not duplicates and not in
   * `excluded` (used by leave-one-out), from the current fit; empty (no
   * rows) when the rig has none (HasCylinder() is false).
   */
  lfd::RingLayout GetRingLayout(const std::vector<int>& excluded = {}) const;

  /**
   * The two-plane layout over the views (lfd::BuildTwoPlaneLayout), the
   * cells of `excluded` views left empty (leave-one-out); empty (Empty())
   * when the rig is not a two-plane one.
   */
  lfd::TwoPlaneLayout GetTwoPlaneLayout(const std::vector<int>& excluded = {}) const;

  /**
   * The rig's validation, shared by every reader, importer and writer: each
   * view passes lfd::CheckPinhole() (its distortion checked over the rig's
   * ImageSize) and no two views have the same K, R and t. Returns -1 when
   * the rig is valid; otherwise the first invalid view, with `field` ("K",
   * "R", "t", "distortion", or "" for a repeated view) and `problem`.
   */
  int FindInvalidView(std::string& field, std::string& problem) const;
#endif

protected:
  vtkCameraRig();
  ~vtkCameraRig() override;

  int ImageSize[2] = { 0, 0 };
  double DuplicateTolerance = 0.01;
  double MinimumRowGap = 0.001;
  double RowGapRatio = 4.0;
  double Axis[3] = { 0.0, 1.0, 0.0 };
  double Center[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.0;
  double FitResidual = 0.0;

private:
  vtkCameraRig(const vtkCameraRig&) = delete;
  void operator=(const vtkCameraRig&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

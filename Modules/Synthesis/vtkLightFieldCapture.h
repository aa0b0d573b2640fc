/**
 * @class   vtkLightFieldCapture
 * @brief   renders a mesh from a rig of cameras into a synthetic vtkLightField
 *
 * vtkLightFieldCapture photographs a vtkPolyData (input port 0) from every
 * view of a camera rig with VTK's OpenGL renderer and stores the images as
 * the passes of a vtkLightField (DESIGN.md section 5):
 *
 * - `Coaxial` (RGB uint8): a positional point light at the camera centre,
 *   no attenuation, not a spotlight; Lambertian diffuse (coefficient
 *   1 - Ambient) plus Ambient, no specular, so a surface seen at normal
 *   incidence shows exactly its albedo. The albedo is the mesh's "RGB"
 *   array (uint8, 3 components, point or cell data) used as direct
 *   scalars, or, when the mesh has texture coordinates and a texture image
 *   is connected to input port 1, that texture (linear interpolation), or
 *   else white. A mesh without point normals is shaded per facet. With
 *   SceneFixedLight on, the same light stays in world space
 *   at the centre of view 0 for every view (Chen et al. 2005, Fig. 5).
 * - `Label` (uint8): the mesh's cell array "Label" rendered with flat
 *   colours (no lighting, no anti-aliasing, no blending), 0 where no surface
 *   is seen. Cells of a mesh without "Label" are label 1.
 * - `Depth` (float): distance of the visible surface along the camera's
 *   optical axis, in world units, 0 where no surface is seen. The clipping
 *   range is set tight around the mesh bounds for every view, so the
 *   24-bit depth buffer resolves a small fraction of the object size.
 *
 * The rig is a cylinder built with vtkCameraRig::MakeCylinder: NumberOfRows
 * rings (or one ring per entry of RowHeights or RowElevations) of
 * ViewsPerRing cameras about Axis through Center, at distance Radius,
 * Width x Height pixels and a vertical ViewAngle. Radius 0 frames the mesh:
 * the sphere about Center that holds the bounds fills the narrower field of
 * view with a 10 % margin, seen from every row. The rows are placed, by
 * priority:
 * - RowHeights: heights along the axis, world units, relative to Center;
 * - RowElevations: elevation angles (degrees) seen from Center, a row at
 *   radius x tan(elevation);
 * - Eyes: NumberOfRows rows spread evenly (at least RowSpacing apart) over
 *   the heights where the rays from every eye to the mesh bounds (and to
 *   the EyeTargets) enter the rig cylinder, RowMargin x radius beyond them
 *   at both ends, so that a renderer at those eyes never clamps a ray to
 *   the outermost row (issue 11: a camera above the top row lost ~10 dB);
 * - otherwise NumberOfRows rows symmetric about Center, RowSpacing apart
 *   (0 = 0.05 x radius).
 * vtkCameraRig tells rows of any spacing apart (see its MinimumRowGap), so
 * the spacing is free.
 * Alternatively SetRig() captures from the views of a given rig (its image
 * size wins over Width and Height). The views are rendered as ideal
 * pinholes (vtkCamera): a rig or projector rig with lens distortion is
 * refused with an error.
 *
 *
 * **Projectors** (Chen et al. 2005, section 4.1). With NumberOfProjectors
 * > 0, or a projector rig set with SetProjectors(), the capture also
 * simulates video projectors that paint the object with colour masks:
 * - `Coded` (RGB uint8): every projector shows its mask; a surface point
 *   gets, from each projector that sees it (projective texturing with the
 *   projector's own depth map, so self-shadowed points get no colour), the
 *   mask colour at its projector pixel times the Lambertian irradiance of a
 *   point light at the projector centre, times the albedo.
 * - `Flood` (RGB uint8): the same projectors showing white.
 * Both add ProjectorAmbient x albedo (room light) and Gaussian sensor noise
 * of standard deviation ProjectorNoise (8-bit levels, seeded by NoiseSeed),
 * and are clamped to [0, 255]. The masks are SetProjectorMasks() (painted,
 * Wp x Hp x P with an RGB uint8 "Mask" or RGB scalars, rows bottom first),
 * or else generated from the mesh's cell "Label": each projector shows the
 * Palette colour of the part it sees at each of its pixels (a part's colour
 * where the projector sees that part's box when the labels come from
 * vtkLabelCellsByBoxes). Generated masks need a Palette, and so do the
 * passes' users: the palette, the projector rig and the masks are stored on
 * the output (vtkLightField::GetPalette(), GetProjectors(),
 * GetProjectorMasks()). Projectors built from NumberOfProjectors take the
 * poses of views of the middle ring evenly spaced in azimuth (half a step
 * away from view 0), with the cameras' field of view and an image of
 * ProjectorWidth x ProjectorHeight pixels (0 = the cameras' size).
 *
 * **Prefiltering.** With Supersample N > 1 the Coaxial pass is rendered at
 * N x N times the pixels and each pixel is the mean of its N x N samples (a
 * box filter over the pixel's footprint: what a camera's sensor integrates),
 * so fine texture and silhouettes are anti-aliased instead of point-sampled;
 * the provenance records "supersample": N (vtkGroundTruthEvaluator renders
 * its truth the same way). The Label and Depth passes stay point-sampled at
 * the pixel centre (no multisampling, no FXAA): a label is one part's, never
 * a mix, and a depth is one surface's. The projector passes (Coded, Flood)
 * are prefiltered the same way: each of a pixel's N x N samples is lit by
 * the projectors at the surface point it sees (its own depth), and the
 * pixel is their mean before the room light and the noise are added; a
 * pixel over a mask's colour edge or the object's silhouette mixes them,
 * as a camera's would. With Supersample 1 (default) a
 * pixel's colour, label and depth all come from the one surface its centre
 * sees, so the edges of the passes agree exactly.
 *
 * The light field's pixel rows are copied bottom row first, exactly as the
 * OpenGL read-back delivers them (see vtkLightField, "Row order"). The
 * output owns a copy of the rig, cylinder fitted when it has 3 or more
 * views. Progress is reported once per view; AbortExecute stops the capture
 * after the current view.
 *
 * Rendering needs an OpenGL context: under Debian's VTK an X server, e.g.
 * `xvfb-run -a`.
 *
 * @sa vtkProceduralObjectSource vtkLightField vtkCameraRig
 */
#ifndef vtkLightFieldCapture_h
#define vtkLightFieldCapture_h

#include "lfdSynthesisModule.h" // For export macro
#include "vtkLightFieldAlgorithm.h"

class vtkCameraRig;
class vtkDeformationCage;
class vtkDoubleArray;
class vtkImageData;
class vtkLightField;
class vtkPoints;
class vtkPolyData;
class vtkUnsignedCharArray;

class LFDSYNTHESIS_EXPORT vtkLightFieldCapture : public vtkLightFieldAlgorithm
{
public:
  static vtkLightFieldCapture* New();
  vtkTypeMacro(vtkLightFieldCapture, vtkLightFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Cameras per ring (default 120) and number of rings (default 3).
   */
  vtkSetClampMacro(ViewsPerRing, int, 1, 100000);
  vtkGetMacro(ViewsPerRing, int);
  vtkSetClampMacro(NumberOfRows, int, 1, 1000);
  vtkGetMacro(NumberOfRows, int);
  ///@}

  ///@{
  /**
   * Distance of the cameras from the axis; 0 (default) frames the mesh.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Distance between neighbouring rows along the axis; 0 (default) is
   * 0.05 x the radius.
   */
  vtkSetClampMacro(RowSpacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RowSpacing, double);
  ///@}

  ///@{
  /**
   * Explicit row heights along the axis (world units, relative to Center).
   * When set and not empty they replace NumberOfRows, RowSpacing and Eyes.
   */
  virtual void SetRowHeights(vtkDoubleArray* heights);
  vtkGetObjectMacro(RowHeights, vtkDoubleArray);
  ///@}

  ///@{
  /**
   * Explicit row elevations in degrees (-89..89) seen from Center: a row
   * at height radius x tan(elevation), so the angles hold whatever radius
   * the framing chooses. When set and not empty (and RowHeights is not)
   * they replace NumberOfRows, RowSpacing and Eyes.
   */
  virtual void SetRowElevations(vtkDoubleArray* elevations);
  vtkGetObjectMacro(RowElevations, vtkDoubleArray);
  ///@}

  ///@{
  /**
   * Eyes the rows must cover (e.g. a scene's camera): NumberOfRows rows
   * are spread over the heights where the rays from each eye to the 8
   * corners and the centre of the mesh bounds, and to every EyeTargets
   * point (e.g. a cage's corners at every keyframe), enter the rig
   * cylinder, extended by RowMargin x radius at both ends (default 0.05),
   * and over the rows NumberOfRows and RowSpacing give without eyes; the
   * rows are never closer than RowSpacing (or its default). One row sits in
   * the middle of those heights. Default nullptr: no eyes.
   */
  virtual void SetEyes(vtkPoints* eyes);
  /**
   * Appends to `eyes` the eye as each box of `cage` sees its rest contents
   * (a deformed render looks the light field up along the rest-space images
   * of its rays): `eye` through the inverse of the affine map that best
   * carries the box's rest corners to its deformed corners (least squares,
   * vtkLandmarkTransform). Rows that cover these eyes too keep a deformed
   * box's rays inside the captured heights: the swimming fish's boxes turn
   * the side camera's rays up to 0.2 radius above it (swim 29.2 dB with 3
   * rows about the camera, 32.3 dB with 5 rows covering the rest eyes).
   * Boxes at rest add the eye itself.
   */
  static void AppendRestEyes(vtkDeformationCage* cage, const double eye[3], vtkPoints* eyes);
  vtkGetObjectMacro(Eyes, vtkPoints);
  virtual void SetEyeTargets(vtkPoints* targets);
  vtkGetObjectMacro(EyeTargets, vtkPoints);
  vtkSetClampMacro(RowMargin, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RowMargin, double);
  ///@}

  ///@{
  /**
   * Image size in pixels. Default 256 x 256.
   */
  vtkSetClampMacro(Width, int, 1, 16384);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 1, 16384);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * Vertical field of view in degrees. Default 30.
   */
  vtkSetClampMacro(ViewAngle, double, 0.1, 179.0);
  vtkGetMacro(ViewAngle, double);
  ///@}

  ///@{
  /**
   * Direction of the rig's axis (image "up" of every camera). Default +Y.
   */
  vtkSetVector3Macro(Axis, double);
  vtkGetVector3Macro(Axis, double);
  ///@}

  ///@{
  /**
   * Point of the axis the rows are placed about. By default (AutoCenter on)
   * it is the centre of the mesh bounds; setting a centre turns AutoCenter
   * off.
   */
  virtual void SetCenter(double x, double y, double z);
  virtual void SetCenter(const double center[3]);
  vtkGetVector3Macro(Center, double);
  vtkSetMacro(AutoCenter, bool);
  vtkGetMacro(AutoCenter, bool);
  vtkBooleanMacro(AutoCenter, bool);
  ///@}

  ///@{
  /**
   * Passes to capture. All on by default.
   */
  vtkSetMacro(CaptureCoaxial, bool);
  vtkGetMacro(CaptureCoaxial, bool);
  vtkBooleanMacro(CaptureCoaxial, bool);
  vtkSetMacro(CaptureLabel, bool);
  vtkGetMacro(CaptureLabel, bool);
  vtkBooleanMacro(CaptureLabel, bool);
  vtkSetMacro(CaptureDepth, bool);
  vtkGetMacro(CaptureDepth, bool);
  vtkBooleanMacro(CaptureDepth, bool);
  ///@}

  ///@{
  /**
   * Samples per pixel along each image axis of the Coaxial, Coded and
   * Flood passes (see Prefiltering above): 1 (default) point-samples the
   * pixel centre, N > 1 averages N x N samples over the pixel.
   */
  vtkSetClampMacro(Supersample, int, 1, 8);
  vtkGetMacro(Supersample, int);
  ///@}

  ///@{
  /**
   * Off (default): coaxial light, the lamp travels with the camera. On: the
   * same point light fixed in world space at the centre of view 0.
   */
  vtkSetMacro(SceneFixedLight, bool);
  vtkGetMacro(SceneFixedLight, bool);
  vtkBooleanMacro(SceneFixedLight, bool);
  ///@}

  ///@{
  /**
   * The name of the built-in object captured (vtkProceduralObjectSource's
   * names: "fish", "figure", ...), recorded in the output's provenance as
   * "object" so that a front end can rebuild it (the Studio's live
   * projector simulation, vtkProjectorView). Default nullptr: a mesh of the
   * user's, not recorded.
   */
  vtkSetStringMacro(ObjectName);
  vtkGetStringMacro(ObjectName);
  ///@}

  ///@{
  /**
   * Ambient coefficient of the Coaxial pass; the diffuse coefficient is
   * 1 - Ambient. Default 0.1.
   */
  vtkSetClampMacro(Ambient, double, 0.0, 1.0);
  vtkGetMacro(Ambient, double);
  ///@}

  ///@{
  /**
   * A rig to capture from instead of the cylinder built from the
   * parameters above. Default nullptr.
   */
  virtual void SetRig(vtkCameraRig* rig);
  vtkGetObjectMacro(Rig, vtkCameraRig);
  ///@}

  ///@{
  /**
   * Number of projectors placed on the ring (see Projectors above); 0
   * (default) captures no Coded and Flood passes unless SetProjectors() is
   * given a rig.
   */
  vtkSetClampMacro(NumberOfProjectors, int, 0, 64);
  vtkGetMacro(NumberOfProjectors, int);
  ///@}

  ///@{
  /**
   * Projector image size for projectors built from NumberOfProjectors;
   * 0 (default) = the cameras' image size.
   */
  vtkSetClampMacro(ProjectorWidth, int, 0, 16384);
  vtkGetMacro(ProjectorWidth, int);
  vtkSetClampMacro(ProjectorHeight, int, 0, 16384);
  vtkGetMacro(ProjectorHeight, int);
  ///@}

  ///@{
  /**
   * Explicit projectors (K, R, t and image size), overriding
   * NumberOfProjectors. Default nullptr.
   */
  virtual void SetProjectors(vtkCameraRig* projectors);
  vtkGetObjectMacro(Projectors, vtkCameraRig);
  ///@}

  ///@{
  /**
   * Painted masks, one slice per projector. Default nullptr: masks are
   * generated from the mesh labels and the Palette.
   */
  virtual void SetProjectorMasks(vtkImageData* masks);
  vtkGetObjectMacro(ProjectorMasks, vtkImageData);
  ///@}

  ///@{
  /**
   * The label palette (3 x uint8 per label, entry 0 = unlabelled), see
   * vtkLabelPalette. Default nullptr.
   */
  virtual void SetPalette(vtkUnsignedCharArray* palette);
  vtkGetObjectMacro(Palette, vtkUnsignedCharArray);
  ///@}

  ///@{
  /**
   * Room light in the projector passes, as a fraction of the albedo
   * (default 0), and the standard deviation of the sensor noise in 8-bit
   * levels (default 0) with its random seed (default 1).
   */
  vtkSetClampMacro(ProjectorAmbient, double, 0.0, 1.0);
  vtkGetMacro(ProjectorAmbient, double);
  vtkSetClampMacro(ProjectorNoise, double, 0.0, 255.0);
  vtkGetMacro(ProjectorNoise, double);
  vtkSetMacro(NoiseSeed, int);
  vtkGetMacro(NoiseSeed, int);
  ///@}

  ///@{
  /**
   * Input connections: the mesh (port 0) and its optional texture image
   * (port 1).
   */
  void SetInputData(vtkPolyData* mesh);
  void SetTextureConnection(vtkAlgorithmOutput* texture);
  void SetTextureData(vtkImageData* texture);
  ///@}

protected:
  vtkLightFieldCapture();
  ~vtkLightFieldCapture() override;

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

  /**
   * Builds the cylinder rig for a mesh with the given bounds (Rig unset).
   */
  bool BuildRig(const double bounds[6], vtkCameraRig* rig);

  /**
   * The number of rows the rig will have: the explicit heights' or
   * elevations' count, or NumberOfRows.
   */
  int GetNumberOfRigRows();

  /**
   * The projectors to simulate for the camera rig `rig` (Projectors, or
   * NumberOfProjectors views of the middle ring); false when there are none.
   */
  bool BuildProjectors(vtkCameraRig* rig, vtkCameraRig* projectors);

  int ViewsPerRing = 120;
  int NumberOfRows = 3;
  double Radius = 0.0;
  double RowSpacing = 0.0;
  vtkDoubleArray* RowHeights = nullptr;
  vtkDoubleArray* RowElevations = nullptr;
  vtkPoints* Eyes = nullptr;
  vtkPoints* EyeTargets = nullptr;
  double RowMargin = 0.05;
  int Width = 256;
  int Height = 256;
  double ViewAngle = 30.0;
  double Axis[3] = { 0.0, 1.0, 0.0 };
  double Center[3] = { 0.0, 0.0, 0.0 };
  bool AutoCenter = true;
  bool CaptureCoaxial = true;
  bool CaptureLabel = true;
  bool CaptureDepth = true;
  bool SceneFixedLight = false;
  int Supersample = 1;
  char* ObjectName = nullptr;
  double Ambient = 0.1;
  vtkCameraRig* Rig = nullptr;
  int NumberOfProjectors = 0;
  int ProjectorWidth = 0;
  int ProjectorHeight = 0;
  vtkCameraRig* Projectors = nullptr;
  vtkImageData* ProjectorMasks = nullptr;
  vtkUnsignedCharArray* Palette = nullptr;
  double ProjectorAmbient = 0.0;
  double ProjectorNoise = 0.0;
  int NoiseSeed = 1;

private:
  vtkLightFieldCapture(const vtkLightFieldCapture&) = delete;
  void operator=(const vtkLightFieldCapture&) = delete;
};

#endif

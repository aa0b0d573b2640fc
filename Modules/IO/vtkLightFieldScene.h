/**
 * @class   vtkLightFieldScene
 * @brief   the scene file (`scene.json`): light field, deformation cage, keyframes, camera, render
 * settings
 *
 * vtkLightFieldScene reads and writes `scene.json`, version 1 (format
 * "lfd-scene", documented in Data/README.md and DESIGN.md section 3):
 *
 * - LightFieldPath: the light-field dataset as written in the file;
 *   GetResolvedLightFieldPath() resolves it against the scene file's folder.
 * - The cage (GetCage()): a vtkUnstructuredGrid with one VTK_HEXAHEDRON per
 *   box, corners in VTK's hexahedron order (0-3 bottom face counter-clockwise,
 *   4-7 the top face above them), shared between neighbouring boxes. Its
 *   points are the deformed positions; the point array "RestPosition" (3
 *   doubles) holds the rest positions; the cell array "Label" (int) the label
 *   of each box. A file without `points` gets points equal to the rest
 *   positions; a file without `cage` gives an empty grid (HasCage() false).
 * - Keyframes: (time, cage point positions), in file order, and how they
 *   are interpolated (Interpolation: linear or Catmull-Rom, the default).
 * - Camera: a vtkCamera (position, focal point, view up, view angle in
 *   degrees) and the image Width x Height (default 512 x 512, 30 degrees).
 * - Render settings: FocalDistance (default 0), FocalSurface (`render.focal`:
 *   "auto", the default, "plane" or "proxy"; see
 *   vtkLightFieldRenderer::SetFocalSurface), FocalDepth and Aperture
 *   (`render.focal_depth`, `render.aperture`, default 0: the refocusing of
 *   a two-plane light field, see vtkLightFieldRenderer::SetFocalDepth;
 *   rings ignore them), Subdivision (k x k x k
 *   sub-boxes per box, >= 1, default 1; the string "auto" is stored as 0,
 *   see GetSubdivisionAuto()), WidenedSearch (views searched on each side
 *   for regions a deformation uncovers, >= 0, default 2, 0 = off),
 *   ObjectThreshold (brightness in [0, 255] above which a pixel of a light
 *   field without a Label pass is the object, default 10), AntiAliasing
 *   (`render.antialiasing`, true or false, default true: soft silhouettes
 *   from label coverage, see vtkLightFieldRenderer::SetAntiAliasing) and
 *   Background (RGB, each in [0, 1], default black).
 *
 * Read() validates the whole file before changing anything and returns false
 * with one error line (vtkErrorMacro; a vtkLightFieldErrorObserver gets it)
 * naming the file and the field: malformed
 * JSON (line and column), wrong format, unknown version, missing fields, a
 * corner index out of range, a box without exactly 8 corners, `points` and
 * `rest_points` of different lengths, a keyframe whose point count differs
 * from the cage's, a non-finite number, a value out of range, JSON nested
 * deeper than lfd::MaximumJsonDepth, a path that is not a regular file, a
 * degenerate camera (lfd::CheckLookAt(): position = focal point, view_up
 * parallel to the view direction, view_angle outside [0.5, 179] degrees), an
 * image size above lfd::MaximumRenderSize, a subdivision outside
 * [1, lfd::MaximumSubdivision], two keyframes at the same time, a file name
 * with a NUL. Write() refuses the same settings, and writes atomically and
 * durably (lfdFileUtilities.h: checked writes, fsync, a temporary file in the
 * same folder renamed onto the target) with doubles printed so that they
 * read back bit for bit.
 */
#ifndef vtkLightFieldScene_h
#define vtkLightFieldScene_h

#include "lfdIOModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkCamera;
class vtkLightFieldReader;
class vtkPoints;
class vtkUnstructuredGrid;

class LFDIO_EXPORT vtkLightFieldScene : public vtkObject
{
public:
  static vtkLightFieldScene* New();
  vtkTypeMacro(vtkLightFieldScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Reads `fileName`. On failure returns false, keeps the current content and
   * reports the error.
   */
  bool Read(const char* fileName);

  /**
   * Writes `fileName` atomically. On failure returns false and reports the
   * error; an existing file is left untouched. A relative
   * light-field path of a scene read from (or written to) a file is
   * rewritten relative to `fileName`'s folder, so the new file names the
   * same light field.
   */
  bool Write(const char* fileName);

  /**
   * The checks Read() and Write() make on the view camera (lfd::CheckLookAt),
   * the image size, the subdivision and the keyframe times: "" when they
   * pass, else "field \"name\": problem" (the scene logic refuses a setting
   * with it).
   */
  std::string CheckSettings();

  /**
   * Resets everything to the defaults (no light field, no cage, no
   * keyframes, default camera and render settings).
   */
  void Initialize();

  ///@{
  /**
   * The file last read or written successfully (used to resolve relative
   * paths); may be set to place a scene built in memory.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The light-field dataset, as written in the file.
   */
  vtkSetStringMacro(LightFieldPath);
  vtkGetStringMacro(LightFieldPath);
  ///@}

  /**
   * LightFieldPath resolved against the folder of FileName (unchanged when
   * absolute or when FileName is not set); "" when LightFieldPath is unset.
   */
  const char* GetResolvedLightFieldPath();

  /**
   * Points `reader` (may be null, to check only) at the scene's light field.
   * Returns false, with an error naming the scene file and its
   * field "lightfield", when the scene names no light field or the resolved
   * path does not exist.
   */
  bool ConfigureReader(vtkLightFieldReader* reader);

  ///@{
  /**
   * The cage (see the class description). SetCage() stores the grid given
   * (no copy); Write() reads it through vtkDeformationCage, so it must pass
   * vtkDeformationCage::CheckGridArrays() (a grid without rest positions is
   * written at rest).
   */
  vtkUnstructuredGrid* GetCage();
  void SetCage(vtkUnstructuredGrid* cage);
  bool HasCage();
  ///@}

  ///@{
  /**
   * Keyframes: cage point positions at a time. AddKeyframe() stores a copy
   * of `points`.
   */
  int GetNumberOfKeyframes() const;
  double GetKeyframeTime(int i) const;
  vtkPoints* GetKeyframePoints(int i) const;
  void AddKeyframe(double time, vtkPoints* points);
  void RemoveAllKeyframes();
  ///@}

  /**
   * How the keyframes are interpolated over time ("interpolation" in
   * scene.json). The values are vtkKeyframeInterpolator's (Deformation),
   * which the scene logic hands them to.
   */
  enum InterpolationTypes
  {
    INTERPOLATION_LINEAR = 0,
    INTERPOLATION_CATMULL_ROM = 1
  };

  ///@{
  /**
   * Keyframe interpolation, one of InterpolationTypes. Default
   * INTERPOLATION_CATMULL_ROM (what `lfd animate` always rendered).
   */
  vtkSetClampMacro(Interpolation, int, INTERPOLATION_LINEAR, INTERPOLATION_CATMULL_ROM);
  vtkGetMacro(Interpolation, int);
  void SetInterpolationToLinear() { this->SetInterpolation(INTERPOLATION_LINEAR); }
  void SetInterpolationToCatmullRom() { this->SetInterpolation(INTERPOLATION_CATMULL_ROM); }
  ///@}

  /**
   * The view camera (never null).
   */
  vtkCamera* GetCamera();

  ///@{
  /**
   * Image size of the rendered view in pixels (default 512 x 512).
   */
  vtkSetClampMacro(Width, int, 1, VTK_INT_MAX);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 1, VTK_INT_MAX);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * The paper's focal distance d (Sec. 6.2), in world units (default 0).
   */
  vtkSetMacro(FocalDistance, double);
  vtkGetMacro(FocalDistance, double);
  ///@}

  ///@{
  /**
   * The focal surface, `render.focal`: 0 "auto" (default: the proxy when
   * the light field has a Depth pass), 1 "plane", 2 "proxy" (the values of
   * vtkLightFieldRenderer::FocalSurfaceType). Written only when not "auto".
   */
  vtkSetClampMacro(FocalSurface, int, 0, 2);
  vtkGetMacro(FocalSurface, int);
  ///@}

  ///@{
  /**
   * Anti-aliased silhouettes, `render.antialiasing` (default true; see
   * vtkLightFieldRenderer::SetAntiAliasing). Written only when false.
   */
  vtkSetMacro(AntiAliasing, bool);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Two-plane light fields: the focal plane's depth in front of the camera
   * plane (`render.focal_depth`, 0 = infinity) and the synthetic aperture
   * (`render.aperture`, 0 = the 4 nearest cameras), as
   * vtkLightFieldRenderer::SetFocalDepth / SetAperture. Rings ignore them.
   * Written only when not 0.
   */
  vtkSetClampMacro(FocalDepth, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FocalDepth, double);
  vtkSetClampMacro(Aperture, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Aperture, double);
  ///@}

  ///@{
  /**
   * Tessellation of every box into k x k x k sub-boxes (DESIGN.md 4.4);
   * k >= 1, default 1. 0 means "auto" (the renderer chooses).
   */
  vtkSetClampMacro(Subdivision, int, 0, 1024);
  vtkGetMacro(Subdivision, int);
  bool GetSubdivisionAuto() const { return this->Subdivision == 0; }
  void SetSubdivisionAuto() { this->SetSubdivision(0); }
  ///@}

  ///@{
  /**
   * Widened camera search of the renderer (paper Sec. 8, see
   * vtkLightFieldRenderer::SetWidenedSearch): views tried on each side for
   * regions a deformation uncovers; 0 turns it off. Default 2.
   */
  vtkSetClampMacro(WidenedSearch, int, 0, 64);
  vtkGetMacro(WidenedSearch, int);
  ///@}

  ///@{
  /**
   * Brightness (mean of RGB, 0..255) above which a pixel of a light field
   * without a Label pass is the object, which a cage then moves as one part
   * (see vtkLightFieldRenderer::SetObjectThreshold). Default 10.
   */
  vtkSetClampMacro(ObjectThreshold, double, 0.0, 255.0);
  vtkGetMacro(ObjectThreshold, double);
  ///@}

  ///@{
  /**
   * Background colour, RGB in [0, 1] (default black).
   */
  vtkSetVector3Macro(Background, double);
  vtkGetVector3Macro(Background, double);
  ///@}

protected:
  vtkLightFieldScene();
  ~vtkLightFieldScene() override;

  char* FileName = nullptr;
  char* LightFieldPath = nullptr;
  int Width = 512;
  int Height = 512;
  double FocalDistance = 0.0;
  int FocalSurface = 0;
  bool AntiAliasing = true;
  double FocalDepth = 0.0;
  double Aperture = 0.0;
  int Subdivision = 1;
  int WidenedSearch = 2;
  double ObjectThreshold = 10.0;
  double Background[3] = { 0.0, 0.0, 0.0 };
  int Interpolation = INTERPOLATION_CATMULL_ROM;

private:
  vtkLightFieldScene(const vtkLightFieldScene&) = delete;
  void operator=(const vtkLightFieldScene&) = delete;

  bool Fail(const std::string& message);
  bool WriteFile(const char* fileName);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

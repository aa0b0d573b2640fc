/**
 * @class   vtkLightField
 * @brief   a stack of calibrated images: W x H pixels x V views, one array per pass
 *
 * vtkLightField is a vtkImageData whose dimensions are (W, H, V): the i index
 * runs along an image row, j along the image columns and k over the views.
 * Each illumination pass is a named point-data array (see Pass): `Coaxial`
 * (RGB uint8, the radiance used for rendering), `Coded` and `Flood` (RGB
 * uint8, projector captures: colour masks, and the same projectors white),
 * `Label` (uint8, 0 = background or unlabelled, 1..N = parts), `Depth`
 * (float, distance along the camera's optical axis, 0 where no surface was
 * seen) and `Confidence` (uint8, how sure a segmentation is of each label,
 * 0..255). The calibrated cameras are a vtkCameraRig.
 *
 * **Palette.** Label i is painted (by projectors, in label images) with
 * colour i of the palette, the field-data array "LabelPalette" (3 x uint8 per
 * label, entry 0 = unlabelled, black); see GetPalette().
 *
 * **Projectors.** A light field split by projectors (Chen et al. 2005,
 * section 4.1) also holds the projectors as a second rig (K, R, t, image
 * size) and the colour mask each one showed: GetProjectors() and
 * GetProjectorMasks(), a Wp x Hp x P image (one slice per projector, rows
 * in the same order as the views) with the RGB uint8 array "Mask".
 *
 * **Row order.** Rows are stored the VTK way, bottom image row first: the
 * pixel at OpenCV coordinates (x, y) of view v (origin at the top-left pixel,
 * y down) is the point (i, j, k) = (x, H - 1 - y, v). So a slice of the stack
 * shows upright in any VTK image viewer and every VTK image filter works on
 * it unchanged, while cameras and files keep the OpenCV/top-left convention.
 * GetPointIndex() does the conversion; readers and writers flip rows.
 *
 * Plain VTK image filters downstream output a vtkImageData, not a
 * vtkLightField: re-attach the rig (SetRig) where it must survive them.
 *
 * @sa vtkCameraRig
 */
#ifndef vtkLightField_h
#define vtkLightField_h

#include "lfdCoreModule.h" // For export macro
#include "vtkImageData.h"

#include <vector> // For std::vector

class vtkCameraRig;
class vtkDataArray;
class vtkInformation;
class vtkInformationVector;
class vtkLightFieldTexelSource;
class vtkUnsignedCharArray;

class LFDCORE_EXPORT vtkLightField : public vtkImageData
{
public:
  static vtkLightField* New();
  vtkTypeMacro(vtkLightField, vtkImageData);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The passes a light field can hold (DESIGN.md section 2).
   */
  enum Pass
  {
    COAXIAL = 0,
    CODED,
    FLOOD,
    LABEL,
    DEPTH,
    CONFIDENCE,
    NUMBER_OF_PASSES
  };

  /**
   * Array name of a pass ("Coaxial", "Coded", "Flood", "Label", "Depth",
   * "Confidence"),
   * or nullptr for an invalid pass.
   */
  static const char* GetPassName(int pass);

  /**
   * Pass whose name is `name` (case-insensitive), or -1.
   */
  static int GetPassFromName(const char* name);

  /**
   * Number of components of a pass (3 for colour passes, 1 otherwise).
   */
  static int GetPassComponents(int pass);

  /**
   * VTK scalar type of a pass (VTK_UNSIGNED_CHAR, or VTK_FLOAT for Depth).
   */
  static int GetPassScalarType(int pass);

  /**
   * Sets the dimensions to width x height x views (spacing 1, origin 0).
   * Existing pass arrays are removed.
   */
  void SetLayout(int width, int height, int views);

  ///@{
  /**
   * Width, height and number of views (from the dimensions).
   */
  int GetWidth();
  int GetHeight();
  int GetNumberOfViews();
  ///@}

  /**
   * The array of a pass, or nullptr when the light field does not hold it.
   */
  vtkDataArray* GetPass(int pass);

  /**
   * Whether the Label pass holds `label` anywhere (false without a Label
   * pass; asked of the texel source when the pass is not in memory). The scan is cached until the
   * pass array is replaced or modified: after editing its values in place, call its Modified(), as
   * for vtkDataArray::GetRange().
   */
  bool HasLabel(int label);

  /**
   * Whether the light field holds `pass`: its array in memory, or its
   * texels through the texel source (a light field larger than memory).
   */
  bool HasPass(int pass);

  /**
   * Creates (or replaces) the zero-filled array of a pass, sized to the
   * layout, and returns it. Its memory is asked for on transparent huge
   * pages before it is filled (lfd::AdviseHugePages): a pass of tens of MB
   * faults in 512 times fewer pages.
   */
  vtkDataArray* AllocatePass(int pass);

  /**
   * Point index of the pixel at OpenCV coordinates (x, y) of view `view`
   * (see Row order above).
   */
  vtkIdType GetPointIndex(int view, int x, int y);

  ///@{
  /**
   * The calibrated cameras. A new light field owns an empty rig.
   */
  virtual void SetRig(vtkCameraRig* rig);
  vtkGetObjectMacro(Rig, vtkCameraRig);
  ///@}

  /**
   * The light field's modification time, its rig's and its projectors'
   * included: a camera of the rig changed (its pose, a calibration) makes
   * the filters downstream of the light field update, as a changed array does.
   */
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * The projectors that lit the Coded and Flood passes (K, R, t and their
   * image size), and their masks (Wp x Hp x P, RGB uint8 point array
   * "Mask", bottom row first). A new light field owns an empty projector
   * rig and no masks.
   */
  virtual void SetProjectors(vtkCameraRig* projectors);
  vtkGetObjectMacro(Projectors, vtkCameraRig);
  virtual void SetProjectorMasks(vtkImageData* masks);
  vtkGetObjectMacro(ProjectorMasks, vtkImageData);
  ///@}

  ///@{
  /**
   * The label palette: the field-data array "LabelPalette" (3 components,
   * tuple i = colour of label i), or nullptr when there is none. Setting
   * a palette renames the array "LabelPalette"; nullptr removes it.
   */
  vtkUnsignedCharArray* GetPalette();
  void SetPalette(vtkUnsignedCharArray* palette);
  ///@}

  ///@{
  /**
   * Where the pixels of the passes that are not in memory are read from
   * (nullptr: every pass is an array). A light field read out of core
   * (vtkLightFieldReader::SetCacheSize) has no Coaxial, Label and Depth arrays;
   * vtkLightFieldRenderer samples them through this source. Copies, deep
   * or shallow, share it (it is read-only).
   */
  virtual void SetTexelSource(vtkLightFieldTexelSource* source);
  vtkGetObjectMacro(TexelSource, vtkLightFieldTexelSource);
  ///@}

  ///@{
  /**
   * Free-form provenance (JSON text), stored in the dataset manifest.
   */
  vtkSetStringMacro(Provenance);
  vtkGetStringMacro(Provenance);
  ///@}

  /**
   * Empties the light field completely: no passes, an empty rig, no
   * projectors or masks, no provenance (vtkImageData::Initialize() alone
   * would keep them).
   */
  void Initialize() override;

  ///@{
  /**
   * Shallow copies share the rig, the projectors and their masks; deep
   * copies copy them.
   */
  void ShallowCopy(vtkDataObject* source) override;
  void DeepCopy(vtkDataObject* source) override;
  ///@}

  ///@{
  /**
   * Retrieve an instance of this class from an information object.
   */
  static vtkLightField* GetData(vtkInformation* info);
  static vtkLightField* GetData(vtkInformationVector* v, int i = 0);
  ///@}

protected:
  vtkLightField();
  ~vtkLightField() override;

  vtkCameraRig* Rig = nullptr;
  vtkCameraRig* Projectors = nullptr;
  vtkImageData* ProjectorMasks = nullptr;
  vtkLightFieldTexelSource* TexelSource = nullptr;
  char* Provenance = nullptr;

  // The labels the Label pass holds (index = label), for the array and
  // modification time they were counted from.
  std::vector<bool> LabelsPresent;
  vtkDataArray* LabelsPresentArray = nullptr;
  vtkMTimeType LabelsPresentTime = 0;

private:
  vtkLightField(const vtkLightField&) = delete;
  void operator=(const vtkLightField&) = delete;
};

#endif

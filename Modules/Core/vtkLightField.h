/**
 * @class   vtkLightField
 * @brief   a stack of calibrated images: W x H pixels x V views, one array per pass
 *
 * vtkLightField is a vtkImageData whose dimensions are (W, H, V): the i index
 * runs along an image row, j along the image columns and k over the views.
 * Each illumination pass is a named point-data array (see Pass): `Coaxial`
 * (RGB uint8, the radiance used for rendering), `Coded` and `Flood` (RGB
 * uint8, projector captures), `Label` (uint8, 0 = background, 1..N = parts)
 * and `Depth` (float, distance along the camera's optical axis, 0 where no
 * surface was seen). The calibrated cameras are a vtkCameraRig.
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

class vtkCameraRig;
class vtkDataArray;
class vtkInformation;
class vtkInformationVector;

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
    NUMBER_OF_PASSES
  };

  /**
   * Array name of a pass ("Coaxial", "Coded", "Flood", "Label", "Depth"),
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
   * Creates (or replaces) the zero-filled array of a pass, sized to the
   * layout, and returns it.
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

  ///@{
  /**
   * Free-form provenance (JSON text), stored in the dataset manifest.
   */
  vtkSetStringMacro(Provenance);
  vtkGetStringMacro(Provenance);
  ///@}

  ///@{
  /**
   * Shallow copies share the rig; deep copies copy it.
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
  char* Provenance = nullptr;

private:
  vtkLightField(const vtkLightField&) = delete;
  void operator=(const vtkLightField&) = delete;
};

#endif

/**
 * @class   vtkCalibratedImageExporter
 * @brief   superclass of the exporters of a light field as a calibrated image set (COLMAP,
 * transforms.json): the Coaxial views as PNG images + the cameras in a foreign format
 *
 * Writes into DirectoryName the Coaxial pass of the input vtkLightField,
 * one PNG per view in `images/`, and the calibration files the subclass
 * formats from the rig. Image names are the views' names (with the
 * extension .png) when every name is a plain file name (letters, digits,
 * `.`, `_`, `-`) and the names sort in view order, so an exported set
 * imports back in the same order; otherwise `view_0000.png`,
 * `view_0001.png`, ...
 *
 * Writing is atomic, as vtkLightFieldWriter's: a temporary sibling folder
 * renamed onto DirectoryName when complete. An existing DirectoryName is
 * replaced only when it is empty or an export of the same format (it holds
 * GetMarkerFile()). Errors are one line (vtkErrorMacro, GetErrorCode())
 * naming the folder, the file or the view.
 *
 * @sa vtkColmapExporter vtkTransformsExporter vtkCalibratedImageImporter
 */
#ifndef vtkCalibratedImageExporter_h
#define vtkCalibratedImageExporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkWriter.h"

#include <map>    // For std::map
#include <string> // For std::string
#include <vector> // For std::vector

class vtkCameraRig;
class vtkLightField;

class LFDIO_EXPORT vtkCalibratedImageExporter : public vtkWriter
{
public:
  vtkTypeMacro(vtkCalibratedImageExporter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The folder to create (or replace).
   */
  vtkSetStringMacro(DirectoryName);
  vtkGetStringMacro(DirectoryName);
  ///@}

  /**
   * The input light field.
   */
  vtkLightField* GetInput();

  /**
   * Runs the pipeline request; a C++ exception is reported as an error
   * naming the folder, never passed on.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkCalibratedImageExporter();
  ~vtkCalibratedImageExporter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

#ifndef __VTK_WRAP__
  /**
   * The calibration files (path relative to DirectoryName -> contents) of
   * `rig`, whose view i is the image `images/<imageNames[i]>`. On failure
   * returns false with the one-line reason (naming the view).
   */
  virtual bool FormatCalibration(vtkCameraRig* rig,
    const std::vector<std::string>& imageNames,
    std::map<std::string, std::string>& files,
    std::string& error) = 0;

  /**
   * The file (relative) that marks a folder as an export of this format.
   */
  virtual std::string GetMarkerFile() = 0;

  /**
   * A view's K has no skew (the foreign formats have none): "" or the
   * reason naming the view.
   */
  static std::string CheckNoSkew(vtkCameraRig* rig, int view);
#endif

  char* DirectoryName = nullptr;

private:
  vtkCalibratedImageExporter(const vtkCalibratedImageExporter&) = delete;
  void operator=(const vtkCalibratedImageExporter&) = delete;

  void Fail(unsigned long errorCode, const std::string& message);
};

#endif

/**
 * @class   vtkCalibratedImageImporter
 * @brief   superclass of the importers of calibrated image sets (Middlebury, COLMAP,
 * transforms.json): images + cameras -> vtkLightField
 *
 * A subclass parses its calibration format into a list of views (image
 * file, name, K, R, t in the rig's OpenCV convention, optional lens
 * distortion, and where in the calibration file the view is described, for
 * messages). This class does the rest, the same way for every format:
 *
 * - RequestInformation() parses the calibration, reads the first image's
 *   header, checks the light field's size against lfd::MaximumLightFieldBytes
 *   and validates the rig with vtkCameraRig::FindInvalidView() (the dataset
 *   reader's validation, so an importer never produces a light field its
 *   own reader would refuse; distortion is checked over the image size);
 * - RequestData() checks every image (same size as the first, 8-bit grey or
 *   colour) before the Coaxial pass is allocated, reads them (grey expanded
 *   to RGB, alpha dropped), builds the rig with the views' names and, when
 *   FitRigCylinder is on and there are at least 3 views, fits its cylinder
 *   (a rig no cylinder fits is imported unfitted, with a warning).
 *
 * Every error is one line through vtkErrorMacro (see
 * vtkLightFieldErrorObserver) that names the calibration file and the line
 * or field of the view concerned ("images.txt:12: image a.png: file not
 * found"); the output is then empty and GetErrorCode() is set.
 *
 * @sa vtkMiddleburyImporter vtkColmapImporter vtkTransformsImporter
 */
#ifndef vtkCalibratedImageImporter_h
#define vtkCalibratedImageImporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkLightFieldAlgorithm.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class LFDIO_EXPORT vtkCalibratedImageImporter : public vtkLightFieldAlgorithm
{
public:
  vtkTypeMacro(vtkCalibratedImageImporter, vtkLightFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The calibration: a file (Middlebury's `*_par.txt`, `transforms.json`)
   * or a folder (COLMAP's sparse model), as the subclass documents.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The folder that relative image names are resolved against; by default
   * (null or empty) the folder holding FileName (for a folder FileName, the
   * folder itself).
   */
  vtkSetStringMacro(ImageDirectory);
  vtkGetStringMacro(ImageDirectory);
  ///@}

  ///@{
  /**
   * Fit the rig's cylinder after import (default on).
   */
  vtkSetMacro(FitRigCylinder, bool);
  vtkGetMacro(FitRigCylinder, bool);
  vtkBooleanMacro(FitRigCylinder, bool);
  ///@}

protected:
  vtkCalibratedImageImporter();
  ~vtkCalibratedImageImporter() override;

#ifndef __VTK_WRAP__
  /// One view as the calibration describes it.
  struct CalibratedView
  {
    std::string Where;       // "file:line" or "file: field \"frames[3]\"", for messages
    std::string CameraWhere; // where the intrinsics are, when elsewhere ("cameras.txt:4")
    std::string Name;        // the view's name in the rig (the image name as written)
    std::string Image;       // the image file, resolved
    double K[9];
    double R[9];
    double t[3];
    double Distortion[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 }; // k1, k2, p1, p2, k3
  };

  /**
   * Parses FileName into `views` (at least one), with image names resolved
   * against GetImageFolder(). On failure returns false with the vtkErrorCode
   * and the complete one-line message. C++ exceptions are reported too
   * (DescribeFailure()).
   */
  virtual bool ParseCalibration(std::vector<CalibratedView>& views,
    unsigned long& errorCode,
    std::string& error) = 0;

  /**
   * The format's name in the light field's provenance ("COLMAP text model").
   */
  virtual std::string GetFormatDescription() = 0;

  /**
   * The format's name for a field of vtkCameraRig::FindInvalidView() ("K",
   * "R", "t", "distortion"), for messages; the default is the field itself.
   */
  virtual std::string DescribeField(const std::string& field)
  {
    return field;
  }

  /**
   * The image size the calibration announces (0 x 0 when it announces
   * none): when given, the images must have it.
   */
  int CalibratedImageSize[2] = { 0, 0 };

  /**
   * ImageDirectory, or the folder holding FileName by default.
   */
  virtual std::string GetImageFolder();
#endif

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;
  std::string DescribeFailure(const std::string& problem) override;

  char* FileName = nullptr;
  char* ImageDirectory = nullptr;
  bool FitRigCylinder = true;

private:
  vtkCalibratedImageImporter(const vtkCalibratedImageImporter&) = delete;
  void operator=(const vtkCalibratedImageImporter&) = delete;

  struct Internals; // what RequestInformation parsed, for RequestData
  std::unique_ptr<Internals> Internal;
};

#endif

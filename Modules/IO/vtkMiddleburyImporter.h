/**
 * @class   vtkMiddleburyImporter
 * @brief   imports a Middlebury multi-view stereo set (`*_par.txt` and its images) as a
 * vtkLightField
 *
 * The Middlebury multi-view stereo benchmark (Seitz, Curless, Diebel,
 * Scharstein and Szeliski, "A Comparison and Evaluation of Multi-View Stereo
 * Reconstruction Algorithms", CVPR 2006) ships each image set with a
 * calibration file `<name>_par.txt`: the first line is the number of images,
 * every following line is
 *
 *     imgname.png k11 k12 k13 k21 k22 k23 k31 k32 k33 r11 r12 r13 r21 r22 r23 r31 r32 r33 t1 t2 t3
 *
 * (22 fields: the image name and 21 numbers, K and R row-major, in the
 * OpenCV convention `x ~ K [R | t] X` with the pixel origin at the top-left,
 * which is the rig's convention). FileName is the par file; the images are
 * found next to it (or in ImageDirectory). The importer loads them as the
 * Coaxial pass and builds the rig with the image names as view names
 * (vtkCalibratedImageImporter, which also fits the cylinder).
 * The calibration is used as given: in templeRing about a third of the
 * images are rotated by 180 degrees in the image plane, and their R
 * includes that rotation.
 *
 * Errors name the file and line ("templeR_par.txt:5: ..."): a wrong number
 * of fields, a non-numeric token, a non-finite number, a count on line 1 that
 * disagrees with the number of lines, a camera that fails
 * vtkCameraRig::FindInvalidView() (the dataset reader's validation: R not a
 * rotation, a singular K, |t| too large, a repeated camera), a par file or
 * image that is not a regular file, a missing or unreadable image, an image
 * whose size differs from the first one or that is not 8-bit grey or colour,
 * a light field above lfd::MaximumLightFieldBytes (all checked before the
 * pass is allocated). The output is then empty, GetErrorCode() is set and
 * the one-line message is reported (see vtkLightFieldErrorObserver).
 *
 * @sa vtkLightFieldReader vtkCameraRig
 */
#ifndef vtkMiddleburyImporter_h
#define vtkMiddleburyImporter_h

#include "lfdIOModule.h" // For export macro
#include "vtkCalibratedImageImporter.h"

class LFDIO_EXPORT vtkMiddleburyImporter : public vtkCalibratedImageImporter
{
public:
  static vtkMiddleburyImporter* New();
  vtkTypeMacro(vtkMiddleburyImporter, vtkCalibratedImageImporter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkMiddleburyImporter();
  ~vtkMiddleburyImporter() override;

#ifndef __VTK_WRAP__
  bool ParseCalibration(std::vector<CalibratedView>& views,
    unsigned long& errorCode,
    std::string& error) override;
  std::string GetFormatDescription() override;
  std::string DescribeField(const std::string& field) override;
#endif

private:
  vtkMiddleburyImporter(const vtkMiddleburyImporter&) = delete;
  void operator=(const vtkMiddleburyImporter&) = delete;
};

#endif

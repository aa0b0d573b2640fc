/**
 * @file   lfdLightFieldOutput.h
 * @brief  pipeline steps shared by the sources of a vtkLightField (private to LFD::IO)
 *
 * vtkLightFieldReader and vtkMiddleburyImporter produce a vtkLightField on
 * their only output port; these functions are the parts of their pipeline
 * requests that do not depend on the file format.
 */
#ifndef lfdLightFieldOutput_h
#define lfdLightFieldOutput_h

class vtkInformationVector;
class vtkLightField;

namespace lfd
{
namespace io
{
/**
 * REQUEST_INFORMATION: the whole extent of `views` views of width x height
 * pixels, unit spacing and zero origin.
 */
void SetLightFieldInformation(vtkInformationVector* outputs, int width, int height, int views);

}
}

#endif

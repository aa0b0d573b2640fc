#include "lfdLightFieldOutput.h"

#include "vtkCameraRig.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace lfd
{
namespace io
{
//------------------------------------------------------------------------------
void SetLightFieldInformation(vtkInformationVector* outputs, int width, int height, int views)
{
  int extent[6] = { 0, width - 1, 0, height - 1, 0, views - 1 };
  vtkInformation* info = outputs->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
}

}
}

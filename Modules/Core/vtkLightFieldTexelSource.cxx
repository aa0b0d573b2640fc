#include "vtkLightFieldTexelSource.h"

//------------------------------------------------------------------------------
void vtkLightFieldTexelSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

#include "vtkLightFieldActor.h"

#include "vtkLightFieldMapper.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <algorithm>

vtkStandardNewMacro(vtkLightFieldActor);
vtkCxxSetObjectMacro(vtkLightFieldActor, Mapper, vtkLightFieldMapper);

//------------------------------------------------------------------------------
vtkLightFieldActor::vtkLightFieldActor() = default;

//------------------------------------------------------------------------------
vtkLightFieldActor::~vtkLightFieldActor()
{
  this->SetMapper(nullptr);
}

//------------------------------------------------------------------------------
double* vtkLightFieldActor::GetBounds()
{
  return this->Mapper ? this->Mapper->GetBounds() : nullptr;
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::RenderOpaqueGeometry(vtkViewport* viewport)
{
  vtkRenderer* renderer = vtkRenderer::SafeDownCast(viewport);
  if (!this->Mapper || !renderer)
  {
    return 0;
  }
  this->Mapper->Render(renderer);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Mapper)
  {
    this->Mapper->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldActor::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  return this->Mapper ? std::max(mtime, this->Mapper->GetMTime()) : mtime;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper: " << this->Mapper << "\n";
}

#include "vtkCameraFrustumSource.h"

#include "lfdPinholeCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>

vtkStandardNewMacro(vtkCameraFrustumSource);
vtkCxxSetObjectMacro(vtkCameraFrustumSource, Rig, vtkCameraRig);

namespace
{
// A frustum depth in proportion to the rig: cameras a quarter of the way to
// the axis do not hide the object.
double RigDepth(vtkCameraRig* rig)
{
  if (rig->HasCylinder() && rig->GetRadius() > 0.0)
  {
    return 0.25 * rig->GetRadius();
  }
  if (rig->GetNumberOfViews() > 1)
  {
    const glm::dvec3 spacing = rig->GetCamera(1).Center() - rig->GetCamera(0).Center();
    if (glm::length(spacing) > 0.0)
    {
      return 0.25 * glm::length(spacing);
    }
  }
  return 1.0;
}
}

//------------------------------------------------------------------------------
vtkCameraFrustumSource::vtkCameraFrustumSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkCameraFrustumSource::~vtkCameraFrustumSource()
{
  this->SetRig(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCameraFrustumSource::GetMTime()
{
  const vtkMTimeType time = this->Superclass::GetMTime();
  return this->Rig ? std::max(time, this->Rig->GetMTime()) : time;
}

//------------------------------------------------------------------------------
int vtkCameraFrustumSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!this->Rig || this->Rig->GetNumberOfViews() == 0)
  {
    return 1;
  }
  this->UsedDepth = this->Depth > 0.0 ? this->Depth : RigDepth(this->Rig);
  const int* size = this->Rig->GetImageSize();
  const int first = this->View < 0 ? 0 : std::min(this->View, this->Rig->GetNumberOfViews());
  const int last = this->View < 0 ? this->Rig->GetNumberOfViews()
                                  : std::min(this->View + 1, this->Rig->GetNumberOfViews());
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkIntArray> views, rows;
  views->SetName("View");
  rows->SetName("Row");
  // The image corners, outer edges of the corner pixels, clockwise on the
  // image (x right, y down).
  const glm::dvec2 corners[4] = { { -0.5, -0.5 },
    { size[0] - 0.5, -0.5 },
    { size[0] - 0.5, size[1] - 0.5 },
    { -0.5, size[1] - 0.5 } };
  for (int view = first; view < last; ++view)
  {
    const lfd::PinholeCamera& camera = this->Rig->GetCamera(view);
    const glm::dvec3 apex = camera.Center();
    const vtkIdType base = points->InsertNextPoint(apex.x, apex.y, apex.z);
    for (const glm::dvec2& corner : corners)
    {
      const glm::dvec3 p = camera.Unproject(corner, this->UsedDepth);
      points->InsertNextPoint(p.x, p.y, p.z);
    }
    for (int side = 0; side < 4; ++side)
    {
      const vtkIdType triangle[3] = { base, base + 1 + side, base + 1 + (side + 1) % 4 };
      polygons->InsertNextCell(3, triangle);
    }
    const vtkIdType quad[4] = { base + 1, base + 4, base + 3, base + 2 };
    polygons->InsertNextCell(4, quad);
    const int row = this->Rig->HasCylinder() ? this->Rig->GetRow(view) : 0;
    for (int cell = 0; cell < 5; ++cell)
    {
      views->InsertNextValue(view);
      rows->InsertNextValue(row);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polygons);
  output->GetCellData()->AddArray(views);
  output->GetCellData()->AddArray(rows);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCameraFrustumSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Rig: " << this->Rig << "\n";
  os << indent << "Depth: " << this->Depth << "\n";
  os << indent << "View: " << this->View << "\n";
}

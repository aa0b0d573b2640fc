#include "vtkLightFieldSceneInitializer.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLabelPropagation.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightFieldSceneInitializer);

namespace
{
// View 0 painted label 1 all over, for a hull whose labels do not matter.
vtkSmartPointer<vtkImageData> PaintedAllOne(vtkLightField* lightField)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(lightField->GetWidth(), lightField->GetHeight(), 1);
  vtkNew<vtkUnsignedCharArray> painted;
  painted->SetNumberOfTuples(
    static_cast<vtkIdType>(lightField->GetWidth()) * lightField->GetHeight());
  painted->FillValue(1);
  image->GetPointData()->SetScalars(painted);
  return image;
}

// The labelled voxels of `proxy` whose coordinate along the longest side of
// its bounds lies between the `fraction` and 1 - `fraction` quantiles of
// their label's: a visual hull cannot carve the hollows between parts, and
// the few voxels of one part standing in such a hollow beside the next part
// would otherwise move the slab boundary between them (vtkPartCageSource
// takes each part's extent from its extreme voxels).
vtkSmartPointer<vtkPolyData> TrimLabelExtents(vtkPolyData* proxy, double fraction)
{
  double bounds[6];
  proxy->GetBounds(bounds);
  int axis = 0;
  for (int c = 1; c < 3; ++c)
  {
    axis = bounds[2 * c + 1] - bounds[2 * c] > bounds[2 * axis + 1] - bounds[2 * axis] ? c : axis;
  }
  vtkDataArray* labels = proxy->GetCellData()->GetArray("Label");
  std::map<int, std::vector<double>> along;
  for (vtkIdType i = 0; i < proxy->GetNumberOfPoints(); ++i)
  {
    along[static_cast<int>(labels->GetComponent(i, 0))].push_back(proxy->GetPoint(i)[axis]);
  }
  std::map<int, std::pair<double, double>> kept;
  for (auto& part : along)
  {
    std::vector<double>& values = part.second;
    std::sort(values.begin(), values.end());
    const size_t cut = static_cast<size_t>(fraction * (values.size() - 1));
    kept[part.first] = { values[cut], values[values.size() - 1 - cut] };
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkUnsignedCharArray> trimmed;
  trimmed->SetName("Label");
  for (vtkIdType i = 0; i < proxy->GetNumberOfPoints(); ++i)
  {
    const int label = static_cast<int>(labels->GetComponent(i, 0));
    const double* point = proxy->GetPoint(i);
    if (point[axis] >= kept[label].first && point[axis] <= kept[label].second)
    {
      const vtkIdType id = points->InsertNextPoint(point);
      vertices->InsertNextCell(1, &id);
      trimmed->InsertNextValue(static_cast<unsigned char>(label));
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetVerts(vertices);
  result->GetCellData()->AddArray(trimmed);
  return result;
}

// A camera at view 0's centre with its "up", looking at the bounds' centre,
// holding their sphere with 10 % to spare.
void FrameBounds(vtkCameraRig* rig, const double bounds[6], vtkCamera* camera)
{
  double position[3];
  double up[3];
  rig->GetCameraCenter(0, position);
  rig->GetViewUp(0, up);
  const double centre[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double low[3] = { bounds[0], bounds[2], bounds[4] };
  const double high[3] = { bounds[1], bounds[3], bounds[5] };
  const double radius = 0.5 * std::sqrt(vtkMath::Distance2BetweenPoints(low, high));
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(position, centre));
  camera->SetPosition(position);
  camera->SetFocalPoint(centre);
  camera->SetViewUp(up);
  camera->OrthogonalizeViewUp();
  // A camera inside the sphere keeps the captured view's angle.
  camera->SetViewAngle(distance > 1.1 * radius
      ? 2.0 * vtkMath::DegreesFromRadians(std::asin(1.1 * radius / distance))
      : rig->GetViewAngle(0));
}
}

//------------------------------------------------------------------------------
vtkLightFieldSceneInitializer::vtkLightFieldSceneInitializer() = default;

//------------------------------------------------------------------------------
vtkLightFieldSceneInitializer::~vtkLightFieldSceneInitializer() = default;

//------------------------------------------------------------------------------
bool vtkLightFieldSceneInitializer::Initialize(vtkLightFieldSceneLogic* logic)
{
  vtkLightField* lightField = logic ? logic->GetLightField() : nullptr;
  if (!lightField)
  {
    vtkErrorMacro(<< "Initialize: the scene has no light field");
    return false;
  }
  vtkDataArray* labels = lightField->GetPass(vtkLightField::LABEL);
  if (this->BoxMode == LABELS && !labels)
  {
    vtkErrorMacro(<< "the light field has no Label pass to put one box per label around: split it "
                     "first (lfd split) or ask for slabs or one box");
    return false;
  }
  // The hull, labelled by every view's Label pass (or by one view painted
  // label 1 when the labels do not matter).
  vtkNew<vtkLabelPropagation> hull;
  hull->SetInputData(lightField);
  hull->SetProxy(vtkLabelPropagation::VISUAL_HULL);
  hull->SetResolution(this->Resolution);
  hull->SetThreshold(this->Threshold);
  const bool byLabel = this->BoxMode == LABELS;
  if (byLabel)
  {
    hull->SetPaintedViews(labels, lightField->GetWidth(), lightField->GetHeight());
  }
  else
  {
    hull->SetPaintedView(0, PaintedAllOne(lightField));
  }
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(hull);
  hull->Update();
  if (errors->HasError() || hull->GetErrorCode() != 0)
  {
    vtkErrorMacro(<< "the object's visual hull: "
                  << (errors->HasError() ? errors->GetErrorMessage() : "failed"));
    return false;
  }
  vtkPolyData* proxy = hull->GetProxyVoxels();
  proxy->GetBounds(this->ObjectBounds);

  vtkCameraRig* rig = lightField->GetRig();
  vtkNew<vtkCamera> camera;
  FrameBounds(rig, this->ObjectBounds, camera);
  if (!logic->SetSize(rig->GetImageSize()[0], rig->GetImageSize()[1]) ||
    !logic->SetCamera(camera) || (!labels && !logic->SetObjectThreshold(this->Threshold)))
  {
    return false; // the logic said why
  }
  if (byLabel)
  {
    return logic->BuildCageFromLabels(TrimLabelExtents(proxy, this->OutlierFraction), -1);
  }
  double grown[6];
  double size = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    size = std::max(size, this->ObjectBounds[2 * c + 1] - this->ObjectBounds[2 * c]);
  }
  for (int c = 0; c < 3; ++c)
  {
    grown[2 * c] = this->ObjectBounds[2 * c] - this->Margin * size;
    grown[2 * c + 1] = this->ObjectBounds[2 * c + 1] + this->Margin * size;
  }
  int axis = -1; // the ring axis
  if (!rig->HasCylinder())
  {
    axis = 0;
    for (int c = 1; c < 3; ++c)
    {
      axis = grown[2 * c + 1] - grown[2 * c] > grown[2 * axis + 1] - grown[2 * axis] ? c : axis;
    }
  }
  return logic->BuildCageFromSlabs(
    grown, this->BoxMode == SLABS ? this->NumberOfSlabs : 1, axis, 1);
}

//------------------------------------------------------------------------------
void vtkLightFieldSceneInitializer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BoxMode: " << this->BoxMode << "\n";
  os << indent << "NumberOfSlabs: " << this->NumberOfSlabs << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "OutlierFraction: " << this->OutlierFraction << "\n";
  os << indent << "ObjectBounds: (" << this->ObjectBounds[0] << ", " << this->ObjectBounds[1]
     << ", " << this->ObjectBounds[2] << ", " << this->ObjectBounds[3] << ", "
     << this->ObjectBounds[4] << ", " << this->ObjectBounds[5] << ")\n";
}

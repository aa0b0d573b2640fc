#include "vtkBoxCoverageCheck.h"

#include "lfdRequestGuard.h"

#include "lfdPinholeCamera.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDeformationCage.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLightField.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <map>
#include <set>

vtkStandardNewMacro(vtkBoxCoverageCheck);

namespace
{
using Polygon = std::vector<glm::dvec2>;

double Cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b)
{
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Convex hull, counter-clockwise (Andrew's monotone chain).
Polygon ConvexHull(Polygon points)
{
  std::sort(points.begin(),
    points.end(),
    [](const glm::dvec2& a, const glm::dvec2& b)
    { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Polygon hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
  {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  hull.resize(k > 0 ? k - 1 : 0);
  return hull;
}

bool Inside(const Polygon& hull, const glm::dvec2& p)
{
  if (hull.size() < 3)
  {
    return false;
  }
  for (size_t i = 0; i < hull.size(); ++i)
  {
    if (Cross(hull[i], hull[(i + 1) % hull.size()], p) < 0.0)
    {
      return false;
    }
  }
  return true;
}

// The rest boxes of each label projected into a view: the convex hull of
// the 8 projected corners (a box partly behind the camera is left out).
std::map<int, std::vector<Polygon>> ProjectBoxes(vtkDeformationCage* cage,
  const lfd::PinholeCamera& camera)
{
  std::map<int, std::vector<Polygon>> hulls;
  for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
  {
    double rest[24];
    if (!cage->GetRestCorners(box, rest))
    {
      continue;
    }
    Polygon corners;
    for (int c = 0; c < 8; ++c)
    {
      glm::dvec2 pixel;
      if (camera.Project(glm::dvec3(rest[3 * c], rest[3 * c + 1], rest[3 * c + 2]), pixel))
      {
        corners.push_back(pixel);
      }
    }
    if (corners.size() == 8)
    {
      hulls[cage->GetBoxLabel(box)].push_back(ConvexHull(corners));
    }
  }
  return hulls;
}
}

//------------------------------------------------------------------------------
vtkBoxCoverageCheck::vtkBoxCoverageCheck()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoxCoverageCheck::~vtkBoxCoverageCheck() = default;

//------------------------------------------------------------------------------
void vtkBoxCoverageCheck::SetCageConnection(vtkAlgorithmOutput* cage)
{
  this->SetInputConnection(1, cage);
}

//------------------------------------------------------------------------------
void vtkBoxCoverageCheck::SetCageData(vtkDataObject* cage)
{
  this->SetInputDataObject(1, cage);
}

//------------------------------------------------------------------------------
int vtkBoxCoverageCheck::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(
    vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkLightField" : "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoxCoverageCheck::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkTable" : "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
vtkImageData* vtkBoxCoverageCheck::GetOutsideMask()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkBoxCoverageCheck::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->Labels.clear();
  this->LabelsWithoutBox.clear();
  this->BoxLabelsWithoutPixels.clear();
  this->ViewCoverage.clear();
  vtkLightField* lightField = vtkLightField::GetData(inputVector[0]);
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::GetData(inputVector[1]);
  vtkTable* output = vtkTable::GetData(outputVector, 0);
  auto* labels = lightField
    ? vtkUnsignedCharArray::SafeDownCast(lightField->GetPass(vtkLightField::LABEL))
    : nullptr;
  if (!labels || !grid)
  {
    vtkErrorMacro(<< (labels ? "No cage on input port 1."
                             : "The light field has no Label pass to check."));
    return 0;
  }
  const std::string why = vtkDeformationCage::CheckGridArrays(grid);
  if (!why.empty())
  {
    vtkErrorMacro("Input port 1: " << why << ".");
    return 0;
  }
  vtkNew<vtkDeformationCage> cage;
  cage->InitializeFromGrid(grid);
  const int width = lightField->GetWidth();
  const int height = lightField->GetHeight();
  const int views = lightField->GetNumberOfViews();
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkCameraRig* rig = lightField->GetRig();

  vtkNew<vtkIntArray> labelColumn, viewColumn;
  vtkNew<vtkIdTypeArray> pixelColumn, insideColumn;
  vtkNew<vtkDoubleArray> fractionColumn;
  labelColumn->SetName("Label");
  viewColumn->SetName("View");
  pixelColumn->SetName("Pixels");
  insideColumn->SetName("Inside");
  fractionColumn->SetName("Fraction");
  std::map<int, Summary> summaries;
  vtkImageData* outsideMask = vtkImageData::GetData(outputVector, 1);
  outsideMask->SetDimensions(width, height, views);
  vtkNew<vtkUnsignedCharArray> outside;
  outside->SetName("Outside");
  outside->SetNumberOfTuples(pixels * views);
  outside->FillValue(0);
  outsideMask->GetPointData()->SetScalars(outside);
  for (int view = 0; view < views; ++view)
  {
    std::map<int, std::vector<Polygon>> hulls = ProjectBoxes(cage, rig->GetCamera(view));
    std::map<int, std::pair<vtkIdType, vtkIdType>> counts; // label -> (pixels, inside)
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      const int label = labels->GetValue(view * pixels + p);
      if (label == 0)
      {
        continue;
      }
      auto& count = counts[label];
      ++count.first;
      const glm::dvec2 pixel(static_cast<double>(p % width), height - 1.0 - p / width);
      const auto& boxes = hulls[label];
      if (std::any_of(
            boxes.begin(), boxes.end(), [&](const Polygon& h) { return Inside(h, pixel); }))
      {
        ++count.second;
      }
      else
      {
        outside->SetValue(view * pixels + p, 1);
      }
    }
    double coverage = 1.0;
    for (const auto& entry : counts)
    {
      const double fraction = static_cast<double>(entry.second.second) / entry.second.first;
      labelColumn->InsertNextValue(entry.first);
      viewColumn->InsertNextValue(view);
      pixelColumn->InsertNextValue(entry.second.first);
      insideColumn->InsertNextValue(entry.second.second);
      fractionColumn->InsertNextValue(fraction);
      coverage = std::min(coverage, fraction);
      auto found = summaries.find(entry.first);
      if (found == summaries.end())
      {
        found = summaries.emplace(entry.first, Summary{ entry.first, 2.0, -1, {} }).first;
      }
      Summary& summary = found->second;
      if (fraction < summary.WorstFraction)
      {
        summary.WorstFraction = fraction;
        summary.WorstView = view;
      }
      if (fraction < this->Threshold)
      {
        summary.Below.push_back(view);
      }
    }
    this->ViewCoverage.push_back(coverage);
    this->UpdateProgress(static_cast<double>(view + 1) / views);
  }
  output->AddColumn(labelColumn);
  output->AddColumn(viewColumn);
  output->AddColumn(pixelColumn);
  output->AddColumn(insideColumn);
  output->AddColumn(fractionColumn);
  std::set<int> boxLabels;
  for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
  {
    boxLabels.insert(cage->GetBoxLabel(box));
  }
  for (const auto& entry : summaries)
  {
    this->Labels.push_back(entry.second);
    if (!boxLabels.count(entry.first))
    {
      this->LabelsWithoutBox.push_back(entry.first);
    }
  }
  for (int label : boxLabels)
  {
    if (!summaries.count(label))
    {
      this->BoxLabelsWithoutPixels.push_back(label);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkBoxCoverageCheck::GetLabel(int index) const
{
  return index >= 0 && index < this->GetNumberOfLabels() ? this->Labels[index].Label : -1;
}

//------------------------------------------------------------------------------
double vtkBoxCoverageCheck::GetWorstFraction(int index) const
{
  return index >= 0 && index < this->GetNumberOfLabels() ? this->Labels[index].WorstFraction : 0.0;
}

//------------------------------------------------------------------------------
int vtkBoxCoverageCheck::GetWorstView(int index) const
{
  return index >= 0 && index < this->GetNumberOfLabels() ? this->Labels[index].WorstView : -1;
}

//------------------------------------------------------------------------------
std::vector<int> vtkBoxCoverageCheck::GetViewsBelow(int index) const
{
  return index >= 0 && index < this->GetNumberOfLabels() ? this->Labels[index].Below
                                                         : std::vector<int>();
}

//------------------------------------------------------------------------------
double vtkBoxCoverageCheck::GetViewCoverage(int view) const
{
  return view >= 0 && view < static_cast<int>(this->ViewCoverage.size()) ? this->ViewCoverage[view]
                                                                         : -1.0;
}

//------------------------------------------------------------------------------
bool vtkBoxCoverageCheck::GetPassed() const
{
  return std::all_of(this->Labels.begin(),
    this->Labels.end(),
    [](const Summary& summary) { return summary.Below.empty(); });
}

//------------------------------------------------------------------------------
void vtkBoxCoverageCheck::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Labels: " << this->Labels.size() << "\n";
}

//------------------------------------------------------------------------------
lfdGuardedProcessRequestMacro(vtkBoxCoverageCheck);

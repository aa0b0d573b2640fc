#include "vtkCagePoseFilter.h"

#include "vtkDeformationCage.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkCagePoseFilter);

namespace
{
/// Rodrigues' rotation of `v` about the unit vector `axis` by `angle`
/// radians.
void Rotate(const double axis[3], double angle, const double v[3], double out[3])
{
  const double c = std::cos(angle), s = std::sin(angle);
  double cross[3];
  vtkMath::Cross(axis, v, cross);
  const double along = vtkMath::Dot(axis, v) * (1.0 - c);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = v[i] * c + cross[i] * s + axis[i] * along;
  }
}

/// sin(phi) / phi and (1 - cos(phi)) / phi, the arc's chord terms, without
/// dividing by a tiny phi.
void ArcTerms(double phi, double& sinc, double& cosc)
{
  if (std::abs(phi) < 1e-8)
  {
    sinc = 1.0 - phi * phi / 6.0;
    cosc = 0.5 * phi;
    return;
  }
  sinc = std::sin(phi) / phi;
  cosc = (1.0 - std::cos(phi)) / phi;
}

/// The rest positions of the cage's points (x0 y0 z0 x1 ...), their axis
/// (`requested`, or the longest side of their bounds when it is -1) and
/// their length along it.
std::vector<double> RestPoints(vtkDeformationCage* cage, int requested, int& axis, double& length)
{
  const vtkIdType numberOfPoints = cage->GetNumberOfPoints();
  std::vector<double> rest(3 * numberOfPoints);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double* p = &rest[3 * i];
    cage->GetRestPoint(i, p);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  axis = requested;
  if (axis < 0)
  {
    axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      if (hi[a] - lo[a] > hi[axis] - lo[axis])
      {
        axis = a;
      }
    }
  }
  length = hi[axis] - lo[axis];
  return rest;
}

/// The layers of a cage: its points grouped by their rest coordinate along
/// the axis (equal within 1e-6 of the length), in increasing order.
struct Layers
{
  std::vector<int> Of;                       // the layer of each point
  std::vector<double> Coordinate;            // each layer's coordinate along the axis
  std::vector<std::array<double, 3>> Centre; // the mean of its points

  Layers(const std::vector<double>& rest, int axis, double length)
  {
    const vtkIdType numberOfPoints = static_cast<vtkIdType>(rest.size() / 3);
    std::vector<vtkIdType> order(numberOfPoints);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(),
      order.end(),
      [&](vtkIdType a, vtkIdType b) { return rest[3 * a + axis] < rest[3 * b + axis]; });
    const double tolerance = 1e-6 * (length > 0.0 ? length : 1.0);
    this->Of.resize(numberOfPoints);
    std::vector<int> count;
    double previous = 0.0;
    for (vtkIdType n = 0; n < numberOfPoints; ++n)
    {
      const double* p = &rest[3 * order[n]];
      if (n == 0 || p[axis] - previous > tolerance)
      {
        this->Coordinate.push_back(p[axis]);
        this->Centre.push_back({ 0.0, 0.0, 0.0 });
        count.push_back(0);
      }
      previous = p[axis];
      const int k = static_cast<int>(count.size()) - 1;
      this->Of[order[n]] = k;
      for (int a = 0; a < 3; ++a)
      {
        this->Centre[k][a] += p[a];
      }
      ++count[k];
    }
    for (size_t k = 0; k < count.size(); ++k)
    {
      for (int a = 0; a < 3; ++a)
      {
        this->Centre[k][a] /= count[k];
      }
    }
  }

  int GetNumberOfLayers() const { return static_cast<int>(this->Coordinate.size()); }
};
}

//------------------------------------------------------------------------------
vtkCagePoseFilter::vtkCagePoseFilter() {}

//------------------------------------------------------------------------------
vtkCagePoseFilter::~vtkCagePoseFilter() = default;

//------------------------------------------------------------------------------
void vtkCagePoseFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const modeNames[] = { "TWIST", "SWIM", "BEND" };
  os << indent << "Mode: " << modeNames[this->Mode] << "\n";
  os << indent << "Angle: " << this->Angle << "\n";
  os << indent << "Phase: " << this->Phase << "\n";
  os << indent << "Wavelength: " << this->Wavelength << "\n";
  os << indent << "Amplitude: " << this->Amplitude << "\n";
  os << indent << "Axis: " << this->Axis << "\n";
  os << indent << "TurnAxis: (" << this->TurnAxis[0] << ", " << this->TurnAxis[1] << ", "
     << this->TurnAxis[2] << ")\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers << "\n";
}

//------------------------------------------------------------------------------
int vtkCagePoseFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkCagePoseFilter::RequestData(vtkInformation*,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inInfo[0]);
  vtkDeformationCage* cage = vtkDeformationCage::GetData(outInfo);
  this->NumberOfLayers = 0;
  cage->InitializeFromGrid(input);
  if (!input)
  {
    vtkErrorMacro("No input cage on port 0.");
    return 0;
  }
  const vtkIdType numberOfPoints = cage->GetNumberOfPoints();
  if (numberOfPoints == 0)
  {
    vtkErrorMacro("The input cage has no points: there is nothing to pose.");
    return 0;
  }
  int axis = 0;
  double length = 0.0;
  const std::vector<double> rest = RestPoints(cage, this->Axis, axis, length);
  double direction[3] = { 0.0, 0.0, 0.0 };
  direction[axis] = 1.0;

  // The turn axis without its component along the slab axis, and the
  // sideways direction n = turn x axis, towards which a positive turn moves
  // the slab axis.
  double turn[3] = { this->TurnAxis[0], this->TurnAxis[1], this->TurnAxis[2] };
  turn[axis] = 0.0;
  const bool hasTurn = vtkMath::Normalize(turn) > 1e-12;
  if (this->Mode != TWIST && !hasTurn)
  {
    vtkErrorMacro("TurnAxis (" << this->TurnAxis[0] << ", " << this->TurnAxis[1] << ", "
                               << this->TurnAxis[2] << ") is parallel to the slab axis " << axis
                               << ": the layers cannot turn about it.");
    return 0;
  }
  double sideways[3] = { 0.0, 0.0, 0.0 };
  if (hasTurn)
  {
    vtkMath::Cross(turn, direction, sideways);
  }

  const Layers layers(rest, axis, length);
  const int numberOfLayers = layers.GetNumberOfLayers();
  const std::vector<double>& layerCoordinate = layers.Coordinate;

  // Per layer: the rotation axis and angle, and the new position of its
  // centre.
  const double angle = vtkMath::RadiansFromDegrees(this->Angle);
  const double first = layerCoordinate.front();
  const double middle = 0.5 * (first + layerCoordinate.back());
  std::vector<double> layerAngle(numberOfLayers);
  std::vector<std::array<double, 3>> layerTarget(layers.Centre);
  for (int k = 0; k < numberOfLayers; ++k)
  {
    const double t = length > 0.0 ? (layerCoordinate[k] - first) / length : 0.0;
    std::array<double, 3>& target = layerTarget[k];
    switch (this->Mode)
    {
      case TWIST:
        layerAngle[k] = angle * t;
        break;
      case SWIM:
      {
        const double wave = this->Phase - k * this->Wavelength;
        layerAngle[k] = angle * std::sin(wave);
        const double shift = this->Amplitude * length * std::sin(wave + 0.5);
        for (int a = 0; a < 3; ++a)
        {
          target[a] += shift * sideways[a];
        }
        break;
      }
      case BEND:
      {
        // The arc of length `length` turning by `angle`, centred on the
        // middle layer: arc length sigma from the middle turns the tangent
        // by phi = angle * sigma / length.
        const double sigma = layerCoordinate[k] - middle;
        const double phi = length > 0.0 ? angle * sigma / length : 0.0;
        layerAngle[k] = phi;
        double sinc, cosc;
        ArcTerms(phi, sinc, cosc);
        for (int a = 0; a < 3; ++a)
        {
          target[a] += sigma * (sinc - 1.0) * direction[a] + sigma * cosc * sideways[a];
        }
        break;
      }
    }
  }

  const double* rotationAxis = this->Mode == TWIST ? direction : turn;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const int k = layers.Of[i];
    const double* p = &rest[3 * i];
    const std::array<double, 3>& centre = layers.Centre[k];
    const double offset[3] = { p[0] - centre[0], p[1] - centre[1], p[2] - centre[2] };
    double rotated[3];
    Rotate(rotationAxis, layerAngle[k], offset, rotated);
    const double q[3] = {
      layerTarget[k][0] + rotated[0], layerTarget[k][1] + rotated[1], layerTarget[k][2] + rotated[2]
    };
    cage->SetDeformedPoint(i, q);
  }
  this->NumberOfLayers = numberOfLayers;
  return 1;
}

#include "vtkKeyframeInterpolator.h"

#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkKeyframeInterpolator);

struct vtkKeyframeInterpolator::Internals
{
  struct Keyframe
  {
    double Time;
    vtkSmartPointer<vtkPoints> Points;
  };
  std::vector<Keyframe> Keyframes; // sorted by time
};

//------------------------------------------------------------------------------
vtkKeyframeInterpolator::vtkKeyframeInterpolator()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkKeyframeInterpolator::~vtkKeyframeInterpolator() = default;

//------------------------------------------------------------------------------
bool vtkKeyframeInterpolator::AddKeyframe(double time, vtkPoints* points)
{
  auto& keyframes = this->Internal->Keyframes;
  if (!points)
  {
    vtkErrorMacro("Keyframe at time " << time << " has no points.");
    return false;
  }
  if (!keyframes.empty() &&
    keyframes.front().Points->GetNumberOfPoints() != points->GetNumberOfPoints())
  {
    vtkErrorMacro("Keyframe at time " << time << " has " << points->GetNumberOfPoints()
                                      << " points; the keyframes before it have "
                                      << keyframes.front().Points->GetNumberOfPoints() << ".");
    return false;
  }
  const auto at = std::lower_bound(keyframes.begin(),
    keyframes.end(),
    time,
    [](const Internals::Keyframe& k, double t) { return k.Time < t; });
  if (at != keyframes.end() && at->Time == time)
  {
    vtkErrorMacro("Two keyframes at time " << time << ".");
    return false;
  }
  auto copy = vtkSmartPointer<vtkPoints>::New();
  copy->SetDataTypeToDouble();
  copy->DeepCopy(points);
  keyframes.insert(at, { time, copy });
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkKeyframeInterpolator::RemoveAllKeyframes()
{
  this->Internal->Keyframes.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkKeyframeInterpolator::GetNumberOfKeyframes() const
{
  return static_cast<int>(this->Internal->Keyframes.size());
}

//------------------------------------------------------------------------------
double vtkKeyframeInterpolator::GetStartTime() const
{
  return this->Internal->Keyframes.empty() ? 0.0 : this->Internal->Keyframes.front().Time;
}

//------------------------------------------------------------------------------
double vtkKeyframeInterpolator::GetEndTime() const
{
  return this->Internal->Keyframes.empty() ? 0.0 : this->Internal->Keyframes.back().Time;
}

//------------------------------------------------------------------------------
bool vtkKeyframeInterpolator::InterpolatePoints(double time, vtkPoints* points) const
{
  const auto& keyframes = this->Internal->Keyframes;
  if (keyframes.empty() || !points)
  {
    return false;
  }
  const int n = static_cast<int>(keyframes.size());
  // Segment [k, k + 1] holding the time, and the position f in it.
  int k = 0;
  while (k + 1 < n && keyframes[k + 1].Time <= time)
  {
    ++k;
  }
  double f = 0.0;
  if (k + 1 < n && time > keyframes[k].Time)
  {
    f = (time - keyframes[k].Time) / (keyframes[k + 1].Time - keyframes[k].Time);
  }
  const int k1 = std::min(k + 1, n - 1);
  const int k0 = std::max(k - 1, 0);
  const int k2 = std::min(k + 2, n - 1);
  const vtkIdType count = keyframes.front().Points->GetNumberOfPoints();
  points->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p0[3], p1[3], p2[3], p3[3], out[3];
    keyframes[k0].Points->GetPoint(i, p0);
    keyframes[k].Points->GetPoint(i, p1);
    keyframes[k1].Points->GetPoint(i, p2);
    keyframes[k2].Points->GetPoint(i, p3);
    for (int c = 0; c < 3; ++c)
    {
      if (this->Interpolation == LINEAR)
      {
        out[c] = (1.0 - f) * p1[c] + f * p2[c];
      }
      else
      {
        // Uniform Catmull-Rom: tangents (p2 - p0) / 2 and (p3 - p1) / 2.
        const double f2 = f * f;
        const double f3 = f2 * f;
        out[c] = 0.5 *
          (2.0 * p1[c] + (p2[c] - p0[c]) * f +
            (2.0 * p0[c] - 5.0 * p1[c] + 4.0 * p2[c] - p3[c]) * f2 +
            (3.0 * p1[c] - p0[c] - 3.0 * p2[c] + p3[c]) * f3);
      }
    }
    points->SetPoint(i, out);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkKeyframeInterpolator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Interpolation: " << (this->Interpolation == LINEAR ? "Linear" : "CatmullRom")
     << "\n";
  os << indent << "NumberOfKeyframes: " << this->GetNumberOfKeyframes() << "\n";
  for (const auto& keyframe : this->Internal->Keyframes)
  {
    os << indent << "  time " << keyframe.Time << ": " << keyframe.Points->GetNumberOfPoints()
       << " points\n";
  }
}

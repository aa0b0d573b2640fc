#include "vtkLabelPalette.h"

#include "lfdColour.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkLabelPalette);

namespace
{
// Smallest distance between the chosen candidates, using the distance table.
double SmallestDistance(const std::vector<int>& chosen, const std::vector<double>& distance, int n)
{
  double smallest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < chosen.size(); ++a)
  {
    for (size_t b = a + 1; b < chosen.size(); ++b)
    {
      smallest = std::min(smallest, distance[chosen[a] * n + chosen[b]]);
    }
  }
  return smallest;
}
}

//------------------------------------------------------------------------------
vtkLabelPalette::vtkLabelPalette() = default;

//------------------------------------------------------------------------------
void vtkLabelPalette::BuildDefault(int largestLabel, vtkUnsignedCharArray* palette)
{
  const int labels = std::max(1, std::min(largestLabel, 255));
  vtkNew<vtkLabelPalette> builder;
  // Levels^3 - 1 candidates (black is not one).
  int levels = builder->GetLevels();
  while (levels * levels * levels - 1 < labels)
  {
    ++levels;
  }
  builder->SetLevels(levels);
  builder->SetNumberOfLabels(labels);
  builder->Build(palette);
}

//------------------------------------------------------------------------------
bool vtkLabelPalette::Build(vtkUnsignedCharArray* palette)
{
  if (!palette)
  {
    vtkErrorMacro("Build: no palette array given.");
    return false;
  }
  // Candidates: every projector colour on the Levels grid but black.
  std::vector<glm::dvec3> candidates;
  for (int r = 0; r < this->Levels; ++r)
  {
    for (int g = 0; g < this->Levels; ++g)
    {
      for (int b = 0; b < this->Levels; ++b)
      {
        if (r + g + b > 0)
        {
          const double step = 255.0 / (this->Levels - 1);
          candidates.emplace_back(std::round(r * step), std::round(g * step), std::round(b * step));
        }
      }
    }
  }
  const int n = static_cast<int>(candidates.size());
  if (this->NumberOfLabels > n)
  {
    vtkErrorMacro("Cannot choose " << this->NumberOfLabels << " label colours from " << n
                                   << " candidates; raise Levels.");
    return false;
  }
  // What the camera sees of each candidate, and all pairwise distances.
  const double* m = this->ColourResponse;
  std::vector<glm::dvec3> lab(n);
  for (int i = 0; i < n; ++i)
  {
    const glm::dvec3& c = candidates[i];
    lab[i] = lfd::SrgbToLab(glm::clamp(glm::dvec3(m[0] * c.x + m[1] * c.y + m[2] * c.z,
                                         m[3] * c.x + m[4] * c.y + m[5] * c.z,
                                         m[6] * c.x + m[7] * c.y + m[8] * c.z),
      0.0,
      255.0));
  }
  std::vector<double> distance(static_cast<size_t>(n) * n, 0.0);
  for (int a = 0; a < n; ++a)
  {
    for (int b = a + 1; b < n; ++b)
    {
      distance[a * n + b] = distance[b * n + a] = glm::length(lab[a] - lab[b]);
    }
  }

  // Greedy farthest points from the farthest pair (or the brightest colour
  // for a single label), then single swaps while the smallest distance grows.
  std::vector<int> chosen;
  if (this->NumberOfLabels == 1)
  {
    chosen.push_back(n - 1);
  }
  else
  {
    int bestA = 0, bestB = 1;
    for (int a = 0; a < n; ++a)
    {
      for (int b = a + 1; b < n; ++b)
      {
        if (distance[a * n + b] > distance[bestA * n + bestB])
        {
          bestA = a;
          bestB = b;
        }
      }
    }
    chosen = { bestA, bestB };
  }
  while (static_cast<int>(chosen.size()) < this->NumberOfLabels)
  {
    int best = -1;
    double bestDistance = -1.0;
    for (int c = 0; c < n; ++c)
    {
      if (std::find(chosen.begin(), chosen.end(), c) != chosen.end())
      {
        continue;
      }
      double nearest = std::numeric_limits<double>::infinity();
      for (int k : chosen)
      {
        nearest = std::min(nearest, distance[c * n + k]);
      }
      if (nearest > bestDistance)
      {
        bestDistance = nearest;
        best = c;
      }
    }
    chosen.push_back(best);
  }
  double current = SmallestDistance(chosen, distance, n);
  for (bool improved = true; improved && chosen.size() > 1;)
  {
    improved = false;
    for (size_t slot = 0; slot < chosen.size(); ++slot)
    {
      for (int c = 0; c < n; ++c)
      {
        if (std::find(chosen.begin(), chosen.end(), c) != chosen.end())
        {
          continue;
        }
        std::vector<int> trial = chosen;
        trial[slot] = c;
        const double d = SmallestDistance(trial, distance, n);
        if (d > current + 1e-9)
        {
          chosen = trial;
          current = d;
          improved = true;
        }
      }
    }
  }
  this->MinimumDistance = chosen.size() > 1 ? current : 0.0;

  palette->Initialize();
  palette->SetName("LabelPalette");
  palette->SetNumberOfComponents(3);
  palette->SetNumberOfTuples(this->NumberOfLabels + 1);
  const unsigned char black[3] = { 0, 0, 0 };
  palette->SetTypedTuple(0, black);
  for (int label = 1; label <= this->NumberOfLabels; ++label)
  {
    const glm::dvec3& c = candidates[chosen[label - 1]];
    const unsigned char rgb[3] = { static_cast<unsigned char>(c.x),
      static_cast<unsigned char>(c.y),
      static_cast<unsigned char>(c.z) };
    palette->SetTypedTuple(label, rgb);
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
double vtkLabelPalette::GetSeparation(vtkUnsignedCharArray* palette)
{
  if (!palette || palette->GetNumberOfComponents() != 3 || palette->GetNumberOfTuples() < 3)
  {
    return 0.0;
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (vtkIdType a = 1; a < palette->GetNumberOfTuples(); ++a)
  {
    for (vtkIdType b = a + 1; b < palette->GetNumberOfTuples(); ++b)
    {
      const glm::dvec3 ca(palette->GetTypedComponent(a, 0),
        palette->GetTypedComponent(a, 1),
        palette->GetTypedComponent(a, 2));
      const glm::dvec3 cb(palette->GetTypedComponent(b, 0),
        palette->GetTypedComponent(b, 1),
        palette->GetTypedComponent(b, 2));
      smallest = std::min(smallest, lfd::ColourDistance(ca, cb));
    }
  }
  return smallest;
}

//------------------------------------------------------------------------------
void vtkLabelPalette::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLabels: " << this->NumberOfLabels << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "ColourResponse:";
  for (double v : this->ColourResponse)
  {
    os << " " << v;
  }
  os << "\n";
  os << indent << "MinimumDistance: " << this->MinimumDistance << "\n";
}

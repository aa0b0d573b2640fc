/**
 * @file   lfdViewCoverage.h
 * @brief  Where a view's rays are looked up on a cylindrical light field.
 *
 * The renderer looks a ray up where its line enters the rig cylinder on the
 * camera side (Chen, Ofek, Shum and Levoy 2005, Sec. 6.2) and clamps a
 * height beyond the outermost rows to them. Whether a view is covered by
 * the captured rows is therefore a question about those entry points: these
 * helpers follow the rays from an eye to a few points of what it looks at
 * (the corners and the centre of a bounding box). vtkCameraRig uses them to
 * warn about extrapolation and vtkLightFieldCapture to place rows that cover
 * given eyes.
 *
 * Plain C++17 + GLM, no VTK.
 */
#ifndef lfdViewCoverage_h
#define lfdViewCoverage_h

#include "lfdCylinderSampling.h"

#include <glm/glm.hpp>

#include <array>

namespace lfd
{

/// The 8 corners and the centre of axis-aligned bounds (xmin, xmax, ymin,
/// ymax, zmin, zmax): the points a view of the box is followed to.
inline std::array<glm::dvec3, 9> BoundsProbes(const double bounds[6])
{
  std::array<glm::dvec3, 9> probes;
  for (int corner = 0; corner < 8; ++corner)
  {
    for (int c = 0; c < 3; ++c)
    {
      probes[corner][c] = bounds[2 * c + ((corner >> c) & 1)];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    probes[8][c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
  }
  return probes;
}

/**
 * The point where the line from `eye` through `target` enters the cylinder
 * on the eye's side (the lookup point of Sec. 6.2; behind the eye when the
 * eye is inside the cylinder). Returns false when the line misses the
 * cylinder, runs along its axis, or `target` is the eye.
 */
inline bool RayEntry(const Cylinder& cylinder,
  const glm::dvec3& eye,
  const glm::dvec3& target,
  glm::dvec3& entry)
{
  double s = 0.0;
  if (target == eye || !IntersectCylinderEntry(cylinder, eye, target - eye, s))
  {
    return false;
  }
  entry = eye + s * (target - eye);
  return true;
}

}

#endif

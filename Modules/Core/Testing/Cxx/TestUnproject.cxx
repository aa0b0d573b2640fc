// lfd::PinholeCamera::Unproject and the perspective depth conversions of
// lfdPerspectiveDepth.h: projecting a point and unprojecting its pixel at its
// camera z gives the point back; window depth and distance are inverses, with
// the near and far planes at 0 and 1.
#include "lfdPerspectiveDepth.h"
#include "lfdPinholeCamera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

int TestUnproject(int, char*[])
{
  int failures = 0;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);

  lfd::PinholeCamera camera;
  camera.K = glm::transpose(glm::dmat3(500, 0.5, 320, 0, 510, 240, 0, 0, 1));
  const glm::dmat4 turn =
    glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(0.3, 1.0, -0.2)));
  camera.R = glm::dmat3(turn);
  camera.t = glm::dvec3(0.1, -0.2, 3.0);

  double worst = 0.0;
  int seen = 0;
  for (int i = 0; i < 1000; ++i)
  {
    const glm::dvec3 X(uniform(random), uniform(random), uniform(random));
    glm::dvec2 pixel;
    if (!camera.Project(X, pixel))
    {
      continue;
    }
    const double z = (camera.R * X + camera.t).z;
    worst = std::max(worst, glm::length(camera.Unproject(pixel, z) - X));
    ++seen;
  }
  std::printf("unproject(project(X)): %d points, largest error %.3g\n", seen, worst);
  if (seen < 900 || !(worst < 1e-12))
  {
    ++failures;
  }

  const double n = 0.25, f = 40.0;
  double worstDepth = 0.0;
  for (int i = 1; i < 1000; ++i)
  {
    const double z = n + (f - n) * i / 1000.0;
    const double d = lfd::DistanceToWindowDepth(z, n, f);
    worstDepth = std::max(worstDepth, std::abs(lfd::WindowDepthToDistance(d, n, f) - z) / z);
  }
  const double nearPlane = lfd::DistanceToWindowDepth(n, n, f);
  const double farPlane = lfd::DistanceToWindowDepth(f, n, f);
  std::printf("window depth round trip: largest relative error %.3g; near %.3g, far %.17g\n",
    worstDepth,
    nearPlane,
    farPlane);
  if (!(worstDepth < 1e-12) || !(std::abs(nearPlane) < 1e-12) ||
    !(std::abs(farPlane - 1.0) < 1e-12))
  {
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}

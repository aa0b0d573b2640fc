// vtkLightFieldRenderer on analytic two-plane light fields (a 5 x 5 grid of
// cameras 0.25 apart on the plane z = 0, looking along +Z, 64 x 64 pixels,
// f = 64), no OpenGL:
// (1) a novel view between the cameras of a textured plane at depth 4,
//     focused at 4, matches the analytic image (PSNR);
// (2) refocusing (Isaksen et al. 2000): a white bar at depth 2 over black,
//     seen from the grid's centre with aperture 0.625, stays as sharp as
//     through one camera when the focal plane is at 2, and when it is at 4
//     spreads over copies f du (1/2 - 1/4) apart: the standard deviation of
//     its column profile grows by exactly the tent-weighted spread of the
//     cameras' offsets du (measured against predicted, pixels).
#include "lfdPinholeCamera.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using lfdtest::Expect;

namespace TestTwoPlaneRefocusHelpers
{
constexpr int Size = 64;
constexpr double Focal = 64.0;
constexpr double Spacing = 0.25;

/// What the ray o + s d sees: an RGB colour, false for the black background.
using Scene = std::function<bool(const glm::dvec3& o, const glm::dvec3& d, unsigned char rgb[3])>;

/// The point where o + s d (s > 0) meets the plane z = depth, if it does.
bool HitDepth(const glm::dvec3& o, const glm::dvec3& d, double depth, glm::dvec3& p)
{
  const double s = (depth - o.z) / d.z;
  p = o + s * d;
  return d.z != 0.0 && s > 0.0;
}

/// A textured square at depth 4, wider than every view (no silhouette).
bool Square(const glm::dvec3& o, const glm::dvec3& d, unsigned char rgb[3])
{
  glm::dvec3 p;
  if (!HitDepth(o, d, 4.0, p) || std::abs(p.x) >= 5.0 || std::abs(p.y) >= 5.0)
  {
    return false;
  }
  rgb[0] =
    static_cast<unsigned char>(std::lround(128 + 100 * std::sin(3 * p.x) * std::cos(2 * p.y)));
  rgb[1] = static_cast<unsigned char>(std::lround(128 + 100 * std::cos(4 * p.x + 1)));
  rgb[2] = static_cast<unsigned char>(std::lround(128 + 100 * std::sin(2 * p.y - p.x)));
  return true;
}

/// A white bar |x| < 0.05, |y| < 0.3 at depth 2.
bool Bar(const glm::dvec3& o, const glm::dvec3& d, unsigned char rgb[3])
{
  glm::dvec3 p;
  if (!HitDepth(o, d, 2.0, p) || std::abs(p.x) >= 0.05 || std::abs(p.y) >= 0.3)
  {
    return false;
  }
  std::fill(rgb, rgb + 3, 255);
  return true;
}

/// The image of `scene` through `camera`, VTK row order.
void Paint(const Scene& scene, const lfd::PinholeCamera& camera, unsigned char* rgb)
{
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      unsigned char* pixel = rgb + 3 * (static_cast<std::size_t>(Size - 1 - y) * Size + x);
      std::fill(pixel, pixel + 3, 0);
      scene(camera.Center(), camera.RayDirection({ x, y }), pixel);
    }
  }
}

double ViewAngle()
{
  return 2.0 * std::atan(0.5 * Size / Focal) * 180.0 / 3.14159265358979323846;
}

/// The 5 x 5 grid's light field of `scene` (no Label pass).
vtkSmartPointer<vtkLightField> Capture(const Scene& scene)
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  const double forward[3] = { 0.0, 0.0, 1.0 };
  const double up[3] = { 0.0, -1.0, 0.0 };
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  vtkCameraRig* rig = lightField->GetRig();
  rig->MakePlaneGrid(centre, forward, up, 5, 5, Spacing, Size, Size, ViewAngle());
  lightField->SetLayout(Size, Size, rig->GetNumberOfViews());
  auto* coaxial =
    vtkUnsignedCharArray::SafeDownCast(lightField->AllocatePass(vtkLightField::COAXIAL));
  for (int v = 0; v < rig->GetNumberOfViews(); ++v)
  {
    Paint(scene, rig->GetCamera(v), coaxial->GetPointer(3 * Size * Size * v));
  }
  return lightField;
}

/// The eye: at `position` on the camera plane, looking along +Z, f = 64.
lfd::PinholeCamera Eye(const glm::dvec3& position)
{
  glm::dmat3 K(1.0);
  K[0][0] = K[1][1] = Focal;
  K[2][0] = K[2][1] = 0.5 * (Size - 1);
  return lfd::PinholeCamera::LookAt(K, position, { 0, 0, 1 }, { 0, -1, 0 });
}

/// The render of `lightField` from `eye`, focused at `depth`, aperture `aperture`.
vtkSmartPointer<vtkImageData> Render(vtkLightField* lightField,
  const lfd::PinholeCamera& eye,
  double depth,
  double aperture)
{
  double K[9], R[9], t[3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      K[3 * r + c] = eye.K[c][r];
      R[3 * r + c] = eye.R[c][r];
    }
    t[r] = eye.t[r];
  }
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(lightField);
  renderer->SetPinhole(K, R, t);
  renderer->SetWidth(Size);
  renderer->SetHeight(Size);
  renderer->SetFocalDepth(depth);
  renderer->SetAperture(aperture);
  renderer->Update();
  return renderer->GetOutput();
}

/// Standard deviation (pixels) of the column profile of the red channel.
double ProfileSpread(vtkImageData* image)
{
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  double total = 0.0, sum = 0.0, squares = 0.0;
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    const double x = static_cast<double>(i % Size);
    const double value = rgb->GetValue(3 * i);
    total += value;
    sum += value * x;
    squares += value * x * x;
  }
  const double mean = sum / total;
  return std::sqrt(squares / total - mean * mean);
}
}

int TestTwoPlaneRefocus(int, char*[])
{
  using namespace TestTwoPlaneRefocusHelpers;
  // (1) A novel view between the cameras, focused on the square.
  vtkSmartPointer<vtkLightField> square = Capture(Square);
  const lfd::PinholeCamera novel = Eye({ 0.1, 0.07, 0.0 });
  vtkSmartPointer<vtkImageData> rendered = Render(square, novel, 4.0, 0.0);
  std::vector<unsigned char> truth(3 * Size * Size);
  Paint(Square, novel, truth.data());
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(rendered->GetPointData()->GetScalars());
  const double psnr =
    vtkLeaveOneOutEvaluator::ComputePSNR(pixels->GetPointer(0), truth.data(), nullptr, Size * Size);
  Expect(psnr > 50.0, "novel view between cameras vs analytic image, PSNR dB (> 50)", psnr);
  // Focused at infinity instead, the square (4 away) doubles between cameras.
  const double ghosted = vtkLeaveOneOutEvaluator::ComputePSNR(
    vtkUnsignedCharArray::SafeDownCast(
      Render(square, novel, 0.0, 0.0)->GetPointData()->GetScalars())
      ->GetPointer(0),
    truth.data(),
    nullptr,
    Size * Size);
  Expect(ghosted < psnr - 15.0, "focused at infinity instead, PSNR dB (15 dB lower)", ghosted);

  // (2) Refocusing the bar.
  vtkSmartPointer<vtkLightField> bar = Capture(Bar);
  const lfd::PinholeCamera centre = Eye({ 0.0, 0.0, 0.0 });
  const double aperture = 2.5 * Spacing;
  const double pinhole = ProfileSpread(Render(bar, centre, 2.0, 0.0));
  const double sharp = ProfileSpread(Render(bar, centre, 2.0, aperture));
  const double blurred = ProfileSpread(Render(bar, centre, 4.0, aperture));
  // The cameras' columns du = -0.5 .. 0.5 weigh 1 - |du| / 0.625; each shows
  // the bar f du (1/2 - 1/4) pixels off, a whole number (4 per column), so
  // that every copy of the bar is as wide as the others.
  double weights = 0.0, moment = 0.0;
  for (int c = -2; c <= 2; ++c)
  {
    const double du = c * Spacing;
    const double w = 1.0 - std::abs(du) / aperture;
    weights += w;
    moment += w * du * du;
  }
  const double predicted = Focal * (1.0 / 2.0 - 1.0 / 4.0) * std::sqrt(moment / weights);
  const double measured = std::sqrt(blurred * blurred - sharp * sharp);
  std::cout << "bar profile spread: one camera " << pinhole << " px, aperture " << aperture
            << " focused on it " << sharp << " px, focused at 4 " << blurred << " px\n";
  Expect(std::abs(sharp - pinhole) < 0.01,
    "in focus, the aperture adds no blur: spread difference px (< 0.01)",
    sharp - pinhole);
  Expect(std::abs(measured - predicted) < 0.02 * predicted,
    "out of focus, added blur px (predicted f |du| |1/z - 1/D|, within 2 %)",
    measured);
  std::cout << "     predicted blur: " << predicted << " px\n";

  // Leave-one-out of every view leaves nothing to render: one error.
  vtkNew<vtkLightFieldRenderer> empty;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(empty);
  empty->SetInputData(bar);
  empty->SetWidth(Size);
  empty->SetHeight(Size);
  for (int v = 0; v < bar->GetNumberOfViews(); ++v)
  {
    empty->AddExcludedView(v);
  }
  empty->Update();
  Expect(errors->GetNumberOfErrors() == 1 &&
      std::string(errors->GetErrorMessage()) == "Every view of the two-plane grid is excluded.",
    "every view excluded: one error",
    errors->GetNumberOfErrors());
  return lfdtest::Result();
}

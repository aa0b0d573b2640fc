// Lens distortion (lfdLensDistortion.h, OpenCV's k1, k2, p1, p2, k3) in the
// pinhole camera and where pixels meet rays:
// (1) Project() against hand-computed values (the same as OpenCV 4.6's
//     cv::projectPoints gives for this camera);
// (2) Unproject() undoes Project() to 1e-9 px over the whole image for a
//     realistic lens, and the zero model is the plain pinhole, bit for bit;
// (3) the one camera check refuses non-finite and non-monotonic models,
//     naming the field, and the rig carries the coefficients per view;
// (4) end to end through the cylindrical sampler (the renderer's lookup):
//     an analytic light field captured by distorted cameras, with images
//     correspondingly distorted, samples a novel view like the same light
//     field captured by undistorted cameras (inside the object's silhouette,
//     measured 49.4 dB against the analytic image for both; ignoring the
//     distortion gives 41.9 dB for the realistic lens, 33.4 for a strong one).
#include "lfdCylinderSampling.h"
#include "lfdPinholeCamera.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkNew.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using lfdtest::Expect;

namespace
{
// The realistic lens of the brief: barrel distortion with a little
// decentring.
const double Realistic[5] = { -0.2, 0.05, 1e-3, -5e-4, 0.0 };

lfd::PinholeCamera TestCamera()
{
  lfd::PinholeCamera camera;
  camera.K = glm::transpose(glm::dmat3(500, 0, 320, 0, 500, 240, 0, 0, 1));
  return camera;
}

void CheckHandValues()
{
  lfd::PinholeCamera camera = TestCamera();
  camera.Lens = lfd::LensDistortion::FromArray(Realistic);
  // x' = 0.2, y' = -0.1: r^2 = 0.05, radial 0.990125; tangential
  // (-4e-5 - 6.5e-5, 7e-5 + 2e-5): x'' = 0.19792, y'' = -0.0989225.
  glm::dvec2 pixel;
  camera.Project({ 0.2, -0.1, 1.0 }, pixel);
  Expect(std::abs(pixel.x - 418.96) < 1e-9 && std::abs(pixel.y - 190.53875) < 1e-9,
    "projection of (0.2, -0.1, 1), x (expected 418.96, y 190.53875)",
    pixel.x);
  // x' = -0.3, y' = 0.25 (at z = 2): r^2 = 0.1525, radial 0.9706628125.
  camera.Project({ -0.6, 0.5, 2.0 }, pixel);
  Expect(std::abs(pixel.x - 174.242453125) < 1e-9 && std::abs(pixel.y - 361.5091015625) < 1e-9,
    "projection of (-0.6, 0.5, 2), x (expected 174.242453125, y 361.5091015625)",
    pixel.x);
}

void CheckRoundTrip()
{
  lfd::PinholeCamera camera = lfd::PinholeCamera::LookAt(
    TestCamera().K, { 0.3, -0.2, 4.0 }, { -0.1, 0.05, -1.0 }, { 0.1, 1.0, 0.0 });
  camera.Lens = lfd::LensDistortion::FromArray(Realistic);
  const lfd::PinholeCamera::Unprojection unproject = camera.GetUnprojection();
  double worst = 0.0;
  int count = 0;
  for (double y = -0.5; y <= 479.5; y += 4.0)
  {
    for (double x = -0.5; x <= 639.5; x += 4.0)
    {
      const double depth = 1.0 + 0.01 * (count % 300);
      glm::dvec2 back;
      camera.Project(unproject({ x, y }, depth), back);
      worst = std::max(worst, glm::length(back - glm::dvec2(x, y)));
      ++count;
    }
  }
  Expect(
    worst < 1e-9, "project(unproject(pixel)) over 160 x 120 pixels, largest error (px)", worst);

  // The zero model is the plain pinhole: no polynomial, identical numbers.
  lfd::PinholeCamera plain = camera;
  const double zero[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
  plain.Lens = lfd::LensDistortion::FromArray(zero);
  const glm::dvec3 X(0.4, -0.3, 0.2);
  const glm::dvec3 h = plain.K * (plain.R * X + plain.t);
  glm::dvec2 pixel;
  plain.Project(X, pixel);
  Expect(!plain.Lens.Active && pixel == glm::dvec2(h.x / h.z, h.y / h.z),
    "zero distortion projects as K [R | t] X exactly, x",
    pixel.x);
  const glm::dvec3 direction = plain.GetUnprojection().Direction(pixel);
  Expect(direction == plain.PixelToDirection() * glm::dvec3(pixel, 1.0),
    "zero distortion unprojects through R^T K^-1 exactly, direction z",
    direction.z);
}

void CheckValidation()
{
  double K[9] = { 500, 0, 320, 0, 500, 240, 0, 0, 1 };
  const double R[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const double t[3] = { 0, 0, 4 };
  std::string field, problem;
  Expect(lfd::CheckPinhole(K, R, t, Realistic, 640, 480, field, problem),
    "the realistic lens is accepted",
    1);
  const double nan[5] = { -0.2, std::nan(""), 0, 0, 0 };
  const bool refusedNan = !lfd::CheckPinhole(K, R, t, nan, 640, 480, field, problem);
  std::printf("     non-finite: %s: %s\n", field.c_str(), problem.c_str());
  Expect(refusedNan && field == "distortion" &&
      problem == "has a non-finite coefficient (expected [k1, k2, p1, p2, k3])",
    "a non-finite coefficient is refused",
    refusedNan);
  // k1 = -1: r (1 - r^2) peaks at r = 0.577 with 0.385, inside the image
  // (its corners are at 0.80 normalised): the lens folds the image.
  const double folding[5] = { -1.0, 0, 0, 0, 0 };
  const bool refusedFold = !lfd::CheckPinhole(K, R, t, folding, 640, 480, field, problem);
  std::printf("     folding: %s: %s\n", field.c_str(), problem.c_str());
  Expect(refusedFold && field == "distortion" &&
      problem == "folds the image (the distortion is not monotonic up to the image border)",
    "a non-monotonic lens (k1 = -1) is refused",
    refusedFold);
  // The same lens on a smaller image (corners at 0.36 < 0.577): monotonic there.
  const double smallK[9] = { 500, 0, 149.5, 0, 500, 99.5, 0, 0, 1 };
  Expect(lfd::CheckPinhole(smallK, R, t, folding, 300, 200, field, problem) ||
      (std::printf("     %s\n", problem.c_str()), false),
    "k1 = -1 is accepted on an image it does not fold (corner radius 0.36)",
    1);

  // The rig carries the coefficients per view and validates them.
  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(2);
  rig->SetImageSize(640, 480);
  rig->SetView(0, K, R, t);
  const double t1[3] = { 1, 0, 4 };
  rig->SetView(1, K, R, t1);
  Expect(!rig->HasDistortion(), "a new rig has no distortion", rig->HasDistortion());
  rig->SetDistortion(1, Realistic);
  vtkNew<vtkCameraRig> copy;
  copy->DeepCopy(rig);
  double read[5];
  copy->GetDistortion(1, read);
  Expect(copy->HasDistortion() && read[0] == -0.2 && read[3] == -5e-4 &&
      copy->GetCamera(1).Lens.Active && !copy->GetCamera(0).Lens.Active,
    "the rig keeps view 1's distortion through DeepCopy, k1",
    read[0]);
  Expect(rig->FindInvalidView(field, problem) == -1, "the distorted rig is valid", 1);
  rig->SetDistortion(1, folding);
  Expect(rig->FindInvalidView(field, problem) == 1 && field == "distortion",
    "the rig names view 1's folding distortion",
    1);
}

// The analytic object: the square |x|, |y| < 1 of the plane z = 0 with a
// smooth texture (label 1), seen through `camera` at a pixel.
bool Square(const lfd::PinholeCamera& camera, const glm::dvec2& pixel, glm::dvec3& rgb)
{
  const glm::dvec3 o = camera.Center();
  const glm::dvec3 d = camera.RayDirection(pixel);
  const double s = std::abs(d.z) > 1e-12 ? -o.z / d.z : -1.0;
  const glm::dvec3 p = o + s * d;
  if (s <= 0.0 || std::abs(p.x) >= 1.0 || std::abs(p.y) >= 1.0)
  {
    return false;
  }
  rgb = glm::dvec3(128 + 100 * std::sin(4 * p.x) * std::cos(3 * p.y),
    128 + 100 * std::cos(5 * p.x + 1),
    128 + 100 * std::sin(3 * p.y - 2 * p.x));
  return true;
}

// A ring light field of the square, every view painted through its own
// (possibly distorted) camera, and the image the sampler gives of it from
// `eye` (Sec. 6.2: label vote, colour of the voted label).
std::vector<double> SampleRing(const double lens[5],
  bool lookUpWithLens,
  const lfd::PinholeCamera& eye)
{
  const int size = 96, views = 72;
  const double center[3] = { 0.0, 0.0, 0.0 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double height = 0.0;
  vtkNew<vtkCameraRig> rig;
  rig->MakeCylinder(center, axis, 4.0, views, 1, &height, size, size, 40.0);
  std::vector<lfd::PinholeCamera> cameras(views);
  std::vector<std::uint8_t> rgb(3 * size * size * views), label(size * size * views);
  const lfd::ViewStack<std::uint8_t> colours{ rgb.data(), size, size, 3 };
  const lfd::ViewStack<std::uint8_t> labels{ label.data(), size, size, 1 };
  for (int v = 0; v < views; ++v)
  {
    rig->SetDistortion(v, lens);
    const lfd::PinholeCamera& camera = rig->GetCamera(v);
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        glm::dvec3 c(0.0);
        const bool hit = Square(camera, { x, y }, c);
        auto* pixel = const_cast<std::uint8_t*>(colours.Pixel(v, x, y));
        for (int k = 0; k < 3; ++k)
        {
          pixel[k] = static_cast<std::uint8_t>(std::lround(c[k]));
        }
        *const_cast<std::uint8_t*>(labels.Pixel(v, x, y)) = hit ? 1 : 0;
      }
    }
    cameras[v] = camera;
    if (!lookUpWithLens)
    {
      cameras[v].Lens = lfd::LensDistortion();
    }
  }
  // The lenses modified the rig: fit it again (a fit is kept until the rig changes).
  const bool fitted = rig->FitCylinder();
  Expect(fitted, "the distorted ring fits a cylinder", fitted);
  const lfd::RingLayout layout = rig->GetRingLayout();
  lfd::LightFieldSampler sampler;
  sampler.Layout = &layout;
  sampler.Cameras = cameras.data();
  sampler.Radiance = colours;
  sampler.Labels = labels;
  std::vector<double> image(3 * size * size, 0.0);
  lfd::RaySamples samples;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      glm::dvec3 colour(0.0);
      if (sampler.Gather(eye.Center(), eye.RayDirection({ x, y }), samples) &&
        lfd::VoteLabel(samples) == 1)
      {
        lfd::BlendLabel(samples, 1, colour);
      }
      for (int k = 0; k < 3; ++k)
      {
        image[3 * (y * size + x) + k] = colour[k];
      }
    }
  }
  return image;
}

// PSNR over the pixels whose `inside` is set (3 channels each).
double PSNR(const std::vector<double>& a,
  const std::vector<double>& b,
  const std::vector<bool>& inside)
{
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (inside[i / 3])
    {
      sum += (a[i] - b[i]) * (a[i] - b[i]);
      ++count;
    }
  }
  const double mse = sum / count;
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 100.0;
}

void CheckEndToEnd()
{
  // A novel view from further away, between views 1 and 2 of the ring.
  const double phi = 1.5 * lfd::TwoPi / 72;
  const glm::dmat3 K = glm::transpose(glm::dmat3(120, 0, 47.5, 0, 120, 47.5, 0, 0, 1));
  const lfd::PinholeCamera eye = lfd::PinholeCamera::LookAt(K,
    { 6.0 * std::sin(phi), 0.3, 6.0 * std::cos(phi) },
    { -std::sin(phi), -0.05, -std::cos(phi) },
    { 0.0, 1.0, 0.0 });
  // The analytic image, and the pixels at least 2 pixels inside the
  // square's silhouette (where the images must agree; at the silhouette
  // each pixel is one label or the other).
  const int size = 96;
  std::vector<double> truth(3 * size * size, 0.0);
  std::vector<bool> hit(size * size, false), inside(size * size, false);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      glm::dvec3 colour(0.0);
      hit[y * size + x] = Square(eye, { x, y }, colour);
      for (int k = 0; k < 3; ++k)
      {
        truth[3 * (y * size + x) + k] = colour[k];
      }
    }
  }
  for (int y = 2; y < size - 2; ++y)
  {
    for (int x = 2; x < size - 2; ++x)
    {
      bool all = true;
      for (int dy = -2; dy <= 2; ++dy)
      {
        for (int dx = -2; dx <= 2; ++dx)
        {
          all = all && hit[(y + dy) * size + x + dx];
        }
      }
      inside[y * size + x] = all;
    }
  }
  const double none[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
  const double ideal = PSNR(truth, SampleRing(none, false, eye), inside);
  std::printf("     undistorted light field vs the analytic image, inside: %.2f dB\n", ideal);
  // The realistic lens, and a strong barrel (6.5 px at the views' corners).
  const double barrel[5] = { -0.6, 0.2, 2e-3, -1e-3, 0.0 };
  for (const double* lens : { Realistic, barrel })
  {
    const double matched = PSNR(truth, SampleRing(lens, true, eye), inside);
    const double ignored = PSNR(truth, SampleRing(lens, false, eye), inside);
    std::printf("     lens k1 = %g: through the distortion %.2f dB, ignoring it %.2f dB\n",
      lens[0],
      matched,
      ignored);
    Expect(std::abs(matched - ideal) < 0.5,
      "distorted views sampled through their distortion: PSNR within 0.5 dB of the undistorted "
      "light field's (dB)",
      matched);
    Expect(ignored < ideal - 5.0,
      "the same views sampled as if undistorted: PSNR more than 5 dB lower (dB)",
      ignored);
  }
}
}

int TestLensDistortion(int, char*[])
{
  CheckHandValues();
  CheckRoundTrip();
  CheckValidation();
  CheckEndToEnd();
  return lfdtest::Result();
}

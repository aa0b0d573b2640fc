#include "vtkCameraRig.h"

#include "lfdCylinderSampling.h"
#include "lfdPinholeCamera.h"
#include "lfdTwoPlaneSampling.h"
#include "lfdViewCoverage.h"

#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkTimeStamp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkCameraRig);

namespace
{
glm::dvec3 ToVec(const double v[3])
{
  return glm::dvec3(v[0], v[1], v[2]);
}

/// K of a square-pixel camera of `width` x `height` pixels and vertical view
/// angle `viewAngle` (degrees), principal point at the image centre.
glm::dmat3 IdealIntrinsics(int width, int height, double viewAngle)
{
  const double fy = 0.5 * height / std::tan(0.5 * vtkMath::RadiansFromDegrees(viewAngle));
  glm::dmat3 intrinsics(1.0);
  intrinsics[0][0] = fy;
  intrinsics[1][1] = fy;
  intrinsics[2][0] = 0.5 * (width - 1);
  intrinsics[2][1] = 0.5 * (height - 1);
  return intrinsics;
}

void FromVec(const glm::dvec3& v, double out[3])
{
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

void ToRowMajor(const glm::dmat3& m, double out[9])
{
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      out[3 * row + col] = m[col][row];
    }
  }
}

/// Eigen-decomposition of a symmetric 3x3 matrix; columns of `vectors`
/// are sorted by decreasing eigenvalue (vtkMath::Jacobi's order).
void SymmetricEigen(const glm::dmat3& m, double values[3], glm::dvec3 vectors[3])
{
  double a[3][3], v[3][3];
  double* aRows[3] = { a[0], a[1], a[2] };
  double* vRows[3] = { v[0], v[1], v[2] };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      a[i][j] = m[j][i];
    }
  }
  vtkMath::Jacobi(aRows, values, vRows);
  for (int k = 0; k < 3; ++k)
  {
    vectors[k] = glm::dvec3(v[0][k], v[1][k], v[2][k]);
  }
}

/// Any unit vector orthogonal to `axis`: the axis-orthogonal part of +Z,
/// or of +X when the axis is (nearly) Z.
glm::dvec3 ReferenceDirection(const glm::dvec3& axis)
{
  glm::dvec3 ref(0.0, 0.0, 1.0);
  if (std::abs(glm::dot(ref, axis)) > 0.9)
  {
    ref = glm::dvec3(1.0, 0.0, 0.0);
  }
  return glm::normalize(ref - glm::dot(ref, axis) * axis);
}

/// The camera centres' mean and principal directions (scatter eigenvectors,
/// by decreasing spread).
struct CentreSpread
{
  glm::dvec3 Mean{ 0.0 };
  double Values[3] = { 0.0, 0.0, 0.0 };
  glm::dvec3 Vectors[3];
};

CentreSpread MeasureSpread(const std::vector<glm::dvec3>& centers)
{
  CentreSpread spread;
  for (const glm::dvec3& c : centers)
  {
    spread.Mean += c;
  }
  spread.Mean /= static_cast<double>(centers.size());
  glm::dmat3 scatter(0.0);
  for (const glm::dvec3& c : centers)
  {
    scatter += glm::outerProduct(c - spread.Mean, c - spread.Mean);
  }
  SymmetricEigen(scatter, spread.Values, spread.Vectors);
  return spread;
}

/// The cylinder axis: the principal direction whose spread stands apart
/// from the other two, the smallest one for a ring (the normal of the plane
/// fitted by SVD), the largest one for a stack of rings taller than wide
/// (whose two other directions span the round cross-section). Oriented like
/// most views' image "up" when they agree on one (views rolled by 180
/// degrees vote against), otherwise towards +Y, VTK's usual view up.
glm::dvec3 FitAxis(const CentreSpread& spread, const std::vector<lfd::PinholeCamera>& cameras)
{
  const double floor = 1e-300;
  const double* values = spread.Values;
  const double smallGap = std::log(std::max(values[1], floor) / std::max(values[2], floor));
  const double largeGap = std::log(std::max(values[0], floor) / std::max(values[1], floor));
  glm::dvec3 axis = glm::normalize(smallGap >= largeGap ? spread.Vectors[2] : spread.Vectors[0]);
  double upVote = 0.0;
  for (const lfd::PinholeCamera& camera : cameras)
  {
    upVote += glm::dot(camera.Up(), axis);
  }
  const bool upDecides = std::abs(upVote) > 0.1 * static_cast<double>(cameras.size());
  if ((upDecides && upVote < 0.0) || (!upDecides && axis.y < 0.0))
  {
    axis = -axis;
  }
  return axis;
}

/// Circle fit of the centres in the plane orthogonal to `axis`: algebraic
/// (Kasa) start, then Gauss-Newton on the geometric distance. Returns false
/// when the centres are collinear or coincide.
bool FitCircle(const std::vector<glm::dvec3>& centers,
  const CentreSpread& spread,
  const glm::dvec3& axis,
  glm::dvec3& center,
  double& radius)
{
  const double n = static_cast<double>(centers.size());
  const glm::dvec3 refX = ReferenceDirection(axis);
  const glm::dvec3 refY = glm::cross(axis, refX);
  std::vector<glm::dvec2> planar;
  planar.reserve(centers.size());
  glm::dmat3 normal(0.0);
  glm::dvec3 rhs(0.0);
  for (const glm::dvec3& c : centers)
  {
    const glm::dvec3 v = c - spread.Mean;
    const glm::dvec2 p(glm::dot(v, refX), glm::dot(v, refY));
    planar.push_back(p);
    const glm::dvec3 row(p.x, p.y, 1.0);
    normal += glm::outerProduct(row, row);
    rhs -= (p.x * p.x + p.y * p.y) * row;
  }
  // "<=": coinciding centres give a zero scatter, and a zero bound.
  if (std::abs(glm::determinant(normal)) <= 1e-12 * std::pow(spread.Values[0] * n, 2.0) * n)
  {
    return false;
  }
  const glm::dvec3 def = glm::inverse(normal) * rhs;
  glm::dvec2 c2(-0.5 * def.x, -0.5 * def.y);
  radius = std::sqrt(std::max(glm::dot(c2, c2) - def.z, 0.0));
  for (int iteration = 0; iteration < 20; ++iteration)
  {
    glm::dmat3 jtj(0.0);
    glm::dvec3 jtr(0.0);
    for (const glm::dvec2& p : planar)
    {
      const glm::dvec2 d = p - c2;
      const double len = std::max(glm::length(d), 1e-300);
      const glm::dvec3 j(-d.x / len, -d.y / len, -1.0);
      jtj += glm::outerProduct(j, j);
      jtr += (len - radius) * j;
    }
    const glm::dvec3 step = glm::inverse(jtj) * jtr;
    c2 -= glm::dvec2(step.x, step.y);
    radius -= step.z;
    if (glm::length(step) < 1e-14 * radius)
    {
      break;
    }
  }
  center = spread.Mean + c2.x * refX + c2.y * refY;
  return true;
}

/// Near-duplicates: a view closer than `distance` to an earlier one of the
/// same row that looks the same way within 5 degrees (roll is free: a view rotated by 180
/// degrees in its image plane sees the same rays) duplicates the first such
/// view; -1 for the others.
std::vector<int> FindDuplicates(const std::vector<glm::dvec3>& centers,
  const std::vector<lfd::PinholeCamera>& cameras,
  const std::vector<int>& rows,
  double distance)
{
  const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(5.0));
  const int n = static_cast<int>(centers.size());
  std::vector<int> duplicateOf(n, -1);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < j; ++i)
    {
      if (duplicateOf[i] < 0 && rows[i] == rows[j] &&
        glm::distance(centers[i], centers[j]) < distance &&
        glm::dot(cameras[i].Forward(), cameras[j].Forward()) > cosLimit)
      {
        duplicateOf[j] = i;
        break;
      }
    }
  }
  return duplicateOf;
}

/// Rows: the heights sorted, split at every gap between neighbours wider
/// than a threshold found from the data, not fixed. Merging the gaps in
/// increasing order (single linkage) gives every candidate split "all gaps
/// wider than g"; the candidate kept is the one whose narrowest split gap is
/// the largest multiple of the widest row (its height spread), when that
/// multiple reaches `ratio` and the gap `minimumGap`. Evenly spaced rows of
/// exact heights therefore split at any spacing, a noisy ring stays whole,
/// and rows never merge because their spacing equals a tolerance. The
/// candidate "every view its own row" is not considered (a helix is a
/// ring). Rows are numbered by increasing height, with their mean height.
void ClusterRows(const std::vector<double>& heights,
  double minimumGap,
  double ratio,
  std::vector<int>& rows,
  std::vector<double>& rowHeights)
{
  const int n = static_cast<int>(heights.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return heights[a] < heights[b]; });
  std::vector<double> sorted(n);
  for (int k = 0; k < n; ++k)
  {
    sorted[k] = heights[order[k]];
  }
  const int gaps = std::max(n - 1, 0);
  std::vector<int> byWidth(gaps);
  std::iota(byWidth.begin(), byWidth.end(), 0);
  const auto width = [&](int g) { return sorted[g + 1] - sorted[g]; };
  std::sort(byWidth.begin(), byWidth.end(), [&](int a, int b) { return width(a) < width(b); });

  // Segments of sorted views merged so far: each end knows the other end.
  std::vector<int> otherEnd(n);
  std::iota(otherEnd.begin(), otherEnd.end(), 0);
  const double span = n > 0 ? sorted[n - 1] - sorted[0] : 0.0;
  const double spreadFloor = 1e-12 * std::max(span, minimumGap);
  double widestRow = 0.0;
  double bestSeparation = 0.0;
  double threshold = std::numeric_limits<double>::infinity();
  for (int k = 0; k < gaps; ++k)
  {
    const int g = byWidth[k];
    const int low = otherEnd[g];
    const int high = otherEnd[g + 1];
    otherEnd[low] = high;
    otherEnd[high] = low;
    widestRow = std::max(widestRow, sorted[high] - sorted[low]);
    if (k + 1 == gaps || width(byWidth[k + 1]) <= width(g))
    {
      continue;
    }
    const double narrowestSplit = width(byWidth[k + 1]);
    const double separation = narrowestSplit / std::max(widestRow, spreadFloor);
    if (narrowestSplit >= minimumGap && separation >= ratio && separation > bestSeparation)
    {
      bestSeparation = separation;
      threshold = width(g);
    }
  }

  rows.assign(n, 0);
  rowHeights.clear();
  std::vector<int> rowCounts;
  for (int k = 0; k < n; ++k)
  {
    if (k == 0 || sorted[k] - sorted[k - 1] > threshold)
    {
      rowHeights.push_back(0.0);
      rowCounts.push_back(0);
    }
    rows[order[k]] = static_cast<int>(rowHeights.size()) - 1;
    rowHeights.back() += sorted[k];
    rowCounts.back() += 1;
  }
  for (std::size_t r = 0; r < rowHeights.size(); ++r)
  {
    rowHeights[r] /= rowCounts[r];
  }
}

/// A gap of a ring that an azimuth falls in: an azimuth step of the row
/// nearest to `height` wider than twice the row's median step.
struct RingGap
{
  bool Found = false;
  double Azimuth = 0.0;
  double Width = 0.0;
  double MedianStep = 0.0;
  int From = -1;
  int To = -1;
};

RingGap FindRingGap(const lfd::RingLayout& layout, double azimuth, double height)
{
  RingGap gap;
  const auto nearest = std::min_element(layout.Rows.begin(),
    layout.Rows.end(),
    [height](const lfd::RingRow& a, const lfd::RingRow& b)
    { return std::abs(a.Height - height) < std::abs(b.Height - height); });
  const std::vector<double>& azimuths = nearest->Azimuth;
  const std::size_t n = azimuths.size();
  if (n < 2)
  {
    return gap;
  }
  std::vector<double> steps(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    steps[k] = k + 1 < n ? azimuths[k + 1] - azimuths[k] : azimuths[0] + lfd::TwoPi - azimuths[k];
  }
  // The step that holds the azimuth: from the last view at or below it.
  const std::size_t upper =
    std::upper_bound(azimuths.begin(), azimuths.end(), azimuth) - azimuths.begin();
  const std::size_t from = (upper + n - 1) % n;
  const double width = steps[from];
  std::nth_element(steps.begin(), steps.begin() + n / 2, steps.end());
  gap.MedianStep = steps[n / 2];
  if (width > 2.0 * gap.MedianStep)
  {
    gap.Found = true;
    gap.Azimuth = azimuth;
    gap.Width = width;
    gap.From = nearest->View[from];
    gap.To = nearest->View[(from + 1) % n];
  }
  return gap;
}
}

struct vtkCameraRig::Internals
{
  std::vector<lfd::PinholeCamera> Cameras;
  std::vector<std::string> Names;

  bool Fitted = false;
  vtkTimeStamp FitTime;
  glm::dvec3 RefX{ 1.0, 0.0, 0.0 };
  glm::dvec3 RefY{ 0.0, 0.0, 1.0 };
  std::vector<double> Azimuth;
  std::vector<double> Height;
  std::vector<int> Row;
  std::vector<int> DuplicateOf;
  std::vector<double> RowHeights;
};

//------------------------------------------------------------------------------
vtkCameraRig::vtkCameraRig()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCameraRig::~vtkCameraRig() = default;

//------------------------------------------------------------------------------
void vtkCameraRig::SetNumberOfViews(int n)
{
  n = std::max(n, 0);
  if (n == this->GetNumberOfViews())
  {
    return;
  }
  this->Internal->Cameras.resize(n);
  this->Internal->Names.resize(n);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraRig::GetNumberOfViews() const
{
  return static_cast<int>(this->Internal->Cameras.size());
}

//------------------------------------------------------------------------------
void vtkCameraRig::SetView(int i, const double K[9], const double R[9], const double t[3])
{
  this->SetView(i, lfd::PinholeCamera::FromRowMajor(K, R, t));
}

//------------------------------------------------------------------------------
void vtkCameraRig::SetView(int i, const lfd::PinholeCamera& camera)
{
  if (i < 0 || i >= this->GetNumberOfViews())
  {
    vtkErrorMacro(
      "SetView: view " << i << " out of range [0, " << this->GetNumberOfViews() << ").");
    return;
  }
  this->Internal->Cameras[i] = camera;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetIntrinsics(int i, double K[9]) const
{
  ToRowMajor(this->GetCamera(i).K, K);
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetRotation(int i, double R[9]) const
{
  ToRowMajor(this->GetCamera(i).R, R);
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetTranslation(int i, double t[3]) const
{
  FromVec(this->GetCamera(i).t, t);
}

//------------------------------------------------------------------------------
int vtkCameraRig::FindInvalidView(std::string& field, std::string& problem) const
{
  // Views keyed by their 21 numbers: a repeated view (a copy-paste error in a
  // calibration) would otherwise surface as a failed cylinder fit.
  std::map<std::array<double, 21>, int> seen;
  for (int i = 0; i < this->GetNumberOfViews(); ++i)
  {
    std::array<double, 21> values;
    this->GetIntrinsics(i, values.data());
    this->GetRotation(i, values.data() + 9);
    this->GetTranslation(i, values.data() + 18);
    const lfd::PinholeCamera& camera = this->GetCamera(i);
    if (!lfd::CheckPinhole(values.data(),
          values.data() + 9,
          values.data() + 18,
          camera.Lens.Coefficients,
          this->ImageSize[0],
          this->ImageSize[1],
          field,
          problem))
    {
      return i;
    }
    const auto inserted = seen.emplace(values, i);
    if (!inserted.second)
    {
      field.clear();
      problem = "the same camera (K, R and t) as view " + std::to_string(inserted.first->second) +
        "; every view must be a distinct camera";
      return i;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
void vtkCameraRig::SetDistortion(int i, const double coefficients[5])
{
  if (i < 0 || i >= this->GetNumberOfViews())
  {
    vtkErrorMacro(
      "SetDistortion: view " << i << " out of range [0, " << this->GetNumberOfViews() << ").");
    return;
  }
  this->Internal->Cameras[i].Lens = lfd::LensDistortion::FromArray(coefficients);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetDistortion(int i, double coefficients[5]) const
{
  const lfd::LensDistortion& lens = this->GetCamera(i).Lens;
  std::copy_n(lens.Coefficients, 5, coefficients);
}

//------------------------------------------------------------------------------
bool vtkCameraRig::HasDistortion() const
{
  return std::any_of(this->Internal->Cameras.begin(),
    this->Internal->Cameras.end(),
    [](const lfd::PinholeCamera& camera) { return camera.Lens.Active; });
}

//------------------------------------------------------------------------------
void vtkCameraRig::SetViewName(int i, const char* name)
{
  if (i < 0 || i >= this->GetNumberOfViews())
  {
    vtkErrorMacro("SetViewName: view " << i << " out of range.");
    return;
  }
  this->Internal->Names[i] = name ? name : "";
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkCameraRig::GetViewName(int i) const
{
  return (i >= 0 && i < this->GetNumberOfViews()) ? this->Internal->Names[i].c_str() : "";
}

//------------------------------------------------------------------------------
const lfd::PinholeCamera& vtkCameraRig::GetCamera(int i) const
{
  static const lfd::PinholeCamera identity;
  if (i < 0 || i >= this->GetNumberOfViews())
  {
    return identity;
  }
  return this->Internal->Cameras[i];
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetCameraCenter(int i, double center[3]) const
{
  FromVec(this->GetCamera(i).Center(), center);
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetViewDirection(int i, double direction[3]) const
{
  FromVec(this->GetCamera(i).Forward(), direction);
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetViewUp(int i, double up[3]) const
{
  FromVec(this->GetCamera(i).Up(), up);
}

//------------------------------------------------------------------------------
bool vtkCameraRig::Project(int i, const double point[3], double pixel[2]) const
{
  glm::dvec2 uv;
  if (!this->GetCamera(i).Project(ToVec(point), uv))
  {
    return false;
  }
  pixel[0] = uv.x;
  pixel[1] = uv.y;
  return true;
}

//------------------------------------------------------------------------------
double vtkCameraRig::GetViewAngle(int i) const
{
  return vtkMath::DegreesFromRadians(
    2.0 * std::atan(0.5 * this->ImageSize[1] / this->GetCamera(i).K[1][1]));
}

//------------------------------------------------------------------------------
void vtkCameraRig::ApplyToCamera(int i, vtkCamera* camera) const
{
  if (!camera)
  {
    return;
  }
  const lfd::PinholeCamera& pinhole = this->GetCamera(i);
  const double width = this->ImageSize[0];
  const double height = this->ImageSize[1];
  const glm::dvec3 center = pinhole.Center();
  const glm::dvec3 forward = pinhole.Forward();
  double distance = 1.0;
  if (this->HasCylinder())
  {
    const glm::dvec3 toAxis = ToVec(this->Center) - center;
    distance = std::max(glm::dot(toAxis, forward), 1e-6 * this->Radius);
  }
  const glm::dvec3 focal = center + distance * forward;
  const glm::dvec3 up = pinhole.Up();
  camera->SetPosition(center.x, center.y, center.z);
  camera->SetFocalPoint(focal.x, focal.y, focal.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetViewAngle(this->GetViewAngle(i));
  // The optical axis lands on NDC (-wx, -wy) (vtkCamera's frustum); OpenCV
  // pixel centres are at integer coordinates, VTK's at half-integers, and
  // VTK's y grows upwards.
  const double cx = pinhole.K[2][0];
  const double cy = pinhole.K[2][1];
  camera->SetWindowCenter(1.0 - 2.0 * (cx + 0.5) / width, 2.0 * (cy + 0.5) / height - 1.0);
}

//------------------------------------------------------------------------------
void vtkCameraRig::CameraToPinhole(vtkCamera* camera,
  int width,
  int height,
  double K[9],
  double R[9],
  double t[3])
{
  const double fy =
    0.5 * height / std::tan(0.5 * vtkMath::RadiansFromDegrees(camera->GetViewAngle()));
  const double* wc = camera->GetWindowCenter();
  glm::dmat3 intrinsics(1.0);
  intrinsics[0][0] = fy;
  intrinsics[1][1] = fy;
  intrinsics[2][0] = 0.5 * width * (1.0 - wc[0]) - 0.5;
  intrinsics[2][1] = 0.5 * height * (1.0 + wc[1]) - 0.5;
  const glm::dvec3 position = ToVec(camera->GetPosition());
  const lfd::PinholeCamera pinhole = lfd::PinholeCamera::LookAt(
    intrinsics, position, ToVec(camera->GetFocalPoint()) - position, ToVec(camera->GetViewUp()));
  ToRowMajor(pinhole.K, K);
  ToRowMajor(pinhole.R, R);
  FromVec(pinhole.t, t);
}

//------------------------------------------------------------------------------
void vtkCameraRig::MakeCylinder(const double center[3],
  const double axis[3],
  double radius,
  int viewsPerRing,
  int rows,
  const double* heights,
  int width,
  int height,
  double viewAngle)
{
  if (viewsPerRing < 1 || rows < 1 || radius <= 0.0 || width < 1 || height < 1 ||
    !(viewAngle > 0.0 && viewAngle < 180.0))
  {
    vtkErrorMacro("MakeCylinder: need at least one view and row, a positive radius and image "
                  "size and a view angle in (0, 180) degrees.");
    return;
  }
  const glm::dvec3 a = glm::normalize(ToVec(axis));
  const glm::dvec3 refX = ReferenceDirection(a);
  const glm::dvec3 refY = glm::cross(a, refX);
  const glm::dmat3 intrinsics = IdealIntrinsics(width, height, viewAngle);
  this->SetImageSize(width, height);
  this->SetNumberOfViews(viewsPerRing * rows);
  for (int r = 0; r < rows; ++r)
  {
    const glm::dvec3 target = ToVec(center) + heights[r] * a;
    for (int k = 0; k < viewsPerRing; ++k)
    {
      const double phi = lfd::TwoPi * k / viewsPerRing;
      const glm::dvec3 position = target + radius * (std::cos(phi) * refX + std::sin(phi) * refY);
      this->SetView(r * viewsPerRing + k,
        lfd::PinholeCamera::LookAt(intrinsics, position, target - position, a));
    }
  }
  // Built, so fitted; rings of fewer than 3 views are not fitted.
  std::string noCylinder;
  if (viewsPerRing >= 3)
  {
    this->FitCylinder(noCylinder);
  }
}

//------------------------------------------------------------------------------
void vtkCameraRig::MakePlaneGrid(const double center[3],
  const double forward[3],
  const double up[3],
  int columns,
  int rows,
  double spacing,
  int width,
  int height,
  double viewAngle)
{
  const glm::dvec3 f = ToVec(forward);
  const glm::dvec3 u = ToVec(up);
  if (columns < 1 || rows < 1 || !(spacing > 0.0) || width < 1 || height < 1 ||
    !(viewAngle > 0.0 && viewAngle < 180.0) || !(glm::length(f) > 0.0) ||
    !(glm::length(glm::cross(f, u)) > 1e-9 * glm::length(f) * glm::length(u)))
  {
    vtkErrorMacro("MakePlaneGrid: need at least one column and row, a positive spacing and image "
                  "size, a view angle in (0, 180) degrees and an up not parallel to forward.");
    return;
  }
  const glm::dmat3 intrinsics = IdealIntrinsics(width, height, viewAngle);
  const lfd::PinholeCamera frame = lfd::PinholeCamera::LookAt(intrinsics, ToVec(center), f, u);
  const glm::dvec3 right = glm::transpose(frame.R)[0];
  const glm::dvec3 down = glm::transpose(frame.R)[1];
  this->SetImageSize(width, height);
  this->SetNumberOfViews(columns * rows);
  for (int r = 0; r < rows; ++r)
  {
    for (int c = 0; c < columns; ++c)
    {
      const glm::dvec3 position = ToVec(center) +
        spacing * ((c - 0.5 * (columns - 1)) * right + (r - 0.5 * (rows - 1)) * down);
      lfd::PinholeCamera camera = frame;
      camera.t = -(camera.R * position);
      this->SetView(r * columns + c, camera);
      std::ostringstream name;
      name << "r" << std::setw(2) << std::setfill('0') << r << "_c" << std::setw(2) << c;
      this->SetViewName(r * columns + c, name.str().c_str());
    }
  }
}

//------------------------------------------------------------------------------
bool vtkCameraRig::IsTwoPlane() const
{
  return !this->GetTwoPlaneLayout().Empty();
}

//------------------------------------------------------------------------------
lfd::TwoPlaneLayout vtkCameraRig::GetTwoPlaneLayout(const std::vector<int>& excluded) const
{
  lfd::TwoPlaneLayout layout;
  std::string notPlanar;
  lfd::BuildTwoPlaneLayout(
    this->Internal->Cameras.data(), this->GetNumberOfViews(), excluded, layout, notPlanar);
  return layout;
}

//------------------------------------------------------------------------------
bool vtkCameraRig::HasCylinder() const
{
  // The fit is a cache of the calibration: any later change (views, image
  // size, tolerances) makes it stale.
  return this->Internal->Fitted && this->Internal->FitTime.GetMTime() > this->MTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkCameraRig::FitCylinder()
{
  std::string problem;
  if (!this->FitCylinder(problem))
  {
    vtkErrorMacro("FitCylinder: " << problem);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCameraRig::FitCylinder(std::string& problem)
{
  Internals& in = *this->Internal;
  in.Fitted = false;
  const int n = this->GetNumberOfViews();
  if (n < 3)
  {
    problem = "a cylinder needs at least 3 views, the rig has " + std::to_string(n) + ".";
    return false;
  }
  std::vector<glm::dvec3> centers(n);
  for (int i = 0; i < n; ++i)
  {
    centers[i] = in.Cameras[i].Center();
  }
  const CentreSpread spread = MeasureSpread(centers);
  const glm::dvec3 axis = FitAxis(spread, in.Cameras);
  glm::dvec3 center;
  double radius = 0.0;
  if (!FitCircle(centers, spread, axis, center, radius))
  {
    problem = "the camera centres are collinear or coincide; no ring can be fitted to them.";
    return false;
  }
  FromVec(axis, this->Axis);
  FromVec(center, this->Center);
  this->Radius = radius;

  // Azimuth 0 at the first view.
  glm::dvec3 first = centers[0] - center;
  first -= glm::dot(first, axis) * axis;
  in.RefX = glm::length(first) > 0.0 ? glm::normalize(first) : ReferenceDirection(axis);
  in.RefY = glm::cross(axis, in.RefX);
  lfd::RingLayout frame;
  frame.Cyl = { center, axis, radius };
  frame.RefX = in.RefX;
  frame.RefY = in.RefY;
  in.Azimuth.assign(n, 0.0);
  in.Height.assign(n, 0.0);
  double residual2 = 0.0;
  for (int i = 0; i < n; ++i)
  {
    frame.Locate(centers[i], in.Azimuth[i], in.Height[i]);
    glm::dvec3 radial = centers[i] - center;
    radial -= glm::dot(radial, axis) * axis;
    residual2 += std::pow(glm::length(radial) - radius, 2.0);
  }
  this->FitResidual = std::sqrt(residual2 / n);

  // Rows first: views of two rows are never duplicates, however close the
  // rows (a row is a deliberate height, a duplicate an accidental repeat).
  ClusterRows(in.Height, this->MinimumRowGap * radius, this->RowGapRatio, in.Row, in.RowHeights);
  in.DuplicateOf = FindDuplicates(centers, in.Cameras, in.Row, this->DuplicateTolerance * radius);
  in.Fitted = true;
  in.FitTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
double vtkCameraRig::GetAzimuth(int i) const
{
  return (this->HasCylinder() && i >= 0 && i < this->GetNumberOfViews())
    ? this->Internal->Azimuth[i]
    : 0.0;
}

//------------------------------------------------------------------------------
double vtkCameraRig::GetHeight(int i) const
{
  return (this->HasCylinder() && i >= 0 && i < this->GetNumberOfViews()) ? this->Internal->Height[i]
                                                                         : 0.0;
}

//------------------------------------------------------------------------------
int vtkCameraRig::GetRow(int i) const
{
  return (this->HasCylinder() && i >= 0 && i < this->GetNumberOfViews()) ? this->Internal->Row[i]
                                                                         : -1;
}

//------------------------------------------------------------------------------
int vtkCameraRig::GetDuplicateOf(int i) const
{
  return (this->HasCylinder() && i >= 0 && i < this->GetNumberOfViews())
    ? this->Internal->DuplicateOf[i]
    : -1;
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetAzimuthFrame(double zero[3], double quarter[3]) const
{
  FromVec(this->Internal->RefX, zero);
  FromVec(this->Internal->RefY, quarter);
}

//------------------------------------------------------------------------------
int vtkCameraRig::GetNumberOfRows() const
{
  return this->HasCylinder() ? static_cast<int>(this->Internal->RowHeights.size()) : 0;
}

//------------------------------------------------------------------------------
double vtkCameraRig::GetRowHeight(int row) const
{
  return (row >= 0 && row < this->GetNumberOfRows()) ? this->Internal->RowHeights[row] : 0.0;
}

//------------------------------------------------------------------------------
int vtkCameraRig::GetNumberOfDuplicates() const
{
  if (!this->HasCylinder())
  {
    return 0;
  }
  return static_cast<int>(std::count_if(this->Internal->DuplicateOf.begin(),
    this->Internal->DuplicateOf.end(),
    [](int d) { return d >= 0; }));
}

//------------------------------------------------------------------------------
void vtkCameraRig::GetSortedViews(vtkIdList* views) const
{
  views->Reset();
  const int n = this->GetNumberOfViews();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (this->HasCylinder())
  {
    const Internals& in = *this->Internal;
    std::stable_sort(order.begin(),
      order.end(),
      [&](int a, int b)
      { return in.Row[a] != in.Row[b] ? in.Row[a] < in.Row[b] : in.Azimuth[a] < in.Azimuth[b]; });
  }
  for (int v : order)
  {
    views->InsertNextId(v);
  }
}

//------------------------------------------------------------------------------
lfd::RingLayout vtkCameraRig::GetRingLayout(const std::vector<int>& excluded) const
{
  lfd::RingLayout layout;
  if (!this->HasCylinder())
  {
    return layout;
  }
  const Internals& in = *this->Internal;
  const int n = this->GetNumberOfViews();
  auto group = [&](int v) { return in.DuplicateOf[v] >= 0 ? in.DuplicateOf[v] : v; };
  std::vector<bool> skip(n, false);
  for (int e : excluded)
  {
    if (e < 0 || e >= n)
    {
      continue;
    }
    for (int v = 0; v < n; ++v)
    {
      skip[v] = skip[v] || group(v) == group(e);
    }
  }
  layout.Cyl = { ToVec(this->Center), ToVec(this->Axis), this->Radius };
  layout.RefX = in.RefX;
  layout.RefY = in.RefY;
  layout.Rows.resize(in.RowHeights.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(
    order.begin(), order.end(), [&](int a, int b) { return in.Azimuth[a] < in.Azimuth[b]; });
  for (int v : order)
  {
    if (skip[v] || in.DuplicateOf[v] >= 0)
    {
      continue;
    }
    lfd::RingRow& row = layout.Rows[in.Row[v]];
    row.Azimuth.push_back(in.Azimuth[v]);
    row.View.push_back(v);
  }
  for (std::size_t r = 0; r < layout.Rows.size(); ++r)
  {
    layout.Rows[r].Height = in.RowHeights[r];
    layout.Rows[r].Index();
  }
  layout.Rows.erase(std::remove_if(layout.Rows.begin(),
                      layout.Rows.end(),
                      [](const lfd::RingRow& row) { return row.View.empty(); }),
    layout.Rows.end());
  return layout;
}

//------------------------------------------------------------------------------
std::string vtkCameraRig::DescribeExtrapolation(const double eye[3]) const
{
  if (!this->HasCylinder())
  {
    return std::string();
  }
  const std::vector<double>& rows = this->Internal->RowHeights;
  const glm::dvec3 low = ToVec(this->Center) + rows.front() * ToVec(this->Axis);
  const glm::dvec3 high = ToVec(this->Center) + rows.back() * ToVec(this->Axis);
  double bounds[6];
  for (int c = 0; c < 3; ++c)
  {
    bounds[2 * c] = std::min(low[c], high[c]);
    bounds[2 * c + 1] = std::max(low[c], high[c]);
  }
  return this->DescribeExtrapolation(eye, bounds);
}

//------------------------------------------------------------------------------
std::string vtkCameraRig::DescribeExtrapolation(const double eye[3], const double bounds[6]) const
{
  const lfd::RingLayout layout = this->GetRingLayout();
  if (layout.Rows.empty())
  {
    return std::string();
  }
  const glm::dvec3 origin = ToVec(eye);
  const double lowest = layout.Rows.front().Height;
  const double highest = layout.Rows.back().Height;
  double above = 0.0;
  double below = 0.0;
  RingGap gap;
  for (const glm::dvec3& target : lfd::BoundsProbes(bounds))
  {
    glm::dvec3 entry;
    if (!lfd::RayEntry(layout.Cyl, origin, target, entry))
    {
      continue;
    }
    double azimuth = 0.0;
    double height = 0.0;
    layout.Locate(entry, azimuth, height);
    above = std::max(above, height - highest);
    below = std::max(below, lowest - height);
    if (!gap.Found)
    {
      gap = FindRingGap(layout, azimuth, height);
    }
  }
  const double tolerance = 0.01 * layout.Cyl.Radius;
  std::ostringstream line;
  line << std::setprecision(4);
  if (above > tolerance || below > tolerance)
  {
    const bool up = above >= below;
    line << "rays from the eye (" << eye[0] << ", " << eye[1] << ", " << eye[2]
         << ") reach the rig cylinder " << (up ? above : below) << (up ? " above" : " below")
         << " the " << (up ? "highest" : "lowest") << " of the " << layout.Rows.size()
         << " captured rows (height " << (up ? highest : lowest)
         << "), where the renderer clamps them to that row";
  }
  if (gap.Found)
  {
    line << (line.tellp() > 0 ? "; they also enter" : "rays from the eye enter")
         << " the ring at azimuth " << vtkMath::DegreesFromRadians(gap.Azimuth) << " degrees, in a "
         << vtkMath::DegreesFromRadians(gap.Width) << "-degree gap between views " << gap.From
         << " and " << gap.To << " (the row's median step is "
         << vtkMath::DegreesFromRadians(gap.MedianStep) << " degrees)";
  }
  return line.str();
}

//------------------------------------------------------------------------------
void vtkCameraRig::DeepCopy(vtkCameraRig* source)
{
  if (!source || source == this)
  {
    return;
  }
  const bool fitted = source->HasCylinder();
  *this->Internal = *source->Internal;
  this->SetImageSize(source->ImageSize);
  this->DuplicateTolerance = source->DuplicateTolerance;
  this->MinimumRowGap = source->MinimumRowGap;
  this->RowGapRatio = source->RowGapRatio;
  std::copy(source->Axis, source->Axis + 3, this->Axis);
  std::copy(source->Center, source->Center + 3, this->Center);
  this->Radius = source->Radius;
  this->FitResidual = source->FitResidual;
  this->Modified();
  // A current fit is copied as current: the copy need not be fitted again.
  this->Internal->Fitted = fitted;
  this->Internal->FitTime.Modified();
}

//------------------------------------------------------------------------------
void vtkCameraRig::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfViews: " << this->GetNumberOfViews() << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "DuplicateTolerance: " << this->DuplicateTolerance << "\n";
  os << indent << "MinimumRowGap: " << this->MinimumRowGap << "\n";
  os << indent << "RowGapRatio: " << this->RowGapRatio << "\n";
  os << indent << "Distortion: " << (this->HasDistortion() ? "yes" : "none") << "\n";
  os << indent << "Cylinder fitted: " << (this->HasCylinder() ? "yes" : "no") << "\n";
  if (this->HasCylinder())
  {
    os << indent << "Axis: (" << this->Axis[0] << ", " << this->Axis[1] << ", " << this->Axis[2]
       << ")\n";
    os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
       << this->Center[2] << ")\n";
    os << indent << "Radius: " << this->Radius << "\n";
    os << indent << "FitResidual: " << this->FitResidual << "\n";
    os << indent << "NumberOfRows: " << this->GetNumberOfRows() << "\n";
    os << indent << "NumberOfDuplicates: " << this->GetNumberOfDuplicates() << "\n";
  }
}

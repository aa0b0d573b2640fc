#include "vtkColmapExporter.h"

#include "vtkCameraRig.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <array>
#include <cstdio>
#include <sstream>

vtkStandardNewMacro(vtkColmapExporter);

namespace
{
// Shortest text that reads back as the same double.
std::string Exact(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// fx fy cx cy k1 k2 p1 p2 k3: what makes two views one COLMAP camera.
using Intrinsics = std::array<double, 9>;

Intrinsics ViewIntrinsics(vtkCameraRig* rig, int view)
{
  double K[9];
  double d[5];
  rig->GetIntrinsics(view, K);
  rig->GetDistortion(view, d);
  return { K[0], K[4], K[2], K[5], d[0], d[1], d[2], d[3], d[4] };
}

std::string CameraLine(int id, const Intrinsics& c, int width, int height)
{
  // COLMAP's pixel centres are at half-integers, the rig's at integers.
  std::string line = std::to_string(id);
  const bool distorted = c[4] != 0.0 || c[5] != 0.0 || c[6] != 0.0 || c[7] != 0.0 || c[8] != 0.0;
  line += !distorted ? " PINHOLE " : c[8] == 0.0 ? " OPENCV " : " FULL_OPENCV ";
  line += std::to_string(width) + " " + std::to_string(height);
  const double parameters[4] = { c[0], c[1], c[2] + 0.5, c[3] + 0.5 };
  for (double p : parameters)
  {
    line += " " + Exact(p);
  }
  const int coefficients = !distorted ? 0 : c[8] == 0.0 ? 4 : 5;
  for (int k = 0; k < coefficients; ++k)
  {
    line += " " + Exact(c[4 + k]);
  }
  if (coefficients == 5)
  {
    line += " 0 0 0"; // k4 k5 k6: the rational terms, unused
  }
  return line + "\n";
}
}

//------------------------------------------------------------------------------
vtkColmapExporter::vtkColmapExporter() = default;

//------------------------------------------------------------------------------
vtkColmapExporter::~vtkColmapExporter() = default;

//------------------------------------------------------------------------------
bool vtkColmapExporter::FormatCalibration(vtkCameraRig* rig,
  const std::vector<std::string>& imageNames,
  std::map<std::string, std::string>& files,
  std::string& error)
{
  const int* size = rig->GetImageSize();
  std::map<Intrinsics, int> cameraIds;
  std::string cameras = "# Camera list with one line of data per camera:\n"
                        "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
                        "# Written by lfd (vtkColmapExporter)\n";
  std::string images = "# Image list with two lines of data per image:\n"
                       "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
                       "#   POINTS2D[] as (X, Y, POINT3D_ID)\n";
  for (int i = 0; i < rig->GetNumberOfViews(); ++i)
  {
    error = CheckNoSkew(rig, i);
    if (!error.empty())
    {
      return false;
    }
    const Intrinsics intrinsics = ViewIntrinsics(rig, i);
    auto camera = cameraIds.find(intrinsics);
    if (camera == cameraIds.end())
    {
      const int id = static_cast<int>(cameraIds.size()) + 1;
      camera = cameraIds.emplace(intrinsics, id).first;
      cameras += CameraLine(id, intrinsics, size[0], size[1]);
    }
    double R[9];
    double t[3];
    rig->GetRotation(i, R);
    rig->GetTranslation(i, t);
    const double rotation[3][3] = {
      { R[0], R[1], R[2] }, { R[3], R[4], R[5] }, { R[6], R[7], R[8] }
    };
    double q[4];
    vtkMath::Matrix3x3ToQuaternion(rotation, q);
    const double sign = q[0] < 0.0 ? -1.0 : 1.0; // q and -q are one rotation
    std::string line = std::to_string(i + 1);
    for (double value : q)
    {
      line += " " + Exact(sign * value);
    }
    for (double value : t)
    {
      line += " " + Exact(value);
    }
    images += line + " " + std::to_string(camera->second) + " " + imageNames[i] + "\n\n";
  }
  files["sparse/cameras.txt"] = cameras;
  files["sparse/images.txt"] = images;
  files["sparse/points3D.txt"] = "# 3D point list with one line of data per point:\n"
                                 "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, "
                                 "POINT2D_IDX)\n";
  return true;
}

//------------------------------------------------------------------------------
void vtkColmapExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

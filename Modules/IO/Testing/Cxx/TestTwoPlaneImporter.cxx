// vtkTwoPlaneImporter: a tiny 2 x 3 grid folder named like the Stanford
// archive imports into the exact rig (centres, R, K, order, names, a
// two-plane rig without a cylinder fit), also with per-image positions from
// a PositionsFile, and each malformed folder or positions file fails with
// one line naming the folder or the file (and the line).
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkTwoPlaneImporter.h"

#include <filesystem>

namespace TestTwoPlaneImporterHelpers
{

/// Imports `folder`; the output, or null with the error in `message`.
vtkSmartPointer<vtkLightField> Import(const std::string& folder,
  double focalLength,
  std::string& message,
  const std::string& positions = "")
{
  vtkNew<vtkTwoPlaneImporter> importer;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(importer);
  importer->SetFileName(folder.c_str());
  importer->SetSpacing(0.25);
  importer->SetFocalLength(focalLength);
  importer->SetPositionsFile(positions.empty() ? nullptr : positions.c_str());
  importer->Update();
  message = catcher->GetErrorMessage();
  if (importer->GetErrorCode() != 0)
  {
    lfdtest::Check(
      importer->GetOutput()->GetNumberOfPoints() == 0, "the output of a failed import is empty");
    return nullptr;
  }
  return importer->GetOutput();
}

/// A folder of the 2 x 3 grid, rows 0-1 and columns 0-2, 5 x 4 pixels,
/// view (r, c) filled with 10 (3 r + c), plus a file that is not an image.
std::string GridFolder(const std::string& name)
{
  const std::string folder = lfdtest::ScratchFolder("TestTwoPlaneImporter/" + name);
  for (int r = 0; r < 2; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      lfdtest::WriteUniformPng(folder + "/out_0" + std::to_string(r) + "_0" + std::to_string(c) +
          "_-381.6_" + std::to_string(100 * c) + ".5_.png",
        5,
        4,
        3,
        10 * (3 * r + c));
    }
  }
  lfdtest::WriteText(folder + "/README.txt", "not an image\n");
  return folder;
}
}

int TestTwoPlaneImporter(int, char*[])
{
  using namespace TestTwoPlaneImporterHelpers;
  std::string message;
  const std::string folder = GridFolder("valid");
  vtkSmartPointer<vtkLightField> lightField = Import(folder, 40.0, message);
  lfdtest::Check(lightField != nullptr, "the 2 x 3 grid imports: " + message);
  if (lightField)
  {
    vtkCameraRig* rig = lightField->GetRig();
    lfdtest::CheckEqual(rig->GetNumberOfViews(), 6, "views");
    lfdtest::CheckEqual(rig->GetImageSize()[0] * 10 + rig->GetImageSize()[1], 54, "image 5 x 4");
    lfdtest::Check(rig->IsTwoPlane(), "a two-plane rig");
    lfdtest::Check(!rig->HasCylinder(), "no cylinder fitted to a grid");
    lfdtest::CheckEqual(std::string(rig->GetViewName(5)),
      std::string("out_01_02_-381.6_200.5_.png"),
      "view 5 is row 1, column 2");
    bool exact = true;
    for (int v = 0; v < 6; ++v)
    {
      double K[9], R[9], centre[3];
      rig->GetIntrinsics(v, K);
      rig->GetRotation(v, R);
      rig->GetCameraCenter(v, centre);
      const double expectedK[9] = { 40, 0, 2, 0, 40, 1.5, 0, 0, 1 };
      const double expectedR[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
      const double expectedCentre[3] = { 0.25 * (v % 3), 0.25 * (v / 3), 0.0 };
      for (int i = 0; i < 9; ++i)
      {
        exact = exact && K[i] == expectedK[i] && R[i] == expectedR[i];
      }
      for (int i = 0; i < 3; ++i)
      {
        exact = exact && centre[i] == expectedCentre[i];
      }
      const vtkIdType p = lightField->GetPointIndex(v, 1, 1);
      exact = exact && lightField->GetPass(vtkLightField::COAXIAL)->GetComponent(p, 0) == 10 * v;
    }
    lfdtest::Check(exact,
      "every view: K = [40 0 2; 0 40 1.5; 0 0 1], R = I, centre (c, r, 0) / 4 "
      "and its image");
  }

  // Per-image positions: each image's centre from the file, in any order.
  const std::string positions = folder + "/positions.txt";
  std::string lines = "# name x y\n";
  for (int v = 5; v >= 0; --v)
  {
    lines += "out_0" + std::to_string(v / 3) + "_0" + std::to_string(v % 3) + "_-381.6_" +
      std::to_string(100 * (v % 3)) + ".5_.png " + std::to_string(0.5 * v) + " " +
      std::to_string(-0.125 * v) + "\n";
  }
  lfdtest::WriteText(positions, lines);
  vtkSmartPointer<vtkLightField> placed = Import(folder, 40.0, message, positions);
  lfdtest::Check(placed != nullptr, "the grid with a positions file imports: " + message);
  if (placed)
  {
    bool exact = true;
    for (int v = 0; v < 6; ++v)
    {
      double centre[3];
      placed->GetRig()->GetCameraCenter(v, centre);
      exact = exact && centre[0] == 0.5 * v && centre[1] == -0.125 * v && centre[2] == 0.0;
    }
    lfdtest::Check(exact, "every view's centre is its line's (x, y, 0)");
  }
  const std::string shortFile = folder + "/short.txt";
  lfdtest::WriteText(shortFile, "out_00_00_-381.6_0.5_.png 0 0\n");
  lfdtest::CheckFailure("an image without a position",
    Import(folder, 40.0, message, shortFile) == nullptr,
    message,
    { shortFile, "no position for out_00_01_-381.6_100.5_.png" });
  const std::string badFile = folder + "/bad.txt";
  lfdtest::WriteText(badFile, "# positions\nout_00_00_-381.6_0.5_.png 0 x\n");
  lfdtest::CheckFailure("a position that is not a number",
    Import(folder, 40.0, message, badFile) == nullptr,
    message,
    { badFile + ": line 2", "is not a number: \"x\"" });
  const std::string extraFile = folder + "/extra.txt";
  lfdtest::WriteText(extraFile, lines + "elsewhere.png 1 1\n");
  lfdtest::CheckFailure("a line for no image of the folder",
    Import(folder, 40.0, message, extraFile) == nullptr,
    message,
    { extraFile + ": line 8", "elsewhere.png is not an image of" });

  // Malformed folders: one line naming the folder or the file.
  lfdtest::CheckFailure("focal length not set",
    Import(folder, 0.0, message) == nullptr,
    message,
    { folder, "FocalLength" });
  const std::string missing = folder + "/nowhere";
  lfdtest::CheckFailure("not a folder",
    Import(missing, 40.0, message) == nullptr,
    message,
    { missing, "not a folder" });
  const std::string empty = lfdtest::ScratchFolder("TestTwoPlaneImporter/empty");
  lfdtest::CheckFailure(
    "no images", Import(empty, 40.0, message) == nullptr, message, { empty, "no images" });

  const std::string unnamed = GridFolder("unnamed");
  lfdtest::WriteUniformPng(unnamed + "/view_a_b.png", 5, 4, 3, 0);
  lfdtest::CheckFailure("a name without row and column",
    Import(unnamed, 40.0, message) == nullptr,
    message,
    { unnamed + "/view_a_b.png", "no row and column" });

  const std::string twice = GridFolder("twice");
  lfdtest::WriteUniformPng(twice + "/1_2.png", 5, 4, 3, 0);
  lfdtest::CheckFailure("two files for one cell",
    Import(twice, 40.0, message) == nullptr,
    message,
    { "row 1, column 2 again", "out_01_02_-381.6_200.5_.png" });

  const std::string hole = GridFolder("hole");
  std::filesystem::remove(hole + "/out_01_01_-381.6_100.5_.png");
  lfdtest::CheckFailure("a missing cell",
    Import(hole, 40.0, message) == nullptr,
    message,
    { hole, "no image for row 1, column 1", "rows 0..1 and columns 0..2" });

  const std::string sizes = GridFolder("sizes");
  lfdtest::WriteUniformPng(sizes + "/out_01_00_-381.6_0.5_.png", 6, 4, 3, 0);
  lfdtest::CheckFailure("an image of another size",
    Import(sizes, 40.0, message) == nullptr,
    message,
    { sizes + "/out_01_00_-381.6_0.5_.png", "image is 6x4", "5x4" });
  return lfdtest::Result();
}

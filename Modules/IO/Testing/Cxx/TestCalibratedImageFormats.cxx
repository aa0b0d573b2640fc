// COLMAP text and binary models and transforms.json: export -> import
// gives the same rig (K, R, t, distortion to 1e-9) and the same pixels, with
// shared and per-view intrinsics; malformed files (text, and binary files
// truncated or corrupted field by field) fail with one exact line naming
// the file and the line, record or field.
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkColmapExporter.h"
#include "vtkColmapImporter.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransformsExporter.h"
#include "vtkTransformsImporter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

namespace TestCalibratedImageFormatsHelpers
{
// A ring of 6 views of 16x12 pixels; with `perView`, every view has its own
// focal lengths, principal point and distortion (k3 on one view).
vtkSmartPointer<vtkLightField> MakeLightField(bool perView)
{
  const int width = 16, height = 12, views = 6;
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->SetLayout(width, height, views);
  vtkDataArray* coaxial = lightField->AllocatePass(vtkLightField::COAXIAL);
  for (vtkIdType i = 0; i < coaxial->GetNumberOfValues(); ++i)
  {
    coaxial->SetVariantValue(i, vtkVariant(static_cast<unsigned char>((i * 37) % 251)));
  }
  vtkNew<vtkCameraRig> rig;
  const double centre[3] = { 0.1, -0.2, 0.3 };
  const double axis[3] = { 0.0, 1.0, 0.0 };
  const double heights[1] = { 0.0 };
  rig->MakeCylinder(centre, axis, 2.5, views, 1, heights, width, height, 40.0);
  for (int v = 0; v < views; ++v)
  {
    double K[9], R[9], t[3];
    rig->GetIntrinsics(v, K);
    rig->GetRotation(v, R);
    rig->GetTranslation(v, t);
    const double s = perView ? v : 1.0;
    K[0] *= 1.0 + 0.01 * s;
    K[4] *= 1.0 + 0.013 * s;
    K[2] += 0.25 * s;
    K[5] -= 0.125 * s;
    rig->SetView(v, K, R, t);
    const double distortion[5] = {
      -0.05 * s / 5.0, 0.01, 0.001 * s, -0.0005, perView && v == 3 ? 0.002 : 0.0
    };
    rig->SetDistortion(v, distortion);
    const std::string name = "shot_" + std::to_string(10 + v) + ".jpg";
    rig->SetViewName(v, name.c_str());
  }
  lightField->SetRig(rig);
  return lightField;
}

// The largest difference between two rigs' K, R, t and distortion.
double RigDifference(vtkCameraRig* a, vtkCameraRig* b)
{
  double largest = 0.0;
  for (int v = 0; v < a->GetNumberOfViews(); ++v)
  {
    double x[9], y[9];
    auto compare = [&](int n)
    {
      for (int i = 0; i < n; ++i)
      {
        largest = std::max(largest, std::abs(x[i] - y[i]));
      }
    };
    a->GetIntrinsics(v, x);
    b->GetIntrinsics(v, y);
    compare(9);
    a->GetRotation(v, x);
    b->GetRotation(v, y);
    compare(9);
    a->GetTranslation(v, x);
    b->GetTranslation(v, y);
    compare(3);
    a->GetDistortion(v, x);
    b->GetDistortion(v, y);
    compare(5);
  }
  return largest;
}

template<typename Importer>
void RoundTrip(const std::string& format,
  vtkCalibratedImageExporter* exporter,
  vtkLightField* original,
  const std::string& folder,
  const std::string& calibration,
  const std::string& images)
{
  vtkNew<vtkLightFieldErrorObserver> exportErrors;
  exportErrors->Observe(exporter);
  exporter->SetInputData(original);
  exporter->SetDirectoryName(folder.c_str());
  exporter->Write();
  lfdtest::Check(exporter->GetErrorCode() == 0 && !exportErrors->HasError(),
    format + ": export " + exportErrors->GetErrorMessage());
  vtkNew<Importer> importer;
  vtkNew<vtkLightFieldErrorObserver> importErrors;
  importErrors->Observe(importer);
  importer->SetFileName((folder + "/" + calibration).c_str());
  if (!images.empty())
  {
    importer->SetImageDirectory((folder + "/" + images).c_str());
  }
  importer->Update();
  if (!lfdtest::Check(
        importer->GetErrorCode() == 0, format + ": import " + importErrors->GetErrorMessage()))
  {
    return;
  }
  vtkLightField* back = importer->GetOutput();
  lfdtest::CheckEqual(back->GetNumberOfViews(), original->GetNumberOfViews(), format + ": views");
  const double difference = RigDifference(original->GetRig(), back->GetRig());
  lfdtest::CheckRange(difference, 0.0, 1e-9, format + ": largest K/R/t/distortion difference");
  vtkDataArray* a = original->GetPass(vtkLightField::COAXIAL);
  vtkDataArray* b = back->GetPass(vtkLightField::COAXIAL);
  bool same = b && a->GetNumberOfValues() == b->GetNumberOfValues();
  for (vtkIdType i = 0; same && i < a->GetNumberOfValues(); ++i)
  {
    same = a->GetVariantValue(i) == b->GetVariantValue(i);
  }
  lfdtest::Check(same, format + ": every pixel of every view identical");
  lfdtest::CheckEqual(std::string(back->GetRig()->GetViewName(0)),
    std::string(calibration == "sparse" ? "shot_10.png" : "images/shot_10.png"),
    format + ": view 0's name");
}

template<typename Importer>
void ExpectFailure(const std::string& name,
  const std::string& fileName,
  const std::string& expected)
{
  vtkNew<Importer> importer;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(importer);
  importer->SetFileName(fileName.c_str());
  importer->Update();
  const bool failed = importer->GetErrorCode() != 0;
  lfdtest::CheckFailure(name, failed, errors->GetErrorMessage(), { expected });
  lfdtest::CheckEqual(
    std::string(errors->GetErrorMessage()), expected, name + ": the whole message, exactly");
  lfdtest::CheckEqual(
    importer->GetOutput()->GetNumberOfPoints(), static_cast<vtkIdType>(0), name + ": empty output");
}

const std::string Pose = " 1 0 0 0 0 0 4";

void MalformedColmap(const std::string& root)
{
  int number = 0;
  auto model = [&](const std::string& cameras, const std::string& images)
  {
    const std::string folder = root + "/colmap" + std::to_string(++number);
    std::filesystem::create_directories(folder);
    lfdtest::WriteUniformPng(folder + "/a.png", 8, 6, 3, 80);
    lfdtest::WriteUniformPng(folder + "/b.png", 8, 6, 3, 80);
    lfdtest::WriteText(folder + "/cameras.txt", "# comment\n" + cameras);
    lfdtest::WriteText(folder + "/images.txt", "# comment\n" + images);
    return folder;
  };
  std::string f = model("1 PINHOLE 8 6 10 10 4 3\n", "1" + Pose + " 1 a.png\n\n");
  {
    vtkNew<vtkColmapImporter> importer;
    importer->SetFileName(f.c_str());
    importer->Update();
    double K[9];
    importer->GetOutput()->GetRig()->GetIntrinsics(0, K);
    lfdtest::Check(importer->GetErrorCode() == 0 && K[2] == 3.5 && K[5] == 2.5,
      "a valid one-view model imports, principal point moved by half a pixel: (" +
        std::to_string(K[2]) + ", " + std::to_string(K[5]) + ")");
  }
  f = model("1 PINHOLE 8 6 10 10 4\n", "");
  ExpectFailure<vtkColmapImporter>("too few camera parameters",
    f,
    f + "/cameras.txt:2: a PINHOLE camera has 4 parameters, found 3");
  f = model("1 OPENCV_FISHEYE 8 6 10 10 4 3 0 0 0 0\n", "");
  ExpectFailure<vtkColmapImporter>("unsupported model",
    f,
    f +
      "/cameras.txt:2: MODEL OPENCV_FISHEYE is not supported (supported: SIMPLE_PINHOLE, "
      "PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV)");
  f = model("1 FULL_OPENCV 8 6 10 10 4 3 0 0 0 0 0 0.1 0 0\n", "");
  ExpectFailure<vtkColmapImporter>("rational FULL_OPENCV",
    f,
    f +
      "/cameras.txt:2: k4 is not 0: the rational terms of FULL_OPENCV have no equivalent in the "
      "rig's distortion (k1, k2, p1, p2, k3)");
  f = model("1 PINHOLE 8 6 10 ten 4 3\n", "");
  ExpectFailure<vtkColmapImporter>(
    "a word for a number", f, f + "/cameras.txt:2: fy is not a number: \"ten\"");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n", "1 1 0 0 0 0 0 4 1\n\n");
  ExpectFailure<vtkColmapImporter>("9 image fields",
    f,
    f +
      "/images.txt:2: expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (10 fields), found 9");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n", "1 0 0 0 0 0 0 4 1 a.png\n\n");
  ExpectFailure<vtkColmapImporter>(
    "zero quaternion", f, f + "/images.txt:2: QW QX QY QZ: not a rotation (a zero quaternion)");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n", "1" + Pose + " 7 a.png\n\n");
  ExpectFailure<vtkColmapImporter>(
    "unknown camera", f, f + "/images.txt:2: CAMERA_ID 7 is not in cameras.txt");
  f = model(
    "1 SIMPLE_PINHOLE 8 6 10 4 3\n", "1" + Pose + " 1 a.png\n2 3 4\n2 1 0 0 0 0 0 5 1 a.png\n\n");
  ExpectFailure<vtkColmapImporter>("repeated name",
    f,
    f + "/images.txt:4: NAME a.png is repeated (first on " + f + "/images.txt:2)");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n2 SIMPLE_PINHOLE 9 6 10 4 3\n",
    "1" + Pose + " 1 a.png\n\n2 1 0 0 0 0 0 5 2 b.png\n\n");
  ExpectFailure<vtkColmapImporter>("cameras of two sizes",
    f,
    f + "/cameras.txt:3: the camera is 9x6, " + f +
      "/cameras.txt:2 is 8x6 (a light field has one image size)");
  f = model("1 SIMPLE_PINHOLE 8 6 -10 4 3\n", "1" + Pose + " 1 a.png\n\n");
  ExpectFailure<vtkColmapImporter>("negative focal length (the rig's validation)",
    f,
    f +
      "/cameras.txt:2: camera parameters: focal lengths fx = K[0] and fy = K[4] must be positive");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n", "1" + Pose + " 1 gone.png\n\n");
  ExpectFailure<vtkColmapImporter>(
    "missing image", f, f + "/images.txt:2: image " + f + "/gone.png: file not found");
  f = model("1 SIMPLE_PINHOLE 8 6 10 4 3\n", "");
  ExpectFailure<vtkColmapImporter>("no image", f, f + "/images.txt: no registered image");
  ExpectFailure<vtkColmapImporter>("no model folder",
    root + "/none",
    root + "/none: no COLMAP sparse model (no cameras.bin, no cameras.txt)");
}

// Writes `size` little-endian bytes of `value` at `offset` of `bytes`.
void Put(std::string& bytes, size_t offset, uint64_t value, int size)
{
  for (int b = 0; b < size; ++b)
  {
    bytes[offset + b] = static_cast<char>((value >> (8 * b)) & 0xff);
  }
}

// The binary export of MakeLightField(false) in `exported` (one OPENCV
// camera: cameras.bin is 8 + 96 bytes, the count then CAMERA_ID at 8,
// MODEL_ID 12, WIDTH 16, HEIGHT 24, PARAMS from 32; images.bin the count
// then 6 records of 84 bytes from 8: IMAGE_ID +0, QW..QZ +4, TX..TZ +36,
// CAMERA_ID +60, NAME "shot_1N.png" +64, POINTS2D +76), corrupted one way
// per case.
void MalformedBinaryColmap(const std::string& root, const std::string& exported)
{
  int number = 0;
  auto corrupt = [&](const std::string& file, const std::function<void(std::string&)>& change)
  {
    const std::string folder = root + "/colmap-bin" + std::to_string(++number);
    std::filesystem::create_directories(folder);
    for (const std::string name : { "cameras.bin", "images.bin", "points3D.bin" })
    {
      std::string bytes = lfdtest::ReadText(exported + "/sparse/" + name);
      if (name == file)
      {
        change(bytes);
      }
      if (!bytes.empty() || name == file)
      {
        lfdtest::WriteText(folder + "/" + name, bytes);
      }
    }
    return folder;
  };
  std::string f = corrupt("", [](std::string&) {});
  {
    vtkNew<vtkColmapImporter> importer;
    importer->SetFileName(f.c_str());
    importer->SetImageDirectory((exported + "/images").c_str());
    importer->Update();
    lfdtest::Check(importer->GetErrorCode() == 0 && importer->GetBinaryModel() &&
        importer->GetOutput()->GetNumberOfViews() == 6,
      "an uncorrupted copy of the binary export imports as a binary model, 6 views");
  }
  const std::string cameras = "/cameras.bin: record 1 of 1: ";
  const std::string images = "/images.bin: record ";
  f = corrupt("cameras.bin", [](std::string& b) { b.clear(); });
  ExpectFailure<vtkColmapImporter>("empty cameras.bin",
    f,
    f + "/cameras.bin: truncated in the number of cameras (the file ends at byte 0)");
  f = corrupt("cameras.bin", [](std::string& b) { b.resize(60); });
  ExpectFailure<vtkColmapImporter>(
    "cameras.bin cut inside cy", f, f + cameras + "truncated in cy (the file ends at byte 60)");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 12, 5, 4); });
  ExpectFailure<vtkColmapImporter>("fisheye MODEL_ID",
    f,
    f + cameras +
      "MODEL_ID 5 (OPENCV_FISHEYE) is not supported (supported: SIMPLE_PINHOLE, PINHOLE, "
      "SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV)");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 12, 0xffffffff, 4); });
  ExpectFailure<vtkColmapImporter>("MODEL_ID -1",
    f,
    f + cameras +
      "MODEL_ID -1 (not a COLMAP 3.8 camera model) is not supported (supported: "
      "SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, FULL_OPENCV)");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 16, 0, 8); });
  ExpectFailure<vtkColmapImporter>(
    "WIDTH 0", f, f + cameras + "WIDTH is 0, not an integer from 1 to 2147483647");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 32, 0x7ff8000000000000ULL, 8); });
  ExpectFailure<vtkColmapImporter>("fx NaN", f, f + cameras + "fx is not finite (nan)");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 0, 2, 8); });
  ExpectFailure<vtkColmapImporter>("2 cameras announced, 1 written",
    f,
    f + "/cameras.bin: record 2 of 2: truncated in CAMERA_ID (the file ends at byte 96)");
  f = corrupt("cameras.bin", [](std::string& b) { Put(b, 0, 0, 8); });
  ExpectFailure<vtkColmapImporter>("0 cameras announced, 1 written",
    f,
    f + "/cameras.bin: 88 bytes after the last of the 0 records");
  f = corrupt("cameras.bin", [](std::string& b) { b.assign(8, '\0'); });
  ExpectFailure<vtkColmapImporter>("no camera", f, f + "/cameras.bin: no camera");
  f = corrupt("images.bin", [](std::string& b) { Put(b, 0, 7, 8); });
  ExpectFailure<vtkColmapImporter>("7 images announced, 6 written",
    f,
    f + images + "7 of 7: truncated in IMAGE_ID (the file ends at byte 512)");
  f = corrupt("images.bin", [](std::string& b) { b.resize(8 + 5 * 84 + 70); });
  ExpectFailure<vtkColmapImporter>("images.bin cut inside the last NAME",
    f,
    f + images + "6 of 6: NAME has no terminating 0 byte (the file ends at byte 498)");
  f = corrupt("images.bin", [](std::string& b) { Put(b, 8 + 5 * 84 + 76, 1000000, 8); });
  ExpectFailure<vtkColmapImporter>("a million 2D points announced",
    f,
    f + images + "6 of 6: truncated in POINTS2D: 1000000 of 24 bytes, 0 bytes left");
  f = corrupt("images.bin", [](std::string& b) { b += "abc"; });
  ExpectFailure<vtkColmapImporter>(
    "bytes after the last image", f, f + "/images.bin: 3 bytes after the last of the 6 records");
  f = corrupt("images.bin", [](std::string& b) { b.replace(12, 32, 32, '\0'); });
  ExpectFailure<vtkColmapImporter>(
    "zero quaternion", f, f + images + "1 of 6: QW QX QY QZ: not a rotation (a zero quaternion)");
  f = corrupt("images.bin", [](std::string& b) { Put(b, 68, 9, 4); });
  ExpectFailure<vtkColmapImporter>(
    "unknown camera", f, f + images + "1 of 6: CAMERA_ID 9 is not in cameras.bin");
  f = corrupt("images.bin", [](std::string& b) { Put(b, 92, 1, 4); });
  ExpectFailure<vtkColmapImporter>("repeated IMAGE_ID",
    f,
    f + images + "2 of 6: IMAGE_ID 1 is repeated (first on " + f + images + "1 of 6)");
  f = corrupt("images.bin", [](std::string& b) { b.clear(); });
  std::filesystem::remove(f + "/images.bin");
  ExpectFailure<vtkColmapImporter>("no images.bin", f, f + "/images.bin: file not found");
}

void MalformedTransforms(const std::string& root)
{
  lfdtest::WriteUniformPng(root + "/a.png", 8, 6, 3, 80);
  int number = 0;
  auto file = [&](const std::string& text)
  {
    const std::string path = root + "/transforms" + std::to_string(++number) + ".json";
    lfdtest::WriteText(path, text);
    return path;
  };
  const std::string frame =
    R"({"file_path": "a.png", "transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]})";
  std::string f = file(R"({"fl_x": 10, "w": 8, "h": 6, "frames": [)" + frame + "]}");
  {
    vtkNew<vtkTransformsImporter> importer;
    importer->SetFileName(f.c_str());
    importer->Update();
    double K[9], R[9], t[3];
    importer->GetOutput()->GetRig()->GetIntrinsics(0, K);
    importer->GetOutput()->GetRig()->GetRotation(0, R);
    importer->GetOutput()->GetRig()->GetTranslation(0, t);
    // OpenGL camera at (0, 0, 4) looking along -z: OpenCV R = diag(1, -1, -1), t = (0, 0, 4).
    lfdtest::Check(importer->GetErrorCode() == 0 && K[4] == 10.0 && K[2] == 3.5 && K[5] == 2.5 &&
        R[0] == 1.0 && R[4] == -1.0 && R[8] == -1.0 && t[2] == 4.0,
      "a valid one-frame file imports: fl_y = fl_x, cx = w/2 - 0.5, OpenGL -> OpenCV axes");
  }
  f = file(R"({"w": 8, "h": 6, "frames": [)" + frame + "]}");
  ExpectFailure<vtkTransformsImporter>(
    "no focal length", f, f + ": field \"frames[0].fl_x\": missing (give fl_x or camera_angle_x)");
  f = file(R"({"fl_x": "10", "w": 8, "h": 6, "frames": [)" + frame + "]}");
  ExpectFailure<vtkTransformsImporter>("focal length as a string",
    f,
    f + ": field \"fl_x\": expected a number, found the string \"10\"");
  f =
    file(R"({"fl_x": 10, "w": 8, "h": 6, "frames": [{"file_path": "a.png", "k1": null, "fl_y": [1],
    "transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]})");
  ExpectFailure<vtkTransformsImporter>("per-frame fl_y an array",
    f,
    f + ": field \"frames[0].fl_y\": expected a number, found an array of 1 elements");
  f = file(R"({"fl_x": 10, "w": 8, "h": 6, "frames": [{"file_path": "a.png",
    "transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,1,1]]}]})");
  ExpectFailure<vtkTransformsImporter>("last row not 0 0 0 1",
    f,
    f +
      ": field \"frames[0].transform_matrix[3]\": expected [0, 0, 0, 1] (a rigid "
      "camera-to-world matrix)");
  f = file(R"({"fl_x": 10, "w": 8, "h": 6, "frames": [{"file_path": "a.png",
    "transform_matrix": [[2,0,0,0],[0,1,0,0],[0,0,1,4],[0,0,0,1]]}]})");
  ExpectFailure<vtkTransformsImporter>("a scaled rotation (the rig's validation)",
    f,
    f + ": field \"frames[0]\": transform_matrix (rotation): not a rotation matrix (R R^T != I)");
  f = file(
    R"({"camera_model": "OPENCV_FISHEYE", "fl_x": 10, "w": 8, "h": 6, "frames": [)" + frame + "]}");
  ExpectFailure<vtkTransformsImporter>("fisheye",
    f,
    f +
      ": field \"camera_model\": camera model \"OPENCV_FISHEYE\" is not supported (OPENCV, "
      "PINHOLE)");
  f = file(R"({"fl_x": 10, "w": 8, "frames": [)" + frame + "]}");
  ExpectFailure<vtkTransformsImporter>(
    "no height", f, f + ": field \"frames[0].h\": missing (the image size w, h is required)");
  f = file(R"({"fl_x": 10, "w": 8, "h": 6, "frames": []})");
  ExpectFailure<vtkTransformsImporter>("no frame",
    f,
    f + ": field \"frames\": expected a non-empty array, found an array of 0 elements");
  f = file(R"({"fl_x": 10, "w": 9, "h": 6, "frames": [)" + frame + "]}");
  ExpectFailure<vtkTransformsImporter>("image of another size",
    f,
    f + ": field \"frames[0]\": image " + root + "/a.png: image is 8x6, the calibration says 9x6");
}
}

int TestCalibratedImageFormats(int, char*[])
{
  using namespace TestCalibratedImageFormatsHelpers;
  const std::string folder = lfdtest::ScratchFolder("TestCalibratedImageFormats");
  for (bool perView : { false, true })
  {
    auto lightField = MakeLightField(perView);
    const std::string tag = perView ? "per-view" : "shared";
    for (bool binary : { false, true })
    {
      vtkNew<vtkColmapExporter> exporter;
      exporter->SetBinary(binary);
      const std::string kind = binary ? "binary" : "text";
      RoundTrip<vtkColmapImporter>("COLMAP " + kind + " (" + tag + " intrinsics)",
        exporter,
        lightField,
        folder + "/colmap-" + kind + "-" + tag,
        "sparse",
        "images");
    }
    vtkNew<vtkTransformsExporter> exporter;
    RoundTrip<vtkTransformsImporter>("transforms.json (" + tag + " intrinsics)",
      exporter,
      lightField,
      folder + "/transforms-" + tag,
      "transforms.json",
      "");
  }
  // Shared intrinsics are written once; per-view ones in each frame; COLMAP
  // gives each distinct camera a line.
  const std::string shared = lfdtest::ReadText(folder + "/transforms-shared/transforms.json");
  const std::string perView = lfdtest::ReadText(folder + "/transforms-per-view/transforms.json");
  lfdtest::CheckEqual(shared.find("\"fl_x\"") < shared.find("\"frames\""),
    true,
    "transforms.json: shared fl_x at the top level");
  lfdtest::CheckEqual(perView.find("\"fl_x\"") > perView.find("\"frames\""),
    true,
    "transforms.json: per-view fl_x in the frames");
  const std::string cameras =
    lfdtest::ReadText(folder + "/colmap-text-per-view/sparse/cameras.txt");
  lfdtest::CheckEqual(static_cast<int>(std::count(cameras.begin(), cameras.end(), '\n')),
    3 + 6,
    "COLMAP, per-view intrinsics: 3 comment lines + 6 cameras");
  lfdtest::Check(cameras.find(" FULL_OPENCV ") != std::string::npos &&
      cameras.find(" OPENCV ") != std::string::npos,
    "COLMAP: OPENCV cameras, FULL_OPENCV for the view with k3");
  // An existing folder that is not an export is never replaced.
  std::filesystem::create_directories(folder + "/precious");
  lfdtest::WriteText(folder + "/precious/notes.txt", "keep");
  {
    vtkNew<vtkColmapExporter> exporter;
    vtkNew<vtkLightFieldErrorObserver> errors;
    errors->Observe(exporter);
    exporter->SetInputData(MakeLightField(false));
    exporter->SetDirectoryName((folder + "/precious").c_str());
    exporter->Write();
    lfdtest::CheckEqual(std::string(errors->GetErrorMessage()),
      folder +
        "/precious: exists and is not an export of this format (no sparse/cameras.txt); "
        "refusing to replace it",
      "export onto an unrelated folder refused");
    lfdtest::CheckEqual(
      lfdtest::ReadText(folder + "/precious/notes.txt"), std::string("keep"), "folder untouched");
  }
  MalformedColmap(folder);
  MalformedBinaryColmap(folder, folder + "/colmap-binary-shared");
  MalformedTransforms(folder);
  return lfdtest::Result();
}

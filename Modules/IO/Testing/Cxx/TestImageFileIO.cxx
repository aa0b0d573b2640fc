// vtkImageFileWriter / vtkImageFileReader: 8-bit RGB PNG, grey PNG, RGBA,
// 16-bit PNG and float EXR round trips with exact values and row order
// (checked against VTK's PNG reader), atomic writes and error messages.
#include "lfdIOTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageFileReader.h"
#include "vtkImageFileWriter.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"

using lfdtest::Check;
using lfdtest::CheckEqual;

namespace TestImageFileIOHelpers
{
constexpr int W = 9;
constexpr int H = 4;

double Value(int type, int x, int y, int c)
{
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      return (x * 23 + y * 61 + c * 7) % 256;
    case VTK_UNSIGNED_SHORT:
      return (x * 5003 + y * 911 + c * 17) % 65536;
    default:
      return static_cast<float>(x / 3.0 - y * 1e5 + c * 0.125);
  }
}

// Image whose VTK row j holds image row y = H - 1 - j.
vtkSmartPointer<vtkImageData> MakeImage(int type, int components)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  image->AllocateScalars(type, components);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      for (int c = 0; c < components; ++c)
      {
        scalars->SetComponent((H - 1 - y) * W + x, c, Value(type, x, y, c));
      }
    }
  }
  return image;
}

void RoundTrip(const std::string& file, int type, int components)
{
  vtkSmartPointer<vtkImageData> image = MakeImage(type, components);
  vtkNew<vtkImageFileWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(file.c_str());
  Check(writer->Write() == 1, "write " + file);
  vtkNew<vtkImageFileReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* read = reader->GetOutput();
  vtkDataArray* a = image->GetPointData()->GetScalars();
  vtkDataArray* b = read->GetPointData()->GetScalars();
  CheckEqual(read->GetDimensions()[0] * 100 + read->GetDimensions()[1],
    W * 100 + H,
    file + " size (100 W + H)");
  if (!b || b->GetNumberOfComponents() != components || b->GetDataType() != type)
  {
    Check(false, file + " scalars of the written type and components");
    return;
  }
  int differing = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      differing += a->GetComponent(i, c) == b->GetComponent(i, c) ? 0 : 1;
    }
  }
  CheckEqual(differing, 0, file + " values differing");
}
}

int TestImageFileIO(int, char*[])
{
  using namespace TestImageFileIOHelpers;
  const std::string folder = lfdtest::ScratchFolder("TestImageFileIO");
  RoundTrip(folder + "/rgb.png", VTK_UNSIGNED_CHAR, 3);
  RoundTrip(folder + "/grey.png", VTK_UNSIGNED_CHAR, 1);
  RoundTrip(folder + "/rgba.png", VTK_UNSIGNED_CHAR, 4);
  RoundTrip(folder + "/deep.png", VTK_UNSIGNED_SHORT, 3);
  RoundTrip(folder + "/depth.exr", VTK_FLOAT, 1);
  RoundTrip(folder + "/colour.tif", VTK_FLOAT, 3);
  CheckEqual(lfdtest::CountEntries(folder, "rgb.tmp-"), 0, "temporary files left");

  // Row order against VTK's reader: file row 0 (top) is image row y = 0.
  vtkNew<vtkPNGReader> png;
  png->SetFileName((folder + "/rgb.png").c_str());
  png->Update();
  vtkDataArray* scalars = png->GetOutput()->GetPointData()->GetScalars();
  CheckEqual(scalars->GetComponent((H - 1) * W + 2, 1),
    Value(VTK_UNSIGNED_CHAR, 2, 0, 1),
    "vtkPNGReader: pixel (2, 0) green");

  vtkNew<vtkImageFileReader> reader;
  vtkNew<vtkLightFieldErrorObserver> catcher;
  catcher->Observe(reader);
  reader->SetFileName((folder + "/absent.png").c_str());
  reader->Update();
  lfdtest::CheckFailure("read a missing file",
    reader->GetErrorCode() != 0,
    catcher->GetErrorMessage(),
    { folder + "/absent.png", "not found" });

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(2, 2, 2);
  volume->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  vtkNew<vtkImageFileWriter> writer;
  catcher->Observe(writer);
  catcher->Clear();
  writer->SetInputData(volume);
  writer->SetFileName((folder + "/volume.png").c_str());
  bool failed = writer->Write() != 1;
  lfdtest::CheckFailure(
    "write a 3D image", failed, catcher->GetErrorMessage(), { folder + "/volume.png", "only 2D" });
  writer->SetInputData(MakeImage(VTK_UNSIGNED_CHAR, 3));
  writer->SetFileName((folder + "/image.unknownformat").c_str());
  catcher->Clear();
  failed = writer->Write() != 1;
  lfdtest::CheckFailure("write an unknown extension",
    failed,
    catcher->GetErrorMessage(),
    { folder + "/image.unknownformat" });
  CheckEqual(lfdtest::CountEntries(folder, "image"), 0, "files left by the failed writes");
  CheckEqual(lfdtest::CountEntries(folder, "volume"), 0, "volume files left");
  return lfdtest::Result();
}

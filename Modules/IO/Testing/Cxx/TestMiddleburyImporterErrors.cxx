// Malformed Middlebury par files: each fails with one line naming the file
// and the line; a valid file with a grey image imports it as RGB.
#include "lfdIOTestUtilities.h"

#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkMiddleburyImporter.h"
#include "vtkNew.h"

namespace TestMiddleburyImporterErrorsHelpers
{

const std::string Calibration = " 100 0 4 0 100 3 0 0 1  1 0 0 0 1 0 0 0 1  0 0 1\n";
// A second camera: every view of a rig must be a distinct camera.
const std::string Calibration2 = " 100 0 4 0 100 3 0 0 1  1 0 0 0 1 0 0 0 1  0 0 2\n";
}

int TestMiddleburyImporterErrors(int, char*[])
{
  using namespace TestMiddleburyImporterErrorsHelpers;
  const std::string folder = lfdtest::ScratchFolder("TestMiddleburyImporterErrors");
  lfdtest::WriteUniformPng(folder + "/a.png", 8, 6, 3, 50);
  lfdtest::WriteUniformPng(folder + "/b.png", 8, 6, 1, 90);
  lfdtest::WriteUniformPng(folder + "/small.png", 4, 4, 3, 10);

  int caseNumber = 0;
  std::string message;
  auto import = [&](const std::string& text, std::string& parFile)
  {
    parFile = folder + "/case" + std::to_string(++caseNumber) + "_par.txt";
    lfdtest::WriteText(parFile, text);
    vtkNew<vtkMiddleburyImporter> importer;
    vtkNew<vtkLightFieldErrorObserver> catcher;
    catcher->Observe(importer);
    importer->SetFileName(parFile.c_str());
    importer->Update();
    message = catcher->GetErrorMessage();
    const bool ok = importer->GetErrorCode() == 0;
    if (!ok && importer->GetOutput()->GetNumberOfPoints() != 0)
    {
      lfdtest::Check(false, "the output of a failed import is empty");
    }
    return ok ? vtkSmartPointer<vtkLightField>(importer->GetOutput()) : nullptr;
  };
  auto expectFailure =
    [&](const std::string& name, const std::string& text, int line, std::vector<std::string> parts)
  {
    std::string parFile;
    const bool ok = import(text, parFile) != nullptr;
    parts.insert(parts.begin(), parFile + ":" + std::to_string(line) + ":");
    lfdtest::CheckFailure(name, !ok, message, parts);
  };

  {
    std::string parFile;
    vtkSmartPointer<vtkLightField> lightField =
      import("2\na.png" + Calibration + "\nb.png" + Calibration2 + "\n\n", parFile);
    lfdtest::Check(lightField != nullptr, "a valid two-view file imports: " + message);
    if (lightField)
    {
      lfdtest::CheckEqual(lightField->GetNumberOfViews(), 2, "views");
      vtkDataArray* coaxial = lightField->GetPass(vtkLightField::COAXIAL);
      const vtkIdType p = lightField->GetPointIndex(1, 2, 3);
      lfdtest::CheckEqual(coaxial->GetComponent(p, 0) + 1000 * coaxial->GetComponent(p, 1) +
          1000000 * coaxial->GetComponent(p, 2),
        90090090.0,
        "grey view 1 expanded to RGB (90, 90, 90)");
      lfdtest::Check(!lightField->GetRig()->HasCylinder(), "no cylinder for 2 views");
    }
  }
  expectFailure("missing count", "a.png" + Calibration, 1, { "number of images" });
  expectFailure("21 fields",
    "1\na.png 100 0 4 0 100 3 0 0 1 1 0 0 0 1 0 0 0 1 0 0\n",
    2,
    { "22 fields", "found 21" });
  expectFailure("23 fields",
    "1\n\na.png" + Calibration.substr(0, Calibration.size() - 1) + " 5\n",
    3,
    { "22 fields", "found 23" });
  expectFailure("non-numeric token",
    "1\na.png 100 0 4 0 100 3 0 0 1 1 0 0 0 1x 0 0 0 1 0 0 1\n",
    2,
    { "field r22", "not a number", "1x" });
  expectFailure("NaN in R",
    "1\na.png 100 0 4 0 100 3 0 0 1 1 0 nan 0 1 0 0 0 1 0 0 1\n",
    2,
    { "field r13", "not finite" });
  expectFailure("inf in t",
    "1\na.png 100 0 4 0 100 3 0 0 1 1 0 0 0 1 0 0 0 1 0 -inf 1\n",
    2,
    { "field t2", "not finite" });
  expectFailure("count larger than the lines",
    "3\na.png" + Calibration + "b.png" + Calibration,
    1,
    { "announces 3 images", "2 calibration lines" });
  expectFailure("count smaller than the lines",
    "1\na.png" + Calibration + "b.png" + Calibration,
    1,
    { "announces 1 images" });
  expectFailure("missing image",
    "2\na.png" + Calibration + "gone.png" + Calibration2,
    3,
    { "gone.png", "not found" });
  expectFailure("image of another size",
    "2\na.png" + Calibration + "small.png" + Calibration2,
    3,
    { "small.png", "4x4", "a.png", "8x6" });
  {
    vtkNew<vtkMiddleburyImporter> importer;
    vtkNew<vtkLightFieldErrorObserver> catcher;
    catcher->Observe(importer);
    importer->SetFileName((folder + "/none_par.txt").c_str());
    importer->Update();
    lfdtest::CheckFailure("missing par file",
      importer->GetErrorCode() != 0,
      catcher->GetErrorMessage(),
      { folder + "/none_par.txt", "file not found" });
  }
  // The dataset reader's camera validation (vtkCameraRig::FindInvalidView):
  // what the importer accepts, its reader accepts.
  expectFailure("R not a rotation",
    "1\na.png 100 0 4 0 100 3 0 0 1 2 0 0 0 1 0 0 0 1 0 0 1\n",
    2,
    { "r11..r33", "not a rotation" });
  expectFailure("zero K",
    "1\na.png 0 0 0 0 0 0 0 0 0 1 0 0 0 1 0 0 0 1 0 0 1\n",
    2,
    { "k11..k33", "not an intrinsic matrix" });
  expectFailure("t = 1e308",
    "1\na.png 100 0 4 0 100 3 0 0 1 1 0 0 0 1 0 0 0 1 0 0 1e308\n",
    2,
    { "t1 t2 t3", "below 1e6" });
  expectFailure("identical cameras",
    "2\na.png" + Calibration + "b.png" + Calibration,
    3,
    { "the same camera (K, R and t) as view 0" });
  return lfdtest::Result();
}

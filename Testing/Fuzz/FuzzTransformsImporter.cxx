// libFuzzer target: vtkTransformsImporter on a mutated transforms.json
// (nerfstudio / instant-ngp) whose seed names the images of
// Testing/Fuzz/images. A refused file is fine; a crash, a sanitizer report,
// an uncaught exception or a hang is a finding.
#include "lfdFuzzing.h"

#include "vtkNew.h"
#include "vtkTransformsImporter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = lfdfuzz::WriteInput(data, size, "transforms.json");
  vtkNew<vtkTransformsImporter> importer;
  importer->SetFileName(path.c_str());
  importer->Update();
  return 0;
}

// libFuzzer target: vtkMiddleburyImporter on a mutated par file whose seed
// names the images of Testing/Fuzz/images. Par files are not JSON: the
// mutator hands them to libFuzzer's byte mutator. A refused file is fine; a
// crash, a sanitizer report, an uncaught exception or a hang is a finding.
#include "lfdFuzzing.h"

#include "vtkMiddleburyImporter.h"
#include "vtkNew.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = lfdfuzz::WriteInput(data, size, "fuzz_par.txt");
  vtkNew<vtkMiddleburyImporter> importer;
  importer->SetFileName(path.c_str());
  importer->Update();
  return 0;
}

// libFuzzer target: vtkLightFieldReader on a mutated lightfield.json whose
// seed names the images of Testing/Fuzz/images. A refused file is fine; a
// crash, a sanitizer report, an uncaught exception or a hang is a finding.
#include "lfdFuzzing.h"

#include "vtkLightFieldReader.h"
#include "vtkNew.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = lfdfuzz::WriteInput(data, size, "lightfield.json");
  vtkNew<vtkLightFieldReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return 0;
}

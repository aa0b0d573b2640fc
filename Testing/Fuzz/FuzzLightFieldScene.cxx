// libFuzzer target: vtkLightFieldScene::Read on a mutated scene.json. A
// refused file is fine; a crash, a sanitizer report, an uncaught exception
// or a hang is a finding.
#include "lfdFuzzing.h"

#include "vtkLightFieldScene.h"
#include "vtkNew.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = lfdfuzz::WriteInput(data, size, "scene.json");
  vtkNew<vtkLightFieldScene> scene;
  scene->Read(path.c_str());
  return 0;
}

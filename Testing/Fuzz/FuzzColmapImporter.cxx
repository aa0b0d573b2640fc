// libFuzzer target: vtkColmapImporter on a mutated COLMAP sparse model, the
// text model (cameras.txt, images.txt) or, built with
// LFD_FUZZ_COLMAP_BINARY=1 (0 for text), the binary one (cameras.bin, images.bin). One
// input holds both files, cameras first, separated by
// lfdfuzz::FileSeparator; the seeds name the images of Testing/Fuzz/images
// (the binary seed is colmap model_converter's conversion of the text one).
// A refused model is fine; a crash, a sanitizer report, an uncaught
// exception or a hang is a finding.
#include "lfdFuzzing.h"

#include "lfdFileUtilities.h"
#include "vtkColmapImporter.h"
#include "vtkNew.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string extension = LFD_FUZZ_COLMAP_BINARY ? ".bin" : ".txt";
  const std::string model =
    lfdfuzz::WriteInputFiles(data, size, "sparse", { "cameras" + extension, "images" + extension });
  vtkNew<vtkColmapImporter> importer;
  importer->SetFileName(model.c_str());
  importer->SetImageDirectory(lfd::io::ParentFolder(model).c_str());
  importer->Update();
  return 0;
}

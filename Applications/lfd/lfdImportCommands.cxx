// `lfd import colmap|transforms`, `lfd export colmap|transforms` and `lfd scene init`:
// calibrated image sets of other tools in and out, and a first scene for a light field.
#include "lfdCommands.h"

#include "vtkCalibratedImageExporter.h"
#include "vtkCalibratedImageImporter.h"
#include "vtkCameraRig.h"
#include "vtkColmapExporter.h"
#include "vtkColmapImporter.h"
#include "vtkDeformationCage.h"
#include "vtkLightField.h"
#include "vtkLightFieldSceneExporter.h"
#include "vtkLightFieldSceneInitializer.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransformsExporter.h"
#include "vtkTransformsImporter.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace lfd::cli
{
void ImportCalibratedImages(vtkCalibratedImageImporter* importer,
  const std::string& out,
  const std::string& shownAs)
{
  lfd::ShowProgress(importer, "importing");
  Run(importer, "importing " + std::string(importer->GetFileName()));
  WriteLightField(importer->GetOutput(), out);
  vtkCameraRig* rig = importer->GetOutput()->GetRig();
  std::cout << "imported " << rig->GetNumberOfViews() << " views (" << rig->GetNumberOfDuplicates()
            << " near-duplicates) into " << shownAs << "\n";
}

namespace
{
struct ImportOptions
{
  std::string Calibration;
  std::string Images;
  std::string Out;
};

template<typename Importer>
void Import(const ImportOptions& options)
{
  vtkNew<Importer> importer;
  importer->SetFileName(options.Calibration.c_str());
  importer->SetImageDirectory(options.Images.c_str());
  ImportCalibratedImages(importer, options.Out, options.Out);
}

void Export(vtkCalibratedImageExporter* exporter,
  const std::string& lightFieldPath,
  const std::string& out,
  const char* calibration)
{
  auto lightField = ReadLightField(lightFieldPath);
  exporter->SetInputData(lightField);
  exporter->SetDirectoryName(out.c_str());
  lfd::ShowProgress(exporter, "exporting");
  Run(exporter, "exporting to " + out);
  std::cout << "exported " << lightField->GetNumberOfViews() << " views to " << out << " ("
            << calibration << ", images/)\n";
}

struct ParaViewOptions
{
  std::string Scene;
  std::string Out;
  bool NoLightField = false;
  bool NoVtkJs = false;
};

/// `lfd export paraview`: vtkLightFieldSceneExporter on a scene.
void ExportParaView(const ParaViewOptions& options)
{
  auto scene = ReadScene(options.Scene);
  auto lightField = ReadSceneLightField(scene);
  vtkNew<vtkLightFieldSceneExporter> exporter;
  exporter->SetSceneLogic(scene);
  exporter->SetLightField(lightField);
  exporter->SetDirectoryName(options.Out.c_str());
  exporter->SetWriteLightField(!options.NoLightField);
  exporter->SetWriteVtkJs(!options.NoVtkJs);
  if (!exporter->Write())
  {
    Fail(""); // the exporter said why
  }
  std::cout << "exported the scene to " << options.Out << " (rig.vtp"
            << (lightField->GetProjectors() && lightField->GetProjectors()->GetNumberOfViews() > 0
                   ? ", projectors.vtp"
                   : "")
            << (scene->HasCage() ? ", cage.vtu" : "")
            << (options.NoLightField ? "" : ", lightfield.vti")
            << (options.NoVtkJs ? "" : ", vtkjs/") << ")\n";
}

struct SceneInitOptions
{
  std::string LightField;
  std::string Out;
  std::vector<std::string> Boxes;
  double Threshold = 20.0;
  int Resolution = 128;
};

/// The box mode of `--boxes labels|slabs N|one` (and the slab count).
int BoxMode(const std::vector<std::string>& boxes, vtkLightField* lightField, int& slabs)
{
  const std::string usage = "--boxes: expected labels, slabs N or one";
  if (boxes.empty())
  {
    return lightField->GetPass(vtkLightField::LABEL) ? vtkLightFieldSceneInitializer::LABELS
                                                     : vtkLightFieldSceneInitializer::ONE;
  }
  if (boxes[0] == "slabs")
  {
    vtkNew<vtkLightFieldSceneInitializer> limits;
    char* end = nullptr;
    const long count = boxes.size() == 2 ? std::strtol(boxes[1].c_str(), &end, 10) : 0;
    if (boxes.size() != 2 || *end != '\0' || count < limits->GetNumberOfSlabsMinValue() ||
      count > limits->GetNumberOfSlabsMaxValue())
    {
      Fail("--boxes slabs N: N is an integer from " +
        std::to_string(limits->GetNumberOfSlabsMinValue()) + " to " +
        std::to_string(limits->GetNumberOfSlabsMaxValue()));
    }
    slabs = static_cast<int>(count);
    return vtkLightFieldSceneInitializer::SLABS;
  }
  if (boxes.size() != 1 || (boxes[0] != "labels" && boxes[0] != "one"))
  {
    Fail(usage);
  }
  return boxes[0] == "labels" ? vtkLightFieldSceneInitializer::LABELS
                              : vtkLightFieldSceneInitializer::ONE;
}

void InitScene(const SceneInitOptions& options)
{
  auto lightField = ReadLightField(options.LightField);
  vtkNew<vtkLightFieldSceneInitializer> initializer;
  int slabs = initializer->GetNumberOfSlabs();
  initializer->SetBoxMode(BoxMode(options.Boxes, lightField, slabs));
  initializer->SetNumberOfSlabs(slabs);
  initializer->SetThreshold(options.Threshold);
  initializer->SetResolution(options.Resolution);
  auto logic = vtkSmartPointer<vtkLightFieldSceneLogic>::New();
  logic->NewScene();
  // The scene names its light field relative to its own folder.
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(fs::path(options.Out)).parent_path();
  const fs::path relative =
    fs::absolute(fs::path(lfd::io::TrimSeparators(options.LightField))).lexically_relative(folder);
  logic->GetScene()->SetLightFieldPath(relative.string().c_str());
  logic->SetLightField(lightField);
  if (!initializer->Initialize(logic))
  {
    Fail(""); // the initializer or the logic said why
  }
  WriteScene(logic->GetScene(), options.Out);
  vtkDeformationCage* cage = logic->GetCage();
  std::set<int> labels;
  for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
  {
    labels.insert(cage->GetBoxLabel(box));
  }
  std::string labelList;
  for (int label : labels)
  {
    labelList += (labelList.empty() ? "" : " ") + std::to_string(label);
  }
  std::cout << "wrote " << options.Out << ": " << cage->GetNumberOfBoxes() << " boxes (labels "
            << labelList << "), camera framing the object from view 0, "
            << logic->GetScene()->GetWidth() << "x" << logic->GetScene()->GetHeight() << "\n";
}

void AddImportCommand(CLI::App* import,
  const std::string& name,
  const std::string& help,
  const std::string& calibrationHelp,
  const std::string& imagesHelp,
  std::function<void(const ImportOptions&)> run,
  std::vector<Command>& commands)
{
  auto options = std::make_shared<ImportOptions>();
  auto* command = import->add_subcommand(name, help);
  command->add_option("CALIBRATION", options->Calibration, calibrationHelp)->required();
  command->add_option("--images", options->Images, imagesHelp);
  command->add_option("--out", options->Out, "output light-field directory")->required();
  commands.push_back({ command, [options, run] { run(*options); }, false });
}

CLI::App* AddExportCommand(CLI::App* exportCommand,
  const std::string& name,
  const std::string& help,
  std::function<void(const std::string&, const std::string&)> run,
  std::vector<Command>& commands)
{
  auto lightField = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto* command = exportCommand->add_subcommand(name, help);
  command->add_option("LF", *lightField, "light-field directory")->required();
  command->add_option("--out", *out, "output folder")->required();
  commands.push_back({ command, [lightField, out, run] { run(*lightField, *out); }, false });
  return command;
}
}

void AddImportCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  CLI::App* import = app.get_subcommand("import");
  AddImportCommand(import,
    "colmap",
    "COLMAP sparse model, binary (cameras.bin, images.bin, as colmap mapper writes it) or text "
    "(cameras.txt, images.txt), camera models SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, "
    "OPENCV, FULL_OPENCV without rational terms, and its images into the dataset folder OUT "
    "(replaced when complete); views sorted by image name",
    "the sparse model folder (e.g. sparse/0; the binary model when it holds cameras.bin, else the "
    "text model)",
    "folder of the images named in images.txt (COLMAP's --image_path; default: the model folder)",
    Import<vtkColmapImporter>,
    commands);
  AddImportCommand(import,
    "transforms",
    "nerfstudio / instant-ngp transforms.json (fl_x fl_y cx cy w h, k1 k2 p1 p2 k3, per-frame "
    "intrinsics, OpenGL camera-to-world transform_matrix) and its images into the dataset folder "
    "OUT (replaced when complete)",
    "the transforms.json file",
    "folder the frames' file_path is relative to (default: the folder of transforms.json)",
    Import<vtkTransformsImporter>,
    commands);

  auto* exportCommand = app.add_subcommand("export",
    "export a light field's views and cameras (colmap, transforms) or a scene (paraview) for other "
    "tools");
  exportCommand->require_subcommand(1);
  auto binary = std::make_shared<bool>(false);
  AddExportCommand(
    exportCommand,
    "colmap",
    "write OUT/images/*.png and the COLMAP sparse model OUT/sparse/{cameras,images,points3D}.txt, "
    "or .bin with --binary (replaces OUT when complete: OUT must be empty or an earlier export "
    "of the same kind)",
    [binary](const std::string& lightField, const std::string& out)
    {
      vtkNew<vtkColmapExporter> exporter;
      exporter->SetBinary(*binary);
      Export(exporter,
        lightField,
        out,
        *binary ? "sparse/cameras.bin, sparse/images.bin"
                : "sparse/cameras.txt, sparse/images.txt");
    },
    commands)
    ->add_flag("--binary",
      *binary,
      "write COLMAP's binary model (cameras.bin, images.bin, points3D.bin) instead of the text "
      "one");
  AddExportCommand(
    exportCommand,
    "transforms",
    "write OUT/images/*.png and OUT/transforms.json (nerfstudio / instant-ngp, OPENCV camera "
    "model; replaces OUT when complete: OUT must be empty or an earlier export)",
    [](const std::string& lightField, const std::string& out)
    {
      vtkNew<vtkTransformsExporter> exporter;
      Export(exporter, lightField, out, "transforms.json");
    },
    commands);
  auto paraview = std::make_shared<ParaViewOptions>();
  auto* paraviewCommand = exportCommand->add_subcommand("paraview",
    "write a scene for ParaView and vtk.js into OUT: rig.vtp (camera frusta, cell arrays View "
    "and Row), projectors.vtp, cage.vtu (the current cage: RestPosition, Label), lightfield.vti "
    "(W x H x views, one array per pass) and vtkjs/ (rig and cage for vtk.js); the cage over "
    "time: lfd animate --paraview. Replaces OUT when complete (OUT must be empty or an earlier "
    "export)");
  paraviewCommand->add_option("SCENE", paraview->Scene, "scene.json")->required();
  paraviewCommand->add_option("--out", paraview->Out, "output folder")->required();
  paraviewCommand->add_flag(
    "--no-lightfield", paraview->NoLightField, "leave out lightfield.vti (the largest file)");
  paraviewCommand->add_flag("--no-vtkjs", paraview->NoVtkJs, "leave out the vtk.js scene");
  commands.push_back({ paraviewCommand, [paraview] { ExportParaView(*paraview); }, false });

  auto* scene = app.add_subcommand("scene", "author scenes");
  scene->require_subcommand(1);
  auto init = std::make_shared<SceneInitOptions>();
  auto* initCommand = scene->add_subcommand("init",
    "write a scene.json for a light field: a camera at view 0 framing the object's visual hull, "
    "the rig's image size, and a cage around the hull (replaced when complete)");
  initCommand->add_option("LF", init->LightField, "light-field directory")->required();
  initCommand->add_option("--out", init->Out, "output scene.json")->required();
  initCommand
    ->add_option("--boxes",
      init->Boxes,
      "labels: one box per label of the Label pass (slabs along the object's long side, each "
      "bounding its part's voxels of the hull); slabs N: N boxes of label 1 along the ring axis; "
      "one: one box of label 1 (default: labels when the light field has a Label pass, else one)")
    ->type_name("labels|slabs N|one")
    ->expected(1, 2);
  vtkNew<vtkLightFieldSceneInitializer> limits;
  numbers.Add(initCommand,
    "--threshold",
    init->Threshold,
    limits->GetThresholdMinValue(),
    limits->GetThresholdMaxValue(),
    "silhouette threshold on the Coaxial pass (mean of RGB) for the visual hull");
  numbers.Add(initCommand,
    "--resolution",
    init->Resolution,
    limits->GetResolutionMinValue(),
    limits->GetResolutionMaxValue(),
    "voxels of the visual hull along its longest side");
  commands.push_back({ initCommand, [init] { InitScene(*init); }, false });
}
}

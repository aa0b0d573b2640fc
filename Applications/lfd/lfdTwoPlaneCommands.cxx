// `lfd import twoplane`: a folder of images named by grid row and column (a
// two-plane light field, e.g. the Stanford archive's) into a light field.
#include "lfdCommands.h"

#include "vtkNew.h"
#include "vtkTwoPlaneImporter.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace lfd::cli
{
void AddTwoPlaneCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  struct TwoPlaneOptions
  {
    std::string Folder;
    std::string Out;
    double Spacing = 1.0;
    double FocalLength = 0.0;
    std::string Positions;
  };
  auto options = std::make_shared<TwoPlaneOptions>();
  vtkNew<vtkTwoPlaneImporter> limits;
  auto* command = app.get_subcommand("import")->add_subcommand("twoplane",
    "two-plane light field (Levoy and Hanrahan 1996): a folder of images named by grid row and "
    "column (the first two whole-number fields of the name split at '_': the Stanford archive's "
    "out_RR_CC_*.png, RR_CC.png) into the dataset folder OUT (replaced when complete); camera "
    "(r, c) at (c, r, 0) x SPACING, or at the position --positions gives its image, looking along "
    "+Z, R = I, principal point at the image centre");
  command->add_option("FOLDER", options->Folder, "the folder of images")->required();
  command->add_option("--out", options->Out, "output light-field directory")->required();
  numbers.Add(command,
    "--spacing",
    options->Spacing,
    limits->GetSpacingMinValue(),
    limits->GetSpacingMaxValue(),
    "distance between neighbouring camera positions, world units");
  command->add_option("--positions",
    options->Positions,
    "per-image camera positions instead of --spacing: a text file of lines 'NAME X Y' (the "
    "image's file name, its camera centre on the camera plane, world units; '#' starts a "
    "comment line), one for every image");
  numbers
    .Add(command,
      "--focal-length",
      options->FocalLength,
      1e-9,
      limits->GetFocalLengthMaxValue(),
      "focal length of every view, pixels")
    ->required()
    ->default_str("");
  commands.push_back({ command,
    [options]
    {
      vtkNew<vtkTwoPlaneImporter> importer;
      importer->SetFileName(options->Folder.c_str());
      importer->SetSpacing(options->Spacing);
      importer->SetFocalLength(options->FocalLength);
      importer->SetPositionsFile(options->Positions.empty() ? nullptr : options->Positions.c_str());
      ImportCalibratedImages(importer, options->Out, options->Out);
    },
    false });
}
}

// `lfd eval groundtruth` and `lfd eval loo`: rendering quality.
#include "lfdCommands.h"

#include "vtkDeformationCage.h"
#include "vtkGroundTruthEvaluator.h"
#include "vtkImageData.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
void EvalGroundTruth(const std::string& scenePath,
  const std::string& meshName,
  const std::string& out,
  const double* time,
  const RenderOverrides& overrides)
{
  auto scene = ReadScene(scenePath);
  ApplyRenderOverrides(overrides, scene);
  auto lightField = ReadSceneLightField(scene);
  auto cage = SceneCage(scene, lightField, time);
  vtkSmartPointer<vtkImageData> texture;
  auto mesh = SourceMesh(meshName, texture);
  if (cage)
  {
    // The light field's parts are its scene's boxes: so are the ground truth's.
    mesh = LabelByScene(mesh, scene);
  }
  vtkNew<vtkGroundTruthEvaluator> evaluator;
  evaluator->SetInputData(lightField);
  evaluator->SetMeshData(mesh);
  evaluator->SetCageData(cage);
  evaluator->SetTextureData(texture);
  scene->ApplyView(evaluator);
  Run(evaluator.Get(), "ground-truth evaluation");
  std::printf("PSNR (object)     %.2f dB\n", evaluator->GetPSNR());
  std::printf("SSIM (object)     %.4f\n", evaluator->GetSSIM());
  std::printf("silhouette IoU    %.4f\n", evaluator->GetIoU());
  std::printf("label agreement   %.4f\n", evaluator->GetLabelAgreement());
  std::printf("object pixels     %lld\n", static_cast<long long>(evaluator->GetObjectPixels()));
  if (!out.empty())
  {
    // Both images or neither: each is written under a temporary name first
    // (a message names the target, lfd::io::NameTargets()).
    const std::string names[2] = { out + "_lightfield.png", out + "_groundtruth.png" };
    std::string temporaries[2];
    for (int i = 0; i < 2; ++i)
    {
      temporaries[i] = lfd::io::TemporaryFileName(names[i]);
    }
    try
    {
      WriteImage(evaluator->GetOutput(0), temporaries[0]);
      WriteImage(evaluator->GetOutput(1), temporaries[1]);
    }
    catch (const Failure&)
    {
      lfd::io::RemoveQuietly(temporaries[0]);
      lfd::io::RemoveQuietly(temporaries[1]);
      throw;
    }
    for (int i = 0; i < 2; ++i)
    {
      std::string error;
      if (!lfd::io::CommitFile(temporaries[i], names[i], error))
      {
        lfd::io::RemoveQuietly(temporaries[1]);
        Fail(error);
      }
    }
  }
}

void EvalLeaveOneOut(const std::string& path,
  int stride,
  const std::vector<int>& views,
  double focalDistance,
  const std::string& focal,
  int threshold)
{
  auto lightField = ReadLightField(path);
  vtkNew<vtkLeaveOneOutEvaluator> evaluator;
  evaluator->SetInputData(lightField);
  evaluator->SetStride(stride);
  for (int v : views)
  {
    evaluator->AddView(v);
  }
  evaluator->SetFocalDistance(focalDistance);
  evaluator->SetFocalSurface(FocalSurfaceFromName(focal));
  evaluator->SetObjectThreshold(threshold);
  lfd::ShowProgress(evaluator, "evaluating");
  Run(evaluator.Get(), "leave-one-out evaluation");
  vtkTable* table = evaluator->GetOutput();
  std::printf("%6s %10s %12s %12s\n", "view", "PSNR", "object PSNR", "object px");
  for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row)
  {
    std::printf("%6d %10.2f %12.2f %12d\n",
      table->GetValue(row, 0).ToInt(),
      table->GetValue(row, 1).ToDouble(),
      table->GetValue(row, 2).ToDouble(),
      table->GetValue(row, 3).ToInt());
  }
  std::printf("mean   %10.2f %12.2f   (%lld views, dB)\n",
    evaluator->GetMeanPSNR(),
    evaluator->GetMeanObjectPSNR(),
    static_cast<long long>(table->GetNumberOfRows()));
}

}

void AddEvalCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto* evalCommand = app.add_subcommand("eval", "measure rendering quality");
  evalCommand->require_subcommand(1);

  struct GroundTruthOptions
  {
    std::string Scene;
    std::string Mesh;
    std::string Out;
    double Time = 0.0;
    RenderOverrides Overrides;
  };
  auto gt = std::make_shared<GroundTruthOptions>();
  auto* groundTruth = evalCommand->add_subcommand("groundtruth",
    "render the source mesh, labelled by the scene's rest boxes and deformed by its cage, and "
    "compare it with the deformed light field: PSNR and SSIM over the object pixels, "
    "silhouette IoU, label agreement (prints; writes images only with --out); needs an X "
    "display (xvfb-run -a)");
  groundTruth->add_option("SCENE", gt->Scene, "scene.json")->required();
  groundTruth
    ->add_option(
      "--mesh", gt->Mesh, "the light field's source: fish, figure, checkerboard or a mesh file")
    ->required();
  groundTruth->add_option("--out",
    gt->Out,
    "also write OUT_lightfield.png and OUT_groundtruth.png (both or neither, replaced when "
    "complete)");
  auto* gtTimeOption = numbers.AddReal(groundTruth,
    "--time",
    gt->Time,
    "time of the keyframes to evaluate (default: the cage's points)");
  AddRenderOverrideOptions(groundTruth, gt->Overrides);
  commands.push_back({ groundTruth,
    [gt, gtTimeOption]
    {
      EvalGroundTruth(
        gt->Scene, gt->Mesh, gt->Out, *gtTimeOption ? &gt->Time : nullptr, gt->Overrides);
    },
    true });

  struct LeaveOneOutOptions
  {
    std::string Path;
    int Stride = 1;
    std::vector<int> Views;
    double FocalDistance = 0.0;
    std::string Focal;
    int Threshold = 20;
  };
  auto loo = std::make_shared<LeaveOneOutOptions>();
  vtkNew<vtkLeaveOneOutEvaluator> looLimits;
  auto* looCommand = evalCommand->add_subcommand("loo",
    "leave-one-out: render each chosen view from all the others, print PSNR per view and mean "
    "(writes nothing)");
  looCommand->add_option("DIR", loo->Path, "light-field directory")->required();
  numbers.Add(looCommand,
    "--stride",
    loo->Stride,
    looLimits->GetStrideMinValue(),
    looLimits->GetStrideMaxValue(),
    "evaluate every N-th view");
  numbers
    .Add(looCommand,
      "--views",
      loo->Views,
      0,
      VTK_INT_MAX,
      "evaluate these views (overrides --stride)")
    ->delimiter(',');
  numbers.AddReal(looCommand, "--focal-distance", loo->FocalDistance, "focal distance d");
  AddFocalOption(looCommand, loo->Focal, "auto");
  numbers.Add(looCommand,
    "--threshold",
    loo->Threshold,
    looLimits->GetObjectThresholdMinValue(),
    looLimits->GetObjectThresholdMaxValue(),
    "object pixel threshold for light fields without labels");
  commands.push_back({ looCommand,
    [loo]
    {
      EvalLeaveOneOut(
        loo->Path, loo->Stride, loo->Views, loo->FocalDistance, loo->Focal, loo->Threshold);
    },
    false });
}
}

// `lfd split projector|scanline|propagate|check`: light fields into parts;
// `lfd proxy`: their geometric proxy (a Depth pass).
#include "lfdCommands.h"

#include "vtkBoxCoverageCheck.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkLabelAccuracy.h"
#include "vtkLabelPropagation.h"
#include "vtkLightField.h"
#include "vtkLightFieldProxy.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProjectorSegmentation.h"
#include "vtkScanlineSplit.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lfd::cli
{
namespace
{
struct SplitOptions
{
  std::string In;
  std::string Out;
  std::string Truth;
  std::vector<int> Rows;
  std::vector<int> Labels;
  std::vector<std::string> Paint;
  std::string Proxy = "auto";
  int Resolution = 128;
  double Tolerance = 1.5;
  double Threshold = -1.0;
  int Morphology = 1;
  bool NoCompletion = false;
  double ObjectThreshold = 20.0;
  std::string Scene;
};

/**
 * Prints the accuracy of `split`'s labels against the Label pass of the
 * light field `truthPath` on the truth's object pixels, and the confusion
 * per label.
 */
void ReportAccuracy(vtkLightField* split, const std::string& truthPath)
{
  auto truth = ReadLightField(truthPath);
  vtkNew<vtkLabelAccuracy> accuracy;
  const std::string refusal = accuracy->Compute(split, truth);
  if (!refusal.empty())
  {
    Fail(truthPath + ": " + refusal);
  }
  std::printf("accuracy on object pixels: %.2f %% (%lld of %lld)\n",
    accuracy->GetAccuracy(),
    static_cast<long long>(accuracy->GetCorrectPixels()),
    static_cast<long long>(accuracy->GetObjectPixels()));
  std::printf("confusion (rows: truth, columns: split; column 0 = unlabelled)\n");
  for (int e = 1; e <= accuracy->GetMaximumLabel(); ++e)
  {
    std::printf("  %3d:", e);
    for (int f = 0; f <= accuracy->GetMaximumLabel(); ++f)
    {
      std::printf(" %9lld", static_cast<long long>(accuracy->GetConfusion(e, f)));
    }
    std::printf("\n");
  }
}

/// Runs a splitter on `input` (its error is said once, here, after the
/// input's name), prints the figures and writes the split light field.
void RunSplit(vtkLightFieldSplitter* splitter, vtkLightField* input, const SplitOptions& options)
{
  splitter->SetInputData(input);
  lfd::ShowProgress(splitter, "splitting");
  StepErrors errors;
  errors->Observe(splitter);
  splitter->Update();
  errors.FailOnError(options.In + ": ");
  auto* label =
    vtkUnsignedCharArray::SafeDownCast(splitter->GetOutput()->GetPass(vtkLightField::LABEL));
  vtkIdType labelled = 0;
  for (vtkIdType i = 0; i < label->GetNumberOfTuples(); ++i)
  {
    labelled += label->GetValue(i) ? 1 : 0;
  }
  std::printf("labelled pixels: %lld of %lld\n",
    static_cast<long long>(labelled),
    static_cast<long long>(label->GetNumberOfTuples()));
  if (!options.Truth.empty())
  {
    ReportAccuracy(splitter->GetOutput(), options.Truth);
  }
  WriteLightField(splitter->GetOutput(), options.Out);
  std::printf("wrote %s\n", options.Out.c_str());
}

void SplitProjector(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkProjectorSegmentation> segmentation;
  segmentation->SetMorphologyRadius(options.Morphology);
  if (options.Threshold >= 0.0)
  {
    segmentation->SetDarkThreshold(options.Threshold);
  }
  segmentation->SetCompleteLabels(!options.NoCompletion);
  segmentation->SetObjectThreshold(options.ObjectThreshold);
  RunSplit(segmentation, lightField, options);
  std::printf("sensor noise sigma: %.2f\n", segmentation->GetEstimatedNoise());
  if (!options.NoCompletion)
  {
    std::printf("completed pixels (no projector decided them): %lld, through the %s\n",
      static_cast<long long>(segmentation->GetNumberOfCompletedPixels()),
      lightField->GetPass(vtkLightField::DEPTH) ? "Depth pass" : "visual hull");
  }
}

void SplitScanline(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkScanlineSplit> split;
  for (int row : options.Rows)
  {
    split->AddBoundary(row);
  }
  if (!options.Labels.empty() && options.Labels.size() != options.Rows.size() + 1)
  {
    Fail("--labels: " + std::to_string(options.Rows.size()) + " rows make " +
      std::to_string(options.Rows.size() + 1) + " bands, " + std::to_string(options.Labels.size()) +
      " labels given");
  }
  for (size_t band = 0; band < options.Labels.size(); ++band)
  {
    split->SetBandLabel(static_cast<int>(band), options.Labels[band]);
  }
  if (options.Threshold >= 0.0)
  {
    split->SetThreshold(options.Threshold);
  }
  split->SetMorphologyRadius(options.Morphology);
  RunSplit(split, lightField, options);
}

void SplitPropagate(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkLabelPropagation> propagation;
  for (const std::string& paint : options.Paint)
  {
    const size_t equals = paint.find('=');
    char* end = nullptr;
    const long view = equals == std::string::npos ? -1 : std::strtol(paint.c_str(), &end, 10);
    if (equals == std::string::npos || end != paint.c_str() + equals || view < 0)
    {
      Fail("--paint '" + paint + "': expected VIEW=LABELS.png, e.g. 0=paint/view0.png");
    }
    const std::string file = paint.substr(equals + 1);
    vtkSmartPointer<vtkImageData> image = ReadImage(file);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    if (scalars && scalars->GetNumberOfComponents() > 1)
    {
      Fail(file + ": a label image has one channel (label values), this one has " +
        std::to_string(scalars->GetNumberOfComponents()));
    }
    propagation->SetPaintedView(static_cast<int>(view), image);
  }
  propagation->SetProxy(options.Proxy == "depth" ? vtkLabelPropagation::DEPTH
      : options.Proxy == "hull"                  ? vtkLabelPropagation::VISUAL_HULL
                                                 : vtkLabelPropagation::AUTOMATIC);
  propagation->SetResolution(options.Resolution);
  propagation->SetSilhouetteTolerance(options.Tolerance);
  if (options.Threshold >= 0.0)
  {
    propagation->SetThreshold(options.Threshold);
  }
  RunSplit(propagation, lightField, options);
  std::printf(
    "proxy voxels: %lld\n", static_cast<long long>(propagation->GetNumberOfProxyVoxels()));
}

void SplitCheck(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  auto scene = ReadScene(options.Scene);
  if (!scene->HasCage())
  {
    Fail(options.Scene + ": the scene has no cage to check");
  }
  if (!lightField->GetPass(vtkLightField::LABEL))
  {
    Fail(options.In +
      ": has no Label pass to check; split it first (lfd split projector|scanline|propagate)");
  }
  vtkNew<vtkBoxCoverageCheck> check;
  check->SetInputData(0, lightField);
  check->SetCageData(scene->GetCage());
  check->SetThreshold(options.Threshold >= 0.0 ? options.Threshold : 0.95);
  Run(check.Get(), "box coverage check");
  // Every box's label must have pixels and every label value a box: a
  // mismatch (a scene written for another split) is warned about per label.
  const std::vector<int> unboxed = check->GetLabelsWithoutBox();
  const std::vector<int> empty = check->GetBoxLabelsWithoutPixels();
  std::vector<std::pair<int, bool>> mismatches; // (label, it is a box's), by label
  for (int label : unboxed)
  {
    mismatches.emplace_back(label, false);
  }
  for (int label : empty)
  {
    mismatches.emplace_back(label, true);
  }
  std::sort(mismatches.begin(), mismatches.end());
  for (const auto& [label, boxed] : mismatches)
  {
    lfd::PrintWarning(boxed
        ? options.Scene + ": box label " + std::to_string(label) + " has no pixels in " + options.In
        : options.In + ": label " + std::to_string(label) + " has no box in " + options.Scene);
  }
  if (!mismatches.empty())
  {
    Fail("the labels of " + options.Scene + " and " + options.In +
      " do not match (see the warnings); split again or fix the boxes' labels");
  }
  std::printf("label  worst fraction  worst view  views below %.3f\n", check->GetThreshold());
  for (int i = 0; i < check->GetNumberOfLabels(); ++i)
  {
    const std::vector<int> below = check->GetViewsBelow(i);
    std::string list;
    for (size_t k = 0; k < below.size() && k < 10; ++k)
    {
      list += (k ? "," : " (") + std::to_string(below[k]);
    }
    list += below.empty() ? "" : (below.size() > 10 ? ",...)" : ")");
    std::printf("%5d  %14.4f  %10d  %zu%s\n",
      check->GetLabel(i),
      check->GetWorstFraction(i),
      check->GetWorstView(i),
      below.size(),
      list.c_str());
  }
  if (!check->GetPassed())
  {
    Fail("some labels fall outside their boxes (fraction under " +
      std::to_string(check->GetThreshold()) + "); grow the boxes or fix the labels");
  }
  std::printf("every label is inside its boxes\n");
}

}

struct ProxyOptions
{
  std::string In;
  std::string Out;
  bool Replace = false;
  int Resolution = 128;
  double Threshold = 20.0;
  double Tolerance = 1.5;
  int Steps = 24;
  double Depth = 0.1;
};

/// `lfd proxy`: the Depth pass the renderer's proxy focal surface uses.
void Proxy(const ProxyOptions& options)
{
  auto lightField = ReadLightField(options.In);
  const bool recorded = lightField->GetPass(vtkLightField::DEPTH) != nullptr;
  vtkNew<vtkLightFieldProxy> proxy;
  proxy->SetInputData(lightField);
  proxy->SetReplaceDepth(options.Replace);
  proxy->SetResolution(options.Resolution);
  proxy->SetThreshold(options.Threshold);
  proxy->SetSilhouetteTolerance(options.Tolerance);
  proxy->SetSweepSteps(options.Steps);
  proxy->SetSweepDepth(options.Depth);
  lfd::ShowProgress(proxy, "proxy");
  StepErrors errors;
  errors->Observe(proxy);
  proxy->Update();
  errors.FailOnError(options.In + ": ");
  WriteLightField(proxy->GetOutput(), options.Out);
  std::printf("wrote %s (depth: %s)\n",
    options.Out.c_str(),
    recorded && !options.Replace ? "the recorded Depth pass" : "estimated");
}

void AddProxyCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto proxy = std::make_shared<ProxyOptions>();
  vtkNew<vtkLightFieldProxy> limits;
  auto* command = app.add_subcommand("proxy",
    "compute a light field's geometric proxy once: a Depth pass per view (the visual hull of "
    "the silhouettes refined by a plane sweep), which `lfd render` focuses rays on "
    "(render.focal); writes the dataset folder OUT (IN + depth, replaced when complete); a "
    "recorded Depth pass (synthetic captures) is kept unless --replace");
  command->add_option("IN", proxy->In, "light-field directory")->required();
  command->add_option("--out", proxy->Out, "output light-field directory (IN + depth)")->required();
  command->add_flag("--replace", proxy->Replace, "estimate even when IN has a Depth pass");
  numbers.Add(command,
    "--resolution",
    proxy->Resolution,
    limits->GetResolutionMinValue(),
    limits->GetResolutionMaxValue(),
    "visual hull voxels along its longest side");
  numbers.Add(command,
    "--threshold",
    proxy->Threshold,
    limits->GetThresholdMinValue(),
    limits->GetThresholdMaxValue(),
    "silhouette brightness threshold (mean of RGB)");
  numbers.Add(command,
    "--tolerance",
    proxy->Tolerance,
    limits->GetSilhouetteToleranceMinValue(),
    limits->GetSilhouetteToleranceMaxValue(),
    "pixels of silhouette or calibration error the visual hull tolerates");
  numbers.Add(command,
    "--sweep-steps",
    proxy->Steps,
    limits->GetSweepStepsMinValue(),
    limits->GetSweepStepsMaxValue(),
    "depths tried per pixel behind the hull (1 = the hull alone)");
  numbers.Add(command,
    "--sweep-depth",
    proxy->Depth,
    limits->GetSweepDepthMinValue(),
    limits->GetSweepDepthMaxValue(),
    "how far behind the hull the sweep reaches, as a fraction of the hull's diagonal");
  commands.push_back({ command, [proxy] { Proxy(*proxy); }, false });
}

void AddSplitCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  AddProxyCommand(app, numbers, commands);
  auto split = std::make_shared<SplitOptions>();
  vtkNew<vtkProjectorSegmentation> projectorLimits;
  vtkNew<vtkScanlineSplit> scanlineLimits;
  vtkNew<vtkLabelPropagation> propagationLimits;
  vtkNew<vtkBoxCoverageCheck> checkLimits;
  auto* splitCommand = app.add_subcommand("split",
    "split a light field into parts: label its rays (projector masks, image rows, or labels "
    "painted in a few views) into the dataset folder OUT (IN + Label, replaced when complete), "
    "or check the boxes against the labels");
  splitCommand->require_subcommand(1);
  auto addSplitIO = [split](CLI::App* command)
  {
    command->add_option("IN", split->In, "light-field directory")->required();
    command->add_option("--out", split->Out, "output light-field directory (IN + Label)")
      ->required();
    command->add_option("--truth",
      split->Truth,
      "a light field with the true Label pass: print the accuracy and confusion");
  };
  auto* splitProjector = splitCommand->add_subcommand("projector",
    "label by the projector colour masks: Eq. 1 normalisation of Coded by Flood, nearest "
    "palette colour (CIELAB), morphological clean-up, completion of the undecided object "
    "pixels");
  addSplitIO(splitProjector);
  numbers
    .Add(splitProjector,
      "--dark",
      split->Threshold,
      0.0,
      255.0,
      "Flood level below which a channel is dark (default: from the noise)")
    ->default_str("");
  numbers.Add(splitProjector,
    "--morphology",
    split->Morphology,
    projectorLimits->GetMorphologyRadiusMinValue(),
    projectorLimits->GetMorphologyRadiusMaxValue(),
    "clean-up radius in pixels (0 = none)");
  splitProjector->add_flag("--no-completion",
    split->NoCompletion,
    "leave the object pixels no projector decided (unlit, or of no clear palette colour) "
    "unlabelled; by default they take the labels of the decided pixels of every view, carried "
    "through the Depth pass or the visual hull (an unlabelled object pixel renders as "
    "background)");
  numbers.Add(splitProjector,
    "--object-threshold",
    split->ObjectThreshold,
    projectorLimits->GetObjectThresholdMinValue(),
    projectorLimits->GetObjectThresholdMaxValue(),
    "completion through the visual hull: Coaxial level (mean of RGB) above which a pixel is "
    "object");
  auto* splitScanline = splitCommand->add_subcommand("scanline",
    "label by image rows within the object (aligned rings): band 1 above the first row, ...");
  addSplitIO(splitScanline);
  numbers.Add(splitScanline, "--rows", split->Rows, 0, VTK_INT_MAX, "boundary rows, from the top")
    ->delimiter(',')
    ->required();
  numbers
    .Add(splitScanline, "--labels", split->Labels, 1, 255, "label of each band (default 1, 2, ...)")
    ->delimiter(',');
  numbers
    .Add(splitScanline,
      "--threshold",
      split->Threshold,
      scanlineLimits->GetThresholdMinValue(),
      scanlineLimits->GetThresholdMaxValue(),
      "object brightness threshold when IN has no Label pass (default 10)")
    ->default_str("");
  numbers.Add(splitScanline,
    "--morphology",
    split->Morphology,
    scanlineLimits->GetMorphologyRadiusMinValue(),
    scanlineLimits->GetMorphologyRadiusMaxValue(),
    "clean-up radius of the object mask (0 = none: no opening, closing or hole filling)");
  auto* splitPropagate = splitCommand->add_subcommand("propagate",
    "carry labels painted in a few views to every view through the Depth pass or a visual hull");
  addSplitIO(splitPropagate);
  splitPropagate
    ->add_option("--paint", split->Paint, "VIEW=LABELS.png (one channel, 0 = unpainted); repeat")
    ->required();
  splitPropagate->add_option("--proxy", split->Proxy, "auto (depth when present), depth or hull")
    ->check(CLI::IsMember({ "auto", "depth", "hull" }))
    ->capture_default_str();
  numbers.Add(splitPropagate,
    "--resolution",
    split->Resolution,
    propagationLimits->GetResolutionMinValue(),
    propagationLimits->GetResolutionMaxValue(),
    "proxy voxels along its longest side");
  numbers.Add(splitPropagate,
    "--tolerance",
    split->Tolerance,
    propagationLimits->GetSilhouetteToleranceMinValue(),
    propagationLimits->GetSilhouetteToleranceMaxValue(),
    "pixels of silhouette or calibration error the visual hull tolerates");
  numbers
    .Add(splitPropagate,
      "--threshold",
      split->Threshold,
      propagationLimits->GetThresholdMinValue(),
      propagationLimits->GetThresholdMaxValue(),
      "silhouette brightness threshold (default 20)")
    ->default_str("");
  auto* splitCheck = splitCommand->add_subcommand("check",
    "project each rest box into every view and report the fraction of its label's pixels "
    "inside (writes nothing); exits 1 under the threshold, or when a box label has no pixels "
    "or a label no box");
  splitCheck->add_option("IN", split->In, "light-field directory (with a Label pass)")->required();
  splitCheck->add_option("--scene", split->Scene, "scene.json whose cage holds the boxes")
    ->required();
  numbers
    .Add(splitCheck,
      "--threshold",
      split->Threshold,
      checkLimits->GetThresholdMinValue(),
      checkLimits->GetThresholdMaxValue(),
      "smallest acceptable fraction (default 0.95)")
    ->default_str("");
  commands.push_back({ splitProjector, [split] { SplitProjector(*split); }, false });
  commands.push_back({ splitScanline, [split] { SplitScanline(*split); }, false });
  commands.push_back({ splitPropagate, [split] { SplitPropagate(*split); }, false });
  commands.push_back({ splitCheck, [split] { SplitCheck(*split); }, false });
}
}

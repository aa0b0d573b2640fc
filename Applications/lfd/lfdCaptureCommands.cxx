// `lfd synth`, `lfd import` and `lfd info`: light fields in.
#include "lfdCommands.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkLabelPalette.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkMath.h"
#include "vtkMiddleburyImporter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
vtkSmartPointer<vtkPolyData> SourceMesh(const std::string& name,
  vtkSmartPointer<vtkImageData>& texture)
{
  const int object = vtkProceduralObjectSource::GetObjectFromString(name.c_str());
  if (object < 0)
  {
    return ReadMesh(name);
  }
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObject(object);
  source->Update();
  texture = source->GetTextureOutput();
  return source->GetOutput();
}

void WarnIfExtrapolating(vtkLightField* lightField,
  vtkLightFieldSceneLogic* scene,
  vtkDeformationCage* cage)
{
  vtkCameraRig* rig = lightField->GetRig();
  const double* eye = scene->GetScene()->GetCamera()->GetPosition();
  const std::string why =
    cage ? rig->DescribeExtrapolation(eye, cage->GetBounds()) : rig->DescribeExtrapolation(eye);
  if (!why.empty())
  {
    PrintWarning(why);
  }
}

RowCoverage SceneCoverage(vtkLightFieldSceneLogic* scene, vtkDeformationCage* cage)
{
  RowCoverage coverage;
  coverage.Eyes = vtkSmartPointer<vtkPoints>::New();
  const double* eye = scene->GetScene()->GetCamera()->GetPosition();
  coverage.Eyes->InsertNextPoint(eye);
  // The eye as each moved box sees its rest contents, as it stands and at
  // every keyframe: the deformed render looks the light field up from there.
  vtkLightFieldCapture::AppendRestEyes(cage, eye, coverage.Eyes);
  // What the camera looks at besides the mesh: the boxes at rest, as they
  // stand, and at every keyframe.
  coverage.Targets = vtkSmartPointer<vtkPoints>::New();
  for (vtkIdType p = 0; p < cage->GetNumberOfPoints(); ++p)
  {
    double rest[3];
    cage->GetRestPoint(p, rest);
    coverage.Targets->InsertNextPoint(rest);
    coverage.Targets->InsertNextPoint(cage->GetPoint(p));
  }
  for (int k = 0; k < scene->GetScene()->GetNumberOfKeyframes(); ++k)
  {
    vtkPoints* points = scene->GetScene()->GetKeyframePoints(k);
    vtkNew<vtkDeformationCage> posed;
    posed->DeepCopy(cage);
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      coverage.Targets->InsertNextPoint(points->GetPoint(p));
      posed->SetDeformedPoint(p, points->GetPoint(p));
    }
    vtkLightFieldCapture::AppendRestEyes(posed, eye, coverage.Eyes);
  }
  return coverage;
}

namespace
{
/// The painted masks of `projectors` projectors, one RGB image each, stacked
/// into one image of Wp x Hp x projectors (the "Mask" array).
vtkSmartPointer<vtkImageData> ReadProjectorMasks(const std::vector<std::string>& files,
  int projectors)
{
  if (static_cast<int>(files.size()) != projectors)
  {
    Fail("--projector-mask: " + std::to_string(files.size()) + " masks for " +
      std::to_string(projectors) + " projectors (give one per projector)");
  }
  auto masks = vtkSmartPointer<vtkImageData>::New();
  vtkNew<vtkUnsignedCharArray> stack;
  stack->SetName("Mask");
  stack->SetNumberOfComponents(3);
  for (size_t p = 0; p < files.size(); ++p)
  {
    vtkSmartPointer<vtkImageData> image = ReadImage(files[p]);
    vtkDataArray* rgb = image->GetPointData()->GetScalars();
    const int* dims = image->GetDimensions();
    if (!rgb || rgb->GetNumberOfComponents() < 3)
    {
      Fail(files[p] + ": a projector mask is an RGB image");
    }
    if (p == 0)
    {
      masks->SetDimensions(dims[0], dims[1], projectors);
      stack->SetNumberOfTuples(masks->GetNumberOfPoints());
    }
    else if (dims[0] != masks->GetDimensions()[0] || dims[1] != masks->GetDimensions()[1])
    {
      Fail(files[p] + ": is " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + ", " +
        files[0] + " " + std::to_string(masks->GetDimensions()[0]) + "x" +
        std::to_string(masks->GetDimensions()[1]) + " (every projector mask has the same size)");
    }
    const vtkIdType pixels = static_cast<vtkIdType>(dims[0]) * dims[1];
    for (vtkIdType i = 0; i < pixels; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        stack->SetTypedComponent(
          p * pixels + i, c, static_cast<unsigned char>(rgb->GetComponent(i, c)));
      }
    }
  }
  masks->GetPointData()->SetScalars(stack);
  return masks;
}

}

vtkSmartPointer<vtkLightField> Capture(vtkPolyData* mesh,
  vtkImageData* texture,
  const SynthOptions& options,
  const RowCoverage* coverage)
{
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputData(mesh);
  capture->SetTextureData(texture);
  capture->SetViewsPerRing(options.Views);
  capture->SetNumberOfRows(options.Rows);
  capture->SetRowSpacing(options.RowSpacing);
  capture->SetRowMargin(options.RowMargin);
  vtkNew<vtkDoubleArray> rowHeights;
  for (double h : options.RowHeights)
  {
    rowHeights->InsertNextValue(h);
  }
  capture->SetRowHeights(rowHeights);
  vtkNew<vtkDoubleArray> elevations;
  for (double e : options.Elevations)
  {
    elevations->InsertNextValue(e);
  }
  capture->SetRowElevations(elevations);
  if (coverage)
  {
    capture->SetEyes(coverage->Eyes);
    capture->SetEyeTargets(coverage->Targets);
  }
  capture->SetWidth(options.Width);
  capture->SetHeight(options.Height);
  capture->SetRadius(options.Radius);
  if (options.ViewAngle > 0.0)
  {
    capture->SetViewAngle(options.ViewAngle);
  }
  capture->SetAxis(options.Axis[0], options.Axis[1], options.Axis[2]);
  capture->SetSceneFixedLight(options.SceneFixedLight);
  if (options.Mesh.empty())
  {
    capture->SetObjectName(options.Object.c_str());
  }
  capture->SetCaptureDepth(!options.NoDepth);
  capture->SetSupersample(options.Supersample);
  if (options.Projectors > 0)
  {
    // One palette colour per part of the mesh, as far apart as the camera
    // can tell them; the projectors paint each part with its colour.
    vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
    double range[2] = { 1.0, 1.0 };
    if (labels)
    {
      labels->GetRange(range, 0);
    }
    vtkNew<vtkLabelPalette> chooser;
    chooser->SetNumberOfLabels(std::max(1, static_cast<int>(range[1])));
    vtkNew<vtkUnsignedCharArray> palette;
    if (!chooser->Build(palette))
    {
      Fail("cannot choose " + std::to_string(static_cast<int>(range[1])) + " label colours");
    }
    capture->SetPalette(palette);
    capture->SetNumberOfProjectors(options.Projectors);
    if (!options.ProjectorMasks.empty())
    {
      capture->SetProjectorMasks(ReadProjectorMasks(options.ProjectorMasks, options.Projectors));
      capture->SetProjectorWidth(capture->GetProjectorMasks()->GetDimensions()[0]);
      capture->SetProjectorHeight(capture->GetProjectorMasks()->GetDimensions()[1]);
    }
    capture->SetProjectorNoise(options.ProjectorNoise);
    capture->SetProjectorAmbient(options.ProjectorAmbient);
  }
  lfd::ShowProgress(capture, "capturing");
  Run(capture.Get(), "synthetic capture");
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->ShallowCopy(capture->GetOutput());
  return lightField;
}

vtkSmartPointer<vtkLightField> Synthesize(const SynthOptions& options)
{
  vtkSmartPointer<vtkImageData> texture;
  vtkSmartPointer<vtkPolyData> mesh;
  if (!options.Mesh.empty())
  {
    mesh = ReadMesh(options.Mesh);
    if (!options.Texture.empty())
    {
      texture = ReadImage(options.Texture);
    }
  }
  else
  {
    mesh = SourceMesh(options.Object, texture);
  }
  if (!options.Scene.empty())
  {
    auto scene = ReadScene(options.Scene);
    if (!scene->HasCage())
    {
      Fail("scene '" + options.Scene + "' has no cage: its rest boxes are what label the mesh");
    }
    auto cage = SceneCage(scene, nullptr);
    mesh = LabelByScene(mesh, scene);
    const RowCoverage coverage = SceneCoverage(scene, cage);
    auto lightField = Capture(mesh, texture, options, &coverage);
    WarnIfExtrapolating(lightField, scene, cage);
    return lightField;
  }
  return Capture(mesh, texture, options);
}

namespace
{
void AddSynthOptions(CLI::App* command, SynthOptions& options, NumericOptions& numbers)
{
  vtkNew<vtkLightFieldCapture> limits; // the capture's own ranges
  command->add_option("--object", options.Object, "built-in object")
    ->check(CLI::IsMember({ "fish", "figure", "checkerboard" }))
    ->capture_default_str();
  numbers.Add(command,
    "--views",
    options.Views,
    limits->GetViewsPerRingMinValue(),
    limits->GetViewsPerRingMaxValue(),
    "views per ring");
  numbers.Add(command,
    "--rows",
    options.Rows,
    limits->GetNumberOfRowsMinValue(),
    limits->GetNumberOfRowsMaxValue(),
    "rings (rows) of views");
  numbers.Add(command,
    "--row-spacing",
    options.RowSpacing,
    limits->GetRowSpacingMinValue(),
    limits->GetRowSpacingMaxValue(),
    "distance between neighbouring rows along the axis, in the mesh's units (built-in objects: "
    "metres); 0: 0.05 x the ring radius");
  auto* heights = numbers
                    .AddReal(command,
                      "--row-heights",
                      options.RowHeights,
                      "explicit row heights along the axis relative to the mesh centre, in the "
                      "mesh's units, comma-separated (replaces --rows and --row-spacing)")
                    ->delimiter(',');
  numbers
    .Add(command,
      "--elevations",
      options.Elevations,
      -89.0,
      89.0,
      "explicit row elevations in degrees seen from the mesh centre, comma-separated (replaces "
      "--rows and --row-spacing)")
    ->delimiter(',')
    ->excludes(heights);
  numbers.Add(command,
    "--row-margin",
    options.RowMargin,
    limits->GetRowMarginMinValue(),
    limits->GetRowMarginMaxValue(),
    "with --scene: the rows reach this many ring radii beyond the heights the scene's camera "
    "looks up");
  numbers.Add(command,
    "--width",
    options.Width,
    limits->GetWidthMinValue(),
    limits->GetWidthMaxValue(),
    "image width in pixels");
  numbers.Add(command,
    "--height",
    options.Height,
    limits->GetHeightMinValue(),
    limits->GetHeightMaxValue(),
    "image height in pixels");
  numbers.Add(command,
    "--radius",
    options.Radius,
    limits->GetRadiusMinValue(),
    limits->GetRadiusMaxValue(),
    "ring radius (0: frame the mesh)");
  numbers.Add(command,
    "--view-angle",
    options.ViewAngle,
    0.0,
    limits->GetViewAngleMaxValue(),
    "vertical field of view in degrees (0: frame the mesh)");
  numbers.AddReal(command, "--axis", options.Axis, "rig axis x y z")->expected(3);
  command->add_flag("--scene-fixed-light",
    options.SceneFixedLight,
    "light fixed in the scene instead of travelling with the camera (paper Fig. 5)");
  command->add_flag("--no-depth", options.NoDepth, "skip the Depth pass");
  numbers.Add(command,
    "--supersample",
    options.Supersample,
    limits->GetSupersampleMinValue(),
    limits->GetSupersampleMaxValue(),
    "prefilter the Coaxial pass: render N x N samples per pixel and average them (a box over "
    "the pixel: fine texture and silhouettes anti-aliased); the Label and Depth passes stay "
    "point-sampled (1: point-sample the colour too)");
  numbers.Add(command,
    "--projectors",
    options.Projectors,
    limits->GetNumberOfProjectorsMinValue(),
    limits->GetNumberOfProjectorsMaxValue(),
    "also capture the Coded and Flood passes lit by N projectors on the ring, painting each "
    "part with its palette colour");
  numbers.Add(command,
    "--projector-noise",
    options.ProjectorNoise,
    limits->GetProjectorNoiseMinValue(),
    limits->GetProjectorNoiseMaxValue(),
    "sensor noise sigma of the projector passes (8-bit levels)");
  command->add_option("--projector-mask",
    options.ProjectorMasks,
    "a painted mask (RGB image in the palette's colours, see the palette printed) for each "
    "projector, in order; repeat (default: masks generated from the part labels)");
  numbers.Add(command,
    "--projector-ambient",
    options.ProjectorAmbient,
    limits->GetProjectorAmbientMinValue(),
    limits->GetProjectorAmbientMaxValue(),
    "room light in the projector passes (fraction of the albedo)");
}

void Synth(const SynthOptions& options)
{
  const double start = vtkTimerLog::GetUniversalTime();
  auto lightField = Synthesize(options);
  WriteLightField(lightField, options.Out);
  if (vtkUnsignedCharArray* palette = lightField->GetPalette())
  {
    std::cout << "palette:";
    for (vtkIdType label = 1; label < palette->GetNumberOfTuples(); ++label)
    {
      std::cout << " " << label << "=(" << static_cast<int>(palette->GetTypedComponent(label, 0))
                << "," << static_cast<int>(palette->GetTypedComponent(label, 1)) << ","
                << static_cast<int>(palette->GetTypedComponent(label, 2)) << ")";
    }
    std::cout << "\n";
  }
  vtkCameraRig* rig = lightField->GetRig();
  std::printf("rows:");
  for (int row = 0; row < rig->GetNumberOfRows(); ++row)
  {
    // Heights are fitted: print a rounding residue of 0 as 0.
    const double h = rig->GetRowHeight(row);
    std::printf("%s%.4g", row ? ", " : " ", std::abs(h) < 1e-9 * rig->GetRadius() ? 0.0 : h);
  }
  std::printf(
    " (heights along the axis about the cameras' mean height; radius %.4g)\n", rig->GetRadius());
  std::cout << "wrote " << lightField->GetNumberOfViews() << " views of " << lightField->GetWidth()
            << "x" << lightField->GetHeight() << " to " << options.Out << " in " << Seconds(start)
            << " s\n";
}

}

void ImportMiddlebury(const std::string& par, const std::string& out, const std::string& shownAs)
{
  vtkNew<vtkMiddleburyImporter> importer;
  importer->SetFileName(par.c_str());
  ImportCalibratedImages(importer, out, shownAs);
}

namespace
{
void Info(const std::string& path)
{
  auto lightField = ReadLightField(path);
  vtkCameraRig* rig = lightField->GetRig();
  std::cout << "light field  " << path << "\n";
  std::cout << "views        " << lightField->GetNumberOfViews() << " of " << lightField->GetWidth()
            << " x " << lightField->GetHeight() << " pixels\n";
  std::cout << "passes      ";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (lightField->GetPass(pass))
    {
      std::cout << " " << vtkLightField::GetPassName(pass);
    }
  }
  std::cout << "\n";
  if (vtkUnsignedCharArray* palette = lightField->GetPalette())
  {
    std::cout << "palette      " << palette->GetNumberOfTuples() - 1 << " label colours\n";
  }
  if (vtkCameraRig* projectors = lightField->GetProjectors();
      projectors && projectors->GetNumberOfViews() > 0)
  {
    std::cout << "projectors   " << projectors->GetNumberOfViews() << " of "
              << projectors->GetImageSize()[0] << " x " << projectors->GetImageSize()[1]
              << (lightField->GetProjectorMasks() ? ", with masks" : "") << "\n";
  }
  // The reader fitted the rig; one no cylinder fits is read unfitted.
  if (!rig->HasCylinder())
  {
    Fail("no cylinder can be fitted to the cameras of '" + path + "'");
  }
  const double* axis = rig->GetAxis();
  const double* center = rig->GetCenter();
  std::printf("rig axis     (%.4f, %.4f, %.4f)\n", axis[0], axis[1], axis[2]);
  std::printf("rig centre   (%.4f, %.4f, %.4f)\n", center[0], center[1], center[2]);
  std::printf("rig radius   %.4f (RMS residual %.4f)\n", rig->GetRadius(), rig->GetFitResidual());
  std::printf("rows         %d\n", rig->GetNumberOfRows());
  std::printf("duplicates   %d\n", rig->GetNumberOfDuplicates());
  for (int row = 0; row < rig->GetNumberOfRows(); ++row)
  {
    std::vector<double> azimuths;
    for (int v = 0; v < rig->GetNumberOfViews(); ++v)
    {
      if (rig->GetRow(v) == row && rig->GetDuplicateOf(v) < 0)
      {
        azimuths.push_back(vtkMath::DegreesFromRadians(rig->GetAzimuth(v)));
      }
    }
    std::sort(azimuths.begin(), azimuths.end());
    double gap = 360.0 - azimuths.back() + azimuths.front();
    for (std::size_t i = 1; i < azimuths.size(); ++i)
    {
      gap = std::max(gap, azimuths[i] - azimuths[i - 1]);
    }
    std::printf("row %-8d height %.4f, %zu views, largest azimuth gap %.1f degrees\n",
      row,
      rig->GetRowHeight(row),
      azimuths.size(),
      gap);
  }
}

}

void AddCaptureCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto synth = std::make_shared<SynthOptions>();
  auto* synthCommand = app.add_subcommand("synth",
    "capture a synthetic light field of a mesh or a built-in object into the dataset folder "
    "OUT (replaced when complete); needs an X display (xvfb-run -a)");
  synthCommand->add_option("--mesh", synth->Mesh, "mesh file (.ply .obj .stl .vtp .vtk)");
  synthCommand->add_option("--texture",
    synth->Texture,
    "texture image for a mesh with texture "
    "coordinates");
  synthCommand->add_option("--scene",
    synth->Scene,
    "scene.json whose rest boxes label the mesh (a triangle takes the box holding its centroid); "
    "its boxes are validated as lfd render validates them. Unless --row-heights or --elevations "
    "are given, the --rows rows are spread over the heights the scene's camera looks up when it "
    "views the mesh and the boxes (at rest, deformed and at every keyframe), --row-margin beyond "
    "them, so that lfd render never clamps its rays to the outermost row");
  synthCommand->add_option("--out", synth->Out, "output light-field directory")->required();
  AddSynthOptions(synthCommand, *synth, numbers);
  commands.push_back({ synthCommand, [synth] { Synth(*synth); }, true });

  auto* importCommand = app.add_subcommand("import", "import a calibrated image set");
  importCommand->require_subcommand(1);
  auto par = std::make_shared<std::string>();
  auto importOut = std::make_shared<std::string>();
  auto* middlebury = importCommand->add_subcommand("middlebury",
    "Middlebury multi-view stereo set (*_par.txt: name k11..k33 r11..r33 t1 t2 t3) into the "
    "dataset folder OUT (replaced when complete)");
  middlebury->add_option("PAR_FILE", *par, "the *_par.txt file")->required();
  middlebury->add_option("--out", *importOut, "output light-field directory")->required();
  commands.push_back(
    { middlebury, [par, importOut] { ImportMiddlebury(*par, *importOut, *importOut); }, false });

  auto infoPath = std::make_shared<std::string>();
  auto* infoCommand = app.add_subcommand(
    "info", "describe a light field and fit its rig (prints only, writes nothing)");
  infoCommand->add_option("DIR", *infoPath, "light-field directory")->required();
  commands.push_back({ infoCommand, [infoPath] { Info(*infoPath); }, false });
}
}

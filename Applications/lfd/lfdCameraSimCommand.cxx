// `lfd camera-sim`: the simulated rig camera (vtkSimulatedRigCamera) served
// as a GigE Vision camera until interrupted, for any GigE Vision client.
#include "lfdCommands.h"

#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkPolyData.h"
#include "vtkSimulatedCoaxialLight.h"
#include "vtkSimulatedProjector.h"
#include "vtkSimulatedRigCamera.h"

#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

namespace lfd::cli
{
namespace
{
struct CameraSimOptions
{
  std::string LightField;
  std::string Object = "fish";
  std::string Address = "127.0.0.1";
  std::string Light = "coaxial";
  int HomeView = 0;
  double Angle = 0.0;
  double Noise = 0.0;
  double Seconds = 0.0;
};

volatile std::sig_atomic_t Interrupted = 0;

void Interrupt(int)
{
  Interrupted = 1;
}

void CameraSim(const CameraSimOptions& options)
{
  const int pass = vtkLightField::GetPassFromName(options.Light.c_str());
  if (options.Light != "none" && pass != vtkLightField::COAXIAL && pass != vtkLightField::CODED &&
    pass != vtkLightField::FLOOD)
  {
    Fail("--light '" + options.Light + "': expected coaxial, coded, flood or none");
  }
  vtkSmartPointer<vtkLightField> lightField = ReadLightField(options.LightField);
  vtkCameraRig* rig = lightField->GetRig();
  if (options.HomeView >= rig->GetNumberOfViews())
  {
    Fail("--home-view " + std::to_string(options.HomeView) + ": the light field '" +
      options.LightField + "' has " + std::to_string(rig->GetNumberOfViews()) + " views");
  }
  vtkCameraRig* projectors = lightField->GetProjectors();
  const int projectorCount = projectors ? projectors->GetNumberOfViews() : 0;
  if ((pass == vtkLightField::CODED || pass == vtkLightField::FLOOD) && projectorCount == 0)
  {
    Fail("--light " + options.Light + ": the light field '" + options.LightField +
      "' has no projectors");
  }
  vtkSmartPointer<vtkImageData> texture;
  vtkSmartPointer<vtkPolyData> mesh = SourceMesh(options.Object, texture);

  vtkNew<vtkSimulatedRigCamera> camera;
  camera->SetAddress(options.Address.c_str());
  camera->GetCapture()->SetInputData(mesh);
  if (texture)
  {
    camera->GetCapture()->SetTextureData(texture);
  }
  camera->SetRig(rig);
  camera->SetHomeView(options.HomeView);
  camera->SetProjectors(projectorCount > 0 ? projectors : nullptr);
  camera->SetAngle(options.Angle);
  camera->SetSensorNoise(options.Noise);
  StepErrors errors;
  errors->Observe(camera);
  vtkNew<vtkSimulatedCoaxialLight> lamp;
  lamp->SetCamera(camera);
  errors->Observe(lamp);
  std::vector<vtkSmartPointer<vtkSimulatedProjector>> lights;
  for (int p = 0; p < projectorCount; ++p)
  {
    auto projector = vtkSmartPointer<vtkSimulatedProjector>::New();
    projector->SetCamera(camera);
    projector->SetMasks(lightField->GetProjectorMasks());
    projector->SetProjectorIndex(p);
    errors->Observe(projector);
    lights.push_back(projector);
  }
  if (pass >= 0)
  {
    lamp->Apply(pass);
    for (auto& projector : lights)
    {
      projector->Apply(pass);
    }
  }
  errors.FailOnError();
  if (!camera->Start())
  {
    errors.FailOnError();
  }
  std::cout << "Serving the GigE Vision camera " << camera->GetSerialNumber() << " on "
            << options.Address << " (GVCP port 3956): " << rig->GetImageSize()[0] << " x "
            << rig->GetImageSize()[1] << ", " << options.Object << " at " << options.Angle
            << " degrees, light " << options.Light << "; Ctrl-C stops." << std::endl;
  std::signal(SIGINT, Interrupt);
  std::signal(SIGTERM, Interrupt);
  const auto start = std::chrono::steady_clock::now();
  while (!Interrupted &&
    (options.Seconds <= 0.0 ||
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
        options.Seconds))
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  camera->Stop();
  std::cout << "Stopped after " << camera->GetNumberOfFramesRendered() << " frames." << std::endl;
  errors.FailOnError();
}
}

void AddCameraSimCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto options = std::make_shared<CameraSimOptions>();
  auto* command = app.add_subcommand("camera-sim",
    "serve a simulated rig camera on the network: a GigE Vision camera whose frames are renders "
    "of OBJECT from view HOME of a synthetic light field's rig, turned by ANGLE about the rig's "
    "axis, under LIGHT (vtkSimulatedRigCamera); runs until Ctrl-C; needs an X display");
  command
    ->add_option("--lightfield",
      options->LightField,
      "light field (e.g. written by lfd synth) whose rig, projectors and projector masks are "
      "simulated")
    ->required();
  command
    ->add_option("--object",
      options->Object,
      "built-in object (fish, figure, checkerboard) or mesh file photographed")
    ->capture_default_str();
  command
    ->add_option("--address",
      options->Address,
      "local IPv4 address the camera serves on (its GVCP port 3956 must be free)")
    ->capture_default_str();
  command
    ->add_option("--light",
      options->Light,
      "lights on: coaxial (the lamp), coded (projectors show their masks), flood (projectors "
      "white) or none")
    ->capture_default_str();
  numbers.Add(command,
    "--home-view",
    options->HomeView,
    0,
    VTK_INT_MAX,
    "the light field's view that is the camera at angle 0");
  numbers.Add(command,
    "--angle",
    options->Angle,
    -36000.0,
    36000.0,
    "gantry angle in degrees (right-handed about the rig's axis)");
  numbers.Add(command,
    "--noise",
    options->Noise,
    0.0,
    255.0,
    "standard deviation of the sensor noise in 8-bit levels");
  numbers.Add(command,
    "--seconds",
    options->Seconds,
    0.0,
    1.0e6,
    "stop after this many seconds (0: run until Ctrl-C or SIGTERM)");
  commands.push_back({ command, [options] { CameraSim(*options); }, true });
}
}

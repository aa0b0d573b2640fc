// `lfd capture`: a light field captured by vtkCaptureSession from a gantry
// (Modbus TCP), a GigE Vision camera and the rig's lights, view after view
// into a dataset that survives faults and kill -9 (--resume); with
// --simulate, the gantry simulator and the simulated rig camera are served
// by this process on 127.0.0.1, so the same code runs against real peers.
#include "lfdCommands.h"

#include "vtkAravisCamera.h"
#include "vtkCameraRig.h"
#include "vtkCaptureSession.h"
#include "vtkGantrySimulator.h"
#include "vtkImageData.h"
#include "vtkIncrementalLightFieldWriter.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkModbusGantry.h"
#include "vtkModbusLight.h"
#include "vtkPolyData.h"
#include "vtkProjectorWindow.h"
#include "vtkSimulatedProjector.h"
#include "vtkSimulatedRigCamera.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <sstream>

namespace lfd::cli
{
namespace
{
struct CaptureSessionOptions
{
  std::string Gantry = "127.0.0.1:502";
  std::string GantryConfig;
  std::string Camera = "127.0.0.1";
  std::string Rig;
  std::string Out;
  std::vector<std::string> ProjectorDisplays;
  int Views = 0;
  int Projectors = 0;
  double FirstAngle = 0.0;
  double Velocity = 30.0;
  double Acceleration = 60.0;
  double Exposure = 10000.0;
  double Gain = 0.0;
  bool Resume = false;
  bool Simulate = false;
  std::string Object = "fish";
  double Noise = 0.0;
  int CoaxialCoil = -1;
  std::string CoaxialLamp;
  int CoaxialUnit = 255;
  double CoaxialSettle = -1.0;
};

/// The session Ctrl-C stops (Abort() is async-signal-safe).
vtkCaptureSession* RunningSession = nullptr;

extern "C" void AbortCapture(int)
{
  if (RunningSession)
  {
    RunningSession->Abort();
  }
}

/// "ADDR:PORT" split; fails naming the option.
void SplitAddress(const std::string& option,
  const std::string& text,
  std::string& address,
  int& port)
{
  const size_t colon = text.rfind(':');
  char* end = nullptr;
  const long value =
    colon == std::string::npos ? -1 : std::strtol(text.c_str() + colon + 1, &end, 10);
  if (colon == std::string::npos || colon == 0 || !end || *end != '\0' || value < 0 ||
    value > 65535)
  {
    Fail(option + " '" + text + "': expected ADDRESS:PORT, e.g. 192.168.1.10:502");
  }
  address = text.substr(0, colon);
  port = static_cast<int>(value);
}

/// The plan: every (rig views / --views)-th view of the rig's ring, its
/// first --projectors projectors with their masks; view k is photographed
/// at gantry angle FirstAngle + k * 360 / --views.
vtkSmartPointer<vtkLightField> MakePlan(vtkLightField* rigField, CaptureSessionOptions& options)
{
  vtkCameraRig* ring = rigField->GetRig();
  const int ringViews = ring->GetNumberOfViews();
  options.Views = options.Views > 0 ? options.Views : ringViews;
  if (ringViews % options.Views != 0)
  {
    Fail("--views " + std::to_string(options.Views) + ": the rig of '" + options.Rig + "' has " +
      std::to_string(ringViews) + " views, not a multiple of it");
  }
  const int projectorCount = rigField->GetProjectors()->GetNumberOfViews();
  if (options.Projectors != 0 &&
    (options.Projectors != projectorCount || !rigField->GetProjectorMasks()))
  {
    Fail("--projectors " + std::to_string(options.Projectors) + ": the rig of '" + options.Rig +
      "' has " + std::to_string(projectorCount) + " projectors" +
      (rigField->GetProjectorMasks() ? "" : " and no masks"));
  }
  const int step = ringViews / options.Views;
  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(options.Views);
  rig->SetImageSize(ring->GetImageSize()[0], ring->GetImageSize()[1]);
  for (int k = 0; k < options.Views; ++k)
  {
    rig->SetView(k, ring->GetCamera(k * step));
  }
  auto plan = vtkSmartPointer<vtkLightField>::New();
  plan->SetLayout(ring->GetImageSize()[0], ring->GetImageSize()[1], options.Views);
  plan->SetRig(rig);
  if (options.Projectors > 0)
  {
    plan->SetProjectors(rigField->GetProjectors());
    plan->SetProjectorMasks(rigField->GetProjectorMasks());
  }
  plan->SetPalette(rigField->GetPalette());
  std::ostringstream provenance;
  provenance << "{\"source\": \"lfd capture\", \"rig\": \"" << options.Rig
             << "\", \"first angle\": " << options.FirstAngle
             << ", \"angle step\": " << 360.0 / options.Views << "}";
  plan->SetProvenance(provenance.str().c_str());
  return plan;
}

/// The simulated rig (gantry simulator, GigE camera, projectors) served by
/// this process for --simulate; the coaxial lamp is wired to coil
/// `LampCoil` of the gantry simulator, whose state the camera sees.
struct SimulatedRig
{
  vtkNew<vtkGantrySimulator> Gantry;
  vtkNew<vtkModbusGantry> AngleReader;
  vtkNew<vtkSimulatedRigCamera> Camera;
  int LampCoil = 0;

  /// Serves the gantry on `address`:`port` (0: a free port, returned) and
  /// the camera on `cameraAddress`, rendering `rigField`'s rig at the
  /// gantry's actual angle, read over Modbus as any client would.
  int Start(const std::string& address,
    int port,
    const std::string& cameraAddress,
    vtkLightField* rigField,
    const CaptureSessionOptions& options,
    StepErrors& errors)
  {
    this->Gantry->SetAddress(address.c_str());
    this->Gantry->SetPort(port);
    errors->Observe(this->Gantry);
    if (!this->Gantry->Start())
    {
      errors.FailOnError();
    }
    this->AngleReader->SetAddress(address.c_str());
    this->AngleReader->SetPort(this->Gantry->GetBoundPort());
    errors->Observe(this->AngleReader);
    if (!this->AngleReader->Connect())
    {
      errors.FailOnError();
    }
    vtkModbusGantry* reader = this->AngleReader;
    this->Camera->SetAngleSource(
      [reader](double& degrees)
      {
        if (!reader->UpdateState())
        {
          return false;
        }
        degrees = reader->GetActualAngle();
        return true;
      });
    vtkGantrySimulator* simulator = this->Gantry;
    const int coil = this->LampCoil = std::max(0, options.CoaxialCoil);
    this->Camera->SetCoaxialLightSource([simulator, coil] { return simulator->GetCoil(coil); });
    vtkSmartPointer<vtkImageData> texture;
    vtkSmartPointer<vtkPolyData> mesh = SourceMesh(options.Object, texture);
    this->Camera->SetAddress(cameraAddress.c_str());
    this->Camera->GetCapture()->SetInputData(mesh);
    if (texture)
    {
      this->Camera->GetCapture()->SetTextureData(texture);
    }
    this->Camera->SetRig(rigField->GetRig());
    this->Camera->SetProjectors(options.Projectors > 0 ? rigField->GetProjectors() : nullptr);
    this->Camera->SetSensorNoise(options.Noise);
    errors->Observe(this->Camera);
    if (!this->Camera->Start())
    {
      errors.FailOnError();
    }
    return this->Gantry->GetBoundPort();
  }
};

/// The coaxial lamp on a Modbus coil: `coil` of the gantry's controller, or
/// of the device at --coaxial-lamp (with the gantry's timeouts and retries).
vtkSmartPointer<vtkModbusLight> MakeLamp(vtkModbusGantry* gantry,
  int coil,
  const CaptureSessionOptions& options)
{
  auto lamp = vtkSmartPointer<vtkModbusLight>::New();
  lamp->SetName("coaxial lamp");
  lamp->SetAddress(gantry->GetAddress());
  lamp->SetPort(gantry->GetPort());
  if (!options.CoaxialLamp.empty())
  {
    std::string address;
    int port = 0;
    SplitAddress("--coaxial-lamp", options.CoaxialLamp, address, port);
    lamp->SetAddress(address.c_str());
    lamp->SetPort(port);
  }
  lamp->SetUnitId(options.CoaxialUnit);
  lamp->SetCoil(coil);
  // The simulated lamp is bright at once; a real one takes its time.
  lamp->SetSettleTime(
    options.CoaxialSettle >= 0.0 ? options.CoaxialSettle : (options.Simulate ? 0.0 : 0.05));
  lamp->SetConnectTimeout(gantry->GetConnectTimeout());
  lamp->SetResponseTimeout(gantry->GetResponseTimeout());
  lamp->SetRetries(gantry->GetRetries());
  return lamp;
}

/// The lights of the rig: the coaxial lamp on a Modbus coil (with
/// --simulate, always: the simulator's coil), and the simulated projectors
/// or the projectors' windows on their X screens.
std::vector<vtkSmartPointer<vtkCaptureLight>> MakeLights(vtkLightField* plan,
  vtkModbusGantry* gantry,
  SimulatedRig* simulated,
  const CaptureSessionOptions& options)
{
  std::vector<vtkSmartPointer<vtkCaptureLight>> lights;
  if (simulated || options.CoaxialCoil >= 0)
  {
    lights.emplace_back(
      MakeLamp(gantry, simulated ? simulated->LampCoil : options.CoaxialCoil, options));
  }
  if (!simulated && options.Projectors > 0 &&
    static_cast<int>(options.ProjectorDisplays.size()) != options.Projectors)
  {
    Fail("--projectors " + std::to_string(options.Projectors) + ": give one --projector-display " +
      "per projector (" + std::to_string(options.ProjectorDisplays.size()) + " given)");
  }
  for (int p = 0; p < options.Projectors; ++p)
  {
    vtkSmartPointer<vtkCaptureProjector> projector;
    if (simulated)
    {
      auto simulatedProjector = vtkSmartPointer<vtkSimulatedProjector>::New();
      simulatedProjector->SetCamera(simulated->Camera);
      projector = simulatedProjector;
    }
    else
    {
      auto window = vtkSmartPointer<vtkProjectorWindow>::New();
      window->SetDisplay(options.ProjectorDisplays[p].c_str());
      projector = window;
    }
    projector->SetName(("projector " + std::to_string(p)).c_str());
    projector->SetMasks(plan->GetProjectorMasks());
    projector->SetProjectorIndex(p);
    lights.emplace_back(projector);
  }
  return lights;
}

void CaptureLightField(CaptureSessionOptions options)
{
  vtkSmartPointer<vtkLightField> rigField = ReadLightField(options.Rig);
  vtkSmartPointer<vtkLightField> plan = MakePlan(rigField, options);
  std::string gantryAddress;
  int gantryPort = 0;
  SplitAddress("--gantry", options.Gantry, gantryAddress, gantryPort);
  if (options.Simulate && !options.CoaxialLamp.empty())
  {
    Fail("--coaxial-lamp '" + options.CoaxialLamp +
      "': not with --simulate (the simulated lamp is on a coil of the gantry simulator)");
  }

  StepErrors errors;
  SimulatedRig simulated;
  if (options.Simulate)
  {
    gantryPort =
      simulated.Start(gantryAddress, gantryPort, options.Camera, rigField, options, errors);
  }
  vtkNew<vtkModbusGantry> gantry;
  if (!options.GantryConfig.empty() && !gantry->ReadConfiguration(options.GantryConfig.c_str()))
  {
    errors.FailOnError();
  }
  if (options.GantryConfig.empty() || options.Simulate)
  {
    gantry->SetAddress(gantryAddress.c_str());
    gantry->SetPort(gantryPort);
    gantry->SetVelocity(options.Velocity);
    gantry->SetAcceleration(options.Acceleration);
  }
  vtkNew<vtkAravisCamera> camera;
  camera->SetAddress(options.Camera.c_str());
  camera->SetExposureTime(options.Exposure);
  camera->SetGain(options.Gain);
  if (options.Simulate)
  {
    // A simulated frame is a render, which a loaded machine can stretch
    // past the 2 s a real exposure gets. A trigger retried meanwhile is
    // queued by the fake camera and answered by one more frame, which the
    // next pass can take for its own (seen at load 18: a view's Flood pass
    // holding its Coded image).
    camera->SetFrameTimeout(30000);
  }

  vtkNew<vtkCaptureSession> session;
  session->SetGantry(gantry);
  session->SetCamera(camera);
  for (vtkCaptureLight* light :
    MakeLights(plan, gantry, options.Simulate ? &simulated : nullptr, options))
  {
    session->AddLight(light);
  }
  session->SetFirstAngle(options.FirstAngle);
  session->SetAngleStep(360.0 / options.Views);
  vtkIncrementalLightFieldWriter* writer = session->GetWriter();
  writer->SetDirectory(options.Out.c_str());
  writer->SetPlan(plan);
  writer->AddPass(vtkLightField::COAXIAL);
  if (options.Projectors > 0)
  {
    writer->AddPass(vtkLightField::CODED);
    writer->AddPass(vtkLightField::FLOOD);
  }
  errors->Observe(session);
  lfd::ShowSteps(session,
    "capturing",
    [writer](vtkObject* caller)
    {
      auto* running = static_cast<vtkCaptureSession*>(caller);
      char text[64];
      std::snprintf(text,
        sizeof(text),
        "view %d/%d, %.0f s left",
        writer->GetNumberOfCompleteViews(),
        writer->GetNumberOfPlannedViews(),
        running->GetSecondsRemaining());
      return std::string(text);
    });
  RunningSession = session;
  std::signal(SIGINT, AbortCapture);
  std::signal(SIGTERM, AbortCapture);
  const bool ok = options.Resume ? session->Resume() : session->Capture();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  RunningSession = nullptr;
  if (options.Simulate)
  {
    simulated.Camera->Stop();
    simulated.Gantry->Stop();
  }
  if (!ok)
  {
    errors.FailOnError();
  }
  const int taken = session->GetNumberOfViewsTaken();
  const int complete = writer->GetNumberOfCompleteViews();
  if (session->GetAborted())
  {
    Fail("interrupted: " + std::to_string(complete) + " of " + std::to_string(options.Views) +
      " views complete in '" + options.Out + "'; continue with --resume");
  }
  std::printf("Captured %d views x %d passes into %s (%d of them now; %d were complete). "
              "Devices %.2f s (moves and exposures), lfd capture overhead %.1f ms per view.\n",
    complete,
    writer->GetNumberOfPasses(),
    options.Out.c_str(),
    taken,
    complete - taken,
    session->GetDeviceSeconds(),
    taken > 0 ? 1000.0 * session->GetOverheadSeconds() / taken : 0.0);
}
}

void AddCaptureSessionCommand(CLI::App& app,
  NumericOptions& numbers,
  std::vector<Command>& commands)
{
  auto options = std::make_shared<CaptureSessionOptions>();
  auto* command = app.add_subcommand("capture",
    "capture a light field with a ring gantry (Modbus TCP), a GigE Vision camera and the "
    "projectors: at each of VIEWS positions a Coaxial pass, plus Coded and Flood with "
    "projectors; every view is committed to OUT as soon as it is taken, Ctrl-C stops after the "
    "current view, --resume continues an interrupted or failed capture (vtkCaptureSession)");
  command
    ->add_option("--rig",
      options->Rig,
      "light field whose rig (a ring of views about its axis, view k at k * 360 / its views "
      "degrees: lfd synth --rows 1, or a calibrated rig), projectors and masks are captured")
    ->required();
  command->add_option("--out", options->Out, "the dataset to write (or to resume)")->required();
  command
    ->add_option("--gantry",
      options->Gantry,
      "the gantry controller's ADDRESS:PORT (Modbus TCP); with --simulate where the simulator "
      "serves (port 0: any free port)")
    ->capture_default_str();
  command->add_option("--gantry-config",
    options->GantryConfig,
    "gantry description (gantry.json, Data/README.md): address, port, motion and timeouts");
  command->add_option("--camera", options->Camera, "the GigE Vision camera's IPv4 address")
    ->capture_default_str();
  numbers.Add(command,
    "--views",
    options->Views,
    0,
    VTK_INT_MAX,
    "gantry positions: every (rig views / VIEWS)-th view of the rig (0: all)");
  numbers.Add(command,
    "--projectors",
    options->Projectors,
    0,
    VTK_INT_MAX,
    "projectors used (0, or all of the rig's): adds the Coded and Flood passes");
  command->add_option("--projector-display",
    options->ProjectorDisplays,
    "X screen of each projector (e.g. :0.1), once per projector; not with --simulate");
  numbers.AddReal(
    command, "--first-angle", options->FirstAngle, "gantry angle of the first view, in degrees");
  numbers.Add(command, "--velocity", options->Velocity, 0.01, 655.35, "gantry degree/s");
  numbers.Add(command, "--acceleration", options->Acceleration, 0.1, 6553.5, "gantry degree/s^2");
  numbers.Add(command, "--exposure", options->Exposure, 1.0, 1.0e7, "exposure time in us");
  numbers.Add(command, "--gain", options->Gain, 0.0, 48.0, "camera gain in dB");
  command->add_flag("--resume",
    options->Resume,
    "continue the capture in OUT after its complete views (same --rig, --views, --projectors)");
  command->add_flag("--simulate",
    options->Simulate,
    "serve the gantry simulator and the simulated rig camera (rendering OBJECT at the gantry's "
    "actual angle under the simulated lights) from this process, and capture from them");
  command
    ->add_option("--object",
      options->Object,
      "with --simulate: built-in object (fish, figure, checkerboard) or mesh file photographed")
    ->capture_default_str();
  numbers.Add(command,
    "--noise",
    options->Noise,
    0.0,
    255.0,
    "with --simulate: standard deviation of the sensor noise in 8-bit levels");
  numbers.Add(command,
    "--coaxial-coil",
    options->CoaxialCoil,
    -1,
    65535,
    "the Modbus coil (0-based) switching the coaxial lamp, on for the Coaxial pass only, read "
    "back after each switch: a digital output of the gantry's controller, or of --coaxial-lamp "
    "(-1: no lamp switched by lfd; with --simulate the lamp is on this coil of the simulator, "
    "coil 0 for -1)");
  command->add_option("--coaxial-lamp",
    options->CoaxialLamp,
    "ADDRESS:PORT of the Modbus TCP device (relay module) with --coaxial-coil, when it is not "
    "the gantry's controller");
  numbers.Add(command,
    "--coaxial-unit",
    options->CoaxialUnit,
    0,
    255,
    "Modbus unit id of the lamp's device: 0 to 247 (a relay module behind a gateway), or 255 "
    "for the device itself");
  numbers.Add(command,
    "--coaxial-settle",
    options->CoaxialSettle,
    -1.0,
    60.0,
    "seconds to wait after the lamp switches, before the photograph (-1: 0.05, or 0 with "
    "--simulate, whose lamp is bright at once)");
  commands.push_back({ command, [options] { CaptureLightField(*options); }, true });
}
}

// vtkCaptureSession with real peers on 127.0.0.1: the gantry simulator
// (Modbus TCP, in this process, a free port) and the simulated rig camera
// (GigE Vision), the simulated coaxial lamp and two projectors. A plan of
// 4 ring views x 3 passes is captured through faults:
// - an emergency stop during the move to view 2: one error naming the
//   gantry and the fault, views 0-1 complete and readable, the axis still;
//   then Resume() completes views 2-3, each view once, matching
//   vtkLightFieldCapture's own render of the ring views;
// - the gantry going silent before view 1, the camera gone before view 2
//   (one error each naming the device; the complete views listed);
// - Abort() after view 0: no error, one view, resumable.
#include "lfdCameraTestScene.h"
#include "lfdFileUtilities.h"
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"
#include "vtkAravisCamera.h"
#include "vtkCallbackCommand.h"
#include "vtkCaptureSession.h"
#include "vtkIncrementalLightFieldWriter.h"
#include "vtkLightFieldReader.h"
#include "vtkSimulatedCoaxialLight.h"
#include "vtkSimulatedProjector.h"

#include <cmath>
#include <filesystem>
#include <functional>

namespace
{
namespace fs = std::filesystem;
using lfd::test::Check;
using lfd::test::CheckError;
constexpr int PlannedViews = 4;

/// The devices and the session of the test.
struct CaptureRig
{
  lfdtest::CameraScene Scene;
  lfd::test::GantryRig Gantry;
  vtkNew<vtkSimulatedRigCamera> Simulated;
  vtkNew<vtkSimulatedCoaxialLight> Lamp;
  vtkNew<vtkSimulatedProjector> Projectors[2];
  vtkNew<vtkAravisCamera> Camera;
  vtkNew<vtkCaptureSession> Session;
  vtkNew<vtkLightField> Plan;
  vtkNew<vtkLightFieldErrorObserver> Errors;
  std::function<void(int)> AfterView; // called with the number of complete views

  bool Start()
  {
    this->Scene.SetUp(this->Simulated);
    // The camera sees the gantry's actual angle, as the rig does.
    vtkGantrySimulator* simulator = this->Gantry.Simulator;
    this->Simulated->SetAngleSource(
      [simulator](double& degrees)
      {
        degrees = simulator->GetActualAngle();
        return true;
      });
    this->Lamp->SetCamera(this->Simulated);
    this->Session->AddLight(this->Lamp);
    for (int p = 0; p < 2; ++p)
    {
      this->Projectors[p]->SetCamera(this->Simulated);
      this->Projectors[p]->SetMasks(this->Scene.Masks);
      this->Projectors[p]->SetProjectorIndex(p);
      this->Session->AddLight(this->Projectors[p]);
    }
    this->Camera->SetAddress("127.0.0.1");
    // Generous: a retried trigger under load could deliver the late frame
    // of the first (the camera gone fails at its trigger, not here).
    this->Camera->SetFrameTimeout(3000);
    this->Camera->SetMaximumAttempts(2);
    // Fast moves: a 10 degree step takes about 0.1 s.
    this->Gantry.Gantry->SetVelocity(360.0);
    this->Gantry.Gantry->SetAcceleration(3600.0);
    this->Gantry.Gantry->SetRetries(1);
    this->Session->SetGantry(this->Gantry.Gantry);
    this->Session->SetCamera(this->Camera);
    this->Session->SetAngleStep(360.0 / lfdtest::RingViews);
    // The plan: the first 4 ring views, the projectors and their masks.
    vtkNew<vtkCameraRig> rig;
    rig->SetNumberOfViews(PlannedViews);
    rig->SetImageSize(lfdtest::FrameSize, lfdtest::FrameSize);
    for (int v = 0; v < PlannedViews; ++v)
    {
      rig->SetView(v, this->Scene.Ring->GetCamera(v));
    }
    this->Plan->SetLayout(lfdtest::FrameSize, lfdtest::FrameSize, PlannedViews);
    this->Plan->SetRig(rig);
    this->Plan->SetProjectors(this->Scene.Projectors);
    // A dataset's masks are its "Mask" array (Data/README.md).
    this->Scene.Masks->GetPointData()->GetScalars()->SetName("Mask");
    this->Plan->SetProjectorMasks(this->Scene.Masks);
    vtkIncrementalLightFieldWriter* writer = this->Session->GetWriter();
    writer->SetPlan(this->Plan);
    for (int pass : { vtkLightField::COAXIAL, vtkLightField::CODED, vtkLightField::FLOOD })
    {
      writer->AddPass(pass);
    }
    this->Errors->Observe(this->Session);
    this->Errors->Observe(this->Simulated);
    vtkNew<vtkCallbackCommand> progress;
    progress->SetClientData(this);
    progress->SetCallback(
      [](vtkObject*, unsigned long, void* self, void*)
      {
        auto* rig = static_cast<CaptureRig*>(self);
        if (rig->AfterView)
        {
          rig->AfterView(rig->Session->GetWriter()->GetNumberOfCompleteViews());
        }
      });
    this->Session->AddObserver(vtkCommand::ProgressEvent, progress);
    this->Gantry.Simulator->SetSilentTime(1.0);
    return this->Gantry.Start(false) && this->Simulated->Start();
  }

  /// Starts (or resumes) a capture into `directory`; its result.
  bool Run(const std::string& directory, bool resume)
  {
    this->Session->GetWriter()->SetDirectory(directory.c_str());
    return resume ? this->Session->Resume() : this->Session->Capture();
  }
};

/// Every image file in `directory` (recursively), and whether a temporary
/// (".tmp-") is among them.
int CountFiles(const std::string& directory, bool& temporaries)
{
  int count = 0;
  temporaries = false;
  std::error_code ec;
  for (const auto& entry : fs::recursive_directory_iterator(directory, ec))
  {
    temporaries = temporaries || entry.path().string().find(".tmp-") != std::string::npos;
    count += entry.is_regular_file() && entry.path().extension() == ".png" ? 1 : 0;
  }
  return count;
}

/// The dataset reads back with `views` views; PSNR (dB) of its passes
/// against the reference's first `views` views (0 when unreadable).
double ReadBack(const std::string& directory, int views, vtkLightField* reference)
{
  vtkNew<vtkLightFieldReader> reader;
  reader->SetFileName(directory.c_str());
  reader->Update();
  vtkLightField* read = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || read->GetNumberOfViews() != views)
  {
    return 0.0;
  }
  double sum = 0.0;
  vtkIdType count = 0;
  for (int pass : { vtkLightField::COAXIAL, vtkLightField::CODED, vtkLightField::FLOOD })
  {
    vtkDataArray* got = read->GetPass(pass);
    vtkDataArray* want = reference->GetPass(pass);
    if (!got)
    {
      return 0.0;
    }
    for (vtkIdType i = 0; i < got->GetNumberOfValues(); ++i)
    {
      const double d = got->GetComponent(i / 3, i % 3) - want->GetComponent(i / 3, i % 3);
      sum += d * d;
      ++count;
    }
  }
  const double mse = sum / count;
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 100.0;
}

/// The gantry stands still and reports `fault` (lfdGantryRegisters.h).
bool GantryStopped(CaptureRig& rig, int fault, const std::string& what)
{
  lfd::test::Sleep(0.05);
  const int status = rig.Gantry.Simulator->GetStatusWord();
  return Check(
    (status & lfd::gantry::MovingBit) == 0 && rig.Gantry.Simulator->GetFaultCode() == fault,
    what + ": the gantry stands still, fault code " + std::to_string(fault),
    "status " + std::to_string(status) + ", fault " +
      std::to_string(rig.Gantry.Simulator->GetFaultCode()));
}
}

int TestCaptureSession(int, char*[])
{
  CaptureRig rig;
  if (!rig.Start())
  {
    std::cerr << rig.Errors->GetErrorMessage() << rig.Gantry.Errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkLightField> reference = rig.Scene.Reference({ 0, 1, 2, 3 });
  const std::string temp = LFD_TEST_TEMP_DIR;
  const std::string gantry = rig.Gantry.Gantry->GetDeviceName();
  bool ok = true;
  bool temporaries = false;

  // Emergency stop during the move to view 2, then resumed.
  const std::string estop = temp + "/session-estop.lf";
  lfd::io::RemoveQuietly(estop);
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 2)
    {
      rig.Gantry.Simulator->ArmFault(lfd::gantry::EmergencyStopMode);
    }
  };
  ok &= Check(!rig.Run(estop, false), "e-stop: the capture fails", "");
  ok &= CheckError(rig.Errors,
    "view 2 of 4 (gantry angle 20): " + gantry +
      ": drive fault 2 (emergency stop) during the move to 20 deg");
  ok &= GantryStopped(rig, lfd::gantry::EmergencyStop, "e-stop");
  ok &= Check(CountFiles(estop, temporaries) == 2 * 3 + 2 && !temporaries,
    "e-stop: 2 views x 3 passes + 2 masks written, no temporary",
    CountFiles(estop, temporaries));
  const double partial = ReadBack(estop, 2, reference);
  ok &= Check(partial > 40.0, "e-stop: the dataset reads back with 2 views, PSNR (dB)", partial);
  rig.AfterView = nullptr;
  ok &= Check(rig.Run(estop, true) && rig.Session->GetNumberOfViewsTaken() == 2,
    "e-stop: resumed, views taken",
    rig.Session->GetNumberOfViewsTaken());
  ok &= Check(!rig.Errors->HasError(),
    "e-stop: resumed without error",
    rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "none");
  ok &= Check(CountFiles(estop, temporaries) == 4 * 3 + 2 && !temporaries,
    "e-stop: 4 views x 3 passes + 2 masks, each once",
    CountFiles(estop, temporaries));
  const double complete = ReadBack(estop, 4, reference);
  ok &= Check(complete > 40.0, "e-stop: 4 views read back, PSNR against the render (dB)", complete);
  std::cout << "overhead per view " << 1000.0 * rig.Session->GetOverheadSeconds() / 2
            << " ms, devices " << 1000.0 * rig.Session->GetDeviceSeconds() / 2 << " ms\n";
  const bool again = rig.Run(estop, true);
  ok &= Check(again && rig.Session->GetNumberOfViewsTaken() == 0,
    "e-stop: resuming a complete capture takes no view",
    rig.Session->GetNumberOfViewsTaken());

  // The gantry silent before the move to view 1.
  const std::string silent = temp + "/session-silent.lf";
  lfd::io::RemoveQuietly(silent);
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 1)
    {
      rig.Gantry.Simulator->ArmFault(lfd::gantry::SilentMode);
    }
  };
  ok &= Check(!rig.Run(silent, false), "silent: the capture fails", "");
  const std::string silentMessage = rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "";
  ok &= Check(silentMessage.rfind("view 1 of 4 (gantry angle 10): " + gantry + ": ", 0) == 0 &&
      silentMessage.find("no answer within 0.2 s") != std::string::npos &&
      rig.Errors->GetNumberOfErrors() == 1,
    "silent: one error naming the view and the gantry",
    silentMessage);
  rig.Errors->Clear();
  lfd::test::Sleep(1.0);
  ok &= GantryStopped(rig, lfd::gantry::NoFault, "silent");
  ok &= Check(ReadBack(silent, 1, reference) > 40.0, "silent: 1 view listed", "");

  // Aborted after view 0 of a new capture: no error, one view.
  const std::string aborted = temp + "/session-abort.lf";
  lfd::io::RemoveQuietly(aborted);
  rig.AfterView = [&rig](int) { rig.Session->Abort(); };
  ok &= Check(rig.Run(aborted, false) && rig.Session->GetAborted() &&
      rig.Session->GetNumberOfViewsTaken() == 1 && !rig.Errors->HasError(),
    "abort: stopped after 1 view without error",
    rig.Session->GetNumberOfViewsTaken());

  // A capture is never started over an existing one.
  ok &= Check(!rig.Run(silent, false), "an existing capture is not replaced", "");
  ok &= CheckError(rig.Errors,
    silent + ": exists; resume that capture, or choose a new name (it is never replaced)");

  // The camera gone before view 2 of the resumed silent capture.
  rig.AfterView = [&rig](int complete)
  {
    if (complete == 2)
    {
      rig.Simulated->Stop();
    }
  };
  ok &= Check(!rig.Run(silent, true), "camera gone: the capture fails", "");
  const std::string cameraMessage = rig.Errors->HasError() ? rig.Errors->GetErrorMessage() : "";
  ok &= Check(cameraMessage.rfind(
                "view 2 of 4 (gantry angle 20), Coaxial pass: Camera 127.0.0.1: ", 0) == 0 &&
      rig.Errors->GetNumberOfErrors() == 1,
    "camera gone: one error naming the view and the camera",
    cameraMessage);
  rig.Errors->Clear();
  ok &= GantryStopped(rig, lfd::gantry::NoFault, "camera gone");
  ok &= Check(ReadBack(silent, 2, reference) > 40.0 && CountFiles(silent, temporaries) == 2 * 3 + 2,
    "camera gone: 2 views listed and written",
    CountFiles(silent, temporaries));

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

/**
 * @file   lfdCaptureTestRig.h
 * @brief  What the capture session tests share: the simulated rig served in
 *         the test process on 127.0.0.1 (the gantry simulator on a free
 *         port, whose coil 0 switches the coaxial lamp through a real
 *         vtkModbusLight; the simulated GigE camera, which sees the gantry's
 *         actual angle and that coil; two simulated projectors), a session
 *         capturing 4 ring views x 3 passes, and the checks of a dataset
 *         after a fault.
 */
#ifndef lfdCaptureTestRig_h
#define lfdCaptureTestRig_h

#include "lfdCameraTestScene.h"
#include "lfdFileUtilities.h"
#include "lfdGantryRegisters.h"
#include "lfdGantryTestUtilities.h"
#include "vtkAravisCamera.h"
#include "vtkCallbackCommand.h"
#include "vtkCaptureSession.h"
#include "vtkIncrementalLightFieldWriter.h"
#include "vtkLightFieldReader.h"
#include "vtkModbusLight.h"
#include "vtkSimulatedProjector.h"

#include <cmath>
#include <filesystem>
#include <functional>

namespace lfd
{
namespace test
{
constexpr int PlannedViews = 4;

/// The devices and the session of the test.
struct CaptureRig
{
  lfdtest::CameraScene Scene;
  GantryRig Gantry;
  vtkNew<vtkSimulatedRigCamera> Simulated;
  vtkNew<vtkModbusLight> Lamp;
  vtkNew<vtkSimulatedProjector> Projectors[2];
  vtkNew<vtkAravisCamera> Camera;
  vtkNew<vtkCaptureSession> Session;
  vtkNew<vtkLightField> Plan;
  vtkNew<vtkLightFieldErrorObserver> Errors;
  std::function<void(int)> AfterView; // called with the number of complete views

  bool Start()
  {
    this->Scene.SetUp(this->Simulated);
    // The camera sees the gantry's actual angle and the lamp as its coil
    // is, as the rig does.
    vtkGantrySimulator* simulator = this->Gantry.Simulator;
    this->Simulated->SetAngleSource(
      [simulator](double& degrees)
      {
        degrees = simulator->GetActualAngle();
        return true;
      });
    this->Simulated->SetCoaxialLightSource([simulator] { return simulator->GetCoil(0); });
    this->Lamp->SetName("coaxial lamp");
    this->Lamp->SetAddress("127.0.0.1");
    this->Lamp->SetResponseTimeout(0.2);
    this->Lamp->SetRetries(1);
    this->Lamp->SetSettleTime(0.0);
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
    this->Gantry.Simulator->SetSlowFactor(0.01);
    if (!this->Gantry.Start(false))
    {
      return false;
    }
    this->Lamp->SetPort(this->Gantry.Simulator->GetBoundPort());
    return this->Simulated->Start();
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
inline int CountFiles(const std::string& directory, bool& temporaries)
{
  int count = 0;
  temporaries = false;
  std::error_code ec;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(directory, ec))
  {
    temporaries = temporaries || entry.path().string().find(".tmp-") != std::string::npos;
    count += entry.is_regular_file() && entry.path().extension() == ".png" ? 1 : 0;
  }
  return count;
}

/// The dataset reads back with `views` views; PSNR (dB) of its passes
/// against the reference's first `views` views (0 when unreadable).
inline double ReadBack(const std::string& directory, int views, vtkLightField* reference)
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

/// The gantry stands still (velocity 0, not moving) and reports `fault`
/// (lfdGantryRegisters.h).
inline bool GantryStopped(CaptureRig& rig, int fault, const std::string& what)
{
  Sleep(0.05);
  vtkGantrySimulator* simulator = rig.Gantry.Simulator;
  const int status = simulator->GetStatusWord();
  const double velocity = simulator->GetActualVelocity();
  return Check(
    (status & lfd::gantry::MovingBit) == 0 && velocity == 0.0 && simulator->GetFaultCode() == fault,
    what + ": the gantry stands still, fault code " + std::to_string(fault),
    "status " + std::to_string(status) + ", velocity " + std::to_string(velocity) + ", fault " +
      std::to_string(simulator->GetFaultCode()));
}

/// The lamp's coil is off and no projector lights the object.
inline bool LightsOff(CaptureRig& rig, const std::string& what)
{
  const bool lamp = rig.Gantry.Simulator->GetCoil(0);
  const int projectors = rig.Simulated->GetNumberOfLitProjectors();
  return Check(!lamp && projectors == 0,
    what + ": the lights are off",
    std::string(lamp ? "lamp on, " : "lamp off, ") + std::to_string(projectors) +
      " projectors lit");
}

/// The dataset in `directory` lists `views` complete views, holds their 3
/// images each and the 2 masks, and no temporary.
inline bool CheckDataset(const std::string& directory,
  int views,
  vtkLightField* reference,
  const std::string& what)
{
  bool temporaries = false;
  const int files = CountFiles(directory, temporaries);
  const double psnr = ReadBack(directory, views, reference);
  return Check(files == views * 3 + 2 && !temporaries && psnr > 40.0,
    what + ": " + std::to_string(views) + " views listed, " + std::to_string(views) +
      " x 3 images + 2 masks, no temporary, PSNR > 40 dB against the render",
    std::to_string(files) + " images" + (temporaries ? " and temporaries" : "") + ", " +
      std::to_string(psnr) + " dB");
}
}
}

#endif

// The simulated rig camera over a real GigE Vision stream on 127.0.0.1:
// frames of each pass (coaxial lamp, projectors coded, projectors flood) at
// three gantry angles, acquired by vtkAravisCamera in RGB8, compared with
// vtkLightFieldCapture's own render of the same ring views (sensor noise
// sigma 2: PSNR about 44.8 dB, the black background clamps half the
// noise); the last angle through an angle source; then the same view in
// BayerRG8 (demosaiced, 34.3 dB) and Mono8 (against the luma).
#include "lfdCameraTestScene.h"
#include "vtkAravisCamera.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkSimulatedCoaxialLight.h"
#include "vtkSimulatedProjector.h"

#include <chrono>

int TestSimulatedRigCamera(int, char*[])
{
  lfdtest::CameraScene scene;
  vtkNew<vtkSimulatedRigCamera> simulated;
  scene.SetUp(simulated);
  simulated->SetSensorNoise(2.0);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(simulated);
  if (!simulated->Start())
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkSimulatedCoaxialLight> lamp;
  lamp->SetCamera(simulated);
  vtkNew<vtkSimulatedProjector> projectors[2];
  for (int p = 0; p < 2; ++p)
  {
    projectors[p]->SetCamera(simulated);
    projectors[p]->SetMasks(scene.Masks);
    projectors[p]->SetProjectorIndex(p);
  }
  const int views[3] = { 0, 12, 22 };
  vtkSmartPointer<vtkLightField> reference = scene.Reference({ views[0], views[1], views[2] });

  vtkNew<vtkAravisCamera> camera;
  camera->SetAddress("127.0.0.1");
  errors->Observe(camera);
  if (!camera->Open())
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  lfdtest::Check(camera->GetFrameSize()[0] == lfdtest::FrameSize &&
      camera->GetFrameSize()[1] == lfdtest::FrameSize,
    "frame width reported by the camera",
    camera->GetFrameSize()[0],
    lfdtest::FrameSize);
  vtkNew<vtkImageData> frame;
  const int passes[3] = { vtkLightField::COAXIAL, vtkLightField::CODED, vtkLightField::FLOOD };
  const auto start = std::chrono::steady_clock::now();
  for (int v = 0; v < 3; ++v)
  {
    // The last angle comes from an angle source, as the gantry's will.
    const double angle = 360.0 * views[v] / lfdtest::RingViews;
    if (v < 2)
    {
      simulated->SetAngle(angle);
    }
    else
    {
      simulated->SetAngleSource(
        [angle](double& degrees)
        {
          degrees = angle;
          return true;
        });
    }
    for (int pass : passes)
    {
      lamp->Apply(pass);
      for (auto& projector : projectors)
      {
        projector->Apply(pass);
      }
      if (!camera->Acquire(frame))
      {
        std::cerr << errors->GetErrorMessage() << "\n";
        return EXIT_FAILURE;
      }
      const int* dims = frame->GetDimensions();
      lfdtest::Check(dims[0] == lfdtest::FrameSize && dims[1] == lfdtest::FrameSize &&
          dims[2] == 1 && frame->GetNumberOfScalarComponents() == 3 &&
          frame->GetScalarType() == VTK_UNSIGNED_CHAR,
        "RGB uint8 frame of 96 x 96, width",
        dims[0],
        lfdtest::FrameSize);
      const std::string what =
        std::string("view ") + std::to_string(views[v]) + " " + vtkLightField::GetPassName(pass);
      // The reference shows the object (not a black frame that noise alone
      // would match).
      const double lit = lfdtest::LitFraction(reference, v, pass);
      lfdtest::Check(lit > 0.05, "fraction of lit pixels in the reference " + what, lit, 0.05);
      const double psnr = lfdtest::FramePSNR(frame, reference, v, pass);
      lfdtest::Check(psnr > 43.5, "PSNR of " + what + " (dB)", psnr, 43.5);
    }
  }
  // The test tells views apart: the last frame (view 22, Flood) is far from
  // the Flood of view 12.
  const double wrong = lfdtest::FramePSNR(frame, reference, 1, vtkLightField::FLOOD);
  lfdtest::Check(wrong < 30.0, "PSNR of view 22 Flood against view 12 Flood (dB)", wrong, 30.0);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "9 frames in " << seconds << " s\n";
  lfdtest::Check(camera->GetNumberOfRetries() == 0, "retries", camera->GetNumberOfRetries(), 0);

  // The same coaxial view through a Bayer mosaic (demosaiced: edges blur)
  // and in grey.
  lamp->Apply(vtkLightField::COAXIAL);
  for (auto& projector : projectors)
  {
    projector->Off();
  }
  simulated->SetAngleSource(nullptr);
  simulated->SetAngle(120.0);
  camera->SetPixelFormat(vtkAravisCamera::BAYER_RG8);
  if (!camera->Open() || !camera->Acquire(frame))
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  const double bayer = lfdtest::FramePSNR(frame, reference, 1, vtkLightField::COAXIAL);
  lfdtest::Check(bayer > 33.5, "PSNR of view 12 Coaxial through BayerRG8 (dB)", bayer, 33.5);
  camera->SetPixelFormat(vtkAravisCamera::MONO8);
  if (!camera->Open() || !camera->Acquire(frame))
  {
    std::cerr << errors->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  const auto* grey = static_cast<const unsigned char*>(frame->GetScalarPointer());
  bool greyPixels = true;
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    greyPixels = greyPixels && grey[3 * i] == grey[3 * i + 1] && grey[3 * i] == grey[3 * i + 2];
  }
  lfdtest::Check(greyPixels, "Mono8 frame is grey (R = G = B)", greyPixels, 1);
  const double mono = lfdtest::FramePSNR(frame, reference, 1, vtkLightField::COAXIAL, true);
  lfdtest::Check(
    mono > 43.5, "PSNR of view 12 Coaxial through Mono8, against its luma (dB)", mono, 43.5);
  camera->Close();
  simulated->Stop();
  lfdtest::Check(!errors->HasError(), "errors reported", errors->HasError(), 0);
  return lfdtest::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

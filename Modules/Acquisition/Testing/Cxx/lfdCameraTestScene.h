// The simulated rig the camera tests photograph: the fish on a ring of 36
// views of 96 x 96 pixels about the Y axis, two projectors at views 4 and
// 14 of the ring, each with a painted two-colour mask; helpers to compare
// frames (top row first) with a light field's views (bottom row first).
#ifndef lfdCameraTestScene_h
#define lfdCameraTestScene_h

#include "lfdPixelFormat.h"
#include "lfdTestChecks.h"
#include "vtkCameraRig.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSimulatedRigCamera.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <string>

namespace lfdtest
{
constexpr int FrameSize = 96;
constexpr int RingViews = 36;

struct CameraScene
{
  vtkNew<vtkProceduralObjectSource> Fish;
  vtkNew<vtkCameraRig> Ring;
  vtkNew<vtkCameraRig> Projectors;
  vtkNew<vtkImageData> Masks;

  CameraScene()
  {
    this->Fish->SetObjectToFish();
    this->Fish->SetResolution(24);
    this->Fish->Update();
    double bounds[6];
    vtkPolyData::SafeDownCast(this->Fish->GetOutputDataObject(0))->GetBounds(bounds);
    const double center[3] = {
      0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
    };
    const double axis[3] = { 0.0, 1.0, 0.0 };
    const double sphere = 0.5 *
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
        (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    const double height = 0.0;
    this->Ring->MakeCylinder(
      center, axis, 4.5 * sphere, RingViews, 1, &height, FrameSize, FrameSize, 30.0);
    this->Projectors->SetNumberOfViews(2);
    this->Projectors->SetImageSize(FrameSize, FrameSize);
    this->Projectors->SetView(0, this->Ring->GetCamera(4));
    this->Projectors->SetView(1, this->Ring->GetCamera(14));
    // Projector 0: red left half, green right half; projector 1: blue top,
    // yellow bottom (rows bottom first).
    this->Masks->SetDimensions(FrameSize, FrameSize, 2);
    this->Masks->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* mask = static_cast<unsigned char*>(this->Masks->GetScalarPointer());
    for (int p = 0; p < 2; ++p)
    {
      for (int j = 0; j < FrameSize; ++j)
      {
        for (int i = 0; i < FrameSize; ++i)
        {
          unsigned char* rgb = mask + 3 * ((p * FrameSize + j) * FrameSize + i);
          const bool first = p == 0 ? i < FrameSize / 2 : j >= FrameSize / 2;
          const unsigned char colours[2][2][3] = { { { 255, 0, 0 }, { 0, 255, 0 } },
            { { 0, 0, 255 }, { 255, 255, 0 } } };
          for (int c = 0; c < 3; ++c)
          {
            rgb[c] = colours[p][first ? 0 : 1][c];
          }
        }
      }
    }
  }

  /// Connects the fish and the projectors to a simulated camera.
  void SetUp(vtkSimulatedRigCamera* camera)
  {
    camera->GetCapture()->SetInputConnection(this->Fish->GetOutputPort(0));
    camera->GetCapture()->SetTextureConnection(this->Fish->GetOutputPort(1));
    camera->SetRig(this->Ring);
    camera->SetProjectors(this->Projectors);
  }

  /// vtkLightFieldCapture's own render of the given ring views, all passes.
  vtkSmartPointer<vtkLightField> Reference(std::initializer_list<int> views)
  {
    vtkNew<vtkCameraRig> rig;
    rig->SetNumberOfViews(static_cast<int>(views.size()));
    rig->SetImageSize(FrameSize, FrameSize);
    int i = 0;
    for (int view : views)
    {
      rig->SetView(i++, this->Ring->GetCamera(view));
    }
    vtkNew<vtkLightFieldCapture> capture;
    capture->SetInputConnection(this->Fish->GetOutputPort(0));
    capture->SetTextureConnection(this->Fish->GetOutputPort(1));
    capture->SetRig(rig);
    capture->SetProjectors(this->Projectors);
    capture->SetProjectorMasks(this->Masks);
    capture->CaptureLabelOff();
    capture->CaptureDepthOff();
    capture->Update();
    return capture->GetOutput();
  }
};

/// Fraction of the pixels of view `view` of pass `pass` brighter than 20
/// in some channel.
inline double LitFraction(vtkLightField* reference, int view, int pass)
{
  const vtkIdType pixels = static_cast<vtkIdType>(reference->GetWidth()) * reference->GetHeight();
  const auto* rgb = static_cast<const unsigned char*>(reference->GetPass(pass)->GetVoidPointer(0)) +
    3 * view * pixels;
  vtkIdType lit = 0;
  for (vtkIdType q = 0; q < pixels; ++q)
  {
    lit += std::max({ rgb[3 * q], rgb[3 * q + 1], rgb[3 * q + 2] }) > 20 ? 1 : 0;
  }
  return static_cast<double>(lit) / pixels;
}

/// PSNR (dB) of a frame (RGB, top row first) against view `view` of pass
/// `pass` of a light field, or against its Rec. 601 luma when `grey`.
inline double FramePSNR(vtkImageData* frame,
  vtkLightField* reference,
  int view,
  int pass,
  bool grey = false)
{
  const int w = reference->GetWidth();
  const int h = reference->GetHeight();
  const auto* expected =
    static_cast<const unsigned char*>(reference->GetPass(pass)->GetVoidPointer(0)) +
    3 * static_cast<size_t>(view) * w * h;
  const auto* got = static_cast<const unsigned char*>(frame->GetScalarPointer());
  double sum = 0.0;
  for (int y = 0; y < h; ++y)
  {
    for (int i = 0; i < 3 * w; ++i)
    {
      const unsigned char* pixel = expected + 3 * (h - 1 - y) * w + 3 * (i / 3);
      const double want = grey ? lfd::Luma(pixel) : pixel[i % 3];
      const double d = double(got[3 * y * w + i]) - want;
      sum += d * d;
    }
  }
  const double mse = sum / (3.0 * w * h);
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 100.0;
}
}

#endif

#include "vtkAravisCamera.h"

#include "lfdPixelFormat.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <arv.h>

#include <algorithm>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkAravisCamera);

namespace
{
// The stream settings that loopback and cameras without pacing need
// (PLATFORM-NOTES.md, Aravis): the kernel buffers a whole frame, packets
// fit a standard MTU.
constexpr int SocketBufferBytes = 4 * 1024 * 1024;
constexpr int PacketBytes = 1400;
// Frames queued for the stream: one being filled, one late, one spare.
constexpr int StreamBuffers = 3;

const char* StatusName(ArvBufferStatus status)
{
  switch (status)
  {
    case ARV_BUFFER_STATUS_SUCCESS:
      return "success";
    case ARV_BUFFER_STATUS_CLEARED:
      return "cleared";
    case ARV_BUFFER_STATUS_TIMEOUT:
      return "timeout while receiving";
    case ARV_BUFFER_STATUS_MISSING_PACKETS:
      return "missing packets";
    case ARV_BUFFER_STATUS_WRONG_PACKET_ID:
      return "wrong packet id";
    case ARV_BUFFER_STATUS_SIZE_MISMATCH:
      return "size mismatch";
    case ARV_BUFFER_STATUS_FILLING:
      return "still filling";
    case ARV_BUFFER_STATUS_ABORTED:
      return "aborted";
    default:
      return "unknown status";
  }
}

// The message of a GError, which is then freed.
std::string Consume(GError*& error)
{
  std::string message = error && error->message ? error->message : "unknown error";
  g_clear_error(&error);
  return message;
}

// What a GenICam call that set `error` was refused, in words ("refuses
// FEATURE: reason"), or "" when `error` is not set.
std::string Refusal(GError*& error, const std::string& feature)
{
  return error ? "refuses " + feature + ": " + Consume(error) : std::string();
}

// Sets a float feature within the camera's own bounds: Aravis writes any
// value into a camera's registers, so a value outside them is refused here,
// with the bounds.
std::string SetBounded(ArvCamera* camera,
  const char* feature,
  double value,
  const char* unit,
  void (*getBounds)(ArvCamera*, double*, double*, GError**),
  void (*set)(ArvCamera*, double, GError**))
{
  std::ostringstream setting;
  setting << feature << " = " << value << " " << unit;
  GError* error = nullptr;
  double low = 0.0, high = 0.0;
  getBounds(camera, &low, &high, &error);
  if (error)
  {
    return Refusal(error, setting.str() + " (reading its range)");
  }
  if (value < low || value > high)
  {
    std::ostringstream range;
    range << "refuses " << setting.str() << ": its range is [" << low << ", " << high << "] "
          << unit;
    return range.str();
  }
  set(camera, value, &error);
  return Refusal(error, setting.str());
}

// The settings of a capture camera (Data/README.md, "Camera features"), in
// order, and the frame size; the first refusal in words, "" when all went.
std::string ConfigureCamera(ArvCamera* camera,
  const char* format,
  double exposure,
  double gain,
  int frameSize[2])
{
  GError* error = nullptr;
  std::string problem;
  if (arv_camera_is_gv_device(camera))
  {
    arv_gv_device_set_stream_options(
      ARV_GV_DEVICE(arv_camera_get_device(camera)), ARV_GV_STREAM_OPTION_PACKET_SOCKET_DISABLED);
    arv_camera_gv_set_packet_size(camera, PacketBytes, &error);
    problem = Refusal(error, "GevSCPSPacketSize = " + std::to_string(PacketBytes));
  }
  if (problem.empty())
  {
    arv_camera_clear_triggers(camera, &error);
    problem = Refusal(error, "TriggerMode = Off (clearing the triggers)");
  }
  if (problem.empty())
  {
    arv_camera_set_pixel_format_from_string(camera, format, &error);
    problem = Refusal(error, std::string("PixelFormat = ") + format);
  }
  if (problem.empty())
  {
    problem = SetBounded(camera,
      "ExposureTime",
      exposure,
      "us",
      &arv_camera_get_exposure_time_bounds,
      &arv_camera_set_exposure_time);
  }
  if (problem.empty())
  {
    problem =
      SetBounded(camera, "Gain", gain, "dB", &arv_camera_get_gain_bounds, &arv_camera_set_gain);
  }
  if (problem.empty())
  {
    arv_camera_set_acquisition_mode(camera, ARV_ACQUISITION_MODE_CONTINUOUS, &error);
    problem = Refusal(error, "AcquisitionMode = Continuous");
  }
  if (problem.empty())
  {
    arv_camera_set_trigger(camera, "Software", &error);
    problem = Refusal(error, "TriggerSource = Software");
  }
  if (problem.empty())
  {
    int x = 0, y = 0;
    arv_camera_get_region(camera, &x, &y, &frameSize[0], &frameSize[1], &error);
    problem = Refusal(error, "Width and Height (reading the frame size)");
  }
  return problem;
}
}

// The Aravis objects of an open camera.
struct vtkAravisCamera::Device
{
  ArvCamera* Camera = nullptr;
  ArvStream* Stream = nullptr;
  bool Acquiring = false;
  /// The camera stopped answering: closing does not ask it to stop (each
  /// request would wait for its GVCP timeouts and retries, seconds).
  bool Lost = false;
  /// Triggers sent whose frame has not arrived (see DiscardLateFrames).
  int Unanswered = 0;

  // Opens the stream, queues its buffers and starts the acquisition; the
  // problem in words, "" when it runs.
  std::string StartStream(const int frameSize[2])
  {
    GError* error = nullptr;
    const guint payload = arv_camera_get_payload(this->Camera, &error);
    if (error)
    {
      return Refusal(error,
        "PayloadSize (reading the frame's bytes for " + std::to_string(frameSize[0]) + " x " +
          std::to_string(frameSize[1]) + " pixels)");
    }
    this->Stream = arv_camera_create_stream(this->Camera, nullptr, nullptr, &error);
    if (!this->Stream)
    {
      return "cannot open its stream: " + Consume(error);
    }
    if (ARV_IS_GV_STREAM(this->Stream))
    {
      g_object_set(this->Stream,
        "socket-buffer",
        ARV_GV_STREAM_SOCKET_BUFFER_FIXED,
        "socket-buffer-size",
        SocketBufferBytes,
        nullptr);
    }
    for (int i = 0; i < StreamBuffers; ++i)
    {
      arv_stream_push_buffer(this->Stream, arv_buffer_new(payload, nullptr));
    }
    arv_camera_start_acquisition(this->Camera, &error);
    if (error)
    {
      return Refusal(error, "AcquisitionStart");
    }
    this->Acquiring = true;
    return std::string();
  }

  ~Device()
  {
    if (this->Acquiring && !this->Lost)
    {
      arv_camera_stop_acquisition(this->Camera, nullptr);
    }
    g_clear_object(&this->Stream);
    g_clear_object(&this->Camera);
  }
};

//------------------------------------------------------------------------------
vtkAravisCamera::vtkAravisCamera() = default;

//------------------------------------------------------------------------------
vtkAravisCamera::~vtkAravisCamera()
{
  this->Close();
}

//------------------------------------------------------------------------------
const char* vtkAravisCamera::GetPixelFormatName(int format)
{
  return format >= RGB8 && format <= MONO8
    ? lfd::PixelFormatName(static_cast<lfd::PixelFormat>(format))
    : nullptr;
}

//------------------------------------------------------------------------------
int vtkAravisCamera::GetPixelFormatFromName(const char* name)
{
  for (int format = RGB8; name && format <= MONO8; ++format)
  {
    if (std::string(name) == GetPixelFormatName(format))
    {
      return format;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
bool vtkAravisCamera::Open()
{
  this->Close();
  const std::string address = this->Address ? this->Address : "";
  if (address.empty())
  {
    vtkErrorMacro("Camera: no Address set (an IP address or an Aravis device id).");
    return false;
  }
  auto device = std::unique_ptr<Device>(new Device);
  GError* error = nullptr;
  device->Camera = arv_camera_new(address.c_str(), &error);
  if (!device->Camera)
  {
    vtkErrorMacro("Camera " << address << ": cannot connect: " << Consume(error));
    return false;
  }
  std::string problem = ConfigureCamera(device->Camera,
    GetPixelFormatName(this->PixelFormat),
    this->ExposureTime,
    this->Gain,
    this->FrameSize);
  if (problem.empty())
  {
    problem = device->StartStream(this->FrameSize);
  }
  if (!problem.empty())
  {
    vtkErrorMacro("Camera " << address << ": " << problem);
    return false;
  }
  this->NumberOfRetries = 0;
  this->NumberOfLateFrames = 0;
  this->Connection = std::move(device);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAravisCamera::Acquire(vtkImageData* frame)
{
  const std::string address = this->Address ? this->Address : "";
  if (!this->Connection)
  {
    vtkErrorMacro("Camera " << address << ": not open; call Open() first.");
    return false;
  }
  if (!frame)
  {
    vtkErrorMacro("Camera " << address << ": Acquire() needs an image to fill.");
    return false;
  }
  ArvCamera* camera = this->Connection->Camera;
  ArvStream* stream = this->Connection->Stream;
  std::string problem;
  this->DiscardLateFrames();
  for (int attempt = 0; attempt < this->MaximumAttempts; ++attempt)
  {
    if (attempt > 0)
    {
      ++this->NumberOfRetries;
    }
    GError* error = nullptr;
    arv_camera_software_trigger(camera, &error);
    if (error)
    {
      this->Connection->Lost = g_error_matches(error, ARV_DEVICE_ERROR, ARV_DEVICE_ERROR_TIMEOUT);
      vtkErrorMacro("Camera " << address << ": refuses TriggerSoftware: " << Consume(error));
      return false;
    }
    ++this->Connection->Unanswered;
    ArvBuffer* buffer =
      arv_stream_timeout_pop_buffer(stream, static_cast<guint64>(this->FrameTimeout) * 1000);
    if (!buffer)
    {
      problem = "no frame within " + std::to_string(this->FrameTimeout) + " ms";
      continue;
    }
    --this->Connection->Unanswered;
    const ArvBufferStatus status = arv_buffer_get_status(buffer);
    if (status != ARV_BUFFER_STATUS_SUCCESS)
    {
      problem = std::string("frame ") + StatusName(status);
      arv_stream_push_buffer(stream, buffer);
      continue;
    }
    const int width = arv_buffer_get_image_width(buffer);
    const int height = arv_buffer_get_image_height(buffer);
    size_t size = 0;
    const auto* data = static_cast<const unsigned char*>(arv_buffer_get_image_data(buffer, &size));
    const auto wire = static_cast<lfd::PixelFormat>(this->PixelFormat);
    if (arv_buffer_get_image_pixel_format(buffer) != lfd::PixelFormatCode(wire) ||
      size < static_cast<size_t>(width) * height * lfd::PixelFormatBytes(wire))
    {
      arv_stream_push_buffer(stream, buffer);
      vtkErrorMacro("Camera " << address << ": sent a frame of " << width << " x " << height
                              << " pixels in " << size << " bytes, not "
                              << GetPixelFormatName(this->PixelFormat));
      return false;
    }
    frame->SetDimensions(width, height, 1);
    frame->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    lfd::DecodePixels(
      data, width, height, wire, static_cast<unsigned char*>(frame->GetScalarPointer()));
    frame->GetPointData()->GetScalars()->SetName("RGB");
    arv_stream_push_buffer(stream, buffer);
    return true;
  }
  vtkErrorMacro("Camera " << address << ": no good frame after " << this->MaximumAttempts
                          << (this->MaximumAttempts == 1 ? " attempt" : " attempts")
                          << " (last: " << problem << ")");
  return false;
}

//------------------------------------------------------------------------------
void vtkAravisCamera::DiscardLateFrames()
{
  ArvStream* stream = this->Connection->Stream;
  // Frames already queued first, then the answers still owed to triggers
  // given up on: a slow camera sends them after its attempt timed out. A
  // frame that does not come within FrameTimeout was lost: owed no more.
  while (ArvBuffer* late = arv_stream_try_pop_buffer(stream))
  {
    arv_stream_push_buffer(stream, late);
    this->Connection->Unanswered = std::max(0, this->Connection->Unanswered - 1);
    ++this->NumberOfLateFrames;
  }
  while (this->Connection->Unanswered > 0)
  {
    ArvBuffer* late =
      arv_stream_timeout_pop_buffer(stream, static_cast<guint64>(this->FrameTimeout) * 1000);
    if (!late)
    {
      this->Connection->Unanswered = 0;
      break;
    }
    arv_stream_push_buffer(stream, late);
    --this->Connection->Unanswered;
    ++this->NumberOfLateFrames;
  }
}

//------------------------------------------------------------------------------
void vtkAravisCamera::Close()
{
  this->Connection.reset();
}

//------------------------------------------------------------------------------
void vtkAravisCamera::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PixelFormat: " << GetPixelFormatName(this->PixelFormat) << "\n";
  os << indent << "FrameTimeout: " << this->FrameTimeout << " ms\n";
  os << indent << "MaximumAttempts: " << this->MaximumAttempts << "\n";
  os << indent << "NumberOfRetries: " << this->NumberOfRetries << "\n";
  os << indent << "NumberOfLateFrames: " << this->NumberOfLateFrames << "\n";
  os << indent << "FrameSize: " << this->FrameSize[0] << " x " << this->FrameSize[1] << "\n";
  os << indent << "Open: " << (this->Connection ? "yes" : "no") << "\n";
}

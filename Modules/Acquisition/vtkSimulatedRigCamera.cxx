#include "vtkSimulatedRigCamera.h"

#include "lfdPinholeCamera.h"
#include "lfdPixelFormat.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <arv.h>
#include <glm/gtc/matrix_transform.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

vtkStandardNewMacro(vtkSimulatedRigCamera);
vtkCxxSetObjectMacro(vtkSimulatedRigCamera, Rig, vtkCameraRig);
vtkCxxSetObjectMacro(vtkSimulatedRigCamera, Projectors, vtkCameraRig);

namespace
{
// How long Aravis's thread waits for a render before it drops the frame:
// far above a render of a few hundred milliseconds under llvmpipe.
constexpr auto RenderDeadline = std::chrono::seconds(20);
// Lost-packet ratio of a damaged frame: of a frame's hundreds of packets
// some are lost, yet most arrive, so the client sees an incomplete frame.
constexpr double DamagedFrameLoss = 0.5;

// The camera of `rig`'s view `home` turned by `degrees` about the rig's
// cylinder axis (right-handed): the centre moves on the circle, the
// orientation turns with it.
lfd::PinholeCamera TurnedCamera(vtkCameraRig* rig, int home, double degrees)
{
  const double* a = rig->GetAxis();
  const double* c = rig->GetCenter();
  const glm::dvec3 axis(a[0], a[1], a[2]);
  const glm::dvec3 centre(c[0], c[1], c[2]);
  const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis));
  lfd::PinholeCamera camera = rig->GetCamera(home);
  const glm::dvec3 position = centre + turn * (camera.Center() - centre);
  camera.R = camera.R * glm::transpose(turn);
  camera.t = -(camera.R * position);
  return camera;
}

// Whether no one listens on the GVCP port of `address`. Aravis's fake camera
// binds it with SO_REUSEADDR, so a second one would start and share the
// port with the first; a plain bind fails when any socket holds it.
bool GvcpPortFree(const char* address)
{
  sockaddr_in gvcp{};
  gvcp.sin_family = AF_INET;
  gvcp.sin_port = htons(3956);
  if (inet_pton(AF_INET, address, &gvcp.sin_addr) != 1)
  {
    return true; // not an IPv4 address: Aravis says so
  }
  // Only "in use" means taken: an address that is not local is Aravis's to
  // report.
  const int probe = socket(AF_INET, SOCK_DGRAM, 0);
  const bool free = probe < 0 ||
    bind(probe, reinterpret_cast<sockaddr*>(&gvcp), sizeof(gvcp)) == 0 || errno != EADDRINUSE;
  if (probe >= 0)
  {
    close(probe);
  }
  return free;
}
}

// The state shared by the caller's thread (lights, faults), Aravis's thread
// (the frame callback) and the render thread, under one mutex.
struct vtkSimulatedRigCamera::Internals
{
  vtkNew<vtkLightFieldCapture> Capture;
  std::mutex Mutex;
  std::condition_variable Wake;
  std::thread Renderer;
  ArvGvFakeCamera* Fake = nullptr;
  bool Running = false;
  bool Stopping = false;
  // Frame requests of the callback and the render thread's answers.
  unsigned long long Requested = 0;
  unsigned long long Rendered = 0;
  std::vector<unsigned char> Frame; // RGB, top row first
  bool FrameOk = false;
  int FramesRendered = 0;
  // What the next frame is rendered under, copied by the render thread.
  struct Lights
  {
    bool Coaxial = false;
    std::vector<vtkSmartPointer<vtkImageData>> Patterns;
    std::function<bool(double&)> AngleSource;
    std::function<bool()> CoaxialSource;
  };
  Lights Current;
  // Faults still to come.
  int Drop = 0;
  int Damage = 0;
  int Delay = 0;
  int DelayMilliseconds = 0;

  static void Fill(ArvBuffer* buffer, void* data, guint32, guint32, ArvPixelFormat format);
  void RenderLoop(vtkSimulatedRigCamera* owner);
  // Renders the lit passes of the view at the current angle into `sum` (RGB,
  // top row first); false, with an error, when there is no frame to send.
  bool RenderFrame(vtkSimulatedRigCamera* owner,
    const Lights& lights,
    vtkLightFieldErrorObserver* errors,
    std::vector<int>& sum);
};

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::Internals::Fill(ArvBuffer* buffer,
  void* data,
  guint32,
  guint32,
  ArvPixelFormat format)
{
  auto* self = static_cast<vtkSimulatedRigCamera::Internals*>(data);
  const size_t width = arv_buffer_get_image_width(buffer);
  const size_t height = arv_buffer_get_image_height(buffer);
  auto* pixels =
    static_cast<unsigned char*>(const_cast<void*>(arv_buffer_get_data(buffer, nullptr)));
  std::unique_lock<std::mutex> lock(self->Mutex);
  if (self->Stopping)
  {
    return;
  }
  if (self->Delay > 0)
  {
    // A slow camera: the frame comes, late. Triggers that arrive meanwhile
    // wait in the fake camera's queue, each answered in turn.
    --self->Delay;
    const auto delay = std::chrono::milliseconds(self->DelayMilliseconds);
    self->Wake.wait_for(lock, delay, [self] { return self->Stopping; });
    if (self->Stopping)
    {
      return;
    }
  }
  // The fault decides how many of this frame's packets the camera sends.
  double loss = 0.0;
  if (self->Drop > 0)
  {
    --self->Drop;
    loss = 1.0;
  }
  else if (self->Damage > 0)
  {
    --self->Damage;
    loss = DamagedFrameLoss;
  }
  g_object_set(self->Fake, "gvsp-lost-ratio", loss, nullptr);
  std::memset(pixels, 0, width * height * ARV_PIXEL_FORMAT_BIT_PER_PIXEL(format) / 8);
  const int rendered = lfd::PixelFormatFromCode(format);
  if (loss >= 1.0 || rendered < 0)
  {
    return;
  }
  const unsigned long long request = ++self->Requested;
  self->Wake.notify_all();
  const bool answered = self->Wake.wait_for(
    lock, RenderDeadline, [self, request] { return self->Rendered >= request || self->Stopping; });
  if (self->Stopping)
  {
    return;
  }
  if (!answered || !self->FrameOk || self->Frame.size() != 3 * width * height)
  {
    // No image (a failed render, a client asking for another size): the
    // frame is lost, as a camera's would be.
    g_object_set(self->Fake, "gvsp-lost-ratio", 1.0, nullptr);
    return;
  }
  lfd::EncodePixels(
    self->Frame.data(), width, height, static_cast<lfd::PixelFormat>(rendered), pixels);
}

namespace
{
// Adds the pass `pass` of the capture's one-view output (bottom row first)
// to `sum` (top row first).
void AddPass(vtkLightFieldCapture* capture, int pass, int width, int height, std::vector<int>& sum)
{
  vtkDataArray* image = capture->GetOutput()->GetPass(pass);
  const auto* bytes = static_cast<const unsigned char*>(image->GetVoidPointer(0));
  for (int y = 0; y < height; ++y)
  {
    const unsigned char* row = bytes + 3 * static_cast<size_t>(height - 1 - y) * width;
    for (int i = 0; i < 3 * width; ++i)
    {
      sum[3 * static_cast<size_t>(y) * width + i] += row[i];
    }
  }
}

// The projectors that show a pattern, as a rig, and their patterns as the
// mask stack of a Coded pass; false when all are dark.
bool LitProjectors(vtkCameraRig* projectors,
  const std::vector<vtkSmartPointer<vtkImageData>>& patterns,
  vtkCameraRig* lit,
  vtkImageData* masks)
{
  std::vector<int> shown;
  for (size_t p = 0; p < patterns.size(); ++p)
  {
    if (patterns[p])
    {
      shown.push_back(static_cast<int>(p));
    }
  }
  if (shown.empty())
  {
    return false;
  }
  const int* size = projectors->GetImageSize();
  lit->SetNumberOfViews(static_cast<int>(shown.size()));
  lit->SetImageSize(size[0], size[1]);
  masks->SetDimensions(size[0], size[1], static_cast<int>(shown.size()));
  masks->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const size_t slice = 3 * static_cast<size_t>(size[0]) * size[1];
  for (size_t i = 0; i < shown.size(); ++i)
  {
    lit->SetView(static_cast<int>(i), projectors->GetCamera(shown[i]));
    std::memcpy(static_cast<unsigned char*>(masks->GetScalarPointer()) + i * slice,
      patterns[shown[i]]->GetScalarPointer(),
      slice);
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkSimulatedRigCamera::Internals::RenderFrame(vtkSimulatedRigCamera* owner,
  const Lights& lights,
  vtkLightFieldErrorObserver* errors,
  std::vector<int>& sum)
{
  const int width = owner->Rig->GetImageSize()[0];
  const int height = owner->Rig->GetImageSize()[1];
  std::fill(sum.begin(), sum.end(), 0);
  double angle = owner->Angle;
  if (lights.AngleSource && !lights.AngleSource(angle))
  {
    vtkErrorWithObjectMacro(owner,
      "Simulated camera " << owner->Address
                          << ": the angle source gave no gantry "
                             "angle; the frame is dropped.");
    return false;
  }
  // The camera where the gantry has turned it; the passes of one view.
  vtkNew<vtkCameraRig> view;
  view->SetNumberOfViews(1);
  view->SetImageSize(width, height);
  view->SetView(0, TurnedCamera(owner->Rig, owner->HomeView, angle));
  vtkLightFieldCapture* capture = this->Capture;
  capture->SetRig(view);
  capture->CaptureLabelOff();
  capture->CaptureDepthOff();
  capture->SetProjectorNoise(0.0);
  errors->Clear();
  if (lights.CoaxialSource ? lights.CoaxialSource() : lights.Coaxial)
  {
    capture->CaptureCoaxialOn();
    capture->SetProjectors(nullptr);
    capture->SetNumberOfProjectors(0);
    capture->SetProjectorMasks(nullptr);
    capture->Update();
    if (!errors->HasError())
    {
      AddPass(capture, vtkLightField::COAXIAL, width, height, sum);
    }
  }
  vtkNew<vtkCameraRig> lit;
  vtkNew<vtkImageData> masks;
  if (!errors->HasError() && LitProjectors(owner->Projectors, lights.Patterns, lit, masks))
  {
    capture->CaptureCoaxialOff();
    capture->SetProjectors(lit);
    capture->SetProjectorMasks(masks);
    capture->Update();
    if (!errors->HasError())
    {
      AddPass(capture, vtkLightField::CODED, width, height, sum);
    }
  }
  if (errors->HasError())
  {
    vtkErrorWithObjectMacro(owner,
      "Simulated camera " << owner->Address
                          << ": cannot render the frame: " << errors->GetErrorMessage());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::Internals::RenderLoop(vtkSimulatedRigCamera* owner)
{
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->ObservePipeline(this->Capture);
  std::mt19937 random(static_cast<unsigned int>(owner->NoiseSeed));
  std::normal_distribution<double> noise(0.0, owner->SensorNoise);
  const int* size = owner->Rig->GetImageSize();
  std::vector<int> sum(3 * static_cast<size_t>(size[0]) * size[1]);
  std::vector<unsigned char> frame(sum.size());
  for (;;)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Wake.wait(lock, [this] { return this->Requested > this->Rendered || this->Stopping; });
    if (this->Stopping)
    {
      return;
    }
    const unsigned long long request = this->Requested;
    const Lights lights = this->Current;
    lock.unlock();

    const bool ok = this->RenderFrame(owner, lights, errors, sum);
    // The sensor: lights add up, noise, 8 bits.
    for (size_t i = 0; i < sum.size(); ++i)
    {
      const double value = sum[i] + (owner->SensorNoise > 0.0 ? noise(random) : 0.0);
      frame[i] = static_cast<unsigned char>(std::lround(std::min(255.0, std::max(0.0, value))));
    }

    lock.lock();
    this->Frame = frame;
    this->FrameOk = ok;
    this->Rendered = request;
    this->FramesRendered += ok ? 1 : 0;
    this->Wake.notify_all();
  }
}

//------------------------------------------------------------------------------
vtkSimulatedRigCamera::vtkSimulatedRigCamera()
  : Internal(new Internals)
{
  this->SetAddress("127.0.0.1");
  this->SetSerialNumber("LFD-SIM");
}

//------------------------------------------------------------------------------
vtkSimulatedRigCamera::~vtkSimulatedRigCamera()
{
  this->Stop();
  this->SetAddress(nullptr);
  this->SetSerialNumber(nullptr);
  this->SetRig(nullptr);
  this->SetProjectors(nullptr);
}

//------------------------------------------------------------------------------
vtkLightFieldCapture* vtkSimulatedRigCamera::GetCapture()
{
  return this->Internal->Capture;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::SetAngleSource(std::function<bool(double&)> source)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Current.AngleSource = std::move(source);
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::SetCoaxialLight(bool on)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Current.Coaxial = on;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::SetCoaxialLightSource(std::function<bool()> source)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Current.CoaxialSource = std::move(source);
}

//------------------------------------------------------------------------------
bool vtkSimulatedRigCamera::GetCoaxialLight()
{
  std::function<bool()> source;
  {
    std::lock_guard<std::mutex> lock(this->Internal->Mutex);
    if (!this->Internal->Current.CoaxialSource)
    {
      return this->Internal->Current.Coaxial;
    }
    source = this->Internal->Current.CoaxialSource;
  }
  return source();
}

//------------------------------------------------------------------------------
int vtkSimulatedRigCamera::GetNumberOfLitProjectors()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  int lit = 0;
  for (const vtkSmartPointer<vtkImageData>& pattern : this->Internal->Current.Patterns)
  {
    vtkDataArray* scalars = pattern ? pattern->GetPointData()->GetScalars() : nullptr;
    const auto* bytes =
      scalars ? static_cast<const unsigned char*>(scalars->GetVoidPointer(0)) : nullptr;
    const vtkIdType size = scalars ? scalars->GetNumberOfValues() : 0;
    lit += std::any_of(bytes, bytes + size, [](unsigned char value) { return value != 0; }) ? 1 : 0;
  }
  return lit;
}

//------------------------------------------------------------------------------
bool vtkSimulatedRigCamera::SetProjectorPattern(int projector, vtkImageData* pattern)
{
  const int count = this->Projectors ? this->Projectors->GetNumberOfViews() : 0;
  if (projector < 0 || projector >= count)
  {
    vtkErrorMacro("Simulated camera " << this->Address << ": there is no projector " << projector
                                      << " (the simulated rig has " << count << ").");
    return false;
  }
  vtkSmartPointer<vtkImageData> copy;
  if (pattern)
  {
    const int* size = this->Projectors->GetImageSize();
    const int* dims = pattern->GetDimensions();
    vtkDataArray* scalars = pattern->GetPointData()->GetScalars();
    if (dims[0] != size[0] || dims[1] != size[1] || dims[2] != 1 || !scalars ||
      scalars->GetDataType() != VTK_UNSIGNED_CHAR || scalars->GetNumberOfComponents() != 3)
    {
      vtkErrorMacro("Simulated camera "
        << this->Address << ": projector " << projector << " shows RGB uint8 patterns of "
        << size[0] << " x " << size[1] << " pixels; the pattern is " << dims[0] << " x " << dims[1]
        << " x " << dims[2] << (scalars ? "" : " without scalars") << ".");
      return false;
    }
    copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(pattern);
  }
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Current.Patterns.resize(count);
  this->Internal->Current.Patterns[projector] = copy;
  return true;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::DropFrames(int count)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Drop = std::max(0, count);
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::DamageFrames(int count)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Damage = std::max(0, count);
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::DelayFrames(int count, int milliseconds)
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Delay = std::max(0, count);
  this->Internal->DelayMilliseconds = std::max(0, milliseconds);
}

//------------------------------------------------------------------------------
bool vtkSimulatedRigCamera::Start()
{
  this->Stop();
  const char* address = this->Address ? this->Address : "(none)";
  if (!this->Rig || this->HomeView >= this->Rig->GetNumberOfViews() || !this->Rig->HasCylinder())
  {
    vtkErrorMacro("Simulated camera " << address
                                      << ": needs a rig with a fitted cylinder (the gantry axis) "
                                         "and its view HomeView "
                                      << this->HomeView << " (the camera at angle 0).");
    return false;
  }
  if (this->Internal->Capture->GetNumberOfInputConnections(0) == 0)
  {
    vtkErrorMacro(
      "Simulated camera " << address << ": nothing to photograph; connect a mesh to GetCapture().");
    return false;
  }
  if (!GvcpPortFree(this->Address))
  {
    vtkErrorMacro("Simulated camera " << address
                                      << ": the GVCP port 3956 of this address is taken (another "
                                         "camera serves there).");
    return false;
  }
  Internals& internal = *this->Internal;
  internal.Fake = arv_gv_fake_camera_new(this->Address, this->SerialNumber);
  if (!internal.Fake || !arv_gv_fake_camera_is_running(internal.Fake))
  {
    g_clear_object(&internal.Fake);
    vtkErrorMacro("Simulated camera " << address
                                      << ": cannot serve GigE Vision there (not a local IPv4 "
                                         "address).");
    return false;
  }
  ArvFakeCamera* sensor = arv_gv_fake_camera_get_fake_camera(internal.Fake);
  const int* size = this->Rig->GetImageSize();
  arv_fake_camera_write_register(sensor, ARV_FAKE_CAMERA_REGISTER_SENSOR_WIDTH, size[0]);
  arv_fake_camera_write_register(sensor, ARV_FAKE_CAMERA_REGISTER_SENSOR_HEIGHT, size[1]);
  arv_fake_camera_write_register(sensor, ARV_FAKE_CAMERA_REGISTER_WIDTH, size[0]);
  arv_fake_camera_write_register(sensor, ARV_FAKE_CAMERA_REGISTER_HEIGHT, size[1]);
  {
    std::lock_guard<std::mutex> lock(internal.Mutex);
    internal.Stopping = false;
    internal.Requested = 0;
    internal.Rendered = 0;
    internal.FramesRendered = 0;
    internal.Current.Patterns.resize(this->Projectors ? this->Projectors->GetNumberOfViews() : 0);
  }
  internal.Renderer = std::thread([this] { this->Internal->RenderLoop(this); });
  arv_fake_camera_set_fill_pattern(sensor, &Internals::Fill, &internal);
  internal.Running = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::Stop()
{
  Internals& internal = *this->Internal;
  // Stopping first: a frame callback still running in Aravis's thread then
  // neither waits for a render nor touches the camera being finalized.
  {
    std::lock_guard<std::mutex> lock(internal.Mutex);
    internal.Stopping = true;
  }
  internal.Wake.notify_all();
  if (internal.Fake)
  {
    g_object_unref(internal.Fake);
    internal.Fake = nullptr;
  }
  if (internal.Renderer.joinable())
  {
    internal.Renderer.join();
  }
  internal.Running = false;
}

//------------------------------------------------------------------------------
bool vtkSimulatedRigCamera::IsRunning()
{
  return this->Internal->Running;
}

//------------------------------------------------------------------------------
int vtkSimulatedRigCamera::GetNumberOfFramesRendered()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->FramesRendered;
}

//------------------------------------------------------------------------------
void vtkSimulatedRigCamera::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Address: " << (this->Address ? this->Address : "(none)") << "\n";
  os << indent << "SerialNumber: " << (this->SerialNumber ? this->SerialNumber : "(none)") << "\n";
  os << indent << "Rig: " << (this->Rig ? "set" : "(none)") << "\n";
  os << indent << "HomeView: " << this->HomeView << "\n";
  os << indent << "Projectors: " << (this->Projectors ? this->Projectors->GetNumberOfViews() : 0)
     << "\n";
  os << indent << "Angle: " << this->Angle << " degrees\n";
  os << indent << "SensorNoise: " << this->SensorNoise << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
  os << indent << "CoaxialLight: " << this->GetCoaxialLight() << "\n";
  os << indent << "Running: " << this->IsRunning() << "\n";
}

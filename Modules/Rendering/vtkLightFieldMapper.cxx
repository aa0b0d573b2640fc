#include "vtkLightFieldMapper.h"
#include "lfdPerspectiveDepth.h"

#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldRenderer.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkLightFieldMapper);

namespace
{
/// Draws the light-field image and writes its depth; background is discarded.
const char* const FragmentShader = R"GLSL(//VTK::System::Dec
//VTK::Output::Dec
in vec2 texCoord;
uniform sampler2D colorTexture;
uniform sampler2D depthTexture;
void main()
{
  vec4 color = texture(colorTexture, texCoord);
  if (color.a < 0.5)
  {
    discard;
  }
  gl_FragData[0] = vec4(color.rgb, 1.0);
  gl_FragDepth = texture(depthTexture, texCoord).r;
}
)GLSL";
}

struct vtkLightFieldMapper::Internals
{
  vtkNew<vtkLightFieldRenderer> Renderer;
  vtkNew<vtkLightFieldErrorObserver> Errors;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkNew<vtkTextureObject> Color;
  vtkNew<vtkTextureObject> Depth;
  std::vector<unsigned char> Rgba;
  vtkNew<vtkImageData> WindowDepth; ///< GetDepthImage()
};

//------------------------------------------------------------------------------
vtkLightFieldMapper::vtkLightFieldMapper()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(0);
  this->Internal->Errors->Observe(this->Internal->Renderer);
}

//------------------------------------------------------------------------------
vtkLightFieldMapper::~vtkLightFieldMapper() = default;

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetInputData(vtkDataObject* lightField)
{
  this->SetInputDataInternal(0, lightField);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetCageConnection(vtkAlgorithmOutput* output)
{
  this->Superclass::SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetCageData(vtkDataObject* cage)
{
  this->SetInputDataInternal(1, cage);
}

//------------------------------------------------------------------------------
vtkLightFieldRenderer* vtkLightFieldMapper::GetLightFieldRenderer()
{
  return this->Internal->Renderer;
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldMapper::GetDepthImage()
{
  return this->Internal->WindowDepth;
}

//------------------------------------------------------------------------------
int vtkLightFieldMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
double* vtkLightFieldMapper::GetBounds()
{
  vtkMath::UninitializeBounds(this->Bounds);
  if (this->GetNumberOfInputConnections(0) == 0)
  {
    return this->Bounds;
  }
  // The inputs as they are: asking for bounds runs no pipeline and fits no
  // rig (a vtkRenderer asks before every render).
  vtkLightField* lightField = vtkLightField::SafeDownCast(this->GetInputDataObject(0, 0));
  vtkCameraRig* rig = lightField ? lightField->GetRig() : nullptr;
  if (!rig || !rig->HasCylinder())
  {
    return this->Bounds;
  }
  const double* center = rig->GetCenter();
  const double half = 0.5 * rig->GetRadius();
  for (int a = 0; a < 3; ++a)
  {
    this->Bounds[2 * a] = center[a] - half;
    this->Bounds[2 * a + 1] = center[a] + half;
  }
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    if (auto* cage = vtkUnstructuredGrid::SafeDownCast(this->GetInputDataObject(1, 0)))
    {
      const double* cageBounds = cage->GetBounds();
      for (int a = 0; a < 3 && cage->GetNumberOfPoints() > 0; ++a)
      {
        this->Bounds[2 * a] = std::min(this->Bounds[2 * a], cageBounds[2 * a]);
        this->Bounds[2 * a + 1] = std::max(this->Bounds[2 * a + 1], cageBounds[2 * a + 1]);
      }
    }
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::Render(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window || this->GetNumberOfInputConnections(0) == 0)
  {
    return;
  }
  Internals& in = *this->Internal;
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  const bool interactive = window->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
  const int subsampling = interactive ? this->InteractiveSubsampling : 1;
  const int width = std::max(1, size[0] / subsampling);
  const int height = std::max(1, size[1] / subsampling);

  // The view of the active camera; the pipeline recomputes it only when the
  // camera, the cage, the light field or the size changed.
  vtkLightFieldRenderer* view = in.Renderer;
  view->SetInputConnection(0, this->GetInputConnection(0, 0));
  view->SetInputConnection(
    1, this->GetNumberOfInputConnections(1) > 0 ? this->GetInputConnection(1, 0) : nullptr);
  view->SetCamera(renderer->GetActiveCamera());
  view->SetWidth(width);
  view->SetHeight(height);
  view->Update();
  if (in.Errors->HasError())
  {
    // The renderer's error is said once, as the mapper's own.
    vtkErrorMacro(<< in.Errors->GetErrorMessage());
    in.Errors->Clear();
  }
  vtkImageData* image = view->GetOutput();
  auto* colors = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  auto* depths = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("Depth"));
  if (!colors || !depths)
  {
    return;
  }
  this->LastImageSize[0] = width;
  this->LastImageSize[1] = height;

  // Camera z -> window depth of the perspective projection (clipping range
  // n, f); no ray: the far plane.
  double range[2];
  renderer->GetActiveCamera()->GetClippingRange(range);
  const double n = range[0], f = range[1];
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  in.Rgba.resize(4 * pixels);
  int* dimensions = in.WindowDepth->GetDimensions();
  if (dimensions[0] != width || dimensions[1] != height)
  {
    in.WindowDepth->SetDimensions(width, height, 1);
    in.WindowDepth->AllocateScalars(VTK_FLOAT, 1);
    in.WindowDepth->GetPointData()->GetScalars()->SetName("Depth");
  }
  auto* windowDepth = vtkFloatArray::SafeDownCast(in.WindowDepth->GetPointData()->GetScalars());
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const double z = depths->GetValue(p);
    std::copy(colors->GetPointer(3 * p), colors->GetPointer(3 * p) + 3, &in.Rgba[4 * p]);
    in.Rgba[4 * p + 3] = z > 0.0 ? 255 : 0;
    const double window = z > 0.0 ? lfd::DistanceToWindowDepth(z, n, f) : 1.0;
    windowDepth->SetValue(p, static_cast<float>(std::clamp(window, 0.0, 1.0)));
  }
  windowDepth->Modified();
  in.WindowDepth->Modified();

  in.Color->SetContext(window);
  in.Color->Create2DFromRaw(width, height, 4, VTK_UNSIGNED_CHAR, in.Rgba.data());
  in.Color->SetMinificationFilter(vtkTextureObject::Linear);
  in.Color->SetMagnificationFilter(vtkTextureObject::Linear);
  in.Depth->SetContext(window);
  in.Depth->Create2DFromRaw(width, height, 1, VTK_FLOAT, windowDepth->GetPointer(0));
  in.Depth->SetMinificationFilter(vtkTextureObject::Nearest);
  in.Depth->SetMagnificationFilter(vtkTextureObject::Nearest);

  if (!in.Quad)
  {
    in.Quad.reset(new vtkOpenGLQuadHelper(window,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
      FragmentShader,
      ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.Quad->Program);
  }
  if (!in.Quad->Program || !in.Quad->Program->GetCompiled())
  {
    vtkErrorMacro("Could not compile the light-field shader.");
    return;
  }
  vtkOpenGLState* state = window->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LEQUAL);
  in.Color->Activate();
  in.Depth->Activate();
  in.Quad->Program->SetUniformi("colorTexture", in.Color->GetTextureUnit());
  in.Quad->Program->SetUniformi("depthTexture", in.Depth->GetTextureUnit());
  in.Quad->Render();
  in.Depth->Deactivate();
  in.Color->Deactivate();
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Quad.reset();
  this->Internal->Color->ReleaseGraphicsResources(window);
  this->Internal->Depth->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveSubsampling: " << this->InteractiveSubsampling << "\n";
  os << indent << "LastImageSize: " << this->LastImageSize[0] << " x " << this->LastImageSize[1]
     << "\n";
}

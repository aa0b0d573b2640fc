#include "vtkLightFieldAlgorithm.h"

#include "lfdExceptions.h"
#include "vtkCameraRig.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

vtkStandardNewMacro(vtkLightFieldAlgorithm);

//------------------------------------------------------------------------------
vtkLightFieldAlgorithm::vtkLightFieldAlgorithm()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldAlgorithm::~vtkLightFieldAlgorithm() = default;

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldAlgorithm::GetOutput()
{
  return this->GetOutput(0);
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightFieldAlgorithm::GetOutput(int port)
{
  return vtkLightField::SafeDownCast(this->GetOutputDataObject(port));
}

//------------------------------------------------------------------------------
vtkTypeBool vtkLightFieldAlgorithm::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  try
  {
    return this->DispatchRequest(request, inputVector, outputVector);
  }
  catch (...)
  {
    // An exception must not cross the pipeline into Python or a front end:
    // it becomes this algorithm's error like any other failure.
    vtkInformation* outInfo =
      this->GetNumberOfOutputPorts() > 0 ? outputVector->GetInformationObject(0) : nullptr;
    this->Fail(outInfo ? vtkLightField::GetData(outInfo) : nullptr,
      vtkErrorCode::UnknownError,
      this->DescribeFailure(lfd::CurrentExceptionMessage()));
    return 0;
  }
}

//------------------------------------------------------------------------------
std::string vtkLightFieldAlgorithm::DescribeFailure(const std::string& problem)
{
  return std::string(this->GetClassName()) + ": " + problem;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkLightFieldAlgorithm::DispatchRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    return this->RequestInformation(request, inputVector, outputVector);
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    return this->RequestUpdateExtent(request, inputVector, outputVector);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::RequestDataObject(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    if (!vtkLightField::GetData(outInfo))
    {
      vtkNew<vtkLightField> output;
      outInfo->Set(vtkDataObject::DATA_OBJECT(), output);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldAlgorithm::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldAlgorithm::SetOutputLayout(vtkInformationVector* outputVector,
  int width,
  int height,
  int views)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, width - 1, 0, height - 1, 0, views - 1 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
}

//------------------------------------------------------------------------------
void vtkLightFieldAlgorithm::Fail(vtkLightField* output,
  unsigned long errorCode,
  const std::string& message)
{
  if (output)
  {
    output->Initialize();
  }
  this->SetErrorCode(errorCode);
  vtkErrorMacro(<< message);
}

//------------------------------------------------------------------------------
void vtkLightFieldAlgorithm::ClearError()
{
  this->SetErrorCode(vtkErrorCode::NoError);
}

//------------------------------------------------------------------------------
void vtkLightFieldAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

#include "vtkLightFieldSplitter.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkStreamingDemandDrivenPipeline.h"

//------------------------------------------------------------------------------
vtkLightFieldSplitter::vtkLightFieldSplitter()
{
  this->SetNumberOfInputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightFieldSplitter::~vtkLightFieldSplitter() = default;

//------------------------------------------------------------------------------
void vtkLightFieldSplitter::SetInputData(vtkLightField* input)
{
  this->SetInputDataObject(0, input);
}

//------------------------------------------------------------------------------
int vtkLightFieldSplitter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkLightField");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldSplitter::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(),
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
      6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldSplitter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->ClearError();
  vtkLightField* input = vtkLightField::GetData(inputVector[0]);
  vtkLightField* output = vtkLightField::GetData(outputVector);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    this->Fail(output,
      vtkErrorCode::UnknownError,
      this->GetClassName() + std::string(": the input light field is empty"));
    return 0;
  }
  output->ShallowCopy(input);
  std::string error;
  if (!this->Split(input, output, error))
  {
    this->Fail(output, vtkErrorCode::UnknownError, error);
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldSplitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

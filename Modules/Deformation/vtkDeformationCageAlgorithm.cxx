#include "vtkDeformationCageAlgorithm.h"

#include "lfdRequestGuard.h"
#include "vtkDeformationCage.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"

//------------------------------------------------------------------------------
vtkDeformationCageAlgorithm::vtkDeformationCageAlgorithm()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkDeformationCageAlgorithm::~vtkDeformationCageAlgorithm() = default;

//------------------------------------------------------------------------------
void vtkDeformationCageAlgorithm::SetInputData(vtkDataObject* input)
{
  this->SetInputDataObject(0, input);
}

//------------------------------------------------------------------------------
vtkDeformationCage* vtkDeformationCageAlgorithm::GetOutput()
{
  return vtkDeformationCage::SafeDownCast(this->GetOutputDataObject(0));
}

//------------------------------------------------------------------------------
vtkTypeBool vtkDeformationCageAlgorithm::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return lfd::GuardRequest(
    this,
    [&]
    {
      if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
      {
        return this->RequestDataObject(request, inputVector, outputVector);
      }
      if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
      {
        return this->RequestData(request, inputVector, outputVector);
      }
      return static_cast<int>(this->Superclass::ProcessRequest(request, inputVector, outputVector));
    },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

//------------------------------------------------------------------------------
int vtkDeformationCageAlgorithm::RequestDataObject(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  if (!vtkDeformationCage::GetData(info))
  {
    vtkNew<vtkDeformationCage> cage;
    info->Set(vtkDataObject::DATA_OBJECT(), cage);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDeformationCageAlgorithm::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkDeformationCageAlgorithm::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDeformationCage");
  return 1;
}

//------------------------------------------------------------------------------
void vtkDeformationCageAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

#include "vtkLightField.h"

#include "lfdHugePages.h"

#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightFieldTexelSource.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

vtkStandardNewMacro(vtkLightField);

namespace
{
const char* const PassNames[vtkLightField::NUMBER_OF_PASSES] = { "Coaxial",
  "Coded",
  "Flood",
  "Label",
  "Depth",
  "Confidence" };
}

//------------------------------------------------------------------------------
vtkLightField::vtkLightField()
{
  this->Rig = vtkCameraRig::New();
  this->Projectors = vtkCameraRig::New();
}

//------------------------------------------------------------------------------
vtkLightField::~vtkLightField()
{
  this->SetRig(nullptr);
  this->SetProjectors(nullptr);
  this->SetProjectorMasks(nullptr);
  this->SetTexelSource(nullptr);
  this->SetProvenance(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkLightField, TexelSource, vtkLightFieldTexelSource);
vtkCxxSetObjectMacro(vtkLightField, Rig, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightField, Projectors, vtkCameraRig);
vtkCxxSetObjectMacro(vtkLightField, ProjectorMasks, vtkImageData);

//------------------------------------------------------------------------------
vtkMTimeType vtkLightField::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (vtkObject* part :
    { static_cast<vtkObject*>(this->Rig), static_cast<vtkObject*>(this->Projectors) })
  {
    if (part)
    {
      time = std::max(time, part->GetMTime());
    }
  }
  return time;
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkLightField::GetPalette()
{
  auto* palette =
    vtkUnsignedCharArray::SafeDownCast(this->GetFieldData()->GetAbstractArray("LabelPalette"));
  return palette && palette->GetNumberOfComponents() == 3 ? palette : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightField::SetPalette(vtkUnsignedCharArray* palette)
{
  this->GetFieldData()->RemoveArray("LabelPalette");
  if (palette)
  {
    palette->SetName("LabelPalette");
    this->GetFieldData()->AddArray(palette);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkLightField::GetPassName(int pass)
{
  return (pass >= 0 && pass < NUMBER_OF_PASSES) ? PassNames[pass] : nullptr;
}

//------------------------------------------------------------------------------
int vtkLightField::GetPassFromName(const char* name)
{
  if (!name)
  {
    return -1;
  }
  std::string lower(name);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  for (int pass = 0; pass < NUMBER_OF_PASSES; ++pass)
  {
    std::string candidate(PassNames[pass]);
    candidate[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(candidate[0])));
    if (candidate == lower)
    {
      return pass;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
int vtkLightField::GetPassComponents(int pass)
{
  return (pass == COAXIAL || pass == CODED || pass == FLOOD) ? 3 : 1;
}

//------------------------------------------------------------------------------
int vtkLightField::GetPassScalarType(int pass)
{
  return pass == DEPTH ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
}

//------------------------------------------------------------------------------
void vtkLightField::SetLayout(int width, int height, int views)
{
  for (int pass = 0; pass < NUMBER_OF_PASSES; ++pass)
  {
    this->GetPointData()->RemoveArray(PassNames[pass]);
  }
  this->SetOrigin(0.0, 0.0, 0.0);
  this->SetSpacing(1.0, 1.0, 1.0);
  this->SetDimensions(width, height, views);
}

//------------------------------------------------------------------------------
int vtkLightField::GetWidth()
{
  return this->GetDimensions()[0];
}

//------------------------------------------------------------------------------
int vtkLightField::GetHeight()
{
  return this->GetDimensions()[1];
}

//------------------------------------------------------------------------------
int vtkLightField::GetNumberOfViews()
{
  return this->GetDimensions()[2];
}

//------------------------------------------------------------------------------
vtkDataArray* vtkLightField::GetPass(int pass)
{
  const char* name = GetPassName(pass);
  return name ? this->GetPointData()->GetArray(name) : nullptr;
}

//------------------------------------------------------------------------------
bool vtkLightField::HasPass(int pass)
{
  return this->GetPass(pass) || (this->TexelSource && this->TexelSource->HasPass(pass));
}

//------------------------------------------------------------------------------
bool vtkLightField::HasLabel(int label)
{
  vtkDataArray* labels = this->GetPass(LABEL);
  if (!labels && this->TexelSource && this->TexelSource->HasPass(LABEL))
  {
    return label >= 0 && label <= 255 && this->TexelSource->HasLabel(label);
  }
  if (!labels || label < 0 || label > 255)
  {
    return false;
  }
  if (this->LabelsPresentArray != labels || this->LabelsPresentTime < labels->GetMTime())
  {
    this->LabelsPresent.assign(256, false);
    if (auto* bytes = vtkUnsignedCharArray::SafeDownCast(labels))
    {
      // A plain byte table, not the vector<bool>'s bit operations: every
      // label texel of every view passes through this loop (23.6 M for the
      // demo's fish, about 80 ms of the first deformed render before).
      std::array<unsigned char, 256> seen{};
      const unsigned char* values = bytes->GetPointer(0);
      const vtkIdType count = bytes->GetNumberOfValues();
      for (vtkIdType i = 0; i < count; ++i)
      {
        seen[values[i]] = 1;
      }
      for (int value = 0; value < 256; ++value)
      {
        this->LabelsPresent[value] = seen[value] != 0;
      }
    }
    else
    {
      for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
      {
        const double value = labels->GetComponent(i, 0);
        if (value >= 0.0 && value <= 255.0)
        {
          this->LabelsPresent[static_cast<int>(value)] = true;
        }
      }
    }
    this->LabelsPresentArray = labels;
    this->LabelsPresentTime = labels->GetMTime();
  }
  return this->LabelsPresent[label];
}

//------------------------------------------------------------------------------
vtkDataArray* vtkLightField::AllocatePass(int pass)
{
  const char* name = GetPassName(pass);
  if (!name)
  {
    vtkErrorMacro("AllocatePass: invalid pass " << pass << ".");
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> array;
  if (GetPassScalarType(pass) == VTK_FLOAT)
  {
    array = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  array->SetName(name);
  array->SetNumberOfComponents(GetPassComponents(pass));
  array->SetNumberOfTuples(this->GetNumberOfPoints());
  // Before the first write (Fill), so that the pass faults in 2 MiB at a
  // time instead of 4 KiB (lfdHugePages.h).
  lfd::AdviseHugePages(array->GetVoidPointer(0),
    static_cast<std::size_t>(array->GetNumberOfValues()) *
      static_cast<std::size_t>(array->GetDataTypeSize()));
  array->Fill(0.0);
  this->GetPointData()->AddArray(array);
  if (pass == COAXIAL)
  {
    this->GetPointData()->SetActiveScalars(name);
  }
  return array;
}

//------------------------------------------------------------------------------
vtkIdType vtkLightField::GetPointIndex(int view, int x, int y)
{
  const int* dims = this->GetDimensions();
  return (static_cast<vtkIdType>(view) * dims[1] + (dims[1] - 1 - y)) * dims[0] + x;
}

//------------------------------------------------------------------------------
void vtkLightField::Initialize()
{
  this->Superclass::Initialize();
  vtkNew<vtkCameraRig> rig;
  this->SetRig(rig);
  vtkNew<vtkCameraRig> projectors;
  this->SetProjectors(projectors);
  this->SetProjectorMasks(nullptr);
  this->SetTexelSource(nullptr);
  this->SetProvenance(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightField::ShallowCopy(vtkDataObject* source)
{
  this->Superclass::ShallowCopy(source);
  if (vtkLightField* lightField = vtkLightField::SafeDownCast(source))
  {
    this->SetRig(lightField->GetRig());
    this->SetProjectors(lightField->GetProjectors());
    this->SetProjectorMasks(lightField->GetProjectorMasks());
    this->SetTexelSource(lightField->GetTexelSource());
    this->SetProvenance(lightField->GetProvenance());
  }
}

//------------------------------------------------------------------------------
void vtkLightField::DeepCopy(vtkDataObject* source)
{
  this->Superclass::DeepCopy(source);
  if (vtkLightField* lightField = vtkLightField::SafeDownCast(source))
  {
    vtkNew<vtkCameraRig> rig;
    rig->DeepCopy(lightField->GetRig());
    this->SetRig(rig);
    vtkNew<vtkCameraRig> projectors;
    projectors->DeepCopy(lightField->GetProjectors());
    this->SetProjectors(projectors);
    vtkSmartPointer<vtkImageData> masks;
    if (lightField->GetProjectorMasks())
    {
      masks = vtkSmartPointer<vtkImageData>::New();
      masks->DeepCopy(lightField->GetProjectorMasks());
    }
    this->SetProjectorMasks(masks);
    this->SetTexelSource(lightField->GetTexelSource());
    this->SetProvenance(lightField->GetProvenance());
  }
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightField::GetData(vtkInformation* info)
{
  return info ? vtkLightField::SafeDownCast(info->Get(DATA_OBJECT())) : nullptr;
}

//------------------------------------------------------------------------------
vtkLightField* vtkLightField::GetData(vtkInformationVector* v, int i)
{
  return vtkLightField::GetData(v->GetInformationObject(i));
}

//------------------------------------------------------------------------------
void vtkLightField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Passes:";
  for (int pass = 0; pass < NUMBER_OF_PASSES; ++pass)
  {
    if (this->HasPass(pass))
    {
      os << " " << PassNames[pass] << (this->GetPass(pass) ? "" : " (texel source)");
    }
  }
  os << "\n";
  os << indent << "Provenance: " << (this->Provenance ? this->Provenance : "(none)") << "\n";
  os << indent << "Rig:\n";
  this->Rig->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Projectors: " << this->Projectors->GetNumberOfViews() << "\n";
  os << indent << "ProjectorMasks: " << (this->ProjectorMasks ? "set" : "(none)") << "\n";
}

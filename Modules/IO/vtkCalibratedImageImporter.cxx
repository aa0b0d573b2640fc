#include "vtkCalibratedImageImporter.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdJsonFields.h"
#include "lfdLimits.h"
#include "vtkCameraRig.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkNew.h"

#include <vtksys/SystemTools.hxx>

#include <cstdint>

namespace
{
std::string Size(int width, int height)
{
  return std::to_string(width) + "x" + std::to_string(height);
}
}

//------------------------------------------------------------------------------
struct vtkCalibratedImageImporter::Internals
{
  std::vector<CalibratedView> Views;
};

//------------------------------------------------------------------------------
vtkCalibratedImageImporter::vtkCalibratedImageImporter()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCalibratedImageImporter::~vtkCalibratedImageImporter()
{
  this->SetFileName(nullptr);
  this->SetImageDirectory(nullptr);
}

//------------------------------------------------------------------------------
std::string vtkCalibratedImageImporter::GetImageFolder()
{
  if (this->ImageDirectory && *this->ImageDirectory)
  {
    return this->ImageDirectory;
  }
  const std::string calibration = this->FileName ? this->FileName : "";
  return vtksys::SystemTools::FileIsDirectory(calibration) ? lfd::io::TrimSeparators(calibration)
                                                           : lfd::io::ParentFolder(calibration);
}

//------------------------------------------------------------------------------
int vtkCalibratedImageImporter::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  std::vector<CalibratedView>& views = this->Internal->Views;
  views.clear();
  this->CalibratedImageSize[0] = this->CalibratedImageSize[1] = 0;
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  if (!this->FileName || !*this->FileName)
  {
    this->Fail(output,
      vtkErrorCode::NoFileNameError,
      this->GetClassName() + std::string(": no FileName set"));
    return 0;
  }
  if (!this->ParseCalibration(views, errorCode, error))
  {
    views.clear();
    this->Fail(output, errorCode, error);
    return 0;
  }
  const CalibratedView& first = views[0];
  lfd::io::ImageHeader header;
  if (!lfd::io::ReadImageHeader(first.Image, header, error, errorCode))
  {
    this->Fail(output, errorCode, first.Where + ": image " + first.Image + ": " + error);
    return 0;
  }
  // An image header may announce any size: the coaxial pass it implies is
  // checked before it is allocated.
  const std::string tooLarge = lfd::CheckLightFieldSize(
    header.Width, header.Height, static_cast<std::int64_t>(views.size()), 3);
  if (!tooLarge.empty())
  {
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      first.Where + ": image " + first.Image +
        ": the light field is too large to import: " + tooLarge);
    return 0;
  }
  // The rig's one validation, over the image size the distortion must stay
  // monotonic on.
  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(static_cast<int>(views.size()));
  rig->SetImageSize(header.Width, header.Height);
  for (size_t i = 0; i < views.size(); ++i)
  {
    rig->SetView(static_cast<int>(i), views[i].K, views[i].R, views[i].t);
    rig->SetDistortion(static_cast<int>(i), views[i].Distortion);
  }
  std::string field;
  std::string problem;
  const int invalid = rig->FindInvalidView(field, problem);
  if (invalid >= 0)
  {
    const CalibratedView& view = views[invalid];
    const bool intrinsic = field == "K" || field == "distortion";
    const std::string& where =
      intrinsic && !view.CameraWhere.empty() ? view.CameraWhere : view.Where;
    this->Fail(output,
      vtkErrorCode::FileFormatError,
      where + ": " + (field.empty() ? problem : this->DescribeField(field) + ": " + problem));
    return 0;
  }
  SetOutputLayout(outputs, header.Width, header.Height, static_cast<int>(views.size()));
  return 1;
}

//------------------------------------------------------------------------------
int vtkCalibratedImageImporter::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputs)
{
  this->ClearError();
  vtkLightField* output = vtkLightField::GetData(outputs);
  const std::vector<CalibratedView>& views = this->Internal->Views;
  unsigned long errorCode = vtkErrorCode::NoError;
  std::string error;
  const int count = static_cast<int>(views.size());
  // Every header is checked (size, channels, bit depth) before the coaxial
  // pass is allocated.
  std::vector<lfd::io::ImageHeader> headers(views.size());
  for (int i = 0; i < count; ++i)
  {
    const CalibratedView& view = views[i];
    const std::string where = view.Where + ": image " + view.Image + ": ";
    lfd::io::ImageHeader& header = headers[i];
    if (!lfd::io::ReadImageHeader(view.Image, header, error, errorCode))
    {
      this->Fail(output, errorCode, where + error);
      return 0;
    }
    if (this->CalibratedImageSize[0] > 0 &&
      (header.Width != this->CalibratedImageSize[0] ||
        header.Height != this->CalibratedImageSize[1]))
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        where + "image is " + Size(header.Width, header.Height) + ", the calibration says " +
          Size(this->CalibratedImageSize[0], this->CalibratedImageSize[1]));
      return 0;
    }
    if (header.Width != headers[0].Width || header.Height != headers[0].Height)
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        where + "image is " + Size(header.Width, header.Height) + ", the first image (" +
          views[0].Name + ") is " + Size(headers[0].Width, headers[0].Height));
      return 0;
    }
    if ((header.Channels != 1 && header.Channels < 3) || header.ScalarType != VTK_UNSIGNED_CHAR)
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        where + "image has " + lfd::io::DescribePixels(header.Channels, header.ScalarType) +
          ", expected 8-bit grey (1 channel) or colour (3 or 4)");
      return 0;
    }
  }
  const int width = headers[0].Width;
  const int height = headers[0].Height;
  output->Initialize();
  output->SetLayout(width, height, count);
  vtkDataArray* coaxial = output->AllocatePass(vtkLightField::COAXIAL);
  this->UpdateProgress(0.0);
  for (int i = 0; i < count; ++i)
  {
    if (!lfd::io::ReadViewPixels(views[i].Image, headers[i], coaxial, i, error))
    {
      this->Fail(output,
        vtkErrorCode::FileFormatError,
        views[i].Where + ": image " + views[i].Image + ": " + error);
      return 0;
    }
    this->UpdateProgress(0.95 * (i + 1) / count);
  }

  vtkNew<vtkCameraRig> rig;
  rig->SetNumberOfViews(count);
  rig->SetImageSize(width, height);
  for (int i = 0; i < count; ++i)
  {
    rig->SetView(i, views[i].K, views[i].R, views[i].t);
    rig->SetDistortion(i, views[i].Distortion);
    rig->SetViewName(i, views[i].Name.c_str());
  }
  std::string noCylinder;
  if (this->FitRigCylinder && count >= 3 && !rig->FitCylinder(noCylinder))
  {
    vtkWarningMacro(<< this->FileName << ": the camera centres do not determine a cylinder; "
                    << "the rig is imported without a cylinder fit.");
  }
  output->SetRig(rig);
  const lfd::io::Json provenance = { { "importer", this->GetClassName() },
    { "source", this->FileName },
    { "format", this->GetFormatDescription() } };
  output->SetProvenance(provenance.dump().c_str());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkCalibratedImageImporter::DescribeFailure(const std::string& problem)
{
  return (this->FileName ? std::string(this->FileName) : std::string(this->GetClassName())) + ": " +
    problem;
}

//------------------------------------------------------------------------------
void vtkCalibratedImageImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ImageDirectory: " << (this->ImageDirectory ? this->ImageDirectory : "(none)")
     << "\n";
  os << indent << "FitRigCylinder: " << (this->FitRigCylinder ? "On" : "Off") << "\n";
}

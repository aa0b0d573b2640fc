#include "vtkCharucoBoard.h"

#include "lfdCalibrationImages.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkCharucoBoard);

//------------------------------------------------------------------------------
vtkCharucoBoard::vtkCharucoBoard()
{
  this->SetDictionary("DICT_5X5_100");
}

//------------------------------------------------------------------------------
vtkCharucoBoard::~vtkCharucoBoard()
{
  this->SetDictionary(nullptr);
}

//------------------------------------------------------------------------------
std::string vtkCharucoBoard::Check() const
{
  return lfd::calibration::CheckBoard(this);
}

//------------------------------------------------------------------------------
int vtkCharucoBoard::GetNumberOfCorners() const
{
  return (this->SquaresX - 1) * (this->SquaresY - 1);
}

//------------------------------------------------------------------------------
void vtkCharucoBoard::GetCornerPosition(int id, double position[3]) const
{
  const int across = this->SquaresX - 1;
  position[0] = (id % across + 1) * this->SquareLength;
  position[1] = (id / across + 1) * this->SquareLength;
  position[2] = 0.0;
}

//------------------------------------------------------------------------------
bool vtkCharucoBoard::DrawImage(int pixelsPerSquare, vtkImageData* image)
{
  const std::string problem = this->Check();
  if (!problem.empty())
  {
    vtkErrorMacro("ChArUco board: " << problem);
    return false;
  }
  if (pixelsPerSquare < 8)
  {
    vtkErrorMacro("ChArUco board: " << pixelsPerSquare
                                    << " pixels per square cannot hold a marker (at least 8)");
    return false;
  }
  cv::Mat drawn;
  lfd::calibration::MakeBoard(this)->draw(
    cv::Size(this->SquaresX * pixelsPerSquare, this->SquaresY * pixelsPerSquare), drawn, 0, 1);
  lfd::calibration::FromGrey(drawn, image);
  return true;
}

//------------------------------------------------------------------------------
void vtkCharucoBoard::DeepCopy(vtkCharucoBoard* source)
{
  this->SetSquaresX(source->SquaresX);
  this->SetSquaresY(source->SquaresY);
  this->SetSquareLength(source->SquareLength);
  this->SetMarkerLength(source->MarkerLength);
  this->SetDictionary(source->Dictionary);
}

//------------------------------------------------------------------------------
void vtkCharucoBoard::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SquaresX: " << this->SquaresX << "\n";
  os << indent << "SquaresY: " << this->SquaresY << "\n";
  os << indent << "SquareLength: " << this->SquareLength << "\n";
  os << indent << "MarkerLength: " << this->MarkerLength << "\n";
  os << indent << "Dictionary: " << (this->Dictionary ? this->Dictionary : "(none)") << "\n";
}

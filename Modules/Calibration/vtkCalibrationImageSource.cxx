#include "vtkCalibrationImageSource.h"

#include "lfdCalibrationImages.h"
#include "lfdPinholeCamera.h"

#include "vtkCharucoBoard.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <random>

vtkStandardNewMacro(vtkCalibrationImageSource);
vtkCxxSetObjectMacro(vtkCalibrationImageSource, Board, vtkCharucoBoard);
vtkCxxSetObjectMacro(vtkCalibrationImageSource, ProjectorPattern, vtkImageData);

namespace
{
/// Texture pixels per board square: a marker bit spans at least 6 of them.
constexpr int TexturePixelsPerSquare = 64;

/// The board's reflectance over the plane z = 0.
struct BoardAlbedo
{
  cv::Mat Board;       // the drawn board, top row first
  double Scale;        // texture pixels per world unit
  double MarginX[2];   // x extent of the board with its margin
  double MarginY[2];   // y extent
  double Black, White; // albedos

  /// Albedo at board point (x, y); -1 when the point is off the board and
  /// its margin.
  double operator()(double x, double y) const
  {
    if (x < this->MarginX[0] || x > this->MarginX[1] || y < this->MarginY[0] ||
      y > this->MarginY[1])
    {
      return -1.0;
    }
    // Texture pixel centres are at (i + 0.5) / Scale: bilinear between them,
    // white beyond the drawn board (the margin).
    const double u = x * this->Scale - 0.5;
    const double v = y * this->Scale - 0.5;
    const int u0 = static_cast<int>(std::floor(u));
    const int v0 = static_cast<int>(std::floor(v));
    const double fu = u - u0;
    const double fv = v - v0;
    double texture = 0.0;
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        const int col = u0 + i;
        const int row = v0 + j;
        const bool inside =
          col >= 0 && row >= 0 && col < this->Board.cols && row < this->Board.rows;
        const double value = inside ? this->Board.at<unsigned char>(row, col) / 255.0 : 1.0;
        texture += (i ? fu : 1.0 - fu) * (j ? fv : 1.0 - fv) * value;
      }
    }
    return this->Black + (this->White - this->Black) * texture;
  }
};
}

/// Per ray (pixel by pixel, Supersampling^2 rays each): the albedo it sees
/// (negative: nothing) and the projector pixel that lights that point (index
/// into the pattern, top row first; -1: none), with the set-up they were
/// traced for.
struct vtkCalibrationImageSource::Samples
{
  std::vector<double> SetUp;
  std::vector<float> Albedo;
  std::vector<int> ProjectorPixel;
};

//------------------------------------------------------------------------------
vtkCalibrationImageSource::vtkCalibrationImageSource()
  : Traced(new Samples)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkCalibrationImageSource::~vtkCalibrationImageSource()
{
  this->SetBoard(nullptr);
  this->SetProjectorPattern(nullptr);
}

//------------------------------------------------------------------------------
void vtkCalibrationImageSource::SetCamera(const double K[9], const double R[9], const double t[3])
{
  std::copy(K, K + 9, this->CameraK);
  std::copy(R, R + 9, this->CameraR);
  std::copy(t, t + 3, this->CameraT);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCalibrationImageSource::SetDistortion(const double coefficients[5])
{
  std::copy(coefficients, coefficients + 5, this->Distortion);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCalibrationImageSource::SetProjector(const double K[9],
  const double R[9],
  const double t[3])
{
  std::copy(K, K + 9, this->ProjectorK);
  std::copy(R, R + 9, this->ProjectorR);
  std::copy(t, t + 3, this->ProjectorT);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCalibrationImageSource::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->ImageSize[0] - 1, 0, this->ImageSize[1] - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_UNSIGNED_CHAR, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCalibrationImageSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!this->Board)
  {
    vtkErrorMacro("calibration image: no board set");
    return 0;
  }
  const std::string problem = this->Board->Check();
  if (!problem.empty())
  {
    vtkErrorMacro("ChArUco board: " << problem);
    return 0;
  }
  const int width = this->ImageSize[0];
  const int height = this->ImageSize[1];
  if (width < 1 || height < 1)
  {
    vtkErrorMacro("calibration image: size " << width << " x " << height << " is empty");
    return 0;
  }

  cv::Mat pattern;
  if (this->ProjectorPattern)
  {
    std::string patternProblem;
    if (!lfd::calibration::ToGrey(this->ProjectorPattern, pattern, patternProblem))
    {
      vtkErrorMacro("projector pattern: " << patternProblem);
      return 0;
    }
  }
  this->Trace(pattern.cols, pattern.rows);

  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  output->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(output->GetPointData()->GetScalars());
  scalars->SetName("Intensity");
  const int rays = this->Supersampling * this->Supersampling;
  const float* albedo = this->Traced->Albedo.data();
  const int* lit = this->Traced->ProjectorPixel.data();
  std::mt19937 generator(static_cast<unsigned>(this->NoiseSeed));
  std::normal_distribution<double> noise(0.0, this->NoiseSigma > 0.0 ? this->NoiseSigma : 1.0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      // grey = 255 albedo (Ambient + pattern), averaged over the pixel's rays.
      const size_t first = (static_cast<size_t>(y) * width + x) * rays;
      double sum = 0.0;
      for (size_t r = first; r < first + rays; ++r)
      {
        if (albedo[r] >= 0.0f)
        {
          const double light = lit[r] >= 0 ? pattern.data[lit[r]] / 255.0 : 0.0;
          sum += 255.0 * albedo[r] * (this->Ambient + light);
        }
      }
      double value = sum / rays;
      if (this->NoiseSigma > 0.0)
      {
        value += noise(generator);
      }
      // Image row y (top first) is VTK row height - 1 - y.
      scalars->SetValue(static_cast<vtkIdType>(height - 1 - y) * width + x,
        static_cast<unsigned char>(std::clamp(std::lround(value), 0L, 255L)));
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkCalibrationImageSource::Trace(int patternWidth, int patternHeight)
{
  vtkCharucoBoard* board = this->Board;
  std::vector<double> setUp = { double(this->ImageSize[0]),
    double(this->ImageSize[1]),
    double(this->Supersampling),
    double(board->GetSquaresX()),
    double(board->GetSquaresY()),
    board->GetSquareLength(),
    board->GetMarkerLength(),
    double(lfd::calibration::DictionaryId(board->GetDictionary())),
    this->BlackAlbedo,
    this->WhiteAlbedo,
    double(patternWidth),
    double(patternHeight) };
  setUp.insert(setUp.end(), this->CameraK, this->CameraK + 9);
  setUp.insert(setUp.end(), this->CameraR, this->CameraR + 9);
  setUp.insert(setUp.end(), this->CameraT, this->CameraT + 3);
  setUp.insert(setUp.end(), this->Distortion, this->Distortion + 5);
  setUp.insert(setUp.end(), this->ProjectorK, this->ProjectorK + 9);
  setUp.insert(setUp.end(), this->ProjectorR, this->ProjectorR + 9);
  setUp.insert(setUp.end(), this->ProjectorT, this->ProjectorT + 3);
  if (setUp == this->Traced->SetUp)
  {
    return;
  }

  BoardAlbedo reflectance;
  lfd::calibration::MakeBoard(board)->draw(cv::Size(board->GetSquaresX() * TexturePixelsPerSquare,
                                             board->GetSquaresY() * TexturePixelsPerSquare),
    reflectance.Board,
    0,
    1);
  const double square = board->GetSquareLength();
  reflectance.Scale = TexturePixelsPerSquare / square;
  reflectance.MarginX[0] = -square;
  reflectance.MarginX[1] = (board->GetSquaresX() + 1) * square;
  reflectance.MarginY[0] = -square;
  reflectance.MarginY[1] = (board->GetSquaresY() + 1) * square;
  reflectance.Black = this->BlackAlbedo;
  reflectance.White = this->WhiteAlbedo;
  const lfd::PinholeCamera projector =
    lfd::PinholeCamera::FromRowMajor(this->ProjectorK, this->ProjectorR, this->ProjectorT);
  lfd::PinholeCamera camera =
    lfd::PinholeCamera::FromRowMajor(this->CameraK, this->CameraR, this->CameraT);
  camera.Lens = lfd::LensDistortion::FromArray(this->Distortion);
  const lfd::PinholeCamera::Unprojection rays = camera.GetUnprojection();

  const int width = this->ImageSize[0];
  const int samples = this->Supersampling;
  const size_t count = static_cast<size_t>(width) * this->ImageSize[1] * samples * samples;
  std::vector<float>& albedo = this->Traced->Albedo;
  std::vector<int>& lit = this->Traced->ProjectorPixel;
  albedo.assign(count, -1.0f);
  lit.assign(count, -1);
  vtkSMPTools::For(0,
    this->ImageSize[1],
    [&](int firstRow, int lastRow)
    {
      for (int y = firstRow; y < lastRow; ++y)
      {
        for (int x = 0; x < width; ++x)
        {
          size_t r = (static_cast<size_t>(y) * width + x) * samples * samples;
          for (int j = 0; j < samples; ++j)
          {
            for (int i = 0; i < samples; ++i, ++r)
            {
              // Rays spread evenly over the pixel, whose centre is at
              // integer coordinates (OpenCV's convention).
              const glm::dvec2 pixel(x - 0.5 + (i + 0.5) / samples, y - 0.5 + (j + 0.5) / samples);
              const glm::dvec3 direction = rays.Direction(pixel);
              const double s = -rays.Center.z / direction.z;
              if (!(s > 0.0))
              {
                continue;
              }
              const glm::dvec3 hit = rays.Center + s * direction;
              albedo[r] = static_cast<float>(reflectance(hit.x, hit.y));
              // The projector pixel nearest to where the projector sees the point.
              glm::dvec2 seen;
              if (albedo[r] >= 0.0f && patternWidth > 0 && projector.Project(hit, seen))
              {
                const long col = std::lround(seen.x);
                const long row = std::lround(seen.y);
                if (col >= 0 && row >= 0 && col < patternWidth && row < patternHeight)
                {
                  lit[r] = static_cast<int>(row * patternWidth + col);
                }
              }
            }
          }
        }
      }
    });
  this->Traced->SetUp = std::move(setUp);
}

//------------------------------------------------------------------------------
void vtkCalibrationImageSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Board: " << this->Board << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  const auto print = [&os, indent](const char* name, const double* values, int count)
  {
    os << indent << name << ":";
    for (int i = 0; i < count; ++i)
    {
      os << " " << values[i];
    }
    os << "\n";
  };
  print("CameraK", this->CameraK, 9);
  print("CameraR", this->CameraR, 9);
  print("CameraT", this->CameraT, 3);
  print("Distortion", this->Distortion, 5);
  print("ProjectorK", this->ProjectorK, 9);
  print("ProjectorR", this->ProjectorR, 9);
  print("ProjectorT", this->ProjectorT, 3);
  os << indent << "ProjectorPattern: " << this->ProjectorPattern << "\n";
  os << indent << "Ambient: " << this->Ambient << "\n";
  os << indent << "BlackAlbedo: " << this->BlackAlbedo << "\n";
  os << indent << "WhiteAlbedo: " << this->WhiteAlbedo << "\n";
  os << indent << "Supersampling: " << this->Supersampling << "\n";
  os << indent << "NoiseSigma: " << this->NoiseSigma << "\n";
  os << indent << "NoiseSeed: " << this->NoiseSeed << "\n";
}

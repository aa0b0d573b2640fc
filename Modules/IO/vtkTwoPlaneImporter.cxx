#include "vtkTwoPlaneImporter.h"

#include "lfdFileUtilities.h"
#include "lfdImageFiles.h"
#include "lfdTextFields.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkTwoPlaneImporter);

namespace
{
/// True when `name` ends in one of the image extensions the importer reads.
bool IsImageName(const std::string& name)
{
  static const std::set<std::string> extensions = {
    ".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr", ".bmp", ".ppm", ".pgm"
  };
  std::string extension = vtksys::SystemTools::GetFilenameLastExtension(name);
  std::transform(extension.begin(),
    extension.end(),
    extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extensions.count(extension) > 0;
}

/// The row and column of an image name: its first two '_'-separated fields
/// (extension removed) made of digits only. False when it has fewer.
bool ParseRowColumn(const std::string& name, int& row, int& column)
{
  const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(name);
  int found[2];
  int count = 0;
  std::size_t start = 0;
  while (count < 2 && start <= stem.size())
  {
    std::size_t end = stem.find('_', start);
    end = end == std::string::npos ? stem.size() : end;
    const std::string field = stem.substr(start, end - start);
    if (!field.empty() && field.size() <= 6 &&
      std::all_of(field.begin(), field.end(), [](unsigned char c) { return std::isdigit(c); }))
    {
      found[count++] = std::stoi(field);
    }
    start = end + 1;
  }
  if (count < 2)
  {
    return false;
  }
  row = found[0];
  column = found[1];
  return true;
}

/// The camera positions of a PositionsFile, by image name (see the header).
bool ReadPositions(const std::string& path,
  std::map<std::string, std::pair<double, double>>& positions,
  std::map<std::string, int>& lineOf,
  std::string& error)
{
  std::vector<std::string> lines;
  try
  {
    lines = lfd::io::ReadTextLines(path);
  }
  catch (const std::exception& failure)
  {
    error = failure.what();
    return false;
  }
  for (std::size_t n = 0; n < lines.size(); ++n)
  {
    const std::vector<std::string> fields = lfd::io::SplitFields(lines[n]);
    if (fields.empty() || fields[0][0] == '#')
    {
      continue;
    }
    const std::string where = path + ": line " + std::to_string(n + 1);
    double x = 0.0, y = 0.0;
    std::string problem;
    if (fields.size() != 3)
    {
      error = where + ": expected NAME X Y, found " + std::to_string(fields.size()) + " fields";
      return false;
    }
    if (!lfd::io::ParseFiniteNumber(fields[1], x, problem) ||
      !lfd::io::ParseFiniteNumber(fields[2], y, problem))
    {
      error = where + ": the position " + problem;
      return false;
    }
    if (!positions.emplace(fields[0], std::make_pair(x, y)).second)
    {
      error =
        where + ": " + fields[0] + " again (also line " + std::to_string(lineOf[fields[0]]) + ")";
      return false;
    }
    lineOf[fields[0]] = static_cast<int>(n + 1);
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkTwoPlaneImporter::vtkTwoPlaneImporter()
{
  // A grid is not a ring: the renderer samples it by its plane.
  this->FitRigCylinder = false;
}

//------------------------------------------------------------------------------
vtkTwoPlaneImporter::~vtkTwoPlaneImporter()
{
  this->SetPositionsFile(nullptr);
}

//------------------------------------------------------------------------------
bool vtkTwoPlaneImporter::ParseCalibration(std::vector<CalibratedView>& views,
  unsigned long& errorCode,
  std::string& error)
{
  const std::string folder = lfd::io::TrimSeparators(this->FileName);
  errorCode = vtkErrorCode::FileFormatError;
  if (!(this->FocalLength > 0.0))
  {
    error = folder + ": FocalLength (pixels) is not set";
    return false;
  }
  if (!vtksys::SystemTools::FileIsDirectory(folder))
  {
    errorCode = vtkErrorCode::FileNotFoundError;
    error = folder + ": not a folder of images";
    return false;
  }
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && IsImageName(name))
    {
      names.push_back(name);
    }
  }
  if (names.empty())
  {
    error = folder + ": no images (png, jpg, jpeg, tif, tiff, exr, bmp, ppm, pgm) in the folder";
    return false;
  }
  std::sort(names.begin(), names.end());
  std::map<std::pair<int, int>, std::string> cells;
  for (const std::string& name : names)
  {
    int row = 0, column = 0;
    const std::string path = lfd::io::ResolvePath(folder, name);
    if (!ParseRowColumn(name, row, column))
    {
      error = path +
        ": the name has no row and column (two whole-number fields separated by '_', "
        "as in out_RR_CC_*.png)";
      return false;
    }
    const auto inserted = cells.emplace(std::make_pair(row, column), name);
    if (!inserted.second)
    {
      error = path + ": row " + std::to_string(row) + ", column " + std::to_string(column) +
        " again (also " + inserted.first->second + ")";
      return false;
    }
  }
  int rows[2] = { cells.begin()->first.first, cells.rbegin()->first.first };
  int columns[2] = { cells.begin()->first.second, cells.begin()->first.second };
  for (const auto& cell : cells)
  {
    columns[0] = std::min(columns[0], cell.first.second);
    columns[1] = std::max(columns[1], cell.first.second);
  }
  std::map<std::string, std::pair<double, double>> positions;
  std::map<std::string, int> lineOf;
  const bool positioned = this->PositionsFile && *this->PositionsFile;
  if (positioned && !ReadPositions(this->PositionsFile, positions, lineOf, error))
  {
    return false;
  }
  // The image size gives the principal point.
  lfd::io::ImageHeader header;
  const std::string first = lfd::io::ResolvePath(folder, cells.begin()->second);
  if (!lfd::io::ReadImageHeader(first, header, error, errorCode))
  {
    error = first + ": " + error;
    return false;
  }
  for (int r = rows[0]; r <= rows[1]; ++r)
  {
    for (int c = columns[0]; c <= columns[1]; ++c)
    {
      const auto cell = cells.find({ r, c });
      if (cell == cells.end())
      {
        error = folder + ": no image for row " + std::to_string(r) + ", column " +
          std::to_string(c) + " (the grid has rows " + std::to_string(rows[0]) + ".." +
          std::to_string(rows[1]) + " and columns " + std::to_string(columns[0]) + ".." +
          std::to_string(columns[1]) + ")";
        return false;
      }
      CalibratedView view;
      view.Name = cell->second;
      view.Image = lfd::io::ResolvePath(folder, cell->second);
      view.Where = folder;
      const double K[9] = { this->FocalLength,
        0.0,
        0.5 * (header.Width - 1),
        0.0,
        this->FocalLength,
        0.5 * (header.Height - 1),
        0.0,
        0.0,
        1.0 };
      const double R[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
      // t = -R C for the centre C = (c, r, 0) x Spacing, or the file's.
      double centre[2] = { c * this->Spacing, r * this->Spacing };
      if (positioned)
      {
        const auto position = positions.find(view.Name);
        if (position == positions.end())
        {
          error = std::string(this->PositionsFile) + ": no position for " + view.Name;
          return false;
        }
        centre[0] = position->second.first;
        centre[1] = position->second.second;
        positions.erase(position);
      }
      const double t[3] = { -centre[0], -centre[1], 0.0 };
      std::copy(K, K + 9, view.K);
      std::copy(R, R + 9, view.R);
      std::copy(t, t + 3, view.t);
      views.push_back(view);
    }
  }
  if (!positions.empty())
  {
    const std::string& name = positions.begin()->first;
    error = std::string(this->PositionsFile) + ": line " + std::to_string(lineOf[name]) + ": " +
      name + " is not an image of " + folder;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkTwoPlaneImporter::GetFormatDescription()
{
  return "two-plane grid of images named by row and column";
}

//------------------------------------------------------------------------------
void vtkTwoPlaneImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "FocalLength: " << this->FocalLength << "\n";
  os << indent << "PositionsFile: " << (this->PositionsFile ? this->PositionsFile : "(none)")
     << "\n";
}

/**
 * @file   lfdColmapModel.h
 * @brief  COLMAP sparse models as text (cameras.txt, images.txt) or binary (cameras.bin,
 *         images.bin) files: read with every field checked, and written (private to LFD::IO)
 *
 * One definition of COLMAP's model files (Schoenberger and Frahm,
 * "Structure-from-Motion Revisited", CVPR 2016; the layouts of COLMAP 3.8's
 * documentation, "Output Format") for vtkColmapImporter and
 * vtkColmapExporter. The binary files are little-endian:
 *
 * - `cameras.bin`: uint64 count, then per camera uint32 CAMERA_ID, int32
 *   MODEL_ID, uint64 WIDTH, uint64 HEIGHT, float64 PARAMS[n(MODEL_ID)];
 * - `images.bin`: uint64 count, then per image uint32 IMAGE_ID, float64 QW
 *   QX QY QZ TX TY TZ, uint32 CAMERA_ID, NAME (bytes ending with a 0 byte),
 *   uint64 POINTS2D count, then per point float64 X, Y and uint64
 *   POINT3D_ID (skipped);
 * - `points3D.bin`: uint64 count and the points (not read; written empty).
 */
#ifndef lfdColmapModel_h
#define lfdColmapModel_h

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lfd
{
namespace io
{
/// A camera model of COLMAP 3.8: its name, its MODEL_ID in binary models,
/// and its parameters in COLMAP's order when the rig can hold it (empty for
/// the others, which are refused).
struct ColmapCameraModel
{
  const char* Name;
  int Id;
  std::vector<std::string> Parameters;
};

/// Every camera model of COLMAP 3.8, by MODEL_ID.
const std::vector<ColmapCameraModel>& ColmapCameraModels();

/// One camera of a model file.
struct ColmapCamera
{
  std::string Where; // "<file>:<line>" or "<file>: record <n> of <count>", for messages
  const ColmapCameraModel* Model = nullptr;
  int Width = 0;
  int Height = 0;
  std::vector<double> Parameters;
};

/// One registered image of a model file (its 2D points are not kept).
struct ColmapImage
{
  std::string Where;
  long long Id = 0;
  double Q[4] = { 1.0, 0.0, 0.0, 0.0 }; // QW QX QY QZ: world-to-camera rotation
  double T[3] = { 0.0, 0.0, 0.0 };      // TX TY TZ: world-to-camera translation
  long long CameraId = 0;
  std::string Name;
};

/// A sparse model: cameras by CAMERA_ID, images in file order.
struct ColmapModel
{
  std::string CamerasFile; // the files read, for messages
  std::string ImagesFile;
  bool Binary = false;
  std::map<long long, ColmapCamera> Cameras;
  std::vector<ColmapImage> Images;
};

/// A malformed model file: the message names the file and the line or record.
struct ColmapModelError : std::runtime_error
{
  ColmapModelError(const std::string& where, const std::string& problem)
    : std::runtime_error(where + ": " + problem)
  {
  }
};

/**
 * Reads the sparse model in `folder`: the binary files when it holds
 * `cameras.bin` (COLMAP's own preference), else the text files. Checks the
 * syntax of every field (counts, numbers, finite values, sizes from 1 to
 * INT_MAX, supported models and their parameter counts, truncated records,
 * unterminated names, bytes after the last record) and that no CAMERA_ID or
 * IMAGE_ID is repeated, and that there is a camera. Throws ColmapModelError
 * for a malformed file, std::runtime_error ("<file>: file not found") for a
 * file that cannot be read.
 */
ColmapModel ReadColmapModel(const std::string& folder);

/**
 * The rig's OpenCV camera (K, distortion k1 k2 p1 p2 k3) of a COLMAP camera:
 * the principal point moved by half a pixel (COLMAP's pixel centres are at
 * half-integers, the rig's at integers). Throws ColmapModelError for a
 * FULL_OPENCV camera with rational terms.
 */
void ColmapCameraToOpenCV(const ColmapCamera& camera, double K[9], double distortion[5]);

/**
 * The COLMAP camera of the rig's OpenCV camera (no skew): PINHOLE without
 * distortion, OPENCV when k3 = 0, else FULL_OPENCV with k4 = k5 = k6 = 0.
 */
ColmapCamera OpenCVToColmapCamera(const double K[9],
  const double distortion[5],
  int width,
  int height);

/**
 * The files of `model` (file name -> contents): `cameras`, `images` and an
 * empty `points3D`, `.txt` (numbers with 17 significant digits, so they read
 * back exactly) or `.bin`.
 */
std::map<std::string, std::string> FormatColmapModel(const ColmapModel& model, bool binary);
}
}

#endif

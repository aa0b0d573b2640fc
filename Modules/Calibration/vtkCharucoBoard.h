/**
 * @class   vtkCharucoBoard
 * @brief   the description of a ChArUco calibration board
 *
 * A ChArUco board (Garrido-Jurado et al., "Automatic generation and detection
 * of highly reliable fiducial markers under occlusion", Pattern Recognition
 * 47(6), 2014; OpenCV's aruco module) is a chessboard whose white squares hold
 * ArUco markers: each inner chessboard corner is identified by the markers
 * around it, so a partly visible or steeply seen board still gives labelled
 * corners. The board is described by its number of squares across and down,
 * the side of a square and of a marker (world units, e.g. metres) and the
 * marker dictionary (OpenCV's predefined names, e.g. "DICT_5X5_100").
 *
 * The board frame is OpenCV's: the board lies in the plane z = 0, x along
 * its rows (to the right of the drawn image), y down the drawn image, the
 * origin at the outer corner of the top-left square, which is black; z
 * points into the board, so a camera that sees the board's face is on the
 * side z < 0. Corner `i` (0 .. (SquaresX - 1)(SquaresY - 1) - 1) is the
 * inner corner at ((i % (SquaresX - 1)) + 1, (i / (SquaresX - 1)) + 1)
 * squares from the origin.
 *
 * @sa vtkCameraCalibration vtkProjectorCalibration vtkCalibrationImageSource
 */
#ifndef vtkCharucoBoard_h
#define vtkCharucoBoard_h

#include "lfdCalibrationModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class vtkImageData;

class LFDCALIBRATION_EXPORT vtkCharucoBoard : public vtkObject
{
public:
  static vtkCharucoBoard* New();
  vtkTypeMacro(vtkCharucoBoard, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Squares across (x) and down (y); default 7 x 5.
   */
  vtkSetClampMacro(SquaresX, int, 2, 200);
  vtkGetMacro(SquaresX, int);
  vtkSetClampMacro(SquaresY, int, 2, 200);
  vtkGetMacro(SquaresY, int);
  ///@}

  ///@{
  /**
   * Side of a square and of a marker, world units; defaults 0.03 and 0.022.
   * The marker must be smaller than the square (Check()).
   */
  vtkSetClampMacro(SquareLength, double, 1e-6, 1e6);
  vtkGetMacro(SquareLength, double);
  vtkSetClampMacro(MarkerLength, double, 1e-6, 1e6);
  vtkGetMacro(MarkerLength, double);
  ///@}

  ///@{
  /**
   * OpenCV predefined marker dictionary, by name: "DICT_4X4_50" ...
   * "DICT_7X7_1000", "DICT_ARUCO_ORIGINAL"; default "DICT_5X5_100".
   */
  vtkSetStringMacro(Dictionary);
  vtkGetStringMacro(Dictionary);
  ///@}

  /**
   * "" when the board can be made, else the reason in words (an unknown
   * dictionary, a marker not smaller than its square, more markers than the
   * dictionary holds).
   */
  std::string Check() const;

  /**
   * Number of inner chessboard corners, (SquaresX - 1) x (SquaresY - 1).
   */
  int GetNumberOfCorners() const;

  /**
   * Position of inner corner `id` in the board frame (z = 0).
   */
  void GetCornerPosition(int id, double position[3]) const;

  /**
   * Draws the board as OpenCV prints it into `image`: one channel of 8-bit
   * grey (0 black, 255 white), `pixelsPerSquare` pixels per square, no
   * margin, rows stored the VTK way (bottom image row first). Returns false
   * (with an error) when Check() refuses the board.
   */
  bool DrawImage(int pixelsPerSquare, vtkImageData* image);

  /**
   * Copies the description of another board.
   */
  void DeepCopy(vtkCharucoBoard* source);

protected:
  vtkCharucoBoard();
  ~vtkCharucoBoard() override;

  int SquaresX = 7;
  int SquaresY = 5;
  double SquareLength = 0.03;
  double MarkerLength = 0.022;
  char* Dictionary = nullptr;

private:
  vtkCharucoBoard(const vtkCharucoBoard&) = delete;
  void operator=(const vtkCharucoBoard&) = delete;
};

#endif

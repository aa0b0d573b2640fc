/**
 * @class   vtkProceduralObjectSource
 * @brief   procedural test objects for synthetic light fields: checkerboard, fish, figure
 *
 * vtkProceduralObjectSource builds the objects the synthetic light fields are
 * captured from (Chen et al. 2005, Figs. 4-5 and the part-based examples),
 * without any downloaded data. Output port 0 is a triangle mesh with point
 * normals and a cell array "Label" (int, 1..N for the parts; 0 is reserved
 * for the background of a light field). Output port 1 is the object's
 * texture image (RGB uint8); objects coloured per vertex or per cell output a
 * 1 x 1 white image there.
 *
 * - CHECKERBOARD: a unit square in the XY plane, centred at the origin,
 *   facing +Z, with 8 x 8 black (0) and white (255) checks as a cell array
 *   "RGB". The check (i, j) = (floor(8 (x + 0.5)), floor(8 (y + 0.5))) is
 *   white when i + j is even. Each check is split into
 *   ceil(Resolution / 8)^2 quads (two triangles each), so check edges are
 *   mesh edges. One label (1). The square is vertical, so a ring about +Y
 *   sees it face-on from +Z (azimuth 0) and -Z.
 * - FISH: about 1.2 units long along +X, centred at the origin: head (label
 *   1, +X end), body (2) and a flat tail fin (3, -X end), each an ellipsoid,
 *   with per-vertex "RGB" colours (stripes, spots, an eye).
 * - FIGURE: a standing figure along +Y, about 1.2 units tall, centred at the
 *   origin: head (label 1, a sphere), torso (2, a capped cylinder) and legs
 *   (3, two capped cylinders). Texture coordinates wrap around the Y axis
 *   (s mirrored so the wrap has no seam, t along Y) and the texture on port
 *   1 is a 256 x 256 pattern of checks and stripes.
 *
 * Resolution is the number of subdivisions around each round part (and the
 * checkerboard's subdivision, see above).
 *
 * @sa vtkLightFieldCapture
 */
#ifndef vtkProceduralObjectSource_h
#define vtkProceduralObjectSource_h

#include "lfdSynthesisModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkImageData;

class LFDSYNTHESIS_EXPORT vtkProceduralObjectSource : public vtkPolyDataAlgorithm
{
public:
  static vtkProceduralObjectSource* New();
  vtkTypeMacro(vtkProceduralObjectSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's request; a C++ exception thrown by it becomes this
   * algorithm's error (error code UnknownError), see lfdRequestGuard.h.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * The objects this source builds.
   */
  enum Object
  {
    CHECKERBOARD = 0,
    FISH,
    FIGURE
  };

  ///@{
  /**
   * The object to build. Default FISH.
   */
  vtkSetClampMacro(Object, int, CHECKERBOARD, FIGURE);
  vtkGetMacro(Object, int);
  void SetObjectToCheckerboard() { this->SetObject(CHECKERBOARD); }
  void SetObjectToFish() { this->SetObject(FISH); }
  void SetObjectToFigure() { this->SetObject(FIGURE); }
  const char* GetObjectAsString();
  ///@}

  /**
   * Object whose name is `name` ("checkerboard", "fish", "figure",
   * case-insensitive), or -1.
   */
  static int GetObjectFromString(const char* name);

  ///@{
  /**
   * Subdivisions around each round part; checkerboard subdivision. Default
   * 48.
   */
  vtkSetClampMacro(Resolution, int, 8, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  /**
   * Side of the (square) texture image of textured objects: 256.
   */
  static int GetTextureSize();

  /**
   * The texture image (output port 1).
   */
  vtkImageData* GetTextureOutput();

protected:
  vtkProceduralObjectSource();
  ~vtkProceduralObjectSource() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Object = FISH;
  int Resolution = 48;

private:
  vtkProceduralObjectSource(const vtkProceduralObjectSource&) = delete;
  void operator=(const vtkProceduralObjectSource&) = delete;
};

#endif

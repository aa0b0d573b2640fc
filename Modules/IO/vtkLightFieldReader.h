/**
 * @class   vtkLightFieldReader
 * @brief   reads a light-field dataset (lightfield.json and its images) into a vtkLightField
 *
 * A light-field dataset is a directory holding a manifest, `lightfield.json`,
 * and one image per view per pass (see Data/README.md for the format).
 * FileName is the directory or the manifest itself. The reader reads the
 * image size, the rig (K, R, t and name of every view), the label palette
 * (vtkLightField::GetPalette()), the projectors and their masks when the
 * manifest lists them (vtkLightField::GetProjectors(), GetProjectorMasks()), the
 * provenance (as JSON text, vtkLightField::GetProvenance()) and every pass
 * listed in the manifest, or only the passes selected with SetReadPass().
 * Images are read through OpenImageIO; their rows are flipped into
 * vtkLightField's order (bottom image row first, see vtkLightField.h).
 * Progress is reported once per image.
 *
 * The manifest is validated completely: malformed JSON (with the parser's
 * line and column), a wrong "format" or unsupported "version", a missing
 * field, an array of the wrong length, a camera that fails
 * vtkCameraRig::FindInvalidView() (not a rotation, a singular K, |t| too
 * large, a repeated view), an unknown or not lower-case pass, a file name
 * with a NUL, JSON nested deeper than lfd::MaximumJsonDepth, a light field
 * larger than lfd::MaximumLightFieldBytes, a missing image file, a path that
 * is not a regular file (directory, FIFO, device) and an image whose size,
 * bit depth or channel count differs from what the manifest and the pass
 * expect (checked for every image before any pass is allocated) are each
 * reported by one error that names the file and the field. A C++ exception
 * is reported the same way (vtkLightFieldAlgorithm::ProcessRequest). The output is then empty
 * and GetErrorCode() is not vtkErrorCode::NoError. As for any VTK algorithm,
 * the pipeline's executive reports the failed request too; a
 * vtkLightFieldErrorObserver observing the reader records both quietly and
 * gives back the reader's one line.
 *
 * **Out of core.** With a CacheSize (bytes, > 0) the Coaxial, Label and
 * Depth passes (what the renderer reads per ray; Depth: the proxy) are not
 * read into memory: the output has no arrays for them but a
 * vtkLightFieldImageCache of that budget (vtkLightField::GetTexelSource())
 * that the renderer reads tile by tile; the other selected passes are read
 * as usual. Their images must then be tiled (`lfd tile`,
 * vtkLightFieldTiler): an untiled one is an error naming it.
 *
 * @sa vtkLightFieldWriter vtkLightField vtkMiddleburyImporter vtkLightFieldImageCache
 */
#ifndef vtkLightFieldReader_h
#define vtkLightFieldReader_h

#include "lfdIOModule.h"   // For export macro
#include "vtkLightField.h" // For NUMBER_OF_PASSES
#include "vtkLightFieldAlgorithm.h"

#include <memory> // For std::unique_ptr

#include <string> // For std::string

class vtkDataArray;

namespace lfd
{
namespace io
{
struct ImageHeader;
}
}

class LFDIO_EXPORT vtkLightFieldReader : public vtkLightFieldAlgorithm
{
public:
  static vtkLightFieldReader* New();
  vtkTypeMacro(vtkLightFieldReader, vtkLightFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The dataset directory, or its `lightfield.json`.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Which passes to read (vtkLightField::Pass). All are selected by default;
   * a selected pass is read when the manifest lists it, an unselected one is
   * skipped even when it is listed. ReadAllPasses() selects every pass,
   * ReadNoPasses() none (only the manifest and the rig are read).
   */
  void SetReadPass(int pass, bool read);
  bool GetReadPass(int pass) const;
  void ReadAllPasses();
  void ReadNoPasses();
  ///@}

  ///@{
  /**
   * Reads one piece of the views: the images of views [first, end) of every
   * selected pass, GetPieceViews() of Piece out of NumberOfPieces (default
   * 0 of 1: every view). The passes are allocated whole, the views of the
   * other pieces left zero, and only the images read are checked: the
   * processes of `mpirun -np N lfd animate` each read one piece and
   * broadcast it to the others, so the decoding is split N ways. The
   * projector masks are read whole by every piece, and so are the passes
   * served by the image cache (CacheSize): each process reads their tiles.
   */
  vtkSetClampMacro(Piece, int, 0, VTK_INT_MAX);
  vtkGetMacro(Piece, int);
  vtkSetClampMacro(NumberOfPieces, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfPieces, int);
  ///@}

  /**
   * The views [range[0], range[1]) of piece `piece` out of `pieces` of a
   * light field of `views` views: consecutive blocks whose sizes differ by at
   * most one, empty for a piece >= `pieces`.
   */
  static void GetPieceViews(int views, int piece, int pieces, int range[2]);

  ///@{
  /**
   * One image at a time, after UpdateInformation(), for streaming a
   * dataset larger than memory view by view (vtkLightFieldTiler):
   * GetImageFileName() is the image of view `view` of `pass` (a
   * vtkLightField::Pass) as the manifest names it, resolved against its
   * folder, or nullptr when the manifest lists none; ReadView() reads that
   * image alone into `pixels` (an array of the pass's scalar type, given
   * the pass's components and one view's width x height tuples), checked
   * as Update() checks every image, and returns false after reporting the
   * error.
   */
  const char* GetImageFileName(int pass, int view);
  bool ReadView(int pass, int view, vtkDataArray* pixels);
  ///@}

  ///@{
  /**
   * 0 (default): every selected pass is read into memory. > 0: the Coaxial,
   * Label and Depth passes are served out of core by an image cache of this many
   * bytes (see Out of core above).
   */
  vtkSetClampMacro(CacheSize, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(CacheSize, vtkTypeInt64);
  ///@}

protected:
  vtkLightFieldReader();
  ~vtkLightFieldReader() override;

  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputs,
    vtkInformationVector* outputs) override;

  // Checks the header of an image against the size, scalar type and
  // channels the manifest and pass expect; on failure reports the error
  // naming the manifest, the field and the image, and returns false.
  bool CheckImage(const std::string& image,
    const std::string& field,
    int width,
    int height,
    int scalarType,
    int channels,
    lfd::io::ImageHeader& header,
    vtkLightField* output);

  // What a failure to read `image`, of the manifest's field `field`, says:
  // the manifest, the field and the image named, then `problem`.
  std::string ImageProblem(const std::string& image,
    const std::string& field,
    const std::string& problem) const;

  std::string DescribeFailure(const std::string& problem) override;

  char* FileName = nullptr;
  vtkTypeInt64 CacheSize = 0;
  bool ReadPass[vtkLightField::NUMBER_OF_PASSES];
  int Piece = 0;
  int NumberOfPieces = 1;

private:
  vtkLightFieldReader(const vtkLightFieldReader&) = delete;
  void operator=(const vtkLightFieldReader&) = delete;

  struct Internals; // what RequestInformation parsed, for RequestData
  std::unique_ptr<Internals> Internal;
};

#endif

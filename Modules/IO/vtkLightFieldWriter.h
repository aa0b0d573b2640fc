/**
 * @class   vtkLightFieldWriter
 * @brief   writes a vtkLightField as a light-field dataset directory
 *
 * Writes `Directory/lightfield.json` and one image per view per pass held by
 * the input: 8-bit passes as PNG (`coaxial/view_0000.png`, `label/...`),
 * Depth as 32-bit float EXR (`depth/view_0000.exr`). Rows are flipped from
 * vtkLightField's order (bottom row first) to the files' (top row first). The
 * rig (K, R, t and names), the label palette (vtkLightField::GetPalette()),
 * the projectors (K, R, t, size; masks as `projectors/mask_0000.png`) and the
 * provenance are written to the manifest; provenance text
 * that is valid JSON is stored as JSON, any other text as a JSON string. See
 * Data/README.md for the format.
 *
 * With a TileSize every pass is written as a tiled, MIP-mapped TIFF instead
 * (`coaxial/view_0000.tif`, TileSize x TileSize tiles, zip): the dataset a
 * vtkLightFieldReader reads like any other, and also out of core, tile by
 * tile through an image cache (vtkLightFieldReader::SetCacheSize). One file
 * per view keeps the manifest's one image per view per pass.
 *
 * Writing is atomic: everything goes to a temporary sibling directory,
 * `Directory.tmp-<pid>`, which is renamed onto Directory only when complete.
 * An existing Directory is replaced only after success, and only when it is
 * empty or a light-field dataset (it holds a lightfield.json), so a mistyped
 * path never deletes unrelated files. On failure the temporary directory is
 * removed, GetErrorCode() is set and one line naming the file and the problem
 * is reported (vtkErrorMacro; a vtkLightFieldErrorObserver gets it). Progress is reported once per
 * image.
 *
 * @sa vtkLightFieldReader vtkLightField
 */
#ifndef vtkLightFieldWriter_h
#define vtkLightFieldWriter_h

#include "lfdIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For std::string

class vtkLightField;

class LFDIO_EXPORT vtkLightFieldWriter : public vtkWriter
{
public:
  static vtkLightFieldWriter* New();
  vtkTypeMacro(vtkLightFieldWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The dataset directory to create (or replace).
   */
  vtkSetStringMacro(Directory);
  vtkGetStringMacro(Directory);
  ///@}

  ///@{
  /**
   * 0 (default): PNG and EXR images. A multiple of 16 from 16 to 4096 (TIFF
   * tiles are multiples of 16): tiled, MIP-mapped TIFF images with square
   * tiles of this size; any other value is an error when writing.
   */
  vtkSetMacro(TileSize, int);
  vtkGetMacro(TileSize, int);
  ///@}

  /**
   * The input light field.
   */
  vtkLightField* GetInput();

  /**
   * Runs the pipeline request; a C++ exception thrown by it is caught and
   * reported as an error (error code UnknownError, a message naming
   * the file), never passed on to the caller.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  vtkLightFieldWriter();
  ~vtkLightFieldWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* Directory = nullptr;
  int TileSize = 0;

private:
  vtkLightFieldWriter(const vtkLightFieldWriter&) = delete;
  void operator=(const vtkLightFieldWriter&) = delete;

  void Fail(unsigned long errorCode, const std::string& message);
};

#endif

/**
 * @class   vtkLightFieldTiler
 * @brief   rewrites a light-field dataset with tiled, MIP-mapped images, one image at a time
 *
 * `lfd tile`: reads the dataset that FileName names (its directory or its
 * lightfield.json) and writes Directory with every view's image of every
 * pass as a tiled, MIP-mapped TIFF of TileSize x TileSize tiles: the
 * dataset vtkLightFieldReader reads out of core (SetCacheSize), tile by tile
 * through a vtkLightFieldImageCache. The files are those vtkLightFieldWriter
 * writes with the same TileSize from the light field read whole, byte for
 * byte, but streamed: each image is read, written and dropped before the
 * next one is read, so that at most one view of each pass is in memory and
 * a dataset larger than memory can be tiled. The manifest's rig, palette,
 * projectors (their masks, small, are read whole and stay PNG) and
 * provenance are carried over.
 *
 * Writing is atomic, as vtkLightFieldWriter's (a temporary sibling renamed
 * onto Directory when complete; an existing Directory is replaced only
 * when it is empty or a dataset). Every failure (the source's manifest or
 * an image of it, a tile size that is not a multiple of 16 from 16 to
 * 4096, the disk) is one error naming the file (vtkErrorMacro; a
 * vtkLightFieldErrorObserver gets it) and Write() returns false.
 *
 * @sa vtkLightFieldReader vtkLightFieldWriter vtkLightFieldImageCache
 */
#ifndef vtkLightFieldTiler_h
#define vtkLightFieldTiler_h

#include "lfdIOModule.h" // For export macro
#include "vtkObject.h"

class LFDIO_EXPORT vtkLightFieldTiler : public vtkObject
{
public:
  static vtkLightFieldTiler* New();
  vtkTypeMacro(vtkLightFieldTiler, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The source dataset: its directory or its lightfield.json.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The dataset directory to create (or replace).
   */
  vtkSetStringMacro(Directory);
  vtkGetStringMacro(Directory);
  ///@}

  ///@{
  /**
   * Tile width and height in pixels, a multiple of 16 from 16 to 4096
   * (default 64).
   */
  vtkSetMacro(TileSize, int);
  vtkGetMacro(TileSize, int);
  ///@}

  /**
   * Tiles FileName into Directory; false after reporting the error.
   */
  bool Write();

protected:
  vtkLightFieldTiler();
  ~vtkLightFieldTiler() override;

  char* FileName = nullptr;
  char* Directory = nullptr;
  int TileSize = 64;

private:
  vtkLightFieldTiler(const vtkLightFieldTiler&) = delete;
  void operator=(const vtkLightFieldTiler&) = delete;
};

#endif

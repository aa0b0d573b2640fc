/**
 * @class   vtkLightFieldImageCache
 * @brief   the pixels of a light field larger than memory, read tile by tile
 *
 * A vtkLightFieldTexelSource over OpenImageIO's ImageCache: each pass it
 * serves is one tiled image file per view (`lfd tile`,
 * vtkLightFieldTiler), and the samplers' texel reads load only the tiles
 * they touch, within a memory budget (SetCacheSize): when the budget is
 * full the least recently used tiles are dropped and read again if a ray
 * needs them. vtkLightFieldReader builds one in its out-of-core mode.
 *
 * Each thread keeps its last few tiles pinned (a small per-thread table,
 * least recently used out) so that the 2 x 2 texels of a bilinear lookup,
 * which almost always share a tile, cost one table search and no call into
 * the cache. A tile that cannot be read (a file deleted or damaged after it
 * was opened) reads as zeros and GetError() names the file.
 *
 * @sa vtkLightFieldTexelSource vtkLightFieldReader vtkLightFieldTiler
 */
#ifndef vtkLightFieldImageCache_h
#define vtkLightFieldImageCache_h

#include "lfdIOModule.h" // For export macro
#include "vtkLightFieldTexelSource.h"

#include <memory> // For std::unique_ptr
#ifndef __VTK_WRAP__
#include <string> // For std::string
#include <vector> // For std::vector
#endif

class LFDIO_EXPORT vtkLightFieldImageCache : public vtkLightFieldTexelSource
{
public:
  static vtkLightFieldImageCache* New();
  vtkTypeMacro(vtkLightFieldImageCache, vtkLightFieldTexelSource);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Memory budget of the tile cache, in bytes (default 256 MiB, at least
   * 1 MiB).
   */
  void SetCacheSize(vtkTypeInt64 bytes);
  vtkGetMacro(CacheSize, vtkTypeInt64);
  ///@}

  bool HasPass(int pass) override;
  bool HasLabel(int label) override;

  ///@{
  /**
   * The cache's statistics since it was created: tiles read from the files
   * (a tile dropped and read again counts again), bytes of pixels read,
   * bytes of pixels of every level of the files opened, and the most tiles
   * held at once.
   */
  vtkTypeInt64 GetTilesRead();
  vtkTypeInt64 GetBytesRead();
  vtkTypeInt64 GetImageBytes();
  vtkTypeInt64 GetPeakTiles();
  ///@}

  /**
   * The first tile that could not be read ("file: reason"), or an empty
   * string.
   */
  const char* GetError();

#ifndef __VTK_WRAP__
  const lfd::TexelSource* GetTexels(int pass) override;

  /**
   * Serves `pass` from `files` (one per view, each a tiled image of width x
   * height pixels of the pass's type and components). Replaces what the
   * pass was served from.
   */
  void SetPassFiles(int pass, const std::vector<std::string>& files, int width, int height);
#endif

protected:
  vtkLightFieldImageCache();
  ~vtkLightFieldImageCache() override;

  vtkTypeInt64 CacheSize;

private:
  vtkLightFieldImageCache(const vtkLightFieldImageCache&) = delete;
  void operator=(const vtkLightFieldImageCache&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif

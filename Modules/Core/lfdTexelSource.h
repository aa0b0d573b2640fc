/**
 * @file   lfdTexelSource.h
 * @brief  texels of one pass read on demand (a light field larger than memory)
 *
 * The interface lfd::ViewStack reads a pass through when its pixels are not
 * in memory (ViewStack::Source). Plain C++17, no VTK: the implementation
 * over OpenImageIO's ImageCache lives in LFD::IO (vtkLightFieldImageCache).
 */
#ifndef lfdTexelSource_h
#define lfdTexelSource_h

namespace lfd
{

class TexelSource
{
public:
  virtual ~TexelSource() = default;

  /**
   * The values (the pass's components, contiguous) of the pixel at OpenCV
   * coordinates (x, y) of view `view`, which the caller keeps inside the
   * image. Thread-safe; the pointer stays valid until the calling thread's
   * next Texel() call on this source, so a caller reads the texel at once.
   */
  virtual const void* Texel(int view, int x, int y) const = 0;
};

}

#endif

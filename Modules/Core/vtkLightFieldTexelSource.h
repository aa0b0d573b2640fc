/**
 * @class   vtkLightFieldTexelSource
 * @brief   pixels of a light field that are read on demand, not held in memory
 *
 * A light field larger than memory keeps its rig and metadata in a
 * vtkLightField but serves the pixels of some passes through a texel
 * source (vtkLightField::SetTexelSource): the samplers read each texel
 * through lfd::TexelSource (lfd::ViewStack::Source), the one hook where
 * lfdCylinderSampling.h and lfdTwoPlaneSampling.h read pixels. Core only
 * defines the interface; LFD::IO implements it over OpenImageIO's
 * ImageCache (vtkLightFieldImageCache), so Core does not depend on a file
 * library.
 *
 * @sa vtkLightField vtkLightFieldImageCache
 */
#ifndef vtkLightFieldTexelSource_h
#define vtkLightFieldTexelSource_h

#include "lfdCoreModule.h" // For export macro
#include "vtkObject.h"

namespace lfd
{
class TexelSource;
}

class LFDCORE_EXPORT vtkLightFieldTexelSource : public vtkObject
{
public:
  vtkTypeMacro(vtkLightFieldTexelSource, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Whether the source serves the pixels of `pass` (a vtkLightField::Pass).
   */
  virtual bool HasPass(int pass) = 0;

  /**
   * Whether the Label pass the source serves holds `label` anywhere (false
   * without one): vtkLightField::HasLabel() for a pass not in memory.
   */
  virtual bool HasLabel(int label) = 0;

#ifndef __VTK_WRAP__
  /**
   * The texels of `pass`, or nullptr when the source does not serve it.
   * Owned by the source.
   */
  virtual const lfd::TexelSource* GetTexels(int pass) = 0;
#endif

protected:
  vtkLightFieldTexelSource() = default;
  ~vtkLightFieldTexelSource() override = default;

private:
  vtkLightFieldTexelSource(const vtkLightFieldTexelSource&) = delete;
  void operator=(const vtkLightFieldTexelSource&) = delete;
};

#endif

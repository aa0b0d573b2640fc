/**
 * @file   lfdProjectorMasks.h
 * @brief  The colours of a projector mask stack (vtkLightField::GetProjectorMasks()).
 *
 * A mask stack is a Wp x Hp x P image whose RGB uint8 colours are the point
 * array "Mask" or, for masks read from image files, the scalars. The capture,
 * the scene logic's mask command and the projector view read it through this
 * one function.
 */
#ifndef lfdProjectorMasks_h
#define lfdProjectorMasks_h

#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

namespace lfd
{
/// The RGB uint8 colours of `masks` ("Mask", else the scalars), or nullptr
/// when it has none (or `masks` is null).
inline vtkUnsignedCharArray* GetMaskColours(vtkImageData* masks)
{
  if (!masks)
  {
    return nullptr;
  }
  vtkDataArray* data = masks->GetPointData()->GetArray("Mask");
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(data ? data : masks->GetPointData()->GetScalars());
  return rgb && rgb->GetNumberOfComponents() == 3 ? rgb : nullptr;
}
}

#endif

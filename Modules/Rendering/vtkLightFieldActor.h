/**
 * @class   vtkLightFieldActor
 * @brief   a prop that shows a light field in a vtkRenderer
 *
 * vtkLightFieldActor holds a vtkLightFieldMapper and draws it with the
 * opaque geometry, so it composites by depth with the other actors of the
 * renderer (its pixels carry an approximate depth). Bounds come from the
 * mapper, so vtkRenderer::ResetCamera frames it.
 *
 * @sa vtkLightFieldMapper
 */
#ifndef vtkLightFieldActor_h
#define vtkLightFieldActor_h

#include "lfdRenderingModule.h" // For export macro
#include "vtkProp3D.h"

class vtkLightFieldMapper;

class LFDRENDERING_EXPORT vtkLightFieldActor : public vtkProp3D
{
public:
  static vtkLightFieldActor* New();
  vtkTypeMacro(vtkLightFieldActor, vtkProp3D);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mapper that computes and draws the light field.
   */
  virtual void SetMapper(vtkLightFieldMapper* mapper);
  vtkGetObjectMacro(Mapper, vtkLightFieldMapper);
  ///@}

  double* GetBounds() override;
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
  void ReleaseGraphicsResources(vtkWindow* window) override;
  vtkMTimeType GetMTime() override;

protected:
  vtkLightFieldActor();
  ~vtkLightFieldActor() override;

  vtkLightFieldMapper* Mapper = nullptr;

private:
  vtkLightFieldActor(const vtkLightFieldActor&) = delete;
  void operator=(const vtkLightFieldActor&) = delete;
};

#endif

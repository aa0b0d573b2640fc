/**
 * @class   vtkLightFieldSceneInitializer
 * @brief   builds a first scene for any light field: a camera that frames the object and a cage
 * around it (one box per label, N slabs, or one box)
 *
 * A light field imported from COLMAP or transforms.json, captured or split
 * has no scene yet. Initialize() gives the scene logic's light field one,
 * as `lfd scene init` does:
 *
 * - the object's extent is its visual hull (Laurentini 1994), carved from
 *   the silhouettes of the Coaxial pass (brighter than Threshold) with the
 *   rig's calibration by vtkLabelPropagation (Resolution voxels along the
 *   longest side): the labelled proxy that class propagates labels with;
 * - BoxMode LABELS (needs a Label pass): every view's Label pass is
 *   painted onto the hull, each voxel some pixel sees takes the majority
 *   label of the pixels that see it (vtkLabelPropagation), and
 *   vtkPartCageSource builds one box per label around those voxels (each
 *   label's extent along the slab axis trimmed by OutlierFraction at both
 *   ends), slabs along the hull's longest side sharing their corners (Chen
 *   et al. 2005, Fig. 13);
 * - BoxMode SLABS: NumberOfSlabs boxes stacked along the ring axis (the
 *   coordinate axis nearest it; the longest side of the hull when the rig has
 *   no fitted ring), label 1, filling the hull's bounds grown by Margin;
 * - BoxMode ONE: one box of label 1 around the hull (grown by Margin);
 * - the camera sits at view 0's centre with its image "up", looks at the
 *   centre of the hull's bounds, and its view angle holds the bounds'
 *   sphere with 10 % to spare; the render size is the rig's image size;
 * - for a light field without a Label pass the render's object threshold is
 *   Threshold, so rendering and the hull agree on what is object.
 *
 * Each step is an edit of the scene logic (undoable, validated). On
 * failure Initialize() returns false and reports one line with
 * vtkErrorMacro (no light field, LABELS without a Label pass, an empty
 * hull, parts that slabs cannot separate).
 *
 * @sa vtkLightFieldSceneLogic vtkLabelPropagation vtkPartCageSource
 */
#ifndef vtkLightFieldSceneInitializer_h
#define vtkLightFieldSceneInitializer_h

#include "lfdSceneModule.h" // For export macro
#include "vtkObject.h"

class vtkLightFieldSceneLogic;

class LFDSCENE_EXPORT vtkLightFieldSceneInitializer : public vtkObject
{
public:
  static vtkLightFieldSceneInitializer* New();
  vtkTypeMacro(vtkLightFieldSceneInitializer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BoxModes
  {
    LABELS = 0,
    SLABS,
    ONE
  };

  ///@{
  /**
   * How the cage is built (default LABELS).
   */
  vtkSetClampMacro(BoxMode, int, LABELS, ONE);
  vtkGetMacro(BoxMode, int);
  ///@}

  ///@{
  /**
   * Boxes of BoxMode SLABS (default 3).
   */
  vtkSetClampMacro(NumberOfSlabs, int, 1, 1024);
  vtkGetMacro(NumberOfSlabs, int);
  ///@}

  ///@{
  /**
   * Silhouette threshold on the Coaxial pass (mean of RGB), default 20.
   */
  vtkSetClampMacro(Threshold, double, 0.0, 255.0);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * Voxels of the hull along its longest side, default 128 (vtkLabelPropagation's).
   */
  vtkSetClampMacro(Resolution, int, 8, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * BoxMode LABELS: the fraction of each label's voxels, at each end along
   * the slab axis, left out of its extent (default 0.02): a visual hull
   * cannot carve the hollow between two parts, and the few voxels of one
   * part it leaves standing beside the next would move their boundary.
   */
  vtkSetClampMacro(OutlierFraction, double, 0.0, 0.25);
  vtkGetMacro(OutlierFraction, double);
  ///@}

  ///@{
  /**
   * How far SLABS and ONE reach beyond the hull, as a fraction of its
   * largest side (default 0.05, vtkPartCageSource's margin).
   */
  vtkSetClampMacro(Margin, double, 0.0, 10.0);
  vtkGetMacro(Margin, double);
  ///@}

  /**
   * Gives the logic's light field (vtkLightFieldSceneLogic::GetLightField)
   * a camera, a render size and a cage; false with an ErrorEvent on failure.
   */
  bool Initialize(vtkLightFieldSceneLogic* logic);

  /**
   * Bounds of the centres of the hull's voxels that the views see, found
   * by the last Initialize().
   */
  vtkGetVector6Macro(ObjectBounds, double);

protected:
  vtkLightFieldSceneInitializer();
  ~vtkLightFieldSceneInitializer() override;

  int BoxMode = LABELS;
  int NumberOfSlabs = 3;
  double Threshold = 20.0;
  int Resolution = 128;
  double Margin = 0.05;
  double OutlierFraction = 0.02;
  double ObjectBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };

private:
  vtkLightFieldSceneInitializer(const vtkLightFieldSceneInitializer&) = delete;
  void operator=(const vtkLightFieldSceneInitializer&) = delete;
};

#endif

/**
 * @class   vtkLabelPropagation
 * @brief   spreads labels painted in a few views to every view through a 3D proxy
 *
 * A light field captured without projectors can still be split: the user
 * paints the parts in two or three views (label images: 0 = unpainted,
 * 1..N = parts) and vtkLabelPropagation carries the labels to every view
 * through a geometric proxy of the object, as Chen, Ofek, Shum and Levoy
 * suggest (I3D 2005, section 4.1). The proxy is a voxel grid of Resolution
 * voxels along its longest side:
 *
 * - DEPTH (the default when the light field has a `Depth` pass): the
 *   surface points of every view's depth map;
 * - VISUAL_HULL (otherwise): the voxels that project onto the object's
 *   silhouette in every view (Laurentini's visual hull, 1994): a voxel is
 *   kept when its projected centre lies within its projected half-diagonal,
 *   plus SilhouetteTolerance pixels, of the silhouette, so parts thinner
 *   than a voxel and small calibration errors survive.
 *   Silhouettes are the Coaxial pass brighter than Threshold (mean of RGB),
 *   cleaned by a morphological opening and closing, as is usual for the
 *   Middlebury rings on black, their holes filled unless they show the
 *   backdrop (lfd::segmentation::FillObjectHoles). The grid is placed by a coarse carve of the
 *   box the rig's cameras surround, then carved at full resolution.
 *
 * Each pixel of each view sees the first proxy voxel along its ray (with
 * depth: the voxel holding its depth point), which is the visibility test.
 * Painted pixels vote for the label of the voxel they see; every other voxel
 * takes the label of the nearest voted voxel (a breadth-first flood over
 * the grid); and every object pixel of every view takes the label of the
 * voxel it sees. Painted pixels keep their painted label. Pixels that see
 * no voxel are unlabelled (0).
 *
 * Bad input is one readable error: no painted view, a painted view out of
 * range, a label image whose size differs from the views', no Coaxial pass
 * for a visual hull, an empty hull.
 *
 * @sa vtkLightFieldSplitter vtkBoxCoverageCheck
 */
#ifndef vtkLabelPropagation_h
#define vtkLabelPropagation_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkLightFieldSplitter.h"

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <map> // For std::map

class vtkDataArray;
class vtkImageData;
class vtkPolyData;

class LFDSEGMENTATION_EXPORT vtkLabelPropagation : public vtkLightFieldSplitter
{
public:
  static vtkLabelPropagation* New();
  vtkTypeMacro(vtkLabelPropagation, vtkLightFieldSplitter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The painted label image of a view: W x H, one uint8 component (the
   * image's scalars), VTK row order (bottom row first, as VTK's image
   * readers deliver it).
   */
  void SetPaintedView(int view, vtkImageData* labels);
  void RemoveAllPaintedViews();
  ///@}

  /**
   * Paints every view at once from a one-component array of width x height
   * x views values in the light field's layout, e.g. a Label pass (0 =
   * unpainted): view v gets a copy of the v-th width x height slice. A
   * splitter that decides only some pixels (vtkProjectorSegmentation)
   * completes the others this way.
   */
  void SetPaintedViews(vtkDataArray* labels, int width, int height);

  /**
   * The number of painted views.
   */
  int GetNumberOfPaintedViews() const { return static_cast<int>(this->Painted.size()); }

  enum ProxyType
  {
    AUTOMATIC = 0,
    DEPTH,
    VISUAL_HULL
  };

  ///@{
  /**
   * The proxy. Default AUTOMATIC: DEPTH when the input has a Depth pass.
   */
  vtkSetClampMacro(Proxy, int, AUTOMATIC, VISUAL_HULL);
  vtkGetMacro(Proxy, int);
  ///@}

  ///@{
  /**
   * Voxels along the longest side of the proxy grid. Default 128.
   */
  vtkSetClampMacro(Resolution, int, 8, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Silhouette threshold on the Coaxial pass (mean of RGB). Default 20.
   */
  vtkSetClampMacro(Threshold, double, 0.0, 255.0);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * Pixels of silhouette or calibration error the visual hull tolerates: a
   * voxel survives a view when the silhouette is within its projected
   * half-diagonal plus this. Default 1.5 (real rings: templeRing agrees
   * 0.921 -> 0.939 with the painting rule); 0 suits exact synthetic
   * calibrations.
   */
  vtkSetClampMacro(SilhouetteTolerance, double, 0.0, 100.0);
  vtkGetMacro(SilhouetteTolerance, double);
  ///@}

  /**
   * Number of occupied voxels of the last proxy.
   */
  vtkGetMacro(NumberOfProxyVoxels, vtkIdType);

  /**
   * The labelled surface of the last update's proxy: one vertex per voxel
   * that some object pixel sees, at its centre, with the voxel's label in
   * the cell array "Label" (the majority of the painted pixels seeing it):
   * what vtkPartCageSource turns into one box per part (`lfd scene init`).
   * Empty before an update and after a failed one.
   */
  vtkPolyData* GetProxyVoxels();

protected:
  vtkLabelPropagation();
  ~vtkLabelPropagation() override;

  bool Split(vtkLightField* input, vtkLightField* output, std::string& error) override;

  std::map<int, vtkSmartPointer<vtkImageData>> Painted;
  int Proxy = AUTOMATIC;
  int Resolution = 128;
  double Threshold = 20.0;
  double SilhouetteTolerance = 1.5;
  vtkIdType NumberOfProxyVoxels = 0;
  vtkSmartPointer<vtkPolyData> ProxyVoxels;

private:
  vtkLabelPropagation(const vtkLabelPropagation&) = delete;
  void operator=(const vtkLabelPropagation&) = delete;
};

#endif

/**
 * @class   vtkScanlineSplit
 * @brief   splits a light field by image rows (the paper's scan-line split)
 *
 * For a ring whose cameras are level and at the same height, a horizontal
 * cut through the object (above the neck, below the waist) is the same image
 * row in every view (Chen, Ofek, Shum, Levoy, I3D 2005, section 4). The
 * boundaries are image rows, counted from the top (OpenCV convention): rows
 * above the first boundary are band 0, rows from boundary i to boundary
 * i + 1 - 1 are band i + 1. Band b gets label b + 1 unless SetBandLabel()
 * says otherwise. Only object pixels are labelled: the input's Label pass
 * > 0 when it has one (so a scan-line split can refine a silhouette), else
 * the Coaxial pass brighter than Threshold (mean of RGB), cleaned with a
 * morphological opening and closing of MorphologyRadius pixels, its holes
 * filled unless they show the backdrop (the object's grooves and shadows
 * darker than Threshold are object; lfd::segmentation::FillObjectHoles).
 *
 * @sa vtkLightFieldSplitter vtkProjectorSegmentation vtkLabelPropagation
 */
#ifndef vtkScanlineSplit_h
#define vtkScanlineSplit_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkLightFieldSplitter.h"

#include <vector> // For std::vector

class LFDSEGMENTATION_EXPORT vtkScanlineSplit : public vtkLightFieldSplitter
{
public:
  static vtkScanlineSplit* New();
  vtkTypeMacro(vtkScanlineSplit, vtkLightFieldSplitter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Boundary rows (from the top), in any order; duplicates are ignored.
   */
  void AddBoundary(int row);
  void RemoveAllBoundaries();
  int GetNumberOfBoundaries() const { return static_cast<int>(this->Boundaries.size()); }
  ///@}

  ///@{
  /**
   * Label of band `band` (0 = the top band); by default band + 1.
   */
  void SetBandLabel(int band, int label);
  int GetBandLabel(int band) const;
  ///@}

  ///@{
  /**
   * Coaxial brightness (0..255, mean of RGB) above which a pixel is the
   * object when the input has no Label pass. Default 10.
   */
  vtkSetClampMacro(Threshold, double, 0.0, 255.0);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * Radius of the clean-up of the thresholded object mask; 0 disables it
   * (the hole filling too). Default 1.
   */
  vtkSetClampMacro(MorphologyRadius, int, 0, 50);
  vtkGetMacro(MorphologyRadius, int);
  ///@}

protected:
  vtkScanlineSplit();
  ~vtkScanlineSplit() override;

  bool Split(vtkLightField* input, vtkLightField* output, std::string& error) override;

  std::vector<int> Boundaries;
  std::vector<int> BandLabels;
  double Threshold = 10.0;
  int MorphologyRadius = 1;

private:
  vtkScanlineSplit(const vtkScanlineSplit&) = delete;
  void operator=(const vtkScanlineSplit&) = delete;
};

#endif

/**
 * @class   vtkBoxCoverageCheck
 * @brief   checks that every part's rest boxes cover its labelled pixels in every view
 *
 * A deformation moves the rays of a part only where they pass through the
 * part's box, so each box must hold its part (Chen, Ofek, Shum, Levoy,
 * I3D 2005, section 4.1: "the bounding box of each sub-light field"). For
 * every view and every label of the light field (input port 0, its `Label`
 * pass and rig), vtkBoxCoverageCheck projects the rest boxes of that label
 * of the cage (input port 1: a vtkUnstructuredGrid read through
 * vtkDeformationCage, which gives each box's label and rest corners; a grid
 * that vtkDeformationCage::CheckGridArrays() refuses is an error) into the
 * view, and counts the label's pixels that fall inside the
 * projection (the convex hull of the 8 projected corners; the union over
 * the label's boxes).
 *
 * The output is a vtkTable, one row per (label, view) with pixels of that
 * label: columns "Label", "View", "Pixels", "Inside", "Fraction". Per
 * label, GetWorstFraction() and GetWorstView() give the worst view and
 * GetViewsBelow() the views under Threshold; GetPassed() is true when no
 * view of any label is under Threshold. A label with pixels but no box
 * covers nothing (fraction 0). GetViewCoverage() gives, per view, the
 * smallest fraction of its labels (what the Studio's gantry-camera view
 * shows beside the photo).
 *
 * Output port 1 (GetOutsideMask()) is a W x H x V vtkImageData laid out
 * as the light field (rows bottom first, see vtkLightField) with the uint8
 * point array "Outside": 1 at the labelled pixels that fall outside every
 * rest box of their label, 0 elsewhere, so a view can highlight them.
 *
 * @sa vtkLightFieldSplitter vtkDeformationCage
 */
#ifndef vtkBoxCoverageCheck_h
#define vtkBoxCoverageCheck_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkTableAlgorithm.h"

#include <vector> // For std::vector

class vtkImageData;

class LFDSEGMENTATION_EXPORT vtkBoxCoverageCheck : public vtkTableAlgorithm
{
public:
  static vtkBoxCoverageCheck* New();
  vtkTypeMacro(vtkBoxCoverageCheck, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's request; a C++ exception thrown by it becomes this
   * algorithm's error (error code UnknownError), see lfdRequestGuard.h.
   */
  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * The light field (port 0) and the cage (port 1).
   */
  void SetCageConnection(vtkAlgorithmOutput* cage);
  void SetCageData(vtkDataObject* cage);
  ///@}

  ///@{
  /**
   * Smallest acceptable fraction of a label's pixels inside its boxes, per
   * view. Default 0.95.
   */
  vtkSetClampMacro(Threshold, double, 0.0, 1.0);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * The summary of the last update: the labels found (in increasing order),
   * and per label its worst view, that view's fraction and every view under
   * Threshold.
   */
  int GetNumberOfLabels() const { return static_cast<int>(this->Labels.size()); }
  int GetLabel(int index) const;
  double GetWorstFraction(int index) const;
  int GetWorstView(int index) const;
  std::vector<int> GetViewsBelow(int index) const;
  bool GetPassed() const;
  ///@}

  /**
   * The smallest fraction over the labels of view `view` in the last
   * update; 1 for a view without labelled pixels, -1 for an invalid view.
   */
  double GetViewCoverage(int view) const;

  /**
   * Output port 1: the labelled pixels outside their boxes (see above).
   */
  vtkImageData* GetOutsideMask();

  ///@{
  /**
   * Labels of the last update that do not match between the light field and
   * the cage, in increasing order: labels with pixels but no box (they cover
   * nothing: fraction 0), and labels of boxes that have no pixel in any view
   * (a scene written for another split). Both empty when they match.
   */
  std::vector<int> GetLabelsWithoutBox() const { return this->LabelsWithoutBox; }
  std::vector<int> GetBoxLabelsWithoutPixels() const { return this->BoxLabelsWithoutPixels; }
  ///@}

protected:
  vtkBoxCoverageCheck();
  ~vtkBoxCoverageCheck() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  double Threshold = 0.95;
  struct Summary
  {
    int Label;
    double WorstFraction;
    int WorstView;
    std::vector<int> Below;
  };
  std::vector<Summary> Labels;
  std::vector<int> LabelsWithoutBox;
  std::vector<int> BoxLabelsWithoutPixels;
  std::vector<double> ViewCoverage;

private:
  vtkBoxCoverageCheck(const vtkBoxCoverageCheck&) = delete;
  void operator=(const vtkBoxCoverageCheck&) = delete;
};

#endif

/**
 * @class   vtkLabelAccuracy
 * @brief   how well a split light field's labels match the true ones: accuracy and confusion
 *
 * vtkLabelAccuracy compares the Label pass of a split light field (paper
 * Sec. 4: projectors, scan lines or propagation) with the true Label pass of
 * the same views (a synthetic capture), on the truth's object pixels
 * (label > 0): the share of them the split labels the same (GetAccuracy(),
 * in percent) and the confusion of every true label with every found one
 * (GetConfusion(); found label 0 = left unlabelled). `lfd split --truth`
 * prints these figures.
 *
 * Compute() holds no error state: it returns the reason it cannot compare,
 * for the caller to say with the file it came from.
 *
 * @sa vtkLightFieldSplitter vtkGroundTruthEvaluator
 */
#ifndef vtkLabelAccuracy_h
#define vtkLabelAccuracy_h

#include "lfdEvaluationModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkLightField;

class LFDEVALUATION_EXPORT vtkLabelAccuracy : public vtkObject
{
public:
  static vtkLabelAccuracy* New();
  vtkTypeMacro(vtkLabelAccuracy, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Compares the Label passes of `split` and `truth`. Returns "" on
   * success, else one line about `truth` ("has no Label pass to compare
   * with", "its Label pass has another size than the split light field's")
   * or `split` ("the split light field has no Label pass"); the figures are
   * then zero.
   */
  std::string Compute(vtkLightField* split, vtkLightField* truth);

  ///@{
  /**
   * The figures of the last Compute(): object pixels of the truth, those
   * the split labels the same, their share in percent (0 without object
   * pixels), and the largest label met in either pass.
   */
  vtkGetMacro(ObjectPixels, vtkIdType);
  vtkGetMacro(CorrectPixels, vtkIdType);
  double GetAccuracy() const;
  vtkGetMacro(MaximumLabel, int);
  ///@}

  /**
   * Object pixels of true label `truthLabel` (1..255) that the split labels
   * `foundLabel` (0..255; 0 = unlabelled); 0 out of range.
   */
  vtkIdType GetConfusion(int truthLabel, int foundLabel) const;

protected:
  vtkLabelAccuracy();
  ~vtkLabelAccuracy() override;

  vtkIdType ObjectPixels = 0;
  vtkIdType CorrectPixels = 0;
  int MaximumLabel = 0;

private:
  vtkLabelAccuracy(const vtkLabelAccuracy&) = delete;
  void operator=(const vtkLabelAccuracy&) = delete;

  /// 256 x 256 counts, row = true label, column = found label.
  std::vector<vtkIdType> Confusion;
};

#endif

/**
 * @class   vtkLightFieldSplitter
 * @brief   superclass of the filters that split a light field into parts
 *
 * A splitter takes a vtkLightField and outputs the same light field (the
 * passes, rig, palette and projectors are shared, not copied) with a new
 * `Label` pass (0 = unlabelled or background, 1..N = parts) and, when the
 * splitter measures it, a `Confidence` pass (0..255). Subclasses implement
 * Split(); a failure is one readable error line (see vtkLightFieldAlgorithm
 * and vtkLightFieldErrorObserver) and an empty output. Progress is reported by the
 * subclasses once per view.
 *
 * @sa vtkProjectorSegmentation vtkScanlineSplit vtkLabelPropagation
 */
#ifndef vtkLightFieldSplitter_h
#define vtkLightFieldSplitter_h

#include "lfdSegmentationModule.h" // For export macro
#include "vtkLightFieldAlgorithm.h"

class LFDSEGMENTATION_EXPORT vtkLightFieldSplitter : public vtkLightFieldAlgorithm
{
public:
  vtkTypeMacro(vtkLightFieldSplitter, vtkLightFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The light field to split (input port 0).
   */
  void SetInputData(vtkLightField* input);
  ///@}

protected:
  vtkLightFieldSplitter();
  ~vtkLightFieldSplitter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * Writes the Label pass (and Confidence when measured) of `output`, a
   * shallow copy of `input`. On failure returns false with the message in
   * `error` (one line).
   */
  virtual bool Split(vtkLightField* input, vtkLightField* output, std::string& error) = 0;

private:
  vtkLightFieldSplitter(const vtkLightFieldSplitter&) = delete;
  void operator=(const vtkLightFieldSplitter&) = delete;
};

#endif

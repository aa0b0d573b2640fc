/**
 * @class   vtkIncrementalLightFieldWriter
 * @brief   writes a light-field dataset view after view, as a capture takes them
 *
 * A capture (paper Sec. 4.1: a camera on a ring gantry photographs every
 * position under each pass) can fail or be killed at any moment; what it has
 * taken must survive and be readable. This writer produces the same dataset
 * as vtkLightFieldWriter (Data/README.md, one definition of the format in
 * lfdLightFieldManifest.h), one complete view at a time:
 *
 * - Start() creates Directory (atomically: a temporary sibling renamed into
 *   place) with `capture.json`, the plan (the manifest of every planned
 *   view, format "lfd-capture"), the pass folders and the projector masks;
 *   there is no lightfield.json until the first view is complete.
 * - SetViewFrame() hands over the photograph of each pass of the next view;
 *   CommitView() writes its images (each under a temporary name, flushed
 *   and renamed) and then replaces lightfield.json by one that lists the
 *   views 0 .. n (also atomically). So lightfield.json always lists only
 *   complete views and the dataset is readable (vtkLightFieldReader) after
 *   every view; images of a view that was not committed are not listed and
 *   are overwritten when the view is taken again.
 * - Resume() opens a dataset started with the same plan (capture.json must
 *   match it exactly) and continues after its complete views, checking
 *   that each listed image is there.
 *
 * The plan is a vtkLightField without pass arrays: its layout (width,
 * height, views), rig (one camera per planned view), projectors with their
 * masks, palette and provenance. Every failure is one error naming the
 * dataset and the file (vtkErrorMacro) and the call returns false.
 *
 * @sa vtkLightFieldWriter vtkCaptureSession
 */
#ifndef vtkIncrementalLightFieldWriter_h
#define vtkIncrementalLightFieldWriter_h

#include "lfdIOModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkLightField;

class LFDIO_EXPORT vtkIncrementalLightFieldWriter : public vtkObject
{
public:
  static vtkIncrementalLightFieldWriter* New();
  vtkTypeMacro(vtkIncrementalLightFieldWriter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The dataset directory. Default nullptr.
   */
  vtkSetStringMacro(Directory);
  vtkGetStringMacro(Directory);
  ///@}

  ///@{
  /**
   * The planned light field (layout, rig, projectors, masks, palette,
   * provenance; its pass arrays are ignored). Default nullptr.
   */
  virtual void SetPlan(vtkLightField* plan);
  vtkLightField* GetPlan();
  ///@}

  ///@{
  /**
   * The passes photographed at every view (vtkLightField::COAXIAL, CODED,
   * FLOOD; 8-bit colour passes), in the order they are taken. Default none.
   */
  void AddPass(int pass);
  void RemoveAllPasses();
  int GetNumberOfPasses() const;
  int GetPass(int index) const;
  ///@}

  /**
   * Creates a new dataset for the plan. Refused when Directory exists and
   * is not an empty folder (resume it, or choose another name).
   */
  bool Start();

  /**
   * Opens the dataset that Start() created for the same plan and passes,
   * with its complete views.
   */
  bool Resume();

  /**
   * The photograph of `pass` for the next view: RGB uint8, the plan's width
   * x height, row 0 = top of the photograph (as vtkCaptureCamera gives
   * it). The writer keeps a reference until CommitView().
   */
  bool SetViewFrame(int pass, vtkImageData* frame);

  /**
   * Writes the next view (every pass must have its frame) and lists it in
   * lightfield.json.
   */
  bool CommitView();

  ///@{
  /**
   * Views listed as complete, and views planned.
   */
  vtkGetMacro(NumberOfCompleteViews, int);
  int GetNumberOfPlannedViews();
  ///@}

protected:
  vtkIncrementalLightFieldWriter();
  ~vtkIncrementalLightFieldWriter() override;

  char* Directory = nullptr;
  int NumberOfCompleteViews = 0;

private:
  vtkIncrementalLightFieldWriter(const vtkIncrementalLightFieldWriter&) = delete;
  void operator=(const vtkIncrementalLightFieldWriter&) = delete;

  /// The directory (no trailing separator) and the plan checked; empty and
  /// an error reported when either is missing or invalid.
  std::string CheckPlan();
  bool Fail(const std::string& message);

  vtkSmartPointer<vtkLightField> Plan;
  std::vector<int> Passes;
  std::vector<vtkSmartPointer<vtkImageData>> Frames;
  bool Open = false;
};

#endif

/**
 * @class   vtkLightFieldErrorObserver
 * @brief   collects the error (and warning) messages of the objects it observes
 *
 * Errors in this library take VTK's one path: a class reports a failure once
 * with vtkErrorMacro (an algorithm also sets GetErrorCode()), and the macro
 * invokes an ErrorEvent with the text when the object is observed, or prints
 * it otherwise. vtkLightFieldErrorObserver is how a caller gets that text:
 *
 * @code{.cpp}
 * vtkNew<vtkLightFieldErrorObserver> errors;
 * errors->Observe(reader);
 * reader->Update();
 * if (errors->HasError()) { std::cerr << errors->GetErrorMessage() << "\n"; }
 * @endcode
 *
 * Observed messages are recorded, not printed. Each is recorded without VTK's
 * location prefix ("ERROR: In <file>, line <n>\n<class> (<address>): ") and
 * trailing blank lines (StripLocation()), so GetErrorMessage() is the one
 * line the class said, e.g. "scene.json: field \"cage\": ...".
 *
 * Observe() on an algorithm also observes its executive, whose error after a
 * failed request ("Algorithm vtkX(0x...) returned failure for request: ...")
 * repeats the failure the algorithm already reported: it is recorded, as
 * "vtkX failed", only when nothing else was, so that an algorithm that
 * returned failure without a message is not silent.
 *
 * An algorithm that runs another one internally observes it with its own
 * vtkLightFieldErrorObserver and reports the inner message as its own error,
 * so an observer on the outer algorithm sees it.
 */
#ifndef vtkLightFieldErrorObserver_h
#define vtkLightFieldErrorObserver_h

#include "lfdCoreModule.h" // For export macro
#include "vtkCommand.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkAlgorithm;
class vtkObject;

class LFDCORE_EXPORT vtkLightFieldErrorObserver : public vtkCommand
{
public:
  static vtkLightFieldErrorObserver* New();
  vtkTypeMacro(vtkLightFieldErrorObserver, vtkCommand);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Records the ErrorEvents and WarningEvents of `object` (and, for an
   * algorithm, the ErrorEvents of its executive) from now on; an object
   * already observed is left as it is. The object keeps a reference to this
   * observer until StopObserving().
   */
  void Observe(vtkObject* object);

  /**
   * Observe() `algorithm` and every algorithm upstream of it (as connected
   * now): the errors of a whole pipeline that one Update() runs.
   */
  void ObservePipeline(vtkAlgorithm* algorithm);

  ///@{
  /**
   * Stops observing `object` (and its executive), or every object observed.
   */
  void StopObserving(vtkObject* object);
  void StopObserving();
  ///@}

  ///@{
  /**
   * The recorded errors: whether there is one, the first (the failure's own
   * message; "" when none), and each in the order reported.
   */
  bool HasError() const { return !this->Errors.empty(); }
  const char* GetErrorMessage() const;
  int GetNumberOfErrors() const { return static_cast<int>(this->Errors.size()); }
  const char* GetError(int i) const;
  ///@}

  ///@{
  /**
   * The recorded warnings, as the errors.
   */
  bool HasWarning() const { return !this->Warnings.empty(); }
  const char* GetWarningMessage() const;
  int GetNumberOfWarnings() const { return static_cast<int>(this->Warnings.size()); }
  const char* GetWarning(int i) const;
  ///@}

  /**
   * Forgets the recorded errors and warnings (before the next update).
   */
  void Clear();

  /**
   * The message of a VTK error or warning text without VTK's location prefix
   * ("ERROR: In <file>, line <n>\n<class> (<address>): ", or "Warning: In
   * ...") and trailing blank lines. Text without the prefix is only trimmed.
   */
  static std::string StripLocation(const std::string& text);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override;

protected:
  vtkLightFieldErrorObserver();
  ~vtkLightFieldErrorObserver() override;

private:
  vtkLightFieldErrorObserver(const vtkLightFieldErrorObserver&) = delete;
  void operator=(const vtkLightFieldErrorObserver&) = delete;

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  std::vector<vtkWeakPointer<vtkObject>> Observed;
};

#endif

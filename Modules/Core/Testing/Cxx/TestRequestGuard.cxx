// lfd::GuardRequest (through lfdGuardedProcessRequestMacro): an exception thrown inside a pipeline
// request becomes the algorithm's error (ErrorEvent with the message, error code set, Update
// returns) instead of terminating the process.
#include "lfdRequestGuard.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"

#include <iostream>
#include <new>
#include <stdexcept>
#include <string>

namespace
{
/// A source whose RequestData throws what it is told to.
class ThrowingSource : public vtkPolyDataAlgorithm
{
public:
  static ThrowingSource* New();
  vtkTypeMacro(ThrowingSource, vtkPolyDataAlgorithm);

  int What = 0; // 0: nothing, 1: runtime_error, 2: bad_alloc

  vtkTypeBool ProcessRequest(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  ThrowingSource() { this->SetNumberOfInputPorts(0); }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override
  {
    if (this->What == 1)
    {
      throw std::runtime_error("field \"views\": boom");
    }
    if (this->What == 2)
    {
      throw std::bad_alloc();
    }
    return 1;
  }
};
vtkStandardNewMacro(ThrowingSource);
lfdGuardedProcessRequestMacro(ThrowingSource);
}

int TestRequestGuard(int, char*[])
{
  // The executive logs every failed request on stderr, which VTK's test
  // harness counts as a failure: the errors checked here are the expected ones.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  int failures = 0;
  std::string message;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&message);
  observer->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData)
    { *static_cast<std::string*>(clientData) = static_cast<const char*>(callData); });

  const struct
  {
    int What;
    const char* Expected; // empty: no error
  } cases[] = { { 0, "" },
    { 1, "ThrowingSource: field \"views\": boom" },
    { 2, "ThrowingSource: out of memory" } };
  for (const auto& c : cases)
  {
    vtkNew<ThrowingSource> source;
    source->AddObserver(vtkCommand::ErrorEvent, observer);
    source->What = c.What;
    message.clear();
    source->Update();
    const bool failed = source->GetErrorCode() != 0;
    const bool expectFailure = *c.Expected != '\0';
    if (failed != expectFailure || message.find(c.Expected) == std::string::npos ||
      (!expectFailure && !message.empty()))
    {
      std::cerr << "case " << c.What << ": error code " << source->GetErrorCode() << ", message '"
                << message << "', expected '" << c.Expected << "'\n";
      ++failures;
    }
    else
    {
      std::cout << "case " << c.What << ": '" << message << "'\n";
    }
  }
  return failures == 0 ? 0 : 1;
}

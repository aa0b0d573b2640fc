// vtkLightFieldErrorObserver, the one way to get an error's text back: a
// failing vtkLightFieldAlgorithm gives exactly its one line (the executive's
// "returned failure" repeat is not a second error), an algorithm that fails
// without a message is "<class> failed", warnings are kept apart, Clear()
// forgets, ObservePipeline() hears what is upstream, StopObserving() lets
// messages through again, and StripLocation()
// removes VTK's prefix from both kinds of text.
#include "lfdTestChecks.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightField.h"
#include "vtkLightFieldAlgorithm.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <cstdlib>
#include <iostream>
#include <string>

using lfdtest::Expect;

namespace
{
/// A source that fails with a message (Fail), fails silently, or warns.
class FailingSource : public vtkLightFieldAlgorithm
{
public:
  static FailingSource* New();
  vtkTypeMacro(FailingSource, vtkLightFieldAlgorithm);

  int Mode = 0; // 0: fail with a message, 1: fail without one, 2: warn and succeed

protected:
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override
  {
    this->ClearError();
    if (this->Mode == 0)
    {
      this->Fail(vtkLightField::GetData(outputs),
        vtkErrorCode::FileFormatError,
        "scene.json: field \"cage\": expected an object");
      return 0;
    }
    if (this->Mode == 2)
    {
      vtkWarningMacro("view 3 is a duplicate");
      return 1;
    }
    return 0;
  }
};
vtkStandardNewMacro(FailingSource);

/// A filter downstream of a FailingSource: fails only for want of input.
class Follower : public vtkLightFieldAlgorithm
{
public:
  static Follower* New();
  vtkTypeMacro(Follower, vtkLightFieldAlgorithm);

protected:
  Follower() { this->SetNumberOfInputPorts(1); }
};
vtkStandardNewMacro(Follower);
}

int TestErrorObserver(int, char*[])
{
  // The executive also logs failed requests to stderr through vtkLogger.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<FailingSource> source;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(source);
  source->Update();
  Expect(errors->GetNumberOfErrors() == 1 &&
      std::string(errors->GetErrorMessage()) == "scene.json: field \"cage\": expected an object" &&
      source->GetErrorCode() == vtkErrorCode::FileFormatError,
    "the failure's one line, once",
    errors->GetErrorMessage());

  errors->Clear();
  Expect(!errors->HasError() && *errors->GetErrorMessage() == '\0', "Clear() forgets", "");
  source->Mode = 1;
  source->Modified();
  source->Update();
  Expect(errors->GetNumberOfErrors() == 1 &&
      std::string(errors->GetErrorMessage()) == "FailingSource failed",
    "a silent failure is named by the executive's repeat",
    errors->GetErrorMessage());

  errors->Clear();
  source->Mode = 2;
  source->Modified();
  source->Update();
  Expect(!errors->HasError() && errors->GetNumberOfWarnings() == 1 &&
      std::string(errors->GetWarningMessage()) == "view 3 is a duplicate",
    "a warning is not an error",
    errors->GetWarningMessage());

  errors->Clear();
  vtkNew<Follower> follower;
  follower->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkLightFieldErrorObserver> pipeline;
  pipeline->ObservePipeline(follower);
  pipeline->ObservePipeline(follower); // observing twice records once
  source->Mode = 0;
  source->Modified();
  follower->Update();
  Expect(pipeline->GetNumberOfErrors() == 1 &&
      std::string(pipeline->GetErrorMessage()) == "scene.json: field \"cage\": expected an object",
    "ObservePipeline hears the upstream source, once",
    pipeline->GetErrorMessage());
  pipeline->StopObserving();

  errors->Clear();
  errors->StopObserving(source);
  vtkNew<vtkLightFieldErrorObserver> other;
  other->Observe(source);
  source->Mode = 0;
  source->Modified();
  source->Update();
  Expect(!errors->HasError() && other->HasError(), "StopObserving() stops recording", "");

  const std::string error = vtkLightFieldErrorObserver::StripLocation(
    "ERROR: In /src/Modules/IO/vtkLightFieldScene.cxx, line 190\nvtkLightFieldScene "
    "(0x55d0c0a0): a.json: field \"render\" (0x1): bad\n\n");
  Expect(error == "a.json: field \"render\" (0x1): bad", "StripLocation of an error", error);
  const std::string warning =
    vtkLightFieldErrorObserver::StripLocation("Warning: In f.cxx, line 3\nvtkX (0x1): careful\n\n");
  Expect(warning == "careful", "StripLocation of a warning", warning);
  const std::string plain = vtkLightFieldErrorObserver::StripLocation("no prefix (0x1): here\n");
  Expect(plain == "no prefix (0x1): here", "StripLocation of text without the prefix", plain);
  return lfdtest::Result();
}

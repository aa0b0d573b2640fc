// What the scene logic's tests share: counting the events an object invokes,
// the last error heard.
#ifndef lfdSceneTestUtilities_h
#define lfdSceneTestUtilities_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"

#include <map>
#include <string>

namespace lfdtest
{
/// Counts the events of an object by id since the last Reset(); stops
/// observing when destroyed (so an object that outlives it, and invokes
/// DeleteEvent as it goes, never reaches a dead counter).
struct EventCounter
{
  std::map<unsigned long, int> Counts;
  vtkNew<vtkCallbackCommand> Callback;
  vtkObject* Observed;

  explicit EventCounter(vtkObject* object)
    : Observed(object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* self, void*)
      { ++static_cast<EventCounter*>(self)->Counts[event]; });
    object->AddObserver(vtkCommand::AnyEvent, this->Callback);
  }
  ~EventCounter() { this->Observed->RemoveObserver(this->Callback); }
  EventCounter(const EventCounter&) = delete;
  void operator=(const EventCounter&) = delete;

  int operator[](unsigned long event) { return this->Counts[event]; }
  void Reset() { this->Counts.clear(); }

  /// "cage keyframes settings modified stack error" counts, for one check.
  std::string Summary()
  {
    using Logic = vtkLightFieldSceneLogic;
    return std::to_string(this->Counts[Logic::CageModifiedEvent]) + " " +
      std::to_string(this->Counts[Logic::KeyframesModifiedEvent]) + " " +
      std::to_string(this->Counts[Logic::SettingsModifiedEvent]) + " " +
      std::to_string(this->Counts[vtkCommand::ModifiedEvent]) + " " +
      std::to_string(this->Counts[Logic::UndoStackModifiedEvent]) + " " +
      std::to_string(this->Counts[vtkCommand::ErrorEvent]);
  }
};

/// The last error's own line ("" when there is none).
inline std::string LastError(vtkLightFieldErrorObserver* errors)
{
  const int count = errors->GetNumberOfErrors();
  return count > 0 ? std::string(errors->GetError(count - 1)) : std::string();
}
}

#endif

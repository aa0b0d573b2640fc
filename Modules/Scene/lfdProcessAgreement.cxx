#include "lfdProcessAgreement.h"

#include "vtkMultiProcessController.h"
#include "vtkMultiProcessStream.h"

namespace
{
// The tag of an agreement's messages (apart from those of the writer's rounds).
const int AgreeTag = 28410;
}

namespace lfd
{
namespace scene
{
std::string AgreeOnError(vtkMultiProcessController* controller, const std::string& error)
{
  if (!controller || controller->GetNumberOfProcesses() == 1)
  {
    return error;
  }
  std::string first = error;
  if (controller->GetLocalProcessId() == 0)
  {
    for (int process = 1; process < controller->GetNumberOfProcesses(); ++process)
    {
      vtkMultiProcessStream stream;
      controller->Receive(stream, process, AgreeTag);
      std::string theirs;
      stream >> theirs;
      first = first.empty() ? theirs : first;
    }
  }
  else
  {
    vtkMultiProcessStream stream;
    stream << error;
    controller->Send(stream, 0, AgreeTag);
  }
  return ShareText(controller, first);
}

std::string ShareText(vtkMultiProcessController* controller, const std::string& text)
{
  if (!controller || controller->GetNumberOfProcesses() == 1)
  {
    return text;
  }
  vtkMultiProcessStream stream;
  if (controller->GetLocalProcessId() == 0)
  {
    stream << text;
  }
  controller->Broadcast(stream, 0);
  std::string shared;
  stream >> shared;
  return shared;
}
}
}

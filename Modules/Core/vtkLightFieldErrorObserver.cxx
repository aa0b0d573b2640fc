#include "vtkLightFieldErrorObserver.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkLightFieldErrorObserver);

namespace
{
/// What vtkExecutive says after any failed request: "Algorithm vtkX(0x...)
/// returned failure for request: <information dump>". Returns "vtkX failed",
/// or "" for any other message.
std::string DescribeFailedRequest(const std::string& message)
{
  const std::string prefix = "Algorithm ";
  const std::size_t open = message.find('(');
  if (message.rfind(prefix, 0) != 0 || open == std::string::npos ||
    message.find(") returned failure for request") == std::string::npos)
  {
    return std::string();
  }
  return message.substr(prefix.size(), open - prefix.size()) + " failed";
}

const char* Nth(const std::vector<std::string>& messages, int i)
{
  return (i >= 0 && i < static_cast<int>(messages.size())) ? messages[i].c_str() : "";
}
}

//------------------------------------------------------------------------------
vtkLightFieldErrorObserver::vtkLightFieldErrorObserver() = default;

//------------------------------------------------------------------------------
vtkLightFieldErrorObserver::~vtkLightFieldErrorObserver() = default;

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::Observe(vtkObject* object)
{
  // Observed twice, every message would be recorded twice.
  if (!object || object->HasObserver(vtkCommand::ErrorEvent, this))
  {
    return;
  }
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
  this->Observed.emplace_back(object);
  if (auto* algorithm = vtkAlgorithm::SafeDownCast(object))
  {
    vtkExecutive* executive = algorithm->GetExecutive();
    executive->AddObserver(vtkCommand::ErrorEvent, this);
    this->Observed.emplace_back(executive);
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::ObservePipeline(vtkAlgorithm* algorithm)
{
  if (!algorithm || algorithm->HasObserver(vtkCommand::ErrorEvent, this))
  {
    return;
  }
  this->Observe(algorithm);
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int connection = 0; connection < algorithm->GetNumberOfInputConnections(port);
         ++connection)
    {
      this->ObservePipeline(algorithm->GetInputAlgorithm(port, connection));
    }
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::StopObserving(vtkObject* object)
{
  if (!object)
  {
    return;
  }
  object->RemoveObserver(this);
  if (auto* algorithm = vtkAlgorithm::SafeDownCast(object))
  {
    algorithm->GetExecutive()->RemoveObserver(this);
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::StopObserving()
{
  for (vtkObject* object : this->Observed)
  {
    if (object)
    {
      object->RemoveObserver(this);
    }
  }
  this->Observed.clear();
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::Execute(vtkObject*, unsigned long event, void* callData)
{
  const std::string message = StripLocation(callData ? static_cast<const char*>(callData) : "");
  if (event == vtkCommand::WarningEvent)
  {
    this->Warnings.push_back(message);
    return;
  }
  if (event != vtkCommand::ErrorEvent)
  {
    return;
  }
  const std::string failedRequest = DescribeFailedRequest(message);
  if (failedRequest.empty())
  {
    this->Errors.push_back(message);
  }
  else if (this->Errors.empty())
  {
    this->Errors.push_back(failedRequest);
  }
}

//------------------------------------------------------------------------------
std::string vtkLightFieldErrorObserver::StripLocation(const std::string& text)
{
  std::string message = text;
  if (message.rfind("ERROR: In ", 0) == 0 || message.rfind("Warning: In ", 0) == 0)
  {
    // The second line starts with "<class> (<address>): ".
    const std::size_t line = message.find('\n');
    const std::size_t address = message.find("): ", line);
    if (line != std::string::npos && address != std::string::npos)
    {
      message.erase(0, address + 3);
    }
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}

//------------------------------------------------------------------------------
const char* vtkLightFieldErrorObserver::GetErrorMessage() const
{
  return Nth(this->Errors, 0);
}

//------------------------------------------------------------------------------
const char* vtkLightFieldErrorObserver::GetError(int i) const
{
  return Nth(this->Errors, i);
}

//------------------------------------------------------------------------------
const char* vtkLightFieldErrorObserver::GetWarningMessage() const
{
  return Nth(this->Warnings, 0);
}

//------------------------------------------------------------------------------
const char* vtkLightFieldErrorObserver::GetWarning(int i) const
{
  return Nth(this->Warnings, i);
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::Clear()
{
  this->Errors.clear();
  this->Warnings.clear();
}

//------------------------------------------------------------------------------
void vtkLightFieldErrorObserver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfErrors: " << this->Errors.size() << "\n";
  os << indent << "ErrorMessage: " << (this->HasError() ? this->Errors.front() : "(none)") << "\n";
  os << indent << "NumberOfWarnings: " << this->Warnings.size() << "\n";
}

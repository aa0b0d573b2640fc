#include "lfdParaViewFiles.h"

#include "lfdFileUtilities.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkXMLDataObjectWriter.h"

#include <sstream>

namespace lfd
{
namespace scene
{
//------------------------------------------------------------------------------
bool WriteXMLData(vtkDataObject* data, const std::string& path, std::string& error)
{
  vtkNew<vtkXMLDataObjectWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(writer);
  const int written = writer->Write();
  errors->StopObserving();
  if (written != 1 || errors->HasError())
  {
    error = path + ": " +
      (errors->HasError() ? std::string(errors->GetErrorMessage()) : "cannot be written");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool WriteCollection(const std::string& path,
  const std::vector<std::pair<double, std::string>>& steps,
  std::string& error)
{
  std::ostringstream text;
  // Times printed so that they read back exactly (17 significant digits).
  text.precision(17);
  text << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"Collection\" version=\"0.1\">\n"
       << "  <Collection>\n";
  for (const auto& step : steps)
  {
    text << "    <DataSet timestep=\"" << step.first << "\" part=\"0\" file=\"" << step.second
         << "\"/>\n";
  }
  text << "  </Collection>\n</VTKFile>\n";
  if (!lfd::io::WriteFileAtomically(path, text.str(), error))
  {
    error = path + ": " + error;
    return false;
  }
  return true;
}
}
}

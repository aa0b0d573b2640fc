/**
 * @file   lfdParaViewFiles.h
 * @brief  VTK XML files and ParaView collections (.pvd) of the exports
 *
 * The one writer of the files ParaView opens directly: a data object as
 * VTK XML (.vtp, .vtu, .vti by its type, binary, zlib-compressed) and a
 * time series as a ParaView collection (.pvd: one `DataSet` element per
 * step, its `timestep` and `file`). Used by vtkLightFieldAnimationWriter
 * (frames and cage over time) and vtkLightFieldSceneExporter (rig, cage,
 * light field). Private to the module (std:: types).
 */
#ifndef lfdParaViewFiles_h
#define lfdParaViewFiles_h

#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkDataObject;

namespace lfd
{
namespace scene
{
/**
 * Writes `data` to `path` as VTK XML (the writer of its type). False with
 * `error` (one line, naming `path`) when it cannot.
 */
bool WriteXMLData(vtkDataObject* data, const std::string& path, std::string& error);

/**
 * Writes the ParaView collection `path` of `steps` (time, file name
 * relative to the collection's folder). False with `error` naming `path`.
 */
bool WriteCollection(const std::string& path,
  const std::vector<std::pair<double, std::string>>& steps,
  std::string& error);
}
}

#endif

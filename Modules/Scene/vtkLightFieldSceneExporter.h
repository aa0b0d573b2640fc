/**
 * @class   vtkLightFieldSceneExporter
 * @brief   writes a scene for ParaView and vtk.js: the rig as camera frusta,
 * the cage, the light field as an image stack, and a vtk.js scene
 *
 * Write() fills the folder DirectoryName with files ParaView opens
 * directly (VTK XML, lfdParaViewFiles.h):
 * - rig.vtp: one frustum per captured view (vtkCameraFrustumSource: 5
 *   polygons a view, cell arrays "View" and "Row");
 * - projectors.vtp: the projectors' frusta, when the light field has some;
 * - cage.vtu (when the scene has a cage): the boxes as VTK_HEXAHEDRON
 *   cells at their current (deformed) positions, the point array
 *   "RestPosition" and the cell array "Label";
 * - lightfield.vti (WriteLightField, on by default): the light field as a
 *   W x H x V image whose slices are the views, one point array per pass
 *   (Coaxial, Label, ...); slice k is the photograph of view k, rows in
 *   VTK order;
 * - vtkjs/ (WriteVtkJs, on by default): the rig and the cage as a vtk.js
 *   scene (VTK's vtkJSONSceneExporter: index.json and its data), for a
 *   browser view with vtk.js's HttpSceneLoader (or zipped into a .vtkjs
 *   file for its SceneExplorer).
 * The cage's animation over time is written by the animation export
 * (vtkLightFieldAnimationWriter::SetWriteParaView: cage.pvd), next to the
 * rendered frames at the same times.
 *
 * The folder is staged and renamed onto DirectoryName only when complete
 * (lfd::scene::StagedFolder): nothing is half-written, and an existing
 * DirectoryName may hold only such files. Errors: Write() returns false and
 * reports one line with vtkErrorMacro (no scene logic or directory, the
 * light field that cannot be read, a file that cannot be written, a folder
 * of the user's in the way).
 *
 * @sa vtkLightFieldAnimationWriter vtkCameraFrustumSource
 */
#ifndef vtkLightFieldSceneExporter_h
#define vtkLightFieldSceneExporter_h

#include "lfdSceneModule.h" // For export macro
#include "vtkObject.h"

class vtkLightField;
class vtkLightFieldSceneLogic;

class LFDSCENE_EXPORT vtkLightFieldSceneExporter : public vtkObject
{
public:
  static vtkLightFieldSceneExporter* New();
  vtkTypeMacro(vtkLightFieldSceneExporter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene to export (its cage and light field).
   */
  void SetSceneLogic(vtkLightFieldSceneLogic* logic);
  vtkGetObjectMacro(SceneLogic, vtkLightFieldSceneLogic);
  ///@}

  ///@{
  /**
   * The light field, when the caller has it already; by default the scene
   * logic's (vtkLightFieldSceneLogic::GetLightField()).
   */
  void SetLightField(vtkLightField* lightField);
  vtkGetObjectMacro(LightField, vtkLightField);
  ///@}

  ///@{
  /**
   * The folder to write.
   */
  vtkSetStringMacro(DirectoryName);
  vtkGetStringMacro(DirectoryName);
  ///@}

  ///@{
  /**
   * Which of the optional files to write (both on by default).
   */
  vtkSetMacro(WriteLightField, bool);
  vtkGetMacro(WriteLightField, bool);
  vtkBooleanMacro(WriteLightField, bool);
  vtkSetMacro(WriteVtkJs, bool);
  vtkGetMacro(WriteVtkJs, bool);
  vtkBooleanMacro(WriteVtkJs, bool);
  ///@}

  /**
   * Writes the folder. False after one error (see the class description).
   */
  bool Write();

protected:
  vtkLightFieldSceneExporter();
  ~vtkLightFieldSceneExporter() override;

  vtkLightFieldSceneLogic* SceneLogic = nullptr;
  vtkLightField* LightField = nullptr;
  char* DirectoryName = nullptr;
  bool WriteLightField = true;
  bool WriteVtkJs = true;

private:
  vtkLightFieldSceneExporter(const vtkLightFieldSceneExporter&) = delete;
  void operator=(const vtkLightFieldSceneExporter&) = delete;
};

#endif

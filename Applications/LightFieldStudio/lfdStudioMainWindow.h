/**
 * @file   lfdStudioMainWindow.h
 * @brief  LightField Studio's main window: one VTK render window holding
 *         the views (lfdStudioViews), docks that edit the scene through
 *         vtkLightFieldSceneLogic, files, undo/redo and settings.
 *
 * The window holds no scene behaviour: every edit is a command of the
 * scene logic (so it is undoable, validated and named), and the window
 * follows the logic's events (CageModifiedEvent, KeyframesModifiedEvent,
 * SettingsModifiedEvent, UndoStackModifiedEvent) to refresh the views, the
 * docks and the Edit menu. Errors the logic reports (a bad file, a refused
 * edit) are collected by a vtkLightFieldErrorObserver and shown in the
 * status bar; a refused edit changes nothing.
 *
 * The public slots are the menu actions, so a test (or a script) drives the
 * window as a user does.
 */
#ifndef lfdStudioMainWindow_h
#define lfdStudioMainWindow_h

#include "vtkNew.h"

#include <QMainWindow>

#include <memory>
#include <vector>

class QAction;
class QComboBox;
class QLabel;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QMenu;
class QSlider;
class QSpinBox;
class QTableWidget;
class QTimer;
class QVTKOpenGLNativeWidget;
class lfdStudioViews;
class vtkDeformationCage;
class vtkGenericOpenGLRenderWindow;
class vtkLightFieldErrorObserver;
class vtkLightFieldSceneLogic;
class vtkObject;

class lfdStudioMainWindow : public QMainWindow
{
  Q_OBJECT

public:
  explicit lfdStudioMainWindow(QWidget* parent = nullptr);
  ~lfdStudioMainWindow() override;

  /// Opens a scene (`*.json`) or a light field (`*.lf`, in a new scene).
  /// False, with the error in the status bar, when it cannot be read; the
  /// previous scene is then kept.
  bool OpenFile(const QString& fileName);

  /// Saves the scene as `fileName` (scene.json); false with the error in
  /// the status bar.
  bool SaveSceneAs(const QString& fileName);

  /// Exports the animation of `frames` frames into `folder` (frames, MP4
  /// with ffmpeg, contact sheet; vtkLightFieldAnimationWriter) behind a
  /// progress dialog whose Cancel stops it; false when cancelled or refused
  /// (the reason in the status bar).
  bool ExportAnimationTo(const QString& folder, int frames);

  /// Shows the scene's cage at `time` (interpolated through the keyframes)
  /// in the views; the timeline's slider does this.
  void ShowTime(double time);

  /// Selects the gantry camera view's view and pass and the projector
  /// view's projector, as the Views dock does.
  void ShowView(int view, int pass, int projector);

  /// Writes every projector's mask to `folder`/projector_<k>.png
  /// (vtkProjectorView::WriteMask(), as `lfd synth --projector-mask` reads
  /// them); false with the reason in the status bar.
  bool SaveProjectorMasksTo(const QString& folder);

  vtkLightFieldSceneLogic* GetLogic();
  lfdStudioViews* GetViews();
  QVTKOpenGLNativeWidget* GetViewWidget();
  /// The scene file opened or last saved ("" for a new scene).
  QString GetSceneFile() const { return this->SceneFile; }

public Q_SLOTS:
  void Open();
  void Save();
  void SaveAs();
  void ExportAnimation();
  void SaveScreenshot();
  void SaveProjectorMasks();
  void Undo();
  void Redo();
  void StoreCamera();
  void ResetCamera();
  void SetLayout(int layout);
  void SetKeyframe();
  void RemoveKeyframe();
  void SetPlaying(bool playing);
  void ShowShortcuts();

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  void CreateActions();
  void CreateBoxesDock();
  void CreateSettingsDock();
  void CreateTimelineDock();
  void CreateViewDock();
  void ObserveLogic();
  void RestoreSettings();
  void AddRecentFile(const QString& fileName);
  void UpdateRecentFiles();
  void UpdateTitle();

  /// Shows the recorded error (if any) in the status bar and forgets it;
  /// true when there was none.
  bool ReportErrors();
  void LogicError(vtkObject*, unsigned long, void*);
  /// Re-reads the light field the scene names and shows the scene anew.
  void ShowScene();
  void Render();

  void CageModified(vtkObject*, unsigned long, void*);
  void KeyframesModified(vtkObject*, unsigned long, void*);
  void SettingsModified(vtkObject*, unsigned long, void*);
  void UndoStackModified(vtkObject*, unsigned long, void*);
  void Tick();
  void ViewSelected(vtkObject*, unsigned long, void* view);
  /// The gantry camera view's coverage in the Views dock.
  void UpdateCoverage();
  int SelectedBox() const;

  vtkNew<vtkLightFieldSceneLogic> Logic;
  vtkNew<vtkLightFieldErrorObserver> Errors;
  vtkNew<vtkGenericOpenGLRenderWindow> RenderWindow;
  vtkNew<vtkDeformationCage> ShownCage;
  std::unique_ptr<lfdStudioViews> Views;
  QVTKOpenGLNativeWidget* ViewWidget;
  QString SceneFile;
  /// The undo index when the scene was opened or saved: the title shows
  /// "*" when the index differs (the scene has unsaved edits).
  int SavedUndoIndex = 0;

  QAction* UndoAction = nullptr;
  QAction* RedoAction = nullptr;
  QMenu* RecentMenu = nullptr;
  std::vector<QAction*> LayoutActions;
  QTableWidget* BoxTable = nullptr;
  QSpinBox* LabelSpin = nullptr;
  QComboBox* SplitAxis = nullptr;
  QDoubleSpinBox* FocalDistance = nullptr;
  QSpinBox* Subdivision = nullptr;
  QSpinBox* WidenedSearch = nullptr;
  QComboBox* Interpolation = nullptr;
  QListWidget* KeyList = nullptr;
  QDoubleSpinBox* KeyTime = nullptr;
  QSlider* Scrub = nullptr;
  QAction* PlayAction = nullptr;
  QAction* LoopAction = nullptr;
  QTimer* PlayTimer = nullptr;
  QSlider* ViewSlider = nullptr;
  QComboBox* PassCombo = nullptr;
  QComboBox* ProjectorCombo = nullptr;
  QComboBox* BrushLabel = nullptr;
  QLabel* Coverage = nullptr;
};

#endif

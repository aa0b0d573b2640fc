#include "lfdStudioMainWindow.h"

#include "lfdStudioViews.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkGantryCameraView.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLightField.h"
#include "vtkLightFieldAnimationWriter.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkProjectorView.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRigView.h"
#include "vtkUnsignedCharArray.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QColor>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QPixmap>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace
{
constexpr int MaximumRecentFiles = 8;
constexpr int ScrubSteps = 1000;
constexpr int PlayIntervalMs = 40;

/// The key bindings the Help dialog lists: the Studio's menus, then the
/// main view's (the cage widget's, vtkCageWidget, and VTK's trackball camera).
const char* const Shortcuts[][2] = {
  { "Ctrl+O", "Open a scene (.json) or a light field (.lf)" },
  { "Ctrl+S", "Save the scene" },
  { "Ctrl+Shift+S", "Save the scene as" },
  { "Ctrl+E", "Export the animation (frames, MP4, contact sheet)" },
  { "Ctrl+P", "Save a screenshot of the window (PNG)" },
  { "Ctrl+Z", "Undo (the Edit menu names the command)" },
  { "Ctrl+Shift+Z", "Redo" },
  { "Ctrl+K", "Store the view's camera in the scene" },
  { "Home", "Put the view's camera back where the scene's is" },
  { "Ctrl+1 / Ctrl+2 / Ctrl+3", "Layout: main / main + camera / four-up" },
  { "I", "Set a keyframe at the timeline's time" },
  { "Alt+I", "Delete the selected keyframe" },
  { "Space", "Play / pause the animation" },
  { "F1", "This list" },
  { "Left drag on a corner (view)", "Move the corner (and the selection); one undoable command" },
  { "Left click / Shift+left click (view)", "Select a corner / toggle it in the selection" },
  { "B, then left drag (view)", "Rubber-band selection of the visible corners" },
  { "A (view)", "Select every corner / clear the selection" },
  { "G / R / S (view)", "Grab / rotate / scale the selection about its pivot" },
  { "X / Y / Z, Shift+X / Y / Z (view)", "During G / R / S: constrain to an axis / a plane" },
  { "Enter or left click / Esc or right click (view)", "Confirm / cancel G / R / S" },
  { "Esc (view)", "Clear the selection" },
  { "Left drag elsewhere (view)", "Rotate the camera" },
  { "Middle drag / Shift+left drag (view)", "Pan" },
  { "Right drag / wheel (view)", "Zoom" },
};

QString Which(const QString& fileName)
{
  return QFileInfo(fileName).fileName();
}
}

//------------------------------------------------------------------------------
lfdStudioMainWindow::lfdStudioMainWindow(QWidget* parent)
  : QMainWindow(parent)
  , ViewWidget(new QVTKOpenGLNativeWidget(this))
{
  this->setObjectName("LightFieldStudio");
  this->Errors->Observe(this->Logic);
  this->ViewWidget->setRenderWindow(this->RenderWindow);
  // The camera moves as the Help dialog says (VTK's trackball).
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  this->RenderWindow->GetInteractor()->SetInteractorStyle(style);
  this->setCentralWidget(this->ViewWidget);
  this->Views = std::make_unique<lfdStudioViews>(this->Logic, this->RenderWindow);
  this->PlayTimer = new QTimer(this);
  this->PlayTimer->setInterval(PlayIntervalMs);
  connect(this->PlayTimer, &QTimer::timeout, this, &lfdStudioMainWindow::Tick);

  this->CreateActions();
  this->CreateBoxesDock();
  this->CreateSettingsDock();
  this->CreateTimelineDock();
  this->CreateViewDock();
  this->ObserveLogic();
  this->RestoreSettings();
  this->ShowScene();
  this->UndoStackModified(nullptr, 0, nullptr);
  this->statusBar()->showMessage(tr("Ready"));
}

//------------------------------------------------------------------------------
lfdStudioMainWindow::~lfdStudioMainWindow()
{
  this->Logic->RemoveAllObservers();
  this->Errors->StopObserving();
}

//------------------------------------------------------------------------------
vtkLightFieldSceneLogic* lfdStudioMainWindow::GetLogic()
{
  return this->Logic;
}

//------------------------------------------------------------------------------
lfdStudioViews* lfdStudioMainWindow::GetViews()
{
  return this->Views.get();
}

//------------------------------------------------------------------------------
QVTKOpenGLNativeWidget* lfdStudioMainWindow::GetViewWidget()
{
  return this->ViewWidget;
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CreateActions()
{
  QMenu* file = this->menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open..."), this, &lfdStudioMainWindow::Open, QKeySequence::Open);
  this->RecentMenu = file->addMenu(tr("Open &Recent"));
  file->addAction(tr("&Save"), this, &lfdStudioMainWindow::Save, QKeySequence::Save);
  file->addAction(
    tr("Save &As..."), this, &lfdStudioMainWindow::SaveAs, QKeySequence(tr("Ctrl+Shift+S")));
  file->addAction(tr("&Export Animation..."),
    this,
    &lfdStudioMainWindow::ExportAnimation,
    QKeySequence(tr("Ctrl+E")));
  file->addAction(tr("Save Screens&hot..."),
    this,
    &lfdStudioMainWindow::SaveScreenshot,
    QKeySequence(tr("Ctrl+P")));
  file->addAction(tr("Save Projector &Masks..."), this, &lfdStudioMainWindow::SaveProjectorMasks);
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  QMenu* edit = this->menuBar()->addMenu(tr("&Edit"));
  this->UndoAction =
    edit->addAction(tr("Undo"), this, &lfdStudioMainWindow::Undo, QKeySequence(tr("Ctrl+Z")));
  this->RedoAction =
    edit->addAction(tr("Redo"), this, &lfdStudioMainWindow::Redo, QKeySequence(tr("Ctrl+Shift+Z")));
  this->UndoAction->setObjectName("Undo");
  this->RedoAction->setObjectName("Redo");
  edit->addSeparator();
  edit->addAction(tr("Store View &Camera in Scene"),
    this,
    &lfdStudioMainWindow::StoreCamera,
    QKeySequence(tr("Ctrl+K")));

  QMenu* view = this->menuBar()->addMenu(tr("&View"));
  auto* layouts = new QActionGroup(this);
  const QString names[] = { tr("&Main View"), tr("Main + &Camera"), tr("&Four-Up") };
  for (int layout = 0; layout < 3; ++layout)
  {
    QAction* action = view->addAction(names[layout], this, [this, layout] { SetLayout(layout); });
    action->setShortcut(QKeySequence(QString("Ctrl+%1").arg(layout + 1)));
    action->setCheckable(true);
    layouts->addAction(action);
    this->LayoutActions.push_back(action);
  }
  view->addSeparator();
  view->addAction(tr("&Reset Camera"), this, &lfdStudioMainWindow::ResetCamera, Qt::Key_Home);
  QAction* frameTime = view->addAction(tr("Show &Frame Time"));
  frameTime->setCheckable(true);
  frameTime->setChecked(true);
  connect(frameTime,
    &QAction::toggled,
    this,
    [this](bool on)
    {
      this->Views->SetFrameTimeVisible(on);
      this->Render();
    });
  this->menuBar()
    ->addMenu(tr("&Help"))
    ->addAction(
      tr("&Shortcuts..."), this, &lfdStudioMainWindow::ShowShortcuts, QKeySequence::HelpContents);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CreateBoxesDock()
{
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  this->BoxTable = new QTableWidget(0, 2);
  this->BoxTable->setObjectName("Boxes");
  this->BoxTable->setHorizontalHeaderLabels({ tr("Box (shown)"), tr("Label") });
  this->BoxTable->horizontalHeader()->setStretchLastSection(true);
  this->BoxTable->setSelectionBehavior(QAbstractItemView::SelectRows);
  this->BoxTable->setSelectionMode(QAbstractItemView::SingleSelection);
  this->BoxTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(this->BoxTable);
  // The check box of a row shows or hides that box in the cage widget.
  QObject::connect(this->BoxTable,
    &QTableWidget::itemChanged,
    [this](QTableWidgetItem* item)
    {
      if (item->column() == 0)
      {
        this->Views->GetEditor()->GetWidget()->GetCageRepresentation()->SetBoxVisibility(
          item->row(), item->checkState() == Qt::Checked);
        this->Render();
      }
    });

  auto* row = new QHBoxLayout;
  auto* add = new QPushButton(tr("Add"));
  auto* remove = new QPushButton(tr("Remove"));
  auto* split = new QPushButton(tr("Split"));
  this->SplitAxis = new QComboBox;
  this->SplitAxis->setObjectName("SplitAxis");
  this->SplitAxis->addItems({ "u", "v", "w" });
  row->addWidget(add);
  row->addWidget(remove);
  row->addWidget(split);
  row->addWidget(this->SplitAxis);
  layout->addLayout(row);
  auto* relabelRow = new QHBoxLayout;
  this->LabelSpin = new QSpinBox;
  this->LabelSpin->setObjectName("Label");
  this->LabelSpin->setRange(1, 255);
  auto* relabel = new QPushButton(tr("Relabel"));
  relabelRow->addWidget(new QLabel(tr("Label")));
  relabelRow->addWidget(this->LabelSpin);
  relabelRow->addWidget(relabel);
  layout->addLayout(relabelRow);

  connect(add,
    &QPushButton::clicked,
    this,
    [this]
    {
      // A new box beside the cage (to its +x side), as large as its first box.
      vtkDeformationCage* cage = this->Logic->GetCage();
      double bounds[6] = { -0.25, 0.25, -0.25, 0.25, -0.25, 0.25 };
      if (cage->GetNumberOfBoxes() > 0)
      {
        double first[6];
        cage->GetRestBounds(0, first);
        const double* all = cage->GetBounds();
        const double width = first[1] - first[0];
        std::copy(first, first + 6, bounds);
        bounds[0] = all[1] + 0.1 * width;
        bounds[1] = bounds[0] + width;
      }
      this->Logic->AddBox(bounds, this->LabelSpin->value());
    });
  connect(
    remove, &QPushButton::clicked, this, [this] { this->Logic->RemoveBox(this->SelectedBox()); });
  connect(split,
    &QPushButton::clicked,
    this,
    [this] { this->Logic->SplitBox(this->SelectedBox(), this->SplitAxis->currentIndex()); });
  connect(relabel,
    &QPushButton::clicked,
    this,
    [this] { this->Logic->SetBoxLabel(this->SelectedBox(), this->LabelSpin->value()); });

  auto* dock = new QDockWidget(tr("Boxes and Labels"), this);
  dock->setObjectName("BoxesDock");
  dock->setWidget(panel);
  this->addDockWidget(Qt::LeftDockWidgetArea, dock);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CreateSettingsDock()
{
  auto* panel = new QWidget;
  auto* form = new QFormLayout(panel);
  this->FocalDistance = new QDoubleSpinBox;
  this->FocalDistance->setRange(-1e6, 1e6);
  this->FocalDistance->setDecimals(3);
  this->FocalDistance->setSingleStep(0.05);
  this->FocalDistance->setSpecialValueText(tr("auto"));
  this->Subdivision = new QSpinBox;
  this->Subdivision->setRange(0, 1024);
  this->Subdivision->setSpecialValueText(tr("auto"));
  this->WidenedSearch = new QSpinBox;
  this->WidenedSearch->setRange(0, 64);
  for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{
         this->FocalDistance, this->Subdivision, this->WidenedSearch })
  {
    box->setKeyboardTracking(false);
  }
  form->addRow(tr("Focal distance"), this->FocalDistance);
  form->addRow(tr("Subdivision"), this->Subdivision);
  form->addRow(tr("Widened search (views)"), this->WidenedSearch);
  // Each change is one undoable command; a refused value is put back by
  // SettingsModified() (the logic keeps its value).
  connect(this->FocalDistance,
    &QDoubleSpinBox::editingFinished,
    this,
    [this]
    {
      if (this->FocalDistance->value() != this->Logic->GetScene()->GetFocalDistance())
      {
        this->Logic->SetFocalDistance(this->FocalDistance->value());
      }
    });
  connect(this->Subdivision,
    &QSpinBox::editingFinished,
    this,
    [this]
    {
      if (this->Subdivision->value() != this->Logic->GetScene()->GetSubdivision())
      {
        this->Logic->SetSubdivision(this->Subdivision->value());
      }
    });
  connect(this->WidenedSearch,
    &QSpinBox::editingFinished,
    this,
    [this]
    {
      if (this->WidenedSearch->value() != this->Logic->GetScene()->GetWidenedSearch())
      {
        this->Logic->SetWidenedSearch(this->WidenedSearch->value());
      }
    });
  auto* dock = new QDockWidget(tr("Render Settings"), this);
  dock->setObjectName("SettingsDock");
  dock->setWidget(panel);
  this->addDockWidget(Qt::LeftDockWidgetArea, dock);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CreateTimelineDock()
{
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  auto* toolbar = new QToolBar;
  this->KeyTime = new QDoubleSpinBox;
  this->KeyTime->setObjectName("KeyTime");
  this->KeyTime->setRange(0.0, 1e6);
  this->KeyTime->setDecimals(2);
  this->KeyTime->setPrefix(tr("t = "));
  toolbar->addWidget(this->KeyTime);
  toolbar->addAction(tr("Set Key"), this, &lfdStudioMainWindow::SetKeyframe)
    ->setShortcut(Qt::Key_I);
  toolbar->addAction(tr("Delete Key"), this, &lfdStudioMainWindow::RemoveKeyframe)
    ->setShortcut(QKeySequence(tr("Alt+I")));
  this->PlayAction = toolbar->addAction(tr("Play"));
  this->PlayAction->setCheckable(true);
  this->PlayAction->setShortcut(Qt::Key_Space);
  connect(this->PlayAction, &QAction::toggled, this, &lfdStudioMainWindow::SetPlaying);
  this->LoopAction = toolbar->addAction(tr("Loop"));
  this->LoopAction->setCheckable(true);
  this->Interpolation = new QComboBox;
  this->Interpolation->setObjectName("Interpolation");
  // Indices are vtkKeyframeInterpolator's: LINEAR = 0, CATMULL_ROM = 1. The
  // choice is the scene's (scene.json "interpolation"), an undoable edit;
  // SettingsModified() shows it after a load, an undo or a redo.
  this->Interpolation->addItems({ tr("Linear"), tr("Catmull-Rom") });
  this->Interpolation->setCurrentIndex(this->Logic->GetInterpolation());
  connect(this->Interpolation,
    QOverload<int>::of(&QComboBox::currentIndexChanged),
    this,
    [this](int index)
    {
      this->Logic->SetInterpolation(index);
      this->ShowTime(-1.0);
    });
  toolbar->addWidget(this->Interpolation);
  layout->addWidget(toolbar);

  this->Scrub = new QSlider(Qt::Horizontal);
  this->Scrub->setObjectName("Scrub");
  this->Scrub->setRange(0, ScrubSteps);
  connect(this->Scrub,
    &QSlider::valueChanged,
    this,
    [this](int step)
    {
      const double first = this->Logic->GetAnimationTime(0, ScrubSteps + 1);
      const double time = this->Logic->GetAnimationTime(step, ScrubSteps + 1);
      this->KeyTime->setValue(std::max(time, first));
      this->ShowTime(time);
    });
  layout->addWidget(this->Scrub);
  this->KeyList = new QListWidget;
  this->KeyList->setObjectName("Keyframes");
  this->KeyList->setFlow(QListView::LeftToRight);
  this->KeyList->setMaximumHeight(48);
  layout->addWidget(this->KeyList);

  auto* dock = new QDockWidget(tr("Keyframes"), this);
  dock->setObjectName("TimelineDock");
  dock->setWidget(panel);
  this->addDockWidget(Qt::BottomDockWidgetArea, dock);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CreateViewDock()
{
  auto* panel = new QWidget;
  auto* form = new QFormLayout(panel);
  this->ViewSlider = new QSlider(Qt::Horizontal);
  this->ViewSlider->setObjectName("GantryView");
  connect(this->ViewSlider,
    &QSlider::valueChanged,
    this,
    [this](int view)
    {
      this->Views->SetCameraView(view);
      this->UpdateCoverage();
      this->Render();
    });
  this->PassCombo = new QComboBox;
  this->PassCombo->setObjectName("Pass");
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    this->PassCombo->addItem(vtkLightField::GetPassName(pass));
  }
  // Eq. 1 of the paper: the coded pass divided by the flood pass.
  this->PassCombo->addItem(tr("Normalised (B')"));
  connect(this->PassCombo,
    QOverload<int>::of(&QComboBox::currentIndexChanged),
    this,
    [this](int pass)
    {
      this->Views->SetPass(pass);
      this->UpdateCoverage();
      this->Render();
    });
  this->ProjectorCombo = new QComboBox;
  this->ProjectorCombo->setObjectName("Projector");
  connect(this->ProjectorCombo,
    QOverload<int>::of(&QComboBox::currentIndexChanged),
    this,
    [this](int projector)
    {
      this->Views->SetProjector(projector);
      this->Render();
    });
  this->Coverage = new QLabel;
  this->Coverage->setObjectName("Coverage");
  this->Coverage->setToolTip(tr("The smallest fraction of a label's pixels inside its rest boxes "
                                "in this view (n/a without boxes or a Label pass)"));
  vtkProjectorView* projector = this->Views->GetProjectorView();
  auto* radius = new QDoubleSpinBox;
  radius->setObjectName("BrushRadius");
  radius->setRange(0.5, 256.0);
  radius->setSuffix(tr(" px"));
  radius->setValue(projector->GetBrushRadius());
  connect(radius,
    QOverload<double>::of(&QDoubleSpinBox::valueChanged),
    this,
    [projector](double value) { projector->SetBrushRadius(value); });
  this->BrushLabel = new QComboBox;
  this->BrushLabel->setObjectName("BrushLabel");
  connect(this->BrushLabel,
    QOverload<int>::of(&QComboBox::currentIndexChanged),
    this,
    [projector](int label) { projector->SetBrushLabel(std::max(label, 0)); });
  form->addRow(tr("Gantry view"), this->ViewSlider);
  form->addRow(tr("Pass"), this->PassCombo);
  form->addRow(tr("Coverage"), this->Coverage);
  form->addRow(tr("Projector"), this->ProjectorCombo);
  form->addRow(tr("Brush radius"), radius);
  form->addRow(tr("Brush label"), this->BrushLabel);
  auto* dock = new QDockWidget(tr("Views"), this);
  dock->setObjectName("ViewDock");
  dock->setWidget(panel);
  this->addDockWidget(Qt::RightDockWidgetArea, dock);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ObserveLogic()
{
  using SceneLogic = vtkLightFieldSceneLogic;
  this->Logic->AddObserver(SceneLogic::CageModifiedEvent, this, &lfdStudioMainWindow::CageModified);
  this->Logic->AddObserver(
    SceneLogic::KeyframesModifiedEvent, this, &lfdStudioMainWindow::KeyframesModified);
  this->Logic->AddObserver(
    SceneLogic::SettingsModifiedEvent, this, &lfdStudioMainWindow::SettingsModified);
  this->Logic->AddObserver(
    SceneLogic::UndoStackModifiedEvent, this, &lfdStudioMainWindow::UndoStackModified);
  // A stroke, its undo or redo: the projector view shows the mask anew.
  this->Logic->AddObserver(
    SceneLogic::ProjectorMasksModifiedEvent, this, &lfdStudioMainWindow::Render);
  // A click on a camera frustum in the rig view shows that view.
  this->Views->GetRigView()->AddObserver(
    vtkRigView::ViewSelectedEvent, this, &lfdStudioMainWindow::ViewSelected);
  // A mask that cannot be written reaches the status bar as the logic's errors.
  this->Errors->Observe(this->Views->GetProjectorView());
  this->Views->GetProjectorView()->AddObserver(
    vtkCommand::ErrorEvent, this, &lfdStudioMainWindow::LogicError, -1.0f);
  // After the error observer (priority 0) has recorded it: every error of
  // the logic, whatever edit or read made it, reaches the status bar.
  this->Logic->AddObserver(vtkCommand::ErrorEvent, this, &lfdStudioMainWindow::LogicError, -1.0f);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::RestoreSettings()
{
  QSettings settings;
  this->resize(1100, 760);
  this->restoreGeometry(settings.value("window/geometry").toByteArray());
  this->restoreState(settings.value("window/state").toByteArray());
  this->SetLayout(settings.value("view/layout", lfdStudioViews::MAIN_ONLY).toInt());
  this->UpdateRecentFiles();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::closeEvent(QCloseEvent* event)
{
  QSettings settings;
  settings.setValue("window/geometry", this->saveGeometry());
  settings.setValue("window/state", this->saveState());
  settings.setValue("view/layout", this->Views->GetLayout());
  QMainWindow::closeEvent(event);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::LogicError(vtkObject*, unsigned long, void*)
{
  this->ReportErrors();
}

//------------------------------------------------------------------------------
bool lfdStudioMainWindow::ReportErrors()
{
  if (!this->Errors->HasError())
  {
    return true;
  }
  this->statusBar()->showMessage(QString::fromStdString(this->Errors->GetErrorMessage()));
  this->Errors->Clear();
  return false;
}

//------------------------------------------------------------------------------
bool lfdStudioMainWindow::OpenFile(const QString& fileName)
{
  const QByteArray path = fileName.toLocal8Bit();
  if (fileName.endsWith(".lf", Qt::CaseInsensitive))
  {
    // A light field alone: a new scene that names it.
    vtkNew<vtkLightFieldSceneLogic> probe;
    this->Errors->Observe(probe);
    const QByteArray absolute = QFileInfo(fileName).absoluteFilePath().toLocal8Bit();
    probe->GetScene()->SetLightFieldPath(absolute.constData());
    const bool read = probe->GetLightField() != nullptr;
    this->Errors->StopObserving(probe);
    if (!read)
    {
      return this->ReportErrors();
    }
    this->Logic->NewScene();
    this->Logic->GetScene()->SetLightFieldPath(probe->GetScene()->GetLightFieldPath());
    this->Logic->SetLightField(probe->GetLightField());
    // A view from outside the ring, as `lfd demo` frames its scenes.
    vtkCameraRig* rig = probe->GetLightField()->GetRig();
    if (rig && rig->HasCylinder())
    {
      vtkLightFieldSceneLogic::OrbitCamera(
        rig, 0.0, 1.15, 0.0, 0.7 * rig->GetViewAngle(0), this->Logic->GetScene()->GetCamera());
    }
    this->SceneFile.clear();
  }
  else
  {
    // Load() keeps the scene when the file is refused.
    if (!this->Logic->Load(path.constData()))
    {
      return false;
    }
    this->SceneFile = fileName;
  }
  this->SavedUndoIndex = 0;
  this->ShowScene();
  this->AddRecentFile(fileName);
  QSettings().setValue("files/folder", QFileInfo(fileName).absolutePath());
  if (this->Views->GetLightField() || !this->Logic->GetScene()->GetLightFieldPath())
  {
    this->statusBar()->showMessage(tr("Opened %1").arg(Which(fileName)));
  }
  return true;
}

//------------------------------------------------------------------------------
bool lfdStudioMainWindow::SaveSceneAs(const QString& fileName)
{
  if (!this->Logic->Save(fileName.toLocal8Bit().constData()))
  {
    return false;
  }
  this->SceneFile = fileName;
  this->SavedUndoIndex = this->Logic->GetUndoIndex();
  this->AddRecentFile(fileName);
  this->UpdateTitle();
  this->statusBar()->showMessage(tr("Saved %1").arg(Which(fileName)));
  return true;
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ShowScene()
{
  vtkLightField* lightField = this->Logic->GetScene()->GetLightFieldPath() || this->Logic->HasCage()
    ? this->Logic->GetLightField()
    : nullptr;
  this->Views->SetLightField(lightField);
  const int views = lightField ? lightField->GetNumberOfViews() : 1;
  this->ViewSlider->setRange(0, std::max(views - 1, 0));
  this->ViewSlider->setValue(this->Views->GetCameraView());
  this->ProjectorCombo->clear();
  vtkImageData* masks = lightField ? lightField->GetProjectorMasks() : nullptr;
  for (int p = 0; masks && p < masks->GetDimensions()[2]; ++p)
  {
    this->ProjectorCombo->addItem(tr("Projector %1").arg(p));
  }
  // The brush paints the labels of the light field's palette (0: black, no part).
  const int brushLabel = std::max(this->BrushLabel->currentIndex(), 1);
  this->BrushLabel->clear();
  vtkUnsignedCharArray* palette = lightField ? lightField->GetPalette() : nullptr;
  // Without a palette of its own, the first labels of the default one.
  const int labels = palette ? static_cast<int>(palette->GetNumberOfTuples()) : 8;
  for (int label = 0; label < labels; ++label)
  {
    unsigned char rgb[3];
    this->Views->GetLabelColour(label, rgb);
    QPixmap swatch(16, 16);
    swatch.fill(QColor(rgb[0], rgb[1], rgb[2]));
    this->BrushLabel->addItem(QIcon(swatch), QString::number(label));
  }
  this->BrushLabel->setCurrentIndex(std::min(brushLabel, labels - 1));
  this->CageModified(nullptr, 0, nullptr);
  this->KeyframesModified(nullptr, 0, nullptr);
  this->SettingsModified(nullptr, 0, nullptr);
  this->UpdateTitle();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ShowTime(double time)
{
  // A negative time shows the current (editable) cage.
  const bool shown = time >= 0.0 ? this->Logic->GetCageAtTime(time, nullptr, this->ShownCage)
                                 : this->Logic->GetCurrentCage(nullptr, this->ShownCage);
  if (!shown)
  {
    // Nothing to show, or a refused keyframe (its error is in the status bar).
    this->ShownCage->Initialize();
  }
  this->Views->ShowCage(time, this->ShownCage);
  // During a drag the editor renders each step itself.
  if (!this->Views->GetEditor()->GetInteracting())
  {
    this->Render();
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ShowView(int view, int pass, int projector)
{
  this->ViewSlider->setValue(view);
  this->PassCombo->setCurrentIndex(pass);
  this->ProjectorCombo->setCurrentIndex(projector);
}

//------------------------------------------------------------------------------
bool lfdStudioMainWindow::SaveProjectorMasksTo(const QString& folder)
{
  const int projectors = this->ProjectorCombo->count();
  if (projectors == 0)
  {
    this->statusBar()->showMessage(tr("The light field has no projector masks"));
    return false;
  }
  QDir().mkpath(folder);
  for (int p = 0; p < projectors; ++p)
  {
    const QByteArray file = QDir(folder).filePath(QString("projector_%1.png").arg(p)).toLocal8Bit();
    if (!this->Views->GetProjectorView()->WriteMask(p, file.constData()))
    {
      return false;
    }
  }
  this->statusBar()->showMessage(tr("Saved %1 projector masks to %2").arg(projectors).arg(folder));
  return true;
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SaveProjectorMasks()
{
  const QString folder = QFileDialog::getExistingDirectory(
    this, tr("Save Projector Masks"), QSettings().value("files/folder").toString());
  if (!folder.isEmpty())
  {
    this->SaveProjectorMasksTo(folder);
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ViewSelected(vtkObject*, unsigned long, void* view)
{
  this->ViewSlider->setValue(*static_cast<int*>(view));
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::UpdateCoverage()
{
  const double coverage = this->Views->GetCoverage();
  this->Coverage->setText(coverage < 0.0 ? tr("n/a") : QString::number(coverage, 'f', 4));
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Render()
{
  this->RenderWindow->Render();
  this->ViewWidget->update();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::CageModified(vtkObject*, unsigned long, void*)
{
  if (this->Views->GetEditor()->GetInteracting())
  {
    // A drag moves points only: the boxes and labels stay as listed.
    this->ShowTime(-1.0);
    return;
  }
  vtkDeformationCage* cage = this->Logic->GetCage();
  const int boxes = static_cast<int>(cage->GetNumberOfBoxes());
  const QSignalBlocker blocker(this->BoxTable);
  this->BoxTable->setRowCount(boxes);
  for (int box = 0; box < boxes; ++box)
  {
    auto* name = new QTableWidgetItem(QString::number(box));
    name->setFlags(name->flags() | Qt::ItemIsUserCheckable);
    name->setCheckState(
      this->Views->GetEditor()->GetWidget()->GetCageRepresentation()->GetBoxVisibility(box)
        ? Qt::Checked
        : Qt::Unchecked);
    auto* label = new QTableWidgetItem(QString::number(cage->GetBoxLabel(box)));
    unsigned char rgb[3];
    this->Views->GetLabelColour(cage->GetBoxLabel(box), rgb);
    label->setBackground(QColor(rgb[0], rgb[1], rgb[2]));
    label->setForeground(qGray(rgb[0], rgb[1], rgb[2]) > 128 ? Qt::black : Qt::white);
    this->BoxTable->setItem(box, 0, name);
    this->BoxTable->setItem(box, 1, label);
  }
  this->ShowTime(-1.0);
  // The rest boxes may have changed: the coverage with them.
  this->UpdateCoverage();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::KeyframesModified(vtkObject*, unsigned long, void*)
{
  vtkLightFieldScene* scene = this->Logic->GetScene();
  this->KeyList->clear();
  for (int k = 0; k < scene->GetNumberOfKeyframes(); ++k)
  {
    this->KeyList->addItem(QString::number(scene->GetKeyframeTime(k), 'g', 4));
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SettingsModified(vtkObject*, unsigned long, void*)
{
  vtkLightFieldScene* scene = this->Logic->GetScene();
  const QSignalBlocker b1(this->FocalDistance);
  const QSignalBlocker b2(this->Subdivision);
  const QSignalBlocker b3(this->WidenedSearch);
  const QSignalBlocker b4(this->Interpolation);
  this->FocalDistance->setValue(scene->GetFocalDistance());
  this->Subdivision->setValue(scene->GetSubdivision());
  this->WidenedSearch->setValue(scene->GetWidenedSearch());
  this->Interpolation->setCurrentIndex(scene->GetInterpolation());
  this->Render();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::UndoStackModified(vtkObject*, unsigned long, void*)
{
  const QString undo = QString::fromStdString(this->Logic->GetUndoName());
  const QString redo = QString::fromStdString(this->Logic->GetRedoName());
  this->UndoAction->setEnabled(this->Logic->CanUndo());
  this->UndoAction->setText(undo.isEmpty() ? tr("Undo") : tr("Undo %1").arg(undo));
  this->RedoAction->setEnabled(this->Logic->CanRedo());
  this->RedoAction->setText(redo.isEmpty() ? tr("Redo") : tr("Redo %1").arg(redo));
  this->UpdateTitle();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::UpdateTitle()
{
  const QString name = this->SceneFile.isEmpty() ? tr("untitled") : Which(this->SceneFile);
  this->setWindowTitle(tr("%1%2 - LightField Studio")
                         .arg(name)
                         .arg(this->Logic->GetUndoIndex() != this->SavedUndoIndex ? "*" : ""));
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::AddRecentFile(const QString& fileName)
{
  QSettings settings;
  QStringList files = settings.value("files/recent").toStringList();
  const QString path = QFileInfo(fileName).absoluteFilePath();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > MaximumRecentFiles)
  {
    files.removeLast();
  }
  settings.setValue("files/recent", files);
  this->UpdateRecentFiles();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::UpdateRecentFiles()
{
  this->RecentMenu->clear();
  const QStringList files = QSettings().value("files/recent").toStringList();
  for (const QString& file : files)
  {
    this->RecentMenu->addAction(Which(file), this, [this, file] { OpenFile(file); })
      ->setToolTip(file);
  }
  this->RecentMenu->setEnabled(!files.isEmpty());
}

//------------------------------------------------------------------------------
int lfdStudioMainWindow::SelectedBox() const
{
  const QList<QTableWidgetItem*> items = this->BoxTable->selectedItems();
  return items.isEmpty() ? -1 : items.front()->row();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Open()
{
  const QString fileName = QFileDialog::getOpenFileName(this,
    tr("Open Scene or Light Field"),
    QSettings().value("files/folder").toString(),
    tr("Scenes and light fields (*.json *.lf);;All files (*)"));
  if (!fileName.isEmpty())
  {
    this->OpenFile(fileName);
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Save()
{
  if (this->SceneFile.isEmpty())
  {
    this->SaveAs();
    return;
  }
  this->SaveSceneAs(this->SceneFile);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SaveAs()
{
  const QString fileName = QFileDialog::getSaveFileName(
    this, tr("Save Scene"), QSettings().value("files/folder").toString(), tr("Scenes (*.json)"));
  if (!fileName.isEmpty())
  {
    this->SaveSceneAs(fileName);
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ExportAnimation()
{
  const QString folder = QFileDialog::getSaveFileName(this,
    tr("Export Animation to Folder"),
    QSettings().value("files/folder").toString() + "/animation");
  if (folder.isEmpty())
  {
    return;
  }
  bool ok = false;
  const int frames =
    QInputDialog::getInt(this, tr("Export Animation"), tr("Frames"), 48, 1, 100000, 1, &ok);
  if (ok)
  {
    this->ExportAnimationTo(folder, frames);
  }
}

//------------------------------------------------------------------------------
bool lfdStudioMainWindow::ExportAnimationTo(const QString& folder, int frames)
{
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(this->Logic);
  const QByteArray path = folder.toLocal8Bit();
  writer->SetDirectoryName(path.constData());
  writer->SetNumberOfFrames(frames);
  writer->WriteContactSheetOn();
  QProgressDialog progress(tr("Exporting the animation..."), tr("Cancel"), 0, 1000, this);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(0);
  // The writer renders in this thread: its progress events keep the dialog
  // (and its Cancel button) alive.
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback(
    [](vtkObject* caller, unsigned long, void* dialog, void* fraction)
    {
      auto* shown = static_cast<QProgressDialog*>(dialog);
      auto* exporting = static_cast<vtkLightFieldAnimationWriter*>(caller);
      shown->setValue(static_cast<int>(1000.0 * *static_cast<double*>(fraction)));
      shown->setLabelText(QString::fromUtf8(exporting->GetProgressText()));
      QApplication::processEvents();
      exporting->SetAbort(shown->wasCanceled());
    });
  writer->AddObserver(vtkCommand::ProgressEvent, onProgress);
  this->Errors->Observe(writer);
  const bool written = writer->Write();
  this->Errors->StopObserving(writer);
  progress.reset();
  if (written)
  {
    this->statusBar()->showMessage(tr("Exported %1 frames to %2%3")
                                     .arg(writer->GetNumberOfFramesWritten())
                                     .arg(folder)
                                     .arg(writer->GetMovieWritten() ? " (animation.mp4)" : ""));
  }
  else if (writer->GetAborted())
  {
    this->statusBar()->showMessage(tr("Export cancelled: %1 is unchanged").arg(folder));
  }
  else
  {
    this->ReportErrors();
  }
  return written;
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SaveScreenshot()
{
  const QString fileName = QFileDialog::getSaveFileName(this,
    tr("Save Screenshot"),
    QSettings().value("files/folder").toString(),
    tr("PNG images (*.png)"));
  if (fileName.isEmpty())
  {
    return;
  }
  this->Render();
  if (this->grab().save(fileName, "PNG"))
  {
    this->statusBar()->showMessage(tr("Saved %1").arg(Which(fileName)));
  }
  else
  {
    this->statusBar()->showMessage(tr("%1: cannot be written").arg(fileName));
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Undo()
{
  const QString name = QString::fromStdString(this->Logic->GetUndoName());
  if (this->Logic->Undo())
  {
    this->statusBar()->showMessage(tr("Undid %1").arg(name));
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Redo()
{
  const QString name = QString::fromStdString(this->Logic->GetRedoName());
  if (this->Logic->Redo())
  {
    this->statusBar()->showMessage(tr("Redid %1").arg(name));
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::StoreCamera()
{
  this->Logic->SetCamera(this->Views->GetMainRenderer()->GetActiveCamera());
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ResetCamera()
{
  this->Views->ResetCamera();
  this->Render();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SetLayout(int layout)
{
  this->Views->SetLayout(layout);
  this->LayoutActions[this->Views->GetLayout()]->setChecked(true);
  this->Render();
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SetKeyframe()
{
  this->Logic->SetKeyframe(this->KeyTime->value());
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::RemoveKeyframe()
{
  this->Logic->RemoveKeyframe(this->KeyList->currentRow());
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::SetPlaying(bool playing)
{
  if (playing)
  {
    this->PlayTimer->start();
  }
  else
  {
    this->PlayTimer->stop();
  }
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::Tick()
{
  // One scrub step per tick: the whole animation in ScrubSteps / 25 s at
  // 25 ticks per second, whatever its keyframe times.
  int step = this->Scrub->value() + 25;
  if (step > ScrubSteps)
  {
    step = 0;
    if (!this->LoopAction->isChecked())
    {
      this->PlayAction->setChecked(false);
      return;
    }
  }
  this->Scrub->setValue(step);
}

//------------------------------------------------------------------------------
void lfdStudioMainWindow::ShowShortcuts()
{
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Shortcuts"));
  auto* layout = new QVBoxLayout(&dialog);
  const int rows = static_cast<int>(sizeof(Shortcuts) / sizeof(Shortcuts[0]));
  auto* table = new QTableWidget(rows, 2);
  table->setHorizontalHeaderLabels({ tr("Key"), tr("Action") });
  for (int row = 0; row < rows; ++row)
  {
    table->setItem(row, 0, new QTableWidgetItem(Shortcuts[row][0]));
    table->setItem(row, 1, new QTableWidgetItem(tr(Shortcuts[row][1])));
  }
  table->resizeColumnsToContents();
  table->horizontalHeader()->setStretchLastSection(true);
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(table);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  layout->addWidget(buttons);
  dialog.resize(560, 520);
  dialog.exec();
}

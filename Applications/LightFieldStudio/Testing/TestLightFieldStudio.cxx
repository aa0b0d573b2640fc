// LightField Studio's main window driven in-process as a user drives it:
// open the demo scene, orbit the view with the mouse, drag a corner of the
// cage widget with the mouse (one command), a refused fold, two keyframes,
// save (equals the committed scene baseline), export the animation (and
// cancel an export), the calibration views (a click on a camera frustum in
// the rig view selects that view; every view of the demo has a coverage of
// at least 0.98), a four-up screenshot (equals the committed baseline
// image), undo of everything (the scene saves byte for byte as loaded), a
// malformed scene (its error in the status bar, the scene kept), a light
// field with projectors whose mask is painted with the mouse (one command,
// undone byte for byte), and the boxes dock. Run under Xvfb with
// QT_QPA_PLATFORM=xcb; the data come from the fixture tests (lfd demo,
// lfd synth), paths in the environment (see CMakeLists.txt).
#include "lfdStudioMainWindow.h"
#include "lfdStudioViews.h"

#include "QVTKOpenGLNativeWidget.h"
#include "lfdPinholeCamera.h"
#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCell.h"
#include "vtkDeformationCage.h"
#include "vtkGantryCameraView.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProjectorView.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRigView.h"
#include "vtkTesting.h"
#include "vtkTrivialProducer.h"
#include "vtkUnsignedCharArray.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <cstring>
#include <vector>

namespace
{
/// Display position (x, y, z; y up) of a world point in `renderer`.
void ToDisplay(vtkRenderer* renderer, const double world[3], double display[3])
{
  renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
}

/// A mouse event with the left button held or not, as a user's.
void SendMouse(QWidget* view, QEvent::Type type, const QPoint& at, Qt::MouseButtons held)
{
  const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
  QMouseEvent event(type, at, button, held, Qt::NoModifier);
  QApplication::sendEvent(view, &event);
}

QString Env(const char* name)
{
  return QString::fromLocal8Bit(qgetenv(name));
}

QByteArray ReadAll(const QString& fileName)
{
  QFile file(fileName);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// `image` (a QWidget grab) as a VTK RGB image, bottom row first.
vtkSmartPointer<vtkImageData> ToVTK(const QImage& grabbed)
{
  const QImage image = grabbed.convertToFormat(QImage::Format_RGB888);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width(), image.height(), 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(data->GetScalarPointer());
  for (int y = 0; y < image.height(); ++y)
  {
    std::memcpy(pixels + 3 * image.width() * (image.height() - 1 - y),
      image.constScanLine(y),
      3 * image.width());
  }
  return data;
}

/// A left-button drag in `view` through `path` (display positions, y up).
void Drag(QWidget* view, const std::vector<QPoint>& path)
{
  const auto at = [view](const QPoint& p) { return QPoint(p.x(), view->height() - 1 - p.y()); };
  SendMouse(view, QEvent::MouseMove, at(path.front()), Qt::NoButton);
  SendMouse(view, QEvent::MouseButtonPress, at(path.front()), Qt::LeftButton);
  for (size_t k = 1; k < path.size(); ++k)
  {
    SendMouse(view, QEvent::MouseMove, at(path[k]), Qt::LeftButton);
  }
  SendMouse(view, QEvent::MouseButtonRelease, at(path.back()), Qt::NoButton);
}

/// The bytes of a light field's projector masks.
QByteArray MaskBytes(vtkLightField* lightField)
{
  vtkImageData* masks = lightField->GetProjectorMasks();
  return QByteArray(static_cast<const char*>(masks->GetScalarPointer()),
    static_cast<int>(masks->GetNumberOfPoints() * masks->GetNumberOfScalarComponents()));
}

QPushButton* Button(QWidget* window, const QString& text)
{
  for (QPushButton* button : window->findChildren<QPushButton*>())
  {
    if (button->text() == text)
    {
      return button;
    }
  }
  return nullptr;
}
}

class TestLightFieldStudio : public QObject
{
  Q_OBJECT

private:
  lfdStudioMainWindow* Window = nullptr;
  QString Demo;
  QString Temp;
  QString Baselines;

  vtkLightFieldSceneLogic* Logic() { return this->Window->GetLogic(); }
  QString Status() { return this->Window->statusBar()->currentMessage(); }
  QString UndoText() { return this->Window->findChild<QAction*>("Undo")->text(); }

private Q_SLOTS:
  void initTestCase()
  {
    this->Demo = Env("LFD_STUDIO_DEMO");
    this->Temp = Env("LFD_TEMP_DIR");
    this->Baselines = Env("LFD_STUDIO_BASELINE_DIR");
    QVERIFY(QFile::exists(this->Demo + "/swim.json"));
    // Settings of this run only: the window starts at its default layout.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, this->Temp + "/StudioSettings");
    QSettings().clear();
    this->Window = new lfdStudioMainWindow;
    this->Window->resize(1000, 700);
    this->Window->show();
    QVERIFY(QTest::qWaitForWindowExposed(this->Window));
  }

  void cleanupTestCase() { delete this->Window; }

  void openScene()
  {
    QVERIFY(this->Window->OpenFile(this->Demo + "/swim.json"));
    QCOMPARE(this->Status(), QString("Opened swim.json"));
    QCOMPARE(this->Window->findChild<QTableWidget*>("Boxes")->rowCount(), 3);
    QCOMPARE(this->Window->findChild<QListWidget*>("Keyframes")->count(), 9);
    QCOMPARE(this->Window->windowTitle(), QString("swim.json - LightField Studio"));
    QVERIFY(!this->Window->findChild<QAction*>("Undo")->isEnabled());
    QVERIFY(this->Window->SaveSceneAs(this->Demo + "/loaded.json"));
    QCOMPARE(ReadAll(this->Demo + "/loaded.json"), ReadAll(this->Demo + "/swim.json"));
  }

  void orbitWithTheMouse()
  {
    // QTest mouse events reach VTK's interactor (trackball camera style).
    QWidget* view = this->Window->GetViewWidget();
    vtkCamera* camera = this->Window->GetViews()->GetMainRenderer()->GetActiveCamera();
    double before[3];
    camera->GetPosition(before);
    // Low on the view, below the fish and its cage: no corner there.
    const QPoint from(view->width() / 2, view->height() - 20);
    SendMouse(view, QEvent::MouseMove, from, Qt::NoButton);
    SendMouse(view, QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int step = 1; step <= 5; ++step)
    {
      SendMouse(view, QEvent::MouseMove, from + QPoint(8 * step, 0), Qt::LeftButton);
    }
    SendMouse(view, QEvent::MouseButtonRelease, from + QPoint(40, 0), Qt::NoButton);
    double after[3];
    camera->GetPosition(after);
    QVERIFY(std::abs(after[0] - before[0]) + std::abs(after[2] - before[2]) > 1e-3);
    // The orbit is a view change, not an edit, until it is stored.
    QVERIFY(!this->Logic()->CanUndo());
    this->Window->ResetCamera();
    camera->GetPosition(after);
    QCOMPARE(after[0], before[0]);
    QCOMPARE(after[2], before[2]);
  }

  void dragOnePoint()
  {
    // A drag of a visible corner of the cage widget with QTest mouse
    // events on the VTK widget: one interaction, one command.
    QWidget* view = this->Window->GetViewWidget();
    vtkRenderer* renderer = this->Window->GetViews()->GetMainRenderer();
    vtkCageRepresentation* cage =
      this->Window->GetViews()->GetEditor()->GetWidget()->GetCageRepresentation();
    // The first corner the widget can pick that is well inside the view.
    const vtkIdType points = this->Logic()->GetCage()->GetNumberOfPoints();
    vtkIdType corner = 0;
    double world[3];
    double start[3];
    for (; corner < points; ++corner)
    {
      this->Logic()->GetCage()->GetDeformedPoint(corner, world);
      ToDisplay(renderer, world, start);
      if (cage->IsPointVisible(corner) && start[0] > 10 && start[0] < view->width() - 10 &&
        start[1] > 30 && start[1] < view->height() - 10)
      {
        break;
      }
    }
    QVERIFY(corner < points);
    const QPoint from(static_cast<int>(std::lround(start[0])),
      view->height() - 1 - static_cast<int>(std::lround(start[1])));
    SendMouse(view, QEvent::MouseMove, from, Qt::NoButton);
    SendMouse(view, QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int step = 1; step <= 4; ++step)
    {
      SendMouse(view, QEvent::MouseMove, from - QPoint(0, 5 * step), Qt::LeftButton);
    }
    SendMouse(view, QEvent::MouseButtonRelease, from - QPoint(0, 20), Qt::NoButton);
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 1);
    QCOMPARE(this->UndoText(), QString("Undo Move 1 point"));
    QCOMPARE(this->Window->windowTitle(), QString("loaded.json* - LightField Studio"));
    // The corner followed the cursor: 20 pixels up on the screen.
    double end[3];
    this->Logic()->GetCage()->GetDeformedPoint(corner, world);
    ToDisplay(renderer, world, end);
    QVERIFY2(std::abs(end[0] - start[0]) < 0.5 && std::abs(end[1] - start[1] - 20.0) < 0.5,
      qPrintable(
        QString("display %1 %2 from %3 %4").arg(end[0]).arg(end[1]).arg(start[0]).arg(start[1])));
  }

  void refusedFold()
  {
    // Corner 0 of box 0 dragged past corner 6: the box folds, the move is
    // refused with its reason in the status bar, the cage is unchanged.
    vtkDeformationCage* cage = this->Logic()->GetCage();
    double corners[24];
    QVERIFY(cage->GetDeformedCorners(0, corners));
    vtkIdType corner0 = cage->GetCell(0)->GetPointId(0);
    const double beyond[3] = {
      2.0 * corners[18] - corners[0], 2.0 * corners[19] - corners[1], 2.0 * corners[20] - corners[2]
    };
    QVERIFY(!this->Logic()->MovePoint(corner0, beyond));
    QCOMPARE(this->Status(),
      this->Demo +
        "/loaded.json: cage: box 0 (label 3): the deformed box folds (Jacobian determinant "
        "-0.317699 at uvw (0, 0, 0), up to 0.0661055 elsewhere)");
    double now[3];
    cage->GetDeformedPoint(corner0, now);
    QCOMPARE(now[0], corners[0]);
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 1);
  }

  void keyTwoFrames()
  {
    auto* time = this->Window->findChild<QDoubleSpinBox*>("KeyTime");
    time->setValue(0.0);
    this->Window->SetKeyframe();
    double p[3];
    this->Logic()->GetCage()->GetDeformedPoint(9, p);
    QVERIFY(this->Logic()->MovePoint(9, p[0] + 0.05, p[1], p[2]));
    time->setValue(8.0);
    this->Window->SetKeyframe();
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 4);
    QCOMPARE(this->UndoText(), QString("Undo Set keyframe"));
    QCOMPARE(this->Window->findChild<QListWidget*>("Keyframes")->count(), 9);
    // The timeline's interpolation is the scene's: one undoable edit, saved
    // in scene.json (the baseline holds "linear").
    this->Window->findChild<QComboBox*>("Interpolation")->setCurrentIndex(0);
    QCOMPARE(this->Logic()->GetInterpolation(), 0);
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 5);
    QCOMPARE(this->UndoText(), QString("Undo Set interpolation"));
    // Scrubbing shows the interpolated cage, edits nothing.
    this->Window->findChild<QSlider*>("Scrub")->setValue(500);
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 5);
  }

  void saveEqualsBaseline()
  {
    QVERIFY(this->Window->SaveSceneAs(this->Demo + "/studio.json"));
    QCOMPARE(this->Status(), QString("Saved studio.json"));
    const QByteArray saved = ReadAll(this->Demo + "/studio.json");
    const QByteArray baseline = ReadAll(this->Baselines + "/TestLightFieldStudio.json");
    if (saved != baseline)
    {
      QFile::copy(this->Demo + "/studio.json", this->Temp + "/TestLightFieldStudio.json");
    }
    QVERIFY2(
      saved == baseline, "studio.json differs from the baseline (candidate in the temp dir)");
  }

  void exportAnimation()
  {
    const QString folder = this->Demo + "/export";
    QVERIFY(this->Window->ExportAnimationTo(folder, 2));
    QVERIFY2(
      this->Status().startsWith("Exported 2 frames to " + folder), qPrintable(this->Status()));
    for (const char* file : { "frame_0000.png", "frame_0001.png", "contact_sheet.png" })
    {
      QVERIFY2(QFile::exists(folder + "/" + file), file);
    }
    QVERIFY(!QFile::exists(folder + "/frame_0002.png"));

    // Cancel in the progress dialog: nothing written, the folder unchanged.
    const QString cancelled = this->Demo + "/cancelled";
    QDir(cancelled).removeRecursively();
    QTimer::singleShot(0,
      [this]
      {
        QProgressDialog* dialog = this->Window->findChild<QProgressDialog*>();
        QVERIFY(dialog);
        dialog->cancel();
      });
    QVERIFY(!this->Window->ExportAnimationTo(cancelled, 3));
    QCOMPARE(this->Status(), "Export cancelled: " + cancelled + " is unchanged");
    QVERIFY(!QDir(cancelled).exists());
  }

  void calibrationViews()
  {
    this->Window->SetLayout(lfdStudioViews::FOUR_UP);
    lfdStudioViews* views = this->Window->GetViews();
    vtkRenderer* rig = views->GetRigView()->GetRenderer();
    // A click inside the frustum of the camera nearest the rig view's eye
    // (on its optical axis, half way to the frustum's base at a quarter of
    // the ring radius) selects that view: the gantry slider follows.
    vtkLightField* lightField = views->GetLightField();
    vtkCameraRig* cameras = lightField->GetRig();
    const double* eye = rig->GetActiveCamera()->GetPosition();
    const glm::dvec3 e(eye[0], eye[1], eye[2]);
    int nearest = 0;
    for (int v = 1; v < cameras->GetNumberOfViews(); ++v)
    {
      if (glm::length(cameras->GetCamera(v).Center() - e) <
        glm::length(cameras->GetCamera(nearest).Center() - e))
      {
        nearest = v;
      }
    }
    // Another view shown first, so the click changes it.
    this->Window->findChild<QSlider*>("GantryView")
      ->setValue((nearest + 1) % cameras->GetNumberOfViews());
    const glm::dvec3 inside = cameras->GetCamera(nearest).Unproject(
      glm::dvec2(0.5 * lightField->GetWidth() - 0.5, 0.5 * lightField->GetHeight() - 0.5),
      0.125 * cameras->GetRadius());
    const double world[3] = { inside.x, inside.y, inside.z };
    double display[3];
    ToDisplay(rig, world, display);
    const QPoint click(
      static_cast<int>(std::lround(display[0])), static_cast<int>(std::lround(display[1])));
    QVERIFY(rig->IsInViewport(click.x(), click.y()));
    Drag(this->Window->GetViewWidget(), { click });
    QCOMPARE(this->Window->findChild<QSlider*>("GantryView")->value(), nearest);
    QCOMPARE(views->GetCameraView(), nearest);
    QCOMPARE(views->GetRigView()->GetCurrentView(), nearest);
    // Selecting a view edits nothing.
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 5);

    // Paper section 4.1: the projected rest boxes cover the labelled pixels
    // of the fish in every view (as `lfd split check` reports).
    auto* pass = this->Window->findChild<QComboBox*>("Pass");
    QCOMPARE(pass->count(), vtkLightField::NUMBER_OF_PASSES + 1);
    QCOMPARE(pass->itemText(vtkGantryCameraView::NORMALISED), QString("Normalised (B')"));
    pass->setCurrentIndex(vtkLightField::LABEL);
    auto* slider = this->Window->findChild<QSlider*>("GantryView");
    for (int view = 0; view <= slider->maximum(); ++view)
    {
      slider->setValue(view);
      const double coverage = this->Window->findChild<QLabel*>("Coverage")->text().toDouble();
      QVERIFY2(coverage >= 0.98, qPrintable(QString("view %1: %2").arg(view).arg(coverage)));
      QCOMPARE(coverage, std::round(views->GetCoverage() * 1e4) / 1e4);
    }
    pass->setCurrentIndex(vtkLightField::COAXIAL);
    this->Window->SetLayout(lfdStudioViews::MAIN_ONLY);
  }

  void screenshotEqualsBaseline()
  {
    this->Window->SetLayout(lfdStudioViews::FOUR_UP);
    this->Window->GetViews()->SetFrameTimeVisible(false);
    this->Window->findChild<QSlider*>("GantryView")->setValue(3);
    this->Window->findChild<QSlider*>("Scrub")->setValue(0);
    this->Window->ShowTime(-1.0);
    // The last message names a folder of this build.
    this->Window->statusBar()->clearMessage();
    QTest::qWait(100);
    vtkNew<vtkTrivialProducer> image;
    image->SetOutput(ToVTK(this->Window->grab().toImage()));
    vtkNew<vtkTesting> testing;
    testing->AddArgument("-V");
    testing->AddArgument(qPrintable(this->Baselines + "/TestLightFieldStudio.png"));
    testing->AddArgument("-T");
    testing->AddArgument(qPrintable(this->Temp));
    QCOMPARE(testing->RegressionTest(image, 0.15), static_cast<int>(vtkTesting::PASSED));
    this->Window->GetViews()->SetFrameTimeVisible(true);
    this->Window->SetLayout(lfdStudioViews::MAIN_ONLY);
  }

  void undoEverything()
  {
    int undone = 0;
    while (this->Logic()->CanUndo())
    {
      this->Window->Undo();
      ++undone;
    }
    QCOMPARE(undone, 5);
    QCOMPARE(this->Status(), QString("Undid Move 1 point"));
    QVERIFY(!this->Window->findChild<QAction*>("Undo")->isEnabled());
    QCOMPARE(this->Window->findChild<QAction*>("Redo")->text(), QString("Redo Move 1 point"));
    QVERIFY(this->Window->SaveSceneAs(this->Demo + "/undone.json"));
    QCOMPARE(ReadAll(this->Demo + "/undone.json"), ReadAll(this->Demo + "/loaded.json"));
  }

  void malformedSceneIsRefused()
  {
    const QString bad = this->Demo + "/malformed.json";
    QFile file(bad);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"version\": 1, \"cage\": ");
    file.close();
    QVERIFY(!this->Window->OpenFile(bad));
    QCOMPARE(this->Status(),
      bad +
        ": not valid JSON: parse error at line 1, column 25: syntax error while parsing value - "
        "unexpected end of input; expected '[', '{', or a literal");
    QCOMPARE(this->Window->GetSceneFile(), this->Demo + "/undone.json");
    QCOMPARE(this->Window->findChild<QTableWidget*>("Boxes")->rowCount(), 3);
    QCOMPARE(this->Logic()->GetCage()->GetNumberOfBoxes(), vtkIdType(3));
  }

  void boxesDock()
  {
    auto* boxes = this->Window->findChild<QTableWidget*>("Boxes");
    // A row's check box hides and shows its box in the cage widget.
    vtkCageRepresentation* representation =
      this->Window->GetViews()->GetEditor()->GetWidget()->GetCageRepresentation();
    QCOMPARE(boxes->item(0, 0)->checkState(), Qt::Checked);
    boxes->item(0, 0)->setCheckState(Qt::Unchecked);
    QVERIFY(!representation->GetBoxVisibility(0) && representation->GetBoxVisibility(1));
    boxes->item(0, 0)->setCheckState(Qt::Checked);
    QVERIFY(representation->GetBoxVisibility(0));
    QPushButton* add = Button(this->Window, "Add");
    QVERIFY(add);
    add->click();
    QCOMPARE(boxes->rowCount(), 4);
    QCOMPARE(this->UndoText(), QString("Undo Add box"));
    boxes->selectRow(3);
    this->Window->findChild<QComboBox*>("SplitAxis")->setCurrentIndex(2);
    Button(this->Window, "Split")->click();
    QCOMPARE(boxes->rowCount(), 5);
    QCOMPARE(this->UndoText(), QString("Undo Split box"));
    boxes->selectRow(4);
    Button(this->Window, "Remove")->click();
    QCOMPARE(boxes->rowCount(), 4);
    // Relabelling to a label the light field does not hold is refused.
    boxes->selectRow(0);
    this->Window->findChild<QSpinBox*>("Label")->setValue(200);
    Button(this->Window, "Relabel")->click();
    QCOMPARE(this->Status(),
      this->Demo +
        "/undone.json: cage: box 0 (label 200): the light field's Label pass has no sub-light "
        "field 200");
    QCOMPARE(boxes->item(0, 1)->text(), QString("3"));
    while (this->Logic()->CanUndo())
    {
      this->Window->Undo();
    }
    QCOMPARE(boxes->rowCount(), 3);
  }

  void openLightFieldWithProjectors()
  {
    QVERIFY(this->Window->OpenFile(Env("LFD_STUDIO_PROJECTORS")));
    QCOMPARE(this->Window->findChild<QComboBox*>("Projector")->count(), 2);
    QCOMPARE(this->Window->findChild<QSlider*>("GantryView")->maximum(), 11);
    QCOMPARE(this->Window->findChild<QTableWidget*>("Boxes")->rowCount(), 0);
    QCOMPARE(this->Window->windowTitle(), QString("untitled - LightField Studio"));
    // No boxes: no coverage.
    QCOMPARE(this->Window->findChild<QLabel*>("Coverage")->text(), QString("n/a"));
  }

  void paintProjectorMask()
  {
    // A stroke across the middle of the projector view (four-up: bottom
    // left) in the palette colour of label 3: one command, undone byte for
    // byte.
    this->Window->SetLayout(lfdStudioViews::FOUR_UP);
    this->Window->findChild<QComboBox*>("Projector")->setCurrentIndex(1);
    this->Window->findChild<QComboBox*>("BrushLabel")->setCurrentIndex(3);
    this->Window->findChild<QDoubleSpinBox*>("BrushRadius")->setValue(3.0);
    vtkProjectorView* projector = this->Window->GetViews()->GetProjectorView();
    QCOMPARE(projector->GetBrushLabel(), 3);
    QCOMPARE(projector->GetBrushRadius(), 3.0);
    // `lfd synth` recorded the fish in the provenance: it is simulated.
    QVERIFY(projector->GetSimulationMesh() != nullptr);
    vtkLightField* lightField = this->Window->GetViews()->GetLightField();
    const QByteArray before = MaskBytes(lightField);
    const int* size = projector->GetRenderer()->GetSize();
    const int* origin = projector->GetRenderer()->GetOrigin();
    const QPoint middle(origin[0] + size[0] / 2, origin[1] + size[1] / 2);
    Drag(this->Window->GetViewWidget(),
      { middle - QPoint(30, 0),
        middle - QPoint(10, 5),
        middle + QPoint(10, 5),
        middle + QPoint(30, 0) });
    QCOMPARE(this->Logic()->GetNumberOfCommands(), 1);
    QCOMPARE(this->UndoText(), QString("Undo Paint projector mask"));
    const QByteArray painted = MaskBytes(lightField);
    QVERIFY(painted != before);
    // The coded pass of the current view was re-rendered under the stroke.
    QVERIFY(projector->GetSimulatedImage()->GetNumberOfPoints() > 0);
    QTest::qWait(100);
    this->Window->grab().save(this->Temp + "/studio_four_up.png");
    // Save Projector Masks writes one image per projector.
    QVERIFY(this->Window->SaveProjectorMasksTo(this->Temp + "/StudioMasks"));
    QCOMPARE(this->Status(), "Saved 2 projector masks to " + this->Temp + "/StudioMasks");
    QVERIFY(QFile::exists(this->Temp + "/StudioMasks/projector_1.png"));
    this->Window->Undo();
    QCOMPARE(MaskBytes(lightField), before);
    this->Window->Redo();
    QCOMPARE(MaskBytes(lightField), painted);
    this->Window->SetLayout(lfdStudioViews::MAIN_ONLY);
  }
};

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  TestLightFieldStudio test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestLightFieldStudio.moc"

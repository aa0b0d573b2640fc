/**
 * @file   main.cxx
 * @brief  LightField Studio: `LightFieldStudio [options] [scene.json | lightfield.lf]`
 *         (also started by `lfd studio`).
 *
 * With --screenshot the Studio opens the file, writes a PNG of its window
 * and exits (status 1 with the error on stderr when the file is refused):
 * how the README's pictures are made, and a check that runs headless.
 */
#include "lfdStudioMainWindow.h"
#include "lfdStudioViews.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkGantryCameraView.h"
#include "vtkLightField.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTest>

#include <iostream>

namespace
{
/// --screenshot: the window once it has drawn, as a PNG; false with the
/// reason on stderr.
bool Screenshot(lfdStudioMainWindow& window, const QString& fileName)
{
  if (!QTest::qWaitForWindowExposed(&window))
  {
    std::cerr << "LightFieldStudio: the window was never shown (no display?)\n";
    return false;
  }
  QTest::qWait(200);
  if (!window.grab().save(fileName, "PNG"))
  {
    std::cerr << "LightFieldStudio: " << qPrintable(fileName) << ": cannot be written\n";
    return false;
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  // The OpenGL format VTK needs, before the application creates a context.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  QApplication::setOrganizationName("LightFieldDeform");
  QApplication::setApplicationName("LightFieldStudio");
  QApplication::setApplicationVersion(LFD_VERSION);

  QCommandLineParser parser;
  parser.setApplicationDescription(
    "LightField Studio: deform a light field by dragging the corners of its cage, beside the "
    "gantry camera, projector and rig views");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("file", "a scene (scene.json) or a light field (*.lf) to open");
  const QCommandLineOption layout("layout", "views: main, camera or four-up", "layout");
  const QCommandLineOption view("view", "the gantry camera view's captured view", "index");
  const QCommandLineOption pass(
    "pass", "the gantry camera view's pass (Coaxial, Label, Normalised...)", "pass");
  const QCommandLineOption projector("projector", "the projector view's projector", "index");
  const QCommandLineOption screenshot(
    "screenshot", "write a PNG of the window once it has drawn, then exit", "png");
  parser.addOptions({ layout, view, pass, projector, screenshot });
  parser.process(application);

  lfdStudioMainWindow window;
  window.show();
  const QStringList files = parser.positionalArguments();
  const bool opened = files.isEmpty() || window.OpenFile(files.front());
  const QStringList layouts = { "main", "camera", "four-up" };
  if (parser.isSet(layout))
  {
    if (!layouts.contains(parser.value(layout)))
    {
      std::cerr << "LightFieldStudio: --layout: " << qPrintable(parser.value(layout))
                << " is not one of main, camera, four-up\n";
      return 1;
    }
    window.SetLayout(layouts.indexOf(parser.value(layout)));
  }
  // Normalised: the coded pass divided by the flood pass (B', Eq. 1).
  const int passIndex = !parser.isSet(pass) ? 0
    : parser.value(pass) == "Normalised"
    ? static_cast<int>(vtkGantryCameraView::NORMALISED)
    : vtkLightField::GetPassFromName(qPrintable(parser.value(pass)));
  if (passIndex < 0)
  {
    std::cerr << "LightFieldStudio: --pass: " << qPrintable(parser.value(pass))
              << " is not a pass (Coaxial, Coded, Flood, Label, Depth, Confidence, Normalised)\n";
    return 1;
  }
  window.ShowView(parser.value(view).toInt(), passIndex, parser.value(projector).toInt());
  if (parser.isSet(screenshot))
  {
    if (!opened)
    {
      std::cerr << "LightFieldStudio: " << qPrintable(window.statusBar()->currentMessage()) << "\n";
      return 1;
    }
    return Screenshot(window, parser.value(screenshot)) ? 0 : 1;
  }
  return QApplication::exec();
}

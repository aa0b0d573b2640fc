// A projector window on the test's X screen: a Gray-code pattern, white
// (Flood), a colour mask (Coded) and black (Off) each cover the whole
// screen pixel for pixel (a screenshot of the root window, compared with
// the pattern exactly); a pattern of the wrong size and a display that
// does not exist are one error each.
#include "vtkDataArray.h"
#include "vtkGrayCodePatternSource.h"
#include "vtkImageData.h"
#include "vtkLightField.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProjectorWindow.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what, double value, double expected)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << ": " << value << " (expected " << expected
            << ")\n";
  Failures += ok ? 0 : 1;
}

// Pixels of the X screen that differ from `pattern` (rows bottom first).
long CountScreenDifferences(Display* display, vtkImageData* pattern)
{
  const int w = pattern->GetDimensions()[0];
  const int h = pattern->GetDimensions()[1];
  XImage* shot = XGetImage(display, DefaultRootWindow(display), 0, 0, w, h, AllPlanes, ZPixmap);
  const auto* rgb = static_cast<const unsigned char*>(pattern->GetScalarPointer());
  long differences = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const unsigned long pixel = XGetPixel(shot, x, y);
      const unsigned char* expected = rgb + 3 * (static_cast<size_t>(h - 1 - y) * w + x);
      differences += ((pixel >> 16) & 255) != expected[0] || ((pixel >> 8) & 255) != expected[1] ||
          (pixel & 255) != expected[2]
        ? 1
        : 0;
    }
  }
  XDestroyImage(shot);
  return differences;
}
}

int TestProjectorWindow(int, char*[])
{
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    std::cerr << "No X display: run under xvfb-run -a.\n";
    return EXIT_FAILURE;
  }
  const int w = DisplayWidth(display, DefaultScreen(display));
  const int h = DisplayHeight(display, DefaultScreen(display));
  std::cout << "screen " << w << " x " << h << "\n";

  vtkNew<vtkLightFieldErrorObserver> errors;
  vtkNew<vtkProjectorWindow> projector;
  projector->SetName("test");
  errors->Observe(projector);
  vtkNew<vtkGrayCodePatternSource> gray;
  gray->SetWidth(w);
  gray->SetHeight(h);
  gray->SetPatternIndex(5);
  gray->Update();
  Check(projector->ShowPattern(gray->GetOutput()), "Gray code 5 shown", 1, 1);
  Check(CountScreenDifferences(display, gray->GetOutput()) == 0,
    "screen pixels unlike Gray code 5",
    CountScreenDifferences(display, gray->GetOutput()),
    0);

  vtkNew<vtkImageData> white;
  white->SetDimensions(w, h, 1);
  white->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  white->GetPointData()->GetScalars()->Fill(255);
  Check(projector->Apply(vtkLightField::FLOOD), "Flood applied", 1, 1);
  const long notWhite = CountScreenDifferences(display, white);
  Check(notWhite == 0, "screen pixels not white in the Flood pass", notWhite, 0);

  // A colour mask: a different colour in every 64 x 64 block.
  vtkNew<vtkImageData> masks;
  masks->SetDimensions(w, h, 1);
  masks->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* mask = static_cast<unsigned char*>(masks->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      unsigned char* rgb = mask + 3 * (static_cast<size_t>(j) * w + i);
      rgb[0] = static_cast<unsigned char>(40 * (i / 64));
      rgb[1] = static_cast<unsigned char>(40 * (j / 64));
      rgb[2] = static_cast<unsigned char>(i + j);
    }
  }
  projector->SetMasks(masks);
  Check(projector->Apply(vtkLightField::CODED), "Coded applied", 1, 1);
  const long notMask = CountScreenDifferences(display, masks);
  Check(notMask == 0, "screen pixels unlike the mask in the Coded pass", notMask, 0);

  projector->Off();
  white->GetPointData()->GetScalars()->Fill(0);
  const long notBlack = CountScreenDifferences(display, white);
  Check(notBlack == 0, "screen pixels not black after Off()", notBlack, 0);
  Check(!errors->HasError(), "errors so far", errors->HasError(), 0);

  vtkNew<vtkImageData> small;
  small->SetDimensions(64, 48, 1);
  small->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  Check(!projector->ShowPattern(small), "a 64 x 48 pattern is refused", 1, 1);
  const std::string sizeError = "Projector test: shows RGB uint8 patterns of " + std::to_string(w) +
    " x " + std::to_string(h) + " pixels; the pattern is 64 x 48 x 1 of 3 components.";
  std::cout << "error: " << errors->GetErrorMessage() << "\n";
  Check(sizeError == errors->GetErrorMessage(), "exact size error", 0, 0);
  projector->Close();
  errors->Clear();

  vtkNew<vtkProjectorWindow> missing;
  missing->SetName("projector 2");
  missing->SetDisplay(":99.3");
  errors->Observe(missing);
  Check(!missing->Apply(vtkLightField::FLOOD), "a display that does not exist fails", 1, 1);
  std::cout << "error: " << errors->GetErrorMessage() << "\n";
  Check(std::string(errors->GetErrorMessage()) ==
      "Projector projector 2: cannot open the X display :99.3.",
    "exact display error",
    0,
    0);
  XCloseDisplay(display);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

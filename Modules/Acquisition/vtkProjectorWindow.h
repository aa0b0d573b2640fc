/**
 * @class   vtkProjectorWindow
 * @brief   a real projector: patterns shown full screen on an X screen
 *
 * A video projector is a screen of the X server (e.g. `:0.1` for the second
 * screen of display 0, or its own display `:1`). The first pattern opens a
 * borderless window covering that whole screen at (0, 0); every pattern is
 * then drawn 1:1 into it, pixel for pixel (no scaling, no filtering), so the
 * pattern must be the screen's size: Resolution, when unset, is taken from
 * the screen. Close() (or the destructor) takes the window down.
 *
 * Opening a display that does not exist, or a pattern that is not the
 * screen's size, gives one error naming the projector and the display.
 *
 * @sa vtkCaptureProjector vtkGrayCodePatternSource vtkSimulatedProjector
 */
#ifndef vtkProjectorWindow_h
#define vtkProjectorWindow_h

#include "lfdAcquisitionModule.h" // For export macro
#include "vtkCaptureProjector.h"

class vtkRenderWindow;

class LFDACQUISITION_EXPORT vtkProjectorWindow : public vtkCaptureProjector
{
public:
  static vtkProjectorWindow* New();
  vtkTypeMacro(vtkProjectorWindow, vtkCaptureProjector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The X display and screen of the projector, e.g. ":0.1". Default
   * nullptr: $DISPLAY.
   */
  vtkSetStringMacro(Display);
  vtkGetStringMacro(Display);
  ///@}

  bool ShowPattern(vtkImageData* pattern) override;

  /**
   * Closes the window and the display connection; safe when not open.
   */
  void Close();

protected:
  vtkProjectorWindow();
  ~vtkProjectorWindow() override;

  /**
   * Opens the display and the full-screen window (once); false with an
   * error.
   */
  bool PrepareDevice() override;

  char* Display = nullptr;

private:
  vtkProjectorWindow(const vtkProjectorWindow&) = delete;
  void operator=(const vtkProjectorWindow&) = delete;

  vtkRenderWindow* Window = nullptr;
  void* Connection = nullptr; // the X Display
};

#endif

#include "vtkProjectorWindow.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <string>

vtkStandardNewMacro(vtkProjectorWindow);

//------------------------------------------------------------------------------
vtkProjectorWindow::vtkProjectorWindow() = default;

//------------------------------------------------------------------------------
vtkProjectorWindow::~vtkProjectorWindow()
{
  this->Close();
  this->SetDisplay(nullptr);
}

//------------------------------------------------------------------------------
bool vtkProjectorWindow::PrepareDevice()
{
  if (this->Window)
  {
    return true;
  }
  const char* environment = std::getenv("DISPLAY");
  const std::string display =
    this->Display ? this->Display : (environment ? environment : "(DISPLAY not set)");
  const char* name = this->Name ? this->Name : "(unnamed)";
  ::Display* connection = XOpenDisplay(this->Display);
  if (!connection)
  {
    vtkErrorMacro("Projector " << name << ": cannot open the X display " << display << ".");
    return false;
  }
  const int screen = DefaultScreen(connection);
  const int size[2] = { DisplayWidth(connection, screen), DisplayHeight(connection, screen) };
  if (this->Resolution[0] == 0 && this->Resolution[1] == 0)
  {
    this->SetResolution(size[0], size[1]);
  }
  if (this->Resolution[0] != size[0] || this->Resolution[1] != size[1])
  {
    vtkErrorMacro("Projector " << name << ": the screen " << display << " is " << size[0] << " x "
                               << size[1] << " pixels, the projector's Resolution "
                               << this->Resolution[0] << " x " << this->Resolution[1] << ".");
    XCloseDisplay(connection);
    return false;
  }
  this->Connection = connection;
  this->Window = vtkRenderWindow::New();
  this->Window->SetDisplayId(connection);
  this->Window->SetWindowName(name);
  this->Window->BordersOff();
  this->Window->SetMultiSamples(0);
  this->Window->SetPosition(0, 0);
  this->Window->SetSize(size[0], size[1]);
  vtkNew<vtkRenderer> black;
  black->SetBackground(0.0, 0.0, 0.0);
  this->Window->AddRenderer(black);
  this->Window->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkProjectorWindow::ShowPattern(vtkImageData* pattern)
{
  if (!this->PrepareDevice() || !this->CheckPattern(pattern))
  {
    return false;
  }
  // Drawn into the back buffer and swapped in: the projector never shows
  // half a pattern.
  this->Window->SetPixelData(0,
    0,
    this->Resolution[0] - 1,
    this->Resolution[1] - 1,
    static_cast<unsigned char*>(pattern->GetScalarPointer()),
    0);
  this->Window->Frame();
  this->Window->WaitForCompletion();
  XSync(static_cast<::Display*>(this->Connection), False);
  return true;
}

//------------------------------------------------------------------------------
void vtkProjectorWindow::Close()
{
  if (this->Window)
  {
    this->Window->Finalize();
    this->Window->Delete();
    this->Window = nullptr;
  }
  if (this->Connection)
  {
    XCloseDisplay(static_cast<::Display*>(this->Connection));
    this->Connection = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkProjectorWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Display: " << (this->Display ? this->Display : "($DISPLAY)") << "\n";
  os << indent << "Open: " << (this->Window ? "yes" : "no") << "\n";
}

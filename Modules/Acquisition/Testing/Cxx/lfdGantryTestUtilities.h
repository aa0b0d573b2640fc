/**
 * @file   lfdGantryTestUtilities.h
 * @brief  What the gantry tests share: a simulator served in this process
 *         on a free port of 127.0.0.1 and a client connected to it, and
 *         checks that print the measured value.
 */
#ifndef lfdGantryTestUtilities_h
#define lfdGantryTestUtilities_h

#include "vtkGantrySimulator.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkModbusGantry.h"
#include "vtkNew.h"

#include <chrono>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

namespace lfd
{
namespace test
{
/// Prints the measured value next to what was expected; false on a mismatch.
template<typename T>
bool Check(bool condition, const std::string& what, const T& value)
{
  std::cout << (condition ? "ok   " : "FAIL ") << what << ": " << value << "\n";
  return condition;
}

/// The observer's only error is `expected`.
inline bool CheckError(vtkLightFieldErrorObserver* errors, const std::string& expected)
{
  const std::string message = errors->HasError() ? errors->GetErrorMessage() : "(no error)";
  const bool one = errors->GetNumberOfErrors() == 1;
  const bool ok = Check(message == expected && one,
    "error '" + expected + "'",
    message + (one ? "" : " (" + std::to_string(errors->GetNumberOfErrors()) + " errors)"));
  errors->Clear();
  return ok;
}

inline double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline void Sleep(double seconds)
{
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

/**
 * A simulator serving on a free port and a client set up for short moves:
 * 60 degree/s, 240 degree/s^2 (a 30 degree move takes 0.75 s), answers
 * within 0.2 s, a 0.3 s watchdog.
 */
struct GantryRig
{
  vtkNew<vtkGantrySimulator> Simulator;
  vtkNew<vtkModbusGantry> Gantry;
  vtkNew<vtkLightFieldErrorObserver> Errors;

  GantryRig()
  {
    this->Simulator->SetStartAngle(10.0);
    this->Errors->Observe(this->Simulator);
    this->Errors->Observe(this->Gantry);
    this->Gantry->SetAddress("127.0.0.1");
    this->Gantry->SetVelocity(60.0);
    this->Gantry->SetAcceleration(240.0);
    this->Gantry->SetResponseTimeout(0.2);
    this->Gantry->SetWatchdogTimeout(0.3);
  }

  /// Serves, connects and enables (homes too when asked).
  bool Start(bool home)
  {
    if (!this->Simulator->Start())
    {
      return Check(false, "simulator serving", this->Errors->GetErrorMessage());
    }
    this->Gantry->SetPort(this->Simulator->GetBoundPort());
    const bool ready =
      this->Gantry->Connect() && this->Gantry->Enable() && (!home || this->Gantry->Home());
    return Check(ready,
      "gantry connected, enabled" + std::string(home ? ", homed" : ""),
      this->Errors->HasError() ? this->Errors->GetErrorMessage() : "yes");
  }

  /// "gantry 127.0.0.1:<port>: ", how every message of the client begins.
  std::string Device() const { return this->Gantry->GetDeviceName() + ": "; }

  /// Reads the state until the axis stands still (at most `seconds`).
  bool WaitStill(double seconds = 2.0)
  {
    const double end = Now() + seconds;
    while (Now() < end)
    {
      if (this->Gantry->UpdateState() && !this->Gantry->IsMoving())
      {
        return true;
      }
      Sleep(0.02);
    }
    return false;
  }
};
}
}

#endif

/**
 * @file   lfdRequestGuard.h
 * @brief  A pipeline request that turns a C++ exception into the algorithm's error.
 *
 * VTK's executives and the Python wrappers do not expect C++ exceptions: one
 * that leaves ProcessRequest terminates the process (and the interpreter).
 * Algorithms of lfd whose superclass is one of VTK's override ProcessRequest
 * with GuardRequest(), so an exception (bad_alloc, a JSON or filesystem
 * error) ends like any other failure: an ErrorEvent carrying the message
 * (vtkErrorMacro's channel) and a non-zero error code. Most only guard their
 * superclass's request: they declare the override in their header and define
 * it with lfdGuardedProcessRequestMacro(vtkX) in their .cxx (as
 * vtkStandardNewMacro defines New()).
 */
#ifndef lfdRequestGuard_h
#define lfdRequestGuard_h

#include "lfdExceptions.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkSetGet.h"

namespace lfd
{
/**
 * Returns `request()`; when it throws, calls `setErrorCode(code)` with
 * vtkErrorCode::UnknownError (SetErrorCode is protected: the algorithm
 * passes a lambda that calls it), reports "<class>: <exception>" as the
 * algorithm's error and returns 0 (the request failed).
 */
template<typename Request, typename SetErrorCode>
int GuardRequest(vtkAlgorithm* algorithm, Request&& request, SetErrorCode&& setErrorCode)
{
  try
  {
    return request();
  }
  catch (...)
  {
    setErrorCode(vtkErrorCode::UnknownError);
    vtkErrorWithObjectMacro(
      algorithm, << algorithm->GetClassName() << ": " << CurrentExceptionMessage());
    return 0;
  }
}
}

/**
 * Defines thisClass::ProcessRequest as the superclass's request under
 * lfd::GuardRequest.
 */
#define lfdGuardedProcessRequestMacro(thisClass)                                                   \
  vtkTypeBool thisClass::ProcessRequest(vtkInformation* request,                                   \
    vtkInformationVector** inputVector,                                                            \
    vtkInformationVector* outputVector)                                                            \
  {                                                                                                \
    return lfd::GuardRequest(                                                                      \
      this,                                                                                        \
      [&] { return this->Superclass::ProcessRequest(request, inputVector, outputVector); },        \
      [this](unsigned long code) { this->SetErrorCode(code); });                                   \
  }

#endif

/**
 * @file   lfdExceptions.h
 * @brief  One line describing the exception being handled.
 *
 * VTK's pipeline and Python wrappers do not expect C++ exceptions: one that
 * escapes an algorithm terminates the process (and the Python interpreter).
 * Every algorithm superclass of lfd catches them in ProcessRequest and turns
 * them into its error code and message with this function.
 */
#ifndef lfdExceptions_h
#define lfdExceptions_h

#include <new>
#include <stdexcept>
#include <string>

namespace lfd
{
/**
 * The message of the exception currently handled; call it only inside a
 * `catch (...)` block.
 */
inline std::string CurrentExceptionMessage()
{
  try
  {
    throw;
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory";
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  catch (...)
  {
    return "unknown exception";
  }
}
}

#endif

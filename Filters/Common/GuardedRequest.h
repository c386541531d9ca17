#pragma once
// A filter's request with its exceptions turned into an error message that names the filter:
// std::bad_alloc (memory ran out) and the cores' std::invalid_argument never abort ParaView and
// the user's session with it. (vtkPFParticleAlgorithm does the same for the particle filters.)
#include "vtkAlgorithm.h"
#include "vtkSetGet.h"

#include <exception>
#include <new>
#include <string>

namespace parafluid::vtk
{
/// An exception as a user reads it: a failed allocation says so and what to do (its own text is
/// only "std::bad_alloc").
inline std::string exceptionText(const std::exception& e)
{
  if (dynamic_cast<const std::bad_alloc*>(&e))
  {
    return "not enough memory for this request (an allocation failed); lower its resolution, size or particle count";
  }
  return e.what();
}

template<class Request>
int guardedRequest(vtkAlgorithm* algorithm, const char* label, Request&& request)
{
  try
  {
    return request();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(algorithm, << label << ": not enough memory for this output; lower its resolution or size");
  }
  catch (const std::exception& e)
  {
    vtkErrorWithObjectMacro(algorithm, << label << ": " << e.what());
  }
  return 0;
}
} // namespace parafluid::vtk

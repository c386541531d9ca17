#include "parafluid/rain/RainParameters.h"

#include "parafluid/rain/RainParameterTable.h"

#include <cmath>
#include <sstream>

namespace parafluid::rain
{
std::string RainParameters::validate() const
{
  const std::string declared = checkDeclared(rainParameterTable(), *this);
  if (!declared.empty())
  {
    return declared;
  }
  std::ostringstream problem;
  for (double v : this->bounds)
  {
    if (!std::isfinite(v) || std::fabs(v) > 1e7)
    {
      problem << "PrecipitationBounds must be finite coordinates within 1e7 m";
      return problem.str();
    }
  }
  if (!(this->bounds[1] > this->bounds[0] && this->bounds[3] > this->bounds[2]))
  {
    problem << "PrecipitationBounds must have x1 > x0 and y1 > y0 (got " << this->bounds[0] << " " << this->bounds[1]
            << " " << this->bounds[2] << " " << this->bounds[3] << ")";
  }
  else if (this->cells[0] < 1 || this->cells[1] < 1 || this->cells[0] > 4096 || this->cells[1] > 4096)
  {
    problem << "Cells must be from 1 to 4096 per side (got " << this->cells[0] << " x " << this->cells[1] << ")";
  }
  else if (!std::isfinite(this->wind[0]) || !std::isfinite(this->wind[1]) ||
           std::hypot(this->wind[0], this->wind[1]) > 100.0)
  {
    problem << "WindVelocity must be finite and at most 100 m/s";
  }
  return problem.str();
}
} // namespace parafluid::rain

#include "parafluid/common/ParameterTable.h"

#include <sstream>

namespace parafluid
{
std::string formatNumber(double v)
{
  std::ostringstream text;
  text << v;
  return text.str();
}

std::string checkNumber(const char* name, const char* unit, double minimum, double maximum, double value,
                        bool zeroAllowed, const char* zeroMeans)
{
  if ((zeroAllowed && value == 0.0) || (std::isfinite(value) && value >= minimum && value <= maximum))
  {
    return {};
  }
  return std::string(name) + " = " + formatNumber(value) + " is not allowed: it must be a finite number from " +
         formatNumber(minimum) + " to " + formatNumber(maximum) + (*unit ? std::string(" ") + unit : std::string()) +
         (zeroAllowed ? std::string(", or 0 (") + (zeroMeans ? zeroMeans : "automatic") + ")" : std::string());
}
} // namespace parafluid

#pragma once
// Checks a filter's numeric properties before it runs. The first value that is NaN, infinite or
// outside what the property allows becomes one sentence that names the property (as the GUI and
// pvpython call it), gives the value and says what is allowed, so a user never gets silent
// nonsense from an absurd parameter. The ranges mirror the XML domains (the GUI's limits and
// tooltips); Testing/Common/test_parameter_table.py holds the two together.
#include "parafluid/common/ParameterTable.h"

#include <cmath>
#include <sstream>
#include <string>

namespace parafluid::vtk
{
class ParameterCheck
{
public:
  /// `value` finite and within [lo, hi].
  ParameterCheck& inRange(const char* name, double value, double lo, double hi, const char* unit = "")
  {
    if (this->Problem.empty())
    {
      this->Problem = parafluid::checkNumber(name, unit, lo, hi, value);
    }
    return *this;
  }

  /// Each of n values finite and within [lo, hi].
  ParameterCheck& allInRange(const char* name, const double* values, int n, double lo, double hi, const char* unit = "")
  {
    for (int k = 0; k < n; ++k)
    {
      this->inRange(name, values[k], lo, hi, unit);
    }
    return *this;
  }

  /// A box xmin xmax ymin ymax zmin zmax of finite values with min <= max (min < max if `solid`).
  ParameterCheck& box(const char* name, const double* bounds, bool solid)
  {
    for (int a = 0; a < 3 && this->Problem.empty(); ++a)
    {
      const double lo = bounds[2 * a], hi = bounds[2 * a + 1];
      if (!std::isfinite(lo) || !std::isfinite(hi) || std::fabs(lo) > 1e12 || std::fabs(hi) > 1e12 ||
          (solid ? !(lo < hi) : !(lo <= hi)))
      {
        this->Problem = std::string(name) + " (" + number(lo) + ", " + number(hi) + " along " + "xyz"[a] +
                        ") is not allowed: each minimum must be finite and " + (solid ? "below" : "at most") +
                        " its maximum (metres, |value| <= 1e12)";
      }
    }
    return *this;
  }

  /// A check of the caller's own: `fine` false sets `problem` (which should name the property).
  ParameterCheck& require(bool fine, const std::string& problem)
  {
    if (this->Problem.empty() && !fine)
    {
      this->Problem = problem;
    }
    return *this;
  }

  bool ok() const { return this->Problem.empty(); }
  const std::string& problem() const { return this->Problem; }

  static std::string number(double v) { return parafluid::formatNumber(v); }
  static std::string describe(const char* name, double value) { return std::string(name) + " = " + number(value); }

private:
  std::string Problem;
};
} // namespace parafluid::vtk

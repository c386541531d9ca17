#include "parafluid/rain/RainParameters.h"

#include <cmath>
#include <sstream>

namespace parafluid::rain
{
std::string RainParameters::validate() const
{
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
  else if (!std::isfinite(this->height) || std::fabs(this->height) > 1e7)
  {
    problem << "PrecipitationHeight must be a finite height in metres";
  }
  else if (this->cells[0] < 1 || this->cells[1] < 1 || this->cells[0] > 4096 || this->cells[1] > 4096)
  {
    problem << "Cells must be from 1 to 4096 per side (got " << this->cells[0] << " x " << this->cells[1] << ")";
  }
  else if (!(this->rainfallRate > 0.0) || !(this->rainfallRate <= 1e4))
  {
    problem << "RainfallRate must be between 0 and 10000 mm/h (got " << this->rainfallRate << ")";
  }
  else if (!(this->dropsPerRealDrop > 0.0) || !(this->dropsPerRealDrop <= 1.0))
  {
    problem << "DropsPerRealDrop must be in (0, 1] (got " << this->dropsPerRealDrop << ")";
  }
  else if (!std::isfinite(this->wind[0]) || !std::isfinite(this->wind[1]) ||
           std::hypot(this->wind[0], this->wind[1]) > 100.0)
  {
    problem << "WindVelocity must be finite and at most 100 m/s";
  }
  else if (!(this->velocityJitter >= 0.0) || !(this->velocityJitter <= 10.0))
  {
    problem << "VelocityJitter must be from 0 to 10 m/s (got " << this->velocityJitter << ")";
  }
  else if (!(this->initialSpeed >= 0.0) || !(this->initialSpeed <= 100.0))
  {
    problem << "InitialSpeed must be from 0 to 100 m/s (got " << this->initialSpeed << ")";
  }
  else if (!(this->gravity > 0.0) || !(this->gravity <= 1000.0))
  {
    problem << "Gravity must be in (0, 1000] m/s^2 (got " << this->gravity << ")";
  }
  else if (!(this->duration >= 0.0) || !(this->duration <= 1e9))
  {
    problem << "RainDuration must be from 0 to 1e9 s (0: forever; got " << this->duration << ")";
  }
  return problem.str();
}
} // namespace parafluid::rain

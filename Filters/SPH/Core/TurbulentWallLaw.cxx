#include "parafluid/sph/TurbulentWallLaw.h"

#include <cmath>

namespace parafluid::sph
{
float TurbulentWallLaw::sublayerEdge()
{
  // Fixed point of y+ = ln(y+)/kappa + B, converging from above (about 11.0 for these constants).
  static const float edge = []
  {
    double y = 20.0;
    for (int k = 0; k < 60; ++k)
    {
      y = std::log(y) / kappa + logIntercept;
    }
    return static_cast<float>(y);
  }();
  return edge;
}
} // namespace parafluid::sph

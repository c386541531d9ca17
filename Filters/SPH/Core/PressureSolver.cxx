#include "parafluid/sph/PressureSolver.h"

#include "parafluid/sph/DFSPHSolver.h"
#include "parafluid/sph/DeltaSPHSolver.h"
#include "parafluid/sph/WCSPHSolver.h"

#include <stdexcept>

namespace parafluid::sph
{
std::unique_ptr<PressureSolver> makePressureSolver(PressureSolverType type)
{
  switch (type)
  {
    case PressureSolverType::WCSPH:
      return std::make_unique<WCSPHSolver>();
    case PressureSolverType::DFSPH:
      return std::make_unique<DFSPHSolver>();
    case PressureSolverType::DeltaSPH:
      return std::make_unique<DeltaSPHSolver>();
  }
  throw std::invalid_argument("SPH: unknown pressure solver");
}
} // namespace parafluid::sph

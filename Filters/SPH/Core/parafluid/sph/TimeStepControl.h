#pragma once
// The SPH time-step control, the same for every backend: the adaptive step's limits and the steps
// that land exactly on an output time.
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/SolverRegistry.h"

#include <cstdint>
#include <functional>
#include <string>

namespace parafluid::sph
{
/// The step the control would take now [s]: timeStep when adaptiveTimeStep is off, else the
/// smallest of the limits SPHParameters lists, for the solver's signal speed c [m/s], the fastest
/// particle [m/s], the largest acceleration [m/s^2] and the viscous operator's lattice correction.
double proposedTimeStep(const SPHParameters& p, const SolverEntry& solver, double signalSpeed, double fastest,
                        double largestAcceleration, float laplacianCorrection);
/// The step to take with `remaining` seconds left, given the proposed one: fixed steps are equal
/// steps that fit the remaining time exactly; adaptive ones split the last two evenly.
double timeStepFor(const SPHParameters& p, double proposed, double remaining);
/// Throws std::invalid_argument unless the time to advance is a non-negative number [s].
void checkAdvanceDuration(double duration);
/// Simulation::advance's loop: step(remaining) (returning the step taken [s]) until `duration`
/// more seconds have passed, `time` [s] landing exactly on the end; progress(fraction) every 8
/// steps stops it when false. Throws std::runtime_error, with advice(), when the step falls below
/// 1e-7 of the longest allowed (forces that have blown up). Returns the steps taken.
std::int64_t advanceInSteps(const SPHParameters& p, double& time, double duration,
                            const std::function<double(double)>& step, const std::function<bool(double)>& progress,
                            const std::function<std::string()>& advice);
} // namespace parafluid::sph

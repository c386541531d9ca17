#pragma once
// What every SPH backend checks and completes of the initial state it is given, before its start.
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"

namespace parafluid::sph
{
/// Checks the arrays' sizes and values (throws std::invalid_argument naming the particle) and gives
/// particles without velocities, ids or original indices zero velocity and their index.
void completeInitialState(ParticleState& state);
/// Throws std::invalid_argument when two particles share a position: SPH forces vanish at zero
/// distance, so they would never separate.
void checkCoincident(const ParticleState& state);
/// The fastest a particle may move in this scene before the run counts as blown up [m/s]: ten
/// times the free-fall speed over the domain's largest extent plus the fastest initial speed.
double sceneSpeedLimit(const SPHParameters& parameters, const ParticleState& state);
/// Appends particles at positions [m] with velocities [m/s], at rest density [kg/m^3], their ids
/// and original indices continuing after the largest so far; returns how many. Throws
/// std::invalid_argument (s unchanged) for mismatched sizes or non-finite values.
std::size_t appendParticles(ParticleState& s, const std::vector<float>& x, const std::vector<float>& y,
                            const std::vector<float>& z, const std::vector<float>& vx, const std::vector<float>& vy,
                            const std::vector<float>& vz, float restDensity);
} // namespace parafluid::sph

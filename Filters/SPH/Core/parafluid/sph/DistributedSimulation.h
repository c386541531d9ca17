#pragma once
// One process's part of an SPH run spread over processes (ParaView's MPI ranks, or threads): the
// domain is cut into slabs along one axis, each process owns the particles in its slab and runs
// them with the CPU simulation beside ghosts, read-only copies of the other processes' particles
// within reach (a kernel support and a margin of a quarter support each side), refreshed between
// the passes that read them and after each step. When a particle may have moved by the margin, the
// particles that left a slab go to their new owner and the ghosts are gathered afresh; the cuts
// move then when one process holds over 20 % more than the mean.
// Every call is collective: each process makes it, with its own particles.
#include "parafluid/common/Communicator.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/Simulation.h"

#include <memory>
#include <string>

namespace parafluid
{
class TriangleBoundary;
}

namespace parafluid::sph
{
/// Why `parameters` cannot run distributed ("" when they can): a solver without ghost refreshes
/// (SolverEntry::runsDistributed), or every axis periodic.
std::string distributedRunLacks(const SPHParameters& parameters);

/// This process's simulation of a distributed run: `localPiece` holds the particles it was given
/// (any of the scene's, any number, none included); their ids are kept when every process gives
/// them, else numbered across the processes in rank order. Throws std::invalid_argument on every
/// process when any process's input or the parameters are refused.
std::unique_ptr<Simulation> makeDistributedSimulation(const SPHParameters& parameters, ParticleState localPiece,
                                                      std::shared_ptr<const TriangleBoundary> boundary,
                                                      Communicator& communicator);
} // namespace parafluid::sph

#pragma once
// What SPH Step does differently when its run is spread over ParaView's processes (each steps its
// own particles, DistributedSimulation.h): the parameters, the boundary and the verdicts made the
// same on every process, and each process's particles written in id order.
#include "parafluid/common/Communicator.h"
#include "parafluid/common/ParticleState.h"
#include "parafluid/sph/SPHParameters.h"
#include "vtkSmartPointer.h"

class vtkDataObject;

namespace parafluid::vtk
{
/// Every process gets the parameters of the lowest-ranked process that resolved them (`resolved`:
/// 1 resolved, 0 failed after its own error, -1 had nothing to resolve them from). False on every
/// process when one failed or none resolved.
bool agreeOnParameters(parafluid::sph::SPHParameters& parameters, int resolved, parafluid::Communicator& processes);

/// The whole Boundary on every process: the processes' surface pieces appended, or process 0's
/// height image (a height image is not split). Null where there is no Boundary.
vtkSmartPointer<vtkDataObject> boundaryOnEveryProcess(vtkDataObject* local);

/// This process's particles with originalIndex numbering them in id order, so that the output lists
/// them by id (their indices in the whole scene mean nothing to one process's output).
parafluid::ParticleState ownParticlesInIdOrder(const parafluid::ParticleState& own);
} // namespace parafluid::vtk

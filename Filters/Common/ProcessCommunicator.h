#pragma once
// The Core's Communicator (parafluid/common/Communicator.h) over ParaView's MPI processes: a
// private copy of the global controller's communicator, so that its messages never meet VTK's own,
// and raw byte buffers sent without blocking.
#include "parafluid/common/Communicator.h"

#include <memory>

namespace parafluid::vtk
{
/// The processes of this session as a Communicator, or null in a serial session (no MPI, or one
/// process). Collective: every process calls it at the same point.
std::unique_ptr<parafluid::Communicator> makeProcessCommunicator();
} // namespace parafluid::vtk

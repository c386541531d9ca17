#pragma once
// The H5Part writer under MPI: one file that every process writes together through parallel HDF5
// (MPI-IO), each process its own particles as its slice of every dataset, in process order, so no
// process gathers the others' particles. Every call is collective.
#include "H5PartColumns.h"
#include "parafluid/h5part/Handle.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPointSet;

namespace parafluid
{
class Communicator;
}

namespace parafluid::vtk
{
/// Whether this build's HDF5 writes in parallel (Debian's libhdf5-openmpi does).
bool parallelHdf5Available();

/// A file-access property list that opens one file on all ParaView processes with MPI-IO; invalid
/// when HDF5 has no parallel support.
parafluid::h5::Handle parallelFileAccess();

/// `text` as process 0 has it, on every process.
std::string fromFirstProcess(const std::string& text, parafluid::Communicator& processes);

/// Writes each process's `local` particles (null or empty: none) into `group` as its slice of the
/// datasets of one step (h5partColumns). The datasets are those of the lowest process with
/// particles, less the arrays some other process with particles lacks (`warnings` says which);
/// values of another type are converted to that process's. False (on this process) when HDF5
/// failed; `error` says where.
bool writeParallelStep(hid_t group, vtkPointSet* local, int compression, parafluid::Communicator& processes,
                       std::vector<std::string>& warnings, std::string& error);

/// The field data of the lowest process with particles (process 0 when none has any), on every
/// process: the root attributes all processes write alike.
vtkSmartPointer<vtkFieldData> agreedFieldData(vtkPointSet* local, parafluid::Communicator& processes);
} // namespace parafluid::vtk

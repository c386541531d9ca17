#pragma once
// The fluid representations draw every particle on one process when ParaView's processes share
// the rendering: the depth smoothing and the thickness need all particles on one screen, and a
// piece smoothed alone shows seams where pieces meet.
#include "vtkSmartPointer.h"

class vtkPolyData;

namespace parafluid
{
class Communicator;

/// Every process's particles (points, point arrays, field data) on process 0, in rank order; an
/// empty polydata on the others. Collective. Point arrays that some non-empty piece lacks are
/// dropped, as vtkAppendPolyData does.
vtkSmartPointer<vtkPolyData> gatherParticlesOnFirst(vtkPolyData* local, Communicator& processes);
} // namespace parafluid

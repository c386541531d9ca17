#pragma once
// The HDF5 C API as ParaView's VTK sees it (vtk_hdf5.h selects the 1.10 API of Debian's external,
// openmpi-flavoured HDF5): the H5Part core includes this instead, so it builds without VTK and
// uses the same library and API as the VTK reader it serves.
#ifndef H5_USE_110_API
#define H5_USE_110_API
#endif
#include <hdf5.h>

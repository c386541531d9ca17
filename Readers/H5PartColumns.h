#pragma once
// The datasets of one H5Part step, as the writer stores them: x, y, z in the points' precision,
// then each named point array in a type H5Part holds (other numbers as double, "id" as int64). The
// serial and the parallel writer take their datasets from here, so both write the same file.
#include "vtkDataArray.h"
#include "vtkSmartPointer.h"

#include <hdf5.h>

#include <string>
#include <vector>

class vtkPointSet;

namespace parafluid::vtk
{
struct H5PartColumn
{
  std::string name;     // the dataset's name
  int type = VTK_FLOAT; // as stored: VTK_FLOAT, VTK_DOUBLE, VTK_INT or VTK_LONG_LONG
  int components = 1;
  vtkSmartPointer<vtkDataArray> values; // n x components, of `type` (any 64-bit integer for LONG_LONG)
};

/// The step's datasets of `points`; `warnings` gets a sentence for each array that is renamed or
/// not written.
std::vector<H5PartColumn> h5partColumns(vtkPointSet* points, std::vector<std::string>& warnings);

/// `array` as values of the stored `type` (itself when it already is).
vtkSmartPointer<vtkDataArray> h5partValuesAs(vtkDataArray* array, int type);
/// The HDF5 memory type of a column's values, and the file type of a stored type.
hid_t h5partMemoryType(vtkDataArray* values);
hid_t h5partFileType(int vtkType);
/// The native HDF5 type of a stored type.
hid_t h5partNativeType(int vtkType);
} // namespace parafluid::vtk

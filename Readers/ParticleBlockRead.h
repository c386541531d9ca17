#pragma once
// One block of particles (parafluid::h5::ParticleBlock: N-row datasets over one or more files)
// read into a vtkPolyData: this piece's contiguous share of the rows (of the rows near the
// selection box, where the file has a spatial index), less the particles the box, the stride and
// the layout's real-particle tag leave out, the coordinates at the
// file's precision, an int64 "id" (the file's, else the row), the selected arrays (scaled to SI
// where the layout knows the factor, the unit in the array's information), the block's constants
// as arrays. The memory a block declares is checked before anything is allocated.
#include "parafluid/h5part/ParticleLayouts.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataArraySelection;
class vtkInformation;
class vtkPolyData;

namespace parafluid::vtk
{
struct BlockReading
{
  vtkDataArraySelection* selection = nullptr; // every array when null
  int piece = 0, pieces = 1;
  /// Keep about one particle in `stride`, chosen by a hash of its id (the same ones at every time).
  int stride = 1;
  /// Keep only the particles inside `box` (xmin, xmax, ymin, ymax, zmin, zmax; the output's
  /// units), reading only the rows the file's spatial index puts near it.
  bool useBox = false;
  double box[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  vtkAlgorithm* algorithm = nullptr; // for Abort, when set
};

/// The piece `outInfo` asks for (0 of 1 without a request), with the array selection and the
/// algorithm whose Abort stops the read.
BlockReading blockReadingFor(vtkInformation* outInfo, vtkDataArraySelection* selection, vtkAlgorithm* algorithm);

/// False with `error` (naming the file and group) when the block cannot be read; warnings (NaN
/// coordinates, ids that are not whole numbers) are appended.
bool readParticleBlock(const parafluid::h5::ParticleBlock& block, const BlockReading& how, vtkPolyData* output,
                       std::vector<std::string>& warnings, std::string& error);

/// The names of the arrays a block offers (the first part's, and its constants).
std::vector<std::string> blockArrayNames(const parafluid::h5::ParticleBlock& block);
} // namespace parafluid::vtk

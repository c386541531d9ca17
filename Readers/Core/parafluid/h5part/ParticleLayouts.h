#pragma once
// The HDF5 particle layouts particle codes write, told apart by what a file holds, not by its
// name: H5Part ("Step#<n>" groups), H5MD 1.x (an /h5md group, /particles/<group>/<element>),
// Gadget-style snapshots (/Header and /PartType<n>; SWIFT's per-dataset unit attributes applied;
// a snapshot split over NumFilesPerSnapshot files read as one) and openPMD 1.x particles
// (/data/<iteration>/particles/<species>/<record>/<component>, in one file or one file per
// iteration, unitSI applied), VTKHDF PolyData (newer VTK's point clouds, its steps too) and
// PySPH's output (/particles/<array>/arrays/<property>, /solver_data). Files of one time numbered
// in a series (name_00020.hdf5, snap_003.hdf5) are the times of one source. Each is described as
// frames of blocks of N-row datasets (StepLayout), the one path the readers turn into particles.
#include "parafluid/h5part/Layout.h"

#include <cstdint>
#include <string>
#include <vector>

namespace parafluid::h5
{
enum class ParticleLayout
{
  Unknown,
  H5Part,
  H5MD,
  Gadget,
  OpenPMD,
  VTKHDF,
  PySPH
};

/// One file's rows of a block: the group its datasets are in, and what they are.
struct BlockPart
{
  std::string file;
  std::string group;
  StepLayout layout;
  /// The particle type whose cells the file's spatial index lists (SWIFT's /Cells, "PartType0")
  /// and the file's index in its snapshot; empty when the file has none.
  std::string cellIndexType;
  int fileIndex = 0;
};

/// Rows [first, first + count) of a part's datasets.
struct RowRange
{
  std::uint64_t first = 0, count = 0;
};

/// A value every particle of a block shares (Gadget's MassTable, an H5MD scalar element).
struct ConstantArray
{
  std::string name;
  double value = 0.0;
  std::string unit;
};

/// The particles of one group, species or type at one time: its rows over one or more files.
struct ParticleBlock
{
  std::string name;
  std::vector<BlockPart> parts;
  std::vector<ConstantArray> constants;
  std::uint64_t particles() const;
};

/// A named value of the file or frame (box, time, redshift), for the output's field data.
struct FieldValue
{
  std::string name;
  std::vector<double> values;
};

struct ParticleFrame
{
  double time = 0.0;
  std::vector<ParticleBlock> blocks;
  std::vector<FieldValue> fields;
  std::vector<std::string> warnings;
  std::string error; // empty when the frame is readable
};

struct ParticleFileInfo
{
  ParticleLayout layout = ParticleLayout::Unknown;
  std::string description;        // "H5MD 1.1 (LAMMPS)", "SWIFT snapshot, 2 files"
  std::vector<std::string> files; // the files read together (a multi-file snapshot's parts)
  std::vector<double> times;      // the times offered, increasing
  /// Per time, where its frame is when the layout keeps frames apart (openPMD: the file and the
  /// iteration's group, "/data/100/").
  std::vector<std::string> frameFiles, frameGroups;
  /// Per time, the file of a numbered series whose one time it is; empty when not a series.
  std::vector<std::string> seriesFiles;
  std::string error; // empty when the file could be placed
  std::vector<std::string> warnings;
};

/// The layout `file` holds (Unknown when none of them).
ParticleLayout detectLayout(hid_t file);
const char* layoutName(ParticleLayout layout);

/// Places a file: its layout, its companion files and its times; `error` lists what was looked
/// for when the file is none of the layouts, or names what is missing or inconsistent. With
/// `findSeries`, a file of one time whose name ends in a number (before the extension, and before
/// a multi-file snapshot's file index) is read with the files beside it that differ only in that
/// number, in the order of the numbers, each file one time (its own time attribute).
ParticleFileInfo describeParticleFile(const std::string& fileName, bool findSeries = true);

/// The rows of `part` that can hold particles inside `box` (xmin, xmax, ymin, ymax, zmin, zmax,
/// in the output's units), sorted and merged: those of the cells of the file's spatial index
/// whose particles' bounds (or, without them, the cell widened by the one cell-length its
/// particles may drift out by) overlap the box; every row when the part has no index, with a
/// warning in `warning` when the index is unusable.
std::vector<RowRange> rowsNearBox(const BlockPart& part, const double box[6], std::string& warning);

/// The blocks of frame `timeIndex` (of info.times), checked against what the datasets hold.
ParticleFrame describeFrame(const ParticleFileInfo& info, std::size_t timeIndex);
} // namespace parafluid::h5

/**
 * @class vtkPFH5PartReader
 * @brief Reads particles from H5Part files (HDF5 groups "Step#0", "Step#1", ...).
 *
 * Coordinates come from datasets x, y, z or one N x 3 "position" dataset; every other numeric
 * dataset of N (or N x k) values becomes a point array, with component triples (vx, vy, vz;
 * velocity_x, ...) combined into vectors. Steps are time steps (time from a time/Time/TimeValue
 * group attribute, else the step index). Only the selected arrays are read. Under MPI each piece
 * reads its own contiguous slice of particles. Numeric root attributes (particle_spacing,
 * smoothing_length, rest_density, ...) go to field data. Output: one vertex per particle and an
 * int64 "id" array (the id dataset, else the particle's index in the file).
 *
 * What a file declares is checked before anything is allocated (README, "What the reader
 * refuses"): datasets never written or beyond the end of the file, missing sources of virtual
 * datasets, steps larger than the memory budget are errors; datasets no point array can hold,
 * attributes it cannot read, non-integer ids and step times that are not finite and increasing
 * are warnings that say what was done instead.
 */
#pragma once

#include "ParaFluidReadersModule.h"
#include "vtkNew.h"
#include "vtkPolyDataAlgorithm.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDataArraySelection;

class PARAFLUIDREADERS_EXPORT vtkPFH5PartReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPFH5PartReader* New();
  vtkTypeMacro(vtkPFH5PartReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// True when the file is HDF5 and has at least one "Step#" group.
  static int CanReadFile(const char* fileName);

  vtkDataArraySelection* GetPointDataArraySelection() { return this->PointArraySelection; }
  int GetNumberOfPointArrays();
  const char* GetPointArrayName(int index);
  int GetPointArrayStatus(const char* name);
  void SetPointArrayStatus(const char* name, int status);

  vtkMTimeType GetMTime() override;

  /// Read about one particle in `stride` (by a hash of its id) and, with `useBox`, only those
  /// inside `box` (xmin, xmax, ymin, ymax, zmin, zmax): ParaFluid HDF5 Particles' Stride and
  /// SelectionBox for the H5Part files it reads through this class.
  void SetSubset(int stride, bool useBox, const double box[6]);

protected:
  vtkPFH5PartReader();
  ~vtkPFH5PartReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFH5PartReader(const vtkPFH5PartReader&) = delete;
  void operator=(const vtkPFH5PartReader&) = delete;

  std::string FileName;
  vtkNew<vtkDataArraySelection> PointArraySelection;
  std::vector<std::string> StepGroups;
  std::vector<double> StepTimes;
  int Stride = 1;
  bool UseBox = false;
  double Box[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  std::string InformationError; // why RequestInformation failed, repeated by RequestData
  std::set<std::string> Warned; // warnings given since the file was (re)opened: each is given once

  /// The step nearest the requested time into `output`; false with `error` when it cannot be read.
  bool ReadStep(vtkInformation* info, vtkPolyData* output, std::string& error);
  void WarnOnce(const std::string& warning);
};

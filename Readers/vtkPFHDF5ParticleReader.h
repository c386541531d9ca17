/**
 * @class vtkPFHDF5ParticleReader
 * @brief Reads the HDF5 particle layouts particle codes write: H5MD (one block per particle
 * group, every frame a time step, the box as domain bounds and periodicity), Gadget-style
 * snapshots of Gadget, SWIFT, GIZMO and AREPO (one block per particle type, gas first; SWIFT's
 * unit attributes applied, so values are SI; a multi-file snapshot read as one) and H5Part (one
 * block). The layout is found from the file's content, not its name (DetectedLayout says which);
 * a file of none of them is an error that lists what was looked for.
 *
 * Each block is a vtkPolyData of one vertex per particle with an int64 "id" (the file's ids,
 * else the row), the selected arrays (velocity, mass, density, smoothing_length, ... in the
 * particle contract's names where the layout has them; units in each array's UNITS_LABEL) and
 * field data (time, domain_bounds, domain_periodic, redshift). Under MPI each process reads its
 * own contiguous rows of every block.
 */
#pragma once

#include "ParaFluidReadersModule.h"
#include "vtkMultiBlockDataSetAlgorithm.h"
#include "vtkNew.h"

#include <memory>
#include <set>
#include <string>

class vtkDataArraySelection;

class PARAFLUIDREADERS_EXPORT vtkPFHDF5ParticleReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkPFHDF5ParticleReader* New();
  vtkTypeMacro(vtkPFHDF5ParticleReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// True when the file is HDF5 in one of the layouts.
  static int CanReadFile(const char* fileName);

  /// The layout found in the file ("H5MD 1.1 (LAMMPS)", "SWIFT snapshot, 4 files", "H5Part"),
  /// after the pipeline's information pass.
  const char* GetDetectedLayout() const { return this->DetectedLayout.c_str(); }

  vtkDataArraySelection* GetPointDataArraySelection() { return this->PointArraySelection; }
  int GetNumberOfPointArrays();
  const char* GetPointArrayName(int index);
  int GetPointArrayStatus(const char* name);
  void SetPointArrayStatus(const char* name, int status);

  vtkMTimeType GetMTime() override;

protected:
  vtkPFHDF5ParticleReader();
  ~vtkPFHDF5ParticleReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFHDF5ParticleReader(const vtkPFHDF5ParticleReader&) = delete;
  void operator=(const vtkPFHDF5ParticleReader&) = delete;
  void WarnOnce(const std::string& warning);

  struct Placed;
  std::string FileName;
  std::string DetectedLayout;
  vtkNew<vtkDataArraySelection> PointArraySelection;
  std::unique_ptr<Placed> File; // what RequestInformation found
  std::set<std::string> Warned;
};

/**
 * @class vtkPFHDF5ParticleReader
 * @brief Reads the HDF5 particle layouts particle codes write: H5MD (one block per particle
 * group, every frame a time step, the box as domain bounds and periodicity), Gadget-style
 * snapshots of Gadget, SWIFT, GIZMO and AREPO (one block per particle type, gas first; SWIFT's
 * unit attributes applied, so values are SI; a multi-file snapshot read as one) and H5Part (one
 * block). The layout is found from the file's content, not its name (DetectedLayout says which);
 * a file of none of them is an error that lists what was looked for.
 *
 * An H5Part file is read into one vtkPolyData (its particles, every step a time step, the root's
 * numeric attributes as field data), as it always was; every other layout into a multiblock.
 * Each block is a vtkPolyData of one vertex per particle with an int64 "id" (the file's ids,
 * else the row), the selected arrays (velocity, mass, density, smoothing_length, ... in the
 * particle contract's names where the layout has them; units in each array's UNITS_LABEL) and
 * field data (time, domain_bounds, domain_periodic, redshift). Under MPI each process reads its
 * own contiguous rows of every block. Stride and SelectionBox read a subset; numbered files of
 * one time each (PySPH's name_00020.hdf5, snap_003.hdf5) are read as one time series.
 */
#pragma once

#include "ParaFluidReadersModule.h"
#include "vtkDataObjectAlgorithm.h"
#include "vtkNew.h"

#include <memory>
#include <set>
#include <string>

class vtkDataArraySelection;
class vtkPFH5PartReader;

class PARAFLUIDREADERS_EXPORT vtkPFHDF5ParticleReader : public vtkDataObjectAlgorithm
{
public:
  static vtkPFHDF5ParticleReader* New();
  vtkTypeMacro(vtkPFHDF5ParticleReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// True when the file is HDF5 in one of the layouts.
  static int CanReadFile(const char* fileName);

  /// The layout found in the file ("H5MD 1.1 (LAMMPS)", "SWIFT snapshot, 4 files", "H5Part"),
  /// after the pipeline's information pass.
  const char* GetDetectedLayout() const { return this->DetectedLayout.c_str(); }

  /// Read about one particle in Stride (chosen by a hash of its id, so the same particles at every
  /// time); 1 reads every particle.
  vtkSetClampMacro(Stride, int, 1, 1000000000);
  vtkGetMacro(Stride, int);

  /// Read only the particles inside SelectionBox (xmin, xmax, ymin, ymax, zmin, zmax, in the
  /// output's units); where the file has a spatial index (SWIFT's /Cells) only the rows of the
  /// cells near the box are read from disk.
  vtkSetMacro(UseSelectionBox, bool);
  vtkGetMacro(UseSelectionBox, bool);
  vtkBooleanMacro(UseSelectionBox, bool);
  vtkSetVector6Macro(SelectionBox, double);
  vtkGetVector6Macro(SelectionBox, double);

  /// Read the numbered files beside FileName (name_00020.hdf5, snap_003.hdf5) as the time steps
  /// of one series, when FileName holds one time.
  vtkSetMacro(FileSeries, bool);
  vtkGetMacro(FileSeries, bool);
  vtkBooleanMacro(FileSeries, bool);

  vtkDataArraySelection* GetPointDataArraySelection() { return this->PointArraySelection; }
  int GetNumberOfPointArrays();
  const char* GetPointArrayName(int index);
  int GetPointArrayStatus(const char* name);
  void SetPointArrayStatus(const char* name, int status);

  vtkMTimeType GetMTime() override;

protected:
  vtkPFHDF5ParticleReader();
  ~vtkPFHDF5ParticleReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPFHDF5ParticleReader(const vtkPFHDF5ParticleReader&) = delete;
  void operator=(const vtkPFHDF5ParticleReader&) = delete;
  void WarnOnce(const std::string& warning);
  /// Passes the H5Part reader's errors and warnings on as this reader's.
  void PassOn(vtkObject* caller, unsigned long event, void* message);
  void SyncH5PartSelection();

  struct Placed;
  std::string FileName;
  std::string DetectedLayout;
  int Stride = 1;
  bool UseSelectionBox = false;
  double SelectionBox[6] = { 0.0, 1.0, 0.0, 1.0, 0.0, 1.0 };
  bool FileSeries = true;
  vtkNew<vtkDataArraySelection> PointArraySelection;
  std::unique_ptr<Placed> File; // what RequestInformation found
  std::set<std::string> Warned;
  vtkNew<vtkPFH5PartReader> H5Part; // reads H5Part files, whose output stays a vtkPolyData
  bool ReadsH5Part = false;
  bool H5PartFailed = false;
};

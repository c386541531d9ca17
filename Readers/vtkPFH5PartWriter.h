/**
 * @class vtkPFH5PartWriter
 * @brief Writes particles (any vtkPointSet) to an H5Part file that vtkPFH5PartReader reads back.
 *
 * Per step a group "Step#k" with a "time" attribute, coordinates as datasets x, y, z and each point
 * array as a dataset (N values, or N x k for k components; "id" as int64). Field-data numbers
 * (particle_spacing, smoothing_length, ...) become root attributes. Datasets are chunked and
 * deflate-compressed. Everything is written to a temporary file beside the target, which is renamed
 * over the target only once complete, so a failed write never destroys an existing file.
 * With WriteAllTimeSteps, every time step of the input goes into one file. Under MPI the processes
 * write the one file together with parallel HDF5, each its own particles as its slice of every
 * dataset (H5MD files: gathered on process 0, which writes them).
 */
#pragma once

#include "ParaFluidReadersModule.h"
#include "vtkWriter.h"

class vtkFieldData;

#include <memory>
#include <string>
#include <vector>

class PARAFLUIDREADERS_EXPORT vtkPFH5PartWriter : public vtkWriter
{
public:
  static vtkPFH5PartWriter* New();
  vtkTypeMacro(vtkPFH5PartWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// Write every time step of the input (default: only the current one).
  vtkSetMacro(WriteAllTimeSteps, bool);
  vtkGetMacro(WriteAllTimeSteps, bool);
  vtkBooleanMacro(WriteAllTimeSteps, bool);

  /// Deflate level 0 (none) .. 9; default 1, which already halves typical particle data cheaply.
  /// Other values are refused when the write starts.
  vtkSetMacro(CompressionLevel, int);
  vtkGetMacro(CompressionLevel, int);

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  vtkPFH5PartWriter();
  ~vtkPFH5PartWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override {} // writing happens in ProcessRequest, step by step

private:
  vtkPFH5PartWriter(const vtkPFH5PartWriter&) = delete;
  void operator=(const vtkPFH5PartWriter&) = delete;

  /// Writes the input's current step, or with WriteAllTimeSteps every time step (bringing the input
  /// to each); false after an error, with nothing written.
  bool WriteSteps(vtkDataObject* first);
  /// The input brought to `time` (this process's piece); null when it fails.
  vtkDataObject* UpdateInputTo(double time);
  /// `parallel`: every process opens the one file with MPI-IO and writes its own particles.
  bool BeginFile(bool parallel);
  bool WriteStep(vtkDataObject* input, int stepIndex, double time);
  /// The field data's numbers and text as root attributes.
  void WriteFieldData(vtkFieldData* fieldData);
  void Warn(const std::vector<std::string>& warnings);
  bool IsH5md() const;
  bool FinishFile();
  void AbandonFile();

  std::string FileName;
  bool WriteAllTimeSteps = false;
  int CompressionLevel = 1;

  struct OpenFile;
  std::unique_ptr<OpenFile> File;
  std::vector<double> InputTimes;
};

#include "vtkPFH5PartWriter.h"

#include "H5PartColumns.h"
#include "H5mdFrameWriter.h"
#include "ParallelH5PartStep.h"
#include "ParticleArrays.h"
#include "ProcessCommunicator.h"
#include "TemporaryFiles.h"
#include "parafluid/common/Communicator.h"
#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Handle.h"

#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cstdio>
#include <new>

using parafluid::h5::Handle;

struct vtkPFH5PartWriter::OpenFile
{
  explicit OpenFile(const std::string& temporaryName)
    : TemporaryName(temporaryName)
    , Guard(temporaryName)
  {
  }
  std::string TemporaryName;
  parafluid::h5::TemporaryFileGuard Guard; // removes the temporary if a signal ends the process
  Handle File;
  std::unique_ptr<parafluid::vtk::H5mdFrameWriter> H5md; // set when the file name ends in .h5md
  // Under MPI with parallel HDF5: the processes that write this one file together.
  std::unique_ptr<parafluid::Communicator> Processes;
};

namespace
{
/// Writes n x components values of the given memory type as dataset `name` of `group`.
bool writeDataset(hid_t group, const std::string& name, hid_t memoryType, hid_t fileType, const void* data, hsize_t n,
                  hsize_t components, int compression)
{
  const hsize_t dims[2] = { n, components };
  const int rank = components == 1 ? 1 : 2;
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (n > 0)
  {
    // 64k rows a chunk: big enough for fast sequential reads, small enough that a reader of one
    // MPI slice decompresses little it does not need.
    const hsize_t chunk[2] = { std::min<hsize_t>(n, 65536), components };
    H5Pset_chunk(properties, rank, chunk);
    if (compression > 0)
    {
      H5Pset_shuffle(properties);
      H5Pset_deflate(properties, static_cast<unsigned>(compression));
    }
  }
  Handle dataset(H5Dcreate2(group, name.c_str(), fileType, space, H5P_DEFAULT, properties, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
  {
    return false;
  }
  return n == 0 || H5Dwrite(dataset, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
}

bool writeStringAttribute(hid_t object, const char* name, vtkStringArray* strings)
{
  std::size_t width = 1;
  for (vtkIdType k = 0; k < strings->GetNumberOfValues(); ++k)
  {
    width = std::max(width, strings->GetValue(k).size() + 1);
  }
  const auto count = static_cast<hsize_t>(strings->GetNumberOfValues());
  std::vector<char> text(static_cast<std::size_t>(count) * width, '\0');
  for (vtkIdType k = 0; k < strings->GetNumberOfValues(); ++k)
  {
    const std::string& value = strings->GetValue(k);
    std::copy(value.begin(), value.end(), text.begin() + static_cast<std::ptrdiff_t>(k * width));
  }
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, width);
  Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute, type, text.data()) >= 0;
}

bool writeDoubleAttribute(hid_t object, const char* name, const double* values, hsize_t count)
{
  Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute, H5T_NATIVE_DOUBLE, values) >= 0;
}

} // namespace

vtkStandardNewMacro(vtkPFH5PartWriter);

vtkPFH5PartWriter::vtkPFH5PartWriter() = default;

vtkPFH5PartWriter::~vtkPFH5PartWriter()
{
  this->AbandonFile();
}

int vtkPFH5PartWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

vtkTypeBool vtkPFH5PartWriter::ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                                              vtkInformationVector* outputVector)
{
  vtkInformation* inputInfo = inputVector[0]->GetInformationObject(0);
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    this->InputTimes.clear();
    if (inputInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    {
      const double* times = inputInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      this->InputTimes.assign(times, times + inputInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
    }
    return 1;
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    // A writer is a sink: it asks for this process's piece itself (the whole data when serial).
    inputInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), parafluid::vtk::processIndex());
    inputInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), parafluid::vtk::processCount());
    if (this->WriteAllTimeSteps && !this->InputTimes.empty())
    {
      inputInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), this->InputTimes.front());
    }
    return 1;
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->WriteSteps(inputInfo->Get(vtkDataObject::DATA_OBJECT())) ? 1 : 0;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

vtkDataObject* vtkPFH5PartWriter::UpdateInputTo(double time)
{
  // The input is brought to each further time here, inside this one request, rather than by the
  // executive's CONTINUE_EXECUTING loop: that loop never ends when the input fails at one of the
  // times (the writer's REQUEST_DATA is then not called, so nothing clears the flag).
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  vtkAlgorithm* producer = connection ? connection->GetProducer() : nullptr;
  if (!producer)
  {
    return nullptr;
  }
  const int port = connection->GetIndex();
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(producer->GetNumberOfOutputPorts());
  vtkInformation* wanted = requests->GetInformationObject(port);
  wanted->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), time);
  wanted->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), parafluid::vtk::processIndex());
  wanted->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), parafluid::vtk::processCount());
  wanted->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return producer->Update(port, requests) ? producer->GetOutputDataObject(port) : nullptr;
}

bool vtkPFH5PartWriter::WriteSteps(vtkDataObject* first)
{
  const bool allSteps = this->WriteAllTimeSteps && !this->InputTimes.empty();
  const std::size_t steps = allSteps ? this->InputTimes.size() : 1;
  bool ok = true;
  bool writesHere = true;
  // Under MPI every process holds a piece. With parallel HDF5 all processes write the one H5Part
  // file together, each its particles; otherwise (and for H5MD) process 0 gathers the pieces and
  // writes alone, so processes never write (and rename) over each other. Every verdict (the
  // input's, the write's) is agreed by all processes before the next collective call, so a failure
  // on one of them (a missing folder, a full disk, an input that fails) stops all at the same step.
  const bool parallel =
    parafluid::vtk::processCount() > 1 && parafluid::vtk::parallelHdf5Available() && !this->IsH5md();
  for (std::size_t k = 0; k < steps && ok; ++k)
  {
    vtkDataObject* local = k == 0 ? first : this->UpdateInputTo(this->InputTimes[k]);
    if (!parafluid::vtk::agreeOnAllProcesses(local != nullptr && (!parallel || vtkPointSet::SafeDownCast(local))))
    {
      vtkErrorMacro("ParaFluid H5Part Writer: the input failed at time " << this->InputTimes[k]
                                                                         << "; nothing was written");
      ok = false;
      break;
    }
    vtkSmartPointer<vtkDataObject> input = local;
    if (!parallel)
    {
      input = parafluid::vtk::gatherToFirstProcess(local, writesHere);
    }
    if (writesHere)
    {
      double time = 0.0;
      if (allSteps)
      {
        time = this->InputTimes[k];
      }
      else if (local->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
      {
        time = local->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
      }
      try
      {
        ok = (k > 0 || this->BeginFile(parallel)) && this->WriteStep(input, static_cast<int>(k), time);
      }
      catch (const std::bad_alloc&)
      {
        vtkErrorMacro("ParaFluid H5Part Writer: not enough memory to write step " << k);
        ok = false;
      }
    }
    ok = parafluid::vtk::agreeOnAllProcesses(ok);
    this->UpdateProgress(static_cast<double>(k + 1) / static_cast<double>(steps));
  }
  if (!ok)
  {
    this->AbandonFile();
    return false;
  }
  return parafluid::vtk::agreeOnAllProcesses(!writesHere || this->FinishFile());
}

bool vtkPFH5PartWriter::IsH5md() const
{
  const std::size_t dot = this->FileName.rfind('.');
  return dot != std::string::npos && this->FileName.substr(dot) == ".h5md";
}

bool vtkPFH5PartWriter::BeginFile(bool parallel)
{
  this->AbandonFile();
  if (this->FileName.empty())
  {
    vtkErrorMacro("ParaFluid H5Part Writer: no file name was given");
    return false;
  }
  if (this->CompressionLevel < 0 || this->CompressionLevel > 9)
  {
    vtkErrorMacro("ParaFluid H5Part Writer: CompressionLevel = " << this->CompressionLevel
                                                                 << " is not allowed: it must be from 0 to 9");
    return false;
  }
  parafluid::h5::QuietErrors quiet;
  std::unique_ptr<parafluid::Communicator> processes = parallel ? parafluid::vtk::makeProcessCommunicator() : nullptr;
  std::string temporary;
  if (!processes || processes->rank() == 0)
  {
    // Temporaries that killed writers left beside this target (SIGKILL cannot be caught).
    parafluid::h5::removeStaleTemporaries(this->FileName);
    temporary = parafluid::h5::temporaryNameFor(this->FileName);
  }
  if (processes)
  {
    temporary = parafluid::vtk::fromFirstProcess(temporary, *processes); // one file for all
  }
  this->File = std::make_unique<OpenFile>(temporary);
  this->File->Processes = std::move(processes);
  // The 1.8 file format at least: attributes larger than 64 kB (long field-data arrays) go to
  // dense storage instead of failing.
  Handle access =
    this->File->Processes ? parafluid::vtk::parallelFileAccess() : Handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(access, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  this->File->File = Handle(H5Fcreate(this->File->TemporaryName.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose);
  if (!this->File->File.valid())
  {
    vtkErrorMacro("ParaFluid H5Part Writer: cannot create '" << this->File->TemporaryName
                                                             << "' (is the folder writable?)");
    this->File.reset();
    return false;
  }
  if (this->IsH5md())
  {
    this->File->H5md = std::make_unique<parafluid::vtk::H5mdFrameWriter>(this->File->File, this->CompressionLevel);
  }
  return true;
}

bool vtkPFH5PartWriter::WriteStep(vtkDataObject* input, int stepIndex, double time)
{
  if (this->File->H5md)
  {
    auto* particles = vtkPointSet::SafeDownCast(input);
    std::vector<std::string> warnings;
    std::string error = particles ? ""
                                  : std::string("the input is a ") + (input ? input->GetClassName() : "null") +
                                      ", not particles (a vtkPointSet)";
    parafluid::h5::QuietErrors quiet;
    const bool written = particles && this->File->H5md->write(particles, stepIndex, time, warnings, error);
    for (const std::string& warning : warnings)
    {
      vtkWarningMacro("ParaFluid H5Part Writer: '" << this->FileName << "': " << warning);
    }
    if (!written)
    {
      vtkErrorMacro("ParaFluid H5Part Writer: '" << this->FileName << "': " << error << "; nothing was written");
    }
    return written;
  }
  auto* points = vtkPointSet::SafeDownCast(input);
  if (!points)
  {
    vtkErrorMacro("ParaFluid H5Part Writer: the input is a " << (input ? input->GetClassName() : "null")
                                                             << ", not particles (a vtkPointSet)");
    return false;
  }
  parafluid::h5::QuietErrors quiet;
  const hid_t file = this->File->File;
  const std::string groupName = "Step#" + std::to_string(stepIndex);
  Handle group(H5Gcreate2(file, groupName.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid() || !writeDoubleAttribute(group, "time", &time, 1))
  {
    vtkErrorMacro("ParaFluid H5Part Writer: cannot create " << groupName);
    return false;
  }
  if (this->File->Processes)
  {
    std::vector<std::string> warnings;
    std::string error;
    const bool written =
      parafluid::vtk::writeParallelStep(group, points, this->CompressionLevel, *this->File->Processes, warnings, error);
    this->Warn(warnings);
    if (!written)
    {
      vtkErrorMacro("ParaFluid H5Part Writer: " << error << " in " << groupName);
    }
    if (stepIndex == 0)
    {
      this->WriteFieldData(parafluid::vtk::agreedFieldData(points, *this->File->Processes));
    }
    return written;
  }
  const auto n = static_cast<hsize_t>(points->GetNumberOfPoints());
  std::vector<std::string> warnings;
  const std::vector<parafluid::vtk::H5PartColumn> columns = parafluid::vtk::h5partColumns(points, warnings);
  this->Warn(warnings);
  for (const parafluid::vtk::H5PartColumn& column : columns)
  {
    if (!writeDataset(group, column.name, parafluid::vtk::h5partMemoryType(column.values),
                      parafluid::vtk::h5partFileType(column.type), column.values->GetVoidPointer(0), n,
                      static_cast<hsize_t>(column.components), this->CompressionLevel))
    {
      vtkErrorMacro("ParaFluid H5Part Writer: failed writing '" << column.name << "' of " << groupName);
      return false;
    }
  }
  if (stepIndex == 0)
  {
    this->WriteFieldData(input->GetFieldData());
  }
  return true;
}

void vtkPFH5PartWriter::WriteFieldData(vtkFieldData* fieldData)
{
  const hid_t file = this->File->File;
  for (int k = 0; fieldData && k < fieldData->GetNumberOfArrays(); ++k)
  {
    vtkAbstractArray* abstract = fieldData->GetAbstractArray(k);
    if (!abstract || !abstract->GetName() || std::string(abstract->GetName()) == parafluid::contract::Time ||
        abstract->GetNumberOfValues() == 0)
    {
      continue;
    }
    const std::string name = abstract->GetName();
    if (static_cast<std::size_t>(abstract->GetNumberOfValues()) > parafluid::h5::kMaxAttributeValues)
    {
      vtkWarningMacro("ParaFluid H5Part Writer: field data '"
                      << name << "' (" << abstract->GetNumberOfValues()
                      << " values) is not written: an H5Part root attribute holds at most "
                      << parafluid::h5::kMaxAttributeValues << " values");
      continue;
    }
    if (auto* strings = vtkStringArray::SafeDownCast(abstract))
    {
      if (!writeStringAttribute(file, name.c_str(), strings))
      {
        vtkWarningMacro("ParaFluid H5Part Writer: field data '" << name << "' could not be written");
      }
      continue;
    }
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    if (!array)
    {
      vtkWarningMacro("ParaFluid H5Part Writer: field data '" << name << "' is neither numbers nor text: not written");
      continue;
    }
    std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfValues()));
    for (vtkIdType v = 0; v < array->GetNumberOfValues(); ++v)
    {
      values[static_cast<std::size_t>(v)] = array->GetVariantValue(v).ToDouble();
    }
    if (!writeDoubleAttribute(file, name.c_str(), values.data(), values.size()))
    {
      vtkWarningMacro("ParaFluid H5Part Writer: field data '" << name << "' could not be written");
    }
  }
}

void vtkPFH5PartWriter::Warn(const std::vector<std::string>& warnings)
{
  if (this->File && this->File->Processes && this->File->Processes->rank() != 0)
  {
    return; // every process has the same to say: process 0 says it
  }
  for (const std::string& warning : warnings)
  {
    vtkWarningMacro("ParaFluid H5Part Writer: '" << this->FileName << "': " << warning);
  }
}

bool vtkPFH5PartWriter::FinishFile()
{
  if (!this->File)
  {
    return false;
  }
  const std::string temporary = this->File->TemporaryName;
  const bool renames = !this->File->Processes || this->File->Processes->rank() == 0;
  this->File->File.reset(); // flush and close before the rename (collective under MPI-IO)
  this->File.reset();
  if (renames && std::rename(temporary.c_str(), this->FileName.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    vtkErrorMacro("ParaFluid H5Part Writer: cannot replace '" << this->FileName << "'");
    return false;
  }
  return true;
}

void vtkPFH5PartWriter::AbandonFile()
{
  if (this->File)
  {
    const std::string temporary = this->File->TemporaryName;
    const bool removes = !this->File->Processes || this->File->Processes->rank() == 0;
    this->File->File.reset();
    this->File.reset();
    if (removes)
    {
      std::remove(temporary.c_str());
    }
  }
}

void vtkPFH5PartWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "WriteAllTimeSteps: " << this->WriteAllTimeSteps << "\n";
  os << indent << "CompressionLevel: " << this->CompressionLevel << "\n";
}

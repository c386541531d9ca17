#include "vtkPFH5PartReader.h"

#include "GuardedRequest.h"
#include "ParticleArrays.h"
#include "ParticleBlockRead.h"
#include "parafluid/common/MemoryBudget.h"
#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Datasets.h"
#include "parafluid/h5part/Handle.h"
#include "parafluid/h5part/Layout.h"

#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt64Array.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <numeric>

namespace
{
using parafluid::h5::Handle;

/// Numeric root attributes become field-data arrays; string attributes become string arrays.
void readSceneConstants(hid_t file, vtkFieldData* fieldData, std::vector<std::string>& warnings)
{
  for (const auto& attribute : parafluid::h5::readAttributes(file, warnings))
  {
    if (attribute.text)
    {
      vtkNew<vtkStringArray> array;
      array->SetName(attribute.name.c_str());
      for (const std::string& value : attribute.strings)
      {
        array->InsertNextValue(value);
      }
      fieldData->AddArray(array);
      continue;
    }
    vtkNew<vtkDoubleArray> array;
    array->SetName(attribute.name.c_str());
    array->SetNumberOfValues(static_cast<vtkIdType>(attribute.numbers.size()));
    std::copy(attribute.numbers.begin(), attribute.numbers.end(), array->GetPointer(0));
    fieldData->AddArray(array);
  }
}

Handle openFile(const std::string& fileName, std::string& error)
{
  return Handle(parafluid::h5::openForReading(fileName, error), H5Fclose);
}
} // namespace

vtkStandardNewMacro(vtkPFH5PartReader);

vtkPFH5PartReader::vtkPFH5PartReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPFH5PartReader::~vtkPFH5PartReader() = default;

int vtkPFH5PartReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::string error;
  Handle file = openFile(fileName, error);
  if (!file.valid())
  {
    return 0;
  }
  parafluid::h5::QuietErrors quiet;
  return parafluid::h5::listSteps(file, error).empty() ? 0 : 1;
}

int vtkPFH5PartReader::GetNumberOfPointArrays()
{
  return this->PointArraySelection->GetNumberOfArrays();
}

const char* vtkPFH5PartReader::GetPointArrayName(int index)
{
  return this->PointArraySelection->GetArrayName(index);
}

int vtkPFH5PartReader::GetPointArrayStatus(const char* name)
{
  return this->PointArraySelection->ArrayIsEnabled(name);
}

void vtkPFH5PartReader::SetPointArrayStatus(const char* name, int status)
{
  if (status)
  {
    this->PointArraySelection->EnableArray(name);
  }
  else
  {
    this->PointArraySelection->DisableArray(name);
  }
}

vtkMTimeType vtkPFH5PartReader::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->PointArraySelection->GetMTime());
}

void vtkPFH5PartReader::WarnOnce(const std::string& warning)
{
  if (this->Warned.insert(warning).second)
  {
    vtkWarningMacro("ParaFluid H5Part Reader: '" << this->FileName << "': " << warning);
  }
}

int vtkPFH5PartReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->StepGroups.clear();
  this->StepTimes.clear();
  this->InformationError.clear();
  this->Warned.clear();
  std::string error;
  Handle file = openFile(this->FileName, error);
  if (!file.valid())
  {
    this->InformationError = error;
    vtkErrorMacro("ParaFluid H5Part Reader: " << error);
    return 0;
  }
  parafluid::h5::QuietErrors quiet;
  std::vector<std::string> warnings;
  const auto steps = parafluid::h5::listSteps(file, error, &warnings);
  if (steps.empty())
  {
    this->InformationError = "'" + this->FileName + "': " + error;
    vtkErrorMacro("ParaFluid H5Part Reader: " << this->InformationError);
    return 0;
  }
  for (const std::string& warning : warnings)
  {
    this->WarnOnce(warning);
  }
  for (const auto& s : steps)
  {
    this->StepGroups.push_back(s.group);
    this->StepTimes.push_back(s.time);
  }
  // The arrays offered for selection are those of the first step that has any.
  for (const auto& s : steps)
  {
    const auto layout = parafluid::h5::describeStep(file, s.group);
    if (!layout.error.empty())
    {
      continue;
    }
    for (const auto& a : layout.arrays)
    {
      if (!this->PointArraySelection->ArrayExists(a.name.c_str()))
      {
        this->PointArraySelection->AddArray(a.name.c_str(), true);
      }
    }
    break;
  }

  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->StepTimes.data(),
            static_cast<int>(this->StepTimes.size()));
  const double range[2] = { this->StepTimes.front(), this->StepTimes.back() };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkPFH5PartReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(info);
  std::string error;
  try
  {
    if (this->ReadStep(info, output, error))
    {
      return 1;
    }
  }
  catch (const std::bad_alloc&)
  {
    error = "'" + this->FileName + "': not enough memory to read this step";
  }
  catch (const std::exception& e)
  {
    error = "'" + this->FileName + "': " + parafluid::vtk::exceptionText(e);
  }
  output->Initialize();
  vtkErrorMacro("ParaFluid H5Part Reader: " << error);
  return 0;
}

bool vtkPFH5PartReader::ReadStep(vtkInformation* info, vtkPolyData* output, std::string& error)
{
  if (this->StepGroups.empty())
  {
    error = this->InformationError.empty() ? std::string("no steps to read") : this->InformationError;
    return false;
  }
  Handle file = openFile(this->FileName, error);
  if (!file.valid())
  {
    return false;
  }
  parafluid::h5::QuietErrors quiet;
  const std::string where = "'" + this->FileName + "': ";

  // The step whose time is nearest the requested one (times are finite: listSteps sees to it).
  std::size_t step = 0;
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double requested = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    if (std::isnan(requested))
    {
      error = where + "the requested time is NaN";
      return false;
    }
    // Past the last step (+inf too) the last, before the first the first, else the nearest.
    const double clamped = std::clamp(requested, this->StepTimes.front(), this->StepTimes.back());
    for (std::size_t k = 0; k < this->StepTimes.size(); ++k)
    {
      if (std::fabs(this->StepTimes[k] - clamped) < std::fabs(this->StepTimes[step] - clamped))
      {
        step = k;
      }
    }
  }
  const double time = this->StepTimes[step];
  const std::string& groupName = this->StepGroups[step];
  const auto layout = parafluid::h5::describeStep(file, groupName);
  if (!layout.error.empty())
  {
    error = where + layout.error;
    return false;
  }
  for (const std::string& warning : layout.warnings)
  {
    this->WarnOnce(warning);
  }
  // This piece's contiguous slice of the particles, read by the path every layout shares.
  parafluid::vtk::BlockReading how = parafluid::vtk::blockReadingFor(info, this->PointArraySelection, this);
  how.stride = this->Stride;
  how.useBox = this->UseBox;
  std::copy(this->Box, this->Box + 6, how.box);
  const parafluid::h5::ParticleBlock block{ groupName, { { this->FileName, groupName, layout } }, {} };
  std::vector<std::string> blockWarnings;
  const bool read = parafluid::vtk::readParticleBlock(block, how, output, blockWarnings, error);
  for (const std::string& warning : blockWarnings)
  {
    this->WarnOnce(warning);
  }
  if (!read)
  {
    error = error.rfind("'", 0) == 0 ? error : where + error;
    return false;
  }

  std::vector<std::string> warnings;
  readSceneConstants(file, output->GetFieldData(), warnings);
  for (const std::string& warning : warnings)
  {
    this->WarnOnce(warning);
  }
  vtkNew<vtkDoubleArray> timeArray;
  timeArray->SetName(parafluid::contract::Time);
  timeArray->InsertNextValue(time);
  output->GetFieldData()->AddArray(timeArray);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return true;
}

void vtkPFH5PartReader::SetSubset(int stride, bool useBox, const double box[6])
{
  if (stride != this->Stride || useBox != this->UseBox || !std::equal(box, box + 6, this->Box))
  {
    this->Stride = std::max(stride, 1);
    this->UseBox = useBox;
    std::copy(box, box + 6, this->Box);
    this->Modified();
  }
}

void vtkPFH5PartReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Steps: " << this->StepGroups.size() << "\n";
}

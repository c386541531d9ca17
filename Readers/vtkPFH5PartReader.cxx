#include "vtkPFH5PartReader.h"

#include "GuardedRequest.h"
#include "ParticleArrays.h"
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
using parafluid::h5::ValueType;

vtkSmartPointer<vtkDataArray> arrayOf(ValueType type)
{
  switch (type)
  {
    case ValueType::Float32:
      return vtkSmartPointer<vtkFloatArray>::New();
    case ValueType::Float64:
      return vtkSmartPointer<vtkDoubleArray>::New();
    case ValueType::Int32:
      return vtkSmartPointer<vtkIntArray>::New();
    case ValueType::Int64:
      return vtkSmartPointer<vtkTypeInt64Array>::New();
    default:
      return vtkSmartPointer<vtkTypeUInt64Array>::New();
  }
}

/// Sizes an array to n tuples; false when the memory could not be had (VTK then leaves it empty).
bool allocate(vtkDataArray* array, int components, vtkIdType n)
{
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  return array->GetNumberOfTuples() == n;
}

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
  Handle group(H5Gopen2(file, groupName.c_str(), H5P_DEFAULT), H5Gclose);

  // This piece's contiguous slice of the particles.
  const int piece = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      : 0;
  const int pieces = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
                       ? std::max(1, info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
                       : 1;
  const std::uint64_t total = layout.particles;
  const std::uint64_t begin = total / pieces * piece + std::min<std::uint64_t>(piece, total % pieces);
  const std::uint64_t count = total / pieces + (static_cast<std::uint64_t>(piece) < total % pieces ? 1 : 0);
  const auto n = static_cast<vtkIdType>(count);

  // What this step will take in memory, checked before anything is allocated.
  const auto coordinateType = parafluid::h5::commonValueType(group, layout.coordinateDatasets) == ValueType::Float32
                                ? ValueType::Float32
                                : ValueType::Float64;
  double bytes = static_cast<double>(count) * (3.0 * parafluid::h5::valueBytes(coordinateType) + 8.0 + 16.0);
  std::vector<ValueType> arrayTypes;
  for (const auto& source : layout.arrays)
  {
    arrayTypes.push_back(parafluid::h5::commonValueType(group, source.datasets));
    if (this->PointArraySelection->ArrayIsEnabled(source.name.c_str()))
    {
      bytes += static_cast<double>(count) * source.components * parafluid::h5::valueBytes(arrayTypes.back());
    }
  }
  const std::string tooLarge =
    parafluid::checkMemoryBudget(bytes, groupName + " (" + std::to_string(total) + " particles, as the file declares)");
  if (!tooLarge.empty())
  {
    error = where + tooLarge + "; deselect point arrays or read it under MPI in pieces";
    return false;
  }

  // Coordinates, keeping the file's precision.
  vtkSmartPointer<vtkDataArray> coordinates = arrayOf(coordinateType);
  if (!allocate(coordinates, 3, n))
  {
    error = where + "not enough memory for the coordinates of " + groupName;
    return false;
  }
  for (std::size_t c = 0; c < layout.coordinateDatasets.size(); ++c)
  {
    if (!parafluid::h5::readSlice(group, layout.coordinateDatasets[c], coordinateType, begin, count,
                                  coordinates->GetVoidPointer(0), 3, layout.coordinateDatasets.size() > 1 ? c : 0,
                                  error))
    {
      error = where + groupName + ": " + error;
      return false;
    }
  }
  this->WarnAboutNonFinite(coordinates, "coordinate", groupName, begin);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  parafluid::vtk::setOneVertexPerPoint(output, n);

  // Stable ids: the file's, else the index in the file.
  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(parafluid::contract::Id);
  if (!allocate(ids, 1, n))
  {
    error = where + "not enough memory for the ids of " + groupName;
    return false;
  }
  std::string idProblem;
  if (layout.idDataset.empty() ||
      !parafluid::h5::readIds(group, layout.idDataset, begin, count,
                              reinterpret_cast<std::int64_t*>(ids->GetPointer(0)), idProblem))
  {
    if (!idProblem.empty())
    {
      this->WarnOnce(groupName + ": " + idProblem + "; each particle's id is its index in the file instead");
    }
    std::iota(ids->GetPointer(0), ids->GetPointer(0) + n, static_cast<vtkTypeInt64>(begin));
  }
  output->GetPointData()->AddArray(ids);

  for (std::size_t k = 0; k < layout.arrays.size(); ++k)
  {
    const auto& source = layout.arrays[k];
    if (this->CheckAbort())
    {
      error = where + "reading was aborted";
      return false;
    }
    if (!this->PointArraySelection->ArrayIsEnabled(source.name.c_str()))
    {
      continue;
    }
    auto array = arrayOf(arrayTypes[k]);
    array->SetName(source.name.c_str());
    if (!allocate(array, source.components, n))
    {
      error = where + "not enough memory for array " + source.name + " of " + groupName;
      return false;
    }
    for (std::size_t c = 0; c < source.datasets.size(); ++c)
    {
      if (!parafluid::h5::readSlice(group, source.datasets[c], arrayTypes[k], begin, count, array->GetVoidPointer(0),
                                    static_cast<std::uint64_t>(source.components), source.datasets.size() > 1 ? c : 0,
                                    error))
      {
        error = where + groupName + ": " + error;
        return false;
      }
    }
    output->GetPointData()->AddArray(array);
    this->UpdateProgress(0.1 + 0.9 * static_cast<double>(k + 1) / static_cast<double>(layout.arrays.size()));
  }
  if (auto* velocity = output->GetPointData()->GetArray(parafluid::contract::Velocity))
  {
    output->GetPointData()->SetVectors(velocity);
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

void vtkPFH5PartReader::WarnAboutNonFinite(vtkDataArray* values, const char* what, const std::string& groupName,
                                           std::uint64_t begin)
{
  const vtkIdType n = values->GetNumberOfTuples();
  const int components = values->GetNumberOfComponents();
  // A typed scan of the raw values (the coordinates are float or double): GetComponent's virtual
  // call per value cost as much as the read itself.
  auto firstNonFinite = [&](const auto* v) -> vtkIdType
  {
    const vtkIdType total = n * components;
    for (vtkIdType k = 0; k < total; ++k)
    {
      if (!std::isfinite(v[k]))
      {
        return k / components;
      }
    }
    return -1;
  };
  vtkIdType bad = -1;
  if (auto* floats = vtkFloatArray::SafeDownCast(values))
  {
    bad = firstNonFinite(floats->GetPointer(0));
  }
  else if (auto* doubles = vtkDoubleArray::SafeDownCast(values))
  {
    bad = firstNonFinite(doubles->GetPointer(0));
  }
  if (bad >= 0)
  {
    this->WarnOnce(groupName + ": particle " + std::to_string(begin + static_cast<std::uint64_t>(bad)) +
                   " has a NaN or infinite " + what +
                   " (read as it is; filters that need finite values refuse or drop such particles)");
  }
}

void vtkPFH5PartReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Steps: " << this->StepGroups.size() << "\n";
}

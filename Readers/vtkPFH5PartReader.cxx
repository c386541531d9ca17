#include "vtkPFH5PartReader.h"

#include "H5Handle.h"
#include "H5PartLayout.h"
#include "ParticleArrays.h"

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

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace
{
using parafluid::h5::Handle;

/// VTK array of the type that holds a dataset's values without loss, and its HDF5 memory type.
vtkSmartPointer<vtkDataArray> arrayForDataset(hid_t dataset, hid_t& memoryType)
{
  Handle type(H5Dget_type(dataset), H5Tclose);
  const std::size_t size = H5Tget_size(type);
  if (H5Tget_class(type) == H5T_FLOAT)
  {
    if (size <= 4)
    {
      memoryType = H5T_NATIVE_FLOAT;
      return vtkSmartPointer<vtkFloatArray>::New();
    }
    memoryType = H5T_NATIVE_DOUBLE;
    return vtkSmartPointer<vtkDoubleArray>::New();
  }
  if (size <= 4)
  {
    memoryType = H5T_NATIVE_INT;
    return vtkSmartPointer<vtkIntArray>::New();
  }
  memoryType = H5T_NATIVE_INT64;
  return vtkSmartPointer<vtkTypeInt64Array>::New();
}

/// Reads rows [offset, offset + count) of a dataset of N or N x k values into column `column`
/// (of `stride` columns) of `target`. A component of a vector (x of the points, vx of velocity)
/// is read contiguously and then interleaved: HDF5's own strided scatter is several times slower
/// on chunked, compressed datasets.
bool readSlice(hid_t group, const std::string& name, hid_t memoryType, hsize_t offset, hsize_t count, void* target,
               hsize_t stride, hsize_t column)
{
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
  {
    return false;
  }
  Handle fileSpace(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(fileSpace);
  hsize_t dims[2] = { 0, 1 };
  H5Sget_simple_extent_dims(fileSpace, dims, nullptr);
  const hsize_t width = rank == 2 ? dims[1] : 1;
  if (count == 0)
  {
    return true;
  }
  const hsize_t fileStart[2] = { offset, 0 };
  const hsize_t fileCount[2] = { count, width };
  if (H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, fileStart, nullptr, fileCount, nullptr) < 0)
  {
    return false;
  }
  const hsize_t memoryDims[2] = { count, width };
  Handle memorySpace(H5Screate_simple(rank, memoryDims, nullptr), H5Sclose);
  if (width == stride)
  {
    return H5Dread(dataset, memoryType, memorySpace, fileSpace, H5P_DEFAULT, target) >= 0;
  }
  if (width != 1)
  {
    return false; // an N x k dataset is never a component of a wider array
  }
  const std::size_t valueSize = H5Tget_size(memoryType);
  std::vector<unsigned char> component(static_cast<std::size_t>(count) * valueSize);
  if (H5Dread(dataset, memoryType, memorySpace, fileSpace, H5P_DEFAULT, component.data()) < 0)
  {
    return false;
  }
  auto* out = static_cast<unsigned char*>(target) + column * valueSize;
  const std::size_t step = static_cast<std::size_t>(stride) * valueSize;
  for (hsize_t i = 0; i < count; ++i)
  {
    std::memcpy(out + i * step, component.data() + i * valueSize, valueSize);
  }
  return true;
}

herr_t collectAttributeName(hid_t, const char* name, const H5A_info_t*, void* data)
{
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}

/// Numeric root attributes become field-data arrays; string attributes become string arrays.
void readSceneConstants(hid_t file, vtkFieldData* fieldData)
{
  std::vector<std::string> names;
  H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collectAttributeName, &names);
  for (const std::string& name : names)
  {
    std::vector<double> values;
    if (parafluid::h5::readNumericAttribute(file, name.c_str(), values))
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(name.c_str());
      array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
      std::copy(values.begin(), values.end(), array->GetPointer(0));
      fieldData->AddArray(array);
      continue;
    }
    Handle attribute(H5Aopen(file, name.c_str(), H5P_DEFAULT), H5Aclose);
    Handle type(H5Aget_type(attribute), H5Tclose);
    if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
    {
      continue;
    }
    std::string text(H5Tget_size(type), '\0');
    Handle memoryType(H5Tcopy(type), H5Tclose);
    if (H5Aread(attribute, memoryType, text.data()) >= 0)
    {
      text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
      vtkNew<vtkStringArray> array;
      array->SetName(name.c_str());
      array->InsertNextValue(text);
      fieldData->AddArray(array);
    }
  }
}

Handle openFile(const std::string& fileName, std::string& error)
{
  if (fileName.empty())
  {
    error = "no file name was given";
    return {};
  }
  parafluid::h5::QuietErrors quiet;
  if (H5Fis_hdf5(fileName.c_str()) <= 0)
  {
    FILE* probe = std::fopen(fileName.c_str(), "rb");
    error = probe ? "'" + fileName + "' is not an HDF5 file" : "cannot open '" + fileName + "' (missing or unreadable)";
    if (probe)
    {
      std::fclose(probe);
    }
    return {};
  }
  Handle file(H5Fopen(fileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid())
  {
    error = "HDF5 could not open '" + fileName + "'";
  }
  return file;
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

int vtkPFH5PartReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->StepGroups.clear();
  this->StepTimes.clear();
  this->InformationError.clear();
  std::string error;
  Handle file = openFile(this->FileName, error);
  if (!file.valid())
  {
    this->InformationError = error;
    vtkErrorMacro("ParaFluid H5Part Reader: " << error);
    return 0;
  }
  parafluid::h5::QuietErrors quiet;
  const auto steps = parafluid::h5::listSteps(file, error);
  if (steps.empty())
  {
    this->InformationError = "'" + this->FileName + "': " + error;
    vtkErrorMacro("ParaFluid H5Part Reader: " << this->InformationError);
    return 0;
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
  if (std::is_sorted(this->StepTimes.begin(), this->StepTimes.end()) &&
      std::adjacent_find(this->StepTimes.begin(), this->StepTimes.end()) == this->StepTimes.end())
  {
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->StepTimes.data(),
              static_cast<int>(this->StepTimes.size()));
    const double range[2] = { this->StepTimes.front(), this->StepTimes.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  else
  {
    vtkWarningMacro("ParaFluid H5Part Reader: step times are not increasing; steps are offered by index");
    for (std::size_t k = 0; k < this->StepTimes.size(); ++k)
    {
      this->StepTimes[k] = static_cast<double>(k);
    }
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->StepTimes.data(),
              static_cast<int>(this->StepTimes.size()));
    const double range[2] = { 0.0, static_cast<double>(this->StepTimes.size() - 1) };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

int vtkPFH5PartReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(info);
  if (this->StepGroups.empty())
  {
    vtkErrorMacro("ParaFluid H5Part Reader: " << (this->InformationError.empty() ? std::string("no steps to read")
                                                                                 : this->InformationError));
    return 0;
  }
  std::string error;
  Handle file = openFile(this->FileName, error);
  if (!file.valid())
  {
    vtkErrorMacro("ParaFluid H5Part Reader: " << error);
    return 0;
  }
  parafluid::h5::QuietErrors quiet;

  // The step whose time is nearest the requested one.
  std::size_t step = 0;
  double time = this->StepTimes[0];
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double requested = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    for (std::size_t k = 0; k < this->StepTimes.size(); ++k)
    {
      if (std::fabs(this->StepTimes[k] - requested) < std::fabs(this->StepTimes[step] - requested))
      {
        step = k;
      }
    }
    time = this->StepTimes[step];
  }
  const std::string& groupName = this->StepGroups[step];
  const auto layout = parafluid::h5::describeStep(file, groupName);
  if (!layout.error.empty())
  {
    vtkErrorMacro("ParaFluid H5Part Reader: '" << this->FileName << "': " << layout.error);
    return 0;
  }
  Handle group(H5Gopen2(file, groupName.c_str(), H5P_DEFAULT), H5Gclose);

  // This piece's contiguous slice of the particles.
  const int piece = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      : 0;
  const int pieces = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
                       ? std::max(1, info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
                       : 1;
  const hsize_t total = layout.particles;
  const hsize_t begin = total * static_cast<hsize_t>(piece) / static_cast<hsize_t>(pieces);
  const hsize_t end = total * static_cast<hsize_t>(piece + 1) / static_cast<hsize_t>(pieces);
  const hsize_t count = end - begin;
  const auto n = static_cast<vtkIdType>(count);

  // Coordinates, keeping the file's precision.
  hid_t memoryType = H5T_NATIVE_FLOAT;
  vtkSmartPointer<vtkDataArray> coordinates;
  {
    Handle first(H5Dopen2(group, layout.coordinateDatasets[0].c_str(), H5P_DEFAULT), H5Dclose);
    coordinates = arrayForDataset(first, memoryType);
    if (memoryType != H5T_NATIVE_FLOAT && memoryType != H5T_NATIVE_DOUBLE)
    {
      coordinates = vtkSmartPointer<vtkDoubleArray>::New();
      memoryType = H5T_NATIVE_DOUBLE;
    }
  }
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(n);
  bool ok = true;
  for (std::size_t c = 0; c < layout.coordinateDatasets.size(); ++c)
  {
    ok = ok &&
         readSlice(group, layout.coordinateDatasets[c], memoryType, begin, count, coordinates->GetVoidPointer(0), 3, c);
  }
  if (!ok)
  {
    vtkErrorMacro("ParaFluid H5Part Reader: failed to read the coordinates of " << groupName);
    return 0;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    coordinates->GetTuple(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      vtkWarningMacro("ParaFluid H5Part Reader: particle " << begin + static_cast<hsize_t>(i) << " of " << groupName
                                                           << " has a NaN or infinite coordinate");
      break;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);

  parafluid::vtk::setOneVertexPerPoint(output, n);

  // Stable ids: the file's, else the index in the file.
  vtkNew<vtkTypeInt64Array> ids;
  ids->SetName(parafluid::contract::Id);
  ids->SetNumberOfValues(n);
  if (!layout.idDataset.empty())
  {
    ok = readSlice(group, layout.idDataset, H5T_NATIVE_INT64, begin, count, ids->GetPointer(0), 1, 0);
  }
  else
  {
    std::iota(ids->GetPointer(0), ids->GetPointer(0) + n, static_cast<vtkTypeInt64>(begin));
  }
  output->GetPointData()->AddArray(ids);

  for (const auto& source : layout.arrays)
  {
    if (!ok || this->CheckAbort())
    {
      break;
    }
    if (!this->PointArraySelection->ArrayIsEnabled(source.name.c_str()))
    {
      continue;
    }
    Handle first(H5Dopen2(group, source.datasets[0].c_str(), H5P_DEFAULT), H5Dclose);
    hid_t type = H5T_NATIVE_FLOAT;
    auto array = arrayForDataset(first, type);
    array->SetName(source.name.c_str());
    array->SetNumberOfComponents(source.components);
    array->SetNumberOfTuples(n);
    for (std::size_t c = 0; c < source.datasets.size() && ok; ++c)
    {
      ok = readSlice(group, source.datasets[c], type, begin, count, array->GetVoidPointer(0),
                     static_cast<hsize_t>(source.components), source.datasets.size() > 1 ? c : 0);
    }
    output->GetPointData()->AddArray(array);
    this->UpdateProgress(0.1 + 0.9 * static_cast<double>(&source - layout.arrays.data() + 1) /
                                 static_cast<double>(layout.arrays.size()));
  }
  if (!ok)
  {
    vtkErrorMacro("ParaFluid H5Part Reader: failed to read a dataset of " << groupName);
    output->Initialize();
    return 0;
  }
  if (auto* velocity = output->GetPointData()->GetArray(parafluid::contract::Velocity))
  {
    output->GetPointData()->SetVectors(velocity);
  }

  readSceneConstants(file, output->GetFieldData());
  vtkNew<vtkDoubleArray> timeArray;
  timeArray->SetName(parafluid::contract::Time);
  timeArray->InsertNextValue(time);
  output->GetFieldData()->AddArray(timeArray);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

void vtkPFH5PartReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Steps: " << this->StepGroups.size() << "\n";
}

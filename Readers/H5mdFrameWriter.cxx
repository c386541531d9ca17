#include "H5mdFrameWriter.h"

#include "ParticleContract.h"
#include "parafluid/h5part/Handle.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <algorithm>

namespace parafluid::vtk
{
namespace
{
using parafluid::h5::Handle;

bool writeTextAttribute(hid_t object, const char* name, const std::string& text)
{
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, text.size() + 1);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute, type, text.c_str()) >= 0;
}

Handle makeGroup(hid_t parent, const char* path)
{
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links, 1);
  return Handle(H5Gcreate2(parent, path, links, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
}

/// An extensible dataset of `rank` dimensions, the first the frame axis, one frame made.
Handle makeFrames(hid_t group, const char* name, hid_t fileType, int rank, const hsize_t* frame, int level)
{
  hsize_t dims[3], maxDims[3], chunk[3];
  for (int d = 0; d < rank; ++d)
  {
    dims[d] = frame[d];
    maxDims[d] = d == 0 ? H5S_UNLIMITED : frame[d];
    chunk[d] =
      d == 0 ? (rank == 1 ? 256 : 1) : (d == 1 ? std::max<hsize_t>(1, std::min<hsize_t>(frame[d], 65536)) : frame[d]);
  }
  Handle space(H5Screate_simple(rank, dims, maxDims), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(properties, rank, chunk);
  if (level > 0 && rank > 1)
  {
    H5Pset_deflate(properties, static_cast<unsigned>(level));
  }
  return Handle(H5Dcreate2(group, name, fileType, space, H5P_DEFAULT, properties, H5P_DEFAULT), H5Dclose);
}

/// Writes `values` (the shape of `frame`, its first dimension 1) as frame `index` of `dataset`.
bool writeFrame(hid_t dataset, hid_t memoryType, int rank, const hsize_t* frame, hsize_t index, const void* values)
{
  hsize_t dims[3] = { index + 1, rank > 1 ? frame[1] : 1, rank > 2 ? frame[2] : 1 };
  if (index > 0 && H5Dset_extent(dataset, dims) < 0)
  {
    return false;
  }
  Handle fileSpace(H5Dget_space(dataset), H5Sclose);
  hsize_t start[3] = { index, 0, 0 };
  if (H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start, nullptr, frame, nullptr) < 0)
  {
    return false;
  }
  Handle memorySpace(H5Screate_simple(rank, frame, nullptr), H5Sclose);
  return H5Dwrite(dataset, memoryType, memorySpace, fileSpace, H5P_DEFAULT, values) >= 0;
}

bool typesOf(vtkDataArray* array, hid_t& memoryType, hid_t& fileType)
{
  switch (array->GetDataType())
  {
    case VTK_FLOAT:
      memoryType = H5T_NATIVE_FLOAT, fileType = H5T_IEEE_F32LE;
      return true;
    case VTK_DOUBLE:
      memoryType = H5T_NATIVE_DOUBLE, fileType = H5T_IEEE_F64LE;
      return true;
    case VTK_INT:
      memoryType = H5T_NATIVE_INT, fileType = H5T_STD_I32LE;
      return true;
    default:
      if ((array->GetDataType() == VTK_LONG_LONG || array->GetDataType() == VTK_ID_TYPE ||
           array->GetDataType() == VTK_LONG) &&
          array->GetDataTypeSize() == 8)
      {
        memoryType = H5T_NATIVE_INT64, fileType = H5T_STD_I64LE;
        return true;
      }
      return false;
  }
}

/// `array` in a type H5MD's file holds as is (other numbers as doubles).
vtkSmartPointer<vtkDataArray> storable(vtkDataArray* array, hid_t& memoryType, hid_t& fileType)
{
  vtkSmartPointer<vtkDataArray> source = array;
  if (!typesOf(array, memoryType, fileType))
  {
    source = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(VTK_DOUBLE));
    source->DeepCopy(array);
    typesOf(source, memoryType, fileType);
  }
  return source;
}
} // namespace

H5mdFrameWriter::H5mdFrameWriter(hid_t file, int compressionLevel)
  : File(file)
  , Level(compressionLevel)
{
}

bool H5mdFrameWriter::append(const Element& element, const void* values, int frame, double time, std::string& error)
{
  Handle group(frame == 0
                 ? makeGroup(this->File, ("particles/all/" + element.name).c_str())
                 : Handle(H5Gopen2(this->File, ("particles/all/" + element.name).c_str(), H5P_DEFAULT), H5Gclose));
  const hsize_t shape[3] = { 1, static_cast<hsize_t>(this->Particles), static_cast<hsize_t>(element.components) };
  const int rank = element.components > 1 ? 3 : 2;
  const hsize_t one[1] = { 1 };
  const long long step = frame;
  Handle value(frame == 0 ? makeFrames(group, "value", element.fileType, rank, shape, this->Level)
                          : Handle(H5Dopen2(group, "value", H5P_DEFAULT), H5Dclose));
  Handle steps(frame == 0 ? makeFrames(group, "step", H5T_STD_I64LE, 1, one, 0)
                          : Handle(H5Dopen2(group, "step", H5P_DEFAULT), H5Dclose));
  Handle times(frame == 0 ? makeFrames(group, "time", H5T_IEEE_F64LE, 1, one, 0)
                          : Handle(H5Dopen2(group, "time", H5P_DEFAULT), H5Dclose));
  if (!value.valid() || !steps.valid() || !times.valid() ||
      !writeFrame(value, element.memoryType, rank, shape, static_cast<hsize_t>(frame), values) ||
      !writeFrame(steps, H5T_NATIVE_LLONG, 1, one, static_cast<hsize_t>(frame), &step) ||
      !writeFrame(times, H5T_NATIVE_DOUBLE, 1, one, static_cast<hsize_t>(frame), &time))
  {
    error = "failed writing /particles/all/" + element.name + " of frame " + std::to_string(frame);
    return false;
  }
  return true;
}

bool H5mdFrameWriter::write(vtkPointSet* points, int frame, double time, std::vector<std::string>& warnings,
                            std::string& error)
{
  vtkPointData* pointData = points->GetPointData();
  const long long n = points->GetNumberOfPoints();
  if (frame == 0 && n == 0)
  {
    error = "the input has no particles (an H5MD element needs at least one)";
    return false;
  }
  if (frame == 0)
  {
    this->Particles = n;
    Handle h5md = makeGroup(this->File, "h5md");
    const int version[2] = { 1, 1 };
    const hsize_t two = 2;
    Handle space(H5Screate_simple(1, &two, nullptr), H5Sclose);
    Handle attribute(H5Acreate2(h5md, "version", H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    Handle author(makeGroup(h5md, "author")), creator(makeGroup(h5md, "creator"));
    Handle box(makeGroup(this->File, "particles/all/box"));
    const int dimension = 3;
    Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
    Handle dimensionAttribute(H5Acreate2(box, "dimension", H5T_STD_I32LE, scalar, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    Handle textType(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(textType, 5);
    const hsize_t three = 3;
    Handle boundarySpace(H5Screate_simple(1, &three, nullptr), H5Sclose);
    Handle boundary(H5Acreate2(box, "boundary", textType, boundarySpace, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    const char none[3][5] = { "none", "none", "none" };
    if (!attribute.valid() || H5Awrite(attribute, H5T_NATIVE_INT, version) < 0 ||
        !writeTextAttribute(author, "name", "ParaFluid") || !writeTextAttribute(creator, "name", "ParaFluid") ||
        !writeTextAttribute(creator, "version", "5.11") || !dimensionAttribute.valid() ||
        H5Awrite(dimensionAttribute, H5T_NATIVE_INT, &dimension) < 0 || !boundary.valid() ||
        H5Awrite(boundary, textType, none) < 0)
    {
      error = "failed writing the /h5md metadata and the box";
      return false;
    }
    vtkDataArray* coordinates = points->GetPoints() ? points->GetPoints()->GetData() : nullptr;
    hid_t memoryType = -1, fileType = -1;
    if (coordinates)
    {
      storable(coordinates, memoryType, fileType);
    }
    this->Elements.push_back({ "position", "", 3, memoryType, fileType });
    for (int k = 0; k < pointData->GetNumberOfArrays(); ++k)
    {
      vtkDataArray* array = pointData->GetArray(k);
      if (!array || !array->GetName() || std::string(array->GetName()).empty())
      {
        continue;
      }
      const std::string name = array->GetName();
      if (name == "position" || name == "box" || name.find('/') != std::string::npos)
      {
        warnings.push_back("point array '" + name + "' is not written: H5MD uses the name, or it is no element name");
        continue;
      }
      storable(array, memoryType, fileType);
      this->Elements.push_back({ name, name, array->GetNumberOfComponents(), memoryType, fileType });
    }
  }
  else if (n != this->Particles)
  {
    error = "H5MD keeps the same particles in every frame: the step at time " + std::to_string(time) + " has " +
            std::to_string(n) + " particles, the first " + std::to_string(this->Particles) +
            " (write an .h5part file, which holds any count per step)";
    return false;
  }
  for (const Element& element : this->Elements)
  {
    vtkDataArray* array = element.array.empty() ? (points->GetPoints() ? points->GetPoints()->GetData() : nullptr)
                                                : pointData->GetArray(element.array.c_str());
    if (!array || array->GetNumberOfComponents() != element.components)
    {
      error = "H5MD keeps the same elements in every frame: the step at time " + std::to_string(time) +
              (array ? " has another number of components in '" : " has no point array '") +
              (element.array.empty() ? "points" : element.array) + "'";
      return false;
    }
    hid_t memoryType = -1, fileType = -1;
    vtkSmartPointer<vtkDataArray> values = storable(array, memoryType, fileType);
    if (memoryType != element.memoryType)
    {
      auto converted = vtkSmartPointer<vtkDataArray>::Take(
        vtkDataArray::CreateDataArray(element.memoryType == H5T_NATIVE_FLOAT   ? VTK_FLOAT
                                      : element.memoryType == H5T_NATIVE_INT   ? VTK_INT
                                      : element.memoryType == H5T_NATIVE_INT64 ? VTK_LONG_LONG
                                                                               : VTK_DOUBLE));
      converted->DeepCopy(array);
      values = converted;
    }
    if (n > 0 && !this->append(element, values->GetVoidPointer(0), frame, time, error))
    {
      return false;
    }
  }
  return true;
}
} // namespace parafluid::vtk

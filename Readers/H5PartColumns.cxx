#include "H5PartColumns.h"

#include "ParticleArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

namespace parafluid::vtk
{
namespace
{
/// The VTK type H5Part stores `array` as: its own when H5Part holds it, else double.
int storedType(vtkDataArray* array)
{
  switch (array->GetDataType())
  {
    case VTK_FLOAT:
    case VTK_DOUBLE:
    case VTK_INT:
      return array->GetDataType();
    case VTK_LONG_LONG:
    case VTK_ID_TYPE:
    case VTK_LONG:
      return array->GetDataTypeSize() == 8 ? VTK_LONG_LONG : VTK_DOUBLE;
    default:
      return VTK_DOUBLE;
  }
}

} // namespace

vtkSmartPointer<vtkDataArray> h5partValuesAs(vtkDataArray* array, int type)
{
  // 64-bit integers of any VTK type are written as they are (h5partMemoryType).
  if (array->GetDataType() == type || (type == VTK_LONG_LONG && storedType(array) == VTK_LONG_LONG))
  {
    return array;
  }
  auto converted = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  converted->DeepCopy(array);
  return converted;
}

std::vector<H5PartColumn> h5partColumns(vtkPointSet* points, std::vector<std::string>& warnings)
{
  std::vector<H5PartColumn> columns;
  const vtkIdType n = points->GetNumberOfPoints();
  vtkDataArray* coordinates = points->GetPoints() ? points->GetPoints()->GetData() : nullptr;
  const bool doublePrecision = coordinates && coordinates->GetDataType() == VTK_DOUBLE;
  const char* axes[3] = { "x", "y", "z" };
  for (int a = 0; a < 3; ++a)
  {
    vtkSmartPointer<vtkDataArray> axis;
    if (doublePrecision)
    {
      axis = vtkSmartPointer<vtkDoubleArray>::New();
    }
    else
    {
      axis = vtkSmartPointer<vtkFloatArray>::New();
    }
    axis->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      axis->SetTuple1(i, coordinates->GetComponent(i, a));
    }
    columns.push_back({ axes[a], doublePrecision ? VTK_DOUBLE : VTK_FLOAT, 1, axis });
  }
  vtkPointData* pointData = points->GetPointData();
  for (int k = 0; k < pointData->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* array = pointData->GetArray(k);
    if (!array || !array->GetName() || std::string(array->GetName()).empty())
    {
      continue;
    }
    const std::string name = array->GetName();
    if (name == "x" || name == "y" || name == "z")
    {
      warnings.push_back("point array '" + name + "' is not written: its name is a coordinate's");
      continue;
    }
    H5PartColumn column{ name, storedType(array), array->GetNumberOfComponents(), nullptr };
    if (name == parafluid::contract::Id)
    {
      if (array->GetNumberOfComponents() != 1)
      {
        // The H5Part id is one whole number per particle; a vector named id keeps its values under
        // another name instead of making the file unreadable as H5Part.
        column.name = "id_components";
        warnings.push_back("point array 'id' has " + std::to_string(array->GetNumberOfComponents()) +
                           " components; written as 'id_components'");
      }
      else
      {
        column.type = VTK_LONG_LONG;
      }
    }
    column.values = h5partValuesAs(array, column.type);
    columns.push_back(std::move(column));
  }
  return columns;
}

hid_t h5partMemoryType(vtkDataArray* values)
{
  switch (values->GetDataType())
  {
    case VTK_ID_TYPE:
    case VTK_LONG:
      return H5T_NATIVE_INT64; // 8 bytes: the only sizes h5partValuesAs leaves as they are
    default:
      return h5partNativeType(values->GetDataType());
  }
}

hid_t h5partNativeType(int vtkType)
{
  switch (vtkType)
  {
    case VTK_FLOAT:
      return H5T_NATIVE_FLOAT;
    case VTK_INT:
      return H5T_NATIVE_INT;
    case VTK_LONG_LONG:
      return H5T_NATIVE_INT64;
    default:
      return H5T_NATIVE_DOUBLE;
  }
}

hid_t h5partFileType(int vtkType)
{
  switch (vtkType)
  {
    case VTK_FLOAT:
      return H5T_IEEE_F32LE;
    case VTK_INT:
      return H5T_STD_I32LE;
    case VTK_LONG_LONG:
      return H5T_STD_I64LE;
    default:
      return H5T_IEEE_F64LE;
  }
}
} // namespace parafluid::vtk

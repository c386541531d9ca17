#include "CloudVolumeTextures.h"

#include "parafluid/clouds/LightPaths.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace parafluid
{
namespace
{
vtkSmartPointer<vtkTextureObject> texture3D(vtkOpenGLRenderWindow* window, const int dims[3], int components,
                                            const float* data, bool linear)
{
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(window);
  t->Create3DFromRaw(dims[0], dims[1], dims[2], components, VTK_FLOAT, const_cast<float*>(data));
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetWrapR(vtkTextureObject::ClampToEdge);
  t->SetMinificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  t->SetMagnificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  return t;
}
} // namespace

CloudVolumeTextures::CloudVolumeTextures() = default;
CloudVolumeTextures::~CloudVolumeTextures() = default;

bool CloudVolumeTextures::Update(vtkOpenGLRenderWindow* window, vtkImageData* image, const char* array,
                                 vtkMTimeType dataKey, const double toLight[3], bool shadows, std::string& error)
{
  if (this->Context && this->Context != window)
  {
    this->Release(this->Context);
  }
  this->Context = window;
  this->LightMilliseconds = 0.0;
  if (!this->DensityTexture || dataKey != this->DataKey)
  {
    vtkDataArray* values = nullptr;
    bool cells = false;
    if (array && array[0])
    {
      values = image->GetPointData()->GetArray(array);
      if (!values)
      {
        values = image->GetCellData()->GetArray(array);
        cells = values != nullptr;
      }
    }
    else
    {
      values = image->GetPointData()->GetScalars();
    }
    if (!values)
    {
      error = std::string("the image has no array '") + (array ? array : "") + "' to draw as density";
      return false;
    }
    int dims[3];
    image->GetDimensions(dims);
    if (cells)
    {
      for (int& d : dims)
      {
        d = std::max(d - 1, 1);
      }
    }
    const std::size_t count = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
    if (count == 0 || static_cast<std::size_t>(values->GetNumberOfTuples()) != count)
    {
      error = "the image has no samples to draw";
      return false;
    }
    this->Values.resize(count);
    const int components = values->GetNumberOfComponents();
    double largest = 0.0;
    for (std::size_t n = 0; n < count; ++n)
    {
      double v = 0.0;
      if (components == 1)
      {
        v = values->GetComponent(static_cast<vtkIdType>(n), 0);
      }
      else
      {
        for (int c = 0; c < components; ++c)
        {
          const double x = values->GetComponent(static_cast<vtkIdType>(n), c);
          v += x * x;
        }
        v = std::sqrt(v);
      }
      // Negative or non-finite density neither scatters nor absorbs.
      v = std::isfinite(v) ? std::max(v, 0.0) : 0.0;
      this->Values[n] = static_cast<float>(v);
      largest = std::max(largest, v);
    }
    this->Largest = largest;
    double spacing[3], origin[3];
    image->GetSpacing(spacing);
    image->GetOrigin(origin);
    int extent[6];
    image->GetExtent(extent);
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Dims[axis] = dims[axis];
      this->Spacing[axis] = std::abs(spacing[axis]) > 0.0 ? std::abs(spacing[axis]) : 1.0;
      // Each sample owns the voxel around it (cell data: the cells themselves).
      const double first = origin[axis] + spacing[axis] * extent[2 * axis] + (cells ? 0.5 * spacing[axis] : 0.0);
      this->WorldBox[2 * axis] = first - 0.5 * this->Spacing[axis];
      this->WorldBox[2 * axis + 1] = first + (dims[axis] - 0.5) * this->Spacing[axis];
      this->Blocks_[axis] = (dims[axis] + BlockSamples - 1) / BlockSamples;
    }
    this->DensityTexture = texture3D(window, dims, 1, this->Values.data(), true);
    // Each block's largest sample, its one-sample border included: trilinear reads in a block
    // blend those.
    std::vector<float> blocks(static_cast<std::size_t>(this->Blocks_[0]) * this->Blocks_[1] * this->Blocks_[2], 0.0f);
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i)
        {
          const float v = this->Values[(static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i];
          if (v <= 0.0f)
          {
            continue;
          }
          const int idx[3] = { i, j, k };
          int lo[3], hi[3];
          for (int axis = 0; axis < 3; ++axis)
          {
            lo[axis] = std::max((idx[axis] - 1) / BlockSamples, 0);
            hi[axis] = std::min((idx[axis] + 1) / BlockSamples, this->Blocks_[axis] - 1);
          }
          for (int c = lo[2]; c <= hi[2]; ++c)
            for (int b = lo[1]; b <= hi[1]; ++b)
              for (int a = lo[0]; a <= hi[0]; ++a)
              {
                float& m = blocks[(static_cast<std::size_t>(c) * this->Blocks_[1] + b) * this->Blocks_[0] + a];
                m = std::max(m, v);
              }
        }
    this->BlockTexture = texture3D(window, this->Blocks_.data(), 1, blocks.data(), false);
    this->DataKey = dataKey;
    this->LightValid = false;
  }
  const double turned = toLight[0] * this->LitFrom[0] + toLight[1] * this->LitFrom[1] + toLight[2] * this->LitFrom[2];
  if (shadows && (!this->LightValid || turned < std::cos(0.25 * M_PI / 180.0)))
  {
    const auto start = std::chrono::steady_clock::now();
    const double up[3] = { 0.0, 0.0, 1.0 };
    const std::vector<float> sun =
      clouds::densityPathToward(this->Values, this->Dims.data(), this->Spacing.data(), toLight);
    const std::vector<float> sky = clouds::densityPathToward(this->Values, this->Dims.data(), this->Spacing.data(), up);
    std::vector<float> both(2 * sun.size());
    for (std::size_t n = 0; n < sun.size(); ++n)
    {
      both[2 * n] = sun[n];
      both[2 * n + 1] = sky[n];
    }
    this->LightTexture = texture3D(window, this->Dims.data(), 2, both.data(), true);
    std::copy(toLight, toLight + 3, this->LitFrom.begin());
    this->LightValid = true;
    this->LightMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return true;
}

void CloudVolumeTextures::Release(vtkWindow* window)
{
  for (vtkTextureObject* t : { this->DensityTexture.Get(), this->LightTexture.Get(), this->BlockTexture.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->DensityTexture = this->LightTexture = this->BlockTexture = nullptr;
  this->Context = nullptr;
  this->LightValid = false;
  this->DataKey = 0;
}
} // namespace parafluid

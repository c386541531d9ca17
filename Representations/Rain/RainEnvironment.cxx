#include "RainEnvironment.h"

#include "parafluid/rain/SphericalHarmonics.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <vector>

namespace parafluid
{
void RainEnvironment::SetImage(int face, const std::string& file)
{
  if (face >= 0 && face < 6 && this->Files[face] != file)
  {
    this->Files[face] = file;
    this->FilesChanged = true;
  }
}

bool RainEnvironment::ProjectImages()
{
  // Six square faces of one size, as floats in [0, 1], rows from the face's top (OpenGL's
  // cube-map order; VTK images run bottom-up).
  std::array<std::vector<float>, 6> faces;
  int size = 0;
  for (int face = 0; face < 6; ++face)
  {
    if (this->Files[face].empty())
    {
      return false;
    }
    vtkSmartPointer<vtkImageReader2> reader;
    reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(this->Files[face].c_str()));
    if (!reader)
    {
      return false;
    }
    reader->SetFileName(this->Files[face].c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    if (!scalars || dims[0] != dims[1] || dims[0] < 1 || (size && dims[0] != size))
    {
      return false;
    }
    size = dims[0];
    const int components = scalars->GetNumberOfComponents();
    const double scale = scalars->GetDataTypeMax() > 1.0 ? 1.0 / scalars->GetDataTypeMax() : 1.0;
    faces[face].resize(static_cast<std::size_t>(size) * size * 3);
    for (int row = 0; row < size; ++row)
    {
      for (int col = 0; col < size; ++col)
      {
        const vtkIdType source = static_cast<vtkIdType>(size - 1 - row) * size + col;
        for (int c = 0; c < 3; ++c)
        {
          faces[face][(static_cast<std::size_t>(row) * size + col) * 3 + c] =
            static_cast<float>(scalars->GetComponent(source, components >= 3 ? c : 0) * scale);
        }
      }
    }
  }
  const auto sh = rain::shProjectCubeMap(
    { faces[0].data(), faces[1].data(), faces[2].data(), faces[3].data(), faces[4].data(), faces[5].data() }, size, 3);
  for (std::size_t k = 0; k < 48; ++k)
  {
    this->Images[k] = static_cast<float>(sh[k]);
  }
  return true;
}

const std::array<float, 48>& RainEnvironment::Coefficients(vtkRenderer* renderer, const double bottom[3],
                                                           const double top[3])
{
  if (this->FilesChanged)
  {
    this->FilesChanged = false;
    this->HaveImages = this->ProjectImages();
    this->HaveBackground = false;
  }
  if (this->HaveImages)
  {
    this->Current = this->Images;
    return this->Current;
  }
  double up[3] = { 0.0, 0.0, 1.0 };
  renderer->GetActiveCamera()->GetViewUp(up);
  const std::array<double, 9> key = { bottom[0], bottom[1], bottom[2], top[0], top[1], top[2], up[0], up[1], up[2] };
  if (this->HaveBackground && key == this->BackgroundKey)
  {
    return this->Current;
  }
  for (int c = 0; c < 3; ++c)
  {
    const double lo = bottom[c], hi = top[c];
    const auto sh = rain::shProject(
      [&](double x, double y, double z)
      {
        const double height = 0.5 * (1.0 + x * up[0] + y * up[1] + z * up[2]);
        return lo + (hi - lo) * height;
      },
      12);
    for (int k = 0; k < rain::kSHCount; ++k)
    {
      this->Current[static_cast<std::size_t>(c * rain::kSHCount + k)] = static_cast<float>(sh[k]);
    }
  }
  this->BackgroundKey = key;
  this->HaveBackground = true;
  return this->Current;
}

void RainEnvironment::Average(float rgb[3]) const
{
  // L_00 Y_00 with Y_00 = 1 / (2 sqrt(pi)).
  const float y00 = 0.28209479f;
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = this->Current[static_cast<std::size_t>(c * rain::kSHCount)] * y00;
  }
}
} // namespace parafluid

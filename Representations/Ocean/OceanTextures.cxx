#include "OceanTextures.h"
#include "parafluid/common/MathConstants.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageFlip.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace parafluid::vtk
{
namespace
{
}

vtkSmartPointer<vtkTexture> makeRippleTexture(int size, unsigned seed)
{
  // Capillary-gravity ripples: many short waves, amplitude falling with wavenumber.
  struct Ripple
  {
    int kx, ky;
    double amplitude, phase;
  };
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ripple> ripples;
  for (int r = 0; r < 48; ++r)
  {
    const double cycles = 3.0 + 21.0 * unit(random); // per tile
    const double angle = 2.0 * kPi * unit(random);
    Ripple w;
    w.kx = static_cast<int>(std::lround(cycles * std::cos(angle)));
    w.ky = static_cast<int>(std::lround(cycles * std::sin(angle)));
    if (w.kx == 0 && w.ky == 0)
    {
      continue;
    }
    w.amplitude = 1.0 / std::pow(cycles, 1.5);
    w.phase = 2.0 * kPi * unit(random);
    ripples.push_back(w);
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  rgb->SetName("ripples");
  // Slope scale chosen so the steepest ripples tilt the normal by about 35 degrees.
  double largest = 0.0;
  std::vector<double> gradient(2 * static_cast<std::size_t>(size) * size, 0.0);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const double u = static_cast<double>(i) / size, v = static_cast<double>(j) / size;
      double gx = 0.0, gy = 0.0;
      for (const Ripple& w : ripples)
      {
        const double c = w.amplitude * std::cos(2.0 * kPi * (w.kx * u + w.ky * v) + w.phase);
        gx += c * 2.0 * kPi * w.kx;
        gy += c * 2.0 * kPi * w.ky;
      }
      const std::size_t k = 2 * (static_cast<std::size_t>(j) * size + i);
      gradient[k] = gx;
      gradient[k + 1] = gy;
      largest = std::max(largest, std::hypot(gx, gy));
    }
  }
  const double scale = largest > 0.0 ? 0.7 / largest : 0.0;
  for (vtkIdType t = 0; t < rgb->GetNumberOfTuples(); ++t)
  {
    double n[3] = { -scale * gradient[2 * t], -scale * gradient[2 * t + 1], 1.0 };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int c = 0; c < 3; ++c)
    {
      rgb->SetComponent(t, c, std::round(127.5 * (n[c] / length + 1.0)));
    }
  }
  image->GetPointData()->SetScalars(rgb);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->SetColorModeToDirectScalars();
  texture->RepeatOn();
  texture->InterpolateOn();
  texture->MipmapOn();
  return texture;
}

vtkSmartPointer<vtkTexture> makeFixedPointTexture(const double* values, int nx, int ny, int components,
                                                  std::vector<double>& ranges)
{
  const std::size_t samples = static_cast<std::size_t>(nx) * ny;
  ranges.assign(2 * static_cast<std::size_t>(components), 0.0);
  for (int c = 0; c < components; ++c)
  {
    double lo = values[c], hi = values[c];
    for (std::size_t k = 0; k < samples; ++k)
    {
      lo = std::min(lo, values[k * components + c]);
      hi = std::max(hi, values[k * components + c]);
    }
    ranges[2 * c] = lo;
    ranges[2 * c + 1] = std::max(hi - lo, 1e-30);
  }
  constexpr double top = 16777215.0; // 2^24 - 1
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx * components, ny, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(samples) * components);
  unsigned char* bytes = rgb->GetPointer(0);
  for (std::size_t k = 0; k < samples; ++k)
  {
    for (int c = 0; c < components; ++c)
    {
      const double unit = (values[k * components + c] - ranges[2 * c]) / ranges[2 * c + 1];
      const auto code = static_cast<std::uint32_t>(std::lround(std::clamp(unit, 0.0, 1.0) * top));
      unsigned char* texel = bytes + 3 * (k * components + c);
      texel[0] = static_cast<unsigned char>(code >> 16);
      texel[1] = static_cast<unsigned char>((code >> 8) & 0xff);
      texel[2] = static_cast<unsigned char>(code & 0xff);
    }
  }
  image->GetPointData()->SetScalars(rgb);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->SetColorModeToDirectScalars();
  texture->InterpolateOff();
  texture->MipmapOff();
  texture->RepeatOff();
  texture->EdgeClampOn();
  return texture;
}

vtkSmartPointer<vtkTexture> loadCubeMap(const std::array<std::string, 6>& files, std::string& error, double mean[3])
{
  double sum[3] = { 0.0, 0.0, 0.0 };
  double count = 0.0;
  vtkNew<vtkTexture> cube;
  cube->CubeMapOn();
  cube->InterpolateOn();
  cube->MipmapOn();
  cube->SetColorModeToDirectScalars();
  const char* faces[6] = { "+X", "-X", "+Y", "-Y", "+Z", "-Z" };
  for (int f = 0; f < 6; ++f)
  {
    vtkSmartPointer<vtkImageReader2> reader;
    reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(files[f].c_str()));
    if (!reader)
    {
      error = std::string("EnvironmentImages: cannot read the ") + faces[f] + " face '" + files[f] +
              "' (missing, or not an image format VTK reads)";
      return nullptr;
    }
    reader->SetFileName(files[f].c_str());
    // Cube map faces are stored top row first; VTK images bottom row first.
    vtkNew<vtkImageFlip> flip;
    flip->SetInputConnection(reader->GetOutputPort());
    flip->SetFilteredAxis(1);
    flip->Update();
    vtkDataArray* scalars = flip->GetOutput()->GetPointData()->GetScalars();
    if (!scalars || scalars->GetNumberOfComponents() < 3)
    {
      error = std::string("EnvironmentImages: the ") + faces[f] + " face '" + files[f] + "' is not an RGB image";
      return nullptr;
    }
    const double scale = scalars->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
    for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += scale * scalars->GetComponent(t, c);
      }
    }
    count += static_cast<double>(scalars->GetNumberOfTuples());
    cube->SetInputDataObject(f, flip->GetOutput());
  }
  for (int c = 0; c < 3; ++c)
  {
    mean[c] = count > 0.0 ? sum[c] / count : 0.0;
  }
  return cube;
}
} // namespace parafluid::vtk

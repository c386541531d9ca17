#pragma once
// What the Volumetric Cloud's march reads, kept on the GPU and rebuilt only when its source
// changes: the density as a 3-D float texture (linear, clamped), the density paths toward the
// light and toward the sky (parafluid/clouds/LightPaths.h, two channels), and the coarse grid of
// block maxima that the march skips empty space with.
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // the getters convert the smart pointers
#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkWindow;

namespace parafluid
{
class CloudVolumeTextures
{
public:
  /// Samples per block side of the skipping grid.
  static constexpr int BlockSamples = 8;
  CloudVolumeTextures();
  ~CloudVolumeTextures();

  /// Reads `array` of `image` (point data, else cell data; several components: their magnitude)
  /// when `dataKey` changed, and the light paths when the data or `toLight` (unit) moved by more
  /// than a quarter of a degree. False with `error` set when the array is missing or the image has
  /// no samples.
  bool Update(vtkOpenGLRenderWindow* window, vtkImageData* image, const char* array, vtkMTimeType dataKey,
              const double toLight[3], bool shadows, std::string& error);
  void Release(vtkWindow* window);

  vtkTextureObject* Density() const { return this->DensityTexture; }
  vtkTextureObject* Light() const { return this->LightTexture; }
  vtkTextureObject* Blocks() const { return this->BlockTexture; }
  /// The volume's world box (each sample owns the voxel around it) and the blocks per axis.
  const double* Box() const { return this->WorldBox.data(); }
  const int* BlockCount() const { return this->Blocks_.data(); }
  /// The largest density in the volume.
  double MaxDensity() const { return this->Largest; }
  /// Milliseconds the last light-path sweep took (0 when it was not redone).
  double LastLightMilliseconds() const { return this->LightMilliseconds; }

private:
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkSmartPointer<vtkTextureObject> DensityTexture, LightTexture, BlockTexture;
  std::vector<float> Values;
  std::array<int, 3> Dims{ 0, 0, 0 };
  std::array<double, 3> Spacing{ 1.0, 1.0, 1.0 };
  std::array<double, 6> WorldBox{ 0, 0, 0, 0, 0, 0 };
  std::array<int, 3> Blocks_{ 0, 0, 0 };
  std::array<double, 3> LitFrom{ 0.0, 0.0, 0.0 };
  vtkMTimeType DataKey = 0;
  bool LightValid = false;
  double Largest = 0.0;
  double LightMilliseconds = 0.0;
};
} // namespace parafluid

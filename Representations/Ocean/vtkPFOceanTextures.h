/**
 * Textures of the Gerstner Ocean representation, made on the CPU: the tileable capillary-ripple
 * normal map, float data textures (bathymetry, wave phase fields) read with texelFetch, and the
 * environment cube map from six image files.
 */
#ifndef vtkPFOceanTextures_h
#define vtkPFOceanTextures_h

#include "vtkSmartPointer.h"

#include <array>
#include <string>

class vtkTexture;

namespace parafluid::vtk
{
/// A size x size RGB tangent-space normal map of capillary ripples that tiles seamlessly: the
/// height is a sum of sines whose wave vectors are whole numbers of cycles across the tile,
/// directions and phases from a fixed seed; normals from its analytic gradient.
vtkSmartPointer<vtkTexture> makeRippleTexture(int size = 256, unsigned seed = 1);

/// An nx x ny texture of `components` floats per texel (1, 3 or 4), uploaded as floats
/// (direct scalars, no colour mapping), nearest filtering, clamped: for texelFetch.
vtkSmartPointer<vtkTexture> makeDataTexture(const float* values, int nx, int ny, int components);

/// A cube map from six images (+X, -X, +Y, -Y, +Z, -Z), or null with `error` set.
vtkSmartPointer<vtkTexture> loadCubeMap(const std::array<std::string, 6>& files, std::string& error);
} // namespace parafluid::vtk

#endif

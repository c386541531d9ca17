/**
 * Textures of the Gerstner Ocean representation, made on the CPU: the tileable capillary-ripple
 * normal map, float data textures (bathymetry, wave phase fields) read with texelFetch, and the
 * environment cube map from six image files.
 */
#pragma once

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkTexture;

namespace parafluid::vtk
{
/// A size x size RGB tangent-space normal map of capillary ripples that tiles seamlessly: the
/// height is a sum of sines whose wave vectors are whole numbers of cycles across the tile,
/// directions and phases from a fixed seed; normals from its analytic gradient.
vtkSmartPointer<vtkTexture> makeRippleTexture(int size = 256, unsigned seed = 1);

/// Float data for texelFetch, stored as 24-bit fixed point in the RGB bytes of ordinary textures
/// (ParaView 5.11's vtkTexture maps float scalars through a colour table instead of uploading
/// them): an nx x ny grid of `components` values per sample becomes an (nx * components) x ny
/// RGB texture, sample (i, j) component c at texel (i * components + c, j). ranges receives
/// (lowest, span) per component; the shader decodes lowest + code * span / (2^24 - 1).
/// Relative resolution 6e-8 of each component's range.
vtkSmartPointer<vtkTexture> makeFixedPointTexture(const double* values, int nx, int ny, int components,
                                                  std::vector<double>& ranges);

/// A cube map from six images (+X, -X, +Y, -Y, +Z, -Z), or null with `error` set; `mean`
/// receives the mean colour of all faces (0..1), for the automatic exposure.
vtkSmartPointer<vtkTexture> loadCubeMap(const std::array<std::string, 6>& files, std::string& error, double mean[3]);
} // namespace parafluid::vtk

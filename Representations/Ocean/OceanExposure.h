/**
 * Automatic exposure of the Gerstner Ocean representation: the mean linear luminance of the water
 * as the current camera sees it, from the shading model of GerstnerOceanShading.glsl evaluated on
 * the CPU for a grid of view rays against a flat sea (no waves, ripples or foam), so the exposure
 * can map that mean to mid-grey.
 */
#pragma once

#include <functional>

namespace parafluid::vtk
{
struct OceanExposureScene
{
  double eye[3], focal[3], up[3];
  double viewAngle = 30.0; // [degrees], vertical
  double aspect = 1.0;     // width / height
  double seaLevel = 0.0;
  double sun[3]; // unit vector towards the sun
  double sunColor[3], sunIntensity = 1.0, shininess = 400.0;
  double horizon[3], zenith[3];
  double environmentMean[3]; // mean radiance of the cube map, used when hasEnvironment
  bool hasEnvironment = false;
  double deepColor[3], shallowColor[3], colorDepth = 4.0;
  std::function<double(double, double)> depth; // water depth at (x, y); empty: deep water
};

/// Mean luminance over the rays (24 x 16) that hit the sea; 0 when none does.
double meanWaterLuminance(const OceanExposureScene& scene);
} // namespace parafluid::vtk

#pragma once
// How much density lies between each sample of a volume and the volume's edge along a direction
// (toward the sun, or up toward the sky): the integral of density along that ray [density x m].
// Times an extinction coefficient it is the optical depth, so exp(-extinction x path) is the light
// that reaches the sample through the volume (self-shadowing), computed once per volume and light
// instead of a march toward the light from every sample of every pixel.
//
// One sweep over the slices across the direction's dominant axis, starting at the slice nearest
// the light: a sample's path is the path of the point one slice toward the light (bilinear in
// that slice, which is done) plus the segment between them (trapezoid rule). Light that enters
// through a side face passes no density before it.
#include <vector>

namespace parafluid::clouds
{
/// `density`: dims[0] x dims[1] x dims[2] samples, x fastest, spacing[3] [m] between them;
/// `toward`: the direction to follow (needs no unit length; not zero). Throws
/// std::invalid_argument for a zero or non-finite direction, a non-positive spacing or data that
/// does not match dims.
std::vector<float> densityPathToward(const std::vector<float>& density, const int dims[3], const double spacing[3],
                                     const double toward[3]);
} // namespace parafluid::clouds

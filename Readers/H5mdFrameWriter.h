#pragma once
// Particles written as H5MD 1.1 (de Buyl, Colberg & Höfling 2014): /h5md's version, author and
// creator, and one particle group /particles/all whose position, id and point arrays are
// time-dependent elements (value with a frame axis, one step and time per frame), a frame per
// call, chunked (a frame, up to 65536 particles) and deflated. H5MD keeps the same particles in
// every frame, so a frame of another particle count or other arrays is refused.
#include "parafluid/h5part/Hdf5.h"

#include <string>
#include <vector>

class vtkPointSet;

namespace parafluid::vtk
{
class H5mdFrameWriter
{
public:
  H5mdFrameWriter(hid_t file, int compressionLevel);

  /// Appends `points` at `time` as frame `frame` (0, 1, ...); false with `error` when it cannot.
  bool write(vtkPointSet* points, int frame, double time, std::vector<std::string>& warnings, std::string& error);

private:
  struct Element
  {
    std::string name;  // the element's name under /particles/all
    std::string array; // the point array it holds ("" for the positions)
    int components = 1;
    hid_t memoryType = -1, fileType = -1;
  };
  bool append(const Element& element, const void* values, int frame, double time, std::string& error);

  hid_t File;
  int Level;
  long long Particles = -1;
  std::vector<Element> Elements; // the first frame's, which every frame must have
};
} // namespace parafluid::vtk

// PySPH's HDF5 output (pysph.solver.output.HDFOutput, one file <name>_<count>.hdf5 per output):
// /particles/<array>/arrays/<property> datasets (x, y, z, u, v, w, m, rho, p, h, gid, tag, ...;
// a property PySPH did not store is a dataset of no values; a property of stride k holds N x k
// values in one row), /particles/<array>/constants, and the solver's t, dt and count as
// attributes of /solver_data. One block per particle array; particles whose tag is not 0 (PySPH's
// remote and ghost particles, in detailed output) are not real and are left out.
#include "parafluid/h5part/Attributes.h"
#include "parafluid/h5part/Datasets.h"
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <cmath>

namespace parafluid::h5::detail
{
namespace
{
/// PySPH's property names in the particle contract's (pysph.base.utils.get_particle_array).
const DatasetNames& pysphNames()
{
  static const DatasetNames names{ { "position" },
                                   { "gid" },
                                   { { "m", "mass" },
                                     { "rho", "density" },
                                     { "p", "pressure" },
                                     { "h", "smoothing_length" },
                                     { "cs", "sound_speed" },
                                     { "e", "internal_energy" } },
                                   { { "velocity", { "u", "v", "w" } },
                                     { "acceleration", { "au", "av", "aw" } },
                                     { "position_rate", { "ax", "ay", "az" } }, // the integrator's dx/dt
                                     { "velocity0", { "u0", "v0", "w0" } },
                                     { "position0", { "x0", "y0", "z0" } } } };
  return names;
}

std::vector<double> solverValue(hid_t file, const char* name)
{
  Handle solver(H5Gopen2(file, "solver_data", H5P_DEFAULT), H5Gclose);
  std::vector<double> value;
  if (!solver.valid() || !readNumericAttribute(solver, name, value, 1) || !std::isfinite(value[0]))
  {
    return {};
  }
  return value;
}

/// Datasets of `arrays` that are not one value per particle: the ones PySPH did not store (no
/// values) and, with a warning, those of a stride other than 1.
std::set<std::string> notPerParticle(hid_t arrays, const std::string& groupName, std::vector<std::string>& warnings)
{
  std::set<std::string> skip;
  std::string problem;
  const std::vector<std::uint64_t> x = datasetShape(arrays, "x", problem);
  const std::uint64_t n = x.size() == 1 ? x[0] : 0;
  for (const std::string& name : linkNames(arrays))
  {
    if (!hasObject(arrays, name, H5O_TYPE_DATASET))
    {
      continue;
    }
    const std::vector<std::uint64_t> shape = datasetShape(arrays, name, problem);
    if (shape.size() == 1 && shape[0] == 0 && n > 0)
    {
      skip.insert(name);
      continue;
    }
    Handle dataset(H5Dopen2(arrays, name.c_str(), H5P_DEFAULT), H5Dclose);
    std::vector<double> stride;
    if (dataset.valid() && readNumericAttribute(dataset, "stride", stride, 1) && stride[0] > 1.0 && shape.size() == 1 &&
        shape[0] != n)
    {
      skip.insert(name);
      warnings.push_back(groupName + "/" + name + " is not read: it holds " + std::to_string(shape[0]) + " values, " +
                         std::to_string(static_cast<long long>(stride[0])) + " per particle in one row");
    }
  }
  return skip;
}
} // namespace

bool isPySphFile(hid_t file)
{
  if (!hasObject(file, "particles", H5O_TYPE_GROUP) || !hasObject(file, "solver_data", H5O_TYPE_GROUP))
  {
    return false;
  }
  Handle particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose);
  for (const std::string& name : linkNames(particles))
  {
    if (hasObject(particles, name + "/arrays", H5O_TYPE_GROUP))
    {
      return true;
    }
  }
  return false;
}

void describePySphFile(hid_t file, ParticleFileInfo& info)
{
  info.description = "PySPH output";
  const std::vector<double> t = solverValue(file, "t");
  info.times = { t.empty() ? 0.0 : t[0] };
}

ParticleFrame describePySphFrame(hid_t file, const ParticleFileInfo& info)
{
  ParticleFrame frame;
  frame.time = info.times.front();
  frame.fields.push_back({ "time", { frame.time } });
  for (const char* name : { "dt", "count" })
  {
    const std::vector<double> value = solverValue(file, name);
    if (!value.empty())
    {
      frame.fields.push_back({ name == std::string("count") ? "iteration" : name, value });
    }
  }
  Handle particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose);
  for (const std::string& name : linkNames(particles))
  {
    const std::string group = "/particles/" + name + "/arrays";
    if (!hasObject(file, group, H5O_TYPE_GROUP))
    {
      continue;
    }
    Handle arrays(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose);
    DatasetNames names = pysphNames();
    names.skip = notPerParticle(arrays, group, frame.warnings);
    StepLayout layout = describeStep(file, group, names);
    if (!layout.error.empty())
    {
      frame.error = "'" + info.files.front() + "': " + layout.error;
      return frame;
    }
    if (layout.particles == 0)
    {
      continue; // an array with no particles at this output (PySPH writes every array)
    }
    if (hasObject(arrays, "tag", H5O_TYPE_DATASET) && !names.skip.count("tag"))
    {
      layout.realTagDataset = "tag";
    }
    // A serial run leaves gid at its default, 2^32 - 1 (unassigned): the rows are the ids then.
    double firstGid = 0.0;
    std::string error;
    if (layout.idDataset == "gid" &&
        (!readSlice(arrays, "gid", ValueType::Float64, 0, 1, &firstGid, 1, 0, error) || firstGid == 4294967295.0))
    {
      layout.idDataset.clear();
    }
    frame.warnings.insert(frame.warnings.end(), layout.warnings.begin(), layout.warnings.end());
    frame.blocks.push_back({ name, { { info.files.front(), group, std::move(layout) } }, {} });
  }
  if (frame.blocks.empty())
  {
    frame.error = "'" + info.files.front() + "': no particle array under /particles has particles";
  }
  return frame;
}
} // namespace parafluid::h5::detail

// Gadget-style HDF5 snapshots (Springel 2005, Gadget-2's format 3; SWIFT, GIZMO and AREPO write
// the same): /Header's attributes (NumPart_ThisFile, NumPart_Total with its high word, MassTable,
// Time, Redshift, BoxSize, NumFilesPerSnapshot) and one group per particle type,
// /PartType<n>/{Coordinates, Velocities, ParticleIDs, Masses, ...}. SWIFT gives each dataset its
// factor to CGS and the exponents of mass, length, time, temperature and current in it: those
// values are read in SI units (comoving: the factor that leaves out the cosmological
// corrections). A snapshot of NumFilesPerSnapshot files <stem>.<k>.hdf5 is read as one.
#include "parafluid/h5part/Handle.h"
#include "private/LayoutParts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sys/stat.h>

namespace parafluid::h5::detail
{
namespace
{
const char* const kTypeNames[6] = { "gas", "dark matter", "PartType2", "PartType3", "stars", "black holes" };

const DatasetNames& gadgetNames()
{
  static const DatasetNames names{ { "Coordinates" },
                                   { "ParticleIDs" },
                                   { { "Velocities", "velocity" },
                                     { "Masses", "mass" },
                                     { "Density", "density" },
                                     { "Densities", "density" },
                                     { "SmoothingLength", "smoothing_length" },
                                     { "SmoothingLengths", "smoothing_length" },
                                     { "InternalEnergy", "internal_energy" },
                                     { "InternalEnergies", "internal_energy" },
                                     { "Pressure", "pressure" },
                                     { "Pressures", "pressure" } } };
  return names;
}

bool headerValues(hid_t file, const char* name, std::vector<double>& values, std::size_t count)
{
  Handle header(H5Gopen2(file, "Header", H5P_DEFAULT), H5Gclose);
  return header.valid() && readNumericAttribute(header, name, values, count);
}

/// SWIFT's factor from a dataset's values to SI, and the SI unit, from its attributes; 1 and ""
/// when it has none (Gadget: the code's own units).
std::string swiftUnits(hid_t group, const std::string& name, double& scale, std::string& unit)
{
  scale = 1.0;
  unit.clear();
  static const char* const factor = "Conversion factor to CGS (not including cosmological corrections)";
  Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose);
  std::vector<double> cgs;
  if (!dataset.valid() || H5Aexists(dataset, factor) <= 0)
  {
    return "";
  }
  if (!readNumericAttribute(dataset, factor, cgs, 1) || !std::isfinite(cgs[0]))
  {
    return name + "'s CGS conversion factor is not a number; it is read in the code's units";
  }
  // Grams and centimetres to kilograms and metres; seconds, kelvin and amperes stay.
  struct Dimension
  {
    const char* attribute;
    const char* si;
    double fromCgs;
  };
  static const Dimension dimensions[] = { { "U_M exponent", "kg", 1e-3 },
                                          { "U_L exponent", "m", 1e-2 },
                                          { "U_t exponent", "s", 1.0 },
                                          { "U_T exponent", "K", 1.0 },
                                          { "U_I exponent", "A", 1.0 } };
  scale = cgs[0];
  for (const Dimension& d : dimensions)
  {
    std::vector<double> exponent;
    if (!readNumericAttribute(dataset, d.attribute, exponent, 1) || exponent[0] == 0.0)
    {
      continue;
    }
    scale *= std::pow(d.fromCgs, exponent[0]);
    char part[32];
    std::snprintf(part, sizeof(part), exponent[0] == 1.0 ? "%s" : "%s^%g", d.si, exponent[0]);
    unit += (unit.empty() ? "" : " ") + std::string(part);
  }
  return "";
}

bool exists(const std::string& path)
{
  struct stat status;
  return ::stat(path.c_str(), &status) == 0;
}

/// The files of a snapshot of `count` files, given one of them (<stem>.<k>.hdf5); empty when the
/// name does not follow the pattern.
std::vector<std::string> snapshotFiles(const std::string& fileName, int count)
{
  const std::size_t extension = fileName.rfind('.');
  const std::size_t dot =
    extension == std::string::npos || extension == 0 ? std::string::npos : fileName.rfind('.', extension - 1);
  if (dot == std::string::npos)
  {
    return {};
  }
  const std::string index = fileName.substr(dot + 1, extension - dot - 1);
  if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos)
  {
    return {};
  }
  std::vector<std::string> files;
  for (int k = 0; k < count; ++k)
  {
    files.push_back(fileName.substr(0, dot + 1) + std::to_string(k) + fileName.substr(extension));
  }
  return files;
}
} // namespace

void describeGadgetFile(hid_t file, const std::string& fileName, ParticleFileInfo& info)
{
  const bool swift = hasObject(file, "Units", H5O_TYPE_GROUP) || hasObject(file, "Code", H5O_TYPE_GROUP);
  std::vector<double> filesPerSnapshot;
  const int count =
    headerValues(file, "NumFilesPerSnapshot", filesPerSnapshot, 1) ? static_cast<int>(filesPerSnapshot[0]) : 1;
  if (count < 1 || count > 65536)
  {
    info.error = "'" + fileName + "': /Header's NumFilesPerSnapshot is " + std::to_string(count) + ", not 1 to 65536";
    return;
  }
  if (count > 1)
  {
    info.files = snapshotFiles(fileName, count);
    if (info.files.empty())
    {
      info.error = "'" + fileName + "': /Header says the snapshot is " + std::to_string(count) +
                   " files, but the name is not <stem>.<k>.hdf5 to find the others by";
      return;
    }
    for (const std::string& part : info.files)
    {
      if (!exists(part))
      {
        info.error =
          "'" + part + "', file of " + std::to_string(count) + " of the snapshot '" + fileName + "', is missing";
        return;
      }
    }
  }
  info.description = std::string(swift ? "SWIFT" : "Gadget-style") + " snapshot" +
                     (count > 1 ? ", " + std::to_string(count) + " files" : "");
  std::vector<double> time;
  info.times = { headerValues(file, "Time", time, 1) && std::isfinite(time[0]) ? time[0] : 0.0 };
}

ParticleFrame describeGadgetFrame(const ParticleFileInfo& info)
{
  ParticleFrame frame;
  frame.time = info.times.front();
  frame.fields.push_back({ "time", { frame.time } });
  std::vector<ParticleBlock> blocks(6);
  std::vector<double> totals(6, 0.0), total, high, masses;
  double massScale = 1.0;
  std::string massUnit;
  for (std::size_t f = 0; f < info.files.size(); ++f)
  {
    std::string error;
    Handle file(openForReading(info.files[f], error), H5Fclose);
    if (!file.valid())
    {
      frame.error = error;
      return frame;
    }
    std::vector<double> thisFile;
    const auto isCount = [](double v) { return v >= 0.0 && v < 9.2e18 && v == std::floor(v); };
    if (!headerValues(file, "NumPart_ThisFile", thisFile, 6) || thisFile.size() != 6 ||
        !std::all_of(thisFile.begin(), thisFile.end(), isCount))
    {
      frame.error = "'" + info.files[f] + "': /Header has no NumPart_ThisFile of 6 whole, non-negative counts";
      return frame;
    }
    std::vector<double> fileTotal;
    if (f > 0 && headerValues(file, "NumPart_Total", fileTotal, 6) && fileTotal != total)
    {
      frame.error = "'" + info.files[f] + "': /Header's NumPart_Total differs from that of '" + info.files[0] +
                    "' (the files of one snapshot must agree)";
      return frame;
    }
    if (f == 0)
    {
      headerValues(file, "NumPart_Total", total, 6);
      headerValues(file, "NumPart_Total_HighWord", high, 6);
      headerValues(file, "MassTable", masses, 6);
      Handle units(H5Gopen2(file, "Units", H5P_DEFAULT), H5Gclose);
      std::vector<double> unitMass;
      if (units.valid() && readNumericAttribute(units, "Unit mass in cgs (U_M)", unitMass, 1))
      {
        massScale = unitMass[0] * 1e-3; // MassTable is in the code's units
        massUnit = "kg";
      }
      std::vector<double> redshift, box;
      if (headerValues(file, "Redshift", redshift, 1))
      {
        frame.fields.push_back({ "redshift", redshift });
      }
      if (headerValues(file, "BoxSize", box, 3))
      {
        double scale = 1.0;
        std::vector<double> length;
        if (units.valid() && readNumericAttribute(units, "Unit length in cgs (U_L)", length, 1))
        {
          scale = length[0] * 1e-2;
        }
        std::vector<double> bounds;
        for (int a = 0; a < 3; ++a)
        {
          bounds.push_back(0.0);
          bounds.push_back(scale * box[box.size() == 3 ? a : 0]);
        }
        frame.fields.push_back({ "domain_bounds", bounds });
      }
    }
    for (int type = 0; type < 6; ++type)
    {
      const auto n = static_cast<std::uint64_t>(thisFile[type]);
      totals[type] += thisFile[type];
      const std::string group = "PartType" + std::to_string(type);
      if (n == 0)
      {
        continue;
      }
      if (!hasObject(file, group, H5O_TYPE_GROUP))
      {
        frame.error = "'" + info.files[f] + "': /Header counts " + std::to_string(n) + " particles of type " +
                      std::to_string(type) + " but there is no /" + group;
        return frame;
      }
      StepLayout layout = describeStep(file, group, gadgetNames());
      if (!layout.error.empty())
      {
        frame.error = "'" + info.files[f] + "': " + layout.error;
        return frame;
      }
      if (layout.particles != n)
      {
        frame.error = "'" + info.files[f] + "': /" + group + " holds " + std::to_string(layout.particles) +
                      " particles, /Header's NumPart_ThisFile says " + std::to_string(n);
        return frame;
      }
      Handle partType(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose);
      std::vector<std::string> unitProblems = { swiftUnits(partType, layout.coordinates.datasets.front(),
                                                           layout.coordinates.scale, layout.coordinates.unit) };
      for (ArraySource& array : layout.arrays)
      {
        unitProblems.push_back(swiftUnits(partType, array.datasets.front(), array.scale, array.unit));
      }
      for (const std::string& problem : unitProblems)
      {
        if (!problem.empty())
        {
          frame.warnings.push_back("/" + group + "/" + problem);
        }
      }
      frame.warnings.insert(frame.warnings.end(), layout.warnings.begin(), layout.warnings.end());
      const std::string cells = hasObject(file, "Cells", H5O_TYPE_GROUP) &&
                                    (hasObject(file, "Cells/OffsetsInFile/" + group, H5O_TYPE_DATASET) ||
                                     hasObject(file, "Cells/Offsets/" + group, H5O_TYPE_DATASET))
                                  ? group
                                  : "";
      blocks[type].parts.push_back({ info.files[f], "/" + group, std::move(layout), cells, static_cast<int>(f) });
    }
  }
  for (int type = 0; type < 6; ++type)
  {
    if (total.size() == 6)
    {
      const double declared = total[type] + (high.size() == 6 ? high[type] * 4294967296.0 : 0.0);
      if (declared != totals[type])
      {
        char text[200];
        std::snprintf(text, sizeof(text),
                      "the snapshot's files hold %.0f particles of type %d, /Header's NumPart_Total says %.0f",
                      totals[type], type, declared);
        frame.error = text;
        return frame;
      }
    }
    if (blocks[type].parts.empty())
    {
      continue;
    }
    blocks[type].name =
      "PartType" + std::to_string(type) + (type == 2 || type == 3 ? "" : std::string(" (") + kTypeNames[type] + ")");
    const auto& arrays = blocks[type].parts.front().layout.arrays;
    const bool hasMass =
      std::any_of(arrays.begin(), arrays.end(), [](const ArraySource& a) { return a.name == "mass"; });
    if (!hasMass && masses.size() == 6 && masses[type] > 0.0)
    {
      blocks[type].constants.push_back({ "mass", masses[type] * massScale, massUnit });
    }
    frame.blocks.push_back(std::move(blocks[type]));
  }
  return frame;
}
} // namespace parafluid::h5::detail

#pragma once
// What each layout's describer provides to ParticleLayouts.cxx, and the small reads they share.
#include "parafluid/h5part/ParticleLayouts.h"

#include <string>
#include <vector>

namespace parafluid::h5::detail
{
void describeH5mdFile(hid_t file, ParticleFileInfo& info);
ParticleFrame describeH5mdFrame(hid_t file, const ParticleFileInfo& info, std::size_t timeIndex);
void describeGadgetFile(hid_t file, const std::string& fileName, ParticleFileInfo& info);
ParticleFrame describeGadgetFrame(const ParticleFileInfo& info);
void describeOpenPmdFile(hid_t file, const std::string& fileName, ParticleFileInfo& info);
ParticleFrame describeOpenPmdFrame(const ParticleFileInfo& info, std::size_t timeIndex);
bool isPySphFile(hid_t file);
void describePySphFile(hid_t file, ParticleFileInfo& info);
ParticleFrame describePySphFrame(hid_t file, const ParticleFileInfo& info);
void describeVtkHdfFile(hid_t file, ParticleFileInfo& info);
ParticleFrame describeVtkHdfFrame(hid_t file, const ParticleFileInfo& info, std::size_t timeIndex);

/// The files beside `fileName` that differ from it only in the number its name ends in (before the
/// extension and, for a part of a multi-file snapshot, before the part's index), sorted by that
/// number, `fileName` among them; empty when its name ends in no number or it has no such sibling.
std::vector<std::string> numberedSeries(const std::string& fileName, bool multiFilePart);

/// The names of the links in `group`, in name order.
std::vector<std::string> linkNames(hid_t group);
/// True when `group` has a link `name` to an object of `type`.
bool hasObject(hid_t group, const std::string& name, H5O_type_t type);
/// The values of a numeric dataset of at most `maxValues` values; false when absent or larger.
bool readSmallDataset(hid_t group, const std::string& name, std::vector<double>& values, std::size_t maxValues);
/// The strings of a string attribute (fixed or variable length); empty when absent.
std::vector<std::string> stringAttribute(hid_t object, const char* name);
} // namespace parafluid::h5::detail

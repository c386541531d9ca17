#pragma once
// Every numeric SPH parameter declared once (parafluid/common/ParameterTable.h): its property
// name, GUI label, unit, range, default (the SPHParameters member's own) and a one-line
// description. The Core's validation, SPH Step's and the Rain filter's checks and the docs'
// property table come from here, and a test holds the plugin XML's domains, defaults and labels
// to it.
#include "parafluid/common/ParameterTable.h"
#include "parafluid/sph/SPHParameters.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace parafluid::sph
{
using ParameterDeclaration = parafluid::ParameterDeclaration<SPHParameters>;

/// The declarations, in the order of SPH Step's property panel.
const std::vector<ParameterDeclaration>& sphParameterTable();
/// The declaration of the property `name`, or null.
const ParameterDeclaration* findSPHParameter(std::string_view name);
/// Empty when `value` is finite and in the range of `d` (or 0 with zeroAllowed); else one sentence
/// naming the property, the value and its range.
std::string checkParameter(const ParameterDeclaration& d, double value, bool zeroAllowed = false);
/// The same for the parameters `names` of `p` (a filter that exposes only some of them).
std::string checkParameters(const SPHParameters& p, std::initializer_list<std::string_view> names,
                            std::initializer_list<std::string_view> zeroAllowed = {});
/// Empty when every declared parameter of `p` is finite and in its range (or 0 for a property in
/// `zeroAllowed`); else one sentence naming the first that is not, its value and its range.
std::string checkParameterRanges(const SPHParameters& p, std::initializer_list<std::string_view> zeroAllowed = {});
/// The declarations SPH Step offers as the Markdown table of the docs (docs/sph-step.md).
std::string parameterTableMarkdown();
} // namespace parafluid::sph

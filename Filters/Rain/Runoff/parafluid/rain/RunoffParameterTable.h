#pragma once
// The runoff's numeric parameters declared once (parafluid/common/ParameterTable.h): the Runoff
// constructor, the Rain filter and docs/rain.md read them, and a test holds the plugin XML to them.
// The runoff's SPH parameters are SPH Step's (parafluid/sph/SPHParameterTable.h).
#include "parafluid/common/ParameterTable.h"
#include "parafluid/rain/Runoff.h"

#include <vector>

namespace parafluid::rain
{
const std::vector<ParameterDeclaration<RunoffParameters>>& runoffParameterTable();
} // namespace parafluid::rain

#pragma once
// The rain's numeric parameters declared once (parafluid/common/ParameterTable.h):
// RainParameters::validate, the Rain filter and docs/rain.md read them, and a test holds the
// plugin XML to them.
#include "parafluid/common/ParameterTable.h"
#include "parafluid/rain/RainParameters.h"

#include <vector>

namespace parafluid::rain
{
const std::vector<ParameterDeclaration<RainParameters>>& rainParameterTable();
} // namespace parafluid::rain

#pragma once
// The sea's numeric settings declared once (parafluid/common/ParameterTable.h): SeaSettings::validate,
// the Gerstner Ocean source and representation and docs/gerstner-ocean.md read them, and a test
// holds the plugin XML to them.
#include "parafluid/common/ParameterTable.h"
#include "parafluid/ocean/SeaSettings.h"

#include <vector>

namespace parafluid::ocean
{
const std::vector<ParameterDeclaration<SeaSettings>>& seaParameterTable();
} // namespace parafluid::ocean

#pragma once
// Stable Fluids' numeric parameters declared once (parafluid/common/ParameterTable.h): the source's
// checks and docs/stable-fluids.md read them, and a test holds the plugin XML to them.
#include "parafluid/clouds/StableFluids.h"
#include "parafluid/common/ParameterTable.h"

#include <vector>

namespace parafluid::clouds
{
/// The Stable Fluids source's defaults: smoke from an emitter box rising through the open top of
/// the box, with vorticity confinement.
StableFluidsParameters sourceDefaults();
const std::vector<ParameterDeclaration<StableFluidsParameters>>& stableFluidsParameterTable();
} // namespace parafluid::clouds

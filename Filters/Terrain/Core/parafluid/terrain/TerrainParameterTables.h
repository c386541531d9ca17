#pragma once
// The terrain's numeric settings declared once (parafluid/common/ParameterTable.h): the settings'
// problem() checks and docs/terrain.md read them, and a test holds the plugin XML to them.
#include "parafluid/common/ParameterTable.h"
#include "parafluid/terrain/DropletErosion.h"
#include "parafluid/terrain/PipeErosion.h"
#include "parafluid/terrain/TerrainGenerator.h"

#include <vector>

namespace parafluid::terrain
{
/// The Procedural Terrain source's defaults: a landscape a few kilometres across.
TerrainSettings proceduralTerrainDefaults();
const std::vector<ParameterDeclaration<FractalSettings>>& fractalParameterTable();
const std::vector<ParameterDeclaration<TerrainSettings>>& terrainParameterTable();
const std::vector<ParameterDeclaration<DropletSettings>>& dropletParameterTable();
const std::vector<ParameterDeclaration<PipeSettings>>& pipeParameterTable();
} // namespace parafluid::terrain

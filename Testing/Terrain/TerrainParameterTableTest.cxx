// The terrain's setting declarations against their problem() checks, the plugin XML of Procedural
// Terrain and Hydraulic Erosion, and docs/terrain.md.
#include "parafluid/terrain/TerrainParameterTables.h"

#include "PluginXml.h"

#include <gtest/gtest.h>

#include <string>

using namespace parafluid;
using namespace parafluid::terrain;
using namespace parafluid::testing;

TEST(TerrainParameterTable, ProceduralTerrainXmlIsTheDeclarations)
{
  const std::string block = proxyBlock(pluginXml("ParaFluidTerrain.xml"), "ProceduralTerrain");
  expectXmlMatches(fractalParameterTable(), block);
  expectXmlMatches(terrainParameterTable(), block, {}, proceduralTerrainDefaults());
}

TEST(TerrainParameterTable, HydraulicErosionXmlIsTheDeclarations)
{
  const std::string block = proxyBlock(pluginXml("ParaFluidTerrain.xml"), "HydraulicErosion");
  expectXmlMatches(dropletParameterTable(), block);
  expectXmlMatches(pipeParameterTable(), block);
}

TEST(TerrainParameterTable, DocsTablesAreTheDeclarations)
{
  expectDocsTable("terrain.md", markdownTable(fractalParameterTable()), "fractal");
  expectDocsTable("terrain.md", markdownTable(terrainParameterTable(), proceduralTerrainDefaults()), "terrain");
  expectDocsTable("terrain.md", markdownTable(dropletParameterTable()), "droplets");
  expectDocsTable("terrain.md", markdownTable(pipeParameterTable()), "pipes");
}

TEST(TerrainParameterTable, EachSettingsProblemNamesTheDeclaredSettingOutsideItsRange)
{
  EXPECT_EQ(proceduralTerrainDefaults().problem(), "");
  for (const auto& d : fractalParameterTable())
  {
    TerrainSettings s;
    d.set(s.fractal, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(s.problem().rfind(d.name, 0), 0u) << d.name << ": " << s.problem();
  }
  for (const auto& d : terrainParameterTable())
  {
    TerrainSettings s;
    d.set(s, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(s.problem().rfind(d.name, 0), 0u) << d.name << ": " << s.problem();
  }
  for (const auto& d : dropletParameterTable())
  {
    DropletSettings s;
    d.set(s, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(s.problem().rfind(d.name, 0), 0u) << d.name << ": " << s.problem();
  }
  for (const auto& d : pipeParameterTable())
  {
    PipeSettings s;
    d.set(s, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(s.problem().rfind(d.name, 0), 0u) << d.name << ": " << s.problem();
  }
}

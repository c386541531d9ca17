// The sea's setting declarations against SeaSettings::validate, the plugin XML of the Gerstner
// Ocean source and representation, and docs/gerstner-ocean.md.
#include "parafluid/ocean/SeaParameterTable.h"

#include "PluginXml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace parafluid;
using namespace parafluid::ocean;
using namespace parafluid::testing;

TEST(SeaParameterTable, SourceXmlIsTheDeclarations)
{
  expectXmlMatches(seaParameterTable(), proxyBlock(pluginXml("ParaFluidOcean.xml"), "GerstnerOcean"));
}

TEST(SeaParameterTable, RepresentationOffersSettingsWithinTheDeclarations)
{
  // The representation draws the same sea on the GPU: each setting it offers (as Ocean<Name>) lies
  // within the declared range with the declared default.
  const std::string block = proxyBlock(pluginXml("ParaFluidOceanRepresentation.xml"), "GerstnerOceanRepresentation");
  ASSERT_FALSE(block.empty());
  EXPECT_GE(expectXmlWithin(seaParameterTable(), block, "Ocean"), 5);
}

TEST(SeaParameterTable, DocsTableIsTheDeclarations)
{
  expectDocsTable("gerstner-ocean.md", markdownTable(seaParameterTable()));
}

TEST(SeaParameterTable, ValidateRefusesEachDeclaredSettingByName)
{
  for (const auto& d : seaParameterTable())
  {
    EXPECT_EQ(SeaSettings{}.validate(), "");
    for (double bad :
         { d.minimum - 1.0 - std::fabs(d.minimum), 2.0 * d.maximum + 1.0, std::numeric_limits<double>::quiet_NaN() })
    {
      if (d.isInteger() && std::isnan(bad))
      {
        continue;
      }
      SeaSettings s;
      d.set(s, bad);
      EXPECT_EQ(s.validate().rfind(d.name, 0), 0u) << d.name << " = " << bad << ": " << s.validate();
    }
  }
}

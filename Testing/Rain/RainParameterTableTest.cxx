// The rain's and the runoff's parameter declarations against their Core checks, the plugin XML
// and docs/rain.md.
#include "parafluid/rain/RainParameterTable.h"
#include "parafluid/rain/RunoffParameterTable.h"

#include "PluginXml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace parafluid;
using namespace parafluid::rain;
using parafluid::testing::expectDocsTable;
using parafluid::testing::expectXmlMatches;
using parafluid::testing::pluginXml;
using parafluid::testing::proxyBlock;

TEST(RainParameterTable, RainXmlIsTheDeclarations)
{
  const std::string block = proxyBlock(pluginXml("ParaFluidRain.xml"), "Rain");
  expectXmlMatches(rainParameterTable(), block);
  expectXmlMatches(runoffParameterTable(), block);
}

TEST(RainParameterTable, DocsTablesAreTheDeclarations)
{
  expectDocsTable("rain.md", markdownTable(rainParameterTable()), "rain");
  expectDocsTable("rain.md", markdownTable(runoffParameterTable()), "runoff");
}

TEST(RainParameterTable, TheCoreRefusesEachDeclaredParameterByName)
{
  for (const auto& d : rainParameterTable())
  {
    EXPECT_EQ(checkNumber(d.name, d.unit, d.minimum, d.maximum, d.defaultValue()), "") << d.name;
    for (double bad :
         { d.minimum - 1.0 - std::fabs(d.minimum), 2.0 * d.maximum + 1.0, std::numeric_limits<double>::quiet_NaN() })
    {
      RainParameters p;
      d.set(p, bad);
      EXPECT_EQ(p.validate().rfind(d.name, 0), 0u) << d.name << " = " << bad << ": " << p.validate();
    }
  }
  for (const auto& d : runoffParameterTable())
  {
    EXPECT_EQ(checkNumber(d.name, d.unit, d.minimum, d.maximum, d.defaultValue()), "") << d.name;
    RunoffParameters p;
    d.set(p, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(checkDeclared(runoffParameterTable(), p).rfind(d.name, 0), 0u) << d.name;
  }
}

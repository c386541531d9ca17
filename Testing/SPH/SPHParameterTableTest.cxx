// The SPH parameter declarations against the Core's validation, the plugin XML (domains, defaults,
// labels, units) and the docs' property table.
#include "parafluid/sph/SPHParameterTable.h"

#include "PluginXml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace
{
using namespace parafluid::sph;
using namespace parafluid::testing;

} // namespace

TEST(SPHParameterTable, DeclarationsAreDistinctAndTheirDefaultsValid)
{
  std::set<std::string> names;
  for (const ParameterDeclaration& d : sphParameterTable())
  {
    EXPECT_TRUE(names.insert(d.name).second) << d.name;
    EXPECT_EQ((d.real != nullptr) + (d.real64 != nullptr) + (d.integer != nullptr) + (d.integer64 != nullptr), 1)
      << d.name << " names exactly one field";
    EXPECT_LT(d.minimum, d.maximum) << d.name;
    EXPECT_GT(std::string(d.doc).size(), 10u) << d.name;
    EXPECT_EQ(findSPHParameter(d.name), &d);
    // The Core's default lies in the range, except where SPH Step's 0 asks for a value from the input.
    EXPECT_EQ(checkParameter(d, d.defaultValue(), d.zeroMeans != nullptr), "") << d.name;
  }
  EXPECT_EQ(findSPHParameter("NoSuchProperty"), nullptr);
}

TEST(SPHParameterTable, ValidationRefusesEachParameterByNameOutsideItsRange)
{
  // Every declared parameter, set just outside its range or to NaN, is refused by the Core with a
  // message that names it and its range.
  for (const ParameterDeclaration& d : sphParameterTable())
  {
    for (double bad : { d.minimum - (d.minimum != 0.0 ? 0.5 * std::fabs(d.minimum) : 1.0), 2.0 * d.maximum + 1.0,
                        std::numeric_limits<double>::quiet_NaN() })
    {
      if (d.isInteger() && std::isnan(bad))
      {
        continue;
      }
      SPHParameters p;
      p.particleMass = 1e-3f;
      d.set(p, bad);
      const std::string problem = p.validate();
      EXPECT_EQ(problem.rfind(d.name, 0), 0u) << d.name << " = " << bad << ": " << problem;
      EXPECT_NE(problem.find("from"), std::string::npos) << problem;
    }
  }
}

TEST(SPHParameterTable, SPHStepXmlDomainsDefaultsLabelsAndUnitsAreTheDeclarations)
{
  expectXmlMatches(sphParameterTable(), proxyBlock(pluginXml("ParaFluidSPH.xml"), "SPHStep"));
}

TEST(SPHParameterTable, RainXmlDomainsAreTheDeclarations)
{
  const std::string block = proxyBlock(pluginXml("ParaFluidRain.xml"), "Rain");
  ASSERT_FALSE(block.empty());
  int checked = 0;
  for (const ParameterDeclaration& d : sphParameterTable())
  {
    const XmlProperty x = xmlProperty(block, d.name);
    if (!x.found)
    {
      continue;
    }
    ++checked;
    // The Rain filter's CFLNumber 0 is its automatic choice for the solver.
    EXPECT_EQ(x.minimum, std::string(d.name) == "CFLNumber" ? 0.0 : d.minimum) << d.name;
    EXPECT_EQ(x.maximum, d.maximum) << d.name;
  }
  EXPECT_EQ(checked, 6);
}

TEST(SPHParameterTable, DocsPropertyTableIsTheDeclarations)
{
  expectDocsTable("sph-step.md", parameterTableMarkdown());
}

TEST(SPHParameterTable, AFilterChecksOnlyWhatItOffersAndItsAutomaticZeros)
{
  SPHParameters p;
  p.particleMass = 0.0f; // derived later by the filter
  EXPECT_EQ(checkParameters(p, { "KinematicViscosity", "CFLNumber" }), "");
  p.cflNumber = 0.0f;
  EXPECT_EQ(checkParameters(p, { "CFLNumber" }, { "CFLNumber" }), "");
  EXPECT_EQ(checkParameters(p, { "CFLNumber" }).rfind("CFLNumber = 0", 0), 0u);
  EXPECT_NE(checkParameterRanges(p, { "CFLNumber" }).find("ParticleMass"), std::string::npos);
}

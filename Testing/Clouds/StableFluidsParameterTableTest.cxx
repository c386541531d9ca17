// Stable Fluids' parameter declarations against the plugin XML and docs/stable-fluids.md.
#include "parafluid/clouds/StableFluidsParameterTable.h"

#include "PluginXml.h"

#include <gtest/gtest.h>

#include <string>

using namespace parafluid;
using namespace parafluid::clouds;
using namespace parafluid::testing;

TEST(StableFluidsParameterTable, SourceXmlIsTheDeclarations)
{
  expectXmlMatches(stableFluidsParameterTable(), proxyBlock(pluginXml("ParaFluidClouds.xml"), "StableFluids"), {},
                   sourceDefaults());
}

TEST(StableFluidsParameterTable, DocsTableIsTheDeclarations)
{
  expectDocsTable("stable-fluids.md", markdownTable(stableFluidsParameterTable(), sourceDefaults()));
}

TEST(StableFluidsParameterTable, TheSourcesDefaultsAreValidAndAnyDeclaredValueOutsideIsRefused)
{
  EXPECT_EQ(checkDeclared(stableFluidsParameterTable(), sourceDefaults()), "");
  for (const auto& d : stableFluidsParameterTable())
  {
    StableFluidsParameters p = sourceDefaults();
    d.set(p, 2.0 * d.maximum + 1.0);
    EXPECT_EQ(checkDeclared(stableFluidsParameterTable(), p).rfind(d.name, 0), 0u) << d.name;
  }
}

#pragma once
// Reading a proxy's properties from the plugin XML in Core tests (no ParaView): the tests that
// hold a concern's parameter declarations (parafluid/common/ParameterTable.h) to the XML.
#include "parafluid/common/ParameterTable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace parafluid::testing
{
inline std::string readFile(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The XML of the source or representation proxy `proxy` in `xml`.
inline std::string proxyBlock(const std::string& xml, const std::string& proxy)
{
  const std::size_t at = xml.find("name=\"" + proxy + "\"");
  if (at == std::string::npos)
  {
    return {};
  }
  std::size_t end = std::string::npos;
  for (const char* close : { "</SourceProxy>", "</RepresentationProxy>" })
  {
    end = std::min(end, xml.find(close, at));
  }
  return xml.substr(at, end - at);
}

struct XmlProperty
{
  bool found = false;
  std::string label, defaults, documentation;
  double minimum = std::numeric_limits<double>::quiet_NaN(), maximum = std::numeric_limits<double>::quiet_NaN();
};

inline XmlProperty xmlProperty(const std::string& block, const std::string& name)
{
  XmlProperty p;
  const std::regex element("<(Int|Double)VectorProperty\\s+name=\"" + name +
                           "\"([^>]*)>([\\s\\S]*?)</\\1VectorProperty>");
  std::smatch m;
  if (!std::regex_search(block, m, element))
  {
    return p;
  }
  p.found = true;
  const std::string attributes = m[2], body = m[3];
  std::smatch a;
  if (std::regex_search(attributes, a, std::regex("label=\"([^\"]*)\"")))
  {
    p.label = a[1];
  }
  if (std::regex_search(attributes, a, std::regex("default_values=\"([^\"]*)\"")))
  {
    p.defaults = a[1];
  }
  if (std::regex_search(body, a, std::regex("RangeDomain[^>]*min=\"([^\"]*)\"")))
  {
    p.minimum = std::stod(a[1]);
  }
  if (std::regex_search(body, a, std::regex("RangeDomain[^>]*max=\"([^\"]*)\"")))
  {
    p.maximum = std::stod(a[1]);
  }
  if (std::regex_search(body, a, std::regex("<Documentation>([\\s\\S]*?)</Documentation>")))
  {
    p.documentation = a[1];
  }
  return p;
}

inline std::string withoutSpaces(std::string text)
{
  text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
  return text;
}

/// The plugin XML file `file` (Plugins/ParaFluid/<file>).
inline std::string pluginXml(const std::string& file)
{
  return readFile(std::string(PARAFLUID_PLUGIN_XML_DIR) + "/" + file);
}

/// Every declaration its filter offers is a property of `block` with the declared label (which,
/// without spaces, is pvpython's name: the property's name), range (reaching 0 for those with
/// zeroMeans or in `zeroAllowed`), default (0 for those with zeroMeans) and "[unit]" in its
/// documentation; the others are not in the XML. The defaults are `defaults`' members (the filter's).
template<class Parameters>
void expectXmlMatches(const std::vector<ParameterDeclaration<Parameters>>& table, const std::string& block,
                      const std::set<std::string>& zeroAllowed = {}, const Parameters& defaults = Parameters{})
{
  ASSERT_FALSE(block.empty());
  for (const ParameterDeclaration<Parameters>& d : table)
  {
    const XmlProperty x = xmlProperty(block, d.name);
    if (!d.offeredByFilter)
    {
      EXPECT_FALSE(x.found) << d.name << " is in the XML: it is offered";
      continue;
    }
    ASSERT_TRUE(x.found) << d.name << " is declared but the proxy has no such property";
    EXPECT_EQ(x.label, d.label) << d.name;
    EXPECT_EQ(withoutSpaces(x.label), d.name) << "pvpython's name of a property is its label without spaces";
    // A 0 that means something is the XML's minimum unless the range reaches below it.
    EXPECT_EQ(x.minimum, d.zeroMeans || zeroAllowed.count(d.name) ? std::min(0.0, d.minimum) : d.minimum) << d.name;
    EXPECT_EQ(x.maximum, d.maximum) << d.name;
    // Compared as the float or double the setter stores.
    const double expected = d.zeroMeans ? 0.0 : d.value(defaults);
    if (d.real)
    {
      EXPECT_EQ(static_cast<float>(std::stod(x.defaults)), static_cast<float>(expected)) << d.name;
    }
    else
    {
      EXPECT_EQ(std::stod(x.defaults), expected) << d.name;
    }
    if (*d.unit)
    {
      EXPECT_NE(x.documentation.find(std::string("[") + d.unit), std::string::npos)
        << d.name << "'s tooltip gives its unit [" << d.unit << "]";
    }
  }
}

/// A representation that offers some of the declarations under `prefix` + name: each it has lies
/// within the declared range and has the declared default. Returns how many it has.
template<class Parameters>
int expectXmlWithin(const std::vector<ParameterDeclaration<Parameters>>& table, const std::string& block,
                    const std::string& prefix)
{
  int found = 0;
  for (const ParameterDeclaration<Parameters>& d : table)
  {
    const XmlProperty x = xmlProperty(block, prefix + d.name);
    if (!x.found)
    {
      continue;
    }
    ++found;
    EXPECT_GE(x.minimum, d.minimum) << prefix << d.name;
    EXPECT_LE(x.maximum, d.maximum) << prefix << d.name;
    EXPECT_EQ(std::stod(x.defaults), d.defaultValue()) << prefix << d.name;
  }
  return found;
}

/// The Markdown table between "<!-- <marker>:begin -->" and "<!-- <marker>:end -->" of the docs
/// page `page` (docs/<page>) is `expected`.
inline void expectDocsTable(const std::string& page, const std::string& expected,
                            const std::string& marker = "parameters")
{
  const std::string text = readFile(std::string(PARAFLUID_DOCS_DIR) + "/" + page);
  const std::string begin = "<!-- " + marker + ":begin -->\n", end = "<!-- " + marker + ":end -->";
  const std::size_t from = text.find(begin), to = text.find(end);
  ASSERT_NE(from, std::string::npos) << "docs/" << page << " has no generated table " << marker;
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(text.substr(from + begin.size(), to - from - begin.size()), expected)
    << "docs/" << page << "'s table is out of date; between the markers it should read:\n"
    << expected;
}
} // namespace parafluid::testing

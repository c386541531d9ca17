#pragma once
// A concern's numeric parameters declared once: property name, GUI label, unit, range, default (the
// parameter struct's own member) and a one-line description. A Core's validation, its filter's
// checks and the docs' property tables read the declarations, and each concern's tests hold the
// plugin XML's domains, defaults and labels to them.
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace parafluid
{
template<class Parameters>
struct ParameterDeclaration
{
  const char* name;  // the property's name in the plugin XML and pvpython
  const char* label; // the GUI label (the XML's label attribute)
  const char* unit;  // SI unit as messages and the docs write it ("" for none)
  double minimum;    // the range of a value the Core runs with, inclusive
  double maximum;
  const char* zeroMeans;       // null, or what the filter's default 0 stands for (resolved before the Core)
  const char* doc;             // one line: what it is
  bool offeredByFilter = true; // false: a finer control of the Core its filter leaves at its default
  float Parameters::*real = nullptr;
  double Parameters::*real64 = nullptr;
  int Parameters::*integer = nullptr;
  long long Parameters::*integer64 = nullptr;

  double value(const Parameters& p) const
  {
    if (real)
    {
      return static_cast<double>(p.*real);
    }
    if (real64)
    {
      return p.*real64;
    }
    return integer ? static_cast<double>(p.*integer) : static_cast<double>(p.*integer64);
  }
  double defaultValue() const { return this->value(Parameters{}); }
  bool isInteger() const { return integer != nullptr || integer64 != nullptr; }
  void set(Parameters& p, double v) const
  {
    if (real)
    {
      p.*real = static_cast<float>(v);
    }
    else if (real64)
    {
      p.*real64 = v;
    }
    else if (integer)
    {
      p.*integer = static_cast<int>(v);
    }
    else
    {
      p.*integer64 = static_cast<long long>(v);
    }
  }
};

/// Declarations of a float, double, int or long long member of `Parameters`.
template<class Parameters, class Field>
ParameterDeclaration<Parameters> declare(const char* name, const char* label, const char* unit, double minimum,
                                         double maximum, Field Parameters::*field, const char* doc,
                                         const char* zeroMeans = nullptr)
{
  ParameterDeclaration<Parameters> d{ name, label, unit, minimum, maximum, zeroMeans, doc };
  if constexpr (std::is_same_v<Field, float>)
  {
    d.real = field;
  }
  else if constexpr (std::is_same_v<Field, double>)
  {
    d.real64 = field;
  }
  else if constexpr (std::is_same_v<Field, int>)
  {
    d.integer = field;
  }
  else
  {
    static_assert(std::is_same_v<Field, long long>, "a declared parameter is a float, a double, an int or a long long");
    d.integer64 = field;
  }
  return d;
}

/// The same declaration, not offered by the concern's filter.
template<class Parameters>
ParameterDeclaration<Parameters> coreOnly(ParameterDeclaration<Parameters> d)
{
  d.offeredByFilter = false;
  return d;
}

/// "1e-06", "0.5": a number as messages and the docs write it.
std::string formatNumber(double v);

/// Empty when `value` is finite and in [minimum, maximum] (or 0 with zeroAllowed); else one
/// sentence naming the property, the value and its range.
std::string checkNumber(const char* name, const char* unit, double minimum, double maximum, double value,
                        bool zeroAllowed = false, const char* zeroMeans = nullptr);

/// The first problem of the declared parameters of `p` named in `names` (all of them when `names`
/// is empty), with 0 allowed for those in `zeroAllowed`; empty when there is none.
template<class Parameters>
std::string checkDeclared(const std::vector<ParameterDeclaration<Parameters>>& table, const Parameters& p,
                          std::initializer_list<std::string_view> names = {},
                          std::initializer_list<std::string_view> zeroAllowed = {})
{
  auto listed = [](std::initializer_list<std::string_view> list, const char* name)
  {
    for (std::string_view n : list)
    {
      if (n == name)
      {
        return true;
      }
    }
    return false;
  };
  for (const ParameterDeclaration<Parameters>& d : table)
  {
    if (names.size() > 0 && !listed(names, d.name))
    {
      continue;
    }
    const std::string problem =
      checkNumber(d.name, d.unit, d.minimum, d.maximum, d.value(p), listed(zeroAllowed, d.name), d.zeroMeans);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return {};
}

/// The declarations a filter offers as a Markdown table for the docs: property, unit, range,
/// default (the member's in `defaults`) and description.
template<class Parameters>
std::string markdownTable(const std::vector<ParameterDeclaration<Parameters>>& table,
                          const Parameters& defaults = Parameters{})
{
  std::string md = "| property | unit | range | default | what it is |\n|---|---|---|---|---|\n";
  for (const ParameterDeclaration<Parameters>& d : table)
  {
    if (!d.offeredByFilter)
    {
      continue;
    }
    md += std::string("| `") + d.name + "` | " + (*d.unit ? d.unit : "–") + " | " + formatNumber(d.minimum) + " to " +
          formatNumber(d.maximum) + (d.zeroMeans ? std::string(", or 0: ") + d.zeroMeans : std::string()) + " | " +
          formatNumber(d.zeroMeans ? 0.0 : d.value(defaults)) + " | " + d.doc + " |\n";
  }
  return md;
}
} // namespace parafluid

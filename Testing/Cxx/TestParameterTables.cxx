// SPDX-License-Identifier: BSD-3-Clause
// Each registered filter's settings are listed once, in its core parameters' table (ForEach): the
// plugin's XML gives each of them as a property of the filter's proxy with the core's default and,
// where it has a range, the table's range; SetSettingByName knows each name, and no other; and
// the documentation of each setting's property, the filter's own or a common one, begins with
// the setting's line of help.
#include "MeshSimplificationFilters.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include "TestBadInput.h"

#include <cstdlib>
#include <sstream>
#include <string>

namespace
{
/// The element of the proxy's property of that name, or nullptr.
vtkXMLDataElement* Property(vtkXMLDataElement* proxy, const char* name)
{
  for (int i = 0; proxy && i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = proxy->GetNestedElement(i);
    const char* property = element->GetAttribute("name");
    if (property && std::string(property) == name && std::string(element->GetName()).find("Property") != std::string::npos)
    {
      return element;
    }
  }
  return nullptr;
}

/// The range a property's domain allows: [min, max] of a range domain (a missing bound stays
/// as it is), [0, 1] of a boolean, the smallest and largest value of an enumeration.
void DomainRange(vtkXMLDataElement* property, double& minimum, double& maximum)
{
  for (int i = 0; i < property->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* domain = property->GetNestedElement(i);
    const std::string kind = domain->GetName();
    if (kind == "DoubleRangeDomain" || kind == "IntRangeDomain")
    {
      domain->GetScalarAttribute("min", minimum);
      domain->GetScalarAttribute("max", maximum);
    }
    else if (kind == "BooleanDomain")
    {
      minimum = 0.0;
      maximum = 1.0;
    }
    else if (kind == "EnumerationDomain")
    {
      minimum = 1e300;
      maximum = -1e300;
      for (int e = 0; e < domain->GetNumberOfNestedElements(); ++e)
      {
        double value = 0.0;
        domain->GetNestedElement(e)->GetScalarAttribute("value", value);
        minimum = std::min(minimum, value);
        maximum = std::max(maximum, value);
      }
    }
  }
}

/// The proxy of that name in the plugin's XML file (parsed by parser), or nullptr.
vtkXMLDataElement* Proxy(vtkXMLDataParser* parser, const char* file, const char* proxyName)
{
  parser->SetFileName((std::string(MESHSIMPLIFICATION_PLUGIN_XML) + "/" + file).c_str());
  CHECK(parser->Parse() == 1);
  vtkXMLDataElement* group = parser->GetRootElement() ? parser->GetRootElement()->FindNestedElementWithName("ProxyGroup") : nullptr;
  return group ? group->FindNestedElementWithNameAndAttribute("SourceProxy", "name", proxyName) : nullptr;
}

/// A property's documentation with its runs of white space made single spaces.
std::string Documentation(vtkXMLDataElement* property)
{
  vtkXMLDataElement* documentation = property ? property->FindNestedElementWithName("Documentation") : nullptr;
  std::string text, word;
  std::istringstream words(documentation && documentation->GetCharacterData() ? documentation->GetCharacterData() : "");
  while (words >> word)
  {
    text += (text.empty() ? "" : " ") + word;
  }
  return text;
}

void CheckHelp(const char* file, const char* proxyName, vtkMeshSimplificationFilter* filter)
{
  vtkNew<vtkXMLDataParser> own, common;
  vtkXMLDataElement* proxy = Proxy(own, file, proxyName);
  vtkXMLDataElement* base = Proxy(common, "MeshSimplificationFilter.xml", "MeshSimplificationFilter");
  int settings = 0;
  filter->ForEachSetting([&](const meshsimp::SettingEntry& entry) {
    ++settings;
    vtkXMLDataElement* property = Property(proxy, entry.Name);
    const std::string documentation = Documentation(property ? property : Property(base, entry.Name));
    if (documentation.compare(0, std::string(entry.Help).size(), entry.Help) != 0)
    {
      std::printf("%s %s: the documentation does not begin with the help line\n  %s\n  %s\n", proxyName, entry.Name,
        documentation.c_str(), entry.Help);
      CHECK(false);
    }
  });
  CHECK(settings > 6);
}

template <class Table>
void CheckTable(const char* file, const char* proxyName, vtkMeshSimplificationFilter* filter)
{
  vtkNew<vtkXMLDataParser> parser;
  vtkXMLDataElement* proxy = Proxy(parser, file, proxyName);
  CHECK(proxy != nullptr);
  const Table defaults{};
  Table::ForEach(defaults, [&](const char* name, const auto& member, double minimum, double maximum, const char*) {
    vtkXMLDataElement* property = Property(proxy, name);
    double xmlDefault = -1e300;
    if (!property || !property->GetScalarAttribute("default_values", xmlDefault) ||
      xmlDefault != meshsimp::AsNumber(member))
    {
      std::printf("%s %s: the plugin's default %g, the core's %g\n", proxyName, name, xmlDefault, meshsimp::AsNumber(member));
      CHECK(false);
      return;
    }
    double xmlMinimum = minimum, xmlMaximum = maximum;
    DomainRange(property, xmlMinimum, xmlMaximum);
    if (xmlMinimum != minimum || xmlMaximum != maximum)
    {
      std::printf("%s %s: the plugin's range [%g, %g], the table's [%g, %g]\n", proxyName, name, xmlMinimum,
        xmlMaximum, minimum, maximum);
      CHECK(false);
    }
    CHECK(filter->SetSettingByName(name, meshsimp::AsNumber(member)));
  });
  CHECK(!filter->SetSettingByName("NoSuchSetting", 1.0));
}
}

int TestParameterTables(int, char*[])
{
#define MESHSIMPLIFICATION_CHECK(name, method, parameters, tolerance, blends, alias)                \
  CheckTable<meshsimp::parameters>(#name ".xml", #name, vtkSmartPointer<vtk##name>::New());           \
  CheckHelp(#name ".xml", #name, vtkSmartPointer<vtk##name>::New());
  MESHSIMPLIFICATION_FILTERS(MESHSIMPLIFICATION_CHECK)
#undef MESHSIMPLIFICATION_CHECK
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The parameter table against its readers: the ParaView XML (names, commands, property types,
// defaults, ranges, enumeration entries; besides, the box widget's properties), the filter
// (defaults and clamps) and the colouring registry (choice names). Argument: the server-manager
// XML file.
#include "AdaptationOptions.h"
#include "Coloring/PartitionColoring.h"
#include "FilterTestSupport.h"

#include "vtkNew.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

namespace
{

using cgmesh::ParameterKind;
using cgmesh::ParameterSpec;

const char* propertyTag(ParameterKind kind)
{
  switch (kind)
  {
    case ParameterKind::Real:
      return "DoubleVectorProperty";
    case ParameterKind::Count:
      return "IdTypeVectorProperty";
    case ParameterKind::Text:
      return "StringVectorProperty";
    default:
      return "IntVectorProperty";
  }
}

// The largest value of a kind: a table maximum at this limit has no max in the XML.
double naturalMaximum(ParameterKind kind)
{
  switch (kind)
  {
    case ParameterKind::Integer:
      return 2147483647.0;
    default:
      return cgmesh::Unbounded;
  }
}

vtkXMLDataElement* childWithTagSuffix(vtkXMLDataElement* element, const std::string& suffix)
{
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    const std::string tag = element->GetNestedElement(i)->GetName();
    if (tag.size() >= suffix.size() &&
      tag.compare(tag.size() - suffix.size(), suffix.size(), suffix) == 0)
    {
      return element->GetNestedElement(i);
    }
  }
  return nullptr;
}

void checkRange(const ParameterSpec& spec, vtkXMLDataElement* property)
{
  vtkXMLDataElement* range = childWithTagSuffix(property, "RangeDomain");
  CGMESH_CHECK(range != nullptr, spec.name << ": no range domain in the XML");
  if (!range)
  {
    return;
  }
  const char* minimum = range->GetAttribute("min");
  CGMESH_CHECK(minimum && std::atof(minimum) == spec.minimum,
    spec.name << ": XML min " << (minimum ? minimum : "(none)") << ", table " << spec.minimum);
  const char* maximum = range->GetAttribute("max");
  const bool bounded = spec.maximum < naturalMaximum(spec.kind);
  CGMESH_CHECK(
    (maximum != nullptr) == bounded, spec.name << ": XML max and table maximum disagree");
  if (maximum && bounded)
  {
    CGMESH_CHECK(std::atof(maximum) == spec.maximum,
      spec.name << ": XML max " << maximum << ", table " << spec.maximum);
  }
}

void checkDefault(const ParameterSpec& spec, vtkXMLDataElement* property)
{
  const char* text = property->GetAttribute("default_values");
  const bool arrayName = property->FindNestedElementWithName("ArrayListDomain") != nullptr;
  if (spec.kind == ParameterKind::Text && !arrayName && !spec.defaultText[0])
  {
    // A free text whose default is empty: ParaView's default too, so the XML gives none.
    CGMESH_CHECK(!text || !text[0], spec.name << ": XML default " << text << ", table empty");
    return;
  }
  CGMESH_CHECK(text != nullptr, spec.name << ": no default_values in the XML");
  if (!text)
  {
    return;
  }
  if (spec.kind == ParameterKind::Text)
  {
    // "None" is ParaView's "no array" entry: an array name's empty default.
    const std::string expected = spec.defaultText[0] ? spec.defaultText : "None";
    CGMESH_CHECK(expected == text, spec.name << ": XML default " << text);
    return;
  }
  CGMESH_CHECK(std::atof(text) == spec.defaultValue,
    spec.name << ": XML default " << text << ", table " << spec.defaultValue);
}

void checkDomain(const ParameterSpec& spec, vtkXMLDataElement* property)
{
  if (spec.kind == ParameterKind::Choice)
  {
    vtkXMLDataElement* enumeration = property->FindNestedElementWithName("EnumerationDomain");
    CGMESH_CHECK(enumeration != nullptr, spec.name << ": no enumeration domain");
    if (!enumeration)
    {
      return;
    }
    CGMESH_CHECK(enumeration->GetNumberOfNestedElements() == static_cast<int>(spec.choices.size()),
      spec.name << ": XML entries and table choices differ in number");
    for (int i = 0; i < enumeration->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* entry = enumeration->GetNestedElement(i);
      const int value = std::atoi(entry->GetAttribute("value"));
      const std::string label = entry->GetAttribute("text");
      CGMESH_CHECK(
        value == i && i < static_cast<int>(spec.choices.size()) && label == spec.choices[i].label,
        spec.name << ": XML entry " << value << " '" << label << "'");
    }
  }
  else if (spec.kind == ParameterKind::Boolean)
  {
    CGMESH_CHECK(property->FindNestedElementWithName("BooleanDomain") != nullptr,
      spec.name << ": no boolean domain");
  }
  else if (spec.kind == ParameterKind::Count)
  {
    // ParaView 5.11 has no range domain for IdType properties (an IdTypeRangeDomain element is
    // an error on every plugin load); the filter's setter clamps to the table's range instead.
    CGMESH_CHECK(childWithTagSuffix(property, "RangeDomain") == nullptr,
      spec.name << ": a range domain on an IdType property, which ParaView 5.11 cannot create");
  }
  else if (spec.kind != ParameterKind::Text)
  {
    checkRange(spec, property);
  }
}

// The first element below `element` whose name attribute is `name`.
vtkXMLDataElement* findNamed(vtkXMLDataElement* element, const std::string& name)
{
  const char* attribute = element->GetAttribute("name");
  if (attribute && name == attribute)
  {
    return element;
  }
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    if (vtkXMLDataElement* found = findNamed(element->GetNestedElement(i), name))
    {
      return found;
    }
  }
  return nullptr;
}

// The box widget's properties, which only the GUI and scripts set (the command line has
// --refine-box): a switch and two 3-vectors, the vectors shown by ParaView's InteractiveBox
// widget as its Position and Scale. They are taken out of `properties`, which then holds the
// table's.
void checkBoxWidget(vtkXMLDataElement* proxy, std::map<std::string, vtkXMLDataElement*>& properties)
{
  const struct
  {
    const char* name;
    const char* tag;
    int elements;
    const char* defaults;
    const char* widgetFunction;
  } expected[] = { { "RefinementBoxEnabled", "IntVectorProperty", 1, "0", nullptr },
    { "RefinementBoxOrigin", "DoubleVectorProperty", 3, "0 0 0", "Position" },
    { "RefinementBoxLength", "DoubleVectorProperty", 3, "1 1 1", "Scale" } };
  vtkXMLDataElement* widget = nullptr;
  for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = proxy->GetNestedElement(i);
    const char* panel = element->GetAttribute("panel_widget");
    widget = panel && std::string(panel) == "InteractiveBox" ? element : widget;
  }
  CGMESH_CHECK(widget != nullptr, "no InteractiveBox property group in the XML");
  // With an Input in its group, ParaView's box widget takes Position and Scale relative to the
  // input's bounds (as Transform does) and draws a box the filter does not refine.
  for (int i = 0; widget && i < widget->GetNumberOfNestedElements(); ++i)
  {
    const char* function = widget->GetNestedElement(i)->GetAttribute("function");
    CGMESH_CHECK(!function || std::string(function) != "Input",
      "the box widget's group holds Input: the drawn box would be relative to the input's bounds");
  }
  for (const auto& property : expected)
  {
    const auto found = properties.find(property.name);
    CGMESH_CHECK(found != properties.end(), property.name << ": not in the XML");
    if (found == properties.end())
    {
      continue;
    }
    vtkXMLDataElement* element = found->second;
    int elements = 0;
    element->GetScalarAttribute("number_of_elements", elements);
    const char* defaults = element->GetAttribute("default_values");
    CGMESH_CHECK(std::string(element->GetName()) == property.tag && elements == property.elements &&
        defaults && std::string(defaults) == property.defaults,
      property.name << ": " << element->GetName() << " of " << elements << " elements, default "
                    << (defaults ? defaults : "(none)"));
    CGMESH_CHECK(
      std::string(element->GetAttribute("command")) == "Set" + std::string(property.name),
      property.name << ": XML command " << element->GetAttribute("command"));
    if (property.widgetFunction && widget)
    {
      bool linked = false;
      for (int i = 0; i < widget->GetNumberOfNestedElements(); ++i)
      {
        const char* name = widget->GetNestedElement(i)->GetAttribute("name");
        const char* function = widget->GetNestedElement(i)->GetAttribute("function");
        linked = linked ||
          (name && function && std::string(name) == property.name &&
            std::string(function) == property.widgetFunction);
      }
      CGMESH_CHECK(linked, property.name << ": not the box widget's " << property.widgetFunction);
    }
    properties.erase(found);
  }
}

void checkXml(const char* fileName)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(fileName);
  CGMESH_CHECK(parser->Parse() == 1, "cannot parse " << fileName);
  vtkXMLDataElement* root = parser->GetRootElement();
  vtkXMLDataElement* proxy = root ? findNamed(root, "CoarseGrainedMeshAdaptation") : nullptr;
  CGMESH_CHECK(proxy != nullptr, "no CoarseGrainedMeshAdaptation proxy in " << fileName);
  if (!proxy)
  {
    return;
  }
  std::map<std::string, vtkXMLDataElement*> properties;
  for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = proxy->GetNestedElement(i);
    const char* command = element->GetAttribute("command");
    if (element->GetAttribute("name") && command && std::string(command) != "SetInputConnection")
    {
      properties[element->GetAttribute("name")] = element;
    }
  }
  checkBoxWidget(proxy, properties);
  CGMESH_CHECK(properties.size() == cgmesh::parameterTable().size(),
    "the XML has " << properties.size() << " parameter properties, the table "
                   << cgmesh::parameterTable().size());
  for (const ParameterSpec& spec : cgmesh::parameterTable())
  {
    const auto found = properties.find(spec.name);
    CGMESH_CHECK(found != properties.end(), spec.name << ": not in the XML");
    if (found == properties.end())
    {
      continue;
    }
    vtkXMLDataElement* property = found->second;
    CGMESH_CHECK(std::string(property->GetName()) == propertyTag(spec.kind),
      spec.name << ": XML " << property->GetName() << ", expected " << propertyTag(spec.kind));
    CGMESH_CHECK(std::string(property->GetAttribute("command")) == "Set" + std::string(spec.name),
      spec.name << ": XML command " << property->GetAttribute("command"));
    checkDefault(spec, property);
    checkDomain(spec, property);
  }
}

void checkFilterDefaultsAndClamps()
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  for (const ParameterSpec& spec : cgmesh::parameterTable())
  {
    if (spec.kind == ParameterKind::Text)
    {
      CGMESH_CHECK(filter->GetParameterText(spec.name) == nullptr, spec.name << ": set by default");
      continue;
    }
    CGMESH_CHECK(filter->GetParameterValue(spec.name) == spec.defaultValue,
      spec.name << ": filter default " << filter->GetParameterValue(spec.name));
    filter->SetParameterValue(spec.name, spec.minimum - 1);
    CGMESH_CHECK(
      filter->GetParameterValue(spec.name) == spec.minimum, spec.name << ": not clamped up");
    if (std::isfinite(spec.maximum))
    {
      filter->SetParameterValue(spec.name, spec.maximum + 1);
      CGMESH_CHECK(
        filter->GetParameterValue(spec.name) == spec.maximum, spec.name << ": not clamped down");
    }
  }
  // The typed setters go through the same table.
  filter->SetNumberOfImprovementPasses(50);
  CGMESH_CHECK(filter->GetNumberOfImprovementPasses() == 20, "passes not clamped to 20");
  filter->SetEdgeLengthFactor(0.3);
  CGMESH_CHECK(filter->GetEdgeLengthFactor() == 0.3, "EdgeLengthFactor not stored");
  filter->SetRegionArrayName("Material");
  CGMESH_CHECK(std::string(filter->GetRegionArrayName()) == "Material", "region array not stored");
}

void checkColoringNames()
{
  const auto& choices = cgmesh::findParameter("ColoringAlgorithm")->choices;
  const std::vector<std::string> registered = cgmesh::coloringNames();
  CGMESH_CHECK(choices.size() == registered.size(), "colourings: table and registry differ");
  for (std::size_t i = 0; i < choices.size() && i < registered.size(); ++i)
  {
    CGMESH_CHECK(registered[i] == choices[i].name, "colouring " << i << ": " << registered[i]);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestParameterTable CoarseGrainedMeshAdaptation.xml\n";
    return 2;
  }
  checkXml(argv[1]);
  checkFilterDefaultsAndClamps();
  checkColoringNames();
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << cgmesh::parameterTable().size() << " parameters: XML, filter and registry agree\n";
  return EXIT_SUCCESS;
}

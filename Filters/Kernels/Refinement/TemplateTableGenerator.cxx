// Build step: searches the refinement templates (TemplateTable) and writes them as the C++ source
// of compiledTemplateData(), so that a run reads them instead of searching at start-up.
// Usage: TemplateTableGenerator OUTPUT.cxx
#include "Refinement/TemplateTable.h"

#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: TemplateTableGenerator OUTPUT.cxx\n";
    return 2;
  }
  const cgmesh::TemplateTable table;
  if (!table.status().ok())
  {
    std::cerr << "TemplateTableGenerator: " << table.status().message() << "\n";
    return 1;
  }
  const std::vector<std::array<int, 4>> orders = cgmesh::TemplateTable::rankOrders();

  std::ofstream out(argv[1]);
  out << "// Written by TemplateTableGenerator at build time; not to be edited.\n"
      << "#include \"Refinement/TemplateTable.h\"\n\nnamespace cgmesh\n{\nnamespace\n{\n\n"
      << "constexpr std::uint32_t Offsets[TemplateData::Entries + 1] = {";
  std::uint32_t offset = 0;
  std::vector<cgmesh::LocalTet> all;
  for (int mask = 1; mask < 63; ++mask)
  {
    for (const auto& order : orders)
    {
      out << ((mask == 1 && order == orders.front()) ? " " : ", ") << offset;
      const auto& tets = table.partialSplit(mask, order);
      all.insert(all.end(), tets.begin(), tets.end());
      offset += static_cast<std::uint32_t>(tets.size());
    }
  }
  out << ", " << offset << " };\n\nconstexpr std::uint8_t Corners[] = {";
  for (std::size_t t = 0; t < all.size(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      out << ((t == 0 && k == 0) ? " " : ", ") << static_cast<int>(all[t][k]);
    }
  }
  out << " };\n\n} // namespace\n\nTemplateData compiledTemplateData()\n{\n"
      << "  return { Offsets, Corners };\n}\n\n} // namespace cgmesh\n";
  if (!out)
  {
    std::cerr << "TemplateTableGenerator: could not write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}

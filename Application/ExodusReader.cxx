// Exodus II files in (see ExodusFiles.h).
#include "ExodusFiles.h"

#include "ExodusLibrary.h"
#include "FileTags.h"
#include "QuietStream.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace cgmesh
{

namespace
{

using namespace exodus;

// True for TETRA, TETRA4, TET4, tetra...: the spellings of the linear tetrahedron.
bool isLinearTetrahedron(const char* topology, std::int64_t nodesPerElement)
{
  return lowerCase(topology).rfind("tet", 0) == 0 && nodesPerElement == 4;
}

std::vector<std::int64_t> entityIds(int file, ex_entity_type type, std::int64_t count)
{
  std::vector<std::int64_t> ids(static_cast<std::size_t>(count));
  if (count > 0 && ex_get_ids(file, type, ids.data()) < 0)
    ids.clear();
  return ids;
}

// The names of `count` entities of `type`; empty strings where the file has none.
std::vector<std::string> entityNames(int file, ex_entity_type type, std::int64_t count)
{
  std::vector<std::vector<char>> storage(
    static_cast<std::size_t>(count), std::vector<char>(MaximumNameLength + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& name : storage)
    pointers.push_back(name.data());
  std::vector<std::string> names(static_cast<std::size_t>(count));
  if (count > 0 && ex_get_names(file, type, pointers.data()) >= 0)
    for (std::size_t k = 0; k < names.size(); ++k)
      names[k] = storage[k].data();
  return names;
}

bool fitsInt(std::int64_t value)
{
  return value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
}

Status readBlocks(int file, const ex_init_params& init, vtkUnstructuredGrid* grid,
  vtkIntArray* tags, MeshFileNames* names)
{
  const std::vector<std::int64_t> ids = entityIds(file, EX_ELEM_BLOCK, init.num_elem_blk);
  const std::vector<std::string> blockNames = entityNames(file, EX_ELEM_BLOCK, init.num_elem_blk);
  if (static_cast<std::int64_t>(ids.size()) != init.num_elem_blk)
    return Status::failure("its element block ids cannot be read: " + exodusError("unknown error"));
  for (std::size_t b = 0; b < ids.size(); ++b)
  {
    ex_block block{};
    block.id = ids[b];
    block.type = EX_ELEM_BLOCK;
    if (ex_get_block_param(file, &block) < 0)
      return Status::failure("element block " + std::to_string(ids[b]) +
        " cannot be read: " + exodusError("unknown error"));
    if (block.num_entry == 0)
      continue;
    if (!isLinearTetrahedron(block.topology, block.num_nodes_per_entry))
      return Status::failure("element block " + std::to_string(ids[b]) + " holds " +
        std::to_string(block.num_entry) + " " + block.topology + " elements of " +
        std::to_string(block.num_nodes_per_entry) +
        " nodes, which cgmesh does not refine: it takes linear tetrahedra (TETRA, 4 nodes), "
        "with side sets tagging their faces");
    if (!fitsInt(ids[b]))
      return Status::failure(
        "element block id " + std::to_string(ids[b]) + " is beyond the range of a Tag");
    std::vector<std::int64_t> connectivity(static_cast<std::size_t>(4 * block.num_entry));
    if (ex_get_conn(file, EX_ELEM_BLOCK, ids[b], connectivity.data(), nullptr, nullptr) < 0)
      return Status::failure("the connectivity of element block " + std::to_string(ids[b]) +
        " cannot be read: " + exodusError("unknown error"));
    for (std::int64_t e = 0; e < block.num_entry; ++e)
    {
      vtkIdType corners[4];
      for (int k = 0; k < 4; ++k)
      {
        const std::int64_t node = connectivity[static_cast<std::size_t>(4 * e + k)];
        if (node < 1 || node > init.num_nodes)
          return Status::failure("element " + std::to_string(e + 1) + " of block " +
            std::to_string(ids[b]) + " names node " + std::to_string(node) +
            ", which does not exist");
        corners[k] = static_cast<vtkIdType>(node - 1);
      }
      grid->InsertNextCell(VTK_TETRA, 4, corners);
      tags->InsertNextValue(static_cast<int>(ids[b]));
    }
    if (names && !blockNames[b].empty())
      names->physicalNames[{ 3, static_cast<int>(ids[b]) }] = blockNames[b];
  }
  return Status::success();
}

// One side or node set as the file holds it.
struct ExodusSet
{
  std::int64_t id = 0;
  std::string name;
  std::vector<std::int64_t> entries; // element numbers (side sets) or node numbers, from 1
  std::vector<std::int64_t> sides;   // side sets: the side of each element, from 1
};

// Every set of `type` (EX_SIDE_SET or EX_NODE_SET, called `what` in messages), in file order.
Status readSets(int file, ex_entity_type type, std::int64_t count, const std::string& what,
  std::vector<ExodusSet>& sets)
{
  const std::vector<std::int64_t> ids = entityIds(file, type, count);
  const std::vector<std::string> names = entityNames(file, type, count);
  if (static_cast<std::int64_t>(ids.size()) != count)
    return Status::failure("its " + what + " ids cannot be read: " + exodusError("unknown error"));
  for (std::size_t s = 0; s < ids.size(); ++s)
  {
    const std::string set = what + " " + std::to_string(ids[s]);
    std::int64_t entries = 0, factors = 0;
    if (ex_get_set_param(file, type, ids[s], &entries, &factors) < 0)
      return Status::failure(set + " cannot be read: " + exodusError("unknown error"));
    if (!fitsInt(ids[s]))
      return Status::failure(set + ": the id is beyond the range of a Tag");
    ExodusSet read;
    read.id = ids[s];
    read.name = names[s];
    read.entries.resize(static_cast<std::size_t>(entries));
    read.sides.resize(type == EX_SIDE_SET ? read.entries.size() : 0);
    if (entries > 0 &&
      ex_get_set(file, type, ids[s], read.entries.data(),
        type == EX_SIDE_SET ? read.sides.data() : nullptr) < 0)
      return Status::failure(set + " cannot be read: " + exodusError("unknown error"));
    sets.push_back(std::move(read));
  }
  return Status::success();
}

// Every side set entry as a triangle: the element's side, in outward order. Elements are numbered
// from 1 in block order, which is the order readBlocks inserted the tetrahedra in.
Status readSideSets(int file, const ex_init_params& init, vtkUnstructuredGrid* grid,
  vtkIntArray* tags, MeshFileNames* names)
{
  std::vector<ExodusSet> sets;
  const Status status = readSets(file, EX_SIDE_SET, init.num_side_sets, "side set", sets);
  if (!status.ok())
    return status;
  const vtkIdType tets = grid->GetNumberOfCells();
  for (const ExodusSet& set : sets)
  {
    for (std::size_t k = 0; k < set.entries.size(); ++k)
    {
      const std::int64_t element = set.entries[k], side = set.sides[k];
      if (element < 1 || element > tets || side < 1 || side > 4)
        return Status::failure("side set " + std::to_string(set.id) + " names side " +
          std::to_string(side) + " of element " + std::to_string(element) +
          ", which does not exist (the mesh has " + std::to_string(tets) +
          " tetrahedra of 4 sides)");
      const vtkIdType* tet;
      vtkIdType count;
      grid->GetCellPoints(static_cast<vtkIdType>(element - 1), count, tet);
      const int* corner = TetSideCorners[side - 1];
      const vtkIdType corners[3] = { tet[corner[0]], tet[corner[1]], tet[corner[2]] };
      grid->InsertNextCell(VTK_TRIANGLE, 3, corners);
      tags->InsertNextValue(static_cast<int>(set.id));
    }
    if (names && !set.name.empty())
      names->physicalNames[{ 2, static_cast<int>(set.id) }] = set.name;
  }
  return Status::success();
}

Status readNodeSets(
  int file, const ex_init_params& init, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  std::vector<ExodusSet> sets;
  const Status status = readSets(file, EX_NODE_SET, init.num_node_sets, "node set", sets);
  if (!status.ok())
    return status;
  for (const ExodusSet& set : sets)
  {
    std::string arrayName = set.name;
    if (arrayName.empty() || grid->GetPointData()->GetAbstractArray(arrayName.c_str()))
      arrayName = "NodeSet" + std::to_string(set.id);
    vtkNew<vtkIntArray> members;
    members->SetName(arrayName.c_str());
    members->SetNumberOfValues(grid->GetNumberOfPoints());
    members->FillValue(0);
    for (const std::int64_t node : set.entries)
    {
      if (node < 1 || node > init.num_nodes)
        return Status::failure("node set " + std::to_string(set.id) + " names node " +
          std::to_string(node) + ", which does not exist (the mesh has " +
          std::to_string(init.num_nodes) + ")");
      members->SetValue(static_cast<vtkIdType>(node - 1), 1);
    }
    grid->GetPointData()->AddArray(members);
    if (names)
      names->nodeSets[arrayName] = static_cast<int>(set.id);
  }
  return Status::success();
}

Status readOpenFile(int file, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  ex_init_params init{};
  if (ex_get_init_ext(file, &init) < 0)
    return Status::failure("its header cannot be read: " + exodusError("unknown error"));
  if (init.num_dim != 3)
    return Status::failure("it holds a " + std::to_string(init.num_dim) +
      "-dimensional mesh; cgmesh refines 3-D tetrahedral meshes");
  const std::int64_t usedNameLength = ex_inquire_int(file, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  ex_set_max_name_length(
    file, static_cast<int>(std::clamp<std::int64_t>(usedNameLength, 32, MaximumNameLength)));

  std::vector<double> x(static_cast<std::size_t>(init.num_nodes));
  std::vector<double> y(x.size()), z(x.size());
  if (init.num_nodes > 0 && ex_get_coord(file, x.data(), y.data(), z.data()) < 0)
    return Status::failure("its coordinates cannot be read: " + exodusError("unknown error"));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(init.num_nodes));
  for (std::size_t p = 0; p < x.size(); ++p)
    points->SetPoint(static_cast<vtkIdType>(p), x[p], y[p], z[p]);
  grid->Initialize();
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(init.num_elem));

  vtkNew<vtkIntArray> tags;
  tags->SetName(TagArrayName);
  Status status = readBlocks(file, init, grid, tags, names);
  if (status.ok())
    status = readSideSets(file, init, grid, tags, names);
  if (status.ok())
    status = readNodeSets(file, init, grid, names);
  if (status.ok())
    grid->GetCellData()->AddArray(tags);
  return status;
}

} // namespace

bool isExodusFileName(const std::string& fileName)
{
  const std::string extension = std::filesystem::path(fileName).extension().string();
  for (const char* known : { ".exo", ".e", ".ex2", ".g", ".gen" })
    if (extension == known)
      return true;
  return false;
}

Status readExodusFile(const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  int computeWordSize = 8, storedWordSize = 0;
  float version = 0.0f;
  const QuietStream quiet(stderr, STDERR_FILENO); // failures are reported in the status
  const ExodusFile file(ex_open(
    fileName.c_str(), EX_READ | EX_ALL_INT64_API, &computeWordSize, &storedWordSize, &version));
  if (file.id() < 0)
    return Status::failure(
      "'" + fileName + "': not an Exodus II file, or libexodus cannot read it");
  const Status status = readOpenFile(file.id(), grid, names);
  return status.ok() ? status : Status::failure("'" + fileName + "': " + status.message());
}

} // namespace cgmesh

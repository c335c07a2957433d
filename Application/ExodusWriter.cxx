// Exodus II files out (see ExodusFiles.h).
#include "ExodusFiles.h"

#include "ExodusLibrary.h"
#include "FileTags.h"
#include "QuietStream.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace cgmesh
{

namespace
{

using namespace exodus;

// A triangle's corners as a key that does not depend on their order.
using FaceKey = std::array<vtkIdType, 3>;
FaceKey faceKey(vtkIdType a, vtkIdType b, vtkIdType c)
{
  FaceKey key{ a, b, c };
  std::sort(key.begin(), key.end());
  return key;
}
struct FaceKeyHash
{
  std::size_t operator()(const FaceKey& key) const
  {
    std::size_t hash = 0;
    for (const vtkIdType id : key)
      hash = hash * 1000003u ^ static_cast<std::size_t>(id);
    return hash;
  }
};

// True when (a, b, c) is (d, e, f) turned: the same corners in the same cyclic order.
bool sameCycle(const vtkIdType* abc, const vtkIdType* def)
{
  for (int turn = 0; turn < 3; ++turn)
    if (abc[0] == def[turn] && abc[1] == def[(turn + 1) % 3] && abc[2] == def[(turn + 2) % 3])
      return true;
  return false;
}

// A side set entry: (element number, side number), both from 1.
struct Side
{
  std::int64_t element;
  std::int64_t side;
};

// What the file holds, gathered from the grid before anything is written.
struct ExodusContent
{
  std::map<int, std::vector<vtkIdType>> blocks;   // id -> tet cells, in grid order
  std::map<int, std::vector<vtkIdType>> sideSets; // id -> triangle cells, in grid order
  std::map<int, std::pair<std::string, vtkDataArray*>> nodeSets; // id -> (name, point array)
  int shift = 0;
};

Status gatherContent(vtkUnstructuredGrid* grid, const WriteOptions& options, ExodusContent& content)
{
  vtkDataArray* tags =
    options.tagArray.empty() ? nullptr : grid->GetCellData()->GetArray(options.tagArray.c_str());
  content.shift = positiveTagShift(tags);
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const int type = grid->GetCellType(cellId);
    if (type != VTK_TETRA && type != VTK_TRIANGLE)
      return Status::failure("cell " + std::to_string(cellId) +
        " is neither a tetrahedron nor a triangle, which is all cgmesh writes to Exodus files");
    const int id = tagValue(tags, cellId, 1) + content.shift;
    (type == VTK_TETRA ? content.blocks : content.sideSets)[id].push_back(cellId);
  }
  if (content.blocks.empty())
    return Status::failure("the mesh has no tetrahedra");

  // Node sets: the arrays a read Exodus file named, then those called NodeSet<id>.
  vtkPointData* pointData = grid->GetPointData();
  std::set<std::string> taken;
  const auto addNodeSet = [&](const std::string& name, int id)
  {
    vtkDataArray* array = pointData->GetArray(name.c_str());
    if (!array || id < 1 || content.nodeSets.count(id) || !taken.insert(name).second)
      return;
    content.nodeSets[id] = { name, array };
  };
  if (options.names)
    for (const auto& [name, id] : options.names->nodeSets)
      addNodeSet(name, id);
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    const char* name = pointData->GetArrayName(a);
    const std::string prefix = "NodeSet";
    if (!name || std::string(name).rfind(prefix, 0) != 0)
      continue;
    const std::string digits = std::string(name).substr(prefix.size());
    if (!digits.empty() && digits.size() < 10 &&
      std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
      addNodeSet(name, std::stoi(digits));
  }
  return Status::success();
}

// Each triangle of each side set as (element, side): the side of a tet that has the triangle's
// corners, preferring the tet the triangle faces out of. `elementOf` numbers the tets (by cell id).
Status findSides(vtkUnstructuredGrid* grid, const ExodusContent& content,
  const std::vector<std::int64_t>& elementOf, std::map<int, std::vector<Side>>& sidesOfSet)
{
  struct Candidate
  {
    vtkIdType tet;
    int side;
  };
  std::unordered_map<FaceKey, std::vector<Candidate>, FaceKeyHash> candidates;
  for (const auto& entry : content.sideSets)
    for (const vtkIdType cellId : entry.second)
    {
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(cellId, count, corners);
      candidates[faceKey(corners[0], corners[1], corners[2])];
    }
  if (candidates.empty())
    return Status::success();
  for (const auto& entry : content.blocks)
    for (const vtkIdType tet : entry.second)
    {
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(tet, count, corners);
      for (int side = 0; side < 4; ++side)
      {
        const int* local = TetSideCorners[side];
        const auto found =
          candidates.find(faceKey(corners[local[0]], corners[local[1]], corners[local[2]]));
        if (found != candidates.end())
          found->second.push_back({ tet, side });
      }
    }

  for (const auto& [id, triangles] : content.sideSets)
  {
    std::vector<Side>& sides = sidesOfSet[id];
    for (const vtkIdType cellId : triangles)
    {
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(cellId, count, corners);
      const std::vector<Candidate>& onFace =
        candidates.at(faceKey(corners[0], corners[1], corners[2]));
      if (onFace.empty())
        return Status::failure("triangle cell " + std::to_string(cellId) +
          " is no face of a tetrahedron, and a side set can only name sides of elements");
      const Candidate* chosen = &onFace.front();
      for (const Candidate& candidate : onFace)
      {
        const vtkIdType* tet;
        vtkIdType tetCount;
        grid->GetCellPoints(candidate.tet, tetCount, tet);
        const int* local = TetSideCorners[candidate.side];
        const vtkIdType side[3] = { tet[local[0]], tet[local[1]], tet[local[2]] };
        if (sameCycle(corners, side))
        {
          chosen = &candidate;
          break;
        }
      }
      sides.push_back({ elementOf[chosen->tet], chosen->side + 1 });
    }
  }
  return Status::success();
}

// The name of block or side set `id` (dimension 3 or 2): what the read file called it, or, when
// ids were shifted, what the tag was.
std::string groupName(const WriteOptions& options, int shift, int dimension, int id)
{
  if (shift != 0)
    return options.tagArray + " " + std::to_string(id - shift);
  if (options.names)
  {
    const auto found = options.names->physicalNames.find({ dimension, id });
    if (found != options.names->physicalNames.end())
      return found->second;
  }
  return std::string();
}

// Entity names made unique across blocks, side sets and node sets, ignoring case: ParaView's IOSS
// reader keys entities by lower-case name, and gave a side set named like a block (a Gmsh volume
// and surface both called "ball") the block's points. A later entity whose name is taken gets
// `suffix` ("surface", "nodes"), then its id too.
class UniqueNames
{
public:
  std::string claim(const std::string& name, const std::string& suffix, int id)
  {
    if (name.empty())
      return name;
    for (const std::string& candidate :
      { name, name + "_" + suffix, name + "_" + suffix + "_" + std::to_string(id) })
    {
      const std::string shortened = candidate.substr(0, MaximumNameLength);
      if (this->Taken.insert(lowerCase(shortened)).second)
        return shortened;
    }
    return std::string(); // unnamed rather than ambiguous
  }

private:
  std::set<std::string> Taken;
};

// ex_put_names wants mutable C strings.
Status putNames(int file, ex_entity_type type, const std::vector<std::string>& names)
{
  if (std::all_of(names.begin(), names.end(), [](const std::string& name) { return name.empty(); }))
    return Status::success();
  std::vector<std::vector<char>> storage;
  std::vector<char*> pointers;
  for (const std::string& name : names)
    storage.emplace_back(name.c_str(), name.c_str() + name.size() + 1);
  for (auto& name : storage)
    pointers.push_back(name.data());
  if (ex_put_names(file, type, pointers.data()) < 0)
    return Status::failure("the names cannot be written: " + exodusError("unknown error"));
  return Status::success();
}

Status writeContent(
  int file, vtkUnstructuredGrid* grid, const ExodusContent& content, const WriteOptions& options)
{
  // Elements are numbered block after block.
  std::vector<std::int64_t> elementOf(static_cast<std::size_t>(grid->GetNumberOfCells()), 0);
  std::int64_t elements = 0;
  for (const auto& entry : content.blocks)
    for (const vtkIdType tet : entry.second)
      elementOf[tet] = ++elements;
  std::map<int, std::vector<Side>> sidesOfSet;
  Status status = findSides(grid, content, elementOf, sidesOfSet);
  if (!status.ok())
    return status;

  ex_init_params init{};
  std::snprintf(init.title, sizeof(init.title), "%s", "cgmesh");
  init.num_dim = 3;
  init.num_nodes = grid->GetNumberOfPoints();
  init.num_elem = elements;
  init.num_elem_blk = static_cast<std::int64_t>(content.blocks.size());
  init.num_side_sets = static_cast<std::int64_t>(content.sideSets.size());
  init.num_node_sets = static_cast<std::int64_t>(content.nodeSets.size());
  if (ex_put_init_ext(file, &init) < 0)
    return Status::failure("the header cannot be written: " + exodusError("unknown error"));

  std::vector<double> x(static_cast<std::size_t>(init.num_nodes));
  std::vector<double> y(x.size()), z(x.size());
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    double point[3];
    grid->GetPoint(p, point);
    x[p] = point[0];
    y[p] = point[1];
    z[p] = point[2];
  }
  char coordinateNames[3][2] = { "x", "y", "z" };
  char* coordinateNamePointers[3] = { coordinateNames[0], coordinateNames[1], coordinateNames[2] };
  if (ex_put_coord(file, x.data(), y.data(), z.data()) < 0 ||
    ex_put_coord_names(file, coordinateNamePointers) < 0)
    return Status::failure("the coordinates cannot be written: " + exodusError("unknown error"));

  UniqueNames unique;
  std::vector<std::string> names;
  for (const auto& [id, tets] : content.blocks)
  {
    std::vector<std::int64_t> connectivity;
    connectivity.reserve(4 * tets.size());
    for (const vtkIdType tet : tets)
    {
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(tet, count, corners);
      for (int k = 0; k < 4; ++k)
        connectivity.push_back(static_cast<std::int64_t>(corners[k]) + 1);
    }
    if (ex_put_block(file, EX_ELEM_BLOCK, id, "TETRA", static_cast<std::int64_t>(tets.size()), 4, 0,
          0, 0) < 0 ||
      ex_put_conn(file, EX_ELEM_BLOCK, id, connectivity.data(), nullptr, nullptr) < 0)
      return Status::failure("element block " + std::to_string(id) +
        " cannot be written: " + exodusError("unknown error"));
    names.push_back(unique.claim(groupName(options, content.shift, 3, id), "block", id));
  }
  status = putNames(file, EX_ELEM_BLOCK, names);
  if (!status.ok())
    return status;

  names.clear();
  for (const auto& [id, sides] : sidesOfSet)
  {
    std::vector<std::int64_t> elementList, sideList;
    for (const Side& side : sides)
    {
      elementList.push_back(side.element);
      sideList.push_back(side.side);
    }
    if (ex_put_set_param(file, EX_SIDE_SET, id, static_cast<std::int64_t>(sides.size()), 0) < 0 ||
      ex_put_set(file, EX_SIDE_SET, id, elementList.data(), sideList.data()) < 0)
      return Status::failure(
        "side set " + std::to_string(id) + " cannot be written: " + exodusError("unknown error"));
    names.push_back(unique.claim(groupName(options, content.shift, 2, id), "surface", id));
  }
  status = putNames(file, EX_SIDE_SET, names);
  if (!status.ok())
    return status;

  names.clear();
  for (const auto& [id, set] : content.nodeSets)
  {
    std::vector<std::int64_t> nodes;
    for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
      if (tagValue(set.second, p) != 0)
        nodes.push_back(static_cast<std::int64_t>(p) + 1);
    if (ex_put_set_param(file, EX_NODE_SET, id, static_cast<std::int64_t>(nodes.size()), 0) < 0 ||
      (!nodes.empty() && ex_put_set(file, EX_NODE_SET, id, nodes.data(), nullptr) < 0))
      return Status::failure(
        "node set " + std::to_string(id) + " cannot be written: " + exodusError("unknown error"));
    names.push_back(unique.claim(set.first, "nodes", id));
  }
  return putNames(file, EX_NODE_SET, names);
}

} // namespace

Status writeExodusFile(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  ExodusContent content;
  Status status = gatherContent(grid, options, content);
  if (!status.ok())
    return status;
  // 64-bit integers in the file only where 32 bits cannot number the nodes or elements, so that
  // older readers keep working on everything smaller. NetCDF-4 (HDF5) storage: through the
  // netCDF classic format, 6.6 M tets took 2 s and some 650,000 small reads, seeks and writes;
  // netCDF-4 takes 1.1 s and a few hundred large writes. Readers built on netCDF 4 (IOSS and
  // ParaView, SEACAS, Cubit, meshio with netCDF4) read both.
  const bool large = grid->GetNumberOfPoints() >= std::numeric_limits<int>::max() ||
    grid->GetNumberOfCells() >= std::numeric_limits<int>::max();
  int computeWordSize = 8, storedWordSize = 8;
  const QuietStream quiet(stderr, STDERR_FILENO);
  ExodusFile file(ex_create(fileName.c_str(),
    EX_CLOBBER | EX_NETCDF4 | EX_ALL_INT64_API | (large ? EX_ALL_INT64_DB : 0), &computeWordSize,
    &storedWordSize));
  if (file.id() < 0)
    return Status::failure("libexodus cannot create it: " + exodusError("unknown error"));
  int longestName = 32;
  if (options.names)
  {
    for (const auto& entry : options.names->physicalNames)
      longestName = std::max(longestName, static_cast<int>(entry.second.size()));
    for (const auto& entry : options.names->nodeSets)
      longestName = std::max(longestName, static_cast<int>(entry.first.size()));
  }
  // Room for the suffixes UniqueNames may add.
  ex_set_max_name_length(file.id(), std::min(longestName + 24, MaximumNameLength));
  status = writeContent(file.id(), grid, content, options);
  if (!file.close() && status.ok())
    status = Status::failure("the file cannot be completed: " + exodusError("unknown error"));
  return status;
}

} // namespace cgmesh

// The Gmsh side of GmshFiles.h, built as a module of its own that the command line loads with
// dlopen(RTLD_LOCAL): libgmsh exports a TetGen of its own (the tetgenmesh class and friends) whose
// layout differs from Debian's libtet, and linked into the executable it took the place of the
// TetGen the Delaunay method and the generators use. Loaded locally, its symbols stay out of the
// executable's lookup scope. Only the two entry points at the end are exported.
#include "GmshFiles.h"

#include "FileTags.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace cgmesh
{

namespace
{

// Gmsh element types and the VTK cells they become: first-order elements of the kinds a tet mesh
// with tags holds.
struct ElementKind
{
  int gmshType;
  int vtkType;
  int dimension;
  int nodes;
};
constexpr ElementKind ElementKinds[] = { { 4, VTK_TETRA, 3, 4 }, { 2, VTK_TRIANGLE, 2, 3 },
  { 1, VTK_LINE, 1, 2 }, { 15, VTK_VERTEX, 0, 1 } };

const ElementKind* kindOfGmshType(int gmshType)
{
  for (const ElementKind& kind : ElementKinds)
    if (kind.gmshType == gmshType)
      return &kind;
  return nullptr;
}

const ElementKind* kindOfVTKType(int vtkType)
{
  for (const ElementKind& kind : ElementKinds)
    if (kind.vtkType == vtkType)
      return &kind;
  return nullptr;
}

// One Gmsh API session: the library keeps global state, opened and closed around each file. Its
// messages go to its logger instead of the terminal; the last error is what a failure reports.
class GmshSession
{
public:
  GmshSession()
  {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

std::string lastGmshError(const std::string& fallback)
{
  std::string error;
  try
  {
    gmsh::logger::getLastError(error);
  }
  catch (...)
  {
  }
  return error.empty() ? fallback : error;
}

// Runs `body` in a Gmsh session; whatever Gmsh throws becomes a failure. The messages do not
// name the file: the caller does (a written file has a temporary name here).
template <typename Body>
Status withGmsh(const char* action, Body&& body)
{
  try
  {
    GmshSession session;
    try
    {
      return body();
    }
    catch (const std::exception& error)
    {
      return Status::failure(
        std::string("Gmsh cannot ") + action + " it: " + lastGmshError(error.what()));
    }
    catch (...)
    {
      return Status::failure(
        std::string("Gmsh cannot ") + action + " it: " + lastGmshError("unknown error"));
    }
  }
  catch (...)
  {
    return Status::failure("the Gmsh library could not be started");
  }
}

vtkSmartPointer<vtkIntArray> newIntArray(const char* name, vtkIdType size)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->Allocate(size);
  return array;
}

Status readOpenModel(vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  std::vector<std::size_t> nodeTags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(nodeTags, coordinates, parametric, -1, -1, false, false);
  // Node tags may have gaps: the point of a tag is found through a map.
  std::unordered_map<std::size_t, vtkIdType> pointOfTag;
  pointOfTag.reserve(nodeTags.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nodeTags.size()));
  for (std::size_t k = 0; k < nodeTags.size(); ++k)
  {
    pointOfTag.emplace(nodeTags[k], static_cast<vtkIdType>(k));
    points->SetPoint(static_cast<vtkIdType>(k), &coordinates[3 * k]);
  }
  if (names)
  {
    names->pointNumbers.assign(nodeTags.begin(), nodeTags.end());
    names->cellNumbers.clear();
  }

  grid->Initialize();
  grid->SetPoints(points);
  grid->Allocate(1024);
  auto tags = newIntArray(TagArrayName, 1024);
  auto entities = newIntArray(EntityArrayName, 1024);
  for (int dimension = 3; dimension >= 0; --dimension)
  {
    gmsh::vectorpair dimTags;
    gmsh::model::getEntities(dimTags, dimension);
    for (const auto& [dim, entity] : dimTags)
    {
      std::vector<int> physicals;
      gmsh::model::getPhysicalGroupsForEntity(dim, entity, physicals);
      const int tag = physicals.empty() ? entity : physicals.front();
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elementTags, elementNodes;
      gmsh::model::mesh::getElements(types, elementTags, elementNodes, dim, entity);
      for (std::size_t t = 0; t < types.size(); ++t)
      {
        const ElementKind* kind = kindOfGmshType(types[t]);
        if (!kind)
        {
          std::string name;
          int elementDimension = 0, order = 0, nodes = 0, primary = 0;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(
            types[t], name, elementDimension, order, nodes, local, primary);
          return Status::failure("the file holds " + std::to_string(elementTags[t].size()) +
            " elements of type " + name +
            ", which cgmesh does not refine: it takes linear tetrahedra, with triangles tagging "
            "their faces");
        }
        for (std::size_t e = 0; e < elementTags[t].size(); ++e)
        {
          vtkIdType corners[4];
          for (int c = 0; c < kind->nodes; ++c)
          {
            const auto found = pointOfTag.find(elementNodes[t][kind->nodes * e + c]);
            if (found == pointOfTag.end())
              return Status::failure("element " + std::to_string(elementTags[t][e]) +
                " names a node that does not exist");
            corners[c] = found->second;
          }
          grid->InsertNextCell(kind->vtkType, kind->nodes, corners);
          if (names)
            names->cellNumbers.push_back(static_cast<std::int64_t>(elementTags[t][e]));
          tags->InsertNextValue(tag);
          entities->InsertNextValue(entity);
        }
      }
    }
  }
  grid->GetCellData()->AddArray(tags);
  grid->GetCellData()->AddArray(entities);
  gmsh::vectorpair groups;
  if (names)
    gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups)
  {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (!name.empty())
      names->physicalNames[{ dim, tag }] = name;
  }
  return Status::success();
}

// A cell's (dimension, entity, tag): entities come from the Entity array when the grid has one.
struct CellGroup
{
  int dimension;
  int entity;
  int tag;
  bool operator<(const CellGroup& other) const
  {
    return std::tie(dimension, entity, tag) < std::tie(other.dimension, other.entity, other.tag);
  }
};

Status writeModel(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  const std::string& tagArray = options.tagArray;
  vtkDataArray* tags = tagArray.empty() ? nullptr : grid->GetCellData()->GetArray(tagArray.c_str());
  vtkDataArray* entities = grid->GetCellData()->GetArray(EntityArrayName);
  // Cells by group; physical groups must have positive tags, so all tags are shifted when some
  // are not (a region array numbered from 0), and the file says so in the group names.
  const int shift = positiveTagShift(tags);
  std::map<CellGroup, std::vector<vtkIdType>> cellsOfGroup;
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const ElementKind* kind = kindOfVTKType(grid->GetCellType(cellId));
    if (!kind)
      return Status::failure("cell " + std::to_string(cellId) +
        " is neither a tetrahedron, a triangle, a line nor a vertex");
    const int tag = tagValue(tags, cellId, 1) + shift;
    const int entity = entities && shift == 0 ? tagValue(entities, cellId, tag) : tag;
    cellsOfGroup[{ kind->dimension, entity, tag }].push_back(cellId);
  }

  gmsh::model::add("cgmesh");
  // One discrete entity per group: an entity split between two tags gets a fresh tag for the
  // second part.
  std::map<std::pair<int, int>, std::vector<int>> entitiesOfPhysical;
  std::map<CellGroup, int> entityOfGroup;
  std::set<std::pair<int, int>> usedEntities;
  std::map<int, int> nextFreeEntity;
  for (const auto& entry : cellsOfGroup)
    nextFreeEntity[entry.first.dimension] =
      std::max(nextFreeEntity[entry.first.dimension], entry.first.entity + 1);
  int nodeEntityDimension = -1, nodeEntity = 0;
  std::size_t nextElementTag = 1;
  for (const auto& [group, cells] : cellsOfGroup)
  {
    int entity = group.entity;
    if (entity <= 0 || !usedEntities.insert({ group.dimension, entity }).second)
    {
      entity = nextFreeEntity[group.dimension]++;
      usedEntities.insert({ group.dimension, entity });
    }
    gmsh::model::addDiscreteEntity(group.dimension, entity);
    entityOfGroup[group] = entity;
    entitiesOfPhysical[{ group.dimension, group.tag }].push_back(entity);
    if (group.dimension > nodeEntityDimension)
    {
      nodeEntityDimension = group.dimension;
      nodeEntity = entity;
    }
  }
  if (nodeEntityDimension < 0)
    return Status::failure("the mesh has no cells");

  // Each node lives on the lowest-dimensional entity among its cells', as Gmsh classifies the
  // nodes of its own meshes (boundary nodes on surfaces): Medit files number vertex references
  // by it. Nodes of no cell go to the entity of the highest dimension.
  using EntityKey = std::pair<int, int>; // (dimension, entity)
  const EntityKey unclassified{ std::numeric_limits<int>::max(), 0 };
  std::vector<EntityKey> homeOf(static_cast<std::size_t>(grid->GetNumberOfPoints()), unclassified);
  for (const auto& [group, cells] : cellsOfGroup)
  {
    const EntityKey key{ group.dimension, entityOfGroup.at(group) };
    for (const vtkIdType cellId : cells)
    {
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(cellId, count, corners);
      for (vtkIdType c = 0; c < count; ++c)
        homeOf[corners[c]] = std::min(homeOf[corners[c]], key);
    }
  }
  std::map<EntityKey, std::pair<std::vector<std::size_t>, std::vector<double>>> nodesOf;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    const EntityKey home =
      homeOf[p] == unclassified ? EntityKey{ nodeEntityDimension, nodeEntity } : homeOf[p];
    auto& [tags, coordinates] = nodesOf[home];
    tags.push_back(static_cast<std::size_t>(p) + 1);
    double point[3];
    grid->GetPoint(p, point);
    coordinates.insert(coordinates.end(), point, point + 3);
  }
  for (const auto& [home, nodes] : nodesOf)
    gmsh::model::mesh::addNodes(home.first, home.second, nodes.first, nodes.second);

  for (const auto& [group, cells] : cellsOfGroup)
  {
    const int entity = entityOfGroup.at(group);
    const ElementKind* kind = kindOfVTKType(grid->GetCellType(cells.front()));
    std::vector<std::size_t> elementTags(cells.size());
    std::vector<std::size_t> elementNodes;
    elementNodes.reserve(cells.size() * kind->nodes);
    for (std::size_t k = 0; k < cells.size(); ++k)
    {
      elementTags[k] = nextElementTag++;
      const vtkIdType* corners;
      vtkIdType count;
      grid->GetCellPoints(cells[k], count, corners);
      for (vtkIdType c = 0; c < count; ++c)
        elementNodes.push_back(static_cast<std::size_t>(corners[c]) + 1);
    }
    gmsh::model::mesh::addElementsByType(entity, kind->gmshType, elementTags, elementNodes);
  }
  for (const auto& [physical, members] : entitiesOfPhysical)
  {
    gmsh::model::addPhysicalGroup(physical.first, members, physical.second);
    std::string name;
    if (shift != 0)
      name = tagArray + " " + std::to_string(physical.second - shift);
    else if (options.names && options.names->physicalNames.count(physical))
      name = options.names->physicalNames.at(physical);
    if (!name.empty())
      gmsh::model::setPhysicalName(physical.first, physical.second, name);
  }
  gmsh::option::setNumber("Mesh.MshFileVersion", options.mshVersion);
  gmsh::option::setNumber("Mesh.SaveElementTagType", 2); // Medit references: physical groups
  gmsh::write(fileName);
  return Status::success();
}

Status readFile(const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  const Status status = withGmsh("read",
    [&]()
    {
      gmsh::open(fileName);
      return readOpenModel(grid, names);
    });
  return status.ok() ? status : Status::failure("'" + fileName + "': " + status.message());
}

Status writeFile(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  return withGmsh("write", [&]() { return writeModel(grid, fileName, options); });
}

} // namespace
} // namespace cgmesh

// The module's entry points (see GmshFiles.cxx): false and `error` set on failure.
extern "C" __attribute__((visibility("default"))) bool cgmeshReadGmshFile(
  const char* fileName, vtkUnstructuredGrid* grid, cgmesh::MeshFileNames* names, std::string* error)
{
  const cgmesh::Status status = cgmesh::readFile(fileName, grid, names);
  *error = status.ok() ? std::string() : status.message();
  return status.ok();
}

extern "C" __attribute__((visibility("default"))) bool cgmeshWriteGmshFile(
  vtkUnstructuredGrid* grid, const char* fileName, const cgmesh::WriteOptions* options,
  std::string* error)
{
  const cgmesh::Status status = cgmesh::writeFile(grid, fileName, *options);
  *error = status.ok() ? std::string() : status.message();
  return status.ok();
}

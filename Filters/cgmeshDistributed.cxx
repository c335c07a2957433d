#include "cgmeshDistributed.h"

#include "AdaptationPlan.h"
#include "Core/FaceKey.h"

#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkGhostCellsGenerator.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRedistributeDataSetFilter.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <sched.h>
#include <unistd.h>
#include <unordered_map>

namespace cgmesh
{
namespace
{

// A point's exact coordinates as a hash key. Pieces compute a shared point alike (input points
// as read, midpoints as the same sum of the same two ends), so equal bits mean the same point.
using CoordinateKey = std::array<std::uint64_t, 3>;

CoordinateKey coordinateKey(const double* point)
{
  CoordinateKey key;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double value = point[axis] == 0 ? 0.0 : point[axis]; // -0 and +0 are one point
    std::memcpy(&key[axis], &value, sizeof(double));
  }
  return key;
}

struct CoordinateKeyHash
{
  std::size_t operator()(const CoordinateKey& key) const
  {
    std::uint64_t h = key[0] * 0x9E3779B97F4A7C15ull;
    h ^= key[1] * 0xC2B2AE3D27D4EB4Full;
    h ^= key[2] * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// The points on faces of one tet only, in increasing order: the only ones another piece can hold.
// A face of one tet is a face of one tet within any run of consecutive tets that holds it, so the
// runs' own boundaries (small hash tables that stay in cache; the tets come partition by partition,
// so a run is compact and its boundary a small share of its faces) are the candidates, and one sort
// of the candidates keeps those no other run holds. One table over all faces of a 3.4 M-tet piece
// took 9 s.
std::vector<PointId> boundaryPoints(const TetMesh& piece)
{
  constexpr std::size_t RunLength = 8192;
  std::vector<Face> candidates;
  for (std::size_t first = 0; first < piece.tets.size(); first += RunLength)
  {
    forEachDistinctFace(piece.tets[first].data(), std::min(RunLength, piece.tets.size() - first),
      [&](const Face& face, std::size_t, std::size_t, std::size_t count)
      {
        if (count == 1)
        {
          candidates.push_back(face);
        }
      });
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<char> onBoundary(piece.numberOfPoints(), 0);
  for (std::size_t i = 0; i < candidates.size();)
  {
    std::size_t next = i + 1;
    while (next < candidates.size() && candidates[next] == candidates[i])
    {
      ++next;
    }
    if (next - i == 1)
    {
      for (PointId p : candidates[i])
      {
        onBoundary[p] = 1;
      }
    }
    i = next;
  }
  std::vector<PointId> points;
  for (PointId p = 0; p < piece.numberOfPoints(); ++p)
  {
    if (onBoundary[p])
    {
      points.push_back(p);
    }
  }
  return points;
}

void removeGhostArrays(vtkUnstructuredGrid* grid)
{
  grid->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  grid->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> prepareDistributedPiece(
  const ProcessGroup& group, vtkUnstructuredGrid* input, std::string& note)
{
  vtkSmartPointer<vtkUnstructuredGrid> piece = input;
  if (input->GetCellGhostArray() || input->GetPointGhostArray())
  {
    // Ghost cells belong to another piece, which refines them; a copy, since the input stays as
    // it is.
    piece = vtkSmartPointer<vtkUnstructuredGrid>::New();
    piece->DeepCopy(input);
    piece->RemoveGhostCells();
    removeGhostArrays(piece);
  }
  const std::vector<long long> cells =
    group.gather(static_cast<long long>(piece->GetNumberOfCells()));
  const long long total = std::accumulate(cells.begin(), cells.end(), 0LL);
  const long long holders =
    std::count_if(cells.begin(), cells.end(), [](long long count) { return count > 0; });
  if (total < group.size() || holders == group.size())
  {
    return piece;
  }
  vtkNew<vtkRedistributeDataSetFilter> redistribute;
  redistribute->SetController(group.controller());
  redistribute->SetInputData(piece);
  redistribute->SetBoundaryModeToAssignToOneRegion(); // each cell on one process: no copies
  redistribute->SetGenerateGlobalCellIds(false);
  redistribute->Update();
  vtkSmartPointer<vtkUnstructuredGrid> spread =
    vtkUnstructuredGrid::SafeDownCast(redistribute->GetOutputDataObject(0));
  if (!spread)
  {
    return piece;
  }
  removeGhostArrays(spread);
  note = "The input's " + std::to_string(total) + " cells were held by " + std::to_string(holders) +
    " of " + std::to_string(group.size()) +
    " processes; they were spread over all of them first (as RedistributeDataSet does). Put "
    "RedistributeDataSet before the filter to choose how.";
  return spread;
}

namespace
{

int processesOnThisHost(const ProcessGroup& group)
{
  char name[256] = {};
  gethostname(name, sizeof(name) - 1);
  const std::vector<char> mine(name, name + std::strlen(name) + 1);
  std::vector<long long> offsets;
  const std::vector<char> all = group.gather(mine, offsets);
  int count = 0;
  for (int r = 0; r < group.size(); ++r)
  {
    count +=
      std::equal(mine.begin(), mine.end(), all.begin() + offsets[r], all.begin() + offsets[r + 1]);
  }
  return std::max(1, count);
}

} // namespace

void resolveDistributedOptions(
  const ProcessGroup& group, const TetMesh& piece, AdaptationOptions& options)
{
  options.orderCornersByCoordinates = true;
  options.keepBoundaryTriangulation = true; // the pieces' faces against each other stay as they are
  // "Every core" means this process's share of the cores it may run on: processes on one host
  // would otherwise each start a thread per core.
  if (options.numberOfThreads == 0)
  {
    const int local = processesOnThisHost(group);
    cpu_set_t cores;
    const int available = sched_getaffinity(0, sizeof(cores), &cores) == 0 ? CPU_COUNT(&cores) : 1;
    options.numberOfThreads = std::max(1, available / local);
  }
  // The whole mesh's mean: the pieces' means weighted by their tet counts.
  const double tets = static_cast<double>(piece.numberOfTets());
  const auto meanOfAll = [&](double pieceMean)
  {
    const double all = group.sum(tets);
    return all > 0 ? group.sum(pieceMean * tets) / all : 0;
  };
  if (options.method == RefinementMethod::Delaunay)
  {
    if (!(options.maximumVolume > 0))
    {
      options.maximumVolume = options.volumeFactor * meanOfAll(meanTetVolume(piece));
    }
  }
  else if (!(options.maximumEdgeLength > 0))
  {
    options.maximumEdgeLength = options.edgeLengthFactor * meanOfAll(meanTetEdgeLength(piece));
  }
}

std::vector<std::string> unionAcrossProcesses(
  const ProcessGroup& group, const std::vector<std::string>& names)
{
  std::vector<char> joined;
  for (const std::string& name : names)
  {
    joined.insert(joined.end(), name.begin(), name.end());
    joined.push_back('\0');
  }
  std::vector<long long> offsets;
  const std::vector<char> all = group.gather(joined, offsets);
  std::vector<std::string> together;
  for (std::size_t start = 0; start < all.size();)
  {
    const std::size_t end = std::find(all.begin() + start, all.end(), '\0') - all.begin();
    std::string name(all.begin() + start, all.begin() + end);
    if (std::find(together.begin(), together.end(), name) == together.end())
    {
      together.push_back(std::move(name));
    }
    start = end + 1;
  }
  return together;
}

std::string unsupportedAcrossProcesses(const AdaptationOptions& options, bool hasSizeArray)
{
  // Each option makes an edge's split depend on the tets around it (their sizes, regions or
  // place), and a piece sees only its own side of a face it shares.
  const char* why = "a piece decides the edges of a face it shares with another piece from its "
                    "own tets only, and the pieces would split the face differently";
  if (hasSizeArray)
  {
    return std::string("SizeArrayName is not supported across processes yet: ") + why;
  }
  if (!options.refinementRegions.empty())
  {
    return std::string("RefinementRegions is not supported across processes yet: ") + why;
  }
  if (!options.refinementBox.empty())
  {
    return std::string("RefinementBox is not supported across processes yet: ") + why;
  }
  return std::string();
}

GlobalNumbering numberAcrossProcesses(const ProcessGroup& group, const TetMesh& piece,
  const std::vector<long long>& keptIds, long long cellCount)
{
  GlobalNumbering numbering;
  const PointId points = piece.numberOfPoints();
  const std::vector<PointId> boundary = boundaryPoints(piece);
  std::vector<double> boundaryCoordinates;
  boundaryCoordinates.reserve(3 * boundary.size());
  std::unordered_map<CoordinateKey, std::size_t, CoordinateKeyHash> indexOf;
  indexOf.reserve(boundary.size());
  for (std::size_t b = 0; b < boundary.size(); ++b)
  {
    const double* point = piece.point(boundary[b]);
    boundaryCoordinates.insert(boundaryCoordinates.end(), point, point + 3);
    indexOf.emplace(coordinateKey(point), b);
  }
  std::vector<long long> offsets;
  const std::vector<double> allCoordinates = group.gather(boundaryCoordinates, offsets);
  numbering.exchangedBytes +=
    static_cast<long long>((allCoordinates.size() - boundaryCoordinates.size()) * sizeof(double));

  // For each boundary point: where the lowest lower rank holding it has it in the gathered lists
  // (an index into every process's boundary lists), or -1; and whether any other rank holds it.
  std::vector<long long> ownerSlot(boundary.size(), -1);
  std::vector<char> shared(boundary.size(), 0);
  for (int r = 0; r < group.size(); ++r)
  {
    if (r == group.rank())
    {
      continue;
    }
    for (long long slot = offsets[r] / 3; slot < offsets[r + 1] / 3; ++slot)
    {
      const auto found = indexOf.find(coordinateKey(allCoordinates.data() + 3 * slot));
      if (found == indexOf.end())
      {
        continue;
      }
      shared[found->second] = 1;
      if (r < group.rank() && ownerSlot[found->second] < 0)
      {
        ownerSlot[found->second] = slot;
      }
    }
  }
  numbering.sharedPoints = std::count(shared.begin(), shared.end(), 1);

  // Points this process numbers: those without a kept id that no lower rank holds.
  std::vector<char> ownedElsewhere(points, 0);
  for (std::size_t b = 0; b < boundary.size(); ++b)
  {
    ownedElsewhere[boundary[b]] = ownerSlot[b] >= 0;
  }
  long long largestKept = -1;
  long long toNumber = 0;
  for (PointId p = 0; p < points; ++p)
  {
    const long long kept = keptIds.empty() ? -1 : keptIds[p];
    largestKept = std::max(largestKept, kept);
    toNumber += kept < 0 && !ownedElsewhere[p];
  }
  const long long firstFree = group.maximum(largestKept) + 1;
  const std::vector<long long> counts = group.gather(toNumber);
  long long next = firstFree;
  for (int r = 0; r < group.rank(); ++r)
  {
    next += counts[r];
  }
  numbering.pointIds.assign(points, -1);
  for (PointId p = 0; p < points; ++p)
  {
    const long long kept = keptIds.empty() ? -1 : keptIds[p];
    numbering.pointIds[p] = kept >= 0 ? kept : ownedElsewhere[p] ? -1 : next++;
  }

  // The owners' ids for the points a lower rank numbered, through the same boundary lists.
  std::vector<long long> boundaryIds(boundary.size());
  for (std::size_t b = 0; b < boundary.size(); ++b)
  {
    boundaryIds[b] = numbering.pointIds[boundary[b]];
  }
  std::vector<long long> idOffsets;
  const std::vector<long long> allIds = group.gather(boundaryIds, idOffsets);
  numbering.exchangedBytes +=
    static_cast<long long>((allIds.size() - boundaryIds.size()) * sizeof(long long));
  for (std::size_t b = 0; b < boundary.size(); ++b)
  {
    if (ownerSlot[b] >= 0 && numbering.pointIds[boundary[b]] < 0)
    {
      numbering.pointIds[boundary[b]] = allIds[ownerSlot[b]];
    }
  }

  const std::vector<long long> cellCounts = group.gather(cellCount);
  for (int r = 0; r < group.rank(); ++r)
  {
    numbering.firstCellId += cellCounts[r];
  }
  return numbering;
}

vtkSmartPointer<vtkUnstructuredGrid> addGhostCells(
  const ProcessGroup& group, vtkUnstructuredGrid* piece, int levels)
{
  vtkNew<vtkGhostCellsGenerator> generator;
  generator->SetController(group.controller());
  generator->SetInputData(piece);
  generator->BuildIfRequiredOff();
  generator->SetNumberOfGhostLayers(levels);
  generator->Update();
  vtkSmartPointer<vtkUnstructuredGrid> withGhosts =
    vtkUnstructuredGrid::SafeDownCast(generator->GetOutputDataObject(0));
  return withGhosts ? withGhosts : vtkSmartPointer<vtkUnstructuredGrid>(piece);
}

} // namespace cgmesh

#include "Validation/MeshValidation.h"

#include "Core/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <tuple>

namespace cgmesh
{
namespace
{

struct FaceRecord
{
  std::array<PointId, 3> sorted; // the face's corners, ascending
  bool evenPermutation;          // orientation of the tet's outward face relative to `sorted`
  CellId tet;
};

// The four faces of tet (a, b, c, d), each oriented outward for a positive tet.
constexpr int OutwardFaces[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

FaceRecord makeFace(const Tet& tet, int face, CellId tetId)
{
  std::array<PointId, 3> corners = { tet[OutwardFaces[face][0]], tet[OutwardFaces[face][1]],
    tet[OutwardFaces[face][2]] };
  // Parity of the sorting permutation tells the orientation.
  int swaps = 0;
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2 - i; ++j)
    {
      if (corners[j] > corners[j + 1])
      {
        std::swap(corners[j], corners[j + 1]);
        ++swaps;
      }
    }
  }
  return FaceRecord{ corners, swaps % 2 == 0, tetId };
}

void inspectFaces(const TetMesh& mesh, MeshReport& report)
{
  std::vector<FaceRecord> faces;
  faces.reserve(4 * mesh.tets.size());
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      faces.push_back(makeFace(mesh.tets[t], f, t));
    }
  }
  std::sort(faces.begin(), faces.end(),
    [](const FaceRecord& x, const FaceRecord& y)
    { return std::tie(x.sorted, x.tet) < std::tie(y.sorted, y.tet); });

  for (size_t begin = 0; begin < faces.size();)
  {
    size_t end = begin + 1;
    while (end < faces.size() && faces[end].sorted == faces[begin].sorted)
    {
      ++end;
    }
    const auto& corners = faces[begin].sorted;
    const size_t count = end - begin;
    if (count == 1)
    {
      ++report.boundaryFaces;
      report.boundaryArea +=
        triangleArea(mesh.point(corners[0]), mesh.point(corners[1]), mesh.point(corners[2]));
    }
    else if (count == 2)
    {
      ++report.interiorFaces;
      if (faces[begin].evenPermutation == faces[begin + 1].evenPermutation)
      {
        ++report.misorientedFacePairs;
      }
      if (mesh.hasRegions() && mesh.regions[faces[begin].tet] != mesh.regions[faces[begin + 1].tet])
      {
        ++report.regionInterfaceFaces;
        report.regionInterfaceArea +=
          triangleArea(mesh.point(corners[0]), mesh.point(corners[1]), mesh.point(corners[2]));
      }
    }
    else
    {
      ++report.overSharedFaces;
    }
    begin = end;
  }
}

void inspectPoints(const TetMesh& mesh, MeshReport& report)
{
  std::vector<char> used(mesh.numberOfPoints(), 0);
  for (const Tet& tet : mesh.tets)
  {
    for (PointId p : tet)
    {
      if (p >= 0 && p < mesh.numberOfPoints())
      {
        used[p] = 1;
      }
    }
  }
  report.unusedPoints = std::count(used.begin(), used.end(), 0);
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    const double* x = mesh.point(p);
    report.nonFinitePoints += !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]));
  }
  if (report.nonFinitePoints > 0)
  {
    return; // coordinates that do not compare cannot be sorted to find duplicates
  }

  std::vector<PointId> order(mesh.numberOfPoints());
  for (PointId i = 0; i < mesh.numberOfPoints(); ++i)
  {
    order[i] = i;
  }
  auto coordinatesOf = [&mesh](PointId p)
  {
    return std::make_tuple(mesh.point(p)[0], mesh.point(p)[1], mesh.point(p)[2]);
  };
  std::sort(order.begin(), order.end(),
    [&](PointId x, PointId y) { return coordinatesOf(x) < coordinatesOf(y); });
  for (size_t i = 1; i < order.size(); ++i)
  {
    if (coordinatesOf(order[i]) == coordinatesOf(order[i - 1]))
    {
      ++report.duplicatePoints;
    }
  }
}

// A sum of many terms with the rounding of each addition carried along (Neumaier's variant of
// Kahan's summation): millions of tet volumes added in plain doubles lose about 1e-12 of the
// total, as much as the conservation checks allow, and the loss depends on the tets' order.
class CompensatedSum
{
public:
  void add(double term)
  {
    const double sum = this->Sum + term;
    this->Carry +=
      std::abs(this->Sum) >= std::abs(term) ? (this->Sum - sum) + term : (term - sum) + this->Sum;
    this->Sum = sum;
  }
  double value() const { return this->Sum + this->Carry; }

private:
  double Sum = 0;
  double Carry = 0;
};

void inspectTets(const TetMesh& mesh, MeshReport& report)
{
  CompensatedSum volume;
  std::map<int, CompensatedSum> regionVolumes;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    const Tet& tet = mesh.tets[t];
    bool repeated = false;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        repeated = repeated || tet[i] == tet[j];
      }
    }
    if (repeated)
    {
      ++report.repeatedCornerTets;
      continue;
    }
    const double volume6 = signedVolume6(mesh, tet);
    double longestSquared = 0;
    for (const auto& edge : TetEdgeCorners)
    {
      longestSquared =
        std::max(longestSquared, squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
    }
    const double longestCubed = longestSquared * std::sqrt(longestSquared);
    if (std::abs(volume6) <= 1e-12 * longestCubed)
    {
      ++report.degenerateTets;
    }
    else if (volume6 < 0)
    {
      ++report.invertedTets;
    }
    volume.add(volume6 / 6.0);
    if (mesh.hasRegions())
    {
      regionVolumes[mesh.regions[t]].add(volume6 / 6.0);
    }
  }
  report.volume = volume.value();
  for (const auto& region : regionVolumes)
  {
    report.regionVolumes[region.first] = region.second.value();
  }
}

} // namespace

MeshReport inspectMesh(const TetMesh& mesh)
{
  MeshReport report;
  report.numberOfTets = mesh.numberOfTets();
  report.numberOfPoints = mesh.numberOfPoints();
  inspectTets(mesh, report);
  inspectFaces(mesh, report);
  inspectPoints(mesh, report);
  return report;
}

bool MeshReport::isValid() const
{
  return this->describeProblems().empty();
}

std::string MeshReport::describeProblems() const
{
  std::ostringstream problems;
  auto complain = [&problems](std::int64_t count, const char* what)
  {
    if (count != 0)
    {
      problems << count << ' ' << what << '\n';
    }
  };
  complain(this->invertedTets, "inverted tets");
  complain(this->degenerateTets, "degenerate tets");
  complain(this->repeatedCornerTets, "tets naming a point twice");
  complain(this->overSharedFaces, "faces shared by more than two tets");
  complain(this->misorientedFacePairs, "interior faces with inconsistent orientation");
  complain(this->unusedPoints, "unused points");
  complain(this->duplicatePoints, "duplicate points");
  complain(this->nonFinitePoints, "points with a NaN or infinite coordinate");
  return problems.str();
}

} // namespace cgmesh

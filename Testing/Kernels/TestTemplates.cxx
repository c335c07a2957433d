// Template refinement of a single tet: every split pattern tiles its parent with positive tets,
// two tets sharing a face always triangulate it identically, and full splits keep 3/4 of their
// parent's mean ratio, which lets refinement leave the children of good parents unscreened.
// Passes that hand on the tets they left whole measure only the last pass's children.
#include "Core/ConstrainedFaces.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "CubeGenerator.h"
#include "Refinement/ConstrainedEdgeSplits.h"
#include "Refinement/PartitionRefiner.h"
#include "Refinement/TemplateTable.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <algorithm>
#include <array>
#include <random>
#include <set>

using namespace cgmesh;

namespace
{

// An irregular, positively oriented tet.
const double Corners[4][3] = { { 0.1, 0.0, 0.05 }, { 1.3, 0.2, 0.0 }, { 0.3, 1.1, 0.1 },
  { 0.2, 0.4, 0.9 } };

std::vector<LocalTet> templateFor(
  const TemplateTable& table, int mask, const std::array<int, 4>& ranks, int diagonal)
{
  if (mask == 0)
  {
    return { LocalTet{ 0, 1, 2, 3 } };
  }
  return mask == 63 ? table.fullSplit(diagonal) : table.partialSplit(mask, ranks);
}

TetMesh childMesh(const std::vector<LocalTet>& children)
{
  TetMesh mesh;
  for (int c = 0; c < 4; ++c)
  {
    mesh.coordinates.insert(mesh.coordinates.end(), Corners[c], Corners[c] + 3);
  }
  for (const auto& edge : TetEdgeCorners)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      mesh.coordinates.push_back(0.5 * (Corners[edge[0]][axis] + Corners[edge[1]][axis]));
    }
  }
  for (const LocalTet& child : children)
  {
    mesh.tets.push_back({ child[0], child[1], child[2], child[3] });
  }
  return mesh;
}

void checkOneCase(
  const TemplateTable& table, int mask, const std::array<int, 4>& ranks, int diagonal)
{
  const TetMesh parent = childMesh({ LocalTet{ 0, 1, 2, 3 } });
  const MeshReport parentReport = inspectMesh(parent);
  const TetMesh children = childMesh(templateFor(table, mask, ranks, diagonal));
  const MeshReport report = inspectMesh(children);
  CHECK_EQUAL(report.invertedTets, 0);
  CHECK_EQUAL(report.degenerateTets, 0);
  CHECK_EQUAL(report.overSharedFaces, 0);
  CHECK_EQUAL(report.misorientedFacePairs, 0);
  CHECK_CLOSE(report.volume, parentReport.volume, 1e-12);
  CHECK_CLOSE(report.boundaryArea, parentReport.boundaryArea, 1e-12);

  // The children's boundary is exactly the face rule's triangulation of the parent's faces.
  std::set<std::array<int, 3>> expected;
  const std::array<std::array<int, 3>, 4> faces = { { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 },
    { 0, 1, 2 } } };
  for (const auto& face : faces)
  {
    for (auto triangle : triangulateFace(face, mask, ranks))
    {
      std::sort(triangle.begin(), triangle.end());
      expected.insert(triangle);
    }
  }
  std::multiset<std::array<int, 3>> childFaces;
  for (const Tet& tet : children.tets)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<int, 3> triangle;
      int n = 0;
      for (int i = 0; i < 4; ++i)
      {
        if (i != skip)
        {
          triangle[n++] = static_cast<int>(tet[i]);
        }
      }
      std::sort(triangle.begin(), triangle.end());
      childFaces.insert(triangle);
    }
  }
  std::set<std::array<int, 3>> boundary;
  for (const auto& triangle : childFaces)
  {
    if (childFaces.count(triangle) == 1)
    {
      boundary.insert(triangle);
    }
  }
  CHECK(boundary == expected);

  const int splitCount = __builtin_popcount(mask);
  if (splitCount == 1)
  {
    CHECK_EQUAL(children.tets.size(), 2u);
  }
  if (mask == 63)
  {
    CHECK_EQUAL(children.tets.size(), 8u);
  }
}

void test_every_template_case()
{
  const TemplateTable table;
  CHECK(table.status().ok());
  std::array<int, 4> ranks = { 0, 1, 2, 3 };
  int cases = 0;
  do
  {
    for (int mask = 1; mask < 63; ++mask)
    {
      checkOneCase(table, mask, ranks, 0);
      ++cases;
    }
  } while (std::next_permutation(ranks.begin(), ranks.end()));
  for (int diagonal = 0; diagonal < 3; ++diagonal)
  {
    checkOneCase(table, 63, ranks, diagonal);
    ++cases;
  }
  CHECK_EQUAL(cases, 62 * 24 + 3);
  // Two opposite edges split: four tets around the segment joining their midpoints.
  CHECK_EQUAL(table.partialSplit(1 | 32, ranks).size(), 4u);
}

// Vertex identity for comparing the two sides of a face: a corner's global id, or the edge a
// midpoint splits.
using VertexKey = std::pair<int, int>;

std::set<std::array<VertexKey, 3>> facePieces(const TemplateTable& table,
  const std::array<int, 4>& globalIds, int mask, const std::set<int>& faceIds)
{
  std::array<int, 4> ranks;
  for (int i = 0; i < 4; ++i)
  {
    ranks[i] = static_cast<int>(
      std::count_if(globalIds.begin(), globalIds.end(), [&](int g) { return g < globalIds[i]; }));
  }
  auto keyOf = [&](int local) -> VertexKey
  {
    if (local < 4)
    {
      return { globalIds[local], globalIds[local] };
    }
    const int a = globalIds[TetEdgeCorners[local - 4][0]];
    const int b = globalIds[TetEdgeCorners[local - 4][1]];
    return { std::min(a, b), std::max(a, b) };
  };
  auto onFace = [&](const VertexKey& key)
  {
    return faceIds.count(key.first) && faceIds.count(key.second);
  };
  std::set<std::array<VertexKey, 3>> pieces;
  for (const LocalTet& child : templateFor(table, mask, ranks, 0))
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<VertexKey, 3> triangle;
      int n = 0;
      for (int i = 0; i < 4; ++i)
      {
        if (i != skip)
        {
          triangle[n++] = keyOf(child[i]);
        }
      }
      if (onFace(triangle[0]) && onFace(triangle[1]) && onFace(triangle[2]))
      {
        std::sort(triangle.begin(), triangle.end());
        pieces.insert(triangle);
      }
    }
  }
  return pieces;
}

// Tets (a, b, c, d) and (a, c, b, e) share face abc. For every global numbering of the five
// points and every split pattern that agrees on the face, both sides cut the face identically.
void test_shared_face_agreement()
{
  const TemplateTable table;
  std::array<int, 5> ids = { 0, 1, 2, 3, 4 };
  int comparisons = 0;
  do
  {
    const int a = ids[0], b = ids[1], c = ids[2], d = ids[3], e = ids[4];
    const std::set<int> face = { a, b, c };
    for (int faceMask = 0; faceMask < 8; ++faceMask)
    {
      // Local edge order: (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
      // First tet (a,b,c,d): ab = edge 0, ac = edge 1, bc = edge 3.
      const int first = (faceMask & 1 ? 1 : 0) | (faceMask & 2 ? 2 : 0) | (faceMask & 4 ? 8 : 0);
      // Second tet (a,c,b,e): ac = edge 0, ab = edge 1, bc = edge 3.
      const int second = (faceMask & 2 ? 1 : 0) | (faceMask & 1 ? 2 : 0) | (faceMask & 4 ? 8 : 0);
      for (int firstOther = 0; firstOther < 8; ++firstOther)
      {
        const int otherEdges =
          (firstOther & 1 ? 4 : 0) | (firstOther & 2 ? 16 : 0) | (firstOther & 4 ? 32 : 0);
        const auto pieces1 = facePieces(table, { a, b, c, d }, first | otherEdges, face);
        for (int secondOther = 0; secondOther < 8; ++secondOther)
        {
          const int otherEdges2 =
            (secondOther & 1 ? 4 : 0) | (secondOther & 2 ? 16 : 0) | (secondOther & 4 ? 32 : 0);
          const auto pieces2 = facePieces(table, { a, c, b, e }, second | otherEdges2, face);
          CHECK(pieces1 == pieces2);
          CHECK_EQUAL(pieces1.size(),
            static_cast<std::size_t>(faceMask == 0  ? 1
                : __builtin_popcount(faceMask) == 3 ? 4
                                                    : __builtin_popcount(faceMask) + 1));
          ++comparisons;
        }
      }
    }
  } while (std::next_permutation(ids.begin(), ids.end()));
  CHECK_EQUAL(comparisons, 120 * 8 * 8 * 8);
}

// Template refinement over `coordinates` with the given interface flags: edges longer than
// `threshold` split.
RefinementContext templateContext(const std::vector<double>& coordinates,
  const std::vector<char>& interfaceVertex, double threshold, const TemplateTable& templates)
{
  RefinementContext context;
  context.coordinates = &coordinates;
  context.interfaceVertex = &interfaceVertex;
  context.squaredThreshold = threshold * threshold;
  context.templates = &templates;
  return context;
}

// `count` separate tets with random corners in [low, 1]^3, each positively oriented and with
// |six times its volume| of at least `smallestVolume6`; their corners are appended to
// `coordinates`, four points per tet.
PartitionMesh randomTetSoup(unsigned seed, std::size_t count, double low, double smallestVolume6,
  std::vector<double>& coordinates)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(low, 1);
  PartitionMesh soup;
  while (soup.tets.size() < count)
  {
    double corners[4][3];
    for (auto& corner : corners)
    {
      for (double& value : corner)
      {
        value = coordinate(random);
      }
    }
    const double volume6 = signedVolume6(corners[0], corners[1], corners[2], corners[3]);
    if (std::abs(volume6) < smallestVolume6)
    {
      continue;
    }
    const PointId first = static_cast<PointId>(coordinates.size() / 3);
    for (int c : { 0, volume6 > 0 ? 1 : 2, volume6 > 0 ? 2 : 1, 3 })
    {
      coordinates.insert(coordinates.end(), corners[c], corners[c] + 3);
    }
    soup.tets.push_back({ first, first + 1, first + 2, first + 3 });
    soup.parentCells.push_back(static_cast<CellId>(soup.tets.size() - 1));
  }
  return soup;
}

// Random tets of every shape, slivers included, refined on their own: every child of a full split
// keeps at least FullSplitChildQuality of its parent's mean ratio, and the bound is tight. With
// an improvement target, refinement lists exactly the children under it (as improvement's
// screening measures them), though it skips measuring the children the bound clears.
void test_full_split_children_keep_three_quarters()
{
  std::vector<double> coordinates;
  const PartitionMesh soup = randomTetSoup(11, 20000, -1, 1e-9, coordinates);
  const double target = 0.5;
  const TemplateTable table;
  const std::vector<char> noInterface(coordinates.size() / 3, 0);
  // Every edge split, then only edges longer than 1: full and partial splits side by side.
  for (double threshold : { 0.0, 1.0 })
  {
    RefinementContext context = templateContext(coordinates, noInterface, threshold, table);
    context.improvementTarget = target;
    PartitionMesh refined = soup;
    PartitionRefinement refinement;
    std::vector<std::size_t> origins;
    CHECK(
      refinePartition(refined, context, PostedSplits(), refinement, EdgeFilter(), &origins).ok());
    const auto at = [&](PointId id)
    {
      return pointCoordinates(coordinates, refinement.newCoordinates, id);
    };
    const auto quality = [&](const Tet& tet)
    {
      return meanRatio(at(tet[0]), at(tet[1]), at(tet[2]), at(tet[3]));
    };
    const std::vector<std::size_t>& listed = refinement.tetsToScreen;
    CHECK(std::adjacent_find(listed.begin(), listed.end(),
            [](std::size_t a, std::size_t b) { return a >= b; }) == listed.end());
    double worstRatio = 1;
    std::size_t fullSplitChildren = 0, poorChildren = 0;
    for (std::size_t t = 0; t < refined.tets.size(); ++t)
    {
      const Tet& parent = soup.tets[origins[t]];
      bool fullSplit = true;
      for (const auto& edge : TetEdgeCorners)
      {
        fullSplit = fullSplit &&
          squaredDistance(at(parent[edge[0]]), at(parent[edge[1]])) > context.squaredThreshold;
      }
      const double childQuality = quality(refined.tets[t]);
      const double parentQuality = quality(parent);
      if (fullSplit)
      {
        ++fullSplitChildren;
        worstRatio = std::min(worstRatio, childQuality / parentQuality);
      }
      const bool isListed = std::binary_search(listed.begin(), listed.end(), t);
      const Tet& child = refined.tets[t];
      const bool isPoor =
        meanRatioBelow(at(child[0]), at(child[1]), at(child[2]), at(child[3]), target);
      poorChildren += isPoor ? 1 : 0;
      CHECK_EQUAL(isListed, isPoor);
      CHECK(isListed || childQuality >= target * (1 - 1e-12));
    }
    std::cout << "threshold " << threshold << ": " << refined.tets.size() << " tets, "
              << fullSplitChildren << " from full splits (worst quality ratio to the parent "
              << worstRatio << "), " << poorChildren << " under " << target << ", " << listed.size()
              << " listed\n";
    CHECK(fullSplitChildren > 0 && worstRatio >= FullSplitChildQuality * (1 - 1e-12));
    CHECK(worstRatio < FullSplitChildQuality + 0.05); // tight: some child comes close
    CHECK(poorChildren > 0 && listed.size() == poorChildren);
    CHECK(threshold > 0 || fullSplitChildren == refined.tets.size());
    CHECK(threshold == 0 || fullSplitChildren < refined.tets.size());
  }
}

// Passes that hand on which tets came through unsplit (refinePartition's `passedUnsplit`) make
// exactly the tets of passes that measure every tet, flag exactly the tets a pass left whole, and
// do not measure a flagged tet again: one flagged on purpose despite its long edge stays whole.
void test_passes_measure_only_what_the_last_pass_made()
{
  std::vector<double> coordinates;
  const PartitionMesh soup = randomTetSoup(5, 3000, 0, 1e-6, coordinates);
  const TemplateTable table;
  struct Run
  {
    PartitionMesh mesh;
    std::vector<double> coordinates;
    std::vector<char> unsplit;
  };
  Run measuringAll{ soup, coordinates, {} }, skipping{ soup, coordinates, {} };
  // One pass on `run`, its new points then given global ids after the existing ones.
  const auto pass = [&table](
                      Run& run, std::vector<char>* unsplit, std::vector<std::size_t>& origins)
  {
    const std::vector<char> noInterface(run.coordinates.size() / 3, 0);
    const RefinementContext context = templateContext(run.coordinates, noInterface, 0.15, table);
    PartitionRefinement refinement;
    CHECK(refinePartition(
      run.mesh, context, PostedSplits(), refinement, EdgeFilter(), &origins, nullptr, unsplit)
            .ok());
    finalizeNewPoints(run.mesh, refinement, static_cast<PointId>(run.coordinates.size() / 3));
    run.coordinates.insert(
      run.coordinates.end(), refinement.newCoordinates.begin(), refinement.newCoordinates.end());
  };
  int passesSplitting = 0;
  for (int p = 0; p < 6; ++p)
  {
    const PartitionMesh before = skipping.mesh;
    std::vector<std::size_t> origins, ignored;
    pass(measuringAll, nullptr, ignored);
    pass(skipping, &skipping.unsplit, origins);
    CHECK(skipping.mesh.tets == measuringAll.mesh.tets);
    CHECK(skipping.coordinates == measuringAll.coordinates);
    CHECK_EQUAL(skipping.unsplit.size(), skipping.mesh.tets.size());
    std::vector<int> madeOf(before.tets.size(), 0); // tets made of each tet before
    for (std::size_t origin : origins)
    {
      ++madeOf[origin];
    }
    std::size_t children = 0;
    for (std::size_t t = 0; t < skipping.mesh.tets.size(); ++t)
    {
      const bool whole =
        madeOf[origins[t]] == 1 && skipping.mesh.tets[t] == before.tets[origins[t]];
      CHECK_EQUAL(skipping.unsplit[t] != 0, whole);
      children += whole ? 0 : 1;
    }
    passesSplitting += children > 0 ? 1 : 0;
  }
  std::cout << passesSplitting << " of 6 passes split tets; " << skipping.mesh.tets.size()
            << " tets after them\n";
  CHECK(passesSplitting >= 3);

  // A flagged tet is taken as whole without being measured.
  Run flagged{ soup, coordinates, std::vector<char>(soup.tets.size(), 0) };
  flagged.unsplit[0] = 1; // the first random tet has an edge over 0.15
  std::vector<std::size_t> origins;
  pass(flagged, &flagged.unsplit, origins);
  CHECK(std::count(origins.begin(), origins.end(), 0u) == 1);
  CHECK(flagged.mesh.tets[0] == soup.tets[0]);
  CHECK(std::count(origins.begin(), origins.end(), 1u) > 1); // the second one split
}

// mostChildren() sizes refinement's output: it must bound every corner order's template and be
// reached by one of them.
void test_most_children_bounds_every_template()
{
  const TemplateTable table;
  CHECK(table.status().ok());
  CHECK_EQUAL(table.mostChildren(0), 1);
  CHECK_EQUAL(table.mostChildren(63), 8);
  for (int mask = 1; mask < 63; ++mask)
  {
    std::array<int, 4> ranks = { 0, 1, 2, 3 };
    std::size_t most = 0;
    do
    {
      const std::size_t children = table.partialSplit(mask, ranks).size();
      CHECK(children <= static_cast<std::size_t>(table.mostChildren(mask)));
      most = std::max(most, children);
    } while (std::next_permutation(ranks.begin(), ranks.end()));
    CHECK_EQUAL(most, static_cast<std::size_t>(table.mostChildren(mask)));
  }
}

} // namespace

// Constrained-face marks handed on by refinePartition() name exactly the faces a search of the
// refined partition finds: boundary faces (of the domain and of the cut) and the faces between
// regions, round after round, through full splits (every long edge) and partial ones (only the
// constrained edges, as the Delaunay interface rounds split them). An irregular block of three
// regions, cut out of a jittered cube so that it has boundary faces of both kinds.
void test_face_marks_follow_the_children()
{
  TetMesh cube;
  CHECK(generateKuhnCube(4, cube).ok());
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  for (double& coordinate : cube.coordinates)
  {
    const bool onSide = coordinate < 1e-12 || coordinate > 1 - 1e-12;
    coordinate += onSide ? 0.0 : jitter(random);
  }
  PartitionMesh partition;
  for (std::size_t t = 0; t < cube.tets.size(); ++t)
  {
    double centroid[3] = { 0, 0, 0 };
    for (PointId p : cube.tets[t])
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        centroid[axis] += 0.25 * cube.point(p)[axis];
      }
    }
    if (centroid[0] < 0.6)
    {
      partition.tets.push_back(cube.tets[t]);
      partition.parentCells.push_back(static_cast<CellId>(t));
      partition.regions.push_back(centroid[2] < 0.3 ? 1 : (centroid[1] < 0.5 ? 2 : 3));
    }
  }
  const TemplateTable templates;
  const std::vector<char> interfaceVertex(cube.coordinates.size() / 3, 0);
  const RefinementContext context =
    templateContext(cube.coordinates, interfaceVertex, 0.04, templates);
  const PostedSplits noSplits;
  PartitionRefinement refinement;
  ConstrainedFaceMarks marks;
  markConstrainedFaces(partition, marks);
  for (int round = 0; round < 4; ++round)
  {
    std::vector<Face> boundaryFaces, interfaceFaces;
    findConstrainedFaces(partition, boundaryFaces, interfaceFaces);
    EdgeSet constrainedEdges;
    addFaceEdges(boundaryFaces, constrainedEdges);
    addFaceEdges(interfaceFaces, constrainedEdges);
    const EdgeFilter filter = round == 0 ? EdgeFilter() : EdgeFilter{ &constrainedEdges, true };
    const std::size_t tetsBefore = partition.tets.size();
    std::vector<std::size_t> origins;
    CHECK(refinePartition(partition, context, noSplits, refinement, filter, &origins, &marks).ok());
    CHECK(partition.tets.size() > tetsBefore);
    CHECK_EQUAL(marks.size(), partition.tets.size());

    boundaryFaces.clear();
    interfaceFaces.clear();
    findConstrainedFaces(partition, boundaryFaces, interfaceFaces);
    std::vector<Face> markedBoundary, markedInterface;
    appendMarkedFaces(partition, marks, markedBoundary, markedInterface);
    CHECK(!boundaryFaces.empty() && !interfaceFaces.empty());
    CHECK(markedBoundary == boundaryFaces);
    CHECK(markedInterface == interfaceFaces);
  }
}

// The templates compiled in at build time are the search's, entry for entry, and a table read
// from data that has been tampered with refuses to serve: a tet turned inside out, a corner moved,
// a tet dropped.
void test_compiled_templates_are_the_searched_ones()
{
  const TemplateTable searched;
  const TemplateTable compiled(compiledTemplateData());
  CHECK(searched.status().ok());
  CHECK(compiled.status().ok());
  for (int mask = 1; mask < 63; ++mask)
  {
    CHECK_EQUAL(compiled.mostChildren(mask), searched.mostChildren(mask));
    for (const auto& ranks : TemplateTable::rankOrders())
    {
      CHECK(compiled.partialSplit(mask, ranks) == searched.partialSplit(mask, ranks));
    }
  }
  CHECK_EQUAL(compiled.mostChildren(63), searched.mostChildren(63));

  const TemplateData data = compiledTemplateData();
  const std::uint32_t tets = data.offsets[TemplateData::Entries];
  const std::vector<std::uint8_t> original(data.corners, data.corners + 4 * tets);
  const auto refused =
    [&](const std::vector<std::uint8_t>& corners, const std::vector<std::uint32_t>& offsets)
  {
    return !TemplateTable(TemplateData{ offsets.data(), corners.data() }).status().ok();
  };
  const std::vector<std::uint32_t> offsets(data.offsets, data.offsets + TemplateData::Entries + 1);
  CHECK(!refused(original, offsets));
  std::mt19937 random(11);
  for (int trial = 0; trial < 20; ++trial)
  {
    const std::uint32_t t = random() % tets;
    std::vector<std::uint8_t> inverted = original;
    std::swap(inverted[4 * t + 2], inverted[4 * t + 3]);
    CHECK(refused(inverted, offsets));
    std::vector<std::uint8_t> moved = original;
    moved[4 * t + random() % 4] = static_cast<std::uint8_t>(random() % 10);
    CHECK(moved == original || refused(moved, offsets));
  }
  // The last tet of the first entry dropped: the entry's offset moves one back, so the next
  // entry starts with that tet.
  std::vector<std::uint32_t> shorter = offsets;
  --shorter[1];
  CHECK(refused(original, shorter));
}

int main()
{
  test_compiled_templates_are_the_searched_ones();
  test_every_template_case();
  test_face_marks_follow_the_children();
  test_most_children_bounds_every_template();
  test_shared_face_agreement();
  test_full_split_children_keep_three_quarters();
  test_passes_measure_only_what_the_last_pass_made();
  return cgmesh_test::finish("TestTemplates");
}

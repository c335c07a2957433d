// Awkward and bad inputs through adaptMesh(): each gives a valid conforming mesh or a clear error,
// and the input is never modified.
#include "AdaptationDriver.h"
#include "Core/FaceKey.h"
#include "CubeGenerator.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using namespace cgmesh;

namespace
{

TetMesh cube(int n, double scale = 1.0)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (double& c : mesh.coordinates)
  {
    c *= scale;
  }
  return mesh;
}

AdaptationOptions templateOptions(int partitions)
{
  AdaptationOptions options;
  options.numberOfPartitions = partitions;
  options.numberOfIterations = 1;
  options.edgeLengthFactor = 0.5;
  options.numberOfThreads = 2;
  return options;
}

// Runs, checks the input is untouched, and for a success checks validity and conservation.
Status refineAndCheck(
  const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result)
{
  const TetMesh copy = input;
  const Status status = adaptMesh(input, options, result);
  CHECK(copy.coordinates.size() == input.coordinates.size() && copy.tets == input.tets &&
    copy.regions == input.regions);
  CHECK(std::equal(copy.coordinates.begin(), copy.coordinates.end(), input.coordinates.begin(),
    [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }));
  if (!status.ok())
  {
    CHECK(result.mesh.tets.empty());
    CHECK(!status.message().empty() && status.message().find('\n') == std::string::npos);
    return status;
  }
  const MeshReport after = inspectMesh(result.mesh);
  if (!after.isValid())
  {
    std::cerr << after.describeProblems();
  }
  CHECK(after.isValid());
  return status;
}

void test_non_finite_coordinates_are_refused()
{
  for (double bad :
    { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    TetMesh mesh = cube(2);
    mesh.coordinates[3 * 5 + 1] = bad;
    AdaptationResult result;
    const Status status = refineAndCheck(mesh, templateOptions(4), result);
    CHECK(!status.ok());
    CHECK(status.message().find("NaN or infinite") != std::string::npos);
    // The mesh check (cgmesh check) calls such a mesh invalid too.
    const MeshReport report = inspectMesh(mesh);
    CHECK_EQUAL(report.nonFinitePoints, 1);
    CHECK(!report.isValid());
  }
}

void test_zero_volume_tets_are_refused()
{
  TetMesh mesh = cube(2);
  mesh.tets[3][3] = mesh.tets[3][2]; // repeats a point
  AdaptationResult result;
  Status status = refineAndCheck(mesh, templateOptions(4), result);
  CHECK(!status.ok() && status.message().find("zero volume") != std::string::npos);
  mesh = cube(2);
  mesh.coordinates.insert(mesh.coordinates.end(), { 0.25, 0.25, 0.0 }); // flat tet on the floor
  mesh.tets.push_back({ 0, 1, 3, mesh.numberOfPoints() - 1 });
  status = refineAndCheck(mesh, templateOptions(4), result);
  CHECK(!status.ok());
}

void test_inverted_tets_are_reoriented()
{
  const TetMesh reference = cube(3);
  const double volume = inspectMesh(reference).volume;
  for (int every : { 1, 2 }) // all inverted (Netgen), every other one (DOLFIN)
  {
    TetMesh mesh = reference;
    for (std::size_t t = 0; t < mesh.tets.size(); t += every)
    {
      std::swap(mesh.tets[t][0], mesh.tets[t][1]);
    }
    AdaptationResult result;
    CHECK(refineAndCheck(mesh, templateOptions(8), result).ok());
    CHECK_EQUAL(result.summary.reorientedTets,
      static_cast<std::int64_t>((mesh.tets.size() + every - 1) / every));
    const MeshReport report = inspectMesh(result.mesh);
    CHECK_EQUAL(report.invertedTets, 0);
    CHECK_CLOSE(report.volume, volume, 1e-12);
  }
}

// Two cubes side by side whose touching faces have their own copies of the points.
void test_touching_parts_without_shared_points_are_joined()
{
  TetMesh mesh = cube(2);
  const TetMesh second = cube(2);
  const PointId offset = mesh.numberOfPoints();
  for (PointId p = 0; p < second.numberOfPoints(); ++p)
  {
    mesh.coordinates.insert(
      mesh.coordinates.end(), { second.point(p)[0] + 1.0, second.point(p)[1], second.point(p)[2] });
  }
  for (Tet tet : second.tets)
  {
    for (PointId& p : tet)
    {
      p += offset;
    }
    mesh.tets.push_back(tet);
  }
  AdaptationResult result;
  CHECK(refineAndCheck(mesh, templateOptions(4), result).ok());
  CHECK_EQUAL(result.summary.gluedPoints, 9);
  CHECK_EQUAL(result.summary.keptApartPoints, 0);
  const MeshReport report = inspectMesh(result.mesh);
  CHECK_EQUAL(report.duplicatePoints, 0);
  CHECK_CLOSE(report.boundaryArea, 10.0, 1e-12); // the joined 2 x 1 x 1 box
}

// Assemblies of touching parts: glue where the contact conforms, keep apart where it does not.

std::vector<double> evenLines(double from, double to, int cells)
{
  std::vector<double> lines;
  for (int i = 0; i <= cells; ++i)
  {
    lines.push_back(i == cells ? to : from + (to - from) * i / cells);
  }
  return lines;
}

TetMesh kuhnBox(
  const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z)
{
  TetMesh mesh;
  CHECK(generateKuhnGrid({ x, y, z }, mesh).ok());
  return mesh;
}

// `second`'s points and tets appended to `first`, its points moved by `shift` along x.
TetMesh assemble(const TetMesh& first, const TetMesh& second, double shift)
{
  TetMesh mesh = first;
  const PointId offset = mesh.numberOfPoints();
  for (PointId p = 0; p < second.numberOfPoints(); ++p)
  {
    const double* x = second.point(p);
    mesh.coordinates.insert(mesh.coordinates.end(), { x[0] + shift, x[1], x[2] });
  }
  for (Tet tet : second.tets)
  {
    for (PointId& p : tet)
    {
      p += offset;
    }
    mesh.tets.push_back(tet);
  }
  return mesh;
}

// The output tets whose input tet satisfies `fromPart`, their points numbered anew.
template <typename Predicate>
TetMesh outputPart(const AdaptationResult& result, Predicate fromPart)
{
  TetMesh part;
  std::vector<PointId> newId(result.mesh.numberOfPoints(), -1);
  for (std::size_t t = 0; t < result.mesh.tets.size(); ++t)
  {
    if (!fromPart(result.parentCell[t]))
    {
      continue;
    }
    Tet tet = result.mesh.tets[t];
    for (PointId& p : tet)
    {
      if (newId[p] < 0)
      {
        newId[p] = part.numberOfPoints();
        part.coordinates.insert(
          part.coordinates.end(), result.mesh.point(p), result.mesh.point(p) + 3);
      }
      p = newId[p];
    }
    part.tets.push_back(tet);
  }
  return part;
}

// Boundary faces of `mesh` lying in the plane x = `x` (within 1e-9).
int boundaryFacesAt(const TetMesh& mesh, double x)
{
  int faces = 0;
  forEachDistinctFace(mesh.tets[0].data(), mesh.tets.size(),
    [&](const Face& face, std::size_t, std::size_t, std::size_t count)
    {
      faces += count == 1 &&
        std::all_of(face.begin(), face.end(),
          [&](PointId p) { return std::abs(mesh.point(p)[0] - x) < 1e-9; });
    });
  return faces;
}

const AdaptationWarning* findWarning(const AdaptationSummary& summary, WarningKind kind)
{
  for (const AdaptationWarning& warning : summary.warnings)
  {
    if (warning.kind == kind)
    {
      return &warning;
    }
  }
  return nullptr;
}

std::vector<AdaptationOptions> bothMethods(int partitions)
{
  AdaptationOptions delaunay = templateOptions(partitions);
  delaunay.method = RefinementMethod::Delaunay;
  delaunay.volumeFactor = 0.1;
  return { templateOptions(partitions), delaunay };
}

// Two boxes meshed independently, [0,1]^3 with 2 cells per side and [1,2]x[0,1]^2 with 4: the
// second box's x = 1 face has all nine grid points of the first one's, but no face in common.
// Merging the coincident points would pin the boxes together at nine vertices and leave them
// unglued in between; they are kept apart instead and refined as two separate meshes. Also with
// the second box 1e-13 away or overlapping by 1e-13 (near-duplicates). With Delaunay and one
// partition, TetGen refines both boxes in one call, coincident points included.
void test_touching_parts_with_independent_meshes_stay_apart()
{
  const TetMesh coarse = kuhnBox(evenLines(0, 1, 2), evenLines(0, 1, 2), evenLines(0, 1, 2));
  const TetMesh fine = kuhnBox(evenLines(1, 2, 4), evenLines(0, 1, 4), evenLines(0, 1, 4));
  const CellId coarseTets = coarse.numberOfTets();
  for (double shift : { 0.0, 1e-13, -1e-13 }) // touching, a hair apart, overlapping by a hair
  {
    const TetMesh mesh = assemble(coarse, fine, shift);
    for (const AdaptationOptions& options : bothMethods(6))
    {
      for (int partitions : { 1, 6 }) // one partition: TetGen gets both boxes in one call
      {
        AdaptationOptions run = options;
        run.numberOfPartitions = partitions;
        AdaptationResult result;
        const Status status = adaptMesh(mesh, run, result);
        CHECK(status.ok());
        if (!status.ok())
        {
          std::cerr << status.message() << "\n";
          continue;
        }
        CHECK_EQUAL(result.summary.gluedPoints, 0);
        CHECK_EQUAL(result.summary.keptApartPoints, 9);
        CHECK_EQUAL(result.summary.delaunayFallbacks, 0);
        CHECK(run.method == RefinementMethod::Template || result.summary.tetgenPoints > 0);
        CHECK(result.mesh.numberOfTets() > 4 * mesh.numberOfTets());
        const AdaptationWarning* warning =
          findWarning(result.summary, WarningKind::CoincidentPointsKeptApart);
        CHECK(warning != nullptr &&
          warning->text.find(
            "kept 9 coincident points apart (the first is point 27 at (1, 0, 0))") !=
            std::string::npos);
        CHECK(findWarning(result.summary, WarningKind::CoincidentPointsMerged) == nullptr);

        const MeshReport whole = inspectMesh(result.mesh);
        CHECK_EQUAL(whole.overSharedFaces + whole.misorientedFacePairs + whole.invertedTets +
            whole.degenerateTets + whole.unusedPoints,
          0);
        CHECK_CLOSE(whole.boundaryArea, 12.0, 1e-12); // the contact is boundary on both sides
        std::vector<char> inFirst(result.mesh.numberOfPoints(), 0);
        std::vector<char> inSecond(result.mesh.numberOfPoints(), 0);
        for (std::size_t t = 0; t < result.mesh.tets.size(); ++t)
        {
          for (PointId p : result.mesh.tets[t])
          {
            (result.parentCell[t] < coarseTets ? inFirst : inSecond)[p] = 1;
          }
        }
        PointId shared = 0;
        for (PointId p = 0; p < result.mesh.numberOfPoints(); ++p)
        {
          shared += inFirst[p] && inSecond[p];
        }
        CHECK_EQUAL(shared, 0);
        // Each box on its own: a conforming mesh (no crack: its boundary is its surface alone)
        // of its volume, without coincident points.
        for (bool first : { true, false })
        {
          const TetMesh part =
            outputPart(result, [&](CellId parent) { return (parent < coarseTets) == first; });
          const MeshReport report = inspectMesh(part);
          if (!report.isValid())
          {
            std::cerr << report.describeProblems();
          }
          CHECK(report.isValid());
          CHECK_CLOSE(report.volume, 1.0, 1e-12);
          CHECK_CLOSE(report.boundaryArea, 6.0, 1e-12);
          CHECK(boundaryFacesAt(part, first ? 1.0 : 1.0 + shift) > 0);
        }
      }
    }
  }
}

// One Kuhn grid of [0,2]x[0,1]^2 whose x > 1 half has its own copies of its points: the copies on
// x = 1 are corners of faces matching the other half's, so the halves are glued into one
// conforming mesh (also when the copies are 1e-13 away).
void test_duplicated_halves_with_matching_faces_are_glued()
{
  const TetMesh grid = kuhnBox(evenLines(0, 2, 4), evenLines(0, 1, 2), evenLines(0, 1, 2));
  for (double shift : { 0.0, 1e-13 })
  {
    TetMesh mesh = grid;
    std::vector<PointId> copyOf(grid.numberOfPoints(), -1);
    for (Tet& tet : mesh.tets)
    {
      double centroidX = 0;
      for (PointId p : tet)
      {
        centroidX += 0.25 * grid.point(p)[0];
      }
      if (centroidX < 1)
      {
        continue;
      }
      for (PointId& p : tet)
      {
        if (copyOf[p] < 0)
        {
          copyOf[p] = mesh.numberOfPoints();
          const double* x = grid.point(p);
          mesh.coordinates.insert(mesh.coordinates.end(), { x[0] + shift, x[1], x[2] });
        }
        p = copyOf[p];
      }
    }
    CHECK_EQUAL(boundaryFacesAt(mesh, 1.0), 16); // the input: two unglued copies of 8 faces
    for (const AdaptationOptions& options : bothMethods(6))
    {
      AdaptationResult result;
      CHECK(refineAndCheck(mesh, options, result).ok());
      CHECK_EQUAL(result.summary.gluedPoints, 9);
      CHECK_EQUAL(result.summary.keptApartPoints, 0);
      CHECK(findWarning(result.summary, WarningKind::CoincidentPointsMerged) != nullptr);
      CHECK(findWarning(result.summary, WarningKind::CoincidentPointsKeptApart) == nullptr);
      CHECK_EQUAL(result.summary.delaunayFallbacks, 0);
      const MeshReport report = inspectMesh(result.mesh);
      CHECK_EQUAL(report.duplicatePoints, 0);
      CHECK_CLOSE(report.volume, 2.0, 1e-12);
      CHECK_CLOSE(report.boundaryArea, 10.0, 1e-12);
      CHECK(result.mesh.numberOfTets() > 4 * mesh.numberOfTets());
      CHECK_EQUAL(boundaryFacesAt(result.mesh, 1.0), 0); // x = 1 is interior now
    }
  }
}

// Every tet with its own four points (as some exporters write meshes): every face matches its
// neighbour's copy, so the whole mesh is glued back together.
void test_exploded_mesh_is_glued_back()
{
  const TetMesh reference = cube(2);
  TetMesh mesh;
  for (const Tet& tet : reference.tets)
  {
    Tet own;
    for (int k = 0; k < 4; ++k)
    {
      own[k] = mesh.numberOfPoints();
      mesh.coordinates.insert(
        mesh.coordinates.end(), reference.point(tet[k]), reference.point(tet[k]) + 3);
    }
    mesh.tets.push_back(own);
  }
  AdaptationResult result;
  CHECK(refineAndCheck(mesh, templateOptions(4), result).ok());
  CHECK_EQUAL(result.summary.gluedPoints, mesh.numberOfPoints() - reference.numberOfPoints());
  CHECK_EQUAL(result.summary.keptApartPoints, 0);
  const MeshReport report = inspectMesh(result.mesh);
  CHECK_CLOSE(report.boundaryArea, 6.0, 1e-12);
  CHECK_CLOSE(report.volume, 1.0, 1e-12);
}

// Glued where the faces match, apart where they do not, in one contact: the second box repeats
// the first box's x = 1 faces for y < 0.5 and is finer for y > 0.5. The six points of the matching
// faces are glued; the three on y = 1 are kept apart; the y > 0.5 half of the contact stays an
// inner crack (its area counts twice in the boundary).
void test_partly_matching_contact_is_glued_where_it_matches()
{
  const TetMesh first = kuhnBox(evenLines(0, 1, 2), evenLines(0, 1, 2), evenLines(0, 1, 2));
  const TetMesh second = kuhnBox(evenLines(1, 2, 2), { 0, 0.5, 0.75, 1 }, evenLines(0, 1, 2));
  const TetMesh mesh = assemble(first, second, 0);
  for (const AdaptationOptions& options : bothMethods(6))
  {
    AdaptationResult result;
    CHECK(adaptMesh(mesh, options, result).ok());
    CHECK_EQUAL(result.summary.gluedPoints, 6);
    CHECK_EQUAL(result.summary.keptApartPoints, 3);
    CHECK_EQUAL(result.summary.delaunayFallbacks, 0);
    const MeshReport report = inspectMesh(result.mesh);
    CHECK_EQUAL(report.overSharedFaces + report.misorientedFacePairs + report.invertedTets +
        report.degenerateTets + report.unusedPoints,
      0);
    CHECK_CLOSE(report.volume, 2.0, 1e-12);
    CHECK_CLOSE(report.boundaryArea, 11.0, 1e-12);
  }
}

// A part repeated on top of itself: every boundary face has a coincident copy, but its tet lies on
// the same side, so nothing is glued (gluing would put four tets on the faces).
void test_stacked_copies_are_not_glued()
{
  const TetMesh mesh = assemble(cube(2), cube(2), 0);
  AdaptationResult result;
  CHECK(adaptMesh(mesh, templateOptions(4), result).ok());
  CHECK_EQUAL(result.summary.gluedPoints, 0);
  CHECK_EQUAL(result.summary.keptApartPoints, 27);
  const MeshReport report = inspectMesh(result.mesh);
  CHECK_EQUAL(report.overSharedFaces, 0);
  CHECK_CLOSE(report.volume, 2.0, 1e-12);
}

void test_scale_invariance()
{
  for (double scale : { 1e-6, 1e6, 1e-4 })
  {
    const TetMesh mesh = cube(3, scale);
    AdaptationResult result;
    CHECK(refineAndCheck(mesh, templateOptions(8), result).ok());
    CHECK(result.mesh.numberOfTets() > mesh.numberOfTets());
    CHECK_CLOSE(inspectMesh(result.mesh).volume / (scale * scale * scale), 1.0, 1e-9);
  }
}

void test_tiny_meshes_and_partition_counts()
{
  TetMesh one;
  one.coordinates = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  one.tets = { { 0, 1, 2, 3 } };
  one.regions = { -7 };
  AdaptationResult result;
  CHECK(refineAndCheck(one, templateOptions(1024), result).ok());
  CHECK_EQUAL(result.summary.plan.partitions, 1);
  CHECK(result.mesh.numberOfTets() > 1);
  CHECK(result.mesh.regions == std::vector<int>(result.mesh.tets.size(), -7));

  TetMesh empty;
  CHECK(refineAndCheck(empty, templateOptions(4), result).ok());
  CHECK(result.mesh.tets.empty());

  CHECK(refineAndCheck(cube(2), templateOptions(1), result).ok());
  CHECK_EQUAL(result.summary.numberOfColors, 1);
  CHECK(refineAndCheck(cube(2), templateOptions(48), result).ok());
  CHECK_EQUAL(result.summary.plan.partitions, 48);
}

void test_size_guard_refuses_before_refining()
{
  AdaptationOptions options = templateOptions(8);
  options.numberOfIterations = 3;
  options.edgeLengthFactor = 0.1;
  options.maximumNumberOfCells = 50000;
  AdaptationResult result;
  const Status status = refineAndCheck(cube(4), options, result);
  CHECK(!status.ok());
  CHECK(status.message().find("MaximumNumberOfCells") != std::string::npos);
  options.maximumNumberOfCells = 0; // no limit
  options.numberOfIterations = 1;
  CHECK(refineAndCheck(cube(4), options, result).ok());
}

} // namespace

int main()
{
  test_non_finite_coordinates_are_refused();
  test_zero_volume_tets_are_refused();
  test_inverted_tets_are_reoriented();
  test_touching_parts_without_shared_points_are_joined();
  test_touching_parts_with_independent_meshes_stay_apart();
  test_duplicated_halves_with_matching_faces_are_glued();
  test_exploded_mesh_is_glued_back();
  test_partly_matching_contact_is_glued_where_it_matches();
  test_stacked_copies_are_not_glued();
  test_scale_invariance();
  test_tiny_meshes_and_partition_counts();
  test_size_guard_refuses_before_refining();
  return cgmesh_test::finish("TestInputRepairs");
}

// A size field: a target edge length h per point. Template refinement splits an edge (a, b) when
// it is longer than sqrt(2) times h at its midpoint, (h(a) + h(b)) / 2, and gives the new vertex
// that h; an edge is within the field when its length lies in [h / sqrt(2), sqrt(2) h] (the
// measure MMG reports), which repeated halving reaches from above.
#ifndef cgmesh_SizeField_h
#define cgmesh_SizeField_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace cgmesh
{

// Whether an edge of squared length `lengthSquared` between points of sizes ha and hb is too long.
inline bool longerThanSize(double lengthSquared, double ha, double hb)
{
  const double h = 0.5 * (ha + hb);
  return lengthSquared > 2.0 * h * h;
}

// Whether it is too short: below h / sqrt(2), what coarsening collapses. Never where a size is
// infinite (a point outside a refinement selection).
inline bool shorterThanSize(double lengthSquared, double ha, double hb)
{
  const double h = 0.5 * (ha + hb);
  return std::isfinite(h) && lengthSquared < 0.5 * h * h;
}

// Checks one size per point, each positive and finite where a tet uses the point.
Status checkSizeField(const TetMesh& mesh);

// Limits the field's gradation: afterwards h(b) <= gradation * h(a) for every edge (a, b) of the
// mesh, by lowering sizes only (each point gets min over all points p of h(p) * gradation^hops).
// Deterministic; gradation must be at least 1.
void limitSizeGradation(const TetMesh& mesh, double gradation, std::vector<double>& sizes);

// Edges by their length over h at the midpoint.
struct EdgeSizeReport
{
  std::int64_t edges = 0;
  double shareWithinBounds = 0; // length / h in [1/sqrt(2), sqrt(2)]
  // Edge counts in the bins of length / h split at 1/2, 1/sqrt(2), 1, sqrt(2) and 2 (each bin
  // closed below).
  std::array<std::int64_t, 6> histogram = {};
};

// Concurrently through `parallelFor`; the report is the same for any schedule.
Status measureEdgeSizes(
  const TetMesh& mesh, const ParallelFor& parallelFor, EdgeSizeReport& report);

// Per tet: its longest edge over the mean size of its corners (0 where a corner lies outside a
// refinement selection, see below).
Status edgeLengthRatios(
  const TetMesh& mesh, const ParallelFor& parallelFor, std::vector<double>& ratios);

// How many regular tets of its corners' mean size fill `tet` (a positively oriented tet of
// `coordinates`, with `sizes` per point): the work a size field asks of it, 0 where a corner's
// size is infinite (outside a refinement selection).
double regularTetsFilling(
  const Tet& tet, const std::vector<double>& coordinates, const std::vector<double>& sizes);

// Weights for partitioning by the work a size field puts into each tet (TetWeights): 1 for the
// tet itself plus its forecast output, regularTetsFilling(), scaled to a mean of 16 (less on
// meshes of over 2^26 tets, so that the total stays within METIS' 32-bit indices). With the
// field graded to 1.3 per edge, a FinFET's forecast runs from a few tets to thousands.
std::vector<std::int64_t> forecastWeights(const TetMesh& mesh);

// Where refinement may happen: tets of the listed regions (empty: any region) whose bounding box
// meets `box` (xmin, ymin, zmin, xmax, ymax, zmax; null: no box).
std::vector<char> selectTets(
  const TetMesh& mesh, const std::vector<int>& regions, const std::array<double, 6>* box);

// Restricts refinement to the selected tets by way of the sizes: a point of no selected tet gets
// an infinite size, so no edge touching it is split; the others keep their size, or, without a
// size field (`sizes` empty), get threshold / sqrt(2), which splits exactly the edges longer than
// the threshold. Midpoints of two selected points are selected in turn, so later passes stay in
// the selection, and the tets outside change only where they share an edge between two selected
// points (closure templates on the faces they share with the selection).
void restrictToSelection(const TetMesh& mesh, const std::vector<char>& selectedTets,
  double threshold, std::vector<double>& sizes);

// Flags the points restrictToSelection() put outside the selection (those of infinite size; a
// size field given by the user is finite everywhere), for ImprovementParameters::keptPoints.
std::vector<char> pointsOutsideSelection(const std::vector<double>& sizes);

} // namespace cgmesh

#endif

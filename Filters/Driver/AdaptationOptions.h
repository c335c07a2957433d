// The options of one adaptation run and the table of user parameters. Each parameter is a field
// below and one row of the table, which gives its property name, command-line flag, range,
// default and documentation: the options' defaults, the filter's properties and clamps, the
// command line's parsing and --help all come from it, and a test holds the ParaView XML to it.
// Adding a parameter: a field and a row here, a line in vtkCoarseGrainedMeshAdaptation.h, a
// property in the XML.
#ifndef cgmesh_AdaptationOptions_h
#define cgmesh_AdaptationOptions_h

#include "Parameters.h"

#include <array>
#include <climits>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace cgmesh
{

enum class RefinementMethod
{
  Template, // split long edges by templates
  Delaunay  // templates on interfaces, TetGen inside partitions
};

enum class PartitionerKind
{
  Automatic,  // Hilbert for templates, curve chunks for Delaunay (resolved in the plan)
  Metis,      // METIS k-way on the dual graph
  Hilbert,    // equal runs along a Hilbert curve through the tet centroids
  CurveChunks // Hilbert chunks, each cut by METIS, concurrently
};

struct AdaptationOptions
{
  AdaptationOptions() { applyDefaults(*this); }

  // User parameters: documented in parameterTable() below, which also sets their defaults. The
  // zero initialisers only make the first assignment's "did it change" read a defined value.
  int numberOfPartitions{};
  PartitionerKind partitioner{};
  std::string regionArrayName; // read by the VTK adapter, which fills TetMesh::regions
  bool partitionByRegion{};
  int partitionsPerRegion{};
  std::string coloring;
  RefinementMethod method{};
  int numberOfIterations{};
  double maximumEdgeLength{};
  double edgeLengthFactor{};
  std::string sizeArrayName; // read by the VTK adapter, which fills TetMesh::sizes
  double sizeGradation{};
  bool coarsen{};                // with a size field: collapse edges shorter than h / sqrt(2)
  std::string refinementRegions; // "2,5": region ids (parsed into the plan)
  std::string refinementBox;     // "x0,y0,z0,x1,y1,z1"
  // Integer point arrays to interpolate (and round) like fields, comma-separated; the others are
  // labels (read by the VTK adapter).
  std::string interpolatedPointArrays;
  // Floating-point point arrays to treat as labels, comma-separated (read by the VTK adapter).
  std::string labelPointArrays;
  double maximumVolume{};
  double volumeFactor{};
  double radiusEdgeRatio{};
  bool improveQuality{};
  bool improveInput{}; // improve (a sliver-laden one meshed anew) before refining
  int improvementPasses{};
  int numberOfThreads{};
  std::int64_t maximumNumberOfCells{};
  bool diagnostics{};

  // For tests and stress runs, not user parameters.
  // Delaunay: run TetGen calls one at a time even where they could overlap.
  bool serializeTetGen = false;
  // Partitions whose TetGen call is made to fail, to exercise the fallback.
  std::vector<int> simulateTetGenFailureIn;
  // Delaunay: the sweep that meshes the slivers at former interfaces anew (RemeshSweep.h); off
  // only to measure what it does.
  bool remeshAcrossFormerInterfaces = true;
  // Template: a partition a pass found nothing to split in is not read again while nothing
  // changes it, and a pass measures only the tets the pass before split (ColorLoop.cxx,
  // refinePartition's `passedUnsplit`); off only to check that skipping them changes nothing.
  bool skipSettledPartitions = true;

  // Set when the mesh is one piece of a mesh spread over processes (the filter under MPI): face
  // diagonals then follow coordinates, which the processes sharing a face agree on, not ids.
  bool orderCornersByCoordinates = false;
  // Set when the boundary's triangulation must stay as given up to refinement: a piece of a mesh
  // spread over processes shares its boundary faces with other pieces. Then a sliver-laden input
  // is meshed anew around its slivers with its boundary faces kept, never as a whole with its
  // boundary re-triangulated.
  bool keepBoundaryTriangulation = false;
  // Triangles tagged on boundary and interface faces (the filter's triangle cells): each one's
  // sorted corners with its surface class, equal for triangles of equal cell data, sorted by
  // corners. A sliver-laden input is then meshed anew as a whole (with keepBoundaryTriangulation
  // off), each class's faces free to split and to merge only with coplanar ones of their class;
  // AdaptationSummary::boundaryRetriangulated then tells the caller to find the triangles'
  // children by position (findTriangleChildrenByPosition).
  std::vector<std::pair<std::array<std::int64_t, 3>, int>> surfaceClasses;
  // Whether the result needs point provenance (the weights that interpolate point data). Without
  // point data there is nothing to interpolate, and the merge skips locating moved points in the
  // input and expanding every new point's recipe.
  bool pointProvenance = true;
  // Whether the output tets take cell data from their parents beyond the region ids (the input's
  // other cell arrays): then a Delaunay tet's parent must be the input tet holding its centroid.
  // Without such data, its parent is the input tet it descends from in TetGen, of the same
  // partition and region, and nothing needs locating (RefinementContext::locateTetGenOutput).
  bool cellDataByParent = true;

  // Called on the calling thread only: fraction in [0, 1], never decreasing, and the phase name.
  std::function<void(double fraction, const char* phase)> progress;
  // Polled on the calling thread between colours and phases; returning true aborts the run.
  std::function<bool()> abortRequested;
};

inline const std::vector<ParameterSpec>& parameterTable()
{
  using K = ParameterKind;
  using S = MethodScope;
  using O = AdaptationOptions;
  static const std::vector<ParameterSpec> table = {
    { "NumberOfPartitions", "--partitions", "N", K::Integer, 0, INT_MAX, 0, "", S::Any,
      "partitions; 0 = automatic: 1024 for Template, for Delaunay one per about 30,000 "
      "forecast output tets (8 to 1024); reduced to the number of tets of a smaller mesh (with "
      "a warning when requested); not used with PartitionByRegion",
      &O::numberOfPartitions },
    { "Partitioner", "--partitioner", "NAME", K::Choice, 0, 3, 0, "", S::Any,
      "how the mesh is cut into NumberOfPartitions parts, of equal forecast work with a size "
      "field, regions or a box (else of equal tet counts); not used with PartitionByRegion, "
      "which runs METIS inside each region",
      &O::partitioner,
      { { "auto", "Automatic",
          "Hilbert for Template (no graph partitioning; templates do not mind the longer "
          "interfaces), curve chunks for Delaunay (short interfaces: fewer pre-split interface "
          "edges)" },
        { "metis", "METIS",
          "k-way on the whole dual graph: compact parts, the shortest interfaces; one serial "
          "METIS call whose cost grows with the partition count" },
        { "hilbert", "Hilbert",
          "equal runs along a Hilbert curve through the tet centroids: one sort, the same cost "
          "for any count, longer interfaces" },
        { "curve-chunks", "CurveChunks",
          "from 400,000 tets: the Hilbert curve cuts the mesh into one chunk per 200,000 tets "
          "(at most one per 16 partitions), METIS cuts every chunk's dual graph, the chunks at "
          "once in worker processes: a few percent more interface points than METIS; a smaller "
          "mesh goes to METIS whole" } } },
    { "RegionArrayName", "--region-array", "NAME", K::Text, 0, 0, 0, "", S::Any,
      "numeric cell array of material/region ids; empty or None: the input's integer cell "
      "arrays (ids, ghost flags and cgmesh's own arrays excepted) are kept as material labels "
      "together, so no material interface moves",
      &O::regionArrayName },
    { "InterpolatedPointArrays", "--interpolate-arrays", "NAMES", K::Text, 0, 0, 0, "", S::Any,
      "comma-separated integer point arrays to interpolate and round like fields; the other "
      "integer point arrays are labels: a new point takes the value its sources share, else 0",
      &O::interpolatedPointArrays },
    { "LabelPointArrays", "--label-arrays", "NAMES", K::Text, 0, 0, 0, "", S::Any,
      "comma-separated floating-point point arrays to keep as labels (flags stored as floats): a "
      "new point takes the value its sources share, else 0; their values must be finite",
      &O::labelPointArrays },
    { "PartitionByRegion", "--partition-by-region", "", K::Boolean, 0, 1, 0, "", S::Any,
      "cut along the regions of RegionArrayName instead of METIS on the whole mesh: no partition "
      "holds two regions",
      &O::partitionByRegion },
    { "PartitionsPerRegion", "--partitions-per-region", "N", K::Integer, 1, INT_MAX, 1, "", S::Any,
      "with PartitionByRegion: METIS partitions within each region", &O::partitionsPerRegion },
    { "ColoringAlgorithm", "--coloring", "NAME", K::Choice, 0, 3, 1, "", S::Any,
      "colouring of the partition graph; every one gives the same colours for any thread count",
      &O::coloring,
      { { "greedy", "Greedy", "first fit, serial, unbalanced" },
        { "greedy-lu", "Greedy-LU", "least-used permissible colour, serial, balanced" },
        { "iterative", "Iterative", "speculative parallel colouring, conflict rounds" },
        { "recoloring", "Recoloring", "parallel rebalancing of an initial colouring" } } },
    { "Method", "--method", "NAME", K::Choice, 0, 1, 0, "", S::Any,
      "serial refinement kernel run on each partition", &O::method,
      { { "template", "Template", "split long edges by conforming templates" },
        { "delaunay", "Delaunay", "templates on interfaces, TetGen inside partitions" } } },
    { "NumberOfIterations", "--iterations", "K", K::Integer, 1, INT_MAX, 1, "", S::Any,
      "refinement passes at most; they stop after one that adds no point", &O::numberOfIterations },
    { "MaximumEdgeLength", "--max-edge-length", "L", K::Real, 0, Unbounded, 0, "", S::Template,
      "split edges longer than L (absolute); 0: use EdgeLengthFactor", &O::maximumEdgeLength },
    { "EdgeLengthFactor", "--edge-length-factor", "F", K::Real, 0, Unbounded, 0.5, "", S::Template,
      "split edges longer than F x the input's mean edge length", &O::edgeLengthFactor },
    { "SizeArrayName", "--size-array", "NAME", K::Text, 0, 0, 0, "", S::Any,
      "point array (or cell array, averaged to the points) of target edge lengths h, instead of "
      "the threshold or volume bound: Template splits edges longer than sqrt(2) h at their "
      "midpoint (set NumberOfIterations high enough: passes stop when nothing changes); "
      "Delaunay gives TetGen 0.7 h per point as its size bound (switch m)",
      &O::sizeArrayName },
    { "SizeGradation", "--size-gradation", "G", K::Real, 1, Unbounded, 1.3, "", S::Any,
      "with SizeArrayName: the field is lowered until neighbouring points' sizes differ by at "
      "most this factor per edge (as MMG's -hgrad); a large value leaves it as given",
      &O::sizeGradation },
    { "Coarsen", "--no-coarsen", "", K::Boolean, 0, 1, 1, "", S::Any,
      "with SizeArrayName: collapse edges shorter than h / sqrt(2) at vertices on no boundary or "
      "material interface, keeping every tet valid and no worse than mean ratio 0.3 (or its "
      "ring's worst); --no-coarsen only refines",
      &O::coarsen },
    { "RefinementRegions", "--refine-regions", "IDS", K::Text, 0, 0, 0, "", S::Template,
      "comma-separated region ids of RegionArrayName: only their tets are refined, the others "
      "only where they share a face with them (closure templates); empty: every region",
      &O::refinementRegions },
    { "RefinementBox", "--refine-box", "X0,Y0,Z0,X1,Y1,Z1", K::Text, 0, 0, 0, "", S::Template,
      "only tets whose bounding box meets this box are refined (with RefinementRegions: tets in "
      "both); empty: everywhere",
      &O::refinementBox },
    { "MaximumVolume", "--max-volume", "V", K::Real, 0, Unbounded, 0, "", S::Delaunay,
      "TetGen's volume bound (switch a), absolute; 0: use VolumeFactor", &O::maximumVolume },
    { "VolumeFactor", "--volume-factor", "F", K::Real, 0, Unbounded, 0.1, "", S::Delaunay,
      "volume bound V = F x the input's mean tet volume; interface edges are split by templates "
      "down to (6 sqrt(2) V)^(1/3), the edge of the regular tet of volume V",
      &O::volumeFactor },
    { "RadiusEdgeRatio", "--radius-edge-ratio", "Q", K::Real, 1, Unbounded, 2, "", S::Delaunay,
      "TetGen's radius-edge quality bound (switch q); smaller asks for better tets and more points",
      &O::radiusEdgeRatio },
    { "ImproveQuality", "--no-improve", "", K::Boolean, 0, 1, 1, "", S::Any,
      "improve the tets after refinement (edge removal, face swaps, guarded smoothing), then "
      "again over box partitions across the former interfaces; --no-improve skips it",
      &O::improveQuality },
    { "ImproveInput", "--no-improve-input", "", K::Boolean, 0, 1, 1, "", S::Any,
      "with ImproveQuality, also improve the input's tets before refining them, as the refined "
      "ones are. Template: children keep their parent's shape, so this does the work on an "
      "eighth of the tets per pass (not with RefinementRegions or RefinementBox, which leave the "
      "other tets as they are). An input with more than 0.1% of its tets under 1 degree is "
      "first meshed anew by TetGen as a whole from its boundary and interface faces, which "
      "TetGen may split, then improved (Delaunay with a volume bound and at most 240,000 "
      "forecast output tets: refined to the bound in that same call, the passes then only "
      "improving; Delaunay across MPI pieces: around its slivers, its boundary and interface "
      "edges split as refinement splits them; Template: not across MPI pieces, nor with "
      "RefinementRegions or RefinementBox); --no-improve-input "
      "refines the input as given, and a sliver-laden one with a warning (Delaunay: slow, as "
      "TetGen refines its partitions against the slivers' faces)",
      &O::improveInput },
    { "NumberOfImprovementPasses", "--improve-passes", "N", K::Integer, 0, 20, 2, "", S::Any,
      "passes of edge removal, face swaps and smoothing per partition in each sweep",
      &O::improvementPasses },
    { "NumberOfThreads", "--threads", "T", K::Integer, 0, INT_MAX, 0, "", S::Any,
      "OpenMP threads, 0 = all cores; the output does not depend on it", &O::numberOfThreads },
    { "MaximumNumberOfCells", "--max-cells", "N", K::Count, 0, LargestExactCount, 100000000, "",
      S::Any,
      "size guard: refuse, before allocating them, a refinement forecast to make more tets; "
      "0 = no limit",
      &O::maximumNumberOfCells },
    { "Diagnostics", "--diagnostics", "", K::Boolean, 0, 1, 0, "", S::Any,
      "also put into the output's field data the diagnostics that are text or may be empty "
      "(Method and ColoringAlgorithm names, FallbackPartitions), which some readers (meshio) "
      "refuse; the numbers are always there",
      &O::diagnostics },
  };
  return table;
}

} // namespace cgmesh

#endif

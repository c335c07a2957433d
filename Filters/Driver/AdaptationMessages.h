// Warnings of an adaptation run, typed: front ends switch on the kind (the filter sums up
// fallbacks, the command line counts them) and show the text.
#ifndef cgmesh_AdaptationMessages_h
#define cgmesh_AdaptationMessages_h

#include <string>
#include <utility>

namespace cgmesh
{

enum class WarningKind
{
  PartitionsReduced,         // more partitions requested than the mesh has tets
  InvertedTetsReoriented,    // input tets with negative volume were turned around
  CoincidentPointsMerged,    // copies of the corners of matching faces were glued into one point
  CoincidentPointsKeptApart, // coincident points not on matching faces were left distinct
  UnusedPointsRemoved,       // points no tet uses were left out of the output
  DelaunayFallback,          // TetGen failed on a partition, refined by templates instead
  SweepRemeshFailed,         // TetGen failed on a box of the Delaunay sweep, left as refined
  InputRemeshFailed,         // TetGen failed on a cluster of the input's slivers, left as it was
  SliverLadenInputKept,      // a sliver-laden input was refined as given
  NothingRefined             // the run added no point (the command line's check of its output)
};

// The kind's name in reports ("delaunay-fallback").
inline const char* warningKindName(WarningKind kind)
{
  switch (kind)
  {
    case WarningKind::PartitionsReduced:
      return "partitions-reduced";
    case WarningKind::InvertedTetsReoriented:
      return "inverted-tets-reoriented";
    case WarningKind::CoincidentPointsMerged:
      return "coincident-points-merged";
    case WarningKind::CoincidentPointsKeptApart:
      return "coincident-points-kept-apart";
    case WarningKind::UnusedPointsRemoved:
      return "unused-points-removed";
    case WarningKind::DelaunayFallback:
      return "delaunay-fallback";
    case WarningKind::SweepRemeshFailed:
      return "sweep-remesh-failed";
    case WarningKind::InputRemeshFailed:
      return "input-remesh-failed";
    case WarningKind::SliverLadenInputKept:
      return "sliver-laden-input-kept";
    case WarningKind::NothingRefined:
      return "nothing-refined";
  }
  return "unknown";
}

struct AdaptationWarning
{
  WarningKind kind;
  int partition = -1; // the partition it applies to, or -1
  std::string text;   // one line, for people
};

} // namespace cgmesh

#endif

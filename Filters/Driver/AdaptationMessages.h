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
  PartitionsReduced,      // more partitions requested than the mesh has tets
  InvertedTetsReoriented, // input tets with negative volume were turned around
  CoincidentPointsMerged, // input points with equal coordinates were merged
  UnusedPointsRemoved,    // points no tet uses were left out of the output
  DelaunayFallback        // TetGen failed on a partition, refined by templates instead
};

struct AdaptationWarning
{
  WarningKind kind;
  int partition = -1; // the partition it applies to, or -1
  std::string text;   // one line, for people
};

} // namespace cgmesh

#endif

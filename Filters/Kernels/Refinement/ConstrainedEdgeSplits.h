// The interface rounds of the Delaunay method: before TetGen refines a partition with its boundary
// and material-interface faces kept, templates split those faces' edges down to the interface
// length, so that neighbouring partitions agree on them (they heal the same splits from the
// outbox, round by round).
#ifndef cgmesh_ConstrainedEdgeSplits_h
#define cgmesh_ConstrainedEdgeSplits_h

#include "Core/FaceKey.h"
#include "Refinement/PartitionRefiner.h"

#include <vector>

namespace cgmesh
{

// Adds the three edges of each face to `edges`.
void addFaceEdges(const std::vector<Face>& faces, EdgeSet& edges);

// Splits the partition's boundary and material-interface edges longer than
// `context.squaredThreshold` by templates, in rounds (a split edge's halves may still be too
// long), at most eight. Leaves the faces TetGen must keep, as they stand after the last round and
// each list sorted, in `boundaryFaces` and `regionInterfaceFaces`.
Status splitConstrainedEdges(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, PartitionRefinement& refinement, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces);

} // namespace cgmesh

#endif

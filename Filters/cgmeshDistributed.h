// The steps the filter adds when its input is one piece of a mesh spread over processes (ParaView's
// MPI): one input spread over every process, the threshold or volume bound of the whole mesh
// instead of the piece's, and one global id per point after refinement. Refinement itself stays
// local: every piece refines its own tets, and the pieces conform because a shared face is
// refined alike on both sides (the same split decision per edge, face diagonals by coordinates,
// frozen piece boundaries); docs/design.md, section 11.
#ifndef cgmeshDistributed_h
#define cgmeshDistributed_h

#include "cgmeshProcessGroup.h"

#include "AdaptationOptions.h"
#include "Core/TetMesh.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace cgmesh
{

// The piece this process refines. Ghost cells are dropped (each cell is refined by the one
// process that owns it) and, when some process holds no cell while others do (a reader that
// gives the whole mesh to the first process), the cells are spread over all processes with
// VTK's vtkRedistributeDataSetFilter; `note` then says so. Collective.
vtkSmartPointer<vtkUnstructuredGrid> prepareDistributedPiece(
  const ProcessGroup& group, vtkUnstructuredGrid* input, std::string& note);

// Turns a threshold or volume bound relative to the mesh (EdgeLengthFactor, VolumeFactor) into
// the absolute one of the whole mesh, so that every piece splits a shared edge alike, makes face
// diagonals follow coordinates, and resolves NumberOfThreads 0 to the cores this process may use
// divided by the processes on its host. Collective.
void resolveDistributedOptions(
  const ProcessGroup& group, const TetMesh& piece, AdaptationOptions& options);

// Every process's names, each once, in order of first appearance by rank: material label
// arrays found in each piece, so that every piece guards the same interfaces. Collective.
std::vector<std::string> unionAcrossProcesses(
  const ProcessGroup& group, const std::vector<std::string>& names);

// Option values that would make pieces decide a shared edge differently: refused across
// processes, with the reason (empty when none).
std::string unsupportedAcrossProcesses(const AdaptationOptions& options, bool hasSizeArray);

struct GlobalNumbering
{
  std::vector<long long> pointIds; // per point of the piece
  long long firstCellId = 0;       // the piece's cells are numbered on from here
  long long sharedPoints = 0;      // points of the piece that other processes hold too
  long long exchangedBytes = 0;    // what this process received to find and number them
};

// One id per point of the whole mesh: a point that several pieces hold (found by its exact
// coordinates on the pieces' boundaries) gets the id of its copy on the lowest rank. Points with
// a kept id (keptIds[p] >= 0: input points whose input carried global ids) keep it, the others
// are numbered on from the largest kept id of any process, rank by rank in point order.
// `cellCount` counts the piece's cells for the cell ids. Collective.
GlobalNumbering numberAcrossProcesses(const ProcessGroup& group, const TetMesh& piece,
  const std::vector<long long>& keptIds, long long cellCount);

// `levels` layers of ghost cells from the neighbouring pieces (VTK's vtkGhostCellsGenerator,
// matching points by their global ids), marked in vtkGhostType. Collective.
vtkSmartPointer<vtkUnstructuredGrid> addGhostCells(
  const ProcessGroup& group, vtkUnstructuredGrid* piece, int levels);

} // namespace cgmesh

#endif

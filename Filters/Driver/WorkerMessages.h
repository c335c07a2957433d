// What the host and its worker processes send each other over a socket: a message is a sequence
// of length-prefixed arrays, and the worker protocol (WorkerPool) sends TetGen's meshes and dual
// graphs that way.
#ifndef cgmesh_WorkerMessages_h
#define cgmesh_WorkerMessages_h

#include "Partitioning/DualGraph.h"
#include "SocketTransfer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

class tetgenio;

namespace cgmesh
{

// A message is a sequence of length-prefixed arrays.
template <typename T>
bool sendArray(int socket, const T* values, std::int64_t count)
{
  return sendAll(socket, &count, sizeof(count)) &&
    (count == 0 || sendAll(socket, values, sizeof(T) * static_cast<std::size_t>(count)));
}

template <typename T>
bool receiveArray(int socket, T*& values, std::int64_t& count)
{
  values = nullptr;
  if (!receiveAll(socket, &count, sizeof(count)) || count < 0 || count > (std::int64_t(1) << 40))
  {
    return false;
  }
  if (count == 0)
  {
    return true;
  }
  values = new T[static_cast<std::size_t>(count)];
  return receiveAll(socket, values, sizeof(T) * static_cast<std::size_t>(count));
}

// Receives an array into `values` (resized); false on a short read or an implausible length.
template <typename T>
bool receiveArray(int socket, std::vector<T>& values)
{
  std::int64_t count = 0;
  if (!receiveAll(socket, &count, sizeof(count)) || count < 0 || count > (std::int64_t(1) << 40))
  {
    return false;
  }
  values.resize(static_cast<std::size_t>(count));
  return count == 0 || receiveAll(socket, values.data(), sizeof(T) * values.size());
}

// The header's last entry says what follows the tets and their attributes.
enum MeshParts : int
{
  WithFaces = 1,      // the faces and their markers (a request)
  WithNeighbours = 2, // the face neighbours of each tet (a reply to TetGen's switch n)
  WithPointSizes = 4, // one size per point (a request with TetGen's switch m)
  WithFacets = 8,     // triangular facets, their markers and the region list (a request with p)
};

// A TetGen mesh with the parts named in `parts` (fewer when `io` lacks them). False if the peer
// is gone or a facet is not a single triangle.
bool sendMesh(int socket, const tetgenio& io, int parts);
bool receiveMesh(int socket, tetgenio& io);

// A dual graph in compressed rows.
bool sendGraph(int socket, const DualGraph& graph);
// False on a short read or rows that do not fit the neighbour list.
bool receiveGraph(int socket, DualGraph& graph);

} // namespace cgmesh

#endif

#include "WorkerMessages.h"

#include "Refinement/TetGenRefiner.h"

#define TETLIBRARY
#include <tetgen.h>

namespace cgmesh
{

namespace
{

// The facets of a PLC made of single triangles, flattened: what the Delaunay method sends with
// switch p. False for any other facet, which this protocol does not carry.
bool flattenTriangleFacets(const tetgenio& io, std::vector<int>& corners)
{
  corners.clear();
  for (int f = 0; f < io.numberoffacets; ++f)
  {
    const tetgenio::facet& facet = io.facetlist[f];
    if (facet.numberofpolygons != 1 || facet.numberofholes != 0 ||
      facet.polygonlist[0].numberofvertices != 3)
    {
      return false;
    }
    corners.insert(
      corners.end(), facet.polygonlist[0].vertexlist, facet.polygonlist[0].vertexlist + 3);
  }
  return true;
}

} // namespace

bool sendMesh(int socket, const tetgenio& io, int parts)
{
  if (io.neighborlist == nullptr)
  {
    parts &= ~WithNeighbours;
  }
  if ((parts & WithFaces) && io.pointmtrlist != nullptr && io.numberofpointmtrs == 1)
  {
    parts |= WithPointSizes;
  }
  std::vector<int> facetCorners;
  if ((parts & WithFaces) && io.numberoffacets > 0)
  {
    if (!flattenTriangleFacets(io, facetCorners))
    {
      return false;
    }
    parts |= WithFacets;
  }
  const int header[4] = { io.numberofcorners, io.numberoftetrahedronattributes, io.firstnumber,
    parts };
  return sendAll(socket, header, sizeof(header)) &&
    sendArray(socket, io.pointlist, 3 * static_cast<std::int64_t>(io.numberofpoints)) &&
    (!(parts & WithPointSizes) ||
      sendArray(socket, io.pointmtrlist, static_cast<std::int64_t>(io.numberofpoints))) &&
    sendArray(
      socket, io.tetrahedronlist, std::int64_t(io.numberofcorners) * io.numberoftetrahedra) &&
    sendArray(socket, io.tetrahedronattributelist,
      std::int64_t(io.numberoftetrahedronattributes) * io.numberoftetrahedra) &&
    (!(parts & WithFaces) ||
      (sendArray(socket, io.trifacelist, 3 * static_cast<std::int64_t>(io.numberoftrifaces)) &&
        sendArray(socket, io.trifacemarkerlist, static_cast<std::int64_t>(io.numberoftrifaces)))) &&
    (!(parts & WithFacets) ||
      (sendArray(socket, facetCorners.data(), static_cast<std::int64_t>(facetCorners.size())) &&
        sendArray(socket, io.facetmarkerlist, static_cast<std::int64_t>(io.numberoffacets)) &&
        sendArray(socket, io.regionlist, 5 * static_cast<std::int64_t>(io.numberofregions)))) &&
    (!(parts & WithNeighbours) ||
      sendArray(socket, io.neighborlist, 4 * static_cast<std::int64_t>(io.numberoftetrahedra)));
}

bool receiveMesh(int socket, tetgenio& io)
{
  int header[4];
  std::int64_t count = 0;
  if (!receiveAll(socket, header, sizeof(header)))
  {
    return false;
  }
  io.numberofcorners = header[0];
  io.numberoftetrahedronattributes = header[1];
  io.firstnumber = header[2];
  const int parts = header[3];
  if (!receiveArray(socket, io.pointlist, count))
  {
    return false;
  }
  io.numberofpoints = static_cast<int>(count / 3);
  if (parts & WithPointSizes)
  {
    if (!receiveArray(socket, io.pointmtrlist, count) || count != io.numberofpoints)
    {
      return false;
    }
    io.numberofpointmtrs = 1;
  }
  if (!receiveArray(socket, io.tetrahedronlist, count) || io.numberofcorners <= 0)
  {
    return false;
  }
  io.numberoftetrahedra = static_cast<int>(count / io.numberofcorners);
  if (!receiveArray(socket, io.tetrahedronattributelist, count))
  {
    return false;
  }
  if (parts & WithFaces)
  {
    if (!receiveArray(socket, io.trifacelist, count))
    {
      return false;
    }
    io.numberoftrifaces = static_cast<int>(count / 3);
    if (!receiveArray(socket, io.trifacemarkerlist, count))
    {
      return false;
    }
  }
  if (parts & WithFacets)
  {
    int* corners = nullptr;
    const bool facets = receiveArray(socket, corners, count) && count % 3 == 0;
    if (facets)
    {
      setTriangleFacets(io, corners, static_cast<int>(count / 3));
    }
    delete[] corners;
    if (!facets || !receiveArray(socket, io.facetmarkerlist, count) || count != io.numberoffacets ||
      !receiveArray(socket, io.regionlist, count) || count % 5 != 0)
    {
      return false;
    }
    io.numberofregions = static_cast<int>(count / 5);
  }
  if (parts & WithNeighbours)
  {
    if (!receiveArray(socket, io.neighborlist, count) ||
      count != 4 * std::int64_t(io.numberoftetrahedra))
    {
      return false;
    }
  }
  return true;
}

bool sendGraph(int socket, const DualGraph& graph)
{
  return sendArray(socket, graph.offsets.data(), static_cast<std::int64_t>(graph.offsets.size())) &&
    sendArray(
      socket, graph.neighbours.data(), static_cast<std::int64_t>(graph.neighbours.size())) &&
    sendArray(
      socket, graph.vertexWeights.data(), static_cast<std::int64_t>(graph.vertexWeights.size()));
}

bool receiveGraph(int socket, DualGraph& graph)
{
  if (!receiveArray(socket, graph.offsets) || !receiveArray(socket, graph.neighbours) ||
    !receiveArray(socket, graph.vertexWeights) || graph.offsets.empty() ||
    graph.offsets.front() != 0 ||
    graph.offsets.back() != static_cast<std::int64_t>(graph.neighbours.size()) ||
    (!graph.vertexWeights.empty() && graph.vertexWeights.size() + 1 != graph.offsets.size()))
  {
    return false;
  }
  for (std::int64_t weight : graph.vertexWeights)
  {
    if (weight < 1)
    {
      return false;
    }
  }
  for (std::size_t v = 0; v + 1 < graph.offsets.size(); ++v)
  {
    if (graph.offsets[v] > graph.offsets[v + 1])
    {
      return false;
    }
  }
  const auto vertices = static_cast<CellId>(graph.offsets.size() - 1);
  for (CellId neighbour : graph.neighbours)
  {
    if (neighbour < 0 || neighbour >= vertices)
    {
      return false;
    }
  }
  return true;
}

} // namespace cgmesh

// The TetGen (piecewise linear complex) version of the FinFET generator; see FinFetGenerator.h.
#include "FinFetGenerator.h"

#include "FinFetLayout.h"

#define TETLIBRARY
#include <tetgen.h>

#include <cmath>
#include <cstdio>
#include <new>
#include <string>

namespace cgmesh
{
namespace
{

struct BoxGrid
{
  std::array<std::vector<double>, 3> breaks = { finFetBreaks(0), finFetBreaks(1), finFetBreaks(2) };

  int points(int axis) const { return static_cast<int>(this->breaks[axis].size()); }
  int pointIndex(int i, int j, int k) const
  {
    return (k * this->points(1) + j) * this->points(0) + i;
  }
  // Material of cell (i, j, k), or -1 outside the device.
  int material(int i, int j, int k) const
  {
    if (i < 0 || j < 0 || k < 0 || i + 1 >= this->points(0) || j + 1 >= this->points(1) ||
      k + 1 >= this->points(2))
    {
      return -1;
    }
    return finFetMaterialAt(0.5 * (this->breaks[0][i] + this->breaks[0][i + 1]),
      0.5 * (this->breaks[1][j] + this->breaks[1][j + 1]),
      0.5 * (this->breaks[2][k] + this->breaks[2][k + 1]));
  }
};

void addQuad(std::vector<std::array<int, 4>>& quads, const std::array<int, 4>& corners)
{
  quads.push_back(corners);
}

// Facets: every cell face across which the material changes, the outer boundary included.
std::vector<std::array<int, 4>> materialFacets(const BoxGrid& grid)
{
  std::vector<std::array<int, 4>> quads;
  for (int k = 0; k + 1 < grid.points(2); ++k)
  {
    for (int j = 0; j + 1 < grid.points(1); ++j)
    {
      for (int i = 0; i + 1 < grid.points(0); ++i)
      {
        const int here = grid.material(i, j, k);
        // The low face of the cell along each axis, and the high face at the domain's end.
        for (int side = 0; side < 2; ++side)
        {
          if (side == 0 || grid.material(i + 1, j, k) < 0)
          {
            const int x = i + side;
            if (side == 1 || grid.material(i - 1, j, k) != here)
              addQuad(quads,
                { grid.pointIndex(x, j, k), grid.pointIndex(x, j + 1, k),
                  grid.pointIndex(x, j + 1, k + 1), grid.pointIndex(x, j, k + 1) });
          }
          if (side == 0 || grid.material(i, j + 1, k) < 0)
          {
            const int y = j + side;
            if (side == 1 || grid.material(i, j - 1, k) != here)
              addQuad(quads,
                { grid.pointIndex(i, y, k), grid.pointIndex(i + 1, y, k),
                  grid.pointIndex(i + 1, y, k + 1), grid.pointIndex(i, y, k + 1) });
          }
          if (side == 0 || grid.material(i, j, k + 1) < 0)
          {
            const int z = k + side;
            if (side == 1 || grid.material(i, j, k - 1) != here)
              addQuad(quads,
                { grid.pointIndex(i, j, z), grid.pointIndex(i + 1, j, z),
                  grid.pointIndex(i + 1, j + 1, z), grid.pointIndex(i, j + 1, z) });
          }
        }
      }
    }
  }
  return quads;
}

void fillPlc(const BoxGrid& grid, tetgenio& in)
{
  in.firstnumber = 0;
  in.numberofpoints = grid.points(0) * grid.points(1) * grid.points(2);
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int k = 0; k < grid.points(2); ++k)
  {
    for (int j = 0; j < grid.points(1); ++j)
    {
      for (int i = 0; i < grid.points(0); ++i)
      {
        REAL* x = in.pointlist + 3 * grid.pointIndex(i, j, k);
        x[0] = grid.breaks[0][i];
        x[1] = grid.breaks[1][j];
        x[2] = grid.breaks[2][k];
      }
    }
  }
  const auto quads = materialFacets(grid);
  in.numberoffacets = static_cast<int>(quads.size());
  in.facetlist = new tetgenio::facet[quads.size()];
  for (std::size_t f = 0; f < quads.size(); ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 4;
    facet.polygonlist[0].vertexlist = new int[4];
    std::copy(quads[f].begin(), quads[f].end(), facet.polygonlist[0].vertexlist);
  }
  const int cells = (grid.points(0) - 1) * (grid.points(1) - 1) * (grid.points(2) - 1);
  in.numberofregions = cells;
  in.regionlist = new REAL[5 * cells];
  int r = 0;
  for (int k = 0; k + 1 < grid.points(2); ++k)
  {
    for (int j = 0; j + 1 < grid.points(1); ++j)
    {
      for (int i = 0; i + 1 < grid.points(0); ++i, ++r)
      {
        REAL* seed = in.regionlist + 5 * r;
        seed[0] = 0.5 * (grid.breaks[0][i] + grid.breaks[0][i + 1]);
        seed[1] = 0.5 * (grid.breaks[1][j] + grid.breaks[1][j + 1]);
        seed[2] = 0.5 * (grid.breaks[2][k] + grid.breaks[2][k + 1]);
        seed[3] = grid.material(i, j, k);
        seed[4] = -1; // no region-specific volume bound
      }
    }
  }
}

Status meshPlc(const BoxGrid& grid, double maximumVolume, TetMesh& mesh)
{
  tetgenio in, out;
  fillPlc(grid, in);
  char switches[64];
  // p: a PLC; q: radius-edge quality; a: volume bound; A: region attributes; Q: quiet.
  std::snprintf(switches, sizeof(switches), "pq1.414a%.17gAQ", maximumVolume);
  try
  {
    tetgenbehavior behavior;
    behavior.parse_commandline(switches);
    tetrahedralize(&behavior, &in, &out);
  }
  catch (int code)
  {
    return Status::failure(
      "TetGen failed to mesh the FinFET (error code " + std::to_string(code) + ")");
  }
  catch (const std::bad_alloc&)
  {
    return Status::failure("out of memory while meshing the FinFET");
  }
  mesh = TetMesh();
  mesh.coordinates.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    const int* c = out.tetrahedronlist + out.numberofcorners * t;
    mesh.tets.push_back({ c[0], c[1], c[2], c[3] });
    mesh.regions.push_back(static_cast<int>(std::lround(out.tetrahedronattributelist[t])));
  }
  return Status::success();
}

} // namespace

Status generateFinFetWithTetGen(std::int64_t targetTets, TetMesh& mesh)
{
  if (targetTets < 1000 || targetTets > 50000000)
  {
    return Status::failure("the FinFET needs between 1,000 and 50,000,000 tetrahedra");
  }
  const BoxGrid grid;
  double volume = 1;
  for (int axis = 0; axis < 3; ++axis)
  {
    volume *= grid.breaks[axis].back() - grid.breaks[axis].front();
  }
  // TetGen's tets average about half the bound. Scale the bound by each attempt's miss until the
  // target is bracketed, then bisect (geometrically); keep the closest mesh.
  double bound = 2.0 * volume / static_cast<double>(targetTets);
  double tooFine = 0, tooCoarse = 0; // bounds known to give too many / too few tets
  double bestMiss = HUGE_VAL;
  TetMesh attemptMesh;
  for (int attempt = 0; attempt < 12; ++attempt)
  {
    Status status = meshPlc(grid, bound, attemptMesh);
    if (!status.ok())
    {
      return status;
    }
    const double ratio =
      static_cast<double>(attemptMesh.numberOfTets()) / static_cast<double>(targetTets);
    if (std::abs(ratio - 1.0) < bestMiss)
    {
      bestMiss = std::abs(ratio - 1.0);
      mesh = attemptMesh;
    }
    if (bestMiss <= 0.05)
    {
      break;
    }
    (ratio > 1 ? tooFine : tooCoarse) = bound;
    bound = tooFine > 0 && tooCoarse > 0 ? std::sqrt(tooFine * tooCoarse) : bound * ratio;
  }
  return Status::success();
}

} // namespace cgmesh

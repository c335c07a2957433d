// libFuzzer target over the kernels and the driver: bytes become a small mesh (a perturbed Kuhn
// grid, or the Delaunay tetrahedralisation of random points), region ids and options; the run
// must either refuse with a one-line message or give a valid mesh that conserves volume,
// boundary area, region volumes and material-interface area, and leave its input untouched.
#include "AdaptationDriver.h"
#include "CubeGenerator.h"
#include "WorkerPool.h"
#include "Validation/MeshValidation.h"

#define TETLIBRARY
#include <tetgen.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

using namespace cgmesh;

namespace
{

class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t next() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  double unit() { return this->next() / 255.0; } // [0, 1]

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

void fail(const char* what)
{
  std::cerr << "invariant violated: " << what << "\n";
  std::abort();
}

TetMesh perturbedGrid(ByteReader& bytes)
{
  const int cells = 1 + bytes.next() % 4;
  TetMesh mesh;
  generateKuhnCube(cells, mesh);
  const double h = 1.0 / cells;
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    double* x = mesh.coordinates.data() + 3 * p;
    for (int axis = 0; axis < 3; ++axis)
    {
      const bool inside = x[axis] > 1e-9 && x[axis] < 1 - 1e-9;
      x[axis] += inside ? 0.15 * h * (bytes.unit() - 0.5) : 0.0;
    }
  }
  return mesh;
}

// The Delaunay tetrahedralisation of up to 40 random points (in a TetGen worker process).
TetMesh randomDelaunay(ByteReader& bytes)
{
  const int count = 5 + bytes.next() % 36;
  tetgenio in, out;
  in.numberofpoints = count;
  in.pointlist = new REAL[3 * count];
  for (int i = 0; i < 3 * count; ++i)
  {
    in.pointlist[i] = bytes.unit() * (1 + (i % 3));
  }
  TetMesh mesh;
  WorkerPool pool(1);
  if (!pool.runTetGen(0, in, "Q", out).empty())
  {
    return mesh;
  }
  mesh.coordinates.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    const int* c = out.tetrahedronlist + 4 * t;
    mesh.tets.push_back({ c[0], c[1], c[2], c[3] });
  }
  return mesh;
}

void checkInvariants(const TetMesh& input, const AdaptationResult& result)
{
  const MeshReport before = inspectMesh(input);
  const MeshReport after = inspectMesh(result.mesh);
  if (!after.isValid())
  {
    std::cerr << after.describeProblems();
    fail("output is not a valid mesh");
  }
  auto close = [](double a, double b)
  {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
  };
  if (!close(after.volume, std::abs(before.volume)) ||
    !close(after.boundaryArea, before.boundaryArea))
  {
    fail("volume or boundary area changed");
  }
  if (!close(after.regionInterfaceArea, before.regionInterfaceArea))
  {
    fail("material interface area changed");
  }
  for (const auto& region : before.regionVolumes)
  {
    const auto found = after.regionVolumes.find(region.first);
    if (found == after.regionVolumes.end() || !close(found->second, std::abs(region.second)))
    {
      fail("a region's volume changed");
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader bytes(data, size);
  const std::uint8_t shape = bytes.next();
  TetMesh input = shape % 4 == 3 ? randomDelaunay(bytes) : perturbedGrid(bytes);
  const int regionCount = bytes.next() % 4;
  if (regionCount > 0)
  {
    for (std::size_t t = 0; t < input.tets.size(); ++t)
    {
      input.regions.push_back(static_cast<int>(bytes.next() % regionCount) * 37 - 40);
    }
  }
  AdaptationOptions options;
  options.method = bytes.next() % 5 == 0 ? RefinementMethod::Delaunay : RefinementMethod::Template;
  options.numberOfPartitions = 1 + bytes.next() % 40;
  options.numberOfIterations = 1 + bytes.next() % 2;
  options.edgeLengthFactor = 0.3 + 0.9 * bytes.unit();
  options.volumeFactor = 0.05 + 0.5 * bytes.unit();
  options.numberOfThreads = 1 + bytes.next() % 3;
  options.improveQuality = bytes.next() % 2 == 0;
  options.coloring =
    std::vector<const char*>{ "greedy", "greedy-lu", "iterative", "recoloring" }[bytes.next() % 4];
  options.maximumNumberOfCells = 2000000;
  options.partitioner = static_cast<PartitionerKind>(bytes.next() % 3); // auto, METIS, Hilbert
  // A size field on one run in three: sizes between a tenth and the whole of the mesh's extent,
  // now and then a bad one (zero or negative), with a gradation from 1 to 3.
  if (bytes.next() % 3 == 0 && input.numberOfPoints() > 0)
  {
    for (PointId p = 0; p < input.numberOfPoints(); ++p)
    {
      const std::uint8_t byte = bytes.next();
      input.sizes.push_back(byte == 255 ? -1.0 : byte == 254 ? 0.0 : 0.1 + byte / 255.0);
    }
    options.sizeGradation = 1.0 + 2.0 * bytes.unit();
  }
  // Refinement restricted to region lists (ids present, absent, or text that is no list) and to
  // boxes (inside, around, outside or inverted against the unit cube, or malformed), one run in
  // four each.
  if (bytes.next() % 4 == 0)
  {
    options.refinementRegions = std::vector<const char*>{ "-40", "-3,34", "34,-40,99", "7", "",
      "2,,x", "-3", " 34 , -3 " }[bytes.next() % 8];
  }
  if (bytes.next() % 4 == 0)
  {
    if (bytes.next() % 8 == 0)
    {
      options.refinementBox = std::vector<const char*>{ "0,0,0,1,1", "a,b,c,d,e,f", "0,0,0,1,1,1,1",
        "nan,0,0,1,1,1" }[bytes.next() % 4];
    }
    else
    {
      std::string box;
      for (int k = 0; k < 6; ++k)
      {
        box += (k ? "," : "") + std::to_string(1.4 * bytes.unit() - 0.2);
      }
      options.refinementBox = box;
    }
  }

  const bool inputValid = inspectMesh(input).isValid();
  const TetMesh copy = input;
  AdaptationResult result;
  const Status status = adaptMesh(input, options, result);
  if (copy.tets != input.tets || copy.regions != input.regions || copy.sizes != input.sizes ||
    (!copy.coordinates.empty() &&
      std::memcmp(copy.coordinates.data(), input.coordinates.data(),
        copy.coordinates.size() * sizeof(double)) != 0))
  {
    fail("the input was modified");
  }
  if (!status.ok())
  {
    if (status.message().empty() || status.message().find('\n') != std::string::npos)
    {
      fail("an error without a one-line message");
    }
    return 0;
  }
  if (inputValid)
  {
    checkInvariants(input, result);
  }
  return 0;
}

// Reading and writing unstructured grids, the format chosen by extension: VTK XML (.vtu) and legacy
// (.vtk) files through VTK, Gmsh (.msh) and Medit (.mesh) files through Gmsh's library (see
// GmshFiles.h), Exodus II files through libexodus (see ExodusFiles.h), TetGen .node/.ele/.face
// files through tetgenio (see TetGenFiles.h); and the checks on file names and arrays that the
// commands make before any long work.
#ifndef cgmesh_MeshFiles_h
#define cgmesh_MeshFiles_h

#include "Core/Status.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkUnstructuredGrid;

namespace cgmesh
{

// How the arrays of a .vtu file are compressed (appended raw binary data in every case). Legacy
// .vtk files are always written as uncompressed binary.
enum class Compression
{
  None,
  LZ4,
  ZLib
};
// None: the fastest to write (see compressionHelp()); LZ4 and zlib trade writing speed for size.
// meshio 7 reads None and ZLib; it knows no LZ4.
constexpr Compression DefaultCompression = Compression::None;

// "none", "lz4" or "zlib": the names of --compression.
const char* compressionName(Compression compression);
// False for an unknown name.
bool compressionFromName(const std::string& name, Compression& compression);

// True for a .vtk (legacy) file name.
bool isLegacyFileName(const std::string& fileName);
// True for a .vtu (XML) file name: the only format with compression settings.
bool isXMLFileName(const std::string& fileName);

// The integer cell array that holds what Gmsh, Medit, Exodus and TetGen files tag cells with
// (physical group, reference, element block or side set, region attribute or face marker).
constexpr const char* TagArrayName = "Tag";

// What a file says about its tags beyond the grid's cell and point arrays, so that a refined mesh
// is written back with it: the names of Gmsh's physical groups by (dimension, tag), which also
// hold Exodus block (3) and side set (2) names, and Exodus node sets as point array -> set id.
struct MeshFileNames
{
  std::map<std::pair<int, int>, std::string> physicalNames;
  std::map<std::string, int> nodeSets;
  // The file's own numbers of the grid's cells and points where the reader keeps them (Gmsh
  // element and node tags), for messages about the input; empty otherwise.
  std::vector<std::int64_t> cellNumbers;
  std::vector<std::int64_t> pointNumbers;
};

// `message` with the filter's "cell C (points a, b, c)" named by the file's own numbers, "element
// E (nodes A, B, C)", where `names` has them; unchanged otherwise.
std::string inFileNumbers(const std::string& message, const MeshFileNames& names);

// How a grid is written.
struct WriteOptions
{
  Compression compression = DefaultCompression; // .vtu only
  // Gmsh, Medit, Exodus and TetGen: the integer cell array whose values become the tags (see
  // GmshFiles.h, ExodusFiles.h and TetGenFiles.h).
  std::string tagArray;
  double mshVersion = 4.1;              // Gmsh: 4.1 or 2.2
  const MeshFileNames* names = nullptr; // Gmsh and Exodus: group names and node sets to write
};

// Fails with a one-line message for a missing file, an unknown extension or a reader error.
// `names`, when given, receives the file's physical group names.
Status readUnstructuredGrid(
  const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names = nullptr);

// Fails unless `fileName` has a known extension and can be created (see checkWritableFileName):
// checked before a long run, so that a typo does not cost a refinement.
Status checkOutputFileName(const std::string& fileName);

// Fails unless `fileName`'s directory exists and is writable and `fileName` is not a directory.
// `what` names the file in the message ("statistics file").
Status checkWritableFileName(const std::string& fileName, const std::string& what);

// What a command checks before it reads `input`: that `output` and `stats` (when not empty) are
// neither `input` nor each other, by any spelling or link (an InvalidOption failure: writing one
// would overwrite the other), then that both can be created.
Status checkCommandFiles(
  const std::string& input, const std::string& output, const std::string& stats);

// Fails, naming the cell arrays `grid` has, unless it has a numeric cell array `name`.
Status checkRegionArray(
  vtkUnstructuredGrid* grid, const std::string& name, const std::string& fileName);

// Writes to a temporary file next to `fileName` and renames it, so a failed write never leaves a
// partial `fileName` behind. The bytes depend only on the grid and `compression`.
Status writeUnstructuredGrid(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options);
Status writeUnstructuredGrid(vtkUnstructuredGrid* grid, const std::string& fileName,
  Compression compression = DefaultCompression);

} // namespace cgmesh

#endif

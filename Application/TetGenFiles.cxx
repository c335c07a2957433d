#include "TetGenFiles.h"

#include "FileTags.h"
#include "QuietStream.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <tetgen.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace cgmesh
{

namespace
{

std::string baseNameOf(const std::string& fileName)
{
  const std::filesystem::path path(fileName);
  return (path.parent_path() / path.stem()).string();
}

// The files a TetGen mesh is written to, under one base name.
constexpr const char* WrittenExtensions[] = { ".node", ".ele", ".face" };

// tetgenio takes mutable C strings.
std::vector<char> cString(const std::string& text)
{
  return std::vector<char>(text.c_str(), text.c_str() + text.size() + 1);
}

// The whitespace-separated words of `line` before any '#' comment.
std::vector<std::string> wordsOf(const std::string& line)
{
  std::istringstream stream(line.substr(0, line.find('#')));
  std::vector<std::string> words;
  for (std::string word; stream >> word;)
    words.push_back(word);
  return words;
}

// Checks the layout TetGen's own reader takes for granted (it crashes or throws on anything else):
// a header whose first number is the count of records, then at least that many records of at
// least `wordsPerRecord(header)` numbers each. The values themselves are TetGen's to read.
template <typename WordsPerRecord>
Status checkRecords(const std::string& fileName, WordsPerRecord wordsPerRecord)
{
  std::ifstream file(fileName);
  if (!file)
    return Status::failure("'" + fileName + "': cannot be opened");
  std::vector<std::string> header;
  std::string line;
  while (header.empty() && std::getline(file, line))
    header = wordsOf(line);
  long long count = -1;
  std::size_t needed = 0;
  try
  {
    count = header.empty() ? -1 : std::stoll(header[0]);
    needed = wordsPerRecord(header);
  }
  catch (const std::exception&)
  {
    count = -1;
  }
  if (count < 0 || needed == 0)
    return Status::failure("'" + fileName +
      "': not a TetGen file (its first line must give the count of records that follow)");
  for (long long record = 0; record < count; ++record)
  {
    std::vector<std::string> words;
    while (words.empty() && std::getline(file, line))
      words = wordsOf(line);
    if (words.size() < needed)
      return Status::failure("'" + fileName + "': record " + std::to_string(record + 1) +
        " of the " + std::to_string(count) + " its header announces is " +
        (words.empty() ? "missing" : "incomplete"));
  }
  return Status::success();
}

// The .node, .ele and (when there) .face files under `base`, checked before TetGen reads them.
Status checkTetGenFiles(const std::string& base, bool withFaces)
{
  const auto headerNumber =
    [](const std::vector<std::string>& header, std::size_t index, long long fallback)
  {
    return header.size() > index ? std::stoll(header[index]) : fallback;
  };
  Status status = checkRecords(base + ".node",
    [&](const std::vector<std::string>& header) -> std::size_t
    {
      // index, dimension coordinates, attributes, a marker when flagged
      const long long dimension = headerNumber(header, 1, 3);
      const long long attributes = headerNumber(header, 2, 0);
      const long long markers = headerNumber(header, 3, 0);
      if (dimension != 3 || attributes < 0 || markers < 0 || markers > 1)
        return 0;
      return static_cast<std::size_t>(1 + dimension + attributes + markers);
    });
  if (status.ok())
    status = checkRecords(base + ".ele",
      [&](const std::vector<std::string>& header) -> std::size_t
      {
        const long long corners = headerNumber(header, 1, 4);
        const long long attributes = headerNumber(header, 2, 0);
        if ((corners != 4 && corners != 10) || attributes < 0)
          return 0;
        return static_cast<std::size_t>(1 + corners + attributes);
      });
  if (status.ok() && withFaces)
    status = checkRecords(base + ".face",
      [&](const std::vector<std::string>& header) -> std::size_t
      {
        const long long markers = headerNumber(header, 1, 0);
        return markers < 0 || markers > 1 ? 0 : static_cast<std::size_t>(4 + markers);
      });
  return status;
}

} // namespace

bool isTetGenFileName(const std::string& fileName)
{
  const std::string extension = std::filesystem::path(fileName).extension().string();
  return extension == ".ele" || extension == ".node";
}

Status readTetGenFiles(const std::string& fileName, vtkUnstructuredGrid* grid)
{
  const std::string base = baseNameOf(fileName);
  for (const char* extension : { ".node", ".ele" })
  {
    std::error_code error;
    if (!std::filesystem::is_regular_file(base + extension, error))
      return Status::failure("'" + base + extension +
        "': no such file (TetGen meshes are read "
        "from the .node and .ele files together)");
  }
  std::error_code error;
  const bool withFaces = std::filesystem::is_regular_file(base + ".face", error);
  const Status layout = checkTetGenFiles(base, withFaces);
  if (!layout.ok())
    return layout;
  tetgenio io;
  std::vector<char> name = cString(base);
  bool loaded = false;
  try
  {
    const QuietStream quiet(stdout, STDOUT_FILENO);
    loaded = io.load_node(name.data()) && io.load_tet(name.data());
    if (loaded && withFaces)
      loaded = io.load_face(name.data());
  }
  catch (int)
  {
    // TetGen's reader throws its error code (an index out of range, a bad number).
    loaded = false;
  }
  if (!loaded)
    return Status::failure("'" + fileName +
      "': TetGen cannot read the .node, .ele or .face file (a node index out of range, or a "
      "value that is not a number?)");
  if (io.numberofcorners != 4)
    return Status::failure("'" + fileName + "' holds tetrahedra with " +
      std::to_string(io.numberofcorners) + " nodes; cgmesh refines linear tetrahedra");

  const vtkIdType points = io.numberofpoints;
  const auto pointOf = [&](int index, vtkIdType& point)
  {
    point = static_cast<vtkIdType>(index) - io.firstnumber;
    return point >= 0 && point < points;
  };
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  coordinates->SetNumberOfPoints(points);
  for (vtkIdType p = 0; p < points; ++p)
    coordinates->SetPoint(p, io.pointlist + 3 * p);
  grid->Initialize();
  grid->SetPoints(coordinates);
  if (io.pointmarkerlist)
  {
    vtkNew<vtkIntArray> markers;
    markers->SetName("Marker");
    markers->SetNumberOfValues(points);
    for (vtkIdType p = 0; p < points; ++p)
      markers->SetValue(p, io.pointmarkerlist[p]);
    grid->GetPointData()->AddArray(markers);
  }

  vtkNew<vtkIntArray> tags;
  tags->SetName(TagArrayName);
  grid->Allocate(io.numberoftetrahedra + io.numberoftrifaces);
  for (int t = 0; t < io.numberoftetrahedra; ++t)
  {
    vtkIdType corners[4];
    for (int k = 0; k < 4; ++k)
      if (!pointOf(io.tetrahedronlist[4 * t + k], corners[k]))
        return Status::failure("'" + base + ".ele': tetrahedron " + std::to_string(t + 1) +
          " names a node that does not exist");
    grid->InsertNextCell(VTK_TETRA, 4, corners);
    tags->InsertNextValue(io.numberoftetrahedronattributes > 0
        ? static_cast<int>(
            std::lround(io.tetrahedronattributelist[io.numberoftetrahedronattributes * t]))
        : 0);
  }
  for (int f = 0; f < io.numberoftrifaces; ++f)
  {
    vtkIdType corners[3];
    for (int k = 0; k < 3; ++k)
      if (!pointOf(io.trifacelist[3 * f + k], corners[k]))
        return Status::failure("'" + base + ".face': face " + std::to_string(f + 1) +
          " names a node that does not exist");
    grid->InsertNextCell(VTK_TRIANGLE, 3, corners);
    tags->InsertNextValue(io.trifacemarkerlist ? io.trifacemarkerlist[f] : 0);
  }
  grid->GetCellData()->AddArray(tags);
  return Status::success();
}

Status writeTetGenFiles(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  vtkDataArray* tags =
    options.tagArray.empty() ? nullptr : grid->GetCellData()->GetArray(options.tagArray.c_str());
  std::vector<vtkIdType> tets, triangles;
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const int type = grid->GetCellType(cellId);
    if (type != VTK_TETRA && type != VTK_TRIANGLE)
      return Status::failure("cell " + std::to_string(cellId) +
        " is neither a tetrahedron nor a triangle, which is all TetGen files hold");
    (type == VTK_TETRA ? tets : triangles).push_back(cellId);
  }

  // tetgenio owns its arrays and frees them with delete[].
  tetgenio io;
  io.firstnumber = 1;
  io.numberofpoints = static_cast<int>(grid->GetNumberOfPoints());
  io.pointlist = new REAL[3 * static_cast<std::size_t>(io.numberofpoints)];
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
    grid->GetPoint(p, io.pointlist + 3 * p);
  vtkDataArray* markers = grid->GetPointData()->GetArray("Marker");
  if (markers)
  {
    io.pointmarkerlist = new int[io.numberofpoints];
    for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
      io.pointmarkerlist[p] = tagValue(markers, p);
  }
  const auto copyCorners = [&](vtkIdType cellId, int* destination)
  {
    const vtkIdType* corners;
    vtkIdType count;
    grid->GetCellPoints(cellId, count, corners);
    for (vtkIdType k = 0; k < count; ++k)
      destination[k] = static_cast<int>(corners[k]) + 1;
  };
  io.numberoftetrahedra = static_cast<int>(tets.size());
  io.tetrahedronlist = new int[4 * tets.size()];
  if (tags)
  {
    io.numberoftetrahedronattributes = 1;
    io.tetrahedronattributelist = new REAL[tets.size()];
  }
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    copyCorners(tets[t], io.tetrahedronlist + 4 * t);
    if (tags)
      io.tetrahedronattributelist[t] = tagValue(tags, tets[t]);
  }
  io.numberoftrifaces = static_cast<int>(triangles.size());
  io.trifacelist = new int[3 * triangles.size()];
  io.trifacemarkerlist = new int[triangles.size()];
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    copyCorners(triangles[f], io.trifacelist + 3 * f);
    io.trifacemarkerlist[f] = tagValue(tags, triangles[f]);
  }

  // Written under a temporary base name, then renamed file by file.
  const std::string base = baseNameOf(fileName);
  const std::string temporary = base + ".partial-" + std::to_string(::getpid());
  std::vector<char> name = cString(temporary);
  {
    const QuietStream quiet(stdout, STDOUT_FILENO);
    io.save_nodes(name.data());
    io.save_elements(name.data());
    io.save_faces(name.data());
  }
  for (const char* extension : WrittenExtensions)
  {
    std::error_code error;
    if (!std::filesystem::is_regular_file(temporary + extension, error))
    {
      for (const char* written : WrittenExtensions)
        std::filesystem::remove(temporary + written, error);
      return Status::failure(std::string("TetGen did not write the ") + extension + " file");
    }
  }
  for (const char* extension : WrittenExtensions)
  {
    std::error_code error;
    std::filesystem::rename(temporary + extension, base + extension, error);
    if (error)
      return Status::failure("'" + base + extension + "': " + error.message());
  }
  return Status::success();
}

} // namespace cgmesh

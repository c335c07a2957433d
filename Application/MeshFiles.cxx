#include "MeshFiles.h"

#include "ExodusFiles.h"
#include "GmshFiles.h"
#include "TetGenFiles.h"
#include "VTKMessages.h"
#include "WriterCaches.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <regex>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <vector>

namespace cgmesh
{

namespace
{

enum class FileFormat
{
  XML,
  Legacy,
  Gmsh,   // .msh and Medit .mesh, through Gmsh's library
  Exodus, // Exodus II, through libexodus
  TetGen, // .node/.ele/.face, through TetGen's library
  Unknown
};

FileFormat formatOf(const std::string& fileName)
{
  const std::string extension = std::filesystem::path(fileName).extension().string();
  if (extension == ".vtu")
    return FileFormat::XML;
  if (extension == ".vtk")
    return FileFormat::Legacy;
  if (isGmshFileName(fileName))
    return FileFormat::Gmsh;
  if (isExodusFileName(fileName))
    return FileFormat::Exodus;
  if (isTetGenFileName(fileName))
    return FileFormat::TetGen;
  return FileFormat::Unknown;
}

Status unknownFormat(const std::string& fileName)
{
  return Status::failure("'" + fileName +
    "': unknown file type (use .vtu, .vtk, .msh, .mesh, .exo (.e, .ex2, .g, .gen), or .ele or "
    ".node)");
}

constexpr std::pair<Compression, const char*> CompressionNames[] = { { Compression::None, "none" },
  { Compression::LZ4, "lz4" }, { Compression::ZLib, "zlib" } };

// "'a', 'b' and 'c'", or "none".
std::string listOfNames(const std::vector<std::string>& names)
{
  if (names.empty())
    return "none";
  std::string list = "'" + names.front() + "'";
  for (std::size_t index = 1; index < names.size(); ++index)
    list += (index + 1 == names.size() ? " and '" : ", '") + names[index] + "'";
  return list;
}

// True when the two names reach the same file: the same inode when both exist (other spellings,
// symbolic and hard links), else the same canonical path.
bool isSameFile(const std::string& first, const std::string& second)
{
  std::error_code error;
  if (std::filesystem::exists(first, error) && std::filesystem::exists(second, error))
    return std::filesystem::equivalent(first, second, error) && !error;
  const auto canonical = [](const std::string& name)
  {
    std::error_code ignored;
    return std::filesystem::weakly_canonical(std::filesystem::absolute(name, ignored), ignored);
  };
  return canonical(first) == canonical(second);
}

// The name that stands for a mesh file when names are compared: a TetGen mesh is its .ele file, as
// its .node, .ele and .face files share a base name ("a.1.node" and "a.1.ele" are one mesh).
std::string meshFileKey(const std::string& fileName)
{
  if (!isTetGenFileName(fileName))
    return fileName;
  return std::filesystem::path(fileName).replace_extension(".ele").string();
}

// The files of a command as (role, name), the one read first: fails with an InvalidOption status
// when a file written later is the same as an earlier one. Empty names are skipped.
Status checkDistinctFiles(const std::vector<std::pair<std::string, std::string>>& files)
{
  for (std::size_t later = 1; later < files.size(); ++later)
  {
    for (std::size_t earlier = 0; earlier < later; ++earlier)
    {
      const auto& [laterRole, laterName] = files[later];
      const auto& [earlierRole, earlierName] = files[earlier];
      if (laterName.empty() || earlierName.empty() ||
        !isSameFile(meshFileKey(earlierName), meshFileKey(laterName)))
        continue;
      return Status::failure(ErrorKind::InvalidOption,
        laterRole + " '" + laterName + "' is the same file as " + earlierRole + " '" + earlierName +
          "': writing " + laterRole + " would overwrite " + earlierRole + "; choose another name");
    }
  }
  return Status::success();
}

// Appended raw binary data: base64 would add a third to the bytes, and the time to encode them.
void configureXMLWriter(vtkXMLUnstructuredGridWriter* writer, Compression compression)
{
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  // Uncompressed arrays carry their byte count in the header: 32 bits would stop at 4 GiB.
  writer->SetHeaderTypeToUInt64();
  switch (compression)
  {
    case Compression::None:
      writer->SetCompressorTypeToNone();
      break;
    case Compression::LZ4:
      writer->SetCompressorTypeToLZ4();
      break;
    case Compression::ZLib:
      writer->SetCompressorTypeToZLib();
      // The fastest level: about three times faster than the default for files only slightly
      // larger.
      writer->SetCompressionLevel(1);
      break;
  }
}

} // namespace

const char* compressionName(Compression compression)
{
  for (const auto& entry : CompressionNames)
  {
    if (entry.first == compression)
      return entry.second;
  }
  return "";
}

bool compressionFromName(const std::string& name, Compression& compression)
{
  for (const auto& entry : CompressionNames)
  {
    if (name == entry.second)
    {
      compression = entry.first;
      return true;
    }
  }
  return false;
}

bool isLegacyFileName(const std::string& fileName)
{
  return formatOf(fileName) == FileFormat::Legacy;
}

bool isXMLFileName(const std::string& fileName)
{
  return formatOf(fileName) == FileFormat::XML;
}

Status readUnstructuredGrid(
  const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  const FileFormat format = formatOf(fileName);
  if (format == FileFormat::Unknown)
    return unknownFormat(fileName);
  std::error_code error;
  if (!std::filesystem::is_regular_file(fileName, error))
    return Status::failure("'" + fileName + "': no such file");
  if (format == FileFormat::Gmsh)
    return readGmshFile(fileName, grid, names);
  if (format == FileFormat::Exodus)
    return readExodusFile(fileName, grid, names);
  if (format == FileFormat::TetGen)
    return readTetGenFiles(fileName, grid);

  vtkNew<VTKMessageCollector> messages;
  vtkNew<vtkXMLUnstructuredGridReader> xmlReader;
  vtkNew<vtkUnstructuredGridReader> legacyReader;
  vtkAlgorithm* reader = xmlReader;
  if (format == FileFormat::XML)
    xmlReader->SetFileName(fileName.c_str());
  else
  {
    legacyReader->SetFileName(fileName.c_str());
    legacyReader->ReadAllScalarsOn(); // every array, not only the active ones
    legacyReader->ReadAllVectorsOn();
    legacyReader->ReadAllNormalsOn();
    legacyReader->ReadAllTensorsOn();
    legacyReader->ReadAllColorScalarsOn();
    legacyReader->ReadAllTCoordsOn();
    legacyReader->ReadAllFieldsOn();
    reader = legacyReader;
  }
  messages->watch(reader);
  reader->Update();
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
  if (!messages->errors().empty() || !output)
  {
    return Status::failure(
      "'" + fileName + "': " + messages->firstError("not an unstructured grid"));
  }
  grid->ShallowCopy(output);
  return Status::success();
}

std::string inFileNumbers(const std::string& message, const MeshFileNames& names)
{
  if (names.cellNumbers.empty() || names.pointNumbers.empty())
    return message;
  static const std::regex described(R"(cell (\d+) \(points (\d+), (\d+), (\d+)\))");
  std::smatch match;
  if (!std::regex_search(message, match, described))
    return message;
  const auto numberOf =
    [](const std::vector<std::int64_t>& numbers, const std::string& text, std::string& number)
  {
    const unsigned long long index = std::stoull(text);
    if (index >= numbers.size())
      return false;
    number = std::to_string(numbers[index]);
    return true;
  };
  std::string element, nodes[3];
  if (!numberOf(names.cellNumbers, match[1], element) ||
    !numberOf(names.pointNumbers, match[2], nodes[0]) ||
    !numberOf(names.pointNumbers, match[3], nodes[1]) ||
    !numberOf(names.pointNumbers, match[4], nodes[2]))
    return message;
  return match.prefix().str() + "element " + element + " (nodes " + nodes[0] + ", " + nodes[1] +
    ", " + nodes[2] + ")" + inFileNumbers(match.suffix().str(), names);
}

Status checkOutputFileName(const std::string& fileName)
{
  if (formatOf(fileName) == FileFormat::Unknown)
    return unknownFormat(fileName);
  return checkWritableFileName(fileName, "output file");
}

Status checkWritableFileName(const std::string& fileName, const std::string& what)
{
  const std::string cannot = "cannot write " + what + " '" + fileName + "': ";
  const std::filesystem::path path(fileName);
  const std::filesystem::path directory = path.parent_path().empty() ? "." : path.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    return Status::failure(cannot +
      (std::filesystem::exists(directory, error)
          ? "'" + directory.string() + "' is not a directory"
          : "directory '" + directory.string() + "' does not exist"));
  if (::access(directory.c_str(), W_OK | X_OK) != 0)
    return Status::failure(cannot + "directory '" + directory.string() + "' is not writable");
  if (std::filesystem::is_directory(path, error))
    return Status::failure(cannot + "it is a directory");
  // access() grants root everything, and a file system may refuse what the mode bits allow (/proc,
  // a read-only mount): the file is opened for writing, not truncated (non-blocking, should it be
  // a FIFO), and removed again when this made it, so that a long run does not end in a failed
  // write.
  const bool existed = std::filesystem::exists(path, error);
  const int descriptor =
    ::open(fileName.c_str(), O_WRONLY | O_CREAT | O_NONBLOCK | O_CLOEXEC, 0666);
  if (descriptor < 0)
    return Status::failure(cannot + std::strerror(errno));
  ::close(descriptor);
  if (!existed)
    ::unlink(fileName.c_str());
  return Status::success();
}

Status checkCommandFiles(
  const std::string& input, const std::string& output, const std::string& stats)
{
  Status status = checkDistinctFiles({ { "IN", input }, { "OUT", output }, { "--stats", stats } });
  if (status.ok())
    status = checkOutputFileName(output);
  if (status.ok() && !stats.empty())
    status = checkWritableFileName(stats, "statistics file");
  return status;
}

Status checkRegionArray(
  vtkUnstructuredGrid* grid, const std::string& name, const std::string& fileName)
{
  vtkCellData* cellData = grid->GetCellData();
  std::vector<std::string> all, numeric;
  for (int index = 0; index < cellData->GetNumberOfArrays(); ++index)
  {
    vtkAbstractArray* array = cellData->GetAbstractArray(index);
    const std::string arrayName = array->GetName() ? array->GetName() : "";
    all.push_back(arrayName);
    if (vtkDataArray::SafeDownCast(array))
      numeric.push_back(arrayName);
  }
  vtkAbstractArray* array = cellData->GetAbstractArray(name.c_str());
  if (!array)
    return Status::failure("'" + fileName + "' has no cell array '" + name +
      "' (--region-array); its cell arrays: " + listOfNames(all));
  if (!vtkDataArray::SafeDownCast(array))
    return Status::failure("cell array '" + name + "' of '" + fileName +
      "' is not numeric (--region-array needs region ids); its numeric cell arrays: " +
      listOfNames(numeric));
  return Status::success();
}

Status writeUnstructuredGrid(
  vtkUnstructuredGrid* grid, const std::string& fileName, Compression compression)
{
  WriteOptions options;
  options.compression = compression;
  return writeUnstructuredGrid(grid, fileName, options);
}

Status writeUnstructuredGrid(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  const FileFormat format = formatOf(fileName);
  if (format == FileFormat::Unknown)
    return unknownFormat(fileName);
  if (format == FileFormat::TetGen) // three files, each written under a temporary name
  {
    const Status status = writeTetGenFiles(grid, fileName, options);
    return status.ok() ? status
                       : Status::failure("cannot write '" + fileName + "': " + status.message());
  }
  // The temporary keeps the extension: Gmsh chooses the format by it.
  const std::filesystem::path path(fileName);
  const std::string temporaryName = (path.parent_path() /
    (path.stem().string() + ".partial-" + std::to_string(::getpid()) + path.extension().string()))
                                      .string();

  vtkNew<VTKMessageCollector> messages;
  int written = 0;
  if (format == FileFormat::Gmsh || format == FileFormat::Exodus)
  {
    const Status status = format == FileFormat::Gmsh
      ? writeGmshFile(grid, temporaryName, options)
      : writeExodusFile(grid, temporaryName, options);
    if (!status.ok())
    {
      std::error_code ignored;
      std::filesystem::remove(temporaryName, ignored);
      return Status::failure("cannot write '" + fileName + "': " + status.message());
    }
    written = 1;
  }
  else if (format == FileFormat::XML)
  {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    messages->watch(writer);
    writer->SetFileName(temporaryName.c_str());
    writer->SetInputData(gridWithWriterCaches(grid));
    configureXMLWriter(writer, options.compression);
    written = writer->Write();
  }
  else
  {
    vtkNew<vtkUnstructuredGridWriter> writer;
    messages->watch(writer);
    writer->SetFileName(temporaryName.c_str());
    writer->SetFileTypeToBinary();
    // Version 4.2, which every reader of legacy files knows; meshio 5 misreads 5.1's header.
    writer->SetFileVersion(vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    writer->SetInputData(grid);
    written = writer->Write();
  }

  std::error_code error;
  if (written != 1 || !messages->errors().empty())
  {
    std::filesystem::remove(temporaryName, error);
    return Status::failure(
      "cannot write '" + fileName + "': " + messages->firstError("the writer failed"));
  }
  std::filesystem::rename(temporaryName, fileName, error);
  if (error)
  {
    std::filesystem::remove(temporaryName, error);
    return Status::failure("cannot write '" + fileName + "': " + error.message());
  }
  return Status::success();
}

} // namespace cgmesh

#include "MeshFiles.h"

#include "VTKMessages.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace cgmesh
{

namespace
{

enum class FileFormat
{
  XML,
  Legacy,
  Unknown
};

FileFormat formatOf(const std::string& fileName)
{
  const std::string extension = std::filesystem::path(fileName).extension().string();
  if (extension == ".vtu")
    return FileFormat::XML;
  if (extension == ".vtk")
    return FileFormat::Legacy;
  return FileFormat::Unknown;
}

Status unknownFormat(const std::string& fileName)
{
  return Status::failure("'" + fileName + "': unknown file type (use .vtu or .vtk)");
}

} // namespace

Status readUnstructuredGrid(const std::string& fileName, vtkUnstructuredGrid* grid)
{
  const FileFormat format = formatOf(fileName);
  if (format == FileFormat::Unknown)
    return unknownFormat(fileName);
  std::error_code error;
  if (!std::filesystem::is_regular_file(fileName, error))
    return Status::failure("'" + fileName + "': no such file");

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

Status checkOutputFileName(const std::string& fileName)
{
  if (formatOf(fileName) == FileFormat::Unknown)
    return unknownFormat(fileName);
  std::filesystem::path directory = std::filesystem::path(fileName).parent_path();
  std::error_code error;
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
    return Status::failure(
      "'" + fileName + "': directory '" + directory.string() + "' does not exist");
  return Status::success();
}

Status writeUnstructuredGrid(vtkUnstructuredGrid* grid, const std::string& fileName)
{
  const FileFormat format = formatOf(fileName);
  if (format == FileFormat::Unknown)
    return unknownFormat(fileName);
  const std::string temporaryName = fileName + ".partial-" + std::to_string(::getpid());

  vtkNew<VTKMessageCollector> messages;
  int written = 0;
  if (format == FileFormat::XML)
  {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    messages->watch(writer);
    writer->SetFileName(temporaryName.c_str());
    writer->SetInputData(grid);
    // zlib at its fastest level: about three times faster than the default level for files
    // only slightly larger.
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(1);
    written = writer->Write();
  }
  else
  {
    vtkNew<vtkUnstructuredGridWriter> writer;
    messages->watch(writer);
    writer->SetFileName(temporaryName.c_str());
    writer->SetFileTypeToBinary();
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

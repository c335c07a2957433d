// The command line's side of GmshFiles.h: the Gmsh module (GmshModule.cxx) is loaded on first use,
// with RTLD_LOCAL so that libgmsh's own TetGen never stands in for the one the executable uses.
#include "GmshFiles.h"

#include <dlfcn.h>

#include <filesystem>

namespace cgmesh
{

namespace
{

using ReadEntry = bool (*)(const char*, vtkUnstructuredGrid*, MeshFileNames*, std::string*);
using WriteEntry = bool (*)(vtkUnstructuredGrid*, const char*, const WriteOptions*, std::string*);

struct GmshModule
{
  ReadEntry read = nullptr;
  WriteEntry write = nullptr;
  std::string error; // why the module could not be loaded
};

const GmshModule& gmshModule()
{
  static const GmshModule module = []()
  {
    GmshModule loaded;
    // The module sits at a path fixed when cgmesh was built (CGMESH_GMSH_MODULE).
    void* handle = ::dlopen(CGMESH_GMSH_MODULE, RTLD_NOW | RTLD_LOCAL);
    if (!handle)
    {
      const char* reason = ::dlerror();
      loaded.error = std::string("the Gmsh file module cannot be loaded: ") +
        (reason ? reason : CGMESH_GMSH_MODULE);
      return loaded;
    }
    loaded.read = reinterpret_cast<ReadEntry>(::dlsym(handle, "cgmeshReadGmshFile"));
    loaded.write = reinterpret_cast<WriteEntry>(::dlsym(handle, "cgmeshWriteGmshFile"));
    if (!loaded.read || !loaded.write)
      loaded.error = "the Gmsh file module " CGMESH_GMSH_MODULE " lacks its entry points";
    return loaded;
  }();
  return module;
}

} // namespace

bool isGmshFileName(const std::string& fileName)
{
  const std::string extension = std::filesystem::path(fileName).extension().string();
  return extension == ".msh" || extension == ".mesh";
}

Status readGmshFile(const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names)
{
  const GmshModule& module = gmshModule();
  std::string error = module.error;
  if (!module.read || !module.read(fileName.c_str(), grid, names, &error))
    return Status::failure(error);
  return Status::success();
}

Status writeGmshFile(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options)
{
  const GmshModule& module = gmshModule();
  std::string error = module.error;
  if (!module.write || !module.write(grid, fileName.c_str(), &options, &error))
    return Status::failure(error);
  return Status::success();
}

} // namespace cgmesh

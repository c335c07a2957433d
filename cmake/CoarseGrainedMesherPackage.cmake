# Install rules for what the module and plugin builds do not install themselves, and the package
# files of find_package(CoarseGrainedMesher):
#   CGMesh::Filters                the VTK module (library, headers; from vtk_module_build)
#   CGMesh::CoarseGrainedMesher    the ParaView plugin (from paraview_plugin_build)
#   CGMesh::cgmesh                 the command line
# The package is relocatable: every path is relative to the installed config file, and the
# installed binaries find lib/ through $ORIGIN-relative RPATHs.
include(CMakePackageConfigHelpers)

# The command line lives in bin/ and loads libcgmeshFilters.so from lib/.
file(RELATIVE_PATH cgmesh_bin_to_lib
  "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
set_target_properties(cgmesh PROPERTIES INSTALL_RPATH "$ORIGIN/${cgmesh_bin_to_lib}")
install(
  TARGETS cgmesh
  EXPORT CoarseGrainedMesherTools
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
  COMPONENT runtime)
install(
  EXPORT CoarseGrainedMesherTools
  NAMESPACE CGMesh::
  DESTINATION "${CGMESH_CMAKE_DESTINATION}"
  FILE CoarseGrainedMesherTools-targets.cmake
  COMPONENT development)

install(
  DIRECTORY "${PROJECT_SOURCE_DIR}/examples/"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}/examples"
  COMPONENT runtime)

# ParaView's VTK is not on CMake's default search path (Debian installs it under ParaView's
# prefix): the config file looks for the VTK this project was built against first.
set(CGMESH_VTK_DIR "${VTK_DIR}")
set(CGMESH_PLUGIN_SUBDIRECTORY
  "paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins/CoarseGrainedMesher")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/CoarseGrainedMesherConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/CMakeFiles/CoarseGrainedMesherConfig.cmake"
  INSTALL_DESTINATION "${CGMESH_CMAKE_DESTINATION}"
  PATH_VARS CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_BINDIR CGMESH_PYTHON_DESTINATION)
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/CMakeFiles/CoarseGrainedMesherConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(
  FILES
    "${CMAKE_BINARY_DIR}/CMakeFiles/CoarseGrainedMesherConfig.cmake"
    "${CMAKE_BINARY_DIR}/CMakeFiles/CoarseGrainedMesherConfigVersion.cmake"
  DESTINATION "${CGMESH_CMAKE_DESTINATION}"
  COMPONENT development)

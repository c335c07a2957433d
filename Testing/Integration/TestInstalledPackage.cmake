# cmake -P driver of the Package.Consumer test: installs the build tree into a fresh prefix, then
# configures, builds and runs Testing/Consumer against it with find_package(CoarseGrainedMesher),
# and runs the installed command line and Python package. Every step must succeed.
#
# Variables (-D): BUILD_DIR, CONSUMER_SOURCE_DIR, SCRATCH, GENERATOR, PYTHON.
foreach (variable IN ITEMS BUILD_DIR CONSUMER_SOURCE_DIR SCRATCH GENERATOR PYTHON)
  if (NOT DEFINED ${variable})
    message(FATAL_ERROR "${variable} is not set")
  endif ()
endforeach ()

set(prefix "${SCRATCH}/prefix")
set(consumer_build "${SCRATCH}/consumer-build")
# A stale prefix would hide a missing install rule.
file(REMOVE_RECURSE "${prefix}" "${consumer_build}")

function (run_step description)
  message(STATUS "${description}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${description}: failed (${result})")
  endif ()
endfunction ()

run_step("install into ${prefix}"
  "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
# Only the prefix is given: the package must find ParaView's VTK by itself.
run_step("configure the consumer"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
run_step("build the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}")
run_step("run the consumer" "${consumer_build}/refine_cube")

# The installed binaries must find lib/ through their RPATHs, not through the build tree.
file(STRINGS "${consumer_build}/package-paths.txt" package_paths)
foreach (line IN LISTS package_paths)
  string(REGEX MATCH "^([a-z]+)=(.*)$" _ "${line}")
  set(path_${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
endforeach ()
foreach (path IN ITEMS "${path_plugin}" "${path_cli}" "${path_pythonpath}/cgmesh/__init__.py")
  if (NOT path MATCHES "^${prefix}/" OR NOT EXISTS "${path}")
    message(FATAL_ERROR "not installed in the prefix: ${path}")
  endif ()
endforeach ()
run_step("installed command line"
  "${path_cli}" generate cube 3 "${SCRATCH}/cube.vtu")
run_step("installed command line refines"
  "${path_cli}" refine "${SCRATCH}/cube.vtu" "${SCRATCH}/cube-refined.vtu" --partitions 4
    --threads 1)
run_step("installed Python package"
  "${CMAKE_COMMAND}" -E env "PYTHONPATH=${path_pythonpath}"
    "${PYTHON}" -c "import cgmesh, sys; sys.exit(not cgmesh.__file__.startswith('${prefix}/'))")

# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# cmake -DSOURCE_DIR=... -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DMODULES=a,b
#       [-DGENERATOR=...] [-DCXX=...] -P run_consumer_test.cmake
# Installs the build tree into BUILD_DIR/install-test, checks what was installed,
# then configures, builds and runs the outside consumer project against it.
# Any failure stops with a message saying which step failed and why.
foreach(var SOURCE_DIR BUILD_DIR CONSUMER_DIR WORK_DIR MODULES)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer_test.cmake: -D${var}=... is required")
  endif()
endforeach()
string(REPLACE "," ";" MODULES "${MODULES}")
set(prefix ${BUILD_DIR}/install-test)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${prefix} ${consumer_build})

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: step '${step}' failed (exit ${rc}): ${ARGN}")
  endif()
endfunction()

run("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# The program, its docs and (when built) the Python module, importable from
# the prefix with its version.
if(EXISTS ${BUILD_DIR}/bin/tessella)
  foreach(file ${prefix}/bin/tessella ${prefix}/share/doc/tessella/README.md ${prefix}/share/doc/tessella/LICENSE
               ${prefix}/share/doc/tessella/config.md ${prefix}/share/doc/tessella/configs/figure17.yaml)
    if(NOT EXISTS ${file})
      message(FATAL_ERROR "install test: ${file} was not installed")
    endif()
  endforeach()
  run("installed program" ${prefix}/bin/tessella --version)
endif()
file(GLOB _python_modules ${BUILD_DIR}/python/tessella*.so)
if(_python_modules AND EXISTS /usr/bin/python3)
  file(GLOB _installed ${prefix}/lib/python3*/site-packages/tessella*.so)
  if(NOT _installed)
    message(FATAL_ERROR "install test: the Python module was not installed into ${prefix}/lib/python3.X/site-packages")
  endif()
  get_filename_component(_site ${_installed} DIRECTORY)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${_site} PYTHONNOUSERSITE=1 /usr/bin/python3 -c
                          "import tessella; print(tessella.__file__, tessella.__version__)"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${_site}")
    message(FATAL_ERROR "install test: the installed Python module does not import from ${_site}: ${out}${err}")
  endif()
endif()

# What a consumer needs must be there, and nothing of the build tree.
set(pkg ${prefix}/lib/cmake/Tessella)
foreach(file ${pkg}/TessellaConfig.cmake ${pkg}/TessellaConfigVersion.cmake
             ${pkg}/TessellaTargets.cmake ${prefix}/include/tessella/tissue.hpp)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "install test: ${file} was not installed")
  endif()
endforeach()
foreach(module IN LISTS MODULES)
  if(NOT IS_DIRECTORY ${prefix}/include/tessella/${module})
    message(FATAL_ERROR "install test: headers of module ${module} were not installed")
  endif()
endforeach()
# Exported files use paths relative to the prefix: a source or build-tree
# path, or the build-only warnings target, means the export leaked.
file(GLOB package_files ${pkg}/*.cmake)
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(leak tessella_warnings "${SOURCE_DIR}/" "${BUILD_DIR}/")
    string(FIND "${text}" "${leak}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "install test: ${file} refers to '${leak}' (the build tree leaked into the package)")
    endif()
  endforeach()
endforeach()

set(configure_args -S ${CONSUMER_DIR} -B ${consumer_build} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix})
# Comma-separated: execute_process would split a ';' list into arguments.
string(REPLACE ";" "," modules_arg "${MODULES}")
list(APPEND configure_args -DTESSELLA_EXPECTED_MODULES=${modules_arg})
if(GENERATOR)
  list(APPEND configure_args -G ${GENERATOR})
endif()
if(CXX)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX})
endif()
run("configure consumer" ${CMAKE_COMMAND} ${configure_args})
run("build consumer" ${CMAKE_COMMAND} --build ${consumer_build} -j2)
run("run consumer" ${consumer_build}/consumer)

# The C++ meristem example, built against the same installed package, must
# write a ParaView series whose every listed snapshot exists.
if(DEFINED EXAMPLE_DIR)
  set(example_build ${WORK_DIR}/meristem-build)
  set(example_out ${WORK_DIR}/meristem-out)
  file(REMOVE_RECURSE ${example_build} ${example_out})
  list(REMOVE_ITEM configure_args -S ${CONSUMER_DIR} -B ${consumer_build})
  list(FILTER configure_args EXCLUDE REGEX "^-DTESSELLA_EXPECTED_MODULES=")
  run("configure example" ${CMAKE_COMMAND} -S ${EXAMPLE_DIR} -B ${example_build} ${configure_args})
  run("build example" ${CMAKE_COMMAND} --build ${example_build} -j2)
  run("run example" ${example_build}/meristem ${example_out})
  if(NOT EXISTS ${example_out}/meristem.pvd)
    message(FATAL_ERROR "install test: the meristem example wrote no ${example_out}/meristem.pvd")
  endif()
  file(READ ${example_out}/meristem.pvd pvd)
  string(REGEX MATCHALL "file=\"[^\"]+\"" listed "${pvd}")
  list(LENGTH listed snapshots)
  if(snapshots LESS 2)
    message(FATAL_ERROR "install test: meristem.pvd lists ${snapshots} snapshots (expected several)")
  endif()
  foreach(entry IN LISTS listed)
    string(REGEX REPLACE "^file=\"([^\"]+)\"$" "\\1" name "${entry}")
    if(NOT EXISTS ${example_out}/${name})
      message(FATAL_ERROR "install test: meristem.pvd lists ${name}, which is missing")
    endif()
  endforeach()
  message("install test: the meristem example wrote ${snapshots} snapshots")
endif()

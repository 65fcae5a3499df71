# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# tessella_add_module(name PUBLIC_DEPS ... PRIVATE_DEPS ...)
# One module = one directory = one library target `tessella_<name>` with the
# aliases `tessella::<name>` and `Tessella::<name>` (the latter is the name an
# installed package exports, so code written against either works unchanged).
# Sources are every src/**/*.cpp, subfolders too (so that adding a file needs no CMake edit);
# headers live in include/tessella/<name>/.
#
# With TESSELLA_INSTALL on, the module also installs itself: its library into
# the `TessellaTargets` export set (exported as Tessella::<name>) and its
# whole include/ tree. cmake/TessellaPackage.cmake writes the package files.
include(GNUInstallDirs)

function(tessella_add_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  set(target tessella_${name})
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    # Warnings are a build-tree concern: BUILD_INTERFACE keeps the target out
    # of the export (a static library's private deps are exported as LINK_ONLY).
    target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS}
      PRIVATE ${ARG_PRIVATE_DEPS} $<BUILD_INTERFACE:tessella_warnings>)
    if(TESSELLA_PARANOID)
      target_compile_definitions(${target} PUBLIC TESSELLA_PARANOID=1)
    endif()
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${target} INTERFACE ${ARG_PUBLIC_DEPS})
  endif()
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(tessella::${name} ALIAS ${target})
  add_library(Tessella::${name} ALIAS ${target})
  # The package (umbrella target, dependency list) is built from this list.
  set_property(GLOBAL APPEND PROPERTY TESSELLA_MODULE_TARGETS ${target})
  # At the end of the module's CMakeLists.txt: its imported targets are
  # visible there, and later target_link_libraries() calls are included.
  # (EVAL bakes the name in: DEFER expands variables only when it runs.)
  cmake_language(EVAL CODE "cmake_language(DEFER CALL _tessella_record_dependencies [[${target}]])")

  if(TESSELLA_INSTALL)
    install(TARGETS ${target} EXPORT TessellaTargets
      ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
      LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
      # The whole tree: everything under include/ is public by convention,
      # implementation files included by headers (detail/*.ipp) too.
      install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
    endif()
  endif()
endfunction()

# tessella_add_header_part(name HEADERS <paths under include/> PUBLIC_DEPS ...)
# A header-only part of the current module that other modules can link alone,
# without the module's library and its private dependencies: target
# `tessella_<name>` (INTERFACE) with the aliases `tessella::<name>` and
# `Tessella::<name>`, exported and installed like a module. Example: fe_mesh,
# the FeMesh type of mesh/, all that solvers/ and io/ need of it (no CGAL, no
# TetGen). Its headers stay in the module's include/ tree; they are installed
# here too, so the part is complete when the module itself is not built.
function(tessella_add_header_part name)
  cmake_parse_arguments(ARG "" "" "HEADERS;PUBLIC_DEPS" ${ARGN})
  set(target tessella_${name})
  add_library(${target} INTERFACE)
  target_include_directories(${target} INTERFACE
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} INTERFACE ${ARG_PUBLIC_DEPS})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(tessella::${name} ALIAS ${target})
  add_library(Tessella::${name} ALIAS ${target})
  _tessella_record_dependencies(${target})
  if(TESSELLA_INSTALL)
    install(TARGETS ${target} EXPORT TessellaTargets)
    foreach(header IN LISTS ARG_HEADERS)
      get_filename_component(dir ${header} DIRECTORY)
      install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/include/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${dir})
    endforeach()
  endif()
endfunction()

# tessella_link_items(target out_var): everything `target` links directly, as
# written (aliases, generator expressions and all): its own link libraries
# (a real library's) and its interface ones. The package export and the
# dependency check (tests/architecture) both read a target's links this way.
function(tessella_link_items target out_var)
  get_target_property(type ${target} TYPE)
  set(items "")
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(direct ${target} LINK_LIBRARIES)
    if(direct)
      list(APPEND items ${direct})
    endif()
  endif()
  get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
  if(interface)
    list(APPEND items ${interface})
  endif()
  set(${out_var} "${items}" PARENT_SCOPE)
endfunction()

# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# tessella_install_package(): the installable CMake package `Tessella`.
# Call once, after every module is added. It creates the umbrella target
# Tessella::tessella (links every built module), installs the export set
# TessellaTargets with the namespace Tessella::, and writes TessellaConfig.cmake
# and TessellaConfigVersion.cmake.
#
# The config must find what the exported link interfaces name: public deps
# (Eigen, OpenMP) and, because the modules are static archives, their private
# deps too (CMake exports them as $<LINK_ONLY:...>). Rather than a hand-kept
# list that goes stale when a module gains a dependency, the dependencies are
# read from the module targets' link libraries here and turned into
# find_dependency() calls (imported target Ns::X -> package Ns). Targets that
# pkg_check_modules() made cannot be re-found by name, so their resolved
# properties are written into the config instead. Anything not understood
# stops the configure with a message naming the module and the item.
include(CMakePackageConfigHelpers)

set(TESSELLA_CONFIG_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Tessella)

# Records, in global properties, what a consumer needs so that `item` (one
# link item of `module`) resolves: TESSELLA_DEP_PACKAGES (packages in order of
# first use), TESSELLA_DEP_COMPONENTS_<package>, TESSELLA_DEP_CODE (targets
# recreated verbatim). Runs in the module's directory, where the imported
# targets its CMakeLists.txt found are visible.
function(_tessella_record_dependency module item)
  if(item MATCHES "^\\$<LINK_ONLY:(.*)>$")
    set(item "${CMAKE_MATCH_1}")
  endif()
  if(item MATCHES "^\\$<BUILD_INTERFACE:")
    return()  # never exported
  endif()
  if(item MATCHES "^\\$<")
    message(FATAL_ERROR "Tessella package: module ${module} links the generator expression "
      "'${item}', which cmake/TessellaPackage.cmake does not know how to export.")
  endif()
  if(NOT TARGET ${item})
    # A plain library path or a linker flag (-lm, /usr/lib/.../libtet.so) is
    # written into the export as is and needs nothing from the config.
    if(item MATCHES "::")
      message(FATAL_ERROR "Tessella package: module ${module} links '${item}', which is not a target.")
    endif()
    if(IS_ABSOLUTE "${item}" AND NOT EXISTS "${item}")
      message(FATAL_ERROR "Tessella package: module ${module} links '${item}', which does not exist.")
    endif()
    return()
  endif()
  get_target_property(aliased ${item} ALIASED_TARGET)
  if(aliased)
    set(item ${aliased})
  endif()
  if(item MATCHES "^tessella_")
    return()  # one of ours: part of the export set
  endif()
  get_target_property(imported ${item} IMPORTED)
  if(NOT imported)
    message(FATAL_ERROR "Tessella package: module ${module} links the build target '${item}', "
      "which is not installed. Link it as $<BUILD_INTERFACE:${item}> or install it.")
  endif()
  get_property(packages GLOBAL PROPERTY TESSELLA_DEP_PACKAGES)
  if(item MATCHES "^PkgConfig::")
    # pkg_check_modules() targets cannot be re-found by name: recreate the
    # target from what was found at build time.
    if(NOT "${item}" IN_LIST packages)
      set_property(GLOBAL APPEND PROPERTY TESSELLA_DEP_PACKAGES ${item})
      set(code "if(NOT TARGET ${item})\n  add_library(${item} INTERFACE IMPORTED)\n")
      foreach(prop INTERFACE_LINK_LIBRARIES INTERFACE_INCLUDE_DIRECTORIES
                   INTERFACE_COMPILE_OPTIONS INTERFACE_LINK_OPTIONS INTERFACE_LINK_DIRECTORIES)
        get_target_property(value ${item} ${prop})
        if(value)
          string(APPEND code "  set_property(TARGET ${item} PROPERTY ${prop} \"${value}\")\n")
        endif()
      endforeach()
      string(APPEND code "endif()\n")
      set_property(GLOBAL APPEND_STRING PROPERTY TESSELLA_DEP_CODE "${code}")
    endif()
    return()
  endif()
  # Ns::Component -> package Ns (components kept for VTK and OpenMP, whose
  # configs create only the targets asked for); an un-namespaced imported
  # target (yaml-cpp) names its package.
  if(item MATCHES "^([^:]+)::(.+)$")
    set(package ${CMAKE_MATCH_1})
    set(component ${CMAKE_MATCH_2})
  else()
    set(package ${item})
    set(component "")
  endif()
  if(package STREQUAL "OpenMP")
    string(REGEX REPLACE "^OpenMP_" "" component "${component}")
  elseif(NOT package STREQUAL "VTK")
    set(component "")
  endif()
  if(NOT "${package}" IN_LIST packages)
    set_property(GLOBAL APPEND PROPERTY TESSELLA_DEP_PACKAGES ${package})
  endif()
  if(component)
    get_property(comps GLOBAL PROPERTY TESSELLA_DEP_COMPONENTS_${package})
    if(NOT "${component}" IN_LIST comps)
      set_property(GLOBAL APPEND PROPERTY TESSELLA_DEP_COMPONENTS_${package} ${component})
    endif()
  endif()
endfunction()

# Deferred by tessella_add_module to the end of the module's CMakeLists.txt,
# so link libraries added after the call are seen too.
function(_tessella_record_dependencies target)
  string(REGEX REPLACE "^tessella_" "" module ${target})
  tessella_link_items(${target} items)
  foreach(item IN LISTS items)
    _tessella_record_dependency(${module} "${item}")
  endforeach()
endfunction()

function(tessella_install_package)
  get_property(modules GLOBAL PROPERTY TESSELLA_MODULE_TARGETS)

  # Umbrella target. Not called `tessella`: that is the command-line program.
  add_library(tessella_all INTERFACE)
  target_link_libraries(tessella_all INTERFACE ${modules})
  set_target_properties(tessella_all PROPERTIES EXPORT_NAME tessella)
  add_library(Tessella::tessella ALIAS tessella_all)
  if(NOT TESSELLA_INSTALL)
    return()
  endif()
  install(TARGETS tessella_all EXPORT TessellaTargets)

  # Dependencies, in module order (so a package is found before one using it).
  set(names "")
  foreach(target IN LISTS modules)
    string(REGEX REPLACE "^tessella_" "" name ${target})
    list(APPEND names ${name})
  endforeach()
  get_property(packages GLOBAL PROPERTY TESSELLA_DEP_PACKAGES)
  set(find_code "")
  foreach(package IN LISTS packages)
    if(package MATCHES "^PkgConfig::")
      continue()
    endif()
    set(args ${package})
    if(package STREQUAL "Eigen3")
      list(APPEND args NO_MODULE)
    endif()
    get_property(comps GLOBAL PROPERTY TESSELLA_DEP_COMPONENTS_${package})
    if(comps)
      list(APPEND args COMPONENTS ${comps})
    endif()
    list(JOIN args " " args)
    string(APPEND find_code "find_dependency(${args})\n")
  endforeach()
  get_property(pkgconfig_code GLOBAL PROPERTY TESSELLA_DEP_CODE)
  string(APPEND find_code "${pkgconfig_code}")

  set(TESSELLA_CONFIG_DEPENDENCIES "${find_code}")
  set(TESSELLA_CONFIG_MODULES "${names}")
  configure_package_config_file(
    ${PROJECT_SOURCE_DIR}/cmake/TessellaConfig.cmake.in
    ${PROJECT_BINARY_DIR}/TessellaConfig.cmake
    INSTALL_DESTINATION ${TESSELLA_CONFIG_INSTALL_DIR})
  # 0.x: a minor release may break the API, so only the same minor matches.
  write_basic_package_version_file(
    ${PROJECT_BINARY_DIR}/TessellaConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/TessellaConfig.cmake ${PROJECT_BINARY_DIR}/TessellaConfigVersion.cmake
    DESTINATION ${TESSELLA_CONFIG_INSTALL_DIR})
  install(EXPORT TessellaTargets NAMESPACE Tessella:: DESTINATION ${TESSELLA_CONFIG_INSTALL_DIR})

  # The umbrella header of the tissue module is installed with tissue's
  # include/ tree; the command-line program, when built, goes to bin/.
  if(TARGET tessella)
    install(TARGETS tessella RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endfunction()

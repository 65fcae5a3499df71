# tessella_add_module(name PUBLIC_DEPS ... PRIVATE_DEPS ...)
# One module = one directory = one library target `tessella_<name>` with the
# alias `tessella::<name>`. Sources are every src/*.cpp (so that adding a file
# needs no CMake edit); headers live in include/tessella/<name>/.
function(tessella_add_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  set(target tessella_${name})
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
    target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS} tessella_warnings)
    if(TESSELLA_PARANOID)
      target_compile_definitions(${target} PUBLIC TESSELLA_PARANOID=1)
    endif()
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
    target_link_libraries(${target} INTERFACE ${ARG_PUBLIC_DEPS})
  endif()
  add_library(tessella::${name} ALIAS ${target})
endfunction()

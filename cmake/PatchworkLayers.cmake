# The folder tree is the architecture (docs/DESIGN.md, "Layers"). Every folder of core/, render/
# and ui/ is one library, patchwork_<path with _>, for example core/model -> patchwork_core_model,
# built from the folder's *.cpp (an INTERFACE library when it has none). The folder's LAYER file
# names the folders it may use, one `uses FOLDER` a line; they are linked PUBLIC, so a folder is
# built and linked against exactly what it declares (and what those declare). tests/test_layering.cpp
# reads the same files and fails on any include that is not declared.

# The targets that the LAYER file of `dir` (relative to the repository root) declares.
function(patchwork_layer_uses dir out)
  file(STRINGS ${PROJECT_SOURCE_DIR}/${dir}/LAYER lines)
  set(targets)
  foreach(line IN LISTS lines)
    if(line MATCHES "^uses[ \t]+([a-z0-9_/]+)[ \t]*$")
      string(REPLACE "/" "_" dep "patchwork_${CMAKE_MATCH_1}")
      list(APPEND targets ${dep})
    elseif(NOT line MATCHES "^(#.*)?$")
      message(FATAL_ERROR "${dir}/LAYER: '${line}' is neither a comment nor 'uses FOLDER'")
    endif()
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/LAYER)
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# Precompiled headers for the product libraries (PATCHWORK_PCH): the standard library and GLM
# headers most of their sources include, compiled once by the first library with sources
# (core/base) and reused by every other one, as the tests reuse one for GoogleTest. On in the
# sanitizer build (scripts/sanitize.sh: a unity build, which already hides a missing include),
# off in the Release build, where GCC 12 raises its -Warray-bounds false positives in libstdc++
# through the precompiled header (and a PATCHWORK_UNITY=OFF build, one file at a time, checks
# that every file includes what it uses). docs/PERFORMANCE.md has the build times with and without.
option(PATCHWORK_PCH "Precompiled headers for the product libraries" OFF)
function(patchwork_precompiled_headers target)
  if(NOT PATCHWORK_PCH)
    return()
  endif()
  get_property(first GLOBAL PROPERTY PATCHWORK_PCH_TARGET)
  if(NOT first)
    set_property(GLOBAL PROPERTY PATCHWORK_PCH_TARGET ${target})
    target_precompile_headers(${target} PRIVATE <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <functional> <map>
                              <memory> <optional> <string> <string_view> <utility> <vector> <glm/geometric.hpp> <glm/vec3.hpp>)
  else()
    target_precompile_headers(${target} REUSE_FROM ${first})
  endif()
endfunction()

# patchwork_layer([PUBLIC libs...] [PRIVATE libs...]): the library of the calling folder.
function(patchwork_layer)
  cmake_parse_arguments(L "" "" "PUBLIC;PRIVATE" ${ARGN})
  file(RELATIVE_PATH dir ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  string(REPLACE "/" "_" name "patchwork_${dir}")
  patchwork_layer_uses(${dir} uses)
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC ${uses} ${L_PUBLIC} PRIVATE ${L_PRIVATE})
    patchwork_precompiled_headers(${name})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${uses} ${L_PUBLIC})
  endif()
  set_property(GLOBAL APPEND PROPERTY PATCHWORK_LAYERS ${name})
endfunction()

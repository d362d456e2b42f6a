# Checks the layering of core/ (docs/design.md): every package may include only itself and the
# packages below it, and nothing in core/ includes Qt or the ui/ and app/ trees. Run as
#   cmake -DCORE_DIR=<core> -P CheckCoreLayers.cmake
# It is a build step of every core library and a test (test_core_layers); a back-reference fails
# both, naming the file, the line and the rule it breaks.
#
# The layers, bottom up. A package sees the packages listed after its colon (and itself).
cmake_minimum_required(VERSION 3.25)
set(FILMDYN_CORE_LAYERS
  "base:"
  "lubrication:base"
  "multibody:base"
  "coupling:base,lubrication,multibody"
  "engine:base,lubrication,multibody,coupling"
  "verification:base,lubrication,multibody,coupling,engine"
  "io:base,lubrication,multibody,coupling,engine"
  "batch:base,lubrication,multibody,coupling,engine,io")

set(offenders "")
set(known_packages "")
foreach(entry IN LISTS FILMDYN_CORE_LAYERS)
  string(REPLACE ":" ";" parts "${entry}")
  list(GET parts 0 package)
  list(APPEND known_packages "${package}")
endforeach()

file(GLOB top_level_files "${CORE_DIR}/*.hpp" "${CORE_DIR}/*.cpp" "${CORE_DIR}/*.h")
foreach(f IN LISTS top_level_files)
  list(APPEND offenders "${f}: a source outside every package (put it in one of ${known_packages})")
endforeach()
file(GLOB package_dirs LIST_DIRECTORIES true "${CORE_DIR}/*")
foreach(dir IN LISTS package_dirs)
  if(IS_DIRECTORY "${dir}")
    get_filename_component(name "${dir}" NAME)
    if(NOT name IN_LIST known_packages)
      list(APPEND offenders "${dir}: a package that is not in the layer table of CheckCoreLayers.cmake")
    endif()
  endif()
endforeach()

foreach(entry IN LISTS FILMDYN_CORE_LAYERS)
  string(REPLACE ":" ";" parts "${entry}")
  list(GET parts 0 package)
  list(LENGTH parts n)
  set(allowed "${package}")
  if(n GREATER 1)
    list(GET parts 1 below)
    string(REPLACE "," ";" below "${below}")
    list(APPEND allowed ${below})
  endif()
  file(GLOB_RECURSE files "${CORE_DIR}/${package}/*.hpp" "${CORE_DIR}/${package}/*.h"
       "${CORE_DIR}/${package}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      if(line MATCHES "[<\"](Q[A-Za-z]+|Qt[A-Za-z]*/)")
        list(APPEND offenders "${f}: ${line} (core/ never includes Qt)")
      elseif(line MATCHES "[<\"](ui|app)/")
        list(APPEND offenders "${f}: ${line} (core/ never includes the ui/ or app/ trees)")
      elseif(line MATCHES "[<\"]core/([a-z_]+)/")
        set(target "${CMAKE_MATCH_1}")
        if(NOT target IN_LIST allowed)
          string(REPLACE ";" ", " allowed_text "${allowed}")
          list(APPEND offenders
               "${f}: ${line} (core/${package} may include only: ${allowed_text})")
        endif()
      elseif(line MATCHES "[<\"]core/[^/]+[\">]")
        list(APPEND offenders "${f}: ${line} (no headers outside a package)")
      endif()
    endforeach()
  endforeach()
endforeach()

if(offenders)
  string(REPLACE ";" "\n  " msg "${offenders}")
  message(FATAL_ERROR "core/ layering broken:\n  ${msg}")
endif()

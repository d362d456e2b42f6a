# test_core_layers: the real core/ passes the layer check, and the check does catch what it
# must (each rule is broken once in a scratch tree and must fail with a message naming it).
# Run as cmake -DCORE_DIR=... -DCHECKER=... -DSCRATCH=... -P layer_check_test.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${CMAKE_COMMAND} -DCORE_DIR=${CORE_DIR} -P ${CHECKER}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "core/ breaks its layering:\n${err}")
endif()

function(expect_failure label file content expected)
  file(REMOVE_RECURSE "${SCRATCH}")
  foreach(p base lubrication multibody coupling engine verification io batch)
    file(MAKE_DIRECTORY "${SCRATCH}/${p}")
  endforeach()
  file(WRITE "${SCRATCH}/${file}" "${content}\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -DCORE_DIR=${SCRATCH} -P ${CHECKER}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "layer check accepted ${label}")
  endif()
  string(FIND "${err}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "layer check rejected ${label} without saying '${expected}':\n${err}")
  endif()
  message(STATUS "rejected as expected: ${label}")
endfunction()

expect_failure("a leaf including the engine" "lubrication/a.hpp"
               "#include \"core/engine/crank_train.hpp\"" "core/lubrication may include only")
expect_failure("the two leaves knowing each other" "multibody/a.cpp"
               "#include \"core/lubrication/tri_mesh.hpp\"" "core/multibody may include only")
expect_failure("coupling including the engine" "coupling/a.hpp"
               "#include \"core/engine/engine_case.hpp\"" "core/coupling may include only")
expect_failure("the engine including io" "engine/a.cpp"
               "#include \"core/io/case_file.hpp\"" "core/engine may include only")
expect_failure("io including batch" "io/a.cpp"
               "#include \"core/batch/sweep.hpp\"" "core/io may include only")
expect_failure("a Qt include" "base/a.cpp" "#include <QString>" "never includes Qt")
expect_failure("a ui include" "io/a.cpp" "#include \"ui/run/run_record.hpp\"" "ui/ or app/")
expect_failure("a file outside every package" "loose.cpp" "int x;" "outside every package")
expect_failure("an unknown package" "newpkg/a.cpp" "int x;" "not in the layer table")
file(REMOVE_RECURSE "${SCRATCH}")

# Precompiled headers: the build parses the heavy library headers (the standard library, Eigen,
# fmt, JSON, Qt) once per target instead of once per source file. FILMDYN_PCH=OFF turns them off
# (e.g. to check that every file includes what it uses).
#
# - filmdyn_target_pch(<target> [headers...]): a target's own PCH (the common headers below plus
#   the ones given), shared by the target's sources — GCC and clang.
# - The test suites are one executable each, mostly of one source: a PCH of their own would save
#   nothing. With GCC they reuse the PCH of one donor executable (filmdyn_test_pch, tests/pch)
#   built with the same options; GCC accepts a PCH whose command line differs only by macros the
#   headers in it never test (each test's QT_TESTCASE_BUILDDIR, FILMDYN_EXECUTABLE, QT_*_LIB),
#   which is why QtTest (which tests several of them) is not in it. clang rejects any difference
#   in the command line's macros.
#   With clang (the sanitizer builds) the core's suites share a PCH per test folder instead: Qt
#   Test's macros QT_TESTCASE_BUILDDIR and QT_TESTCASE_SOURCEDIR are the folder's, and every core
#   suite links the same libraries, so within a folder the command lines' macros agree
#   (filmdyn_folder_test_pch in cmake/FilmDynTesting.cmake). The GUI's and the app's suites, a
#   few per folder and with differing libraries, are built without one there.
# - With GCC the core's packages likewise share one PCH, the base package's (core/CMakeLists.txt).
option(FILMDYN_PCH "Use precompiled headers" ON)

set(FILMDYN_PCH_COMMON
    <algorithm> <array> <cmath> <cstddef> <filesystem> <functional> <map> <memory> <optional>
    <sstream> <string> <utility> <vector> <Eigen/Dense> <fmt/format.h>)

function(filmdyn_target_pch target)
  if(FILMDYN_PCH)
    target_precompile_headers(${target} PRIVATE ${FILMDYN_PCH_COMMON} ${ARGN})
  endif()
endfunction()

# Whether PCHs are shared across targets (GCC; see above): the core's and the suites'.
if(FILMDYN_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(FILMDYN_SHARED_PCH ON)
else()
  set(FILMDYN_SHARED_PCH OFF)
endif()
if(FILMDYN_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(FILMDYN_FOLDER_TEST_PCH ON)
else()
  set(FILMDYN_FOLDER_TEST_PCH OFF)
endif()

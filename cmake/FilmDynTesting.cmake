# filmdyn_add_qtest(<name> SOURCES <files...> LIBS <targets...> LABEL core|ui|app [GL] [TIMEOUT s]
#                   [COST s])
# Every test is a Qt Test executable. Non-GL tests run on the `offscreen` platform; GL tests need
# a real X server (Qt 6.4 segfaults rendering a QOpenGLWidget offscreen), so they are wrapped in
# xvfb-run automatically unless a DISPLAY is already set.
find_program(XVFB_RUN_EXECUTABLE xvfb-run)

# The suites' common compile definitions (FILMDYN_INSTRUMENTED: see filmdyn_add_qtest).
function(filmdyn_test_definitions target)
  target_compile_definitions(${target} PRIVATE
    FILMDYN_SOURCE_DIR="${PROJECT_SOURCE_DIR}" FILMDYN_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=")
    target_compile_definitions(${target} PRIVATE FILMDYN_INSTRUMENTED=1)
  endif()
endfunction()

# filmdyn_test_moc(<suite> <sources...>): a suite's Q_OBJECT classes live in its source, which
# includes "<source's name>.moc" at its end. moc runs on each source by itself instead of through
# AUTOMOC: AUTOMOC hands moc the target's include paths, and moc then preprocesses every header the
# suite includes (Eigen, Qt Test, FilmDyn's) to about a second per suite, for the same output moc
# gives in a hundredth of that without them (the test class's slots need no macro from a header).
function(filmdyn_test_moc name)
  set(moc_dir "${CMAKE_CURRENT_BINARY_DIR}/${name}_moc")
  foreach(source IN LISTS ARGN)
    get_filename_component(path "${source}" ABSOLUTE)
    get_filename_component(base "${source}" NAME_WE)
    add_custom_command(OUTPUT "${moc_dir}/${base}.moc"
      COMMAND Qt6::moc --no-notes "${path}" -o "${moc_dir}/${base}.moc"
      DEPENDS "${path}" Qt6::moc
      COMMENT "moc ${source}" VERBATIM)
    target_sources(${name} PRIVATE "${moc_dir}/${base}.moc")
  endforeach()
  target_include_directories(${name} PRIVATE "${moc_dir}")
  set_target_properties(${name} PROPERTIES AUTOMOC OFF)
endfunction()

# filmdyn_folder_test_pch(<suite>): with clang, a core suite reuses the PCH of its folder's donor
# (cmake/FilmDynPch.cmake says why one per folder), made with the first suite of the folder.
function(filmdyn_folder_test_pch name)
  string(MAKE_C_IDENTIFIER "${CMAKE_CURRENT_SOURCE_DIR}" folder)
  string(MD5 folder "${folder}")
  string(SUBSTRING "${folder}" 0 10 folder)
  set(donor filmdyn_test_pch_${folder})
  if(NOT TARGET ${donor})
    add_executable(${donor} "${PROJECT_SOURCE_DIR}/tests/pch/pch_donor.cpp")
    target_link_libraries(${donor} PRIVATE FilmDyn::core Qt6::Test)
    filmdyn_test_definitions(${donor})
    filmdyn_warnings(${donor})
    set_target_properties(${donor} PROPERTIES AUTOMOC OFF)
    target_precompile_headers(${donor} PRIVATE ${FILMDYN_PCH_COMMON} <nlohmann/json.hpp>
                              <QtCore/QtCore>)
  endif()
  target_precompile_headers(${name} REUSE_FROM ${donor})
  target_compile_options(${name} PRIVATE -Winvalid-pch)
endfunction()

function(filmdyn_add_qtest name)
  cmake_parse_arguments(T "GL" "LABEL;TIMEOUT;COST" "SOURCES;LIBS" ${ARGN})
  if(NOT T_LABEL)
    message(FATAL_ERROR "filmdyn_add_qtest(${name}): LABEL is required")
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} Qt6::Test)
  filmdyn_test_definitions(${name})
  filmdyn_test_moc(${name} ${T_SOURCES})
  filmdyn_warnings(${name})
  # The donor's PCH (tests/CMakeLists.txt) for the suites that link FilmDyn's libraries (the
  # donor's macros and include paths come from them); a rejected PCH is a warning.
  if(FILMDYN_SHARED_PCH AND "${T_LIBS}" MATCHES "FilmDyn::|filmdyn_cli")
    target_precompile_headers(${name} REUSE_FROM filmdyn_test_pch)
    target_compile_options(${name} PRIVATE -Winvalid-pch)
  elseif(FILMDYN_FOLDER_TEST_PCH AND T_LABEL STREQUAL "core" AND "${T_LIBS}" STREQUAL "FilmDyn::core")
    filmdyn_folder_test_pch(${name})
  endif()
  set(labels ${T_LABEL})
  if(T_GL)
    list(APPEND labels gl)
    add_test(NAME ${name} COMMAND ${CMAKE_COMMAND}
      -DEXE=$<TARGET_FILE:${name}> -DXVFB_RUN=${XVFB_RUN_EXECUTABLE}
      -P ${PROJECT_SOURCE_DIR}/cmake/RunWithDisplay.cmake)
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "QT_QPA_PLATFORM=xcb")
  else()
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
  endif()
  # One time bound per suite, CTest's: QtTest's own watchdog (5 minutes per test function by
  # default) is set to the suite's timeout, so that a slow machine or an instrumented build gets
  # the whole budget and a suite that overruns it ends with CTest's clear timeout.
  math(EXPR function_timeout_ms "${T_TIMEOUT} * 1000")
  set_property(TEST ${name} APPEND PROPERTY ENVIRONMENT "QTEST_FUNCTION_TIMEOUT=${function_timeout_ms}")
  # Instrumented builds (the sanitizer scripts' -fsanitize=...) run 3-6x slower: a suite may
  # leave out there what only checks numbers the Release suites check (FILMDYN_INSTRUMENTED,
  # defined by filmdyn_test_definitions).
  set_tests_properties(${name} PROPERTIES LABELS "${labels}" TIMEOUT ${T_TIMEOUT})
  # COST: the suite's wall time in seconds, measured in a Release build. `ctest -j` starts the
  # costliest suites first, so that a fresh build directory (CI's, with no timings of earlier
  # runs) does not end with two long suites running one after the other.
  if(T_COST)
    set_tests_properties(${name} PROPERTIES COST ${T_COST})
  endif()
endfunction()

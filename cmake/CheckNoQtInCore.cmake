# Build step: core/ is the numerical engine and must never include Qt (SPEC §2).
# Run as `cmake -DCORE_DIR=... -P CheckNoQtInCore.cmake`; fails the build naming the offenders.
file(GLOB_RECURSE core_files "${CORE_DIR}/*.hpp" "${CORE_DIR}/*.h" "${CORE_DIR}/*.cpp")
set(offenders "")
foreach(f IN LISTS core_files)
  file(STRINGS "${f}" hits REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](Q[A-Za-z]+|Qt[A-Za-z]*/)")
  if(hits)
    list(APPEND offenders "${f}: ${hits}")
  endif()
endforeach()
if(offenders)
  string(REPLACE ";" "\n  " msg "${offenders}")
  message(FATAL_ERROR "core/ must not include Qt headers (SPEC §2):\n  ${msg}")
endif()

# Warnings on for our own targets only; third-party headers come in as SYSTEM includes.
function(filmdyn_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-deprecated-enum-enum-conversion)
endfunction()

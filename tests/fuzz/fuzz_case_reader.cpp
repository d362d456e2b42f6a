// libFuzzer harness: the case reader (JSON text → EngineCase, the schema's checks, the
// cross-field rules) on arbitrary bytes. Bad input must end in filmdyn::InputError and nothing
// else: any other exception, a crash, a sanitizer report or a hang is a finding.
// Run: scripts/fuzz.sh (docs/reliability.md).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)filmdyn::io::LoadCaseText(text, "fuzz");
  } catch (const filmdyn::InputError&) {
    // the expected answer to bad input
  } catch (const std::exception& error) {
    std::fprintf(stderr, "not an InputError: %s\n", error.what());
    std::abort();
  }
  return 0;
}

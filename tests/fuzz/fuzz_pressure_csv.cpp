// libFuzzer harness: the cylinder-pressure CSV reader (text → PressureCurve, with the curve's
// own checks) on arbitrary bytes. Bad input must end in filmdyn::InputError and nothing else.
// Run: scripts/fuzz.sh (docs/reliability.md).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>

#include "core/base/input_error.hpp"
#include "core/io/pressure_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    (void)filmdyn::io::ReadPressureCsv(in, "fuzz");
  } catch (const filmdyn::InputError&) {
  } catch (const std::exception& error) {
    std::fprintf(stderr, "not an InputError: %s\n", error.what());
    std::abort();
  }
  return 0;
}

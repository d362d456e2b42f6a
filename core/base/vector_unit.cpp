#include "core/base/vector_unit.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace filmdyn {

#if defined(__x86_64__) || defined(__i386__)
namespace {
__attribute__((target("avx"))) void ZeroUpper() { _mm256_zeroupper(); }
const bool kHasAvx = __builtin_cpu_supports("avx");
}  // namespace

void ResetVectorUnitState() {
  if (kHasAvx) ZeroUpper();
}
#else
void ResetVectorUnitState() {}
#endif

}  // namespace filmdyn

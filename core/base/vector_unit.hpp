#pragma once
/// @file The CPU's vector-register state before numerical work.
///
/// Code that uses 256- or 512-bit AVX instructions and returns without VZEROUPPER leaves the
/// upper halves of the vector registers "dirty"; on Intel cores from Skylake on, every later
/// 128-bit SSE instruction then carries a false dependency on them. Creating a QApplication
/// does this (measured: plain SSE loops 4x slower afterwards on an Ice Lake Xeon; a whole
/// coupled run 2x slower — docs/performance.md). The numerical core is compiled for SSE2, so
/// it clears that state on every thread before it computes. A new thread inherits its creator's
/// register state, so every thread that runs a solve calls this.
namespace filmdyn {

/// Executes VZEROUPPER when the CPU has AVX (else nothing). Costs a few cycles.
void ResetVectorUnitState();

}  // namespace filmdyn

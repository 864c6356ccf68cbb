// simd.h — which vector code the processor runs: chosen once, at run time, for every unit that has wider paths.
//
// Each wide path computes the same operations as the narrow one, lane for lane (no FMA: it rounds differently),
// so the choice changes speed, never results.
#pragma once

namespace softgl::detail {

enum class SimdLevel : int {
  kBaseline = 0,  // SSE2 on x86-64 (or no vector code elsewhere)
  kAvx2 = 1,      // AVX2 with SSE4.1
  kAvx512 = 2,    // AVX-512 F, DQ, BW and VL
};

/// The widest level the processor has, capped by SOFTGL_SIMD=sse2 or SOFTGL_SIMD=avx2 in the environment (to test
/// the narrower paths on a wide processor). Read once.
SimdLevel CpuSimdLevel();

}  // namespace softgl::detail

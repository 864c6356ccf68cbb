// simd.h — which vector code the processor runs: chosen once, at run time, for every unit that has wider paths.
//
// Each wide path computes the same operations as the narrow one, lane for lane (no FMA: it rounds differently),
// so the choice changes speed, never results.
#pragma once

#include <softgl/lanes.h>  // SOFTGL_HAS_DISPATCH

namespace softgl::detail {

enum class SimdLevel : int {
  kBaseline = 0,  // SSE2 on x86-64 (or no vector code elsewhere)
  kAvx2 = 1,      // AVX2 with SSE4.1
  kAvx512 = 2,    // AVX-512 F, DQ, BW and VL
};

/// The widest level the processor has, capped by SOFTGL_SIMD=sse2 or SOFTGL_SIMD=avx2 in the environment (to test
/// the narrower paths on a wide processor). Read once.
SimdLevel CpuSimdLevel();

/// Of the three compiled forms of a wide function, the one for the processor (CpuSimdLevel).
///
/// A unit's AVX-512 form may run 8 lanes rather than 16. GCC 12 compiles a comparison of 16-lane (64-byte) vectors
/// inside an always-inlined helper lane by lane (a compare, a set and an insert per lane) before the helper is
/// inlined into the AVX-512 function; 32-byte vectors are compiled whole. Where a unit compares in its helpers
/// (clip codes, the triangle-group verdict, the per-fragment operations), its AVX-512 form takes 8 lanes, with
/// the AVX-512 instruction set. The generated code was checked function by function (instruction counts).
/// The rasterizer's wide units and the early depth test take 8 lanes there too: measured, they ran faster than
/// with 16 on every bench scene but blended fill (docs/performance.md). The texture sampler keeps 16 (its gathers
/// gain from them).
template <class Fn>
Fn ForSimdLevel(Fn base, Fn avx2, Fn avx512) {
  switch (CpuSimdLevel()) {
    case SimdLevel::kAvx512: return avx512;
    case SimdLevel::kAvx2: return avx2;
    default: return base;
  }
}

}  // namespace softgl::detail

// The form of wide function NAME that the processor runs: NAMEAvx512, NAMEAvx2 or NAMEBase (the wider two exist
// where SOFTGL_HAS_DISPATCH is defined, compiled with SOFTGL_TARGET_AVX512 and SOFTGL_TARGET_AVX2). A template's
// arguments follow the name: SOFTGL_CHOOSE(Fn, <4>).
#if defined(SOFTGL_HAS_DISPATCH)
#define SOFTGL_CHOOSE(name, ...) \
  ::softgl::detail::ForSimdLevel(name##Base __VA_ARGS__, name##Avx2 __VA_ARGS__, name##Avx512 __VA_ARGS__)
#else
#define SOFTGL_CHOOSE(name, ...) (name##Base __VA_ARGS__)
#endif

// wide.h — the vector types of softgl's own wide code (interpolation, texture sampling, per-fragment operations):
// GCC vector extensions of W lanes, W being the processor's native width (4 with SSE2, 8 with AVX2, 16 with
// AVX-512), so that every operation, comparisons included, compiles to that width's instructions. Each wide unit
// is a template on W, compiled three times by functions marked SOFTGL_TARGET_* (softgl/lanes.h) and chosen once at
// run time (CpuSimdLevel, simd.h).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

#include <softgl/lanes.h>

#if defined(SOFTGL_HAS_DISPATCH)
#include <immintrin.h>
#endif

// The helpers pass vectors by value, always inlined: the compilers' note that such a call's ABI depends on the
// instruction set (-Wpsabi) is moot, and CMakeLists.txt turns it off for the files that include this header.

// Wide helpers are always inlined into the function compiled for one instruction set: no out-of-line copy of them
// exists, compiled for another.
#define SOFTGL_WIDE inline __attribute__((always_inline))
// The same for a lambda that takes or returns vectors: [&](F x) SOFTGL_WIDE_LAMBDA { ... }.
#define SOFTGL_WIDE_LAMBDA __attribute__((always_inline))

namespace softgl::detail {

template <int W>
struct V {
  typedef float F __attribute__((vector_size(4 * W)));
  typedef std::int32_t I __attribute__((vector_size(4 * W)));
  typedef std::uint32_t U __attribute__((vector_size(4 * W)));
  typedef std::uint8_t B __attribute__((vector_size(W)));
  typedef std::uint16_t S __attribute__((vector_size(2 * W)));  // W lanes of 16 bits
  typedef std::uint64_t Q __attribute__((vector_size(4 * W)));  // pairs of 32-bit lanes
  typedef std::uint16_t H __attribute__((vector_size(4 * W)));  // halves of 32-bit lanes
  typedef std::uint64_t D __attribute__((vector_size(8 * W)));  // W lanes of 64 bits
};

// Unaligned vector loads and stores: one move through a type that may alias anything (a memcpy may be expanded as
// 16-byte pieces through the stack).
template <class T>
struct __attribute__((packed, may_alias)) UnalignedVec {
  T v;
};
template <class T>
SOFTGL_WIDE T LoadVec(const void* p) {
  return static_cast<const UnalignedVec<T>*>(p)->v;
}
template <class T>
SOFTGL_WIDE void StoreVec(void* p, const T& v) {
  static_cast<UnalignedVec<T>*>(p)->v = v;
}
/// 0, 1, 2, ... W - 1.
template <int W>
SOFTGL_WIDE typename V<W>::I Iota() {
  typename V<W>::I r;
  for (int l = 0; l < W; ++l) r[l] = l;
  return r;
}

/// The lanes l0 .. l0 + W - 1 of bit mask `bits` as a vector mask (all bits set where the bit is).
template <int W>
SOFTGL_WIDE typename V<W>::I BitsToMask(std::uint32_t bits, int l0) {
  using I = typename V<W>::I;
  const I lane_bit = (I{} + 1) << Iota<W>();
  return ((I{} + std::int32_t(bits >> l0)) & lane_bit) != 0;
}

/// A vector mask as bits, shifted to lanes l0 .. l0 + W - 1.
template <int W>
SOFTGL_WIDE std::uint32_t MaskToBits(typename V<W>::I m, int l0) {
  using I = typename V<W>::I;
  I v = m & ((I{} + 1) << Iota<W>());
  std::int32_t bits = 0;
  for (int l = 0; l < W; ++l) bits |= v[l];  // OR of the lanes (the compiler reduces it)
  return std::uint32_t(bits) << l0;
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// On x86 the lanes' sign bits, one instruction (movmskps, vpmovd2m); the 8- and 16-lane forms are compiled for the
// instruction sets that have them, and inlined into the functions compiled for those. (Clang checks a target
// attribute before it inlines the template that calls this into its target function, and rejects the call: it
// compiles the generic form.)
template <>
inline std::uint32_t MaskToBits<4>(V<4>::I m, int l0) {
  return std::uint32_t(_mm_movemask_ps(__m128(m))) << l0;
}
template <>
__attribute__((target("avx2"))) inline std::uint32_t MaskToBits<8>(V<8>::I m, int l0) {
  return std::uint32_t(_mm256_movemask_ps(__m256(m))) << l0;
}
template <>
__attribute__((target("avx512f,avx512dq"))) inline std::uint32_t MaskToBits<16>(V<16>::I m, int l0) {
  return std::uint32_t(_mm512_movepi32_mask(__m512i(m))) << l0;
}
#endif

/// table[idx[l]] for each lane l (idx within the table): on x86 with AVX2 and AVX-512 one gather instruction, else
/// lane by lane. T is float or std::int32_t; Vec the lanes of T.
template <int W, class T, class Vec = std::conditional_t<std::is_same_v<T, float>, typename V<W>::F, typename V<W>::I>>
SOFTGL_WIDE Vec TableLanes(const T* table, typename V<W>::I idx) {
  Vec r;
  for (int l = 0; l < W; ++l) r[l] = table[idx[l]];
  return r;
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
template <>
__attribute__((target("avx2"))) inline V<8>::F TableLanes<8, float>(const float* table, V<8>::I idx) {
  return V<8>::F(_mm256_i32gather_ps(table, __m256i(idx), 4));
}
template <>
__attribute__((target("avx2"))) inline V<8>::I TableLanes<8, std::int32_t>(const std::int32_t* table, V<8>::I idx) {
  return V<8>::I(_mm256_i32gather_epi32(reinterpret_cast<const int*>(table), __m256i(idx), 4));
}
#endif

/// The lanes' sign bits (bit l: lane l is negative), from l0 on.
template <int W>
SOFTGL_WIDE std::uint32_t SignBits(typename V<W>::I v, int l0 = 0) {
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
  return MaskToBits<W>(v, l0);  // (the x86 forms read the sign bits alone)
#else
  return MaskToBits<W>(v >> 31, l0);
#endif
}

/// The components of W texels as four vectors: c[0] the x of each, c[1] the y, c[2] the z, c[3] the w; texel k
/// at at(k), where texels 2 j and 2 j + 1 lie side by side (a quad row). With 4 and 8 lanes, 4x4 transposes by
/// shuffles (within each 128-bit half for 8); with 16, lane by lane.
template <int W, class At>
SOFTGL_WIDE void LoadComponentsAt(At&& at, typename V<W>::F (&c)[4]) {
  using F = typename V<W>::F;
  if constexpr (W == 4) {
    const F r0 = LoadVec<F>(at(0)), r1 = LoadVec<F>(at(1)), r2 = LoadVec<F>(at(2)), r3 = LoadVec<F>(at(3));
    const F t0 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5), t1 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    const F t2 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7), t3 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    c[0] = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
    c[1] = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
    c[2] = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
    c[3] = __builtin_shufflevector(t2, t3, 2, 3, 6, 7);
  } else if constexpr (W == 8) {
    // Pairs of texels: a = (p0, p1), b = (p2, p3), d = (p4, p5), e = (p6, p7); then (p0, p4), (p1, p5), ...
    const F a = LoadVec<F>(at(0)), b = LoadVec<F>(at(2)), d = LoadVec<F>(at(4)), e = LoadVec<F>(at(6));
    const F r04 = __builtin_shufflevector(a, d, 0, 1, 2, 3, 8, 9, 10, 11);
    const F r15 = __builtin_shufflevector(a, d, 4, 5, 6, 7, 12, 13, 14, 15);
    const F r26 = __builtin_shufflevector(b, e, 0, 1, 2, 3, 8, 9, 10, 11);
    const F r37 = __builtin_shufflevector(b, e, 4, 5, 6, 7, 12, 13, 14, 15);
    const F t0 = __builtin_shufflevector(r04, r15, 0, 8, 1, 9, 4, 12, 5, 13);
    const F t1 = __builtin_shufflevector(r26, r37, 0, 8, 1, 9, 4, 12, 5, 13);
    const F t2 = __builtin_shufflevector(r04, r15, 2, 10, 3, 11, 6, 14, 7, 15);
    const F t3 = __builtin_shufflevector(r26, r37, 2, 10, 3, 11, 6, 14, 7, 15);
    c[0] = __builtin_shufflevector(t0, t1, 0, 1, 8, 9, 4, 5, 12, 13);
    c[1] = __builtin_shufflevector(t0, t1, 2, 3, 10, 11, 6, 7, 14, 15);
    c[2] = __builtin_shufflevector(t2, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    c[3] = __builtin_shufflevector(t2, t3, 2, 3, 10, 11, 6, 7, 14, 15);
  } else {
    for (int k = 0; k < 4; ++k) {
      F v{};
      for (int l = 0; l < W; ++l) v[l] = at(l)[k];
      c[k] = v;
    }
  }
}
/// The components of p[0 .. W - 1] (LoadComponentsAt).
template <int W>
SOFTGL_WIDE void LoadComponents(const glm::vec4* p, typename V<W>::F (&c)[4]) {
  LoadComponentsAt<W>([p](int k) SOFTGL_WIDE_LAMBDA { return &p[k][0]; }, c);
}
/// The inverse of LoadComponentsAt: texel k of the four component vectors c stored at at(k) (texels 2 j and 2 j + 1
/// side by side), for the texels k whose group of four (bit k / 4 of `quads`) is chosen.
template <int W, class At>
SOFTGL_WIDE void StoreComponentsAt(At&& at, const typename V<W>::F (&c)[4], unsigned quads = ~0u) {
  using F = typename V<W>::F;
  if constexpr (W == 4) {
    const F t0 = __builtin_shufflevector(c[0], c[1], 0, 4, 1, 5), t1 = __builtin_shufflevector(c[2], c[3], 0, 4, 1, 5);
    const F t2 = __builtin_shufflevector(c[0], c[1], 2, 6, 3, 7), t3 = __builtin_shufflevector(c[2], c[3], 2, 6, 3, 7);
    if (!(quads & 1u)) return;
    StoreVec(at(0), F(__builtin_shufflevector(t0, t1, 0, 1, 4, 5)));
    StoreVec(at(1), F(__builtin_shufflevector(t0, t1, 2, 3, 6, 7)));
    StoreVec(at(2), F(__builtin_shufflevector(t2, t3, 0, 1, 4, 5)));
    StoreVec(at(3), F(__builtin_shufflevector(t2, t3, 2, 3, 6, 7)));
  } else if constexpr (W == 8) {
    // Within each 128-bit half (lanes 0-3, then 4-7): x y interleaved, z w interleaved, then texel pairs.
    const F xy_lo = __builtin_shufflevector(c[0], c[1], 0, 8, 1, 9, 4, 12, 5, 13);
    const F zw_lo = __builtin_shufflevector(c[2], c[3], 0, 8, 1, 9, 4, 12, 5, 13);
    const F xy_hi = __builtin_shufflevector(c[0], c[1], 2, 10, 3, 11, 6, 14, 7, 15);
    const F zw_hi = __builtin_shufflevector(c[2], c[3], 2, 10, 3, 11, 6, 14, 7, 15);
    const F p04 = __builtin_shufflevector(xy_lo, zw_lo, 0, 1, 8, 9, 4, 5, 12, 13);   // texels 0, 4
    const F p15 = __builtin_shufflevector(xy_lo, zw_lo, 2, 3, 10, 11, 6, 7, 14, 15);  // texels 1, 5
    const F p26 = __builtin_shufflevector(xy_hi, zw_hi, 0, 1, 8, 9, 4, 5, 12, 13);    // texels 2, 6
    const F p37 = __builtin_shufflevector(xy_hi, zw_hi, 2, 3, 10, 11, 6, 7, 14, 15);  // texels 3, 7
    if (quads & 1u) {
      StoreVec(at(0), F(__builtin_shufflevector(p04, p15, 0, 1, 2, 3, 8, 9, 10, 11)));
      StoreVec(at(2), F(__builtin_shufflevector(p26, p37, 0, 1, 2, 3, 8, 9, 10, 11)));
    }
    if (quads & 2u) {
      StoreVec(at(4), F(__builtin_shufflevector(p04, p15, 4, 5, 6, 7, 12, 13, 14, 15)));
      StoreVec(at(6), F(__builtin_shufflevector(p26, p37, 4, 5, 6, 7, 12, 13, 14, 15)));
    }
  } else {
    for (int l = 0; l < W; ++l)
      if ((quads >> (l / 4)) & 1u)
        for (int k = 0; k < 4; ++k) at(l)[k] = c[k][l];
  }
}

/// As std::floor, for |x| < 2^31 (callers keep x in range).
template <int W>
SOFTGL_WIDE typename V<W>::F FloorVec(typename V<W>::F x) {
  const typename V<W>::F t = __builtin_convertvector(__builtin_convertvector(x, typename V<W>::I), typename V<W>::F);
  return t > x ? t - 1.0f : t;
}

/// HalfToFloat for W lanes (h in the low 16 bits): the exponent and mantissa moved to a float's places and scaled
/// by 2^112, exact for normal and subnormal halves alike; infinities and NaNs get the float's top exponent, NaNs
/// the quiet bit too.
template <int W>
SOFTGL_WIDE typename V<W>::F HalfLanes(typename V<W>::U h) {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  const U em = h & 0x7FFFu;
  const U shifted = em << 13;
  F f;
  std::memcpy(&f, &shifted, sizeof f);
  f *= 0x1p112f;
  U bits;
  std::memcpy(&bits, &f, sizeof bits);
  bits = em >= 0x7C00u ? shifted | 0x7F800000u : bits;
  bits = em > 0x7C00u ? bits | 0x00400000u : bits;
  bits |= (h & 0x8000u) << 16;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// With AVX-512, one conversion instruction (VCVTPH2PS, exact, a NaN made quiet); 8 lanes by F16C's (the AVX2 and
// AVX-512 levels have it), the halves packed to 16 bits first.
template <>
__attribute__((target("avx512f"))) inline V<16>::F HalfLanes<16>(V<16>::U h) {
  return V<16>::F(_mm512_cvtph_ps(_mm512_cvtepi32_epi16(__m512i(h))));
}
template <>
__attribute__((target("avx2,f16c"))) inline V<8>::F HalfLanes<8>(V<8>::U h) {
  const __m256i packed = _mm256_packus_epi32(__m256i(h & 0xFFFFu), _mm256_setzero_si256());  // 0-3, -, 4-7, -
  return V<8>::F(_mm256_cvtph_ps(_mm256_castsi256_si128(_mm256_permute4x64_epi64(packed, 0x08))));
}
#endif

/// |f| (its bits `a`, not NaN) as a float of 5 exponent bits (bias 15) and M mantissa bits, without a sign:
/// normal values by rounding away 23 - M mantissa bits (to nearest, ties to even; past the largest finite,
/// infinity), subnormal ones by adding 2^23 to |f| in units of 2^(-14 - M). For W lanes.
template <int W, int M>
SOFTGL_WIDE typename V<W>::U MagnitudeBitsLanes(typename V<W>::U a) {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  constexpr int kShift = 23 - M;
  U r = a - 0x38000000u;  // the exponent rebased from 127 to 15
  r = (r + ((1u << (kShift - 1)) - 1u) + ((r >> kShift) & 1u)) >> kShift;
  r = r < (31u << M) ? r : U{} + (31u << M);
  F units;
  std::memcpy(&units, &a, sizeof units);
  units = units * float(1u << (14 + M)) + 8388608.0f;
  U u;
  std::memcpy(&u, &units, sizeof u);
  return a >= 0x38800000u ? r : u & ((2u << M) - 1u);  // (at most 2^M: the smallest normal when it rounds up)
}

/// FloatToHalf for W lanes (the half in the low 16 bits of each); every NaN as 0x7E00 with its sign.
template <int W>
SOFTGL_WIDE typename V<W>::U HalfBitsLanes(typename V<W>::F f) {
  using U = typename V<W>::U;
  U x;
  std::memcpy(&x, &f, sizeof x);
  const U a = x & 0x7FFFFFFFu;
  const U h = a > 0x7F800000u ? U{} + 0x7E00u : MagnitudeBitsLanes<W, 10>(a);
  return ((x >> 16) & 0x8000u) | h;
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// 8 lanes by F16C's VCVTPS2PH (round to nearest even, overflow to infinity, as FloatToHalf); a NaN keeps the top
// of its payload there, so NaNs are set to 0x7E00 after.
template <>
__attribute__((target("avx2,f16c"))) inline V<8>::U HalfBitsLanes<8>(V<8>::F f) {
  using U = V<8>::U;
  const U h = U(_mm256_cvtepu16_epi32(_mm256_cvtps_ph(__m256(f), _MM_FROUND_TO_NEAREST_INT)));
  U x;
  std::memcpy(&x, &f, sizeof x);
  return (x & 0x7FFFFFFFu) > 0x7F800000u ? ((x >> 16) & 0x8000u) | 0x7E00u : h;
}
#endif

/// FloatToUnsignedSmall for W lanes, M mantissa bits: NaN as (31 << M) | 1, negative values and zeros as 0.
template <int W, int M>
SOFTGL_WIDE typename V<W>::U SmallFloatBitsLanes(typename V<W>::F f) {
  using U = typename V<W>::U;
  U a;
  std::memcpy(&a, &f, sizeof a);
  const U v = f > 0.0f ? MagnitudeBitsLanes<W, M>(a) : U{};
  return f == f ? v : U{} + ((31u << M) | 1u);
}

}  // namespace softgl::detail

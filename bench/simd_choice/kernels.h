// kernels.h — one fragment shader's arithmetic (Blinn-Phong: three normalizations, dot products, a clamp, a
// specular power by squaring, a per-lane choice) written with each candidate for softgl's lane types, to measure
// what each costs on 16 lanes. Every version reads the same structure-of-arrays input and writes three channels.
#pragma once

#include <cstddef>

namespace simd_choice {

/// n fragments (a multiple of 16), each array n floats: normal, position; out r, g, b.
struct Fragments {
  const float *nx, *ny, *nz, *px, *py, *pz;
  float *r, *g, *b;
  std::size_t n;
};

// softgl's lanes, dispatched at run time (kernels_softgl.cpp): isa 0 SSE2, 1 AVX2, 2 AVX-512.
void ShadeSoftgl(const Fragments& f, int isa);
// std::experimental::fixed_size_simd<float, 16>, xsimd and Highway, each compiled into a translation unit of its
// own with the instruction set's compiler flags (the only way these libraries choose wider instructions).
void ShadeStdSimdBaseline(const Fragments& f);       // stdx, in a baseline unit, from a function marked avx2
void ShadeStdSimdAvx2(const Fragments& f);           // stdx, unit compiled with -mavx2 -mfma
void ShadeStdSimdAvx512(const Fragments& f);         // stdx, unit compiled with -mavx512f ...
void ShadeXsimdAvx2(const Fragments& f);             // xsimd::batch<float, avx2>, two per 16 lanes
void ShadeXsimdAvx512(const Fragments& f);           // xsimd::batch<float, avx512f>
void ShadeHighwayAvx2(const Fragments& f);           // Highway, static target AVX2
void ShadeHighwayAvx512(const Fragments& f);         // Highway, static target AVX-512
void ShadeScalar(const Fragments& f);                // plain floats, one lane at a time (the compiler's own)

}  // namespace simd_choice

// kernels_library.cpp — the kernel with a SIMD library's types, compiled once per library and instruction set
// (CMakeLists.txt sets SIMD_LIB to STDX, XSIMD or HWY, SIMD_ISA to AVX2 or AVX512, and the matching -m flags;
// STDX_BASELINE compiles the std::experimental::simd form without them, from a function marked avx2).
#include <algorithm>

#include "kernels.h"

#if defined(SIMD_LIB_STDX)
#include <experimental/simd>
namespace stdx = std::experimental;
#elif defined(SIMD_LIB_XSIMD)
#include <xsimd/xsimd.hpp>
#elif defined(SIMD_LIB_HWY)
#include <hwy/highway.h>
#endif

namespace simd_choice {

#if defined(SIMD_LIB_STDX)
namespace {
using F = stdx::fixed_size_simd<float, 16>;
struct V3 {
  F x, y, z;
};
inline F Dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 Normalize(const V3& a) {
  const F k = F(1.0f) / stdx::sqrt(Dot(a, a));
  return {a.x * k, a.y * k, a.z * k};
}
#if defined(STDX_BASELINE)
__attribute__((target("avx2"), flatten))
#endif
void Body(const Fragments& f) {
  const V3 light{F(0.267f), F(0.802f), F(0.534f)};
  for (std::size_t i = 0; i < f.n; i += 16) {
    const V3 n = Normalize({F(f.nx + i, stdx::element_aligned), F(f.ny + i, stdx::element_aligned),
                            F(f.nz + i, stdx::element_aligned)});
    const V3 v = Normalize({F(0.0f) - F(f.px + i, stdx::element_aligned), F(1.0f) - F(f.py + i, stdx::element_aligned),
                            F(3.0f) - F(f.pz + i, stdx::element_aligned)});
    const V3 h = Normalize({light.x + v.x, light.y + v.y, light.z + v.z});
    const F d = stdx::max(Dot(n, light), F(0.0f));
    F s = stdx::max(Dot(n, h), F(0.0f));
    for (int k = 0; k < 5; ++k) s = s * s;
    const F lit = d * 0.8f + 0.1f + s;
    F r(0.1f), g(0.1f), b(0.2f);
    const auto on = d > 0.0f;
    stdx::where(on, r) = lit;
    stdx::where(on, g) = lit;
    stdx::where(on, b) = lit;
    r.copy_to(f.r + i, stdx::element_aligned);
    g.copy_to(f.g + i, stdx::element_aligned);
    b.copy_to(f.b + i, stdx::element_aligned);
  }
}
}  // namespace
#if defined(STDX_BASELINE)
void ShadeStdSimdBaseline(const Fragments& f) { Body(f); }
#elif defined(SIMD_ISA_AVX512)
void ShadeStdSimdAvx512(const Fragments& f) { Body(f); }
#else
void ShadeStdSimdAvx2(const Fragments& f) { Body(f); }
#endif

#elif defined(SIMD_LIB_XSIMD)
namespace {
#if defined(SIMD_ISA_AVX512)
using Arch = xsimd::avx512f;
#else
using Arch = xsimd::avx2;
#endif
using B = xsimd::batch<float, Arch>;
struct V3 {
  B x, y, z;
};
inline B Dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 Normalize(const V3& a) {
  const B k = B(1.0f) / xsimd::sqrt(Dot(a, a));
  return {a.x * k, a.y * k, a.z * k};
}
void Body(const Fragments& f) {
  const V3 light{B(0.267f), B(0.802f), B(0.534f)};
  for (std::size_t i = 0; i < f.n; i += B::size) {
    const V3 n = Normalize({B::load_unaligned(f.nx + i), B::load_unaligned(f.ny + i), B::load_unaligned(f.nz + i)});
    const V3 v = Normalize({B(0.0f) - B::load_unaligned(f.px + i), B(1.0f) - B::load_unaligned(f.py + i),
                            B(3.0f) - B::load_unaligned(f.pz + i)});
    const V3 h = Normalize({light.x + v.x, light.y + v.y, light.z + v.z});
    const B d = xsimd::max(Dot(n, light), B(0.0f));
    B s = xsimd::max(Dot(n, h), B(0.0f));
    for (int k = 0; k < 5; ++k) s = s * s;
    const B lit = d * B(0.8f) + B(0.1f) + s;
    const auto on = d > B(0.0f);
    xsimd::select(on, lit, B(0.1f)).store_unaligned(f.r + i);
    xsimd::select(on, lit, B(0.1f)).store_unaligned(f.g + i);
    xsimd::select(on, lit, B(0.2f)).store_unaligned(f.b + i);
  }
}
}  // namespace
#if defined(SIMD_ISA_AVX512)
void ShadeXsimdAvx512(const Fragments& f) { Body(f); }
#else
void ShadeXsimdAvx2(const Fragments& f) { Body(f); }
#endif

#elif defined(SIMD_LIB_HWY)
namespace {
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<float>;
using VF = hn::Vec<D>;
struct V3 {
  VF x, y, z;
};
inline VF Dot(const V3& a, const V3& b) { return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z)); }
inline V3 Normalize(D d, const V3& a) {
  const VF k = hn::Div(hn::Set(d, 1.0f), hn::Sqrt(Dot(a, a)));
  return {hn::Mul(a.x, k), hn::Mul(a.y, k), hn::Mul(a.z, k)};
}
void Body(const Fragments& f) {
  const D d;
  const V3 light{hn::Set(d, 0.267f), hn::Set(d, 0.802f), hn::Set(d, 0.534f)};
  for (std::size_t i = 0; i < f.n; i += hn::Lanes(d)) {
    const V3 n = Normalize(d, {hn::LoadU(d, f.nx + i), hn::LoadU(d, f.ny + i), hn::LoadU(d, f.nz + i)});
    const V3 v = Normalize(d, {hn::Sub(hn::Set(d, 0.0f), hn::LoadU(d, f.px + i)),
                               hn::Sub(hn::Set(d, 1.0f), hn::LoadU(d, f.py + i)),
                               hn::Sub(hn::Set(d, 3.0f), hn::LoadU(d, f.pz + i))});
    const V3 h = Normalize(d, {hn::Add(light.x, v.x), hn::Add(light.y, v.y), hn::Add(light.z, v.z)});
    const VF dd = hn::Max(Dot(n, light), hn::Zero(d));
    VF s = hn::Max(Dot(n, h), hn::Zero(d));
    for (int k = 0; k < 5; ++k) s = hn::Mul(s, s);
    const VF lit = hn::Add(hn::Add(hn::Mul(dd, hn::Set(d, 0.8f)), hn::Set(d, 0.1f)), s);
    const auto on = hn::Gt(dd, hn::Zero(d));
    hn::StoreU(hn::IfThenElse(on, lit, hn::Set(d, 0.1f)), d, f.r + i);
    hn::StoreU(hn::IfThenElse(on, lit, hn::Set(d, 0.1f)), d, f.g + i);
    hn::StoreU(hn::IfThenElse(on, lit, hn::Set(d, 0.2f)), d, f.b + i);
  }
}
}  // namespace
#if defined(SIMD_ISA_AVX512)
void ShadeHighwayAvx512(const Fragments& f) { Body(f); }
#else
void ShadeHighwayAvx2(const Fragments& f) { Body(f); }
#endif
#endif

}  // namespace simd_choice

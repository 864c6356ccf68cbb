// texture_sampler.cpp — texture sampling for the shader stages: level of detail, mipmap selection, NEAREST and
// LINEAR filtering, wrap modes, cube map faces and depth comparison (OpenGL 4.6, sections 8.13 to 8.14, 8.22).
//
// Texels are filtered in their storage units (the bytes 0..255 of fixed-point formats, the floats of the others)
// and the result is divided by the format's scale (255 or 1) once, at the end. The wide form (SampleLanes) computes
// 2D sampling (every filter, wrap mode, size and layout; not anisotropic filtering) for a whole block of lanes with
// vector instructions and the same operations, in the same order, as the one-lane form, so both give the same
// floats.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <bit>
#include <cstring>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <softgl/lanes.h>
#include <softgl/texture.h>

#include "fragment_ops.h"
#include "simd.h"
#include "texture.h"
#include "wide.h"

// GCC 12's AVX-512 gather starts from a self-initialized "undefined" vector, which its uninitialized-value warnings
// report: a known false positive.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace softgl {

namespace {

#if defined(__GNUC__)
#define SOFTGL_INLINE inline __attribute__((always_inline))
#else
#define SOFTGL_INLINE inline
#endif

using detail::SamplerParams;
using detail::TexelLayout;
using detail::TextureLevel;
using detail::TextureView;

const glm::vec4 kMissing(0.0f, 0.0f, 0.0f, 1.0f);  // what an incomplete or missing texture samples as
// What an incomplete integer texture samples as: the integers (0, 0, 0, 1), as floats' bits.
const glm::vec4 kMissingInteger(0.0f, 0.0f, 0.0f, std::bit_cast<float>(1));

// A sample in the view's units: the storage units divided by the scale; an integer texture's bits as they are.
SOFTGL_INLINE glm::vec4 Unscaled(const TextureView& v, const glm::vec4& t) { return v.integer ? t : t / v.scale; }

// Table 8.20: the texel index i wrapped into [0, size); -1 for a border texel.
SOFTGL_INLINE int Wrap(Enum mode, long i, int size) {
  switch (mode) {
    case CLAMP_TO_EDGE: return int(std::clamp<long>(i, 0, size - 1));
    case CLAMP_TO_BORDER: return (i < 0 || i >= size) ? -1 : int(i);
    case MIRRORED_REPEAT: {
      const long m = ((i % (2L * size)) + 2L * size) % (2L * size);
      const long a = m - size;
      const long mirror = a >= 0 ? a : -(1 + a);
      return int((size - 1) - mirror);
    }
    default:  // REPEAT; a power-of-two size needs no division
      if ((size & (size - 1)) == 0) return int(i & long(size - 1));
      return int(((i % size) + size) % size);
  }
}

// Texel-space coordinate, kept finite and within a range where integer conversion is defined.
SOFTGL_INLINE float TexelCoord(float s, int size) {
  const float u = s * float(size);
  return std::isnan(u) ? 0.0f : std::clamp(u, -1e9f, 1e9f);
}

struct DepthCompare {
  bool on = false;
  Enum func = LEQUAL;
  float ref = 0.0f;
};

// One texel in storage units (an sRGB texture's colour decoded to linear), wrapped (the border colour outside the level under CLAMP_TO_BORDER), compared when
// depth comparison is on.
// `layer` is the plane of a layered level (a 2D array's layer, a 3D texture's slice), already wrapped.
glm::vec4 Fetch(const TextureView& view, const TextureLevel& level, long i, long j, const DepthCompare& cmp,
                int layer = 0) {
  const SamplerParams& p = view.params;
  const int wi = Wrap(p.wrap_s, i, level.width), wj = Wrap(p.wrap_t, j, level.height);
  const glm::vec4 t = (wi >= 0 && wj >= 0) ? level.Sampled(wi, layer * level.height + wj) : view.border_raw;
  if (cmp.on) return glm::vec4(detail::Compare(cmp.func, cmp.ref, t.r) ? 1.0f : 0.0f);
  return t;
}

// Bilinear weights of texel-space coordinates (u, v), and the lower-left texel.
struct Bilerp {
  long i0, j0;
  float w00, w10, w01, w11;
};
SOFTGL_INLINE Bilerp Weights(float u, float v) {
  const float fu = u - 0.5f, fv = v - 0.5f;
  const float flu = std::floor(fu), flv = std::floor(fv);
  const float a = fu - flu, b = fv - flv;
  return Bilerp{long(flu), long(flv), (1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
}
// The weighted sum, always in this order: ((w00 t00 + w10 t10) + w01 t01) + w11 t11.
SOFTGL_INLINE glm::vec4 Sum(const Bilerp& w, const glm::vec4& t00, const glm::vec4& t10, const glm::vec4& t01,
                            const glm::vec4& t11) {
  return w.w00 * t00 + w.w10 * t10 + w.w01 * t01 + w.w11 * t11;
}

// One level, NEAREST or LINEAR (section 8.14.2): texel centres at +0.5.
SOFTGL_INLINE glm::vec4 FilterLevel(const TextureView& view, const TextureLevel& level, Enum filter, glm::vec2 st,
                                    const DepthCompare& cmp, int layer = 0) {
  const float u = TexelCoord(st.x, level.width), v = TexelCoord(st.y, level.height);
  if (filter == NEAREST) return Fetch(view, level, long(std::floor(u)), long(std::floor(v)), cmp, layer);
  const Bilerp w = Weights(u, v);
  return Sum(w, Fetch(view, level, w.i0, w.j0, cmp, layer), Fetch(view, level, w.i0 + 1, w.j0, cmp, layer),
             Fetch(view, level, w.i0, w.j0 + 1, cmp, layer), Fetch(view, level, w.i0 + 1, w.j0 + 1, cmp, layer));
}

// One level of a 3D texture, NEAREST or LINEAR (section 8.14.2): the slices wrapped by TEXTURE_WRAP_R, LINEAR the
// two slices' bilinear samples weighted by the fraction of w.
SOFTGL_INLINE glm::vec4 FilterVolume(const TextureView& view, const TextureLevel& level, Enum filter, glm::vec3 str) {
  const Enum wrap_r = view.params.wrap_r;
  const float w = TexelCoord(str.z, level.depth);
  auto slice = [&](long k) {
    const int wk = Wrap(wrap_r, k, level.depth);
    return wk >= 0 ? FilterLevel(view, level, filter, glm::vec2(str), DepthCompare{}, wk) : view.border_raw;
  };
  if (filter == NEAREST) return slice(long(std::floor(w)));
  const float fw = w - 0.5f, flw = std::floor(fw), c = fw - flw;
  return (1.0f - c) * slice(long(flw)) + c * slice(long(flw) + 1);
}

// LINEAR for REPEAT on a power-of-two level: the same arithmetic, the wrap a mask, no border texel.
SOFTGL_INLINE glm::vec4 BilinearRepeatPow2(const TextureLevel& level, glm::vec2 st) {
  const Bilerp w = Weights(TexelCoord(st.x, level.width), TexelCoord(st.y, level.height));
  const long mi = level.width - 1, mj = level.height - 1;
  const int c0 = int(w.i0 & mi), c1 = int((w.i0 + 1) & mi), r0 = int(w.j0 & mj), r1 = int((w.j0 + 1) & mj);
  return Sum(w, level.Sampled(c0, r0), level.Sampled(c1, r0), level.Sampled(c0, r1), level.Sampled(c1, r1));
}

// The fast path's level choice (what SampleFace decides for these filters), in storage units.
SOFTGL_INLINE glm::vec4 SampleRepeat(const TextureView& view, glm::vec2 st, float lambda) {
  const auto& levels = view.texture->levels[0];
  if (lambda <= 0.0f || view.fast == TextureView::Fast::kRepeatLinear)  // magnification, or LINEAR
    return BilinearRepeatPow2(levels[view.base], st);
  if (float(view.base) + lambda >= float(view.q)) return BilinearRepeatPow2(levels[view.q], st);
  const float fl = std::floor(lambda);
  const int d1 = view.base + int(fl);
  const float f = lambda - fl;
  return (1.0f - f) * BilinearRepeatPow2(levels[d1], st) + f * BilinearRepeatPow2(levels[d1 + 1], st);
}

// log2 evaluated piecewise-linearly between powers of two: exponent + (mantissa - 1). Exact at powers of two,
// at most 0.086 below log2 in between.
SOFTGL_INLINE float PiecewiseLog2(float x) {
  if (!(x > 0.0f)) return -INFINITY;
  std::uint32_t bits;
  std::memcpy(&bits, &x, 4);
  const int biased = int(bits >> 23);
  if (biased > 0 && biased < 255) {  // a normal number: exponent and mantissa straight from its bits
    std::uint32_t one_m = (bits & 0x007FFFFFu) | 0x3F800000u;  // 1.mantissa, the same m as frexp gives
    float m;
    std::memcpy(&m, &one_m, 4);
    return float(biased - 127) + (m - 1.0f);
  }
  int e = 0;
  const float m = std::frexp(x, &e) * 2.0f;  // x = m * 2^(e - 1), m in [1, 2)
  return float(e - 1) + (m - 1.0f);
}

// Level of detail (section 8.14.1): lambda = log2(rho) + biases, clamped to [min_lod, max_lod], with rho the
// larger length of the texel-space derivatives along x and y. log2(rho) is taken as 1/2 log2(rho^2) with the
// piecewise-linear log2 above (at most 0.043 levels from the exact value): the approximation Mesa's llvmpipe
// makes, which keeps trilinear filtering within +-1 of it where the exact logarithm differs by up to 4
// (docs/conformance.md).
SOFTGL_INLINE float LambdaOfRho2(const TextureView& view, float rho2, float shader_bias) {
  const SamplerParams& p = view.params;
  const float bias = std::clamp(p.lod_bias + shader_bias, -16.0f, 16.0f);
  float lambda = 0.5f * PiecewiseLog2(rho2) + bias;
  if (std::isnan(lambda)) lambda = 0.0f;
  return std::clamp(lambda, p.min_lod, p.max_lod);
}
SOFTGL_INLINE float Lambda(const TextureView& view, glm::vec2 dx, glm::vec2 dy, float shader_bias) {
  const TextureLevel& base = view.texture->levels[0][view.base];
  const glm::vec2 size(float(base.width), float(base.height));
  const glm::vec2 tx = dx * size, ty = dy * size;
  return LambdaOfRho2(view, std::max(glm::dot(tx, tx), glm::dot(ty, ty)), shader_bias);
}
// A 3D texture's: the derivatives of (u, v, w) in texels.
SOFTGL_INLINE float LambdaVolume(const TextureView& view, glm::vec3 dx, glm::vec3 dy, float shader_bias) {
  const TextureLevel& base = view.texture->levels[0][view.base];
  const glm::vec3 size(float(base.width), float(base.height), float(base.depth));
  const glm::vec3 tx = dx * size, ty = dy * size;
  return LambdaOfRho2(view, std::max(glm::dot(tx, tx), glm::dot(ty, ty)), shader_bias);
}
// textureLod's lambda: lod plus TEXTURE_LOD_BIAS, clamped to [min_lod, max_lod]; NaN as 0.
SOFTGL_INLINE float ExplicitLambda(const TextureView& view, float lod) {
  const SamplerParams& p = view.params;
  const float lambda = std::clamp(lod + std::clamp(p.lod_bias, -16.0f, 16.0f), p.min_lod, p.max_lod);
  return std::isnan(lambda) ? 0.0f : lambda;
}

// Minification or magnification at level of detail lambda (section 8.14.2 to 8.14.3), in storage units:
// filter(d, f) filters level d with NEAREST or LINEAR f.
template <class Filter>
SOFTGL_INLINE glm::vec4 SampleMip(const TextureView& view, float lambda, Filter&& filter) {
  const SamplerParams& p = view.params;
  const bool nearest_mip = p.min_filter == NEAREST_MIPMAP_NEAREST || p.min_filter == LINEAR_MIPMAP_NEAREST;
  const float c = (p.mag_filter == LINEAR && nearest_mip) ? 0.5f : 0.0f;
  if (lambda <= c) return filter(view.base, p.mag_filter);
  const Enum f = (p.min_filter == LINEAR || p.min_filter == LINEAR_MIPMAP_NEAREST ||
                  p.min_filter == LINEAR_MIPMAP_LINEAR)
                     ? LINEAR
                     : NEAREST;
  switch (p.min_filter) {
    case NEAREST:
    case LINEAR: return filter(view.base, f);
    case NEAREST_MIPMAP_NEAREST:
    case LINEAR_MIPMAP_NEAREST: {
      const int d = lambda <= 0.5f ? view.base
                                   : int(std::min<float>(float(view.base) + std::ceil(lambda + 0.5f) - 1.0f,
                                                         float(view.q)));
      return filter(d, f);
    }
    default: {  // *_MIPMAP_LINEAR
      if (float(view.base) + lambda >= float(view.q)) return filter(view.q, f);
      const float fl = std::floor(lambda);
      const int d1 = view.base + int(fl);
      const float t = lambda - fl;
      return (1.0f - t) * filter(d1, f) + t * filter(d1 + 1, f);
    }
  }
}

// SampleMip on one face of a 2D texture or cube map, or one layer of a 2D array.
SOFTGL_INLINE glm::vec4 SampleFace(const TextureView& view, int face, glm::vec2 st, float lambda,
                                   const DepthCompare& cmp, int layer = 0) {
  const auto& levels = view.texture->levels[face];
  return SampleMip(view, lambda,
                   [&](int d, Enum f) SOFTGL_WIDE_LAMBDA { return FilterLevel(view, levels[d], f, st, cmp, layer); });
}

// The layer of a 2D array that r selects: floor(r + 0.5) clamped to the layers (section 8.14.2); NaN takes 0.
int ArrayLayer(const TextureView& view, float r) {
  const int layers = view.texture->levels[0][view.base].depth;
  const float l = std::floor(r + 0.5f);
  return std::isnan(l) ? 0 : int(std::clamp(l, 0.0f, float(layers - 1)));
}

// What unit's texture samples as while unusable: an integer texture's integers (0, 0, 0, 1), else kMissing.
const glm::vec4& MissingFor(const TextureView* const* units, int unit) {
  const bool integer = unit >= 0 && unit < kMaxTextureUnits && units[unit] && units[unit]->integer;
  return integer ? kMissingInteger : kMissing;
}

const TextureView* Usable(const TextureView* const* units, int unit) {
  if (unit < 0 || unit >= kMaxTextureUnits) return nullptr;
  const TextureView* v = units[unit];
  return (v && v->complete) ? v : nullptr;
}

// Table 8.19: (sc, tc, ma) of direction r on cube face f, and its (s, t) in [0, 1] when ma > 0.
bool FaceCoords(int face, glm::vec3 r, glm::vec2& st) {
  float sc, tc, ma;
  switch (face) {
    case 0: sc = -r.z; tc = -r.y; ma = r.x; break;
    case 1: sc = r.z; tc = -r.y; ma = -r.x; break;
    case 2: sc = r.x; tc = r.z; ma = r.y; break;
    case 3: sc = r.x; tc = -r.z; ma = -r.y; break;
    case 4: sc = r.x; tc = -r.y; ma = r.z; break;
    default: sc = -r.x; tc = -r.y; ma = -r.z; break;
  }
  if (!(ma > 0.0f)) return false;
  st = glm::vec2((sc / ma + 1.0f) * 0.5f, (tc / ma + 1.0f) * 0.5f);
  return true;
}

// The face the major axis of r selects.
int CubeFace(glm::vec3 r) {
  const glm::vec3 a = glm::abs(r);
  if (a.x >= a.y && a.x >= a.z) return r.x >= 0 ? 0 : 1;
  if (a.y >= a.z) return r.y >= 0 ? 2 : 3;
  return r.z >= 0 ? 4 : 5;
}

// A 2D texture's sample (Textures::Sample) in its format's units; not inlined (the vector paths call it for the odd
// lane, and their flatten attribute would otherwise copy every filter into each of them).
__attribute__((noinline)) glm::vec4 Sample2D(const TextureView& v, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy,
                                             float bias);

// The lookups the vector path takes: texture() and textureLod() on a 2D texture, a 2D array, a cube map and a 3D
// texture, and texture() on a 2D shadow sampler and a 2D array shadow sampler.
enum class Lookup : unsigned char { k2D, kLod, kArray, kArrayLod, kCube, kCubeLod, kShadow, kArrayShadow, k3D, k3DLod };

// Lane `lane` of a block's lookup through the one-lane path (for the lanes the vector path leaves: rho^2 not a
// normal float), in the format's units divided by its scale, as the Textures calls give it. Not inlined, as
// Sample2D.
__attribute__((noinline)) glm::vec4 SampleOneLane(const TextureView& v, Lookup kind, const Textures::Lanes& c,
                                                  int lane, float bias, const float* lod);

// ---- 2D sampling for a block of lanes -----------------------------------------------------------------------
//
// W lanes at a time (4 with SSE2, 8 with AVX2, 16 with AVX-512), each lane's operations those of SampleFace above in
// the same order, for every filter pair, wrap mode and size. The levels a chunk of lanes needs are taken one at a
// time (usually one or two), and each is filtered for all its lanes: texel addresses, wraps, texel loads, weights
// side by side. Texels are loaded with one 64-bit load a lane (a row's two texels at once where they fit) and decoded
// in vector form, in every layout. Lanes whose rho^2 is not a normal positive float (zero or NaN derivatives, say)
// take the one-lane path.
//
// GCC 12 compiles a select whose mask is not plainly one comparison (an OR of two, a mask passed through a select)
// into a branch per lane, about 80 cycles a block at 16 lanes; the masks below are kept single comparisons, or
// turned into bits (MaskToBits, SignBits) before they are combined.

using detail::V;
using detail::HalfLanes;

template <int W>
SOFTGL_INLINE typename V<W>::F LoadF(const float* p) {
  return detail::LoadVec<typename V<W>::F>(p);
}
template <int W>
SOFTGL_INLINE typename V<W>::F FloorF(typename V<W>::F x) {
  return detail::FloorVec<W>(x);
}

// Each lane's 64 bits at byte offset off[lane] of `base` (unaligned), one scalar load a lane: a texel and its
// right-hand neighbour together. On the x86 processor measured, a gather instruction costs about as much as the
// loads it stands for or more (docs/architecture.md), and one 64-bit load brings both texels of a row.
template <int W, std::size_t... L>
SOFTGL_WIDE typename V<W>::D LoadPairs(const std::uint8_t* base, const typename V<W>::I& off,
                                       std::index_sequence<L...>) {
  // The offsets go through memory: a load each costs less than taking each lane out of a vector register, which
  // the compiler otherwise does (the empty asm tells it the array may have changed).
  alignas(64) std::int32_t o[W];
  detail::StoreVec(o, off);
  asm("" : "+m"(o));
  auto load = [base](std::int32_t at) {
    std::uint64_t x;
    std::memcpy(&x, base + at, 8);
    return x;
  };
  return typename V<W>::D{load(o[L])...};
}

// Byte c of each lane, alone at the bottom of the lane.
template <int W>
inline typename V<W>::U ByteToBottom(typename V<W>::U x, int c) {
  return (x >> (8 * c)) & 0xFFu;
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// One byte shuffle (pshufb) in place of the shift and the mask; the same pattern in each 128-bit part. (Compiled for
// the instruction sets that have it, as MaskToBits in wide.h.)
inline __m128i ByteToBottomPattern(int c) {
  return _mm_setr_epi32(int(0x80808000u + unsigned(c)), int(0x80808004u + unsigned(c)),
                        int(0x80808008u + unsigned(c)), int(0x8080800Cu + unsigned(c)));
}
template <>
__attribute__((target("avx2"))) inline V<8>::U ByteToBottom<8>(V<8>::U x, int c) {
  return V<8>::U(_mm256_shuffle_epi8(__m256i(x), _mm256_broadcastsi128_si256(ByteToBottomPattern(c))));
}
template <>
__attribute__((target("avx512f,avx512bw"))) inline V<16>::U ByteToBottom<16>(V<16>::U x, int c) {
  return V<16>::U(_mm512_shuffle_epi8(__m512i(x), _mm512_broadcast_i32x4(ByteToBottomPattern(c))));
}
#endif

// detail::SrgbDecodeSample for W lanes, the same operations in the same order.
template <int W>
SOFTGL_INLINE typename V<W>::F DecodeSrgb(typename V<W>::F k) {
  using F = typename V<W>::F;
  F p = F{} + detail::kSrgbDecodePoly[6];
  for (int i = 5; i >= 0; --i) p = p * k + detail::kSrgbDecodePoly[i];
  return k <= 10.0f ? k * detail::kSrgbToeScale : p;
}

// Byte C of each lane's texel, as a float; 0 (alpha 255) for a channel the layout lacks. With Srgb the colour
// bytes are decoded (255 times linear), as TextureLevel::Sampled has them.
template <int W, int Bytes, int C, bool Srgb>
SOFTGL_INLINE typename V<W>::F Channel(typename V<W>::U x) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  if constexpr (Srgb && C < 3) {
    return DecodeSrgb<W>(Channel<W, Bytes, C, false>(x));
  } else if constexpr (C >= Bytes) {
    return F{} + (C == 3 ? 255.0f : 0.0f);
  } else if constexpr (C == 0) {
    return __builtin_convertvector(I(x & 0xFFu), F);  // as signed: one instruction on every set
  } else if constexpr (C == 3) {
    return __builtin_convertvector(I(x >> 24), F);
  } else {
    return __builtin_convertvector(I(ByteToBottom<W>(x, C)), F);
  }
}

// i modulo n (n >= 1) in [0, n), for |i| up to 1e9 + 1 (what TexelCoord's clamp leaves): a mask for a power of two,
// else two steps of a float quotient. The first leaves |r| <= n + 128 (i and i / n are rounded to 24 bits); the
// second is exact, a float holding that r and its quotient's floor exactly (n is at most 2 x kMaxTextureSize).
template <int W>
SOFTGL_INLINE typename V<W>::I FloorMod(typename V<W>::I i, int n) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  if ((n & (n - 1)) == 0) return i & (n - 1);
  const float fn = float(n);
  I r = i - __builtin_convertvector(FloorF<W>(__builtin_convertvector(i, F) / fn), I) * n;
  r = r - __builtin_convertvector(FloorF<W>(__builtin_convertvector(r, F) / fn), I) * n;
  return r;
}

// Wrap() for W lanes, the same indices: -1 for a border texel (CLAMP_TO_BORDER).
template <int W>
SOFTGL_INLINE typename V<W>::I WrapLanes(Enum mode, typename V<W>::I i, int size) {
  using I = typename V<W>::I;
  if (mode == CLAMP_TO_EDGE) {
    const I hi = I{} + (size - 1);
    i = i < 0 ? I{} : i;
    return hi < i ? hi : i;
  }
  // (One unsigned comparison for i < 0 or i >= size: GCC 12 compiles a select on an OR of two comparisons lane by
  // lane.)
  using U = typename V<W>::U;
  if (mode == CLAMP_TO_BORDER) return (U(i) >= unsigned(size)) ? I{} - 1 : i;
  if (mode == REPEAT) return FloorMod<W>(i, size);
  const I a = FloorMod<W>(i, 2 * size) - size;  // MIRRORED_REPEAT
  const I mirror = a >= 0 ? a : -(a + 1);
  return (size - 1) - mirror;
}

// TexelCoord for W lanes: s * size, NaN -> 0, clamped to [-1e9, 1e9] (std::clamp's order of tests).
template <int W>
SOFTGL_INLINE typename V<W>::F TexelCoordLanes(typename V<W>::F x, float size) {
  using F = typename V<W>::F;
  F u = x * size;
  u = u == u ? u : F{} + 0.0f;
  u = F{} + 1e9f < u ? F{} + 1e9f : u;
  return u < -1e9f ? F{} - 1e9f : u;
}

// x in every lane, its bits as they are (F{} + x would quiet a signalling NaN: an integer border colour's bits
// may be one).
template <int W>
SOFTGL_INLINE typename V<W>::F SplatBits(float x) {
  const typename V<W>::U bits = typename V<W>::U{} + std::bit_cast<std::uint32_t>(x);
  typename V<W>::F f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// What the filters of one 2D view need: its wrap modes, whether one is CLAMP_TO_BORDER, and the border colour.
// (And, for a 2D array, each lane's layer: `layered` set, `layer` the layer.)
template <int W>
struct LanesWrap {
  Enum s, t;
  bool border;
  typename V<W>::F border_raw[4];
  bool layered = false;
  typename V<W>::I layer{};
  // (And, for a shadow lookup, the comparison: `compare` set, channel 0 of each texel (border texels included)
  // replaced by 1 where ref `func` texel passes, else 0.)
  bool compare = false;
  Enum func = LEQUAL;
  typename V<W>::F ref{};
};

// The depth comparison of W texels x against wr.ref: 1 where it passes, 0 elsewhere (a select on one comparison
// in each case).
template <int W>
SOFTGL_INLINE typename V<W>::F CompareLanes(const LanesWrap<W>& wr, typename V<W>::F x) {
  using F = typename V<W>::F;
  const F one = F{} + 1.0f, zero = F{};
  const F r = wr.ref;
  switch (wr.func) {
    case NEVER: return zero;
    case LESS: return r < x ? one : zero;
    case EQUAL: return r == x ? one : zero;
    case LEQUAL: return r <= x ? one : zero;
    case GREATER: return r > x ? one : zero;
    case NOTEQUAL: return r != x ? one : zero;
    case GEQUAL: return r >= x ? one : zero;
    default: return one;  // ALWAYS
  }
}

// The four channels of each lane's 8-bit texel x (Channel).
template <int W, int Bytes, bool Srgb>
SOFTGL_INLINE void Channels(typename V<W>::U x, typename V<W>::F out[4]) {
  out[0] = Channel<W, Bytes, 0, Srgb>(x);
  out[1] = Channel<W, Bytes, 1, Srgb>(x);
  out[2] = Channel<W, Bytes, 2, Srgb>(x);
  out[3] = Channel<W, Bytes, 3, Srgb>(x);
}

// Whether a layout's texel is decoded from its first 32 bits by WordTexels (one channel of 32 or 16 bits, two of
// 16, a packed fixed-point word, or R11F_G11F_B10F's three small floats): a row's two texels then come from one 64-bit load.
inline bool IsWordLayout(TexelLayout l) {
  return l == TexelLayout::kFloat32x1 || l == TexelLayout::kFloat16x1 || l == TexelLayout::kFloat16x2 ||
         l == TexelLayout::kUnorm16x1 || l == TexelLayout::kUnorm16x2 || l == TexelLayout::kFloat11x11x10 ||
         detail::IsPackedUnorm(l);
}
// The texels whose first 32 bits are `word`, in a WordTexels layout, as RawTexel reads them.
template <int W>
SOFTGL_INLINE void WordTexels(TexelLayout layout, typename V<W>::U word, typename V<W>::F out[4]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  out[1] = out[2] = F{};
  out[3] = F{} + 1.0f;
  // A packed layout's channels: bits and lowest bit of red, green, blue, alpha (0 bits: alpha absent, reads 1), as
  // RawTexel has them: k / (2^bits - 1).
  auto packed = [&](const int (&bits)[4], const int (&shift)[4]) SOFTGL_WIDE_LAMBDA {
    for (int c = 0; c < 4; ++c)
      if (bits[c]) {
        const unsigned max = (1u << bits[c]) - 1u;
        out[c] = __builtin_convertvector(I((word >> shift[c]) & max), F) / float(max);
      }
  };
  switch (layout) {
    case TexelLayout::kUnorm565: return packed({5, 6, 5, 0}, {11, 5, 0, 0});
    case TexelLayout::kUnorm4444: return packed({4, 4, 4, 4}, {12, 8, 4, 0});
    case TexelLayout::kUnorm5551: return packed({5, 5, 5, 1}, {11, 6, 1, 0});
    case TexelLayout::kUnorm1010102: return packed({10, 10, 10, 2}, {0, 10, 20, 30});
    case TexelLayout::kFloat32x1: std::memcpy(&out[0], &word, sizeof word); break;
    case TexelLayout::kFloat11x11x10: {
      // Unsigned floats of 5 exponent bits (bias 15) and 6, 6 and 5 mantissa bits: a half's magnitude once the
      // mantissa is moved up to the half's 10 bits; a NaN is the quiet NaN, as RawTexel gives it.
      const F nan = F{} + std::numeric_limits<float>::quiet_NaN();
      const F ch[3] = {HalfLanes<W>((word & 0x7FFu) << 4), HalfLanes<W>(((word >> 11) & 0x7FFu) << 4),
                       HalfLanes<W>((word >> 22) << 5)};
      for (int c = 0; c < 3; ++c) out[c] = ch[c] == ch[c] ? ch[c] : nan;
      break;
    }
    case TexelLayout::kFloat16x2: out[1] = HalfLanes<W>(word >> 16); [[fallthrough]];
    case TexelLayout::kFloat16x1: out[0] = HalfLanes<W>(word & 0xFFFFu); break;
    case TexelLayout::kUnorm16x2: out[1] = __builtin_convertvector(I(word >> 16), F) / 65535.0f; [[fallthrough]];
    default: out[0] = __builtin_convertvector(I(word & 0xFFFFu), F) / 65535.0f; break;  // kUnorm16x1
  }
}

// The four halves of each lane's RGBA16F texel (the lane's 64 bits of `texels`) as floats (HalfLanes).
template <int W>
SOFTGL_INLINE void Rgba16fTexels(typename V<W>::D texels, typename V<W>::F out[4]) {
  for (int c = 0; c < 4; ++c)
    out[c] = HalfLanes<W>(__builtin_convertvector((texels >> (16 * c)) & 0xFFFFu, typename V<W>::U));
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// With AVX-512: channel c's 16 halves picked out of the two registers of texels by one word permutation (word
// 4 * lane + c), then one conversion (VCVTPH2PS, as HalfLanes<16>).
template <>
__attribute__((target("avx512f,avx512bw"))) inline void Rgba16fTexels<16>(V<16>::D texels, V<16>::F out[4]) {
  __m512i part[2];
  std::memcpy(part, &texels, sizeof part);
  for (int c = 0; c < 4; ++c) {
    alignas(64) std::uint16_t pick[32] = {};
    for (int l = 0; l < 16; ++l) pick[l] = std::uint16_t(4 * l + c);
    const __m512i words = _mm512_permutex2var_epi16(part[0], _mm512_load_si512(pick), part[1]);
    out[c] = V<16>::F(_mm512_cvtph_ps(_mm512_castsi512_si256(words)));
  }
}
#endif

// Each lane's RGBA32F texel at byte offset at[lane] of `base`, its four floats into out: two 64-bit loads a lane.
template <int W>
SOFTGL_INLINE void Rgba32Texels(const std::uint8_t* base, typename V<W>::I at, typename V<W>::F out[4]) {
  using D = typename V<W>::D;
  using U = typename V<W>::U;
  const D lo = LoadPairs<W>(base, at, std::make_index_sequence<W>());
  const D hi = LoadPairs<W>(base + 8, at, std::make_index_sequence<W>());
  for (int c = 0; c < 4; ++c) {
    const U bits = __builtin_convertvector((c < 2 ? lo : hi) >> (32 * (c & 1)), U);
    std::memcpy(&out[c], &bits, sizeof bits);
  }
}
#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
// With AVX-512: one 128-bit load a lane, four lanes a register (lanes k, k + 4, k + 8, k + 12 in register k), then
// a 4 x 4 transpose inside each 128-bit part, which leaves lane 4 * part + k of each channel in its place.
template <>
__attribute__((target("avx512f"))) inline void Rgba32Texels<16>(const std::uint8_t* base, V<16>::I at,
                                                                V<16>::F out[4]) {
  alignas(64) std::int32_t o[16];
  detail::StoreVec(o, at);
  asm("" : "+m"(o));
  auto texel = [&](int lane) { return _mm_loadu_ps(reinterpret_cast<const float*>(base + o[lane])); };
  __m512 q[4];
  for (int k = 0; k < 4; ++k) {
    __m512 v = _mm512_castps128_ps512(texel(k));
    v = _mm512_insertf32x4(v, texel(k + 4), 1);
    v = _mm512_insertf32x4(v, texel(k + 8), 2);
    q[k] = _mm512_insertf32x4(v, texel(k + 12), 3);
  }
  const __m512 t0 = _mm512_unpacklo_ps(q[0], q[1]), t1 = _mm512_unpacklo_ps(q[2], q[3]);
  const __m512 t2 = _mm512_unpackhi_ps(q[0], q[1]), t3 = _mm512_unpackhi_ps(q[2], q[3]);
  out[0] = V<16>::F(_mm512_shuffle_ps(t0, t1, 0x44));
  out[1] = V<16>::F(_mm512_shuffle_ps(t0, t1, 0xEE));
  out[2] = V<16>::F(_mm512_shuffle_ps(t2, t3, 0x44));
  out[3] = V<16>::F(_mm512_shuffle_ps(t2, t3, 0xEE));
}
#endif

// Texel `index` (row * width + column) of level `lv` for each lane of `mask` (every lane if All), in any layout,
// as Sampled() gives it; anything in the other lanes. Float layouts (16- and 32-bit), 16-bit fixed point, the
// packed fixed-point layouts and R11F_G11F_B10F are read with one or two 64-bit loads a lane and converted in vector
// form; any other layout (the 8-bit ones, which the callers load themselves) with RawTexel, one lane at a time.
// (The texels at `data`, `bytes` a texel, of `layout`: a level's, or a buffer texture's store, whose reads the
// caller keeps inside it.)
template <int W, bool All>
SOFTGL_INLINE void GatherTexels(const std::uint8_t* data, TexelLayout layout, int bytes, typename V<W>::I index,
                                typename V<W>::I mask, typename V<W>::F out[4]) {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  using D = typename V<W>::D;
  if (const detail::IntegerLayout k = detail::IntegerLayoutOf(layout); k.channels) {
    // An integer texel's channels sign- or zero-extended to 32 bits and carried as the floats' bits (IntegerTexel's
    // values), the channels it lacks (0, 0, 0, 1). (Lanes outside the mask read at texel 0; a 64-bit read at the
    // last texel stays in the level's padding.)
    using I = typename V<W>::I;
    const std::uint8_t* base = data;
    const I at = (All ? index : index & mask) * bytes;
    if (bytes == 16) return Rgba32Texels<W>(base, at, out);
    const D lo = LoadPairs<W>(base, at, std::make_index_sequence<W>());
    for (int c = 0; c < 4; ++c) {
      I v;
      if (c >= k.channels) {
        v = I{} + (c == 3 ? 1 : 0);
      } else if (k.packed) {  // RGB10_A2UI
        v = I(__builtin_convertvector((lo >> (10 * c)) & (c < 3 ? 0x3FFu : 0x3u), U));
      } else {
        const int bits = 8 * k.bytes;
        const U raw = __builtin_convertvector(lo >> (bits * c), U);
        if (bits == 32) v = I(raw);
        else if (k.is_signed) v = I(raw << (32 - bits)) >> (32 - bits);
        else v = I(raw & ((1u << bits) - 1u));
      }
      std::memcpy(&out[c], &v, sizeof v);
    }
    return;
  }
  if (IsWordLayout(layout)) {  // (lanes outside the mask read at texel 0)
    const typename V<W>::I at = (All ? index : index & mask) * bytes;
    WordTexels<W>(layout, __builtin_convertvector(LoadPairs<W>(data, at, std::make_index_sequence<W>()), U), out);
    return;
  }
  const int channels =
      layout == TexelLayout::kFloat16x4 || layout == TexelLayout::kFloat32x4 || layout == TexelLayout::kUnorm16x4 ? 4
      : layout == TexelLayout::kFloat16x2 || layout == TexelLayout::kFloat32x2 || layout == TexelLayout::kUnorm16x2
          ? 2
          : 1;
  const bool half = layout == TexelLayout::kFloat16x4 || layout == TexelLayout::kFloat16x2 ||
                    layout == TexelLayout::kFloat16x1;
  const bool single = layout == TexelLayout::kFloat32x4 || layout == TexelLayout::kFloat32x2 ||
                      layout == TexelLayout::kFloat32x1;
  const bool unorm16 = detail::IsUnorm16(layout);
  if (half || single || unorm16) {
    // (A texel's 64-bit read may run past the level's last texel into its padding; lanes outside the mask read at
    // texel 0.)
    const std::uint8_t* base = data;
    const typename V<W>::I at = (All ? index : index & mask) * bytes;
    if (channels == 4 && single) return Rgba32Texels<W>(base, at, out);
    const D lo = LoadPairs<W>(base, at, std::make_index_sequence<W>());
    if (channels == 4 && half) return Rgba16fTexels<W>(lo, out);
    for (int c = 0; c < 4; ++c) {
      if (c >= channels) {
        out[c] = F{} + (c == 3 ? 1.0f : 0.0f);
      } else if (half) {
        out[c] = HalfLanes<W>(__builtin_convertvector((lo >> (16 * c)) & 0xFFFFu, U));
      } else if (unorm16) {  // k / 65535, as RawTexel
        const typename V<W>::I k = __builtin_convertvector((lo >> (16 * c)) & 0xFFFFu, typename V<W>::I);
        out[c] = __builtin_convertvector(k, F) / 65535.0f;
      } else {
        const U bits = __builtin_convertvector(lo >> (32 * c), U);
        std::memcpy(&out[c], &bits, sizeof bits);
      }
    }
    return;
  }
  alignas(64) std::int32_t at[W];
  detail::StoreVec(at, index);
  alignas(64) float v[4][W] = {};
  const std::uint32_t lanes = All ? (1u << W) - 1 : detail::MaskToBits<W>(mask, 0);
  for (std::uint32_t bits = lanes; bits != 0; bits &= bits - 1) {
    const int l = __builtin_ctz(bits);
    const glm::vec4 t = detail::RawTexel(layout, data + std::size_t(at[l]) * std::size_t(bytes));
    for (int c = 0; c < 4; ++c) v[c][l] = t[c];
  }
  for (int c = 0; c < 4; ++c) out[c] = detail::LoadVec<F>(v[c]);
}
template <int W, bool All>
SOFTGL_INLINE void GatherTexels(const TextureLevel& lv, typename V<W>::I index, typename V<W>::I mask,
                                typename V<W>::F out[4]) {
  GatherTexels<W, All>(lv.data.data(), lv.layout, lv.bytes, index, mask, out);
}

// The first 32 bits of the four texels of each lane's bilinear footprint (bytes a texel, at most 4): rows r0 and r1
// (texel indices of their first texel), columns k0 and k1, for the lanes of `mask` (every lane if All). Each row's
// two texels come from one 64-bit read at its left texel (lanes outside the mask read at texel 0, always there);
// the level's padding covers a read at its last texel. Where the right-hand texel is not the next one in the row
// (it wrapped, was clamped or mirrored), it is read on its own, unless it or both rows are border texels (c1, q0,
// q1 negative: the border colour replaces them). (`apart` as bits: GCC 12 compiles an OR of two comparisons lane
// by lane.)
template <int W, bool All>
SOFTGL_INLINE void RowPairs(const std::uint8_t* base, int bytes, typename V<W>::I r0, typename V<W>::I r1,
                            typename V<W>::I k0, typename V<W>::I k1, typename V<W>::I c1, typename V<W>::I q0,
                            typename V<W>::I q1, typename V<W>::I mask, typename V<W>::U& t00, typename V<W>::U& t10,
                            typename V<W>::U& t01, typename V<W>::U& t11) {
  using D = typename V<W>::D;
  using U = typename V<W>::U;
  const typename V<W>::I o0 = (All ? r0 + k0 : (r0 + k0) & mask) * bytes;
  const typename V<W>::I o1 = (All ? r1 + k0 : (r1 + k0) & mask) * bytes;
  const D p0 = LoadPairs<W>(base, o0, std::make_index_sequence<W>()),
          p1 = LoadPairs<W>(base, o1, std::make_index_sequence<W>());
  t00 = __builtin_convertvector(p0, U);
  t01 = __builtin_convertvector(p1, U);
  t10 = __builtin_convertvector(p0 >> (8 * bytes), U);
  t11 = __builtin_convertvector(p1 >> (8 * bytes), U);
  const std::uint32_t apart =
      detail::MaskToBits<W>(All ? k1 != k0 + 1 : (k1 != k0 + 1) & mask, 0) & ~detail::SignBits<W>(c1 | (q0 & q1));
  for (std::uint32_t wrap = apart; wrap != 0; wrap &= wrap - 1) {
    const int l = __builtin_ctz(wrap);
    std::uint32_t w0, w1;
    std::memcpy(&w0, base + std::size_t(r0[l] + k1[l]) * bytes, 4);
    std::memcpy(&w1, base + std::size_t(r1[l] + k1[l]) * bytes, 4);
    t10[l] = w0;
    t11[l] = w1;
  }
}

// Bilinear samples of level `lv` for the lanes of `mask` (for every lane if All), in storage units, written into
// out (r, g, b, a): of an 8-bit layout (RGBA8 and RGB8, RG8 or R8: Bytes 4, 2 or 1 a texel; channels the layout
// lacks read 0, alpha 255, as Raw() has them), or of any layout (Bytes 0: its texels read one lane at a time).
// Texel indices wrap as `wr` says (WrapLanes); a border texel is the border colour.
template <int W, int Bytes, bool Srgb, bool All = false>
SOFTGL_INLINE void BilinearLanes(const TextureLevel& lv, const LanesWrap<W>& wr, typename V<W>::F s,
                                 typename V<W>::F t, typename V<W>::I mask, typename V<W>::F out[4]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  const F u = TexelCoordLanes<W>(s, float(lv.width)), v = TexelCoordLanes<W>(t, float(lv.height));
  const F fu = u - 0.5f, fv = v - 0.5f;
  const F flu = FloorF<W>(fu), flv = FloorF<W>(fv);
  const F a = fu - flu, b = fv - flv;
  const I i0 = __builtin_convertvector(flu, I), j0 = __builtin_convertvector(flv, I);
  const I c0 = WrapLanes<W>(wr.s, i0, lv.width), c1 = WrapLanes<W>(wr.s, i0 + 1, lv.width);
  const I q0 = WrapLanes<W>(wr.t, j0, lv.height), q1 = WrapLanes<W>(wr.t, j0 + 1, lv.height);
  // (A border texel's index, -1, reads texel 0 of its row or column instead, replaced below.)
  I r0 = q0, r1 = q1, k0 = c0, k1 = c1;
  if (wr.border) {
    r0 = r0 < 0 ? I{} : r0;
    r1 = r1 < 0 ? I{} : r1;
    k0 = k0 < 0 ? I{} : k0;
    k1 = k1 < 0 ? I{} : k1;
  }
  if (wr.layered) {  // the layer's rows come first (Fetch's layer * height + row)
    r0 += wr.layer * lv.height;
    r1 += wr.layer * lv.height;
  }
  r0 *= lv.width;
  r1 *= lv.width;
  const F w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
  // Channel c's weighted sum of the four texels (with `border`, the border colour for border texels), into out.
  auto channel_sum = [&](auto border, int c, F x00, F x10, F x01, F x11) SOFTGL_WIDE_LAMBDA {
    if constexpr (decltype(border)::value) {
      x00 = ((c0 | q0) >= 0) ? x00 : wr.border_raw[c];
      x10 = ((c1 | q0) >= 0) ? x10 : wr.border_raw[c];
      x01 = ((c0 | q1) >= 0) ? x01 : wr.border_raw[c];
      x11 = ((c1 | q1) >= 0) ? x11 : wr.border_raw[c];
    }
    if (c == 0 && wr.compare) {
      x00 = CompareLanes<W>(wr, x00);
      x10 = CompareLanes<W>(wr, x10);
      x01 = CompareLanes<W>(wr, x01);
      x11 = CompareLanes<W>(wr, x11);
    }
    const F sum = w00 * x00 + w10 * x10 + w01 * x01 + w11 * x11;
    if constexpr (All) out[c] = sum;
    else out[c] = mask != 0 ? sum : out[c];
  };
  if constexpr (Bytes == 0) {
    F x00[4], x10[4], x01[4], x11[4];
    if (IsWordLayout(lv.layout)) {
      // A row's two texels in one 64-bit load at its left texel, as for the 8-bit layouts below.
      U t00, t10, t01, t11;
      RowPairs<W, All>(lv.data.data(), lv.bytes, r0, r1, k0, k1, c1, q0, q1, mask, t00, t10, t01, t11);
      WordTexels<W>(lv.layout, t00, x00);
      WordTexels<W>(lv.layout, t10, x10);
      WordTexels<W>(lv.layout, t01, x01);
      WordTexels<W>(lv.layout, t11, x11);
    } else {
      GatherTexels<W, All>(lv, r0 + k0, mask, x00);
      GatherTexels<W, All>(lv, r0 + k1, mask, x10);
      GatherTexels<W, All>(lv, r1 + k0, mask, x01);
      GatherTexels<W, All>(lv, r1 + k1, mask, x11);
    }
    for (int c = 0; c < 4; ++c) {
      if (wr.border) channel_sum(std::true_type(), c, x00[c], x10[c], x01[c], x11[c]);
      else channel_sum(std::false_type(), c, x00[c], x10[c], x01[c], x11[c]);
    }
  } else {
    U t00, t10, t01, t11;
    RowPairs<W, All>(lv.data.data(), Bytes, r0, r1, k0, k1, c1, q0, q1, mask, t00, t10, t01, t11);
    // One channel at a time, decoded where it is summed (fewer registers live than four decoded texels); the
    // border's selects in a form of their own.
    auto sums = [&](auto border) SOFTGL_WIDE_LAMBDA {
      auto sum_of = [&](auto c) SOFTGL_WIDE_LAMBDA {
        channel_sum(border, c, Channel<W, Bytes, c, Srgb>(t00), Channel<W, Bytes, c, Srgb>(t10),
                    Channel<W, Bytes, c, Srgb>(t01), Channel<W, Bytes, c, Srgb>(t11));
      };
      sum_of(std::integral_constant<int, 0>());
      sum_of(std::integral_constant<int, 1>());
      sum_of(std::integral_constant<int, 2>());
      sum_of(std::integral_constant<int, 3>());
    };
    if (wr.border) sums(std::true_type());
    else sums(std::false_type());
  }
}

// NEAREST (FilterLevel's) of level `lv` for the lanes of `mask`, as BilinearLanes gives LINEAR: the texel that
// holds (u, v), wrapped, or the border colour.
template <int W, int Bytes, bool Srgb, bool All = false>
SOFTGL_INLINE void NearestLanes(const TextureLevel& lv, const LanesWrap<W>& wr, typename V<W>::F s,
                                typename V<W>::F t, typename V<W>::I mask, typename V<W>::F out[4]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  const F u = TexelCoordLanes<W>(s, float(lv.width)), v = TexelCoordLanes<W>(t, float(lv.height));
  const I c = WrapLanes<W>(wr.s, __builtin_convertvector(FloorF<W>(u), I), lv.width);
  const I q = WrapLanes<W>(wr.t, __builtin_convertvector(FloorF<W>(v), I), lv.height);
  I row = q < 0 ? I{} : q;
  if (wr.layered) row += wr.layer * lv.height;
  const I at = row * lv.width + (c < 0 ? I{} : c);
  F x[4];
  if constexpr (Bytes == 0) {
    GatherTexels<W, All>(lv, at, mask, x);
  } else {
    const U texel = __builtin_convertvector(
        LoadPairs<W>(lv.data.data(), (All ? at : at & mask) * Bytes, std::make_index_sequence<W>()), U);
    Channels<W, Bytes, Srgb>(texel, x);
  }
  const I in = (c | q) >= 0;
  for (int ch = 0; ch < 4; ++ch) {
    if (wr.border) x[ch] = in ? x[ch] : wr.border_raw[ch];
    if (ch == 0 && wr.compare) x[ch] = CompareLanes<W>(wr, x[ch]);
    if constexpr (All) out[ch] = x[ch];
    else out[ch] = mask != 0 ? x[ch] : out[ch];
  }
}

// Level `lv` filtered for the lanes of `mask`: LINEAR where `linear` is set, else NEAREST.
template <int W, int Bytes, bool Srgb>
SOFTGL_INLINE void FilterLanes(const TextureLevel& lv, const LanesWrap<W>& wr, typename V<W>::F s,
                               typename V<W>::F t, typename V<W>::I mask, typename V<W>::I linear,
                               typename V<W>::F out[4]) {
  if (detail::MaskToBits<W>(mask & linear, 0) != 0) BilinearLanes<W, Bytes, Srgb>(lv, wr, s, t, mask & linear, out);
  if (detail::MaskToBits<W>(mask & ~linear, 0) != 0) NearestLanes<W, Bytes, Srgb>(lv, wr, s, t, mask & ~linear, out);
}

// LambdaOfRho2 for W lanes; false for lanes whose rho^2 is not a normal positive float.
template <int W>
SOFTGL_INLINE typename V<W>::I LambdaOfRho2Lanes(const TextureView& view, typename V<W>::F rho2, float bias,
                                                 typename V<W>::F& lambda) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  I bits;
  std::memcpy(&bits, &rho2, sizeof bits);
  const I biased = (bits >> 23) & 0x1FF;  // the sign bit makes negative numbers out of range
  const I normal = U(biased - 1) < 254u;  // 0 < biased < 255 (one comparison: GCC 12 scalarizes an & of two)
  I m_bits = (bits & 0x007FFFFF) | 0x3F800000;
  F m;
  std::memcpy(&m, &m_bits, sizeof m);
  const F log2 = __builtin_convertvector(biased - 127, F) + (m - 1.0f);
  const SamplerParams& p = view.params;
  const float b = std::clamp(p.lod_bias + bias, -16.0f, 16.0f);
  F lam = 0.5f * log2 + b;
  lam = lam == lam ? lam : F{} + 0.0f;
  const F lo = F{} + p.min_lod, hi = F{} + p.max_lod;
  lam = lam < lo ? lo : (hi < lam ? hi : lam);  // std::clamp
  lambda = lam;
  return normal;
}

// ExplicitLambda for W lanes.
template <int W>
SOFTGL_INLINE typename V<W>::F ExplicitLambdaLanes(const TextureView& view, typename V<W>::F lod) {
  using F = typename V<W>::F;
  const SamplerParams& p = view.params;
  const F lo = F{} + p.min_lod, hi = F{} + p.max_lod;
  F lam = lod + std::clamp(p.lod_bias, -16.0f, 16.0f);
  lam = lam < lo ? lo : (hi < lam ? hi : lam);  // std::clamp
  return lam == lam ? lam : F{} + 0.0f;
}

// ArrayLayer for W lanes: floor(r + 1/2) clamped to the layers, NaN as 0. (r + 1/2 is clamped to [-1, layers]
// first, which changes no result, so that the floor's conversion to integers stays in range.)
template <int W>
SOFTGL_INLINE typename V<W>::I ArrayLayerLanes(const TextureView& view, typename V<W>::F r) {
  using F = typename V<W>::F;
  const float top = float(view.texture->levels[0][view.base].depth - 1);
  F x = r + 0.5f;
  x = x == x ? x : F{} + 0.0f;
  x = x < -1.0f ? F{} - 1.0f : (top + 1.0f < x ? F{} + (top + 1.0f) : x);
  F l = FloorF<W>(x);
  l = l < 0.0f ? F{} + 0.0f : (top < l ? F{} + top : l);
  return __builtin_convertvector(l, typename V<W>::I);
}

// CubeFace and FaceCoords for W lanes: each lane's face (of direction (s, t, r)), its (s, t) on it ((1/2, 1/2)
// where the major axis is not positive), and, unless `explicit_lod`, the derivatives of (s, t) measured on that
// face (0 where the neighbouring direction does not point at it), as SampleCube computes them.
template <int W>
SOFTGL_INLINE void CubeLanes(const Textures::Lanes& c, int l0, bool explicit_lod, typename V<W>::I& face,
                             typename V<W>::F& s, typename V<W>::F& t, typename V<W>::F& ds_dx,
                             typename V<W>::F& dt_dx, typename V<W>::F& ds_dy, typename V<W>::F& dt_dy) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  const F x = LoadF<W>(c.s + l0), y = LoadF<W>(c.t + l0), z = LoadF<W>(c.r + l0);
  auto abs = [](F v) SOFTGL_WIDE_LAMBDA { return v < 0.0f ? -v : v; };
  const F ax = abs(x), ay = abs(y), az = abs(z);
  // (Selects on single comparisons: x is the major axis where ax >= ay and ax >= az.)
  const I fx = x >= 0.0f ? I{} : I{} + 1, fy = y >= 0.0f ? I{} + 2 : I{} + 3, fz = z >= 0.0f ? I{} + 4 : I{} + 5;
  const I yz = ay >= az ? fy : fz;
  I f = ax >= az ? fx : yz;
  f = ax >= ay ? f : yz;
  face = f;
  // Table 8.19's (sc, tc, ma) of a direction on each lane's face.
  auto coords = [&](F dx, F dy, F dz, F& u, F& v) SOFTGL_WIDE_LAMBDA {
    F sc = dx, tc = -dy, ma = dz;  // face 4
    sc = f == 0 ? -dz : sc;
    ma = f == 0 ? dx : ma;
    sc = f == 1 ? dz : sc;
    ma = f == 1 ? -dx : ma;
    tc = f == 2 ? dz : tc;
    ma = f == 2 ? dy : ma;
    tc = f == 3 ? -dz : tc;
    ma = f == 3 ? -dy : ma;
    sc = f == 5 ? -dx : sc;
    ma = f == 5 ? -dz : ma;
    u = (sc / ma + 1.0f) * 0.5f;
    v = (tc / ma + 1.0f) * 0.5f;
    return ma > 0.0f;
  };
  F u, v;
  const I on = coords(x, y, z, u, v);
  s = on ? u : F{} + 0.5f;
  t = on ? v : F{} + 0.5f;
  if (explicit_lod) return;
  F ux, vx, uy, vy;
  const I on_x = coords(x + LoadF<W>(c.ds_dx + l0), y + LoadF<W>(c.dt_dx + l0), z + LoadF<W>(c.dr_dx + l0), ux, vx);
  const I on_y = coords(x + LoadF<W>(c.ds_dy + l0), y + LoadF<W>(c.dt_dy + l0), z + LoadF<W>(c.dr_dy + l0), uy, vy);
  ds_dx = on_x ? ux - s : F{} + 0.0f;
  dt_dx = on_x ? vx - t : F{} + 0.0f;
  ds_dy = on_y ? uy - s : F{} + 0.0f;
  dt_dy = on_y ? vy - t : F{} + 0.0f;
}

// SampleFace for W lanes of a 2D view (Bytes: the 8-bit layout's bytes a texel, 0 for any layout): SampleMip's level
// choice (magnification, or one level, or two with a weight), then each level's lanes filtered together. Linear: the
// form for LINEAR magnification with LINEAR or LINEAR_MIPMAP_LINEAR minification, with a shorter level choice.
// A 3D texture's levels are filtered slice by slice (FilterVolume); anisotropic filtering takes its probes one after
// another, each for every lane that has that many (SampleAnisotropic).
template <int W, int Bytes, bool Srgb, bool Linear>
SOFTGL_INLINE void SampleTexelLanes(const TextureView& view, Lookup kind, const Textures::Lanes& c, float bias,
                                    const float* lod, float out[4][16]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  const auto& all_levels = view.texture->levels;
  const bool cube = kind == Lookup::kCube || kind == Lookup::kCubeLod;
  const bool volume = kind == Lookup::k3D || kind == Lookup::k3DLod;
  const bool explicit_lod =
      kind == Lookup::kLod || kind == Lookup::kArrayLod || kind == Lookup::kCubeLod || kind == Lookup::k3DLod;
  const SamplerParams& p = view.params;
  LanesWrap<W> wr;
  wr.s = p.wrap_s;
  wr.t = p.wrap_t;
  wr.border = p.wrap_s == CLAMP_TO_BORDER || p.wrap_t == CLAMP_TO_BORDER;
  for (int ch = 0; ch < 4; ++ch) wr.border_raw[ch] = SplatBits<W>(view.border_raw[ch]);
  // 0: no mipmaps (NEAREST, LINEAR); 1: *_MIPMAP_NEAREST; 2: *_MIPMAP_LINEAR.
  const int mip = p.min_filter == NEAREST || p.min_filter == LINEAR                             ? 0
                  : p.min_filter == NEAREST_MIPMAP_NEAREST || p.min_filter == LINEAR_MIPMAP_NEAREST ? 1
                                                                                                    : 2;
  const float mag_below = (p.mag_filter == LINEAR && mip == 1) ? 0.5f : 0.0f;
  const I mag_linear = I{} + (p.mag_filter == LINEAR ? -1 : 0);
  const I min_linear = I{} + (p.min_filter == LINEAR || p.min_filter == LINEAR_MIPMAP_NEAREST ||
                                      p.min_filter == LINEAR_MIPMAP_LINEAR
                                  ? -1
                                  : 0);
  const F fbase = F{} + float(view.base), fq = F{} + float(view.q);
  wr.layered = kind == Lookup::kArray || kind == Lookup::kArrayLod || kind == Lookup::kArrayShadow || volume;
  wr.compare = kind == Lookup::kShadow || kind == Lookup::kArrayShadow;
  wr.func = p.compare_func;
  // Anisotropic filtering: texture() on a colour texture with TEXTURE_MAX_ANISOTROPY above 1, not on a 3D one.
  const bool aniso = !explicit_lod && !wr.compare && !volume && !view.depth && view.anisotropy > 1.0f;
  const TextureLevel& base = all_levels[0][view.base];
  const float width = float(base.width), height = float(base.height), depth = float(base.depth);
  for (int l0 = 0; l0 < 16; l0 += W) {
    // The lookup's coordinates on its face or layer, and lambda: from the derivatives (false in `normal` for
    // lanes whose rho^2 is not a normal positive float), or textureLod's.
    F s, t, lam, ds_dx, dt_dx, ds_dy, dt_dy, r = F{};
    I face = I{};
    if (cube) {
      CubeLanes<W>(c, l0, explicit_lod, face, s, t, ds_dx, dt_dx, ds_dy, dt_dy);
    } else {
      s = LoadF<W>(c.s + l0);
      t = LoadF<W>(c.t + l0);
      if (!explicit_lod) {
        ds_dx = LoadF<W>(c.ds_dx + l0), dt_dx = LoadF<W>(c.dt_dx + l0);
        ds_dy = LoadF<W>(c.ds_dy + l0), dt_dy = LoadF<W>(c.dt_dy + l0);
      }
    }
    if (volume) r = LoadF<W>(c.r + l0);
    else if (wr.layered) wr.layer = ArrayLayerLanes<W>(view, LoadF<W>(c.r + l0));
    if (wr.compare) {  // the reference: r, or (for an array) `lod`'s lanes; NaN as 0, clamped to [0, 1]
      F ref = LoadF<W>((kind == Lookup::kShadow ? c.r : lod) + l0);
      ref = ref == ref ? ref : F{} + 0.0f;
      wr.ref = ref < 0.0f ? F{} + 0.0f : (1.0f < ref ? F{} + 1.0f : ref);
    }
    I normal = I{} - 1;
    // Anisotropic filtering's probes: n of them along the longer derivative (ms, mt); `probes` the most any lane
    // takes.
    I n = I{} + 1;
    F ms = F{}, mt = F{};
    int probes = 1;
    if (explicit_lod) {
      lam = ExplicitLambdaLanes<W>(view, LoadF<W>(lod + l0));
    } else {
      // Lambda (LambdaVolume): the squared lengths of the texel-space derivatives along x and y.
      const F txx = ds_dx * width, txy = dt_dx * height;
      const F tyx = ds_dy * width, tyy = dt_dy * height;
      F dot_x = txx * txx + txy * txy, dot_y = tyx * tyx + tyy * tyy;
      if (volume) {
        const F txz = LoadF<W>(c.dr_dx + l0) * depth, tyz = LoadF<W>(c.dr_dy + l0) * depth;
        dot_x = dot_x + txz * txz;
        dot_y = dot_y + tyz * tyz;
      }
      F rho2 = dot_x < dot_y ? dot_y : dot_x;  // std::max(dot_x, dot_y)
      if (aniso) {
        const F min2 = dot_y < dot_x ? dot_y : dot_x;  // std::min
        ms = dot_x >= dot_y ? ds_dx : ds_dy;
        mt = dot_x >= dot_y ? dt_dx : dt_dy;
        alignas(64) float ratio[W];
        for (int l = 0; l < W; ++l)  // (NaN: one probe below)
          ratio[l] = min2[l] > 0.0f ? std::sqrt(rho2[l] / min2[l]) : view.anisotropy;
        const F rt = LoadF<W>(ratio);
        // min(ceil(ratio), anisotropy), ratio first cut to 64 (above the anisotropy) so that the ceiling's
        // conversion stays in range.
        const F cut = rt < 64.0f ? rt : F{} + 64.0f;
        F nf = F{} - FloorF<W>(F{} - cut);
        nf = view.anisotropy < nf ? F{} + view.anisotropy : nf;
        n = rt > 1.0f ? __builtin_convertvector(nf, I) : I{} + 1;
        rho2 = rho2 / __builtin_convertvector(n * n, F);
      }
      normal = LambdaOfRho2Lanes<W>(view, rho2, bias, lam);
      if (aniso) {
        // (The lanes of n, not of `normal`: GCC 12 computes a mask whose lanes are read one by one lane by lane.)
        const I used = normal != 0 ? n : I{} + 1;
        for (int l = 0; l < W; ++l) probes = std::max(probes, int(used[l]));
      }
    }
    // SampleMip's choice: the level (level_a), a second one (level_a + 1) where `two`, with weight f; LINEAR
    // filtering where `linear` is set, NEAREST elsewhere.
    I level_a = I{} + view.base, two = I{}, linear = I{} - 1;
    F f = F{} + 0.0f;
    if constexpr (Linear) {
      // LINEAR magnification, LINEAR or LINEAR_MIPMAP_LINEAR minification: one level (base or q) or two (d1,
      // d1 + 1) with weight f.
      const F fl = FloorF<W>(lam);
      const I single_base = (lam <= 0.0f) | (I{} + (mip == 0 ? -1 : 0));
      const I single_q = ~single_base & (fbase + lam >= fq);
      two = ~single_base & ~single_q;
      level_a = __builtin_convertvector(fl, I) + view.base;
      level_a = single_base ? I{} + view.base : (single_q ? I{} + view.q : level_a);
      f = two ? lam - fl : F{} + 0.0f;
    } else {
      const I mag = lam <= mag_below;
      if (mip == 1) {
        const F d = fbase + (F{} - FloorF<W>(F{} - (lam + 0.5f))) - 1.0f;  // base + ceil(lambda + 1/2) - 1
        level_a = lam <= 0.5f ? level_a : __builtin_convertvector(fq < d ? fq : d, I);
      } else if (mip == 2) {
        const F fl = FloorF<W>(lam);
        const I single_q = fbase + lam >= fq;
        level_a = single_q ? I{} + view.q : __builtin_convertvector(fl, I) + view.base;
        two = ~single_q;
        f = lam - fl;
      }
      level_a = mag ? I{} + view.base : level_a;
      two &= ~mag;
      f = two != 0 ? f : F{} + 0.0f;
      linear = mag ? mag_linear : min_linear;
    }
    const std::uint32_t normal_bits = detail::MaskToBits<W>(normal, 0);
    const std::uint32_t linear_bits = detail::MaskToBits<W>(linear, 0);
    // (Arrays set element by element: GCC 12 clears an array initialized with {} by a string instruction, tens
    // of cycles a block.)
    F sum[4], first[4];
    for (int ch = 0; ch < 4; ++ch) sum[ch] = first[ch] = F{};
    for (int probe = 1; probe <= probes; ++probe) {
      // This probe's lanes and coordinates: every lane on the vector path, at (s, t), without anisotropy.
      I active = normal;
      F ps = s, pt = t;
      if (probes > 1) {
        active = normal & (n >= probe);
        const F k = float(probe) / __builtin_convertvector(n + 1, F) - 0.5f;
        ps = n == 1 ? s : s + ms * k;
        pt = n == 1 ? t : t + mt * k;
      }
      const std::uint32_t active_bits = detail::MaskToBits<W>(active, 0);
      F ra[4], rb[4];
      for (int ch = 0; ch < 4; ++ch) ra[ch] = rb[ch] = F{};
      // Each level a lane needs, first (into ra) and second (level_a + 1, into rb), filtered for the lanes that
      // need it: usually one level for all. (The masks stay results of comparisons: GCC 12 turns a select on a
      // mask it cannot see is one into a branch per lane.)
      bool usual = false;
      if constexpr (Bytes != 0) {
        // The usual block: every lane on the vector path, on the same first level (so a second level, where any
        // lane needs one, exists for all) with the same filter; filtered with the forms for every lane, their
        // results kept in registers.
        usual = !volume && active_bits == (1u << W) - 1 && (linear_bits == 0 || linear_bits == active_bits) &&
                detail::MaskToBits<W>(level_a != level_a[0], 0) == 0 &&
                (!cube || detail::MaskToBits<W>(face != face[0], 0) == 0);
        const auto& levels = all_levels[face[0]];
        if (usual && linear_bits != 0) {
          BilinearLanes<W, Bytes, Srgb, true>(levels[level_a[0]], wr, ps, pt, active, ra);
          if (detail::MaskToBits<W>(two, 0) != 0)
            BilinearLanes<W, Bytes, Srgb, true>(levels[level_a[0] + 1], wr, ps, pt, active, rb);
        } else if (usual) {
          NearestLanes<W, Bytes, Srgb, true>(levels[level_a[0]], wr, ps, pt, active, ra);
          if (detail::MaskToBits<W>(two, 0) != 0)
            NearestLanes<W, Bytes, Srgb, true>(levels[level_a[0] + 1], wr, ps, pt, active, rb);
        }
      }
      // Otherwise each level the lanes need, first (into ra) and second (level_a + 1, into rb), for the lanes that
      // need it; a cube map's lanes by face and level (the key face * 64 + level, one comparison). A 3D level's
      // lanes are filtered on one slice, or two (LINEAR) weighted by the fraction of w (FilterVolume). (One loop,
      // its trip count not known to the compiler, so that the filters are inlined once here.)
      const int stages = usual ? 0 : detail::MaskToBits<W>(active & two, 0) != 0 ? 2 : 1;
      for (int k = 0; k < stages; ++k) {
        I pending = k ? active & two : active;
        const I level = level_a + k;
        const I key = cube ? face * 64 + level : level;
        F* res = k ? rb : ra;
        for (std::uint32_t bits = detail::MaskToBits<W>(pending, 0); bits != 0;
             bits = detail::MaskToBits<W>(pending, 0)) {
          const int lane = __builtin_ctz(bits);
          const I mask = pending & (key == key[lane]);
          const TextureLevel& lv = all_levels[face[lane]][level[lane]];
          // A 3D level's slices: k0 (NEAREST: the one holding w; LINEAR: the lower one) and k0 + 1, wrapped by
          // TEXTURE_WRAP_R (-1: the border colour), LINEAR's weight cw; each filtered into slice[j]. (One call of
          // FilterLanes for both cases, so that its filters are inlined once.)
          I wk[2] = {};
          F cw = F{};
          int slices = 1;
          if (volume) {
            const F w = TexelCoordLanes<W>(r, float(lv.depth));
            const F fw = w - 0.5f, flw = FloorF<W>(fw);
            cw = fw - flw;
            const I k0 = linear != 0 ? __builtin_convertvector(flw, I) : __builtin_convertvector(FloorF<W>(w), I);
            wk[0] = WrapLanes<W>(p.wrap_r, k0, lv.depth);
            wk[1] = WrapLanes<W>(p.wrap_r, k0 + 1, lv.depth);
            slices = detail::MaskToBits<W>(mask & linear, 0) != 0 ? 2 : 1;
          }
          F slice[2][4];
          for (int ch = 0; ch < 4; ++ch) slice[0][ch] = slice[1][ch] = F{};
          for (int j = 0; j < slices; ++j) {
            if (volume) wr.layer = wk[j] < 0 ? I{} : wk[j];
            F* into = volume ? slice[j] : res;
            FilterLanes<W, Bytes, Srgb>(lv, wr, ps, pt, j ? mask & linear : mask, linear, into);
            if (volume)
              for (int ch = 0; ch < 4; ++ch) into[ch] = wk[j] < 0 ? wr.border_raw[ch] : into[ch];
          }
          if (volume) {
            for (int ch = 0; ch < 4; ++ch) {
              const F lerp = (1.0f - cw) * slice[0][ch] + cw * slice[1][ch];
              const F v = linear != 0 ? lerp : slice[0][ch];
              res[ch] = mask != 0 ? v : res[ch];
            }
          }
          pending &= ~mask;
        }
      }
      for (int ch = 0; ch < 4; ++ch) {
        const F lerp = (1.0f - f) * ra[ch] + f * rb[ch];
        const F v = two != 0 ? lerp : ra[ch];
        if (probes == 1) {
          first[ch] = v;
        } else {  // SampleAnisotropic's sum, from 0 in probe order
          if (probe == 1) first[ch] = v;
          sum[ch] = active != 0 ? sum[ch] + v : sum[ch];
        }
      }
    }
    for (int ch = 0; ch < 4; ++ch) {
      F v = first[ch];
      if (probes > 1) v = n == 1 ? v : sum[ch] / __builtin_convertvector(n, F);
      if (!view.integer) v = v / view.scale;  // (an integer texture's bits as they are: Unscaled)
      std::memcpy(&out[ch][l0], &v, sizeof v);
    }
    // Lanes the vector path does not take: one lane at a time.
    for (std::uint32_t rest = ~normal_bits & ((1u << W) - 1); rest != 0; rest &= rest - 1) {
      const int lane = l0 + __builtin_ctz(rest);
      const glm::vec4 res = SampleOneLane(view, kind, c, lane, bias, lod);
      for (int ch = 0; ch < 4; ++ch) out[ch][lane] = res[ch];
    }
  }
}

using SampleTexelLanesFn = void (*)(const TextureView&, Lookup, const Textures::Lanes&, float, const float*,
                                    float[4][16]);

// Each layout's form (an sRGB one for four bytes), for each instruction set.
template <int Bytes, bool Srgb, bool Linear>
void SampleTexelLanesBase(const TextureView& v, Lookup k, const Textures::Lanes& c, float bias, const float* lod,
                          float out[4][16]) {
  SampleTexelLanes<4, Bytes, Srgb, Linear>(v, k, c, bias, lod, out);
}
#if defined(SOFTGL_HAS_DISPATCH)
template <int Bytes, bool Srgb, bool Linear>
SOFTGL_TARGET_AVX2 void SampleTexelLanesAvx2(const TextureView& v, Lookup k, const Textures::Lanes& c, float bias,
                                             const float* lod, float out[4][16]) {
  SampleTexelLanes<8, Bytes, Srgb, Linear>(v, k, c, bias, lod, out);
}
template <int Bytes, bool Srgb, bool Linear>
SOFTGL_TARGET_AVX512 void SampleTexelLanesAvx512(const TextureView& v, Lookup k, const Textures::Lanes& c, float bias,
                                                 const float* lod, float out[4][16]) {
  SampleTexelLanes<16, Bytes, Srgb, Linear>(v, k, c, bias, lod, out);
}
#endif

// The lookups whose level of detail changes nothing: one level (NEAREST or LINEAR minification) filtered as it is
// magnified, no anisotropy (texture(), textureLod() and the shadow lookups on every target). Every lane is filtered
// on the base level: the samples SampleTexelLanes gives (whose one-lane path gives such a lane the same sample
// whatever its lambda), without its level of detail and level choice. A post-processing pass reading a render
// target, a shadow map with LINEAR, a NEAREST texture, a skybox, a 3D colour-grading table.
template <int W, int Bytes, bool Srgb>
SOFTGL_INLINE void SampleBaseLanes(const TextureView& view, Lookup kind, const Textures::Lanes& c, const float* lod,
                                   float out[4][16]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  const SamplerParams& p = view.params;
  LanesWrap<W> wr;
  wr.s = p.wrap_s;
  wr.t = p.wrap_t;
  wr.border = p.wrap_s == CLAMP_TO_BORDER || p.wrap_t == CLAMP_TO_BORDER;
  for (int ch = 0; ch < 4; ++ch) wr.border_raw[ch] = SplatBits<W>(view.border_raw[ch]);
  const bool cube = kind == Lookup::kCube || kind == Lookup::kCubeLod;
  const bool volume = kind == Lookup::k3D || kind == Lookup::k3DLod;
  const bool array = kind == Lookup::kArray || kind == Lookup::kArrayLod || kind == Lookup::kArrayShadow;
  wr.layered = array || volume;
  wr.compare = kind == Lookup::kShadow || kind == Lookup::kArrayShadow;
  wr.func = p.compare_func;
  const bool linear = p.mag_filter == LINEAR;
  const TextureLevel& lv = view.texture->levels[0][view.base];
  const I all = I{} - 1;
  for (int l0 = 0; l0 < 16; l0 += W) {
    F s, t;
    I face = I{};
    if (cube) {
      F unused[4];
      CubeLanes<W>(c, l0, true, face, s, t, unused[0], unused[1], unused[2], unused[3]);
    } else {
      s = LoadF<W>(c.s + l0);
      t = LoadF<W>(c.t + l0);
    }
    if (array) wr.layer = ArrayLayerLanes<W>(view, LoadF<W>(c.r + l0));
    if (wr.compare) {  // as SampleTexelLanes
      F ref = LoadF<W>((kind == Lookup::kShadow ? c.r : lod) + l0);
      ref = ref == ref ? ref : F{} + 0.0f;
      wr.ref = ref < 0.0f ? F{} + 0.0f : (1.0f < ref ? F{} + 1.0f : ref);
    }
    F r[4];
    if (cube) {
      // Each face the lanes point at (usually one for the block), its lanes filtered together.
      I pending = all;
      for (std::uint32_t bits = detail::MaskToBits<W>(pending, 0); bits != 0;
           bits = detail::MaskToBits<W>(pending, 0)) {
        const I mask = pending & (face == face[__builtin_ctz(bits)]);
        const TextureLevel& face_level = view.texture->levels[face[__builtin_ctz(bits)]][view.base];
        if (linear) BilinearLanes<W, Bytes, Srgb>(face_level, wr, s, t, mask, r);
        else NearestLanes<W, Bytes, Srgb>(face_level, wr, s, t, mask, r);
        pending &= ~mask;
      }
    } else {
      // A 2D texture or array; or a 3D texture's slices (FilterVolume): the one holding w (NEAREST) or the two
      // around it (LINEAR, weighted by w's fraction cw), wrapped by TEXTURE_WRAP_R (-1: the border colour).
      I wk[2] = {};
      F cw = F{};
      int slices = 1;
      if (volume) {
        const F w = TexelCoordLanes<W>(LoadF<W>(c.r + l0), float(lv.depth));
        const F fw = w - 0.5f, flw = FloorF<W>(fw);
        cw = fw - flw;
        const I k0 = __builtin_convertvector(linear ? flw : FloorF<W>(w), I);
        wk[0] = WrapLanes<W>(p.wrap_r, k0, lv.depth);
        wk[1] = WrapLanes<W>(p.wrap_r, k0 + 1, lv.depth);
        slices = linear ? 2 : 1;
      }
      F slice[2][4];
      for (int j = 0; j < slices; ++j) {
        F* into = volume ? slice[j] : r;
        if (volume) wr.layer = wk[j] < 0 ? I{} : wk[j];
        if (linear) BilinearLanes<W, Bytes, Srgb, true>(lv, wr, s, t, all, into);
        else NearestLanes<W, Bytes, Srgb, true>(lv, wr, s, t, all, into);
        if (volume)
          for (int ch = 0; ch < 4; ++ch) into[ch] = wk[j] < 0 ? wr.border_raw[ch] : into[ch];
      }
      if (volume)
        for (int ch = 0; ch < 4; ++ch) r[ch] = linear ? (1.0f - cw) * slice[0][ch] + cw * slice[1][ch] : slice[0][ch];
    }
    for (int ch = 0; ch < 4; ++ch) {  // (an integer texture's bits as they are: Unscaled)
      const F v = view.integer ? r[ch] : r[ch] / view.scale;
      std::memcpy(&out[ch][l0], &v, sizeof v);
    }
  }
}

template <int Bytes, bool Srgb>
void SampleBaseLanesBase(const TextureView& v, Lookup k, const Textures::Lanes& c, float, const float* lod,
                         float out[4][16]) {
  SampleBaseLanes<4, Bytes, Srgb>(v, k, c, lod, out);
}
#if defined(SOFTGL_HAS_DISPATCH)
template <int Bytes, bool Srgb>
SOFTGL_TARGET_AVX2 void SampleBaseLanesAvx2(const TextureView& v, Lookup k, const Textures::Lanes& c, float,
                                            const float* lod, float out[4][16]) {
  SampleBaseLanes<8, Bytes, Srgb>(v, k, c, lod, out);
}
template <int Bytes, bool Srgb>
SOFTGL_TARGET_AVX512 void SampleBaseLanesAvx512(const TextureView& v, Lookup k, const Textures::Lanes& c, float,
                                                const float* lod, float out[4][16]) {
  SampleBaseLanes<16, Bytes, Srgb>(v, k, c, lod, out);
}
#endif

// The vector path for a lookup on a view: its 8-bit layout's, or the one for any layout (null for none). The 8-bit
// layouts have a second form for LINEAR magnification with LINEAR or LINEAR_MIPMAP_LINEAR minification (the usual
// states), whose level choice is shorter; lookups whose level of detail changes nothing take SampleBaseLanes.
SampleTexelLanesFn SampleTexelLanesFor(const TextureView& view, Lookup kind) {
  static const SampleTexelLanesFn by_bytes[2][4] = {
      {SOFTGL_CHOOSE(SampleTexelLanes, <1, false, false>), SOFTGL_CHOOSE(SampleTexelLanes, <2, false, false>),
       SOFTGL_CHOOSE(SampleTexelLanes, <4, false, false>), SOFTGL_CHOOSE(SampleTexelLanes, <4, true, false>)},
      {SOFTGL_CHOOSE(SampleTexelLanes, <1, false, true>), SOFTGL_CHOOSE(SampleTexelLanes, <2, false, true>),
       SOFTGL_CHOOSE(SampleTexelLanes, <4, false, true>), SOFTGL_CHOOSE(SampleTexelLanes, <4, true, true>)}};
  static const SampleTexelLanesFn any_layout = SOFTGL_CHOOSE(SampleTexelLanes, <0, false, false>);
  static const SampleTexelLanesFn base_by_bytes[5] = {
      SOFTGL_CHOOSE(SampleBaseLanes, <1, false>), SOFTGL_CHOOSE(SampleBaseLanes, <2, false>),
      SOFTGL_CHOOSE(SampleBaseLanes, <4, false>), SOFTGL_CHOOSE(SampleBaseLanes, <4, true>),
      SOFTGL_CHOOSE(SampleBaseLanes, <0, false>)};
  const SamplerParams& p = view.params;
  const bool explicit_lod =
      kind == Lookup::kLod || kind == Lookup::kArrayLod || kind == Lookup::kCubeLod || kind == Lookup::k3DLod;
  const bool shadow = kind == Lookup::kShadow || kind == Lookup::kArrayShadow;
  const bool volume = kind == Lookup::k3D || kind == Lookup::k3DLod;
  const bool anisotropic = !explicit_lod && !shadow && !volume && !view.depth && view.anisotropy > 1.0f;
  const bool base_only = !anisotropic && (p.min_filter == NEAREST || p.min_filter == LINEAR) &&
                         (p.min_filter == LINEAR) == (p.mag_filter == LINEAR);
  const bool linear =
      p.mag_filter == LINEAR && (p.min_filter == LINEAR || p.min_filter == LINEAR_MIPMAP_LINEAR);
  switch (view.layout) {
    case TexelLayout::kNone: return nullptr;
    case TexelLayout::kUnorm8x1: return base_only ? base_by_bytes[0] : by_bytes[linear][0];
    case TexelLayout::kUnorm8x2: return base_only ? base_by_bytes[1] : by_bytes[linear][1];
    case TexelLayout::kUnorm8x4:
      return base_only ? base_by_bytes[view.srgb ? 3 : 2] : by_bytes[linear][view.srgb ? 3 : 2];
    default: return base_only ? base_by_bytes[4] : any_layout;
  }
}

// Anisotropic filtering (TEXTURE_MAX_ANISOTROPY, OpenGL 4.6 section 8.14.1, as EXT_texture_filter_anisotropic
// describes it): the footprint's longer axis Pmax and shorter Pmin (texel-space lengths of the two derivatives)
// give N = min(ceil(Pmax / Pmin), the anisotropy) probes; each is an ordinary sample at lambda = log2(Pmax / N)
// (the piecewise log2 of Lambda), placed at uv + (i / (N + 1) - 1/2) times the longer derivative, i = 1 .. N, and
// their mean is the result. N = 1 is the isotropic sample. A cube map's probes lie on the face the direction chose,
// uv and the derivatives measured on it (probes past its edges wrap by the wrap modes on that face, as its samples
// do).
glm::vec4 SampleAnisotropic(const TextureView& view, glm::vec2 uv, glm::vec2 dx, glm::vec2 dy, float shader_bias,
                            int layer = 0, int face = 0) {
  const TextureLevel& base = view.texture->levels[face][view.base];
  const glm::vec2 size(float(base.width), float(base.height));
  const glm::vec2 tx = dx * size, ty = dy * size;
  const float px2 = glm::dot(tx, tx), py2 = glm::dot(ty, ty);
  const float max2 = std::max(px2, py2), min2 = std::min(px2, py2);
  const glm::vec2 major = px2 >= py2 ? dx : dy;
  const float ratio = min2 > 0.0f ? std::sqrt(max2 / min2) : view.anisotropy;  // NaN: 1 below
  const int n = ratio > 1.0f ? int(std::min(std::ceil(ratio), view.anisotropy)) : 1;
  const float lambda = LambdaOfRho2(view, max2 / float(n * n), shader_bias);
  if (n == 1) return SampleFace(view, face, uv, lambda, DepthCompare{}, layer);
  glm::vec4 sum(0.0f);
  for (int i = 1; i <= n; ++i)
    sum += SampleFace(view, face, uv + major * (float(i) / float(n + 1) - 0.5f), lambda, DepthCompare{}, layer);
  return sum / float(n);
}

glm::vec4 Sample2D(const TextureView& v, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias) {
  if (v.anisotropy > 1.0f && !v.depth) return Unscaled(v, SampleAnisotropic(v, uv, duv_dx, duv_dy, bias));
  const float lambda = Lambda(v, duv_dx, duv_dy, bias);
  if (v.fast != TextureView::Fast::kNone) return Unscaled(v, SampleRepeat(v, uv, lambda));
  return Unscaled(v, SampleFace(v, 0, uv, lambda, DepthCompare{}));
}

// Textures::SampleArray and SampleCube on a usable view.
glm::vec4 SampleArrayOf(const TextureView& v, glm::vec3 uvl, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias) {
  const int layer = ArrayLayer(v, uvl.z);
  const glm::vec2 uv(uvl);
  if (v.anisotropy > 1.0f && !v.depth) return Unscaled(v, SampleAnisotropic(v, uv, duv_dx, duv_dy, bias, layer));
  return Unscaled(v, SampleFace(v, 0, uv, Lambda(v, duv_dx, duv_dy, bias), DepthCompare{}, layer));
}
glm::vec4 SampleCubeOf(const TextureView& v, glm::vec3 dir, glm::vec3 ddir_dx, glm::vec3 ddir_dy, float bias) {
  const int face = CubeFace(dir);
  glm::vec2 st(0.5f), st_x, st_y;
  FaceCoords(face, dir, st);
  // Derivatives of (s, t) on the chosen face, projecting the neighbouring directions onto that same face (a
  // neighbour may point at another face: its coordinates must still be measured on this one).
  const glm::vec2 dx = FaceCoords(face, dir + ddir_dx, st_x) ? st_x - st : glm::vec2(0.0f);
  const glm::vec2 dy = FaceCoords(face, dir + ddir_dy, st_y) ? st_y - st : glm::vec2(0.0f);
  if (v.anisotropy > 1.0f && !v.depth) return Unscaled(v, SampleAnisotropic(v, st, dx, dy, bias, 0, face));
  return Unscaled(v, SampleFace(v, face, st, Lambda(v, dx, dy, bias), DepthCompare{}));
}
// SampleShadow on a 2D texture or one layer of a 2D array.
float ShadowOf(const TextureView* v, glm::vec2 uv, int layer_or_minus, float r, float ref, glm::vec2 duv_dx,
               glm::vec2 duv_dy) {
  if (!v || !v->depth || v->params.compare_mode != COMPARE_REF_TO_TEXTURE) return 0.0f;
  DepthCompare cmp;
  cmp.on = true;
  cmp.func = v->params.compare_func;
  cmp.ref = std::isnan(ref) ? 0.0f : std::clamp(ref, 0.0f, 1.0f);  // depth textures hold [0, 1]
  const int layer = layer_or_minus < 0 ? ArrayLayer(*v, r) : 0;
  return SampleFace(*v, 0, uv, Lambda(*v, duv_dx, duv_dy, 0.0f), cmp, layer).r;
}

// Textures::SampleLod, SampleArrayLod and SampleCubeLod on a usable view.
glm::vec4 SampleLodOf(const TextureView& v, glm::vec2 uv, float lod, int layer = 0) {
  return Unscaled(v, SampleFace(v, 0, uv, ExplicitLambda(v, lod), DepthCompare{}, layer));
}
glm::vec4 SampleCubeLodOf(const TextureView& v, glm::vec3 dir, float lod) {
  const int face = CubeFace(dir);
  glm::vec2 st(0.5f);
  FaceCoords(face, dir, st);
  return Unscaled(v, SampleFace(v, face, st, ExplicitLambda(v, lod), DepthCompare{}));
}

// Textures::Sample3D and Sample3DLod on a usable view.
glm::vec4 Sample3DOf(const TextureView& v, glm::vec3 str, glm::vec3 dstr_dx, glm::vec3 dstr_dy, float bias) {
  const auto& levels = v.texture->levels[0];
  return Unscaled(v, SampleMip(v, LambdaVolume(v, dstr_dx, dstr_dy, bias),
                               [&](int d, Enum f) { return FilterVolume(v, levels[d], f, str); }));
}
glm::vec4 Sample3DLodOf(const TextureView& v, glm::vec3 str, float lod) {
  const auto& levels = v.texture->levels[0];
  return Unscaled(v, SampleMip(v, ExplicitLambda(v, lod),
                               [&](int d, Enum f) { return FilterVolume(v, levels[d], f, str); }));
}

glm::vec4 SampleOneLane(const TextureView& v, Lookup kind, const Textures::Lanes& c, int l, float bias,
                        const float* lod) {
  const glm::vec2 dx(c.ds_dx[l], c.dt_dx[l]), dy(c.ds_dy[l], c.dt_dy[l]);
  switch (kind) {
    case Lookup::k2D: return Sample2D(v, glm::vec2(c.s[l], c.t[l]), dx, dy, bias);
    case Lookup::kLod: return SampleLodOf(v, glm::vec2(c.s[l], c.t[l]), lod[l]);
    case Lookup::kArray: return SampleArrayOf(v, glm::vec3(c.s[l], c.t[l], c.r[l]), dx, dy, bias);
    case Lookup::kArrayLod: return SampleLodOf(v, glm::vec2(c.s[l], c.t[l]), lod[l], ArrayLayer(v, c.r[l]));
    case Lookup::kCube:
      return SampleCubeOf(v, glm::vec3(c.s[l], c.t[l], c.r[l]), glm::vec3(c.ds_dx[l], c.dt_dx[l], c.dr_dx[l]),
                          glm::vec3(c.ds_dy[l], c.dt_dy[l], c.dr_dy[l]), bias);
    case Lookup::kCubeLod: return SampleCubeLodOf(v, glm::vec3(c.s[l], c.t[l], c.r[l]), lod[l]);
    case Lookup::kShadow: return glm::vec4(ShadowOf(&v, glm::vec2(c.s[l], c.t[l]), 0, 0.0f, c.r[l], dx, dy));
    case Lookup::kArrayShadow:
      return glm::vec4(ShadowOf(&v, glm::vec2(c.s[l], c.t[l]), -1, c.r[l], lod[l], dx, dy));
    case Lookup::k3D:
      return Sample3DOf(v, glm::vec3(c.s[l], c.t[l], c.r[l]), glm::vec3(c.ds_dx[l], c.dt_dx[l], c.dr_dx[l]),
                        glm::vec3(c.ds_dy[l], c.dt_dy[l], c.dr_dy[l]), bias);
    case Lookup::k3DLod: return Sample3DLodOf(v, glm::vec3(c.s[l], c.t[l], c.r[l]), lod[l]);
  }
  return kMissing;
}

// A block's lookup: on the vector path where the view allows, else lane by lane.
void SampleBlock(const TextureView* v, const glm::vec4& missing, Lookup kind, const Textures::Lanes& c, float bias,
                 const float* lod, float out[4][16]) {
  if (!v) {
    for (int l = 0; l < 16; ++l)
      for (int ch = 0; ch < 4; ++ch) out[ch][l] = missing[ch];
    return;
  }
  const bool shadow = kind == Lookup::kShadow || kind == Lookup::kArrayShadow;
  if (shadow && (!v->depth || v->params.compare_mode != COMPARE_REF_TO_TEXTURE)) {
    for (int l = 0; l < 16; ++l)
      for (int ch = 0; ch < 4; ++ch) out[ch][l] = 0.0f;
    return;
  }
  if (v->wide) {
    if (const SampleTexelLanesFn sample = SampleTexelLanesFor(*v, kind)) return sample(*v, kind, c, bias, lod, out);
  }
  for (int l = 0; l < 16; ++l) {
    const glm::vec4 r = SampleOneLane(*v, kind, c, l, bias, lod);
    for (int ch = 0; ch < 4; ++ch) out[ch][l] = r[ch];
  }
}

}  // namespace

glm::vec4 Textures::Sample(int unit, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias) const {
  const TextureView* v = Usable(unit_2d, unit);
  return v ? Sample2D(*v, uv, duv_dx, duv_dy, bias) : MissingFor(unit_2d, unit);
}

void Textures::SampleQuad(int unit, const glm::vec2 uv[4], const glm::vec2 duv_dx[4], const glm::vec2 duv_dy[4],
                          float bias, glm::vec4 out[4]) const {
  for (int l = 0; l < 4; ++l) out[l] = Sample(unit, uv[l], duv_dx[l], duv_dy[l], bias);
}

void Textures::SampleLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_2d, unit), MissingFor(unit_2d, unit), Lookup::k2D, c, bias, nullptr, out);
}

glm::vec4 Textures::SampleLod(int unit, glm::vec2 uv, float lod) const {
  const TextureView* v = Usable(unit_2d, unit);
  return v ? SampleLodOf(*v, uv, lod) : MissingFor(unit_2d, unit);
}

void Textures::SampleLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_2d, unit), MissingFor(unit_2d, unit), Lookup::kLod, c, 0.0f, lod, out);
}

glm::vec4 Textures::SampleCube(int unit, glm::vec3 dir, glm::vec3 ddir_dx, glm::vec3 ddir_dy, float bias) const {
  const TextureView* v = Usable(unit_cube, unit);
  return v ? SampleCubeOf(*v, dir, ddir_dx, ddir_dy, bias) : MissingFor(unit_cube, unit);
}

void Textures::SampleCubeLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_cube, unit), MissingFor(unit_cube, unit), Lookup::kCube, c, bias, nullptr, out);
}

glm::vec4 Textures::SampleCubeLod(int unit, glm::vec3 dir, float lod) const {
  const TextureView* v = Usable(unit_cube, unit);
  return v ? SampleCubeLodOf(*v, dir, lod) : MissingFor(unit_cube, unit);
}

void Textures::SampleCubeLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_cube, unit), MissingFor(unit_cube, unit), Lookup::kCubeLod, c, 0.0f, lod, out);
}


float Textures::SampleShadow(int unit, glm::vec2 uv, float ref, glm::vec2 duv_dx, glm::vec2 duv_dy) const {
  return ShadowOf(Usable(unit_2d, unit), uv, 0, 0.0f, ref, duv_dx, duv_dy);
}

void Textures::SampleShadowLanes(int unit, const Lanes& c, float out[16]) const {
  float all[4][16];
  SampleBlock(Usable(unit_2d, unit), MissingFor(unit_2d, unit), Lookup::kShadow, c, 0.0f, nullptr, all);
  std::memcpy(out, all[0], sizeof all[0]);
}

glm::vec4 Textures::SampleArray(int unit, glm::vec3 uvl, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias) const {
  const TextureView* v = Usable(unit_2d_array, unit);
  return v ? SampleArrayOf(*v, uvl, duv_dx, duv_dy, bias) : MissingFor(unit_2d_array, unit);
}

glm::vec4 Textures::SampleArrayLod(int unit, glm::vec3 uvl, float lod) const {
  const TextureView* v = Usable(unit_2d_array, unit);
  return v ? SampleLodOf(*v, glm::vec2(uvl), lod, ArrayLayer(*v, uvl.z)) : MissingFor(unit_2d_array, unit);
}

float Textures::SampleArrayShadow(int unit, glm::vec3 uvl, float ref, glm::vec2 duv_dx, glm::vec2 duv_dy) const {
  return ShadowOf(Usable(unit_2d_array, unit), glm::vec2(uvl), -1, uvl.z, ref, duv_dx, duv_dy);
}

glm::vec4 Textures::Sample3D(int unit, glm::vec3 str, glm::vec3 dstr_dx, glm::vec3 dstr_dy, float bias) const {
  const TextureView* v = Usable(unit_3d, unit);
  return v ? Sample3DOf(*v, str, dstr_dx, dstr_dy, bias) : MissingFor(unit_3d, unit);
}

glm::vec4 Textures::Sample3DLod(int unit, glm::vec3 str, float lod) const {
  const TextureView* v = Usable(unit_3d, unit);
  return v ? Sample3DLodOf(*v, str, lod) : MissingFor(unit_3d, unit);
}


void Textures::SampleArrayLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_2d_array, unit), MissingFor(unit_2d_array, unit), Lookup::kArray, c, bias, nullptr, out);
}

void Textures::SampleArrayLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_2d_array, unit), MissingFor(unit_2d_array, unit), Lookup::kArrayLod, c, 0.0f, lod, out);
}

void Textures::SampleArrayShadowLanes(int unit, const Lanes& c, const float ref[16], float out[16]) const {
  float all[4][16];
  SampleBlock(Usable(unit_2d_array, unit), MissingFor(unit_2d_array, unit), Lookup::kArrayShadow, c, 0.0f, ref, all);
  std::memcpy(out, all[0], sizeof all[0]);
}

void Textures::Sample3DLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_3d, unit), MissingFor(unit_3d, unit), Lookup::k3D, c, bias, nullptr, out);
}

void Textures::Sample3DLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_3d, unit), MissingFor(unit_3d, unit), Lookup::k3DLod, c, 0.0f, lod, out);
}

// 1D textures: as 2D ones one texel high, sampled at t = 1/2 with t's derivatives 0 (the view clamps in t).
glm::vec4 Textures::Sample1D(int unit, float s, float ds_dx, float ds_dy, float bias) const {
  const TextureView* v = Usable(unit_1d, unit);
  return v ? Sample2D(*v, glm::vec2(s, 0.5f), glm::vec2(ds_dx, 0.0f), glm::vec2(ds_dy, 0.0f), bias) : MissingFor(unit_1d, unit);
}

glm::vec4 Textures::Sample1DLod(int unit, float s, float lod) const {
  const TextureView* v = Usable(unit_1d, unit);
  return v ? SampleLodOf(*v, glm::vec2(s, 0.5f), lod) : MissingFor(unit_1d, unit);
}

glm::vec4 Textures::Sample1DArray(int unit, glm::vec2 sl, float ds_dx, float ds_dy, float bias) const {
  const TextureView* v = Usable(unit_1d_array, unit);
  return v ? SampleArrayOf(*v, glm::vec3(sl.x, 0.5f, sl.y), glm::vec2(ds_dx, 0.0f), glm::vec2(ds_dy, 0.0f), bias)
           : MissingFor(unit_1d_array, unit);
}

glm::vec4 Textures::Sample1DArrayLod(int unit, glm::vec2 sl, float lod) const {
  const TextureView* v = Usable(unit_1d_array, unit);
  return v ? SampleLodOf(*v, glm::vec2(sl.x, 0.5f), lod, ArrayLayer(*v, sl.y)) : MissingFor(unit_1d_array, unit);
}

namespace {
// The lanes of a 1D lookup as the 2D (or 2D array) lookup takes them: t = 1/2 (or the layer moved from t to r),
// t's derivatives 0.
Textures::Lanes OneDimensional(const Textures::Lanes& c, bool array) {
  Textures::Lanes d = c;
  for (int l = 0; l < 16; ++l) {
    d.r[l] = array ? c.t[l] : 0.0f;
    d.t[l] = 0.5f;
    d.dt_dx[l] = d.dt_dy[l] = 0.0f;
  }
  return d;
}
}  // namespace

void Textures::Sample1DLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_1d, unit), MissingFor(unit_1d, unit), Lookup::k2D, OneDimensional(c, false), bias, nullptr, out);
}

void Textures::Sample1DLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_1d, unit), MissingFor(unit_1d, unit), Lookup::kLod, OneDimensional(c, false), 0.0f, lod, out);
}

void Textures::Sample1DArrayLanes(int unit, const Lanes& c, float bias, float out[4][16]) const {
  SampleBlock(Usable(unit_1d_array, unit), MissingFor(unit_1d_array, unit), Lookup::kArray, OneDimensional(c, true), bias, nullptr, out);
}

void Textures::Sample1DArrayLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const {
  SampleBlock(Usable(unit_1d_array, unit), MissingFor(unit_1d_array, unit), Lookup::kArrayLod, OneDimensional(c, true), 0.0f, lod, out);
}

namespace {
// Width, height and layers (or slices) of a level of the view's texture; zero where there is none.
glm::ivec3 LevelSize(const TextureView* v, int level) {
  if (!v || level < 0 || v->base + level >= detail::kMaxLevels) return glm::ivec3(0);
  const TextureLevel& lv = v->texture->levels[0][v->base + level];
  return lv.Defined() ? glm::ivec3(lv.width, lv.height, lv.depth) : glm::ivec3(0);
}
}  // namespace

glm::ivec3 Textures::SizeArray(int unit, int level) const {
  return unit < 0 || unit >= kMaxTextureUnits ? glm::ivec3(0) : LevelSize(unit_2d_array[unit], level);
}

glm::ivec3 Textures::Size3D(int unit, int level) const {
  return unit < 0 || unit >= kMaxTextureUnits ? glm::ivec3(0) : LevelSize(unit_3d[unit], level);
}

int Textures::Size1D(int unit, int level) const {
  return unit < 0 || unit >= kMaxTextureUnits ? 0 : LevelSize(unit_1d[unit], level).x;
}

glm::ivec2 Textures::Size1DArray(int unit, int level) const {
  if (unit < 0 || unit >= kMaxTextureUnits) return glm::ivec2(0);
  const glm::ivec3 s = LevelSize(unit_1d_array[unit], level);
  return glm::ivec2(s.x, s.z);
}

namespace {
// Texel (x, y) of plane `plane` of a level, as sampling reads it (an sRGB colour decoded), divided by the scale;
// zero outside it.
glm::vec4 TexelOf(const TextureView& v, const TextureLevel& lv, glm::ivec2 p, int plane, int planes) {
  if (!lv.Defined() || p.x < 0 || p.y < 0 || p.x >= lv.width || p.y >= lv.height || plane < 0 || plane >= planes)
    return glm::vec4(0.0f);
  return Unscaled(v, lv.Sampled(p.x, plane * lv.height + p.y));
}

// ---- texelFetch for a block of lanes ------------------------------------------------------------------------------
//
// TexelOf for W lanes at a time: each lane's texel (x, y) of plane `which` (a multisample texture's sample) of level
// base + `which` (a 2D texture's level), 0 outside; lanes on one level go together (usually all), their texels read
// in vector form (GatherTexels; an 8-bit layout's with one load a lane), in the format's units divided by its scale.
template <int W>
SOFTGL_INLINE void FetchTexelLanes(const TextureView& v, bool multisample, const int* xs, const int* ys,
                                   const int* which, float out[4][16]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  const auto& levels = v.texture->levels[0];
  for (int l0 = 0; l0 < 16; l0 += W) {
    const I x = detail::LoadVec<I>(xs + l0), y = detail::LoadVec<I>(ys + l0), k = detail::LoadVec<I>(which + l0);
    // The level each lane reads (base + level, or 0), -1 where there is none.
    I level = multisample ? I{} : I(U(k) + unsigned(v.base));  // (unsigned: k may be anything)
    level = U(k) < unsigned(multisample ? 0x7FFFFFFF : detail::kMaxLevels - v.base) ? level : I{} - 1;
    F r[4] = {};
    I pending = level >= 0;
    for (std::uint32_t bits = detail::MaskToBits<W>(pending, 0); bits != 0; bits = detail::MaskToBits<W>(pending, 0)) {
      const int L = level[__builtin_ctz(bits)];
      const I on_level = pending & (level == L);
      pending &= ~on_level;
      const TextureLevel& lv = levels[L];
      if (!lv.Defined()) continue;
      const int planes = multisample ? lv.samples * lv.depth : 1;  // (a multisample array's: layer * samples + sample)
      const I plane = multisample ? k : I{};
      // Inside: 0 <= x < width, 0 <= y < height, 0 <= plane < planes (unsigned comparisons, as bits).
      const std::uint32_t inside = detail::MaskToBits<W>(on_level, 0) &
                                   detail::MaskToBits<W>(U(x) < unsigned(lv.width), 0) &
                                   detail::MaskToBits<W>(U(y) < unsigned(lv.height), 0) &
                                   detail::MaskToBits<W>(U(plane) < unsigned(planes), 0);
      const I in = detail::BitsToMask<W>(inside, 0);
      // (In unsigned arithmetic: lanes outside may overflow, and read texel 0.)
      const I index = I(((U(plane) * unsigned(lv.height) + U(y)) * unsigned(lv.width) + U(x)) & U(in));
      F t[4];
      switch (lv.layout) {
        case TexelLayout::kUnorm8x4: {
          const U word = __builtin_convertvector(
              LoadPairs<W>(lv.data.data(), index * 4, std::make_index_sequence<W>()), U);
          if (lv.srgb) Channels<W, 4, true>(word, t);
          else Channels<W, 4, false>(word, t);
          break;
        }
        case TexelLayout::kUnorm8x2:
        case TexelLayout::kUnorm8x1: {
          const int bytes = lv.layout == TexelLayout::kUnorm8x2 ? 2 : 1;
          const U word = __builtin_convertvector(
              LoadPairs<W>(lv.data.data(), index * bytes, std::make_index_sequence<W>()), U);
          if (bytes == 2) Channels<W, 2, false>(word, t);
          else Channels<W, 1, false>(word, t);
          break;
        }
        default: GatherTexels<W, false>(lv, index, in, t); break;
      }
      for (int c = 0; c < 4; ++c) r[c] = in != 0 ? (v.integer ? t[c] : t[c] / v.scale) : r[c];  // (bits kept)
    }
    for (int c = 0; c < 4; ++c) std::memcpy(&out[c][l0], &r[c], sizeof r[c]);
  }
}

void FetchTexelLanesBase(const TextureView& v, bool ms, const int* x, const int* y, const int* k, float out[4][16]) {
  FetchTexelLanes<4>(v, ms, x, y, k, out);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void FetchTexelLanesAvx2(const TextureView& v, bool ms, const int* x, const int* y, const int* k,
                                            float out[4][16]) {
  FetchTexelLanes<8>(v, ms, x, y, k, out);
}
SOFTGL_TARGET_AVX512 void FetchTexelLanesAvx512(const TextureView& v, bool ms, const int* x, const int* y,
                                                const int* k, float out[4][16]) {
  FetchTexelLanes<16>(v, ms, x, y, k, out);
}
#endif
using FetchTexelLanesFn = void (*)(const TextureView&, bool, const int*, const int*, const int*, float[4][16]);

void FetchBlock(const TextureView* v, bool multisample, const int* x, const int* y, const int* k, float out[4][16]) {
  if (!v) {
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < 16; ++l) out[c][l] = 0.0f;
    return;
  }
  static const FetchTexelLanesFn fetch = SOFTGL_CHOOSE(FetchTexelLanes, );
  fetch(*v, multisample, x, y, k, out);
}
}  // namespace

glm::vec4 Textures::Fetch(int unit, glm::ivec2 texel, int level) const {
  const TextureView* v = Usable(unit_2d, unit);
  if (!v || level < 0 || v->base + level >= detail::kMaxLevels) return glm::vec4(0.0f);
  return TexelOf(*v, v->texture->levels[0][v->base + level], texel, 0, 1);
}

glm::vec4 Textures::FetchSample(int unit, glm::ivec2 texel, int sample) const {
  const TextureView* v = Usable(unit_2d_ms, unit);
  if (!v) return glm::vec4(0.0f);
  const TextureLevel& lv = v->texture->levels[0][0];
  return TexelOf(*v, lv, texel, sample, lv.samples);
}

glm::ivec2 Textures::SizeMultisample(int unit) const {
  const TextureView* v = Usable(unit_2d_ms, unit);
  return v ? glm::ivec2(v->texture->levels[0][0].width, v->texture->levels[0][0].height) : glm::ivec2(0);
}

int Textures::Samples(int unit) const {
  const TextureView* v = Usable(unit_2d_ms, unit);
  return v ? v->texture->levels[0][0].samples : 0;
}

void Textures::FetchLanes(int unit, const int x[16], const int y[16], const int level[16], float out[4][16]) const {
  FetchBlock(Usable(unit_2d, unit), false, x, y, level, out);
}

void Textures::FetchSampleLanes(int unit, const int x[16], const int y[16], const int sample[16],
                                float out[4][16]) const {
  FetchBlock(Usable(unit_2d_ms, unit), true, x, y, sample, out);
}

glm::vec4 Textures::FetchSampleArray(int unit, glm::ivec3 texel_layer, int sample) const {
  const TextureView* v = Usable(unit_2d_ms_array, unit);
  if (!v) return glm::vec4(0.0f);
  const TextureLevel& lv = v->texture->levels[0][0];
  const int layer = texel_layer.z;
  if (layer < 0 || layer >= lv.depth || sample < 0 || sample >= lv.samples) return glm::vec4(0.0f);
  return TexelOf(*v, lv, glm::ivec2(texel_layer), layer * lv.samples + sample, lv.samples * lv.depth);
}

glm::ivec3 Textures::SizeMultisampleArray(int unit) const {
  const TextureView* v = Usable(unit_2d_ms_array, unit);
  if (!v) return glm::ivec3(0);
  const TextureLevel& lv = v->texture->levels[0][0];
  return glm::ivec3(lv.width, lv.height, lv.depth);
}

int Textures::SamplesArray(int unit) const {
  const TextureView* v = Usable(unit_2d_ms_array, unit);
  return v ? v->texture->levels[0][0].samples : 0;
}

void Textures::FetchSampleArrayLanes(int unit, const int x[16], const int y[16], const int layer[16],
                                     const int sample[16], float out[4][16]) const {
  // Each lane's plane, layer * samples + sample (-1 where either is outside: zero), fetched as a multisample
  // texture's sample.
  const TextureView* v = Usable(unit_2d_ms_array, unit);
  const int layers = v ? v->texture->levels[0][0].depth : 0, samples = v ? v->texture->levels[0][0].samples : 0;
  alignas(64) int plane[16];
  for (int l = 0; l < 16; ++l)
    plane[l] = layer[l] >= 0 && layer[l] < layers && sample[l] >= 0 && sample[l] < samples ? layer[l] * samples + sample[l]
                                                                                         : -1;
  FetchBlock(v, true, x, y, plane, out);
}

namespace {
constexpr std::uint8_t kZeroTexel[16] = {};
// Texel `index` of a buffer texture's store, divided by the scale: a texel of zero bytes outside the store.
glm::vec4 BufferTexel(const TextureView& v, int index) {
  const bool inside = index >= 0 && index < v.buffer_texels;
  return Unscaled(v, RawTexel(v.layout, inside ? v.buffer + std::size_t(index) * std::size_t(BytesPerTexel(v.layout))
                                               : kZeroTexel));
}
}  // namespace

glm::vec4 Textures::FetchBuffer(int unit, int index) const {
  const TextureView* v = Usable(unit_buffer, unit);
  return v ? BufferTexel(*v, index) : glm::vec4(0.0f);
}

int Textures::SizeBuffer(int unit) const {
  const TextureView* v = Usable(unit_buffer, unit);
  return v ? v->buffer_texels : 0;
}

namespace {
// ---- Buffer textures' texels for a block of lanes -----------------------------------------------------------------
//
// BufferTexel for W lanes at a time: no filtering, no wrapping, a texel of zero bytes outside the store. The texels are read in
// vector form (GatherTexels; an 8-bit layout's with one load a lane) where a lane's read stays inside the store (a
// 64-bit read at each texel of under 8 bytes: the store has no padding, so its last few texels), the rest one lane
// at a time (BufferTexel).
template <int W>
SOFTGL_INLINE void FetchBufferTexelLanes(const TextureView& v, const int* indices, float out[4][16]) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  const int bytes = BytesPerTexel(v.layout);
  // The texels whose read stays inside: those of 8 or 16 bytes all, else up to the last 8 bytes' first texel.
  const int safe = bytes == 8 || bytes == 16                  ? v.buffer_texels
                   : (bytes == 1 || bytes == 2 || bytes == 4) ? std::max(0, v.buffer_texels - 8 / bytes + 1)
                                                              : 0;
  const std::uint8_t* data = v.buffer;
  const glm::vec4 zero = Unscaled(v, RawTexel(v.layout, kZeroTexel));
  F outside[4];
  for (int c = 0; c < 4; ++c) outside[c] = SplatBits<W>(zero[c]);
  for (int l0 = 0; l0 < 16; l0 += W) {
    const I index = detail::LoadVec<I>(indices + l0);
    const I in = U(index) < unsigned(safe);
    const std::uint32_t in_bits = detail::MaskToBits<W>(in, 0);
    F t[4] = {};
    if (in_bits != 0) {
      const I at = index & in;  // (lanes outside read texel 0, inside when safe > 0)
      switch (v.layout) {
        case TexelLayout::kUnorm8x4:
          Channels<W, 4, false>(__builtin_convertvector(LoadPairs<W>(data, at * 4, std::make_index_sequence<W>()), U), t);
          break;
        case TexelLayout::kUnorm8x2:
          Channels<W, 2, false>(__builtin_convertvector(LoadPairs<W>(data, at * 2, std::make_index_sequence<W>()), U), t);
          break;
        case TexelLayout::kUnorm8x1:
          Channels<W, 1, false>(__builtin_convertvector(LoadPairs<W>(data, at, std::make_index_sequence<W>()), U), t);
          break;
        default: GatherTexels<W, false>(data, v.layout, bytes, at, in, t); break;
      }
    }
    for (int c = 0; c < 4; ++c) {
      const F r = in != 0 ? (v.integer ? t[c] : t[c] / v.scale) : outside[c];  // (bits kept)
      std::memcpy(&out[c][l0], &r, sizeof r);
    }
    // The lanes inside the store past `safe`: one at a time.
    for (std::uint32_t rest = ~in_bits & ((1u << W) - 1); rest != 0; rest &= rest - 1) {
      const int lane = l0 + __builtin_ctz(rest);
      if (indices[lane] < safe || indices[lane] >= v.buffer_texels) continue;  // (outside: the zero texel, as set)
      const glm::vec4 r = BufferTexel(v, indices[lane]);
      for (int c = 0; c < 4; ++c) out[c][lane] = r[c];
    }
  }
}

void FetchBufferTexelLanesBase(const TextureView& v, const int* index, float out[4][16]) {
  FetchBufferTexelLanes<4>(v, index, out);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void FetchBufferTexelLanesAvx2(const TextureView& v, const int* index, float out[4][16]) {
  FetchBufferTexelLanes<8>(v, index, out);
}
SOFTGL_TARGET_AVX512 void FetchBufferTexelLanesAvx512(const TextureView& v, const int* index, float out[4][16]) {
  FetchBufferTexelLanes<16>(v, index, out);
}
#endif
}  // namespace

void Textures::FetchBufferLanes(int unit, const int index[16], float out[4][16]) const {
  const TextureView* v = Usable(unit_buffer, unit);
  if (!v) {
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < 16; ++l) out[c][l] = 0.0f;
    return;
  }
  static const auto fetch = SOFTGL_CHOOSE(FetchBufferTexelLanes, );
  fetch(*v, index, out);
}

glm::ivec2 Textures::Size(int unit, int level) const {
  if (unit < 0 || unit >= kMaxTextureUnits || !unit_2d[unit]) return glm::ivec2(0);
  const TextureView& v = *unit_2d[unit];
  const int l = v.base + level;
  if (level < 0 || l >= detail::kMaxLevels) return glm::ivec2(0);
  const TextureLevel& lv = v.texture->levels[0][l];
  return glm::ivec2(lv.width, lv.height);
}

}  // namespace softgl

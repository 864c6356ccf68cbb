// texture_sampler.cpp — texture sampling for the shader stages: level of detail, mipmap selection, NEAREST and
// LINEAR filtering, wrap modes, cube map faces and depth comparison (OpenGL 4.6, sections 8.13 to 8.14, 8.22).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <softgl/texture.h>

#include "fragment_ops.h"
#include "simd.h"
#include "texture.h"

namespace softgl {

namespace {

// The sampling path is inlined into each entry point, so that each is compiled for its own case (depth comparison
// or not, a constant face).
#if defined(__GNUC__)
#define SOFTGL_INLINE inline __attribute__((always_inline))
#else
#define SOFTGL_INLINE inline
#endif

using detail::SamplerParams;
using detail::TextureLevel;
using detail::TextureView;

const glm::vec4 kMissing(0.0f, 0.0f, 0.0f, 1.0f);  // what an incomplete or missing texture samples as

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

glm::vec4 Fetch(const SamplerParams& p, const TextureLevel& level, long i, long j, const DepthCompare& cmp) {
  const int wi = Wrap(p.wrap_s, i, level.width), wj = Wrap(p.wrap_t, j, level.height);
  glm::vec4 t = p.border;
  if (wi >= 0 && wj >= 0) {
    const float* texel = level.At(wi, wj);
    t = glm::vec4(texel[0], texel[1], texel[2], texel[3]);
  }
  if (cmp.on) return glm::vec4(detail::Compare(cmp.func, cmp.ref, t.r) ? 1.0f : 0.0f);
  return t;
}

// LINEAR on one level without depth comparison: each of the two wrapped columns and rows is computed once, and
// the weighted sum is taken four channels at a time, with the same operations in the same order as the generic
// path below.
SOFTGL_INLINE glm::vec4 Bilinear(const SamplerParams& p, const TextureLevel& level, float u, float v) {
  const float fu = u - 0.5f, fv = v - 0.5f;
  const long i0 = long(std::floor(fu)), j0 = long(std::floor(fv));
  const float a = fu - float(i0), b = fv - float(j0);
  const int wi[2] = {Wrap(p.wrap_s, i0, level.width), Wrap(p.wrap_s, i0 + 1, level.width)};
  const int wj[2] = {Wrap(p.wrap_t, j0, level.height), Wrap(p.wrap_t, j0 + 1, level.height)};
  const float* t[4];
  for (int k = 0; k < 4; ++k) {
    const int i = wi[k & 1], j = wj[k >> 1];
    t[k] = (i >= 0 && j >= 0) ? level.At(i, j) : &p.border.x;
  }
  const float w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
#if defined(__SSE2__)
  __m128 sum = _mm_mul_ps(_mm_set1_ps(w00), _mm_loadu_ps(t[0]));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w10), _mm_loadu_ps(t[1])));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w01), _mm_loadu_ps(t[2])));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w11), _mm_loadu_ps(t[3])));
  glm::vec4 out;
  _mm_storeu_ps(&out.x, sum);
  return out;
#else
  auto texel = [](const float* x) { return glm::vec4(x[0], x[1], x[2], x[3]); };
  return w00 * texel(t[0]) + w10 * texel(t[1]) + w01 * texel(t[2]) + w11 * texel(t[3]);
#endif
}

// Bilinear() for REPEAT on a power-of-two level: the same arithmetic, the wrap a mask, no border texel.
SOFTGL_INLINE glm::vec4 BilinearRepeatPow2(const TextureLevel& level, glm::vec2 st) {
  const float u = TexelCoord(st.x, level.width), v = TexelCoord(st.y, level.height);
  const float fu = u - 0.5f, fv = v - 0.5f;
  const long i0 = long(std::floor(fu)), j0 = long(std::floor(fv));
  const float a = fu - float(i0), b = fv - float(j0);
  const long mi = level.width - 1, mj = level.height - 1;
  const std::size_t c0 = std::size_t(i0 & mi), c1 = std::size_t((i0 + 1) & mi);
  const float* row0 = level.texels.data() + std::size_t(j0 & mj) * std::size_t(level.width) * 4;
  const float* row1 = level.texels.data() + std::size_t((j0 + 1) & mj) * std::size_t(level.width) * 4;
  const float w00 = (1 - a) * (1 - b), w10 = a * (1 - b), w01 = (1 - a) * b, w11 = a * b;
#if defined(__SSE2__)
  __m128 sum = _mm_mul_ps(_mm_set1_ps(w00), _mm_loadu_ps(row0 + c0 * 4));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w10), _mm_loadu_ps(row0 + c1 * 4)));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w01), _mm_loadu_ps(row1 + c0 * 4)));
  sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w11), _mm_loadu_ps(row1 + c1 * 4)));
  glm::vec4 out;
  _mm_storeu_ps(&out.x, sum);
  return out;
#else
  auto texel = [](const float* x) { return glm::vec4(x[0], x[1], x[2], x[3]); };
  return w00 * texel(row0 + c0 * 4) + w10 * texel(row0 + c1 * 4) + w01 * texel(row1 + c0 * 4) +
         w11 * texel(row1 + c1 * 4);
#endif
}

// SampleFace() for a view whose `fast` is set: the same decisions, taken knowing the filters.
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

// One level, NEAREST or LINEAR (section 8.14.2): texel centres at +0.5.
SOFTGL_INLINE glm::vec4 FilterLevel(const SamplerParams& p, const TextureLevel& level, Enum filter, glm::vec2 st,
                      const DepthCompare& cmp) {
  const float u = TexelCoord(st.x, level.width), v = TexelCoord(st.y, level.height);
  if (filter == NEAREST) return Fetch(p, level, long(std::floor(u)), long(std::floor(v)), cmp);
  if (!cmp.on) return Bilinear(p, level, u, v);
  const float fu = u - 0.5f, fv = v - 0.5f;
  const long i0 = long(std::floor(fu)), j0 = long(std::floor(fv));
  const float a = fu - float(i0), b = fv - float(j0);
  return (1 - a) * (1 - b) * Fetch(p, level, i0, j0, cmp) + a * (1 - b) * Fetch(p, level, i0 + 1, j0, cmp) +
         (1 - a) * b * Fetch(p, level, i0, j0 + 1, cmp) + a * b * Fetch(p, level, i0 + 1, j0 + 1, cmp);
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
SOFTGL_INLINE float Lambda(const TextureView& view, glm::vec2 dx, glm::vec2 dy, float shader_bias) {
  const TextureLevel& base = view.texture->levels[0][view.base];
  const glm::vec2 size(float(base.width), float(base.height));
  const glm::vec2 tx = dx * size, ty = dy * size;
  const float rho2 = std::max(glm::dot(tx, tx), glm::dot(ty, ty));
  const SamplerParams& p = view.texture->params;
  const float bias = std::clamp(p.lod_bias + shader_bias, -16.0f, 16.0f);
  float lambda = 0.5f * PiecewiseLog2(rho2) + bias;
  if (std::isnan(lambda)) lambda = 0.0f;
  return std::clamp(lambda, p.min_lod, p.max_lod);
}

// Minification or magnification at level of detail lambda, on one face (section 8.14.2 to 8.14.3).
SOFTGL_INLINE glm::vec4 SampleFace(const TextureView& view, int face, glm::vec2 st, float lambda, const DepthCompare& cmp) {
  const SamplerParams& p = view.texture->params;
  const auto& levels = view.texture->levels[face];
  const bool nearest_mip = p.min_filter == NEAREST_MIPMAP_NEAREST || p.min_filter == LINEAR_MIPMAP_NEAREST;
  const float c = (p.mag_filter == LINEAR && nearest_mip) ? 0.5f : 0.0f;
  if (lambda <= c) return FilterLevel(p, levels[view.base], p.mag_filter, st, cmp);
  const Enum filter = (p.min_filter == LINEAR || p.min_filter == LINEAR_MIPMAP_NEAREST ||
                       p.min_filter == LINEAR_MIPMAP_LINEAR)
                          ? LINEAR
                          : NEAREST;
  switch (p.min_filter) {
    case NEAREST:
    case LINEAR: return FilterLevel(p, levels[view.base], filter, st, cmp);
    case NEAREST_MIPMAP_NEAREST:
    case LINEAR_MIPMAP_NEAREST: {
      const int d = lambda <= 0.5f ? view.base
                                   : int(std::min<float>(float(view.base) + std::ceil(lambda + 0.5f) - 1.0f,
                                                         float(view.q)));
      return FilterLevel(p, levels[d], filter, st, cmp);
    }
    default: {  // *_MIPMAP_LINEAR
      if (float(view.base) + lambda >= float(view.q)) return FilterLevel(p, levels[view.q], filter, st, cmp);
      const float fl = std::floor(lambda);
      const int d1 = view.base + int(fl);
      const float f = lambda - fl;
      return (1.0f - f) * FilterLevel(p, levels[d1], filter, st, cmp) +
             f * FilterLevel(p, levels[d1 + 1], filter, st, cmp);
    }
  }
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

}  // namespace

namespace {

// The common 2D case, compiled twice: for the baseline processor, and for processors with AVX2 and SSE4.1 (which
// round to an integer in one instruction), chosen once at run time. The arithmetic is the same operations, so the
// results are the same (no FMA: it would round differently).
glm::vec4 SampleRepeatBaseline(const TextureView& v, glm::vec2 uv, glm::vec2 dx, glm::vec2 dy, float bias) {
  return SampleRepeat(v, uv, Lambda(v, dx, dy, bias));
}

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
__attribute__((target("avx2,sse4.1"))) glm::vec4 SampleRepeatAvx2(const TextureView& v, glm::vec2 uv, glm::vec2 dx,
                                                                  glm::vec2 dy, float bias) {
  return SampleRepeat(v, uv, Lambda(v, dx, dy, bias));
}
#endif

// Four lanes of a quad on the common 2D path. The baseline loops over the lanes; the AVX2 version computes the
// level of detail, the level choice and the texel coordinates and weights of the four lanes side by side, with
// each lane's operations those of the one-lane path in the same order, then fetches and weights each lane's texels
// as BilinearRepeatPow2 does. Lanes whose rho^2 is not a normal positive float take the one-lane path.
void SampleRepeatQuadBaseline(const TextureView& v, const glm::vec2* uv, const glm::vec2* dx, const glm::vec2* dy,
                              float bias, glm::vec4* out) {
  for (int l = 0; l < 4; ++l) out[l] = SampleRepeat(v, uv[l], Lambda(v, dx[l], dy[l], bias));
}

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
__attribute__((target("avx2,sse4.1"))) void SampleRepeatQuadAvx2(const TextureView& v, const glm::vec2* uv,
                                                                 const glm::vec2* dx, const glm::vec2* dy,
                                                                 float bias, glm::vec4* out) {
  const auto& levels = v.texture->levels[0];
  const SamplerParams& p = v.texture->params;
  const TextureLevel& base = levels[v.base];
  const __m128 one = _mm_set1_ps(1.0f);
  // Lambda(): tx = dx * size, ty = dy * size, rho^2 = max(dot(tx, tx), dot(ty, ty)).
  const __m128 W = _mm_set1_ps(float(base.width)), H = _mm_set1_ps(float(base.height));
  const __m128 txx = _mm_mul_ps(_mm_setr_ps(dx[0].x, dx[1].x, dx[2].x, dx[3].x), W);
  const __m128 txy = _mm_mul_ps(_mm_setr_ps(dx[0].y, dx[1].y, dx[2].y, dx[3].y), H);
  const __m128 tyx = _mm_mul_ps(_mm_setr_ps(dy[0].x, dy[1].x, dy[2].x, dy[3].x), W);
  const __m128 tyy = _mm_mul_ps(_mm_setr_ps(dy[0].y, dy[1].y, dy[2].y, dy[3].y), H);
  const __m128 dot_x = _mm_add_ps(_mm_mul_ps(txx, txx), _mm_mul_ps(txy, txy));
  const __m128 dot_y = _mm_add_ps(_mm_mul_ps(tyx, tyx), _mm_mul_ps(tyy, tyy));
  const __m128 rho2 = _mm_max_ps(dot_y, dot_x);  // std::max(dot_x, dot_y): dot_y if dot_x < dot_y, else dot_x
  // PiecewiseLog2 for normal positive numbers: exponent + (1.mantissa - 1).
  const __m128i bits = _mm_castps_si128(rho2);
  const __m128i biased = _mm_srli_epi32(bits, 23);  // includes the sign bit: negative numbers are out of range
  const __m128i normal = _mm_and_si128(_mm_cmpgt_epi32(biased, _mm_setzero_si128()),
                                       _mm_cmplt_epi32(biased, _mm_set1_epi32(255)));
  if (_mm_movemask_ps(_mm_castsi128_ps(normal)) != 0xF) return SampleRepeatQuadBaseline(v, uv, dx, dy, bias, out);
  const __m128 m = _mm_castsi128_ps(
      _mm_or_si128(_mm_and_si128(bits, _mm_set1_epi32(0x007FFFFF)), _mm_set1_epi32(0x3F800000)));
  const __m128 log2 = _mm_add_ps(_mm_cvtepi32_ps(_mm_sub_epi32(biased, _mm_set1_epi32(127))), _mm_sub_ps(m, one));
  const float b = std::clamp(p.lod_bias + bias, -16.0f, 16.0f);
  __m128 lambda = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(0.5f), log2), _mm_set1_ps(b));
  lambda = _mm_and_ps(lambda, _mm_cmpord_ps(lambda, lambda));  // NaN -> 0
  {  // std::clamp(lambda, min_lod, max_lod): lo if lambda < lo, else hi if hi < lambda, else lambda
    const __m128 lo = _mm_set1_ps(p.min_lod), hi = _mm_set1_ps(p.max_lod);
    __m128 r = _mm_blendv_ps(lambda, hi, _mm_cmplt_ps(hi, lambda));
    lambda = _mm_blendv_ps(r, lo, _mm_cmplt_ps(lambda, lo));
  }
  // SampleRepeat(): the level (or the two levels and the weight between them) of each lane.
  alignas(16) float lam[4];
  _mm_store_ps(lam, lambda);
  int level_a[4], level_b[4];
  float f[4];
  bool two[4];
  for (int l = 0; l < 4; ++l) {
    two[l] = false;
    f[l] = 0.0f;
    if (lam[l] <= 0.0f || v.fast == TextureView::Fast::kRepeatLinear) {
      level_a[l] = level_b[l] = v.base;
    } else if (float(v.base) + lam[l] >= float(v.q)) {
      level_a[l] = level_b[l] = v.q;
    } else {
      const float fl = std::floor(lam[l]);
      level_a[l] = v.base + int(fl);
      level_b[l] = level_a[l] + 1;
      f[l] = lam[l] - fl;
      two[l] = true;
    }
  }
  const __m128 s = _mm_setr_ps(uv[0].x, uv[1].x, uv[2].x, uv[3].x), t = _mm_setr_ps(uv[0].y, uv[1].y, uv[2].y, uv[3].y);
  glm::vec4 result[2][4];
  for (int pass = 0; pass < 2; ++pass) {
    const int* level = pass == 0 ? level_a : level_b;
    if (pass == 1 && !(two[0] || two[1] || two[2] || two[3])) break;
    const TextureLevel* lv[4] = {&levels[level[0]], &levels[level[1]], &levels[level[2]], &levels[level[3]]};
    const __m128i wi = _mm_setr_epi32(lv[0]->width, lv[1]->width, lv[2]->width, lv[3]->width);
    const __m128i hi = _mm_setr_epi32(lv[0]->height, lv[1]->height, lv[2]->height, lv[3]->height);
    // TexelCoord(): s * float(size), NaN -> 0, clamped to [-1e9, 1e9] (std::clamp's order of tests); then
    // BilinearRepeatPow2's arithmetic.
    const __m128 lo = _mm_set1_ps(-1e9f), hi1 = _mm_set1_ps(1e9f);
    __m128 u = _mm_mul_ps(s, _mm_cvtepi32_ps(wi));
    u = _mm_and_ps(u, _mm_cmpord_ps(u, u));
    u = _mm_blendv_ps(_mm_blendv_ps(u, hi1, _mm_cmplt_ps(hi1, u)), lo, _mm_cmplt_ps(u, lo));
    __m128 vv = _mm_mul_ps(t, _mm_cvtepi32_ps(hi));
    vv = _mm_and_ps(vv, _mm_cmpord_ps(vv, vv));
    vv = _mm_blendv_ps(_mm_blendv_ps(vv, hi1, _mm_cmplt_ps(hi1, vv)), lo, _mm_cmplt_ps(vv, lo));
    const __m128 fu = _mm_sub_ps(u, _mm_set1_ps(0.5f));
    const __m128 fv = _mm_sub_ps(vv, _mm_set1_ps(0.5f));
    const __m128 flu = _mm_floor_ps(fu), flv = _mm_floor_ps(fv);
    const __m128i i0 = _mm_cvttps_epi32(flu), j0 = _mm_cvttps_epi32(flv);
    const __m128 a = _mm_sub_ps(fu, flu), bb = _mm_sub_ps(fv, flv);
    const __m128i mi = _mm_sub_epi32(wi, _mm_set1_epi32(1)), mj = _mm_sub_epi32(hi, _mm_set1_epi32(1));
    alignas(16) std::int32_t c0[4], c1[4], r0[4], r1[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(c0), _mm_and_si128(i0, mi));
    _mm_store_si128(reinterpret_cast<__m128i*>(c1), _mm_and_si128(_mm_add_epi32(i0, _mm_set1_epi32(1)), mi));
    _mm_store_si128(reinterpret_cast<__m128i*>(r0), _mm_and_si128(j0, mj));
    _mm_store_si128(reinterpret_cast<__m128i*>(r1), _mm_and_si128(_mm_add_epi32(j0, _mm_set1_epi32(1)), mj));
    const __m128 one_a = _mm_sub_ps(one, a), one_b = _mm_sub_ps(one, bb);
    alignas(16) float w00[4], w10[4], w01[4], w11[4];
    _mm_store_ps(w00, _mm_mul_ps(one_a, one_b));
    _mm_store_ps(w10, _mm_mul_ps(a, one_b));
    _mm_store_ps(w01, _mm_mul_ps(one_a, bb));
    _mm_store_ps(w11, _mm_mul_ps(a, bb));
    for (int l = 0; l < 4; ++l) {
      const float* texels = lv[l]->texels.data();
      const std::size_t w = std::size_t(lv[l]->width);
      const float* row0 = texels + std::size_t(r0[l]) * w * 4;
      const float* row1 = texels + std::size_t(r1[l]) * w * 4;
      __m128 sum = _mm_mul_ps(_mm_set1_ps(w00[l]), _mm_loadu_ps(row0 + std::size_t(c0[l]) * 4));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w10[l]), _mm_loadu_ps(row0 + std::size_t(c1[l]) * 4)));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w01[l]), _mm_loadu_ps(row1 + std::size_t(c0[l]) * 4)));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_set1_ps(w11[l]), _mm_loadu_ps(row1 + std::size_t(c1[l]) * 4)));
      _mm_storeu_ps(&result[pass][l].x, sum);
    }
  }
  for (int l = 0; l < 4; ++l)
    out[l] = two[l] ? (1.0f - f[l]) * result[0][l] + f[l] * result[1][l] : result[0][l];
}
#endif

using SampleRepeatQuadFn = void (*)(const TextureView&, const glm::vec2*, const glm::vec2*, const glm::vec2*, float,
                                    glm::vec4*);

SampleRepeatQuadFn ChooseSampleRepeatQuad() {
#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
  if (detail::CpuSimdLevel() >= detail::SimdLevel::kAvx2) return SampleRepeatQuadAvx2;
#endif
  return SampleRepeatQuadBaseline;
}

using SampleRepeatFn = glm::vec4 (*)(const TextureView&, glm::vec2, glm::vec2, glm::vec2, float);

SampleRepeatFn ChooseSampleRepeat() {
#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
  if (detail::CpuSimdLevel() >= detail::SimdLevel::kAvx2) return SampleRepeatAvx2;
#endif
  return SampleRepeatBaseline;
}

}  // namespace

glm::vec4 Textures::Sample(int unit, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias) const {
  const TextureView* v = Usable(unit_2d, unit);
  if (!v) return kMissing;
  if (v->fast != TextureView::Fast::kNone) {
    static const SampleRepeatFn sample_repeat = ChooseSampleRepeat();
    return sample_repeat(*v, uv, duv_dx, duv_dy, bias);
  }
  return SampleFace(*v, 0, uv, Lambda(*v, duv_dx, duv_dy, bias), DepthCompare{});
}

void Textures::SampleQuad(int unit, const glm::vec2 uv[4], const glm::vec2 duv_dx[4], const glm::vec2 duv_dy[4],
                          float bias, glm::vec4 out[4]) const {
  const TextureView* v = Usable(unit_2d, unit);
  if (v && v->fast != TextureView::Fast::kNone) {
    static const SampleRepeatQuadFn sample_quad = ChooseSampleRepeatQuad();
    return sample_quad(*v, uv, duv_dx, duv_dy, bias, out);
  }
  for (int l = 0; l < 4; ++l) out[l] = Sample(unit, uv[l], duv_dx[l], duv_dy[l], bias);
}

glm::vec4 Textures::SampleLod(int unit, glm::vec2 uv, float lod) const {
  const TextureView* v = Usable(unit_2d, unit);
  if (!v) return kMissing;
  const SamplerParams& p = v->texture->params;
  const float lambda = std::clamp(lod + std::clamp(p.lod_bias, -16.0f, 16.0f), p.min_lod, p.max_lod);
  return SampleFace(*v, 0, uv, std::isnan(lambda) ? 0.0f : lambda, DepthCompare{});
}

glm::vec4 Textures::SampleCube(int unit, glm::vec3 dir, glm::vec3 ddir_dx, glm::vec3 ddir_dy, float bias) const {
  const TextureView* v = Usable(unit_cube, unit);
  if (!v) return kMissing;
  const int face = CubeFace(dir);
  glm::vec2 st(0.5f), st_x, st_y;
  FaceCoords(face, dir, st);
  // Derivatives of (s, t) on the chosen face, projecting the neighbouring directions onto that same face (a
  // neighbour may point at another face: its coordinates must still be measured on this one).
  const glm::vec2 dx = FaceCoords(face, dir + ddir_dx, st_x) ? st_x - st : glm::vec2(0.0f);
  const glm::vec2 dy = FaceCoords(face, dir + ddir_dy, st_y) ? st_y - st : glm::vec2(0.0f);
  return SampleFace(*v, face, st, Lambda(*v, dx, dy, bias), DepthCompare{});
}

glm::vec4 Textures::SampleCubeLod(int unit, glm::vec3 dir, float lod) const {
  const TextureView* v = Usable(unit_cube, unit);
  if (!v) return kMissing;
  const int face = CubeFace(dir);
  glm::vec2 st(0.5f);
  FaceCoords(face, dir, st);
  const SamplerParams& p = v->texture->params;
  const float lambda = std::clamp(lod + std::clamp(p.lod_bias, -16.0f, 16.0f), p.min_lod, p.max_lod);
  return SampleFace(*v, face, st, std::isnan(lambda) ? 0.0f : lambda, DepthCompare{});
}

float Textures::SampleShadow(int unit, glm::vec2 uv, float ref, glm::vec2 duv_dx, glm::vec2 duv_dy) const {
  const TextureView* v = Usable(unit_2d, unit);
  if (!v || !v->depth || v->texture->params.compare_mode != COMPARE_REF_TO_TEXTURE) return 0.0f;
  DepthCompare cmp;
  cmp.on = true;
  cmp.func = v->texture->params.compare_func;
  cmp.ref = std::clamp(ref, 0.0f, 1.0f);  // depth textures hold [0, 1]
  return SampleFace(*v, 0, uv, Lambda(*v, duv_dx, duv_dy, 0.0f), cmp).r;
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

// fragment_ops.cpp — stencil, depth, blending and masks with OpenGL's arithmetic.
#include "fragment_ops.h"

#include "simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace softgl::detail {

bool StencilTest(const StencilFace& face, std::uint8_t stored) {
  const std::uint32_t ref = std::uint32_t(std::clamp(face.ref, 0, 255));
  return Compare(face.func, ref & face.value_mask, std::uint32_t(stored) & face.value_mask);
}

std::uint8_t StencilUpdate(const StencilFace& face, Enum op, std::uint8_t stored) {
  std::uint32_t v = stored;
  switch (op) {
    case KEEP: return stored;
    case ZERO: v = 0; break;
    case REPLACE: v = std::uint32_t(std::clamp(face.ref, 0, 255)); break;
    case INCR: v = std::min<std::uint32_t>(v + 1, 255); break;
    case DECR: v = v == 0 ? 0 : v - 1; break;
    case INVERT: v = ~v & 0xFFu; break;
    case INCR_WRAP: v = (v + 1) & 0xFFu; break;
    case DECR_WRAP: v = (v - 1) & 0xFFu; break;
    default: return stored;
  }
  const std::uint32_t wm = face.write_mask & 0xFFu;
  return std::uint8_t((std::uint32_t(stored) & ~wm) | (v & wm));
}

namespace {

// The factor for one blend term (OpenGL 4.6, table 17.2). Returns the full RGBA factor; the caller takes rgb
// from the rgb factor and alpha from the alpha factor.
glm::vec4 Factor(Enum f, const glm::vec4& s, const glm::vec4& d, const glm::vec4& c) {
  switch (f) {
    case ZERO: return glm::vec4(0.0f);
    case ONE: return glm::vec4(1.0f);
    case SRC_COLOR: return s;
    case ONE_MINUS_SRC_COLOR: return 1.0f - s;
    case DST_COLOR: return d;
    case ONE_MINUS_DST_COLOR: return 1.0f - d;
    case SRC_ALPHA: return glm::vec4(s.a);
    case ONE_MINUS_SRC_ALPHA: return glm::vec4(1.0f - s.a);
    case DST_ALPHA: return glm::vec4(d.a);
    case ONE_MINUS_DST_ALPHA: return glm::vec4(1.0f - d.a);
    case CONSTANT_COLOR: return c;
    case ONE_MINUS_CONSTANT_COLOR: return 1.0f - c;
    case CONSTANT_ALPHA: return glm::vec4(c.a);
    case ONE_MINUS_CONSTANT_ALPHA: return glm::vec4(1.0f - c.a);
    case SRC_ALPHA_SATURATE: {
      const float f_sat = std::min(s.a, 1.0f - d.a);
      return glm::vec4(f_sat, f_sat, f_sat, 1.0f);
    }
    default: return glm::vec4(0.0f);
  }
}

float Equation(Enum eq, float s, float sf, float d, float df) {
  switch (eq) {
    case FUNC_SUBTRACT: return s * sf - d * df;
    case FUNC_REVERSE_SUBTRACT: return d * df - s * sf;
    case MIN: return std::min(s, d);  // MIN and MAX ignore the factors
    case MAX: return std::max(s, d);
    default: return s * sf + d * df;
  }
}

}  // namespace

glm::vec4 Blend(const BlendState& state, const glm::vec4& src, const glm::vec4& dst) {
  // The framebuffer is fixed point, so the constant colour is clamped to [0, 1] as it is used.
  const glm::vec4 c = glm::clamp(state.color, 0.0f, 1.0f);
  const glm::vec4 sf_rgb = Factor(state.src_rgb, src, dst, c), df_rgb = Factor(state.dst_rgb, src, dst, c);
  const float sf_a = Factor(state.src_alpha, src, dst, c).a, df_a = Factor(state.dst_alpha, src, dst, c).a;
  glm::vec4 out;
  for (int i = 0; i < 3; ++i) out[i] = Equation(state.eq_rgb, src[i], sf_rgb[i], dst[i], df_rgb[i]);
  out.a = Equation(state.eq_alpha, src.a, sf_a, dst.a, df_a);
  return out;
}

namespace {

// Blending and storing into an 8-bit RGBA buffer, one pixel's four channels at a time. Every operation is the one
// Blend(), ColorBuffer::Load/Store and FloatToUnorm8 do per channel, in the same order, so the bytes written are
// the same; a factor is evaluated as k0 + k1 * v (v a source, destination or constant vector, k1 in {-1, 0, 1}),
// which is exact.
struct Unorm8Blender {
  enum Source { kNone, kSrc, kDst, kSrcAlpha, kDstAlpha, kConst, kConstAlpha };
  struct Term {
    float k0 = 0.0f, k1 = 0.0f;
    Source source = kNone;
  };
  bool blend = false;
  bool usable = true;  // false for SRC_ALPHA_SATURATE: the generic path then runs
  Term src_rgb, dst_rgb, src_a, dst_a;
  Enum eq_rgb = FUNC_ADD, eq_a = FUNC_ADD;
  glm::vec4 constant{0.0f};
  std::uint32_t keep = 0;  // bytes of the stored pixel the colour mask keeps

  static Term TermOf(Enum f, bool& usable) {
    switch (f) {
      case ZERO: return {0.0f, 0.0f, kNone};
      case ONE: return {1.0f, 0.0f, kNone};
      case SRC_COLOR: return {0.0f, 1.0f, kSrc};
      case ONE_MINUS_SRC_COLOR: return {1.0f, -1.0f, kSrc};
      case DST_COLOR: return {0.0f, 1.0f, kDst};
      case ONE_MINUS_DST_COLOR: return {1.0f, -1.0f, kDst};
      case SRC_ALPHA: return {0.0f, 1.0f, kSrcAlpha};
      case ONE_MINUS_SRC_ALPHA: return {1.0f, -1.0f, kSrcAlpha};
      case DST_ALPHA: return {0.0f, 1.0f, kDstAlpha};
      case ONE_MINUS_DST_ALPHA: return {1.0f, -1.0f, kDstAlpha};
      case CONSTANT_COLOR: return {0.0f, 1.0f, kConst};
      case ONE_MINUS_CONSTANT_COLOR: return {1.0f, -1.0f, kConst};
      case CONSTANT_ALPHA: return {0.0f, 1.0f, kConstAlpha};
      case ONE_MINUS_CONSTANT_ALPHA: return {1.0f, -1.0f, kConstAlpha};
      default: usable = false; return {};
    }
  }

  explicit Unorm8Blender(const FragmentOpsState& state) {
    blend = state.blend.enabled;
    for (int c = 0; c < 4; ++c)
      if (!state.color_mask[c]) keep |= 0xFFu << (8 * c);
    if (!blend) return;
    src_rgb = TermOf(state.blend.src_rgb, usable);
    dst_rgb = TermOf(state.blend.dst_rgb, usable);
    src_a = TermOf(state.blend.src_alpha, usable);
    dst_a = TermOf(state.blend.dst_alpha, usable);
    eq_rgb = state.blend.eq_rgb;
    eq_a = state.blend.eq_alpha;
    constant = glm::clamp(state.blend.color, 0.0f, 1.0f);
#if defined(__SSE2__)
    Prepare();
#endif
  }

#if defined(__SSE2__)
  // Per channel (r, g, b from the rgb state, a from the alpha state): factor = k0 + k1 * source, and for the
  // equations ADD, SUBTRACT and REVERSE_SUBTRACT, result = ks * (s * sf) + kd * (d * df) with ks, kd = +-1.
  __m128 sk0, sk1, dk0, dk1, ks, kd;
  int src_pick[2], dst_pick[2];  // [rgb, alpha]: index into the source vectors
  bool min_max = false;          // MIN or MAX in either equation: the generic equations run

  void Prepare() {
    sk0 = _mm_setr_ps(src_rgb.k0, src_rgb.k0, src_rgb.k0, src_a.k0);
    sk1 = _mm_setr_ps(src_rgb.k1, src_rgb.k1, src_rgb.k1, src_a.k1);
    dk0 = _mm_setr_ps(dst_rgb.k0, dst_rgb.k0, dst_rgb.k0, dst_a.k0);
    dk1 = _mm_setr_ps(dst_rgb.k1, dst_rgb.k1, dst_rgb.k1, dst_a.k1);
    auto sign_s = [](Enum eq) { return eq == FUNC_REVERSE_SUBTRACT ? -1.0f : 1.0f; };
    auto sign_d = [](Enum eq) { return eq == FUNC_SUBTRACT ? -1.0f : 1.0f; };
    ks = _mm_setr_ps(sign_s(eq_rgb), sign_s(eq_rgb), sign_s(eq_rgb), sign_s(eq_a));
    kd = _mm_setr_ps(sign_d(eq_rgb), sign_d(eq_rgb), sign_d(eq_rgb), sign_d(eq_a));
    src_pick[0] = src_rgb.source;
    src_pick[1] = src_a.source;
    dst_pick[0] = dst_rgb.source;
    dst_pick[1] = dst_a.source;
    min_max = eq_rgb == MIN || eq_rgb == MAX || eq_a == MIN || eq_a == MAX;
  }

  static __m128 Alpha(__m128 v) { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 3, 3, 3)); }
  static __m128 RgbA(__m128 rgb, __m128 a) {  // (rgb.r, rgb.g, rgb.b, a.a)
    const __m128 alpha_lane = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    return _mm_or_ps(_mm_andnot_ps(alpha_lane, rgb), _mm_and_ps(alpha_lane, a));
  }
  static __m128 Equation(Enum eq, __m128 s, __m128 sf, __m128 d, __m128 df) {
    switch (eq) {
      case FUNC_SUBTRACT: return _mm_sub_ps(_mm_mul_ps(s, sf), _mm_mul_ps(d, df));
      case FUNC_REVERSE_SUBTRACT: return _mm_sub_ps(_mm_mul_ps(d, df), _mm_mul_ps(s, sf));
      case MIN: return _mm_min_ps(d, s);
      case MAX: return _mm_max_ps(d, s);
      default: return _mm_add_ps(_mm_mul_ps(s, sf), _mm_mul_ps(d, df));
    }
  }

  // Writes fragment colour `color` at `p` (4 bytes), blended with what is there.
  void Store(const glm::vec4& color, std::uint8_t* p) const {
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), scale = _mm_set1_ps(255.0f);
    __m128 s = _mm_loadu_ps(&color.x);
    s = _mm_and_ps(s, _mm_cmpord_ps(s, s));  // NaN -> 0
    s = _mm_min_ps(_mm_max_ps(s, zero), one);
    std::uint32_t old;
    std::memcpy(&old, p, 4);
    if (blend) {
      const __m128i bytes = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(int(old)), _mm_setzero_si128()),
                                               _mm_setzero_si128());
      const __m128 d = _mm_div_ps(_mm_cvtepi32_ps(bytes), scale);
      const __m128 c = _mm_loadu_ps(&constant.x);
      const __m128 sources[7] = {zero, s, d, Alpha(s), Alpha(d), c, Alpha(c)};  // indexed by Source
      const __m128 sf = _mm_add_ps(sk0, _mm_mul_ps(sk1, RgbA(sources[src_pick[0]], sources[src_pick[1]])));
      const __m128 df = _mm_add_ps(dk0, _mm_mul_ps(dk1, RgbA(sources[dst_pick[0]], sources[dst_pick[1]])));
      if (!min_max) {
        s = _mm_add_ps(_mm_mul_ps(ks, _mm_mul_ps(s, sf)), _mm_mul_ps(kd, _mm_mul_ps(d, df)));
      } else {
        s = RgbA(Equation(eq_rgb, s, sf, d, df), Equation(eq_a, s, sf, d, df));
      }
      s = _mm_min_ps(_mm_max_ps(s, zero), one);  // FloatToUnorm8's clamp (NaN -> 0)
    }
    const __m128i v = _mm_cvtps_epi32(_mm_mul_ps(s, scale));  // round to nearest even, as lrint
    const __m128i packed = _mm_packus_epi16(_mm_packs_epi32(v, v), _mm_setzero_si128());
    const auto bytes = std::uint32_t(_mm_cvtsi128_si32(packed));
    const std::uint32_t out = (old & keep) | (bytes & ~keep);
    std::memcpy(p, &out, 4);
  }
#endif
};

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#define SOFTGL_AVX2_DISPATCH 1

// Two horizontally adjacent pixels at once in 256-bit registers: Unorm8Blender::Store's operations, lane for lane,
// so the bytes are the same. Compiled for AVX2 (without FMA, which would round differently) and used only when the
// processor has it; the blender must not use MIN or MAX (their lane selection stays in the 128-bit path).
__attribute__((target("avx2"))) void Store2Avx2(const Unorm8Blender& b, const glm::vec4& c0, const glm::vec4& c1,
                                                std::uint8_t* p) {
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f);
  __m256 s = _mm256_set_m128(_mm_loadu_ps(&c1.x), _mm_loadu_ps(&c0.x));
  s = _mm256_and_ps(s, _mm256_cmp_ps(s, s, _CMP_ORD_Q));  // NaN -> 0
  s = _mm256_min_ps(_mm256_max_ps(s, zero), one);
  std::uint64_t old;
  std::memcpy(&old, p, 8);
  if (b.blend) {
    const __m256 d =
        _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(_mm_cvtsi64_si128(std::int64_t(old)))), scale);
    const __m128 c128 = _mm_loadu_ps(&b.constant.x);
    const __m256 c = _mm256_set_m128(c128, c128);
    // Each pixel's alpha in its four channels: _mm256_permute_ps(v, 0xFF); (rgb, alpha) lanes: blend 0x88.
    const __m256 sources[7] = {zero, s, d, _mm256_permute_ps(s, 0xFF), _mm256_permute_ps(d, 0xFF), c,
                               _mm256_permute_ps(c, 0xFF)};
    const __m256 src_v = _mm256_blend_ps(sources[b.src_pick[0]], sources[b.src_pick[1]], 0x88);
    const __m256 dst_v = _mm256_blend_ps(sources[b.dst_pick[0]], sources[b.dst_pick[1]], 0x88);
    const __m256 sf = _mm256_add_ps(_mm256_set_m128(b.sk0, b.sk0), _mm256_mul_ps(_mm256_set_m128(b.sk1, b.sk1), src_v));
    const __m256 df = _mm256_add_ps(_mm256_set_m128(b.dk0, b.dk0), _mm256_mul_ps(_mm256_set_m128(b.dk1, b.dk1), dst_v));
    s = _mm256_add_ps(_mm256_mul_ps(_mm256_set_m128(b.ks, b.ks), _mm256_mul_ps(s, sf)),
                      _mm256_mul_ps(_mm256_set_m128(b.kd, b.kd), _mm256_mul_ps(d, df)));
    s = _mm256_min_ps(_mm256_max_ps(s, zero), one);
  }
  const __m256i v = _mm256_cvtps_epi32(_mm256_mul_ps(s, scale));
  const __m128i w16 = _mm_packs_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
  const auto bytes = std::uint64_t(_mm_cvtsi128_si64(_mm_packus_epi16(w16, w16)));
  const std::uint64_t keep = std::uint64_t(b.keep) | std::uint64_t(b.keep) << 32;
  const std::uint64_t out = (old & keep) | (bytes & ~keep);
  std::memcpy(p, &out, 8);
}

// A whole quad (two rows of two pixels) in one 512-bit register: the same operations again, lane for lane.
// (GCC 12's AVX-512 headers start intrinsics from a self-initialized "undefined" vector, which its
// uninitialized-value warnings report at every use: a known false positive, silenced for this function only.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
__attribute__((target("avx512f"))) void Store4Avx512(const Unorm8Blender& b, const FragmentOut* row0,
                                                     const FragmentOut* row1, std::uint8_t* p0, std::uint8_t* p1) {
  const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f), scale = _mm512_set1_ps(255.0f);
  __m512 s = _mm512_castps128_ps512(_mm_loadu_ps(&row0[0].color[0].x));
  s = _mm512_insertf32x4(s, _mm_loadu_ps(&row0[1].color[0].x), 1);
  s = _mm512_insertf32x4(s, _mm_loadu_ps(&row1[0].color[0].x), 2);
  s = _mm512_insertf32x4(s, _mm_loadu_ps(&row1[1].color[0].x), 3);
  s = _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(s, s, _CMP_ORD_Q), s);  // NaN -> 0
  s = _mm512_min_ps(_mm512_max_ps(s, zero), one);
  std::uint64_t old0, old1;
  std::memcpy(&old0, p0, 8);
  std::memcpy(&old1, p1, 8);
  if (b.blend) {
    const __m128i old_bytes = _mm_set_epi64x(std::int64_t(old1), std::int64_t(old0));
    const __m512 d = _mm512_div_ps(_mm512_cvtepi32_ps(_mm512_cvtepu8_epi32(old_bytes)), scale);
    const __m512 c = _mm512_broadcast_f32x4(_mm_loadu_ps(&b.constant.x));
    const __m512 sources[7] = {zero, s, d, _mm512_permute_ps(s, 0xFF), _mm512_permute_ps(d, 0xFF), c,
                               _mm512_permute_ps(c, 0xFF)};
    const __m512 src_v = _mm512_mask_blend_ps(0x8888, sources[b.src_pick[0]], sources[b.src_pick[1]]);
    const __m512 dst_v = _mm512_mask_blend_ps(0x8888, sources[b.dst_pick[0]], sources[b.dst_pick[1]]);
    const __m512 sf = _mm512_add_ps(_mm512_broadcast_f32x4(b.sk0), _mm512_mul_ps(_mm512_broadcast_f32x4(b.sk1), src_v));
    const __m512 df = _mm512_add_ps(_mm512_broadcast_f32x4(b.dk0), _mm512_mul_ps(_mm512_broadcast_f32x4(b.dk1), dst_v));
    s = _mm512_add_ps(_mm512_mul_ps(_mm512_broadcast_f32x4(b.ks), _mm512_mul_ps(s, sf)),
                      _mm512_mul_ps(_mm512_broadcast_f32x4(b.kd), _mm512_mul_ps(d, df)));
    s = _mm512_min_ps(_mm512_max_ps(s, zero), one);
  }
  const __m128i bytes = _mm512_cvtusepi32_epi8(_mm512_cvtps_epi32(_mm512_mul_ps(s, scale)));  // values in [0, 255]
  const std::uint64_t keep = std::uint64_t(b.keep) | std::uint64_t(b.keep) << 32;
  const auto new0 = std::uint64_t(_mm_cvtsi128_si64(bytes));
  const auto new1 = std::uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(bytes, bytes)));
  const std::uint64_t out0 = (old0 & keep) | (new0 & ~keep), out1 = (old1 & keep) | (new1 & ~keep);
  std::memcpy(p0, &out0, 8);
  std::memcpy(p1, &out1, 8);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#endif

}  // namespace

bool EarlyDepthTestApplies(const FragmentOpsState& state, bool shader_writes_depth) {
  const Enum f = state.depth_func;
  return !shader_writes_depth && state.depth_test && !state.stencil_test &&
         (f == LESS || f == LEQUAL || f == GREATER || f == GEQUAL);
}

namespace {

// The early test for one comparison, chosen once per batch rather than per lane.
template <class Passes>
int EarlyDepthLoop(QuadBuffer& quads, const RenderTarget& target, Passes passes) {
  int live = 0;
  for (int q = 0; q < quads.count; ++q) {
    for (int lane = 0; lane < 4; ++lane) {
      const int l = q * 4 + lane;
      if (!quads.live[l]) continue;  // a live lane lies inside the target; the others may not
      const float depth = quads.frag_coord[l].z;
      const float stored = target.Depth(quads.qx[q] + (lane & 1), quads.qy[q] + (lane >> 1));
      // As the late test: depth clamped to [0, 1], NaN fails.
      if (std::isnan(depth) || !passes(std::clamp(depth, 0.0f, 1.0f), stored)) quads.live[l] = 0;
      live += quads.live[l];
    }
  }
  return live;
}

}  // namespace

int EarlyDepthTest(const FragmentOpsState& state, QuadBuffer& quads, const RenderTarget& target) {
  if (!target.depth) {
    int live = 0;
    for (int l = 0; l < quads.count * 4; ++l) live += quads.live[l];
    return live;
  }
  switch (state.depth_func) {
    case LESS: return EarlyDepthLoop(quads, target, [](float z, float d) { return z < d; });
    case LEQUAL: return EarlyDepthLoop(quads, target, [](float z, float d) { return z <= d; });
    case GREATER: return EarlyDepthLoop(quads, target, [](float z, float d) { return z > d; });
    case GEQUAL: return EarlyDepthLoop(quads, target, [](float z, float d) { return z >= d; });
    default:
      return EarlyDepthLoop(quads, target, [&](float z, float d) { return DepthTest(state.depth_func, z, d); });
  }
}

void ApplyFragmentOps(const FragmentOpsState& state, const QuadBuffer& quads, const RenderTarget& target) {
  const StencilFace& face = quads.front_facing ? state.front : state.back;
  // Without a depth or stencil buffer the test passes and nothing is written (OpenGL 4.6, 17.3.5 and 17.3.6).
  const bool stencil_test = state.stencil_test && target.stencil != nullptr;
  const bool depth_test = state.depth_test && target.depth != nullptr;
  const bool any_color = state.color_mask[0] || state.color_mask[1] || state.color_mask[2] || state.color_mask[3];
#if defined(__SSE2__)
  const Unorm8Blender unorm8(state);
#endif
#if defined(__SSE2__)
  // The common case, in a loop of its own: one 8-bit colour buffer, no stencil test.
  const ColorBuffer& cb0 = target.color[0];
  if (unorm8.usable && !stencil_test && any_color && cb0.rgba8 && !target.color[1].Present() &&
      !target.color[2].Present() && !target.color[3].Present()) {
    // Wider paths for the blenders without MIN or MAX: a row of two pixels (AVX2), a whole quad (AVX-512).
    const int wide = unorm8.min_max ? 0 : int(CpuSimdLevel());
    for (int q = 0; q < quads.count; ++q) {
      // Depth first for the four lanes (four different pixels), then colour a row of two at a time.
      unsigned pass = 0;
      for (int lane = 0; lane < 4; ++lane) {
        const int l = q * 4 + lane;
        if (!quads.live[l]) continue;
        if (depth_test) {
          const int x = quads.qx[q] + (lane & 1), y = quads.qy[q] + (lane >> 1);
          const float depth = quads.out[l].depth;
          const float z = std::clamp(depth, 0.0f, 1.0f);
          float& stored = target.Depth(x, y);
          if (std::isnan(depth) || !DepthTest(state.depth_func, z, stored)) continue;
          if (state.depth_write) stored = z;
        }
        pass |= 1u << lane;
      }
#if defined(SOFTGL_AVX2_DISPATCH)
      if (wide == 2 && pass == 0xFu) {
        Store4Avx512(unorm8, quads.out + q * 4, quads.out + q * 4 + 2,
                     cb0.rgba8 + cb0.Index(quads.qx[q], quads.qy[q]) * 4,
                     cb0.rgba8 + cb0.Index(quads.qx[q], quads.qy[q] + 1) * 4);
        continue;
      }
#endif
      for (int row = 0; row < 2; ++row) {
        const unsigned bits = (pass >> (2 * row)) & 3u;
        if (!bits) continue;
        std::uint8_t* p = cb0.rgba8 + cb0.Index(quads.qx[q], quads.qy[q] + row) * 4;
        const FragmentOut* out = quads.out + q * 4 + 2 * row;
#if defined(SOFTGL_AVX2_DISPATCH)
        if (wide >= 1 && bits == 3u) {
          Store2Avx2(unorm8, out[0].color[0], out[1].color[0], p);
          continue;
        }
#endif
        if (bits & 1u) unorm8.Store(out[0].color[0], p);
        if (bits & 2u) unorm8.Store(out[1].color[0], p + 4);
      }
    }
    return;
  }
#endif
  for (int q = 0; q < quads.count; ++q) {
    for (int lane = 0; lane < 4; ++lane) {
      const int l = q * 4 + lane;
      if (!quads.live[l]) continue;
      const int x = quads.qx[q] + (lane & 1), y = quads.qy[q] + (lane >> 1);
      const FragmentOut& out = quads.out[l];

      if (stencil_test && !StencilTest(face, target.Stencil(x, y))) {
        target.Stencil(x, y) = StencilUpdate(face, face.sfail, target.Stencil(x, y));
        continue;
      }
      if (depth_test) {
        // Depth is clamped to [0, 1] before the test (the depth buffer holds [0, 1]); NaN fails.
        const float z = std::clamp(out.depth, 0.0f, 1.0f);
        if (std::isnan(out.depth) || !DepthTest(state.depth_func, z, target.Depth(x, y))) {
          if (stencil_test) target.Stencil(x, y) = StencilUpdate(face, face.dpfail, target.Stencil(x, y));
          continue;
        }
        if (state.depth_write) target.Depth(x, y) = z;
      }
      if (stencil_test) target.Stencil(x, y) = StencilUpdate(face, face.dppass, target.Stencil(x, y));
      if (!any_color) continue;

      for (int o = 0; o < kMaxColorOutputs; ++o) {
        const ColorBuffer& cb = target.color[o];
        if (!cb.Present()) continue;
#if defined(__SSE2__)
        if (cb.rgba8 && unorm8.usable) {
          unorm8.Store(out.color[o], cb.rgba8 + cb.Index(x, y) * 4);
          continue;
        }
#endif
        glm::vec4 color = out.color[o];
        for (int c = 0; c < 4; ++c)
          if (std::isnan(color[c])) color[c] = 0.0f;
        // Fixed-point buffers take colours clamped to [0, 1], before blending.
        if (cb.normalized) color = glm::clamp(color, 0.0f, 1.0f);
        if (state.blend.enabled) color = Blend(state.blend, color, cb.Load(x, y));
        cb.Store(x, y, color, state.color_mask);
      }
    }
  }
}

}  // namespace softgl::detail

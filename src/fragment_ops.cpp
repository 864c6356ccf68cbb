// fragment_ops.cpp — stencil, depth, blending and masks with OpenGL's arithmetic.
#include "fragment_ops.h"

#include "simd.h"
#include "wide.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

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

// The NaN every blend that makes one gives (positive, quiet).
constexpr float kBlendNaN = __builtin_nanf("");

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
  const glm::vec4 c = state.color;  // a float buffer takes the constant colour unclamped
  const glm::vec4 sf_rgb = Factor(state.src_rgb, src, dst, c), df_rgb = Factor(state.dst_rgb, src, dst, c);
  const float sf_a = Factor(state.src_alpha, src, dst, c).a, df_a = Factor(state.dst_alpha, src, dst, c).a;
  glm::vec4 out;
  for (int i = 0; i < 3; ++i) out[i] = Equation(state.eq_rgb, src[i], sf_rgb[i], dst[i], df_rgb[i]);
  out.a = Equation(state.eq_alpha, src.a, sf_a, dst.a, df_a);
  // A NaN result (a NaN or infinite stored value, or a colour out of a float buffer) is one NaN: which of two NaN
  // operands an operation returns depends on their order, which a compiler may swap (a * b as b * a), so the
  // vector and the lane-by-lane paths would store NaNs of different signs.
  for (int i = 0; i < 4; ++i)
    if (out[i] != out[i]) out[i] = kBlendNaN;
  return out;
}


// ---- 8-bit blending: exact integer arithmetic -------------------------------------------------------------------

namespace {

Term TermOf(Enum f, bool alpha) {
  switch (f) {
    case ZERO: return {0, 0, kNothing};
    case ONE: return {255, 0, kNothing};
    case SRC_COLOR: return {0, 1, kSrc};
    case ONE_MINUS_SRC_COLOR: return {255, -1, kSrc};
    case DST_COLOR: return {0, 1, kDst};
    case ONE_MINUS_DST_COLOR: return {255, -1, kDst};
    case SRC_ALPHA: return {0, 1, kSrcAlpha};
    case ONE_MINUS_SRC_ALPHA: return {255, -1, kSrcAlpha};
    case DST_ALPHA: return {0, 1, kDstAlpha};
    case ONE_MINUS_DST_ALPHA: return {255, -1, kDstAlpha};
    case CONSTANT_COLOR: return {0, 1, kConst};
    case ONE_MINUS_CONSTANT_COLOR: return {255, -1, kConst};
    case CONSTANT_ALPHA: return {0, 1, kConstAlpha};
    case ONE_MINUS_CONSTANT_ALPHA: return {255, -1, kConstAlpha};
    case SRC_ALPHA_SATURATE: return alpha ? Term{255, 0, kNothing} : Term{0, 1, kSaturate};
    default: return {0, 0, kNothing};
  }
}

}  // namespace

Unorm8Blend::Unorm8Blend(const FragmentOpsState& state, int o, bool rgb_only) {
  for (int c = 0; c < 4; ++c)
    if (!state.Writes(o, c) || (c == 3 && rgb_only)) keep |= 0xFFu << (8 * c);
  logic = state.LogicMode();
  blend = state.Blends(o) || logic != 0;
  const BlendState& b = state.blend;
  for (int c = 0; c < 4; ++c) {
    const bool a = c == 3;
    src[c] = TermOf(a ? b.src_alpha : b.src_rgb, a);
    dst[c] = TermOf(a ? b.dst_alpha : b.dst_rgb, a);
    eq[c] = a ? b.eq_alpha : b.eq_rgb;
    constant[c] = FloatToUnorm8(b.color[c]);
  }
  packed = state.Blends(o) && b.eq_rgb == b.eq_alpha &&
           (b.eq_rgb == FUNC_ADD || b.eq_rgb == FUNC_SUBTRACT || b.eq_rgb == FUNC_REVERSE_SUBTRACT);
  alpha_over = packed && b.eq_rgb == FUNC_ADD && b.src_rgb == SRC_ALPHA && b.src_alpha == SRC_ALPHA &&
               b.dst_rgb == ONE_MINUS_SRC_ALPHA && b.dst_alpha == ONE_MINUS_SRC_ALPHA;
}

namespace {
ColourPath PathOf(const ColorBuffer& cb) {
  if (!cb.Present()) return ColourPath::kNone;
  if (IsUnorm8(cb.layout)) return cb.srgb ? ColourPath::kFloat : ColourPath::kUnorm8;
  if (IsIntegerLayout(cb.layout)) return ColourPath::kInteger;
  // Float, half, R11F_G11F_B10F, packed and 16-bit fixed point in vectors.
  return ColourPath::kFloat;
}
}  // namespace

FragmentOpsPlan PlanFragmentOps(const FragmentOpsState& state, const RenderTarget& target) {
  FragmentOpsPlan plan;
  for (int o = 0; o < kMaxColorOutputs; ++o) {
    if (!target.color[o].Present()) continue;  // (nothing reads an absent buffer's plan)
    plan.blend[o] = Unorm8Blend(state, o, target.color[o].rgb_only);
    plan.path[o] = state.color_masks[o] != 0 ? PathOf(target.color[o]) : ColourPath::kNone;
    if (plan.path[o] != ColourPath::kNone) plan.buffers = o + 1;
    if (target.color[o].srgb) plan.srgb = &SrgbLanes();
  }
  plan.one_rgba8 = !target.color[0].Present() || target.color[0].Rgba8();
  for (int o = 1; o < kMaxColorOutputs; ++o) plan.one_rgba8 = plan.one_rgba8 && !target.color[o].Present();
  // The multisampled context framebuffer (samples side by side) has the vector path for its formats: RGBA8, and
  // RGB565 and sRGB-encoded RGBA8 in float.
  const TexelLayout l0 = target.color[0].layout;
  plan.wide_target = !target.interleaved || plan.one_rgba8 ||
                     (plan.buffers <= 1 && (l0 == TexelLayout::kUnorm565 ||
                                            (l0 == TexelLayout::kUnorm8x4 && target.color[0].srgb && !target.color[0].rgb_only)));
  return plan;
}


namespace {

// (x + 127) / 255 for x in [0, 65025]: x / 255 rounded to the nearest integer (never a tie: 255 is odd).
inline int Div255Round(int x) { return ((x + 127) * 32897) >> 23; }

// One channel of the equation on 8-bit operands.
inline int Equation8(Enum eq, int s, int sf, int d, int df) {
  int x;
  switch (eq) {
    case FUNC_SUBTRACT: x = s * sf - d * df; break;
    case FUNC_REVERSE_SUBTRACT: x = d * df - s * sf; break;
    case MIN: return std::min(s, d);
    case MAX: return std::max(s, d);
    default: x = s * sf + d * df; break;
  }
  return Div255Round(std::clamp(x, 0, 65025));
}

inline int Factor8(const Term& t, int c, const int s[4], const int d[4], const int k[4]) {
  int v = 0;
  switch (t.source) {
    case kNothing: v = 0; break;
    case kSrc: v = s[c]; break;
    case kDst: v = d[c]; break;
    case kSrcAlpha: v = s[3]; break;
    case kDstAlpha: v = d[3]; break;
    case kConst: v = k[c]; break;
    case kConstAlpha: v = k[3]; break;
    case kSaturate: return std::min(s[3], 255 - d[3]);
  }
  return t.k0 + t.k1 * v;
}

// The new bytes of one pixel (before the colour mask).
void Blend8(const Unorm8Blend& b, const glm::vec4& color, const std::uint8_t dst[4], std::uint8_t out[4]) {
  int s[4], d[4];
  for (int c = 0; c < 4; ++c) {
    s[c] = FloatToUnorm8(color[c]);
    d[c] = dst[c];
  }
  for (int c = 0; c < 4; ++c) {
    if (!b.blend || b.logic) {
      out[c] = b.logic ? std::uint8_t(LogicOpBits(b.logic, unsigned(s[c]), unsigned(d[c]))) : std::uint8_t(s[c]);
      continue;
    }
    const int sf = Factor8(b.src[c], c, s, d, b.constant), df = Factor8(b.dst[c], c, s, d, b.constant);
    out[c] = std::uint8_t(Equation8(b.eq[c], s[c], sf, d[c], df));
  }
}

// The same, W pixels at a time: `color` the fragments' channels, `pixels` the stored RGBA8 words; the result
// words, the colour mask applied.
template <int W>
SOFTGL_WIDE typename V<W>::U Blend8Lanes(const Unorm8Blend& b, const typename V<W>::F color[4],
                                    typename V<W>::U pixels) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  I s[4], d[4];
#pragma GCC unroll 4
  for (int c = 0; c < 4; ++c) {
    // FloatToUnorm8: NaN and below 0 give 0, 1 and above 255, the rest round(f * 255) to nearest even (adding and
    // subtracting 1.5 * 2^23 rounds, as lrint does, in the default rounding mode).
    F x = color[c] > 0.0f ? color[c] : F{} + 0.0f;
    x = x < 1.0f ? x : F{} + 1.0f;
    x = (x * 255.0f + 12582912.0f) - 12582912.0f;
    s[c] = __builtin_convertvector(x, I);
    d[c] = I((pixels >> (8 * c)) & 0xFFu);
  }
  U out = U{};
  if (!b.blend || b.logic) {
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) out |= U(s[c]) << (8 * c);
    if (b.logic) out = LogicOpBits(b.logic, out, pixels);
  } else {
    auto factor = [&](const Term& t, int c) SOFTGL_WIDE_LAMBDA -> I {
      I v;
      switch (t.source) {
        case kNothing: return I{} + t.k0;
        case kSrc: v = s[c]; break;
        case kDst: v = d[c]; break;
        case kSrcAlpha: v = s[3]; break;
        case kDstAlpha: v = d[3]; break;
        case kConst: v = I{} + b.constant[c]; break;
        case kConstAlpha: v = I{} + b.constant[3]; break;
        default: {  // kSaturate
          const I one_minus = 255 - d[3];
          return s[3] < one_minus ? s[3] : one_minus;
        }
      }
      return t.k1 == 1 ? t.k0 + v : (t.k1 == -1 ? t.k0 - v : I{} + t.k0);
    };
    if (b.packed) {
      // Two channels to a 32-bit lane, as its 16-bit halves (r and b, g and a): the products, the equation and
      // the division by 255 on 2W lanes of 16 bits, half the instructions of one channel per lane. Every product
      // fits (255 x 255); a sum past 16 bits is caught by its wrap-around, and x / 255 rounded to nearest is
      // (t + (t >> 8)) >> 8 with t = x + 128, exact for every x in [0, 65025].
      using H = typename V<W>::H;
      auto pack = [](I lo, I hi) SOFTGL_WIDE_LAMBDA { return H(U(lo) | (U(hi) << 16)); };
      const U low = U{} + 0x00FF00FFu;
      const H s_rb = pack(s[0], s[2]), s_ga = pack(s[1], s[3]);
      const H d_rb = H(pixels & low), d_ga = H((pixels >> 8) & low);
      if (b.alpha_over) {
        // The most common blend, without choosing factors: a and 255 - a in every channel. s a + d (255 - a) is
        // at most 65025, so the equation needs no clamping; the rest is the general path's arithmetic.
        const H sf = pack(s[3], s[3]), df = H(low) - sf;
        auto div255 = [](H x) SOFTGL_WIDE_LAMBDA {
          const H t = x + 128;
          return (t + (t >> 8)) >> 8;
        };
        const H r_rb = div255(s_rb * sf + d_rb * df), r_ga = div255(s_ga * sf + d_ga * df);
        return (pixels & b.keep) | ((U(r_rb) | (U(r_ga) << 8)) & ~b.keep);
      }
      const H sf_rb = pack(factor(b.src[0], 0), factor(b.src[2], 2));
      const H sf_ga = pack(factor(b.src[1], 1), factor(b.src[3], 3));
      const H df_rb = pack(factor(b.dst[0], 0), factor(b.dst[2], 2));
      const H df_ga = pack(factor(b.dst[1], 1), factor(b.dst[3], 3));
      const Enum eq = b.eq[0];
      auto combine = [eq](H ss, H dd) SOFTGL_WIDE_LAMBDA {
        H x;
        if (eq == FUNC_ADD) {
          x = ss + dd;
          x = x < ss ? H{} + 65025 : x;  // past 16 bits (one comparison per select: GCC scalarizes an OR of two)
          x = x > 65025 ? H{} + 65025 : x;
        } else if (eq == FUNC_SUBTRACT) {
          x = ss > dd ? ss - dd : H{};
        } else {
          x = dd > ss ? dd - ss : H{};
        }
        const H t = x + 128;
        return (t + (t >> 8)) >> 8;
      };
      const H r_rb = combine(s_rb * sf_rb, d_rb * df_rb), r_ga = combine(s_ga * sf_ga, d_ga * df_ga);
      out = U(r_rb) | (U(r_ga) << 8);
    } else {
      for (int c = 0; c < 4; ++c) {
        I r;
        switch (b.eq[c]) {
          case MIN: r = s[c] < d[c] ? s[c] : d[c]; break;
          case MAX: r = s[c] > d[c] ? s[c] : d[c]; break;
          default: {
            const I ss = s[c] * factor(b.src[c], c), dd = d[c] * factor(b.dst[c], c);
            I x = b.eq[c] == FUNC_SUBTRACT ? ss - dd : (b.eq[c] == FUNC_REVERSE_SUBTRACT ? dd - ss : ss + dd);
            x = x < 0 ? I{} : x;
            x = x > 65025 ? I{} + 65025 : x;
            r = ((x + 127) * 32897) >> 23;
            break;
          }
        }
        out |= U(r) << (8 * c);
      }
    }
  }
  return (pixels & b.keep) | (out & ~b.keep);
}

}  // namespace

void BlendUnorm8(const BlendState& state, const glm::vec4& src, const std::uint8_t dst[4], std::uint8_t out[4]) {
  FragmentOpsState s;
  s.blend = state;
  s.blend_buffers = 1;  // (draw buffer 0 blends)
  Blend8(Unorm8Blend(s, 0, false), src, dst, out);
}

std::uint32_t CoverageMask(const MultisampleState& state, int samples) {
  const int n = int(state.coverage_value * float(samples));  // value in [0, 1]: truncated, as Mesa does
  const std::uint32_t all = (std::uint32_t(1) << samples) - 1, first = (std::uint32_t(1) << n) - 1;
  return state.coverage_invert ? all & ~first : first;
}

std::uint32_t AlphaToCoverageMask(float alpha, int samples) {
  std::uint32_t mask = 0;
  for (int s = 0; s < samples; ++s)
    if (alpha * float(samples) > float(s)) mask |= 1u << s;  // (NaN keeps none)
  return mask;
}

bool EarlyDepthTestApplies(const FragmentOpsState& state, bool shader_writes_depth) {
  const Enum f = state.depth_func;
  return !shader_writes_depth && state.depth_test && !state.stencil_test &&
         (f == LESS || f == LEQUAL || f == GREATER || f == GEQUAL);
}

// ---- Whole blocks ----------------------------------------------------------------------------------------------

namespace {

// Whether a block's quads lie inside the target, so that whole quads of it can be read and written. Always, when
// the target's width and height are even: a quad starts at even coordinates, at a pixel inside the target (its
// unused places repeat its first quad's).
bool Inside(const RenderTarget& t, const BlockBuffer& bb, int b) {
  if (((t.width | t.height) & 1) == 0) return true;
  for (int q = 0; q < 4; ++q)
    if (bb.qx[b][q] + 2 > t.width || bb.qy[b][q] + 2 > t.height) return false;
  return true;
}

// Where block b's quads start in a buffer of `pitch` values between rows: qy * pitch + qx, computed once per block
// for all the loads and stores (and sample planes) that share the pitch.
// (`step` values from one pixel to the next: the sample count where samples lie side by side.)
struct QuadPlaces {
  std::size_t at[4];
  std::size_t pitch;
  QuadPlaces() = default;
  QuadPlaces(const BlockBuffer& bb, int b, int row_pitch, int step = 1) : pitch(std::size_t(row_pitch)) {
    for (int q = 0; q < 4; ++q)
      at[q] = std::size_t(bb.qy[b][q]) * pitch + std::size_t(bb.qx[b][q]) * std::size_t(step);
  }
};

// The values of a block's lanes l0 .. l0 + W - 1 (quads l0 / 4 on), each quad two rows of two values, from or to
// `base` at the quads' places.
template <class T, int W, class Vec>
SOFTGL_WIDE Vec LoadQuads(const T* base, const QuadPlaces& places, int l0) {
  const std::size_t pitch = places.pitch;
  if constexpr (sizeof(T) <= 4) {
    // Values of up to 32 bits: each quad row (two values) is one word, gathered into the vector in registers (a
    // vector read back from small stores would stall the processor).
    using Row = std::conditional_t<sizeof(T) == 4, std::uint64_t,
                                   std::conditional_t<sizeof(T) == 2, std::uint32_t, std::uint16_t>>;
    typedef Row Rows __attribute__((vector_size(sizeof(Vec))));
    Rows rows;
    for (int k = 0; k < W / 4; ++k) {
      const T* p = base + places.at[l0 / 4 + k];
      Row lo, hi;
      std::memcpy(&lo, p, sizeof lo);
      std::memcpy(&hi, p + pitch, sizeof hi);
      rows[2 * k] = lo;
      rows[2 * k + 1] = hi;
    }
    Vec r;
    std::memcpy(&r, &rows, sizeof r);
    return r;
  } else if constexpr (sizeof(T) == 8 && (W == 4 || W == 8)) {
    // 64-bit values: each quad row one 16-byte load, the rows joined in registers (as above).
    typedef T Pair __attribute__((vector_size(2 * sizeof(T))));
    typedef T Four __attribute__((vector_size(4 * sizeof(T))));
    auto quad = [&](int k) SOFTGL_WIDE_LAMBDA {
      const T* p = base + places.at[l0 / 4 + k];
      Pair lo, hi;
      std::memcpy(&lo, p, sizeof lo);
      std::memcpy(&hi, p + pitch, sizeof hi);
      return Four(__builtin_shufflevector(lo, hi, 0, 1, 2, 3));
    };
    const Four q0 = quad(0);
    if constexpr (W == 4) {
      return Vec(q0);
    } else {
      const Four q1 = quad(1);
      return Vec(__builtin_shufflevector(q0, q1, 0, 1, 2, 3, 4, 5, 6, 7));
    }
  } else {
    T lanes[W];
    for (int k = 0; k < W / 4; ++k) {
      const T* p = base + places.at[l0 / 4 + k];
      std::memcpy(lanes + 4 * k, p, 2 * sizeof(T));
      std::memcpy(lanes + 4 * k + 2, p + pitch, 2 * sizeof(T));
    }
    return LoadVec<Vec>(lanes);
  }
}
// Quads without a live lane (in `live`, the block's) are not written back: they change nothing, and a block's unused
// quads repeat its first quad's place.
template <class T, int W, class Vec>
SOFTGL_WIDE void StoreQuads(T* base, const QuadPlaces& places, std::uint32_t live, int l0, const Vec& v) {
  const std::size_t pitch = places.pitch;
  T lanes[W];
  StoreVec(lanes, v);
  for (int k = 0; k < W / 4; ++k) {
    const int q = l0 / 4 + k;
    if (!((live >> (4 * q)) & 0xFu)) continue;
    T* p = base + places.at[q];
    std::memcpy(p, lanes + 4 * k, 2 * sizeof(T));
    std::memcpy(p + pitch, lanes + 4 * k + 2, 2 * sizeof(T));
  }
}

// StencilUpdate for W lanes, where `where` holds.
template <int W>
SOFTGL_WIDE typename V<W>::I StencilOpLanes(const StencilFace& face, Enum op, typename V<W>::I s, typename V<W>::I where) {
  using I = typename V<W>::I;
  I v;
  switch (op) {
    case KEEP: return s;
    case ZERO: v = I{}; break;
    case REPLACE: v = I{} + std::clamp(face.ref, 0, 255); break;
    case INCR: v = s < 255 ? s + 1 : s; break;
    case DECR: v = s > 0 ? s - 1 : s; break;
    case INVERT: v = ~s & 0xFF; break;
    case INCR_WRAP: v = (s + 1) & 0xFF; break;
    case DECR_WRAP: v = (s - 1) & 0xFF; break;
    default: return s;
  }
  const std::int32_t wm = std::int32_t(face.write_mask & 0xFFu);
  v = (s & ~wm) | (v & wm);
  return where ? v : s;
}

// Depths in [0, 1] to a 16-bit buffer's values, round(d * 65535) to nearest even (adding and subtracting 1.5 * 2^23
// rounds as nearbyint does), as RenderTarget::Depth16.
template <int W>
SOFTGL_WIDE typename V<W>::I Depth16Lanes(typename V<W>::F d) {
  return __builtin_convertvector((d * 65535.0f + 12582912.0f) - 12582912.0f, typename V<W>::I);
}

// Output o of block b's lane `lane` into integer colour buffer `cb` (R8UI ... RGBA32I, RGB10_A2UI): the output's
// integers (its floats' bits) clamped to the channels' range, then the logic operation with the stored integers
// (on the channels' bits), through the colour mask. Integer buffers are never blended (OpenGL 4.6, section 17.3.6).
void IntegerLane(const FragmentOpsState& st, const BlockBuffer& bb, int b, int o, int lane, const ColorBuffer& cb) {
  const int x = bb.X(b, lane), y = bb.Y(b, lane);
  glm::vec4 color(bb.Color(b, o, 0)[lane], bb.Color(b, o, 1)[lane], bb.Color(b, o, 2)[lane], bb.Color(b, o, 3)[lane]);
  bool mask[4];
  st.Mask(o, mask);
  if (const Enum logic = st.LogicMode()) {
    const IntegerLayout k = IntegerLayoutOf(cb.layout);
    std::int32_t bits[4];
    std::memcpy(bits, &color.x, 16);
    std::uint8_t texel[16];
    std::int64_t v[4];
    for (int c = 0; c < 4; ++c) v[c] = IntegerValue(cb.layout, bits[c]);
    StoreIntegerTexel(cb.layout, texel, v);
    const glm::ivec4 src = IntegerTexel(cb.layout, texel), dst = IntegerTexel(cb.layout, cb.At(x, y));
    for (int c = 0; c < 4; ++c) {
      // (Sign-extended operands give a sign-extended result; an unsigned channel keeps its own bits.)
      const int width = k.packed ? (c < 3 ? 10 : 2) : 8 * k.bytes;
      std::uint32_t r = LogicOpBits(logic, std::uint32_t(src[c]), std::uint32_t(dst[c]));
      if (!k.is_signed && width < 32) r &= (1u << width) - 1u;
      bits[c] = std::int32_t(r);
    }
    std::memcpy(&color.x, bits, 16);
  }
  cb.Store(x, y, color, mask);
}

// Output o of block b's lane `lane` into colour buffer `cb` (present), through blending and the colour mask.
void ColourLane(const FragmentOpsState& st, const Unorm8Blend& blend8, const BlockBuffer& bb, int b, int o, int lane,
                const ColorBuffer& cb) {
  if (IsIntegerLayout(cb.layout)) return IntegerLane(st, bb, b, o, lane, cb);
  const int x = bb.X(b, lane), y = bb.Y(b, lane);
  glm::vec4 color(bb.Color(b, o, 0)[lane], bb.Color(b, o, 1)[lane], bb.Color(b, o, 2)[lane], bb.Color(b, o, 3)[lane]);
  if (cb.srgb || IsWideFixedPoint(cb.layout)) {
    // An sRGB buffer under FRAMEBUFFER_SRGB, or a fixed-point one of other than 8 bits (RGB565, RGBA4, RGB5_A1,
    // RGB10_A2, RGBA16, RG16, R16): the colour clamped as for any fixed-point buffer, blended in float with the
    // stored colour (decoded to linear for sRGB; the constant colour clamped), converted again on store.
    color = glm::clamp(color, 0.0f, 1.0f);
    for (int c = 0; c < 4; ++c)
      if (std::isnan(color[c])) color[c] = 0.0f;
    if (const Enum logic = st.LogicMode(); logic && !cb.srgb) {
      // The logic operation on each channel's fixed-point value: the colour's as Store rounds it, the stored one's
      // (exact), the result stored back through its value.
      const glm::vec4 dst = cb.Load(x, y);
      for (int c = 0; c < 4; ++c) {
        const int bits = FixedPointBits(cb.layout, c);
        if (!bits) continue;
        const std::uint32_t max = (1u << bits) - 1u;
        const auto q = [max](float v) { return std::uint32_t(std::nearbyint(v * float(max))); };
        color[c] = float(LogicOpBits(logic, q(color[c]), q(dst[c])) & max) / float(max);
      }
    }
    if (st.Blends(o)) {
      BlendState linear = st.blend;
      linear.color = glm::clamp(linear.color, 0.0f, 1.0f);
      color = Blend(linear, color, cb.Load(x, y));
    }
    bool mask[4];
    st.Mask(o, mask);
    cb.Store(x, y, color, mask);
    return;
  }
  if (cb.Normalized()) {
    // 8-bit channels: the exact integer blend on the pixel's bytes (channels the format lacks read 0 or 1).
    std::uint8_t* p = cb.At(x, y);
    const int n = cb.Bytes();
    std::uint8_t d[4] = {0, 0, 0, 255}, out[4];
    for (int c = 0; c < n; ++c) d[c] = p[c];
    if (cb.rgb_only) d[3] = 255;
    Blend8(blend8, color, d, out);
    const int channels = cb.layout == TexelLayout::kUnorm8x4 ? (cb.rgb_only ? 3 : 4) : n;
    for (int c = 0; c < channels; ++c)
      if (!((blend8.keep >> (8 * c)) & 0xFFu)) p[c] = out[c];
    return;
  }
  for (int c = 0; c < 4; ++c)
    if (std::isnan(color[c])) color[c] = 0.0f;
  if (st.Blends(o)) color = Blend(st.blend, color, cb.Load(x, y));
  bool mask[4];
  st.Mask(o, mask);
  cb.Store(x, y, color, mask);
}

// ---- Colour buffers, W lanes at a time ----

// W texels of a colour buffer: block lanes l0 .. l0 + W - 1 at their quads' places in the buffer (or sample plane)
// starting at `base`; `live` the block's live lanes (quads without one are not written back).
template <int W>
struct TexelQuads {
  std::uint8_t* base;
  const QuadPlaces& at;
  std::uint32_t live;
  int l0;
  template <class T, class Vec>
  SOFTGL_WIDE Vec Load() const { return LoadQuads<T, W, Vec>(reinterpret_cast<const T*>(base), at, l0); }
  template <class T, class Vec>
  SOFTGL_WIDE void Store(const Vec& v) const { StoreQuads<T, W>(reinterpret_cast<T*>(base), at, live, l0, v); }
};

// The exact 8-bit blend (Blend8Lanes) into an RGBA8, RGB8, RG8 or R8 buffer, the lanes of `go`: the stored bytes
// widened to RGBA words (channels the format lacks 0, alpha 255), blended, the format's bytes stored.
template <int W>
SOFTGL_WIDE void Unorm8Lanes(const Unorm8Blend& blend, const ColorBuffer& cb, const TexelQuads<W>& at,
                             const typename V<W>::F color[4], typename V<W>::I go) {
  using U = typename V<W>::U;
  switch (cb.layout) {
    case TexelLayout::kUnorm8x4: {
      const U pixels = at.template Load<std::uint32_t, U>();
      U result;
      if (cb.rgb_only) {  // alpha reads 1 and is not stored
        result = Blend8Lanes<W>(blend, color, pixels | 0xFF000000u);
        result = (result & 0x00FFFFFFu) | (pixels & 0xFF000000u);
      } else {
        result = Blend8Lanes<W>(blend, color, pixels);
      }
      at.template Store<std::uint32_t>(go ? result : pixels);
      return;
    }
    case TexelLayout::kUnorm8x2: {
      const U pixels = __builtin_convertvector((at.template Load<std::uint16_t, typename V<W>::S>()), U);
      const U result = Blend8Lanes<W>(blend, color, pixels | 0xFF000000u);
      at.template Store<std::uint16_t>(__builtin_convertvector(go ? result & 0xFFFFu : pixels, typename V<W>::S));
      return;
    }
    default: {  // kUnorm8x1
      const U pixels = __builtin_convertvector((at.template Load<std::uint8_t, typename V<W>::B>()), U);
      const U result = Blend8Lanes<W>(blend, color, pixels | 0xFF000000u);
      at.template Store<std::uint8_t>(__builtin_convertvector(go ? result & 0xFFu : pixels, typename V<W>::B));
      return;
    }
  }
}

// Blend for W lanes: the same factors and equations in the same order.
template <int W>
SOFTGL_WIDE void BlendFloatLanes(const BlendState& st, const glm::vec4& k, const typename V<W>::F s[4],
                                 const typename V<W>::F d[4], typename V<W>::F out[4]) {
  using F = typename V<W>::F;
  auto factor = [&](Enum f, int c) SOFTGL_WIDE_LAMBDA -> F {
    switch (f) {
      case ZERO: return F{};
      case ONE: return F{} + 1.0f;
      case SRC_COLOR: return s[c];
      case ONE_MINUS_SRC_COLOR: return 1.0f - s[c];
      case DST_COLOR: return d[c];
      case ONE_MINUS_DST_COLOR: return 1.0f - d[c];
      case SRC_ALPHA: return s[3];
      case ONE_MINUS_SRC_ALPHA: return 1.0f - s[3];
      case DST_ALPHA: return d[3];
      case ONE_MINUS_DST_ALPHA: return 1.0f - d[3];
      case CONSTANT_COLOR: return F{} + k[c];
      case ONE_MINUS_CONSTANT_COLOR: return F{} + (1.0f - k[c]);
      case CONSTANT_ALPHA: return F{} + k[3];
      case ONE_MINUS_CONSTANT_ALPHA: return F{} + (1.0f - k[3]);
      case SRC_ALPHA_SATURATE: {
        if (c == 3) return F{} + 1.0f;
        const F one_minus = 1.0f - d[3];
        return one_minus < s[3] ? one_minus : s[3];  // std::min(s.a, 1 - d.a)
      }
      default: return F{};
    }
  };
  for (int c = 0; c < 4; ++c) {
    const Enum eq = c == 3 ? st.eq_alpha : st.eq_rgb;
    switch (eq) {
      case MIN: out[c] = d[c] < s[c] ? d[c] : s[c]; break;  // std::min(s, d)
      case MAX: out[c] = s[c] < d[c] ? d[c] : s[c]; break;  // std::max(s, d)
      default: {
        const F sf = factor(c == 3 ? st.src_alpha : st.src_rgb, c);
        const F df = factor(c == 3 ? st.dst_alpha : st.dst_rgb, c);
        out[c] = eq == FUNC_SUBTRACT ? s[c] * sf - d[c] * df
                 : eq == FUNC_REVERSE_SUBTRACT ? d[c] * df - s[c] * sf
                                               : s[c] * sf + d[c] * df;
      }
    }
    out[c] = out[c] == out[c] ? out[c] : F{} + kBlendNaN;  // (as Blend: one NaN whatever the operands' order)
  }
}

// SrgbEncode8 for W lanes, by the bucket table (SrgbLaneTables): one gather by the bucket.
template <int W>
SOFTGL_WIDE typename V<W>::I SrgbEncodeLanes(const SrgbLaneTables& t, typename V<W>::F x) {
  using I = typename V<W>::I;
  I bits;
  std::memcpy(&bits, &x, sizeof bits);
  I i = (bits >> 16) - SrgbLaneTables::kBucket0;
  i = i > 0 ? i : I{};
  i = i < SrgbLaneTables::kBuckets - 1 ? i : I{} + (SrgbLaneTables::kBuckets - 1);
  const I bucket = TableLanes<W>(t.bucket, i);
  I k = bucket & 0xFF;
  k -= (bits & 0xFFFF) >= (bucket >> 8);  // (a comparison is -1 where it holds)
  k = x > 0.0f ? k : I{};  // NaN too
  return x >= 1.0f ? I{} + 255 : k;
}

// FloatToUnorm8 for W lanes: clamped to [0, 1] (NaN as 0), round(f * 255) to nearest even.
template <int W>
SOFTGL_WIDE typename V<W>::I Unorm8OfLanes(typename V<W>::F x) {
  using F = typename V<W>::F;
  x = x > 0.0f ? x : F{};
  x = x < 1.0f ? x : F{} + 1.0f;
  return __builtin_convertvector((x * 255.0f + 12582912.0f) - 12582912.0f, typename V<W>::I);
}

// An RGBA32F buffer's texel of lane k of `at`: in quad row k / 2 of the block's quads.
template <int W>
SOFTGL_WIDE float* Float4TexelAt(const TexelQuads<W>& at, int k) {
  float* p = reinterpret_cast<float*>(at.base) + 4 * at.at.at[at.l0 / 4 + k / 4];
  return p + 4 * (std::size_t((k >> 1) & 1) * at.at.pitch + std::size_t(k & 1));
}

// The buffers blended in float (ColourPath::kFloat), the lanes of `go`: each texel decoded to RGBA floats (the
// channels the layout lacks (0, 0, 0, 1)), the fragment colour clamped for a fixed-point buffer (NaN as 0 either
// way), blended, the colour mask applied, encoded again; as ColourLane does it lane by lane. `keep` is the
// 8-bit buffers' mask of kept bytes (the sRGB buffer's). `at` loads and stores the texels: TexelQuads, or
// ElementTexels for samples side by side (RGB565 and sRGB, the layouts the context's framebuffer has).
template <int W, TexelLayout L, bool kSrgb, class At>
SOFTGL_WIDE void FloatLanesOf(const FragmentOpsState& st, const FragmentOpsPlan& plan, int o, bool rgb_only,
                              const At& at, const typename V<W>::F color[4], typename V<W>::I go) {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  using D = typename V<W>::D;
  using I = typename V<W>::I;
  const std::uint32_t keep = plan.blend[o].keep;
  const SrgbLaneTables* const srgb = plan.srgb;  // (set where a buffer is sRGB)
  constexpr bool kFixed = kSrgb || IsWideFixedPoint(L);
  constexpr bool kPacked = IsPackedUnorm(L), kUnorm16 = IsUnorm16(L);
  constexpr int kBytes = BytesPerTexel(L);
  auto as_f = [](U u) SOFTGL_WIDE_LAMBDA {
    F f;
    std::memcpy(&f, &u, sizeof f);
    return f;
  };
  auto as_u = [](F f) SOFTGL_WIDE_LAMBDA {
    U u;
    std::memcpy(&u, &f, sizeof u);
    return u;
  };
  // The stored texels, decoded where blending or the colour mask reads them (an sRGB buffer keeps its masked
  // bytes as they are).
  const bool all_channels = st.color_masks[o] == 0xF;
  const bool decode = st.Blends(o) || (!kSrgb && !all_channels);
  F d[4] = {F{}, F{}, F{}, F{} + 1.0f};
  U word{};
  D dword{};
  if constexpr (L == TexelLayout::kFloat32x4) {
    LoadComponentsAt<W>([&](int k) SOFTGL_WIDE_LAMBDA { return Float4TexelAt(at, k); }, d);
  } else if constexpr (kBytes == 8) {
    dword = at.template Load<std::uint64_t, D>();
    if constexpr (L == TexelLayout::kFloat32x2) {
      d[0] = as_f(__builtin_convertvector(dword & 0xFFFFFFFFu, U));
      d[1] = as_f(__builtin_convertvector(dword >> 32, U));
    } else if (decode) {
      for (int c = 0; c < 4; ++c) {
        const U k = __builtin_convertvector((dword >> (16 * c)) & 0xFFFFu, U);
        d[c] = kUnorm16 ? __builtin_convertvector(k, F) / 65535.0f : HalfLanes<W>(k);
      }
    }
  } else if constexpr (kBytes == 2) {
    word = __builtin_convertvector((at.template Load<std::uint16_t, typename V<W>::S>()), U);
    if constexpr (L == TexelLayout::kFloat16x1) d[0] = decode ? HalfLanes<W>(word) : F{};
    else if constexpr (kUnorm16) d[0] = __builtin_convertvector(word, F) / 65535.0f;
  } else {
    word = at.template Load<std::uint32_t, U>();
    if constexpr (L == TexelLayout::kFloat32x1) {
      d[0] = as_f(word);
    } else if (!decode) {
    } else if constexpr (L == TexelLayout::kFloat16x2) {
      d[0] = HalfLanes<W>(word & 0xFFFFu);
      d[1] = HalfLanes<W>(word >> 16);
    } else if constexpr (L == TexelLayout::kUnorm16x2) {
      d[0] = __builtin_convertvector(word & 0xFFFFu, F) / 65535.0f;
      d[1] = __builtin_convertvector(word >> 16, F) / 65535.0f;
    } else if constexpr (L == TexelLayout::kFloat11x11x10) {  // each small float at a half's places
      d[0] = HalfLanes<W>((word & 0x7FFu) << 4);
      d[1] = HalfLanes<W>(((word >> 11) & 0x7FFu) << 4);
      d[2] = HalfLanes<W>((word >> 22) << 5);
    } else if constexpr (kPacked) {
    } else {  // sRGB8_ALPHA8, SRGB8
      for (int c = 0; c < 3; ++c) d[c] = TableLanes<W>(srgb->decode, I((word >> (8 * c)) & 0xFFu));
      d[3] = rgb_only ? F{} + 1.0f : __builtin_convertvector(word >> 24, F) / 255.0f;
    }
  }
  if constexpr (kPacked) {
    constexpr PackedUnorm kPacking = PackingOf(L);
    for (int c = 0; c < 4; ++c)
      if (kPacking.bits[c] && decode) {
        const float max = float((1u << kPacking.bits[c]) - 1u);
        d[c] = __builtin_convertvector((word >> kPacking.shift[c]) & ((1u << kPacking.bits[c]) - 1u), F) / max;
      }
  }
  // The fragment colour, blended.
  F r[4];
  for (int c = 0; c < 4; ++c) {
    F x = color[c];
    if constexpr (kFixed) {
      x = x > 0.0f ? x : F{};  // (NaN as 0)
      x = x < 1.0f ? x : F{} + 1.0f;
    } else {
      x = x == x ? x : F{};
    }
    r[c] = x;
  }
  if (st.Blends(o)) {
    const glm::vec4 k = kFixed ? glm::clamp(st.blend.color, 0.0f, 1.0f) : st.blend.color;
    const F s[4] = {r[0], r[1], r[2], r[3]};
    BlendFloatLanes<W>(st.blend, k, s, d, r);
  }
  // Encoded, through the colour mask.
  if constexpr (kSrgb) {
    U out = U(Unorm8OfLanes<W>(r[3])) << 24;
    for (int c = 0; c < 3; ++c) out |= U(SrgbEncodeLanes<W>(*srgb, r[c])) << (8 * c);
    out = (word & keep) | (out & ~keep);
    at.template Store<std::uint32_t>(go ? out : word);
    return;
  }
  for (int c = 0; c < 4; ++c)
    if (!st.Writes(o, c)) r[c] = d[c];
  // A fixed-point channel: clamped to [0, 1] (NaN as 0), round(c * max) to nearest even.
  auto fixed = [](F x, float max) SOFTGL_WIDE_LAMBDA {
    x = x > 0.0f ? x : F{};
    x = x < 1.0f ? x : F{} + 1.0f;
    return __builtin_convertvector((x * max + 12582912.0f) - 12582912.0f, U);
  };
  // The logic operation on the encoded texel and the stored one, the masked channels' bits kept (LogicOpBits
  // works bit by bit, so on whole texels as on each channel).
  const Enum logic = st.LogicMode();
  auto logic_op = [&](auto out, auto stored, auto channel_bits) SOFTGL_WIDE_LAMBDA {
    using T = decltype(out);
    if (!logic) return out;
    using Word = std::remove_cvref_t<decltype(stored[0])>;
    Word keep_bits = 0;
    for (int c = 0; c < 4; ++c)
      if (!st.Writes(o, c)) keep_bits |= Word(channel_bits(c));
    return T((stored & keep_bits) | (LogicOpBits(logic, out, stored) & ~keep_bits));
  };
  if constexpr (kPacked) {
    constexpr PackedUnorm kPacking = PackingOf(L);
    U out{};
    for (int c = 0; c < 4; ++c)
      if (kPacking.bits[c]) out |= fixed(r[c], float((1u << kPacking.bits[c]) - 1u)) << kPacking.shift[c];
    out = logic_op(out, word, [&](int c) { return ((1u << kPacking.bits[c]) - 1u) << kPacking.shift[c]; });
    if constexpr (kBytes == 4) at.template Store<std::uint32_t>(go ? out : word);
    else at.template Store<std::uint16_t>(__builtin_convertvector(go ? out : word, typename V<W>::S));
  } else if constexpr (L == TexelLayout::kUnorm16x4) {
    D out{};
    for (int c = 0; c < 4; ++c) out |= __builtin_convertvector(fixed(r[c], 65535.0f), D) << (16 * c);
    out = logic_op(out, dword, [](int c) { return std::uint64_t(0xFFFF) << (16 * c); });
    at.template Store<std::uint64_t>(__builtin_convertvector(go, D) != 0 ? out : dword);
  } else if constexpr (L == TexelLayout::kUnorm16x2) {
    const U out = logic_op(fixed(r[0], 65535.0f) | (fixed(r[1], 65535.0f) << 16), word,
                           [](int c) { return c < 2 ? 0xFFFFu << (16 * c) : 0u; });
    at.template Store<std::uint32_t>(go ? out : word);
  } else if constexpr (L == TexelLayout::kUnorm16x1) {
    const U out = logic_op(fixed(r[0], 65535.0f), word, [](int c) { return c < 1 ? 0xFFFFu : 0u; });
    at.template Store<std::uint16_t>(__builtin_convertvector(go ? out : word, typename V<W>::S));
  } else if constexpr (L == TexelLayout::kFloat32x4) {
    for (int c = 0; c < 4; ++c) r[c] = go ? r[c] : d[c];
    unsigned quads = 0;  // those with a live lane (StoreQuads)
    for (int q = 0; q < W / 4; ++q) quads |= ((at.live >> (at.l0 + 4 * q)) & 0xFu) ? 1u << q : 0u;
    StoreComponentsAt<W>([&](int k) SOFTGL_WIDE_LAMBDA { return Float4TexelAt(at, k); }, r, quads);
  } else if constexpr (L == TexelLayout::kFloat32x2) {
    const D out = __builtin_convertvector(as_u(r[0]), D) | (__builtin_convertvector(as_u(r[1]), D) << 32);
    at.template Store<std::uint64_t>(__builtin_convertvector(go, D) != 0 ? out : dword);
  } else if constexpr (L == TexelLayout::kFloat16x4) {
    D out{};
    for (int c = 0; c < 4; ++c) out |= __builtin_convertvector(HalfBitsLanes<W>(r[c]), D) << (16 * c);
    at.template Store<std::uint64_t>(__builtin_convertvector(go, D) != 0 ? out : dword);
  } else if constexpr (L == TexelLayout::kFloat16x2) {
    const U out = HalfBitsLanes<W>(r[0]) | (HalfBitsLanes<W>(r[1]) << 16);
    at.template Store<std::uint32_t>(go ? out : word);
  } else if constexpr (L == TexelLayout::kFloat16x1) {
    const U out = HalfBitsLanes<W>(r[0]);
    at.template Store<std::uint16_t>(__builtin_convertvector(go ? out : word, typename V<W>::S));
  } else if constexpr (L == TexelLayout::kFloat11x11x10) {
    const U out = SmallFloatBitsLanes<W, 6>(r[0]) | (SmallFloatBitsLanes<W, 6>(r[1]) << 11) |
                  (SmallFloatBitsLanes<W, 5>(r[2]) << 22);
    at.template Store<std::uint32_t>(go ? out : word);
  } else {  // kFloat32x1
    at.template Store<std::uint32_t>(go ? as_u(r[0]) : word);
  }
}
// Integer colour buffers (ColourPath::kInteger), the lanes of `go`: each channel's integers (the output's floats'
// bits) clamped to the channel's range, packed into the texel's 32-bit words, combined with the stored words by
// the logic operation if one is on (bit by bit: on whole words as on each channel's bits), the channels the colour
// mask keeps taken from the stored texel; what IntegerLane stores lane by lane.
template <int W>
SOFTGL_WIDE void IntegerLanes(const FragmentOpsState& st, int o, const ColorBuffer& cb, const TexelQuads<W>& at,
                              const typename V<W>::F color[4], typename V<W>::I go) {
  using U = typename V<W>::U;
  using I = typename V<W>::I;
  using D = typename V<W>::D;
  using F = typename V<W>::F;
  const IntegerLayout k = IntegerLayoutOf(cb.layout);
  bool mask[4];
  st.Mask(o, mask);
  U word[4] = {};
  std::uint32_t keep[4] = {0, 0, 0, 0};  // the bits of each word the colour mask keeps
  for (int c = 0; c < k.channels; ++c) {
    U v;
    std::memcpy(&v, &color[c], sizeof v);
    const int bits = k.packed ? (c < 3 ? 10 : 2) : 8 * k.bytes, shift = k.packed ? 10 * c : 8 * k.bytes * c;
    const std::uint32_t ones = bits == 32 ? ~0u : (1u << bits) - 1u;
    if (bits < 32 && k.is_signed) {
      const I lo = I{} - (1 << (bits - 1)), hi = I{} + ((1 << (bits - 1)) - 1);
      I value = I(v);
      value = value < lo ? lo : value;
      value = value > hi ? hi : value;
      v = U(value) & ones;
    } else if (bits < 32) {
      v = v > ones ? U{} + ones : v;  // (unsigned: the bits of a negative int are above every channel's range)
    }
    word[shift / 32] |= v << (shift % 32);
    if (!mask[c]) keep[shift / 32] |= ones << (shift % 32);
  }
  const Enum logic = st.LogicMode();
  const auto merge = [&](U fresh, U old, int w) SOFTGL_WIDE_LAMBDA {
    if (logic) fresh = LogicOpBits(logic, fresh, old);
    return go ? ((fresh & ~keep[w]) | (old & keep[w])) : old;
  };
  switch (cb.Bytes()) {
    case 1: {
      const U old = __builtin_convertvector((at.template Load<std::uint8_t, typename V<W>::B>()), U);
      at.template Store<std::uint8_t>(__builtin_convertvector(merge(word[0], old, 0), typename V<W>::B));
      return;
    }
    case 2: {
      const U old = __builtin_convertvector((at.template Load<std::uint16_t, typename V<W>::S>()), U);
      at.template Store<std::uint16_t>(__builtin_convertvector(merge(word[0], old, 0), typename V<W>::S));
      return;
    }
    case 4: {
      const U old = at.template Load<std::uint32_t, U>();
      at.template Store<std::uint32_t>(merge(word[0], old, 0));
      return;
    }
    case 8: {
      const D old = at.template Load<std::uint64_t, D>();
      const U old0 = __builtin_convertvector(old, U), old1 = __builtin_convertvector(old >> 32, U);
      const D out = __builtin_convertvector(merge(word[0], old0, 0), D) |
                    (__builtin_convertvector(merge(word[1], old1, 1), D) << 32);
      at.template Store<std::uint64_t>(out);
      return;
    }
    default: {  // 16 bytes: four words, as RGBA32F's texels (their bits only moved)
      F old[4], out[4];
      LoadComponentsAt<W>([&](int t) SOFTGL_WIDE_LAMBDA { return Float4TexelAt(at, t); }, old);
      for (int w = 0; w < 4; ++w) {
        U old_bits;
        std::memcpy(&old_bits, &old[w], sizeof old_bits);
        const U merged = merge(word[w], old_bits, w);
        std::memcpy(&out[w], &merged, sizeof merged);
      }
      unsigned quads = 0;  // those with a live lane (StoreQuads)
      for (int q = 0; q < W / 4; ++q) quads |= ((at.live >> (at.l0 + 4 * q)) & 0xFu) ? 1u << q : 0u;
      StoreComponentsAt<W>([&](int t) SOFTGL_WIDE_LAMBDA { return Float4TexelAt(at, t); }, out, quads);
      return;
    }
  }
}

template <int W>
SOFTGL_WIDE void FloatLanes(const FragmentOpsState& st, const FragmentOpsPlan& plan, int o, const ColorBuffer& cb,
                            const TexelQuads<W>& at, const typename V<W>::F color[4], typename V<W>::I go) {
  switch (cb.layout) {
    case TexelLayout::kFloat32x4: return FloatLanesOf<W, TexelLayout::kFloat32x4, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat32x2: return FloatLanesOf<W, TexelLayout::kFloat32x2, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat32x1: return FloatLanesOf<W, TexelLayout::kFloat32x1, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat16x4: return FloatLanesOf<W, TexelLayout::kFloat16x4, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat16x2: return FloatLanesOf<W, TexelLayout::kFloat16x2, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat16x1: return FloatLanesOf<W, TexelLayout::kFloat16x1, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kFloat11x11x10:
      return FloatLanesOf<W, TexelLayout::kFloat11x11x10, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm565: return FloatLanesOf<W, TexelLayout::kUnorm565, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm4444: return FloatLanesOf<W, TexelLayout::kUnorm4444, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm5551: return FloatLanesOf<W, TexelLayout::kUnorm5551, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm1010102:
      return FloatLanesOf<W, TexelLayout::kUnorm1010102, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm16x4: return FloatLanesOf<W, TexelLayout::kUnorm16x4, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm16x2: return FloatLanesOf<W, TexelLayout::kUnorm16x2, false>(st, plan, o, cb.rgb_only, at, color, go);
    case TexelLayout::kUnorm16x1: return FloatLanesOf<W, TexelLayout::kUnorm16x1, false>(st, plan, o, cb.rgb_only, at, color, go);
    default: return FloatLanesOf<W, TexelLayout::kUnorm8x4, true>(st, plan, o, cb.rgb_only, at, color, go);  // sRGB
  }
}

// What a batch's blocks share.
struct BlockOpsContext {
  const FragmentOpsState* state;
  const BlockBuffer* blocks;
  const RenderTarget* target;
  const FragmentOpsPlan* plan;
  const Unorm8Blend* blend;  // for color[0] when it is RGBA8
  bool shader_depth;
  bool stencil_test, depth_test, any_color;
  const StencilFace* face;
  std::uint64_t* passed;  // counts the lanes that pass every test, while an occlusion query is active (else null)
  // A multisampled target: its samples' depths (null: single-sampled, the depth in gl_FragCoord.z).
  const SampleDepths* depths;
  int samples;  // planes: 1 when single-sampled
};

// The lanes of block b that go through the operations of sample plane s, and their depths there.
inline std::uint32_t PlaneLanes(const BlockOpsContext& ctx, int b, int s) {
  return ctx.depths ? ctx.blocks->live[b] & ctx.blocks->sample_live[b][s] : ctx.blocks->live[b];
}
// (lane l's at [l * PlaneStride])
inline const float* PlaneDepths(const BlockOpsContext& ctx, int b, int s) {
  if (ctx.shader_depth) return ctx.blocks->Depth(b);
  return ctx.depths ? ctx.depths->Lanes(b, s) : ctx.blocks->frag_coord[b][2];
}
inline int PlaneStride(const BlockOpsContext& ctx) { return ctx.depths && !ctx.shader_depth ? ctx.depths->Stride() : 1; }

// The stencil test, the depth test, the stencil operations and the colour write on W values at once (W lanes of one
// sample plane, or W elements of samples side by side), `go` those covered. `io` reads and writes each buffer's
// values at their places (Stencil, SetStencil, Depth, SetDepth, Depth16, SetDepth16, Pixels, SetPixels), gives the
// values' depths (Z) and the colour to write over the pixels (Result: blended, or the converted colour through the
// colour mask). kDepthFunc, where not 0, is the state's depth comparison as a constant; kPlain: the state is known
// to be the plainest (PlainOps), its tests and writes folded at compile time.
template <int W, class Io, Enum kDepthFunc = 0, bool kPlain = false>
SOFTGL_WIDE void VectorOps(const BlockOpsContext& ctx, typename V<W>::I go, const Io& io) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  const RenderTarget& t = *ctx.target;
  const FragmentOpsState& st = *ctx.state;
  const bool stencil_test = !kPlain && ctx.stencil_test, depth_test = kPlain || ctx.depth_test;
  const bool depth16 = !kPlain && t.depth16, depth_write = kPlain || st.depth_write, colour = kPlain || io.colour;
  std::uint64_t* const passed = kPlain ? nullptr : ctx.passed;
  I sten{};
  if (stencil_test) {
    sten = __builtin_convertvector(io.Stencil(), I);
    const StencilFace& f = *ctx.face;
    const std::int32_t m = std::int32_t(f.value_mask & 0xFFu);
    const I pass = Compare(f.func, I{} + (std::clamp(f.ref, 0, 255) & m), sten & m);
    sten = StencilOpLanes<W>(f, f.sfail, sten, go & ~pass);
    go &= pass;
  }
  if (depth_test) {
    const Enum depth_func = kDepthFunc ? kDepthFunc : st.depth_func;
    const F z = io.Z();
    F zc = z > 0.0f ? z : F{} + 0.0f;  // clamped to [0, 1]; NaN fails below
    zc = zc < 1.0f ? zc : F{} + 1.0f;
    I pass;
    if (depth16) {  // 16 bits: the depths converted, round(zc * 65535) (as RenderTarget::Depth16), compared
      const I stored = __builtin_convertvector(io.Depth16(), I);
      const I zq = Depth16Lanes<W>(zc);
      pass = Compare(depth_func, zq, stored) & (z == z);
      if (depth_write) io.SetDepth16(__builtin_convertvector((go & pass) ? zq : stored, typename V<W>::S));
    } else {
      const F stored = io.Depth();
      pass = Compare(depth_func, zc, stored) & (z == z);
      if (depth_write) io.SetDepth((go & pass) ? zc : stored);
    }
    if (stencil_test) {
      sten = StencilOpLanes<W>(*ctx.face, ctx.face->dpfail, sten, go & ~pass);
      sten = StencilOpLanes<W>(*ctx.face, ctx.face->dppass, sten, go & pass);
    }
    go &= pass;
  } else if (stencil_test) {
    sten = StencilOpLanes<W>(*ctx.face, ctx.face->dppass, sten, go);
  }
  if (stencil_test) io.SetStencil(__builtin_convertvector(sten, typename V<W>::B));
  if (passed) *passed += std::uint64_t(__builtin_popcount(MaskToBits<W>(go, 0)));
  if (colour) io.WriteColour(go);
}

// VectorOps' access to sample plane s (kSamples; else the single-sampled target) of block b's lanes l0 .. l0 + W - 1.
// kOne: colour buffer 0 RGBA8 (or none) and no other (FragmentOpsPlan::one_rgba8), the colour given (`color`,
// and without blending its bytes, `packed`).
template <int W, bool kSamples, bool kOne>
struct PlaneIo {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  const BlockOpsContext& ctx;
  const RenderTarget& t;
  const QuadPlaces &depth_at, &stencil_at;
  const QuadPlaces* colour_at;  // each colour buffer's
  int b, s, l0;
  int buffers;  // colour buffers 0 .. buffers - 1 may be written (plan->path)
  bool colour;
  const F* color;  // kOne: the lanes' colour channels
  U packed;        // kOne, without blending: the colour's bytes
  SOFTGL_WIDE std::uint32_t live() const { return ctx.blocks->live[b]; }
  SOFTGL_WIDE std::size_t Plane(std::size_t plane) const { return kSamples ? plane * std::size_t(s) : 0; }
  SOFTGL_WIDE typename V<W>::B Stencil() const {
    return LoadQuads<std::uint8_t, W, typename V<W>::B>(t.stencil + Plane(t.stencil_plane), stencil_at, l0);
  }
  SOFTGL_WIDE void SetStencil(typename V<W>::B v) const {
    StoreQuads<std::uint8_t, W>(t.stencil + Plane(t.stencil_plane), stencil_at, live(), l0, v);
  }
  SOFTGL_WIDE F Depth() const { return LoadQuads<float, W, F>(t.depth + Plane(t.depth_plane), depth_at, l0); }
  SOFTGL_WIDE void SetDepth(F v) const { StoreQuads<float, W>(t.depth + Plane(t.depth_plane), depth_at, live(), l0, v); }
  SOFTGL_WIDE typename V<W>::S Depth16() const {
    return LoadQuads<std::uint16_t, W, typename V<W>::S>(t.depth16 + Plane(t.depth_plane), depth_at, l0);
  }
  SOFTGL_WIDE void SetDepth16(typename V<W>::S v) const {
    StoreQuads<std::uint16_t, W>(t.depth16 + Plane(t.depth_plane), depth_at, live(), l0, v);
  }
  SOFTGL_WIDE F Z() const {
    const BlockBuffer& bb = *ctx.blocks;
    if (ctx.shader_depth) return LoadVec<F>(bb.Depth(b) + l0);
    if constexpr (kSamples) return LoadVec<F>(ctx.depths->z[b][s] + l0);
    return LoadVec<F>(bb.frag_coord[b][2] + l0);
  }
  // Each colour buffer by its path, the lanes of `go`.
  SOFTGL_WIDE void WriteColour(typename V<W>::I go) const {
    const BlockBuffer& bb = *ctx.blocks;
    if constexpr (kOne) {
      auto* pixels = reinterpret_cast<std::uint32_t*>(t.color[0].data) + Plane(t.color[0].plane);
      const U dst = LoadQuads<std::uint32_t, W, U>(pixels, colour_at[0], l0);
      const U result = ctx.blend->blend ? Blend8Lanes<W>(*ctx.blend, color, dst) : (dst & ctx.blend->keep) | packed;
      StoreQuads<std::uint32_t, W>(pixels, colour_at[0], live(), l0, go ? result : dst);
      return;
    }
    for (int o = 0; o < buffers; ++o) {
      const ColourPath path = ctx.plan->path[o];
      if (path == ColourPath::kNone) continue;
      const ColorBuffer& cb = t.color[o];
      std::uint8_t* base = cb.data + Plane(cb.plane) * std::size_t(cb.Bytes());
      F color[4];
      for (int c = 0; c < 4; ++c) color[c] = LoadVec<F>(bb.Color(b, o, c) + l0);
      const TexelQuads<W> at{base, colour_at[o], live(), l0};
      if (path == ColourPath::kInteger) {
        IntegerLanes<W>(*ctx.state, o, cb, at, color, go);
        continue;
      }
      if (path == ColourPath::kUnorm8) Unorm8Lanes<W>(ctx.plan->blend[o], cb, at, color, go);
      else FloatLanes<W>(*ctx.state, *ctx.plan, o, cb, at, color, go);
    }
  }
};

// The per-fragment operations on block b (inside the target), W lanes at a time, on every sample plane the lanes
// cover (kSamples: ctx.depths given). kOne (one RGBA8 buffer or none): the colour converted to bytes once for all
// the planes.
template <int W, bool kSamples, bool kOne, Enum kDepthFunc = 0, bool kPlain = false>
SOFTGL_WIDE void BlockOps(const BlockOpsContext& ctx, int b) {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  const BlockBuffer& bb = *ctx.blocks;
  const RenderTarget& t = *ctx.target;
  const int buffers = ctx.any_color ? ctx.plan->buffers : 0;
  constexpr std::uint32_t kChunk = (1u << W) - 1u;
  const std::uint32_t live = bb.live[b];
  const QuadPlaces depth_at(bb, b, t.depth_pitch);
  const QuadPlaces stencil_at = t.stencil_pitch == t.depth_pitch ? depth_at : QuadPlaces(bb, b, t.stencil_pitch);
  QuadPlaces colour_at[kMaxColorOutputs];
  for (int o = 0; o < std::max(buffers, 1); ++o)
    colour_at[o] = t.color[o].pitch != t.depth_pitch ? QuadPlaces(bb, b, t.color[o].pitch) : depth_at;
  for (int l0 = 0; l0 < kLanes; l0 += W) {
    if (!((live >> l0) & kChunk)) continue;
    // kOne: the lanes' colour (read only where `colour` holds; the block buffer's colour is always there to load)
    F color[4];
    for (int c = 0; c < 4; ++c) color[c] = kOne ? LoadVec<F>(bb.Color(b, 0, c) + l0) : F{};
    U packed{};  // kOne, without blending: the colour's bytes through the colour mask
    if (kOne && buffers > 0 && !ctx.blend->blend) packed = Blend8Lanes<W>(*ctx.blend, color, U{});
    for (int s = 0; s < (kSamples ? ctx.samples : 1); ++s) {
      const std::uint32_t lanes = kSamples ? live & bb.sample_live[b][s] : live;
      if (!((lanes >> l0) & kChunk)) continue;
      const PlaneIo<W, kSamples, kOne> io{ctx, t, depth_at, stencil_at, colour_at, b, s, l0, buffers, buffers > 0,
                                          color, packed};
      VectorOps<W, PlaneIo<W, kSamples, kOne>, kDepthFunc, kPlain>(ctx, BitsToMask<W>(lanes, l0), io);
    }
  }
}
// BlockOps with kOne chosen from the plan.
template <int W, bool kSamples>
SOFTGL_WIDE void BlockOpsEither(const BlockOpsContext& ctx, int b) {
  if (ctx.plan->one_rgba8) BlockOps<W, kSamples, true>(ctx, b);
  else BlockOps<W, kSamples, false>(ctx, b);
}

// ---- Samples side by side ----
//
// Into an interleaved target (RenderTarget::interleaved) a block's values go in element order: element e is sample
// e % S of lane e / S. A quad row's 2 S elements are one run of memory (its two pixels' samples), so W elements are
// one load or store of a run, or of two runs when a run is shorter than W.
template <int W, int S>
struct Elements {
  static constexpr int kRun = 2 * S;                       // elements of a quad row
  static constexpr int kPieces = W > kRun ? W / kRun : 1;  // runs in W elements
  static constexpr int kPiece = W > kRun ? kRun : W;       // elements from each
  static constexpr int kChunks = kLanes * S / W;           // W elements at a time over a block
};
// fn(chunk) for each chunk of W elements that holds some of `lanes`, in order.
template <int W, int S, class Fn>
SOFTGL_WIDE void ForEachChunk(std::uint32_t lanes, Fn&& fn) {
  if constexpr (W >= S) {
    constexpr int kL = W / S;  // lanes to a chunk: the chunk's bit at its first lane
    std::uint32_t m = lanes;
    for (int i = 1; i < kL; ++i) m |= lanes >> i;
    std::uint32_t pattern = 0;
    for (int l = 0; l < kLanes; l += kL) pattern |= 1u << l;
    for (m &= pattern; m; m &= m - 1) fn(__builtin_ctz(m) / kL);
  } else {
    constexpr int kPer = S / W;  // chunks to a lane
    for (std::uint32_t m = lanes; m; m &= m - 1)
      for (int k = 0; k < kPer; ++k) fn(__builtin_ctz(m) * kPer + k);
  }
}

// Where each of a block's eight quad rows starts (quad q's rows 2 q and 2 q + 1), from its quad places.
struct RowPlaces {
  std::size_t at[8];
  SOFTGL_WIDE explicit RowPlaces(const QuadPlaces& q) {
    for (int r = 0; r < 8; ++r) at[r] = q.at[r >> 1] + std::size_t(r & 1) * q.pitch;
  }
  // Where piece k of the W elements from e0 starts.
  template <int W, int S>
  SOFTGL_WIDE std::size_t At(int e0, int k) const {
    using E = Elements<W, S>;
    const int e = e0 + k * E::kPiece;
    return at[e / E::kRun] + std::size_t(e % E::kRun);
  }
};
template <class T, int W, int S, class Vec>
SOFTGL_WIDE Vec LoadElements(const T* base, const RowPlaces& at, int e0) {
  using E = Elements<W, S>;
  if constexpr (E::kPieces == 1) {
    return LoadVec<Vec>(base + at.template At<W, S>(e0, 0));
  } else {
    T values[W];
    for (int k = 0; k < E::kPieces; ++k) std::memcpy(values + k * E::kPiece, base + at.template At<W, S>(e0, k), sizeof(T) * E::kPiece);
    return LoadVec<Vec>(values);
  }
}
template <class T, int W, int S, class Vec>
SOFTGL_WIDE void StoreElements(T* base, const RowPlaces& at, int e0, const Vec& v) {
  using E = Elements<W, S>;
  if constexpr (E::kPieces == 1) {
    StoreVec(base + at.template At<W, S>(e0, 0), v);
  } else {
    T values[W];
    StoreVec(values, v);
    for (int k = 0; k < E::kPieces; ++k) std::memcpy(base + at.template At<W, S>(e0, k), values + k * E::kPiece, sizeof(T) * E::kPiece);
  }
}
// Values spread over W elements: element e takes v[e / S].
template <int S, class Vec, std::size_t... E>
SOFTGL_WIDE auto SpreadLanes(const Vec& v, std::index_sequence<E...>) {
  return __builtin_shufflevector(v, v, int(E / S)...);
}
// The W elements of lanes[0 ..] (the W / S lanes they cover, read alone, straight into a register: a vector read
// back from narrower stores would stall): element e takes lanes[e / S]. T is 32 bits.
template <int W, int S, class Vec, class T>
SOFTGL_WIDE Vec Spread(const T* lanes) {
  static_assert(sizeof(T) == 4);
  constexpr int kCovered = W >= S ? W / S : 1;
  if constexpr (kCovered == 1) {
    return Vec{} + lanes[0];
  } else if constexpr (kCovered == 2) {
    std::uint64_t pair;
    std::memcpy(&pair, lanes, 8);
    using Q = typename V<W>::Q;
    return SpreadLanes<S>(Vec(Q{} + pair), std::make_index_sequence<W>{});
  } else if constexpr (kCovered == W) {
    return LoadVec<Vec>(lanes);
  } else {  // four lanes
    typedef T Four __attribute__((vector_size(16)));
    return SpreadLanes<S>(LoadVec<Four>(lanes), std::make_index_sequence<W>{});
  }
}
// The covered elements of a block, W at a time: for lane bits `covered[s]` of each sample (live lanes only).
template <int W, int S>
struct ElementCoverage {
  using I = typename V<W>::I;
  static constexpr int kPatterns = S > W ? S / W : 1;  // chunks repeat their samples every kPatterns
  I bits[kPatterns];  // element e: covered[sample of e] (the lane bits of its sample)
  I lane_of;          // element e's lane, less the chunk's first
  SOFTGL_WIDE explicit ElementCoverage(const std::uint32_t* covered) {
    for (int p = 0; p < kPatterns; ++p)
      for (int e = 0; e < W; ++e) bits[p][e] = std::int32_t(covered[(p * W + e) % S]);
    for (int e = 0; e < W; ++e) lane_of[e] = e / S;
  }
  SOFTGL_WIDE I Mask(int chunk) const {
    const int e0 = chunk * W;
    return ((bits[chunk % kPatterns] >> (lane_of + e0 / S)) & 1) != 0;
  }
};
// A chunk's element bits (MaskToBits) back to lane bits per sample, for S <= 4 and S <= W: table[m] holds, at bit
// 16 s + i, the bit of chunk-lane i's sample s. (S = 8 goes element by element.)
template <int W, int S>
struct ElementBits {
  std::uint64_t table[1 << W];
  constexpr ElementBits() : table() {
    for (int m = 0; m < (1 << W); ++m)
      for (int e = 0; e < W; ++e)
        if ((m >> e) & 1) table[m] |= std::uint64_t(1) << (16 * (e % S) + e / S);
  }
};
template <int W, int S>
SOFTGL_WIDE void AddElementBits(std::uint32_t bits, int e0, std::uint64_t& packed, std::uint32_t* per_sample) {
  if constexpr (S <= 4 && S <= W) {
    static constexpr ElementBits<W, S> kTable;
    packed |= kTable.table[bits] << (e0 / S);
  } else {
    for (; bits; bits &= bits - 1) {
      const int e = e0 + __builtin_ctz(bits);
      per_sample[e % S] |= 1u << (e / S);
    }
  }
}
template <int W, int S>
SOFTGL_WIDE void TakeElementBits(std::uint64_t packed, std::uint32_t* per_sample) {
  if constexpr (S <= 4 && S <= W)
    for (int s = 0; s < S; ++s) per_sample[s] |= std::uint32_t(packed >> (16 * s)) & 0xFFFFu;
}

// Block b's depths in element order, W at a time, as FillSampleDepths (tile_renderer.cpp) computes them: the lane's
// centre depth plus, at a sample's position, its triangle's change in depth from the centre (a quad without a
// triangle's planes, or with MULTISAMPLE disabled: none).
template <int W, int S>
struct ElementDepths {
  using F = typename V<W>::F;
  static constexpr int kPatterns = S > W ? S / W : 1;
  const float* centre;         // the lanes' depths at their centres
  F delta[4][kPatterns];       // each quad's change from the centre at each element's sample
  // (A quad's planes, where it has them, are those of a multisampled triangle, which sets sample_dz; a quad that is
  // not live has its block's first quad's, and its elements are not taken.)
  SOFTGL_WIDE ElementDepths(const BlockBuffer& bb, int b, bool at_samples) : centre(bb.frag_coord[b][2]) {
    for (int q = 0; q < 4; ++q) {
      const TrianglePlanes* p = at_samples ? bb.quad_planes[b][q] : nullptr;
      for (int k = 0; k < kPatterns; ++k) delta[q][k] = p ? Pattern(p->sample_dz, k) : F{};
    }
  }
  // Element e of pattern k takes d[(k W + e) % S].
  SOFTGL_WIDE static F Pattern(const float* d, int k) {
    if constexpr (S >= W) {
      return LoadVec<F>(d + k * W);
    } else if constexpr (S == 4) {
      typedef float Four __attribute__((vector_size(16)));
      return SpreadPattern(LoadVec<Four>(d), std::make_index_sequence<W>{});
    } else {
      static_assert(S == 2);
      typedef float Two __attribute__((vector_size(8)));
      return SpreadPattern(LoadVec<Two>(d), std::make_index_sequence<W>{});
    }
  }
  template <class Run, std::size_t... E>
  SOFTGL_WIDE static F SpreadPattern(const Run& run, std::index_sequence<E...>) {
    return __builtin_shufflevector(run, run, int(E % S)...);
  }
  SOFTGL_WIDE F At(int chunk) const {
    const int l0 = chunk * W / S;
    return Spread<W, S, F>(centre + l0) + delta[l0 >> 2][chunk % kPatterns];
  }
};

// W texels of an interleaved target's colour buffer from element e0, as FloatLanesOf loads and stores them.
template <int W, int S>
struct ElementTexels {
  std::uint8_t* base;
  const RowPlaces& at;
  int e0;
  template <class T, class Vec>
  SOFTGL_WIDE Vec Load() const { return LoadElements<T, W, S, Vec>(reinterpret_cast<const T*>(base), at, e0); }
  template <class T, class Vec>
  SOFTGL_WIDE void Store(const Vec& v) const { StoreElements<T, W, S>(reinterpret_cast<T*>(base), at, e0, v); }
};

// VectorOps' access to the W elements of chunk `chunk` of block b in an interleaved target of S samples.
template <int W, int S>
struct ElementIo {
  using F = typename V<W>::F;
  using U = typename V<W>::U;
  const BlockOpsContext& ctx;
  const RowPlaces &depth_at, &stencil_at, &colour_at;
  int chunk, b;
  const ElementDepths<W, S>& sample_z;
  std::uint8_t* stencil;
  float* depth;
  std::uint16_t* depth16;
  std::uint32_t* pixels;
  const std::uint32_t* packed;  // without blending: each lane's colour as bytes
  bool colour;
  SOFTGL_WIDE int E0() const { return chunk * W; }
  SOFTGL_WIDE int L0() const { return chunk * W / S; }
  SOFTGL_WIDE typename V<W>::B Stencil() const { return LoadElements<std::uint8_t, W, S, typename V<W>::B>(stencil, stencil_at, E0()); }
  SOFTGL_WIDE void SetStencil(typename V<W>::B v) const { StoreElements<std::uint8_t, W, S>(stencil, stencil_at, E0(), v); }
  SOFTGL_WIDE F Depth() const { return LoadElements<float, W, S, F>(depth, depth_at, E0()); }
  SOFTGL_WIDE void SetDepth(F v) const { StoreElements<float, W, S>(depth, depth_at, E0(), v); }
  SOFTGL_WIDE typename V<W>::S Depth16() const { return LoadElements<std::uint16_t, W, S, typename V<W>::S>(depth16, depth_at, E0()); }
  SOFTGL_WIDE void SetDepth16(typename V<W>::S v) const { StoreElements<std::uint16_t, W, S>(depth16, depth_at, E0(), v); }
  SOFTGL_WIDE U Pixels() const { return LoadElements<std::uint32_t, W, S, U>(pixels, colour_at, E0()); }
  SOFTGL_WIDE void SetPixels(U v) const { StoreElements<std::uint32_t, W, S>(pixels, colour_at, E0(), v); }
  SOFTGL_WIDE F Z() const { return ctx.shader_depth ? Spread<W, S, F>(ctx.blocks->Depth(b) + L0()) : sample_z.At(chunk); }
  SOFTGL_WIDE U Result(U dst) const {
    if (!ctx.blend->blend) return (dst & ctx.blend->keep) | Spread<W, S, U>(packed + L0());
    F color[4];
    for (int c = 0; c < 4; ++c) color[c] = Spread<W, S, F>(ctx.blocks->Color(b, 0, c) + L0());
    return Blend8Lanes<W>(*ctx.blend, color, dst);
  }
  SOFTGL_WIDE void WriteColour(typename V<W>::I go) const {
    if (ctx.plan->path[0] == ColourPath::kFloat) {  // RGB565 or sRGB-encoded (FRAMEBUFFER_SRGB): in float
      const ColorBuffer& cb = ctx.target->color[0];
      F color[4];
      for (int c = 0; c < 4; ++c) color[c] = Spread<W, S, F>(ctx.blocks->Color(b, 0, c) + L0());
      const ElementTexels<W, S> at{cb.data, colour_at, E0()};
      if (cb.layout == TexelLayout::kUnorm565)
        FloatLanesOf<W, TexelLayout::kUnorm565, false>(*ctx.state, *ctx.plan, 0, cb.rgb_only, at, color, go);
      else
        FloatLanesOf<W, TexelLayout::kUnorm8x4, true>(*ctx.state, *ctx.plan, 0, cb.rgb_only, at, color, go);
      return;
    }
    const U dst = Pixels();
    SetPixels(go ? Result(dst) : dst);
  }
};

// BlockOps into an interleaved target of S samples, W elements at a time (kDepthFunc, kPlain: VectorOps').
template <int W, int S, Enum kDepthFunc, bool kPlain>
SOFTGL_WIDE void BlockOpsInterleaved(const BlockOpsContext& ctx, int b) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  const BlockBuffer& bb = *ctx.blocks;
  const RenderTarget& t = *ctx.target;
  const bool colour = ctx.any_color && t.color[0].Present();
  const std::uint32_t live = bb.live[b];
  std::uint32_t covered[S], any = 0;
  for (int s = 0; s < S; ++s) any |= covered[s] = live & bb.sample_live[b][s];
  const ElementCoverage<W, S> coverage(covered);
  const ElementDepths<W, S> sample_z(bb, b, ctx.depths->at_samples);
  // The context's framebuffer, the only interleaved target, has one pitch for all its buffers.
  const RowPlaces at(QuadPlaces(bb, b, t.depth_pitch, S));
  // Without blending, the lanes' colours as bytes, converted once.
  alignas(32) std::uint32_t packed[kLanes];
  if (colour && !ctx.blend->blend && ctx.plan->path[0] == ColourPath::kUnorm8) {
    for (int l0 = 0; l0 < kLanes; l0 += W) {
      F lanes[4];
      for (int c = 0; c < 4; ++c) lanes[c] = LoadVec<F>(bb.Color(b, 0, c) + l0);
      StoreVec(packed + l0, Blend8Lanes<W>(*ctx.blend, lanes, U{}));
    }
  }
  auto* pixels = colour ? reinterpret_cast<std::uint32_t*>(t.color[0].data) : nullptr;
  ForEachChunk<W, S>(any, [&](int chunk) SOFTGL_WIDE_LAMBDA {
    const I go = coverage.Mask(chunk);
    const ElementIo<W, S> io{ctx, at, at, at, chunk, b, sample_z, t.stencil, t.depth, t.depth16,
                             pixels, packed, colour};
    VectorOps<W, ElementIo<W, S>, kDepthFunc, kPlain>(ctx, go, io);
  });
}
// The usual depth comparisons as constants, the others read from the state; the plainest state (a depth test that
// writes float depths, a colour written whole without blending, no stencil test, no query) folded.
inline bool PlainOps(const BlockOpsContext& ctx) {
  const RenderTarget& t = *ctx.target;
  return ctx.depth_test && ctx.state->depth_write && !t.depth16 && !ctx.stencil_test && !ctx.passed &&
         ctx.any_color && t.color[0].Present() && !ctx.blend->blend;
}
// Blocks b0 to b1 - 1 (those with live lanes), the instance chosen once for all of them.
template <int W, int S, Enum kDepthFunc, bool kPlain>
SOFTGL_WIDE void BlockOpsInterleavedRange(const BlockOpsContext& ctx, int b0, int b1) {
  for (int b = b0; b < b1; ++b)
    if (ctx.blocks->live[b]) BlockOpsInterleaved<W, S, kDepthFunc, kPlain>(ctx, b);
}
template <int W, int S, bool kPlain>
SOFTGL_WIDE void BlockOpsInterleavedFunc(const BlockOpsContext& ctx, int b0, int b1) {
  switch (ctx.depth_test ? ctx.state->depth_func : Enum(0)) {
    case LESS: return BlockOpsInterleavedRange<W, S, LESS, kPlain>(ctx, b0, b1);
    case LEQUAL: return BlockOpsInterleavedRange<W, S, LEQUAL, kPlain>(ctx, b0, b1);
    case GREATER: return BlockOpsInterleavedRange<W, S, GREATER, kPlain>(ctx, b0, b1);
    case GEQUAL: return BlockOpsInterleavedRange<W, S, GEQUAL, kPlain>(ctx, b0, b1);
    default: return BlockOpsInterleavedRange<W, S, 0, false>(ctx, b0, b1);
  }
}
template <int W, int S>
SOFTGL_WIDE void BlockOpsInterleavedState(const BlockOpsContext& ctx, int b0, int b1) {
  if (PlainOps(ctx)) return BlockOpsInterleavedFunc<W, S, true>(ctx, b0, b1);
  BlockOpsInterleavedFunc<W, S, false>(ctx, b0, b1);
}
template <int W>
SOFTGL_WIDE void BlockOpsInterleavedAny(const BlockOpsContext& ctx, int b0, int b1) {
  switch (ctx.samples) {
    case 2: return BlockOpsInterleavedState<W, 2>(ctx, b0, b1);
    case 4: return BlockOpsInterleavedState<W, 4>(ctx, b0, b1);
    default: return BlockOpsInterleavedState<W, 8>(ctx, b0, b1);
  }
}

// The same for any block, lane by lane: the lanes in `lanes`, with their depths at `z`, into target `t` (a
// single-sampled target or one sample's plane).
void LaneOps(const BlockOpsContext& ctx, const Unorm8Blend* per_buffer, int b, const RenderTarget& t,
             std::uint32_t lanes, const float* z_lanes, int z_stride) {
  const BlockBuffer& bb = *ctx.blocks;
  const FragmentOpsState& st = *ctx.state;
  const StencilFace& face = *ctx.face;
  for (int lane = 0; lane < kLanes; ++lane) {
    if (!((lanes >> lane) & 1u)) continue;
    const int x = bb.X(b, lane), y = bb.Y(b, lane);
    if (ctx.stencil_test && !StencilTest(face, t.Stencil(x, y))) {
      t.Stencil(x, y) = StencilUpdate(face, face.sfail, t.Stencil(x, y));
      continue;
    }
    if (ctx.depth_test) {
      const float depth = z_lanes[lane * z_stride];
      // Depth is clamped to [0, 1] before the test (the depth buffer holds [0, 1]), and converted to a 16-bit
      // buffer's fixed point; NaN fails.
      // (-0 clamps to +0, as in the vector path.)
      const float z = std::isnan(depth) ? depth : t.StoredDepth(depth > 0.0f ? std::min(depth, 1.0f) : 0.0f);
      if (std::isnan(depth) || !DepthTest(st.depth_func, z, t.DepthAt(x, y))) {
        if (ctx.stencil_test) t.Stencil(x, y) = StencilUpdate(face, face.dpfail, t.Stencil(x, y));
        continue;
      }
      if (st.depth_write) t.SetDepth(x, y, z);
    }
    if (ctx.stencil_test) t.Stencil(x, y) = StencilUpdate(face, face.dppass, t.Stencil(x, y));
    if (ctx.passed) ++*ctx.passed;
    if (!ctx.any_color) continue;
    for (int o = 0; o < kMaxColorOutputs; ++o)
      if (t.color[o].Present()) ColourLane(st, per_buffer[o], bb, b, o, lane, t.color[o]);
  }
}

using BlockOpsFn = void (*)(const BlockOpsContext&, int);
template <bool kSamples>
void BlockOpsBase(const BlockOpsContext& ctx, int b) { BlockOpsEither<4, kSamples>(ctx, b); }
using BlockRangeOpsFn = void (*)(const BlockOpsContext&, int, int);
// BlockOps<W, false> on blocks b0 to b1 - 1 (those with live lanes), into a single-sampled target.
template <int W, Enum kDepthFunc, bool kPlain>
SOFTGL_WIDE void BlockOpsOneRange(const BlockOpsContext& ctx, int b0, int b1) {
  for (int b = b0; b < b1; ++b)
    if (ctx.blocks->live[b]) BlockOps<W, false, true, kDepthFunc, kPlain>(ctx, b);
}
template <int W>
SOFTGL_WIDE void BlockOpsRange(const BlockOpsContext& ctx, int b0, int b1) {
  if (ctx.plan->one_rgba8) {
    // The plainest state with the usual depth comparisons folded at compile time (as for interleaved targets).
    if (PlainOps(ctx)) {
      switch (ctx.state->depth_func) {
        case LESS: return BlockOpsOneRange<W, LESS, true>(ctx, b0, b1);
        case LEQUAL: return BlockOpsOneRange<W, LEQUAL, true>(ctx, b0, b1);
        case GREATER: return BlockOpsOneRange<W, GREATER, true>(ctx, b0, b1);
        case GEQUAL: return BlockOpsOneRange<W, GEQUAL, true>(ctx, b0, b1);
        default: break;
      }
    }
    BlockOpsOneRange<W, 0, false>(ctx, b0, b1);
  } else {
    for (int b = b0; b < b1; ++b)
      if (ctx.blocks->live[b]) BlockOps<W, false, false>(ctx, b);
  }
}
void BlockOpsSingleBase(const BlockOpsContext& ctx, int b0, int b1) { BlockOpsRange<4>(ctx, b0, b1); }
void BlockOpsInterleavedBase(const BlockOpsContext& ctx, int b0, int b1) { BlockOpsInterleavedAny<4>(ctx, b0, b1); }
#if defined(SOFTGL_HAS_DISPATCH)
template <bool kSamples>
SOFTGL_TARGET_AVX2 void BlockOpsAvx2(const BlockOpsContext& ctx, int b) { BlockOpsEither<8, kSamples>(ctx, b); }
SOFTGL_TARGET_AVX2 void BlockOpsSingleAvx2(const BlockOpsContext& ctx, int b0, int b1) { BlockOpsRange<8>(ctx, b0, b1); }
SOFTGL_TARGET_AVX2 void BlockOpsInterleavedAvx2(const BlockOpsContext& ctx, int b0, int b1) {
  BlockOpsInterleavedAny<8>(ctx, b0, b1);
}
// 8 lanes on AVX-512 too: GCC 12 compiles this unit's 16-lane comparisons lane by lane (see simd.h).
template <bool kSamples>
SOFTGL_TARGET_AVX512 void BlockOpsAvx512(const BlockOpsContext& ctx, int b) { BlockOpsEither<8, kSamples>(ctx, b); }
SOFTGL_TARGET_AVX512 void BlockOpsSingleAvx512(const BlockOpsContext& ctx, int b0, int b1) { BlockOpsRange<8>(ctx, b0, b1); }
SOFTGL_TARGET_AVX512 void BlockOpsInterleavedAvx512(const BlockOpsContext& ctx, int b0, int b1) {
  BlockOpsInterleavedAny<8>(ctx, b0, b1);
}
#endif

// The early depth test of W lanes (from l0) of a block at `at`, fragment depths z, against a depth plane (float,
// or 16-bit when kDepth16, compared as the late test compares them): the lanes that pass.
template <int W, bool kDepth16>
SOFTGL_WIDE typename V<W>::I EarlyPass(Enum func, const void* plane, const QuadPlaces& at, int l0, typename V<W>::F z) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  F zc = z > 0.0f ? z : F{} + 0.0f;
  zc = zc < 1.0f ? zc : F{} + 1.0f;
  if constexpr (kDepth16) {
    const I stored = __builtin_convertvector(
        (LoadQuads<std::uint16_t, W, typename V<W>::S>(static_cast<const std::uint16_t*>(plane), at, l0)), I);
    return Compare(func, Depth16Lanes<W>(zc), stored) & (z == z);
  } else {
    const F stored = LoadQuads<float, W, F>(static_cast<const float*>(plane), at, l0);
    return Compare(func, zc, stored) & (z == z);
  }
}
// Depth plane s of the target, as EarlyPass<kDepth16> reads it.
template <bool kDepth16>
const void* DepthPlane(const RenderTarget& t, int s) {
  if constexpr (kDepth16) return t.depth16 + t.depth_plane * std::size_t(s);
  else return t.depth + t.depth_plane * std::size_t(s);
}

// The early test on block b, W lanes at a time; returns its live lanes.
template <int W, bool kDepth16>
SOFTGL_WIDE std::uint32_t EarlyBlock(Enum func, BlockBuffer& bb, const RenderTarget& t, int b) {
  using F = typename V<W>::F;
  const QuadPlaces depth_at(bb, b, t.depth_pitch);
  const void* plane = DepthPlane<kDepth16>(t, 0);
  std::uint32_t keep = 0;
  for (int l0 = 0; l0 < kLanes; l0 += W) {
    const F z = LoadVec<F>(&bb.frag_coord[b][2][l0]);
    keep |= MaskToBits<W>(EarlyPass<W, kDepth16>(func, plane, depth_at, l0, z), l0);
  }
  return bb.live[b] &= keep;
}
// The same into a multisampled target: each sample's covered lanes at its depth against its plane; a lane's sample
// that fails is no longer covered.
template <int W, bool kDepth16>
SOFTGL_WIDE std::uint32_t EarlyBlockSamples(Enum func, BlockBuffer& bb, const RenderTarget& t, int b,
                                            const SampleDepths* depths) {
  using F = typename V<W>::F;
  constexpr std::uint32_t kChunk = (1u << W) - 1u;
  const QuadPlaces depth_at(bb, b, t.depth_pitch);
  std::uint32_t any = 0;
  for (int s = 0; s < t.samples; ++s) {
    const std::uint32_t lanes = bb.live[b] & bb.sample_live[b][s];
    const void* plane = DepthPlane<kDepth16>(t, s);
    std::uint32_t keep = 0;
    for (int l0 = 0; l0 < kLanes; l0 += W) {
      if (!((lanes >> l0) & kChunk)) continue;
      const F z = LoadVec<F>(depths->z[b][s] + l0);
      keep |= MaskToBits<W>(EarlyPass<W, kDepth16>(func, plane, depth_at, l0, z), l0);
    }
    any |= bb.sample_live[b][s] = lanes & keep;
  }
  return bb.live[b] &= any;
}
// The same into an interleaved target of S samples, W elements at a time, with comparison kFunc.
template <int W, int S, bool kDepth16, Enum kFunc>
SOFTGL_WIDE std::uint32_t EarlyBlockInterleaved(BlockBuffer& bb, const RenderTarget& t, int b, const SampleDepths* depths) {
  using F = typename V<W>::F;
  std::uint32_t covered[S], kept[S] = {}, any_sample = 0;
  for (int s = 0; s < S; ++s) any_sample |= covered[s] = bb.live[b] & bb.sample_live[b][s];
  const RowPlaces depth_at(QuadPlaces(bb, b, t.depth_pitch, S));
  const ElementDepths<W, S> sample_z(bb, b, depths->at_samples);
  std::uint64_t packed = 0;  // every element is tested; `covered` then keeps the covered ones
  ForEachChunk<W, S>(any_sample, [&](int chunk) SOFTGL_WIDE_LAMBDA {
    const int e0 = chunk * W;
    const F z = sample_z.At(chunk);
    F zc = z > 0.0f ? z : F{} + 0.0f;
    zc = zc < 1.0f ? zc : F{} + 1.0f;
    typename V<W>::I pass;
    if constexpr (kDepth16) {
      const auto stored = __builtin_convertvector(
          (LoadElements<std::uint16_t, W, S, typename V<W>::S>(t.depth16, depth_at, e0)), typename V<W>::I);
      pass = Compare(kFunc, Depth16Lanes<W>(zc), stored) & (z == z);
    } else {
      pass = Compare(kFunc, zc, LoadElements<float, W, S, F>(t.depth, depth_at, e0)) & (z == z);
    }
    AddElementBits<W, S>(MaskToBits<W>(pass, 0), e0, packed, kept);
  });
  TakeElementBits<W, S>(packed, kept);
  std::uint32_t any = 0;
  for (int s = 0; s < S; ++s) any |= bb.sample_live[b][s] = covered[s] & kept[s];
  return bb.live[b] &= any;
}
// Blocks b0 to b1 - 1 (those with live lanes), the instance chosen once for all of them: their live lanes after the
// test, together. (The early test takes only these four comparisons: EarlyDepthTestApplies.)
template <int W, int S, bool kDepth16, Enum kFunc>
SOFTGL_WIDE std::uint32_t EarlyInterleavedRange(BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                                const SampleDepths* d) {
  std::uint32_t live = 0;
  for (int b = b0; b < b1; ++b)
    if (bb.live[b]) live |= EarlyBlockInterleaved<W, S, kDepth16, kFunc>(bb, t, b, d);
  return live;
}
template <int W, int S, bool kDepth16>
SOFTGL_WIDE std::uint32_t EarlyInterleavedFunc(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                               const SampleDepths* d) {
  switch (f) {
    case LESS: return EarlyInterleavedRange<W, S, kDepth16, LESS>(bb, t, b0, b1, d);
    case LEQUAL: return EarlyInterleavedRange<W, S, kDepth16, LEQUAL>(bb, t, b0, b1, d);
    case GREATER: return EarlyInterleavedRange<W, S, kDepth16, GREATER>(bb, t, b0, b1, d);
    default: return EarlyInterleavedRange<W, S, kDepth16, GEQUAL>(bb, t, b0, b1, d);
  }
}
template <int W>
SOFTGL_WIDE std::uint32_t EarlyInterleavedAny(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                              const SampleDepths* d) {
  switch (t.samples + (t.depth16 ? 16 : 0)) {
    case 2: return EarlyInterleavedFunc<W, 2, false>(f, bb, t, b0, b1, d);
    case 4: return EarlyInterleavedFunc<W, 4, false>(f, bb, t, b0, b1, d);
    case 8: return EarlyInterleavedFunc<W, 8, false>(f, bb, t, b0, b1, d);
    case 18: return EarlyInterleavedFunc<W, 2, true>(f, bb, t, b0, b1, d);
    case 20: return EarlyInterleavedFunc<W, 4, true>(f, bb, t, b0, b1, d);
    default: return EarlyInterleavedFunc<W, 8, true>(f, bb, t, b0, b1, d);
  }
}
// EarlyBlock on blocks b0 to b1 - 1 (those with live lanes), into a single-sampled target: their live lanes after
// the test, together.
template <int W>
SOFTGL_WIDE std::uint32_t EarlySingleRange(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1) {
  std::uint32_t live = 0;
  for (int b = b0; b < b1; ++b)
    if (bb.live[b]) live |= t.depth16 ? EarlyBlock<W, true>(f, bb, t, b) : EarlyBlock<W, false>(f, bb, t, b);
  return live;
}
// The early test of blocks b0 to b1 - 1 into an even-sized target: samples side by side (kInterleaved) or a
// single-sampled target.
template <int W, bool kInterleaved>
SOFTGL_WIDE std::uint32_t EarlyRangeAny(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                        const SampleDepths* d) {
  if constexpr (kInterleaved) return EarlyInterleavedAny<W>(f, bb, t, b0, b1, d);
  else return EarlySingleRange<W>(f, bb, t, b0, b1);
}
using EarlyRangeFn = std::uint32_t (*)(Enum, BlockBuffer&, const RenderTarget&, int, int, const SampleDepths*);
template <bool kInterleaved>
std::uint32_t EarlyRangeBase(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1, const SampleDepths* d) {
  return EarlyRangeAny<4, kInterleaved>(f, bb, t, b0, b1, d);
}
#if defined(SOFTGL_HAS_DISPATCH)
template <bool kInterleaved>
SOFTGL_TARGET_AVX2 std::uint32_t EarlyRangeAvx2(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                                const SampleDepths* d) {
  return EarlyRangeAny<8, kInterleaved>(f, bb, t, b0, b1, d);
}
template <bool kInterleaved>
SOFTGL_TARGET_AVX512 std::uint32_t EarlyRangeAvx512(Enum f, BlockBuffer& bb, const RenderTarget& t, int b0, int b1,
                                                    const SampleDepths* d) {
  return EarlyRangeAny<8, kInterleaved>(f, bb, t, b0, b1, d);
}
#endif
using EarlyBlockFn = std::uint32_t (*)(Enum, BlockBuffer&, const RenderTarget&, int, const SampleDepths*);
template <int W>
SOFTGL_WIDE std::uint32_t EarlyBlockEither(Enum f, BlockBuffer& bb, const RenderTarget& t, int b, const SampleDepths* d) {
  if (d && t.interleaved) return EarlyInterleavedAny<W>(f, bb, t, b, b + 1, d);
  if (t.depth16) return d ? EarlyBlockSamples<W, true>(f, bb, t, b, d) : EarlyBlock<W, true>(f, bb, t, b);
  return d ? EarlyBlockSamples<W, false>(f, bb, t, b, d) : EarlyBlock<W, false>(f, bb, t, b);
}
std::uint32_t EarlyBlockBase(Enum f, BlockBuffer& bb, const RenderTarget& t, int b, const SampleDepths* d) {
  return EarlyBlockEither<4>(f, bb, t, b, d);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 std::uint32_t EarlyBlockAvx2(Enum f, BlockBuffer& bb, const RenderTarget& t, int b, const SampleDepths* d) {
  return EarlyBlockEither<8>(f, bb, t, b, d);
}
// 8 lanes on AVX-512 too, with its instruction set: measured faster than 16 on the bench scenes (docs/performance.md).
SOFTGL_TARGET_AVX512 std::uint32_t EarlyBlockAvx512(Enum f, BlockBuffer& bb, const RenderTarget& t, int b,
                                                    const SampleDepths* d) {
  return EarlyBlockEither<8>(f, bb, t, b, d);
}
#endif

// The early test of every block, into a single-sampled target or (`depths` given) a multisampled one.
bool EarlyTest(const FragmentOpsState& state, BlockBuffer& blocks, const RenderTarget& target, const SampleDepths* depths) {
  static const EarlyRangeFn early_interleaved = SOFTGL_CHOOSE(EarlyRange, <true>);
  static const EarlyRangeFn early_single = SOFTGL_CHOOSE(EarlyRange, <false>);
  // The range forms where they apply: on every block of an even-sized target, on each run of blocks inside an
  // odd-sized one (the others below, one at a time).
  const EarlyRangeFn range = !target.HasDepth()                ? nullptr
                             : depths && target.interleaved ? early_interleaved
                             : !depths                      ? early_single
                                                            : nullptr;
  if (range && ((target.width | target.height) & 1) == 0)  // every block inside (Inside)
    return range(state.depth_func, blocks, target, 0, blocks.count, depths) != 0;
  std::uint32_t live = 0;
  static const EarlyBlockFn early = SOFTGL_CHOOSE(EarlyBlock);
  for (int b = 0; b < blocks.count; ++b) {
    if (range && Inside(target, blocks, b)) {
      int end = b + 1;
      while (end < blocks.count && Inside(target, blocks, end)) ++end;
      live |= range(state.depth_func, blocks, target, b, end, depths);
      b = end - 1;
      continue;
    }
    if (target.HasDepth() && blocks.live[b]) {
      if (Inside(target, blocks, b)) {
        early(state.depth_func, blocks, target, b, depths);
      } else {
        // As the late test: depth clamped to [0, 1] and converted as the buffer keeps it, NaN fails.
        auto passes = [&](float depth, int s, int lane) {
          const float stored = target.DepthAt(blocks.X(b, lane), blocks.Y(b, lane), s);
          return !std::isnan(depth) &&
                 DepthTest(state.depth_func, target.StoredDepth(std::clamp(depth, 0.0f, 1.0f)), stored);
        };
        std::uint32_t any = 0;
        for (int lane = 0; lane < kLanes; ++lane) {
          if (!((blocks.live[b] >> lane) & 1u)) continue;  // a live lane lies inside the target
          if (!depths) {
            if (!passes(blocks.frag_coord[b][2][lane], 0, lane)) blocks.live[b] &= ~(1u << lane);
            continue;
          }
          for (int s = 0; s < target.samples; ++s)
            if (((blocks.sample_live[b][s] >> lane) & 1u) && !passes(depths->Lanes(b, s)[lane * depths->Stride()], s, lane))
              blocks.sample_live[b][s] &= ~(1u << lane);
        }
        if (depths) {
          for (int s = 0; s < target.samples; ++s) any |= blocks.sample_live[b][s] &= blocks.live[b];
          blocks.live[b] &= any;
        }
      }
    }
    live |= blocks.live[b];
  }
  return live != 0;
}

// The operations of block b (live), into a single-sampled target or (`depths` given) a multisampled one.
void BlockOpsOne(const BlockOpsContext& ctx, const FragmentOpsPlan& plan, const RenderTarget& target,
                 const SampleDepths* depths, int b) {
  static const BlockOpsFn block_ops = SOFTGL_CHOOSE(BlockOps, <false>);
  static const BlockOpsFn block_ops_samples = SOFTGL_CHOOSE(BlockOps, <true>);
  static const BlockRangeOpsFn block_ops_interleaved = SOFTGL_CHOOSE(BlockOpsInterleaved);
  const BlockBuffer& blocks = *ctx.blocks;
  if (plan.wide_target && Inside(target, blocks, b)) {
    if (depths && target.interleaved) block_ops_interleaved(ctx, b, b + 1);
    else (depths ? block_ops_samples : block_ops)(ctx, b);
  } else if (!depths) {
    LaneOps(ctx, plan.blend, b, target, blocks.live[b], PlaneDepths(ctx, b, 0), PlaneStride(ctx));
  } else {
    for (int s = 0; s < target.samples; ++s)
      LaneOps(ctx, plan.blend, b, target.Sample(s), PlaneLanes(ctx, b, s), PlaneDepths(ctx, b, s), PlaneStride(ctx));
  }
}

// What the operations of a batch share.
BlockOpsContext ContextOf(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                          bool shader_depth, const RenderTarget& target, const SampleDepths* depths) {
  // Without a depth or stencil buffer the test passes and nothing is written (OpenGL 4.6, 17.3.5 and 17.3.6).
  BlockOpsContext ctx;
  ctx.plan = &plan;
  ctx.state = &state;
  ctx.blocks = &blocks;
  ctx.target = &target;
  ctx.shader_depth = shader_depth;
  ctx.stencil_test = state.stencil_test && target.stencil != nullptr;
  ctx.depth_test = state.depth_test && target.HasDepth();
  ctx.any_color = state.WritesAny();
  ctx.face = blocks.front_facing ? &state.front : &state.back;
  ctx.blend = &plan.blend[0];
  ctx.depths = depths;
  ctx.samples = depths ? target.samples : 1;
  ctx.passed = nullptr;
  return ctx;
}

// The operations of every block, into a single-sampled target or (`depths` given) a multisampled one.
void BlockOpsAll(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                 bool shader_depth, const RenderTarget& target, const SampleDepths* depths) {
  BlockOpsContext ctx = ContextOf(state, plan, blocks, shader_depth, target, depths);
  std::uint64_t passed = 0;
  ctx.passed = state.occlusion[0] || state.occlusion[1] ? &passed : nullptr;
  static const BlockRangeOpsFn block_ops_interleaved = SOFTGL_CHOOSE(BlockOpsInterleaved);
  static const BlockRangeOpsFn block_ops_single = SOFTGL_CHOOSE(BlockOpsSingle);
  const bool even = ((target.width | target.height) & 1) == 0;  // every block inside (Inside)
  const BlockRangeOpsFn range = !plan.wide_target                ? nullptr
                                : depths && target.interleaved ? block_ops_interleaved
                                : !depths                      ? block_ops_single
                                                               : nullptr;
  if (range && even) {
    range(ctx, 0, blocks.count);
  } else {
    // Each run of blocks inside an odd-sized target by the range form, the others one at a time.
    for (int b = 0; b < blocks.count; ++b) {
      if (range && Inside(target, blocks, b)) {
        int end = b + 1;
        while (end < blocks.count && Inside(target, blocks, end)) ++end;
        range(ctx, b, end);
        b = end - 1;
      } else if (blocks.live[b]) {
        BlockOpsOne(ctx, plan, target, depths, b);
      }
    }
  }
  for (OcclusionCounter* c : state.occlusion)
    if (c && passed) c->passed.fetch_add(passed, std::memory_order_relaxed);
}

}  // namespace

bool EarlyDepthTest(const FragmentOpsState& state, BlockBuffer& blocks, const RenderTarget& target) {
  return EarlyTest(state, blocks, target, nullptr);
}

bool EarlyDepthTestSamples(const FragmentOpsState& state, BlockBuffer& blocks, const RenderTarget& target,
                           const SampleDepths& depths) {
  return EarlyTest(state, blocks, target, &depths);
}

void ApplyFragmentOps(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                      bool shader_depth, const RenderTarget& target) {
  BlockOpsAll(state, plan, blocks, shader_depth, target, nullptr);
}

void ApplyFragmentOpsReference(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                               bool shader_depth, const RenderTarget& target) {
  const BlockOpsContext ctx = ContextOf(state, plan, blocks, shader_depth, target, nullptr);
  for (int b = 0; b < blocks.count; ++b)
    if (blocks.live[b]) LaneOps(ctx, plan.blend, b, target, blocks.live[b], PlaneDepths(ctx, b, 0), PlaneStride(ctx));
}

void ApplyFragmentOpsSamples(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                             bool shader_depth, const RenderTarget& target, const SampleDepths& depths) {
  BlockOpsAll(state, plan, blocks, shader_depth, target, &depths);
}

}  // namespace softgl::detail

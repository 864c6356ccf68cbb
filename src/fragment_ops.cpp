// fragment_ops.cpp — stencil, depth, blending and masks with OpenGL's arithmetic.
#include "fragment_ops.h"

#include <algorithm>
#include <cmath>

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

void ApplyFragmentOps(const FragmentOpsState& state, const QuadBuffer& quads, const RenderTarget& target) {
  const StencilFace& face = quads.front_facing ? state.front : state.back;
  // Without a depth or stencil buffer the test passes and nothing is written (OpenGL 4.6, 17.3.5 and 17.3.6).
  const bool stencil_test = state.stencil_test && target.stencil != nullptr;
  const bool depth_test = state.depth_test && target.depth != nullptr;
  const bool any_color = state.color_mask[0] || state.color_mask[1] || state.color_mask[2] || state.color_mask[3];
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

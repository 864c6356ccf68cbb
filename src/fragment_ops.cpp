// fragment_ops.cpp — depth test and colour write with OpenGL's arithmetic.
#include "fragment_ops.h"

#include <algorithm>
#include <cmath>

namespace softgl::detail {

bool DepthTest(Enum func, float incoming, float stored) {
  switch (func) {
    case NEVER: return false;
    case LESS: return incoming < stored;
    case EQUAL: return incoming == stored;
    case LEQUAL: return incoming <= stored;
    case GREATER: return incoming > stored;
    case NOTEQUAL: return incoming != stored;
    case GEQUAL: return incoming >= stored;
    default: return true;  // ALWAYS
  }
}

std::uint8_t FloatToUnorm8(float f) {
  if (!(f > 0.0f)) return 0;  // also NaN
  if (f >= 1.0f) return 255;
  return std::uint8_t(std::lrint(f * 255.0f));
}

void ApplyFragmentOps(const FragmentOpsState& state, const QuadBuffer& quads, Framebuffer& fb) {
  for (int q = 0; q < quads.count; ++q) {
    for (int lane = 0; lane < 4; ++lane) {
      const int l = q * 4 + lane;
      if (!quads.live[l]) continue;
      const std::size_t idx = fb.Index(quads.qx[q] + (lane & 1), quads.qy[q] + (lane >> 1));
      const FragmentOut& out = quads.out[l];
      if (state.depth_test) {
        // Depth values are clamped to [0, 1] before the test (the depth buffer holds [0, 1]); NaN fails.
        const float z = std::clamp(out.depth, 0.0f, 1.0f);
        if (std::isnan(out.depth) || !DepthTest(state.depth_func, z, fb.depth[idx])) continue;
        if (state.depth_write) fb.depth[idx] = z;
      }
      std::uint8_t* px = &fb.color[idx * 4];
      for (int c = 0; c < 4; ++c) px[c] = FloatToUnorm8(out.color[0][c]);
    }
  }
}

}  // namespace softgl::detail

// fragment_ops.h — stage 9: per-fragment operations after the fragment shader (depth test, colour write).
#pragma once

#include <softgl/enums.h>

#include "framebuffer.h"
#include "types.h"

namespace softgl::detail {

struct FragmentOpsState {
  bool depth_test = false;
  Enum depth_func = LESS;
  bool depth_write = true;
};

/// Whether `incoming` passes the depth comparison `func` against `stored`.
bool DepthTest(Enum func, float incoming, float stored);

/// OpenGL's float-to-normalized-fixed conversion for 8 bits: clamp to [0, 1], then round(f * 255).
std::uint8_t FloatToUnorm8(float f);

/// Runs depth test and colour write for every live lane of `quads` (after the fragment shader has filled
/// quads.out and cleared discarded lanes) into `fb`.
void ApplyFragmentOps(const FragmentOpsState& state, const QuadBuffer& quads, Framebuffer& fb);

}  // namespace softgl::detail

// fragment_ops.h — stage 9: the per-fragment operations after the fragment shader, in OpenGL's order:
// (scissor, done by the rasterizer's bounds) -> stencil test -> depth test -> stencil update -> blending ->
// colour mask -> framebuffer. Arithmetic follows the OpenGL 4.6 specification, chapter 17.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>
#include <softgl/enums.h>

#include "framebuffer.h"
#include "types.h"

namespace softgl::detail {

struct StencilFace {
  Enum func = ALWAYS;
  int ref = 0;
  std::uint32_t value_mask = 0xFFFFFFFFu;  // StencilFunc's mask
  Enum sfail = KEEP;                       // stencil test fails
  Enum dpfail = KEEP;                      // stencil passes, depth fails
  Enum dppass = KEEP;                      // both pass (or depth test disabled)
  std::uint32_t write_mask = 0xFFFFFFFFu;  // StencilMask
};

struct BlendState {
  bool enabled = false;
  Enum eq_rgb = FUNC_ADD, eq_alpha = FUNC_ADD;
  Enum src_rgb = ONE, dst_rgb = ZERO, src_alpha = ONE, dst_alpha = ZERO;
  glm::vec4 color{0.0f};  // BlendColor
};

struct FragmentOpsState {
  bool stencil_test = false;
  StencilFace front, back;
  bool depth_test = false;
  Enum depth_func = LESS;
  bool depth_write = true;
  BlendState blend;
  bool color_mask[4] = {true, true, true, true};
};

/// Whether `a` passes comparison `func` against `b` (a func b): the depth test compares incoming to stored, the
/// stencil test the masked reference to the masked stored value.
template <class T>
bool Compare(Enum func, T a, T b) {
  switch (func) {
    case NEVER: return false;
    case LESS: return a < b;
    case EQUAL: return a == b;
    case LEQUAL: return a <= b;
    case GREATER: return a > b;
    case NOTEQUAL: return a != b;
    case GEQUAL: return a >= b;
    default: return true;  // ALWAYS
  }
}

/// Depth test: whether `incoming` passes `func` against `stored`.
inline bool DepthTest(Enum func, float incoming, float stored) { return Compare(func, incoming, stored); }

/// Stencil test for an 8-bit stencil buffer: (ref & mask) func (stored & mask), ref clamped to [0, 255].
bool StencilTest(const StencilFace& face, std::uint8_t stored);

/// The stencil value after operation `op` (KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP) on
/// `stored`, written through the face's write mask.
std::uint8_t StencilUpdate(const StencilFace& face, Enum op, std::uint8_t stored);

/// Blends source colour `src` (already clamped to [0, 1]) over destination `dst` (in [0, 1]): OpenGL's factors
/// and equations, computed in float.
glm::vec4 Blend(const BlendState& state, const glm::vec4& src, const glm::vec4& dst);

/// Whether the depth test may run before the fragment shader without changing the result: the shader does not
/// write depth, the stencil test is off (its depth-fail operation would be skipped), and the depth function is
/// monotonic (LESS, LEQUAL, GREATER, GEQUAL), so that a fragment failing against the buffer now fails against any
/// later content of it too, the buffer only moving towards the test's winning side.
bool EarlyDepthTestApplies(const FragmentOpsState& state, bool shader_writes_depth);

/// The early depth test: clears the live flag of every lane whose interpolated depth (frag_coord.z, clamped as
/// the late test clamps it) fails against the depth buffer. Writes nothing; the late test runs as usual after the
/// shader. Returns the number of lanes still live.
int EarlyDepthTest(const FragmentOpsState& state, QuadBuffer& quads, const RenderTarget& target);

/// Runs the per-fragment operations for every live lane of `quads` (after the fragment shader has filled
/// quads.out and cleared discarded lanes) into the buffers of `target`.
void ApplyFragmentOps(const FragmentOpsState& state, const QuadBuffer& quads, const RenderTarget& target);

}  // namespace softgl::detail

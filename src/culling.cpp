// culling.cpp — OpenGL's facing rule (section 14.6.1 of the 4.6 specification).
#include "culling.h"

#include "rasterizer.h"
#include "simd.h"
#include "snap_wide.h"
#include "wide.h"

namespace softgl::detail {

float SignedArea(const WindowVertex* v, int count) {
  // A fan of cross products around vertex 0: exact for a triangle's orientation up to float rounding, and
  // free of the cancellation that absolute coordinates would bring far from the origin.
  float area = 0.0f;
  for (int i = 1; i + 1 < count; ++i) {
    const glm::vec2 a = glm::vec2(v[i].win) - glm::vec2(v[0].win);
    const glm::vec2 b = glm::vec2(v[i + 1].win) - glm::vec2(v[0].win);
    area += a.x * b.y - b.x * a.y;
  }
  return area;
}

bool IsFrontFacing(float area, Enum front_face) { return front_face == CW ? area < 0.0f : area > 0.0f; }

bool IsCulled(bool front_facing, Enum cull_face) {
  switch (cull_face) {
    case FRONT_AND_BACK: return true;
    case FRONT: return front_facing;
    default: return !front_facing;
  }
}

void CullState::SetSamples(int count) {
  const SampleSpan& span = SampleSpan::Of(count);
  span_x0 = int(span.x0);
  span_x1 = int(span.x1);
  span_y0 = int(span.y0);
  span_y1 = int(span.y1);
  samples = count <= 1 ? 1 : count;
  const auto* pos = SamplePositions(samples);
  for (int s = 0; s < samples; ++s) {
    sample_x[s] = pos[s][0] * (256 / 16);
    sample_y[s] = pos[s][1] * (256 / 16);
  }
}

namespace {

template <int W>
SOFTGL_WIDE void JudgeLanes(const TriangleGroup& g, const CullState& st, int l0, GroupVerdict& out) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  F x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = LoadVec<F>(g.x[k] + l0);
    y[k] = LoadVec<F>(g.y[k] + l0);
  }
  // SignedArea of a triangle: 0 + (a.x b.y - b.x a.y), a and b the edges from vertex 0.
  const F ax = x[1] - x[0], ay = y[1] - y[0], bx = x[2] - x[0], by = y[2] - y[0];
  const F area = ax * by - bx * ay;
  const I front = st.front_face == CW ? I(area < 0.0f) : I(area > 0.0f);
  I nothing = area == 0.0f;
  if (st.cull_enabled) {
    switch (st.cull_face) {
      case FRONT_AND_BACK: nothing = nothing | ~I{}; break;
      case FRONT: nothing = nothing | front; break;
      default: nothing = nothing | ~front; break;
    }
  }
  // Snapped to 1/256 pixel as the rasterizer snaps, exact in range (the lanes out of range are not marked).
  I exact = ~I{}, X[3], Y[3];
  for (int k = 0; k < 3; ++k) exact = exact & SnapLanes<W>(x[k], y[k], X[k], Y[k]);
  // Lane-wise minimum and maximum, by masks (a comparison gives all bits set where it holds).
  auto min = [](I a, I b) SOFTGL_WIDE_LAMBDA { return (a & (a < b)) | (b & ~(a < b)); };
  auto max = [](I a, I b) SOFTGL_WIDE_LAMBDA { return (a & (a > b)) | (b & ~(a > b)); };
  auto min3 = [&](I a, I b, I c) SOFTGL_WIDE_LAMBDA { return min(min(a, b), c); };
  auto max3 = [&](I a, I b, I c) SOFTGL_WIDE_LAMBDA { return max(max(a, b), c); };
  // TriangleCentreBox's first and last centres (pixels with some sample inside), cut to the bounds.
  I first_x = -((st.span_x1 - min3(X[0], X[1], X[2])) >> 8), last_x = (max3(X[0], X[1], X[2]) - st.span_x0) >> 8;
  I first_y = -((st.span_y1 - min3(Y[0], Y[1], Y[2])) >> 8), last_y = (max3(Y[0], Y[1], Y[2]) - st.span_y0) >> 8;
  // At most 2 x 2 pixels before the cut: the vertices lie within 3 pixels of each other.
  const I tiny = exact & I(last_x - first_x <= 1) & I(last_y - first_y <= 1);
  const I bx0 = I{} + st.bounds.x0, bx1 = I{} + (st.bounds.x1 - 1), by0 = I{} + st.bounds.y0,
          by1 = I{} + (st.bounds.y1 - 1);
  first_x = max(first_x, bx0);
  last_x = min(last_x, bx1);
  first_y = max(first_y, by0);
  last_y = min(last_y, by1);
  nothing = nothing | (exact & ((first_x > last_x) | (first_y > last_y)));
  // The snapped area (SnappedArea), in 32 bits where the edges are shorter than 2^15 subpixels (128 pixels): each
  // product is then below 2^30 in magnitude. Computed unsigned, so that longer edges wrap harmlessly.
  const I dx1 = X[1] - X[0], dy1 = Y[1] - Y[0], dx2 = X[2] - X[0], dy2 = Y[2] - Y[0];
  auto short_edge = [](I d) SOFTGL_WIDE_LAMBDA { return I(d < 32768) & I(d > -32768); };
  const I small = exact & short_edge(dx1) & short_edge(dy1) & short_edge(dx2) & short_edge(dy2);
  const U snapped_area = U(dx1) * U(dy2) - U(dx2) * U(dy1);
  nothing = nothing | (small & I(snapped_area == 0u));
  // A tiny triangle draws nothing when none of the positions in the (at most four) pixels of its box is inside:
  // each pixel's centre, or each of its samples' positions when multisampled. The rasterizer's edge test
  // (RasterizeTriangle), each edge's value at the position in subpixels, the vertices in counter-clockwise order.
  // A clockwise triangle's edges are the reverses of the counter-clockwise order's, whose values are the negated
  // values of these. Every value is below 2^21 in magnitude.
  if (const I test = tiny & ~nothing; MaskToBits<W>(test, 0) != 0) {
    const I ccw = I(snapped_area) > 0;
    const I px = first_x * 256, py = first_y * 256;  // the box's first pixel's corner
    I value[3], step_x[3], step_y[3], owns_ties[3], ex[3], ey[3];
    for (int e = 0; e < 3; ++e) {
      const int f = e == 2 ? 0 : e + 1;
      ex[e] = ccw ? X[f] - X[e] : X[e] - X[f];
      ey[e] = ccw ? Y[f] - Y[e] : Y[e] - Y[f];
      value[e] = ex[e] * (py - (ccw ? Y[e] : Y[f])) - ey[e] * (px - (ccw ? X[e] : X[f]));
      step_x[e] = ey[e] * -256;  // to the next pixel in x, in y
      step_y[e] = ex[e] * 256;
      owns_ties[e] = I(ey[e] < 0) | (I(ey[e] == 0) & I(ex[e] > 0));  // left and bottom edges
    }
    // The other pixels only where some lane's box has them.
    const bool two_x = MaskToBits<W>(test & I(last_x > first_x), 0) != 0;
    const bool two_y = MaskToBits<W>(test & I(last_y > first_y), 0) != 0;
    I covered{};
    for (int s = 0; s < st.samples; ++s) {
      I at[3];  // each edge at the position in the box's first pixel
      for (int e = 0; e < 3; ++e) at[e] = value[e] - ey[e] * st.sample_x[s] + ex[e] * st.sample_y[s];
      for (int k = 0; k < 4; ++k) {
        if (((k & 1) && !two_x) || ((k >> 1) && !two_y)) continue;
        I inside = I(first_x + (k & 1) <= last_x) & I(first_y + (k >> 1) <= last_y);
        for (int e = 0; e < 3; ++e) {
          const I v = at[e] + (k & 1 ? step_x[e] : I{}) + (k >> 1 ? step_y[e] : I{});
          inside &= I(v > 0) | (I(v == 0) & owns_ties[e]);
        }
        covered |= inside;
      }
    }
    nothing = nothing | (tiny & ~covered);
  }
  const I known = small & ~nothing;
  out.nothing |= MaskToBits<W>(nothing, l0);
  out.known |= MaskToBits<W>(known, l0);
  out.front |= MaskToBits<W>(front, l0);
  StoreVec(out.x0 + l0, first_x);
  StoreVec(out.y0 + l0, first_y);
  StoreVec(out.x1 + l0, last_x + 1);
  StoreVec(out.y1 + l0, last_y + 1);
}

template <int W>
SOFTGL_WIDE void JudgeGroup(const TriangleGroup& g, const CullState& st, GroupVerdict& out) {
  out.nothing = out.known = out.front = 0;
  for (int l0 = 0; l0 < g.count; l0 += W) JudgeLanes<W>(g, st, l0, out);  // the vectors holding triangles
  const std::uint32_t used = g.count >= 32 ? ~0u : (std::uint32_t(1) << g.count) - 1;
  out.nothing &= used;
  out.known &= used;
}

using JudgeFn = void (*)(const TriangleGroup&, const CullState&, GroupVerdict&);
void JudgeGroupBase(const TriangleGroup& g, const CullState& st, GroupVerdict& out) { JudgeGroup<4>(g, st, out); }
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void JudgeGroupAvx2(const TriangleGroup& g, const CullState& st, GroupVerdict& out) {
  JudgeGroup<8>(g, st, out);
}
// 8 lanes on AVX-512 too: GCC 12 compiles this unit's 16-lane comparisons lane by lane (see simd.h).
SOFTGL_TARGET_AVX512 void JudgeGroupAvx512(const TriangleGroup& g, const CullState& st, GroupVerdict& out) {
  JudgeGroup<8>(g, st, out);
}
#endif

}  // namespace

void JudgeTriangles(const TriangleGroup& group, const CullState& state, GroupVerdict& verdict) {
  static const JudgeFn fn = SOFTGL_CHOOSE(JudgeGroup);
  fn(group, state, verdict);
}

std::uint32_t DrawsNothing(const TriangleGroup& group, const CullState& state) {
  GroupVerdict verdict;
  JudgeTriangles(group, state, verdict);
  return verdict.nothing;
}

}  // namespace softgl::detail

// Facing and culling: window-space signed area, both windings, each cull mode; and through the API.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <random>

#include "culling.h"
#include "helpers.h"
#include "rasterizer.h"

using namespace softgl;
using namespace softgl::detail;

namespace {
WindowVertex W(float x, float y) {
  WindowVertex v{};
  v.win = glm::vec4(x, y, 0, 1);
  return v;
}
}  // namespace

TEST_CASE("signed area is positive for counter-clockwise polygons", "[culling]") {
  const WindowVertex ccw[3] = {W(0, 0), W(4, 0), W(0, 4)};
  const WindowVertex cw[3] = {W(0, 0), W(0, 4), W(4, 0)};
  CHECK(SignedArea(ccw, 3) == Approx(16.0f));
  CHECK(SignedArea(cw, 3) == Approx(-16.0f));
  const WindowVertex quad[4] = {W(10000, 10000), W(10002, 10000), W(10002, 10002), W(10000, 10002)};
  CHECK(SignedArea(quad, 4) == Approx(8.0f));
}

TEST_CASE("facing follows FrontFace and culling follows CullFace", "[culling]") {
  CHECK(IsFrontFacing(1.0f, CCW));
  CHECK_FALSE(IsFrontFacing(-1.0f, CCW));
  CHECK(IsFrontFacing(-1.0f, CW));
  CHECK_FALSE(IsFrontFacing(1.0f, CW));
  CHECK(IsCulled(false, BACK));
  CHECK_FALSE(IsCulled(true, BACK));
  CHECK(IsCulled(true, FRONT));
  CHECK(IsCulled(true, FRONT_AND_BACK));
  CHECK(IsCulled(false, FRONT_AND_BACK));
}

TEST_CASE("culling through the API removes the right triangles", "[culling]") {
  Context gl(8, 8);
  // Left half: a counter-clockwise triangle; right half: a clockwise one.
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {0, -1, 0, 1}, {-1, 1, 0, 1}, {0.01f, -1, 0, 1}, {0.01f, 1, 0, 1},
                                {1, -1, 0, 1}});
  testing::SolidShader shader;
  gl.UseProgram(shader);
  auto draw = [&](bool cull, Enum face, Enum front) {
    gl.Clear(COLOR_BUFFER_BIT);
    if (cull) gl.Enable(CULL_FACE);
    else gl.Disable(CULL_FACE);
    gl.CullFace(face);
    gl.FrontFace(front);
    gl.DrawArrays(TRIANGLES, 0, 6);
    std::uint8_t left[4], right[4];
    gl.ReadPixel(1, 1, left);
    gl.ReadPixel(6, 1, right);
    return std::pair<bool, bool>(left[0] == 255, right[0] == 255);
  };
  CHECK(draw(false, BACK, CCW) == std::pair(true, true));
  CHECK(draw(true, BACK, CCW) == std::pair(true, false));
  CHECK(draw(true, FRONT, CCW) == std::pair(false, true));
  CHECK(draw(true, BACK, CW) == std::pair(false, true));
  CHECK(draw(true, FRONT_AND_BACK, CCW) == std::pair(false, false));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("gl_FrontFacing reaches the fragment stage", "[culling]") {
  Context gl(4, 4);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}},
                           std::vector<glm::vec4>(6, glm::vec4(0)));
  testing::CaptureShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 6);
  gl.Finish();  // fragments are shaded when the context renders
  CHECK(shader.samples.at({0, 0}).front_facing);       // counter-clockwise
  CHECK_FALSE(shader.samples.at({3, 3}).front_facing);  // clockwise
}

TEST_CASE("a group of triangles: those marked as drawing nothing are those the scalar path drops, and the known "
          "ones have the scalar path's facing and box", "[culling]") {
  // Random triangles from slivers to hundreds of pixels, both windings, some far out (beyond 16384 pixels the
  // group leaves the box test to the scalar path), under every cull state and a bounds rectangle. A marked
  // triangle must be one the scalar path drops (culled, no area, TriangleCentreBox empty, or no centre covered by
  // the rasterizer); and the group must find nearly all of those, or the test would pass with a group that marks
  // nothing. A triangle marked known must be drawn, with the facing and TriangleCentreBox of the scalar path; and
  // nearly all small drawn ones are known. Into a 4-sample target too: boxes of the pixels with some sample inside.
  const int samples = GENERATE(1, 4);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const Enum faces[] = {BACK, FRONT, FRONT_AND_BACK};
  int marked = 0, dropped = 0, known = 0, small_drawn = 0, uncovered = 0, marked_uncovered = 0;
  testing::CoverageCounter counter(300, 200);
  auto covers_nothing = [&](const WindowVertex v[3], const Rect& bounds) {  // the rasterizer's verdict
    std::fill(counter.hits.begin(), counter.hits.end(), 0);
    auto blocks = std::make_unique<BlockBuffer>();
    RasterTarget target;
    target.bounds = bounds;
    target.samples = samples;
    blocks->samples = samples;
    const BlockSink sink = counter.Sink();
    RasterizeTriangle(v[0], v[1], v[2], true, target, *blocks, sink);
    sink.Flush(*blocks);
    return std::all_of(counter.hits.begin(), counter.hits.end(), [](int h) { return h == 0; });
  };
  const SampleSpan& span = SampleSpan::Of(samples);
  for (int round = 0; round < 600; ++round) {
    CullState st;
    st.SetSamples(samples);
    CHECK(st.span_x0 == int(span.x0));
    CHECK(st.span_y1 == int(span.y1));
    st.cull_enabled = round % 4 != 0;
    st.cull_face = faces[round % 3];
    st.front_face = round % 2 ? CW : CCW;
    st.bounds = Rect{int(unit(rng) * 40), int(unit(rng) * 40), 200 + int(unit(rng) * 40), 150 + int(unit(rng) * 40)};
    TriangleGroup g;
    g.count = 1 + round % TriangleGroup::kSize;
    const float size = (round % 5 == 0) ? 0.2f : (round % 5 == 1 ? 2.0f : (round % 5 == 2 ? 9.0f : 300.0f));
    const float far = round % 7 == 0 ? 20000.0f : 0.0f;
    for (int t = 0; t < g.count; ++t) {
      const float ax = far + unit(rng) * 260.0f - 20.0f, ay = unit(rng) * 210.0f - 20.0f;
      g.x[0][t] = ax;
      g.y[0][t] = ay;
      for (int k = 1; k < 3; ++k) {
        g.x[k][t] = ax + (unit(rng) - 0.5f) * size;
        g.y[k][t] = ay + (unit(rng) - 0.5f) * size;
      }
      if (t % 5 == 4) {  // a degenerate one: vertex 2 on vertex 1
        g.x[2][t] = g.x[1][t];
        g.y[2][t] = g.y[1][t];
      } else if (t % 7 == 6) {  // of some area in float, none once snapped: vertex 2 within 1/1024 of vertex 1
        g.x[2][t] = g.x[1][t] + 1.0f / 1024.0f;
        g.y[2][t] = g.y[1][t] - 1.0f / 2048.0f;
      }
    }
    const std::uint32_t bits = DrawsNothing(g, st);
    CHECK((bits >> g.count) == 0u);
    GroupVerdict verdict;
    JudgeTriangles(g, st, verdict);
    CHECK(verdict.nothing == bits);
    CHECK((verdict.known >> g.count) == 0u);
    for (int t = 0; t < g.count; ++t) {
      const WindowVertex v[3] = {W(g.x[0][t], g.y[0][t]), W(g.x[1][t], g.y[1][t]), W(g.x[2][t], g.y[2][t])};
      const float area = SignedArea(v, 3);
      const bool culled = area == 0.0f || (st.cull_enabled && IsCulled(IsFrontFacing(area, st.front_face), st.cull_face));
      const bool empty_box = culled || TriangleCentreBox(v[0].win, v[1].win, v[2].win, st.bounds, samples).Empty();
      const bool nothing = empty_box || (far == 0.0f && covers_nothing(v, st.bounds));
      uncovered += nothing && !empty_box;
      marked_uncovered += nothing && !empty_box && ((bits >> t) & 1u);
      const bool mark = (bits >> t) & 1u;
      INFO("round " << round << " triangle " << t);
      REQUIRE((!mark || nothing));
      marked += mark;
      dropped += nothing;
      if ((verdict.known >> t) & 1u) {  // (a sliver that covers no centre may be known)
        REQUIRE(!empty_box);
        CHECK(bool((verdict.front >> t) & 1u) == IsFrontFacing(area, st.front_face));
        const Rect box = TriangleCentreBox(v[0].win, v[1].win, v[2].win, st.bounds, samples), got = verdict.Box(t);
        CHECK((got.x0 == box.x0 && got.y0 == box.y0 && got.x1 == box.x1 && got.y1 == box.y1));
        ++known;
      }
      small_drawn += !nothing && size < 100.0f && far == 0.0f;
    }
  }
  INFO("samples " << samples << ": " << marked << " marked of " << dropped << " dropped, " << marked_uncovered
                   << " of " << uncovered << " uncovered");
  CHECK(marked > 1000);
  CHECK(marked >= dropped * 9 / 10);
  // Triangles with centres (samples) in their box and none covered: the tiny ones among them are marked.
  CHECK(uncovered > (samples == 1 ? 100 : 10));
  CHECK(marked_uncovered >= uncovered / 2);
  CHECK(small_drawn > 150);
  CHECK(known >= small_drawn);
}

TEST_CASE("a group of triangles: a tiny triangle is marked exactly when the rasterizer covers none of its centres, "
          "ties included", "[culling]") {
  // Vertices on a quarter-pixel grid around the centre (10.5, 10.5), so that many edges pass exactly through
  // pixel centres, where the tie rule decides; both windings; boxes of at most 2 x 2 pixels. Multisampled, on the
  // samples' 1/16 pixel grid, so that edges pass through sample positions, and the samples' positions tested.
  const int samples = GENERATE(1, 2, 4, 8);
  INFO("samples " << samples);
  std::mt19937 rng(7);
  const int grid = samples == 1 ? 4 : 16;
  std::uniform_int_distribution<int> step(-5 * grid / 4, 5 * grid / 4);
  testing::CoverageCounter counter(24, 24);
  CullState st;
  st.SetSamples(samples);
  st.bounds = Rect{0, 0, 24, 24};
  int marked = 0, covered = 0, tiny = 0;
  for (int round = 0; round < 400; ++round) {
    TriangleGroup g;
    g.count = TriangleGroup::kSize;
    for (int t = 0; t < g.count; ++t)
      for (int k = 0; k < 3; ++k) {
        g.x[k][t] = 10.5f + float(step(rng)) / float(grid);
        g.y[k][t] = 10.5f + float(step(rng)) / float(grid);
      }
    const std::uint32_t bits = DrawsNothing(g, st);
    for (int t = 0; t < g.count; ++t) {
      const WindowVertex v[3] = {W(g.x[0][t], g.y[0][t]), W(g.x[1][t], g.y[1][t]), W(g.x[2][t], g.y[2][t])};
      const Rect box = TriangleCentreBox(v[0].win, v[1].win, v[2].win, st.bounds, samples);
      if (box.x1 - box.x0 > 2 || box.y1 - box.y0 > 2) continue;  // not tiny: the group need not decide
      ++tiny;
      std::fill(counter.hits.begin(), counter.hits.end(), 0);
      auto blocks = std::make_unique<BlockBuffer>();
      RasterTarget target;
      target.bounds = st.bounds;
      target.samples = samples;
      blocks->samples = samples;
      const BlockSink sink = counter.Sink();
      RasterizeTriangle(v[0], v[1], v[2], true, target, *blocks, sink);
      sink.Flush(*blocks);
      const bool draws = std::any_of(counter.hits.begin(), counter.hits.end(), [](int h) { return h != 0; });
      INFO("round " << round << " triangle " << t);
      CHECK(((bits >> t) & 1u) == (draws ? 0u : 1u));
      marked += (bits >> t) & 1u;
      covered += draws;
    }
  }
  CHECK(tiny > 2000);
  CHECK(marked > 500);
  CHECK(covered > 500);
}

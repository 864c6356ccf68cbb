// Rasterization: the fill rule (no gaps, no double hits, Mesa's tie convention), bounds, lines and points.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "helpers.h"
#include "rasterizer.h"

using namespace softgl::detail;
using testing::CoverageCounter;

namespace {

WindowVertex W(float x, float y) {
  WindowVertex v{};
  v.win = glm::vec4(x, y, 0.5f, 1.0f);
  return v;
}

struct Raster {
  CoverageCounter counter;
  std::unique_ptr<BlockBuffer> blocks = std::make_unique<BlockBuffer>();
  RasterTarget target;
  explicit Raster(int w, int h) : counter(w, h) { target.bounds = Rect{0, 0, w, h}; }
  void Tri(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const BlockSink sink = counter.Sink();
    RasterizeTriangle(W(a.x, a.y), W(b.x, b.y), W(c.x, c.y), true, target, *blocks, sink);
    sink.Flush(*blocks);
  }
  void Line(glm::vec2 a, glm::vec2 b) {
    const BlockSink sink = counter.Sink();
    RasterizeLine(W(a.x, a.y), W(b.x, b.y), true, target, *blocks, sink);
    sink.Flush(*blocks);
  }
  void Point(glm::vec2 p, float size) {
    const BlockSink sink = counter.Sink();
    RasterizePoint(W(p.x, p.y), size, true, target, *blocks, sink);
    sink.Flush(*blocks);
  }
  // Rows top (high y) first, '#' for a hit, as the rows would read on screen.
  std::string Picture() const {
    std::string s;
    for (int y = counter.height - 1; y >= 0; --y) {
      for (int x = 0; x < counter.width; ++x) s += counter.At(x, y) ? '#' : '.';
      s += '\n';
    }
    return s;
  }
};

}  // namespace

TEST_CASE("centres on edges follow Mesa's rule: left and bottom edges own them", "[rasterizer]") {
  // The same two triangles drawn by Mesa's llvmpipe (OpenGL window coordinates, y up) give these pictures.
  Raster lower(10, 10);
  lower.Tri({2.5f, 2.5f}, {6.5f, 2.5f}, {2.5f, 6.5f});
  CHECK(lower.Picture() ==
        "..........\n"
        "..........\n"
        "..........\n"
        "..........\n"
        "..#.......\n"
        "..##......\n"
        "..###.....\n"
        "..####....\n"
        "..........\n"
        "..........\n");
  Raster upper(10, 10);
  upper.Tri({2.5f, 6.5f}, {6.5f, 6.5f}, {6.5f, 2.5f});
  CHECK(upper.Picture() ==
        "..........\n"
        "..........\n"
        "..........\n"
        "..........\n"
        "...###....\n"
        "....##....\n"
        ".....#....\n"
        "..........\n"
        "..........\n"
        "..........\n");
}

TEST_CASE("a grid of triangles sharing edges covers every pixel exactly once", "[rasterizer]") {
  // A 9 x 7 grid of jittered sub-pixel vertices over a 64 x 48 target, each cell split into two triangles
  // along alternating diagonals, in both windings; plus fans around interior vertices.
  constexpr int W = 64, H = 48, NX = 9, NY = 7;
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> jitter(-2.3f, 2.3f);
  glm::vec2 grid[NY + 1][NX + 1];
  for (int j = 0; j <= NY; ++j)
    for (int i = 0; i <= NX; ++i) {
      const bool border = i == 0 || j == 0 || i == NX || j == NY;
      // Border vertices sit outside the target so that the whole target is covered.
      grid[j][i] = glm::vec2(-3.0f + float(i) * (W + 6.0f) / NX, -3.0f + float(j) * (H + 6.0f) / NY);
      if (!border) grid[j][i] += glm::vec2(jitter(rng), jitter(rng));
      // Some vertices exactly on pixel centres and on pixel corners, where ties are decided.
      if (!border && (i + j) % 3 == 0) grid[j][i] = glm::floor(grid[j][i]) + 0.5f;
      if (!border && (i + j) % 3 == 1) grid[j][i] = glm::floor(grid[j][i]);
    }
  Raster r(W, H);
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      const glm::vec2 a = grid[j][i], b = grid[j][i + 1], c = grid[j + 1][i + 1], d = grid[j + 1][i];
      if ((i + j) % 2) {
        r.Tri(a, b, c);
        r.Tri(a, d, c);  // clockwise
      } else {
        r.Tri(a, b, d);
        r.Tri(b, c, d);
      }
    }
  int zero = 0, twice = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      zero += r.counter.At(x, y) == 0;
      twice += r.counter.At(x, y) > 1;
    }
  CHECK(zero == 0);
  CHECK(twice == 0);
}

TEST_CASE("a fan of thin triangles around a pixel centre hits each pixel once", "[rasterizer]") {
  constexpr int N = 37;
  Raster r(32, 32);
  const glm::vec2 c(16.5f, 16.5f);  // exactly on a pixel centre shared by every triangle
  glm::vec2 ring[N];
  for (int i = 0; i < N; ++i) {
    const float a = 2.0f * 3.14159265f * float(i) / float(N);
    ring[i] = c + 40.0f * glm::vec2(std::cos(a), std::sin(a));
  }
  for (int i = 0; i < N; ++i) r.Tri(c, ring[i], ring[(i + 1) % N]);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      INFO("pixel " << x << ", " << y);
      REQUIRE(r.counter.At(x, y) == 1);
    }
}

TEST_CASE("coverage stops at the target bounds", "[rasterizer]") {
  Raster r(8, 8);
  r.target.bounds = Rect{2, 3, 6, 5};
  r.Tri({-100, -100}, {100, -100}, {0, 100});
  int hits = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x < 6 && y >= 3 && y < 5;
      CHECK(r.counter.At(x, y) == (inside ? 1 : 0));
      hits += r.counter.At(x, y);
    }
  CHECK(hits == 8);
}

TEST_CASE("degenerate triangles produce nothing", "[rasterizer]") {
  Raster r(8, 8);
  r.Tri({1, 1}, {5, 5}, {3, 3});  // collinear
  r.Tri({2, 2}, {2, 2}, {2, 2});
  r.Tri({1.0f, 1.0f}, {7.0f, 1.0f}, {4.0f, 1.001f});  // sliver thinner than a subpixel: snaps to zero area
  for (int v : r.counter.hits) CHECK(v == 0);
}

TEST_CASE("a triangle's centre box holds every pixel it draws, and is empty when it draws nothing", "[rasterizer]") {
  // Random small triangles around pixel centres and edges (subpixel slivers to a few pixels, both windings),
  // plus out-of-range and zero-area ones: every pixel drawn lies in TriangleCentreBox, and a triangle whose box is
  // empty (the front end drops it) draws nothing; the test sees both kinds, so a box that dropped drawn
  // triangles, or one that missed drawn pixels, would fail it.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> place(2.0f, 6.0f), size(-1.5f, 1.5f);
  int dropped = 0, drawn = 0;
  for (int i = 0; i < 20000; ++i) {
    const float scale = (i % 3 == 0) ? 0.05f : (i % 3 == 1 ? 0.4f : 1.0f);
    const glm::vec2 a(place(rng), place(rng));
    const glm::vec2 b = a + scale * glm::vec2(size(rng), size(rng)), c = a + scale * glm::vec2(size(rng), size(rng));
    Raster r(8, 8);
    r.Tri(a, b, c);
    const Rect box = TriangleCentreBox(glm::vec4(a, 0.5f, 1.0f), glm::vec4(b, 0.5f, 1.0f),
                                       glm::vec4(c, 0.5f, 1.0f), r.target.bounds);
    INFO("triangle " << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y);
    int hits = 0, outside = 0;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x)
        if (r.counter.At(x, y)) {
          ++hits;
          outside += x < box.x0 || x >= box.x1 || y < box.y0 || y >= box.y1;
        }
    REQUIRE(outside == 0);
    dropped += box.Empty();
    drawn += hits > 0;
  }
  CHECK(dropped > 1000);
  CHECK(drawn > 1000);
  const Rect all{-100, -100, 100, 100};
  const glm::vec4 p(1.5f, 1.5f, 0.5f, 1.0f);
  CHECK(TriangleCentreBox(p, p, glm::vec4(3.5f, 3.5f, 0.5f, 1.0f), all).Empty());  // no area
  CHECK(TriangleCentreBox(p, glm::vec4(2e7f, 1.5f, 0.5f, 1.0f), glm::vec4(1.5f, 9.f, 0.5f, 1.0f), all).Empty());
  const Rect one = TriangleCentreBox(p, glm::vec4(1.5f, 0.5f, 0.5f, 1.0f), glm::vec4(0.5f, 1.5f, 0.5f, 1.0f), all);
  CHECK((one.x0 == 0 && one.x1 == 2 && one.y0 == 0 && one.y1 == 2));  // centres (0.5 .. 1.5) both ways
  CHECK(TriangleCentreBox(p, glm::vec4(1.5f, 0.5f, 0.5f, 1.0f), glm::vec4(0.5f, 1.5f, 0.5f, 1.0f),
                          Rect{5, 5, 9, 9}).Empty());  // outside the bounds
}

namespace {
// The fill rule pixel by pixel, as the specification states it: vertices snapped to 1/256 pixel, the centre inside
// every edge of the counter-clockwise triangle, or on a left or bottom one.
bool CoversCentre(glm::vec2 a, glm::vec2 b, glm::vec2 c, int x, int y) {
  const glm::vec2 v[3] = {a, b, c};
  std::int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) {
    X[i] = std::llrint(double(v[i].x) * 256.0);
    Y[i] = std::llrint(double(v[i].y) * 256.0);
  }
  const std::int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return false;
  if (area < 0) {
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
  }
  const std::int64_t px = std::int64_t(x) * 256 + 128, py = std::int64_t(y) * 256 + 128;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    const std::int64_t e = -dy * (px - X[i]) + dx * (py - Y[i]);
    const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);
    if (e < 0 || (e == 0 && !owns_ties)) return false;
  }
  return true;
}
}  // namespace

TEST_CASE("coverage matches the fill rule pixel by pixel, for small, medium and large triangles cut by bounds",
          "[rasterizer]") {
  // Sizes from a subpixel sliver to larger than the target: small triangles take the one-region path, larger ones
  // the region walk (skipped, partly covered and whole regions); bounds of every parity cut them.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float sizes[] = {0.3f, 2.0f, 5.0f, 9.0f, 24.0f, 80.0f};
  int pixels = 0;
  for (int i = 0; i < 3000; ++i) {
    const float size = sizes[i % 6];
    const glm::vec2 a(unit(rng) * 48.0f, unit(rng) * 40.0f);
    const glm::vec2 b = a + size * glm::vec2(unit(rng) - 0.5f, unit(rng) - 0.5f) * 2.0f;
    const glm::vec2 c = a + size * glm::vec2(unit(rng) - 0.5f, unit(rng) - 0.5f) * 2.0f;
    Raster r(48, 40);
    const int x0 = int(unit(rng) * 12), y0 = int(unit(rng) * 12);
    r.target.bounds = Rect{x0, y0, 48 - int(unit(rng) * 12), 40 - int(unit(rng) * 12)};
    r.Tri(a, b, c);
    INFO("triangle " << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y);
    int wrong = 0;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 48; ++x) {
        const Rect& k = r.target.bounds;
        const bool want = x >= k.x0 && x < k.x1 && y >= k.y0 && y < k.y1 && CoversCentre(a, b, c, x, y);
        wrong += r.counter.At(x, y) != (want ? 1 : 0);
        pixels += want;
      }
    REQUIRE(wrong == 0);
  }
  CHECK(pixels > 100000);
}

TEST_CASE("lines: one fragment per major-axis step, last pixel left out", "[rasterizer]") {
  Raster h(8, 4);
  h.Line({0.5f, 1.5f}, {6.5f, 1.5f});
  CHECK(h.Picture() ==
        "........\n"
        "........\n"
        "######..\n"
        "........\n");
  Raster d(6, 6);
  d.Line({0.5f, 0.5f}, {5.5f, 5.5f});
  CHECK(d.Picture() ==
        "......\n"
        "....#.\n"
        "...#..\n"
        "..#...\n"
        ".#....\n"
        "#.....\n");
  Raster v(4, 6);
  v.Line({1.5f, 5.5f}, {1.5f, 0.5f});  // downwards: the start pixel (row 5) in, the end pixel (row 0) out
  CHECK(v.Picture() ==
        ".#..\n"
        ".#..\n"
        ".#..\n"
        ".#..\n"
        ".#..\n"
        "....\n");
}

TEST_CASE("wide lines: each column (row) the line crosses holds w fragments centred on it", "[rasterizer][wide_lines]") {
  Raster h(8, 6);
  h.target.line_width = 3.0f;
  h.Line({0.5f, 2.5f}, {6.5f, 2.5f});
  CHECK(h.Picture() ==
        "........\n"
        "........\n"
        "######..\n"
        "######..\n"
        "######..\n"
        "........\n");
  // Two wide: the centres in [y - 1, y + 1) for a horizontal line (its lower side owns them, a bottom edge)...
  Raster h2(8, 6);
  h2.target.line_width = 2.0f;
  h2.Line({0.5f, 2.5f}, {6.5f, 2.5f});
  CHECK(h2.Picture() ==
        "........\n"
        "........\n"
        "........\n"
        "######..\n"
        "######..\n"
        "........\n");
  // ... and in (y - 1, y + 1] for a rising one, whose upper side is a left edge (as llvmpipe draws it).
  Raster r(10, 6);
  r.target.line_width = 2.0f;
  r.Line({0.5f, 0.5f}, {8.5f, 2.5f});
  CHECK(r.Picture() ==
        "..........\n"
        "..........\n"
        "..........\n"
        "....####..\n"
        "########..\n"
        "####......\n");
  // y-major: rows, each 3 wide; 2.6 rounds to 3.
  Raster v(6, 6);
  v.target.line_width = 2.6f;
  v.Line({2.5f, 0.5f}, {2.5f, 4.5f});
  CHECK(v.Picture() ==
        "......\n"
        "......\n"
        ".###..\n"
        ".###..\n"
        ".###..\n"
        ".###..\n");
  // Past the target's edges: cut to them, every pixel once.
  Raster e(8, 6);
  e.target.line_width = 5.0f;
  e.Line({-3.0f, 2.25f}, {20.0f, 2.75f});
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) CHECK(e.counter.At(x, y) == (y <= 4 ? 1 : 0));
  // Huge: no pixel twice, nothing outside.
  Raster g(16, 16);
  g.target.line_width = 255.0f;
  g.Line({-100.0f, 3.3f}, {100.0f, 9.1f});
  for (int n : g.counter.hits) CHECK(n == 1);
}

TEST_CASE("a line strip hits shared vertices once", "[rasterizer]") {
  Raster r(12, 12);
  r.Line({0.5f, 0.5f}, {8.5f, 3.5f});
  r.Line({8.5f, 3.5f}, {2.5f, 10.5f});
  r.Line({2.5f, 10.5f}, {0.5f, 0.5f});
  for (int v : r.counter.hits) CHECK(v <= 1);
  CHECK(r.counter.At(8, 3) == 1);
  CHECK(r.counter.At(0, 0) == 1);
}

TEST_CASE("points are squares of their size", "[rasterizer]") {
  Raster one(6, 6);
  one.Point({2.3f, 3.9f}, 1.0f);
  CHECK(one.counter.At(2, 3) == 1);
  int total = 0;
  for (int v : one.counter.hits) total += v;
  CHECK(total == 1);

  Raster three(8, 8);
  three.Point({4.5f, 4.5f}, 3.0f);
  CHECK(three.Picture() ==
        "........\n"
        "........\n"
        "...###..\n"
        "...###..\n"
        "...###..\n"
        "........\n"
        "........\n"
        "........\n");
  Raster two(6, 6);
  two.Point({3.0f, 3.0f}, 2.0f);  // centred on a pixel corner: the 2 x 2 block around it
  CHECK(two.counter.At(2, 2) + two.counter.At(3, 2) + two.counter.At(2, 3) + two.counter.At(3, 3) == 4);
}

TEST_CASE("lines: the diamond-exit rule at end points off pixel centres", "[rasterizer]") {
  // From (1.2, 1.3) to (9.7, 5.6): the end point lies inside pixel (9, 5)'s diamond, so that pixel is not drawn
  // (the same pictures as Mesa's llvmpipe).
  Raster fwd(12, 7);
  fwd.Line({1.2f, 1.3f}, {9.7f, 5.6f});
  CHECK(fwd.Picture() ==
        "............\n"
        "............\n"
        ".......##...\n"
        ".....##.....\n"
        "...##.......\n"
        ".##.........\n"
        "............\n");
  // Backwards, the start point is inside that diamond: the segment leaves it, so (9, 5) is drawn.
  Raster back(12, 7);
  back.Line({9.7f, 5.6f}, {1.2f, 1.3f});
  CHECK(back.counter.At(9, 5) == 1);
  CHECK(back.counter.At(1, 1) == 1);
  // A start point inside its diamond but past the centre still draws its pixel.
  Raster past(8, 3);
  past.Line({1.6f, 1.5f}, {6.2f, 1.5f});
  CHECK(past.Picture() ==
        "........\n"
        ".#####..\n"
        "........\n");
}

TEST_CASE("lines: varyings follow OpenGL's projection parameter", "[rasterizer]") {
  // A steep-ish x-major line with var[0] going 0 -> 1: at each fragment the value is the projection of the pixel
  // centre onto the segment, t = (p - a).(b - a) / |b - a|^2 (OpenGL 4.6, equation 14.3), not x alone.
  WindowVertex a = W(0.5f, 0.5f), b = W(20.5f, 12.5f);
  a.var[0] = 0.0f;
  b.var[0] = 1.0f;
  struct Sink {
    std::vector<std::pair<glm::vec2, float>> values;
    static void Flush(void* user, BlockBuffer& q) {
      for (int b = 0; b < q.count; ++b)
        for (int l = 0; l < softgl::kLanes; ++l)
          if ((q.live[b] >> l) & 1u)
            static_cast<Sink*>(user)->values.push_back(
                {glm::vec2(q.frag_coord[b][0][l], q.frag_coord[b][1][l]), q.Varyings(b)[l]});  // var 0
    }
  } collected;
  auto blocks = std::make_unique<BlockBuffer>();
  RasterTarget target;
  target.bounds = Rect{0, 0, 32, 32};
  target.nvar = 1;
  const BlockSink sink{&Sink::Flush, &collected};
  RasterizeLine(a, b, true, target, *blocks, sink);
  sink.Flush(*blocks);
  REQUIRE(collected.values.size() == 20);
  for (const auto& [p, value] : collected.values) {
    const glm::vec2 d(20.0f, 12.0f);
    const float t = glm::dot(p - glm::vec2(0.5f, 0.5f), d) / glm::dot(d, d);
    CHECK(value == Approx(t).margin(1e-5));
  }
}

namespace {

// Every block a sink receives, as words: facing, quads, positions, coverage (and each sample's), gl_FragCoord and
// the varyings of every lane (interpolated here), compared bit for bit.
struct BlockRecorder {
  std::vector<std::uint32_t> words;
  static void Flush(void* user, BlockBuffer& blocks) {
    auto& w = static_cast<BlockRecorder*>(user)->words;
    InterpolateVaryings(blocks);
    auto bits = [&](float f) {
      std::uint32_t u;
      std::memcpy(&u, &f, sizeof u);
      w.push_back(u);
    };
    for (int b = 0; b < blocks.count; ++b) {
      w.push_back(blocks.front_facing);
      w.push_back(std::uint32_t(blocks.quads[b]));
      w.push_back(blocks.live[b]);
      for (int s = 0; blocks.samples > 1 && s < blocks.samples; ++s) w.push_back(blocks.sample_live[b][s]);
      for (int q = 0; q < 4; ++q) {
        w.push_back(std::uint32_t(blocks.qx[b][q]));
        w.push_back(std::uint32_t(blocks.qy[b][q]));
      }
      for (int c = 0; c < 4; ++c)
        for (int l = 0; l < softgl::kLanes; ++l) bits(blocks.frag_coord[b][c][l]);
      const float* v = blocks.Varyings(b);
      for (int i = 0; i < blocks.nvar * softgl::kLanes; ++i) bits(v[i]);
    }
  }
  BlockSink Sink() { return {&BlockRecorder::Flush, this}; }
};

}  // namespace

TEST_CASE("triangles rasterized in groups give the quads and values of one at a time", "[rasterizer]") {
  // RasterizeTriangles sets up many triangles per instruction where their coordinates allow and falls back to the
  // one-triangle set-up elsewhere: small, medium and large triangles, slivers whose float area disagrees with the
  // snapped one, vertices on pixel centres (ties), far from the origin, beyond the range, of no area, NaN.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float sizes[] = {0.4f, 3.0f, 7.0f, 12.0f, 60.0f, 127.0f, 200.0f, 3000.0f};
  constexpr int kVar = 3;
  std::vector<float> vars;
  for (int samples : {1, 4}) {
    std::vector<WindowVertex> v;
    std::vector<float> offsets;
    std::vector<bool> front;
    for (int i = 0; i < 4000; ++i) {
      const int kind = i % 11;
      const float size = sizes[i % 8];
      glm::vec2 a(unit(rng) * 300.0f - 20.0f, unit(rng) * 220.0f - 20.0f);
      if (kind == 9) a += glm::vec2(16384.0f - 200.0f * unit(rng), 0.0f);  // at the edge of the exact range
      glm::vec2 p[3] = {a, a + size * glm::vec2(unit(rng) - 0.5f, unit(rng) - 0.5f) * 2.0f,
                        a + size * glm::vec2(unit(rng) - 0.5f, unit(rng) - 0.5f) * 2.0f};
      if (kind == 1)  // on pixel centres
        for (auto& q : p) q = glm::floor(q) + 0.5f;
      if (kind == 2) p[2] = p[0] + (p[1] - p[0]) * 0.37f + glm::vec2(1e-4f, -1e-4f) * unit(rng);  // a sliver
      if (kind == 3) p[2] = p[1];  // no area
      if (kind == 4 && i % 3 == 0) p[1].x = std::numeric_limits<float>::quiet_NaN();
      if (kind == 5) p[2].y = 1e6f * (unit(rng) - 0.5f);  // beyond 16384 pixels
      for (int k = 0; k < 3; ++k) {
        WindowVertex w{};
        w.win = glm::vec4(p[k], unit(rng), 0.2f + unit(rng));
        for (int j = 0; j < kVar; ++j) w.var[j] = unit(rng) * 10.0f - 5.0f;
        v.push_back(w);
      }
      offsets.push_back(kind == 6 ? unit(rng) * 0.01f : 0.0f);
      front.push_back(unit(rng) < 0.7f);
    }
    const int count = int(offsets.size());
    auto run = [&](bool grouped) {
      BlockRecorder rec;
      auto blocks = std::make_unique<BlockBuffer>();
      blocks->samples = samples;
      RasterTarget target;
      target.bounds = Rect{3, 5, 250, 190};
      target.nvar = kVar;
      target.samples = samples;
      const BlockSink sink = rec.Sink();
      std::mt19937 sizes_rng(3);
      for (int t = 0; t < count;) {
        const int n = std::min(count - t, 1 + int(sizes_rng() % kTriangleGroup));  // groups of every size
        if (grouped) {
          TriangleQueue q;
          for (int k = t; k < t + n; ++k)
            q.Add(v[std::size_t(3 * k)], v[std::size_t(3 * k + 1)], v[std::size_t(3 * k + 2)], offsets[std::size_t(k)],
                  front[std::size_t(k)]);
          RasterizeTriangles(q, target, *blocks, sink);
          CHECK(q.count == 0);
        } else {
          for (int k = t; k < t + n; ++k) {
            target.depth_offset = offsets[std::size_t(k)];
            RasterizeTriangle(v[std::size_t(3 * k)], v[std::size_t(3 * k + 1)], v[std::size_t(3 * k + 2)],
                              front[std::size_t(k)], target, *blocks, sink);
          }
        }
        t += n;
      }
      sink.Flush(*blocks);
      return rec.words;
    };
    const std::vector<std::uint32_t> one = run(false), grouped = run(true);
    INFO("samples " << samples);
    CHECK(one.size() > 100000);
    REQUIRE(one.size() == grouped.size());
    // (The first difference, not the whole streams: their printout would be millions of words.)
    const auto diff = std::mismatch(one.begin(), one.end(), grouped.begin());
    CHECK(diff.first - one.begin() == std::ptrdiff_t(one.size()));
  }
}

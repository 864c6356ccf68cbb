// Tests of hierarchical depth (src/hierarchical_depth.h): the bound test on its own, then whole scenes drawn with
// it on and off, which must give the same bytes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "color_shader.h"
#include "helpers.h"
#include "hierarchical_depth.h"

using namespace softgl;
using softgl::detail::HierarchicalDepth;
using softgl::detail::Plane;
using softgl::detail::Rect;
using softgl::detail::RenderTarget;

namespace {

// A 64 x 64 single-sampled target (one tile) with a float depth buffer of `value`, or a 16-bit one.
struct DepthTile {
  std::vector<float> depth;
  std::vector<std::uint16_t> depth16;
  RenderTarget target;
  explicit DepthTile(float value, bool sixteen = false) {
    target.width = target.height = 64;
    target.depth_pitch = 64;
    if (sixteen) {
      depth16.assign(64 * 64, RenderTarget::Depth16(value));
      target.depth16 = depth16.data();
    } else {
      depth.assign(64 * 64, value);
      target.depth = depth.data();
    }
  }
};

Plane FlatPlane(float z) { return Plane{z, 0.0f, 0.0f}; }

}  // namespace

TEST_CASE("hierarchical depth: a plane behind every stored depth under its pixels is hidden, one that may reach "
          "nearer is not",
          "[hierarchical_depth]") {
  DepthTile tile(0.5f);
  HierarchicalDepth hz;
  hz.Begin(tile.target, Rect{0, 0, 64, 64});
  for (const bool lequal : {false, true}) {
    hz.func = lequal ? LEQUAL : LESS;
    CHECK(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK(hz.Hides(FlatPlane(0.5001f), 0.0f, 0.0f, 10, 3, 40, 60));
    CHECK_FALSE(hz.Hides(FlatPlane(0.4f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK_FALSE(hz.Hides(FlatPlane(0.5f), 0.0f, 0.0f, 0, 0, 7, 7));  // equal passes LEQUAL (and the bound is not exact)
    // Sloped: 0.6 at x = 0 falling to 0.49 at the far side of pixel 7 (its centre 0.497) reaches nearer.
    CHECK_FALSE(hz.Hides(Plane{0.6f, -0.11f / 8.0f, 0.0f}, 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK(hz.Hides(Plane{0.6f, -0.09f / 8.0f, 0.0f}, 0.0f, 0.0f, 0, 0, 7, 7));
    // Relative to a vertex elsewhere: z = 0.7 - 0.01 (x - 30) is 0.76 at x = 24, 0.68 at x = 32.
    CHECK(hz.Hides(Plane{0.7f, -0.01f, 0.0f}, 30.0f, 5.0f, 24, 0, 31, 7));
    CHECK_FALSE(hz.Hides(Plane{0.7f, -0.05f, 0.0f}, 30.0f, 5.0f, 24, 0, 40, 7));  // 0.2 at x = 40
    // No bound from NaN or infinite planes.
    CHECK_FALSE(hz.Hides(FlatPlane(NAN), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK_FALSE(hz.Hides(FlatPlane(INFINITY), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK_FALSE(hz.Hides(Plane{0.6f, INFINITY, 0.0f}, 0.0f, 0.0f, 0, 0, 7, 7));
  }

  SECTION("a depth written farther is seen once the block is marked stale") {
    tile.depth[3 * 64 + 5] = 0.7f;  // pixel (5, 3), block 0
    hz.func = LESS;
    hz.TouchAll();
    CHECK_FALSE(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 8, 0, 15, 7));  // block 1 is still at 0.5
    CHECK_FALSE(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 4, 0, 12, 3));  // over blocks 0 and 1
    CHECK(hz.Hides(FlatPlane(0.71f), 0.0f, 0.0f, 4, 0, 12, 3));
  }
  SECTION("a clear of the whole tile gives every block its value; a block is read again kAsks asks later, and only "
          "where its bound as it stands does not hide the plane") {
    hz.Cleared(0.7f);  // as if cleared to 0.7 and drawn nearer since (the buffer holds 0.5), nothing read
    hz.func = LESS;
    for (int ask = 1; ask < HierarchicalDepth::kAsks; ++ask)  // behind 0.7, then in front of it, and so on
      CHECK(hz.Hides(FlatPlane(ask % 2 ? 0.8f : 0.6f), 0.0f, 0.0f, 0, 0, 7, 7) == (ask % 2 == 1));
    CHECK(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));  // read again: the 0.5 the buffer holds
    hz.Cleared(0.7f);
    for (int y = 0; y < 8; ++y)  // (a state no drawing makes: 0.9 behind the bound, to show when it is read)
      for (int x = 0; x < 8; ++x) tile.depth[std::size_t(y * 64 + x)] = 0.9f;
    for (int ask = 1; ask <= 2 * HierarchicalDepth::kAsks; ++ask)  // hidden by the bound as it stands: not read
      CHECK(hz.Hides(FlatPlane(0.8f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK_FALSE(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));  // due long since: read for this one (0.9)
    CHECK_FALSE(hz.Hides(FlatPlane(0.8f), 0.0f, 0.0f, 0, 0, 7, 7));  // and the 0.9 kept
    hz.Cleared(0.7f);
    hz.Wrote(GREATER);  // writes that may have moved depths farther: read before use (the 0.7 would hide it)
    CHECK_FALSE(hz.Hides(FlatPlane(0.8f), 0.0f, 0.0f, 0, 0, 7, 7));
  }

  SECTION("GREATER and GEQUAL against the nearest stored depth") {
    for (const Enum func : {GREATER, GEQUAL}) {
      hz.func = func;
      CHECK(hz.Hides(FlatPlane(0.4f), 0.0f, 0.0f, 0, 0, 7, 7));
      CHECK_FALSE(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));
      CHECK_FALSE(hz.Hides(FlatPlane(0.5f), 0.0f, 0.0f, 0, 0, 7, 7));
      // Sloped: 0.4 at x = 0 rising to 0.51 at the far side of pixel 7 reaches farther.
      CHECK_FALSE(hz.Hides(Plane{0.4f, 0.11f / 8.0f, 0.0f}, 0.0f, 0.0f, 0, 0, 7, 7));
      CHECK(hz.Hides(Plane{0.4f, 0.09f / 8.0f, 0.0f}, 0.0f, 0.0f, 0, 0, 7, 7));
    }
    hz.func = GREATER;
    for (std::size_t i = 0; i < 64 * 8; ++i) tile.depth[i] = 0.0f;  // clamped to 0: not above 0
    hz.TouchAll();
    CHECK(hz.Hides(FlatPlane(-1.0f), 0.0f, 0.0f, 0, 0, 63, 7));
    hz.func = GEQUAL;
    CHECK_FALSE(hz.Hides(FlatPlane(-1.0f), 0.0f, 0.0f, 0, 0, 63, 7));
  }
  SECTION("a bound that writes may have made wrong is read again: nearer writes for GREATER, farther for LESS") {
    hz.func = GREATER;
    CHECK(hz.Hides(FlatPlane(0.3f), 0.0f, 0.0f, 0, 0, 7, 7));  // (block 0 read: 0.5)
    tile.depth[2 * 64 + 2] = 0.2f;  // a LESS draw brings pixel (2, 2) nearer
    hz.Wrote(LESS);
    CHECK_FALSE(hz.Hides(FlatPlane(0.3f), 0.0f, 0.0f, 0, 0, 7, 7));
    hz.func = LESS;
    CHECK(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));
    tile.depth[2 * 64 + 2] = 0.7f;  // a GREATER draw takes it farther
    hz.Wrote(GREATER);
    CHECK_FALSE(hz.Hides(FlatPlane(0.6f), 0.0f, 0.0f, 0, 0, 7, 7));
    tile.depth[2 * 64 + 2] = 0.9f;  // ALWAYS, either way
    hz.Wrote(ALWAYS);
    CHECK_FALSE(hz.Hides(FlatPlane(0.8f), 0.0f, 0.0f, 0, 0, 7, 7));
  }
  SECTION("a depth brought nearer tightens the bound within a few asks, and never makes it wrong") {
    hz.func = LESS;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) tile.depth[std::size_t(y * 64 + x)] = 0.2f;  // (as LESS writes: nearer)
    bool hidden = false;
    for (int k = 0; k < HierarchicalDepth::kAsks; ++k) hidden = hz.Hides(FlatPlane(0.3f), 0.0f, 0.0f, 0, 0, 7, 7);
    CHECK(hidden);
    CHECK_FALSE(hz.Hides(FlatPlane(0.1f), 0.0f, 0.0f, 0, 0, 7, 7));
  }
  SECTION("depth beyond [0, 1] is clamped as the depth test clamps it") {
    for (std::size_t i = 0; i < 64 * 8; ++i) tile.depth[i] = 1.0f;  // row of blocks 0
    hz.TouchAll();
    hz.func = LESS;
    CHECK(hz.Hides(FlatPlane(2.0f), 0.0f, 0.0f, 0, 0, 63, 7));  // clamped to 1: not below 1
    hz.func = LEQUAL;
    CHECK_FALSE(hz.Hides(FlatPlane(2.0f), 0.0f, 0.0f, 0, 0, 63, 7));  // 1 <= 1 passes
    for (std::size_t i = 0; i < 64 * 8; ++i) tile.depth[i] = 0.0f;
    hz.TouchAll();
    hz.func = LESS;
    CHECK(hz.Hides(FlatPlane(-1.0f), 0.0f, 0.0f, 0, 0, 63, 7));  // clamped to 0: not below 0
    hz.func = LEQUAL;
    CHECK_FALSE(hz.Hides(FlatPlane(-1.0f), 0.0f, 0.0f, 0, 0, 63, 7));
  }
}

TEST_CASE("hierarchical depth: no plane is hidden from a stored depth that its nearest fragment passes, however "
          "its evaluation rounds",
          "[hierarchical_depth]") {
  // Random planes, gradients from 1e-12 (where only rounding separates the fragments) to 1e2 per pixel; the
  // block's depths set to what its nearest fragment passes (equal to it for LEQUAL, one step farther for LESS; the
  // farthest for GEQUAL and GREATER), a fragment's depth evaluated as the rasterizer does: (a0 + dx rx) + dy ry with
  // rx = (x + 0.5) - x0.
  std::mt19937 rng(7);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
  int cases = 0;
  for (int i = 0; i < 20000; ++i) {
    const float a0 = uniform(0.0f, 1.0f), x0 = uniform(-300.0f, 300.0f), y0 = uniform(-300.0f, 300.0f);
    const float dx = std::pow(10.0f, uniform(-12.0f, 2.0f)) * (uniform(0, 1) < 0.5f ? -1.0f : 1.0f);
    const float dy = std::pow(10.0f, uniform(-12.0f, 2.0f)) * (uniform(0, 1) < 0.5f ? -1.0f : 1.0f);
    const Plane z{a0, dx, dy};
    float nearest = INFINITY, farthest = -INFINITY;
    for (int y = 8; y < 16; ++y)
      for (int x = 16; x < 24; ++x) {
        const float rx = (float(x) + 0.5f) - x0, ry = (float(y) + 0.5f) - y0;
        const float d = (z.a0 + z.dx * rx) + z.dy * ry;
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
      }
    if (!(nearest > 0.0f && farthest < 1.0f)) continue;  // (inside the depth range: no clamping)
    ++cases;
    // The stored depth each comparison's nearest (farthest) fragment just passes.
    const std::pair<Enum, float> tests[] = {{LEQUAL, nearest},
                                            {LESS, std::nextafter(nearest, 2.0f)},
                                            {GEQUAL, farthest},
                                            {GREATER, std::nextafter(farthest, -1.0f)}};
    for (const auto& [func, stored] : tests) {
      DepthTile tile(stored);
      HierarchicalDepth hz;
      hz.Begin(tile.target, Rect{0, 0, 64, 64});
      hz.func = func;
      if (hz.Hides(z, x0, y0, 16, 8, 23, 15)) {
        CAPTURE(a0, x0, y0, dx, dy, nearest, farthest, func);
        FAIL_CHECK("hidden");
      }
    }
  }
  CHECK(cases > 1000);
}

TEST_CASE("hierarchical depth: a multisampled buffer's bounds are over every sample", "[hierarchical_depth]") {
  for (const bool interleaved : {false, true}) {
    CAPTURE(interleaved);
    // 64 x 64, 4 samples: planes one after another, or each pixel's samples side by side.
    std::vector<float> depth(64 * 64 * 4, 0.2f);
    RenderTarget t;
    t.width = t.height = 64;
    t.samples = 4;
    t.depth = depth.data();
    t.interleaved = interleaved;
    t.step = interleaved ? 4 : 1;
    t.depth_pitch = interleaved ? 64 * 4 : 64;
    t.depth_plane = interleaved ? 1 : 64 * 64;
    depth[t.DepthIndex(5, 3, 2)] = 1.0f;  // one sample of pixel (5, 3), block 0, not drawn over
    depth[t.DepthIndex(13, 3, 1)] = 0.0f;  // one of pixel (13, 3), block 1, nearer
    HierarchicalDepth hz;
    hz.Begin(t, Rect{0, 0, 64, 64});
    hz.func = LESS;
    CHECK_FALSE(hz.Hides(FlatPlane(0.5f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK(hz.Hides(FlatPlane(0.5f), 0.0f, 0.0f, 8, 0, 15, 7));
    hz.func = GREATER;
    CHECK(hz.Hides(FlatPlane(0.1f), 0.0f, 0.0f, 0, 0, 7, 7));
    CHECK_FALSE(hz.Hides(FlatPlane(0.1f), 0.0f, 0.0f, 8, 0, 15, 7));
  }
}

TEST_CASE("hierarchical depth: a 16-bit depth buffer is compared as the test converts depths", "[hierarchical_depth]") {
  DepthTile tile(0.5f, true);  // stored 32768 (0.5 * 65535 = 32767.5, ties to even)
  REQUIRE(tile.depth16[0] == 32768);
  HierarchicalDepth hz;
  hz.Begin(tile.target, Rect{0, 0, 64, 64});
  // 0.50001 * 65535 = 32768.16: 32768 too, not below the stored value (LESS fails), equal to it (LEQUAL passes).
  hz.func = LESS;
  CHECK(hz.Hides(FlatPlane(0.50001f), 0.0f, 0.0f, 0, 0, 63, 63));
  hz.func = LEQUAL;
  CHECK_FALSE(hz.Hides(FlatPlane(0.50001f), 0.0f, 0.0f, 0, 0, 63, 63));
  CHECK(hz.Hides(FlatPlane(0.50005f), 0.0f, 0.0f, 0, 0, 63, 63));  // 32770
  hz.func = LESS;
  CHECK_FALSE(hz.Hides(FlatPlane(0.4999f), 0.0f, 0.0f, 0, 0, 63, 63));
}

namespace {

using testing::ColorShader;

struct SceneResult {
  std::vector<std::uint8_t> color;
  std::vector<float> depth;
  Context::HierarchicalDepthCounts counts;
};

// A random scene of many draws, 150 x 110 (3 x 2 tiles, the last ones partial): an occluder, then triangles in
// front of and behind it, coplanar with it, steep (nearly edge-on), beyond the depth range, with random depth
// functions and masks, polygon offset, lines and points, the stencil test, scissored depth clears; `reversed`:
// the depth cleared to 0 and GREATER for LESS (a reversed depth range's usual state); `samples` for the context's
// framebuffer (4: multisampled, MULTISAMPLE sometimes disabled).
SceneResult DrawScene(bool hierarchical, int threads, Enum depth_format, std::uint32_t seed, bool reversed,
                      int samples) {
  Context::Options options;
  options.threads = threads;
  options.depth_format = depth_format;
  options.samples = samples;
  Context gl(150, 110, options);
  gl.UseHierarchicalDepth(hierarchical);
  ColorShader shader;
  gl.UseProgram(shader);
  std::mt19937 rng(seed);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
  auto pick = [&](int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(rng)); };
  std::vector<glm::vec4> positions, colors;
  auto vertex = [&](float x, float y, float z) {
    positions.push_back({x, y, z, 1.0f});
    colors.push_back({uniform(0, 1), uniform(0, 1), uniform(0, 1), 1.0f});
  };
  // The occluder (two triangles over most of the window at z = 0), then triangles of every kind.
  vertex(-0.9f, -0.9f, 0.0f), vertex(0.9f, -0.9f, 0.0f), vertex(0.9f, 0.9f, 0.0f);
  vertex(-0.9f, -0.9f, 0.0f), vertex(0.9f, 0.9f, 0.0f), vertex(-0.9f, 0.9f, 0.0f);
  const int kTriangles = 1500;
  for (int i = 0; i < kTriangles; ++i) {
    const float cx = uniform(-1.1f, 1.1f), cy = uniform(-1.1f, 1.1f), size = pick(4) == 0 ? uniform(0.3f, 1.5f) : uniform(0.01f, 0.2f);
    switch (pick(5)) {
      case 0:  // coplanar with the occluder
        for (int k = 0; k < 3; ++k) vertex(cx + uniform(-size, size), cy + uniform(-size, size), 0.0f);
        break;
      case 1: {  // steep: depth changes fast across a thin triangle
        const float z = uniform(-0.5f, 0.5f);
        vertex(cx, cy, z - 0.8f), vertex(cx + size, cy + size * 0.01f, z + 0.8f), vertex(cx + size * 0.5f, cy + size * 0.02f, z);
        break;
      }
      case 2:  // reaching beyond the depth range (clipped, or clamped where it crosses nothing)
        for (int k = 0; k < 3; ++k) vertex(cx + uniform(-size, size), cy + uniform(-size, size), uniform(-1.5f, 1.5f));
        break;
      default:  // behind or in front, flat or sloped
        for (int k = 0; k < 3; ++k) vertex(cx + uniform(-size, size), cy + uniform(-size, size), uniform(-0.3f, 0.9f));
    }
  }
  testing::MakeVertexArray(gl, positions, colors);
  gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  gl.ClearDepth(reversed ? 0.0 : 1.0);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  gl.Enable(DEPTH_TEST);
  gl.DepthFunc(reversed ? GREATER : LESS);
  gl.DrawArrays(TRIANGLES, 0, 6);
  // Mostly nearer passing (or, reversed, farther passing: depth from 1 near to 0 far), the others among them.
  const Enum funcs[] = {LESS, LESS, LESS, LEQUAL, LEQUAL, GREATER, GEQUAL, ALWAYS, EQUAL, NOTEQUAL, NEVER};
  const Enum reversed_funcs[] = {GREATER, GREATER, GREATER, GEQUAL, GEQUAL, LESS, LEQUAL, ALWAYS, EQUAL, NOTEQUAL, NEVER};
  for (int first = 6; first < 6 + 3 * kTriangles;) {
    const int count = 3 * (1 + pick(40));
    const int n = std::min(count, 6 + 3 * kTriangles - first);
    gl.DepthFunc((reversed ? reversed_funcs : funcs)[pick(11)]);
    gl.DepthMask(pick(4) != 0);
    if (pick(6) == 0) gl.Enable(POLYGON_OFFSET_FILL), gl.PolygonOffset(uniform(-2, 2), uniform(-4, 4));
    else gl.Disable(POLYGON_OFFSET_FILL);
    if (samples > 1 && pick(4) == 0) gl.Disable(MULTISAMPLE);  // (each fragment then covers all its samples)
    else if (samples > 1) gl.Enable(MULTISAMPLE);
    if (pick(8) == 0) {  // the stencil test counts depth failures
      gl.Enable(STENCIL_TEST);
      gl.StencilFunc(ALWAYS, 0, 0xFF);
      gl.StencilOp(KEEP, INCR, KEEP);
    } else {
      gl.Disable(STENCIL_TEST);
    }
    const int kind = pick(10);
    if (kind == 0) gl.DrawArrays(LINES, first, n - n % 2);
    else if (kind == 1) gl.DrawArrays(POINTS, first, n);
    else gl.DrawArrays(TRIANGLES, first, n);
    if (pick(5) == 0) {  // a depth clear, often to the far end (what lay nearer is gone): mostly of part of the
                         // window, else of all of it (whole tiles, whose bounds then come from the clear value)
      const bool part = pick(3) != 0;
      if (part) gl.Enable(SCISSOR_TEST);
      gl.Scissor(pick(150), pick(110), 1 + pick(100), 1 + pick(80));
      gl.ClearDepth(pick(2) ? (reversed ? 0.0 : 1.0) : uniform(0, 1));
      gl.Clear(DEPTH_BUFFER_BIT);
      gl.Disable(SCISSOR_TEST);
    }
    first += n;
  }
  SceneResult r;
  r.color.resize(150 * 110 * 4);
  r.depth.resize(150 * 110);
  std::vector<std::uint8_t> stencil(152 * 110);  // rows of 150 bytes padded to PACK_ALIGNMENT 4
  gl.ReadPixels(0, 0, 150, 110, RGBA, UNSIGNED_BYTE, r.color.data());
  gl.ReadPixels(0, 0, 150, 110, DEPTH_COMPONENT, FLOAT, r.depth.data());
  gl.ReadPixels(0, 0, 150, 110, STENCIL_INDEX, UNSIGNED_BYTE, stencil.data());
  r.color.insert(r.color.end(), stencil.begin(), stencil.end());
  r.counts = gl.TakeHierarchicalDepthCounts();
  return r;
}

}  // namespace

TEST_CASE("hierarchical depth drops only what the depth test would: random scenes give the same bytes with it on "
          "and off",
          "[hierarchical_depth]") {
  for (const bool reversed : {false, true})
    for (const int samples : {0, 4}) {
    std::uint64_t hidden = 0;
    for (const Enum format : {DEPTH_COMPONENT32F, DEPTH_COMPONENT16})
      for (const int threads : {1, 3})
        for (std::uint32_t seed = 1; seed <= 6; ++seed) {
          CAPTURE(reversed, samples, format, threads, seed);
          const SceneResult on = DrawScene(true, threads, format, seed, reversed, samples);
          const SceneResult off = DrawScene(false, threads, format, seed, reversed, samples);
          const bool same_color = on.color == off.color, same_depth = on.depth == off.depth;
          CHECK(same_color);
          CHECK(same_depth);
          CHECK(off.counts.triangles_tested + off.counts.regions_tested == 0);
          hidden += on.counts.triangles_hidden + on.counts.regions_hidden;
        }
    CAPTURE(reversed, samples, hidden);
    CHECK(hidden > 500);  // the scenes give it something to drop
  }
}

TEST_CASE("hierarchical depth: a depth clear between draws is seen at once, also where the multisampled tile only "
          "notes it",
          "[hierarchical_depth]") {
  // A near quad (drawn 1 to 4 times, so that the bounds are read at different points), a clear of the whole
  // window's depth, a far quad: the far one is drawn (its first triangles would be dropped against bounds read
  // before the clear).
  for (const int samples : {0, 4})
  for (int repeats = 1; repeats <= 4; ++repeats) {
    CAPTURE(samples, repeats);
    Context::Options options;
    options.samples = samples;
    Context gl(64, 64, options);
    ColorShader shader;
    gl.UseProgram(shader);
    const std::vector<glm::vec4> quad = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1},
                                         {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
    std::vector<glm::vec4> positions, colors;
    for (const float z : {-0.6f, 0.0f})
      for (const glm::vec4& p : quad) {
        positions.push_back({p.x, p.y, z, 1.0f});
        colors.push_back(z < 0.0f ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 0, 1, 1));
      }
    testing::MakeVertexArray(gl, positions, colors);
    gl.Enable(DEPTH_TEST);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    for (int k = 0; k < repeats; ++k) gl.DrawArrays(TRIANGLES, 0, 6);  // near, red
    gl.Clear(DEPTH_BUFFER_BIT);
    gl.DrawArrays(TRIANGLES, 6, 6);  // far, blue: passes against the cleared depth
    for (const auto& [x, y] : {std::pair{10, 50}, std::pair{50, 10}}) {  // each of its two triangles
      std::uint8_t px[4];
      gl.ReadPixel(x, y, px);
      CHECK(int(px[0]) == 0);
      CHECK(int(px[2]) == 255);
    }
  }
}

// test_multisample.cpp — multisampling: per-sample coverage in the rasterizer, per-sample tests and writes, the
// coverage operations, resolves, the multisampled context framebuffer, and the calls' errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <vector>

#include <softgl/softgl.h>

#include "helpers.h"
#include "rasterizer.h"
#include "types.h"

using namespace softgl;
using namespace testing;

namespace {

// Every sample mask the rasterizer emits, by pixel: bit s for sample s; and how often each pixel was emitted.
struct SampleRecorder {
  int width, height, samples;
  std::vector<std::uint32_t> mask;
  std::vector<int> emitted;
  SampleRecorder(int w, int h, int n)
      : width(w), height(h), samples(n), mask(std::size_t(w * h), 0), emitted(std::size_t(w * h), 0) {}
  static void Flush(void* user, detail::BlockBuffer& blocks) {
    auto* self = static_cast<SampleRecorder*>(user);
    for (int b = 0; b < blocks.count; ++b)
      for (int lane = 0; lane < kLanes; ++lane) {
        if (!((blocks.live[b] >> lane) & 1u)) continue;
        const std::size_t i = std::size_t(blocks.Y(b, lane) * self->width + blocks.X(b, lane));
        ++self->emitted[i];
        for (int s = 0; s < self->samples; ++s)
          if ((blocks.sample_live[b][s] >> lane) & 1u) self->mask[i] |= 1u << s;
      }
  }
};

// The reference: whether the point (px, py), in 1/256 pixel, is inside the triangle of snapped vertices X, Y, by
// OpenGL's rule for points on an edge (a left or bottom edge of the counter-clockwise triangle owns them).
bool Inside(std::int64_t px, std::int64_t py, std::int64_t X[3], std::int64_t Y[3]) {
  const std::int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return false;
  int order[3] = {0, 1, 2};
  if (area < 0) std::swap(order[1], order[2]);
  for (int e = 0; e < 3; ++e) {
    const int i = order[e], j = order[(e + 1) % 3];
    const std::int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    const std::int64_t value = dx * (py - Y[i]) - dy * (px - X[i]);
    const bool owns = dy < 0 || (dy == 0 && dx > 0);
    if (value < 0 || (value == 0 && !owns)) return false;
  }
  return true;
}

Context::Options Samples(int n) {
  Context::Options o;
  o.samples = n;
  o.threads = 1;
  return o;
}

int Red(Context& gl, int x, int y) {
  std::uint8_t p[4];
  gl.ReadPixel(x, y, p);
  return p[0];
}

// A framebuffer object with a multisampled RGBA8 colour and DEPTH24_STENCIL8 renderbuffer, and a single-sampled
// one to resolve into; Resolve() blits and returns the resolved pixel's bytes.
struct MultisampleFbo {
  Context& gl;
  std::uint32_t ms = 0, single = 0;
  int width, height;
  MultisampleFbo(Context& context, int samples, int w, int h, Enum colour = RGBA8, Enum resolved = RGBA8)
      : gl(context), width(w), height(h) {
    const std::uint32_t rb[3] = {gl.GenRenderbuffer(), gl.GenRenderbuffer(), gl.GenRenderbuffer()};
    ms = gl.GenFramebuffer();
    gl.BindFramebuffer(FRAMEBUFFER, ms);
    gl.BindRenderbuffer(RENDERBUFFER, rb[0]);
    gl.RenderbufferStorageMultisample(RENDERBUFFER, samples, colour, w, h);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb[0]);
    gl.BindRenderbuffer(RENDERBUFFER, rb[1]);
    gl.RenderbufferStorageMultisample(RENDERBUFFER, samples, DEPTH24_STENCIL8, w, h);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, rb[1]);
    single = gl.GenFramebuffer();
    gl.BindFramebuffer(FRAMEBUFFER, single);
    gl.BindRenderbuffer(RENDERBUFFER, rb[2]);
    gl.RenderbufferStorage(RENDERBUFFER, resolved, w, h);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb[2]);
    gl.BindFramebuffer(FRAMEBUFFER, ms);
    gl.Viewport(0, 0, w, h);
  }
  // Clears the multisampled buffers: colour opaque black, depth 1, stencil 0.
  void Clear(Bitfield mask) {
    gl.BindFramebuffer(FRAMEBUFFER, ms);
    gl.ClearColor(0, 0, 0, 1);
    gl.ClearDepth(1.0);
    gl.ClearStencil(0);
    gl.Clear(mask);
  }
  void Resolve() {
    gl.BindFramebuffer(READ_FRAMEBUFFER, ms);
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, single);
    gl.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, COLOR_BUFFER_BIT, NEAREST);
    gl.BindFramebuffer(FRAMEBUFFER, single);
  }
  int Red(int x, int y) { return ::Red(gl, x, y); }
};

// A 16 x 16 context drawing into a 4-sample framebuffer object with a solid shader.
struct Fixture {
  Context gl{16, 16};
  MultisampleFbo fbo{gl, 4, 16, 16};
  SolidShader shader;
};

void DrawWindowTriangle(Context& gl, SolidShader& shader, glm::vec2 a, glm::vec2 b, glm::vec2 c, int w, int h,
                        float za = 0.0f, float zb = 0.0f, float zc = 0.0f) {
  MakeVertexArray(gl, {WindowToClip(a.x, a.y, w, h, za), WindowToClip(b.x, b.y, w, h, zb), WindowToClip(c.x, c.y, w, h, zc)});
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
}

}  // namespace

TEST_CASE("multisample rasterizer: each sample's coverage is the exact edge test at its position", "[multisample]") {
  std::mt19937 rng(1234);
  for (int samples : {2, 4, 8}) {
    const auto* pos = detail::SamplePositions(samples);
    for (int trial = 0; trial < 300; ++trial) {
      constexpr int W = 40, H = 40;
      // Vertices on the 1/16 grid half the time, so that edges pass exactly through sample positions.
      std::uniform_int_distribution<int> coord(-16 * 256, (W + 4) * 256);
      std::int64_t X[3], Y[3];
      detail::WindowVertex v[3];
      for (int k = 0; k < 3; ++k) {
        X[k] = coord(rng);
        Y[k] = coord(rng);
        if (trial % 2) {
          X[k] &= ~15;
          Y[k] &= ~15;
        }
        if (trial % 5 == 0 && k > 0) {  // small triangles too
          X[k] = X[0] + (coord(rng) % 700);
          Y[k] = Y[0] + (coord(rng) % 700);
        }
        v[k].win = glm::vec4(float(X[k]) / 256.0f, float(Y[k]) / 256.0f, 0.5f, 1.0f);
      }
      SampleRecorder rec(W, H, samples);
      detail::RasterTarget target;
      target.bounds = detail::Rect{0, 0, W, H};
      target.samples = samples;
      auto blocks = std::make_unique<detail::BlockBuffer>();
      blocks->samples = samples;
      const detail::BlockSink sink{&SampleRecorder::Flush, &rec};
      detail::RasterizeTriangle(v[0], v[1], v[2], true, target, *blocks, sink);
      sink.Flush(*blocks);
      const detail::Rect box = detail::TriangleCentreBox(v[0].win, v[1].win, v[2].win, target.bounds, samples);
      int wrong = 0, twice = 0, outside_box = 0;
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          std::uint32_t expect = 0;
          for (int s = 0; s < samples; ++s)
            if (Inside(std::int64_t(x) * 256 + pos[s][0] * 16, std::int64_t(y) * 256 + pos[s][1] * 16, X, Y))
              expect |= 1u << s;
          const std::size_t i = std::size_t(y * W + x);
          if (rec.mask[i] != expect) ++wrong;
          if (rec.emitted[i] > 1) ++twice;
          if (expect && (x < box.x0 || x >= box.x1 || y < box.y0 || y >= box.y1)) ++outside_box;
        }
      INFO("samples " << samples << ", trial " << trial);
      REQUIRE(wrong == 0);
      REQUIRE(twice == 0);
      REQUIRE(outside_box == 0);
    }
  }
}

TEST_CASE_METHOD(Fixture, "multisample: an edge through a pixel resolves to the share of its samples covered",
                 "[multisample]") {
  fbo.Clear(COLOR_BUFFER_BIT);
  // Covers x < 8.5: column 8 has the samples at x offsets 0.375 and 0.125 inside (two of four).
  DrawWindowTriangle(gl, shader, {-10, -10}, {8.5f, -10}, {8.5f, 40}, 16, 16);
  fbo.Resolve();
  CHECK(fbo.Red(7, 8) == 255);
  CHECK(std::abs(fbo.Red(8, 8) - 128) <= 1);
  CHECK(fbo.Red(9, 8) == 0);
  CHECK(gl.GetError() == NO_ERROR);

  SECTION("with MULTISAMPLE disabled a pixel is covered at its centre, in all samples") {
    gl.BindFramebuffer(FRAMEBUFFER, fbo.ms);
    gl.Disable(MULTISAMPLE);
    gl.Clear(COLOR_BUFFER_BIT);
    DrawWindowTriangle(gl, shader, {-10, -10}, {8.6f, -10}, {8.6f, 40}, 16, 16);  // the centre 8.5 inside
    fbo.Resolve();
    CHECK(fbo.Red(8, 8) == 255);
    CHECK(fbo.Red(9, 8) == 0);
  }
}

TEST_CASE("multisample: the fragment shader runs once per pixel", "[multisample]") {
  Context gl(16, 16, Samples(4));
  CaptureShader shader;
  MakeVertexArray(gl, {WindowToClip(0.3f, 0.2f, 16, 16), WindowToClip(15.6f, 3.1f, 16, 16), WindowToClip(4.2f, 15.3f, 16, 16)},
                  {glm::vec4(0), glm::vec4(0), glm::vec4(0)});
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.Finish();
  REQUIRE(!shader.samples.empty());
  for (const auto& [pixel, sample] : shader.samples) {
    CHECK(sample.hits == 1);
    CHECK(sample.frag_coord.x == float(pixel.first) + 0.5f);  // gl_FragCoord at the pixel centre
  }
}

TEST_CASE_METHOD(Fixture, "multisample: depth is tested per sample at each sample's depth", "[multisample]") {
  fbo.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.Enable(DEPTH_TEST);
  // A wall at depth 0 (window 0.5) everywhere, then a plane rising in x through it at x = 8.5: its left half in
  // front. Column 8's samples left of 8.5 pass, those right of it fail.
  DrawWindowTriangle(gl, shader, {-40, -40}, {60, -40}, {-40, 60}, 16, 16);
  DrawWindowTriangle(gl, shader, {-40, 60}, {60, -40}, {60, 60}, 16, 16);
  shader.color = glm::vec4(0, 0, 0, 1);
  const float slope = 0.05f;  // clip z per pixel
  auto z = [&](float x) { return (x - 8.5f) * slope; };
  MakeVertexArray(gl, {WindowToClip(-8, -8, 16, 16, z(-8)), WindowToClip(24, -8, 16, 16, z(24)),
                       WindowToClip(-8, 24, 16, 16, z(-8)), WindowToClip(24, 24, 16, 16, z(24))});
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  fbo.Resolve();
  CHECK(fbo.Red(7, 5) == 0);
  CHECK(std::abs(fbo.Red(8, 5) - 128) <= 1);
  CHECK(fbo.Red(9, 5) == 255);
}

TEST_CASE("multisample: SAMPLE_COVERAGE, SAMPLE_MASK and SAMPLE_ALPHA_TO_COVERAGE keep samples; SAMPLE_ALPHA_TO_ONE",
          "[multisample]") {
  Context gl(8, 8);
  MultisampleFbo fbo(gl, 4, 8, 8);
  SolidShader shader;
  auto fill = [&]() {
    gl.BindFramebuffer(FRAMEBUFFER, fbo.ms);
    gl.ClearColor(0, 0, 0, 0);
    gl.Clear(COLOR_BUFFER_BIT);
    DrawWindowTriangle(gl, shader, {-20, -20}, {40, -20}, {-20, 40}, 8, 8);
    fbo.Resolve();
    return fbo.Red(2, 2);
  };
  CHECK(fill() == 255);
  gl.Enable(SAMPLE_COVERAGE);
  gl.SampleCoverage(0.5f, false);  // two of four
  CHECK(std::abs(fill() - 128) <= 1);
  gl.SampleCoverage(0.3f, true);  // floor(1.2) = 1 sample, inverted: three of four
  CHECK(std::abs(fill() - 191) <= 1);
  gl.Disable(SAMPLE_COVERAGE);
  gl.Enable(SAMPLE_MASK);
  gl.SampleMaski(0, 0x1);
  CHECK(std::abs(fill() - 64) <= 1);
  gl.SampleMaski(0, 0x0);
  CHECK(fill() == 0);
  gl.Disable(SAMPLE_MASK);
  gl.Enable(SAMPLE_ALPHA_TO_COVERAGE);
  shader.color = glm::vec4(1, 1, 1, 0.74f);  // samples 0 to 2: alpha > s / 4
  CHECK(std::abs(fill() - 191) <= 1);
  shader.color = glm::vec4(1, 1, 1, 0.1f);  // sample 0 only: alpha > 0 / 4
  CHECK(std::abs(fill() - 64) <= 1);
  shader.color = glm::vec4(1, 1, 1, 0.0f);
  CHECK(fill() == 0);
  shader.color = glm::vec4(1, 1, 1, 0.76f);  // all: alpha > 3 / 4
  CHECK(fill() == 255);
  // SAMPLE_ALPHA_TO_ONE: the coverage still comes from the shader's alpha (three samples of 0.74), then the samples
  // store alpha 1: resolved, 3 x 255 over 4 (not 3 x 189 over 4 = 142).
  auto alpha = [&] {
    std::uint8_t px[4];
    gl.ReadPixel(2, 2, px);
    return int(px[3]);
  };
  shader.color = glm::vec4(1, 1, 1, 0.74f);
  CHECK(std::abs(fill() - 191) <= 1);
  CHECK(std::abs(alpha() - 142) <= 1);
  gl.Enable(SAMPLE_ALPHA_TO_ONE);
  CHECK(std::abs(fill() - 191) <= 1);
  CHECK(std::abs(alpha() - 191) <= 1);
  gl.Disable(SAMPLE_ALPHA_TO_COVERAGE);
  CHECK(fill() == 255);
  CHECK(alpha() == 255);
  gl.Disable(SAMPLE_ALPHA_TO_ONE);
  gl.Enable(SAMPLE_ALPHA_TO_COVERAGE);
  gl.Disable(MULTISAMPLE);  // the coverage operations act only while MULTISAMPLE is enabled
  shader.color = glm::vec4(1, 1, 1, 0.1f);
  CHECK(fill() == 255);
  gl.Enable(MULTISAMPLE);
  CHECK(gl.GetError() == NO_ERROR);
  // Into a single-sampled framebuffer the coverage operations do nothing.
  gl.BindFramebuffer(FRAMEBUFFER, fbo.single);
  gl.Clear(COLOR_BUFFER_BIT);
  DrawWindowTriangle(gl, shader, {-20, -20}, {40, -20}, {-20, 40}, 8, 8);
  CHECK(fbo.Red(2, 2) == 255);
}

TEST_CASE_METHOD(Fixture, "multisample: stencil is kept per sample", "[multisample]") {
  fbo.Clear(COLOR_BUFFER_BIT | STENCIL_BUFFER_BIT);
  gl.Enable(STENCIL_TEST);
  gl.StencilFunc(ALWAYS, 1, 0xFF);
  gl.StencilOp(KEEP, KEEP, REPLACE);
  gl.ColorMask(false, false, false, false);
  DrawWindowTriangle(gl, shader, {-10, -10}, {8.5f, -10}, {8.5f, 40}, 16, 16);  // marks x < 8.5
  gl.ColorMask(true, true, true, true);
  gl.StencilFunc(EQUAL, 1, 0xFF);
  DrawWindowTriangle(gl, shader, {-40, -40}, {60, -40}, {-40, 60}, 16, 16);
  DrawWindowTriangle(gl, shader, {-40, 60}, {60, -40}, {60, 60}, 16, 16);
  fbo.Resolve();
  CHECK(fbo.Red(7, 3) == 255);
  CHECK(std::abs(fbo.Red(8, 3) - 128) <= 1);
  CHECK(fbo.Red(9, 3) == 0);
}

TEST_CASE("multisample: the lane-by-lane operations (a float target, an odd size) match the vector path's",
          "[multisample]") {
  // Overlapping random triangles of random depths and colours, depth-tested, each pass counting into the stencil
  // per sample; then a cover pass of stencil EQUAL 2. An RGBA8 target of even size takes every block through the
  // vector operations; RGBA16F takes them lane by lane, and an odd-sized RGBA8 target its edge blocks. The
  // colours are multiples of 1/255 (exact in both formats), so the resolves (averages rounded to bytes) agree
  // within 1.
  auto render = [](Enum format, int w, int h) {
    Context gl(w, h);
    MultisampleFbo fbo(gl, 4, w, h, format);
    fbo.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    SolidShader shader;
    gl.Enable(DEPTH_TEST);
    gl.Enable(STENCIL_TEST);
    gl.StencilFunc(ALWAYS, 0, 0xFF);
    gl.StencilOp(KEEP, KEEP, INCR);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> pos(-4.0f, 40.0f), depth(-0.5f, 0.9f);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int t = 0; t < 40; ++t) {
      shader.color = glm::vec4(float(byte(rng)), float(byte(rng)), float(byte(rng)), 255.0f) / 255.0f;
      DrawWindowTriangle(gl, shader, {pos(rng), pos(rng)}, {pos(rng), pos(rng)}, {pos(rng), pos(rng)}, w, h, depth(rng),
                         depth(rng), depth(rng));
    }
    gl.Disable(DEPTH_TEST);
    gl.StencilFunc(EQUAL, 2, 0xFF);
    gl.StencilOp(KEEP, KEEP, KEEP);
    shader.color = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    DrawWindowTriangle(gl, shader, {-40, -40}, {90, -40}, {-40, 90}, w, h);
    DrawWindowTriangle(gl, shader, {-40, 90}, {90, -40}, {90, 90}, w, h);
    fbo.Resolve();
    std::vector<std::uint8_t> px(std::size_t(w * h) * 4);
    gl.ReadPixels(0, 0, w, h, RGBA, UNSIGNED_BYTE, px.data());
    return px;
  };
  const std::vector<std::uint8_t> vector_path = render(RGBA8, 32, 32), lanes = render(RGBA16F, 32, 32);
  const std::vector<std::uint8_t> odd = render(RGBA8, 31, 31);
  int differ = 0, blue = 0, edged = 0;
  for (int y = 0; y < 31; ++y)
    for (int x = 0; x < 31; ++x) {
      const std::size_t i = std::size_t(y * 32 + x) * 4, j = std::size_t(y * 31 + x) * 4;
      for (int c = 0; c < 4; ++c) {
        differ += std::abs(int(vector_path[i + c]) - int(lanes[i + c])) > 1;
        differ += std::abs(int(vector_path[i + c]) - int(odd[j + c])) > 1;
      }
      blue += vector_path[i + 2] == 255 && vector_path[i] == 0;
      edged += vector_path[i + 2] != 255 && vector_path[i + 2] > 0 && vector_path[i] > 0;
    }
  INFO(blue << " pixels blue, " << edged << " mixed");
  CHECK(differ == 0);
  CHECK(blue > 20);    // the stencil pass drew where exactly two triangles passed
  CHECK(edged > 20);   // and the resolve mixed samples
}

TEST_CASE("multisample: a line covers the samples of a rectangle along it, a point those of its square",
          "[multisample]") {
  // Sample positions at 4 samples (x, y in 1/16 pixel): (6, 2), (14, 6), (2, 10), (10, 14).
  Context gl(16, 16, Samples(4));
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  SolidShader shader;
  MakeVertexArray(gl, {WindowToClip(0.5f, 4.5f, 16, 16), WindowToClip(15.5f, 4.5f, 16, 16),
                       WindowToClip(2.0f, 10.2f, 16, 16), WindowToClip(9.0f, 10.2f, 16, 16),
                       WindowToClip(3.5f, 13.5f, 16, 16), WindowToClip(12.3f, 12.3f, 16, 16)});
  gl.UseProgram(shader);
  gl.DrawArrays(LINES, 0, 4);
  gl.DrawArrays(POINTS, 4, 1);
  gl.PointSize(1.5f);
  gl.DrawArrays(POINTS, 5, 1);
  // The line through pixel centres at y = 4.5: the rectangle [0.5, 15.5) x [4, 5) holds every sample of row 4 from
  // pixel 1 to 14, the samples right of 0.5 in pixel 0 (1 and 3) and left of 15.5 in pixel 15 (0 and 2).
  CHECK(Red(gl, 6, 4) == 255);
  CHECK(Red(gl, 0, 4) == 128);
  CHECK(Red(gl, 15, 4) == 128);
  CHECK(Red(gl, 6, 3) == 0);
  CHECK(Red(gl, 6, 5) == 0);
  // The line at y = 10.2: the rectangle's rows [9.7, 10.7) hold sample 3 of row 9 and samples 0 to 2 of row 10
  // (one pixel wide lines without multisampling light row 10 alone).
  CHECK(Red(gl, 5, 9) == 64);
  CHECK(Red(gl, 5, 10) == 191);
  CHECK(Red(gl, 5, 11) == 0);
  // The point of size 1 at a pixel centre covers that pixel; the one of size 1.5 at (12.3, 12.3) the square
  // [11.55, 13.05) x [11.55, 13.05): sample 3 of pixel (11, 11), samples 2 and 3 of (12, 11), 1 and 3 of (11, 12),
  // all of (12, 12).
  CHECK(Red(gl, 3, 13) == 255);
  CHECK(Red(gl, 11, 11) == 64);
  CHECK(Red(gl, 12, 11) == 128);
  CHECK(Red(gl, 11, 12) == 128);
  CHECK(Red(gl, 12, 12) == 255);
  CHECK(Red(gl, 13, 12) == 0);
}

TEST_CASE("multisample: with MULTISAMPLE disabled lines and points light every sample of their pixels",
          "[multisample]") {
  Context gl(16, 16, Samples(4));
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Disable(MULTISAMPLE);
  SolidShader shader;
  MakeVertexArray(gl, {WindowToClip(2.0f, 10.2f, 16, 16), WindowToClip(9.0f, 10.2f, 16, 16),
                       WindowToClip(12.3f, 12.3f, 16, 16)});
  gl.UseProgram(shader);
  gl.DrawArrays(LINES, 0, 2);
  gl.PointSize(1.5f);
  gl.DrawArrays(POINTS, 2, 1);
  CHECK(Red(gl, 5, 9) == 0);  // the diamond-exit rule: row 10 alone, all its samples
  CHECK(Red(gl, 5, 10) == 255);
  CHECK(Red(gl, 11, 11) == 0);  // the pixels whose centres lie in the square: (12, 12) alone
  CHECK(Red(gl, 12, 12) == 255);
}

TEST_CASE("multisample: the context's framebuffer reads resolved", "[multisample]") {
  Context gl(16, 16, Samples(4));
  CHECK(gl.GetError() == NO_ERROR);
  int v = -1;
  gl.GetIntegerv(SAMPLES, &v);
  CHECK(v == 4);
  gl.GetIntegerv(SAMPLE_BUFFERS, &v);
  CHECK(v == 1);
  gl.ClearColor(0, 0, 1, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  SolidShader shader;
  DrawWindowTriangle(gl, shader, {-10, -10}, {8.5f, -10}, {8.5f, 40}, 16, 16);
  std::uint8_t px[4];
  gl.ReadPixels(8, 8, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(std::abs(int(px[0]) - 128) <= 1);
  CHECK(std::abs(int(px[2]) - 255) <= 1);
  const Image image = gl.ReadPixels();
  CHECK(std::abs(int(image.rgba[(std::size_t(15 - 8) * 16 + 8) * 4]) - 128) <= 1);
  // A draw after a read is resolved again at the next read.
  gl.Enable(DEPTH_TEST);
  DrawWindowTriangle(gl, shader, {-10, -10}, {40, -10}, {-10, 40}, 16, 16);
  gl.ReadPixels(8, 8, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(px[0] == 255);
  CHECK(gl.ReadDepth(8, 8) == 0.5f);

  SECTION("sample counts round up; outside 0 to 8 is refused") {
    Context three(4, 4, Samples(3));
    three.GetIntegerv(SAMPLES, &v);
    CHECK(v == 4);
    Context nine(4, 4, Samples(9));
    CHECK(nine.GetError() == INVALID_VALUE);
    nine.GetIntegerv(SAMPLES, &v);
    CHECK(v == 0);
  }
}

TEST_CASE("multisample: renderbuffers, completeness, blits and reads follow OpenGL", "[multisample]") {
  Context gl(8, 8);
  int v = 0;
  gl.GetIntegerv(MAX_SAMPLES, &v);
  CHECK(v == 8);
  const std::uint32_t rb = gl.GenRenderbuffer(), rb2 = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 3, RGBA8, 8, 8);
  gl.GetRenderbufferParameteriv(RENDERBUFFER, RENDERBUFFER_SAMPLES, &v);
  CHECK(v == 4);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 9, RGBA8, 8, 8);  // OpenGL 3.3, section 4.4.2.1
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, -1, RGBA8, 8, 8);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 8, 8);
  gl.GetRenderbufferParameteriv(RENDERBUFFER, RENDERBUFFER_SAMPLES, &v);
  CHECK(v == 0);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, RGBA8, 8, 8);
  gl.BindRenderbuffer(RENDERBUFFER, rb2);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 2, DEPTH_COMPONENT24, 8, 8);
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, rb2);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_MULTISAMPLE);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, DEPTH_COMPONENT24, 8, 8);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.GetIntegerv(SAMPLES, &v);
  CHECK(v == 4);
  float p[2];
  gl.GetMultisamplefv(SAMPLE_POSITION, 1, p);
  CHECK(p[0] == 0.875f);
  CHECK(p[1] == 0.375f);
  gl.GetMultisamplefv(SAMPLE_POSITION, 4, p);
  CHECK(gl.GetError() == INVALID_VALUE);
  std::uint8_t px[4];
  gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 4, 4, COLOR_BUFFER_BIT, NEAREST);  // scaling
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, COLOR_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == NO_ERROR);
  gl.SampleMaski(1, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(gl.IsEnabled(MULTISAMPLE));
}

namespace {

// Triangles at window positions p (of a 16 x 16 window) drawn with `shader`, each vertex's window position its
// attribute 1.
template <class S>
void DrawWithWindowPositions(Context& gl, S& shader, std::initializer_list<glm::vec2> p) {
  std::vector<glm::vec4> pos, value;
  for (const glm::vec2& v : p) {
    pos.push_back(WindowToClip(v.x, v.y, 16, 16));
    value.push_back(glm::vec4(v, 0, 1));
  }
  MakeVertexArray(gl, pos, value);
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, int(p.size()));
}

struct CentroidVaryings {
  softgl::Centroid<glm::vec4> at_sample;
  glm::vec4 at_centre;
};

// Attribute 1 (the window position) into both varyings; records each pixel's values.
struct CentroidShader : softgl::Shader<CentroidShader, CentroidVaryings> {
  std::shared_ptr<std::map<std::pair<int, int>, std::pair<glm::vec4, glm::vec4>>> seen =
      std::make_shared<std::map<std::pair<int, int>, std::pair<glm::vec4, glm::vec4>>>();
  std::shared_ptr<std::mutex> mutex = std::make_shared<std::mutex>();
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<CentroidVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.at_sample = in.attrib[1];
    out.varyings.at_centre = in.attrib[1];
  }
  bool Fragment(const softgl::FragmentIn<CentroidVaryings>& in, softgl::FragmentOut& out) const {
    std::lock_guard<std::mutex> lock(*mutex);
    (*seen)[{int(in.frag_coord.x), int(in.frag_coord.y)}] = {in.varyings.at_sample, in.varyings.at_centre};
    out.color[0] = glm::vec4(1.0f);
    return true;
  }
};

}  // namespace

TEST_CASE("multisample: Centroid<> varyings are taken at the first covered sample of a partly covered pixel",
          "[multisample]") {
  REQUIRE(CentroidShader().VaryingInterpolation()[0] == Interpolation::kCentroid);
  REQUIRE(CentroidShader().VaryingInterpolation()[4] == Interpolation::kSmooth);
  for (int samples : {0, 4, 8}) {
    Context gl(16, 16, Samples(samples));
    CentroidShader shader;
    // A triangle whose right edge is x = 8.3 (w = 1: the window position interpolates linearly).
    DrawWithWindowPositions(gl, shader, {{-10, -10}, {8.3f, -10}, {8.3f, 40}});
    gl.Finish();
    const auto* positions = detail::SamplePositions(samples);
    for (const auto& [pixel, values] : *shader.seen) {
      const auto& [at_sample, at_centre] = values;
      INFO(samples << " samples, pixel " << pixel.first << ", " << pixel.second);
      CHECK(std::abs(at_centre.x - (float(pixel.first) + 0.5f)) < 1e-3f);
      CHECK(std::abs(at_centre.y - (float(pixel.second) + 0.5f)) < 1e-3f);
      if (samples == 0 || pixel.first != 8) {  // covered whole (or single-sampled): the centre
        CHECK(at_sample == at_centre);
        continue;
      }
      // Column 8: the samples left of x = 8.3 are covered; the first of them in sample order.
      int first = -1;
      for (int s = 0; s < samples && first < 0; ++s)
        if (float(positions[s][0]) / 16.0f < 0.3f) first = s;
      REQUIRE(first >= 0);
      CHECK(std::abs(at_sample.x - (8.0f + float(positions[first][0]) / 16.0f)) < 1e-3f);
      CHECK(std::abs(at_sample.y - (float(pixel.second) + float(positions[first][1]) / 16.0f)) < 1e-3f);
    }
  }
}

namespace {
// Into the bound 8 x 8 framebuffer (4 samples): blue, then red left of x = 3.5: in pixel column 3 the samples left
// of its centre, 0 (at x 0.375) and 2 (0.125), are covered; 1 (0.875) and 3 (0.625) are not.
void BlueThenRedLeftOfColumn3(Context& gl) {
  gl.ClearColor(0, 0, 1, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  SolidShader red;
  red.color = glm::vec4(1, 0, 0, 1);
  gl.UseProgram(red);
  const float x = 3.5f / 4.0f - 1.0f;
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {x, -1, 0, 1}, {-1, 1, 0, 1}, {x, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
}

// A full-screen pass writing texelFetch(sampler2DMS on unit 0, gl_FragCoord.xy, sample), written wide.
struct NoVary {};
struct FetchSampleShader : Shader<FetchSampleShader, NoVary> {
  int sample = 0;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVary>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVary>& in, FragmentLanesOut& out) const {
    out.color[0] = in.TexelFetchMS(0, Int(in.frag_coord.x), Int(in.frag_coord.y), Int(sample));
  }
};
}  // namespace

TEST_CASE("TEXTURE_2D_MULTISAMPLE: drawn into, fetched sample by sample, resolved by a blit", "[multisample]") {
  Context gl(8, 8, Samples(1));
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D_MULTISAMPLE, tex);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 3, RGBA8, 8, 8, true);  // 3 rounds up to 4
  REQUIRE(gl.GetError() == NO_ERROR);
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D_MULTISAMPLE, 0, TEXTURE_SAMPLES, &v);
  CHECK(v == 4);
  gl.GetIntegerv(TEXTURE_BINDING_2D_MULTISAMPLE, &v);
  CHECK(v == int(tex));
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, tex, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  BlueThenRedLeftOfColumn3(gl);

  // Each sample through a wide fragment shader into the context's framebuffer.
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  FetchSampleShader fetch;
  gl.UseProgram(fetch);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  const int want_red[4] = {255, 0, 255, 0};
  for (int s = 0; s < 4; ++s) {
    fetch.sample = s;
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    CHECK(Red(gl, 3, 4) == want_red[s]);
    CHECK(Red(gl, 2, 4) == 255);
    CHECK(Red(gl, 4, 4) == 0);
  }
  fetch.sample = 4;  // a sample the texture does not have: zero
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  std::uint8_t px[4];
  gl.ReadPixel(3, 4, px);
  CHECK((px[0] == 0 && px[2] == 0 && px[3] == 0));

  // Resolved by a blit: column 3 is half red, half blue, rounded half up.
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, COLOR_BUFFER_BIT, NEAREST);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.ReadPixel(3, 4, px);
  CHECK((px[0] == 128 && px[2] == 128));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("TEXTURE_2D_MULTISAMPLE and texelFetch reject bad input with OpenGL's errors", "[multisample][errors]") {
  Context gl(8, 8);
  const std::uint32_t tex = gl.GenTexture(), flat = gl.GenTexture(), fbo = gl.GenFramebuffer(),
                      rb = gl.GenRenderbuffer();
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 4, RGBA8, 8, 8, true);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_2D_MULTISAMPLE, tex);
  gl.TexImage2DMultisample(TEXTURE_2D, 4, RGBA8, 8, 8, true);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 4, 0x1234, 8, 8, true);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 0, RGBA8, 8, 8, true);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 4, RGBA8, kMaxTextureSize + 1, 8, true);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 9, RGBA8, 8, 8, true);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 2, RGBA8, 8, 8, false);
  CHECK(gl.GetError() == NO_ERROR);
  CheckRefusesLevelsAndSampling(gl, TEXTURE_2D_MULTISAMPLE);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, tex, 1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindTexture(TEXTURE_2D, flat);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, flat, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  // A 2-sample texture beside a 4-sample renderbuffer: FRAMEBUFFER_INCOMPLETE_MULTISAMPLE.
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D_MULTISAMPLE, tex, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, DEPTH24_STENCIL8, 8, 8);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, rb);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_MULTISAMPLE);
  int v = 0;
  gl.GetIntegerv(MAX_COLOR_TEXTURE_SAMPLES, &v);
  CHECK(v == 8);
  CHECK(gl.GetError() == NO_ERROR);

  // texelFetch of a 2D texture: level 1 of a 4 x 4 texture whose level 1 is defined; zero outside.
  gl.BindTexture(TEXTURE_2D, flat);
  const std::uint8_t l0[16 * 4] = {}, l1[4 * 4] = {10, 0, 0, 255, 20, 0, 0, 255, 30, 0, 0, 255, 40, 0, 0, 255};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, l0);
  gl.TexImage2D(TEXTURE_2D, 1, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, l1);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MAX_LEVEL, 1);
  struct Probe : Shader<Probe, NoVaryings> {
    mutable glm::vec4 got[3];
    void Vertex(const VertexIn& in, VertexOut<NoVaryings>& out) const {
      out.position = glm::vec4(2, 2, 2, 1);
      got[0] = in.textures->Fetch(0, {1, 1}, 1);
      got[1] = in.textures->Fetch(0, {2, 0}, 1);
      got[2] = in.textures->Fetch(0, {0, 0}, 2);
    }
    bool Fragment(const FragmentIn<NoVaryings>&, FragmentOut&) const { return false; }
  } probe;
  gl.UseProgram(probe);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  MakeVertexArray(gl, {{0, 0, 0, 1}});
  gl.DrawArrays(POINTS, 0, 1);
  gl.Finish();
  CHECK(probe.got[0].r == Approx(40.0f / 255.0f));
  CHECK(probe.got[1] == glm::vec4(0.0f));
  CHECK(probe.got[2] == glm::vec4(0.0f));
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {
// A full-screen pass writing texelFetch(sampler2DMSArray on unit 0, ivec3(gl_FragCoord.xy, layer), sample).
struct FetchArrayShader : Shader<FetchArrayShader, NoVary> {
  int layer = 0, sample = 0;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVary>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVary>& in, FragmentLanesOut& out) const {
    out.color[0] = in.TexelFetchMSArray(0, Int(in.frag_coord.x), Int(in.frag_coord.y), Int(layer), Int(sample));
  }
};
// Position from attribute 0, gl_Layer from attribute 1's x, colour (1, 1 - layer / 4, 0, 1).
struct LayerVary {
  vec4 color;
};
struct ToLayerShader : Shader<ToLayerShader, LayerVary> {
  static constexpr bool kWritesLayer = true;
  void Vertex(const VertexLanes& in, VertexLanesOut<LayerVary>& out) const {
    out.position = in.attrib[0];
    out.layer = Int(in.attrib[1].x);
    out.varyings.color = vec4(1.0f, 1.0f - in.attrib[1].x * 0.25f, 0.0f, 1.0f);
  }
  void Fragment(const FragmentLanes<LayerVary>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};
}  // namespace

TEST_CASE("TEXTURE_2D_MULTISAMPLE_ARRAY: layers drawn into one by one and layered, fetched by sample, resolved",
          "[multisample]") {
  Context gl(8, 8, Samples(1));
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
  gl.TexImage3DMultisample(TEXTURE_2D_MULTISAMPLE_ARRAY, 3, RGBA8, 8, 8, 3, true);  // 3 samples round up to 4
  REQUIRE(gl.GetError() == NO_ERROR);
  int v = 0;
  const std::pair<Enum, int> levels[] = {{TEXTURE_WIDTH, 8}, {TEXTURE_HEIGHT, 8}, {TEXTURE_DEPTH, 3},
                                         {TEXTURE_SAMPLES, 4}, {TEXTURE_INTERNAL_FORMAT, int(RGBA8)}};
  for (const auto& [pname, want] : levels) {
    gl.GetTexLevelParameteriv(TEXTURE_2D_MULTISAMPLE_ARRAY, 0, pname, &v);
    CHECK(v == want);
  }
  gl.GetIntegerv(TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY, &v);
  CHECK(v == int(tex));
  // Layer 1: blue, then red left of x = 3.5 (in column 3, samples 0 and 2); layer 2: green.
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, tex, 0, 1);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.GetIntegerv(SAMPLES, &v);
  CHECK(v == 4);
  BlueThenRedLeftOfColumn3(gl);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, tex, 0, 2);
  gl.ClearColor(0, 1, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);

  // Each layer's samples through a wide fragment shader into the context's framebuffer.
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  FetchArrayShader fetch;
  gl.UseProgram(fetch);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  const auto pixel = [&](int layer, int sample, int px) {
    fetch.layer = layer;
    fetch.sample = sample;
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    std::uint8_t p[4];
    gl.ReadPixel(px, 4, p);
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
  };
  for (int s = 0; s < 4; ++s) {
    CAPTURE(s);
    CHECK(pixel(0, s, 3) == 0u);  // never drawn: zero
    CHECK(pixel(1, s, 3) == (s % 2 == 0 ? 0xFF0000FFu : 0x0000FFFFu));
    CHECK(pixel(1, s, 2) == 0xFF0000FFu);
    CHECK(pixel(2, s, 3) == 0x00FF00FFu);
  }
  CHECK(pixel(3, 0, 3) == 0u);   // a layer it does not have
  CHECK(pixel(-1, 0, 3) == 0u);
  CHECK(pixel(1, 4, 3) == 0u);   // a sample it does not have

  // Layer 1 resolved by a blit: column 3 half red, half blue.
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  gl.FramebufferTextureLayer(READ_FRAMEBUFFER, COLOR_ATTACHMENT0, tex, 0, 1);
  gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, COLOR_BUFFER_BIT, NEAREST);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  std::uint8_t px[4];
  gl.ReadPixel(3, 4, px);
  CHECK((px[0] == 128 && px[2] == 128));

  // Every layer attached (a layered framebuffer): gl_Layer picks the layer; a clear clears them all.
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, tex, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  ToLayerShader to_layer;
  gl.UseProgram(to_layer);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}, {-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}},
                  {glm::vec4(2), glm::vec4(2), glm::vec4(2), glm::vec4(0), glm::vec4(0), glm::vec4(0)});
  gl.DrawArrays(TRIANGLES, 0, 6);  // a triangle into layer 2, one into layer 0; layer 1 stays cleared
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.UseProgram(fetch);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  for (int s = 0; s < 4; ++s) {
    CAPTURE(s);
    CHECK(pixel(0, s, 3) == 0xFFFF00FFu);
    CHECK(pixel(1, s, 3) == 0x000000FFu);
    CHECK(pixel(2, s, 3) == 0xFF8000FFu);
  }
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("TEXTURE_2D_MULTISAMPLE_ARRAY rejects bad input with OpenGL's errors", "[multisample][errors]") {
  Context gl(8, 8);
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.TexImage3DMultisample(TEXTURE_2D_MULTISAMPLE_ARRAY, 4, RGBA8, 8, 8, 2, true);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
  const struct Bad { Enum target; int samples; Enum format; int w, h, d; Enum error; } bad[] = {
      {TEXTURE_2D_MULTISAMPLE, 4, RGBA8, 8, 8, 2, INVALID_ENUM},
      {TEXTURE_2D_ARRAY, 4, RGBA8, 8, 8, 2, INVALID_ENUM},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 4, COMPRESSED_RGBA_S3TC_DXT1_EXT, 8, 8, 2, INVALID_ENUM},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 0, RGBA8, 8, 8, 2, INVALID_VALUE},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 4, RGBA8, 8, 8, -1, INVALID_VALUE},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 4, RGBA8, 8, 8, kMaxArrayTextureLayers + 1, INVALID_VALUE},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 4, RGBA8, kMaxTextureSize + 1, 8, 2, INVALID_VALUE},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 64, RGBA8, 8, 8, 2, INVALID_OPERATION},
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 2, DEPTH24_STENCIL8, 8, 8, 0, NO_ERROR},  // no layers: an empty image
      {TEXTURE_2D_MULTISAMPLE_ARRAY, 2, DEPTH24_STENCIL8, 8, 8, 2, NO_ERROR},
  };
  for (const Bad& b : bad) {
    CAPTURE(b.target, b.samples, b.format, b.d);
    gl.TexImage3DMultisample(b.target, b.samples, b.format, b.w, b.h, b.d, false);
    CHECK(gl.GetError() == b.error);
  }
  int v = -7;
  gl.GetTexLevelParameteriv(TEXTURE_2D_MULTISAMPLE_ARRAY, 1, TEXTURE_WIDTH, &v);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(v == -7);
  CheckRefusesLevelsAndSampling(gl, TEXTURE_2D_MULTISAMPLE_ARRAY, true);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  const Enum none = NONE;  // (depth and stencil alone)
  gl.DrawBuffers(1, &none);
  gl.ReadBuffer(NONE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, tex, 1, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, tex, 1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, tex, 0, 1);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, tex, 0, 2);  // past its layers
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {

struct StepVaryings {
  glm::vec4 window;
};
// Attribute 1 (the window position) as a varying; red where its x passes `edge`: a step inside the pixel that
// only shading at the samples resolves to a fraction.
struct StepShader : softgl::Shader<StepShader, StepVaryings> {
  float edge = 8.45f;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<StepVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.window = in.attrib[1];
  }
  bool Fragment(const softgl::FragmentIn<StepVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = glm::vec4(in.varyings.window.x > edge ? 1.0f : 0.0f, 0.0f, 0.0f, 1.0f);
    return true;
  }
};

// A quad over the whole 16 x 16 window with the step shader; returns the red of pixels 7 to 9 of row 4.
float ShadingValue(Context& gl) {
  float v = -1.0f;
  gl.GetFloatv(MIN_SAMPLE_SHADING_VALUE, &v);
  return v;
}

std::array<int, 3> StepRow(Context& gl) {
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  StepShader shader;
  DrawWithWindowPositions(gl, shader, {{0, 0}, {16, 0}, {16, 16}, {0, 0}, {16, 16}, {0, 16}});
  return {Red(gl, 7, 4), Red(gl, 8, 4), Red(gl, 9, 4)};
}

}  // namespace

TEST_CASE("multisample: SAMPLE_SHADING runs the shader at each sample once MinSampleShading asks for two or more",
          "[multisample]") {
  Context gl(16, 16, Samples(4));
  CHECK(ShadingValue(gl) == 0.0f);
  CHECK_FALSE(gl.IsEnabled(SAMPLE_SHADING));
  // Once per pixel: pixel 8's centre (8.5) is past the step at 8.45, so all its samples are red.
  CHECK(StepRow(gl) == std::array<int, 3>{0, 255, 255});
  gl.Enable(SAMPLE_SHADING);
  gl.MinSampleShading(0.25f);  // one sample of four: still once per pixel
  CHECK(StepRow(gl) == std::array<int, 3>{0, 255, 255});
  // At each sample: pixel 8's samples at x = 8.375, 8.875, 8.125, 8.625; the two past 8.45 red.
  for (float value : {0.5f, 1.0f, 7.0f}) {
    gl.MinSampleShading(value);
    INFO(value);
    CHECK(StepRow(gl) == std::array<int, 3>{0, 128, 255});
  }
  CHECK(ShadingValue(gl) == 1.0f);  // clamped
  gl.MinSampleShading(std::nanf(""));
  CHECK(ShadingValue(gl) == 0.0f);
  gl.MinSampleShading(1.0f);
  gl.Disable(MULTISAMPLE);  // no effect without multisampling
  CHECK(StepRow(gl) == std::array<int, 3>{0, 255, 255});
  gl.Enable(MULTISAMPLE);
  gl.Disable(SAMPLE_SHADING);
  CHECK(StepRow(gl) == std::array<int, 3>{0, 255, 255});
  CHECK(gl.GetError() == NO_ERROR);
  // A single-sampled framebuffer has no samples to shade apart.
  Context single(16, 16);
  single.Enable(SAMPLE_SHADING);
  single.MinSampleShading(1.0f);
  CHECK(StepRow(single) == std::array<int, 3>{0, 255, 255});
}

namespace {

std::array<int, 4> Pixel(const Image& image, int x, int y) {  // (x, y) with row 0 at the bottom
  const std::uint8_t* p = image.rgba.data() + (std::size_t(image.height - 1 - y) * std::size_t(image.width) + x) * 4;
  return {p[0], p[1], p[2], p[3]};
}

}  // namespace

// The context's multisampled framebuffer defers a clear of a whole 64 x 64 tile until a primitive reaches the
// tile or something else reads its samples (detail::SampleTiles). Whatever the path, the image is OpenGL's.
TEST_CASE("multisample: deferred clears of the context's framebuffer read as cleared", "[multisample]") {
  constexpr int kW = 150, kH = 100;  // 3 x 2 tiles, the last column and row partial
  Context gl(kW, kH, Samples(4));
  SolidShader shader;
  shader.color = glm::vec4(1, 0, 0, 1);
  gl.ClearColor(0, 0, 1, 1);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  // A triangle in the bottom-left tile only.
  DrawWindowTriangle(gl, shader, {4, 4}, {40, 4}, {4, 40}, kW, kH);
  Image image = gl.ReadPixels();
  CHECK(Pixel(image, 10, 10) == std::array<int, 4>{255, 0, 0, 255});
  CHECK(Pixel(image, 50, 50) == std::array<int, 4>{0, 0, 255, 255});    // the drawn tile's background
  CHECK(Pixel(image, 100, 80) == std::array<int, 4>{0, 0, 255, 255});   // tiles no primitive reached
  CHECK(Pixel(image, 149, 99) == std::array<int, 4>{0, 0, 255, 255});
  CHECK(gl.ReadDepth(100, 80) == 1.0f);

  SECTION("a clear with no draw after it, and one after a draw") {
    gl.ClearColor(0, 1, 0, 1);
    gl.Clear(COLOR_BUFFER_BIT);
    image = gl.ReadPixels();
    for (const auto& [x, y] : {std::pair{10, 10}, {50, 50}, {100, 80}, {149, 0}})
      CHECK(Pixel(image, x, y) == std::array<int, 4>{0, 255, 0, 255});
    // The triangle's edge pixel resolves from green, not from the red drawn before the clear.
    DrawWindowTriangle(gl, shader, {-10, -10}, {20.5f, -10}, {20.5f, 120}, kW, kH);
    image = gl.ReadPixels();
    CHECK(std::abs(Pixel(image, 20, 60)[0] - 128) <= 1);
    CHECK(std::abs(Pixel(image, 20, 60)[1] - 128) <= 1);
    CHECK(Pixel(image, 21, 60) == std::array<int, 4>{0, 255, 0, 255});
  }
  SECTION("a scissored clear and a masked clear change part of a deferred one") {
    gl.ClearColor(1, 1, 1, 1);
    gl.Clear(COLOR_BUFFER_BIT);  // deferred in every tile
    gl.Enable(SCISSOR_TEST);
    gl.Scissor(60, 30, 20, 40);  // across the first two columns of tiles
    gl.ClearColor(0, 0, 0, 1);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.Disable(SCISSOR_TEST);
    gl.ColorMask(false, true, false, false);
    gl.ClearColor(0, 0.5f, 0, 0);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.ColorMask(true, true, true, true);
    image = gl.ReadPixels();
    CHECK(Pixel(image, 59, 50) == std::array<int, 4>{255, 128, 255, 255});
    CHECK(Pixel(image, 60, 50) == std::array<int, 4>{0, 128, 0, 255});
    CHECK(Pixel(image, 79, 69) == std::array<int, 4>{0, 128, 0, 255});
    CHECK(Pixel(image, 80, 69) == std::array<int, 4>{255, 128, 255, 255});
    CHECK(Pixel(image, 140, 90) == std::array<int, 4>{255, 128, 255, 255});
  }
  SECTION("deferred depth and stencil are what the tests and the reads see") {
    gl.ClearDepth(0.25);
    gl.ClearStencil(0x35);
    gl.Clear(DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
    (void)gl.ReadPixels();  // colour alone resolved: depth and stencil stay out of date until read
    float depth = 0.0f;
    gl.ReadPixels(100, 80, 1, 1, DEPTH_COMPONENT, FLOAT, &depth);
    CHECK(depth == 0.25f);
    std::uint8_t stencil = 0;
    gl.ReadPixels(10, 10, 1, 1, STENCIL_INDEX, UNSIGNED_BYTE, &stencil);
    CHECK(stencil == 0x35);
    CHECK(gl.ReadDepth(100, 80) == 0.25f);
    CHECK(gl.ReadStencil(100, 80) == 0x35);
    gl.Enable(DEPTH_TEST);  // depth 0.5 fails against 0.25 everywhere
    shader.color = glm::vec4(1, 1, 0, 1);
    DrawWindowTriangle(gl, shader, {-10, -10}, {400, -10}, {-10, 400}, kW, kH);
    gl.Disable(DEPTH_TEST);
    image = gl.ReadPixels();
    CHECK(Pixel(image, 10, 10) == std::array<int, 4>{255, 0, 0, 255});
    CHECK(Pixel(image, 100, 80) == std::array<int, 4>{0, 0, 255, 255});
    // A stencil clear through a write mask keeps the deferred value's other bits.
    gl.StencilMask(0x0F);
    gl.ClearStencil(0xFA);
    gl.Clear(STENCIL_BUFFER_BIT);
    gl.StencilMask(0xFF);
    CHECK(gl.ReadStencil(100, 80) == 0x3A);
    CHECK(gl.ReadStencil(10, 10) == 0x3A);
  }
  SECTION("blits read and write the samples with the deferred clears in them") {
    gl.ClearColor(0, 1, 1, 1);
    gl.Clear(COLOR_BUFFER_BIT);
    // From the multisampled framebuffer into a single-sampled object: resolved from the clear's value.
    const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, RGBA8, kW, kH);
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    gl.BlitFramebuffer(0, 0, kW, kH, 0, 0, kW, kH, COLOR_BUFFER_BIT, NEAREST);
    CHECK(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
    image = gl.ReadPixels();
    CHECK(Pixel(image, 100, 80) == std::array<int, 4>{0, 255, 255, 255});
    CHECK(Pixel(image, 10, 10) == std::array<int, 4>{0, 255, 255, 255});
    // Into the multisampled framebuffer: a rectangle of one tile from the object, the rest of it as cleared.
    gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    gl.ClearColor(1, 0, 1, 1);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.BlitFramebuffer(0, 0, 10, 10, 70, 70, 80, 80, COLOR_BUFFER_BIT, NEAREST);
    gl.BindFramebuffer(READ_FRAMEBUFFER, 0);
    image = gl.ReadPixels();
    CHECK(Pixel(image, 75, 75) == std::array<int, 4>{0, 255, 255, 255});
    CHECK(Pixel(image, 69, 75) == std::array<int, 4>{255, 0, 255, 255});
    CHECK(Pixel(image, 120, 90) == std::array<int, 4>{255, 0, 255, 255});
  }
}

namespace {

// A solid colour whose depth the shader writes (gl_FragDepth): its window depth pulled towards 0.3.
struct SolidDepthShader : softgl::Shader<SolidDepthShader, NoVaryings> {
  static constexpr bool kWritesDepth = true;
  glm::vec4 color{1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const softgl::FragmentIn<NoVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = color;
    out.depth = 0.3f + 0.5f * (in.frag_coord.z - 0.3f);
    return true;
  }
};

// Random overlapping triangles into whatever is bound: depth-tested, every third blended, a run with MULTISAMPLE
// disabled, a run whose shader writes the depth, each pass counting into the stencil (when `stencil`); then a
// cover pass where the stencil is 2 and a line across. Colours are multiples of 1/255.
// Two resolved RGBA images of DrawMixedScene: the same bytes, and edges and blending left colours between.
void CheckSameMixed(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  int differ = 0, mixed = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
  for (std::size_t i = 0; i < a.size(); i += 4) mixed += a[i + 2] > 0 && a[i + 2] < 255 && a[i] > 0;
  CHECK(differ == 0);
  CHECK(mixed > 10);
}

void DrawMixedScene(Context& gl, int w, int h, bool stencil) {
  SolidShader shader;
  SolidDepthShader depth_shader;
  gl.Enable(DEPTH_TEST);
  gl.DepthFunc(LEQUAL);
  if (stencil) {
    gl.Enable(STENCIL_TEST);
    gl.StencilFunc(ALWAYS, 0, 0xFF);
    gl.StencilOp(KEEP, KEEP, INCR);
  }
  gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> pos(-4.0f, float(w) + 8.0f), depth(-0.3f, 0.9f);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int t = 0; t < 60; ++t) {
    const glm::vec4 colour = glm::vec4(float(byte(rng)), float(byte(rng)), float(byte(rng)), 128.0f) / 255.0f;
    const glm::vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng)), c(pos(rng), pos(rng));
    const float za = depth(rng), zb = depth(rng), zc = depth(rng);
    if (t % 3 == 0) gl.Enable(BLEND);
    if (t == 20) gl.Disable(MULTISAMPLE);
    if (t == 28) gl.Enable(MULTISAMPLE);
    MakeVertexArray(gl, {WindowToClip(a.x, a.y, w, h, za), WindowToClip(b.x, b.y, w, h, zb), WindowToClip(c.x, c.y, w, h, zc)});
    if (t >= 40 && t < 48) {
      depth_shader.color = colour;
      gl.UseProgram(depth_shader);
    } else {
      shader.color = colour;
      gl.UseProgram(shader);
    }
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.Disable(BLEND);
  }
  shader.color = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
  gl.Disable(DEPTH_TEST);
  if (stencil) {
    gl.StencilFunc(EQUAL, 2, 0xFF);
    gl.StencilOp(KEEP, KEEP, KEEP);
    DrawWindowTriangle(gl, shader, {-40, -40}, {90, -40}, {-40, 90}, w, h);
    DrawWindowTriangle(gl, shader, {-40, 90}, {90, -40}, {90, 90}, w, h);
    gl.Disable(STENCIL_TEST);
  }
  shader.color = glm::vec4(1.0f, 1.0f, 0.0f, 1.0f);
  MakeVertexArray(gl, {WindowToClip(1.3f, 2.1f, w, h), WindowToClip(float(w) - 2.6f, float(h) - 5.2f, w, h)});
  gl.UseProgram(shader);
  gl.DrawArrays(LINES, 0, 2);
}

}  // namespace

TEST_CASE("an odd-sized target draws, where it overlaps, the bytes of an even-sized one", "[fragment_ops]") {
  // A 31 x 31 target takes the blocks inside it on the vector operations, run by run, and its edge blocks lane by
  // lane; a 32 x 32 one (drawing through a 31 x 31 viewport) takes every block on the vector operations. The same
  // scene (depth-tested, blended, stencil-counted triangles, a stencil pass, a line), single-sampled, with float
  // and 16-bit depth, into the context's framebuffer and into a framebuffer object of RGBA8 and of RGBA16F, must
  // give the same bytes in the 31 x 31 pixels both have.
  for (const bool depth16 : {false, true})
    for (const Enum format : {Enum(0), RGBA8, RGBA16F}) {
      CAPTURE(depth16, format);
      auto render = [&](int size) {
        Context::Options options = Samples(0);
        if (depth16) options.depth_format = DEPTH_COMPONENT16;
        Context gl(size, size, options);
        if (format) {
          MultisampleFbo fbo(gl, 0, size, size, format);
          if (depth16) {  // the depth a 16-bit renderbuffer, no stencil
            const std::uint32_t rb = gl.GenRenderbuffer();
            gl.BindRenderbuffer(RENDERBUFFER, rb);
            gl.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT16, size, size);
            gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
            gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, rb);
          }
          REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
          gl.Viewport(0, 0, 31, 31);
          gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
          DrawMixedScene(gl, 31, 31, !depth16);
        } else {
          gl.Viewport(0, 0, 31, 31);
          gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
          DrawMixedScene(gl, 31, 31, !depth16);
        }
        std::vector<float> px(31 * 31 * 4);
        gl.ReadPixels(0, 0, 31, 31, RGBA, FLOAT, px.data());
        CHECK(gl.GetError() == NO_ERROR);
        return px;
      };
      const std::vector<float> odd = render(31), even = render(32);
      int drawn = 0;
      for (std::size_t i = 0; i < odd.size(); i += 4) drawn += odd[i] != 0.0f || odd[i + 1] != 0.0f || odd[i + 2] != 0.0f;
      CHECK(drawn > 400);
      CHECK(odd == even);
    }
}

TEST_CASE("multisample: the context's framebuffer (samples side by side) draws as a framebuffer object (planes)",
          "[multisample]") {
  // The context's own multisampled framebuffer keeps each pixel's samples together and has its own vector
  // operations (early test, depth, stencil, blending); a framebuffer object keeps a plane per sample. The same
  // scene into each must resolve to the same bytes: at 2, 4 and 8 samples, at an even size (every block on the
  // vector path) and an odd one (edge blocks lane by lane), with float and 16-bit depth.
  for (int samples : {2, 4, 8})
    for (int size : {32, 31})
      for (bool depth16 : {false, true}) {
        CAPTURE(samples, size, depth16);
        Context::Options options = Samples(samples);
        if (depth16) options.depth_format = DEPTH_COMPONENT16;
        Context own(size, size, options);
        own.ClearColor(0, 0, 0, 1);
        own.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
        DrawMixedScene(own, size, size, !depth16);
        std::vector<std::uint8_t> a(std::size_t(size * size) * 4), b(a.size());
        own.ReadPixels(0, 0, size, size, RGBA, UNSIGNED_BYTE, a.data());

        Context gl(size, size, Samples(0));
        MultisampleFbo fbo(gl, samples, size, size);
        if (depth16) {  // the depth a 16-bit renderbuffer, no stencil
          const std::uint32_t rb = gl.GenRenderbuffer();
          gl.BindRenderbuffer(RENDERBUFFER, rb);
          gl.RenderbufferStorageMultisample(RENDERBUFFER, samples, DEPTH_COMPONENT16, size, size);
          gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
          gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, rb);
          REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
        }
        fbo.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
        DrawMixedScene(gl, size, size, !depth16);
        fbo.Resolve();
        gl.ReadPixels(0, 0, size, size, RGBA, UNSIGNED_BYTE, b.data());
        CHECK(own.GetError() == NO_ERROR);
        CHECK(gl.GetError() == NO_ERROR);
        CheckSameMixed(a, b);
      }
}

TEST_CASE("multisample: the context's SRGB8_ALPHA8 and RGB565 framebuffers (samples side by side) draw as framebuffer "
          "objects of the format", "[multisample][formats]") {
  // The block path writes a context framebuffer of samples side by side in RGB565 or sRGB-encoded RGBA8 in float
  // vectors; a framebuffer object of the same format keeps a plane per sample. The same scene into each must resolve
  // to the same bytes (even sizes: every block on the vector path; an odd one: edge blocks lane by lane).
  for (const Enum format : {SRGB8_ALPHA8, RGB565})
    for (int samples : {2, 4, 8})
      for (int size : {32, 31}) {
        CAPTURE(format, samples, size);
        Context::Options options = Samples(samples);
        options.color_format = format;
        Context own(size, size, options);
        own.Enable(FRAMEBUFFER_SRGB);
        own.ClearColor(0, 0, 0, 1);
        own.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
        DrawMixedScene(own, size, size, true);
        std::vector<std::uint8_t> a(std::size_t(size * size) * 4), b(a.size());
        own.ReadPixels(0, 0, size, size, RGBA, UNSIGNED_BYTE, a.data());

        Context gl(size, size, Samples(0));
        gl.Enable(FRAMEBUFFER_SRGB);
        MultisampleFbo fbo(gl, samples, size, size, format, format);
        REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
        fbo.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
        DrawMixedScene(gl, size, size, true);
        gl.Disable(FRAMEBUFFER_SRGB);  // the stored bytes averaged, as the context's framebuffer resolves
        fbo.Resolve();
        gl.ReadPixels(0, 0, size, size, RGBA, UNSIGNED_BYTE, b.data());
        CHECK(own.GetError() == NO_ERROR);
        CHECK(gl.GetError() == NO_ERROR);
        CheckSameMixed(a, b);
      }
}

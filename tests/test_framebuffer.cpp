// Framebuffers: renderbuffers, stencil in framebuffer objects (renderbuffers and depth-stencil textures), the read
// buffer, and BlitFramebuffer (detail::Blit's mapping, mirroring, scaling and clipping; the call's errors).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

#include "framebuffer.h"
#include "helpers.h"

using namespace softgl;

namespace {

// A framebuffer object with an RGBA8 colour renderbuffer and a depth/stencil renderbuffer of `ds_format` (0: none),
// w x h, bound to FRAMEBUFFER.
struct RenderbufferFbo {
  std::uint32_t fbo = 0, color = 0, ds = 0;
  RenderbufferFbo(Context& gl, int w, int h, Enum ds_format, Enum ds_attachment = DEPTH_STENCIL_ATTACHMENT) {
    fbo = gl.GenFramebuffer();
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    color = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, color);
    gl.RenderbufferStorage(RENDERBUFFER, RGBA8, w, h);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, color);
    if (ds_format != 0) {
      ds = gl.GenRenderbuffer();
      gl.BindRenderbuffer(RENDERBUFFER, ds);
      gl.RenderbufferStorage(RENDERBUFFER, ds_format, w, h);
      gl.FramebufferRenderbuffer(FRAMEBUFFER, ds_attachment, RENDERBUFFER, ds);
    }
  }
};

// Marks the stencil buffer with 1 where a quad covers x in [x0, x1) of the viewport (clip-space x), then draws
// full-screen colour `c` where the stencil is 1.
void StencilMaskedFill(Context& gl, float x0, float x1, const glm::vec4& c) {
  testing::SolidShader shader;
  gl.UseProgram(shader);
  gl.Enable(STENCIL_TEST);
  gl.ClearStencil(0);
  gl.Clear(STENCIL_BUFFER_BIT);
  gl.StencilFunc(ALWAYS, 1, 0xFF);
  gl.StencilOp(KEEP, KEEP, REPLACE);
  gl.ColorMask(false, false, false, false);
  testing::MakeVertexArray(gl, {{x0, -1, 0, 1}, {x1, -1, 0, 1}, {x0, 1, 0, 1}, {x1, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.ColorMask(true, true, true, true);
  gl.StencilFunc(EQUAL, 1, 0xFF);
  gl.StencilOp(KEEP, KEEP, KEEP);
  shader.color = c;
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.Finish();
  gl.Disable(STENCIL_TEST);
}

// An RGBA8 buffer with depth and stencil (colour 0, depth 1, stencil 0) of w x h, for detail::Blit.
struct Buffers : detail::Framebuffer {
  Buffers(int w, int h) { REQUIRE(Allocate(w, h)); }
  std::uint8_t& R(int x, int y) { return color[Index(x, y) * 4]; }
};

// A source whose red channel is x * 16 + y and stencil x + 10 * y, depth (x + y) / 64.
Buffers Gradient(int w, int h) {
  Buffers b(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      b.R(x, y) = std::uint8_t(x * 16 + y);
      b.stencil[std::size_t(y * w + x)] = std::uint8_t(x + 10 * y);
      b.depth[std::size_t(y * w + x)] = float(x + y) / 64.0f;
    }
  return b;
}

detail::BlitRegion Region(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, int clip_w,
                          int clip_h) {
  detail::BlitRegion r;
  r.src[0] = sx0, r.src[1] = sy0, r.src[2] = sx1, r.src[3] = sy1;
  r.dst[0] = dx0, r.dst[1] = dy0, r.dst[2] = dx1, r.dst[3] = dy1;
  r.clip = detail::Rect{0, 0, clip_w, clip_h};
  r.color = r.depth = r.stencil = true;
  return r;
}

}  // namespace

TEST_CASE("renderbuffer objects: storage, parameters and errors", "[framebuffer]") {
  Context gl(4, 4);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 4, 4);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  const std::uint32_t rb = gl.GenRenderbuffer();
  CHECK(gl.IsRenderbuffer(rb));
  gl.BindRenderbuffer(TEXTURE_2D, rb);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindRenderbuffer(RENDERBUFFER, 999);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  int v = -1;
  gl.GetRenderbufferParameteriv(RENDERBUFFER, RENDERBUFFER_INTERNAL_FORMAT, &v);
  CHECK(v == int(RGBA));  // before any storage
  gl.GetIntegerv(RENDERBUFFER_BINDING, &v);
  CHECK(v == int(rb));
  gl.RenderbufferStorage(RENDERBUFFER, 0x1234, 4, 4);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, -1, 4);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, kMaxFramebufferSize + 1, 4);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetIntegerv(MAX_RENDERBUFFER_SIZE, &v);
  CHECK(v == kMaxFramebufferSize);
  struct Expect {
    Enum format;
    int r, g, b, a, d, s;
  };
  for (const Expect& e : {Expect{RGBA8, 8, 8, 8, 8, 0, 0}, Expect{RGB8, 8, 8, 8, 0, 0, 0},
                          Expect{R32F, 32, 0, 0, 0, 0, 0},
                          Expect{DEPTH_COMPONENT16, 0, 0, 0, 0, 16, 0}, Expect{DEPTH_COMPONENT, 0, 0, 0, 0, 24, 0},
                          Expect{DEPTH24_STENCIL8, 0, 0, 0, 0, 24, 8}, Expect{DEPTH32F_STENCIL8, 0, 0, 0, 0, 32, 8},
                          Expect{STENCIL_INDEX8, 0, 0, 0, 0, 0, 8}, Expect{DEPTH_STENCIL, 0, 0, 0, 0, 24, 8},
                          // OpenGL 3.3 accepts these without requiring their sizes: the sizes stored are reported
                          Expect{DEPTH_COMPONENT32, 0, 0, 0, 0, 24, 0}, Expect{STENCIL_INDEX1, 0, 0, 0, 0, 0, 8},
                          Expect{STENCIL_INDEX4, 0, 0, 0, 0, 0, 8}, Expect{STENCIL_INDEX16, 0, 0, 0, 0, 0, 8}}) {
    gl.RenderbufferStorage(RENDERBUFFER, e.format, 16, 8);
    int got[9];
    const Enum names[9] = {RENDERBUFFER_WIDTH, RENDERBUFFER_HEIGHT, RENDERBUFFER_INTERNAL_FORMAT, RENDERBUFFER_RED_SIZE,
                           RENDERBUFFER_GREEN_SIZE, RENDERBUFFER_BLUE_SIZE, RENDERBUFFER_ALPHA_SIZE,
                           RENDERBUFFER_DEPTH_SIZE, RENDERBUFFER_STENCIL_SIZE};
    for (int k = 0; k < 9; ++k) gl.GetRenderbufferParameteriv(RENDERBUFFER, names[k], &got[k]);
    INFO("format " << e.format);
    CHECK(got[0] == 16);
    CHECK(got[1] == 8);
    CHECK(got[2] == int(e.format));
    CHECK((got[3] == e.r && got[4] == e.g && got[5] == e.b && got[6] == e.a && got[7] == e.d && got[8] == e.s));
  }
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetRenderbufferParameteriv(RENDERBUFFER, 0x1234, &v);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.DeleteRenderbuffer(rb);
  CHECK(!gl.IsRenderbuffer(rb));
  gl.GetIntegerv(RENDERBUFFER_BINDING, &v);
  CHECK(v == 0);  // deleting the bound renderbuffer unbinds it
}

TEST_CASE("framebuffer completeness with renderbuffers and stencil attachments", "[framebuffer]") {
  Context gl(4, 4);
  RenderbufferFbo f(gl, 8, 8, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  const std::uint32_t depth = gl.GenRenderbuffer(), stencil = gl.GenRenderbuffer(), both = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, depth);
  gl.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT24, 8, 8);
  gl.BindRenderbuffer(RENDERBUFFER, stencil);
  gl.RenderbufferStorage(RENDERBUFFER, STENCIL_INDEX8, 8, 8);
  gl.BindRenderbuffer(RENDERBUFFER, both);
  gl.RenderbufferStorage(RENDERBUFFER, DEPTH24_STENCIL8, 8, 8);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, STENCIL_ATTACHMENT, RENDERBUFFER, stencil);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);  // stencil alone
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, depth);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);  // separate depth and stencil images
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, stencil);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);  // stencil-only as depth
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, depth);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, STENCIL_ATTACHMENT, RENDERBUFFER, depth);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);  // depth-only as stencil
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, RENDERBUFFER, both);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, both);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);  // depth-stencil as colour
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, RENDERBUFFER, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  int v = 0;
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
  CHECK(v == int(both));
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, STENCIL_ATTACHMENT, FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  CHECK(v == int(RENDERBUFFER));
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0 + 2, FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  CHECK(v == int(NONE));
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  CHECK(gl.GetError() == INVALID_ENUM);  // a renderbuffer has no level
  // An RGBA8 renderbuffer at a zero size is attached but not complete.
  gl.BindRenderbuffer(RENDERBUFFER, f.color);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 0, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  // Errors of FramebufferRenderbuffer.
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, both);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, BACK, RENDERBUFFER, both);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, 777);
  CHECK(gl.GetError() == INVALID_OPERATION);
  // Deleting an attached renderbuffer detaches it from the bound framebuffer object.
  gl.DeleteRenderbuffer(both);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, DEPTH_ATTACHMENT, FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  CHECK(v == int(NONE));
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, depth);
  CHECK(gl.GetError() == INVALID_OPERATION);  // the context's own framebuffer has no attachment points
}

TEST_CASE("the stencil test works in framebuffer objects: renderbuffers and depth-stencil textures", "[framebuffer]") {
  for (Enum format : {DEPTH24_STENCIL8, DEPTH32F_STENCIL8, STENCIL_INDEX8}) {
    INFO("renderbuffer format " << format);
    Context gl(4, 4);
    RenderbufferFbo f(gl, 8, 4, format, format == STENCIL_INDEX8 ? STENCIL_ATTACHMENT : DEPTH_STENCIL_ATTACHMENT);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    gl.Viewport(0, 0, 8, 4);
    gl.ClearColor(0, 0, 0, 1);
    gl.Clear(COLOR_BUFFER_BIT);
    StencilMaskedFill(gl, -1.0f, 0.0f, glm::vec4(1, 0, 0, 1));  // left half
    std::uint8_t px[4];
    gl.ReadPixel(1, 1, px);
    CHECK(px[0] == 255);
    gl.ReadPixel(6, 1, px);
    CHECK(px[0] == 0);
    CHECK(gl.ReadStencil(1, 1) == 1);
    CHECK(gl.ReadStencil(6, 1) == 0);
    CHECK(gl.GetError() == NO_ERROR);
  }
  // A DEPTH24_STENCIL8 texture: rendered with depth and stencil, then its depth sampled and its texels read back.
  Context gl(4, 4);
  const std::uint32_t color = gl.GenTexture(), ds = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D, color);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 8, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindTexture(TEXTURE_2D, ds);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 8, 4, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, nullptr);
  CHECK(gl.GetError() == NO_ERROR);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, color, 0);
  gl.FramebufferTexture2D(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, TEXTURE_2D, ds, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.Viewport(0, 0, 8, 4);
  gl.ClearDepth(0.25);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  StencilMaskedFill(gl, 0.0f, 1.0f, glm::vec4(0, 1, 0, 1));  // right half
  std::vector<std::uint32_t> words(32, 0);
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, words.data());
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(words[0] == ((std::uint32_t(std::lround(0.25 * 16777215.0)) << 8) | 0u));
  CHECK((words[7] & 0xFF) == 1u);  // right half marked
  std::uint8_t px[4];
  gl.ReadPixel(6, 2, px);
  CHECK(px[1] == 255);
  gl.ReadPixel(1, 2, px);
  CHECK(px[1] == 0);
  // Data uploads as DEPTH_STENCIL: UNSIGNED_INT_24_8 and FLOAT_32_UNSIGNED_INT_24_8_REV.
  const std::uint32_t packed[2] = {(0x800000u << 8) | 7u, (0xFFFFFFu << 8) | 200u};
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 2, 1, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, packed);
  std::uint32_t back[2] = {0, 0};
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, back);
  CHECK(back[0] == packed[0]);
  CHECK(back[1] == packed[1]);
  struct {
    float depth;
    std::uint32_t stencil;
  } rev[1] = {{0.5f, 9u}};
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH32F_STENCIL8, 1, 1, 0, DEPTH_STENCIL, FLOAT_32_UNSIGNED_INT_24_8_REV, rev);
  float d = 0;
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_COMPONENT, FLOAT, &d);
  CHECK(d == 0.5f);
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, back);
  CHECK((back[0] & 0xFF) == 9u);
  CHECK(gl.GetError() == NO_ERROR);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 1, 1, 0, DEPTH_STENCIL, FLOAT, nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);  // DEPTH_STENCIL takes the packed types only (OpenGL 3.3, section 4.3.1)
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_INT_24_8, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);  // depth data for a colour format
  gl.TexImage2D(TEXTURE_2D, 0, STENCIL_INDEX8, 1, 1, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);  // stencil-only textures are not OpenGL 3.3's
}

TEST_CASE("ReadBuffer chooses the colour buffer that reads and copies take", "[framebuffer]") {
  Context gl(4, 4);
  int v = 0;
  gl.GetIntegerv(READ_BUFFER, &v);
  CHECK(v == int(BACK));
  for (Enum ok : {FRONT, LEFT, FRONT_LEFT, BACK_LEFT, FRONT_AND_BACK, BACK}) {
    gl.ReadBuffer(ok);
    CHECK(gl.GetError() == NO_ERROR);
  }
  gl.ReadBuffer(RIGHT);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.ReadBuffer(COLOR_ATTACHMENT0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.ReadBuffer(0x1234);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ReadBuffer(NONE);
  std::uint8_t px[4];
  gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_OPERATION);  // no colour buffer to read
  float d = 0;
  gl.ReadPixels(0, 0, 1, 1, DEPTH_COMPONENT, FLOAT, &d);
  CHECK(gl.GetError() == NO_ERROR);  // depth still reads
  gl.ReadBuffer(BACK);
  // A framebuffer object with two colour attachments: each clear goes to one, ReadBuffer picks which is read.
  Context g2(2, 2);
  const std::uint32_t fbo = g2.GenFramebuffer(), rb[2] = {g2.GenRenderbuffer(), g2.GenRenderbuffer()};
  g2.BindFramebuffer(FRAMEBUFFER, fbo);
  for (int k = 0; k < 2; ++k) {
    g2.BindRenderbuffer(RENDERBUFFER, rb[k]);
    g2.RenderbufferStorage(RENDERBUFFER, RGBA8, 2, 2);
    g2.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(k), RENDERBUFFER, rb[k]);
    const Enum buf = COLOR_ATTACHMENT0 + Enum(k);
    g2.DrawBuffers(1, &buf);
    g2.ClearColor(k == 0 ? 1.0f : 0.0f, k == 1 ? 1.0f : 0.0f, 0, 1);
    g2.Clear(COLOR_BUFFER_BIT);
  }
  g2.GetIntegerv(READ_BUFFER, &v);
  CHECK(v == int(COLOR_ATTACHMENT0));
  g2.ReadPixel(0, 0, px);
  CHECK((px[0] == 255 && px[1] == 0));
  g2.ReadBuffer(COLOR_ATTACHMENT0 + 1);
  g2.ReadPixel(0, 0, px);
  CHECK((px[0] == 0 && px[1] == 255));
  g2.ReadBuffer(BACK);
  CHECK(g2.GetError() == INVALID_OPERATION);
  g2.ReadBuffer(COLOR_ATTACHMENT0 + kMaxColorOutputs);
  CHECK(g2.GetError() == INVALID_OPERATION);  // beyond MAX_COLOR_ATTACHMENTS (8)
  g2.ReadBuffer(COLOR_ATTACHMENT0 + 7);  // the last
  CHECK(g2.GetError() == NO_ERROR);
  g2.ReadBuffer(COLOR_ATTACHMENT0 + 3);  // an empty attachment: accepted, but reading colour fails
  CHECK(g2.GetError() == NO_ERROR);
  CHECK(g2.CheckFramebufferStatus(READ_FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  g2.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(g2.GetError() == INVALID_OPERATION);
}

TEST_CASE("Blit copies, scales, mirrors and clips as BlitFramebuffer says", "[framebuffer]") {
  SECTION("one to one, with depth and stencil, only inside the clip") {
    Buffers src = Gradient(4, 4), dst(8, 8);
    detail::BlitRegion r = Region(0, 0, 4, 4, 2, 3, 6, 7, 8, 8);
    r.clip = detail::Rect{0, 0, 5, 8};  // a scissor box cutting x at 5
    detail::Blit(src.Target(), dst.Target(), r);
    CHECK(dst.R(2, 3) == src.R(0, 0));
    CHECK(dst.R(4, 6) == src.R(2, 3));
    CHECK(dst.R(5, 6) == 0);  // outside the clip
    CHECK(dst.R(1, 3) == 0);  // outside the rectangle
    CHECK(dst.stencil[std::size_t(6 * 8 + 4)] == src.stencil[std::size_t(3 * 4 + 2)]);
    CHECK(dst.depth[std::size_t(6 * 8 + 4)] == src.depth[std::size_t(3 * 4 + 2)]);
  }
  SECTION("mirrored by a reversed destination or source") {
    Buffers src = Gradient(4, 4), a(4, 4), b(4, 4);
    detail::Blit(src.Target(), a.Target(), Region(0, 0, 4, 4, 4, 0, 0, 4, 4, 4));
    detail::Blit(src.Target(), b.Target(), Region(0, 4, 4, 0, 0, 0, 4, 4, 4, 4));
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        CHECK(a.R(x, y) == src.R(3 - x, y));
        CHECK(b.R(x, y) == src.R(x, 3 - y));
      }
  }
  SECTION("NEAREST scaling takes the pixel holding each destination centre") {
    Buffers src = Gradient(4, 4), up(8, 8), down(2, 2);
    detail::Blit(src.Target(), up.Target(), Region(0, 0, 4, 4, 0, 0, 8, 8, 8, 8));
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) CHECK(up.R(x, y) == src.R(x / 2, y / 2));
    detail::Blit(src.Target(), down.Target(), Region(0, 0, 4, 4, 0, 0, 2, 2, 2, 2));
    CHECK(down.R(0, 0) == src.R(1, 1));  // centre 0.5 maps to 1.0: pixel 1
    CHECK(down.R(1, 1) == src.R(3, 3));
  }
  SECTION("LINEAR mixes the four nearest centres, clamped to the edge") {
    Buffers src(2, 1), dst(4, 1);
    src.R(0, 0) = 0;
    src.R(1, 0) = 200;
    detail::BlitRegion r = Region(0, 0, 2, 1, 0, 0, 4, 1, 4, 1);
    r.depth = r.stencil = false;
    r.linear = true;
    detail::Blit(src.Target(), dst.Target(), r);
    // Destination centres 0.5, 1.5, 2.5, 3.5 map to 0.25, 0.75, 1.25, 1.75: 0, 50, 150, 200 after the clamp.
    CHECK(dst.R(0, 0) == 0);
    CHECK(dst.R(1, 0) == 50);
    CHECK(dst.R(2, 0) == 150);
    CHECK(dst.R(3, 0) == 200);
  }
  SECTION("source outside the read buffer is clipped, not read") {
    Buffers src = Gradient(4, 4), dst(8, 8);
    dst.R(0, 0) = 77;
    detail::Blit(src.Target(), dst.Target(), Region(-2, 0, 6, 8, 0, 0, 8, 8, 8, 8));
    CHECK(dst.R(0, 0) == 77);  // its source x is -1.5
    CHECK(dst.R(2, 0) == src.R(0, 0));
    CHECK(dst.R(6, 0) == 0);  // source x 4.5: outside, left as it was
  }
}

TEST_CASE("BlitFramebuffer between framebuffer objects and the context's framebuffer, and its errors",
          "[framebuffer]") {
  Context gl(8, 8);
  RenderbufferFbo f(gl, 4, 4, DEPTH24_STENCIL8);
  gl.ClearColor(1, 0, 0, 1);
  gl.ClearDepth(0.5);
  gl.ClearStencil(5);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 8, 8, COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == NO_ERROR);
  gl.BindFramebuffer(READ_FRAMEBUFFER, 0);
  std::uint8_t px[4];
  gl.ReadPixel(7, 7, px);
  CHECK((px[0] == 255 && px[3] == 255));
  CHECK(gl.ReadDepth(7, 7) == 0.5f);
  CHECK(gl.ReadStencil(7, 7) == 5);
  // Errors.
  gl.BindFramebuffer(READ_FRAMEBUFFER, f.fbo);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, 0x8000, NEAREST);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, COLOR_BUFFER_BIT, 0x1234);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, DEPTH_BUFFER_BIT, LINEAR);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, 0, NEAREST);
  CHECK(gl.GetError() == NO_ERROR);  // nothing to copy
  // DEPTH32F_STENCIL8 against the context's framebuffer (DEPTH24_STENCIL8): formats differ for depth and stencil.
  gl.BindRenderbuffer(RENDERBUFFER, f.ds);
  gl.RenderbufferStorage(RENDERBUFFER, DEPTH32F_STENCIL8, 4, 4);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, DEPTH_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, STENCIL_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, COLOR_BUFFER_BIT, LINEAR);
  CHECK(gl.GetError() == NO_ERROR);  // colour goes whatever the depth formats
  // A read framebuffer without depth: the depth bit is skipped without an error.
  gl.FramebufferRenderbuffer(READ_FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, 0);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == NO_ERROR);
  // An incomplete read framebuffer.
  gl.BindRenderbuffer(RENDERBUFFER, f.color);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 0, 0);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, COLOR_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == INVALID_FRAMEBUFFER_OPERATION);
  // The scissor test limits what is written; the colour mask does not.
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.ClearColor(0, 0, 0, 0);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ClearColor(0, 0, 1, 1);
  gl.Scissor(0, 0, 4, 4);
  gl.Enable(SCISSOR_TEST);
  gl.Clear(COLOR_BUFFER_BIT);  // blue in the lower-left quarter
  gl.Disable(SCISSOR_TEST);
  gl.Scissor(4, 0, 2, 8);
  gl.Enable(SCISSOR_TEST);
  gl.ColorMask(false, false, false, false);
  gl.BlitFramebuffer(0, 0, 4, 4, 4, 0, 8, 4, COLOR_BUFFER_BIT, NEAREST);  // same framebuffer, side by side
  gl.ColorMask(true, true, true, true);
  gl.Disable(SCISSOR_TEST);
  gl.ReadPixel(5, 1, px);
  CHECK((px[2] == 255 && px[3] == 255));
  gl.ReadPixel(6, 1, px);
  CHECK(px[2] == 0);  // outside the scissor box
  CHECK(gl.GetError() == NO_ERROR);
  // Overlapping rectangles in one buffer (undefined in OpenGL) are refused and copy nothing; in different buffers,
  // or with the shared buffer left out of the mask, they are not.
  gl.BlitFramebuffer(0, 0, 4, 4, 3, 3, 7, 7, COLOR_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.ReadPixel(3, 3, px);
  CHECK((px[2] == 255 && px[0] == 0));  // still the blue quarter
  gl.BlitFramebuffer(4, 4, 0, 0, 6, 6, 2, 2, STENCIL_BUFFER_BIT, NEAREST);  // reversed, still overlapping
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindFramebuffer(READ_FRAMEBUFFER, f.fbo);
  gl.BindRenderbuffer(RENDERBUFFER, f.color);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 4, 4);
  gl.BlitFramebuffer(0, 0, 4, 4, 2, 2, 6, 6, COLOR_BUFFER_BIT, NEAREST);
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {

// Draws the rectangle x0 <= x < x1 of an 8 x 8 viewport, all rows, at window depth z_steps / 65535.
void DepthRect(Context& gl, testing::SolidShader& shader, float z_steps, float x0, float x1) {
  using testing::WindowToClip;
  const float z = 2.0f * z_steps / 65535.0f - 1.0f;
  testing::MakeVertexArray(gl, {WindowToClip(x0, 0, 8, 8, z), WindowToClip(x1, 0, 8, 8, z), WindowToClip(x1, 8, 8, 8, z),
                                WindowToClip(x0, 0, 8, 8, z), WindowToClip(x1, 8, 8, 8, z), WindowToClip(x0, 8, 8, 8, z)});
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 6);
}

}  // namespace

TEST_CASE("DEPTH_COMPONENT16 keeps 16-bit depth: two bytes a texel, the test on values converted to 16 bits",
          "[framebuffer]") {
  // Storage: the level's layout is one 16-bit word a texel.
  CHECK(detail::LayoutOf(DEPTH_COMPONENT16) == detail::TexelLayout::kUnorm16x1);
  CHECK(detail::BytesPerTexel(detail::LayoutOf(DEPTH_COMPONENT16)) == 2);
  CHECK(detail::BytesPerTexel(detail::LayoutOf(DEPTH_COMPONENT24)) == 4);
  Context gl(8, 8);
  testing::SolidShader shader;
  auto rect = [&](float z_steps, float x0, float x1) { DepthRect(gl, shader, z_steps, x0, x1); };
  // RGBA8 colour takes the vector operations, RGBA16F the lane-by-lane ones.
  for (const auto& [samples, colour] : {std::pair{1, RGBA8}, std::pair{4, RGBA8}, std::pair{1, RGBA16F},
                                        std::pair{4, RGBA16F}}) {
    INFO(samples << " samples, colour format " << colour);
    const std::uint32_t fbo = gl.GenFramebuffer(), rb[2] = {gl.GenRenderbuffer(), gl.GenRenderbuffer()};
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.BindRenderbuffer(RENDERBUFFER, rb[0]);
    gl.RenderbufferStorageMultisample(RENDERBUFFER, samples == 1 ? 0 : samples, colour, 8, 8);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb[0]);
    gl.BindRenderbuffer(RENDERBUFFER, rb[1]);
    gl.RenderbufferStorageMultisample(RENDERBUFFER, samples == 1 ? 0 : samples, DEPTH_COMPONENT16, 8, 8);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, rb[1]);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    gl.Viewport(0, 0, 8, 8);
    gl.ClearColor(0, 0, 0, 1);
    gl.ClearDepth(20000.25 / 65535.0);  // kept as 20000
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.Enable(DEPTH_TEST);
    gl.DepthFunc(LESS);
    shader.color = glm::vec4(1, 0, 0, 1);
    rect(19999.6f, 0, 4);  // 20000 too: not less, draws nothing (a float buffer would take it)
    rect(19999.4f, 4, 8);  // 19999: less
    gl.DepthFunc(EQUAL);
    shader.color = glm::vec4(0, 1, 0, 1);
    rect(20000.3f, 0, 2);  // 20000: equal to the clear
    gl.Disable(DEPTH_TEST);
    // Read back single-sampled (resolved through a blit into a 16-bit depth buffer).
    std::uint32_t read = fbo;
    if (samples > 1) {
      read = gl.GenFramebuffer();
      const std::uint32_t single[2] = {gl.GenRenderbuffer(), gl.GenRenderbuffer()};
      gl.BindFramebuffer(FRAMEBUFFER, read);
      gl.BindRenderbuffer(RENDERBUFFER, single[0]);
      gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 8, 8);
      gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, single[0]);
      gl.BindRenderbuffer(RENDERBUFFER, single[1]);
      gl.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT16, 8, 8);
      gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, single[1]);
      gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
      gl.BindFramebuffer(DRAW_FRAMEBUFFER, read);
      gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT, NEAREST);
      gl.BindFramebuffer(FRAMEBUFFER, read);
    }
    CHECK(gl.GetError() == NO_ERROR);
    std::uint8_t px[4];
    gl.ReadPixel(1, 3, px);
    CHECK((px[0] == 0 && px[1] == 255));  // the EQUAL pass
    gl.ReadPixel(3, 3, px);
    CHECK((px[0] == 0 && px[1] == 0));  // the LESS rectangle that converts to the stored value
    gl.ReadPixel(6, 3, px);
    CHECK((px[0] == 255 && px[1] == 0));
    CHECK(gl.ReadDepth(3, 3) == 20000.0f / 65535.0f);
    CHECK(gl.ReadDepth(6, 3) == 19999.0f / 65535.0f);
    std::uint16_t words[2];
    gl.ReadPixels(5, 2, 2, 1, DEPTH_COMPONENT, UNSIGNED_SHORT, words);
    CHECK(words[0] == 19999);
    CHECK(words[1] == 19999);
    gl.BindFramebuffer(FRAMEBUFFER, 0);
  }
}

TEST_CASE("a DEPTH_COMPONENT16 texture takes depth data, renders depth and reads it back in 16 bits",
          "[framebuffer]") {
  Context gl(4, 4);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  const float data[4] = {0.0f, 0.25f, 0.5f + 0.4f / 65535.0f, 1.0f};
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT16, 2, 2, 0, DEPTH_COMPONENT, FLOAT, data);
  std::uint16_t back[4];
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_COMPONENT, UNSIGNED_SHORT, back);
  CHECK(back[0] == 0);
  CHECK(back[1] == 16384);  // 0.25 * 65535 = 16383.75
  CHECK(back[2] == 32768);  // 32767.9
  CHECK(back[3] == 65535);
  // Attached as the depth buffer: a clear and a draw store 16-bit values, which CopyTexSubImage2D copies on.
  const std::uint32_t fbo = gl.GenFramebuffer(), colour = gl.GenRenderbuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.BindRenderbuffer(RENDERBUFFER, colour);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 2, 2);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, colour);
  gl.FramebufferTexture2D(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, tex, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.ClearDepth(0.75);
  gl.Clear(DEPTH_BUFFER_BIT);
  gl.Finish();
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_COMPONENT, UNSIGNED_SHORT, back);
  for (std::uint16_t v : back) CHECK(v == 49151);  // 49151.25
  CHECK(gl.ReadDepth(0, 0) == 49151.0f / 65535.0f);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("Options::depth_format DEPTH_COMPONENT16 gives the context's framebuffer a 16-bit depth buffer",
          "[framebuffer]") {
  for (const int samples : {0, 4}) {
    INFO(samples << " samples");
    Context::Options options;
    options.depth_format = DEPTH_COMPONENT16;
    options.samples = samples;
    Context gl(8, 8, options);
    CHECK(gl.GetError() == NO_ERROR);
    testing::SolidShader shader;
    auto rect = [&](float z_steps, float x0, float x1) { DepthRect(gl, shader, z_steps, x0, x1); };
    gl.Enable(DEPTH_TEST);
    gl.ClearColor(0, 0, 0, 1);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    shader.color = glm::vec4(1, 0, 0, 1);
    rect(40000.2f, 0, 8);  // stored as 40000
    shader.color = glm::vec4(0, 1, 0, 1);
    rect(39999.7f, 0, 4);  // 40000 again: not LESS
    rect(39999.4f, 4, 8);  // 39999: LESS
    std::uint8_t px[4];
    gl.ReadPixel(1, 1, px);
    CHECK((px[0] == 255 && px[1] == 0));
    gl.ReadPixel(6, 1, px);
    CHECK((px[0] == 0 && px[1] == 255));
    CHECK(gl.ReadDepth(1, 1) == 40000.0f / 65535.0f);
    CHECK(gl.ReadDepth(6, 1) == 39999.0f / 65535.0f);
    // A framebuffer object of DEPTH_COMPONENT16 takes a depth blit from it (same format); DEPTH_COMPONENT24 does not.
    const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer(), colour = gl.GenRenderbuffer();
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, fbo);
    gl.BindRenderbuffer(RENDERBUFFER, colour);
    gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 8, 8);
    gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, colour);
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT16, 8, 8);
    gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, rb);
    gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, DEPTH_BUFFER_BIT, NEAREST);
    CHECK(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
    CHECK(gl.ReadDepth(6, 1) == 39999.0f / 65535.0f);
    gl.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT24, 8, 8);
    gl.BindFramebuffer(READ_FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, DEPTH_BUFFER_BIT, NEAREST);
    CHECK(gl.GetError() == INVALID_OPERATION);
  }
  Context::Options bad;
  bad.depth_format = RGBA8;
  Context gl(4, 4, bad);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.Clear(DEPTH_BUFFER_BIT);
  CHECK(gl.ReadDepth(0, 0) == 1.0f);
}

TEST_CASE("SampleTiles: a deferred clear fills the resolve without its samples until stored", "[framebuffer][multisample]") {
  detail::Framebuffer fb;
  fb.samples = 4;
  REQUIRE(fb.Allocate(100, 70));  // 2 x 2 tiles of 64
  detail::SampleTiles& tiles = fb.sample_tiles;
  REQUIRE(tiles.tiles.size() == 4);
  CHECK(tiles.TileRect(3, 100, 70).x0 == 64);
  CHECK(tiles.TileRect(3, 100, 70).y1 == 70);
  const detail::RenderTarget t = fb.FrameTarget();
  CHECK(t.tiles == &tiles);
  CHECK(fb.Target().tiles == nullptr);
  // The samples as they are (side by side: sample s of pixel (x, y) at (y 100 + x) 4 + s).
  auto sample = [&](int s) { return fb.Samples(false).Sample(s); };
  auto sample_red = [&](int x, int y, int s) { return sample(s).color[0].At(x, y)[0]; };
  const std::size_t pitch = std::size_t(t.color[0].pitch);
  CHECK(pitch >= 400);
  CHECK(&fb.color[(66 * pitch + 80 * 4 + 3) * 4] == sample(3).color[0].At(80, 66));

  tiles.NoteColor(t, 3, glm::vec4(1, 0, 0, 1));
  tiles.NoteDepth(3, 0.5f);
  tiles.NoteStencil(3, 7);
  tiles.tiles[3].stale = detail::kAllBuffers;
  detail::RenderTarget read = fb.ReadTarget(false, detail::kColorBit);
  CHECK(read.color[0].At(80, 66)[0] == 255);
  CHECK(read.color[0].At(10, 10)[0] == 0);
  CHECK(sample_red(80, 66, 3) == 0);  // the samples are not written
  CHECK(tiles.tiles[3].stale == (detail::kDepthBit | detail::kStencilBit));
  read = fb.ReadTarget();
  CHECK(read.DepthAt(80, 66) == 0.5f);
  CHECK(read.Stencil(80, 66) == 7);
  CHECK(tiles.tiles[3].stale == 0);

  tiles.Store(t, 3, detail::kColorBit);
  for (int s = 0; s < 4; ++s) CHECK(sample_red(99, 69, s) == 255);
  CHECK(sample_red(63, 69, 0) == 0);  // another tile
  CHECK(tiles.tiles[3].cleared == (detail::kDepthBit | detail::kStencilBit));
  CHECK(sample(2).DepthAt(80, 66) == 1.0f);
  // Target stores every deferred clear, and takes the whole resolved image as out of date.
  fb.Target();
  CHECK(sample(2).DepthAt(80, 66) == 0.5f);
  CHECK(sample(3).Stencil(80, 66) == 7);
  CHECK(fb.stencil[66 * pitch + 80 * 4 + 3] == 7);
  for (const detail::SampleTiles::Tile& tile : tiles.tiles) {
    CHECK(tile.cleared == 0);
    CHECK(tile.stale == detail::kAllBuffers);
  }
}

namespace {

// Every colour buffer format: its layout, whether alpha is not stored (RGB8, SRGB8), whether sRGB is on.
struct ColourFormat {
  detail::TexelLayout layout;
  bool rgb_only = false, srgb = false;
};
using L = detail::TexelLayout;
const ColourFormat kColourFormats[] = {
    {L::kUnorm8x4},  {L::kUnorm8x4, true},  {L::kUnorm8x2},  {L::kUnorm8x1},  {L::kUnorm8x4, false, true},
    {L::kUnorm8x4, true, true},  {L::kFloat32x4},  {L::kFloat32x2},  {L::kFloat32x1},  {L::kFloat16x4},
    {L::kFloat16x2},  {L::kFloat16x1},  {L::kFloat11x11x10},  {L::kUnorm565},  {L::kUnorm4444},  {L::kUnorm5551},
    {L::kUnorm1010102},  {L::kUnorm16x4},  {L::kUnorm16x2},  {L::kUnorm16x1}};

// Makes t a w x h single-sampled target whose colour buffer 0 has format f, rows `pitch` texels apart, its bytes
// in `bytes` (resized, zero).
detail::ColorBuffer& ColourTarget(detail::RenderTarget& t, const ColourFormat& f, int w, int h, int pitch,
                                  std::vector<std::uint8_t>& bytes) {
  t.width = w;
  t.height = h;
  detail::ColorBuffer& cb = t.color[0];
  cb.layout = f.layout;
  cb.rgb_only = f.rgb_only;
  cb.srgb = f.srgb;
  cb.pitch = pitch;
  bytes.assign(std::size_t(pitch) * std::size_t(h) * std::size_t(cb.Bytes()), 0);
  cb.data = bytes.data();
  return cb;
}

}  // namespace

TEST_CASE("ClearColor of every colour format: the texel Store writes, through the colour mask, inside the rectangle",
          "[framebuffer][formats]") {
  using detail::TexelLayout;
  const auto& formats = kColourFormats;
  const float specials[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e30f, -1e30f, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(), 3e-5f, 65504.0f, 0.2f};
  std::uint32_t seed = 7;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  auto random_value = [&] {
    const std::uint32_t r = next();
    return (r & 3u) == 0 ? specials[(r >> 2) % std::size(specials)] : float(int(r >> 8) % 4001 - 1000) / 1000.0f;
  };
  int compared = 0;
  for (int round = 0; round < 400; ++round) {
    const ColourFormat& f = formats[std::size_t(round) % std::size(formats)];
    const int w = 1 + int(next() % 37), h = 1 + int(next() % 5);
    detail::RenderTarget t;
    std::vector<std::uint8_t> bytes;
    detail::ColorBuffer& cb = ColourTarget(t, f, w, h, w + int(next() % 3), bytes);
    // Texels as Store leaves them (random colours), so that the reference's re-encoding of the kept channels
    // keeps their bits.
    const bool all[4] = {true, true, true, true};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        cb.Store(x, y, glm::vec4(random_value(), random_value(), random_value(), random_value()), all);
    std::vector<std::uint8_t> expected = bytes;
    const std::uint32_t m = next();
    const bool mask[4] = {(m & 1u) != 0, (m & 2u) != 0, (m & 4u) != 0, (m & 8u) != 0 || (m & 16u) != 0};
    const glm::vec4 value(random_value(), random_value(), random_value(), random_value());
    detail::Rect r;
    r.x0 = int(next() % std::uint32_t(w));
    r.x1 = r.x0 + 1 + int(next() % std::uint32_t(w - r.x0));
    r.y0 = int(next() % std::uint32_t(h));
    r.y1 = r.y0 + 1 + int(next() % std::uint32_t(h - r.y0));
    if (round % 4 == 0) r = detail::Rect{0, 0, w, h};
    detail::ColorBuffer reference = cb;
    reference.data = expected.data();
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) reference.Store(x, y, value, mask);
    t.ClearColor(r, value, mask);
    INFO("round " << round << ", layout " << int(f.layout) << ", " << w << " x " << h << ", mask " << (m & 15u));
    CHECK(bytes == expected);
    ++compared;
  }
  CHECK(compared == 400);
}

TEST_CASE("resolving by rows gives LoadResolved's bytes in every colour format", "[framebuffer][multisample][formats]") {
  using detail::TexelLayout;
  const auto& formats = kColourFormats;
  constexpr int kFormats = int(std::size(formats));
  std::uint32_t seed = 11;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  int compared = 0;
  for (int round = 0; round < kFormats * 6; ++round) {
    const ColourFormat& f = formats[round % kFormats];
    const TexelLayout layout = f.layout;
    const int samples = 2 << (round / kFormats % 3);        // 2, 4, 8
    const bool interleaved = (round / (3 * kFormats)) == 1;  // samples side by side, or planes
    const int w = 1 + int(next() % 40), h = 1 + int(next() % 6);
    detail::RenderTarget src;
    src.width = w;
    src.height = h;
    src.samples = samples;
    src.interleaved = interleaved;
    detail::ColorBuffer& in = src.color[0];
    in.layout = layout;
    in.rgb_only = f.rgb_only;
    in.srgb = f.srgb;
    in.pitch = interleaved ? w * samples : w;
    in.step = interleaved ? samples : 1;
    in.plane = interleaved ? 1 : std::size_t(w) * std::size_t(h);
    const std::size_t bytes = std::size_t(in.Bytes());
    std::vector<std::uint8_t> texels(std::size_t(w) * std::size_t(h) * std::size_t(samples) * bytes);
    for (std::uint8_t& b : texels) b = std::uint8_t(next() >> 24);
    // A few texels of all-0 and all-1 bits.
    for (std::size_t i = 0; i + bytes <= texels.size(); i += bytes * 7) std::memset(&texels[i], (i / bytes) % 2 ? 0xFF : 0, bytes);
    // No NaN among the float inputs: which of two NaNs' payloads a sum keeps depends on the order the compiler gives
    // the operands (OpenGL leaves NaN's bits open). Infinities stay.
    auto no_nan = [&](std::size_t at, int bits, int exponent_shift, std::uint32_t exponent, std::uint32_t mantissa) {
      std::uint32_t v = 0;
      std::memcpy(&v, &texels[at], std::size_t(bits / 8));
      if (((v >> exponent_shift) & exponent) == exponent && (v & mantissa) != 0) v &= ~mantissa;
      std::memcpy(&texels[at], &v, std::size_t(bits / 8));
    };
    for (std::size_t i = 0; i < texels.size(); i += 4) {
      if (layout == TexelLayout::kFloat32x4 || layout == TexelLayout::kFloat32x2 || layout == TexelLayout::kFloat32x1)
        no_nan(i, 32, 23, 0xFFu, 0x7FFFFFu);
      if (layout == TexelLayout::kFloat16x4 || layout == TexelLayout::kFloat16x2 || layout == TexelLayout::kFloat16x1) {
        no_nan(i, 16, 10, 0x1Fu, 0x3FFu);
        no_nan(i + 2, 16, 10, 0x1Fu, 0x3FFu);
      }
      if (layout == TexelLayout::kFloat11x11x10) {
        std::uint32_t w;
        std::memcpy(&w, &texels[i], 4);
        const int shift[3] = {0, 11, 22}, mantissa[3] = {6, 6, 5};
        for (int c = 0; c < 3; ++c) {
          const std::uint32_t e = (w >> (shift[c] + mantissa[c])) & 0x1Fu, m = (w >> shift[c]) & ((1u << mantissa[c]) - 1u);
          if (e == 0x1Fu && m != 0) w &= ~(((1u << mantissa[c]) - 1u) << shift[c]);
        }
        std::memcpy(&texels[i], &w, 4);
      }
    }
    in.data = texels.data();
    detail::RenderTarget dst;
    std::vector<std::uint8_t> result;
    detail::ColorBuffer& out = ColourTarget(dst, f, w, h, w, result);
    std::vector<std::uint8_t> expected = result;
    detail::ColorBuffer reference = out;
    reference.data = expected.data();
    const bool all[4] = {true, true, true, true};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) reference.Store(x, y, detail::LoadResolved(in, samples, x, y), all);
    detail::BlitRegion region;
    region.src[2] = region.dst[2] = w;
    region.src[3] = region.dst[3] = h;
    region.clip = detail::Rect{0, 0, w, h};
    region.color = true;
    detail::Blit(src, dst, region);
    INFO("round " << round << ", layout " << int(layout) << (f.srgb ? " sRGB" : "") << (f.rgb_only ? " RGB" : "") << ", "
                  << samples << " samples, "
                  << (interleaved ? "interleaved" : "planes") << ", " << w << " x " << h);
    CHECK(result == expected);
    ++compared;
  }
  CHECK(compared == kFormats * 6);
}

TEST_CASE("same-size NEAREST blits between buffers of one format give Load and Store's bytes, offset and clipped",
          "[framebuffer][formats]") {
  std::uint32_t seed = 5;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  const int kFormats = int(std::size(kColourFormats));
  for (int round = 0; round < kFormats * 4; ++round) {
    const ColourFormat& f = kColourFormats[round % kFormats];
    const int w = 1 + int(next() % 30), h = 1 + int(next() % 6);
    auto buffer = [&](detail::RenderTarget& t, std::vector<std::uint8_t>& bytes, std::vector<float>& depth,
                      std::vector<std::uint8_t>& stencil) {
      detail::ColorBuffer& cb = ColourTarget(t, f, w, h, w, bytes);
      const bool all[4] = {true, true, true, true};
      for (int y = 0; y < h; ++y)  // values as Store leaves them (no NaN payloads: Store makes them canonical)
        for (int x = 0; x < w; ++x)
          cb.Store(x, y, glm::vec4(float(int(next() % 2001) - 500) / 1000.0f, float(next() % 1000) / 999.0f,
                                   float(int(next() % 5) - 1) * 0.75f, float(next() % 256) / 255.0f), all);
      depth.resize(std::size_t(w) * std::size_t(h));
      for (float& d : depth) d = float(next() % 1000) / 999.0f;
      stencil.resize(depth.size());
      for (std::uint8_t& v : stencil) v = std::uint8_t(next());
      t.depth = depth.data();
      t.depth_pitch = w;
      t.stencil = stencil.data();
      t.stencil_pitch = w;
    };
    detail::RenderTarget src, dst, ref;
    std::vector<std::uint8_t> src_bytes, dst_bytes, ref_bytes, src_st, dst_st, ref_st;
    std::vector<float> src_d, dst_d, ref_d;
    buffer(src, src_bytes, src_d, src_st);
    buffer(dst, dst_bytes, dst_d, dst_st);
    ref = dst;
    ref_bytes = dst_bytes;
    ref_d = dst_d;
    ref_st = dst_st;
    ref.color[0].data = ref_bytes.data();
    ref.depth = ref_d.data();
    ref.stencil = ref_st.data();
    // A rectangle of the source onto one of the same size elsewhere, the offset up to the size either way, clipped.
    const int sw = 1 + int(next() % std::uint32_t(w)), sh = 1 + int(next() % std::uint32_t(h));
    const int sx = int(next() % std::uint32_t(w)) - 2, sy = int(next() % std::uint32_t(h)) - 1;
    const int tx = int(next() % std::uint32_t(w)) - 3, ty = int(next() % std::uint32_t(h)) - 1;
    detail::BlitRegion region;
    region.src[0] = sx, region.src[1] = sy, region.src[2] = sx + sw, region.src[3] = sy + sh;
    region.dst[0] = tx, region.dst[1] = ty, region.dst[2] = tx + sw, region.dst[3] = ty + sh;
    region.clip = detail::Rect{int(next() % 3), 0, w - int(next() % 3), h};
    region.color = true;
    region.depth = round % 2 == 0;
    region.stencil = round % 3 == 0;
    const bool all[4] = {true, true, true, true};
    for (int y = std::max({ty, region.clip.y0, 0}); y < std::min({ty + sh, region.clip.y1, h}); ++y)
      for (int x = std::max({tx, region.clip.x0, 0}); x < std::min({tx + sw, region.clip.x1, w}); ++x) {
        const int px = x - tx + sx, py = y - ty + sy;
        if (px < 0 || py < 0 || px >= w || py >= h) continue;
        ref.color[0].Store(x, y, src.color[0].Load(px, py), all);
        if (region.depth) ref.SetDepth(x, y, ref.StoredDepth(src.DepthAt(px, py)));
        if (region.stencil) ref.Stencil(x, y) = src.Stencil(px, py);
      }
    detail::Blit(src, dst, region);
    INFO("round " << round << ", layout " << int(f.layout) << (f.srgb ? " sRGB" : "") << (f.rgb_only ? " RGB" : "")
                  << ", " << w << " x " << h << ", from " << sx << ", " << sy << " to " << tx << ", " << ty);
    CHECK(dst_bytes == ref_bytes);
    CHECK(dst_d == ref_d);
    CHECK(dst_st == ref_st);
  }
}

TEST_CASE("scaled, mirrored, LINEAR and cross-format blits give Load and Store's values pixel by pixel",
          "[framebuffer][formats]") {
  // The reference is BlitFramebuffer's definition pixel by pixel (OpenGL 4.6, section 18.3.1), through Load (or
  // LoadResolved) and Store: each destination centre mapped into the source, NEAREST the pixel holding the point,
  // LINEAR the mix of the four nearest centres clamped to the edge, points outside the source not written.
  std::uint32_t seed = 17;
  auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  const int kFormats = int(std::size(kColourFormats));
  int compared = 0, written = 0;
  for (int round = 0; round < kFormats * 12; ++round) {
    const ColourFormat& fs = kColourFormats[round % kFormats];
    // Every third round into the same format (the texel copy where it applies), else into another: 12 of the
    // formats for each source format.
    const ColourFormat& fd = round % 3 == 0 ? fs : kColourFormats[(round / kFormats + 7 * round) % kFormats];
    const bool resolve = round % 5 == 4;  // a 4-sample source, mirrored onto a rectangle of the same size
    const bool linear = !resolve && round % 2 == 1;
    const int samples = resolve ? 4 : 1;
    const int ws = 1 + int(next() % 40), hs = 1 + int(next() % 12), wd = 1 + int(next() % 40), hd = 1 + int(next() % 12);
    const bool all[4] = {true, true, true, true};
    // The source: `samples` planes of ws x hs, values as Store leaves them (finite: no NaN whose payload the order
    // of a LINEAR mix's operations would choose).
    detail::RenderTarget src;
    std::vector<std::uint8_t> src_bytes;
    detail::ColorBuffer& in = ColourTarget(src, fs, ws, hs, ws, src_bytes);
    src_bytes.resize(src_bytes.size() * std::size_t(samples));
    in.data = src_bytes.data();
    in.plane = std::size_t(ws) * std::size_t(hs);
    src.samples = samples;
    std::vector<float> src_d(in.plane * std::size_t(samples));
    std::vector<std::uint8_t> src_st(src_d.size());
    for (float& d : src_d) d = float(next() % 1000) / 999.0f;
    for (std::uint8_t& v : src_st) v = std::uint8_t(next());
    src.depth = src_d.data();
    src.depth_pitch = ws;
    src.depth_plane = in.plane;
    src.stencil = src_st.data();
    src.stencil_pitch = ws;
    src.stencil_plane = in.plane;
    for (int s = 0; s < samples; ++s)
      for (int y = 0; y < hs; ++y)
        for (int x = 0; x < ws; ++x)
          src.Sample(s).color[0].Store(x, y, glm::vec4(float(int(next() % 2001) - 500) / 1000.0f, float(next() % 1000) / 999.0f,
                                                       float(int(next() % 5) - 1) * 0.75f, float(next() % 256) / 255.0f),
                                       all);
    // The destination and its reference copy, starting from the same bytes.
    detail::RenderTarget dst;
    std::vector<std::uint8_t> dst_bytes;
    ColourTarget(dst, fd, wd, hd, wd + int(next() % 3), dst_bytes);
    for (std::uint8_t& b : dst_bytes) b = std::uint8_t(next() >> 24);
    std::vector<float> dst_d(std::size_t(wd) * std::size_t(hd));
    std::vector<std::uint8_t> dst_st(dst_d.size());
    for (float& d : dst_d) d = float(next() % 1000) / 999.0f;
    dst.depth = dst_d.data();
    dst.depth_pitch = wd;
    dst.stencil = dst_st.data();
    dst.stencil_pitch = wd;
    std::vector<std::uint8_t> ref_bytes = dst_bytes, ref_st = dst_st;
    std::vector<float> ref_d = dst_d;
    detail::RenderTarget ref = dst;
    ref.color[0].data = ref_bytes.data();
    ref.depth = ref_d.data();
    ref.stencil = ref_st.data();
    // Rectangles reaching past both buffers by up to 3 pixels, either reversed; a resolve's of the same size.
    detail::BlitRegion region;
    auto corners = [&](int size, int& a, int& b) {
      a = int(next() % std::uint32_t(size / 2 + 4)) - 3;
      b = size / 2 + int(next() % std::uint32_t(size / 2 + 4));
      if (next() % 2) std::swap(a, b);
    };
    for (int k = 0; k < 2; ++k) {
      corners(k ? hs : ws, region.src[k], region.src[k + 2]);
      corners(k ? hd : wd, region.dst[k], region.dst[k + 2]);
      if (resolve) region.dst[k + 2] = region.dst[k] + region.src[k] - region.src[k + 2];
    }
    region.clip = detail::Rect{int(next() % 3), int(next() % 2), wd - int(next() % 3), hd};
    region.color = true;
    region.linear = linear;
    region.depth = !linear && round % 4 == 0;
    region.stencil = !linear && round % 4 == 2;
    auto axis = [](int s0, int s1, int e0, int e1, int c0, int c1, int& d0, int& d1, double& scale) {
      scale = (double(s1) - double(s0)) / (double(e1) - double(e0));
      d0 = std::max(std::min(e0, e1), c0);
      d1 = std::min(std::max(e0, e1), c1);
    };
    int x0, x1, y0, y1;
    double scale_x, scale_y;
    axis(region.src[0], region.src[2], region.dst[0], region.dst[2], std::max(region.clip.x0, 0),
         std::min(region.clip.x1, wd), x0, x1, scale_x);
    axis(region.src[1], region.src[3], region.dst[1], region.dst[3], std::max(region.clip.y0, 0),
         std::min(region.clip.y1, hd), y0, y1, scale_y);
    const bool empty = region.src[0] == region.src[2] || region.src[1] == region.src[3] ||
                       region.dst[0] == region.dst[2] || region.dst[1] == region.dst[3];
    for (int y = y0; y < y1 && !empty; ++y)
      for (int x = x0; x < x1; ++x) {
        const double sx = region.src[0] + (double(x) + 0.5 - region.dst[0]) * scale_x;
        const double sy = region.src[1] + (double(y) + 0.5 - region.dst[1]) * scale_y;
        if (!(sx >= 0.0 && sx < ws && sy >= 0.0 && sy < hs)) continue;
        const int px = int(sx), py = int(sy);
        glm::vec4 c;
        if (linear) {
          const double u = sx - 0.5, v = sy - 0.5;
          const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
          const float a = float(u - i0), b = float(v - j0);
          const int i1 = std::min(i0 + 1, ws - 1), j1 = std::min(j0 + 1, hs - 1), ic = std::max(i0, 0),
                    jc = std::max(j0, 0);
          c = (1.0f - b) * ((1.0f - a) * in.Load(ic, jc) + a * in.Load(i1, jc)) +
              b * ((1.0f - a) * in.Load(ic, j1) + a * in.Load(i1, j1));
        } else {
          c = samples > 1 ? detail::LoadResolved(in, samples, px, py) : in.Load(px, py);
        }
        ref.color[0].Store(x, y, c, all);
        if (region.depth) ref.SetDepth(x, y, ref.StoredDepth(src.DepthAt(px, py)));
        if (region.stencil) ref.Stencil(x, y) = src.Stencil(px, py);
        ++written;
      }
    detail::Blit(src, dst, region);
    INFO("round " << round << ", layout " << int(fs.layout) << (fs.srgb ? " sRGB" : "") << (fs.rgb_only ? " RGB" : "")
                  << " into " << int(fd.layout) << (fd.srgb ? " sRGB" : "") << (fd.rgb_only ? " RGB" : "") << ", "
                  << (linear ? "LINEAR" : "NEAREST") << ", " << samples << " samples, " << ws << " x " << hs << " ("
                  << region.src[0] << ", " << region.src[1] << ", " << region.src[2] << ", " << region.src[3] << ") to "
                  << wd << " x " << hd << " (" << region.dst[0] << ", " << region.dst[1] << ", " << region.dst[2] << ", "
                  << region.dst[3] << ")");
    const bool same_colour = dst_bytes == ref_bytes, same_depth = dst_d == ref_d, same_stencil = dst_st == ref_st;
    CHECK(same_colour);
    CHECK(same_depth);
    CHECK(same_stencil);
    ++compared;
  }
  CHECK(compared == kFormats * 12);
  CHECK(written > 5000);  // (the rectangles are not mostly empty)
}

TEST_CASE("a 4-sample framebuffer object blitted into the 4-sample context framebuffer keeps each sample",
          "[framebuffer][multisample]") {
  // Sample s goes to sample s (the context's samples side by side, the object's in planes), so the context's
  // resolved image is the object's resolve, which a blit into a single-sampled context gives.
  Image images[2];
  for (const int samples : {0, 4}) {
    Context::Options options;
    options.samples = samples;
    options.threads = 1;
    Context gl(31, 23, options);
    const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, RGBA8, 31, 23);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    gl.ClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    testing::SolidShader shader;
    shader.color = glm::vec4(0.9f, 0.1f, 0.5f, 0.8f);
    gl.UseProgram(shader);
    gl.Viewport(0, 0, 31, 23);
    testing::MakeVertexArray(gl, {{-0.9f, -0.8f, 0, 1}, {0.85f, -0.3f, 0, 1}, {-0.2f, 0.9f, 0, 1}});
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, 31, 23, 0, 0, 31, 23, COLOR_BUFFER_BIT, NEAREST);
    CHECK(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(READ_FRAMEBUFFER, 0);
    images[samples ? 1 : 0] = gl.ReadPixels();
  }
  const bool same = images[0].rgba == images[1].rgba;
  CHECK(same);
  // The triangle's edges hold mixtures: a red neither the clear colour's (51) nor the triangle's (230).
  int mixed = 0;
  for (std::size_t i = 0; i < images[1].rgba.size(); i += 4) mixed += images[1].rgba[i] != 51 && images[1].rgba[i] != 230;
  CHECK(mixed > 10);
}

TEST_CASE("eight draw buffers of mixed formats, mapped in any order, each takes its output in one draw",
          "[framebuffer][formats]") {
  // Output o is (o / 8, 1 - o / 8, 0.25, 1); draw buffer o goes to attachment 7 - o, whose format is formats[7 - o];
  // draw buffer 5 is NONE (its attachment keeps the clear colour, cleared before with all eight as draw buffers).
  struct Eight : softgl::Shader<Eight, testing::NoVaryings> {
    void Vertex(const VertexLanes& in, VertexLanesOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
    void Fragment(const FragmentLanes<testing::NoVaryings>&, FragmentLanesOut& out) const {
      for (int o = 0; o < kMaxColorOutputs; ++o)
        out.color[o] = vec4(Float(float(o) / 8.0f), Float(1.0f - float(o) / 8.0f), Float(0.25f), Float(1.0f));
    }
  } shader;
  const Enum formats[8] = {RGBA8, RGBA16F, R32F, RGB565, RG8, SRGB8_ALPHA8, RGBA32F, R11F_G11F_B10F};
  Context gl(1, 1);
  gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
  for (int a = 0; a < 8; ++a) {
    const std::uint32_t rb = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, formats[a], 8, 8);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(a), RENDERBUFFER, rb);
  }
  CHECK(gl.GetError() == NO_ERROR);
  Enum bufs[8];
  for (int o = 0; o < 8; ++o) bufs[o] = COLOR_ATTACHMENT0 + Enum(o);
  gl.DrawBuffers(8, bufs);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.ClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  gl.Clear(COLOR_BUFFER_BIT);
  for (int o = 0; o < 8; ++o) bufs[o] = o == 5 ? NONE : COLOR_ATTACHMENT0 + Enum(7 - o);
  gl.DrawBuffers(8, bufs);
  std::int32_t got = 0;
  gl.GetIntegerv(DRAW_BUFFER0 + 7, &got);
  CHECK(Enum(got) == COLOR_ATTACHMENT0);
  gl.Viewport(0, 0, 8, 8);
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == NO_ERROR);
  for (int a = 0; a < 8; ++a) {
    const int o = 7 - a;  // the output drawn into attachment a
    gl.ReadBuffer(COLOR_ATTACHMENT0 + Enum(a));
    std::vector<float> px(8 * 8 * 4);
    gl.ReadPixels(0, 0, 8, 8, RGBA, FLOAT, px.data());
    CHECK(gl.GetError() == NO_ERROR);
    const glm::vec4 want = o == 5 ? glm::vec4(0.5f) : glm::vec4(float(o) / 8.0f, 1.0f - float(o) / 8.0f, 0.25f, 1.0f);
    const int channels = formats[a] == R32F ? 1 : formats[a] == RG8 ? 2 : formats[a] == RGB565 || formats[a] == R11F_G11F_B10F ? 3 : 4;
    for (int i = 0; i < 64; ++i)
      for (int c = 0; c < channels; ++c) {
        INFO("attachment " << a << " pixel " << i << " channel " << c);
        CHECK(px[std::size_t(4 * i + c)] == Approx(want[c]).margin(0.02));  // (RGB565's 5 bits: within 1/62)
      }
  }
}

TEST_CASE("ColorMaski and Enablei: each draw buffer its own colour mask and blending, in draws and clears",
          "[framebuffer][formats]") {
  // Four attachments (RGBA8, RGBA16F, RGBA32F, RGBA8) as draw buffers 0 to 3; every output (0.8, 0.6, 0.4, 0.5).
  struct Four : softgl::Shader<Four, testing::NoVaryings> {
    void Vertex(const VertexLanes& in, VertexLanesOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
    void Fragment(const FragmentLanes<testing::NoVaryings>&, FragmentLanesOut& out) const {
      for (int o = 0; o < 4; ++o) out.color[o] = vec4(Float(0.8f), Float(0.6f), Float(0.4f), Float(0.5f));
    }
  } shader;
  const Enum formats[4] = {RGBA8, RGBA16F, RGBA32F, RGBA8};
  for (int threads : {1, 3}) {
    INFO(threads << " threads");
    Context gl(1, 1, Context::Options{threads});
    gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
    Enum bufs[4];
    for (int a = 0; a < 4; ++a) {
      const std::uint32_t rb = gl.GenRenderbuffer();
      gl.BindRenderbuffer(RENDERBUFFER, rb);
      gl.RenderbufferStorage(RENDERBUFFER, formats[a], 8, 8);
      gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(a), RENDERBUFFER, rb);
      bufs[a] = COLOR_ATTACHMENT0 + Enum(a);
    }
    gl.DrawBuffers(4, bufs);
    gl.Viewport(0, 0, 8, 8);
    gl.ClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    // Clear through four masks: buffer 0 all, 1 red, 2 green and alpha, 3 nothing.
    gl.ColorMaski(1, true, false, false, false);
    gl.ColorMaski(2, false, true, false, true);
    gl.ColorMaski(3, false, false, false, false);
    gl.ClearColor(1.0f, 1.0f, 1.0f, 0.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    const auto read = [&](int a) {
      gl.ReadBuffer(COLOR_ATTACHMENT0 + Enum(a));
      float px[4];
      gl.ReadPixels(3, 3, 1, 1, RGBA, FLOAT, px);
      return glm::vec4(px[0], px[1], px[2], px[3]);
    };
    const auto near = [](glm::vec4 a, glm::vec4 b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec4(0.003f))); };
    CHECK(near(read(0), glm::vec4(1, 1, 1, 0)));
    CHECK(near(read(1), glm::vec4(1, 0.2f, 0.2f, 1)));
    CHECK(near(read(2), glm::vec4(0.2f, 1, 0.2f, 0)));
    CHECK(near(read(3), glm::vec4(0.2f, 0.2f, 0.2f, 1)));
    // A draw: blending (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) on for buffers 1 and 3 only; masks: 0 all, 1 red and green,
    // 2 blue, 3 all.
    gl.ColorMask(true, true, true, true);
    gl.ColorMaski(1, true, true, false, false);
    gl.ColorMaski(2, false, false, true, false);
    gl.Enablei(BLEND, 1);
    gl.Enablei(BLEND, 3);
    gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
    CHECK(gl.IsEnabledi(BLEND, 3));
    CHECK_FALSE(gl.IsEnabledi(BLEND, 2));
    CHECK_FALSE(gl.IsEnabled(BLEND));  // (draw buffer 0's)
    gl.UseProgram(shader);
    testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
    gl.DrawArrays(TRIANGLES, 0, 3);
    CHECK(gl.GetError() == NO_ERROR);
    const glm::vec4 src(0.8f, 0.6f, 0.4f, 0.5f);
    CHECK(near(read(0), src));                                                   // written whole, not blended
    CHECK(near(read(1), glm::vec4(0.5f * 0.8f + 0.5f * 1.0f, 0.5f * 0.6f + 0.5f * 0.2f, 0.2f, 1)));  // blended, r g
    CHECK(near(read(2), glm::vec4(0.2f, 1, 0.4f, 0)));                           // blue only, not blended
    CHECK(near(read(3), glm::vec4(0.5f * 0.8f + 0.5f * 0.2f, 0.5f * 0.6f + 0.5f * 0.2f, 0.5f * 0.4f + 0.5f * 0.2f,
                                  0.5f * 0.5f + 0.5f * 1.0f)));                  // blended, all channels
    // ClearBuffer goes through its buffer's own mask.
    const float value[4] = {0, 0, 0, 0};
    gl.ClearBufferfv(COLOR, 2, value);
    CHECK(near(read(2), glm::vec4(0.2f, 1, 0, 0)));
    // Enable and ColorMask set every draw buffer's again.
    gl.Enable(BLEND);
    gl.ColorMask(false, true, false, true);
    bool m[4] = {true, false, true, false};
    gl.GetBooleani_v(COLOR_WRITEMASK, 2, m);
    CHECK((!m[0] && m[1] && !m[2] && m[3]));
    CHECK(gl.IsEnabledi(BLEND, 2));
    gl.Disablei(BLEND, 0);
    CHECK_FALSE(gl.IsEnabled(BLEND));
    CHECK(gl.IsEnabledi(BLEND, 7));
    CHECK(gl.GetError() == NO_ERROR);
    // Errors.
    gl.ColorMaski(std::uint32_t(kMaxColorOutputs), true, true, true, true);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.Enablei(BLEND, 8);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.Disablei(DEPTH_TEST, 0);
    CHECK(gl.GetError() == INVALID_ENUM);
    CHECK_FALSE(gl.IsEnabledi(SCISSOR_TEST, 0));
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.GetBooleani_v(COLOR_WRITEMASK, 8, m);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.GetBooleani_v(COLOR_WRITEMASK, 0, nullptr);
    CHECK(gl.GetError() == INVALID_VALUE);
    int iv = 5;
    gl.GetIntegeri_v(DEPTH_FUNC, 0, &iv);
    CHECK(gl.GetError() == INVALID_ENUM);
    std::int64_t lv = 0;
    gl.GetInteger64i_v(SAMPLE_MASK_VALUE, 0, &lv);
    CHECK(lv == -1);  // (all 32 bits, as a GLint)
    gl.GetInteger64i_v(SAMPLE_MASK_VALUE, 1, &lv);
    CHECK(gl.GetError() == INVALID_VALUE);
  }
}

TEST_CASE("ClearBuffer clears one draw buffer, the depth or the stencil, through the masks and the scissor box",
          "[framebuffer][formats]") {
  // Three colour attachments of different formats, draw buffers 0, 1, 2 sent to attachments 2, NONE, 0, and a
  // depth-stencil renderbuffer; each clear is read back from every buffer.
  Context gl(1, 1);
  gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
  const Enum formats[3] = {RGBA8, RGBA16F, R32F};
  for (int a = 0; a < 3; ++a) {
    const std::uint32_t rb = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, formats[a], 8, 8);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(a), RENDERBUFFER, rb);
  }
  const std::uint32_t ds = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, ds);
  gl.RenderbufferStorage(RENDERBUFFER, DEPTH24_STENCIL8, 8, 8);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, ds);
  const Enum all[3] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2};
  gl.DrawBuffers(3, all);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.ClearColor(0.25f, 0.25f, 0.25f, 0.25f);
  gl.ClearDepth(0.75);
  gl.ClearStencil(9);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  const Enum mapped[3] = {COLOR_ATTACHMENT0 + 2, NONE, COLOR_ATTACHMENT0};
  gl.DrawBuffers(3, mapped);
  // The pixel (x, y) of attachment a, as floats.
  auto colour = [&](int a, int x, int y) {
    gl.ReadBuffer(COLOR_ATTACHMENT0 + Enum(a));
    float px[4];
    gl.ReadPixels(x, y, 1, 1, RGBA, FLOAT, px);
    return glm::vec4(px[0], px[1], px[2], px[3]);
  };
  const glm::vec4 before(0.25f, 0.25f, 0.25f, 0.25f), before8(64.0f / 255.0f), before_r(0.25f, 0.0f, 0.0f, 1.0f);

  // Draw buffer 0 (attachment 2, R32F) to a value outside [0, 1]: only there, inside the scissor box.
  gl.Enable(SCISSOR_TEST);
  gl.Scissor(2, 2, 4, 4);
  const float v[4] = {-3.5f, 2.0f, 0.5f, 7.0f};
  gl.ClearBufferfv(COLOR, 0, v);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(colour(2, 3, 3) == glm::vec4(-3.5f, 0.0f, 0.0f, 1.0f));
  CHECK(colour(2, 1, 1) == before_r);
  CHECK(colour(0, 3, 3) == before8);
  CHECK(colour(1, 3, 3) == before);
  gl.Disable(SCISSOR_TEST);
  // Draw buffer 2 (attachment 0, RGBA8) through the colour mask; draw buffer 1 is NONE: nothing changes.
  gl.ColorMask(true, false, true, false);
  const float w[4] = {1.0f, 1.0f, 0.0f, 1.0f};
  gl.ClearBufferfv(COLOR, 2, w);
  gl.ColorMask(true, true, true, true);
  CHECK(colour(0, 7, 7) == glm::vec4(1.0f, 64.0f / 255.0f, 0.0f, 64.0f / 255.0f));
  gl.ClearBufferfv(COLOR, 1, w);
  CHECK(colour(1, 0, 0) == before);
  CHECK(colour(0, 0, 0) == glm::vec4(1.0f, 64.0f / 255.0f, 0.0f, 64.0f / 255.0f));
  CHECK(colour(2, 0, 0) == before_r);
  // Integer colours are taken as floats.
  const int ones[4] = {1, 0, 1, 1};
  gl.ClearBufferiv(COLOR, 2, ones);
  CHECK(colour(0, 4, 4) == glm::vec4(1.0f, 0.0f, 1.0f, 1.0f));
  const std::uint32_t uones[4] = {0, 1, 0, 1};
  gl.ClearBufferuiv(COLOR, 2, uones);
  CHECK(colour(0, 4, 4) == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  CHECK(colour(2, 4, 4) == glm::vec4(-3.5f, 0.0f, 0.0f, 1.0f));

  // Depth (clamped, through DepthMask), stencil (through the front write mask), both at once.
  const float d = 0.25f, big = 5.0f;
  gl.ClearBufferfv(DEPTH, 0, &d);
  CHECK(gl.ReadDepth(4, 4) == Approx(0.25f).margin(1e-6));
  CHECK(int(gl.ReadStencil(4, 4)) == 9);
  gl.DepthMask(false);
  gl.ClearBufferfv(DEPTH, 0, &big);
  CHECK(gl.ReadDepth(4, 4) == Approx(0.25f).margin(1e-6));
  gl.DepthMask(true);
  gl.ClearBufferfv(DEPTH, 0, &big);
  CHECK(gl.ReadDepth(4, 4) == 1.0f);
  gl.StencilMask(0x0F);
  const int st = 0x1F3;
  gl.ClearBufferiv(STENCIL, 0, &st);
  CHECK(int(gl.ReadStencil(4, 4)) == 0x03);  // 9 = 0x09: the low four bits from 0xF3
  gl.StencilMask(0xFF);
  gl.ClearBufferfi(DEPTH_STENCIL, 0, -1.0f, 200);
  CHECK(gl.ReadDepth(4, 4) == 0.0f);
  CHECK(int(gl.ReadStencil(4, 4)) == 200);
  CHECK(colour(0, 4, 4) == glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
  CHECK(gl.GetError() == NO_ERROR);

  // Errors: nothing changes.
  gl.ClearBufferfv(STENCIL, 0, v);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClearBufferiv(DEPTH, 0, ones);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClearBufferuiv(DEPTH, 0, uones);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClearBufferfi(DEPTH, 0, 0.5f, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClearBufferfv(COLOR, kMaxColorOutputs, v);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.ClearBufferfv(COLOR, -1, v);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.ClearBufferfv(DEPTH, 1, v);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.ClearBufferfi(DEPTH_STENCIL, 2, 0.5f, 1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.ClearBufferfv(COLOR, 0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.ClearBufferiv(STENCIL, 0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(gl.ReadDepth(4, 4) == 0.0f);
  CHECK(int(gl.ReadStencil(4, 4)) == 200);
  CHECK(colour(2, 3, 3) == glm::vec4(-3.5f, 0.0f, 0.0f, 1.0f));
  // An incomplete framebuffer object.
  gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
  gl.ClearBufferfv(COLOR, 0, v);
  CHECK(gl.GetError() == INVALID_FRAMEBUFFER_OPERATION);
}

TEST_CASE("ClearBuffer on the context's framebuffer, 1 and 4 samples, sRGB-encoded: the bytes Clear gives",
          "[framebuffer][multisample][srgb]") {
  for (int samples : {0, 4}) {
    for (bool srgb : {false, true}) {
      Context::Options options;
      options.samples = samples;
      if (srgb) options.color_format = SRGB8_ALPHA8;
      Context a(16, 16, options), b(16, 16, options);
      for (Context* gl : {&a, &b}) {
        if (srgb) gl->Enable(FRAMEBUFFER_SRGB);
        gl->Enable(SCISSOR_TEST);
        gl->Scissor(3, 5, 9, 7);
      }
      const float c[4] = {0.2f, 0.4f, 0.6f, 0.8f}, d = 0.3f;
      a.ClearColor(c[0], c[1], c[2], c[3]);
      a.ClearDepth(d);
      a.ClearStencil(77);
      a.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
      b.ClearBufferfv(COLOR, 0, c);
      b.ClearBufferfi(DEPTH_STENCIL, 0, d, 77);
      b.ClearBufferfv(COLOR, 1, c);  // (draw buffer 1 is NONE: nothing)
      CHECK(b.GetError() == NO_ERROR);
      CHECK(a.ReadPixels().rgba == b.ReadPixels().rgba);
      for (int y = 0; y < 16; y += 3)
        for (int x = 0; x < 16; x += 3) {
          CHECK(a.ReadDepth(x, y) == b.ReadDepth(x, y));
          CHECK(a.ReadStencil(x, y) == b.ReadStencil(x, y));
        }
      std::uint8_t px[4];
      b.ReadPixel(6, 8, px);
      CHECK(int(px[1]) > 50);  // (the clear is there)
    }
  }
}

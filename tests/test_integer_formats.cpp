// Integer textures and colour buffers (R8UI ... RGBA32I, RGB10_A2UI): uploads and read-backs clamped as OpenGL
// converts integers (the values Mesa gives), every 32-bit pattern kept exact through sampling and rendering, no
// filtering, no blending, the logic operation and the colour mask, ClearBufferiv / uiv, and the errors of mixing
// integer and non-integer data.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "helpers.h"
#include "texture.h"

using namespace softgl;
using namespace testing;

namespace {

constexpr int kW = 8, kH = 4;
using NoVary = NoVaryings;

// A full-screen pass writing one integer output: the value `value` everywhere (`kind` 0), texture(isampler2D) of
// unit 0 at the pixel's centre scaled by `scale` (1), or texelFetch(isampler2D, (x, y), 0) (2), or
// texelFetch(isamplerBuffer, x + y * kW) (3).
struct IntegerShader : Shader<IntegerShader, NoVary> {
  int kind = 0;
  glm::ivec4 value{0};
  float scale = 1.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVary>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVary>& in, FragmentLanesOut& out) const {
    const Int x(in.frag_coord.x), y(in.frag_coord.y);
    ivec4 v(value);
    if (kind == 1) v = in.ITexture(0, vec2(in.frag_coord.x / float(kW), in.frag_coord.y / float(kH)) * scale);
    if (kind == 2) v = in.ITexelFetch(0, x, y);
    if (kind == 3) v = in.ITexelFetchBuffer(0, x + y * kW);
    out.SetColorI(0, v);
  }
};

// A kW x kH context drawing into a renderbuffer of `format`, bound, with a full-screen strip and an IntegerShader.
struct IntegerTarget {
  Context gl{kW, kH};
  std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
  IntegerShader shader;
  explicit IntegerTarget(Enum format) {
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, format, kW, kH);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    gl.Viewport(0, 0, kW, kH);
    gl.UseProgram(shader);
    MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  }
  void Draw() { gl.DrawArrays(TRIANGLE_STRIP, 0, 4); }
  // The target as RGBA_INTEGER INT (unsigned values above 2^31 as their bits).
  std::vector<glm::ivec4> Read(Enum type = INT) {
    std::vector<glm::ivec4> px(kW * kH, glm::ivec4(-7));
    gl.ReadPixels(0, 0, kW, kH, RGBA_INTEGER, type, px.data());
    return px;
  }
};

}  // namespace

TEST_CASE("integer textures: uploads clamp to the format's range, read-backs to the type's, as Mesa converts", "[texture][integer]") {
  Context gl(1, 1);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  const std::uint32_t ui[4] = {300, 5, 0xFFFFFFFFu, 7};
  const std::int32_t si[4] = {-200, 100, -5, 1000000};
  std::uint32_t out[8];
  // Four texels of a red format from unsigned or signed ints, read back as the format's own sign.
  const struct {
    Enum format;
    bool from_signed;
    std::int64_t want[4];
  } clamps[] = {{R8UI, false, {255, 5, 255, 7}},
                {R8UI, true, {0, 100, 0, 255}},
                {R8I, true, {-128, 100, -5, 127}},
                {R8I, false, {127, 5, 127, 7}},
                {R32I, false, {300, 5, 2147483647, 7}}};
  for (const auto& c : clamps) {
    CAPTURE(c.format, c.from_signed);
    gl.TexImage2D(TEXTURE_2D, 0, c.format, 4, 1, 0, RED_INTEGER, c.from_signed ? INT : UNSIGNED_INT,
                  c.from_signed ? static_cast<const void*>(si) : static_cast<const void*>(ui));
    const bool is_signed = c.format != R8UI;
    gl.GetTexImage(TEXTURE_2D, 0, RED_INTEGER, is_signed ? INT : UNSIGNED_INT, out);
    for (int i = 0; i < 4; ++i)
      CHECK((is_signed ? std::int64_t(std::int32_t(out[i])) : std::int64_t(out[i])) == c.want[i]);
  }
  std::uint8_t ub[4];
  std::int8_t sb[4];
  gl.GetTexImage(TEXTURE_2D, 0, RED_INTEGER, UNSIGNED_BYTE, ub);
  CHECK((ub[0] == 255 && ub[1] == 5 && ub[2] == 255 && ub[3] == 7));
  gl.GetTexImage(TEXTURE_2D, 0, RED_INTEGER, BYTE, sb);
  CHECK((sb[0] == 127 && sb[1] == 5 && sb[2] == 127 && sb[3] == 7));
  // RGB: alpha reads 1.
  const std::uint32_t rgb[6] = {300, 5, 0xFFFFFFFFu, 7, 0, 0};
  gl.TexImage2D(TEXTURE_2D, 0, RGB32UI, 2, 1, 0, RGB_INTEGER, UNSIGNED_INT, rgb);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA_INTEGER, UNSIGNED_INT, out);
  CHECK((out[0] == 300 && out[1] == 5 && out[2] == 0xFFFFFFFFu && out[3] == 1));
  CHECK((out[4] == 7 && out[5] == 0 && out[6] == 0 && out[7] == 1));
  // RGB10_A2UI from its packed type, and from integers (clamped to 10 and 2 bits).
  const std::uint32_t packed = 3u << 30 | 1023u << 20 | 5u << 10 | 9u;
  gl.TexImage2D(TEXTURE_2D, 0, RGB10_A2UI, 1, 1, 0, RGBA_INTEGER, UNSIGNED_INT_2_10_10_10_REV, &packed);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA_INTEGER, UNSIGNED_INT, out);
  CHECK((out[0] == 9 && out[1] == 5 && out[2] == 1023 && out[3] == 3));
  const std::uint32_t wide[4] = {2000, 3, 4, 9};
  gl.TexImage2D(TEXTURE_2D, 0, RGB10_A2UI, 1, 1, 0, RGBA_INTEGER, UNSIGNED_INT, wide);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA_INTEGER, UNSIGNED_INT, out);
  CHECK((out[0] == 1023 && out[1] == 3 && out[2] == 4 && out[3] == 3));
  std::uint32_t back = 0;
  gl.GetTexImage(TEXTURE_2D, 0, RGBA_INTEGER, UNSIGNED_INT_2_10_10_10_REV, &back);
  CHECK(back == (3u << 30 | 4u << 20 | 3u << 10 | 1023u));
  // Signed 16 bits, two channels, from shorts and bytes; TexSubImage into part of it.
  const std::int16_t shorts[4] = {-32768, 32767, -1, 2};
  gl.TexImage2D(TEXTURE_2D, 0, RG16I, 2, 1, 0, RG_INTEGER, SHORT, shorts);
  const std::int8_t bytes[2] = {-100, 100};
  gl.TexSubImage2D(TEXTURE_2D, 0, 1, 0, 1, 1, RG_INTEGER, BYTE, bytes);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA_INTEGER, INT, out);
  const std::int32_t want[8] = {-32768, 32767, 0, 1, -100, 100, 0, 1};
  CHECK(std::memcmp(out, want, sizeof want) == 0);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("integer textures: integer and non-integer data do not mix; no mipmaps, no multisampling", "[texture][integer]") {
  Context gl(1, 1);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  const std::int32_t v[4] = {1, 2, 3, 4};
  gl.TexImage2D(TEXTURE_2D, 0, R32I, 1, 1, 0, RED, INT, v);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA_INTEGER, UNSIGNED_BYTE, v);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, R32I, 1, 1, 0, RED_INTEGER, FLOAT, v);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, R32I, 1, 1, 0, RED_INTEGER, INT, v);
  CHECK(gl.GetError() == NO_ERROR);
  gl.TexSubImage2D(TEXTURE_2D, 0, 0, 0, 1, 1, RED, INT, v);
  CHECK(gl.GetError() == INVALID_OPERATION);
  std::int32_t out[4];
  gl.GetTexImage(TEXTURE_2D, 0, RED, UNSIGNED_BYTE, out);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GenerateMipmap(TEXTURE_2D);
  CHECK(gl.GetError() == INVALID_OPERATION);  // not filterable
  int max_samples = -1;
  gl.GetIntegerv(MAX_INTEGER_SAMPLES, &max_samples);
  CHECK(max_samples == kMaxIntegerSamples);
  gl.BindRenderbuffer(RENDERBUFFER, gl.GenRenderbuffer());
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, RGBA8UI, 4, 4);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 1, RGBA8UI, 4, 4);
  CHECK(gl.GetError() == NO_ERROR);
  int samples = -1;
  gl.GetRenderbufferParameteriv(RENDERBUFFER, RENDERBUFFER_SAMPLES, &samples);
  CHECK(samples == 1);
  gl.BindTexture(TEXTURE_2D_MULTISAMPLE, gl.GenTexture());
  gl.TexImage2DMultisample(TEXTURE_2D_MULTISAMPLE, 2, R32UI, 4, 4, true);
  CHECK(gl.GetError() == INVALID_OPERATION);
  // RGB integer formats are textures only: an attachment of one leaves the framebuffer incomplete.
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGB16UI, 4, 4, 0, RGB_INTEGER, UNSIGNED_SHORT, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16UI, 4, 4, 0, RGBA_INTEGER, UNSIGNED_SHORT, nullptr);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("integer colour buffers: outputs stored exactly, clamped to the channels, never blended", "[framebuffer][integer]") {
  SECTION("R32UI keeps every 32-bit pattern, NaN's bits included") {
    IntegerTarget t(R32UI);
    for (const std::uint32_t id : {0u, 1u, 0x7F800001u, 0xFF800001u, 0xFFFFFFFFu, 0x80000000u}) {
      CAPTURE(id);
      t.shader.value = glm::ivec4(int(id), 0, 0, 0);
      t.Draw();
      std::vector<std::uint32_t> px(kW * kH, 7);
      t.gl.ReadPixels(0, 0, kW, kH, RED_INTEGER, UNSIGNED_INT, px.data());
      for (const std::uint32_t p : px) CHECK(p == id);
    }
  }
  SECTION("RGBA8I clamps, blending and glClear leave it, ClearBufferiv clears it, XOR and masks apply") {
    IntegerTarget t(RGBA8I);
    t.gl.Enable(BLEND);
    t.gl.BlendFunc(ONE, ONE);
    t.shader.value = glm::ivec4(-300, 200, -5, 127);
    t.Draw();
    CHECK(t.Read()[5] == glm::ivec4(-128, 127, -5, 127));  // as Mesa
    t.gl.ClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    t.gl.Clear(COLOR_BUFFER_BIT);
    CHECK(t.Read()[5] == glm::ivec4(-128, 127, -5, 127));  // Clear leaves an integer buffer (undefined in OpenGL)
    const int value[4] = {10, -20, 300, -400};
    t.gl.ClearBufferiv(COLOR, 0, value);
    CHECK(t.Read()[0] == glm::ivec4(10, -20, 127, -128));
    t.gl.Disable(BLEND);
    t.gl.Enable(COLOR_LOGIC_OP);
    t.gl.LogicOp(XOR);
    t.shader.value = glm::ivec4(3, -1, 0, 1);
    t.Draw();
    CHECK(t.Read()[7] == glm::ivec4(10 ^ 3, -20 ^ -1, 127, -128 ^ 1));
    t.gl.LogicOp(INVERT);  // the inverted bits of a signed channel stay in range
    t.Draw();
    CHECK(t.Read()[7] == glm::ivec4(~(10 ^ 3), ~(-20 ^ -1), ~127, ~(-128 ^ 1)));
    t.gl.Disable(COLOR_LOGIC_OP);
    t.gl.ColorMask(true, false, true, false);
    t.shader.value = glm::ivec4(1, 2, 3, 4);
    t.Draw();
    CHECK(t.Read()[3] == glm::ivec4(1, ~(-20 ^ -1), 3, ~(-128 ^ 1)));
    CHECK(t.gl.GetError() == NO_ERROR);
  }
  SECTION("RG16UI: the logic operation keeps an unsigned channel's bits; ClearBufferuiv clamps") {
    IntegerTarget t(RG16UI);
    const std::uint32_t value[4] = {70000, 65535, 9, 9};
    t.gl.ClearBufferuiv(COLOR, 0, value);
    CHECK(t.Read()[0] == glm::ivec4(65535, 65535, 0, 1));
    t.gl.Enable(COLOR_LOGIC_OP);
    t.gl.LogicOp(COPY_INVERTED);
    t.shader.value = glm::ivec4(1, 0x1234, 0, 0);
    t.Draw();
    CHECK(t.Read()[0] == glm::ivec4(0xFFFE, 0xFFFF ^ 0x1234, 0, 1));
  }
  SECTION("reads and blits keep integer and non-integer apart") {
    IntegerTarget t(R16I);
    std::uint8_t rgba[4];
    t.gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, rgba);
    CHECK(t.gl.GetError() == INVALID_OPERATION);
    const std::uint32_t draw = t.gl.GenFramebuffer(), rb = t.gl.GenRenderbuffer();
    t.gl.BindRenderbuffer(RENDERBUFFER, rb);
    t.gl.RenderbufferStorage(RENDERBUFFER, RGBA8, kW, kH);
    t.gl.BindFramebuffer(DRAW_FRAMEBUFFER, draw);
    t.gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    t.gl.BlitFramebuffer(0, 0, kW, kH, 0, 0, kW, kH, COLOR_BUFFER_BIT, NEAREST);
    CHECK(t.gl.GetError() == INVALID_OPERATION);
    t.gl.RenderbufferStorage(RENDERBUFFER, R32I, kW, kH);
    t.gl.BlitFramebuffer(0, 0, kW, kH, 0, 0, kW, kH, COLOR_BUFFER_BIT, LINEAR);
    CHECK(t.gl.GetError() == INVALID_OPERATION);
    const int v[4] = {-1234, 0, 0, 0};
    t.gl.BindFramebuffer(FRAMEBUFFER, t.fbo);
    t.gl.ClearBufferiv(COLOR, 0, v);
    t.gl.BindFramebuffer(DRAW_FRAMEBUFFER, draw);
    t.gl.BlitFramebuffer(0, 0, kW, kH, kW, 0, 0, kH, COLOR_BUFFER_BIT, NEAREST);
    CHECK(t.gl.GetError() == NO_ERROR);
    t.gl.BindFramebuffer(READ_FRAMEBUFFER, draw);
    std::int32_t back[4] = {};
    t.gl.ReadPixels(2, 1, 1, 1, RGBA_INTEGER, INT, back);
    CHECK((back[0] == -1234 && back[1] == 0 && back[2] == 0 && back[3] == 1));
  }
}

TEST_CASE("integer textures: sampled and fetched exactly, NEAREST only, integer border and incomplete values", "[texture][integer]") {
  IntegerTarget t(RGBA32I);
  std::vector<glm::ivec4> texels(kW * kH);
  for (int i = 0; i < kW * kH; ++i)  // patterns that are NaNs and denormals as floats
    texels[std::size_t(i)] = glm::ivec4(i, -i, int(0x7F800001u) + i, int(0xFF800001u) - i);
  const std::uint32_t tex = t.gl.GenTexture();
  t.gl.BindTexture(TEXTURE_2D, tex);
  t.gl.TexImage2D(TEXTURE_2D, 0, RGBA32I, kW, kH, 0, RGBA_INTEGER, INT, texels.data());
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST);
  for (const int kind : {1, 2}) {
    CAPTURE(kind);
    t.shader.kind = kind;
    t.Draw();
    CHECK(t.Read() == texels);
  }
  // Outside [0, 1] with CLAMP_TO_BORDER: TexParameterIiv's numbers.
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_BORDER);
  const int border[4] = {-5, 6, int(0x7FC00001u), 8};
  t.gl.TexParameterIiv(TEXTURE_2D, TEXTURE_BORDER_COLOR, border);
  t.shader.kind = 1;
  t.shader.scale = 2.0f;
  t.Draw();
  const std::vector<glm::ivec4> px = t.Read();
  CHECK(px[0] == texels[kW + 1]);  // (0.0625, 0.125) x 2: texel (1, 1)
  CHECK(px[kW - 1] == glm::ivec4(border[0], border[1], border[2], border[3]));
  // LINEAR filtering leaves an integer texture incomplete: it reads (0, 0, 0, 1).
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR);
  t.Draw();
  for (const glm::ivec4& p : t.Read()) CHECK(p == glm::ivec4(0, 0, 0, 1));
  CHECK(t.gl.GetError() == NO_ERROR);
}

TEST_CASE("integer textures: buffer textures of integer formats, and a rendered R16UI texture sampled back", "[texture][integer]") {
  IntegerTarget t(RGBA32UI);
  std::vector<std::uint16_t> values(kW * kH * 2);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::uint16_t(65535 - 977 * i);
  const std::uint32_t buf = t.gl.GenBuffer(), tex = t.gl.GenTexture();
  t.gl.BindBuffer(TEXTURE_BUFFER, buf);
  t.gl.BufferData(TEXTURE_BUFFER, std::ptrdiff_t(values.size() * 2), values.data(), STATIC_DRAW);
  t.gl.BindTexture(TEXTURE_BUFFER, tex);
  t.gl.TexBuffer(TEXTURE_BUFFER, RG16UI, buf);
  CHECK(t.gl.GetError() == NO_ERROR);
  t.shader.kind = 3;
  t.Draw();
  std::vector<glm::ivec4> px = t.Read(UNSIGNED_INT);
  for (int i = 0; i < kW * kH; ++i)
    CHECK(px[std::size_t(i)] == glm::ivec4(values[2 * std::size_t(i)], values[2 * std::size_t(i) + 1], 0, 1));
  // Render ids into an R16UI texture, then fetch them from it.
  const std::uint32_t ids = t.gl.GenTexture(), fbo = t.gl.GenFramebuffer();
  t.gl.BindTexture(TEXTURE_2D, ids);
  t.gl.TexImage2D(TEXTURE_2D, 0, R16UI, kW, kH, 0, RED_INTEGER, UNSIGNED_SHORT, nullptr);
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  t.gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST);
  t.gl.BindFramebuffer(FRAMEBUFFER, fbo);
  t.gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, ids, 0);
  t.shader.kind = 0;
  t.shader.value = glm::ivec4(40000, 1, 2, 3);
  t.Draw();
  t.gl.BindFramebuffer(FRAMEBUFFER, t.fbo);
  t.shader.kind = 2;
  t.Draw();
  px = t.Read(UNSIGNED_INT);
  for (const glm::ivec4& p : px) CHECK(p == glm::ivec4(40000, 0, 0, 1));
  CHECK(t.gl.GetError() == NO_ERROR);
}

TEST_CASE("integer textures: texelFetch in vectors gives the one-lane fetch's integers, every format", "[texture][integer]") {
  // Texels of pseudo-random bytes (every bit pattern of each channel), two levels, fetched 16 lanes at a time at
  // places inside and outside each level, against Textures::Fetch's texel by texel.
  const Enum formats[] = {R8I,     R8UI,     R16I,     R16UI,   R32I,    R32UI,    RG8I,    RG8UI,   RG16I,
                          RG16UI,  RG32I,    RG32UI,   RGB8I,   RGB8UI,  RGB16I,   RGB16UI, RGB32I,  RGB32UI,
                          RGBA8I,  RGBA8UI,  RGBA16I,  RGBA16UI, RGBA32I, RGBA32UI, RGB10_A2UI};
  std::uint32_t seed = 9;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  for (const Enum format : formats) {
    CAPTURE(format);
    detail::TextureObject t;
    t.target = TEXTURE_2D;
    for (int level = 0; level < 2; ++level) {
      detail::TextureLevel& lv = t.levels[0][level];
      lv.Allocate(format, 7 >> level, 5 >> level);
      for (std::size_t i = 0; i + detail::TextureLevel::kGatherPad < lv.data.size(); ++i) lv.data[i] = std::uint8_t(next());
    }
    t.params.min_filter = NEAREST_MIPMAP_NEAREST;
    t.params.mag_filter = NEAREST;
    t.params.max_level = 1;
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    Textures tx;
    tx.unit_2d[0] = &view;
    for (int round = 0; round < 8; ++round) {
      int x[16], y[16], level[16];
      for (int l = 0; l < 16; ++l) {
        x[l] = int(next() % 10) - 1;
        y[l] = int(next() % 8) - 1;
        level[l] = int(next() % 4) - 1;
      }
      float out[4][16];
      tx.FetchLanes(0, x, y, level, out);
      for (int l = 0; l < 16; ++l) {
        const glm::vec4 one = tx.Fetch(0, glm::ivec2(x[l], y[l]), level[l]);
        for (int c = 0; c < 4; ++c) {
          CAPTURE(l, c, x[l], y[l], level[l]);
          CHECK(std::bit_cast<std::uint32_t>(out[c][l]) == std::bit_cast<std::uint32_t>(one[c]));
        }
      }
    }
  }
}

TEST_CASE("integer textures: texture() and textureLod() in vectors give the one-lane lookup's integers, every format, "
          "target, wrap mode and filter",
          "[texture][integer]") {
  // Texels of pseudo-random bytes (NaN and denormal patterns among them) in a full mip chain; NEAREST and
  // NEAREST_MIPMAP_NEAREST (the filters that leave an integer texture complete) under each wrap mode, an integer
  // border colour that is a NaN pattern; 2D textures, 2D arrays, cube maps and 3D textures, 16 lanes a call
  // (lanes on several levels, faces and layers, NaN, huge and zero coordinates and derivatives) against the
  // one-lane calls, compared as bits.
  const Enum formats[] = {R8I,     R8UI,     R16I,     R16UI,   R32I,    R32UI,    RG8I,    RG8UI,   RG16I,
                          RG16UI,  RG32I,    RG32UI,   RGB8I,   RGB8UI,  RGB16I,   RGB16UI, RGB32I,  RGB32UI,
                          RGBA8I,  RGBA8UI,  RGBA16I,  RGBA16UI, RGBA32I, RGBA32UI, RGB10_A2UI};
  const Enum targets[] = {TEXTURE_2D, TEXTURE_2D_ARRAY, TEXTURE_CUBE_MAP, TEXTURE_3D};
  const Enum wraps[] = {REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER};
  std::uint32_t seed = 21;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(next() & 0xFFFF) / 65535.0f; };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  int compared = 0, differing = 0;
  for (const Enum format : formats) {
    for (const Enum target : targets) {
      for (int state = 0; state < 8; ++state) {
        const Enum wrap = wraps[state % 4];
        const Enum min_filter = state < 4 ? NEAREST : NEAREST_MIPMAP_NEAREST;
        detail::TextureObject t;
        t.target = target;
        const int w = target == TEXTURE_CUBE_MAP ? 4 : 7, h = target == TEXTURE_CUBE_MAP ? 4 : 5;
        const int d = target == TEXTURE_2D_ARRAY ? 3 : target == TEXTURE_3D ? 6 : 1;
        int levels = 0;
        for (int size = std::max({w, h, target == TEXTURE_3D ? d : 1}); size > 0; size >>= 1) ++levels;
        for (int face = 0; face < t.Faces(); ++face) {
          for (int level = 0; level < levels; ++level) {
            detail::TextureLevel& lv = t.levels[face][level];
            lv.Allocate(format, std::max(1, w >> level), std::max(1, h >> level), 1,
                        target == TEXTURE_3D ? std::max(1, d >> level) : d);
            for (std::size_t i = 0; i + detail::TextureLevel::kGatherPad < lv.data.size(); ++i)
              lv.data[i] = std::uint8_t(next());
          }
        }
        t.params.min_filter = min_filter;
        t.params.mag_filter = NEAREST;
        t.params.wrap_s = t.params.wrap_t = t.params.wrap_r = wrap;
        t.params.border_integer = 1;
        const std::uint32_t border[4] = {0xFFFFFFFBu, 7u, 0x7F800003u, 0x80000001u};
        std::memcpy(t.params.border_bits, border, sizeof border);
        std::memcpy(&t.params.border.x, border, sizeof border);
        const detail::TextureView view = detail::MakeView(t);
        REQUIRE(view.complete);
        REQUIRE(view.wide);
        Textures tx;
        if (target == TEXTURE_CUBE_MAP) tx.unit_cube[0] = &view;
        else if (target == TEXTURE_2D_ARRAY) tx.unit_2d_array[0] = &view;
        else if (target == TEXTURE_3D) tx.unit_3d[0] = &view;
        else tx.unit_2d[0] = &view;
        for (int round = 0; round < 6; ++round) {
          Textures::Lanes c;
          float lod[16];
          for (int k = 0; k < 16; ++k) {
            c.s[k] = uniform(-2.0f, 2.0f);
            c.t[k] = uniform(-2.0f, 2.0f);
            c.r[k] = target == TEXTURE_2D_ARRAY ? uniform(-1.0f, 4.0f) : uniform(-2.0f, 2.0f);
            const float scale = k % 3 == 0 ? 0.01f : k % 3 == 1 ? 0.2f : 1.5f;  // lanes on several levels
            c.ds_dx[k] = uniform(-1.0f, 1.0f) * scale;
            c.dt_dx[k] = uniform(-1.0f, 1.0f) * scale;
            c.dr_dx[k] = uniform(-1.0f, 1.0f) * scale;
            c.ds_dy[k] = uniform(-1.0f, 1.0f) * scale;
            c.dt_dy[k] = uniform(-1.0f, 1.0f) * scale;
            c.dr_dy[k] = uniform(-1.0f, 1.0f) * scale;
            lod[k] = uniform(-3.0f, 6.0f);
          }
          if (round == 1) {
            c.s[0] = nan;
            c.t[1] = 1e30f;
            c.r[2] = -1e30f;
            c.r[3] = nan;
            c.s[4] = c.t[4] = c.r[4] = 0.0f;
            c.ds_dx[5] = c.dt_dx[5] = c.dr_dx[5] = c.ds_dy[5] = c.dt_dy[5] = c.dr_dy[5] = 0.0f;
            c.ds_dy[6] = nan;
            lod[7] = nan;
            lod[8] = -1e30f;
            lod[9] = 1e30f;
          }
          float out[4][16], out_lod[4][16];
          if (target == TEXTURE_CUBE_MAP) {
            tx.SampleCubeLanes(0, c, 0.0f, out);
            tx.SampleCubeLodLanes(0, c, lod, out_lod);
          } else if (target == TEXTURE_2D_ARRAY) {
            tx.SampleArrayLanes(0, c, 0.0f, out);
            tx.SampleArrayLodLanes(0, c, lod, out_lod);
          } else if (target == TEXTURE_3D) {
            tx.Sample3DLanes(0, c, 0.0f, out);
            tx.Sample3DLodLanes(0, c, lod, out_lod);
          } else {
            tx.SampleLanes(0, c, 0.0f, out);
            tx.SampleLodLanes(0, c, lod, out_lod);
          }
          for (int k = 0; k < 16; ++k) {
            const glm::vec3 p(c.s[k], c.t[k], c.r[k]);
            const glm::vec3 dx(c.ds_dx[k], c.dt_dx[k], c.dr_dx[k]), dy(c.ds_dy[k], c.dt_dy[k], c.dr_dy[k]);
            glm::vec4 one, one_lod;
            if (target == TEXTURE_CUBE_MAP) {
              one = tx.SampleCube(0, p, dx, dy, 0.0f);
              one_lod = tx.SampleCubeLod(0, p, lod[k]);
            } else if (target == TEXTURE_2D_ARRAY) {
              one = tx.SampleArray(0, p, glm::vec2(dx), glm::vec2(dy), 0.0f);
              one_lod = tx.SampleArrayLod(0, p, lod[k]);
            } else if (target == TEXTURE_3D) {
              one = tx.Sample3D(0, p, dx, dy, 0.0f);
              one_lod = tx.Sample3DLod(0, p, lod[k]);
            } else {
              one = tx.Sample(0, glm::vec2(p), glm::vec2(dx), glm::vec2(dy), 0.0f);
              one_lod = tx.SampleLod(0, glm::vec2(p), lod[k]);
            }
            for (int ch = 0; ch < 4; ++ch) {
              const bool same = std::bit_cast<std::uint32_t>(out[ch][k]) == std::bit_cast<std::uint32_t>(one[ch]) &&
                                std::bit_cast<std::uint32_t>(out_lod[ch][k]) ==
                                    std::bit_cast<std::uint32_t>(one_lod[ch]);
              if (!same) {
                CAPTURE(format, target, wrap, min_filter, round, k, ch);
                CHECK(std::bit_cast<std::uint32_t>(out[ch][k]) == std::bit_cast<std::uint32_t>(one[ch]));
                CHECK(std::bit_cast<std::uint32_t>(out_lod[ch][k]) == std::bit_cast<std::uint32_t>(one_lod[ch]));
                ++differing;
              }
              compared += 2;
            }
          }
        }
      }
    }
  }
  CHECK(differing == 0);
  CHECK(compared == 25 * 4 * 8 * 6 * 16 * 8);
}

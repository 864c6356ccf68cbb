// Per-fragment operations: depth comparisons, depth writes and masks, colour conversion.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <array>
#include <atomic>
#include <memory>
#include <cmath>
#include <limits>
#include <vector>

#include "fragment_ops.h"
#include "helpers.h"

using namespace softgl;
using detail::DepthTest;
using detail::FloatToUnorm8;

TEST_CASE("every depth function compares as OpenGL does", "[fragment_ops]") {
  struct Row {
    Enum func;
    bool less, equal, greater;  // result for incoming <, ==, > stored
  };
  const Row rows[] = {{NEVER, false, false, false}, {LESS, true, false, false},   {EQUAL, false, true, false},
                      {LEQUAL, true, true, false},  {GREATER, false, false, true}, {NOTEQUAL, true, false, true},
                      {GEQUAL, false, true, true},  {ALWAYS, true, true, true}};
  for (const Row& r : rows) {
    INFO("func 0x" << std::hex << r.func);
    CHECK(DepthTest(r.func, 0.25f, 0.5f) == r.less);
    CHECK(DepthTest(r.func, 0.5f, 0.5f) == r.equal);
    CHECK(DepthTest(r.func, 0.75f, 0.5f) == r.greater);
  }
}

TEST_CASE("colours convert to 8 bits by rounding, clamped", "[fragment_ops]") {
  CHECK(FloatToUnorm8(0.0f) == 0);
  CHECK(FloatToUnorm8(1.0f) == 255);
  CHECK(FloatToUnorm8(-3.0f) == 0);
  CHECK(FloatToUnorm8(7.0f) == 255);
  CHECK(FloatToUnorm8(0.5f) == 128);
  CHECK(FloatToUnorm8(1.0f / 255.0f) == 1);
  CHECK(FloatToUnorm8(0.4f / 255.0f) == 0);
  CHECK(FloatToUnorm8(0.6f / 255.0f) == 1);
  CHECK(FloatToUnorm8(std::numeric_limits<float>::quiet_NaN()) == 0);
}

namespace {
// Draws a full-viewport quad at NDC depth z with colour c.
void FullQuad(Context& gl, testing::SolidShader& shader, float z, glm::vec4 c) {
  testing::MakeVertexArray(gl, {{-1, -1, z, 1}, {1, -1, z, 1}, {-1, 1, z, 1}, {1, 1, z, 1}});
  shader.color = c;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
}
}  // namespace

TEST_CASE("the depth test keeps the nearest surface; DepthMask stops writes", "[fragment_ops]") {
  Context gl(4, 4);
  testing::SolidShader shader;
  gl.Enable(DEPTH_TEST);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  FullQuad(gl, shader, 0.0f, {1, 0, 0, 1});   // depth 0.5
  FullQuad(gl, shader, 0.5f, {0, 1, 0, 1});   // behind: rejected
  std::uint8_t px[4];
  gl.ReadPixel(2, 2, px);
  CHECK(px[0] == 255);
  CHECK(px[1] == 0);
  CHECK(gl.ReadDepth(2, 2) == Approx(0.5f));
  gl.DepthMask(false);
  FullQuad(gl, shader, -0.5f, {0, 0, 1, 1});  // in front: passes, but depth stays
  gl.ReadPixel(2, 2, px);
  CHECK(px[2] == 255);
  CHECK(gl.ReadDepth(2, 2) == Approx(0.5f));
  gl.DepthMask(true);
  gl.DepthFunc(GREATER);
  FullQuad(gl, shader, 0.5f, {0, 1, 0, 1});  // now the farther one wins
  gl.ReadPixel(2, 2, px);
  CHECK(px[1] == 255);
  CHECK(gl.ReadDepth(2, 2) == Approx(0.75f));
}

TEST_CASE("with the depth test disabled, depth is neither tested nor written", "[fragment_ops]") {
  Context gl(4, 4);
  testing::SolidShader shader;
  gl.ClearDepth(0.25);
  gl.Clear(DEPTH_BUFFER_BIT);
  FullQuad(gl, shader, 0.5f, {1, 1, 0, 1});
  std::uint8_t px[4];
  gl.ReadPixel(0, 0, px);
  CHECK(px[0] == 255);
  CHECK(gl.ReadDepth(0, 0) == 0.25f);
}

TEST_CASE("DepthRange maps NDC depth", "[fragment_ops]") {
  Context gl(4, 4);
  testing::SolidShader shader;
  gl.Enable(DEPTH_TEST);
  gl.DepthFunc(ALWAYS);
  gl.DepthRange(0.2, 0.6);
  FullQuad(gl, shader, 0.0f, {1, 1, 1, 1});
  CHECK(gl.ReadDepth(1, 1) == Approx(0.4f));
  gl.DepthRange(1.0, 0.0);  // reversed ranges are allowed
  FullQuad(gl, shader, -1.0f, {1, 1, 1, 1});
  CHECK(gl.ReadDepth(1, 1) == Approx(1.0f));
}

TEST_CASE("a discarding shader writes nothing", "[fragment_ops]") {
  struct Discard : softgl::Shader<Discard, testing::NoVaryings> {
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
    bool Fragment(const FragmentIn<testing::NoVaryings>& in, FragmentOut& out) const {
      out.color[0] = glm::vec4(1);
      return int(in.frag_coord.x) % 2 == 0;  // keep even columns only
    }
  };
  Context gl(4, 2);
  gl.Enable(DEPTH_TEST);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  Discard shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  for (int x = 0; x < 4; ++x) {
    std::uint8_t px[4];
    gl.ReadPixel(x, 0, px);
    CHECK(px[0] == (x % 2 == 0 ? 255 : 0));
    CHECK(gl.ReadDepth(x, 0) == (x % 2 == 0 ? 0.5f : 1.0f));
  }
}

// ---- Stencil ----------------------------------------------------------------------------------------------------

using detail::StencilFace;
using detail::StencilTest;
using detail::StencilUpdate;

TEST_CASE("every stencil function compares masked reference and stored value", "[fragment_ops][stencil]") {
  struct Row {
    Enum func;
    int ref;
    std::uint32_t mask;
    std::uint8_t stored;
    bool pass;
  };
  const Row rows[] = {
      {NEVER, 5, 0xFF, 5, false},     {ALWAYS, 5, 0xFF, 9, true},
      {LESS, 4, 0xFF, 5, true},       {LESS, 5, 0xFF, 5, false},      // ref < stored
      {LEQUAL, 5, 0xFF, 5, true},     {LEQUAL, 6, 0xFF, 5, false},
      {EQUAL, 0x13, 0x0F, 0x23, true}, {EQUAL, 0x13, 0xFF, 0x23, false},  // only the masked bits compare
      {NOTEQUAL, 7, 0xFF, 7, false},  {NOTEQUAL, 7, 0xFE, 6, false},   // 7 & 0xFE == 6
      {GREATER, 9, 0xFF, 5, true},    {GREATER, 9, 0x03, 5, false},    // 1 > 1 fails
      {GEQUAL, 5, 0xFF, 5, true},     {GEQUAL, 4, 0xFF, 5, false},
      {EQUAL, 300, 0xFF, 255, true},  {EQUAL, -3, 0xFF, 0, true},      // ref clamps to [0, 255]
  };
  for (const Row& r : rows) {
    INFO("func 0x" << std::hex << r.func << " ref " << std::dec << r.ref << " stored " << int(r.stored));
    StencilFace f;
    f.func = r.func;
    f.ref = r.ref;
    f.value_mask = r.mask;
    CHECK(StencilTest(f, r.stored) == r.pass);
  }
}

TEST_CASE("every stencil operation, through the write mask", "[fragment_ops][stencil]") {
  struct Row {
    Enum op;
    std::uint8_t stored;
    int ref;
    std::uint32_t write_mask;
    std::uint8_t result;
  };
  const Row rows[] = {
      {KEEP, 7, 3, 0xFF, 7},        {ZERO, 7, 3, 0xFF, 0},         {REPLACE, 7, 3, 0xFF, 3},
      {INCR, 7, 0, 0xFF, 8},        {INCR, 255, 0, 0xFF, 255},     {INCR_WRAP, 255, 0, 0xFF, 0},
      {DECR, 7, 0, 0xFF, 6},        {DECR, 0, 0, 0xFF, 0},         {DECR_WRAP, 0, 0, 0xFF, 255},
      {INVERT, 0x0F, 0, 0xFF, 0xF0},
      {REPLACE, 0xAA, 0x55, 0x0F, 0xA5},  // only the low bits change
      {INVERT, 0xAA, 0, 0xF0, 0x5A},      {ZERO, 0xFF, 0, 0x00, 0xFF},
      {INCR_WRAP, 0x0F, 0, 0x0F, 0x00},   // 0x10 through mask 0x0F
      {REPLACE, 1, 999, 0xFF, 255},       // ref clamps
  };
  for (const Row& r : rows) {
    INFO("op 0x" << std::hex << r.op << " stored " << int(r.stored));
    StencilFace f;
    f.ref = r.ref;
    f.write_mask = r.write_mask;
    CHECK(int(StencilUpdate(f, r.op, r.stored)) == int(r.result));
  }
}

// ---- Blending ---------------------------------------------------------------------------------------------------

TEST_CASE("every blend factor", "[fragment_ops][blend]") {
  // src, dst and constant chosen so that every factor gives a different value.
  const glm::vec4 s(0.8f, 0.6f, 0.4f, 0.7f), d(0.2f, 0.5f, 1.0f, 0.4f), c(0.1f, 0.3f, 0.9f, 0.25f);
  struct Row {
    Enum factor;
    glm::vec4 value;  // the factor itself (rgb from the rgb factor, a from the alpha factor)
  };
  const Row rows[] = {
      {ZERO, {0, 0, 0, 0}},
      {ONE, {1, 1, 1, 1}},
      {SRC_COLOR, s},
      {ONE_MINUS_SRC_COLOR, {0.2f, 0.4f, 0.6f, 0.3f}},
      {DST_COLOR, d},
      {ONE_MINUS_DST_COLOR, {0.8f, 0.5f, 0.0f, 0.6f}},
      {SRC_ALPHA, {0.7f, 0.7f, 0.7f, 0.7f}},
      {ONE_MINUS_SRC_ALPHA, {0.3f, 0.3f, 0.3f, 0.3f}},
      {DST_ALPHA, {0.4f, 0.4f, 0.4f, 0.4f}},
      {ONE_MINUS_DST_ALPHA, {0.6f, 0.6f, 0.6f, 0.6f}},
      {CONSTANT_COLOR, c},
      {ONE_MINUS_CONSTANT_COLOR, {0.9f, 0.7f, 0.1f, 0.75f}},
      {CONSTANT_ALPHA, {0.25f, 0.25f, 0.25f, 0.25f}},
      {ONE_MINUS_CONSTANT_ALPHA, {0.75f, 0.75f, 0.75f, 0.75f}},
      {SRC_ALPHA_SATURATE, {0.6f, 0.6f, 0.6f, 1.0f}},  // min(As, 1 - Ad) = min(0.7, 0.6); alpha 1
  };
  for (const Row& r : rows) {
    INFO("factor 0x" << std::hex << r.factor);
    detail::BlendState b;
    b.color = c;
    // As source factor with the destination factor ZERO: result = s * factor.
    b.src_rgb = b.src_alpha = r.factor;
    b.dst_rgb = b.dst_alpha = ZERO;
    const glm::vec4 as_src = detail::Blend(b, s, d);
    // As destination factor with the source factor ZERO: result = d * factor.
    b.src_rgb = b.src_alpha = ZERO;
    b.dst_rgb = b.dst_alpha = r.factor;
    const glm::vec4 as_dst = detail::Blend(b, s, d);
    for (int i = 0; i < 4; ++i) {
      CHECK(as_src[i] == Approx(s[i] * r.value[i]).margin(1e-6));
      CHECK(as_dst[i] == Approx(d[i] * r.value[i]).margin(1e-6));
    }
  }
}

TEST_CASE("every blend equation, separately for colour and alpha", "[fragment_ops][blend]") {
  const glm::vec4 s(0.8f, 0.2f, 0.5f, 0.6f), d(0.3f, 0.9f, 0.5f, 0.2f);
  detail::BlendState b;
  b.src_rgb = b.src_alpha = SRC_ALPHA;          // 0.6
  b.dst_rgb = b.dst_alpha = ONE_MINUS_SRC_ALPHA;  // 0.4
  struct Row {
    Enum eq;
    glm::vec4 result;
  };
  const Row rows[] = {
      {FUNC_ADD, s * 0.6f + d * 0.4f},
      {FUNC_SUBTRACT, s * 0.6f - d * 0.4f},
      {FUNC_REVERSE_SUBTRACT, d * 0.4f - s * 0.6f},
      {MIN, glm::min(s, d)},  // factors ignored
      {MAX, glm::max(s, d)},
  };
  for (const Row& r : rows) {
    INFO("equation 0x" << std::hex << r.eq);
    b.eq_rgb = b.eq_alpha = r.eq;
    const glm::vec4 out = detail::Blend(b, s, d);
    for (int i = 0; i < 4; ++i) CHECK(out[i] == Approx(r.result[i]).margin(1e-6));
  }
  b.eq_rgb = FUNC_ADD;
  b.eq_alpha = MAX;
  const glm::vec4 mixed = detail::Blend(b, s, d);
  CHECK(mixed.r == Approx(0.8f * 0.6f + 0.3f * 0.4f));
  CHECK(mixed.a == Approx(0.6f));
}

namespace {
// One pixel of framebuffer, cleared to `dst`, then a fragment of colour `src` drawn over it.
std::array<int, 4> DrawOnePixel(Context& gl, const glm::vec4& dst, const glm::vec4& src) {
  testing::SolidShader shader;
  gl.ClearColor(dst.r, dst.g, dst.b, dst.a);
  gl.Clear(COLOR_BUFFER_BIT);
  FullQuad(gl, shader, 0.0f, src);
  std::uint8_t px[4];
  gl.ReadPixel(0, 0, px);
  return {px[0], px[1], px[2], px[3]};
}
}  // namespace

TEST_CASE("blending into the 8-bit framebuffer, by hand", "[fragment_ops][blend]") {
  Context gl(1, 1);
  gl.Enable(BLEND);
  gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  // The operands are the buffer's 8 bits: src (1, 0.5, 0, 0.5) -> (255, 128, 0, 128), so the source alpha is
  // 128/255 and one minus it 127/255; dst (0, 0, 255, 255). R 255*128/255 = 128, G 128*128/255 = 64.25 -> 64,
  // B 255*127/255 = 127, A (128*128 + 255*127)/255 = 191.25 -> 191.
  CHECK(DrawOnePixel(gl, {0, 0, 1, 1}, {1, 0.5f, 0, 0.5f}) == std::array<int, 4>{128, 64, 127, 191});
  gl.BlendFunc(ONE, ONE);  // saturates at 1
  CHECK(DrawOnePixel(gl, {0.6f, 0.2f, 0, 1}, {0.6f, 0.2f, 0, 0}) == std::array<int, 4>{255, 102, 0, 255});
  gl.BlendEquation(FUNC_REVERSE_SUBTRACT);  // d - s, clamped at 0; alpha 255 - 128 = 127
  CHECK(DrawOnePixel(gl, {0.6f, 0.2f, 0, 1}, {0.2f, 0.4f, 0, 0.5f}) == std::array<int, 4>{102, 0, 0, 127});
  gl.BlendEquation(FUNC_ADD);
  gl.BlendColor(0.2f, 0.4f, 0.6f, 0.8f);
  gl.BlendFuncSeparate(CONSTANT_COLOR, ZERO, ZERO, CONSTANT_ALPHA);  // rgb = s * c; a = d * 0.8
  CHECK(DrawOnePixel(gl, {1, 1, 1, 1}, {1, 1, 0.25f, 0}) == std::array<int, 4>{51, 102, 38, 204});
  // Fragment colours are clamped to [0, 1] before blending.
  gl.BlendFunc(ONE, ZERO);
  CHECK(DrawOnePixel(gl, {0, 0, 0, 0}, {2, -1, 0.5f, 1}) == std::array<int, 4>{255, 0, 128, 255});
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("logic operations on the colour's and the stored value's bits, by hand", "[fragment_ops][logic_op]") {
  // Source 0xF0 and destination 0xCC in every channel of an RGBA8 buffer; OpenGL's table of the sixteen
  // operations. Blending is enabled with factors that would give 0, to show that the logic operation replaces it.
  // A 1 x 1 target goes lane by lane, a 4 x 4 one by whole blocks.
  const Enum ops[16] = {CLEAR, AND, AND_REVERSE, COPY, AND_INVERTED, NOOP, XOR, OR,
                        NOR, EQUIV, INVERT, OR_REVERSE, COPY_INVERTED, OR_INVERTED, NAND, SET};
  const int expected[16] = {0x00, 0xC0, 0x30, 0xF0, 0x0C, 0xCC, 0x3C, 0xFC,
                            0x03, 0xC3, 0x33, 0xF3, 0x0F, 0xCF, 0x3F, 0xFF};
  for (const int size : {1, 4}) {
    Context gl(size, size);
    CHECK_FALSE(gl.IsEnabled(COLOR_LOGIC_OP));
    int mode = 0;
    gl.GetIntegerv(LOGIC_OP_MODE, &mode);
    CHECK(mode == int(COPY));
    gl.Enable(BLEND);
    gl.BlendFunc(ZERO, ZERO);
    gl.Enable(COLOR_LOGIC_OP);
    CHECK(gl.IsEnabled(COLOR_LOGIC_OP));
    CHECK(gl.IsEnabled(BLEND));  // still enabled, only not applied
    const glm::vec4 src(240.0f / 255.0f), dst(204.0f / 255.0f);
    for (int k = 0; k < 16; ++k) {
      gl.LogicOp(ops[k]);
      INFO("size " << size << ", operation 0x" << std::hex << ops[k]);
      const int e = expected[k];
      CHECK(DrawOnePixel(gl, dst, src) == std::array<int, 4>{e, e, e, e});
    }
    // Through the colour mask: green and alpha keep the stored bits.
    gl.LogicOp(XOR);
    gl.ClearColor(dst.r, dst.g, dst.b, dst.a);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.ColorMask(true, false, true, false);
    testing::SolidShader shader;
    FullQuad(gl, shader, 0.0f, src);
    std::uint8_t px[4];
    gl.ReadPixel(size - 1, size - 1, px);
    CHECK((px[0] == 0x3C && px[1] == 0xCC && px[2] == 0x3C && px[3] == 0xCC));
    gl.ColorMask(true, true, true, true);
    // Disabled: blending again (ZERO, ZERO).
    gl.Disable(COLOR_LOGIC_OP);
    CHECK(DrawOnePixel(gl, dst, src) == std::array<int, 4>{0, 0, 0, 0});
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("logic operations on packed, 16-bit and float buffers", "[fragment_ops][logic_op]") {
  // RGB565 (5, 6, 5 bits), RGBA16 and RGBA32F renderbuffers, 4 x 4 and 3 x 3 (whole blocks and lane by lane): XOR
  // of the colour's fixed-point value and the stored one; a float buffer takes the colour as it is, unblended.
  for (const int size : {3, 4}) {
    for (const Enum format : {RGB565, RGBA16, RGBA32F}) {
      Context gl(size, size);
      const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
      gl.BindFramebuffer(FRAMEBUFFER, fbo);
      gl.BindRenderbuffer(RENDERBUFFER, rb);
      gl.RenderbufferStorage(RENDERBUFFER, format, size, size);
      gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
      REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
      gl.Enable(BLEND);
      gl.BlendFunc(ONE, ONE);
      gl.Enable(COLOR_LOGIC_OP);
      gl.LogicOp(XOR);
      // Red 22/31 over 13/31 in 5 bits: 10110 ^ 01101 = 11011 (27); green 40/63 over 25/63: 101000 ^ 011001 =
      // 110001 (49). In 16 bits: 0xF0F0 ^ 0x0FF0 = 0xFF00; 0x1234 ^ 0xFFFF = 0xEDCB.
      glm::vec4 src, dst, want;
      if (format == RGB565) {
        src = {22.0f / 31, 40.0f / 63, 0, 0};
        dst = {13.0f / 31, 25.0f / 63, 1, 1};
        want = {27.0f / 31, 49.0f / 63, 1, 1};
      } else if (format == RGBA16) {
        src = {0xF0F0 / 65535.0f, 0x1234 / 65535.0f, 0, 1};
        dst = {0x0FF0 / 65535.0f, 1, 0, 1};
        want = {0xFF00 / 65535.0f, 0xEDCB / 65535.0f, 0, 0};
      } else {
        src = {0.3f, -2.0f, 5.0f, 0.25f};
        dst = {0.5f, 0.5f, 0.5f, 0.5f};
        want = src;
      }
      testing::SolidShader shader;
      gl.ClearColor(dst.r, dst.g, dst.b, dst.a);
      gl.Clear(COLOR_BUFFER_BIT);
      FullQuad(gl, shader, 0.0f, src);
      std::vector<float> px(std::size_t(size * size) * 4);
      gl.ReadPixels(0, 0, size, size, RGBA, FLOAT, px.data());
      INFO("format 0x" << std::hex << format << std::dec << ", size " << size);
      for (int i = 0; i < size * size; ++i)
        for (int c = 0; c < 4; ++c) CHECK(px[std::size_t(i * 4 + c)] == Approx(want[c]).margin(1e-6));
      CHECK(gl.GetError() == NO_ERROR);
    }
  }
}

TEST_CASE("LogicOp rejects what is not a logic operation", "[fragment_ops][logic_op][errors]") {
  Context gl(1, 1);
  gl.LogicOp(0x1510);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.LogicOp(0x14FF);
  CHECK(gl.GetError() == INVALID_ENUM);
  int mode = 0;
  gl.GetIntegerv(LOGIC_OP_MODE, &mode);
  CHECK(mode == int(COPY));
  gl.LogicOp(INVERT);
  gl.GetIntegerv(LOGIC_OP_MODE, &mode);
  CHECK(mode == int(INVERT));
  CHECK(gl.GetError() == NO_ERROR);
}

// ---- Masks, scissor, stencil through the API --------------------------------------------------------------------

TEST_CASE("colour, depth and stencil masks apply to Clear and to drawing", "[fragment_ops][masks]") {
  Context gl(2, 2);
  testing::SolidShader shader;
  std::uint8_t px[4];
  gl.ClearColor(1, 1, 1, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ColorMask(true, false, true, false);
  gl.ClearColor(0, 0, 0, 0);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ReadPixel(0, 0, px);
  CHECK((px[0] == 0 && px[1] == 255 && px[2] == 0 && px[3] == 255));
  FullQuad(gl, shader, 0.0f, {0.2f, 0.2f, 0.2f, 0.2f});
  gl.ReadPixel(1, 1, px);
  CHECK((px[0] == 51 && px[1] == 255 && px[2] == 51 && px[3] == 255));
  gl.ColorMask(true, true, true, true);

  gl.ClearDepth(0.5);
  gl.Clear(DEPTH_BUFFER_BIT);
  gl.DepthMask(false);
  gl.ClearDepth(0.9);
  gl.Clear(DEPTH_BUFFER_BIT);
  CHECK(gl.ReadDepth(0, 0) == 0.5f);
  gl.DepthMask(true);

  gl.ClearStencil(0xFF);
  gl.Clear(STENCIL_BUFFER_BIT);
  gl.StencilMask(0x0F);
  gl.ClearStencil(0x00);
  gl.Clear(STENCIL_BUFFER_BIT);
  CHECK(gl.ReadStencil(0, 0) == 0xF0);
  gl.Enable(STENCIL_TEST);
  gl.StencilFunc(ALWAYS, 0x3C, 0xFF);
  gl.StencilOp(KEEP, KEEP, REPLACE);
  FullQuad(gl, shader, 0.0f, {1, 1, 1, 1});
  CHECK(gl.ReadStencil(1, 0) == 0xFC);  // high bits kept, low bits from 0x3C
}

TEST_CASE("the scissor test bounds drawing and Clear", "[fragment_ops][scissor]") {
  Context gl(8, 8);
  testing::SolidShader shader;
  gl.Scissor(2, 3, 4, 2);
  gl.Enable(SCISSOR_TEST);
  gl.ClearColor(0, 1, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  FullQuad(gl, shader, 0.0f, {1, 0, 0, 1});
  gl.Disable(SCISSOR_TEST);
  std::uint8_t px[4];
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      gl.ReadPixel(x, y, px);
      const bool inside = x >= 2 && x < 6 && y >= 3 && y < 5;
      CHECK(int(px[0]) == (inside ? 255 : 0));
      CHECK(int(px[1]) == 0);  // the clear was scissored too, and the quad covered all of it
    }
  gl.Scissor(0, 0, -1, 4);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.Scissor(-100, -100, 1000000000, 1000000000);  // far outside: clamps, no overflow
  gl.Enable(SCISSOR_TEST);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ReadPixel(7, 7, px);
  CHECK(px[1] == 255);
}

TEST_CASE("front and back faces use their own stencil state", "[fragment_ops][stencil]") {
  Context gl(8, 4);
  // Left half counter-clockwise (front), right half clockwise (back).
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {0, -1, 0, 1}, {-1, 1, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1},
                                {-1, 1, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1},
                                {1, -1, 0, 1}, {0, 1, 0, 1}});
  testing::SolidShader shader;
  gl.UseProgram(shader);
  gl.ClearStencil(10);
  gl.Clear(STENCIL_BUFFER_BIT | COLOR_BUFFER_BIT);
  gl.Enable(STENCIL_TEST);
  gl.StencilFuncSeparate(FRONT, ALWAYS, 0, 0xFF);
  gl.StencilFuncSeparate(BACK, EQUAL, 10, 0xFF);
  gl.StencilOpSeparate(FRONT, KEEP, KEEP, INCR);
  gl.StencilOpSeparate(BACK, KEEP, KEEP, DECR);
  gl.StencilMaskSeparate(BACK, 0xFF);
  // Left: two CCW triangles. Right: (0,-1),(0,1),(1,-1) and (1,1),(1,-1),(0,1) are both clockwise.
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.DrawArrays(TRIANGLES, 6, 6);
  CHECK(gl.ReadStencil(0, 1) == 11);
  CHECK(gl.ReadStencil(6, 2) == 9);
  // Back faces now fail (9 != 10): their sfail op runs instead.
  gl.StencilOpSeparate(BACK, ZERO, KEEP, KEEP);
  gl.DrawArrays(TRIANGLES, 6, 6);
  CHECK(gl.ReadStencil(6, 2) == 0);
  std::uint8_t px[4];
  gl.ReadPixel(6, 2, px);
  CHECK(px[0] == 255);  // from the first, passing draw
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("stencil ops see the depth result: sfail, dpfail, dppass", "[fragment_ops][stencil]") {
  Context gl(2, 2);
  testing::SolidShader shader;
  gl.Enable(DEPTH_TEST);
  gl.Enable(STENCIL_TEST);
  gl.ClearDepth(0.5);
  gl.ClearStencil(5);
  gl.Clear(DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  gl.StencilOp(ZERO, INCR, INVERT);
  gl.StencilFunc(EQUAL, 5, 0xFF);
  FullQuad(gl, shader, 0.5f, {1, 1, 1, 1});  // depth 0.75 fails LESS against 0.5: dpfail
  CHECK(gl.ReadStencil(0, 0) == 6);
  FullQuad(gl, shader, -0.5f, {1, 1, 1, 1});  // stencil 6 != 5: sfail
  CHECK(gl.ReadStencil(0, 0) == 0);
  gl.StencilFunc(EQUAL, 0, 0xFF);
  FullQuad(gl, shader, -0.5f, {1, 1, 1, 1});  // both pass: dppass
  CHECK(gl.ReadStencil(0, 0) == 255);
  gl.Disable(DEPTH_TEST);
  gl.StencilFunc(ALWAYS, 0, 0);
  gl.StencilOp(KEEP, ZERO, DECR);  // no depth test: dppass
  FullQuad(gl, shader, 0.9f, {1, 1, 1, 1});
  CHECK(gl.ReadStencil(0, 0) == 254);
}

TEST_CASE("polygon offset separates coplanar surfaces", "[fragment_ops][offset]") {
  Context gl(4, 4);
  testing::SolidShader shader;
  gl.Enable(DEPTH_TEST);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  FullQuad(gl, shader, 0.0f, {1, 0, 0, 1});
  FullQuad(gl, shader, 0.0f, {0, 1, 0, 1});  // coplanar: LESS fails
  std::uint8_t px[4];
  gl.ReadPixel(1, 1, px);
  CHECK(px[0] == 255);
  gl.Enable(POLYGON_OFFSET_FILL);
  gl.PolygonOffset(0.0f, -1.0f);  // one resolvable unit nearer: r = 2^-24 at depth 0.5
  FullQuad(gl, shader, 0.0f, {0, 1, 0, 1});
  gl.ReadPixel(1, 1, px);
  CHECK(px[1] == 255);
  CHECK(gl.ReadDepth(1, 1) == 0.5f - std::ldexp(1.0f, -24));
  // The slope term: a plane with dz/dx = 0.25 per pixel, factor 2 -> +0.5.
  gl.DepthFunc(ALWAYS);
  gl.PolygonOffset(2.0f, 0.0f);
  testing::MakeVertexArray(gl, {{-1, -1, -1, 1}, {1, -1, 1, 1}, {-1, 1, -1, 1}});  // z from 0 to 1 across x
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.ReadDepth(0, 0) == Approx(0.125f + 0.5f));
}

TEST_CASE("per-fragment state rejects bad enums and changes nothing", "[fragment_ops][errors]") {
  Context gl(1, 1);
  gl.StencilFunc(0x1234, 0, 0xFF);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.StencilFuncSeparate(CW, ALWAYS, 0, 0xFF);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.StencilOp(KEEP, 0x1234, KEEP);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.StencilOpSeparate(0, KEEP, KEEP, KEEP);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.StencilMaskSeparate(0x1234, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BlendFunc(SRC_ALPHA, 0x0309);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BlendFuncSeparate(ONE, ONE, 2, ONE);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BlendEquation(0x8009);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BlendEquationSeparate(FUNC_ADD, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  // Nothing changed: blending still replaces (ONE, ZERO, FUNC_ADD) and the stencil test still passes.
  gl.Enable(BLEND);
  gl.Enable(STENCIL_TEST);
  testing::SolidShader shader;
  gl.ClearColor(0, 0, 1, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  FullQuad(gl, shader, 0.0f, {1, 0, 0, 0.5f});
  std::uint8_t px[4];
  gl.ReadPixel(0, 0, px);
  CHECK((px[0] == 255 && px[2] == 0 && px[3] == 128));
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {
struct DepthWriter : softgl::Shader<DepthWriter, testing::NoVaryings> {
  static constexpr bool kWritesDepth = true;  // as a GLSL shader that writes gl_FragDepth
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>& in, FragmentOut& out) const {
    out.color[0] = glm::vec4(1);
    out.depth = in.frag_coord.x < 2.0f ? 0.1f : 0.9f;  // left half near, right half far
    return true;
  }
};

// A 4 x 1 target with depth cleared to 0.5, then `shader` over all of it at window depth 0.5 with LESS.
struct DepthProbe {
  Context gl{4, 1};
  template <class S>
  explicit DepthProbe(const S& shader) {
    gl.Enable(DEPTH_TEST);
    gl.ClearDepth(0.5);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});  // window z 0.5
    gl.UseProgram(shader);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  }
  std::uint8_t Red(int x) {
    std::uint8_t px[4];
    gl.ReadPixel(x, 0, px);
    return px[0];
  }
};

}  // namespace

TEST_CASE("a fragment shader may write depth (gl_FragDepth)", "[fragment_ops]") {
  DepthWriter shader;
  DepthProbe probe(shader);
  CHECK(probe.Red(0) == 255);
  CHECK(probe.gl.ReadDepth(0, 0) == 0.1f);
  CHECK(probe.Red(3) == 0);
  CHECK(probe.gl.ReadDepth(3, 0) == 0.5f);
}

namespace {

// OpenGL's blend on 8-bit operands (the fragment colour converted to the buffer's 8 bits, like the destination and
// the constant colour), evaluated in double on the values k / 255 and rounded once: the reference the 8-bit path
// must match byte for byte.
std::uint8_t ReferenceBlend8(const detail::BlendState& b, int channel, const std::uint8_t s8[4],
                             const std::uint8_t d8[4]) {
  double s[4], d[4], c[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = s8[i] / 255.0;
    d[i] = d8[i] / 255.0;
    c[i] = FloatToUnorm8(b.color[i]) / 255.0;
  }
  const bool alpha = channel == 3;
  auto factor = [&](Enum f) -> double {
    const int i = channel;
    switch (f) {
      case ZERO: return 0.0;
      case ONE: return 1.0;
      case SRC_COLOR: return s[i];
      case ONE_MINUS_SRC_COLOR: return 1.0 - s[i];
      case DST_COLOR: return d[i];
      case ONE_MINUS_DST_COLOR: return 1.0 - d[i];
      case SRC_ALPHA: return s[3];
      case ONE_MINUS_SRC_ALPHA: return 1.0 - s[3];
      case DST_ALPHA: return d[3];
      case ONE_MINUS_DST_ALPHA: return 1.0 - d[3];
      case CONSTANT_COLOR: return c[i];
      case ONE_MINUS_CONSTANT_COLOR: return 1.0 - c[i];
      case CONSTANT_ALPHA: return c[3];
      case ONE_MINUS_CONSTANT_ALPHA: return 1.0 - c[3];
      case SRC_ALPHA_SATURATE: return alpha ? 1.0 : std::min(s[3], 1.0 - d[3]);
      default: return 0.0;
    }
  };
  const Enum eq = alpha ? b.eq_alpha : b.eq_rgb;
  const double sf = factor(alpha ? b.src_alpha : b.src_rgb), df = factor(alpha ? b.dst_alpha : b.dst_rgb);
  double r;
  switch (eq) {
    case FUNC_SUBTRACT: r = s[channel] * sf - d[channel] * df; break;
    case FUNC_REVERSE_SUBTRACT: r = d[channel] * df - s[channel] * sf; break;
    case MIN: r = std::min(s[channel], d[channel]); break;
    case MAX: r = std::max(s[channel], d[channel]); break;
    default: r = s[channel] * sf + d[channel] * df; break;
  }
  return std::uint8_t(std::lround(std::clamp(r, 0.0, 1.0) * 255.0));  // never a tie: 255 * r is k / 255
}

// Every blend factor and equation.
const Enum kBlendFactors[] = {ZERO, ONE, SRC_COLOR, ONE_MINUS_SRC_COLOR, DST_COLOR, ONE_MINUS_DST_COLOR, SRC_ALPHA,
                              ONE_MINUS_SRC_ALPHA, DST_ALPHA, ONE_MINUS_DST_ALPHA, CONSTANT_COLOR,
                              ONE_MINUS_CONSTANT_COLOR, CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA, SRC_ALPHA_SATURATE};
const Enum kBlendEquations[] = {FUNC_ADD, FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN, MAX};

}  // namespace

TEST_CASE("blending into 8-bit buffers is OpenGL's formula on the 8-bit operands, correctly rounded",
          "[fragment_ops][blend]") {
  // Four blocks of four quads into an 8x8 RGBA8 target: the block path's instance for one RGBA8 buffer, and again
  // with a second colour buffer present, which takes its general instance for both. Every factor pair
  // and equation, alpha by the same pair or the swapped one, random colours (out of range and NaN included),
  // random colour masks.
  const auto& factors = kBlendFactors;
  const auto& equations = kBlendEquations;
  std::uint32_t seed = 7;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  constexpr int kSize = 8;
  std::vector<std::uint8_t> pixels(kSize * kSize * 4), second(kSize * kSize * 4);
  auto blocks = std::make_unique<detail::BlockBuffer>();
  int checked = 0;
  for (const bool two_buffers : {false, true}) {
    detail::RenderTarget target;
    target.width = target.height = kSize;
    target.color[0].data = pixels.data();
    target.color[0].layout = detail::TexelLayout::kUnorm8x4;
    target.color[0].pitch = kSize;
    if (two_buffers) target.color[1] = detail::ColorBuffer{second.data(), detail::TexelLayout::kUnorm8x4, false, kSize};
    for (Enum src : factors)
      for (Enum dst : factors)
        for (Enum eq : equations)
          for (const bool same_equation : {false, true})  // one equation for all four channels, or two
            // Alpha by the same pair (SRC_ALPHA, ONE_MINUS_SRC_ALPHA and FUNC_ADD take a path of their own) or by
            // the swapped one.
            for (const bool same_pair : {false, true}) {
              detail::FragmentOpsState state;
              state.blend_buffers = 0xFF;
              state.blend.src_rgb = src;
              state.blend.dst_rgb = dst;
              state.blend.src_alpha = same_pair ? src : dst;
              state.blend.dst_alpha = same_pair ? dst : src;
              state.blend.eq_rgb = eq;
              state.blend.eq_alpha = same_equation ? eq : equations[(int(next()) % 5)];
              state.blend.color = glm::vec4(0.3f, 1.2f, -0.1f, 0.55f);
              std::uint8_t mask = 0;
              for (int c = 0; c < 4; ++c) mask |= std::uint8_t(((next() % 5) != 0) << c);
              for (std::uint8_t& m : state.color_masks) m = mask;
              for (auto& v : pixels) v = std::uint8_t(next());
              const std::vector<std::uint8_t> before = pixels;
              blocks->count = 4;
              for (int b = 0; b < 4; ++b) {  // block b: the quads of rows 2b and 2b + 1, in a scrambled order
                blocks->quads[b] = 4;
                for (int q = 0; q < 4; ++q) {
                  blocks->qx[b][q] = ((q + b) % 4) * 2;
                  blocks->qy[b][q] = 2 * b;
                }
                blocks->live[b] = 0xFFFFu;
                for (int o = 0; o < 2; ++o)
                  for (int c = 0; c < 4; ++c)
                    for (int l = 0; l < softgl::kLanes; ++l)
                      blocks->out[b].color[o][c].v.Set(l, float(int(next() % 1400) - 200) / 1000.0f);  // [-0.2, 1.2)
              }
              blocks->out[1].color[0][1].v.Set(5, std::numeric_limits<float>::quiet_NaN());
              detail::ApplyFragmentOps(state, detail::PlanFragmentOps(state, target), *blocks, false, target);
              for (int b = 0; b < 4; ++b)
                for (int l = 0; l < softgl::kLanes; ++l) {
                  const int x = blocks->X(b, l), y = blocks->Y(b, l);
                  const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
                  std::uint8_t s8[4];
                  for (int c = 0; c < 4; ++c) s8[c] = FloatToUnorm8(blocks->out[b].color[0][c][l]);  // NaN reads 0
                  for (int c = 0; c < 4; ++c) {
                    const std::uint8_t want =
                        state.Writes(0, c) ? ReferenceBlend8(state.blend, c, s8, &before[i])
                                            : before[i + std::size_t(c)];
                    if (pixels[i + std::size_t(c)] != want) {
                      INFO("src 0x" << std::hex << src << " dst 0x" << dst << " eq 0x" << eq << std::dec << " channel "
                                    << c << " two buffers " << two_buffers);
                      CHECK(int(pixels[i + std::size_t(c)]) == int(want));
                    }
                    ++checked;
                  }
                }
            }
  }
  CHECK(checked == 2 * 15 * 15 * 5 * 2 * 2 * 64 * 4);
}

namespace {

// Writes out.depth like DepthWriter above but does not declare it; counts its invocations.
struct CountingShader : softgl::Shader<CountingShader, testing::NoVaryings> {
  std::shared_ptr<std::atomic<int>> calls = std::make_shared<std::atomic<int>>(0);
  glm::vec4 color{1.0f};
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
    ++*calls;
    out.color[0] = color;
    out.depth = 0.0f;  // not declared (no kWritesDepth): ignored
    return true;
  }
};

}  // namespace

TEST_CASE("a depth write the shader does not declare is ignored", "[fragment_ops]") {
  CountingShader shader;
  DepthProbe probe(shader);
  CHECK(probe.Red(0) == 0);  // 0.5 < 0.5 fails: the written 0.0 did not count
  CHECK(probe.gl.ReadDepth(0, 0) == 0.5f);
}

TEST_CASE("the early depth test skips hidden fragments without changing the image", "[fragment_ops]") {
  // A near quad, then a far one behind it: with LESS the far quad's fragments fail the depth test before the
  // shader runs. The same draws with GL's late test give the same image (checked against ALWAYS-then-masked).
  const int n = 64;
  auto render = [&](Enum func, int* calls) {
    Context gl(n, n);
    gl.Enable(DEPTH_TEST);
    gl.DepthFunc(func);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    CountingShader shader;
    gl.UseProgram(shader);
    const float z_near = func == GREATER ? 0.5f : -0.5f;
    testing::MakeVertexArray(gl, {{-1, -1, z_near, 1}, {1, -1, z_near, 1}, {-1, 1, z_near, 1}, {1, 1, z_near, 1},
                                  {-1, -1, -z_near, 1}, {1, -1, -z_near, 1}, {-1, 1, -z_near, 1}, {1, 1, -z_near, 1}});
    if (func == GREATER) gl.ClearDepth(0.0);
    gl.Clear(DEPTH_BUFFER_BIT);
    shader.color = glm::vec4(1, 0, 0, 1);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    shader.color = glm::vec4(0, 1, 0, 1);  // the second draw's own copy of the shader is green
    gl.DrawArrays(TRIANGLE_STRIP, 4, 4);
    softgl::Image img = gl.ReadPixels();
    *calls = *shader.calls;
    return img;
  };
  for (Enum func : {LESS, GREATER}) {
    int calls = 0;
    const softgl::Image img = render(func, &calls);
    CHECK(calls == n * n);  // the hidden quad was never shaded
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
      REQUIRE(img.rgba[i] == 255);  // red: the near quad everywhere
      REQUIRE(img.rgba[i + 1] == 0);
    }
  }
  int calls = 0;
  render(NOTEQUAL, &calls);  // not monotonic: every fragment is shaded
  CHECK(calls == 2 * n * n);
}

namespace {

// A colour format as a render target holds it.
struct TargetFormat {
  const char* name;
  detail::TexelLayout layout;
  bool rgb_only = false, srgb = false;
};
const TargetFormat kTargetFormats[] = {
    {"RGBA8", detail::TexelLayout::kUnorm8x4},
    {"RGB8", detail::TexelLayout::kUnorm8x4, true},
    {"RG8", detail::TexelLayout::kUnorm8x2},
    {"R8", detail::TexelLayout::kUnorm8x1},
    {"SRGB8_ALPHA8", detail::TexelLayout::kUnorm8x4, false, true},
    {"SRGB8", detail::TexelLayout::kUnorm8x4, true, true},
    {"RGBA32F", detail::TexelLayout::kFloat32x4},
    {"RG32F", detail::TexelLayout::kFloat32x2},
    {"R32F", detail::TexelLayout::kFloat32x1},
    {"RGBA16F", detail::TexelLayout::kFloat16x4},
    {"RG16F", detail::TexelLayout::kFloat16x2},
    {"R16F", detail::TexelLayout::kFloat16x1},
    {"R11F_G11F_B10F", detail::TexelLayout::kFloat11x11x10},
    {"RGB565", detail::TexelLayout::kUnorm565},
    {"RGBA4", detail::TexelLayout::kUnorm4444},
    {"RGB5_A1", detail::TexelLayout::kUnorm5551},
    {"RGB10_A2", detail::TexelLayout::kUnorm1010102},
    {"RGBA16", detail::TexelLayout::kUnorm16x4},
    {"RG16", detail::TexelLayout::kUnorm16x2},
    {"R16", detail::TexelLayout::kUnorm16x1},
    {"RGBA8UI", detail::IntegerLayoutFor(4, 1, false)},
    {"RGBA8I", detail::IntegerLayoutFor(4, 1, true)},
    {"RG8UI", detail::IntegerLayoutFor(2, 1, false)},
    {"R8I", detail::IntegerLayoutFor(1, 1, true)},
    {"RGBA16UI", detail::IntegerLayoutFor(4, 2, false)},
    {"RG16I", detail::IntegerLayoutFor(2, 2, true)},
    {"R16UI", detail::IntegerLayoutFor(1, 2, false)},
    {"RGBA32I", detail::IntegerLayoutFor(4, 4, true)},
    {"RG32UI", detail::IntegerLayoutFor(2, 4, false)},
    {"R32UI", detail::IntegerLayoutFor(1, 4, false)},
    {"RGB10_A2UI", detail::TexelLayout::kUint1010102},
};

// Buffers of a render target for the comparison below: colour buffers of the given formats, float depth and 8-bit
// stencil, each row `pitch` texels.
struct TargetBuffers {
  static constexpr int kSize = 8, kPitch = 11;
  std::vector<std::uint8_t> color[kMaxColorOutputs];
  std::vector<float> depth = std::vector<float>(kSize * kPitch);
  std::vector<std::uint8_t> stencil = std::vector<std::uint8_t>(kSize * kPitch);
  detail::RenderTarget target;
  explicit TargetBuffers(const std::vector<const TargetFormat*>& formats) {
    target.width = target.height = kSize;
    for (std::size_t o = 0; o < formats.size(); ++o) {
      if (!formats[o]) continue;
      const int bytes = detail::BytesPerTexel(formats[o]->layout);
      color[o].resize(std::size_t(kSize * kPitch * bytes));
      detail::ColorBuffer& cb = target.color[o];
      cb.layout = formats[o]->layout;
      cb.rgb_only = formats[o]->rgb_only;
      cb.srgb = formats[o]->srgb;
      cb.pitch = kPitch;
    }
    target.depth = depth.data();
    target.depth_pitch = target.stencil_pitch = kPitch;
    target.stencil = stencil.data();
    Point();
  }
  TargetBuffers(const TargetBuffers& other) : color{}, depth(other.depth), stencil(other.stencil), target(other.target) {
    for (int o = 0; o < kMaxColorOutputs; ++o) color[o] = other.color[o];
    Point();
  }
  void Point() {
    for (int o = 0; o < kMaxColorOutputs; ++o) target.color[o].data = color[o].empty() ? nullptr : color[o].data();
    target.depth = depth.data();
    target.stencil = stencil.data();
  }
};

}  // namespace

TEST_CASE("every colour format, draw buffer set and depth-stencil state: the block path writes the reference's bytes",
          "[fragment_ops][formats]") {
  // Random states, buffer contents (any bits: NaN, infinite and huge floats included), fragment colours (out of
  // range, NaN, infinite) and depths; the block path (ApplyFragmentOps) against the lane-by-lane reference on a copy
  // of the same buffers. Each format alone first, then sets of up to eight of them (kMaxColorOutputs).
  const auto& factors = kBlendFactors;
  const auto& equations = kBlendEquations;
  const Enum funcs[] = {NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS};
  const Enum stencil_ops[] = {KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP};
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(), 1e30f, -1e30f, 65520.0f, 1e-8f, -0.0f};
  std::uint32_t seed = 11;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  auto value = [&](float lo, float hi) {
    if (next() % 16 == 0) return specials[next() % 8];
    return lo + (hi - lo) * float(next() % 100000) / 100000.0f;
  };
  constexpr int kFormats = int(std::size(kTargetFormats));
  auto blocks = std::make_unique<detail::BlockBuffer>();
  int compared = 0;
  for (int round = 0; round < 2 * kFormats + 400; ++round) {
    std::vector<const TargetFormat*> formats;
    if (round < 2 * kFormats) {
      formats.push_back(&kTargetFormats[round % kFormats]);  // alone, twice
    } else {
      const int n = 1 + int(next() % kMaxColorOutputs);
      for (int o = 0; o < n; ++o) formats.push_back(next() % 5 == 0 ? nullptr : &kTargetFormats[next() % kFormats]);
    }
    TargetBuffers a(formats);
    for (auto& buffer : a.color)
      for (auto& byte : buffer) byte = std::uint8_t(next());
    if (next() % 2) {  // or values in range, as a buffer mostly holds
      for (int o = 0; o < kMaxColorOutputs; ++o)
        if (a.target.color[o].Present())
          for (int y = 0; y < TargetBuffers::kSize; ++y)
            for (int x = 0; x < TargetBuffers::kSize; ++x) {
              const bool mask[4] = {true, true, true, true};
              a.target.color[o].Store(x, y, glm::vec4(value(0, 1), value(0, 1), value(0, 1), value(0, 1)), mask);
            }
    }
    for (auto& d : a.depth) d = value(0.0f, 1.0f);
    for (auto& s : a.stencil) s = std::uint8_t(next());

    detail::FragmentOpsState state;
    // BLEND and the colour mask per draw buffer: mostly all alike, a quarter of the rounds each its own.
    const bool per_buffer = next() % 4 == 0;
    state.blend_buffers = next() % 4 != 0 ? 0xFF : 0;
    if (per_buffer) state.blend_buffers = std::uint8_t(next());
    state.blend.src_rgb = factors[next() % 15];
    state.blend.dst_rgb = factors[next() % 15];
    state.blend.src_alpha = factors[next() % 15];
    state.blend.dst_alpha = factors[next() % 15];
    state.blend.eq_rgb = equations[next() % 5];
    state.blend.eq_alpha = equations[next() % 5];
    state.blend.color = glm::vec4(value(-0.2f, 1.2f), value(-0.2f, 1.2f), value(-0.2f, 1.2f), value(-0.2f, 1.2f));
    state.logic_op = next() % 5 == 0;  // (which turns blending off)
    state.logic_mode = CLEAR + Enum(next() % 16);
    for (int o = 0; o < kMaxColorOutputs; ++o) {
      std::uint8_t mask = 0;
      for (int c = 0; c < 4; ++c) mask |= std::uint8_t((next() % 4 != 0) << c);
      state.color_masks[o] = o == 0 || per_buffer ? mask : state.color_masks[0];
    }
    state.depth_test = next() % 2;
    state.depth_func = funcs[next() % 8];
    state.depth_write = next() % 4 != 0;
    state.stencil_test = next() % 3 == 0;
    for (detail::StencilFace* face : {&state.front, &state.back}) {
      face->func = funcs[next() % 8];
      face->ref = int(next() % 300) - 20;
      face->value_mask = next();
      face->write_mask = next();
      face->sfail = stencil_ops[next() % 8];
      face->dpfail = stencil_ops[next() % 8];
      face->dppass = stencil_ops[next() % 8];
    }
    blocks->count = 4;
    blocks->front_facing = next() % 2;
    // A third of the rounds into an odd-sized target (7 wide, or high, or both: its edge blocks lane by lane, the
    // others on the vector operations), its lanes outside it not live, as the rasterizer leaves them.
    if (next() % 3 == 0) {
      const int odd = 1 + int(next() % 3);
      a.target.width = odd & 1 ? 7 : 8;
      a.target.height = odd & 2 ? 7 : 8;
    }
    for (int b = 0; b < 4; ++b) {
      // Block b: the quads of rows 2b and 2b + 1, in a scrambled order; sometimes fewer than four, the unused ones
      // at the first one's place without live lanes (as the rasterizer leaves them).
      const int quads = next() % 4 == 0 ? 1 + int(next() % 3) : 4;
      blocks->quads[b] = quads;
      for (int q = 0; q < 4; ++q) {
        blocks->qx[b][q] = (((q < quads ? q : 0) + b) % 4) * 2;
        blocks->qy[b][q] = 2 * b;
      }
      blocks->live[b] = next() % 3 == 0 ? 0xFFFFu : next() & 0xFFFFu;
      blocks->live[b] &= (1u << (4 * quads)) - 1u;
      for (int l = 0; l < 4 * quads; ++l)
        if (blocks->X(b, l) >= a.target.width || blocks->Y(b, l) >= a.target.height) blocks->live[b] &= ~(1u << l);
      // Colours as floats, or (a third of the blocks) as integers' bits, as integer outputs give them: small
      // numbers of either sign, or any 32 bits.
      const bool integers = next() % 3 == 0;
      for (int l = 0; l < softgl::kLanes; ++l) {
        blocks->frag_coord[b][2][l] = value(-0.1f, 1.1f);
        for (int o = 0; o < kMaxColorOutputs; ++o)
          for (int c = 0; c < 4; ++c) {
            const std::uint32_t bits = next() % 2 ? next() % 2048 - 1024 : (next() << 8) ^ next();
            blocks->out[b].color[o][c].v.Set(l, integers ? std::bit_cast<float>(bits) : value(-0.3f, 1.3f));
          }
      }
    }
    TargetBuffers b(a);
    const detail::FragmentOpsPlan plan = detail::PlanFragmentOps(state, a.target);
    detail::ApplyFragmentOps(state, plan, *blocks, false, a.target);
    detail::ApplyFragmentOpsReference(state, plan, *blocks, false, b.target);
    std::string names;
    for (const TargetFormat* f : formats) names += std::string(f ? f->name : "none") + " ";
    INFO("round " << round << ": " << names << a.target.width << " x " << a.target.height << ", blend 0x" << std::hex
                  << int(state.blend_buffers) << std::dec
                  << ", logic op 0x" << std::hex << state.LogicMode() << std::dec);
    for (int o = 0; o < kMaxColorOutputs; ++o) {
      if (a.color[o] != b.color[o]) {
        std::size_t i = 0;
        while (a.color[o][i] == b.color[o][i]) ++i;
        INFO("buffer " << o << ", first differing byte " << i);
        CHECK(a.color[o] == b.color[o]);
      }
    }
    CHECK(std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)) == 0);
    CHECK(a.stencil == b.stencil);
    ++compared;
  }
  CHECK(compared == 2 * kFormats + 400);
}

TEST_CASE("sRGB encoding in the block path: every step between two codes, on both sides", "[fragment_ops][formats]") {
  // The colours at each step of SrgbEncode8 and the float just below it, written without blending into an
  // SRGB8_ALPHA8 buffer (FRAMEBUFFER_SRGB on) by the block path and by the reference.
  const detail::SrgbLaneTables& tables = detail::SrgbLanes();
  std::vector<float> values;
  for (int k = 0; k < 255; ++k) {
    values.push_back(tables.up[k]);
    values.push_back(std::nextafter(tables.up[k], 0.0f));
  }
  for (int i = 0; i < detail::SrgbLaneTables::kBuckets; i += 7) {  // bucket edges
    const std::uint32_t bits = std::uint32_t(detail::SrgbLaneTables::kBucket0 + i) << 16;
    float x;
    std::memcpy(&x, &bits, 4);
    values.push_back(x);
    values.push_back(std::nextafter(x, 0.0f));
  }
  for (const float x : {1e-5f, 1e-20f, 1e-38f, 1e-45f, 1.2e-4f, 0.99999994f})  // below the buckets, and the top
    values.push_back(x);
  // What the bucket table rests on: at most one step a bucket, none in bucket 0 (which smaller values take too).
  std::vector<int> steps(detail::SrgbLaneTables::kBuckets);
  for (int k = 0; k < 255; ++k) {
    std::uint32_t bits;
    std::memcpy(&bits, &tables.up[k], 4);
    const int i = int(bits >> 16) - detail::SrgbLaneTables::kBucket0;
    REQUIRE(i >= 0);
    REQUIRE(i < detail::SrgbLaneTables::kBuckets);
    ++steps[std::size_t(i)];
  }
  CHECK(steps[0] == 0);
  CHECK(*std::max_element(steps.begin(), steps.end()) == 1);
  auto blocks = std::make_unique<detail::BlockBuffer>();
  std::size_t at = 0;
  int checked = 0;
  while (at < values.size()) {
    TargetBuffers a({&kTargetFormats[4]});
    blocks->count = 4;
    for (int b = 0; b < 4; ++b) {
      blocks->quads[b] = 4;
      for (int q = 0; q < 4; ++q) {
        blocks->qx[b][q] = q * 2;
        blocks->qy[b][q] = 2 * b;
      }
      blocks->live[b] = 0xFFFFu;
      for (int l = 0; l < softgl::kLanes; ++l)
        for (int c = 0; c < 4; ++c) {
          blocks->out[b].color[0][c].v.Set(l, values[at % values.size()]);
          ++at;
        }
    }
    TargetBuffers b(a);
    detail::FragmentOpsState state;
    const detail::FragmentOpsPlan plan = detail::PlanFragmentOps(state, a.target);
    detail::ApplyFragmentOps(state, plan, *blocks, false, a.target);
    detail::ApplyFragmentOpsReference(state, plan, *blocks, false, b.target);
    CHECK(a.color[0] == b.color[0]);
    // and the reference is SrgbEncode8
    for (int b2 = 0; b2 < 4; ++b2)
      for (int l = 0; l < softgl::kLanes; ++l)
        for (int c = 0; c < 3; ++c) {
          const int x = blocks->X(b2, l), y = blocks->Y(b2, l);
          const std::uint8_t want = detail::SrgbEncode8(blocks->out[b2].color[0][c][l]);
          if (b.color[0][(std::size_t(y) * TargetBuffers::kPitch + std::size_t(x)) * 4 + std::size_t(c)] != want)
            FAIL_CHECK("reference differs from SrgbEncode8");
          ++checked;
        }
  }
  CHECK(checked * 4 == int(at) * 3);  // red, green and blue of every value written
}

// Per-fragment operations: depth comparisons, depth writes and masks, colour conversion.
#include <catch2/catch.hpp>

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

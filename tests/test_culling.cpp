// Facing and culling: window-space signed area, both windings, each cull mode; and through the API.
#include <catch2/catch.hpp>

#include "culling.h"
#include "helpers.h"

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

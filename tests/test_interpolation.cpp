// Interpolation: perspective-correct varyings and linear window-space depth, checked against ray casting.
#include <memory>
#include <mutex>

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "helpers.h"

using namespace softgl;

TEST_CASE("varyings are perspective-correct: they match the world point seen through each pixel", "[interpolation]") {
  constexpr int N = 64;
  Context gl(N, N);
  const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 50.0f);
  // A floor triangle receding from the camera (at the origin, looking down -z).
  const glm::vec4 world[3] = {{-3, -1, -1.5f, 1}, {3, -1, -1.5f, 1}, {0, -1, -30, 1}};
  std::vector<glm::vec4> clip, values;
  for (const glm::vec4& p : world) {
    clip.push_back(proj * p);
    values.push_back(p);
  }
  testing::MakeVertexArray(gl, clip, values);
  testing::CaptureShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.Finish();  // fragments are shaded when the context renders
  REQUIRE(shader.samples.size() > 200);

  const glm::mat4 inv = glm::inverse(proj);
  int checked = 0;
  for (const auto& [pixel, s] : shader.samples) {
    // The ray through the pixel centre, intersected with the plane y = -1.
    const float nx = (float(pixel.first) + 0.5f) / N * 2 - 1, ny = (float(pixel.second) + 0.5f) / N * 2 - 1;
    glm::vec4 a = inv * glm::vec4(nx, ny, -1, 1), b = inv * glm::vec4(nx, ny, 1, 1);
    a /= a.w;
    b /= b.w;
    const float t = (-1.0f - a.y) / (b.y - a.y);
    const glm::vec3 expect = glm::vec3(a + t * (b - a));
    INFO("pixel " << pixel.first << ", " << pixel.second);
    CHECK(s.value.x == Approx(expect.x).margin(2e-3 * std::fabs(expect.z)));
    CHECK(s.value.z == Approx(expect.z).epsilon(1e-3));
    CHECK(s.value.y == Approx(-1.0f).margin(1e-4));
    // Window depth is linear in window space: it matches the projected depth of that world point.
    const glm::vec4 c = proj * glm::vec4(expect, 1.0f);
    CHECK(s.frag_coord.z == Approx(c.z / c.w * 0.5f + 0.5f).margin(1e-4));
    CHECK(s.frag_coord.w == Approx(1.0f / c.w).epsilon(1e-3));
    CHECK(s.hits == 1);
    ++checked;
  }
  CHECK(checked == int(shader.samples.size()));
}

TEST_CASE("with w = 1 everywhere, varyings are affine in window space", "[interpolation]") {
  constexpr int N = 16;
  Context gl(N, N);
  // value = (x_window, y_window) at each vertex: the interpolated value must equal the pixel centre.
  const glm::vec2 win[3] = {{0.0f, 0.0f}, {16.0f, 3.0f}, {5.0f, 16.0f}};
  std::vector<glm::vec4> clip, values;
  for (const glm::vec2& w : win) {
    clip.push_back(testing::WindowToClip(w.x, w.y, N, N));
    values.push_back(glm::vec4(w, 0, 0));
  }
  testing::MakeVertexArray(gl, clip, values);
  testing::CaptureShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.Finish();  // fragments are shaded when the context renders
  REQUIRE(!shader.samples.empty());
  for (const auto& [pixel, s] : shader.samples) {
    CHECK(s.value.x == Approx(float(pixel.first) + 0.5f).margin(1e-4));
    CHECK(s.value.y == Approx(float(pixel.second) + 0.5f).margin(1e-4));
    CHECK(s.frag_coord.x == float(pixel.first) + 0.5f);
  }
}

TEST_CASE("derivatives across the 2x2 quad", "[interpolation]") {
  struct UV {
    glm::vec2 uv;
  };
  struct DerivShader : softgl::Shader<DerivShader, UV> {
    struct Seen {
      std::mutex mutex;
      glm::vec2 ddx{0}, ddy{0};
    };
    std::shared_ptr<Seen> seen = std::make_shared<Seen>();  // shared with the draw's copy of the shader
    void Vertex(const softgl::VertexIn& in, softgl::VertexOut<UV>& out) const {
      out.position = in.attrib[0];
      out.varyings.uv = glm::vec2(in.attrib[1]);
    }
    bool Fragment(const softgl::FragmentIn<UV>& in, softgl::FragmentOut& out) const {
      std::lock_guard<std::mutex> lock(seen->mutex);
      seen->ddx = in.dFdx(&UV::uv);
      seen->ddy = in.dFdy(&UV::uv);
      out.color[0] = glm::vec4(1);
      return true;
    }
  };
  Context gl(8, 8);
  // uv = (window x / 8, 2 * window y / 8) over the whole viewport.
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}}, {{0, 0, 0, 0}, {2, 0, 0, 0}, {0, 4, 0, 0}});
  DerivShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.Finish();
  CHECK(shader.seen->ddx.x == Approx(1.0f / 8));
  CHECK(shader.seen->ddx.y == Approx(0.0f).margin(1e-6));
  CHECK(shader.seen->ddy.y == Approx(2.0f / 8));
}

// A program outside the softgl tree: draws one triangle with softgl and frames a box with softgl::model's camera,
// then checks a few pixels.
#include <cmath>
#include <cstdio>

#include <softgl/model.h>
#include <softgl/softgl.h>

struct Flat {};
struct FlatShader : softgl::Shader<FlatShader, Flat> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Flat>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const softgl::FragmentIn<Flat>&, softgl::FragmentOut& out) const {
    out.color[0] = glm::vec4(1.0f, 0.5f, 0.0f, 1.0f);
    return true;
  }
};

int main() {
  softgl::Context gl(16, 16);
  const float tri[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};  // covers the whole viewport
  const auto vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof tri, tri);
  gl.VertexAttributePointer(0, 4, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  FlatShader shader;
  gl.UseProgram(shader);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  std::uint8_t a[4], b[4];
  gl.ReadPixel(0, 0, a);
  gl.ReadPixel(15, 15, b);
  // softgl::model: a camera that frames the unit box looks at its centre.
  const softgl::Camera cam = softgl::Camera::Frame(softgl::Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)}, 1.0f);
  const glm::vec4 centre = cam.Projection(1.0f) * cam.View() * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  const bool centred = std::abs(centre.x / centre.w) < 1e-4f && std::abs(centre.y / centre.w) < 1e-4f;
  const bool ok = gl.GetError() == softgl::NO_ERROR && a[0] == 255 && a[1] == 128 && b[0] == 255 && b[2] == 0 &&
                  centred;
  std::printf("consumer: %s (C++ level %ld)\n", ok ? "ok" : "wrong result", long(__cplusplus));
  return ok ? 0 : 1;
}

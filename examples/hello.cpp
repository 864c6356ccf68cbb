// hello — the program of docs/guide.md: one indexed, colour-interpolated triangle. Writes hello.png.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include <softgl/softgl.h>

struct Vertex {
  float pos[3];
  std::uint8_t color[4];
};

using namespace softgl;  // the lane types: Float, vec3, vec4, ... (softgl/lanes.h)

struct Vary {
  vec3 color;
};

// A wide shader: each call runs 16 vertices or 16 fragments at once, in code that reads like GLSL.
struct ColorShader : Shader<ColorShader, Vary> {
  glm::mat4 mvp{1.0f};  // a uniform
  void Vertex(const VertexLanes& in, VertexLanesOut<Vary>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.color = vec3(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<Vary>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.color, 1.0f);
  }
};

int main(int argc, char** argv) {
  const Vertex vertices[] = {{{-0.8f, -0.7f, 0}, {255, 0, 0, 255}},
                             {{0.8f, -0.7f, 0}, {0, 255, 0, 255}},
                             {{0.0f, 0.8f, 0}, {0, 0, 255, 255}}};
  const std::uint32_t indices[] = {0, 1, 2};

  softgl::Context gl(640, 480);  // RGBA8 colour, float depth, 8-bit stencil
  std::uint32_t vbo = gl.GenBuffer(), ebo = gl.GenBuffer(), vao = gl.GenVertexArray();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof vertices, vertices);
  gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, ebo);  // recorded in the vertex array
  gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, sizeof(Vertex), offsetof(Vertex, pos));
  gl.VertexAttributePointer(1, 4, softgl::UNSIGNED_BYTE, true, sizeof(Vertex), offsetof(Vertex, color));
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);

  ColorShader shader;  // shader.mvp is a uniform: set it any time before the draw
  gl.UseProgram(shader);
  gl.Enable(softgl::DEPTH_TEST);
  gl.ClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.DrawElement(softgl::TRIANGLES, 3, softgl::UNSIGNED_INT, 0);
  if (gl.GetError() != softgl::NO_ERROR) return 1;
  const std::string path = std::string(argc > 1 ? argv[1] : ".") + "/hello.png";
  if (!softgl::WritePng(path, gl.ReadPixels())) return 1;
  std::printf("%s\n", path.c_str());
  return 0;
}

// fuzz_pipeline — random vertex and index data (NaN, infinities, 1e30, w <= 0 included) and random state through
// the whole pipeline: fetch, clipping, culling, rasterization, per-fragment operations.
#include <algorithm>
#include <cstring>
#include <vector>

#include <softgl/softgl.h>

#include "fuzz_input.h"

namespace {

struct Vary {
  glm::vec4 color;
  glm::vec2 uv;
};

struct PipelineShader : softgl::Shader<PipelineShader, Vary> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Vary>& out) const {
    out.position = in.attrib[0];
    out.point_size = in.attrib[1].w * 16.0f;
    out.varyings.color = in.attrib[1];
    out.varyings.uv = glm::vec2(in.attrib[0]);
  }
  bool Fragment(const softgl::FragmentIn<Vary>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.color + in.Texture(0, &Vary::uv);
    return true;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace softgl;
  fuzz::Input in(data, size);
  Context gl(1 + in.Byte() % 40, 1 + in.Byte() % 40);
  const int vertex_count = in.Byte() % 65;
  std::vector<float> vertices(std::size_t(std::max(vertex_count, 0)) * 8);
  for (float& f : vertices) f = in.Float();
  const int index_count = in.Byte() % 97;
  std::vector<std::uint32_t> indices(std::size_t(std::max(index_count, 0)));
  for (std::uint32_t& i : indices) i = in.Byte() < 250 ? in.Byte() % 70 : in.Get<std::uint32_t>();

  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer(), ebo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(float)), vertices.data());
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
  gl.VertexAttributePointer(0, 4, FLOAT, false, 32, 0);
  gl.VertexAttributePointer(1, 4, FLOAT, false, 32, 16);
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  const std::uint8_t texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, texels);
  gl.GenerateMipmap(TEXTURE_2D);
  PipelineShader shader;
  gl.UseProgram(shader);

  const std::uint8_t flags = in.Byte();
  if (flags & 1) gl.Enable(CULL_FACE);
  if (flags & 2) gl.Enable(DEPTH_TEST);
  if (flags & 4) gl.Enable(BLEND);
  if (flags & 8) gl.Enable(STENCIL_TEST);
  if (flags & 16) gl.Enable(POLYGON_OFFSET_FILL);
  if (flags & 32) gl.Enable(PROGRAM_POINT_SIZE);
  if (flags & 64) {
    gl.Enable(SCISSOR_TEST);
    gl.Scissor(in.Int(-8, 40), in.Int(-8, 40), in.Int(0, 48), in.Int(0, 48));
  }
  gl.PolygonOffset(in.Float(), in.Float());
  const Enum polygon_modes[] = {FILL, LINE, POINT};
  gl.PolygonMode(FRONT_AND_BACK, polygon_modes[in.Byte() % 3]);
  gl.PointSize(in.Float());
  gl.DepthRange(in.Float(), in.Float());
  gl.Viewport(in.Int(-40, 40), in.Int(-40, 40), in.Int(0, 80), in.Int(0, 80));
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  const Enum modes[] = {POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN};
  const Enum mode = modes[in.Byte() % 7];
  if (in.Byte() & 1) gl.DrawElement(mode, index_count, UNSIGNED_INT, 0);
  else gl.DrawArrays(mode, in.Int(0, 8), vertex_count);
  (void)gl.ReadPixels();
  return 0;
}

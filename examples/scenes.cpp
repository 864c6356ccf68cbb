// scenes.cpp — geometry, shaders and state for the example scenes.
#include "scenes.h"

#include "scene_kit.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes {

using namespace kit;

softgl::Image Triangle(int width, int height) {
  softgl::Context gl(width, height);
  const float positions[] = {-0.8f, -0.7f, 0.8f, -0.7f, 0.0f, 0.8f};
  const std::uint8_t colors[] = {255, 0, 0, 0, 255, 0, 0, 0, 255};
  const std::uint32_t vao = gl.GenVertexArray(), pos_vbo = gl.GenBuffer(), color_vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, pos_vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof positions, positions);
  gl.VertexAttributePointer(0, 2, softgl::FLOAT, false, 0, 0);
  gl.BindBuffer(softgl::ARRAY_BUFFER, color_vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof colors, colors);
  gl.VertexAttributePointer(1, 3, softgl::UNSIGNED_BYTE, true, 0, 0);
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);
  ColorShader shader;
  gl.UseProgram(shader);
  gl.ClearColor(0.08f, 0.08f, 0.1f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

softgl::Image Cube(int width, int height, float angle) {
  softgl::Context gl(width, height);
  const Mesh cube = MakeCube();
  UploadLitMesh(gl, cube);
  LitShader shader;
  shader.model = glm::rotate(glm::mat4(1.0f), angle, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.2f, 2.6f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  shader.mvp = Projection(width, height, 45.0f, 0.1f, 10.0f) * view * shader.model;
  gl.UseProgram(shader);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  gl.ClearColor(0.1f, 0.12f, 0.16f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.DrawElement(softgl::TRIANGLES, int(cube.indices.size()), softgl::UNSIGNED_INT, 0);
  return gl.ReadPixels();
}

softgl::Image Wireframe(int width, int height) {
  softgl::Context gl(width, height);
  const Mesh torus = MakeTorus(24, 12, 0.65f, 0.28f);
  UploadLitMesh(gl, torus);
  LitShader shader;
  shader.model = glm::rotate(glm::mat4(1.0f), 0.6f, glm::vec3(1.0f, 0.0f, 0.2f));
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.8f, 2.4f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  shader.mvp = Projection(width, height, 45.0f, 0.1f, 10.0f) * view * shader.model;
  gl.UseProgram(shader);
  gl.Enable(softgl::DEPTH_TEST);
  gl.DepthFunc(softgl::LEQUAL);
  gl.ClearColor(0.05f, 0.05f, 0.08f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const int count = int(torus.indices.size());
  // A dim filled pass hides the back half; then the edges and the vertices on top of it. The filled pass is
  // pushed slightly back in depth so that the edges, interpolated along lines, do not fight with it.
  shader.brightness = 0.3f;
  gl.DepthRange(0.002, 1.0);
  gl.DrawElement(softgl::TRIANGLES, count, softgl::UNSIGNED_INT, 0);
  gl.DepthRange(0.0, 0.998);
  gl.PolygonMode(softgl::FRONT_AND_BACK, softgl::LINE);
  shader.brightness = 1.0f;
  gl.DrawElement(softgl::TRIANGLES, count, softgl::UNSIGNED_INT, 0);
  gl.PolygonMode(softgl::FRONT_AND_BACK, softgl::POINT);
  gl.PointSize(3.0f);
  shader.brightness = 1.6f;
  gl.DrawElement(softgl::TRIANGLES, count, softgl::UNSIGNED_INT, 0);
  return gl.ReadPixels();
}

namespace {

using softgl::Float;
using softgl::vec3;
using softgl::vec4;

struct WireVaryings {
  vec3 normal;
  vec3 color;
  softgl::NoPerspective<vec3> edge;  // window-space distance, in pixels, to each of the triangle's three edges
};

// A lit surface with its triangles' edges drawn over it in the same pass: the geometry stage gives each vertex its
// distance, in pixels, to the opposite edge (and 0 to the other two), interpolated without perspective; the fragment
// stage darkens whatever lies within about a pixel of an edge, smoothly (the lines come anti-aliased).
struct SolidWireShader : softgl::Shader<SolidWireShader, LitVaryings, WireVaryings> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::TRIANGLE_STRIP, 3};
  glm::mat4 mvp{1.0f};
  glm::mat4 model{1.0f};
  glm::vec2 half_viewport{1.0f};  // viewport width and height / 2
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.4f, 0.8f, 0.6f));
  glm::vec3 wire{0.05f, 0.05f, 0.1f};
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<LitVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[2]);
  }
  void Geometry(const softgl::GeometryLanes<LitVaryings>& in, softgl::GeometryLanesOut<WireVaryings>& out) const {
    softgl::vec2 p[3];  // window positions, in pixels
    for (int k = 0; k < 3; ++k) {
      const vec4& c = in.vertex[k].position;
      p[k] = softgl::vec2(c.x / c.w * half_viewport.x, c.y / c.w * half_viewport.y);
    }
    const softgl::vec2 e0 = p[2] - p[1], e1 = p[0] - p[2], e2 = p[1] - p[0];
    const Float area = abs(e1.x * e2.y - e1.y * e2.x);  // twice the triangle's area
    const Float height[3] = {area / length(e0), area / length(e1), area / length(e2)};
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[k].position;
      out.varyings.normal = in.vertex[k].varyings.normal;
      out.varyings.color = in.vertex[k].varyings.color;
      out.varyings.edge = vec3(k == 0 ? height[0] : Float(0.0f), k == 1 ? height[1] : Float(0.0f),
                               k == 2 ? height[2] : Float(0.0f));
      out.EmitVertex();
    }
  }
  void Fragment(const softgl::FragmentLanes<WireVaryings>& in, softgl::FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    const vec3 lit = in.varyings.color * (0.25f + 0.75f * diffuse);
    const vec3& e = in.varyings.edge;
    const Float near_edge = 1.0f - smoothstep(0.5f, 1.5f, min(min(e.x, e.y), e.z));
    out.color[0] = vec4(mix(lit, vec3(wire), near_edge), 1.0f);
  }
};

struct WorldVaryings {
  vec3 world;
};
struct ColourVaryings {
  vec3 color;
};

// Each triangle's face normal drawn as a short line from its centre: a geometry stage that takes triangles and makes
// line strips, a debugging view of a mesh's orientation (the lines fade from yellow at the face to red at the tip).
struct FaceNormalShader : softgl::Shader<FaceNormalShader, WorldVaryings, ColourVaryings> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::LINE_STRIP, 2};
  glm::mat4 model{1.0f};
  glm::mat4 view_projection{1.0f};
  float length = 0.1f;
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WorldVaryings>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.world = vec3(world);
    out.position = world;  // (not rasterized: the geometry stage makes the positions)
  }
  void Geometry(const softgl::GeometryLanes<WorldVaryings>& in, softgl::GeometryLanesOut<ColourVaryings>& out) const {
    const vec3& a = in.vertex[0].varyings.world;
    const vec3& b = in.vertex[1].varyings.world;
    const vec3& c = in.vertex[2].varyings.world;
    const vec3 centre = (a + b + c) * (1.0f / 3.0f);
    const vec3 normal = normalize(cross(b - a, c - a));
    out.position = view_projection * vec4(centre, 1.0f);
    out.varyings.color = vec3(1.0f, 0.9f, 0.2f);
    out.EmitVertex();
    out.position = view_projection * vec4(centre + normal * length, 1.0f);
    out.varyings.color = vec3(1.0f, 0.2f, 0.1f);
    out.EmitVertex();
  }
  void Fragment(const softgl::FragmentLanes<ColourVaryings>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.color, 1.0f);
  }
};

}  // namespace

softgl::Image GeometryStage(int width, int height) {
  softgl::Context gl(width, height);
  const Mesh torus = MakeTorus(32, 16, 0.65f, 0.28f);
  UploadLitMesh(gl, torus);
  const int count = int(torus.indices.size());
  const glm::mat4 projection = Projection(width, height, 40.0f, 0.1f, 10.0f);
  gl.Enable(softgl::DEPTH_TEST);
  gl.ClearColor(0.78f, 0.8f, 0.84f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  // Left: the torus shaded with its wireframe, one pass. Right: the same torus, and its face normals.
  for (int side = 0; side < 2; ++side) {
    const float x = side == 0 ? -1.0f : 1.0f;
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.2f, 4.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)) *
                            glm::rotate(glm::mat4(1.0f), side == 0 ? 0.5f : -0.7f, glm::vec3(1.0f, 0.2f, 0.1f));
    SolidWireShader solid;
    LitShader lit;
    solid.model = lit.model = model;
    solid.mvp = lit.mvp = projection * view * model;
    solid.half_viewport = glm::vec2(float(width), float(height)) * 0.5f;
    if (side == 0) gl.UseProgram(solid);
    else gl.UseProgram(lit);
    gl.DrawElement(softgl::TRIANGLES, count, softgl::UNSIGNED_INT, 0);
    if (side == 1) {
      FaceNormalShader normals;
      normals.model = model;
      normals.view_projection = projection * view;
      normals.length = 0.12f;
      gl.UseProgram(normals);
      gl.DrawElement(softgl::TRIANGLES, count, softgl::UNSIGNED_INT, 0);
    }
  }
  return gl.ReadPixels();
}

softgl::Image Clipped(int width, int height) {
  softgl::Context gl(width, height);
  const glm::mat4 proj = Projection(width, height, 70.0f, 0.5f, 60.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.6f, -4.0f), glm::vec3(0, 1, 0));

  // The floor: two huge triangles around the camera, crossing the near plane and every side plane.
  const float floor_vertices[] = {-40, 0, -40, 40, 0, -40, 40, 0, 40, -40, 0, 40};
  const std::uint8_t floor_indices[] = {0, 2, 1, 0, 3, 2};
  const std::uint32_t floor_vao = gl.GenVertexArray(), floor_vbo = gl.GenBuffer(), floor_ebo = gl.GenBuffer();
  gl.BindVertexArray(floor_vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, floor_vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof floor_vertices, floor_vertices);
  gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, floor_ebo);
  gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, sizeof floor_indices, floor_indices);
  gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);

  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  gl.ClearColor(0.55f, 0.7f, 0.9f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  FloorShader floor;
  floor.mvp = proj * view;
  gl.UseProgram(floor);
  gl.DrawElement(softgl::TRIANGLES, 6, softgl::UNSIGNED_BYTE, 0);

  // Cubes: two far, one cut open by the near plane at the lower left. Culling is off for them, so that the inside
  // of the cut cube shows.
  const Mesh cube = MakeCube();
  UploadLitMesh(gl, cube);
  LitShader lit;
  gl.UseProgram(lit);
  gl.Disable(softgl::CULL_FACE);
  const glm::vec3 places[] = {{1.5f, 0.5f, -5.0f}, {-0.75f, 0.4f, -0.8f}, {-3.0f, 1.0f, -9.0f}};
  const float sizes[] = {1.0f, 1.0f, 2.0f};
  for (int i = 0; i < 3; ++i) {
    lit.model = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), places[i]), 0.5f + float(i),
                                       glm::vec3(0, 1, 0)),
                           glm::vec3(sizes[i]));
    lit.mvp = proj * view * lit.model;
    gl.DrawElement(softgl::TRIANGLES, int(cube.indices.size()), softgl::UNSIGNED_INT, 0);
  }
  return gl.ReadPixels();
}

namespace {

struct FieldVaryings {
  vec3 normal;
  vec3 color;
};

// The fragment stage of the instanced cubes: the colour lit by one directional light, with some ambient.
template <class Derived>
struct LitInstances : softgl::Shader<Derived, FieldVaryings> {
  glm::mat4 view_proj{1.0f};
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.5f, 0.8f, 0.3f));
  void Fragment(const FragmentLanes<FieldVaryings>& in, FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = vec4(in.varyings.color * (0.3f + 0.7f * diffuse), 1.0f);
  }
};

// Clears to `clear` and draws `instances` of the cube bound (its `indices` indices) with `shader`, depth-tested
// and back faces culled; the image.
template <class Shader>
softgl::Image DrawCubes(softgl::Context& gl, Shader& shader, glm::vec3 clear, int indices, int instances) {
  gl.UseProgram(shader);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  gl.ClearColor(clear.r, clear.g, clear.b, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.DrawElementsInstanced(softgl::TRIANGLES, indices, softgl::UNSIGNED_INT, 0, instances);
  return gl.ReadPixels();
}

// One cube per instance: gl_InstanceID places it on a kSide x kSide grid; attribute 4 (divisor 1) holds its
// height and attribute 5 (divisor 1) its colour, as normalized bytes.
struct FieldShader : LitInstances<FieldShader> {
  static constexpr int kSide = 100;
  void Vertex(const VertexLanes& in, VertexLanesOut<FieldVaryings>& out) const {
    const Float col = Float(in.instance_id % kSide), row = Float(in.instance_id / kSide);
    const Float height = in.attrib[4].x;
    const vec3 p = vec3(in.attrib[0]);  // the unit cube, [-0.5, 0.5]^3
    const vec3 world(p.x * 0.8f + col - 0.5f * (kSide - 1), (p.y + 0.5f) * height, p.z * 0.8f + row - 0.5f * (kSide - 1));
    out.position = view_proj * vec4(world, 1.0f);
    out.varyings.normal = vec3(in.attrib[1]);  // scaling along the axes keeps a cube's face normals
    out.varyings.color = vec3(in.attrib[5]);
  }
};

}  // namespace

softgl::Image Instancing(int width, int height) {
  softgl::Context gl(width, height);
  const Mesh cube = MakeCube();
  UploadLitMesh(gl, cube);
  // Per instance: a height (a rolling landscape) and a colour from it, read once per instance.
  constexpr int kSide = FieldShader::kSide, kInstances = kSide * kSide;
  std::vector<float> heights(kInstances);
  std::vector<std::uint8_t> colors(std::size_t(kInstances) * 4);
  for (int i = 0; i < kInstances; ++i) {
    const float x = float(i % kSide), z = float(i / kSide);
    const float h = 0.6f + 1.6f * (0.5f + 0.25f * std::sin(x * 0.21f) + 0.25f * std::cos(z * 0.17f + x * 0.05f));
    heights[std::size_t(i)] = h;
    const float t = (h - 0.6f) / 1.6f;
    const std::uint8_t c[4] = {std::uint8_t(40 + 200 * t), std::uint8_t(170 - 60 * t), std::uint8_t(220 - 170 * t), 255};
    std::copy(c, c + 4, colors.begin() + std::ptrdiff_t(i) * 4);
  }
  const std::uint32_t instance_vbo = gl.GenBuffer();
  gl.BindBuffer(softgl::ARRAY_BUFFER, instance_vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(heights.size() * sizeof(float) + colors.size()), nullptr);
  gl.BufferSubData(softgl::ARRAY_BUFFER, 0, std::ptrdiff_t(heights.size() * sizeof(float)), heights.data());
  gl.BufferSubData(softgl::ARRAY_BUFFER, std::ptrdiff_t(heights.size() * sizeof(float)), std::ptrdiff_t(colors.size()),
                   colors.data());
  gl.VertexAttributePointer(4, 1, softgl::FLOAT, false, 0, 0);
  gl.VertexAttributePointer(5, 4, softgl::UNSIGNED_BYTE, true, 0, heights.size() * sizeof(float));
  gl.EnableVertexAttribArray(4);
  gl.EnableVertexAttribArray(5);
  gl.VertexAttribDivisor(4, 1);
  gl.VertexAttribDivisor(5, 1);

  FieldShader shader;
  const glm::mat4 view = glm::lookAt(glm::vec3(-50.0f, 56.0f, 74.0f), glm::vec3(2.0f, -8.0f, 4.0f), glm::vec3(0, 1, 0));
  shader.view_proj = Projection(width, height, 50.0f, 1.0f, 300.0f) * view;
  return DrawCubes(gl, shader, glm::vec3(0.08f, 0.09f, 0.12f), int(cube.indices.size()), kInstances);
}

namespace {

// One cube per instance, its model matrix read from a buffer texture (unit 0: four RGBA32F texels, the columns, per
// instance) by gl_InstanceID, its colour from a palette (unit 1: a buffer texture of RGBA8 texels) at the index an
// integer attribute gives (attribute 4, VertexAttribIPointer, divisor 1).
struct HelixShader : LitInstances<HelixShader> {
  void Vertex(const VertexLanes& in, VertexLanesOut<FieldVaryings>& out) const {
    const softgl::Int first = in.instance_id * 4;
    const softgl::mat4 model(in.TexelFetchBuffer(0, first), in.TexelFetchBuffer(0, first + 1),
                             in.TexelFetchBuffer(0, first + 2), in.TexelFetchBuffer(0, first + 3));
    out.position = view_proj * (model * vec4(vec3(in.attrib[0]), 1.0f));
    out.varyings.normal = vec3(model * vec4(vec3(in.attrib[1]), 0.0f));  // rotation and uniform scale only
    out.varyings.color = vec3(in.TexelFetchBuffer(1, in.AttribI(4, 0)));
  }
};

}  // namespace

softgl::Image BufferTextures(int width, int height) {
  softgl::Context gl(width, height);
  const Mesh cube = MakeCube();
  UploadLitMesh(gl, cube);
  // 1,200 cubes along a double helix of four turns: a matrix (four texels) and a palette index each.
  constexpr int kInstances = 1200, kPairs = kInstances / 2;
  std::vector<glm::mat4> models(kInstances);
  std::vector<std::uint8_t> palette_index(kInstances);
  for (int i = 0; i < kInstances; ++i) {
    const float t = float(i / 2) / float(kPairs), angle = t * 4.0f * 6.2831853f + ((i % 2) ? 3.14159265f : 0.0f);
    const glm::vec3 at(3.2f * std::cos(angle), t * 16.0f - 8.0f, 3.2f * std::sin(angle));
    models[std::size_t(i)] = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), at), angle * 2.0f, glm::vec3(0.3f, 1, 0.2f)),
                                        glm::vec3(0.3f + 0.12f * std::sin(t * 40.0f)));
    palette_index[std::size_t(i)] = std::uint8_t((i / 2) % 48 / 6 + (i % 2) * 8);
  }
  const std::uint8_t palette[16][4] = {{230, 57, 70, 255},   {241, 130, 60, 255},  {244, 200, 70, 255},
                                       {140, 200, 80, 255},  {60, 180, 140, 255},  {60, 150, 220, 255},
                                       {100, 90, 210, 255},  {190, 80, 190, 255},  {250, 250, 250, 255},
                                       {200, 210, 225, 255}, {150, 170, 195, 255}, {110, 130, 160, 255},
                                       {150, 170, 195, 255}, {200, 210, 225, 255}, {250, 250, 250, 255},
                                       {225, 225, 235, 255}};
  const auto buffer_texture = [&](int unit, softgl::Enum format, const void* data, std::size_t bytes) {
    gl.ActiveTexture(softgl::TEXTURE0 + std::uint32_t(unit));
    gl.BindTexture(softgl::TEXTURE_BUFFER, gl.GenTexture());
    const std::uint32_t buffer = gl.GenBuffer();
    gl.BindBuffer(softgl::TEXTURE_BUFFER, buffer);
    gl.BufferData(softgl::TEXTURE_BUFFER, std::ptrdiff_t(bytes), data);
    gl.TexBuffer(softgl::TEXTURE_BUFFER, format, buffer);
  };
  buffer_texture(0, softgl::RGBA32F, models.data(), models.size() * sizeof(glm::mat4));  // (columns, in order)
  buffer_texture(1, softgl::RGBA8, palette, sizeof palette);
  gl.BindBuffer(softgl::ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(palette_index.size()), palette_index.data());
  gl.VertexAttribIPointer(4, 1, softgl::UNSIGNED_BYTE, 0, 0);
  gl.EnableVertexAttribArray(4);
  gl.VertexAttribDivisor(4, 1);

  HelixShader shader;
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 5.0f, 20.0f), glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0, 1, 0));
  shader.view_proj = Projection(width, height, 55.0f, 1.0f, 100.0f) * view;
  return DrawCubes(gl, shader, glm::vec3(0.06f, 0.07f, 0.1f), int(cube.indices.size()), kInstances);
}

namespace {

// A fixed hash of x into [0, 1): the same jitter on every machine.
float Hash01(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7FEB352Du;
  x ^= x >> 15;
  x *= 0x846CA68Bu;
  x ^= x >> 16;
  return float(x >> 8) / 16777216.0f;
}

struct SpriteVaryings {
  vec4 color;
};

// A particle as a point sprite: attribute 0 its position, 1 its colour (alpha: how bright); the vertex stage sizes
// it by its distance (gl_PointSize, with PROGRAM_POINT_SIZE), the fragment stage shapes a soft disc from
// gl_PointCoord with a hot core, and discards the corners outside the disc.
struct SpriteShader : softgl::Shader<SpriteShader, SpriteVaryings> {
  glm::mat4 view_proj{1.0f};
  float size_at_unit_distance = 60.0f;  // pixels
  void Vertex(const VertexLanes& in, VertexLanesOut<SpriteVaryings>& out) const {
    out.position = view_proj * vec4(vec3(in.attrib[0]), 1.0f);
    out.point_size = size_at_unit_distance / max(out.position.w, 0.1f);
    out.varyings.color = in.attrib[1];
  }
  void Fragment(const FragmentLanes<SpriteVaryings>& in, FragmentLanesOut& out) const {
    const vec2 d = in.point_coord * 2.0f - 1.0f;  // (-1, -1) to (1, 1) across the sprite
    const Float r2 = dot(d, d);
    out.Discard(r2 > 1.0f);
    const Float glow = (1.0f - r2) * (1.0f - r2);
    const Float core = smoothstep(Float(0.25f), Float(0.0f), r2);
    const vec3 c = vec3(in.varyings.color) * glow + vec3(core * 0.6f);
    out.color[0] = vec4(c * in.varyings.color.w, 1.0f);
  }
};

}  // namespace

softgl::Image Particles(int width, int height) {
  softgl::Context gl(width, height);
  // A fountain: particles leave the nozzle with jittered speeds (a fixed hash, the same on every machine), rise and
  // fall under gravity, each shown at its age; hot white-yellow when young, red and dim when old.
  constexpr int kParticles = 1500;
  std::vector<float> data;
  data.reserve(kParticles * 8);
  for (int i = 0; i < kParticles; ++i) {
    const std::uint32_t k = std::uint32_t(i) * 4u;
    const float age = Hash01(k), angle = 6.2831853f * Hash01(k + 1), spread = 0.4f + 1.1f * Hash01(k + 2);
    const float speed = 5.4f + 1.0f * Hash01(k + 3);
    const glm::vec3 v(std::cos(angle) * spread, speed, std::sin(angle) * spread);
    const float t = age * 1.3f;  // seconds: the oldest are back near the nozzle's height
    const glm::vec3 p = v * t + glm::vec3(0.0f, -4.9f * t * t, 0.0f);
    const glm::vec3 young(1.0f, 0.95f, 0.6f), old(0.9f, 0.15f, 0.05f);
    const glm::vec3 c = young + (old - young) * age;
    const float bright = 0.16f * (1.0f - 0.5f * age);
    const float v8[8] = {p.x, p.y, p.z, 1.0f, c.r, c.g, c.b, bright};
    data.insert(data.end(), v8, v8 + 8);
  }
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(data.size() * sizeof(float)), data.data());
  gl.VertexAttributePointer(0, 4, softgl::FLOAT, false, 8 * sizeof(float), 0);
  gl.VertexAttributePointer(1, 4, softgl::FLOAT, false, 8 * sizeof(float), 4 * sizeof(float));
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);

  SpriteShader shader;
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.6f, 6.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0, 1, 0));
  shader.view_proj = Projection(width, height, 45.0f, 0.1f, 50.0f) * view;
  shader.size_at_unit_distance = 0.25f * float(height);
  gl.UseProgram(shader);
  gl.Enable(softgl::PROGRAM_POINT_SIZE);
  gl.Enable(softgl::BLEND);
  gl.BlendFunc(softgl::ONE, softgl::ONE);  // additive: the order of the particles does not matter
  gl.ClearColor(0.02f, 0.02f, 0.05f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  gl.DrawArrays(softgl::POINTS, 0, kParticles);
  return gl.ReadPixels();
}

namespace {

struct StepVaryings {
  vec4 position;  // xyz, and w: the particle's age in seconds (negative: not yet launched)
  vec4 velocity;  // xyz, and w: the particle's launch speed, kept
};

// One step of the fountain on the vertex stage, recorded by transform feedback: attribute 0 a particle's position
// and age, 1 its velocity. A particle waits at the nozzle until its age passes 0, then flies under gravity and
// bounces on the floor (y = 0) losing half its speed.
struct StepShader : softgl::Shader<StepShader, StepVaryings> {
  float dt = 1.0f / 60.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<StepVaryings>& out) const {
    const Float age = in.attrib[0].w + dt;
    const softgl::Bool flying = age > 0.0f;
    vec3 v = vec3(in.attrib[1]);
    v.y = select(flying, v.y - 9.8f * dt, v.y);
    vec3 p = vec3(in.attrib[0]) + v * select(flying, Float(dt), Float(0.0f));
    const softgl::Bool below = p.y < 0.0f;
    p.y = select(below, -p.y, p.y);
    v = select(below, vec3(v.x * 0.7f, -v.y * 0.5f, v.z * 0.7f), v);
    out.varyings.position = vec4(p, age);
    out.varyings.velocity = vec4(v, in.attrib[1].w);
    out.position = vec4(0.0f, 0.0f, 0.0f, 1.0f);  // (nothing is drawn: RASTERIZER_DISCARD)
  }
  void Fragment(const FragmentLanes<StepVaryings>&, FragmentLanesOut&) const {}
};

// The particles as small glowing points, coloured by age, at `brightness` (older snapshots dimmer: trails).
struct TrailVaryings {
  vec4 color;
};

struct TrailShader : softgl::Shader<TrailShader, TrailVaryings> {
  glm::mat4 view_proj{1.0f};
  float size_at_unit_distance = 20.0f;  // pixels
  float brightness = 1.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<TrailVaryings>& out) const {
    out.position = view_proj * vec4(vec3(in.attrib[0]), 1.0f);
    out.point_size = size_at_unit_distance / max(out.position.w, 0.1f);
    const Float t = clamp(in.attrib[0].w * 0.5f, 0.0f, 1.0f);  // young: blue-white, old: violet
    const vec3 c = mix(vec3(0.7f, 0.9f, 1.0f), vec3(0.6f, 0.2f, 0.9f), t);
    out.varyings.color = vec4(c, select(in.attrib[0].w > 0.0f, Float(brightness), Float(0.0f)));
  }
  void Fragment(const FragmentLanes<TrailVaryings>& in, FragmentLanesOut& out) const {
    const vec2 d = in.point_coord * 2.0f - 1.0f;
    const Float r2 = dot(d, d);
    out.Discard(r2 > 1.0f);
    out.color[0] = vec4(vec3(in.varyings.color) * ((1.0f - r2) * in.varyings.color.w), 1.0f);
  }
};

}  // namespace

softgl::Image FeedbackParticles(int width, int height) {
  softgl::Context gl(width, height);
  // 800 particles launched one after another from a nozzle; every step of the simulation runs on the vertex stage
  // and transform feedback writes the new state into the other of two buffers (the state never leaves them).
  constexpr int kParticles = 800, kSteps = 150, kTrailEvery = 2;
  std::vector<float> start;
  start.reserve(kParticles * 8);
  for (int i = 0; i < kParticles; ++i) {
    const std::uint32_t k = std::uint32_t(i) * 3u + 7u;
    const float angle = 6.2831853f * Hash01(k), spread = 0.5f + 0.9f * Hash01(k + 1);
    const float speed = 5.0f + 1.2f * Hash01(k + 2);
    const float wait = -2.2f * float(i) / float(kParticles);
    const float v8[8] = {0.0f, 0.2f, 0.0f, wait, std::cos(angle) * spread, speed, std::sin(angle) * spread, speed};
    start.insert(start.end(), v8, v8 + 8);
  }
  const std::ptrdiff_t bytes = std::ptrdiff_t(start.size() * sizeof(float));
  std::uint32_t state[2] = {gl.GenBuffer(), gl.GenBuffer()}, arrays[2] = {gl.GenVertexArray(), gl.GenVertexArray()};
  for (int b = 0; b < 2; ++b) {  // vertex array b reads state buffer b
    gl.BindVertexArray(arrays[b]);
    gl.BindBuffer(softgl::ARRAY_BUFFER, state[b]);
    gl.BufferData(softgl::ARRAY_BUFFER, bytes, b == 0 ? start.data() : nullptr, softgl::DYNAMIC_COPY);
    gl.VertexAttributePointer(0, 4, softgl::FLOAT, false, 8 * sizeof(float), 0);
    gl.VertexAttributePointer(1, 4, softgl::FLOAT, false, 8 * sizeof(float), 4 * sizeof(float));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
  }
  StepShader step;
  const softgl::FeedbackVarying record[] = {StepShader::Capture(&StepVaryings::position, "position"),
                                            StepShader::Capture(&StepVaryings::velocity, "velocity")};
  gl.TransformFeedbackVaryings(step, 2, record, softgl::INTERLEAVED_ATTRIBS);

  TrailShader trail;
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 2.4f, 5.2f), glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0, 1, 0));
  trail.view_proj = Projection(width, height, 45.0f, 0.1f, 50.0f) * view;
  trail.size_at_unit_distance = 0.05f * float(height);
  gl.Enable(softgl::PROGRAM_POINT_SIZE);
  gl.BlendFunc(softgl::ONE, softgl::ONE);  // additive: the order of the points does not matter
  gl.ClearColor(0.01f, 0.01f, 0.03f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  int current = 0;
  for (int s = 1; s <= kSteps; ++s) {
    // The step: read buffer `current`, record into the other, nothing rasterized.
    gl.UseProgram(step);
    gl.BindVertexArray(arrays[current]);
    gl.Enable(softgl::RASTERIZER_DISCARD);
    gl.BindBufferBase(softgl::TRANSFORM_FEEDBACK_BUFFER, 0, state[1 - current]);
    gl.BeginTransformFeedback(softgl::POINTS);
    gl.DrawArrays(softgl::POINTS, 0, kParticles);
    gl.EndTransformFeedback();
    gl.Disable(softgl::RASTERIZER_DISCARD);
    current = 1 - current;
    if (s % kTrailEvery != 0) continue;
    // A snapshot of the particles, brighter the later it is: the last one full, the earlier ones faint trails.
    trail.brightness = s == kSteps ? 0.9f : 0.03f + 0.15f * float(s) / float(kSteps);
    trail.size_at_unit_distance = (s == kSteps ? 0.05f : 0.03f) * float(height);
    gl.UseProgram(trail);
    gl.BindVertexArray(arrays[current]);
    gl.Enable(softgl::BLEND);
    gl.DrawArrays(softgl::POINTS, 0, kParticles);
    gl.Disable(softgl::BLEND);
  }
  return gl.ReadPixels();
}

namespace {

// The picking pass: every fragment of an object writes its id (GLSL: `out uvec4 id;`) into an R32UI attachment.
struct PickVaryings {};
struct PickShader : softgl::Shader<PickShader, PickVaryings> {
  glm::mat4 mvp{1.0f};
  int id = 0;
  void Vertex(const VertexLanes& in, VertexLanesOut<PickVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
  }
  void Fragment(const FragmentLanes<PickVaryings>&, FragmentLanesOut& out) const {
    out.SetColorI(0, softgl::ivec4(id, 0, 0, 0));
  }
};

// The picked objects lit in their colour, the others dimmed towards grey.
struct PickedLitShader : softgl::Shader<PickedLitShader, FieldVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f};
  glm::vec3 color{1.0f};
  bool picked = false;
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.4f, 0.8f, 0.6f));
  void Vertex(const VertexLanes& in, VertexLanesOut<FieldVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = picked ? color : glm::mix(color, glm::vec3(0.45f), 0.75f) * 0.6f;
  }
  void Fragment(const FragmentLanes<FieldVaryings>& in, FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = vec4(in.varyings.color * (0.3f + 0.7f * diffuse), 1.0f);
  }
};

// A pass over the screen triangle (MakeScreenTriangle) that reads whole buffers, maybe scaled down: the texel of
// a fragment is (its place - origin) * scale.
template <class Derived>
struct ScreenPass : softgl::Shader<Derived, PickVaryings> {
  glm::vec2 origin{0.0f};
  float scale = 1.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<PickVaryings>& out) const {
    out.position = vec4(in.attrib[0].x, in.attrib[0].y, 0.0f, 1.0f);
  }
  softgl::Int TexelX(const FragmentLanes<PickVaryings>& in) const { return softgl::Int((in.frag_coord.x - origin.x) * scale); }
  softgl::Int TexelY(const FragmentLanes<PickVaryings>& in) const { return softgl::Int((in.frag_coord.y - origin.y) * scale); }
};

// The id buffer (unit 0, R32UI) in false colours: texelFetch of the integer texture, each id hashed to a colour,
// 0 (nothing) black.
struct IdColorsShader : ScreenPass<IdColorsShader> {
  void Fragment(const FragmentLanes<PickVaryings>& in, FragmentLanesOut& out) const {
    using softgl::Int;
    const Int id = in.ITexelFetch(0, TexelX(in), TexelY(in)).x;
    const Int h = id * Int(int(2654435761u));
    const vec3 c(Float((h >> 8) & 255), Float((h >> 16) & 255), Float((h >> 24) & 255));
    out.color[0] = vec4(select(id == 0, vec3(0.0f), c / 255.0f * 0.8f + 0.2f), 1.0f);
  }
};

}  // namespace

softgl::Image Picking(int width, int height) {
  softgl::Context gl(width, height);
  // 6 x 4 objects (cubes, tori and spheres turning each its own way), ids 1 to 24; 0 is the background.
  const Mesh meshes[3] = {MakeCube(), MakeTorus(32, 16, 0.42f, 0.16f), MakeSphere(32, 16, 0.5f)};
  std::uint32_t vaos[3];
  for (int m = 0; m < 3; ++m) vaos[m] = UploadLitMesh(gl, meshes[m]);
  constexpr int kCols = 6, kRows = 4, kObjects = kCols * kRows;
  const glm::mat4 proj = Projection(width, height, 45.0f, 1.0f, 50.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 6.5f, 8.0f), glm::vec3(0.0f, -0.6f, 0.2f), glm::vec3(0, 1, 0));
  glm::mat4 models[kObjects];
  glm::vec3 colors[kObjects];
  for (int i = 0; i < kObjects; ++i) {
    const float x = (float(i % kCols) - 2.5f) * 1.5f, z = (float(i / kCols) - 1.5f) * -1.6f;
    models[i] = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, z)), 0.4f + 0.9f * float(i),
                            glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f * float(i % 3))));
    const float t = float(i) / float(kObjects);
    colors[i] = glm::vec3(0.55f + 0.45f * std::cos(6.2831853f * t), 0.55f + 0.45f * std::cos(6.2831853f * (t + 0.33f)),
                          0.55f + 0.45f * std::cos(6.2831853f * (t + 0.67f)));
  }
  const auto draw_all = [&](auto& shader, auto&& set) {
    for (int i = 0; i < kObjects; ++i) {
      set(i);
      shader.mvp = proj * view * models[i];
      gl.BindVertexArray(vaos[i % 3]);
      DrawMesh(gl, meshes[i % 3]);
    }
  };

  // The picking pass: ids into an R32UI texture, with a depth buffer of its own.
  const std::uint32_t ids = gl.GenTexture(), depth = gl.GenRenderbuffer(), fbo = gl.GenFramebuffer();
  gl.BindTexture(softgl::TEXTURE_2D, ids);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::R32UI, width, height, 0, softgl::RED_INTEGER, softgl::UNSIGNED_INT, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, softgl::NEAREST);
  gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
  gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::DEPTH_COMPONENT24, width, height);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, ids, 0);
  gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  const std::uint32_t nothing[4] = {0, 0, 0, 0};
  gl.ClearBufferuiv(softgl::COLOR, 0, nothing);
  gl.Clear(softgl::DEPTH_BUFFER_BIT);
  PickShader pick;
  gl.UseProgram(pick);
  draw_all(pick, [&](int i) { pick.id = i + 1; });

  // Five clicks: four at objects' centres (projected), one on the background; each reads the id under it.
  const glm::vec3 targets[] = {{-3.75f, 0.0f, 2.4f}, {0.75f, 0.0f, 0.8f}, {2.25f, 0.0f, -0.8f}, {-0.75f, 0.0f, -2.4f},
                               {5.2f, 0.0f, 2.4f}};
  bool picked[kObjects + 1] = {};
  glm::vec2 clicks[5];
  for (int k = 0; k < 5; ++k) {
    const glm::vec4 clip = proj * view * glm::vec4(targets[k], 1.0f);
    clicks[k] = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(float(width), float(height));
    std::uint32_t id = 0;
    gl.ReadPixels(int(clicks[k].x), int(clicks[k].y), 1, 1, softgl::RED_INTEGER, softgl::UNSIGNED_INT, &id);
    if (id <= std::uint32_t(kObjects)) picked[id] = true;
  }

  // The scene, the picked objects in colour.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.ClearColor(0.07f, 0.08f, 0.11f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  PickedLitShader lit;
  gl.UseProgram(lit);
  draw_all(lit, [&](int i) {
    lit.model = models[i];
    lit.color = colors[i];
    lit.picked = picked[i + 1];
  });
  gl.Disable(softgl::DEPTH_TEST);
  gl.Disable(softgl::CULL_FACE);

  // The clicks as small crosses (white where they hit, red where they missed), by the scissor box and Clear.
  gl.Enable(softgl::SCISSOR_TEST);
  for (int k = 0; k < 5; ++k) {
    std::uint32_t id = 0;
    gl.BindFramebuffer(softgl::READ_FRAMEBUFFER, fbo);
    gl.ReadPixels(int(clicks[k].x), int(clicks[k].y), 1, 1, softgl::RED_INTEGER, softgl::UNSIGNED_INT, &id);
    gl.ClearColor(1.0f, id ? 1.0f : 0.2f, id ? 1.0f : 0.2f, 1.0f);
    const int x = int(clicks[k].x), y = int(clicks[k].y);
    gl.Scissor(x - 7, y - 1, 15, 3);
    gl.Clear(softgl::COLOR_BUFFER_BIT);
    gl.Scissor(x - 1, y - 7, 3, 15);
    gl.Clear(softgl::COLOR_BUFFER_BIT);
  }
  gl.BindFramebuffer(softgl::READ_FRAMEBUFFER, 0);

  // The id buffer itself, a quarter of the size, in the top right corner (framed in grey).
  const int iw = width / 4, ih = height / 4, ix = width - iw - 8, iy = height - ih - 8;
  gl.Scissor(ix - 2, iy - 2, iw + 4, ih + 4);
  gl.ClearColor(0.6f, 0.6f, 0.65f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  gl.Disable(softgl::SCISSOR_TEST);
  gl.Viewport(ix, iy, iw, ih);
  IdColorsShader colors_of_ids;
  colors_of_ids.origin = glm::vec2(float(ix), float(iy));
  colors_of_ids.scale = 4.0f;
  gl.UseProgram(colors_of_ids);
  gl.BindTexture(softgl::TEXTURE_2D, ids);
  MakeScreenTriangle(gl);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

namespace {

// The G-buffer pass: three outputs, albedo (RGBA8), the world normal (RGBA16F, w 1 where something was drawn) and
// the world position (RGBA16F).
struct GBufferVaryings {
  vec3 normal, color, world;
};
struct GBufferShader : softgl::Shader<GBufferShader, GBufferVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<GBufferVaryings>& out) const {
    const vec4 p = vec4(vec3(in.attrib[0]), 1.0f);
    out.position = mvp * p;
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[2]);
    out.varyings.world = vec3(model * p);
  }
  void Fragment(const FragmentLanes<GBufferVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.color, 1.0f);
    out.color[1] = vec4(normalize(in.varyings.normal), 1.0f);
    out.color[2] = vec4(in.varyings.world, 1.0f);
  }
};

// A decal on the floor: stripes written into the albedo target alone (ColorMaski keeps the others); its fragment
// stage writes all three outputs, as any shader of the pass would.
struct StripesShader : softgl::Shader<StripesShader, GBufferVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<GBufferVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.world = vec3(in.attrib[0]);
  }
  void Fragment(const FragmentLanes<GBufferVaryings>& in, FragmentLanesOut& out) const {
    const softgl::Bool dark = (softgl::Int(floor((in.varyings.world.x + in.varyings.world.z) * 2.0f)) & 1) != 0;
    out.color[0] = select(dark, vec4(glm::vec4(0.16f, 0.17f, 0.2f, 1.0f)), vec4(glm::vec4(0.85f, 0.8f, 0.7f, 1.0f)));
    out.color[1] = vec4(0.0f);  // (masked: the floor's normal and position stay)
    out.color[2] = vec4(0.0f);
  }
};

// The lighting pass: per pixel, the G-buffer's three texels (texelFetch of units 0, 1 and 2) lit by kLights point
// lights; where no surface was drawn (normal w 0) the albedo target's clear colour shows. `inset` draws one target
// scaled down instead (0 none, 1 albedo, 2 normal, 3 position).
struct DeferredLightShader : ScreenPass<DeferredLightShader> {
  static constexpr int kLights = 6;
  glm::vec3 light_pos[kLights], light_color[kLights];
  int inset = 0;
  void Fragment(const FragmentLanes<PickVaryings>& in, FragmentLanesOut& out) const {
    const softgl::Int x = TexelX(in), y = TexelY(in);
    const vec4 albedo = in.TexelFetch(0, x, y), normal = in.TexelFetch(1, x, y), world = in.TexelFetch(2, x, y);
    if (inset == 1) return void(out.color[0] = albedo);
    if (inset == 2) return void(out.color[0] = vec4(vec3(normal) * 0.5f + 0.5f, 1.0f));
    if (inset == 3) return void(out.color[0] = vec4(fract(vec3(world) * 0.5f), 1.0f));
    const vec3 n = vec3(normal), p = vec3(world);
    vec3 light = vec3(0.08f);
    for (int k = 0; k < kLights; ++k) {
      const vec3 to = vec3(light_pos[k]) - p;
      const Float d2 = dot(to, to);
      const Float lambert = max(dot(n, to * inversesqrt(d2)), 0.0f);
      light = light + vec3(light_color[k]) * (lambert * 2.5f / (1.0f + d2));
    }
    out.color[0] = vec4(select(normal.w > 0.5f, vec3(albedo) * light, vec3(albedo)), 1.0f);
  }
};

}  // namespace

softgl::Image Deferred(int width, int height) {
  softgl::Context gl(width, height);
  // The G-buffer: albedo RGBA8, normal and position RGBA16F, a depth buffer; each target cleared to its own value.
  const softgl::Enum formats[3] = {softgl::RGBA8, softgl::RGBA16F, softgl::RGBA16F};
  std::uint32_t targets[3];
  const std::uint32_t fbo = gl.GenFramebuffer(), depth = gl.GenRenderbuffer();
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  for (int k = 0; k < 3; ++k) {
    targets[k] = gl.GenTexture();
    gl.BindTexture(softgl::TEXTURE_2D, targets[k]);
    gl.TexImage2D(softgl::TEXTURE_2D, 0, formats[k], width, height, 0, softgl::RGBA, softgl::FLOAT, nullptr);
    gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);  // one level: complete
    gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0 + softgl::Enum(k), softgl::TEXTURE_2D,
                            targets[k], 0);
  }
  gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
  gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::DEPTH_COMPONENT24, width, height);
  gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
  const softgl::Enum draw_buffers[3] = {softgl::COLOR_ATTACHMENT0, softgl::COLOR_ATTACHMENT0 + 1,
                                        softgl::COLOR_ATTACHMENT0 + 2};
  gl.DrawBuffers(3, draw_buffers);
  const float sky[4] = {0.1f, 0.12f, 0.2f, 1.0f}, no_normal[4] = {0, 0, 0, 0}, far_away[4] = {0, -100, 0, 1};
  const float far_depth = 1.0f;
  gl.ClearBufferfv(softgl::COLOR, 0, sky);
  gl.ClearBufferfv(softgl::COLOR, 1, no_normal);
  gl.ClearBufferfv(softgl::COLOR, 2, far_away);
  gl.ClearBufferfv(softgl::DEPTH, 0, &far_depth);

  // The geometry pass: a floor and a ring of objects.
  const glm::mat4 vp = Projection(width, height, 50.0f, 0.5f, 60.0f) *
                       glm::lookAt(glm::vec3(0.0f, 5.0f, 9.0f), glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
  const std::uint8_t grey[4] = {170, 170, 170, 255};
  const Mesh meshes[4] = {MakeQuad(7.0f, grey), MakeCube(), MakeTorus(40, 20, 0.55f, 0.22f), MakeSphere(32, 16, 0.6f)};
  std::uint32_t vaos[4];
  for (int m = 0; m < 4; ++m) vaos[m] = UploadLitMesh(gl, meshes[m]);
  gl.Enable(softgl::DEPTH_TEST);
  GBufferShader geometry;
  gl.UseProgram(geometry);
  const auto draw = [&](int m, const glm::mat4& model) {
    geometry.model = model;
    geometry.mvp = vp * model;
    gl.BindVertexArray(vaos[m]);
    DrawMesh(gl, meshes[m]);
  };
  draw(0, glm::mat4(1.0f));
  for (int i = 0; i < 9; ++i) {
    const float a = 6.2831853f * float(i) / 9.0f;
    const glm::vec3 at(3.6f * std::cos(a), 0.62f, 3.6f * std::sin(a) - 0.5f);
    draw(1 + i % 3, glm::rotate(glm::translate(glm::mat4(1.0f), at), a * 1.7f, glm::vec3(0.2f, 1.0f, 0.3f)));
  }
  // The decal: stripes into the albedo target only, over the floor's middle.
  gl.ColorMaski(1, false, false, false, false);
  gl.ColorMaski(2, false, false, false, false);
  gl.DepthMask(false);
  gl.DepthFunc(softgl::LEQUAL);
  StripesShader stripes;
  stripes.mvp = vp * glm::scale(glm::mat4(1.0f), glm::vec3(0.25f, 1.0f, 0.25f));
  gl.UseProgram(stripes);
  gl.BindVertexArray(vaos[0]);
  DrawMesh(gl, meshes[0]);
  gl.ColorMaski(1, true, true, true, true);
  gl.ColorMaski(2, true, true, true, true);
  gl.DepthMask(true);

  // The lighting pass into the context's framebuffer, then the three targets as insets along the bottom.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.Disable(softgl::DEPTH_TEST);
  for (int k = 0; k < 3; ++k) {
    gl.ActiveTexture(softgl::TEXTURE0 + softgl::Enum(k));
    gl.BindTexture(softgl::TEXTURE_2D, targets[k]);
  }
  DeferredLightShader light;
  for (int k = 0; k < DeferredLightShader::kLights; ++k) {
    const float a = 6.2831853f * (float(k) + 0.5f) / float(DeferredLightShader::kLights);
    light.light_pos[k] = glm::vec3(2.2f * std::cos(a), 1.2f, 2.2f * std::sin(a) - 0.5f);
    light.light_color[k] = glm::vec3(0.6f + 0.4f * std::cos(a), 0.6f + 0.4f * std::cos(a + 2.1f),
                                     0.6f + 0.4f * std::cos(a + 4.2f));
  }
  gl.UseProgram(light);
  MakeScreenTriangle(gl);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  const int iw = width / 5, ih = height / 5;
  gl.Enable(softgl::SCISSOR_TEST);
  for (int k = 0; k < 3; ++k) {
    const int ix = 8 + k * (iw + 8), iy = 8;
    gl.Scissor(ix - 2, iy - 2, iw + 4, ih + 4);  // a frame
    gl.ClearColor(0.6f, 0.6f, 0.65f, 1.0f);
    gl.Clear(softgl::COLOR_BUFFER_BIT);
    gl.Scissor(ix, iy, iw, ih);
    light.inset = k + 1;
    light.origin = glm::vec2(float(ix), float(iy));
    light.scale = 5.0f;
    gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  }
  return gl.ReadPixels();
}

}  // namespace scenes

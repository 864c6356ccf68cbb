// scenes.cpp — geometry, shaders and state for the example scenes.
#include "scenes.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes {

namespace {

constexpr float kPi = 3.14159265358979f;

// ---- Shaders ------------------------------------------------------------------------------------------------

struct ColorVaryings {
  glm::vec3 color;
};

// Position (attribute 0) through a matrix; colour (attribute 1) interpolated.
struct ColorShader : softgl::Shader<ColorShader, ColorVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<ColorVaryings>& out) const {
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.color = glm::vec3(in.attrib[1]);
  }
  bool Fragment(const softgl::FragmentIn<ColorVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = glm::vec4(in.varyings.color, 1.0f);
    return true;
  }
};

struct LitVaryings {
  glm::vec3 normal;
  glm::vec3 color;
};

// Per-fragment diffuse lighting from one directional light plus ambient.
struct LitShader : softgl::Shader<LitShader, LitVaryings> {
  glm::mat4 mvp{1.0f};
  glm::mat4 model{1.0f};
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.4f, 0.8f, 0.6f));
  float ambient = 0.25f;
  float brightness = 1.0f;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<LitVaryings>& out) const {
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * glm::vec3(in.attrib[1]);
    out.varyings.color = glm::vec3(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<LitVaryings>& in, softgl::FragmentOut& out) const {
    const float diffuse = std::max(glm::dot(glm::normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = glm::vec4(in.varyings.color * (ambient + (1.0f - ambient) * diffuse) * brightness, 1.0f);
    return true;
  }
};

struct FloorVaryings {
  glm::vec2 world;  // world-space x, z: the checks are computed per fragment from it
};

struct FloorShader : softgl::Shader<FloorShader, FloorVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<FloorVaryings>& out) const {
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.world = glm::vec2(in.attrib[0].x, in.attrib[0].z);
  }
  bool Fragment(const softgl::FragmentIn<FloorVaryings>& in, softgl::FragmentOut& out) const {
    const int cx = int(std::floor(in.varyings.world.x)), cz = int(std::floor(in.varyings.world.y));
    const bool dark = ((cx + cz) & 1) != 0;
    out.color[0] = dark ? glm::vec4(0.15f, 0.2f, 0.3f, 1.0f) : glm::vec4(0.9f, 0.85f, 0.7f, 1.0f);
    return true;
  }
};

// ---- Geometry -----------------------------------------------------------------------------------------------

struct LitVertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint8_t color[4];
};

struct Mesh {
  std::vector<LitVertex> vertices;
  std::vector<std::uint32_t> indices;
};

Mesh MakeCube() {
  Mesh m;
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::uint8_t colors[6][4] = {{230, 80, 60, 255},  {60, 170, 230, 255}, {240, 200, 60, 255},
                                     {120, 200, 90, 255}, {200, 100, 220, 255}, {250, 150, 50, 255}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 n = normals[f];
    // u, v span the face with cross(u, v) = n, so the corners below run counter-clockwise seen from outside.
    const glm::vec3 u = std::fabs(n.x) > 0.0f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(n, u);
    const auto base = std::uint32_t(m.vertices.size());
    const glm::vec3 corners[4] = {n - u - v, n + u - v, n + u + v, n - u + v};
    for (const glm::vec3& c : corners)
      m.vertices.push_back({c * 0.5f, n, {colors[f][0], colors[f][1], colors[f][2], colors[f][3]}});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

Mesh MakeTorus(int rings, int sides, float major, float minor) {
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const float a = 2.0f * kPi * float(i) / float(rings);
    for (int j = 0; j <= sides; ++j) {
      const float b = 2.0f * kPi * float(j) / float(sides);
      const glm::vec3 center(std::cos(a) * major, 0.0f, std::sin(a) * major);
      const glm::vec3 n(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
      const auto shade = std::uint8_t(120 + 120 * float(j) / float(sides));
      m.vertices.push_back({center + n * minor, n, {shade, std::uint8_t(90 + i % 2 * 60), 200, 255}});
    }
  }
  const int row = sides + 1;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const auto a = std::uint32_t(i * row + j), b = std::uint32_t((i + 1) * row + j);
      m.indices.insert(m.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
    }
  return m;
}

// Uploads a mesh into a new vertex array: attribute 0 position, 1 normal, 2 colour (normalized bytes).
std::uint32_t UploadLitMesh(softgl::Context& gl, const Mesh& mesh) {
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer(), ebo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(mesh.vertices.size() * sizeof(LitVertex)),
                mesh.vertices.data());
  gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, ebo);
  gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(mesh.indices.size() * sizeof(std::uint32_t)),
                mesh.indices.data());
  gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, position));
  gl.VertexAttributePointer(1, 3, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, normal));
  gl.VertexAttributePointer(2, 4, softgl::UNSIGNED_BYTE, true, sizeof(LitVertex), offsetof(LitVertex, color));
  for (std::uint32_t i = 0; i < 3; ++i) gl.EnableVertexAttribArray(i);
  return vao;
}

glm::mat4 Projection(int width, int height, float fovy_degrees, float near_plane, float far_plane) {
  const float aspect = height > 0 ? float(width) / float(height) : 1.0f;
  return glm::perspective(glm::radians(fovy_degrees), aspect, near_plane, far_plane);
}

}  // namespace

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

}  // namespace scenes

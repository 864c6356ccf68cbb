// scene_kit.cpp — meshes and helpers for the example scenes.
#include "scene_kit.h"

#include <glm/gtc/matrix_transform.hpp>

namespace scenes::kit {

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
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k)
      m.vertices.push_back({corners[k] * 0.5f, n, {colors[f][0], colors[f][1], colors[f][2], colors[f][3]}, uvs[k]});
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
      m.vertices.push_back({center + n * minor, n, {shade, std::uint8_t(90 + i % 2 * 60), 200, 255},
                            {float(i) / float(rings), float(j) / float(sides)}});
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
  gl.VertexAttributePointer(3, 2, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, uv));
  for (std::uint32_t i = 0; i < 4; ++i) gl.EnableVertexAttribArray(i);
  return vao;
}

std::uint32_t MakeScreenTriangle(softgl::Context& gl) {
  static const float kScreenTriangle[] = {-1, -1, 3, -1, -1, 3};
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof kScreenTriangle, kScreenTriangle);
  gl.VertexAttributePointer(0, 2, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  return vao;
}

glm::mat4 Projection(int width, int height, float fovy_degrees, float near_plane, float far_plane) {
  const float aspect = height > 0 ? float(width) / float(height) : 1.0f;
  return glm::perspective(glm::radians(fovy_degrees), aspect, near_plane, far_plane);
}

Mesh MakeSphere(int slices, int stacks, float radius) {
  Mesh m;
  for (int j = 0; j <= stacks; ++j) {
    const float v = float(j) / float(stacks), phi = kPi * v;
    for (int i = 0; i <= slices; ++i) {
      const float u = float(i) / float(slices), theta = 2.0f * kPi * u;
      const glm::vec3 n(std::sin(phi) * std::cos(theta), -std::cos(phi), std::sin(phi) * std::sin(theta));
      m.vertices.push_back({n * radius, n, {220, 220, 220, 255}, {u, v}});
    }
  }
  const int row = slices + 1;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto a = std::uint32_t(j * row + i), b = std::uint32_t((j + 1) * row + i);
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  return m;
}

Mesh MakeQuad(float half, const std::uint8_t color[4]) {
  Mesh m;
  const glm::vec3 corners[4] = {{-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half}};
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k)
    m.vertices.push_back({corners[k], {0, 1, 0}, {color[0], color[1], color[2], color[3]}, uvs[k]});
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

}  // namespace scenes::kit

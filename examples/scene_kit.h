// scene_kit.h — shaders, meshes and helpers that the example scenes share.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <softgl/softgl.h>

namespace scenes::kit {

inline constexpr float kPi = 3.14159265358979f;

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
  float alpha = 1.0f;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<LitVaryings>& out) const {
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * glm::vec3(in.attrib[1]);
    out.varyings.color = glm::vec3(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<LitVaryings>& in, softgl::FragmentOut& out) const {
    const float diffuse = std::max(glm::dot(glm::normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = glm::vec4(in.varyings.color * (ambient + (1.0f - ambient) * diffuse) * brightness, alpha);
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

struct FlatVaryings {};

// One colour with alpha for every fragment: outlines, mirror tints, translucent panels.
struct FlatShader : softgl::Shader<FlatShader, FlatVaryings> {
  glm::mat4 mvp{1.0f};
  glm::vec4 color{1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<FlatVaryings>& out) const {
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
  }
  bool Fragment(const softgl::FragmentIn<FlatVaryings>&, softgl::FragmentOut& out) const {
    out.color[0] = color;
    return true;
  }
};

// ---- Geometry -----------------------------------------------------------------------------------------------

struct LitVertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint8_t color[4];
  glm::vec2 uv{0.0f};
};

struct Mesh {
  std::vector<LitVertex> vertices;
  std::vector<std::uint32_t> indices;
};

Mesh MakeCube();
Mesh MakeTorus(int rings, int sides, float major, float minor);
/// A UV sphere of the given radius, uv = (longitude, latitude) in [0, 1].
Mesh MakeSphere(int slices, int stacks, float radius);
/// A square of side 2 * half in the y = 0 plane, normal +y, counter-clockwise seen from above.
Mesh MakeQuad(float half, const std::uint8_t color[4]);

/// Uploads a mesh into a new vertex array: attribute 0 position, 1 normal, 2 colour (normalized bytes), 3 texture
/// coordinates, with an element buffer of unsigned ints. Returns the vertex array id (left bound).
std::uint32_t UploadLitMesh(softgl::Context& gl, const Mesh& mesh);

glm::mat4 Projection(int width, int height, float fovy_degrees, float near_plane, float far_plane);

/// Draws an uploaded mesh (its vertex array bound) with its element count.
inline void DrawMesh(softgl::Context& gl, const Mesh& mesh) {
  gl.DrawElement(softgl::TRIANGLES, int(mesh.indices.size()), softgl::UNSIGNED_INT, 0);
}

}  // namespace scenes::kit

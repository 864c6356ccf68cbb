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

// The scenes' shaders are wide (softgl/shader.h): each call runs 16 vertices or fragments, in code that reads like
// GLSL, with softgl's lane types.
using softgl::Float;
using softgl::FragmentLanes;
using softgl::FragmentLanesOut;
using softgl::VertexLanes;
using softgl::VertexLanesOut;
using softgl::vec2;
using softgl::vec3;
using softgl::vec4;

struct ColorVaryings {
  vec3 color;
};

// Position (attribute 0) through a matrix; colour (attribute 1) interpolated.
struct ColorShader : softgl::Shader<ColorShader, ColorVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<ColorVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.color = vec3(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<ColorVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.color, 1.0f);
  }
};

struct LitVaryings {
  vec3 normal;
  vec3 color;
};

// Per-fragment diffuse lighting from one directional light plus ambient.
struct LitShader : softgl::Shader<LitShader, LitVaryings> {
  glm::mat4 mvp{1.0f};
  glm::mat4 model{1.0f};
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.4f, 0.8f, 0.6f));
  float ambient = 0.25f;
  float brightness = 1.0f;
  float alpha = 1.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<LitVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[2]);
  }
  void Fragment(const FragmentLanes<LitVaryings>& in, FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = vec4(in.varyings.color * (ambient + (1.0f - ambient) * diffuse) * brightness, alpha);
  }
};

struct FloorVaryings {
  vec2 world;  // world-space x, z: the checks are computed per fragment from it
};

struct FloorShader : softgl::Shader<FloorShader, FloorVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<FloorVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.world = vec2(in.attrib[0].x, in.attrib[0].z);
  }
  void Fragment(const FragmentLanes<FloorVaryings>& in, FragmentLanesOut& out) const {
    const softgl::Int cells = softgl::Int(floor(in.varyings.world.x)) + softgl::Int(floor(in.varyings.world.y));
    const softgl::Bool dark = (cells & 1) != 0;
    out.color[0] = select(dark, vec4(glm::vec4(0.15f, 0.2f, 0.3f, 1.0f)), vec4(glm::vec4(0.9f, 0.85f, 0.7f, 1.0f)));
  }
};

struct FlatVaryings {};

// One colour with alpha for every fragment: outlines, mirror tints, translucent panels.
struct FlatShader : softgl::Shader<FlatShader, FlatVaryings> {
  glm::mat4 mvp{1.0f};
  glm::vec4 color{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<FlatVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
  }
  void Fragment(const FragmentLanes<FlatVaryings>&, FragmentLanesOut& out) const { out.color[0] = color; }
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

/// A new vertex array (left bound) of one triangle covering the viewport: clip-space x, y in attribute 0.
std::uint32_t MakeScreenTriangle(softgl::Context& gl);

// ---- Compressed images ----------------------------------------------------------------------------------------

/// A plain S3TC / RGTC block encoder, so that the compressed examples and tests have blocks to load without a
/// texture tool (a real asset pipeline uses one: this one takes each block's extremes as its endpoints and gives
/// each texel the nearest value between them). The blocks of a w x h RGBA8 image, rows in the order given (edge
/// texels repeated into partial blocks), in `format`: the S3TC formats (texels of alpha below 128 become DXT1's
/// transparent black in the RGBA forms of DXT1) and RGTC's (red, or red and green; the signed forms take each byte
/// minus 128).
std::vector<std::uint8_t> EncodeBlocks(const std::uint8_t* rgba, int w, int h, softgl::Enum format);

/// A DDS file of `levels` (each level's blocks, level 0 first) of a w x h image in `format` (an S3TC format, or
/// RGTC as ATI1 / BC4S / ATI2 / BC5S), with the 128-byte header of FourCC files.
std::vector<std::uint8_t> MakeDds(softgl::Enum format, int w, int h,
                                  const std::vector<std::vector<std::uint8_t>>& levels);

/// Draws an uploaded mesh (its vertex array bound) with its element count.
inline void DrawMesh(softgl::Context& gl, const Mesh& mesh) {
  gl.DrawElement(softgl::TRIANGLES, int(mesh.indices.size()), softgl::UNSIGNED_INT, 0);
}

}  // namespace scenes::kit

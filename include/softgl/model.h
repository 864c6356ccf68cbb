// softgl/model.h — models from files through assimp, material shaders' interface, and a camera helper.
//
// Part of the companion library softgl::model (it links assimp; the core library does not). A Model loads any
// format assimp reads (OBJ+MTL, glTF 2.0 .gltf/.glb with embedded or external images, FBX, COLLADA, PLY, STL, 3DS,
// ...) into a Context's buffers, vertex arrays and textures, and draws its node hierarchy with a MaterialProgram,
// such as the built-in shaders of softgl/shaders.h.
#pragma once

#include <softgl/config.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/context.h>

namespace softgl {

/// Vertex attribute locations of model meshes.
enum ModelAttribute : std::uint32_t {
  kAttribPosition = 0,  // vec3
  kAttribNormal = 1,    // vec3 (generated, smooth, where the file has none)
  kAttribUv = 2,        // vec2 (first channel; (0, 0) where absent)
  kAttribTangent = 3,   // vec4: xyz tangent, w handedness (+1 or -1) of the bitangent; (0, 0, 0, 1) without uvs
  kAttribColor = 4,     // vec4 vertex colour ((1, 1, 1, 1) where absent)
};

/// Texture units a material's textures are bound to while its meshes are drawn.
enum MaterialUnit : int {
  kUnitBaseColor = 0,
  kUnitNormal = 1,
  kUnitMetallicRoughness = 2,  // glTF: roughness in g, metallic in b
  kUnitEmissive = 3,
  kUnitOcclusion = 4,  // r
  kUnitSpecular = 5,   // Phong specular intensity
  kUnitEnvironment = 6,  // not a material's: a cube map for image-based ambient light (PbrShader)
  kUnitIrradiance = 7,   // not a material's: a cube map of diffuse irradiance (PbrShader, with LoadEnvironment)
  kUnitShadow = 8,       // not a material's: the shadow map of the built-in shaders' first light (SurfaceShader)
};

struct Material {
  enum class AlphaMode { kOpaque, kMask, kBlend };
  std::string name;
  glm::vec4 base_color{1.0f};  // glTF baseColorFactor or the diffuse colour
  glm::vec3 specular{0.25f};   // Phong specular colour
  float shininess = 32.0f;
  glm::vec3 emissive{0.0f};
  float metallic = 0.0f;
  float roughness = 1.0f;
  bool pbr = false;  // the file gives metallic-roughness parameters (glTF)
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
  // Texture ids in the Context (0: none). The colour maps (base colour, emissive) are sRGB textures (SRGB8 or
  // SRGB8_ALPHA8: they sample decoded to linear); the others hold their values as they are.
  std::uint32_t base_color_texture = 0, normal_texture = 0, metallic_roughness_texture = 0, emissive_texture = 0,
                occlusion_texture = 0, specular_texture = 0;
};

struct ModelMesh {
  std::uint32_t vertex_array = 0;
  std::uint32_t vertex_buffer = 0, index_buffer = 0;  // the vertex array's buffers
  int index_count = 0;
  int vertex_count = 0;
  int material = 0;
  Enum mode = TRIANGLES;    // TRIANGLES, LINES (polylines and loops come as segments) or POINTS
  bool has_normals = true;  // false: the file gives none (points and lines), and the built-in shaders draw it unlit
};

struct ModelNode {
  std::string name;
  glm::mat4 transform{1.0f};  // relative to the parent
  std::vector<int> meshes;
  std::vector<int> children;
};

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  glm::vec3 Center() const { return (min + max) * 0.5f; }
  float Radius() const { return glm::length(max - min) * 0.5f; }
};

/// What Model::Draw needs of a shader: the built-in shaders implement it; so can yours.
class MaterialProgram {
 public:
  virtual ~MaterialProgram() = default;
  virtual const Program& GetProgram() const = 0;
  /// The node's world transform and the camera's view-projection, before each mesh.
  virtual void SetTransforms(const glm::mat4& model, const glm::mat4& view_proj) = 0;
  /// The mesh's material (its textures are bound to the MaterialUnit units by then).
  virtual void SetMaterial(const Material& material) = 0;
  /// The mesh about to be drawn (after SetMaterial); by default ignored.
  virtual void SetMesh(const ModelMesh& mesh) { (void)mesh; }
};

/// Limits on one import (assimp's reading of a file), for files from untrusted or unknown sources: some malformed
/// files keep an importer busy for minutes or make it allocate without end, and none of that can be stopped from
/// inside. With a limit set, Model::Load first imports the file in a child process (fork) that it stops at the
/// limit; only a file whose import finished there within the limits is imported again in the calling process
/// (so an import's work is done twice). A crash inside the importer ends only the child, and Load reports it.
/// POSIX systems only; elsewhere the limits are not applied. softgl's own threads are idle between draws, so the
/// fork is safe for them; in a program built with AddressSanitizer, no other thread may be allocating at that
/// moment (its allocator, unlike glibc's, leaves a lock held in the child).
struct LoadOptions {
  double timeout_seconds = 0.0;    ///< the most wall-clock time the import may take; 0: no limit
  /// The most memory it may add, in bytes: new address space, and resident memory (memory the process had freed
  /// counts when the import uses it again); 0: no limit.
  std::size_t memory_budget = 0;
};

class Model {
 public:
  /// Loads `path` into `gl`: meshes triangulated, smooth normals generated where missing, tangents computed,
  /// images (external files or embedded) loaded as mipmapped textures; meshes of points or lines are kept as
  /// they are (mode POINTS or LINES). Returns false, with a message in `error`, for a missing file, a format
  /// assimp cannot read, a corrupt file or a scene with nothing to draw; `gl` may then hold objects already made
  /// (deleting them is the caller's choice: Context objects die with it).
  bool Load(Context& gl, const std::string& path, std::string* error = nullptr);
  /// The same within `options`' limits; past one, false with a message naming the limit.
  bool Load(Context& gl, const std::string& path, const LoadOptions& options, std::string* error = nullptr);

  /// Draws every node, accumulating transforms from the root (times `world`): opaque and masked materials first,
  /// then blended ones with blending on and depth writes off; back faces culled unless a material is double
  /// sided; point meshes at the context's PointSize. Leaves the vertex array, culling, blending and depth mask as
  /// they were.
  void Draw(Context& gl, MaterialProgram& program, const glm::mat4& view_proj,
            const glm::mat4& world = glm::mat4(1.0f)) const;

  /// Deletes the model's vertex arrays, buffers and textures from `gl` (the context it was loaded into) and
  /// empties it: for a program that loads one model after another into one context. A failed Load has already
  /// deleted what it made.
  void Release(Context& gl);

  /// Whether assimp has a reader for the file name's extension (case-insensitive): "duck.dae" yes, "notes.txt"
  /// no. Says nothing about the content; Load is the judge of that.
  static bool CanRead(const std::string& path);

  std::vector<ModelMesh> meshes;
  std::vector<Material> materials;
  std::vector<ModelNode> nodes;  // nodes[0] is the root
  Bounds bounds;                 // of all vertices drawn, node transforms applied
  int triangles_drawn = 0;       // instances counted
  int lines_drawn = 0, points_drawn = 0;
  int textures_loaded = 0;
  std::vector<std::string> warnings;  // textures that could not be read (the material then goes without)
};

/// A look-at camera with a perspective projection.
struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 3.0f}, target{0.0f}, up{0.0f, 1.0f, 0.0f};
  float fovy_degrees = 45.0f;
  float near_plane = 0.1f, far_plane = 100.0f;

  glm::mat4 View() const;
  glm::mat4 Projection(float aspect) const;
  /// On a sphere around `target`: azimuth about +y from +z, elevation above the xz plane, both in degrees.
  static Camera Orbit(glm::vec3 target, float distance, float azimuth_degrees, float elevation_degrees,
                      float fovy_degrees = 45.0f);
  /// Orbits the centre of `bounds` at the distance where its bounding sphere fills the view (with a margin),
  /// near and far planes fitted around it.
  static Camera Frame(const Bounds& bounds, float aspect, float azimuth_degrees = 30.0f,
                      float elevation_degrees = 20.0f, float fovy_degrees = 40.0f);
};

}  // namespace softgl

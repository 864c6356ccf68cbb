// The Python module's high-level renderer: meshes (from arrays) and models (from files) with poses and ids, a
// camera (look-at or pinhole intrinsics in OpenCV's convention), lights, one of the built-in shaders, and from one
// render the colour image and, from a second pass without multisampling, linear depth, normals and instance ids.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

namespace softgl_python {

/// A mesh as the module receives it: float32 rows, uint32 triangles (empty: the positions are a triangle list).
struct MeshData {
  std::vector<float> positions;  // 3 a vertex
  std::vector<std::uint32_t> faces;
  std::vector<float> normals;    // 3 a vertex, or empty (made from the faces, smooth)
  std::vector<float> colors;     // 4 a vertex (RGBA, [0, 1], as the file's colours: sRGB-encoded), or empty
  std::vector<float> uvs;        // 2 a vertex, or empty
  std::vector<std::uint8_t> texture;  // RGBA8, rows bottom first (OpenGL's order), or empty
  int texture_width = 0, texture_height = 0;
  /// TRIANGLES (faces: 3 indices each), LINES (2 each) or POINTS (none: every vertex); points and lines are drawn
  /// unlit, `size` pixels wide.
  softgl::Enum mode = softgl::TRIANGLES;
  float size = 1.0f;
};

/// The surface of a mesh given as arrays.
struct Surface {
  glm::vec4 base_color{1.0f};
  float metallic = 0.0f, roughness = 0.5f;
  glm::vec3 specular{0.25f};
  float shininess = 32.0f;
  glm::vec3 emissive{0.0f};
};

/// What Render writes: each buffer either empty (not asked for) or width x height values, top row first.
struct Frame {
  std::uint8_t* color = nullptr;  // 3 or 4 bytes a pixel (`alpha`)
  float* color_hdr = nullptr;     // or 3 or 4 floats a pixel: the shaders' colours unclamped (hdr_output)
  bool alpha = false;
  float* depth = nullptr;         // distance along the optical axis; 0 where nothing is drawn
  float* normals = nullptr;       // 3 floats a pixel, unit world-space normals facing the camera; 0 elsewhere
  std::uint32_t* ids = nullptr;   // each pixel's object id; 0 where nothing is drawn
};

class Renderer {
 public:
  /// Throws std::invalid_argument for a bad size, sample count or shader name.
  Renderer(int width, int height, int msaa, const std::string& shader, int threads);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int Width() const { return width_; }
  int Height() const { return height_; }

  /// Adds a mesh; returns its handle (1, 2, 3, ...). Its id in the id image is `id`, or the handle when `id` < 0.
  int AddMesh(const MeshData& mesh, const Surface& surface, const glm::mat4& pose, std::int64_t id, bool cull_back);
  /// Adds a model file; returns its handle. Throws std::runtime_error with the loader's message when it fails.
  int AddModel(const std::string& path, const glm::mat4& pose, std::int64_t id);
  /// Throws std::out_of_range for an unknown handle.
  void SetPose(int handle, const glm::mat4& pose);
  void Remove(int handle);
  int ObjectCount() const { return int(objects_.size()); }
  /// The bounds of every object's vertices, poses applied (min, max); false when there is none.
  bool Bounds(glm::vec3& min, glm::vec3& max) const;

  /// A look-at camera (OpenGL's: looking along -z of its frame, y up), vertical field of view in degrees.
  void LookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fov_y_degrees, float near,
              float far);
  /// A pinhole camera: OpenCV's intrinsics (pixel centres at integer coordinates, (0, 0) the centre of the top-left
  /// pixel) and extrinsics (world to camera: x right, y down, z forward).
  void Intrinsics(float fx, float fy, float cx, float cy, float near, float far, const glm::mat4& world_to_camera);
  const glm::mat4& View() const { return view_; }
  const glm::mat4& Projection() const { return projection_; }
  glm::vec3 Eye() const;

  /// Directional lights (towards the light, colour); none given: three-point lighting placed from the camera.
  void SetLights(const std::vector<softgl::DirectionalLight>& lights, const glm::vec3& ambient, bool follow_camera);
  /// An equirectangular HDR image as the PBR shader's environment; throws std::runtime_error when it cannot be read.
  void SetEnvironment(const std::string& path, float strength);
  void SetToneMap(softgl::ToneMap tone_map, float exposure);
  void SetBackground(const glm::vec4& color) { background_ = color; }
  /// Shadows of the first light from a size x size shadow map fitted around the objects (`bias` subtracted from
  /// each fragment's depth in the map, which is in [0, 1] across the objects' bounding sphere).
  void SetShadows(bool on, int size, float bias);
  void SetShader(const std::string& name);
  const std::string& ShaderName() const { return shader_name_; }

  /// Renders into `frame`'s buffers (those not null). Call without the GIL: it touches no Python object.
  void Render(const Frame& frame);

 private:
  struct Object;
  void DrawColour(const glm::mat4& view_proj, bool hdr);
  void DrawShadowMap(const glm::vec3& to_light);
  void MakeHdrTargets();
  void DrawAux(const glm::mat4& view_proj);
  /// Every object with `program` (its uniforms set per object), writing each object's id to `id` first if given.
  void DrawObjects(softgl::MaterialProgram& program, const glm::mat4& view_proj, std::uint32_t* id);
  softgl::MaterialProgram& Program();

  int width_, height_;
  softgl::Context gl_;
  std::vector<std::unique_ptr<Object>> objects_;
  int next_handle_ = 1;
  glm::mat4 view_{1.0f}, projection_{1.0f};
  float near_ = 0.1f, far_ = 100.0f;
  softgl::UnlitShader unlit_;
  softgl::PhongShader phong_;
  softgl::PbrShader pbr_;
  std::string shader_name_;
  bool studio_ = false;  // the studio environment is made (PBR without an HDR image)
  std::vector<softgl::DirectionalLight> lights_;
  glm::vec3 ambient_{0.08f};
  bool follow_camera_ = true;
  glm::vec4 background_{0.0f, 0.0f, 0.0f, 0.0f};
  // The second pass: a framebuffer of linear depth (R32F), normals (RGBA32F) and ids (R32UI), with its own depth.
  std::uint32_t aux_fbo_ = 0;
  // Float colour: a framebuffer of RGBA32F (multisampled as the context's) with its depth, resolved into another.
  std::uint32_t hdr_fbo_ = 0, hdr_resolve_fbo_ = 0;
  bool shadows_ = false;
  int shadow_size_ = 2048;
  float shadow_bias_ = 0.002f;
  softgl::ShadowMap shadow_;
  int samples_ = 0;
  std::vector<float> scratch_;
};

}  // namespace softgl_python

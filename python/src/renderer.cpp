#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace softgl_python {

namespace {

using namespace softgl;

// The second pass's shader: linear depth (distance along the optical axis), the unit normal facing the camera,
// and the object's id, into three colour buffers.
struct AuxVaryings {
  Float depth;
  vec3 normal;
};
struct AuxShader : Shader<AuxShader, AuxVaryings>, MaterialProgram {
  glm::mat4 model{1.0f}, view_proj{1.0f}, view{1.0f};
  glm::mat3 normal_matrix{1.0f};
  std::uint32_t id = 0;

  const Program& GetProgram() const override { return *this; }
  void SetTransforms(const glm::mat4& m, const glm::mat4& vp) override {
    model = m;
    view_proj = vp;
    normal_matrix = glm::transpose(glm::inverse(glm::mat3(m)));
  }
  void SetMaterial(const Material&) override {}

  void Vertex(const VertexLanes& in, VertexLanesOut<AuxVaryings>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[kAttribPosition]), 1.0f);
    out.position = view_proj * world;
    out.varyings.depth = -(view * world).z;
    out.varyings.normal = normal_matrix * vec3(in.attrib[kAttribNormal]);
  }
  void Fragment(const FragmentLanes<AuxVaryings>& in, FragmentLanesOut& out) const {
    const vec3 n = in.varyings.normal;
    const Float len = length(n);
    vec3 unit = select(len > 0.0f, n / len, vec3(0.0f));
    if (!in.front_facing) unit = -unit;
    out.color[0] = vec4(in.varyings.depth, 0.0f, 0.0f, 1.0f);
    out.color[1] = vec4(unit, 1.0f);  // (alpha 1: a blended material's normal replaces what is there)
    out.SetColorI(2, ivec4(Int(std::int32_t(id)), Int(0), Int(0), Int(0)));
  }
};

int Samples(int msaa) {
  if (msaa != 0 && msaa != 1 && msaa != 2 && msaa != 4 && msaa != 8)
    throw std::invalid_argument("msaa: must be 0 or 1 (none), 2, 4 or 8, got " + std::to_string(msaa));
  return msaa <= 1 ? 0 : msaa;
}

Context::Options ContextOptions(int msaa, int threads) {
  Context::Options o;
  o.samples = Samples(msaa);
  if (threads < 0 || threads > 256) throw std::invalid_argument("threads: must be 0 (all) to 256, got " + std::to_string(threads));
  o.threads = threads;
  return o;
}

int CheckSize(int v, const char* arg) {
  if (v < 1 || v > kMaxFramebufferSize)
    throw std::invalid_argument(std::string(arg) + ": must be 1 to " + std::to_string(kMaxFramebufferSize) + ", got " +
                                std::to_string(v));
  return v;
}

void CheckShader(const std::string& name) {
  if (name != "unlit" && name != "phong" && name != "pbr")
    throw std::invalid_argument("shader: must be 'unlit', 'phong' or 'pbr', got '" + name + "'");
}

void CheckDepthRange(float near, float far) {
  if (!(near > 0.0f) || !std::isfinite(near)) throw std::invalid_argument("near: must be a finite number > 0");
  if (!(far > near) || !std::isfinite(far)) throw std::invalid_argument("far: must be finite and greater than near");
}

// Copies `rows` rows of `row_bytes` from `src` (bottom row first) to `dst` (top row first).
void FlipRows(const void* src, void* dst, int rows, std::size_t row_bytes) {
  for (int y = 0; y < rows; ++y)
    std::memcpy(static_cast<std::uint8_t*>(dst) + std::size_t(y) * row_bytes,
                static_cast<const std::uint8_t*>(src) + std::size_t(rows - 1 - y) * row_bytes, row_bytes);
}

}  // namespace

struct Renderer::Object {
  int handle = 0;
  std::uint32_t id = 0;
  glm::mat4 pose{1.0f};
  bool is_model = false;
  Model model;
  // A mesh from arrays:
  std::uint32_t vao = 0, texture = 0;
  std::vector<std::uint32_t> buffers;
  int count = 0;
  bool indexed = false, has_colors = false, cull_back = false;
  Enum mode = TRIANGLES;
  float size = 1.0f;  // points and lines
  Material material;
  glm::vec3 min{0.0f}, max{0.0f};  // of the vertices, before the pose
};

Renderer::Renderer(int width, int height, int msaa, const std::string& shader, int threads)
    : width_(CheckSize(width, "width")),
      height_(CheckSize(height, "height")),
      gl_(width_, height_, ContextOptions(msaa, threads)),
      samples_(Samples(msaa)) {
  CheckShader(shader);
  shader_name_ = shader;
  if (gl_.GetError() != NO_ERROR) throw std::runtime_error("the framebuffer cannot be allocated");
  LookAt(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 45.0f, 0.1f, 100.0f);
  gl_.PixelStore(PACK_ALIGNMENT, 1);
}

Renderer::~Renderer() = default;

int Renderer::AddMesh(const MeshData& mesh, const Surface& surface, const glm::mat4& pose, std::int64_t id,
                      bool cull_back) {
  auto object = std::make_unique<Object>();
  Object& o = *object;
  o.handle = next_handle_++;
  o.id = std::uint32_t(id < 0 ? o.handle : id);
  o.pose = pose;
  o.cull_back = cull_back;
  const std::size_t vertices = mesh.positions.size() / 3;
  o.min = glm::vec3(mesh.positions[0], mesh.positions[1], mesh.positions[2]);
  o.max = o.min;
  for (std::size_t v = 0; v < vertices; ++v) {
    const glm::vec3 p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    o.min = glm::min(o.min, p);
    o.max = glm::max(o.max, p);
  }
  // Smooth normals from the triangles where none are given: each face's area-weighted normal added to its corners.
  o.mode = mesh.mode;
  o.size = mesh.size;
  std::vector<float> normals = mesh.normals;
  if (normals.empty() && mesh.mode == TRIANGLES) {
    normals.assign(vertices * 3, 0.0f);
    const std::size_t corners = mesh.faces.empty() ? vertices - vertices % 3 : mesh.faces.size();
    for (std::size_t t = 0; t + 3 <= corners; t += 3) {
      std::uint32_t idx[3];
      for (int k = 0; k < 3; ++k) idx[k] = mesh.faces.empty() ? std::uint32_t(t + std::size_t(k)) : mesh.faces[t + std::size_t(k)];
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = glm::vec3(mesh.positions[3 * idx[k]], mesh.positions[3 * idx[k] + 1], mesh.positions[3 * idx[k] + 2]);
      const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) normals[3 * idx[k] + std::size_t(c)] += n[c];
    }
  }
  o.vao = gl_.GenVertexArray();
  gl_.BindVertexArray(o.vao);
  auto attribute = [&](std::uint32_t location, const std::vector<float>& data, int size) {
    const std::uint32_t buffer = gl_.GenBuffer();
    o.buffers.push_back(buffer);
    gl_.BindBuffer(ARRAY_BUFFER, buffer);
    gl_.BufferData(ARRAY_BUFFER, std::ptrdiff_t(data.size() * sizeof(float)), data.data());
    gl_.VertexAttributePointer(location, size, FLOAT, false, 0, 0);
    gl_.EnableVertexAttribArray(location);
  };
  attribute(kAttribPosition, mesh.positions, 3);
  if (!normals.empty()) attribute(kAttribNormal, normals, 3);
  if (!mesh.uvs.empty()) attribute(kAttribUv, mesh.uvs, 2);
  if (!mesh.colors.empty()) attribute(kAttribColor, mesh.colors, 4);
  o.has_colors = !mesh.colors.empty();
  if (!mesh.faces.empty()) {
    const std::uint32_t buffer = gl_.GenBuffer();
    o.buffers.push_back(buffer);
    gl_.BindBuffer(ELEMENT_ARRAY_BUFFER, buffer);
    gl_.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(mesh.faces.size() * sizeof(std::uint32_t)), mesh.faces.data());
    o.indexed = true;
    o.count = int(mesh.faces.size());
  } else {
    o.count = mesh.mode == TRIANGLES ? int(vertices - vertices % 3) : mesh.mode == LINES ? int(vertices - vertices % 2)
                                                                                          : int(vertices);
  }
  gl_.BindVertexArray(0);
  if (!mesh.texture.empty()) {
    o.texture = gl_.GenTexture();
    gl_.ActiveTexture(TEXTURE0);
    gl_.BindTexture(TEXTURE_2D, o.texture);
    gl_.PixelStore(UNPACK_ALIGNMENT, 1);
    gl_.TexImage2D(TEXTURE_2D, 0, SRGB8_ALPHA8, mesh.texture_width, mesh.texture_height, 0, RGBA, UNSIGNED_BYTE,
                   mesh.texture.data());
    gl_.GenerateMipmap(TEXTURE_2D);
    gl_.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
    gl_.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR);
    gl_.BindTexture(TEXTURE_2D, 0);
  }
  Material& m = o.material;
  m.base_color = surface.base_color;
  m.metallic = surface.metallic;
  m.roughness = surface.roughness;
  m.specular = surface.specular;
  m.shininess = surface.shininess;
  m.emissive = surface.emissive;
  m.double_sided = !cull_back;
  m.base_color_texture = o.texture;
  if (gl_.GetError() != NO_ERROR) throw std::runtime_error("the mesh cannot be stored (out of memory?)");
  objects_.push_back(std::move(object));
  return o.handle;
}

int Renderer::AddModel(const std::string& path, const glm::mat4& pose, std::int64_t id) {
  auto object = std::make_unique<Object>();
  std::string error;
  if (!object->model.Load(gl_, path, &error)) throw std::runtime_error(error);
  object->is_model = true;
  object->handle = next_handle_++;
  object->id = std::uint32_t(id < 0 ? object->handle : id);
  object->pose = pose;
  object->min = object->model.bounds.min;
  object->max = object->model.bounds.max;
  objects_.push_back(std::move(object));
  return objects_.back()->handle;
}

void Renderer::SetPose(int handle, const glm::mat4& pose) {
  for (auto& o : objects_)
    if (o->handle == handle) {
      o->pose = pose;
      return;
    }
  throw std::out_of_range("handle: no object " + std::to_string(handle));
}

void Renderer::Remove(int handle) {
  for (auto it = objects_.begin(); it != objects_.end(); ++it) {
    Object& o = **it;
    if (o.handle != handle) continue;
    if (o.is_model) {
      o.model.Release(gl_);
    } else {
      gl_.DeleteVertexArray(o.vao);
      gl_.DeleteBuffers(int(o.buffers.size()), o.buffers.data());
      if (o.texture) gl_.DeleteTexture(o.texture);
    }
    objects_.erase(it);
    return;
  }
  throw std::out_of_range("handle: no object " + std::to_string(handle));
}

bool Renderer::Bounds(glm::vec3& min, glm::vec3& max) const {
  bool any = false;
  for (const auto& o : objects_)
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local((corner & 1) ? o->max.x : o->min.x, (corner & 2) ? o->max.y : o->min.y,
                            (corner & 4) ? o->max.z : o->min.z);
      const glm::vec3 p = glm::vec3(o->pose * glm::vec4(local, 1.0f));
      min = any ? glm::min(min, p) : p;
      max = any ? glm::max(max, p) : p;
      any = true;
    }
  return any;
}

void Renderer::LookAt(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up, float fov_y_degrees,
                      float near, float far) {
  if (!(fov_y_degrees > 0.0f && fov_y_degrees < 180.0f))
    throw std::invalid_argument("fov_y: must be between 0 and 180 degrees");
  CheckDepthRange(near, far);
  const glm::vec3 forward = target - eye;
  if (glm::length(forward) == 0.0f) throw std::invalid_argument("target: must differ from eye");
  if (glm::length(glm::cross(forward, up)) <= 1e-6f * glm::length(forward) * glm::length(up))
    throw std::invalid_argument("up: must not be zero or parallel to the view direction");
  view_ = glm::lookAt(eye, target, up);
  projection_ = glm::perspective(glm::radians(fov_y_degrees), float(width_) / float(height_), near, far);
  near_ = near;
  far_ = far;
}

void Renderer::Intrinsics(float fx, float fy, float cx, float cy, float near, float far,
                          const glm::mat4& world_to_camera) {
  if (!(fx > 0.0f) || !(fy > 0.0f) || !std::isfinite(fx) || !std::isfinite(fy))
    throw std::invalid_argument("fx, fy: the focal lengths must be finite numbers > 0");
  if (!std::isfinite(cx) || !std::isfinite(cy)) throw std::invalid_argument("cx, cy: must be finite");
  CheckDepthRange(near, far);
  if (std::abs(glm::determinant(glm::mat3(world_to_camera))) < 1e-12f)
    throw std::invalid_argument("world_to_camera: its rotation part is singular");
  // OpenCV's camera frame (y down, z forward) to OpenGL's (y up, looking along -z).
  glm::mat4 flip(1.0f);
  flip[1][1] = -1.0f;
  flip[2][2] = -1.0f;
  view_ = flip * world_to_camera;
  // Pixel centre (u, v) in OpenCV's coordinates is window point (u + 0.5, height - v - 0.5).
  const float w = float(width_), h = float(height_);
  glm::mat4 p(0.0f);
  p[0][0] = 2.0f * fx / w;
  p[2][0] = 1.0f - 2.0f * (cx + 0.5f) / w;
  p[1][1] = 2.0f * fy / h;
  p[2][1] = 2.0f * (cy + 0.5f) / h - 1.0f;
  p[2][2] = -(far + near) / (far - near);
  p[3][2] = -2.0f * far * near / (far - near);
  p[2][3] = -1.0f;
  projection_ = p;
  near_ = near;
  far_ = far;
}

glm::vec3 Renderer::Eye() const { return glm::vec3(glm::inverse(view_)[3]); }

void Renderer::SetLights(const std::vector<DirectionalLight>& lights, const glm::vec3& ambient, bool follow_camera) {
  if (lights.size() > std::size_t(Lighting::kMaxLights))
    throw std::invalid_argument("lights: at most " + std::to_string(Lighting::kMaxLights) + " lights");
  lights_ = lights;
  for (DirectionalLight& l : lights_) {
    if (glm::length(l.direction) == 0.0f) throw std::invalid_argument("lights: a direction must not be zero");
    l.direction = glm::normalize(l.direction);
  }
  ambient_ = ambient;
  follow_camera_ = follow_camera;
}

void Renderer::SetEnvironment(const std::string& path, float strength) {
  std::string error;
  const float levels = LoadEnvironment(gl_, path, 128, &error);
  if (levels == 0.0f) throw std::runtime_error(error.empty() ? path + ": cannot read" : error);
  pbr_.environment_levels = levels;
  pbr_.environment_hdr = true;
  pbr_.environment_strength = strength;
}

void Renderer::SetToneMap(ToneMap tone_map, float exposure) {
  unlit_.tone_map = phong_.tone_map = pbr_.tone_map = tone_map;
  unlit_.exposure = phong_.exposure = pbr_.exposure = exposure;
}

void Renderer::SetShadows(bool on, int size, float bias) {
  if (size < 16 || size > 8192) throw std::invalid_argument("size: the shadow map must be 16 to 8192, got " + std::to_string(size));
  if (!std::isfinite(bias)) throw std::invalid_argument("bias: must be finite");
  if (shadow_.framebuffer && size != shadow_size_) {  // made again at the new size
    gl_.DeleteFramebuffer(shadow_.framebuffer);
    gl_.DeleteTexture(shadow_.texture);
    shadow_ = ShadowMap();
  }
  shadows_ = on;
  shadow_size_ = size;
  shadow_bias_ = bias;
}

void Renderer::DrawShadowMap(const glm::vec3& to_light) {
  gl_.ActiveTexture(TEXTURE0 + Enum(kUnitShadow));
  gl_.BindTexture(TEXTURE_2D, 0);  // not bound to a unit while drawn into
  if (!shadow_.framebuffer) shadow_ = MakeShadowMap(gl_, shadow_size_);
  glm::vec3 lo, hi;
  Bounds(lo, hi);
  const glm::vec3 centre = (lo + hi) * 0.5f;
  const float r = std::max(glm::length(hi - lo) * 0.5f, 1e-6f);
  // The light's orthographic view of the objects' bounding sphere, from 3 radii away: depth 0 to 1 over [2 r, 4 r].
  const glm::vec3 l = glm::normalize(to_light);
  const glm::vec3 up = std::abs(l.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::mat4 light_vp = glm::ortho(-r, r, -r, r, 2.0f * r, 4.0f * r) * glm::lookAt(centre + l * 3.0f * r, centre, up);
  gl_.BindFramebuffer(FRAMEBUFFER, shadow_.framebuffer);
  gl_.Viewport(0, 0, shadow_size_, shadow_size_);
  gl_.Enable(DEPTH_TEST);
  gl_.DepthFunc(LESS);
  gl_.DepthMask(true);
  gl_.Clear(DEPTH_BUFFER_BIT);
  gl_.Enable(POLYGON_OFFSET_FILL);  // keeps surfaces from shadowing themselves (acne)
  gl_.PolygonOffset(2.0f, 4.0f);
  AuxShader depth;
  DrawObjects(depth, light_vp, nullptr);
  gl_.Finish();  // the shader is a local
  gl_.Disable(POLYGON_OFFSET_FILL);
  gl_.ActiveTexture(TEXTURE0 + Enum(kUnitShadow));
  gl_.BindTexture(TEXTURE_2D, shadow_.texture);
  // Clip space to the map's texture coordinates and depth, [-1, 1] to [0, 1].
  const glm::mat4 to_texture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  unlit_.shadow_matrix = phong_.shadow_matrix = pbr_.shadow_matrix = to_texture * light_vp;
  unlit_.shadow_bias = phong_.shadow_bias = pbr_.shadow_bias = shadow_bias_;
  unlit_.shadows = phong_.shadows = pbr_.shadows = true;
}

void Renderer::SetShader(const std::string& name) {
  CheckShader(name);
  shader_name_ = name;
}

MaterialProgram& Renderer::Program() {
  if (shader_name_ == "pbr") return pbr_;
  if (shader_name_ == "phong") return phong_;
  return unlit_;
}

void Renderer::MakeHdrTargets() {
  auto framebuffer = [&](int samples, bool depth) {
    const std::uint32_t fbo = gl_.GenFramebuffer();
    gl_.BindFramebuffer(FRAMEBUFFER, fbo);
    auto attach = [&](Enum attachment, Enum format) {
      const std::uint32_t rb = gl_.GenRenderbuffer();
      gl_.BindRenderbuffer(RENDERBUFFER, rb);
      if (samples > 1) gl_.RenderbufferStorageMultisample(RENDERBUFFER, samples, format, width_, height_);
      else gl_.RenderbufferStorage(RENDERBUFFER, format, width_, height_);
      gl_.FramebufferRenderbuffer(FRAMEBUFFER, attachment, RENDERBUFFER, rb);
    };
    attach(COLOR_ATTACHMENT0, RGBA32F);
    if (depth) attach(DEPTH_ATTACHMENT, DEPTH_COMPONENT32F);
    if (gl_.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the float colour buffers cannot be allocated");
    return fbo;
  };
  hdr_fbo_ = framebuffer(samples_, true);
  hdr_resolve_fbo_ = samples_ > 1 ? framebuffer(0, false) : hdr_fbo_;
}

void Renderer::DrawColour(const glm::mat4& view_proj, bool hdr) {
  if (shader_name_ == "pbr" && pbr_.environment_levels == 0.0f && !studio_) {
    pbr_.environment_levels = MakeStudioEnvironment(gl_, 64);
    studio_ = true;
  }
  const glm::vec3 eye = Eye();
  Lighting lighting;
  if (follow_camera_) {
    const glm::vec3 forward = -glm::vec3(glm::inverse(view_)[2]);
    lighting = Lighting::ThreePoint(eye, eye + forward);
  } else {
    lighting.count = int(lights_.size());
    for (std::size_t i = 0; i < lights_.size(); ++i) lighting.lights[i] = lights_[i];
  }
  lighting.eye = eye;
  lighting.ambient = ambient_;
  unlit_.lighting = phong_.lighting = pbr_.lighting = lighting;
  unlit_.hdr_output = phong_.hdr_output = pbr_.hdr_output = hdr;
  unlit_.shadows = phong_.shadows = pbr_.shadows = false;
  if (shadows_ && lighting.count > 0 && !objects_.empty() && shader_name_ != "unlit")
    DrawShadowMap(lighting.lights[0].direction);
  if (pbr_.environment_hdr && follow_camera_) pbr_.lighting.count = 0;  // the HDR image is then the only light

  if (hdr && !hdr_fbo_) MakeHdrTargets();
  gl_.BindFramebuffer(FRAMEBUFFER, hdr ? hdr_fbo_ : 0);
  gl_.Viewport(0, 0, width_, height_);
  gl_.ClearColor(background_.r, background_.g, background_.b, background_.a);
  gl_.Enable(DEPTH_TEST);
  gl_.DepthFunc(LESS);
  gl_.DepthMask(true);
  gl_.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  DrawObjects(Program(), view_proj, nullptr);
}

void Renderer::DrawObjects(MaterialProgram& program, const glm::mat4& view_proj, std::uint32_t* id) {
  for (const auto& object : objects_) {
    const Object& o = *object;
    if (id) *id = o.id;
    if (o.is_model) {
      gl_.PointSize(1.0f);  // (a model's point and line meshes: one pixel, as the C++ API draws them by default)
      gl_.LineWidth(1.0f);
      o.model.Draw(gl_, program, view_proj, o.pose);
      continue;
    }
    program.SetTransforms(o.pose, view_proj);
    program.SetMaterial(o.material);
    ModelMesh shape;
    shape.mode = o.mode;
    shape.has_normals = o.mode == TRIANGLES;  // points and lines are drawn unlit
    program.SetMesh(shape);
    gl_.ActiveTexture(TEXTURE0 + Enum(kUnitBaseColor));
    gl_.BindTexture(TEXTURE_2D, o.texture);
    gl_.UseProgram(program.GetProgram());
    // The attributes a mesh from arrays may lack, at the values the model loader gives them.
    gl_.VertexAttrib4f(kAttribUv, 0.0f, 0.0f, 0.0f, 1.0f);
    gl_.VertexAttrib4f(kAttribTangent, 0.0f, 0.0f, 0.0f, 1.0f);
    gl_.VertexAttrib4f(kAttribColor, 1.0f, 1.0f, 1.0f, 1.0f);
    gl_.VertexAttrib4f(kAttribNormal, 0.0f, 0.0f, 0.0f, 1.0f);
    if (o.cull_back) gl_.Enable(CULL_FACE);
    else gl_.Disable(CULL_FACE);
    if (o.mode == POINTS) gl_.PointSize(o.size);
    if (o.mode == LINES) gl_.LineWidth(o.size);
    gl_.BindVertexArray(o.vao);
    if (o.indexed) gl_.DrawElement(o.mode, o.count, UNSIGNED_INT, 0);
    else gl_.DrawArrays(o.mode, 0, o.count);
  }
  gl_.BindVertexArray(0);
  gl_.Disable(CULL_FACE);
}

void Renderer::DrawAux(const glm::mat4& view_proj) {
  if (!aux_fbo_) {
    aux_fbo_ = gl_.GenFramebuffer();
    gl_.BindFramebuffer(FRAMEBUFFER, aux_fbo_);
    const Enum formats[3] = {R32F, RGBA32F, R32UI};
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t rb = gl_.GenRenderbuffer();
      gl_.BindRenderbuffer(RENDERBUFFER, rb);
      gl_.RenderbufferStorage(RENDERBUFFER, formats[i], width_, height_);
      gl_.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(i), RENDERBUFFER, rb);
    }
    const std::uint32_t depth = gl_.GenRenderbuffer();
    gl_.BindRenderbuffer(RENDERBUFFER, depth);
    gl_.RenderbufferStorage(RENDERBUFFER, DEPTH_COMPONENT32F, width_, height_);
    gl_.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, RENDERBUFFER, depth);
    const Enum buffers[3] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2};
    gl_.DrawBuffers(3, buffers);
    if (gl_.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the depth, normal and id buffers cannot be allocated");
  }
  gl_.BindFramebuffer(FRAMEBUFFER, aux_fbo_);
  gl_.Viewport(0, 0, width_, height_);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const std::uint32_t no_id[4] = {0, 0, 0, 0};
  gl_.ClearBufferfv(COLOR, 0, zero);
  gl_.ClearBufferfv(COLOR, 1, zero);
  gl_.ClearBufferuiv(COLOR, 2, no_id);
  gl_.ClearBufferfi(DEPTH_STENCIL, 0, 1.0f, 0);
  gl_.Enable(DEPTH_TEST);
  gl_.DepthFunc(LESS);
  AuxShader aux;
  aux.view = view_;
  DrawObjects(aux, view_proj, &aux.id);
  gl_.Finish();  // the shader is a local: its draws are rendered before it goes
}

void Renderer::Render(const Frame& frame) {
  const glm::mat4 view_proj = projection_ * view_;
  const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
  const int channels = frame.alpha ? 4 : 3;
  if (frame.color) {
    DrawColour(view_proj, false);
    // Read as RGBA (the framebuffer's own layout, copied by rows), then flipped, and packed to RGB here.
    scratch_.resize(pixels);
    gl_.BindFramebuffer(READ_FRAMEBUFFER, 0);
    gl_.ReadPixels(0, 0, width_, height_, RGBA, UNSIGNED_BYTE, scratch_.data());
    if (frame.alpha) {
      FlipRows(scratch_.data(), frame.color, height_, std::size_t(width_) * 4);
    } else {
      const auto* src = reinterpret_cast<const std::uint8_t*>(scratch_.data());
      for (int y = 0; y < height_; ++y) {
        const std::uint8_t* s = src + std::size_t(height_ - 1 - y) * std::size_t(width_) * 4;
        std::uint8_t* d = frame.color + std::size_t(y) * std::size_t(width_) * 3;
        for (int x = 0; x < width_; ++x) {
          d[3 * x] = s[4 * x];
          d[3 * x + 1] = s[4 * x + 1];
          d[3 * x + 2] = s[4 * x + 2];
        }
      }
    }
  }
  if (frame.color_hdr) {
    DrawColour(view_proj, true);
    if (hdr_resolve_fbo_ != hdr_fbo_) {  // the samples averaged
      gl_.BindFramebuffer(READ_FRAMEBUFFER, hdr_fbo_);
      gl_.BindFramebuffer(DRAW_FRAMEBUFFER, hdr_resolve_fbo_);
      gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, COLOR_BUFFER_BIT, NEAREST);
    }
    gl_.BindFramebuffer(READ_FRAMEBUFFER, hdr_resolve_fbo_);
    scratch_.resize(pixels * std::size_t(channels));
    gl_.ReadPixels(0, 0, width_, height_, frame.alpha ? RGBA : RGB, FLOAT, scratch_.data());
    FlipRows(scratch_.data(), frame.color_hdr, height_, std::size_t(width_) * std::size_t(channels) * sizeof(float));
    gl_.BindFramebuffer(FRAMEBUFFER, 0);
  }
  if (frame.depth || frame.normals || frame.ids) {
    DrawAux(view_proj);
    gl_.BindFramebuffer(READ_FRAMEBUFFER, aux_fbo_);
    scratch_.resize(pixels * 3);
    if (frame.depth) {
      gl_.ReadBuffer(COLOR_ATTACHMENT0);
      gl_.ReadPixels(0, 0, width_, height_, RED, FLOAT, scratch_.data());
      FlipRows(scratch_.data(), frame.depth, height_, std::size_t(width_) * sizeof(float));
    }
    if (frame.normals) {
      gl_.ReadBuffer(COLOR_ATTACHMENT0 + 1);
      gl_.ReadPixels(0, 0, width_, height_, RGB, FLOAT, scratch_.data());
      FlipRows(scratch_.data(), frame.normals, height_, std::size_t(width_) * 3 * sizeof(float));
    }
    if (frame.ids) {
      gl_.ReadBuffer(COLOR_ATTACHMENT0 + 2);
      gl_.ReadPixels(0, 0, width_, height_, RED_INTEGER, UNSIGNED_INT, scratch_.data());
      FlipRows(scratch_.data(), frame.ids, height_, std::size_t(width_) * sizeof(std::uint32_t));
    }
    gl_.BindFramebuffer(FRAMEBUFFER, 0);
  }
  const Enum error = gl_.GetError();
  if (error != NO_ERROR) throw std::runtime_error("rendering failed with OpenGL error " + std::to_string(error));
}

}  // namespace softgl_python

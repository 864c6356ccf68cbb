// scenes_fragment_ops.cpp — example scenes for the per-fragment operations: stencil, blending, polygon offset,
// multisampling.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene_kit.h"
#include "scenes.h"

namespace scenes {

using namespace kit;

namespace {

const glm::mat4 kIdentity(1.0f);

// A silhouette shell: each vertex pushed out along its normal, drawn in one flat colour.
struct OutlineShader : softgl::Shader<OutlineShader, FlatVaryings> {
  glm::mat4 mvp{1.0f};
  float thickness = 0.05f;
  glm::vec4 color{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<FlatVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]) + thickness * vec3(in.attrib[1]), 1.0f);
  }
  void Fragment(const FragmentLanes<FlatVaryings>&, FragmentLanesOut& out) const { out.color[0] = color; }
};

glm::mat4 Place(glm::vec3 at, float yaw, float scale) {
  return glm::scale(glm::rotate(glm::translate(kIdentity, at), yaw, glm::vec3(0, 1, 0)), glm::vec3(scale));
}

// A checkered floor quad of half size `half` at y = 0, through FloorShader.
struct Floor {
  std::uint32_t vao;
  explicit Floor(softgl::Context& gl, float half) {
    const float v[] = {-half, 0, half, half, 0, half, half, 0, -half, -half, 0, -half};
    vao = gl.GenVertexArray();
    const std::uint32_t vbo = gl.GenBuffer();
    gl.BindVertexArray(vao);
    gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
    gl.BufferData(softgl::ARRAY_BUFFER, sizeof v, v);
    gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, 0, 0);
    gl.EnableVertexAttribArray(0);
  }
  void Draw(softgl::Context& gl) const {
    gl.BindVertexArray(vao);
    gl.DrawArrays(softgl::TRIANGLE_FAN, 0, 4);
  }
};

}  // namespace

softgl::Image StencilOutline(int width, int height) {
  softgl::Context gl(width, height);
  const glm::mat4 vp = Projection(width, height, 45.0f, 0.1f, 20.0f) *
                       glm::lookAt(glm::vec3(0.0f, 1.6f, 4.2f), glm::vec3(0.0f, 0.1f, 0.0f), glm::vec3(0, 1, 0));
  const Mesh torus = MakeTorus(32, 16, 0.6f, 0.25f), cube = MakeCube();
  const std::uint32_t torus_vao = UploadLitMesh(gl, torus), cube_vao = UploadLitMesh(gl, cube);
  Floor floor(gl, 6.0f);

  gl.Enable(softgl::DEPTH_TEST);
  gl.ClearColor(0.12f, 0.13f, 0.17f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT | softgl::STENCIL_BUFFER_BIT);
  FloorShader floor_shader;
  floor_shader.mvp = vp;
  gl.UseProgram(floor_shader);
  floor.Draw(gl);

  // Pass 1: the objects, each writing 1 into the stencil buffer wherever it is drawn.
  gl.Enable(softgl::STENCIL_TEST);
  gl.StencilFunc(softgl::ALWAYS, 1, 0xFF);
  gl.StencilOp(softgl::KEEP, softgl::KEEP, softgl::REPLACE);
  const glm::mat4 torus_model = Place({-0.9f, 0.85f, 0.0f}, 0.4f, 1.0f) *
                                glm::rotate(kIdentity, 1.1f, glm::vec3(1, 0, 0.3f));
  const glm::mat4 cube_model = Place({1.0f, 0.5f, -0.2f}, 0.6f, 1.0f);
  LitShader lit;
  gl.UseProgram(lit);
  for (auto [vao, mesh, model] : {std::tuple{torus_vao, &torus, torus_model}, std::tuple{cube_vao, &cube, cube_model}}) {
    lit.model = model;
    lit.mvp = vp * model;
    gl.BindVertexArray(vao);
    DrawMesh(gl, *mesh);
  }

  // Pass 2: shells pushed out along the normals, drawn where the stencil is not 1, on top of everything: only
  // the rim around each silhouette shows (inside the torus's hole too).
  gl.StencilFunc(softgl::NOTEQUAL, 1, 0xFF);
  gl.StencilMask(0x00);
  gl.Disable(softgl::DEPTH_TEST);
  OutlineShader outline;
  outline.color = glm::vec4(1.0f, 0.55f, 0.1f, 1.0f);
  gl.UseProgram(outline);
  gl.BindVertexArray(torus_vao);
  outline.mvp = vp * torus_model;
  DrawMesh(gl, torus);
  gl.BindVertexArray(cube_vao);
  outline.thickness = 0.0f;  // a cube's normals are per face: extruding would split its corners; scale instead
  outline.mvp = vp * cube_model * glm::scale(kIdentity, glm::vec3(1.1f));
  DrawMesh(gl, cube);
  return gl.ReadPixels();
}

softgl::Image Mirror(int width, int height) {
  softgl::Context gl(width, height);
  const glm::mat4 vp = Projection(width, height, 50.0f, 0.1f, 30.0f) *
                       glm::lookAt(glm::vec3(0.0f, 2.2f, 4.5f), glm::vec3(0.0f, 0.2f, 0.0f), glm::vec3(0, 1, 0));
  const Mesh cube = MakeCube(), torus = MakeTorus(32, 16, 0.45f, 0.16f);
  const std::uint8_t mirror_color[4] = {255, 255, 255, 255};
  const Mesh mirror = MakeQuad(1.6f, mirror_color);
  const std::uint32_t cube_vao = UploadLitMesh(gl, cube), torus_vao = UploadLitMesh(gl, torus);
  const std::uint32_t mirror_vao = UploadLitMesh(gl, mirror);
  Floor floor(gl, 8.0f);
  const glm::mat4 cube_model = Place({-0.3f, 0.9f, 0.0f}, 0.7f, 0.9f);
  const glm::mat4 torus_model = Place({0.9f, 0.5f, 0.6f}, 0.0f, 1.0f) * glm::rotate(kIdentity, 1.2f, glm::vec3(1, 0, 0));
  const glm::mat4 reflect = glm::scale(kIdentity, glm::vec3(1.0f, -1.0f, 1.0f));  // about the plane y = 0

  gl.ClearColor(0.5f, 0.62f, 0.78f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT | softgl::STENCIL_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  gl.Enable(softgl::STENCIL_TEST);

  // 1. The mirror into the stencil buffer only: 1 where it is, no colour, no depth.
  FlatShader flat;
  flat.mvp = vp;
  gl.UseProgram(flat);
  gl.StencilFunc(softgl::ALWAYS, 1, 0xFF);
  gl.StencilOp(softgl::KEEP, softgl::KEEP, softgl::REPLACE);
  gl.ColorMask(false, false, false, false);
  gl.DepthMask(false);
  gl.BindVertexArray(mirror_vao);
  DrawMesh(gl, mirror);
  gl.ColorMask(true, true, true, true);
  gl.DepthMask(true);

  // 2. The reflected objects where the stencil is 1. A reflection reverses the winding, so front faces are CW.
  gl.StencilFunc(softgl::EQUAL, 1, 0xFF);
  gl.StencilOp(softgl::KEEP, softgl::KEEP, softgl::KEEP);
  gl.FrontFace(softgl::CW);
  LitShader lit;
  auto draw_objects = [&](const glm::mat4& world) {
    gl.UseProgram(lit);
    for (auto [vao, mesh, model] : {std::tuple{cube_vao, &cube, cube_model}, std::tuple{torus_vao, &torus, torus_model}}) {
      lit.model = world * model;
      lit.mvp = vp * lit.model;
      gl.BindVertexArray(vao);
      DrawMesh(gl, *mesh);
    }
  };
  draw_objects(reflect);
  gl.FrontFace(softgl::CCW);

  // 3. The floor around the mirror (where the stencil is not 1).
  gl.StencilFunc(softgl::NOTEQUAL, 1, 0xFF);
  FloorShader floor_shader;
  floor_shader.mvp = vp;
  gl.UseProgram(floor_shader);
  floor.Draw(gl);

  // 4. The mirror's glass: a tinted translucent layer blended over the reflection.
  gl.Disable(softgl::STENCIL_TEST);
  gl.Enable(softgl::BLEND);
  gl.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
  flat.color = glm::vec4(0.55f, 0.7f, 0.85f, 0.35f);
  gl.UseProgram(flat);
  gl.BindVertexArray(mirror_vao);
  DrawMesh(gl, mirror);
  gl.Disable(softgl::BLEND);

  // 5. The objects themselves.
  draw_objects(kIdentity);
  return gl.ReadPixels();
}

softgl::Image Transparency(int width, int height) {
  softgl::Context gl(width, height);
  const glm::mat4 vp = Projection(width, height, 45.0f, 0.1f, 30.0f) *
                       glm::lookAt(glm::vec3(0.0f, 1.2f, 6.0f), glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, 1, 0));
  const Mesh cube = MakeCube();
  const std::uint8_t white[4] = {255, 255, 255, 255};
  const Mesh panel = MakeQuad(0.6f, white);
  const std::uint32_t cube_vao = UploadLitMesh(gl, cube), panel_vao = UploadLitMesh(gl, panel);
  Floor floor(gl, 10.0f);

  gl.ClearColor(0.9f, 0.9f, 0.92f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  FloorShader floor_shader;
  floor_shader.mvp = vp;
  gl.UseProgram(floor_shader);
  floor.Draw(gl);
  LitShader lit;
  gl.UseProgram(lit);
  gl.BindVertexArray(cube_vao);
  for (float x : {-1.6f, 1.6f}) {
    lit.model = Place({x, 0.5f, -1.5f}, 0.5f, 1.0f);
    lit.mvp = vp * lit.model;
    DrawMesh(gl, cube);
  }

  // Three upright panels per side, red nearest; depth writes off while blending.
  const glm::vec4 colors[3] = {{0.1f, 0.3f, 1.0f, 0.5f}, {0.1f, 0.85f, 0.2f, 0.5f}, {1.0f, 0.15f, 0.1f, 0.5f}};
  const float depths[3] = {-0.6f, 0.2f, 1.0f};  // far to near
  FlatShader flat;
  gl.UseProgram(flat);
  gl.BindVertexArray(panel_vao);
  gl.Enable(softgl::BLEND);
  gl.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(false);
  auto draw_panel = [&](float x, int i) {
    flat.color = colors[i];
    const glm::mat4 model = glm::translate(kIdentity, glm::vec3(x + 0.3f * float(i), 0.8f + 0.15f * float(i), depths[i])) *
                            glm::rotate(kIdentity, glm::radians(90.0f), glm::vec3(1, 0, 0));
    flat.mvp = vp * model;
    DrawMesh(gl, panel);
  };
  for (int i = 0; i < 3; ++i) draw_panel(-1.9f, i);  // back to front: correct
  for (int i = 2; i >= 0; --i) draw_panel(1.3f, i);  // front to back: wrong
  gl.DepthMask(true);
  gl.Disable(softgl::BLEND);
  return gl.ReadPixels();
}

namespace {

struct DecalVaryings {
  vec2 uv;
};

// A round badge: rings in uv in [-1, 1]^2, discarded outside the unit circle.
struct DecalShader : softgl::Shader<DecalShader, DecalVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<DecalVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<DecalVaryings>& in, FragmentLanesOut& out) const {
    const Float r = length(in.varyings.uv);
    out.Discard(r > 1.0f);
    const softgl::Bool ring = (softgl::Int(floor(r * 4.0f)) & 1) == 0;
    out.color[0] = select(ring, vec4(glm::vec4(0.95f, 0.95f, 0.9f, 1.0f)), vec4(glm::vec4(0.85f, 0.1f, 0.15f, 1.0f)));
  }
};

}  // namespace

softgl::Image Decals(int width, int height) {
  softgl::Context gl(width, height);
  const glm::mat4 vp = Projection(width, height, 40.0f, 0.5f, 40.0f) *
                       glm::lookAt(glm::vec3(0.0f, 2.0f, 6.5f), glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
  const Mesh cube = MakeCube();
  const std::uint32_t cube_vao = UploadLitMesh(gl, cube);
  // A decal quad on the cube's +z face (z = 0.5), smaller than the face, with its own corners: coplanar with the
  // face but not the same triangles, so without an offset its depth rounds differently from the face's.
  const float decal[] = {-0.37f, -0.31f, 0.5f, -1, -1, 0.33f, -0.31f, 0.5f, 1, -1,
                         0.33f,  0.39f,  0.5f, 1,  1,  -0.37f, 0.39f, 0.5f, -1, 1};
  const std::uint32_t decal_vao = gl.GenVertexArray(), decal_vbo = gl.GenBuffer();
  gl.BindVertexArray(decal_vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, decal_vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof decal, decal);
  gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, 5 * sizeof(float), 0);
  gl.VertexAttributePointer(1, 2, softgl::FLOAT, false, 5 * sizeof(float), 3 * sizeof(float));
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);

  gl.ClearColor(0.16f, 0.17f, 0.2f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  LitShader lit;
  DecalShader decal_shader;
  for (int side = 0; side < 2; ++side) {
    const glm::mat4 model = Place({side == 0 ? -1.3f : 1.3f, 0.3f, 0.0f}, side == 0 ? 0.45f : -0.45f, 1.6f) *
                            glm::rotate(kIdentity, 0.35f, glm::vec3(1, 0, 0));
    lit.model = model;
    lit.mvp = vp * model;
    gl.UseProgram(lit);
    gl.BindVertexArray(cube_vao);
    DrawMesh(gl, cube);
    // The decal, drawn with the face's own depth function (LESS): without offset it loses wherever its depth
    // rounds to the same or a larger value than the face's.
    if (side == 1) {
      gl.Enable(softgl::POLYGON_OFFSET_FILL);
      gl.PolygonOffset(-1.0f, -1.0f);
    }
    decal_shader.mvp = vp * model;
    gl.UseProgram(decal_shader);
    gl.BindVertexArray(decal_vao);
    gl.DrawArrays(softgl::TRIANGLE_FAN, 0, 4);
    gl.Disable(softgl::POLYGON_OFFSET_FILL);
  }
  return gl.ReadPixels();
}

namespace {

// The multisample example's scene, drawn into the bound framebuffer (width x height): a lit torus and a fan of
// thin spokes in front of it, seen at a slant, so that edges of every slope and sliver triangles show.
void SpokesScene(softgl::Context& gl, int width, int height) {
  static const Mesh torus = MakeTorus(32, 16, 0.62f, 0.22f);
  gl.Viewport(0, 0, width, height);
  gl.ClearColor(0.93f, 0.93f, 0.9f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  const glm::mat4 proj = Projection(width, height, 40.0f, 0.1f, 10.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.6f, 4.6f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  LitShader lit;
  lit.model = glm::rotate(kIdentity, 1.1f, glm::vec3(1.0f, 0.2f, 0.0f));
  lit.mvp = proj * view * lit.model;
  UploadLitMesh(gl, torus);
  gl.UseProgram(lit);
  DrawMesh(gl, torus);
  // Spokes: 24 triangles from the centre, each 4 degrees wide, in the plane z = 0.3.
  std::vector<glm::vec4> spokes;
  for (int i = 0; i < 24; ++i) {
    const float a = float(i) * 2.0f * kPi / 24.0f, w = 0.035f;
    spokes.push_back(glm::vec4(0.0f, 0.0f, 0.3f, 1.0f));
    spokes.push_back(glm::vec4(1.0f * std::cos(a - w), 1.0f * std::sin(a - w), 0.3f, 1.0f));
    spokes.push_back(glm::vec4(1.0f * std::cos(a + w), 1.0f * std::sin(a + w), 0.3f, 1.0f));
  }
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(spokes.size() * sizeof(glm::vec4)), spokes.data());
  gl.VertexAttributePointer(0, 4, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  FlatShader flat;
  flat.mvp = proj * view * glm::rotate(kIdentity, -0.5f, glm::vec3(1.0f, 0.0f, 0.0f));
  flat.color = glm::vec4(0.12f, 0.2f, 0.45f, 1.0f);
  gl.UseProgram(flat);
  gl.DrawArrays(softgl::TRIANGLES, 0, int(spokes.size()));
  gl.Disable(softgl::DEPTH_TEST);
}

// `panels` panels side by side, each rendered by draw(p, w, h) at half the panel's size into a framebuffer object
// of samples[p] samples a pixel (colour and depth renderbuffers), resolved into a single-sampled one by a blit,
// then magnified 2x (NEAREST) into the panel, so that the pixels show.
template <class Draw>
softgl::Image MagnifiedPanels(int width, int height, int panels, const int* samples, Draw&& draw) {
  softgl::Context gl(width, height);
  const int panel = width / panels, w = panel / 2, h = height / 2;
  const std::uint32_t resolved = gl.GenFramebuffer(), resolved_color = gl.GenRenderbuffer();
  gl.BindRenderbuffer(softgl::RENDERBUFFER, resolved_color);
  gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::RGBA8, w, h);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, resolved);
  gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::RENDERBUFFER, resolved_color);
  for (int p = 0; p < panels; ++p) {
    const std::uint32_t fbo = gl.GenFramebuffer(), color = gl.GenRenderbuffer(), depth = gl.GenRenderbuffer();
    gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
    gl.BindRenderbuffer(softgl::RENDERBUFFER, color);
    gl.RenderbufferStorageMultisample(softgl::RENDERBUFFER, samples[p], softgl::RGBA8, w, h);
    gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::RENDERBUFFER, color);
    gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
    gl.RenderbufferStorageMultisample(softgl::RENDERBUFFER, samples[p], softgl::DEPTH_COMPONENT24, w, h);
    gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
    draw(gl, p, w, h);
    gl.BindFramebuffer(softgl::READ_FRAMEBUFFER, fbo);
    gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, resolved);
    gl.BlitFramebuffer(0, 0, w, h, 0, 0, w, h, softgl::COLOR_BUFFER_BIT, softgl::NEAREST);  // the resolve
    gl.BindFramebuffer(softgl::READ_FRAMEBUFFER, resolved);
    gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, w, h, p * panel, 0, p * panel + 2 * w, 2 * h, softgl::COLOR_BUFFER_BIT, softgl::NEAREST);
  }
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  return gl.ReadPixels();
}

struct StripesVaryings {
  vec3 normal;
  vec2 uv;
};

// A lit sphere striped along its longitudes: a hard edge (step) inside each triangle, which only shading at the
// samples smooths.
struct StripesShader : softgl::Shader<StripesShader, StripesVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<StripesVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.uv = vec2(in.attrib[3]);
  }
  void Fragment(const FragmentLanes<StripesVaryings>& in, FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), normalize(vec3(0.4f, 0.7f, 0.6f))), 0.0f);
    const Float stripe = step(0.5f, fract(in.varyings.uv.x * 18.0f));
    const vec3 colour = mix(vec3(0.95f, 0.75f, 0.2f), vec3(0.15f, 0.2f, 0.45f), stripe);
    out.color[0] = vec4(colour * (0.25f + 0.75f * diffuse), 1.0f);
  }
};

}  // namespace

softgl::Image Multisample(int width, int height) {
  // Four panels, left to right 1, 2, 4 and 8 samples a pixel.
  const int counts[4] = {0, 2, 4, 8};
  return MagnifiedPanels(width, height, 4, counts, [](softgl::Context& gl, int, int w, int h) { SpokesScene(gl, w, h); });
}

softgl::Image SampleShading(int width, int height) {
  // Two panels of 4 samples a pixel: the shader once per pixel (left), once per sample (right).
  static const Mesh sphere = MakeSphere(24, 12, 1.0f);
  const int counts[2] = {4, 4};
  return MagnifiedPanels(width, height, 2, counts, [](softgl::Context& gl, int p, int w, int h) {
    gl.Viewport(0, 0, w, h);
    gl.ClearColor(0.93f, 0.93f, 0.9f, 1.0f);
    gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
    gl.Enable(softgl::DEPTH_TEST);
    if (p == 1) {
      gl.Enable(softgl::SAMPLE_SHADING);
      gl.MinSampleShading(1.0f);
    }
    StripesShader stripes;
    stripes.model = glm::rotate(glm::rotate(kIdentity, 0.5f, glm::vec3(1, 0, 0)), 0.4f, glm::vec3(0, 0, 1));
    stripes.mvp = Projection(w, h, 40.0f, 0.1f, 10.0f) *
                  glm::lookAt(glm::vec3(0.0f, 0.0f, 3.4f), glm::vec3(0.0f), glm::vec3(0, 1, 0)) * stripes.model;
    UploadLitMesh(gl, sphere);
    gl.UseProgram(stripes);
    DrawMesh(gl, sphere);
    gl.Disable(softgl::SAMPLE_SHADING);
    gl.Disable(softgl::DEPTH_TEST);
  });
}

softgl::Image SmallFormats(int width, int height) {
  softgl::Context gl(width, height);
  // Four panels, left to right RGBA8, RGB565, RGB5_A1 and RGBA4 colour (with a DEPTH_COMPONENT16 depth buffer),
  // each drawn into a framebuffer object of those renderbuffers and copied into the panel by a blit.
  static const Mesh torus = MakeTorus(48, 24, 0.62f, 0.26f);
  const int panel = width / 4;
  const softgl::Enum formats[4] = {softgl::RGBA8, softgl::RGB565, softgl::RGB5_A1, softgl::RGBA4};
  UploadLitMesh(gl, torus);
  for (int p = 0; p < 4; ++p) {
    const std::uint32_t fbo = gl.GenFramebuffer(), color = gl.GenRenderbuffer(), depth = gl.GenRenderbuffer();
    gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
    gl.BindRenderbuffer(softgl::RENDERBUFFER, color);
    gl.RenderbufferStorage(softgl::RENDERBUFFER, formats[p], panel, height);
    gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::RENDERBUFFER, color);
    gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
    gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::DEPTH_COMPONENT16, panel, height);
    gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
    gl.Viewport(0, 0, panel, height);
    gl.ClearColor(0.08f, 0.1f, 0.16f, 1.0f);
    gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
    gl.Enable(softgl::DEPTH_TEST);
    LitShader lit;
    lit.ambient = 0.08f;
    lit.model = glm::rotate(kIdentity, 1.0f, glm::vec3(1.0f, 0.3f, 0.0f));
    lit.mvp = Projection(panel, height, 38.0f, 0.1f, 10.0f) *
              glm::lookAt(glm::vec3(0.0f, 0.4f, 3.4f), glm::vec3(0.0f), glm::vec3(0, 1, 0)) * lit.model;
    gl.UseProgram(lit);
    DrawMesh(gl, torus);
    gl.Disable(softgl::DEPTH_TEST);
    gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, panel, height, p * panel, 0, (p + 1) * panel, height, softgl::COLOR_BUFFER_BIT,
                       softgl::NEAREST);
  }
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  return gl.ReadPixels();
}

}  // namespace scenes

// scenes_textures.cpp — example scenes for textures: mipmapped filtering, shadow mapping, post-processing through
// a framebuffer object, environment mapping with a cube map.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <softgl/shaders.h>

#include "scene_kit.h"
#include "scenes.h"

namespace scenes {

using namespace kit;

namespace {

const glm::mat4 kIdentity(1.0f);

// A 256 x 256 RGBA8 pattern with detail at every scale: checks of 32 texels, a grid every 8, thin diagonals.
std::vector<std::uint8_t> PatternTexels(int n) {
  std::vector<std::uint8_t> px(std::size_t(n) * n * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const bool check = ((x / 32) + (y / 32)) % 2 == 0;
      const bool grid = x % 8 == 0 || y % 8 == 0;
      const bool diagonal = (x + y) % 16 == 0;
      glm::vec3 c = check ? glm::vec3(0.92f, 0.86f, 0.7f) : glm::vec3(0.55f, 0.22f, 0.18f);
      if (grid) c *= 0.35f;
      if (diagonal) c = glm::vec3(0.2f, 0.45f, 0.85f);
      std::uint8_t* p = &px[(std::size_t(y) * n + x) * 4];
      for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(c[k] * 255.0f + 0.5f);
      p[3] = 255;
    }
  return px;
}

// Creates a mipmapped pattern texture on the active unit.
std::uint32_t MakePatternTexture(softgl::Context& gl) {
  constexpr int kN = 256;
  const std::vector<std::uint8_t> px = PatternTexels(kN);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(softgl::TEXTURE_2D, tex);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, kN, kN, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, px.data());
  gl.GenerateMipmap(softgl::TEXTURE_2D);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, softgl::LINEAR);
  return tex;
}

struct TexVaryings {
  vec3 normal;
  vec2 uv;
};

// Diffuse lighting of a texture read on unit 0 through the uv varying (its derivatives give the LOD).
struct TexturedShader : softgl::Shader<TexturedShader, TexVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f};
  float uv_scale = 1.0f;
  glm::vec3 light_dir = glm::normalize(glm::vec3(0.4f, 0.8f, 0.6f));
  void Vertex(const VertexLanes& in, VertexLanesOut<TexVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.uv = vec2(in.attrib[3]) * uv_scale;
  }
  bool use_alpha = false;  // keep the texture's alpha (else 1)
  void Fragment(const FragmentLanes<TexVaryings>& in, FragmentLanesOut& out) const {
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    const vec4 texel = in.Texture(0, in.varyings.uv);
    out.color[0] = texel * (0.35f + 0.65f * diffuse);
    out.color[0].w = use_alpha ? texel.w : Float(1.0f);
  }
};

// A full-screen triangle: positions cover the viewport, uv spans [0, 1] over it.
struct ScreenVaryings {
  vec2 uv;
};

// The floor and cube of TexturedCube and CompressedTextures, uploaded, with the view; depth test on, cleared to sky.
struct FloorScene {
  glm::mat4 vp;
  Mesh floor, cube;
  std::uint32_t floor_vao = 0, cube_vao = 0;
  FloorScene(softgl::Context& gl, int width, int height)
      : vp(Projection(width, height, 55.0f, 0.1f, 200.0f) *
           glm::lookAt(glm::vec3(0.0f, 1.4f, 3.2f), glm::vec3(0.0f, 0.6f, -4.0f), glm::vec3(0, 1, 0))) {
    const std::uint8_t white[4] = {255, 255, 255, 255};
    floor = MakeQuad(60.0f, white);
    cube = MakeCube();
    floor_vao = UploadLitMesh(gl, floor);
    cube_vao = UploadLitMesh(gl, cube);
    gl.Enable(softgl::DEPTH_TEST);
    gl.ClearColor(0.62f, 0.75f, 0.9f, 1.0f);
    gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  }
};

}  // namespace

softgl::Image TexturedCube(int width, int height) {
  softgl::Context gl(width, height);
  const FloorScene scene(gl, width, height);
  const glm::mat4& vp = scene.vp;
  const Mesh &floor = scene.floor, &cube = scene.cube;
  const std::uint32_t floor_vao = scene.floor_vao, cube_vao = scene.cube_vao;
  MakePatternTexture(gl);
  TexturedShader shader;
  gl.UseProgram(shader);
  // The floor repeats the texture 60 times, in three bands. Left, NEAREST (no mipmaps): the far field breaks into
  // moire. Middle, trilinear filtering (LINEAR_MIPMAP_LINEAR): it fades smoothly, but blurs where the floor is
  // seen at a grazing angle. Right, trilinear with 16x anisotropic filtering: the lines stay sharp further away.
  shader.model = kIdentity;
  shader.mvp = vp;
  shader.uv_scale = 60.0f;
  gl.BindVertexArray(floor_vao);
  gl.Enable(softgl::SCISSOR_TEST);
  const int third = width / 3;
  gl.Scissor(0, 0, third, height);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  DrawMesh(gl, floor);
  gl.Scissor(third, 0, third, height);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  DrawMesh(gl, floor);
  gl.Scissor(2 * third, 0, width - 2 * third, height);
  gl.TexParameterf(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_ANISOTROPY, 16.0f);
  DrawMesh(gl, floor);
  gl.TexParameterf(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_ANISOTROPY, 1.0f);
  gl.Disable(softgl::SCISSOR_TEST);
  // The cube, trilinear.
  shader.model = glm::rotate(glm::translate(kIdentity, glm::vec3(0.0f, 0.55f, -1.2f)), 0.6f, glm::vec3(0, 1, 0));
  shader.mvp = vp * shader.model;
  shader.uv_scale = 1.0f;
  gl.BindVertexArray(cube_vao);
  DrawMesh(gl, cube);
  return gl.ReadPixels();
}

namespace {

// The pattern's levels (2 x 2 box averages down to 1 x 1, alpha 255 on the light checks and 96 on the dark ones),
// each with its rows top first as an image file stores them, encoded in `format` and written as a DDS file.
std::vector<std::uint8_t> PatternDds(softgl::Enum format) {
  constexpr int kN = 256;
  std::vector<std::uint8_t> level = PatternTexels(kN);
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) level[(std::size_t(y) * kN + x) * 4 + 3] = ((x / 32) + (y / 32)) % 2 == 0 ? 255 : 96;
  std::vector<std::vector<std::uint8_t>> blocks;
  for (int n = kN;; n /= 2) {
    std::vector<std::uint8_t> top_first(level.size());
    for (int y = 0; y < n; ++y)
      std::copy_n(&level[std::size_t(n - 1 - y) * n * 4], std::size_t(n) * 4, &top_first[std::size_t(y) * n * 4]);
    blocks.push_back(EncodeBlocks(top_first.data(), n, n, format));
    if (n == 1) break;
    std::vector<std::uint8_t> next(std::size_t(n / 2) * (n / 2) * 4);
    for (int y = 0; y < n / 2; ++y)
      for (int x = 0; x < n / 2; ++x)
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int k = 0; k < 4; ++k) sum += level[(std::size_t(2 * y + k / 2) * n + 2 * x + k % 2) * 4 + c];
          next[(std::size_t(y) * (n / 2) + x) * 4 + c] = std::uint8_t((sum + 2) / 4);
        }
    level = std::move(next);
  }
  return MakeDds(format, kN, kN, blocks);
}

}  // namespace

softgl::Image CompressedTextures(int width, int height) {
  softgl::Context gl(width, height);
  const FloorScene scene(gl, width, height);
  const glm::mat4& vp = scene.vp;
  // Three textures of the same pattern: RGBA8 with GenerateMipmap's levels, and DXT1 and DXT5 from DDS files (made
  // here; a real program reads them with TexImage2DFromFile), each of their levels given in the file. The files
  // store the top row first: flip_vertically puts the bottom row at t = 0.
  const std::uint32_t plain = MakePatternTexture(gl), dxt1 = gl.GenTexture(), dxt5 = gl.GenTexture();
  for (const auto& [tex, format] : {std::pair(dxt1, softgl::COMPRESSED_RGB_S3TC_DXT1_EXT),
                                    std::pair(dxt5, softgl::COMPRESSED_RGBA_S3TC_DXT5_EXT)}) {
    const std::vector<std::uint8_t> dds = PatternDds(format);
    gl.BindTexture(softgl::TEXTURE_2D, tex);
    std::string error;
    if (!gl.TexImage2DFromMemory(softgl::TEXTURE_2D, dds.data(), dds.size(), true, &error))
      std::fprintf(stderr, "compressed_textures: %s\n", error.c_str());
    gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  }
  TexturedShader shader;
  gl.UseProgram(shader);
  // The floor in three bands: RGBA8 (4 bytes a texel), DXT1 (half a byte: the colours of each 4 x 4 block on a
  // line between two), DXT5 (one byte: DXT1's colours and an alpha block, blended over the sky).
  shader.mvp = vp;
  shader.uv_scale = 60.0f;
  gl.BindVertexArray(scene.floor_vao);
  gl.Enable(softgl::SCISSOR_TEST);
  const int third = width / 3;
  const std::uint32_t bands[3] = {plain, dxt1, dxt5};
  for (int b = 0; b < 3; ++b) {
    gl.Scissor(b * third, 0, b == 2 ? width - 2 * third : third, height);
    gl.BindTexture(softgl::TEXTURE_2D, bands[b]);
    shader.use_alpha = b == 2;
    if (b == 2) {
      gl.Enable(softgl::BLEND);
      gl.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
    }
    DrawMesh(gl, scene.floor);
  }
  gl.Disable(softgl::BLEND);
  gl.Disable(softgl::SCISSOR_TEST);
  // A cube of each texture, close: the blocks' colours show at this scale.
  shader.use_alpha = false;
  shader.uv_scale = 1.0f;
  gl.BindVertexArray(scene.cube_vao);
  for (int b = 0; b < 3; ++b) {
    shader.model = glm::rotate(glm::translate(kIdentity, glm::vec3(-1.5f + 1.5f * float(b), 0.55f, -1.0f)), 0.6f,
                               glm::vec3(0, 1, 0));
    shader.mvp = vp * shader.model;
    gl.BindTexture(softgl::TEXTURE_2D, bands[b]);
    DrawMesh(gl, scene.cube);
  }
  return gl.ReadPixels();
}

namespace {

// The scene of Srgb(), drawn into the rectangle (x, 0, width, height) of whatever is bound: a textured floor (the
// pattern on unit 0), a white sphere lit by one light, and two overlapping translucent panels. `linear` gives the
// colours it sets as linear values (the sRGB half), else as the encoded values they are on screen.
void SrgbScene(softgl::Context& gl, int x, int width, int height, bool linear) {
  auto to_linear = [&](glm::vec4 c) {
    if (!linear) return c;
    for (int k = 0; k < 3; ++k) c[k] = c[k] <= 0.04045f ? c[k] / 12.92f : std::pow((c[k] + 0.055f) / 1.055f, 2.4f);
    return c;
  };
  gl.Viewport(x, 0, width, height);
  gl.Scissor(x, 0, width, height);
  gl.Enable(softgl::SCISSOR_TEST);
  const glm::mat4 vp = Projection(width, height, 50.0f, 0.1f, 100.0f) *
                       glm::lookAt(glm::vec3(0.0f, 1.5f, 4.2f), glm::vec3(0.0f, 0.7f, -3.0f), glm::vec3(0, 1, 0));
  const std::uint8_t white[4] = {255, 255, 255, 255};
  const Mesh floor = MakeQuad(40.0f, white), sphere = MakeSphere(48, 24, 0.6f), panel = MakeQuad(0.4f, white);
  const glm::vec4 sky = to_linear(glm::vec4(0.62f, 0.75f, 0.9f, 1.0f));
  gl.ClearColor(sky.r, sky.g, sky.b, sky.a);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  TexturedShader textured;
  textured.mvp = vp;
  textured.uv_scale = 16.0f;
  gl.UseProgram(textured);
  UploadLitMesh(gl, floor);
  DrawMesh(gl, floor);
  LitShader lit;
  lit.ambient = 0.02f;
  lit.light_dir = glm::normalize(glm::vec3(0.9f, 0.6f, 0.4f));
  lit.model = glm::translate(kIdentity, glm::vec3(-0.45f, 0.6f, 0.2f));
  lit.mvp = vp * lit.model;
  gl.UseProgram(lit);
  UploadLitMesh(gl, sphere);
  DrawMesh(gl, sphere);
  FlatShader flat;
  gl.UseProgram(flat);
  UploadLitMesh(gl, panel);
  gl.Enable(softgl::BLEND);
  gl.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(false);
  const glm::vec4 colors[2] = {{0.1f, 0.9f, 0.15f, 0.5f}, {0.95f, 0.1f, 0.1f, 0.5f}};
  for (int i = 0; i < 2; ++i) {
    flat.color = to_linear(colors[i]);
    flat.mvp = vp * glm::translate(kIdentity, glm::vec3(0.25f + 0.4f * float(i), 1.15f + 0.3f * float(i), 0.0f + 0.3f * float(i))) *
               glm::rotate(kIdentity, glm::radians(90.0f), glm::vec3(1, 0, 0));
    DrawMesh(gl, panel);
  }
  gl.DepthMask(true);
  gl.Disable(softgl::BLEND);
  gl.Disable(softgl::DEPTH_TEST);
  gl.Disable(softgl::SCISSOR_TEST);
}

}  // namespace

softgl::Image Srgb(int width, int height) {
  softgl::Context gl(width, height);
  const int half = width / 2;
  const std::vector<std::uint8_t> px = PatternTexels(256);
  const std::uint32_t srgb_tex = gl.GenTexture(), plain_tex = gl.GenTexture();
  for (const std::uint32_t tex : {srgb_tex, plain_tex}) {
    gl.BindTexture(softgl::TEXTURE_2D, tex);
    gl.TexImage2D(softgl::TEXTURE_2D, 0, tex == srgb_tex ? softgl::SRGB8_ALPHA8 : softgl::RGBA8, 256, 256, 0,
                  softgl::RGBA, softgl::UNSIGNED_BYTE, px.data());
    gl.GenerateMipmap(softgl::TEXTURE_2D);
    gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  }
  // Left half: in linear light. The pattern is an sRGB texture (decoded before filtering), and the scene is drawn
  // into an SRGB8_ALPHA8 colour texture with FRAMEBUFFER_SRGB enabled (lighting and blending in linear light, the
  // result encoded on store); its bytes are then copied to the screen as they are.
  const std::uint32_t fbo = gl.GenFramebuffer(), color = gl.GenTexture(), depth = gl.GenRenderbuffer();
  gl.BindTexture(softgl::TEXTURE_2D, color);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::SRGB8_ALPHA8, half, height, 0, softgl::RGBA, softgl::UNSIGNED_BYTE,
                nullptr);
  gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
  gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::DEPTH_COMPONENT24, half, height);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, color, 0);
  gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
  gl.BindTexture(softgl::TEXTURE_2D, srgb_tex);
  gl.Enable(softgl::FRAMEBUFFER_SRGB);
  SrgbScene(gl, 0, half, height, true);
  gl.Disable(softgl::FRAMEBUFFER_SRGB);
  gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, 0);
  gl.BlitFramebuffer(0, 0, half, height, 0, 0, half, height, softgl::COLOR_BUFFER_BIT, softgl::NEAREST);
  // Right half: the same scene the naive way, the encoded colours lit, filtered and blended as if linear.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.BindTexture(softgl::TEXTURE_2D, plain_tex);
  SrgbScene(gl, half, width - half, height, false);
  return gl.ReadPixels();
}

namespace {

struct DepthOnlyShader : softgl::Shader<DepthOnlyShader, FlatVaryings> {
  glm::mat4 mvp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<FlatVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
  }
  void Fragment(const FragmentLanes<FlatVaryings>&, FragmentLanesOut&) const {}
};

struct ShadowVaryings {
  vec3 normal;
  vec3 color;
  vec4 light_pos;  // position in the light's clip space
};

// Per-fragment diffuse lighting, shadowed by a 3 x 3 grid of comparison samples of the shadow map on unit 0
// (each itself a 2 x 2 bilinear comparison): percentage-closer filtering.
struct ShadowedShader : softgl::Shader<ShadowedShader, ShadowVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f}, light_vp{1.0f};
  glm::vec3 light_dir{0, 1, 0};
  float texel = 1.0f / 1024.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<ShadowVaryings>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[0]), 1.0f);
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[2]);
    out.varyings.light_pos = light_vp * world;
  }
  void Fragment(const FragmentLanes<ShadowVaryings>& in, FragmentLanesOut& out) const {
    const vec3 p = vec3(in.varyings.light_pos) / in.varyings.light_pos.w * 0.5f + 0.5f;
    Float lit = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        lit += in.TextureShadow(0, vec3(vec2(p) + glm::vec2(dx, dy) * texel, p.z));
    lit /= 9.0f;
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    out.color[0] = vec4(in.varyings.color * (0.25f + 0.75f * diffuse * lit), 1.0f);
  }
};

}  // namespace

namespace {

// The meshes of the two shadow scenes, uploaded in this order: a ground quad of half size `half`, a cube, a torus.
struct ShadowProps {
  Mesh floor, cube, torus;
  std::uint32_t floor_vao, cube_vao, torus_vao;
  ShadowProps(softgl::Context& gl, float half, const std::uint8_t ground[4])
      : floor(MakeQuad(half, ground)), cube(MakeCube()), torus(MakeTorus(40, 20, 0.55f, 0.22f)),
        floor_vao(UploadLitMesh(gl, floor)), cube_vao(UploadLitMesh(gl, cube)), torus_vao(UploadLitMesh(gl, torus)) {}
};

// A mesh placed in the world.
struct Object {
  std::uint32_t vao;
  const Mesh* mesh;
  glm::mat4 model;
};

// Draws each object with `shader` (bound already), its model and mvp = vp * model set first.
template <class Shader, class Objects>
void DrawObjects(softgl::Context& gl, Shader& shader, const glm::mat4& vp, const Objects& objects) {
  for (const Object& o : objects) {
    shader.model = o.model;
    shader.mvp = vp * o.model;
    gl.BindVertexArray(o.vao);
    DrawMesh(gl, *o.mesh);
  }
}

}  // namespace

softgl::Image ShadowMap(int width, int height) {
  softgl::Context gl(width, height);
  constexpr int kShadowSize = 1024;
  const std::uint8_t ground[4] = {200, 200, 190, 255};
  const ShadowProps props(gl, 5.0f, ground);
  const Mesh &floor = props.floor, &cube = props.cube, &torus = props.torus;
  const std::uint32_t floor_vao = props.floor_vao, cube_vao = props.cube_vao, torus_vao = props.torus_vao;
  const Object objects[] = {
      {floor_vao, &floor, kIdentity},
      {cube_vao, &cube, glm::rotate(glm::translate(kIdentity, glm::vec3(-0.9f, 0.5f, 0.3f)), 0.5f, glm::vec3(0, 1, 0))},
      {cube_vao, &cube, glm::scale(glm::translate(kIdentity, glm::vec3(1.1f, 0.35f, -0.9f)), glm::vec3(0.7f))},
      {torus_vao, &torus, glm::rotate(glm::translate(kIdentity, glm::vec3(0.6f, 1.0f, 0.9f)), 1.0f, glm::vec3(1, 0, 0.4f))},
  };
  const glm::vec3 light_dir = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f));
  const glm::mat4 light_vp = glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.5f, 16.0f) *
                             glm::lookAt(light_dir * 8.0f, glm::vec3(0.0f), glm::vec3(0, 1, 0));

  // Pass 1: depth from the light into a depth texture (no colour buffer): softgl::MakeShadowMap makes both with
  // the usual settings (LINEAR comparison filtering, a border of depth 1, LEQUAL compare) and binds them.
  const softgl::ShadowMap shadow = softgl::MakeShadowMap(gl, kShadowSize);
  gl.Viewport(0, 0, kShadowSize, kShadowSize);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Clear(softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::POLYGON_OFFSET_FILL);  // keeps lit surfaces from shadowing themselves (acne)
  gl.PolygonOffset(2.0f, 4.0f);
  DepthOnlyShader depth_shader;
  gl.UseProgram(depth_shader);
  for (const Object& o : objects) {
    depth_shader.mvp = light_vp * o.model;
    gl.BindVertexArray(o.vao);
    DrawMesh(gl, *o.mesh);
  }
  gl.Disable(softgl::POLYGON_OFFSET_FILL);

  // Pass 2: the camera's view, lit and shadowed.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.BindTexture(softgl::TEXTURE_2D, shadow.texture);  // on unit 0, where ShadowedShader reads it
  gl.Viewport(0, 0, width, height);
  gl.ClearColor(0.16f, 0.18f, 0.22f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const glm::mat4 vp = Projection(width, height, 45.0f, 0.1f, 30.0f) *
                       glm::lookAt(glm::vec3(2.2f, 3.4f, 5.2f), glm::vec3(0.0f, 0.4f, 0.0f), glm::vec3(0, 1, 0));
  ShadowedShader lit;
  lit.light_vp = light_vp;
  lit.light_dir = light_dir;
  lit.texel = 1.0f / float(kShadowSize);
  gl.UseProgram(lit);
  DrawObjects(gl, lit, vp, objects);
  return gl.ReadPixels();
}

namespace {

constexpr int kCascades = 3;

struct CascadeVaryings {
  vec3 normal;
  vec3 color;
  vec3 world;
  Float view_depth;  // distance along the camera's view direction
};

// Diffuse lighting shadowed by a cascade of three shadow maps, the layers of a depth texture array on unit 0: each
// fragment takes the first cascade whose far split lies beyond it (the nearest cascade, the finest texels), 2 x 2
// percentage-closer filtering in that layer. With `tint` each cascade colours the surfaces it shadows.
struct CascadeShader : softgl::Shader<CascadeShader, CascadeVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f}, view{1.0f};
  glm::mat4 light_vp[kCascades];
  float split[kCascades] = {};
  glm::vec3 light_dir{0, 1, 0};
  bool tint = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<CascadeVaryings>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[0]), 1.0f);
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[2]);
    out.varyings.world = vec3(world);
    out.varyings.view_depth = -(view * world).z;
  }
  void Fragment(const FragmentLanes<CascadeVaryings>& in, FragmentLanesOut& out) const {
    const vec4 world(in.varyings.world, 1.0f);
    // The cascade: 0, 1 or 2 as the depth passes the splits; its light-space position by a select per lane.
    const Float d = in.varyings.view_depth;
    const softgl::Bool second = d > split[0], third = d > split[1];
    const Float layer = select(third, Float(2.0f), select(second, Float(1.0f), Float(0.0f)));
    const vec4 p0 = light_vp[0] * world, p1 = light_vp[1] * world, p2 = light_vp[2] * world;
    vec3 p;
    for (int c = 0; c < 3; ++c)
      p[c] = select(third, p2[c], select(second, p1[c], p0[c])) * 0.5f + 0.5f;
    const Float lit = in.TextureArrayShadow(0, vec4(vec2(p.x, p.y), layer, p.z));
    const Float diffuse = max(dot(normalize(in.varyings.normal), light_dir), 0.0f);
    vec3 color = in.varyings.color;
    if (tint) {
      const vec3 hue = select(third, vec3(glm::vec3(0.55f, 0.65f, 1.0f)),
                              select(second, vec3(glm::vec3(0.6f, 1.0f, 0.6f)), vec3(glm::vec3(1.0f, 0.6f, 0.55f))));
      color = color * hue;
    }
    out.color[0] = vec4(color * (0.25f + 0.75f * diffuse * lit), 1.0f);
  }
};

// The light's view-projection that holds the part of the camera's view between depths near and far: an
// orthographic box around the sphere through that slice's corners, stretched back towards the light so that
// casters outside the slice still cast into it, its centre snapped to whole texels of a size x size map (the
// shadows then stay put as the camera moves).
glm::mat4 CascadeMatrix(const glm::mat4& view, float fovy, float aspect, float near_d, float far_d,
                        const glm::vec3& light_dir, int size) {
  const glm::mat4 inv = glm::inverse(glm::perspective(fovy, aspect, near_d, far_d) * view);
  glm::vec3 corners[8];
  glm::vec3 centre(0.0f);
  for (int k = 0; k < 8; ++k) {
    const glm::vec4 c = inv * glm::vec4(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f, 1.0f);
    corners[k] = glm::vec3(c) / c.w;
    centre += corners[k] / 8.0f;
  }
  float radius = 0.0f;
  for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - centre));
  radius = std::ceil(radius * 16.0f) / 16.0f;
  const glm::mat4 light_view = glm::lookAt(glm::vec3(0.0f), -light_dir, glm::vec3(0, 1, 0));
  glm::vec3 c = glm::vec3(light_view * glm::vec4(centre, 1.0f));
  const float texel = 2.0f * radius / float(size);
  c.x = std::floor(c.x / texel) * texel;
  c.y = std::floor(c.y / texel) * texel;
  return glm::ortho(c.x - radius, c.x + radius, c.y - radius, c.y + radius, -c.z - radius - 30.0f, -c.z + radius) *
         light_view;
}

}  // namespace

softgl::Image CascadedShadows(int width, int height) {
  softgl::Context gl(width, height);
  constexpr int kShadowSize = 1024;
  const std::uint8_t ground[4] = {205, 200, 185, 255};
  const ShadowProps props(gl, 60.0f, ground);
  const Mesh &floor = props.floor, &cube = props.cube, &torus = props.torus;
  const std::uint32_t floor_vao = props.floor_vao, cube_vao = props.cube_vao, torus_vao = props.torus_vao;
  // Two rows of pillars running away from the camera, and a torus on each near pillar.
  std::vector<Object> objects = {{floor_vao, &floor, kIdentity}};
  for (int i = 0; i < 12; ++i) {
    const float z = 1.0f - 4.5f * float(i);
    for (float x : {-2.2f, 2.2f})
      objects.push_back({cube_vao, &cube, glm::scale(glm::translate(kIdentity, glm::vec3(x, 1.2f, z)),
                                                     glm::vec3(0.5f, 2.4f, 0.5f))});
    if (i < 4)
      objects.push_back({torus_vao, &torus, glm::rotate(glm::translate(kIdentity, glm::vec3(0.0f, 0.9f, z - 2.0f)),
                                                        0.6f * float(i), glm::vec3(0, 1, 0))});
  }
  const glm::vec3 light_dir = glm::normalize(glm::vec3(-0.8f, 0.9f, -0.35f));
  const float fovy = glm::radians(50.0f), aspect = float(width / 2) / float(height), near_d = 0.1f;
  const float splits[kCascades + 1] = {near_d, 6.0f, 18.0f, 55.0f};
  const glm::mat4 view = glm::lookAt(glm::vec3(0.3f, 2.2f, 5.0f), glm::vec3(0.0f, 0.6f, -10.0f), glm::vec3(0, 1, 0));

  // Pass 1: each cascade's depth into its layer of one DEPTH_COMPONENT32F 2D array, through FramebufferTextureLayer.
  const std::uint32_t maps = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(softgl::TEXTURE_2D_ARRAY, maps);
  gl.TexImage3D(softgl::TEXTURE_2D_ARRAY, 0, softgl::DEPTH_COMPONENT32F, kShadowSize, kShadowSize, kCascades, 0,
                softgl::DEPTH_COMPONENT, softgl::FLOAT, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D_ARRAY, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR);
  gl.TexParameteri(softgl::TEXTURE_2D_ARRAY, softgl::TEXTURE_MAG_FILTER, softgl::LINEAR);
  gl.TexParameteri(softgl::TEXTURE_2D_ARRAY, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
  gl.TexParameteri(softgl::TEXTURE_2D_ARRAY, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);
  gl.TexParameteri(softgl::TEXTURE_2D_ARRAY, softgl::TEXTURE_COMPARE_MODE, softgl::COMPARE_REF_TO_TEXTURE);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  const softgl::Enum no_color = softgl::NONE;
  gl.DrawBuffers(1, &no_color);
  gl.Viewport(0, 0, kShadowSize, kShadowSize);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::POLYGON_OFFSET_FILL);  // keeps lit surfaces from shadowing themselves (acne)
  gl.PolygonOffset(2.0f, 4.0f);
  CascadeShader lit;
  DepthOnlyShader depth_shader;
  gl.UseProgram(depth_shader);
  for (int c = 0; c < kCascades; ++c) {
    lit.light_vp[c] = CascadeMatrix(view, fovy, aspect, splits[c], splits[c + 1], light_dir, kShadowSize);
    lit.split[c] = splits[c + 1];
    gl.FramebufferTextureLayer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, maps, 0, c);
    gl.Clear(softgl::DEPTH_BUFFER_BIT);
    for (const Object& o : objects) {
      depth_shader.mvp = lit.light_vp[c] * o.model;
      gl.BindVertexArray(o.vao);
      DrawMesh(gl, *o.mesh);
    }
  }
  gl.Disable(softgl::POLYGON_OFFSET_FILL);

  // Pass 2: the camera's view twice, side by side: lit and shadowed, and with each cascade tinted.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.ClearColor(0.62f, 0.72f, 0.85f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const glm::mat4 vp = glm::perspective(fovy, aspect, near_d, splits[kCascades]) * view;
  lit.view = view;
  lit.light_dir = light_dir;
  gl.UseProgram(lit);
  for (int half = 0; half < 2; ++half) {
    gl.Viewport(half * (width / 2), 0, width / 2, height);
    lit.tint = half == 1;
    DrawObjects(gl, lit, vp, objects);
  }
  return gl.ReadPixels();
}

namespace {

// Tone map (Reinhard) of the HDR scene on unit 0; right of `split`, a 9 x 9 box blur first.
struct PostShader : softgl::Shader<PostShader, ScreenVaryings> {
  glm::vec2 texel{0.0f};
  float split = 0.5f;
  void Vertex(const VertexLanes& in, VertexLanesOut<ScreenVaryings>& out) const {
    out.position = vec4(vec2(in.attrib[0]), 0.0f, 1.0f);
    out.varyings.uv = vec2(in.attrib[0]) * 0.5f + 0.5f;
  }
  void Fragment(const FragmentLanes<ScreenVaryings>& in, FragmentLanesOut& out) const {
    const vec2 uv = in.varyings.uv;
    const softgl::Bool sharp = uv.x < split;
    vec3 hdr = vec3(in.TextureLod(0, uv, 0.0f));
    if (!all(sharp)) {  // some lanes lie right of the split: blur them
      vec3 sum(0.0f);
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) sum += vec3(in.TextureLod(0, uv + glm::vec2(dx, dy) * texel, 0.0f));
      hdr = select(sharp, hdr, sum / 81.0f);
    }
    vec3 ldr = hdr / (hdr + 1.0f);
    ldr = select(abs(uv.x - split) < texel.x, vec3(1.0f), ldr);  // the dividing line
    out.color[0] = vec4(pow(ldr, 1.0f / 2.2f), 1.0f);
  }
};

}  // namespace

softgl::Image PostProcess(int width, int height) {
  softgl::Context gl(width, height);
  // Pass 1: the scene into a half-float (RGBA16F: 8 bytes a pixel) texture, with light brighter than 1 (HDR).
  const std::uint32_t scene_tex = gl.GenTexture(), depth_tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(softgl::TEXTURE_2D, scene_tex);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA16F, width, height, 0, softgl::RGBA, softgl::FLOAT, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);
  gl.BindTexture(softgl::TEXTURE_2D, depth_tex);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::DEPTH_COMPONENT, width, height, 0, softgl::DEPTH_COMPONENT, softgl::FLOAT,
                nullptr);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, scene_tex, 0);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::TEXTURE_2D, depth_tex, 0);
  gl.Enable(softgl::DEPTH_TEST);
  gl.ClearColor(0.05f, 0.06f, 0.1f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const glm::mat4 vp = Projection(width, height, 45.0f, 0.1f, 30.0f) *
                       glm::lookAt(glm::vec3(0.0f, 1.6f, 4.4f), glm::vec3(0.0f, 0.4f, 0.0f), glm::vec3(0, 1, 0));
  const Mesh cube = MakeCube(), torus = MakeTorus(40, 20, 0.6f, 0.24f), sphere = MakeSphere(32, 16, 0.45f);
  const std::uint32_t cube_vao = UploadLitMesh(gl, cube), torus_vao = UploadLitMesh(gl, torus),
                      sphere_vao = UploadLitMesh(gl, sphere);
  LitShader lit;
  lit.brightness = 4.0f;  // HDR: lit faces well above 1
  gl.UseProgram(lit);
  auto draw = [&](std::uint32_t vao, const Mesh& mesh, const glm::mat4& model) {
    lit.model = model;
    lit.mvp = vp * model;
    gl.BindVertexArray(vao);
    DrawMesh(gl, mesh);
  };
  draw(cube_vao, cube, glm::rotate(glm::translate(kIdentity, glm::vec3(-1.3f, 0.4f, 0.0f)), 0.7f, glm::vec3(0, 1, 0)));
  draw(torus_vao, torus, glm::rotate(glm::translate(kIdentity, glm::vec3(0.1f, 0.5f, -0.4f)), 1.2f, glm::vec3(1, 0, 0)));
  draw(sphere_vao, sphere, glm::translate(kIdentity, glm::vec3(1.3f, 0.45f, 0.3f)));

  // Pass 2: the default framebuffer, one full-screen triangle sampling the scene texture.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.Disable(softgl::DEPTH_TEST);
  gl.BindTexture(softgl::TEXTURE_2D, scene_tex);
  MakeScreenTriangle(gl);
  PostShader post;
  post.texel = glm::vec2(1.0f / float(width), 1.0f / float(height));
  gl.UseProgram(post);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

namespace {

// The sky of the environment: a gradient, a sun, and a checkered ground below the horizon.
glm::vec3 Sky(glm::vec3 d) {
  d = glm::normalize(d);
  if (d.y < 0.0f) {
    const glm::vec2 g = glm::vec2(d.x, d.z) / std::max(-d.y, 0.05f);
    const bool check = (int(std::floor(g.x * 2.0f)) + int(std::floor(g.y * 2.0f))) % 2 == 0;
    return check ? glm::vec3(0.35f, 0.3f, 0.25f) : glm::vec3(0.15f, 0.14f, 0.12f);
  }
  const glm::vec3 sun_dir = glm::normalize(glm::vec3(0.6f, 0.5f, -0.6f));
  const float sun = std::pow(std::max(glm::dot(d, sun_dir), 0.0f), 200.0f);
  return glm::mix(glm::vec3(0.85f, 0.9f, 1.0f), glm::vec3(0.2f, 0.45f, 0.85f), std::sqrt(d.y)) + glm::vec3(sun);
}

// The direction through texel (i, j) of cube face f (OpenGL's face orientations, table 8.19 read backwards).
glm::vec3 FaceDirection(int f, float s, float t) {
  const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
  switch (f) {
    case 0: return {1, -tc, -sc};
    case 1: return {-1, -tc, sc};
    case 2: return {sc, 1, tc};
    case 3: return {sc, -1, -tc};
    case 4: return {sc, -tc, 1};
    default: return {-sc, -tc, -1};
  }
}

struct EnvVaryings {
  vec3 dir;  // reflected (objects) or viewing (sky) direction, in world space
};

struct ReflectShader : softgl::Shader<ReflectShader, EnvVaryings> {
  glm::mat4 mvp{1.0f}, model{1.0f};
  glm::vec3 eye{0.0f};
  glm::vec3 tint{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<EnvVaryings>& out) const {
    const vec3 world = vec3(model * vec4(vec3(in.attrib[0]), 1.0f));
    const vec3 n = normalize(glm::mat3(model) * vec3(in.attrib[1]));
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.dir = reflect(world - eye, n);
  }
  void Fragment(const FragmentLanes<EnvVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(vec3(in.TextureCube(0, in.varyings.dir)) * tint, 1.0f);
  }
};

// The background: each pixel looks up the direction it sees.
struct SkyShader : softgl::Shader<SkyShader, EnvVaryings> {
  glm::mat4 inverse_vp{1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<EnvVaryings>& out) const {
    const vec2 p(in.attrib[0]);
    out.position = vec4(p, 1.0f, 1.0f);  // on the far plane
    const vec4 near_point = inverse_vp * vec4(p, -1.0f, 1.0f), far_point = inverse_vp * vec4(p, 1.0f, 1.0f);
    out.varyings.dir = vec3(far_point) / far_point.w - vec3(near_point) / near_point.w;
  }
  void Fragment(const FragmentLanes<EnvVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = in.TextureCube(0, in.varyings.dir);
  }
};

}  // namespace

softgl::Image EnvironmentMap(int width, int height) {
  softgl::Context gl(width, height);
  // The cube map, computed per texel from the direction it stands for.
  constexpr int kFace = 128;
  const std::uint32_t cube_map = gl.GenTexture();
  gl.BindTexture(softgl::TEXTURE_CUBE_MAP, cube_map);
  std::vector<float> texels(std::size_t(kFace) * kFace * 4);
  for (int f = 0; f < 6; ++f) {
    for (int j = 0; j < kFace; ++j)
      for (int i = 0; i < kFace; ++i) {
        const glm::vec3 c = Sky(FaceDirection(f, (float(i) + 0.5f) / kFace, (float(j) + 0.5f) / kFace));
        float* p = &texels[(std::size_t(j) * kFace + i) * 4];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = 1.0f;
      }
    gl.TexImage2D(softgl::TEXTURE_CUBE_MAP_POSITIVE_X + softgl::Enum(f), 0, softgl::RGBA8, kFace, kFace, 0, softgl::RGBA,
                  softgl::FLOAT, texels.data());
  }
  gl.GenerateMipmap(softgl::TEXTURE_CUBE_MAP);
  gl.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
  gl.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);

  const glm::vec3 eye(0.0f, 0.6f, 4.0f);
  const glm::mat4 vp = Projection(width, height, 50.0f, 0.1f, 50.0f) *
                       glm::lookAt(eye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
  gl.Enable(softgl::DEPTH_TEST);
  gl.DepthFunc(softgl::LEQUAL);  // the sky is drawn on the far plane
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const Mesh sphere = MakeSphere(48, 24, 0.8f), torus = MakeTorus(48, 24, 0.7f, 0.25f);
  const std::uint32_t sphere_vao = UploadLitMesh(gl, sphere), torus_vao = UploadLitMesh(gl, torus);
  ReflectShader reflect;
  reflect.eye = eye;
  gl.UseProgram(reflect);
  reflect.model = glm::translate(kIdentity, glm::vec3(-1.0f, 0.3f, 0.0f));
  reflect.mvp = vp * reflect.model;
  gl.BindVertexArray(sphere_vao);
  DrawMesh(gl, sphere);
  reflect.model = glm::rotate(glm::translate(kIdentity, glm::vec3(1.1f, 0.3f, 0.0f)), 1.1f, glm::vec3(1, 0, 0.3f));
  reflect.mvp = vp * reflect.model;
  reflect.tint = glm::vec3(1.0f, 0.8f, 0.45f);  // gold
  gl.BindVertexArray(torus_vao);
  DrawMesh(gl, torus);
  SkyShader sky;
  sky.inverse_vp = glm::inverse(vp);
  gl.UseProgram(sky);
  MakeScreenTriangle(gl);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

}  // namespace scenes

// Wide shaders through the whole pipeline: the same shader written in the wide and in the scalar form draws the
// same bytes; per-lane branches, discard and NaN lanes; Flat<> and NoPerspective<> varyings with both provoking
// vertex conventions; the wide vertex stage; textures sampled 16 lanes at a time against one at a time.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <softgl/softgl.h>

#include "helpers.h"
#include "scene_kit.h"
#include "texture.h"

using namespace softgl;
namespace kit = scenes::kit;

namespace {

// ---- Pairs of shaders: the same computation, wide and scalar -----------------------------------------------------

// Lit and textured: normalize, dot, max, mix, floor, a texture with its mipmaps, a cube map, discard.
struct WideVary {
  vec3 normal;
  vec2 uv;
  vec3 dir;
};
struct ScalarVary {
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec3 dir;
};

struct Uniforms {
  glm::mat4 mvp{1.0f}, model{1.0f};
  glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.9f, 0.4f));
  glm::vec3 eye{0.0f, 1.0f, 3.0f};
  float uv_scale = 3.0f;
  int mode = 0;  // 0 lit texture, 1 checks and discard, 2 cube map, 3 specular (pow)
};

struct WideShader : Shader<WideShader, WideVary>, Uniforms {
  void Vertex(const VertexLanes& in, VertexLanesOut<WideVary>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[0]), 1.0f);
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * vec3(in.attrib[1]);
    out.varyings.uv = vec2(in.attrib[3]) * uv_scale;
    out.varyings.dir = reflect(vec3(world) - eye, normalize(out.varyings.normal));
  }
  void Fragment(const FragmentLanes<WideVary>& in, FragmentLanesOut& out) const {
    const vec3 n = normalize(in.varyings.normal);
    const Float d = max(dot(n, light), 0.0f);
    switch (mode) {
      case 0: out.color[0] = vec4(vec3(in.Texture(0, in.varyings.uv)) * mix(Float(0.3f), Float(1.0f), d), 1.0f); break;
      case 1: {
        const Int cells = Int(floor(in.varyings.uv.x)) + Int(floor(in.varyings.uv.y));
        out.Discard((cells & 3) == 0);
        out.color[0] = vec4(select((cells & 1) != 0, vec3(d), vec3(1.0f - d)), 1.0f);
        break;
      }
      case 2: out.color[0] = in.TextureCube(1, in.varyings.dir) * (0.5f + 0.5f * d); break;
      default: {
        const vec3 h = normalize(light + normalize(glm::vec3(0.0f, 0.0f, 1.0f) - n));
        out.color[0] = vec4(vec3(d * 0.7f + pow(max(dot(n, h), 0.0f), 24.0f)), 1.0f);
        break;
      }
    }
  }
};

struct ScalarShader : softgl::Shader<ScalarShader, ScalarVary>, Uniforms {
  void Vertex(const VertexIn& in, VertexOut<ScalarVary>& out) const {
    const glm::vec4 world = model * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.position = mvp * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::mat3(model) * glm::vec3(in.attrib[1]);
    out.varyings.uv = glm::vec2(in.attrib[3]) * uv_scale;
    out.varyings.dir = glm::reflect(glm::vec3(world) - eye, glm::normalize(out.varyings.normal));
  }
  bool Fragment(const FragmentIn<ScalarVary>& in, FragmentOut& out) const {
    const glm::vec3 n = glm::normalize(in.varyings.normal);
    const float d = std::max(glm::dot(n, light), 0.0f);
    switch (mode) {
      case 0: out.color[0] = glm::vec4(glm::vec3(in.Texture(0, &ScalarVary::uv)) * glm::mix(0.3f, 1.0f, d), 1.0f); break;
      case 1: {
        const int cells = int(std::floor(in.varyings.uv.x)) + int(std::floor(in.varyings.uv.y));
        if ((cells & 3) == 0) return false;
        out.color[0] = glm::vec4((cells & 1) != 0 ? glm::vec3(d) : glm::vec3(1.0f - d), 1.0f);
        break;
      }
      case 2: out.color[0] = in.TextureCube(1, &ScalarVary::dir) * (0.5f + 0.5f * d); break;
      default: {
        const glm::vec3 h = glm::normalize(light + glm::normalize(glm::vec3(0.0f, 0.0f, 1.0f) - n));
        out.color[0] = glm::vec4(glm::vec3(d * 0.7f + std::pow(std::max(glm::dot(n, h), 0.0f), 24.0f)), 1.0f);
        break;
      }
    }
    return true;
  }
};

// A torus and a sphere in perspective, textured (unit 0: RGBA8 mipmapped, trilinear) and environment-mapped (unit
// 1: a cube map), drawn with `shader`.
template <class S>
softgl::Image DrawScene(S& shader, int mode, int w = 200, int h = 150) {
  Context gl(w, h);
  gl.Enable(DEPTH_TEST);
  gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  std::vector<std::uint8_t> texels(64 * 64 * 4);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i)
      for (int c = 0; c < 4; ++c) texels[std::size_t((j * 64 + i) * 4 + c)] = std::uint8_t((i * 37 + j * 11 + c * 90) ^ (i * j));
  gl.ActiveTexture(TEXTURE0);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 64, 64, 0, RGBA, UNSIGNED_BYTE, texels.data());
  gl.GenerateMipmap(TEXTURE_2D);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  gl.ActiveTexture(TEXTURE0 + 1);
  gl.BindTexture(TEXTURE_CUBE_MAP, gl.GenTexture());
  for (int f = 0; f < 6; ++f) {
    std::vector<std::uint8_t> face(16 * 16 * 4);
    for (std::size_t i = 0; i < face.size(); ++i) face[i] = std::uint8_t(f * 40 + int(i % 61) * 3);
    gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, RGBA8, 16, 16, 0, RGBA, UNSIGNED_BYTE, face.data());
  }
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR);
  const kit::Mesh torus = kit::MakeTorus(24, 12, 0.7f, 0.3f), sphere = kit::MakeSphere(16, 12, 0.5f);
  const glm::mat4 vp = kit::Projection(w, h, 50.0f, 0.1f, 20.0f) *
                       glm::lookAt(glm::vec3(0.0f, 1.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  shader.mode = mode;
  gl.UseProgram(shader);
  const glm::mat4 models[2] = {glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f, 0.0f, 0.0f)), 0.9f,
                                           glm::vec3(1, 0.3f, 0)),
                               glm::translate(glm::mat4(1.0f), glm::vec3(0.8f, 0.1f, 0.4f))};
  const kit::Mesh* meshes[2] = {&torus, &sphere};
  for (int k = 0; k < 2; ++k) {
    shader.model = models[k];
    shader.mvp = vp * models[k];
    kit::UploadLitMesh(gl, *meshes[k]);
    kit::DrawMesh(gl, *meshes[k]);
  }
  CHECK(gl.GetError() == NO_ERROR);
  return gl.ReadPixels();
}

// Largest channel difference and number of differing pixels.
std::pair<int, int> Difference(const softgl::Image& a, const softgl::Image& b) {
  int worst = 0, pixels = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    worst = std::max(worst, d);
    pixels += d > 0;
  }
  return {worst, pixels};
}

}  // namespace

TEST_CASE("a shader in the wide and in the scalar form draws the same bytes", "[wide]") {
  // Interpolation, normalize, dot, mix, floor, integer arithmetic, discard, trilinear texturing and cube maps are
  // exact in both forms: the images are identical.
  for (int mode : {0, 1, 2}) {
    WideShader wide;
    ScalarShader scalar;
    const softgl::Image a = DrawScene(wide, mode), b = DrawScene(scalar, mode);
    const auto [worst, pixels] = Difference(a, b);
    INFO("mode " << mode << ": " << pixels << " pixels differ, by up to " << worst);
    CHECK(worst == 0);
    int drawn = 0;  // the scene is there (not two blank images)
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) drawn += a.rgba[i + 2] != 77;
    CHECK(drawn > 4000);
  }
  // pow is a polynomial in the wide form (std::pow in the scalar one): within one step of 8 bits.
  WideShader wide;
  ScalarShader scalar;
  const auto [worst, pixels] = Difference(DrawScene(wide, 3), DrawScene(scalar, 3));
  INFO("pow: " << pixels << " pixels differ, by up to " << worst);
  CHECK(worst <= 1);
}

namespace {

struct NoVary {};

// Each lane takes its own branch, by pixel; NaN and infinite values in some lanes.
struct LaneShader : Shader<LaneShader, NoVary> {
  int mode = 0;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVary>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVary>& in, FragmentLanesOut& out) const {
    const Int x = Int(in.frag_coord.x), y = Int(in.frag_coord.y);
    if (mode == 0) {  // a branch per lane: red where x + y is even, else green, blue scaled by x
      const Bool even = ((x + y) & 1) == 0;
      out.color[0] = select(even, vec4(1.0f, 0.0f, Float(x) / 255.0f, 1.0f), vec4(0.0f, 1.0f, 0.0f, 1.0f));
    } else if (mode == 1) {  // discard where x is a multiple of 3
      out.Discard((x - (x / 3) * 3) == 0);
      out.color[0] = vec4(1.0f);
    } else {  // NaN where x % 4 == 1 (sqrt of a negative), infinity where x % 4 == 2, 0.5 elsewhere
      const Int k = x & 3;
      const Float v = select(k == 1, sqrt(Float(-1.0f)), select(k == 2, Float(1.0f) / 0.0f, Float(0.5f)));
      out.color[0] = vec4(v, 0.25f, v, 1.0f);
    }
  }
};

softgl::Image DrawLanes(int mode) {
  Context gl(37, 23);  // not a multiple of 4: quads and blocks cut at the edges
  gl.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  LaneShader shader;
  shader.mode = mode;
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  gl.DrawArrays(TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

const std::uint8_t* Pixel(const softgl::Image& img, int x, int y) {
  return img.rgba.data() + (std::size_t(img.height - 1 - y) * std::size_t(img.width) + std::size_t(x)) * 4;
}

}  // namespace

TEST_CASE("lanes that branch differently each get their own result", "[wide]") {
  const softgl::Image img = DrawLanes(0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = Pixel(img, x, y);
      if ((x + y) % 2 == 0) {
        REQUIRE(int(p[0]) == 255);
        REQUIRE(int(p[2]) == x);
      } else {
        REQUIRE(int(p[0]) == 0);
        REQUIRE(int(p[1]) == 255);
      }
    }
}

TEST_CASE("discard is a lane mask: discarded lanes write nothing, the others go on", "[wide]") {
  const softgl::Image img = DrawLanes(1);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = Pixel(img, x, y);
      const bool discarded = x % 3 == 0;
      REQUIRE(int(p[0]) == (discarded ? 0 : 255));
      REQUIRE(int(p[2]) == 255);
    }
}

TEST_CASE("NaN and infinite colours in some lanes convert as OpenGL says and leave the others alone", "[wide]") {
  const softgl::Image img = DrawLanes(2);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = Pixel(img, x, y);
      const int want = x % 4 == 1 ? 0 : x % 4 == 2 ? 255 : 128;  // NaN -> 0, +inf clamps to 1
      REQUIRE(int(p[0]) == want);
      REQUIRE(int(p[1]) == 64);
      REQUIRE(int(p[2]) == want);
    }
}

namespace {

// Flat and noperspective varyings beside a smooth one.
struct QualifiedVary {
  Flat<vec3> flat;
  NoPerspective<Float> linear;
  Float smooth;
};
struct QualifiedShader : Shader<QualifiedShader, QualifiedVary> {
  void Vertex(const VertexLanes& in, VertexLanesOut<QualifiedVary>& out) const {
    out.position = in.attrib[0];
    out.varyings.flat = vec3(in.attrib[1]);
    out.varyings.linear = in.attrib[1].w;
    out.varyings.smooth = in.attrib[1].w;
  }
  void Fragment(const FragmentLanes<QualifiedVary>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.flat, 1.0f);
    out.color[1] = vec4(in.varyings.linear, in.varyings.smooth, 0.0f, 1.0f);
  }
};

// Draws `mode` with vertex i coloured colours[i] (and w of attribute 1 = i), returns the colour at pixel (x, y).
struct FlatProbe {
  Context gl{32, 32};
  QualifiedShader shader;
  FlatProbe() { gl.UseProgram(shader); }
  glm::ivec3 Draw(Enum mode, const std::vector<glm::vec4>& positions, int x, int y, bool first = false) {
    std::vector<glm::vec4> values;
    for (std::size_t i = 0; i < positions.size(); ++i)
      values.push_back(glm::vec4(float(i + 1) / 8.0f, float(i % 2), float(i % 3) / 2.0f, float(i)));
    gl.ProvokingVertex(first ? FIRST_VERTEX_CONVENTION : LAST_VERTEX_CONVENTION);
    gl.Clear(COLOR_BUFFER_BIT);
    testing::MakeVertexArray(gl, positions, values);
    gl.DrawArrays(mode, 0, int(positions.size()));
    std::uint8_t px[4];
    gl.ReadPixel(x, y, px);
    return glm::ivec3(px[0], px[1], px[2]);
  }
  static glm::ivec3 ColorOf(int vertex) {
    return glm::ivec3(FloatToByte(float(vertex + 1) / 8.0f), FloatToByte(float(vertex % 2)),
                      FloatToByte(float(vertex % 3) / 2.0f));
  }
  static int FloatToByte(float f) { return int(std::lround(f * 255.0f)); }
};

}  // namespace

TEST_CASE("flat varyings take the provoking vertex's value, by OpenGL's table for every mode", "[wide]") {
  QualifiedShader probe_shader;
  REQUIRE(probe_shader.VaryingInterpolation() != nullptr);
  CHECK(probe_shader.VaryingInterpolation()[0] == Interpolation::kFlat);
  CHECK(probe_shader.VaryingInterpolation()[2] == Interpolation::kFlat);
  CHECK(probe_shader.VaryingInterpolation()[3] == Interpolation::kNoPerspective);
  CHECK(probe_shader.VaryingInterpolation()[4] == Interpolation::kSmooth);
  FlatProbe p;
  const std::vector<glm::vec4> tri = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}};
  CHECK(p.Draw(TRIANGLES, tri, 4, 4) == FlatProbe::ColorOf(2));        // last
  CHECK(p.Draw(TRIANGLES, tri, 4, 4, true) == FlatProbe::ColorOf(0));  // first
  // A strip of two triangles: triangle 1 is (1, 2, 3), its provoking vertex 3 (last) or 1 (first), though the
  // strip reorders its vertices to keep the winding.
  const std::vector<glm::vec4> strip = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}};
  CHECK(p.Draw(TRIANGLE_STRIP, strip, 4, 4) == FlatProbe::ColorOf(2));
  CHECK(p.Draw(TRIANGLE_STRIP, strip, 28, 28) == FlatProbe::ColorOf(3));
  CHECK(p.Draw(TRIANGLE_STRIP, strip, 4, 4, true) == FlatProbe::ColorOf(0));
  CHECK(p.Draw(TRIANGLE_STRIP, strip, 28, 28, true) == FlatProbe::ColorOf(1));
  // A fan (0, 1, 2), (0, 2, 3): last i + 2, first i + 1 (not the hub).
  const std::vector<glm::vec4> fan = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
  CHECK(p.Draw(TRIANGLE_FAN, fan, 28, 4) == FlatProbe::ColorOf(2));
  CHECK(p.Draw(TRIANGLE_FAN, fan, 4, 28) == FlatProbe::ColorOf(3));
  CHECK(p.Draw(TRIANGLE_FAN, fan, 28, 4, true) == FlatProbe::ColorOf(1));
  CHECK(p.Draw(TRIANGLE_FAN, fan, 4, 28, true) == FlatProbe::ColorOf(2));
  // Lines: the second vertex of each segment, or the first.
  const std::vector<glm::vec4> line = {{-1, 0.03f, 0, 1}, {1, 0.03f, 0, 1}};
  CHECK(p.Draw(LINES, line, 10, 16) == FlatProbe::ColorOf(1));
  CHECK(p.Draw(LINES, line, 10, 16, true) == FlatProbe::ColorOf(0));
  // Clipped: a triangle crossing the near plane keeps its provoking vertex's value in every piece.
  const std::vector<glm::vec4> clipped = {{-1, -1, -2, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}};
  CHECK(p.Draw(TRIANGLES, clipped, 20, 20) == FlatProbe::ColorOf(2));  // (the corner near (0, 0) is cut off)
  CHECK(p.Draw(TRIANGLES, clipped, 6, 26) == FlatProbe::ColorOf(2));
  CHECK(p.Draw(TRIANGLES, clipped, 2, 2) == glm::ivec3(0));
  CHECK(p.gl.GetError() == NO_ERROR);
  p.gl.ProvokingVertex(0x1234);
  CHECK(p.gl.GetError() == INVALID_ENUM);
}

TEST_CASE("noperspective varyings are linear in window space, smooth ones perspective-correct", "[wide]") {
  // A quad receding in depth (w from 1 at the left to 4 at the right), attribute w from 0 to 1 left to right.
  Context gl(64, 8);
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA32F, 64, 8, 0, RGBA, FLOAT, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  const std::uint32_t unused = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, unused);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA32F, 64, 8, 0, RGBA, FLOAT, nullptr);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, TEXTURE_2D, unused, 0);
  const Enum bufs[2] = {NONE, COLOR_ATTACHMENT0};  // out.color[1] (linear, smooth) into the float texture
  gl.DrawBuffers(2, bufs);
  QualifiedShader shader;
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {4, -4, 0, 4}, {-1, 1, 0, 1}, {4, 4, 0, 4}},
                           {{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.Finish();
  REQUIRE(gl.GetError() == NO_ERROR);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  // Read the float texture back through a texture fetch: not needed, the framebuffer object is read directly.
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  for (int x : {3, 20, 40, 60}) {
    const float t = (float(x) + 0.5f) / 64.0f;  // window-space fraction of the way across
    std::uint8_t px[4];
    gl.ReadPixel(x, 4, px);
    // noperspective: t itself; smooth: t / w over (1 - t) / 1 + t / 4 (perspective-correct), well below t.
    CHECK(std::abs(int(px[0]) - int(std::lround(t * 255.0f))) <= 1);
    const float smooth = (t / 4.0f) / ((1.0f - t) + t / 4.0f);
    CHECK(std::abs(int(px[1]) - int(std::lround(smooth * 255.0f))) <= 1);
  }
}

namespace {

// Vertex id, a disabled attribute's current value, and textureLod in the vertex stage, for any vertex count.
struct IdVary {
  Float id;
  vec4 current;
  vec4 fetched;
};
struct IdShader : Shader<IdShader, IdVary> {
  void Vertex(const VertexLanes& in, VertexLanesOut<IdVary>& out) const {
    const Float id = Float(in.vertex_id);
    out.position = vec4(in.attrib[0].x, in.attrib[0].y, 0.0f, 1.0f);
    out.point_size = 1.0f;
    out.varyings.id = id;
    out.varyings.current = in.attrib[5];
    out.varyings.fetched = in.TextureLod(0, vec2(id / 64.0f, 0.5f), 0.0f);
  }
  void Fragment(const FragmentLanes<IdVary>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.id / 255.0f, in.varyings.current.y, in.varyings.fetched.x, 1.0f);
  }
};

}  // namespace

TEST_CASE("the wide vertex stage: vertex ids, current values, textureLod, counts not a multiple of 16", "[wide]") {
  for (int count : {1, 15, 16, 17, 40, 100}) {
    Context gl(128, 4);
    std::vector<std::uint8_t> row(64 * 4);
    for (int i = 0; i < 64; ++i) row[std::size_t(i) * 4] = std::uint8_t(255 - i * 4);
    gl.BindTexture(TEXTURE_2D, gl.GenTexture());
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 64, 1, 0, RGBA, UNSIGNED_BYTE, row.data());
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST);
    IdShader shader;
    gl.UseProgram(shader);
    std::vector<glm::vec4> points;
    for (int i = 0; i < count; ++i) points.push_back(glm::vec4((float(i) + 0.5f) / 64.0f - 1.0f, 0.25f, 0.0f, 1.0f));  // pixel (i, 2)
    testing::MakeVertexArray(gl, points);
    gl.VertexAttrib4f(5, 0.0f, 0.6f, 0.0f, 1.0f);  // attribute 5 disabled: its current value
    gl.DrawArrays(POINTS, 0, count);
    REQUIRE(gl.GetError() == NO_ERROR);
    for (int i = 0; i < count; ++i) {
      std::uint8_t px[4];
      gl.ReadPixel(i, 2, px);
      INFO("count " << count << " vertex " << i);
      REQUIRE(int(px[0]) == i);
      REQUIRE(int(px[1]) == 153);
      REQUIRE(int(px[2]) == 255 - (i % 64) * 4);
    }
  }
}

TEST_CASE("textures sampled 16 lanes at a time give the floats of one lane at a time", "[wide][texture]") {
  // Every format (the vector path takes them all: 8-bit layouts loaded in vector form, with a shorter form for
  // LINEAR magnification and LINEAR or LINEAR_MIPMAP_LINEAR minification; the others read texel by texel), every
  // filter pair, every wrap mode (a border colour set), powers of two or not; random coordinates (far outside
  // [0, 1] too) and derivatives (NaN, huge and zero ones included), compared as bits.
  struct Case {
    Enum format;
    int w, h;
    Enum min_filter, wrap, wrap_t = 0;  // wrap_t 0: as wrap
    Enum mag_filter = LINEAR;
  };
  const Case cases[] = {{RGBA8, 64, 32, LINEAR_MIPMAP_LINEAR, REPEAT}, {RGBA8, 64, 64, LINEAR, REPEAT},
                        {RGB8, 32, 32, LINEAR_MIPMAP_LINEAR, REPEAT},  {RG8, 16, 16, LINEAR_MIPMAP_NEAREST, MIRRORED_REPEAT},
                        {R8, 30, 20, LINEAR, CLAMP_TO_EDGE},            {RGBA32F, 16, 8, NEAREST_MIPMAP_LINEAR, REPEAT},
                        {RGBA8, 48, 16, LINEAR_MIPMAP_LINEAR, REPEAT},  {R8, 32, 16, LINEAR_MIPMAP_LINEAR, REPEAT},
                        {RG8, 16, 16, LINEAR, REPEAT},                 {RG8, 8, 32, LINEAR_MIPMAP_LINEAR, REPEAT},
                        {SRGB8_ALPHA8, 64, 32, LINEAR_MIPMAP_LINEAR, REPEAT}, {SRGB8, 32, 32, LINEAR, REPEAT},
                        {SRGB8_ALPHA8, 24, 16, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE},
                        {RGBA8, 64, 32, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE}, {RGBA8, 32, 64, LINEAR_MIPMAP_LINEAR, MIRRORED_REPEAT},
                        {RGBA8, 37, 23, LINEAR_MIPMAP_LINEAR, MIRRORED_REPEAT}, {RGBA8, 100, 3, LINEAR, MIRRORED_REPEAT},
                        {RGB8, 45, 27, LINEAR_MIPMAP_LINEAR, REPEAT, CLAMP_TO_EDGE},
                        {RG8, 13, 16, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE, MIRRORED_REPEAT},
                        {R8, 1, 5, LINEAR_MIPMAP_LINEAR, MIRRORED_REPEAT, REPEAT},
                        {SRGB8_ALPHA8, 20, 12, LINEAR, MIRRORED_REPEAT, REPEAT},
                        {RGBA8, 16, 16, LINEAR_MIPMAP_LINEAR, CLAMP_TO_BORDER},
                        {RGBA8, 30, 30, NEAREST, MIRRORED_REPEAT},
                        {RGBA8, 32, 32, NEAREST_MIPMAP_NEAREST, REPEAT, 0, NEAREST},
                        {RGBA8, 32, 32, NEAREST_MIPMAP_NEAREST, CLAMP_TO_EDGE, 0, LINEAR},
                        {RGB8, 40, 24, LINEAR_MIPMAP_NEAREST, MIRRORED_REPEAT, 0, NEAREST},
                        {RGBA8, 64, 64, LINEAR_MIPMAP_NEAREST, REPEAT, 0, LINEAR},
                        {RGBA8, 32, 32, LINEAR_MIPMAP_LINEAR, REPEAT, 0, NEAREST},
                        {RGBA8, 20, 36, LINEAR, CLAMP_TO_BORDER, 0, NEAREST},
                        {R8, 17, 33, NEAREST_MIPMAP_LINEAR, REPEAT, CLAMP_TO_BORDER, LINEAR},
                        {SRGB8_ALPHA8, 32, 16, NEAREST_MIPMAP_LINEAR, CLAMP_TO_BORDER, 0, NEAREST},
                        {RG8, 16, 16, NEAREST, CLAMP_TO_BORDER, MIRRORED_REPEAT, NEAREST},
                        {SRGB8, 24, 24, LINEAR, CLAMP_TO_BORDER, CLAMP_TO_EDGE, NEAREST},
                        {RGBA8, 50, 10, LINEAR_MIPMAP_LINEAR, CLAMP_TO_BORDER, REPEAT},
                        {RGBA16F, 16, 16, LINEAR_MIPMAP_LINEAR, CLAMP_TO_BORDER},
                        {RGBA16F, 40, 20, LINEAR_MIPMAP_NEAREST, MIRRORED_REPEAT, REPEAT, NEAREST},
                        {RG32F, 16, 32, NEAREST, REPEAT}, {R16F, 9, 9, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE},
                        {R11F_G11F_B10F, 32, 32, LINEAR_MIPMAP_LINEAR, REPEAT},
                        {RGB565, 20, 30, NEAREST_MIPMAP_LINEAR, CLAMP_TO_BORDER, REPEAT, LINEAR},
                        {RGB10_A2, 16, 16, LINEAR, MIRRORED_REPEAT}, {RGBA16, 32, 16, LINEAR_MIPMAP_LINEAR, REPEAT},
                        {RG16F, 20, 12, LINEAR_MIPMAP_LINEAR, REPEAT}, {RG16, 33, 7, LINEAR, MIRRORED_REPEAT},
                        {R16, 16, 16, LINEAR_MIPMAP_NEAREST, CLAMP_TO_BORDER},
                        {R32F, 31, 17, LINEAR_MIPMAP_LINEAR, REPEAT, CLAMP_TO_EDGE},
                        {RGBA4, 12, 12, NEAREST, REPEAT}, {RGB5_A1, 16, 8, LINEAR_MIPMAP_LINEAR, CLAMP_TO_BORDER}};
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coord(-2.0f, 2.0f), deriv(-0.3f, 0.3f);
  for (const Case& c : cases) {
    detail::TextureObject t;
    t.target = TEXTURE_2D;
    auto& l = t.levels[0][0];
    l.Allocate(c.format, c.w, c.h);
    for (std::size_t i = 0; i < l.data.size(); ++i) l.data[i] = std::uint8_t(rng());
    if (!detail::IsUnorm8(l.layout))  // (random bytes would be NaN floats)
      for (int j = 0; j < c.h; ++j)
        for (int i = 0; i < c.w; ++i)
          detail::StoreTexel(l, i, j, glm::vec4(coord(rng), coord(rng) * 0.5f + 0.5f, 0.5f, coord(rng)));
    detail::GenerateMipmaps(t);
    t.params.min_filter = c.min_filter;
    t.params.wrap_s = c.wrap;
    t.params.wrap_t = c.wrap_t ? c.wrap_t : c.wrap;
    t.params.mag_filter = c.mag_filter;
    t.params.border = glm::vec4(0.2f, 0.9f, 0.45f, 0.7f);
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    CHECK(view.wide);  // a 2D colour texture without anisotropy: the vector path's
    Textures tx;
    tx.unit_2d[0] = &view;
    int compared = 0;
    for (int round = 0; round < 200; ++round) {
      Textures::Lanes lanes;
      const float far = round % 3 == 0 ? 700.0f : 1.0f;  // many periods away: the wrap's modulo at work
      for (int k = 0; k < 16; ++k) {
        lanes.s[k] = coord(rng) * far;
        lanes.t[k] = coord(rng) * (k % 2 ? far : 1.0f);
        lanes.ds_dx[k] = deriv(rng) * (round % 4 == 0 ? 0.01f : 1.0f);
        lanes.dt_dx[k] = deriv(rng);
        lanes.ds_dy[k] = deriv(rng);
        lanes.dt_dy[k] = deriv(rng) * (round % 7 == 0 ? 40.0f : 1.0f);
      }
      if (round == 3) {
        lanes.s[2] = std::numeric_limits<float>::quiet_NaN();
        lanes.ds_dx[5] = lanes.dt_dx[5] = lanes.ds_dy[5] = lanes.dt_dy[5] = 0.0f;
        lanes.dt_dy[6] = std::numeric_limits<float>::infinity();
        lanes.t[7] = 3e9f;
        lanes.s[8] = -3e9f;
        lanes.s[9] = -1e6f;
      }
      float out[4][16];
      const float bias = round % 5 == 0 ? 0.7f : 0.0f;
      tx.SampleLanes(0, lanes, bias, out);
      for (int k = 0; k < 16; ++k) {
        const glm::vec4 one = tx.Sample(0, glm::vec2(lanes.s[k], lanes.t[k]), glm::vec2(lanes.ds_dx[k], lanes.dt_dx[k]),
                                        glm::vec2(lanes.ds_dy[k], lanes.dt_dy[k]), bias);
        for (int ch = 0; ch < 4; ++ch) {
          std::uint32_t a, b;
          std::memcpy(&a, &out[ch][k], 4);
          std::memcpy(&b, &one[ch], 4);
          if (a != b) {
            INFO("format 0x" << std::hex << c.format << std::dec << " lane " << k << " channel " << ch << ": "
                             << out[ch][k] << " vs " << one[ch]);
            CHECK(a == b);
          }
          ++compared;
        }
      }
    }
    CHECK(compared == 200 * 64);
  }
}

TEST_CASE("texels take the bytes of their format", "[wide][texture]") {
  struct Row {
    Enum format;
    std::size_t bytes;
  };
  for (const Row& r : {Row{RGBA8, 4}, Row{RGB8, 4}, Row{RG8, 2}, Row{R8, 1}, Row{RGBA32F, 16}, Row{R32F, 4},
                       Row{DEPTH_COMPONENT, 4}}) {
    detail::TextureLevel l;
    l.Allocate(r.format, 10, 7);
    INFO("format 0x" << std::hex << r.format);
    CHECK(l.data.size() == 10 * 7 * r.bytes + detail::TextureLevel::kGatherPad);
  }
  // RGB8 reads alpha 1; R8 reads (r, 0, 0, 1).
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  const std::uint8_t rgb[3] = {10, 20, 30};
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(TEXTURE_2D, 0, RGB8, 1, 1, 0, RGB, UNSIGNED_BYTE, rgb);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  detail::TextureObject probe;  // (the context's texture is private: check the conversion on a level directly)
  probe.levels[0][0].Allocate(RGB8, 1, 1);
  detail::UploadPixels(probe.levels[0][0], 0, 0, 1, 1, RGB, UNSIGNED_BYTE, detail::ClientLayout{1}, rgb);
  const glm::vec4 texel = probe.levels[0][0].Texel(0, 0);
  CHECK(texel == glm::vec4(10.0f / 255.0f, 20.0f / 255.0f, 30.0f / 255.0f, 1.0f));
  probe.levels[0][0].Allocate(R8, 1, 1);
  detail::UploadPixels(probe.levels[0][0], 0, 0, 1, 1, RGB, UNSIGNED_BYTE, detail::ClientLayout{1}, rgb);
  CHECK(probe.levels[0][0].Texel(0, 0) == glm::vec4(10.0f / 255.0f, 0.0f, 0.0f, 1.0f));
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {
// The first `count` texels of a w x h 2D view (NEAREST), each read at its centre 16 lanes at a time and one at a
// time: how many channel values differ as bits (each reported).
int DifferingTexels(const detail::TextureView& view, int w, int h, int count) {
  Textures tx;
  tx.unit_2d[0] = &view;
  int differ = 0;
  for (int first = 0; first < count; first += 16) {
    Textures::Lanes lanes;
    for (int k = 0; k < 16; ++k) {
      const int i = first + k;
      lanes.s[k] = (float(i % w) + 0.5f) / float(w);
      lanes.t[k] = (float(i / w) + 0.5f) / float(h);
      lanes.ds_dx[k] = 1.0f / float(w);
      lanes.dt_dy[k] = 1.0f / float(h);
      lanes.dt_dx[k] = lanes.ds_dy[k] = 0.0f;
    }
    float out[4][16];
    tx.SampleLanes(0, lanes, 0.0f, out);
    for (int k = 0; k < 16; ++k) {
      const glm::vec4 one = tx.Sample(0, glm::vec2(lanes.s[k], lanes.t[k]), glm::vec2(lanes.ds_dx[k], 0.0f),
                                      glm::vec2(0.0f, lanes.dt_dy[k]), 0.0f);
      for (int ch = 0; ch < 4; ++ch) {
        std::uint32_t a, b;
        std::memcpy(&a, &out[ch][k], 4);
        std::memcpy(&b, &one[ch], 4);
        if (a != b) {
          INFO("texel " << first + k << " channel " << ch << ": 0x" << std::hex << a << " vs 0x" << b);
          CHECK(a == b);
          ++differ;
        }
      }
    }
  }
  return differ;
}
}  // namespace

TEST_CASE("the vector path decodes every half-float texel as the one-lane path does", "[wide][texture]") {
  // Each of the 65536 half-float bit patterns once (zeros, subnormals, normals, infinities, NaNs of both signs),
  // one to a texel in an R16F texture and four to a texel in an RGBA16F one (each read by its own code on the
  // vector path), read with NEAREST at each texel's centre, 16 lanes at a time and one at a time, compared as bits.
  for (const auto& [format, w, h] : {std::tuple{R16F, 256, 256}, std::tuple{RGBA16F, 128, 128}}) {
    detail::TextureObject t;
    t.target = TEXTURE_2D;
    auto& l = t.levels[0][0];
    l.Allocate(format, w, h);
    for (int i = 0; i < 65536; ++i) {
      const std::uint16_t half = std::uint16_t(i);
      std::memcpy(l.data.data() + 2 * i, &half, 2);
    }
    t.params.min_filter = NEAREST;
    t.params.mag_filter = NEAREST;
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    INFO("format 0x" << std::hex << format);
    CHECK(DifferingTexels(view, w, h, w * h) == 0);
  }
}

TEST_CASE("the vector path decodes every R11F_G11F_B10F channel value as the one-lane path does", "[wide][texture]") {
  // Texel i of a 2048-texel R11F_G11F_B10F texture holds 11-bit pattern i in red, 2047 - i in green and the 10-bit
  // pattern i mod 1024 in blue (zeros, subnormals, normals, infinities, NaNs), read with NEAREST at its centre, 16
  // lanes at a time and one at a time, compared as bits.
  detail::TextureObject t;
  t.target = TEXTURE_2D;
  auto& l = t.levels[0][0];
  l.Allocate(R11F_G11F_B10F, 64, 32);
  for (std::uint32_t i = 0; i < 2048; ++i) {
    const std::uint32_t word = i | (2047u - i) << 11 | (i & 1023u) << 22;
    std::memcpy(l.data.data() + 4 * i, &word, 4);
  }
  t.params.min_filter = NEAREST;
  t.params.mag_filter = NEAREST;
  const detail::TextureView view = detail::MakeView(t);
  REQUIRE(view.complete);
  CHECK(DifferingTexels(view, 64, 32, 2048) == 0);
}

TEST_CASE("cube maps, 2D arrays, 3D textures, textureLod and anisotropic filtering sampled 16 lanes at a time give "
          "the floats of one lane at a time",
          "[wide][texture]") {
  // The vector path's other lookups: texture() on a cube map (each lane's face chosen by its direction, lanes of
  // one block on several faces), on a 2D array (each lane's layer, out-of-range and NaN layers included) and on a 3D
  // texture (two slices a level, wrapped by TEXTURE_WRAP_R), and textureLod() on all four targets (NaN, huge and
  // negative levels of detail included); every filter pair and wrap mode, and anisotropic filtering (each lane with
  // its own number of probes) on 2D textures, arrays and cube maps; compared as bits with the one-lane calls.
  struct Case {
    Enum target, format;
    int w, h, layers;
    Enum min_filter, mag_filter, wrap;
    float anisotropy = 1.0f;
    Enum wrap_r = 0;  // 0: as wrap
  };
  const Case cases[] = {
      {TEXTURE_CUBE_MAP, RGBA8, 16, 16, 1, LINEAR_MIPMAP_LINEAR, LINEAR, CLAMP_TO_EDGE},
      {TEXTURE_CUBE_MAP, SRGB8_ALPHA8, 8, 8, 1, LINEAR, LINEAR, REPEAT},
      {TEXTURE_CUBE_MAP, RGBA16F, 32, 32, 1, LINEAR_MIPMAP_NEAREST, NEAREST, MIRRORED_REPEAT},
      {TEXTURE_CUBE_MAP, R8, 5, 5, 1, NEAREST_MIPMAP_LINEAR, LINEAR, CLAMP_TO_BORDER},
      {TEXTURE_2D_ARRAY, RGBA8, 16, 8, 5, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT},
      {TEXTURE_2D_ARRAY, RG8, 12, 20, 3, NEAREST, NEAREST, CLAMP_TO_BORDER},
      {TEXTURE_2D_ARRAY, RGBA32F, 8, 8, 4, LINEAR_MIPMAP_NEAREST, LINEAR, MIRRORED_REPEAT},
      {TEXTURE_2D_ARRAY, RGB565, 10, 6, 2, LINEAR_MIPMAP_LINEAR, NEAREST, CLAMP_TO_EDGE},
      {TEXTURE_2D, RGBA8, 32, 32, 1, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT},
      {TEXTURE_2D, RGB8, 24, 40, 1, NEAREST_MIPMAP_NEAREST, LINEAR, CLAMP_TO_BORDER},
      {TEXTURE_2D, R16F, 16, 16, 1, LINEAR_MIPMAP_NEAREST, NEAREST, MIRRORED_REPEAT},
      {TEXTURE_3D, RGBA8, 16, 16, 16, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT},
      {TEXTURE_3D, RGBA8, 8, 8, 8, LINEAR, LINEAR, CLAMP_TO_EDGE},
      {TEXTURE_3D, SRGB8_ALPHA8, 12, 6, 10, LINEAR_MIPMAP_NEAREST, NEAREST, MIRRORED_REPEAT, 1.0f, CLAMP_TO_BORDER},
      {TEXTURE_3D, RG8, 5, 7, 9, NEAREST_MIPMAP_LINEAR, LINEAR, CLAMP_TO_BORDER, 1.0f, REPEAT},
      {TEXTURE_3D, RGBA16F, 8, 16, 4, NEAREST, NEAREST, REPEAT, 1.0f, MIRRORED_REPEAT},
      {TEXTURE_3D, R11F_G11F_B10F, 8, 8, 8, LINEAR_MIPMAP_LINEAR, LINEAR, CLAMP_TO_EDGE},
      {TEXTURE_3D, R8, 3, 17, 6, NEAREST_MIPMAP_NEAREST, LINEAR, REPEAT, 1.0f, CLAMP_TO_EDGE},
      {TEXTURE_3D, RG8, 6, 5, 7, LINEAR, LINEAR, REPEAT, 1.0f, CLAMP_TO_BORDER},
      {TEXTURE_CUBE_MAP, RGBA16F, 16, 16, 1, NEAREST, NEAREST, CLAMP_TO_BORDER},
      {TEXTURE_2D, RGBA8, 64, 64, 1, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT, 16.0f},
      {TEXTURE_2D, RGBA8, 40, 24, 1, LINEAR_MIPMAP_LINEAR, LINEAR, CLAMP_TO_EDGE, 4.0f},
      {TEXTURE_2D, SRGB8_ALPHA8, 32, 32, 1, LINEAR_MIPMAP_NEAREST, NEAREST, MIRRORED_REPEAT, 2.5f},
      {TEXTURE_2D, RGBA16F, 16, 32, 1, NEAREST_MIPMAP_LINEAR, LINEAR, CLAMP_TO_BORDER, 8.0f},
      {TEXTURE_2D, R8, 16, 16, 1, LINEAR, LINEAR, REPEAT, 16.0f},
      {TEXTURE_2D_ARRAY, RGBA8, 16, 16, 3, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT, 16.0f},
      {TEXTURE_CUBE_MAP, RGBA8, 16, 16, 1, LINEAR_MIPMAP_LINEAR, LINEAR, CLAMP_TO_EDGE, 16.0f},
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coord(-2.0f, 2.0f), deriv(-0.3f, 0.3f), level(-3.0f, 8.0f);
  for (const Case& c : cases) {
    detail::TextureObject t;
    t.target = c.target;
    for (int face = 0; face < t.Faces(); ++face) {
      auto& l = t.levels[face][0];
      l.Allocate(c.format, c.w, c.h, 1, c.layers);
      for (std::size_t i = 0; i < l.data.size(); ++i) l.data[i] = std::uint8_t(rng());
      if (!detail::IsUnorm8(l.layout))  // (random bytes would be NaN floats)
        for (int j = 0; j < c.h * c.layers; ++j)
          for (int i = 0; i < c.w; ++i)
            detail::StoreTexel(l, i, j, glm::vec4(coord(rng), coord(rng) * 0.5f + 0.5f, 0.5f, coord(rng)));
    }
    detail::GenerateMipmaps(t);
    t.params.min_filter = c.min_filter;
    t.params.mag_filter = c.mag_filter;
    t.params.wrap_s = t.params.wrap_t = c.wrap;
    t.params.wrap_r = c.wrap_r ? c.wrap_r : c.wrap;
    t.params.border = glm::vec4(0.2f, 0.9f, 0.45f, 0.7f);
    t.params.max_anisotropy = c.anisotropy;
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    CHECK(view.wide);
    Textures tx;
    if (c.target == TEXTURE_CUBE_MAP) tx.unit_cube[0] = &view;
    else if (c.target == TEXTURE_2D_ARRAY) tx.unit_2d_array[0] = &view;
    else if (c.target == TEXTURE_3D) tx.unit_3d[0] = &view;
    else tx.unit_2d[0] = &view;
    int compared = 0;
    auto compare = [&](const float out[4][16], int k, const glm::vec4& one, const char* what) {
      for (int ch = 0; ch < 4; ++ch) {
        std::uint32_t a, b;
        std::memcpy(&a, &out[ch][k], 4);
        std::memcpy(&b, &one[ch], 4);
        if (a != b) {
          INFO(what << " format 0x" << std::hex << c.format << std::dec << " lane " << k << " channel " << ch << ": "
                    << out[ch][k] << " vs " << one[ch]);
          CHECK(a == b);
        }
        ++compared;
      }
    };
    for (int round = 0; round < 100; ++round) {
      Textures::Lanes lanes;
      float lod[16];
      for (int k = 0; k < 16; ++k) {
        lanes.s[k] = coord(rng);
        lanes.t[k] = coord(rng);
        lanes.r[k] = c.target == TEXTURE_2D_ARRAY ? coord(rng) * 3.0f + 1.0f : coord(rng);
        lanes.ds_dx[k] = deriv(rng) * (round % 4 == 0 ? 0.01f : 1.0f);
        lanes.dt_dx[k] = deriv(rng);
        lanes.dr_dx[k] = deriv(rng);
        lanes.ds_dy[k] = deriv(rng);
        lanes.dt_dy[k] = deriv(rng) * (round % 7 == 0 ? 40.0f : 1.0f);
        lanes.dr_dy[k] = deriv(rng);
        lod[k] = level(rng);
      }
      if (round == 3) {
        lanes.s[2] = std::numeric_limits<float>::quiet_NaN();
        lanes.r[3] = std::numeric_limits<float>::quiet_NaN();
        lanes.r[4] = 1e30f;
        lanes.r[5] = -1e30f;
        lanes.s[6] = lanes.t[6] = lanes.r[6] = 0.0f;  // no direction
        lanes.ds_dx[7] = lanes.dt_dx[7] = lanes.dr_dx[7] = lanes.ds_dy[7] = lanes.dt_dy[7] = lanes.dr_dy[7] = 0.0f;
        lod[8] = std::numeric_limits<float>::quiet_NaN();
        lod[9] = 1e30f;
        lod[10] = -1e30f;
      }
      const float bias = round % 5 == 0 ? 0.7f : 0.0f;
      float out[4][16], out_lod[4][16];
      if (c.target == TEXTURE_CUBE_MAP) {
        tx.SampleCubeLanes(0, lanes, bias, out);
        tx.SampleCubeLodLanes(0, lanes, lod, out_lod);
      } else if (c.target == TEXTURE_2D_ARRAY) {
        tx.SampleArrayLanes(0, lanes, bias, out);
        tx.SampleArrayLodLanes(0, lanes, lod, out_lod);
      } else if (c.target == TEXTURE_3D) {
        tx.Sample3DLanes(0, lanes, bias, out);
        tx.Sample3DLodLanes(0, lanes, lod, out_lod);
      } else {
        tx.SampleLanes(0, lanes, bias, out);
        tx.SampleLodLanes(0, lanes, lod, out_lod);
      }
      for (int k = 0; k < 16; ++k) {
        const glm::vec3 p(lanes.s[k], lanes.t[k], lanes.r[k]);
        const glm::vec3 dx(lanes.ds_dx[k], lanes.dt_dx[k], lanes.dr_dx[k]);
        const glm::vec3 dy(lanes.ds_dy[k], lanes.dt_dy[k], lanes.dr_dy[k]);
        if (c.target == TEXTURE_CUBE_MAP) {
          compare(out, k, tx.SampleCube(0, p, dx, dy, bias), "texture");
          compare(out_lod, k, tx.SampleCubeLod(0, p, lod[k]), "textureLod");
        } else if (c.target == TEXTURE_2D_ARRAY) {
          compare(out, k, tx.SampleArray(0, p, glm::vec2(dx), glm::vec2(dy), bias), "texture");
          compare(out_lod, k, tx.SampleArrayLod(0, p, lod[k]), "textureLod");
        } else if (c.target == TEXTURE_3D) {
          compare(out, k, tx.Sample3D(0, p, dx, dy, bias), "texture");
          compare(out_lod, k, tx.Sample3DLod(0, p, lod[k]), "textureLod");
        } else {
          compare(out, k, tx.Sample(0, glm::vec2(p), glm::vec2(dx), glm::vec2(dy), bias), "texture");
          compare(out_lod, k, tx.SampleLod(0, glm::vec2(p), lod[k]), "textureLod");
        }
      }
    }
    CHECK(compared == 100 * 2 * 64);
  }
}

TEST_CASE("shadow lookups 16 lanes at a time give the floats of one lane at a time", "[wide][texture]") {
  // texture(sampler2DShadow) and texture(sampler2DArrayShadow) on the vector path: each depth format, every
  // comparison function, NEAREST and LINEAR (four comparisons), mipmapped or not, the border's depth compared
  // too; references outside [0, 1] and NaN included. Then texture() on the same depth textures (no comparison).
  struct Case {
    Enum target, format, func, min_filter, mag_filter, wrap;
  };
  const Case cases[] = {
      {TEXTURE_2D, DEPTH_COMPONENT32F, LEQUAL, LINEAR, LINEAR, CLAMP_TO_EDGE},
      {TEXTURE_2D, DEPTH_COMPONENT16, LESS, NEAREST, NEAREST, CLAMP_TO_BORDER},
      {TEXTURE_2D, DEPTH24_STENCIL8, GEQUAL, LINEAR_MIPMAP_LINEAR, LINEAR, REPEAT},
      {TEXTURE_2D, DEPTH_COMPONENT24, GREATER, LINEAR_MIPMAP_NEAREST, NEAREST, CLAMP_TO_BORDER},
      {TEXTURE_2D, DEPTH_COMPONENT32F, EQUAL, NEAREST, NEAREST, MIRRORED_REPEAT},
      {TEXTURE_2D, DEPTH_COMPONENT16, NOTEQUAL, LINEAR, LINEAR, CLAMP_TO_EDGE},
      {TEXTURE_2D, DEPTH_COMPONENT32F, ALWAYS, LINEAR, LINEAR, REPEAT},
      {TEXTURE_2D, DEPTH_COMPONENT32F, NEVER, LINEAR, LINEAR, REPEAT},
      {TEXTURE_2D_ARRAY, DEPTH_COMPONENT32F, LEQUAL, LINEAR, LINEAR, CLAMP_TO_BORDER},
      {TEXTURE_2D_ARRAY, DEPTH_COMPONENT16, GREATER, NEAREST_MIPMAP_LINEAR, LINEAR, REPEAT},
  };
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> coord(-2.0f, 2.0f), deriv(-0.3f, 0.3f), depth(0.0f, 1.0f);
  for (const Case& c : cases) {
    detail::TextureObject t;
    t.target = c.target;
    const int w = 24, h = 16, layers = c.target == TEXTURE_2D_ARRAY ? 3 : 1;
    auto& l = t.levels[0][0];
    l.Allocate(c.format, w, h, 1, layers);
    for (int j = 0; j < h * layers; ++j)
      for (int i = 0; i < w; ++i)
        detail::StoreTexel(l, i, j, glm::vec4(i % 5 == 0 ? 0.5f : depth(rng), 0.0f, 0.0f, 1.0f));
    detail::GenerateMipmaps(t);
    t.params.min_filter = c.min_filter;
    t.params.mag_filter = c.mag_filter;
    t.params.wrap_s = t.params.wrap_t = c.wrap;
    t.params.border = glm::vec4(0.6f, 0.0f, 0.0f, 1.0f);
    t.params.compare_mode = COMPARE_REF_TO_TEXTURE;
    t.params.compare_func = c.func;
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    REQUIRE(view.depth);
    CHECK(view.wide);
    Textures tx;
    if (c.target == TEXTURE_2D_ARRAY) tx.unit_2d_array[0] = &view;
    else tx.unit_2d[0] = &view;
    int compared = 0;
    for (int round = 0; round < 100; ++round) {
      Textures::Lanes lanes;
      float ref[16];
      for (int k = 0; k < 16; ++k) {
        lanes.s[k] = coord(rng);
        lanes.t[k] = coord(rng);
        ref[k] = round % 9 == 0 ? 0.5f : coord(rng) * 0.4f + 0.5f;  // some outside [0, 1]; 0.5 hits EQUAL
        lanes.r[k] = c.target == TEXTURE_2D_ARRAY ? coord(rng) * 2.0f + 1.0f : ref[k];
        lanes.ds_dx[k] = deriv(rng) * (round % 4 == 0 ? 0.01f : 1.0f);
        lanes.dt_dx[k] = deriv(rng);
        lanes.ds_dy[k] = deriv(rng);
        lanes.dt_dy[k] = deriv(rng) * (round % 7 == 0 ? 40.0f : 1.0f);
        lanes.dr_dx[k] = lanes.dr_dy[k] = 0.0f;
      }
      if (round == 3) {
        ref[1] = lanes.r[1] = std::numeric_limits<float>::quiet_NaN();
        lanes.s[2] = std::numeric_limits<float>::quiet_NaN();
        lanes.ds_dx[5] = lanes.dt_dx[5] = lanes.ds_dy[5] = lanes.dt_dy[5] = 0.0f;
      }
      float out[16], plain[4][16];
      if (c.target == TEXTURE_2D_ARRAY) {
        tx.SampleArrayShadowLanes(0, lanes, ref, out);
        tx.SampleArrayLanes(0, lanes, 0.0f, plain);
      } else {
        tx.SampleShadowLanes(0, lanes, out);
        tx.SampleLanes(0, lanes, 0.0f, plain);
      }
      for (int k = 0; k < 16; ++k) {
        const glm::vec2 uv(lanes.s[k], lanes.t[k]), dx(lanes.ds_dx[k], lanes.dt_dx[k]), dy(lanes.ds_dy[k], lanes.dt_dy[k]);
        const glm::vec3 uvl(uv, lanes.r[k]);
        const float one = c.target == TEXTURE_2D_ARRAY ? tx.SampleArrayShadow(0, uvl, ref[k], dx, dy)
                                                       : tx.SampleShadow(0, uv, lanes.r[k], dx, dy);
        const glm::vec4 one_plain =
            c.target == TEXTURE_2D_ARRAY ? tx.SampleArray(0, uvl, dx, dy, 0.0f) : tx.Sample(0, uv, dx, dy, 0.0f);
        std::uint32_t a, b;
        std::memcpy(&a, &out[k], 4);
        std::memcpy(&b, &one, 4);
        if (a != b) {
          INFO("shadow, format 0x" << std::hex << c.format << " func 0x" << c.func << std::dec << " lane " << k << ": "
                                   << out[k] << " vs " << one);
          CHECK(a == b);
        }
        ++compared;
        for (int ch = 0; ch < 4; ++ch) {
          std::memcpy(&a, &plain[ch][k], 4);
          std::memcpy(&b, &one_plain[ch], 4);
          if (a != b) {
            INFO("no comparison, format 0x" << std::hex << c.format << std::dec << " lane " << k << " channel " << ch);
            CHECK(a == b);
          }
          ++compared;
        }
      }
    }
    CHECK(compared == 100 * 16 * 5);
  }
}

TEST_CASE("texelFetch of a multisample array 16 lanes at a time gives the floats of one lane at a time",
          "[wide][texture]") {
  // FetchSampleArrayLanes (layer * samples + sample, read as a multisample texture's plane) against FetchSampleArray:
  // layers and samples inside and outside the texture, texels inside and outside, every kind of layout.
  const Enum formats[] = {RGBA8, SRGB8_ALPHA8, R8, RGBA16F, RGBA32F, R32F, RGB565, RGBA32UI, RG16I, DEPTH_COMPONENT32F};
  std::mt19937 rng(29);
  std::uniform_int_distribution<int> coord(-2, 12), which(-2, 6);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  int compared = 0;
  for (const Enum format : formats) {
    detail::TextureObject t;
    t.target = TEXTURE_2D_MULTISAMPLE_ARRAY;
    auto& l = t.levels[0][0];
    l.Allocate(format, 11, 7, 4, 3);
    for (std::size_t i = 0; i + detail::TextureLevel::kGatherPad < l.data.size(); ++i) l.data[i] = std::uint8_t(rng());
    if (!detail::IsIntegerLayout(l.layout))  // (random bytes would be NaN floats)
      for (int j = 0; j < 7 * 4 * 3; ++j)
        for (int i = 0; i < 11; ++i)
          detail::StoreTexel(l, i, j, glm::vec4(value(rng), value(rng), value(rng), value(rng)));
    const detail::TextureView view = detail::MakeView(t);
    REQUIRE(view.complete);
    Textures tx;
    tx.unit_2d_ms_array[0] = &view;
    for (int round = 0; round < 40; ++round) {
      int x[16], y[16], layer[16], sample[16];
      for (int k = 0; k < 16; ++k) {
        x[k] = coord(rng);
        y[k] = coord(rng);
        layer[k] = which(rng) % 4;
        sample[k] = which(rng);
      }
      if (round == 0) {
        layer[0] = std::numeric_limits<int>::max();
        sample[1] = std::numeric_limits<int>::min();
        x[2] = std::numeric_limits<int>::min();
      }
      float out[4][16];
      tx.FetchSampleArrayLanes(0, x, y, layer, sample, out);
      for (int k = 0; k < 16; ++k) {
        const glm::vec4 one = tx.FetchSampleArray(0, glm::ivec3(x[k], y[k], layer[k]), sample[k]);
        for (int c = 0; c < 4; ++c) {
          CAPTURE(format, k, x[k], y[k], layer[k], sample[k], c);
          CHECK(std::bit_cast<std::uint32_t>(out[c][k]) == std::bit_cast<std::uint32_t>(one[c]));
          ++compared;
        }
      }
    }
  }
  CHECK(compared == 10 * 40 * 64);
}

TEST_CASE("texelFetch 16 lanes at a time gives the floats of one lane at a time", "[wide][texture]") {
  // FetchLanes on every layout (levels of a mipmapped texture, levels it does not have, negative ones) and
  // FetchSampleLanes on a multisample texture (samples it does not have); texels inside, on the edges and outside.
  const Enum formats[] = {RGBA8, SRGB8_ALPHA8, RGB8, RG8, R8, RGBA16F, RGBA32F, R32F, RG16F, RGB565, RGB10_A2,
                          R11F_G11F_B10F, RGBA16, DEPTH_COMPONENT32F};
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> coord(-3, 40), level(-2, 7);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (const bool multisample : {false, true}) {
    for (const Enum format : formats) {
      detail::TextureObject t;
      t.target = multisample ? TEXTURE_2D_MULTISAMPLE : TEXTURE_2D;
      auto& l = t.levels[0][0];
      const int samples = multisample ? 4 : 1;
      l.Allocate(format, 37, 23, samples);
      for (int j = 0; j < 23 * samples; ++j)
        for (int i = 0; i < 37; ++i)
          detail::StoreTexel(l, i, j, glm::vec4(value(rng), value(rng), value(rng), value(rng)));
      if (!multisample) detail::GenerateMipmaps(t);
      t.params.min_filter = NEAREST_MIPMAP_NEAREST;
      const detail::TextureView view = detail::MakeView(t);
      REQUIRE(view.complete);
      Textures tx;
      if (multisample) tx.unit_2d_ms[0] = &view;
      else tx.unit_2d[0] = &view;
      int differ = 0;
      for (int round = 0; round < 50; ++round) {
        int x[16], y[16], which[16];
        for (int k = 0; k < 16; ++k) {
          x[k] = coord(rng);
          y[k] = coord(rng);
          which[k] = multisample ? level(rng) % 6 : (round % 2 ? level(rng) : 0);
        }
        if (round == 1) {
          x[0] = std::numeric_limits<int>::min();
          y[1] = std::numeric_limits<int>::max();
          which[2] = std::numeric_limits<int>::max();
          which[3] = std::numeric_limits<int>::min();
        }
        float out[4][16];
        if (multisample) tx.FetchSampleLanes(0, x, y, which, out);
        else tx.FetchLanes(0, x, y, which, out);
        for (int k = 0; k < 16; ++k) {
          const glm::vec4 one = multisample ? tx.FetchSample(0, glm::ivec2(x[k], y[k]), which[k])
                                            : tx.Fetch(0, glm::ivec2(x[k], y[k]), which[k]);
          for (int c = 0; c < 4; ++c) {
            std::uint32_t a, b;
            std::memcpy(&a, &out[c][k], 4);
            std::memcpy(&b, &one[c], 4);
            if (a != b) {
              INFO("format 0x" << std::hex << format << std::dec << (multisample ? " samples" : "") << " lane " << k
                               << " (" << x[k] << ", " << y[k] << ", " << which[k] << ") channel " << c);
              CHECK(a == b);
              ++differ;
            }
          }
        }
      }
      CHECK(differ == 0);
    }
  }
}

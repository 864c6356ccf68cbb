// Texture arrays and 3D textures: uploads plane by plane, the layer rule, filtering between slices, the level of
// detail of a volume, mipmaps, rendering into one layer (colour and depth), the wide calls against the one-lane
// ones, and the errors of TexImage3D, TexSubImage3D and FramebufferTextureLayer.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "helpers.h"
#include "texture.h"

using namespace softgl;
using detail::TextureObject;
using detail::TextureView;

namespace {

// A layered texture made directly: w x h x d texels of RGBA32F, texel (i, j, k) = f(i, j, k), NEAREST.
template <class F>
TextureObject MakeLayered(Enum target, int w, int h, int d, F f) {
  TextureObject t;
  t.target = target;
  auto& l = t.levels[0][0];
  l.Allocate(RGBA32F, w, h, 1, d);
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) detail::StoreTexel(l, i, k * h + j, f(i, j, k));
  t.params.min_filter = t.params.mag_filter = NEAREST;
  return t;
}

// A colour array (RGBA8) and a depth array (DEPTH_COMPONENT32F) of size x size x layers, no data, and a framebuffer
// object bound (nothing attached yet).
struct ArrayTargets {
  std::uint32_t color = 0, depth = 0, fbo = 0;
  ArrayTargets(Context& gl, int size, int layers)
      : color(gl.GenTexture()), depth(gl.GenTexture()), fbo(gl.GenFramebuffer()) {
    gl.BindTexture(TEXTURE_2D_ARRAY, color);
    gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, size, size, layers, 0, RGBA, UNSIGNED_BYTE, nullptr);
    gl.BindTexture(TEXTURE_2D_ARRAY, depth);
    gl.TexImage3D(TEXTURE_2D_ARRAY, 0, DEPTH_COMPONENT32F, size, size, layers, 0, DEPTH_COMPONENT, FLOAT, nullptr);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
  }
};

// Units 0 of every kind pointing at one view.
struct Bound {
  TextureView view;
  Textures tx;
  explicit Bound(const TextureObject& t) {
    view = detail::MakeView(t);
    tx.unit_2d_array[0] = &view;
    tx.unit_3d[0] = &view;
  }
};

// A full-screen pass whose fragment stage writes texture(unit 0, vec3(uv, layer)) of a 2D array, or of a 3D
// texture with `volume`: uv from the window position over [0, 1], the third coordinate a uniform.
struct ArrayVaryings {
  glm::vec4 uv;
};
struct ShowLayer : softgl::Shader<ShowLayer, ArrayVaryings> {
  float r = 0.0f;
  bool volume = false;
  void Vertex(const VertexIn& in, VertexOut<ArrayVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = in.attrib[0] * 0.5f + 0.5f;
  }
  bool Fragment(const FragmentIn<ArrayVaryings>& in, FragmentOut& out) const {
    const glm::vec3 c(glm::vec2(in.varyings.uv), r);
    out.color[0] = volume ? in.textures->Sample3D(0, c, {}, {}) : in.textures->SampleArray(0, c, {}, {});
    return true;
  }
};

}  // namespace

TEST_CASE("2D arrays: each layer samples on its own; the layer is floor(r + 0.5), clamped", "[texture][layers]") {
  // 2 x 2 x 3: texel (i, j, k) = 100 k + i + 2 j.
  TextureObject t = MakeLayered(TEXTURE_2D_ARRAY, 2, 2, 3, [](int i, int j, int k) {
    return glm::vec4(float(100 * k + i + 2 * j), 0.0f, 0.0f, 1.0f);
  });
  Bound b(t);
  REQUIRE(b.view.complete);
  auto at = [&](float s, float tt, float r) { return b.tx.SampleArray(0, {s, tt, r}, {}, {}).r; };
  CHECK(at(0.25f, 0.25f, 0.0f) == 0.0f);
  CHECK(at(0.75f, 0.75f, 1.0f) == 103.0f);
  CHECK(at(0.75f, 0.25f, 1.49f) == 101.0f);  // rounds down below .5
  CHECK(at(0.75f, 0.25f, 1.5f) == 201.0f);   // and up at it
  CHECK(at(0.25f, 0.75f, -7.0f) == 2.0f);    // clamped to layer 0
  CHECK(at(0.25f, 0.75f, 9.0f) == 202.0f);   // and to the last
  CHECK(at(0.25f, 0.25f, std::nanf("")) == 0.0f);
  // LINEAR filters within the layer only: half way between texel columns of layer 2.
  t.params.mag_filter = LINEAR;
  t.params.wrap_s = t.params.wrap_t = CLAMP_TO_EDGE;
  b.view = detail::MakeView(t);
  CHECK(at(0.5f, 0.25f, 2.0f) == Approx(200.5f));
  // Nothing of another kind answers: the 2D unit is empty, and a 2D array is not a 3D texture's unit.
  CHECK(b.tx.Sample(0, {0.5f, 0.5f}, {}, {}) == glm::vec4(0, 0, 0, 1));
  CHECK(b.tx.SizeArray(0) == glm::ivec3(2, 2, 3));
  CHECK(b.tx.SizeArray(1) == glm::ivec3(0));
}

TEST_CASE("3D textures: LINEAR blends two slices, TEXTURE_WRAP_R wraps them, lambda counts r", "[texture][layers]") {
  // 2 x 2 x 4: texel (i, j, k) = 10 k + i.
  TextureObject t = MakeLayered(TEXTURE_3D, 2, 2, 4, [](int i, int, int k) {
    return glm::vec4(float(10 * k + i), 0.0f, 0.0f, 1.0f);
  });
  Bound b(t);
  REQUIRE(b.view.complete);
  auto at = [&](float s, float r) { return b.tx.Sample3D(0, {s, 0.25f, r}, {}, {}).r; };
  CHECK(at(0.25f, 0.125f) == 0.0f);
  CHECK(at(0.75f, 0.625f) == 21.0f);
  CHECK(at(0.25f, 1.125f) == 0.0f);  // REPEAT in r
  t.params.wrap_r = CLAMP_TO_EDGE;
  b.view = detail::MakeView(t);
  CHECK(at(0.25f, 1.125f) == 30.0f);
  t.params.mag_filter = LINEAR;
  b.view = detail::MakeView(t);
  CHECK(at(0.25f, 0.25f) == Approx(5.0f));    // half way between slices 0 and 1
  CHECK(at(0.5f, 0.3125f) == Approx(8.0f));   // and between columns: (0.75 * 0 + 0.25 * 10) + 0.5
  t.params.wrap_r = CLAMP_TO_BORDER;
  t.params.border = glm::vec4(-40.0f, 0.0f, 0.0f, 1.0f);
  b.view = detail::MakeView(t);
  CHECK(at(0.25f, 1.0f) == Approx(-5.0f));    // half slice 3 (30), half the border (-40)
  CHECK(b.tx.Size3D(0) == glm::ivec3(2, 2, 4));

  // The level of detail: a derivative along r alone minifies a volume (rho = 4 texels of r a pixel: lambda 2).
  TextureObject m;
  m.target = TEXTURE_3D;
  for (int l = 0; l < 4; ++l) {
    const int n = 8 >> l;
    m.levels[0][l].Allocate(RGBA32F, n, n, 1, n);
    for (int k = 0; k < n * n; ++k)
      for (int i = 0; i < n; ++i) detail::StoreTexel(m.levels[0][l], i, k, glm::vec4(float(l), 0, 0, 1));
  }
  m.params.min_filter = NEAREST_MIPMAP_NEAREST;
  m.params.mag_filter = NEAREST;
  Bound mb(m);
  REQUIRE(mb.view.complete);
  CHECK(mb.tx.Sample3D(0, glm::vec3(0.5f), {0, 0, 0.5f}, {0, 0, 0}).r == 2.0f);
  CHECK(mb.tx.Sample3D(0, glm::vec3(0.5f), {0, 0, 0.125f}, {0, 0, 0}).r == 0.0f);
  CHECK(mb.tx.Sample3DLod(0, glm::vec3(0.5f), 3.0f).r == 3.0f);
  // A level whose depth does not halve makes the texture incomplete.
  m.levels[0][2].Allocate(RGBA32F, 2, 2, 1, 1);
  CHECK_FALSE(detail::MakeView(m).complete);
}

TEST_CASE("TexImage3D lays out images plane by plane; GenerateMipmap keeps layers, halves slices",
          "[texture][layers]") {
  Context gl(4, 4);
  const std::uint32_t arr = gl.GenTexture(), vol = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D_ARRAY, arr);
  // 3 x 2 x 2 RGB bytes with UNPACK_ALIGNMENT 4: rows of 9 bytes padded to 12.
  std::vector<std::uint8_t> px(12 * 2 * 2, 0);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) px[std::size_t(k * 24 + j * 12 + i * 3)] = std::uint8_t(100 * k + 10 * j + i);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 3, 2, 2, 0, RGB, UNSIGNED_BYTE, px.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D_ARRAY, 0, TEXTURE_DEPTH, &v);
  CHECK(v == 2);
  gl.GetIntegerv(TEXTURE_BINDING_2D_ARRAY, &v);
  CHECK(v == int(arr));
  gl.GetIntegerv(MAX_ARRAY_TEXTURE_LAYERS, &v);
  CHECK(v == kMaxArrayTextureLayers);
  // Replace texel (1, 1) of layer 1.
  const std::uint8_t one[4] = {7, 0, 0, 0};
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.TexSubImage3D(TEXTURE_2D_ARRAY, 0, 1, 1, 1, 1, 1, 1, RGB, UNSIGNED_BYTE, one);
  CHECK(gl.GetError() == NO_ERROR);
  // Read the layers back through a draw: each layer's texels where the draw samples them.
  gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_MIN_FILTER, NEAREST);
  gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, NEAREST);
  ShowLayer show;
  gl.UseProgram(show);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  auto texel = [&](float layer, float s, float t) {
    show.r = layer;
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    std::uint8_t out[4];
    gl.ReadPixel(int(s * 4), int(t * 4), out);  // the pixel whose centre samples (s, t)'s texel
    return int(out[0]);
  };
  CHECK(texel(0, 0.0f, 0.0f) == 0);
  CHECK(texel(0, 0.75f, 0.75f) == 12);
  CHECK(texel(1, 0.5f, 0.0f) == 101);
  CHECK(texel(1, 0.5f, 0.75f) == 7);
  CHECK(gl.GetError() == NO_ERROR);

  // GenerateMipmap: an array keeps its 2 layers at 1 x 1; a 4 x 4 x 2 volume goes 2 x 2 x 1, then 1 x 1 x 1.
  gl.GenerateMipmap(TEXTURE_2D_ARRAY);
  gl.GetTexLevelParameteriv(TEXTURE_2D_ARRAY, 1, TEXTURE_DEPTH, &v);
  CHECK(v == 2);
  gl.BindTexture(TEXTURE_3D, vol);
  std::vector<float> texels(4 * 4 * 2 * 4, 0.0f);
  for (int k = 0; k < 2; ++k)
    for (int n = 0; n < 16; ++n) texels[std::size_t((k * 16 + n) * 4)] = k ? 1.0f : 0.5f;
  gl.TexImage3D(TEXTURE_3D, 0, RGBA32F, 4, 4, 2, 0, RGBA, FLOAT, texels.data());
  gl.GenerateMipmap(TEXTURE_3D);
  CHECK(gl.GetError() == NO_ERROR);
  const int sizes[4][3] = {{4, 4, 2}, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}};
  for (int l = 0; l < 4; ++l) {
    int w = -1, h = -1, d = -1;
    gl.GetTexLevelParameteriv(TEXTURE_3D, l, TEXTURE_WIDTH, &w);
    gl.GetTexLevelParameteriv(TEXTURE_3D, l, TEXTURE_HEIGHT, &h);
    gl.GetTexLevelParameteriv(TEXTURE_3D, l, TEXTURE_DEPTH, &d);
    CHECK(glm::ivec3(w, h, d) == glm::ivec3(sizes[l][0], sizes[l][1], sizes[l][2]));
  }
  // Level 1's texels average both slices: 0.75.
  gl.TexParameteri(TEXTURE_3D, TEXTURE_MIN_FILTER, NEAREST_MIPMAP_NEAREST);
  show.volume = true;
  gl.BindTexture(TEXTURE_2D_ARRAY, 0);
  struct Lod1 : softgl::Shader<Lod1, testing::NoVaryings> {
    mutable glm::vec4 got{-1.0f};
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      out.position = glm::vec4(2, 2, 2, 1);
      got = in.textures->Sample3DLod(0, glm::vec3(0.5f), 1.0f);
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut&) const { return false; }
  } lod1;
  gl.UseProgram(lod1);
  gl.DrawArrays(POINTS, 0, 1);
  gl.Finish();
  CHECK(lod1.got.r == Approx(0.75f));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("FramebufferTextureLayer draws into one layer, of colour and of depth", "[texture][layers][framebuffer]") {
  Context gl(4, 4);
  const ArrayTargets arrays(gl, 4, 3);
  const std::uint32_t color = arrays.color, depth = arrays.depth;
  testing::SolidShader solid;
  gl.UseProgram(solid);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.Enable(DEPTH_TEST);
  // Layer k: cleared to depth 1, then a quad of colour k at depth (k + 1) / 4 (window z of clip z (k + 1) / 2 - 1).
  for (int k = 0; k < 3; ++k) {
    gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0, k);
    gl.FramebufferTextureLayer(FRAMEBUFFER, DEPTH_ATTACHMENT, depth, 0, k);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    gl.ClearColor(0, 0, 0, 0);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    solid.color = glm::vec4(float(k + 1) * 0.25f, 0.0f, 0.0f, 1.0f);
    const float z = float(k + 1) * 0.5f - 1.0f;
    testing::MakeVertexArray(gl, {{-1, -1, z, 1}, {1, -1, z, 1}, {-1, 1, z, 1}, {1, 1, z, 1}});
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  }
  int v = -1;
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &v);
  CHECK(v == 2);
  // Reading reads the attached layer.
  std::uint8_t px[4];
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == 191);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0, 0);
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == 64);
  // A layer the level does not have: incomplete.
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0, 3);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  CHECK(gl.GetError() == NO_ERROR);

  // Each depth layer holds its own quad's depth: a shadow lookup per layer against 0.4 passes only where the
  // stored depth (0.25, 0.5, 0.75) is at least 0.4... with LEQUAL: ref <= stored.
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_COMPARE_MODE, COMPARE_REF_TO_TEXTURE);
  gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_MIN_FILTER, NEAREST);
  gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, NEAREST);
  struct Probe : softgl::Shader<Probe, testing::NoVaryings> {
    mutable float got[3] = {-1, -1, -1};
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      out.position = glm::vec4(2, 2, 2, 1);
      for (int k = 0; k < 3; ++k) got[k] = in.textures->SampleArrayShadow(0, {0.5f, 0.5f, float(k)}, 0.4f, {}, {});
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut&) const { return false; }
  } probe;
  gl.UseProgram(probe);
  gl.DrawArrays(POINTS, 0, 1);
  gl.Finish();
  CHECK(probe.got[0] == 0.0f);
  CHECK(probe.got[1] == 1.0f);
  CHECK(probe.got[2] == 1.0f);
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {
// A quad in perspective drawn with `program` (w grows upwards, so the level of detail changes over it): the image.
std::vector<std::uint8_t> DrawPerspectiveQuad(Context& gl, const Program& program) {
  gl.UseProgram(program);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-3, 3, 0, 3}, {3, 3, 0, 3}},
                           {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 3, 0, 3}, {3, 3, 0, 3}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  CHECK(gl.GetError() == NO_ERROR);
  return gl.ReadPixels().rgba;
}

// A wide shader's image against its one-lane twin's: the same bytes, and most of the 48 x 40 pixels coloured.
void CheckSameImage(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  REQUIRE(a.size() == b.size());
  int differing = 0, coloured = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    differing += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    coloured += a[i] != 0 || a[i + 1] != 0;
  }
  CHECK(differing == 0);
  CHECK(coloured > 48 * 40 / 2);
}

// The same lookups written wide and one lane at a time: a 2D array (its layer from x) and a 3D texture (r from
// y), both LINEAR_MIPMAP_LINEAR with mipmaps, so that the level of detail and both filters take part.
struct WideUv {
  softgl::vec3 a, b;
};
struct ScalarUv {
  glm::vec3 a, b;
};
struct WideLayers : softgl::Shader<WideLayers, WideUv> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideUv>& out) const {
    out.position = in.attrib[0];
    const softgl::vec2 uv(in.attrib[1].x, in.attrib[1].y);
    out.varyings.a = softgl::vec3(uv * 3.0f, uv.x * 4.0f);
    out.varyings.b = softgl::vec3(uv * 2.0f, uv.y * 1.5f);
  }
  void Fragment(const softgl::FragmentLanes<WideUv>& in, softgl::FragmentLanesOut& out) const {
    const softgl::vec4 a = in.TextureArray(0, in.varyings.a);
    const softgl::vec4 b = in.Texture3D(1, in.varyings.b);
    out.color[0] = softgl::vec4(a.x, b.y, a.z * 0.5f + b.z * 0.5f, 1.0f);
  }
};
struct ScalarLayers : softgl::Shader<ScalarLayers, ScalarUv> {
  void Vertex(const VertexIn& in, VertexOut<ScalarUv>& out) const {
    out.position = in.attrib[0];
    const glm::vec2 uv(in.attrib[1]);
    out.varyings.a = glm::vec3(uv * 3.0f, uv.x * 4.0f);
    out.varyings.b = glm::vec3(uv * 2.0f, uv.y * 1.5f);
  }
  bool Fragment(const FragmentIn<ScalarUv>& in, FragmentOut& out) const {
    const glm::vec4 a = in.TextureArray(0, &ScalarUv::a);
    const glm::vec4 b = in.Texture3D(1, &ScalarUv::b);
    out.color[0] = glm::vec4(a.x, b.y, a.z * 0.5f + b.z * 0.5f, 1.0f);
    return true;
  }
};
}  // namespace

TEST_CASE("the wide array and 3D calls give the one-lane calls' bytes", "[texture][layers][wide]") {
  auto render = [](const Program& program) {
    Context gl(48, 40);
    std::vector<std::uint8_t> noise(16 * 16 * 8 * 4);
    std::uint32_t x = 12345;
    for (auto& b : noise) b = std::uint8_t((x = x * 1664525u + 1013904223u) >> 24);
    const std::uint32_t arr = gl.GenTexture(), vol = gl.GenTexture();
    gl.ActiveTexture(TEXTURE0);
    gl.BindTexture(TEXTURE_2D_ARRAY, arr);
    gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 16, 16, 5, 0, RGBA, UNSIGNED_BYTE, noise.data());
    gl.GenerateMipmap(TEXTURE_2D_ARRAY);
    gl.TexParameteri(TEXTURE_2D_ARRAY, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
    gl.ActiveTexture(TEXTURE0 + 1);
    gl.BindTexture(TEXTURE_3D, vol);
    gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 16, 16, 8, 0, RGBA, UNSIGNED_BYTE, noise.data());
    gl.GenerateMipmap(TEXTURE_3D);
    gl.TexParameteri(TEXTURE_3D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
    return DrawPerspectiveQuad(gl, program);
  };
  WideLayers wide;
  ScalarLayers scalar;
  CheckSameImage(render(wide), render(scalar));
}

TEST_CASE("TexImage3D, TexSubImage3D and FramebufferTextureLayer reject bad input", "[texture][layers][errors]") {
  Context gl(4, 4);
  const std::uint32_t arr = gl.GenTexture(), vol = gl.GenTexture(), flat = gl.GenTexture();
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_2D_ARRAY, arr);
  gl.BindTexture(TEXTURE_3D, vol);
  gl.BindTexture(TEXTURE_2D, flat);
  gl.BindTexture(TEXTURE_3D, arr);
  CHECK(gl.GetError() == INVALID_OPERATION);  // first bound to the other target
  gl.TexImage3D(TEXTURE_2D, 0, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 1, 1, kMaxArrayTextureLayers + 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, kMax3DTextureSize + 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 1, 1, -1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 1, 1, 1, 1, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);  // border
  gl.TexImage3D(TEXTURE_3D, 0, DEPTH_COMPONENT32F, 1, 1, 1, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);
  // 2048^3 RGBA32F texels (128 GiB) and 16384 x 16384 x 2048 bytes: refused without allocating.
  gl.TexImage3D(TEXTURE_3D, 0, RGBA32F, kMax3DTextureSize, kMax3DTextureSize, kMax3DTextureSize, 0, RGBA, FLOAT,
                nullptr);
  CHECK(gl.GetError() == OUT_OF_MEMORY);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, R8, kMaxTextureSize, kMaxTextureSize, kMaxArrayTextureLayers, 0, RED,
                UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == OUT_OF_MEMORY);
  int v = -1;
  gl.GetTexLevelParameteriv(TEXTURE_3D, 0, TEXTURE_WIDTH, &v);
  CHECK(v == 0);  // nothing defined by the refused calls
  // TexSubImage3D: undefined level, then a box outside the level.
  const std::uint8_t px[4] = {1, 2, 3, 4};
  gl.TexSubImage3D(TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 2, 2, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.TexSubImage3D(TEXTURE_3D, 0, 0, 0, 2, 1, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexSubImage3D(TEXTURE_3D, 0, 0, 0, -1, 1, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexSubImage3D(TEXTURE_3D, 0, 1, 1, 1, 1, 1, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == NO_ERROR);
  // FramebufferTextureLayer.
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // framebuffer 0
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, flat, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // a 2D texture
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, 999, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, 0, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, 0, kMax3DTextureSize);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, detail::kMaxLevels, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, 0x1234, vol, 0, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, vol, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // a 3D texture through the 2D call
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, 0, 1);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, vol, 0, 2);  // the level has 2 slices
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, 0, 0, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT);
  // Deleting a bound array texture unbinds it.
  gl.DeleteTexture(arr);
  gl.GetIntegerv(TEXTURE_BINDING_2D_ARRAY, &v);
  CHECK(v == 0);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("CopyTexSubImage3D copies into one layer; GetTexImage returns every layer", "[texture][layers]") {
  Context gl(8, 8);
  gl.ClearColor(1.0f, 0.5f, 0.0f, 1.0f);  // orange, with the top-right 4 x 4 pixels blue
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Enable(SCISSOR_TEST);
  gl.Scissor(4, 4, 4, 4);
  gl.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Disable(SCISSOR_TEST);
  gl.PixelStore(PACK_ALIGNMENT, 1);
  auto word = [](const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
  };
  for (Enum target : {TEXTURE_2D_ARRAY, TEXTURE_3D}) {
    INFO(target);
    const std::uint32_t tex = gl.GenTexture();
    gl.BindTexture(target, tex);
    // 4 x 4 x 3 texels, layer k all of grey 10 (k + 1).
    std::vector<std::uint8_t> texels(4 * 4 * 3 * 4);
    for (std::size_t t = 0; t < texels.size(); ++t) texels[t] = std::uint8_t(10 * (t / 64 + 1));
    gl.TexImage3D(target, 0, RGBA8, 4, 4, 3, 0, RGBA, UNSIGNED_BYTE, texels.data());
    // Framebuffer (3, 3) .. (5, 5) into layer 1 at (1, 1): texel (1, 1) orange, (2, 2) and (3, 3) blue.
    gl.CopyTexSubImage3D(target, 0, 1, 1, 1, 3, 3, 3, 3);
    REQUIRE(gl.GetError() == NO_ERROR);
    std::vector<std::uint8_t> out(texels.size(), 0xCD);
    gl.GetTexImage(target, 0, RGBA, UNSIGNED_BYTE, out.data());
    REQUIRE(gl.GetError() == NO_ERROR);
    auto at = [&](int i, int j, int k) { return word(&out[((std::size_t(k) * 4 + std::size_t(j)) * 4 + std::size_t(i)) * 4]); };
    CHECK(at(1, 1, 1) == 0xFF8000FFu);
    CHECK(at(2, 2, 1) == 0x0000FFFFu);
    CHECK(at(3, 3, 1) == 0x0000FFFFu);
    CHECK(at(0, 0, 1) == 0x14141414u);  // outside the copy: layer 1's grey 20
    CHECK(at(3, 0, 1) == 0x14141414u);
    CHECK(at(1, 1, 0) == 0x0A0A0A0Au);  // the other layers untouched
    CHECK(at(1, 1, 2) == 0x1E1E1E1Eu);
    CHECK(at(3, 3, 2) == 0x1E1E1E1Eu);
    // Errors.
    gl.CopyTexSubImage3D(target, 0, 0, 0, 3, 0, 0, 1, 1);  // layer 3 of 3
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.CopyTexSubImage3D(target, 0, 0, 0, -1, 0, 0, 1, 1);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.CopyTexSubImage3D(target, 0, 2, 0, 0, 0, 0, 3, 1);  // past the 4 texels of a row
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.CopyTexSubImage3D(target, 1, 0, 0, 0, 0, 0, 1, 1);  // level 1 not defined
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.CopyTexSubImage3D(target, -1, 0, 0, 0, 0, 0, 1, 1);
    CHECK(gl.GetError() == INVALID_VALUE);
  }
  gl.CopyTexSubImage3D(TEXTURE_2D, 0, 0, 0, 0, 0, 0, 1, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  // A depth texture array takes the depth buffer.
  gl.ClearDepth(0.25);
  gl.Clear(DEPTH_BUFFER_BIT);
  const std::uint32_t depth = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D_ARRAY, depth);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, DEPTH_COMPONENT32F, 2, 2, 2, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  gl.CopyTexSubImage3D(TEXTURE_2D_ARRAY, 0, 0, 0, 1, 0, 0, 2, 2);
  float d[8] = {};
  gl.GetTexImage(TEXTURE_2D_ARRAY, 0, DEPTH_COMPONENT, FLOAT, d);
  CHECK(d[0] == 0.0f);  // layer 0 as allocated
  CHECK(d[4] == 0.25f);
  CHECK(d[7] == 0.25f);
  CHECK(gl.GetError() == NO_ERROR);
  // Without a texture bound.
  gl.BindTexture(TEXTURE_3D, 0);
  gl.CopyTexSubImage3D(TEXTURE_3D, 0, 0, 0, 0, 0, 0, 1, 1);
  CHECK(gl.GetError() == INVALID_OPERATION);
}

TEST_CASE("FramebufferTexture attaches every layer: clears clear them all, draws go to layer 0",
          "[texture][layers][framebuffer]") {
  for (Enum kind : {TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_CUBE_MAP}) {
    INFO(kind);
    const int layers = kind == TEXTURE_CUBE_MAP ? 6 : 3;
    Context gl(4, 4);
    const std::uint32_t color = gl.GenTexture(), depth = gl.GenTexture(), fbo = gl.GenFramebuffer();
    gl.BindTexture(kind, color);
    const std::vector<std::uint8_t> grey(4 * 4 * 4 * 3, 99);  // every texel grey 99 before
    if (kind == TEXTURE_CUBE_MAP) {
      for (int f = 0; f < 6; ++f) gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, grey.data());
    } else {
      gl.TexImage3D(kind, 0, RGBA8, 4, 4, 3, 0, RGBA, UNSIGNED_BYTE, grey.data());
    }
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0);
    int v = -1;
    gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_LAYERED, &v);
    CHECK(v == 1);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    if (kind == TEXTURE_2D_ARRAY) {  // with a layered depth array of as many layers
      gl.BindTexture(TEXTURE_2D_ARRAY, depth);
      gl.TexImage3D(TEXTURE_2D_ARRAY, 0, DEPTH_COMPONENT32F, 4, 4, 3, 0, DEPTH_COMPONENT, FLOAT, nullptr);
      gl.FramebufferTexture(FRAMEBUFFER, DEPTH_ATTACHMENT, depth, 0);
      REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
      gl.ClearDepth(0.25);
    }
    gl.ClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    testing::SolidShader solid;
    solid.color = {1, 0, 0, 1};
    gl.UseProgram(solid);
    testing::MakeVertexArray(gl, {{-1, -1, -1, 1}, {0, -1, -1, 1}, {-1, 0, -1, 1}, {0, 0, -1, 1}});
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);  // the bottom-left 2 x 2 pixels of layer 0 red
    REQUIRE(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    // Every layer green, layer 0's corner red.
    std::vector<std::uint8_t> out(std::size_t(4 * 4 * 4 * layers), 0xCD);
    if (kind == TEXTURE_CUBE_MAP) {
      for (int f = 0; f < 6; ++f)
        gl.GetTexImage(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, RGBA, UNSIGNED_BYTE, out.data() + f * 64);
    } else {
      gl.BindTexture(kind, color);
      gl.GetTexImage(kind, 0, RGBA, UNSIGNED_BYTE, out.data());
    }
    for (int l = 0; l < layers; ++l)
      for (int p = 0; p < 16; ++p) {
        const bool corner = l == 0 && p % 4 < 2 && p / 4 < 2;
        const std::uint8_t* px = &out[std::size_t(l * 16 + p) * 4];
        INFO("layer " << l << " pixel " << p);
        CHECK(int(px[0]) == (corner ? 255 : 0));
        CHECK(int(px[1]) == (corner ? 0 : 255));
      }
    if (kind == TEXTURE_2D_ARRAY) {
      std::vector<float> d(4 * 4 * 3, -1.0f);
      gl.BindTexture(TEXTURE_2D_ARRAY, depth);
      gl.GetTexImage(TEXTURE_2D_ARRAY, 0, DEPTH_COMPONENT, FLOAT, d.data());
      CHECK(d[0] == 0.25f);   // (the draw wrote no depth: DEPTH_TEST is off)
      CHECK(d[16] == 0.25f);  // layer 1
      CHECK(d[47] == 0.25f);  // layer 2
    }
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("layered framebuffers: completeness, FramebufferTexture3D, errors", "[texture][layers][framebuffer]") {
  Context gl(4, 4);
  const std::uint32_t array = gl.GenTexture(), cube = gl.GenTexture(), vol = gl.GenTexture(), flat = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D_ARRAY, array);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 4, 4, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindTexture(TEXTURE_3D, vol);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 4, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindTexture(TEXTURE_2D, flat);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindTexture(TEXTURE_CUBE_MAP, cube);
  for (int f = 0; f < 5; ++f) gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  // A layered attachment beside an unlayered one; layered ones of two targets.
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, array, 0);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, flat, 0);  // a 2D texture: not layered
  int v = -1;
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, FRAMEBUFFER_ATTACHMENT_LAYERED, &v);
  CHECK(v == 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, vol, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, 0, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  // A cube map with a face missing.
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, cube, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  gl.TexImage2D(TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  // FramebufferTexture3D: one slice, as FramebufferTextureLayer.
  gl.FramebufferTexture3D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_3D, vol, 0, 3);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &v);
  CHECK(v == 3);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_LAYERED, &v);
  CHECK(v == 0);
  CHECK(gl.GetError() == NO_ERROR);
  gl.FramebufferTexture3D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, vol, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.FramebufferTexture3D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_3D, array, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.FramebufferTexture3D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_3D, vol, 0, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture3D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_3D, vol, 12, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, 999, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, gl.GenTexture(), 0);  // never bound: no target
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, array, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTexture(FRAMEBUFFER, 0x1234, array, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, array, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
}

namespace {

struct LayerVaryings {
  vec4 color;
};

// Position from attribute 0, colour from attribute 1, gl_Layer from attribute 2's x.
struct LayerShader : Shader<LayerShader, LayerVaryings> {
  static constexpr bool kWritesLayer = true;
  void Vertex(const VertexLanes& in, VertexLanesOut<LayerVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.layer = Int(in.attrib[2].x);
  }
  void Fragment(const FragmentLanes<LayerVaryings>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};

}  // namespace

TEST_CASE("gl_Layer from the vertex stage routes each primitive to its layer", "[texture][layers][framebuffer]") {
  for (int threads : {1, 3}) {
    INFO(threads << " threads");
    Context gl(8, 8, Context::Options{threads});
    const ArrayTargets arrays(gl, 8, 4);
    const std::uint32_t color = arrays.color, depth = arrays.depth, fbo = arrays.fbo;
    gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0);
    gl.FramebufferTexture(FRAMEBUFFER, DEPTH_ATTACHMENT, depth, 0);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    gl.ClearColor(0, 0, 0, 1);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.Enable(DEPTH_TEST);
    LayerShader shader;
    gl.UseProgram(shader);
    // One draw of 5 full-screen triangles: layer 2 (red, far), layer 0 (green), layer 2 again (blue, near: over the
    // red), layer 9 (past the last: layer 3, yellow), layer 1 by a triangle whose provoking (last) vertex says 1
    // though its first says 3 (white).
    struct V {
      glm::vec4 pos, color, extra;
    };
    auto tri = [](float z, glm::vec4 c, float l0, float l2) {
      return std::vector<V>{{{-1, -1, z, 1}, c, {l0, 0, 0, 0}}, {{3, -1, z, 1}, c, {l0, 0, 0, 0}}, {{-1, 3, z, 1}, c, {l2, 0, 0, 0}}};
    };
    std::vector<V> v;
    for (const auto& t : {tri(0.5f, {1, 0, 0, 1}, 2, 2), tri(0.0f, {0, 1, 0, 1}, 0, 0), tri(-0.5f, {0, 0, 1, 1}, 2, 2),
                          tri(0.0f, {1, 1, 0, 1}, 9, 9), tri(0.0f, {1, 1, 1, 1}, 3, 1)})
      v.insert(v.end(), t.begin(), t.end());
    gl.BindVertexArray(gl.GenVertexArray());
    gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(v.size() * sizeof(V)), v.data());
    for (std::uint32_t a = 0; a < 3; ++a) {
      gl.VertexAttributePointer(a, 4, FLOAT, false, sizeof(V), a * sizeof(glm::vec4));
      gl.EnableVertexAttribArray(a);
    }
    gl.DrawArrays(TRIANGLES, 0, int(v.size()));
    REQUIRE(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    std::vector<std::uint8_t> out(8 * 8 * 4 * 4, 0xCD);
    gl.BindTexture(TEXTURE_2D_ARRAY, color);
    gl.GetTexImage(TEXTURE_2D_ARRAY, 0, RGBA, UNSIGNED_BYTE, out.data());
    const std::uint32_t want[4] = {0x00FF00FFu, 0xFFFFFFFFu, 0x0000FFFFu, 0xFFFF00FFu};
    for (int l = 0; l < 4; ++l) {
      const std::uint8_t* p = &out[std::size_t(l * 64 + 27) * 4];
      const std::uint32_t got = std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
      INFO("layer " << l);
      CHECK(got == want[l]);
    }
    // Without kWritesLayer (SolidShader), everything goes to layer 0.
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    testing::SolidShader solid;
    solid.color = {1, 0, 1, 1};
    gl.UseProgram(solid);
    gl.DrawArrays(TRIANGLES, 0, int(v.size()));
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    gl.GetTexImage(TEXTURE_2D_ARRAY, 0, RGBA, UNSIGNED_BYTE, out.data());
    for (int l = 0; l < 4; ++l) CHECK(int(out[std::size_t(l * 64 + 27) * 4 + 2]) == (l == 0 ? 255 : 0));
    CHECK(gl.GetError() == NO_ERROR);
  }
}

// ---- 1D textures and 1D arrays ----------------------------------------------------------------------------------

namespace {
struct WideS {
  softgl::Float s;
  softgl::vec2 sl;
};
struct ScalarS {
  float s;
  glm::vec2 sl;
};
// texture(sampler1D) on unit 0 and texture(sampler1DArray) on unit 1, wide and one lane at a time.
struct Wide1D : softgl::Shader<Wide1D, WideS> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideS>& out) const {
    out.position = in.attrib[0];
    out.varyings.s = in.attrib[1].x * 3.0f - 1.0f;
    out.varyings.sl = softgl::vec2(in.attrib[1].x * 2.0f, in.attrib[1].y * 3.0f);
  }
  void Fragment(const softgl::FragmentLanes<WideS>& in, softgl::FragmentLanesOut& out) const {
    const softgl::vec4 a = in.Texture1D(0, in.varyings.s);
    const softgl::vec4 b = in.Texture1DArray(1, in.varyings.sl);
    out.color[0] = softgl::vec4(a.x, b.y, a.z * 0.5f + b.z * 0.5f, 1.0f);
  }
};
struct Scalar1D : softgl::Shader<Scalar1D, ScalarS> {
  void Vertex(const VertexIn& in, VertexOut<ScalarS>& out) const {
    out.position = in.attrib[0];
    out.varyings.s = in.attrib[1].x * 3.0f - 1.0f;
    out.varyings.sl = glm::vec2(in.attrib[1].x * 2.0f, in.attrib[1].y * 3.0f);
  }
  bool Fragment(const FragmentIn<ScalarS>& in, FragmentOut& out) const {
    const glm::vec4 a = in.Texture1D(0, &ScalarS::s);
    const glm::vec4 b = in.Texture1DArray(1, &ScalarS::sl);
    out.color[0] = glm::vec4(a.x, b.y, a.z * 0.5f + b.z * 0.5f, 1.0f);
    return true;
  }
};
}  // namespace

TEST_CASE("1D textures sample as a 2D texture one texel high, whatever TEXTURE_WRAP_T says", "[texture][layers][1d]") {
  // 13 texels with their mipmaps, as TEXTURE_1D and as a 13 x 1 TEXTURE_2D clamped in t; the 1D texture's own
  // TEXTURE_WRAP_T is CLAMP_TO_BORDER with a NaN border, which must not reach a sample.
  auto texel = [](int i, int, int) { return glm::vec4(float(i), float(i * i) * 0.25f, 13.0f - float(i), 1.0f); };
  TextureObject one = MakeLayered(TEXTURE_1D, 13, 1, 1, texel), two = MakeLayered(TEXTURE_2D, 13, 1, 1, texel);
  detail::GenerateMipmaps(one);
  detail::GenerateMipmaps(two);
  one.params.wrap_t = CLAMP_TO_BORDER;
  one.params.border = glm::vec4(std::nanf(""));
  two.params.wrap_t = CLAMP_TO_EDGE;
  // NEAREST picks texel floor(13 s).
  {
    const TextureView v = detail::MakeView(one);
    Textures tx;
    tx.unit_1d[0] = &v;
    REQUIRE(v.complete);
    for (int i = 0; i < 13; ++i) CHECK(tx.Sample1D(0, (float(i) + 0.5f) / 13.0f, 0, 0) == texel(i, 0, 0));
    CHECK(tx.Size1D(0) == 13);
    CHECK(tx.Size1D(0, 1) == 6);
    CHECK(tx.Sample(0, {0.5f, 0.5f}, {}, {}) == glm::vec4(0, 0, 0, 1));  // the 2D unit is empty
  }
  const Enum filters[][2] = {{NEAREST, NEAREST}, {LINEAR, LINEAR}, {LINEAR_MIPMAP_LINEAR, LINEAR},
                             {NEAREST_MIPMAP_NEAREST, NEAREST}, {LINEAR_MIPMAP_NEAREST, LINEAR}};
  const Enum wraps[] = {REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER};
  int compared = 0;
  for (const auto& f : filters)
    for (const Enum w : wraps) {
      for (TextureObject* t : {&one, &two}) {
        t->params.min_filter = f[0];
        t->params.mag_filter = f[1];
        t->params.wrap_s = w;
        t->params.border = t == &one ? glm::vec4(std::nanf("")) : glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
      }
      one.params.border = two.params.border;  // (the border in s is the same colour for both)
      one.params.wrap_t = CLAMP_TO_BORDER;
      const TextureView v1 = detail::MakeView(one), v2 = detail::MakeView(two);
      Textures tx;
      tx.unit_1d[0] = &v1;
      tx.unit_2d[0] = &v2;
      Textures::Lanes lanes{};
      float lod[16];
      for (int l = 0; l < 16; ++l) {
        lanes.s[l] = -1.3f + 0.23f * float(l);
        lanes.t[l] = 7.0f;  // unread
        lanes.ds_dx[l] = 0.01f * float(l * l);
        lanes.ds_dy[l] = l % 3 == 0 ? 0.3f : 0.0f;
        lod[l] = -1.0f + 0.4f * float(l);
      }
      float wide[4][16], wide_lod[4][16];
      tx.Sample1DLanes(0, lanes, 0.25f, wide);
      tx.Sample1DLodLanes(0, lanes, lod, wide_lod);
      for (int l = 0; l < 16; ++l) {
        const float s = lanes.s[l];
        const glm::vec4 a = tx.Sample1D(0, s, lanes.ds_dx[l], lanes.ds_dy[l], 0.25f);
        const glm::vec4 b = tx.Sample(0, {s, 0.5f}, {lanes.ds_dx[l], 0.0f}, {lanes.ds_dy[l], 0.0f}, 0.25f);
        INFO("filter 0x" << std::hex << f[0] << ", wrap 0x" << w << std::dec << ", lane " << l);
        CHECK(a == b);
        CHECK(glm::vec4(wide[0][l], wide[1][l], wide[2][l], wide[3][l]) == a);
        CHECK(tx.Sample1DLod(0, s, lod[l]) == tx.SampleLod(0, {s, 0.5f}, lod[l]));
        CHECK(glm::vec4(wide_lod[0][l], wide_lod[1][l], wide_lod[2][l], wide_lod[3][l]) == tx.Sample1DLod(0, s, lod[l]));
        ++compared;
      }
    }
  CHECK(compared == 5 * 4 * 16);
  // TEXTURE_WRAP_T unused: CLAMP_TO_BORDER with an infinite or NaN border in t changes no LINEAR sample.
  for (const float border : {std::numeric_limits<float>::infinity(), std::nanf("")}) {
    one.params.min_filter = one.params.mag_filter = two.params.min_filter = two.params.mag_filter = LINEAR;
    one.params.wrap_s = two.params.wrap_s = REPEAT;
    one.params.wrap_t = CLAMP_TO_BORDER;
    one.params.border = glm::vec4(border);
    const TextureView v1 = detail::MakeView(one), v2 = detail::MakeView(two);
    Textures tx;
    tx.unit_1d[0] = &v1;
    tx.unit_2d[0] = &v2;
    for (int k = 0; k < 40; ++k) {
      const float s = -1.0f + 0.077f * float(k);
      CHECK(tx.Sample1D(0, s, 0.002f, 0.0f) == tx.Sample(0, {s, 0.5f}, {0.002f, 0.0f}, {}));
    }
  }
}

TEST_CASE("1D arrays: a row of texels a layer; the layer is floor(layer + 0.5), clamped", "[texture][layers][1d]") {
  // 4 texels x 3 layers: texel (i, layer k) = 100 k + i.
  TextureObject t = MakeLayered(TEXTURE_1D_ARRAY, 4, 1, 3, [](int i, int, int k) {
    return glm::vec4(float(100 * k + i), 0.0f, 0.0f, 1.0f);
  });
  const TextureView v = detail::MakeView(t);
  Textures tx;
  tx.unit_1d_array[0] = &v;
  REQUIRE(v.complete);
  auto at = [&](float s, float layer) { return tx.Sample1DArray(0, {s, layer}, 0, 0).r; };
  CHECK(at(0.125f, 0.0f) == 0.0f);
  CHECK(at(0.875f, 1.0f) == 103.0f);
  CHECK(at(0.375f, 1.49f) == 101.0f);
  CHECK(at(0.375f, 1.5f) == 201.0f);
  CHECK(at(0.625f, -7.0f) == 2.0f);
  CHECK(at(0.625f, 9.0f) == 202.0f);
  CHECK(tx.Sample1DArrayLod(0, {0.625f, 2.0f}, 0.0f).r == 202.0f);
  CHECK(tx.Size1DArray(0) == glm::ivec2(4, 3));
  Textures::Lanes lanes{};
  for (int l = 0; l < 16; ++l) {
    lanes.s[l] = float(l) / 16.0f;
    lanes.t[l] = float(l % 5) * 0.6f - 0.5f;
  }
  float wide[4][16];
  tx.Sample1DArrayLanes(0, lanes, 0.0f, wide);
  for (int l = 0; l < 16; ++l) CHECK(wide[0][l] == at(lanes.s[l], lanes.t[l]));
}

TEST_CASE("1D textures through the API: uploads, copies, mipmaps, rendering into them, queries", "[texture][layers][1d]") {
  Context gl(8, 4);
  const std::uint32_t one = gl.GenTexture(), arr = gl.GenTexture();
  gl.BindTexture(TEXTURE_1D, one);
  const std::uint8_t row[8 * 4] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16,
                                   17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32};
  gl.TexImage1D(TEXTURE_1D, 0, RGBA8, 8, 0, RGBA, UNSIGNED_BYTE, row);
  const std::uint8_t two[8] = {200, 201, 202, 203, 204, 205, 206, 207};
  gl.TexSubImage1D(TEXTURE_1D, 0, 3, 2, RGBA, UNSIGNED_BYTE, two);
  std::uint8_t back[8 * 4] = {};
  gl.GetTexImage(TEXTURE_1D, 0, RGBA, UNSIGNED_BYTE, back);
  for (int i = 0; i < 32; ++i) CHECK(int(back[i]) == (i >= 12 && i < 20 ? 200 + i - 12 : i + 1));
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_1D, 0, TEXTURE_HEIGHT, &v);
  CHECK(v == 1);
  gl.GenerateMipmap(TEXTURE_1D);
  gl.GetTexLevelParameteriv(TEXTURE_1D, 2, TEXTURE_WIDTH, &v);
  CHECK(v == 2);
  gl.GetIntegerv(TEXTURE_BINDING_1D, &v);
  CHECK(v == int(one));
  // A 1D array of 3 layers from a 2D image, rows as layers.
  gl.BindTexture(TEXTURE_1D_ARRAY, arr);
  std::uint8_t rows[4 * 3 * 4];
  for (int i = 0; i < 48; ++i) rows[i] = std::uint8_t(i * 5);
  gl.TexImage2D(TEXTURE_1D_ARRAY, 0, RGBA8, 4, 3, 0, RGBA, UNSIGNED_BYTE, rows);
  gl.GetTexLevelParameteriv(TEXTURE_1D_ARRAY, 0, TEXTURE_HEIGHT, &v);
  CHECK(v == 3);  // the layers
  std::uint8_t rows_back[48] = {};
  gl.GetTexImage(TEXTURE_1D_ARRAY, 0, RGBA, UNSIGNED_BYTE, rows_back);
  CHECK(std::equal(rows, rows + 48, rows_back));
  gl.GetIntegerv(TEXTURE_BINDING_1D_ARRAY, &v);
  CHECK(v == int(arr));
  CHECK(gl.GetError() == NO_ERROR);

  // Rendering into level 0 of the 1D texture (a framebuffer 8 x 1) and into layer 1 of the array.
  testing::SolidShader shader;
  auto full_quad = [&](glm::vec4 c) {
    testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
    shader.color = c;
    gl.UseProgram(shader);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  };
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture1D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_1D, one, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.Viewport(0, 0, 8, 1);
  full_quad({1.0f, 0.0f, 0.5f, 1.0f});
  gl.GetTexImage(TEXTURE_1D, 0, RGBA, UNSIGNED_BYTE, back);
  for (int i = 0; i < 8; ++i) CHECK((back[4 * i] == 255 && back[4 * i + 1] == 0 && back[4 * i + 2] == 128));
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, arr, 0, 1);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.Viewport(0, 0, 4, 1);
  full_quad({0.0f, 1.0f, 0.0f, 1.0f});
  gl.GetTexImage(TEXTURE_1D_ARRAY, 0, RGBA, UNSIGNED_BYTE, rows_back);
  for (int i = 0; i < 48; ++i) {
    const bool layer1 = i >= 16 && i < 32;
    CHECK(int(rows_back[i]) == (layer1 ? (i % 4 == 1 || i % 4 == 3 ? 255 : 0) : i * 5));
  }
  // Copies from the context's framebuffer: row 2 into the 1D texture, rows 1 and 2 into layers 0 and 1.
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.Viewport(0, 0, 8, 4);
  gl.ClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.CopyTexSubImage1D(TEXTURE_1D, 0, 2, 1, 2, 3);
  gl.GetTexImage(TEXTURE_1D, 0, RGBA, UNSIGNED_BYTE, back);
  for (int i = 0; i < 8; ++i) CHECK(int(back[4 * i]) == (i >= 2 && i < 5 ? 51 : 255));
  gl.CopyTexImage1D(TEXTURE_1D, 1, RGBA8, 0, 0, 4, 0);
  gl.GetTexLevelParameteriv(TEXTURE_1D, 1, TEXTURE_WIDTH, &v);
  CHECK(v == 4);
  gl.CopyTexSubImage2D(TEXTURE_1D_ARRAY, 0, 0, 0, 0, 1, 4, 2);
  gl.GetTexImage(TEXTURE_1D_ARRAY, 0, RGBA, UNSIGNED_BYTE, rows_back);
  for (int i = 0; i < 32; ++i) CHECK(int(rows_back[i]) == (i % 4 == 0 ? 51 : i % 4 == 1 ? 102 : i % 4 == 2 ? 153 : 204));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("1D texture calls reject bad input", "[texture][layers][1d][errors]") {
  Context gl(4, 4);
  const std::uint32_t one = gl.GenTexture(), flat = gl.GenTexture();
  const std::uint8_t px[16] = {};
  gl.TexImage1D(TEXTURE_1D, 0, RGBA8, 4, 0, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_1D, one);
  gl.TexImage1D(TEXTURE_2D, 0, RGBA8, 4, 0, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage1D(TEXTURE_1D, 0, RGBA8, -1, 0, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage1D(TEXTURE_1D, 0, RGBA8, 4, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage1D(TEXTURE_1D, 0, RGBA8, 4, 0, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == NO_ERROR);
  gl.TexSubImage1D(TEXTURE_1D, 0, 3, 2, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexSubImage1D(TEXTURE_1D, 1, 0, 1, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_OPERATION);  // level 1 not defined
  gl.CopyTexSubImage1D(TEXTURE_1D, 0, 2, 0, 0, 3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BindTexture(TEXTURE_2D, one);  // first bound as 1D
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage3D(TEXTURE_1D_ARRAY, 0, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, px);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindTexture(TEXTURE_2D, flat);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, px);
  gl.BindFramebuffer(FRAMEBUFFER, gl.GenFramebuffer());
  gl.FramebufferTexture1D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, one, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.FramebufferTexture1D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_1D, flat, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.FramebufferTexture1D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_1D, one, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, one, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // a 1D texture has no layers
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("the wide 1D calls give the one-lane calls' bytes", "[texture][layers][1d][wide]") {
  auto render = [](const Program& program) {
    Context gl(48, 40);
    std::vector<std::uint8_t> noise(64 * 5 * 4);
    std::uint32_t x = 777;
    for (auto& b : noise) b = std::uint8_t((x = x * 1664525u + 1013904223u) >> 24);
    const std::uint32_t one = gl.GenTexture(), arr = gl.GenTexture();
    gl.ActiveTexture(TEXTURE0);
    gl.BindTexture(TEXTURE_1D, one);
    gl.TexImage1D(TEXTURE_1D, 0, RGBA8, 64, 0, RGBA, UNSIGNED_BYTE, noise.data());
    gl.GenerateMipmap(TEXTURE_1D);
    gl.TexParameteri(TEXTURE_1D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
    gl.TexParameteri(TEXTURE_1D, TEXTURE_WRAP_S, MIRRORED_REPEAT);
    gl.ActiveTexture(TEXTURE0 + 1);
    gl.BindTexture(TEXTURE_1D_ARRAY, arr);
    gl.TexImage2D(TEXTURE_1D_ARRAY, 0, RGBA8, 64, 5, 0, RGBA, UNSIGNED_BYTE, noise.data());
    gl.GenerateMipmap(TEXTURE_1D_ARRAY);
    gl.TexParameteri(TEXTURE_1D_ARRAY, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_NEAREST);
    return DrawPerspectiveQuad(gl, program);
  };
  Wide1D wide;
  Scalar1D scalar;
  CheckSameImage(render(wide), render(scalar));
}

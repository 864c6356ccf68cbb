// Textures: wrap modes and filters against hand-computed texels, mipmap contents, LOD selection from known
// derivatives, completeness, depth comparison, cube faces; framebuffer objects; uploads and errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include <jpeglib.h>

#include "helpers.h"
#include "framebuffer.h"
#include "image_io.h"
#include "pixel_transfer.h"
#include "texture.h"
#include "simd.h"
#include "wide.h"

using namespace softgl;
using detail::TextureObject;
using detail::TextureView;

namespace {

// A texture made directly: level 0 of w x h with texel (i, j) = f(i, j), format RGBA32F unless given.
template <class F>
TextureObject MakeTexture(int w, int h, F f, Enum format = RGBA32F) {
  TextureObject t;
  t.target = TEXTURE_2D;
  auto& l = t.levels[0][0];
  l.Allocate(format, w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) detail::StoreTexel(l, i, j, f(i, j));
  t.params.min_filter = NEAREST;
  t.params.mag_filter = NEAREST;
  return t;
}

// Reads texels back through textureLod(unit 0, attrib 1 .xy, attrib 1 .z) in the vertex stage; draws nothing.
struct LodProbe : softgl::Shader<LodProbe, testing::NoVaryings> {
  mutable std::vector<glm::vec4> got;
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
    out.position = glm::vec4(2, 2, 2, 1);  // outside the view volume
    got.push_back(in.textures->SampleLod(0, glm::vec2(in.attrib[1]), in.attrib[1].z));
  }
  bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut&) const { return false; }
};

// Samples texture `t` at (s, t) with derivatives giving lambda = log2(scale) on a square texture of size n.
struct Sampler {
  TextureView view;
  Textures textures;
  explicit Sampler(const TextureObject& t) {
    view = detail::MakeView(t);
    textures.unit_2d[0] = &view;
  }
  glm::vec4 At(float s, float t, float texels_per_pixel = 1.0f) const {
    const int w = view.texture->levels[0][view.base].width;
    return textures.Sample(0, {s, t}, {texels_per_pixel / float(w), 0.0f}, {0.0f, texels_per_pixel / float(w)});
  }
};


// The pixel a 4 x 4 context whose own colour buffer is `format` (Options::color_format) reads back after a clear to
// `clear`, with FRAMEBUFFER_SRGB enabled when `srgb`; the context's first error goes to `error`.
struct Cleared {
  int rgba[4] = {0, 0, 0, 0};
  Enum error = NO_ERROR;
};
Cleared ClearContext(Enum format, const glm::vec4& clear, bool srgb = false) {
  Context::Options options;
  options.color_format = format;
  Context gl(4, 4, options);
  Cleared out;
  out.error = gl.GetError();
  if (srgb) gl.Enable(FRAMEBUFFER_SRGB);
  gl.ClearColor(clear.r, clear.g, clear.b, clear.a);
  gl.Clear(COLOR_BUFFER_BIT);
  std::uint8_t px[4];
  gl.ReadPixel(3, 3, px);
  for (int k = 0; k < 4; ++k) out.rgba[k] = px[k];
  return out;
}
}  // namespace

TEST_CASE("wrap modes pick OpenGL's texels", "[texture]") {
  // Texel i of a 4 x 1 texture holds i; sample at the centre of texel index k (s = (k + 0.5) / 4).
  TextureObject t = MakeTexture(4, 1, [](int i, int) { return glm::vec4(float(i), 0, 0, 1); });
  struct Row {
    Enum wrap;
    int k;
    float expect;  // -1: border
  };
  const Row rows[] = {
      {REPEAT, 0, 0},          {REPEAT, 5, 1},          {REPEAT, -1, 3},          {REPEAT, -6, 2},
      {MIRRORED_REPEAT, 4, 3}, {MIRRORED_REPEAT, 5, 2}, {MIRRORED_REPEAT, -1, 0}, {MIRRORED_REPEAT, -5, 3},
      {MIRRORED_REPEAT, 8, 0}, {CLAMP_TO_EDGE, -3, 0},  {CLAMP_TO_EDGE, 9, 3},    {CLAMP_TO_BORDER, -1, -1},
      {CLAMP_TO_BORDER, 4, -1}, {CLAMP_TO_BORDER, 2, 2},
  };
  for (const Row& r : rows) {
    INFO("wrap 0x" << std::hex << r.wrap << std::dec << " texel " << r.k);
    t.params.wrap_s = t.params.wrap_t = r.wrap;
    t.params.border = glm::vec4(-1, -1, -1, -1);
    const Sampler s(t);
    CHECK(s.At((float(r.k) + 0.5f) / 4.0f, 0.5f).r == r.expect);
  }
}

TEST_CASE("LINEAR weights texels by distance to their centres", "[texture]") {
  // 2 x 2 texture: 0, 1 / 2, 3. At texel-space (1.0, 1.0) all four weigh 1/4.
  TextureObject t = MakeTexture(2, 2, [](int i, int j) { return glm::vec4(float(i + 2 * j), 0, 0, 1); });
  t.params.mag_filter = t.params.min_filter = LINEAR;
  t.params.wrap_s = t.params.wrap_t = CLAMP_TO_EDGE;
  const Sampler s(t);
  CHECK(s.At(0.5f, 0.5f).r == Approx(1.5f));
  // At texel-space (0.75, 0.5): u - 0.5 = 0.25 -> 0.75 of texel 0 and 0.25 of texel 1, row 0 only.
  CHECK(s.At(0.375f, 0.25f).r == Approx(0.25f));
  // At the centre of texel 1 exactly: no blending.
  CHECK(s.At(0.75f, 0.25f).r == Approx(1.0f));
  // Clamped at the edge: left of texel 0's centre stays texel 0.
  CHECK(s.At(0.0f, 0.25f).r == Approx(0.0f));
  t.params.wrap_s = REPEAT;  // repeat blends texel 0 with texel 1 across the edge
  const Sampler r(t);
  CHECK(r.At(0.0f, 0.25f).r == Approx(0.5f));
}

TEST_CASE("GenerateMipmaps gives each texel the bilinear sample of the level above, every format, size and layer",
          "[texture][formats]") {
  // The reference: each texel of level l the bilinear sample of level l - 1 at its centre, clamped to the edge,
  // through Sampled and StoreTexel one texel at a time (weights (1 - a)(1 - b), a(1 - b), (1 - a)b, ab, summed
  // from 0 in that order).
  const Enum formats[] = {RGBA8,  RGB8,    RG8,   R8,      SRGB8_ALPHA8, SRGB8,   RGBA32F, RG32F,   R32F,    RGBA16F,
                          RG16F,  R16F,    R11F_G11F_B10F, RGB565,       RGBA4,   RGB5_A1, RGB10_A2, RGBA16, R16};
  const int sizes[][3] = {{16, 16, 1}, {13, 7, 1}, {1, 9, 1}, {10, 1, 1}, {6, 5, 3}, {33, 2, 2}};
  std::uint32_t seed = 9;
  auto next = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1u << 24); };
  int compared = 0;
  for (const Enum format : formats)
    for (const auto& size : sizes) {
      TextureObject t;
      t.target = size[2] > 1 ? TEXTURE_2D_ARRAY : TEXTURE_2D;
      t.levels[0][0].Allocate(format, size[0], size[1], 1, size[2]);
      for (int j = 0; j < size[1] * size[2]; ++j)
        for (int i = 0; i < size[0]; ++i)
          detail::StoreTexel(t.levels[0][0], i, j, glm::vec4(next() * 1.4f - 0.2f, next(), next() * 3.0f, next()), true);
      TextureObject want = t;
      detail::GenerateMipmaps(t);
      for (int l = 1; l < detail::kMaxLevels; ++l) {
        const detail::TextureLevel& above = want.levels[0][l - 1];
        if (above.width == 1 && above.height == 1) break;
        detail::TextureLevel& level = want.levels[0][l];
        level.Allocate(format, std::max(1, above.width / 2), std::max(1, above.height / 2), 1, above.depth);
        for (int k = 0; k < level.depth; ++k)
          for (int j = 0; j < level.height; ++j)
            for (int i = 0; i < level.width; ++i) {
              const float u = (float(i) + 0.5f) * float(above.width) / float(level.width) - 0.5f;
              const float v = (float(j) + 0.5f) * float(above.height) / float(level.height) - 0.5f;
              const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
              const float a = u - float(i0), b = v - float(j0);
              glm::vec4 sum(0.0f);
              for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di)
                  sum += (di ? a : 1.0f - a) * (dj ? b : 1.0f - b) * 1.0f *
                         (above.Sampled(std::clamp(i0 + di, 0, above.width - 1),
                                        k * above.height + std::clamp(j0 + dj, 0, above.height - 1)) /
                          detail::StorageScale(above.layout));
              detail::StoreTexel(level, i, k * level.height + j, sum, true);
            }
        const detail::TextureLevel& got = t.levels[0][l];
        INFO("format " << std::hex << format << std::dec << ", " << size[0] << " x " << size[1] << " x " << size[2]
                       << ", level " << l);
        REQUIRE((got.width == level.width && got.height == level.height && got.depth == level.depth));
        const bool same = got.data == level.data;
        CHECK(same);
        ++compared;
      }
    }
  CHECK(compared > 19 * 6 * 2);
}

TEST_CASE("UploadPixels by rows gives each pixel's UnpackColor stored by StoreTexel, in every colour format",
          "[texture][formats]") {
  const Enum formats[] = {RGBA8,  RGB8,    RG8,   R8,      SRGB8_ALPHA8, SRGB8,   RGBA32F, RG32F,   R32F,    RGBA16F,
                          RG16F,  R16F,    R11F_G11F_B10F, RGB565,       RGBA4,   RGB5_A1, RGB10_A2, RGBA16, R16};
  // Client data: RGBA floats (some NaN, infinite, negative and above 1) and bytes as RGBA, RGB, RG and RED; a
  // rectangle written into the middle of a level, rows padded as UNPACK_ALIGNMENT 4 and UNPACK_ROW_LENGTH say.
  constexpr int kW = 9, kH = 4, kRowLength = 11;
  std::vector<std::uint8_t> client(std::size_t(kRowLength) * kH * 16);
  std::uint32_t seed = 21;
  for (std::size_t i = 0; i + 4 <= client.size(); i += 4) {
    seed = seed * 1664525u + 1013904223u;
    const float v = i % 36 == 8   ? std::numeric_limits<float>::quiet_NaN()
                    : i % 52 == 4 ? -std::numeric_limits<float>::infinity()
                                  : float(int(seed >> 20) % 3001 - 1000) / 1000.0f;
    std::memcpy(&client[i], &v, 4);
  }
  const std::pair<Enum, Enum> pairs[] = {{RGBA, FLOAT}, {RGBA, UNSIGNED_BYTE}, {RGB, UNSIGNED_BYTE},
                                         {RG, UNSIGNED_BYTE}, {RED, UNSIGNED_BYTE}};
  int compared = 0;
  for (const Enum format : formats)
    for (const auto& [client_format, type] : pairs) {
      detail::ClientLayout layout;
      layout.row_length = kRowLength;
      detail::TextureLevel got, want;
      got.Allocate(format, kW + 3, kH + 2);
      for (std::uint8_t& b : got.data) b = std::uint8_t(b + 0x3C);
      want = got;
      detail::UploadPixels(got, 2, 1, kW, kH, client_format, type, layout, client.data());
      const std::size_t pixel = detail::TransferPixelBytes(client_format, type);
      const std::size_t row = (std::size_t(kRowLength) * pixel + 3) / 4 * 4;
      for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
          glm::vec4 in = detail::UnpackColor(client_format, type, client.data() + std::size_t(j) * row + std::size_t(i) * pixel);
          for (int c = 0; c < 4; ++c)
            if (std::isnan(in[c])) in[c] = 0.0f;
          if (type == UNSIGNED_BYTE && IsUnorm8(want.layout)) {  // bytes go in as they are
            std::uint8_t* dst = want.At(2 + i, 1 + j);
            const std::uint8_t* src = client.data() + std::size_t(j) * row + std::size_t(i) * pixel;
            for (int c = 0; c < want.bytes; ++c) dst[c] = c < int(pixel) ? src[c] : (c == 3 ? 255 : 0);
            if (format == RGB8 || format == SRGB8) dst[3] = 255;
          } else {
            detail::StoreTexel(want, 2 + i, 1 + j, in);
          }
        }
      INFO("format " << std::hex << format << ", client " << client_format << ", type " << type);
      const bool same = got.data == want.data;
      CHECK(same);
      ++compared;
    }
  CHECK(compared == 19 * 5);
}

TEST_CASE("GenerateMipmap averages 2x2 blocks; odd sizes sample bilinearly", "[texture]") {
  Context gl(1, 1);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  std::vector<float> px(4 * 4);
  for (int i = 0; i < 16; ++i) px[i] = float(i);
  gl.TexImage2D(TEXTURE_2D, 0, R32F, 4, 4, 0, RED, FLOAT, px.data());
  gl.GenerateMipmap(TEXTURE_2D);
  CHECK(gl.GetError() == NO_ERROR);
  // Level 1 texel (0, 0) = mean of 0, 1, 4, 5; (1, 1) = mean of 10, 11, 14, 15; level 2 = mean of all.
  // Read back through textureLod in the vertex stage.
  struct Lod : softgl::Shader<Lod, testing::NoVaryings> {
    mutable std::vector<glm::vec4> got;
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      out.position = in.attrib[0];
      got.push_back(in.textures->SampleLod(0, glm::vec2(in.attrib[1]), in.attrib[1].z));
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
      out.color[0] = glm::vec4(1);
      return true;
    }
  } shader;
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST_MIPMAP_NEAREST);
  testing::MakeVertexArray(gl, {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}},
                           {{0.25f, 0.25f, 1, 0}, {0.75f, 0.75f, 1, 0}, {0.5f, 0.5f, 2, 0}});
  gl.UseProgram(shader);
  gl.DrawArrays(POINTS, 0, 3);
  REQUIRE(shader.got.size() == 3);
  CHECK(shader.got[0].r == Approx(2.5f));
  CHECK(shader.got[1].r == Approx(12.5f));
  CHECK(shader.got[2].r == Approx(7.5f));

  // 3 x 3 -> 1 x 1: the bilinear sample at the centre of the 3 x 3 level is its middle texel.
  std::vector<float> odd = {0, 0, 0, 0, 9, 0, 0, 0, 0};
  gl.TexImage2D(TEXTURE_2D, 0, R32F, 3, 3, 0, RED, FLOAT, odd.data());
  gl.GenerateMipmap(TEXTURE_2D);
  shader.got.clear();
  testing::MakeVertexArray(gl, {{0, 0, 0, 1}}, {{0.5f, 0.5f, 5, 0}});
  gl.DrawArrays(POINTS, 0, 1);
  REQUIRE(shader.got.size() == 1);
  CHECK(shader.got[0].r == Approx(9.0f));
}

TEST_CASE("the level of detail comes from the derivatives, and selects levels as OpenGL says", "[texture]") {
  // A 16 x 16 texture whose level k is filled with the value k.
  TextureObject t;
  t.target = TEXTURE_2D;
  for (int k = 0; k < 5; ++k) {
    auto& l = t.levels[0][k];
    l.Allocate(RGBA32F, 16 >> k, 16 >> k);
    for (int j = 0; j < l.height; ++j)
      for (int i = 0; i < l.width; ++i) detail::StoreTexel(l, i, j, glm::vec4(float(k)));
  }
  struct Row {
    Enum min_filter;
    float texels_per_pixel;  // rho: lambda = log2(rho)
    float expect;
  };
  const Row rows[] = {
      {NEAREST_MIPMAP_NEAREST, 1.0f, 0},   {NEAREST_MIPMAP_NEAREST, 1.4f, 0},  // lambda 0.49 -> level 0
      {NEAREST_MIPMAP_NEAREST, 1.5f, 1},   {NEAREST_MIPMAP_NEAREST, 4.0f, 2},  // lambda 2 -> ceil(2.5) - 1 = 2
      {NEAREST_MIPMAP_NEAREST, 5.0f, 2},   {NEAREST_MIPMAP_NEAREST, 6.0f, 3},  // 2.32 -> 2; 2.58 -> 3
      {LINEAR_MIPMAP_LINEAR, 2.0f, 1},     {LINEAR_MIPMAP_LINEAR, 2.8284271f, 1.5f},
      {NEAREST_MIPMAP_LINEAR, 8.0f, 3},    {LINEAR_MIPMAP_LINEAR, 1000.0f, 4},  // clamped to the last level
      {LINEAR, 1000.0f, 0},                {LINEAR_MIPMAP_LINEAR, 0.25f, 0},     // magnification
  };
  for (const Row& r : rows) {
    INFO("min filter 0x" << std::hex << r.min_filter << std::dec << " rho " << r.texels_per_pixel);
    t.params.min_filter = r.min_filter;
    t.params.mag_filter = LINEAR;
    const Sampler s(t);
    CHECK(s.At(0.3f, 0.6f, r.texels_per_pixel).r == Approx(r.expect));
  }
  // Bias, min/max LOD and base/max level.
  t.params.min_filter = NEAREST_MIPMAP_NEAREST;
  t.params.lod_bias = 1.0f;
  CHECK(Sampler(t).At(0.3f, 0.6f, 2.0f).r == Approx(2.0f));
  t.params.lod_bias = 0.0f;
  t.params.max_lod = 1.0f;
  CHECK(Sampler(t).At(0.3f, 0.6f, 16.0f).r == Approx(1.0f));
  t.params.max_lod = 1000.0f;
  t.params.base_level = 1;
  t.params.max_level = 2;
  CHECK(Sampler(t).At(0.3f, 0.6f, 1.0f).r == Approx(1.0f));
  CHECK(Sampler(t).At(0.3f, 0.6f, 64.0f).r == Approx(2.0f));
}

TEST_CASE("an incomplete texture samples as (0, 0, 0, 1)", "[texture]") {
  TextureObject t = MakeTexture(4, 4, [](int, int) { return glm::vec4(1, 1, 1, 1); });
  t.params.min_filter = LINEAR_MIPMAP_LINEAR;  // needs levels 1 and 2, which are missing
  CHECK(Sampler(t).At(0.5f, 0.5f) == glm::vec4(0, 0, 0, 1));
  t.params.min_filter = LINEAR;
  CHECK(Sampler(t).At(0.5f, 0.5f) == glm::vec4(1, 1, 1, 1));
  t.params.base_level = 2;
  t.params.max_level = 1;  // base > max
  CHECK(Sampler(t).At(0.5f, 0.5f) == glm::vec4(0, 0, 0, 1));
  Textures none;
  CHECK(none.Sample(0, {0.5f, 0.5f}, {}, {}) == glm::vec4(0, 0, 0, 1));
  CHECK(none.Sample(99, {0.5f, 0.5f}, {}, {}) == glm::vec4(0, 0, 0, 1));
}

TEST_CASE("depth comparison filters the results of the comparisons (PCF)", "[texture]") {
  // 2 x 1 depth texture: 0.2 | 0.6.
  TextureObject t = MakeTexture(2, 1, [](int i, int) { return glm::vec4(i ? 0.6f : 0.2f, 0, 0, 1); },
                                DEPTH_COMPONENT);
  t.params.compare_mode = COMPARE_REF_TO_TEXTURE;
  t.params.compare_func = LEQUAL;
  t.params.wrap_s = t.params.wrap_t = CLAMP_TO_EDGE;
  TextureView view = detail::MakeView(t);
  Textures tx;
  tx.unit_2d[0] = &view;
  CHECK(tx.SampleShadow(0, {0.25f, 0.5f}, 0.1f, {}, {}) == 1.0f);  // 0.1 <= 0.2
  CHECK(tx.SampleShadow(0, {0.25f, 0.5f}, 0.4f, {}, {}) == 0.0f);
  t.params.mag_filter = LINEAR;
  view = detail::MakeView(t);
  // Half way between the texels: one comparison passes, one fails.
  CHECK(tx.SampleShadow(0, {0.5f, 0.5f}, 0.4f, {}, {}) == Approx(0.5f));
  t.params.compare_mode = NONE;
  view = detail::MakeView(t);
  CHECK(tx.SampleShadow(0, {0.5f, 0.5f}, 0.4f, {}, {}) == 0.0f);
}

TEST_CASE("the border colour is a texel of the texture's format: channels it lacks read 0, alpha 1", "[texture]") {
  // (OpenGL 4.6, table 8.11; Mesa gives these too.) Sampled outside a 2 x 2 texture under CLAMP_TO_BORDER, on the
  // one-lane path and the vector one.
  const struct { Enum format; glm::vec4 want; } cases[] = {
      {R8, {0.4f, 0, 0, 1}},       {RG8, {0.4f, 0.6f, 0, 1}},   {RGB8, {0.4f, 0.6f, 0.2f, 1}},
      {R32F, {0.4f, 0, 0, 1}},     {RGB565, {0.4f, 0.6f, 0.2f, 1}}, {R11F_G11F_B10F, {0.4f, 0.6f, 0.2f, 1}},
      {RGBA8, {0.4f, 0.6f, 0.2f, 0.8f}}, {RG16F, {0.4f, 0.6f, 0, 1}}};
  for (const auto& c : cases) {
    CAPTURE(c.format);
    TextureObject t;
    t.target = TEXTURE_2D;
    t.levels[0][0].Allocate(c.format, 2, 2);
    t.params.min_filter = t.params.mag_filter = NEAREST;
    t.params.wrap_s = t.params.wrap_t = CLAMP_TO_BORDER;
    t.params.border = glm::vec4(0.4f, 0.6f, 0.2f, 0.8f);
    TextureView view = detail::MakeView(t);
    Textures tx;
    tx.unit_2d[0] = &view;
    const glm::vec4 one = tx.Sample(0, {-0.5f, -0.5f}, {}, {});
    Textures::Lanes lanes{};
    for (int l = 0; l < 16; ++l) lanes.s[l] = lanes.t[l] = -0.5f;
    float out[4][16];
    tx.SampleLanes(0, lanes, 0.0f, out);
    for (int ch = 0; ch < 4; ++ch) {
      CHECK(one[ch] == Approx(c.want[ch]).margin(1e-6));
      CHECK(out[ch][7] == Approx(c.want[ch]).margin(1e-6));
    }
  }
}

TEST_CASE("cube maps choose the face of the major axis", "[texture]") {
  TextureObject t;
  t.target = TEXTURE_CUBE_MAP;
  for (int f = 0; f < 6; ++f) {
    auto& l = t.levels[f][0];
    l.Allocate(RGBA32F, 2, 2);
    // Face f: texel (i, j) = f * 10 + i + 2 j.
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) detail::StoreTexel(l, i, j, glm::vec4(float(f * 10 + i + 2 * j), 0.0f, 0.0f, 1.0f));
  }
  t.params.min_filter = t.params.mag_filter = NEAREST;
  TextureView view = detail::MakeView(t);
  REQUIRE(view.complete);
  Textures tx;
  tx.unit_cube[0] = &view;
  auto at = [&](glm::vec3 d) { return tx.SampleCube(0, d, {}, {}).r; };
  CHECK(at({1, 0.1f, 0.1f}) == Approx(0));    // +x: sc = -z < 0 -> i 0; tc = -y < 0 -> j 0
  CHECK(at({1, -0.5f, -0.5f}) == Approx(3));  // +x: sc = 0.5 -> i 1; tc = 0.5 -> j 1
  CHECK(at({-1, 0.5f, 0.5f}) == Approx(11));  // -x: sc = z -> i 1; tc = -y -> j 0
  CHECK(at({0.5f, 1, 0.5f}) == Approx(23));   // +y: sc = x, tc = z
  CHECK(at({0.5f, -1, 0.5f}) == Approx(31));  // -y: sc = x, tc = -z
  CHECK(at({0.5f, -0.5f, 1}) == Approx(43));  // +z: sc = x, tc = -y
  CHECK(at({0.5f, -0.5f, -1}) == Approx(52)); // -z: sc = -x, tc = -y
}

TEST_CASE("uploads honour UNPACK_ALIGNMENT and convert formats", "[texture]") {
  Context gl(1, 1);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  // 3 x 2 RGB bytes: rows of 9 bytes, padded to 12 with the default alignment of 4.
  const std::uint8_t rgb[24] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 7, 7, 7,  // row 0 + padding
                                51, 51, 51, 102, 102, 102, 204, 204, 204, 7, 7, 7};
  gl.TexImage2D(TEXTURE_2D, 0, RGB8, 3, 2, 0, RGB, UNSIGNED_BYTE, rgb);
  CHECK(gl.GetError() == NO_ERROR);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST);
  LodProbe shader;
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{0, 0, 0, 1}, {0, 0, 0, 1}}, {{0.5f / 3, 0.25f, 0, 0}, {2.5f / 3, 0.75f, 0, 0}});
  gl.DrawArrays(POINTS, 0, 2);
  REQUIRE(shader.got.size() == 2);
  CHECK(shader.got[0] == glm::vec4(1, 0, 0, 1));  // RGB8 reads alpha 1
  CHECK(shader.got[1].r == Approx(0.8f));
  // With alignment 1 the same bytes are read without padding: row 1 starts at byte 9.
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(TEXTURE_2D, 0, RGB8, 3, 2, 0, RGB, UNSIGNED_BYTE, rgb);
  shader.got.clear();
  gl.DrawArrays(POINTS, 0, 2);
  CHECK(shader.got[1].r == Approx(102.0f / 255.0f));  // texel (2, 1) = bytes 15..17
  // Floats into a fixed-point format are clamped and rounded to 8 bits.
  const float f[4] = {1.5f, -1.0f, 0.5f, 0.25f};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, FLOAT, f);
  shader.got.clear();
  gl.DrawArrays(POINTS, 0, 1);
  CHECK(shader.got[0].r == 1.0f);
  CHECK(shader.got[0].g == 0.0f);
  CHECK(shader.got[0].b == Approx(128.0f / 255.0f));
  CHECK(shader.got[0].a == Approx(64.0f / 255.0f));
}

TEST_CASE("texture calls reject bad input with OpenGL's errors", "[texture][errors]") {
  Context gl(1, 1);
  const std::uint32_t tex = gl.GenTexture();
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_2D, tex);
  gl.BindTexture(TEXTURE_CUBE_MAP, tex);
  CHECK(gl.GetError() == INVALID_OPERATION);  // already a 2D texture
  gl.BindTexture(0x1234, tex);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindTexture(TEXTURE_2D, 999);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, -1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, kMaxTextureSize + 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 1, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2D(TEXTURE_2D, -1, RGBA8, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2D(TEXTURE_2D, 0, 0x1234, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, 0x1234, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, DOUBLE, nullptr);  // (an attribute type, not a pixel type)
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexSubImage2D(TEXTURE_2D, 0, 0, 0, 1, 1, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_OPERATION);  // level 0 not defined yet
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.TexSubImage2D(TEXTURE_2D, 0, 1, 1, 2, 1, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, REPEAT);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_WRAP_S, LINEAR);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_BASE_LEVEL, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexParameteri(TEXTURE_2D, 0x1234, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ActiveTexture(TEXTURE0 + kMaxTextureUnits);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PixelStore(UNPACK_ALIGNMENT, 3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GenerateMipmap(TEXTURE_CUBE_MAP);
  CHECK(gl.GetError() == INVALID_OPERATION);  // no cube map bound
  const std::uint32_t cube = gl.GenTexture();
  gl.BindTexture(TEXTURE_CUBE_MAP, cube);
  gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X, 0, RGBA8, 2, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);  // faces are square
}

TEST_CASE("image files: formats load, missing and corrupt files give a clear error", "[texture][files]") {
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "files";
  std::filesystem::create_directories(dir);
  // A 2 x 2 PNG written by softgl itself: top row red, bottom row blue.
  Image img;
  img.width = img.height = 2;
  img.rgba = {255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
  REQUIRE(WritePng((dir / "two.png").string(), img));
  Context gl(1, 1);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  std::string error;
  REQUIRE(gl.TexImage2DFromFile(TEXTURE_2D, (dir / "two.png").string(), true, &error));
  LodProbe shader;
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{0, 0, 0, 1}, {0, 0, 0, 1}}, {{0.25f, 0.25f, 0, 0}, {0.25f, 0.75f, 0, 0}});
  gl.DrawArrays(POINTS, 0, 2);
  REQUIRE(shader.got.size() == 2);
  CHECK(shader.got[0] == glm::vec4(0, 0, 1, 1));  // flipped: the file's bottom row (blue) is at t = 0
  CHECK(shader.got[1] == glm::vec4(1, 0, 0, 1));

  CHECK_FALSE(gl.TexImage2DFromFile(TEXTURE_2D, (dir / "missing.png").string(), true, &error));
  CHECK(error.find("missing.png") != std::string::npos);
  {
    std::ofstream corrupt(dir / "corrupt.png", std::ios::binary);
    corrupt << "\x89PNG\r\n\x1a\n this is not a png";
  }
  CHECK_FALSE(gl.TexImage2DFromFile(TEXTURE_2D, (dir / "corrupt.png").string(), true, &error));
  {
    std::ofstream truncated(dir / "truncated.png", std::ios::binary);
    std::ifstream good(dir / "two.png", std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(good)), {});
    truncated.write(bytes.data(), std::streamsize(bytes.size() / 2));
  }
  CHECK_FALSE(gl.TexImage2DFromFile(TEXTURE_2D, (dir / "truncated.png").string(), true, &error));
  CHECK(gl.GetError() == NO_ERROR);  // a bad file is not a GL error
}

// ---- Framebuffer objects --------------------------------------------------------------------------------------

TEST_CASE("framebuffer completeness rules", "[framebuffer]") {
  Context gl(4, 4);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);  // the context's own
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT);
  const std::uint32_t color = gl.GenTexture(), depth = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, color);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, color, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);  // level 0 undefined
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 8, 8, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.BindTexture(TEXTURE_2D, depth);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 8, 8, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.FramebufferTexture2D(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, depth, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);  // colour as depth
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT, 6, 6, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);  // sizes may differ (OpenGL 3.0+)
  const Enum bufs[2] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1};
  gl.DrawBuffers(2, bufs);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER);
  gl.Clear(COLOR_BUFFER_BIT);
  CHECK(gl.GetError() == INVALID_FRAMEBUFFER_OPERATION);
  gl.DrawBuffers(1, bufs);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0 + kMaxColorOutputs, TEXTURE_2D, color, 0);
  CHECK(gl.GetError() == INVALID_ENUM);  // beyond MAX_COLOR_ATTACHMENTS (8)
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_CUBE_MAP_POSITIVE_X, color, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // not a cube map
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, 12345, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CheckFramebufferStatus(0x1234);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, color, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // the context's own framebuffer has no attachments
  // Deleting an attached texture detaches it from the bound framebuffer object.
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.DeleteTexture(color);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER);
}

TEST_CASE("render to texture, then sample it in a second pass", "[framebuffer]") {
  Context gl(8, 8);
  // Pass 1: a 4 x 4 RGBA8 texture, left half red and right half green, drawn through a framebuffer object.
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, NEAREST);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.Viewport(0, 0, 4, 4);
  gl.ClearColor(0, 1, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  testing::SolidShader red;
  red.color = glm::vec4(1, 0, 0, 1);
  gl.UseProgram(red);
  const std::uint32_t quad = testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {0, -1, 0, 1}, {-1, 1, 0, 1}, {0, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  std::uint8_t px[4];
  gl.ReadPixel(1, 1, px);  // reads the framebuffer object now
  CHECK((px[0] == 255 && px[1] == 0));
  CHECK(gl.ReadPixels().width == 4);
  // Pass 2: the default framebuffer, a full-screen quad sampling the texture.
  struct Show : softgl::Shader<Show, testing::Vec4Varyings> {
    void Vertex(const VertexIn& in, VertexOut<testing::Vec4Varyings>& out) const {
      out.position = in.attrib[0];
      out.varyings.value = in.attrib[0] * 0.5f + 0.5f;
    }
    bool Fragment(const FragmentIn<testing::Vec4Varyings>& in, FragmentOut& out) const {
      out.color[0] = in.textures->Sample(0, glm::vec2(in.varyings.value), {}, {});
      return true;
    }
  } show;
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.Viewport(0, 0, 8, 8);
  gl.UseProgram(show);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.ReadPixel(1, 4, px);
  CHECK((px[0] == 255 && px[1] == 0));
  gl.ReadPixel(6, 4, px);
  CHECK((px[0] == 0 && px[1] == 255));
  CHECK(gl.GetError() == NO_ERROR);
  (void)quad;
}

TEST_CASE("one fragment shader writes four render targets, with depth in a depth texture", "[framebuffer]") {
  struct Mrt : softgl::Shader<Mrt, testing::NoVaryings> {
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
      out.color[0] = glm::vec4(1, 0, 0, 1);
      out.color[1] = glm::vec4(0, 1, 0, 1);
      out.color[2] = glm::vec4(0.25f, 2.0f, -1.0f, 1);  // a float target keeps values outside [0, 1]
      out.color[3] = glm::vec4(0.5f, 0, 0, 0);
      return true;
    }
  } shader;
  Context gl(1, 1);
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  const Enum formats[4] = {RGBA8, RGBA8, RGBA32F, R8};
  std::uint32_t tex[5];
  gl.GenTextures(5, tex);
  for (int i = 0; i < 4; ++i) {
    gl.BindTexture(TEXTURE_2D, tex[i]);
    gl.TexImage2D(TEXTURE_2D, 0, formats[i], 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
    gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0 + Enum(i), TEXTURE_2D, tex[i], 0);
  }
  gl.BindTexture(TEXTURE_2D, tex[4]);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT, 4, 4, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  gl.FramebufferTexture2D(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, tex[4], 0);
  const Enum bufs[4] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2, COLOR_ATTACHMENT0 + 3};
  gl.DrawBuffers(4, bufs);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.Viewport(0, 0, 4, 4);
  gl.Enable(DEPTH_TEST);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}});
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(gl.ReadDepth(2, 2) == Approx(0.75f));
  // Read each target back by sampling it.
  struct Fetch : softgl::Shader<Fetch, testing::NoVaryings> {
    mutable std::vector<glm::vec4> got;
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      out.position = glm::vec4(2, 2, 2, 1);
      for (int u = 0; u < 5; ++u) got.push_back(in.textures->SampleLod(u, {0.5f, 0.5f}, 0.0f));
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut&) const { return false; }
  } fetch;
  for (int u = 0; u < 5; ++u) {
    gl.ActiveTexture(TEXTURE0 + Enum(u));
    gl.BindTexture(TEXTURE_2D, tex[u]);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  }
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.UseProgram(fetch);
  gl.DrawArrays(POINTS, 0, 1);
  REQUIRE(fetch.got.size() == 5);
  CHECK(fetch.got[0] == glm::vec4(1, 0, 0, 1));
  CHECK(fetch.got[1] == glm::vec4(0, 1, 0, 1));
  CHECK(fetch.got[2] == glm::vec4(0.25f, 2.0f, -1.0f, 1));
  CHECK(fetch.got[3].r == Approx(128.0f / 255.0f));  // R8 keeps r only
  CHECK(fetch.got[3].a == 1.0f);
  CHECK(fetch.got[4].r == Approx(0.75f));
}

TEST_CASE("corrupt JPEG files are refused with libjpeg's reason", "[texture][files]") {
  // Inputs on which stb_image 2.27 misbehaved (found by fuzz_image): a Huffman table of more than 256 codes (after
  // 0xFF fill bytes, which stb skipped; without them for libjpeg), a scan using a table never defined, a scan that
  // runs out of data.
  auto read = [](const std::string& name) {
    std::ifstream f(std::string(SOFTGL_SOURCE_DIR) + "/tests/fuzz/corpus/fuzz_image/" + name, std::ios::binary);
    return std::vector<char>((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  std::vector<char> oversized = read("regression_jpeg_huffman");
  REQUIRE(oversized.size() > 40);
  Context gl(1, 1);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  std::string error;
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, oversized.data(), oversized.size(), true, &error));
  CHECK(error.find("not of any known type") != std::string::npos);  // 0xFF bytes before SOI: not a JPEG
  while (oversized.size() > 1 && std::uint8_t(oversized[1]) == 0xFF) oversized.erase(oversized.begin());
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, oversized.data(), oversized.size(), true, &error));
  CHECK(error.find("corrupt JPEG (Bogus Huffman table definition)") != std::string::npos);

  const std::vector<char> undefined = read("regression_jpeg_undefined_table");
  REQUIRE(!undefined.empty());
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, undefined.data(), undefined.size(), true, &error));
  CHECK(error.find("Huffman table 0x03 was not defined") != std::string::npos);
  int w = 0, h = 0, n = 0;
  CHECK(ReadImageInfo(undefined.data(), undefined.size(), &w, &h, &n));  // the header itself is sound
  CHECK((w == 4 && h == 4 && n == 3));

  const std::vector<char> short_scan = read("regression_jpeg_short_scan");
  REQUIRE(!short_scan.empty());
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, short_scan.data(), short_scan.size(), true, &error));
  CHECK(error.find("corrupt JPEG") != std::string::npos);

  // The seed decodes: 4x4, three channels.
  const std::vector<char> seed = read("seed.jpg");
  CHECK(gl.TexImage2DFromMemory(TEXTURE_2D, seed.data(), seed.size(), true, &error));
  CHECK(ReadImageInfo(seed.data(), seed.size(), &w, &h, &n));
  CHECK((w == 4 && h == 4 && n == 3));
}

TEST_CASE("formats beyond PNG, JPEG, TGA, BMP and HDR are refused", "[texture][files]") {
  // A PNM header whose width overflows stb's integer parser (found by fuzz_image): stb reads only the documented
  // formats, so the file is of no known type.
  std::ifstream f(std::string(SOFTGL_SOURCE_DIR) + "/tests/fuzz/corpus/fuzz_image/regression_pnm_overflow",
                  std::ios::binary);
  const std::vector<char> pnm((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  REQUIRE(pnm.size() > 2);
  REQUIRE((pnm[0] == 'P' && pnm[1] == '6'));
  Context gl(1, 1);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  std::string error;
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, pnm.data(), pnm.size(), true, &error));
  CHECK(error.find("not of any known type") != std::string::npos);
  int w = 0, h = 0, n = 0;
  CHECK_FALSE(ReadImageInfo(pnm.data(), pnm.size(), &w, &h, &n));
  // A well-formed 2x1 binary PPM is refused the same way.
  const char ppm[] = "P6\n2 1\n255\n\x10\x20\x30\x40\x50\x60";
  CHECK_FALSE(gl.TexImage2DFromMemory(TEXTURE_2D, ppm, sizeof(ppm) - 1, true, &error));
  CHECK_FALSE(ReadImageInfo(ppm, sizeof(ppm) - 1, &w, &h, &n));
}

namespace {

// A width x height JPEG of `components` channels (1 grey, 3 RGB, 4 CMYK, which libjpeg marks as Adobe's) at quality
// 100, encoded by libjpeg: `sample(x, y, c)` gives each sample; `progressive` asks for libjpeg's progressive scans.
template <class Sample>
std::vector<unsigned char> EncodeJpeg(int width, int height, int components, Sample sample, bool progressive = false) {
  jpeg_compress_struct info;
  jpeg_error_mgr errors;
  info.err = jpeg_std_error(&errors);
  jpeg_create_compress(&info);
  unsigned char* out = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &out, &size);
  info.image_width = JDIMENSION(width);
  info.image_height = JDIMENSION(height);
  info.input_components = components;
  info.in_color_space = components == 1 ? JCS_GRAYSCALE : components == 3 ? JCS_RGB : JCS_CMYK;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 100, TRUE);
  if (progressive) jpeg_simple_progression(&info);
  jpeg_start_compress(&info, TRUE);
  std::vector<unsigned char> row(std::size_t(width) * std::size_t(components));
  while (info.next_scanline < info.image_height) {
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < components; ++c)
        row[std::size_t(x * components + c)] = std::uint8_t(sample(x, int(info.next_scanline), c));
    JSAMPROW r = row.data();
    jpeg_write_scanlines(&info, &r, 1);
  }
  jpeg_finish_compress(&info);
  std::vector<unsigned char> bytes(out, out + size);
  jpeg_destroy_compress(&info);
  std::free(out);
  return bytes;
}

}  // namespace

TEST_CASE("JPEG files of each colour space decode to their channels", "[texture][files]") {
  // Grey: one channel; RGB: three; CMYK, stored as Adobe's files store it (255 no ink): red = C K / 255, ...
  struct Case {
    int components;
    std::uint8_t value[4];
    int channels;
    std::uint8_t expect[3];
  } cases[] = {
      {1, {77, 0, 0, 0}, 1, {77, 0, 0}},
      {3, {200, 100, 30, 0}, 3, {200, 100, 30}},
      {4, {255, 128, 0, 255}, 3, {255, 128, 0}},
      {4, {255, 255, 255, 102}, 3, {102, 102, 102}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.components, int(c.value[0]), int(c.value[3]));
    const std::vector<unsigned char> file =
        EncodeJpeg(16, 8, c.components, [&](int, int, int channel) { return c.value[channel]; });
    detail::LoadedImage img;
    std::string error;
    REQUIRE(detail::LoadImageMemory(file.data(), file.size(), "encoded", false, img, &error));
    CHECK((img.width == 16 && img.height == 8 && img.channels == c.channels));
    int w = 0, h = 0, n = 0;
    CHECK(ReadImageInfo(file.data(), file.size(), &w, &h, &n));
    CHECK((w == 16 && h == 8 && n == c.channels));
    int worst = 0;  // quality 100 still rounds in the colour conversion and the transform
    for (std::size_t i = 0; i < img.bytes.size(); ++i)
      worst = std::max(worst, std::abs(int(img.bytes[i]) - int(c.expect[i % std::size_t(c.channels)])));
    CHECK(worst <= 2);
  }
}

TEST_CASE("a progressive JPEG loads, through ReadImage and as decoded bytes alike", "[texture][files]") {
  // A 96 x 80 RGB image of smooth gradients, encoded by libjpeg once with progressive scans (SOF2) and once
  // sequentially (SOF0). The progressive file loads through ReadImage (RGBA) and through the texture decoder with the
  // same bytes, and those bytes are the sequential file's: the scans carry the same coefficients.
  auto sample = [](int x, int y, int c) { return c == 0 ? x * 2 : c == 1 ? y * 3 : (x + y) % 256; };
  const std::vector<unsigned char> progressive = EncodeJpeg(96, 80, 3, sample, true);
  const std::vector<unsigned char> sequential = EncodeJpeg(96, 80, 3, sample, false);
  auto has_marker = [](const std::vector<unsigned char>& file, unsigned char marker) {
    for (std::size_t i = 0; i + 1 < file.size(); ++i)
      if (file[i] == 0xFF && file[i + 1] == marker) return true;
    return false;
  };
  REQUIRE(has_marker(progressive, 0xC2));
  REQUIRE_FALSE(has_marker(sequential, 0xC2));
  std::filesystem::create_directories(SOFTGL_TEST_OUTPUT_DIR);
  const std::string path = std::string(SOFTGL_TEST_OUTPUT_DIR) + "/progressive.jpg";
  {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(progressive.data()), std::streamsize(progressive.size()));
  }
  Image rgba;
  std::string error;
  REQUIRE(ReadImage(path, rgba, &error));
  REQUIRE((rgba.width == 96 && rgba.height == 80));
  detail::LoadedImage loaded, reference;
  REQUIRE(detail::LoadImageMemory(progressive.data(), progressive.size(), "progressive", false, loaded, &error));
  REQUIRE(detail::LoadImageMemory(sequential.data(), sequential.size(), "sequential", false, reference, &error));
  REQUIRE((loaded.channels == 3 && reference.channels == 3));
  bool same = true;
  int worst = 0;
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 96; ++x) {
      const std::size_t i = std::size_t(y * 96 + x);
      for (int c = 0; c < 3; ++c) {
        same = same && rgba.rgba[i * 4 + std::size_t(c)] == loaded.bytes[i * 3 + std::size_t(c)];
        same = same && loaded.bytes[i * 3 + std::size_t(c)] == reference.bytes[i * 3 + std::size_t(c)];
        worst = std::max(worst, std::abs(int(loaded.bytes[i * 3 + std::size_t(c)]) - sample(x, y, c)));
      }
      same = same && rgba.rgba[i * 4 + 3] == 255;
    }
  CHECK(same);
  CHECK(worst <= 8);  // quality 100: the colour conversion, subsampled chroma and the transform round
}

TEST_CASE("ReadImageInfo reads a header without decoding", "[texture][files]") {
  int w = 0, h = 0, n = 0;
  // A good image's header is read without decoding it.
  Image img;
  img.width = 3;
  img.height = 2;
  img.rgba.assign(24, 200);
  const std::string path = std::string(SOFTGL_TEST_OUTPUT_DIR) + "/info.png";
  std::filesystem::create_directories(SOFTGL_TEST_OUTPUT_DIR);
  REQUIRE(WritePng(path, img));
  std::ifstream png(path, std::ios::binary);
  const std::vector<char> png_bytes((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>());
  REQUIRE(ReadImageInfo(png_bytes.data(), png_bytes.size(), &w, &h, &n));
  CHECK((w == 3 && h == 2 && n == 4));
}

namespace {

// For the exactness tests of the fast sampling paths: a mipmapped REPEAT / LINEAR texture of random texels, and
// per minification filter the view MakeView resolves (which takes the fast path) beside a copy of it with the fast
// path switched off (the general path), each bound to unit 0 of its own Textures.
struct FastAndGeneral {
  std::uint32_t seed;
  TextureObject texture;
  TextureView fast_view, general_view;
  Textures fast, general;

  FastAndGeneral(int w, int h, std::uint32_t s, Enum format = RGBA32F) : seed(s) {
    texture = MakeTexture(w, h, [&](int, int) { return glm::vec4(Next(), Next(), Next(), Next()); }, format);
    detail::GenerateMipmaps(texture);
    texture.params.wrap_s = texture.params.wrap_t = REPEAT;
    texture.params.mag_filter = LINEAR;
  }
  // A pseudo-random float in [0, 1).
  float Next() {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 24);
  }
  void Use(Enum min_filter, float lod_bias = 0.0f) {
    texture.params.min_filter = min_filter;
    texture.params.lod_bias = lod_bias;
    fast_view = detail::MakeView(texture);
    general_view = fast_view;
    general_view.fast = TextureView::Fast::kNone;
    fast.unit_2d[0] = &fast_view;
    general.unit_2d[0] = &general_view;
  }
};

}  // namespace

TEST_CASE("the fast REPEAT path samples exactly as the general one", "[texture]") {
  // A 64 x 32 mipmapped texture of arbitrary texels, sampled at random places with random derivatives (both
  // magnified and minified, lambda past the last level too) through the fast path and the general one: the results
  // must be the same floats.
  for (const Enum format : {RGBA32F, RGBA8, SRGB8_ALPHA8})
  for (Enum min_filter : {LINEAR_MIPMAP_LINEAR, LINEAR}) {
    FastAndGeneral f(64, 32, 99, format);
    f.Use(min_filter);
    REQUIRE(f.fast_view.fast != TextureView::Fast::kNone);
    int differing = 0;
    for (int i = 0; i < 20000; ++i) {
      const glm::vec2 uv((f.Next() - 0.5f) * 8.0f, (f.Next() - 0.5f) * 8.0f);
      const float scale = std::ldexp(1.0f, int(f.Next() * 14.0f) - 10);  // 2^-10 .. 2^3 per pixel
      const glm::vec2 dx(f.Next() * scale, f.Next() * scale), dy(f.Next() * scale, f.Next() * scale);
      const float bias = f.Next() - 0.5f;
      differing += f.fast.Sample(0, uv, dx, dy, bias) != f.general.Sample(0, uv, dx, dy, bias);
    }
    INFO("format 0x" << std::hex << format << ", min filter 0x" << min_filter);
    CHECK(differing == 0);
  }
}

TEST_CASE("SampleQuad gives each lane exactly what Sample gives it", "[texture]") {
  // Random quads (each lane its own coordinates and derivatives, mixed magnification and minification, some
  // lanes past the last level, some with NaN or huge coordinates) on the fast path and on an incomplete unit.
  FastAndGeneral f(128, 64, 7);
  for (Enum min_filter : {LINEAR_MIPMAP_LINEAR, LINEAR, NEAREST_MIPMAP_LINEAR}) {
    f.Use(min_filter, min_filter == LINEAR ? 0.0f : 0.25f);
    // NEAREST_MIPMAP_LINEAR is not on the fast path: SampleQuad samples lane by lane there.
    CHECK((f.fast_view.fast != TextureView::Fast::kNone) == (min_filter != NEAREST_MIPMAP_LINEAR));
    int differing = 0;
    for (int i = 0; i < 5000; ++i) {
      glm::vec2 uv[4], dx[4], dy[4];
      for (int l = 0; l < 4; ++l) {
        uv[l] = glm::vec2((f.Next() - 0.5f) * 6.0f, (f.Next() - 0.5f) * 6.0f);
        const float scale = std::ldexp(1.0f, int(f.Next() * 16.0f) - 11);
        dx[l] = glm::vec2((f.Next() - 0.5f) * scale, f.Next() * scale);
        dy[l] = glm::vec2(f.Next() * scale, (f.Next() - 0.5f) * scale);
      }
      if (i % 97 == 0) uv[1].x = std::numeric_limits<float>::quiet_NaN();
      if (i % 89 == 0) uv[2].y = 3e9f;
      if (i % 83 == 0) dx[3] = dy[3] = glm::vec2(0.0f);  // rho = 0: lambda clamps to min_lod
      const float bias = f.Next() - 0.5f;
      glm::vec4 got[4];
      f.fast.SampleQuad(0, uv, dx, dy, bias, got);
      for (int l = 0; l < 4; ++l) {
        const glm::vec4 want = f.general.Sample(0, uv[l], dx[l], dy[l], bias);
        differing += std::memcmp(&got[l], &want, sizeof want) != 0;
      }
    }
    INFO("min filter 0x" << std::hex << min_filter);
    CHECK(differing == 0);
  }
  Textures none;  // no texture: (0, 0, 0, 1) in every lane
  const glm::vec2 z[4] = {};
  glm::vec4 got[4];
  none.SampleQuad(0, z, z, z, 0.0f, got);
  for (const glm::vec4& g : got) CHECK(g == glm::vec4(0, 0, 0, 1));
}

TEST_CASE("texture parameters and level parameters read back", "[texture]") {
  Context gl(4, 4);
  float f[4] = {0, 0, 0, 0};
  gl.GetTexParameterfv(TEXTURE_2D, TEXTURE_MIN_FILTER, f);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing bound
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  int i[4] = {0, 0, 0, 0};
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MIN_FILTER, i);
  CHECK(i[0] == int(NEAREST_MIPMAP_LINEAR));  // OpenGL's initial value
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_WRAP_T, i);
  CHECK(i[0] == int(REPEAT));
  const int mag = int(NEAREST);
  gl.TexParameteriv(TEXTURE_2D, TEXTURE_MAG_FILTER, &mag);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MAG_FILTER, i);
  CHECK(i[0] == int(NEAREST));
  gl.TexParameterf(TEXTURE_2D, TEXTURE_LOD_BIAS, 1.5f);
  gl.GetTexParameterfv(TEXTURE_2D, TEXTURE_LOD_BIAS, f);
  CHECK(f[0] == 1.5f);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_LOD_BIAS, i);
  CHECK(i[0] == 2);  // rounded
  const int border[4] = {2147483647, 0, -2147483647, 1073741824};
  gl.TexParameteriv(TEXTURE_2D, TEXTURE_BORDER_COLOR, border);
  gl.GetTexParameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, f);
  CHECK((f[0] == 1.0f && f[1] == 0.0f && f[2] == -1.0f && std::fabs(f[3] - 0.5f) < 1e-6f));
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_BORDER_COLOR, i);
  CHECK((i[0] == 2147483647 && i[1] == 0 && i[2] == -2147483647));
  // Small integers read back as they were set (rounded, not truncated: -1 is stored as -1 / (2^31 - 1)).
  const int small[4] = {-1, 1, -1000, 12345};
  gl.TexParameteriv(TEXTURE_2D, TEXTURE_BORDER_COLOR, small);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_BORDER_COLOR, i);
  CHECK((i[0] == -1 && i[1] == 1 && i[2] == -1000 && i[3] == 12345));
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetTexParameteriv(TEXTURE_2D, 0x1234, i);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetTexParameteriv(TEXTURE_CUBE_MAP_POSITIVE_X, TEXTURE_MIN_FILTER, i);
  CHECK(gl.GetError() == INVALID_ENUM);
  // Level parameters.
  gl.TexImage2D(TEXTURE_2D, 0, RGB8, 8, 4, 0, RGB, UNSIGNED_BYTE, nullptr);
  gl.TexImage2D(TEXTURE_2D, 1, DEPTH24_STENCIL8, 4, 2, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, nullptr);
  struct Expect {
    int level;
    Enum pname;
    int value;
  };
  for (const Expect& e : {Expect{0, TEXTURE_WIDTH, 8}, Expect{0, TEXTURE_HEIGHT, 4}, Expect{0, TEXTURE_DEPTH, 1},
                          Expect{0, TEXTURE_INTERNAL_FORMAT, int(RGB8)}, Expect{0, TEXTURE_RED_SIZE, 8},
                          Expect{0, TEXTURE_ALPHA_SIZE, 0}, Expect{1, TEXTURE_WIDTH, 4},
                          Expect{1, TEXTURE_DEPTH_SIZE, 24}, Expect{1, TEXTURE_STENCIL_SIZE, 8},
                          Expect{1, TEXTURE_RED_SIZE, 0}, Expect{2, TEXTURE_WIDTH, 0},
                          Expect{2, TEXTURE_INTERNAL_FORMAT, int(RGBA)}}) {
    int v = -1;
    gl.GetTexLevelParameteriv(TEXTURE_2D, e.level, e.pname, &v);
    INFO("level " << e.level << " pname " << e.pname);
    CHECK(v == e.value);
  }
  float w = 0;
  gl.GetTexLevelParameterfv(TEXTURE_2D, 0, TEXTURE_WIDTH, &w);
  CHECK(w == 8.0f);
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetTexLevelParameteriv(TEXTURE_2D, -1, TEXTURE_WIDTH, i);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_MIN_FILTER, i);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetTexLevelParameteriv(TEXTURE_CUBE_MAP, 0, TEXTURE_WIDTH, i);
  CHECK(gl.GetError() == INVALID_ENUM);
}

TEST_CASE("sRGB conversions: the decode table, an exact encode, and their round trip", "[texture][srgb]") {
  CHECK(detail::SrgbDecode8(0) == 0.0f);
  CHECK(detail::SrgbDecode8(255) == 1.0f);
  // Section 8.24's formula at two bytes, one on each side of its linear segment.
  CHECK(detail::SrgbDecode8(10) == Approx(10.0 / 255.0 / 12.92).epsilon(1e-6));
  CHECK(detail::SrgbDecode8(128) == Approx(0.2158605).epsilon(1e-6));
  for (int k = 0; k < 256; ++k) {
    INFO("byte " << k);
    CHECK(detail::SrgbEncode8(detail::SrgbDecode8(std::uint8_t(k))) == k);  // decoding loses nothing
    if (k > 0) CHECK(detail::SrgbDecode8(std::uint8_t(k)) > detail::SrgbDecode8(std::uint8_t(k - 1)));
  }
  // The encode is the nearest byte to 255 times section 17.3.7's value: checked on a dense sweep, away from the
  // half-way points where float and double could disagree.
  int checked = 0;
  for (int i = 0; i <= 100000; ++i) {
    const double l = i / 100000.0;
    const double c = l < 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    const double scaled = c * 255.0;
    if (std::fabs(scaled - std::floor(scaled) - 0.5) < 1e-4) continue;
    CHECK(int(detail::SrgbEncode8(float(l))) == int(std::lround(scaled)));
    ++checked;
  }
  CHECK(checked > 99000);
  CHECK(detail::SrgbEncode8(0.5f) == 188);  // a linear half is sRGB 0.735
  CHECK(detail::SrgbEncode8(-1.0f) == 0);
  CHECK(detail::SrgbEncode8(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(detail::SrgbEncode8(2.0f) == 255);
}

TEST_CASE("sRGB conversions: the bucket table's encode is SrgbEncode8 on every float near each step and across (0, 1)",
          "[texture][srgb]") {
  const detail::SrgbLaneTables& t = detail::SrgbLanes();
  bool same = true;
  auto check = [&](float x) { same = same && detail::SrgbEncode8ByTable(t, x) == detail::SrgbEncode8(x); };
  for (std::uint32_t bits = 0; bits < 0x3F900000u; bits += 61) {  // 0 to a little past 1, every 61st float
    float x;
    std::memcpy(&x, &bits, 4);
    check(x);
  }
  for (int k = 0; k < 255; ++k)  // each step's float and its neighbours
    for (float x : {std::nextafter(t.up[k], 0.0f), t.up[k], std::nextafter(t.up[k], 2.0f)}) check(x);
  for (float x : {-0.0f, -1.0f, 1.0f, 2.0f, std::numeric_limits<float>::infinity(),
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()})
    check(x);
  CHECK(same);
}

TEST_CASE("sRGB textures decode before filtering; their mipmaps average in linear light", "[texture][srgb]") {
  Context gl(4, 4);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  // A 2 x 2 level: black and white columns, alpha 0 and 255 (alpha is linear).
  const std::uint8_t texels[16] = {0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255};
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(TEXTURE_2D, 0, SRGB8_ALPHA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, texels);
  REQUIRE(gl.GetError() == NO_ERROR);
  int format = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &format);
  CHECK(format == int(SRGB8_ALPHA8));
  gl.GenerateMipmap(TEXTURE_2D);
  // The texels come back as stored: no conversion on the way out.
  std::uint8_t level0[16] = {}, level1[4] = {};
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, level0);
  CHECK(std::memcmp(level0, texels, 16) == 0);
  gl.GetTexImage(TEXTURE_2D, 1, RGBA, UNSIGNED_BYTE, level1);
  // Black and white average to a linear half, which encodes to 188 (an average of the bytes would give 128);
  // alpha averages as it is.
  CHECK(int(level1[0]) == 188);
  CHECK(int(level1[2]) == 188);
  CHECK(int(level1[3]) == 128);

  // LINEAR between the two columns: a linear half (0.5), not the decoded average byte 128 (0.216).
  TextureObject t = MakeTexture(2, 1, [](int i, int) { return glm::vec4(float(i), float(i), float(i), 1.0f); }, SRGB8_ALPHA8);
  t.params.mag_filter = LINEAR;
  t.params.wrap_s = t.params.wrap_t = CLAMP_TO_EDGE;
  const Sampler s(t);
  CHECK(s.view.srgb);
  CHECK(s.At(0.5f, 0.5f).r == Approx(0.5f).margin(1e-5));
  CHECK(s.At(0.25f, 0.5f).g == 0.0f);
  CHECK(s.At(0.75f, 0.5f).b == Approx(1.0f).margin(1e-5));
  // A middle grey byte samples as its decoded value.
  TextureObject grey = MakeTexture(1, 1, [](int, int) { return glm::vec4(128.0f / 255.0f, 0.0f, 1.0f, 0.5f); }, SRGB8);
  const Sampler g(grey);
  const glm::vec4 v = g.At(0.5f, 0.5f);
  CHECK(v.r == Approx(detail::SrgbDecode8(128)).margin(1e-5));
  CHECK(v.a == 1.0f);  // SRGB8 has no alpha
  // Sampling's decode (a polynomial, the same on every path) is within 1e-5 of the formula for every byte, and
  // exact on its linear segment.
  detail::TextureLevel all;
  all.Allocate(SRGB8_ALPHA8, 256, 1);
  for (int k = 0; k < 256; ++k) all.At(k, 0)[0] = std::uint8_t(k);
  for (int k = 0; k < 256; ++k) {
    INFO("byte " << k);
    const float decoded = all.Sampled(k, 0).r / 255.0f;
    CHECK(decoded == Approx(detail::SrgbDecode8(std::uint8_t(k))).margin(1e-5));
    if (k <= 10) CHECK(decoded == Approx(float(k) / 255.0f / 12.92f).epsilon(1e-6));
  }
}

TEST_CASE("FRAMEBUFFER_SRGB: an sRGB attachment encodes clears and fragments, and blends in linear light",
          "[framebuffer][srgb]") {
  Context gl(4, 4);
  const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, SRGB8_ALPHA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  int encoding = 0;
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
                                         &encoding);
  CHECK(encoding == int(SRGB));
  CHECK_FALSE(gl.IsEnabled(FRAMEBUFFER_SRGB));
  std::uint8_t px[4];

  // Disabled (the default): values are stored as they are.
  gl.ClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ReadPixel(0, 0, px);
  CHECK(int(px[0]) == 128);

  // Enabled: the clear colour is encoded, alpha is not.
  gl.Enable(FRAMEBUFFER_SRGB);
  CHECK(gl.IsEnabled(FRAMEBUFFER_SRGB));
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ReadPixel(0, 0, px);  // ReadPixels returns the stored bytes
  CHECK((int(px[0]) == 188 && int(px[1]) == 188 && int(px[2]) == 188 && int(px[3]) == 128));

  // A fragment of 0.5 is encoded; blended 50% over black, the linear quarter 0.25 encodes to 137 (blending the
  // stored bytes would give 64).
  testing::SolidShader solid;
  solid.color = glm::vec4(0.5f, 0.0f, 1.0f, 1.0f);
  gl.UseProgram(solid);
  const std::uint32_t vao =
      testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.ReadPixel(1, 1, px);
  CHECK((int(px[0]) == 188 && int(px[1]) == 0 && int(px[2]) == 255 && int(px[3]) == 255));
  gl.ClearColor(0, 0, 0, 0);
  gl.Clear(COLOR_BUFFER_BIT);
  solid.color = glm::vec4(0.5f, 0.5f, 0.5f, 0.5f);
  gl.Enable(BLEND);
  gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.ReadPixel(2, 2, px);
  CHECK((int(px[0]) == 137 && int(px[3]) == 64));
  // Again over that: 0.5 * 0.5 + 0.5 * 0.25 = 0.375 linear, from the stored 137 decoded.
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == int(detail::SrgbEncode8(0.5f * 0.5f + 0.5f * detail::SrgbDecode8(137))));
  gl.Disable(BLEND);

  // Blit from the sRGB texture into a linear RGBA8 renderbuffer: decoded while FRAMEBUFFER_SRGB is enabled, the
  // bytes as they are when it is not.
  const std::uint32_t rb = gl.GenRenderbuffer(), dst = gl.GenFramebuffer();
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 4, 4);
  gl.BindFramebuffer(DRAW_FRAMEBUFFER, dst);
  gl.FramebufferRenderbuffer(DRAW_FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, COLOR_BUFFER_BIT, NEAREST);
  gl.BindFramebuffer(READ_FRAMEBUFFER, dst);
  gl.ReadPixel(0, 0, px);
  const int stored = int(detail::SrgbEncode8(0.5f * 0.5f + 0.5f * detail::SrgbDecode8(137)));
  CHECK(int(px[0]) == int(detail::FloatToUnorm8(detail::SrgbDecode8(std::uint8_t(stored)))));
  gl.Disable(FRAMEBUFFER_SRGB);
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  gl.BlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, COLOR_BUFFER_BIT, NEAREST);
  gl.BindFramebuffer(READ_FRAMEBUFFER, dst);
  gl.ReadPixel(0, 0, px);
  CHECK(int(px[0]) == stored);
  CHECK(gl.GetError() == NO_ERROR);

  // A linear attachment reports LINEAR, and FRAMEBUFFER_SRGB leaves it alone.
  gl.BindFramebuffer(FRAMEBUFFER, dst);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0, FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
                                         &encoding);
  CHECK(encoding == int(LINEAR));
  gl.Enable(FRAMEBUFFER_SRGB);
  gl.ClearColor(0.5f, 0.5f, 0.5f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ReadPixel(0, 0, px);
  CHECK(int(px[0]) == 128);
  gl.GetFramebufferAttachmentParameteriv(FRAMEBUFFER, COLOR_ATTACHMENT0 + 1, FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING,
                                         &encoding);
  CHECK(gl.GetError() == INVALID_OPERATION);  // nothing attached there
  (void)vao;

  // A context whose own colour buffer is SRGB8_ALPHA8: the same rules.
  const glm::vec4 value(0.5f, 0.25f, 0.5f, 0.5f);
  const Cleared plain = ClearContext(SRGB8_ALPHA8, value), encoded = ClearContext(SRGB8_ALPHA8, value, true);
  CHECK(plain.error == NO_ERROR);
  CHECK((plain.rgba[0] == 128 && plain.rgba[1] == 64 && plain.rgba[3] == 128));  // FRAMEBUFFER_SRGB off: as they are
  CHECK((encoded.rgba[0] == 188 && encoded.rgba[1] == int(detail::SrgbEncode8(0.25f)) && encoded.rgba[3] == 128));
}

TEST_CASE("image files load as sRGB textures when asked", "[texture][files][srgb]") {
  const std::string path = (std::filesystem::temp_directory_path() / "softgl_srgb_test.png").string();
  Image image;
  image.width = 2;
  image.height = 1;
  image.rgba = {128, 0, 0, 255, 255, 255, 255, 128};
  REQUIRE(WritePng(path, image));
  Context gl(2, 2);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  int format = 0;
  CHECK(gl.TexImage2DFromFile(TEXTURE_2D, path, false, nullptr, SRGB));
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &format);
  CHECK(format == int(SRGB8_ALPHA8));
  CHECK(gl.TexImage2DFromFile(TEXTURE_2D, path, false));
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &format);
  CHECK(format == int(RGBA8));
  CHECK(gl.GetError() == NO_ERROR);
  std::string error;
  CHECK_FALSE(gl.TexImage2DFromFile(TEXTURE_2D, path, false, &error, RGBA));
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(error.find("LINEAR or SRGB") != std::string::npos);
  std::filesystem::remove(path);
}

#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#include <immintrin.h>
namespace {
__attribute__((target("f16c"))) std::uint16_t HardwareHalf(float f) {
  return std::uint16_t(_mm_cvtsi128_si32(_mm_cvtps_ph(_mm_set_ss(f), _MM_FROUND_TO_NEAREST_INT)) & 0xFFFF);
}
// F16C, from CPUID leaf 1 (Clang 14's __builtin_cpu_supports does not know the name).
bool HasF16c() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  return __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C) != 0;
}
}  // namespace
#endif

TEST_CASE("half floats and the unsigned 11- and 10-bit floats convert as IEEE rounding says", "[texture][float]") {
  // Every half decodes and encodes back to itself (NaNs to a NaN).
  for (std::uint32_t h = 0; h < 65536; ++h) {
    const float f = detail::HalfToFloat(std::uint16_t(h));
    if (std::isnan(f)) {
      CHECK(((h & 0x7C00u) == 0x7C00u && (h & 0x3FFu) != 0));
      continue;
    }
    if (detail::FloatToHalf(f) != h) FAIL("half 0x" << std::hex << h);
  }
  CHECK(detail::HalfToFloat(0x3C00) == 1.0f);
  CHECK(detail::HalfToFloat(0x7BFF) == 65504.0f);
  CHECK(detail::HalfToFloat(0x0001) == std::ldexp(1.0f, -24));
  CHECK(detail::FloatToHalf(65519.0f) == 0x7BFF);   // below the half-way point to 65536: the largest finite
  CHECK(detail::FloatToHalf(65520.0f) == 0x7C00);   // the half-way point rounds to even: infinity
  CHECK(detail::FloatToHalf(1.0f + std::ldexp(1.0f, -11)) == 0x3C00);  // a tie: to the even mantissa
  CHECK(detail::FloatToHalf(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3C02);
  CHECK(detail::FloatToHalf(-2.0f) == 0xC000);
  CHECK(detail::FloatToHalf(std::ldexp(1.0f, -26)) == 0x0000);  // a quarter of the smallest subnormal: 0
  CHECK(detail::FloatToHalf(-std::numeric_limits<float>::infinity()) == 0xFC00);
#if defined(__x86_64__) && defined(__GNUC__)
  if (HasF16c()) {  // against the processor's own conversion, on a sweep of floats
    std::uint32_t seed = 12345;
    int differing = 0;
    for (int i = 0; i < 200000; ++i) {
      seed = seed * 1664525u + 1013904223u;
      const float f = std::ldexp(float(seed >> 8) / float(1u << 24) - 0.5f, int(seed % 44) - 28);
      differing += detail::FloatToHalf(f) != HardwareHalf(f);
    }
    CHECK(differing == 0);
  }
#endif
  // The unsigned forms: every code round-trips; negative values and -0 give 0; too large gives infinity.
  for (const int m : {6, 5}) {
    INFO("mantissa bits " << m);
    for (std::uint32_t v = 0; v < (32u << m); ++v) {
      const float f = detail::UnsignedSmallToFloat(v, m);
      if (std::isnan(f)) continue;
      if (detail::FloatToUnsignedSmall(f, m) != v) FAIL("code " << v);
    }
    CHECK(detail::FloatToUnsignedSmall(-3.0f, m) == 0u);
    CHECK(detail::FloatToUnsignedSmall(-0.0f, m) == 0u);
    CHECK(detail::UnsignedSmallToFloat(detail::FloatToUnsignedSmall(1e9f, m), m) == std::numeric_limits<float>::infinity());
    CHECK(std::isnan(detail::UnsignedSmallToFloat(detail::FloatToUnsignedSmall(std::nanf(""), m), m)));
  }
  CHECK(detail::UnsignedSmallToFloat((30u << 6) | 63u, 6) == 65024.0f);  // the largest 11-bit value
  CHECK(detail::UnsignedSmallToFloat((30u << 5) | 31u, 5) == 64512.0f);  // and 10-bit
}

#if defined(SOFTGL_HAS_DISPATCH) && !defined(__clang__)
namespace {
// The vector half conversions as the AVX2 and AVX-512 levels compile them with GCC (F16C's instructions: src/wide.h),
// 8 lanes.
SOFTGL_TARGET_AVX2 void HalvesToFloatsAvx2(const std::uint32_t* h, float* f) {
  detail::V<8>::U in;
  std::memcpy(&in, h, sizeof in);
  const detail::V<8>::F out = detail::HalfLanes<8>(in);
  std::memcpy(f, &out, sizeof out);
}
SOFTGL_TARGET_AVX2 void FloatsToHalvesAvx2(const float* f, std::uint32_t* h) {
  detail::V<8>::F in;
  std::memcpy(&in, f, sizeof in);
  const detail::V<8>::U out = detail::HalfBitsLanes<8>(in);
  std::memcpy(h, &out, sizeof out);
}
}  // namespace

TEST_CASE("the vector half conversions give FloatToHalf's and HalfToFloat's bits, NaNs included", "[texture][float]") {
  if (detail::CpuSimdLevel() == detail::SimdLevel::kBaseline) return;  // (SSE2: the generic lanes, tested above)
  int compared = 0;
  for (std::uint32_t h0 = 0; h0 < 65536; h0 += 8) {  // every half
    std::uint32_t h[8];
    float f[8];
    for (std::uint32_t k = 0; k < 8; ++k) h[k] = h0 + k;
    HalvesToFloatsAvx2(h, f);
    for (int k = 0; k < 8; ++k) {
      const float want = detail::HalfToFloat(std::uint16_t(h[k]));
      if (std::memcmp(&want, &f[k], 4) != 0) FAIL("half 0x" << std::hex << h[k]);
      ++compared;
    }
  }
  // Floats: a sweep over every exponent, ties and the edges of the halves' range, infinities and NaNs of every
  // payload and sign.
  std::vector<std::uint32_t> bits = {0x00000000u, 0x80000000u, 0x7F800000u, 0xFF800000u, 0x7F800001u, 0xFF800001u,
                                     0x7FC00000u, 0xFFC00000u, 0x7FFFFFFFu, 0xFFFFFFFFu, 0x7FA00000u, 0x7F802000u,
                                     0x477FE000u, 0x477FEFFFu, 0x477FF000u, 0x38800000u, 0x387FFFFFu, 0x33800000u,
                                     0x33000000u, 0x33000001u, 0x3F801000u, 0x3F803000u};
  std::uint32_t seed = 99;
  for (int i = 0; i < 100000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    bits.push_back(seed);
  }
  while (bits.size() % 8) bits.push_back(0x3F800000u);
  for (std::size_t i = 0; i < bits.size(); i += 8) {
    float f[8];
    std::uint32_t h[8];
    std::memcpy(f, &bits[i], sizeof f);
    FloatsToHalvesAvx2(f, h);
    for (int k = 0; k < 8; ++k) {
      if (h[k] != detail::FloatToHalf(f[k])) FAIL("float bits 0x" << std::hex << bits[i + std::size_t(k)]);
      ++compared;
    }
  }
  CHECK(compared == 65536 + int(bits.size()));
}
#endif

TEST_CASE("float render targets keep values outside [0, 1] and blend in float", "[framebuffer][float]") {
  struct Case {
    Enum format;
    int channels;
    bool negative;  // keeps negative values
  };
  for (const Case c : {Case{RGBA16F, 4, true}, Case{RG16F, 2, true}, Case{R16F, 1, true}, Case{RG32F, 2, true},
                       Case{R11F_G11F_B10F, 3, false}, Case{RGBA32F, 4, true}}) {
    INFO("format 0x" << std::hex << c.format);
    Context gl(4, 4);
    const std::uint32_t tex = gl.GenTexture(), fbo = gl.GenFramebuffer();
    gl.BindTexture(TEXTURE_2D, tex);
    gl.TexImage2D(TEXTURE_2D, 0, c.format, 4, 4, 0, RGBA, FLOAT, nullptr);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    int bits = 0;
    gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_RED_SIZE, &bits);
    CHECK(bits == (c.format == RGBA32F || c.format == RG32F ? 32 : c.format == R11F_G11F_B10F ? 11 : 16));
    gl.ClearColor(2.5f, -0.75f, 0.5f, 3.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    testing::SolidShader solid;
    solid.color = glm::vec4(1.25f, 4.0f, -0.25f, 0.5f);
    gl.UseProgram(solid);
    testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
    gl.Enable(BLEND);
    gl.BlendFunc(ONE, ONE);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    float px[4] = {};
    gl.ReadPixels(1, 1, 1, 1, RGBA, FLOAT, px);
    const auto stored = [&](float v) { return c.negative ? v : std::max(v, 0.0f); };
    // Exactly representable sums in every format: the clear, then the colour added twice (each step stored).
    const glm::vec4 want(2.5f + 2 * 1.25f, stored(stored(-0.75f) + 4.0f) + 4.0f, stored(stored(0.5f - 0.25f) - 0.25f),
                         3.0f + 2 * 0.5f);
    for (int k = 0; k < 4; ++k) {
      INFO("channel " << k);
      const float expect = k < c.channels ? want[k] : (k == 3 ? 1.0f : 0.0f);
      CHECK(px[k] == expect);
    }
    // Sampled back: a LINEAR sample between two texels of different values.
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    gl.BindTexture(TEXTURE_2D, tex);
    const float texels[8] = {0.0f, -8.0f, 0.0f, 1.0f, 10.0f, 8.0f, 6.0f, 1.0f};
    gl.TexImage2D(TEXTURE_2D, 0, c.format, 2, 1, 0, RGBA, FLOAT, texels);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_EDGE);
    CHECK(gl.GetError() == NO_ERROR);
  }
  // The texel values of each format, sampled halfway: the mean of what each stores.
  for (const Enum format : {RGBA16F, R11F_G11F_B10F}) {
    TextureObject t = MakeTexture(2, 1, [](int i, int) { return i ? glm::vec4(10.0f, 8.0f, 6.0f, 1.0f) : glm::vec4(0.0f, -8.0f, 0.0f, 1.0f); }, format);
    t.params.mag_filter = LINEAR;
    t.params.wrap_s = t.params.wrap_t = CLAMP_TO_EDGE;
    const Sampler s(t);
    const glm::vec4 v = s.At(0.5f, 0.5f);
    CHECK(v.r == 5.0f);
    CHECK(v.g == (format == RGBA16F ? 0.0f : 4.0f));  // the unsigned format stored -8 as 0
    CHECK(v.b == 3.0f);
  }
}

TEST_CASE("packed formats: RGB565, RGBA4, RGB5_A1 and RGB10_A2 textures and targets, and a 16-bit context",
          "[framebuffer][packed]") {
  struct Case {
    Enum format;
    int bits[4];  // 0: no such channel (alpha reads 1)
  };
  for (const Case c : {Case{RGB565, {5, 6, 5, 0}}, Case{RGBA4, {4, 4, 4, 4}}, Case{RGB5_A1, {5, 5, 5, 1}},
                       Case{RGB10_A2, {10, 10, 10, 2}}}) {
    INFO("format 0x" << std::hex << c.format);
    // Stored: clamped to [0, 1] and rounded to each channel's bits; read back as k / (2^bits - 1).
    detail::TextureLevel level;
    level.Allocate(c.format, 2, 1);
    const std::size_t bytes = c.format == RGB10_A2 ? 4 : 2;  // one word a texel
    CHECK(level.data.size() == 2 * bytes + detail::TextureLevel::kGatherPad);
    const glm::vec4 in(0.45f, 1.7f, -0.2f, 0.31f);  // no ties between two steps
    detail::StoreTexel(level, 0, 0, in);
    const glm::vec4 got = level.Texel(0, 0);
    for (int k = 0; k < 4; ++k) {
      INFO("channel " << k);
      if (!c.bits[k]) {
        CHECK(got[k] == 1.0f);
        continue;
      }
      const float max = float((1 << c.bits[k]) - 1);
      CHECK(got[k] == std::round(std::clamp(in[k], 0.0f, 1.0f) * max) / max);
    }
    // As a render target: a clear, a blended draw (in float, the colour clamped first), per-channel masks.
    Context gl(4, 4);
    const std::uint32_t rb = gl.GenRenderbuffer(), fbo = gl.GenFramebuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, c.format, 4, 4);
    int red_bits = 0;
    gl.GetRenderbufferParameteriv(RENDERBUFFER, RENDERBUFFER_RED_SIZE, &red_bits);
    CHECK(red_bits == c.bits[0]);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    gl.ClearColor(1.0f, 0.0f, 1.0f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    testing::SolidShader solid;
    solid.color = glm::vec4(2.0f, 1.0f, 0.0f, 0.5f);  // red clamped to 1
    gl.UseProgram(solid);
    testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
    gl.Enable(BLEND);
    gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
    gl.ColorMask(true, true, false, true);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    float px[4] = {};
    gl.ReadPixels(2, 2, 1, 1, RGBA, FLOAT, px);
    auto quantized = [](float v, int bits) {
      const float max = float((1 << bits) - 1);
      return std::round(v * max) / max;
    };
    CHECK(px[0] == 1.0f);                                  // 0.5 * 1 + 0.5 * 1
    CHECK(px[1] == quantized(0.5f, c.bits[1]));            // 0.5 * 1 + 0.5 * 0
    CHECK(px[2] == 1.0f);                                  // masked: the clear's
    CHECK(px[3] == (c.bits[3] ? quantized(0.5f * 0.5f + 0.5f * 1.0f, c.bits[3]) : 1.0f));
    CHECK(gl.GetError() == NO_ERROR);
  }
  // The context's own colour buffer in RGB565: 5, 6 and 5 bits, alpha 1.
  const Cleared small = ClearContext(RGB565, glm::vec4(0.5f, 0.5f, 0.5f, 0.0f));
  CHECK(small.rgba[0] == int(std::lround(std::round(0.5f * 31.0f) / 31.0f * 255.0f)));  // 16 / 31 of 255: 132
  CHECK(small.rgba[1] == int(std::lround(std::round(0.5f * 63.0f) / 63.0f * 255.0f)));  // 32 / 63: 130
  CHECK(small.rgba[3] == 255);
  CHECK(small.error == NO_ERROR);
  const Cleared refused = ClearContext(RGBA4, glm::vec4(0.5f));
  CHECK(refused.error == INVALID_ENUM);
  CHECK(refused.rgba[3] == 128);  // RGBA8 after all
}

TEST_CASE("anisotropic filtering: N probes along the footprint's longer axis, at the level of Pmax / N",
          "[texture][anisotropic]") {
  // A 64 x 64 mipmapped texture of arbitrary texels; a footprint 8 texels long in s and 1 in t.
  TextureObject t = MakeTexture(64, 64, [](int i, int j) {
    return glm::vec4(float((i * 7 + j * 3) % 11) / 10.0f, float((i + 2 * j) % 5) / 4.0f, float(i % 3), 1.0f);
  });
  detail::GenerateMipmaps(t);
  t.params.min_filter = LINEAR_MIPMAP_LINEAR;
  t.params.mag_filter = LINEAR;
  const glm::vec2 uv(0.37f, 0.61f), dx(8.0f / 64.0f, 0.0f), dy(0.0f, 1.0f / 64.0f);
  auto probes = [&](const Sampler& s, int n, float lod) {  // the mean of n level-`lod` samples along dx
    glm::vec4 sum(0.0f);
    for (int i = 1; i <= n; ++i)
      sum += s.textures.SampleLod(0, uv + dx * (float(i) / float(n + 1) - 0.5f), lod);
    return sum / float(n);
  };
  t.params.max_anisotropy = 16.0f;  // N = 8: each probe at level 0
  Sampler s16(t);
  CHECK(s16.view.fast == TextureView::Fast::kNone);
  CHECK(s16.textures.Sample(0, uv, dx, dy) == probes(s16, 8, 0.0f));
  t.params.max_anisotropy = 4.0f;  // N = 4: level log2(8 / 4) = 1
  Sampler s4(t);
  CHECK(s4.textures.Sample(0, uv, dx, dy) == probes(s4, 4, 1.0f));
  t.params.max_anisotropy = 100.0f;  // taken as 16
  Sampler s100(t);
  CHECK(s100.view.anisotropy == 16.0f);
  // The footprint along t: the probes follow dy.
  const glm::vec2 long_dy(0.0f, 4.0f / 64.0f), short_dx(1.0f / 64.0f, 0.0f);
  glm::vec4 sum(0.0f);
  for (int i = 1; i <= 4; ++i) sum += s16.textures.SampleLod(0, uv + long_dy * (float(i) / 5.0f - 0.5f), 0.0f);
  CHECK(s16.textures.Sample(0, uv, short_dx, long_dy) == sum / 4.0f);
  // A round footprint is the ordinary trilinear sample.
  t.params.max_anisotropy = 1.0f;
  Sampler plain(t);
  CHECK(s16.textures.Sample(0, uv, dx * 0.25f, glm::vec2(0.0f, 2.0f / 64.0f)) ==
        plain.textures.Sample(0, uv, dx * 0.25f, glm::vec2(0.0f, 2.0f / 64.0f)));
  // The parameter: at least 1, read back as given; the limit is 16.
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.TexParameterf(TEXTURE_2D, TEXTURE_MAX_ANISOTROPY, 8.0f);
  float v = 0.0f;
  gl.GetTexParameterfv(TEXTURE_2D, TEXTURE_MAX_ANISOTROPY, &v);
  CHECK(v == 8.0f);
  gl.TexParameterf(TEXTURE_2D, TEXTURE_MAX_ANISOTROPY, 0.5f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetFloatv(MAX_TEXTURE_MAX_ANISOTROPY, &v);
  CHECK(v == 16.0f);
}

TEST_CASE("anisotropic filtering of a cube map: the probes on the chosen face, as a 2D texture's", "[texture][anisotropic]") {
  // The +x face holds the 2D texture's texels, the other faces others; both mipmapped, anisotropy 16.
  auto texel = [](int i, int j) {
    return glm::vec4(float((i * 7 + j * 3) % 11) / 10.0f, float((i + 2 * j) % 5) / 4.0f, float(i % 3), 1.0f);
  };
  TextureObject flat = MakeTexture(64, 64, texel);
  TextureObject cube;
  cube.target = TEXTURE_CUBE_MAP;
  for (int f = 0; f < 6; ++f) {
    cube.levels[f][0].Allocate(RGBA32F, 64, 64);
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i)
        detail::StoreTexel(cube.levels[f][0], i, j, f == 0 ? texel(i, j) : glm::vec4(float(f), 0.5f, 0.25f, 1.0f));
  }
  for (TextureObject* t : {&flat, &cube}) {
    detail::GenerateMipmaps(*t);
    t->params.min_filter = LINEAR_MIPMAP_LINEAR;
    t->params.mag_filter = LINEAR;
    t->params.wrap_s = t->params.wrap_t = CLAMP_TO_EDGE;
    t->params.max_anisotropy = 16.0f;
  }
  Sampler s2d(flat);
  TextureView cube_view = detail::MakeView(cube);
  REQUIRE(cube_view.complete);
  Textures tx;
  tx.unit_cube[0] = &cube_view;
  // On +x, s = (-z + 1) / 2 and t = (-y + 1) / 2 for x = 1: (s, t) and its derivatives as a direction and its.
  auto dir = [](glm::vec2 st) { return glm::vec3(1.0f, 1.0f - 2.0f * st.y, 1.0f - 2.0f * st.x); };
  auto ddir = [](glm::vec2 d) { return glm::vec3(0.0f, -2.0f * d.y, -2.0f * d.x); };
  const glm::vec2 uv(0.37f, 0.61f);
  const glm::vec2 footprints[3][2] = {{{8.0f / 64, 0}, {0, 1.0f / 64}},           // 8 : 1 along s
                                      {{0.5f / 64, 0}, {0, 3.0f / 64}},           // 6 : 1 along t
                                      {{2.0f / 64, 2.0f / 64}, {-1.0f / 64, 1.0f / 64}}};  // turned, 2 : 1
  for (const auto& fp : footprints) {
    const glm::vec4 want = s2d.textures.Sample(0, uv, fp[0], fp[1]);
    const glm::vec4 got = tx.SampleCube(0, dir(uv), ddir(fp[0]), ddir(fp[1]));
    for (int c = 0; c < 4; ++c) CHECK(got[c] == Approx(want[c]).margin(1e-4));
  }
  // An isotropic cube sample differs from the anisotropic one where the footprint is long.
  cube.params.max_anisotropy = 1.0f;
  TextureView iso = detail::MakeView(cube);
  tx.unit_cube[0] = &iso;
  const glm::vec4 blurred = tx.SampleCube(0, dir(uv), ddir(footprints[0][0]), ddir(footprints[0][1]));
  tx.unit_cube[0] = &cube_view;
  CHECK(blurred != tx.SampleCube(0, dir(uv), ddir(footprints[0][0]), ddir(footprints[0][1])));
}

TEST_CASE("16-bit normalized formats and the UNSIGNED_SHORT and HALF_FLOAT uploads", "[texture][packed]") {
  Context gl(4, 4);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.PixelStore(PACK_ALIGNMENT, 1);
  // R16 from UNSIGNED_SHORT: every value comes back exactly (k / 65535, stored as round(v * 65535)).
  const std::uint16_t shorts[4] = {0, 1, 32768, 65535};
  gl.TexImage2D(TEXTURE_2D, 0, R16, 4, 1, 0, RED, UNSIGNED_SHORT, shorts);
  std::uint16_t back[4] = {9, 9, 9, 9};
  gl.GetTexImage(TEXTURE_2D, 0, RED, UNSIGNED_SHORT, back);
  for (int i = 0; i < 4; ++i) CHECK(back[i] == shorts[i]);
  int bits = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_RED_SIZE, &bits);
  CHECK(bits == 16);
  // RGBA16 from floats: clamped to [0, 1], rounded to 16 bits; sampled as k / 65535.
  const float floats[4] = {0.25f, 1.5f, -1.0f, 0.1f};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16, 1, 1, 0, RGBA, FLOAT, floats);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_SHORT, back);
  CHECK(back[0] == 16384);
  CHECK(back[1] == 65535);
  CHECK(back[2] == 0);
  CHECK(back[3] == 6554);  // 6553.5 rounds to even
  // RGBA16F from HALF_FLOAT: the halves kept bit for bit (1, -2, 65504, the smallest subnormal).
  const std::uint16_t halves[4] = {0x3C00, 0xC000, 0x7BFF, 0x0001};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16F, 1, 1, 0, RGBA, HALF_FLOAT, halves);
  float got[4] = {};
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, got);
  CHECK(got[0] == 1.0f);
  CHECK(got[1] == -2.0f);
  CHECK(got[2] == 65504.0f);
  CHECK(got[3] == std::ldexp(1.0f, -24));
  // RGBA8 from UNSIGNED_SHORT: 65535 is 255, 32768 (0.50001) is 128.
  const std::uint16_t rgba[4] = {65535, 32768, 0, 65535};
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_SHORT, rgba);
  std::uint8_t bytes[4] = {};
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, bytes);
  CHECK((bytes[0] == 255 && bytes[1] == 128 && bytes[2] == 0 && bytes[3] == 255));
  CHECK(gl.GetError() == NO_ERROR);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16, 1, 1, 0, RGBA, 0x1234, rgba);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 1, 1, 0, DEPTH_STENCIL, HALF_FLOAT, rgba);
  CHECK(gl.GetError() == INVALID_ENUM);  // DEPTH_STENCIL with another type (OpenGL 3.3, section 4.3.1)

  // RGBA16 as a render target: a clear, then an additive blend, in float, clamped and rounded to 16 bits.
  const std::uint32_t target = gl.GenTexture(), fbo = gl.GenFramebuffer();
  gl.BindTexture(TEXTURE_2D, target);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16, 4, 4, 0, RGBA, UNSIGNED_SHORT, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, target, 0);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  gl.ClearColor(0.25f, 0.5f, 1.5f, -1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  testing::SolidShader solid;
  solid.color = glm::vec4(0.0001f, 0.25f, 0.0f, 0.5f);
  gl.UseProgram(solid);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.Enable(BLEND);
  gl.BlendFunc(ONE, ONE);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  std::vector<std::uint16_t> px(4 * 4 * 4);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_SHORT, px.data());
  // Red: (16384 / 65535 + 0.0001) * 65535 = 16390.55 -> 16391: finer than 8 bits could hold. Green:
  // 32768 + 0.25 * 65535 = 49151.75 -> 49152.
  CHECK(px[0] == 16391);
  CHECK(px[1] == 49152);
  CHECK(px[2] == 65535);
  CHECK(px[3] == 32768);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("PixelStore: uploads take a sub-rectangle of a larger client image, read-backs write one, bytes swapped",
          "[texture][unpack]") {
  Context gl(1, 1);
  // A 3 x 2 rectangle from (2, 1) of an 8 x 6 RGBA8 image: UNPACK_ROW_LENGTH, _SKIP_PIXELS and _SKIP_ROWS.
  std::vector<std::uint8_t> image(8 * 6 * 4);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i)
      for (int c = 0; c < 4; ++c) image[std::size_t((j * 8 + i) * 4 + c)] = std::uint8_t(c == 0 ? i : c == 1 ? j : c == 2 ? 7 : 255);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.PixelStore(UNPACK_ROW_LENGTH, 8);
  gl.PixelStore(UNPACK_SKIP_PIXELS, 2);
  gl.PixelStore(UNPACK_SKIP_ROWS, 1);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 3, 2, 0, RGBA, UNSIGNED_BYTE, image.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  std::vector<std::uint8_t> texels(3 * 2 * 4);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      CAPTURE(i, j);
      CHECK(int(texels[std::size_t((j * 3 + i) * 4)]) == i + 2);
      CHECK(int(texels[std::size_t((j * 3 + i) * 4 + 1)]) == j + 1);
    }
  // TexSubImage2D takes the same layout: texel (1, 0) from the image's (2, 1).
  gl.TexSubImage2D(TEXTURE_2D, 0, 1, 0, 1, 1, RGBA, UNSIGNED_BYTE, image.data());
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  CHECK((texels[4] == 2 && texels[5] == 1));
  int v[3] = {};
  gl.GetIntegerv(UNPACK_ROW_LENGTH, &v[0]);
  gl.GetIntegerv(UNPACK_SKIP_PIXELS, &v[1]);
  gl.GetIntegerv(UNPACK_SKIP_ROWS, &v[2]);
  CHECK((v[0] == 8 && v[1] == 2 && v[2] == 1));
  gl.PixelStore(UNPACK_ROW_LENGTH, 0);
  gl.PixelStore(UNPACK_SKIP_PIXELS, 0);
  gl.PixelStore(UNPACK_SKIP_ROWS, 0);

  // A 2 x 2 x 2 block from (1, 1, 1) of 4 x 3 x 3 images of 4 rows each: UNPACK_IMAGE_HEIGHT and _SKIP_IMAGES.
  std::vector<std::uint8_t> volume(4 * 4 * 3 * 4, 0);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        std::uint8_t* p = volume.data() + ((k * 4 + j) * 4 + i) * 4;
        p[0] = std::uint8_t(i);
        p[1] = std::uint8_t(j);
        p[2] = std::uint8_t(k);
        p[3] = 255;
      }
  gl.BindTexture(TEXTURE_3D, gl.GenTexture());
  gl.PixelStore(UNPACK_ROW_LENGTH, 4);
  gl.PixelStore(UNPACK_IMAGE_HEIGHT, 4);
  gl.PixelStore(UNPACK_SKIP_IMAGES, 1);
  gl.PixelStore(UNPACK_SKIP_ROWS, 1);
  gl.PixelStore(UNPACK_SKIP_PIXELS, 1);
  gl.TexImage3D(TEXTURE_3D, 0, RGBA8, 2, 2, 2, 0, RGBA, UNSIGNED_BYTE, volume.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  for (const Enum p : {UNPACK_ROW_LENGTH, UNPACK_IMAGE_HEIGHT, UNPACK_SKIP_IMAGES, UNPACK_SKIP_ROWS, UNPACK_SKIP_PIXELS})
    gl.PixelStore(p, 0);
  // Read back as 3 images of 3 rows (PACK_IMAGE_HEIGHT) after one skipped image (PACK_SKIP_IMAGES).
  gl.PixelStore(PACK_IMAGE_HEIGHT, 3);
  gl.PixelStore(PACK_SKIP_IMAGES, 1);
  std::vector<std::uint8_t> out(2 * 3 * 3 * 4, 0xEE);
  gl.GetTexImage(TEXTURE_3D, 0, RGBA, UNSIGNED_BYTE, out.data());
  CHECK(gl.GetError() == NO_ERROR);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        CAPTURE(i, j, k);
        const std::uint8_t* p = out.data() + (((k + 1) * 3 + j) * 2 + i) * 4;
        CHECK((int(p[0]) == i + 1 && int(p[1]) == j + 1 && int(p[2]) == k + 1));
      }
  CHECK(out[0] == 0xEE);                    // the skipped image is left alone
  CHECK(out[(1 * 3 + 2) * 2 * 4] == 0xEE);  // and so is the third row of each image
  gl.PixelStore(PACK_IMAGE_HEIGHT, 0);
  gl.PixelStore(PACK_SKIP_IMAGES, 0);

  // UNPACK_SWAP_BYTES and PACK_SWAP_BYTES: 16-bit and float components written big-endian.
  const std::uint8_t shorts[8] = {0x12, 0x34, 0xAB, 0xCD, 0x00, 0x01, 0xFF, 0xFF};  // 0x1234, 0xABCD, 0x0001, 0xFFFF
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.PixelStore(UNPACK_SWAP_BYTES, 1);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA16, 1, 1, 0, RGBA, UNSIGNED_SHORT, shorts);
  gl.PixelStore(UNPACK_SWAP_BYTES, 0);
  std::uint16_t native[4] = {};
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_SHORT, native);
  CHECK((native[0] == 0x1234 && native[1] == 0xABCD && native[2] == 0x0001 && native[3] == 0xFFFF));
  std::uint8_t swapped[8] = {};
  gl.PixelStore(PACK_SWAP_BYTES, 1);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_SHORT, swapped);
  CHECK(std::memcmp(swapped, shorts, 8) == 0);
  bool flag = false;
  gl.GetBooleanv(PACK_SWAP_BYTES, &flag);
  CHECK(flag);
  gl.PixelStore(PACK_SWAP_BYTES, 0);
  float one_and_half = 1.5f;  // a float's bytes reversed
  std::uint8_t reversed[4];
  std::memcpy(reversed, &one_and_half, 4);
  std::reverse(reversed, reversed + 4);
  gl.PixelStore(UNPACK_SWAP_BYTES, 1);
  gl.TexImage2D(TEXTURE_2D, 0, R32F, 1, 1, 0, RED, FLOAT, reversed);
  gl.PixelStore(UNPACK_SWAP_BYTES, 0);
  float back = 0.0f;
  gl.GetTexImage(TEXTURE_2D, 0, RED, FLOAT, &back);
  CHECK(back == 1.5f);

  // Errors: negative values, names outside the tables.
  gl.PixelStore(UNPACK_ROW_LENGTH, -1);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PixelStore(PACK_SKIP_IMAGES, -3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PixelStore(0x0CF6, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PixelStore(UNPACK_LSB_FIRST, 1);  // accepted and kept: it concerns bitmaps only
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetBooleanv(UNPACK_LSB_FIRST, &flag);
  CHECK(flag);
}

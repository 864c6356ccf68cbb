// Sampler objects (OpenGL 3.3, section 3.8.2): their state replaces the bound textures' sampling state per unit,
// draws keep the state they were recorded with, and the calls give OpenGL's errors and read back what was set.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "helpers.h"

using namespace softgl;

namespace {

struct UvVaryings {
  vec2 uv;
};

// A perspective quad (w from 1 at the bottom to 4 at the top) whose coordinates run past [0, 1] on both sides,
// sampling unit `unit` (texture(sampler2D, uv), or a shadow comparison against 0.5).
struct SampleShader : Shader<SampleShader, UvVaryings> {
  int unit = 0;
  bool shadow = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = vec2(in.attrib[1].x, in.attrib[1].y);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    if (shadow) {
      const Float c = in.TextureShadow(unit, vec3(in.varyings.uv, Float(0.5f)));
      out.color[0] = vec4(c, c, c, Float(1.0f));
    } else {
      out.color[0] = in.Texture(unit, in.varyings.uv);
    }
  }
};

constexpr int kSize = 48;

void DrawQuad(Context& gl) {
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-4, 4, 0, 4}, {4, 4, 0, 4}},
                           {{-0.7f, -0.4f, 0, 0}, {1.6f, -0.4f, 0, 0}, {-0.7f, 2.3f, 0, 0}, {1.6f, 2.3f, 0, 0}});
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
}

// A 16 x 16 texture of random bytes with its mipmaps (RGBA8), or a depth texture of random depths.
std::uint32_t MakeTexture(Context& gl, bool depth = false) {
  std::mt19937 rng(7);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  if (depth) {
    std::vector<float> d(16 * 16);
    for (float& v : d) v = float(rng() % 1000) / 999.0f;
    gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT32F, 16, 16, 0, DEPTH_COMPONENT, FLOAT, d.data());
  } else {
    std::vector<std::uint8_t> texels(16 * 16 * 4);
    for (auto& t : texels) t = std::uint8_t(rng());
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 16, 16, 0, RGBA, UNSIGNED_BYTE, texels.data());
  }
  gl.GenerateMipmap(TEXTURE_2D);
  return tex;
}

// A sampling state, set on a texture (TexParameter) or on a sampler object (SamplerParameter).
struct State {
  Enum min = NEAREST_MIPMAP_LINEAR, mag = LINEAR, wrap_s = REPEAT, wrap_t = REPEAT;
  float bias = 0.0f, min_lod = -1000.0f, max_lod = 1000.0f, anisotropy = 1.0f;
  glm::vec4 border{0.0f};
  Enum compare = NONE, func = LEQUAL;
};
// Sets `s` through `seti(pname, int)`, `setf(pname, float)` and `setfv(pname, const float*)`.
template <class SetI, class SetF, class SetFv>
void Apply(const State& s, SetI seti, SetF setf, SetFv setfv) {
  seti(TEXTURE_MIN_FILTER, int(s.min));
  seti(TEXTURE_MAG_FILTER, int(s.mag));
  seti(TEXTURE_WRAP_S, int(s.wrap_s));
  seti(TEXTURE_WRAP_T, int(s.wrap_t));
  setf(TEXTURE_LOD_BIAS, s.bias);
  setf(TEXTURE_MIN_LOD, s.min_lod);
  setf(TEXTURE_MAX_LOD, s.max_lod);
  setf(TEXTURE_MAX_ANISOTROPY, s.anisotropy);
  setfv(TEXTURE_BORDER_COLOR, &s.border[0]);
  seti(TEXTURE_COMPARE_MODE, int(s.compare));
  seti(TEXTURE_COMPARE_FUNC, int(s.func));
}
void SetOnTexture(Context& gl, const State& s) {
  Apply(s, [&](Enum p, int v) { gl.TexParameteri(TEXTURE_2D, p, v); },
        [&](Enum p, float v) { gl.TexParameterf(TEXTURE_2D, p, v); },
        [&](Enum p, const float* v) { gl.TexParameterfv(TEXTURE_2D, p, v); });
}
void SetOnSampler(Context& gl, std::uint32_t sampler, const State& s) {
  Apply(s, [&](Enum p, int v) { gl.SamplerParameteri(sampler, p, v); },
        [&](Enum p, float v) { gl.SamplerParameterf(sampler, p, v); },
        [&](Enum p, const float* v) { gl.SamplerParameterfv(sampler, p, v); });
}

// The quad drawn with the texture's own state `s` (no sampler object), as RGBA bytes.
std::vector<std::uint8_t> DrawnWithTexture(const State& s, bool depth, int base_level) {
  Context gl(kSize, kSize);
  MakeTexture(gl, depth);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_BASE_LEVEL, base_level);
  SetOnTexture(gl, s);
  SampleShader shader;
  shader.shadow = depth;
  gl.UseProgram(shader);
  DrawQuad(gl);
  REQUIRE(gl.GetError() == NO_ERROR);
  return gl.ReadPixels().rgba;
}

std::vector<State> States() {
  std::vector<State> states;
  State s;
  states.push_back(s);  // the defaults
  s.min = NEAREST;
  s.mag = NEAREST;
  s.wrap_s = CLAMP_TO_EDGE;
  s.wrap_t = MIRRORED_REPEAT;
  states.push_back(s);
  s = State{};
  s.min = LINEAR_MIPMAP_NEAREST;
  s.wrap_s = CLAMP_TO_BORDER;
  s.wrap_t = CLAMP_TO_BORDER;
  s.border = {0.25f, 0.5f, 1.0f, 0.75f};
  s.bias = 1.5f;
  states.push_back(s);
  s = State{};
  s.min = LINEAR_MIPMAP_LINEAR;
  s.min_lod = 1.0f;
  s.max_lod = 2.5f;
  s.anisotropy = 8.0f;
  states.push_back(s);
  s = State{};
  s.min = LINEAR;
  s.wrap_s = MIRRORED_REPEAT;
  s.bias = -2.0f;
  states.push_back(s);
  return states;
}

}  // namespace

TEST_CASE("sampler objects: a bound sampler's state replaces the texture's, its levels staying the texture's",
          "[texture][samplers]") {
  // The texture's own state, set far from each case's, is overridden whole: each case draws the same bytes as the
  // texture set up with that state. The base level (1 in the second pass) stays the texture's.
  State other;
  other.min = NEAREST_MIPMAP_NEAREST;
  other.mag = NEAREST;
  other.wrap_s = other.wrap_t = CLAMP_TO_EDGE;
  other.bias = 3.0f;
  other.border = {1, 0, 0, 1};
  for (int base_level : {0, 1}) {
    for (const State& s : States()) {
      const std::vector<std::uint8_t> expected = DrawnWithTexture(s, false, base_level);
      Context gl(kSize, kSize);
      MakeTexture(gl);
      gl.TexParameteri(TEXTURE_2D, TEXTURE_BASE_LEVEL, base_level);
      SetOnTexture(gl, other);
      const std::uint32_t sampler = gl.GenSampler();
      SetOnSampler(gl, sampler, s);
      gl.BindSampler(0, sampler);
      SampleShader shader;
      gl.UseProgram(shader);
      DrawQuad(gl);
      CHECK(gl.GetError() == NO_ERROR);
      CHECK(gl.ReadPixels().rgba == expected);
      // Unbound, the texture's own state again.
      gl.BindSampler(0, 0);
      DrawQuad(gl);
      CHECK(gl.ReadPixels().rgba == DrawnWithTexture(other, false, base_level));
    }
  }
  // Depth comparison comes from the sampler too.
  State shadow;
  shadow.min = LINEAR;
  shadow.compare = COMPARE_REF_TO_TEXTURE;
  shadow.func = GREATER;
  const std::vector<std::uint8_t> expected = DrawnWithTexture(shadow, true, 0);
  Context gl(kSize, kSize);
  MakeTexture(gl, true);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);  // (no comparison on the texture itself)
  const std::uint32_t sampler = gl.GenSampler();
  SetOnSampler(gl, sampler, shadow);
  gl.BindSampler(0, sampler);
  SampleShader shader;
  shader.shadow = true;
  gl.UseProgram(shader);
  DrawQuad(gl);
  const std::vector<std::uint8_t> drawn = gl.ReadPixels().rgba;
  CHECK(drawn == expected);
  int passed = 0, failed = 0;  // the comparison passes at every texel of some pixels, at none of others
  for (std::size_t i = 0; i < drawn.size(); i += 4) {
    passed += drawn[i] == 255 ? 1 : 0;
    failed += drawn[i] == 0 ? 1 : 0;
  }
  CHECK(passed > 20);
  CHECK(failed > 20);
}

TEST_CASE("sampler objects: completeness follows the sampler's filter; units are independent; draws keep their state",
          "[texture][samplers]") {
  // A 2 x 2 texture without its 1 x 1 level, with the default mipmapping filter, is incomplete (samples (0, 0, 0,
  // 1)); a sampler that does not mipmap makes it complete, on its unit only.
  Context gl(4, 4);
  std::uint8_t red[16];
  for (int k = 0; k < 16; ++k) red[k] = k % 4 == 0 || k % 4 == 3 ? 255 : 0;
  for (int unit : {0, 1}) {
    gl.ActiveTexture(TEXTURE0 + Enum(unit));
    gl.BindTexture(TEXTURE_2D, gl.GenTexture());
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, red);
  }
  const std::uint32_t linear = gl.GenSampler();
  gl.SamplerParameteri(linear, TEXTURE_MIN_FILTER, LINEAR);
  gl.BindSampler(1, linear);
  SampleShader shader;
  gl.UseProgram(shader);
  std::uint8_t px[4];
  for (int unit : {0, 1}) {
    shader.unit = unit;
    DrawQuad(gl);
    gl.ReadPixel(2, 2, px);
    CHECK(int(px[0]) == (unit == 1 ? 255 : 0));
    CHECK(int(px[3]) == 255);
  }
  // A draw keeps the state it was recorded with: the sampler changed, or deleted, before the frame is rendered.
  shader.unit = 1;
  DrawQuad(gl);  // complete: red
  gl.SamplerParameteri(linear, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);  // (incomplete from here)
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == 255);
  gl.SamplerParameteri(linear, TEXTURE_MIN_FILTER, LINEAR);
  DrawQuad(gl);
  gl.DeleteSampler(linear);  // unit 1 has no sampler from here: incomplete again
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == 255);
  DrawQuad(gl);
  gl.ReadPixel(2, 2, px);
  CHECK(int(px[0]) == 0);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("sampler objects: OpenGL's errors, bindings and the state read back", "[texture][samplers][errors]") {
  Context gl(4, 4);
  std::uint32_t ids[3] = {0, 0, 0};
  gl.GenSamplers(3, ids);
  CHECK((ids[0] != 0 && ids[1] != ids[0] && ids[2] != ids[1]));
  CHECK(gl.IsSampler(ids[0]));
  CHECK_FALSE(gl.IsSampler(0));
  CHECK_FALSE(gl.IsSampler(ids[2] + 100));
  gl.GenSamplers(-1, ids);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GenSamplers(2, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.DeleteSamplers(-1, ids);
  CHECK(gl.GetError() == INVALID_VALUE);

  // Bindings: per unit, a number (not TEXTURE0 + i), SAMPLER_BINDING of the active unit.
  gl.BindSampler(kMaxTextureUnits, ids[0]);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BindSampler(-1, ids[0]);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BindSampler(0, ids[2] + 100);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindSampler(0, ids[0]);
  gl.BindSampler(5, ids[0]);
  gl.BindSampler(kMaxTextureUnits - 1, ids[1]);
  CHECK(gl.GetError() == NO_ERROR);
  int bound = -1;
  gl.GetIntegerv(SAMPLER_BINDING, &bound);
  CHECK(bound == int(ids[0]));
  gl.ActiveTexture(TEXTURE0 + kMaxTextureUnits - 1);
  gl.GetIntegerv(SAMPLER_BINDING, &bound);
  CHECK(bound == int(ids[1]));
  gl.ActiveTexture(TEXTURE0 + 3);
  gl.GetIntegerv(SAMPLER_BINDING, &bound);
  CHECK(bound == 0);
  // Deleting unbinds it from every unit; its id is then no sampler.
  gl.DeleteSamplers(1, ids);
  gl.ActiveTexture(TEXTURE0 + 5);
  gl.GetIntegerv(SAMPLER_BINDING, &bound);
  CHECK(bound == 0);
  CHECK_FALSE(gl.IsSampler(ids[0]));
  gl.BindSampler(0, ids[0]);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.DeleteSampler(ids[0]);  // (unknown ids and 0 are ignored)
  gl.DeleteSampler(0);
  CHECK(gl.GetError() == NO_ERROR);

  // Parameters: a sampler's defaults are a texture's.
  const std::uint32_t s = ids[1];
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  for (Enum pname : {TEXTURE_MIN_FILTER, TEXTURE_MAG_FILTER, TEXTURE_WRAP_S, TEXTURE_WRAP_T, TEXTURE_WRAP_R,
                     TEXTURE_MIN_LOD, TEXTURE_MAX_LOD, TEXTURE_LOD_BIAS, TEXTURE_MAX_ANISOTROPY, TEXTURE_COMPARE_MODE,
                     TEXTURE_COMPARE_FUNC, TEXTURE_BORDER_COLOR}) {
    float a[4] = {-9, -9, -9, -9}, b[4] = {-9, -9, -9, -9};
    gl.GetSamplerParameterfv(s, pname, a);
    gl.GetTexParameterfv(TEXTURE_2D, pname, b);
    CHECK(std::vector<float>(a, a + 4) == std::vector<float>(b, b + 4));
  }
  CHECK(gl.GetError() == NO_ERROR);
  // Set and read back in each form.
  gl.SamplerParameteri(s, TEXTURE_WRAP_R, MIRRORED_REPEAT);
  gl.SamplerParameterf(s, TEXTURE_MAX_LOD, 3.5f);
  const int func = NOTEQUAL;
  gl.SamplerParameteriv(s, TEXTURE_COMPARE_FUNC, &func);
  const float aniso = 4.0f;
  gl.SamplerParameterfv(s, TEXTURE_MAX_ANISOTROPY, &aniso);
  int iv = 0;
  float fv = 0.0f;
  gl.GetSamplerParameteriv(s, TEXTURE_WRAP_R, &iv);
  CHECK(iv == int(MIRRORED_REPEAT));
  gl.GetSamplerParameterfv(s, TEXTURE_MAX_LOD, &fv);
  CHECK(fv == 3.5f);
  gl.GetSamplerParameteriv(s, TEXTURE_MAX_LOD, &iv);
  CHECK(iv == 4);  // (rounded)
  gl.GetSamplerParameterIiv(s, TEXTURE_COMPARE_FUNC, &iv);
  CHECK(iv == int(NOTEQUAL));
  gl.GetSamplerParameterfv(s, TEXTURE_MAX_ANISOTROPY, &fv);
  CHECK(fv == 4.0f);
  // The border colour: floats; integers mapped to [-1, 1] and back; the integer forms' numbers as they are.
  const float border_f[4] = {0.25f, -0.5f, 2.0f, 1.0f};
  gl.SamplerParameterfv(s, TEXTURE_BORDER_COLOR, border_f);
  float back_f[4];
  gl.GetSamplerParameterfv(s, TEXTURE_BORDER_COLOR, back_f);
  CHECK(std::vector<float>(back_f, back_f + 4) == std::vector<float>(border_f, border_f + 4));
  const int border_i[4] = {std::numeric_limits<int>::max(), -std::numeric_limits<int>::max(), 0, 1 << 30};
  gl.SamplerParameteriv(s, TEXTURE_BORDER_COLOR, border_i);
  int back_i[4];
  gl.GetSamplerParameteriv(s, TEXTURE_BORDER_COLOR, back_i);
  CHECK(back_i[0] == border_i[0]);
  CHECK(back_i[1] == border_i[1]);
  CHECK(back_i[2] == 0);
  gl.GetSamplerParameterfv(s, TEXTURE_BORDER_COLOR, back_f);
  CHECK(back_f[0] == 1.0f);
  CHECK(back_f[3] == Approx(0.5f).epsilon(1e-6));
  const int numbers[4] = {-5, 7, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
  gl.SamplerParameterIiv(s, TEXTURE_BORDER_COLOR, numbers);
  gl.GetSamplerParameterIiv(s, TEXTURE_BORDER_COLOR, back_i);
  CHECK(std::vector<int>(back_i, back_i + 4) == std::vector<int>(numbers, numbers + 4));
  gl.GetSamplerParameterfv(s, TEXTURE_BORDER_COLOR, back_f);
  CHECK((back_f[0] == -5.0f && back_f[1] == 7.0f));
  const std::uint32_t unumbers[4] = {0xFFFFFFFFu, 3, 0x80000000u, 0};
  gl.SamplerParameterIuiv(s, TEXTURE_BORDER_COLOR, unumbers);
  std::uint32_t back_u[4];
  gl.GetSamplerParameterIuiv(s, TEXTURE_BORDER_COLOR, back_u);
  CHECK(std::vector<std::uint32_t>(back_u, back_u + 4) == std::vector<std::uint32_t>(unumbers, unumbers + 4));
  gl.SamplerParameterfv(s, TEXTURE_BORDER_COLOR, border_f);  // floats again: their integers clamp
  gl.GetSamplerParameterIuiv(s, TEXTURE_BORDER_COLOR, back_u);
  CHECK((back_u[0] == 0 && back_u[1] == 0 && back_u[2] == 2 && back_u[3] == 1));
  gl.SamplerParameterIiv(s, TEXTURE_MAG_FILTER, &func);  // (another name: as SamplerParameteriv)
  CHECK(gl.GetError() == INVALID_ENUM);
  const int nearest = NEAREST;
  gl.SamplerParameterIiv(s, TEXTURE_MAG_FILTER, &nearest);
  gl.GetSamplerParameterIuiv(s, TEXTURE_MAG_FILTER, back_u);
  CHECK(back_u[0] == std::uint32_t(NEAREST));
  CHECK(gl.GetError() == NO_ERROR);

  // Errors: not a sampler; no levels; bad names and values; null pointers. Nothing changes.
  gl.SamplerParameteri(12345, TEXTURE_MIN_FILTER, LINEAR);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetSamplerParameteriv(12345, TEXTURE_MIN_FILTER, &iv);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.SamplerParameteri(s, TEXTURE_BASE_LEVEL, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetSamplerParameteriv(s, TEXTURE_MAX_LEVEL, &iv);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameteri(s, TEXTURE_WRAP_S, LINEAR);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameteri(s, TEXTURE_MIN_FILTER, REPEAT);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameteri(s, TEXTURE_BORDER_COLOR, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameterf(s, TEXTURE_BORDER_COLOR, 0.0f);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameterf(s, TEXTURE_MAX_ANISOTROPY, 0.5f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.SamplerParameterf(s, TEXTURE_MIN_LOD, std::numeric_limits<float>::quiet_NaN());
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.SamplerParameteri(s, TEXTURE_WIDTH, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.SamplerParameterfv(s, TEXTURE_BORDER_COLOR, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.SamplerParameteriv(s, TEXTURE_BORDER_COLOR, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.SamplerParameterIuiv(s, TEXTURE_BORDER_COLOR, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetSamplerParameterfv(s, TEXTURE_MIN_LOD, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetSamplerParameterIiv(s, TEXTURE_MIN_LOD, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetSamplerParameteriv(s, TEXTURE_WRAP_R, &iv);
  CHECK(iv == int(MIRRORED_REPEAT));
  gl.GetSamplerParameterfv(s, TEXTURE_MAX_ANISOTROPY, &fv);
  CHECK(fv == 4.0f);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("TexParameterI*: a texture's border colour kept as integers, other names as TexParameteriv; the errors",
          "[texture][samplers][errors]") {
  Context gl(4, 4);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D_ARRAY, tex);
  const int numbers[4] = {-5, 7, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, numbers);
  int back_i[4] = {0, 0, 0, 0};
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, back_i);
  CHECK(std::vector<int>(back_i, back_i + 4) == std::vector<int>(numbers, numbers + 4));
  float back_f[4];
  gl.GetTexParameterfv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, back_f);
  CHECK((back_f[0] == -5.0f && back_f[1] == 7.0f));  // (sampled as these floats: no integer textures yet)
  const std::uint32_t unumbers[4] = {0xFFFFFFFFu, 3, 0x80000000u, 0};
  gl.TexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, unumbers);
  std::uint32_t back_u[4] = {0, 0, 0, 0};
  gl.GetTexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, back_u);
  CHECK(std::vector<std::uint32_t>(back_u, back_u + 4) == std::vector<std::uint32_t>(unumbers, unumbers + 4));
  const float floats[4] = {0.25f, -3.0f, 2.6f, 1.0f};
  gl.TexParameterfv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, floats);  // floats again: the I queries round and clamp
  gl.GetTexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, back_u);
  CHECK((back_u[0] == 0 && back_u[1] == 0 && back_u[2] == 3 && back_u[3] == 1));
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, back_i);
  CHECK((back_i[0] == 0 && back_i[1] == -3 && back_i[2] == 3 && back_i[3] == 1));
  // Other names, the texture's levels included: as TexParameteriv.
  const int base = 2, nearest = int(NEAREST);
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BASE_LEVEL, &base);
  const std::uint32_t filter = LINEAR_MIPMAP_NEAREST;
  gl.TexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_MIN_FILTER, &filter);
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, &nearest);
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BASE_LEVEL, back_i);
  CHECK(back_i[0] == 2);
  gl.GetTexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_MIN_FILTER, back_u);
  CHECK(back_u[0] == std::uint32_t(LINEAR_MIPMAP_NEAREST));
  int iv = 0;
  gl.GetTexParameteriv(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, &iv);
  CHECK(iv == int(NEAREST));
  CHECK(gl.GetError() == NO_ERROR);

  // Errors, each changing nothing.
  const int bad = 12345;
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, &bad);
  CHECK(gl.GetError() == INVALID_ENUM);
  const int negative = -1;
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BASE_LEVEL, &negative);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexParameterIiv(TEXTURE_2D_MULTISAMPLE, TEXTURE_BORDER_COLOR, numbers);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.TexParameterIuiv(TEXTURE_3D, TEXTURE_BORDER_COLOR, unumbers);  // nothing bound there
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BORDER_COLOR, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexParameterIuiv(TEXTURE_2D_ARRAY, TEXTURE_WIDTH, back_u);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_BASE_LEVEL, back_i);
  gl.GetTexParameterIiv(TEXTURE_2D_ARRAY, TEXTURE_MAG_FILTER, &iv);
  CHECK(back_i[0] == 2);
  CHECK(iv == int(NEAREST));
  CHECK(gl.GetError() == NO_ERROR);
}

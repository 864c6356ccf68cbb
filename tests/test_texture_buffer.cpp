// Buffer textures: texelFetch from a buffer's store in every format TexBuffer takes, what lies outside the store,
// the store as each draw saw it when it was made, fetches in the vertex stage, the wide call against the one-lane
// one, and the state and errors of TexBuffer.
#include <catch2/catch.hpp>

#include <bit>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "helpers.h"
#include "texture.h"

using namespace softgl;
using namespace testing;

namespace {

constexpr int kW = 8, kH = 4;

using NoVary = NoVaryings;
// A full-screen pass writing texelFetch(samplerBuffer on unit 0, x + y * kW + offset) at pixel (x, y); with
// `size_row`, row kH - 1 writes textureSize(samplerBuffer) in red instead.
struct FetchBufferShader : Shader<FetchBufferShader, NoVary> {
  int offset = 0;
  bool size_row = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVary>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVary>& in, FragmentLanesOut& out) const {
    const Int x(in.frag_coord.x), y(in.frag_coord.y);
    out.color[0] = in.TexelFetchBuffer(0, x + y * kW + offset);
    if (size_row) {
      const Float row = select(y == kH - 1, Float(1.0f), Float(0.0f));
      const Float size(float(in.TextureSizeBuffer(0)));
      out.color[0] = out.color[0] * (1.0f - row) + vec4(size, 0.0f, 0.0f, 0.0f) * row;
    }
  }
};

// Points, one a pixel along row 0: vertex i takes its colour from texelFetch(samplerBuffer on unit 0, i) in the
// vertex stage.
struct WideColor {
  vec4 value;
};
struct VertexFetchShader : Shader<VertexFetchShader, WideColor> {
  void Vertex(const VertexLanes& in, VertexLanesOut<WideColor>& out) const {
    out.position = in.attrib[0];
    out.varyings.value = in.TexelFetchBuffer(0, in.vertex_id);
  }
  void Fragment(const FragmentLanes<WideColor>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.value; }
};

// A kW x kH RGBA32F framebuffer object, bound.
struct FloatTarget {
  std::uint32_t fbo, rb;
  explicit FloatTarget(Context& gl) : fbo(gl.GenFramebuffer()), rb(gl.GenRenderbuffer()) {
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, RGBA32F, kW, kH);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    gl.Viewport(0, 0, kW, kH);
  }
};

// A kW x kH context drawing into a FloatTarget, with a texture bound to TEXTURE_BUFFER of unit 0 and a buffer
// bound to the TEXTURE_BUFFER buffer target.
struct BufferFixture {
  Context gl{kW, kH};
  FloatTarget target{gl};
  std::uint32_t tex = gl.GenTexture(), buf = gl.GenBuffer();
  BufferFixture() {
    gl.BindTexture(TEXTURE_BUFFER, tex);
    gl.BindBuffer(TEXTURE_BUFFER, buf);
  }
};

std::vector<glm::vec4> ReadFloats(Context& gl) {
  std::vector<glm::vec4> px(kW * kH);
  gl.ReadPixels(0, 0, kW, kH, RGBA, FLOAT, px.data());
  return px;
}

// The channels of a format TexBuffer takes, and the bytes of each.
int Channels(Enum format) {
  switch (format) {
    case R8: case R16: case R16F: case R32F: return 1;
    case RG8: case RG16: case RG16F: case RG32F: return 2;
    default: return 4;
  }
}
int ChannelBytes(Enum format) {
  switch (format) {
    case R8: case RG8: case RGBA8: return 1;
    case R16: case RG16: case RGBA16: case R16F: case RG16F: case RGBA16F: return 2;
    default: return 4;
  }
}
int TexelBytes(Enum format) { return Channels(format) * ChannelBytes(format); }

// What texel i of a store of `bytes` reads as in `format`, computed from the bytes by the format's definition.
glm::vec4 Expected(Enum format, const std::vector<std::uint8_t>& bytes, int i) {
  const int channels = Channels(format), size = ChannelBytes(format);
  glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
  const std::size_t texel = std::size_t(TexelBytes(format));
  if (i < 0 || (std::size_t(i) + 1) * texel > bytes.size()) {
    v = glm::vec4(0.0f, 0.0f, 0.0f, channels == 4 ? 0.0f : 1.0f);
    return v;
  }
  for (int c = 0; c < channels; ++c) {
    const std::uint8_t* p = bytes.data() + std::size_t(i) * texel + std::size_t(c) * std::size_t(size);
    std::uint16_t h;
    float f;
    switch (format) {
      case R8: case RG8: case RGBA8: v[c] = float(p[0]) / 255.0f; break;
      case R16: case RG16: case RGBA16: std::memcpy(&h, p, 2); v[c] = float(h) / 65535.0f; break;
      case R16F: case RG16F: case RGBA16F: std::memcpy(&h, p, 2); v[c] = detail::HalfToFloat(h); break;
      default: std::memcpy(&f, p, 4); v[c] = f; break;
    }
  }
  return v;
}

bool SameFloat(float a, float b) { return a == b || (a != a && b != b); }
bool SameTexel(const glm::vec4& a, const glm::vec4& b) {
  return SameFloat(a.x, b.x) && SameFloat(a.y, b.y) && SameFloat(a.z, b.z) && SameFloat(a.w, b.w);
}

constexpr Enum kFormats[] = {R8, R16, R16F, R32F, RG8, RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F};

// Bytes whose halves and floats are ordinary numbers: each 16-bit word below 0x7800 (a half below 32768), each
// 32-bit float between -4 and 4.
std::vector<std::uint8_t> StoreBytes(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> bytes(std::size_t(n), 0);
  for (int i = 0; i + 3 < n; i += 4) {
    const float f = std::uniform_real_distribution<float>(-4.0f, 4.0f)(rng);
    std::memcpy(&bytes[std::size_t(i)], &f, 4);
    const std::uint16_t lo = std::uint16_t(rng() % 0x7800);
    if (rng() % 2) std::memcpy(&bytes[std::size_t(i)], &lo, 2);  // some words halves, some the low half of a float
  }
  return bytes;
}

}  // namespace

TEST_CASE_METHOD(BufferFixture, "buffer textures: texelFetch reads the store in every format; zero texels outside it", "[texture][buffer]") {
  const std::vector<std::uint8_t> bytes = StoreBytes(200, 7);  // not a whole number of RGBA32F texels
  gl.BufferData(TEXTURE_BUFFER, std::ptrdiff_t(bytes.size()), bytes.data(), STATIC_DRAW);
  FetchBufferShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  for (const Enum format : kFormats)
    for (const int offset : {-3, 0, 20}) {
      CAPTURE(format, offset);
      gl.TexBuffer(TEXTURE_BUFFER, format, buf);
      shader.offset = offset;
      gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
      const std::vector<glm::vec4> px = ReadFloats(gl);
      for (int i = 0; i < kW * kH; ++i) {
        CAPTURE(i);
        CHECK(SameTexel(px[std::size_t(i)], Expected(format, bytes, i + offset)));
      }
      int width = -1;
      gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_WIDTH, &width);
      CHECK(width == int(bytes.size()) / TexelBytes(format));
    }
  // textureSize: the whole texels of the store.
  gl.TexBuffer(TEXTURE_BUFFER, RGBA32F, buf);
  shader.offset = 0;
  shader.size_row = true;
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  CHECK(ReadFloats(gl)[std::size_t(kW * (kH - 1))].x == 12.0f);  // 200 bytes: 12 texels of 16
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE_METHOD(BufferFixture, "buffer textures: without a buffer every fetch reads (0, 0, 0, 0) and textureSize 0", "[texture][buffer]") {
  const std::vector<std::uint8_t> bytes(64, 0x80);
  gl.BufferData(TEXTURE_BUFFER, 64, bytes.data(), STATIC_DRAW);
  FetchBufferShader shader;
  shader.size_row = true;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  gl.ClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  for (int step = 0; step < 3; ++step) {
    CAPTURE(step);
    if (step == 1) gl.TexBuffer(TEXTURE_BUFFER, R8, buf);
    if (step == 2) gl.TexBuffer(TEXTURE_BUFFER, R8, 0);  // detached again
    gl.Clear(COLOR_BUFFER_BIT);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    const std::vector<glm::vec4> px = ReadFloats(gl);
    if (step == 1) {
      CHECK(px[0] == glm::vec4(128.0f / 255.0f, 0, 0, 1));
      CHECK(px[std::size_t(kW * (kH - 1))].x == 64.0f);
    } else {
      for (const glm::vec4& p : px) CHECK(p == glm::vec4(0.0f));
    }
  }
  // No texture bound to the unit at all: the same.
  gl.BindTexture(TEXTURE_BUFFER, 0);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  for (const glm::vec4& p : ReadFloats(gl)) CHECK(p == glm::vec4(0.0f));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE_METHOD(BufferFixture, "buffer textures: each draw reads the store as it was when the draw was made",
                 "[texture][buffer]") {
  const std::uint32_t other = gl.GenBuffer();
  std::vector<float> values(kW * 4, 1.0f);
  gl.BufferData(TEXTURE_BUFFER, std::ptrdiff_t(values.size() * 4), values.data(), DYNAMIC_DRAW);
  gl.TexBuffer(TEXTURE_BUFFER, R32F, buf);
  FetchBufferShader shader;
  gl.UseProgram(shader);
  // Each draw covers one row (y = k), reading texels k * kW ...; between draws the store changes by each call
  // that writes it, and the draws are recorded, not yet rendered, when it does.
  const auto draw_row = [&](int k) {
    const float y0 = float(k) / kH * 2.0f - 1.0f, y1 = float(k + 1) / kH * 2.0f - 1.0f;
    MakeVertexArray(gl, {{-1, y0, 0, 1}, {1, y0, 0, 1}, {-1, y1, 0, 1}, {1, y1, 0, 1}});
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  };
  draw_row(0);  // all 1
  const std::vector<float> twos(values.size(), 2.0f);
  gl.BufferSubData(TEXTURE_BUFFER, 0, std::ptrdiff_t(twos.size() * 4), twos.data());
  draw_row(1);  // all 2
  float* mapped = static_cast<float*>(gl.MapBufferRange(TEXTURE_BUFFER, 0, std::ptrdiff_t(values.size() * 4), MAP_WRITE_BIT));
  REQUIRE(mapped != nullptr);
  for (std::size_t i = 0; i < values.size(); ++i) mapped[i] = 3.0f;
  gl.UnmapBuffer(TEXTURE_BUFFER);
  draw_row(2);  // all 3
  gl.BindBuffer(COPY_READ_BUFFER, other);
  const std::vector<float> fours(values.size(), 4.0f);
  gl.BufferData(COPY_READ_BUFFER, std::ptrdiff_t(fours.size() * 4), fours.data(), STATIC_DRAW);
  gl.CopyBufferSubData(COPY_READ_BUFFER, TEXTURE_BUFFER, 0, 0, std::ptrdiff_t(fours.size() * 4));
  draw_row(3);  // all 4
  gl.BufferData(TEXTURE_BUFFER, 4, nullptr, STATIC_DRAW);  // a store of one texel, 0
  const std::vector<glm::vec4> px = ReadFloats(gl);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      CAPTURE(x, y);
      CHECK(px[std::size_t(y * kW + x)] == glm::vec4(float(y + 1), 0, 0, 1));
    }
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE_METHOD(BufferFixture, "buffer textures: the vertex stage fetches too", "[texture][buffer]") {
  std::vector<std::uint8_t> rgba(kW * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 7 + 3);
  gl.BufferData(TEXTURE_BUFFER, std::ptrdiff_t(rgba.size()), rgba.data(), STATIC_DRAW);
  gl.TexBuffer(TEXTURE_BUFFER, RGBA8, buf);
  VertexFetchShader shader;
  gl.UseProgram(shader);
  std::vector<glm::vec4> points;
  for (int x = 0; x < kW; ++x) points.push_back(WindowToClip(float(x) + 0.5f, 0.5f, kW, kH));
  MakeVertexArray(gl, points);
  gl.DrawArrays(POINTS, 0, kW);
  const std::vector<glm::vec4> px = ReadFloats(gl);
  for (int x = 0; x < kW; ++x) {
    CAPTURE(x);
    const std::uint8_t* t = &rgba[std::size_t(x) * 4];
    CHECK(px[std::size_t(x)] == glm::vec4(t[0], t[1], t[2], t[3]) / 255.0f);
  }
}

TEST_CASE("buffer textures: the wide fetch gives the one-lane fetch's floats in every lane", "[texture][buffer][wide]") {
  const std::vector<std::uint8_t> bytes = StoreBytes(1000, 11);
  auto store = std::make_shared<const std::vector<std::uint8_t>>(bytes);
  std::mt19937 rng(3);
  for (const Enum format : kFormats) {
    CAPTURE(format);
    detail::TextureObject t;
    t.target = TEXTURE_BUFFER;
    t.buffer_format = format;
    t.buffer_store = store;
    const detail::TextureView view = detail::MakeView(t);
    Textures tx;
    tx.unit_buffer[2] = &view;
    for (int round = 0; round < 20; ++round) {
      int index[16];
      const int special[] = {-1, 0, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), view.buffer_texels - 1,
                             view.buffer_texels};
      for (int l = 0; l < 16; ++l)
        index[l] = l < 6 && round == 0 ? special[l] : int(rng() % 1200) - 100;
      float out[4][16];
      tx.FetchBufferLanes(2, index, out);
      for (int l = 0; l < 16; ++l) {
        CAPTURE(index[l]);
        const glm::vec4 one = tx.FetchBuffer(2, index[l]);
        CHECK(SameTexel(glm::vec4(out[0][l], out[1][l], out[2][l], out[3][l]), one));
        CHECK(SameTexel(one, Expected(format, bytes, index[l])));
      }
    }
    CHECK(tx.SizeBuffer(2) == view.buffer_texels);
    CHECK(tx.SizeBuffer(1) == 0);
    CHECK(tx.FetchBuffer(1, 0) == glm::vec4(0.0f));
    CHECK(tx.FetchBuffer(-5, 0) == glm::vec4(0.0f));
  }
}

TEST_CASE("buffer textures: the wide fetch keeps integer texels' bits, and reads nothing past a small store",
          "[texture][buffer][wide]") {
  // Every integer buffer format over random bytes (NaN patterns among the texels' bits), and stores of 0 to 9
  // bytes of each format (under a 64-bit read): the wide fetch against the one-lane fetch, as bits.
  const Enum formats[] = {R8I,   R8UI,   R16I,   R16UI,  R32I,    R32UI,    RG8I,    RG8UI,    RG16I,   RG16UI,
                          RG32I, RG32UI, RGBA8I, RGBA8UI, RGBA16I, RGBA16UI, RGBA32I, RGBA32UI, R8,      RG16F,
                          RGBA8, R32F};
  std::mt19937 rng(7);
  int compared = 0;
  for (const Enum format : formats) {
    for (int size = 0; size <= 10; ++size) {
      const int bytes = size == 10 ? 997 : size;
      std::vector<std::uint8_t> data(static_cast<std::size_t>(bytes));
      for (std::uint8_t& b : data) b = std::uint8_t(rng());
      detail::TextureObject t;
      t.target = TEXTURE_BUFFER;
      t.buffer_format = format;
      t.buffer_store = std::make_shared<const std::vector<std::uint8_t>>(data);
      const detail::TextureView view = detail::MakeView(t);
      Textures tx;
      tx.unit_buffer[0] = &view;
      for (int round = 0; round < 8; ++round) {
        int index[16];
        for (int l = 0; l < 16; ++l) index[l] = int(rng() % std::uint32_t(view.buffer_texels + 4)) - 2;
        if (round == 0) index[0] = std::numeric_limits<int>::min(), index[1] = std::numeric_limits<int>::max();
        float out[4][16];
        tx.FetchBufferLanes(0, index, out);
        for (int l = 0; l < 16; ++l) {
          const glm::vec4 one = tx.FetchBuffer(0, index[l]);
          for (int c = 0; c < 4; ++c) {
            CAPTURE(format, bytes, index[l], c);
            CHECK(std::bit_cast<std::uint32_t>(out[c][l]) == std::bit_cast<std::uint32_t>(one[c]));
            ++compared;
          }
        }
      }
    }
  }
  CHECK(compared == 22 * 11 * 8 * 64);
}

TEST_CASE("TexBuffer: state queries and OpenGL's errors", "[texture][buffer][errors]") {
  Context gl(kW, kH);
  const std::uint32_t tex = gl.GenTexture(), flat = gl.GenTexture(), buf = gl.GenBuffer(), fbo = gl.GenFramebuffer();
  int v = -1;
  gl.GetIntegerv(MAX_TEXTURE_BUFFER_SIZE, &v);
  CHECK(v == kMaxTextureBufferSize);
  CHECK(v >= 65536);  // OpenGL 3.3's minimum
  // Nothing bound to TEXTURE_BUFFER: INVALID_OPERATION.
  gl.TexBuffer(TEXTURE_BUFFER, R8, buf);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindTexture(TEXTURE_BUFFER, tex);
  gl.BindBuffer(TEXTURE_BUFFER, buf);
  gl.GetIntegerv(TEXTURE_BINDING_BUFFER, &v);
  CHECK(v == int(tex));
  gl.GetIntegerv(TEXTURE_BUFFER, &v);
  CHECK(v == int(buf));
  // A texture no TexBuffer has named: R8, no buffer, no texels.
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(R8));
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_BUFFER_DATA_STORE_BINDING, &v);
  CHECK(v == 0);
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_WIDTH, &v);
  CHECK(v == 0);
  const std::vector<std::uint8_t> bytes(64, 1);
  gl.BufferData(TEXTURE_BUFFER, 64, bytes.data(), STATIC_DRAW);
  gl.TexBuffer(TEXTURE_BUFFER, RGBA8, buf);
  CHECK(gl.GetError() == NO_ERROR);
  const std::pair<Enum, int> levels[] = {{TEXTURE_BUFFER_DATA_STORE_BINDING, int(buf)}, {TEXTURE_INTERNAL_FORMAT, int(RGBA8)},
                                         {TEXTURE_WIDTH, 16}, {TEXTURE_HEIGHT, 1}, {TEXTURE_DEPTH, 1},
                                         {TEXTURE_RED_SIZE, 8}, {TEXTURE_ALPHA_SIZE, 8}, {TEXTURE_DEPTH_SIZE, 0},
                                         {TEXTURE_COMPRESSED, 0}, {TEXTURE_SAMPLES, 0}};
  for (const auto& [pname, want] : levels) {
    CAPTURE(pname);
    v = -7;
    gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, pname, &v);
    CHECK(v == want);
    CHECK(gl.GetError() == NO_ERROR);
  }
  // Bad input.
  v = -7;
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 1, TEXTURE_WIDTH, &v);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(v == -7);
  gl.TexBuffer(TEXTURE_2D, R8, buf);
  CHECK(gl.GetError() == INVALID_ENUM);
  for (const Enum bad : {RGB8, SRGB8_ALPHA8, DEPTH_COMPONENT32F, RGB565, Enum(0), Enum(0xFFFFFFFF)}) {
    gl.TexBuffer(TEXTURE_BUFFER, bad, buf);
    CHECK(gl.GetError() == INVALID_ENUM);
  }
  gl.TexBuffer(TEXTURE_BUFFER, R8, 999);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(RGBA8));  // the failed calls changed nothing
  CheckRefusesLevelsAndSampling(gl, TEXTURE_BUFFER);
  gl.GetTexParameteriv(TEXTURE_BUFFER, TEXTURE_MIN_FILTER, &v);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, tex, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.BindTexture(TEXTURE_2D, flat);
  gl.BindTexture(TEXTURE_BUFFER, flat);  // first bound as 2D
  CHECK(gl.GetError() == INVALID_OPERATION);
  // A deleted buffer's store stays the texture's.
  gl.DeleteBuffer(buf);
  gl.GetIntegerv(TEXTURE_BUFFER, &v);
  CHECK(v == 0);
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_WIDTH, &v);
  CHECK(v == 16);
  gl.GetTexLevelParameteriv(TEXTURE_BUFFER, 0, TEXTURE_BUFFER_DATA_STORE_BINDING, &v);
  CHECK(v == int(buf));
  CHECK(gl.GetError() == NO_ERROR);
}

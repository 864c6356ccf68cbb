// Pixel transfers: OpenGL 3.3's format and type pairs (sections 3.7.2 and 4.3.1-4.3.2, tables 3.2 to 3.5), their
// errors, and each type's conversion, alone and through TexImage2D, GetTexImage and ReadPixels.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <vector>

#include <softgl/softgl.h>

#include "helpers.h"
#include "pixel_transfer.h"

using namespace softgl;
using detail::TransferCall;

namespace {

const Enum kColourFormats[] = {RED, GREEN, BLUE, RG, RGB, BGR, RGBA, BGRA};
const Enum kIntegerFormats[] = {RED_INTEGER, GREEN_INTEGER, BLUE_INTEGER, RG_INTEGER,
                                RGB_INTEGER, BGR_INTEGER,   RGBA_INTEGER, BGRA_INTEGER};
const Enum kPlainTypes[] = {UNSIGNED_BYTE, BYTE, UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT, HALF_FLOAT, FLOAT};
// Table 3.5: each packed type and the formats of its component count.
const Enum kRgbPacked[] = {UNSIGNED_BYTE_3_3_2,          UNSIGNED_BYTE_2_3_3_REV,    UNSIGNED_SHORT_5_6_5,
                           UNSIGNED_SHORT_5_6_5_REV,     UNSIGNED_INT_10F_11F_11F_REV, UNSIGNED_INT_5_9_9_9_REV};
const Enum kRgbaPacked[] = {UNSIGNED_SHORT_4_4_4_4,  UNSIGNED_SHORT_4_4_4_4_REV,  UNSIGNED_SHORT_5_5_5_1,
                            UNSIGNED_SHORT_1_5_5_5_REV, UNSIGNED_INT_8_8_8_8,     UNSIGNED_INT_8_8_8_8_REV,
                            UNSIGNED_INT_10_10_10_2, UNSIGNED_INT_2_10_10_10_REV};
const Enum kDepthStencilTypes[] = {UNSIGNED_INT_24_8, FLOAT_32_UNSIGNED_INT_24_8_REV};

bool InList(Enum v, std::initializer_list<Enum> set) { return std::find(set.begin(), set.end(), v) != set.end(); }
template <std::size_t N>
bool In(Enum v, const Enum (&set)[N]) {
  return std::find(std::begin(set), std::end(set), v) != std::end(set);
}

// The code OpenGL 3.3 gives (format, type), written from the specification's tables, not from the implementation.
Enum Expected(Enum format, Enum type, TransferCall call) {
  const bool format_known = In(format, kColourFormats) || In(format, kIntegerFormats) ||
                            InList(format, {DEPTH_COMPONENT, DEPTH_STENCIL}) ||
                            (format == STENCIL_INDEX && call == TransferCall::kReadPixels);
  const bool type_known = In(type, kPlainTypes) || In(type, kRgbPacked) || In(type, kRgbaPacked) ||
                          In(type, kDepthStencilTypes);
  if (!format_known || !type_known) return INVALID_ENUM;
  if (format == DEPTH_STENCIL) return In(type, kDepthStencilTypes) ? NO_ERROR : INVALID_ENUM;  // section 4.3.1
  if (In(type, kDepthStencilTypes)) return INVALID_OPERATION;
  if (In(type, kRgbPacked) && format != RGB && format != RGB_INTEGER) return INVALID_OPERATION;
  if (In(type, kRgbaPacked) && !InList(format, {RGBA, BGRA, RGBA_INTEGER, BGRA_INTEGER})) return INVALID_OPERATION;
  // Integer data with a float type (section 3.7.2: an integer format goes with an integer or packed type).
  if (In(format, kIntegerFormats) && InList(type, {FLOAT, HALF_FLOAT, UNSIGNED_INT_10F_11F_11F_REV, UNSIGNED_INT_5_9_9_9_REV}))
    return INVALID_OPERATION;
  return NO_ERROR;
}

// Packs c as (format, type) and returns the first `sizeof(T)` bytes as a T.
template <class T>
T Pack(Enum format, Enum type, const glm::vec4& c) {
  std::uint8_t bytes[16] = {};
  detail::PackColor(format, type, c, bytes);
  return detail::LoadUnaligned<T>(bytes);
}

void BindTarget(Context& gl, Enum internal_format, int w, int h) {
  const std::uint32_t fbo = gl.GenFramebuffer(), tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, internal_format, w, h, 0, RGBA, FLOAT, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
}

}  // namespace

TEST_CASE("pixel transfer: every format and type pair gets OpenGL 3.3's code", "[pixel_transfer]") {
  std::vector<Enum> formats(std::begin(kColourFormats), std::end(kColourFormats));
  formats.insert(formats.end(), std::begin(kIntegerFormats), std::end(kIntegerFormats));
  // (and two names of no format: an internal format, and LUMINANCE, which a core profile does not have)
  for (Enum f : {DEPTH_COMPONENT, DEPTH_STENCIL, STENCIL_INDEX, RGBA8, Enum(0), Enum(0x1909)}) formats.push_back(f);
  std::vector<Enum> types(std::begin(kPlainTypes), std::end(kPlainTypes));
  types.insert(types.end(), std::begin(kRgbPacked), std::end(kRgbPacked));
  types.insert(types.end(), std::begin(kRgbaPacked), std::end(kRgbaPacked));
  types.insert(types.end(), std::begin(kDepthStencilTypes), std::end(kDepthStencilTypes));
  for (Enum t : {DOUBLE, INT_2_10_10_10_REV, Enum(0), RGBA}) types.push_back(t);
  for (TransferCall call : {TransferCall::kUnpack, TransferCall::kReadPixels, TransferCall::kGetTexImage}) {
    int accepted = 0;
    for (Enum format : formats)
      for (Enum type : types) {
        INFO("call " << int(call) << " format 0x" << std::hex << format << " type 0x" << type);
        const char* why = "";
        const Enum got = detail::CheckPixelTransfer(format, type, call, why);
        CHECK(got == Expected(format, type, call));
        if (got != NO_ERROR) CHECK(std::strlen(why) > 0);
        accepted += got == NO_ERROR;
      }
    // 8 colour formats x 8 plain types, RGB x 6 packed types, RGBA and BGRA x 8, DEPTH_COMPONENT x 8, DEPTH_STENCIL
    // x 2; the 8 integer formats x the 6 integer types, RGB_INTEGER x the 4 packed ones that are not floats,
    // RGBA_INTEGER and BGRA_INTEGER x 8; and STENCIL_INDEX x 8 for ReadPixels.
    CHECK(accepted == 64 + 6 + 16 + 8 + 2 + 48 + 4 + 16 + (call == TransferCall::kReadPixels ? 8 : 0));
  }
  // Sizes: one packed value a pixel, the plain types a component each.
  CHECK(detail::TransferPixelBytes(RGB, UNSIGNED_SHORT_5_6_5) == 2);
  CHECK(detail::TransferPixelBytes(BGRA, UNSIGNED_INT_2_10_10_10_REV) == 4);
  CHECK(detail::TransferPixelBytes(BGR, SHORT) == 6);
  CHECK(detail::TransferPixelBytes(RGBA, FLOAT) == 16);
  CHECK(detail::TransferPixelBytes(DEPTH_STENCIL, FLOAT_32_UNSIGNED_INT_24_8_REV) == 8);
  CHECK(detail::TransferElementBytes(UNSIGNED_SHORT_5_6_5) == 2);
  CHECK(detail::TransferElementBytes(UNSIGNED_BYTE_3_3_2) == 1);
  CHECK(detail::TransferElementBytes(FLOAT_32_UNSIGNED_INT_24_8_REV) == 4);
  CHECK(detail::TransferElementBytes(HALF_FLOAT) == 2);
}

TEST_CASE("pixel transfer: each type packs as section 4.3.2 says", "[pixel_transfer]") {
  const glm::vec4 c(1.0f, 0.5f, 0.25f, 0.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const glm::vec4 odd(-0.5f, 2.0f, nan, 0.25f);
  SECTION("normalized: clamped, NaN as 0, times 2^b - 1 (unsigned) or 2^(b-1) - 1 (signed), rounded") {
    std::int8_t b[4];
    detail::PackColor(RGBA, BYTE, odd, reinterpret_cast<std::uint8_t*>(b));
    CHECK((b[0] == -64 && b[1] == 127 && b[2] == 0 && b[3] == 32));
    std::int16_t s[4];
    detail::PackColor(RGBA, SHORT, odd, reinterpret_cast<std::uint8_t*>(s));
    CHECK((s[0] == -16384 && s[1] == 32767 && s[2] == 0 && s[3] == 8192));
    std::int32_t i[4];
    detail::PackColor(RGBA, INT, glm::vec4(-2.0f, 1.0f, 0.0f, nan), reinterpret_cast<std::uint8_t*>(i));
    CHECK((i[0] == -2147483647 && i[1] == 2147483647 && i[2] == 0 && i[3] == 0));
    std::uint16_t u[3];
    detail::PackColor(BGR, UNSIGNED_SHORT, c, reinterpret_cast<std::uint8_t*>(u));
    CHECK((u[0] == 16384 && u[1] == 32768 && u[2] == 65535));  // blue first: round(0.25 * 65535) = 16384
    std::uint8_t g = 0;
    detail::PackColor(GREEN, UNSIGNED_BYTE, c, &g);
    CHECK(g == 128);
  }
  SECTION("HALF_FLOAT and FLOAT: the value itself") {
    std::uint16_t h[4];
    detail::PackColor(RGBA, HALF_FLOAT, odd, reinterpret_cast<std::uint8_t*>(h));
    CHECK((h[0] == 0xB800 && h[1] == 0x4000 && h[2] == 0x7E00 && h[3] == 0x3400));
    float f[4];
    detail::PackColor(RGBA, FLOAT, odd, reinterpret_cast<std::uint8_t*>(f));
    CHECK((f[0] == -0.5f && f[1] == 2.0f && std::isnan(f[2]) && f[3] == 0.25f));
  }
  SECTION("packed: the first component in the highest bits, or with _REV the lowest (table 3.5)") {
    CHECK(Pack<std::uint8_t>(RGB, UNSIGNED_BYTE_3_3_2, glm::vec4(1, 0, 1, 1)) == 0xE3);
    CHECK(Pack<std::uint8_t>(RGB, UNSIGNED_BYTE_2_3_3_REV, glm::vec4(1, 0, 1, 1)) == 0xC7);
    CHECK(Pack<std::uint16_t>(RGB, UNSIGNED_SHORT_5_6_5, glm::vec4(1, 0, 0, 1)) == 0xF800);
    CHECK(Pack<std::uint16_t>(RGB, UNSIGNED_SHORT_5_6_5_REV, glm::vec4(1, 0, 0, 1)) == 0x001F);
    CHECK(Pack<std::uint16_t>(RGBA, UNSIGNED_SHORT_4_4_4_4, glm::vec4(1, 0, 0, 0)) == 0xF000);
    CHECK(Pack<std::uint16_t>(RGBA, UNSIGNED_SHORT_4_4_4_4_REV, glm::vec4(1, 0, 0, 0)) == 0x000F);
    CHECK(Pack<std::uint16_t>(RGBA, UNSIGNED_SHORT_5_5_5_1, glm::vec4(0, 0, 0, 1)) == 0x0001);
    CHECK(Pack<std::uint16_t>(RGBA, UNSIGNED_SHORT_1_5_5_5_REV, glm::vec4(1, 0, 0, 1)) == 0x801F);
    CHECK(Pack<std::uint32_t>(RGBA, UNSIGNED_INT_8_8_8_8, c) == 0xFF804000u);
    CHECK(Pack<std::uint32_t>(BGRA, UNSIGNED_INT_8_8_8_8_REV, c) == 0x00FF8040u);  // the bytes B, G, R, A
    CHECK(Pack<std::uint32_t>(RGBA, UNSIGNED_INT_10_10_10_2, glm::vec4(1, 0, 0, 1.0f / 3.0f)) == 0xFFC00001u);
    CHECK(Pack<std::uint32_t>(RGBA, UNSIGNED_INT_2_10_10_10_REV, glm::vec4(1, 0, 0, 1)) == (1023u | 3u << 30));
    // 5_6_5 of (1, 0.5, 0.25): 31, round(31.5) = 32, round(7.75) = 8
    CHECK(Pack<std::uint16_t>(RGB, UNSIGNED_SHORT_5_6_5, c) == (31u << 11 | 32u << 5 | 8u));
  }
  SECTION("the packed floats: 11- and 10-bit unsigned floats, and three mantissas with a shared exponent") {
    // red negative: 0; green 2.0: exponent 16, mantissa 0; blue NaN: the 10-bit NaN (exponent 31, mantissa 1)
    CHECK(Pack<std::uint32_t>(RGB, UNSIGNED_INT_10F_11F_11F_REV, odd) == (1024u << 11 | 993u << 22));
    // (1, 0.5, 0.25): exponent 16 (2^(16 - 15 - 9) = 1 / 256), mantissas 256, 128, 64
    CHECK(Pack<std::uint32_t>(RGB, UNSIGNED_INT_5_9_9_9_REV, c) == (16u << 27 | 64u << 18 | 128u << 9 | 256u));
    CHECK(detail::EncodeRgb9e5(glm::vec3(0.0f)) == 0u);
    CHECK(detail::EncodeRgb9e5(glm::vec3(-1.0f, nan, 0.0f)) == 0u);
    // Clamped to the largest value, 511 / 512 * 2^16; a mantissa that rounds up to 512 takes the next exponent.
    CHECK(detail::DecodeRgb9e5(detail::EncodeRgb9e5(glm::vec3(1e30f, 0, 0))) == glm::vec3(65408.0f, 0, 0));
    CHECK(detail::DecodeRgb9e5(detail::EncodeRgb9e5(glm::vec3(511.9f, 0, 0))) == glm::vec3(512.0f, 0, 0));
  }
  SECTION("stencil indices are masked to the type; depth and stencil pack together") {
    std::uint8_t bytes[8] = {};
    detail::PackStencil(BYTE, 200, bytes);
    CHECK(bytes[0] == 200);
    detail::PackStencil(HALF_FLOAT, 200, bytes);
    CHECK(detail::LoadUnaligned<std::uint16_t>(bytes) == 0x5A40);
    detail::PackStencil(FLOAT, 200, bytes);
    CHECK(detail::LoadUnaligned<float>(bytes) == 200.0f);
    detail::PackDepthStencil(UNSIGNED_INT_24_8, 0.75f, 7, bytes);
    CHECK(detail::LoadUnaligned<std::uint32_t>(bytes) == (std::uint32_t(std::llround(0.75 * 16777215.0)) << 8 | 7u));
    detail::PackDepthStencil(FLOAT_32_UNSIGNED_INT_24_8_REV, nan, 3, bytes);
    CHECK(detail::LoadUnaligned<float>(bytes) == 0.0f);
    CHECK(detail::LoadUnaligned<std::uint32_t>(bytes + 4) == 3u);
  }
}

TEST_CASE("pixel transfer: each type unpacks as table 3.2 and section 3.7.2 say, and packs back", "[pixel_transfer]") {
  const std::uint8_t bgr[3] = {10, 20, 30};
  CHECK(detail::UnpackColor(BGR, UNSIGNED_BYTE, bgr) == glm::vec4(30.0f / 255, 20.0f / 255, 10.0f / 255, 1.0f));
  const std::int8_t green[1] = {-128};
  CHECK(detail::UnpackColor(GREEN, BYTE, reinterpret_cast<const std::uint8_t*>(green)) == glm::vec4(0, -1, 0, 1));
  const std::int32_t ints[2] = {2147483647, -2147483647 - 1};
  CHECK(detail::UnpackColor(RG, INT, reinterpret_cast<const std::uint8_t*>(ints)) == glm::vec4(1, -1, 0, 1));
  const std::uint16_t f565 = 0xF800 | 16u << 5;  // red 31, green 16 of 63
  const glm::vec4 v = detail::UnpackColor(RGB, UNSIGNED_SHORT_5_6_5, reinterpret_cast<const std::uint8_t*>(&f565));
  CHECK(v == glm::vec4(1.0f, float(16.0 / 63.0), 0.0f, 1.0f));
  // Every packed type: a colour on its own grid packs and unpacks to itself.
  for (Enum type : kRgbaPacked) {
    INFO("type 0x" << std::hex << type);
    for (Enum format : {RGBA, BGRA}) {
      const glm::vec4 in(1.0f, 0.0f, 1.0f, 0.0f);
      std::uint8_t bytes[4] = {};
      detail::PackColor(format, type, in, bytes);
      CHECK(detail::UnpackColor(format, type, bytes) == in);
    }
  }
  for (Enum type : kRgbPacked) {
    INFO("type 0x" << std::hex << type);
    const glm::vec4 in(1.0f, 0.0f, 1.0f, 1.0f);
    std::uint8_t bytes[4] = {};
    detail::PackColor(RGB, type, in, bytes);
    CHECK(detail::UnpackColor(RGB, type, bytes) == in);
  }
  float depth = 0;
  std::uint8_t stencil = 0;
  const std::uint32_t word = 0xFFFFFF00u | 42u;
  detail::UnpackDepthStencil(UNSIGNED_INT_24_8, reinterpret_cast<const std::uint8_t*>(&word), depth, stencil);
  CHECK((depth == 1.0f && stencil == 42));
}

TEST_CASE("pixel transfer: ReadPixels in every type from fixed-point and float buffers", "[pixel_transfer][context]") {
  SECTION("an RGBA8 buffer holding (255, 128, 64, 0)") {
    Context gl(2, 2);
    gl.ClearColor(1.0f, 0.5f, 0.25f, 0.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    std::int8_t b[4] = {};
    gl.ReadPixels(0, 0, 1, 1, RGBA, BYTE, b);
    CHECK((b[0] == 127 && b[1] == 64 && b[2] == 32 && b[3] == 0));
    std::int16_t s[3] = {};
    gl.ReadPixels(0, 0, 1, 1, BGR, SHORT, s);
    CHECK((s[0] == 8224 && s[1] == 16448 && s[2] == 32767));
    std::uint16_t packed16 = 0;
    gl.ReadPixels(0, 0, 1, 1, RGB, UNSIGNED_SHORT_5_6_5, &packed16);
    CHECK(packed16 == (31u << 11 | 32u << 5 | 8u));
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_SHORT_4_4_4_4, &packed16);
    CHECK(packed16 == (15u << 12 | 8u << 8 | 4u << 4));
    std::uint32_t packed32 = 0;
    gl.ReadPixels(0, 0, 1, 1, BGRA, UNSIGNED_INT_8_8_8_8_REV, &packed32);
    CHECK(packed32 == (64u | 128u << 8 | 255u << 16));
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_INT_2_10_10_10_REV, &packed32);
    CHECK(packed32 == (1023u | 514u << 10 | 257u << 20));
    CHECK(gl.GetError() == NO_ERROR);
  }
  SECTION("an RGBA32F buffer holding (-0.5, 2, NaN, 0.25)") {
    Context gl(2, 2);
    BindTarget(gl, RGBA32F, 2, 2);
    gl.ClearColor(-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 0.25f);
    gl.Clear(COLOR_BUFFER_BIT);
    std::int8_t b[4] = {};
    gl.ReadPixels(1, 1, 1, 1, RGBA, BYTE, b);
    CHECK((b[0] == -64 && b[1] == 127 && b[2] == 0 && b[3] == 32));
    std::uint16_t h[4] = {};
    gl.ReadPixels(1, 1, 1, 1, RGBA, HALF_FLOAT, h);
    CHECK((h[0] == 0xB800 && h[1] == 0x4000 && h[2] == 0x7E00 && h[3] == 0x3400));
    std::uint32_t w = 0;
    gl.ReadPixels(1, 1, 1, 1, RGB, UNSIGNED_INT_10F_11F_11F_REV, &w);
    CHECK(w == (1024u << 11 | 993u << 22));
    gl.ReadPixels(1, 1, 1, 1, RGB, UNSIGNED_INT_5_9_9_9_REV, &w);
    CHECK(w == (17u << 27 | 256u << 9));  // green 2.0 = 256 * 2^(17 - 24); red and blue 0
    CHECK(gl.GetError() == NO_ERROR);
  }
  SECTION("rows of a packed type are aligned by its whole value, and PACK_SWAP_BYTES reverses it") {
    Context gl(3, 2);
    gl.ClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    std::vector<std::uint16_t> out(8, 0xABCD);  // 3 pixels of 2 bytes, rows of 8 bytes (PACK_ALIGNMENT 4)
    gl.ReadPixels(0, 0, 3, 2, RGB, UNSIGNED_SHORT_5_6_5, out.data());
    CHECK(out == std::vector<std::uint16_t>{0xF800, 0xF800, 0xF800, 0xABCD, 0xF800, 0xF800, 0xF800, 0xABCD});
    gl.PixelStore(PACK_SWAP_BYTES, 1);
    gl.ReadPixels(0, 0, 1, 1, RGB, UNSIGNED_SHORT_5_6_5, out.data());
    CHECK(out[0] == 0x00F8);
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("pixel transfer: ReadPixels by rows gives GetTexImage's bytes for every colour format, format and type",
          "[pixel_transfer][context][formats]") {
  // ReadPixels converts a row at a time; GetTexImage reads the same texture level pixel by pixel (Texel, then
  // PackColor). Both give the stored values (no sRGB decoding), so the bytes must agree for every pair.
  const Enum internal_formats[] = {RGBA8,   RGB8,    RG8,     R8,      SRGB8_ALPHA8,   SRGB8,  RGBA32F,
                                   RG32F,   R32F,    RGBA16F, RG16F,   R16F,           R11F_G11F_B10F,
                                   RGB565,  RGBA4,   RGB5_A1, RGB10_A2, RGBA16,        RG16,   R16};
  constexpr int kW = 13, kH = 5;
  std::vector<float> texels(std::size_t(kW) * kH * 4);
  std::uint32_t seed = 3;
  for (float& v : texels) v = float(int((seed = seed * 1664525u + 1013904223u) >> 20) % 2201 - 600) / 1000.0f;
  texels[0] = 0.0f, texels[1] = 1.0f, texels[2] = 0.5f, texels[3] = 1.0f / 255.0f;
  int compared = 0;
  for (const Enum internal : internal_formats) {
    Context gl(1, 1);
    BindTarget(gl, internal, kW, kH);
    gl.TexImage2D(TEXTURE_2D, 0, internal, kW, kH, 0, RGBA, FLOAT, texels.data());
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    std::vector<std::pair<Enum, Enum>> pairs;
    for (const Enum format : kColourFormats) {
      for (const Enum type : kPlainTypes) pairs.push_back({format, type});
      for (const Enum type : kRgbPacked) pairs.push_back({format, type});
      for (const Enum type : kRgbaPacked) pairs.push_back({format, type});
    }
    for (const auto& [format, type] : pairs) {
      const char* why = "";
      if (detail::CheckPixelTransfer(format, type, TransferCall::kReadPixels, why) != NO_ERROR ||
          detail::CheckPixelTransfer(format, type, TransferCall::kGetTexImage, why) != NO_ERROR)
        continue;
      for (const bool swap : {false, true}) {
        gl.PixelStore(PACK_SWAP_BYTES, swap ? 1 : 0);
        const std::size_t pixel = detail::TransferPixelBytes(format, type), element = detail::TransferElementBytes(type);
        auto stride = [&](int w) {
          const std::size_t row = std::size_t(w) * pixel;
          return element < 4 ? (row + 3) / 4 * 4 : row;
        };
        std::vector<std::uint8_t> whole(stride(kW) * kH, 0xA5), read = whole;
        gl.GetTexImage(TEXTURE_2D, 0, format, type, whole.data());
        gl.ReadPixels(0, 0, kW, kH, format, type, read.data());
        // A rectangle inside, 8 x 3 from (2, 1), and one past the corner (only its inside pixels written).
        std::vector<std::uint8_t> part(stride(8) * 3, 0x5A), corner(stride(4) * 3, 0x5A);
        gl.ReadPixels(2, 1, 8, 3, format, type, part.data());
        gl.ReadPixels(kW - 2, kH - 1, 4, 3, format, type, corner.data());
        REQUIRE(gl.GetError() == NO_ERROR);
        bool same = read == whole;
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 4; ++i) {
            const std::uint8_t* got = corner.data() + std::size_t(j) * stride(4) + std::size_t(i) * pixel;
            const bool inside = i < 2 && j < 1;
            const std::size_t want = inside ? std::size_t(kH - 1 + j) * stride(kW) + std::size_t(kW - 2 + i) * pixel : 0;
            for (std::size_t k = 0; k < pixel; ++k) same = same && got[k] == (inside ? whole[want + k] : 0x5A);
          }
        for (int j = 0; j < 3; ++j)
          same = same && std::equal(part.begin() + std::ptrdiff_t(std::size_t(j) * stride(8)),
                                    part.begin() + std::ptrdiff_t(std::size_t(j) * stride(8) + 8 * pixel),
                                    whole.begin() + std::ptrdiff_t(std::size_t(1 + j) * stride(kW) + 2 * pixel));
        INFO("internal format " << std::hex << internal << ", format " << format << ", type " << type
                                << (swap ? ", swapped" : ""));
        CHECK(same);
        ++compared;
      }
    }
  }
  CHECK(compared > 20 * 2 * 60);
}

TEST_CASE("pixel transfer: CopyTexImage2D by rows gives the read buffer's values, zero outside it",
          "[pixel_transfer][context][formats]") {
  // The source is a texture attached for reading; its values as GetTexImage gives them (texel by texel) are what
  // the copy must hold, in an RGBA32F texture that keeps every float.
  constexpr int kW = 9, kH = 5;
  std::vector<float> texels(std::size_t(kW) * kH * 4);
  std::uint32_t seed = 5;
  for (float& v : texels) v = float(int((seed = seed * 1664525u + 1013904223u) >> 20) % 1601 - 300) / 1000.0f;
  for (const Enum internal : {RGBA8, SRGB8_ALPHA8, RGB8, RGBA16F, RGB565, R11F_G11F_B10F, RG32F}) {
    Context gl(1, 1);
    BindTarget(gl, internal, kW, kH);
    gl.TexImage2D(TEXTURE_2D, 0, internal, kW, kH, 0, RGBA, FLOAT, texels.data());
    REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
    std::vector<float> source(texels.size());
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, source.data());
    gl.BindTexture(TEXTURE_2D, gl.GenTexture());
    // A 6 x 4 rectangle from (-2, 3), past the left and top edges, and a 5 x 3 one from (6, -1), past the right
    // and bottom ones.
    bool same = true;
    for (const auto& [x0, y0, w, h] : {std::array<int, 4>{-2, 3, 6, 4}, std::array<int, 4>{6, -1, 5, 3}}) {
      gl.CopyTexImage2D(TEXTURE_2D, 0, RGBA32F, x0, y0, w, h, 0);
      std::vector<float> copy(std::size_t(w * h * 4), -7.0f);
      gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, copy.data());
      CHECK(gl.GetError() == NO_ERROR);
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
          for (int c = 0; c < 4; ++c) {
            const int x = x0 + i, y = y0 + j;
            const bool inside = x >= 0 && y >= 0 && x < kW && y < kH;
            const float want = inside ? source[std::size_t((y * kW + x) * 4 + c)] : 0.0f;
            same = same && copy[std::size_t((j * w + i) * 4 + c)] == want;
          }
    }
    INFO("internal format " << std::hex << internal);
    CHECK(same);
  }
}

TEST_CASE("pixel transfer: ReadPixels() gives each pixel's ReadPixel bytes, top row first, in every context format",
          "[pixel_transfer][context]") {
  for (const Enum colour : {RGBA8, SRGB8_ALPHA8, RGB565})
    for (const int samples : {0, 4}) {
      Context::Options options;
      options.color_format = colour;
      options.samples = samples;
      options.threads = 1;
      Context gl(11, 6, options);
      // Four quarters of different colours, and a clipped triangle whose edge leaves partly covered pixels.
      const glm::vec4 colours[4] = {{0.1f, 0.9f, 0.3f, 0.6f}, {1.0f, 0.5f, 0.0f, 1.0f}, {0.3f, 0.3f, 0.8f, 0.2f},
                                    {0.0f, 0.0f, 0.0f, 0.0f}};
      gl.Enable(SCISSOR_TEST);
      for (int q = 0; q < 4; ++q) {
        gl.Scissor((q % 2) * 5, (q / 2) * 3, 6, 3);
        gl.ClearColor(colours[q].r, colours[q].g, colours[q].b, colours[q].a);
        gl.Clear(COLOR_BUFFER_BIT);
      }
      gl.Disable(SCISSOR_TEST);
      testing::SolidShader shader;
      shader.color = glm::vec4(0.95f, 0.05f, 0.6f, 0.7f);
      gl.UseProgram(shader);
      testing::MakeVertexArray(gl, {{-1.0f, -1.0f, 0, 1}, {0.9f, -0.7f, 0, 1}, {-0.6f, 0.95f, 0, 1}});
      gl.DrawArrays(TRIANGLES, 0, 3);
      const Image image = gl.ReadPixels();
      REQUIRE((image.width == 11 && image.height == 6));
      bool same = true;
      for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 11; ++x) {
          std::uint8_t want[4];
          gl.ReadPixel(x, y, want);
          same = same && std::equal(want, want + 4, image.rgba.begin() + std::ptrdiff_t(((5 - y) * 11 + x) * 4));
        }
      INFO("colour format " << std::hex << colour << std::dec << ", " << samples << " samples");
      CHECK(same);
      CHECK(gl.GetError() == NO_ERROR);
    }
}

TEST_CASE("pixel transfer: TexImage2D takes every type and GetTexImage gives it back", "[pixel_transfer][texture]") {
  Context gl(1, 1);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  SECTION("5_6_5 into RGBA8") {
    const std::uint16_t texels[2] = {0xF800, 16u << 5};  // (rows aligned: 4 bytes a row of 2 pixels)
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 1, 0, RGB, UNSIGNED_SHORT_5_6_5, texels);
    std::uint8_t out[8] = {};
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, out);
    CHECK(std::vector<std::uint8_t>(out, out + 8) == std::vector<std::uint8_t>{255, 0, 0, 255, 0, 65, 0, 255});
  }
  SECTION("BGRA, GREEN and signed bytes into RGBA8; signed shorts into RGBA32F keep -1") {
    const std::uint8_t bgra[4] = {10, 20, 30, 40};
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, BGRA, UNSIGNED_BYTE, bgra);
    std::uint8_t out[4] = {};
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, out);
    CHECK((out[0] == 30 && out[1] == 20 && out[2] == 10 && out[3] == 40));
    const std::uint8_t g = 77;
    gl.PixelStore(UNPACK_ALIGNMENT, 1);
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, GREEN, UNSIGNED_BYTE, &g);
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, out);
    CHECK((out[0] == 0 && out[1] == 77 && out[2] == 0 && out[3] == 255));
    const std::int8_t sb[4] = {-128, 127, 64, 0};
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, BYTE, sb);
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, out);
    CHECK((out[0] == 0 && out[1] == 255 && out[2] == 129 && out[3] == 0));  // -1 clamps; 64 / 127 * 255 = 128.5
    const std::int16_t ss[4] = {-32768, -32767, 32767, 0};
    gl.TexImage2D(TEXTURE_2D, 0, RGBA32F, 1, 1, 0, RGBA, SHORT, ss);
    float f[4] = {};
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, f);
    CHECK((f[0] == -1.0f && f[1] == -1.0f && f[2] == 1.0f && f[3] == 0.0f));
  }
  SECTION("2_10_10_10_REV through RGBA16 and 10F_11F_11F_REV through R11F_G11F_B10F come back bit for bit") {
    const std::uint32_t words[2] = {1u | 511u << 10 | 1000u << 20 | 2u << 30, 1023u << 20};
    gl.TexImage2D(TEXTURE_2D, 0, RGBA16, 2, 1, 0, RGBA, UNSIGNED_INT_2_10_10_10_REV, words);
    std::uint32_t back[2] = {};
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_INT_2_10_10_10_REV, back);
    CHECK((back[0] == words[0] && back[1] == words[1]));
    const std::uint32_t floats[2] = {1024u << 11 | 600u << 22, 77u | 1983u << 11};  // (0, 2.0, ...), (...)
    gl.TexImage2D(TEXTURE_2D, 0, R11F_G11F_B10F, 2, 1, 0, RGB, UNSIGNED_INT_10F_11F_11F_REV, floats);
    gl.GetTexImage(TEXTURE_2D, 0, RGB, UNSIGNED_INT_10F_11F_11F_REV, back);
    CHECK((back[0] == floats[0] && back[1] == floats[1]));
  }
  SECTION("the codes of the mismatched pairs") {
    const std::uint32_t word = 0;
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGB, UNSIGNED_SHORT_4_4_4_4, &word);
    CHECK(gl.GetError() == INVALID_OPERATION);  // table 3.5: 4_4_4_4 holds RGBA or BGRA
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA_INTEGER, UNSIGNED_BYTE, &word);
    CHECK(gl.GetError() == INVALID_OPERATION);  // integer data into a normalized format
    gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT24, 1, 1, 0, DEPTH_COMPONENT, UNSIGNED_SHORT_5_6_5, &word);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 1, 1, 0, DEPTH_STENCIL, UNSIGNED_INT, &word);
    CHECK(gl.GetError() == INVALID_ENUM);  // section 4.3.1: DEPTH_STENCIL with another type
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, STENCIL_INDEX, UNSIGNED_BYTE, &word);
    CHECK(gl.GetError() == INVALID_ENUM);  // not a TexImage format in OpenGL 3.3
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, DOUBLE, &word);
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_BYTE, &word);
    std::uint32_t out = 0;
    gl.GetTexImage(TEXTURE_2D, 0, STENCIL_INDEX, UNSIGNED_BYTE, &out);
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.GetTexImage(TEXTURE_2D, 0, BGR, UNSIGNED_INT_5_9_9_9_REV, &out);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.GetTexImage(TEXTURE_2D, 0, BGRA_INTEGER, UNSIGNED_INT_8_8_8_8, &out);
    CHECK(gl.GetError() == INVALID_OPERATION);  // integer data from a normalized texture
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_SHORT_5_6_5, &out);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.ReadPixels(0, 0, 1, 1, RED_INTEGER, FLOAT, &out);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.ReadPixels(0, 0, 1, 1, DEPTH_STENCIL, UNSIGNED_SHORT, &out);
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.ReadPixels(0, 0, -1, 1, RGB, UNSIGNED_SHORT_4_4_4_4, &out);
    CHECK(gl.GetError() == INVALID_VALUE);  // (one of the two errors; both would be right)
  }
}

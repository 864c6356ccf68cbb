// Compressed textures: each block kind decoded to the values texture_compression.h states, CompressedTexImage2D /
// 3D and CompressedTexSubImage2D through the context (partial blocks, read back decoded and compressed), the level
// state, completeness, and what softgl answers where it would have to compress (TexImage*, TexSubImage*,
// GenerateMipmap, rendering into one). Mesa's decodes and errors are compared by the conformance suite.
#include <catch2/catch.hpp>

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <softgl/softgl.h>

#include "texture.h"
#include "texture_compression.h"

using namespace softgl;

namespace {

std::vector<std::uint8_t> Bytes(std::initializer_list<int> v) {
  std::vector<std::uint8_t> out;
  for (int x : v) out.push_back(std::uint8_t(x));
  return out;
}

// The 16 texels of one block of `format`.
struct Decoded {
  float t[16][4];
};
Decoded Decode(Enum format, const std::vector<std::uint8_t>& block) {
  const detail::CompressedFormat* f = detail::CompressedFormatOf(format);
  REQUIRE(f != nullptr);
  REQUIRE(block.size() == std::size_t(f->block_bytes));
  Decoded d;
  detail::DecodeBlock(*f, block.data(), d.t);
  return d;
}

// A DXT1 colour block: c0 pure red, c1 pure blue (c0 > c1: four colours), texels 0..3 indices 0..3, the rest 0.
const std::vector<std::uint8_t> kFourColours = Bytes({0x00, 0xF8, 0x1F, 0x00, 0xE4, 0, 0, 0});
// The same colours swapped (c0 < c1: three colours and black).
const std::vector<std::uint8_t> kThreeColours = Bytes({0x1F, 0x00, 0x00, 0xF8, 0xE4, 0, 0, 0});

}  // namespace

TEST_CASE("S3TC colour blocks decode to their endpoints and 8-bit mixes", "[compression]") {
  const Decoded four = Decode(COMPRESSED_RGB_S3TC_DXT1_EXT, kFourColours);
  auto rgba = [](const Decoded& d, int t) {
    return std::vector<float>{d.t[t][0], d.t[t][1], d.t[t][2], d.t[t][3]};
  };
  CHECK(rgba(four, 0) == std::vector<float>{255, 0, 0, 255});
  CHECK(rgba(four, 1) == std::vector<float>{0, 0, 255, 255});
  // A third of the way: weight floor(255 / 3) = 85 of 256, rounded down: 255 * 171 / 256 = 170.3, 255 * 85 / 256 = 84.7.
  CHECK(rgba(four, 2) == std::vector<float>{170, 0, 84, 255});
  CHECK(rgba(four, 3) == std::vector<float>{85, 0, 169, 255});
  CHECK(rgba(four, 4) == rgba(four, 0));
  const Decoded three = Decode(COMPRESSED_RGBA_S3TC_DXT1_EXT, kThreeColours);
  CHECK(rgba(three, 0) == std::vector<float>{0, 0, 255, 255});
  CHECK(rgba(three, 2) == std::vector<float>{128, 0, 128, 255});  // (0 + 255 + 1) / 2
  CHECK(rgba(three, 3) == std::vector<float>{0, 0, 0, 0});        // transparent black
  CHECK(Decode(COMPRESSED_RGB_S3TC_DXT1_EXT, kThreeColours).t[3][3] == 255.0f);  // opaque without the alpha form

  // DXT3 and DXT5 always take four colours, whatever the order of c0 and c1.
  std::vector<std::uint8_t> dxt3 = Bytes({0xF0, 0x08, 0, 0, 0, 0, 0, 0});
  dxt3.insert(dxt3.end(), kThreeColours.begin(), kThreeColours.end());
  const Decoded d3 = Decode(COMPRESSED_RGBA_S3TC_DXT3_EXT, dxt3);
  CHECK(d3.t[0][3] == 0.0f);
  CHECK(d3.t[1][3] == 255.0f);  // nibble 15
  CHECK(d3.t[2][3] == 136.0f);  // nibble 8: 0x88
  CHECK(rgba(d3, 2) == std::vector<float>{84, 0, 170, 136});
  CHECK(d3.t[3][0] == 169.0f);
  CHECK(d3.t[3][2] == 85.0f);
}

TEST_CASE("alpha and RGTC blocks: eight values or six and the extremes, unsigned and signed", "[compression]") {
  // Indices 0..7 in texels 0..7: bits 3t.
  auto block = [](int a0, int a1) {
    std::uint64_t bits = 0;
    for (int t = 0; t < 8; ++t) bits |= std::uint64_t(t) << (3 * t);
    std::vector<std::uint8_t> b = {std::uint8_t(a0), std::uint8_t(a1)};
    for (int k = 0; k < 6; ++k) b.push_back(std::uint8_t(bits >> (8 * k)));
    return b;
  };
  const Decoded eight = Decode(COMPRESSED_RED_RGTC1, block(255, 0));
  const float want8[8] = {255, 0, 219, 183, 146, 110, 73, 37};  // 255 (256 - w) / 256, w = floor(255 k / 7)
  for (int t = 0; t < 8; ++t) CHECK(eight.t[t][0] == want8[t]);
  CHECK(eight.t[0][1] == 0.0f);
  CHECK(eight.t[0][3] == 255.0f);
  const Decoded six = Decode(COMPRESSED_RED_RGTC1, block(0, 255));
  const float want6[8] = {0, 255, 50, 101, 152, 203, 0, 255};
  for (int t = 0; t < 8; ++t) CHECK(six.t[t][0] == want6[t]);

  std::vector<std::uint8_t> dxt5 = block(255, 0);
  dxt5.insert(dxt5.end(), kFourColours.begin(), kFourColours.end());
  const Decoded d5 = Decode(COMPRESSED_RGBA_S3TC_DXT5_EXT, dxt5);
  for (int t = 0; t < 8; ++t) CHECK(d5.t[t][3] == want8[t]);

  // Signed: 127 and -128 (read as -127: both -1), eight values; six values with -127 and 127 as the extremes.
  const Decoded s8 = Decode(COMPRESSED_SIGNED_RED_RGTC1, block(127, 0x80));
  CHECK(s8.t[0][0] == 1.0f);
  CHECK(s8.t[1][0] == -1.0f);
  CHECK(s8.t[7][0] == -91.0f / 127.0f);  // (127 * 38 - 128 * 218) / 256 = -90.1, rounded down
  CHECK(s8.t[0][3] == 1.0f);
  const Decoded s6 = Decode(COMPRESSED_SIGNED_RED_RGTC1, block(0, 100));
  CHECK(s6.t[6][0] == -1.0f);
  CHECK(s6.t[7][0] == 1.0f);
  CHECK(s6.t[2][0] == 19.0f / 127.0f);  // 100 * 51 / 256 = 19.9

  std::vector<std::uint8_t> rg = block(255, 0);
  const std::vector<std::uint8_t> green = block(0, 255);
  rg.insert(rg.end(), green.begin(), green.end());
  const Decoded two = Decode(COMPRESSED_RG_RGTC2, rg);
  for (int t = 0; t < 8; ++t) {
    CHECK(two.t[t][0] == want8[t]);
    CHECK(two.t[t][1] == want6[t]);
  }
}

namespace {
// A BC7 block written bit by bit, lowest first (the layout ARB_texture_compression_bptc gives each mode).
struct Bc7Writer {
  std::vector<std::uint8_t> block = std::vector<std::uint8_t>(16, 0);
  int pos = 0;
  Bc7Writer& Put(std::uint32_t v, int bits) {
    for (int i = 0; i < bits; ++i, ++pos)
      if ((v >> i) & 1) block[std::size_t(pos >> 3)] = std::uint8_t(block[std::size_t(pos >> 3)] | 1 << (pos & 7));
    return *this;
  }
};
}  // namespace

TEST_CASE("BC7 blocks: endpoints widened with their p-bits, 64ths between them, subsets, rotation", "[compression]") {
  // Mode 6: one subset, RGBA endpoints of 7 bits and a p-bit each, 4-bit indices (texel 0's has 3 bits).
  Bc7Writer m6;
  m6.Put(1 << 6, 7);
  for (const int v : {10, 100, 20, 110, 30, 120, 40, 127}) m6.Put(std::uint32_t(v), 7);  // R0 R1 G0 G1 B0 B1 A0 A1
  m6.Put(1, 1).Put(0, 1);                                                                 // p-bits: 1, 0
  m6.Put(0, 3);                                                                           // texel 0: index 0
  for (int t = 1; t < 16; ++t) m6.Put(std::uint32_t(t), 4);                               // texel t: index t
  const Decoded d6 = Decode(COMPRESSED_RGBA_BPTC_UNORM, m6.block);
  // Endpoint 0 = (v << 1 | 1) (8 bits already), endpoint 1 = (v << 1).
  const int e0[4] = {21, 41, 61, 81}, e1[4] = {200, 220, 240, 254};
  const int weights[16] = {0, 4, 9, 13, 17, 21, 26, 30, 34, 38, 43, 47, 51, 55, 60, 64};
  for (int t = 0; t < 16; ++t)
    for (int c = 0; c < 4; ++c) {
      CAPTURE(t, c);
      CHECK(d6.t[t][c] == float(((64 - weights[t]) * e0[c] + weights[t] * e1[c] + 32) >> 6));
    }
  // Mode 5 with rotation 1 (alpha and red swapped after interpolation): colour 7-bit endpoints widened by
  // repeating their high bit, alpha 8-bit; 2-bit indices for both.
  Bc7Writer m5;
  m5.Put(1 << 5, 6).Put(1, 2);                                               // mode 5, rotation 1
  for (const int v : {127, 0, 64, 64, 1, 126}) m5.Put(std::uint32_t(v), 7);  // R0 R1 G0 G1 B0 B1
  m5.Put(50, 8).Put(250, 8);                                                 // A0 A1
  for (int t = 0; t < 16; ++t) m5.Put(3, t == 0 ? 1 : 2);                    // colour indices: 3 (texel 0: 1)
  for (int t = 0; t < 16; ++t) m5.Put(0, t == 0 ? 1 : 2);                    // alpha indices: 0
  const Decoded d5 = Decode(COMPRESSED_RGBA_BPTC_UNORM, m5.block);
  CHECK(d5.t[1][3] == 0.0f);    // red (index 3: endpoint 1, 0) moved to alpha
  CHECK(d5.t[1][0] == 50.0f);   // alpha (index 0: 50) moved to red
  CHECK(d5.t[1][1] == 129.0f);  // 64 widened: 64 << 1 | 64 >> 6
  CHECK(d5.t[1][2] == 253.0f);  // 126 widened: 126 << 1 | 1
  CHECK(d5.t[0][3] == 171.0f);  // texel 0's index 1 (one bit): 21 / 64 of the way from 255 to 0, as alpha
  // Mode 1, partition 13 (the lower half subset 0, the upper subset 1): each subset its own colour.
  Bc7Writer m1;
  m1.Put(1 << 1, 2).Put(13, 6);
  for (int c = 0; c < 3; ++c) m1.Put(0, 6).Put(0, 6).Put(63, 6).Put(63, 6);  // subset 0 black, subset 1 white
  m1.Put(0, 1).Put(1, 1);                                                      // shared p-bits: 0 and 1
  const Decoded d1 = Decode(COMPRESSED_RGBA_BPTC_UNORM, m1.block);
  for (int t = 0; t < 16; ++t) CHECK(d1.t[t][0] == (t >= 8 ? 255.0f : 0.0f));
  // No mode bit in the first byte: a reserved mode, transparent black.
  const Decoded none = Decode(COMPRESSED_RGBA_BPTC_UNORM, std::vector<std::uint8_t>(16, 0));
  for (int t = 0; t < 16; ++t) CHECK((none.t[t][0] == 0.0f && none.t[t][3] == 0.0f));
}

TEST_CASE("BC6H blocks: endpoints unquantized to 16 bits, 64ths between them, half floats; reserved modes", "[compression]") {
  // Mode 3 (bits 00011): one subset, six 10-bit endpoint components stored whole, 4-bit indices (texel 0's 3).
  const auto block = [](int r0, int g0, int b0, int r1, int g1, int b1) {
    Bc7Writer w;
    w.Put(3, 5);
    for (const int v : {r0, g0, b0, r1, g1, b1}) w.Put(std::uint32_t(v), 10);
    w.Put(0, 3).Put(15, 4).Put(8, 4);  // texels 0, 1, 2: indices 0, 15, 8; the others 0
    return w.block;
  };
  const auto half = [](const Decoded& d, int t, int c) { return detail::FloatToHalf(d.t[t][c]); };
  const Decoded u = Decode(COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT, block(0, 512, 1023, 1023, 512, 0));
  // Unquantized: 0 -> 0, 1023 -> 0xFFFF, 512 -> ((512 << 15) + 0x4000) >> 9 = 32800; then times 31 / 64.
  CHECK(half(u, 0, 0) == 0);
  CHECK(half(u, 0, 1) == 0x3E0F);  // 32800 * 31 >> 6
  CHECK(half(u, 0, 2) == 0x7BFF);  // 65535 * 31 >> 6: the largest half, 65504
  CHECK(half(u, 1, 0) == 0x7BFF);
  CHECK(half(u, 1, 2) == 0);
  CHECK(half(u, 2, 0) == 0x41DF);  // weight 34: (34 * 65535 + 32) >> 6 = 34815, times 31 / 64
  CHECK(u.t[0][3] == 1.0f);
  // Signed: 10-bit endpoints sign-extended (-512 -> -0x7FFF, saturated), then times 31 / 32 with the sign kept.
  const Decoded s = Decode(COMPRESSED_RGB_BPTC_SIGNED_FLOAT, block(512, 256, 0, 1, 1, 1));
  CHECK(half(s, 0, 0) == (0x8000 | 0x7BFF));   // -32767 -> -(32767 * 31 >> 5)
  CHECK(half(s, 0, 1) == 0x3E1F);              // 256: ((256 << 15) + 0x4000) >> 9 = 16416, * 31 >> 5 = 15903
  CHECK(half(s, 0, 2) == 0);
  // The reserved modes (19, 23, 27, 31) decode to (0, 0, 0, 1).
  for (const int mode : {19, 23, 27, 31}) {
    std::vector<std::uint8_t> reserved(16, 0xFF);
    reserved[0] = std::uint8_t(0xE0 | mode);
    const Decoded r = Decode(COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT, reserved);
    for (int t = 0; t < 16; ++t) CHECK((r.t[t][0] == 0.0f && r.t[t][1] == 0.0f && r.t[t][2] == 0.0f && r.t[t][3] == 1.0f));
  }
}

TEST_CASE("CompressedTexImage2D and CompressedTexSubImage2D: decoded texels, blocks and level state", "[compression]") {
  Context gl(8, 8);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  // A 6 x 5 DXT1 image: 2 x 2 blocks, the right and top ones partial.
  std::vector<std::uint8_t> blocks;
  for (int b = 0; b < 4; ++b) blocks.insert(blocks.end(), kFourColours.begin(), kFourColours.end());
  blocks[8 + 4] = 0x55;  // block 1: its first row all index 1 (blue)
  gl.CompressedTexImage2D(TEXTURE_2D, 0, COMPRESSED_RGB_S3TC_DXT1_EXT, 6, 5, 0, int(blocks.size()), blocks.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_COMPRESSED, &v);
  CHECK(v == 1);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
  CHECK(v == 32);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(COMPRESSED_RGB_S3TC_DXT1_EXT));
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_WIDTH, &v);
  CHECK(v == 6);

  std::vector<std::uint8_t> texels(6 * 5 * 4);
  gl.PixelStore(PACK_ALIGNMENT, 1);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  auto at = [&](int x, int y) {
    const std::uint8_t* p = &texels[std::size_t((y * 6 + x) * 4)];
    return std::vector<int>{p[0], p[1], p[2], p[3]};
  };
  CHECK(at(0, 0) == std::vector<int>{255, 0, 0, 255});
  CHECK(at(2, 0) == std::vector<int>{170, 0, 84, 255});
  CHECK(at(3, 0) == std::vector<int>{85, 0, 169, 255});
  CHECK(at(4, 0) == std::vector<int>{0, 0, 255, 255});  // block 1's first row
  CHECK(at(5, 0) == std::vector<int>{0, 0, 255, 255});
  CHECK(at(4, 1) == std::vector<int>{255, 0, 0, 255});
  CHECK(at(2, 4) == std::vector<int>{170, 0, 84, 255});  // block 2 (above block 0), its first row

  std::vector<std::uint8_t> back(40, 0xCD);
  gl.GetCompressedTexImage(TEXTURE_2D, 0, back.data());
  CHECK(std::equal(blocks.begin(), blocks.end(), back.begin()));
  CHECK(back[32] == 0xCD);

  // Block 3 (partial in both directions) replaced by the three-colour block.
  gl.CompressedTexSubImage2D(TEXTURE_2D, 0, 4, 4, 2, 1, COMPRESSED_RGB_S3TC_DXT1_EXT, 8, kThreeColours.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  CHECK(at(4, 4) == std::vector<int>{0, 0, 255, 255});
  CHECK(at(5, 4) == std::vector<int>{255, 0, 0, 255});
  CHECK(at(2, 4) == std::vector<int>{170, 0, 84, 255});  // block 2 unchanged
  gl.GetCompressedTexImage(TEXTURE_2D, 0, back.data());
  CHECK(std::equal(kThreeColours.begin(), kThreeColours.end(), back.begin() + 24));

  // A 2D array: layer 1 of two, its one block replaced.
  gl.BindTexture(TEXTURE_2D_ARRAY, gl.GenTexture());
  std::vector<std::uint8_t> layers = kFourColours;
  layers.insert(layers.end(), kFourColours.begin(), kFourColours.end());
  gl.CompressedTexImage3D(TEXTURE_2D_ARRAY, 0, COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 2, 0, 16, layers.data());
  gl.CompressedTexSubImage3D(TEXTURE_2D_ARRAY, 0, 0, 0, 1, 4, 4, 1, COMPRESSED_RGBA_S3TC_DXT1_EXT, 8,
                             kThreeColours.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  std::vector<std::uint8_t> array_texels(4 * 4 * 2 * 4);
  gl.GetTexImage(TEXTURE_2D_ARRAY, 0, RGBA, UNSIGNED_BYTE, array_texels.data());
  CHECK(array_texels[0] == 255);    // layer 0, texel 0: red
  CHECK(array_texels[64 + 2] == 255);  // layer 1, texel 0: blue
  CHECK(array_texels[64 + 3 * 4 + 3] == 0);  // layer 1, texel 3: transparent black
}

TEST_CASE("compressed levels: completeness, and what softgl does not compress", "[compression]") {
  Context gl(8, 8);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  const std::vector<std::uint8_t> block = kFourColours;
  gl.CompressedTexImage2D(TEXTURE_2D, 0, COMPRESSED_RGBA_S3TC_DXT1_EXT, 2, 2, 0, 8, block.data());
  gl.CompressedTexImage2D(TEXTURE_2D, 1, COMPRESSED_RGBA_S3TC_DXT1_EXT, 1, 1, 0, 8, block.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  detail::TextureObject probe;
  probe.target = TEXTURE_2D;
  {  // the same chain built directly: complete; with level 1 an RGBA8 level of the decoded bytes: incomplete
    const detail::CompressedFormat* f = detail::CompressedFormatOf(COMPRESSED_RGBA_S3TC_DXT1_EXT);
    for (int l = 0; l < 2; ++l) {
      detail::TextureLevel& lv = probe.levels[0][l];
      lv.Allocate(f->decoded, 2 >> l, 2 >> l);
      lv.compressed = f->format;
      lv.blocks.assign(8, 0);
      detail::DecodeRegion(*f, block.data(), 0, 0, 0, lv.width, lv.height, 1, lv);
    }
    probe.params.min_filter = LINEAR_MIPMAP_LINEAR;
    CHECK(detail::MakeView(probe).complete);
    probe.levels[0][1].compressed = 0;
    probe.levels[0][1].blocks.clear();
    CHECK(!detail::MakeView(probe).complete);
  }

  // No compression: a specific compressed format through TexImage*, CopyTexImage*; any change to a compressed
  // level but CompressedTexSubImage*; GenerateMipmap from one.
  const std::uint8_t rgba[16] = {};
  gl.TexImage2D(TEXTURE_2D, 2, COMPRESSED_RGBA_S3TC_DXT5_EXT, 1, 1, 0, RGBA, UNSIGNED_BYTE, rgba);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CopyTexImage2D(TEXTURE_2D, 2, COMPRESSED_RED_RGTC1, 0, 0, 1, 1, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexSubImage2D(TEXTURE_2D, 0, 0, 0, 1, 1, RGBA, UNSIGNED_BYTE, rgba);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GenerateMipmap(TEXTURE_2D);
  CHECK(gl.GetError() == INVALID_OPERATION);
  // Not colour-renderable.
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_INCOMPLETE_ATTACHMENT);
  gl.BindFramebuffer(FRAMEBUFFER, 0);

  // The generic formats are accepted and stored uncompressed.
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.TexImage2D(TEXTURE_2D, 0, COMPRESSED_RGBA, 2, 2, 0, RGBA, UNSIGNED_BYTE, rgba);
  REQUIRE(gl.GetError() == NO_ERROR);
  int v = -1;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_COMPRESSED, &v);
  CHECK(v == 0);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(RGBA8));
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_COMPRESSED_IMAGE_SIZE, &v);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.TexImage2D(TEXTURE_2D, 0, COMPRESSED_SRGB_ALPHA, 2, 2, 0, RGBA, UNSIGNED_BYTE, rgba);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(SRGB8_ALPHA8));

  int formats[5] = {0, 0, 0, 0, -1};
  gl.GetIntegerv(NUM_COMPRESSED_TEXTURE_FORMATS, formats);
  CHECK(formats[0] == 4);
  gl.GetIntegerv(COMPRESSED_TEXTURE_FORMATS, formats);
  CHECK(formats[0] == int(COMPRESSED_RGB_S3TC_DXT1_EXT));
  CHECK(formats[3] == int(COMPRESSED_RGBA_S3TC_DXT5_EXT));
  CHECK(formats[4] == -1);
}

TEST_CASE("compressed texture calls reject bad sizes, null data and huge images", "[compression]") {
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  const std::vector<std::uint8_t> block = kFourColours;
  const Enum dxt1 = COMPRESSED_RGB_S3TC_DXT1_EXT;
  gl.CompressedTexImage2D(TEXTURE_2D, 0, dxt1, 4, 4, 0, 8, nullptr);  // null data for a block
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage2D(TEXTURE_2D, 0, dxt1, 4, 4, 0, -8, block.data());
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage2D(TEXTURE_2D, 0, dxt1, 4, 4, 1, 8, block.data());  // border
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage2D(TEXTURE_2D, 0, dxt1, 16384, 16384, 0, 8, block.data());  // the size does not match
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage2D(TEXTURE_2D, 0, dxt1, 16385, 4, 0, 8, block.data());
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage2D(TEXTURE_2D, 0, 0xFFFF, 4, 4, 0, 8, block.data());
  CHECK(gl.GetError() == INVALID_ENUM);
  // Layers beyond what a level holds: the size that would match overflows int, so it cannot be given.
  gl.BindTexture(TEXTURE_2D_ARRAY, gl.GenTexture());
  gl.CompressedTexImage3D(TEXTURE_2D_ARRAY, 0, dxt1, 16384, 16384, 2048, 0, 8, block.data());
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexImage3D(TEXTURE_2D_ARRAY, 0, dxt1, 4, 4, 1, 0, 8, block.data());
  REQUIRE(gl.GetError() == NO_ERROR);
  gl.CompressedTexSubImage3D(TEXTURE_2D_ARRAY, 0, 0, 0, 0, 4, 4, 1, dxt1, 8, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CompressedTexSubImage3D(TEXTURE_2D_ARRAY, 0, 0, 0, 1, 4, 4, 1, dxt1, 8, block.data());  // past the layers
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetCompressedTexImage(TEXTURE_2D_ARRAY, 0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetCompressedTexImage(TEXTURE_2D_ARRAY, 15, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetCompressedTexImage(0x1234, 0, nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
}

namespace {

// A DDS file: the 128-byte header (FourCC `four_cc`, or "DX10" and a 20-byte header of DXGI format `dxgi`),
// `levels` mipmap levels of `block_bytes` blocks, the blocks pseudo-random from `seed`.
std::vector<std::uint8_t> MakeDds(const char* four_cc, std::uint32_t dxgi, int w, int h, int levels, int block_bytes,
                                  std::uint32_t seed, std::uint32_t caps2 = 0) {
  const bool dx10 = std::strcmp(four_cc, "DX10") == 0;
  std::vector<std::uint8_t> f(dx10 ? 148 : 128, 0);
  auto put = [&](std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) f[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
  };
  f[0] = 'D', f[1] = 'D', f[2] = 'S', f[3] = ' ';
  put(4, 124);
  put(8, 0x1007 | 0x20000);  // caps, height, width, pixel format, mipmap count
  put(12, std::uint32_t(h));
  put(16, std::uint32_t(w));
  put(28, std::uint32_t(levels));
  put(76, 32);
  put(80, 0x4);  // FourCC
  for (int k = 0; k < 4; ++k) f[std::size_t(84 + k)] = std::uint8_t(four_cc[k]);
  put(112, caps2);
  if (dx10) {
    put(128, dxgi);
    put(132, 3);  // a 2D texture
    put(140, 1);  // one element
  }
  std::vector<std::uint8_t> blocks;
  for (int l = 0; l < levels; ++l) {
    const int lw = std::max(1, w >> l), lh = std::max(1, h >> l);
    for (int b = 0; b < (lw + 3) / 4 * ((lh + 3) / 4) * block_bytes; ++b) {
      seed = seed * 1664525u + 1013904223u;
      blocks.push_back(std::uint8_t(seed >> 24));
    }
  }
  f.insert(f.end(), blocks.begin(), blocks.end());
  return f;
}

// Level `level` of the bound TEXTURE_2D as RGBA floats, rows bottom first.
std::vector<float> Texels(Context& gl, int level, int w, int h) {
  std::vector<float> out(std::size_t(w) * std::size_t(h) * 4, -9.0f);
  gl.GetTexImage(TEXTURE_2D, level, RGBA, FLOAT, out.data());
  return out;
}

}  // namespace

TEST_CASE("DDS files define every level from their blocks, flipped on request", "[compression]") {
  struct Case {
    const char* four_cc;
    std::uint32_t dxgi;
    int block_bytes;
    Enum want;
  };
  const Case cases[] = {
      {"DXT1", 0, 8, COMPRESSED_RGB_S3TC_DXT1_EXT},  {"DXT3", 0, 16, COMPRESSED_RGBA_S3TC_DXT3_EXT},
      {"DXT5", 0, 16, COMPRESSED_RGBA_S3TC_DXT5_EXT}, {"ATI1", 0, 8, COMPRESSED_RED_RGTC1},
      {"BC4S", 0, 8, COMPRESSED_SIGNED_RED_RGTC1},    {"ATI2", 0, 16, COMPRESSED_RG_RGTC2},
      {"DX10", 78, 16, COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}, {"DX10", 84, 16, COMPRESSED_SIGNED_RG_RGTC2},
  };
  for (const Case& c : cases) {
    for (const glm::ivec2 size : {glm::ivec2(16, 8), glm::ivec2(8, 2), glm::ivec2(12, 16)}) {
      INFO(c.four_cc << " " << c.dxgi << ", " << size.x << " x " << size.y);
      const int levels = size.x == 12 ? 2 : 3;
      const std::vector<std::uint8_t> file = MakeDds(c.four_cc, c.dxgi, size.x, size.y, levels, c.block_bytes, 5);
      Context gl(4, 4);
      const std::uint32_t plain = gl.GenTexture(), flipped = gl.GenTexture();
      std::string error;
      gl.BindTexture(TEXTURE_2D, plain);
      REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, file.data(), file.size(), false, &error));
      int v = 0;
      gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
      CHECK(v == int(c.want));
      gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MAX_LEVEL, &v);
      CHECK(v == levels - 1);
      // Level 1's blocks are the file's second run of blocks.
      const int w1 = std::max(1, size.x / 2), h1 = std::max(1, size.y / 2);
      const std::size_t header = c.dxgi ? 148 : 128;
      const std::size_t first = std::size_t((size.x + 3) / 4 * ((size.y + 3) / 4) * c.block_bytes);
      const std::size_t second = std::size_t((w1 + 3) / 4 * ((h1 + 3) / 4) * c.block_bytes);
      std::vector<std::uint8_t> blocks(second);
      gl.GetCompressedTexImage(TEXTURE_2D, 1, blocks.data());
      CHECK(std::equal(blocks.begin(), blocks.end(), file.begin() + std::ptrdiff_t(header + first)));
      // Flipped: every level the mirror image of the unflipped one.
      gl.BindTexture(TEXTURE_2D, flipped);
      REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, file.data(), file.size(), true, &error));
      for (int l = 0; l < levels; ++l) {
        const int lw = std::max(1, size.x >> l), lh = std::max(1, size.y >> l);
        gl.BindTexture(TEXTURE_2D, plain);
        const std::vector<float> a = Texels(gl, l, lw, lh);
        gl.BindTexture(TEXTURE_2D, flipped);
        const std::vector<float> b = Texels(gl, l, lw, lh);
        int differ = 0;
        for (int y = 0; y < lh; ++y)
          for (int x = 0; x < lw * 4; ++x)
            differ += a[std::size_t(y * lw * 4 + x)] != b[std::size_t((lh - 1 - y) * lw * 4 + x)];
        CHECK(differ == 0);
      }
      CHECK(gl.GetError() == NO_ERROR);
    }
  }
  // sRGB on request: the S3TC and BC7 formats' sRGB forms; RGTC has none.
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  const std::vector<std::uint8_t> dxt1 = MakeDds("DXT1", 0, 8, 8, 1, 8, 1);
  REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, dxt1.data(), dxt1.size(), false, nullptr, SRGB));
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(COMPRESSED_SRGB_S3TC_DXT1_EXT));
  // BC7 (DX10 headers only), unflipped: its blocks as they are, in both forms.
  for (const std::uint32_t dxgi : {98u, 99u}) {
    const std::vector<std::uint8_t> bc7 = MakeDds("DX10", dxgi, 8, 8, 2, 16, 9);
    REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, bc7.data(), bc7.size(), false));
    gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
    CHECK(v == int(dxgi == 98 ? COMPRESSED_RGBA_BPTC_UNORM : COMPRESSED_SRGB_ALPHA_BPTC_UNORM));
    std::vector<std::uint8_t> blocks(64);
    gl.GetCompressedTexImage(TEXTURE_2D, 0, blocks.data());
    CHECK(std::equal(blocks.begin(), blocks.end(), bc7.begin() + 148));
  }
  // BC6H (DX10 headers), unsigned and signed; no sRGB form.
  for (const std::uint32_t dxgi : {95u, 96u}) {
    const std::vector<std::uint8_t> bc6 = MakeDds("DX10", dxgi, 8, 8, 1, 16, 5);
    REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, bc6.data(), bc6.size(), false, nullptr, SRGB));
    gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
    CHECK(v == int(dxgi == 95 ? COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT : COMPRESSED_RGB_BPTC_SIGNED_FLOAT));
  }
  const std::vector<std::uint8_t> bc7 = MakeDds("DX10", 98, 4, 4, 1, 16, 9);
  REQUIRE(gl.TexImage2DFromMemory(TEXTURE_2D, bc7.data(), bc7.size(), false, nullptr, SRGB));
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_INTERNAL_FORMAT, &v);
  CHECK(v == int(COMPRESSED_SRGB_ALPHA_BPTC_UNORM));
}

TEST_CASE("DDS files softgl cannot take are refused with a message", "[compression]") {
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  std::vector<std::uint8_t> good = MakeDds("DXT5", 0, 8, 8, 4, 16, 3);
  auto refused = [&](const std::vector<std::uint8_t>& file, const char* words, bool flip = false) {
    std::string error;
    const bool ok = gl.TexImage2DFromMemory(TEXTURE_2D, file.data(), file.size(), flip, &error);
    INFO(error);
    CHECK(!ok);
    CHECK(error.find(words) != std::string::npos);
    CHECK(gl.GetError() == NO_ERROR);
  };
  refused(std::vector<std::uint8_t>(good.begin(), good.end() - 1), "truncated DDS data");
  refused(std::vector<std::uint8_t>(good.begin(), good.begin() + 100), "DDS header");
  refused(MakeDds("DX10", 95, 8, 8, 1, 16, 3), "BPTC (BC6H, BC7) blocks cannot be turned upside down", true);
  refused(MakeDds("DX10", 98, 8, 8, 1, 16, 3), "BPTC (BC6H, BC7) blocks cannot be turned upside down", true);
  refused(MakeDds("DXT5", 0, 8, 8, 1, 16, 3, 0x200), "cube maps");
  refused(MakeDds("RGBG", 0, 8, 8, 1, 16, 3), "not a block-compressed DDS file");
  refused(MakeDds("DXT5", 0, 8, 6, 1, 16, 3), "cannot flip", true);
  refused(MakeDds("DXT5", 0, 16385, 4, 1, 16, 3), "larger than kMaxTextureSize");
  std::vector<std::uint8_t> uncompressed = good;
  uncompressed[80] = 0x41;  // RGB with alpha, no FourCC
  refused(uncompressed, "uncompressed DDS");
  // A mipmap count beyond the chain reads the chain only.
  good[28] = 40;
  std::string error;
  CHECK(gl.TexImage2DFromMemory(TEXTURE_2D, good.data(), good.size(), false, &error));
  int v = 0;
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MAX_LEVEL, &v);
  CHECK(v == 3);
}

// texture_compression.cpp — decoding S3TC and RGTC blocks into level texels.
#include "texture_compression.h"

#include <algorithm>
#include <cstring>

#include "texture.h"

namespace softgl::detail {

namespace {

using Kind = CompressedFormat::Kind;

constexpr CompressedFormat kFormats[] = {
    {COMPRESSED_RGB_S3TC_DXT1_EXT, 8, RGB8, Kind::kDxt1Rgb},
    {COMPRESSED_RGBA_S3TC_DXT1_EXT, 8, RGBA8, Kind::kDxt1Rgba},
    {COMPRESSED_RGBA_S3TC_DXT3_EXT, 16, RGBA8, Kind::kDxt3},
    {COMPRESSED_RGBA_S3TC_DXT5_EXT, 16, RGBA8, Kind::kDxt5},
    {COMPRESSED_SRGB_S3TC_DXT1_EXT, 8, SRGB8, Kind::kDxt1Rgb},
    {COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT, 8, SRGB8_ALPHA8, Kind::kDxt1Rgba},
    {COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT, 16, SRGB8_ALPHA8, Kind::kDxt3},
    {COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT, 16, SRGB8_ALPHA8, Kind::kDxt5},
    {COMPRESSED_RED_RGTC1, 8, R8, Kind::kRgtc1},
    {COMPRESSED_SIGNED_RED_RGTC1, 8, R32F, Kind::kRgtc1Signed},
    {COMPRESSED_RG_RGTC2, 16, RG8, Kind::kRgtc2},
    {COMPRESSED_SIGNED_RG_RGTC2, 16, RG32F, Kind::kRgtc2Signed},
};

// k / n of the way from a to b, by an 8-bit weight w = floor(255 k / n): (a (256 - w) + b w) / 256 rounded down.
int Mix(int a, int b, int k, int n) {
  const int w = 255 * k / n;
  return (a * (256 - w) + b * w) >> 8;
}

std::uint32_t Word16(const std::uint8_t* p) { return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8; }

// The four colours of an S3TC colour block (8 bytes) as RGBA bytes, and its 16 two-bit indices. `four` forces the
// four-colour mode (DXT3, DXT5); `black_alpha` is colour 3's alpha in three-colour mode.
void ColourBlock(const std::uint8_t* b, bool four, int black_alpha, float out[16][4]) {
  const std::uint32_t w0 = Word16(b), w1 = Word16(b + 2);
  int c[4][4];
  for (int k = 0; k < 2; ++k) {
    const std::uint32_t w = k ? w1 : w0;
    const int r = int(w >> 11) & 31, g = int(w >> 5) & 63, bl = int(w) & 31;
    c[k][0] = r << 3 | r >> 2;
    c[k][1] = g << 2 | g >> 4;
    c[k][2] = bl << 3 | bl >> 2;
    c[k][3] = 255;
  }
  for (int ch = 0; ch < 3; ++ch) {
    if (four || w0 > w1) {
      c[2][ch] = Mix(c[0][ch], c[1][ch], 1, 3);
      c[3][ch] = Mix(c[0][ch], c[1][ch], 2, 3);
    } else {
      c[2][ch] = (c[0][ch] + c[1][ch] + 1) >> 1;
      c[3][ch] = 0;
    }
  }
  c[2][3] = 255;
  c[3][3] = four || w0 > w1 ? 255 : black_alpha;
  std::uint32_t bits;
  std::memcpy(&bits, b + 4, 4);  // (little-endian, as every target softgl builds for)
  for (int t = 0; t < 16; ++t) {
    const int i = int(bits >> (2 * t)) & 3;
    for (int ch = 0; ch < 4; ++ch) out[t][ch] = float(c[i][ch]);
  }
}

// The 16 values of an 8-byte alpha block (DXT5 alpha, an RGTC channel), as integers: endpoints, then 3-bit
// indices. Signed blocks hold signed bytes; their least value is -127.
void ValueBlock(const std::uint8_t* b, bool is_signed, int out[16]) {
  const int a0 = is_signed ? int(std::int8_t(b[0])) : int(b[0]);
  const int a1 = is_signed ? int(std::int8_t(b[1])) : int(b[1]);
  int v[8];
  v[0] = a0;
  v[1] = a1;
  if (a0 > a1) {
    for (int i = 2; i < 8; ++i) v[i] = Mix(a0, a1, i - 1, 7);
  } else {
    for (int i = 2; i < 6; ++i) v[i] = Mix(a0, a1, i - 1, 5);
    v[6] = is_signed ? -127 : 0;
    v[7] = is_signed ? 127 : 255;
  }
  std::uint64_t bits = 0;
  for (int k = 0; k < 6; ++k) bits |= std::uint64_t(b[2 + k]) << (8 * k);
  for (int t = 0; t < 16; ++t) out[t] = v[(bits >> (3 * t)) & 7];
}

float SignedValue(int v) { return v <= -127 ? -1.0f : float(v) / 127.0f; }

}  // namespace

const CompressedFormat* CompressedFormatOf(Enum f) {
  for (const CompressedFormat& c : kFormats)
    if (c.format == f) return &c;
  return nullptr;
}

Enum UncompressedForGeneric(Enum f) {
  switch (f) {
    case COMPRESSED_RED: return R8;
    case COMPRESSED_RG: return RG8;
    case COMPRESSED_RGB: return RGB8;
    case COMPRESSED_RGBA: return RGBA8;
    case COMPRESSED_SRGB: return SRGB8;
    case COMPRESSED_SRGB_ALPHA: return SRGB8_ALPHA8;
    default: return f;
  }
}

std::uint64_t CompressedImageBytes(const CompressedFormat& f, int w, int h, int d) {
  return (std::uint64_t(std::max(w, 0)) + 3) / 4 * ((std::uint64_t(std::max(h, 0)) + 3) / 4) *
         std::uint64_t(std::max(d, 0)) * std::uint64_t(f.block_bytes);
}

void DecodeBlock(const CompressedFormat& f, const std::uint8_t* block, float out[16][4]) {
  int v[16];
  switch (f.kind) {
    case Kind::kDxt1Rgb: ColourBlock(block, false, 255, out); return;
    case Kind::kDxt1Rgba: ColourBlock(block, false, 0, out); return;
    case Kind::kDxt3:
      ColourBlock(block + 8, true, 255, out);
      for (int t = 0; t < 16; ++t) {
        const int a = (block[t / 2] >> (4 * (t & 1))) & 15;
        out[t][3] = float(a << 4 | a);
      }
      return;
    case Kind::kDxt5:
      ColourBlock(block + 8, true, 255, out);
      ValueBlock(block, false, v);
      for (int t = 0; t < 16; ++t) out[t][3] = float(v[t]);
      return;
    case Kind::kRgtc1:
    case Kind::kRgtc2:
    case Kind::kRgtc1Signed:
    case Kind::kRgtc2Signed: {
      const bool is_signed = f.kind == Kind::kRgtc1Signed || f.kind == Kind::kRgtc2Signed;
      const int channels = f.kind == Kind::kRgtc2 || f.kind == Kind::kRgtc2Signed ? 2 : 1;
      for (int t = 0; t < 16; ++t) out[t][0] = out[t][1] = out[t][2] = 0.0f, out[t][3] = is_signed ? 1.0f : 255.0f;
      for (int ch = 0; ch < channels; ++ch) {
        ValueBlock(block + 8 * ch, is_signed, v);
        for (int t = 0; t < 16; ++t) out[t][ch] = is_signed ? SignedValue(v[t]) : float(v[t]);
      }
      return;
    }
  }
}

void DecodeRegion(const CompressedFormat& f, const std::uint8_t* blocks, int x, int y, int z, int w, int h, int d,
                  TextureLevel& level) {
  const int across = (w + 3) / 4, up = (h + 3) / 4;
  const int level_across = (level.width + 3) / 4, level_up = (level.height + 3) / 4;
  const bool floats = level.layout == TexelLayout::kFloat32x1 || level.layout == TexelLayout::kFloat32x2;
  const int channels = FormatComponents(f.decoded);
  float texels[16][4];
  for (int k = 0; k < d; ++k)
    for (int by = 0; by < up; ++by)
      for (int bx = 0; bx < across; ++bx) {
        const std::uint8_t* b = blocks + ((std::size_t(k) * up + by) * across + bx) * std::size_t(f.block_bytes);
        const std::size_t at =
            ((std::size_t(z + k) * level_up + (y / 4 + by)) * level_across + (x / 4 + bx)) * std::size_t(f.block_bytes);
        std::memcpy(level.blocks.data() + at, b, std::size_t(f.block_bytes));
        DecodeBlock(f, b, texels);
        for (int t = 0; t < 16; ++t) {
          const int i = x + bx * 4 + t % 4, j = y + by * 4 + t / 4;
          if (i >= level.width || j >= level.height) continue;
          std::uint8_t* p = level.At(i, (z + k) * level.height + j);
          if (floats) {
            std::memcpy(p, texels[t], std::size_t(channels) * 4);
          } else {
            // (RGB8 and SRGB8 keep four bytes a texel, their alpha 255.)
            for (int ch = 0; ch < level.bytes; ++ch) p[ch] = std::uint8_t(texels[t][ch]);
          }
        }
      }
}

}  // namespace softgl::detail

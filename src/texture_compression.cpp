// texture_compression.cpp — decoding S3TC, RGTC and BPTC (BC7, BC6H) blocks into level texels.
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
    {COMPRESSED_RGBA_BPTC_UNORM, 16, RGBA8, Kind::kBc7},
    {COMPRESSED_SRGB_ALPHA_BPTC_UNORM, 16, SRGB8_ALPHA8, Kind::kBc7},
    {COMPRESSED_RGB_BPTC_SIGNED_FLOAT, 16, RGBA16F, Kind::kBc6hSigned},
    {COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT, 16, RGBA16F, Kind::kBc6hUnsigned},
};

// ---- BPTC (BC7) -----------------------------------------------------------------------------------------------
//
// The partition shapes and anchor texels of BC7 (ARB_texture_compression_bptc's tables): kShapes2[p] bit t set puts
// texel t in subset 1 of a two-subset block; kShapes3[p] holds each texel's subset of a three-subset block in two
// bits (texel t at bits 2t); kAnchor2, kAnchor3a and kAnchor3b give the anchor texel of subset 1 (and 2).
constexpr std::uint16_t kShapes2[64] = {
    0xCCCC, 0x8888, 0xEEEE, 0xECC8, 0xC880, 0xFEEC, 0xFEC8, 0xEC80,
    0xC800, 0xFFEC, 0xFE80, 0xE800, 0xFFE8, 0xFF00, 0xFFF0, 0xF000,
    0xF710, 0x008E, 0x7100, 0x08CE, 0x008C, 0x7310, 0x3100, 0x8CCE,
    0x088C, 0x3110, 0x6666, 0x366C, 0x17E8, 0x0FF0, 0x718E, 0x399C,
    0xAAAA, 0xF0F0, 0x5A5A, 0x33CC, 0x3C3C, 0x55AA, 0x9696, 0xA55A,
    0x73CE, 0x13C8, 0x324C, 0x3BDC, 0x6996, 0xC33C, 0x9966, 0x0660,
    0x0272, 0x04E4, 0x4E40, 0x2720, 0xC936, 0x936C, 0x39C6, 0x639C,
    0x9336, 0x9CC6, 0x817E, 0xE718, 0xCCF0, 0x0FCC, 0x7744, 0xEE22,
};
constexpr std::uint8_t kAnchor2[64] = {
    15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15,
    15, 2, 8, 2, 2, 8, 8, 15, 2, 8, 2, 2, 8, 8, 2, 2,
    15, 15, 6, 8, 2, 8, 15, 15, 2, 8, 2, 2, 2, 15, 15, 6,
    6, 2, 6, 8, 15, 15, 2, 2, 15, 15, 15, 15, 15, 2, 2, 15,
};
constexpr std::uint32_t kShapes3[64] = {
    0xAA685050, 0x6A5A5040, 0x5A5A4200, 0x5450A0A8, 0xA5A50000, 0xA0A05050,
    0x5555A0A0, 0x5A5A5050, 0xAA550000, 0xAA555500, 0xAAAA5500, 0x90909090,
    0x94949494, 0xA4A4A4A4, 0xA9A59450, 0x2A0A4250, 0xA5945040, 0x0A425054,
    0xA5A5A500, 0x55A0A0A0, 0xA8A85454, 0x6A6A4040, 0xA4A45000, 0x1A1A0500,
    0x0050A4A4, 0xAAA59090, 0x14696914, 0x69691400, 0xA08585A0, 0xAA821414,
    0x50A4A450, 0x6A5A0200, 0xA9A58000, 0x5090A0A8, 0xA8A09050, 0x24242424,
    0x00AA5500, 0x24924924, 0x24499224, 0x50A50A50, 0x500AA550, 0xAAAA4444,
    0x66660000, 0xA5A0A5A0, 0x50A050A0, 0x69286928, 0x44AAAA44, 0x66666600,
    0xAA444444, 0x54A854A8, 0x95809580, 0x96969600, 0xA85454A8, 0x80959580,
    0xAA141414, 0x96960000, 0xAAAA1414, 0xA05050A0, 0xA0A5A5A0, 0x96000000,
    0x40804080, 0xA9A8A9A8, 0xAAAAAA44, 0x2A4A5254,
};
constexpr std::uint8_t kAnchor3a[64] = {
    3, 3, 15, 15, 8, 3, 15, 15, 8, 8, 6, 6, 6, 5, 3, 3,
    3, 3, 8, 15, 3, 3, 6, 10, 5, 8, 8, 6, 8, 5, 15, 15,
    8, 15, 3, 5, 6, 10, 8, 15, 15, 3, 15, 5, 15, 15, 15, 15,
    3, 15, 5, 5, 5, 8, 5, 10, 5, 10, 8, 13, 15, 12, 3, 3,
};
constexpr std::uint8_t kAnchor3b[64] = {
    15, 8, 8, 3, 15, 15, 3, 8, 15, 15, 15, 15, 15, 15, 15, 8,
    15, 8, 15, 3, 15, 8, 15, 8, 3, 15, 6, 10, 15, 15, 10, 8,
    15, 3, 15, 10, 10, 8, 9, 10, 6, 15, 8, 15, 3, 6, 6, 8,
    15, 3, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 3, 15, 15, 8,
};

// One BC7 mode's layout: subsets, partition bits, rotation bits, index-selection bits, colour and alpha bits an
// endpoint, p-bits (one an endpoint, or one shared by a subset's two), and the bits of the two index sets.
struct Bc7Mode {
  int subsets, partition_bits, rotation_bits, selection_bits, colour_bits, alpha_bits;
  bool endpoint_pbits, shared_pbits;
  int index_bits, index2_bits;
};
constexpr Bc7Mode kBc7Modes[8] = {
    {3, 4, 0, 0, 4, 0, true, false, 3, 0}, {2, 6, 0, 0, 6, 0, false, true, 3, 0},
    {3, 6, 0, 0, 5, 0, false, false, 2, 0}, {2, 6, 0, 0, 7, 0, true, false, 2, 0},
    {1, 0, 2, 1, 5, 6, false, false, 2, 3}, {1, 0, 2, 0, 7, 8, false, false, 2, 2},
    {1, 0, 0, 0, 7, 7, true, false, 4, 0},  {2, 6, 0, 0, 5, 5, true, false, 2, 0},
};
// The interpolation weights (of 64) for 2-, 3- and 4-bit indices.
constexpr int kWeights2[4] = {0, 21, 43, 64};
constexpr int kWeights3[8] = {0, 9, 18, 27, 37, 46, 55, 64};
constexpr int kWeights4[16] = {0, 4, 9, 13, 17, 21, 26, 30, 34, 38, 43, 47, 51, 55, 60, 64};

// The block's bits from the first byte's lowest on.
struct BlockBits {
  const std::uint8_t* b;
  int pos = 0;
  int Take(int n) {
    int v = 0;
    for (int i = 0; i < n; ++i, ++pos) v |= ((b[pos >> 3] >> (pos & 7)) & 1) << i;
    return v;
  }
};

// An endpoint of `bits` bits (p-bit included) widened to 8 by repeating its high bits.
int Widen(int v, int bits) { return bits >= 8 ? v : (v << (8 - bits)) | (v >> (2 * bits - 8)); }

int Interpolate(int e0, int e1, int index, int index_bits) {
  const int w = index_bits == 2 ? kWeights2[index] : index_bits == 3 ? kWeights3[index] : kWeights4[index];
  return ((64 - w) * e0 + w * e1 + 32) >> 6;
}

// Decodes a BC7 block into 16 RGBA bytes a texel (as floats 0..255); a block of no mode (its first byte 0) is
// transparent black.
void Bc7Block(const std::uint8_t* block, float out[16][4]) {
  BlockBits in{block};
  int m = 0;
  while (m < 8 && in.Take(1) == 0) ++m;
  if (m == 8) {
    for (int t = 0; t < 16; ++t) out[t][0] = out[t][1] = out[t][2] = out[t][3] = 0.0f;
    return;
  }
  const Bc7Mode& mode = kBc7Modes[m];
  const int partition = in.Take(mode.partition_bits), rotation = in.Take(mode.rotation_bits);
  const int selection = in.Take(mode.selection_bits);
  int e[3][2][4] = {};  // [subset][endpoint][channel]
  for (int c = 0; c < 3; ++c)
    for (int s = 0; s < mode.subsets; ++s)
      for (int k = 0; k < 2; ++k) e[s][k][c] = in.Take(mode.colour_bits);
  for (int s = 0; s < mode.subsets; ++s)
    for (int k = 0; k < 2; ++k) e[s][k][3] = mode.alpha_bits ? in.Take(mode.alpha_bits) : 255;
  int colour_bits = mode.colour_bits, alpha_bits = mode.alpha_bits;
  if (mode.endpoint_pbits || mode.shared_pbits) {
    for (int s = 0; s < mode.subsets; ++s) {
      const int shared = mode.shared_pbits ? in.Take(1) : 0;
      for (int k = 0; k < 2; ++k) {
        const int p = mode.endpoint_pbits ? in.Take(1) : shared;
        for (int c = 0; c < 4; ++c)
          if (c < 3 || mode.alpha_bits) e[s][k][c] = e[s][k][c] << 1 | p;
      }
    }
    ++colour_bits;
    if (alpha_bits) ++alpha_bits;
  }
  for (int s = 0; s < mode.subsets; ++s)
    for (int k = 0; k < 2; ++k) {
      for (int c = 0; c < 3; ++c) e[s][k][c] = Widen(e[s][k][c], colour_bits);
      if (alpha_bits) e[s][k][3] = Widen(e[s][k][3], alpha_bits);
    }
  // Each texel's subset, and the anchors whose index has one bit less.
  int subset[16];
  for (int t = 0; t < 16; ++t)
    subset[t] = mode.subsets == 2 ? (kShapes2[partition] >> t) & 1
                : mode.subsets == 3 ? int(kShapes3[partition] >> (2 * t)) & 3 : 0;
  const auto anchor = [&](int t) {
    return t == 0 || (mode.subsets == 2 && t == kAnchor2[partition]) ||
           (mode.subsets == 3 && (t == kAnchor3a[partition] || t == kAnchor3b[partition]));
  };
  int index[16], index2[16] = {};
  for (int t = 0; t < 16; ++t) index[t] = in.Take(mode.index_bits - (anchor(t) ? 1 : 0));
  if (mode.index2_bits)
    for (int t = 0; t < 16; ++t) index2[t] = in.Take(mode.index2_bits - (t == 0 ? 1 : 0));
  for (int t = 0; t < 16; ++t) {
    const int (&ends)[2][4] = e[subset[t]];
    int rgba[4];
    // Colour from the first index set and alpha from the second (mode 4 with its selection bit: the other way).
    const bool swap = selection == 1;
    const int ci = mode.index2_bits && swap ? index2[t] : index[t];
    const int cb = mode.index2_bits && swap ? mode.index2_bits : mode.index_bits;
    const int ai = mode.index2_bits ? (swap ? index[t] : index2[t]) : index[t];
    const int ab = mode.index2_bits ? (swap ? mode.index_bits : mode.index2_bits) : mode.index_bits;
    for (int c = 0; c < 3; ++c) rgba[c] = Interpolate(ends[0][c], ends[1][c], ci, cb);
    rgba[3] = Interpolate(ends[0][3], ends[1][3], ai, ab);
    if (rotation > 0) std::swap(rgba[3], rgba[rotation - 1]);
    for (int c = 0; c < 4; ++c) out[t][c] = float(rgba[c]);
  }
}

// ---- BPTC (BC6H) ----------------------------------------------------------------------------------------------
//
// BC6H's fourteen modes (ARB_texture_compression_bptc, tables MF and F): each block's mode in its low 2 bits (0 and
// 1) or 5 bits, then the endpoints' bits scattered as the mode lays them out. A Bc6Step gives the next `count`
// bits of the block to endpoint component `field` (r0 g0 b0 r1 g1 b1 r2 g2 b2 r3 g3 b3: 0 to 11) from bit `lo`
// up, or with `reversed` from bit lo + count - 1 down.
struct Bc6Step {
  std::uint8_t field, lo, count, reversed;
};
struct Bc6Mode {
  int number;        // the mode bits' value
  bool transformed;  // endpoints after the first are deltas from it
  int partition_bits, endpoint_bits, delta_bits[3];
  Bc6Step steps[23];
};
constexpr Bc6Mode kBc6Modes[14] = {
    {0, true, 5, 10, {5, 5, 5}, {}},  {1, true, 5, 7, {6, 6, 6}, {}},   {2, true, 5, 11, {5, 4, 4}, {}},
    {6, true, 5, 11, {4, 5, 4}, {}},  {10, true, 5, 11, {4, 4, 5}, {}}, {14, true, 5, 9, {5, 5, 5}, {}},
    {18, true, 5, 8, {6, 5, 5}, {}},  {22, true, 5, 8, {5, 6, 5}, {}},  {26, true, 5, 8, {5, 5, 6}, {}},
    {30, false, 5, 6, {6, 6, 6}, {}}, {3, false, 0, 10, {10, 10, 10}, {}}, {7, true, 0, 11, {9, 9, 9}, {}},
    {11, true, 0, 12, {8, 8, 8}, {}}, {15, true, 0, 16, {4, 4, 4}, {}},
};
// Each mode's layout, in kBc6Modes' order (empty steps end a list).
constexpr Bc6Step kBc6Layouts[14][23] = {
    /*  0 */ {{7, 4, 1, 0}, {8, 4, 1, 0}, {11, 4, 1, 0}, {0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 5, 0},
                  {10, 4, 1, 0}, {7, 0, 4, 0}, {4, 0, 5, 0}, {11, 0, 1, 0}, {10, 0, 4, 0}, {5, 0, 5, 0},
                  {11, 1, 1, 0}, {8, 0, 4, 0}, {6, 0, 5, 0}, {11, 2, 1, 0}, {9, 0, 5, 0}, {11, 3, 1, 0}},
    /*  1 */ {{7, 5, 1, 0}, {10, 4, 1, 0}, {10, 5, 1, 0}, {0, 0, 7, 0}, {11, 0, 1, 0}, {11, 1, 1, 0}, {8, 4, 1, 0},
                  {1, 0, 7, 0}, {8, 5, 1, 0}, {11, 2, 1, 0}, {7, 4, 1, 0}, {2, 0, 7, 0}, {11, 3, 1, 0},
                  {11, 5, 1, 0}, {11, 4, 1, 0}, {3, 0, 6, 0}, {7, 0, 4, 0}, {4, 0, 6, 0}, {10, 0, 4, 0},
                  {5, 0, 6, 0}, {8, 0, 4, 0}, {6, 0, 6, 0}, {9, 0, 6, 0}},
    /*  2 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 5, 0}, {0, 10, 1, 0}, {7, 0, 4, 0}, {4, 0, 4, 0},
                  {1, 10, 1, 0}, {11, 0, 1, 0}, {10, 0, 4, 0}, {5, 0, 4, 0}, {2, 10, 1, 0}, {11, 1, 1, 0},
                  {8, 0, 4, 0}, {6, 0, 5, 0}, {11, 2, 1, 0}, {9, 0, 5, 0}, {11, 3, 1, 0}},
    /*  6 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 4, 0}, {0, 10, 1, 0}, {10, 4, 1, 0}, {7, 0, 4, 0},
                  {4, 0, 5, 0}, {1, 10, 1, 0}, {10, 0, 4, 0}, {5, 0, 4, 0}, {2, 10, 1, 0}, {11, 1, 1, 0},
                  {8, 0, 4, 0}, {6, 0, 4, 0}, {11, 0, 1, 0}, {11, 2, 1, 0}, {9, 0, 4, 0}, {7, 4, 1, 0},
                  {11, 3, 1, 0}},
    /* 10 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 4, 0}, {0, 10, 1, 0}, {8, 4, 1, 0}, {7, 0, 4, 0},
                  {4, 0, 4, 0}, {1, 10, 1, 0}, {11, 0, 1, 0}, {10, 0, 4, 0}, {5, 0, 5, 0}, {2, 10, 1, 0},
                  {8, 0, 4, 0}, {6, 0, 4, 0}, {11, 1, 1, 0}, {11, 2, 1, 0}, {9, 0, 4, 0}, {11, 4, 1, 0},
                  {11, 3, 1, 0}},
    /* 14 */ {{0, 0, 9, 0}, {8, 4, 1, 0}, {1, 0, 9, 0}, {7, 4, 1, 0}, {2, 0, 9, 0}, {11, 4, 1, 0}, {3, 0, 5, 0},
                  {10, 4, 1, 0}, {7, 0, 4, 0}, {4, 0, 5, 0}, {11, 0, 1, 0}, {10, 0, 4, 0}, {5, 0, 5, 0},
                  {11, 1, 1, 0}, {8, 0, 4, 0}, {6, 0, 5, 0}, {11, 2, 1, 0}, {9, 0, 5, 0}, {11, 3, 1, 0}},
    /* 18 */ {{0, 0, 8, 0}, {10, 4, 1, 0}, {8, 4, 1, 0}, {1, 0, 8, 0}, {11, 2, 1, 0}, {7, 4, 1, 0}, {2, 0, 8, 0},
                  {11, 3, 1, 0}, {11, 4, 1, 0}, {3, 0, 6, 0}, {7, 0, 4, 0}, {4, 0, 5, 0}, {11, 0, 1, 0},
                  {10, 0, 4, 0}, {5, 0, 5, 0}, {11, 1, 1, 0}, {8, 0, 4, 0}, {6, 0, 6, 0}, {9, 0, 6, 0}},
    /* 22 */ {{0, 0, 8, 0}, {11, 0, 1, 0}, {8, 4, 1, 0}, {1, 0, 8, 0}, {7, 5, 1, 0}, {7, 4, 1, 0}, {2, 0, 8, 0},
                  {10, 5, 1, 0}, {11, 4, 1, 0}, {3, 0, 5, 0}, {10, 4, 1, 0}, {7, 0, 4, 0}, {4, 0, 6, 0},
                  {10, 0, 4, 0}, {5, 0, 5, 0}, {11, 1, 1, 0}, {8, 0, 4, 0}, {6, 0, 5, 0}, {11, 2, 1, 0},
                  {9, 0, 5, 0}, {11, 3, 1, 0}},
    /* 26 */ {{0, 0, 8, 0}, {11, 1, 1, 0}, {8, 4, 1, 0}, {1, 0, 8, 0}, {8, 5, 1, 0}, {7, 4, 1, 0}, {2, 0, 8, 0},
                  {11, 5, 1, 0}, {11, 4, 1, 0}, {3, 0, 5, 0}, {10, 4, 1, 0}, {7, 0, 4, 0}, {4, 0, 5, 0},
                  {11, 0, 1, 0}, {10, 0, 4, 0}, {5, 0, 6, 0}, {8, 0, 4, 0}, {6, 0, 5, 0}, {11, 2, 1, 0},
                  {9, 0, 5, 0}, {11, 3, 1, 0}},
    /* 30 */ {{0, 0, 6, 0}, {10, 4, 1, 0}, {11, 0, 1, 0}, {11, 1, 1, 0}, {8, 4, 1, 0}, {1, 0, 6, 0}, {7, 5, 1, 0},
                  {8, 5, 1, 0}, {11, 2, 1, 0}, {7, 4, 1, 0}, {2, 0, 6, 0}, {10, 5, 1, 0}, {11, 3, 1, 0},
                  {11, 5, 1, 0}, {11, 4, 1, 0}, {3, 0, 6, 0}, {7, 0, 4, 0}, {4, 0, 6, 0}, {10, 0, 4, 0},
                  {5, 0, 6, 0}, {8, 0, 4, 0}, {6, 0, 6, 0}, {9, 0, 6, 0}},
    /*  3 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 10, 0}, {4, 0, 10, 0}, {5, 0, 10, 0}},
    /*  7 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 9, 0}, {0, 10, 1, 0}, {4, 0, 9, 0}, {1, 10, 1, 0},
                  {5, 0, 9, 0}, {2, 10, 1, 0}},
    /* 11 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 8, 0}, {0, 10, 2, 1}, {4, 0, 8, 0}, {1, 10, 2, 1},
                  {5, 0, 8, 0}, {2, 10, 2, 1}},
    /* 15 */ {{0, 0, 10, 0}, {1, 0, 10, 0}, {2, 0, 10, 0}, {3, 0, 4, 0}, {0, 10, 6, 1}, {4, 0, 4, 0}, {1, 10, 6, 1},
                  {5, 0, 4, 0}, {2, 10, 6, 1}},
};

int SignExtend(int v, int bits) { return bits >= 32 ? v : int(std::uint32_t(v) << (32 - bits)) >> (32 - bits); }

// The endpoint unquantization of BC6H (the extension's pseudocode): x of `bits` bits to a 16-bit range.
int Bc6Unquantize(int x, int bits, bool is_signed) {
  if (!is_signed) {
    if (bits >= 15) return x;
    if (x == 0) return 0;
    if (x == (1 << bits) - 1) return 0xFFFF;
    return ((x << 15) + 0x4000) >> (bits - 1);
  }
  if (bits >= 16) return x;
  const bool negative = x < 0;
  const int a = negative ? -x : x;
  int q = 0;
  if (a == 0) q = 0;
  else if (a >= (1 << (bits - 1)) - 1) q = 0x7FFF;
  else q = ((a << 15) + 0x4000) >> (bits - 1);
  return negative ? -q : q;
}

// Decodes a BC6H block into 16 RGB half floats a texel (alpha 1), as floats; a reserved mode gives (0, 0, 0, 1).
void Bc6hBlock(const std::uint8_t* block, bool is_signed, float out[16][4]) {
  BlockBits in{block};
  int number = in.Take(2);
  if (number >= 2) number |= in.Take(3) << 2;
  int m = 0;
  while (m < 14 && kBc6Modes[m].number != number) ++m;
  for (int t = 0; t < 16; ++t) out[t][0] = out[t][1] = out[t][2] = 0.0f, out[t][3] = 1.0f;
  if (m == 14) return;
  const Bc6Mode& mode = kBc6Modes[m];
  int e[12] = {};
  for (const Bc6Step& step : kBc6Layouts[m]) {
    for (int i = 0; i < step.count; ++i) {
      const int bit = step.reversed ? step.lo + step.count - 1 - i : step.lo + i;
      e[step.field] |= in.Take(1) << bit;
    }
  }
  const int subsets = mode.partition_bits ? 2 : 1;
  const int partition = in.Take(mode.partition_bits);
  const int bits = mode.endpoint_bits, mask = (1 << bits) - 1;
  for (int c = 0; c < 3; ++c) {
    if (is_signed) e[c] = SignExtend(e[c], bits);
    for (int k = 1; k < 2 * subsets; ++k) {
      int& v = e[3 * k + c];
      if (mode.transformed) {
        v = (e[c] + SignExtend(v, mode.delta_bits[c])) & mask;
        if (is_signed) v = SignExtend(v, bits);
      } else if (is_signed) {
        v = SignExtend(v, bits);
      }
    }
  }
  for (int& v : e) v = Bc6Unquantize(v, bits, is_signed);
  const int index_bits = subsets == 2 ? 3 : 4;
  for (int t = 0; t < 16; ++t) {
    const int s = subsets == 2 ? (kShapes2[partition] >> t) & 1 : 0;
    const bool anchor = t == 0 || (subsets == 2 && t == kAnchor2[partition]);
    const int index = in.Take(index_bits - (anchor ? 1 : 0));
    for (int c = 0; c < 3; ++c) {
      const int v = Interpolate(e[6 * s + c], e[6 * s + 3 + c], index, index_bits);
      std::uint16_t h;
      if (!is_signed) h = std::uint16_t((v * 31) >> 6);
      else h = std::uint16_t(v < 0 ? ((-v * 31) >> 5) | 0x8000 : (v * 31) >> 5);
      out[t][c] = HalfToFloat(h);
    }
  }
}

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
    case Kind::kBc7: Bc7Block(block, out); return;
    case Kind::kBc6hSigned: Bc6hBlock(block, true, out); return;
    case Kind::kBc6hUnsigned: Bc6hBlock(block, false, out); return;
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
          } else if (level.layout == TexelLayout::kFloat16x4) {  // BC6H: its halves, exactly
            for (int ch = 0; ch < 4; ++ch) {
              const std::uint16_t h = FloatToHalf(texels[t][ch]);
              std::memcpy(p + 2 * ch, &h, 2);
            }
          } else {
            // (RGB8 and SRGB8 keep four bytes a texel, their alpha 255.)
            for (int ch = 0; ch < level.bytes; ++ch) p[ch] = std::uint8_t(texels[t][ch]);
          }
        }
      }
}

}  // namespace softgl::detail

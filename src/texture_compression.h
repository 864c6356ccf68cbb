// texture_compression.h — compressed texture formats: block sizes, image sizes and decoding.
//
// softgl decodes compressed images when they are defined (CompressedTexImage*, CompressedTexSubImage*) into an
// ordinary level format, which every sampling path then reads as it reads any other level; the level also keeps
// the blocks as given, for GetCompressedTexImage and TEXTURE_COMPRESSED_IMAGE_SIZE. A compressed level so costs its
// decoded size (4 bytes a texel for S3TC and BC7, 1 or 2 for unsigned RGTC, 4 or 8 for signed RGTC, 8 for BC6H's
// RGBA16F) plus its blocks (half a byte or one byte a texel).
//
// Each format's texels are 4 x 4 blocks, rows of blocks from the image's first row (the bottom, as OpenGL orders
// rows), a block's texels row by row from its own first row; blocks past the image's right or top edge are whole
// blocks whose extra texels are dropped. The decoded values are 8-bit (sRGB-encoded for the sRGB forms, decoded when
// sampled), or for signed RGTC floats k / 127 of the 8-bit signed result (-128 reads -1). The formats leave the
// interpolation's precision to the implementation; softgl's is llvmpipe's, texel for texel, and within one unit of
// the exact fractions. Mix(a, b, k, n), k / n of the way from a to b, is (a (256 - w) + b w) / 256 rounded down,
// with the 8-bit weight w = floor(255 k / n):
//
// - S3TC colour (DXT1, and the colour half of DXT3 and DXT5): two RGB565 colours c0, c1 (little-endian words),
//   widened to 8 bits by repeating their high bits, and 2 bits an index: 0 c0, 1 c1, and with c0 > c1 as words (or
//   always, for DXT3 and DXT5) 2 Mix(c0, c1, 1, 3) and 3 Mix(c0, c1, 2, 3), otherwise 2 (c0 + c1 + 1) / 2 rounded
//   down and 3 black (alpha 0 for the RGBA forms of DXT1), per channel.
// - DXT3 alpha: 4 bits a texel, widened to 8 by repeating them.
// - DXT5 alpha and RGTC channels: two 8-bit endpoints a0, a1 (signed bytes for signed RGTC) and 3 bits an index: 0
//   a0, 1 a1, and with a0 > a1 index i in 2..7 Mix(a0, a1, i - 1, 7), otherwise i in 2..5 Mix(a0, a1, i - 1, 5), 6
//   the least value (0, or -127 signed) and 7 the greatest (255, or 127).
// - BC7 (BPTC's RGBA forms) defines its arithmetic itself: endpoints (with their p-bits) widened to 8 bits by
//   repeating their high bits, and index i of a 2-, 3- or 4-bit set the weight w = BC7's table value (of 64), giving
//   ((64 - w) e0 + w e1 + 32) / 64 rounded down; a block whose first byte has no mode bit decodes to transparent
//   black.
// - BC6H (BPTC's float forms) too: endpoints (deltas from the first in most modes, sign-extended for the signed
//   form) unquantized to 16 bits, interpolated as BC7's, then scaled by 31 / 64 (unsigned) or 31 / 32 (signed,
//   on the magnitude) into a half float's bits, kept exactly in an RGBA16F level (alpha 1); a reserved mode
//   decodes to (0, 0, 0, 1).
#pragma once

#include <cstddef>
#include <cstdint>

#include <softgl/enums.h>

namespace softgl::detail {

struct TextureLevel;

/// A compressed format: its enum, its block's bytes, the level format it decodes into, and its kind.
struct CompressedFormat {
  enum class Kind : std::uint8_t {
    kDxt1Rgb, kDxt1Rgba, kDxt3, kDxt5, kRgtc1, kRgtc1Signed, kRgtc2, kRgtc2Signed, kBc7, kBc6hSigned, kBc6hUnsigned
  };
  Enum format;
  int block_bytes;  // 8 or 16
  Enum decoded;     // RGB8, RGBA8, SRGB8, SRGB8_ALPHA8, R8, RG8, R32F, RG32F or RGBA16F (BC6H)
  Kind kind;
};

/// The compressed format `f`, or null when `f` is not one softgl decodes.
const CompressedFormat* CompressedFormatOf(Enum f);

/// COMPRESSED_TEXTURE_FORMATS: the formats OpenGL lists there (RGTC's are left out, as OpenGL 3.3 says).
inline constexpr Enum kListedCompressedFormats[4] = {COMPRESSED_RGB_S3TC_DXT1_EXT, COMPRESSED_RGBA_S3TC_DXT1_EXT,
                                                     COMPRESSED_RGBA_S3TC_DXT3_EXT, COMPRESSED_RGBA_S3TC_DXT5_EXT};

/// The sized format TexImage* stores a generic compressed format in (COMPRESSED_RGBA as RGBA8, ...), or `f`.
Enum UncompressedForGeneric(Enum f);

/// The bytes of a w x h x d image's blocks: ceil(w / 4) * ceil(h / 4) blocks a plane.
std::uint64_t CompressedImageBytes(const CompressedFormat& f, int w, int h, int d);

/// Decodes one block into 16 texels, row by row from the block's first row, in storage units: channel bytes 0..255
/// as floats for the 8-bit formats, the values for signed RGTC; channels the format lacks read 0 (alpha 255).
void DecodeBlock(const CompressedFormat& f, const std::uint8_t* block, float out[16][4]);

/// Decodes the blocks of a w x h x d region (CompressedImageBytes(f, w, h, d) bytes at `blocks`) into `level`
/// (allocated in f.decoded) at texel (x, y) of planes z .. z + d - 1, dropping texels past the level's edges, and
/// copies them into level.blocks, which must hold the whole level's blocks.
void DecodeRegion(const CompressedFormat& f, const std::uint8_t* blocks, int x, int y, int z, int w, int h, int d,
                  TextureLevel& level);

}  // namespace softgl::detail

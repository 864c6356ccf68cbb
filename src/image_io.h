// image_io.h — decoding image files for textures: 8-bit PNG, TGA, BMP and float HDR (stb_image), JPEG (libjpeg-turbo),
// and DDS files of S3TC or RGTC blocks (read here: their blocks go to CompressedTexImage2D as they are).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <softgl/enums.h>

namespace softgl::detail {

/// One mipmap level of a compressed image: its size and its blocks (texture_compression.h orders them).
struct CompressedImageLevel {
  int width = 0, height = 0;
  std::vector<std::uint8_t> blocks;
};

struct LoadedImage {
  int width = 0, height = 0, channels = 0;  // channels: 1 to 4 as stored in the file (HDR: 3 or 4)
  bool hdr = false;                         // floats (Radiance HDR) instead of bytes
  std::vector<std::uint8_t> bytes;          // [height][width][channels], rows bottom first when flipped
  std::vector<float> floats;
  // A DDS file of S3TC or RGTC blocks: its format (COMPRESSED_RGBA_S3TC_DXT1_EXT ... COMPRESSED_SIGNED_RG_RGTC2; an
  // sRGB form where the file says sRGB, or where `srgb` asks for it and the format has one) and every level the
  // file holds, level 0 first; width, height and channels are level 0's (channels 4). 0 for other files.
  Enum compressed = 0;
  std::vector<CompressedImageLevel> levels;
};

/// Decodes `path`. Decoders return the top row first; flip_vertically puts the bottom row first, which is where
/// OpenGL's texture coordinate t = 0 is (for a DDS file, by reordering the blocks and the rows inside them, which
/// needs each level's height a multiple of 4, or below 4, and is refused for BC7). Returns false with a message for
/// a missing, truncated or corrupt file, or a DDS file softgl cannot take (BC6H, cube maps, volumes, arrays,
/// uncompressed data). `srgb` picks the sRGB form of a DDS file's S3TC or BC7 format.
bool LoadImageFile(const std::string& path, bool flip_vertically, LoadedImage& out, std::string* error,
                   bool srgb = false);

/// Reads a DDS file (`size` bytes at d, "DDS " first) into out.compressed and out.levels; null, or why it cannot.
const char* ReadDds(const std::uint8_t* d, std::size_t size, bool flip_vertically, bool srgb, LoadedImage& out);

/// As LoadImageFile, from an encoded image in memory; `name` labels error messages.
bool LoadImageMemory(const void* data, std::size_t size, const std::string& name, bool flip_vertically,
                     LoadedImage& out, std::string* error, bool srgb = false);

}  // namespace softgl::detail

// image_io.h — decoding image files for textures: 8-bit PNG, TGA, BMP and float HDR (stb_image), JPEG (libjpeg-turbo).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace softgl::detail {

struct LoadedImage {
  int width = 0, height = 0, channels = 0;  // channels: 1 to 4 as stored in the file (HDR: 3 or 4)
  bool hdr = false;                         // floats (Radiance HDR) instead of bytes
  std::vector<std::uint8_t> bytes;          // [height][width][channels], rows bottom first when flipped
  std::vector<float> floats;
};

/// Decodes `path`. Decoders return the top row first; flip_vertically puts the bottom row first, which is where
/// OpenGL's texture coordinate t = 0 is. Returns false with a message for a missing, truncated or corrupt file.
bool LoadImageFile(const std::string& path, bool flip_vertically, LoadedImage& out, std::string* error);

/// As LoadImageFile, from an encoded image in memory; `name` labels error messages.
bool LoadImageMemory(const void* data, std::size_t size, const std::string& name, bool flip_vertically,
                     LoadedImage& out, std::string* error);

}  // namespace softgl::detail

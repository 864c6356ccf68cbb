// softgl/image.h — an RGBA8 image in memory, and PNG output.
#pragma once

#include <softgl/config.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace softgl {

/// An 8-bit RGBA image. Rows are stored top row first, as in image files (the reverse of OpenGL's window
/// coordinates, whose row 0 is the bottom one): Context::ReadPixels() does the flip.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row-major, top row first.

  /// The pixel at column x, row y counted from the top, as {r, g, b, a}. No bounds check beyond an assert.
  const std::uint8_t* At(int x, int y) const { return rgba.data() + (std::size_t(y) * width + x) * 4; }
};

/// Writes `image` to a PNG file. Returns false if the image is empty or the file cannot be written whole (a
/// partly written file is removed).
bool WritePng(const std::string& path, const Image& image);

/// Reads a PNG (or JPEG, TGA, BMP, HDR: any format TexImage2DFromFile reads) into an RGBA8 image. Returns false,
/// with a message in `error` when given, for a missing or corrupt file.
bool ReadImage(const std::string& path, Image& image, std::string* error = nullptr);

/// The size and channel count an encoded image (PNG, JPEG, TGA, BMP, HDR, ...) declares, read from its header
/// without decoding it: check it against your own budget before loading an untrusted image (a 100-byte TGA can
/// declare 16384 x 16384 pixels). Returns false when the bytes are not an image softgl recognizes (or
/// a JPEG whose header is corrupt).
bool ReadImageInfo(const void* data, std::size_t size, int* width, int* height, int* channels);

}  // namespace softgl

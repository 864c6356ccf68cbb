// image_io.cpp — PNG output and image decoding through stb_image_write and stb_image (Debian's libstb-dev).
#include <softgl/image.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_MAX_DIMENSIONS 16384  // kMaxTextureSize: larger images are refused before anything is decoded
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "image_io.h"

namespace softgl {

bool WritePng(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
    return false;
  // Encoded in memory, then written; a write that fails (a full disk, say) leaves no partial file behind.
  int size = 0;
  unsigned char* png = stbi_write_png_to_mem(image.rgba.data(), image.width * 4, image.width, image.height, 4, &size);
  if (png == nullptr) return false;
  bool ok = false;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    ok = out && out.write(reinterpret_cast<const char*>(png), std::streamsize(size)) && out.flush();
  }
  STBIW_FREE(png);
  std::error_code ec;
  if (!ok && std::filesystem::is_regular_file(path, ec)) std::filesystem::remove(path, ec);
  return ok;
}

bool ReadImage(const std::string& path, Image& image, std::string* error) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (pixels == nullptr) {
    if (error) *error = path + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "cannot read image");
    return false;
  }
  image.width = w;
  image.height = h;
  image.rgba.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(pixels);
  return true;
}

namespace detail {
namespace {
bool JpegHuffmanTablesValid(const std::uint8_t* d, std::size_t size);
}  // namespace
}  // namespace detail

bool ReadImageInfo(const void* data, std::size_t size, int* width, int* height, int* channels) {
  int w = 0, h = 0, n = 0;
  if (data == nullptr || size == 0 || size > std::size_t(INT32_MAX) ||
      !detail::JpegHuffmanTablesValid(static_cast<const std::uint8_t*>(data), size) ||
      !stbi_info_from_memory(static_cast<const stbi_uc*>(data), int(size), &w, &h, &n))
    return false;
  if (width) *width = w;
  if (height) *height = h;
  if (channels) *channels = n;
  return true;
}

namespace detail {

namespace {

// Decodes through the given stb calls (file or memory), then flips when asked.
template <class Info, class IsHdr, class LoadF, class Load8>
bool Decode(const std::string& name, bool flip_vertically, LoadedImage& out, std::string* error, Info info, IsHdr is_hdr,
            LoadF loadf, Load8 load8) {
  int w = 0, h = 0, n = 0;
  out = LoadedImage{};
  auto fail = [&](const char* what) {
    if (error) *error = name + ": " + (stbi_failure_reason() ? stbi_failure_reason() : what);
    return false;
  };
  if (!info(&w, &h, &n)) return fail("cannot read image");
  out.hdr = is_hdr();
  std::size_t row_bytes = 0;
  if (out.hdr) {
    float* data = loadf(&w, &h, &n);
    if (!data) return fail("cannot decode image");
    out.floats.assign(data, data + std::size_t(w) * std::size_t(h) * std::size_t(n));
    stbi_image_free(data);
    row_bytes = std::size_t(w) * std::size_t(n) * sizeof(float);
  } else {
    stbi_uc* data = load8(&w, &h, &n);
    if (!data) return fail("cannot decode image");
    out.bytes.assign(data, data + std::size_t(w) * std::size_t(h) * std::size_t(n));
    stbi_image_free(data);
    row_bytes = std::size_t(w) * std::size_t(n);
  }
  if (w <= 0 || h <= 0 || n < 1 || n > 4) {
    out = LoadedImage{};
    if (error) *error = name + ": empty image";
    return false;
  }
  out.width = w;
  out.height = h;
  out.channels = n;
  if (flip_vertically) {
    auto* base = out.hdr ? reinterpret_cast<std::uint8_t*>(out.floats.data()) : out.bytes.data();
    std::vector<std::uint8_t> tmp(row_bytes);
    for (int y = 0; y < h / 2; ++y) {
      std::uint8_t* a = base + std::size_t(y) * row_bytes;
      std::uint8_t* b = base + std::size_t(h - 1 - y) * row_bytes;
      std::memcpy(tmp.data(), a, row_bytes);
      std::memcpy(a, b, row_bytes);
      std::memcpy(b, tmp.data(), row_bytes);
    }
  }
  return true;
}

// stb_image 2.27 trusts the code counts of a JPEG Huffman table and writes past its tables when they add up to more
// than 256 (found by fuzz_image). For any file stb would read as a JPEG (0xFF bytes, then SOI), every DHT marker in
// the file is checked the way stb reads it, bytes past the end reading as zero; such a file is corrupt anyway.
// (Compressed scan data cannot hold 0xFF 0xC4: a 0xFF there is always followed by 0x00 or a marker.)
bool JpegHuffmanTablesValid(const std::uint8_t* d, std::size_t size) {
  auto at = [&](std::size_t i) -> std::size_t { return i < size ? d[i] : 0; };
  std::size_t p = 0;
  if (at(0) != 0xFF) return true;
  while (p < size && d[p] == 0xFF) ++p;
  if (at(p) != 0xD8) return true;  // not a JPEG to stb
  for (std::size_t i = p; i + 1 < size; ++i) {
    if (d[i] != 0xFF || d[i + 1] != 0xC4) continue;
    const std::size_t length = (at(i + 2) << 8) | at(i + 3);
    std::size_t q = i + 4;
    for (std::size_t left = length >= 2 ? length - 2 : 0; left > 0;) {
      std::size_t total = 0;
      for (std::size_t k = 1; k <= 16; ++k) total += at(q + k);
      if (total > 256) return false;
      if (left < 17 + total) break;
      left -= 17 + total;
      q += 17 + total;
    }
  }
  return true;
}

bool Check(const std::uint8_t* d, std::size_t size, const std::string& name, std::string* error) {
  if (JpegHuffmanTablesValid(d, size)) return true;
  if (error) *error = name + ": corrupt JPEG (a Huffman table has more than 256 codes)";
  return false;
}

}  // namespace

bool LoadImageFile(const std::string& path, bool flip_vertically, LoadedImage& out, std::string* error) {
  // Read whole, then decode from memory: the same checks for files and for embedded images.
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    if (error) *error = path + ": cannot open file";
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return LoadImageMemory(bytes.data(), bytes.size(), path, flip_vertically, out, error);
}

bool LoadImageMemory(const void* data, std::size_t size, const std::string& name, bool flip_vertically,
                     LoadedImage& out, std::string* error) {
  if (data == nullptr || size == 0 || size > std::size_t(INT32_MAX)) {
    if (error) *error = name + ": empty or oversized image data";
    return false;
  }
  const auto* d = static_cast<const stbi_uc*>(data);
  const int len = int(size);
  if (!Check(d, size, name, error)) return false;
  return Decode(
      name, flip_vertically, out, error, [&](int* w, int* h, int* n) { return stbi_info_from_memory(d, len, w, h, n); },
      [&] { return stbi_is_hdr_from_memory(d, len) != 0; },
      [&](int* w, int* h, int* n) { return stbi_loadf_from_memory(d, len, w, h, n, 0); },
      [&](int* w, int* h, int* n) { return stbi_load_from_memory(d, len, w, h, n, 0); });
}

}  // namespace detail

}  // namespace softgl

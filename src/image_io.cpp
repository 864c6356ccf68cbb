// image_io.cpp — PNG output and image decoding: stb_image_write and stb_image (Debian's libstb-dev), and
// libjpeg-turbo for JPEG (docs/testing.md says why: stb_image 2.27 misbehaves on corrupt JPEG files).
#include <softgl/image.h>

#include <csetjmp>
#include <cstdio>  // (jpeglib.h needs FILE declared)
#include <cstdlib>

#include <jpeglib.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_MAX_DIMENSIONS 16384  // kMaxTextureSize: larger images are refused before anything is decoded
#define STBI_FAILURE_USERMSG
// The formats softgl documents, and no more: each of stb's decoders is code a hostile file can reach (its PNM
// parser's integers overflow, found by fuzz_image). JPEG goes to libjpeg-turbo.
#define STBI_ONLY_PNG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_ONLY_HDR
// stb's decoder state starts zeroed: whatever of it a corrupt file leaves unset reads the same on every machine.
#define STBI_MALLOC(size) std::calloc(1, size)
#define STBI_REALLOC(pointer, size) std::realloc(pointer, size)
#define STBI_FREE(pointer) std::free(pointer)
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

namespace detail {

namespace {

bool IsJpeg(const std::uint8_t* d, std::size_t size) { return size >= 2 && d[0] == 0xFF && d[1] == 0xD8; }

// libjpeg reports a fatal error through error_exit, which must not return: it jumps back to Jpeg::Read, whose frame
// holds no object with a destructor between the jump and its target. Warnings (data libjpeg recovers from, such as
// a truncated scan, whose rest decodes grey) are not printed.
struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};
[[noreturn]] void JpegFail(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  errors->manager.format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}
void JpegQuiet(j_common_ptr, int) {}

// A JPEG's header or its pixels (top row first): grey files give one channel, any other three (CMYK converted).
struct Jpeg {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint8_t> row;  // one CMYK row
  char message[JMSG_LENGTH_MAX] = {};

  bool Read(const std::uint8_t* d, std::size_t size, bool decode) {
    jpeg_decompress_struct info;
    JpegErrors errors;
    info.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = JpegFail;
    errors.manager.emit_message = JpegQuiet;
    if (setjmp(errors.jump)) {
      std::memcpy(message, errors.message, sizeof(message));
      jpeg_destroy_decompress(&info);
      return false;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, d, static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    if (info.image_width > STBI_MAX_DIMENSIONS || info.image_height > STBI_MAX_DIMENSIONS) {
      std::snprintf(message, sizeof(message), "JPEG of %u x %u pixels, more than %d a side", info.image_width,
                    info.image_height, STBI_MAX_DIMENSIONS);
      jpeg_destroy_decompress(&info);
      return false;
    }
    const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
    info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : cmyk ? JCS_CMYK : JCS_RGB;
    width = int(info.image_width);
    height = int(info.image_height);
    channels = info.num_components == 1 ? 1 : 3;
    if (decode) {
      const std::size_t stride = std::size_t(width) * std::size_t(channels);
      try {
        bytes.assign(stride * std::size_t(height), 0);
        row.assign(cmyk ? std::size_t(width) * 4 : 0, 0);
      } catch (...) {
        jpeg_destroy_decompress(&info);
        throw;
      }
      jpeg_start_decompress(&info);
      // Adobe's CMYK files store the inks inverted (255 no ink): red = C K / 255 then; other files are inverted here.
      const unsigned invert = info.saw_Adobe_marker ? 0 : 255;
      while (info.output_scanline < info.output_height) {
        std::uint8_t* out = bytes.data() + std::size_t(info.output_scanline) * stride;
        JSAMPROW target = cmyk ? row.data() : out;
        jpeg_read_scanlines(&info, &target, 1);
        for (std::size_t x = 0; cmyk && x < std::size_t(width); ++x) {
          const unsigned k = row[x * 4 + 3] ^ invert;
          for (int c = 0; c < 3; ++c) out[x * 3 + c] = std::uint8_t(((row[x * 4 + c] ^ invert) * k + 127) / 255);
        }
      }
      jpeg_finish_decompress(&info);
    }
    jpeg_destroy_decompress(&info);
    return true;
  }
};

// Checks the decoded size and flips the rows when asked.
bool Finish(const std::string& name, bool flip_vertically, LoadedImage& out, std::string* error) {
  const int w = out.width, h = out.height, n = out.channels;
  if (w <= 0 || h <= 0 || n < 1 || n > 4) {
    out = LoadedImage{};
    if (error) *error = name + ": empty image";
    return false;
  }
  if (flip_vertically) {
    const std::size_t row_bytes = std::size_t(w) * std::size_t(n) * (out.hdr ? sizeof(float) : 1);
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

// Decodes through the given stb calls, then checks and flips.
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
  if (out.hdr) {
    float* data = loadf(&w, &h, &n);
    if (!data) return fail("cannot decode image");
    out.floats.assign(data, data + std::size_t(w) * std::size_t(h) * std::size_t(n));
    stbi_image_free(data);
  } else {
    stbi_uc* data = load8(&w, &h, &n);
    if (!data) return fail("cannot decode image");
    out.bytes.assign(data, data + std::size_t(w) * std::size_t(h) * std::size_t(n));
    stbi_image_free(data);
  }
  out.width = w;
  out.height = h;
  out.channels = n;
  return Finish(name, flip_vertically, out, error);
}

}  // namespace

}  // namespace detail

bool ReadImage(const std::string& path, Image& image, std::string* error) {
  detail::LoadedImage loaded;
  std::ifstream file(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto* d = reinterpret_cast<const std::uint8_t*>(bytes.data());
  if (file && detail::IsJpeg(d, bytes.size())) {
    if (!detail::LoadImageMemory(bytes.data(), bytes.size(), path, false, loaded, error)) return false;
    image.width = loaded.width;
    image.height = loaded.height;
    image.rgba.resize(std::size_t(loaded.width) * std::size_t(loaded.height) * 4);
    const int n = loaded.channels;  // 1 or 3
    for (std::size_t i = 0; i < image.rgba.size() / 4; ++i)
      for (int c = 0; c < 4; ++c) image.rgba[i * 4 + c] = c == 3 ? 255 : loaded.bytes[i * n + (n == 1 ? 0 : c)];
    return true;
  }
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = file && !bytes.empty() && bytes.size() <= std::size_t(INT32_MAX)
                        ? stbi_load_from_memory(d, int(bytes.size()), &w, &h, &channels, 4)
                        : nullptr;
  if (pixels == nullptr) {
    if (error) *error = path + ": " + (!file ? "cannot open file" : stbi_failure_reason() ? stbi_failure_reason() : "cannot read image");
    return false;
  }
  image.width = w;
  image.height = h;
  image.rgba.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
  stbi_image_free(pixels);
  return true;
}

bool ReadImageInfo(const void* data, std::size_t size, int* width, int* height, int* channels) {
  int w = 0, h = 0, n = 0;
  const auto* d = static_cast<const std::uint8_t*>(data);
  if (data == nullptr || size == 0 || size > std::size_t(INT32_MAX)) return false;
  if (detail::IsJpeg(d, size)) {
    detail::Jpeg jpeg;
    if (!jpeg.Read(d, size, false)) return false;
    w = jpeg.width;
    h = jpeg.height;
    n = jpeg.channels;
  } else if (!stbi_info_from_memory(d, int(size), &w, &h, &n)) {
    return false;
  }
  if (width) *width = w;
  if (height) *height = h;
  if (channels) *channels = n;
  return true;
}

namespace detail {

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
  if (IsJpeg(d, size)) {
    Jpeg jpeg;
    out = LoadedImage{};
    if (!jpeg.Read(d, size, true)) {
      if (error) *error = name + ": corrupt JPEG (" + jpeg.message + ")";
      return false;
    }
    out.width = jpeg.width;
    out.height = jpeg.height;
    out.channels = jpeg.channels;
    out.bytes = std::move(jpeg.bytes);
    return Finish(name, flip_vertically, out, error);
  }
  return Decode(
      name, flip_vertically, out, error, [&](int* w, int* h, int* n) { return stbi_info_from_memory(d, len, w, h, n); },
      [&] { return stbi_is_hdr_from_memory(d, len) != 0; },
      [&](int* w, int* h, int* n) { return stbi_loadf_from_memory(d, len, w, h, n, 0); },
      [&](int* w, int* h, int* n) { return stbi_load_from_memory(d, len, w, h, n, 0); });
}

}  // namespace detail

}  // namespace softgl

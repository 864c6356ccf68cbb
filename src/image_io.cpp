// image_io.cpp — PNG output and image decoding: stb_image_write and stb_image (Debian's libstb-dev), and
// libjpeg-turbo for JPEG (docs/testing.md says why: stb_image 2.27 misbehaves on corrupt JPEG files).
#include <softgl/image.h>
#include <softgl/texture.h>

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
#include <algorithm>
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

namespace {

std::uint32_t Le32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

constexpr std::uint32_t FourCc(const char (&c)[5]) {
  return std::uint32_t(std::uint8_t(c[0])) | std::uint32_t(std::uint8_t(c[1])) << 8 |
         std::uint32_t(std::uint8_t(c[2])) << 16 | std::uint32_t(std::uint8_t(c[3])) << 24;
}

// The compressed format of a DDS pixel format (its FourCC, or with "DX10" the DXGI format), 0 for one softgl does
// not take; `why` says which kind that is.
Enum DdsFormat(std::uint32_t four_cc, std::uint32_t dxgi, bool alpha_pixels, const char*& why) {
  why = "not a block-compressed DDS file softgl takes (S3TC: DXT1 to DXT5, RGTC: ATI1, ATI2, BC4U/S, BC5U/S, BC6H, BC7)";
  if (four_cc == FourCc("DX10")) {
    switch (dxgi) {
      case 70: case 71: return COMPRESSED_RGBA_S3TC_DXT1_EXT;  // BC1_TYPELESS, BC1_UNORM
      case 72: return COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;      // BC1_UNORM_SRGB
      case 73: case 74: return COMPRESSED_RGBA_S3TC_DXT3_EXT;
      case 75: return COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;
      case 76: case 77: return COMPRESSED_RGBA_S3TC_DXT5_EXT;
      case 78: return COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT;
      case 79: case 80: return COMPRESSED_RED_RGTC1;
      case 81: return COMPRESSED_SIGNED_RED_RGTC1;
      case 82: case 83: return COMPRESSED_RG_RGTC2;
      case 84: return COMPRESSED_SIGNED_RG_RGTC2;
      case 97: case 98: return COMPRESSED_RGBA_BPTC_UNORM;  // BC7_TYPELESS, BC7_UNORM
      case 99: return COMPRESSED_SRGB_ALPHA_BPTC_UNORM;        // BC7_UNORM_SRGB
      case 94: case 95: return COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT;  // BC6H_TYPELESS, BC6H_UF16
      case 96: return COMPRESSED_RGB_BPTC_SIGNED_FLOAT;               // BC6H_SF16
      default: return 0;
    }
  }
  if (four_cc == FourCc("DXT1")) return alpha_pixels ? COMPRESSED_RGBA_S3TC_DXT1_EXT : COMPRESSED_RGB_S3TC_DXT1_EXT;
  if (four_cc == FourCc("DXT2") || four_cc == FourCc("DXT3")) return COMPRESSED_RGBA_S3TC_DXT3_EXT;
  if (four_cc == FourCc("DXT4") || four_cc == FourCc("DXT5")) return COMPRESSED_RGBA_S3TC_DXT5_EXT;
  if (four_cc == FourCc("ATI1") || four_cc == FourCc("BC4U")) return COMPRESSED_RED_RGTC1;
  if (four_cc == FourCc("BC4S")) return COMPRESSED_SIGNED_RED_RGTC1;
  if (four_cc == FourCc("ATI2") || four_cc == FourCc("BC5U")) return COMPRESSED_RG_RGTC2;
  if (four_cc == FourCc("BC5S")) return COMPRESSED_SIGNED_RG_RGTC2;
  return 0;
}

Enum SrgbFormOf(Enum f) {
  switch (f) {
    case COMPRESSED_RGB_S3TC_DXT1_EXT: return COMPRESSED_SRGB_S3TC_DXT1_EXT;
    case COMPRESSED_RGBA_S3TC_DXT1_EXT: return COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;
    case COMPRESSED_RGBA_S3TC_DXT3_EXT: return COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;
    case COMPRESSED_RGBA_S3TC_DXT5_EXT: return COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT;
    case COMPRESSED_RGBA_BPTC_UNORM: return COMPRESSED_SRGB_ALPHA_BPTC_UNORM;
    default: return f;  // (RGTC has no sRGB form)
  }
}

// Reverses rows 0 .. n - 1 of one block, given as 4 rows of `row_bits` bits each from bit `first` of the block.
void FlipBlockRows(std::uint8_t* block, int first, int row_bits, int n) {
  std::uint64_t bits = 0;
  const int bytes = row_bits / 2;  // 4 rows: row_bits * 4 / 8
  for (int k = 0; k < bytes; ++k) bits |= std::uint64_t(block[first / 8 + k]) << (8 * k);
  const std::uint64_t mask = (std::uint64_t(1) << row_bits) - 1;
  std::uint64_t flipped = bits;
  for (int r = 0; r < n; ++r) {
    const std::uint64_t row = (bits >> (row_bits * r)) & mask;
    flipped &= ~(mask << (row_bits * (n - 1 - r)));
    flipped |= row << (row_bits * (n - 1 - r));
  }
  for (int k = 0; k < bytes; ++k) block[first / 8 + k] = std::uint8_t(flipped >> (8 * k));
}

// Turns a level's blocks upside down (its bottom row first): block rows reversed, and each block's n rows (4, or
// the height below 4). False where the height is above 4 and not a multiple of it.
bool FlipLevel(Enum format, CompressedImageLevel& level, int block_bytes) {
  if (level.height > 4 && level.height % 4 != 0) return false;
  const int n = std::min(level.height, 4);
  const int across = (level.width + 3) / 4, up = (level.height + 3) / 4;
  const std::size_t row = std::size_t(across) * std::size_t(block_bytes);
  for (int b = 0; b < up / 2; ++b)
    std::swap_ranges(level.blocks.begin() + std::ptrdiff_t(b * row), level.blocks.begin() + std::ptrdiff_t((b + 1) * row),
                     level.blocks.begin() + std::ptrdiff_t((up - 1 - b) * row));
  for (std::size_t at = 0; at + std::size_t(block_bytes) <= level.blocks.size(); at += std::size_t(block_bytes)) {
    std::uint8_t* block = level.blocks.data() + at;
    switch (format) {
      case COMPRESSED_RED_RGTC1:
      case COMPRESSED_SIGNED_RED_RGTC1: FlipBlockRows(block, 16, 12, n); break;
      case COMPRESSED_RG_RGTC2:
      case COMPRESSED_SIGNED_RG_RGTC2:
        FlipBlockRows(block, 16, 12, n);
        FlipBlockRows(block + 8, 16, 12, n);
        break;
      case COMPRESSED_RGBA_S3TC_DXT3_EXT:
      case COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT:
        FlipBlockRows(block, 0, 16, n);
        FlipBlockRows(block + 8, 32, 8, n);
        break;
      case COMPRESSED_RGBA_S3TC_DXT5_EXT:
      case COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT:
        FlipBlockRows(block, 16, 12, n);
        FlipBlockRows(block + 8, 32, 8, n);
        break;
      default: FlipBlockRows(block, 32, 8, n); break;  // DXT1
    }
  }
  return true;
}

}  // namespace

const char* ReadDds(const std::uint8_t* d, std::size_t size, bool flip_vertically, bool srgb, LoadedImage& out) {
  constexpr std::size_t kHeader = 128, kHeader10 = 20;
  if (size < kHeader || Le32(d + 4) != 124) return "truncated or corrupt DDS header";
  const std::uint32_t flags = Le32(d + 8), height = Le32(d + 12), width = Le32(d + 16);
  const std::uint32_t mips = Le32(d + 28), pf_flags = Le32(d + 80), four_cc = Le32(d + 84), caps2 = Le32(d + 112);
  constexpr std::uint32_t kFourCcFlag = 0x4, kAlphaPixels = 0x1, kMipMapCount = 0x20000, kCubeMap = 0x200,
                          kVolume = 0x200000;
  if (!(pf_flags & kFourCcFlag)) return "uncompressed DDS files are not supported (use PNG or another image format)";
  if (caps2 & kCubeMap) return "DDS cube maps are not supported (load each face as its own file)";
  if (caps2 & kVolume) return "DDS volume textures are not supported";
  std::size_t at = kHeader;
  std::uint32_t dxgi = 0;
  if (four_cc == FourCc("DX10")) {
    if (size < kHeader + kHeader10) return "truncated DDS header";
    dxgi = Le32(d + 128);
    if (Le32(d + 140) > 1) return "DDS texture arrays are not supported";
    at += kHeader10;
  }
  const char* why = nullptr;
  Enum format = DdsFormat(four_cc, dxgi, (pf_flags & kAlphaPixels) != 0, why);
  if (format == 0) return why;
  if (srgb) format = SrgbFormOf(format);
  if (width == 0 || height == 0 || width > std::uint32_t(kMaxTextureSize) || height > std::uint32_t(kMaxTextureSize))
    return "DDS image size is zero or larger than kMaxTextureSize";
  const int block_bytes = format == COMPRESSED_RGB_S3TC_DXT1_EXT || format == COMPRESSED_RGBA_S3TC_DXT1_EXT ||
                                  format == COMPRESSED_SRGB_S3TC_DXT1_EXT ||
                                  format == COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT || format == COMPRESSED_RED_RGTC1 ||
                                  format == COMPRESSED_SIGNED_RED_RGTC1
                              ? 8
                              : 16;
  int chain = 1;  // the levels down to 1 x 1
  for (std::uint32_t s = std::max(width, height); s > 1; s /= 2) ++chain;
  const int count = (flags & kMipMapCount) && mips > 0 ? int(std::min<std::uint32_t>(mips, std::uint32_t(chain))) : 1;
  out.compressed = format;
  out.width = int(width);
  out.height = int(height);
  out.channels = 4;
  for (int l = 0; l < count; ++l) {
    CompressedImageLevel level;
    level.width = std::max(1, int(width >> l));
    level.height = std::max(1, int(height >> l));
    const std::size_t bytes =
        std::size_t((level.width + 3) / 4) * std::size_t((level.height + 3) / 4) * std::size_t(block_bytes);
    if (size - at < bytes) return "truncated DDS data (fewer blocks than its levels need)";
    level.blocks.assign(d + at, d + at + bytes);
    at += bytes;
    const bool bptc = format == COMPRESSED_RGBA_BPTC_UNORM || format == COMPRESSED_SRGB_ALPHA_BPTC_UNORM ||
                      format == COMPRESSED_RGB_BPTC_SIGNED_FLOAT || format == COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT;
    if (flip_vertically && bptc)  // (a BPTC block's partition and anchors tie its texels to their places)
      return "BPTC (BC6H, BC7) blocks cannot be turned upside down: load the DDS file unflipped and flip t";
    if (flip_vertically && !FlipLevel(format, level, block_bytes))
      return "cannot flip a DDS level whose height is above 4 and not a multiple of 4 (load it unflipped and flip t)";
    out.levels.push_back(std::move(level));
  }
  return nullptr;
}

bool LoadImageFile(const std::string& path, bool flip_vertically, LoadedImage& out, std::string* error, bool srgb) {
  // Read whole, then decode from memory: the same checks for files and for embedded images.
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    if (error) *error = path + ": cannot open file";
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return LoadImageMemory(bytes.data(), bytes.size(), path, flip_vertically, out, error, srgb);
}

bool LoadImageMemory(const void* data, std::size_t size, const std::string& name, bool flip_vertically,
                     LoadedImage& out, std::string* error, bool srgb) {
  if (data == nullptr || size == 0 || size > std::size_t(INT32_MAX)) {
    if (error) *error = name + ": empty or oversized image data";
    return false;
  }
  const auto* d = static_cast<const stbi_uc*>(data);
  if (size >= 4 && std::memcmp(d, "DDS ", 4) == 0) {
    out = LoadedImage{};
    const char* why = ReadDds(d, size, flip_vertically, srgb, out);
    if (why != nullptr && error) *error = name + ": " + why;
    return why == nullptr;
  }
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

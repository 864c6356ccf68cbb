// image_io.cpp — PNG output and image decoding through stb_image_write and stb_image (Debian's libstb-dev).
#include <softgl/image.h>

#include <cstdlib>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_MAX_DIMENSIONS 16384  // kMaxTextureSize: larger images are refused before anything is decoded
#define STBI_FAILURE_USERMSG
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
const char* JpegProblem(const std::uint8_t* d, std::size_t size);
}  // namespace
}  // namespace detail

bool ReadImageInfo(const void* data, std::size_t size, int* width, int* height, int* channels) {
  int w = 0, h = 0, n = 0;
  if (data == nullptr || size == 0 || size > std::size_t(INT32_MAX) ||
      detail::JpegProblem(static_cast<const std::uint8_t*>(data), size) != nullptr ||
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

// Where stb would read a JPEG: the position just after its SOI marker (0xFF bytes, then 0xD8), else 0.
std::size_t JpegStart(const std::uint8_t* d, std::size_t size) {
  std::size_t p = 0;
  if (size == 0 || d[0] != 0xFF) return 0;
  while (p < size && d[p] == 0xFF) ++p;
  return p < size && d[p] == 0xD8 ? p + 1 : 0;
}

// stb_image 2.27 trusts the code counts of a JPEG Huffman table and writes past its tables when they add up to more
// than 256 (found by fuzz_image). For any file stb would read as a JPEG, every DHT marker in the file is checked the
// way stb reads it, bytes past the end reading as zero; such a file is corrupt anyway.
// (Compressed scan data cannot hold 0xFF 0xC4: a 0xFF there is always followed by 0x00 or a marker.)
bool JpegHuffmanCountsValid(const std::uint8_t* d, std::size_t size, std::size_t start) {
  auto at = [&](std::size_t i) -> std::size_t { return i < size ? d[i] : 0; };
  for (std::size_t i = start; i + 1 < size; ++i) {
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

// stb_image 2.27 decodes a scan with whatever its Huffman table slots hold, and the slots of tables no DHT segment
// defined are uninitialized memory: their symbol indices run past the tables (found by fuzz_image, which it made
// depend on the heap's contents). So the markers are walked in stb's order, and a scan is refused when it uses a
// table not yet defined: both of a component's tables in a sequential frame; in a progressive one, the DC table in
// a first DC scan and the AC table in an AC scan (refinements of DC read no table). The walk is, where stb goes on
// reading, the same as stb's: bytes between segments are skipped, as are runs of 0xFF before a marker, and a scan's
// compressed data ends at the first 0xFF followed by neither 0x00 nor a restart marker. Wherever the walk stops
// early (an unknown marker, a bad length, the end), stb would refuse the file itself.
bool JpegScansUseDefinedTables(const std::uint8_t* d, std::size_t size, std::size_t p) {
  auto at = [&](std::size_t i) -> std::size_t { return i < size ? d[i] : 0; };
  bool defined[2][4] = {};
  bool frame = false, progressive = false;
  while (true) {
    while (p < size && d[p] != 0xFF) ++p;
    while (p < size && d[p] == 0xFF) ++p;
    if (p >= size) return true;
    const std::size_t m = d[p++];
    const std::size_t length = (at(p) << 8) | at(p + 1);
    if (length < 2) return true;
    const std::size_t end = p + length;
    if (m == 0xC4) {  // DHT: tables one after another, each class and slot, 16 counts, then the symbols
      for (std::size_t q = p + 2; q < end && q < size;) {
        const std::size_t tc = at(q) >> 4, th = at(q) & 15;
        if (tc > 1 || th > 3) return true;
        std::size_t total = 0;
        for (std::size_t k = 1; k <= 16; ++k) total += at(q + k);
        defined[tc][th] = true;
        q += 17 + total;
      }
    } else if (m == 0xC0 || m == 0xC1 || m == 0xC2) {  // the frame: stb reads one
      if (frame) return true;
      frame = true;
      progressive = m == 0xC2;
    } else if (m == 0xDA) {  // SOS: the components' table slots, then the spectral start and approximation
      if (!frame) return true;
      const std::size_t n = at(p + 2);
      if (n < 1 || n > 4 || length != 6 + 2 * n) return true;
      const std::size_t spectral_start = at(p + 3 + 2 * n), high = at(p + 5 + 2 * n) >> 4;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t q = at(p + 4 + 2 * i), dc = q >> 4, ac = q & 15;
        if (dc > 3 || ac > 3) return true;
        const bool needs_dc = !progressive || (spectral_start == 0 && high == 0);
        const bool needs_ac = !progressive || spectral_start != 0;
        if ((needs_dc && !defined[0][dc]) || (needs_ac && !defined[1][ac])) return false;
      }
      // The compressed data: 0xFF 0x00 is a data byte, 0xFF 0xD0..0xD7 a restart; any other marker ends it.
      std::size_t q = end;
      while (q < size) {
        if (d[q] != 0xFF) {
          ++q;
          continue;
        }
        std::size_t r = q + 1;
        while (r < size && d[r] == 0xFF) ++r;
        if (r >= size) return true;
        if (d[r] != 0x00 && (d[r] < 0xD0 || d[r] > 0xD7)) break;
        q = r + 1;
      }
      p = q;
      continue;
    } else if (m == 0xD9) {  // EOI
      return true;
    } else if (m != 0xDB && m != 0xDD && m != 0xDC && m != 0xFE && (m < 0xE0 || m > 0xEF)) {
      return true;  // a marker stb does not know: it refuses the file
    }
    p = end;
  }
}

// Why stb_image must not see these bytes (a JPEG it would misread), or nullptr.
const char* JpegProblem(const std::uint8_t* d, std::size_t size) {
  const std::size_t start = JpegStart(d, size);
  if (start == 0) return nullptr;  // not a JPEG to stb
  if (!JpegHuffmanCountsValid(d, size, start)) return "corrupt JPEG (a Huffman table has more than 256 codes)";
  if (!JpegScansUseDefinedTables(d, size, start)) return "corrupt JPEG (a scan uses a Huffman table never defined)";
  return nullptr;
}

bool Check(const std::uint8_t* d, std::size_t size, const std::string& name, std::string* error) {
  const char* problem = JpegProblem(d, size);
  if (problem == nullptr) return true;
  if (error) *error = name + ": " + problem;
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

// pixel_transfer.cpp — OpenGL 3.3's client pixel formats and types, their errors and conversions.
#include "pixel_transfer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>

#include "texture.h"

namespace softgl::detail {

// The components of a format in client order, as RGBA channel numbers (red 0 ... alpha 3); 0 for an unknown format.
// Depth and stencil formats have one component, kept in channel 0.
int FormatChannels(Enum format, int ch[4]) {
  auto set = [&](std::initializer_list<int> c) {
    int n = 0;
    for (int k : c) ch[n++] = k;
    return n;
  };
  switch (format) {
    case RED:
    case RED_INTEGER:
    case DEPTH_COMPONENT:
    case STENCIL_INDEX:
    case DEPTH_STENCIL: return set({0});
    case GREEN:
    case GREEN_INTEGER: return set({1});
    case BLUE:
    case BLUE_INTEGER: return set({2});
    case RG:
    case RG_INTEGER: return set({0, 1});
    case RGB:
    case RGB_INTEGER: return set({0, 1, 2});
    case BGR:
    case BGR_INTEGER: return set({2, 1, 0});
    case RGBA:
    case RGBA_INTEGER: return set({0, 1, 2, 3});
    case BGRA:
    case BGRA_INTEGER: return set({2, 1, 0, 3});
    default: return 0;
  }
}

bool IsIntegerTransfer(Enum format) {
  switch (format) {
    case RED_INTEGER:
    case GREEN_INTEGER:
    case BLUE_INTEGER:
    case RG_INTEGER:
    case RGB_INTEGER:
    case RGBA_INTEGER:
    case BGR_INTEGER:
    case BGRA_INTEGER: return true;
    default: return false;
  }
}

namespace {

// A packed type's fields in client order (the format's first component in field 0): lowest bit and width.
struct Packing {
  int fields = 0;     // 0: not a packed colour type
  std::size_t bytes = 0;
  int shift[4] = {}, bits[4] = {};
};
Packing PackingOf(Enum type) {
  auto make = [](std::size_t bytes, std::initializer_list<int> widths, bool rev) {
    Packing p;
    p.bytes = bytes;
    int total = 0;
    for (int w : widths) p.bits[p.fields++] = w, total += w;
    // Not reversed: the first field in the highest bits. Reversed: the first field in the lowest.
    int at = rev ? 0 : total;
    for (int k = 0; k < p.fields; ++k) {
      if (rev) p.shift[k] = at, at += p.bits[k];
      else at -= p.bits[k], p.shift[k] = at;
    }
    return p;
  };
  switch (type) {
    case UNSIGNED_BYTE_3_3_2: return make(1, {3, 3, 2}, false);
    case UNSIGNED_BYTE_2_3_3_REV: return make(1, {3, 3, 2}, true);
    case UNSIGNED_SHORT_5_6_5: return make(2, {5, 6, 5}, false);
    case UNSIGNED_SHORT_5_6_5_REV: return make(2, {5, 6, 5}, true);
    case UNSIGNED_SHORT_4_4_4_4: return make(2, {4, 4, 4, 4}, false);
    case UNSIGNED_SHORT_4_4_4_4_REV: return make(2, {4, 4, 4, 4}, true);
    case UNSIGNED_SHORT_5_5_5_1: return make(2, {5, 5, 5, 1}, false);
    case UNSIGNED_SHORT_1_5_5_5_REV: return make(2, {5, 5, 5, 1}, true);
    case UNSIGNED_INT_8_8_8_8: return make(4, {8, 8, 8, 8}, false);
    case UNSIGNED_INT_8_8_8_8_REV: return make(4, {8, 8, 8, 8}, true);
    case UNSIGNED_INT_10_10_10_2: return make(4, {10, 10, 10, 2}, false);
    case UNSIGNED_INT_2_10_10_10_REV: return make(4, {10, 10, 10, 2}, true);
    case UNSIGNED_INT_10F_11F_11F_REV: return make(4, {11, 11, 10}, true);
    case UNSIGNED_INT_5_9_9_9_REV: return make(4, {9, 9, 9, 5}, true);
    default: return {};
  }
}

bool IsPlainType(Enum type) {
  switch (type) {
    case UNSIGNED_BYTE:
    case BYTE:
    case UNSIGNED_SHORT:
    case SHORT:
    case UNSIGNED_INT:
    case INT:
    case HALF_FLOAT:
    case FLOAT: return true;
    default: return false;
  }
}

bool IsDepthStencilType(Enum type) { return type == UNSIGNED_INT_24_8 || type == FLOAT_32_UNSIGNED_INT_24_8_REV; }

std::size_t PlainBytes(Enum type) {
  switch (type) {
    case UNSIGNED_BYTE:
    case BYTE: return 1;
    case UNSIGNED_SHORT:
    case SHORT:
    case HALF_FLOAT: return 2;
    default: return 4;
  }
}

// A packed value of 1, 2 or 4 bytes, in the machine's byte order.
std::uint32_t LoadWord(const std::uint8_t* p, std::size_t bytes) {
  if (bytes == 1) return *p;
  if (bytes == 2) return LoadUnaligned<std::uint16_t>(p);
  return LoadUnaligned<std::uint32_t>(p);
}
void StoreWord(std::uint8_t* p, std::size_t bytes, std::uint32_t v) {
  if (bytes == 1) *p = std::uint8_t(v);
  else if (bytes == 2) StoreUnaligned(p, std::uint16_t(v));
  else StoreUnaligned(p, v);
}

// v clamped to [0, 1] (NaN as 0) times max, rounded.
std::uint64_t Unorm(double v, double max) {
  const double c = v > 0.0 ? std::min(v, 1.0) : 0.0;
  return std::uint64_t(std::llround(c * max));
}
// v clamped to [-1, 1] (NaN as 0) times max, rounded (OpenGL 4.2's signed normalized conversion).
std::int64_t Snorm(double v, double max) {
  const double c = v > -1.0 ? std::min(v, 1.0) : (v <= -1.0 ? -1.0 : 0.0);
  return std::llround(c * max);
}

double UnpackPlain(Enum type, const std::uint8_t* p) {
  switch (type) {
    case UNSIGNED_BYTE: return *p / 255.0;
    case BYTE: return std::max(LoadUnaligned<std::int8_t>(p) / 127.0, -1.0);
    case UNSIGNED_SHORT: return LoadUnaligned<std::uint16_t>(p) / 65535.0;
    case SHORT: return std::max(LoadUnaligned<std::int16_t>(p) / 32767.0, -1.0);
    case UNSIGNED_INT: return LoadUnaligned<std::uint32_t>(p) / 4294967295.0;
    case INT: return std::max(LoadUnaligned<std::int32_t>(p) / 2147483647.0, -1.0);
    case HALF_FLOAT: return HalfToFloat(LoadUnaligned<std::uint16_t>(p));
    default: return LoadUnaligned<float>(p);
  }
}

void PackPlain(Enum type, double v, std::uint8_t* p) {
  switch (type) {
    case UNSIGNED_BYTE: *p = std::uint8_t(Unorm(v, 255.0)); break;
    case BYTE: StoreUnaligned(p, std::int8_t(Snorm(v, 127.0))); break;
    case UNSIGNED_SHORT: StoreUnaligned(p, std::uint16_t(Unorm(v, 65535.0))); break;
    case SHORT: StoreUnaligned(p, std::int16_t(Snorm(v, 32767.0))); break;
    case UNSIGNED_INT: StoreUnaligned(p, std::uint32_t(Unorm(v, 4294967295.0))); break;
    case INT: StoreUnaligned(p, std::int32_t(Snorm(v, 2147483647.0))); break;
    case HALF_FLOAT: StoreUnaligned(p, FloatToHalf(float(v))); break;
    default: StoreUnaligned(p, float(v)); break;
  }
}

}  // namespace

Enum CheckPixelTransfer(Enum format, Enum type, TransferCall call, const char*& why) {
  int ch[4];
  const bool stencil_ok = call == TransferCall::kReadPixels;
  if (FormatChannels(format, ch) == 0 || (format == STENCIL_INDEX && !stencil_ok)) {
    why = stencil_ok ? "format is not a pixel format of OpenGL 3.3"
                     : "format is not a pixel format of OpenGL 3.3 (STENCIL_INDEX only for ReadPixels)";
    return INVALID_ENUM;
  }
  const Packing packing = PackingOf(type);
  if (!IsPlainType(type) && packing.fields == 0 && !IsDepthStencilType(type)) {
    why = "type is not a pixel type of OpenGL 3.3";
    return INVALID_ENUM;
  }
  if (format == DEPTH_STENCIL && !IsDepthStencilType(type)) {
    why = "DEPTH_STENCIL data is UNSIGNED_INT_24_8 or FLOAT_32_UNSIGNED_INT_24_8_REV";
    return INVALID_ENUM;
  }
  if (IsDepthStencilType(type) && format != DEPTH_STENCIL) {
    why = "UNSIGNED_INT_24_8 and FLOAT_32_UNSIGNED_INT_24_8_REV go with DEPTH_STENCIL only";
    return INVALID_OPERATION;
  }
  if (packing.fields != 0) {
    const int n = FormatChannels(format, ch);
    // 3_3_2, 5_6_5, 10F_11F_11F_REV and 5_9_9_9_REV (three fields and an exponent) hold RGB; the others four
    // components: RGBA, BGRA and their integer forms.
    const bool rgb_only = packing.fields == 3 || type == UNSIGNED_INT_5_9_9_9_REV;
    const bool ok = rgb_only ? (format == RGB || format == RGB_INTEGER) : n == 4;
    if (!ok) {
      why = "a packed type goes with the format of its component count (table 3.5): RGB for 3_3_2, 5_6_5, "
            "10F_11F_11F_REV and 5_9_9_9_REV, RGBA or BGRA for the others";
      return INVALID_OPERATION;
    }
  }
  if (IsIntegerTransfer(format) && (type == FLOAT || type == HALF_FLOAT || type == UNSIGNED_INT_10F_11F_11F_REV ||
                                    type == UNSIGNED_INT_5_9_9_9_REV)) {
    why = "an integer format with a float type";
    return INVALID_OPERATION;
  }
  return NO_ERROR;
}

std::size_t TransferElementBytes(Enum type) {
  if (IsDepthStencilType(type)) return 4;
  const Packing packing = PackingOf(type);
  return packing.fields ? packing.bytes : PlainBytes(type);
}

std::size_t TransferPixelBytes(Enum format, Enum type) {
  if (type == FLOAT_32_UNSIGNED_INT_24_8_REV) return 8;
  if (type == UNSIGNED_INT_24_8) return 4;
  const Packing packing = PackingOf(type);
  if (packing.fields) return packing.bytes;
  int ch[4];
  return std::size_t(FormatChannels(format, ch)) * PlainBytes(type);
}

std::uint32_t EncodeRgb9e5(const glm::vec3& rgb) {
  constexpr int kN = 9, kB = 15;
  constexpr double kMax = 511.0 / 512.0 * 65536.0;  // (2^N - 1) / 2^N * 2^(Emax - B)
  double c[3];
  for (int k = 0; k < 3; ++k) c[k] = rgb[k] > 0.0f ? std::min(double(rgb[k]), kMax) : 0.0;  // NaN as 0
  const double maxc = std::max({c[0], c[1], c[2]});
  int floor_log2 = -kB - 1;
  if (maxc > 0.0) {
    int e = 0;
    std::frexp(maxc, &e);  // maxc = m * 2^e, m in [0.5, 1): floor(log2(maxc)) = e - 1
    floor_log2 = std::max(floor_log2, e - 1);
  }
  int exp_shared = floor_log2 + 1 + kB;
  if (std::floor(maxc / std::ldexp(1.0, exp_shared - kB - kN) + 0.5) >= 512.0) ++exp_shared;
  std::uint32_t out = std::uint32_t(exp_shared) << 27;
  for (int k = 0; k < 3; ++k)
    out |= std::uint32_t(std::floor(c[k] / std::ldexp(1.0, exp_shared - kB - kN) + 0.5)) << (9 * k);
  return out;
}

glm::vec3 DecodeRgb9e5(std::uint32_t v) {
  const int exponent = int(v >> 27) - 15 - 9;
  glm::vec3 out;
  for (int k = 0; k < 3; ++k) out[k] = float(std::ldexp(double((v >> (9 * k)) & 511u), exponent));
  return out;
}

glm::vec4 UnpackColor(Enum format, Enum type, const std::uint8_t* p) {
  int ch[4];
  const int n = FormatChannels(format, ch);
  glm::vec4 out(0.0f, 0.0f, 0.0f, 1.0f);
  const Packing packing = PackingOf(type);
  if (packing.fields == 0) {
    const std::size_t size = PlainBytes(type);
    for (int k = 0; k < n; ++k) out[ch[k]] = float(UnpackPlain(type, p + std::size_t(k) * size));
    return out;
  }
  const std::uint32_t word = LoadWord(p, packing.bytes);
  if (type == UNSIGNED_INT_5_9_9_9_REV) return glm::vec4(DecodeRgb9e5(word), 1.0f);
  for (int k = 0; k < n && k < packing.fields; ++k) {
    const std::uint32_t field = (word >> packing.shift[k]) & ((1u << packing.bits[k]) - 1u);
    out[ch[k]] = type == UNSIGNED_INT_10F_11F_11F_REV ? UnsignedSmallToFloat(field, packing.bits[k] - 5)
                                                      : float(double(field) / double((1u << packing.bits[k]) - 1u));
  }
  return out;
}

void UnpackInteger(Enum format, Enum type, const std::uint8_t* p, std::int64_t out[4]) {
  int ch[4];
  const int n = FormatChannels(format, ch);
  out[0] = out[1] = out[2] = 0;
  out[3] = 1;
  const Packing packing = PackingOf(type);
  if (packing.fields == 0) {
    const std::size_t size = PlainBytes(type);
    for (int k = 0; k < n; ++k) {
      const std::uint8_t* e = p + std::size_t(k) * size;
      switch (type) {
        case UNSIGNED_BYTE: out[ch[k]] = *e; break;
        case BYTE: out[ch[k]] = LoadUnaligned<std::int8_t>(e); break;
        case UNSIGNED_SHORT: out[ch[k]] = LoadUnaligned<std::uint16_t>(e); break;
        case SHORT: out[ch[k]] = LoadUnaligned<std::int16_t>(e); break;
        case UNSIGNED_INT: out[ch[k]] = LoadUnaligned<std::uint32_t>(e); break;
        default: out[ch[k]] = LoadUnaligned<std::int32_t>(e); break;  // INT (CheckPixelTransfer refused floats)
      }
    }
    return;
  }
  const std::uint32_t word = LoadWord(p, packing.bytes);
  for (int k = 0; k < n && k < packing.fields; ++k)
    out[ch[k]] = (word >> packing.shift[k]) & ((1u << packing.bits[k]) - 1u);
}

void PackInteger(Enum format, Enum type, const std::int64_t v[4], std::uint8_t* p) {
  int ch[4];
  const int n = FormatChannels(format, ch);
  const Packing packing = PackingOf(type);
  if (packing.fields == 0) {
    const std::size_t size = PlainBytes(type);
    for (int k = 0; k < n; ++k) {
      std::uint8_t* e = p + std::size_t(k) * size;
      const std::int64_t c = v[ch[k]];
      switch (type) {
        case UNSIGNED_BYTE: *e = std::uint8_t(std::clamp<std::int64_t>(c, 0, 255)); break;
        case BYTE: StoreUnaligned(e, std::int8_t(std::clamp<std::int64_t>(c, -128, 127))); break;
        case UNSIGNED_SHORT: StoreUnaligned(e, std::uint16_t(std::clamp<std::int64_t>(c, 0, 65535))); break;
        case SHORT: StoreUnaligned(e, std::int16_t(std::clamp<std::int64_t>(c, -32768, 32767))); break;
        case UNSIGNED_INT: StoreUnaligned(e, std::uint32_t(std::clamp<std::int64_t>(c, 0, 4294967295LL))); break;
        default: StoreUnaligned(e, std::int32_t(std::clamp<std::int64_t>(c, INT32_MIN, INT32_MAX))); break;
      }
    }
    return;
  }
  std::uint32_t word = 0;
  for (int k = 0; k < n && k < packing.fields; ++k)
    word |= std::uint32_t(std::clamp<std::int64_t>(v[ch[k]], 0, (1 << packing.bits[k]) - 1)) << packing.shift[k];
  StoreWord(p, packing.bytes, word);
}

void UnpackDepthStencil(Enum type, const std::uint8_t* p, float& depth, std::uint8_t& stencil) {
  if (type == FLOAT_32_UNSIGNED_INT_24_8_REV) {
    depth = LoadUnaligned<float>(p);
    stencil = std::uint8_t(LoadUnaligned<std::uint32_t>(p + 4));
  } else {
    const std::uint32_t word = LoadUnaligned<std::uint32_t>(p);
    depth = float(double(word >> 8) / 16777215.0);
    stencil = std::uint8_t(word);
  }
}

void PackColor(Enum format, Enum type, const glm::vec4& c, std::uint8_t* p) {
  int ch[4];
  const int n = FormatChannels(format, ch);
  const Packing packing = PackingOf(type);
  if (packing.fields == 0) {
    const std::size_t size = PlainBytes(type);
    for (int k = 0; k < n; ++k) PackPlain(type, double(c[ch[k]]), p + std::size_t(k) * size);
    return;
  }
  if (type == UNSIGNED_INT_5_9_9_9_REV) return StoreWord(p, 4, EncodeRgb9e5(glm::vec3(c)));
  std::uint32_t word = 0;
  for (int k = 0; k < n && k < packing.fields; ++k) {
    const std::uint32_t field = type == UNSIGNED_INT_10F_11F_11F_REV
                                    ? FloatToUnsignedSmall(c[ch[k]], packing.bits[k] - 5)
                                    : std::uint32_t(Unorm(double(c[ch[k]]), double((1u << packing.bits[k]) - 1u)));
    word |= field << packing.shift[k];
  }
  StoreWord(p, packing.bytes, word);
}

void PackColorRow(Enum format, Enum type, const float* rgba, int n, std::uint8_t* p, std::size_t pixel) {
  int ch[4];
  const int channels = FormatChannels(format, ch);
  if (type == UNSIGNED_BYTE) {
    // Unorm(v, 255): for c in [0, 1], c * 255 + 1/2 is exact in double and its truncation is llround's result.
    for (int i = 0; i < n; ++i, p += pixel)
      for (int k = 0; k < channels; ++k) {
        const double v = double(rgba[4 * i + ch[k]]);
        const double c = v > 0.0 ? std::min(v, 1.0) : 0.0;
        p[k] = std::uint8_t(int(c * 255.0 + 0.5));
      }
    return;
  }
  if (type == FLOAT) {
    for (int i = 0; i < n; ++i, p += pixel)
      for (int k = 0; k < channels; ++k) {
        const float v = float(double(rgba[4 * i + ch[k]]));  // (PackPlain's conversions: a signalling NaN made quiet)
        std::memcpy(p + 4 * k, &v, 4);
      }
    return;
  }
  for (int i = 0; i < n; ++i, p += pixel)
    PackColor(format, type, glm::vec4(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]), p);
}

void PackStencil(Enum type, std::uint32_t stencil, std::uint8_t* p) {
  switch (type) {
    case UNSIGNED_BYTE:
    case BYTE: *p = std::uint8_t(stencil); break;
    case UNSIGNED_SHORT:
    case SHORT: StoreUnaligned(p, std::uint16_t(stencil)); break;
    case UNSIGNED_INT:
    case INT: StoreUnaligned(p, stencil); break;
    case HALF_FLOAT: StoreUnaligned(p, FloatToHalf(float(stencil))); break;
    default: StoreUnaligned(p, float(stencil)); break;
  }
}

void PackDepthStencil(Enum type, float depth, std::uint8_t stencil, std::uint8_t* p) {
  if (type == FLOAT_32_UNSIGNED_INT_24_8_REV) {
    StoreUnaligned(p, depth > 0.0f ? std::min(depth, 1.0f) : 0.0f);
    StoreUnaligned(p + 4, std::uint32_t(stencil));
  } else {
    StoreUnaligned(p, std::uint32_t(Unorm(depth, 16777215.0)) << 8 | stencil);
  }
}

}  // namespace softgl::detail

// texture.cpp — texture storage: formats, uploads, mipmap generation, completeness.
#include "texture.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>

#include "framebuffer.h"
#include "pixel_transfer.h"
#include "wide.h"

namespace softgl::detail {

int FormatComponents(Enum f) {
  switch (f) {
    case R8:
    case R16:
    case R16F:
    case R32F:
    case DEPTH_COMPONENT:
    case DEPTH_COMPONENT16:
    case DEPTH_COMPONENT24:
    case DEPTH_COMPONENT32F:
    case DEPTH24_STENCIL8:
    case DEPTH32F_STENCIL8: return 1;
    case RG8:
    case RG16:
    case RG16F:
    case RG32F: return 2;
    case RGB8:
    case SRGB8:
    case R11F_G11F_B10F:
    case RGB565: return 3;
    case RGBA8:
    case SRGB8_ALPHA8:
    case RGBA4:
    case RGB5_A1:
    case RGB10_A2:
    case RGBA16:
    case RGBA16F:
    case RGBA32F: return 4;
    default: {
      // The integer formats: the R, RG and RGBA ones by their layout's channels, the RGB ones 3.
      switch (f) {
        case RGB8UI: case RGB8I: case RGB16UI: case RGB16I: case RGB32UI: case RGB32I: return 3;
        default: return IntegerLayoutOf(LayoutOf(f)).channels;
      }
    }
  }
}

bool IsIntegerInternalFormat(Enum f) { return IsIntegerLayout(LayoutOf(f)); }

bool IsDepthFormat(Enum f) {
  return f == DEPTH_COMPONENT || f == DEPTH_COMPONENT16 || f == DEPTH_COMPONENT24 || f == DEPTH_COMPONENT32F ||
         f == DEPTH24_STENCIL8 || f == DEPTH32F_STENCIL8;
}

bool HasStencil(Enum f) { return f == DEPTH24_STENCIL8 || f == DEPTH32F_STENCIL8 || f == STENCIL_INDEX8; }

bool IsNormalizedFormat(Enum f) {
  return f == R8 || f == RG8 || f == RGB8 || f == RGBA8 || IsSrgbFormat(f) || f == RGB565 || f == RGBA4 || f == RGB5_A1 ||
         f == RGB10_A2;
}

TexelLayout LayoutOf(Enum f) {
  switch (f) {
    case RGBA8:
    case RGB8:
    case SRGB8_ALPHA8:
    case SRGB8: return TexelLayout::kUnorm8x4;
    case RG8: return TexelLayout::kUnorm8x2;
    case R8: return TexelLayout::kUnorm8x1;
    case RGBA32F: return TexelLayout::kFloat32x4;
    case RG32F: return TexelLayout::kFloat32x2;
    case RGBA16F: return TexelLayout::kFloat16x4;
    case RG16F: return TexelLayout::kFloat16x2;
    case R16F: return TexelLayout::kFloat16x1;
    case R11F_G11F_B10F: return TexelLayout::kFloat11x11x10;
    case RGB565: return TexelLayout::kUnorm565;
    case RGBA4: return TexelLayout::kUnorm4444;
    case RGB5_A1: return TexelLayout::kUnorm5551;
    case RGB10_A2: return TexelLayout::kUnorm1010102;
    case RGBA16: return TexelLayout::kUnorm16x4;
    case RG16: return TexelLayout::kUnorm16x2;
    case R16:
    case DEPTH_COMPONENT16: return TexelLayout::kUnorm16x1;
    case R32F:
    case DEPTH_COMPONENT:
    case DEPTH_COMPONENT24:
    case DEPTH_COMPONENT32F:
    case DEPTH24_STENCIL8:
    case DEPTH32F_STENCIL8: return TexelLayout::kFloat32x1;
    case R8UI: return IntegerLayoutFor(1, 1, false);
    case R8I: return IntegerLayoutFor(1, 1, true);
    case R16UI: return IntegerLayoutFor(1, 2, false);
    case R16I: return IntegerLayoutFor(1, 2, true);
    case R32UI: return IntegerLayoutFor(1, 4, false);
    case R32I: return IntegerLayoutFor(1, 4, true);
    case RG8UI: return IntegerLayoutFor(2, 1, false);
    case RG8I: return IntegerLayoutFor(2, 1, true);
    case RG16UI: return IntegerLayoutFor(2, 2, false);
    case RG16I: return IntegerLayoutFor(2, 2, true);
    case RG32UI: return IntegerLayoutFor(2, 4, false);
    case RG32I: return IntegerLayoutFor(2, 4, true);
    case RGB8UI:
    case RGBA8UI: return IntegerLayoutFor(4, 1, false);
    case RGB8I:
    case RGBA8I: return IntegerLayoutFor(4, 1, true);
    case RGB16UI:
    case RGBA16UI: return IntegerLayoutFor(4, 2, false);
    case RGB16I:
    case RGBA16I: return IntegerLayoutFor(4, 2, true);
    case RGB32UI:
    case RGBA32UI: return IntegerLayoutFor(4, 4, false);
    case RGB32I:
    case RGBA32I: return IntegerLayoutFor(4, 4, true);
    case RGB10_A2UI: return TexelLayout::kUint1010102;
    default: return TexelLayout::kNone;
  }
}

namespace {

// |f| (not NaN) as a float of 5 exponent bits (bias 15) and m mantissa bits, without its sign: rounded to nearest,
// ties to even (nearbyint in the default rounding mode), too large to infinity.
std::uint32_t EncodeMagnitude(float a, int m) {
  const std::uint32_t inf = 31u << m;
  if (std::isinf(a)) return inf;
  if (a == 0.0f) return 0;
  int e = 0;
  std::frexp(a, &e);  // a = f * 2^e, f in [0.5, 1): a = 1.x * 2^(e - 1)
  int exponent = e - 1;
  if (exponent < -14) return std::uint32_t(std::nearbyint(std::ldexp(double(a), 14 + m)));  // subnormal (or the
                                                                                            // smallest normal)
  double q = std::nearbyint(std::ldexp(double(a), m - exponent));  // in [2^m, 2^(m + 1)]
  if (q == double(2u << m)) {
    q /= 2.0;
    ++exponent;
  }
  if (exponent > 15) return inf;
  return std::uint32_t(exponent + 15) << m | (std::uint32_t(q) - (1u << m));
}

float DecodeMagnitude(std::uint32_t v, int m) {
  const std::uint32_t exponent = (v >> m) & 31u, mantissa = v & ((1u << m) - 1u);
  if (exponent == 31) return mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  if (exponent == 0) return float(std::ldexp(double(mantissa), -14 - m));
  return float(std::ldexp(double(mantissa + (1u << m)), int(exponent) - 15 - m));
}

std::uint16_t Half(const std::uint8_t* p) {
  std::uint16_t h;
  std::memcpy(&h, p, 2);
  return h;
}

}  // namespace

// Half floats by their bits: they are converted for every fragment written to a half-float target.
std::uint16_t FloatToHalf(float f) {
  std::uint32_t x;
  std::memcpy(&x, &f, 4);
  const std::uint32_t sign = (x >> 16) & 0x8000u, a = x & 0x7FFFFFFFu;
  if (a > 0x7F800000u) return std::uint16_t(sign | 0x7E00u);  // NaN
  if (a >= 0x38800000u) {  // 2^-14 and up: a normal half, or too large
    std::uint32_t r = a - 0x38000000u;  // the exponent rebased from 127 to 15
    r = (r + 0xFFFu + ((r >> 13) & 1u)) >> 13;  // 13 mantissa bits dropped, to nearest, ties to even
    return std::uint16_t(sign | std::min(r, 0x7C00u));  // past the largest finite: infinity
  }
  // A subnormal half (or 0): |f| in units of 2^-24, rounded to an integer by adding 2^23 (to nearest, ties to
  // even, in the default rounding mode; exact below 2^23).
  float units = 0.0f;
  std::memcpy(&units, &a, 4);
  units = units * 16777216.0f + 8388608.0f;
  std::uint32_t u;
  std::memcpy(&u, &units, 4);
  return std::uint16_t(sign | (u & 0x7FFu));  // at most 1024: the smallest normal half when it rounds up
}

float HalfToFloat(std::uint16_t h) {
  const std::uint32_t sign = std::uint32_t(h & 0x8000u) << 16, e = (h >> 10) & 31u, m = h & 0x3FFu;
  if (e == 0) {
    const float v = float(m) * (1.0f / 16777216.0f);
    return sign ? -v : v;
  }
  // (A NaN keeps its payload, with the quiet bit set: as processors convert halves.)
  const std::uint32_t quiet = (e == 31 && m != 0) ? 0x00400000u : 0u;
  const std::uint32_t bits = sign | (e == 31 ? 0x7F800000u : (e + 112u) << 23) | m << 13 | quiet;
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

std::uint32_t FloatToUnsignedSmall(float f, int m) {
  if (std::isnan(f)) return (31u << m) | 1u;
  return f > 0.0f ? EncodeMagnitude(f, m) : 0u;
}

float UnsignedSmallToFloat(std::uint32_t v, int m) { return DecodeMagnitude(v, m); }

namespace {

// The word of a packed layout (2 or 4 bytes), and back.
std::uint32_t LoadPacked(TexelLayout l, const std::uint8_t* p) {
  if (BytesPerTexel(l) == 4) {
    std::uint32_t w;
    std::memcpy(&w, p, 4);
    return w;
  }
  std::uint16_t h;
  std::memcpy(&h, p, 2);
  return h;
}
void StorePacked(TexelLayout l, std::uint8_t* p, std::uint32_t w) {
  if (BytesPerTexel(l) == 4) return std::memcpy(p, &w, 4), void();
  const std::uint16_t h = std::uint16_t(w);
  std::memcpy(p, &h, 2);
}

}  // namespace

glm::ivec4 IntegerTexel(TexelLayout layout, const std::uint8_t* p) {
  const IntegerLayout k = IntegerLayoutOf(layout);
  glm::ivec4 v(0, 0, 0, 1);
  if (k.packed) {
    const std::uint32_t w = LoadPacked(TexelLayout::kUnorm1010102, p);
    return glm::ivec4(int(w & 0x3FFu), int((w >> 10) & 0x3FFu), int((w >> 20) & 0x3FFu), int(w >> 30));
  }
  for (int c = 0; c < k.channels; ++c, p += k.bytes) {
    switch (k.bytes) {
      case 1: v[c] = k.is_signed ? int(std::int8_t(*p)) : int(*p); break;
      case 2: {
        std::uint16_t h;
        std::memcpy(&h, p, 2);
        v[c] = k.is_signed ? int(std::int16_t(h)) : int(h);
        break;
      }
      default: std::memcpy(&v[c], p, 4); break;
    }
  }
  return v;
}

void StoreIntegerTexel(TexelLayout layout, std::uint8_t* p, const std::int64_t in[4], bool rgb_only) {
  const IntegerLayout k = IntegerLayoutOf(layout);
  std::int64_t v[4] = {in[0], in[1], in[2], rgb_only ? 1 : in[3]};
  if (k.packed) {
    std::uint32_t w = 0;
    for (int c = 0; c < 4; ++c) {
      const int bits = c < 3 ? 10 : 2;
      w |= std::uint32_t(std::clamp<std::int64_t>(v[c], 0, (1 << bits) - 1)) << (10 * c);
    }
    return StorePacked(TexelLayout::kUnorm1010102, p, w);
  }
  const int bits = 8 * k.bytes;
  const std::int64_t lo = k.is_signed ? -(std::int64_t(1) << (bits - 1)) : 0;
  const std::int64_t hi = k.is_signed ? (std::int64_t(1) << (bits - 1)) - 1 : (std::int64_t(1) << bits) - 1;
  for (int c = 0; c < k.channels; ++c, p += k.bytes) {
    const std::uint32_t w = std::uint32_t(std::clamp(v[c], lo, hi));  // (two's complement for the signed ones)
    switch (k.bytes) {
      case 1: *p = std::uint8_t(w); break;
      case 2: {
        const std::uint16_t h = std::uint16_t(w);
        std::memcpy(p, &h, 2);
        break;
      }
      default: std::memcpy(p, &w, 4); break;
    }
  }
}

void PackIntegerTexel(TexelLayout layout, const std::uint8_t* texel, Enum format, Enum type, std::uint8_t* out) {
  const glm::ivec4 v = IntegerTexel(layout, texel);
  const std::int64_t values[4] = {IntegerValue(layout, v[0]), IntegerValue(layout, v[1]), IntegerValue(layout, v[2]),
                                  IntegerValue(layout, v[3])};
  PackInteger(format, type, values, out);
}

glm::vec4 RawTexel(TexelLayout layout, const std::uint8_t* p) {
  if (IsIntegerLayout(layout)) {
    const glm::ivec4 i = IntegerTexel(layout, p);
    glm::vec4 v;
    std::memcpy(&v.x, &i.x, 16);
    return v;
  }
  if (IsPackedUnorm(layout)) {
    const PackedUnorm k = PackingOf(layout);
    const std::uint32_t w = LoadPacked(layout, p);
    glm::vec4 v(1.0f);
    for (int c = 0; c < 4; ++c)
      if (k.bits[c]) {
        const unsigned max = (1u << k.bits[c]) - 1u;
        v[c] = float((w >> k.shift[c]) & max) / float(max);
      }
    return v;
  }
  if (IsUnorm16(layout)) {
    glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
    for (int c = 0; c < BytesPerTexel(layout) / 2; ++c) v[c] = float(Half(p + 2 * c)) / 65535.0f;
    return v;
  }
  switch (layout) {
    case TexelLayout::kFloat32x2: {
      float v[2];
      std::memcpy(v, p, 8);
      return glm::vec4(v[0], v[1], 0.0f, 1.0f);
    }
    case TexelLayout::kFloat16x4:
      return glm::vec4(HalfToFloat(Half(p)), HalfToFloat(Half(p + 2)), HalfToFloat(Half(p + 4)), HalfToFloat(Half(p + 6)));
    case TexelLayout::kFloat16x2: return glm::vec4(HalfToFloat(Half(p)), HalfToFloat(Half(p + 2)), 0.0f, 1.0f);
    case TexelLayout::kFloat16x1: return glm::vec4(HalfToFloat(Half(p)), 0.0f, 0.0f, 1.0f);
    case TexelLayout::kFloat11x11x10: {
      std::uint32_t w;
      std::memcpy(&w, p, 4);
      return glm::vec4(UnsignedSmallToFloat(w & 0x7FFu, 6), UnsignedSmallToFloat((w >> 11) & 0x7FFu, 6),
                       UnsignedSmallToFloat(w >> 22, 5), 1.0f);
    }
    case TexelLayout::kUnorm8x4: return glm::vec4(float(p[0]), float(p[1]), float(p[2]), float(p[3]));
    case TexelLayout::kUnorm8x2: return glm::vec4(float(p[0]), float(p[1]), 0.0f, 255.0f);
    case TexelLayout::kUnorm8x1: return glm::vec4(float(p[0]), 0.0f, 0.0f, 255.0f);
    case TexelLayout::kFloat32x4: {
      glm::vec4 v;
      std::memcpy(&v.x, p, 16);
      return v;
    }
    case TexelLayout::kFloat32x1: {
      float r;
      std::memcpy(&r, p, 4);
      return glm::vec4(r, 0.0f, 0.0f, 1.0f);
    }
    default: return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  }
}

namespace {
// The 256 decoded values, and the 255 linear values at which the encoded byte steps from k to k + 1 (where the sRGB
// value is (k + 1/2) / 255), computed in double.
struct SrgbTables {
  float decode[256];
  double step[255];
  SrgbTables() {
    for (int k = 0; k < 256; ++k) {
      const double c = k / 255.0;
      decode[k] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    for (int k = 0; k < 255; ++k) {
      const double c = (k + 0.5) / 255.0;
      step[k] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
  }
};
const SrgbTables& Srgb() {
  static const SrgbTables tables;
  return tables;
}
}  // namespace

float SrgbDecode8(std::uint8_t k) { return Srgb().decode[k]; }

std::uint8_t SrgbEncode8(float linear) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  const double* step = Srgb().step;
  return std::uint8_t(std::upper_bound(step, step + 255, double(linear)) - step);
}

const SrgbLaneTables& SrgbLanes() {
  static const SrgbLaneTables tables = [] {
    SrgbLaneTables t;
    for (int k = 0; k < 256; ++k) t.decode[k] = Srgb().decode[k];
    for (int k = 0; k < 255; ++k) {
      const double step = Srgb().step[k];
      float f = float(step);
      if (double(f) < step) f = std::nextafter(f, 2.0f);
      t.up[k] = f;
    }
    t.up[255] = std::numeric_limits<float>::infinity();
    for (int i = 0; i < SrgbLaneTables::kBuckets; ++i) {
      const std::uint32_t bits = std::uint32_t(SrgbLaneTables::kBucket0 + i) << 16;
      float x;
      std::memcpy(&x, &bits, 4);
      const int start = SrgbEncode8(x);
      std::uint32_t next;  // the step above, if inside the bucket
      std::memcpy(&next, &t.up[start], 4);
      const std::uint32_t low = (next >> 16) == (bits >> 16) ? next & 0xFFFFu : 0x10000u;
      t.bucket[i] = std::int32_t(std::uint32_t(start) | (low << 8));
    }
    return t;
  }();
  return tables;
}

void StoreSmallFloatTexel(TexelLayout layout, std::uint8_t* p, const glm::vec4& in) {
  switch (layout) {
    case TexelLayout::kFloat32x2: std::memcpy(p, &in.x, 8); break;
    case TexelLayout::kFloat16x4:
    case TexelLayout::kFloat16x2:
    case TexelLayout::kFloat16x1:
      for (int c = 0; c < BytesPerTexel(layout) / 2; ++c) {
        const std::uint16_t h = FloatToHalf(in[c]);
        std::memcpy(p + 2 * c, &h, 2);
      }
      break;
    case TexelLayout::kFloat11x11x10: {
      const std::uint32_t w = FloatToUnsignedSmall(in[0], 6) | FloatToUnsignedSmall(in[1], 6) << 11 |
                              FloatToUnsignedSmall(in[2], 5) << 22;
      std::memcpy(p, &w, 4);
      break;
    }
    case TexelLayout::kUnorm16x4:
    case TexelLayout::kUnorm16x2:
    case TexelLayout::kUnorm16x1:
      for (int c = 0; c < BytesPerTexel(layout) / 2; ++c) {  // clamped to [0, 1] (NaN as 0), round(c * 65535)
        const float v = in[c] > 0.0f ? std::min(in[c], 1.0f) : 0.0f;
        const auto k = std::uint16_t(std::lrint(v * 65535.0f));
        std::memcpy(p + 2 * c, &k, 2);
      }
      break;
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551:
    case TexelLayout::kUnorm1010102: {  // OpenGL's fixed-point conversion: clamped to [0, 1], round(c * (2^bits - 1))
      const PackedUnorm k = PackingOf(layout);
      std::uint32_t w = 0;
      for (int c = 0; c < 4; ++c) {
        if (!k.bits[c]) continue;
        const float max = float((1u << k.bits[c]) - 1u);
        const float v = in[c] > 0.0f ? std::min(in[c], 1.0f) : 0.0f;  // NaN as 0
        w |= std::uint32_t(std::lrint(v * max)) << k.shift[c];
      }
      StorePacked(layout, p, w);
      break;
    }
    default: break;
  }
}

glm::vec4 TextureLevel::Raw(int i, int j) const { return RawTexel(layout, At(i, j)); }

glm::vec4 TextureLevel::Sampled(int i, int j) const {
  glm::vec4 t = RawTexel(layout, At(i, j));
  if (srgb)
    for (int c = 0; c < 3; ++c) t[c] = SrgbDecodeSample(t[c]);
  return t;
}

glm::vec4 TextureLevel::Texel(int i, int j) const { return Raw(i, j) / StorageScale(layout); }

void TextureLevel::Allocate(Enum internal_format, int w, int h, int sample_count, int d) {
  const TexelLayout l = LayoutOf(internal_format);
  const int b = BytesPerTexel(l);
  const std::uint64_t count = std::uint64_t(std::max(w, 0)) * std::uint64_t(std::max(h, 0)) *
                              std::uint64_t(std::max(sample_count, 1)) * std::uint64_t(std::max(d, 1));
  if (count * std::uint64_t(b) > kMaxLevelBytes) throw std::bad_alloc();
  const std::size_t texels = std::size_t(count);
  data.assign(texels * std::size_t(b) + kGatherPad, 0);
  if (HasStencil(internal_format)) stencil.assign(texels, 0);
  else stencil.clear();
  format = internal_format;
  width = w;
  height = h;
  layout = l;
  bytes = b;
  samples = sample_count;
  depth = std::max(d, 1);
  srgb = IsSrgbFormat(internal_format);
  if (NoStoredAlpha(internal_format))  // alpha reads 1
    for (std::size_t k = 3; k < data.size() - kGatherPad; k += 4) data[k] = 255;
  if (IsIntegerLayout(l) && FormatComponents(internal_format) == 3) {  // RGB8UI ...: alpha is 1 too
    const std::int64_t zero[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < texels; ++k) StoreIntegerTexel(l, data.data() + k * std::size_t(b), zero);
  }
}

void StoreTexel(TextureLevel& level, int i, int j, const glm::vec4& in, bool encode) {
  std::uint8_t* p = level.At(i, j);
  switch (level.layout) {
    case TexelLayout::kUnorm8x4:
      for (int c = 0; c < 4; ++c) p[c] = encode && level.srgb && c < 3 ? SrgbEncode8(in[c]) : FloatToUnorm8(in[c]);
      if (NoStoredAlpha(level.format)) p[3] = 255;
      break;
    case TexelLayout::kUnorm8x2:
      p[0] = FloatToUnorm8(in[0]);
      p[1] = FloatToUnorm8(in[1]);
      break;
    case TexelLayout::kUnorm8x1: p[0] = FloatToUnorm8(in[0]); break;
    case TexelLayout::kFloat32x4: std::memcpy(p, &in.x, 16); break;
    case TexelLayout::kFloat32x2:
    case TexelLayout::kFloat16x4:
    case TexelLayout::kFloat16x2:
    case TexelLayout::kFloat16x1:
    case TexelLayout::kFloat11x11x10:
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551:
    case TexelLayout::kUnorm1010102:
    case TexelLayout::kUnorm16x4:
    case TexelLayout::kUnorm16x2:
    case TexelLayout::kUnorm16x1: StoreSmallFloatTexel(level.layout, p, in); break;
    case TexelLayout::kFloat32x1: {
      float v = in[0];
      if (IsDepthFormat(level.format)) v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);  // depth holds [0, 1]
      std::memcpy(p, &v, 4);
      break;
    }
    default: break;
  }
}

namespace {
// The bytes of one client row of w pixels, aligned: when an element is smaller than the alignment, rows start at
// multiples of it (OpenGL 3.3, section 3.7.4; with larger elements a row's length is already such a multiple).
std::size_t TransferRowBytes(int w, Enum format, Enum type, int alignment) {
  const std::size_t row = std::size_t(w) * TransferPixelBytes(format, type);
  return (row + std::size_t(alignment) - 1) / std::size_t(alignment) * std::size_t(alignment);
}

// The channels RED, RG, RGB and RGBA put first in a texel: the formats whose bytes copy straight into 8-bit
// texels.
bool InTexelOrder(Enum format) { return format == RED || format == RG || format == RGB || format == RGBA; }

void StoreTexelRow(TextureLevel& lv, int x, int row, int n, const float* in, bool encode);

// Rect (x, y, w, h) of `level` from client rows `row` bytes apart, the first pixel at `first`.
void UploadRect(TextureLevel& level, int x, int y, int w, int h, Enum format, Enum type, std::size_t row,
                const std::uint8_t* first, bool swap_bytes) {
  const std::size_t size = TransferPixelBytes(format, type), element = TransferElementBytes(type);
  std::uint8_t swapped[16];
  // The pixel at (i, j), its elements' bytes reversed when asked (into `swapped`).
  auto pixel = [&](int i, int j) -> const std::uint8_t* {
    const std::uint8_t* p = first + std::size_t(j) * row + std::size_t(i) * size;
    if (!swap_bytes || element == 1) return p;
    for (std::size_t e = 0; e < size; e += element)
      for (std::size_t b = 0; b < element; ++b) swapped[e + b] = p[e + element - 1 - b];
    return swapped;
  };
  if (IsIntegerLayout(level.layout)) {  // integers as they are, clamped to the channels' range
    const bool rgb_only = FormatComponents(level.format) == 3;
    std::int64_t v[4];
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        UnpackInteger(format, type, pixel(i, j), v);
        StoreIntegerTexel(level.layout, level.At(x + i, y + j), v, rgb_only);
      }
    return;
  }
  if (format == DEPTH_STENCIL) {  // one packed value a pixel: 4 bytes (24_8) or 8 (float, then 24_8 with stencil low)
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        float depth;
        std::uint8_t stencil;
        UnpackDepthStencil(type, pixel(i, j), depth, stencil);
        StoreTexel(level, x + i, y + j, glm::vec4(std::isnan(depth) ? 0.0f : depth, 0.0f, 0.0f, 1.0f));
        if (!level.stencil.empty())
          level.stencil[std::size_t(y + j) * std::size_t(level.width) + std::size_t(x + i)] = stencil;
      }
    return;
  }
  const int n = int(size);  // components, when they are bytes
  const bool bytes_into_bytes = type == UNSIGNED_BYTE && IsUnorm8(level.layout) && InTexelOrder(format);
  if (bytes_into_bytes && n == level.bytes) {  // rows as they are (an RGB8 texture's alpha byte then set to 255)
    for (int j = 0; j < h; ++j) {
      std::uint8_t* dst = level.At(x, y + j);
      std::memcpy(dst, first + std::size_t(j) * row, std::size_t(w) * size);
      if (NoStoredAlpha(level.format))
        for (int i = 0; i < w; ++i) dst[4 * i + 3] = 255;
    }
    return;
  }
  if (bytes_into_bytes && n == 3 && level.bytes == 4) {  // RGB into RGBA8 or RGB8 (SRGB8...): alpha 255
    for (int j = 0; j < h; ++j) {
      std::uint8_t* dst = level.At(x, y + j);
      const std::uint8_t* src = first + std::size_t(j) * row;
      for (int i = 0; i < w; ++i, dst += 4, src += 3) {
        dst[0] = src[0];
        dst[1] = src[1];
        dst[2] = src[2];
        dst[3] = 255;
      }
    }
    return;
  }
  if (type == FLOAT && format == RGBA && !swap_bytes) {  // four floats a pixel (NaN as 0), stored a row at a time
    std::vector<float> floats(std::size_t(w) * 4);
    for (int j = 0; j < h; ++j) {
      std::memcpy(floats.data(), first + std::size_t(j) * row, floats.size() * 4);
      for (float& v : floats) v = v == v ? v : 0.0f;
      StoreTexelRow(level, x, y + j, w, floats.data(), false);
    }
    return;
  }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::uint8_t* p = pixel(i, j);
      if (bytes_into_bytes) {  // no conversion
        std::uint8_t* dst = level.At(x + i, y + j);
        for (int c = 0; c < level.bytes; ++c) dst[c] = c < n ? p[c] : (c == 3 ? 255 : 0);
        if (NoStoredAlpha(level.format)) dst[3] = 255;
        continue;
      }
      glm::vec4 in = UnpackColor(format, type, p);
      for (int c = 0; c < 4; ++c)
        if (std::isnan(in[c])) in[c] = 0.0f;
      StoreTexel(level, x + i, y + j, in);
    }
}

// The bytes from one client image of `layout` to the next, and from one row to the next, for w x h rectangles.
std::size_t RowBytes(const ClientLayout& layout, int w, Enum format, Enum type) {
  return TransferRowBytes(layout.row_length > 0 ? layout.row_length : w, format, type, layout.alignment);
}
}  // namespace

void UploadImages(TextureLevel& level, int x, int y, int z, int w, int h, int d, Enum format, Enum type,
                  const ClientLayout& layout, const void* pixels) {
  if (pixels == nullptr || w <= 0 || h <= 0) return;
  const std::size_t row = RowBytes(layout, w, format, type);
  const std::size_t image = row * std::size_t(layout.image_height > 0 ? layout.image_height : h);
  const auto* first = static_cast<const std::uint8_t*>(pixels) + std::size_t(layout.skip_images) * image +
                      std::size_t(layout.skip_rows) * row +
                      std::size_t(layout.skip_pixels) * TransferPixelBytes(format, type);
  for (int k = 0; k < d; ++k)
    UploadRect(level, x, (z + k) * level.height + y, w, h, format, type, row, first + std::size_t(k) * image,
               layout.swap_bytes);
}

void UploadPixels(TextureLevel& level, int x, int y, int w, int h, Enum format, Enum type, const ClientLayout& layout,
                  const void* pixels) {
  if (pixels == nullptr || w <= 0 || h <= 0) return;
  const std::size_t row = RowBytes(layout, w, format, type);
  const auto* first = static_cast<const std::uint8_t*>(pixels) + std::size_t(layout.skip_rows) * row +
                      std::size_t(layout.skip_pixels) * TransferPixelBytes(format, type);
  UploadRect(level, x, y, w, h, format, type, row, first, layout.swap_bytes);
}

namespace {

using F4 = V<4>::F;

// `lv` as a colour buffer (for LoadRow and StoreRow; an RGB8 texture's alpha byte reads 1 as it holds 255).
ColorBuffer LevelBuffer(const TextureLevel& lv) {
  ColorBuffer cb;
  cb.data = const_cast<std::uint8_t*>(lv.data.data());
  cb.layout = lv.layout;
  cb.rgb_only = NoStoredAlpha(lv.format);
  cb.pitch = lv.width;
  return cb;
}

// Row `row` of `lv`, texel by texel as Sampled(i, row) / StorageScale gives it, four floats a texel into out: sRGB
// bytes decoded by a table of SrgbDecodeSample's 256 values, the other layouts by LoadRow (Load's values, which
// are Sampled's over the scale where nothing is decoded).
void SampledRow(const TextureLevel& lv, int row, float* out) {
  if (lv.srgb && lv.layout == TexelLayout::kUnorm8x4) {
    static const auto decoded = [] {  // SrgbDecodeSample of each byte
      std::array<float, 256> t{};
      for (int k = 0; k < 256; ++k) t[std::size_t(k)] = SrgbDecodeSample(float(k));
      return t;
    }();
    const std::uint8_t* in = lv.At(0, row);
    for (int i = 0; i < lv.width; ++i, in += 4)
      StoreVec(out + 4 * i, F4{decoded[in[0]], decoded[in[1]], decoded[in[2]], float(in[3])} / 255.0f);
    return;
  }
  if (lv.srgb) {
    const float scale = StorageScale(lv.layout);
    for (int i = 0; i < lv.width; ++i) {
      const glm::vec4 t = lv.Sampled(i, row) / scale;
      StoreVec(out + 4 * i, F4{t.x, t.y, t.z, t.w});
    }
    return;
  }
  LoadRow(LevelBuffer(lv), 1, 0, lv.width, row, out);
}

// Texels [x, x + n) of row `row` of `lv` from four floats each, as StoreTexel(..., encode) stores them: RGBA8 rounded
// in vector form (FloatToUnorm8 a channel; sRGB colour by the bucket table), RGBA16F by StoreRow, every other
// layout through StoreTexel.
void StoreTexelRow(TextureLevel& lv, int x, int row, int n, const float* in, bool encode) {
  if (lv.layout == TexelLayout::kUnorm8x4) {
    // FloatToUnorm8: NaN and <= 0 give 0, >= 1 gives 255, else c * 255 rounded to nearest even (adding and taking
    // away 1.5 x 2^23, exact up to 255).
    constexpr float kRound = 12582912.0f;
    const bool alpha = !NoStoredAlpha(lv.format), srgb = encode && lv.srgb;
    const SrgbLaneTables* table = srgb ? &SrgbLanes() : nullptr;
    std::uint8_t* out = lv.At(x, row);
    for (int i = 0; i < n; ++i, out += 4) {
      const F4 v = LoadVec<F4>(in + 4 * i);
      F4 c = v > 0.0f ? v : F4{};
      c = c < 1.0f ? c : F4{} + 1.0f;
      const V<4>::I k = __builtin_convertvector((c * 255.0f + kRound) - kRound, V<4>::I);
      for (int ch = 0; ch < 3; ++ch) out[ch] = srgb ? SrgbEncode8ByTable(*table, v[ch]) : std::uint8_t(k[ch]);
      out[3] = alpha ? std::uint8_t(k[3]) : 255;
    }
    return;
  }
  if (lv.layout == TexelLayout::kFloat16x4) return StoreRow(LevelBuffer(lv), x, n, row, in);
  for (int i = 0; i < n; ++i)
    StoreTexel(lv, x + i, row, glm::vec4(in[4 * i], in[4 * i + 1], in[4 * i + 2], in[4 * i + 3]), encode);
}

// Level `dst` of a 2D image, cube face or array from `src` above it, layer by layer: each texel the bilinear
// sample of src at its centre, clamped to the edge, as GenerateMipmaps's general loop computes it (the same
// operations in the same order), with src's rows decoded once and each column's taps and weight found once.
void DownsampleLayers(const TextureLevel& src, TextureLevel& dst) {
  const int w = dst.width;
  std::vector<int> c0(static_cast<std::size_t>(w)), c1(static_cast<std::size_t>(w));
  std::vector<float> wa(static_cast<std::size_t>(w));
  for (int i = 0; i < w; ++i) {
    const float u = (float(i) + 0.5f) * float(src.width) / float(dst.width) - 0.5f;
    const int i0 = int(std::floor(u));
    wa[std::size_t(i)] = u - float(i0);
    c0[std::size_t(i)] = std::clamp(i0, 0, src.width - 1);
    c1[std::size_t(i)] = std::clamp(i0 + 1, 0, src.width - 1);
  }
  std::vector<float> rows(std::size_t(src.width) * 8), out(std::size_t(w) * 4);
  // Two decoded rows, each with the row it holds: a row is decoded into the slot that does not hold `keep`.
  float* const slot[2] = {rows.data(), rows.data() + std::size_t(src.width) * 4};
  int held[2] = {-1, -1};
  auto row = [&](int want, int keep) -> const float* {
    for (int t = 0; t < 2; ++t)
      if (held[t] == want) return slot[t];
    const int t = held[0] == keep ? 1 : 0;
    SampledRow(src, want, slot[t]);
    held[t] = want;
    return slot[t];
  };
  for (int k = 0; k < dst.depth; ++k) {
    for (int j = 0; j < dst.height; ++j) {
      const float v = (float(j) + 0.5f) * float(src.height) / float(dst.height) - 0.5f;
      const int j0 = int(std::floor(v));
      const float b = v - float(j0);
      const int above = k * src.height + std::clamp(j0, 0, src.height - 1);
      const float* r0 = row(above, -1);
      const float* r1 = row(k * src.height + std::clamp(j0 + 1, 0, src.height - 1), above);
      for (int i = 0; i < w; ++i) {
        const float a = wa[std::size_t(i)];
        const std::size_t x0 = std::size_t(c0[std::size_t(i)]) * 4, x1 = std::size_t(c1[std::size_t(i)]) * 4;
        // (Weights (1 - a)(1 - b) and so on, each times the one slice's weight 1, summed from 0 as taps (0, 0),
        // (1, 0), (0, 1), (1, 1).)
        F4 sum = F4{};
        sum = sum + (((1.0f - a) * (1.0f - b)) * 1.0f) * LoadVec<F4>(r0 + x0);
        sum = sum + ((a * (1.0f - b)) * 1.0f) * LoadVec<F4>(r0 + x1);
        sum = sum + (((1.0f - a) * b) * 1.0f) * LoadVec<F4>(r1 + x0);
        sum = sum + ((a * b) * 1.0f) * LoadVec<F4>(r1 + x1);
        StoreVec(out.data() + 4 * i, sum);
      }
      StoreTexelRow(dst, 0, k * dst.height + j, w, out.data(), true);
    }
  }
}

}  // namespace

void GenerateMipmaps(TextureObject& texture) {
  const int base = std::clamp(texture.params.base_level, 0, kMaxLevels - 1);
  const bool volume = texture.target == TEXTURE_3D;
  for (int face = 0; face < texture.Faces(); ++face) {
    for (int l = base + 1; l < kMaxLevels; ++l) {
      const TextureLevel& src = texture.levels[face][l - 1];
      if (src.width == 1 && src.height == 1 && (!volume || src.depth == 1)) {
        for (int k = l; k < kMaxLevels; ++k) texture.levels[face][k] = TextureLevel{};
        break;
      }
      TextureLevel& dst = texture.levels[face][l];
      dst.Allocate(src.format, std::max(1, src.width / 2), std::max(1, src.height / 2), 1,
                   volume ? std::max(1, src.depth / 2) : src.depth);
      if (!volume) {
        DownsampleLayers(src, dst);
        continue;
      }
      for (int k = 0; k < dst.depth; ++k) {
        // A 3D level's slice k lies between two slices of the level above (one when that has a single slice); an
        // array's layer k is layer k above.
        const float w = volume ? (float(k) + 0.5f) * float(src.depth) / float(dst.depth) - 0.5f : float(k);
        const int k0 = int(std::floor(w));
        const float c = w - float(k0);
        const int slices = volume && c > 0.0f ? 2 : 1;
        for (int j = 0; j < dst.height; ++j)
          for (int i = 0; i < dst.width; ++i) {
            // Bilinear (trilinear) sample of src at this texel's centre, clamped to the edge.
            const float u = (float(i) + 0.5f) * float(src.width) / float(dst.width) - 0.5f;
            const float v = (float(j) + 0.5f) * float(src.height) / float(dst.height) - 0.5f;
            const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
            const float a = u - float(i0), b = v - float(j0);
            glm::vec4 sum(0.0f);
            for (int dk = 0; dk < slices; ++dk) {
              const float wk = slices == 1 ? 1.0f : (dk ? c : 1.0f - c);
              const int row0 = std::clamp(k0 + dk, 0, src.depth - 1) * src.height;
              for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di) {
                  const float wgt = (di ? a : 1.0f - a) * (dj ? b : 1.0f - b) * wk;
                  sum += wgt * (src.Sampled(std::clamp(i0 + di, 0, src.width - 1),
                                            row0 + std::clamp(j0 + dj, 0, src.height - 1)) /
                                StorageScale(src.layout));
                }
            }
            StoreTexel(dst, i, k * dst.height + j, sum, true);
          }
      }
    }
  }
}

bool IsBufferTextureFormat(Enum f) {
  switch (f) {
    case R8: case R16: case R16F: case R32F: case RG8: case RG16: case RG16F: case RG32F: case RGBA8: case RGBA16:
    case RGBA16F: case RGBA32F: case R8I: case R8UI: case R16I: case R16UI: case R32I: case R32UI: case RG8I:
    case RG8UI: case RG16I: case RG16UI: case RG32I: case RG32UI: case RGBA8I: case RGBA8UI: case RGBA16I:
    case RGBA16UI: case RGBA32I: case RGBA32UI: return true;
    default: return false;
  }
}

TextureView MakeView(const TextureObject& texture, const SamplerParams* sampler) {
  TextureView view;
  view.texture = &texture;
  view.params = texture.params;
  if (sampler) {  // every sampling parameter but the levels, which belong to the texture
    view.params = *sampler;
    view.params.base_level = texture.params.base_level;
    view.params.max_level = texture.params.max_level;
  }
  if (texture.target == TEXTURE_BUFFER) {  // texels read in place from the buffer's store: no levels, no filtering
    view.layout = LayoutOf(texture.buffer_format);
    view.scale = StorageScale(view.layout);
    view.integer = IsIntegerLayout(view.layout);
    view.complete = texture.buffer_store != nullptr;
    if (view.complete && BytesPerTexel(view.layout) > 0) {
      view.buffer = texture.buffer_store->data();
      view.buffer_texels = int(std::min<std::size_t>(texture.buffer_store->size() / std::size_t(BytesPerTexel(view.layout)),
                                                     std::size_t(kMaxTextureBufferSize)));
    }
    return view;
  }
  if (texture.target == TEXTURE_1D || texture.target == TEXTURE_1D_ARRAY) {
    // One texel high, sampled at its middle: TEXTURE_WRAP_T has no part (a border texel would enter LINEAR's
    // weights at 0, and a NaN border colour would still reach the sum).
    view.params.wrap_t = view.params.wrap_r = CLAMP_TO_EDGE;
  }
  const SamplerParams& p = view.params;
  view.base = p.base_level;
  if (p.base_level < 0 || p.base_level >= kMaxLevels || p.base_level > p.max_level) return view;
  if (IsMultisampleTarget(texture.target)) {  // one image (of layers), fetched by sample: no levels, no filtering
    const TextureLevel& image = texture.levels[0][0];
    view.base = view.q = 0;
    view.complete = image.Defined();
    view.layout = image.layout;
    view.srgb = image.srgb;
    view.depth = IsDepthFormat(image.format);
    view.scale = StorageScale(image.layout);
    view.integer = IsIntegerLayout(image.layout);
    return view;
  }
  const TextureLevel& base = texture.levels[0][p.base_level];
  if (!base.Defined()) return view;
  view.depth = IsDepthFormat(base.format);
  view.layout = base.layout;
  view.srgb = base.srgb;
  view.anisotropy = std::min(p.max_anisotropy, kMaxAnisotropy);
  view.scale = StorageScale(base.layout);
  // The border colour in storage units; a fixed-point texture takes it clamped to [0, 1], as it takes texels.
  view.border_raw = IsUnorm8(base.layout)    ? glm::clamp(p.border, 0.0f, 1.0f) * 255.0f
                    : IsWideFixedPoint(base.layout) ? glm::clamp(p.border, 0.0f, 1.0f)
                                              : p.border;
  view.integer = IsIntegerLayout(base.layout);
  if (view.integer) {
    // An integer texture's border is the numbers TexParameterI* gave, else the bits of the floats (Mesa keeps the
    // colour as one union and reads it so); it is filtered by NEAREST only (any other filter leaves it incomplete).
    std::uint32_t bits[4];
    if (p.border_integer) std::memcpy(bits, p.border_bits, 16);
    else std::memcpy(bits, &p.border.x, 16);
    std::memcpy(&view.border_raw.x, bits, 16);
    view.anisotropy = 1.0f;
  }
  // The border colour as a texel of the format (OpenGL 4.6, section 8.14.2 and table 8.11): the channels the
  // format lacks read 0, alpha 1 (in storage units; an integer format's 1).
  const int channels = FormatComponents(base.format);
  for (int c = channels; c < 3; ++c) view.border_raw[c] = 0.0f;
  if (channels < 4) {
    view.border_raw.a = IsUnorm8(base.layout) ? 255.0f : 1.0f;
    if (view.integer) view.border_raw.a = std::bit_cast<float>(1);
  }
  if (view.integer && (p.mag_filter != NEAREST || (p.min_filter != NEAREST && p.min_filter != NEAREST_MIPMAP_NEAREST)))
    return view;
  // q: the last level of the chain, level_base + floor(log2(max size)), but at most level_max.
  int levels = 0;
  const bool volume = texture.target == TEXTURE_3D;
  for (int size = std::max({base.width, base.height, volume ? base.depth : 1}); size > 1; size >>= 1) ++levels;
  view.q = std::min({p.base_level + levels, p.max_level, kMaxLevels - 1});
  const bool mipmapped = p.min_filter != NEAREST && p.min_filter != LINEAR;
  const int last = mipmapped ? view.q : p.base_level;
  for (int face = 0; face < texture.Faces(); ++face) {
    for (int l = p.base_level; l <= last; ++l) {
      const TextureLevel& lv = texture.levels[face][l];
      const int shift = l - p.base_level;
      if (lv.format != base.format || lv.compressed != base.compressed || lv.width != std::max(1, base.width >> shift) ||
          lv.height != std::max(1, base.height >> shift) ||
          lv.depth != (volume ? std::max(1, base.depth >> shift) : base.depth))
        return view;
    }
  }
  if (texture.target == TEXTURE_CUBE_MAP && base.width != base.height) return view;
  view.complete = true;
  const bool pow2 = (base.width & (base.width - 1)) == 0 && (base.height & (base.height - 1)) == 0;
  if (texture.target == TEXTURE_2D && !view.depth && view.anisotropy <= 1.0f && pow2 && p.wrap_s == REPEAT && p.wrap_t == REPEAT &&
      p.mag_filter == LINEAR && p.compare_mode == NONE) {
    if (p.min_filter == LINEAR) view.fast = TextureView::Fast::kRepeatLinear;
    if (p.min_filter == LINEAR_MIPMAP_LINEAR) view.fast = TextureView::Fast::kRepeatTrilinear;
  }
  view.wide = (texture.target == TEXTURE_2D || texture.target == TEXTURE_CUBE_MAP || texture.target == TEXTURE_2D_ARRAY ||
              texture.target == TEXTURE_3D || texture.target == TEXTURE_1D || texture.target == TEXTURE_1D_ARRAY);
  return view;
}

}  // namespace softgl::detail

// framebuffer.cpp — storage, format conversion on store, and clears.
#include "framebuffer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

#include "simd.h"
#include "wide.h"

#if defined(SOFTGL_HAS_DISPATCH)
#include <immintrin.h>
#endif

namespace softgl::detail {

std::uint8_t FloatToUnorm8(float f) {
  if (!(f > 0.0f)) return 0;  // also NaN
  if (f >= 1.0f) return 255;
  return std::uint8_t(std::lrint(f * 255.0f));
}

glm::vec4 ColorBuffer::Load(int x, int y) const {
  glm::vec4 raw = RawTexel(layout, At(x, y));
  if (IsIntegerLayout(layout)) return raw;  // the integers as the floats' bits
  if (rgb_only) raw.a = 255.0f;
  if (srgb) return glm::vec4(SrgbDecode8(std::uint8_t(raw.r)), SrgbDecode8(std::uint8_t(raw.g)),
                             SrgbDecode8(std::uint8_t(raw.b)), raw.a / 255.0f);
  return raw / StorageScale(layout);
}

void ColorBuffer::Store(int x, int y, const glm::vec4& c, const bool mask[4]) const {
  std::uint8_t* p = At(x, y);
  switch (layout) {
    case TexelLayout::kUnorm8x4:
    case TexelLayout::kUnorm8x2:
    case TexelLayout::kUnorm8x1: {
      const int n = layout == TexelLayout::kUnorm8x4 ? (rgb_only ? 3 : 4) : layout == TexelLayout::kUnorm8x2 ? 2 : 1;
      for (int k = 0; k < n; ++k)
        if (mask[k]) p[k] = srgb && k < 3 ? SrgbEncode8(c[k]) : FloatToUnorm8(c[k]);
      return;
    }
    case TexelLayout::kFloat32x4:
      for (int k = 0; k < 4; ++k)
        if (mask[k]) std::memcpy(p + 4 * k, &c[k], 4);
      return;
    case TexelLayout::kFloat32x1:
      if (mask[0]) std::memcpy(p, &c[0], 4);
      return;
    default: {
      if (IsIntegerLayout(layout)) {  // c holds integers as its floats' bits: stored clamped to the channels' range
        const glm::ivec4 old = IntegerTexel(layout, p);
        std::int32_t bits[4];
        std::memcpy(bits, &c.x, 16);
        std::int64_t v[4];
        for (int k = 0; k < 4; ++k) v[k] = IntegerValue(layout, mask[k] ? bits[k] : old[k]);
        StoreIntegerTexel(layout, p, v);
        return;
      }
      // The other float layouts: the masked channels replaced, the texel encoded again.
      glm::vec4 v = RawTexel(layout, p);
      for (int k = 0; k < 4; ++k)
        if (mask[k]) v[k] = c[k];
      StoreSmallFloatTexel(layout, p, v);
      return;
    }
  }
}

int SupportedSamples(int requested) {
  return requested <= 0 ? 1 : requested <= 2 ? 2 : requested <= 4 ? 4 : 8;
}

RenderTarget RenderTarget::Sample(int s) const {
  RenderTarget t = *this;
  t.samples = 1;
  t.interleaved = false;
  for (ColorBuffer& cb : t.color)
    if (cb.Present()) cb.data += cb.plane * std::size_t(s) * std::size_t(cb.Bytes());
  if (depth) t.depth += depth_plane * std::size_t(s);
  if (depth16) t.depth16 += depth_plane * std::size_t(s);
  if (stencil) t.stencil += stencil_plane * std::size_t(s);
  return t;
}

RenderTarget RenderTarget::Flat() const {
  RenderTarget t = *this;
  t.width = width * samples;
  t.samples = 1;
  t.interleaved = false;
  t.step = 1;
  for (ColorBuffer& cb : t.color) cb.step = 1;
  return t;
}

namespace {
// Rectangle r of an interleaved target in its Flat() view.
Rect FlatRect(const Rect& r, int samples) { return Rect{r.x0 * samples, r.y0, r.x1 * samples, r.y1}; }

// Every sample of rectangle r of colour buffer cb (`samples` planes) set to one texel's bytes.
void FillTexels(ColorBuffer cb, int samples, Rect r, const std::uint8_t* texel) {
  if (samples > 1 && cb.step == samples && cb.plane == 1) {  // side by side: runs of every sample
    r = FlatRect(r, samples);
    samples = 1;
    cb.step = 1;
  }
  const std::size_t bytes = std::size_t(cb.Bytes());
  if (cb.step != 1) {
    for (int s = 0; s < samples; ++s)
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
          std::memcpy(cb.At(x, y) + cb.plane * std::size_t(s) * bytes, texel, bytes);
    return;
  }
  const int width = r.x1 - r.x0;
  if (bytes == 4) {  // (RGBA8 and the other 32-bit texels: a loop of stores the compiler vectorizes)
    std::uint32_t value;
    std::memcpy(&value, texel, 4);
    for (int s = 0; s < samples; ++s)
      for (int y = r.y0; y < r.y1; ++y) {
        std::uint8_t* row = cb.At(r.x0, y) + cb.plane * std::size_t(s) * bytes;
        for (int x = 0; x < width; ++x) std::memcpy(row + 4 * std::size_t(x), &value, 4);
      }
    return;
  }
  std::uint8_t run[16 * 16];  // 16 texels of at most 16 bytes
  for (int k = 0; k < 16; ++k) std::memcpy(run + std::size_t(k) * bytes, texel, bytes);
  for (int s = 0; s < samples; ++s)
    for (int y = r.y0; y < r.y1; ++y) {
      std::uint8_t* row = cb.At(r.x0, y) + cb.plane * std::size_t(s) * bytes;
      int x = 0;
      for (; x + 16 <= width; x += 16) std::memcpy(row + std::size_t(x) * bytes, run, 16 * bytes);
      std::memcpy(row + std::size_t(x) * bytes, run, std::size_t(width - x) * bytes);
    }
}
}  // namespace

glm::vec4 LoadResolved(const ColorBuffer& cb, int samples, int x, int y) {
  if (IsUnorm8(cb.layout) && !cb.srgb) {  // bytes: their average rounded half up, exactly
    glm::vec4 out = cb.Load(x, y);
    const int n = cb.layout == TexelLayout::kUnorm8x4 ? (cb.rgb_only ? 3 : 4) : cb.layout == TexelLayout::kUnorm8x2 ? 2 : 1;
    for (int k = 0; k < n; ++k) {
      int sum = 0;
      for (int s = 0; s < samples; ++s) sum += cb.data[(cb.plane * std::size_t(s) + cb.Index(x, y)) * std::size_t(cb.Bytes()) + std::size_t(k)];
      out[k] = float((sum * 2 + samples) / (2 * samples)) / 255.0f;
    }
    return out;
  }
  glm::vec4 sum(0.0f);
  ColorBuffer plane = cb;
  for (int s = 0; s < samples; ++s) {
    plane.data = cb.data + cb.plane * std::size_t(s) * std::size_t(cb.Bytes());
    sum += plane.Load(x, y);
  }
  return sum / float(samples);
}

namespace {
// Where channel c lies in a texel of `layout` (little-endian bits): its first bit and bit count (0: the layout
// lacks it).
struct ChannelBits {
  int shift = 0, bits = 0;
};
ChannelBits ChannelBitsOf(TexelLayout l, int c) {
  switch (l) {
    case TexelLayout::kUnorm8x4: return {8 * c, 8};
    case TexelLayout::kUnorm8x2: return c < 2 ? ChannelBits{8 * c, 8} : ChannelBits{};
    case TexelLayout::kUnorm8x1: return c < 1 ? ChannelBits{0, 8} : ChannelBits{};
    case TexelLayout::kFloat32x4: return {32 * c, 32};
    case TexelLayout::kFloat32x2: return c < 2 ? ChannelBits{32 * c, 32} : ChannelBits{};
    case TexelLayout::kFloat32x1: return c < 1 ? ChannelBits{0, 32} : ChannelBits{};
    case TexelLayout::kFloat16x4:
    case TexelLayout::kUnorm16x4: return {16 * c, 16};
    case TexelLayout::kFloat16x2:
    case TexelLayout::kUnorm16x2: return c < 2 ? ChannelBits{16 * c, 16} : ChannelBits{};
    case TexelLayout::kFloat16x1:
    case TexelLayout::kUnorm16x1: return c < 1 ? ChannelBits{0, 16} : ChannelBits{};
    case TexelLayout::kFloat11x11x10: return c < 3 ? ChannelBits{11 * c, c < 2 ? 11 : 10} : ChannelBits{};
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551:
    case TexelLayout::kUnorm1010102: {
      const PackedUnorm p = PackingOf(l);
      return {p.shift[c], p.bits[c]};
    }
    case TexelLayout::kUint1010102: return {10 * c, c < 3 ? 10 : 2};
    default: {
      const IntegerLayout k = IntegerLayoutOf(l);
      return c < k.channels ? ChannelBits{8 * k.bytes * c, 8 * k.bytes} : ChannelBits{};
    }
  }
}
}  // namespace

void RenderTarget::ClearColor(const Rect& r, const glm::vec4& value, const bool mask[4], std::uint32_t buffers) const {
  if (interleaved) return Flat().ClearColor(FlatRect(r, samples), value, mask, buffers);
  if (samples > 1) {
    for (int s = 0; s < samples; ++s) Sample(s).ClearColor(r, value, mask, buffers);
    return;
  }
  for (int o = 0; o < kMaxColorOutputs; ++o) {
    const ColorBuffer& cb = color[o];
    if (!cb.Present() || r.Empty() || !((buffers >> o) & 1u)) continue;
    // The texel is encoded once (Store's conversion), with the bits the colour mask keeps (and an RGB buffer's
    // unstored alpha byte); then whole rows are filled, or merged through those bits 16 bytes at a time.
    const std::size_t bytes = std::size_t(cb.Bytes());
    std::uint8_t texel[16] = {}, keep[16] = {};
    ColorBuffer one = cb;
    one.data = texel;
    const bool all[4] = {true, true, true, true};
    one.Store(0, 0, value, all);
    bool any_kept = false;
    for (int c = 0; c < 4; ++c) {
      if (mask[c] && !(c == 3 && cb.rgb_only)) continue;
      const ChannelBits ch = ChannelBitsOf(cb.layout, c);
      for (int bit = ch.shift; bit < ch.shift + ch.bits; ++bit) keep[bit / 8] |= std::uint8_t(1u << (bit % 8));
      any_kept = any_kept || ch.bits > 0;
    }
    if (!any_kept) {
      FillTexels(cb, 1, r, texel);
      continue;
    }
    std::uint8_t value16[16], keep16[16];  // the texel and its kept bits repeated over 16 bytes
    for (std::size_t k = 0; k < 16; ++k) {
      value16[k] = std::uint8_t(texel[k % bytes] & ~keep[k % bytes]);
      keep16[k] = keep[k % bytes];
    }
    const std::size_t n = std::size_t(r.x1 - r.x0) * bytes;
    for (int y = r.y0; y < r.y1; ++y) {
      std::uint8_t* row = cb.At(r.x0, y);
      std::size_t i = 0;
      for (; i + 16 <= n; i += 16)
        for (std::size_t k = 0; k < 16; ++k) row[i + k] = std::uint8_t((row[i + k] & keep16[k]) | value16[k]);
      for (; i < n; ++i) row[i] = std::uint8_t((row[i] & keep16[i % 16]) | value16[i % 16]);
    }
  }
}

void RenderTarget::ClearDepth(const Rect& r, float value) const {
  if (!HasDepth() || r.Empty()) return;
  if (interleaved) return Flat().ClearDepth(FlatRect(r, samples), value);
  if (samples > 1) {
    for (int s = 0; s < samples; ++s) Sample(s).ClearDepth(r, value);
    return;
  }
  const std::uint16_t value16 = Depth16(value);
  if (step != 1) {  // one sample of an interleaved target
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) SetDepth(x, y, StoredDepth(value));
    return;
  }
  for (int y = r.y0; y < r.y1; ++y) {
    if (depth16) std::fill_n(depth16 + DepthIndex(r.x0, y, 0), r.x1 - r.x0, value16);
    else std::fill_n(depth + DepthIndex(r.x0, y, 0), r.x1 - r.x0, value);
  }
}

void RenderTarget::ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask) const {
  if (!stencil || r.Empty()) return;
  if (interleaved) return Flat().ClearStencil(FlatRect(r, samples), value, write_mask);
  if (samples > 1) {
    for (int s = 0; s < samples; ++s) Sample(s).ClearStencil(r, value, write_mask);
    return;
  }
  for (int y = r.y0; y < r.y1; ++y) {
    if (write_mask == 0xFF && step == 1) {  // every bit written: a fill of the row
      std::memset(&Stencil(r.x0, y), value, std::size_t(r.x1 - r.x0));
      continue;
    }
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = Stencil(x, y);
      s = std::uint8_t((s & ~write_mask) | (value & write_mask));
    }
  }
}

namespace {

// Where destination pixels [d0, d1) along one axis read: the source coordinate of each pixel centre, for the
// rectangles' edges s0, s1 (source) and e0, e1 (destination).
struct BlitAxis {
  int d0 = 0, d1 = 0;  // destination pixels written, clipped
  double s0 = 0, scale = 0, e0 = 0;
  double At(int d) const { return s0 + (double(d) + 0.5 - e0) * scale; }
};
BlitAxis MakeAxis(int s0, int s1, int e0, int e1, int clip0, int clip1) {
  BlitAxis a;
  a.s0 = s0;
  a.e0 = e0;
  a.scale = (double(s1) - double(s0)) / (double(e1) - double(e0));
  a.d0 = std::max(std::min(e0, e1), clip0);
  a.d1 = std::min(std::max(e0, e1), clip1);
  return a;
}

// The pixel index holding coordinate c, or -1 outside [0, size).
int PixelAt(double c, int size) {
  if (!(c >= 0.0) || c >= double(size)) return -1;
  return int(c);
}

}  // namespace

namespace {

// out[i] = the average of in[i + s * plane] over the S planes, rounded half up.
template <int S>
void AverageBytes(const std::uint8_t* in, std::size_t plane, std::uint8_t* out, int n) {
  constexpr int kShift = S == 2 ? 1 : S == 4 ? 2 : 3;
  for (int i = 0; i < n; ++i) {
    unsigned sum = S / 2;
    for (int s = 0; s < S; ++s) sum += in[std::size_t(s) * plane + std::size_t(i)];
    out[i] = std::uint8_t(sum >> kShift);
  }
}
// The same for samples side by side: out[4 i + k] = the average of in[4 (S i + s) + k] (n pixels of 4 bytes).
// Each pixel's S words summed as two pairs of 16-bit halves (bytes 0 and 2, bytes 1 and 3): at most 8 x 255 each.
template <int S>
void AverageInterleaved(const std::uint8_t* in, std::uint8_t* out, int n) {
  constexpr int kShift = S == 2 ? 1 : S == 4 ? 2 : 3;
  constexpr std::uint32_t kLow = 0x00FF00FFu, kRound = (S / 2) * 0x00010001u;
  for (int i = 0; i < n; ++i) {
    std::uint32_t even = kRound, odd = kRound;
    for (int s = 0; s < S; ++s) {
      std::uint32_t w;
      std::memcpy(&w, in + (std::size_t(i) * S + std::size_t(s)) * 4, 4);
      even += w & kLow;
      odd += (w >> 8) & kLow;
    }
    const std::uint32_t word = ((even >> kShift) & kLow) | (((odd >> kShift) & kLow) << 8);
    std::memcpy(out + std::size_t(i) * 4, &word, 4);
  }
}

// The floats c / (2^bits - 1) of every code c of a packed channel of `bits` bits (1 to 10), as RawTexel computes
// them: what a resolve sums.
const float* PackedCodeFloats(int bits) {
  static const auto tables = [] {
    std::vector<std::vector<float>> t(11);
    for (int b = 1; b <= 10; ++b) {
      const unsigned max = (1u << b) - 1u;
      for (unsigned c = 0; c <= max; ++c) t[std::size_t(b)].push_back(float(c) / float(max));
    }
    return t;
  }();
  return tables[std::size_t(bits)].data();
}

// Resolving a run of pixels into a buffer of the same format, a format at a time, without LoadResolved's and
// Store's per-texel dispatch but with their operations in their order (so the same bytes): each channel's values
// summed in sample order, divided by the count, and encoded. Texel (x, s) of the source lies at
// in + (x * in_step + s * plane) texels, pixel x of the destination at out + x texels.
struct ResolveRun {
  const std::uint8_t* in;
  std::size_t in_step, plane;
  std::uint8_t* out;
  int samples, n;
  const std::uint8_t* Texel(int x, int s, int bytes) const {
    return in + (std::size_t(x) * in_step + std::size_t(s) * plane) * std::size_t(bytes);
  }
};

std::uint16_t Bits16(const std::uint8_t* p) {
  std::uint16_t h;
  std::memcpy(&h, p, 2);
  return h;
}
std::uint32_t Bits32(const std::uint8_t* p) {
  std::uint32_t w;
  std::memcpy(&w, p, 4);
  return w;
}

// Packed fixed point (RGB565, RGBA4, RGB5_A1, RGB10_A2): RawTexel's c / (2^bits - 1), Store's clamp and round.
void ResolvePacked(TexelLayout layout, const ResolveRun& r) {
  const PackedUnorm k = PackingOf(layout);
  const int bytes = BytesPerTexel(layout);
  const float* value[4];
  float max[4];
  for (int c = 0; c < 4; ++c) {
    value[c] = k.bits[c] ? PackedCodeFloats(k.bits[c]) : nullptr;
    max[c] = float((1u << k.bits[c]) - 1u);
  }
  const float count = float(r.samples);
  for (int x = 0; x < r.n; ++x) {
    std::uint32_t codes[8];
    for (int s = 0; s < r.samples; ++s) codes[s] = bytes == 2 ? Bits16(r.Texel(x, s, 2)) : Bits32(r.Texel(x, s, 4));
    std::uint32_t w = 0;
    for (int c = 0; c < 4; ++c) {
      if (!value[c]) continue;
      const std::uint32_t mask = (1u << k.bits[c]) - 1u;
      float sum = 0.0f;
      for (int s = 0; s < r.samples; ++s) sum += value[c][(codes[s] >> k.shift[c]) & mask];
      const float avg = sum / count;
      const float v = avg > 0.0f ? std::min(avg, 1.0f) : 0.0f;
      w |= std::uint32_t(std::lrint(v * max[c])) << k.shift[c];
    }
    if (bytes == 2) {
      const std::uint16_t h = std::uint16_t(w);
      std::memcpy(r.out + std::size_t(x) * 2, &h, 2);
    } else {
      std::memcpy(r.out + std::size_t(x) * 4, &w, 4);
    }
  }
}

// N channels of `Element` bytes each: decode(p) the float of the channel at p, encode(v, p) stores one.
template <int N, int Element, class Decode, class Encode>
void ResolveChannels(const ResolveRun& r, Decode decode, Encode encode) {
  const float count = float(r.samples);
  for (int x = 0; x < r.n; ++x)
    for (int c = 0; c < N; ++c) {
      float sum = 0.0f;
      for (int s = 0; s < r.samples; ++s) sum += decode(r.Texel(x, s, N * Element) + c * Element);
      encode(sum / count, r.out + (std::size_t(x) * N + std::size_t(c)) * Element);
    }
}

#if defined(SOFTGL_HAS_DISPATCH)
// ResolvePacked, 8 pixels at a time (its scalar form takes the rest): the same division of each code, sums in
// sample order, division, clamp and rounding to nearest even (VCVTPS2DQ in the default rounding mode, as lrint).
SOFTGL_TARGET_AVX2 void ResolvePackedAvx2(TexelLayout layout, const ResolveRun& r) {
  using F = V<8>::F;
  using I = V<8>::I;
  using U = V<8>::U;
  const PackedUnorm k = PackingOf(layout);
  const int bytes = BytesPerTexel(layout);
  const F count = F{} + float(r.samples);
  int x = 0;
  for (; x + 8 <= r.n; x += 8) {
    U codes[8];
    for (int s = 0; s < r.samples; ++s)
      for (int l = 0; l < 8; ++l) codes[s][l] = bytes == 2 ? Bits16(r.Texel(x + l, s, 2)) : Bits32(r.Texel(x + l, s, 4));
    U w = U{};
    for (int c = 0; c < 4; ++c) {
      if (!k.bits[c]) continue;
      const std::uint32_t mask = (1u << k.bits[c]) - 1u;
      const F max = F{} + float(mask);
      F sum = F{};
      for (int s = 0; s < r.samples; ++s) sum += __builtin_convertvector(I((codes[s] >> k.shift[c]) & mask), F) / max;
      const F avg = sum / count;
      const F v = avg > 0.0f ? (avg > 1.0f ? F{} + 1.0f : avg) : F{};
      w |= U(_mm256_cvtps_epi32(__m256(v * max))) << k.shift[c];
    }
    for (int l = 0; l < 8; ++l) {
      if (bytes == 2) {
        const std::uint16_t h = std::uint16_t(w[l]);
        std::memcpy(r.out + std::size_t(x + l) * 2, &h, 2);
      } else {
        const std::uint32_t word = w[l];
        std::memcpy(r.out + std::size_t(x + l) * 4, &word, 4);
      }
    }
  }
  if (x < r.n) {
    ResolveRun rest = r;
    rest.in = r.Texel(x, 0, bytes);
    rest.out = r.out + std::size_t(x) * std::size_t(bytes);
    rest.n = r.n - x;
    ResolvePacked(layout, rest);
  }
}

// RGBA16F by F16C: a texel's four halves converted at once (VCVTPH2PS: HalfToFloat's values, a NaN made quiet
// with its payload kept), summed in sample order, divided, and converted back (VCVTPS2PH, to nearest even, as
// FloatToHalf), NaNs made sign | 0x7E00 after as FloatToHalf makes them. The same bytes as ResolveChannels.
SOFTGL_TARGET_AVX2 void ResolveHalves4F16c(const ResolveRun& r) {
  const __m128 count = _mm_set1_ps(float(r.samples));
  for (int x = 0; x < r.n; ++x) {
    __m128 sum = _mm_setzero_ps();
    for (int s = 0; s < r.samples; ++s)
      sum = _mm_add_ps(sum, _mm_cvtph_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(r.Texel(x, s, 8)))));
    const __m128 avg = _mm_div_ps(sum, count);
    __m128i h = _mm_cvtps_ph(avg, _MM_FROUND_TO_NEAREST_INT);
    const __m128i nan = _mm_packs_epi32(_mm_castps_si128(_mm_cmpunord_ps(avg, avg)), _mm_setzero_si128());
    h = _mm_or_si128(_mm_andnot_si128(nan, h),
                     _mm_and_si128(nan, _mm_or_si128(_mm_and_si128(h, _mm_set1_epi16(short(0x8000))),
                                                     _mm_set1_epi16(0x7E00))));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(r.out + std::size_t(x) * 8), h);
  }
}
#endif

// 8-bit channels (not sRGB): LoadResolved's integer average, rounded half up (what Store keeps of it).
void ResolveBytes(int channels, const ResolveRun& r) {
  for (int x = 0; x < r.n; ++x)
    for (int c = 0; c < channels; ++c) {
      int sum = 0;
      for (int s = 0; s < r.samples; ++s) sum += r.Texel(x, s, channels)[c];
      r.out[std::size_t(x) * std::size_t(channels) + std::size_t(c)] =
          std::uint8_t((sum * 2 + r.samples) / (2 * r.samples));
    }
}

// SRGB8_ALPHA8 while FRAMEBUFFER_SRGB is enabled: the colour decoded (SrgbDecode8), averaged in linear light and
// encoded again (SrgbEncode8); alpha as a fixed-point value.
void ResolveSrgb(const ResolveRun& r) {
  const float count = float(r.samples);
  for (int x = 0; x < r.n; ++x)
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (int s = 0; s < r.samples; ++s) {
        const std::uint8_t k = r.Texel(x, s, 4)[c];
        sum += c < 3 ? SrgbDecode8(k) : float(k) / 255.0f;
      }
      const float avg = sum / count;
      r.out[std::size_t(x) * 4 + std::size_t(c)] = c < 3 ? SrgbEncode8(avg) : FloatToUnorm8(avg);
    }
}

// R11F_G11F_B10F: each small float decoded, averaged and encoded again (rounded to nearest, ties to even).
void ResolveSmallFloats(const ResolveRun& r) {
  constexpr int kShift[3] = {0, 11, 22}, kMantissa[3] = {6, 6, 5};
  constexpr std::uint32_t kMask[3] = {0x7FFu, 0x7FFu, 0x3FFu};
  const float count = float(r.samples);
  for (int x = 0; x < r.n; ++x) {
    std::uint32_t w = 0;
    for (int c = 0; c < 3; ++c) {
      float sum = 0.0f;
      for (int s = 0; s < r.samples; ++s)
        sum += UnsignedSmallToFloat((Bits32(r.Texel(x, s, 4)) >> kShift[c]) & kMask[c], kMantissa[c]);
      w |= FloatToUnsignedSmall(sum / count, kMantissa[c]) << kShift[c];
    }
    std::memcpy(r.out + std::size_t(x) * 4, &w, 4);
  }
}

// Whether ResolveRunOf takes `cb`'s format: all but RGB8 and SRGB8 (whose alpha byte is not stored, and which the
// per-pixel path leaves as it is).
bool RunResolvable(const ColorBuffer& cb) {
  return !cb.rgb_only && cb.layout != TexelLayout::kNone;
}

// Resolves the run from `from`'s format (RunResolvable) into the same format.
void ResolveRunOf(const ColorBuffer& from, const ResolveRun& r) {
  auto half = [](const std::uint8_t* p) { return HalfToFloat(Bits16(p)); };
  auto to_half = [](float v, std::uint8_t* p) {
    const std::uint16_t h = FloatToHalf(v);
    std::memcpy(p, &h, 2);
  };
  auto f32 = [](const std::uint8_t* p) {
    float v;
    std::memcpy(&v, p, 4);
    return v;
  };
  auto to_f32 = [](float v, std::uint8_t* p) { std::memcpy(p, &v, 4); };
  auto u16 = [](const std::uint8_t* p) { return float(Bits16(p)) / 65535.0f; };
  auto to_u16 = [](float v, std::uint8_t* p) {
    const float c = v > 0.0f ? std::min(v, 1.0f) : 0.0f;  // NaN as 0
    const auto k = std::uint16_t(std::lrint(c * 65535.0f));
    std::memcpy(p, &k, 2);
  };
  switch (from.layout) {
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551:
    case TexelLayout::kUnorm1010102:
#if defined(SOFTGL_HAS_DISPATCH)
      if (CpuSimdLevel() != SimdLevel::kBaseline) return ResolvePackedAvx2(from.layout, r);
#endif
      ResolvePacked(from.layout, r);
      return;
    case TexelLayout::kUnorm8x4:
      if (!from.srgb) {
        ResolveBytes(4, r);
        return;
      }
      ResolveSrgb(r);
      return;
    case TexelLayout::kFloat11x11x10: ResolveSmallFloats(r); return;
    case TexelLayout::kUnorm8x2: ResolveBytes(2, r); return;
    case TexelLayout::kUnorm8x1: ResolveBytes(1, r); return;
    case TexelLayout::kFloat16x4:
#if defined(SOFTGL_HAS_DISPATCH)
      if (CpuSimdLevel() != SimdLevel::kBaseline) return ResolveHalves4F16c(r);
#endif
      ResolveChannels<4, 2>(r, half, to_half);
      return;
    case TexelLayout::kFloat16x2: ResolveChannels<2, 2>(r, half, to_half); return;
    case TexelLayout::kFloat16x1: ResolveChannels<1, 2>(r, half, to_half); return;
    case TexelLayout::kFloat32x4: ResolveChannels<4, 4>(r, f32, to_f32); return;
    case TexelLayout::kFloat32x2: ResolveChannels<2, 4>(r, f32, to_f32); return;
    case TexelLayout::kFloat32x1: ResolveChannels<1, 4>(r, f32, to_f32); return;
    case TexelLayout::kUnorm16x4: ResolveChannels<4, 2>(r, u16, to_u16); return;
    case TexelLayout::kUnorm16x2: ResolveChannels<2, 2>(r, u16, to_u16); return;
    case TexelLayout::kUnorm16x1: ResolveChannels<1, 2>(r, u16, to_u16); return;
    default: return;
  }
}

// n depth values from src's (sx, sy) on to dst's (dx, dy): copied as they are between buffers of one kind.
void CopyDepthRow(const RenderTarget& src, const RenderTarget& dst, int sx, int sy, int dx, int dy, int n) {
  if (src.step != 1 || dst.step != 1) {
    for (int i = 0; i < n; ++i) dst.SetDepth(dx + i, dy, dst.StoredDepth(src.DepthAt(sx + i, sy)));
  } else if (src.depth16 && dst.depth16) {  // (memmove: the two may be one buffer)
    std::memmove(dst.depth16 + dst.DepthIndex(dx, dy, 0), src.depth16 + src.DepthIndex(sx, sy, 0), 2 * std::size_t(n));
  } else if (src.depth && dst.depth) {
    std::memmove(dst.depth + dst.DepthIndex(dx, dy, 0), src.depth + src.DepthIndex(sx, sy, 0), 4 * std::size_t(n));
  } else {
    for (int i = 0; i < n; ++i) dst.SetDepth(dx + i, dy, dst.StoredDepth(src.DepthAt(sx + i, sy)));
  }
}

// Resolves rows [y0, y1) x columns [x0, x1) of a multisampled source into the same pixels of dst (an unmirrored
// blit of equal rectangles, offset by (dx, dy)): bytes of RGBA8 into RGBA8 averaged in integers (rounded half
// up), other formats into buffers of the same format by ResolveRunOf, depth and stencil copied from sample 0.
// False, doing nothing, for other pairs of colour formats (the caller's general path handles them, through
// LoadResolved).
bool ResolveRows(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r, int x0, int x1, int y0, int y1,
                 int dx, int dy) {
  const ColorBuffer& from = src.color[0];
  // RGBA8 into RGBA8 by the byte averages below; any other format into buffers of the same format and sRGB state
  // by ResolveRunOf (its rows run by run, without LoadResolved's per-texel dispatch).
  const bool bytes = from.Rgba8() && (from.step == 1 || src.interleaved);
  bool same = !bytes && RunResolvable(from);
  for (const ColorBuffer& cb : dst.color)
    same = same && (!cb.Present() || (cb.layout == from.layout && cb.srgb == from.srgb && !cb.rgb_only && cb.step == 1));
  if (r.color && !bytes && !same) return false;
  for (const ColorBuffer& cb : dst.color)
    if (r.color && bytes && cb.Present() && !cb.Rgba8()) return false;
  const int n = x1 - x0;
  const std::size_t plane_bytes = from.plane * 4;
  for (int y = y0; y < y1; ++y) {
    if (r.color && !bytes) {
      for (const ColorBuffer& cb : dst.color)
        if (cb.Present()) {
          const ResolveRun run{from.At(x0 - dx, y - dy), std::size_t(from.step), from.plane, cb.At(x0, y),
                               src.samples, n};
          ResolveRunOf(from, run);
        }
    } else if (r.color) {
      const std::uint8_t* in = from.At(x0 - dx, y - dy);
      for (const ColorBuffer& cb : dst.color) {
        if (!cb.Present()) continue;
        std::uint8_t* out = cb.At(x0, y);
        if (src.interleaved) {
          switch (src.samples) {
            case 2: AverageInterleaved<2>(in, out, n); break;
            case 4: AverageInterleaved<4>(in, out, n); break;
            default: AverageInterleaved<8>(in, out, n); break;
          }
          continue;
        }
        switch (src.samples) {
          case 2: AverageBytes<2>(in, plane_bytes, out, 4 * n); break;
          case 4: AverageBytes<4>(in, plane_bytes, out, 4 * n); break;
          default: AverageBytes<8>(in, plane_bytes, out, 4 * n); break;
        }
      }
    }
    if (r.depth) CopyDepthRow(src, dst, x0 - dx, y - dy, x0, y, n);
    if (r.stencil && src.step == 1 && dst.step == 1) {
      std::memcpy(&dst.Stencil(x0, y), &src.Stencil(x0 - dx, y - dy), std::size_t(n));
    } else if (r.stencil) {
      for (int i = 0; i < n; ++i) dst.Stencil(x0 + i, y) = src.Stencil(x0 - dx + i, y - dy);
    }
  }
  return true;
}

// Copies rows [y0, y1) x columns [x0, x1) of a single-sampled source into the same pixels of dst (offset by
// (dx, dy)) as they are stored, where that is what Load and Store would give: colour into buffers of the same
// format and sRGB state whose texels every value survives decoding and encoding (8-bit, packed and 16-bit fixed
// point, 32-bit floats; not the halves and small floats, whose Store makes NaNs canonical, nor RGB8 and SRGB8,
// whose alpha byte Store leaves), depth and stencil as the resolve copies them. False, doing nothing, otherwise.
bool CopyRows(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r, int x0, int x1, int y0, int y1,
              int dx, int dy) {
  const ColorBuffer& from = src.color[0];
  if (r.color) {
    const TexelLayout l = from.layout;
    const bool exact = IsUnorm8(l) || IsPackedUnorm(l) || IsUnorm16(l) || l == TexelLayout::kFloat32x4 ||
                       l == TexelLayout::kFloat32x2 || l == TexelLayout::kFloat32x1;
    if (!exact || from.rgb_only || from.step != 1) return false;
    for (const ColorBuffer& cb : dst.color)
      if (cb.Present() && (cb.layout != l || cb.srgb != from.srgb || cb.rgb_only || cb.step != 1)) return false;
  }
  if (r.stencil && (src.step != 1 || dst.step != 1)) return false;
  const int n = x1 - x0;
  for (int y = y0; y < y1; ++y) {
    if (r.color)
      for (const ColorBuffer& cb : dst.color)
        if (cb.Present()) std::memmove(cb.At(x0, y), from.At(x0 - dx, y - dy), std::size_t(n) * std::size_t(cb.Bytes()));
    if (r.depth) CopyDepthRow(src, dst, x0 - dx, y - dy, x0, y, n);
    if (r.stencil) std::memmove(&dst.Stencil(x0, y), &src.Stencil(x0 - dx, y - dy), std::size_t(n));
  }
  return true;
}

// The general blit works a destination row at a time on RGBA floats, four lanes a pixel (Load's values, in the
// same operations, so the same results as Load and Store pixel by pixel): the source rows it reads decoded once,
// each destination column's source columns and weight found once per blit.
using F4 = V<4>::F;
using I4 = V<4>::I;

SOFTGL_WIDE F4 ToF4(const glm::vec4& c) { return F4{c.r, c.g, c.b, c.a}; }

#if defined(SOFTGL_HAS_DISPATCH)
// n RGBA16F texels at `in` (`step` texels apart) as floats, by F16C (HalfToFloat's values).
SOFTGL_TARGET_AVX2 void HalvesToFloats(const std::uint8_t* in, int step, int n, float* out) {
  for (int i = 0; i < n; ++i)
    _mm_storeu_ps(out + 4 * i,
                  _mm_cvtph_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(in + std::size_t(i) * std::size_t(step) * 8))));
}
// n pixels of floats into RGBA16F texels `step` apart, by F16C: FloatToHalf's bits (to nearest even, a NaN made
// sign | 0x7E00), as ResolveHalves4F16c stores them.
SOFTGL_TARGET_AVX2 void FloatsToHalves(const float* in, int n, std::uint8_t* out, int step) {
  for (int i = 0; i < n; ++i) {
    const __m128 v = _mm_loadu_ps(in + 4 * i);
    __m128i h = _mm_cvtps_ph(v, _MM_FROUND_TO_NEAREST_INT);
    const __m128i nan = _mm_packs_epi32(_mm_castps_si128(_mm_cmpunord_ps(v, v)), _mm_setzero_si128());
    h = _mm_or_si128(_mm_andnot_si128(nan, h),
                     _mm_and_si128(nan, _mm_or_si128(_mm_and_si128(h, _mm_set1_epi16(short(0x8000))),
                                                     _mm_set1_epi16(0x7E00))));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + std::size_t(i) * std::size_t(step) * 8), h);
  }
}
#endif

}  // namespace

void LoadRow(const ColorBuffer& cb, int samples, int x, int n, int y, float* rgba) {
  if (samples > 1) {
    for (int i = 0; i < n; ++i) StoreVec(rgba + 4 * i, ToF4(LoadResolved(cb, samples, x + i, y)));
    return;
  }
  const std::uint8_t* in = cb.At(x, y);
  const std::size_t stride = std::size_t(cb.step) * std::size_t(cb.Bytes());
  switch (cb.layout) {
    case TexelLayout::kUnorm8x4:
      if (cb.srgb) break;
      for (int i = 0; i < n; ++i, in += stride)
        StoreVec(rgba + 4 * i, F4{float(in[0]), float(in[1]), float(in[2]), cb.rgb_only ? 255.0f : float(in[3])} / 255.0f);
      return;
    case TexelLayout::kFloat32x4:
      for (int i = 0; i < n; ++i, in += stride) std::memcpy(rgba + 4 * i, in, 16);
      return;
    case TexelLayout::kFloat16x4:
#if defined(SOFTGL_HAS_DISPATCH)
      if (CpuSimdLevel() != SimdLevel::kBaseline) return HalvesToFloats(in, cb.step, n, rgba);
#endif
      break;
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551:
    case TexelLayout::kUnorm1010102: {  // RawTexel's code / (2^bits - 1) a channel, 1 for a channel not stored
      const PackedUnorm k = PackingOf(cb.layout);
      const I4 shift = {k.shift[0], k.shift[1], k.shift[2], k.shift[3]};
      I4 max;
      for (int c = 0; c < 4; ++c) max[c] = int((1u << k.bits[c]) - 1u);
      const F4 fmax = __builtin_convertvector(max, F4);
      const bool wide = cb.Bytes() == 4;
      for (int i = 0; i < n; ++i, in += stride) {
        std::uint32_t w;
        if (wide) {
          std::memcpy(&w, in, 4);
        } else {
          std::uint16_t h;
          std::memcpy(&h, in, 2);
          w = h;
        }
        const I4 code = I4((V<4>::U{} + w) >> V<4>::U(shift)) & max;
        StoreVec(rgba + 4 * i, max != 0 ? __builtin_convertvector(code, F4) / fmax : F4{} + 1.0f);
      }
      return;
    }
    default: break;
  }
  for (int i = 0; i < n; ++i) StoreVec(rgba + 4 * i, ToF4(cb.Load(x + i, y)));
}

void StoreRow(const ColorBuffer& cb, int x, int n, int y, const float* rgba) {
  std::uint8_t* out = cb.At(x, y);
  const std::size_t stride = std::size_t(cb.step) * std::size_t(cb.Bytes());
  if (cb.layout == TexelLayout::kUnorm8x4 && !cb.srgb && !cb.rgb_only) {
    // FloatToUnorm8 a channel: NaN and <= 0 give 0, >= 1 gives 255, else f * 255 rounded to nearest even (by adding
    // and taking away 1.5 x 2^23, exact for values up to 255).
    constexpr float kRound = 12582912.0f;
    for (int i = 0; i < n; ++i, out += stride) {
      const F4 v = LoadVec<F4>(rgba + 4 * i);
      F4 c = v > 0.0f ? v : F4{};
      c = c < 1.0f ? c : F4{} + 1.0f;
      const I4 k = __builtin_convertvector((c * 255.0f + kRound) - kRound, I4);
      const std::uint32_t word = std::uint32_t(k[0]) | std::uint32_t(k[1]) << 8 | std::uint32_t(k[2]) << 16 |
                                 std::uint32_t(k[3]) << 24;
      std::memcpy(out, &word, 4);
    }
    return;
  }
  if (cb.layout == TexelLayout::kFloat32x4) {
    for (int i = 0; i < n; ++i, out += stride) std::memcpy(out, rgba + 4 * i, 16);
    return;
  }
#if defined(SOFTGL_HAS_DISPATCH)
  if (cb.layout == TexelLayout::kFloat16x4 && CpuSimdLevel() != SimdLevel::kBaseline)
    return FloatsToHalves(rgba, n, out, cb.step);
#endif
  const bool all[4] = {true, true, true, true};
  for (int i = 0; i < n; ++i) cb.Store(x + i, y, glm::vec4(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]), all);
}

namespace {

// Texels of B bytes: out[i] (`out_step` texels apart) = the texel of `in` at column from[i] (`in_step` apart).
template <int B>
void GatherTexels(const std::uint8_t* in, int in_step, const int* from, int n, std::uint8_t* out, int out_step) {
  for (int i = 0; i < n; ++i)
    std::memcpy(out + std::size_t(i) * std::size_t(out_step) * B, in + std::size_t(from[i]) * std::size_t(in_step) * B, B);
}

// Whether a NEAREST blit from `src` may copy texels as they are stored into every colour buffer of `dst`: the
// formats CopyRows copies, the same in both, single-sampled.
bool TexelsCopy(const RenderTarget& src, const RenderTarget& dst) {
  const ColorBuffer& from = src.color[0];
  const TexelLayout l = from.layout;
  const bool exact = IsUnorm8(l) || IsPackedUnorm(l) || IsUnorm16(l) || l == TexelLayout::kFloat32x4 ||
                     l == TexelLayout::kFloat32x2 || l == TexelLayout::kFloat32x1;
  if (src.samples > 1 || !exact || from.rgb_only) return false;
  for (const ColorBuffer& cb : dst.color)
    if (cb.Present() && (cb.layout != l || cb.srgb != from.srgb || cb.rgb_only)) return false;
  return true;
}

// The general blit (scaled, mirrored, LINEAR, between formats): destination rows [ay.d0, ay.d1) by columns
// [ax.d0, ax.d1). A destination pixel reads the source at its centre's mapped point: NEAREST the pixel holding it,
// LINEAR (colour) the bilinear mix of the four nearest pixel centres, clamped to the edge; pixels whose point lies
// outside the source are not written. (Those columns are the two ends of the range, the mapping being monotonic.)
void BlitScaled(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r, const BlitAxis& ax,
                const BlitAxis& ay) {
  const int n = ax.d1 - ax.d0;
  std::vector<int> px(static_cast<std::size_t>(n)), k0, k1;
  std::vector<float> wa;
  if (r.linear) {
    k0.resize(std::size_t(n));
    k1.resize(std::size_t(n));
    wa.resize(std::size_t(n));
  }
  int first = n, last = -1, lo = src.width, hi = -1;  // the columns written; the source columns read
  for (int i = 0; i < n; ++i) {
    const double sx = ax.At(ax.d0 + i);
    px[std::size_t(i)] = PixelAt(sx, src.width);
    if (px[std::size_t(i)] < 0) continue;
    first = std::min(first, i);
    last = i;
    if (r.linear) {  // between pixel centres, clamped to the edge
      const double u = sx - 0.5;
      const int i0 = int(std::floor(u));
      wa[std::size_t(i)] = float(u - i0);
      k0[std::size_t(i)] = std::max(i0, 0);
      k1[std::size_t(i)] = std::min(i0 + 1, src.width - 1);
      lo = std::min(lo, k0[std::size_t(i)]);
      hi = std::max(hi, k1[std::size_t(i)]);
    } else {
      lo = std::min(lo, px[std::size_t(i)]);
      hi = std::max(hi, px[std::size_t(i)]);
    }
  }
  if (first > last) return;
  const int count = last - first + 1, x0 = ax.d0 + first;
  const bool copy = r.color && !r.linear && TexelsCopy(src, dst);
  // Source rows decoded (two slots, each with the row it holds) and the destination row.
  std::vector<F4> rows, out;
  int held[2] = {-1, -1};
  if (r.color && !copy) {
    rows.resize(2 * std::size_t(hi - lo + 1));
    out.resize(std::size_t(count));
  }
  auto row = [&](int j, int keep) -> const F4* {
    for (int k = 0; k < 2; ++k)
      if (held[k] == j) return &rows[std::size_t(k) * std::size_t(hi - lo + 1)];
    const int k = held[0] == keep ? 1 : 0;
    held[k] = j;
    F4* into = &rows[std::size_t(k) * std::size_t(hi - lo + 1)];
    LoadRow(src.color[0], src.samples, lo, hi - lo + 1, j, reinterpret_cast<float*>(into));
    return into;
  };
  const bool ascending = !r.linear && px[std::size_t(last)] - px[std::size_t(first)] == last - first;
  for (int y = ay.d0; y < ay.d1; ++y) {
    const double sy = ay.At(y);
    const int py = PixelAt(sy, src.height);
    if (py < 0) continue;
    if (copy) {
      const ColorBuffer& from = src.color[0];
      const int bytes = from.Bytes();
      for (const ColorBuffer& cb : dst.color) {
        if (!cb.Present()) continue;
        std::uint8_t* to = cb.At(x0, y);
        const std::uint8_t* in = from.At(0, py);
        const int* cols = &px[std::size_t(first)];
        if (ascending && from.step == 1 && cb.step == 1) {  // the same columns in order: one run
          std::memmove(to, in + std::size_t(cols[0]) * std::size_t(bytes), std::size_t(count) * std::size_t(bytes));
          continue;
        }
        switch (bytes) {
          case 1: GatherTexels<1>(in, from.step, cols, count, to, cb.step); break;
          case 2: GatherTexels<2>(in, from.step, cols, count, to, cb.step); break;
          case 4: GatherTexels<4>(in, from.step, cols, count, to, cb.step); break;
          case 8: GatherTexels<8>(in, from.step, cols, count, to, cb.step); break;
          default: GatherTexels<16>(in, from.step, cols, count, to, cb.step); break;
        }
      }
    } else if (r.color && r.linear) {
      const double v = sy - 0.5;
      const int j0 = int(std::floor(v));
      const float b = float(v - j0);
      const int j1 = std::min(j0 + 1, src.height - 1), jc = std::max(j0, 0);
      const F4* r0 = row(jc, -1);
      const F4* r1 = row(j1, jc);  // (keeping jc's slot)
      for (int i = 0; i < count; ++i) {
        const std::size_t c = std::size_t(first + i);
        const float a = wa[c];
        const std::size_t c0 = std::size_t(k0[c] - lo), c1 = std::size_t(k1[c] - lo);
        out[std::size_t(i)] = (1.0f - b) * ((1.0f - a) * r0[c0] + a * r0[c1]) + b * ((1.0f - a) * r1[c0] + a * r1[c1]);
      }
    } else if (r.color) {
      const F4* in = row(py, -1);
      for (int i = 0; i < count; ++i) out[std::size_t(i)] = in[px[std::size_t(first + i)] - lo];
    }
    if (r.color && !copy)
      for (const ColorBuffer& cb : dst.color)
        if (cb.Present()) StoreRow(cb, x0, count, y, reinterpret_cast<const float*>(out.data()));
    for (int i = 0; i < count && (r.depth || r.stencil); ++i) {
      const int x = x0 + i, sx = px[std::size_t(first + i)];
      if (r.depth) dst.SetDepth(x, y, dst.StoredDepth(src.DepthAt(sx, py)));
      if (r.stencil) dst.Stencil(x, y) = src.Stencil(sx, py);
    }
  }
}

}  // namespace

void Blit(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r) {
  if (r.src[0] == r.src[2] || r.src[1] == r.src[3] || r.dst[0] == r.dst[2] || r.dst[1] == r.dst[3]) return;
  if (dst.samples > 1) {  // sample by sample from a source of as many, else the same value into each
    for (int s = 0; s < dst.samples; ++s) Blit(src.samples == dst.samples ? src.Sample(s) : src, dst.Sample(s), r);
    return;
  }
  // (Rectangle sizes and offsets in 64 bits: the corners may be any ints, INT_MIN to INT_MAX.)
  using I64 = std::int64_t;
  const I64 sw = I64(r.src[2]) - r.src[0], sh = I64(r.src[3]) - r.src[1];
  if ((src.samples > 1 || !r.linear) && sw == I64(r.dst[2]) - r.dst[0] && sh == I64(r.dst[3]) - r.dst[1] && sw > 0 &&
      sh > 0) {
    // A resolve, or a NEAREST copy, of the same rectangle unmirrored: rows at a time, clipped to both buffers (which
    // also bounds the offset of the two rectangles to the buffers' sizes wherever a pixel is left).
    const I64 dx = I64(r.dst[0]) - r.src[0], dy = I64(r.dst[1]) - r.src[1];
    const I64 x0 = std::max<I64>({r.dst[0], r.clip.x0, 0, dx}), x1 = std::min<I64>({r.dst[2], r.clip.x1, dst.width, src.width + dx});
    const I64 y0 = std::max<I64>({r.dst[1], r.clip.y0, 0, dy}), y1 = std::min<I64>({r.dst[3], r.clip.y1, dst.height, src.height + dy});
    if (x0 >= x1 || y0 >= y1) return;
    if (src.samples > 1 ? ResolveRows(src, dst, r, int(x0), int(x1), int(y0), int(y1), int(dx), int(dy))
                        : CopyRows(src, dst, r, int(x0), int(x1), int(y0), int(y1), int(dx), int(dy)))
      return;
  }
  const BlitAxis ax =
      MakeAxis(r.src[0], r.src[2], r.dst[0], r.dst[2], std::max(r.clip.x0, 0), std::min(r.clip.x1, dst.width));
  const BlitAxis ay =
      MakeAxis(r.src[1], r.src[3], r.dst[1], r.dst[3], std::max(r.clip.y0, 0), std::min(r.clip.y1, dst.height));
  if (ax.d0 >= ax.d1 || ay.d0 >= ay.d1) return;
  BlitScaled(src, dst, r, ax, ay);
}

int Framebuffer::RowPitch(int w) const {
  if (samples <= 1) return w;
  const int lines = (w * samples + 15) / 16;
  return 16 * (lines % 2 ? lines : lines + 1);
}

bool Framebuffer::Allocate(int w, int h) {
  width = height = 0;
  color.clear();
  depth.clear();
  stencil.clear();
  resolved = {};
  sample_tiles.Reset(0, 0);
  const std::size_t n = std::size_t(w) * std::size_t(h), ns = std::size_t(RowPitch(w)) * std::size_t(h);
  try {
    color.assign(ns * std::size_t(BytesPerTexel(layout)), 0);
    if (depth16) depth16_data.assign(ns, 65535);
    else depth.assign(ns, 1.0f);
    stencil.assign(ns, 0);
    if (samples > 1) {
      resolved.color.assign(n * std::size_t(BytesPerTexel(layout)), 0);
      if (depth16) resolved.depth16_data.assign(n, 65535);
      else resolved.depth.assign(n, 1.0f);
      resolved.stencil.assign(n, 0);
    }
  } catch (const std::bad_alloc&) {
    color = {};
    depth = {};
    depth16_data = {};
    stencil = {};
    resolved = {};
    return false;
  }
  width = w;
  height = h;
  if (samples > 1) {
    sample_tiles.Reset(w, h);
    RenderTarget& out = sample_tiles.resolved;
    out = Samples(false).Sample(0);
    out.step = out.color[0].step = 1;
    out.color[0].pitch = out.depth_pitch = out.stencil_pitch = w;
    out.color[0].data = resolved.color.data();
    if (depth16) out.depth16 = resolved.depth16_data.data();
    else out.depth = resolved.depth.data();
    out.stencil = resolved.stencil.data();
  }
  return true;
}

RenderTarget Framebuffer::Target(bool srgb_enabled) {
  const RenderTarget t = Samples(srgb_enabled);
  for (std::size_t i = 0; i < sample_tiles.tiles.size(); ++i) {
    sample_tiles.Store(t, int(i), kAllBuffers);
    sample_tiles.tiles[i].stale = kAllBuffers;
  }
  return t;
}

RenderTarget Framebuffer::FrameTarget(bool srgb_enabled) {
  RenderTarget t = Samples(srgb_enabled);
  if (samples > 1 && !sample_tiles.tiles.empty()) t.tiles = &sample_tiles;
  return t;
}

const RenderTarget& Framebuffer::KeptFrameTarget(bool srgb_enabled) {
  KeptTarget& k = kept_[srgb_enabled ? 1 : 0];
  const TargetKey now{{color.data(), depth16 ? static_cast<const void*>(depth16_data.data()) : depth.data(),
                       stencil.data(), sample_tiles.tiles.data()},
                      width, height, samples, layout, srgb, depth16};
  if (!(k.key == now)) {
    k.target = FrameTarget(srgb_enabled);
    k.key = now;
  }
  return k.target;
}

RenderTarget Framebuffer::Samples(bool srgb_enabled) {
  RenderTarget t;
  t.width = width;
  t.height = height;
  if (width > 0 && height > 0) {
    t.color[0].data = color.data();
    t.color[0].layout = layout;
    t.color[0].srgb = srgb && srgb_enabled;
    if (depth16) t.depth16 = depth16_data.data();
    else t.depth = depth.data();
    t.stencil = stencil.data();
    t.samples = samples;
    // Samples side by side: sample s of pixel (x, y) at y (width samples) + x samples + s.
    t.interleaved = samples > 1;
    t.color[0].pitch = t.depth_pitch = t.stencil_pitch = RowPitch(width);
    t.color[0].step = t.step = samples;
    t.color[0].plane = t.depth_plane = t.stencil_plane = 1;
  }
  return t;
}

RenderTarget Framebuffer::ReadTarget(bool srgb_enabled, unsigned buffers) {
  const RenderTarget t = Samples(srgb_enabled);
  if (samples <= 1 || width <= 0 || height <= 0) return t;
  for (std::size_t i = 0; i < sample_tiles.tiles.size(); ++i) sample_tiles.Resolve(t, int(i), buffers);
  RenderTarget out = sample_tiles.resolved;
  out.color[0].srgb = t.color[0].srgb;
  return out;
}


void SampleTiles::Reset(int width, int height) {
  cols = (std::max(width, 0) + kSize - 1) / kSize;
  rows = (std::max(height, 0) + kSize - 1) / kSize;
  tiles.assign(std::size_t(cols) * std::size_t(rows), Tile{});
  resolved = RenderTarget{};
}

Rect SampleTiles::TileRect(int t, int width, int height) const {
  const int tx = t % cols, ty = t / cols;
  return Rect{tx * kSize, ty * kSize, std::min((tx + 1) * kSize, width), std::min((ty + 1) * kSize, height)};
}

void SampleTiles::NoteColor(const RenderTarget& target, int t, const glm::vec4& value) {
  Tile& tile = tiles[std::size_t(t)];
  ColorBuffer texel = target.color[0];  // one texel, stored as the buffer stores it
  texel.data = tile.color;
  texel.pitch = 1;
  const bool all[4] = {true, true, true, true};
  texel.Store(0, 0, value, all);
  tile.cleared |= kColorBit;
}

void SampleTiles::NoteDepth(int t, float value) {
  tiles[std::size_t(t)].depth = value;
  tiles[std::size_t(t)].cleared |= kDepthBit;
}

void SampleTiles::NoteStencil(int t, std::uint8_t value) {
  tiles[std::size_t(t)].stencil = value;
  tiles[std::size_t(t)].cleared |= kStencilBit;
}

void SampleTiles::Store(const RenderTarget& target, int t, unsigned buffers) {
  Tile& tile = tiles[std::size_t(t)];
  const unsigned store = tile.cleared & buffers;
  if (!store) return;
  const Rect r = TileRect(t, target.width, target.height);
  if ((store & kColorBit) && target.color[0].Present()) FillTexels(target.color[0], target.samples, r, tile.color);
  if (store & kDepthBit) target.ClearDepth(r, tile.depth);
  if (store & kStencilBit) target.ClearStencil(r, tile.stencil, 0xFF);
  tile.cleared = std::uint8_t(tile.cleared & ~store);
}

void SampleTiles::Resolve(const RenderTarget& target, int t, unsigned buffers) {
  Tile& tile = tiles[std::size_t(t)];
  const unsigned todo = tile.stale & buffers;
  if (!todo) return;
  const Rect r = TileRect(t, target.width, target.height);
  const unsigned filled = todo & tile.cleared, read = todo & ~tile.cleared;
  if ((filled & kColorBit) && resolved.color[0].Present()) FillTexels(resolved.color[0], 1, r, tile.color);
  if (filled & kDepthBit) resolved.ClearDepth(r, tile.depth);
  if (filled & kStencilBit) resolved.ClearStencil(r, tile.stencil, 0xFF);
  if (read) {
    BlitRegion region;
    region.src[2] = region.dst[2] = target.width;
    region.src[3] = region.dst[3] = target.height;
    region.clip = r;
    region.color = (read & kColorBit) != 0;
    region.depth = (read & kDepthBit) != 0;
    region.stencil = (read & kStencilBit) != 0;
    RenderTarget raw = target, into = resolved;
    raw.tiles = nullptr;
    raw.color[0].srgb = into.color[0].srgb = false;  // the bytes averaged as stored
    Blit(raw, into, region);
  }
  tile.stale = std::uint8_t(tile.stale & ~todo);
}

}  // namespace softgl::detail

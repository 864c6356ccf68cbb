// texture.h — texture objects: levels and faces, texel formats, uploads, mipmap generation and completeness.
//
// Each level keeps its texels in its own format: RGBA8 four bytes a texel (RGB8 too, alpha stored as 255; SRGB8_ALPHA8
// and SRGB8 the same way, their colour bytes sRGB-encoded), RG8 two, R8 one, RGBA32F sixteen, R32F and the depth
// formats one float, but DEPTH_COMPONENT16 one 16-bit word (as R16); RG32F two floats; RGBA16F, RG16F and R16F half
// floats (IEEE binary16), four, two or one; R11F_G11F_B10F one 32-bit word of three unsigned small floats; RGB565,
// RGBA4 and RGB5_A1 one 16-bit word; RGBA16, RG16 and R16 a 16-bit word a channel.
// 8-bit fixed-point texels are bytes k meaning k / 255; the 16-bit words hold k / (2^bits - 1) a channel.
// Formats with stencil (DEPTH24_STENCIL8, DEPTH32F_STENCIL8, and STENCIL_INDEX8 for renderbuffers) keep their
// stencil indices in a plane of their own, one byte a texel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/enums.h>
#include <softgl/texture.h>

namespace softgl::detail {

inline constexpr int kMaxLevels = 15;  // 16384 x 16384 down to 1 x 1
inline constexpr float kMaxAnisotropy = 16.0f;  // MAX_TEXTURE_MAX_ANISOTROPY

/// How a level stores a texel.
enum class TexelLayout : std::uint8_t {
  kNone,
  kUnorm8x4,   // RGBA8, RGB8 (alpha 255)
  kUnorm8x2,   // RG8
  kUnorm8x1,   // R8
  kFloat32x4,  // RGBA32F
  kFloat32x2,  // RG32F
  kFloat32x1,  // R32F, DEPTH_COMPONENT, DEPTH_COMPONENT24, DEPTH_COMPONENT32F, the depth of DEPTH*_STENCIL8
  kFloat16x4,  // RGBA16F
  kFloat16x2,  // RG16F
  kFloat16x1,  // R16F
  kFloat11x11x10,  // R11F_G11F_B10F: red in bits 0-10, green 11-21, blue 22-31
  kUnorm565,   // RGB565: red in bits 11-15, green 5-10, blue 0-4 (OpenGL's UNSIGNED_SHORT_5_6_5 order)
  kUnorm4444,  // RGBA4: red 12-15, green 8-11, blue 4-7, alpha 0-3
  kUnorm5551,  // RGB5_A1: red 11-15, green 6-10, blue 1-5, alpha 0
  kUnorm1010102,  // RGB10_A2: red 0-9, green 10-19, blue 20-29, alpha 30-31 (UNSIGNED_INT_2_10_10_10_REV's order)
  kUnorm16x4,  // RGBA16: four 16-bit words k, each k / 65535
  kUnorm16x2,  // RG16
  kUnorm16x1,  // R16, DEPTH_COMPONENT16
  // Integer formats (R8UI ... RGBA32I): 8-, 16- or 32-bit integers a channel, unsigned or signed, four, two or one
  // channels (the RGB formats in four, alpha kept 1). IntegerLayoutOf describes them; RGB10_A2UI packs its own.
  kUint8x4, kUint8x2, kUint8x1, kSint8x4, kSint8x2, kSint8x1,
  kUint16x4, kUint16x2, kUint16x1, kSint16x4, kSint16x2, kSint16x1,
  kUint32x4, kUint32x2, kUint32x1, kSint32x4, kSint32x2, kSint32x1,
  kUint1010102,  // RGB10_A2UI: red in bits 0-9, green 10-19, blue 20-29, alpha 30-31, as integers
};

/// An integer layout's channels: how many are stored (0: not an integer layout), their bytes, whether signed.
/// (kUint1010102: four, packed in one word; `packed` set.)
struct IntegerLayout {
  int channels = 0, bytes = 0;
  bool is_signed = false, packed = false;
};
constexpr IntegerLayout IntegerLayoutOf(TexelLayout l) {
  if (l == TexelLayout::kUint1010102) return {4, 1, false, true};
  const int i = int(l) - int(TexelLayout::kUint8x4);
  if (i < 0 || i >= 18) return {};
  constexpr int kCounts[3] = {4, 2, 1};
  return {kCounts[i % 3], 1 << (i / 6), (i / 3) % 2 == 1, false};
}
constexpr bool IsIntegerLayout(TexelLayout l) { return IntegerLayoutOf(l).channels != 0; }
/// The integer layout of `channels` (1, 2 or 4) channels of `bytes` (1, 2 or 4) bytes.
constexpr TexelLayout IntegerLayoutFor(int channels, int bytes, bool is_signed) {
  const int size = bytes == 4 ? 2 : bytes == 2 ? 1 : 0, count = channels == 4 ? 0 : channels == 2 ? 1 : 2;
  return TexelLayout(int(TexelLayout::kUint8x4) + size * 6 + (is_signed ? 3 : 0) + count);
}

/// The layout of an internal format (kNone if softgl does not support it), and its bytes per texel.
TexelLayout LayoutOf(Enum internal_format);
constexpr int BytesPerTexel(TexelLayout l) {
  switch (l) {
    case TexelLayout::kUnorm8x4: return 4;
    case TexelLayout::kUnorm8x2: return 2;
    case TexelLayout::kUnorm8x1: return 1;
    case TexelLayout::kFloat32x4: return 16;
    case TexelLayout::kFloat32x2:
    case TexelLayout::kUnorm16x4:
    case TexelLayout::kFloat16x4: return 8;
    case TexelLayout::kFloat32x1:
    case TexelLayout::kFloat16x2:
    case TexelLayout::kUnorm16x2:
    case TexelLayout::kUnorm1010102:
    case TexelLayout::kFloat11x11x10: return 4;
    case TexelLayout::kUnorm16x1:
    case TexelLayout::kFloat16x1:
    case TexelLayout::kUnorm565:
    case TexelLayout::kUnorm4444:
    case TexelLayout::kUnorm5551: return 2;
    case TexelLayout::kUint1010102: return 4;
    default: {
      const IntegerLayout k = IntegerLayoutOf(l);
      return k.channels * k.bytes;
    }
  }
}
/// The texel at p as RGBA in storage units: byte values 0..255 for fixed-point layouts, the floats otherwise;
/// channels the layout lacks read (0, 0, 0, 1) in the same units.
glm::vec4 RawTexel(TexelLayout layout, const std::uint8_t* p);
/// The texel of an integer layout at p: its channels sign- or zero-extended to 32 bits (an unsigned channel's value
/// as the bits of a uint32), the channels the layout lacks (0, 0, 0, 1). RawTexel gives these 32 bits as floats'
/// bits, so that sampling, which only copies an integer texture's texels, hands them on unchanged.
glm::ivec4 IntegerTexel(TexelLayout layout, const std::uint8_t* p);
/// Stores integer values v (any, each clamped to the channel's range: OpenGL's conversion to an integer format)
/// into an integer texel at p; with `rgb_only` alpha is stored as 1.
void StoreIntegerTexel(TexelLayout layout, std::uint8_t* p, const std::int64_t v[4], bool rgb_only = false);
/// The value of channel bits `bits` (IntegerTexel's) of an integer layout, as a number: signed or unsigned.
inline std::int64_t IntegerValue(TexelLayout layout, std::int32_t bits) {
  return IntegerLayoutOf(layout).is_signed ? std::int64_t(bits) : std::int64_t(std::uint32_t(bits));
}
/// Writes the integer texel at `texel` as a client pixel of integer format `format` and `type` at out (PackInteger's
/// clamping to the type).
void PackIntegerTexel(TexelLayout layout, const std::uint8_t* texel, Enum format, Enum type, std::uint8_t* out);
constexpr bool IsUnorm8(TexelLayout l) {
  return l == TexelLayout::kUnorm8x4 || l == TexelLayout::kUnorm8x2 || l == TexelLayout::kUnorm8x1;
}
/// The fixed-point layouts with all channels in one 16- or 32-bit word (RGB565, RGBA4, RGB5_A1, RGB10_A2): read
/// as floats in [0, 1] (storage scale 1), stored clamped and rounded to each channel's bits.
constexpr bool IsPackedUnorm(TexelLayout l) {
  return l == TexelLayout::kUnorm565 || l == TexelLayout::kUnorm4444 || l == TexelLayout::kUnorm5551 ||
         l == TexelLayout::kUnorm1010102;
}
/// RGBA16, RG16, R16: 16 bits a channel, read as floats in [0, 1] (storage scale 1), stored clamped and rounded.
constexpr bool IsUnorm16(TexelLayout l) {
  return l == TexelLayout::kUnorm16x4 || l == TexelLayout::kUnorm16x2 || l == TexelLayout::kUnorm16x1;
}
/// The fixed-point layouts that are not 8-bit: their values clamp to [0, 1] as 8-bit ones do, but they are read
/// and blended as floats.
constexpr bool IsWideFixedPoint(TexelLayout l) { return IsPackedUnorm(l) || IsUnorm16(l); }
/// The channels of a packed fixed-point layout: bits and lowest bit of red, green, blue, alpha (0 bits: absent,
/// reads 1 for alpha).
struct PackedUnorm {
  int bits[4], shift[4];
};
constexpr PackedUnorm PackingOf(TexelLayout l) {
  switch (l) {
    case TexelLayout::kUnorm565: return {{5, 6, 5, 0}, {11, 5, 0, 0}};
    case TexelLayout::kUnorm4444: return {{4, 4, 4, 4}, {12, 8, 4, 0}};
    case TexelLayout::kUnorm1010102: return {{10, 10, 10, 2}, {0, 10, 20, 30}};
    default: return {{5, 5, 5, 1}, {11, 6, 1, 0}};  // kUnorm5551
  }
}
/// The bits of channel c (0 red ... 3 alpha) of a fixed-point layout (8-bit, packed, 16-bit), 0 where the layout
/// lacks it or is not fixed point.
constexpr int FixedPointBits(TexelLayout l, int c) {
  if (IsPackedUnorm(l)) return PackingOf(l).bits[c];
  switch (l) {
    case TexelLayout::kUnorm8x4: return 8;
    case TexelLayout::kUnorm8x2: return c < 2 ? 8 : 0;
    case TexelLayout::kUnorm8x1: return c < 1 ? 8 : 0;
    case TexelLayout::kUnorm16x4: return 16;
    case TexelLayout::kUnorm16x2: return c < 2 ? 16 : 0;
    case TexelLayout::kUnorm16x1: return c < 1 ? 16 : 0;
    default: return 0;
  }
}
/// OpenGL's small floats (4.6, section 2.3.4): IEEE binary16 (sign, 5 exponent bits, 10 mantissa bits) and the
/// unsigned 11- and 10-bit floats (5 exponent bits, 6 or 5 mantissa bits, no sign). From float: rounded to nearest
/// (ties to even), too large to infinity, NaN to NaN; the unsigned forms take negative values (and -0) as 0.
std::uint16_t FloatToHalf(float f);
float HalfToFloat(std::uint16_t h);
std::uint32_t FloatToUnsignedSmall(float f, int mantissa_bits);
float UnsignedSmallToFloat(std::uint32_t v, int mantissa_bits);

/// The integer internal formats (R8UI ... RGBA32I, RGB10_A2UI).
bool IsIntegerInternalFormat(Enum f);
/// SRGB8 and SRGB8_ALPHA8: colour channels stored sRGB-encoded (OpenGL 4.6, section 8.24).
inline bool IsSrgbFormat(Enum f) { return f == SRGB8 || f == SRGB8_ALPHA8; }
/// RGB8 and SRGB8: four bytes a texel, alpha not stored (kept 255, reads 1).
inline bool NoStoredAlpha(Enum f) { return f == RGB8 || f == SRGB8; }

/// sRGB's transfer functions as OpenGL applies them to 8-bit channels: an encoded byte k decodes to the linear
/// value of k / 255 (section 8.24's formula, to the nearest float); a linear value in [0, 1] (clamped, NaN as 0)
/// encodes to the byte nearest 255 times its sRGB value (section 17.3.7's formula), found exactly from the 255
/// linear values where the rounded byte steps up.
float SrgbDecode8(std::uint8_t k);
std::uint8_t SrgbEncode8(float linear);
/// The tables vector code converts sRGB by. decode[k] is SrgbDecode8(k). up[k] (k < 255) is the least float at or
/// above the k-th step between encoded values, so that SrgbEncode8(x), for x in (0, 1), counts the k with
/// up[k] <= x; up[255] is infinity. The buckets: every float whose bits >> 16 are kBucket0 + i (x in [2^-13, 1),
/// 128 buckets an octave). No bucket holds more than one step, and a step inside bucket i shares its top 16 bits,
/// so that one word tells the encoding of any x in it: bucket[i] & 0xFF is SrgbEncode8 of the bucket's least float,
/// and bucket[i] >> 8 the low 16 bits of the step's up[] inside the bucket (0x10000 where none is), 1 more where
/// x's low 16 bits reach it. (Bucket 0 holds no step, so that smaller x may take it too.)
struct SrgbLaneTables {
  static constexpr int kBucket0 = 0x3900, kBuckets = 0x3F80 - kBucket0;
  float decode[256];
  float up[256];
  std::int32_t bucket[kBuckets];
};
const SrgbLaneTables& SrgbLanes();
/// SrgbEncode8(x) by the bucket table t (SrgbLanes()): one lookup, no search.
inline std::uint8_t SrgbEncode8ByTable(const SrgbLaneTables& t, float x) {
  if (!(x > 0.0f)) return 0;  // also NaN
  if (x >= 1.0f) return 255;
  std::uint32_t bits;
  std::memcpy(&bits, &x, 4);
  const int i = std::clamp(int(bits >> 16) - SrgbLaneTables::kBucket0, 0, SrgbLaneTables::kBuckets - 1);
  const std::int32_t bucket = t.bucket[i];
  return std::uint8_t((bucket & 0xFF) + (std::int32_t(bits & 0xFFFFu) >= (bucket >> 8) ? 1 : 0));
}
/// How sampling decodes an sRGB texel's colour byte k (0..255, as a float) into storage units (255 times linear):
/// k / 12.92 up to byte 10 (the formula's linear segment); above it a polynomial of degree 6 in k, a Chebyshev fit
/// of section 8.24's formula over bytes 11..255, within 2.4e-3 of 255 times it (9.3e-6 in linear), evaluated by
/// Horner's rule in float without fused operations. The one-lane and the vector sampling paths evaluate it alike,
/// so they give the same floats; a dozen vector operations cost less than a gather from a table.
inline constexpr float kSrgbDecodePoly[7] = {0.23888184130191803f,   0.03252549096941948f,   0.0020256806164979935f,
                                             1.0746752195700537e-05f, -2.431343304465372e-08f, 4.7493366878148535e-11f,
                                             -4.3113197744932413e-14f};
inline constexpr float kSrgbToeScale = 1.0f / 12.92f;
inline float SrgbDecodeSample(float k) {
  float p = kSrgbDecodePoly[6];
  for (int i = 5; i >= 0; --i) p = p * k + kSrgbDecodePoly[i];
  return k <= 10.0f ? k * kSrgbToeScale : p;
}

struct TextureLevel {
  Enum format = 0;  // internal format; 0: not defined
  int width = 0, height = 0;
  TexelLayout layout = TexelLayout::kNone;
  int bytes = 0;                    // per texel
  // [height][width][bytes], rows from the bottom, then kGatherPad zero bytes: a 64-bit read at the last texel (the
  // vector sampling path reads a texel and its right-hand neighbour so) stays inside the level.
  std::vector<std::uint8_t> data;
  static constexpr std::size_t kGatherPad = 7;
  std::vector<std::uint8_t> stencil;  // [height][width] stencil indices for a format with stencil, else empty
  bool srgb = false;                  // IsSrgbFormat(format)
  // A multisampled image (a renderbuffer of RenderbufferStorageMultisample): `samples` planes of width x height
  // texels one after another (and as many stencil planes); 1 for every texture level.
  int samples = 1;
  // The layers of a TEXTURE_2D_ARRAY level or the slices of a TEXTURE_3D one, `depth` planes of width x height
  // texels one after another (1 otherwise). Texel (i, j) of plane k is At(i, k * height + j): plane by plane, the
  // rows continue upwards.
  int depth = 1;
  // A level defined by CompressedTexImage*: its compressed format and its blocks as given (texture_compression.h
  // orders them); `format` is then the format its texels were decoded into. 0 and empty for every other level.
  Enum compressed = 0;
  std::vector<std::uint8_t> blocks;
  bool Defined() const { return format != 0 && width > 0 && height > 0; }
  std::uint8_t* At(int i, int j) {
    return data.data() + (std::size_t(j) * std::size_t(width) + std::size_t(i)) * std::size_t(bytes);
  }
  const std::uint8_t* At(int i, int j) const {
    return data.data() + (std::size_t(j) * std::size_t(width) + std::size_t(i)) * std::size_t(bytes);
  }
  /// Texel (i, j) as RGBA in storage units: byte values 0..255 for fixed-point layouts, the floats otherwise;
  /// channels the format lacks read (0, 0, 0, 1) in the same units.
  glm::vec4 Raw(int i, int j) const;
  /// Texel (i, j) as sampling filters it: Raw, with an sRGB format's colour decoded to linear by SrgbDecodeSample
  /// (still in storage units, 255 times the linear value).
  glm::vec4 Sampled(int i, int j) const;
  /// Texel (i, j) as RGBA floats (fixed point divided by 255), as stored (sRGB colours not decoded).
  glm::vec4 Texel(int i, int j) const;
  /// Allocates width x height (x d planes) texels of `internal_format` (`samples` of each), zero (alpha 1 where
  /// the format has no alpha; stencil 0). Throws std::bad_alloc, also for more than kMaxLevelBytes.
  void Allocate(Enum internal_format, int w, int h, int samples = 1, int d = 1);
  /// The largest level softgl allocates: a 16384 x 16384 RGBA32F level. A 3D or array level beyond it (2048^3
  /// RGBA32F texels would be 128 GiB) records OUT_OF_MEMORY without trying.
  static constexpr std::uint64_t kMaxLevelBytes = std::uint64_t(1) << 32;
};

/// The number storage units are divided by to give the value: 255 for fixed-point layouts, 1 for float ones.
inline float StorageScale(TexelLayout l) { return IsUnorm8(l) ? 255.0f : 1.0f; }

struct SamplerParams {
  Enum min_filter = NEAREST_MIPMAP_LINEAR;
  Enum mag_filter = LINEAR;
  Enum wrap_s = REPEAT, wrap_t = REPEAT, wrap_r = REPEAT;
  glm::vec4 border{0.0f};
  // TEXTURE_BORDER_COLOR as SamplerParameterIiv / Iuiv gave it (border_integer: 1 signed, 2 unsigned; 0: as
  // floats): the numbers, for the queries (`border` holds them as floats, which sampling reads).
  int border_integer = 0;
  std::uint32_t border_bits[4] = {0, 0, 0, 0};
  int base_level = 0, max_level = 1000;
  float min_lod = -1000.0f, max_lod = 1000.0f, lod_bias = 0.0f;
  float max_anisotropy = 1.0f;  // TEXTURE_MAX_ANISOTROPY, >= 1 (sampling takes at most kMaxAnisotropy)
  Enum compare_mode = NONE, compare_func = LEQUAL;
  bool operator==(const SamplerParams&) const = default;
};

struct TextureObject {
  Enum target = 0;  // TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_2D_MULTISAMPLE (its
                    // one image is level 0, with `samples` planes), TEXTURE_2D_MULTISAMPLE_ARRAY (level 0 too,
                    // `depth` layers of `samples` planes each: plane layer * samples + sample), TEXTURE_1D or
                    // TEXTURE_1D_ARRAY (levels one texel high), TEXTURE_BUFFER (no levels: the texels are a
                    // buffer's store), fixed by the first bind
  TextureLevel levels[6][kMaxLevels];  // [face][level]; all but a cube map use face 0
  SamplerParams params;
  // A TEXTURE_BUFFER texture (OpenGL 4.6, section 8.9): TexBuffer's format (R8 until one is given), the buffer it
  // named (0: none), and that buffer's store, read in place by every draw (kept alive if the buffer is deleted, as
  // OpenGL keeps it). The context renders recorded draws before a store a buffer texture reads changes.
  Enum buffer_format = R8;
  std::uint32_t buffer_id = 0;
  std::shared_ptr<const std::vector<std::uint8_t>> buffer_store;
  int Faces() const { return target == TEXTURE_CUBE_MAP ? 6 : 1; }
  /// Levels with planes: the layers of a 2D array (as many at every level) or the slices of a 3D texture (halved
  /// with each level, as width and height are).
  bool Layered() const {
    return target == TEXTURE_2D_ARRAY || target == TEXTURE_3D || target == TEXTURE_1D_ARRAY ||
           target == TEXTURE_2D_MULTISAMPLE_ARRAY;
  }
};

/// The texture targets a unit binds, in this order: TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_2D_ARRAY, TEXTURE_3D,
/// TEXTURE_2D_MULTISAMPLE, TEXTURE_1D, TEXTURE_1D_ARRAY, TEXTURE_BUFFER, TEXTURE_2D_MULTISAMPLE_ARRAY. A 1D
/// texture's levels are one texel high; a 1D array's layers are the planes of its levels, as a 2D array's.
inline constexpr int kTextureKinds = 9;
inline constexpr Enum kTextureKindTarget[kTextureKinds] = {TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_2D_ARRAY,
                                                           TEXTURE_3D, TEXTURE_2D_MULTISAMPLE, TEXTURE_1D,
                                                           TEXTURE_1D_ARRAY, TEXTURE_BUFFER,
                                                           TEXTURE_2D_MULTISAMPLE_ARRAY};
/// The index of a texture target in kTextureKindTarget, -1 for another enum.
inline int TextureKind(Enum target) {
  for (int k = 0; k < kTextureKinds; ++k)
    if (kTextureKindTarget[k] == target) return k;
  return -1;
}
/// The unit array of Textures that holds each kind's views.
using UnitViews = const TextureView* (Textures::*)[kMaxTextureUnits];
inline constexpr UnitViews kKindUnits[kTextureKinds] = {&Textures::unit_2d, &Textures::unit_cube,
                                                        &Textures::unit_2d_array, &Textures::unit_3d,
                                                        &Textures::unit_2d_ms, &Textures::unit_1d,
                                                        &Textures::unit_1d_array, &Textures::unit_buffer,
                                                        &Textures::unit_2d_ms_array};
/// The multisample targets: one image of samples a texel (level 0), no levels, no sampling state.
inline bool IsMultisampleTarget(Enum target) {
  return target == TEXTURE_2D_MULTISAMPLE || target == TEXTURE_2D_MULTISAMPLE_ARRAY;
}
/// The targets with levels and sampling state: every kind but the multisample ones and TEXTURE_BUFFER.
inline bool HasLevelsAndSampling(Enum target) {
  return TextureKind(target) >= 0 && !IsMultisampleTarget(target) && target != TEXTURE_BUFFER;
}
/// The formats TexBuffer takes (OpenGL 3.3's table 3.15): R8, R16, R16F, R32F, RG8, RG16, RG16F, RG32F, RGBA8,
/// RGBA16, RGBA16F, RGBA32F and the integer R, RG and RGBA formats of 8, 16 and 32 bits.
bool IsBufferTextureFormat(Enum internal_format);

/// A texture as one draw samples it: completeness and the levels in use resolved once.
struct TextureView {
  const TextureObject* texture = nullptr;
  // The sampling state: the texture's own, or with a sampler object bound to the unit, the sampler's (all but
  // the base and maximum levels, which stay the texture's).
  SamplerParams params;
  bool complete = false;
  bool depth = false;  // a DEPTH_COMPONENT format
  int base = 0;        // level_base
  int q = 0;           // the last level mipmapped filtering may use
  TexelLayout layout = TexelLayout::kNone;
  bool srgb = false;   // an sRGB format: colours decoded before filtering
  // An integer format (R8UI ...): texels copied, never filtered or scaled (their 32 bits carried as floats' bits),
  // NEAREST or NEAREST_MIPMAP_NEAREST only; incomplete, it samples as the integers (0, 0, 0, 1).
  bool integer = false;
  float anisotropy = 1.0f;  // TEXTURE_MAX_ANISOTROPY cut to kMaxAnisotropy; above 1 2D, array and cube samples are anisotropic
  float scale = 1.0f;  // StorageScale(layout)
  glm::vec4 border_raw{0.0f};  // the border colour in storage units
  // The common case, which sampling takes without re-deciding per sample: a 2D colour texture with REPEAT in s
  // and t on power-of-two sizes, LINEAR magnification, and LINEAR or LINEAR_MIPMAP_LINEAR minification, no depth
  // comparison.
  enum class Fast : unsigned char { kNone, kRepeatLinear, kRepeatTrilinear };
  Fast fast = Fast::kNone;
  // Whether the vector path (SampleLanes, SampleLodLanes, SampleShadowLanes, and the cube map, 2D array and 3D
  // forms) samples the view: a 2D, cube map, 2D array or 3D texture, any layout (an integer one's texels copied as
  // bits), filters, wrap modes, size and anisotropy.
  bool wide = false;
  // A buffer texture: its store's texels (null: no buffer) and how many the draw may read.
  const std::uint8_t* buffer = nullptr;
  int buffer_texels = 0;
  bool operator==(const TextureView&) const = default;
};

/// Resolves a texture for sampling (OpenGL 4.6, section 8.17, texture completeness), with the sampling state of
/// `sampler` (a sampler object bound to the unit: OpenGL 4.6, section 8.2) in place of the texture's where given.
TextureView MakeView(const TextureObject& texture, const SamplerParams* sampler = nullptr);

/// Number of colour or depth channels of an internal format, 0 if softgl does not support it.
int FormatComponents(Enum internal_format);
/// DEPTH_COMPONENT, DEPTH_COMPONENT16/24/32F, DEPTH24_STENCIL8, DEPTH32F_STENCIL8.
bool IsDepthFormat(Enum internal_format);
/// DEPTH24_STENCIL8, DEPTH32F_STENCIL8, STENCIL_INDEX8.
bool HasStencil(Enum internal_format);
bool IsNormalizedFormat(Enum internal_format);  // fixed point: RGBA8, RGB8, RG8, R8, SRGB8_ALPHA8, SRGB8

/// Where client pixels lie in memory: OpenGL's PixelStore state for unpacking (UNPACK_*) or packing (PACK_*)
/// (OpenGL 3.3, sections 3.7.4 and 4.3.2). Rows of row_length pixels (0: the rectangle's width) aligned to
/// `alignment` bytes, images of image_height rows (0: the rectangle's height); the first pixel used is skip_pixels
/// in, skip_rows rows and skip_images images on; with swap_bytes each 2- or 4-byte element has its bytes reversed.
struct ClientLayout {
  int alignment = 4;
  int row_length = 0, image_height = 0;
  int skip_pixels = 0, skip_rows = 0, skip_images = 0;
  bool swap_bytes = false;
};

/// Converts client pixels of a valid (format, type) (pixel_transfer.h says which and how), laid out as `layout`
/// says, into the level's format, writing rect (x, y, w, h) of `level` (already allocated). Depth data leaves a level's stencil as
/// it is; depth-stencil data into a depth format drops the stencil. Null pixels leave the level as it is.
void UploadPixels(TextureLevel& level, int x, int y, int w, int h, Enum format, Enum type, const ClientLayout& layout,
                  const void* pixels);

/// UploadPixels for `d` images of w x h (image_height rows apart), written into planes z .. z + d - 1 of a layered
/// level at (x, y).
void UploadImages(TextureLevel& level, int x, int y, int z, int w, int h, int d, Enum format, Enum type,
                  const ClientLayout& layout, const void* pixels);

/// Writes RGBA value `v` into a texel of RG32F, RGBA16F, RG16F, R16F or R11F_G11F_B10F at p (the channels the
/// layout has, converted as FloatToHalf and FloatToUnsignedSmall say), or of RGB565, RGBA4, RGB5_A1 or RGB10_A2 (clamped to
/// [0, 1], NaN as 0, round(c * (2^bits - 1))); other layouts are left alone.
void StoreSmallFloatTexel(TexelLayout layout, std::uint8_t* p, const glm::vec4& v);

/// Writes RGBA value `v` (in [0, 1] for fixed point: clamped and rounded; floats as they are) into texel (i, j);
/// with `encode`, an sRGB level's colour is taken as linear and encoded (else stored as it is, as pixel transfers
/// store it).
void StoreTexel(TextureLevel& level, int i, int j, const glm::vec4& v, bool encode = false);

/// Fills levels base+1 .. the 1 x 1 level of each face from the base level: each texel is the bilinear sample of
/// the level above at its centre (the 2 x 2 box average for even sizes), in the base level's format; an sRGB
/// level's colours are averaged in linear light (decoded, then encoded again). A 2D array's layers are filtered
/// each on its own, all kept at every level; a 3D texture's texels are trilinear samples (the 2 x 2 x 2 average)
/// down to 1 x 1 x 1.
void GenerateMipmaps(TextureObject& texture);

}  // namespace softgl::detail

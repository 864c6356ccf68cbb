// softgl/lanes.h — the types and maths of wide shaders: one shader source that runs on 16 lanes at a time.
//
// A wide shader (see shader.h) is written once, in code that reads like GLSL, with these types in place of float
// and the GLM vectors; each value holds one number per lane, and every operation works on all 16 lanes:
//
//     Float d = max(dot(n, light_dir), 0.0f);          // 16 dot products, 16 maxima
//     vec3 c = mix(dark, base * d, step(0.5f, d));      // uniforms (glm types, floats) mix in freely
//     out.color[0] = vec4(select(d > 0.9f, vec3(1.0f), c), 1.0f);   // a per-lane branch
//
// Lanes: a fragment shader's 16 lanes are four 2x2 quads of pixels, lane = quad * 4 + (x % 2) + 2 * (y % 2) (so dFdx
// and dFdy read the neighbouring lanes of the quad); a vertex shader's are 16 vertices. softgl compiles each shader
// three times (for SSE2, AVX2 and AVX-512: 4, 8 and 8 lanes per instruction, the lanes held in 32-byte parts; see
// lanes_detail) and runs the version the processor allows, chosen at run time; the results are the same on all three
// (none contracts a * b + c into a fused multiply-add).
//
//   Float, Int, Bool    one float, 32-bit int or condition per lane
//   vec2, vec3, vec4    vectors of Float (members x, y, z, w); mat3, mat4: columns of vectors
//   arithmetic          + - * / between lanes, floats and glm values; comparisons give Bool; ! && || & | on Bool
//   select(c, a, b)     per lane: a where c holds, else b (GLSL's c ? a : b, which C++ cannot overload)
//   any(c), all(c)      whether c holds in some or in every lane (to skip work no lane needs)
//   maths               dot cross normalize length distance reflect refract mix clamp min max abs sign floor ceil
//                       fract mod step smoothstep sqrt inversesqrt pow exp exp2 log log2 sin cos
//
// Precision: + - * /, sqrt, inversesqrt (1 / sqrt), min, max, floor and what is built from them give the same bits
// as float and GLM do; pow, exp, exp2, log, log2, sin and cos are polynomials within a few units in the last place
// on their usual domains (tests/test_lanes.cpp measures them), as GLSL allows.
#pragma once

#include <softgl/config.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <glm/glm.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace softgl {

/// Lanes per wide value: four 2x2 quads of fragments, or 16 vertices.
inline constexpr int kLanes = 16;

/// The instruction set the wide code runs on, read once: 0 for SSE2 (or no vector instructions), 1 for AVX2 (with
/// SSE4.1 and F16C), 2 for AVX-512 (F, DQ, BW and VL) on top of that. SOFTGL_SIMD=sse2 or SOFTGL_SIMD=avx2 in the
/// environment caps it.
int SimdLevel();

}  // namespace softgl

// Function attributes that compile a function (and, through `flatten`, everything it calls inline) for one
// instruction set, without contracting a * b + c into a fused multiply-add (so that every version computes the
// same floats). softgl puts them on its own entry points; a shader never needs them.
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define SOFTGL_HAS_DISPATCH 1
#if defined(__clang__)
#define SOFTGL_NO_CONTRACT
#else
#define SOFTGL_NO_CONTRACT , optimize("fp-contract=off")
#endif
#define SOFTGL_TARGET_AVX512 __attribute__((target("avx512f,avx512dq,avx512bw,avx512vl,f16c"), flatten SOFTGL_NO_CONTRACT))
#define SOFTGL_TARGET_AVX2 __attribute__((target("avx2,f16c"), flatten SOFTGL_NO_CONTRACT))
#define SOFTGL_TARGET_BASE __attribute__((flatten SOFTGL_NO_CONTRACT))
#else
#define SOFTGL_TARGET_BASE
#endif

namespace softgl {

namespace lanes_detail {
// The lanes are held in parts of GCC's vector extension types (clang has them too): 32-byte parts of 8 lanes on
// x86, 16-byte parts of 4 lanes elsewhere. The compiler lowers each operation on a part to the vector instructions
// of the function it is compiled in: one ymm instruction per part with AVX2 or AVX-512, two xmm instructions with
// SSE2 (comparisons there go lane by lane: SSE2 alone has no 32-byte vectors). Parts of the processor's own width
// keep every operation, comparisons and broadcasts included, in registers; a 64-byte vector type would leave
// compilers to split it, which GCC does through memory and, for comparisons, one lane at a time. Aligned to 4
// bytes: loads and stores never assume more, and values pass through functions like any struct.
#if defined(__x86_64__) || defined(__i386__)
#define SOFTGL_PART_LANES 8
#else
#define SOFTGL_PART_LANES 4
#endif
inline constexpr int kPartLanes = SOFTGL_PART_LANES;
inline constexpr int kParts = kLanes / kPartLanes;
typedef float FP __attribute__((vector_size(kPartLanes * 4), aligned(4)));
typedef std::int32_t IP __attribute__((vector_size(kPartLanes * 4), aligned(4)));
typedef std::uint32_t UP __attribute__((vector_size(kPartLanes * 4), aligned(4)));
typedef float F4 __attribute__((vector_size(16), aligned(4)));

// 16 floats and 16 ints as parts, with the operations of the vector types applied part by part.
struct F32 {
  FP p[kParts];
  float operator[](int i) const { return p[i / kPartLanes][i % kPartLanes]; }
  void Set(int i, float x) { p[i / kPartLanes][i % kPartLanes] = x; }
};
struct I32 {
  IP p[kParts];
  std::int32_t operator[](int i) const { return p[i / kPartLanes][i % kPartLanes]; }
  void Set(int i, std::int32_t x) { p[i / kPartLanes][i % kPartLanes] = x; }
};
#define SOFTGL_PARTS(T, expr) \
  T r;                        \
  for (int k = 0; k < kParts; ++k) r.p[k] = expr; \
  return r
inline F32 operator+(const F32& a, const F32& b) { SOFTGL_PARTS(F32, a.p[k] + b.p[k]); }
inline F32 operator-(const F32& a, const F32& b) { SOFTGL_PARTS(F32, a.p[k] - b.p[k]); }
inline F32 operator*(const F32& a, const F32& b) { SOFTGL_PARTS(F32, a.p[k] * b.p[k]); }
inline F32 operator/(const F32& a, const F32& b) { SOFTGL_PARTS(F32, a.p[k] / b.p[k]); }
inline F32 operator-(const F32& a) { SOFTGL_PARTS(F32, -a.p[k]); }
inline I32 operator==(const F32& a, const F32& b) { SOFTGL_PARTS(I32, a.p[k] == b.p[k]); }
inline I32 operator!=(const F32& a, const F32& b) { SOFTGL_PARTS(I32, a.p[k] != b.p[k]); }
inline I32 operator<(const F32& a, const F32& b) { SOFTGL_PARTS(I32, a.p[k] < b.p[k]); }
inline I32 operator<=(const F32& a, const F32& b) { SOFTGL_PARTS(I32, a.p[k] <= b.p[k]); }
// Integer + - * wrap around (computed unsigned, where overflow is defined).
inline I32 operator+(const I32& a, const I32& b) { SOFTGL_PARTS(I32, IP(UP(a.p[k]) + UP(b.p[k]))); }
inline I32 operator-(const I32& a, const I32& b) { SOFTGL_PARTS(I32, IP(UP(a.p[k]) - UP(b.p[k]))); }
inline I32 operator*(const I32& a, const I32& b) { SOFTGL_PARTS(I32, IP(UP(a.p[k]) * UP(b.p[k]))); }
inline I32 operator&(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] & b.p[k]); }
inline I32 operator|(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] | b.p[k]); }
inline I32 operator^(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] ^ b.p[k]); }
inline I32 operator~(const I32& a) { SOFTGL_PARTS(I32, ~a.p[k]); }
inline I32 ShiftLeft(const I32& a, int n) { SOFTGL_PARTS(I32, IP(UP(a.p[k]) << n)); }
inline I32 ShiftRight(const I32& a, int n) { SOFTGL_PARTS(I32, a.p[k] >> n); }  // arithmetic
inline I32 operator==(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] == b.p[k]); }
inline I32 operator!=(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] != b.p[k]); }
inline I32 operator<(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] < b.p[k]); }
inline I32 operator<=(const I32& a, const I32& b) { SOFTGL_PARTS(I32, a.p[k] <= b.p[k]); }
// Per lane: a where the mask m (all bits set or none) is set, else b.
inline F32 Select(const I32& m, const F32& a, const F32& b) { SOFTGL_PARTS(F32, m.p[k] ? a.p[k] : b.p[k]); }
inline I32 Select(const I32& m, const I32& a, const I32& b) { SOFTGL_PARTS(I32, m.p[k] ? a.p[k] : b.p[k]); }
// Conversions (truncating float to int) and bit casts.
inline I32 ToInt(const F32& a) { SOFTGL_PARTS(I32, __builtin_convertvector(a.p[k], IP)); }
inline F32 ToFloat(const I32& a) { SOFTGL_PARTS(F32, __builtin_convertvector(a.p[k], FP)); }
inline I32 BitsOf(const F32& a) { SOFTGL_PARTS(I32, IP(a.p[k])); }
inline F32 FloatOf(const I32& a) { SOFTGL_PARTS(F32, FP(a.p[k])); }
// One value in every lane: a broadcast instruction per part. (Written as a shuffle of a 16-byte vector, which
// every x86 compiles natively; GCC builds a literal of the wider part type one lane at a time when the function it
// comes from was compiled for SSE2, before it is inlined into an AVX2 or AVX-512 one.)
typedef std::int32_t I4 __attribute__((vector_size(16), aligned(4)));
inline I32 Splat(std::int32_t x) {
  const I4 v = {x, 0, 0, 0};
  I32 r;
#if SOFTGL_PART_LANES == 8
  for (int k = 0; k < kParts; ++k) r.p[k] = __builtin_shufflevector(v, v, 0, 0, 0, 0, 0, 0, 0, 0);
#else
  for (int k = 0; k < kParts; ++k) r.p[k] = __builtin_shufflevector(v, v, 0, 0, 0, 0);
#endif
  return r;
}
inline F32 Splat(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return FloatOf(Splat(bits));
}
#undef SOFTGL_PARTS
// Loads and stores part by part, each one vector move of a part through a type that may alias anything and sits at
// any address. (A memcpy of a part, or of all 64 bytes, may be expanded as 16-byte pieces through the stack, or as
// one 64-byte move that reads what two 32-byte stores wrote: either stalls the processor.)
struct __attribute__((packed, may_alias)) UnalignedF {
  FP v;
};
struct __attribute__((packed, may_alias)) UnalignedI {
  IP v;
};
template <class V, class T>
inline V Load(const T* src) {
  using U = std::conditional_t<std::is_same_v<V, F32>, UnalignedF, UnalignedI>;
  V r;
  for (int k = 0; k < kParts; ++k) r.p[k] = reinterpret_cast<const U*>(src + k * kPartLanes)->v;
  return r;
}
template <class V, class T>
inline void Store(const V& v, T* dst) {
  using U = std::conditional_t<std::is_same_v<V, F32>, UnalignedF, UnalignedI>;
  for (int k = 0; k < kParts; ++k) reinterpret_cast<U*>(dst + k * kPartLanes)->v = v.p[k];
}
}  // namespace lanes_detail

struct Float;

/// A condition per lane (all bits set where it holds).
struct Bool {
  lanes_detail::I32 m;

  Bool() = default;
  Bool(bool b) : m(lanes_detail::Splat(std::int32_t(b ? -1 : 0))) {}
  explicit Bool(const lanes_detail::I32& mask) : m(mask) {}
  /// Lane i holds where bit i of `bits` is set.
  static Bool FromBits(std::uint32_t bits) {
    lanes_detail::I32 lane;
    for (int i = 0; i < kLanes; ++i) lane.Set(i, std::int32_t(1u << i));
    return Bool((lanes_detail::Splat(std::int32_t(bits)) & lane) != lanes_detail::Splat(0));
  }
  /// Bit i set where lane i holds.
  std::uint32_t Bits() const {
    std::uint32_t bits = 0;
#if defined(__SSE2__) && SOFTGL_PART_LANES == 8
    // The sign bits of each 4-lane half of each part (movmskps).
    using lanes_detail::F4;
    using lanes_detail::FP;
    for (int k = 0; k < lanes_detail::kParts; ++k) {
      const FP f = FP(m.p[k]);
      const F4 lo = __builtin_shufflevector(f, f, 0, 1, 2, 3), hi = __builtin_shufflevector(f, f, 4, 5, 6, 7);
      bits |= std::uint32_t(_mm_movemask_ps(__m128(lo)) | _mm_movemask_ps(__m128(hi)) << 4) << (8 * k);
    }
#else
    for (int i = 0; i < kLanes; ++i) bits |= std::uint32_t(m[i] != 0) << i;
#endif
    return bits;
  }
  bool operator[](int i) const { return m[i] != 0; }

  friend Bool operator!(Bool a) { return Bool(~a.m); }
  friend Bool operator&&(Bool a, Bool b) { return Bool(a.m & b.m); }
  friend Bool operator||(Bool a, Bool b) { return Bool(a.m | b.m); }
  friend Bool operator&(Bool a, Bool b) { return Bool(a.m & b.m); }
  friend Bool operator|(Bool a, Bool b) { return Bool(a.m | b.m); }
  friend Bool operator^(Bool a, Bool b) { return Bool(a.m ^ b.m); }
  Bool& operator&=(Bool b) { return *this = *this & b; }
  Bool& operator|=(Bool b) { return *this = *this | b; }
};

/// Whether c holds in at least one lane; in every lane.
inline bool any(Bool c) { return c.Bits() != 0; }
inline bool all(Bool c) { return c.Bits() == 0xFFFFu; }

/// A 32-bit integer per lane (GLSL int; arithmetic wraps around).
struct Int {
  lanes_detail::I32 v;

  Int() = default;
  Int(int x) : v(lanes_detail::Splat(std::int32_t(x))) {}
  explicit Int(const lanes_detail::I32& x) : v(x) {}
  /// GLSL int(f): truncation towards zero. (Out of range and NaN give some value, never a trap.)
  explicit Int(const Float& f);
  static Int Load(const std::int32_t* p) {
    return Int(lanes_detail::Load<lanes_detail::I32>(p));
  }
  void Store(std::int32_t* p) const { lanes_detail::Store(v, p); }
  int operator[](int i) const { return v[i]; }

  friend Int operator+(Int a, Int b) { return Int(a.v + b.v); }
  friend Int operator-(Int a, Int b) { return Int(a.v - b.v); }
  friend Int operator*(Int a, Int b) { return Int(a.v * b.v); }
  friend Int operator-(Int a) { return Int(0) - a; }
  /// Division truncating toward zero and its remainder (sign of a), as GLSL's int / and %. Where GLSL leaves the
  /// result undefined the lane gets a defined one: 0 for division by zero, a itself for INT_MIN / -1 (and 0 for its
  /// remainder). Processors have no vector integer division, so these run lane by lane.
  friend Int operator/(Int a, Int b) {
    Int r;
    for (int i = 0; i < kLanes; ++i)
      r.v.Set(i, b.v[i] == 0 ? 0 : b.v[i] == -1 ? std::int32_t(0u - std::uint32_t(a.v[i])) : a.v[i] / b.v[i]);
    return r;
  }
  friend Int operator%(Int a, Int b) {
    Int r;
    for (int i = 0; i < kLanes; ++i) r.v.Set(i, b.v[i] == 0 || b.v[i] == -1 ? 0 : a.v[i] % b.v[i]);
    return r;
  }
  friend Int operator&(Int a, Int b) { return Int(a.v & b.v); }
  friend Int operator|(Int a, Int b) { return Int(a.v | b.v); }
  friend Int operator^(Int a, Int b) { return Int(a.v ^ b.v); }
  friend Int operator~(Int a) { return Int(~a.v); }
  friend Int operator<<(Int a, int n) { return Int(lanes_detail::ShiftLeft(a.v, n & 31)); }
  friend Int operator>>(Int a, int n) { return Int(lanes_detail::ShiftRight(a.v, n & 31)); }
  friend Bool operator==(Int a, Int b) { return Bool(a.v == b.v); }
  friend Bool operator!=(Int a, Int b) { return Bool(a.v != b.v); }
  friend Bool operator<(Int a, Int b) { return Bool(a.v < b.v); }
  friend Bool operator<=(Int a, Int b) { return Bool(a.v <= b.v); }
  friend Bool operator>(Int a, Int b) { return Bool(b.v < a.v); }
  friend Bool operator>=(Int a, Int b) { return Bool(b.v <= a.v); }
  Int& operator+=(Int b) { return *this = *this + b; }
  Int& operator-=(Int b) { return *this = *this - b; }
  Int& operator*=(Int b) { return *this = *this * b; }
  Int& operator/=(Int b) { return *this = *this / b; }
  Int& operator%=(Int b) { return *this = *this % b; }
};

/// A float per lane.
struct Float {
  lanes_detail::F32 v;

  Float() = default;
  Float(float x) : v(lanes_detail::Splat(x)) {}
  Float(double x) : Float(float(x)) {}
  Float(int x) : Float(float(x)) {}
  explicit Float(const lanes_detail::F32& x) : v(x) {}
  /// GLSL float(i).
  explicit Float(Int i) : v(lanes_detail::ToFloat(i.v)) {}
  static Float Load(const float* p) {
    return Float(lanes_detail::Load<lanes_detail::F32>(p));
  }
  void Store(float* p) const { lanes_detail::Store(v, p); }
  float operator[](int i) const { return v[i]; }
  /// The lanes' bits as integers (floatBitsToInt), and back (intBitsToFloat).
  Int Bits() const { return Int(lanes_detail::BitsOf(v)); }
  static Float FromBits(Int bits) { return Float(lanes_detail::FloatOf(bits.v)); }

  friend Float operator+(Float a, Float b) { return Float(a.v + b.v); }
  friend Float operator-(Float a, Float b) { return Float(a.v - b.v); }
  friend Float operator*(Float a, Float b) { return Float(a.v * b.v); }
  friend Float operator/(Float a, Float b) { return Float(a.v / b.v); }
  friend Float operator-(Float a) { return Float(-a.v); }
  friend Float operator+(Float a) { return a; }
  friend Bool operator==(Float a, Float b) { return Bool(a.v == b.v); }
  friend Bool operator!=(Float a, Float b) { return Bool(a.v != b.v); }
  friend Bool operator<(Float a, Float b) { return Bool(a.v < b.v); }
  friend Bool operator<=(Float a, Float b) { return Bool(a.v <= b.v); }
  friend Bool operator>(Float a, Float b) { return Bool(b.v < a.v); }
  friend Bool operator>=(Float a, Float b) { return Bool(b.v <= a.v); }
  Float& operator+=(Float b) { return *this = *this + b; }
  Float& operator-=(Float b) { return *this = *this - b; }
  Float& operator*=(Float b) { return *this = *this * b; }
  Float& operator/=(Float b) { return *this = *this / b; }
};

inline Int::Int(const Float& f) : v(lanes_detail::ToInt(f.v)) {}

/// Per lane: a where c holds, else b.
inline Float select(Bool c, Float a, Float b) { return Float(lanes_detail::Select(c.m, a.v, b.v)); }
inline Int select(Bool c, Int a, Int b) { return Int(lanes_detail::Select(c.m, a.v, b.v)); }
inline Bool select(Bool c, Bool a, Bool b) { return Bool(lanes_detail::Select(c.m, a.m, b.m)); }

// ---- Vectors of lanes ---------------------------------------------------------------------------------------------

struct vec2;
struct vec3;
struct vec4;

struct vec2 {
  using Glm = glm::vec2;
  Float x, y;
  vec2() = default;
  vec2(Float s) : x(s), y(s) {}
  vec2(float s) : x(s), y(s) {}
  vec2(Float x_, Float y_) : x(x_), y(y_) {}
  vec2(const glm::vec2& g) : x(g.x), y(g.y) {}
  explicit vec2(const vec3& v);
  explicit vec2(const vec4& v);
  static constexpr int size() { return 2; }
  Float& operator[](int i) { return i == 0 ? x : y; }
  const Float& operator[](int i) const { return i == 0 ? x : y; }
  /// Lane i as a glm value.
  glm::vec2 Lane(int i) const { return glm::vec2(x[i], y[i]); }
};

struct vec3 {
  using Glm = glm::vec3;
  Float x, y, z;
  vec3() = default;
  vec3(Float s) : x(s), y(s), z(s) {}
  vec3(float s) : x(s), y(s), z(s) {}
  vec3(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
  vec3(const vec2& xy_, Float z_) : x(xy_.x), y(xy_.y), z(z_) {}
  vec3(const glm::vec3& g) : x(g.x), y(g.y), z(g.z) {}
  explicit vec3(const vec4& v);
  static constexpr int size() { return 3; }
  Float& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
  const Float& operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
  vec2 xy() const { return vec2(x, y); }
  glm::vec3 Lane(int i) const { return glm::vec3(x[i], y[i], z[i]); }
};

struct vec4 {
  using Glm = glm::vec4;
  Float x, y, z, w;
  vec4() = default;
  vec4(Float s) : x(s), y(s), z(s), w(s) {}
  vec4(float s) : x(s), y(s), z(s), w(s) {}
  vec4(Float x_, Float y_, Float z_, Float w_) : x(x_), y(y_), z(z_), w(w_) {}
  vec4(const vec3& xyz_, Float w_) : x(xyz_.x), y(xyz_.y), z(xyz_.z), w(w_) {}
  vec4(const vec2& xy_, Float z_, Float w_) : x(xy_.x), y(xy_.y), z(z_), w(w_) {}
  vec4(const vec2& xy_, const vec2& zw_) : x(xy_.x), y(xy_.y), z(zw_.x), w(zw_.y) {}
  vec4(const glm::vec4& g) : x(g.x), y(g.y), z(g.z), w(g.w) {}
  static constexpr int size() { return 4; }
  Float& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  const Float& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  vec2 xy() const { return vec2(x, y); }
  vec3 xyz() const { return vec3(x, y, z); }
  vec3 rgb() const { return vec3(x, y, z); }
  glm::vec4 Lane(int i) const { return glm::vec4(x[i], y[i], z[i], w[i]); }
};

/// Four Ints a lane: GLSL's ivec4, and its uvec4 as the same 32 bits (an unsigned value v is the Int of the same
/// bits: compare such values with care above 2^31). Integer textures read as it (FragmentLanes::ITexture ...), and
/// integer colour outputs take it (FragmentLanesOut::SetColorI).
struct ivec4 {
  using Glm = glm::ivec4;
  Int x, y, z, w;
  ivec4() = default;
  ivec4(Int s) : x(s), y(s), z(s), w(s) {}
  ivec4(int s) : x(s), y(s), z(s), w(s) {}
  ivec4(Int x_, Int y_, Int z_, Int w_) : x(x_), y(y_), z(z_), w(w_) {}
  ivec4(const glm::ivec4& g) : x(g.x), y(g.y), z(g.z), w(g.w) {}
  static constexpr int size() { return 4; }
  Int& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  const Int& operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
  /// floatBitsToInt of each component, and intBitsToFloat back: how integers travel in a vec4's floats.
  static ivec4 FromBits(const vec4& v) { return ivec4(v.x.Bits(), v.y.Bits(), v.z.Bits(), v.w.Bits()); }
  vec4 Bits() const { return vec4(Float::FromBits(x), Float::FromBits(y), Float::FromBits(z), Float::FromBits(w)); }
  glm::ivec4 Lane(int i) const { return glm::ivec4(x[i], y[i], z[i], w[i]); }
};

inline vec2::vec2(const vec3& v) : x(v.x), y(v.y) {}
inline vec2::vec2(const vec4& v) : x(v.x), y(v.y) {}
inline vec3::vec3(const vec4& v) : x(v.x), y(v.y), z(v.z) {}

/// vec2, vec3 or vec4.
template <class V>
concept WideVector = std::is_same_v<V, vec2> || std::is_same_v<V, vec3> || std::is_same_v<V, vec4>;

namespace lanes_detail {
template <class G>
struct WideOf {};
template <>
struct WideOf<glm::vec2> {
  using type = vec2;
};
template <>
struct WideOf<glm::vec3> {
  using type = vec3;
};
template <>
struct WideOf<glm::vec4> {
  using type = vec4;
};
template <class G>
concept GlmVector = requires { typename WideOf<G>::type; };
template <class G>
using Wide = typename WideOf<G>::type;

// f applied to each component (of one vector, or of two or three side by side).
template <class V, class F>
inline V Map(const V& a, F f) {
  V r;
  for (int i = 0; i < V::size(); ++i) r[i] = f(a[i]);
  return r;
}
template <class V, class F>
inline V Map(const V& a, const V& b, F f) {
  V r;
  for (int i = 0; i < V::size(); ++i) r[i] = f(a[i], b[i]);
  return r;
}
template <class V, class F>
inline V Map(const V& a, const V& b, const V& c, F f) {
  V r;
  for (int i = 0; i < V::size(); ++i) r[i] = f(a[i], b[i], c[i]);
  return r;
}
}  // namespace lanes_detail

// Componentwise arithmetic between two vectors, a vector and a scalar (Float or float), or a vector and a glm
// value (a uniform); compound assignment too.
#define SOFTGL_LANES_VECTOR_OP(op)                                                                              \
  template <WideVector V>                                                                                       \
  inline V operator op(const V& a, const V& b) {                                                                \
    return lanes_detail::Map(a, b, [](Float p, Float q) { return p op q; });                                     \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(const V& a, Float s) {                                                                   \
    return lanes_detail::Map(a, [s](Float p) { return p op s; });                                               \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(Float s, const V& b) {                                                                   \
    return lanes_detail::Map(b, [s](Float q) { return s op q; });                                               \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(const V& a, float s) {                                                                   \
    return a op Float(s);                                                                                       \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(float s, const V& b) {                                                                   \
    return Float(s) op b;                                                                                       \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(const V& a, const typename V::Glm& g) {                                                  \
    return a op V(g);                                                                                           \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V operator op(const typename V::Glm& g, const V& b) {                                                  \
    return V(g) op b;                                                                                           \
  }                                                                                                             \
  template <lanes_detail::GlmVector G>                                                                          \
  inline lanes_detail::Wide<G> operator op(const G& g, Float s) {                                               \
    return lanes_detail::Wide<G>(g) op s;                                                                       \
  }                                                                                                             \
  template <lanes_detail::GlmVector G>                                                                          \
  inline lanes_detail::Wide<G> operator op(Float s, const G& g) {                                               \
    return s op lanes_detail::Wide<G>(g);                                                                       \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V& operator op##=(V& a, const V& b) {                                                                  \
    return a = a op b;                                                                                          \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V& operator op##=(V& a, Float s) {                                                                     \
    return a = a op s;                                                                                          \
  }                                                                                                             \
  template <WideVector V>                                                                                       \
  inline V& operator op##=(V& a, const typename V::Glm& g) {                                                    \
    return a = a op V(g);                                                                                       \
  }
SOFTGL_LANES_VECTOR_OP(+)
SOFTGL_LANES_VECTOR_OP(-)
SOFTGL_LANES_VECTOR_OP(*)
SOFTGL_LANES_VECTOR_OP(/)
#undef SOFTGL_LANES_VECTOR_OP

template <WideVector V>
inline V operator-(const V& a) {
  return lanes_detail::Map(a, [](Float p) { return -p; });
}

/// Per lane: a where c holds, else b.
template <WideVector V>
inline V select(Bool c, const V& a, const V& b) {
  return lanes_detail::Map(a, b, [c](Float p, Float q) { return select(c, p, q); });
}

// ---- Matrices of lanes (column-major, as GLSL and GLM) --------------------------------------------------------------

struct mat3 {
  vec3 c[3];
  mat3() = default;
  explicit mat3(Float diagonal) : c{vec3(diagonal, 0.0f, 0.0f), vec3(0.0f, diagonal, 0.0f), vec3(0.0f, 0.0f, diagonal)} {}
  mat3(const vec3& c0, const vec3& c1, const vec3& c2) : c{c0, c1, c2} {}
  mat3(const glm::mat3& m) : c{vec3(m[0]), vec3(m[1]), vec3(m[2])} {}
  vec3& operator[](int i) { return c[i]; }
  const vec3& operator[](int i) const { return c[i]; }
};

struct mat4 {
  vec4 c[4];
  mat4() = default;
  explicit mat4(Float diagonal)
      : c{vec4(diagonal, 0.0f, 0.0f, 0.0f), vec4(0.0f, diagonal, 0.0f, 0.0f), vec4(0.0f, 0.0f, diagonal, 0.0f),
          vec4(0.0f, 0.0f, 0.0f, diagonal)} {}
  mat4(const vec4& c0, const vec4& c1, const vec4& c2, const vec4& c3) : c{c0, c1, c2, c3} {}
  mat4(const glm::mat4& m) : c{vec4(m[0]), vec4(m[1]), vec4(m[2]), vec4(m[3])} {}
  vec4& operator[](int i) { return c[i]; }
  const vec4& operator[](int i) const { return c[i]; }
};

// Matrix times vector, in GLM's order of operations (so that the lanes get GLM's bits): for a mat3
// (m0 v.x + m1 v.y) + m2 v.z, for a mat4 (m0 v.x + m1 v.y) + (m2 v.z + m3 v.w).
inline vec3 operator*(const mat3& m, const vec3& v) { return m[0] * v.x + m[1] * v.y + m[2] * v.z; }
inline vec4 operator*(const mat4& m, const vec4& v) { return (m[0] * v.x + m[1] * v.y) + (m[2] * v.z + m[3] * v.w); }
inline vec3 operator*(const glm::mat3& m, const vec3& v) {
  return vec3(m[0]) * v.x + vec3(m[1]) * v.y + vec3(m[2]) * v.z;
}
inline vec4 operator*(const glm::mat4& m, const vec4& v) {
  return (vec4(m[0]) * v.x + vec4(m[1]) * v.y) + (vec4(m[2]) * v.z + vec4(m[3]) * v.w);
}
inline mat3 operator*(const mat3& a, const mat3& b) { return mat3(a * b[0], a * b[1], a * b[2]); }
inline mat4 operator*(const mat4& a, const mat4& b) { return mat4(a * b[0], a * b[1], a * b[2], a * b[3]); }
inline mat3 transpose(const mat3& m) {
  return mat3(vec3(m[0].x, m[1].x, m[2].x), vec3(m[0].y, m[1].y, m[2].y), vec3(m[0].z, m[1].z, m[2].z));
}
inline mat4 transpose(const mat4& m) {
  return mat4(vec4(m[0].x, m[1].x, m[2].x, m[3].x), vec4(m[0].y, m[1].y, m[2].y, m[3].y),
              vec4(m[0].z, m[1].z, m[2].z, m[3].z), vec4(m[0].w, m[1].w, m[2].w, m[3].w));
}

// ---- Functions ------------------------------------------------------------------------------------------------------

// Componentwise functions of one, two or three arguments: defined on Float, then on every vector with vectors or
// scalars in the other places (GLSL's genType forms).
#define SOFTGL_LANES_UNARY(name)                                        \
  template <WideVector V>                                               \
  inline V name(const V& a) {                                           \
    return lanes_detail::Map(a, [](Float p) { return name(p); });      \
  }
#define SOFTGL_LANES_BINARY(name)                                                 \
  template <WideVector V>                                                         \
  inline V name(const V& a, const V& b) {                                         \
    return lanes_detail::Map(a, b, [](Float p, Float q) { return name(p, q); });   \
  }                                                                               \
  template <WideVector V>                                                         \
  inline V name(const V& a, Float s) {                                            \
    return lanes_detail::Map(a, [s](Float p) { return name(p, s); });             \
  }                                                                               \
  template <WideVector V>                                                         \
  inline V name(const V& a, float s) {                                            \
    return name(a, Float(s));                                                     \
  }                                                                               \
  template <WideVector V>                                                         \
  inline V name(const V& a, const typename V::Glm& g) {                           \
    return name(a, V(g));                                                         \
  }

/// Per lane minimum and maximum, as std::min / std::max (and GLSL) take them: min(a, b) = b < a ? b : a.
inline Float min(Float a, Float b) { return select(b < a, b, a); }
inline Float max(Float a, Float b) { return select(a < b, b, a); }
inline Int min(Int a, Int b) { return select(b < a, b, a); }
inline Int max(Int a, Int b) { return select(a < b, b, a); }
SOFTGL_LANES_BINARY(min)
SOFTGL_LANES_BINARY(max)

inline Float abs(Float a) { return Float::FromBits(a.Bits() & Int(0x7FFFFFFF)); }
inline Int abs(Int a) { return select(a < 0, -a, a); }
SOFTGL_LANES_UNARY(abs)

/// -1, 0 or 1 (0 for NaN).
inline Float sign(Float a) { return select(a > 0.0f, Float(1.0f), select(a < 0.0f, Float(-1.0f), Float(0.0f))); }
SOFTGL_LANES_UNARY(sign)

/// Largest integer not above a (as std::floor, -0 and values beyond 2^23 included).
inline Float floor(Float a) {
  const Float t = Float(Int(a));  // truncated; exact where |a| < 2^23
  const Float f = select(t > a, t - 1.0f, t);
  const Bool keep = !(abs(a) < 8388608.0f);  // already an integer, infinite or NaN
  // A zero result keeps a's sign (floor(-0) = -0).
  const Float signed_zero = Float::FromBits(f.Bits() | (a.Bits() & Int(std::int32_t(0x80000000u))));
  return select(keep, a, select(f == 0.0f, signed_zero, f));
}
inline Float ceil(Float a) { return -floor(-a); }
/// a - floor(a).
inline Float fract(Float a) { return a - floor(a); }
/// a - b * floor(a / b), as GLSL defines it.
inline Float mod(Float a, Float b) { return a - b * floor(a / b); }
SOFTGL_LANES_UNARY(floor)
SOFTGL_LANES_UNARY(ceil)
SOFTGL_LANES_UNARY(fract)
SOFTGL_LANES_BINARY(mod)

/// The square root, correctly rounded (as std::sqrt).
inline Float sqrt(Float a) {
#if defined(__SSE2__) && SOFTGL_PART_LANES == 8
  // sqrtps on each 4-lane half of each part (GCC's vector types have no square root of their own).
  using lanes_detail::F4;
  using lanes_detail::FP;
  Float r;
  for (int k = 0; k < lanes_detail::kParts; ++k) {
    const FP f = a.v.p[k];
    const F4 lo = F4(_mm_sqrt_ps(__m128(F4(__builtin_shufflevector(f, f, 0, 1, 2, 3)))));
    const F4 hi = F4(_mm_sqrt_ps(__m128(F4(__builtin_shufflevector(f, f, 4, 5, 6, 7)))));
    r.v.p[k] = __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
  }
  return r;
#else
  Float r;
  for (int i = 0; i < kLanes; ++i) r.v.Set(i, std::sqrt(a.v[i]));
  return r;
#endif
}
/// 1 / sqrt(a), as GLM computes it.
inline Float inversesqrt(Float a) { return Float(1.0f) / sqrt(a); }
SOFTGL_LANES_UNARY(sqrt)
SOFTGL_LANES_UNARY(inversesqrt)

/// 2^a. Exact at integers; within a few units in the last place elsewhere. Below -126 it flushes to 0, above 128 it
/// is infinite; NaN stays NaN.
inline Float exp2(Float a) {
  const Float x = min(max(a, -127.0f), 128.0f);
  const Float n = floor(x);
  const Float f = x - n;  // [0, 1)
  // 2^f on [0, 1): Chebyshev fit of degree 6, absolute error 2.8e-9 (exactly 1 at f = 0).
  Float p = 2.1865784786598053e-4f;
  p = p * f + 1.239133183441148e-3f;
  p = p * f + 9.6841863103423696e-3f;
  p = p * f + 5.5480630196705328e-2f;
  p = p * f + 2.4023045441230568e-1f;
  p = p * f + 6.9314693275886686e-1f;
  p = p * f + 1.0f;
  // times 2^n, in two steps so that n = 128 and n = -127 stay representable until the end
  const Int e = Int(n);
  const Int e1 = e >> 1, e2 = e - e1;
  const Float s1 = Float::FromBits((e1 + 127) << 23), s2 = Float::FromBits((e2 + 127) << 23);
  const Float r = p * s1 * s2;
  return select(a != a, a, select(a < -126.0f, Float(0.0f), r));
}

/// log2(a): exact at powers of two, within a few units in the last place for other normal positive a; -inf at 0, NaN below 0 and for NaN, +inf at
/// +inf. (Subnormal inputs are taken as 0.)
inline Float log2(Float a) {
  const Int bits = a.Bits();
  Int e = ((bits >> 23) & Int(0xFF)) - 127;
  Float m = Float::FromBits((bits & Int(0x007FFFFF)) | Int(0x3F800000));  // [1, 2)
  // Centre the mantissa on 1: m in [sqrt(1/2), sqrt(2)).
  const Bool big = m > 1.41421356f;
  m = select(big, m * 0.5f, m);
  e = select(big, e + 1, e);
  const Float t = (m - 1.0f) / (m + 1.0f);  // log(m) = 2 atanh(t)
  const Float t2 = t * t;
  // 2 atanh(t) / ln 2 = (2 / ln 2) (t + t^3 / 3 + t^5 / 5 + ...), |t| < 0.1716: five terms.
  Float p = 2.8853900817779268f / 9.0f;
  p = p * t2 + 2.8853900817779268f / 7.0f;
  p = p * t2 + 2.8853900817779268f / 5.0f;
  p = p * t2 + 2.8853900817779268f / 3.0f;
  p = p * t2 + 2.8853900817779268f;
  const Float r = Float(e) + t * p;
  const Float inf = Float::FromBits(Int(0x7F800000));
  Float out = select(a == 0.0f || a < 1.17549435e-38f, -inf, r);
  out = select(a == inf, inf, out);
  return select(a < 0.0f || a != a, Float::FromBits(Int(0x7FC00000)), out);
}

/// e^a and the natural logarithm.
inline Float exp(Float a) { return exp2(a * 1.4426950408889634f); }
inline Float log(Float a) { return log2(a) * 0.6931471805599453f; }

/// a^b as exp2(b * log2(a)), GLSL's definition: NaN for a < 0; for a = 0, 0 when b > 0 (infinite when b < 0);
/// pow(a, 0) = 1 for any a, and pow(1, b) = 1.
inline Float pow(Float a, Float b) {
  const Float r = exp2(b * log2(a));
  Float out = select(a == 0.0f, select(b > 0.0f, Float(0.0f), Float::FromBits(Int(0x7F800000))), r);
  out = select(a < 0.0f, Float::FromBits(Int(0x7FC00000)), out);
  return select(b == 0.0f || a == 1.0f, Float(1.0f), out);
}
SOFTGL_LANES_UNARY(exp2)
SOFTGL_LANES_UNARY(log2)
SOFTGL_LANES_UNARY(exp)
SOFTGL_LANES_UNARY(log)
SOFTGL_LANES_BINARY(pow)

namespace lanes_detail {
// sin and cos of a, reduced by multiples of pi/2 (Cody and Waite's three-part pi/2), each a polynomial on
// [-pi/4, pi/4]. Accurate for |a| up to about 10^5; beyond, the result stays in [-1, 1] but loses accuracy.
inline void SinCos(Float a, Float& s, Float& c) {
  const Float q = floor(a * 0.63661977236758134f + 0.5f);  // nearest multiple of pi/2
  Float x = a - q * 1.5703125f;
  x = x - q * 4.837512969970703125e-4f;
  x = x - q * 7.54978995489188216e-8f;
  const Float x2 = x * x;
  // sin on [-pi/4, pi/4]
  Float ps = -1.9515295891e-4f;
  ps = ps * x2 + 8.3321608736e-3f;
  ps = ps * x2 - 1.6666654611e-1f;
  const Float sx = x + x * x2 * ps;
  // cos on [-pi/4, pi/4]
  Float pc = 2.443315711809948e-5f;
  pc = pc * x2 - 1.388731625493765e-3f;
  pc = pc * x2 + 4.166664568298827e-2f;
  const Float cx = 1.0f - 0.5f * x2 + x2 * x2 * pc;
  const Int k = Int(q) & Int(3);
  const Bool swap = (k & Int(1)) != Int(0);
  const Float sr = select(swap, cx, sx), cr = select(swap, sx, cx);
  s = select(k == Int(2) || k == Int(3), -sr, sr);
  c = select(k == Int(1) || k == Int(2), -cr, cr);
  const Bool bad = !(abs(a) < 1e30f);  // infinite or NaN (or too large to reduce): NaN, as sin(inf) is
  s = select(bad, Float::FromBits(Int(0x7FC00000)), s);
  c = select(bad, Float::FromBits(Int(0x7FC00000)), c);
}
}  // namespace lanes_detail

inline Float sin(Float a) {
  Float s, c;
  lanes_detail::SinCos(a, s, c);
  return s;
}
inline Float cos(Float a) {
  Float s, c;
  lanes_detail::SinCos(a, s, c);
  return c;
}
SOFTGL_LANES_UNARY(sin)
SOFTGL_LANES_UNARY(cos)

/// min(max(a, lo), hi), as GLM's clamp.
inline Float clamp(Float a, Float lo, Float hi) { return min(max(a, lo), hi); }
template <WideVector V>
inline V clamp(const V& a, Float lo, Float hi) {
  return lanes_detail::Map(a, [lo, hi](Float p) { return clamp(p, lo, hi); });
}
template <WideVector V>
inline V clamp(const V& a, const V& lo, const V& hi) {
  return lanes_detail::Map(a, lo, hi, [](Float p, Float l, Float h) { return clamp(p, l, h); });
}

/// a (1 - t) + b t, as GLSL defines mix and GLM computes it.
inline Float mix(Float a, Float b, Float t) { return a * (1.0f - t) + b * t; }
template <WideVector V>
inline V mix(const V& a, const V& b, Float t) {
  return lanes_detail::Map(a, b, [t](Float p, Float q) { return mix(p, q, t); });
}
template <WideVector V>
inline V mix(const V& a, const V& b, const V& t) {
  return lanes_detail::Map(a, b, t, [](Float p, Float q, Float s) { return mix(p, q, s); });
}
/// Per lane: b where c holds, else a (GLSL's mix with a bool).
template <WideVector V>
inline V mix(const V& a, const V& b, Bool c) {
  return select(c, b, a);
}

/// 0 where x < edge, else 1.
inline Float step(Float edge, Float x) { return select(x < edge, Float(0.0f), Float(1.0f)); }
template <WideVector V>
inline V step(Float edge, const V& x) {
  return lanes_detail::Map(x, [edge](Float p) { return step(edge, p); });
}
/// Hermite interpolation between 0 and 1 as x goes from e0 to e1: t^2 (3 - 2t), t = clamp((x - e0) / (e1 - e0)).
inline Float smoothstep(Float e0, Float e1, Float x) {
  const Float t = clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
template <WideVector V>
inline V smoothstep(Float e0, Float e1, const V& x) {
  return lanes_detail::Map(x, [e0, e1](Float p) { return smoothstep(e0, e1, p); });
}

/// Dot product, summed left to right as GLM does.
inline Float dot(const vec2& a, const vec2& b) { return a.x * b.x + a.y * b.y; }
inline Float dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Float dot(const vec4& a, const vec4& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
inline vec3 cross(const vec3& a, const vec3& b) {
  return vec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}
template <WideVector V>
inline Float length(const V& a) {
  return sqrt(dot(a, a));
}
template <WideVector V>
inline Float distance(const V& a, const V& b) {
  return length(b - a);
}
/// a * inversesqrt(dot(a, a)), as GLM computes it.
template <WideVector V>
inline V normalize(const V& a) {
  return a * inversesqrt(dot(a, a));
}
/// i - 2 dot(n, i) n.
template <WideVector V>
inline V reflect(const V& i, const V& n) {
  return i - n * dot(n, i) * 2.0f;
}
/// GLSL refract: 0 where total internal reflection occurs.
template <WideVector V>
inline V refract(const V& i, const V& n, Float eta) {
  const Float d = dot(n, i);
  const Float k = 1.0f - eta * eta * (1.0f - d * d);
  const V r = eta * i - (eta * d + sqrt(k)) * n;
  return select(k < 0.0f, V(0.0f), r);
}
/// dot, cross, reflect with a glm operand (a uniform direction).
template <WideVector V>
inline Float dot(const V& a, const typename V::Glm& b) {
  return dot(a, V(b));
}
template <WideVector V>
inline Float dot(const typename V::Glm& a, const V& b) {
  return dot(V(a), b);
}
inline vec3 cross(const vec3& a, const glm::vec3& b) { return cross(a, vec3(b)); }
inline vec3 cross(const glm::vec3& a, const vec3& b) { return cross(vec3(a), b); }

#undef SOFTGL_LANES_UNARY
#undef SOFTGL_LANES_BINARY

// ---- Derivatives across a fragment block ----------------------------------------------------------------------------

/// GLSL dFdx in a fragment shader: per 2x2 quad, the difference between the right and the left fragment of the
/// lane's row.
inline Float dFdx(Float a) {
  Float r;
  for (int k = 0; k < lanes_detail::kParts; ++k) {
    const lanes_detail::FP f = a.v.p[k];
#if SOFTGL_PART_LANES == 8
    r.v.p[k] = __builtin_shufflevector(f, f, 1, 1, 3, 3, 5, 5, 7, 7) - __builtin_shufflevector(f, f, 0, 0, 2, 2, 4, 4, 6, 6);
#else
    r.v.p[k] = __builtin_shufflevector(f, f, 1, 1, 3, 3) - __builtin_shufflevector(f, f, 0, 0, 2, 2);
#endif
  }
  return r;
}
/// GLSL dFdy: the difference between the upper and the lower fragment of the lane's column in its quad.
inline Float dFdy(Float a) {
  Float r;
  for (int k = 0; k < lanes_detail::kParts; ++k) {
    const lanes_detail::FP f = a.v.p[k];
#if SOFTGL_PART_LANES == 8
    r.v.p[k] = __builtin_shufflevector(f, f, 2, 3, 2, 3, 6, 7, 6, 7) - __builtin_shufflevector(f, f, 0, 1, 0, 1, 4, 5, 4, 5);
#else
    r.v.p[k] = __builtin_shufflevector(f, f, 2, 3, 2, 3) - __builtin_shufflevector(f, f, 0, 1, 0, 1);
#endif
  }
  return r;
}
/// |dFdx| + |dFdy|.
inline Float fwidth(Float a) { return abs(dFdx(a)) + abs(dFdy(a)); }
template <WideVector V>
inline V dFdx(const V& a) {
  return lanes_detail::Map(a, [](Float p) { return dFdx(p); });
}
template <WideVector V>
inline V dFdy(const V& a) {
  return lanes_detail::Map(a, [](Float p) { return dFdy(p); });
}

}  // namespace softgl

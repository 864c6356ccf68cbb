// fragment_ops.h — stage 9: the per-fragment operations after the fragment shader, in OpenGL's order:
// (scissor, done by the rasterizer's bounds) -> stencil test -> depth test -> stencil update -> blending ->
// colour mask -> framebuffer. Arithmetic follows the OpenGL 4.6 specification, chapter 17.
//
// They run on whole 4x4 blocks, 4 or 8 lanes per instruction: the stencil and depth tests and writes for every
// depth and stencil format, then each colour buffer by the path its format takes (ColourPath), into framebuffer
// objects of any formats and the context's framebuffer (its samples side by side when multisampled) alike. A block
// that reaches past an odd-sized target's edge goes lane by lane with the same arithmetic
// (ApplyFragmentOpsReference).
// Blending into 8-bit buffers is exact integer arithmetic on the 8-bit operands: the fragment colour is converted
// to the buffer's format first (clamped to [0, 1], round(c * 255)), like the destination, the constant colour and
// the factors; the equation's value, (s * sf + d * df) / 255 with all terms in 0..255, is rounded to the nearest
// byte. Float buffers blend in float.
#pragma once

#include <atomic>
#include <cstdint>

#include <glm/glm.hpp>
#include <softgl/enums.h>

#include "framebuffer.h"
#include "types.h"

namespace softgl::detail {

struct StencilFace {
  Enum func = ALWAYS;
  int ref = 0;
  std::uint32_t value_mask = 0xFFFFFFFFu;  // StencilFunc's mask
  Enum sfail = KEEP;                       // stencil test fails
  Enum dpfail = KEEP;                      // stencil passes, depth fails
  Enum dppass = KEEP;                      // both pass (or depth test disabled)
  std::uint32_t write_mask = 0xFFFFFFFFu;  // StencilMask
  bool operator==(const StencilFace&) const = default;
};

struct BlendState {
  Enum eq_rgb = FUNC_ADD, eq_alpha = FUNC_ADD;
  Enum src_rgb = ONE, dst_rgb = ZERO, src_alpha = ONE, dst_alpha = ZERO;
  glm::vec4 color{0.0f};  // BlendColor
  bool operator==(const BlendState&) const = default;
};

/// Fragments that passed every test while an occlusion query (SAMPLES_PASSED, ANY_SAMPLES_PASSED) was active;
/// tiles add to it as they are rendered, on any thread.
struct OcclusionCounter {
  std::atomic<std::uint64_t> passed{0};
};

/// Multisampling's state (OpenGL 4.6, sections 14.3.1 and 17.3.1): whether triangles cover each sample at its own
/// position (MULTISAMPLE), and what narrows a fragment's samples after the shader.
struct MultisampleState {
  bool multisample = true;
  bool alpha_to_coverage = false;
  bool alpha_to_one = false;
  bool sample_coverage = false;
  float coverage_value = 1.0f;  // SampleCoverage, clamped to [0, 1]
  bool coverage_invert = false;
  bool sample_mask = false;
  std::uint32_t mask = ~0u;  // SampleMaski's word 0
  bool sample_shading = false;
  float min_sample_shading = 0.0f;  // MinSampleShading, clamped to [0, 1]
  bool operator==(const MultisampleState&) const = default;
};

/// The samples (bit s for sample s of `samples`) that SAMPLE_COVERAGE's value keeps: the first
/// floor(value * samples), or the others when inverted (OpenGL leaves which to the implementation; Mesa's choice).
std::uint32_t CoverageMask(const MultisampleState& state, int samples);
/// The samples SAMPLE_ALPHA_TO_COVERAGE keeps for `alpha`: sample s where alpha > s / samples, so 0 (or NaN) keeps
/// none and any alpha above (samples - 1) / samples all (OpenGL leaves the mapping to the implementation; this is
/// llvmpipe's).
std::uint32_t AlphaToCoverageMask(float alpha, int samples);

struct FragmentOpsState {
  OcclusionCounter* occlusion[2] = {nullptr, nullptr};  // the active occlusion queries' counters (null: none)
  bool stencil_test = false;
  StencilFace front, back;
  bool depth_test = false;
  Enum depth_func = LESS;
  bool depth_write = true;
  BlendState blend;  // the equations, factors and constant colour, which every draw buffer that blends uses
  // BLEND and ColorMask per draw buffer (Enable and ColorMask set every draw buffer's, Enablei and ColorMaski one):
  // bit i of blend_buffers, bit c of color_masks[i].
  std::uint8_t blend_buffers = 0;
  std::uint8_t color_masks[kMaxColorOutputs] = {0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF};
  // COLOR_LOGIC_OP and LogicOp's operation: while enabled, no draw buffer blends, and the fixed-point ones take
  // the operation on the colour's and the stored value's bits (LogicOpBits).
  bool logic_op = false;
  Enum logic_mode = COPY;
  MultisampleState multisample;
  bool operator==(const FragmentOpsState&) const = default;
  /// Whether BLEND is enabled for draw buffer o (what IsEnabledi reports).
  bool BlendEnabled(int o) const { return (blend_buffers >> o) & 1u; }
  /// Whether draw buffer o blends (BLEND enabled and no logic operation), and writes channel c.
  bool Blends(int o) const { return !logic_op && BlendEnabled(o); }
  /// The logic operation the fixed-point buffers take, or 0 for none.
  Enum LogicMode() const { return logic_op ? logic_mode : 0; }
  bool Writes(int o, int c) const { return (color_masks[o] >> c) & 1u; }
  /// Whether any draw buffer writes any channel.
  bool WritesAny() const {
    std::uint8_t any = 0;
    for (std::uint8_t m : color_masks) any |= m;
    return any != 0;
  }
  /// Draw buffer o's colour mask as four flags.
  void Mask(int o, bool out[4]) const {
    for (int c = 0; c < 4; ++c) out[c] = Writes(o, c);
  }
};
static_assert(kMaxColorOutputs == 8, "FragmentOpsState's masks are written for 8 draw buffers");

/// Whether `a` passes comparison `func` against `b` (a func b): the depth test compares incoming to stored, the
/// stencil test the masked reference to the masked stored value. For vectors (src/wide.h), a lane mask. Always
/// inlined: a vector argument must not cross into a function compiled for another instruction set.
template <class T>
inline __attribute__((always_inline)) auto Compare(Enum func, T a, T b) {
  using Result = decltype(a < b);
  switch (func) {
    case NEVER: return Result{};
    case LESS: return a < b;
    case EQUAL: return a == b;
    case LEQUAL: return a <= b;
    case GREATER: return a > b;
    case NOTEQUAL: return a != b;
    case GEQUAL: return a >= b;
    default: return Result(!Result{});  // ALWAYS
  }
}

/// OpenGL's logic operation `op` (CLEAR ... SET) on the bits of source `s` and destination `d`: scalars or vectors
/// of unsigned integers. Bits past a channel's are not cleared (the caller keeps its own). Always inlined, as
/// Compare.
template <class T>
inline __attribute__((always_inline)) T LogicOpBits(Enum op, T s, T d) {
  switch (op) {
    case CLEAR: return s & ~s;
    case AND: return s & d;
    case AND_REVERSE: return s & ~d;
    case AND_INVERTED: return ~s & d;
    case NOOP: return d;
    case XOR: return s ^ d;
    case OR: return s | d;
    case NOR: return ~(s | d);
    case EQUIV: return ~(s ^ d);
    case INVERT: return ~d;
    case OR_REVERSE: return s | ~d;
    case COPY_INVERTED: return ~s;
    case OR_INVERTED: return ~s | d;
    case NAND: return ~(s & d);
    case SET: return ~(s & ~s);
    default: return s;  // COPY
  }
}

/// Depth test: whether `incoming` passes `func` against `stored`.
inline bool DepthTest(Enum func, float incoming, float stored) { return Compare(func, incoming, stored); }

/// Stencil test for an 8-bit stencil buffer: (ref & mask) func (stored & mask), ref clamped to [0, 255].
bool StencilTest(const StencilFace& face, std::uint8_t stored);

/// The stencil value after operation `op` (KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP) on
/// `stored`, written through the face's write mask.
std::uint8_t StencilUpdate(const StencilFace& face, Enum op, std::uint8_t stored);

/// Blends source colour `src` over destination `dst` in float: OpenGL's factors and equations (float buffers). A
/// NaN result is always the positive quiet NaN.
glm::vec4 Blend(const BlendState& state, const glm::vec4& src, const glm::vec4& dst);

/// Blends into an 8-bit RGBA pixel: `src` is the fragment colour (converted to 8 bits here, NaN as 0), `dst` the
/// stored bytes; returns the new bytes (before the colour mask). The exact integer arithmetic described above.
void BlendUnorm8(const BlendState& state, const glm::vec4& src, const std::uint8_t dst[4], std::uint8_t out[4]);

/// What an 8-bit blend factor multiplies: factor = k0 + k1 * v, v one of these 8-bit values (k0 in {0, 255}, k1 in
/// {-1, 0, 1}); kSaturate is min(As, 1 - Ad) for colour.
enum Source : std::uint8_t { kNothing, kSrc, kDst, kSrcAlpha, kDstAlpha, kConst, kConstAlpha, kSaturate };
struct Term {
  int k0 = 0, k1 = 0;
  Source source = kNothing;
};

/// The blend state for an 8-bit buffer, resolved once per draw.
struct Unorm8Blend {
  bool blend = false;
  Term src[4], dst[4];  // per channel (r, g, b from the colour state, a from the alpha state)
  Enum eq[4] = {FUNC_ADD, FUNC_ADD, FUNC_ADD, FUNC_ADD};
  int constant[4] = {0, 0, 0, 0};  // the constant colour in 8 bits
  std::uint32_t keep = 0;          // bytes of the stored pixel the colour mask keeps
  bool packed = false;             // blending by one equation, FUNC_ADD or a subtraction, in all four channels
  bool alpha_over = false;         // packed, FUNC_ADD, SRC_ALPHA and ONE_MINUS_SRC_ALPHA in all four channels
  Enum logic = 0;                  // the logic operation instead of blending (then `blend` is set too), or 0

  Unorm8Blend() = default;
  /// Draw buffer o's blending and colour mask (rgb_only: a buffer without alpha, whose alpha byte is kept).
  Unorm8Blend(const FragmentOpsState& state, int o, bool rgb_only);
};

/// How a block's lanes are written into one colour buffer.
enum class ColourPath : std::uint8_t {
  kNone,     // no buffer, or every channel masked
  kUnorm8,   // RGBA8, RGB8, RG8, R8: the exact 8-bit blend in vectors (Unorm8Blend)
  kFloat,    // decoded to floats, blended and encoded again in vectors: the other formats
  kInteger,  // the integer formats (R8UI ... RGBA32I): never blended, clamped and packed in vectors
};

/// What the per-fragment operations resolve once per draw and target.
struct FragmentOpsPlan {
  Unorm8Blend blend[kMaxColorOutputs];  // for the 8-bit colour buffers
  ColourPath path[kMaxColorOutputs] = {};
  int buffers = 0;           // the buffers after the last one with a path have none
  bool one_rgba8 = false;    // colour buffer 0 RGBA8 (or none) and no other: the commonest target, its own code
  const SrgbLaneTables* srgb = nullptr;  // SrgbLanes(), where an sRGB buffer converts
  bool wide_target = false;  // blocks inside the target take the vector path
};
FragmentOpsPlan PlanFragmentOps(const FragmentOpsState& state, const RenderTarget& target);

/// Whether the depth test may run before the fragment shader without changing the result: the shader does not
/// write depth, the stencil test is off (its depth-fail operation would be skipped), and the depth function is
/// monotonic (LESS, LEQUAL, GREATER, GEQUAL), so that a fragment failing against the buffer now fails against any
/// later content of it too, the buffer only moving towards the test's winning side.
bool EarlyDepthTestApplies(const FragmentOpsState& state, bool shader_writes_depth);

/// The early depth test: clears the live bit of every lane whose interpolated depth (frag_coord.z, clamped as the
/// late test clamps it) fails against the depth buffer. Writes nothing; the late test runs as usual after the
/// shader. Returns whether any lane is left live.
bool EarlyDepthTest(const FragmentOpsState& state, BlockBuffer& blocks, const RenderTarget& target);

/// Runs the per-fragment operations for every live lane of `blocks` (after the fragment shader has written its
/// colours, and its depth when `shader_depth`, and cleared discarded lanes) into the buffers of `target`.
void ApplyFragmentOps(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                      bool shader_depth, const RenderTarget& target);

/// The same operations lane by lane, every block: the reference the vector paths are tested against.
void ApplyFragmentOpsReference(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                               bool shader_depth, const RenderTarget& target);

/// A multisampled batch's fragment depths at its samples: z[b][s][lane] is the depth of block b's lane at sample s,
/// on its triangle's depth plane at the sample's position (the fragment stage fills it from the planes).
/// Into an interleaved target they are in element order instead (`interleaved`): ze[b][lane * samples + s].
///
/// The vector operations into an interleaved target compute each element's depth themselves, by the same arithmetic
/// (so the arrays are filled only where some block may take another path: `filled`).
struct SampleDepths {
  bool interleaved = false;
  bool at_samples = true;  // MULTISAMPLE enabled: at each sample's position (else every sample at the centre)
  bool filled = true;      // z or ze hold the depths
  int samples = 1;
  union {
    alignas(64) float z[BlockBuffer::kCapacity][kMaxSamples][kLanes];
    alignas(64) float ze[BlockBuffer::kCapacity][kMaxSamples * kLanes];
  };
  /// Sample s of block b's lanes: lane l at Lanes(b, s)[l * Stride()].
  const float* Lanes(int b, int s) const { return interleaved ? ze[b] + s : z[b][s]; }
  int Stride() const { return interleaved ? samples : 1; }
};

/// The early depth test into a multisampled target: each sample a lane covers (blocks.sample_live) tested at its
/// depth against its plane; a sample that fails is no longer covered, and a lane stays live while some sample is.
/// Returns whether any lane is left live.
bool EarlyDepthTestSamples(const FragmentOpsState& state, BlockBuffer& blocks, const RenderTarget& target,
                           const SampleDepths& depths);

/// The per-fragment operations into a multisampled target: each live lane's colour goes through the operations of
/// every sample it covers (blocks.sample_live), into that sample's plane, with the depth at that sample (the
/// shader's depth at all of them when `shader_depth`). The colour is converted once for all the samples.
void ApplyFragmentOpsSamples(const FragmentOpsState& state, const FragmentOpsPlan& plan, const BlockBuffer& blocks,
                             bool shader_depth, const RenderTarget& target, const SampleDepths& depths);

}  // namespace softgl::detail

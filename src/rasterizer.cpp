// rasterizer.cpp — coverage and interpolation for triangles, lines and points.
#include "rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <cstring>

#if defined(__x86_64__)
#include <emmintrin.h>
#endif

#include <softgl/lanes.h>

#include "hierarchical_depth.h"
#include "simd.h"
#include "snap_wide.h"
#include "wide.h"

namespace softgl::detail {

namespace {

// In 1/16 pixel, y up from the pixel's bottom edge.
constexpr std::uint8_t kCentre[1][2] = {{8, 8}};
constexpr std::uint8_t k2[2][2] = {{12, 12}, {4, 4}};
constexpr std::uint8_t k4[4][2] = {{6, 2}, {14, 6}, {2, 10}, {10, 14}};
constexpr std::uint8_t k8[8][2] = {{9, 5}, {7, 11}, {13, 9}, {5, 3}, {3, 13}, {1, 7}, {11, 15}, {15, 1}};
// (A constant expression: with a constant count, the rasterizer multiplies by the positions as constants.)
constexpr const std::uint8_t (*PositionsOf(int samples))[2] {
  switch (samples) {
    case 2: return k2;
    case 4: return k4;
    case 8: return k8;
    default: return kCentre;
  }
}

}  // namespace

const std::uint8_t (*SamplePositions(int samples))[2] { return PositionsOf(samples); }

namespace {

constexpr std::int64_t kOne = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalf = kOne / 2;


// std::llrint (to nearest, ties to even, in the default rounding mode), without the library call.
inline std::int64_t RoundToInt64(double x) {
#if defined(__x86_64__)
  return _mm_cvtsd_si64(_mm_set_sd(x));
#else
  return std::llrint(x);
#endif
}

// A new block of the four quads of the 4x4 square at (bx, by), all live.
int AddSquare(BlockBuffer& blocks, const BlockSink& sink, bool front_facing, int nvar, int bx, int by) {
  if (blocks.count == BlockBuffer::kCapacity || (blocks.count > 0 && blocks.front_facing != front_facing)) {
    sink.Flush(blocks);
  } else {
    blocks.CloseLast();
  }
  blocks.front_facing = front_facing;
  blocks.nvar = nvar;
  const int b = blocks.count++;
  blocks.quads[b] = 4;
  for (int q = 0; q < 4; ++q) {
    blocks.qx[b][q] = bx + (q & 1) * 2;
    blocks.qy[b][q] = by + (q >> 1) * 2;
  }
  blocks.live[b] = 0xFFFFu;
  for (int s = 0; s < blocks.samples; ++s) blocks.sample_live[b][s] = 0xFFFFu;
  for (int q = 0; q < 4; ++q) blocks.quad_planes[b][q] = nullptr;
  return b;
}

// A multisampled target's quad in slot `slot` of block b: every sample of the lanes in `mask` covered.
inline void SetSampleLanes(BlockBuffer& blocks, int b, int slot, unsigned mask) {
  const std::uint32_t clear = ~(std::uint32_t(0xF) << (4 * slot));
  for (int s = 0; s < blocks.samples; ++s)
    blocks.sample_live[b][s] = (blocks.sample_live[b][s] & clear) | (std::uint32_t(mask) << (4 * slot));
}

// The block of the buffer that may hold quads of earlier primitives when a primitive starts: the last one, in the
// buffer's current epoch. The primitive's own quads never share a place, so only that block needs the check.
struct OpenBlock {
  int block = -1, epoch = -1;
  explicit OpenBlock(const BlockBuffer& blocks) : block(blocks.count - 1), epoch(blocks.epoch) {}
  OpenBlock() = default;  // a primitive that checks every block
  bool MayHoldOthers(const BlockBuffer& blocks, int b) const {
    return epoch < 0 || (b == block && blocks.epoch == epoch);
  }
};

// A place for quad (qx, qy) with coverage `mask` (bit = lane of the quad): the current block while it has room, holds
// no quad at that place and has this facing; else a new block (the buffer flushed first when full). Returns the
// block and sets `slot` to the quad's place in it.
inline int AddQuad(BlockBuffer& blocks, const BlockSink& sink, bool front_facing, int nvar, int qx, int qy,
                   unsigned mask, int& slot, const OpenBlock& open = OpenBlock(), bool all_samples = true) {
  int b = blocks.count - 1;
  bool fresh = b < 0 || blocks.quads[b] == 4 || blocks.front_facing != front_facing;
  if (!fresh && open.MayHoldOthers(blocks, b))
    for (int q = 0; !fresh && q < blocks.quads[b]; ++q) fresh = blocks.qx[b][q] == qx && blocks.qy[b][q] == qy;
  if (fresh) {
    if (blocks.count == BlockBuffer::kCapacity || (blocks.count > 0 && blocks.front_facing != front_facing)) {
      sink.Flush(blocks);
    } else {
      blocks.CloseLast();
    }
    blocks.front_facing = front_facing;
    blocks.nvar = nvar;
    b = blocks.count++;
    blocks.quads[b] = 0;
    blocks.live[b] = 0;
    if (blocks.samples > 1) std::memset(blocks.sample_live[b], 0, sizeof(blocks.sample_live[b]));  // (a constant size: inline stores)
  }
  slot = blocks.quads[b]++;
  blocks.qx[b][slot] = qx;
  blocks.qy[b][slot] = qy;
  blocks.quad_planes[b][slot] = nullptr;
  if (blocks.points) blocks.quad_point[b][slot] = blocks.point;
  blocks.live[b] |= std::uint32_t(mask) << (4 * slot);
  if (blocks.samples > 1 && all_samples) SetSampleLanes(blocks, b, slot, mask);
  return b;
}

// Before a primitive that is not a point: the points' quads go on first (they and others never share a buffer).
void EndPoints(BlockBuffer& blocks, const BlockSink& sink) {
  sink.Flush(blocks);
  blocks.points = false;
}

// The lanes of the quad at (qx, qy) inside `bounds`.
unsigned BoundsMask(const Rect& bounds, int qx, int qy) {
  unsigned mask = 0;
  for (int lane = 0; lane < 4; ++lane) {
    const int px = qx + (lane & 1), py = qy + (lane >> 1);
    if (px >= bounds.x0 && px < bounds.x1 && py >= bounds.y0 && py < bounds.y1) mask |= 1u << lane;
  }
  return mask;
}

// Appends the quad at (qx, qy) with coverage `mask`; `eval(px, py, frag, var)` fills one lane (helper lanes too):
// frag the 4 values of gl_FragCoord, var the nvar varyings.
template <class Eval>
int EmitQuad(BlockBuffer& blocks, const BlockSink& sink, bool front_facing, int nvar, int qx, int qy, unsigned mask,
             Eval&& eval) {
  int slot;
  const int b = AddQuad(blocks, sink, front_facing, nvar, qx, qy, mask, slot);
  float* var = blocks.Varyings(b);
  for (int k = 0; k < 4; ++k) {
    const int lane = slot * 4 + k;
    float frag[4], v[kMaxVaryingFloats];
    eval(qx + (k & 1), qy + (k >> 1), frag, v);
    for (int c = 0; c < 4; ++c) blocks.frag_coord[b][c][lane] = frag[c];
    for (int i = 0; i < nvar; ++i) var[i * kLanes + lane] = v[i];
  }
  return b;
}

// gl_FragCoord of W lanes of block b from l0, every lane (helpers included), at pixels (x, y): with r = pixel
// centre - vertex 0, z = z(r) and q = 1/w = oow(r).
template <int W>
SOFTGL_WIDE void FragCoordLanes(const TrianglePlanes& p, BlockBuffer& blocks, int b, int l0, typename V<W>::F x,
                                typename V<W>::F y) {
  using F = typename V<W>::F;
  const F fx = x + 0.5f, fy = y + 0.5f;
  const F rx = fx - p.x0, ry = fy - p.y0;
  const F q = (p.oow.a0 + p.oow.dx * rx) + p.oow.dy * ry, z = (p.z.a0 + p.z.dx * rx) + p.z.dy * ry;
  StoreVec(&blocks.frag_coord[b][0][l0], fx);
  StoreVec(&blocks.frag_coord[b][1][l0], fy);
  StoreVec(&blocks.frag_coord[b][2][l0], z);
  StoreVec(&blocks.frag_coord[b][3][l0], q);
}

// The varyings of W lanes of block b from l0, whose gl_FragCoord is set: a smooth varying is plane(r) / q, a
// noperspective or flat one plane(r) itself. Each lane's operations those of one lane alone, in the same order.
template <int W>
SOFTGL_WIDE void VaryingLanes(const TrianglePlanes& p, BlockBuffer& blocks, int b, int l0) {
  using F = typename V<W>::F;
  const F rx = LoadVec<F>(&blocks.frag_coord[b][0][l0]) - p.x0, ry = LoadVec<F>(&blocks.frag_coord[b][1][l0]) - p.y0;
  const F w = 1.0f / LoadVec<F>(&blocks.frag_coord[b][3][l0]);
  float* var = blocks.Varyings(b) + l0;
  for (int i = 0; i < p.nvar; ++i) {
    F v = (p.a0[i] + p.dx[i] * rx) + p.dy[i] * ry;
    if (p.perspective[i]) v = v * w;
    StoreVec(var + i * kLanes, v);
  }
}

// gl_FragCoord of the quads of block b that refer to planes (the others have theirs): all 16 lanes at once when
// the four quads share them (W lanes at a time), else quad by quad.
template <int W>
SOFTGL_WIDE void FragCoordOfBlock(BlockBuffer& blocks, int b) {
  using F = typename V<W>::F;
  const TrianglePlanes* const* qp = blocks.quad_planes[b];
  if (qp[0] && qp[1] == qp[0] && qp[2] == qp[0] && qp[3] == qp[0]) {
    if constexpr (W == 4 || W == 8) {
      // Lane l is pixel (l & 1, (l >> 1) & 1) of quad l >> 2: each quad's origin spread over its four lanes.
      using I4 = typename V<4>::I;
      const I4 qx = LoadVec<I4>(blocks.qx[b]), qy = LoadVec<I4>(blocks.qy[b]);
      auto spread = [](I4 o, auto q) SOFTGL_WIDE_LAMBDA {  // the origins of quads q and (W = 8) q + 1
        if constexpr (W == 4) return __builtin_shufflevector(o, o, q(), q(), q(), q());
        else return __builtin_shufflevector(o, o, q(), q(), q(), q(), q() + 1, q() + 1, q() + 1, q() + 1);
      };
      using I = typename V<W>::I;
      I dx, dy;
      for (int l = 0; l < W; ++l) {
        dx[l] = l & 1;
        dy[l] = (l >> 1) & 1;
      }
      auto lanes = [&](auto q) SOFTGL_WIDE_LAMBDA {
        FragCoordLanes<W>(*qp[0], blocks, b, 4 * q(), __builtin_convertvector(spread(qx, q) + dx, F),
                          __builtin_convertvector(spread(qy, q) + dy, F));
      };
      lanes(std::integral_constant<int, 0>());
      lanes(std::integral_constant<int, W / 4>());
      if constexpr (W == 4) {
        lanes(std::integral_constant<int, 2>());
        lanes(std::integral_constant<int, 3>());
      }
    } else {
      alignas(64) float x[kLanes], y[kLanes];
      for (int l = 0; l < kLanes; ++l) {
        x[l] = float(blocks.qx[b][l >> 2] + (l & 1));
        y[l] = float(blocks.qy[b][l >> 2] + ((l >> 1) & 1));
      }
      for (int l0 = 0; l0 < kLanes; l0 += W) FragCoordLanes<W>(*qp[0], blocks, b, l0, LoadVec<F>(x + l0), LoadVec<F>(y + l0));
    }
    return;
  }
  using F4 = typename V<4>::F;
  for (int q = 0; q < 4; ++q)
    if (qp[q])
      FragCoordLanes<4>(*qp[q], blocks, b, 4 * q, float(blocks.qx[b][q]) + F4{0.0f, 1.0f, 0.0f, 1.0f},
                        float(blocks.qy[b][q]) + F4{0.0f, 0.0f, 1.0f, 1.0f});
}

// The varyings of the live quads of a block that refer to planes: all 16 lanes at once when all four quads share
// them (W lanes at a time), else quad by quad.
template <int W>
SOFTGL_WIDE void VaryingsOfBlock(BlockBuffer& blocks, int b) {
  const TrianglePlanes* const* qp = blocks.quad_planes[b];
  const std::uint32_t live = blocks.live[b];
  if (qp[0] && qp[1] == qp[0] && qp[2] == qp[0] && qp[3] == qp[0] && (live & 0xFu) && (live & 0xF0u) &&
      (live & 0xF00u) && (live & 0xF000u)) {
    if (qp[0]->nvar == 0) return;
    for (int l0 = 0; l0 < kLanes; l0 += W) VaryingLanes<W>(*qp[0], blocks, b, l0);
    return;
  }
  for (int q = 0; q < 4; ++q)
    if (qp[q] && qp[q]->nvar > 0 && ((live >> (4 * q)) & 0xFu)) VaryingLanes<4>(*qp[q], blocks, b, 4 * q);
}

using BlockFn = void (*)(BlockBuffer&, int);
void FragCoordOfBlockBase(BlockBuffer& blocks, int b) { FragCoordOfBlock<4>(blocks, b); }
void VaryingsOfBlockBase(BlockBuffer& blocks, int b) { VaryingsOfBlock<4>(blocks, b); }
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void FragCoordOfBlockAvx2(BlockBuffer& blocks, int b) { FragCoordOfBlock<8>(blocks, b); }
// 8 lanes on AVX-512 too, with its instruction set: measured faster than 16 on the bench scenes (docs/performance.md).
SOFTGL_TARGET_AVX512 void FragCoordOfBlockAvx512(BlockBuffer& blocks, int b) { FragCoordOfBlock<8>(blocks, b); }
SOFTGL_TARGET_AVX2 void VaryingsOfBlockAvx2(BlockBuffer& blocks, int b) { VaryingsOfBlock<8>(blocks, b); }
SOFTGL_TARGET_AVX512 void VaryingsOfBlockAvx512(BlockBuffer& blocks, int b) { VaryingsOfBlock<8>(blocks, b); }
#endif

// Coverage of one 8x8 region by a triangle, 64 bits in quad order: bit 4q + k is lane k (x % 2 + 2 (y % 2)) of the
// region's quad q = (y / 2) * 4 + x / 2. Edge e's function at the region's pixel (ix, iy) is
// c00[e] + ix sx[e] + iy sy[e]; only the edges that cross the region are given (an edge true at all four corners
// adds nothing), and for those every value fits 32 bits (the caller checks |sx|, |sy| <= 2^26, and a crossing
// edge has |c00| <= 7 (|sx| + |sy|)), so W lanes are tested per instruction.
struct RegionEdges {
  int count = 0;
  std::int32_t c00[3] = {}, sx[3] = {}, sy[3] = {};  // the edges past `count` stay 0: inside everywhere
  int row0 = 0, row1 = 3;  // the quad rows to test (the others are left out of the result)
};
// Each lane's pixel in the region (x, y), in RegionCoverage's order.
struct RegionLanes {
  std::int32_t x[64], y[64];
  constexpr RegionLanes() : x(), y() {
    for (int l = 0; l < 64; ++l) {
      const int q = l >> 2;
      x[l] = (q & 3) * 2 + (l & 1);
      y[l] = (q >> 2) * 2 + ((l >> 1) & 1);
    }
  }
};
constexpr RegionLanes kRegionLanes;
constexpr const std::int32_t* kRegionX = kRegionLanes.x;
constexpr const std::int32_t* kRegionY = kRegionLanes.y;

template <int W>
SOFTGL_WIDE std::uint64_t RegionCoverage(const RegionEdges& edges) {
  using I = typename V<W>::I;
  constexpr int kChunks = 16 / W;  // vectors to a quad row of 16 lanes
  // Each crossing edge's values at the lanes of quad row row0; a quad row further adds 2 sy.
  // All three edges (those past `count` are 0), so that the loops have a fixed length.
  I value[3][kChunks];
  for (int e = 0; e < 3; ++e)
    for (int c = 0; c < kChunks; ++c) {
      const I ix = LoadVec<I>(kRegionX + c * W), iy = LoadVec<I>(kRegionY + c * W);
      value[e][c] = (edges.c00[e] + 2 * edges.row0 * edges.sy[e]) + ix * edges.sx[e] + iy * edges.sy[e];
    }
  std::uint64_t bits = 0;
  for (int row = edges.row0; row <= edges.row1; ++row) {
    for (int c = 0; c < kChunks; ++c) {
      I outside = I{};  // sign bit set where some edge is negative
      for (int e = 0; e < 3; ++e) {
        outside |= value[e][c];
        value[e][c] += 2 * edges.sy[e];
      }
      bits |= std::uint64_t(MaskToBits<W>(~outside >> 31, 0)) << (row * 16 + c * W);  // >> 31: a lane mask
    }
  }
  return bits;
}
using CoverageFn = std::uint64_t (*)(const RegionEdges&);
std::uint64_t RegionCoverageBase(const RegionEdges& e) { return RegionCoverage<4>(e); }
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 std::uint64_t RegionCoverageAvx2(const RegionEdges& e) { return RegionCoverage<8>(e); }
// 8 lanes on AVX-512 too, with its instruction set: measured faster than 16 on the bench scenes (docs/performance.md).
SOFTGL_TARGET_AVX512 std::uint64_t RegionCoverageAvx512(const RegionEdges& e) { return RegionCoverage<8>(e); }
#endif

// RegionCoverage for S samples at once, every edge tested (a small triangle's: all values fit 32 bits):
// edge e at sample s of the region's pixel (ix, iy) is c00[e] + delta[s][e] + ix sx[e] + iy sy[e]; bits[s] the
// lanes inside at sample s, in RegionCoverage's order, quad rows row0 to row1.
struct SampleEdges {  // (left uninitialized: every field is set before use, the deltas of the S samples)
  std::int32_t c00[3], sx[3], sy[3];
  std::int32_t delta[kMaxSamples][3];
  int row0, row1;
  bool left_half;  // only the region's left four columns are needed (the others' bits are left 0)
};
template <int W, int S>
SOFTGL_WIDE void SampleRegionCoverage(const SampleEdges& edges, std::uint64_t bits[kMaxSamples]) {
  using I = typename V<W>::I;
  constexpr int kChunks = 16 / W;
  const int chunks = edges.left_half && W == 8 ? 1 : kChunks;  // (W = 8: a chunk is two quads, four columns)
  I value[3][kChunks];
  for (int e = 0; e < 3; ++e)
    for (int c = 0; c < chunks; ++c) {
      const I ix = LoadVec<I>(kRegionX + c * W), iy = LoadVec<I>(kRegionY + c * W);
      value[e][c] = (edges.c00[e] + 2 * edges.row0 * edges.sy[e]) + ix * edges.sx[e] + iy * edges.sy[e];
    }
  std::uint64_t outside[S] = {};  // the lanes some edge excludes at sample s (sign bits)
  for (int row = edges.row0; row <= edges.row1; ++row) {
    for (int c = 0; c < chunks; ++c) {
      for (int s = 0; s < S; ++s) {
        const I out = (value[0][c] + edges.delta[s][0]) | (value[1][c] + edges.delta[s][1]) |
                      (value[2][c] + edges.delta[s][2]);
        outside[s] |= std::uint64_t(SignBits<W>(out)) << (row * 16 + c * W);
      }
      for (int e = 0; e < 3; ++e) value[e][c] += 2 * edges.sy[e];
    }
  }
  // The lanes tested: quad rows row0 to row1, the left half only where only that was tested.
  const std::uint64_t rows = (~std::uint64_t(0) >> (64 - 16 * (edges.row1 - edges.row0 + 1))) << (16 * edges.row0);
  const std::uint64_t tested = chunks * W < 16 ? rows & 0x00FF00FF00FF00FFull : rows;
  for (int s = 0; s < S; ++s) bits[s] = ~outside[s] & tested;
}
// The lanes (in RegionCoverage's order) of the region's pixels with ix in [x0, x1) and iy in [y0, y1), 0 <= x0, y0
// and x1, y1 <= 8: from tables of the lanes left of each column and below each row.
struct RegionMasks {
  std::uint64_t left[9], below[9];  // lanes with ix < k, with iy < k
  constexpr RegionMasks() : left(), below() {
    for (int k = 0; k <= 8; ++k)
      for (int l = 0; l < 64; ++l) {
        if (kRegionX[l] < k) left[k] |= std::uint64_t(1) << l;
        if (kRegionY[l] < k) below[k] |= std::uint64_t(1) << l;
      }
  }
};
constexpr RegionMasks kRegionMasks;
std::uint64_t RegionRect(int x0, int x1, int y0, int y1) {
  return (kRegionMasks.left[x1] & ~kRegionMasks.left[x0]) & (kRegionMasks.below[y1] & ~kRegionMasks.below[y0]);
}

// A triangle's planes in the buffer's table, entered when its first quad goes in (and again after each flush):
// `fill` computes the varyings' planes into the entry the first time; after a flush the entry is copied from the
// previous one (its memory is not reused before this triangle's next quad asks for its new entry).
struct PlanesEntry {
  const TrianglePlanes* planes = nullptr;
  int epoch = -1;
  template <class Fill>
  const TrianglePlanes* For(BlockBuffer& blocks, const TrianglePlanes& p, Fill&& fill) {
    if (epoch != blocks.epoch) {
      TrianglePlanes& slot = blocks.planes[blocks.plane_count++];  // never full: one per triangle, <= quads
      slot.x0 = p.x0;
      slot.y0 = p.y0;
      slot.z = p.z;
      slot.oow = p.oow;
      slot.nvar = p.nvar;
      std::memcpy(slot.sample_dz, p.sample_dz, sizeof(p.sample_dz));
      if (planes) {
        std::memcpy(slot.a0, planes->a0, sizeof(float) * std::size_t(p.nvar));
        std::memcpy(slot.dx, planes->dx, sizeof(float) * std::size_t(p.nvar));
        std::memcpy(slot.dy, planes->dy, sizeof(float) * std::size_t(p.nvar));
        std::memcpy(slot.perspective, planes->perspective, sizeof(bool) * std::size_t(p.nvar));
      } else {
        fill(slot);
      }
      planes = &slot;
      epoch = blocks.epoch;
    }
    return planes;
  }
};

// Whether varying i is divided by w (smooth), or taken as it is (noperspective, flat).
bool Perspective(const RasterTarget& t, int i) {
  return !t.interpolation || t.interpolation[i] == Interpolation::kSmooth || t.interpolation[i] == Interpolation::kCentroid;
}

}  // namespace

float PolygonOffset(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, float factor, float units,
                    bool fixed16) {
  const float dx1 = b.x - a.x, dy1 = b.y - a.y, dz1 = b.z - a.z;
  const float dx2 = c.x - a.x, dy2 = c.y - a.y, dz2 = c.z - a.z;
  const float det = dx1 * dy2 - dx2 * dy1;
  float m = 0.0f;
  if (det != 0.0f) {
    const float dzdx = (dz1 * dy2 - dz2 * dy1) / det, dzdy = (dz2 * dx1 - dz1 * dx2) / det;
    m = std::max(std::fabs(dzdx), std::fabs(dzdy));
  }
  const float zmax = std::max({std::fabs(a.z), std::fabs(b.z), std::fabs(c.z)});
  int e = 0;
  std::frexp(zmax, &e);  // zmax = f * 2^e with f in [0.5, 1): the IEEE exponent is e - 1
  const float r = fixed16 ? 1.0f / 65535.0f : zmax > 0.0f ? std::ldexp(1.0f, e - 1 - 23) : std::ldexp(1.0f, -126);
  const float offset = m * factor + r * units;
  return std::isfinite(offset) ? offset : 0.0f;
}

namespace {

// The vertices snapped to the subpixel grid; false when one is beyond the range the rasterizer takes (the
// clipper's guard band keeps finite window coordinates far inside it).
bool Snap(const glm::vec4* const p[3], std::int64_t X[3], std::int64_t Y[3]) {
  for (int i = 0; i < 3; ++i) {
    const float x = p[i]->x, y = p[i]->y;
    if (!(std::fabs(x) < 1e7f) || !(std::fabs(y) < 1e7f)) return false;
    X[i] = RoundToInt64(double(x) * double(kOne));
    Y[i] = RoundToInt64(double(y) * double(kOne));
  }
  return true;
}

std::int64_t SnappedArea(const std::int64_t X[3], const std::int64_t Y[3]) {
  return (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
}

// The first and last pixel whose centre lies in [lo, hi] (snapped units) along one axis: ceil((lo - 1/2) / kOne)
// and floor((hi - 1/2) / kOne), by arithmetic shifts (which round towards minus infinity).
std::int64_t FirstCentre(std::int64_t lo) { return -((kHalf - lo) >> kSubpixelBits); }
std::int64_t LastCentre(std::int64_t hi) { return (hi - kHalf) >> kSubpixelBits; }
// The same for points at offset o (snapped units) into each pixel: the first pixel i with i + o >= lo, the last
// with i + o <= hi.
std::int64_t FirstAt(std::int64_t lo, std::int64_t o) { return -((o - lo) >> kSubpixelBits); }
std::int64_t LastAt(std::int64_t hi, std::int64_t o) { return (hi - o) >> kSubpixelBits; }

}  // namespace

SampleSpan::SampleSpan(int samples) {
  if (samples <= 1) return;
  const auto* pos = SamplePositions(samples);
  x0 = y0 = kOne;
  x1 = y1 = 0;
  for (int s = 0; s < samples; ++s) {
    const std::int64_t x = pos[s][0] * (kOne / 16), y = pos[s][1] * (kOne / 16);
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
}

const SampleSpan& SampleSpan::Of(int samples) {
  static const SampleSpan kSpans[4] = {SampleSpan(1), SampleSpan(2), SampleSpan(4), SampleSpan(8)};
  return kSpans[samples <= 1 ? 0 : samples == 2 ? 1 : samples == 4 ? 2 : 3];
}

namespace {

// Each sample's offset from the pixel centre, in pixels.
template <int S>
struct SampleOffsets {
  float x[S], y[S];
  SampleOffsets() {
    const auto* pos = SamplePositions(S);
    for (int s = 0; s < S; ++s) {
      x[s] = float(pos[s][0]) / 16.0f - 0.5f;
      y[s] = float(pos[s][1]) / 16.0f - 0.5f;
    }
  }
};

// The samples of a triangle whose edge functions are A x + B y + C (snapped units, tie rule folded into C; > =
// 0 inside) over the pixels of `box` (every one inside `bounds`), 8x8 regions at a time: `emit(qx, qy, mask,
// cover, shift)` for each quad with some sample covered, mask its lanes with any, bits shift to shift + 3 of
// cover[s] its lanes with sample s. Each sample's test is the exact integer test of a pixel centre, at the sample's position.
// `small`: the triangle's samples all lie in one region (from the box's first quad) even before the bounds cut it,
// so that its vertices lie within a few pixels and all its edge values there fit 32 bits.
// A region every sample of every pixel of which is covered goes to `square(bx, by)` as four 4x4 squares instead.
// W: the coverage kernel's lanes (the instance is compiled for the instruction set that has them).
template <int samples, int W, class Emit, class Square>
SOFTGL_WIDE void RasterizeSamples(const std::int64_t A[3], const std::int64_t B[3], const std::int64_t C[3],
                                  const Rect& box, bool small, Emit&& emit, Square&& square) {
  constexpr int kRegion = 8;
  auto sample_coverage = [](const SampleEdges& edges, std::uint64_t* cover) SOFTGL_WIDE_LAMBDA {
    SampleRegionCoverage<W, samples>(edges, cover);
  };
  constexpr auto* pos = PositionsOf(samples);
  auto emit_region = [&](std::int64_t rx, std::int64_t ry, std::uint64_t any, const std::uint64_t* cover) {
    while (any) {
      const int q = __builtin_ctzll(any) >> 2;
      const unsigned mask = unsigned(any >> (4 * q)) & 0xFu;
      any &= ~(std::uint64_t(0xF) << (4 * q));
      emit(int(rx) + (q & 3) * 2, int(ry) + (q >> 2) * 2, mask, cover, 4 * q);
    }
  };
  if (small) {
    const std::int64_t rx = box.x0 & ~1, ry = box.y0 & ~1;
    SampleEdges edges;
    for (int e = 0; e < 3; ++e) {
      edges.c00[e] = std::int32_t(A[e] * rx * kOne + B[e] * ry * kOne + C[e]);
      edges.sx[e] = std::int32_t(A[e] * kOne);
      edges.sy[e] = std::int32_t(B[e] * kOne);
      for (int s = 0; s < samples; ++s)
        edges.delta[s][e] = std::int32_t(A[e] * (pos[s][0] * (kOne / 16)) + B[e] * (pos[s][1] * (kOne / 16)));
    }
    edges.row0 = 0;
    edges.row1 = int(box.y1 - 1 - ry) >> 1;
    edges.left_half = box.x1 - rx <= 4;
    std::uint64_t cover[kMaxSamples], any = 0;
    sample_coverage(edges, cover);
    const std::uint64_t cut = RegionRect(int(box.x0 - rx), int(box.x1 - rx), int(box.y0 - ry), int(box.y1 - ry));
    for (int s = 0; s < samples; ++s) any |= cover[s] &= cut;
    emit_region(rx, ry, any, cover);
    return;
  }
  // Edge e at sample s of pixel (px, py) is A (px kOne + ox_s) + B (py kOne + oy_s) + C: its value at the
  // region's first pixel, base, plus delta[s][e] for the sample, plus steps. Over a region an edge lies between
  // base + lo[e] and base + hi[e] at every sample: the region is skipped when some edge is below 0 there, and
  // an edge at or above 0 there is left out of the test.
  std::int64_t step_x[3], step_y[3], lo[3], hi[3], delta[kMaxSamples][3];
  bool narrow = true;
  for (int e = 0; e < 3; ++e) {
    step_x[e] = A[e] * kOne;
    step_y[e] = B[e] * kOne;
    constexpr std::int64_t kLimit = std::int64_t(1) << 26;
    narrow = narrow && step_x[e] <= kLimit && step_x[e] >= -kLimit && step_y[e] <= kLimit && step_y[e] >= -kLimit;
    const std::int64_t dx = step_x[e] * (kRegion - 1), dy = step_y[e] * (kRegion - 1);
    std::int64_t dmin = INT64_MAX, dmax = INT64_MIN;
    for (int s = 0; s < samples; ++s) {
      delta[s][e] = A[e] * (pos[s][0] * (kOne / 16)) + B[e] * (pos[s][1] * (kOne / 16));
      dmin = std::min(dmin, delta[s][e]);
      dmax = std::max(dmax, delta[s][e]);
    }
    lo[e] = std::min<std::int64_t>(dx, 0) + std::min<std::int64_t>(dy, 0) + dmin;
    hi[e] = std::max<std::int64_t>(dx, 0) + std::max<std::int64_t>(dy, 0) + dmax;
  }
  // (A crossing edge's values there lie within hi - lo <= 8 (|sx| + |sy|) of 0: 32 bits while narrow.) The
  // samples' deltas go to the kernel once; an edge left out of a region's test gets value kInside and no steps
  // there (kInside + delta > 0: |delta| <= |sx| + |sy| <= 2^27 while narrow).
  constexpr std::int32_t kInside = std::int32_t(1) << 30;
  SampleEdges edges;
  for (int s = 0; s < samples; ++s)  // (used while narrow)
    for (int e = 0; e < 3; ++e) edges.delta[s][e] = std::int32_t(delta[s][e]);
  const std::int64_t qx_first = box.x0 & ~1, qy_first = box.y0 & ~1;
  std::int64_t row_base[3];  // each edge at the first pixel of the row's first region, stepped region by region
  for (int e = 0; e < 3; ++e) row_base[e] = A[e] * qx_first * kOne + B[e] * qy_first * kOne + C[e];
  for (std::int64_t ry = qy_first; ry < box.y1; ry += kRegion) {
    std::int64_t base[3] = {row_base[0], row_base[1], row_base[2]};
    for (int e = 0; e < 3; ++e) row_base[e] += step_y[e] * kRegion;
    auto next_region = [&] {
      for (int e = 0; e < 3; ++e) base[e] += step_x[e] * kRegion;
    };
    for (std::int64_t rx = qx_first; rx < box.x1; rx += kRegion, next_region()) {
      bool skip = false, whole = true;
      for (int e = 0; e < 3; ++e) {
        skip = skip || base[e] + hi[e] < 0;
        whole = whole && base[e] + lo[e] >= 0;
      }
      if (skip) continue;
      const bool inside = rx >= box.x0 && rx + kRegion <= box.x1 && ry >= box.y0 && ry + kRegion <= box.y1;
      if (whole && inside) {
        for (int sq = 0; sq < 4; ++sq) square(int(rx) + (sq & 1) * 4, int(ry) + (sq >> 1) * 4);
        continue;
      }
      const std::uint64_t cut = RegionRect(int(std::max<std::int64_t>(box.x0 - rx, 0)),
                                           int(std::min<std::int64_t>(box.x1 - rx, kRegion)),
                                           int(std::max<std::int64_t>(box.y0 - ry, 0)),
                                           int(std::min<std::int64_t>(box.y1 - ry, kRegion)));
      std::uint64_t cover[kMaxSamples], any = 0;
      if (narrow) {
        for (int e = 0; e < 3; ++e) {
          const bool test = base[e] + lo[e] < 0;  // else inside at every sample
          edges.c00[e] = test ? std::int32_t(base[e]) : kInside;
          edges.sx[e] = test ? std::int32_t(step_x[e]) : 0;
          edges.sy[e] = test ? std::int32_t(step_y[e]) : 0;
        }
        edges.row0 = int((std::max<std::int64_t>(ry, box.y0) - ry) >> 1);  // the quad rows of the box
        edges.row1 = int((std::min<std::int64_t>(ry + kRegion, box.y1) - 1 - ry) >> 1);
        edges.left_half = box.x1 - rx <= 4;
        sample_coverage(edges, cover);
      } else {  // steep edges: each lane in 64 bits
        for (int s = 0; s < samples; ++s) {
          cover[s] = 0;
          for (int l = 0; l < 64; ++l) {
            bool in = true;
            for (int e = 0; e < 3; ++e) in = in && base[e] + delta[s][e] + kRegionX[l] * step_x[e] + kRegionY[l] * step_y[e] >= 0;
            if (in) cover[s] |= std::uint64_t(1) << l;
          }
        }
      }
      for (int s = 0; s < samples; ++s) any |= cover[s] &= cut;
      emit_region(rx, ry, any, cover);
    }
  }
}

// RasterizeSamples for each instruction set, its bookkeeping compiled for it too, its coverage kernel inlined (16 lanes
// on AVX-512: a quad row in one vector, measured about 1.5% faster on the 4x bench scene than 8).
template <int samples, class Emit, class Square>
SOFTGL_TARGET_BASE void RasterizeSamplesBase(const std::int64_t A[3], const std::int64_t B[3], const std::int64_t C[3],
                                             const Rect& box, bool small, Emit& emit, Square& square) {
  RasterizeSamples<samples, 4>(A, B, C, box, small, emit, square);
}
#if defined(SOFTGL_HAS_DISPATCH)
template <int samples, class Emit, class Square>
SOFTGL_TARGET_AVX2 void RasterizeSamplesAvx2(const std::int64_t A[3], const std::int64_t B[3], const std::int64_t C[3],
                                             const Rect& box, bool small, Emit& emit, Square& square) {
  RasterizeSamples<samples, 8>(A, B, C, box, small, emit, square);
}
template <int samples, class Emit, class Square>
SOFTGL_TARGET_AVX512 void RasterizeSamplesAvx512(const std::int64_t A[3], const std::int64_t B[3],
                                                 const std::int64_t C[3], const Rect& box, bool small, Emit& emit,
                                                 Square& square) {
  RasterizeSamples<samples, 16>(A, B, C, box, small, emit, square);
}
#endif

}  // namespace

Rect TriangleCentreBox(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const Rect& bounds, int samples) {
  const glm::vec4* const p[3] = {&a, &b, &c};
  std::int64_t X[3], Y[3];
  if (!Snap(p, X, Y) || SnappedArea(X, Y) == 0) return Rect{};
  const SampleSpan& span = SampleSpan::Of(samples);
  const Rect r{int(std::max<std::int64_t>(FirstAt(std::min({X[0], X[1], X[2]}), span.x1), bounds.x0)),
               int(std::max<std::int64_t>(FirstAt(std::min({Y[0], Y[1], Y[2]}), span.y1), bounds.y0)),
               int(std::min<std::int64_t>(LastAt(std::max({X[0], X[1], X[2]}), span.x0) + 1, bounds.x1)),
               int(std::min<std::int64_t>(LastAt(std::max({Y[0], Y[1], Y[2]}), span.y0) + 1, bounds.y1))};
  return r.Empty() ? Rect{} : r;
}

namespace {
// Hierarchical depth's test of a triangle's box, made when worth making (the caller asks HierarchicalDepth::Worth
// first, inline: most triangles of a scene where few are hidden are not tested). Out of line, so that the coverage
// step's own code stays as the compiler lays it out without.
__attribute__((noinline)) bool HiddenTriangle(HierarchicalDepth& hz, const Plane& z, float x0, float y0, int px0,
                                              int py0, int px1, int py1) {
  ++hz.triangles_tested;
  const bool hidden = hz.Hides(z, x0, y0, px0, py0, px1, py1);
  hz.Count(hidden);
  hz.triangles_hidden += hidden;
  return hidden;
}
// The same test of an 8x8 region of a larger triangle.
__attribute__((noinline)) bool HiddenRegion(HierarchicalDepth& hz, const Plane& z, float x0, float y0, int px0,
                                            int py0, int px1, int py1) {
  ++hz.regions_tested;
  const bool hidden = hz.Hides(z, x0, y0, px0, py0, px1, py1);
  hz.Count(hidden);
  hz.regions_hidden += hidden;
  return hidden;
}
}  // namespace

namespace {

// RasterizeTriangle, for the buffer as it is (a multisampled point's rectangle is two of these, and stays a point).
void TriangleQuads(const VertexView& v0, const VertexView& v1, const VertexView& v2, bool front_facing,
                   const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink);

}  // namespace

void RasterizeTriangle(const VertexView& v0, const VertexView& v1, const VertexView& v2, bool front_facing,
                       const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink) {
  if (blocks.points) EndPoints(blocks, sink);
  TriangleQuads(v0, v1, v2, front_facing, target, blocks, sink);
}

namespace {

// Filled triangles set up for coverage, up to kTriangleGroup of them as rows of lanes: what RasterizeTriangle
// computes of a triangle before any pixel is tested. Written by the vector set-up (SetUpGroup) or lane by lane
// (SetUpTriangle), read in place by the coverage step (CoverTriangle).
struct SetUpRows {
  static constexpr int N = kTriangleGroup;
  // Bit t for triangle t: set up by SetUpGroup (`handled`: its values all fit 32 bits exactly), drawing something
  // (`drawn`), vertices 1 and 2 exchanged for counter-clockwise order (`swapped`), small (below).
  std::uint32_t handled = 0, drawn = 0, swapped = 0, small = 0;
  const float* var[3][N];  // the vertices' varyings, counter-clockwise (y up): the interior is left of every edge
  std::int64_t X[3][N], Y[3][N];  // the vertices snapped to the subpixel grid, in that order
  std::int64_t area[N];           // twice the snapped area (> 0)
  std::int64_t minX[N], maxX[N], minY[N], maxY[N];
  std::int32_t px0[N], px1[N], py0[N], py1[N];  // the pixels whose centres (samples) the box holds, cut to the bounds
  float x0[N], y0[N];  // vertex 0's unsnapped position, the planes' origin
  float dx1[N], dy1[N], dx2[N], dy2[N];  // vertices 1 and 2 less vertex 0 (snapped where float rounding disagrees)
  float inv_det[N];
  float z[3][N], oow[3][N];  // the depth (with the polygon offset) and 1/w planes: a0, dx, dy
  // A small triangle (single-sampled, its centres in one 8x8 region from the box's first quad): its three edges
  // there (RegionCoverage's c00, sx, sy).
  std::int32_t c00[3][N], sx[3][N], sy[3][N];
};

// The set-up of triangle v0, v1, v2 with polygon offset `depth_offset`; false when it draws nothing (no snapped
// area, beyond the rasterizer's range, or no pixel centre in its box).
// Into lane t of `r` (its bit in r.small set when small, the others left as they are).
bool SetUpTriangle(const VertexView& v0, const VertexView& v1, const VertexView& v2, float depth_offset,
                   const RasterTarget& target, SetUpRows& r, int t) {
  const VertexView* v[3] = {&v0, &v1, &v2};
  std::int64_t X[3], Y[3];
  const glm::vec4* const pos[3] = {&v0.win, &v1.win, &v2.win};
  if (!Snap(pos, X, Y)) return false;
  std::int64_t area = SnappedArea(X, Y);
  if (area == 0) return false;
  if (area < 0) {  // make the vertex order counter-clockwise (y up): the interior is left of every edge
    std::swap(v[1], v[2]);
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
    area = -area;
  }
  r.area[t] = area;
  for (int k = 0; k < 3; ++k) {
    r.var[k][t] = v[k]->var;
    r.X[k][t] = X[k];
    r.Y[k][t] = Y[k];
  }

  // Pixel range whose centres (samples) lie in the snapped bounding box, clipped to the target bounds.
  const std::int64_t minX = std::min({X[0], X[1], X[2]}), maxX = std::max({X[0], X[1], X[2]});
  const std::int64_t minY = std::min({Y[0], Y[1], Y[2]}), maxY = std::max({Y[0], Y[1], Y[2]});
  r.minX[t] = minX;
  r.maxX[t] = maxX;
  r.minY[t] = minY;
  r.maxY[t] = maxY;
  const SampleSpan& span = SampleSpan::Of(target.samples);
  const std::int64_t px0 = std::max<std::int64_t>(FirstAt(minX, span.x1), target.bounds.x0);
  const std::int64_t px1 = std::min<std::int64_t>(LastAt(maxX, span.x0), target.bounds.x1 - 1);
  const std::int64_t py0 = std::max<std::int64_t>(FirstAt(minY, span.y1), target.bounds.y0);
  const std::int64_t py1 = std::min<std::int64_t>(LastAt(maxY, span.y0), target.bounds.y1 - 1);
  if (px0 > px1 || py0 > py1) return false;
  r.px0[t] = std::int32_t(px0);  // (inside the bounds)
  r.px1[t] = std::int32_t(px1);
  r.py0[t] = std::int32_t(py0);
  r.py1[t] = std::int32_t(py1);

  // Interpolation planes from the unsnapped float positions, relative to vertex 0.
  const float x0 = v[0]->win.x, y0 = v[0]->win.y;
  float dx1 = v[1]->win.x - x0, dy1 = v[1]->win.y - y0;
  float dx2 = v[2]->win.x - x0, dy2 = v[2]->win.y - y0;
  float det = dx1 * dy2 - dx2 * dy1;
  if (!(det > 0.0f)) {  // float rounding disagrees with the exact area: use the snapped positions
    dx1 = float(X[1] - X[0]) / kOne;
    dy1 = float(Y[1] - Y[0]) / kOne;
    dx2 = float(X[2] - X[0]) / kOne;
    dy2 = float(Y[2] - Y[0]) / kOne;
    det = float(area) / float(kOne * kOne);
  }
  const float inv_det = 1.0f / det;
  auto make_plane = [&](float a0, float a1, float a2, float (*plane)[SetUpRows::N]) {
    const float da1 = a1 - a0, da2 = a2 - a0;
    plane[0][t] = a0;
    plane[1][t] = (da1 * dy2 - da2 * dy1) * inv_det;
    plane[2][t] = (da2 * dx1 - da1 * dx2) * inv_det;
  };
  r.x0[t] = x0;
  r.y0[t] = y0;
  r.dx1[t] = dx1;
  r.dy1[t] = dy1;
  r.dx2[t] = dx2;
  r.dy2[t] = dy2;
  r.inv_det[t] = inv_det;
  make_plane(v[0]->win.z, v[1]->win.z, v[2]->win.z, r.z);
  r.z[0][t] += depth_offset;
  make_plane(v[0]->win.w, v[1]->win.w, v[2]->win.w, r.oow);

  // A small triangle (most of a detailed model's): all its centres in one region even before the bounds cut it,
  // so its vertices lie within a few pixels and every edge's values there fit 32 bits.
  const bool small = target.samples == 1 && LastCentre(maxX) - (FirstCentre(minX) & ~std::int64_t(1)) < 8 &&
                     LastCentre(maxY) - (FirstCentre(minY) & ~std::int64_t(1)) < 8;
  r.small = (r.small & ~(1u << t)) | (std::uint32_t(small) << t);
  if (small) {
    const std::int64_t qx = px0 & ~std::int64_t(1), qy = py0 & ~std::int64_t(1);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const std::int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
      const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);  // RasterizeTriangle's edges, below
      r.c00[i][t] = std::int32_t(-dy * (qx * kOne + kHalf - X[i]) + dx * (qy * kOne + kHalf - Y[i]) - (owns_ties ? 0 : 1));
      r.sx[i][t] = std::int32_t(-dy * kOne);
      r.sy[i][t] = std::int32_t(dx * kOne);
    }
  }
  return true;
}

// Coverage of a set-up triangle, its quads into `blocks`.
// (Lane t of `r`, read in place.)
void CoverTriangle(const SetUpRows& r, int t, bool front_facing, const RasterTarget& target, BlockBuffer& blocks,
                   const BlockSink& sink) {
  const std::int64_t px0 = r.px0[t], px1 = r.px1[t], py0 = r.py0[t], py1 = r.py1[t];
  const float x0 = r.x0[t], y0 = r.y0[t], dx1 = r.dx1[t], dy1 = r.dy1[t], dx2 = r.dx2[t], dy2 = r.dy2[t],
              inv_det = r.inv_det[t];
  const int nvar = target.nvar;
  TrianglePlanes planes;  // position and depth now; the varyings' planes once a quad is emitted
  planes.x0 = x0;
  planes.y0 = y0;
  planes.nvar = nvar;
  planes.z = Plane{r.z[0][t], r.z[1][t], r.z[2][t]};
  planes.oow = Plane{r.oow[0][t], r.oow[1][t], r.oow[2][t]};
  // Hierarchical depth: a triangle whose depths over its box cannot pass the depth test there is dropped now.
  HierarchicalDepth* const hz = target.depth_bounds;
  if (hz && hz->Worth() && HiddenTriangle(*hz, planes.z, x0, y0, int(px0), int(py0), int(px1), int(py1))) return;
  // The varyings' planes four at a time, each lane make_plane's operations in its order.
  auto varying_planes = [&](TrianglePlanes& p) {
    using F4 = V<4>::F;
    alignas(16) float a[3][kMaxVaryingFloats + 4];
    for (int k = 0; k < 3; ++k) {
      if (nvar > 0) std::memcpy(a[k], r.var[k][t], sizeof(float) * std::size_t(nvar));  // (var may be null)
      std::memset(a[k] + nvar, 0, sizeof(float) * 4);  // the last group's unused lanes
    }
    for (int i = 0; i < nvar; i += 4) {
      const F4 a0 = LoadVec<F4>(a[0] + i), da1 = LoadVec<F4>(a[1] + i) - a0, da2 = LoadVec<F4>(a[2] + i) - a0;
      StoreVec(p.a0 + i, a0);
      StoreVec(p.dx + i, (da1 * dy2 - da2 * dy1) * inv_det);
      StoreVec(p.dy + i, (da2 * dx1 - da1 * dx2) * inv_det);
    }
    for (int i = 0; i < nvar; ++i) {
      p.perspective[i] = Perspective(target, i);
      if (target.interpolation && target.interpolation[i] == Interpolation::kFlat)
        p.dx[i] = p.dy[i] = 0.0f;  // every vertex carries the provoking vertex's value
    }
  };

  // Hierarchical traversal: 8x8 pixel regions first. An edge function is linear, so over a region it is largest and
  // smallest at the region's corner pixel centres: a region some edge excludes at all four corners is skipped, a
  // region every edge includes at all four corners is covered whole, and only the others are tested per pixel,
  // from edge values stepped incrementally. Every pixel's coverage is the same exact integer test as a
  // pixel-by-pixel walk; quads come out region by region (each pixel of a triangle once, so the order does not
  // change the image).
  constexpr int kRegion = 8;
  const Rect& bounds = target.bounds;
  static const CoverageFn region_coverage = SOFTGL_CHOOSE(RegionCoverage);
  PlanesEntry entry;
  const OpenBlock open(blocks);
  // The quads of a region's coverage (RegionCoverage's order), each with its lanes.
  auto emit_region = [&](int rx, int ry, std::uint64_t cover) {
    while (cover) {
      const int q = __builtin_ctzll(cover) >> 2;
      const unsigned mask = unsigned(cover >> (4 * q)) & 0xFu;
      cover &= ~(std::uint64_t(0xF) << (4 * q));
      int slot;
      const int b = AddQuad(blocks, sink, front_facing, nvar, rx + (q & 3) * 2, ry + (q >> 2) * 2, mask, slot, open);
      blocks.quad_planes[b][slot] = entry.For(blocks, planes, varying_planes);
    }
  };
  // Regions start at the first quad of the box (quads are at even pixels; a block takes quads anywhere), so that a
  // triangle of at most 8x8 pixel centres is one region wherever it lies.
  const std::int64_t qx_first = px0 & ~std::int64_t(1), qy_first = py0 & ~std::int64_t(1);
  if (r.small >> t & 1u) {
    // A small triangle: one coverage test of the three edges, cut to the box; no corner tests.
    RegionEdges edges;
    edges.count = 3;
    for (int e = 0; e < 3; ++e) {
      edges.c00[e] = r.c00[e][t];
      edges.sx[e] = r.sx[e][t];
      edges.sy[e] = r.sy[e][t];
    }
    edges.row0 = 0;
    edges.row1 = int(py1 - qy_first) >> 1;
    const std::uint64_t cover = region_coverage(edges) & RegionRect(int(px0 - qx_first), int(px1 - qx_first) + 1,
                                                                    int(py0 - qy_first), int(py1 - qy_first) + 1);
    emit_region(int(qx_first), int(qy_first), cover);
    return;
  }

  // Edge i runs from vertex i to vertex i+1; E(p) = A (px - Xa) + B (py - Ya) is > 0 inside.
  const std::int64_t X[3] = {r.X[0][t], r.X[1][t], r.X[2][t]}, Y[3] = {r.Y[0][t], r.Y[1][t], r.Y[2][t]};
  const std::int64_t minX = r.minX[t], maxX = r.maxX[t], minY = r.minY[t], maxY = r.maxY[t];
  std::int64_t A[3], B[3], C[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    A[i] = -dy;
    B[i] = dx;
    // E at the origin of the fixed-point grid, with the tie rule folded in: left and bottom edges own centres
    // that lie exactly on them; for the others, E must be strictly positive.
    const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);
    C[i] = -A[i] * X[i] - B[i] * Y[i] - (owns_ties ? 0 : 1);
  }
  std::int64_t step_x[3], step_y[3];  // E(px + 1) - E(px), E(py + 1) - E(py)
  for (int e = 0; e < 3; ++e) {
    step_x[e] = A[e] * kOne;
    step_y[e] = B[e] * kOne;
  }
  auto edge_at = [&](int e, std::int64_t px, std::int64_t py) {
    return A[e] * (px * kOne + kHalf) + B[e] * (py * kOne + kHalf) + C[e];
  };
  if (target.samples > 1) {
    const SampleSpan& span = SampleSpan::Of(target.samples);
    const bool small = LastAt(maxX, span.x0) - (FirstAt(minX, span.x1) & ~std::int64_t(1)) < kRegion &&
                       LastAt(maxY, span.y0) - (FirstAt(minY, span.y1) & ~std::int64_t(1)) < kRegion;
    // One instance per sample count, so that the loops over the samples have a fixed length.
    auto rasterize = [&](auto count) {
      constexpr int kSamples = decltype(count)::value;
      static const SampleOffsets<kSamples> kOffsets;
      for (int s = 0; s < kSamples; ++s) planes.sample_dz[s] = planes.z.dx * kOffsets.x[s] + planes.z.dy * kOffsets.y[s];
      auto emit = [&](int qx, int qy, unsigned mask, const std::uint64_t* cover, int shift) {
        int slot;
        const int b = AddQuad(blocks, sink, front_facing, nvar, qx, qy, mask, slot, open, false);
        blocks.quad_planes[b][slot] = entry.For(blocks, planes, varying_planes);
        // (a new slot's sample bits are 0)
        std::uint32_t* live = blocks.sample_live[b];
        if constexpr (kSamples % 4 == 0) {  // four samples to a vector
          using D2 = V<2>::D;
          using U2 = V<2>::U;
          using U4 = V<4>::U;
          for (int g = 0; g < kSamples; g += 4) {
            const U2 lo = __builtin_convertvector(LoadVec<D2>(cover + g) >> shift, U2);
            const U2 hi = __builtin_convertvector(LoadVec<D2>(cover + g + 2) >> shift, U2);
            const U4 bits = (__builtin_shufflevector(lo, hi, 0, 1, 2, 3) & 0xFu) << (4 * slot);
            StoreVec(live + g, LoadVec<U4>(live + g) | bits);
          }
        } else {
          for (int s = 0; s < kSamples; ++s) live[s] |= (std::uint32_t(cover[s] >> shift) & 0xFu) << (4 * slot);
        }
      };
      auto square = [&](int bx, int by) {
        const int b = AddSquare(blocks, sink, front_facing, nvar, bx, by);
        const TrianglePlanes* stored = entry.For(blocks, planes, varying_planes);
        for (int q = 0; q < 4; ++q) blocks.quad_planes[b][q] = stored;
      };
      const Rect box{int(px0), int(py0), int(px1) + 1, int(py1) + 1};
#if defined(SOFTGL_HAS_DISPATCH)
      switch (CpuSimdLevel()) {
        case SimdLevel::kAvx512: return RasterizeSamplesAvx512<kSamples>(A, B, C, box, small, emit, square);
        case SimdLevel::kAvx2: return RasterizeSamplesAvx2<kSamples>(A, B, C, box, small, emit, square);
        default: break;
      }
#endif
      RasterizeSamplesBase<kSamples>(A, B, C, box, small, emit, square);
    };
    if (target.samples == 2) rasterize(std::integral_constant<int, 2>{});
    else if (target.samples == 4) rasterize(std::integral_constant<int, 4>{});
    else rasterize(std::integral_constant<int, 8>{});
    return;
  }
  // Edges no steeper than 2^26 (a side of at most 1024 pixels in x and y) keep a region's edge values in 32 bits.
  bool narrow = true;
  for (int e = 0; e < 3; ++e) {
    constexpr std::int64_t kLimit = std::int64_t(1) << 26;
    narrow = narrow && step_x[e] <= kLimit && step_x[e] >= -kLimit && step_y[e] <= kLimit && step_y[e] >= -kLimit;
  }
  // The smallest and largest of an edge's values at a region's four corner pixels, less its value at the first.
  std::int64_t corner_min[3], corner_max[3];
  for (int e = 0; e < 3; ++e) {
    const std::int64_t dx = step_x[e] * (kRegion - 1), dy = step_y[e] * (kRegion - 1);
    corner_min[e] = std::min<std::int64_t>(dx, 0) + std::min<std::int64_t>(dy, 0);
    corner_max[e] = std::max<std::int64_t>(dx, 0) + std::max<std::int64_t>(dy, 0);
  }
  // Each edge at the first pixel of a row's first region, then of each region, stepped (exact integers).
  std::int64_t row_start[3], at[3];
  for (int e = 0; e < 3; ++e) row_start[e] = edge_at(e, qx_first, qy_first);
  for (std::int64_t ry = qy_first; ry <= py1; ry += kRegion) {
    for (int e = 0; e < 3; ++e) {
      at[e] = row_start[e];
      row_start[e] += step_y[e] * kRegion;
    }
    for (std::int64_t rx = qx_first; rx <= px1; rx += kRegion) {
      bool skip = false, whole = true;
      std::int64_t corner[3], corner_lo[3];
      const std::int64_t here[3] = {at[0], at[1], at[2]};
      for (int e = 0; e < 3; ++e) at[e] += step_x[e] * kRegion;
      for (int e = 0; e < 3 && !skip; ++e) {
        const std::int64_t c00 = here[e], lo = c00 + corner_min[e], hi = c00 + corner_max[e];
        if (hi < 0) skip = true;
        if (lo < 0) whole = false;
        corner[e] = c00;
        corner_lo[e] = lo;
      }
      if (skip) continue;
      if (hz && hz->Worth() && HiddenRegion(*hz, planes.z, x0, y0, int(std::max(rx, px0)), int(std::max(ry, py0)),
                             int(std::min(rx + kRegion - 1, px1)), int(std::min(ry + kRegion - 1, py1))))
        continue;  // the region's pixels of the box lie behind what the tile holds there
      if (whole && rx >= bounds.x0 && rx + kRegion <= bounds.x1 && ry >= bounds.y0 && ry + kRegion <= bounds.y1) {
        // Covered whole, inside the bounds: four full blocks.
        for (int sq = 0; sq < 4; ++sq) {
          const int b = AddSquare(blocks, sink, front_facing, nvar, int(rx) + (sq & 1) * 4, int(ry) + (sq >> 1) * 4);
          const TrianglePlanes* stored = entry.For(blocks, planes, varying_planes);
          for (int q = 0; q < 4; ++q) blocks.quad_planes[b][q] = stored;
        }
        continue;
      }
      if (narrow) {
        // The edges that cross the region, tested 64 pixels at a time; the quads in order, each with its lanes.
        RegionEdges edges;
        for (int e = 0; e < 3; ++e) {
          if (corner_lo[e] >= 0) continue;
          edges.c00[edges.count] = std::int32_t(corner[e]);
          edges.sx[edges.count] = std::int32_t(step_x[e]);
          edges.sy[edges.count] = std::int32_t(step_y[e]);
          ++edges.count;
        }
        edges.row0 = int((std::max(ry, py0) - ry) >> 1);
        edges.row1 = int((std::min(ry + kRegion - 1, py1) - ry) >> 1);
        std::uint64_t cover = region_coverage(edges);
        if (rx < bounds.x0 || rx + kRegion > bounds.x1 || ry < bounds.y0 || ry + kRegion > bounds.y1)
          cover &= RegionRect(int(std::max<std::int64_t>(bounds.x0 - rx, 0)), int(std::min<std::int64_t>(bounds.x1 - rx, kRegion)),
                              int(std::max<std::int64_t>(bounds.y0 - ry, 0)), int(std::min<std::int64_t>(bounds.y1 - ry, kRegion)));
        emit_region(int(rx), int(ry), cover);
        continue;
      }
      const std::int64_t qy0 = std::max(ry, py0 & ~std::int64_t(1)), qy1 = std::min(ry + kRegion - 1, py1);
      const std::int64_t qx0 = std::max(rx, px0 & ~std::int64_t(1)), qx1 = std::min(rx + kRegion - 1, px1);
      for (std::int64_t qy = qy0; qy <= qy1; qy += 2) {
        std::int64_t row[3];
        for (int e = 0; e < 3; ++e) row[e] = edge_at(e, qx0, qy);
        for (std::int64_t qx = qx0; qx <= qx1; qx += 2) {
          unsigned mask = 0xFu;
          if (!whole) {
            mask = 0;
            for (int lane = 0; lane < 4; ++lane) {
              bool inside = true;
              for (int e = 0; e < 3; ++e)
                inside = inside && row[e] + (lane & 1) * step_x[e] + (lane >> 1) * step_y[e] >= 0;
              if (inside) mask |= 1u << lane;
            }
            for (int e = 0; e < 3; ++e) row[e] += 2 * step_x[e];
          }
          if (qx < bounds.x0 || qx + 1 >= bounds.x1 || qy < bounds.y0 || qy + 1 >= bounds.y1)
            mask &= BoundsMask(bounds, int(qx), int(qy));
          if (!mask) continue;
          int slot;
          const int b = AddQuad(blocks, sink, front_facing, nvar, int(qx), int(qy), mask, slot, open);
          blocks.quad_planes[b][slot] = entry.For(blocks, planes, varying_planes);
        }
      }
    }
  }
}

void TriangleQuads(const VertexView& v0, const VertexView& v1, const VertexView& v2, bool front_facing,
                   const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink) {
  SetUpRows r;
  if (SetUpTriangle(v0, v1, v2, target.depth_offset, target, r, 0)) CoverTriangle(r, 0, front_facing, target, blocks, sink);
}

// W lanes from l0 of SetUpTriangle's arithmetic, the same operations in the same order on each lane (float lanes
// give the same bits; the integers are exact).
template <int W>
SOFTGL_WIDE void SetUpLanes(const TriangleQueue& in, const RasterTarget& target, int l0, SetUpRows& out) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  using U = typename V<W>::U;
  auto select = [](I m, auto a, auto b) SOFTGL_WIDE_LAMBDA {
    using T = decltype(a);
    return T((I(a) & m) | (I(b) & ~m));
  };
  auto min = [&](I a, I b) SOFTGL_WIDE_LAMBDA { return select(a < b, a, b); };
  auto max = [&](I a, I b) SOFTGL_WIDE_LAMBDA { return select(a > b, a, b); };
  F x[3], y[3], z[3], w[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = LoadVec<F>(in.x[k] + l0);
    y[k] = LoadVec<F>(in.y[k] + l0);
    z[k] = LoadVec<F>(in.z[k] + l0);
    w[k] = LoadVec<F>(in.w[k] + l0);
  }
  I exact = ~I{}, X[3], Y[3];
  for (int k = 0; k < 3; ++k) exact = exact & SnapLanes<W>(x[k], y[k], X[k], Y[k]);  // (Snap's values, in range)
  auto short_side = [](I d) SOFTGL_WIDE_LAMBDA { return I(d < 32768) & I(d > -32768); };
  const I handled = exact & short_side(X[1] - X[0]) & short_side(Y[1] - Y[0]) & short_side(X[2] - X[0]) &
                    short_side(Y[2] - Y[0]);
  // SnappedArea: each product below 2^30 in magnitude where handled (computed unsigned: the others may wrap).
  const I signed_area = I(U(X[1] - X[0]) * U(Y[2] - Y[0]) - U(X[2] - X[0]) * U(Y[1] - Y[0]));
  const I swap = signed_area < 0;  // counter-clockwise order: vertices 1 and 2 exchanged
  const I area = I(select(swap, U{} - U(signed_area), U(signed_area)));  // (unsigned: no lane overflows)
  {
    const I X1 = X[1], Y1 = Y[1];
    X[1] = select(swap, X[2], X1);
    X[2] = select(swap, X1, X[2]);
    Y[1] = select(swap, Y[2], Y1);
    Y[2] = select(swap, Y1, Y[2]);
    const F f[4][2] = {{x[1], x[2]}, {y[1], y[2]}, {z[1], z[2]}, {w[1], w[2]}};
    x[1] = select(swap, f[0][1], f[0][0]);
    x[2] = select(swap, f[0][0], f[0][1]);
    y[1] = select(swap, f[1][1], f[1][0]);
    y[2] = select(swap, f[1][0], f[1][1]);
    z[1] = select(swap, f[2][1], f[2][0]);
    z[2] = select(swap, f[2][0], f[2][1]);
    w[1] = select(swap, f[3][1], f[3][0]);
    w[2] = select(swap, f[3][0], f[3][1]);
  }
  const I minX = min(min(X[0], X[1]), X[2]), maxX = max(max(X[0], X[1]), X[2]);
  const I minY = min(min(Y[0], Y[1]), Y[2]), maxY = max(max(Y[0], Y[1]), Y[2]);
  const SampleSpan& span = SampleSpan::Of(target.samples);
  // FirstAt and LastAt, cut to the bounds.
  const I px0 = max(-((std::int32_t(span.x1) - minX) >> kSubpixelBits), I{} + target.bounds.x0);
  const I px1 = min((maxX - std::int32_t(span.x0)) >> kSubpixelBits, I{} + (target.bounds.x1 - 1));
  const I py0 = max(-((std::int32_t(span.y1) - minY) >> kSubpixelBits), I{} + target.bounds.y0);
  const I py1 = min((maxY - std::int32_t(span.y0)) >> kSubpixelBits, I{} + (target.bounds.y1 - 1));
  const I drawn = handled & (area != 0) & (px0 <= px1) & (py0 <= py1);

  // The planes, relative to vertex 0: from the float positions, or the snapped ones where float rounding
  // disagrees with the exact area.
  F dx1 = x[1] - x[0], dy1 = y[1] - y[0], dx2 = x[2] - x[0], dy2 = y[2] - y[0];
  F det = dx1 * dy2 - dx2 * dy1;
  const I bad = ~I(det > 0.0f);
  const float kOneF = float(kOne);
  dx1 = select(bad, __builtin_convertvector(X[1] - X[0], F) / kOneF, dx1);
  dy1 = select(bad, __builtin_convertvector(Y[1] - Y[0], F) / kOneF, dy1);
  dx2 = select(bad, __builtin_convertvector(X[2] - X[0], F) / kOneF, dx2);
  dy2 = select(bad, __builtin_convertvector(Y[2] - Y[0], F) / kOneF, dy2);
  det = select(bad, __builtin_convertvector(area, F) / float(kOne * kOne), det);
  const F inv_det = 1.0f / det;
  auto plane = [&](const F* a, float (*rows)[kTriangleGroup]) SOFTGL_WIDE_LAMBDA {
    const F da1 = a[1] - a[0], da2 = a[2] - a[0];
    StoreVec(rows[0] + l0, a[0]);
    StoreVec(rows[1] + l0, (da1 * dy2 - da2 * dy1) * inv_det);
    StoreVec(rows[2] + l0, (da2 * dx1 - da1 * dx2) * inv_det);
  };
  plane(z, out.z);
  StoreVec(out.z[0] + l0, LoadVec<F>(out.z[0] + l0) + LoadVec<F>(in.depth_offset + l0));
  plane(w, out.oow);

  // A small triangle's edges at the box's first quad (SetUpTriangle's), exact where small.
  I small{};
  if (target.samples == 1) {
    auto first_centre = [](I lo) SOFTGL_WIDE_LAMBDA { return -((std::int32_t(kHalf) - lo) >> kSubpixelBits); };
    auto last_centre = [](I hi) SOFTGL_WIDE_LAMBDA { return (hi - std::int32_t(kHalf)) >> kSubpixelBits; };
    small = drawn & I(last_centre(maxX) - (first_centre(minX) & ~1) < 8) &
            I(last_centre(maxY) - (first_centre(minY) & ~1) < 8);
    const U qx = U(px0 & ~1) * std::uint32_t(kOne) + std::uint32_t(kHalf);
    const U qy = U(py0 & ~1) * std::uint32_t(kOne) + std::uint32_t(kHalf);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const I dx = X[j] - X[i], dy = Y[j] - Y[i];
      const I owns_ties = I(dy < 0) | (I(dy == 0) & I(dx > 0));
      const U value = U(-dy) * (qx - U(X[i])) + U(dx) * (qy - U(Y[i])) - U(~owns_ties & 1);
      StoreVec(out.c00[i] + l0, I(value));
      StoreVec(out.sx[i] + l0, I(U(-dy) * std::uint32_t(kOne)));
      StoreVec(out.sy[i] + l0, I(U(dx) * std::uint32_t(kOne)));
    }
  }

  out.handled |= MaskToBits<W>(handled, l0);
  out.drawn |= MaskToBits<W>(drawn, l0);
  out.swapped |= MaskToBits<W>(swap, l0);
  out.small |= MaskToBits<W>(small, l0);
  // What only a larger triangle's coverage reads, widened to the rows' 64 bits.
  typedef std::int64_t L __attribute__((vector_size(8 * W)));
  auto wide = [](I v) SOFTGL_WIDE_LAMBDA { return __builtin_convertvector(v, L); };
  for (int k = 0; k < 3; ++k) {
    StoreVec(out.X[k] + l0, wide(X[k]));
    StoreVec(out.Y[k] + l0, wide(Y[k]));
  }
  StoreVec(out.area + l0, wide(area));
  StoreVec(out.minX + l0, wide(minX));
  StoreVec(out.maxX + l0, wide(maxX));
  StoreVec(out.minY + l0, wide(minY));
  StoreVec(out.maxY + l0, wide(maxY));
  StoreVec(out.px0 + l0, px0);
  StoreVec(out.px1 + l0, px1);
  StoreVec(out.py0 + l0, py0);
  StoreVec(out.py1 + l0, py1);
  StoreVec(out.x0 + l0, x[0]);
  StoreVec(out.y0 + l0, y[0]);
  StoreVec(out.dx1 + l0, dx1);
  StoreVec(out.dy1 + l0, dy1);
  StoreVec(out.dx2 + l0, dx2);
  StoreVec(out.dy2 + l0, dy2);
  StoreVec(out.inv_det + l0, inv_det);
}

template <int W>
SOFTGL_WIDE void SetUpGroup(const TriangleQueue& in, int n, const RasterTarget& target, SetUpRows& out) {
  for (int l0 = 0; l0 < n; l0 += W) SetUpLanes<W>(in, target, l0, out);
  const std::uint32_t used = (std::uint32_t(1) << n) - 1;
  out.handled &= used;
  out.drawn &= used;
}

using SetUpGroupFn = void (*)(const TriangleQueue&, int, const RasterTarget&, SetUpRows&);
void SetUpGroupBase(const TriangleQueue& in, int n, const RasterTarget& t, SetUpRows& out) {
  SetUpGroup<4>(in, n, t, out);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void SetUpGroupAvx2(const TriangleQueue& in, int n, const RasterTarget& t, SetUpRows& out) {
  SetUpGroup<8>(in, n, t, out);
}
// 8 lanes on AVX-512 too, with its instruction set, as the coverage kernels.
SOFTGL_TARGET_AVX512 void SetUpGroupAvx512(const TriangleQueue& in, int n, const RasterTarget& t, SetUpRows& out) {
  SetUpGroup<8>(in, n, t, out);
}
#endif

// A rectangle with corners p[0..3] in order, rasterized as the two triangles (p0, p1, p2) and (p0, p2, p3): the fill
// rule gives each sample on their shared diagonal to one of them, and the rectangle's sides own the samples on them
// as a triangle's edges do. Each corner carries the varyings `var[k]`.
void RasterizeRectangle(const glm::vec4 (&p)[4], const float* const (&var)[4], bool front_facing,
                        const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink) {
  TriangleQuads(VertexView(p[0], var[0]), VertexView(p[1], var[1]), VertexView(p[2], var[2]), front_facing, target,
                blocks, sink);
  TriangleQuads(VertexView(p[0], var[0]), VertexView(p[2], var[2]), VertexView(p[3], var[3]), front_facing, target,
                blocks, sink);
}

}  // namespace

void RasterizeTriangles(TriangleQueue& q, const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink) {
  const int n = q.count;
  q.count = 0;
  if (n <= 0) return;
  if (blocks.points) EndPoints(blocks, sink);
  // The unused lanes of the last vector set up (vectors of 4 or 8 lanes) get finite values.
  for (int t = n, end = std::min(kTriangleGroup, (n + 7) & ~7); t < end; ++t)
    for (int k = 0; k < 3; ++k) q.x[k][t] = q.y[k][t] = q.z[k][t] = q.w[k][t] = q.depth_offset[t] = 0.0f;
  static const SetUpGroupFn set_up = SOFTGL_CHOOSE(SetUpGroup);
  SetUpRows rows;
  if (n > 1) set_up(q, n, target, rows);
  else rows.handled = 0;  // one triangle (a tile's only one of a draw): set up alone, for less than a vector costs
  for (int t = 0; t < n; ++t) {
    if (rows.handled >> t & 1u) {
      if (!(rows.drawn >> t & 1u)) continue;
      const bool swapped = rows.swapped >> t & 1u;
      rows.var[0][t] = q.var[0][t];
      rows.var[1][t] = q.var[swapped ? 2 : 1][t];
      rows.var[2][t] = q.var[swapped ? 1 : 2][t];
    } else {
      VertexView v[3];
      for (int k = 0; k < 3; ++k) v[k] = VertexView(glm::vec4(q.x[k][t], q.y[k][t], q.z[k][t], q.w[k][t]), q.var[k][t]);
      if (!SetUpTriangle(v[0], v[1], v[2], q.depth_offset[t], target, rows, t)) continue;
    }
    CoverTriangle(rows, t, q.front_facing[t], target, blocks, sink);
  }
}

void RasterizeLine(const WindowVertex& a, const WindowVertex& b, bool front_facing, const RasterTarget& target,
                   BlockBuffer& blocks, const BlockSink& sink) {
  if (blocks.points) EndPoints(blocks, sink);
  const float ax = a.win.x, ay = a.win.y, dx = b.win.x - ax, dy = b.win.y - ay;
  if (!(std::fabs(ax) < 1e7f && std::fabs(ay) < 1e7f && std::fabs(dx) < 1e7f && std::fabs(dy) < 1e7f)) return;
  const float len2 = dx * dx + dy * dy;
  if (len2 == 0.0f) return;
  const int nvar = target.nvar;
  if (target.samples > 1) {
    // Multisampled (OpenGL 4.6, section 14.5.4): the samples inside the rectangle of width 1 along the segment,
    // its long sides half a pixel either side. Depth and varyings vary along the segment alone, as at the point
    // of the segment nearest to each position: the same at the two corners of each end.
    // The ends and the half-width offset are each snapped to the subpixel grid, then added: a parallelogram on the
    // grid whose sides stay parallel (the rasterizer then snaps nothing further).
    auto snap = [](float f) { return float(RoundToInt64(double(f) * double(kOne))) / float(kOne); };
    const float scale = 0.5f * std::max(target.line_width, 1.0f) / std::sqrt(len2);
    const glm::vec4 n(snap(-dy * scale), snap(dx * scale), 0.0f, 0.0f);
    const glm::vec4 sa(snap(a.win.x), snap(a.win.y), a.win.z, a.win.w), sb(snap(b.win.x), snap(b.win.y), b.win.z, b.win.w);
    const glm::vec4 corners[4] = {sa + n, sa - n, sb - n, sb + n};
    const float* const var[4] = {a.var, a.var, b.var, b.var};
    RasterizeRectangle(corners, var, front_facing, target, blocks, sink);
    return;
  }

  // Varyings at the point of the segment nearest to the pixel centre (OpenGL's t, section 14.5.1).
  auto eval = [&](int px, int py, float* frag, float* out) {
    const float fx = float(px) + 0.5f, fy = float(py) + 0.5f;
    const float t = std::clamp(((fx - ax) * dx + (fy - ay) * dy) / len2, 0.0f, 1.0f);
    const float q = a.win.w + t * (b.win.w - a.win.w);
    const float w = 1.0f / q;
    frag[0] = fx;
    frag[1] = fy;
    frag[2] = a.win.z + t * (b.win.z - a.win.z) + target.depth_offset;
    frag[3] = q;
    for (int i = 0; i < nvar; ++i) {
      const float v = a.var[i] + t * (b.var[i] - a.var[i]);
      out[i] = Perspective(target, i) ? v * w : v;
    }
  };

  // The diamond-exit rule (OpenGL 4.6, section 14.5.1): pixel f is drawn when the segment leaves its diamond
  // |x - xf| + |y - yf| < 1/2. Along the major axis u that is one fragment per pixel centre u_c in the half-open
  // span [u_start, u_end) (in the direction of travel); besides, a start point strictly inside its pixel's diamond
  // draws that pixel, and an end point strictly inside its diamond does not.
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  const float u0 = x_major ? ax : ay, du = x_major ? dx : dy;
  const float v0 = x_major ? ay : ax, dv = x_major ? dy : dx;
  auto inside_diamond = [](float x, float y) {
    return std::fabs(x - std::floor(x) - 0.5f) + std::fabs(y - std::floor(y) - 0.5f) < 0.5f;
  };
  long first, last;  // inclusive range of major-axis pixel indices, in increasing order
  if (du > 0.0f) {
    first = long(std::ceil(u0 - 0.5f));
    last = long(std::ceil(u0 + du - 0.5f)) - 1;
    if (inside_diamond(ax, ay)) first = std::min(first, long(std::floor(u0)));
    if (inside_diamond(b.win.x, b.win.y)) last = std::min(last, long(std::floor(u0 + du)) - 1);
  } else {
    first = long(std::floor(u0 + du - 0.5f)) + 1;
    last = long(std::floor(u0 - 0.5f));
    if (inside_diamond(ax, ay)) last = std::max(last, long(std::floor(u0)));
    if (inside_diamond(b.win.x, b.win.y)) first = std::max(first, long(std::floor(u0 + du)) + 1);
  }
  // Keep the walk inside the target bounds.
  const long lo = x_major ? target.bounds.x0 : target.bounds.y0, hi = (x_major ? target.bounds.x1 : target.bounds.y1) - 1;
  first = std::max(first, lo);
  last = std::min(last, hi);
  if (const float width = std::round(target.line_width); width >= 2.0f && first <= last) {
    // A wide line (OpenGL 4.6, section 14.5.2.1): columns (rows) first .. last, each `width` fragments centred on
    // the line: the parallelogram between the line moved width / 2 either way across its major axis, cut to those
    // columns by the bounds. Its long sides are the segment extended to 2a - b and 2b - a, moved by a multiple of
    // 1/2: on the subpixel grid when the ends are, so that the fill rule decides centres on them exactly. Its
    // corners take depth, 1/w and varyings at their projection on the segment (the triangles' planes then give each
    // fragment the values at its centre's projection).
    const float half = width * 0.5f;
    const glm::vec2 ends[2] = {glm::vec2(ax - dx, ay - dy), glm::vec2(b.win.x + dx, b.win.y + dy)};
    const glm::vec2 across = x_major ? glm::vec2(0.0f, half) : glm::vec2(half, 0.0f);
    float var[4][kMaxVaryingFloats];
    glm::vec4 p[4];
    for (int k = 0; k < 4; ++k) {
      const glm::vec2 c = ends[k == 1 || k == 2] + (k < 2 ? -across : across);  // (around the parallelogram)
      const float t = ((c.x - ax) * dx + (c.y - ay) * dy) / len2;
      p[k] = glm::vec4(c, a.win.z + t * (b.win.z - a.win.z), a.win.w + t * (b.win.w - a.win.w));
      for (int i = 0; i < nvar; ++i) var[k][i] = a.var[i] + t * (b.var[i] - a.var[i]);
    }
    RasterTarget columns = target;
    (x_major ? columns.bounds.x0 : columns.bounds.y0) = int(first);  // (first and last lie inside the bounds)
    (x_major ? columns.bounds.x1 : columns.bounds.y1) = int(last + 1);
    const float* const vars[4] = {var[0], var[1], var[2], var[3]};
    RasterizeRectangle(p, vars, front_facing, columns, blocks, sink);
    return;
  }
  // Where the line passes exactly between two pixel centres of a column (row), the pixel on the side that a
  // one-pixel-wide parallelogram around the line owns under the fill rule is taken: for x-major lines the upper
  // one when the line rises, else the lower one; for y-major lines the left one.
  const bool upper_on_tie = x_major && dv > 0.0f;
  int last_block = -1, last_slot = -1;  // the last quad this line emitted, while it is still in the buffer
  for (long i = first; i <= last; ++i) {
    const float uc = float(i) + 0.5f;
    const float vc = v0 + (uc - u0) * dv / du;
    const long j = upper_on_tie ? long(std::floor(vc)) : long(std::ceil(vc)) - 1;
    const int px = int(x_major ? i : j), py = int(x_major ? j : i);
    if (px < target.bounds.x0 || px >= target.bounds.x1 || py < target.bounds.y0 || py >= target.bounds.y1) continue;
    const int qx = px & ~1, qy = py & ~1;
    const unsigned lane = unsigned((px & 1) + 2 * (py & 1));
    // Neighbouring fragments of the same 2x2 quad share one quad.
    if (last_block >= 0 && last_block == blocks.count - 1 && last_slot == blocks.quads[last_block] - 1 &&
        blocks.qx[last_block][last_slot] == qx && blocks.qy[last_block][last_slot] == qy) {
      blocks.live[last_block] |= 1u << (4 * last_slot + int(lane));
      for (int s = 0; s < blocks.samples; ++s) blocks.sample_live[last_block][s] |= 1u << (4 * last_slot + int(lane));
      continue;
    }
    last_block = EmitQuad(blocks, sink, front_facing, nvar, qx, qy, 1u << lane, eval);
    last_slot = blocks.quads[last_block] - 1;
  }
}

void RasterizePoint(const WindowVertex& v, float size, bool front_facing, const RasterTarget& target,
                    BlockBuffer& blocks, const BlockSink& sink) {
  if (!(size > 0.0f) || !(std::fabs(v.win.x) < 1e7f) || !(std::fabs(v.win.y) < 1e7f)) return;
  const float half = std::min(size, 1e6f) * 0.5f;
  if (!blocks.points) {  // (a point's quads never share the buffer with another primitive's)
    sink.Flush(blocks);
    blocks.points = true;
  }
  blocks.point = PointSprite{v.win.x, v.win.y, 0.5f / half, target.point_lower_left ? 1.0f : -1.0f};
  if (target.samples > 1) {
    // Multisampled (OpenGL 4.6, section 14.4.3, point sprites as in the core profile): the samples inside the
    // square of side `size` centred on the point.
    const glm::vec4 corners[4] = {v.win + glm::vec4(-half, -half, 0, 0), v.win + glm::vec4(half, -half, 0, 0),
                                  v.win + glm::vec4(half, half, 0, 0), v.win + glm::vec4(-half, half, 0, 0)};
    const float* const var[4] = {v.var, v.var, v.var, v.var};
    RasterizeRectangle(corners, var, front_facing, target, blocks, sink);
    return;
  }
  const long x0 = std::max<long>(long(std::ceil(v.win.x - half - 0.5f)), target.bounds.x0);
  const long x1 = std::min<long>(long(std::ceil(v.win.x + half - 0.5f)) - 1, target.bounds.x1 - 1);
  const long y0 = std::max<long>(long(std::ceil(v.win.y - half - 0.5f)), target.bounds.y0);
  const long y1 = std::min<long>(long(std::ceil(v.win.y + half - 0.5f)) - 1, target.bounds.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const int nvar = target.nvar;
  const float w = 1.0f / v.win.w;
  auto eval = [&](int px, int py, float* frag, float* out) {
    frag[0] = float(px) + 0.5f;
    frag[1] = float(py) + 0.5f;
    frag[2] = v.win.z + target.depth_offset;
    frag[3] = v.win.w;
    for (int i = 0; i < nvar; ++i) out[i] = Perspective(target, i) ? v.var[i] * w : v.var[i];
  };
  for (long qy = y0 & ~1L; qy <= y1; qy += 2) {
    for (long qx = x0 & ~1L; qx <= x1; qx += 2) {
      unsigned mask = 0;
      for (int lane = 0; lane < 4; ++lane) {
        const long px = qx + (lane & 1), py = qy + (lane >> 1);
        if (px >= x0 && px <= x1 && py >= y0 && py <= y1) mask |= 1u << lane;
      }
      if (mask) EmitQuad(blocks, sink, front_facing, nvar, int(qx), int(qy), mask, eval);
    }
  }
}

}  // namespace softgl::detail

namespace softgl::detail {

void InterpolateFragCoords(BlockBuffer& blocks) {
  static const BlockFn frag_coord_of_block = SOFTGL_CHOOSE(FragCoordOfBlock);
  for (int b = 0; b < blocks.count; ++b) frag_coord_of_block(blocks, b);
}

void InterpolateAtSample(BlockBuffer& blocks, int s) {
  const auto* pos = SamplePositions(blocks.samples);
  const float ox = float(pos[s][0]) / 16.0f, oy = float(pos[s][1]) / 16.0f;
  for (int b = 0; b < blocks.count; ++b) {
    float* var = blocks.Varyings(b);
    for (int lane = 0; lane < kLanes; ++lane) {  // helper lanes too: a quad's derivatives come from one position
      const TrianglePlanes* p = blocks.quad_planes[b][lane >> 2];
      if (!p) continue;
      const float rx = (float(blocks.X(b, lane)) + ox) - p->x0, ry = (float(blocks.Y(b, lane)) + oy) - p->y0;
      const float w = 1.0f / ((p->oow.a0 + p->oow.dx * rx) + p->oow.dy * ry);
      for (int i = 0; i < p->nvar; ++i) {
        const float v = (p->a0[i] + p->dx[i] * rx) + p->dy[i] * ry;
        var[i * kLanes + lane] = p->perspective[i] ? v * w : v;
      }
    }
  }
}

void InterpolateCentroids(BlockBuffer& blocks, const std::int8_t (*centroid)[kLanes], const Interpolation* modes) {
  const auto* pos = SamplePositions(blocks.samples);
  for (int b = 0; b < blocks.count; ++b) {
    float* var = blocks.Varyings(b);
    for (int lane = 0; lane < kLanes; ++lane) {
      const int s = centroid[b][lane];
      const TrianglePlanes* p = blocks.quad_planes[b][lane >> 2];
      if (s < 0 || !p || !((blocks.live[b] >> lane) & 1u)) continue;
      const float rx = (float(blocks.X(b, lane)) + float(pos[s][0]) / 16.0f) - p->x0;
      const float ry = (float(blocks.Y(b, lane)) + float(pos[s][1]) / 16.0f) - p->y0;
      const float w = 1.0f / ((p->oow.a0 + p->oow.dx * rx) + p->oow.dy * ry);
      for (int i = 0; i < p->nvar; ++i)
        if (modes[i] == Interpolation::kCentroid) var[i * kLanes + lane] = ((p->a0[i] + p->dx[i] * rx) + p->dy[i] * ry) * w;
    }
  }
}

void InterpolateVaryings(BlockBuffer& blocks) {
  static const BlockFn varyings_of_block = SOFTGL_CHOOSE(VaryingsOfBlock);
  for (int b = 0; b < blocks.count; ++b)
    if (blocks.live[b]) varyings_of_block(blocks, b);
}

}  // namespace softgl::detail

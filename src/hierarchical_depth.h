// hierarchical_depth.h — part of stage 7 (rasterization): the coarse depth of one tile, and the test that drops a
// triangle, or an 8x8 region of one, whose fragments cannot pass the depth test there, before coverage,
// interpolation and shading.
//
// Each 8x8 pixel block of the tile keeps the nearest and the farthest depth its pixels hold (`lo`, `hi`), read from
// the depth buffer when a test first asks for the block, and again every kAsks asks (to follow what drawing
// changed); a clear of the whole tile sets them all to the clear value, with nothing to read. Writes by a depth
// test LESS or LEQUAL only bring depths nearer, which leaves `hi` a bound (a looser one) and may leave `lo` wrong;
// GREATER and GEQUAL the other way round; any other comparison, and a clear of part of the tile, both. The tile
// renderer says which after each draw (Wrote) and at each clear (Cleared, TouchAll); a bound that may be wrong
// makes every block of the tile read again before it is used. So the bounds hold under every depth function,
// write mask and clear, and cost nothing where no triangle asks.
//
// A triangle's fragment depths over a pixel rectangle are bounded by its depth plane at the rectangle's corners,
// widened by the most that the per-fragment float evaluation of the plane can differ from the exact value. A test
// LESS (LEQUAL) fails everywhere when the nearest of them is not below (is above) the farthest stored depth;
// GREATER (GEQUAL) when the farthest is not above (is below) the nearest stored one: the rectangle holds every
// sample position of its pixels, and a multisampled buffer's bounds are over all samples. Only where the depth
// test is the early one (EarlyDepthTestApplies: one of those four, no stencil test, no shader depth).
#pragma once

#include <cstdint>
#include <cstring>

#include "binner.h"
#include "framebuffer.h"
#include "types.h"

namespace softgl::detail {

struct HierarchicalDepth {
  static constexpr int kBlock = 8;                    // pixels on a side of a bounded block
  static constexpr int kPerRow = kTileSize / kBlock;  // blocks on a side of a tile
  static constexpr int kBlocks = kPerRow * kPerRow;
  // A block's bounds are read again every kAsks tests that ask for them.
  static constexpr int kAsks = 4;
  // Tests are skipped while they do not pay: after kWindow tests in the tile that dropped fewer than kWindow / 4,
  // the next kSkip are not made.
  static constexpr int kWindow = 32, kSkip = 480;

  // The tile: its target (with a depth buffer) and the pixel rectangle it covers.
  const RenderTarget* target = nullptr;
  Rect tile;
  float lo[kBlocks], hi[kBlocks];  // StoredDepth's values: k / 65535 for a 16-bit buffer
  std::uint8_t stale[kBlocks];     // 1: read the block before using its bounds
  std::uint8_t asks[kBlocks];      // tests that asked since the block was read
  bool lo_wrong = false, hi_wrong = false;  // writes since may have moved depths past lo (nearer) or hi (farther)
  Enum func = LESS;                // the draw's comparison: LESS, LEQUAL, GREATER or GEQUAL
  int window_tested = 0, window_hidden = 0, skip = 0;
  // Statistics, since they were last taken: triangles and 8x8 regions of larger ones tested and dropped.
  std::uint64_t triangles_tested = 0, triangles_hidden = 0, regions_tested = 0, regions_hidden = 0;

  /// Starts tile `rect` of `t`: every block stale.
  void Begin(const RenderTarget& t, const Rect& rect) {
    target = &t;
    tile = rect;
    TouchAll();
    window_tested = window_hidden = skip = 0;
  }
  /// Marks every block stale (a clear, or writes that may have made a bound wrong).
  void TouchAll() {
    std::memset(stale, 1, sizeof stale);
    lo_wrong = hi_wrong = false;
  }
  /// A clear of the whole tile's depth to `stored` (as StoredDepth gives it): every block's bounds that value,
  /// read afresh, with nothing to read from the buffer.
  void Cleared(float stored) {
    if (!(stored == stored)) return TouchAll();  // (a clear value is never NaN; kept safe all the same)
    for (int i = 0; i < kBlocks; ++i) lo[i] = hi[i] = stored;
    std::memset(stale, 0, sizeof stale);
    std::memset(asks, 0, sizeof asks);
    lo_wrong = hi_wrong = false;
  }
  /// After a draw that wrote depth through comparison `depth_func`: which bound its writes may have made wrong.
  void Wrote(Enum depth_func) {
    const bool nearer = depth_func == LESS || depth_func == LEQUAL, farther = depth_func == GREATER || depth_func == GEQUAL;
    lo_wrong = lo_wrong || !farther;
    hi_wrong = hi_wrong || !nearer;
  }
  /// Whether a test is worth making now (see kWindow); when it is, Count its outcome.
  bool Worth() {
    if (skip == 0) return true;
    --skip;
    return false;
  }
  void Count(bool hidden) {
    window_hidden += hidden;
    if (++window_tested < kWindow) return;
    if (window_hidden * 4 < kWindow) skip = kSkip;
    window_tested = window_hidden = 0;
  }
  /// Whether no fragment of depth plane `z` (relative to (x0, y0), polygon offset included) inside the pixels
  /// [px0, px1] x [py0, py1] (inclusive, inside the tile) can pass the draw's depth test `func`.
  bool Hides(const Plane& z, float x0, float y0, int px0, int py0, int px1, int py1);

 private:
  void Refresh(int index);
};

}  // namespace softgl::detail

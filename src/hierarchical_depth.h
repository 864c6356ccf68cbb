// hierarchical_depth.h — part of stage 7 (rasterization): the coarse depth of one tile, and the test that drops a
// triangle, or an 8x8 region of one, whose fragments cannot pass the depth test there, before coverage,
// interpolation and shading.
//
// Each 8x8 pixel block of the tile keeps the nearest and the farthest depth its pixels hold (`lo`, `hi`). The bounds
// are read from the depth buffer when first asked for after anything wrote there: the tile renderer marks a block
// stale for every quad a batch of fragments with depth writes covered, and every block at the start of a tile and
// after a clear; so they hold under every depth function, write mask and clear, and cost nothing where no triangle
// asks. A triangle's fragment depths over a pixel rectangle are bounded by its depth plane at the rectangle's
// corners, widened by the most that the per-fragment float evaluation of the plane can differ from the exact value.
// A depth test LESS (LEQUAL) fails everywhere when the nearest of them is at least (above) the farthest stored
// depth; GREATER (GEQUAL) when the farthest is at most (below) the nearest stored one. Only where the test is the
// early one (EarlyDepthTestApplies: no stencil test, no shader depth) and the target single-sampled.
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
  // A block's bound is read again every kAsks tests that ask for it, to follow the depths that drawing brings
  // nearer (which leave it a bound, only a looser one).
  static constexpr int kAsks = 4;
  // Tests are skipped while they do not pay: after kWindow tests in the tile that dropped fewer than kWindow / 4,
  // the next kSkip are not made.
  static constexpr int kWindow = 32, kSkip = 480;

  // The tile: its target (single-sampled, with a depth buffer) and the pixel rectangle it covers.
  const RenderTarget* target = nullptr;
  Rect tile;
  float hi[kBlocks];               // StoredDepth's values: k / 65535 for a 16-bit buffer
  std::uint8_t stale[kBlocks];     // 1: hi may be below a stored depth; read the block before using it
  std::uint8_t asks[kBlocks];      // tests that asked since the block was read
  bool lequal = false;             // the draw's comparison: LEQUAL (else LESS)
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
  /// Marks stale the blocks under the quads of `blocks`, whose depths may have been written by a comparison other
  /// than LESS or LEQUAL (those only bring depths nearer, which leaves every bound a bound).
  void Touch(const BlockBuffer& blocks) {
    for (int b = 0; b < blocks.count; ++b)
      for (int q = 0; q < blocks.quads[b]; ++q) stale[Index(blocks.qx[b][q], blocks.qy[b][q])] = 1;
  }
  /// Marks every block stale (a clear).
  void TouchAll() { std::memset(stale, 1, sizeof stale); }
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
  /// [px0, px1] x [py0, py1] (inclusive, inside the tile) can pass the draw's depth test, LESS or LEQUAL (`lequal`).
  bool Hides(const Plane& z, float x0, float y0, int px0, int py0, int px1, int py1);

 private:
  int Index(int x, int y) const {  // (x and y inside the tile)
    return int(unsigned(y - tile.y0) / kBlock) * kPerRow + int(unsigned(x - tile.x0) / kBlock);
  }
  void Refresh(int index);
};

}  // namespace softgl::detail

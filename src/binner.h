// binner.h — binning: primitives after clipping, culling and the viewport transform are stored in window space
// and sorted into the screen tiles they may touch, so that each tile can later be rasterized and shaded on its
// own, by any thread, in primitive order.
//
// A draw is binned in batches of primitives (BinnedBatch), each batch by one thread; a tile's primitives are those
// of its list in each batch, batches taken in order, which is the order the draw submitted them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "types.h"

namespace softgl::detail {

/// Tile edge in pixels: a multiple of 2, so that no 2x2 quad straddles two tiles.
inline constexpr int kTileSize = 64;

/// The tiles covering a width x height render target, row by row from the bottom.
struct TileGrid {
  int width = 0, height = 0, cols = 0, rows = 0;
  static TileGrid For(int width, int height);
  int Count() const { return cols * rows; }
  Rect TileRect(int tile) const;
};

enum class PrimitiveKind : std::uint8_t { kPoint = 1, kLine = 2, kTriangle = 3 };

/// One primitive ready for the rasterizer; its vertices are `kind` runs of 4 + nvar floats each (window position,
/// then varyings), stored from BinnedBatch's vertex floats at `first_float`.
struct BinnedPrimitive {
  PrimitiveKind kind = PrimitiveKind::kTriangle;
  bool front_facing = true;
  float depth_offset = 0.0f;  // polygon offset
  float point_size = 1.0f;
  std::uint32_t first_float = 0;
};

/// The output of binning one batch of primitives. Primitives and their vertices are appended in submission order
/// and stored once; Finish() then lists, for every tile a primitive may touch, the primitive's index (4 bytes per
/// tile, nothing copied), each tile's list in submission order. A primitive over more than kListedTiles tiles is in
/// no tile list but in the batch's list of large primitives, which every tile walks beside its own list, in
/// submission order. So a batch's memory is bounded by its primitives, whatever the framebuffer's size.
class BinnedBatch {
 public:
  /// Empties the batch for a draw with `nvar` floats of varyings per vertex.
  void Reset(int nvar);

  /// Appends a primitive whose fragments all lie in `box` (pixels, half-open, already inside the draw's bounds)
  /// and notes it for every tile that box overlaps; its `kind` vertices are read from `v`.
  void Add(const BinnedPrimitive& prim, const VertexView* v, const Rect& box, const TileGrid& grid);
  void Add(const BinnedPrimitive& prim, const WindowVertex* v, const Rect& box, const TileGrid& grid) {
    const VertexView views[3] = {v[0], int(prim.kind) > 1 ? v[1] : v[0], int(prim.kind) > 2 ? v[2] : v[0]};
    Add(prim, views, box, grid);
  }
  /// Builds the per-tile lists; call once, after the last Add.
  void Finish(const TileGrid& grid);

  /// Walks the primitives of `tile` in order: fn(const BinnedPrimitive&, const float* vertices), the vertices
  /// being `kind` runs of 4 + nvar floats (window position, then varyings).
  template <class Fn>
  void ForEachInTile(int tile, const Rect& tile_rect, Fn&& fn) const {
    const auto [begin, finish] = List(tile);
    const std::uint32_t* p = tile_prims_.data() + begin;
    const std::uint32_t* end = tile_prims_.data() + finish;
    std::size_t g = 0;  // next large primitive
    for (;;) {
      const std::uint32_t listed = p < end ? *p : ~0u;
      if (g < large_.size() && large_[g].index < listed) {  // a large primitive comes first
        const Large& l = large_[g++];
        const BinnedPrimitive& prim = prims_[l.index];
        if (Overlap(l.box, tile_rect)) fn(prim, vertices_.data() + prim.first_float);
        continue;
      }
      if (p >= end) break;
      const BinnedPrimitive& prim = prims_[*p++];
      fn(prim, vertices_.data() + prim.first_float);
    }
  }
  /// Whether ForEachInTile(tile, tile_rect, ...) may call its function at all: the tile's list is not empty, or a
  /// large primitive's box overlaps the tile.
  bool Touches(int tile, const Rect& tile_rect) const {
    if (const auto [begin, finish] = List(tile); begin != finish) return true;
    for (const Large& l : large_)
      if (Overlap(l.box, tile_rect)) return true;
    return false;
  }
  /// The union of the boxes of the primitives added (pixels; empty when none was).
  const Rect& Box() const { return box_; }
  /// Copies vertex k of the run at `vertices` into a WindowVertex.
  void Vertex(const float* vertices, int k, WindowVertex& out) const;
  /// Vertex k of the run at `vertices`, read in place.
  VertexView View(const float* vertices, int k) const {
    const float* src = vertices + std::size_t(k) * std::size_t(4 + nvar_);
    return VertexView(glm::vec4(src[0], src[1], src[2], src[3]), src + 4);
  }

  /// Memory held, in bytes (what the context's recording budget counts).
  std::size_t Bytes() const;

 private:
  static constexpr std::uint32_t kListedTiles = 64;
  struct Large {
    std::uint32_t index;  // in prims_
    Rect box;
  };
  static bool Overlap(const Rect& a, const Rect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  }
  // Where the list of `tile` starts and ends in tile_prims_; empty for a tile outside the range that has lists.
  std::pair<std::uint32_t, std::uint32_t> List(int tile) const {
    const int i = tile - tile_lo_;
    if (i < 0 || std::size_t(i) + 1 >= tile_start_.size()) return {0u, 0u};
    return {tile_start_[std::size_t(i)], tile_start_[std::size_t(i) + 1]};
  }
  std::vector<Large> large_;                // primitives over more than kListedTiles tiles, in order
  Rect box_;                                // the union of the primitives' boxes
  int nvar_ = 0;
  std::vector<BinnedPrimitive> prims_;      // in submission order
  std::vector<float> vertices_;             // every primitive's vertices, in submission order
  std::vector<std::uint64_t> notes_;        // tile << 32 | primitive, in submission order
  int tile_lo_ = 0;                         // the first tile with a list (in grid order)
  std::vector<std::uint32_t> tile_start_;   // where each tile's list starts in tile_prims_, from tile_lo_ to the
                                            // last tile with a list, plus its end: only the tiles the batch
                                            // touches cost anything to build (a small draw builds one or two)
  std::vector<std::uint32_t> tile_prims_;   // the tiles' lists of primitive indices, one after another
  std::vector<std::uint32_t> fill_;         // Finish's write position per tile
};

/// The pixel box a primitive's fragments can fall in, from its window positions: the rounded-out bounding box
/// (one pixel of margin for the fill rule's snapping), or for a point its square, cut to `bounds`. (A filled
/// triangle's box is rasterizer.h's TriangleCentreBox.)
Rect LineBox(const WindowVertex& a, const WindowVertex& b, const Rect& bounds);
Rect PointBox(const WindowVertex& v, float size, const Rect& bounds);

}  // namespace softgl::detail

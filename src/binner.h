// binner.h — binning: primitives after clipping, culling and the viewport transform are stored in window space
// and sorted into the screen tiles they may touch, so that each tile can later be rasterized and shaded on its
// own, by any thread, in primitive order.
//
// A draw is binned in batches of primitives (BinnedBatch), each batch by one thread; a tile's primitives are those
// of its list in each batch, batches taken in order, which is the order the draw submitted them.
#pragma once

#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <tuple>
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
/// then varyings), stored from BinnedBatch::vertices[first_float], or, when `indexed`, `kind` vertex numbers stored
/// there instead, each vertex a run of the batch's table (SetTable).
struct BinnedPrimitive {  // 20 bytes: stored inline in the tile lists
  PrimitiveKind kind = PrimitiveKind::kTriangle;
  bool front_facing = true;
  bool shared = false;  // its vertices are stored once for all its tiles (a primitive over many tiles)
  bool indexed = false;  // its vertices are numbers of runs in the batch's table (32 bits each, in a float's place)
  float depth_offset = 0.0f;  // polygon offset
  float point_size = 1.0f;
  std::uint32_t first_float = 0;
  std::uint32_t index = 0;  // submission order within the batch
};

/// The output of binning one batch of primitives. Primitives are appended in submission order, then Finish()
/// copies each into the contiguous list of every tile it may touch (a primitive record followed by its vertices),
/// so that a tile reads its primitives from consecutive memory. A primitive over more than kInlineTiles tiles
/// keeps one copy of its vertices that its records point to; one over more than kListedTiles tiles is in no tile
/// list at all but in the batch's list of large primitives, which every tile walks beside its own list, in
/// submission order. So a batch's memory is bounded by its primitives, whatever the framebuffer's size.
/// A binned primitive's vertices as a tile reads them: vertex k's window position, then its varyings, from v[k].
struct VertexRuns {
  const float* v[3];
};

class BinnedBatch {
 public:
  /// Empties the batch for a draw with `nvar` floats of varyings per vertex.
  void Reset(int nvar);
  /// The vertices AddIndexed refers to: runs of 4 + nvar floats (window position, then varyings), which must stay
  /// where they are until the batch is reset (the frame keeps them: Frame::KeepVertices).
  void SetTable(const float* table) { table_ = table; }

  /// Appends a primitive whose fragments all lie in `box` (pixels, half-open, already inside the draw's bounds)
  /// and notes it for every tile that box overlaps; its `kind` vertices are read from `v`.
  void Add(const BinnedPrimitive& prim, const VertexView* v, const Rect& box, const TileGrid& grid);
  void Add(const BinnedPrimitive& prim, const WindowVertex* v, const Rect& box, const TileGrid& grid) {
    const VertexView views[3] = {v[0], int(prim.kind) > 1 ? v[1] : v[0], int(prim.kind) > 2 ? v[2] : v[0]};
    Add(prim, views, box, grid);
  }
  /// Add() for a primitive whose vertices are runs index[0 .. kind) of the batch's table, not copied: the tile
  /// lists hold their numbers.
  void AddIndexed(const BinnedPrimitive& prim, const std::uint32_t* index, const Rect& box, const TileGrid& grid);
  /// Builds the per-tile lists; call once, after the last Add.
  void Finish(const TileGrid& grid);

  /// Where a walk of one tile's primitives stands (ForEachInTile below), kept between calls for the same tile.
  struct Cursor {
    bool started = false;
    std::uint32_t at = 0, end = 0;  // in tile_data_
    std::size_t large = 0;          // next in large_
  };
  /// Walks the primitives of `tile` in order: fn(const BinnedPrimitive&, const VertexRuns& vertices).
  template <class Fn>
  void ForEachInTile(int tile, const Rect& tile_rect, Fn&& fn) const {
    Cursor cursor;
    ForEachInTile(tile, tile_rect, cursor, 0, ~0u, fn);
  }
  /// The same walk, of the primitives with indices lo .. hi only, going on from `cursor` and leaving it after
  /// them: consecutive calls for increasing ranges walk the tile once (the draws sharing a batch).
  template <class Fn>
  void ForEachInTile(int tile, const Rect& tile_rect, Cursor& cursor, std::uint32_t lo, std::uint32_t hi,
                     Fn&& fn) const {
    if (!cursor.started) {
      std::tie(cursor.at, cursor.end) = List(tile);
      cursor.started = true;
    }
    const float* base = tile_data_.data();
    for (;;) {
      BinnedPrimitive prim;
      const bool listed = cursor.at < cursor.end;
      if (listed) std::memcpy(static_cast<void*>(&prim), base + cursor.at, sizeof prim);
      const std::uint32_t next = listed ? prim.index : ~0u;
      if (cursor.large < large_.size() && large_[cursor.large].prim.index < next) {  // a large primitive first
        const Large& l = large_[cursor.large];
        if (l.prim.index >= hi) return;
        ++cursor.large;
        if (l.prim.index >= lo && Overlap(l.box, tile_rect)) fn(l.prim, Runs(l.prim, shared_.data() + l.prim.first_float));
        continue;
      }
      if (!listed || next >= hi) return;
      const float* p = base + cursor.at + kHeaderFloats;
      cursor.at += kHeaderFloats + (prim.shared ? 0u : Words(prim));
      if (next < lo) continue;
      fn(prim, Runs(prim, prim.shared ? shared_.data() + prim.first_float : p));
    }
  }
  /// Prefetches, for a walk of `tile` soon, the batch itself (stage 0), where its list starts (1), or the list's
  /// first records (2): a tile walks many batches, each list a cache miss away. Each stage reads what the one
  /// before it fetched.
  void Prefetch(int stage, int tile) const {
    if (stage == 0) {
      const char* self = reinterpret_cast<const char*>(this);
      for (std::size_t b = 0; b < sizeof *this; b += 64) __builtin_prefetch(self + b);
      return;
    }
    const int i = tile - tile_lo_;
    if (i < 0 || std::size_t(i) + 1 >= tile_start_.size()) return;
    if (stage == 1) __builtin_prefetch(&tile_start_[std::size_t(i)]);
    else __builtin_prefetch(tile_data_.data() + tile_start_[std::size_t(i)]);
  }
  /// How far the batch is filled: what TilesSince() walks from.
  struct Mark {
    std::size_t notes = 0, large = 0;
    std::uint32_t primitives = 0;
  };
  Mark Position() const { return Mark{notes_.size(), large_.size(), std::uint32_t(prims_.size())}; }
  /// Calls fn(tile) for each tile the primitives added since `mark` touch (a tile may come more than once);
  /// before Finish().
  template <class Fn>
  void TilesSince(const Mark& mark, const TileGrid& grid, Fn&& fn) const {
    for (std::size_t n = mark.notes; n < notes_.size(); ++n) fn(int(notes_[n] >> 32));
    for (std::size_t g = mark.large; g < large_.size(); ++g) {
      const Rect& b = large_[g].box;
      for (int ty = b.y0 / kTileSize; ty <= (b.y1 - 1) / kTileSize; ++ty)
        for (int tx = b.x0 / kTileSize; tx <= (b.x1 - 1) / kTileSize; ++tx) fn(ty * grid.cols + tx);
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
  int Nvar() const { return nvar_; }
  /// The union of the boxes of the primitives added (pixels; empty when none was).
  Rect Box() const { return box_.Empty() ? Rect{} : box_; }
  /// Copies vertex k of `vertices` into a WindowVertex.
  void Vertex(const VertexRuns& vertices, int k, WindowVertex& out) const;
  /// Vertex k of `vertices`, read in place.
  static VertexView View(const VertexRuns& vertices, int k) {
    const float* src = vertices.v[k];
    return VertexView(glm::vec4(src[0], src[1], src[2], src[3]), src + 4);
  }

  /// Memory held, in bytes (what the context's recording budget counts).
  std::size_t Bytes() const;

 private:
  static constexpr int kHeaderFloats = int(sizeof(BinnedPrimitive) / sizeof(float));
  static constexpr std::uint32_t kInlineTiles = 4;
  static constexpr std::uint32_t kListedTiles = 64;
  struct Large {
    BinnedPrimitive prim;  // shared, in shared_
    Rect box;
  };
  // The floats a primitive's vertices take where they are stored: its runs, or its runs' numbers.
  std::uint32_t Words(const BinnedPrimitive& p) const {
    return std::uint32_t(int(p.kind) * (p.indexed ? 1 : 4 + nvar_));
  }
  // Where the vertices of `p`, stored from `words`, are.
  VertexRuns Runs(const BinnedPrimitive& p, const float* words) const {
    VertexRuns r;
    const int n = int(p.kind);
    const std::size_t stride = std::size_t(4 + nvar_);
    for (int k = 0; k < 3; ++k) {
      const int at = k < n ? k : 0;
      if (p.indexed) {
        std::uint32_t i;
        std::memcpy(&i, words + at, sizeof i);
        r.v[k] = table_ + std::size_t(i) * stride;
      } else {
        r.v[k] = words + std::size_t(at) * stride;
      }
    }
    return r;
  }
  // Notes primitive p, which Add or AddIndexed stored, for the tiles `box` overlaps.
  void Note(const BinnedPrimitive& p, const Rect& box, const TileGrid& grid);
  static bool Overlap(const Rect& a, const Rect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  }
  // Where the list of `tile` starts and ends in tile_data_; empty for a tile outside the range that has lists.
  std::pair<std::uint32_t, std::uint32_t> List(int tile) const {
    const int i = tile - tile_lo_;
    if (i < 0 || std::size_t(i) + 1 >= tile_start_.size()) return {0u, 0u};
    return {tile_start_[std::size_t(i)], tile_start_[std::size_t(i) + 1]};
  }
  std::vector<Large> large_;                // primitives over more than kListedTiles tiles, in order
  Rect box_{INT_MAX, INT_MAX, INT_MIN, INT_MIN};  // the union of the primitives' boxes (inverted: none yet)
  int nvar_ = 0;
  const float* table_ = nullptr;            // SetTable
  std::vector<BinnedPrimitive> prims_;      // in submission order
  std::vector<std::uint32_t> prim_tiles_;   // how many tiles each primitive touches
  std::vector<float> vertices_;             // the primitives' vertices, vertices_used_ floats of it
  std::uint32_t vertices_used_ = 0;
  std::vector<float> shared_;               // the vertices of primitives over more than kInlineTiles tiles
  std::vector<std::uint64_t> notes_;        // tile << 32 | primitive, in submission order
  int tile_lo_ = 0;                         // the first tile with a list (in grid order)
  std::vector<std::uint32_t> tile_start_;   // where each tile's list starts in tile_data_, from tile_lo_ to the
                                            // last tile with a list, plus its end: only the tiles the batch
                                            // touches cost anything to build (a small draw builds one or two)
  std::vector<float> tile_data_;
  std::vector<std::uint32_t> fill_;         // Finish's write position per tile
};

/// The pixel box a primitive's fragments can fall in, from its window positions: the rounded-out bounding box
/// (one pixel of margin for the fill rule's snapping), or for a point its square, cut to `bounds`. (A filled
/// triangle's box is rasterizer.h's TriangleCentreBox.)
Rect LineBox(const WindowVertex& a, const WindowVertex& b, const Rect& bounds, float width = 1.0f);
Rect PointBox(const WindowVertex& v, float size, const Rect& bounds);

}  // namespace softgl::detail

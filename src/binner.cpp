// binner.cpp — per-tile primitive lists, built batch by batch.
#include "binner.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

namespace softgl::detail {

TileGrid TileGrid::For(int width, int height) {
  TileGrid g;
  g.width = std::max(width, 0);
  g.height = std::max(height, 0);
  g.cols = (g.width + kTileSize - 1) / kTileSize;
  g.rows = (g.height + kTileSize - 1) / kTileSize;
  return g;
}

Rect TileGrid::TileRect(int tile) const {
  const int tx = tile % cols, ty = tile / cols;
  return Rect{tx * kTileSize, ty * kTileSize, std::min((tx + 1) * kTileSize, width),
              std::min((ty + 1) * kTileSize, height)};
}

void BinnedBatch::Reset(int nvar) {
  nvar_ = nvar;
  prims_.clear();
  prim_tiles_.clear();
  vertices_used_ = 0;
  shared_.clear();
  large_.clear();
  notes_.clear();
  tile_start_.clear();
  box_ = Rect{INT_MAX, INT_MAX, INT_MIN, INT_MIN};  // (empty; any box's union with it is that box)
  table_ = nullptr;
  // tile_data_ keeps its size: Finish overwrites what it uses (tile_start_ bounds it), without zeroing it first.
}

[[gnu::always_inline]] inline void BinnedBatch::Note(const BinnedPrimitive& p, const Rect& box, const TileGrid& grid) {
  const std::uint32_t index = p.index;
  prims_.push_back(p);
  box_ = Rect{std::min(box_.x0, box.x0), std::min(box_.y0, box.y0), std::max(box_.x1, box.x1),
              std::max(box_.y1, box.y1)};
  // The box lies inside the framebuffer: its coordinates are not negative.
  const auto tile_of = [](int pixel) { return int(unsigned(pixel) / unsigned(kTileSize)); };
  const int tx0 = tile_of(box.x0), tx1 = tile_of(box.x1 - 1);
  const int ty0 = tile_of(box.y0), ty1 = tile_of(box.y1 - 1);
  if (tx0 == tx1 && ty0 == ty1) {  // one tile, as most are
    prim_tiles_.push_back(1);
    notes_.push_back(std::uint64_t(ty0 * grid.cols + tx0) << 32 | index);
    return;
  }
  const auto tiles = std::uint32_t((tx1 - tx0 + 1) * (ty1 - ty0 + 1));
  prim_tiles_.push_back(tiles);
  if (tiles > kListedTiles) {  // in the list of large primitives, not in the tiles' lists
    large_.push_back(Large{p, box});
    return;
  }
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) notes_.push_back(std::uint64_t(ty * grid.cols + tx) << 32 | index);
}

void BinnedBatch::Add(const BinnedPrimitive& prim, const VertexView* v, const Rect& box, const TileGrid& grid) {
  if (box.Empty()) return;
  BinnedPrimitive p = prim;
  p.first_float = vertices_used_;
  p.index = std::uint32_t(prims_.size());
  p.indexed = false;
  const int n = int(prim.kind);
  const std::size_t stride = 4 + std::size_t(nvar_), need = std::size_t(n) * stride;
  if (vertices_used_ + need > vertices_.size())  // grows by doubling; not cleared between batches
    vertices_.resize(std::max(vertices_.size() * 2, vertices_used_ + need));
  float* dst = vertices_.data() + vertices_used_;
  vertices_used_ += std::uint32_t(need);
  const auto copy = [&](int k) {
    std::memcpy(dst + std::size_t(k) * stride, &v[k].win, sizeof(float) * 4);
    if (nvar_ > 0)  // (var may be null)
      std::memcpy(dst + std::size_t(k) * stride + 4, v[k].var, sizeof(float) * std::size_t(nvar_));
  };
  switch (n) {  // (the vertices of a point, a line or a triangle, each copy inline)
    case 3: copy(2); [[fallthrough]];
    case 2: copy(1); [[fallthrough]];
    default: copy(0);
  }
  Note(p, box, grid);
}

void BinnedBatch::AddIndexed(const BinnedPrimitive& prim, const std::uint32_t* index, const Rect& box,
                             const TileGrid& grid) {
  if (box.Empty()) return;
  BinnedPrimitive p = prim;
  p.first_float = vertices_used_;
  p.index = std::uint32_t(prims_.size());
  p.indexed = true;
  const std::size_t need = std::size_t(int(prim.kind));
  if (vertices_used_ + need > vertices_.size()) vertices_.resize(std::max(vertices_.size() * 2, vertices_used_ + need));
  float* dst = vertices_.data() + vertices_used_;  // the numbers in floats' places
  switch (need) {  // (a point, a line or a triangle: each number a move)
    case 3: std::memcpy(dst + 2, index + 2, sizeof(std::uint32_t)); [[fallthrough]];
    case 2: std::memcpy(dst + 1, index + 1, sizeof(std::uint32_t)); [[fallthrough]];
    default: std::memcpy(dst, index, sizeof(std::uint32_t));
  }
  vertices_used_ += std::uint32_t(need);
  Note(p, box, grid);
}

void BinnedBatch::Finish(const TileGrid& grid) {
  // A stable counting sort of the notes by tile, moving the data: each tile's list keeps submission order.
  static_assert(sizeof(BinnedPrimitive) % sizeof(float) == 0);
  static_assert(sizeof(BinnedPrimitive) == 20);
  // Primitives over many tiles: their vertices once, in shared_ (an indexed one's numbers are as small as a
  // reference to them: it is shared only when in no tile's list, as a large primitive).
  std::size_t next_large = 0;
  for (std::size_t i = 0; i < prims_.size(); ++i) {
    if (prim_tiles_[i] <= (prims_[i].indexed ? kListedTiles : kInlineTiles)) continue;
    BinnedPrimitive& p = prims_[i];
    const std::size_t n = Words(p);
    const auto at = std::uint32_t(shared_.size());
    shared_.insert(shared_.end(), vertices_.begin() + p.first_float, vertices_.begin() + p.first_float + n);
    p.first_float = at;
    p.shared = true;
    if (prim_tiles_[i] > kListedTiles) large_[next_large++].prim = p;  // large_ is in the same order
  }
  auto size_of = [&](std::uint32_t prim) {
    const BinnedPrimitive& p = prims_[prim];
    return std::uint32_t(kHeaderFloats) + (p.shared ? 0u : Words(p));
  };
  // Lists for the tiles from the first to the last one noted (grid order).
  int lo = grid.Count(), hi = -1;
  for (std::uint64_t n : notes_) {
    lo = std::min(lo, int(n >> 32));
    hi = std::max(hi, int(n >> 32));
  }
  tile_lo_ = hi >= lo ? lo : 0;
  tile_start_.assign(hi >= lo ? std::size_t(hi - lo) + 2 : 0, 0);
  for (std::uint64_t n : notes_) tile_start_[std::size_t(int(n >> 32) - lo) + 1] += size_of(std::uint32_t(n));
  for (std::size_t t = 1; t < tile_start_.size(); ++t) tile_start_[t] += tile_start_[t - 1];
  if (!tile_start_.empty() && tile_data_.size() < tile_start_.back()) tile_data_.resize(tile_start_.back());
  std::vector<std::uint32_t>& fill = fill_;
  fill.assign(tile_start_.begin(), tile_start_.empty() ? tile_start_.end() : tile_start_.end() - 1);
  for (std::uint64_t n : notes_) {
    const auto prim = std::uint32_t(n);
    float* dst = tile_data_.data() + fill[std::size_t(int(n >> 32) - lo)];
    const BinnedPrimitive& p = prims_[prim];
    std::memcpy(dst, static_cast<const void*>(&p), sizeof p);
    if (!p.shared) std::memcpy(dst + kHeaderFloats, vertices_.data() + p.first_float, sizeof(float) * Words(p));
    fill[std::size_t(int(n >> 32) - lo)] += size_of(prim);
  }
  notes_.clear();
  vertices_used_ = 0;
}

void BinnedBatch::Vertex(const VertexRuns& vertices, int k, WindowVertex& out) const {
  const float* src = vertices.v[k];
  std::memcpy(&out.win, src, sizeof(float) * 4);
  std::memcpy(out.var, src + 4, sizeof(float) * std::size_t(nvar_));
}

std::size_t BinnedBatch::Bytes() const {
  return prims_.capacity() * sizeof(BinnedPrimitive) + prim_tiles_.capacity() * sizeof(std::uint32_t) +
         (vertices_.capacity() + shared_.capacity()) * sizeof(float) + large_.capacity() * sizeof(Large) +
         notes_.capacity() * sizeof(std::uint64_t) + tile_start_.capacity() * sizeof(std::uint32_t) +
         tile_data_.capacity() * sizeof(float);
}

namespace {

// [floor(lo) - 1, ceil(hi) + 1] in pixels, cut to bounds; coordinates beyond the guard band are clamped first.
Rect Box(float x_lo, float y_lo, float x_hi, float y_hi, const Rect& bounds) {
  auto lo = [](float f) { return int(std::floor(std::clamp(f, -1e8f, 1e8f))) - 1; };
  auto hi = [](float f) { return int(std::ceil(std::clamp(f, -1e8f, 1e8f))) + 2; };  // exclusive
  if (!(x_lo == x_lo) || !(y_lo == y_lo) || !(x_hi == x_hi) || !(y_hi == y_hi)) return Rect{};  // NaN
  Rect r{std::max(lo(x_lo), bounds.x0), std::max(lo(y_lo), bounds.y0), std::min(hi(x_hi), bounds.x1),
         std::min(hi(y_hi), bounds.y1)};
  return r.Empty() ? Rect{} : r;
}

}  // namespace

Rect LineBox(const WindowVertex& a, const WindowVertex& b, const Rect& bounds, float width) {
  const float half = width * 0.5f;  // (a wide line reaches this far across its segment)
  return Box(std::min(a.win.x, b.win.x) - half, std::min(a.win.y, b.win.y) - half, std::max(a.win.x, b.win.x) + half,
             std::max(a.win.y, b.win.y) + half, bounds);
}

Rect PointBox(const WindowVertex& v, float size, const Rect& bounds) {
  const float half = std::min(size, 1e6f) * 0.5f;
  return Box(v.win.x - half, v.win.y - half, v.win.x + half, v.win.y + half, bounds);
}

}  // namespace softgl::detail

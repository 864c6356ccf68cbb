// binner.cpp — per-tile primitive lists, built batch by batch.
#include "binner.h"

#include <algorithm>
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
  vertices_.clear();
  large_.clear();
  notes_.clear();
  tile_start_.clear();
  box_ = Rect{};
  // tile_prims_ keeps its size: Finish overwrites what it uses (tile_start_ bounds it), without zeroing it first.
}

void BinnedBatch::Add(const BinnedPrimitive& prim, const VertexView* v, const Rect& box, const TileGrid& grid) {
  if (box.Empty()) return;
  const auto index = std::uint32_t(prims_.size());
  BinnedPrimitive p = prim;
  p.first_float = std::uint32_t(vertices_.size());
  const std::size_t stride = 4 + std::size_t(nvar_);
  vertices_.resize(vertices_.size() + std::size_t(prim.kind) * stride);
  float* dst = vertices_.data() + p.first_float;
  for (int k = 0; k < int(prim.kind); ++k, dst += stride) {
    std::memcpy(dst, &v[k].win, sizeof(float) * 4);
    std::memcpy(dst + 4, v[k].var, sizeof(float) * std::size_t(nvar_));
  }
  prims_.push_back(p);
  box_ = box_.Empty() ? box : Rect{std::min(box_.x0, box.x0), std::min(box_.y0, box.y0), std::max(box_.x1, box.x1),
                                   std::max(box_.y1, box.y1)};
  const int tx0 = box.x0 / kTileSize, tx1 = (box.x1 - 1) / kTileSize;
  const int ty0 = box.y0 / kTileSize, ty1 = (box.y1 - 1) / kTileSize;
  if (std::uint32_t((tx1 - tx0 + 1) * (ty1 - ty0 + 1)) > kListedTiles) {  // listed apart, not in the tiles' lists
    large_.push_back(Large{index, box});
    return;
  }
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) notes_.push_back(std::uint64_t(ty * grid.cols + tx) << 32 | index);
}

void BinnedBatch::Finish(const TileGrid& grid) {
  // A stable counting sort of the notes by tile: each tile's list keeps submission order. Lists for the tiles
  // from the first to the last one noted (grid order).
  int lo = grid.Count(), hi = -1;
  for (std::uint64_t n : notes_) {
    lo = std::min(lo, int(n >> 32));
    hi = std::max(hi, int(n >> 32));
  }
  tile_lo_ = hi >= lo ? lo : 0;
  tile_start_.assign(hi >= lo ? std::size_t(hi - lo) + 2 : 0, 0);
  for (std::uint64_t n : notes_) ++tile_start_[std::size_t(int(n >> 32) - lo) + 1];
  for (std::size_t t = 1; t < tile_start_.size(); ++t) tile_start_[t] += tile_start_[t - 1];
  if (!tile_start_.empty() && tile_prims_.size() < tile_start_.back()) tile_prims_.resize(tile_start_.back());
  std::vector<std::uint32_t>& fill = fill_;
  fill.assign(tile_start_.begin(), tile_start_.empty() ? tile_start_.end() : tile_start_.end() - 1);
  for (std::uint64_t n : notes_) tile_prims_[fill[std::size_t(int(n >> 32) - lo)]++] = std::uint32_t(n);
  notes_.clear();
}

void BinnedBatch::Vertex(const float* vertices, int k, WindowVertex& out) const {
  const float* src = vertices + std::size_t(k) * std::size_t(4 + nvar_);
  std::memcpy(&out.win, src, sizeof(float) * 4);
  std::memcpy(out.var, src + 4, sizeof(float) * std::size_t(nvar_));
}

std::size_t BinnedBatch::Bytes() const {
  return prims_.capacity() * sizeof(BinnedPrimitive) + vertices_.capacity() * sizeof(float) +
         large_.capacity() * sizeof(Large) + notes_.capacity() * sizeof(std::uint64_t) +
         (tile_start_.capacity() + tile_prims_.capacity() + fill_.capacity()) * sizeof(std::uint32_t);
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

Rect LineBox(const WindowVertex& a, const WindowVertex& b, const Rect& bounds) {
  return Box(std::min(a.win.x, b.win.x), std::min(a.win.y, b.win.y), std::max(a.win.x, b.win.x),
             std::max(a.win.y, b.win.y), bounds);
}

Rect PointBox(const WindowVertex& v, float size, const Rect& bounds) {
  const float half = std::min(size, 1e6f) * 0.5f;
  return Box(v.win.x - half, v.win.y - half, v.win.x + half, v.win.y + half, bounds);
}

}  // namespace softgl::detail

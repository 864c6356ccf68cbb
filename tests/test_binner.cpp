// Binning: which tiles a primitive is listed in, the order a tile sees its primitives in, and the memory a batch
// holds, for small, medium and large primitives.
#include <catch2/catch.hpp>

#include <vector>

#include "binner.h"

using namespace softgl;
using detail::BinnedBatch;
using detail::BinnedPrimitive;
using detail::PrimitiveKind;
using detail::Rect;
using detail::TileGrid;
using detail::WindowVertex;

namespace {

// A triangle whose vertices carry `tag` in their window z, so that a visit can say which one it was.
void AddTriangle(BinnedBatch& batch, const TileGrid& grid, const Rect& box, float tag) {
  WindowVertex v[3];
  for (WindowVertex& w : v) w.win = glm::vec4(0.0f, 0.0f, tag, 1.0f);
  BinnedPrimitive p;
  p.kind = PrimitiveKind::kTriangle;
  batch.Add(p, v, box, grid);
}

// The tags of the primitives `tile` visits, in visit order.
std::vector<float> Visits(const BinnedBatch& batch, const TileGrid& grid, int tile) {
  std::vector<float> tags;
  batch.ForEachInTile(tile, grid.TileRect(tile), [&](const BinnedPrimitive& p, const float* vertices) {
    CHECK(p.kind == PrimitiveKind::kTriangle);
    tags.push_back(vertices[2]);  // vertex 0's window z
  });
  return tags;
}

}  // namespace

TEST_CASE("binning: tiles see their primitives in submission order, small, medium and large mixed", "[binner]") {
  const TileGrid grid = TileGrid::For(1024, 1024);  // 16 x 16 tiles of 64
  REQUIRE(grid.Count() == 256);
  BinnedBatch batch;
  batch.Reset(0);
  AddTriangle(batch, grid, Rect{0, 0, 1024, 1024}, 1.0f);     // large: every tile
  AddTriangle(batch, grid, Rect{10, 10, 20, 20}, 2.0f);       // small: tile 0 only
  AddTriangle(batch, grid, Rect{0, 0, 300, 100}, 3.0f);       // medium: 5 x 2 tiles
  AddTriangle(batch, grid, Rect{60, 60, 70, 70}, 4.0f);       // small, on a corner: tiles 0, 1, 16, 17
  AddTriangle(batch, grid, Rect{0, 0, 1024, 1024}, 5.0f);     // large again
  AddTriangle(batch, grid, Rect{1000, 1000, 1024, 1024}, 6.0f);  // small: the last tile
  batch.Finish(grid);
  CHECK(Visits(batch, grid, 0) == std::vector<float>{1, 2, 3, 4, 5});
  CHECK(Visits(batch, grid, 1) == std::vector<float>{1, 3, 4, 5});
  CHECK(Visits(batch, grid, 17) == std::vector<float>{1, 3, 4, 5});
  CHECK(Visits(batch, grid, 4) == std::vector<float>{1, 3, 5});
  CHECK(Visits(batch, grid, 5) == std::vector<float>{1, 5});
  CHECK(Visits(batch, grid, 255) == std::vector<float>{1, 5, 6});
}

TEST_CASE("binning: a shared batch is walked by ranges of primitives, each range once, in order", "[binner]") {
  // Draws that share a batch each walk their own range of its primitives, going on from where the draw before
  // left the walk: the ranges together visit what one walk visits.
  const TileGrid grid = TileGrid::For(1024, 1024);
  BinnedBatch batch;
  batch.Reset(0);
  const BinnedBatch::Mark start = batch.Position();
  AddTriangle(batch, grid, Rect{10, 10, 20, 20}, 1.0f);       // 0: small, tile 0
  AddTriangle(batch, grid, Rect{0, 0, 1024, 1024}, 2.0f);     // 1: large
  const BinnedBatch::Mark second = batch.Position();
  AddTriangle(batch, grid, Rect{0, 0, 300, 100}, 3.0f);       // 2: medium, vertices shared
  AddTriangle(batch, grid, Rect{30, 30, 40, 40}, 4.0f);       // 3: small, tile 0
  // The tiles a range's primitives were noted in, asked right after it (large ones: every tile their box overlaps).
  std::vector<int> tiles;
  batch.TilesSince(second, grid, [&](int t) { tiles.push_back(t); });
  CHECK(tiles.size() == 11);  // primitive 2's 5 x 2 tiles, then primitive 3's
  CHECK(tiles.back() == 0);
  tiles.clear();
  const BinnedBatch::Mark third = batch.Position();
  AddTriangle(batch, grid, Rect{0, 0, 1024, 1024}, 5.0f);     // 4: large
  AddTriangle(batch, grid, Rect{1000, 1000, 1024, 1024}, 6.0f);  // 5: small, the last tile
  batch.TilesSince(third, grid, [&](int t) { tiles.push_back(t); });
  CHECK(tiles.size() == 257);  // primitive 5's tile, then the large primitive 4's 256
  CHECK(tiles.front() == 255);
  CHECK(start.primitives == 0);
  CHECK(second.primitives == 2);
  CHECK(third.primitives == 4);
  batch.Finish(grid);

  for (int tile : {0, 1, 4, 17, 255}) {
    const Rect rect = grid.TileRect(tile);
    std::vector<float> ranged;
    BinnedBatch::Cursor cursor;
    const std::uint32_t bounds[] = {0, 2, 4, 6};
    for (int r = 0; r < 3; ++r) {
      const auto before = ranged.size();
      batch.ForEachInTile(tile, rect, cursor, bounds[r], bounds[r + 1], [&](const BinnedPrimitive& p, const float* v) {
        CHECK(p.index >= bounds[r]);
        CHECK(p.index < bounds[r + 1]);
        ranged.push_back(v[2]);
      });
      for (auto i = before; i < ranged.size(); ++i) CHECK(ranged[i] > float(bounds[r]));  // tags are index + 1
    }
    CHECK(ranged == Visits(batch, grid, tile));
  }
  // A range that starts past primitives no draw of this tile claims skips them.
  BinnedBatch::Cursor cursor;
  std::vector<float> late;
  batch.ForEachInTile(0, grid.TileRect(0), cursor, 3, 6, [&](const BinnedPrimitive&, const float* v) { late.push_back(v[2]); });
  CHECK(late == std::vector<float>{4, 5});
}

TEST_CASE("binning: a large primitive is visited only by the tiles its box overlaps", "[binner]") {
  const TileGrid grid = TileGrid::For(1024, 1024);
  BinnedBatch batch;
  batch.Reset(0);
  AddTriangle(batch, grid, Rect{0, 0, 1024, 640}, 1.0f);  // 16 x 10 tiles: large
  batch.Finish(grid);
  CHECK(Visits(batch, grid, 9 * 16).size() == 1);   // row 9
  CHECK(Visits(batch, grid, 10 * 16).empty());      // row 10: outside
}

TEST_CASE("binning: memory grows with primitives, not with the tiles they cover", "[binner]") {
  // 1,000 primitives with 64 floats of varyings covering all 65,536 tiles of a 16384 x 16384 target: a copy per
  // tile would be 53 GB, a reference per tile 1.3 GB; a batch holds them in well under a megabyte.
  const TileGrid grid = TileGrid::For(16384, 16384);
  BinnedBatch batch;
  batch.Reset(64);
  for (int i = 0; i < 1000; ++i) AddTriangle(batch, grid, Rect{0, 0, 16384, 16384}, float(i));
  batch.Finish(grid);
  CHECK(batch.Bytes() < std::size_t(2) << 20);
  const std::vector<float> last = Visits(batch, grid, grid.Count() - 1);
  REQUIRE(last.size() == 1000);
  CHECK(last.front() == 0.0f);
  CHECK(last.back() == 999.0f);
}

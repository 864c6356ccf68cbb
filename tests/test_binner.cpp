// Binning: which tiles a primitive is listed in, the order a tile sees its primitives in, and the memory a batch
// holds, for small, medium and large primitives.
#include <catch2/catch.hpp>

#include <vector>

#include "binner.h"
#include "helpers.h"

using namespace softgl;
using detail::BinnedBatch;
using detail::BinnedPrimitive;
using detail::PrimitiveKind;
using detail::Rect;
using detail::TileGrid;
using detail::VertexRuns;
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
  batch.ForEachInTile(tile, grid.TileRect(tile), [&](const BinnedPrimitive& p, const VertexRuns& vertices) {
    CHECK(p.kind == PrimitiveKind::kTriangle);
    tags.push_back(vertices.v[0][2]);  // vertex 0's window z
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
      batch.ForEachInTile(tile, rect, cursor, bounds[r], bounds[r + 1], [&](const BinnedPrimitive& p, const VertexRuns& v) {
        CHECK(p.index >= bounds[r]);
        CHECK(p.index < bounds[r + 1]);
        ranged.push_back(v.v[0][2]);
      });
      for (auto i = before; i < ranged.size(); ++i) CHECK(ranged[i] > float(bounds[r]));  // tags are index + 1
    }
    CHECK(ranged == Visits(batch, grid, tile));
  }
  // A range that starts past primitives no draw of this tile claims skips them.
  BinnedBatch::Cursor cursor;
  std::vector<float> late;
  batch.ForEachInTile(0, grid.TileRect(0), cursor, 3, 6, [&](const BinnedPrimitive&, const VertexRuns& v) { late.push_back(v.v[0][2]); });
  CHECK(late == std::vector<float>{4, 5});
}

TEST_CASE("binning: primitives whose vertices are numbers in a table read the table's runs, mixed with copied ones",
          "[binner]") {
  // A table of 8 vertices with 2 varyings each (window position, then varyings): vertex i has window z 100 + i and
  // varyings 200 + i, 300 + i. Indexed triangles of each size, between copied ones, and a point.
  constexpr int kNvar = 2, kStride = 4 + kNvar;
  std::vector<float> table(8 * kStride);
  for (int i = 0; i < 8; ++i) {
    const float run[kStride] = {0.0f, 0.0f, 100.0f + float(i), 1.0f, 200.0f + float(i), 300.0f + float(i)};
    std::copy(run, run + kStride, table.begin() + i * kStride);
  }
  const TileGrid grid = TileGrid::For(1024, 1024);
  BinnedBatch batch;
  batch.Reset(kNvar);
  batch.SetTable(table.data());
  auto indexed = [&](const Rect& box, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    BinnedPrimitive p;
    p.kind = PrimitiveKind::kTriangle;
    const std::uint32_t index[3] = {a, b, c};
    batch.AddIndexed(p, index, box, grid);
  };
  indexed(Rect{10, 10, 20, 20}, 0, 1, 2);     // small: tile 0
  AddTriangle(batch, grid, Rect{0, 0, 300, 100}, 1.0f);  // copied, medium (its vertices shared by its tiles)
  indexed(Rect{0, 0, 300, 100}, 3, 4, 5);     // medium: 5 x 2 tiles, its numbers in each list
  indexed(Rect{0, 0, 1024, 1024}, 7, 6, 5);   // large: in no list
  indexed(Rect{30, 30, 40, 40}, 5, 5, 5);     // small, one vertex three times
  BinnedPrimitive point;
  point.kind = PrimitiveKind::kPoint;
  const std::uint32_t at = 2;
  batch.AddIndexed(point, &at, Rect{1000, 1000, 1002, 1002}, grid);  // the last tile
  batch.Finish(grid);
  // Each visit: vertex 0's window z (a copied triangle's tag) and, for an indexed one, every vertex's varyings.
  auto visits = [&](int tile) {
    std::vector<float> seen;
    batch.ForEachInTile(tile, grid.TileRect(tile), [&](const BinnedPrimitive& p, const VertexRuns& v) {
      seen.push_back(v.v[0][2]);
      if (!p.indexed) return;
      // An indexed triangle's numbers are no larger than a reference to them: only the large one is shared.
      CHECK(p.shared == (v.v[0][2] == 107.0f));
      for (int k = 0; k < int(p.kind); ++k) {
        const float z = v.v[k][2];
        CHECK(v.v[k][4] == z + 100.0f);
        CHECK(v.v[k][5] == z + 200.0f);
        CHECK(BinnedBatch::View(v, k).var == v.v[k] + 4);
      }
    });
    return seen;
  };
  CHECK(visits(0) == std::vector<float>{100, 1, 103, 107, 105});
  CHECK(visits(4) == std::vector<float>{1, 103, 107});
  CHECK(visits(200) == std::vector<float>{107});
  CHECK(visits(255) == std::vector<float>{107, 102});
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

namespace {

// Window coordinates of a 200 x 130 context as a clip-space position (z, w as given).
glm::vec4 Window(float x, float y, float z = 0.0f) { return {x / 100.0f - 1.0f, y / 65.0f - 1.0f, z, 1.0f}; }

// Per tile of a 200 x 130 context (4 x 3 tiles): a triangle over tiles 0 and 1; a triangle facing away, culled;
// one in tile 0 crossing the near plane, clipped into a polygon of two triangles; a line across row 1 (four
// tiles); a point in tile (2, 1).
std::vector<std::uint32_t> CountedScene(int threads, int* cols, int* rows) {
  Context::Options options;
  options.threads = threads;
  Context gl(200, 130, options);
  gl.CountTilePrimitives(true);
  gl.Enable(CULL_FACE);
  testing::SolidShader shader;
  gl.UseProgram(shader);
  std::vector<glm::vec4> tri = {Window(10, 10), Window(100, 10), Window(10, 50)};
  std::vector<glm::vec4> culled = {Window(150, 80), Window(150, 120), Window(190, 80)};
  glm::vec4 behind = Window(30, 40);
  behind.z = -3.0f;  // clip z < -w: in front of the near plane, and not by a little
  std::vector<glm::vec4> clipped = {Window(10, 20), Window(50, 20), behind};
  std::vector<glm::vec4> all = tri;
  all.insert(all.end(), culled.begin(), culled.end());
  all.insert(all.end(), clipped.begin(), clipped.end());
  all.insert(all.end(), {Window(5, 100), Window(195, 100), Window(150.5f, 120.5f)});
  testing::MakeVertexArray(gl, all);
  gl.DrawArrays(TRIANGLES, 0, 9);
  gl.DrawArrays(LINES, 9, 2);
  gl.DrawArrays(POINTS, 11, 1);
  return gl.TilePrimitiveCounts(cols, rows);
}

}  // namespace

TEST_CASE("binning statistics: each tile counts the primitives binned to it, after clipping and culling",
          "[binner]") {
  int cols = -1, rows = -1;
  const std::vector<std::uint32_t> counts = CountedScene(1, &cols, &rows);
  CHECK(cols == 4);
  CHECK(rows == 3);
  const std::vector<std::uint32_t> expected = {1 + 2, 1, 0, 0,  // row 0: the triangle, the clipped one's two parts
                                               1, 1, 1 + 1, 1,  // row 1: the line, the point
                                               0, 0, 0, 0};
  CHECK(counts == expected);
  // The same counts whichever thread renders which tile.
  CHECK(CountedScene(3, nullptr, nullptr) == expected);

  Context gl(200, 130);
  CHECK(gl.TilePrimitiveCounts(&cols, &rows).empty());  // off by default
  CHECK((cols == 0 && rows == 0));
  testing::SolidShader shader;
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {Window(10, 10), Window(100, 10), Window(10, 50)});
  gl.CountTilePrimitives(true);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.TilePrimitiveCounts()[0] == 2);
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.TilePrimitiveCounts()[0] == 3);  // counted on from the call before
  gl.CountTilePrimitives(true);             // starts again
  gl.Clear(COLOR_BUFFER_BIT);
  CHECK(gl.TilePrimitiveCounts() == std::vector<std::uint32_t>(12, 0u));
  // A framebuffer of another size: its own grid, counted from zero.
  const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 70, 20);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
  gl.Viewport(0, 0, 70, 20);
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.TilePrimitiveCounts(&cols, &rows) == std::vector<std::uint32_t>{1, 0});  // (x from 3.5 to 35)
  CHECK((cols == 2 && rows == 1));
  gl.CountTilePrimitives(false);
  CHECK(gl.TilePrimitiveCounts(&cols, &rows).empty());
  CHECK((cols == 0 && rows == 0));
  CHECK(gl.GetError() == NO_ERROR);
}

// scenes.cpp — the conformance scenes. Each is one function over a Backend, so the same vertex data, matrices and
// state reach softgl and Mesa alike. Vertex transforms are done here, once, on the CPU: both pipelines then
// rasterize bit-identical clip-space positions, and what is compared is clipping, rasterization, interpolation and
// the per-fragment operations, not two compilers' rounding of a matrix product.
#include "scenes.h"

#include "scene_kit.h"

#include <array>
#include <cmath>
#include <cstring>
#include <random>

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

namespace conformance {

using namespace softgl;  // OpenGL's enum names

namespace {

constexpr int kSize = 128;

// Clip-space position of window point (x, y) in a kSize x kSize viewport: exact for multiples of 1/256.
glm::vec4 Win(float x, float y, float z = 0.0f) { return glm::vec4(x / 64.0f - 1.0f, y / 64.0f - 1.0f, z, 1.0f); }

// A colour whose channels are exact multiples of 1/255, so that conversion to 8 bits has no ties.
glm::vec4 Palette(unsigned i) {
  const unsigned h = i * 2654435761u;
  return glm::vec4(float((h >> 8) & 255) / 255.0f, float((h >> 16) & 255) / 255.0f, float((h >> 24) & 255) / 255.0f,
                   1.0f);
}

// A random window coordinate on the 1/256 sub-pixel grid; every fourth lands exactly on a pixel centre.
struct Jitter {
  std::mt19937 rng;
  explicit Jitter(unsigned seed) : rng(seed) {}
  float Sub(float lo, float hi) {
    std::uniform_int_distribution<int> d(int(lo * 256), int(hi * 256));
    const float v = float(d(rng)) / 256.0f;
    return (d(rng) % 4 == 0) ? std::floor(v) + 0.5f : v;
  }
  float Uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
};

using Corners = std::array<glm::vec4, 4>;

// Two triangles over corners p (in order around the quad), with `extra` (uv, direction, ...) at each corner.
std::vector<Vertex> QuadWith(const Corners& p, const Corners& extra, glm::vec4 color = glm::vec4(1)) {
  std::vector<Vertex> v;
  for (int k : {0, 1, 3, 1, 2, 3}) v.push_back({p[k], color, extra[k]});
  return v;
}

std::vector<Vertex> Quad(glm::vec4 a, glm::vec4 b, glm::vec4 c, glm::vec4 d, glm::vec4 color) {
  return QuadWith({a, b, c, d}, {}, color);
}

// The corners of the quad [x0, x1] x [z0, z1] in the plane y = 0, through mvp.
Corners Floor(const glm::mat4& mvp, float x0, float x1, float z0, float z1) {
  return {mvp * glm::vec4(x0, 0, z0, 1), mvp * glm::vec4(x1, 0, z0, 1), mvp * glm::vec4(x1, 0, z1, 1),
          mvp * glm::vec4(x0, 0, z1, 1)};
}

// uv (or any two values) at the four corners as extras.
Corners Uv(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  return {glm::vec4(a, 0, 0), glm::vec4(b, 0, 0), glm::vec4(c, 0, 0), glm::vec4(d, 0, 0)};
}

// Opaque black: the background coverage is measured against.
void ClearBlack(Backend& b) {
  b.ClearColor(0, 0, 0, 1);
  b.Clear(COLOR_BUFFER_BIT);
}

// A window-space rectangle as two triangles at NDC depth z.
std::vector<Vertex> Rect(float x0, float y0, float x1, float y1, float z, glm::vec4 color) {
  return Quad(Win(x0, y0, z), Win(x1, y0, z), Win(x1, y1, z), Win(x0, y1, z), color);
}

// ---- Coverage ----------------------------------------------------------------------------------------------------

void FillRuleTriangles(Backend& b) {
  ClearBlack(b);
  Jitter j(7);
  std::vector<Vertex> v;
  for (unsigned i = 0; i < 400; ++i) {
    const float cx = j.Sub(2, 126), cy = j.Sub(2, 126), r = j.Uniform(0.6f, 7.0f);
    const glm::vec4 c = Palette(i);
    for (int k = 0; k < 3; ++k)
      v.push_back({Win(std::round((cx + j.Uniform(-r, r)) * 256) / 256, std::round((cy + j.Uniform(-r, r)) * 256) / 256), c});
  }
  b.Draw(TRIANGLES, v);
}

// A jittered grid drawn as strips, and fans around shared centres, added up: a gap shows black, a double hit
// shows twice the colour.
void FillRuleSharedEdges(Backend& b) {
  ClearBlack(b);
  b.Enable(BLEND);
  b.BlendFunc(ONE, ONE);
  const glm::vec4 c(0.25f, 0.25f, 0.25f, 1.0f);
  Jitter j(11);
  constexpr int N = 12;
  glm::vec2 grid[N + 1][N + 1];
  for (int y = 0; y <= N; ++y)
    for (int x = 0; x <= N; ++x) {
      const bool border = x == 0 || y == 0 || x == N || y == N;
      grid[y][x] = glm::vec2(float(x) * 64.0f / N, float(y) * 128.0f / N);
      if (!border) grid[y][x] += glm::vec2(j.Sub(-2.5f, 2.5f), j.Sub(-2.5f, 2.5f));
    }
  for (int y = 0; y < N; ++y) {  // left half: one strip per row
    std::vector<Vertex> strip;
    for (int x = 0; x <= N; ++x) {
      strip.push_back({Win(grid[y][x].x, grid[y][x].y), c});
      strip.push_back({Win(grid[y + 1][x].x, grid[y + 1][x].y), c});
    }
    b.Draw(TRIANGLE_STRIP, strip);
  }
  // Right half: 4 x 4 cells, each a fan around a jittered centre.
  for (int cy = 0; cy < 4; ++cy)
    for (int cx = 0; cx < 4; ++cx) {
      const float x0 = 64.0f + float(cx) * 16.0f, y0 = float(cy) * 32.0f;
      std::vector<Vertex> fan{{Win(x0 + j.Sub(4, 12), y0 + j.Sub(8, 24)), c}};
      const glm::vec2 ring[] = {{x0, y0}, {x0 + 16, y0}, {x0 + 16, y0 + 32}, {x0, y0 + 32}, {x0, y0}};
      for (const glm::vec2& p : ring) fan.push_back({Win(p.x, p.y), c});
      b.Draw(TRIANGLE_FAN, fan);
    }
  b.Disable(BLEND);
}

void Points(Backend& b) {
  ClearBlack(b);
  Jitter j(3);
  const float sizes[] = {1, 2, 3, 4, 5, 8};
  unsigned n = 0;
  for (float s : sizes) {
    b.PointSize(s);
    std::vector<Vertex> v;
    for (int i = 0; i < 24; ++i) v.push_back({Win(j.Sub(4, 124), j.Sub(4, 124)), Palette(n++)});
    b.Draw(POINTS, v);
  }
}

// gl_PointCoord across points of several sizes at jittered positions, both origins, then points made by
// POLYGON_MODE POINT.
void PointSprites(Backend& b) {
  ClearBlack(b);
  Jitter j(11);
  const float sizes[] = {3, 6, 9.5f, 16, 23};
  for (Enum origin : {UPPER_LEFT, LOWER_LEFT}) {
    b.PointParameteri(POINT_SPRITE_COORD_ORIGIN, int(origin));
    const float y0 = origin == UPPER_LEFT ? 0.0f : 64.0f;
    for (int i = 0; i < 5; ++i) {
      b.PointSize(sizes[i]);
      b.Draw(POINTS, {{Win(12.0f + 25.0f * float(i) + j.Uniform(-0.5f, 0.5f), y0 + 14.0f + j.Uniform(-0.5f, 0.5f)),
                       {0, 0, origin == UPPER_LEFT ? 0.0f : 1.0f, 1}},
                      {Win(12.0f + 25.0f * float(i) + j.Uniform(-0.5f, 0.5f), y0 + 44.0f + j.Uniform(-0.5f, 0.5f)),
                       {0, 0, 0.5f, 1}}},
             Program::kPointCoord);
    }
  }
  b.PointParameteri(POINT_SPRITE_COORD_ORIGIN, int(UPPER_LEFT));
  b.PolygonMode(POINT);
  b.PointSize(7);
  b.Draw(TRIANGLES, {{Win(60.3f, 60.6f), {0, 0, 0.25f, 1}}, {Win(80.2f, 62.1f), {0, 0, 0.25f, 1}}, {Win(70.5f, 75.5f), {0, 0, 0.25f, 1}}},
         Program::kPointCoord);
  b.PolygonMode(FILL);
  b.PointSize(1);
}

void Lines(Backend& b) {
  ClearBlack(b);
  Jitter j(5);
  std::vector<Vertex> v;
  unsigned n = 0;
  for (int i = 0; i < 48; ++i) {  // segments in every direction
    const float a = 6.2831853f * float(i) / 48.0f, len = j.Uniform(8, 40);
    const float x = j.Sub(30, 98), y = j.Sub(30, 98);
    const glm::vec4 c = Palette(n++);
    v.push_back({Win(x, y), c});
    v.push_back({Win(std::round((x + std::cos(a) * len) * 256) / 256, std::round((y + std::sin(a) * len) * 256) / 256), c});
  }
  b.Draw(LINES, v);
  std::vector<Vertex> strip;
  for (int i = 0; i < 8; ++i) strip.push_back({Win(j.Sub(2, 126), j.Sub(2, 30)), Palette(n)});
  b.Draw(LINE_STRIP, strip);
  std::vector<Vertex> loop;
  for (int i = 0; i < 6; ++i) loop.push_back({Win(j.Sub(2, 126), j.Sub(100, 126)), Palette(n + 1)});
  b.Draw(LINE_LOOP, loop);
}

// Wide lines: segments in every direction at widths 2 to 5 and 2.6 (drawn 3 wide: OpenGL rounds the width), flat
// colours, a strip and a polygon drawn as lines 3 wide, and lines past the edges. The segments start on the
// subpixel grid but not on pixel centres: where an end lies on a centre and a long side of the line passes through
// a pixel centre in the end's column, llvmpipe's choice follows its own snapping of the moved end (a column's
// fragments one pixel up or down); wide_ties draws such ends where the sides run exactly through centres.
void WideLines(Backend& b) {
  ClearBlack(b);
  Jitter j(23);
  unsigned n = 0;
  const float widths[5] = {2.0f, 3.0f, 4.0f, 5.0f, 2.6f};
  for (int w = 0; w < 5; ++w) {
    b.LineWidth(widths[w]);
    std::vector<Vertex> v;
    for (int i = 0; i < 12; ++i) {
      const float a = 6.2831853f * (float(i) + 0.37f * float(w)) / 12.0f, len = j.Uniform(8, 30);
      const float x = std::round(j.Uniform(20, 108) * 256) / 256, y = std::round(j.Uniform(20, 108) * 256) / 256;
      const glm::vec4 c = Palette(n++);
      v.push_back({Win(x, y), c});
      v.push_back({Win(std::round((x + std::cos(a) * len) * 256) / 256, std::round((y + std::sin(a) * len) * 256) / 256), c});
    }
    b.Draw(LINES, v);
  }
  b.LineWidth(3.0f);
  std::vector<Vertex> strip;
  for (int i = 0; i < 8; ++i) strip.push_back({Win(j.Sub(2, 126), j.Sub(2, 30)), Palette(n)});
  b.Draw(LINE_STRIP, strip);
  b.Draw(LINES, {{Win(-10, 60.3f), Palette(n + 1)}, {Win(140, 70.8f), Palette(n + 1)},
                 {Win(126.5f, -5), Palette(n + 2)}, {Win(120.2f, 135), Palette(n + 2)}});
  b.PolygonMode(LINE);
  b.Draw(TRIANGLES, {{Win(j.Sub(70, 90), j.Sub(95, 100)), Palette(n + 3)}, {Win(j.Sub(100, 125), j.Sub(100, 110)), Palette(n + 3)},
                     {Win(j.Sub(90, 110), j.Sub(115, 126)), Palette(n + 3)}});
  b.PolygonMode(FILL);
  b.LineWidth(1.0f);
}

// Wide lines (2 pixels) whose long sides pass exactly through pixel centres: rising, falling, x- and y-major, drawn
// either way, from and to pixel centres: the fill rule's choice on the sides.
void WideTies(Backend& b) {
  ClearBlack(b);
  b.LineWidth(2.0f);
  auto line = [&](float x0, float y0, float x1, float y1, unsigned c) {
    b.Draw(LINES, {{Win(x0, y0), Palette(c)}, {Win(x1, y1), Palette(c)}});
  };
  line(10.5f, 10.5f, 50.5f, 20.5f, 1);   // x-major rising, left to right
  line(50.5f, 40.5f, 10.5f, 30.5f, 2);   // x-major rising, right to left
  line(70.5f, 20.5f, 110.5f, 10.5f, 3);  // x-major falling
  line(110.5f, 30.5f, 70.5f, 40.5f, 4);  // x-major falling, right to left
  line(10.5f, 60.5f, 20.5f, 100.5f, 5);  // y-major rising
  line(40.5f, 100.5f, 30.5f, 60.5f, 6);
  line(70.5f, 100.5f, 80.5f, 60.5f, 7);  // y-major falling
  line(100.5f, 60.5f, 90.5f, 100.5f, 8);
  b.LineWidth(1.0f);
}

// Colours varying along lines: OpenGL interpolates by the projection of the pixel centre onto the segment
// (t = (p - a).(b - a) / |b - a|^2), llvmpipe by the major axis coordinate alone; see docs/conformance.md.
void LineInterpolation(Backend& b) {
  ClearBlack(b);
  Jitter j(17);
  std::vector<Vertex> strip;
  for (int i = 0; i < 24; ++i) strip.push_back({Win(j.Sub(2, 126), j.Sub(2, 126)), Palette(unsigned(i))});
  b.Draw(LINE_STRIP, strip);
}

void PolygonModeLine(Backend& b) {
  ClearBlack(b);
  b.PolygonMode(LINE);
  Jitter j(13);
  std::vector<Vertex> v;
  for (unsigned i = 0; i < 30; ++i) {
    const float cx = j.Sub(10, 118), cy = j.Sub(10, 118);
    for (int k = 0; k < 3; ++k) v.push_back({Win(cx + j.Sub(-10, 10), cy + j.Sub(-10, 10)), Palette(i)});
  }
  b.Draw(TRIANGLES, v);
  b.PolygonMode(FILL);
}

void Culling(Backend& b) {
  ClearBlack(b);
  b.Enable(CULL_FACE);
  struct Cell {
    Enum cull, front;
  };
  const Cell cells[4] = {{BACK, CCW}, {FRONT, CCW}, {BACK, CW}, {FRONT_AND_BACK, CCW}};
  for (int i = 0; i < 4; ++i) {
    b.CullFace(cells[i].cull);
    b.FrontFace(cells[i].front);
    const float x0 = float(i % 2) * 64, y0 = float(i / 2) * 64;
    // A counter-clockwise triangle (red) and a clockwise one (green) in each cell.
    b.Draw(TRIANGLES, {{Win(x0 + 4, y0 + 4), {1, 0, 0, 1}}, {Win(x0 + 30, y0 + 4), {1, 0, 0, 1}},
                       {Win(x0 + 4, y0 + 60), {1, 0, 0, 1}}, {Win(x0 + 34, y0 + 4), {0, 1, 0, 1}},
                       {Win(x0 + 34, y0 + 60), {0, 1, 0, 1}}, {Win(x0 + 60, y0 + 4), {0, 1, 0, 1}}});
  }
  b.Disable(CULL_FACE);
}

// ---- Draw variants -------------------------------------------------------------------------------------------------

// A 4 x 3 grid of quads, each four vertices of their own colours, drawn by the OpenGL 3.3 draw variants: quads 0-2
// by DrawElementsBaseVertex from one relative index list, 3-4 by DrawRangeElements, 5, 7, 9 as strips by
// MultiDrawElements, 6, 8, 10, 11 as fans by MultiDrawArrays.
void DrawVariants(Backend& b) {
  ClearBlack(b);
  std::vector<Vertex> v;
  for (int q = 0; q < 12; ++q) {
    const float x0 = float(q % 4) * 32 + 3.25f, y0 = float(q / 4) * 42 + 4.5f, x1 = x0 + 25.5f, y1 = y0 + 33.0f;
    const glm::vec2 corners[4] = {{x0, y0}, {x1, y0 + 2}, {x1 - 3, y1}, {x0 + 1, y1 - 4}};  // counter-clockwise
    for (int k = 0; k < 4; ++k) v.push_back({Win(corners[k].x, corners[k].y), Palette(unsigned(4 * q + k))});
  }
  std::vector<std::uint32_t> idx;
  for (int q = 0; q < 12; ++q)  // quad q's triangles at 6q, its strip order at 72 + 4q
    for (int k : {0, 1, 2, 0, 2, 3}) idx.push_back(std::uint32_t(4 * q + k));
  for (int q = 0; q < 12; ++q)
    for (int k : {0, 1, 3, 2}) idx.push_back(std::uint32_t(4 * q + k));
  const int relative = int(idx.size());  // one quad's triangles, relative to its first vertex
  for (int k : {0, 1, 2, 0, 2, 3}) idx.push_back(std::uint32_t(k));
  using Call = DrawVariant::Call;
  std::vector<DrawVariant> calls;
  for (int q = 0; q < 3; ++q) calls.push_back({Call::kElementsBaseVertex, TRIANGLES, {relative}, {6}, 4 * q, 0, 0});
  calls.push_back({Call::kRangeElements, TRIANGLES, {18}, {12}, 0, 12, 19});
  calls.push_back({Call::kMultiElements, TRIANGLE_STRIP, {72 + 20, 72 + 28, 72 + 36}, {4, 4, 4}, 0, 0, 0});
  calls.push_back({Call::kMultiArrays, TRIANGLE_FAN, {24, 32, 40, 44}, {4, 4, 4, 4}, 0, 0, 0});
  b.DrawVariants(v, idx, calls);
}

// Integer attributes (VertexAttribIPointer): 4 x 4-pixel points coloured by the low bytes of an `ivec4` attribute,
// one quadrant a type (BYTE size 4, UNSIGNED_SHORT size 3, INT size 2 with a stride of 12, UNSIGNED_INT size 4),
// pseudo-random values over each type's whole range (so that only exact integers give the bytes), and a row whose
// attribute is disabled and read from VertexAttribI4i's current value. Attribute 3's VERTEX_ATTRIB_ARRAY_INTEGER
// is drawn too: the top row red where it reads 1.
void IntegerAttributes(Backend& b) {
  ClearBlack(b);
  b.PointSize(4.0f);
  std::uint32_t seed = 3;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return std::uint8_t(seed >> 24);
  };
  const struct Quadrant { float x, y; Enum type; int size, stride; } quadrants[] = {
      {0, 0, BYTE, 4, 0}, {64, 0, UNSIGNED_SHORT, 3, 0}, {0, 64, INT, 2, 12}, {64, 64, UNSIGNED_INT, 4, 0}};
  std::vector<int> integer_state;
  for (const Quadrant& q : quadrants) {
    std::vector<Vertex> points;
    for (int j = 0; j < 15; ++j)
      for (int i = 0; i < 16; ++i) points.push_back({Win(q.x + float(i) * 4 + 2, q.y + float(j) * 4 + 2)});
    const int element = q.type == BYTE ? 1 : q.type == UNSIGNED_SHORT ? 2 : 4;
    const int stride = q.stride ? q.stride : element * q.size;
    std::vector<std::uint8_t> bytes(points.size() * std::size_t(stride));
    for (std::uint8_t& v : bytes) v = next();
    integer_state.push_back(b.DrawIntegerAttribs(points, q.size, q.type, q.stride, bytes, {}));
  }
  std::vector<Vertex> row;
  for (int i = 0; i < 32; ++i) row.push_back({Win(float(i) * 4 + 2, 62)});
  integer_state.push_back(b.DrawIntegerAttribs(row, 4, INT, 0, {}, glm::ivec4(-1, 0x1234, 0x7F800001, -200)));
  std::vector<Vertex> flags;
  for (std::size_t k = 0; k < integer_state.size(); ++k)
    flags.push_back({Win(float(k) * 8 + 4, 126), integer_state[k] == 1 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 0, 1, 1)});
  b.Draw(POINTS, flags);
  b.PointSize(1.0f);
}

// A 4 x 3 grid of cells drawn by instanced calls, each instance placed by attribute 3 (divisor 1 or 2) and
// darkened by gl_InstanceID: row 0 one quad by DrawElementsInstanced, row 1 a fan by DrawArraysInstanced with
// divisor 2 (instances 2k and 2k + 1 in the same cell, the odd one on top), row 2 another quad through relative
// indices by DrawElementsInstancedBaseVertex.
void Instancing(Backend& b) {
  ClearBlack(b);
  std::vector<Vertex> v;
  const glm::vec2 quad[4] = {{3.25f, 4.5f}, {28.75f, 6.5f}, {25.75f, 37.5f}, {4.25f, 33.5f}};
  const glm::vec2 fan[4] = {{6.5f, 3.25f}, {29.25f, 10.5f}, {22.5f, 36.75f}, {2.75f, 29.5f}};
  for (int k = 0; k < 4; ++k) v.push_back({Win(quad[k].x, quad[k].y), Palette(unsigned(k))});
  for (int k = 0; k < 4; ++k) v.push_back({Win(fan[k].x, fan[k].y), Palette(unsigned(4 + k))});
  std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
  std::vector<glm::vec4> offsets;  // cell (column, row) in clip units, row by row
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) offsets.push_back(glm::vec4(float(col) * 0.5f, float(row) * 42.0f / 64.0f, 0, 0));
  using Call = DrawVariant::Call;
  std::vector<DrawVariant> calls;
  DrawVariant c{Call::kElementsInstanced, TRIANGLES, {0}, {6}};
  c.instances = 4;
  calls.push_back(c);
  c = {Call::kArraysInstanced, TRIANGLE_FAN, {4}, {4}};
  c.instances = 8;
  c.divisor = 2;
  c.instance_first = 4;
  calls.push_back(c);
  c = {Call::kElementsInstancedBaseVertex, TRIANGLES, {0}, {6}};
  c.basevertex = 4;
  c.instances = 4;
  c.instance_first = 8;
  calls.push_back(c);
  b.DrawInstanced(v, idx, offsets, calls);
}

// Primitive restart over a 4 x 3 grid of cells, each a ring of 8 vertices (vertex 8c .. 8c + 7 in cell c):
// row 0 strips and fans split by PrimitiveRestartIndex(1000), one with a base vertex (the index compared before
// it is added); row 1 line loops split by the fixed index 2^32 - 1, and a DrawArrays, which never restarts; row 2
// triangles whose runs leave incomplete triangles behind.
void PrimitiveRestart(Backend& b) {
  ClearBlack(b);
  std::vector<Vertex> v;
  for (int c = 0; c < 12; ++c) {
    const float cx = float(c % 4) * 32 + 16.25f, cy = float(c / 4) * 42 + 21.5f;
    for (int k = 0; k < 8; ++k) {
      const float a = 0.7853982f * float(k) + 0.3f, r = k % 2 ? 13.5f : 8.25f;
      // Row 1 (lines) in one colour per cell: lines interpolate colour differently from llvmpipe (line_interpolation).
      v.push_back({Win(cx + r * std::cos(a), cy + r * std::sin(a)), Palette(unsigned(c / 4 == 1 ? c : 8 * c + k))});
    }
  }
  const std::uint32_t R = 1000, F = 0xFFFFFFFFu;
  auto cell = [](std::uint32_t c, std::initializer_list<std::uint32_t> ks, std::uint32_t marker) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t k : ks) out.push_back(k == 99 ? marker : 8 * c + k);
    return out;
  };
  std::vector<std::uint32_t> idx;
  auto add = [&](const std::vector<std::uint32_t>& list) {
    const int first = int(idx.size());
    idx.insert(idx.end(), list.begin(), list.end());
    return first;
  };
  using Call = DrawVariant::Call;
  std::vector<DrawVariant> calls;
  // Row 0: a strip restarting twice (cell 0), a fan restarting once (cell 1), cells 2-3 through one base-vertex
  // list relative to cell 0 with restarts (a marker of 1000 - 16 would not restart).
  int f = add(cell(0, {99, 0, 1, 7, 2, 99, 3, 4, 2, 5, 99}, R));
  calls.push_back({Call::kRangeElements, TRIANGLE_STRIP, {f}, {11}, 0, 0, 1000});
  f = add(cell(1, {0, 1, 2, 3, 99, 4, 5, 6, 7, 0}, R));
  calls.push_back({Call::kMultiElements, TRIANGLE_FAN, {f}, {10}, 0, 0, 0});
  f = add(cell(0, {0, 1, 2, 99, 4, 5, 6, 7, 99, 99, 3, 4}, R));
  calls.push_back({Call::kElementsBaseVertex, TRIANGLE_FAN, {f}, {12}, 16, 0, 0});
  calls.push_back({Call::kElementsBaseVertex, TRIANGLE_STRIP, {f}, {12}, 24, 0, 0});
  b.Enable(PRIMITIVE_RESTART);
  b.PrimitiveRestartIndex(R);
  b.DrawVariants(v, idx, calls);

  // Row 1 with the fixed index (which takes precedence over PrimitiveRestartIndex).
  idx.clear();
  calls.clear();
  std::vector<int> firsts, counts;
  for (std::uint32_t c = 4; c < 7; ++c) {
    firsts.push_back(add(cell(c, {0, 1, 2, 3, 99, 4, 5, 6, 7, 99, 1000 - 8 * c, 99}, F)));
    counts.push_back(12);
  }
  calls.push_back({Call::kMultiElements, LINE_LOOP, firsts, counts, 0, 0, 0});
  calls.push_back({Call::kMultiArrays, LINE_STRIP, {56}, {8}, 0, 0, 0});  // cell 7: no restart
  // Row 2: triangles, runs of 4, 2 and 5 elements (the leftovers of each run are dropped).
  firsts.clear();
  counts.clear();
  for (std::uint32_t c = 8; c < 12; ++c) {
    firsts.push_back(add(cell(c, {0, 1, 2, 3, 99, 4, 5, 99, 5, 6, 7, 0, 1}, F)));
    counts.push_back(13);
  }
  calls.push_back({Call::kMultiElements, TRIANGLES, firsts, counts, 0, 0, 0});
  b.Enable(PRIMITIVE_RESTART_FIXED_INDEX);
  b.DrawVariants(v, idx, calls);
  b.Disable(PRIMITIVE_RESTART_FIXED_INDEX);
  b.Disable(PRIMITIVE_RESTART);
}

// Vertex data that reaches the buffer through MapBufferRange and CopyBufferSubData (left half: a fan of 24
// triangles, 40 vertices written through the mapping and 32 copied), and back through GetBufferSubData: what was
// read back is drawn again on the right, moved by half the width.
void Buffers(Backend& b) {
  ClearBlack(b);
  std::vector<Vertex> v;
  for (int i = 0; i < 24; ++i) {
    const float a0 = 0.2617994f * float(i) + 0.1f, a1 = a0 + 0.2617994f, r = i % 3 == 0 ? 28.5f : 22.25f;
    const float cx = 32.3125f, cy = 64.1875f;  // no edge through a pixel centre
    v.push_back({Win(cx, cy), Palette(unsigned(3 * i))});
    v.push_back({Win(cx + r * std::cos(a0), cy + r * std::sin(a0)), Palette(unsigned(3 * i + 1))});
    v.push_back({Win(cx + r * std::cos(a1), cy + r * std::sin(a1)), Palette(unsigned(3 * i + 2))});
  }
  std::vector<Vertex> back = b.DrawThroughBufferCalls(TRIANGLES, v, 40);
  for (Vertex& x : back) x.pos.x += 1.0f;  // 64 pixels right
  b.Draw(TRIANGLES, back);
}

// ---- Clipping and interpolation ------------------------------------------------------------------------------------

void Clipping(Backend& b) {
  ClearBlack(b);
  const glm::vec4 r(1, 0, 0, 1), g(0, 1, 0, 1), bl(0, 0, 1, 1), w(1, 1, 1, 1);
  std::vector<Vertex> v = {
      // Crossing the near plane (z < -w at one vertex), w varying.
      {{-0.9f, -0.9f, -3.0f, 1.0f}, r}, {{0.5f, -0.6f, 0.2f, 1.5f}, g}, {{-0.2f, 0.4f, 0.5f, 2.0f}, bl},
      // Crossing the far plane.
      {{0.2f, 0.1f, 0.9f, 1.0f}, w}, {{0.9f, 0.2f, 4.0f, 1.2f}, r}, {{0.5f, 0.9f, 0.1f, 0.8f}, g},
      // Crossing the left, top and right planes at once.
      {{-2.5f, 0.6f, 0.0f, 1.0f}, bl}, {{3.0f, 0.7f, 0.0f, 1.0f}, r}, {{0.1f, 2.0f, 0.3f, 1.0f}, g},
      // One vertex behind the eye (w < 0).
      {{-0.3f, -0.2f, 0.0f, 1.0f}, g}, {{0.2f, -0.5f, 0.0f, 1.0f}, w}, {{0.4f, 0.8f, -0.5f, -1.0f}, r},
      // Crossing the bottom and near planes with large w.
      {{-4.0f, -6.0f, -1.0f, 3.0f}, w}, {{4.0f, -5.0f, -9.0f, 4.0f}, bl}, {{0.0f, 2.0f, 1.0f, 5.0f}, r},
  };
  b.Draw(TRIANGLES, v);
}

void Perspective(Backend& b) {
  ClearBlack(b);
  const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 50.0f) *
                        glm::lookAt(glm::vec3(0, 1, 2), glm::vec3(0, 0, -6), glm::vec3(0, 1, 0));
  b.Draw(TRIANGLES, QuadWith(Floor(mvp, -3, 3, 1, -30), Uv({0, 0}, {1, 0}, {1, 1}, {0, 1})), Program::kUv);
}

// ---- Per-fragment operations ---------------------------------------------------------------------------------------

void DepthFunctions(Backend& b) {
  b.ClearColor(0, 0, 0, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  const Enum funcs[8] = {NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS};
  for (int i = 0; i < 8; ++i) {
    const float x0 = float(i) * 16, x1 = x0 + 16;
    b.DepthFunc(LESS);
    b.Draw(TRIANGLES, Rect(x0, 0, x1, 128, 0.0f, {0.2f, 0.2f, 0.6f, 1}));  // depth 0.5
    b.DepthFunc(funcs[i]);
    // Depth from 0.25 (bottom) to 0.75 (top), crossing 0.5 between two rows of centres.
    b.Draw(TRIANGLES, Quad(Win(x0, 0, -0.5f), Win(x1, 0, -0.5f), Win(x1, 128, 0.5f), Win(x0, 128, 0.5f), Palette(i)));
    // The base quad again: EQUAL and LEQUAL pass where the base depth is still stored.
    b.Draw(TRIANGLES, Rect(x0, 56, x1, 72, 0.0f, {1, 1, 1, 1}));
  }
  b.DepthFunc(LESS);
  b.DepthMask(false);
  b.Draw(TRIANGLES, Rect(0, 100, 128, 110, -0.9f, {1, 0.5f, 0, 1}));  // passes, writes no depth
  b.DepthMask(true);
  b.Disable(DEPTH_TEST);
}

void Stencil(Backend& b) {
  b.ClearColor(0, 0, 0, 1);
  b.ClearStencil(0x80);
  b.ClearDepth(0.5);
  b.Clear(COLOR_BUFFER_BIT | STENCIL_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(STENCIL_TEST);
  b.Enable(DEPTH_TEST);
  const Enum funcs[8] = {NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS};
  const Enum ops[8] = {KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP};
  for (int i = 0; i < 8; ++i) {
    const float x0 = float(i) * 16;
    // Front faces (counter-clockwise) in the lower half, back faces (clockwise) in the upper half, each with its
    // own function, reference, masks and operations.
    b.StencilFuncSeparate(FRONT, funcs[i], 0x80 + (i % 3) - 1, 0xF0 | unsigned(i));
    b.StencilFuncSeparate(BACK, funcs[7 - i], 0x7F + i, 0xFF);
    b.StencilOpSeparate(FRONT, ops[i], ops[(i + 3) % 8], ops[(i + 5) % 8]);
    b.StencilOpSeparate(BACK, ops[(i + 1) % 8], ops[(i + 6) % 8], ops[(i + 2) % 8]);
    b.StencilMaskSeparate(FRONT, 0xFF);
    b.StencilMaskSeparate(BACK, i % 2 ? 0x0F : 0xFF);
    for (int pass = 0; pass < 3; ++pass) {
      // Three overlapping draws: depth 0.25 (passes LESS against 0.5) on the left, 0.75 (fails) on the right.
      const float z = -0.5f;
      b.Draw(TRIANGLES, Quad(Win(x0, 0, z), Win(x0 + 8, 0, z), Win(x0 + 8, 64, z), Win(x0, 64, z), Palette(i)));
      b.Draw(TRIANGLES, Quad(Win(x0 + 8, 0, 0.5f), Win(x0 + 16, 0, 0.5f), Win(x0 + 16, 64, 0.5f),
                             Win(x0 + 8, 64, 0.5f), Palette(i)));
      b.Draw(TRIANGLES, Quad(Win(x0, 128, z), Win(x0 + 16, 128, z), Win(x0 + 16, 64, z), Win(x0, 64, z), Palette(i + 8)));
    }
  }
  // Show the stencil values as colours: four bands of values.
  b.Disable(DEPTH_TEST);
  b.StencilOp(KEEP, KEEP, KEEP);
  const int bands[4] = {0x00, 0x7F, 0x80, 0x81};
  for (int k = 0; k < 4; ++k) {
    b.StencilFunc(EQUAL, bands[k], 0xFF);
    b.Draw(TRIANGLES, Rect(0, 0, 128, 128, 0.0f, Palette(100 + unsigned(k))));
  }
  b.Disable(STENCIL_TEST);
}

const Enum kFactors[15] = {ZERO,      ONE,       SRC_COLOR,          ONE_MINUS_SRC_COLOR,   DST_COLOR,
                           ONE_MINUS_DST_COLOR,  SRC_ALPHA,          ONE_MINUS_SRC_ALPHA,   DST_ALPHA,
                           ONE_MINUS_DST_ALPHA,  CONSTANT_COLOR,     ONE_MINUS_CONSTANT_COLOR, CONSTANT_ALPHA,
                           ONE_MINUS_CONSTANT_ALPHA, SRC_ALPHA_SATURATE};

// 15 x 15 cells of 8 x 8 pixels: source factor by column, destination factor by row, over a different
// destination colour in every cell; alpha uses the factors swapped.
void BlendFactors(Backend& b) {
  b.ClearColor(0, 0, 0, 0);
  b.Clear(COLOR_BUFFER_BIT);
  b.BlendColor(0.3f, 0.6f, 0.9f, 0.4f);
  for (int s = 0; s < 15; ++s)
    for (int d = 0; d < 15; ++d) {
      const float x0 = float(s) * 8 + 4, y0 = float(d) * 8 + 4;
      const unsigned cell = unsigned(s * 15 + d);
      glm::vec4 dst = Palette(cell), src = Palette(cell + 1000);
      dst.a = float((cell * 37) % 256) / 255.0f;
      src.a = float((cell * 91 + 13) % 256) / 255.0f;
      b.Disable(BLEND);
      b.Draw(TRIANGLES, Rect(x0, y0, x0 + 8, y0 + 8, 0.0f, dst));
      b.Enable(BLEND);
      b.BlendFuncSeparate(kFactors[s], kFactors[d], kFactors[d], kFactors[s]);
      b.Draw(TRIANGLES, Rect(x0, y0, x0 + 8, y0 + 8, 0.0f, src));
    }
  b.Disable(BLEND);
}

void BlendEquations(Backend& b) {
  b.ClearColor(0, 0, 0, 0);
  b.Clear(COLOR_BUFFER_BIT);
  const Enum eqs[5] = {FUNC_ADD, FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN, MAX};
  for (int e = 0; e < 5; ++e)
    for (int a = 0; a < 5; ++a)
      for (int k = 0; k < 6; ++k) {
        const float x0 = float(e * 5 + a) * 5, y0 = float(k) * 20;
        const unsigned cell = unsigned((e * 5 + a) * 6 + k);
        b.Disable(BLEND);
        b.Draw(TRIANGLES, Rect(x0, y0, x0 + 5, y0 + 20, 0.0f, Palette(cell)));
        b.Enable(BLEND);
        b.BlendEquationSeparate(eqs[e], eqs[a]);
        b.BlendFuncSeparate(kFactors[(k * 4 + 2) % 15], kFactors[(k * 7 + 5) % 15], SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
        glm::vec4 src = Palette(cell + 500);
        src.a = float((cell * 53) % 256) / 255.0f;
        b.Draw(TRIANGLES, Rect(x0, y0, x0 + 5, y0 + 20, 0.0f, src));
      }
  b.Disable(BLEND);
  b.BlendEquationSeparate(FUNC_ADD, FUNC_ADD);
}

void Masks(Backend& b) {
  b.ClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  b.ClearDepth(1.0);
  b.ClearStencil(0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  b.Enable(STENCIL_TEST);
  b.StencilFunc(ALWAYS, 0xFF, 0xFF);
  b.StencilOp(KEEP, KEEP, REPLACE);
  for (int i = 0; i < 16; ++i) {
    b.ColorMask(i & 1, i & 2, i & 4, i & 8);
    b.DepthMask(i % 3 != 0);
    b.StencilMaskSeparate(FRONT_AND_BACK, unsigned(i * 17) & 0xFF);
    const float x0 = float(i % 4) * 32, y0 = float(i / 4) * 32;
    b.Draw(TRIANGLES, Rect(x0, y0, x0 + 24, y0 + 24, -0.2f, Palette(unsigned(i))));
  }
  // Clears honour the masks too.
  b.ColorMask(false, true, false, true);
  b.DepthMask(false);
  b.StencilMaskSeparate(FRONT_AND_BACK, 0x0F);
  b.ClearColor(1, 1, 1, 1);
  b.ClearDepth(0.0);
  b.ClearStencil(0x33);
  b.Enable(SCISSOR_TEST);
  b.Scissor(10, 10, 100, 40);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  b.Disable(SCISSOR_TEST);
  b.ColorMask(true, true, true, true);
  b.DepthMask(true);
  b.StencilMaskSeparate(FRONT_AND_BACK, 0xFF);
  // Make depth visible: a quad at depth 0.6 where the stored depth is nearer fails.
  b.StencilFunc(ALWAYS, 0, 0);
  b.StencilOp(KEEP, KEEP, KEEP);
  b.Draw(TRIANGLES, Rect(0, 100, 128, 128, 0.2f, {1, 0, 1, 1}));
  b.Disable(DEPTH_TEST);
  b.Disable(STENCIL_TEST);
}

// ClearBuffer: colour, depth and stencil cleared one buffer at a time, through the scissor box, the colour mask,
// the depth mask and the stencil write mask; then quads that the depth and stencil tests let through where the
// clears left values that pass, so that depth and stencil show in the colours too.
void ClearBuffers(Backend& b) {
  const float grey[4] = {0.3f, 0.3f, 0.3f, 1.0f};
  b.ClearBufferfv(COLOR, 0, grey);
  b.ClearBufferfi(DEPTH_STENCIL, 0, 1.0f, 0);
  b.Enable(SCISSOR_TEST);
  const float colours[3][4] = {{0.9f, 0.2f, 0.1f, 1.0f}, {0.1f, 0.8f, 0.3f, 0.5f}, {0.2f, 0.3f, 1.0f, 0.0f}};
  for (int i = 0; i < 3; ++i) {
    b.Scissor(8 + i * 40, 8, 32, 112);
    b.ColorMask(true, i != 1, true, i != 2);
    b.ClearBufferfv(COLOR, 0, colours[i]);
    const float depth = 0.2f + 0.3f * float(i);
    b.ClearBufferfv(DEPTH, 0, &depth);
  }
  b.ColorMask(true, true, true, true);
  b.Scissor(0, 64, 128, 40);
  b.StencilMaskSeparate(FRONT_AND_BACK, 0x0F);
  const int stencil = 0x35;
  b.ClearBufferiv(STENCIL, 0, &stencil);
  b.StencilMaskSeparate(FRONT_AND_BACK, 0xFF);
  b.Scissor(20, 20, 30, 20);
  b.DepthMask(false);
  b.ClearBufferfi(DEPTH_STENCIL, 0, 0.0f, 7);  // the depth mask keeps the depth; the stencil is written
  b.DepthMask(true);
  b.Disable(SCISSOR_TEST);
  b.Enable(DEPTH_TEST);
  b.Enable(STENCIL_TEST);
  b.StencilFunc(EQUAL, 0x05, 0xFF);
  b.StencilOp(KEEP, KEEP, KEEP);
  b.Draw(TRIANGLES, Rect(0, 0, 128, 128, 0.1f, {1, 1, 0, 1}));  // depth 0.55: behind the clears of 0.2 and 0.5
  b.StencilFunc(EQUAL, 7, 0xFF);
  b.Draw(TRIANGLES, Rect(0, 0, 128, 128, 0.1f, {0, 1, 1, 1}));
  b.Disable(DEPTH_TEST);
  b.Disable(STENCIL_TEST);
}

// Conditional rendering: in each of 16 cells an occlusion query over a quad in front of or behind an occluder
// (colour writes off), then, conditional on it, a quad, a scissored Clear and a ClearBuffer in the cell, and a
// quad across the whole row after the end. Both occlusion targets, both waiting modes, culled and visible.
void ConditionalRender(Backend& b) {
  ClearBlack(b);
  b.ClearDepth(1.0);
  b.Clear(DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  b.ColorMask(false, false, false, false);
  b.Draw(TRIANGLES, Rect(0, 0, 64, 128, 0.0f, {1, 1, 1, 1}));  // the occluder: the left half, depth 0.5
  b.ColorMask(true, true, true, true);
  for (int i = 0; i < 16; ++i) {
    const int cx = (i % 4) * 32, cy = (i / 4) * 32;
    const std::uint32_t q = b.GenQuery();
    const Enum target = i % 3 ? SAMPLES_PASSED : ANY_SAMPLES_PASSED;
    b.ColorMask(false, false, false, false);
    b.DepthMask(false);
    b.BeginQuery(target, q);
    // Behind the occluder in the left half (no samples pass) but in cell 5, whose quad is in front.
    b.Draw(TRIANGLES, Rect(float(cx + 4), float(cy + 4), float(cx + 28), float(cy + 28), i == 5 ? -0.5f : 0.4f, {1, 1, 1, 1}));
    b.EndQuery(target);
    b.DepthMask(true);
    b.ColorMask(true, true, true, true);
    b.BeginConditionalRender(q, i % 2 ? QUERY_WAIT : QUERY_BY_REGION_WAIT);
    b.Draw(TRIANGLES, Rect(float(cx + 2), float(cy + 2), float(cx + 30), float(cy + 16), -0.9f, Palette(unsigned(i))));
    b.Enable(SCISSOR_TEST);
    b.Scissor(cx + 2, cy + 18, 28, 6);
    b.ClearColor(0.25f, 0.5f, 0.75f, 1);
    b.Clear(COLOR_BUFFER_BIT);
    b.Scissor(cx + 2, cy + 25, 28, 5);
    const float white[4] = {1, 1, 1, 1};
    b.ClearBufferfv(COLOR, 0, white);
    b.Disable(SCISSOR_TEST);
    b.EndConditionalRender();
    b.Draw(TRIANGLES, Rect(float(cx), float(cy + 30), float(cx + 32), float(cy + 32), -0.9f, {1, 0.5f, 0, 1}));
  }
  b.Disable(DEPTH_TEST);
}

// The layers of LayeredFramebuffers' three textures (a 2D array and a 3D texture of 3, a cube map of 6, on units
// 3, 4 and 1), each sampled (NEAREST) on a 32 x 32 square of the window.
void ShowLayers(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, 0);
  b.Viewport(0, 0, kSize, kSize);
  ClearBlack(b);
  auto cell = [&](int x, int y, const Corners& extra, Program p) {
    const float x0 = float(x * 32), y0 = float(y * 32);
    b.Draw(TRIANGLES, QuadWith({Win(x0, y0), Win(x0 + 32, y0), Win(x0 + 32, y0 + 32), Win(x0, y0 + 32)}, extra), p);
  };
  for (int l = 0; l < 3; ++l) {
    const float z = float(l);
    cell(l, 3, {glm::vec4(0, 0, z, 0), glm::vec4(1, 0, z, 0), glm::vec4(1, 1, z, 0), glm::vec4(0, 1, z, 0)}, Program::kArray);
    const float r = (z + 0.5f) / 3.0f;
    cell(l, 2, {glm::vec4(0, 0, r, 0), glm::vec4(1, 0, r, 0), glm::vec4(1, 1, r, 0), glm::vec4(0, 1, r, 0)}, Program::kVolume);
  }
  // Each cube face: its major axis plus the two others, corners at +-0.99.
  for (int f = 0; f < 6; ++f) {
    glm::vec3 m(0.0f), u(0.0f), w(0.0f);
    m[f / 2] = f % 2 ? -1.0f : 1.0f;
    u[(f / 2 + 1) % 3] = 0.99f;
    w[(f / 2 + 2) % 3] = 0.99f;
    const Corners dirs = {glm::vec4(m - u - w, 0), glm::vec4(m + u - w, 0), glm::vec4(m + u + w, 0), glm::vec4(m - u + w, 0)};
    cell(f % 4, f / 4, dirs, Program::kCube);
  }
}

// Layered framebuffers: a 2D array of 3 layers with a layered depth array, a 3D texture of 3 slices and a cube
// map, each attached whole (FramebufferTexture). Clear, a scissored Clear and a ClearBuffer reach every layer, two
// depth-tested quads only layer 0; then every layer is shown by sampling it (NEAREST) in the window.
void LayeredFramebuffers(Backend& b) {
  const Enum kinds[3] = {TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_CUBE_MAP};
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t fbo = b.GenFramebuffer();
    b.BindFramebuffer(FRAMEBUFFER, fbo);
    b.AttachLayered(FRAMEBUFFER, COLOR_ATTACHMENT0, kinds[k], RGBA8, 16, kinds[k] == TEXTURE_CUBE_MAP ? 6 : 3, -1);
    if (k == 0) b.AttachLayered(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D_ARRAY, DEPTH_COMPONENT32F, 16, 3, -1);
    b.Viewport(0, 0, 16, 16);
    const glm::vec4 base = Palette(unsigned(3 * k + 1));
    b.ClearColor(base.r, base.g, base.b, 1);
    b.ClearDepth(0.5);
    b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    b.Enable(SCISSOR_TEST);
    b.Scissor(8, 8, 8, 8);
    b.ClearColor(0.1f, 0.2f, 0.9f, 1);
    b.Clear(COLOR_BUFFER_BIT);
    b.Scissor(0, 8, 8, 8);
    const float white[4] = {1, 1, 1, 1};
    b.ClearBufferfv(COLOR, 0, white);
    b.Disable(SCISSOR_TEST);
    b.Enable(DEPTH_TEST);  // in front of the cleared depth 0.5 (drawn), then behind it (not drawn where there is depth)
    b.Draw(TRIANGLES, Quad({-0.75f, -0.75f, -0.5f, 1}, {0.25f, -0.75f, -0.5f, 1}, {0.25f, 0.25f, -0.5f, 1},
                           {-0.75f, 0.25f, -0.5f, 1}, {1, 0.5f, 0, 1}));
    b.Draw(TRIANGLES, Quad({-0.25f, -0.25f, 0.5f, 1}, {0.75f, -0.25f, 0.5f, 1}, {0.75f, 0.75f, 0.5f, 1},
                           {-0.25f, 0.75f, 0.5f, 1}, {0, 1, 0.5f, 1}));
    b.Disable(DEPTH_TEST);
  }
  ShowLayers(b);
}

// A new framebuffer bound, with every layer of a new 16 x 16 RGBA8 texture of `kind` (three layers, or a cube map's
// six) attached as its colour, the viewport and clear colour set for it; returns the number of layers.
int BindLayeredTarget(Backend& b, Enum kind) {
  const int layers = kind == TEXTURE_CUBE_MAP ? 6 : 3;
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  b.AttachLayered(FRAMEBUFFER, COLOR_ATTACHMENT0, kind, RGBA8, 16, layers, -1);
  b.Viewport(0, 0, 16, 16);
  b.ClearColor(0.2f, 0.2f, 0.25f, 1);
  return layers;
}

// gl_Layer from the vertex stage: the same three layered textures, each cleared, then one draw of a quad per layer
// (different sizes and colours, depth-tested where there is depth), a quad whose first vertex names another layer
// than its provoking (last) one, and quads naming layers past the last and below 0; shown as LayeredFramebuffers.
void VertexLayer(Backend& b) {
  const Enum kinds[3] = {TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_CUBE_MAP};
  for (int k = 0; k < 3; ++k) {
    const int layers = BindLayeredTarget(b, kinds[k]);
    if (k == 0) b.AttachLayered(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D_ARRAY, DEPTH_COMPONENT32F, 16, 3, -1);
    b.ClearDepth(1.0);
    b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    b.Enable(DEPTH_TEST);
    std::vector<Vertex> v;
    auto quad = [&](float x0, float y0, float x1, float y1, float z, glm::vec4 c, float layer, float first = -100) {
      const glm::vec4 lw(0, 0, 0, layer), fw(0, 0, 0, first == -100 ? layer : first);
      const Vertex q[4] = {{{x0, y0, z, 1}, c, lw}, {{x1, y0, z, 1}, c, lw}, {{x1, y1, z, 1}, c, lw}, {{x0, y1, z, 1}, c, lw}};
      for (int i : {0, 1, 3, 1, 2, 3}) v.push_back(q[i]);
      v[v.size() - 6].extra = fw;  // the first triangle's first vertex (not its provoking one)
    };
    for (int l = 0; l < layers; ++l) {
      const float e = 0.9f - 0.1f * float(l);
      quad(-e, -e, e * 0.5f, e * 0.5f, 0.2f, Palette(unsigned(l + 2 * k)), float(l));
    }
    quad(0.1f, -0.9f, 0.9f, -0.1f, -0.3f, {1, 1, 1, 1}, 1.0f, 0.0f);
    quad(-0.9f, 0.3f, -0.3f, 0.9f, -0.5f, {1, 0.5f, 0, 1}, float(layers + 2));
    quad(0.3f, 0.3f, 0.9f, 0.9f, -0.5f, {0, 1, 1, 1}, -1.0f);
    b.Draw(TRIANGLES, v, Program::kLayer);
    b.Disable(DEPTH_TEST);
  }
  ShowLayers(b);
}

// The geometry stage: triangles of a list and of a strip (some with w = 2) shrunk, twice per triangle by two
// invocations, the second coloured by gl_PrimitiveIDIn and for even ids followed by a second strip (EndPrimitive);
// points made squares, some followed by a second square (lanes that emit different numbers of vertices).
void GeometryStage(Backend& b) {
  ClearBlack(b);
  std::vector<Vertex> list;
  for (int i = 0; i < 6; ++i) {
    const float x = -0.875f + 0.3125f * float(i);
    list.push_back({{x, 0.125f, 0, 1}, Palette(unsigned(3 * i))});
    list.push_back({{x + 0.25f, 0.1875f, 0, 1}, Palette(unsigned(3 * i + 1))});
    list.push_back({{x + 0.125f, 0.875f, 0, 1}, Palette(unsigned(3 * i + 2))});
  }
  b.Draw(TRIANGLES, list, Program::kGeometryShrink);
  std::vector<Vertex> strip;
  for (int i = 0; i < 9; ++i) {
    const float w = (i % 3 == 0) ? 2.0f : 1.0f;
    strip.push_back({glm::vec4(-0.9375f + 0.1875f * float(i), (i % 2) ? -0.125f : -0.625f, 0, 1) * w,
                     Palette(unsigned(20 + i))});
  }
  b.Draw(TRIANGLE_STRIP, strip, Program::kGeometryShrink);
  std::vector<Vertex> points;
  for (int i = 0; i < 7; ++i) {
    const float w = (i % 2) ? 2.0f : 1.0f;
    const glm::vec4 p(-0.875f + 0.25f * float(i), -0.875f, 0.5f, 1.0f);
    points.push_back({glm::vec4(p.x * w, p.y * w, p.z * w, w), Palette(unsigned(40 + i)),
                      glm::vec4(0.015625f * float(1 + i % 3), (i % 3 == 1) ? 1.0f : 0.0f, 0, 0)});
  }
  b.Draw(POINTS, points, Program::kGeometrySprites);
}

// Adjacency: triangles and lines with adjacency, as lists and strips (one triangle, several, odd and even), through
// geometry stages that colour each vertex as an adjacent one, then the same modes without a geometry stage, which
// draw the lines and triangles alone.
void GeometryAdjacency(Backend& b) {
  ClearBlack(b);
  // A strip's own vertices at even positions (a zigzag from x0), the adjacent ones at odd positions.
  auto zigzag = [](int n, float x0, float y0, unsigned colour) {
    std::vector<Vertex> v;
    for (int i = 0; i < n; ++i) {
      const int m = i / 2;
      const glm::vec4 own(x0 + 0.125f * float(m), y0 + ((m % 2) ? 0.25f : 0.0f), 0, 1);
      v.push_back({(i % 2) ? own + glm::vec4(0.0625f, -0.5f, 0, 0) : own, Palette(colour + unsigned(i))});
    }
    return v;
  };
  b.Draw(TRIANGLES_ADJACENCY, zigzag(12, -0.875f, 0.5f, 0), Program::kGeometryAdjacency);
  b.Draw(TRIANGLE_STRIP_ADJACENCY, zigzag(6, -0.25f, 0.5f, 20), Program::kGeometryAdjacency);
  b.Draw(TRIANGLE_STRIP_ADJACENCY, zigzag(15, 0.125f, 0.5f, 40), Program::kGeometryAdjacency);
  b.Draw(TRIANGLE_STRIP_ADJACENCY, zigzag(14, -0.875f, -0.125f, 60), Program::kColor);
  b.Draw(TRIANGLES_ADJACENCY, zigzag(12, 0.125f, -0.125f, 80), Program::kColor);
  std::vector<Vertex> lines;
  for (int i = 0; i < 9; ++i)
    lines.push_back({{-0.9375f + 0.1875f * float(i), (i % 2) ? -0.5f : -0.6875f, 0, 1}, Palette(unsigned(100 + i))});
  b.Draw(LINES_ADJACENCY, lines, Program::kGeometryLineAdjacency);
  for (Vertex& v : lines) v.pos.y -= 0.125f;
  b.Draw(LINE_STRIP_ADJACENCY, lines, Program::kGeometryLineAdjacency);
  for (Vertex& v : lines) v.pos.y -= 0.125f;
  b.Draw(LINE_STRIP_ADJACENCY, lines, Program::kColor);
}

// gl_Layer from the geometry stage: the layered textures of VertexLayer, each triangle drawn by three invocations
// into three consecutive layers from the one its last vertex names (past the last: the last), darker each time.
void GeometryLayer(Backend& b) {
  const Enum kinds[3] = {TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_CUBE_MAP};
  for (int k = 0; k < 3; ++k) {
    const int layers = BindLayeredTarget(b, kinds[k]);
    b.Clear(COLOR_BUFFER_BIT);
    std::vector<Vertex> v;
    auto triangle = [&](float x0, float y0, float x1, float y1, glm::vec4 c, float layer) {
      const glm::vec4 lw(0, 0, 0, layer);
      for (const glm::vec4& p : {glm::vec4(x0, y0, 0, 1), glm::vec4(x1, y0, 0, 1), glm::vec4(x0, y1, 0, 1)})
        v.push_back({p, c, lw});
    };
    triangle(-0.875f, -0.875f, 0.75f, 0.5f, Palette(unsigned(3 * k)), 0.0f);
    triangle(0.875f, 0.875f, -0.5f, -0.25f, Palette(unsigned(3 * k + 1)), float(layers - 2));
    b.Draw(TRIANGLES, v, Program::kGeometryLayer);
  }
  ShowLayers(b);
}

void Scissor(Backend& b) {
  ClearBlack(b);
  b.Enable(SCISSOR_TEST);
  const int rects[][4] = {{0, 0, 64, 64}, {40, 30, 50, 70}, {100, 100, 100, 100}, {-20, 90, 50, 60}, {5, 5, 0, 50}};
  for (int i = 0; i < 5; ++i) {
    b.Scissor(rects[i][0], rects[i][1], rects[i][2], rects[i][3]);
    b.ClearColor(0.1f * float(i), 0.2f, 0.3f, 1);
    b.Clear(COLOR_BUFFER_BIT);
    b.Draw(TRIANGLES, {{Win(-10, -10), Palette(unsigned(i))}, {Win(140, 20), Palette(unsigned(i))},
                       {Win(60, 140), Palette(unsigned(i))}});
  }
  b.Disable(SCISSOR_TEST);
}

void PolygonOffset(Backend& b) {
  b.ClearColor(0, 0, 0, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  // A tilted plane, then a smaller coplanar quad pulled forward by the slope term.
  const glm::mat4 mvp = glm::perspective(glm::radians(50.0f), 1.0f, 1.0f, 20.0f) *
                        glm::lookAt(glm::vec3(0, 3, 4), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
  auto plane = [&](float half, glm::vec4 c) { return QuadWith(Floor(mvp, -half, half, half, -half), {}, c); };
  b.Draw(TRIANGLES, plane(3.0f, Palette(1)));
  b.Enable(POLYGON_OFFSET_FILL);
  b.PolygonOffset(-1.0f, -1.0f);
  b.Draw(TRIANGLES, plane(1.5f, Palette(2)));
  // A flat (constant depth) pair: only the units term separates them.
  b.PolygonOffset(0.0f, 0.0f);
  b.Draw(TRIANGLES, Rect(8, 8, 40, 40, 0.1f, {0, 0, 1, 1}));
  b.PolygonOffset(0.0f, -4.0f);
  b.Draw(TRIANGLES, Rect(16, 16, 32, 32, 0.1f, {0, 1, 0, 1}));
  b.PolygonOffset(0.0f, 4.0f);  // pushed back: fails
  b.Draw(TRIANGLES, Rect(20, 20, 48, 28, 0.1f, {1, 0, 0, 1}));
  b.Disable(POLYGON_OFFSET_FILL);
  b.Disable(DEPTH_TEST);
}

// ---- Textures ----------------------------------------------------------------------------------------------------

// A 64 x 64 pattern level and its mipmaps computed here (each texel the pattern at that level's scale), each level
// tinted a little differently, so that a wrong level choice shows; channels are exact bytes.
TextureDesc PatternTexture(bool tint_levels) {
  TextureDesc d;
  for (int size = 64, level = 0; size >= 1; size /= 2, ++level) {
    TextureDesc::Level l;
    l.width = l.height = size;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int scale = 64 / size;
        const int X = x * scale, Y = y * scale;
        const bool check = ((X / 8) + (Y / 8)) % 2 == 0, line = X % 16 < 2;
        std::uint8_t r = check ? 230 : 40, g = line ? 200 : std::uint8_t(X * 4), b = std::uint8_t(Y * 4);
        if (tint_levels) r = std::uint8_t(r * 3 / 4 + level * 10);  // levels apart, as real mipmaps are
        l.rgba.insert(l.rgba.end(), {r, g, b, 255});
      }
    d.levels.push_back(std::move(l));
  }
  return d;
}

// A floor receding to the horizon, with uv repeating `repeat` times, drawn in the viewport rectangle given.
void RecedingPlane(Backend& b, int x, int y, int w, int h, float repeat) {
  b.Viewport(x, y, w, h);
  const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), float(w) / float(h), 0.3f, 60.0f) *
                        glm::lookAt(glm::vec3(0, 1, 1), glm::vec3(0, 0, -8), glm::vec3(0, 1, 0));
  b.Draw(TRIANGLES,
         QuadWith(Floor(mvp, -6, 6, 1, -40), Uv({0, 0}, {repeat, 0}, {repeat, repeat * 3.5f}, {0, repeat * 3.5f})),
         Program::kTexture);
  b.Viewport(0, 0, kSize, kSize);
}

void TextureFilters(Backend& b) {
  ClearBlack(b);
  const Enum mins[6] = {NEAREST, LINEAR, NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_NEAREST, NEAREST_MIPMAP_LINEAR,
                        LINEAR_MIPMAP_LINEAR};
  for (int i = 0; i < 6; ++i) {
    TextureDesc d = PatternTexture(true);
    d.min_filter = mins[i];
    d.mag_filter = i % 2 ? LINEAR : NEAREST;
    b.SetTexture(d);
    RecedingPlane(b, (i % 3) * 42, (i / 3) * 64, 42, 64, 4.0f);
  }
}

void TextureWraps(Backend& b) {
  ClearBlack(b);
  const Enum wraps[4] = {REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER};
  for (int i = 0; i < 8; ++i) {
    TextureDesc d = PatternTexture(false);
    d.levels.resize(1);
    d.levels[0].width = d.levels[0].height = 64;
    d.min_filter = d.mag_filter = i < 4 ? NEAREST : LINEAR;
    d.wrap_s = wraps[i % 4];
    d.wrap_t = wraps[(i + 1) % 4];
    d.border = glm::vec4(0.2f, 0.6f, 1.0f, 1.0f);
    b.SetTexture(d);
    // A quad of 32 x 64 pixels with uv from -1.25 to 2.25: each texel is magnified, wrapping shows.
    const float x0 = float(i % 4) * 32, y0 = float(i / 4) * 64;
    const std::vector<Vertex> v =
        QuadWith({Win(x0, y0), Win(x0 + 32, y0), Win(x0 + 32, y0 + 64), Win(x0, y0 + 64)},
                 Uv({-1.25f, -1.25f}, {2.25f, -1.25f}, {2.25f, 2.25f}, {-1.25f, 2.25f}));
    b.Draw(TRIANGLES, v, Program::kTexture);
  }
}

// Sampler objects: texture_wraps' quads with the texture's own state left at NEAREST / REPEAT, and each quad's
// wrap modes, filters and border colour from a sampler object bound to unit 0; then a trilinear receding floor
// whose LOD bias and LOD range come from a sampler, and a last quad drawn with the sampler unbound (the texture's
// NEAREST / REPEAT again).
void SamplerObjects(Backend& b) {
  ClearBlack(b);
  const Enum wraps[4] = {REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER};
  TextureDesc d = PatternTexture(false);
  d.levels.resize(1);
  d.levels[0].width = d.levels[0].height = 64;
  d.min_filter = d.mag_filter = NEAREST;
  b.SetTexture(d);
  const std::uint32_t sampler = b.GenSampler();
  b.BindSampler(0, sampler);
  const glm::vec4 border(0.2f, 0.6f, 1.0f, 1.0f);
  b.SamplerParameterfv(sampler, TEXTURE_BORDER_COLOR, &border[0]);
  for (int i = 0; i < 4; ++i) {
    b.SamplerParameteri(sampler, TEXTURE_MIN_FILTER, i < 2 ? LINEAR : NEAREST);
    b.SamplerParameteri(sampler, TEXTURE_MAG_FILTER, i < 2 ? LINEAR : NEAREST);
    b.SamplerParameteri(sampler, TEXTURE_WRAP_S, int(wraps[i]));
    b.SamplerParameteri(sampler, TEXTURE_WRAP_T, int(wraps[(i + 3) % 4]));
    const float x0 = float(i) * 32;
    b.Draw(TRIANGLES,
           QuadWith({Win(x0, 0), Win(x0 + 32, 0), Win(x0 + 32, 48), Win(x0, 48)},
                    Uv({-1.25f, -1.25f}, {2.25f, -1.25f}, {2.25f, 2.25f}, {-1.25f, 2.25f})),
           Program::kTexture);
  }
  TextureDesc mip = PatternTexture(true);
  mip.min_filter = mip.mag_filter = NEAREST;
  b.SetTexture(mip);
  b.SamplerParameteri(sampler, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  b.SamplerParameteri(sampler, TEXTURE_MAG_FILTER, LINEAR);
  b.SamplerParameteri(sampler, TEXTURE_WRAP_S, REPEAT);
  b.SamplerParameteri(sampler, TEXTURE_WRAP_T, REPEAT);
  const float bias = 0.75f, min_lod = 0.5f, max_lod = 2.0f;
  b.SamplerParameterfv(sampler, TEXTURE_LOD_BIAS, &bias);
  b.SamplerParameterfv(sampler, TEXTURE_MIN_LOD, &min_lod);
  b.SamplerParameterfv(sampler, TEXTURE_MAX_LOD, &max_lod);
  RecedingPlane(b, 0, 48, 96, 80, 4.0f);
  b.BindSampler(0, 0);
  b.Draw(TRIANGLES,
         QuadWith({Win(96, 48), Win(128, 48), Win(128, 128), Win(96, 128)},
                  Uv({-0.5f, -0.5f}, {1.5f, -0.5f}, {1.5f, 1.5f}, {-0.5f, 1.5f})),
         Program::kTexture);
}

void TextureGeneratedMipmaps(Backend& b) {
  ClearBlack(b);
  TextureDesc d = PatternTexture(false);
  d.levels.resize(1);
  d.generate_mipmap = true;
  d.min_filter = LINEAR_MIPMAP_LINEAR;
  b.SetTexture(d);
  RecedingPlane(b, 0, 0, kSize, kSize, 6.0f);
}

// Anisotropic filtering: the receding floor of texture_filters with TEXTURE_MAX_ANISOTROPY 16 (left) and 4
// (right), trilinear, the levels given. OpenGL leaves the anisotropic filter to the implementation: llvmpipe's
// differs from softgl's (N probes along the longer axis of the footprint, as EXT_texture_filter_anisotropic
// describes), by up to 176 where the floor recedes most, so the scene checks coverage and reports the colours.
void TextureAnisotropic(Backend& b) {
  ClearBlack(b);
  for (int i = 0; i < 2; ++i) {
    TextureDesc d = PatternTexture(true);
    d.max_anisotropy = i == 0 ? 16.0f : 4.0f;
    b.SetTexture(d);
    RecedingPlane(b, i * 64, 0, 64, kSize, 4.0f);
  }
}

// The pattern as an SRGB8_ALPHA8 texture with its levels given, drawn trilinear on a receding floor (texels decoded
// to linear before filtering), and level 0 magnified with NEAREST above it (the decoding alone). The default
// framebuffer is linear, so what is compared is the filtered linear colour. (GenerateMipmap's filter is the
// implementation's choice: llvmpipe's sRGB levels differ from softgl's by up to 3, so they are not compared here.)
void SrgbTexture(Backend& b) {
  ClearBlack(b);
  TextureDesc d = PatternTexture(true);
  d.internal_format = SRGB8_ALPHA8;
  d.min_filter = LINEAR_MIPMAP_LINEAR;
  b.SetTexture(d);
  RecedingPlane(b, 0, 0, kSize, kSize / 2, 6.0f);
  d.min_filter = NEAREST;  // one texel each, magnified: the decode table alone
  d.mag_filter = NEAREST;
  b.SetTexture(d);
  b.Draw(TRIANGLES, QuadWith({Win(0, 64), Win(128, 64), Win(128, 128), Win(0, 128)}, Uv({0, 0}, {1, 0}, {1, 0.5f}, {0, 0.5f})),
         Program::kTexture);
}

// Compressed textures: the pattern with its levels (alpha varied across it) encoded here into six formats, drawn
// trilinear on receding floors: DXT1, DXT1 with its one-bit alpha (alpha shows in the frame's alpha), DXT3, DXT5,
// sRGB DXT1 (decoded to linear before filtering) and RGTC2 (red and green); then signed RGTC1 (red - 128 as a
// signed byte: negative halves clamp to 0 in the frame) magnified with NEAREST and LINEAR across the top.
void CompressedTextures(Backend& b) {
  ClearBlack(b);
  const Enum formats[6] = {COMPRESSED_RGB_S3TC_DXT1_EXT,  COMPRESSED_RGBA_S3TC_DXT1_EXT,
                           COMPRESSED_RGBA_S3TC_DXT3_EXT, COMPRESSED_RGBA_S3TC_DXT5_EXT,
                           COMPRESSED_SRGB_S3TC_DXT1_EXT, COMPRESSED_RG_RGTC2};
  TextureDesc pattern = PatternTexture(true);
  for (TextureDesc::Level& l : pattern.levels)
    for (int i = 0; i < l.width * l.height; ++i) l.rgba[std::size_t(i * 4 + 3)] = std::uint8_t(i * 255 / std::max(1, l.width * l.height - 1));
  for (int i = 0; i < 6; ++i) {
    TextureDesc d = pattern;
    d.compressed = formats[i];
    for (TextureDesc::Level& l : d.levels) l.blocks = scenes::kit::EncodeBlocks(l.rgba.data(), l.width, l.height, formats[i]);
    b.SetTexture(d);
    RecedingPlane(b, (i % 3) * 42, (i / 3) * 48, 42, 48, 4.0f);
  }
  for (int k = 0; k < 2; ++k) {
    TextureDesc d = pattern;
    d.compressed = COMPRESSED_SIGNED_RED_RGTC1;
    d.levels.resize(1);
    d.levels[0].blocks = scenes::kit::EncodeBlocks(d.levels[0].rgba.data(), d.levels[0].width, d.levels[0].height, d.compressed);
    d.min_filter = d.mag_filter = k ? LINEAR : NEAREST;
    b.SetTexture(d);
    const float x0 = float(k) * 64;
    b.Draw(TRIANGLES, QuadWith({Win(x0, 96), Win(x0 + 64, 96), Win(x0 + 64, 128), Win(x0, 128)}, Uv({0, 0}, {0.5f, 0}, {0.5f, 0.25f}, {0, 0.25f})),
           Program::kTexture);
  }
}

// Drawing into an SRGB8_ALPHA8 texture with FRAMEBUFFER_SRGB enabled: a clear (encoded), colour gradients
// (encoded on store) and two blended gradients (the stored colour decoded, blended in linear, encoded again), then
// the same drawn with FRAMEBUFFER_SRGB disabled on the right half (the bytes as they are). The blended triangles do
// not overlap: two blends of one pixel would add two roundings. The object stays bound, so what is compared is its
// stored bytes. softgl converts exactly; llvmpipe's conversions approximate, so a third of the converted pixels
// differ by 1 and about one in 10,000 by 2: the texture check's tolerance.
void SrgbFramebuffer(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  b.AttachNewTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, SRGB8_ALPHA8, kSize, kSize);
  if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) return;  // left black: the check fails
  for (const bool on : {true, false}) {
    const float x0 = on ? 0.0f : 64.0f;
    if (on) b.Enable(FRAMEBUFFER_SRGB);
    else b.Disable(FRAMEBUFFER_SRGB);
    b.Scissor(int(x0), 0, 64, kSize);
    b.Enable(SCISSOR_TEST);
    b.ClearColor(0.2f, 0.5f, 0.05f, 1.0f);
    b.Clear(COLOR_BUFFER_BIT);
    b.Disable(SCISSOR_TEST);
    const glm::vec4 corner[4] = {Win(x0 + 4, 4), Win(x0 + 60, 4), Win(x0 + 60, 60), Win(x0 + 4, 60)};
    const glm::vec4 color[4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 1, 1}, {0, 0, 1, 1}};
    std::vector<Vertex> gradient;
    for (int k : {0, 1, 3, 1, 2, 3}) gradient.push_back({corner[k], color[k], glm::vec4(0)});
    b.Draw(TRIANGLES, gradient);
    b.Enable(BLEND);
    b.BlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ONE_MINUS_SRC_ALPHA);
    b.Draw(TRIANGLES, {{Win(x0 + 2, 2), {1, 1, 0, 0.25f}}, {Win(x0 + 62, 10), {0, 1, 1, 0.5f}},
                       {Win(x0 + 30, 62), {1, 0, 1, 1.0f}}});
    b.BlendColor(0.6f, 0.3f, 0.9f, 0.5f);
    b.BlendFuncSeparate(CONSTANT_COLOR, ONE_MINUS_SRC_COLOR, ONE, ZERO);
    b.Draw(TRIANGLES, {{Win(x0 + 4, 66), {0.1f, 0.8f, 0.3f, 1}}, {Win(x0 + 60, 70), {0.9f, 0.2f, 0.5f, 1}},
                       {Win(x0 + 32, 124), {0.4f, 0.4f, 0.9f, 1}}});
    b.Disable(BLEND);
  }
  b.Disable(FRAMEBUFFER_SRGB);
}

// Float render targets: in each quadrant, a framebuffer object with a colour texture of one float format
// (RGBA16F, R11F_G11F_B10F, RG16F, RGBA32F) takes a clear with values past [0, 1] (negative ones too), three
// gradients added over it (ONE, ONE: sums up to 4), then a quad subtracted (FUNC_REVERSE_SUBTRACT) that brings the
// sums back into [0, 1] only where they went past 1 unclamped; the quadrant is then blitted into the context's
// framebuffer (NEAREST), which clamps and converts to 8 bits.
// Four framebuffer objects, one a quadrant, each with a colour texture of formats[q]: a clear to values outside
// [0, 1], three overlapping quads added by blending, a reverse-subtracted one, then blitted to the window.
void BlendedTargets(Backend& b, const Enum formats[4]) {
  ClearBlack(b);
  for (int q = 0; q < 4; ++q) {
    const int x0 = (q % 2) * 64, y0 = (q / 2) * 64;
    b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
    b.AttachNewTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, formats[q], kSize, kSize);
    if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) continue;  // left black: the check fails
    b.ClearColor(1.5f, -0.5f, 0.25f, 2.0f);
    b.Clear(COLOR_BUFFER_BIT);
    b.Enable(BLEND);
    b.BlendFunc(ONE, ONE);
    for (int k = 0; k < 3; ++k) {
      const float a = float(k) * 6.0f;
      const glm::vec4 corner[4] = {Win(x0 + 2 + a, y0 + 2), Win(x0 + 50 + a, y0 + 4), Win(x0 + 46 + a, y0 + 60),
                                   Win(x0 + 4 + a, y0 + 56)};
      const glm::vec4 color[4] = {{0.1f, 0.9f, 1.3f, 1}, {1.2f, 0.2f, 0.7f, 1}, {0.6f, 1.1f, 0.05f, 1}, {0.9f, 0.45f, 0.3f, 1}};
      // R11F_G11F_B10F keeps 6 and 5 mantissa bits, and OpenGL leaves the rounding to them open (llvmpipe's differs
      // from softgl's nearest): its quads are flat, in colours whose sums it holds exactly.
      const glm::vec4 flat[3] = {{0.25f, 0.75f, 1.25f, 1}, {1.0f, 0.125f, 0.5f, 1}, {0.5f, 1.5f, 0.0625f, 1}};
      std::vector<Vertex> v;
      for (int i : {0, 1, 3, 1, 2, 3}) v.push_back({corner[i], formats[q] == R11F_G11F_B10F ? flat[k] : color[i], glm::vec4(0)});
      b.Draw(TRIANGLES, v);
    }
    b.BlendEquationSeparate(FUNC_REVERSE_SUBTRACT, FUNC_ADD);  // dst - src
    b.BlendFunc(ONE, ONE);
    b.Draw(TRIANGLES, Quad(Win(x0 + 8, y0 + 8), Win(x0 + 60, y0 + 8), Win(x0 + 60, y0 + 40), Win(x0 + 8, y0 + 40),
                           glm::vec4(1.25f, 1.0f, 0.75f, 0.5f)));
    b.BlendEquationSeparate(FUNC_ADD, FUNC_ADD);
    b.Disable(BLEND);
    b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    b.BlitFramebuffer(x0, y0, x0 + 64, y0 + 64, x0, y0, x0 + 64, y0 + 64, COLOR_BUFFER_BIT, NEAREST);
    b.BindFramebuffer(FRAMEBUFFER, 0);
  }
}

void FloatTargets(Backend& b) {
  const Enum formats[4] = {RGBA16F, R11F_G11F_B10F, RG16F, RGBA32F};
  BlendedTargets(b, formats);
}

// Several draw buffers of mixed formats in one framebuffer object (64 x 64): colour textures RGBA8, RGBA16F, RG8
// and R32F, a depth renderbuffer, all cleared to values outside [0, 1]. First the four outputs of kOutputs go to
// the attachments in reverse order (output 0 to R32F, 1 to RG8, 2 (past [0, 1]) to RGBA16F, 3 to RGBA8), in
// overlapping gradient quads, depth-tested and blended by SRC_ALPHA / ONE_MINUS_SRC_ALPHA; then outputs 1 and 3
// alone (with NONE between) add a triangle onto RGBA8 and RG8 (ONE, ONE). Each attachment is then blitted into
// its quadrant of the context's framebuffer (ReadBuffer, NEAREST), which clamps and converts to 8 bits.
// Three overlapping quads in the 64 x 64 framebuffer, with kOutputs' four outputs: colours cycling over the
// corners, depths alternating per corner (a depth test sorts them), extras giving outputs 1 and 3 gradients.
void OutputQuads(Backend& b) {
  auto w = [](float x, float y, float z) { return Win(2 * x, 2 * y, z); };  // window point of the 64 x 64
  for (int k = 0; k < 3; ++k) {
    const float a = float(k) * 9.0f, z = 0.5f - 0.4f * float(k);
    const Corners corner = {w(2 + a, 3 + a, z), w(44 + a, 5, -z), w(40 + a, 58 - a, z), w(4, 52 + a * 0.5f, -z)};
    const Corners extra = {glm::vec4(0.1f, 0.9f, 1.2f, 0.3f), glm::vec4(0.8f, 0.2f, 0.05f, 0.9f),
                           glm::vec4(0.6f, 0.6f, 0.7f, 0.0f), glm::vec4(0.0f, 0.35f, 0.4f, 1.0f)};
    std::vector<Vertex> v = QuadWith(corner, extra);
    const glm::vec4 colors[4] = {{0.9f, 0.2f, 0.1f, 0.6f}, {0.1f, 0.8f, 0.3f, 0.9f}, {0.3f, 0.4f, 1.0f, 0.4f},
                                 {1.0f, 1.0f, 0.2f, 0.75f}};
    const int order[6] = {0, 1, 3, 1, 2, 3};
    for (int i = 0; i < 6; ++i) v[std::size_t(i)].color = colors[(order[i] + k) % 4];
    b.Draw(TRIANGLES, v, Program::kOutputs);
  }
}

// The 64 x 64 colour attachments att[0..3] of the bound framebuffer blitted into the window's quarters (0 bottom
// left, 1 bottom right, 2 top left, 3 top right); then back to the window's framebuffer.
void BlitQuarters(Backend& b, const Enum (&att)[4]) {
  b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  b.Viewport(0, 0, kSize, kSize);
  for (int k = 0; k < 4; ++k) {
    const int x0 = (k % 2) * 64, y0 = (k / 2) * 64;
    b.ReadBuffer(att[k]);
    b.BlitFramebuffer(0, 0, 64, 64, x0, y0, x0 + 64, y0 + 64, COLOR_BUFFER_BIT, NEAREST);
  }
  b.ReadBuffer(att[0]);
  b.BindFramebuffer(FRAMEBUFFER, 0);
}

// The window cleared black, then a new framebuffer object bound with four 64 x 64 colour textures of `formats` at
// `att` (and a DEPTH24_STENCIL8 renderbuffer with `depth_stencil`), the viewport on it. False when it is not
// complete (the window is left black: the check fails).
bool FourTargets(Backend& b, const Enum (&att)[4], const Enum (&formats)[4], bool depth_stencil) {
  ClearBlack(b);
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  for (int k = 0; k < 4; ++k) b.AttachNewTexture(FRAMEBUFFER, att[k], formats[k], 64, 64);
  if (depth_stencil) {
    const std::uint32_t depth = b.GenRenderbuffer();
    b.BindRenderbuffer(depth);
    b.RenderbufferStorage(DEPTH24_STENCIL8, 64, 64);
    b.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, depth);
  }
  if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) return false;
  b.Viewport(0, 0, 64, 64);
  return true;
}

void MultipleOutputs(Backend& b) {
  const Enum att[4] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2, COLOR_ATTACHMENT0 + 3};
  if (!FourTargets(b, att, {RGBA8, RGBA16F, RG8, R32F}, true)) return;
  b.DrawBuffers(4, att);
  b.ClearColor(0.25f, -0.5f, 1.5f, 0.75f);
  b.ClearDepth(0.9);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  const Enum reversed[4] = {att[3], att[2], att[1], att[0]};
  b.DrawBuffers(4, reversed);
  b.Enable(DEPTH_TEST);
  b.Enable(BLEND);
  b.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  OutputQuads(b);
  b.Disable(DEPTH_TEST);
  auto w = [](float x, float y, float z) { return Win(2 * x, 2 * y, z); };  // window point of the 64 x 64
  const Enum some[4] = {NONE, att[0], NONE, att[2]};
  b.DrawBuffers(4, some);
  b.BlendFunc(ONE, ONE);
  b.Draw(TRIANGLES, {{w(10, 60, 0), {0.2f, 0.1f, 0.3f, 1}, {0.3f, 0.2f, 0.1f, 0.4f}},
                     {w(62, 20, 0), {0.4f, 0.3f, 0.2f, 1}, {0.1f, 0.5f, 0.2f, 0.2f}},
                     {w(30, 8, 0), {0.1f, 0.2f, 0.1f, 1}, {0.25f, 0.25f, 0.6f, 0.1f}}},
         Program::kOutputs);
  b.Disable(BLEND);
  BlitQuarters(b, att);
}

// Per-draw-buffer state: four colour textures of mixed formats, each with its own colour mask (ColorMaski) and
// blending on or off (Enablei / Disablei); a Clear through the four masks, a ClearBuffer of one buffer, then
// overlapping blended quads with four outputs. Each buffer blitted into a quarter of the window.
void PerBufferState(Backend& b) {
  const Enum att[4] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 2, COLOR_ATTACHMENT0 + 3};
  if (!FourTargets(b, att, {RGBA8, RGBA16F, RGBA8, RG8}, false)) return;
  b.DrawBuffers(4, att);
  b.ClearColor(0.2f, 0.35f, 0.4f, 1.0f);
  b.Clear(COLOR_BUFFER_BIT);
  b.ColorMaski(1, true, false, true, true);
  b.ColorMaski(2, false, true, false, true);
  b.ColorMaski(3, true, true, false, false);
  b.ClearColor(0.9f, 0.8f, 0.1f, 0.45f);  // (no channel on a tie between two bytes: those may round either way)
  b.Enable(SCISSOR_TEST);
  b.Scissor(0, 0, 64, 20);
  b.Clear(COLOR_BUFFER_BIT);  // each buffer through its own mask
  b.Scissor(0, 20, 20, 44);
  const float magenta[4] = {1.0f, 0.0f, 1.0f, 1.0f};
  b.ClearBufferfv(COLOR, 2, magenta);  // through buffer 2's mask (green and alpha)
  b.Disable(SCISSOR_TEST);
  b.Enable(BLEND);
  b.Disablei(BLEND, 1);
  b.Disablei(BLEND, 3);
  b.Enablei(BLEND, 3);
  b.Disablei(BLEND, 0);
  b.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  OutputQuads(b);
  b.Disable(BLEND);
  b.ColorMask(true, true, true, true);
  BlitQuarters(b, att);
}

// 16-bit normalized render targets: the same drawing into RGBA16, RG16, R16 and RGBA16, values clamped to [0, 1]
// and kept to 16 bits.
void Unorm16Targets(Backend& b) {
  const Enum formats[4] = {RGBA16, RG16, R16, RGBA16};
  BlendedTargets(b, formats);
}

// Textures of 16 bits a channel: RGBA16, RG16 and R16 from UNSIGNED_SHORT data, and RGBA16F from HALF_FLOAT data,
// gradients finer than 8 bits hold (steps of 1/4096) and a checker, magnified with LINEAR filtering.
void Texture16Bit(Backend& b) {
  ClearBlack(b);
  const Enum formats[4] = {RGBA16, RG16, R16, RGBA16F};
  for (int q = 0; q < 4; ++q) {
    TextureDesc d;
    d.internal_format = formats[q];
    d.type = formats[q] == RGBA16F ? HALF_FLOAT : UNSIGNED_SHORT;
    d.min_filter = d.mag_filter = LINEAR;
    d.wrap_s = d.wrap_t = CLAMP_TO_EDGE;
    TextureDesc::Level l;
    l.width = l.height = 8;
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const float v[4] = {float(i * 16 + j) / 4096.0f + 0.3f, float(j * 9 + 3) / 80.0f, (i + j) % 2 ? 0.8f : 0.1f,
                            1.0f};
        for (float c : v)
          l.shorts.push_back(d.type == HALF_FLOAT ? glm::packHalf1x16(c * 1.5f)
                                                  : std::uint16_t(std::lround(c * 65535.0f)));
      }
    d.levels.push_back(std::move(l));
    b.SetTexture(d);
    const float x0 = float(q % 2) * 64, y0 = float(q / 2) * 64;
    b.Draw(TRIANGLES, QuadWith({Win(x0, y0), Win(x0 + 64, y0), Win(x0 + 64, y0 + 64), Win(x0, y0 + 64)},
                               Uv({0, 0}, {1, 0}, {1, 1}, {0, 1})),
           Program::kTexture);
  }
}

// 16-bit targets: in three quadrants, a framebuffer object with an RGB565, RGBA4 or RGB5_A1 colour texture takes
// a clear and colour gradients (with `blend`, a gradient blended over them, SRC_ALPHA, ONE_MINUS_SRC_ALPHA), then
// is blitted into the context's framebuffer; the fourth quadrant draws the same into RGB565 with a colour mask.
// softgl converts to each channel's bits as OpenGL says, round(c * (2^bits - 1)); llvmpipe's conversion is one
// step of the channel apart from that in 2,316 of the 16,384 pixels without blending (8 of 255 for 5 bits, 17
// for 4; mostly higher), and its blends differ by a step too: the scenes allow one 4-bit step.
void Packed16(Backend& b, bool blend) {
  ClearBlack(b);
  const Enum formats[4] = {RGB565, RGBA4, RGB5_A1, RGB565};
  for (int q = 0; q < 4; ++q) {
    const float x0 = float((q % 2) * 64), y0 = float((q / 2) * 64);
    b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
    b.AttachNewTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, formats[q], kSize, kSize);
    if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) continue;  // left black: the check fails
    b.ClearColor(0.2f, 0.6f, 0.9f, 0.4f);
    b.Clear(COLOR_BUFFER_BIT);
    if (q == 3) b.ColorMask(true, false, true, true);
    const glm::vec4 corner[4] = {Win(x0 + 4, y0 + 4), Win(x0 + 56, y0 + 8), Win(x0 + 60, y0 + 44), Win(x0 + 8, y0 + 40)};
    const glm::vec4 color[4] = {{0, 0, 0, 1}, {1, 0.2f, 0, 1}, {1, 1, 1, 1}, {0, 0.5f, 1, 1}};
    std::vector<Vertex> v;
    for (int i : {0, 1, 3, 1, 2, 3}) v.push_back({corner[i], color[i], glm::vec4(0)});
    b.Draw(TRIANGLES, v);
    if (blend) {
      b.Enable(BLEND);
      b.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
      b.Draw(TRIANGLES, {{Win(x0 + 2, y0 + 30), {1, 1, 0, 0.2f}}, {Win(x0 + 62, y0 + 36), {0, 1, 1, 0.9f}},
                         {Win(x0 + 28, y0 + 62), {1, 0, 1, 0.5f}}});
      b.Disable(BLEND);
    }
    b.ColorMask(true, true, true, true);
    b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    const int bx = int(x0), by = int(y0);
    b.BlitFramebuffer(bx, by, bx + 64, by + 64, bx, by, bx + 64, by + 64, COLOR_BUFFER_BIT, NEAREST);
    b.BindFramebuffer(FRAMEBUFFER, 0);
  }
}

// Logic operations: stripes of flat colours (exact in the buffer's bits, so that no conversion differs), then in
// each cell stripes across them with COLOR_LOGIC_OP and one operation (blending enabled too, which the logic
// operation turns off). The top half is the context's RGBA8 framebuffer, the sixteen operations in 32 x 16 cells;
// the bottom half an RGB565 framebuffer object with four operations (one through a colour mask) blitted into it.
void LogicOps(Backend& b) {
  ClearBlack(b);
  auto stripes = [&b](float x0, float y0, float x1, float y1, bool vertical, unsigned seed, int bits_g) {
    for (int k = 0; k < 4; ++k) {
      glm::vec4 c = Palette(seed + unsigned(k));
      if (bits_g) {  // RGB565: 5, 6 and 5 bits
        c = glm::vec4(std::round(c.r * 31) / 31, std::round(c.g * 63) / 63, std::round(c.b * 31) / 31, 1);
      }
      c.a = float((seed * 7 + unsigned(k) * 60) % 256) / 255.0f;
      const float w = (vertical ? x1 - x0 : y1 - y0) / 4;
      if (vertical) b.Draw(TRIANGLES, Rect(x0 + w * float(k), y0, x0 + w * float(k + 1), y1, 0, c));
      else b.Draw(TRIANGLES, Rect(x0, y0 + w * float(k), x1, y0 + w * float(k + 1), 0, c));
    }
  };
  const Enum ops[16] = {CLEAR, AND, AND_REVERSE, COPY, AND_INVERTED, NOOP, XOR, OR,
                        NOR, EQUIV, INVERT, OR_REVERSE, COPY_INVERTED, OR_INVERTED, NAND, SET};
  b.Enable(BLEND);
  b.BlendFunc(ONE, ONE);
  for (int k = 0; k < 16; ++k) {
    const float x0 = float(k % 4) * 32, y0 = 64 + float(k / 4) * 16;
    stripes(x0, y0, x0 + 32, y0 + 16, false, unsigned(k) * 5, 0);
    b.Enable(COLOR_LOGIC_OP);
    b.LogicOp(ops[k]);
    stripes(x0 + 2, y0, x0 + 30, y0 + 16, true, 100 + unsigned(k) * 3, 0);
    b.Disable(COLOR_LOGIC_OP);
  }
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  b.AttachNewTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, RGB565, kSize, kSize);
  if (b.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE) {
    const Enum ops565[4] = {XOR, AND_INVERTED, EQUIV, OR_REVERSE};
    for (int k = 0; k < 4; ++k) {
      const float x0 = float(k % 2) * 64, y0 = float(k / 2) * 32;
      stripes(x0, y0, x0 + 64, y0 + 32, false, 200 + unsigned(k), 6);
      b.Enable(COLOR_LOGIC_OP);
      b.LogicOp(ops565[k]);
      if (k == 3) b.ColorMask(true, false, true, true);
      stripes(x0 + 4, y0, x0 + 60, y0 + 32, true, 300 + unsigned(k) * 4, 6);
      b.ColorMask(true, true, true, true);
      b.Disable(COLOR_LOGIC_OP);
    }
    b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    b.BlitFramebuffer(0, 0, kSize, 64, 0, 0, kSize, 64, COLOR_BUFFER_BIT, NEAREST);
  }
  b.BindFramebuffer(FRAMEBUFFER, 0);
  b.Disable(BLEND);
}

// A logic operation into an SRGB8_ALPHA8 framebuffer object: with FRAMEBUFFER_SRGB enabled on the left half, disabled
// on the right (where the stored bytes are a fixed-point buffer's). The object stays bound: its bytes are compared.
void LogicOpSrgb(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  b.AttachNewTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, SRGB8_ALPHA8, kSize, kSize);
  if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) return;  // left black: the check fails
  ClearBlack(b);
  for (const bool on : {true, false}) {
    const float x0 = on ? 0.0f : 64.0f;
    if (on) b.Enable(FRAMEBUFFER_SRGB);
    else b.Disable(FRAMEBUFFER_SRGB);
    for (int k = 0; k < 4; ++k)  // (stripes of the colours 0 and 1 in each channel: the same bytes either way)
      b.Draw(TRIANGLES, Rect(x0, float(k) * 32, x0 + 64, float(k + 1) * 32, 0,
                             glm::vec4(float(k & 1), float((k >> 1) & 1), float(k == 1), 1)));
    b.Enable(COLOR_LOGIC_OP);
    b.LogicOp(XOR);
    for (int k = 0; k < 4; ++k)
      b.Draw(TRIANGLES, Rect(x0 + float(k) * 16, 0, x0 + float(k + 1) * 16, kSize, 0, Palette(40 + unsigned(k))));
    b.Disable(COLOR_LOGIC_OP);
  }
  b.Disable(FRAMEBUFFER_SRGB);
}

void Packed16Targets(Backend& b) { Packed16(b, false); }
void Packed16Blending(Backend& b) { Packed16(b, true); }

void RenderToTexture(Backend& b) {
  // Pass 1: a 64 x 64 texture with coloured triangles and a depth test.
  b.BeginRenderToTexture(64, 64);
  b.ClearColor(0.1f, 0.2f, 0.3f, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  b.Draw(TRIANGLES, {{{-0.9f, -0.9f, 0.5f, 1}, {1, 0, 0, 1}}, {{0.9f, -0.7f, -0.5f, 1}, {0, 1, 0, 1}},
                     {{0.0f, 0.9f, 0.0f, 1}, {0, 0, 1, 1}}, {{-0.9f, 0.6f, -0.2f, 1}, {1, 1, 0, 1}},
                     {{0.8f, 0.8f, 0.3f, 1}, {1, 0, 1, 1}}, {{0.3f, -0.9f, 0.1f, 1}, {0, 1, 1, 1}}});
  b.Disable(DEPTH_TEST);
  b.EndRenderToTexture();
  // Pass 2: the texture on a rotated quad, magnified (LINEAR).
  ClearBlack(b);
  const float c = std::cos(0.4f), s = std::sin(0.4f);
  auto p = [&](float x, float y) { return glm::vec4(0.8f * (c * x - s * y), 0.8f * (s * x + c * y), 0, 1); };
  const std::vector<Vertex> v =
      QuadWith({p(-1, -1), p(1, -1), p(1, 1), p(-1, 1)}, Uv({0, 0}, {1, 0}, {1, 1}, {0, 1}));
  b.Draw(TRIANGLES, v, Program::kTexture);
}

// Coloured triangles in the lower-left 64 x 64 pixels, copied into a texture by CopyTexImage2D (a 48 x 40 rectangle
// from (8, 12)) and CopyTexSubImage2D (the framebuffer's lower-left 16 x 16 over the texture's upper-right
// corner), then drawn 1:1 with NEAREST into the upper right, where each pixel centre meets a texel centre.
void CopyTexImage(Backend& b) {
  ClearBlack(b);
  b.Draw(TRIANGLES, {{Win(2, 3), {1, 0, 0, 1}}, {Win(61, 9), {0, 1, 0, 1}}, {Win(30, 62), {0, 0, 1, 1}},
                     {Win(5, 50), {1, 1, 0, 1}}, {Win(20, 20), {1, 0, 1, 1}}, {Win(60, 58), {0, 1, 1, 1}}});
  b.CopyToTexture(8, 12, 48, 40, 32, 24, 0, 0, 16, 16);
  b.Draw(TRIANGLES, QuadWith({Win(72, 80), Win(120, 80), Win(120, 120), Win(72, 120)}, Uv({0, 0}, {1, 0}, {1, 1}, {0, 1})),
         Program::kTexture);
}

// The stencil scene drawn into a framebuffer object: colour in an RGBA8 renderbuffer, depth and stencil in one
// image of `format` at `attachment` (a renderbuffer, or a texture when `texture`). The object stays bound, so
// what is compared is read from it.
void StencilInFramebuffer(Backend& b, Enum format, Enum attachment, bool texture) {
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  const std::uint32_t color = b.GenRenderbuffer();
  b.BindRenderbuffer(color);
  b.RenderbufferStorage(RGBA8, kSize, kSize);
  b.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, color);
  if (texture) {
    b.AttachNewTexture(FRAMEBUFFER, attachment, format, kSize, kSize);
  } else {
    const std::uint32_t ds = b.GenRenderbuffer();
    b.BindRenderbuffer(ds);
    b.RenderbufferStorage(format, kSize, kSize);
    b.FramebufferRenderbuffer(FRAMEBUFFER, attachment, ds);
  }
  if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) return;  // left black: the check fails
  Stencil(b);
}

// DEPTH_COMPONENT16: a framebuffer object (left bound: it is what is compared) with an RGBA8 colour and a
// DEPTH_COMPONENT16 depth renderbuffer. Each of four rows gets a base rectangle at depth (20000.1) / 65535 (16-bit
// value 20000), then, with LESS, LEQUAL, EQUAL and GREATER, eight stripes 0.3 steps apart around it, -1.05 to
// +1.05 steps (values 19999, 19999, 20000 x 3, 20001 x 3; none within 0.15 of a rounding tie). The depth test
// compares the fragments' depths converted to 16 bits (OpenGL 4.6, section 17.3.5): with LESS only the first two
// stripes pass, and EQUAL passes the middle three, where a float buffer would pass none. The fifth row keeps
// two rectangles 0.4 steps apart, the second drawn with LESS; the sixth rectangles coplanar with its base, drawn
// with LESS and a polygon offset of -1 unit (drawn) and of -0.3 units (drawn nowhere), without writing depth:
// softgl's unit for a 16-bit buffer is one step (r, the smallest resolvable difference, 1 / 65535), llvmpipe's
// two, and these offsets give the same result under both (a float buffer's r, about 2^-25 here, would draw
// neither).
void Depth16(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  const std::uint32_t rb[2] = {b.GenRenderbuffer(), b.GenRenderbuffer()};
  b.BindRenderbuffer(rb[0]);
  b.RenderbufferStorage(RGBA8, kSize, kSize);
  b.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, rb[0]);
  b.BindRenderbuffer(rb[1]);
  b.RenderbufferStorage(DEPTH_COMPONENT16, kSize, kSize);
  b.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_ATTACHMENT, rb[1]);
  if (b.CheckFramebufferStatus(FRAMEBUFFER) != FRAMEBUFFER_COMPLETE) return;  // left black: the check fails
  b.ClearColor(0, 0, 0, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  auto ndc = [](double steps) { return float(2.0 * steps / 65535.0 - 1.0); };  // NDC z of a depth in 16-bit steps
  const Enum funcs[4] = {LESS, LEQUAL, EQUAL, GREATER};
  for (int row = 0; row < 4; ++row) {
    const float y0 = float(row) * 20, y1 = y0 + 20;
    b.DepthFunc(ALWAYS);
    b.Draw(TRIANGLES, Rect(0, y0, 128, y1, ndc(20000.1), Palette(1)));
    b.DepthFunc(funcs[row]);
    for (int i = 0; i < 8; ++i)
      b.Draw(TRIANGLES, Rect(float(i) * 16, y0, float(i + 1) * 16, y1, ndc(20000.1 + 0.3 * i - 1.05), Palette(10 + i)));
  }
  b.DepthFunc(ALWAYS);
  b.Draw(TRIANGLES, Rect(0, 80, 128, 104, ndc(31000.2), Palette(3)));
  b.DepthFunc(LESS);
  b.Draw(TRIANGLES, Rect(32, 80, 96, 104, ndc(30999.8), Palette(4)));  // the same 16-bit value: fails
  b.Draw(TRIANGLES, Rect(48, 84, 80, 100, ndc(30999.3), Palette(5)));  // one step nearer: passes
  b.DepthFunc(ALWAYS);
  b.Draw(TRIANGLES, Rect(0, 104, 128, 128, ndc(25000.3), Palette(6)));
  b.DepthFunc(LESS);
  b.Enable(POLYGON_OFFSET_FILL);
  b.DepthMask(false);
  b.PolygonOffset(0.0f, -1.0f);
  b.Draw(TRIANGLES, Rect(16, 104, 56, 128, ndc(25000.3), Palette(7)));
  b.PolygonOffset(0.0f, -0.3f);
  b.Draw(TRIANGLES, Rect(72, 104, 112, 128, ndc(25000.3), Palette(8)));
  b.DepthMask(true);
  b.Disable(POLYGON_OFFSET_FILL);
}

void StencilRenderbuffer(Backend& b) { StencilInFramebuffer(b, DEPTH24_STENCIL8, DEPTH_STENCIL_ATTACHMENT, false); }
void StencilIndex8(Backend& b) { StencilInFramebuffer(b, STENCIL_INDEX8, STENCIL_ATTACHMENT, false); }
void StencilTexture(Backend& b) { StencilInFramebuffer(b, DEPTH32F_STENCIL8, DEPTH_STENCIL_ATTACHMENT, true); }

// A 64 x 64 framebuffer object to blit from, left bound for drawing: colour attachments 0 and 1 (RGBA8
// renderbuffers) and a DEPTH24_STENCIL8 renderbuffer, holding overlapping triangles with depth, stencil values
// written by them (REPLACE with a reference per triangle), and a second image in attachment 1. Each triangle has
// one colour, so that the source is identical on both renderers and the blits alone are compared.
void BlitSource(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, b.GenFramebuffer());
  for (Enum attachment : {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, DEPTH_STENCIL_ATTACHMENT}) {
    const std::uint32_t rb = b.GenRenderbuffer();
    b.BindRenderbuffer(rb);
    b.RenderbufferStorage(attachment == DEPTH_STENCIL_ATTACHMENT ? DEPTH24_STENCIL8 : RGBA8, 64, 64);
    b.FramebufferRenderbuffer(FRAMEBUFFER, attachment, rb);
  }
  b.Viewport(0, 0, 64, 64);
  auto w = [](float x, float y, float z = 0.0f) { return Win(2 * x, 2 * y, z); };  // window point of the 64 x 64
  b.ClearColor(0.2f, 0.3f, 0.4f, 1);
  b.ClearDepth(0.75);
  b.ClearStencil(3);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  b.Enable(STENCIL_TEST);
  b.StencilOp(KEEP, KEEP, REPLACE);
  for (unsigned k = 0; k < 6; ++k) {
    b.StencilFunc(ALWAYS, int(10 + 20 * k), 0xFF);
    const float x = float(k * 9), z = 0.6f - 0.25f * float(k % 5);
    b.Draw(TRIANGLES, {{w(x + 1, 2, z), Palette(k)}, {w(x + 30, 20 + float(k) * 5, -z), Palette(k)},
                       {w(x + 6, 62, z * 0.5f), Palette(k)}});
  }
  b.Disable(STENCIL_TEST);
  b.Disable(DEPTH_TEST);
  const Enum second = COLOR_ATTACHMENT0 + 1;
  b.DrawBuffers(1, &second);
  b.ClearColor(0.9f, 0.1f, 0.5f, 1);
  b.Clear(COLOR_BUFFER_BIT);
  b.Draw(TRIANGLES, {{w(0, 0), Palette(40)}, {w(64, 0), Palette(40)}, {w(32, 64), Palette(40)}});
  const Enum first = COLOR_ATTACHMENT0;
  b.DrawBuffers(1, &first);
  b.Viewport(0, 0, kSize, kSize);
}

// NEAREST blits from the framebuffer object into the context's framebuffer: colour, depth and stencil 1:1; scaled
// up 2x; mirrored; scaled down by 1.5 (no pixel centre maps onto an edge); from colour attachment 1 by ReadBuffer;
// and through a scissor box. Colour, depth and stencil must be identical.
void BlitNearest(Backend& b) {
  BlitSource(b);
  const std::uint32_t fbo = 1;  // BlitSource's framebuffer object is the first made
  b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  b.ClearColor(0, 0, 0, 1);
  b.ClearDepth(1.0);
  b.ClearStencil(0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  b.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  b.BlitFramebuffer(0, 0, 64, 64, 0, 0, 64, 64, COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
  b.BlitFramebuffer(0, 0, 32, 32, 64, 0, 128, 64, COLOR_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
  b.BlitFramebuffer(0, 0, 64, 64, 128, 64, 64, 128, COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT, NEAREST);  // mirrored in x
  b.BlitFramebuffer(8, 8, 56, 56, 0, 96, 32, 64, COLOR_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);  // in y, 1.5:1
  b.ReadBuffer(COLOR_ATTACHMENT0 + 1);
  b.BlitFramebuffer(40, 40, 64, 64, 32, 64, 56, 88, COLOR_BUFFER_BIT, NEAREST);
  b.ReadBuffer(COLOR_ATTACHMENT0);
  b.Scissor(36, 100, 20, 16);
  b.Enable(SCISSOR_TEST);
  b.BlitFramebuffer(0, 0, 64, 64, 0, 64, 64, 128, COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
  b.Disable(SCISSOR_TEST);
  b.BindFramebuffer(READ_FRAMEBUFFER, 0);
}

// ---- Multisampling ------------------------------------------------------------------------------------------------

// A 64 x 64 framebuffer object of 4 samples a pixel (RGBA8 and DEPTH24_STENCIL8) bound for drawing, its viewport
// set; returns its id.
std::uint32_t MultisampleTarget(Backend& b) {
  const std::uint32_t fbo = b.GenFramebuffer();
  b.BindFramebuffer(FRAMEBUFFER, fbo);
  for (Enum attachment : {COLOR_ATTACHMENT0, DEPTH_STENCIL_ATTACHMENT}) {
    const std::uint32_t rb = b.GenRenderbuffer();
    b.BindRenderbuffer(rb);
    b.RenderbufferStorageMultisample(4, attachment == DEPTH_STENCIL_ATTACHMENT ? DEPTH24_STENCIL8 : RGBA8, 64, 64);
    b.FramebufferRenderbuffer(FRAMEBUFFER, attachment, rb);
  }
  b.Viewport(0, 0, 64, 64);
  return fbo;
}

// Back to the context's framebuffer and its viewport.
void EndMultisample(Backend& b) {
  b.BindFramebuffer(FRAMEBUFFER, 0);
  b.Viewport(0, 0, kSize, kSize);
}

// Resolves the 64 x 64 framebuffer object `fbo` into the context's framebuffer at (x, y), and draws into `fbo`
// again.
void ResolveInto(Backend& b, std::uint32_t fbo, int x, int y) {
  b.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  b.BlitFramebuffer(0, 0, 64, 64, x, y, x + 64, y + 64, COLOR_BUFFER_BIT, NEAREST);
  b.BindFramebuffer(FRAMEBUFFER, fbo);
}

// Random triangles, each its own colour, with vertices on the 1/256 grid and a third of them on the 1/16 grid of
// the sample positions (edges through samples test the tie rule at samples), in a 64 x 64 viewport.
std::vector<Vertex> SampleTriangles(unsigned seed, int count) {
  Jitter j(seed);
  std::vector<Vertex> v;
  for (int i = 0; i < count; ++i) {
    const float cx = j.Sub(1, 63), cy = j.Sub(1, 63), r = j.Uniform(0.4f, 5.0f);
    const glm::vec4 c = Palette(unsigned(i) + seed);
    for (int k = 0; k < 3; ++k) {
      const float grid = (i + k) % 3 == 0 ? 16.0f : 256.0f;
      const float x = std::round((cx + j.Uniform(-r, r)) * grid) / grid, y = std::round((cy + j.Uniform(-r, r)) * grid) / grid;
      v.push_back({Win(2 * x, 2 * y), c});
    }
  }
  return v;
}

// Draws `draw` four times into a 4-sample framebuffer object, each time into one sample alone (SAMPLE_MASK), and
// resolves each into a quadrant of its own. A quadrant's pixel is a quarter of the colour of the last primitive
// covering that sample, so any sample covered differently shows.
template <class Draw>
void EachSampleIntoQuadrants(Backend& b, Draw&& draw) {
  ClearBlack(b);
  const std::uint32_t fbo = MultisampleTarget(b);
  b.Enable(SAMPLE_MASK);
  for (int s = 0; s < 4; ++s) {
    b.ClearColor(0, 0, 0, 1);
    b.Clear(COLOR_BUFFER_BIT);
    b.SampleMask(1u << s);
    draw();
    ResolveInto(b, fbo, (s & 1) * 64, (s >> 1) * 64);
  }
  b.Disable(SAMPLE_MASK);
  EndMultisample(b);
}

// Per-sample coverage of triangles.
void MultisampleCoverage(Backend& b) {
  const std::vector<Vertex> v = SampleTriangles(5, 260);
  EachSampleIntoQuadrants(b, [&] { b.Draw(TRIANGLES, v); });
}

// Per-sample coverage of lines and points: with multisampling a line covers the samples inside the rectangle of
// width 1 along its segment, a point the samples inside the square of its size around it (OpenGL 4.6, sections
// 14.5.4 and 14.4.3), not the pixels the single-sample rules pick.
// Wide lines in a multisampled framebuffer (as in msaa_lines_points): rectangles 1.5, 2, 3.25 and 5 pixels wide
// (multisampled widths are not rounded) around segments in every direction.
void MultisampleWideLines(Backend& b) {
  Jitter j(47);
  const float widths[4] = {1.5f, 2.0f, 3.25f, 5.0f};
  std::vector<Vertex> lines[4];
  for (int i = 0; i < 32; ++i) {
    const float a = 6.2831853f * float(i) / 32.0f + j.Uniform(0.0f, 0.1f), len = j.Uniform(4, 30);
    const float grid = i % 3 == 0 ? 16.0f : 256.0f;
    const float x = std::round(j.Uniform(4, 60) * grid) / grid, y = std::round(j.Uniform(4, 60) * grid) / grid;
    const float x1 = std::round((x + std::cos(a) * len) * grid) / grid, y1 = std::round((y + std::sin(a) * len) * grid) / grid;
    lines[i % 4].push_back({Win(2 * x, 2 * y), Palette(unsigned(i))});
    lines[i % 4].push_back({Win(2 * x1, 2 * y1), Palette(unsigned(i))});
  }
  EachSampleIntoQuadrants(b, [&] {
    for (int k = 0; k < 4; ++k) {
      b.LineWidth(widths[k]);
      b.Draw(LINES, lines[k]);
    }
    b.LineWidth(1.0f);
  });
}

void MultisampleLinesPoints(Backend& b) {
  Jitter j(41);
  std::vector<Vertex> lines;
  unsigned n = 0;
  for (int i = 0; i < 40; ++i) {  // segments in every direction, a third of their ends on the samples' grid
    const float a = 6.2831853f * float(i) / 40.0f + j.Uniform(0.0f, 0.1f), len = j.Uniform(3, 30);
    const float grid = i % 3 == 0 ? 16.0f : 256.0f;
    const float x = std::round(j.Uniform(2, 62) * grid) / grid, y = std::round(j.Uniform(2, 62) * grid) / grid;
    const float x1 = std::round((x + std::cos(a) * len) * grid) / grid, y1 = std::round((y + std::sin(a) * len) * grid) / grid;
    const glm::vec4 c = Palette(n++);
    lines.push_back({Win(2 * x, 2 * y), c});
    lines.push_back({Win(2 * x1, 2 * y1), c});
  }
  const float sizes[] = {1.0f, 1.5f, 2.0f, 3.0f, 4.25f, 6.0f};
  std::vector<Vertex> points[6];
  Jitter pj(43);
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 8; ++i) {  // half of them on the samples' grid
      const float grid = i % 2 == 0 ? 16.0f : 256.0f;
      const float x = std::round(pj.Uniform(3, 61) * grid) / grid, y = std::round(pj.Uniform(3, 61) * grid) / grid;
      points[k].push_back({Win(2 * x, 2 * y), Palette(100 + unsigned(8 * k + i))});
    }
  EachSampleIntoQuadrants(b, [&] {
    b.Draw(LINES, lines);
    for (int k = 0; k < 6; ++k) {
      b.PointSize(sizes[k]);
      b.Draw(POINTS, points[k]);
    }
    b.PointSize(1.0f);
  });
}

// Sample shading: a magnified checkerboard (NEAREST) on rotated quads drawn into a 4-sample framebuffer object with
// SAMPLE_SHADING and MinSampleShading(1) (bottom half) and without (top half), each resolved. At every sample the
// texel edges inside a pixel resolve to a share of the two texels' colours; shaded once per pixel, to one of them.
void MultisampleSampleShading(Backend& b) {
  ClearBlack(b);
  TextureDesc d = PatternTexture(false);
  d.levels.resize(1);
  d.min_filter = d.mag_filter = NEAREST;
  b.SetTexture(d);
  const std::uint32_t fbo = MultisampleTarget(b);
  for (int half = 0; half < 2; ++half) {
    b.ClearColor(0.1f, 0.2f, 0.3f, 1);
    b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    if (half == 0) {
      b.Enable(SAMPLE_SHADING);
      b.MinSampleShading(1.0f);
    }
    for (int i = 0; i < 2; ++i) {  // two quads turned by 20 and 65 degrees, about 6 pixels a texel
      const float a = (i == 0 ? 20.0f : 65.0f) * 3.14159265f / 180.0f, c = std::cos(a) * 15.0f, s = std::sin(a) * 15.0f;
      const float cx = i == 0 ? 17.3f : 46.6f, cy = i == 0 ? 31.1f : 32.7f;
      const std::vector<Vertex> v = QuadWith({Win(2 * (cx - c + s), 2 * (cy - s - c)), Win(2 * (cx + c + s), 2 * (cy + s - c)),
                                              Win(2 * (cx + c - s), 2 * (cy + s + c)), Win(2 * (cx - c - s), 2 * (cy - s + c))},
                                             Uv({0.0f, 0.0f}, {0.3f, 0.0f}, {0.3f, 0.3f}, {0.0f, 0.3f}));
      b.Draw(TRIANGLES, v, Program::kTexture);
    }
    b.Disable(SAMPLE_SHADING);
    b.MinSampleShading(0.0f);
    ResolveInto(b, fbo, 0, half * 64);
  }
  EndMultisample(b);
}

// A resolved scene: depth-tested triangles crossing each other (depth per sample), a stencil mask drawn at
// samples, and blended triangles over them, in a 4-sample framebuffer object resolved into the bottom half;
// the top half has the same with MULTISAMPLE disabled (each pixel's centre coverage into all its samples).
void MultisampleResolve(Backend& b) {
  ClearBlack(b);
  const std::uint32_t fbo = MultisampleTarget(b);
  for (int half = 0; half < 2; ++half) {
    if (half == 1) b.Disable(MULTISAMPLE);
    for (int part = 0; part < 2; ++part) {
      b.ClearColor(0.1f, 0.2f, 0.3f, 1);
      b.ClearDepth(1.0);
      b.ClearStencil(0);
      b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
      Jitter j(31u + unsigned(part));
      std::vector<Vertex> v;
      for (int i = 0; i < 40; ++i) {
        const glm::vec4 c = Palette(unsigned(i) * 7u + 3u);
        const float cx = j.Sub(4, 60), cy = j.Sub(4, 60);
        for (int k = 0; k < 3; ++k)
          v.push_back({Win(2 * (cx + j.Uniform(-14, 14)), 2 * (cy + j.Uniform(-14, 14)), j.Uniform(-0.9f, 0.9f)), c});
      }
      if (part == 0) {
        b.Enable(DEPTH_TEST);
        b.Draw(TRIANGLES, v);
        b.Disable(DEPTH_TEST);
      } else {
        b.Enable(STENCIL_TEST);
        b.StencilFunc(ALWAYS, 1, 0xFF);
        b.StencilOp(KEEP, KEEP, REPLACE);
        b.ColorMask(false, false, false, false);
        b.Draw(TRIANGLES, {{Win(2 * 3.3f, 2 * 5.1f), glm::vec4(1)}, {Win(2 * 60.7f, 2 * 20.2f), glm::vec4(1)},
                           {Win(2 * 20.4f, 2 * 61.9f), glm::vec4(1)}});
        b.ColorMask(true, true, true, true);
        b.StencilFunc(EQUAL, 1, 0xFF);
        b.Draw(TRIANGLES, v);
        b.Disable(STENCIL_TEST);
        b.Enable(BLEND);
        b.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
        const glm::vec4 glass(0.9f, 0.8f, 0.2f, 0.5f);
        b.Draw(TRIANGLES, {{Win(2 * 0.6f, 2 * 40.3f), glass}, {Win(2 * 63.2f, 2 * 31.7f), glass},
                           {Win(2 * 30.1f, 2 * 63.4f), glass}});
        b.Disable(BLEND);
      }
      ResolveInto(b, fbo, part * 64, half * 64);
    }
  }
  b.Enable(MULTISAMPLE);
  EndMultisample(b);
}

// SAMPLE_COVERAGE (half, and a third inverted), SAMPLE_ALPHA_TO_COVERAGE over an alpha gradient, and SAMPLE_MASK
// with two samples, one quadrant each, resolved.
// Random triangles drawn into a 4-sample TEXTURE_2D_MULTISAMPLE colour attachment (with a 4-sample depth and
// stencil renderbuffer, depth-tested), then each sample read by texelFetch into its own quadrant: every sample's
// colour, not a resolve of them, is compared.
void MultisampleTexture(Backend& b) {
  ClearBlack(b);
  const std::uint32_t fbo = b.GenFramebuffer();
  b.BindFramebuffer(FRAMEBUFFER, fbo);
  b.AttachNewMultisampleTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, 4, RGBA8, 64, 64);
  const std::uint32_t rb = b.GenRenderbuffer();
  b.BindRenderbuffer(rb);
  b.RenderbufferStorageMultisample(4, DEPTH24_STENCIL8, 64, 64);
  b.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, rb);
  b.Viewport(0, 0, 64, 64);
  b.ClearColor(0.1f, 0.1f, 0.2f, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  b.Enable(DEPTH_TEST);
  std::vector<Vertex> tris = SampleTriangles(7, 120);
  for (std::size_t i = 0; i < tris.size(); ++i) tris[i].pos.z = float(int(i / 3) % 7) / 7.0f - 0.5f;
  b.Draw(TRIANGLES, tris);
  b.Disable(DEPTH_TEST);
  EndMultisample(b);
  for (int s = 0; s < 4; ++s) {
    const float x0 = float(s & 1) * 64, y0 = float(s >> 1) * 64;
    b.Draw(TRIANGLES, QuadWith({Win(x0, y0), Win(x0 + 64, y0), Win(x0 + 64, y0 + 64), Win(x0, y0 + 64)},
                               {glm::vec4(x0, y0, float(s), 0), glm::vec4(x0, y0, float(s), 0),
                                glm::vec4(x0, y0, float(s), 0), glm::vec4(x0, y0, float(s), 0)}),
           Program::kFetchSample);
  }
}
// A TEXTURE_2D_MULTISAMPLE_ARRAY of three 64 x 64 layers at 4 samples (with a depth-stencil array beside it): layers
// 0 and 1 drawn into one at a time through FramebufferTextureLayer (depth-tested triangles), then every layer
// attached (FramebufferTexture) and triangles routed to layer 2 by gl_Layer; each quadrant shows one sample of one
// layer by texelFetch: layer 0 sample 0, layer 1 sample 3, layer 2 sample 1, layer 0 sample 2.
void MultisampleTextureArray(Backend& b) {
  ClearBlack(b);
  const std::uint32_t fbo = b.GenFramebuffer();
  b.BindFramebuffer(FRAMEBUFFER, fbo);
  const std::uint32_t depth = b.NewMultisampleArray(4, DEPTH24_STENCIL8, 64, 64, 3);
  const std::uint32_t color = b.NewMultisampleArray(4, RGBA8, 64, 64, 3);  // (made last: unit 6 keeps it)
  b.Viewport(0, 0, 64, 64);
  b.ClearDepth(1.0);
  for (int layer = 0; layer < 2; ++layer) {
    b.FramebufferTextureLayer(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0, layer);
    b.FramebufferTextureLayer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, depth, 0, layer);
    b.ClearColor(0.1f, 0.1f * float(layer), 0.2f, 1);
    b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    b.Enable(DEPTH_TEST);
    std::vector<Vertex> tris = SampleTriangles(7 + unsigned(layer), 90);
    for (std::size_t i = 0; i < tris.size(); ++i) tris[i].pos.z = float(int(i / 3) % 5) / 5.0f - 0.5f;
    b.Draw(TRIANGLES, tris);
    b.Disable(DEPTH_TEST);
  }
  b.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0);
  b.FramebufferTexture(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, depth, 0);
  std::vector<Vertex> to_layer = SampleTriangles(11, 40);
  for (Vertex& v : to_layer) v.extra.w = 2.0f;
  b.Draw(TRIANGLES, to_layer, Program::kLayer);
  EndMultisample(b);
  const int shown[4][2] = {{0, 0}, {1, 3}, {2, 1}, {0, 2}};  // (layer, sample) of each quadrant
  for (int q = 0; q < 4; ++q) {
    const float x0 = float(q & 1) * 64, y0 = float(q >> 1) * 64;
    const glm::vec4 e(x0, y0, float(shown[q][1]), float(shown[q][0]));
    b.Draw(TRIANGLES, QuadWith({Win(x0, y0), Win(x0 + 64, y0), Win(x0 + 64, y0 + 64), Win(x0, y0 + 64)}, {e, e, e, e}),
           Program::kFetchSampleArray);
  }
}
void MultisampleCoverageOps(Backend& b) {
  ClearBlack(b);
  const std::uint32_t fbo = MultisampleTarget(b);
  const std::vector<Vertex> tris = SampleTriangles(9, 60);
  for (int q = 0; q < 4; ++q) {
    b.ClearColor(0, 0, 0, 1);
    b.Clear(COLOR_BUFFER_BIT);
    switch (q) {
      case 0: b.Enable(SAMPLE_COVERAGE); b.SampleCoverage(0.5f, false); break;
      case 1: b.Enable(SAMPLE_COVERAGE); b.SampleCoverage(0.3f, true); break;
      case 2: b.Enable(SAMPLE_ALPHA_TO_COVERAGE); break;
      default: b.Enable(SAMPLE_MASK); b.SampleMask(0x9u); break;
    }
    if (q == 2) {  // alpha from 0 at the left to 1 at the right, in steps between the thresholds s / 4
      std::vector<Vertex> ramp;
      for (int k = 0; k < 8; ++k) {
        const float x0 = float(k) * 8.0f, x1 = x0 + 8.0f, a = (float(k) + 0.5f) / 8.0f;
        for (const Vertex& v : Rect(2 * x0, 0, 2 * x1, 2 * 64, 0, glm::vec4(1, 0.5f, 0.25f, a))) ramp.push_back(v);
      }
      b.Draw(TRIANGLES, ramp);
    }
    b.Draw(TRIANGLES, tris);
    b.Disable(SAMPLE_COVERAGE);
    b.Disable(SAMPLE_ALPHA_TO_COVERAGE);
    b.Disable(SAMPLE_MASK);
    ResolveInto(b, fbo, (q & 1) * 64, (q >> 1) * 64);
  }
  EndMultisample(b);
}

// LINEAR blits of colour: 2x up, 1.5x up mirrored in y, and 2x down, from the framebuffer object's colour into the
// context's framebuffer. Colour within 1 (filtering).
void BlitLinear(Backend& b) {
  BlitSource(b);
  b.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
  ClearBlack(b);
  b.BindFramebuffer(READ_FRAMEBUFFER, 1);
  b.BlitFramebuffer(0, 0, 32, 32, 0, 0, 64, 64, COLOR_BUFFER_BIT, LINEAR);
  b.BlitFramebuffer(16, 16, 48, 48, 64, 112, 112, 64, COLOR_BUFFER_BIT, LINEAR);
  b.BlitFramebuffer(0, 0, 64, 64, 0, 64, 32, 96, COLOR_BUFFER_BIT, LINEAR);
  b.BindFramebuffer(READ_FRAMEBUFFER, 0);
}

// A cube map with a different gradient per face, seen through a full-screen quad whose direction varyings sweep
// across several faces (face selection, per-face coordinates, mipmapped filtering, edges between faces).
void CubeMap(Backend& b) {
  ClearBlack(b);
  constexpr int kFace = 32;
  std::vector<std::uint8_t> faces[6];
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < kFace; ++j)
      for (int i = 0; i < kFace; ++i) {
        const bool check = ((i / 4) + (j / 4)) % 2 == 0;
        faces[f].insert(faces[f].end(), {std::uint8_t(40 * f + (check ? 20 : 0)), std::uint8_t(i * 8),
                                         std::uint8_t(j * 8), 255});
      }
  b.SetCubeTexture(kFace, faces);
  // Directions at the corners: a wide view that spans +z, +x, -x, +y and -y.
  const std::vector<Vertex> v =
      QuadWith({Win(0, 0), Win(128, 0), Win(128, 128), Win(0, 128)},
               {glm::vec4(-1.6f, -1.3f, 1, 0), glm::vec4(1.7f, -1.2f, 1, 0), glm::vec4(1.5f, 1.4f, 1, 0),
                glm::vec4(-1.4f, 1.5f, 1, 0)});
  b.Draw(TRIANGLES, v, Program::kCube);
}

// A depth texture of ramps and steps, compared against a reference that varies across the quad, with NEAREST and
// LINEAR (2 x 2 percentage-closer) filtering and two comparison functions.
void ShadowCompare(Backend& b) {
  ClearBlack(b);
  constexpr int kSize = 16;
  std::vector<float> depth(kSize * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) depth[j * kSize + i] = ((i / 4 + j / 4) % 2 ? 0.3f : 0.7f) + 0.01f * float(i % 4);
  const Enum funcs[2] = {LEQUAL, GREATER};
  const Enum filters[2] = {NEAREST, LINEAR};
  for (int q = 0; q < 4; ++q) {
    b.SetShadowTexture(kSize, depth, funcs[q % 2], filters[q / 2]);
    const float x0 = float(q % 2) * 64, y0 = float(q / 2) * 64;
    // uv across the texture; the reference from 0.15 to 0.85 along x, between the texel depths.
    const std::vector<Vertex> v =
        QuadWith({Win(x0, y0), Win(x0 + 64, y0), Win(x0 + 64, y0 + 64), Win(x0, y0 + 64)},
                 {glm::vec4(0, 0, 0.15f, 0), glm::vec4(1, 0, 0.85f, 0), glm::vec4(1, 1, 0.85f, 0),
                  glm::vec4(0, 1, 0.15f, 0)});
    b.Draw(TRIANGLES, v, Program::kShadow);
  }
}

// RGBA8 texels of a w x h x d texture: a checker of 4-texel cells, each plane its own colours, with a gradient
// within it, so that layers, slices and mipmap levels all look different.
std::vector<std::uint8_t> LayeredPattern(int w, int h, int d) {
  std::vector<std::uint8_t> rgba;
  for (int k = 0; k < d; ++k)
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const bool check = ((i / 4) + (j / 4) + k) % 2 == 0;
        rgba.insert(rgba.end(), {std::uint8_t(check ? 40 + 50 * (k % 5) : 230 - 30 * (k % 7)),
                                 std::uint8_t(i * 255 / std::max(w - 1, 1)), std::uint8_t(60 * (k % 4) + j * 3),
                                 255});
      }
  return rgba;
}

// A mipmapped 2D array of 5 layers on receding planes: layers chosen by constant coordinates (below 0, between
// layers on either side of .5, beyond the last: rounded and clamped), and one plane whose layer coordinate varies
// across it; then the same array NEAREST with CLAMP_TO_EDGE on a quad beyond [0, 1].
void TextureArray(Backend& b) {
  ClearBlack(b);
  LayeredDesc d;
  d.width = d.height = 16;
  d.depth_or_layers = 5;
  d.rgba = LayeredPattern(16, 16, 5);
  d.generate_mipmap = true;
  d.min_filter = LINEAR_MIPMAP_LINEAR;
  b.SetLayeredTexture(d);
  const float layers[5] = {-1.0f, 0.3f, 1.6f, 2.2f, 9.0f};
  const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 25.0f / 64.0f, 0.3f, 60.0f) *
                        glm::lookAt(glm::vec3(0, 1, 1), glm::vec3(0, 0, -8), glm::vec3(0, 1, 0));
  for (int q = 0; q < 5; ++q) {
    b.Viewport(q * 25, 64, 25, 64);
    const float l = layers[q];
    b.Draw(TRIANGLES,
           QuadWith(Floor(mvp, -6, 6, 1, -40),
                    {glm::vec4(0, 0, l, 0), glm::vec4(3, 0, l, 0), glm::vec4(3, 10, l, 0), glm::vec4(0, 10, l, 0)}),
           Program::kArray);
  }
  b.Viewport(0, 0, kSize, kSize);
  // The layer coordinate from 0.1 at the left to 3.9 at the right: bands of layers 0 to 4 (the band edges, where
  // an interpolated coordinate lies within rounding of n + 0.5, may go either way: the texture check's share).
  b.Draw(TRIANGLES,
         QuadWith({Win(0, 0), Win(64, 0), Win(64, 64), Win(0, 64)},
                  {glm::vec4(0, 0, 0.1f, 0), glm::vec4(2, 0, 3.9f, 0), glm::vec4(2, 2, 3.9f, 0),
                   glm::vec4(0, 2, 0.1f, 0)}),
         Program::kArray);
  d.generate_mipmap = false;
  d.min_filter = d.mag_filter = NEAREST;
  d.wrap_s = d.wrap_t = CLAMP_TO_EDGE;
  b.SetLayeredTexture(d);
  b.Draw(TRIANGLES,
         QuadWith({Win(64, 0), Win(128, 0), Win(128, 64), Win(64, 64)},
                  {glm::vec4(-0.3f, -0.2f, 3, 0), glm::vec4(1.4f, -0.2f, 3, 0), glm::vec4(1.4f, 1.3f, 3, 0),
                   glm::vec4(-0.3f, 1.3f, 3, 0)}),
         Program::kArray);
}

// 1D textures: a mipmapped 32-texel TEXTURE_1D on receding floors (trilinear, REPEAT and MIRRORED_REPEAT), the
// same magnified with NEAREST and LINEAR under CLAMP_TO_EDGE and CLAMP_TO_BORDER (TEXTURE_WRAP_T set to
// CLAMP_TO_BORDER too, which a 1D texture does not use), and a TEXTURE_1D_ARRAY of 5 layers: mipmapped on a floor,
// and a band per layer (the layer floor(y + 0.5), clamped) with NEAREST.
void Texture1D(Backend& b) {
  ClearBlack(b);
  LayeredDesc d;
  d.target = TEXTURE_1D;
  d.width = 32;
  d.height = d.depth_or_layers = 1;
  d.rgba = LayeredPattern(32, 1, 1);
  d.generate_mipmap = true;
  d.min_filter = LINEAR_MIPMAP_LINEAR;
  const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 1.0f, 0.3f, 60.0f) *
                        glm::lookAt(glm::vec3(0, 1, 1), glm::vec3(0, 0, -8), glm::vec3(0, 1, 0));
  const Enum wraps[2] = {REPEAT, MIRRORED_REPEAT};
  for (int q = 0; q < 2; ++q) {
    d.wrap_s = wraps[q];
    b.SetLayeredTexture(d);
    b.Viewport(0, 64 + q * 32, 64, 32);
    b.Draw(TRIANGLES,
           QuadWith(Floor(mvp, -6, 6, 1, -7), {glm::vec4(-0.25f, 0, 0, 0), glm::vec4(1.25f, 0, 0, 0),
                                                glm::vec4(1.25f, 10, 0, 0), glm::vec4(-0.25f, 10, 0, 0)}),
           Program::kTexture1D);
  }
  b.Viewport(0, 0, kSize, kSize);
  d.generate_mipmap = false;
  d.wrap_t = CLAMP_TO_BORDER;
  const Enum filters[2] = {NEAREST, LINEAR}, edges[2] = {CLAMP_TO_EDGE, CLAMP_TO_BORDER};
  for (int k = 0; k < 4; ++k) {
    d.min_filter = d.mag_filter = filters[k % 2];
    d.wrap_s = edges[k / 2];
    b.SetLayeredTexture(d);
    const float y0 = float(k) * 16;
    b.Draw(TRIANGLES,
           QuadWith({Win(0, y0), Win(64, y0), Win(64, y0 + 16), Win(0, y0 + 16)},
                    {glm::vec4(-0.2f, 0, 0, 0), glm::vec4(1.2f, 0, 0, 0), glm::vec4(1.2f, 0, 0, 0),
                     glm::vec4(-0.2f, 0, 0, 0)}),
           Program::kTexture1D);
  }
  LayeredDesc a;
  a.target = TEXTURE_1D_ARRAY;
  a.width = 16;
  a.height = 1;
  a.depth_or_layers = 5;
  a.rgba = LayeredPattern(16, 1, 5);
  a.generate_mipmap = true;
  a.min_filter = LINEAR_MIPMAP_LINEAR;
  b.SetLayeredTexture(a);
  b.Viewport(64, 64, 64, 64);
  b.Draw(TRIANGLES,
         QuadWith(Floor(mvp, -6, 6, 1, -7), {glm::vec4(0, 0.4f, 0, 0), glm::vec4(3, 0.4f, 0, 0),
                                              glm::vec4(3, 3.6f, 0, 0), glm::vec4(0, 3.6f, 0, 0)}),
         Program::kTexture1DArray);
  b.Viewport(0, 0, kSize, kSize);
  a.generate_mipmap = false;
  a.min_filter = a.mag_filter = NEAREST;
  b.SetLayeredTexture(a);
  b.Draw(TRIANGLES,
         QuadWith({Win(64, 0), Win(128, 0), Win(128, 64), Win(64, 64)},
                  {glm::vec4(0, -1.3f, 0, 0), glm::vec4(1, -1.3f, 0, 0), glm::vec4(1, 6.3f, 0, 0),
                   glm::vec4(0, 6.3f, 0, 0)}),
         Program::kTexture1DArray);
}

// Integer colour buffers and textures: six 16 x 16 integer textures (R32UI, RGBA8I, RG16UI, RGB10_A2UI, R16I,
// RGBA32I), each cleared by ClearBufferuiv or iv, drawn into by triangles writing integers (values past the
// format's range among them, clamped), then by a triangle through a logic operation and another through a colour
// mask, and shown 40 x 40 pixels each by texture(usampler2D / isampler2D) over uv from -0.25 to 1.25, in each
// wrap mode (integer border colours), as the low bytes of the integers.
void IntegerFormats(Backend& b) {
  ClearBlack(b);
  using IntegerDraw = Backend::IntegerDraw;
  // A triangle of the 16 x 16 target, corners in its pixels, writing `value`.
  const auto tri = [](glm::vec2 p0, glm::vec2 p1, glm::vec2 p2, glm::vec4 value) {
    std::vector<Vertex> v;
    for (glm::vec2 p : {p0, p1, p2}) v.push_back({glm::vec4(p.x / 8.0f - 1.0f, p.y / 8.0f - 1.0f, 0, 1), glm::vec4(1), value});
    return v;
  };
  const auto join = [](std::vector<Vertex> a, const std::vector<Vertex>& c) {
    a.insert(a.end(), c.begin(), c.end());
    return a;
  };
  const struct Cell {
    Enum format;
    glm::ivec4 clear;
    glm::vec4 a, c, logic_value, masked;
    Enum logic;
    unsigned mask;
    Enum wrap;
    glm::ivec4 border;
  } cells[] = {
      {R32UI, glm::ivec4(-1), {3e9f, 0, 0, 0}, {70000, 0, 0, 0}, {3855, 0, 0, 0}, {77, 0, 0, 0}, XOR, 0x1,
       CLAMP_TO_BORDER, glm::ivec4(0x12345678, 0, 0, 0)},
      {RGBA8I, glm::ivec4(-300, 200, 5, -1), {-5, 100, -128, 127}, {400, -400, 7, 1}, {0x55, -2, 3, 0x70}, {9, 9, 9, 9},
       OR_REVERSE, 0x5, REPEAT, glm::ivec4(0)},
      {RG16UI, glm::ivec4(70000, 1, 0, 0), {65535, 40000, 0, 0}, {123, 4567, 0, 0}, {0, 0, 0, 0}, {300, 301, 0, 0},
       INVERT, 0x2, MIRRORED_REPEAT, glm::ivec4(0)},
      {RGB10_A2UI, glm::ivec4(2000, 5, 1023, 9), {512, 1023, 7, 2}, {5000, 1, 2, 3}, {0x3F0, 0x0FF, 0x2AA, 1},
       {11, 12, 13, 0}, AND, 0xB, CLAMP_TO_EDGE, glm::ivec4(0)},
      {R16I, glm::ivec4(-40000, 0, 0, 0), {-1234, 0, 0, 0}, {32767, 0, 0, 0}, {0x1FF, 0, 0, 0}, {-2, 0, 0, 0}, XOR, 0x1,
       CLAMP_TO_BORDER, glm::ivec4(-2, 7, -9, 100)},
      {RGBA32I, glm::ivec4(INT32_MIN, INT32_MAX, -1, 0), {-7, 1e9f, -2e9f, 3}, {2e9f, -5, 6, -2147483648.0f},
       {-1, 0x7FF, -0x800, 5}, {-20, -21, -22, -23}, NAND, 0xA, CLAMP_TO_BORDER, glm::ivec4(INT32_MIN, 5, -6, 7)},
  };
  for (int k = 0; k < 6; ++k) {
    const Cell& c = cells[k];
    std::vector<IntegerDraw> draws(3);
    draws[0].triangles = join(tri({0, 0}, {16, 0}, {0, 16}, c.a), tri({16, 16}, {4.5f, 16}, {16, 5.25f}, c.c));
    draws[1].triangles = tri({2, 1}, {15, 9}, {6, 15}, c.logic_value);
    draws[1].logic = c.logic;
    draws[2].triangles = tri({0, 8}, {10, 2}, {12, 14}, c.masked);
    draws[2].mask = c.mask;
    const float x = 2.0f + float(k % 3) * 42.0f, y = 10.0f + float(k / 3) * 62.0f;
    const std::vector<Vertex> quad = QuadWith({Win(x, y), Win(x + 40, y), Win(x + 40, y + 40), Win(x, y + 40)},
                                              Uv({-0.25f, -0.25f}, {1.25f, -0.25f}, {1.25f, 1.25f}, {-0.25f, 1.25f}));
    b.DrawIntegerTarget(c.format, 16, 16, c.clear, draws, c.wrap, c.border, quad);
  }
}

// Buffer textures: texelFetch in four formats from buffers of pseudo-random texels, 4 x 4 pixels a texel, 16 x 16
// texels a quadrant (indices before the store's first texel and past its last among them: zero texels, (0, 0, 0, 1)
// where the format has no alpha); a store changed by BufferSubData between the draws of the two halves of a
// quadrant (each half shows the texels it was drawn with); textureSize in the top rows of each quadrant.
void TextureBuffer(Backend& b) {
  ClearBlack(b);
  std::uint32_t seed = 5;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  // n texels of `bytes` bytes each, in [0, 1] where the format is a float one (halves 0 ... 0x3C00, floats by value).
  const auto texels = [&](Enum format, int n) {
    std::vector<std::uint8_t> v;
    for (int i = 0; i < n; ++i) {
      const int channels = format == RG16 ? 2 : format == R32F ? 1 : 4;
      for (int c = 0; c < channels; ++c) {
        if (format == RGBA8) {
          v.push_back(std::uint8_t(next()));
        } else if (format == R32F) {
          const float f = float(next() % 100001) / 100000.0f;
          std::uint8_t b4[4];
          std::memcpy(b4, &f, 4);
          v.insert(v.end(), b4, b4 + 4);
        } else {  // RG16: any word; RGBA16F: a half in [0, 1]
          const std::uint32_t w = format == RGBA16F ? next() % 0x3C01 : next() & 0xFFFF;
          v.push_back(std::uint8_t(w));
          v.push_back(std::uint8_t(w >> 8));
        }
      }
    }
    return v;
  };
  const auto draw = [&](float x0, float y0, float x1, float y1, float offset, float size) {
    const glm::vec4 e(offset, size, 0, 0);
    b.Draw(TRIANGLES, QuadWith({Win(x0, y0), Win(x1, y0), Win(x1, y1), Win(x0, y1)}, {e, e, e, e}),
           Program::kTextureBuffer);
  };
  const struct Quadrant { float x, y; Enum format; int texels; float offset; } quadrants[] = {
      {0, 64, RGBA8, 256, 0}, {64, 64, RG16, 200, -20}, {0, 0, RGBA16F, 256, 40}, {64, 0, R32F, 256, 0}};
  for (const Quadrant& q : quadrants) {
    const std::uint32_t buffer = b.NewBufferTexture(q.format, texels(q.format, q.texels));
    if (q.format != R32F) {
      draw(q.x, q.y, q.x + 64, q.y + 60, q.offset, 0);
    } else {  // the left half, then the first 128 texels replaced, then the right half
      draw(q.x, q.y, q.x + 32, q.y + 60, q.offset, 0);
      b.BufferSubDataTexture(buffer, 0, texels(R32F, 128));
      draw(q.x + 32, q.y, q.x + 64, q.y + 60, q.offset, 0);
    }
    draw(q.x, q.y + 60, q.x + 64, q.y + 64, 0, 1);
  }
}

// A mipmapped 16 x 16 x 8 3D texture: trilinear filtering on a receding plane whose r runs through the slices (the
// level of detail takes r's derivatives too), REPEAT and CLAMP_TO_EDGE in r, and NEAREST slices.
void Texture3D(Backend& b) {
  ClearBlack(b);
  LayeredDesc d;
  d.target = TEXTURE_3D;
  d.width = d.height = 16;
  d.depth_or_layers = 8;
  d.rgba = LayeredPattern(16, 16, 8);
  d.generate_mipmap = true;
  d.min_filter = LINEAR_MIPMAP_LINEAR;
  b.SetLayeredTexture(d);
  const glm::mat4 mvp = glm::perspective(glm::radians(60.0f), 1.0f, 0.3f, 60.0f) *
                        glm::lookAt(glm::vec3(0, 1, 1), glm::vec3(0, 0, -8), glm::vec3(0, 1, 0));
  b.Viewport(0, 64, 64, 64);
  b.Draw(TRIANGLES,
         QuadWith(Floor(mvp, -6, 6, 1, -40),
                  {glm::vec4(0, 0, 0, 0), glm::vec4(2, 0, 0, 0), glm::vec4(2, 6, 3, 0), glm::vec4(0, 6, 3, 0)}),
         Program::kVolume);
  // r along x only: the level of detail from r's derivative where s and t change slowly.
  b.Viewport(64, 64, 64, 64);
  b.Draw(TRIANGLES,
         QuadWith({Win(0, 0), Win(128, 0), Win(128, 128), Win(0, 128)},
                  {glm::vec4(0.2f, 0.2f, 0, 0), glm::vec4(0.3f, 0.2f, 6, 0), glm::vec4(0.3f, 0.3f, 6, 0),
                   glm::vec4(0.2f, 0.3f, 0, 0)}),
         Program::kVolume);
  b.Viewport(0, 0, kSize, kSize);
  d.generate_mipmap = false;
  d.min_filter = LINEAR;
  d.wrap_r = CLAMP_TO_EDGE;
  b.SetLayeredTexture(d);
  b.Draw(TRIANGLES,
         QuadWith({Win(0, 0), Win(64, 0), Win(64, 64), Win(0, 64)},
                  {glm::vec4(0, 0, -0.3f, 0), glm::vec4(1, 0, 1.3f, 0), glm::vec4(1, 1, 1.3f, 0),
                   glm::vec4(0, 1, -0.3f, 0)}),
         Program::kVolume);
  d.min_filter = d.mag_filter = NEAREST;
  d.wrap_r = REPEAT;
  b.SetLayeredTexture(d);
  b.Draw(TRIANGLES,
         QuadWith({Win(64, 0), Win(128, 0), Win(128, 64), Win(64, 64)},
                  {glm::vec4(0, 0, 0.03f, 0), glm::vec4(1, 0, 1.97f, 0), glm::vec4(1, 1, 1.97f, 0),
                   glm::vec4(0, 1, 0.03f, 0)}),
         Program::kVolume);
}

// A depth array of 3 layers (ramps of different slopes) compared against a reference across quads, each quad on
// its own layer, NEAREST and LINEAR: a cascaded shadow map's lookups. (The quads are 41 pixels wide, 0.3 pixel off
// the grid: no pixel centre falls on a texel edge, where the interpolated coordinate may round to either texel.)
void ShadowArray(Backend& b) {
  ClearBlack(b);
  LayeredDesc d;
  d.width = d.height = 16;
  d.depth_or_layers = 3;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i)
        d.depth.push_back(((i / 4 + j / 4 + k) % 2 ? 0.3f : 0.7f) + 0.01f * float(i % 4) + 0.05f * float(k));
  d.min_filter = d.mag_filter = NEAREST;
  d.wrap_s = d.wrap_t = CLAMP_TO_EDGE;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) d.min_filter = d.mag_filter = LINEAR;
    d.compare_func = pass == 0 ? LEQUAL : GREATER;
    b.SetLayeredTexture(d);
    for (int k = 0; k < 3; ++k) {
      const float x0 = float(k) * 42 + 0.3f, y0 = float(pass) * 64;
      b.Draw(TRIANGLES,
             QuadWith({Win(x0, y0), Win(x0 + 41, y0), Win(x0 + 41, y0 + 64), Win(x0, y0 + 64)},
                      {glm::vec4(0, 0, float(k), 0.15f), glm::vec4(1, 0, float(k), 0.85f),
                       glm::vec4(1, 1, float(k), 0.85f), glm::vec4(0, 1, float(k), 0.15f)}),
             Program::kArrayShadow);
    }
  }
}

// ---- A real model ------------------------------------------------------------------------------------------------

void Model(Backend& b) {
  b.ClearColor(0.1f, 0.1f, 0.12f, 1);
  b.ClearDepth(1.0);
  b.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  const aiScene* scene = aiImportFile(kModelPath, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                      aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices);
  if (!scene) return;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned i = 0; i < scene->mMeshes[m]->mNumVertices; ++i) {
      const aiVector3D& p = scene->mMeshes[m]->mVertices[i];
      lo = glm::min(lo, glm::vec3(p.x, p.y, p.z));
      hi = glm::max(hi, glm::vec3(p.x, p.y, p.z));
    }
  const glm::vec3 center = (lo + hi) * 0.5f;
  const float radius = glm::length(hi - lo) * 0.5f;
  const glm::mat4 mvp = glm::perspective(glm::radians(40.0f), 1.0f, radius * 0.5f, radius * 6.0f) *
                        glm::lookAt(center + radius * glm::vec3(1.2f, 1.4f, 2.2f), center, glm::vec3(0, 1, 0));
  b.Enable(DEPTH_TEST);
  b.Enable(CULL_FACE);
  Uniforms u;
  u.light_dir = glm::normalize(glm::vec3(0.5f, 0.8f, 0.4f));
  u.half_vector = glm::normalize(u.light_dir + glm::normalize(glm::vec3(1.2f, 1.4f, 2.2f)));
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    std::vector<Vertex> v;
    std::vector<std::uint32_t> idx;
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D& p = mesh->mVertices[i];
      const aiVector3D n = mesh->mNormals ? mesh->mNormals[i] : aiVector3D(0, 1, 0);
      v.push_back({mvp * glm::vec4(p.x, p.y, p.z, 1), glm::vec4(1), glm::vec4(n.x, n.y, n.z, 0)});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        idx.insert(idx.end(), mesh->mFaces[f].mIndices, mesh->mFaces[f].mIndices + 3);
    u.tint = glm::vec4(Palette(m + 7).r * 0.5f + 0.5f, 0.6f, Palette(m + 7).b * 0.5f + 0.4f, 1.0f);
    b.Draw(TRIANGLES, v, idx, Program::kLit, u);
  }
  aiReleaseImport(scene);
  b.Disable(CULL_FACE);
  b.Disable(DEPTH_TEST);
}

}  // namespace

const std::vector<SceneInfo>& Scenes() {
  static const std::vector<SceneInfo> scenes = {
      {"fill_rule_triangles", kSize, kSize, Check::kExact, FillRuleTriangles},
      {"fill_rule_shared_edges", kSize, kSize, Check::kExact, FillRuleSharedEdges},
      {"points", kSize, kSize, Check::kExact, Points},
      {"point_sprites", kSize, kSize, Check::kColor, PointSprites},
      {"lines", kSize, kSize, Check::kExact, Lines},
      {"line_interpolation", kSize, kSize, Check::kCoverage, LineInterpolation},
      {"wide_lines", kSize, kSize, Check::kExact, WideLines},
      {"wide_ties", kSize, kSize, Check::kExact, WideTies},
      {"polygon_mode_line", kSize, kSize, Check::kExact, PolygonModeLine},
      {"culling", kSize, kSize, Check::kExact, Culling},
      {"draw_variants", kSize, kSize, Check::kColor, DrawVariants},
      {"instancing", kSize, kSize, Check::kColor, Instancing},
      {"integer_attributes", kSize, kSize, Check::kExact, IntegerAttributes},
      {"primitive_restart", kSize, kSize, Check::kColor, PrimitiveRestart},
      {"buffers", kSize, kSize, Check::kColor, Buffers},
      {"clipping", kSize, kSize, Check::kColor, Clipping},
      {"perspective", kSize, kSize, Check::kColor, Perspective},
      {"depth_functions", kSize, kSize, Check::kExactWithDepth, DepthFunctions},
      {"stencil", kSize, kSize, Check::kExactWithStencil, Stencil},
      {"blend_factors", kSize, kSize, Check::kColor, BlendFactors},
      {"blend_equations", kSize, kSize, Check::kColor, BlendEquations},
      {"masks", kSize, kSize, Check::kExactWithStencil, Masks},
      {"clear_buffer", kSize, kSize, Check::kExactWithDepthStencil, ClearBuffers},
      {"scissor", kSize, kSize, Check::kExact, Scissor},
      {"conditional_render", kSize, kSize, Check::kExact, ConditionalRender},
      {"layered_framebuffers", kSize, kSize, Check::kExact, LayeredFramebuffers},
      {"vertex_layer", kSize, kSize, Check::kExact, VertexLayer},
      {"geometry_stage", kSize, kSize, Check::kColor, GeometryStage},
      {"geometry_adjacency", kSize, kSize, Check::kColor, GeometryAdjacency},
      {"geometry_layer", kSize, kSize, Check::kColor, GeometryLayer},
      {"polygon_offset", kSize, kSize, Check::kExactWithDepth, PolygonOffset},
      {"texture_filters", kSize, kSize, Check::kTexture, TextureFilters},
      {"texture_wraps", kSize, kSize, Check::kTexture, TextureWraps},
      {"sampler_objects", kSize, kSize, Check::kTexture, SamplerObjects},
      {"texture_generated_mipmaps", kSize, kSize, Check::kTexture, TextureGeneratedMipmaps},
      {"render_to_texture", kSize, kSize, Check::kTexture, RenderToTexture},
      {"texture_anisotropic", kSize, kSize, Check::kCoverage, TextureAnisotropic},
      {"srgb_texture", kSize, kSize, Check::kTexture, SrgbTexture},
      {"srgb_framebuffer", kSize, kSize, Check::kTexture, SrgbFramebuffer},
      {"float_targets", kSize, kSize, Check::kColor, FloatTargets},
      {"unorm16_targets", kSize, kSize, Check::kColor, Unorm16Targets},
      {"multiple_outputs", kSize, kSize, Check::kColor, MultipleOutputs},
      {"per_buffer_state", kSize, kSize, Check::kColor, PerBufferState},
      {"texture_16bit", kSize, kSize, Check::kTexture, Texture16Bit},
      {"packed16_targets", kSize, kSize, Check::kStep4, Packed16Targets},
      {"packed16_blending", kSize, kSize, Check::kStep4, Packed16Blending},
      {"logic_op", kSize, kSize, Check::kExact, LogicOps},
      {"logic_op_srgb", kSize, kSize, Check::kExact, LogicOpSrgb},
      {"copy_tex_image", kSize, kSize, Check::kColor, CopyTexImage},
      {"depth16", kSize, kSize, Check::kExactWithDepth, Depth16},
      {"stencil_renderbuffer", kSize, kSize, Check::kExactWithDepthStencil, StencilRenderbuffer},
      {"stencil_index8", kSize, kSize, Check::kExactWithStencil, StencilIndex8},
      {"stencil_texture", kSize, kSize, Check::kExactWithDepthStencil, StencilTexture},
      {"blit_nearest", kSize, kSize, Check::kExactWithDepthStencil, BlitNearest},
      {"blit_linear", kSize, kSize, Check::kColor, BlitLinear},
      {"msaa_coverage", kSize, kSize, Check::kColor, MultisampleCoverage},
      {"msaa_lines_points", kSize, kSize, Check::kColor, MultisampleLinesPoints},
      {"msaa_wide_lines", kSize, kSize, Check::kColor, MultisampleWideLines},
      {"msaa_sample_shading", kSize, kSize, Check::kTexture, MultisampleSampleShading},
      {"msaa_resolve", kSize, kSize, Check::kColor, MultisampleResolve},
      {"msaa_coverage_ops", kSize, kSize, Check::kColor, MultisampleCoverageOps},
      {"msaa_texture", kSize, kSize, Check::kExact, MultisampleTexture},
      {"msaa_texture_array", kSize, kSize, Check::kExact, MultisampleTextureArray},
      {"cube_map", kSize, kSize, Check::kTexture, CubeMap},
      {"shadow_compare", kSize, kSize, Check::kTexture, ShadowCompare},
      {"texture_array", kSize, kSize, Check::kTexture, TextureArray},
      {"texture_3d", kSize, kSize, Check::kTexture, Texture3D},
      {"texture_1d", kSize, kSize, Check::kTexture, Texture1D},
      {"compressed_textures", kSize, kSize, Check::kTexture, CompressedTextures},
      {"texture_buffer", kSize, kSize, Check::kExact, TextureBuffer},
      {"integer_formats", kSize, kSize, Check::kExact, IntegerFormats},
      {"shadow_array", kSize, kSize, Check::kTexture, ShadowArray},
      {"model", 256, 256, Check::kColor, Model},
  };
  return scenes;
}

}  // namespace conformance

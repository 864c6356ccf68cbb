// Clipping: polygons fully in, fully out, crossing one or several planes; varyings on the planes; lines.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <vector>

#include "clipper.h"

using namespace softgl::detail;

namespace {

ClipVertex V(float x, float y, float z, float w, float var0 = 0.0f) {
  ClipVertex v{};
  v.pos = glm::vec4(x, y, z, w);
  v.var[0] = var0;
  return v;
}

// Every vertex lies inside the view volume (with a little slack for rounding).
bool InsideVolume(const ClipPolygon& p) {
  for (int i = 0; i < p.count; ++i) {
    const glm::vec4& q = p.v[i].pos;
    const float eps = 1e-5f * std::fabs(q.w) + 1e-6f;
    if (std::fabs(q.x) > q.w + eps || std::fabs(q.y) > q.w + eps || std::fabs(q.z) > q.w + eps || q.w <= 0.0f)
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("a triangle inside the view volume passes unchanged", "[clipper]") {
  ClipPolygon out;
  ClipTriangle(V(-0.5f, -0.5f, 0, 1, 1), V(0.5f, -0.5f, 0, 1, 2), V(0, 0.5f, 0, 1, 3), 1, ClipPlanes{}, out);
  REQUIRE(out.count == 3);
  CHECK(out.v[1].pos == glm::vec4(0.5f, -0.5f, 0, 1));
  CHECK(out.v[2].var[0] == 3.0f);
}

TEST_CASE("a triangle outside one plane is removed", "[clipper]") {
  ClipPolygon out;
  ClipTriangle(V(2, 0, 0, 1), V(3, 1, 0, 1), V(2.5f, -1, 0, 1), 1, ClipPlanes{}, out);
  CHECK(out.count == 0);
  ClipTriangle(V(0, 0, -2, 1), V(0.5f, 0, -3, 1), V(0, 0.5f, -2, 1), 1, ClipPlanes{}, out);  // before the near plane
  CHECK(out.count == 0);
  ClipTriangle(V(0, 0, 0, -1), V(0.1f, 0, 0, -1), V(0, 0.1f, 0, -1), 1, ClipPlanes{}, out);  // behind the eye
  CHECK(out.count == 0);
}

TEST_CASE("crossing the near plane puts new vertices on it with interpolated varyings", "[clipper]") {
  // Vertex a is in front of the near plane (z < -w), b and c are inside.
  const ClipVertex a = V(0, 0, -3, 1, 10.0f), b = V(0.5f, 0, 0, 1, 0.0f), c = V(0, 0.5f, 0, 1, 0.0f);
  ClipPolygon out;
  ClipTriangle(a, b, c, 1, ClipPlanes{}, out);
  REQUIRE(out.count == 4);
  CHECK(InsideVolume(out));
  int on_plane = 0;
  for (int i = 0; i < out.count; ++i) {
    const glm::vec4& p = out.v[i].pos;
    if (std::fabs(p.z + p.w) < 1e-6f) {
      ++on_plane;
      // t = 2/3 of the way from the inside vertex (z = 0) to a (z = -3) reaches z = -1.
      CHECK(out.v[i].var[0] == Approx(10.0f * 1.0f / 3.0f));
    }
  }
  CHECK(on_plane == 2);
}

TEST_CASE("a triangle crossing several planes becomes a polygon inside all of them", "[clipper]") {
  // A big triangle covering the whole view volume and more: clipped to the square x, y in [-1, 1].
  ClipPolygon out;
  ClipTriangle(V(-10, -10, 0, 1, 0), V(10, -10, 0, 1, 1), V(0, 10, 0, 1, 2), 1, ClipPlanes{}, out);
  REQUIRE(out.count == 4);
  CHECK(InsideVolume(out));
  // Area of the clipped polygon in NDC is the full 2 x 2 square.
  float area = 0;
  for (int i = 0; i < out.count; ++i) {
    const glm::vec4& p = out.v[i].pos;
    const glm::vec4& q = out.v[(i + 1) % out.count].pos;
    area += p.x * q.y - q.x * p.y;
  }
  CHECK(std::fabs(area) * 0.5f == Approx(4.0f));
  // Varyings stay linear in clip space: at (x, y) the varying is 0 + (x+10)/20 * 1 + ... ; check one corner.
  for (int i = 0; i < out.count; ++i) CHECK(out.v[i].var[0] >= 0.0f);
}

TEST_CASE("near, far and side planes at once, with w varying", "[clipper]") {
  ClipPolygon out;
  ClipTriangle(V(-3, 0, -4, 2), V(4, 1, 5, 3), V(0, -6, 1, 1.5f), 1, ClipPlanes{}, out);
  REQUIRE(out.count >= 3);
  CHECK(out.count <= kMaxPolygonVertices);
  CHECK(InsideVolume(out));
}

TEST_CASE("the guard band decides whether to clip; clipping then uses the view volume", "[clipper]") {
  ClipPlanes guard;
  guard.guard_x = guard.guard_y = 4.0f;
  ClipPolygon out;
  ClipTriangle(V(-3, -3, 0, 1), V(3, -3, 0, 1), V(0, 3, 0, 1), 1, guard, out);
  CHECK(out.count == 3);  // inside the guard band: untouched
  ClipTriangle(V(-3, -3, -2, 1), V(3, -3, 0, 1), V(0, 3, 0, 1), 1, guard, out);
  CHECK(out.count >= 4);  // the near plane forces clipping, and then x and y are clipped to the volume too
  CHECK(InsideVolume(out));
  ClipTriangle(V(-9, -9, 0, 1), V(3, -3, 0, 1), V(0, 3, 0, 1), 1, guard, out);
  CHECK(InsideVolume(out));  // outside the guard band: clipped to the volume
}

TEST_CASE("non-finite positions discard the primitive", "[clipper]") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  ClipPolygon out;
  ClipTriangle(V(nan, 0, 0, 1), V(1, 0, 0, 1), V(0, 1, 0, 1), 1, ClipPlanes{}, out);
  CHECK(out.count == 0);
  ClipTriangle(V(0, 0, 0, inf), V(1, 0, 0, 1), V(0, 1, 0, 1), 1, ClipPlanes{}, out);
  CHECK(out.count == 0);
  CHECK(ClipCodes(glm::vec4(0, 0, 0, nan), ClipPlanes{}) == kClipNonFinite);
}

TEST_CASE("lines are clipped to the view volume", "[clipper]") {
  ClipVertex a, b;
  REQUIRE(ClipLine(V(-2, 0, 0, 1, 0), V(2, 0, 0, 1, 4), 1, ClipPlanes{}, a, b));
  CHECK(a.pos.x == Approx(-1.0f));
  CHECK(b.pos.x == Approx(1.0f));
  CHECK(a.var[0] == Approx(1.0f));
  CHECK(b.var[0] == Approx(3.0f));
  CHECK_FALSE(ClipLine(V(2, 0, 0, 1), V(3, 0, 0, 1), 1, ClipPlanes{}, a, b));
  CHECK_FALSE(ClipLine(V(2, 0, 0, 1), V(0, 3, 0, 1), 1, ClipPlanes{}, a, b));  // passes outside the corner
}

TEST_CASE("clip codes of many vertices at once equal the one-vertex codes", "[clipper]") {
  // Positions on and near every plane, beyond the guard band, at w = 0 and below kMinW, and with NaN or infinite
  // coordinates in each component; counts that leave a remainder for every vector width.
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float values[] = {0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 1.0000001f, -1.0000001f, 2.0f, -3.0f, 1e-7f,
                          1e-6f, 3e4f, -3e4f, 1e30f, -1e30f, inf, -inf, nan};
  std::vector<glm::vec4> p;
  std::uint32_t seed = 7;
  auto pick = [&] {
    seed = seed * 1664525u + 1013904223u;
    return values[(seed >> 8) % std::size(values)];
  };
  for (int i = 0; i < 4000; ++i) p.push_back(glm::vec4(pick(), pick(), pick(), pick()));
  const ClipPlanes planes[] = {ClipPlanes{}, ClipPlanes{1.5f, 2.0f}};
  for (const ClipPlanes& pl : planes) {
    for (int count : {0, 1, 3, 7, 15, 17, 31, 4000}) {
      std::vector<unsigned> codes(std::size_t(count) + 1, 0xDEADu);
      ClipCodesOfVertices(p.data(), count, pl, codes.data());
      int mismatches = 0;
      for (int i = 0; i < count; ++i) mismatches += codes[std::size_t(i)] != ClipCodes(p[std::size_t(i)], pl);
      CHECK(mismatches == 0);
      CHECK(codes[std::size_t(count)] == 0xDEADu);  // nothing written past the end
    }
  }
  // The known cases.
  unsigned c[4];
  const glm::vec4 known[4] = {{0, 0, 0, 1}, {2, 0, -2, 1}, {0, 0, 0, 0}, {0, nan, 0, 1}};
  ClipCodesOfVertices(known, 4, ClipPlanes{}, c);
  CHECK(c[0] == 0u);
  CHECK(c[1] == (kClipRight | kClipNear));
  CHECK(c[2] == kClipW);
  CHECK(c[3] == kClipNonFinite);
}

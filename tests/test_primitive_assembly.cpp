// Primitive assembly: counts and vertex order for every mode.
#include <catch2/catch.hpp>

#include <vector>

#include "primitive_assembly.h"

using namespace softgl;
using detail::AssemblePrimitives;
using detail::Primitives;
using detail::PrimitiveCount;

namespace {
std::vector<std::uint32_t> Assemble(Enum mode, int count) {
  Primitives p;
  AssemblePrimitives(mode, count, p);
  return p.indices;
}
}  // namespace

TEST_CASE("primitive assembly follows OpenGL's modes", "[primitive_assembly]") {
  using V = std::vector<std::uint32_t>;
  CHECK(Assemble(POINTS, 3) == V{0, 1, 2});
  CHECK(Assemble(LINES, 5) == V{0, 1, 2, 3});  // the incomplete last line is dropped
  CHECK(Assemble(LINE_STRIP, 4) == V{0, 1, 1, 2, 2, 3});
  CHECK(Assemble(LINE_LOOP, 3) == V{0, 1, 1, 2, 2, 0});
  CHECK(Assemble(LINE_STRIP, 1).empty());
  CHECK(Assemble(LINE_LOOP, 1).empty());
  CHECK(Assemble(TRIANGLES, 7) == V{0, 1, 2, 3, 4, 5});
  // Odd strip triangles swap their first two vertices so that all keep the winding of the first.
  CHECK(Assemble(TRIANGLE_STRIP, 5) == V{0, 1, 2, 2, 1, 3, 2, 3, 4});
  CHECK(Assemble(TRIANGLE_FAN, 5) == V{0, 1, 2, 0, 2, 3, 0, 3, 4});
  CHECK(Assemble(TRIANGLE_STRIP, 2).empty());
  CHECK(Assemble(TRIANGLES, 0).empty());
}

TEST_CASE("primitive assembly rejects unknown modes", "[primitive_assembly]") {
  Primitives p;
  AssemblePrimitives(0x1234, 6, p);
  CHECK(p.vertices_per_primitive == 0);
  CHECK(p.Count() == 0);
  CHECK(detail::VerticesPerPrimitive(TRIANGLE_FAN) == 3);
  CHECK(detail::VerticesPerPrimitive(LINE_LOOP) == 2);
}

TEST_CASE("primitive restart assembles each run on its own", "[primitive_assembly]") {
  using V = std::vector<std::uint32_t>;
  auto with_restarts = [](Enum mode, int count, V restarts, bool first = false) {
    Primitives p;
    AssemblePrimitives(mode, count, restarts.data(), int(restarts.size()), p, first);
    return p.indices;
  };
  // Positions 3 and 6 restart: runs {0, 1, 2}, {4, 5}, {7, 8, 9, 10}.
  CHECK(with_restarts(TRIANGLE_STRIP, 11, {3, 6}) == V{0, 1, 2, 7, 8, 9, 9, 8, 10});
  CHECK(with_restarts(TRIANGLE_FAN, 11, {3, 6}) == V{0, 1, 2, 7, 8, 9, 7, 9, 10});
  CHECK(with_restarts(TRIANGLE_FAN, 11, {3, 6}, true) == V{1, 2, 0, 8, 9, 7, 9, 10, 7});
  CHECK(with_restarts(LINE_LOOP, 11, {3, 6}) == V{0, 1, 1, 2, 2, 0, 4, 5, 5, 4, 7, 8, 8, 9, 9, 10, 10, 7});
  CHECK(with_restarts(LINE_STRIP, 11, {3, 6}) == V{0, 1, 1, 2, 4, 5, 7, 8, 8, 9, 9, 10});
  CHECK(with_restarts(LINES, 11, {3, 6}) == V{0, 1, 4, 5, 7, 8, 9, 10});  // counting starts again in each run
  CHECK(with_restarts(TRIANGLES, 11, {3, 6}) == V{0, 1, 2, 7, 8, 9});
  CHECK(with_restarts(POINTS, 5, {0, 2}) == V{1, 3, 4});
  // Restarts at both ends and side by side leave empty runs, which draw nothing.
  CHECK(with_restarts(TRIANGLE_STRIP, 7, {0, 1, 5, 6}) == V{2, 3, 4});
  CHECK(with_restarts(TRIANGLE_STRIP, 4, {0, 1, 2, 3}).empty());
  // Strip parity counts from each run's start: the second run's first triangle is not swapped.
  CHECK(with_restarts(TRIANGLE_STRIP, 8, {4}) == V{0, 1, 2, 2, 1, 3, 5, 6, 7});
}

TEST_CASE("PrimitiveCount says how many primitives assembly makes, restarts included", "[primitive_assembly]") {
  const Enum modes[7] = {POINTS, LINES, LINE_STRIP, LINE_LOOP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN};
  const std::vector<std::uint32_t> restart_sets[4] = {{}, {0}, {3, 4, 9}, {1, 2, 5, 6, 11}};
  for (Enum mode : modes)
    for (int count = 0; count <= 13; ++count)
      for (const auto& all : restart_sets) {
        std::vector<std::uint32_t> restarts;
        for (std::uint32_t r : all)
          if (r < std::uint32_t(count)) restarts.push_back(r);
        Primitives p;
        AssemblePrimitives(mode, count, restarts.data(), int(restarts.size()), p);
        INFO("mode " << mode << ", count " << count << ", restarts " << restarts.size());
        CHECK(PrimitiveCount(mode, count, restarts.data(), int(restarts.size())) == std::uint64_t(p.Count()));
      }
  CHECK(PrimitiveCount(TRIANGLE_STRIP, 2000000000) == 1999999998u);  // no memory needed for any count
  CHECK(PrimitiveCount(0x1234, 9) == 0u);
}

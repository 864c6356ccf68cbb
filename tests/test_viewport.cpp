// Viewport mapping: the perspective divide and the viewport transform, one vertex and many at once.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "viewport.h"

using namespace softgl::detail;

TEST_CASE("the viewport transform maps normalized device coordinates onto the viewport and depth range",
          "[viewport]") {
  const ViewportTransform vp = MakeViewportTransform(10, 20, 200, 100, 0.25, 0.75);
  ClipVertex in{};
  in.pos = glm::vec4(-2.0f, 2.0f, -2.0f, 2.0f);  // NDC (-1, 1, -1)
  in.var[0] = 4.0f;
  WindowVertex out{};
  ToWindow(in, 1, vp, out);
  CHECK(out.win.x == 10.0f);
  CHECK(out.win.y == 120.0f);
  CHECK(out.win.z == 0.25f);
  CHECK(out.win.w == 0.5f);
  CHECK(out.var[0] == 2.0f);  // divided by w
}

TEST_CASE("window positions of many vertices at once are ToWindow's, bit for bit", "[viewport]") {
  const ViewportTransform vps[] = {MakeViewportTransform(0, 0, 1280, 720, 0.0, 1.0),
                                   MakeViewportTransform(-7, 13, 333, 77, 0.9, 0.1)};
  std::vector<glm::vec4> p;
  std::uint32_t seed = 11;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1 << 24);
  };
  for (int i = 0; i < 3000; ++i) {
    const float w = 0.01f + 50.0f * next();
    p.push_back(glm::vec4((next() * 2.0f - 1.0f) * w * 1.3f, (next() * 2.0f - 1.0f) * w * 1.3f,
                          (next() * 2.0f - 1.0f) * w, i % 2 ? w : -w));
  }
  for (const ViewportTransform& vp : vps) {
    for (int count : {0, 1, 5, 9, 16, 19, 3000}) {
      std::vector<glm::vec4> win(std::size_t(count) + 1, glm::vec4(-123.0f));
      WindowPositions(p.data(), count, vp, win.data());
      int mismatches = 0;
      for (int i = 0; i < count; ++i) {
        ClipVertex in{};
        in.pos = p[std::size_t(i)];
        WindowVertex one{};
        ToWindow(in, 0, vp, one);
        mismatches += std::memcmp(&one.win, &win[std::size_t(i)], sizeof(glm::vec4)) != 0;
      }
      CHECK(mismatches == 0);
      CHECK(win[std::size_t(count)] == glm::vec4(-123.0f));  // nothing written past the end
    }
  }
}

// Several contexts used from several threads at once: each renders exactly what it renders alone.
#include <catch2/catch.hpp>

#include <functional>
#include <thread>
#include <vector>

#include "scenes.h"

TEST_CASE("contexts on several threads render as they do alone", "[threads]") {
  const std::vector<std::function<softgl::Image()>> scenes_to_draw = {
      [] { return scenes::Triangle(160, 120); },      [] { return scenes::Cube(120, 120, 0.4f); },
      [] { return scenes::Wireframe(160, 120); },     [] { return scenes::Mirror(160, 120); },
      [] { return scenes::TexturedCube(160, 120); },  [] { return scenes::ShadowMap(160, 120); },
      [] { return scenes::EnvironmentMap(160, 120); }, [] { return scenes::Decals(160, 120); },
  };
  std::vector<softgl::Image> alone;
  for (const auto& draw : scenes_to_draw) alone.push_back(draw());
  // Every scene on its own thread, all at once, twice over.
  std::vector<softgl::Image> together(scenes_to_draw.size() * 2);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < together.size(); ++i)
    threads.emplace_back([&, i] { together[i] = scenes_to_draw[i % scenes_to_draw.size()](); });
  for (std::thread& t : threads) t.join();
  for (std::size_t i = 0; i < together.size(); ++i) {
    INFO("scene " << i % scenes_to_draw.size());
    CHECK(together[i].rgba == alone[i % scenes_to_draw.size()].rgba);
  }
}

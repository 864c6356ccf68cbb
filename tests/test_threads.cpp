// Several contexts used from several threads at once: each renders exactly what it renders alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <thread>
#include <vector>

#include "scene_kit.h"
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

namespace {

// Renders `draw` with contexts of `threads` threads (SOFTGL_THREADS is read when a context is created).
softgl::Image WithThreads(int threads, const std::function<softgl::Image()>& draw) {
  const std::string value = std::to_string(threads);
  setenv("SOFTGL_THREADS", value.c_str(), 1);
  softgl::Image image = draw();
  unsetenv("SOFTGL_THREADS");
  return image;
}

}  // namespace

TEST_CASE("every example scene is the same image with 1, 2, 3 and 8 threads", "[threads]") {
  // 320 x 240 is 5 x 4 tiles; the sizes are odd on purpose for the two that are not, so that tiles are cut.
  const std::string models = scenes::kTestModels;
  const std::vector<std::pair<const char*, std::function<softgl::Image()>>> all = {
      {"triangle", [] { return scenes::Triangle(320, 240); }},
      {"cube", [] { return scenes::Cube(241, 199, 0.6f); }},
      {"wireframe", [] { return scenes::Wireframe(320, 240); }},
      {"clipped", [] { return scenes::Clipped(320, 240); }},
      {"stencil_outline", [] { return scenes::StencilOutline(320, 240); }},
      {"mirror", [] { return scenes::Mirror(320, 240); }},
      {"transparency", [] { return scenes::Transparency(320, 240); }},
      {"decals", [] { return scenes::Decals(320, 240); }},
      {"textured_cube", [] { return scenes::TexturedCube(333, 211); }},
      {"srgb", [] { return scenes::Srgb(322, 240); }},
      {"multisample", [] { return scenes::Multisample(324, 170); }},
      {"shadow_map", [] { return scenes::ShadowMap(320, 240); }},
      {"cascaded_shadows", [] { return scenes::CascadedShadows(480, 180); }},
      {"small_formats", [] { return scenes::SmallFormats(400, 120); }},
      {"compressed_textures", [] { return scenes::CompressedTextures(400, 240); }},
      {"buffer_texture", [] { return scenes::BufferTextures(320, 200); }},
      {"picking", [] { return scenes::Picking(320, 200); }},
      {"deferred", [] { return scenes::Deferred(320, 200); }},
      {"post_process", [] { return scenes::PostProcess(320, 240); }},
      {"environment_map", [] { return scenes::EnvironmentMap(320, 240); }},
      {"model_duck_phong", [&] { return scenes::ModelView(models + "/Collada/duck.dae", "phong", 320, 240, 30, 20); }},
      {"model_spider_unlit", [&] { return scenes::ModelView(models + "/OBJ/spider.obj", "unlit", 320, 240, 40, 30); }},
      {"model_box_pbr",
       [&] { return scenes::ModelView(models + "/glTF2/BoxTextured-glTF/BoxTextured.gltf", "pbr", 320, 240, 35, 25); }},
      {"model_engine_pbr",
       [&] {
         return scenes::ModelView(models + "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "pbr", 320, 240,
                                  30, 20);
       }},
  };
  for (const auto& [name, draw] : all) {
    INFO("scene " << name);
    const softgl::Image one = WithThreads(1, draw);
    REQUIRE(one.width > 0);
    REQUIRE(!one.rgba.empty());
    for (int threads : {2, 3, 8}) {
      INFO("threads " << threads);
      const softgl::Image many = WithThreads(threads, draw);
      CHECK(many.width == one.width);
      CHECK(many.rgba == one.rgba);
    }
  }
}

TEST_CASE("Context::Options and SOFTGL_THREADS set the thread count", "[threads]") {
  CHECK(softgl::Context(4, 4, softgl::Context::Options{3}).Threads() == 3);
  setenv("SOFTGL_THREADS", "5", 1);
  CHECK(softgl::Context(4, 4).Threads() == 5);
  CHECK(softgl::Context(4, 4, softgl::Context::Options{2}).Threads() == 2);  // an explicit count wins
  setenv("SOFTGL_THREADS", "zero", 1);  // not a number: the machine's count
  CHECK(softgl::Context(4, 4).Threads() == int(std::max(1u, std::thread::hardware_concurrency())));
  unsetenv("SOFTGL_THREADS");
}

TEST_CASE("BlitFramebuffer in bands of rows on the context's threads gives the same pixels with 1, 2, 3 and 8",
          "[threads]") {
  // A 4-sample RGB565 and a 4-sample RGBA16F framebuffer object resolved into single-sampled ones of their format,
  // each copied 1:1 into the window's halves, then a scaled LINEAR blit of the window into itself elsewhere: row
  // counts of 256 and more, so that the blits are split into bands.
  auto draw = [] {
    using namespace softgl;
    Context gl(700, 600);
    scenes::kit::ColorShader shader;  // position (attribute 0), colour (attribute 1)
    const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
    gl.BindVertexArray(vao);
    gl.BindBuffer(ARRAY_BUFFER, vbo);
    gl.VertexAttributePointer(0, 3, FLOAT, false, 6 * sizeof(float), 0);
    gl.VertexAttributePointer(1, 3, FLOAT, false, 6 * sizeof(float), 3 * sizeof(float));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
    const Enum formats[2] = {RGB565, RGBA16F};
    for (int k = 0; k < 2; ++k) {
      std::uint32_t fbo[2], rb[2];
      for (int i = 0; i < 2; ++i) {
        fbo[i] = gl.GenFramebuffer();
        rb[i] = gl.GenRenderbuffer();
        gl.BindRenderbuffer(RENDERBUFFER, rb[i]);
        gl.RenderbufferStorageMultisample(RENDERBUFFER, i == 0 ? 4 : 0, formats[k], 350, 520);
        gl.BindFramebuffer(FRAMEBUFFER, fbo[i]);
        gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb[i]);
      }
      gl.BindFramebuffer(FRAMEBUFFER, fbo[0]);
      gl.Viewport(0, 0, 350, 520);
      gl.ClearColor(0.1f, 0.2f + 0.3f * float(k), 0.3f, 1.0f);
      gl.Clear(COLOR_BUFFER_BIT);
      const float g = 0.6f - 0.4f * float(k);
      const float vertices[] = {-0.9f, -0.95f, 0, 0.9f, g, 0.2f, 0.95f, -0.4f, 0, 0.2f, g, 0.9f, -0.3f, 0.97f, 0, 0.5f, 1, 0.1f};
      gl.BufferData(ARRAY_BUFFER, sizeof vertices, vertices);
      gl.UseProgram(shader);
      gl.DrawArrays(TRIANGLES, 0, 3);
      gl.BindFramebuffer(DRAW_FRAMEBUFFER, fbo[1]);
      gl.BlitFramebuffer(0, 0, 350, 520, 0, 0, 350, 520, COLOR_BUFFER_BIT, NEAREST);
      gl.BindFramebuffer(READ_FRAMEBUFFER, fbo[1]);
      gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
      gl.BlitFramebuffer(0, 0, 350, 520, 350 * k, 0, 350 * (k + 1), 520, COLOR_BUFFER_BIT, NEAREST);
    }
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    gl.BlitFramebuffer(0, 0, 700, 300, 100, 300, 450, 600, COLOR_BUFFER_BIT, LINEAR);
    CHECK(gl.GetError() == NO_ERROR);
    return gl.ReadPixels();
  };
  const softgl::Image one = WithThreads(1, draw);
  for (int threads : {2, 3, 8}) {
    INFO(threads << " threads");
    const bool same = WithThreads(threads, draw).rgba == one.rgba;  // (not printed: 1.7 million bytes)
    CHECK(same);
  }
}

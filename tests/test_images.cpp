// Image tests: each example scene against its golden PNG (tests/golden), made by this code and checked by eye.
//
// Tolerance: every channel of every pixel within 1 of the golden image (float rounding may differ between
// compilers and optimisation levels; coverage, being exact integer arithmetic, may not). On failure the actual
// image and a difference image are written to the test output folder. Set SOFTGL_UPDATE_GOLDEN=1 to rewrite the
// golden images instead (then look at them before committing).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "scenes.h"

namespace {

constexpr int kTolerance = 1;

void CompareWithGolden(const std::string& name, const softgl::Image& actual) {
  const std::string golden_path = std::string(SOFTGL_GOLDEN_DIR) + "/" + name + ".png";
  if (const char* update = std::getenv("SOFTGL_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    REQUIRE(softgl::WritePng(golden_path, actual));
    WARN("rewrote " << golden_path);
    return;
  }
  softgl::Image golden;
  std::string error;
  REQUIRE(softgl::ReadImage(golden_path, golden, &error));
  REQUIRE(golden.width == actual.width);
  REQUIRE(golden.height == actual.height);
  softgl::Image diff = actual;
  int worst = 0, over = 0;
  for (std::size_t i = 0; i < actual.rgba.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(actual.rgba[i + c]) - int(golden.rgba[i + c])));
    worst = std::max(worst, d);
    over += d > kTolerance;
    const std::uint8_t v = std::uint8_t(std::min(255, d * 32));
    diff.rgba[i] = v;
    diff.rgba[i + 1] = v;
    diff.rgba[i + 2] = v;
    diff.rgba[i + 3] = 255;
  }
  INFO(name << ": largest channel difference " << worst << ", pixels over tolerance " << over);
  if (over > 0) {
    std::filesystem::create_directories(SOFTGL_TEST_OUTPUT_DIR);
    softgl::WritePng(std::string(SOFTGL_TEST_OUTPUT_DIR) + "/" + name + "_actual.png", actual);
    softgl::WritePng(std::string(SOFTGL_TEST_OUTPUT_DIR) + "/" + name + "_diff.png", diff);
  }
  CHECK(over == 0);
}

}  // namespace

TEST_CASE("image: triangle", "[image]") { CompareWithGolden("triangle", scenes::Triangle(640, 480)); }

TEST_CASE("image: cube frames", "[image]") {
  CompareWithGolden("cube_0", scenes::Cube(480, 480, 0.0f));
  CompareWithGolden("cube_3", scenes::Cube(480, 480, 2.0f * 3.14159265f * 3.0f / 32.0f));
}

TEST_CASE("image: wireframe", "[image]") { CompareWithGolden("wireframe", scenes::Wireframe(640, 480)); }

TEST_CASE("image: clipped", "[image]") { CompareWithGolden("clipped", scenes::Clipped(640, 480)); }

TEST_CASE("image: stencil outline", "[image]") { CompareWithGolden("stencil_outline", scenes::StencilOutline(640, 480)); }

TEST_CASE("image: mirror", "[image]") { CompareWithGolden("mirror", scenes::Mirror(640, 480)); }

TEST_CASE("image: transparency", "[image]") { CompareWithGolden("transparency", scenes::Transparency(640, 480)); }

TEST_CASE("image: decals", "[image]") { CompareWithGolden("decals", scenes::Decals(640, 480)); }

TEST_CASE("image: textured cube", "[image]") { CompareWithGolden("textured_cube", scenes::TexturedCube(640, 480)); }

TEST_CASE("image: sRGB", "[image][srgb]") { CompareWithGolden("srgb", scenes::Srgb(640, 480)); }

TEST_CASE("image: multisample", "[image][multisample]") {
  CompareWithGolden("multisample", scenes::Multisample(640, 320));
}

TEST_CASE("image: sample shading", "[image][multisample]") {
  CompareWithGolden("sample_shading", scenes::SampleShading(480, 240));
}

TEST_CASE("image: shadow map", "[image]") { CompareWithGolden("shadow_map", scenes::ShadowMap(640, 480)); }

TEST_CASE("image: compressed textures", "[image][compression]") {
  CompareWithGolden("compressed_textures", scenes::CompressedTextures(800, 480));
}

TEST_CASE("image: small formats", "[image][packed]") {
  CompareWithGolden("small_formats", scenes::SmallFormats(800, 240));
}

TEST_CASE("image: cascaded shadows", "[image][layers]") {
  CompareWithGolden("cascaded_shadows", scenes::CascadedShadows(960, 360));
}

TEST_CASE("image: post-processing", "[image]") { CompareWithGolden("post_process", scenes::PostProcess(640, 480)); }

TEST_CASE("image: instancing", "[image]") { CompareWithGolden("instancing", scenes::Instancing(800, 500)); }
TEST_CASE("image: buffer_texture", "[image]") {
  CompareWithGolden("buffer_texture", scenes::BufferTextures(800, 500));
}

TEST_CASE("image: picking", "[image]") {
  CompareWithGolden("picking", scenes::Picking(800, 500));
}

TEST_CASE("image: deferred", "[image]") {
  CompareWithGolden("deferred", scenes::Deferred(800, 500));
}

TEST_CASE("image: particles", "[image]") { CompareWithGolden("particles", scenes::Particles(640, 400)); }
TEST_CASE("image: feedback_particles", "[image]") {
  CompareWithGolden("feedback_particles", scenes::FeedbackParticles(640, 400));
}

TEST_CASE("image: geometry_stage", "[image]") {
  CompareWithGolden("geometry_stage", scenes::GeometryStage(640, 360));
}

TEST_CASE("image: environment map", "[image]") {
  CompareWithGolden("environment_map", scenes::EnvironmentMap(640, 480));
}

TEST_CASE("WritePng writes a file whole or reports failure", "[image][files]") {
  softgl::Image image;
  image.width = 3;
  image.height = 2;
  image.rgba.assign(3 * 2 * 4, 0);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * 10);
  const std::string path = std::string(SOFTGL_TEST_OUTPUT_DIR) + "/write_png_round_trip.png";
  std::filesystem::create_directories(SOFTGL_TEST_OUTPUT_DIR);
  REQUIRE(softgl::WritePng(path, image));
  softgl::Image back;
  REQUIRE(softgl::ReadImage(path, back));
  CHECK(back.width == 3);
  CHECK(back.height == 2);
  CHECK(back.rgba == image.rgba);
  // No such directory, an empty image, and a device where every write fails (Linux's /dev/full): false.
  CHECK_FALSE(softgl::WritePng(std::string(SOFTGL_TEST_OUTPUT_DIR) + "/no-such-dir/x.png", image));
  CHECK_FALSE(softgl::WritePng(path, softgl::Image{}));
  if (std::filesystem::exists("/dev/full")) {
    CHECK_FALSE(softgl::WritePng("/dev/full", image));
    CHECK(std::filesystem::is_character_file("/dev/full"));  // a device is never removed
  }
}

// The pictures of docs/tour.md, at the sizes examples/tour.cpp draws them.
TEST_CASE("image: tour", "[image]") {
  CompareWithGolden("tour_clipping", scenes::TourClipping(640, 320));
  CompareWithGolden("tour_coverage", scenes::TourCoverage(640, 320));
  CompareWithGolden("tour_viewport", scenes::TourViewport(640, 320));
  CompareWithGolden("tour_barycentric", scenes::TourBarycentric(640, 320));
  CompareWithGolden("tour_depth", scenes::TourDepth(960, 320));
  CompareWithGolden("tour_perspective", scenes::TourPerspective(640, 320));
  CompareWithGolden("tour_culling", scenes::TourCulling(640, 320));
  CompareWithGolden("tour_tiles", scenes::TourTiles(640, 384));
  CompareWithGolden("tour_mipmaps", scenes::TourMipmapLevels(960, 320));
  CompareWithGolden("tour_lines", scenes::TourLines(640, 320));
  CompareWithGolden("tour_multisample", scenes::TourMultisample(640, 320));
}

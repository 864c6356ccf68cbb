// Models: loading each supported format from Debian's assimp-testmodels (counts, materials, hierarchy, textures),
// errors for bad files, the camera helper, and one golden image per built-in shader.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <fstream>
#include <string>
#include <vector>

#include <softgl/model.h>
#include <softgl/shaders.h>

#include "scenes.h"

// Whether AddressSanitizer is on: GCC says so with __SANITIZE_ADDRESS__, Clang (before 15) only through __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define SOFTGL_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SOFTGL_TEST_ASAN 1
#endif
#endif
#ifndef SOFTGL_TEST_ASAN
#define SOFTGL_TEST_ASAN 0
#endif

using namespace softgl;

namespace {

std::string TestModel(const std::string& relative) { return std::string(scenes::kTestModels) + "/" + relative; }

int CountTextures(const Model& m) {
  int n = 0;
  for (const Material& mat : m.materials)
    n += (mat.base_color_texture != 0) + (mat.normal_texture != 0) + (mat.specular_texture != 0);
  return n;
}

}  // namespace

TEST_CASE("every supported format loads from assimp-testmodels", "[model]") {
  struct Row {
    const char* file;
    int triangles;  // drawn, instances counted
    int min_meshes;
  };
  const Row rows[] = {
      {"OBJ/spider.obj", 1368, 19},                                      // OBJ + MTL
      {"glTF2/BoxTextured-glTF/BoxTextured.gltf", 12, 1},               // glTF 2.0, external image
      {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", 12, 1},      // glTF 2.0, data-URI image
      {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", 12, 1},         // GLB, image in the binary chunk
      {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496, 34},  // node hierarchy and instancing
      {"FBX/box.fbx", 12, 1},
      {"Collada/duck.dae", 4212, 1},
      {"PLY/cube.ply", 12, 1},
      {"STL/Spider_binary.stl", 1368, 1},
      {"3DS/cube_with_diffuse_texture.3DS", 12, 1},
  };
  for (const Row& r : rows) {
    INFO(r.file);
    Context gl(4, 4);
    Model model;
    std::string error;
    REQUIRE(model.Load(gl, TestModel(r.file), &error));
    CHECK(model.triangles_drawn == r.triangles);
    CHECK(int(model.meshes.size()) >= r.min_meshes);
    CHECK(!model.materials.empty());
    CHECK(!model.nodes.empty());
    CHECK(model.bounds.Radius() > 0.0f);
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("materials, textures and the node hierarchy come through", "[model]") {
  Context gl(4, 4);
  Model engine;
  REQUIRE(engine.Load(gl, TestModel("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb")));
  CHECK(engine.nodes.size() > 10);
  CHECK(engine.nodes[0].children.size() > 0);
  int instanced = 0;  // the engine draws some meshes from several nodes
  for (const ModelMesh& m : engine.meshes) instanced += m.index_count / 3;
  CHECK(engine.triangles_drawn > instanced);
  bool pbr = false;
  for (const Material& m : engine.materials) pbr = pbr || m.pbr;
  CHECK(pbr);

  Model duck;
  REQUIRE(duck.Load(gl, TestModel("Collada/duck.dae")));
  CHECK(CountTextures(duck) == 1);
  const std::uint32_t tex = duck.materials[std::size_t(duck.meshes[0].material)].base_color_texture;
  CHECK(gl.IsTexture(tex));

  Model glb;
  REQUIRE(glb.Load(gl, TestModel("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb")));
  CHECK(glb.textures_loaded == 1);  // embedded in the .glb
  CHECK(glb.warnings.empty());

  Model spider;
  REQUIRE(spider.Load(gl, TestModel("OBJ/spider.obj")));
  CHECK(spider.textures_loaded >= 4);
  CHECK(spider.materials.size() >= 5);
}

TEST_CASE("bad model files give a clear error", "[model][errors]") {
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  Context gl(4, 4);
  Model model;
  std::string error;
  CHECK_FALSE(model.Load(gl, (dir / "missing.obj").string(), &error));
  CHECK(error.find("no such file") != std::string::npos);
  {
    std::ofstream f(dir / "garbage.glb", std::ios::binary);
    f << "glTF\x02\x00\x00\x00 not really a binary glTF file at all";
  }
  CHECK_FALSE(model.Load(gl, (dir / "garbage.glb").string(), &error));
  CHECK(error.find("garbage.glb") != std::string::npos);
  {
    std::ofstream f(dir / "random.xyz", std::ios::binary);
    for (int i = 0; i < 4096; ++i) f.put(char((i * 2654435761u) >> 13));
  }
  CHECK_FALSE(model.Load(gl, (dir / "random.xyz").string(), &error));
  {  // nothing to draw at all
    std::ofstream f(dir / "empty.obj");
    f << "# no vertices, no faces\no nothing\n";
  }
  CHECK_FALSE(model.Load(gl, (dir / "empty.obj").string(), &error));
  CHECK(error.find("empty.obj") != std::string::npos);
  CHECK_FALSE(model.Load(gl, dir.string(), &error));  // a folder
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("a PLY header that never ends is refused, not handed to the importer", "[model][errors]") {
  // assimp 5.2.5 does not return from such a file (fuzz_model's finding); with its end_header the same file loads.
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  Context gl(4, 4);
  Model model;
  std::string error;
  {
    std::ofstream f(dir / "unterminated.ply", std::ios::binary);
    f << header << "e[nd_header\n" << body;
  }
  CHECK_FALSE(model.Load(gl, (dir / "unterminated.ply").string(), &error));
  CHECK(error.find("end_header") != std::string::npos);
  {  // the word not on a line of its own: assimp does not take it either
    std::ofstream f(dir / "not_a_word.ply", std::ios::binary);
    f << header << "end_header*0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  }
  CHECK_FALSE(model.Load(gl, (dir / "not_a_word.ply").string(), &error));
  CHECK(error.find("end_header") != std::string::npos);
  {  // Windows line ends, spaces before the word
    std::ofstream f(dir / "terminated.ply", std::ios::binary);
    f << header << "  end_header\r\n" << body;
  }
  CHECK(model.Load(gl, (dir / "terminated.ply").string(), &error));
  {  // the word cut between two of the pieces the check reads (64 KiB each): still found
    std::ofstream f(dir / "long_header.ply", std::ios::binary);
    std::string text = header;
    while (text.size() < 65536 - 5) text += "comment padding padding padding\n";
    text.resize(65536 - 5);
    text += "\nend_header\n" + body;
    f << text;
  }
  const bool loaded = model.Load(gl, (dir / "long_header.ply").string(), &error);
  INFO(error);
  CHECK(loaded);
}

TEST_CASE("the camera frames a bounding box", "[model]") {
  Bounds b;
  b.min = glm::vec3(-1, -2, -3);
  b.max = glm::vec3(3, 2, 1);
  const Camera c = Camera::Frame(b, 1.0f, 0.0f, 0.0f, 60.0f);
  CHECK(c.target == b.Center());
  // On the +z axis at azimuth 0, elevation 0, far enough for the bounding sphere to fit the 60 degree view.
  CHECK(c.eye.x == Approx(b.Center().x));
  CHECK(c.eye.z - c.target.z >= b.Radius() / std::sin(glm::radians(30.0f)));
  CHECK(c.near_plane > 0.0f);
  CHECK(c.far_plane > glm::length(c.eye - c.target) + b.Radius());
  const Camera o = Camera::Orbit(glm::vec3(0), 2.0f, 90.0f, 0.0f);
  CHECK(o.eye.x == Approx(2.0f));
  CHECK(o.eye.z == Approx(0.0f).margin(1e-6));
}

namespace {

// Golden images of models, as the image tests do for scenes: every channel within 1.
void CheckGolden(const std::string& name, const softgl::Image& actual) {
  const std::string path = std::string(SOFTGL_GOLDEN_DIR) + "/" + name + ".png";
  if (const char* update = std::getenv("SOFTGL_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    REQUIRE(softgl::WritePng(path, actual));
    return;
  }
  softgl::Image golden;
  REQUIRE(softgl::ReadImage(path, golden));
  REQUIRE(golden.width == actual.width);
  REQUIRE(golden.height == actual.height);
  int over = 0;
  for (std::size_t i = 0; i < golden.rgba.size(); ++i) over += std::abs(int(golden.rgba[i]) - int(actual.rgba[i])) > 1;
  if (over) {
    std::filesystem::create_directories(SOFTGL_TEST_OUTPUT_DIR);
    softgl::WritePng(std::string(SOFTGL_TEST_OUTPUT_DIR) + "/" + name + "_actual.png", actual);
  }
  CHECK(over == 0);
}

}  // namespace

TEST_CASE("image: a model per built-in shader", "[model][image]") {
  CheckGolden("model_spider_unlit", scenes::ModelView(TestModel("OBJ/spider.obj"), "unlit", 320, 240, 40, 30));
  CheckGolden("model_duck_phong", scenes::ModelView(TestModel("Collada/duck.dae"), "phong", 320, 240, 30, 20));
  CheckGolden("model_box_pbr",
              scenes::ModelView(TestModel("glTF2/BoxTextured-glTF/BoxTextured.gltf"), "pbr", 320, 240, 35, 25));
}

TEST_CASE("image: a point cloud file and a wireframe-only file", "[model][image]") {
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  const std::string cloud = (dir / "galaxy_points.ply").string(), knot = (dir / "torus_knot_lines.obj").string();
  REQUIRE(scenes::WritePointCloudPly(cloud));
  REQUIRE(scenes::WriteTorusKnotObj(knot));
  std::string error;
  const Image points = scenes::ModelView(cloud, "phong", 320, 240, 20, 35, &error, 2.0f);
  INFO(error);
  REQUIRE(!points.rgba.empty());
  CheckGolden("model_point_cloud", points);
  const Image lines = scenes::ModelView(knot, "phong", 320, 240, 0, 60, &error, 1.0f);
  REQUIRE(!lines.rgba.empty());
  CheckGolden("model_wireframe_lines", lines);
}

TEST_CASE("point and line meshes are kept and drawn, unlit", "[model]") {
  // An OBJ point cloud of vertices alone (no point elements: assimp's validation refuses it, the second reading
  // takes it), and an OBJ with a point element and a polyline.
  Context gl(64, 64);
  Model model;
  std::string error;
  REQUIRE(model.Load(gl, TestModel("OBJ/point_cloud.obj"), &error));
  REQUIRE(model.meshes.size() == 1);
  CHECK(model.meshes[0].mode == POINTS);
  CHECK(model.meshes[0].index_count == 3);
  CHECK_FALSE(model.meshes[0].has_normals);
  CHECK(model.points_drawn == 3);
  CHECK(model.triangles_drawn == 0);
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "lines_and_points.obj");
    f << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nl 1 2 3 4 1\np 3\n";
  }
  REQUIRE(model.Load(gl, (dir / "lines_and_points.obj").string(), &error));
  CHECK(model.lines_drawn == 4);
  CHECK(model.points_drawn == 1);
  // Drawn with the Phong shader: no normals, so the material's colour as it is (assimp's default grey, 0.6).
  PhongShader phong;
  const Camera cam = Camera::Frame(model.bounds, 1.0f, 0.0f, 0.0f);
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.PointSize(5.0f);
  model.Draw(gl, phong, cam.Projection(1.0f) * cam.View());
  const Image img = gl.ReadPixels();
  int lit = 0, grey = 0;
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    lit += img.rgba[i] > 0;
    grey += img.rgba[i] == 153 && img.rgba[i + 1] == 153 && img.rgba[i + 2] == 153;
  }
  CHECK(lit > 100);      // four edges of a square framed in 64 x 64, and a point
  CHECK(grey == lit);    // every pixel the material's colour, unlit
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("Release deletes what Load made, and CanRead goes by the extension", "[model]") {
  Context gl(32, 32);
  Model model;
  std::string error;
  REQUIRE(model.Load(gl, TestModel("glTF2/BoxTextured-glTF/BoxTextured.gltf"), &error));
  REQUIRE(!model.meshes.empty());
  const ModelMesh mesh = model.meshes[0];
  const std::uint32_t texture = model.materials[std::size_t(mesh.material)].base_color_texture;
  REQUIRE(texture != 0);
  CHECK(gl.IsVertexArray(mesh.vertex_array));
  CHECK(gl.IsBuffer(mesh.vertex_buffer));
  CHECK(gl.IsBuffer(mesh.index_buffer));
  CHECK(gl.IsTexture(texture));
  model.Release(gl);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK_FALSE(gl.IsVertexArray(mesh.vertex_array));
  CHECK_FALSE(gl.IsBuffer(mesh.vertex_buffer));
  CHECK_FALSE(gl.IsBuffer(mesh.index_buffer));
  CHECK_FALSE(gl.IsTexture(texture));
  CHECK(model.meshes.empty());
  CHECK(model.materials.empty());
  // Loaded again into the same context after the release: the same drawing.
  REQUIRE(model.Load(gl, TestModel("glTF2/BoxTextured-glTF/BoxTextured.gltf"), &error));
  CHECK(model.triangles_drawn == 12);

  CHECK(Model::CanRead("duck.dae"));
  CHECK(Model::CanRead("dir/Model.GLB"));
  CHECK(Model::CanRead("x.obj"));
  CHECK_FALSE(Model::CanRead("notes.txt"));
  CHECK_FALSE(Model::CanRead("README"));
  CHECK_FALSE(Model::CanRead("dir.obj/"));
}

TEST_CASE("sRGB transfer functions and the tone curves", "[model][shader]") {
  const float inputs[] = {0.0f, 0.002f, 0.0031308f, 0.04045f, 0.1f, 0.5f, 0.8f, 1.0f};
  for (float x : inputs) {
    // The formulas of IEC 61966-2-1, in double.
    const double to_linear = x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
    const double to_srgb = x <= 0.0031308 ? x * 12.92 : 1.055 * std::pow(double(x), 1.0 / 2.4) - 0.055;
    CHECK(SrgbToLinear(Float(x))[0] == Approx(to_linear).margin(1e-6));
    CHECK(LinearToSrgb(Float(x))[0] == Approx(to_srgb).margin(1e-6));
    CHECK(LinearToSrgb(SrgbToLinear(Float(x)))[0] == Approx(x).margin(1e-5));
  }
  auto neutral = [](glm::vec3 c) {
    const vec3 m = ToneMapPbrNeutral(vec3(c));
    return glm::vec3(m.x[0], m.y[0], m.z[0]);
  };
  auto aces = [](glm::vec3 c) {
    const vec3 m = ToneMapAces(vec3(c));
    return glm::vec3(m.x[0], m.y[0], m.z[0]);
  };
  // PBR Neutral: below the compression start only the small offset (0.04 where the smallest channel >= 0.08).
  const glm::vec3 mid = neutral({0.5f, 0.3f, 0.2f});
  CHECK(mid.x == Approx(0.46f));
  CHECK(mid.y == Approx(0.26f));
  CHECK(mid.z == Approx(0.16f));
  CHECK(neutral({0.0f, 0.0f, 0.0f}) == glm::vec3(0.0f));
  // Highlights roll off below 1, in order, and bright colours lose saturation.
  float last = 0.0f;
  for (float v : {0.9f, 1.0f, 2.0f, 4.0f, 16.0f, 1000.0f}) {
    const float y = neutral(glm::vec3(v)).x;
    CHECK(y > last);
    CHECK(y <= 1.0f);
    last = y;
  }
  const glm::vec3 hot = neutral({8.0f, 2.0f, 1.0f});
  CHECK(hot.x <= 1.0f);
  CHECK(hot.z / hot.x > 1.0f / 8.0f);
  // ACES fit: 0 at 0, 2.54 / 3.16 at 1, 1 for very bright colours.
  CHECK(aces(glm::vec3(0.0f)).x == Approx(0.0f).margin(1e-7));
  CHECK(aces(glm::vec3(1.0f)).x == Approx(2.54f / 3.16f));
  CHECK(aces(glm::vec3(1e4f)).x == Approx(1.0f).margin(1e-3));
}

TEST_CASE("imports within limits: a time limit and a memory budget stop the import, a crash-free file loads", "[model]") {
  Context gl(32, 32);
  const std::string engine = TestModel("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  Model plain, limited;
  std::string error;
  REQUIRE(plain.Load(gl, engine, &error));
  LoadOptions generous;
  generous.timeout_seconds = 120.0;
  generous.memory_budget = std::size_t(8) << 30;
  REQUIRE(limited.Load(gl, engine, generous, &error));
  CHECK(limited.triangles_drawn == plain.triangles_drawn);
  CHECK(limited.meshes.size() == plain.meshes.size());

  // The engine's import (121,496 triangles) takes far more than a microsecond and a megabyte.
  LoadOptions quick;
  quick.timeout_seconds = 1e-6;
  CHECK_FALSE(limited.Load(gl, engine, quick, &error));
  CHECK(error.find("time limit of 1e-06 s") != std::string::npos);
  CHECK(limited.meshes.empty());
#if !SOFTGL_TEST_ASAN  // AddressSanitizer's allocator takes its memory beyond any budget
  LoadOptions small;
  small.memory_budget = std::size_t(1) << 20;
  CHECK_FALSE(limited.Load(gl, engine, small, &error));
  CHECK(error.find("memory budget of 1 MiB") != std::string::npos);
#endif
  // A file assimp refuses is refused with its own reason, limits or not.
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "broken.glb") << "glTF this is not a binary glTF file"; }
  CHECK_FALSE(limited.Load(gl, (dir / "broken.glb").string(), generous, &error));
  CHECK(error.find("cannot read") != std::string::npos);
}

TEST_CASE("a memory budget holds in a process that has freed much memory", "[model]") {
#if defined(__linux__) && !SOFTGL_TEST_ASAN
  // 256 MiB in blocks below the allocator's mapping threshold, freed behind a block that stays: the heap keeps
  // them, reserved address space an import could reuse without adding any.
  std::vector<std::unique_ptr<char[]>> blocks;
  for (int i = 0; i < 4096; ++i) {
    blocks.emplace_back(new char[64 * 1024]);
    std::memset(blocks.back().get(), 1, 64 * 1024);
  }
  const std::unique_ptr<char[]> pin(new char[64]);
  blocks.clear();
  Context gl(32, 32);
  Model model;
  std::string error;
  LoadOptions small;
  small.memory_budget = std::size_t(1) << 20;
  CHECK_FALSE(model.Load(gl, TestModel("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"), small, &error));
  CHECK(error.find("memory budget of 1 MiB") != std::string::npos);
#endif
}

namespace {

// A Radiance HDR file of flat RGBE pixels, w x h, from `radiance(x, y)` (rows from the top).
template <class Radiance>
void WriteHdr(const std::string& path, int w, int h, Radiance radiance) {
  std::ofstream f(path, std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = radiance(x, y);  // grey
      int e = 0;
      const float m = std::frexp(v, &e);  // v = m 2^e, m in [0.5, 1)
      const unsigned char mantissa = v > 0.0f ? static_cast<unsigned char>(m * 256.0f) : 0;
      const unsigned char exponent = v > 0.0f ? static_cast<unsigned char>(e + 128) : 0;
      f << mantissa << mantissa << mantissa << exponent;
    }
}

// The texel at the centre of a cube map face on `unit`.
glm::vec4 FaceCentre(Context& gl, int unit, Enum face, int level = 0) {
  gl.ActiveTexture(TEXTURE0 + Enum(unit));
  int size = 0;
  gl.GetTexLevelParameteriv(face, level, TEXTURE_WIDTH, &size);
  std::vector<float> texels(std::size_t(size) * std::size_t(size) * 4);
  gl.GetTexImage(face, level, RGBA, FLOAT, texels.data());
  gl.ActiveTexture(TEXTURE0);
  const std::size_t centre = (std::size_t(size / 2) * std::size_t(size) + std::size_t(size / 2)) * 4;
  return {texels[centre], texels[centre + 1], texels[centre + 2], texels[centre + 3]};
}

}  // namespace

TEST_CASE("an HDR environment: radiance cube map and diffuse irradiance", "[model]") {
  const std::filesystem::path dir = std::filesystem::path(SOFTGL_TEST_OUTPUT_DIR) / "models";
  std::filesystem::create_directories(dir);
  Context gl(8, 8);
  std::string error;
  // Uniform radiance 0.5: the cube map holds 0.5, and the irradiance (1/pi of the cosine-weighted integral over
  // a hemisphere) is 0.5 too, within the coarse sum's error.
  const std::string uniform = (dir / "uniform.hdr").string();
  WriteHdr(uniform, 64, 32, [](int, int) { return 0.5f; });
  const float levels = LoadEnvironment(gl, uniform, 32, &error);
  INFO(error);
  CHECK(levels == 6.0f);  // 32, 16, 8, 4, 2, 1
  for (Enum face = TEXTURE_CUBE_MAP_POSITIVE_X; face <= TEXTURE_CUBE_MAP_NEGATIVE_Z; ++face) {
    for (int level = 0; level < 6; ++level)  // the prefiltered levels are weighted means: 0.5 too
      CHECK(FaceCentre(gl, kUnitEnvironment, face, level).x == Approx(0.5f).epsilon(1e-4));
    CHECK(FaceCentre(gl, kUnitIrradiance, face).x == Approx(0.5f).epsilon(0.03));
  }
  // Light from above only (the top half of the panorama, radiance 1): the irradiance for a normal n is then
  // (1 + n.y) / 2: 1 straight up, 0 straight down. The texel read on the +x face lies half a texel (of 16) below
  // the horizon, n.y = -0.0625 / |(1, 0.0625, 0.0625)|.
  const std::string sky = (dir / "sky_above.hdr").string();
  WriteHdr(sky, 256, 128, [](int, int y) { return y < 64 ? 1.0f : 0.0f; });
  REQUIRE(LoadEnvironment(gl, sky, 32, &error) > 0.0f);
  CHECK(FaceCentre(gl, kUnitIrradiance, TEXTURE_CUBE_MAP_POSITIVE_Y).x == Approx(1.0f).epsilon(0.03));
  CHECK(FaceCentre(gl, kUnitIrradiance, TEXTURE_CUBE_MAP_NEGATIVE_Y).x == Approx(0.0f).margin(0.01));
  const float side_y = -0.0625f / std::sqrt(1.0f + 2.0f * 0.0625f * 0.0625f);
  CHECK(FaceCentre(gl, kUnitIrradiance, TEXTURE_CUBE_MAP_POSITIVE_X).x == Approx((1.0f + side_y) / 2.0f).epsilon(0.02));
  CHECK(FaceCentre(gl, kUnitEnvironment, TEXTURE_CUBE_MAP_POSITIVE_Y).x == Approx(1.0f));
  CHECK(FaceCentre(gl, kUnitEnvironment, TEXTURE_CUBE_MAP_NEGATIVE_Y).x == Approx(0.0f));
  // A direction just below the horizon (the texel right of and below the +x face's centre) sees no sky as a
  // mirror (level 0), and some of it once prefiltered for roughness (levels 1 to 5, roughness 0.2 to 1), less
  // than half: the GGX lobe around it reaches above the horizon.
  CHECK(FaceCentre(gl, kUnitEnvironment, TEXTURE_CUBE_MAP_POSITIVE_X, 0).x == 0.0f);
  for (int level = 1; level < 6; ++level) {
    INFO("level " << level);
    const float v = FaceCentre(gl, kUnitEnvironment, TEXTURE_CUBE_MAP_POSITIVE_X, level).x;
    CHECK(v > 0.0f);
    CHECK(v < 0.5f);
  }
  // A missing or corrupt file: 0 and a message.
  CHECK(LoadEnvironment(gl, (dir / "no-such.hdr").string(), 32, &error) == 0.0f);
  CHECK_FALSE(error.empty());
}

TEST_CASE("MakeShadowMap: a complete depth-only framebuffer and a comparing depth texture", "[model]") {
  Context gl(8, 8);
  const ShadowMap map = MakeShadowMap(gl, 64);
  CHECK(map.size == 64);
  CHECK(gl.IsTexture(map.texture));
  CHECK(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  int mode = 0, func = 0, wrap = 0, width = 0;
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_COMPARE_MODE, &mode);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_COMPARE_FUNC, &func);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_WRAP_S, &wrap);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_WIDTH, &width);
  CHECK(Enum(mode) == COMPARE_REF_TO_TEXTURE);
  CHECK(Enum(func) == LEQUAL);
  CHECK(Enum(wrap) == CLAMP_TO_BORDER);
  CHECK(width == 64);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("the environment's uploads and read-backs ignore the application's PixelStore settings and keep them",
          "[model]") {
  // The studio cube map made with OpenGL's default pixel layout, and again after the application set rows, skips,
  // alignment and byte swapping for its own uploads: the same texels, and the application's settings stay.
  auto face = [](Context& gl) {
    gl.ActiveTexture(TEXTURE0 + Enum(kUnitEnvironment));
    std::vector<std::uint8_t> texels(16 * 16 * 4);
    gl.GetTexImage(TEXTURE_CUBE_MAP_POSITIVE_Y, 0, RGBA, UNSIGNED_BYTE, texels.data());
    gl.ActiveTexture(TEXTURE0);
    return texels;
  };
  Context plain(4, 4);
  MakeStudioEnvironment(plain, 16);
  Context set(4, 4);
  set.PixelStore(UNPACK_ROW_LENGTH, 7);
  set.PixelStore(UNPACK_SKIP_ROWS, 2);
  set.PixelStore(UNPACK_ALIGNMENT, 8);
  set.PixelStore(UNPACK_SWAP_BYTES, 1);
  MakeStudioEnvironment(set, 16);
  int row_length = 0, skip_rows = 0, alignment = 0, swap = 0;
  set.GetIntegerv(UNPACK_ROW_LENGTH, &row_length);
  set.GetIntegerv(UNPACK_SKIP_ROWS, &skip_rows);
  set.GetIntegerv(UNPACK_ALIGNMENT, &alignment);
  set.GetIntegerv(UNPACK_SWAP_BYTES, &swap);
  CHECK((row_length == 7 && skip_rows == 2 && alignment == 8 && swap == 1));
  for (const Enum p : {UNPACK_ROW_LENGTH, UNPACK_SKIP_ROWS, UNPACK_ALIGNMENT, UNPACK_SWAP_BYTES})
    set.PixelStore(p, p == UNPACK_ALIGNMENT ? 4 : 0);
  CHECK(face(set) == face(plain));
  CHECK(set.GetError() == NO_ERROR);
}

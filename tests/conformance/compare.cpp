// compare.cpp — runs every scene through softgl and Mesa and compares the framebuffers.
//
// As a Catch2 test (the default), each scene is a test case that must meet its Check. With --report, it prints
// one markdown table row per scene instead (used for docs/conformance.md).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include <softgl/image.h>

#include "scenes.h"

namespace conformance {
namespace {

struct Verdict {
  int differing = 0;    // pixels whose colour differs at all
  int max_diff = 0;     // largest channel difference
  int over = 0;         // pixels beyond the scene's colour tolerance
  int depth_over = 0;   // pixels whose depth differs by more than the 24-bit resolution
  int stencil_diff = 0;
  int coverage_diff = 0;  // pixels drawn by one and not the other (kCoverage scenes)
  int allowed_over = 0;   // pixels that may exceed the tolerance (kTexture: 0.5%)
  bool Pass() const { return over <= allowed_over && depth_over == 0 && stencil_diff == 0 && coverage_diff == 0; }
};

softgl::Image ToImage(const Frame& f, bool diff_of = false, const Frame* other = nullptr) {
  softgl::Image img;
  img.width = f.width;
  img.height = f.height;
  img.rgba.resize(f.rgba.size());
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::size_t src = (std::size_t(y) * f.width + x) * 4, dst = (std::size_t(f.height - 1 - y) * f.width + x) * 4;
      for (int c = 0; c < 4; ++c) {
        int v = f.rgba[src + c];
        if (diff_of) v = c == 3 ? 255 : std::min(255, 64 * std::abs(v - int(other->rgba[src + c])));
        img.rgba[dst + c] = std::uint8_t(v);
      }
    }
  return img;
}

Verdict Compare(const SceneInfo& s, const Frame& a, const Frame& b) {
  Verdict v;
  const int tolerance = Tolerance(s.check);
  if (s.check == Check::kTexture) v.allowed_over = int(a.depth.size() / 200);
  for (std::size_t i = 0; i < a.depth.size(); ++i) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c])));
    v.differing += d > 0;
    v.over += d > tolerance;
    v.max_diff = std::max(v.max_diff, d);
    const bool depth = s.check == Check::kExactWithDepth || s.check == Check::kExactWithDepthStencil;
    const bool stencil = s.check == Check::kExactWithStencil || s.check == Check::kExactWithDepthStencil;
    if (depth && std::fabs(a.depth[i] - b.depth[i]) > std::ldexp(1.0f, -22)) ++v.depth_over;
    if (stencil && a.stencil[i] != b.stencil[i]) ++v.stencil_diff;
    if (s.check == Check::kCoverage) {
      const bool drawn_a = a.rgba[i * 4] | a.rgba[i * 4 + 1] | a.rgba[i * 4 + 2];
      const bool drawn_b = b.rgba[i * 4] | b.rgba[i * 4 + 1] | b.rgba[i * 4 + 2];
      v.coverage_diff += drawn_a != drawn_b;
    }
  }
  return v;
}

const char* CheckName(Check c) {
  switch (c) {
    case Check::kExact: return "identical";
    case Check::kExactWithDepth: return "identical, depth";
    case Check::kExactWithStencil: return "identical, stencil";
    case Check::kExactWithDepthStencil: return "identical, depth, stencil";
    case Check::kCoverage: return "coverage";
    case Check::kTexture: return "+-1 on 99.5%";
    case Check::kStep4: return "+-17 (a 4-bit step)";
    default: return "+-1";
  }
}

bool RunScene(const SceneInfo& s, Frame& ours, Frame& mesa, std::string& renderer, std::string& error) {
  auto gl = MakeGlBackend(s.width, s.height, &error);
  if (!gl) return false;
  renderer = gl->Name();
  s.run(*gl);
  mesa = gl->Read();
  auto sg = MakeSoftglBackend(s.width, s.height);
  s.run(*sg);
  ours = sg->Read();
  return true;
}

}  // namespace
}  // namespace conformance

using namespace conformance;

TEST_CASE("conformance scenes match Mesa", "[conformance]") {
  for (const SceneInfo& s : Scenes()) {
    SECTION(s.name) {
      Frame ours, mesa;
      std::string renderer, error;
      REQUIRE(RunScene(s, ours, mesa, renderer, error));
      const Verdict v = Compare(s, ours, mesa);
      INFO(s.name << " against " << renderer << " (" << CheckName(s.check) << "): " << v.differing
                  << " differing pixels, largest channel difference " << v.max_diff << ", over tolerance " << v.over
                  << ", depth beyond resolution " << v.depth_over << ", stencil differing " << v.stencil_diff
                  << ", coverage differing " << v.coverage_diff);
      if (!v.Pass() || std::getenv("SOFTGL_CONFORMANCE_WRITE")) {  // the images of failures, or of every scene
        const std::string dir = SOFTGL_TEST_OUTPUT_DIR "/conformance";
        std::filesystem::create_directories(dir);
        softgl::WritePng(dir + "/" + s.name + "_softgl.png", ToImage(ours));
        softgl::WritePng(dir + "/" + s.name + "_mesa.png", ToImage(mesa));
        softgl::WritePng(dir + "/" + s.name + "_diff.png", ToImage(ours, true, &mesa));
      }
      CHECK(v.Pass());
    }
  }
}

namespace conformance {
namespace {

// Bytes a ReadPixels of `r` may touch, and how to compare two results: component size and tolerance.
std::size_t ReadBytes(const PixelRead& r, std::size_t component, int per_pixel) {
  const std::size_t pixel = component * std::size_t(per_pixel);
  std::size_t stride = std::size_t(r.row_length > 0 ? r.row_length : r.width) * pixel;
  if (component < std::size_t(r.alignment)) stride = (stride + r.alignment - 1) / r.alignment * r.alignment;
  return (std::size_t(r.skip_rows) + std::size_t(r.height)) * stride + std::size_t(r.skip_pixels) * pixel;
}

}  // namespace
}  // namespace conformance

TEST_CASE("ReadPixels formats, types and pack layouts match Mesa", "[conformance]") {
  using softgl::Enum;
  struct Read {
    const char* scene;
    PixelRead r;
    int per_pixel;
    double tolerance;  // per component, in its own units
  };
  namespace gl = softgl;
  const Read reads[] = {
      {"stencil", {0, 0, 128, 128, gl::RGBA, gl::UNSIGNED_BYTE, 1}, 4, 0},
      {"stencil", {-5, 120, 7, 16, gl::RGB, gl::UNSIGNED_BYTE, 4}, 3, 0},  // partly outside, rows padded
      {"stencil", {30, 40, 9, 5, gl::BGRA, gl::UNSIGNED_BYTE, 4, 40, 2, 3}, 4, 0},
      {"stencil", {10, 10, 33, 9, gl::BGR, gl::UNSIGNED_BYTE, 8}, 3, 0},
      {"stencil", {0, 0, 128, 128, gl::RED, gl::FLOAT, 4}, 1, 1e-6},
      {"stencil", {60, 70, 20, 20, gl::RG, gl::UNSIGNED_SHORT, 8}, 2, 0},
      {"stencil", {100, 100, 40, 40, gl::GREEN, gl::UNSIGNED_BYTE, 2}, 1, 0},
      {"stencil", {0, 0, 128, 128, gl::STENCIL_INDEX, gl::UNSIGNED_BYTE, 1}, 1, 0},
      {"stencil", {0, 0, 128, 128, gl::STENCIL_INDEX, gl::FLOAT, 4}, 1, 0},
      {"stencil", {20, -3, 50, 50, gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8, 4}, 1, 3 * 256},
      {"depth_functions", {0, 0, 128, 128, gl::DEPTH_COMPONENT, gl::FLOAT, 4}, 1, 1.0 / (1 << 22)},
      {"depth_functions", {5, 5, 100, 30, gl::DEPTH_COMPONENT, gl::UNSIGNED_SHORT, 2, 0, 1, 1}, 1, 1},
      {"depth_functions", {0, 64, 128, 10, gl::DEPTH_COMPONENT, gl::UNSIGNED_BYTE, 1}, 1, 1},
      {"depth_functions", {0, 0, 128, 128, gl::DEPTH_STENCIL, gl::UNSIGNED_INT_24_8, 4}, 1, 3 * 256},
  };
  for (const Read& read : reads) {
    const PixelRead& r = read.r;
    INFO(read.scene << ": format " << r.format << " type " << r.type << " at (" << r.x << ", " << r.y << ") "
                    << r.width << " x " << r.height << ", alignment " << r.alignment << ", row length "
                    << r.row_length);
    const SceneInfo* scene = nullptr;
    for (const SceneInfo& s : Scenes())
      if (std::string(s.name) == read.scene) scene = &s;
    REQUIRE(scene != nullptr);
    std::string error;
    auto mesa = MakeGlBackend(scene->width, scene->height, &error);
    REQUIRE(mesa);
    auto ours = MakeSoftglBackend(scene->width, scene->height);
    scene->run(*mesa);
    scene->run(*ours);
    const std::size_t component = r.type == gl::UNSIGNED_BYTE ? 1 : r.type == gl::UNSIGNED_SHORT ? 2 : 4;
    const std::size_t bytes = ReadBytes(r, component, read.per_pixel);
    const std::vector<std::uint8_t> a = ours->ReadPixels(r, bytes), b = mesa->ReadPixels(r, bytes);
    int over = 0, untouched_a = 0, untouched_b = 0;
    double worst = 0;
    for (std::size_t i = 0; i + component <= bytes; i += component) {
      double va = 0, vb = 0;
      if (r.type == gl::FLOAT) {
        float fa, fb;
        std::memcpy(&fa, &a[i], 4);
        std::memcpy(&fb, &b[i], 4);
        va = fa, vb = fb;
      } else {
        std::uint32_t ua = 0, ub = 0;
        std::memcpy(&ua, &a[i], component);
        std::memcpy(&ub, &b[i], component);
        va = ua, vb = ub;
        if (r.type == gl::UNSIGNED_INT_24_8 && (ua & 0xFF) != (ub & 0xFF)) ++over;  // stencil exact
      }
      const double d = std::fabs(va - vb);
      worst = std::max(worst, d);
      over += d > read.tolerance;
      untouched_a += a[i] == 0xCD && a[i + component - 1] == 0xCD;
      untouched_b += b[i] == 0xCD && b[i + component - 1] == 0xCD;
    }
    INFO("largest difference " << worst << ", components untouched " << untouched_a << " (softgl) and "
                               << untouched_b << " (Mesa)");
    CHECK(over == 0);
    CHECK(untouched_a == untouched_b);
  }
}

TEST_CASE("state queries return what Mesa returns, at the defaults and after changes", "[conformance]") {
  namespace gl = softgl;
  // Every state name whose value OpenGL defines (the implementation's limits differ by design and are left out),
  // with its value count.
  const std::pair<Enum, int> names[] = {
      {gl::VIEWPORT, 4}, {gl::SCISSOR_BOX, 4}, {gl::DEPTH_RANGE, 2}, {gl::CULL_FACE_MODE, 1}, {gl::FRONT_FACE, 1},
      {gl::POLYGON_MODE, 2}, {gl::POINT_SIZE, 1}, {gl::PROVOKING_VERTEX, 1}, {gl::POLYGON_OFFSET_FACTOR, 1},
      {gl::POLYGON_OFFSET_UNITS, 1}, {gl::PRIMITIVE_RESTART_INDEX, 1}, {gl::DEPTH_FUNC, 1},
      {gl::DEPTH_WRITEMASK, 1}, {gl::DEPTH_CLEAR_VALUE, 1}, {gl::STENCIL_FUNC, 1}, {gl::STENCIL_REF, 1},
      {gl::STENCIL_VALUE_MASK, 1}, {gl::STENCIL_FAIL, 1}, {gl::STENCIL_PASS_DEPTH_FAIL, 1},
      {gl::STENCIL_PASS_DEPTH_PASS, 1}, {gl::STENCIL_WRITEMASK, 1}, {gl::STENCIL_BACK_FUNC, 1},
      {gl::STENCIL_BACK_REF, 1}, {gl::STENCIL_BACK_VALUE_MASK, 1}, {gl::STENCIL_BACK_FAIL, 1},
      {gl::STENCIL_BACK_PASS_DEPTH_FAIL, 1}, {gl::STENCIL_BACK_PASS_DEPTH_PASS, 1}, {gl::STENCIL_BACK_WRITEMASK, 1},
      {gl::STENCIL_CLEAR_VALUE, 1}, {gl::BLEND_SRC_RGB, 1}, {gl::BLEND_DST_RGB, 1}, {gl::BLEND_SRC_ALPHA, 1},
      {gl::BLEND_DST_ALPHA, 1}, {gl::BLEND_EQUATION_RGB, 1}, {gl::BLEND_EQUATION_ALPHA, 1}, {gl::BLEND_COLOR, 4},
      {gl::COLOR_CLEAR_VALUE, 4}, {gl::COLOR_WRITEMASK, 4}, {gl::CULL_FACE, 1}, {gl::DEPTH_TEST, 1},
      {gl::STENCIL_TEST, 1}, {gl::SCISSOR_TEST, 1}, {gl::BLEND, 1}, {gl::POLYGON_OFFSET_FILL, 1},
      {gl::POLYGON_OFFSET_LINE, 1}, {gl::POLYGON_OFFSET_POINT, 1}, {gl::PROGRAM_POINT_SIZE, 1},
      {gl::PRIMITIVE_RESTART, 1}, {gl::PRIMITIVE_RESTART_FIXED_INDEX, 1}, {gl::COLOR_LOGIC_OP, 1},
      {gl::LOGIC_OP_MODE, 1}, {gl::LINE_WIDTH, 1}};
  auto change = [](Backend& b) {
    b.Viewport(3, 5, 70, 40);
    b.Scissor(-2, 7, 11, 13);
    b.DepthRange(0.25, 0.8);
    b.CullFace(gl::FRONT_AND_BACK);
    b.FrontFace(gl::CW);
    b.PolygonMode(gl::LINE);
    b.PointSize(3.5f);
    b.PolygonOffset(-1.5f, 2.0f);
    b.PrimitiveRestartIndex(65535);
    b.DepthFunc(gl::GEQUAL);
    b.DepthMask(false);
    b.ClearDepth(0.3);
    b.StencilFuncSeparate(gl::FRONT, gl::NOTEQUAL, 300, 0x0F);  // the reference is kept as given, clamped on use
    b.StencilFuncSeparate(gl::BACK, gl::LESS, -4, 0xF0F0F0F0u);
    b.StencilOpSeparate(gl::FRONT, gl::INCR_WRAP, gl::INVERT, gl::REPLACE);
    b.StencilOpSeparate(gl::BACK, gl::DECR, gl::ZERO, gl::INCR);
    b.StencilMaskSeparate(gl::FRONT, 0x3C);
    b.ClearStencil(0x1234);
    b.BlendFuncSeparate(gl::SRC_ALPHA, gl::ONE_MINUS_SRC_ALPHA, gl::CONSTANT_COLOR, gl::DST_ALPHA);
    b.BlendEquationSeparate(gl::FUNC_REVERSE_SUBTRACT, gl::MAX);
    // (Colours in [-1, 1]: Mesa's integer conversion overflows beyond, where OpenGL clamps.)
    b.BlendColor(0.2f, 1.0f, -0.25f, 0.75f);
    b.ClearColor(0.1f, 0.9f, 0.0f, -1.0f);
    b.ColorMask(true, false, true, false);
    b.LogicOp(gl::NAND);
    b.LineWidth(2.75f);
    for (Enum cap : {gl::CULL_FACE, gl::DEPTH_TEST, gl::STENCIL_TEST, gl::BLEND, gl::POLYGON_OFFSET_LINE,
                     gl::PRIMITIVE_RESTART, gl::COLOR_LOGIC_OP})
      b.Enable(cap);
  };
  for (bool changed : {false, true}) {
    std::string error;
    auto mesa = MakeGlBackend(32, 32, &error);
    REQUIRE(mesa);
    auto ours = MakeSoftglBackend(32, 32);
    if (changed) {
      change(*mesa);
      change(*ours);
    }
    for (const auto& [pname, count] : names) {
      INFO((changed ? "changed" : "default") << " state 0x" << std::hex << pname);
      CHECK(ours->GetIntegers(pname, count) == mesa->GetIntegers(pname, count));
      CHECK(ours->GetFloats(pname, count) == mesa->GetFloats(pname, count));
      CHECK(ours->GetBooleans(pname, count) == mesa->GetBooleans(pname, count));
      CHECK(ours->GetError() == mesa->GetError());
    }
  }
}

TEST_CASE("sampler object and vertex attribute state read back as Mesa reads it", "[conformance]") {
  namespace gl = softgl;
  const std::pair<Enum, int> sampler_names[] = {
      {gl::TEXTURE_MIN_FILTER, 1}, {gl::TEXTURE_MAG_FILTER, 1}, {gl::TEXTURE_WRAP_S, 1}, {gl::TEXTURE_WRAP_T, 1},
      {gl::TEXTURE_WRAP_R, 1}, {gl::TEXTURE_MIN_LOD, 1}, {gl::TEXTURE_MAX_LOD, 1}, {gl::TEXTURE_LOD_BIAS, 1},
      {gl::TEXTURE_COMPARE_MODE, 1}, {gl::TEXTURE_COMPARE_FUNC, 1}, {gl::TEXTURE_BORDER_COLOR, 4},
      {gl::TEXTURE_BASE_LEVEL, 1}};  // (the last is no sampler state: INVALID_ENUM in both)
  auto change = [](Backend& b, std::uint32_t s) {
    b.SamplerParameteri(s, gl::TEXTURE_MIN_FILTER, gl::LINEAR_MIPMAP_NEAREST);
    b.SamplerParameteri(s, gl::TEXTURE_MAG_FILTER, gl::NEAREST);
    b.SamplerParameteri(s, gl::TEXTURE_WRAP_S, gl::MIRRORED_REPEAT);
    b.SamplerParameteri(s, gl::TEXTURE_WRAP_R, gl::CLAMP_TO_BORDER);
    const float lod[3] = {-2.25f, 6.5f, 1.75f}, border[4] = {0.5f, -0.25f, 1.0f, 0.125f};
    b.SamplerParameterfv(s, gl::TEXTURE_MIN_LOD, &lod[0]);
    b.SamplerParameterfv(s, gl::TEXTURE_MAX_LOD, &lod[1]);
    b.SamplerParameterfv(s, gl::TEXTURE_LOD_BIAS, &lod[2]);
    b.SamplerParameteri(s, gl::TEXTURE_COMPARE_MODE, gl::COMPARE_REF_TO_TEXTURE);
    b.SamplerParameteri(s, gl::TEXTURE_COMPARE_FUNC, gl::GEQUAL);
    b.SamplerParameterfv(s, gl::TEXTURE_BORDER_COLOR, border);
    b.SamplerParameteri(s, gl::TEXTURE_WRAP_T, gl::NEAREST);  // refused: INVALID_ENUM in both
  };
  const std::pair<Enum, int> attrib_names[] = {
      {gl::VERTEX_ATTRIB_ARRAY_ENABLED, 1}, {gl::VERTEX_ATTRIB_ARRAY_SIZE, 1}, {gl::VERTEX_ATTRIB_ARRAY_STRIDE, 1},
      {gl::VERTEX_ATTRIB_ARRAY_TYPE, 1}, {gl::VERTEX_ATTRIB_ARRAY_NORMALIZED, 1},
      {gl::VERTEX_ATTRIB_ARRAY_INTEGER, 1}, {gl::VERTEX_ATTRIB_ARRAY_DIVISOR, 1}, {gl::CURRENT_VERTEX_ATTRIB, 4}};
  std::string error;
  auto mesa = MakeGlBackend(32, 32, &error);
  REQUIRE(mesa);
  auto ours = MakeSoftglBackend(32, 32);
  const std::uint32_t s_mesa = mesa->GenSampler(), s_ours = ours->GenSampler();
  for (bool changed : {false, true}) {
    if (changed) {
      change(*mesa, s_mesa);
      change(*ours, s_ours);
      CHECK(ours->GetError() == mesa->GetError());
    }
    for (const auto& [pname, count] : sampler_names) {
      INFO((changed ? "changed" : "default") << " sampler state 0x" << std::hex << pname);
      // (The border colour as integers: softgl rounds c * (2^31 - 1), as OpenGL 4.6's equation 2.4 says, so that
      // what SamplerParameteriv set reads back as it was; Mesa truncates. The guide's Errors section says so.)
      if (pname != gl::TEXTURE_BORDER_COLOR)
        CHECK(ours->GetSamplerIntegers(s_ours, pname, count) == mesa->GetSamplerIntegers(s_mesa, pname, count));
      CHECK(ours->GetSamplerFloats(s_ours, pname, count) == mesa->GetSamplerFloats(s_mesa, pname, count));
      CHECK(ours->GetError() == mesa->GetError());
    }
  }
  for (std::uint32_t index : {0u, 2u, 5u}) {
    for (const auto& [pname, count] : attrib_names) {
      INFO("attribute " << index << " state 0x" << std::hex << pname);
      CHECK(ours->GetVertexAttribIntegers(index, pname, count) == mesa->GetVertexAttribIntegers(index, pname, count));
      CHECK(ours->GetVertexAttribFloats(index, pname, count) == mesa->GetVertexAttribFloats(index, pname, count));
      CHECK(ours->GetError() == mesa->GetError());
    }
  }
  // Current values from packed words (VertexAttribP*): every field at its extremes and in between, signed and
  // unsigned, normalized or not, 1 to 4 components taken (5: the uiv form); then the errors.
  const std::uint32_t words[] = {0x00000000u, 0xFFFFFFFFu, 0x80100200u, 0x7FEFFDFFu, 0x4A5F1234u, 0xC0000201u};
  for (std::uint32_t word : words)
    for (Enum type : {gl::INT_2_10_10_10_REV, gl::UNSIGNED_INT_2_10_10_10_REV})
      for (bool normalized : {false, true})
        for (int components = 1; components <= 5; ++components) {
          INFO("packed word 0x" << std::hex << word << " type 0x" << type << std::dec << " normalized " << normalized
                                << " components " << components);
          ours->VertexAttribP(components, 3, type, normalized, word);
          mesa->VertexAttribP(components, 3, type, normalized, word);
          // (The components the call gives: OpenGL sets the others to (0, 0, 1), as softgl does; Mesa leaves them as
          // they were. docs/guide.md says so.)
          std::vector<float> a = ours->GetVertexAttribFloats(3, gl::CURRENT_VERTEX_ATTRIB, 4);
          std::vector<float> b = mesa->GetVertexAttribFloats(3, gl::CURRENT_VERTEX_ATTRIB, 4);
          a.resize(std::size_t(std::min(components, 4)));
          b.resize(a.size());
          CHECK(a == b);
          CHECK(ours->GetError() == mesa->GetError());
        }
  for (auto [index, type] : {std::pair<std::uint32_t, Enum>{3, gl::UNSIGNED_INT}, {99, gl::INT_2_10_10_10_REV}, {99, gl::FLOAT}}) {
    ours->VertexAttribP(2, index, type, true, 5);
    mesa->VertexAttribP(2, index, type, true, 5);
    CHECK(ours->GetError() == mesa->GetError());
  }
  // A texture's parameters by the integer forms: the border colour kept as integers, other names as iv; errors.
  TextureDesc desc;
  desc.levels.push_back({2, 2, std::vector<std::uint8_t>(16, 200), {}, {}});
  // (A border colour set as floats is not compared through these queries: softgl rounds and clamps the floats to
  // the type, Mesa returns their bit patterns. docs/guide.md says so.)
  mesa->SetTexture(desc);
  ours->SetTexture(desc);
  const int border[4] = {-5, 7, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()};
  const int base = 1, bad = 12345;
  for (bool is_unsigned : {false, true}) {
    for (Backend* b : {ours.get(), mesa.get()}) b->TexParameterI(gl::TEXTURE_BORDER_COLOR, border, is_unsigned);
    CHECK(ours->GetTexParameterI(gl::TEXTURE_BORDER_COLOR, 4, is_unsigned) == mesa->GetTexParameterI(gl::TEXTURE_BORDER_COLOR, 4, is_unsigned));
    CHECK(ours->GetTexParameterI(gl::TEXTURE_BORDER_COLOR, 4, !is_unsigned) == mesa->GetTexParameterI(gl::TEXTURE_BORDER_COLOR, 4, !is_unsigned));
    for (Backend* b : {ours.get(), mesa.get()}) b->TexParameterI(gl::TEXTURE_BASE_LEVEL, &base, is_unsigned);
    CHECK(ours->GetTexParameterI(gl::TEXTURE_BASE_LEVEL, 1, is_unsigned) == mesa->GetTexParameterI(gl::TEXTURE_BASE_LEVEL, 1, is_unsigned));
    for (Backend* b : {ours.get(), mesa.get()}) b->TexParameterI(gl::TEXTURE_MAG_FILTER, &bad, is_unsigned);
    CHECK(ours->GetError() == mesa->GetError());
    CHECK(ours->GetTexParameterI(gl::TEXTURE_WIDTH, 1, is_unsigned) == mesa->GetTexParameterI(gl::TEXTURE_WIDTH, 1, is_unsigned));
    CHECK(ours->GetError() == mesa->GetError());
  }
  // A name that is no attribute state: the same error (Mesa then writes 0, softgl leaves the values, as OpenGL's
  // "no change is made to params" on an error has it).
  (void)ours->GetVertexAttribIntegers(0, gl::TEXTURE_2D, 1);
  (void)mesa->GetVertexAttribIntegers(0, gl::TEXTURE_2D, 1);
  CHECK(ours->GetError() == mesa->GetError());
}

TEST_CASE("query results equal Mesa's", "[conformance]") {
  namespace gl = softgl;
  // In 128 x 128 window coordinates, z in [-1, 1] as NDC.
  auto win = [](float x, float y, float z) { return glm::vec4(x / 64.0f - 1.0f, y / 64.0f - 1.0f, z, 1.0f); };
  auto quad = [&](float x0, float y0, float x1, float y1, float z, glm::vec4 c) {
    return std::vector<Vertex>{{win(x0, y0, z), c}, {win(x1, y0, z), c}, {win(x1, y1, z), c},
                               {win(x0, y0, z), c}, {win(x1, y1, z), c}, {win(x0, y1, z), c}};
  };
  auto run = [&](Backend& b) {
    std::vector<std::uint64_t> results;
    b.ClearDepth(1.0);
    b.Clear(gl::COLOR_BUFFER_BIT | gl::DEPTH_BUFFER_BIT | gl::STENCIL_BUFFER_BIT);
    b.Enable(gl::DEPTH_TEST);
    std::uint32_t q[6];
    for (std::uint32_t& id : q) id = b.GenQuery();
    // Samples: a quad, then one half behind it; a triangle with edges through pixel centres.
    b.BeginQuery(gl::SAMPLES_PASSED, q[0]);
    b.Draw(gl::TRIANGLES, quad(10.5f, 10.25f, 70.5f, 50.75f, 0.0f, glm::vec4(1, 0, 0, 1)));
    b.Draw(gl::TRIANGLES, quad(40.25f, 20.5f, 100.5f, 60.5f, 0.5f, glm::vec4(0, 1, 0, 1)));
    b.Draw(gl::TRIANGLES, {{win(64, 64, -0.5f)}, {win(120, 64, -0.5f)}, {win(64, 120, -0.5f)}});
    b.EndQuery(gl::SAMPLES_PASSED);
    // Any samples: one draw wholly behind (none), then one in front (some); one occlusion query at a time.
    b.BeginQuery(gl::ANY_SAMPLES_PASSED, q[2]);
    b.Draw(gl::TRIANGLES, quad(20, 20, 30, 30, 0.8f, glm::vec4(1)));
    b.BeginQuery(gl::SAMPLES_PASSED, q[1]);  // INVALID_OPERATION on both
    results.push_back(b.GetError());
    b.EndQuery(gl::ANY_SAMPLES_PASSED);
    b.BeginQuery(gl::ANY_SAMPLES_PASSED, q[3]);
    b.Draw(gl::TRIANGLES, quad(20, 20, 30, 30, -0.8f, glm::vec4(1)));
    b.EndQuery(gl::ANY_SAMPLES_PASSED);
    b.BeginQuery(gl::SAMPLES_PASSED, q[1]);
    b.Draw(gl::TRIANGLES, quad(20, 20, 30, 30, -0.85f, glm::vec4(1)));
    b.EndQuery(gl::SAMPLES_PASSED);
    // Stencil-masked samples: only where the stencil test passes.
    b.Enable(gl::STENCIL_TEST);
    b.StencilFunc(gl::ALWAYS, 1, 0xFF);
    b.StencilOp(gl::KEEP, gl::KEEP, gl::REPLACE);
    b.Draw(gl::TRIANGLES, quad(0, 80, 64, 128, -0.9f, glm::vec4(0, 0, 1, 1)));
    b.StencilFunc(gl::EQUAL, 1, 0xFF);
    b.BeginQuery(gl::SAMPLES_PASSED, q[4]);
    b.Draw(gl::TRIANGLES, quad(30, 70, 128, 128, -0.95f, glm::vec4(1, 1, 0, 1)));
    b.EndQuery(gl::SAMPLES_PASSED);
    b.Disable(gl::STENCIL_TEST);
    // Primitives: a strip of 10 (8 triangles), a loop of 5 (5 lines), 7 points, and triangles culled or clipped
    // away (counted all the same).
    b.BeginQuery(gl::PRIMITIVES_GENERATED, q[5]);
    std::vector<Vertex> strip, loop, points;
    for (int i = 0; i < 10; ++i) strip.push_back({win(5.0f + 10 * i, i % 2 ? 100 : 90, 0.2f)});
    for (int i = 0; i < 5; ++i) loop.push_back({win(60.0f + 9 * i, 110.0f - 3 * i, 0.2f)});
    for (int i = 0; i < 7; ++i) points.push_back({win(3.0f + 4 * i, 3, 0.2f)});
    b.Draw(gl::TRIANGLE_STRIP, strip);
    b.Draw(gl::LINE_LOOP, loop);
    b.Draw(gl::POINTS, points);
    b.Enable(gl::CULL_FACE);
    b.Draw(gl::TRIANGLES, {{win(10, 10, 0)}, {win(10, 40, 0)}, {win(40, 10, 0)},         // clockwise: culled
                           {win(300, 10, 0)}, {win(400, 10, 0)}, {win(300, 90, 0)}});  // outside: clipped away
    b.Disable(gl::CULL_FACE);
    b.EndQuery(gl::PRIMITIVES_GENERATED);
    for (std::uint32_t id : q) results.push_back(b.QueryResult(id));
    return results;
  };
  std::string error;
  auto mesa = MakeGlBackend(128, 128, &error);
  REQUIRE(mesa);
  auto ours = MakeSoftglBackend(128, 128);
  const std::vector<std::uint64_t> want = run(*mesa), got = run(*ours);
  CHECK(mesa->GetError() == softgl::NO_ERROR);
  CHECK(ours->GetError() == softgl::NO_ERROR);
  CHECK(got == want);
  REQUIRE(want.size() == 7);
  CHECK(want[0] == softgl::INVALID_OPERATION);
  CHECK(want[3] == 0);  // the scene means what it says: nothing passed behind the quad, something in front
  CHECK(want[4] == 1);
  CHECK(want[6] == 22);
}

// `run(backend, step)` on Mesa and on softgl (size x size windows), where step(value) records a value (0 where the
// call has none) and the error after it: the (value, error) pairs, step by step, equal.
template <class Run>
void CompareSteps(int size, Run&& run) {
  auto steps = [&](Backend& b) {
    std::vector<std::int64_t> out;
    const auto step = [&](std::int64_t value) {
      out.push_back(value);
      out.push_back(b.GetError());
    };
    run(b, step);
    return out;
  };
  std::string error;
  auto mesa = MakeGlBackend(size, size, &error);
  REQUIRE(mesa);
  auto ours = MakeSoftglBackend(size, size);
  const std::vector<std::int64_t> want = steps(*mesa), got = steps(*ours);
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < want.size(); i += 2) {
    INFO("step " << i / 2);
    CHECK(got[i] == want[i]);
    CHECK(got[i + 1] == want[i + 1]);
  }
}

TEST_CASE("conditional rendering, fences and ClampColor: errors, state and reads as Mesa's", "[conformance]") {
  namespace gl = softgl;
  // Each step's error (and value, where it has one) in both; the fence's wait results are compared only where
  // they do not depend on how fast the work runs.
  auto run = [](Backend& b, const auto& step) {
    step(b.GetIntegers(gl::CLAMP_READ_COLOR, 1)[0]);
    b.ClampColor(gl::CLAMP_READ_COLOR, 2);
    step(0);
    b.ClampColor(gl::READ_BUFFER, 1);
    step(0);
    b.ClampColor(gl::CLAMP_READ_COLOR, 0);
    step(b.GetIntegers(gl::CLAMP_READ_COLOR, 1)[0]);
    // A float framebuffer read as stored, then clamped.
    const std::uint32_t fbo = b.GenFramebuffer();
    b.BindFramebuffer(gl::FRAMEBUFFER, fbo);
    b.AttachNewTexture(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, gl::RGBA32F, 4, 4);
    const float value[4] = {2.5f, -0.75f, 0.25f, 1.5f};
    b.ClearBufferfv(gl::COLOR, 0, value);
    // (SHORT only clamped: unclamped, softgl converts -0.75 to -24575 as OpenGL's signed rule says, and Mesa clamps
    // to [0, 1] first for every type but the float ones; docs/guide.md says so.)
    for (Enum clamp : {Enum(0), Enum(1), gl::FIXED_ONLY})
      for (Enum type : {gl::FLOAT, gl::SHORT, gl::UNSIGNED_BYTE}) {
        if (type == gl::SHORT && clamp != 1) continue;
        b.ClampColor(gl::CLAMP_READ_COLOR, clamp);
        PixelRead r{1, 1, 1, 1, gl::RGBA, type, 1};
        const std::vector<std::uint8_t> bytes = b.ReadPixels(r, 16);
        for (std::size_t i = 0; i < bytes.size(); i += 4) {
          std::uint32_t word = 0;
          std::memcpy(&word, &bytes[i], 4);
          step(word);
        }
      }
    b.BindFramebuffer(gl::FRAMEBUFFER, 0);
    // Conditional rendering.
    const std::uint32_t never = b.GenQuery(), prims = b.GenQuery(), occlusion = b.GenQuery();
    b.BeginConditionalRender(occlusion, gl::QUERY_RESULT);
    step(0);
    b.BeginConditionalRender(occlusion + 100, gl::QUERY_WAIT);
    step(0);
    b.BeginConditionalRender(never, gl::QUERY_WAIT);
    step(0);
    b.BeginQuery(gl::PRIMITIVES_GENERATED, prims);
    b.EndQuery(gl::PRIMITIVES_GENERATED);
    b.BeginConditionalRender(prims, gl::QUERY_NO_WAIT);
    step(0);
    b.BeginQuery(gl::SAMPLES_PASSED, occlusion);
    b.BeginConditionalRender(occlusion, gl::QUERY_WAIT);
    step(0);
    b.EndQuery(gl::SAMPLES_PASSED);
    b.EndConditionalRender();
    step(0);
    b.BeginConditionalRender(occlusion, gl::QUERY_BY_REGION_NO_WAIT);
    step(0);
    b.BeginConditionalRender(occlusion, gl::QUERY_WAIT);
    step(0);
    b.EndConditionalRender();
    step(0);
    // Fences.
    step(b.FenceSync(gl::SYNC_FENCE, 0) == nullptr);
    step(b.FenceSync(gl::SYNC_GPU_COMMANDS_COMPLETE, 1) == nullptr);
    b.Draw(gl::TRIANGLES, {{glm::vec4(-1, -1, 0, 1)}, {glm::vec4(3, -1, 0, 1)}, {glm::vec4(-1, 3, 0, 1)}});
    const void* fence = b.FenceSync(gl::SYNC_GPU_COMMANDS_COMPLETE, 0);
    step(fence != nullptr);
    step(b.IsSync(fence));
    for (Enum pname : {gl::OBJECT_TYPE, gl::SYNC_CONDITION, gl::SYNC_FLAGS, gl::QUERY_RESULT}) step(b.GetSynci(fence, pname));
    const Enum waited = b.ClientWaitSync(fence, gl::SYNC_FLUSH_COMMANDS_BIT, 1000000000);
    step(waited == gl::ALREADY_SIGNALED || waited == gl::CONDITION_SATISFIED);
    step(b.ClientWaitSync(fence, 0, 0));
    step(b.GetSynci(fence, gl::SYNC_STATUS));
    step(b.ClientWaitSync(fence, 4, 0));
    b.WaitSync(fence, 0, gl::TIMEOUT_IGNORED);
    step(0);
    b.WaitSync(fence, 1, gl::TIMEOUT_IGNORED);
    step(0);
    b.WaitSync(fence, 0, 5);
    step(0);
    step(b.GetIntegers(gl::MAX_SERVER_WAIT_TIMEOUT, 1).size());
    b.DeleteSync(nullptr);
    step(0);
    b.DeleteSync(fence);
    step(b.IsSync(fence));
    step(b.ClientWaitSync(fence, 0, 0));
    b.DeleteSync(fence);
    step(0);
  };
  CompareSteps(32, run);
}

TEST_CASE("per-draw-buffer state (ColorMaski, Enablei) and the indexed queries as Mesa's", "[conformance]") {
  namespace gl = softgl;
  auto run = [](Backend& b, const auto& step) {
    auto read = [&](std::uint32_t i) {
      for (bool v : b.GetBooleansI(gl::COLOR_WRITEMASK, i, 4)) step(v);
      step(b.IsEnabledi(gl::BLEND, i));
      step(b.GetBooleansI(gl::BLEND, i, 1)[0]);
      for (std::int64_t v : b.GetIntegersI(gl::COLOR_WRITEMASK, i, 4)) step(v);
    };
    for (std::uint32_t i : {0u, 3u, 7u}) read(i);
    b.ColorMaski(3, true, false, true, false);
    b.Enablei(gl::BLEND, 3);
    b.Enablei(gl::BLEND, 7);
    b.Disablei(gl::BLEND, 7);
    for (std::uint32_t i : {0u, 3u, 7u}) read(i);
    for (bool v : b.GetBooleans(gl::COLOR_WRITEMASK, 4)) step(v);  // draw buffer 0's
    step(b.GetBooleans(gl::BLEND, 1)[0]);
    b.Enable(gl::BLEND);  // every draw buffer's
    b.ColorMask(false, true, false, true);
    for (std::uint32_t i : {0u, 3u, 7u}) read(i);
    b.ColorMaski(3, true, true, true, true);
    b.Disablei(gl::BLEND, 0);
    step(b.GetBooleans(gl::BLEND, 1)[0]);
    for (bool v : b.GetBooleans(gl::COLOR_WRITEMASK, 4)) step(v);
    step(b.GetIntegersI(gl::SAMPLE_MASK_VALUE, 0, 1)[0]);
    // Errors: an index past the last draw buffer or mask word, a name with no indexed value, another capability.
    b.ColorMaski(8, true, true, true, true);
    step(0);
    b.Enablei(gl::BLEND, 8);
    step(0);
    b.Enablei(gl::DEPTH_TEST, 0);
    step(0);
    step(b.IsEnabledi(gl::BLEND, 9));
    (void)b.GetBooleansI(gl::COLOR_WRITEMASK, 8, 4);
    step(0);
    (void)b.GetIntegersI(gl::SAMPLE_MASK_VALUE, 1, 1);
    step(0);
    (void)b.GetIntegersI(gl::DEPTH_FUNC, 0, 1);
    step(0);
  };
  CompareSteps(16, run);
}

TEST_CASE("transform feedback: recorded values, counts, state and errors as Mesa's", "[conformance]") {
  namespace gl = softgl;
  auto run = [](Backend& b, const auto& step) {
    auto floats = [&](std::uint32_t buffer, int n) {  // each float's bits
      for (float f : b.ReadBufferFloats(buffer, n)) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &f, 4);
        step(bits);
      }
    };
    auto bindings = [&] {
      for (std::uint32_t i = 0; i < 4; ++i)
        for (Enum pname : {gl::TRANSFORM_FEEDBACK_BUFFER_BINDING, gl::TRANSFORM_FEEDBACK_BUFFER_START,
                           gl::TRANSFORM_FEEDBACK_BUFFER_SIZE})
          step(b.GetIntegersI(pname, i, 1)[0]);
      step(b.GetIntegers(gl::TRANSFORM_FEEDBACK_BUFFER_BINDING, 1)[0]);
    };
    std::vector<Vertex> v;
    for (int i = 0; i < 8; ++i)
      v.push_back({glm::vec4(-0.8f + 0.2f * float(i), float(i % 3) * 0.3f - 0.4f, 0.1f * float(i), 1.0f + 0.25f * float(i)),
                   glm::vec4(0.125f * float(i), 0.5f, 1.0f - 0.125f * float(i), 1.0f),
                   glm::vec4(float(i), 0.5f * float(i), -1.0f, 3.0f)});
    for (Enum pname : {gl::MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS, gl::MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS,
                       gl::MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS})
      step(b.GetIntegers(pname, 1)[0] >= (pname == gl::MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS ? 64 : 4));
    bindings();
    // Interleaved: colour, extra and position; strips, fans and loops taken apart, indexed draws, both provoking
    // vertex conventions.
    b.FeedbackVaryings({1, 2, 0}, gl::INTERLEAVED_ATTRIBS);
    step(0);
    const std::uint32_t a = b.NewFeedbackBuffer(1200);
    b.BindBufferBase(0, a);
    step(0);
    bindings();
    const std::uint32_t written = b.GenQuery(), generated = b.GenQuery();
    b.Draw(gl::TRIANGLES, v, Program::kFeedback);  // (makes the program current)
    b.BeginQuery(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
    b.BeginQuery(gl::PRIMITIVES_GENERATED, generated);
    b.BeginTransformFeedback(gl::TRIANGLES);
    step(0);
    for (Enum convention : {gl::LAST_VERTEX_CONVENTION, gl::FIRST_VERTEX_CONVENTION}) {
      b.PauseTransformFeedback();
      b.ProvokingVertex(convention);
      b.ResumeTransformFeedback();
      step(0);
      b.Draw(gl::TRIANGLE_STRIP, {v.begin(), v.begin() + 7}, Program::kFeedback);
      b.Draw(gl::TRIANGLE_FAN, {v.begin(), v.begin() + 6}, Program::kFeedback);
      b.Draw(gl::TRIANGLES, v, {7, 2, 5, 0, 0, 3}, Program::kFeedback, Uniforms{});
      step(0);
      b.Draw(gl::LINES, v, Program::kFeedback);  // another kind: INVALID_OPERATION
      step(0);
    }
    b.EndTransformFeedback();
    b.EndQuery(gl::PRIMITIVES_GENERATED);
    b.EndQuery(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    step(b.QueryResult(written));
    step(b.QueryResult(generated));
    floats(a, 1200);
    // Lines and points, separate buffers with ranges too small for every primitive.
    b.ProvokingVertex(gl::LAST_VERTEX_CONVENTION);
    b.FeedbackVaryings({0, 2}, gl::SEPARATE_ATTRIBS);
    const std::uint32_t c = b.NewFeedbackBuffer(64), d = b.NewFeedbackBuffer(64);
    b.BindBufferRange(0, c, 16, 160);  // 10 vertices of 4 floats from float 4
    b.BindBufferBase(1, d);
    bindings();
    b.BeginQuery(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
    b.BeginTransformFeedback(gl::LINES);
    b.Draw(gl::LINE_LOOP, {v.begin(), v.begin() + 4}, Program::kFeedback);  // 4 lines
    b.Draw(gl::LINE_STRIP, {v.begin() + 3, v.begin() + 6}, Program::kFeedback);  // 2 lines: the second does not fit
    b.EndTransformFeedback();
    b.EndQuery(gl::TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    step(b.QueryResult(written));
    floats(c, 64);
    floats(d, 64);
    // Points, paused in the middle (any mode then), and RASTERIZER_DISCARD: recorded, not drawn, clears dropped.
    b.FeedbackVaryings({2}, gl::INTERLEAVED_ATTRIBS);
    const std::uint32_t e = b.NewFeedbackBuffer(64);
    b.BindBufferBase(0, e);
    b.ClearColor(0, 0, 1, 1);
    b.Clear(gl::COLOR_BUFFER_BIT);
    b.Enable(gl::RASTERIZER_DISCARD);
    b.BeginTransformFeedback(gl::POINTS);
    b.Draw(gl::POINTS, {v.begin(), v.begin() + 2}, Program::kFeedback);
    b.PauseTransformFeedback();
    b.Draw(gl::TRIANGLES, {v.begin(), v.begin() + 3}, Program::kFeedback);
    b.ResumeTransformFeedback();
    b.Draw(gl::POINTS, {v.begin() + 5, v.begin() + 7}, Program::kFeedback);
    step(0);
    b.ClearColor(0, 1, 0, 1);
    b.Clear(gl::COLOR_BUFFER_BIT);
    b.EndTransformFeedback();
    b.Disable(gl::RASTERIZER_DISCARD);
    floats(e, 64);
    const Frame f = b.Read();
    step(f.rgba[(8 * f.width + 8) * 4 + 1]);
    step(f.rgba[(8 * f.width + 8) * 4 + 2]);
    // Objects: recorded in one, drawn by DrawTransformFeedback (counted by PRIMITIVES_GENERATED). (Mesa 22.3.6
    // counts the vertices as the bytes recorded over the stride of the draw's vertex buffer, so the layout here
    // is a Vertex's 48 bytes; docs/conformance.md.)
    const std::uint32_t object = b.GenTransformFeedback();
    b.BindTransformFeedback(object);
    step(0);
    bindings();
    b.FeedbackVaryings({1, 2, 0}, gl::INTERLEAVED_ATTRIBS);
    b.BindBufferBase(0, a);
    b.BeginTransformFeedback(gl::TRIANGLES);
    b.Draw(gl::TRIANGLE_STRIP, {v.begin(), v.begin() + 5}, Program::kFeedback);
    b.EndTransformFeedback();
    b.BindTransformFeedback(0);
    bindings();
    b.BeginQuery(gl::PRIMITIVES_GENERATED, generated);
    b.DrawTransformFeedback(gl::POINTS, object);
    step(0);
    b.EndQuery(gl::PRIMITIVES_GENERATED);
    step(b.QueryResult(generated));
    // Errors.
    b.FeedbackVaryings({0, 1, 2, 0, 1}, gl::SEPARATE_ATTRIBS);  // more than 4 separate
    step(0);
    b.BindBufferBase(4, e);
    step(0);
    b.BindBufferRange(0, e, 2, 16);
    step(0);
    b.BindBufferRange(0, e, 0, 0);
    step(0);
    b.BindBufferBase(0, e + 100);
    step(0);
    b.BeginTransformFeedback(gl::TRIANGLE_STRIP);
    step(0);
    b.EndTransformFeedback();
    step(0);
    b.PauseTransformFeedback();
    step(0);
    b.BindBufferBase(0, 0);
    b.BeginTransformFeedback(gl::POINTS);  // binding 0 empty
    step(0);
    b.BindBufferBase(0, e);
    b.BeginTransformFeedback(gl::POINTS);
    b.BeginTransformFeedback(gl::POINTS);
    step(0);
    b.BindBufferBase(0, e);
    step(0);
    b.BindTransformFeedback(object);
    step(0);
    b.ResumeTransformFeedback();
    step(0);
    b.EndTransformFeedback();
    b.DrawTransformFeedback(gl::POINTS, object + 100);
    step(0);
    const std::uint32_t fresh = b.GenTransformFeedback();
    b.DrawTransformFeedback(gl::POINTS, fresh);  // never bound: no object yet
    step(0);
    b.BindTransformFeedback(fresh);
    b.BindTransformFeedback(0);
    b.DrawTransformFeedback(gl::POINTS, fresh);  // never ended
    step(0);
  };
  CompareSteps(16, run);
}

TEST_CASE("layered framebuffers: completeness, attachment state and errors as Mesa's", "[conformance]") {
  namespace gl = softgl;
  auto run = [](Backend& b, const auto& step) {
    const Enum fb = gl::FRAMEBUFFER, c0 = gl::COLOR_ATTACHMENT0, c1 = gl::COLOR_ATTACHMENT0 + 1;
    auto state = [&](Enum attachment) {
      for (Enum pname : {gl::FRAMEBUFFER_ATTACHMENT_LAYERED, gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
                         gl::FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, gl::FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE})
        step(b.GetAttachmentParameter(fb, attachment, pname));
      step(b.CheckFramebufferStatus(fb));
    };
    b.BindFramebuffer(fb, b.GenFramebuffer());
    const std::uint32_t array = b.AttachLayered(fb, c0, gl::TEXTURE_2D_ARRAY, gl::RGBA8, 8, 3, -1);
    state(c0);
    b.AttachNewTexture(fb, c1, gl::RGBA8, 8, 8);  // unlayered beside layered
    state(c1);
    const std::uint32_t volume = b.AttachLayered(fb, c1, gl::TEXTURE_3D, gl::RGBA8, 8, 4, -1);  // two layered targets
    state(c1);
    b.AttachLayered(fb, c1, gl::TEXTURE_2D_ARRAY, gl::RGBA8, 8, 5, -1);  // more layers than the other
    state(c1);
    b.AttachLayered(fb, gl::DEPTH_ATTACHMENT, gl::TEXTURE_2D_ARRAY, gl::DEPTH_COMPONENT32F, 8, 3, 1);  // one layer
    state(gl::DEPTH_ATTACHMENT);
    b.AttachLayered(fb, gl::DEPTH_ATTACHMENT, gl::TEXTURE_2D_ARRAY, gl::DEPTH_COMPONENT32F, 8, 3, -1);
    state(gl::DEPTH_ATTACHMENT);
    b.AttachLayered(fb, c1, gl::TEXTURE_CUBE_MAP, gl::RGBA8, 8, 6, -1);  // a cube map beside an array
    state(c1);
    b.FramebufferTexture(fb, c1, 0, 0);
    b.FramebufferTexture(fb, gl::DEPTH_ATTACHMENT, 0, 0);
    b.FramebufferTexture(fb, c0, 0, 0);
    b.AttachLayered(fb, c0, gl::TEXTURE_CUBE_MAP, gl::RGBA8, 8, 6, -1);
    state(c0);
    b.AttachLayered(fb, c0, gl::TEXTURE_3D, gl::RGBA8, 8, 4, 2);  // FramebufferTexture3D: one slice
    state(c0);
    // Errors.
    b.FramebufferTexture3D(fb, c0, gl::TEXTURE_2D, volume, 0, 0);
    step(0);
    b.FramebufferTexture3D(fb, c0, gl::TEXTURE_3D, array, 0, 0);
    step(0);
    b.FramebufferTexture3D(fb, c0, gl::TEXTURE_3D, volume, 0, -1);
    step(0);
    b.FramebufferTexture3D(fb, c0, gl::TEXTURE_3D, volume, 12, 0);
    step(0);
    b.FramebufferTexture(fb, c0, array + 100, 0);
    step(0);
    b.FramebufferTexture(fb, c0, array, -1);
    step(0);
    b.FramebufferTexture(fb, 0x1234, array, 0);
    step(0);
    b.FramebufferTexture(fb, c0, volume, 0);
    state(c0);
    b.BindFramebuffer(fb, 0);
    b.FramebufferTexture(fb, c0, array, 0);
    step(0);
  };
  CompareSteps(16, run);
}

TEST_CASE("compressed textures: decoded texels, blocks read back, level state and errors as Mesa's", "[conformance]") {
  namespace gl = softgl;
  // Every S3TC, RGTC and BPTC (BC7, BC6H) format, decoded by both from the same pseudo-random blocks (both modes of each block kind
  // come up: c0 > c1 and not, a0 > a1 and not, signed endpoints of -128), read back as floats (compared as whole
  // multiples of 1 / (255 * 127), exact for both unsigned bytes and signed ones); images with partial blocks;
  // CompressedTexSubImage; a 2D array; then OpenGL's errors.
  const Enum formats[] = {gl::COMPRESSED_RGB_S3TC_DXT1_EXT,        gl::COMPRESSED_RGBA_S3TC_DXT1_EXT,
                          gl::COMPRESSED_RGBA_S3TC_DXT3_EXT,       gl::COMPRESSED_RGBA_S3TC_DXT5_EXT,
                          gl::COMPRESSED_SRGB_S3TC_DXT1_EXT,       gl::COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT,
                          gl::COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT, gl::COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT,
                          gl::COMPRESSED_RED_RGTC1,                gl::COMPRESSED_SIGNED_RED_RGTC1,
                          gl::COMPRESSED_RG_RGTC2,                 gl::COMPRESSED_SIGNED_RG_RGTC2,
                          gl::COMPRESSED_RGBA_BPTC_UNORM,          gl::COMPRESSED_SRGB_ALPHA_BPTC_UNORM,
                          gl::COMPRESSED_RGB_BPTC_SIGNED_FLOAT,    gl::COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT};
  auto block_bytes = [](Enum f) {
    return f == gl::COMPRESSED_RGB_S3TC_DXT1_EXT || f == gl::COMPRESSED_RGBA_S3TC_DXT1_EXT ||
                   f == gl::COMPRESSED_SRGB_S3TC_DXT1_EXT || f == gl::COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT ||
                   f == gl::COMPRESSED_RED_RGTC1 || f == gl::COMPRESSED_SIGNED_RED_RGTC1
               ? 8
               : 16;
  };
  auto size_of = [&](Enum f, int w, int h, int d) { return (w + 3) / 4 * ((h + 3) / 4) * d * block_bytes(f); };
  auto blocks = [](int bytes, std::uint32_t seed) {
    std::vector<std::uint8_t> v(static_cast<std::size_t>(bytes));
    for (std::uint8_t& x : v) {
      seed = seed * 1664525u + 1013904223u;
      x = std::uint8_t(seed >> 24);
    }
    for (std::size_t i = 0; i + 16 <= v.size(); i += 40) v[i] = 0x80;  // a signed endpoint of -128 now and then
    return v;
  };
  auto run = [&](Backend& b, const auto& step) {
    auto read = [&](Enum target, int w, int h, int d) {
      for (float v : b.GetTexImageFloats(target, 0, w * h * d * 4)) step(std::llround(double(v) * 255.0 * 127.0));
    };
    auto level_state = [&](Enum target, int level) {
      for (Enum pname : {gl::TEXTURE_COMPRESSED, gl::TEXTURE_COMPRESSED_IMAGE_SIZE, gl::TEXTURE_INTERNAL_FORMAT,
                         gl::TEXTURE_WIDTH, gl::TEXTURE_HEIGHT})
        step(b.GetTexLevelParameter(target, level, pname));
    };
    std::uint32_t seed = 1;
    for (Enum f : formats) {
      for (const glm::ivec2 size : {glm::ivec2(16, 16), glm::ivec2(10, 6), glm::ivec2(3, 2)}) {
        b.BindNewTexture(gl::TEXTURE_2D);
        const int n = size_of(f, size.x, size.y, 1);
        const std::vector<std::uint8_t> data = blocks(n, seed++);
        b.CompressedTexImage(2, gl::TEXTURE_2D, 0, f, size.x, size.y, 1, n, data.data());
        step(0);
        level_state(gl::TEXTURE_2D, 0);
        read(gl::TEXTURE_2D, size.x, size.y, 1);
        for (std::uint8_t v : b.GetCompressedTexImage(gl::TEXTURE_2D, 0, n + 4)) step(v);
        if (size.x == 10) {  // one whole block, then the partial block at the right edge
          const int k = block_bytes(f);
          const std::vector<std::uint8_t> sub = blocks(2 * k, seed++);
          b.CompressedTexSubImage(2, gl::TEXTURE_2D, 0, 4, 0, 0, 4, 4, 1, f, k, sub.data());
          step(0);
          b.CompressedTexSubImage(2, gl::TEXTURE_2D, 0, 8, 4, 0, 2, 2, 1, f, k, sub.data() + k);
          step(0);
          read(gl::TEXTURE_2D, size.x, size.y, 1);
        }
      }
    }
    // A 2D array of three layers, and one layer's block replaced.
    const Enum dxt5 = gl::COMPRESSED_RGBA_S3TC_DXT5_EXT;
    b.BindNewTexture(gl::TEXTURE_2D_ARRAY);
    const std::vector<std::uint8_t> layers = blocks(size_of(dxt5, 8, 8, 3), 99);
    b.CompressedTexImage(3, gl::TEXTURE_2D_ARRAY, 0, dxt5, 8, 8, 3, size_of(dxt5, 8, 8, 3), layers.data());
    step(0);
    b.CompressedTexSubImage(3, gl::TEXTURE_2D_ARRAY, 0, 4, 4, 1, 4, 4, 1, dxt5, 16, layers.data());
    step(0);
    level_state(gl::TEXTURE_2D_ARRAY, 0);
    read(gl::TEXTURE_2D_ARRAY, 8, 8, 3);
    // BC7 in a 3D texture (BPTC's blocks may stack as slices), every mode's first-byte pattern among the blocks.
    const Enum bc7 = gl::COMPRESSED_RGBA_BPTC_UNORM;
    b.BindNewTexture(gl::TEXTURE_3D);
    std::vector<std::uint8_t> slices = blocks(size_of(bc7, 8, 8, 4), 123);
    for (std::size_t k = 0; k * 16 < slices.size(); ++k) slices[k * 16] = std::uint8_t(k % 9 == 8 ? 0 : 1u << (k % 9));
    b.CompressedTexImage(3, gl::TEXTURE_3D, 0, bc7, 8, 8, 4, size_of(bc7, 8, 8, 4), slices.data());
    step(0);
    level_state(gl::TEXTURE_3D, 0);
    read(gl::TEXTURE_3D, 8, 8, 4);
    // BC6H, signed and unsigned, every mode (and two reserved ones) in the low bits of a block's first byte; the
    // first 16 blocks pseudo-random, the next 16 all ones past the mode bits (the largest endpoints, and the
    // deltas of -1), the last 16 all zeros.
    const int bc6_modes[16] = {0, 1, 2, 6, 10, 14, 18, 22, 26, 30, 3, 7, 11, 15, 19, 31};
    for (const Enum bc6 : {gl::COMPRESSED_RGB_BPTC_SIGNED_FLOAT, gl::COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT}) {
      b.BindNewTexture(gl::TEXTURE_2D);
      std::vector<std::uint8_t> modes = blocks(size_of(bc6, 16, 48, 1), 321);
      for (std::size_t k = 0; k * 16 < modes.size(); ++k) {
        if (k >= 16) std::fill_n(modes.begin() + std::ptrdiff_t(k * 16), 16, std::uint8_t(k < 32 ? 0xFF : 0));
        modes[k * 16] = std::uint8_t((modes[k * 16] & 0xE0) | bc6_modes[k % 16]);
      }
      b.CompressedTexImage(2, gl::TEXTURE_2D, 0, bc6, 16, 48, 1, size_of(bc6, 16, 48, 1), modes.data());
      step(0);
      read(gl::TEXTURE_2D, 16, 48, 1);
    }
    // Errors, each call's alone.
    const std::vector<std::uint8_t> some = blocks(4096, 7);
    b.BindNewTexture(gl::TEXTURE_2D);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, gl::RGBA8, 4, 4, 1, 16, some.data());  // not a compressed format
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, gl::COMPRESSED_RGBA, 4, 4, 1, 16, some.data());  // generic
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, dxt5, 4, 4, 1, 17, some.data());  // wrong size
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, dxt5, -4, 4, 1, 16, some.data());
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_2D, -1, dxt5, 4, 4, 1, 16, some.data());
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, dxt5, 0, 0, 1, 0, some.data());  // empty: fine
    step(0);
    level_state(gl::TEXTURE_2D, 0);
    b.CompressedTexImage(2, gl::TEXTURE_CUBE_MAP, 0, dxt5, 4, 4, 1, 16, some.data());  // the cube map itself
    step(0);
    b.BindNewTexture(gl::TEXTURE_CUBE_MAP);
    b.CompressedTexImage(2, gl::TEXTURE_CUBE_MAP_POSITIVE_X, 0, dxt5, 8, 4, 1, 32, some.data());  // not square
    step(0);
    b.CompressedTexImage(2, gl::TEXTURE_CUBE_MAP_NEGATIVE_Y, 1, dxt5, 8, 8, 1, 64, some.data());
    step(0);
    level_state(gl::TEXTURE_CUBE_MAP_NEGATIVE_Y, 1);
    b.BindNewTexture(gl::TEXTURE_1D);
    b.CompressedTexImage(1, gl::TEXTURE_1D, 0, gl::COMPRESSED_RED_RGTC1, 4, 1, 1, 8, some.data());
    step(0);
    b.CompressedTexSubImage(1, gl::TEXTURE_1D, 0, 0, 0, 0, 4, 1, 1, gl::COMPRESSED_RED_RGTC1, 8, some.data());
    step(0);
    b.BindNewTexture(gl::TEXTURE_3D);
    b.CompressedTexImage(3, gl::TEXTURE_3D, 0, dxt5, 4, 4, 4, 64, some.data());
    step(0);
    b.BindNewTexture(gl::TEXTURE_1D_ARRAY);
    b.CompressedTexImage(2, gl::TEXTURE_1D_ARRAY, 0, gl::COMPRESSED_RED_RGTC1, 4, 4, 1, 8, some.data());
    step(0);
    b.BindNewTexture(gl::TEXTURE_2D);
    b.CompressedTexImage(2, gl::TEXTURE_2D, 0, dxt5, 10, 10, 1, size_of(dxt5, 10, 10, 1), some.data());
    step(0);
    const struct Sub { int x, y, w, h, size; Enum format; } subs[] = {
        {2, 0, 4, 4, 16, dxt5},                              // offset not a multiple of 4
        {0, 0, 3, 4, 16, dxt5},                              // width short of the edge
        {8, 8, 2, 2, 16, dxt5},                              // the corner block, reaching both edges: fine
        {8, 8, 4, 4, 16, dxt5},                              // past the level
        {0, 0, 4, 4, 15, dxt5},                              // wrong size
        {0, 0, 4, 4, 16, gl::COMPRESSED_RGBA_S3TC_DXT3_EXT},  // another compressed format
        {0, 0, 4, 4, 16, gl::RGBA8},                          // not a compressed format
        {0, 0, 0, 0, 0, dxt5},                                // empty: fine
        {-4, 0, 4, 4, 16, dxt5},
    };
    for (const Sub& u : subs) {
      b.CompressedTexSubImage(2, gl::TEXTURE_2D, 0, u.x, u.y, 0, u.w, u.h, 1, u.format, u.size, some.data());
      step(0);
    }
    b.CompressedTexSubImage(2, gl::TEXTURE_2D, 1, 0, 0, 0, 4, 4, 1, dxt5, 16, some.data());  // level not defined
    step(0);
    b.TexImage2D(gl::TEXTURE_2D, 1, gl::RGBA8, 5, 5);
    step(0);
    b.CompressedTexSubImage(2, gl::TEXTURE_2D, 1, 0, 0, 0, 4, 4, 1, dxt5, 16, some.data());  // not compressed
    step(0);
    level_state(gl::TEXTURE_2D, 1);  // TEXTURE_COMPRESSED_IMAGE_SIZE of an uncompressed level
    b.GetCompressedTexImage(gl::TEXTURE_2D, 1, 64);
    step(0);
    b.GetCompressedTexImage(gl::TEXTURE_2D, 3, 64);  // not defined
    step(0);
  };
  CompareSteps(16, run);
}

TEST_CASE("multisample arrays: TexImage3DMultisample's level state, attachments and errors as Mesa's", "[conformance]") {
  namespace gl = softgl;
  auto run = [](Backend& b, const auto& step) {
    auto level_state = [&] {
      for (Enum pname : {gl::TEXTURE_WIDTH, gl::TEXTURE_HEIGHT, gl::TEXTURE_DEPTH, gl::TEXTURE_SAMPLES,
                         gl::TEXTURE_INTERNAL_FORMAT, gl::TEXTURE_RED_SIZE, gl::TEXTURE_DEPTH_SIZE, gl::TEXTURE_STENCIL_SIZE})
        step(b.GetTexLevelParameter(gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 0, pname));
    };
    b.TexImage3DMultisample(gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 8, 6, 3);  // the default texture: Mesa
    (void)b.GetError();                                                                // has one, softgl not
    b.BindNewTexture(gl::TEXTURE_2D_MULTISAMPLE_ARRAY);
    step(b.GetIntegers(gl::TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY, 1)[0] != 0);
    const struct Image { Enum target; int samples; Enum format; int w, h, d; } images[] = {
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 8, 6, 3},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 3, gl::DEPTH24_STENCIL8, 5, 7, 2},  // (3 samples: 4 in both)
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA16F, 4, 4, 1},
        {gl::TEXTURE_2D_MULTISAMPLE, 4, gl::RGBA8, 8, 8, 2},              // the other target
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::COMPRESSED_RGBA_S3TC_DXT1_EXT, 8, 8, 2},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 0, gl::RGBA8, 8, 8, 2},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 8, 8, -1},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 8, 8, 5000},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 20000, 8, 2},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 64, gl::RGBA8, 8, 8, 2},
        {gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, gl::RGBA8, 8, 6, 3},
    };
    for (const Image& i : images) {
      b.TexImage3DMultisample(i.target, i.samples, i.format, i.w, i.h, i.d);
      step(0);
      level_state();
    }
    step(b.GetTexLevelParameter(gl::TEXTURE_2D_MULTISAMPLE_ARRAY, 1, gl::TEXTURE_WIDTH));  // no level 1
    b.GenerateMipmap(gl::TEXTURE_2D_MULTISAMPLE_ARRAY);
    step(0);
    // Attached one layer at a time and every layer, beside a multisample array of depth.
    const std::uint32_t color = b.NewMultisampleArray(4, gl::RGBA8, 8, 6, 3);
    const std::uint32_t depth = b.NewMultisampleArray(4, gl::DEPTH24_STENCIL8, 8, 6, 3);
    b.BindFramebuffer(gl::FRAMEBUFFER, b.GenFramebuffer());
    b.FramebufferTextureLayer(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, color, 1, 0);  // level 1
    step(0);
    b.FramebufferTextureLayer(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, color, 0, -1);
    step(0);
    b.FramebufferTextureLayer(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, color, 0, 2);
    step(0);
    step(b.CheckFramebufferStatus(gl::FRAMEBUFFER));
    step(b.GetIntegers(gl::SAMPLES, 1)[0]);
    b.FramebufferTextureLayer(gl::FRAMEBUFFER, gl::DEPTH_STENCIL_ATTACHMENT, depth, 0, 1);
    step(b.CheckFramebufferStatus(gl::FRAMEBUFFER));
    b.FramebufferTexture(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, color, 1);  // level 1
    step(0);
    b.FramebufferTexture(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, color, 0);
    step(b.CheckFramebufferStatus(gl::FRAMEBUFFER));  // layered beside one layer
    step(b.GetAttachmentParameter(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, gl::FRAMEBUFFER_ATTACHMENT_LAYERED));
    b.FramebufferTexture(gl::FRAMEBUFFER, gl::DEPTH_STENCIL_ATTACHMENT, depth, 0);
    step(b.CheckFramebufferStatus(gl::FRAMEBUFFER));
    b.AttachNewMultisampleTexture(gl::FRAMEBUFFER, gl::COLOR_ATTACHMENT0, 4, gl::RGBA8, 8, 6);  // a 2D one: layered beside not
    step(b.CheckFramebufferStatus(gl::FRAMEBUFFER));
    b.BindFramebuffer(gl::FRAMEBUFFER, 0);
  };
  CompareSteps(16, run);
}

TEST_CASE("buffer textures: TexBuffer's level state, bindings and errors as Mesa's", "[conformance]") {
  namespace gl = softgl;
  auto run = [](Backend& b, const auto& step) {
    auto level_state = [&](std::uint32_t buffer) {
      for (Enum pname : {gl::TEXTURE_WIDTH, gl::TEXTURE_HEIGHT, gl::TEXTURE_DEPTH, gl::TEXTURE_INTERNAL_FORMAT,
                         gl::TEXTURE_RED_SIZE, gl::TEXTURE_GREEN_SIZE, gl::TEXTURE_ALPHA_SIZE, gl::TEXTURE_DEPTH_SIZE,
                         gl::TEXTURE_COMPRESSED, gl::TEXTURE_SAMPLES})
        step(b.GetTexLevelParameter(gl::TEXTURE_BUFFER, 0, pname));
      step(b.GetTexLevelParameter(gl::TEXTURE_BUFFER, 0, gl::TEXTURE_BUFFER_DATA_STORE_BINDING) == int(buffer));
    };
    step(b.GetIntegers(gl::MAX_TEXTURE_BUFFER_SIZE, 1)[0] >= 65536);
    const std::vector<std::uint8_t> bytes(64, 7);
    const std::uint32_t buffer = b.NewBufferTexture(gl::RGBA8, bytes);
    step(0);
    step(b.GetIntegers(gl::TEXTURE_BINDING_BUFFER, 1)[0] != 0);
    step(b.GetIntegers(gl::TEXTURE_BUFFER, 1)[0] == std::int64_t(buffer));
    level_state(buffer);
    for (Enum format : {gl::R8, gl::R16, gl::R16F, gl::R32F, gl::RG8, gl::RG16, gl::RG16F, gl::RG32F, gl::RGBA16,
                        gl::RGBA16F, gl::RGBA32F}) {
      b.TexBuffer(gl::TEXTURE_BUFFER, format, buffer);
      step(0);
      level_state(buffer);
    }
    step(b.GetTexLevelParameter(gl::TEXTURE_BUFFER, 1, gl::TEXTURE_WIDTH));  // no level 1
    // Errors: each changes nothing.
    b.TexBuffer(gl::TEXTURE_2D, gl::R8, buffer);
    step(0);
    for (Enum format : {gl::RGB8, gl::SRGB8_ALPHA8, gl::DEPTH_COMPONENT32F, gl::RGB565, gl::RGBA}) {
      b.TexBuffer(gl::TEXTURE_BUFFER, format, buffer);
      step(0);
    }
    b.TexBuffer(gl::TEXTURE_BUFFER, gl::R8, buffer + 1000);
    step(0);
    level_state(buffer);
    b.GenerateMipmap(gl::TEXTURE_BUFFER);
    step(0);
    // Detached, attached again, its buffer deleted: the store stays the texture's.
    b.TexBuffer(gl::TEXTURE_BUFFER, gl::RGBA8, 0);
    step(0);
    level_state(0);
    b.TexBuffer(gl::TEXTURE_BUFFER, gl::RG8, buffer);
    step(0);
    b.DeleteBuffer(buffer);
    step(b.GetIntegers(gl::TEXTURE_BUFFER, 1)[0]);
    level_state(buffer);
  };
  CompareSteps(16, run);
}

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--report") {
    for (const SceneInfo& s : Scenes()) {
      Frame ours, mesa;
      std::string renderer, error;
      if (!RunScene(s, ours, mesa, renderer, error)) {
        std::printf("error: %s\n", error.c_str());
        return 1;
      }
      const Verdict v = Compare(s, ours, mesa);
      if (std::getenv("SOFTGL_CONFORMANCE_VERBOSE")) {
        int shown = 0;
        const int min_diff = std::atoi(std::getenv("SOFTGL_CONFORMANCE_VERBOSE"));
        for (std::size_t i = 0; i < ours.depth.size() && shown < 40; ++i) {
          int d = 0;
          for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(ours.rgba[i * 4 + c]) - int(mesa.rgba[i * 4 + c])));
          const bool depth_differs = std::fabs(ours.depth[i] - mesa.depth[i]) > std::ldexp(1.0f, -22);
          if (depth_differs) {
            ++shown;
            std::printf("  %s (%d, %d): depth softgl %.9g, mesa %.9g\n", s.name, int(i % ours.width),
                        int(i / ours.width), double(ours.depth[i]), double(mesa.depth[i]));
          } else if (d >= std::max(1, min_diff)) {
            ++shown;
            std::printf("  %s (%d, %d): softgl %d %d %d %d, mesa %d %d %d %d\n", s.name, int(i % ours.width),
                        int(i / ours.width), ours.rgba[i * 4], ours.rgba[i * 4 + 1], ours.rgba[i * 4 + 2],
                        ours.rgba[i * 4 + 3], mesa.rgba[i * 4], mesa.rgba[i * 4 + 1], mesa.rgba[i * 4 + 2],
                        mesa.rgba[i * 4 + 3]);
          }
        }
      }
      std::printf("| %s | %s | %s | %d | %d | %d | %d | %d | %d | %s |\n", s.name, renderer.c_str(),
                  CheckName(s.check), v.differing, v.max_diff, v.over, v.coverage_diff, v.depth_over, v.stencil_diff,
                  v.Pass() ? "pass" : "FAIL");
    }
    return 0;
  }
  return Catch::Session().run(argc, argv);
}

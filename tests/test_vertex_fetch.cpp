// Vertex fetch: every attribute type with and without normalization, strides, offsets, bounds, indices.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <vector>

#include "color_shader.h"
#include "helpers.h"
#include "pipeline.h"
#include "vertex_fetch.h"

using namespace softgl;
using detail::AttribSource;
using detail::FetchAttribute;

namespace {

template <class T>
AttribSource Source(const std::vector<T>& data, int components, Enum type, bool normalized, std::size_t stride = 0,
                    std::size_t offset = 0) {
  AttribSource s;
  s.data = reinterpret_cast<const std::uint8_t*>(data.data());
  s.size = data.size() * sizeof(T);
  s.offset = offset;
  s.components = components;
  s.type = type;
  s.normalized = normalized;
  s.stride = stride ? stride : sizeof(T) * std::size_t(components);
  return s;
}

}  // namespace

TEST_CASE("vertex fetch converts every type as OpenGL does", "[vertex_fetch]") {
  struct Row {
    Enum type;
    bool normalized;
    std::vector<std::uint8_t> bytes;  // two components
    float expect0, expect1;
  };
  auto bytes_of = [](auto a, auto b) {
    std::vector<std::uint8_t> v(sizeof a * 2);
    std::memcpy(v.data(), &a, sizeof a);
    std::memcpy(v.data() + sizeof a, &b, sizeof b);
    return v;
  };
  const Row rows[] = {
      {FLOAT, false, bytes_of(1.5f, -2.25f), 1.5f, -2.25f},
      {UNSIGNED_BYTE, false, bytes_of(std::uint8_t(200), std::uint8_t(3)), 200.0f, 3.0f},
      {UNSIGNED_BYTE, true, bytes_of(std::uint8_t(255), std::uint8_t(51)), 1.0f, 0.2f},
      {BYTE, false, bytes_of(std::int8_t(-128), std::int8_t(127)), -128.0f, 127.0f},
      {BYTE, true, bytes_of(std::int8_t(-128), std::int8_t(-127)), -1.0f, -1.0f},  // both clamp to -1
      {BYTE, true, bytes_of(std::int8_t(127), std::int8_t(0)), 1.0f, 0.0f},
      {UNSIGNED_SHORT, false, bytes_of(std::uint16_t(65535), std::uint16_t(7)), 65535.0f, 7.0f},
      {UNSIGNED_SHORT, true, bytes_of(std::uint16_t(65535), std::uint16_t(13107)), 1.0f, 0.2f},
      {SHORT, false, bytes_of(std::int16_t(-32768), std::int16_t(100)), -32768.0f, 100.0f},
      {SHORT, true, bytes_of(std::int16_t(-32768), std::int16_t(16384)), -1.0f, 16384.0f / 32767.0f},
      {UNSIGNED_INT, false, bytes_of(std::uint32_t(4000000000u), std::uint32_t(9)), 4000000000.0f, 9.0f},
      {UNSIGNED_INT, true, bytes_of(std::uint32_t(0xFFFFFFFFu), std::uint32_t(0)), 1.0f, 0.0f},
      {INT, false, bytes_of(std::int32_t(-5), std::int32_t(123456)), -5.0f, 123456.0f},
      {INT, true, bytes_of(std::int32_t(-2147483647 - 1), std::int32_t(2147483647)), -1.0f, 1.0f},
  };
  for (const Row& row : rows) {
    INFO("type 0x" << std::hex << row.type << " normalized " << row.normalized);
    const AttribSource s = Source(row.bytes, 2, row.type, row.normalized);
    const glm::vec4 v = FetchAttribute(s, 0);
    CHECK(v.x == Approx(row.expect0));
    CHECK(v.y == Approx(row.expect1));
    CHECK(v.z == 0.0f);  // missing components come from (0, 0, 0, 1)
    CHECK(v.w == 1.0f);
  }
}

TEST_CASE("vertex fetch reads half floats, doubles, the packed 2_10_10_10 types and BGRA order", "[vertex_fetch]") {
  SECTION("HALF_FLOAT: IEEE binary16, `normalized` ignored") {
    // 1.5, -2, 65504 (the largest half), infinity
    const std::vector<std::uint16_t> halves = {0x3E00, 0xC000, 0x7BFF, 0x7C00};
    for (bool normalized : {false, true}) {
      const glm::vec4 v = FetchAttribute(Source(halves, 4, HALF_FLOAT, normalized), 0);
      CHECK(v == glm::vec4(1.5f, -2.0f, 65504.0f, std::numeric_limits<float>::infinity()));
    }
  }
  SECTION("DOUBLE: the nearest float; beyond the largest float by half a unit, infinity") {
    const double largest = double(std::numeric_limits<float>::max());
    const std::vector<double> d = {0.1, -1e300, largest + std::ldexp(1.0, 102), largest + std::ldexp(1.0, 103)};
    const glm::vec4 v = FetchAttribute(Source(d, 4, DOUBLE, false), 0);
    CHECK(v.x == 0.1f);
    CHECK(v.y == -std::numeric_limits<float>::infinity());
    CHECK(v.z == std::numeric_limits<float>::max());       // rounds down to the largest float
    CHECK(v.w == std::numeric_limits<float>::infinity());  // the tie goes to even: infinity
    const std::vector<double> nan = {std::nan("")};
    CHECK(std::isnan(FetchAttribute(Source(nan, 1, DOUBLE, false), 0).x));
  }
  // x = 1, y = 511, z = -512 (0x200 as signed 10 bits), w = 3 (-1 as signed 2 bits)
  const std::vector<std::uint32_t> word = {1u | 511u << 10 | 0x200u << 20 | 3u << 30};
  auto packed = [&](Enum type, bool normalized, bool bgra) {
    AttribSource s = Source(word, 4, type, normalized);
    s.stride = 4;
    s.bgra = bgra;
    return FetchAttribute(s, 0);
  };
  SECTION("UNSIGNED_INT_2_10_10_10_REV: x in the low 10 bits ... w in the top 2") {
    CHECK(packed(UNSIGNED_INT_2_10_10_10_REV, false, false) == glm::vec4(1.0f, 511.0f, 512.0f, 3.0f));
    const glm::vec4 n = packed(UNSIGNED_INT_2_10_10_10_REV, true, false);
    CHECK(n.x == 1.0f / 1023.0f);
    CHECK(n.y == 511.0f / 1023.0f);
    CHECK(n.z == 512.0f / 1023.0f);
    CHECK(n.w == 1.0f);
  }
  SECTION("INT_2_10_10_10_REV: two's complement fields, normalized as max(c / (2^(b-1) - 1), -1)") {
    CHECK(packed(INT_2_10_10_10_REV, false, false) == glm::vec4(1.0f, 511.0f, -512.0f, -1.0f));
    const glm::vec4 n = packed(INT_2_10_10_10_REV, true, false);
    CHECK(n.x == 1.0f / 511.0f);
    CHECK(n.y == 1.0f);
    CHECK(n.z == -1.0f);  // -512 / 511 clamps
    CHECK(n.w == -1.0f);
  }
  SECTION("size BGRA: the element's first component is blue") {
    CHECK(packed(INT_2_10_10_10_REV, false, true) == glm::vec4(-512.0f, 511.0f, 1.0f, -1.0f));
    const std::vector<std::uint8_t> bytes = {10, 20, 30, 40};
    AttribSource s = Source(bytes, 4, UNSIGNED_BYTE, true);
    s.bgra = true;
    CHECK(FetchAttribute(s, 0) == glm::vec4(30.0f, 20.0f, 10.0f, 40.0f) / 255.0f);
  }
  SECTION("an element of a packed type is 4 bytes, whatever the component count") {
    CHECK(detail::AttributeBytes(INT_2_10_10_10_REV, 4) == 4);
    CHECK(detail::AttributeBytes(DOUBLE, 3) == 24);
    CHECK(detail::AttributeBytes(HALF_FLOAT, 3) == 6);
    AttribSource s = Source(word, 4, UNSIGNED_INT_2_10_10_10_REV, false);
    s.stride = 4;
    CHECK(FetchAttribute(s, 1) == glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // element 1 is past the 4-byte buffer
  }
}

TEST_CASE("vertex fetch fills missing components for sizes 1 to 4", "[vertex_fetch]") {
  const std::vector<float> data = {5, 6, 7, 8};
  for (int size = 1; size <= 4; ++size) {
    const glm::vec4 v = FetchAttribute(Source(data, size, FLOAT, false), 0);
    const glm::vec4 expect(5.0f, size > 1 ? 6.0f : 0.0f, size > 2 ? 7.0f : 0.0f, size > 3 ? 8.0f : 1.0f);
    CHECK(v == expect);
  }
}

TEST_CASE("vertex fetch honours stride and offset in an interleaved buffer", "[vertex_fetch]") {
  // Three vertices of {float x, y, z; uint8 r, g, b, a}: 16 bytes each.
  struct V {
    float p[3];
    std::uint8_t c[4];
  };
  std::vector<V> vertices = {{{1, 2, 3}, {255, 0, 0, 255}}, {{4, 5, 6}, {0, 255, 0, 128}}, {{7, 8, 9}, {0, 0, 255, 0}}};
  std::vector<std::uint8_t> raw(vertices.size() * sizeof(V));
  std::memcpy(raw.data(), vertices.data(), raw.size());
  const AttribSource pos = Source(raw, 3, FLOAT, false, sizeof(V), offsetof(V, p));
  const AttribSource col = Source(raw, 4, UNSIGNED_BYTE, true, sizeof(V), offsetof(V, c));
  CHECK(FetchAttribute(pos, 1) == glm::vec4(4, 5, 6, 1));
  CHECK(FetchAttribute(pos, 2) == glm::vec4(7, 8, 9, 1));
  const glm::vec4 c1 = FetchAttribute(col, 1);
  CHECK(c1.y == 1.0f);
  CHECK(c1.w == Approx(128.0f / 255.0f));
}

TEST_CASE("vertex fetch never reads past the end of a buffer", "[vertex_fetch]") {
  const std::vector<float> data = {1, 2, 3, 4, 5, 6};  // two vec3
  const AttribSource s = Source(data, 3, FLOAT, false);
  CHECK(FetchAttribute(s, 1) == glm::vec4(4, 5, 6, 1));
  CHECK(FetchAttribute(s, 2) == glm::vec4(0, 0, 0, 1));
  CHECK(FetchAttribute(s, 0xFFFFFFFFu) == glm::vec4(0, 0, 0, 1));
  AttribSource shifted = Source(data, 3, FLOAT, false, 0, 4);  // second element would end 4 bytes past the end
  CHECK(FetchAttribute(shifted, 0) == glm::vec4(2, 3, 4, 1));
  CHECK(FetchAttribute(shifted, 1) == glm::vec4(0, 0, 0, 1));
  AttribSource past = Source(data, 3, FLOAT, false, 0, 1000);
  CHECK(FetchAttribute(past, 0) == glm::vec4(0, 0, 0, 1));
}

TEST_CASE("indices of each type are read", "[vertex_fetch]") {
  const std::uint8_t b[] = {1, 200, 255};
  const std::uint16_t s[] = {1, 40000, 65535};
  const std::uint32_t i[] = {1, 70000, 4000000000u};
  std::uint32_t out[3];
  detail::ReadIndices(UNSIGNED_BYTE, b, 3, out);
  CHECK((out[0] == 1 && out[1] == 200 && out[2] == 255));
  detail::ReadIndices(UNSIGNED_SHORT, reinterpret_cast<const std::uint8_t*>(s), 3, out);
  CHECK((out[0] == 1 && out[1] == 40000 && out[2] == 65535));
  detail::ReadIndices(UNSIGNED_INT, reinterpret_cast<const std::uint8_t*>(i), 3, out);
  CHECK((out[0] == 1 && out[1] == 70000 && out[2] == 4000000000u));
}

namespace {
// Rows of lanes as FetchVertices writes them (stride 16), read back one vertex at a time.
struct Rows {
  static constexpr int kStride = 16;
  std::vector<float> data = std::vector<float>(std::size_t(kMaxVertexAttribs) * 4 * kStride, -1.0f);
  glm::vec4 At(int vertex, int attrib) const {
    const float* row = data.data() + std::size_t(attrib) * 4 * kStride + vertex;
    return glm::vec4(row[0], row[kStride], row[2 * kStride], row[3 * kStride]);
  }
};
}  // namespace

TEST_CASE("FetchVertices: enabled attributes per vertex, disabled ones left alone", "[vertex_fetch]") {
  const std::vector<float> positions = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  detail::FetchPlan plan;
  plan.attrib[0] = Source(positions, 3, FLOAT, false);
  plan.attrib[0].stride = 12;
  plan.enabled = 1u;
  plan.attrib[5] = Source(positions, 3, FLOAT, false);  // described but disabled: not read
  plan.current[5] = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
  CHECK(detail::FetchPlan{}.current[7] == glm::vec4(0, 0, 0, 1));  // the default current value
  Rows out;
  const std::uint32_t indices[3] = {2, 0, 1};
  detail::FetchVertices(plan, indices, 3, 0, out.data.data(), Rows::kStride);
  CHECK(out.At(0, 0) == glm::vec4(7, 8, 9, 1));
  CHECK(out.At(1, 0) == glm::vec4(1, 2, 3, 1));
  CHECK(out.At(2, 0) == glm::vec4(4, 5, 6, 1));
  for (int v = 3; v < 16; ++v) CHECK(out.At(v, 0) == glm::vec4(4, 5, 6, 1));  // padding: the last vertex
  for (int a = 1; a < kMaxVertexAttribs; ++a)  // the rows of disabled attributes are not written
    for (int v = 0; v < 16; ++v) CHECK(out.At(v, a) == glm::vec4(-1.0f));
}

TEST_CASE("FetchVertices: an attribute with a divisor reads element instance / divisor for every vertex",
          "[vertex_fetch]") {
  const std::vector<float> positions = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::vector<float> offsets = {10, 20, 30, 40};  // one vec2 per instance pair
  detail::FetchPlan plan;
  plan.attrib[0] = Source(positions, 3, FLOAT, false);
  plan.attrib[0].stride = 12;
  plan.attrib[1] = Source(offsets, 2, FLOAT, false);
  plan.attrib[1].stride = 8;
  plan.attrib[1].divisor = 2;
  plan.enabled = 3u;
  Rows out;
  const std::uint32_t indices[3] = {2, 0, 1};
  for (std::uint32_t instance : {0u, 1u, 2u, 3u, 4u}) {
    detail::FetchVertices(plan, indices, 3, instance, out.data.data(), Rows::kStride);
    // Instances 0 and 1 read element 0, 2 and 3 element 1, 4 element 2: past the end, (0, 0, 0, 1).
    const glm::vec4 want = instance < 2   ? glm::vec4(10, 20, 0, 1)
                           : instance < 4 ? glm::vec4(30, 40, 0, 1)
                                          : glm::vec4(0, 0, 0, 1);
    for (int v = 0; v < 3; ++v) CHECK(out.At(v, 1) == want);
    CHECK(out.At(0, 0) == glm::vec4(7, 8, 9, 1));  // the per-vertex attribute is unchanged by the instance
  }
}

TEST_CASE("a disabled attribute's value reaches every vertex of a large draw", "[vertex_fetch]") {
  // 3000 points (three vertex jobs of 1,024) on a 64 x 64 target; attribute 1 is disabled, so every point takes
  // its current value as colour.
  struct Shader : softgl::Shader<Shader, testing::Vec4Varyings> {
    void Vertex(const VertexIn& in, VertexOut<testing::Vec4Varyings>& out) const {
      out.position = in.attrib[0];
      out.varyings.value = in.attrib[1];
    }
    bool Fragment(const FragmentIn<testing::Vec4Varyings>& in, FragmentOut& out) const {
      out.color[0] = in.varyings.value;
      return true;
    }
  };
  Context gl(64, 64);
  std::vector<glm::vec4> points;
  for (int i = 0; i < 3000; ++i)
    points.push_back(glm::vec4((float(i % 64) + 0.5f) / 32.0f - 1.0f, (float(i / 64 % 64) + 0.5f) / 32.0f - 1.0f, 0, 1));
  testing::MakeVertexArray(gl, points);
  gl.DisableVertexAttribArray(1);
  gl.VertexAttrib4f(1, 1.0f, 0.0f, 1.0f, 1.0f);
  Shader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(POINTS, 0, 3000);
  const softgl::Image img = gl.ReadPixels();
  int magenta = 0;
  for (std::size_t i = 0; i < img.rgba.size(); i += 4)
    magenta += img.rgba[i] == 255 && img.rgba[i + 1] == 0 && img.rgba[i + 2] == 255;
  CHECK(magenta == 3000);  // 3000 distinct pixels
}

TEST_CASE("an indexed draw fetches and shades each distinct index once", "[vertex_fetch]") {
  // Counts vertex shader invocations (the count lives outside the shader: draws run on copies of it) and records
  // which vertex each was.
  struct Counting : softgl::Shader<Counting, testing::NoVaryings> {
    std::atomic<int>* calls = nullptr;
    std::vector<std::atomic<int>>* per_vertex = nullptr;
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      ++*calls;
      ++(*per_vertex)[std::size_t(in.vertex_id)];
      out.position = in.attrib[0];
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
      out.color[0] = glm::vec4(1.0f);
      return true;
    }
  };
  std::atomic<int> calls{0};
  std::vector<std::atomic<int>> per_vertex(300);
  Counting shader;
  shader.calls = &calls;
  shader.per_vertex = &per_vertex;
  Context gl(16, 16);
  gl.UseProgram(shader);
  std::vector<glm::vec4> positions(300);
  for (int i = 0; i < 300; ++i) positions[std::size_t(i)] = glm::vec4(float(i % 17) / 8.0f - 1.0f, float(i / 17) / 8.0f - 1.0f, 0, 1);
  testing::MakeVertexArray(gl, positions);
  // 600 indices over every third vertex of 0 .. 297 (100 distinct), each used six times, out of order.
  std::vector<std::uint32_t> indices;
  for (int r = 0; r < 6; ++r)
    for (int k = 0; k < 100; ++k) indices.push_back(std::uint32_t(3 * ((k * 37 + r * 11) % 100)));
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
  gl.DrawElement(TRIANGLES, int(indices.size()), UNSIGNED_INT, 0);
  gl.Finish();
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(calls == 100);
  for (int i = 0; i < 300; ++i) CHECK(per_vertex[std::size_t(i)] == (i % 3 == 0 ? 1 : 0));
  // Again, then with every index moved by one: the table of first uses starts empty for each draw.
  gl.DrawElement(TRIANGLES, int(indices.size()), UNSIGNED_INT, 0);
  for (std::uint32_t& i : indices) ++i;
  gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
  gl.DrawElement(TRIANGLES, int(indices.size()), UNSIGNED_INT, 0);
  gl.Finish();
  CHECK(calls == 300);
  for (int i = 0; i < 300; ++i) CHECK(per_vertex[std::size_t(i)] == (i % 3 == 0 ? 2 : i % 3 == 1 ? 1 : 0));
}

// The triangles `indices` make of `positions`, coloured by `colors` (attribute 1), drawn with `shader` and the
// depth test into a w x h target: in one DrawElement (`indexed`), or with their vertices copied and drawn in
// DrawArrays of 900 vertices.
template <class S>
softgl::Image DrawTriangles(S& shader, int w, int h, bool indexed, const std::vector<glm::vec4>& positions,
                            const std::vector<glm::vec4>& colors, const std::vector<std::uint32_t>& indices) {
  Context gl(w, h);
  gl.Enable(DEPTH_TEST);
  gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.UseProgram(shader);
  if (indexed) {
    testing::MakeVertexArray(gl, positions, colors);
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
    gl.DrawElement(TRIANGLES, int(indices.size()), UNSIGNED_INT, 0);
  } else {
    std::vector<glm::vec4> p, c;
    for (std::uint32_t i : indices) {
      p.push_back(positions[i]);
      c.push_back(colors[i]);
    }
    testing::MakeVertexArray(gl, p, c);
    for (int first = 0; first < int(p.size()); first += 900) gl.DrawArrays(TRIANGLES, first, std::min(900, int(p.size()) - first));
  }
  CHECK(gl.GetError() == NO_ERROR);
  return gl.ReadPixels();
}

TEST_CASE("an indexed draw of a mesh shades its index range once and draws what the same triangles draw unindexed",
          "[vertex_fetch]") {
  // A 30 x 30 grid of vertices (numbers 40 .. 940, one of them, 490, used by no triangle), 1,682 triangles: its
  // indices are packed close together (the range a third of the elements at most), so the whole range is shaded,
  // each vertex once, the unused one too. The triangles are then binned by their vertices' numbers (more than one
  // batch's worth); a few cross the near plane and are clipped. The image must be the bytes of the same triangles
  // drawn unindexed in draws of 300 (their vertices copied into shared batches).
  struct Counting : softgl::Shader<Counting, testing::Vec4Varyings> {
    std::vector<std::atomic<int>>* per_vertex = nullptr;
    void Vertex(const VertexIn& in, VertexOut<testing::Vec4Varyings>& out) const {
      if (per_vertex) ++(*per_vertex)[std::size_t(in.vertex_id)];
      out.position = in.attrib[0];
      out.varyings.value = in.attrib[1];
    }
    bool Fragment(const FragmentIn<testing::Vec4Varyings>& in, FragmentOut& out) const {
      out.color[0] = in.varyings.value;
      return true;
    }
  };
  constexpr int kSide = 30, kFirst = 40, kUnused = 490, kVertices = kFirst + kSide * kSide + 1;
  auto number = [](int node) { return kFirst + node + (kFirst + node >= kUnused ? 1 : 0); };
  std::vector<glm::vec4> positions(kVertices, glm::vec4(0.0f)), colors(kVertices, glm::vec4(0.0f));
  for (int node = 0; node < kSide * kSide; ++node) {
    const int i = node % kSide, j = node / kSide;
    const float x = float(i) / float(kSide - 1) * 1.8f - 0.9f + 0.013f * float(j % 3);
    const float y = float(j) / float(kSide - 1) * 1.8f - 0.9f + 0.011f * float(i % 4);
    const float z = (i == 7 && j > 10 && j < 14) ? -2.5f : 0.3f * float((i * 7 + j * 3) % 5) / 5.0f;  // (a few behind the near plane)
    positions[std::size_t(number(node))] = glm::vec4(x, y, z, 1.0f);
    colors[std::size_t(number(node))] = glm::vec4(float(i) / kSide, float(j) / kSide, float((i + j) % 7) / 7.0f, 1.0f);
  }
  std::vector<std::uint32_t> indices;
  for (int j = 0; j + 1 < kSide; ++j)
    for (int i = 0; i + 1 < kSide; ++i) {
      const int a = j * kSide + i, b = a + 1, c = a + kSide, d = c + 1;
      for (int node : {a, b, d, a, d, c}) indices.push_back(std::uint32_t(number(node)));
    }
  REQUIRE(indices.size() == 1682 * 3);
  std::vector<std::atomic<int>> per_vertex(kVertices);
  Counting shader;
  shader.per_vertex = &per_vertex;
  auto render = [&](bool indexed) { return DrawTriangles(shader, 96, 80, indexed, positions, colors, indices); };
  const softgl::Image indexed = render(true);
  int wrong = 0;
  for (int i = 0; i < kVertices; ++i) wrong += per_vertex[std::size_t(i)].exchange(0) != (i >= kFirst ? 1 : 0);
  CHECK(wrong == 0);
  shader.per_vertex = nullptr;
  const softgl::Image unindexed = render(false);
  CHECK(indexed.rgba == unindexed.rgba);
  // The picture is the grid's colours, not the clear colour alone.
  std::set<std::uint32_t> colours;
  for (std::size_t k = 0; k < indexed.rgba.size(); k += 4)
    colours.insert(std::uint32_t(indexed.rgba[k]) | std::uint32_t(indexed.rgba[k + 1]) << 8 | std::uint32_t(indexed.rgba[k + 2]) << 16);
  CHECK(colours.size() > 500);
}

TEST_CASE("an indexed draw larger than a piece draws each piece's own triangles", "[vertex_fetch]") {
  // A 130 x 130 grid, 33,282 triangles: 99,846 elements, three pieces of kDrawChunk elements at most, each read
  // from its place in the draw's elements. The image must be the bytes of the same triangles drawn unindexed in
  // draws of 900 vertices (each a piece of its own).
  constexpr int kSide = 130;
  std::vector<glm::vec4> positions, colors;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const float x = float(i) / float(kSide - 1) * 1.9f - 0.95f + 0.004f * float(j % 3);
      const float y = float(j) / float(kSide - 1) * 1.9f - 0.95f + 0.003f * float(i % 4);
      positions.emplace_back(x, y, 0.4f * float((i * 5 + j * 3) % 7) / 7.0f - 0.2f, 1.0f);
      colors.emplace_back(float(i) / kSide, float(j) / kSide, float((i * 3 + j) % 11) / 11.0f, 1.0f);
    }
  std::vector<std::uint32_t> indices;
  for (int j = 0; j + 1 < kSide; ++j)
    for (int i = 0; i + 1 < kSide; ++i) {
      const std::uint32_t a = std::uint32_t(j * kSide + i), b = a + 1, c = a + kSide, d = c + 1;
      for (std::uint32_t v : {a, b, d, a, d, c}) indices.push_back(v);
    }
  REQUIRE(indices.size() > 2 * std::size_t(softgl::detail::kDrawChunk));
  testing::ColorShader shader;
  auto render = [&](bool indexed) { return DrawTriangles(shader, 160, 144, indexed, positions, colors, indices); };
  const softgl::Image indexed = render(true), unindexed = render(false);
  CHECK(indexed.rgba == unindexed.rgba);
  std::set<std::uint32_t> colours;  // the grid's colours, not the clear colour alone
  for (std::size_t k = 0; k < indexed.rgba.size(); k += 4)
    colours.insert(std::uint32_t(indexed.rgba[k]) | std::uint32_t(indexed.rgba[k + 1]) << 8 | std::uint32_t(indexed.rgba[k + 2]) << 16);
  CHECK(colours.size() > 1000);
}

TEST_CASE("a DrawArrays larger than a piece shades each of its vertices once, with its own gl_VertexID",
          "[vertex_fetch]") {
  struct Counting : softgl::Shader<Counting, testing::NoVaryings> {
    std::vector<std::atomic<int>>* per_vertex = nullptr;
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      ++(*per_vertex)[std::size_t(in.vertex_id)];
      out.position = glm::vec4(2.0f, 2.0f, 0.0f, 1.0f);  // outside: only the shading is counted
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
      out.color[0] = glm::vec4(1.0f);
      return true;
    }
  };
  constexpr int kFirst = 7, kCount = 120000;  // more than two pieces
  std::vector<std::atomic<int>> per_vertex(kFirst + kCount + 8);
  Counting shader;
  shader.per_vertex = &per_vertex;
  Context gl(8, 8);
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, std::vector<glm::vec4>(std::size_t(kFirst + kCount + 8), glm::vec4(0.0f)));
  for (Enum mode : {TRIANGLES, POINTS}) {
    gl.DrawArrays(mode, kFirst, kCount);
    gl.Finish();
    CHECK(gl.GetError() == NO_ERROR);
    int wrong = 0;
    for (int i = 0; i < kFirst + kCount + 8; ++i) {
      const bool drawn = i >= kFirst && i < kFirst + kCount;
      wrong += per_vertex[std::size_t(i)].exchange(0) != (drawn ? 1 : 0);
    }
    CHECK(wrong == 0);
  }
}

// ---- Integer attributes (VertexAttribIPointer, VertexAttribI*) ------------------------------------------------------

TEST_CASE("integer attributes keep every type's integers exactly, sign- or zero-extended", "[vertex_fetch]") {
  const auto ints = [](const glm::vec4& v) {
    glm::ivec4 i;
    std::memcpy(&i, &v, sizeof i);
    return i;
  };
  const std::vector<std::int8_t> b = {-128, 127, -1, 5};
  const std::vector<std::int16_t> s = {-32768, 32767, -1, 300};
  const std::vector<std::int32_t> i = {INT32_MIN, INT32_MAX, -1, 0x7F800001};  // (the last: a NaN's bits as a float)
  AttribSource src = Source(b, 4, BYTE, false);
  src.integer = true;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(-128, 127, -1, 5));
  src.type = UNSIGNED_BYTE;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(128, 127, 255, 5));
  src = Source(s, 4, SHORT, false);
  src.integer = true;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(-32768, 32767, -1, 300));
  src.type = UNSIGNED_SHORT;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(32768, 32767, 65535, 300));
  src = Source(i, 4, INT, false);
  src.integer = true;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(INT32_MIN, INT32_MAX, -1, 0x7F800001));
  src.type = UNSIGNED_INT;
  CHECK(ints(FetchAttribute(src, 0)) == glm::ivec4(INT32_MIN, INT32_MAX, -1, 0x7F800001));
  // Missing components and elements past the buffer: (0, 0, 0, 1) as integers.
  src = Source(i, 2, INT, false);
  src.integer = true;
  CHECK(ints(FetchAttribute(src, 1)) == glm::ivec4(-1, 0x7F800001, 0, 1));
  CHECK(ints(FetchAttribute(src, 2)) == glm::ivec4(0, 0, 0, 1));
}

namespace {
// Points whose colour is (x & 255, y & 255, z & 255, w & 255) / 255 of integer attribute 1 (wide), or of
// attribute 1's integers less attribute 2's (scalar).
struct WideIntVary {
  softgl::vec4 color;
};
struct WideIntShader : softgl::Shader<WideIntShader, WideIntVary> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideIntVary>& out) const {
    out.position = in.attrib[0];
    const auto byte = [&](int c) { return softgl::Float(in.AttribI(1, c) & 255) / 255.0f; };
    out.varyings.color = softgl::vec4(byte(0), byte(1), byte(2), byte(3));
  }
  void Fragment(const softgl::FragmentLanes<WideIntVary>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};
struct ScalarIntShader : softgl::Shader<ScalarIntShader, testing::Vec4Varyings> {
  void Vertex(const VertexIn& in, VertexOut<testing::Vec4Varyings>& out) const {
    out.position = in.attrib[0];
    out.varyings.value = glm::vec4((in.AttribUI(1) - in.AttribUI(2)) & 255u) / 255.0f;
  }
  bool Fragment(const FragmentIn<testing::Vec4Varyings>& in, FragmentOut& out) const {
    out.color[0] = in.varyings.value;
    return true;
  }
};
}  // namespace

TEST_CASE("integer attributes reach the vertex stage as integers, wide and scalar, from arrays and current values",
          "[vertex_fetch]") {
  Context gl(8, 1);
  std::vector<glm::vec4> points;
  for (int x = 0; x < 8; ++x) points.push_back(testing::WindowToClip(float(x) + 0.5f, 0.5f, 8, 1));
  testing::MakeVertexArray(gl, points);
  // Attribute 1: four UNSIGNED_SHORTs a vertex, values above 2^8 so that only exact integers give the bytes.
  std::vector<std::uint16_t> words;
  for (int x = 0; x < 8; ++x)
    for (int c = 0; c < 4; ++c) words.push_back(std::uint16_t(0xAB00 + x * 16 + c * 3 + 1));
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(words.size() * 2), words.data());
  gl.VertexAttribIPointer(1, 4, UNSIGNED_SHORT, 0, 0);
  gl.EnableVertexAttribArray(1);
  int integer = -1;
  gl.GetVertexAttribiv(1, VERTEX_ATTRIB_ARRAY_INTEGER, &integer);
  CHECK(integer == 1);
  const auto check = [&](auto want) {
    const softgl::Image img = gl.ReadPixels();
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 4; ++c) {
        CAPTURE(x, c);
        CHECK(int(img.rgba[std::size_t(x * 4 + c)]) == want(x, c));
      }
  };
  WideIntShader wide;
  gl.UseProgram(wide);
  gl.DrawArrays(POINTS, 0, 8);
  check([](int x, int c) { return (x * 16 + c * 3 + 1) & 255; });
  // Scalar: attribute 1 less attribute 2, the latter disabled with a current value given by VertexAttribI4ui.
  ScalarIntShader scalar;
  gl.UseProgram(scalar);
  gl.DisableVertexAttribArray(2);
  gl.VertexAttribI4ui(2, 1, 2, 3, 0xFFFFFFFFu);
  gl.DrawArrays(POINTS, 0, 8);
  check([](int x, int c) { return (x * 16 + c * 3 + 1 - (c == 3 ? -1 : c + 1)) & 255; });
  // The current value of a disabled integer attribute, read wide: VertexAttribI4i.
  gl.DisableVertexAttribArray(1);
  gl.VertexAttribI4i(1, -1, 257, 0x12345678, 7);
  gl.UseProgram(wide);
  gl.DrawArrays(POINTS, 0, 8);
  check([](int, int c) { return c == 0 ? 255 : c == 1 ? 1 : c == 2 ? 0x78 : 7; });
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("VertexAttribIPointer and VertexAttribI*: state queries and OpenGL's errors", "[vertex_fetch][errors]") {
  Context gl(4, 4);
  gl.VertexAttribIPointer(0, 4, INT, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);  // no vertex array
  gl.BindVertexArray(gl.GenVertexArray());
  gl.VertexAttribIPointer(0, 4, INT, 0, 16);
  CHECK(gl.GetError() == INVALID_OPERATION);  // no ARRAY_BUFFER with an offset
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  gl.VertexAttribIPointer(0, 4, FLOAT, 0, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.VertexAttribIPointer(0, 4, INT_2_10_10_10_REV, 0, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.VertexAttribIPointer(0, int(BGRA), UNSIGNED_BYTE, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribIPointer(0, 0, INT, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribIPointer(0, 4, INT, -4, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribIPointer(kMaxVertexAttribs, 4, INT, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribIPointer(3, 2, SHORT, 12, 4);
  CHECK(gl.GetError() == NO_ERROR);
  int v = -1;
  gl.GetVertexAttribiv(3, VERTEX_ATTRIB_ARRAY_INTEGER, &v);
  CHECK(v == 1);
  gl.GetVertexAttribiv(3, VERTEX_ATTRIB_ARRAY_TYPE, &v);
  CHECK(v == int(SHORT));
  gl.GetVertexAttribiv(3, VERTEX_ATTRIB_ARRAY_NORMALIZED, &v);
  CHECK(v == 0);
  gl.VertexAttributePointer(3, 2, SHORT, false, 12, 4);  // the float form again
  gl.GetVertexAttribiv(3, VERTEX_ATTRIB_ARRAY_INTEGER, &v);
  CHECK(v == 0);
  // Current values: the forms, the components they leave as (0, 0, 1), signed and unsigned.
  int iv[4];
  std::uint32_t uv[4];
  gl.VertexAttribI2i(5, -7, 9);
  gl.GetVertexAttribIiv(5, CURRENT_VERTEX_ATTRIB, iv);
  CHECK((iv[0] == -7 && iv[1] == 9 && iv[2] == 0 && iv[3] == 1));
  gl.VertexAttribI4ui(5, 4000000000u, 1, 2, 3);
  gl.GetVertexAttribIuiv(5, CURRENT_VERTEX_ATTRIB, uv);
  CHECK((uv[0] == 4000000000u && uv[1] == 1 && uv[2] == 2 && uv[3] == 3));
  const std::int8_t bytes[4] = {-1, -2, -3, -4};
  gl.VertexAttribI4bv(5, bytes);
  gl.GetVertexAttribIiv(5, CURRENT_VERTEX_ATTRIB, iv);
  CHECK((iv[0] == -1 && iv[3] == -4));
  const std::uint16_t shorts[4] = {65535, 1, 2, 3};
  gl.VertexAttribI4usv(5, shorts);
  gl.GetVertexAttribIuiv(5, CURRENT_VERTEX_ATTRIB, uv);
  CHECK(uv[0] == 65535u);
  gl.VertexAttrib4f(5, 1.5f, 0, 0, 1);  // floats again
  float fv[4];
  gl.GetVertexAttribfv(5, CURRENT_VERTEX_ATTRIB, fv);
  CHECK(fv[0] == 1.5f);
  CHECK(gl.GetError() == NO_ERROR);
  gl.VertexAttribI4i(kMaxVertexAttribs, 0, 0, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribI4iv(0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
}

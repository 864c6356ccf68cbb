// Tests of the geometry stage: primitives in, new vertices and strips out (EmitVertex / EndPrimitive per lane, the
// max_vertices cap), every input mode and the adjacency orders, gl_PrimitiveIDIn across pieces and restarts,
// instanced invocations in order, gl_Layer, transform feedback and PRIMITIVES_GENERATED of its output, a pass-through
// stage drawing what no stage draws, and OpenGL's errors.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "helpers.h"

using namespace softgl;

namespace {

struct In {
  vec4 color;
  Float id;  // gl_VertexID
};

// What RecordShader emits of each input vertex: (gl_VertexID, gl_PrimitiveIDIn, gl_InvocationID, gl_InstanceID,
// the vertex's place in gl_in).
struct Record {
  vec4 ids;
  Float place;
};

// The vertex stage every shader here shares: position from attribute 0, colour from attribute 1.
template <class Derived, class Out>
struct Base : Shader<Derived, In, Out> {
  void Vertex(const VertexLanes& in, VertexLanesOut<In>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.varyings.id = Float(in.vertex_id);
  }
};

// One point per input vertex, in gl_in's order, recording what the stage was given; `Input` is its input mode.
template <Enum Input, int Invocations = 1>
struct RecordShader : Base<RecordShader<Input, Invocations>, Record> {
  static constexpr GeometryLayout kGeometry{Input, POINTS, 6, Invocations};
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<Record>& out) const {
    for (int k = 0; k < in.vertices; ++k) {
      out.position = in.vertex[k].position;
      out.varyings.ids = vec4(in.vertex[k].varyings.id, Float(in.primitive_id), Float(in.invocation_id),
                              Float(in.instance_id));
      out.varyings.place = Float(float(k));
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<Record>&, FragmentLanesOut& out) const { out.color[0] = vec4(1.0f); }
};

struct Vertex {
  glm::vec4 pos, color;
};

// A context of `size` squared with the vertices `v` in a vertex array (attributes 0 and 1).
struct Scene {
  Context gl;
  explicit Scene(const std::vector<Vertex>& v, int size = 16, int threads = 1) : gl(size, size, Context::Options{threads}) {
    gl.BindVertexArray(gl.GenVertexArray());
    gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(v.size() * sizeof(Vertex)), v.data());
    gl.VertexAttributePointer(0, 4, FLOAT, false, sizeof(Vertex), 0);
    gl.VertexAttributePointer(1, 4, FLOAT, false, sizeof(Vertex), sizeof(glm::vec4));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
  }
  // `program` in use, recording the `count` varyings `what` (interleaved) into a new buffer of `bytes`, bound to
  // binding 0; returns the buffer.
  template <class Program>
  std::uint32_t Feed(Program& program, int count, const FeedbackVarying* what, std::size_t bytes) {
    gl.UseProgram(program);
    gl.TransformFeedbackVaryings(program, count, what, INTERLEAVED_ATTRIBS);
    const std::uint32_t buffer = gl.GenBuffer();
    gl.BindBuffer(TRANSFORM_FEEDBACK_BUFFER, buffer);
    gl.BufferData(TRANSFORM_FEEDBACK_BUFFER, std::ptrdiff_t(bytes), nullptr);
    gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    return buffer;
  }
  // Records `program`'s Record varyings (5 floats a vertex) while `draw` runs; returns them, one row per vertex.
  template <class Program, class Draw>
  std::vector<std::vector<float>> Recorded(Program& program, Draw&& draw, std::size_t room = 4096) {
    const FeedbackVarying what[] = {Program::Capture(&Record::ids, "ids"), Program::Capture(&Record::place, "place")};
    const std::uint32_t buffer = Feed(program, 2, what, room * 5 * sizeof(float));
    const std::uint32_t written = gl.GenQuery();
    gl.BeginQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
    gl.BeginTransformFeedback(POINTS);
    draw();
    gl.EndTransformFeedback();
    gl.EndQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    std::uint32_t n = 0;
    gl.GetQueryObjectuiv(written, QUERY_RESULT, &n);
    std::vector<float> all(std::size_t(n) * 5);
    gl.BindBuffer(COPY_READ_BUFFER, buffer);
    gl.GetBufferSubData(COPY_READ_BUFFER, 0, std::ptrdiff_t(all.size() * sizeof(float)), all.data());
    std::vector<std::vector<float>> rows;
    for (std::size_t i = 0; i < n; ++i) rows.emplace_back(all.begin() + std::ptrdiff_t(i * 5), all.begin() + std::ptrdiff_t(i * 5 + 5));
    return rows;
  }
};

std::vector<Vertex> Line(int n) {
  std::vector<Vertex> v;
  for (int i = 0; i < n; ++i) v.push_back({glm::vec4(-0.9f + 1.8f * float(i % 97) / 97.0f, 0.0f, 0.0f, 1.0f), glm::vec4(1.0f)});
  return v;
}

// The gl_VertexID of each vertex recorded.
std::vector<int> Ids(const std::vector<std::vector<float>>& rows) {
  std::vector<int> ids;
  for (const auto& r : rows) ids.push_back(int(r[0]));
  return ids;
}

}  // namespace

TEST_CASE("the geometry stage reads each mode's primitives in gl_in's order, adjacency included", "[geometry]") {
  Scene s(Line(16));
  SECTION("points, lines and triangles in their lists, strips, loops and fans") {
    RecordShader<POINTS> points;
    CHECK(Ids(s.Recorded(points, [&] { s.gl.DrawArrays(POINTS, 2, 3); })) == std::vector<int>{2, 3, 4});
    RecordShader<LINES> lines;
    CHECK(Ids(s.Recorded(lines, [&] { s.gl.DrawArrays(LINE_LOOP, 0, 3); })) == std::vector<int>{0, 1, 1, 2, 2, 0});
    RecordShader<TRIANGLES> triangles;
    CHECK(Ids(s.Recorded(triangles, [&] { s.gl.DrawArrays(TRIANGLE_STRIP, 0, 5); })) ==
          std::vector<int>{0, 1, 2, 2, 1, 3, 2, 3, 4});
    CHECK(Ids(s.Recorded(triangles, [&] { s.gl.DrawArrays(TRIANGLE_FAN, 0, 4); })) ==
          std::vector<int>{0, 1, 2, 0, 2, 3});
  }
  SECTION("lines with adjacency: the line's ends at 1 and 2") {
    RecordShader<LINES_ADJACENCY> adjacency;
    CHECK(Ids(s.Recorded(adjacency, [&] { s.gl.DrawArrays(LINES_ADJACENCY, 0, 9); })) ==
          std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7});
    CHECK(Ids(s.Recorded(adjacency, [&] { s.gl.DrawArrays(LINE_STRIP_ADJACENCY, 0, 6); })) ==
          std::vector<int>{0, 1, 2, 3, 1, 2, 3, 4, 2, 3, 4, 5});
  }
  SECTION("triangles with adjacency: OpenGL's table 10.1 for strips, first, middle and last triangles") {
    RecordShader<TRIANGLES_ADJACENCY> adjacency;
    CHECK(Ids(s.Recorded(adjacency, [&] { s.gl.DrawArrays(TRIANGLES_ADJACENCY, 0, 13); })) ==
          std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    // One triangle: 0 2 4, adjacent 1 5 3.
    CHECK(Ids(s.Recorded(adjacency, [&] { s.gl.DrawArrays(TRIANGLE_STRIP_ADJACENCY, 0, 6); })) ==
          std::vector<int>{0, 1, 2, 5, 4, 3});
    // Four triangles of 12 vertices: first (0 2 4; 1 6 3), odd (4 2 6; 0 5 8), even (4 6 8; 2 10 7), last odd
    // (8 6 10; 4 9 11).
    CHECK(Ids(s.Recorded(adjacency, [&] { s.gl.DrawArrays(TRIANGLE_STRIP_ADJACENCY, 0, 12); })) ==
          std::vector<int>{0, 1, 2, 6, 4, 3, 4, 0, 2, 5, 6, 8, 4, 2, 6, 10, 8, 7, 8, 4, 6, 9, 10, 11});
  }
  CHECK(s.gl.GetError() == NO_ERROR);
}

TEST_CASE("gl_PrimitiveIDIn counts a draw's primitives, across instances, restarts and pieces", "[geometry]") {
  Scene s(Line(16));
  RecordShader<TRIANGLES> shader;
  auto primitive_ids = [](const std::vector<std::vector<float>>& rows) {
    std::vector<int> ids;
    for (std::size_t i = 0; i < rows.size(); i += 3) ids.push_back(int(rows[i][1]));
    return ids;
  };
  auto instances = [](const std::vector<std::vector<float>>& rows) {
    std::vector<int> ids;
    for (std::size_t i = 0; i < rows.size(); i += 3) ids.push_back(int(rows[i][3]));
    return ids;
  };
  const auto rows = s.Recorded(shader, [&] { s.gl.DrawArraysInstanced(TRIANGLE_STRIP, 0, 5, 2); });
  CHECK(primitive_ids(rows) == std::vector<int>{0, 1, 2, 0, 1, 2});
  CHECK(instances(rows) == std::vector<int>{0, 0, 0, 1, 1, 1});
  // A restart between two strips: the count goes on.
  const std::uint8_t elements[] = {0, 1, 2, 3, 255, 4, 5, 6, 7};
  s.gl.BindBuffer(ELEMENT_ARRAY_BUFFER, s.gl.GenBuffer());
  s.gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof elements, elements);
  s.gl.Enable(PRIMITIVE_RESTART);
  s.gl.PrimitiveRestartIndex(255);
  CHECK(primitive_ids(s.Recorded(shader, [&] { s.gl.DrawElement(TRIANGLE_STRIP, 9, UNSIGNED_BYTE, 0); })) ==
        std::vector<int>{0, 1, 2, 3});
  s.gl.Disable(PRIMITIVE_RESTART);
  // A draw larger than a piece (MAX_ELEMENTS_VERTICES): the ids of its last triangles.
  int piece = 0;
  s.gl.GetIntegerv(MAX_ELEMENTS_VERTICES, &piece);
  const int n = piece * 2 + 10;
  std::vector<Vertex> many = Line(n);
  Scene big(many);
  const auto strip = big.Recorded(shader, [&] { big.gl.DrawArrays(TRIANGLE_STRIP, 0, n); }, std::size_t(n) * 3);
  REQUIRE(strip.size() == std::size_t(n - 2) * 3);
  std::vector<int> want(std::size_t(n - 2));
  for (int i = 0; i < n - 2; ++i) want[std::size_t(i)] = i;
  CHECK(primitive_ids(strip) == want);
  const auto fan = big.Recorded(shader, [&] { big.gl.DrawArrays(TRIANGLE_FAN, 0, n); }, std::size_t(n) * 3);
  CHECK(primitive_ids(fan) == want);
  CHECK(s.gl.GetError() == NO_ERROR);
  CHECK(big.gl.GetError() == NO_ERROR);
}

TEST_CASE("instanced geometry stages run every invocation of a primitive before the next primitive", "[geometry]") {
  for (int threads : {1, 3}) {
    Scene s(Line(40), 16, threads);
    RecordShader<LINES, 3> shader;
    const auto rows = s.Recorded(shader, [&] { s.gl.DrawArrays(LINES, 0, 40); });
    REQUIRE(rows.size() == 20 * 3 * 2);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::size_t line = r / 6, invocation = r / 2 % 3, end = r % 2;
      INFO(r);
      CHECK(rows[r][0] == float(line * 2 + end));
      CHECK(rows[r][1] == float(line));
      CHECK(rows[r][2] == float(invocation));
      CHECK(rows[r][4] == float(end));
    }
  }
}

namespace {

struct Plain {
  vec4 color;
};

// Lane by lane, different numbers of vertices in strips of different lengths: point i emits i % 5 vertices, a
// strip ended after its second; points 4, 9, ... try 9 where 8 fit (the ninth is dropped).
struct DivergentShader : Base<DivergentShader, Record> {
  static constexpr GeometryLayout kGeometry{POINTS, LINE_STRIP, 8};
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<Record>& out) const {
    const Float id = in.vertex[0].varyings.id;
    const Float emits = id - floor(id / 5.0f) * 5.0f;  // id % 5
    for (int k = 0; k < 4; ++k) {
      out.position = in.vertex[0].position;
      out.varyings.ids = vec4(id, Float(float(k)), 0.0f, 0.0f);
      out.varyings.place = Float(float(k));
      out.EmitVertex(Float(float(k)) < emits);
      if (k == 1) out.EndPrimitive();
    }
    const Bool last = emits == 4.0f;  // points 4, 9, ... go on to nine vertices
    for (int k = 4; k < 9; ++k) {
      out.varyings.ids = vec4(id, Float(float(k)), 0.0f, 0.0f);
      out.EmitVertex(last);
    }
  }
  void Fragment(const FragmentLanes<Record>&, FragmentLanesOut& out) const { out.color[0] = vec4(1.0f); }
};

}  // namespace

TEST_CASE("EmitVertex and EndPrimitive act per lane; strips too short draw nothing; max_vertices caps", "[geometry]") {
  Scene s(Line(20));
  DivergentShader shader;
  const FeedbackVarying what[] = {DivergentShader::Capture(&Record::ids, "ids")};
  const std::uint32_t buffer = s.Feed(shader, 1, what, 4096);
  const std::uint32_t generated = s.gl.GenQuery();
  s.gl.BeginQuery(PRIMITIVES_GENERATED, generated);
  s.gl.BeginTransformFeedback(LINES);
  s.gl.DrawArrays(POINTS, 0, 20);
  s.gl.EndTransformFeedback();
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  REQUIRE(s.gl.GetError() == NO_ERROR);
  // Point i (i % 5 vertices): 0 and 1 make no line; 2 one (0-1); 3 one (the strip after the cut is one vertex);
  // 4: 0-1, then 2-3-4-5-6-7 (five lines; the ninth vertex dropped): six.
  std::uint32_t lines = 0;
  s.gl.GetQueryObjectuiv(generated, QUERY_RESULT, &lines);
  CHECK(lines == 4 * (1 + 1 + 6));
  std::vector<float> got(std::size_t(lines) * 2 * 4);
  s.gl.BindBuffer(COPY_READ_BUFFER, buffer);
  s.gl.GetBufferSubData(COPY_READ_BUFFER, 0, std::ptrdiff_t(got.size() * sizeof(float)), got.data());
  std::vector<float> want;
  auto line = [&](int id, int a, int b) { want.insert(want.end(), {float(id), float(a), 0, 0, float(id), float(b), 0, 0}); };
  for (int i = 0; i < 20; ++i) {
    if (i % 5 >= 2) line(i, 0, 1);
    if (i % 5 == 4)
      for (int k = 2; k < 7; ++k) line(i, k, k + 1);
  }
  CHECK(got == want);
}

namespace {

// The triangle as it came, through a geometry stage; the same without one.
struct PassShader : Base<PassShader, In> {
  static constexpr GeometryLayout kGeometry{TRIANGLES, TRIANGLE_STRIP, 3};
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<In>& out) const {
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[k].position;
      out.varyings = in.vertex[k].varyings;
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<In>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};
struct NoGeometryShader : Base<NoGeometryShader, In> {
  void Fragment(const FragmentLanes<In>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};

// Each point a square of side 2 * size pixels (in a 32 x 32 target), its colour.
struct SpriteShader : Base<SpriteShader, Plain> {
  static constexpr GeometryLayout kGeometry{POINTS, TRIANGLE_STRIP, 4};
  float size = 2.0f;
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<Plain>& out) const {
    const vec4 c = in.vertex[0].position;
    const float d = size / 16.0f;
    for (int k = 0; k < 4; ++k) {
      out.position = c + vec4((k & 1) ? d : -d, (k & 2) ? d : -d, 0.0f, 0.0f) * c.w;
      out.varyings.color = in.vertex[0].varyings.color;
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<Plain>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};

std::vector<std::uint8_t> Pixels(Context& gl, int size) {
  std::vector<std::uint8_t> p(std::size_t(size * size * 4));
  gl.ReadPixels(0, 0, size, size, RGBA, UNSIGNED_BYTE, p.data());
  return p;
}

}  // namespace

TEST_CASE("a geometry stage that passes triangles through draws the bytes of no geometry stage", "[geometry]") {
  std::vector<Vertex> v;
  std::uint32_t seed = 7;
  auto next = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
  for (int i = 0; i < 300; ++i)
    v.push_back({glm::vec4(next() * 2.4f - 1.2f, next() * 2.4f - 1.2f, next() * 2.0f - 1.0f, 0.5f + next()),
                 glm::vec4(next(), next(), next(), 1.0f)});
  for (Enum mode : {TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN})
    for (bool first : {false, true}) {
      INFO(mode << (first ? " first vertex convention" : ""));
      std::vector<std::uint8_t> images[2];
      for (int k = 0; k < 2; ++k) {
        Scene s(v, 32, 2);
        s.gl.Enable(DEPTH_TEST);
        s.gl.ProvokingVertex(first ? FIRST_VERTEX_CONVENTION : LAST_VERTEX_CONVENTION);
        s.gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
        PassShader pass;
        NoGeometryShader plain;
        if (k == 0) s.gl.UseProgram(pass);
        else s.gl.UseProgram(plain);
        s.gl.DrawArrays(mode, 0, 300);
        images[k] = Pixels(s.gl, 32);
        CHECK(s.gl.GetError() == NO_ERROR);
      }
      CHECK(images[0] == images[1]);
      CHECK(std::count(images[0].begin(), images[0].end(), 0) < 32 * 32 * 2);  // something was drawn
    }
}

TEST_CASE("adjacency modes without a geometry stage draw their lines and triangles", "[geometry]") {
  std::vector<Vertex> v;
  for (int i = 0; i < 14; ++i)
    v.push_back({glm::vec4(-0.9f + 0.13f * float(i), (i % 2) ? 0.7f : -0.6f, 0.0f, 1.0f),
                 glm::vec4(float(i) / 14.0f, 1.0f - float(i) / 14.0f, 0.5f, 1.0f)});
  // The same vertices as lists without adjacency, by index.
  auto drawn = [&](Enum mode, const std::vector<std::uint8_t>& elements) {
    Scene s(v, 32);
    NoGeometryShader shader;
    s.gl.UseProgram(shader);
    if (elements.empty()) {
      s.gl.DrawArrays(mode, 0, 14);
    } else {
      s.gl.BindBuffer(ELEMENT_ARRAY_BUFFER, s.gl.GenBuffer());
      s.gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(elements.size()), elements.data());
      s.gl.DrawElement(mode, int(elements.size()), UNSIGNED_BYTE, 0);
    }
    CHECK(s.gl.GetError() == NO_ERROR);
    return Pixels(s.gl, 32);
  };
  CHECK(drawn(LINES_ADJACENCY, {}) == drawn(LINES, {1, 2, 5, 6, 9, 10}));
  CHECK(drawn(LINE_STRIP_ADJACENCY, {}) == drawn(LINE_STRIP, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  CHECK(drawn(TRIANGLES_ADJACENCY, {}) == drawn(TRIANGLES, {0, 2, 4, 6, 8, 10}));
  CHECK(drawn(TRIANGLE_STRIP_ADJACENCY, {}) == drawn(TRIANGLE_STRIP, {0, 2, 4, 6, 8, 10, 12}));
}

TEST_CASE("a geometry stage makes squares of points", "[geometry]") {
  std::vector<Vertex> v = {{{-0.5f, -0.5f, 0, 1}, {1, 0, 0, 1}}, {{1.0f, 1.0f, 0, 2}, {0, 1, 0, 1}}};
  Scene s(v, 32);
  SpriteShader shader;
  s.gl.UseProgram(shader);
  s.gl.DrawArrays(POINTS, 0, 2);
  const std::vector<std::uint8_t> p = Pixels(s.gl, 32);
  // Point 0 at pixel (8, 8): a red square over pixels 6 .. 9; point 1 at (24, 24), green, 22 .. 25.
  auto at = [&](int x, int y) { return std::vector<std::uint8_t>(&p[std::size_t(y * 32 + x) * 4], &p[std::size_t(y * 32 + x) * 4] + 4); };
  CHECK(at(6, 6) == std::vector<std::uint8_t>{255, 0, 0, 255});
  CHECK(at(9, 9) == std::vector<std::uint8_t>{255, 0, 0, 255});
  CHECK(at(10, 9) == std::vector<std::uint8_t>{0, 0, 0, 0});
  CHECK(at(5, 6) == std::vector<std::uint8_t>{0, 0, 0, 0});
  CHECK(at(22, 25) == std::vector<std::uint8_t>{0, 255, 0, 255});
  CHECK(at(26, 25) == std::vector<std::uint8_t>{0, 0, 0, 0});
  int lit = 0;
  for (std::size_t i = 3; i < p.size(); i += 4) lit += p[i] != 0;
  CHECK(lit == 2 * 16);
}

namespace {

// Each triangle into every layer, gl_Layer = gl_InvocationID, its colour times (layer + 1) / 4.
struct LayersShader : Base<LayersShader, Plain> {
  static constexpr bool kWritesLayer = true;
  static constexpr GeometryLayout kGeometry{TRIANGLES, TRIANGLE_STRIP, 3, 4};
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<Plain>& out) const {
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[k].position;
      out.varyings.color = in.vertex[k].varyings.color * (Float(in.invocation_id) + 1.0f) * 0.25f;
      out.layer = in.invocation_id;
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<Plain>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};

}  // namespace

TEST_CASE("gl_Layer from the geometry stage draws one triangle into every layer", "[geometry][layers]") {
  std::vector<Vertex> v = {{{-1, -1, 0, 1}, {1, 1, 1, 1}}, {{3, -1, 0, 1}, {1, 1, 1, 1}}, {{-1, 3, 0, 1}, {1, 1, 1, 1}}};
  Scene s(v, 8);
  const std::uint32_t color = s.gl.GenTexture();
  s.gl.BindTexture(TEXTURE_2D_ARRAY, color);
  s.gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 8, 8, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  const std::uint32_t fbo = s.gl.GenFramebuffer();
  s.gl.BindFramebuffer(FRAMEBUFFER, fbo);
  s.gl.FramebufferTexture(FRAMEBUFFER, COLOR_ATTACHMENT0, color, 0);
  REQUIRE(s.gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  s.gl.Clear(COLOR_BUFFER_BIT);
  LayersShader shader;
  s.gl.UseProgram(shader);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  REQUIRE(s.gl.GetError() == NO_ERROR);
  s.gl.BindFramebuffer(FRAMEBUFFER, 0);
  std::vector<std::uint8_t> out(8 * 8 * 4 * 4);
  s.gl.GetTexImage(TEXTURE_2D_ARRAY, 0, RGBA, UNSIGNED_BYTE, out.data());
  for (int l = 0; l < 4; ++l) {
    INFO("layer " << l);
    CHECK(int(out[std::size_t(l * 64 + 27) * 4]) == (l + 1) * 255 / 4 + ((l + 1) * 255 % 4 >= 2 ? 1 : 0));
  }
}

TEST_CASE("the geometry stage's errors: modes it does not take, transform feedback of another kind", "[geometry][errors]") {
  Scene s(Line(12));
  SpriteShader sprites;  // takes POINTS, makes triangles
  s.gl.UseProgram(sprites);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.DrawArrays(LINES_ADJACENCY, 0, 4);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.DrawArrays(POINTS, 0, 3);
  CHECK(s.gl.GetError() == NO_ERROR);
  RecordShader<TRIANGLES_ADJACENCY> adjacency;
  s.gl.UseProgram(adjacency);
  s.gl.DrawArrays(TRIANGLES, 0, 6);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.DrawArrays(TRIANGLE_STRIP_ADJACENCY, 0, 6);
  CHECK(s.gl.GetError() == NO_ERROR);
  // Recording TRIANGLES while the stage makes triangles out of points: fine; POINTS: INVALID_OPERATION.
  const FeedbackVarying what[] = {FeedbackVarying::Position()};
  s.Feed(sprites, 1, what, 1024);
  s.gl.BeginTransformFeedback(TRIANGLES);
  s.gl.DrawArrays(POINTS, 0, 2);
  CHECK(s.gl.GetError() == NO_ERROR);
  s.gl.EndTransformFeedback();
  s.gl.BeginTransformFeedback(POINTS);
  s.gl.DrawArrays(POINTS, 0, 2);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.EndTransformFeedback();
  int value = 0;
  s.gl.GetIntegerv(MAX_GEOMETRY_OUTPUT_VERTICES, &value);
  CHECK(value == kMaxGeometryOutputVertices);
  s.gl.GetIntegerv(MAX_GEOMETRY_SHADER_INVOCATIONS, &value);
  CHECK(value == kMaxGeometryInvocations);
  CHECK(s.gl.GetError() == NO_ERROR);
}

TEST_CASE("PRIMITIVES_GENERATED counts the geometry stage's output, under RASTERIZER_DISCARD too", "[geometry]") {
  Scene s(Line(10));
  SpriteShader sprites;  // two triangles a point
  s.gl.UseProgram(sprites);
  const std::uint32_t q = s.gl.GenQuery();
  for (bool discard : {false, true}) {
    if (discard) s.gl.Enable(RASTERIZER_DISCARD);
    s.gl.BeginQuery(PRIMITIVES_GENERATED, q);
    s.gl.DrawArrays(POINTS, 0, 10);
    s.gl.EndQuery(PRIMITIVES_GENERATED);
    std::uint32_t n = 0;
    s.gl.GetQueryObjectuiv(q, QUERY_RESULT, &n);
    CHECK(n == 20);
  }
  CHECK(s.gl.GetError() == NO_ERROR);
}

namespace {

// The fragment stage's gl_PrimitiveID as a colour: its bytes in red, green and blue.
template <class Derived, class Varyings>
struct IdColour {
  static constexpr bool kReadsPrimitiveId = true;
  void Fragment(const FragmentLanes<Varyings>& in, FragmentLanesOut& out) const {
    const Int id = in.primitive_id;
    out.color[0] = vec4(Float(id & Int(255)) / 255.0f, Float((id >> 8) & Int(255)) / 255.0f,
                        Float((id >> 16) & Int(255)) / 255.0f, Float(1.0f));
  }
};
struct IdShader : Base<IdShader, In>, IdColour<IdShader, In> {
  using IdColour<IdShader, In>::kReadsPrimitiveId;
  using IdColour<IdShader, In>::Fragment;
};
// The geometry stage writes gl_PrimitiveID = 1000 * gl_PrimitiveIDIn + 7, or leaves it (gl_PrimitiveIDIn).
template <bool kWrite>
struct GeometryIdShader : Base<GeometryIdShader<kWrite>, In>, IdColour<GeometryIdShader<kWrite>, In> {
  using IdColour<GeometryIdShader<kWrite>, In>::kReadsPrimitiveId;
  using IdColour<GeometryIdShader<kWrite>, In>::Fragment;
  static constexpr GeometryLayout kGeometry{TRIANGLES, TRIANGLE_STRIP, 3};
  void Geometry(const GeometryLanes<In>& in, GeometryLanesOut<In>& out) const {
    if (kWrite) out.primitive_id = in.primitive_id * Int(1000) + Int(7);
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[k].position;
      out.varyings = in.vertex[k].varyings;
      out.EmitVertex();
    }
  }
};

// The id a pixel's colour holds (IdColour).
std::uint32_t IdAt(const std::vector<std::uint8_t>& p, int size, int x, int y) {
  const std::uint8_t* c = &p[std::size_t(y * size + x) * 4];
  return std::uint32_t(c[0]) | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]) << 16;
}

}  // namespace

TEST_CASE("the fragment stage reads gl_PrimitiveID: each primitive's number, or the geometry stage's", "[geometry]") {
  // Four columns of two triangles each: a quad per column, as a list (ids 0 .. 7) in columns of 8 pixels.
  std::vector<Vertex> v;
  for (int c = 0; c < 4; ++c) {
    const float x0 = -1.0f + 0.5f * float(c), x1 = x0 + 0.5f;
    for (glm::vec2 p : {glm::vec2(x0, -1), glm::vec2(x1, -1), glm::vec2(x0, 1), glm::vec2(x1, -1), glm::vec2(x1, 1),
                        glm::vec2(x0, 1)})
      v.push_back({glm::vec4(p, 0, 1), glm::vec4(1.0f)});
  }
  auto draw = [&](auto& shader, Enum polygon) {
    Scene s(v, 32, 2);
    s.gl.UseProgram(shader);
    s.gl.PolygonMode(FRONT_AND_BACK, polygon);
    s.gl.DrawArrays(TRIANGLES, 0, int(v.size()));
    CHECK(s.gl.GetError() == NO_ERROR);
    return Pixels(s.gl, 32);
  };
  IdShader plain;
  GeometryIdShader<true> written;
  GeometryIdShader<false> left;
  const auto p = draw(plain, FILL), w = draw(written, FILL), l = draw(left, FILL);
  for (int c = 0; c < 4; ++c) {
    INFO("column " << c);
    // Pixel (8c + 1, 2) lies in the column's first triangle, (8c + 6, 29) in its second.
    CHECK(IdAt(p, 32, 8 * c + 1, 2) == std::uint32_t(2 * c));
    CHECK(IdAt(p, 32, 8 * c + 6, 29) == std::uint32_t(2 * c + 1));
    CHECK(IdAt(w, 32, 8 * c + 6, 29) == std::uint32_t(1000 * (2 * c + 1) + 7));
    CHECK(IdAt(l, 32, 8 * c + 6, 29) == std::uint32_t(2 * c + 1));
  }
  // As lines, each triangle's edges keep its number: the left edge of column 1 belongs to triangle 2 (drawn after
  // column 0's triangle 1, whose right edge it shares), the column's diagonal to triangle 3 (its last).
  const auto lines = draw(plain, LINE);
  CHECK(IdAt(lines, 32, 7, 16) == 2u);  // (a line at x = 8.0 covers column 7)
  CHECK(IdAt(lines, 32, 11, 16) == 3u);  // the diagonal of column 1
}

TEST_CASE("gl_PrimitiveID past 65535, in a draw made in pieces", "[geometry]") {
  // One point per pixel of a 300 x 300 target: 90,000 points, in pieces of MAX_ELEMENTS_VERTICES.
  constexpr int kSize = 300;
  std::vector<Vertex> v;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      v.push_back({glm::vec4((float(x) + 0.5f) / kSize * 2.0f - 1.0f, (float(y) + 0.5f) / kSize * 2.0f - 1.0f, 0, 1),
                   glm::vec4(1.0f)});
  Scene s(v, kSize, 2);
  IdShader shader;
  s.gl.UseProgram(shader);
  s.gl.DrawArrays(POINTS, 0, int(v.size()));
  const auto p = Pixels(s.gl, kSize);
  int wrong = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) wrong += IdAt(p, kSize, x, y) != std::uint32_t(y * kSize + x);
  CHECK(wrong == 0);
}

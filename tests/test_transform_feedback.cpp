// Tests of transform feedback: what a program's vertex stage wrote, recorded into buffers primitive by primitive
// (interleaved and separate, strips and fans taken apart, instances in order), the room in the buffers, the
// queries that count it, RASTERIZER_DISCARD, pausing, transform feedback objects, and OpenGL's errors.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "helpers.h"

using namespace softgl;

namespace {

struct FeedbackVaryings {
  vec4 color;
  vec2 twice;                // 2 * position.xy
  NoPerspective<vec3> mark;  // (gl_VertexID, gl_InstanceID, position.w): recorded as written, not multiplied by w
};

// Position from attribute 0, colour from attribute 1; the fragment stage writes the colour.
struct FeedbackShader : Shader<FeedbackShader, FeedbackVaryings> {
  void Vertex(const VertexLanes& in, VertexLanesOut<FeedbackVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.varyings.twice = vec2(in.attrib[0].x * 2.0f, in.attrib[0].y * 2.0f);
    out.varyings.mark = vec3(Float(in.vertex_id), Float(in.instance_id), in.attrib[0].w);
  }
  void Fragment(const FragmentLanes<FeedbackVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};

struct Vertex {
  glm::vec4 pos, color;
};

// A context of 16 x 16 with FeedbackShader in use and `vertices` in a vertex array (attributes 0 and 1).
struct Scene {
  Context gl;
  FeedbackShader shader;
  std::uint32_t vbo = 0;
  explicit Scene(const std::vector<Vertex>& vertices, int threads = 1) : gl(16, 16, Context::Options{threads}) {
    gl.UseProgram(shader);
    gl.BindVertexArray(gl.GenVertexArray());
    vbo = gl.GenBuffer();
    gl.BindBuffer(ARRAY_BUFFER, vbo);
    gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(Vertex)), vertices.data());
    gl.VertexAttributePointer(0, 4, FLOAT, false, sizeof(Vertex), 0);
    gl.VertexAttributePointer(1, 4, FLOAT, false, sizeof(Vertex), sizeof(glm::vec4));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
  }
  // A new buffer of `floats` floats, each -7 (what nothing recorded leaves), bound to binding `index`.
  std::uint32_t Target(std::uint32_t index, int floats) {
    const std::uint32_t id = gl.GenBuffer();
    gl.BindBuffer(TRANSFORM_FEEDBACK_BUFFER, id);
    const std::vector<float> fill(std::size_t(floats), -7.0f);
    gl.BufferData(TRANSFORM_FEEDBACK_BUFFER, std::ptrdiff_t(fill.size() * sizeof(float)), fill.data());
    gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, index, id);
    return id;
  }
  std::uint32_t Result(std::uint32_t query) {
    std::uint32_t n = 0;
    gl.GetQueryObjectuiv(query, QUERY_RESULT, &n);
    return n;
  }
  std::vector<float> Read(std::uint32_t id, int floats) {
    std::vector<float> out(static_cast<std::size_t>(floats));
    gl.BindBuffer(COPY_READ_BUFFER, id);
    gl.GetBufferSubData(COPY_READ_BUFFER, 0, std::ptrdiff_t(out.size() * sizeof(float)), out.data());
    return out;
  }
};

std::vector<Vertex> Points(int n) {
  std::vector<Vertex> v;
  for (int i = 0; i < n; ++i)
    v.push_back({glm::vec4(-0.9f + 0.2f * float(i), 0.1f * float(i % 3), 0.25f, 1.0f + 0.5f * float(i)),
                 glm::vec4(0.1f * float(i), 1.0f, 0.5f, 1.0f)});
  return v;
}

// What FeedbackShader records for vertex `i` of `v` with the varyings (color, twice, mark), in instance `inst`.
std::vector<float> Expected(const std::vector<Vertex>& v, int i, int inst = 0) {
  const Vertex& x = v[std::size_t(i)];
  return {x.color.r, x.color.g, x.color.b, x.color.a, 2.0f * x.pos.x, 2.0f * x.pos.y, float(i), float(inst), x.pos.w};
}

const FeedbackVarying kAll[] = {FeedbackShader::Capture(&FeedbackVaryings::color, "color"),
                                FeedbackShader::Capture(&FeedbackVaryings::twice, "twice"),
                                FeedbackShader::Capture(&FeedbackVaryings::mark, "mark")};

}  // namespace

TEST_CASE("Capture gives each member's floats and count", "[feedback]") {
  CHECK(kAll[0].first == 0);
  CHECK(kAll[0].components == 4);
  CHECK(kAll[1].first == 4);
  CHECK(kAll[1].components == 2);
  CHECK(kAll[2].first == 6);
  CHECK(kAll[2].components == 3);
  CHECK(FeedbackVarying::Position().first == FeedbackVarying::kPosition);
}

TEST_CASE("transform feedback records each primitive's vertices in order, interleaved", "[feedback]") {
  // (Strips and fans are taken apart as assembly takes them: the conformance suite compares their order with
  // Mesa's, and the last test here follows a long strip.)
  for (int threads : {1, 3}) {
    const std::vector<Vertex> v = Points(6);
    Scene s(v, threads);
    s.gl.TransformFeedbackVaryings(s.shader, 3, kAll, INTERLEAVED_ATTRIBS);
    const std::uint32_t buffer = s.Target(0, 200);
    const std::uint32_t written = s.gl.GenQuery(), generated = s.gl.GenQuery();
    s.gl.BeginQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
    s.gl.BeginQuery(PRIMITIVES_GENERATED, generated);
    s.gl.BeginTransformFeedback(TRIANGLES);
    s.gl.DrawArrays(TRIANGLES, 0, 6);  // 2 triangles: vertices 0 to 5
    s.gl.DrawArrays(TRIANGLES, 1, 3);  // 1: vertices 1, 2, 3
    s.gl.EndTransformFeedback();
    s.gl.EndQuery(PRIMITIVES_GENERATED);
    s.gl.EndQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    REQUIRE(s.gl.GetError() == NO_ERROR);
    const std::vector<float> got = s.Read(buffer, 200);
    std::vector<float> want;
    for (int i : {0, 1, 2, 3, 4, 5, 1, 2, 3}) {
      const std::vector<float> e = Expected(v, i);
      want.insert(want.end(), e.begin(), e.end());
    }
    want.resize(200, -7.0f);
    CHECK(got == want);
    CHECK(s.Result(written) == 3);
    CHECK(s.Result(generated) == 3);
  }
}

TEST_CASE("transform feedback: separate buffers, gl_Position, indexed and instanced draws", "[feedback]") {
  const std::vector<Vertex> v = Points(5);
  Scene s(v);
  const FeedbackVarying which[] = {FeedbackVarying::Position(), kAll[2]};
  s.gl.TransformFeedbackVaryings(s.shader, 2, which, SEPARATE_ATTRIBS);
  const std::uint32_t pos = s.Target(0, 64);
  const std::uint32_t mark = s.gl.GenBuffer();
  s.gl.BindBuffer(TRANSFORM_FEEDBACK_BUFFER, mark);
  const std::vector<float> fill(64, -7.0f);
  s.gl.BufferData(TRANSFORM_FEEDBACK_BUFFER, 256, fill.data());
  s.gl.BindBufferRange(TRANSFORM_FEEDBACK_BUFFER, 1, mark, 8, 240);  // from float 2 on
  const std::uint32_t ebo = s.gl.GenBuffer();
  s.gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  const std::uint32_t indices[] = {4, 0, 4, 2};
  s.gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  s.gl.BeginTransformFeedback(LINES);
  s.gl.DrawElement(LINES, 4, UNSIGNED_INT, 0);    // (4, 0), (4, 2)
  s.gl.DrawArraysInstanced(LINES, 1, 2, 2);       // (1, 2) in instance 0, then in instance 1
  s.gl.EndTransformFeedback();
  REQUIRE(s.gl.GetError() == NO_ERROR);
  const std::vector<float> p = s.Read(pos, 64), m = s.Read(mark, 64);
  const int order[] = {4, 0, 4, 2, 1, 2, 1, 2};
  for (int k = 0; k < 8; ++k) {
    INFO("vertex " << k);
    const int i = order[k];
    const int inst = k >= 6 ? 1 : 0;
    for (int c = 0; c < 4; ++c) CHECK(p[std::size_t(k * 4 + c)] == v[std::size_t(i)].pos[c]);
    const std::vector<float> e = Expected(v, i, inst);
    for (int c = 0; c < 3; ++c) CHECK(m[std::size_t(2 + k * 3 + c)] == e[std::size_t(6 + c)]);
  }
  CHECK(p[32] == -7.0f);
  CHECK(m[0] == -7.0f);
  CHECK(m[1] == -7.0f);
  CHECK(m[26] == -7.0f);
}

TEST_CASE("transform feedback stops at the first primitive that does not fit, and counts only what it wrote", "[feedback]") {
  const std::vector<Vertex> v = Points(9);
  Scene s(v);
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);  // colour: 4 floats a vertex
  const std::uint32_t buffer = s.Target(0, 64);
  s.gl.BindBufferRange(TRANSFORM_FEEDBACK_BUFFER, 0, buffer, 0, 28 * 4);  // room for 2 triangles and 1 vertex
  const std::uint32_t written = s.gl.GenQuery(), generated = s.gl.GenQuery();
  s.gl.BeginQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written);
  s.gl.BeginQuery(PRIMITIVES_GENERATED, generated);
  s.gl.BeginTransformFeedback(TRIANGLES);
  s.gl.DrawArrays(TRIANGLES, 0, 9);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  s.gl.EndTransformFeedback();
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  s.gl.EndQuery(TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  REQUIRE(s.gl.GetError() == NO_ERROR);
  const std::vector<float> got = s.Read(buffer, 64);
  for (int k = 0; k < 6; ++k) CHECK(got[std::size_t(k * 4)] == v[std::size_t(k)].color.r);
  for (std::size_t f = 24; f < 64; ++f) CHECK(got[f] == -7.0f);
  CHECK(s.Result(written) == 2);
  CHECK(s.Result(generated) == 4);
}

TEST_CASE("RASTERIZER_DISCARD records and counts but draws and clears nothing", "[feedback]") {
  std::vector<Vertex> v = {{{-1, -1, 0, 1}, {1, 0, 0, 1}}, {{3, -1, 0, 1}, {1, 0, 0, 1}}, {{-1, 3, 0, 1}, {1, 0, 0, 1}}};
  Scene s(v);
  s.gl.ClearColor(0, 0, 1, 1);
  s.gl.Clear(COLOR_BUFFER_BIT);
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);
  const std::uint32_t buffer = s.Target(0, 16);
  s.gl.Enable(RASTERIZER_DISCARD);
  CHECK(s.gl.IsEnabled(RASTERIZER_DISCARD));
  const std::uint32_t generated = s.gl.GenQuery();
  s.gl.BeginQuery(PRIMITIVES_GENERATED, generated);
  s.gl.BeginTransformFeedback(TRIANGLES);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  s.gl.EndTransformFeedback();
  s.gl.DrawArrays(TRIANGLES, 0, 3);  // discarded too, without transform feedback
  s.gl.ClearColor(0, 1, 0, 1);
  s.gl.Clear(COLOR_BUFFER_BIT);
  const float white[4] = {1, 1, 1, 1};
  s.gl.ClearBufferfv(COLOR, 0, white);
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  REQUIRE(s.gl.GetError() == NO_ERROR);
  CHECK(s.Read(buffer, 16)[8] == 1.0f);  // vertex 2's red
  CHECK(s.Result(generated) == 2);
  std::uint8_t p[4];
  s.gl.ReadPixel(8, 8, p);
  CHECK((p[0] == 0 && p[1] == 0 && p[2] == 255));
  s.gl.Disable(RASTERIZER_DISCARD);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  s.gl.ReadPixel(8, 8, p);
  CHECK((p[0] == 255 && p[1] == 0 && p[2] == 0));
}

TEST_CASE("transform feedback: pause and resume, objects, DrawTransformFeedback", "[feedback]") {
  const std::vector<Vertex> v = Points(4);
  Scene s(v);
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);
  const std::uint32_t object = s.gl.GenTransformFeedback();
  CHECK_FALSE(s.gl.IsTransformFeedback(object));  // an object once bound
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, object);
  CHECK(s.gl.IsTransformFeedback(object));
  const std::uint32_t buffer = s.Target(0, 32);
  int binding = -1;
  s.gl.GetIntegerv(TRANSFORM_FEEDBACK_BINDING, &binding);
  CHECK(binding == int(object));
  s.gl.BeginTransformFeedback(POINTS);
  s.gl.DrawArrays(POINTS, 0, 1);
  s.gl.PauseTransformFeedback();
  bool paused = false;
  s.gl.GetBooleanv(TRANSFORM_FEEDBACK_BUFFER_PAUSED, &paused);
  CHECK(paused);
  s.gl.DrawArrays(TRIANGLES, 0, 3);  // any mode, nothing recorded
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, 0);  // allowed while paused: 0's bindings are empty
  int id = -1;
  s.gl.GetIntegeri_v(TRANSFORM_FEEDBACK_BUFFER_BINDING, 0, &id);
  CHECK(id == 0);
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, object);
  s.gl.GetIntegeri_v(TRANSFORM_FEEDBACK_BUFFER_BINDING, 0, &id);
  CHECK(id == int(buffer));
  s.gl.ResumeTransformFeedback();
  s.gl.DrawArrays(POINTS, 2, 2);
  s.gl.EndTransformFeedback();
  REQUIRE(s.gl.GetError() == NO_ERROR);
  const std::vector<float> got = s.Read(buffer, 32);
  CHECK(got[0] == v[0].color.r);
  CHECK(got[4] == v[2].color.r);
  CHECK(got[8] == v[3].color.r);
  CHECK(got[12] == -7.0f);
  // DrawTransformFeedback draws as many vertices as were recorded (3), from the bound vertex array.
  const std::uint32_t generated = s.gl.GenQuery();
  s.gl.BeginQuery(PRIMITIVES_GENERATED, generated);
  s.gl.DrawTransformFeedback(POINTS, object);
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  CHECK(s.Result(generated) == 3);
  CHECK(s.gl.GetError() == NO_ERROR);
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, 0);
  s.gl.DeleteTransformFeedbacks(1, &object);
  CHECK_FALSE(s.gl.IsTransformFeedback(object));
  s.gl.DrawTransformFeedback(POINTS, object);
  CHECK(s.gl.GetError() == INVALID_VALUE);
}

TEST_CASE("transform feedback's errors", "[feedback]") {
  const std::vector<Vertex> v = Points(4);
  Scene s(v);
  auto error = [&] { return s.gl.GetError(); };
  // Varyings.
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, TRIANGLES);
  CHECK(error() == INVALID_ENUM);
  s.gl.TransformFeedbackVaryings(s.shader, -1, kAll, INTERLEAVED_ATTRIBS);
  CHECK(error() == INVALID_VALUE);
  const FeedbackVarying five[] = {kAll[0], kAll[1], kAll[2], kAll[0], kAll[1]};
  s.gl.TransformFeedbackVaryings(s.shader, 5, five, SEPARATE_ATTRIBS);
  CHECK(error() == INVALID_VALUE);
  s.gl.TransformFeedbackVaryings(s.shader, 5, five, INTERLEAVED_ATTRIBS);
  CHECK(error() == NO_ERROR);
  const FeedbackVarying past[] = {{"past", 8, 2}}, none[] = {{"none", 0, 0}}, unnamed[] = {{nullptr, 0, 1}};
  for (const FeedbackVarying* bad : {past, none, unnamed}) {
    s.gl.TransformFeedbackVaryings(s.shader, 1, bad, INTERLEAVED_ATTRIBS);
    CHECK(error() == INVALID_VALUE);
  }
  s.gl.TransformFeedbackVaryings(s.shader, 2, nullptr, INTERLEAVED_ATTRIBS);
  CHECK(error() == INVALID_VALUE);
  const std::vector<FeedbackVarying> many(17, kAll[0]);  // 68 floats
  s.gl.TransformFeedbackVaryings(s.shader, 17, many.data(), INTERLEAVED_ATTRIBS);
  CHECK(error() == INVALID_VALUE);
  // GetTransformFeedbackVarying of the five set above.
  char name[8] = "xxxxxxx";
  int length = -1, size = -1;
  Enum type = 0;
  s.gl.GetTransformFeedbackVarying(s.shader, 4, 4, &length, &size, &type, name);
  CHECK(std::string(name) == "twi");
  CHECK(length == 3);
  CHECK(size == 1);
  CHECK(type == FLOAT_VEC2);
  s.gl.GetTransformFeedbackVarying(s.shader, 5, 8, &length, &size, &type, name);
  CHECK(error() == INVALID_VALUE);
  // Bindings.
  const std::uint32_t buffer = s.gl.GenBuffer();
  s.gl.BindBufferBase(ARRAY_BUFFER, 0, buffer);
  CHECK(error() == INVALID_ENUM);
  s.gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, 4, buffer);
  CHECK(error() == INVALID_VALUE);
  s.gl.BindBufferRange(TRANSFORM_FEEDBACK_BUFFER, 0, buffer, 2, 8);
  CHECK(error() == INVALID_VALUE);
  s.gl.BindBufferRange(TRANSFORM_FEEDBACK_BUFFER, 0, buffer, 0, 0);
  CHECK(error() == INVALID_VALUE);
  s.gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, 0, buffer + 100);
  CHECK(error() == INVALID_OPERATION);
  // Begin with nothing bound, with no varyings, twice; draws of another kind; changes while active.
  s.gl.BeginTransformFeedback(TRIANGLE_STRIP);
  CHECK(error() == INVALID_ENUM);
  s.gl.BeginTransformFeedback(TRIANGLES);
  CHECK(error() == INVALID_OPERATION);  // binding 0 empty
  s.gl.BindBuffer(TRANSFORM_FEEDBACK_BUFFER, buffer);
  s.gl.BufferData(TRANSFORM_FEEDBACK_BUFFER, 1024, nullptr);
  s.gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
  s.gl.TransformFeedbackVaryings(s.shader, 0, nullptr, INTERLEAVED_ATTRIBS);
  s.gl.BeginTransformFeedback(TRIANGLES);
  CHECK(error() == INVALID_OPERATION);  // nothing to record
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);
  s.gl.EndTransformFeedback();
  CHECK(error() == INVALID_OPERATION);
  s.gl.ResumeTransformFeedback();
  CHECK(error() == INVALID_OPERATION);
  s.gl.BeginTransformFeedback(TRIANGLES);
  CHECK(error() == NO_ERROR);
  s.gl.BeginTransformFeedback(TRIANGLES);
  CHECK(error() == INVALID_OPERATION);
  s.gl.DrawArrays(LINES, 0, 2);
  CHECK(error() == INVALID_OPERATION);
  s.gl.DrawArrays(TRIANGLE_FAN, 0, 4);  // a triangle mode: fine
  CHECK(error() == NO_ERROR);
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);
  CHECK(error() == INVALID_OPERATION);
  s.gl.UseProgram(s.shader);
  CHECK(error() == INVALID_OPERATION);
  s.gl.BindBufferBase(TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  CHECK(error() == INVALID_OPERATION);
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, 0);
  CHECK(error() == INVALID_OPERATION);
  s.gl.BindBuffer(ARRAY_BUFFER, buffer);
  (void)s.gl.MapBuffer(ARRAY_BUFFER, READ_ONLY);
  s.gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(error() == INVALID_OPERATION);  // the buffer recorded into is mapped
  s.gl.UnmapBuffer(ARRAY_BUFFER);
  s.gl.PauseTransformFeedback();
  s.gl.PauseTransformFeedback();
  CHECK(error() == INVALID_OPERATION);
  const std::uint32_t object = s.gl.GenTransformFeedback();
  s.gl.DeleteTransformFeedbacks(1, &object);
  CHECK(error() == NO_ERROR);
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, object);
  CHECK(error() == INVALID_OPERATION);
  s.gl.EndTransformFeedback();
  CHECK(error() == NO_ERROR);
  s.gl.DrawTransformFeedback(POINTS, 0);  // the context's own object, ended: draws its 6 vertices
  CHECK(error() == NO_ERROR);
  s.gl.BindTransformFeedback(TRIANGLES, 0);
  CHECK(error() == INVALID_ENUM);
  const std::uint32_t fresh = s.gl.GenTransformFeedback();
  s.gl.DrawTransformFeedback(POINTS, fresh);
  CHECK(error() == INVALID_VALUE);  // never bound: no object yet
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, fresh);
  s.gl.BindTransformFeedback(TRANSFORM_FEEDBACK, 0);
  s.gl.DrawTransformFeedback(POINTS, fresh);
  CHECK(error() == INVALID_OPERATION);  // never ended
  // The limits.
  int value = 0;
  s.gl.GetIntegerv(MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS, &value);
  CHECK(value == 64);
  s.gl.GetIntegerv(MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS, &value);
  CHECK(value == 4);
  s.gl.GetIntegerv(MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS, &value);
  CHECK(value == 4);
  CHECK(error() == NO_ERROR);
}

TEST_CASE("transform feedback of a draw larger than one piece keeps every primitive in order", "[feedback]") {
  // 60,002 vertices of a strip: the pipeline takes it in pieces that share vertices; the recorded triangles are
  // the strip's 60,000, each once, in order, with the strip's alternating order of the first two vertices.
  const int n = 60002;
  std::vector<Vertex> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[std::size_t(i)] = {glm::vec4(float(i % 7) * 0.1f, float(i % 5) * 0.1f, 0, 1), glm::vec4(float(i), 0, 0, 1)};
  Scene s(v, 2);
  s.gl.TransformFeedbackVaryings(s.shader, 1, kAll, INTERLEAVED_ATTRIBS);
  const std::size_t floats = std::size_t(n - 2) * 3 * 4;
  const std::uint32_t buffer = s.Target(0, int(floats));
  s.gl.Enable(RASTERIZER_DISCARD);
  s.gl.BeginTransformFeedback(TRIANGLES);
  s.gl.DrawArrays(TRIANGLE_STRIP, 0, n);
  s.gl.EndTransformFeedback();
  REQUIRE(s.gl.GetError() == NO_ERROR);
  const std::vector<float> got = s.Read(buffer, int(floats));
  std::size_t wrong = 0;
  for (int t = 0; t < n - 2; ++t) {
    // The last-vertex convention: triangle t is (t, t + 1, t + 2), odd ones (t + 1, t, t + 2).
    const int a = t % 2 ? t + 1 : t, b = t % 2 ? t : t + 1, c = t + 2;
    const float* f = got.data() + std::size_t(t) * 12;
    wrong += f[0] != float(a) || f[4] != float(b) || f[8] != float(c);
  }
  CHECK(wrong == 0);
}

// The API: objects by id, what VAOs record, draw modes end to end, and OpenGL's error model on bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "helpers.h"

using namespace softgl;
using testing::MakeVertexArray;
using testing::SolidShader;

namespace {

int CountLit(const Context& gl) {
  int n = 0;
  const Image img = gl.ReadPixels();
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) n += img.rgba[i] != 0;
  return n;
}

// Binds a new framebuffer object whose colour attachment is a w x h RGBA32F texture.
void BindFloatTarget(Context& gl, int w, int h) {
  const std::uint32_t fbo = gl.GenFramebuffer(), tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA32F, w, h, 0, RGBA, FLOAT, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
}

// Clears colour, depth and stencil of the bound draw framebuffer to these values.
void ClearAll(Context& gl, const glm::vec4& color, double depth, int stencil) {
  gl.ClearColor(color.r, color.g, color.b, color.a);
  gl.ClearDepth(depth);
  gl.ClearStencil(stencil);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
}

}  // namespace

TEST_CASE("GetError reports the first error and clears it", "[context]") {
  Context gl(4, 4);
  CHECK(gl.GetError() == NO_ERROR);
  gl.Enable(0xDEAD);
  gl.Viewport(0, 0, -1, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("invalid enums set INVALID_ENUM and change nothing", "[context]") {
  Context gl(4, 4);
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(0x1234, vbo);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, 16, nullptr, 0x1234);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.VertexAttributePointer(0, 3, 0x1234, false, 0, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.CullFace(TRIANGLES);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.FrontFace(FRONT);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PolygonMode(FRONT, LINE);  // core profile: only FRONT_AND_BACK
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PolygonMode(FRONT_AND_BACK, FILL + 5);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.DepthFunc(0x0208);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK_FALSE(gl.IsEnabled(0x1234));
  CHECK(gl.GetError() == INVALID_ENUM);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(0x7, 0, 3);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.DrawElement(TRIANGLES, 3, FLOAT, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
}

TEST_CASE("invalid values set INVALID_VALUE", "[context]") {
  Context gl(4, 4);
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, -1, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BufferData(ARRAY_BUFFER, 8, nullptr);
  gl.BufferSubData(ARRAY_BUFFER, 4, 8, "12345678");  // past the end
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.BufferSubData(ARRAY_BUFFER, -1, 2, "12");
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttributePointer(16, 3, FLOAT, false, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttributePointer(0, 5, FLOAT, false, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttributePointer(0, 0, FLOAT, false, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttributePointer(0, 3, FLOAT, false, -4, 0);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.EnableVertexAttribArray(99);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.Viewport(0, 0, 4, -4);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PointSize(0.0f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.LineWidth(0.0f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.LineWidth(std::numeric_limits<float>::quiet_NaN());
  CHECK(gl.GetError() == INVALID_VALUE);
  float width = 0.0f;
  gl.GetFloatv(LINE_WIDTH, &width);
  CHECK(width == 1.0f);  // unchanged by the refused calls
  gl.Clear(0x1);
  CHECK(gl.GetError() == INVALID_VALUE);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, -1, 3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.DrawArrays(TRIANGLES, 0, -3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GenBuffers(-1, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
}

TEST_CASE("unbound or unknown ids set INVALID_OPERATION", "[context]") {
  Context gl(4, 4);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);  // no vertex array bound (core profile)
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindBuffer(ARRAY_BUFFER, 77);  // never generated
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindVertexArray(77);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.VertexAttributePointer(0, 3, FLOAT, false, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, 0);  // the element binding lives in a vertex array
  CHECK(gl.GetError() == INVALID_OPERATION);
  const std::uint32_t vao = gl.GenVertexArray();
  gl.BindVertexArray(vao);
  gl.BufferData(ARRAY_BUFFER, 4, nullptr);  // nothing bound to ARRAY_BUFFER
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.VertexAttributePointer(0, 3, FLOAT, false, 0, 16);  // offset without a buffer
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_INT, 0);  // no element buffer
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.UseProgram(nullptr);
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == INVALID_OPERATION);
  const std::uint32_t vbo = gl.GenBuffer();
  gl.DeleteBuffer(vbo);
  CHECK_FALSE(gl.IsBuffer(vbo));
  gl.BindBuffer(ARRAY_BUFFER, vbo);  // deleted
  CHECK(gl.GetError() == INVALID_OPERATION);
}

TEST_CASE("a vertex array records attribute and element buffer bindings", "[context]") {
  Context gl(8, 8);
  SolidShader shader;
  gl.UseProgram(shader);
  const float full[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  const float none[] = {5, 5, 0, 1, 6, 5, 0, 1, 5, 6, 0, 1};
  const std::uint16_t idx[] = {0, 1, 2};
  std::uint32_t vaos[2], vbos[2], ebo;
  gl.GenVertexArrays(2, vaos);
  gl.GenBuffers(2, vbos);
  ebo = gl.GenBuffer();
  gl.BindVertexArray(vaos[0]);
  gl.BindBuffer(ARRAY_BUFFER, vbos[0]);
  gl.BufferData(ARRAY_BUFFER, sizeof full, full);
  gl.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof idx, idx);
  gl.BindVertexArray(vaos[1]);
  gl.BindBuffer(ARRAY_BUFFER, vbos[1]);
  gl.BufferData(ARRAY_BUFFER, sizeof none, none);
  gl.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_SHORT, 0);  // vaos[1] has no element buffer
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BindVertexArray(vaos[0]);  // brings back its own attribute buffer and element buffer
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_SHORT, 0);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(CountLit(gl) == 64);
  // Deleting a buffer that another vertex array still uses keeps its contents alive for that array.
  gl.BindVertexArray(0);
  gl.DeleteBuffer(vbos[0]);
  gl.DeleteBuffer(ebo);
  gl.BindVertexArray(vaos[0]);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_SHORT, 0);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(CountLit(gl) == 64);
  gl.DeleteVertexArray(vaos[0]);  // deleting the bound array binds 0
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == INVALID_OPERATION);
}

TEST_CASE("buffers: mapping, flushing, copying and reading back", "[context]") {
  Context gl(8, 8);
  const std::uint32_t a = gl.GenBuffer(), b = gl.GenBuffer();
  gl.BindBuffer(ARRAY_BUFFER, a);
  gl.BufferData(ARRAY_BUFFER, 64, nullptr, DYNAMIC_DRAW);
  gl.BindBuffer(COPY_WRITE_BUFFER, b);
  gl.BufferData(COPY_WRITE_BUFFER, 32, nullptr, STREAM_READ);
  int v = -1;
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_SIZE, &v);
  CHECK(v == 64);
  gl.GetBufferParameteriv(COPY_WRITE_BUFFER, BUFFER_USAGE, &v);
  CHECK(v == int(STREAM_READ));
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_ACCESS, &v);
  CHECK(v == int(READ_WRITE));

  // Write bytes 4 .. 11 through a mapping with an explicit flush; the parameters describe the mapping.
  auto* p = static_cast<std::uint8_t*>(gl.MapBufferRange(ARRAY_BUFFER, 4, 8, MAP_WRITE_BIT | MAP_FLUSH_EXPLICIT_BIT));
  REQUIRE(p != nullptr);
  for (int i = 0; i < 8; ++i) p[i] = std::uint8_t(10 + i);
  gl.FlushMappedBufferRange(ARRAY_BUFFER, 0, 8);
  CHECK(gl.GetError() == NO_ERROR);
  std::int64_t w = 0;
  gl.GetBufferParameteri64v(ARRAY_BUFFER, BUFFER_MAP_OFFSET, &w);
  CHECK(w == 4);
  gl.GetBufferParameteri64v(ARRAY_BUFFER, BUFFER_MAP_LENGTH, &w);
  CHECK(w == 8);
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_ACCESS_FLAGS, &v);
  CHECK(v == int(MAP_WRITE_BIT | MAP_FLUSH_EXPLICIT_BIT));
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_ACCESS, &v);
  CHECK(v == int(WRITE_ONLY));
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_MAPPED, &v);
  CHECK(v == 1);
  void* pointer = nullptr;
  gl.GetBufferPointerv(ARRAY_BUFFER, BUFFER_MAP_POINTER, &pointer);
  CHECK(pointer == p);
  CHECK(gl.UnmapBuffer(ARRAY_BUFFER));
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_MAPPED, &v);
  CHECK(v == 0);
  gl.GetBufferPointerv(ARRAY_BUFFER, BUFFER_MAP_POINTER, &pointer);
  CHECK(pointer == nullptr);

  // Copy bytes 4 .. 11 of a to 20 .. 27 of b, read them back, and within a to 40 .. 47.
  gl.CopyBufferSubData(ARRAY_BUFFER, COPY_WRITE_BUFFER, 4, 20, 8);
  gl.CopyBufferSubData(ARRAY_BUFFER, ARRAY_BUFFER, 4, 40, 8);
  CHECK(gl.GetError() == NO_ERROR);
  std::uint8_t got[8] = {};
  gl.GetBufferSubData(COPY_WRITE_BUFFER, 20, 8, got);
  for (int i = 0; i < 8; ++i) CHECK(got[i] == 10 + i);
  gl.GetBufferSubData(ARRAY_BUFFER, 40, 8, got);
  for (int i = 0; i < 8; ++i) CHECK(got[i] == 10 + i);
  gl.GetBufferSubData(ARRAY_BUFFER, 0, 4, got);
  CHECK((got[0] | got[1] | got[2] | got[3]) == 0);

  // MapBuffer reads the whole store; a READ_ONLY map of b reads what the copy put there.
  const auto* r = static_cast<const std::uint8_t*>(gl.MapBuffer(COPY_WRITE_BUFFER, READ_ONLY));
  REQUIRE(r != nullptr);
  CHECK(r[20] == 10);
  CHECK(r[27] == 17);
  gl.GetBufferParameteriv(COPY_WRITE_BUFFER, BUFFER_ACCESS_FLAGS, &v);
  CHECK(v == int(MAP_READ_BIT));
  // BufferData unmaps; DeleteBuffer of a mapped buffer is fine.
  gl.BufferData(COPY_WRITE_BUFFER, 16, nullptr);
  gl.GetBufferParameteriv(COPY_WRITE_BUFFER, BUFFER_MAPPED, &v);
  CHECK(v == 0);
  CHECK(gl.MapBufferRange(COPY_WRITE_BUFFER, 0, 16, MAP_WRITE_BIT | MAP_INVALIDATE_BUFFER_BIT) != nullptr);
  gl.DeleteBuffer(b);
  CHECK(!gl.IsBuffer(b));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("buffers: a draw reads what was written through a mapping, once it is unmapped", "[context]") {
  Context gl(8, 8);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.BindVertexArray(gl.GenVertexArray());
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ARRAY_BUFFER, 48, nullptr);
  gl.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  const float full[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  void* p = gl.MapBufferRange(ARRAY_BUFFER, 0, 48, MAP_WRITE_BIT | MAP_INVALIDATE_RANGE_BIT);
  REQUIRE(p != nullptr);
  std::memcpy(p, full, sizeof full);
  gl.DrawArrays(TRIANGLES, 0, 3);  // reading a mapped buffer: INVALID_OPERATION, nothing drawn
  CHECK(gl.GetError() == INVALID_OPERATION);
  CHECK(CountLit(gl) == 0);
  CHECK(gl.UnmapBuffer(ARRAY_BUFFER));
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(CountLit(gl) == 64);
  // A mapped element buffer, or a mapped buffer behind a disabled array (not read: no error).
  const std::uint32_t indices[3] = {0, 1, 2};
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  REQUIRE(gl.MapBufferRange(ELEMENT_ARRAY_BUFFER, 0, 4, MAP_READ_BIT) != nullptr);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_INT, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.DrawArrays(TRIANGLES, 0, 3);
  CHECK(gl.GetError() == NO_ERROR);  // the element buffer is not read
  CHECK(gl.UnmapBuffer(ELEMENT_ARRAY_BUFFER));
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ARRAY_BUFFER, 64, nullptr);
  gl.VertexAttributePointer(1, 4, FLOAT, false, 0, 0);
  REQUIRE(gl.MapBufferRange(ARRAY_BUFFER, 0, 64, MAP_WRITE_BIT) != nullptr);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_INT, 0);
  CHECK(gl.GetError() == NO_ERROR);  // attribute 1 is disabled
}

TEST_CASE("buffers: the mapping and copying errors, as OpenGL gives them", "[context][errors]") {
  Context gl(8, 8);
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  gl.BufferData(ARRAY_BUFFER, 64, nullptr);
  struct Case {
    std::ptrdiff_t offset, length;
    Bitfield access;
    Enum error;
  };
  for (const Case& c : {Case{0, 0, MAP_WRITE_BIT, INVALID_OPERATION}, Case{60, 8, MAP_WRITE_BIT, INVALID_VALUE},
                        Case{-1, 8, MAP_WRITE_BIT, INVALID_VALUE}, Case{0, 8, 0, INVALID_OPERATION},
                        Case{0, 8, MAP_READ_BIT | MAP_INVALIDATE_RANGE_BIT, INVALID_OPERATION},
                        Case{0, 8, MAP_READ_BIT | MAP_UNSYNCHRONIZED_BIT, INVALID_OPERATION},
                        Case{0, 8, MAP_READ_BIT | MAP_FLUSH_EXPLICIT_BIT, INVALID_OPERATION},
                        Case{0, 8, MAP_READ_BIT | 0x1000, INVALID_VALUE}}) {
    INFO("offset " << c.offset << " length " << c.length << " access " << c.access);
    CHECK(gl.MapBufferRange(ARRAY_BUFFER, c.offset, c.length, c.access) == nullptr);
    CHECK(gl.GetError() == c.error);
  }
  CHECK(gl.MapBuffer(ARRAY_BUFFER, READ_ONLY + 5) == nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(gl.MapBufferRange(ARRAY_BUFFER + 1000, 0, 8, MAP_READ_BIT) == nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(gl.MapBufferRange(COPY_READ_BUFFER, 0, 8, MAP_READ_BIT) == nullptr);  // nothing bound there
  CHECK(gl.GetError() == INVALID_OPERATION);

  REQUIRE(gl.MapBufferRange(ARRAY_BUFFER, 4, 8, MAP_WRITE_BIT) != nullptr);
  CHECK(gl.MapBufferRange(ARRAY_BUFFER, 0, 8, MAP_WRITE_BIT) == nullptr);  // already mapped
  CHECK(gl.GetError() == INVALID_OPERATION);
  const std::uint8_t bytes[8] = {};
  std::uint8_t out[8];
  gl.BufferSubData(ARRAY_BUFFER, 0, 4, bytes);  // outside the mapped range: refused too (OpenGL 3.3, 2.9.2)
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetBufferSubData(ARRAY_BUFFER, 16, 4, out);  // (and 6.1.13)
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BufferSubData(ARRAY_BUFFER, 8, 8, bytes);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetBufferSubData(ARRAY_BUFFER, 0, 8, out);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.FlushMappedBufferRange(ARRAY_BUFFER, 0, 4);  // not mapped with MAP_FLUSH_EXPLICIT_BIT
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CopyBufferSubData(ARRAY_BUFFER, ARRAY_BUFFER, 32, 48, 8);
  CHECK(gl.GetError() == INVALID_OPERATION);
  CHECK(gl.UnmapBuffer(ARRAY_BUFFER));
  CHECK(!gl.UnmapBuffer(ARRAY_BUFFER));
  CHECK(gl.GetError() == INVALID_OPERATION);

  REQUIRE(gl.MapBufferRange(ARRAY_BUFFER, 4, 8, MAP_WRITE_BIT | MAP_FLUSH_EXPLICIT_BIT) != nullptr);
  gl.FlushMappedBufferRange(ARRAY_BUFFER, 4, 8);  // past the 8 mapped bytes
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.FlushMappedBufferRange(ARRAY_BUFFER, -1, 2);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(gl.UnmapBuffer(ARRAY_BUFFER));

  gl.CopyBufferSubData(ARRAY_BUFFER, ARRAY_BUFFER, 0, 8, 16);  // overlapping
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyBufferSubData(ARRAY_BUFFER, ARRAY_BUFFER, 0, 56, 16);  // past the end
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyBufferSubData(ARRAY_BUFFER, ARRAY_BUFFER, -1, 16, 8);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyBufferSubData(ARRAY_BUFFER, COPY_READ_BUFFER, 0, 16, 8);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetBufferSubData(ARRAY_BUFFER, 60, 8, out);
  CHECK(gl.GetError() == INVALID_VALUE);
  int v = 0;
  gl.GetBufferParameteriv(ARRAY_BUFFER, 0x1234, &v);
  CHECK(gl.GetError() == INVALID_ENUM);
  void* pointer = nullptr;
  gl.GetBufferPointerv(ARRAY_BUFFER, BUFFER_SIZE, &pointer);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BufferData(ARRAY_BUFFER, 0, nullptr);
  CHECK(gl.MapBuffer(ARRAY_BUFFER, READ_ONLY) == nullptr);  // no store to map
  CHECK(gl.GetError() == INVALID_OPERATION);
}

TEST_CASE("indices past the end of the element buffer are refused", "[context]") {
  Context gl(4, 4);
  const std::uint32_t vao = MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}});
  (void)vao;
  const std::uint32_t ebo = gl.GenBuffer();
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  const std::uint32_t idx[] = {0, 1, 2};
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof idx, idx);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.DrawElement(TRIANGLES, 4, UNSIGNED_INT, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_INT, 4);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.DrawElement(TRIANGLES, 1, UNSIGNED_INT, std::numeric_limits<std::size_t>::max());
  CHECK(gl.GetError() == INVALID_OPERATION);
  CHECK(CountLit(gl) == 0);
}

TEST_CASE("element values past the end of the vertex buffer read zeros, not memory", "[context]") {
  Context gl(8, 8);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}});
  const std::uint32_t ebo = gl.GenBuffer();
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  const std::uint32_t idx[] = {0, 1, 2, 7, 4000000000u, 9};
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof idx, idx);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.DrawElement(TRIANGLES, 6, UNSIGNED_INT, 0);
  CHECK(gl.GetError() == NO_ERROR);
  // The second triangle reads (0, 0, 0, 1) three times and is degenerate; the first covers the lower-left half
  // without its diagonal.
  CHECK(CountLit(gl) == 28);
}

TEST_CASE("every draw mode through DrawArrays and DrawElement", "[context]") {
  Context gl(16, 16);
  testing::SolidShader shader;
  gl.UseProgram(shader);
  // Four vertices at pixel centres (2,2), (13,2), (13,13), (2,13).
  auto c = [](float x, float y) { return testing::WindowToClip(x, y, 16, 16); };
  MakeVertexArray(gl, {c(2.5f, 2.5f), c(13.5f, 2.5f), c(13.5f, 13.5f), c(2.5f, 13.5f)});
  const std::uint32_t ebo = gl.GenBuffer();
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  const std::uint8_t idx[] = {0, 1, 2, 3};
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof idx, idx);
  struct Row {
    Enum mode;
    int lit;
  };
  const Row rows[] = {
      {POINTS, 4},
      {LINES, 11 + 11},                // bottom and top edges, last pixel of each left out
      {LINE_STRIP, 11 * 3},            // three edges
      {LINE_LOOP, 11 * 4},             // closed square
      {TRIANGLES, 11 * 11 / 2 + 6},    // half the square with its diagonal
      {TRIANGLE_STRIP, 11 * 11 / 2 + 6},  // 0,1,2 then 2,1,3: the second folds back over the first
      {TRIANGLE_FAN, 11 * 11},         // the whole square
  };
  for (const Row& r : rows) {
    INFO("mode " << r.mode);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.DrawArrays(r.mode, 0, 4);
    CHECK(gl.GetError() == NO_ERROR);
    const int arrays = CountLit(gl);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.DrawElement(r.mode, 4, UNSIGNED_BYTE, 0);
    CHECK(CountLit(gl) == arrays);
    if (r.mode != TRIANGLES && r.mode != TRIANGLE_STRIP) CHECK(arrays == r.lit);
  }
}

namespace {

// Colour from gl_VertexID (red = id / 32, flat from the provoking vertex): shows which vertex a draw used.
struct VertexIdVaryings {
  softgl::Flat<glm::vec4> color;
};
struct VertexIdShader : softgl::Shader<VertexIdShader, VertexIdVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<VertexIdVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = glm::vec4(float(in.vertex_id) / 32.0f, 0.0f, 0.0f, 1.0f);
  }
  bool Fragment(const softgl::FragmentIn<VertexIdVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.color;
    return true;
  }
};

// Four quads of two triangles in a row across a 16 x 4 framebuffer (vertices 4q .. 4q + 3), and element lists
// that draw them.
struct QuadRow {
  Context gl{16, 4};
  VertexIdShader shader;
  QuadRow() {
    std::vector<glm::vec4> pos;
    for (int q = 0; q < 4; ++q) {
      const float x0 = -1.0f + 0.5f * float(q), x1 = x0 + 0.5f;
      for (glm::vec2 p : {glm::vec2(x0, -1), glm::vec2(x1, -1), glm::vec2(x1, 1), glm::vec2(x0, 1)})
        pos.push_back(glm::vec4(p, 0, 1));
    }
    MakeVertexArray(gl, pos);
    const std::uint32_t ebo = gl.GenBuffer();
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
    // Quad 0's six indices, then quads 1, 2, 3's (18 more).
    std::vector<std::uint16_t> idx;
    for (int q = 0; q < 4; ++q)
      for (int k : {0, 1, 2, 0, 2, 3}) idx.push_back(std::uint16_t(4 * q + k));
    gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(idx.size() * 2), idx.data());
    gl.UseProgram(shader);
    gl.ProvokingVertex(FIRST_VERTEX_CONVENTION);
  }
  std::vector<std::uint8_t> Red() {
    std::vector<std::uint8_t> r;
    const Image img = gl.ReadPixels();
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) r.push_back(img.rgba[i]);
    return r;
  }
};

// QuadRow's quads as separate triangles, vertices 6q .. 6q + 5.
std::vector<glm::vec4> SeparateTriangles() {
  std::vector<glm::vec4> tri;
  for (int q = 0; q < 4; ++q) {
    const float x0 = -1.0f + 0.5f * float(q), x1 = x0 + 0.5f;
    for (glm::vec2 p : {glm::vec2(x0, -1), glm::vec2(x1, -1), glm::vec2(x1, 1), glm::vec2(x0, -1), glm::vec2(x1, 1),
                        glm::vec2(x0, 1)})
      tri.push_back(glm::vec4(p, 0, 1));
  }
  return tri;
}

}  // namespace

TEST_CASE("base vertex, range and multi-draw calls draw what their plain forms draw", "[context]") {
  QuadRow ref;
  for (int q = 0; q < 4; ++q) ref.gl.DrawElement(TRIANGLES, 6, UNSIGNED_SHORT, std::size_t(12 * q));
  const std::vector<std::uint8_t> want = ref.Red();
  REQUIRE(ref.gl.GetError() == NO_ERROR);
  // Every quad drawn, each in its own red (gl_VertexID 0, 4, 8, 12 provoke): 64 pixels, 4 distinct values.
  CHECK(std::set<std::uint8_t>(want.begin(), want.end()).size() == 4);

  SECTION("DrawElementsBaseVertex: quad 0's indices moved by 4q vertices, gl_VertexID included") {
    QuadRow t;
    for (int q = 0; q < 4; ++q) t.gl.DrawElementsBaseVertex(TRIANGLES, 6, UNSIGNED_SHORT, 0, 4 * q);
    CHECK(t.gl.GetError() == NO_ERROR);
    CHECK(t.Red() == want);
  }
  SECTION("DrawRangeElements") {
    QuadRow t;
    t.gl.DrawRangeElements(TRIANGLES, 0, 15, 24, UNSIGNED_SHORT, 0);
    CHECK(t.gl.GetError() == NO_ERROR);
    CHECK(t.Red() == want);
  }
  SECTION("MultiDrawElements") {
    QuadRow t;
    const int count[] = {6, 12, 6};
    const std::size_t offsets[] = {0, 12, 36};
    t.gl.MultiDrawElements(TRIANGLES, count, UNSIGNED_SHORT, offsets, 3);
    CHECK(t.gl.GetError() == NO_ERROR);
    CHECK(t.Red() == want);
  }
  SECTION("DrawRangeElementsBaseVertex and MultiDrawElementsBaseVertex: quad 0's indices, moved") {
    QuadRow t;
    t.gl.DrawRangeElementsBaseVertex(TRIANGLES, 0, 3, 6, UNSIGNED_SHORT, 0, 0);
    t.gl.DrawRangeElementsBaseVertex(TRIANGLES, 0, 3, 6, UNSIGNED_SHORT, 0, 4);
    const int count[] = {6, 6};
    const std::size_t offsets[] = {0, 0};
    const int base[] = {8, 12};
    t.gl.MultiDrawElementsBaseVertex(TRIANGLES, count, UNSIGNED_SHORT, offsets, 2, base);
    CHECK(t.gl.GetError() == NO_ERROR);
    CHECK(t.Red() == want);
    t.gl.MultiDrawElementsBaseVertex(TRIANGLES, count, UNSIGNED_SHORT, offsets, 2, nullptr);
    CHECK(t.gl.GetError() == INVALID_VALUE);
    t.gl.DrawRangeElementsBaseVertex(TRIANGLES, 4, 3, 6, UNSIGNED_SHORT, 0, 4);
    CHECK(t.gl.GetError() == INVALID_VALUE);
  }
  SECTION("MultiDrawArrays, against DrawArrays one draw at a time") {
    QuadRow t;
    MakeVertexArray(t.gl, SeparateTriangles());
    const int first[] = {0, 6, 12, 18}, count[] = {6, 6, 6, 6};
    t.gl.MultiDrawArrays(TRIANGLES, first, count, 4);
    CHECK(t.gl.GetError() == NO_ERROR);
    QuadRow r;  // the same with DrawArrays one at a time
    MakeVertexArray(r.gl, SeparateTriangles());
    for (int q = 0; q < 4; ++q) r.gl.DrawArrays(TRIANGLES, 6 * q, 6);
    const std::vector<std::uint8_t> got = t.Red(), arrays = r.Red();
    CHECK(got == arrays);
    CHECK(std::set<std::uint8_t>(got.begin(), got.end()).size() == 8);  // each triangle its own first vertex
  }
  SECTION("a base vertex that takes an index below 0 reads zeros there, no crash") {
    QuadRow t;
    t.gl.DrawElementsBaseVertex(TRIANGLES, 6, UNSIGNED_SHORT, 0, -1);  // indices -1, 0, 1, -1, 1, 2
    CHECK(t.gl.GetError() == NO_ERROR);
    t.gl.DrawElementsBaseVertex(TRIANGLES, 6, UNSIGNED_SHORT, 0, std::numeric_limits<int>::max());
    CHECK(t.gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("the draw variants' errors, as OpenGL gives them, draw nothing", "[context][errors]") {
  QuadRow t;
  const int count[] = {6, -1}, good_count[] = {6, 6}, first[] = {0, 0}, bad_first[] = {0, -3};
  const std::size_t offsets[] = {0, 12}, past[] = {0, 48};
  t.gl.DrawElementsBaseVertex(0x7, 6, UNSIGNED_SHORT, 0, 0);
  CHECK(t.gl.GetError() == INVALID_ENUM);
  t.gl.DrawElementsBaseVertex(TRIANGLES, 6, FLOAT, 0, 0);
  CHECK(t.gl.GetError() == INVALID_ENUM);
  t.gl.DrawElementsBaseVertex(TRIANGLES, -6, UNSIGNED_SHORT, 0, 4);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.DrawElementsBaseVertex(TRIANGLES, 6, UNSIGNED_SHORT, 40, 4);  // past the end of the element buffer
  CHECK(t.gl.GetError() == INVALID_OPERATION);
  t.gl.DrawRangeElements(TRIANGLES, 5, 4, 6, UNSIGNED_SHORT, 0);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.DrawRangeElements(TRIANGLES, 0, 3, -1, UNSIGNED_SHORT, 0);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawElements(TRIANGLES, count, UNSIGNED_SHORT, offsets, 2);  // quad 0 fine, then a negative count
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawElements(TRIANGLES, good_count, UNSIGNED_SHORT, offsets, -1);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawElements(TRIANGLES, good_count, UNSIGNED_SHORT, past, 2);
  CHECK(t.gl.GetError() == INVALID_OPERATION);
  t.gl.MultiDrawElements(TRIANGLES, good_count, UNSIGNED_INT + 1, offsets, 2);
  CHECK(t.gl.GetError() == INVALID_ENUM);
  t.gl.MultiDrawElements(TRIANGLES, nullptr, UNSIGNED_SHORT, nullptr, 2);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawArrays(TRIANGLES, bad_first, good_count, 2);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawArrays(TRIANGLES, first, good_count, -2);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.MultiDrawArrays(LINES + 100, first, good_count, 2);
  CHECK(t.gl.GetError() == INVALID_ENUM);
  t.gl.MultiDrawArrays(TRIANGLES, first, good_count, 0);  // nothing to draw, no error
  t.gl.MultiDrawElements(TRIANGLES, nullptr, UNSIGNED_SHORT, nullptr, 0);
  CHECK(t.gl.GetError() == NO_ERROR);
  for (std::uint8_t r : t.Red()) CHECK(r == 0);
  t.gl.BindVertexArray(0);
  t.gl.MultiDrawElements(TRIANGLES, good_count, UNSIGNED_SHORT, offsets, 2);
  CHECK(t.gl.GetError() == INVALID_OPERATION);
  t.gl.MultiDrawArrays(TRIANGLES, first, good_count, 2);
  CHECK(t.gl.GetError() == INVALID_OPERATION);
}

namespace {

// Instancing: attribute 0 a quad's corner, attribute 1 a per-instance colour (divisor set by the test); instance i
// moves right by 4 pixels of a 16 x 4 framebuffer per gl_InstanceID. Written wide and scalar.
struct InstanceVaryings {
  glm::vec4 color;
};
struct WideColor {
  softgl::vec4 value;
};
struct WideInstanceShader : softgl::Shader<WideInstanceShader, WideColor> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideColor>& out) const {
    const softgl::Float dx = softgl::Float(in.instance_id) * 0.5f;
    out.position = softgl::vec4(in.attrib[0].x + dx, in.attrib[0].y, 0.0f, 1.0f);
    out.varyings.value = in.attrib[1];
  }
  void Fragment(const softgl::FragmentLanes<WideColor>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.value;
  }
};
struct ScalarInstanceShader : softgl::Shader<ScalarInstanceShader, InstanceVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<InstanceVaryings>& out) const {
    out.position = in.attrib[0] + glm::vec4(0.5f * float(in.instance_id), 0, 0, 0);
    out.varyings.color = in.attrib[1];
  }
  bool Fragment(const softgl::FragmentIn<InstanceVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.color;
    return true;
  }
};

// Quad 0 of QuadRow (4 vertices, and 6 indices), with 4 instance colours at attribute 1.
struct InstanceScene {
  Context gl{16, 4};
  std::uint32_t colors = 0;
  explicit InstanceScene(std::uint32_t divisor) {
    const std::vector<glm::vec4> quad = {{-1, -1, 0, 1}, {-0.5f, -1, 0, 1}, {-0.5f, 1, 0, 1}, {-1, 1, 0, 1}};
    MakeVertexArray(gl, quad);
    const float c[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    colors = gl.GenBuffer();
    gl.BindBuffer(ARRAY_BUFFER, colors);
    gl.BufferData(ARRAY_BUFFER, sizeof(c), c);
    gl.VertexAttributePointer(1, 4, FLOAT, false, 0, 0);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribDivisor(1, divisor);
    const std::uint8_t idx[6] = {0, 1, 2, 0, 2, 3};
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof(idx), idx);
  }
  // The colour (as 0xRRGGBB) of the middle pixel of each 4 x 4 quad slot.
  std::vector<std::uint32_t> Slots() {
    std::vector<std::uint32_t> out;
    for (int q = 0; q < 4; ++q) {
      std::uint8_t px[4];
      gl.ReadPixel(4 * q + 2, 2, px);
      out.push_back(std::uint32_t(px[0]) << 16 | std::uint32_t(px[1]) << 8 | px[2]);
    }
    return out;
  }
};

}  // namespace

TEST_CASE("instanced draws: gl_InstanceID and attribute divisors, wide and scalar shaders", "[context]") {
  WideInstanceShader wide;
  ScalarInstanceShader scalar;
  using Slots = std::vector<std::uint32_t>;
  const Slots per_instance = {0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF};
  for (const Program* program : {static_cast<const Program*>(&wide), static_cast<const Program*>(&scalar)}) {
    SECTION(program == &wide ? "wide" : "scalar") {
      {
        InstanceScene t(1);
        t.gl.UseProgram(*program);
        t.gl.DrawArraysInstanced(TRIANGLE_FAN, 0, 4, 4);
        CHECK(t.gl.GetError() == NO_ERROR);
        CHECK(t.Slots() == per_instance);
      }
      {
        InstanceScene t(2);  // instances 0 and 1 read colour 0, 2 and 3 colour 1
        t.gl.UseProgram(*program);
        t.gl.DrawElementsInstanced(TRIANGLES, 6, UNSIGNED_BYTE, 0, 4);
        CHECK(t.gl.GetError() == NO_ERROR);
        CHECK(t.Slots() == Slots{0xFF0000, 0xFF0000, 0x00FF00, 0x00FF00});
      }
      {
        InstanceScene t(1);  // three instances: the fourth slot stays clear
        t.gl.UseProgram(*program);
        t.gl.DrawElementsInstancedBaseVertex(TRIANGLES, 6, UNSIGNED_BYTE, 0, 3, 0);
        CHECK(t.Slots() == Slots{0xFF0000, 0x00FF00, 0x0000FF, 0});
      }
      {
        InstanceScene t(0);  // divisor 0: per vertex, so vertices 0-3 read colours 0-3; the plain draw is instance 0
        t.gl.UseProgram(*program);
        t.gl.VertexAttribDivisor(1, 3);
        t.gl.DrawArrays(TRIANGLE_FAN, 0, 4);
        CHECK(t.Slots() == Slots{0xFF0000, 0, 0, 0});
      }
    }
  }
}

TEST_CASE("instanced draws: base vertex moves the vertices, not the instanced attributes", "[context]") {
  // Two quads in the vertex buffer (quad 1 at x + 0.5); basevertex 4 draws quad 1 for each instance.
  InstanceScene t(1);
  WideInstanceShader shader;
  t.gl.UseProgram(shader);
  const std::vector<glm::vec4> quads = {{-1, -1, 0, 1},    {-0.5f, -1, 0, 1}, {-0.5f, 1, 0, 1}, {-1, 1, 0, 1},
                                        {-0.5f, -1, 0, 1}, {0, -1, 0, 1},     {0, 1, 0, 1},     {-0.5f, 1, 0, 1}};
  t.gl.BindBuffer(ARRAY_BUFFER, t.gl.GenBuffer());
  t.gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(quads.size() * sizeof(glm::vec4)), quads.data());
  t.gl.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  t.gl.DrawElementsInstancedBaseVertex(TRIANGLES, 6, UNSIGNED_BYTE, 0, 2, 4);
  CHECK(t.gl.GetError() == NO_ERROR);
  CHECK(t.Slots() == std::vector<std::uint32_t>{0, 0xFF0000, 0x00FF00, 0});
}

TEST_CASE("instanced draws larger than a piece match the same primitives drawn one instance at a time",
          "[context]") {
  // Additive blending counts every hit, so a missed or doubled instance shows. 30,000 instances of a 6-vertex
  // pair of triangles (several pieces of whole instances), and 2 instances of a 60,000-vertex list (each split).
  struct Case {
    int vertices, instances;
  };
  for (const Case& c : {Case{6, 30000}, Case{60000, 2}}) {
    INFO(c.vertices << " vertices x " << c.instances << " instances");
    std::vector<glm::vec4> tris(std::size_t(c.vertices)), offsets(std::size_t(c.instances));
    for (int i = 0; i < c.vertices; ++i) {
      const float a = 0.37f * float(i);
      tris[std::size_t(i)] = glm::vec4(0.1f * std::cos(a), 0.1f * std::sin(a), 0, 1);
    }
    for (int i = 0; i < c.instances; ++i)
      offsets[std::size_t(i)] = glm::vec4(std::fmod(0.013f * float(i), 1.6f) - 0.8f, std::fmod(0.029f * float(i), 1.6f) - 0.8f, 0, 0);
    struct OffsetShader : softgl::Shader<OffsetShader, WideColor> {
      void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideColor>& out) const {
        out.position = in.attrib[0] + in.attrib[1];
        out.varyings.value = softgl::vec4(4.0f / 255.0f, 0.0f, 0.0f, 1.0f);
      }
      void Fragment(const softgl::FragmentLanes<WideColor>& in, softgl::FragmentLanesOut& out) const {
        out.color[0] = in.varyings.value;
      }
    } shader;
    Image images[2];
    for (int pass = 0; pass < 2; ++pass) {
      Context gl(96, 96);
      gl.UseProgram(shader);
      gl.Enable(BLEND);
      gl.BlendFunc(ONE, ONE);
      MakeVertexArray(gl, tris);
      gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
      gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(offsets.size() * sizeof(glm::vec4)), offsets.data());
      gl.VertexAttributePointer(1, 4, FLOAT, false, 0, 0);
      gl.EnableVertexAttribArray(1);
      if (pass == 0) {
        gl.VertexAttribDivisor(1, 1);
        gl.DrawArraysInstanced(TRIANGLES, 0, c.vertices, c.instances);
      } else {  // instance i as a plain draw whose attribute 1 is the constant offsets[i]
        gl.DisableVertexAttribArray(1);
        for (int i = 0; i < c.instances; ++i) {
          const glm::vec4 o = offsets[std::size_t(i)];
          gl.VertexAttrib4f(1, o.x, o.y, o.z, o.w);
          gl.DrawArrays(TRIANGLES, 0, c.vertices);
        }
      }
      CHECK(gl.GetError() == NO_ERROR);
      images[pass] = gl.ReadPixels();
    }
    CHECK(images[0].rgba == images[1].rgba);
  }
}

TEST_CASE("instanced draws' errors, as OpenGL gives them", "[context][errors]") {
  InstanceScene t(1);
  WideInstanceShader shader;
  t.gl.UseProgram(shader);
  t.gl.DrawArraysInstanced(TRIANGLES, 0, 3, -1);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.DrawElementsInstanced(TRIANGLES, 6, UNSIGNED_BYTE, 0, -1);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  t.gl.DrawElementsInstancedBaseVertex(TRIANGLES, 6, FLOAT, 0, 1, 0);
  CHECK(t.gl.GetError() == INVALID_ENUM);
  t.gl.DrawElementsInstanced(TRIANGLES, 6, UNSIGNED_BYTE, 4, 2);  // past the end of the element buffer
  CHECK(t.gl.GetError() == INVALID_OPERATION);
  t.gl.DrawArraysInstanced(TRIANGLES, 0, 3, 0);  // nothing to draw, no error
  t.gl.DrawElementsInstanced(TRIANGLES, 6, UNSIGNED_BYTE, 0, 0);
  CHECK(t.gl.GetError() == NO_ERROR);
  t.gl.VertexAttribDivisor(kMaxVertexAttribs, 1);
  CHECK(t.gl.GetError() == INVALID_VALUE);
  for (std::uint32_t c : t.Slots()) CHECK(c == 0);
  t.gl.BindVertexArray(0);
  t.gl.VertexAttribDivisor(1, 1);
  CHECK(t.gl.GetError() == INVALID_OPERATION);
  t.gl.DrawArraysInstanced(TRIANGLES, 0, 3, 2);
  CHECK(t.gl.GetError() == INVALID_OPERATION);
}

namespace {

// Additive blending of a dim colour: the image counts how often each pixel was drawn, so a primitive missed or
// drawn twice shows.
struct CountingScene {
  Context gl{64, 64};
  SolidShader shader;
  CountingScene(const std::vector<glm::vec4>& positions, const std::vector<std::uint32_t>& indices, Enum type) {
    shader.color = glm::vec4(16.0f / 255.0f, 0, 0, 1);
    gl.UseProgram(shader);
    gl.Enable(BLEND);
    gl.BlendFunc(ONE, ONE);
    MakeVertexArray(gl, positions);
    std::vector<std::uint8_t> bytes;
    for (std::uint32_t i : indices) {
      const std::size_t size = type == UNSIGNED_BYTE ? 1 : type == UNSIGNED_SHORT ? 2 : 4;
      for (std::size_t b = 0; b < size; ++b) bytes.push_back(std::uint8_t(i >> (8 * b)));
    }
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(bytes.size()), bytes.data());
  }
};

// A ring of 40 points around the centre of the framebuffer, and index lists over it.
std::vector<glm::vec4> Ring() {
  std::vector<glm::vec4> v;
  for (int i = 0; i < 40; ++i) {
    const float a = 0.157f * float(i), r = i % 2 ? 0.9f : 0.45f;
    v.push_back(glm::vec4(r * std::cos(a), r * std::sin(a), 0, 1));
  }
  return v;
}

}  // namespace

TEST_CASE("primitive restart: an indexed draw with restarts draws what its runs draw one by one", "[context]") {
  // Runs of 5, 1, 0, 7 and 4 elements; the restart index is 39 (a real vertex of the ring when not a restart).
  const std::vector<std::vector<std::uint32_t>> runs = {{0, 1, 2, 3, 4}, {5}, {}, {8, 9, 10, 11, 12, 13, 14},
                                                        {20, 21, 22, 23}};
  for (Enum mode : {POINTS, LINES, LINE_STRIP, LINE_LOOP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN}) {
    for (Enum type : {UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT}) {
      INFO("mode " << mode << ", type " << type);
      const std::uint32_t fixed = type == UNSIGNED_BYTE ? 0xFFu : type == UNSIGNED_SHORT ? 0xFFFFu : 0xFFFFFFFFu;
      for (bool use_fixed : {false, true}) {
        const std::uint32_t marker = use_fixed ? fixed : 39;
        std::vector<std::uint32_t> all = {marker};  // a leading restart too
        for (const auto& run : runs) {
          all.insert(all.end(), run.begin(), run.end());
          all.push_back(marker);
        }
        all.pop_back();
        CountingScene with(Ring(), all, type), separate(Ring(), all, type);
        with.gl.Enable(use_fixed ? PRIMITIVE_RESTART_FIXED_INDEX : PRIMITIVE_RESTART);
        with.gl.PrimitiveRestartIndex(use_fixed ? 7 : 39);  // ignored while the fixed index is enabled
        with.gl.DrawElement(mode, int(all.size()), type, 0);
        CHECK(with.gl.GetError() == NO_ERROR);
        std::size_t at = 1;  // each run from its place in the element buffer
        for (const auto& run : runs) {
          const std::size_t size = type == UNSIGNED_BYTE ? 1 : type == UNSIGNED_SHORT ? 2 : 4;
          separate.gl.DrawElement(mode, int(run.size()), type, at * size);
          at += run.size() + 1;
        }
        const Image a = with.gl.ReadPixels(), b = separate.gl.ReadPixels();
        CHECK(a.rgba == b.rgba);
      }
    }
  }
}

TEST_CASE("primitive restart: compared before the base vertex, off for DrawArrays and when disabled", "[context]") {
  // Elements {0, 1, 2, 3, 39, 5, 6, 7, 8} as a strip: with restart, two runs of 4.
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 39, 5, 6, 7, 8};
  CountingScene a(Ring(), idx, UNSIGNED_SHORT), b(Ring(), idx, UNSIGNED_SHORT);
  a.gl.Enable(PRIMITIVE_RESTART);
  a.gl.PrimitiveRestartIndex(38);  // 39 - 1: the element 39 is not the restart index, whatever basevertex says
  a.gl.DrawElementsBaseVertex(TRIANGLE_STRIP, 9, UNSIGNED_SHORT, 0, -1);
  b.gl.DrawElementsBaseVertex(TRIANGLE_STRIP, 9, UNSIGNED_SHORT, 0, -1);
  CHECK(a.gl.ReadPixels().rgba == b.gl.ReadPixels().rgba);

  CountingScene c(Ring(), idx, UNSIGNED_SHORT), d(Ring(), idx, UNSIGNED_SHORT);
  c.gl.Enable(PRIMITIVE_RESTART);
  c.gl.PrimitiveRestartIndex(39);
  CHECK(c.gl.IsEnabled(PRIMITIVE_RESTART));
  c.gl.DrawElementsBaseVertex(TRIANGLE_STRIP, 9, UNSIGNED_SHORT, 0, 1);  // restarts at 39, then adds 1
  d.gl.DrawElementsBaseVertex(TRIANGLE_STRIP, 4, UNSIGNED_SHORT, 0, 1);
  d.gl.DrawElementsBaseVertex(TRIANGLE_STRIP, 4, UNSIGNED_SHORT, 10, 1);
  CHECK(c.gl.ReadPixels().rgba == d.gl.ReadPixels().rgba);

  // DrawArrays never restarts, and a disabled restart never does.
  CountingScene e(Ring(), idx, UNSIGNED_SHORT), f(Ring(), idx, UNSIGNED_SHORT);
  e.gl.Enable(PRIMITIVE_RESTART);
  e.gl.Enable(PRIMITIVE_RESTART_FIXED_INDEX);
  e.gl.PrimitiveRestartIndex(3);
  e.gl.DrawArrays(TRIANGLE_STRIP, 0, 40);
  f.gl.DrawArrays(TRIANGLE_STRIP, 0, 40);
  CHECK(e.gl.ReadPixels().rgba == f.gl.ReadPixels().rgba);
  e.gl.Disable(PRIMITIVE_RESTART);
  e.gl.Disable(PRIMITIVE_RESTART_FIXED_INDEX);
  e.gl.DrawElement(TRIANGLE_STRIP, 9, UNSIGNED_SHORT, 0);
  f.gl.DrawElement(TRIANGLE_STRIP, 9, UNSIGNED_SHORT, 0);
  CHECK(e.gl.ReadPixels().rgba == f.gl.ReadPixels().rgba);
  // A draw of nothing but restarts draws nothing.
  CountingScene g(Ring(), {39, 39, 39}, UNSIGNED_SHORT);
  g.gl.Enable(PRIMITIVE_RESTART);
  g.gl.PrimitiveRestartIndex(39);
  g.gl.DrawElement(TRIANGLES, 3, UNSIGNED_SHORT, 0);
  CHECK(g.gl.GetError() == NO_ERROR);
  CHECK(CountLit(g.gl) == 0);
}

TEST_CASE("primitive restart across the pieces of large and instanced draws", "[context]") {
  // 70,000 strip elements over the ring, restarting every 9 elements except for one run of 50,000 (longer than a
  // piece), against the runs drawn one by one; then instanced, against the instances drawn one by one.
  std::vector<std::uint32_t> all, ends;
  for (int k = 0; all.size() < 70000; ++k) {
    const int length = k == 500 ? 50000 : 8;
    for (int i = 0; i < length; ++i) all.push_back(std::uint32_t((k * 3 + i) % 39));
    ends.push_back(std::uint32_t(all.size()));
    all.push_back(39);
  }
  CountingScene with(Ring(), all, UNSIGNED_INT), separate(Ring(), all, UNSIGNED_INT);
  with.shader.color = separate.shader.color = glm::vec4(1.0f / 255.0f, 0, 0, 1);
  with.gl.Enable(PRIMITIVE_RESTART);
  with.gl.PrimitiveRestartIndex(39);
  with.gl.DrawElement(TRIANGLE_STRIP, int(all.size()), UNSIGNED_INT, 0);
  std::uint32_t begin = 0;
  for (std::uint32_t end : ends) {
    separate.gl.DrawElement(TRIANGLE_STRIP, int(end - begin), UNSIGNED_INT, std::size_t(begin) * 4);
    begin = end + 1;
  }
  CHECK(with.gl.GetError() == NO_ERROR);
  CHECK(with.gl.ReadPixels().rgba == separate.gl.ReadPixels().rgba);

  // Instanced: every instance draws all its runs (the shader moves instance i to slot i): the quad's two
  // triangles as runs of 3, then an empty run.
  InstanceScene inst(1);
  WideInstanceShader shader;
  inst.gl.UseProgram(shader);
  const std::uint8_t idx[9] = {0, 1, 2, 255, 0, 2, 3, 255, 255};
  inst.gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof idx, idx);
  inst.gl.Enable(PRIMITIVE_RESTART_FIXED_INDEX);
  inst.gl.DrawElementsInstanced(TRIANGLES, 9, UNSIGNED_BYTE, 0, 4);
  CHECK(inst.gl.GetError() == NO_ERROR);
  CHECK(inst.Slots() == std::vector<std::uint32_t>{0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF});
}

TEST_CASE("polygon mode draws edges or vertices", "[context]") {
  Context gl(16, 16);
  SolidShader shader;
  gl.UseProgram(shader);
  auto c = [](float x, float y) { return testing::WindowToClip(x, y, 16, 16); };
  MakeVertexArray(gl, {c(2.5f, 2.5f), c(13.5f, 2.5f), c(13.5f, 13.5f), c(2.5f, 13.5f)});
  gl.PolygonMode(FRONT_AND_BACK, LINE);
  gl.DrawArrays(TRIANGLE_FAN, 0, 4);
  const int edges = CountLit(gl);
  CHECK(edges > 40);
  CHECK(edges < 60);  // outline and diagonal, not the interior (121)
  std::uint8_t px[4];
  gl.ReadPixel(7, 7, px);  // on the diagonal
  CHECK(px[0] == 255);
  gl.ReadPixel(10, 5, px);  // interior
  CHECK(px[0] == 0);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.PolygonMode(FRONT_AND_BACK, POINT);
  gl.DrawArrays(TRIANGLE_FAN, 0, 4);
  CHECK(CountLit(gl) == 4);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.PointSize(3.0f);
  gl.DrawArrays(TRIANGLE_FAN, 0, 4);
  CHECK(CountLit(gl) == 36);
  // Culling applies before the polygon mode: a culled polygon draws no edges.
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Enable(CULL_FACE);
  gl.CullFace(FRONT);
  gl.PolygonMode(FRONT_AND_BACK, LINE);
  gl.DrawArrays(TRIANGLE_FAN, 0, 4);
  CHECK(CountLit(gl) == 0);
}

TEST_CASE("program point size comes from the vertex stage when enabled", "[context]") {
  struct Sized : softgl::Shader<Sized, testing::NoVaryings> {
    void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const {
      out.position = in.attrib[0];
      out.point_size = 4.0f;
    }
    bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
      out.color[0] = glm::vec4(1);
      return true;
    }
  };
  Context gl(16, 16);
  Sized shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {testing::WindowToClip(8, 8, 16, 16)});
  gl.DrawArrays(POINTS, 0, 1);
  CHECK(CountLit(gl) == 1);
  gl.Enable(PROGRAM_POINT_SIZE);
  gl.DrawArrays(POINTS, 0, 1);
  CHECK(CountLit(gl) == 16);
}

namespace {
// gl_PointCoord as the colour (s, t, 0, 1), written wide and scalar; position from attribute 0.
struct WidePointCoord : softgl::Shader<WidePointCoord, WideColor> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideColor>& out) const { out.position = in.attrib[0]; }
  void Fragment(const softgl::FragmentLanes<WideColor>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = softgl::vec4(in.point_coord.x, in.point_coord.y, 0.0f, 1.0f);
  }
};
struct ScalarPointCoord : softgl::Shader<ScalarPointCoord, testing::NoVaryings> {
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>& in, FragmentOut& out) const {
    out.color[0] = glm::vec4(in.point_coord, 0.0f, 1.0f);
    return true;
  }
};
}  // namespace

TEST_CASE("gl_PointCoord runs across each point from (0, 0) to (1, 1), its origin as POINT_SPRITE_COORD_ORIGIN says",
          "[context]") {
  WidePointCoord wide;
  ScalarPointCoord scalar;
  for (const softgl::Program* shader : {static_cast<const softgl::Program*>(&wide), static_cast<const softgl::Program*>(&scalar)})
    for (bool lower_left : {false, true}) {
      INFO((shader == &wide ? "wide" : "scalar") << ", origin " << (lower_left ? "LOWER_LEFT" : "UPPER_LEFT"));
      Context gl(32, 32);
      BindFloatTarget(gl, 32, 32);
      gl.UseProgram(*shader);
      if (lower_left) gl.PointParameteri(POINT_SPRITE_COORD_ORIGIN, int(LOWER_LEFT));
      // Points of size 8 at (8.5, 8.5) and (20, 23.25), size 5 (pixel (2, 28)'s centre), then a triangle and a
      // line, whose fragments read (0, 0); a point after them again.
      MakeVertexArray(gl, {testing::WindowToClip(8.5f, 8.5f, 32, 32), testing::WindowToClip(20.0f, 23.25f, 32, 32),
                           testing::WindowToClip(26, 2, 32, 32), testing::WindowToClip(31, 2, 32, 32),
                           testing::WindowToClip(31, 7, 32, 32), testing::WindowToClip(2.5f, 28.5f, 32, 32)});
      gl.PointSize(8.0f);
      gl.DrawArrays(POINTS, 0, 2);
      gl.DrawArrays(TRIANGLES, 2, 3);
      gl.PointSize(5.0f);
      gl.DrawArrays(POINTS, 5, 1);
      std::vector<float> px(32 * 32 * 4);
      gl.ReadPixels(0, 0, 32, 32, RGBA, FLOAT, px.data());
      const auto at = [&](int x, int y) { return glm::vec2(px[std::size_t(y * 32 + x) * 4], px[std::size_t(y * 32 + x) * 4 + 1]); };
      const auto expect = [&](float cx, float cy, float size, int x, int y) {
        const float s = 0.5f + (float(x) + 0.5f - cx) / size, d = (float(y) + 0.5f - cy) / size;
        return glm::vec2(s, lower_left ? 0.5f + d : 0.5f - d);
      };
      int checked = 0;
      for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
          glm::vec2 want(-1.0f);
          if (x >= 4 && x < 12 && y >= 4 && y < 12) want = expect(8.5f, 8.5f, 8.0f, x, y);
          if (x >= 16 && x < 24 && y >= 19 && y < 27) want = expect(20.0f, 23.25f, 8.0f, x, y);
          if (x >= 0 && x < 5 && y >= 26 && y < 31) want = expect(2.5f, 28.5f, 5.0f, x, y);
          if (want.x < 0.0f) continue;
          INFO("pixel " << x << ", " << y);
          CHECK(std::abs(at(x, y).x - want.x) < 1e-6f);
          CHECK(std::abs(at(x, y).y - want.y) < 1e-6f);
          ++checked;
        }
      CHECK(checked == 64 + 64 + 25);
      // Corners: the first point's pixel centres from 4.5 (its left edge: s = 0) to 11.5 (s = 7/8); t's direction
      // by the origin.
      CHECK(at(4, 4).x == 0.0f);
      CHECK(at(11, 4).x == 0.875f);
      CHECK(at(4, 11).y == (lower_left ? 0.875f : 0.125f));
      CHECK(at(28, 3) == glm::vec2(0.0f));  // inside the triangle
      CHECK(gl.GetError() == NO_ERROR);
    }
}

TEST_CASE("PointParameter: its state, queries and errors; multisampled and polygon-mode points have gl_PointCoord too",
          "[context][errors]") {
  Context gl(16, 16);
  int origin = 0;
  float threshold = -1.0f;
  gl.GetIntegerv(POINT_SPRITE_COORD_ORIGIN, &origin);
  gl.GetFloatv(POINT_FADE_THRESHOLD_SIZE, &threshold);
  CHECK(origin == int(UPPER_LEFT));
  CHECK(threshold == 1.0f);
  gl.PointParameterf(POINT_SPRITE_COORD_ORIGIN, float(LOWER_LEFT));
  gl.PointParameterf(POINT_FADE_THRESHOLD_SIZE, 2.5f);
  gl.GetIntegerv(POINT_SPRITE_COORD_ORIGIN, &origin);
  gl.GetFloatv(POINT_FADE_THRESHOLD_SIZE, &threshold);
  CHECK(origin == int(LOWER_LEFT));
  CHECK(threshold == 2.5f);
  const int upper = int(UPPER_LEFT), four = 4;
  const float zero = 0.0f;
  gl.PointParameteriv(POINT_SPRITE_COORD_ORIGIN, &upper);
  gl.PointParameteriv(POINT_FADE_THRESHOLD_SIZE, &four);
  gl.PointParameterfv(POINT_FADE_THRESHOLD_SIZE, &zero);
  gl.GetIntegerv(POINT_SPRITE_COORD_ORIGIN, &origin);
  gl.GetFloatv(POINT_FADE_THRESHOLD_SIZE, &threshold);
  CHECK(origin == int(UPPER_LEFT));
  CHECK(threshold == 0.0f);
  CHECK(gl.GetError() == NO_ERROR);
  gl.PointParameteri(POINT_SPRITE_COORD_ORIGIN, int(LOWER_LEFT) + 5);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PointParameterf(POINT_SIZE, 3.0f);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.PointParameterf(POINT_FADE_THRESHOLD_SIZE, -1.0f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PointParameterf(POINT_FADE_THRESHOLD_SIZE, std::numeric_limits<float>::quiet_NaN());
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PointParameteri(POINT_FADE_THRESHOLD_SIZE, -3);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.PointParameterfv(POINT_FADE_THRESHOLD_SIZE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetFloatv(POINT_FADE_THRESHOLD_SIZE, &threshold);
  CHECK(threshold == 0.0f);

  // A 4x multisampled context and a triangle drawn as points (POLYGON_MODE POINT): each pixel's gl_PointCoord as
  // at its centre, resolved to 8 bits.
  for (int samples : {1, 4}) {
    INFO(samples << " samples");
    Context::Options options;
    options.samples = samples;
    Context ms(16, 16, options);
    WidePointCoord shader;
    ms.UseProgram(shader);
    ms.PolygonMode(FRONT_AND_BACK, POINT);
    ms.PointSize(6.0f);
    MakeVertexArray(ms, {testing::WindowToClip(4, 4, 16, 16), testing::WindowToClip(12, 4, 16, 16),
                         testing::WindowToClip(8, 11, 16, 16)});
    ms.DrawArrays(TRIANGLES, 0, 3);
    for (auto [cx, cy] : {std::pair{4, 4}, std::pair{12, 4}, std::pair{8, 11}})
      for (int y = cy - 3; y < cy + 3; ++y)
        for (int x = cx - 3; x < cx + 3; ++x) {
          std::uint8_t p[4];
          ms.ReadPixel(x, y, p);
          const float s = 0.5f + (float(x) + 0.5f - float(cx)) / 6.0f, t = 0.5f - (float(y) + 0.5f - float(cy)) / 6.0f;
          INFO("pixel " << x << ", " << y);
          CHECK(std::abs(float(p[0]) - s * 255.0f) <= 0.51f);
          CHECK(std::abs(float(p[1]) - t * 255.0f) <= 0.51f);
        }
  }
}

TEST_CASE("the viewport maps NDC to its rectangle and bounds the fragments", "[context]") {
  Context gl(16, 16);
  SolidShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-2, -2, 0, 1}, {2, -2, 0, 1}, {-2, 2, 0, 1}, {2, 2, 0, 1}});  // beyond the volume
  gl.Viewport(4, 2, 8, 6);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  CHECK(CountLit(gl) == 48);
  std::uint8_t px[4];
  gl.ReadPixel(4, 2, px);
  CHECK(px[0] == 255);
  gl.ReadPixel(12, 2, px);
  CHECK(px[0] == 0);
  gl.ReadPixel(4, 8, px);
  CHECK(px[0] == 0);
}

TEST_CASE("hostile geometry draws nothing wrong and never crashes", "[context]") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Context gl(32, 32);
  SolidShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{nan, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1},               // NaN
                       {inf, -inf, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1},            // infinities
                       {0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0},                 // w = 0
                       {-1e30f, -1e30f, 0, 1}, {1e30f, -1e30f, 0, 1}, {0, 1e30f, 0, 1},  // huge: covers all
                       {0.1f, 0.1f, 0, -1}, {0.5f, 0.1f, 0, -1}, {0.1f, 0.5f, 0, -1}});  // behind the eye
  for (Enum mode : {TRIANGLES, LINES, LINE_LOOP, POINTS, TRIANGLE_STRIP}) {
    gl.Clear(COLOR_BUFFER_BIT);
    gl.DrawArrays(mode, 0, 15);
    CHECK(gl.GetError() == NO_ERROR);
  }
  gl.Clear(COLOR_BUFFER_BIT);
  gl.DrawArrays(TRIANGLES, 9, 3);
  CHECK(CountLit(gl) == 32 * 32);  // the huge triangle is clipped, not overflowed
  gl.Clear(COLOR_BUFFER_BIT);
  gl.DrawArrays(TRIANGLES, 0, 9);
  gl.DrawArrays(TRIANGLES, 12, 3);
  CHECK(CountLit(gl) == 0);
}

TEST_CASE("zero-sized and oversized framebuffers", "[context]") {
  Context empty(0, 0);
  CHECK(empty.GetError() == NO_ERROR);
  SolidShader shader;
  empty.UseProgram(shader);
  MakeVertexArray(empty, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}});
  empty.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  empty.DrawArrays(TRIANGLES, 0, 3);
  CHECK(empty.GetError() == NO_ERROR);
  CHECK(empty.ReadPixels().rgba.empty());
  CHECK(empty.ReadDepth(0, 0) == 0.0f);

  Context too_big(kMaxFramebufferSize + 1, 4);
  CHECK(too_big.GetError() == INVALID_VALUE);
  CHECK(too_big.Width() == 0);
  Context negative(-4, 4);
  CHECK(negative.GetError() == INVALID_VALUE);

  Context one(1, 1);
  one.UseProgram(shader);
  MakeVertexArray(one, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  one.DrawArrays(TRIANGLES, 0, 3);
  CHECK(CountLit(one) == 1);
}

TEST_CASE("ReadPixels returns rows top first", "[context]") {
  Context gl(2, 2);
  SolidShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 0, 0, 1}, {1, 0, 0, 1}});  // bottom row only
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  const Image img = gl.ReadPixels();
  CHECK(img.At(0, 1)[0] == 255);  // bottom row of the window is the last row of the image
  CHECK(img.At(0, 0)[0] == 0);
}

TEST_CASE("ReadPixels with a format and type: layouts, conversions, rectangles partly outside", "[context]") {
  Context gl(4, 3);
  gl.ClearColor(1.0f, 0.5f, 0.0f, 0.25f);  // bytes 255, 128, 0, 64
  gl.ClearDepth(0.75);
  gl.ClearStencil(7);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT);
  SECTION("RGB bytes with rows padded to 4, and a rectangle half outside") {
    std::vector<std::uint8_t> out(3 * 8, 0xCD);  // 3 rows of 2 pixels: 6 bytes padded to 8
    gl.ReadPixels(3, 1, 2, 3, RGB, UNSIGNED_BYTE, out.data());
    CHECK(gl.GetError() == NO_ERROR);
    // Row 0 (window y 1): pixel x 3 written, x 4 outside; row 2 (window y 3) outside altogether.
    CHECK(std::vector<std::uint8_t>(out.begin(), out.begin() + 8) ==
          std::vector<std::uint8_t>{255, 128, 0, 0xCD, 0xCD, 0xCD, 0xCD, 0xCD});
    CHECK(out[8] == 255);
    CHECK(out[16] == 0xCD);
  }
  SECTION("BGRA, row length and skips") {
    gl.PixelStore(PACK_ALIGNMENT, 1);
    gl.PixelStore(PACK_ROW_LENGTH, 3);
    gl.PixelStore(PACK_SKIP_PIXELS, 1);
    gl.PixelStore(PACK_SKIP_ROWS, 1);
    std::vector<std::uint8_t> out(3 * 4 * 3, 0xCD);
    gl.ReadPixels(0, 0, 2, 2, BGRA, UNSIGNED_BYTE, out.data());
    CHECK(out[0] == 0xCD);  // the skipped row
    const std::size_t first = (3 + 1) * 4;  // one row of 3 pixels, then one pixel in
    CHECK(std::vector<std::uint8_t>(out.begin() + first, out.begin() + first + 4) ==
          std::vector<std::uint8_t>{0, 128, 255, 64});
    CHECK(out[first + 8] == 0xCD);  // third pixel of the row: not part of the rectangle
  }
  SECTION("floats, shorts, depth, stencil and DEPTH_STENCIL") {
    float f[4] = {};
    gl.ReadPixels(0, 0, 1, 1, RGBA, FLOAT, f);
    CHECK(f[1] == 128.0f / 255.0f);
    CHECK(f[3] == 64.0f / 255.0f);
    std::uint16_t h[2] = {};
    gl.ReadPixels(1, 1, 1, 1, RG, UNSIGNED_SHORT, h);
    CHECK((h[0] == 65535 && h[1] == 128 * 257));
    float d = 0;
    gl.ReadPixels(2, 2, 1, 1, DEPTH_COMPONENT, FLOAT, &d);
    CHECK(d == 0.75f);
    std::uint32_t u = 0;
    gl.ReadPixels(2, 2, 1, 1, DEPTH_COMPONENT, UNSIGNED_INT, &u);
    CHECK(u == std::uint32_t(std::llround(0.75 * 4294967295.0)));
    std::uint8_t st = 0;
    gl.ReadPixels(0, 2, 1, 1, STENCIL_INDEX, UNSIGNED_BYTE, &st);
    CHECK(st == 7);
    float sf = 0;
    gl.ReadPixels(0, 2, 1, 1, STENCIL_INDEX, FLOAT, &sf);
    CHECK(sf == 7.0f);  // an index, not normalized
    std::uint32_t ds = 0;
    gl.ReadPixels(3, 0, 1, 1, DEPTH_STENCIL, UNSIGNED_INT_24_8, &ds);
    CHECK(ds == (std::uint32_t(std::llround(0.75 * 16777215.0)) << 8 | 7));
    CHECK(gl.GetError() == NO_ERROR);
  }
  SECTION("errors") {
    std::uint8_t out[64];
    gl.ReadPixels(0, 0, 1, 1, RGBA + 100, UNSIGNED_BYTE, out);
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_INT_24_8 + 100, out);
    CHECK(gl.GetError() == INVALID_ENUM);
    gl.ReadPixels(0, 0, -1, 1, RGBA, UNSIGNED_BYTE, out);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.ReadPixels(0, 0, 1, 1, DEPTH_STENCIL, FLOAT, out);
    CHECK(gl.GetError() == INVALID_ENUM);  // OpenGL 3.3, section 4.3.1
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_INT_24_8, out);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.PixelStore(PACK_ALIGNMENT, 3);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.PixelStore(PACK_ROW_LENGTH, -1);
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.ReadPixels(0, 0, 4, 3, RGBA, UNSIGNED_BYTE, nullptr);  // nothing to write to: refused
    CHECK(gl.GetError() == INVALID_VALUE);
    gl.ReadPixels(0, 0, 0, 3, RGBA, UNSIGNED_BYTE, nullptr);  // nothing to write: no error
    CHECK(gl.GetError() == NO_ERROR);
    // A framebuffer object without a depth attachment has no depth to read; an incomplete one cannot be read.
    const std::uint32_t fbo = gl.GenFramebuffer(), tex = gl.GenTexture();
    gl.BindTexture(TEXTURE_2D, tex);
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, out);
    CHECK(gl.GetError() == INVALID_FRAMEBUFFER_OPERATION);
    gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, tex, 0);
    gl.ReadPixels(0, 0, 1, 1, DEPTH_COMPONENT, FLOAT, out);
    CHECK(gl.GetError() == INVALID_OPERATION);
    gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, out);
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("ReadPixels reads a float attachment as stored, and clamps it for bytes", "[context]") {
  Context gl(2, 2);
  BindFloatTarget(gl, 2, 2);
  gl.ClearColor(2.5f, -1.0f, 0.5f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  float f[4] = {};
  gl.ReadPixels(1, 1, 1, 1, RGBA, FLOAT, f);
  CHECK((f[0] == 2.5f && f[1] == -1.0f && f[2] == 0.5f));
  std::uint8_t b[4] = {};
  gl.ReadPixels(1, 1, 1, 1, RGBA, UNSIGNED_BYTE, b);
  CHECK((b[0] == 255 && b[1] == 0 && b[2] == 128));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("state queries: bindings, conversions, limits, strings and errors", "[context]") {
  Context gl(40, 30);
  int v[4] = {-7, -7, -7, -7};
  gl.GetIntegerv(VIEWPORT, v);
  CHECK((v[0] == 0 && v[1] == 0 && v[2] == 40 && v[3] == 30));
  // Bindings report the ids bound.
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer(), ebo = gl.GenBuffer(), tex = gl.GenTexture();
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  gl.ActiveTexture(TEXTURE0 + 3);
  gl.BindTexture(TEXTURE_2D, tex);
  gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
  const std::pair<Enum, int> bindings[] = {{VERTEX_ARRAY_BINDING, int(vao)}, {ARRAY_BUFFER_BINDING, int(vbo)},
                                           {ELEMENT_ARRAY_BUFFER_BINDING, int(ebo)}, {ACTIVE_TEXTURE, int(TEXTURE0 + 3)},
                                           {TEXTURE_BINDING_2D, int(tex)}, {TEXTURE_BINDING_CUBE_MAP, 0},
                                           {READ_FRAMEBUFFER_BINDING, int(fbo)}, {DRAW_FRAMEBUFFER_BINDING, 0}};
  for (const auto& [name, id] : bindings) {
    INFO("name 0x" << std::hex << name);
    gl.GetIntegerv(name, v);
    CHECK(v[0] == id);
  }
  gl.BindVertexArray(0);
  gl.GetIntegerv(ELEMENT_ARRAY_BUFFER_BINDING, v);  // part of the vertex array: none bound, none to report
  CHECK(v[0] == 0);
  // Conversions: booleans to 0 / 1, floats rounded, colours mapped linearly onto the integers.
  gl.Enable(BLEND);
  bool b[4] = {};
  gl.GetBooleanv(BLEND, b);
  CHECK(b[0]);
  float f[4] = {};
  gl.GetFloatv(BLEND, f);
  CHECK(f[0] == 1.0f);
  gl.PointSize(2.6f);
  gl.GetIntegerv(POINT_SIZE, v);
  CHECK(v[0] == 3);
  gl.ClearColor(1.0f, 0.5f, 0.0f, -1.0f);
  std::int64_t w[4] = {};
  gl.GetInteger64v(COLOR_CLEAR_VALUE, w);
  CHECK((w[0] == 2147483647 && w[1] == 1073741823 && w[2] == 0 && w[3] == -2147483647));
  gl.ColorMask(true, false, true, false);
  gl.GetIntegerv(COLOR_WRITEMASK, v);
  CHECK((v[0] == 1 && v[1] == 0 && v[2] == 1 && v[3] == 0));
  gl.StencilFunc(GEQUAL, 999, 0x0F);
  gl.GetIntegerv(STENCIL_REF, v);
  CHECK(v[0] == 255);  // clamped to the 8-bit stencil buffer's range
  gl.GetIntegerv(STENCIL_FUNC, v);
  CHECK(v[0] == int(GEQUAL));
  // Limits are softgl's own constants.
  gl.GetIntegerv(MAX_VERTEX_ATTRIBS, v);
  CHECK(v[0] == kMaxVertexAttribs);
  gl.GetIntegerv(MAX_TEXTURE_SIZE, v);
  CHECK(v[0] == kMaxTextureSize);
  gl.GetIntegerv(MAX_DRAW_BUFFERS, v);
  CHECK(v[0] == 8);  // OpenGL 3.3's minimum
  gl.GetIntegerv(MAX_VIEWPORT_DIMS, v);
  CHECK((v[0] == kMaxFramebufferSize && v[1] == kMaxFramebufferSize));
  gl.GetIntegerv(MAJOR_VERSION, v);
  gl.GetIntegerv(MINOR_VERSION, v + 1);
  CHECK((v[0] == 3 && v[1] == 3));
  CHECK(std::string(gl.GetString(VERSION)).rfind("3.3 softgl ", 0) == 0);
  CHECK(std::string(gl.GetString(VENDOR)) == "softgl");
  CHECK(gl.GetError() == NO_ERROR);
  // An unknown name: INVALID_ENUM, nothing written.
  v[0] = -7;
  gl.GetIntegerv(0x1234, v);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(v[0] == -7);
  gl.GetFloatv(0x1234, f);
  CHECK(gl.GetError() == INVALID_ENUM);
  CHECK(gl.GetString(0x1234) == nullptr);
  CHECK(gl.GetError() == INVALID_ENUM);
}

TEST_CASE("queries: samples passed, primitives generated, time elapsed, and their errors", "[context]") {
  for (int threads : {1, 3}) {
    INFO(threads << " threads");
    Context gl(64, 64, Context::Options{threads});
    SolidShader shader;
    gl.UseProgram(shader);
    gl.Enable(DEPTH_TEST);
    MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1},              // full screen
                         {-1, -1, 0.5f, 1}, {0, -1, 0.5f, 1}, {-1, 1, 0.5f, 1}, {0, 1, 0.5f, 1}});  // left half, behind
    std::uint32_t q[4];
    gl.GenQueries(4, q);
    gl.BeginQuery(SAMPLES_PASSED, q[0]);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    gl.EndQuery(SAMPLES_PASSED);
    gl.BeginQuery(ANY_SAMPLES_PASSED, q[1]);
    gl.DrawArrays(TRIANGLE_STRIP, 4, 4);  // wholly behind the first
    gl.EndQuery(ANY_SAMPLES_PASSED);
    // Re-begun before its result was read: the second run counts on its own (the draws of the first are still
    // only recorded).
    gl.BeginQuery(SAMPLES_PASSED, q[0]);
    gl.Clear(DEPTH_BUFFER_BIT);
    gl.DrawArrays(TRIANGLE_STRIP, 4, 4);
    gl.EndQuery(SAMPLES_PASSED);
    gl.BeginQuery(PRIMITIVES_GENERATED, q[2]);
    gl.DrawArraysInstanced(TRIANGLE_STRIP, 0, 4, 3);  // 2 triangles x 3 instances
    gl.DrawArrays(LINE_LOOP, 0, 5);                   // 5 lines
    gl.Enable(SCISSOR_TEST);
    gl.Scissor(0, 0, 0, 0);
    gl.DrawArrays(TRIANGLES, 0, 7);  // 2 triangles, though nothing can be drawn
    gl.Disable(SCISSOR_TEST);
    gl.EndQuery(PRIMITIVES_GENERATED);
    gl.BeginQuery(TIME_ELAPSED, q[3]);
    gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    gl.EndQuery(TIME_ELAPSED);
    std::uint64_t r = 0;
    int available = 0;
    gl.GetQueryObjectiv(q[0], QUERY_RESULT_AVAILABLE, &available);
    CHECK(available == 1);
    gl.GetQueryObjectui64v(q[0], QUERY_RESULT, &r);
    CHECK(r == 32 * 64);
    std::uint32_t any = 7;
    gl.GetQueryObjectuiv(q[1], QUERY_RESULT, &any);
    CHECK(any == 0);
    std::int64_t prims = 0;
    gl.GetQueryObjecti64v(q[2], QUERY_RESULT, &prims);
    CHECK(prims == 13);
    gl.GetQueryObjectui64v(q[3], QUERY_RESULT, &r);
    CHECK(r > 0);
    CHECK(gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("queries: discarded fragments and failed tests do not count; the errors", "[context][errors]") {
  Context gl(16, 16);
  struct HalfDiscard : softgl::Shader<HalfDiscard, WideColor> {
    void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideColor>& out) const {
      out.position = in.attrib[0];
    }
    void Fragment(const softgl::FragmentLanes<WideColor>& in, softgl::FragmentLanesOut& out) const {
      out.color[0] = softgl::vec4(1.0f);
      out.Discard(in.frag_coord.x < 8.0f);
    }
  } shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1}});
  const std::uint32_t q = gl.GenQuery(), other = gl.GenQuery();
  gl.Enable(SCISSOR_TEST);
  gl.Scissor(0, 0, 16, 4);
  gl.BeginQuery(SAMPLES_PASSED, q);
  int current = 0;
  gl.GetQueryiv(SAMPLES_PASSED, CURRENT_QUERY, &current);
  CHECK(current == int(q));
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  // The errors, while q is active.
  gl.BeginQuery(SAMPLES_PASSED, other);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BeginQuery(ANY_SAMPLES_PASSED, other);  // one occlusion query at a time
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BeginQuery(PRIMITIVES_GENERATED, q);  // q is active elsewhere
  CHECK(gl.GetError() == INVALID_OPERATION);
  std::uint64_t r = 0;
  gl.GetQueryObjectui64v(q, QUERY_RESULT, &r);  // still active
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.EndQuery(SAMPLES_PASSED);
  gl.GetQueryObjectui64v(q, QUERY_RESULT, &r);
  CHECK(r == 8 * 4);  // the right half of the scissored rows
  gl.BeginQuery(PRIMITIVES_GENERATED, q);  // begun before with SAMPLES_PASSED
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.EndQuery(TIME_ELAPSED);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BeginQuery(0x1234, q);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BeginQuery(SAMPLES_PASSED, 999);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetQueryObjectui64v(other, QUERY_RESULT, &r);  // never begun
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetQueryObjectui64v(q, 0x1234, &r);
  CHECK(gl.GetError() == INVALID_ENUM);
  // Deleting an active query ends it; the draws recorded for it still render safely.
  gl.BeginQuery(SAMPLES_PASSED, other);
  gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  gl.DeleteQuery(other);
  CHECK(!gl.IsQuery(other));
  gl.GetQueryiv(SAMPLES_PASSED, CURRENT_QUERY, &current);
  CHECK(current == 0);
  gl.Finish();
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("CopyTexImage2D, CopyTexSubImage2D and GetTexImage", "[context]") {
  Context gl(8, 8);
  gl.ClearColor(1.0f, 0.5f, 0.0f, 1.0f);
  gl.ClearDepth(0.25);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.Enable(SCISSOR_TEST);  // the top-right 4 x 4 pixels blue
  gl.Scissor(4, 4, 4, 4);
  gl.ClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Disable(SCISSOR_TEST);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  // A 6 x 6 copy from (3, 3): 5 x 5 of it inside the framebuffer, the rest outside (zero).
  gl.CopyTexImage2D(TEXTURE_2D, 0, RGBA8, 3, 3, 6, 6, 0);
  REQUIRE(gl.GetError() == NO_ERROR);
  std::vector<std::uint8_t> texels(6 * 6 * 4, 0xCD);
  gl.PixelStore(PACK_ALIGNMENT, 1);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  auto at = [&](int i, int j) {
    const std::uint8_t* p = &texels[(std::size_t(j) * 6 + std::size_t(i)) * 4];
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
  };
  CHECK(at(0, 0) == 0xFF8000FFu);  // framebuffer (3, 3): orange
  CHECK(at(1, 1) == 0x0000FFFFu);  // (4, 4): blue
  CHECK(at(4, 4) == 0x0000FFFFu);  // (7, 7)
  CHECK(at(5, 5) == 0x00000000u);  // (8, 8): outside, zero
  // CopyTexSubImage2D overwrites part of the level: framebuffer (0, 0) .. (1, 1) to texel (4, 0).
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 4, 0, 0, 0, 2, 2);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  CHECK(at(4, 0) == 0xFF8000FFu);
  CHECK(at(5, 1) == 0xFF8000FFu);
  CHECK(at(3, 0) == 0xFF8000FFu);  // (6, 3) of the first copy, untouched
  // Other formats and types through GetTexImage.
  float f[6 * 6] = {};
  gl.GetTexImage(TEXTURE_2D, 0, GREEN, FLOAT, f);
  CHECK(f[0] == 128.0f / 255.0f);
  // Depth: a depth texture copies the depth buffer.
  const std::uint32_t depth_tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, depth_tex);
  gl.CopyTexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT, 0, 0, 2, 2, 0);
  float d[4] = {};
  gl.GetTexImage(TEXTURE_2D, 0, DEPTH_COMPONENT, FLOAT, d);
  CHECK((d[0] == 0.25f && d[3] == 0.25f));
  CHECK(gl.GetError() == NO_ERROR);
  // Errors.
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, f);  // colour data from a depth texture
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetTexImage(TEXTURE_2D, 0, STENCIL_INDEX, UNSIGNED_BYTE, f);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetTexImage(TEXTURE_2D, -1, DEPTH_COMPONENT, FLOAT, f);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 1, 1, 0, 0, 2, 2);  // past the 2 x 2 level
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyTexSubImage2D(TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1);  // level 1 not defined
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CopyTexImage2D(TEXTURE_2D, 0, RGBA8, 0, 0, 2, 2, 1);  // border
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.CopyTexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X, 0, RGBA8, 0, 0, 2, 2, 0);  // nothing bound to the cube target
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.CopyTexImage2D(TEXTURE_2D + 1, 0, RGBA8, 0, 0, 2, 2, 0);
  CHECK(gl.GetError() == INVALID_ENUM);
  // A framebuffer object with colour only: no depth to copy from; an incomplete one cannot be read.
  const std::uint32_t fbo = gl.GenFramebuffer(), color = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, color);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
  CHECK(gl.GetError() == INVALID_FRAMEBUFFER_OPERATION);
  gl.FramebufferTexture2D(FRAMEBUFFER, COLOR_ATTACHMENT0, TEXTURE_2D, color, 0);
  gl.BindTexture(TEXTURE_2D, depth_tex);
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
  CHECK(gl.GetError() == INVALID_OPERATION);
}

TEST_CASE("the debug callback reports every error with the call's name", "[context][errors]") {
  Context gl(4, 4);
  struct Report {
    Enum error;
    std::string call, message;
  };
  std::vector<Report> reports;
  gl.DebugMessageCallback([&](Enum e, const char* call, const char* message) { reports.push_back({e, call, message}); });
  gl.BindBuffer(ARRAY_BUFFER, 42);
  gl.Enable(0x1234);
  REQUIRE(reports.size() == 2);
  CHECK(reports[0].error == INVALID_OPERATION);
  CHECK(reports[0].call == "BindBuffer");
  CHECK(reports[0].message.find("GenBuffer") != std::string::npos);
  CHECK(reports[1].error == INVALID_ENUM);
  CHECK(reports[1].call == "Enable");
  CHECK(gl.GetError() == INVALID_OPERATION);  // GetError still keeps only the first
  gl.DebugMessageCallback(nullptr);
  gl.Enable(0x1234);
  CHECK(reports.size() == 2);
}

TEST_CASE("large draws go through in pieces with the same result", "[context]") {
  // A triangle strip, a fan and a line loop of more than 100,000 vertices, against the same primitives given as
  // independent triangles and lines (additive blending counts every hit, so a missed or doubled primitive shows).
  constexpr int kN = 100001;
  std::vector<glm::vec4> strip, fan, loop;
  for (int i = 0; i < kN; ++i) {
    const float t = float(i) / float(kN - 1);
    strip.push_back({-0.9f + 1.8f * t, (i % 2 ? 0.2f : -0.2f) + 0.3f * std::sin(t * 40.0f), 0, 1});
    const float a = 6.2831853f * t;
    fan.push_back(i == 0 ? glm::vec4(0, 0, 0, 1) : glm::vec4(0.8f * std::cos(a), 0.8f * std::sin(a), 0, 1));
    loop.push_back({0.7f * std::cos(a * 3), 0.7f * std::sin(a * 2), 0, 1});
  }
  auto as_list = [](const std::vector<glm::vec4>& v, Enum mode) {
    std::vector<glm::vec4> out;
    const int n = int(v.size());
    if (mode == TRIANGLE_STRIP)
      for (int i = 0; i + 2 < n; ++i) {
        if (i % 2) out.insert(out.end(), {v[i + 1], v[i], v[i + 2]});
        else out.insert(out.end(), {v[i], v[i + 1], v[i + 2]});
      }
    if (mode == TRIANGLE_FAN)
      for (int i = 1; i + 1 < n; ++i) out.insert(out.end(), {v[0], v[i], v[i + 1]});
    if (mode == LINE_LOOP)
      for (int i = 0; i < n; ++i) out.insert(out.end(), {v[i], v[(i + 1) % n]});
    return out;
  };
  struct Case {
    std::vector<glm::vec4>* v;
    Enum mode, list_mode;
  };
  for (const Case& c : {Case{&strip, TRIANGLE_STRIP, TRIANGLES}, Case{&fan, TRIANGLE_FAN, TRIANGLES},
                        Case{&loop, LINE_LOOP, LINES}}) {
    INFO("mode " << c.mode);
    Image images[2];
    for (int pass = 0; pass < 2; ++pass) {
      Context gl(96, 96);
      SolidShader shader;
      shader.color = glm::vec4(8.0f / 255.0f, 0, 0, 1);
      gl.UseProgram(shader);
      gl.Enable(BLEND);
      gl.BlendFunc(ONE, ONE);
      const std::vector<glm::vec4> data = pass == 0 ? *c.v : as_list(*c.v, c.mode);
      MakeVertexArray(gl, data);
      gl.DrawArrays(pass == 0 ? c.mode : c.list_mode, 0, int(data.size()));
      CHECK(gl.GetError() == NO_ERROR);
      images[pass] = gl.ReadPixels();
    }
    CHECK(images[0].rgba == images[1].rgba);
  }
}

TEST_CASE("a draw of 100 million vertices completes without exhausting memory", "[context][slow]") {
  Context gl(16, 16);
  SolidShader shader;
  gl.UseProgram(shader);
  gl.BindVertexArray(gl.GenVertexArray());  // no attribute enabled: every vertex reads (0, 0, 0, 1)
  gl.DrawArrays(TRIANGLES, 0, 100000000);
  CHECK(gl.GetError() == NO_ERROR);
  CHECK(CountLit(gl) == 0);  // all degenerate
}

TEST_CASE("the largest framebuffer, 16384 x 16384, works", "[context][slow]") {
  Context gl(kMaxFramebufferSize, kMaxFramebufferSize);
  REQUIRE(gl.GetError() == NO_ERROR);
  REQUIRE(gl.Width() == kMaxFramebufferSize);
  SolidShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{0.999f, 0.999f, 0, 1}, {1.5f, 0.999f, 0, 1}, {0.999f, 1.5f, 0, 1}});  // the top-right corner
  gl.DrawArrays(TRIANGLES, 0, 3);
  std::uint8_t px[4];
  gl.ReadPixel(kMaxFramebufferSize - 1, kMaxFramebufferSize - 1, px);
  CHECK(px[0] == 255);
  gl.ReadPixel(0, 0, px);
  CHECK(px[0] == 0);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("Delete*s, GetDoublev and Flush", "[context]") {
  Context gl(4, 4);
  std::uint32_t buffers[3], arrays[2], textures[2], framebuffers[2], renderbuffers[2], queries[2];
  gl.GenBuffers(3, buffers);
  gl.GenVertexArrays(2, arrays);
  gl.GenTextures(2, textures);
  gl.GenFramebuffers(2, framebuffers);
  gl.GenRenderbuffers(2, renderbuffers);
  gl.GenQueries(2, queries);
  const std::uint32_t two[2] = {buffers[0], 999};  // an unknown id is ignored
  gl.DeleteBuffers(2, two);
  CHECK(!gl.IsBuffer(buffers[0]));
  CHECK(gl.IsBuffer(buffers[1]));
  gl.DeleteBuffers(2, buffers + 1);
  gl.DeleteVertexArrays(2, arrays);
  gl.DeleteTextures(2, textures);
  gl.DeleteFramebuffers(2, framebuffers);
  gl.DeleteRenderbuffers(2, renderbuffers);
  gl.DeleteQueries(2, queries);
  CHECK(gl.GetError() == NO_ERROR);
  for (int k = 0; k < 2; ++k) {
    CHECK(!gl.IsBuffer(buffers[k + 1]));
    CHECK(!gl.IsVertexArray(arrays[k]));
    CHECK(!gl.IsTexture(textures[k]));
    CHECK(!gl.IsFramebuffer(framebuffers[k]));
    CHECK(!gl.IsRenderbuffer(renderbuffers[k]));
    CHECK(!gl.IsQuery(queries[k]));
  }
  gl.DeleteTextures(-1, textures);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.DepthRange(0.25, 0.75);
  double range[2] = {0, 0};
  gl.GetDoublev(DEPTH_RANGE, range);
  CHECK((range[0] == 0.25 && range[1] == 0.75));
  gl.GetDoublev(0x1234, range);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClearColor(1, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.Flush();
  std::uint8_t px[4];
  gl.ReadPixel(0, 0, px);
  CHECK(px[0] == 255);
}

namespace {

// SolidShader with a member whose use count tells how many copies of the shader are alive.
struct HeldShader : softgl::Shader<HeldShader, testing::NoVaryings> {
  std::shared_ptr<int> held = std::make_shared<int>(0);
  int uniform = 0;
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
    out.color[0] = glm::vec4(1.0f);
    return true;
  }
};

}  // namespace

TEST_CASE("the copies of a shader taken at draws live until the frame is rendered", "[context]") {
  Context gl(8, 8);
  HeldShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}});
  for (int frame = 0; frame < 3; ++frame) {  // the context reuses its draw records from frame to frame
    for (int k = 0; k < 5; ++k) {
      shader.uniform = k / 2;  // changed before draws 0, 2 and 4
      gl.DrawArrays(TRIANGLES, 0, 3);
    }
    CHECK(shader.held.use_count() == 4);  // one copy per change: draws of an unchanged shader use it again
    CHECK(CountLit(gl) > 0);
    CHECK(shader.held.use_count() == 1);  // all released by the rendering
  }
}

namespace {

// Colour from a uniform held in a std::vector, changed in place between draws.
struct VectorUniformShader : softgl::Shader<VectorUniformShader, testing::NoVaryings> {
  std::vector<float> red{0.0f};
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>&, FragmentOut& out) const {
    out.color[0] = glm::vec4(red[0], 0.0f, 0.0f, 1.0f);
    return true;
  }
};

}  // namespace

TEST_CASE("a shader changed between draws renders each draw as it was, also where only owned memory changed",
          "[context]") {
  // Draws of an unchanged shader share one copy (and render as one draw); a change anywhere in the shader, also
  // inside memory a member owns, gives the next draw a copy of its own.
  Context gl(8, 8);
  VectorUniformShader shader;
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {0, -1, 0, 1}, {-1, 1, 0, 1}, {0, -1, 0, 1}, {1, -1, 0, 1}, {0, 1, 0, 1},
                       {-1, 1, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}});
  shader.red[0] = 0.2f;
  gl.DrawArrays(TRIANGLES, 0, 3);  // the lower left corner
  gl.DrawArrays(TRIANGLES, 6, 3);  // the middle, with the shader unchanged
  shader.red[0] = 0.6f;
  gl.DrawArrays(TRIANGLES, 3, 3);  // the lower right corner
  std::uint8_t left[4], middle[4], right[4];
  gl.ReadPixel(0, 0, left);
  gl.ReadPixel(3, 5, middle);
  gl.ReadPixel(7, 0, right);
  CHECK(int(left[0]) == 51);
  CHECK(int(middle[0]) == 51);
  CHECK(int(right[0]) == 153);
}

TEST_CASE("draws in a row with the same shader copy keep their own scissor and operations", "[context]") {
  // Consecutive draws of an unchanged shader render as one draw only where their state is the same: a scissor or
  // a colour mask changed between them still applies to the draw after the change only.
  Context gl(8, 8);
  testing::SolidShader shader;  // white; no member that owns memory, so the draws share one copy
  gl.UseProgram(shader);
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  gl.Enable(SCISSOR_TEST);
  gl.Scissor(0, 0, 4, 8);
  gl.DrawArrays(TRIANGLES, 0, 3);  // the left half
  gl.Scissor(4, 0, 4, 8);
  gl.DrawArrays(TRIANGLES, 0, 3);  // the right half
  CHECK(CountLit(gl) == 64);
  gl.Disable(SCISSOR_TEST);
  gl.ClearColor(0, 0, 0, 1);
  gl.Clear(COLOR_BUFFER_BIT);
  gl.ColorMask(false, true, true, true);
  gl.DrawArrays(TRIANGLES, 0, 3);  // red masked: nothing changes
  gl.ColorMask(true, true, true, true);
  gl.DrawArrays(TRIANGLES, 0, 3);  // red written
  std::uint8_t px[4];
  gl.ReadPixel(5, 5, px);
  CHECK(int(px[0]) == 255);
}

namespace {

// A linear congruential generator: floats in [0, 1), the same sequence on every platform.
struct Lcg {
  std::uint32_t seed;
  float operator()() {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 24);
  }
};

// The number of distinct RGBA values in an image.
std::size_t CountColours(const Image& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 4 <= image.rgba.size(); i += 4) {
    std::uint32_t c;
    std::memcpy(&c, &image.rgba[i], 4);
    colours.insert(c);
  }
  return colours.size();
}

}  // namespace

TEST_CASE("many small draws in one frame render what they render one frame each, at any thread count", "[context]") {
  // Consecutive small draws share their binned batch; each tile walks it draw by draw. Overlapping triangles,
  // lines and points in many colours, blended and not, with a larger draw, a clear, a scissor and a shader with
  // varyings in between, recorded as one frame, at 1 and at 3 threads, against the same draws each padded with
  // more than a thousand primitives that draw nothing (clipped away): draws that large bin into batches of their
  // own.
  std::vector<glm::vec4> positions, values;
  Lcg random{12345};
  for (int i = 0; i < 3 * 400; ++i) {  // 400 triangles of 0.05 to 0.3 in NDC, some across tile edges
    if (i % 3 == 0) {
      const float x = random() * 2.0f - 1.0f, y = random() * 2.0f - 1.0f, size = 0.05f + 0.25f * random();
      positions.insert(positions.end(), {{x, y, 0, 1}, {x + size, y, 0, 1}, {x, y + size, 0, 1}});
    }
    values.push_back({random(), random(), random(), 1});
  }
  for (int i = 0; i < 3 * 1500; ++i) positions.push_back({random() * 2 - 1, random() * 2 - 1, 0, 1});  // tiny
  values.resize(positions.size(), glm::vec4(0.5f));
  positions.insert(positions.end(), {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});  // the whole target
  positions.push_back({5, 5, 0, 1});  // outside the view volume
  values.resize(positions.size(), glm::vec4(0.25f));
  const auto outside = std::uint32_t(positions.size() - 1);

  auto render = [&](int threads, bool padded) {
    Context gl(200, 150, Context::Options{threads});
    SolidShader solid;
    testing::CaptureShader varying;
    MakeVertexArray(gl, positions, values);
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    std::vector<std::uint32_t> indices;
    auto draw = [&](Enum mode, int first, int count) {
      if (!padded) return gl.DrawArrays(mode, first, count);
      indices.clear();
      const int per = mode == TRIANGLES ? 3 : mode == LINES ? 2 : 1;  // a partial primitive's vertices are left out
      for (int k = 0; k < count - count % per; ++k) indices.push_back(std::uint32_t(first + k));
      indices.insert(indices.end(), 3 * 1100, outside);
      gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
      gl.DrawElement(mode, int(indices.size()), UNSIGNED_INT, 0);
    };
    gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.UseProgram(solid);
    for (int d = 0; d < 300; ++d) {
      solid.color = glm::vec4(random(), random(), random(), 0.5f);
      if (d == 100) {
        gl.Enable(BLEND);
        gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
      }
      if (d == 150) {  // a draw of 1,500 triangles: batches of its own
        gl.DrawArrays(TRIANGLES, 1200, 3 * 1500);
      }
      if (d == 160) {
        gl.Enable(SCISSOR_TEST);
        gl.Scissor(30, 20, 100, 90);
        gl.Clear(COLOR_BUFFER_BIT);
      }
      if (d == 200) gl.Disable(SCISSOR_TEST);
      if (d == 220) gl.UseProgram(varying);  // four floats of varyings
      if (d == 240) gl.UseProgram(solid);
      if (d == 260) {
        draw(TRIANGLES, 1200 + 3 * 1500, 3);  // one triangle over every tile
      }
      const int first = 3 * ((d * 7) % 395);
      const Enum mode = d % 10 == 3 ? LINES : d % 10 == 7 ? POINTS : TRIANGLES;
      draw(mode, first, 3 + 3 * (d % 3));
    }
    CHECK(gl.GetError() == NO_ERROR);
    return gl.ReadPixels();
  };
  const std::uint32_t start = random.seed;
  const Image one_frame = render(1, false);
  random.seed = start;
  const Image padded = render(1, true);
  random.seed = start;
  const Image threaded = render(3, false);
  CHECK(one_frame.rgba == padded.rgba);
  CHECK(one_frame.rgba == threaded.rgba);
  CHECK(CountColours(one_frame) > 100);  // the scene is not trivially uniform
}

namespace {

// Position from attribute 0 moved by what `offset` points to (data the shader only points to, not copied); colour
// from attribute 1, scaled by gl_VertexID; flat or smooth by the varyings' type.
template <class Varyings>
struct HeldDrawShader : Shader<HeldDrawShader<Varyings>, Varyings> {
  const glm::vec4* offset = nullptr;
  float scale = 1.0f;
  void Vertex(const VertexIn& in, VertexOut<Varyings>& out) const {
    out.position = in.attrib[0] + (offset ? *offset : glm::vec4(0.0f));
    out.point_size = 3.0f;
    out.varyings.value = in.attrib[1] * (scale * float(1 + in.vertex_id % 4) / 4.0f);
  }
  bool Fragment(const FragmentIn<Varyings>& in, FragmentOut& out) const {
    out.color[0] = glm::vec4(glm::vec3(in.varyings.value), 0.6f);
    return true;
  }
};
struct FlatVec4Varyings {
  Flat<glm::vec4> value;
};
// Samples unit 0 at its centre.
struct UnitZeroShader : Shader<UnitZeroShader, testing::NoVaryings> {
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>& in, FragmentOut& out) const {
    out.color[0] = in.textures->SampleLod(0, glm::vec2(0.5f), 0.0f);
    return true;
  }
};

}  // namespace

TEST_CASE("small draws held together render what each renders recorded on its own", "[context]") {
  // Small draws with the same state are shaded at once but recorded together. 600 draws of every mode that is held
  // (and of LINE_LOOP and larger draws, which are not), arrays and indexed, complete and with a partial last
  // primitive, with state changed between some of them (depth function, blending, culling, provoking vertex,
  // polygon mode and offset, viewport, point size, the shader and a uniform): as drawn, against the same draws each
  // followed by Flush (each recorded alone), against them while a PRIMITIVES_GENERATED query counts (no draw is
  // held then), and at 3 threads.
  std::vector<glm::vec4> positions, values;
  Lcg random{777};
  for (int i = 0; i < 2000; ++i) {
    positions.push_back({random() * 2.4f - 1.2f, random() * 2.4f - 1.2f, random() * 2 - 1, 1 + random()});
    values.push_back({random(), random(), random(), 1});
  }
  std::vector<std::uint32_t> indices(4000);
  for (auto& e : indices) e = std::uint32_t(random() * 1999.0f);
  enum class Way { kAsDrawn, kFlushEach, kCounted };
  auto render = [&](int threads, Way way) {
    random.seed = 99;
    Context gl(120, 90, Context::Options{threads});
    HeldDrawShader<testing::Vec4Varyings> smooth;
    HeldDrawShader<FlatVec4Varyings> flat;
    MakeVertexArray(gl, positions, values);
    gl.BindBuffer(ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * 4), indices.data());
    const std::uint32_t query = gl.GenQuery();
    if (way == Way::kCounted) gl.BeginQuery(PRIMITIVES_GENERATED, query);
    gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
    gl.Enable(DEPTH_TEST);
    gl.Enable(PROGRAM_POINT_SIZE);
    gl.UseProgram(smooth);
    const Enum modes[] = {POINTS, LINES, LINE_STRIP, LINE_LOOP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN};
    for (int d = 0; d < 600; ++d) {
      switch (d % 97) {
        case 10: gl.DepthFunc(d % 2 ? GREATER : LEQUAL); break;
        case 20: gl.Enable(BLEND); gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA); break;
        case 30: gl.Enable(CULL_FACE); gl.CullFace(d % 2 ? FRONT : BACK); break;
        case 40: gl.ProvokingVertex(FIRST_VERTEX_CONVENTION); gl.UseProgram(flat); break;
        case 50: gl.PolygonMode(FRONT_AND_BACK, LINE); break;
        case 55: gl.Enable(POLYGON_OFFSET_LINE); gl.PolygonOffset(2.0f, 4.0f); break;
        case 60: gl.PolygonMode(FRONT_AND_BACK, FILL); gl.Viewport(10, 5, 100, 80); break;
        case 65: smooth.scale = 0.5f + random(); break;  // a uniform: a new shader copy
        case 70: gl.ProvokingVertex(LAST_VERTEX_CONVENTION); gl.UseProgram(smooth); break;
        case 80: gl.Disable(BLEND); gl.Disable(CULL_FACE); gl.Disable(POLYGON_OFFSET_LINE); gl.Viewport(0, 0, 120, 90); break;
        default: break;
      }
      const Enum mode = modes[int(random() * 7.0f)];
      const int count = d % 50 == 0 ? 200 : 1 + int(random() * 20.0f);  // some larger than a held draw
      const int first = int(random() * 1700.0f);
      if (random() < 0.5f) gl.DrawArrays(mode, first, count);
      else gl.DrawElementsBaseVertex(mode, count, UNSIGNED_INT, std::size_t(first) * 4, int(random() * 50.0f));
      if (way == Way::kFlushEach) gl.Flush();
    }
    if (way == Way::kCounted) gl.EndQuery(PRIMITIVES_GENERATED);
    CHECK(gl.GetError() == NO_ERROR);
    return gl.ReadPixels();
  };
  const Image drawn = render(1, Way::kAsDrawn);
  CHECK(drawn.rgba == render(1, Way::kFlushEach).rgba);
  CHECK(drawn.rgba == render(1, Way::kCounted).rgba);
  CHECK(drawn.rgba == render(3, Way::kAsDrawn).rgba);
  CHECK(CountColours(drawn) > 1000);  // the scene is not trivially uniform
}

TEST_CASE("a held small draw is shaded when it is drawn and rendered before what follows it", "[context]") {
  // Each draw's vertex stage sees the data the shader points to and the buffers as they are at the draw; a clear,
  // a query's result, a framebuffer switch and a texture bound anew after held draws apply after them.
  Context gl(8, 8);
  HeldDrawShader<testing::Vec4Varyings> shader;
  glm::vec4 offset(0.0f);
  shader.offset = &offset;
  gl.UseProgram(shader);
  const glm::vec4 white(1.0f);
  const std::uint32_t vao = MakeVertexArray(gl, {{-1, -1, 0, 1}, {0, -1, 0, 1}, {-1, 1, 0, 1}}, {white, white, white});
  auto lit = [&](int x, int y) {
    std::uint8_t px[4];
    gl.ReadPixel(x, y, px);
    return px[0] > 0;
  };
  SECTION("data the shader points to, and the vertex buffer, changed after a draw") {
    gl.DrawArrays(TRIANGLES, 0, 3);  // the lower left quarter
    offset = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    gl.DrawArrays(TRIANGLES, 0, 3);  // moved right
    const glm::vec4 up[3] = {{-1, 0, 0, 1}, {0, 0, 0, 1}, {-1, 2, 0, 1}};  // the vertices moved up (and right)
    gl.BufferSubData(ARRAY_BUFFER, 0, sizeof up, up);
    gl.DrawArrays(TRIANGLES, 0, 3);
    CHECK(lit(0, 0));  // the first draw, as it was drawn
    CHECK(lit(4, 0));  // the second
    CHECK(lit(4, 4));  // the third
    CHECK_FALSE(lit(0, 7));  // where the first draw would reach had it read the buffer as changed
  }
  SECTION("a clear after held draws") {
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.Clear(COLOR_BUFFER_BIT);
    offset = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    gl.DrawArrays(TRIANGLES, 0, 3);
    CHECK_FALSE(lit(0, 0));
    CHECK(lit(4, 0));
  }
  SECTION("a query's result asked for while its draws are held") {
    const std::uint32_t q = gl.GenQuery();
    gl.BeginQuery(SAMPLES_PASSED, q);
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.EndQuery(SAMPLES_PASSED);
    std::uint32_t available = 0, samples = 0;
    gl.GetQueryObjectuiv(q, QUERY_RESULT, &samples);
    gl.GetQueryObjectuiv(q, QUERY_RESULT_AVAILABLE, &available);
    CHECK(available == 1);
    CHECK(samples == 2 * 16);  // 16 pixel centres under the triangle, twice
  }
  SECTION("a framebuffer object bound between held draws") {
    const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
    gl.BindRenderbuffer(RENDERBUFFER, rb);
    gl.RenderbufferStorage(RENDERBUFFER, RGBA8, 8, 8);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
    gl.Clear(COLOR_BUFFER_BIT);
    gl.DrawArrays(TRIANGLES, 0, 3);  // into the renderbuffer
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    offset = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    gl.DrawArrays(TRIANGLES, 0, 3);  // into the context's framebuffer, moved right
    CHECK_FALSE(lit(0, 0));
    CHECK(lit(4, 0));
    gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
    CHECK(lit(0, 0));
    CHECK_FALSE(lit(4, 0));
  }
  SECTION("another texture bound between held draws") {
    UnitZeroShader sampling;
    gl.UseProgram(sampling);
    const std::uint8_t red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255};
    const std::uint32_t a = gl.GenTexture(), b = gl.GenTexture();
    for (auto [t, texel] : {std::pair{a, red}, std::pair{b, green}}) {
      gl.BindTexture(TEXTURE_2D, t);
      gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_BYTE, texel);
      gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
    }
    const std::uint32_t right = MakeVertexArray(gl, {{0, -1, 0, 1}, {1, -1, 0, 1}, {0, 1, 0, 1}});
    gl.BindVertexArray(vao);
    gl.BindTexture(TEXTURE_2D, a);
    gl.DrawArrays(TRIANGLES, 0, 3);
    gl.BindVertexArray(right);
    gl.BindTexture(TEXTURE_2D, b);
    gl.DrawArrays(TRIANGLES, 0, 3);
    std::uint8_t px[4];
    gl.ReadPixel(0, 0, px);
    CHECK((px[0] == 255 && px[1] == 0));
    gl.ReadPixel(4, 0, px);
    CHECK((px[0] == 0 && px[1] == 255));
  }
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("hostile calls: rectangles at INT_MIN and INT_MAX blit and copy what lies inside", "[context][errors][hostile]") {
  // Each of these computed a rectangle's size or a pixel's coordinate in int and overflowed: undefined behaviour,
  // which the sanitizer build stops on. Now the sizes are 64-bit and the pixels outside the buffers are skipped.
  constexpr int kMin = std::numeric_limits<int>::min(), kMax = std::numeric_limits<int>::max();
  Context gl(8, 8);
  // A 4x multisampled framebuffer object, cleared to one colour, depth and stencil, resolved into the context's
  // framebuffer through the largest rectangles there are, unmirrored (the resolve path) and mirrored on both axes.
  const std::uint32_t fbo = gl.GenFramebuffer(), color = gl.GenRenderbuffer(), depth = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, color);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, RGBA8, 8, 8);
  gl.BindRenderbuffer(RENDERBUFFER, depth);
  gl.RenderbufferStorageMultisample(RENDERBUFFER, 4, DEPTH24_STENCIL8, 8, 8);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, color);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, DEPTH_STENCIL_ATTACHMENT, RENDERBUFFER, depth);
  REQUIRE(gl.CheckFramebufferStatus(FRAMEBUFFER) == FRAMEBUFFER_COMPLETE);
  for (const bool mirrored : {false, true}) {
    CAPTURE(mirrored);
    gl.BindFramebuffer(FRAMEBUFFER, fbo);
    ClearAll(gl, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f), 0.5, 7);
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    ClearAll(gl, glm::vec4(0.0f), 1.0, 0);
    gl.BindFramebuffer(READ_FRAMEBUFFER, fbo);
    gl.BindFramebuffer(DRAW_FRAMEBUFFER, 0);
    if (mirrored)
      gl.BlitFramebuffer(kMax, kMax, kMin, kMin, kMax, kMax, kMin, kMin,
                         COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
    else
      gl.BlitFramebuffer(kMin, kMin, kMax, kMax, kMin, kMin, kMax, kMax,
                         COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT, NEAREST);
    CHECK(gl.GetError() == NO_ERROR);
    gl.BindFramebuffer(FRAMEBUFFER, 0);
    std::uint8_t rgba[4] = {};
    gl.ReadPixel(3, 5, rgba);
    CHECK((rgba[0] == 51 && rgba[1] == 102 && rgba[2] == 153 && rgba[3] == 255));
    float d = 0.0f;
    gl.ReadPixels(6, 1, 1, 1, DEPTH_COMPONENT, FLOAT, &d);
    CHECK(d == Approx(0.5f).margin(1e-6));
    std::uint8_t stencil = 0;
    gl.ReadPixels(0, 7, 1, 1, STENCIL_INDEX, UNSIGNED_BYTE, &stencil);
    CHECK(stencil == 7);
  }
  // ReadPixels of rectangles at the ends of int: nothing lies inside, nothing is written.
  for (const auto& [rx, ry] : {std::pair<int, int>{0, kMin}, std::pair<int, int>{kMin, 0}, std::pair<int, int>{kMin, kMin},
                               std::pair<int, int>{kMax - 1, 0}, std::pair<int, int>{0, kMax - 1}}) {
    std::uint8_t out[16];
    std::memset(out, 0xCD, sizeof out);
    gl.ReadPixels(rx, ry, 2, 2, RGBA, UNSIGNED_BYTE, out);
    CHECK(gl.GetError() == NO_ERROR);
    CHECK(std::count(out, out + 16, std::uint8_t(0xCD)) == 16);
  }
  // Copies from a source rectangle far outside the framebuffer: every texel is outside, so zero (2D, a cube face,
  // a depth texture, an array layer, and CopyTexImage2D).
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  gl.ClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  std::vector<std::uint8_t> texels(16 * 16 * 4, 0xCD);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 16, 16, 0, RGBA, UNSIGNED_BYTE, texels.data());
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, kMax, kMax, 16, 16);
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  CHECK(std::count(texels.begin(), texels.end(), 0) == 16 * 16 * 4);
  gl.CopyTexImage2D(TEXTURE_2D, 0, RGBA8, kMax, kMax, 4, 4, 0);
  CHECK(gl.GetError() == NO_ERROR);
  std::fill(texels.begin(), texels.end(), 0xCD);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels.data());
  CHECK(std::count(texels.begin(), texels.begin() + 4 * 4 * 4, 0) == 4 * 4 * 4);
  const std::uint32_t cube = gl.GenTexture();
  gl.BindTexture(TEXTURE_CUBE_MAP, cube);
  gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_Y, 0, RGBA8, 4, 4, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.CopyTexSubImage2D(TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 0, 0, kMax - 2, kMax - 2, 4, 4);
  CHECK(gl.GetError() == NO_ERROR);
  const std::uint32_t depth_tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, depth_tex);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH24_STENCIL8, 4, 4, 0, DEPTH_STENCIL, UNSIGNED_INT_24_8, nullptr);
  gl.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, kMax, kMax, 4, 4);
  CHECK(gl.GetError() == NO_ERROR);
  const std::uint32_t array = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D_ARRAY, array);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 0, RGBA8, 4, 4, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);
  gl.CopyTexSubImage3D(TEXTURE_2D_ARRAY, 0, 0, 0, 1, kMax, kMax, 4, 4);
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("hostile calls: a float buffer holding NaN and infinities reads back as integers clamped, NaN as 0",
          "[context][errors][hostile]") {
  // ReadPixels into a normalized integer type clamps to [0, 1] first (OpenGL 3.3, section 4.3.2); NaN went through
  // that clamp unchanged and into a conversion to an integer out of its range (undefined behaviour).
  Context gl(2, 2);
  BindFloatTarget(gl, 2, 2);
  const float inf = std::numeric_limits<float>::infinity();
  gl.ClearColor(std::numeric_limits<float>::quiet_NaN(), inf, -inf, 1e30f);
  gl.Clear(COLOR_BUFFER_BIT);
  std::uint8_t b[4] = {1, 1, 1, 1};
  gl.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, b);
  CHECK((b[0] == 0 && b[1] == 255 && b[2] == 0 && b[3] == 255));
  std::uint16_t h[4] = {1, 1, 1, 1};
  gl.ReadPixels(1, 0, 1, 1, RGBA, UNSIGNED_SHORT, h);
  CHECK((h[0] == 0 && h[1] == 65535 && h[2] == 0 && h[3] == 65535));
  std::uint32_t u[4] = {1, 1, 1, 1};
  gl.ReadPixels(0, 1, 1, 1, RGBA, UNSIGNED_INT, u);
  CHECK((u[0] == 0 && u[1] == 0xFFFFFFFFu && u[2] == 0 && u[3] == 0xFFFFFFFFu));
  CHECK(gl.GetError() == NO_ERROR);
  // The clear colour itself, asked for as integers: NaN reads as 0 (the normalized conversion of 1e30 clamps).
  int clear[4] = {1, 1, 1, 1};
  gl.GetIntegerv(COLOR_CLEAR_VALUE, clear);
  CHECK((clear[0] == 0 && clear[1] == std::numeric_limits<int>::max() && clear[2] == -std::numeric_limits<int>::max() &&
         clear[3] == std::numeric_limits<int>::max()));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("hostile calls: a null pointer the call would read or write through is INVALID_VALUE and changes nothing",
          "[context][errors][hostile]") {
  Context gl(4, 4);
  // Gen*s and Delete*s of every object kind.
  using Ids = void (Context::*)(int, std::uint32_t*);
  using ConstIds = void (Context::*)(int, const std::uint32_t*);
  const Ids gens[] = {&Context::GenBuffers, &Context::GenVertexArrays, &Context::GenTextures,
                      &Context::GenFramebuffers, &Context::GenRenderbuffers, &Context::GenQueries};
  const ConstIds deletes[] = {&Context::DeleteBuffers, &Context::DeleteVertexArrays, &Context::DeleteTextures,
                              &Context::DeleteFramebuffers, &Context::DeleteRenderbuffers, &Context::DeleteQueries};
  for (int k = 0; k < 6; ++k) {
    CAPTURE(k);
    (gl.*gens[k])(2, nullptr);
    CHECK(gl.GetError() == INVALID_VALUE);
    (gl.*gens[k])(0, nullptr);  // nothing to write: no error
    CHECK(gl.GetError() == NO_ERROR);
    (gl.*deletes[k])(3, nullptr);
    CHECK(gl.GetError() == INVALID_VALUE);
    (gl.*deletes[k])(0, nullptr);
    CHECK(gl.GetError() == NO_ERROR);
  }
  // ReadPixel, and DrawBuffers on a framebuffer object (whose draw buffers stay as they were).
  gl.ReadPixel(0, 0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  const std::uint32_t fbo = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.DrawBuffers(2, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  int draw_buffer = 0;
  gl.GetIntegerv(DRAW_BUFFER0, &draw_buffer);
  CHECK(draw_buffer == int(COLOR_ATTACHMENT0));
  gl.BindFramebuffer(FRAMEBUFFER, 0);
  // Queries of every family with a null output.
  gl.GetIntegerv(VIEWPORT, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetFloatv(COLOR_CLEAR_VALUE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetBooleanv(DEPTH_TEST, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetIntegerv(0x1234, nullptr);  // the pname is checked first
  CHECK(gl.GetError() == INVALID_ENUM);
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, tex);
  gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 2, 2, 0, RGBA, UNSIGNED_BYTE, nullptr);  // OpenGL's meaning: no contents
  CHECK(gl.GetError() == NO_ERROR);
  gl.GetTexParameteriv(TEXTURE_2D, TEXTURE_MIN_FILTER, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_WIDTH, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexSubImage2D(TEXTURE_2D, 0, 0, 0, 2, 2, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 2, RGBA, UNSIGNED_BYTE, nullptr);  // an empty rectangle: no error
  CHECK(gl.GetError() == NO_ERROR);
  const std::uint32_t buffer = gl.GenBuffer();
  gl.BindBuffer(ARRAY_BUFFER, buffer);
  gl.BufferData(ARRAY_BUFFER, 16, nullptr);  // OpenGL's meaning: a store without contents
  CHECK(gl.GetError() == NO_ERROR);
  gl.BufferSubData(ARRAY_BUFFER, 0, 8, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetBufferSubData(ARRAY_BUFFER, 0, 8, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetBufferParameteriv(ARRAY_BUFFER, BUFFER_SIZE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetBufferPointerv(ARRAY_BUFFER, BUFFER_MAP_POINTER, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  const std::uint32_t query = gl.GenQuery();
  gl.BeginQuery(SAMPLES_PASSED, query);
  gl.GetQueryiv(SAMPLES_PASSED, CURRENT_QUERY, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.EndQuery(SAMPLES_PASSED);
  gl.GetQueryObjectuiv(query, QUERY_RESULT, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetMultisamplefv(SAMPLE_POSITION, 0, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
}

TEST_CASE("hostile calls: OpenGL 3.3's codes for 3D levels and empty default framebuffers", "[context][errors][hostile]") {
  // A 3D texture has levels 0 to log2(MAX_3D_TEXTURE_SIZE) = 11 (OpenGL 3.3, section 3.8.3); level 12 is
  // INVALID_VALUE, as level 15 is for the other targets.
  Context gl(4, 4);
  const std::uint32_t volume = gl.GenTexture();
  gl.BindTexture(TEXTURE_3D, volume);
  gl.TexImage3D(TEXTURE_3D, 12, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.TexImage3D(TEXTURE_3D, 11, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == NO_ERROR);
  std::uint8_t texel[4] = {};
  gl.GetTexImage(TEXTURE_3D, 12, RGBA, UNSIGNED_BYTE, texel);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetTexImage(TEXTURE_3D, 11, RGBA, UNSIGNED_BYTE, texel);
  CHECK(gl.GetError() == NO_ERROR);
  int v = 0;
  gl.GetTexLevelParameteriv(TEXTURE_3D, 12, TEXTURE_WIDTH, &v);
  CHECK(gl.GetError() == INVALID_VALUE);
  const std::uint32_t array = gl.GenTexture();  // an array's levels follow MAX_TEXTURE_SIZE: 12 is a level
  gl.BindTexture(TEXTURE_2D_ARRAY, array);
  gl.TexImage3D(TEXTURE_2D_ARRAY, 12, RGBA8, 1, 1, 1, 0, RGBA, UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == NO_ERROR);

  // A context of 0 x N pixels still has its framebuffer's colour, depth and stencil buffers, with no pixels: reads
  // and copies from it are valid and read nothing (copied texels outside it are zero, as for any framebuffer).
  for (const auto& size : {std::pair{0, 5}, std::pair{5, 0}, std::pair{0, 0}}) {
    CAPTURE(size.first, size.second);
    Context empty(size.first, size.second);
    std::uint8_t rgba[4] = {9, 9, 9, 9};
    empty.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, rgba);
    CHECK(empty.GetError() == NO_ERROR);
    CHECK(rgba[0] == 9);  // outside the buffer: left as it was
    float depth = 0.5f;
    empty.ReadPixels(0, 0, 1, 1, DEPTH_COMPONENT, FLOAT, &depth);
    CHECK(empty.GetError() == NO_ERROR);
    std::uint8_t stencil = 0;
    empty.ReadPixels(0, 0, 1, 1, STENCIL_INDEX, UNSIGNED_BYTE, &stencil);
    CHECK(empty.GetError() == NO_ERROR);
    const std::uint32_t tex = empty.GenTexture();
    empty.BindTexture(TEXTURE_2D, tex);
    empty.CopyTexImage2D(TEXTURE_2D, 0, RGBA8, 0, 0, 2, 2, 0);
    CHECK(empty.GetError() == NO_ERROR);
    std::uint8_t texels[16];
    std::memset(texels, 0xCD, sizeof texels);
    empty.GetTexImage(TEXTURE_2D, 0, RGBA, UNSIGNED_BYTE, texels);
    CHECK(std::count(texels, texels + 16, 0) == 16);
    empty.CopyTexSubImage2D(TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);
    CHECK(empty.GetError() == NO_ERROR);
    // With ReadBuffer(NONE) there is no colour buffer to read, whatever the size.
    empty.ReadBuffer(NONE);
    empty.ReadPixels(0, 0, 1, 1, RGBA, UNSIGNED_BYTE, rgba);
    CHECK(empty.GetError() == INVALID_OPERATION);
  }
}

TEST_CASE("hostile calls: VertexAttributePointer takes half floats, doubles, the packed types and BGRA as OpenGL 3.3 does",
          "[context][errors][hostile]") {
  // OpenGL 3.3, section 2.8: HALF_FLOAT, DOUBLE, INT_2_10_10_10_REV and UNSIGNED_INT_2_10_10_10_REV are attribute
  // types; the packed ones need size 4 or BGRA, and BGRA needs UNSIGNED_BYTE or a packed type, normalized.
  Context gl(8, 8);
  gl.BindVertexArray(gl.GenVertexArray());
  gl.BindBuffer(ARRAY_BUFFER, gl.GenBuffer());
  for (Enum type : {HALF_FLOAT, DOUBLE}) {
    gl.VertexAttributePointer(0, 3, type, false, 0, 0);
    CHECK(gl.GetError() == NO_ERROR);
  }
  for (Enum type : {INT_2_10_10_10_REV, UNSIGNED_INT_2_10_10_10_REV}) {
    gl.VertexAttributePointer(0, 4, type, true, 0, 0);
    CHECK(gl.GetError() == NO_ERROR);
    gl.VertexAttributePointer(0, int(BGRA), type, true, 0, 0);
    CHECK(gl.GetError() == NO_ERROR);
    gl.VertexAttributePointer(0, 3, type, true, 0, 0);
    CHECK(gl.GetError() == INVALID_OPERATION);
  }
  gl.VertexAttributePointer(0, int(BGRA), UNSIGNED_BYTE, true, 0, 0);
  CHECK(gl.GetError() == NO_ERROR);
  gl.VertexAttributePointer(0, int(BGRA), UNSIGNED_BYTE, false, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.VertexAttributePointer(0, int(BGRA), FLOAT, true, 0, 0);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.VertexAttributePointer(0, int(BGR), UNSIGNED_BYTE, true, 0, 0);
  CHECK(gl.GetError() == INVALID_VALUE);

  // A draw: half-float positions and BGRA byte colours, tightly packed (stride 0 is 6 and 4 bytes).
  const std::uint16_t positions[] = {0xBC00, 0xBC00, 0, 0x4200, 0xBC00, 0, 0xBC00, 0x4200, 0};  // -1 and 3
  const std::uint8_t colours[] = {255, 128, 0, 255, 255, 128, 0, 255, 255, 128, 0, 255};        // blue 1, red 0
  const std::uint32_t vbo = gl.GenBuffer();
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, sizeof positions + sizeof colours, nullptr);
  gl.BufferSubData(ARRAY_BUFFER, 0, sizeof positions, positions);
  gl.BufferSubData(ARRAY_BUFFER, sizeof positions, sizeof colours, colours);
  gl.VertexAttributePointer(0, 3, HALF_FLOAT, false, 0, 0);
  gl.VertexAttributePointer(1, int(BGRA), UNSIGNED_BYTE, true, 0, sizeof positions);
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(1);
  testing::CaptureShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  gl.Finish();
  CHECK(shader.samples.size() == 64);  // the triangle covers the whole 8 x 8 viewport
  const glm::vec4 value = shader.samples[{3, 4}].value;
  CHECK(value.r == Approx(0.0f).margin(1e-6));
  CHECK(value.g == Approx(128.0f / 255.0f));
  CHECK(value.b == Approx(1.0f));
  CHECK(value.a == Approx(1.0f));
  CHECK(gl.GetError() == NO_ERROR);
}

namespace {
struct UnitShader : Shader<UnitShader, testing::NoVaryings> {
  int unit = 0;
  void Vertex(const VertexIn& in, VertexOut<testing::NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const FragmentIn<testing::NoVaryings>& in, FragmentOut& out) const {
    out.color[0] = in.textures->SampleLod(unit, glm::vec2(0.5f), 0.0f);
    return true;
  }
};
}  // namespace

TEST_CASE("hostile calls: OpenGL 3.3's 48 combined texture units, each bindable and sampled", "[context][errors][hostile]") {
  // OpenGL 3.3, table 6.54: MAX_COMBINED_TEXTURE_IMAGE_UNITS is at least 48 (16 for each of three stages).
  Context gl(4, 4);
  int units = 0;
  gl.GetIntegerv(MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
  CHECK(units == 48);
  gl.ActiveTexture(TEXTURE0 + 48);
  CHECK(gl.GetError() == INVALID_ENUM);
  // A different colour on units 0, 16 and 47; a draw samples the one its shader names.
  const std::uint8_t colours[3][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  const int bound[3] = {0, 16, 47};
  for (int i = 0; i < 3; ++i) {
    gl.ActiveTexture(TEXTURE0 + std::uint32_t(bound[i]));
    CHECK(gl.GetError() == NO_ERROR);
    gl.BindTexture(TEXTURE_2D, gl.GenTexture());
    gl.TexImage2D(TEXTURE_2D, 0, RGBA8, 1, 1, 0, RGBA, UNSIGNED_BYTE, colours[i]);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, NEAREST);
  }
  MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  UnitShader shader;
  gl.UseProgram(shader);
  for (int i = 0; i < 3; ++i) {
    shader.unit = bound[i];
    gl.DrawArrays(TRIANGLES, 0, 3);
    std::uint8_t px[4];
    gl.ReadPixel(1, 1, px);
    CHECK(std::vector<std::uint8_t>(px, px + 4) == std::vector<std::uint8_t>(colours[i], colours[i] + 4));
  }
  shader.unit = 30;  // nothing bound there: (0, 0, 0, 1)
  gl.DrawArrays(TRIANGLES, 0, 3);
  std::uint8_t px[4];
  gl.ReadPixel(1, 1, px);
  CHECK((px[0] == 0 && px[1] == 0 && px[2] == 0 && px[3] == 255));
  CHECK(gl.GetError() == NO_ERROR);
}

TEST_CASE("VertexAttribP sets a current value from a packed word, the missing components (0, 0, 1)", "[context][errors]") {
  Context gl(4, 4);
  const auto current = [&](std::uint32_t index) {
    glm::vec4 v(-9.0f);
    gl.GetVertexAttribfv(index, CURRENT_VERTEX_ATTRIB, &v.x);
    return v;
  };
  // x = -512 (0x200), y = 511 (0x1FF), z = -1 (0x3FF), w = -2 (0b10) as signed fields; 512, 511, 1023, 2 unsigned.
  const std::uint32_t word = 0x200u | (0x1FFu << 10) | (0x3FFu << 20) | (0x2u << 30);
  gl.VertexAttrib4f(2, 7, 7, 7, 7);
  gl.VertexAttribP4ui(2, INT_2_10_10_10_REV, false, word);
  CHECK(current(2) == glm::vec4(-512, 511, -1, -2));
  gl.VertexAttribP4ui(2, INT_2_10_10_10_REV, true, word);  // max(c / (2^(b-1) - 1), -1)
  CHECK(current(2) == glm::vec4(-1.0f, 1.0f, -1.0f / 511.0f, -1.0f));
  gl.VertexAttribP4uiv(2, UNSIGNED_INT_2_10_10_10_REV, false, &word);
  CHECK(current(2) == glm::vec4(512, 511, 1023, 2));
  gl.VertexAttribP4ui(2, UNSIGNED_INT_2_10_10_10_REV, true, word);  // c / (2^b - 1)
  CHECK(current(2) == glm::vec4(512.0f / 1023.0f, 511.0f / 1023.0f, 1.0f, 2.0f / 3.0f));
  gl.VertexAttribP3ui(2, UNSIGNED_INT_2_10_10_10_REV, false, word);
  CHECK(current(2) == glm::vec4(512, 511, 1023, 1));
  gl.VertexAttribP2uiv(2, UNSIGNED_INT_2_10_10_10_REV, false, &word);
  CHECK(current(2) == glm::vec4(512, 511, 0, 1));
  gl.VertexAttribP1ui(2, INT_2_10_10_10_REV, false, word);
  CHECK(current(2) == glm::vec4(-512, 0, 0, 1));
  gl.VertexAttribP3uiv(2, INT_2_10_10_10_REV, true, &word);
  gl.VertexAttribP2ui(2, INT_2_10_10_10_REV, true, word);
  gl.VertexAttribP1uiv(2, INT_2_10_10_10_REV, true, &word);
  CHECK(current(2) == glm::vec4(-1, 0, 0, 1));
  CHECK(gl.GetError() == NO_ERROR);
  // Errors change nothing: a type that is not packed, an index past the last, a null pointer.
  gl.VertexAttribP4ui(2, UNSIGNED_INT, false, word);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.VertexAttribP4ui(std::uint32_t(kMaxVertexAttribs), INT_2_10_10_10_REV, false, word);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.VertexAttribP4ui(std::uint32_t(kMaxVertexAttribs), FLOAT, false, word);  // (the type is checked first)
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.VertexAttribP2uiv(2, INT_2_10_10_10_REV, false, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(current(2) == glm::vec4(-1, 0, 0, 1));
}

TEST_CASE("GetVertexAttrib reads back each attribute's array state and current value", "[context][errors]") {
  Context gl(4, 4);
  // Without a vertex array: the current value only.
  gl.VertexAttrib4f(3, 1.5f, -2.5f, 0.25f, 7.0f);
  float fv[4] = {};
  gl.GetVertexAttribfv(3, CURRENT_VERTEX_ATTRIB, fv);
  CHECK((fv[0] == 1.5f && fv[1] == -2.5f && fv[2] == 0.25f && fv[3] == 7.0f));
  int iv[4] = {};
  gl.GetVertexAttribIiv(3, CURRENT_VERTEX_ATTRIB, iv);
  CHECK((iv[0] == 2 && iv[1] == -3 && iv[2] == 0 && iv[3] == 7));  // (rounded to nearest, halves away from 0)
  gl.GetVertexAttribiv(3, VERTEX_ATTRIB_ARRAY_SIZE, iv);
  CHECK(gl.GetError() == INVALID_OPERATION);
  void* pointer = nullptr;
  gl.GetVertexAttribPointerv(3, VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
  CHECK(gl.GetError() == INVALID_OPERATION);

  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  // The defaults (OpenGL 3.3, table 6.4).
  const std::pair<Enum, int> defaults[] = {{VERTEX_ATTRIB_ARRAY_ENABLED, 0}, {VERTEX_ATTRIB_ARRAY_SIZE, 4},
                                           {VERTEX_ATTRIB_ARRAY_STRIDE, 0}, {VERTEX_ATTRIB_ARRAY_TYPE, int(FLOAT)},
                                           {VERTEX_ATTRIB_ARRAY_NORMALIZED, 0}, {VERTEX_ATTRIB_ARRAY_INTEGER, 0},
                                           {VERTEX_ATTRIB_ARRAY_DIVISOR, 0}, {VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, 0}};
  for (const auto& [pname, value] : defaults) {
    int v = -99;
    gl.GetVertexAttribiv(5, pname, &v);
    CHECK(v == value);
  }
  gl.GetVertexAttribfv(5, CURRENT_VERTEX_ATTRIB, fv);
  CHECK((fv[0] == 0.0f && fv[1] == 0.0f && fv[2] == 0.0f && fv[3] == 1.0f));
  // What VertexAttributePointer, EnableVertexAttribArray and VertexAttribDivisor set.
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, 256, nullptr);
  gl.VertexAttributePointer(5, 3, SHORT, true, 12, 40);
  gl.VertexAttributePointer(6, int(BGRA), UNSIGNED_BYTE, true, 0, 8);
  gl.EnableVertexAttribArray(5);
  gl.VertexAttribDivisor(5, 3);
  const std::pair<Enum, int> set[] = {{VERTEX_ATTRIB_ARRAY_ENABLED, 1}, {VERTEX_ATTRIB_ARRAY_SIZE, 3},
                                      {VERTEX_ATTRIB_ARRAY_STRIDE, 12}, {VERTEX_ATTRIB_ARRAY_TYPE, int(SHORT)},
                                      {VERTEX_ATTRIB_ARRAY_NORMALIZED, 1}, {VERTEX_ATTRIB_ARRAY_DIVISOR, 3},
                                      {VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, int(vbo)}};
  for (const auto& [pname, value] : set) {
    int v = -99;
    std::uint32_t u = 99;
    float f = -99.0f;
    double d = -99.0;
    gl.GetVertexAttribiv(5, pname, &v);
    gl.GetVertexAttribIuiv(5, pname, &u);
    gl.GetVertexAttribfv(5, pname, &f);
    gl.GetVertexAttribdv(5, pname, &d);
    CHECK(v == value);
    CHECK(u == std::uint32_t(value));
    CHECK(f == float(value));
    CHECK(d == double(value));
  }
  int v = 0;
  gl.GetVertexAttribiv(6, VERTEX_ATTRIB_ARRAY_SIZE, &v);
  CHECK(v == int(BGRA));
  gl.GetVertexAttribPointerv(5, VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
  CHECK(reinterpret_cast<std::uintptr_t>(pointer) == 40u);
  gl.GetVertexAttribPointerv(6, VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
  CHECK(reinterpret_cast<std::uintptr_t>(pointer) == 8u);
  // A deleted buffer reads 0 while the array keeps its store.
  gl.DeleteBuffer(vbo);
  gl.GetVertexAttribiv(5, VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &v);
  CHECK(v == 0);
  CHECK(gl.GetError() == NO_ERROR);
  // Errors: nothing written.
  v = -7;
  gl.GetVertexAttribiv(kMaxVertexAttribs, VERTEX_ATTRIB_ARRAY_SIZE, &v);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetVertexAttribiv(0, TEXTURE_2D, &v);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetVertexAttribPointerv(0, VERTEX_ATTRIB_ARRAY_SIZE, &pointer);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetVertexAttribPointerv(kMaxVertexAttribs, VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetVertexAttribfv(0, CURRENT_VERTEX_ATTRIB, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  gl.GetVertexAttribPointerv(0, VERTEX_ATTRIB_ARRAY_POINTER, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
  CHECK(v == -7);
}

TEST_CASE("QueryCounter records TIMESTAMP after the work before it; GetInteger64v(TIMESTAMP) reads the same clock",
          "[context][errors]") {
  Context gl(64, 64);
  std::uint32_t ids[3];
  gl.GenQueries(3, ids);
  std::int64_t now0 = 0;
  gl.GetInteger64v(TIMESTAMP, &now0);
  gl.QueryCounter(ids[0], TIMESTAMP);
  testing::SolidShader shader;
  gl.UseProgram(shader);
  testing::MakeVertexArray(gl, {{-1, -1, 0, 1}, {3, -1, 0, 1}, {-1, 3, 0, 1}});
  for (int i = 0; i < 50; ++i) gl.DrawArrays(TRIANGLES, 0, 3);
  gl.QueryCounter(ids[1], TIMESTAMP);
  std::int64_t now1 = 0;
  gl.GetInteger64v(TIMESTAMP, &now1);
  std::uint64_t t0 = 0, t1 = 0;
  gl.GetQueryObjectui64v(ids[0], QUERY_RESULT, &t0);
  gl.GetQueryObjectui64v(ids[1], QUERY_RESULT, &t1);
  CHECK(std::int64_t(t0) >= now0);
  CHECK(t1 > t0);  // (the draws were rendered in between)
  CHECK(now1 >= std::int64_t(t1));
  int available = 0, bits = 0;
  gl.GetQueryObjectiv(ids[1], QUERY_RESULT_AVAILABLE, &available);
  CHECK(available == 1);
  gl.GetQueryiv(TIMESTAMP, QUERY_COUNTER_BITS, &bits);
  CHECK(bits == 64);
  gl.QueryCounter(ids[0], TIMESTAMP);  // again: a later time
  std::uint64_t t2 = 0;
  gl.GetQueryObjectui64v(ids[0], QUERY_RESULT, &t2);
  CHECK(t2 >= t1);
  CHECK(gl.GetError() == NO_ERROR);

  // Errors.
  gl.QueryCounter(ids[2], TIME_ELAPSED);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.QueryCounter(ids[2] + 100, TIMESTAMP);
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BeginQuery(TIMESTAMP, ids[2]);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetQueryiv(TIMESTAMP, CURRENT_QUERY, &bits);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.BeginQuery(SAMPLES_PASSED, ids[2]);
  gl.QueryCounter(ids[2], TIMESTAMP);  // active
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.EndQuery(SAMPLES_PASSED);
  gl.QueryCounter(ids[2], TIMESTAMP);  // begun with another target
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.BeginQuery(TIME_ELAPSED, ids[1]);  // a TIMESTAMP query is not begun with another target either
  CHECK(gl.GetError() == INVALID_OPERATION);
  gl.GetInteger64v(TIMESTAMP, nullptr);
  CHECK(gl.GetError() == INVALID_VALUE);
}

// fuzz_api — random sequences of API calls with random arguments on one context. Every call must validate, record
// OpenGL's error or act, and never crash or touch memory it should not.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

#include <softgl/softgl.h>

#include "fuzz_input.h"

namespace {

struct Vary {
  glm::vec4 a;
  glm::vec3 dir;
  glm::vec2 uv;
};

struct FuzzShader : softgl::Shader<FuzzShader, Vary> {
  static constexpr bool kWritesLayer = true;  // (a layered framebuffer's primitives go where attribute 2's w says)
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Vary>& out) const {
    out.position = in.attrib[0];
    const float layer = in.attrib[2].w * 4.0f;
    out.layer = std::isfinite(layer) ? int(std::clamp(layer, -4.0f, 8.0f)) : 0;
    out.point_size = in.attrib[1].x * 8.0f;
    out.varyings.a = in.attrib[1] + glm::vec4(in.AttribI(3) & 7) * 0.01f;  // (attribute 3 may be an integer one)
    out.varyings.dir = glm::vec3(in.attrib[2]);
    out.varyings.uv = glm::vec2(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<Vary>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.a + in.Texture(0, &Vary::uv) + in.TextureCube(1, &Vary::dir) + glm::vec4(in.point_coord, 0, 0);
    out.color[1] = in.textures->SampleLod(2, in.varyings.uv, in.varyings.a.w);
    out.color[2] = glm::vec4(in.textures->SampleShadow(3, in.varyings.uv, in.varyings.a.x, {}, {}));
    const auto small = [](float v) { return std::isfinite(v) ? int(std::clamp(v, -4.0f, 12.0f)) : 0; };
    const glm::ivec2 texel(small(in.frag_coord.x - 2.0f), small(in.frag_coord.y - 2.0f));
    out.color[3] = in.TextureArray(4, &Vary::dir) + in.Texture3D(5, &Vary::dir) +
                   glm::vec4(in.textures->SampleArrayShadow(6, in.varyings.dir, in.varyings.a.x, {}, {})) +
                   in.textures->FetchSample(7, texel, small(in.varyings.a.y * 9.0f) - 1) +
                   in.textures->FetchSampleArray(7, glm::ivec3(texel, small(in.varyings.a.x * 5.0f) - 1),
                                                 small(in.varyings.a.y * 9.0f) - 1) +
                   in.textures->Fetch(0, texel, small(in.varyings.a.z * 4.0f) - 1) +
                   in.textures->Sample1D(8, in.varyings.uv.x, in.varyings.a.x, in.varyings.a.y) +
                   in.textures->Sample1DArray(9, in.varyings.uv, in.varyings.a.z, 0.0f) +
                   in.textures->FetchBuffer(0, small(in.varyings.a.w * 9.0f) - 2);
    out.depth = in.varyings.a.z;
    return in.varyings.a.w > -0.5f;
  }
};

struct WideVary {
  softgl::vec4 a;
};

// A geometry stage whose every choice comes from the vertices' values (any floats: NaN, infinite, huge): how many
// of its nine tries to emit (one past max_vertices) each lane makes, where strips are cut, gl_Layer and
// gl_PrimitiveID; three invocations, the fragment stage reading the primitive's id.
struct FuzzGeometry : softgl::Shader<FuzzGeometry, WideVary> {
  static constexpr bool kWritesLayer = true;
  static constexpr bool kReadsPrimitiveId = true;
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::TRIANGLE_STRIP, 8, 3};
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideVary>& out) const {
    out.position = in.attrib[0];
    // (a buffer texture's texels at any index: negative, past the store, from any float)
    out.varyings.a = in.attrib[1] + in.TexelFetchBuffer(0, softgl::Int(in.attrib[1].w * 40.0f) - 3);
  }
  void Geometry(const softgl::GeometryLanes<WideVary>& in, softgl::GeometryLanesOut<WideVary>& out) const {
    using softgl::Float;
    for (int k = 0; k < 9; ++k) {
      const auto& v = in.vertex[k % 3];
      out.position = v.position * (Float(in.invocation_id) + 1.0f);
      out.varyings.a = v.varyings.a;
      out.layer = softgl::Int(v.varyings.a.w * 4.0f) + in.invocation_id;
      out.primitive_id = softgl::Int(v.varyings.a.z * 100.0f);
      out.EmitVertex(v.varyings.a.x * 9.0f > Float(float(k)));
      if (k == 3) out.EndPrimitive(v.varyings.a.y > 0.5f);
    }
  }
  void Fragment(const softgl::FragmentLanes<WideVary>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.a + softgl::Float(in.primitive_id) * 0.001f;
  }
};

// Lines with adjacency made points, the vertices beyond the line included.
struct FuzzAdjacency : softgl::Shader<FuzzAdjacency, WideVary> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::LINES_ADJACENCY, softgl::POINTS, 4};
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<WideVary>& out) const {
    out.position = in.attrib[0];
    out.varyings.a = in.attrib[1];
  }
  void Geometry(const softgl::GeometryLanes<WideVary>& in, softgl::GeometryLanesOut<WideVary>& out) const {
    for (int k = 0; k < 4; ++k) {
      out.position = in.vertex[k].position;
      out.point_size = in.vertex[k].point_size;
      out.varyings.a = in.vertex[3 - k].varyings.a;
      out.EmitVertex();
    }
  }
  void Fragment(const softgl::FragmentLanes<WideVary>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.a + in.TexelFetchBuffer(1, softgl::Int(in.frag_coord.x) - 2) * float(in.TextureSizeBuffer(1));
  }
};

using namespace softgl;

constexpr std::uint32_t kCaps[] = {CULL_FACE, DEPTH_TEST, STENCIL_TEST, SCISSOR_TEST, BLEND, POLYGON_OFFSET_FILL,
                                   POLYGON_OFFSET_LINE, POLYGON_OFFSET_POINT, PROGRAM_POINT_SIZE,
                                   PRIMITIVE_RESTART, PRIMITIVE_RESTART_FIXED_INDEX, MULTISAMPLE,
                                   SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE, SAMPLE_COVERAGE, SAMPLE_MASK,
                                   SAMPLE_SHADING, RASTERIZER_DISCARD, COLOR_LOGIC_OP};
constexpr std::uint32_t kModes[] = {POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN,
                                    LINES_ADJACENCY, LINE_STRIP_ADJACENCY, TRIANGLES_ADJACENCY,
                                    TRIANGLE_STRIP_ADJACENCY};
constexpr std::uint32_t kTypes[] = {BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, INT, UNSIGNED_INT, FLOAT, HALF_FLOAT,
                                    DOUBLE, INT_2_10_10_10_REV, UNSIGNED_INT_2_10_10_10_REV};
constexpr std::uint32_t kIndexTypes[] = {UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT};
constexpr std::uint32_t kBufferTargets[] = {ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER, COPY_WRITE_BUFFER,
                                            TRANSFORM_FEEDBACK_BUFFER, TEXTURE_BUFFER};
constexpr std::uint32_t kTexTargets[] = {TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_2D_ARRAY, TEXTURE_3D,
                                         TEXTURE_2D_MULTISAMPLE, TEXTURE_1D, TEXTURE_1D_ARRAY, TEXTURE_BUFFER,
                                         TEXTURE_2D_MULTISAMPLE_ARRAY};
constexpr std::uint32_t kBufferTextureFormats[] = {R8, R16F, RG32F, RGBA8, RGBA16, RGBA32F, RGB8, RGBA32I, R8UI, RGB32UI};
constexpr std::uint32_t kBufferTextureNames[] = {TEXTURE_WIDTH, TEXTURE_INTERNAL_FORMAT, TEXTURE_BUFFER_DATA_STORE_BINDING,
                                                 TEXTURE_RED_SIZE, TEXTURE_SAMPLES, TEXTURE_MIN_FILTER};
constexpr std::uint32_t kImageTargets[] = {TEXTURE_2D,
                                           TEXTURE_CUBE_MAP_POSITIVE_X, TEXTURE_CUBE_MAP_NEGATIVE_X,
                                           TEXTURE_CUBE_MAP_POSITIVE_Y, TEXTURE_CUBE_MAP_NEGATIVE_Y,
                                           TEXTURE_CUBE_MAP_POSITIVE_Z, TEXTURE_CUBE_MAP_NEGATIVE_Z,
                                           TEXTURE_2D_MULTISAMPLE};
constexpr std::uint32_t kInternal[] = {RGBA8, RGB8, RG8, R8, RGBA32F, R32F, RGB10_A2, DEPTH_COMPONENT, DEPTH24_STENCIL8,
                                       DEPTH32F_STENCIL8, RGBA16, R16, RGBA16F, DEPTH_COMPONENT16, COMPRESSED_RGBA,
                                       COMPRESSED_RGBA_S3TC_DXT5_EXT, R32UI, RGBA8I, RGB16UI, RG16I, RGB10_A2UI};
constexpr std::uint32_t kCompressed[] = {COMPRESSED_RGB_S3TC_DXT1_EXT,   COMPRESSED_RGBA_S3TC_DXT1_EXT,
                                         COMPRESSED_RGBA_S3TC_DXT3_EXT,  COMPRESSED_RGBA_S3TC_DXT5_EXT,
                                         COMPRESSED_SRGB_S3TC_DXT1_EXT,  COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT,
                                         COMPRESSED_RED_RGTC1,           COMPRESSED_SIGNED_RED_RGTC1,
                                         COMPRESSED_RG_RGTC2,            COMPRESSED_SIGNED_RG_RGTC2,
                                         COMPRESSED_RGBA_BPTC_UNORM,     COMPRESSED_SRGB_ALPHA_BPTC_UNORM,
                                         COMPRESSED_RGB_BPTC_SIGNED_FLOAT, COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT,
                                         RGBA8};
// Every pixel format and type of OpenGL 3.3 (tables 3.2 to 3.5), and one of neither: a pixel is 16 bytes at most.
constexpr std::uint32_t kFormats[] = {RED, GREEN, BLUE, RG, RGB, BGR, RGBA, BGRA, DEPTH_COMPONENT, DEPTH_STENCIL,
                                      STENCIL_INDEX, RED_INTEGER, RGB_INTEGER, BGRA_INTEGER, RG_INTEGER, RGBA_INTEGER,
                                      0x1909};
constexpr std::uint32_t kPixelTypes[] = {UNSIGNED_BYTE, BYTE, UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT, HALF_FLOAT,
                                         FLOAT, UNSIGNED_BYTE_3_3_2, UNSIGNED_BYTE_2_3_3_REV, UNSIGNED_SHORT_5_6_5,
                                         UNSIGNED_SHORT_5_6_5_REV, UNSIGNED_SHORT_4_4_4_4, UNSIGNED_SHORT_4_4_4_4_REV,
                                         UNSIGNED_SHORT_5_5_5_1, UNSIGNED_SHORT_1_5_5_5_REV, UNSIGNED_INT_8_8_8_8,
                                         UNSIGNED_INT_8_8_8_8_REV, UNSIGNED_INT_10_10_10_2,
                                         UNSIGNED_INT_2_10_10_10_REV, UNSIGNED_INT_10F_11F_11F_REV,
                                         UNSIGNED_INT_5_9_9_9_REV, UNSIGNED_INT_24_8, FLOAT_32_UNSIGNED_INT_24_8_REV,
                                         DOUBLE};

// The bytes of one element of a pixel type (what PACK_ALIGNMENT compares with) and of one pixel, as OpenGL 3.3's
// tables give them (a packed type: one element a pixel; 0 for a pair no call accepts is never needed).
std::size_t ElementBytes(std::uint32_t type) {
  switch (type) {
    case UNSIGNED_BYTE: case BYTE: case UNSIGNED_BYTE_3_3_2: case UNSIGNED_BYTE_2_3_3_REV: return 1;
    case UNSIGNED_SHORT: case SHORT: case HALF_FLOAT: case UNSIGNED_SHORT_5_6_5: case UNSIGNED_SHORT_5_6_5_REV:
    case UNSIGNED_SHORT_4_4_4_4: case UNSIGNED_SHORT_4_4_4_4_REV: case UNSIGNED_SHORT_5_5_5_1:
    case UNSIGNED_SHORT_1_5_5_5_REV: return 2;
    default: return 4;
  }
}
std::size_t PixelBytes(std::uint32_t format, std::uint32_t type) {
  if (type == FLOAT_32_UNSIGNED_INT_24_8_REV) return 8;
  switch (type) {
    case UNSIGNED_BYTE: case BYTE: case UNSIGNED_SHORT: case SHORT: case UNSIGNED_INT: case INT: case HALF_FLOAT:
    case FLOAT: break;
    default: return ElementBytes(type);  // packed
  }
  const std::size_t components = format == RGBA || format == BGRA ? 4 : format == RGB || format == BGR ? 3
                                 : format == RG ? 2 : 1;
  return components * ElementBytes(type);
}
constexpr std::uint32_t kParams[] = {TEXTURE_MIN_FILTER, TEXTURE_MAG_FILTER, TEXTURE_WRAP_S, TEXTURE_WRAP_T,
                                     TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, TEXTURE_MIN_LOD, TEXTURE_MAX_LOD,
                                     TEXTURE_LOD_BIAS, TEXTURE_COMPARE_MODE, TEXTURE_COMPARE_FUNC};
constexpr std::uint32_t kParamValues[] = {NEAREST, LINEAR, NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_LINEAR, REPEAT,
                                          CLAMP_TO_EDGE, CLAMP_TO_BORDER, MIRRORED_REPEAT, COMPARE_REF_TO_TEXTURE,
                                          LEQUAL, 0, 1, 2, 1000};
constexpr std::uint32_t kFuncs[] = {NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS};
constexpr std::uint32_t kOps[] = {KEEP, ZERO, REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP};
constexpr std::uint32_t kFactors[] = {ZERO, ONE, SRC_COLOR, ONE_MINUS_SRC_ALPHA, DST_COLOR, CONSTANT_ALPHA,
                                      SRC_ALPHA_SATURATE};
constexpr std::uint32_t kEquations[] = {FUNC_ADD, FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN, MAX};
constexpr std::uint32_t kFaces[] = {FRONT, BACK, FRONT_AND_BACK};
constexpr std::uint32_t kFbTargets[] = {FRAMEBUFFER, DRAW_FRAMEBUFFER, READ_FRAMEBUFFER};
constexpr std::uint32_t kAttachments[] = {COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1, COLOR_ATTACHMENT0 + 3,
                                          DEPTH_ATTACHMENT, STENCIL_ATTACHMENT, DEPTH_STENCIL_ATTACHMENT,
                                          COLOR_ATTACHMENT0 + 7, COLOR_ATTACHMENT0 + 8};
constexpr std::uint32_t kRenderbufferFormats[] = {RGBA8, RGB8, R32F, RGBA, DEPTH_COMPONENT16, DEPTH_COMPONENT24,
                                                  DEPTH24_STENCIL8, DEPTH32F_STENCIL8, STENCIL_INDEX8, R32UI, RGBA16I, 0x1234};
constexpr std::uint32_t kReadBuffers[] = {NONE, BACK, FRONT, RIGHT, COLOR_ATTACHMENT0, COLOR_ATTACHMENT0 + 1,
                                          COLOR_ATTACHMENT0 + 3, COLOR_ATTACHMENT0 + 5};
constexpr std::uint32_t kPolygonModes[] = {FILL, LINE, POINT};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input in(data, size);
  // Small framebuffers: size validation has its own tests, and a legitimately huge one only costs time here.
  // The bytes' quotients choose a 16-bit depth buffer (Options::depth_format) for some contexts.
  const int wb = in.Byte(), hb = in.Byte();
  Context::Options options;
  options.depth_format = (wb / 49 + hb / 49) % 2 ? DEPTH_COMPONENT16 : DEPTH_COMPONENT32F;
  Context gl(wb % 49, hb % 49, options);
  FuzzShader shader;
  FuzzGeometry geometry;
  FuzzAdjacency adjacency;
  std::vector<std::uint8_t> scratch;
  std::array<Sync, 6> fences{};  // the fences made (deleted ones stay here: stale handles are passed back too)
  // Work per input is bounded, so that an input's time says something about softgl: at most kDrawBudget vertices
  // over all draws (a 255-pixel point covers the whole target, so fragments <= budget x target area), render
  // targets of at most 64x64 (textures above 64 texels a side are folded back unless they are invalid).
  constexpr int kDrawBudget = 1 << 10;
  int drawn = 0;
  const auto draw_count = [&] {
    const int n = in.Amount(-2, 600, 1024);
    const int left = kDrawBudget - drawn;
    drawn += std::max(n, 0);
    return n > left ? std::max(left, 0) : n;
  };
  for (int step = 0; step < 200 && !in.Empty(); ++step) {
    const auto id = [&] { return std::uint32_t(in.Byte() % 8); };
    switch (in.Byte() % 48) {
      case 0: gl.GenBuffer(); break;
      case 1: gl.BindBuffer(in.Enum(kBufferTargets), id()); break;
      case 2: {
        const int n = in.Amount(0, 512, 1 << 20);
        const std::size_t len = std::size_t(std::max(n, 0)), avail = std::min(len, in.Remaining());
        const std::uint8_t* p = in.Bytes(len);
        scratch.assign(len, 0);
        if (avail) std::memcpy(scratch.data(), p, avail);
        gl.BufferData(in.Enum(kBufferTargets), n, in.Byte() % 4 ? scratch.data() : nullptr);
        break;
      }
      case 3: {
        const int n = in.Amount(0, 64, 1 << 16);
        scratch.assign(std::size_t(n > 0 ? n : 0), in.Byte());
        const std::uint32_t target = in.Enum(kBufferTargets);
        switch (in.Byte() % 6) {
          case 0: gl.BufferSubData(target, in.Int(-4, 512), n, scratch.data()); break;
          case 1: gl.GetBufferSubData(target, in.Int(-4, 512), n, scratch.data()); break;
          case 2: {  // the mapping is written end to end, so that ASan sees any range it should not have given
            const Bitfield access = in.Byte() % 4 ? std::uint32_t(in.Int(0, 0x3F)) : in.Get<std::uint32_t>();
            if (auto* p = static_cast<std::uint8_t*>(gl.MapBufferRange(target, in.Int(-4, 512), n, access)))
              std::memset(p, 0x5A, std::size_t(n));
            break;
          }
          case 3: (void)gl.UnmapBuffer(target); break;
          case 4: gl.CopyBufferSubData(target, in.Enum(kBufferTargets), in.Int(-4, 512), in.Int(-4, 512), n); break;
          default: {
            int v = 0;
            gl.GetBufferParameteriv(target, BUFFER_SIZE + std::uint32_t(in.Int(0, 1)), &v);
            gl.FlushMappedBufferRange(target, in.Int(-4, 64), in.Int(-4, 64));
            break;
          }
        }
        break;
      }
      case 4: gl.GenVertexArray(); break;
      case 5: gl.BindVertexArray(id()); break;
      case 6:
        if (in.Byte() % 4)
          gl.VertexAttributePointer(std::uint32_t(in.Int(0, 16)), in.Byte() % 8 ? in.Int(0, 5) : int(BGRA), in.Enum(kTypes), in.Byte() & 1,
                                    in.Int(-4, 64), std::size_t(std::uint32_t(in.Int(0, 256))));
        else  // integer arrays (any type: the float ones are errors)
          gl.VertexAttribIPointer(std::uint32_t(in.Int(0, 16)), in.Int(0, 5), in.Enum(kTypes), in.Int(-4, 64),
                                  std::size_t(std::uint32_t(in.Int(0, 256))));
        break;
      case 7: gl.EnableVertexAttribArray(std::uint32_t(in.Int(0, 16))); break;
      case 8:
        switch (in.Byte() % 4) {
          case 0: gl.DisableVertexAttribArray(std::uint32_t(in.Int(0, 16))); break;
          case 1: gl.VertexAttribDivisor(std::uint32_t(in.Int(0, 16)), std::uint32_t(in.Int(0, 3))); break;
          case 2: gl.VertexAttribI4i(std::uint32_t(in.Int(0, 16)), in.Get<int>(), in.Get<int>(), in.Get<int>(), in.Get<int>()); break;
          default: {
            const std::uint32_t v[4] = {in.Get<std::uint32_t>(), in.Get<std::uint32_t>(), 0, 1};
            gl.VertexAttribI4uiv(std::uint32_t(in.Int(0, 16)), in.Byte() % 8 ? v : nullptr);
            break;
          }
        }
        break;
      case 9: {  // one of the programs, two of them with a geometry stage
        const int which = in.Byte() % 4;
        if (which == 1) gl.UseProgram(geometry);
        else if (which == 2) gl.UseProgram(adjacency);
        else gl.UseProgram(shader);
        break;
      }
      case 10: {
        const std::uint32_t mode = in.Enum(kModes);
        const int first = in.Int(-2, 64);
        const int count = draw_count();
        switch (in.Byte() % 3) {  // (an input that ends here: DrawArrays)
          case 0: gl.DrawArrays(mode, first, count); break;
          case 1: {
            const int firsts[3] = {first, in.Int(-2, 64), in.Int(-2, 64)};
            const int counts[3] = {count, draw_count(), draw_count()};
            gl.MultiDrawArrays(mode, firsts, counts, std::min(in.Int(-1, 3), 3));  // the arrays hold 3
            break;
          }
          default: {  // instances share the budget the count took
            const int instances = in.Int(-1, 4);
            gl.DrawArraysInstanced(mode, first, instances > 1 ? count / instances : count, instances);
            break;
          }
        }
        break;
      }
      case 11: {
        const std::uint32_t mode = in.Enum(kModes);
        const int count = draw_count();
        const std::uint32_t type = in.Enum(kIndexTypes);
        const auto offset = std::size_t(std::uint32_t(in.Int(0, 512)));
        switch (in.Byte() % 5) {  // (an input that ends here: DrawElement)
          case 0: gl.DrawElement(mode, count, type, offset); break;
          case 3: {  // instances share the budget the count took
            const int instances = in.Int(-1, 4);
            gl.DrawElementsInstancedBaseVertex(mode, instances > 1 ? count / instances : count, type, offset,
                                               instances, in.Int(-64, 64));
            break;
          }
          case 1: gl.DrawElementsBaseVertex(mode, count, type, offset, in.Int(-64, 64)); break;
          case 2:
            if (in.Byte() % 2) gl.DrawRangeElements(mode, in.Get<std::uint32_t>(), in.Get<std::uint32_t>(), count, type, offset);
            else gl.DrawRangeElementsBaseVertex(mode, in.Get<std::uint32_t>(), in.Get<std::uint32_t>(), count, type, offset, in.Int(-64, 64));
            break;
          default: {
            const int counts[3] = {count, draw_count(), draw_count()};
            const std::size_t offsets[3] = {offset, std::size_t(std::uint32_t(in.Int(0, 512))),
                                            std::size_t(std::uint32_t(in.Int(0, 512)))};
            const int base[3] = {in.Int(-64, 64), in.Int(-64, 64), in.Int(-64, 64)};
            const int n = std::min(in.Int(-1, 3), 3);  // the arrays hold 3
            if (in.Byte() % 2) gl.MultiDrawElements(mode, counts, type, offsets, n);
            else gl.MultiDrawElementsBaseVertex(mode, counts, type, offsets, n, in.Byte() % 8 ? base : nullptr);
            break;
          }
        }
        break;
      }
      case 12: gl.Enable(in.Enum(kCaps)); break;
      case 13: gl.Disable(in.Enum(kCaps)); break;
      case 14: gl.Viewport(in.Int(-64, 64), in.Int(-64, 64), in.Int(-2, 80), in.Int(-2, 80)); break;
      case 15: gl.Scissor(in.Int(-64, 64), in.Int(-64, 64), in.Int(-2, 80), in.Int(-2, 80)); break;
      case 16: gl.Clear(std::uint32_t(in.Get<std::uint16_t>()) | COLOR_BUFFER_BIT); break;
      case 17: {
        const std::uint32_t ids[2] = {id(), id()};
        if (in.Byte() % 2) gl.DeleteBuffer(ids[0]);
        else gl.DeleteBuffers(std::clamp(in.Int(-1, 2), -1, 2), ids);  // (Int may return any int: ids holds 2)
        break;
      }
      case 18: gl.DeleteVertexArray(id()); break;
      case 19: gl.GenTexture(); break;
      case 20: gl.ActiveTexture(TEXTURE0 + std::uint32_t(in.Int(0, 17))); break;
      case 21: gl.BindTexture(in.Enum(kTexTargets), id()); break;
      case 22: {
        // Sizes are mostly small, sometimes wild; pixels are given only when the buffer holds them (as a caller
        // of OpenGL must), otherwise the level is allocated without data.
        const int w = in.Amount(0, 16, 64, kMaxTextureSize), h = in.Amount(0, 16, 64, kMaxTextureSize);
        const bool small = w >= 0 && h >= 0 && w <= 64 && h <= 64;
        if (small) scratch.assign(std::size_t(w) * std::size_t(h) * 16 + 64, in.Byte());
        const void* pixels = small && in.Byte() % 4 ? scratch.data() : nullptr;
        switch (in.Byte() % 8) {  // 1D textures and 1D arrays now and then
          case 0:
            gl.TexImage1D(in.Byte() % 4 ? TEXTURE_1D : TEXTURE_2D, in.Int(-1, 5), in.Enum(kInternal), w, in.Byte() < 8,
                          in.Enum(kFormats), in.Enum(kPixelTypes), pixels);
            break;
          case 1:
            gl.TexSubImage1D(TEXTURE_1D, in.Int(-1, 3), in.Int(-2, 8), w, in.Enum(kFormats), in.Enum(kPixelTypes), pixels);
            break;
          case 2:
            gl.TexImage2D(TEXTURE_1D_ARRAY, in.Int(-1, 5), in.Enum(kInternal), w, h, in.Byte() < 8, in.Enum(kFormats),
                          in.Enum(kPixelTypes), pixels);
            break;
          case 3:
            if (in.Byte() % 2) gl.CopyTexImage1D(TEXTURE_1D, in.Int(-1, 3), in.Enum(kFormats), in.Int(-60, 60), in.Int(-60, 60), in.Int(-1, 64), in.Byte() < 8);
            else gl.CopyTexSubImage1D(TEXTURE_1D, in.Int(-1, 3), in.Int(-2, 8), in.Int(-60, 60), in.Int(-60, 60), in.Int(-1, 64));
            break;
          case 4:
            gl.FramebufferTexture1D(in.Enum(kFbTargets), in.Enum(kAttachments), in.Byte() % 4 ? TEXTURE_1D : TEXTURE_2D, id(),
                                    in.Int(-1, 4));
            break;
          case 6: {  // buffer textures: any format and buffer id, and their level queries
            gl.TexBuffer(in.Byte() % 8 ? TEXTURE_BUFFER : TEXTURE_2D, in.Enum(kBufferTextureFormats), id());
            int v = 0;
            gl.GetTexLevelParameteriv(in.Byte() % 4 ? TEXTURE_BUFFER : TEXTURE_2D, in.Int(-1, 2), in.Enum(kBufferTextureNames), &v);
            break;
          }
          case 5: {  // compressed images: the right image size mostly, data only where scratch holds that many bytes
            const Enum format = in.Enum(kCompressed);
            const int d = in.Amount(0, 2, 4, kMaxArrayTextureLayers);
            // (Amount may return any int too: sizes are clamped before the product.)
            const auto clamped = [](int v) { return std::int64_t(std::clamp(v, 0, 1 << 16)); };
            const std::int64_t right =
                (clamped(w) + 3) / 4 * ((clamped(h) + 3) / 4) * clamped(d) * (in.Byte() % 2 ? 8 : 16);
            const int size = in.Byte() % 4 ? int(std::min<std::int64_t>(right, INT32_MAX)) : in.Int(-1, 64);
            const void* data = small && size >= 0 && std::size_t(size) <= scratch.size() && in.Byte() % 8 ? scratch.data() : nullptr;
            // (Int may return any int: block offsets are clamped before they are multiplied.)
            const auto block = [&] { return 4 * std::clamp(in.Int(-1, 4), -1, 4); };
            switch (in.Byte() % 6) {
              case 0: gl.CompressedTexImage2D(in.Enum(kImageTargets), in.Int(-1, 5), format, w, h, in.Byte() < 8, size, data); break;
              case 1: gl.CompressedTexImage3D(in.Byte() % 2 ? TEXTURE_2D_ARRAY : TEXTURE_3D, in.Int(-1, 5), format, w, h, d, 0, size, data); break;
              case 2: gl.CompressedTexSubImage2D(in.Enum(kImageTargets), in.Int(-1, 5), block(), block() + (in.Byte() < 16), w, h, format, size, data); break;
              case 3: gl.CompressedTexSubImage3D(TEXTURE_2D_ARRAY, in.Int(-1, 5), block(), block(), in.Int(-1, 4), w, h, d, format, size, data); break;
              case 4: in.Byte() % 2 ? gl.CompressedTexImage1D(TEXTURE_1D, 0, format, w, 0, size, data) : gl.CompressedTexSubImage1D(TEXTURE_1D, 0, 0, w, format, size, data); break;
              default: {
                std::vector<std::uint8_t> out;
                int bytes = 0;
                gl.GetTexLevelParameteriv(in.Enum(kImageTargets), 0, TEXTURE_COMPRESSED_IMAGE_SIZE, &bytes);
                if (gl.GetError() == NO_ERROR && bytes >= 0 && bytes <= (1 << 20)) out.resize(std::size_t(bytes) + 1);
                gl.GetCompressedTexImage(in.Enum(kImageTargets), in.Int(-1, 3), out.empty() ? nullptr : out.data());
                break;
              }
            }
            break;
          }
          default:
            gl.TexImage2D(in.Enum(kImageTargets), in.Int(-1, 5), in.Enum(kInternal), w, h, in.Byte() < 8,
                          in.Enum(kFormats), in.Enum(kPixelTypes), pixels);
            break;
        }
        break;
      }
      case 23: {
        constexpr std::uint32_t kImageTargets[] = {TEXTURE_2D, TEXTURE_CUBE_MAP_POSITIVE_X, TEXTURE_CUBE_MAP_NEGATIVE_Z};
        const auto small = [&](int lo, int hi) { return std::clamp(in.Int(lo, hi), lo, hi); };
        switch (in.Byte() % 4) {
          case 0: gl.GenerateMipmap(in.Enum(kTexTargets)); break;
          case 1:
            gl.CopyTexImage2D(in.Enum(kImageTargets), small(-1, 3), in.Enum(kFormats), in.Int(-60, 60), in.Int(-60, 60),
                              small(-1, 64), small(-1, 64), small(0, 1));
            break;
          case 2:
            gl.CopyTexSubImage2D(in.Enum(kImageTargets), small(-1, 3), in.Int(-4, 64), in.Int(-4, 64), in.Int(-60, 60),
                                 in.Int(-60, 60), small(-1, 64), small(-1, 64));
            break;
          default: {  // into a buffer as large as the largest level any input makes (64 x 64 RGBA floats)
            scratch.assign(std::size_t(64) * 64 * 16 + 64 * 16, 0);
            gl.PixelStore(PACK_ALIGNMENT, 4);
            gl.PixelStore(PACK_ROW_LENGTH, 0);
            gl.PixelStore(PACK_SKIP_ROWS, 0);
            gl.PixelStore(PACK_SKIP_PIXELS, 0);
            gl.GetTexImage(in.Enum(kImageTargets), small(-1, 3), in.Enum(kFormats), in.Enum(kPixelTypes),
                           scratch.data());
            break;
          }
        }
        break;
      }
      case 24: {
        int iv[4] = {int(in.Enum(kParamValues)), in.Int(-9, 9), in.Get<int>(), in.Get<int>()};
        float fv[4];
        switch (in.Byte() % 4) {
          case 0: gl.TexParameteri(in.Enum(kTexTargets), in.Enum(kParams), iv[0]); break;
          case 1: {
            const std::uint32_t target = in.Enum(kTexTargets), pname = in.Byte() % 4 ? in.Enum(kParams) : TEXTURE_BORDER_COLOR;
            switch (in.Byte() % 3) {
              case 0: gl.TexParameteriv(target, pname, iv); break;
              case 1: gl.TexParameterIiv(target, pname, in.Byte() % 8 ? iv : nullptr); break;
              default: gl.TexParameterIuiv(target, pname, reinterpret_cast<const std::uint32_t*>(iv)); break;
            }
            break;
          }
          case 2: {
            std::uint32_t uv[4];
            gl.GetTexParameteriv(in.Enum(kTexTargets), in.Byte() % 4 ? in.Enum(kParams) : TEXTURE_BORDER_COLOR, iv);
            gl.GetTexParameterfv(in.Enum(kTexTargets), in.Enum(kParams), fv);
            gl.GetTexParameterIiv(in.Enum(kTexTargets), in.Byte() % 4 ? in.Enum(kParams) : TEXTURE_BORDER_COLOR, iv);
            gl.GetTexParameterIuiv(in.Enum(kTexTargets), in.Byte() % 4 ? in.Enum(kParams) : TEXTURE_BORDER_COLOR, uv);
            break;
          }
          default:
            gl.GetTexLevelParameteriv(in.Enum(kImageTargets), in.Int(-1, 16), std::uint32_t(in.Int(0x1000, 0x1004)), iv);
            gl.GetTexLevelParameterfv(in.Enum(kImageTargets), in.Int(-1, 16), std::uint32_t(in.Int(0x8059, 0x8060)), fv);
            break;
        }
        break;
      }
      case 25: gl.TexParameterf(in.Enum(kTexTargets), in.Enum(kParams), in.Float()); break;
      case 26: gl.GenFramebuffer(); break;
      case 27: gl.BindFramebuffer(in.Enum(kFbTargets), id()); break;
      case 28:
        gl.FramebufferTexture2D(in.Enum(kFbTargets), in.Enum(kAttachments), in.Enum(kImageTargets), id(),
                                in.Int(-1, 4));
        break;
      case 29: {
        // (n up to one past the limit, read only when it is accepted: the array holds the limit's count)
        std::uint32_t bufs[kMaxColorOutputs] = {in.Enum(kAttachments), in.Enum(kAttachments), NONE, COLOR_ATTACHMENT0 + 2};
        for (int i = 4; i < kMaxColorOutputs; ++i) bufs[i] = in.Enum(kAttachments);
        gl.DrawBuffers(in.Int(-1, kMaxColorOutputs + 1), bufs);
        break;
      }
      case 30: gl.StencilFuncSeparate(in.Enum(kFaces), in.Enum(kFuncs), in.Int(-300, 300), in.Get<std::uint32_t>()); break;
      case 31:
        if (in.Byte() % 4) gl.StencilOpSeparate(in.Enum(kFaces), in.Enum(kOps), in.Enum(kOps), in.Enum(kOps));
        else gl.LogicOp(CLEAR + std::uint32_t(in.Int(-1, 16)));  // the sixteen operations, and one each side
        break;
      case 32: gl.BlendFuncSeparate(in.Enum(kFactors), in.Enum(kFactors), in.Enum(kFactors), in.Enum(kFactors)); break;
      case 33:
        if (in.Byte() % 2) {
          gl.BlendEquationSeparate(in.Enum(kEquations), in.Enum(kEquations));
        } else {  // per-draw-buffer state and the indexed queries: any index (past the last too), other names
          const std::uint32_t index = std::uint32_t(in.Int(-1, kMaxColorOutputs + 1));
          const std::uint32_t cap = in.Byte() % 4 ? BLEND : DEPTH_TEST;
          bool bv[4];
          int iv[4];
          std::int64_t lv[4];
          switch (in.Byte() % 5) {
            case 0: gl.ColorMaski(index, in.Byte() % 2, in.Byte() % 2, in.Byte() % 2, in.Byte() % 2); break;
            case 1: gl.Enablei(cap, index); break;
            case 2: gl.Disablei(cap, index); break;
            case 3: (void)gl.IsEnabledi(cap, index); break;
            default: {
              constexpr std::uint32_t kIndexed[] = {BLEND, COLOR_WRITEMASK, SAMPLE_MASK_VALUE, DEPTH_FUNC};
              const std::uint32_t target = in.Enum(kIndexed);
              gl.GetBooleani_v(target, index, in.Byte() % 8 ? bv : nullptr);
              gl.GetIntegeri_v(target, index, iv);
              gl.GetInteger64i_v(target, index, lv);
              break;
            }
          }
        }
        break;
      case 34: gl.PolygonMode(FRONT_AND_BACK, in.Enum(kPolygonModes)); break;
      case 35: gl.PolygonOffset(in.Float(), in.Float()); break;
      case 36: {
        constexpr std::uint32_t kQueryTargets[] = {SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED,
                                                   TIME_ELAPSED, TIMESTAMP};
        std::uint64_t result = 0;
        int cols = 0, rows = 0;
        switch (in.Byte() % 8) {
          case 0: gl.DepthRange(in.Float(), in.Float()); break;
          case 1: gl.GenQuery(); break;
          case 2: gl.BeginQuery(in.Enum(kQueryTargets), id()); break;
          case 3: gl.EndQuery(in.Enum(kQueryTargets)); break;
          case 4:
            if (in.Byte() % 2) gl.DeleteQuery(id());
            else gl.QueryCounter(id(), in.Enum(kQueryTargets));
            break;
          case 5: gl.CountTilePrimitives(in.Byte() % 2 != 0); break;
          case 6:
            if (gl.TilePrimitiveCounts(&cols, &rows).size() != std::size_t(cols) * std::size_t(rows)) __builtin_trap();
            break;
          default: gl.GetQueryObjectui64v(id(), in.Byte() % 2 ? QUERY_RESULT : QUERY_RESULT_AVAILABLE, &result); break;
        }
        break;
      }
      case 37:
        switch (in.Byte() % 3) {
          case 0:
            if (in.Byte() % 2) gl.PointSize(in.Float());
            else gl.LineWidth(in.Byte() % 2 ? float(in.Int(0, 8)) : in.Float());  // wide lines, any value
            break;
          case 1: gl.PrimitiveRestartIndex(in.Byte() % 2 ? in.Get<std::uint32_t>() : std::uint32_t(in.Int(0, 8))); break;
          default: {  // PointParameter: either name, any value (an origin's enum, as a float too), null now and then
            const std::uint32_t pname = in.Byte() % 4 ? (in.Byte() % 2 ? POINT_SPRITE_COORD_ORIGIN : POINT_FADE_THRESHOLD_SIZE) : POINT_SIZE;
            const int i = in.Byte() % 2 ? int(in.Byte() % 2 ? LOWER_LEFT : UPPER_LEFT) : in.Get<int>();
            const float f = in.Byte() % 2 ? float(i) : in.Float();
            if (in.Byte() % 2) gl.PointParameteriv(pname, in.Byte() % 8 ? &i : nullptr);
            else gl.PointParameterfv(pname, in.Byte() % 8 ? &f : nullptr);
            break;
          }
        }
        break;
      case 38:
        if (in.Byte() % 4) {
          gl.VertexAttrib4f(std::uint32_t(in.Int(0, 16)), in.Float(), in.Float(), in.Float(), in.Float());
        } else {  // packed current values: any word, type and index; null for the uiv form now and then
          const std::uint32_t word = in.Get<std::uint32_t>(), index = std::uint32_t(in.Int(0, 16));
          const std::uint32_t type = in.Byte() % 8 ? (in.Byte() % 2 ? INT_2_10_10_10_REV : UNSIGNED_INT_2_10_10_10_REV) : FLOAT;
          const bool normalized = in.Byte() % 2 != 0;
          switch (in.Byte() % 5) {
            case 0: gl.VertexAttribP1ui(index, type, normalized, word); break;
            case 1: gl.VertexAttribP2uiv(index, type, normalized, &word); break;
            case 2: gl.VertexAttribP3ui(index, type, normalized, word); break;
            case 3: gl.VertexAttribP4ui(index, type, normalized, word); break;
            default: gl.VertexAttribP4uiv(index, type, normalized, in.Byte() % 2 ? &word : nullptr); break;
          }
        }
        break;
      case 39: {  // renderbuffers (sizes mostly small, sometimes wild)
        int v = 0;
        switch (in.Byte() % 6) {
          case 0: gl.GenRenderbuffer(); break;
          case 1: gl.BindRenderbuffer(in.Byte() % 8 ? RENDERBUFFER : TEXTURE_2D, id()); break;
          case 2:
            if (in.Byte() % 2)
              gl.RenderbufferStorage(RENDERBUFFER, in.Enum(kRenderbufferFormats), in.Amount(-1, 16, 64, kMaxFramebufferSize),
                                     in.Amount(-1, 16, 64, kMaxFramebufferSize));
            else  // multisampled: counts beyond MAX_SAMPLES too
              gl.RenderbufferStorageMultisample(RENDERBUFFER, in.Int(-1, 9), in.Enum(kRenderbufferFormats),
                                                in.Amount(-1, 16, 64, kMaxFramebufferSize),
                                                in.Amount(-1, 16, 64, kMaxFramebufferSize));
            if (in.Byte() % 4 == 0) gl.SampleCoverage(in.Float(), in.Byte() % 2);
            if (in.Byte() % 4 == 0) gl.SampleMaski(std::uint32_t(in.Int(0, 1)), in.Get<std::uint32_t>());
            if (in.Byte() % 4 == 0) gl.MinSampleShading(in.Float());
            break;
          case 3: gl.FramebufferRenderbuffer(in.Enum(kFbTargets), in.Enum(kAttachments), RENDERBUFFER, id()); break;
          case 4: gl.DeleteRenderbuffer(id()); break;
          default:
            gl.GetRenderbufferParameteriv(RENDERBUFFER, std::uint32_t(in.Int(0x8D40, 0x8D56)), &v);
            gl.GetFramebufferAttachmentParameteriv(in.Enum(kFbTargets), in.Enum(kAttachments),
                                                   std::uint32_t(in.Int(0x8CCF, 0x8CD4)), &v);
            break;
        }
        break;
      }
      case 40:
        if (in.Byte() % 3 == 0) {
          gl.ReadBuffer(in.Enum(kReadBuffers));
        } else {  // rectangles anywhere, mostly near the small targets
          const auto c = [&] { return in.Int(-80, 80); };
          gl.BlitFramebuffer(c(), c(), c(), c(), c(), c(), c(), c(), std::uint32_t(in.Get<std::uint16_t>()) & 0x4500u,
                             in.Byte() % 2 ? NEAREST : LINEAR);
        }
        break;
      case 41: {  // texture arrays and 3D textures: sizes mostly small, sometimes wild (products beyond any memory)
        constexpr std::uint32_t kLayered[] = {TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_2D};
        const auto size = [&] { return in.Amount(0, 8, 64, kMaxTextureSize); };
        const int w = size(), h = size(), d = size();
        const bool small = w >= 0 && h >= 0 && d >= 0 && w <= 64 && h <= 64 && d <= 64;
        if (small) scratch.assign(std::size_t(w) * std::size_t(h) * std::size_t(d) * 16 + 64, in.Byte());
        const void* pixels = small && in.Byte() % 4 ? scratch.data() : nullptr;
        switch (in.Byte() % 4) {
          case 3:
            if (in.Byte() % 2)
              gl.TexImage2DMultisample(in.Byte() % 8 ? TEXTURE_2D_MULTISAMPLE : TEXTURE_2D, in.Int(-1, 10),
                                       in.Enum(kInternal), w, h, in.Byte() % 2);
            else  // multisample arrays: the layers wild only where width and height are small
              gl.TexImage3DMultisample(in.Byte() % 8 ? TEXTURE_2D_MULTISAMPLE_ARRAY : TEXTURE_2D_ARRAY, in.Int(-1, 10),
                                       in.Enum(kInternal), w, h, small ? d : in.Int(-1, 4), in.Byte() % 2);
            break;
          case 0:
            gl.TexImage3D(in.Enum(kLayered), in.Int(-1, 5), in.Enum(kInternal), w, h, d, in.Byte() < 8,
                          in.Enum(kFormats), in.Enum(kPixelTypes), pixels);
            break;
          case 1:
            gl.TexSubImage3D(in.Enum(kLayered), in.Int(-1, 5), in.Int(-2, 8), in.Int(-2, 8), in.Int(-2, 8), w, h, d,
                             in.Enum(kFormats), in.Enum(kPixelTypes), pixels);
            break;
          default:
            if (in.Byte() % 2) {
              switch (in.Byte() % 3) {  // one layer, one slice, or every layer (a layered framebuffer)
                case 0: gl.FramebufferTextureLayer(in.Enum(kFbTargets), in.Enum(kAttachments), id(), in.Int(-1, 4), in.Int(-1, 9)); break;
                case 1: gl.FramebufferTexture3D(in.Enum(kFbTargets), in.Enum(kAttachments), in.Enum(kLayered), id(), in.Int(-1, 4), in.Int(-1, 9)); break;
                default: gl.FramebufferTexture(in.Enum(kFbTargets), in.Enum(kAttachments), id(), in.Int(-1, 4)); break;
              }
            } else if (in.Byte() % 2) {
              gl.CopyTexSubImage3D(in.Enum(kLayered), in.Int(-1, 3), in.Int(-4, 64), in.Int(-4, 64), in.Int(-2, 9),
                                   in.Int(-60, 60), in.Int(-60, 60), in.Int(-1, 64), in.Int(-1, 64));
            } else {  // into a buffer as large as the bound level (asked for first), when that is small
              const std::uint32_t target = in.Enum(kLayered);
              const int level = in.Int(-1, 3);
              int lw = 0, lh = 0, ld = 0;
              gl.GetTexLevelParameteriv(target, level, TEXTURE_WIDTH, &lw);
              gl.GetTexLevelParameteriv(target, level, TEXTURE_HEIGHT, &lh);
              gl.GetTexLevelParameteriv(target, level, TEXTURE_DEPTH, &ld);
              if (std::int64_t(lw) * lh * ld > 64 * 64 * 64) break;
              scratch.assign(std::size_t(lw) * std::size_t(lh) * std::size_t(ld) * 16 + 64 * 16, 0);
              gl.PixelStore(PACK_ALIGNMENT, 4);
              gl.PixelStore(PACK_ROW_LENGTH, 0);
              gl.PixelStore(PACK_SKIP_ROWS, 0);
              gl.PixelStore(PACK_SKIP_PIXELS, 0);
              gl.GetTexImage(target, level, in.Enum(kFormats), in.Enum(kPixelTypes), scratch.data());
            }
            break;
        }
        break;
      }
      case 42: {  // hostile arguments: rectangles at the ends of int, NaN and infinite colours, null pointers
        constexpr int kEnds[] = {INT_MIN, INT_MIN + 1, -1, 0, 1, INT_MAX - 1, INT_MAX};
        const auto end = [&] { return in.Byte() % 4 ? kEnds[in.Byte() % 7] : in.Get<int>(); };
        const auto small = [&](int lo, int hi) { return std::clamp(in.Int(lo, hi), lo, hi); };
        constexpr std::uint32_t kImageTargets[] = {TEXTURE_2D, TEXTURE_CUBE_MAP_POSITIVE_X, TEXTURE_CUBE_MAP_NEGATIVE_Z};
        switch (in.Byte() % 6) {
          case 0:
            gl.BlitFramebuffer(end(), end(), end(), end(), end(), end(), end(), end(),
                               std::uint32_t(in.Get<std::uint16_t>()) & 0x4500u, in.Byte() % 2 ? NEAREST : LINEAR);
            break;
          case 1:
            if (in.Byte() % 2)
              gl.CopyTexSubImage2D(in.Enum(kImageTargets), small(0, 2), small(0, 8), small(0, 8), end(), end(),
                                   small(-1, 64), small(-1, 64));
            else if (in.Byte() % 2)
              gl.CopyTexImage2D(in.Enum(kImageTargets), small(0, 2), in.Enum(kInternal), end(), end(), small(-1, 64),
                                small(-1, 64), 0);
            else
              gl.CopyTexSubImage3D(in.Byte() % 2 ? TEXTURE_2D_ARRAY : TEXTURE_3D, small(0, 2), small(0, 8),
                                   small(0, 8), small(0, 4), end(), end(), small(-1, 64), small(-1, 64));
            break;
          case 2: {  // colours of any bits cleared into whatever is bound, read back as every type
            gl.ClearColor(in.Float(), in.Float(), in.Float(), in.Float());
            gl.ClearDepth(double(in.Float()));
            gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
            std::uint32_t out[4 * 4];
            gl.PixelStore(PACK_ALIGNMENT, 4);
            gl.PixelStore(PACK_ROW_LENGTH, 0);
            gl.PixelStore(PACK_SKIP_ROWS, 0);
            gl.PixelStore(PACK_SKIP_PIXELS, 0);
            gl.ReadPixels(small(0, 8), small(0, 8), 2, 2, in.Enum(kFormats), in.Enum(kPixelTypes), out);
            gl.ReadPixels(small(0, 8), small(0, 8), 2, 2, in.Byte() % 2 ? DEPTH_COMPONENT : STENCIL_INDEX,
                          in.Enum(kPixelTypes), out);
            int iv[4];
            gl.GetIntegerv(in.Byte() % 2 ? COLOR_CLEAR_VALUE : DEPTH_CLEAR_VALUE, iv);
            break;
          }
          case 3: {  // a rectangle at the ends of int, 2 x 2 at most
            std::uint32_t out[4 * 4];
            gl.PixelStore(PACK_ALIGNMENT, 4);
            gl.PixelStore(PACK_ROW_LENGTH, 0);
            gl.PixelStore(PACK_SKIP_ROWS, 0);
            gl.PixelStore(PACK_SKIP_PIXELS, 0);
            gl.ReadPixels(end(), end(), small(-1, 2), small(-1, 2), RGBA, UNSIGNED_INT, out);
            break;
          }
          default: {  // null pointers with counts and rectangles around zero
            const int n = small(-1, 3);
            int iv[4];
            switch (in.Byte() % 12) {
              case 0: gl.GenBuffers(n, nullptr); break;
              case 1: gl.DeleteTextures(n, nullptr); break;
              case 2: gl.GenQueries(n, nullptr); break;
              case 3: gl.DrawBuffers(n, nullptr); break;
              case 4: gl.ReadPixel(small(0, 8), small(0, 8), nullptr); break;
              case 5: gl.ReadPixels(0, 0, n, small(-1, 3), RGBA, UNSIGNED_BYTE, nullptr); break;
              case 6: gl.GetIntegerv(std::uint32_t(in.Int(0x0B00, 0x0D60)), nullptr); break;
              case 7: gl.GetTexImage(in.Enum(kImageTargets), small(0, 2), RGBA, UNSIGNED_BYTE, nullptr); break;
              case 8: gl.BufferSubData(in.Enum(kBufferTargets), small(0, 8), n, nullptr); break;
              case 9: gl.GetBufferSubData(in.Enum(kBufferTargets), small(0, 8), n, nullptr); break;
              case 10:
                gl.TexSubImage2D(in.Enum(kImageTargets), small(0, 2), 0, 0, n, small(-1, 3), RGBA, UNSIGNED_BYTE,
                                 nullptr);
                break;
              default:
                gl.GetTexParameteriv(in.Enum(kTexTargets), in.Enum(kParams), nullptr);
                gl.GetBufferParameteriv(in.Enum(kBufferTargets), BUFFER_SIZE, nullptr);
                gl.GetIntegerv(VIEWPORT, iv);
                break;
            }
            break;
          }
        }
        break;
      }
      case 43: {  // sampler objects: made, bound to any unit (and past the last), set, read back, deleted
        int iv[4] = {int(in.Enum(kParamValues)), in.Int(-9, 9), in.Get<int>(), in.Get<int>()};
        std::uint32_t uv[4] = {in.Get<std::uint32_t>(), 0, 7, 0xFFFFFFFFu};
        float fv[4] = {in.Float(), in.Float(), in.Float(), in.Float()};
        const std::uint32_t pname = in.Byte() % 4 ? in.Enum(kParams) : TEXTURE_BORDER_COLOR;
        switch (in.Byte() % 8) {
          case 0: gl.GenSampler(); break;
          case 1: gl.BindSampler(in.Int(-1, kMaxTextureUnits), id()); break;
          case 2: gl.SamplerParameteri(id(), pname, iv[0]); break;
          case 3: gl.SamplerParameterfv(id(), pname, in.Byte() % 8 ? fv : nullptr); break;
          case 4: gl.SamplerParameteriv(id(), pname, iv); break;
          case 5:
            gl.SamplerParameterIiv(id(), pname, iv);
            gl.SamplerParameterIuiv(id(), pname, uv);
            break;
          case 6:
            gl.GetSamplerParameteriv(id(), pname, iv);
            gl.GetSamplerParameterfv(id(), pname, fv);
            gl.GetSamplerParameterIiv(id(), pname, iv);
            gl.GetSamplerParameterIuiv(id(), pname, uv);
            (void)gl.IsSampler(id());
            break;
          default: gl.DeleteSampler(id()); break;
        }
        break;
      }
      case 44: {  // ClearBuffer*: any buffer and draw buffer, values NaN, infinite or huge included; GetVertexAttrib*
        constexpr std::uint32_t kBuffers[] = {COLOR, DEPTH, STENCIL, DEPTH_STENCIL, COLOR_BUFFER_BIT, 0};
        const float fv[4] = {in.Float(), in.Float(), in.Float(), in.Float()};
        const int iv[4] = {in.Get<int>(), in.Int(-2, 300), 1, 0};
        const std::uint32_t uv[4] = {in.Get<std::uint32_t>(), 1, 0, 1};
        const std::uint32_t buffer = in.Enum(kBuffers);
        const int drawbuffer = in.Int(-1, kMaxColorOutputs);
        switch (in.Byte() % 5) {
          case 0: gl.ClearBufferfv(buffer, drawbuffer, in.Byte() % 8 ? fv : nullptr); break;
          case 1: gl.ClearBufferiv(buffer, drawbuffer, iv); break;
          case 2: gl.ClearBufferuiv(buffer, drawbuffer, uv); break;
          case 3: gl.ClearBufferfi(buffer, drawbuffer, fv[0], iv[1]); break;
          default: {
            const std::uint32_t index = std::uint32_t(in.Int(-1, kMaxVertexAttribs));
            const std::uint32_t pname = std::uint32_t(in.Byte() % 2 ? in.Int(0x8620, 0x8646) : in.Int(0x8869, 0x88FF));
            int out_i[4];
            std::uint32_t out_u[4];
            float out_f[4];
            double out_d[4];
            void* pointer = nullptr;
            gl.GetVertexAttribiv(index, pname, out_i);
            gl.GetVertexAttribIiv(index, pname, out_i);
            gl.GetVertexAttribIuiv(index, pname, out_u);
            gl.GetVertexAttribfv(index, pname, out_f);
            gl.GetVertexAttribdv(index, pname, out_d);
            gl.GetVertexAttribPointerv(index, pname, &pointer);
            break;
          }
        }
        break;
      }
      case 45: {  // conditional rendering, fences (handles made, deleted, stale and made up), ClampColor
        constexpr std::uint32_t kModes[] = {QUERY_WAIT, QUERY_NO_WAIT, QUERY_BY_REGION_WAIT, QUERY_BY_REGION_NO_WAIT,
                                            QUERY_RESULT, 0};
        constexpr std::uint32_t kSyncNames[] = {OBJECT_TYPE, SYNC_STATUS, SYNC_CONDITION, SYNC_FLAGS, SYNC_FENCE, 0};
        const auto sync = [&]() -> Sync {
          const int pick = in.Byte() % 8;
          if (pick == 6) return nullptr;
          if (pick == 7) return reinterpret_cast<Sync>(&scratch);  // not a fence
          return fences[std::size_t(pick)];
        };
        int values[2] = {0, 0}, length = 0;
        switch (in.Byte() % 8) {
          case 0: gl.BeginConditionalRender(id(), in.Enum(kModes)); break;
          case 1: gl.EndConditionalRender(); break;
          case 2: {
            const Sync made = gl.FenceSync(in.Byte() % 8 ? SYNC_GPU_COMMANDS_COMPLETE : SYNC_FENCE, in.Byte() % 8 ? 0u : 1u);
            fences[in.Byte() % fences.size()] = made;  // (an overwritten one stays alive: DeleteSync never sees it)
            break;
          }
          case 3: gl.DeleteSync(sync()); break;
          case 4: (void)gl.ClientWaitSync(sync(), in.Byte() % 4, in.Byte() % 2 ? 0 : in.Get<std::uint64_t>()); break;
          case 5: gl.WaitSync(sync(), in.Byte() % 4 ? 0 : 1, in.Byte() % 4 ? TIMEOUT_IGNORED : 0); break;
          case 6: gl.GetSynciv(sync(), in.Enum(kSyncNames), in.Int(-1, 2), in.Byte() % 2 ? &length : nullptr, in.Byte() % 8 ? values : nullptr); break;
          default: gl.ClampColor(in.Byte() % 8 ? CLAMP_READ_COLOR : CLAMP_TO_EDGE, std::uint32_t(in.Byte() % 4 ? in.Int(0, 2) : FIXED_ONLY)); break;
        }
        (void)gl.IsSync(sync());
        break;
      }
      case 46: {  // transform feedback: varyings (good and bad), bindings, Begin ... End, objects, their queries
        static const FeedbackVarying kVaryings[] = {
            FeedbackVarying::Position(), FuzzShader::Capture(&Vary::a, "a"), FuzzShader::Capture(&Vary::dir, "dir"),
            FuzzShader::Capture(&Vary::uv, "uv"), {"past", 8, 2}, {"none", 0, 0}, {nullptr, 0, 1}};
        constexpr std::uint32_t kFeedbackNames[] = {TRANSFORM_FEEDBACK_BUFFER_BINDING, TRANSFORM_FEEDBACK_BUFFER_START,
                                                    TRANSFORM_FEEDBACK_BUFFER_SIZE, BLEND};
        const auto target = [&] { return in.Byte() % 8 ? TRANSFORM_FEEDBACK_BUFFER : ARRAY_BUFFER; };
        switch (in.Byte() % 10) {
          case 0: {
            FeedbackVarying pick[6];
            const int n = std::min(in.Int(-1, 6), 6);  // (negative ones too: the error)
            for (int i = 0; i < n; ++i) pick[i] = kVaryings[in.Byte() % 7];
            const std::uint32_t mode = in.Byte() % 2 ? INTERLEAVED_ATTRIBS : in.Byte() % 4 ? SEPARATE_ATTRIBS : TRIANGLES;
            gl.TransformFeedbackVaryings(shader, n, in.Byte() % 8 ? pick : nullptr, mode);
            break;
          }
          case 1: gl.BindBufferRange(target(), std::uint32_t(in.Byte() % 6), id(), in.Int(-4, 64), in.Int(-4, 256)); break;
          case 2: gl.BindBufferBase(target(), std::uint32_t(in.Byte() % 6), id()); break;
          case 3: gl.BeginTransformFeedback(in.Enum(kModes)); break;
          case 4: gl.EndTransformFeedback(); break;
          case 5: in.Byte() % 2 ? gl.PauseTransformFeedback() : gl.ResumeTransformFeedback(); break;
          case 6: in.Byte() % 2 ? void(gl.GenTransformFeedback()) : gl.BindTransformFeedback(in.Byte() % 8 ? TRANSFORM_FEEDBACK : TRIANGLES, id()); break;
          case 7: {
            const std::uint32_t ids[2] = {id(), id()};
            gl.DeleteTransformFeedbacks(std::min(in.Int(-1, 2), 2), in.Byte() % 8 ? ids : nullptr);
            break;
          }
          case 8: {  // (each draws at most the vertices recorded, which draws counted already: a share of the budget)
            if (drawn >= kDrawBudget) break;
            drawn += kDrawBudget / 4;
            gl.DrawTransformFeedback(in.Enum(kModes), id());
            break;
          }
          default: {
            char name[8];
            int length = 0, size = 0;
            Enum type = 0;
            gl.GetTransformFeedbackVarying(shader, std::uint32_t(in.Byte() % 8), in.Int(-1, 8), in.Byte() % 2 ? &length : nullptr,
                                           &size, &type, in.Byte() % 4 ? name : nullptr);
            std::int64_t values[4];
            gl.GetInteger64i_v(in.Enum(kFeedbackNames), std::uint32_t(in.Byte() % 6), values);
            (void)gl.IsTransformFeedback(id());
            break;
          }
        }
        break;
      }
      default: {
        std::uint8_t px[4];
        gl.ReadPixel(in.Int(-2, 50), in.Int(-2, 50), px);
        (void)gl.ReadPixels();
        (void)gl.ReadDepth(in.Int(-2, 50), in.Int(-2, 50));
        {  // a rectangle of any format and pack layout, into a buffer exactly as large as OpenGL says it needs
          // (Int may return any int: sizes are clamped so that the buffer stays small; x and y may be anything.)
          const auto small = [&](int lo, int hi) { return std::clamp(in.Int(lo, hi), lo, hi); };
          const int align = 1 << small(0, 3), row = small(0, 60), skip_rows = small(0, 3), skip_px = small(0, 3);
          gl.PixelStore(PACK_ALIGNMENT, align);
          gl.PixelStore(PACK_ROW_LENGTH, row);
          gl.PixelStore(PACK_SKIP_ROWS, skip_rows);
          gl.PixelStore(PACK_SKIP_PIXELS, skip_px);
          const int x = in.Int(-60, 60), y = in.Int(-60, 60), w = small(-1, 60), h = small(-1, 60);
          const std::uint32_t format = in.Enum(kFormats), type = in.Enum(kPixelTypes);
          const std::size_t element = ElementBytes(type), pixel = PixelBytes(format, type);
          std::size_t stride = std::size_t(row > 0 ? row : std::max(w, 0)) * pixel;
          if (element < std::size_t(align)) stride = (stride + std::size_t(align) - 1) / std::size_t(align) * std::size_t(align);
          // The last pixel written ends at (skip_rows + h - 1) * stride + (skip_pixels + w) * pixel bytes.
          const std::size_t need = w > 0 && h > 0 ? std::size_t(skip_rows + h - 1) * stride + std::size_t(skip_px + w) * pixel : 0;
          scratch.assign(need, 0);
          gl.ReadPixels(x, y, w, h, format, type, scratch.data());
        }
        (void)gl.CheckFramebufferStatus(in.Enum(kFbTargets));
        {  // any name in the ranges OpenGL's state names use (every name fits in 4 values)
          const std::uint32_t pname = in.Byte() % 2 ? std::uint32_t(in.Int(0x0B00, 0x0D60)) : std::uint32_t(in.Int(0x8000, 0x9130));
          int iv[4];
          float fv[4];
          bool bv[4];
          std::int64_t lv[4];
          gl.GetIntegerv(pname, iv);
          gl.GetFloatv(pname, fv);
          gl.GetBooleanv(pname, bv);
          gl.GetInteger64v(pname, lv);
          (void)gl.GetString(pname);
        }
        break;
      }
    }
    (void)gl.GetError();
  }
  return 0;
}

// backend.h — one rendering API for the conformance scenes, implemented twice: by softgl (C++ shaders) and by
// OpenGL 3.3 core through Mesa's OSMesa (GLSL shaders). Every call maps one to one onto the API of the same name;
// the enums are OpenGL's numbers in both.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/enums.h>

namespace conformance {

using softgl::Enum;

/// The vertex layout of every draw: attribute 0 clip-space position, 1 colour, 2 extra (normal or uv).
struct Vertex {
  glm::vec4 pos;
  glm::vec4 color{1.0f};
  glm::vec4 extra{0.0f};
};

/// Whether an integer internal format is signed (R8I ... RGBA32I) rather than unsigned.
inline bool IsSignedInteger(Enum format) {
  switch (format) {
    case softgl::R8I: case softgl::R16I: case softgl::R32I: case softgl::RG8I: case softgl::RG16I: case softgl::RG32I:
    case softgl::RGB8I: case softgl::RGB16I: case softgl::RGB32I: case softgl::RGBA8I: case softgl::RGBA16I:
    case softgl::RGBA32I: return true;
    default: return false;
  }
}

/// The shader pair a draw uses; each is written once in C++ (backend_softgl.cpp) and once in GLSL
/// (backend_gl.cpp).
enum class Program {
  kColor,  // colour = interpolated attribute 1
  kUv,     // colour = (extra.x, extra.y, 0.5, 1), extra interpolated: shows perspective-correct interpolation
  kLit,    // per-fragment Blinn-Phong: normal = extra.xyz (world), colour = tint * (ambient + diffuse) + specular
  kTexture,  // colour = texture(unit 0, extra.xy): implicit derivatives, so the LOD comes from the quad
  kCube,     // colour = texture(cube map on unit 1, extra.xyz)
  kShadow,   // colour = texture(depth texture on unit 2 with comparison, vec3(extra.xy, extra.z)) in red
  kArray,    // colour = texture(2D array on unit 3, extra.xyz): layer extra.z
  kVolume,   // colour = texture(3D texture on unit 4, extra.xyz)
  kArrayShadow,  // colour = texture(depth array on unit 5 with comparison, extra): layer extra.z, reference extra.w
  kFetchSample,  // colour = texelFetch(2D multisample texture on unit 6, ivec2(gl_FragCoord.xy) - ivec2(extra.xy),
                 // int(extra.z))
  kOutputs,      // four colour outputs: 0 colour; 1 (extra.x, extra.y, 0.5, colour.a); 2 colour * 2 - 0.5 (past
                 // [0, 1] both ways); 3 (extra.z, extra.w, colour.g, colour.a)
  kPointCoord,   // colour = (gl_PointCoord, colour.b, 1)
  kFeedback,     // colour = attribute 1; the vertex stage also writes v_extra = attribute 2 * 2 - position, for
                 // transform feedback (Backend::FeedbackVaryings)
  kLayer,        // colour = attribute 1; the vertex stage writes gl_Layer = int(extra.w) (ARB_shader_viewport_layer_array)
  // With a geometry stage (colour = what it emits):
  kGeometryShrink,  // triangles, two invocations: 0 the triangle shrunk by half toward vertex 0 in its colours;
                    // 1 the same quartered, in (id % 4 * 0.2, 1 - that, blue, 1) for gl_PrimitiveIDIn id, and for
                    // even ids a second strip: a small yellow triangle at vertex 2
  kGeometrySprites,  // points: a square of half side extra.x (clip units, times w) in the colour; where extra.y >
                     // 0.5, a second one to its right, half as large, in the colour's inverse
  kGeometryAdjacency,      // triangles with adjacency: the triangle, vertex k coloured as adjacent vertex 2k + 1
  kGeometryLineAdjacency,  // lines with adjacency: the line, its ends coloured as adjacent vertices 0 and 3
  kGeometryLayer,  // triangles, three invocations: into layer int(extra.w) + gl_InvocationID, the colour times
                   // 1 - invocation / 4
  kTexture1D,       // colour = texture(1D texture on unit 7, extra.x)
  kTexture1DArray,  // colour = texture(1D array on unit 7, extra.xy): layer extra.y
  kTextureBuffer,   // colour = texelFetch(buffer texture on unit 0, int(extra.x) + y / 4 % 16 * 16 + x / 4 % 16) at
                    // window pixel (x, y); where extra.y > 0.5, (textureSize / 1024, 0, 0, 1) instead
  kFetchSampleArray,  // colour = texelFetch(2D multisample array on unit 6, ivec3(ivec2(gl_FragCoord.xy) -
                      // ivec2(extra.xy), int(extra.w)), int(extra.z))
};

/// A TEXTURE_2D_ARRAY or TEXTURE_3D defined by TexImage3D: RGBA8 from `rgba` (unit 3 for an array, 4 for 3D), or
/// an array of DEPTH_COMPONENT32F from `depth` compared by `compare_func` (unit 5); or a TEXTURE_1D (TexImage1D,
/// `width` texels) or TEXTURE_1D_ARRAY (TexImage2D, `depth_or_layers` rows) of RGBA8 on unit 7.
struct LayeredDesc {
  Enum target = softgl::TEXTURE_2D_ARRAY;
  int width = 0, height = 0, depth_or_layers = 0;
  std::vector<std::uint8_t> rgba;  // RGBA8 texels, plane after plane, rows bottom first
  std::vector<float> depth;        // or depth values (then a depth array)
  bool generate_mipmap = false;
  Enum min_filter = softgl::LINEAR, mag_filter = softgl::LINEAR;
  Enum wrap_s = softgl::REPEAT, wrap_t = softgl::REPEAT, wrap_r = softgl::REPEAT;
  Enum compare_func = softgl::LEQUAL;
};

/// A 2D RGBA8 (or `internal_format`) texture for unit 0: the levels given (level 0 first), or level 0 and
/// GenerateMipmap.
struct TextureDesc {
  Enum internal_format = softgl::RGBA8;  // RGBA8 or SRGB8_ALPHA8, or any with `type` UNSIGNED_SHORT or HALF_FLOAT
  Enum type = softgl::UNSIGNED_BYTE;     // UNSIGNED_BYTE: `rgba`; UNSIGNED_SHORT or HALF_FLOAT: `shorts`
  struct Level {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;     // rows bottom first
    std::vector<std::uint16_t> shorts;  // the same, 16 bits a channel
    std::vector<std::uint8_t> blocks;   // with `compressed`: the level's blocks
  };
  Enum compressed = 0;  // a compressed format: each level defined by CompressedTexImage2D from its blocks
  std::vector<Level> levels;
  bool generate_mipmap = false;
  Enum min_filter = softgl::LINEAR_MIPMAP_LINEAR, mag_filter = softgl::LINEAR;
  Enum wrap_s = softgl::REPEAT, wrap_t = softgl::REPEAT;
  glm::vec4 border{0.0f};
  float max_anisotropy = 1.0f;  // TEXTURE_MAX_ANISOTROPY
};

struct Uniforms {
  glm::vec4 tint{1.0f};
  glm::vec3 light_dir{0.0f, 0.0f, 1.0f};
  glm::vec3 half_vector{0.0f, 0.0f, 1.0f};
};

/// What a scene leaves in the framebuffer, rows bottom first (OpenGL's order).
struct Frame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;
  std::vector<std::uint8_t> stencil;
};

/// One call of Backend::DrawVariants or Backend::DrawInstanced: an OpenGL 3.3 draw variant and its arguments.
struct DrawVariant {
  enum class Call {
    kElementsBaseVertex, kRangeElements, kMultiElements, kMultiArrays,  // DrawVariants
    kArraysInstanced, kElementsInstanced, kElementsInstancedBaseVertex  // DrawInstanced
  };
  Call call;
  Enum mode;
  std::vector<int> first;  // k*Arrays*: each draw's first vertex; the others: each draw's first index
  std::vector<int> count;  // each draw's count (one draw except for kMultiElements and kMultiArrays)
  int basevertex = 0;               // kElementsBaseVertex, kElementsInstancedBaseVertex
  std::uint32_t start = 0, end = 0;  // kRangeElements
  int instances = 1;                 // the instanced calls: instancecount
  std::uint32_t divisor = 1;         // the instanced calls: attribute 3's divisor
  int instance_first = 0;            // the instanced calls: attribute 3 starts at this element of `instance_data`
};

/// One ReadPixels call with its pack state (PixelStore's PACK_* values).
struct PixelRead {
  int x = 0, y = 0, width = 0, height = 0;
  Enum format = softgl::RGBA, type = softgl::UNSIGNED_BYTE;
  int alignment = 4, row_length = 0, skip_rows = 0, skip_pixels = 0;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string Name() const = 0;
  virtual void Enable(Enum cap) = 0;
  virtual void Disable(Enum cap) = 0;
  virtual void Viewport(int x, int y, int w, int h) = 0;
  virtual void DepthRange(double n, double f) = 0;
  virtual void CullFace(Enum mode) = 0;
  virtual void FrontFace(Enum mode) = 0;
  virtual void PolygonMode(Enum mode) = 0;
  virtual void PointSize(float size) = 0;
  virtual void LineWidth(float width) = 0;
  /// glColorMaski, glEnablei and glDisablei.
  virtual void ColorMaski(std::uint32_t index, bool r, bool g, bool b, bool a) = 0;
  virtual void Enablei(Enum cap, std::uint32_t index) = 0;
  virtual void Disablei(Enum cap, std::uint32_t index) = 0;
  /// glGetBooleani_v and glGetIntegeri_v of `count` values, glIsEnabledi.
  virtual std::vector<bool> GetBooleansI(Enum target, std::uint32_t index, int count) = 0;
  virtual std::vector<std::int64_t> GetIntegersI(Enum target, std::uint32_t index, int count) = 0;
  virtual bool IsEnabledi(Enum cap, std::uint32_t index) = 0;
  /// glPointParameteri.
  virtual void PointParameteri(Enum pname, int value) = 0;
  virtual void DepthFunc(Enum func) = 0;
  virtual void DepthMask(bool flag) = 0;
  virtual void PolygonOffset(float factor, float units) = 0;
  virtual void Scissor(int x, int y, int w, int h) = 0;
  virtual void PrimitiveRestartIndex(std::uint32_t index) = 0;
  virtual void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) = 0;
  virtual void StencilOpSeparate(Enum face, Enum sfail, Enum dpfail, Enum dppass) = 0;
  virtual void StencilMaskSeparate(Enum face, std::uint32_t mask) = 0;
  virtual void BlendFuncSeparate(Enum src_rgb, Enum dst_rgb, Enum src_a, Enum dst_a) = 0;
  virtual void BlendEquationSeparate(Enum rgb, Enum alpha) = 0;
  virtual void BlendColor(float r, float g, float b, float a) = 0;
  virtual void LogicOp(Enum op) = 0;
  virtual void ColorMask(bool r, bool g, bool b, bool a) = 0;
  virtual void ClearColor(float r, float g, float b, float a) = 0;
  virtual void ClearDepth(double d) = 0;
  virtual void ClearStencil(int s) = 0;
  virtual void Clear(std::uint32_t mask) = 0;
  /// glClearBufferfv, glClearBufferiv and glClearBufferfi.
  virtual void ClearBufferfv(Enum buffer, int drawbuffer, const float* value) = 0;
  virtual void ClearBufferiv(Enum buffer, int drawbuffer, const int* value) = 0;
  virtual void ClearBufferfi(Enum buffer, int drawbuffer, float depth, int stencil) = 0;
  /// Draws `vertices` (through `indices` when not empty) with `mode` and `program`.
  virtual void Draw(Enum mode, const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                    Program program, const Uniforms& uniforms) = 0;
  /// Uploads `vertices` and `indices` (UNSIGNED_INT) once, then makes each call of `calls` in order with the
  /// kColor program: DrawElementsBaseVertex, DrawRangeElements, MultiDrawElements or MultiDrawArrays.
  virtual void DrawVariants(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                            const std::vector<DrawVariant>& calls) = 0;
  /// Uploads `vertices`, `indices` (UNSIGNED_INT) and `instance_data` once, then makes each instanced call of
  /// `calls` in order with the instanced program: position = attribute 0 + (attribute 3).xy, colour = attribute 1
  /// times 1 - gl_InstanceID % 8 / 8 in rgb; attribute 3 reads `instance_data` from element c.instance_first, with
  /// divisor c.divisor.
  virtual void DrawInstanced(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                             const std::vector<glm::vec4>& instance_data, const std::vector<DrawVariant>& calls) = 0;
  /// Draws `vertices` (their positions) as points (of PointSize's size) with the integer program: attribute 3 an `ivec4` read by VertexAttribIPointer(3, size, type, stride,
  /// 0) from `bytes` (in a buffer of its own), colour = vec4(a & 255) / 255; with `bytes` empty, attribute 3
  /// disabled and its current value VertexAttribI4i(3, current) instead. Attribute 3 is left disabled, as a float
  /// array. Returns VERTEX_ATTRIB_ARRAY_INTEGER of attribute 3 just before the draw.
  virtual int DrawIntegerAttribs(const std::vector<Vertex>& vertices, int size, Enum type, int stride,
                                 const std::vector<std::uint8_t>& bytes, glm::ivec4 current) = 0;
  /// One draw of DrawIntegerTarget: triangles whose attribute 2 (extra) holds the integers each writes, through
  /// COLOR_LOGIC_OP's `logic` (0: disabled) and the colour mask `mask` (bit c: channel c).
  struct IntegerDraw {
    std::vector<Vertex> triangles;
    Enum logic = 0;
    unsigned mask = 0xF;
  };
  /// Integer colour buffers and textures: a TEXTURE_2D of the integer `format`, w x h, attached to a framebuffer
  /// object of its own, cleared by ClearBufferuiv (an unsigned format) or ClearBufferiv (a signed one) to `clear`;
  /// each of `draws` drawn into it by a fragment stage writing uvec4(extra) or ivec4(extra) (the provoking
  /// vertex's: flat); then `quad` drawn into the default framebuffer (viewport w_ x h_ again) with colour
  /// vec4((t.r, t.g, t.b + 64 t.a) & 255) / 255, 1) of t = texture(usampler2D or isampler2D on unit 0, extra.xy),
  /// NEAREST, wrap mode `wrap` in s and t, border `border` given by TexParameterIiv. The texture and framebuffer
  /// are deleted after.
  virtual void DrawIntegerTarget(Enum format, int w, int h, const glm::ivec4& clear,
                                 const std::vector<IntegerDraw>& draws, Enum wrap, const glm::ivec4& border,
                                 const std::vector<Vertex>& quad) = 0;
  /// Fills a new vertex buffer through the buffer calls: the first `mapped` vertices written through
  /// MapBufferRange (with an explicit flush), the rest copied from a COPY_READ_BUFFER by CopyBufferSubData; draws
  /// BUFFER_SIZE / sizeof(Vertex) of them as `mode` with the kColor program, and returns the store as
  /// GetBufferSubData reads it back.
  virtual std::vector<Vertex> DrawThroughBufferCalls(Enum mode, const std::vector<Vertex>& vertices, int mapped) = 0;
  /// Defines the texture of unit 0 (replacing any before; NEAREST, CLAMP_TO_EDGE) by CopyTexImage2D(RGBA8) of the
  /// framebuffer's rectangle (x, y, w, h), then CopyTexSubImage2D of the framebuffer's (sx, sy, sw, sh) into it at
  /// (dx, dy).
  virtual void CopyToTexture(int x, int y, int w, int h, int dx, int dy, int sx, int sy, int sw, int sh) = 0;
  /// Framebuffer objects and renderbuffers, one to one with OpenGL's calls of the same names (the renderbuffer
  /// target is RENDERBUFFER).
  virtual std::uint32_t GenFramebuffer() = 0;
  virtual void BindFramebuffer(Enum target, std::uint32_t framebuffer) = 0;
  virtual Enum CheckFramebufferStatus(Enum target) = 0;
  virtual std::uint32_t GenRenderbuffer() = 0;
  virtual void BindRenderbuffer(std::uint32_t renderbuffer) = 0;
  virtual void RenderbufferStorage(Enum internal_format, int width, int height) = 0;
  virtual void RenderbufferStorageMultisample(int samples, Enum internal_format, int width, int height) = 0;
  /// glSampleMaski(0, mask) and glSampleCoverage (enabled by SAMPLE_MASK and SAMPLE_COVERAGE).
  virtual void SampleMask(std::uint32_t mask) = 0;
  virtual void MinSampleShading(float value) = 0;  // with SAMPLE_SHADING enabled
  virtual void SampleCoverage(float value, bool invert) = 0;
  virtual void FramebufferRenderbuffer(Enum target, Enum attachment, std::uint32_t renderbuffer) = 0;
  virtual void ReadBuffer(Enum src) = 0;
  virtual void DrawBuffers(int n, const Enum* bufs) = 0;
  virtual void BlitFramebuffer(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1,
                               std::uint32_t mask, Enum filter) = 0;
  /// A new width x height 2D texture of `internal_format` without data (colour: RGBA / UNSIGNED_BYTE; depth:
  /// DEPTH_COMPONENT / FLOAT; depth-stencil: DEPTH_STENCIL with its packed type), attached to `attachment` of the
  /// framebuffer bound to `target` by FramebufferTexture2D.
  virtual void AttachNewTexture(Enum target, Enum attachment, Enum internal_format, int width, int height) = 0;
  /// A new TEXTURE_2D_MULTISAMPLE texture (TexImage2DMultisample, fixed sample locations) on unit 6, attached to
  /// `attachment` of the framebuffer bound to `target`.
  virtual void AttachNewMultisampleTexture(Enum target, Enum attachment, int samples, Enum internal_format,
                                           int width, int height) = 0;
  /// A new texture of `texture_target` with `layers` layers or slices of size x size (a cube map: its first
  /// `layers` faces) of `internal_format` (RGBA8, or DEPTH_COMPONENT32F for an array), no data, NEAREST, bound to
  /// unit 3 (array), 4 (3D) or 1 (cube map), depth arrays to unit 7; attached to `attachment` of the framebuffer
  /// bound to `target` by FramebufferTexture (`layer` < 0), or FramebufferTexture3D (3D) or FramebufferTextureLayer
  /// at `layer`. Returns its id.
  virtual std::uint32_t AttachLayered(Enum target, Enum attachment, Enum texture_target, Enum internal_format,
                                      int size, int layers, int layer) = 0;
  /// A new TEXTURE_2D_MULTISAMPLE_ARRAY texture on unit 6 (TexImage3DMultisample, fixed sample locations), not
  /// attached; returns its id. TexImage3DMultisample itself on the active unit, and glFramebufferTextureLayer.
  virtual std::uint32_t NewMultisampleArray(int samples, Enum internal_format, int width, int height, int layers) = 0;
  virtual void TexImage3DMultisample(Enum target, int samples, Enum internal_format, int width, int height,
                                     int layers) = 0;
  virtual void FramebufferTextureLayer(Enum target, Enum attachment, std::uint32_t texture, int level, int layer) = 0;
  /// glFramebufferTexture, glFramebufferTexture3D and glGetFramebufferAttachmentParameteriv (one value).
  virtual void FramebufferTexture(Enum target, Enum attachment, std::uint32_t texture, int level) = 0;
  virtual void FramebufferTexture3D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level,
                                    int zoffset) = 0;
  virtual std::int64_t GetAttachmentParameter(Enum target, Enum attachment, Enum pname) = 0;
  /// glGetIntegerv, glGetFloatv and glGetBooleanv of `count` values.
  virtual std::vector<std::int64_t> GetIntegers(Enum pname, int count) = 0;
  virtual std::vector<float> GetFloats(Enum pname, int count) = 0;
  virtual std::vector<bool> GetBooleans(Enum pname, int count) = 0;
  /// The first error since the last call (glGetError).
  virtual Enum GetError() = 0;
  /// Sampler objects: a new id, glBindSampler, glSamplerParameteri and glSamplerParameterfv.
  virtual std::uint32_t GenSampler() = 0;
  virtual void BindSampler(int unit, std::uint32_t sampler) = 0;
  virtual void SamplerParameteri(std::uint32_t sampler, Enum pname, int value) = 0;
  virtual void SamplerParameterfv(std::uint32_t sampler, Enum pname, const float* values) = 0;
  /// glGetSamplerParameteriv / fv of `count` values, and glGetVertexAttribiv / fv of the vertex array the draws use.
  virtual std::vector<std::int64_t> GetSamplerIntegers(std::uint32_t sampler, Enum pname, int count) = 0;
  virtual std::vector<float> GetSamplerFloats(std::uint32_t sampler, Enum pname, int count) = 0;
  virtual std::vector<std::int64_t> GetVertexAttribIntegers(std::uint32_t index, Enum pname, int count) = 0;
  virtual std::vector<float> GetVertexAttribFloats(std::uint32_t index, Enum pname, int count) = 0;
  /// Query objects: a new id, glBeginQuery / glEndQuery, and QUERY_RESULT (64-bit).
  virtual std::uint32_t GenQuery() = 0;
  virtual void BeginQuery(Enum target, std::uint32_t id) = 0;
  virtual void EndQuery(Enum target) = 0;
  virtual std::uint64_t QueryResult(std::uint32_t id) = 0;
  /// glVertexAttribP1ui ... glVertexAttribP4ui (`components` 1 to 4; another count: the P4uiv form).
  virtual void VertexAttribP(int components, std::uint32_t index, Enum type, bool normalized, std::uint32_t value) = 0;
  /// glTexParameterIiv / Iuiv and glGetTexParameterIiv / Iuiv (`count` values) on unit 0's TEXTURE_2D.
  virtual void TexParameterI(Enum pname, const int* values, bool is_unsigned) = 0;
  virtual std::vector<std::int64_t> GetTexParameterI(Enum pname, int count, bool is_unsigned) = 0;
  /// glBeginConditionalRender / glEndConditionalRender.
  virtual void BeginConditionalRender(std::uint32_t id, Enum mode) = 0;
  virtual void EndConditionalRender() = 0;
  /// Sync objects, a fence as an opaque handle: glFenceSync, glIsSync, glDeleteSync, glClientWaitSync, glWaitSync,
  /// and glGetSynciv of one value (bufSize 1; the value is -1 where the call writes none).
  virtual const void* FenceSync(Enum condition, std::uint32_t flags) = 0;
  virtual bool IsSync(const void* sync) = 0;
  virtual void DeleteSync(const void* sync) = 0;
  virtual Enum ClientWaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) = 0;
  virtual void WaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) = 0;
  virtual int GetSynci(const void* sync, Enum pname) = 0;
  /// glClampColor.
  virtual void ClampColor(Enum target, Enum clamp) = 0;
  /// Transform feedback. FeedbackVaryings: what the kFeedback program records, `which` naming its outputs (0
  /// gl_Position, 1 v_color, 2 v_extra: vec4 each), with glTransformFeedbackVaryings (and a new link in OpenGL).
  /// NewFeedbackBuffer: a buffer of `floats` floats of -7, made through the TRANSFORM_FEEDBACK_BUFFER target.
  /// ReadBufferFloats: its first `floats` floats by GetBufferSubData. The others one to one with OpenGL's calls
  /// (BindBufferBase / BindBufferRange on TRANSFORM_FEEDBACK_BUFFER, BindTransformFeedback on TRANSFORM_FEEDBACK).
  virtual void FeedbackVaryings(const std::vector<int>& which, Enum buffer_mode) = 0;
  virtual std::uint32_t NewFeedbackBuffer(int floats) = 0;
  virtual std::vector<float> ReadBufferFloats(std::uint32_t buffer, int floats) = 0;
  virtual void BindBufferBase(std::uint32_t index, std::uint32_t buffer) = 0;
  virtual void BindBufferRange(std::uint32_t index, std::uint32_t buffer, std::ptrdiff_t offset, std::ptrdiff_t size) = 0;
  virtual void BeginTransformFeedback(Enum mode) = 0;
  virtual void EndTransformFeedback() = 0;
  virtual void PauseTransformFeedback() = 0;
  virtual void ResumeTransformFeedback() = 0;
  virtual std::uint32_t GenTransformFeedback() = 0;
  virtual void BindTransformFeedback(std::uint32_t id) = 0;
  virtual void DrawTransformFeedback(Enum mode, std::uint32_t id) = 0;
  virtual void ProvokingVertex(Enum convention) = 0;
  virtual Frame Read() = 0;
  /// ReadPixels into a buffer of `bytes` bytes first filled with 0xCD (bytes the call does not write keep it).
  virtual std::vector<std::uint8_t> ReadPixels(const PixelRead& read, std::size_t bytes) = 0;
  /// Defines the texture of unit 0 (replacing any before).
  virtual void SetTexture(const TextureDesc& desc) = 0;
  /// Compressed textures and the calls around them, one to one with OpenGL's (dims 1, 2 or 3 picks the 1D, 2D or
  /// 3D form), on the active unit: BindNewTexture binds a new texture to `target`; TexImage2D and TexSubImage2D take
  /// RGBA / UNSIGNED_BYTE data (null for TexImage2D); GetTexImageFloats is GetTexImage of RGBA / FLOAT into `floats`
  /// floats, GetCompressedTexImage into `bytes` bytes (both first filled with a marker, -9 or 0xCD);
  /// GetTexLevelParameter is GetTexLevelParameteriv of one value (-1 where the call writes none).
  virtual void BindNewTexture(Enum target) = 0;
  virtual void CompressedTexImage(int dims, Enum target, int level, Enum format, int w, int h, int d, int image_size,
                                  const void* data) = 0;
  virtual void CompressedTexSubImage(int dims, Enum target, int level, int x, int y, int z, int w, int h, int d,
                                     Enum format, int image_size, const void* data) = 0;
  virtual std::vector<std::uint8_t> GetCompressedTexImage(Enum target, int level, int bytes) = 0;
  virtual std::vector<float> GetTexImageFloats(Enum target, int level, int floats) = 0;
  virtual int GetTexLevelParameter(Enum target, int level, Enum pname) = 0;
  virtual void TexImage2D(Enum target, int level, Enum internal_format, int w, int h) = 0;
  virtual void TexSubImage2D(Enum target, int level, int x, int y, int w, int h, const std::uint8_t* rgba) = 0;
  virtual void GenerateMipmap(Enum target) = 0;
  /// Buffer textures, on the active unit: NewBufferTexture binds a new texture to TEXTURE_BUFFER and a new buffer to
  /// the TEXTURE_BUFFER buffer target, fills the buffer with `bytes` (BufferData) and makes it the texture's
  /// (TexBuffer with `internal_format`); it returns the buffer. BufferSubDataTexture writes `bytes` at `offset` of
  /// `buffer` through the TEXTURE_BUFFER target (BufferSubData). TexBuffer and DeleteBuffer as OpenGL's.
  virtual std::uint32_t NewBufferTexture(Enum internal_format, const std::vector<std::uint8_t>& bytes) = 0;
  virtual void BufferSubDataTexture(std::uint32_t buffer, int offset, const std::vector<std::uint8_t>& bytes) = 0;
  virtual void TexBuffer(Enum target, Enum internal_format, std::uint32_t buffer) = 0;
  virtual void DeleteBuffer(std::uint32_t buffer) = 0;
  /// Defines the cube map of unit 1 from six faces (+x, -x, +y, -y, +z, -z) of size x size RGBA8, mipmapped with
  /// GenerateMipmap, LINEAR_MIPMAP_LINEAR, CLAMP_TO_EDGE.
  virtual void SetCubeTexture(int size, const std::vector<std::uint8_t> faces[6]) = 0;
  /// Defines the depth texture of unit 2 (size x size floats), TEXTURE_COMPARE_MODE = COMPARE_REF_TO_TEXTURE with
  /// `func`, filters `filter` (NEAREST or LINEAR), CLAMP_TO_EDGE.
  virtual void SetShadowTexture(int size, const std::vector<float>& depth, Enum func, Enum filter) = 0;
  /// Defines the array or 3D texture `desc` describes on its unit (replacing any before).
  virtual void SetLayeredTexture(const LayeredDesc& desc) = 0;
  /// Directs drawing into a new width x height RGBA8 texture with a depth texture (viewport set to it).
  virtual void BeginRenderToTexture(int width, int height) = 0;
  /// Back to the default framebuffer (viewport restored); the texture drawn becomes unit 0's, LINEAR filtered.
  virtual void EndRenderToTexture() = 0;

  // Conveniences over the calls above.
  void StencilFunc(Enum func, int ref, std::uint32_t mask) { StencilFuncSeparate(softgl::FRONT_AND_BACK, func, ref, mask); }
  void StencilOp(Enum a, Enum b, Enum c) { StencilOpSeparate(softgl::FRONT_AND_BACK, a, b, c); }
  void BlendFunc(Enum s, Enum d) { BlendFuncSeparate(s, d, s, d); }
  void Draw(Enum mode, const std::vector<Vertex>& vertices, Program program = Program::kColor,
            const Uniforms& uniforms = {}) {
    Draw(mode, vertices, {}, program, uniforms);
  }
};

/// softgl, rendering into a width x height Context.
std::unique_ptr<Backend> MakeSoftglBackend(int width, int height);

/// Mesa through OSMesa (driver chosen by GALLIUM_DRIVER), OpenGL 3.3 core, RGBA8 + depth 24 + stencil 8.
/// Returns null, with a reason in `error`, when no such context can be made.
std::unique_ptr<Backend> MakeGlBackend(int width, int height, std::string* error);

}  // namespace conformance

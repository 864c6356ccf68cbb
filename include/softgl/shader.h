// softgl/shader.h — the programmable stages: write a shader by subclassing softgl::Shader.
//
// A shader is a C++ class. Its uniforms are ordinary members; its varyings are a plain struct that the vertex stage
// writes and the fragment stage reads, interpolated perspective-correctly (or as the qualifiers Flat<> and
// NoPerspective<> say). Each stage is written once, in code that reads like GLSL, and softgl runs it on 16 lanes at
// a time: 16 vertices, or four 2x2 quads of fragments, with the types of softgl/lanes.h:
//
//     struct Vary { softgl::vec3 color; };
//     struct ColorShader : softgl::Shader<ColorShader, Vary> {
//       glm::mat4 mvp{1.0f};                                       // a uniform
//       void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<Vary>& out) const {
//         out.position = mvp * in.attrib[0];                       // gl_Position, clip space
//         out.varyings.color = softgl::vec3(in.attrib[1]);
//       }
//       void Fragment(const softgl::FragmentLanes<Vary>& in, softgl::FragmentLanesOut& out) const {
//         out.color[0] = softgl::vec4(in.varyings.color, 1.0f);
//         out.Discard(in.varyings.color.x > 0.9f);                 // per lane, as GLSL's discard
//       }
//     };
//
// softgl compiles the two stages for SSE2, AVX2 and AVX-512 and runs the version the processor allows (4, 8 or 16
// lanes per instruction); each lane computes what the same code would compute for one vertex or fragment. Branches
// that differ between lanes are written with select(), which computes both sides; `if (any(c))` skips work that no
// lane needs.
//
// The scalar form of softgl 0.1, one vertex or fragment per call, still works: a shader whose Vertex takes a
// VertexIn and whose Fragment takes a FragmentIn (and whose varyings are floats and GLM vectors) is run lane by
// lane, with the same results and the speed of scalar code.
//
// Vertex() and Fragment() run on the context's worker threads, several at once on the same shader object: they
// must only read the shader's members. How often Vertex() runs for a vertex is not fixed, as in OpenGL: a draw
// shades each vertex it uses at least once, and an indexed draw whose indices lie close together shades every
// vertex from its lowest index to its highest. The vertex stage runs during the draw call; the fragment stage runs
// later, when the context renders (ReadPixels, Finish, ...), on a copy of the shader taken at the draw (Snapshot),
// so changing uniforms between draws works as in OpenGL.
#pragma once

#include <softgl/config.h>

#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <typeinfo>
#include <type_traits>

#include <glm/glm.hpp>
#include <softgl/enums.h>
#include <softgl/lanes.h>
#include <softgl/texture.h>

namespace softgl {

/// Number of vertex attribute locations (GL_MAX_VERTEX_ATTRIBS).
inline constexpr int kMaxVertexAttribs = 16;
/// Largest varyings struct, in floats per vertex: 16 vec4 (GL_MAX_VARYING_COMPONENTS = 64).
inline constexpr int kMaxVaryingFloats = 64;
/// Number of colour outputs a fragment shader may write (color[0] goes to the default framebuffer): the draw
/// buffers and colour attachments of a framebuffer object (GL_MAX_DRAW_BUFFERS, GL_MAX_COLOR_ATTACHMENTS).
inline constexpr int kMaxColorOutputs = 8;

// ---- Interpolation qualifiers ---------------------------------------------------------------------------------

/// How a varying's floats are interpolated across a primitive (GLSL's qualifiers).
enum class Interpolation : std::uint8_t {
  kSmooth = 0,         ///< perspective-correct (the default)
  kNoPerspective = 1,  ///< linear in window space
  kFlat = 2,           ///< the provoking vertex's value for the whole primitive (see Context::ProvokingVertex)
  kCentroid = 3,       ///< perspective-correct, at the first covered sample of a partly covered pixel (multisampling)
};

namespace shader_detail {
// A default-constructed Flat<> or NoPerspective<> member fills its floats with one of these NaN payloads, which is
// how softgl reads the qualifiers of a varyings struct (once per shader class): no user value can carry them.
inline constexpr std::uint32_t kFlatBits = 0x7FA5F1A7u;
inline constexpr std::uint32_t kNoPerspectiveBits = 0x7FA5A0E5u;
inline constexpr std::uint32_t kCentroidBits = 0x7FA5CE27u;
template <class T>
void Mark(T* object, std::uint32_t bits) {
  static_assert(sizeof(T) % sizeof(float) == 0, "interpolation qualifiers take float types");
  unsigned char* p = reinterpret_cast<unsigned char*>(object);
  for (std::size_t i = 0; i < sizeof(T); i += sizeof(float)) std::memcpy(p + i, &bits, sizeof bits);
}
}  // namespace shader_detail

namespace shader_detail {
// A member of a varyings struct with an interpolation qualifier: a T whose default construction marks its floats
// with `Bits`, and which otherwise is a T.
template <class T, std::uint32_t Bits>
struct Qualified : T {
  Qualified() { Mark(static_cast<T*>(this), Bits); }
  Qualified(const T& v) : T(v) {}
  using T::T;
  Qualified& operator=(const T& v) {
    T::operator=(v);
    return *this;
  }
};
}  // namespace shader_detail

/// A varying that is not interpolated: every fragment of a primitive reads the provoking vertex's value (GLSL's
/// `flat`). T is a vector or lane type: Flat<Float>, Flat<vec3> (wide shaders), Flat<glm::vec3> (scalar form).
template <class T>
using Flat = shader_detail::Qualified<T, shader_detail::kFlatBits>;

/// A varying interpolated linearly in window space, without perspective correction (GLSL's `noperspective`).
template <class T>
using NoPerspective = shader_detail::Qualified<T, shader_detail::kNoPerspectiveBits>;

/// A perspective-correct varying taken, in a pixel a triangle covers only partly in a multisampled framebuffer, at
/// the first sample (in sample order) the triangle covers rather than at the pixel centre, which may lie outside
/// it (GLSL's `centroid`): a texture coordinate then never reaches past the triangle's edge. Elsewhere it is a
/// smooth varying. Its derivatives across such a pixel's quad are less exact, as OpenGL allows.
template <class T>
using Centroid = shader_detail::Qualified<T, shader_detail::kCentroidBits>;

// ---- The wide form: 16 lanes per call ------------------------------------------------------------------------------

namespace shader_detail {
// Coordinates (and derivatives) of 16 lanes for the Textures::*Lanes calls, and their RGBA results as a vec4.
inline Textures::Lanes Coords(const Float& s, const Float& t, const Float& r = 0.0f) {
  Textures::Lanes c;
  s.Store(c.s);
  t.Store(c.t);
  r.Store(c.r);
  return c;
}
inline void Derivatives(Textures::Lanes& c, const vec3& dx, const vec3& dy) {
  dx.x.Store(c.ds_dx);
  dx.y.Store(c.dt_dx);
  dx.z.Store(c.dr_dx);
  dy.x.Store(c.ds_dy);
  dy.y.Store(c.dt_dy);
  dy.z.Store(c.dr_dy);
}
inline vec4 Rgba(const float (&out)[4][kLanes]) {
  return vec4(Float::Load(out[0]), Float::Load(out[1]), Float::Load(out[2]), Float::Load(out[3]));
}
// Moving 16 vertices' outputs from lanes to the pipeline's one-vertex-after-another arrays, four vertices at a time
// through 4x4 transposes of 128-bit vectors (never one lane at a time).
using lanes_detail::F4;
inline void Transpose4(F4& a, F4& b, F4& c, F4& d) {
  const F4 t0 = __builtin_shufflevector(a, b, 0, 4, 1, 5), t1 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
  const F4 t2 = __builtin_shufflevector(a, b, 2, 6, 3, 7), t3 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
  a = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
  b = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
  c = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
  d = __builtin_shufflevector(t2, t3, 2, 3, 6, 7);
}
inline void Split(const Float& in, F4 (&q)[4]) {
#if SOFTGL_PART_LANES == 8
  for (int k = 0; k < 2; ++k) {
    const lanes_detail::FP f = in.v.p[k];
    q[2 * k] = __builtin_shufflevector(f, f, 0, 1, 2, 3);
    q[2 * k + 1] = __builtin_shufflevector(f, f, 4, 5, 6, 7);
  }
#else
  for (int k = 0; k < 4; ++k) q[k] = in.v.p[k];
#endif
}
// Rows of lanes out to vertices: rows[k] lanes to dst[l * stride + k] for vertices l < n and rows k < count.
inline void StoreVertices(const Float* rows, int count, float* dst, std::size_t stride, int n) {
  int k = 0;
  for (; k + 4 <= count; k += 4) {
    F4 q[4][4];  // [row][group]
    for (int i = 0; i < 4; ++i) Split(rows[k + i], q[i]);
    for (int g = 0; g < 4; ++g) {
      F4 a = q[0][g], b = q[1][g], c = q[2][g], d = q[3][g];
      Transpose4(a, b, c, d);
      const F4 out[4] = {a, b, c, d};
      for (int v = 0; v < 4 && g * 4 + v < n; ++v) std::memcpy(dst + std::size_t(g * 4 + v) * stride + k, &out[v], 16);
    }
  }
  for (; k < count; ++k)
    for (int l = 0; l < n; ++l) dst[std::size_t(l) * stride + k] = rows[k][l];
}

// The stage inputs, filled by functions that are not inlined: the input is then an object in memory, which the
// compiler reads as such, rather than a value it takes apart lane by lane (GCC's scalar replacement of aggregates
// would build each broadcast one lane at a time).
}  // namespace shader_detail
struct VertexBatch;
struct BlockBatch;
struct VertexLanes;
template <class Varyings>
struct FragmentLanes;
namespace shader_detail {
// The stages' inputs are filled inline, in the loop of each instruction set (out of line, they were copied with
// baseline instructions through the stack: 9% of a texturing scene's time for the fragment stage).
template <class Batch>
void FillVertexLanes(const Batch& batch, int base, int n, VertexLanes& in);
template <class Varyings, bool kPrimitiveId>
void FillFragmentLanes(const BlockBatch& batch, int b, FragmentLanes<Varyings>& in);

// textureLod through one of Textures' *LodLanes calls.
using LodLanesFn = void (Textures::*)(int, const Textures::Lanes&, const float*, float (*)[16]) const;
inline vec4 Lod(const Textures* textures, int unit, const Textures::Lanes& c, const Float& lod, LodLanesFn fn) {
  float l[kLanes], out[4][kLanes];
  lod.Store(l);
  (textures->*fn)(unit, c, l, out);
  return Rgba(out);
}
// texelFetch through Textures::FetchLanes or FetchSampleLanes.
using FetchLanesFn = void (Textures::*)(int, const int*, const int*, const int*, float (*)[16]) const;
inline vec4 Fetch(const Textures* textures, int unit, const Int& x, const Int& y, const Int& which, FetchLanesFn fn) {
  alignas(64) std::int32_t xs[kLanes], ys[kLanes], ws[kLanes];
  x.Store(xs);
  y.Store(ys);
  which.Store(ws);
  float out[4][kLanes];
  (textures->*fn)(unit, xs, ys, ws, out);
  return Rgba(out);
}
// texelFetch(sampler2DMSArray, ivec3(x, y, layer), sample) through Textures::FetchSampleArrayLanes.
inline vec4 FetchSampleArray(const Textures* textures, int unit, const Int& x, const Int& y, const Int& layer,
                             const Int& sample) {
  alignas(64) std::int32_t xs[kLanes], ys[kLanes], ls[kLanes], ss[kLanes];
  x.Store(xs);
  y.Store(ys);
  layer.Store(ls);
  sample.Store(ss);
  float out[4][kLanes];
  textures->FetchSampleArrayLanes(unit, xs, ys, ls, ss, out);
  return Rgba(out);
}
// texelFetch(samplerBuffer, index) through Textures::FetchBufferLanes.
inline vec4 FetchBuffer(const Textures* textures, int unit, const Int& index) {
  alignas(64) std::int32_t is[kLanes];
  index.Store(is);
  float out[4][kLanes];
  textures->FetchBufferLanes(unit, is, out);
  return Rgba(out);
}
// texture() through one of Textures' *Lanes calls, with the derivatives of the coordinates c holds.
using SampleLanesFn = void (Textures::*)(int, const Textures::Lanes&, float, float (*)[16]) const;
inline vec4 Sample(const Textures* textures, int unit, Textures::Lanes& c, const vec3& dx, const vec3& dy, float bias,
                   SampleLanesFn fn) {
  Derivatives(c, dx, dy);
  float out[4][kLanes];
  (textures->*fn)(unit, c, bias, out);
  return Rgba(out);
}
}  // namespace shader_detail

/// The textureLod calls of the stages that have no derivatives (vertex and geometry), on the textures bound for
/// the draw.
struct LodTextures {
  const Textures* textures = nullptr;  ///< the textures bound for this draw

  /// textureLod(sampler2D, uv, lod).
  vec4 TextureLod(int unit, const vec2& uv, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(uv.x, uv.y), lod, &Textures::SampleLodLanes);
  }
  /// textureLod(samplerCube, dir, lod).
  vec4 TextureCubeLod(int unit, const vec3& dir, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(dir.x, dir.y, dir.z), lod,
                              &Textures::SampleCubeLodLanes);
  }
  /// textureLod(sampler2DArray, vec3(uv, layer), lod).
  vec4 TextureArrayLod(int unit, const vec3& uv_layer, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(uv_layer.x, uv_layer.y, uv_layer.z), lod,
                              &Textures::SampleArrayLodLanes);
  }
  /// textureLod(sampler3D, str, lod).
  vec4 Texture3DLod(int unit, const vec3& str, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(str.x, str.y, str.z), lod,
                              &Textures::Sample3DLodLanes);
  }
  /// textureLod(sampler1D, s, lod).
  vec4 Texture1DLod(int unit, const Float& s, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(s, 0.0f), lod, &Textures::Sample1DLodLanes);
  }
  /// textureLod(sampler1DArray, vec2(s, layer), lod).
  vec4 Texture1DArrayLod(int unit, const vec2& s_layer, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(s_layer.x, s_layer.y), lod,
                              &Textures::Sample1DArrayLodLanes);
  }
  /// texelFetch(samplerBuffer, index): texel `index` of unit's buffer texture (Textures::FetchBuffer).
  vec4 TexelFetchBuffer(int unit, const Int& index) const { return shader_detail::FetchBuffer(textures, unit, index); }
  /// textureSize(samplerBuffer): the texels the buffer texture holds.
  int TextureSizeBuffer(int unit) const { return textures->SizeBuffer(unit); }
  /// The integer forms (isampler2D / usampler2D ...), for integer textures (R8UI ... RGBA32I): the texels' integers
  /// (0, 0, 0, 1 while incomplete; an unsigned texture's as the same 32 bits).
  ivec4 ITextureLod(int unit, const vec2& uv, Float lod) const { return ivec4::FromBits(TextureLod(unit, uv, lod)); }
  ivec4 ITexelFetchBuffer(int unit, const Int& index) const { return ivec4::FromBits(TexelFetchBuffer(unit, index)); }
};

/// What a wide vertex stage reads: the attributes of 16 vertices (and, from LodTextures, the textures).
struct VertexLanes : LodTextures {
  /// attrib[i]: attribute location i, converted to float as OpenGL does (normalized or not); missing components
  /// read (0, 0, 0, 1); a disabled attribute reads its current value (VertexAttrib4f), by default (0, 0, 0, 1).
  vec4 attrib[kMaxVertexAttribs];
  Int vertex_id;  ///< gl_VertexID: the index of each vertex (the element value for DrawElement)
  /// Component c (0 to 3: x, y, z, w) of an integer attribute (Context::VertexAttribIPointer, or VertexAttribI*
  /// while its array is disabled): GLSL's `in ivec4`, and `in uvec4` as the same 32 bits. (attrib[i] holds its
  /// integers as the floats' bits.)
  Int AttribI(int i, int c) const {
    const vec4& a = attrib[i];
    return (c == 0 ? a.x : c == 1 ? a.y : c == 2 ? a.z : a.w).Bits();
  }
  Int instance_id;  ///< gl_InstanceID: the instance of an instanced draw (DrawArraysInstanced, ...); 0 otherwise
};

/// What a wide vertex stage writes for its 16 vertices.
template <class Varyings>
struct VertexLanesOut {
  vec4 position = vec4(0.0f, 0.0f, 0.0f, 1.0f);  ///< gl_Position, in clip space
  Float point_size = 1.0f;  ///< gl_PointSize, used when PROGRAM_POINT_SIZE is enabled
  Varyings varyings{};      ///< interpolated across the primitive for the fragment stage
  /// gl_Layer (as OpenGL's ARB_shader_viewport_layer_array lets a vertex shader write it): the layer of a layered
  /// framebuffer the primitive is drawn into, its provoking vertex's. Read only when Derived declares
  /// `static constexpr bool kWritesLayer = true;`.
  Int layer = 0;
};

// ---- The geometry stage ---------------------------------------------------------------------------------------

/// Most vertices a geometry stage may emit per invocation (GL_MAX_GEOMETRY_OUTPUT_VERTICES).
inline constexpr int kMaxGeometryOutputVertices = 256;
/// Most floats a geometry stage may emit per invocation, max_vertices x (4 for the position + its varyings'
/// floats) (GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS).
inline constexpr int kMaxGeometryTotalOutputFloats = 1024;
/// Most invocations of a geometry stage per primitive (GL_MAX_GEOMETRY_SHADER_INVOCATIONS).
inline constexpr int kMaxGeometryInvocations = 32;
/// Most vertices of an input primitive (TRIANGLES_ADJACENCY's six).
inline constexpr int kMaxGeometryInputVertices = 6;

/// What a geometry stage takes and makes: GLSL's `layout(triangles, invocations = 2) in;` and
/// `layout(triangle_strip, max_vertices = 6) out;`. A shader with a Geometry() declares it as
/// `static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::TRIANGLE_STRIP, 6};`.
struct GeometryLayout {
  Enum input = TRIANGLES;        ///< POINTS, LINES, LINES_ADJACENCY, TRIANGLES or TRIANGLES_ADJACENCY
  Enum output = TRIANGLE_STRIP;  ///< POINTS, LINE_STRIP or TRIANGLE_STRIP
  int max_vertices = 3;          ///< most vertices one invocation emits (1 to kMaxGeometryOutputVertices)
  int invocations = 1;           ///< times the stage runs per primitive, gl_InvocationID 0, 1, ... (1 to 32)

  /// Vertices of each input primitive (gl_in.length()): 1, 2, 4, 3 or 6; 0 for a mode that is none of them.
  constexpr int InputVertices() const {
    return input == POINTS ? 1 : input == LINES ? 2 : input == LINES_ADJACENCY ? 4 : input == TRIANGLES ? 3
           : input == TRIANGLES_ADJACENCY ? 6 : 0;
  }
  /// Whether the draw mode `mode` makes the primitives `input` names (OpenGL 4.6, section 11.3.1).
  constexpr bool Accepts(Enum mode) const {
    switch (input) {
      case POINTS: return mode == POINTS;
      case LINES: return mode == LINES || mode == LINE_STRIP || mode == LINE_LOOP;
      case LINES_ADJACENCY: return mode == LINES_ADJACENCY || mode == LINE_STRIP_ADJACENCY;
      case TRIANGLES: return mode == TRIANGLES || mode == TRIANGLE_STRIP || mode == TRIANGLE_FAN;
      case TRIANGLES_ADJACENCY: return mode == TRIANGLES_ADJACENCY || mode == TRIANGLE_STRIP_ADJACENCY;
      default: return false;
    }
  }
};

/// One vertex of 16 input primitives, as the vertex stage wrote it (GLSL's gl_in[i] and the inputs' [i]).
template <class Varyings>
struct GeometryVertexLanes {
  vec4 position;     ///< gl_Position
  Float point_size;  ///< gl_PointSize
  Varyings varyings;
};

/// What a wide geometry stage reads: 16 primitives, one per lane, each with kGeometry.input's vertices. For
/// TRIANGLES_ADJACENCY, vertex 0, 2 and 4 make the triangle and 1, 3, 5 lie beyond its edges 0-2, 2-4 and 4-0;
/// for LINES_ADJACENCY, 1 and 2 make the line and 0, 3 lie beyond its ends (OpenGL 4.6, section 10.1).
template <class Varyings>
struct GeometryLanes : LodTextures {
  GeometryVertexLanes<Varyings> vertex[kMaxGeometryInputVertices];  ///< gl_in[0 .. vertices)
  int vertices = 0;    ///< gl_in.length(), the same in every lane
  Int primitive_id;    ///< gl_PrimitiveIDIn: the primitive's number in its draw (each instance counts from 0)
  Int instance_id;     ///< gl_InstanceID of the primitive's vertices
  Int invocation_id;   ///< gl_InvocationID: which of kGeometry.invocations runs (the same in every lane)
};

namespace shader_detail {
// Floats before the varyings in each vertex a geometry stage emits: the position (4), gl_PointSize, gl_Layer (its
// bits), 1 where the vertex starts a new strip (EndPrimitive came before it) and 0 where it continues one, and
// gl_PrimitiveID (its bits).
inline constexpr int kGeometryHead = 8;
// Where a geometry stage's emitted vertices go: lane l's k-th vertex at records + (l * max_vertices + k) * stride.
struct GeometrySink {
  float* records = nullptr;
  int stride = 0;
  int max_vertices = 0;
  std::uint32_t lanes = 0;  // the lanes that hold a primitive (the others' vertices are dropped)
  std::uint32_t cut = 0;    // lanes whose next vertex starts a new strip
  int count[kLanes] = {};   // vertices each lane has emitted
};
}  // namespace shader_detail

/// What a wide geometry stage writes: the values of the next vertex to emit, per lane, and EmitVertex() /
/// EndPrimitive(), which act in the lanes `lanes` selects (all by default), as GLSL's do in the invocations that
/// reach them. Emitted vertices past kGeometry.max_vertices are dropped. A strip of too few vertices (a line strip
/// of one, a triangle strip of two) makes nothing.
template <class Varyings>
struct GeometryLanesOut {
  vec4 position = vec4(0.0f, 0.0f, 0.0f, 1.0f);  ///< gl_Position, in clip space
  Float point_size = 1.0f;  ///< gl_PointSize, used when PROGRAM_POINT_SIZE is enabled
  Varyings varyings{};      ///< interpolated across the output primitive for the fragment stage
  Int layer = 0;            ///< gl_Layer, read only when Derived declares `static constexpr bool kWritesLayer = true;`
  Int primitive_id = 0;     ///< gl_PrimitiveID for the fragment stage (set to gl_PrimitiveIDIn before Geometry())

  explicit GeometryLanesOut(shader_detail::GeometrySink& sink) : sink_(&sink) {}

  /// EmitVertex(): the values above become the next vertex of the current strip, in each lane of `lanes`.
  void EmitVertex(const Bool& lanes = Bool(true)) {
    const std::uint32_t m = lanes.Bits() & sink_->lanes;
    if (m == 0) return;
    constexpr int kVaryingFloats = std::is_empty_v<Varyings> ? 0 : int(sizeof(Varyings) / sizeof(Float));
    alignas(64) float rows[shader_detail::kGeometryHead + kVaryingFloats][kLanes];
    position.x.Store(rows[0]);
    position.y.Store(rows[1]);
    position.z.Store(rows[2]);
    position.w.Store(rows[3]);
    point_size.Store(rows[4]);
    alignas(64) std::int32_t ints[kLanes];
    layer.Store(ints);
    std::memcpy(rows[5], ints, sizeof ints);
    primitive_id.Store(ints);
    std::memcpy(rows[7], ints, sizeof ints);
    for (int l = 0; l < kLanes; ++l) rows[6][l] = ((sink_->cut >> l) & 1u) ? 1.0f : 0.0f;
    if constexpr (kVaryingFloats > 0) {
      const Float* v = reinterpret_cast<const Float*>(static_cast<const void*>(&varyings));
      for (int f = 0; f < kVaryingFloats; ++f) v[f].Store(rows[shader_detail::kGeometryHead + f]);
    }
    for (std::uint32_t bits = m; bits != 0; bits &= bits - 1) {
      const int l = std::countr_zero(bits);
      const int k = sink_->count[l];
      if (k >= sink_->max_vertices) continue;
      float* r = sink_->records + (std::size_t(l) * std::size_t(sink_->max_vertices) + std::size_t(k)) *
                                      std::size_t(sink_->stride);
      for (int f = 0; f < shader_detail::kGeometryHead + kVaryingFloats; ++f) r[f] = rows[f][l];
      sink_->count[l] = k + 1;
    }
    sink_->cut &= ~m;
  }
  /// EndPrimitive(): the current strip ends in each lane of `lanes`; the next vertex starts another.
  void EndPrimitive(const Bool& lanes = Bool(true)) { sink_->cut |= lanes.Bits(); }

 private:
  shader_detail::GeometrySink* sink_;
};

/// What a wide fragment stage reads: 16 fragments, four 2x2 quads, lane = quad * 4 + (x % 2) + 2 * (y % 2). The
/// quads may lie anywhere and belong to different primitives of the draw (as on a GPU); each quad's lanes are
/// neighbours, so that derivatives are taken within the quad.
template <class Varyings>
struct FragmentLanes {
  Varyings varyings;   ///< interpolated varyings, per lane
  vec4 frag_coord;     ///< gl_FragCoord: window x, y (pixel centre at +0.5), depth z, and 1/w
  vec2 point_coord;    ///< gl_PointCoord: where in its point the fragment lies, (0, 0) to (1, 1) (see
                       ///< PointParameter's POINT_SPRITE_COORD_ORIGIN); (0, 0) for lines and triangles
  bool front_facing;   ///< gl_FrontFacing (the same for all 16 lanes)
  /// gl_PrimitiveID: the number of the fragment's primitive in its draw (each instance counts from 0; a triangle
  /// drawn as lines or points keeps its number), or what the geometry stage wrote for it. Read only when Derived
  /// declares `static constexpr bool kReadsPrimitiveId = true;` (0 otherwise).
  Int primitive_id;
  Bool helper;         ///< gl_HelperInvocation: lanes outside the primitive, run for derivatives, never written
  const Textures* textures;  ///< the textures bound for this draw

  /// texture(sampler2D, uv): the level of detail from uv's derivatives across each quad (implicit, as in GLSL).
  vec4 Texture(int unit, const vec2& uv, float bias = 0.0f) const {
    return TextureGrad(unit, uv, dFdx(uv), dFdy(uv), bias);
  }
  /// textureGrad(sampler2D, uv, dPdx, dPdy), with a bias added to the level of detail.
  vec4 TextureGrad(int unit, const vec2& uv, const vec2& duv_dx, const vec2& duv_dy, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(uv.x, uv.y);
    shader_detail::Derivatives(c, vec3(duv_dx, 0.0f), vec3(duv_dy, 0.0f));
    float out[4][kLanes];
    textures->SampleLanes(unit, c, bias, out);
    return shader_detail::Rgba(out);
  }
  /// textureLod(sampler2D, uv, lod).
  vec4 TextureLod(int unit, const vec2& uv, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(uv.x, uv.y), lod, &Textures::SampleLodLanes);
  }
  /// texture(samplerCube, dir).
  vec4 TextureCube(int unit, const vec3& dir, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(dir.x, dir.y, dir.z);
    shader_detail::Derivatives(c, dFdx(dir), dFdy(dir));
    float out[4][kLanes];
    textures->SampleCubeLanes(unit, c, bias, out);
    return shader_detail::Rgba(out);
  }
  /// textureLod(samplerCube, dir, lod).
  vec4 TextureCubeLod(int unit, const vec3& dir, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(dir.x, dir.y, dir.z), lod,
                              &Textures::SampleCubeLodLanes);
  }
  /// texture(sampler2DArray, vec3(uv, layer)): the layer floor(layer + 0.5), clamped to the texture's layers; the
  /// level of detail from uv's derivatives.
  vec4 TextureArray(int unit, const vec3& uv_layer, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(uv_layer.x, uv_layer.y, uv_layer.z);
    const vec2 uv(uv_layer.x, uv_layer.y);
    return shader_detail::Sample(textures, unit, c, vec3(dFdx(uv), 0.0f), vec3(dFdy(uv), 0.0f), bias,
                                 &Textures::SampleArrayLanes);
  }
  /// textureLod(sampler2DArray, vec3(uv, layer), lod).
  vec4 TextureArrayLod(int unit, const vec3& uv_layer, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(uv_layer.x, uv_layer.y, uv_layer.z), lod,
                              &Textures::SampleArrayLodLanes);
  }
  /// texture(sampler2DArrayShadow, vec4(uv, layer, ref)): TextureShadow on one layer of a depth texture array.
  Float TextureArrayShadow(int unit, const vec4& uv_layer_ref) const {
    Textures::Lanes c = shader_detail::Coords(uv_layer_ref.x, uv_layer_ref.y, uv_layer_ref.z);
    const vec2 uv(uv_layer_ref.x, uv_layer_ref.y);
    shader_detail::Derivatives(c, vec3(dFdx(uv), 0.0f), vec3(dFdy(uv), 0.0f));
    float ref[kLanes], out[kLanes];
    uv_layer_ref.w.Store(ref);
    textures->SampleArrayShadowLanes(unit, c, ref, out);
    return Float::Load(out);
  }
  /// texture(sampler3D, str): the level of detail from the derivatives of all three coordinates.
  vec4 Texture3D(int unit, const vec3& str, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(str.x, str.y, str.z);
    return shader_detail::Sample(textures, unit, c, dFdx(str), dFdy(str), bias, &Textures::Sample3DLanes);
  }
  /// textureLod(sampler3D, str, lod).
  vec4 Texture3DLod(int unit, const vec3& str, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(str.x, str.y, str.z), lod,
                              &Textures::Sample3DLodLanes);
  }
  /// texture(sampler1D, s): the level of detail from s's derivatives across each quad.
  vec4 Texture1D(int unit, const Float& s, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(s, 0.0f);
    return shader_detail::Sample(textures, unit, c, vec3(dFdx(s), 0.0f, 0.0f), vec3(dFdy(s), 0.0f, 0.0f), bias,
                                 &Textures::Sample1DLanes);
  }
  /// textureLod(sampler1D, s, lod).
  vec4 Texture1DLod(int unit, const Float& s, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(s, 0.0f), lod, &Textures::Sample1DLodLanes);
  }
  /// texture(sampler1DArray, vec2(s, layer)): the layer floor(layer + 0.5), clamped to the texture's layers; the
  /// level of detail from s's derivatives.
  vec4 Texture1DArray(int unit, const vec2& s_layer, float bias = 0.0f) const {
    Textures::Lanes c = shader_detail::Coords(s_layer.x, s_layer.y);
    return shader_detail::Sample(textures, unit, c, vec3(dFdx(s_layer.x), 0.0f, 0.0f),
                                 vec3(dFdy(s_layer.x), 0.0f, 0.0f), bias, &Textures::Sample1DArrayLanes);
  }
  /// textureLod(sampler1DArray, vec2(s, layer), lod).
  vec4 Texture1DArrayLod(int unit, const vec2& s_layer, Float lod) const {
    return shader_detail::Lod(textures, unit, shader_detail::Coords(s_layer.x, s_layer.y), lod,
                              &Textures::Sample1DArrayLodLanes);
  }
  /// textureSize(sampler1D, level) and textureSize(sampler1DArray, level) (width, layers).
  int TextureSize1D(int unit, int level = 0) const { return textures->Size1D(unit, level); }
  glm::ivec2 TextureSize1DArray(int unit, int level = 0) const { return textures->Size1DArray(unit, level); }
  /// texture(sampler2DShadow, vec3(uv, ref)): percentage-closer filtering of the comparison (see
  /// Textures::SampleShadow).
  Float TextureShadow(int unit, const vec3& uv_ref) const {
    Textures::Lanes c = shader_detail::Coords(uv_ref.x, uv_ref.y, uv_ref.z);
    const vec2 uv(uv_ref.x, uv_ref.y);
    shader_detail::Derivatives(c, vec3(dFdx(uv), 0.0f), vec3(dFdy(uv), 0.0f));
    float out[kLanes];
    textures->SampleShadowLanes(unit, c, out);
    return Float::Load(out);
  }
  /// textureSize(sampler2D, level).
  glm::ivec2 TextureSize(int unit, int level = 0) const { return textures->Size(unit, level); }
  /// texelFetch(sampler2D, ivec2(x, y), level): one texel of a level, unfiltered ((0, 0, 0, 0) outside it).
  vec4 TexelFetch(int unit, const Int& x, const Int& y, const Int& level = Int(0)) const {
    return shader_detail::Fetch(textures, unit, x, y, level, &Textures::FetchLanes);
  }
  /// texelFetch(sampler2DMS, ivec2(x, y), sample): one sample of a TEXTURE_2D_MULTISAMPLE texture.
  vec4 TexelFetchMS(int unit, const Int& x, const Int& y, const Int& sample) const {
    return shader_detail::Fetch(textures, unit, x, y, sample, &Textures::FetchSampleLanes);
  }
  /// textureSize(sampler2DMS) and textureSamples(sampler2DMS).
  glm::ivec2 TextureSizeMS(int unit) const { return textures->SizeMultisample(unit); }
  int TextureSamples(int unit) const { return textures->Samples(unit); }
  /// texelFetch(sampler2DMSArray, ivec3(x, y, layer), sample): one sample of a layer of a
  /// TEXTURE_2D_MULTISAMPLE_ARRAY texture.
  vec4 TexelFetchMSArray(int unit, const Int& x, const Int& y, const Int& layer, const Int& sample) const {
    return shader_detail::FetchSampleArray(textures, unit, x, y, layer, sample);
  }
  /// textureSize(sampler2DMSArray) (width, height, layers) and textureSamples(sampler2DMSArray).
  glm::ivec3 TextureSizeMSArray(int unit) const { return textures->SizeMultisampleArray(unit); }
  int TextureSamplesArray(int unit) const { return textures->SamplesArray(unit); }
  /// texelFetch(samplerBuffer, index): texel `index` of unit's buffer texture (Textures::FetchBuffer).
  vec4 TexelFetchBuffer(int unit, const Int& index) const { return shader_detail::FetchBuffer(textures, unit, index); }
  /// textureSize(samplerBuffer): the texels the buffer texture holds.
  int TextureSizeBuffer(int unit) const { return textures->SizeBuffer(unit); }
  /// textureSize(sampler2DArray, level): width, height, layers.
  glm::ivec3 TextureSizeArray(int unit, int level = 0) const { return textures->SizeArray(unit, level); }
  /// textureSize(sampler3D, level).
  glm::ivec3 TextureSize3D(int unit, int level = 0) const { return textures->Size3D(unit, level); }

  /// The lookups of integer textures (R8UI ... RGBA32I, RGB10_A2UI), GLSL's isampler* and usampler*: the texels'
  /// integers, sign- or zero-extended (an unsigned texture's as the same 32 bits). OpenGL samples them with NEAREST
  /// filters only (another filter leaves the texture incomplete: it reads (0, 0, 0, 1)). texture(isampler2D, uv):
  ivec4 ITexture(int unit, const vec2& uv, float bias = 0.0f) const { return ivec4::FromBits(Texture(unit, uv, bias)); }
  /// textureLod(isampler2D, uv, lod).
  ivec4 ITextureLod(int unit, const vec2& uv, Float lod) const { return ivec4::FromBits(TextureLod(unit, uv, lod)); }
  /// texture(isampler2DArray, vec3(uv, layer)).
  ivec4 ITextureArray(int unit, const vec3& uv_layer, float bias = 0.0f) const {
    return ivec4::FromBits(TextureArray(unit, uv_layer, bias));
  }
  /// texture(isampler3D, str).
  ivec4 ITexture3D(int unit, const vec3& str, float bias = 0.0f) const {
    return ivec4::FromBits(Texture3D(unit, str, bias));
  }
  /// texture(isamplerCube, dir).
  ivec4 ITextureCube(int unit, const vec3& dir, float bias = 0.0f) const {
    return ivec4::FromBits(TextureCube(unit, dir, bias));
  }
  /// texelFetch(isampler2D, ivec2(x, y), level) ((0, 0, 0, 0) outside the level).
  ivec4 ITexelFetch(int unit, const Int& x, const Int& y, const Int& level = Int(0)) const {
    return ivec4::FromBits(TexelFetch(unit, x, y, level));
  }
  /// texelFetch(isamplerBuffer, index).
  ivec4 ITexelFetchBuffer(int unit, const Int& index) const { return ivec4::FromBits(TexelFetchBuffer(unit, index)); }
};

/// What a wide fragment stage writes for its 16 fragments.
struct FragmentLanesOut {
  vec4 color[kMaxColorOutputs];  ///< colour outputs; color[0] is written to the colour buffer
  Float depth;                   ///< gl_FragDepth, preset to frag_coord.z (see Shader<>::kWritesDepth)
  Bool discarded = false;        ///< lanes discarded so far
  /// GLSL's discard, in the lanes where `c` holds (the others go on).
  void Discard(Bool c) { discarded = discarded | c; }
  /// An integer output (GLSL's `out ivec4` / `out uvec4`) for an integer colour buffer (R8UI ... RGBA32I): output
  /// o holds the integers as its floats' bits, which such a buffer stores clamped to its channels' range (another
  /// buffer would take those bits as floats).
  void SetColorI(int o, const ivec4& c) { color[o] = c.Bits(); }
};

// ---- The scalar form: one vertex or fragment per call ---------------------------------------------------------------

/// What a scalar vertex stage reads: the fetched attributes of one vertex.
struct VertexIn {
  /// attrib[i] is the value of attribute location i, converted to float as OpenGL does (normalized or not);
  /// missing components are filled from (0, 0, 0, 1); a disabled attribute reads its current value, by default
  /// (0, 0, 0, 1).
  const glm::vec4* attrib;
  /// gl_VertexID: the index of this vertex (the element value for DrawElement).
  int vertex_id;
  /// An integer attribute (Context::VertexAttribIPointer, VertexAttribI*): GLSL's `in ivec4` and `in uvec4`.
  glm::ivec4 AttribI(int i) const {
    glm::ivec4 v;
    std::memcpy(&v, &attrib[i], sizeof v);
    return v;
  }
  glm::uvec4 AttribUI(int i) const { return glm::uvec4(AttribI(i)); }
  /// The textures bound for this draw (SampleLod only: there are no derivatives in the vertex stage).
  const Textures* textures;
  /// gl_InstanceID: the instance of an instanced draw (DrawArraysInstanced, ...); 0 otherwise.
  int instance_id = 0;
};

/// What a scalar vertex stage writes.
template <class Varyings>
struct VertexOut {
  glm::vec4 position{0.0f, 0.0f, 0.0f, 1.0f};  ///< gl_Position, in clip space.
  float point_size = 1.0f;  ///< gl_PointSize, used when PROGRAM_POINT_SIZE is enabled.
  Varyings varyings{};      ///< Interpolated across the primitive for the fragment stage.
  int layer = 0;            ///< gl_Layer, as VertexLanesOut::layer (read only with kWritesLayer).
};

/// What a scalar fragment stage writes.
struct FragmentOut {
  glm::vec4 color[kMaxColorOutputs];  ///< Colour outputs; color[0] is written to the colour buffer.
  float depth;                        ///< gl_FragDepth, preset to frag_coord.z (see Shader<>::kWritesDepth)
  /// An integer output for an integer colour buffer, as FragmentLanesOut::SetColorI: the integers as the floats'
  /// bits.
  void SetColorI(int o, const glm::ivec4& c) { std::memcpy(&color[o].x, &c.x, sizeof c); }
};

/// The texture samples a quad's fragments have taken through FragmentIn::Texture(unit, &Varyings::uv): the first
/// lane to sample a (unit, varying, bias) samples all four lanes at once (Textures::SampleQuad), the others read
/// their result. Filled by Shader<>, one per quad.
template <class Varyings>
struct QuadSamples {
  static constexpr int kEntries = 4;
  struct Entry {
    int unit;
    glm::vec2 Varyings::*uv;
    float bias;
    glm::vec4 value[4];
  };
  int count = 0;
  Entry entry[kEntries];
};

/// What a scalar fragment stage reads for one fragment.
template <class Varyings>
struct FragmentIn {
  const Varyings& varyings;  ///< Perspective-correct interpolated varyings.
  glm::vec4 frag_coord;      ///< gl_FragCoord: window x, y (pixel centre at +0.5), depth z, and 1/w.
  bool front_facing;         ///< gl_FrontFacing.
  const Varyings* quad;      ///< The four lanes of this fragment's 2x2 quad (lane = x&1 + 2*(y&1)).
  int lane;                  ///< This fragment's lane in quad.
  const Textures* textures;  ///< The textures bound for this draw.
  QuadSamples<Varyings>* samples = nullptr;  ///< This quad's samples so far (null: sample lane by lane).
  glm::vec2 point_coord{0.0f};  ///< gl_PointCoord: where in its point the fragment lies, (0, 0) to (1, 1); (0, 0)
                                ///< for lines and triangles.

  /// texture(sampler2D, uv) with uv a varying: the level of detail comes from uv's derivatives across the quad.
  glm::vec4 Texture(int unit, glm::vec2 Varyings::*uv, float bias = 0.0f) const {
    if (samples) {
      for (int i = 0; i < samples->count; ++i) {
        const auto& e = samples->entry[i];
        if (e.unit == unit && e.uv == uv && e.bias == bias) return e.value[lane];
      }
      if (samples->count < QuadSamples<Varyings>::kEntries) {
        // Every lane's own coordinates and derivatives (as dFdx and dFdy give them in that lane), sampled at once.
        glm::vec2 st[4], dx[4], dy[4];
        for (int l = 0; l < 4; ++l) {
          st[l] = quad[l].*uv;
          dx[l] = quad[(l & ~1) + 1].*uv - quad[l & ~1].*uv;
          dy[l] = quad[(l & ~2) + 2].*uv - quad[l & ~2].*uv;
        }
        auto& e = samples->entry[samples->count++];
        e.unit = unit;
        e.uv = uv;
        e.bias = bias;
        textures->SampleQuad(unit, st, dx, dy, bias, e.value);
        return e.value[lane];
      }
    }
    return textures->Sample(unit, varyings.*uv, dFdx(uv), dFdy(uv), bias);
  }
  /// texture(sampler2D, uv) for a computed uv: pass its derivatives (e.g. dFdx(&V::uv) * scale).
  glm::vec4 Texture(int unit, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias = 0.0f) const {
    return textures->Sample(unit, uv, duv_dx, duv_dy, bias);
  }
  /// texture(samplerCube, dir) with dir a varying.
  glm::vec4 TextureCube(int unit, glm::vec3 Varyings::*dir, float bias = 0.0f) const {
    return textures->SampleCube(unit, varyings.*dir, dFdx(dir), dFdy(dir), bias);
  }
  /// texture(sampler2DArray, vec3(uv, layer)) with (uv, layer) a varying; the level of detail from uv alone.
  glm::vec4 TextureArray(int unit, glm::vec3 Varyings::*uv_layer, float bias = 0.0f) const {
    return textures->SampleArray(unit, varyings.*uv_layer, glm::vec2(dFdx(uv_layer)), glm::vec2(dFdy(uv_layer)),
                                 bias);
  }
  /// texture(sampler3D, str) with str a varying.
  glm::vec4 Texture3D(int unit, glm::vec3 Varyings::*str, float bias = 0.0f) const {
    return textures->Sample3D(unit, varyings.*str, dFdx(str), dFdy(str), bias);
  }
  /// texture(sampler1D, s) with s a varying.
  glm::vec4 Texture1D(int unit, float Varyings::*s, float bias = 0.0f) const {
    return textures->Sample1D(unit, varyings.*s, dFdx(s), dFdy(s), bias);
  }
  /// texture(sampler1DArray, vec2(s, layer)) with (s, layer) a varying; the level of detail from s alone.
  glm::vec4 Texture1DArray(int unit, glm::vec2 Varyings::*s_layer, float bias = 0.0f) const {
    return textures->Sample1DArray(unit, varyings.*s_layer, dFdx(s_layer).x, dFdy(s_layer).x, bias);
  }

  /// Screen-space derivative of a varying along x (GLSL dFdx, within the 2x2 quad).
  template <class T>
  T dFdx(T Varyings::*member) const {
    const int left = lane & ~1;
    return quad[left + 1].*member - quad[left].*member;
  }
  /// Screen-space derivative of a varying along y (GLSL dFdy, within the 2x2 quad).
  template <class T>
  T dFdy(T Varyings::*member) const {
    const int bottom = lane & ~2;
    return quad[bottom + 2].*member - quad[bottom].*member;
  }
};

// ---- What the pipeline hands a shader ---------------------------------------------------------------------------

/// A batch of vertices handed to the vertex stage. Filled by the pipeline.
struct VertexBatch {
  int count = 0;
  /// Component c of enabled attribute a of vertex i at attribs[(a * 4 + c) * stride + i]: rows of lanes, each row
  /// padded to a multiple of 16 with the last vertex's value. A disabled attribute's rows are not read.
  const float* attribs = nullptr;
  int stride = 0;                      ///< floats per row of `attribs` (a multiple of 16, at least count)
  std::uint32_t enabled = 0xFFFFu;     ///< attributes read from arrays (bit i); the others read `current`
  const glm::vec4* current = nullptr;  ///< [kMaxVertexAttribs] the value of each disabled attribute
  const int* vertex_ids = nullptr;     ///< [count]
  int instance_id = 0;                 ///< gl_InstanceID of every vertex of the batch
  glm::vec4* positions = nullptr;      ///< out: [count] clip-space positions
  float* point_sizes = nullptr;        ///< out: [count]
  int* layers = nullptr;               ///< out: [count] gl_Layer (null: not wanted; see Program::WritesLayer)
  float* varyings = nullptr;           ///< out: [count][VaryingFloats()]
  const Textures* textures = nullptr;
  int simd = 0;                        ///< SimdLevel()
};

/// A batch of primitives handed to the geometry stage, for one invocation. Filled by the pipeline.
struct GeometryBatch {
  int count = 0;     ///< primitives
  int vertices = 0;  ///< vertices of each (GeometryLayout::InputVertices())
  const std::uint32_t* vertex_index = nullptr;  ///< [count][vertices]: each vertex's row in the arrays below
  const glm::vec4* positions = nullptr;  ///< the vertex stage's outputs
  const float* point_sizes = nullptr;
  const float* varyings = nullptr;       ///< [][VertexVaryingFloats()]
  const std::int32_t* primitive_ids = nullptr;  ///< [count]
  const std::int32_t* instance_ids = nullptr;   ///< [count]
  int invocation = 0;
  const Textures* textures = nullptr;
  int simd = 0;
  /// out: primitive p's k-th vertex at records + (p * max_vertices + k) * stride: position, point size, layer,
  /// strip start, primitive id, then the varyings of the fragment stage's struct (shader_detail::kGeometryHead
  /// floats before them).
  float* records = nullptr;
  int stride = 0;
  int max_vertices = 0;
  int* emitted = nullptr;  ///< out: [count] vertices each primitive's invocation emitted
};

/// Floats a block's varyings take in a BlockBatch: kMaxVaryingFloats rows of 16 lanes.
inline constexpr int kBlockVaryingFloats = kMaxVaryingFloats * kLanes;

/// A batch of 4 x 4 fragment blocks handed to the fragment stage. Filled by the pipeline.
struct BlockBatch {
  int count = 0;                          ///< number of blocks
  int outputs = 1;                        ///< colour outputs the target keeps (1 to kMaxColorOutputs)
  bool front_facing = true;
  int simd = 0;                           ///< SimdLevel()
  const float* varyings = nullptr;        ///< block b at + b * kBlockVaryingFloats: [VaryingFloats()][16]
  const float* frag_coord = nullptr;      ///< block b at + b * 64: [4][16] (x, y, z, 1/w)
  const float* point_coord = nullptr;     ///< points: block b at + b * 32: [2][16] (s, t); null for other primitives
  std::uint32_t* live = nullptr;          ///< [count] in: covered lanes (bit = lane); out: discarded lanes cleared
  FragmentLanesOut* out = nullptr;        ///< [count] what the fragment stage writes
  const Textures* textures = nullptr;
};

namespace shader_detail {
template <class Batch>
void FillVertexLanes(const Batch& batch, int base, int n, VertexLanes& in) {
  in.textures = batch.textures;
  // Attributes to lanes: vertex l's attribute a into lane l; lanes past the batch repeat its last vertex. A
  // disabled attribute holds its current value in every vertex. (Unrolled, so that the compiler drops the writes
  // of attributes the shader never reads.)
#if defined(__GNUC__)
#pragma GCC unroll 16
#endif
  for (int a = 0; a < kMaxVertexAttribs; ++a) {
    const float* row = batch.attribs + std::size_t(a) * 4 * std::size_t(batch.stride);
    Float* dst = &in.attrib[a].x;
    if ((batch.enabled >> a) & 1u) {
      for (int c = 0; c < 4; ++c) dst[c] = Float::Load(row + std::size_t(c) * std::size_t(batch.stride) + base);
    } else {
      for (int c = 0; c < 4; ++c) dst[c] = Float(batch.current[a][c]);
    }
  }
  std::int32_t ids[kLanes];
  for (int l = 0; l < kLanes; ++l) ids[l] = batch.vertex_ids[base + (l < n ? l : n - 1)];
  in.vertex_id = Int::Load(ids);
  in.instance_id = Int(batch.instance_id);
}
template <class Varyings, bool kPrimitiveId>
void FillFragmentLanes(const BlockBatch& batch, int b, FragmentLanes<Varyings>& in) {
  constexpr std::size_t kFloats = std::is_empty_v<Varyings> ? 0 : sizeof(Varyings) / sizeof(Float);
  const float* src = batch.varyings + std::size_t(b) * kBlockVaryingFloats;
  if constexpr (kFloats > 0) {  // Float by Float (the struct is made of them)
    Float* dst = reinterpret_cast<Float*>(static_cast<void*>(&in.varyings));
    for (std::size_t i = 0; i < kFloats; ++i) dst[i] = Float::Load(src + i * kLanes);
  }
  if constexpr (kPrimitiveId) {  // two flat floats after the varyings: its low and high 16 bits
    in.primitive_id = Int(Float::Load(src + kFloats * kLanes)) + (Int(Float::Load(src + (kFloats + 1) * kLanes)) << 16);
  } else {
    in.primitive_id = Int(0);
  }
  const float* fc = batch.frag_coord + std::size_t(b) * 4 * kLanes;
  in.frag_coord = vec4(Float::Load(fc), Float::Load(fc + kLanes), Float::Load(fc + 2 * kLanes),
                       Float::Load(fc + 3 * kLanes));
  if (batch.point_coord) {
    const float* pc = batch.point_coord + std::size_t(b) * 2 * kLanes;
    in.point_coord = vec2(Float::Load(pc), Float::Load(pc + kLanes));
  } else {
    in.point_coord = vec2(Float(0.0f));
  }
  in.front_facing = batch.front_facing;
  in.helper = !Bool::FromBits(batch.live[b]);
  in.textures = batch.textures;
}
}  // namespace shader_detail

/// One value transform feedback records from each vertex (Context::TransformFeedbackVaryings): `components` (1 to
/// 4) consecutive floats of the vertex stage's varyings from float `first` (counted as VaryingFloats() counts them:
/// in declaration order, one per Float or float), or gl_Position (`first` = kPosition, 4 components). `name` is
/// what GetTransformFeedbackVarying reports (copied). Shader<>::Capture makes one from a member pointer.
struct FeedbackVarying {
  static constexpr int kPosition = -1;
  const char* name = "";
  int first = kPosition;
  int components = 4;
  /// gl_Position, named as GLSL names it.
  static constexpr FeedbackVarying Position() { return FeedbackVarying{"gl_Position", kPosition, 4}; }
};

namespace detail {
struct FeedbackLayout;  // a program's recorded varyings (src/, never seen by users)
}  // namespace detail

class Context;

/// The interface the pipeline uses to run a shader. Subclass Shader<> rather than this.
class Program {
 public:
  virtual ~Program() = default;
  /// Size of the varyings struct in floats per vertex (0 to kMaxVaryingFloats).
  virtual int VaryingFloats() const = 0;
  /// How each of those floats is interpolated (null: all smooth).
  virtual const Interpolation* VaryingInterpolation() const { return nullptr; }
  /// Runs the vertex stage on every vertex of the batch.
  virtual void ShadeVertices(const VertexBatch& batch) const = 0;
  /// Runs the fragment stage on every block of the batch.
  virtual void ShadeBlocks(const BlockBatch& batch) const = 0;
  /// A copy of this shader as it is now (its uniforms), which the fragment stage of a draw uses: fragments are
  /// shaded later, when the context renders its recorded draws, and the shader may have changed by then. Null
  /// when the shader cannot be copied: the context then renders each draw before the call returns.
  virtual std::shared_ptr<const Program> Snapshot() const { return nullptr; }
  /// Whether `copy`, a Snapshot() of this shader taken earlier, is what Snapshot() would give now, so that the
  /// context may use it again: false unless it is known to be (the default).
  virtual bool SnapshotIs(const Program& copy) const {
    (void)copy;
    return false;
  }
  /// Whether the fragment stage writes gl_FragDepth. When it does not, the depth test may run before the shader
  /// (early depth test), where that cannot change the result.
  virtual bool WritesDepth() const { return true; }
  /// Whether the last stage before rasterization (geometry, or else vertex) writes gl_Layer, which routes
  /// primitives to the layers of a layered framebuffer. When it does not, they all go to layer 0.
  virtual bool WritesLayer() const { return false; }
  /// Whether the fragment stage reads gl_PrimitiveID (FragmentLanes::primitive_id). It then takes the last two of
  /// VaryingFloats(), flat, which the pipeline fills.
  virtual bool ReadsPrimitiveId() const { return false; }
  /// The geometry stage's layout, or null when the program has no geometry stage.
  virtual const GeometryLayout* GeometryStage() const { return nullptr; }
  /// Floats of varyings per vertex the vertex stage writes: VaryingFloats(), unless a geometry stage sits between
  /// the vertex and fragment stages (VaryingFloats() is then the geometry stage's output, what fragments read).
  virtual int VertexVaryingFloats() const { return VaryingFloats(); }
  /// Runs the geometry stage on every primitive of the batch (only called when GeometryStage() is not null).
  virtual void ShadeGeometry(const GeometryBatch& batch) const { (void)batch; }

 private:
  friend class Context;
  // What transform feedback records from this program's vertices (TransformFeedbackVaryings); null: nothing. Never
  // changed in place, only replaced, so that a copy (Snapshot) shares it and compares equal byte for byte.
  std::shared_ptr<const detail::FeedbackLayout> feedback_;
};

/// Base class of user shaders (CRTP): `struct MyShader : softgl::Shader<MyShader, MyVaryings> { ... }`.
///
/// Derived defines, in the wide form (varyings made of Float, vec2, vec3, vec4 and their Flat<> and
/// NoPerspective<> forms):
///   void Vertex(const VertexLanes&, VertexLanesOut<Varyings>&) const;
///   void Fragment(const FragmentLanes<Varyings>&, FragmentLanesOut&) const;
/// or, in the scalar form (varyings made of float and GLM float vectors):
///   void Vertex(const VertexIn&, VertexOut<Varyings>&) const;
///   bool Fragment(const FragmentIn<Varyings>&, FragmentOut&) const;   // false discards the fragment
/// A geometry stage (wide form only) sits between them when Derived defines
///   static constexpr GeometryLayout kGeometry{input, output, max_vertices, invocations};
///   void Geometry(const GeometryLanes<Varyings>&, GeometryLanesOut<FragmentVaryings>&) const;
/// It reads the primitives the vertex stage's Varyings make and emits new ones whose FragmentVaryings the fragment
/// stage reads; without one, FragmentVaryings is Varyings. A Geometry() whose types do not match the other stages'
/// does not compile, as a GLSL program with mismatched stages does not link.
/// The last stage before rasterization that writes gl_Layer (out.layer) says so with
/// `static constexpr bool kWritesLayer = true;`.
/// A Fragment() that writes gl_FragDepth (out.depth) must say so with `static constexpr bool kWritesDepth = true;`
/// in Derived, as GLSL knows from the source; otherwise out.depth is ignored (the fragment keeps frag_coord.z)
/// and the depth test may run before the shader. Varyings must be trivially copyable, at most kMaxVaryingFloats
/// floats per vertex; an empty struct means no varyings.
template <class Derived, class Varyings, class FragmentVaryings = Varyings>
class Shader : public Program {
  // Which form Derived is written in, and what follows from it. (Asked inside member functions, where Derived is
  // complete; in one nested struct, so that no name of it can hide or be hidden by a name of Derived.)
  struct SoftglForm {
    static constexpr bool WideVertex() {
      return requires(const Derived& d, const VertexLanes& in, VertexLanesOut<Varyings>& out) { d.Vertex(in, out); };
    }
    static constexpr bool WideFragment() {
      return requires(const Derived& d, const FragmentLanes<FragmentVaryings>& in, FragmentLanesOut& out) {
        d.Fragment(in, out);
      };
    }
    static constexpr bool DefinesGeometry() {
      return requires(const Derived& d, const GeometryLanes<Varyings>& in, GeometryLanesOut<FragmentVaryings>& out) {
        d.Geometry(in, out);
      };
    }
    static constexpr bool DeclaresGeometry() { return requires { Derived::kGeometry; }; }
    static constexpr bool Wide() { return WideVertex() || WideFragment(); }
    // Floats of varyings per vertex: one per float of the struct, or one per Float (16 lanes) in the wide form.
    static constexpr int FloatBytes() { return Wide() ? int(sizeof(float)) * kLanes : int(sizeof(float)); }
    static constexpr int Floats() { return std::is_empty_v<Varyings> ? 0 : int(sizeof(Varyings)) / FloatBytes(); }
    static constexpr int FragmentFloats() {
      return std::is_empty_v<FragmentVaryings> ? 0 : int(sizeof(FragmentVaryings)) / FloatBytes();
    }
    static constexpr bool DeclaresLayer() {
      if constexpr (requires { Derived::kWritesLayer; }) {
        return bool(Derived::kWritesLayer);
      } else {
        return false;
      }
    }
    static constexpr bool DeclaresPrimitiveId() {
      if constexpr (requires { Derived::kReadsPrimitiveId; }) {
        return bool(Derived::kReadsPrimitiveId);
      } else {
        return false;
      }
    }
    // Floats after the fragment stage's varyings that carry gl_PrimitiveID (its low and high 16 bits, flat).
    static constexpr int Hidden() { return DeclaresPrimitiveId() ? 2 : 0; }
    // Floats per vertex of the vertex stage's output: its struct's, and with no geometry stage the hidden ones.
    static constexpr int VertexStride() { return Floats() + (DeclaresGeometry() ? 0 : Hidden()); }
    static constexpr bool DeclaresDepth() {
      if constexpr (requires { Derived::kWritesDepth; }) {
        return bool(Derived::kWritesDepth);
      } else {
        return false;
      }
    }
    static constexpr bool Check() {
      static_assert(std::is_trivially_copyable_v<Varyings>, "varyings must be trivially copyable");
      static_assert(!Wide() || std::is_empty_v<Varyings> || sizeof(Varyings) % (sizeof(float) * kLanes) == 0,
                    "a wide shader's varyings must be made of Float, vec2, vec3 and vec4");
      static_assert(Wide() || std::is_empty_v<Varyings> || sizeof(Varyings) % sizeof(float) == 0,
                    "varyings must be made of floats");
      static_assert(Floats() <= kMaxVaryingFloats,
                    "too many varyings: at most kMaxVaryingFloats (64) floats per vertex, as "
                    "GL_MAX_VARYING_COMPONENTS (a wide shader counts one per Float, a scalar one per float)");
      static_assert(WideVertex() || requires(const Derived& d, const VertexIn& in, VertexOut<Varyings>& out) {
        d.Vertex(in, out);
      }, "Derived needs a Vertex(const VertexLanes&, VertexLanesOut<Varyings>&) const (or the scalar form)");
      static_assert(WideFragment() || requires(const Derived& d, const FragmentIn<Varyings>& in, FragmentOut& out) {
        { d.Fragment(in, out) } -> std::convertible_to<bool>;
      }, "Derived needs a Fragment(const FragmentLanes<Varyings>&, FragmentLanesOut&) const (or the scalar form)");
      static_assert(WideVertex() == WideFragment(), "Vertex and Fragment must both be wide, or both scalar");
      static_assert(!DeclaresPrimitiveId() || WideFragment(), "gl_PrimitiveID is read in the wide form");
      static_assert(FragmentFloats() + Hidden() <= kMaxVaryingFloats,
                    "too many varyings: gl_PrimitiveID takes two of the kMaxVaryingFloats (64)");
      static_assert(DefinesGeometry() == DeclaresGeometry(),
                    "a Geometry(const GeometryLanes<Varyings>&, GeometryLanesOut<FragmentVaryings>&) const needs a "
                    "static constexpr GeometryLayout kGeometry, and kGeometry needs that Geometry()");
      static_assert(DefinesGeometry() || std::is_same_v<Varyings, FragmentVaryings>,
                    "the fragment stage reads other varyings than the vertex stage writes: a Geometry() must make "
                    "them");
      if constexpr (DeclaresGeometry()) {
        static_assert(WideVertex(), "a shader with a geometry stage is written in the wide form");
        static_assert(std::is_trivially_copyable_v<FragmentVaryings> &&
                          (std::is_empty_v<FragmentVaryings> || sizeof(FragmentVaryings) % (sizeof(float) * kLanes) == 0),
                      "the geometry stage's varyings must be made of Float, vec2, vec3 and vec4");
        static_assert(FragmentFloats() <= kMaxVaryingFloats, "too many varyings out of the geometry stage");
        constexpr GeometryLayout g = Derived::kGeometry;
        static_assert(g.InputVertices() > 0,
                      "kGeometry.input is POINTS, LINES, LINES_ADJACENCY, TRIANGLES or TRIANGLES_ADJACENCY");
        static_assert(g.output == POINTS || g.output == LINE_STRIP || g.output == TRIANGLE_STRIP,
                      "kGeometry.output is POINTS, LINE_STRIP or TRIANGLE_STRIP");
        static_assert(g.max_vertices >= 1 && g.max_vertices <= kMaxGeometryOutputVertices,
                      "kGeometry.max_vertices is 1 to kMaxGeometryOutputVertices (256)");
        static_assert(g.invocations >= 1 && g.invocations <= kMaxGeometryInvocations,
                      "kGeometry.invocations is 1 to kMaxGeometryInvocations (32)");
        static_assert(g.max_vertices * (4 + FragmentFloats()) <= kMaxGeometryTotalOutputFloats,
                      "kGeometry.max_vertices x (4 + the varyings' floats) exceeds "
                      "kMaxGeometryTotalOutputFloats (1024), as GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS");
      }
      return true;
    }
  };

  // A copy of the shader whose storage holds the source's bytes before the copy is constructed in it, so that the
  // bytes no member covers (padding) are the source's too, and SnapshotIs can compare the two objects whole.
  struct SoftglCopy {
    alignas(Derived) unsigned char bytes[sizeof(Derived)];
    const Derived* object;
    explicit SoftglCopy(const Derived& source) {
      std::memcpy(bytes, static_cast<const void*>(&source), sizeof(Derived));
      object = ::new (static_cast<void*>(bytes)) Derived(source);
    }
    SoftglCopy(const SoftglCopy&) = delete;
    SoftglCopy& operator=(const SoftglCopy&) = delete;
    ~SoftglCopy() { object->~Derived(); }
  };

  // The qualifiers of the varyings, read once from a value-initialized struct (Flat<>, NoPerspective<> and
  // Centroid<> mark their floats).
  struct Qualifiers {
    Interpolation mode[kMaxVaryingFloats] = {};
    bool any = false;
    Qualifiers() {
      if constexpr (SoftglForm::FragmentFloats() > 0) {
        const FragmentVaryings probe{};
        const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&probe);
        for (int k = 0; k < SoftglForm::FragmentFloats(); ++k) {
          std::uint32_t bits;
          std::memcpy(&bits, bytes + std::size_t(k) * SoftglForm::FloatBytes(), sizeof bits);
          if (bits == shader_detail::kFlatBits) mode[k] = Interpolation::kFlat;
          if (bits == shader_detail::kNoPerspectiveBits) mode[k] = Interpolation::kNoPerspective;
          if (bits == shader_detail::kCentroidBits) mode[k] = Interpolation::kCentroid;
          any = any || mode[k] != Interpolation::kSmooth;
        }
      }
      for (int k = SoftglForm::FragmentFloats(); k < SoftglForm::FragmentFloats() + SoftglForm::Hidden(); ++k) {
        mode[k] = Interpolation::kFlat;
        any = true;
      }
    }
  };

 public:
  int VaryingFloats() const final {
    static_assert(SoftglForm::Check());
    return SoftglForm::FragmentFloats() + SoftglForm::Hidden();
  }
  int VertexVaryingFloats() const final { return SoftglForm::VertexStride(); }
  bool ReadsPrimitiveId() const final { return SoftglForm::DeclaresPrimitiveId(); }

  const GeometryLayout* GeometryStage() const final {
    if constexpr (SoftglForm::DeclaresGeometry()) {
      static constexpr GeometryLayout layout = Derived::kGeometry;
      return &layout;
    } else {
      return nullptr;
    }
  }

  const Interpolation* VaryingInterpolation() const final {
    static const Qualifiers q;
    return q.any ? q.mode : nullptr;
  }

  bool WritesDepth() const final { return SoftglForm::DeclaresDepth(); }
  bool WritesLayer() const final { return SoftglForm::DeclaresLayer(); }

  /// The varying `member` (a member of the varyings the fragment stage reads: Float, vec2, vec3 or vec4, or float
  /// and GLM vectors in the scalar form; with a geometry stage, its output's) as transform feedback records it,
  /// reported under `name`: `FeedbackVarying v = MyShader::Capture(&MyVaryings::color, "color");`.
  template <class Member>
  static FeedbackVarying Capture(Member FragmentVaryings::*member, const char* name) {
    const FragmentVaryings probe{};
    const auto* base = reinterpret_cast<const unsigned char*>(&probe);
    const auto* at = reinterpret_cast<const unsigned char*>(&(probe.*member));
    return FeedbackVarying{name, int((at - base) / SoftglForm::FloatBytes()),
                           int(sizeof(Member)) / SoftglForm::FloatBytes()};
  }

  std::shared_ptr<const Program> Snapshot() const override {
    if constexpr (std::is_copy_constructible_v<Derived>) {
      // Only a shader whose class is Derived itself is copied (a class derived from it again would be sliced).
      if (typeid(*this) == typeid(Derived)) {
        const auto copy = std::make_shared<SoftglCopy>(static_cast<const Derived&>(*this));
        return std::shared_ptr<const Program>(copy, copy->object);
      }
    }
    return nullptr;
  }

  // A copy equal to this object byte for byte (its padding too: see SoftglCopy): every member copied then gives
  // the same bytes as its source now, which a member that owns memory (std::vector, std::string, ...) never does,
  // since the copy's memory is its own. Such a copy behaves as a fresh one would, and the draws that use it need
  // no copy of their own.
  bool SnapshotIs(const Program& copy) const override {
    if constexpr (std::is_copy_constructible_v<Derived>) {
      if (typeid(*this) != typeid(Derived) || typeid(copy) != typeid(Derived)) return false;
      const void* a = static_cast<const Derived*>(this);
      const void* b = &static_cast<const Derived&>(copy);
      return std::memcmp(a, b, sizeof(Derived)) == 0;
    }
    return false;
  }

  // Defined below the class, out of line: a program that draws with a shader compiled elsewhere (the built-in ones,
  // explicitly instantiated in softgl::model) then does not compile its stages again.
  void ShadeVertices(const VertexBatch& batch) const final;
  void ShadeBlocks(const BlockBatch& batch) const final;
  void ShadeGeometry(const GeometryBatch& batch) const final;

 private:
  // ---- The wide form, compiled three times ----
  void VertexLanesRun(const VertexBatch& batch) const {
    const Derived& self = static_cast<const Derived&>(*this);
    VertexLanes in;
    for (int base = 0; base < batch.count; base += kLanes) {
      const int n = batch.count - base < kLanes ? batch.count - base : kLanes;
      shader_detail::FillVertexLanes(batch, base, n, in);
      VertexLanesOut<Varyings> out;
      self.Vertex(in, out);
      shader_detail::StoreVertices(&out.position.x, 4, &batch.positions[base].x, 4, n);
      for (int l = 0; l < n; ++l) batch.point_sizes[base + l] = out.point_size[l];
      if constexpr (SoftglForm::DeclaresLayer())
        if (batch.layers)
          for (int l = 0; l < n; ++l) batch.layers[base + l] = out.layer[l];
      constexpr int kStride = SoftglForm::VertexStride();
      if constexpr (SoftglForm::Floats() > 0) {
        shader_detail::StoreVertices(reinterpret_cast<const Float*>(&out.varyings), SoftglForm::Floats(),
                                     batch.varyings + std::size_t(base) * kStride, kStride, n);
      }
      if constexpr (kStride > SoftglForm::Floats())  // gl_PrimitiveID's floats, which binning fills
        for (int l = 0; l < n; ++l)
          for (int h = SoftglForm::Floats(); h < kStride; ++h) batch.varyings[std::size_t(base + l) * kStride + h] = 0.0f;
    }
  }

  void BlockLanesRun(const BlockBatch& batch) const {
    const Derived& self = static_cast<const Derived&>(*this);
    for (int b = 0; b < batch.count; ++b) {
      if (!batch.live[b]) continue;  // every lane failed the early depth test
      FragmentLanes<FragmentVaryings> in;  // (not value-initialized: every member is set here)
      shader_detail::FillFragmentLanes<FragmentVaryings, SoftglForm::DeclaresPrimitiveId()>(batch, b, in);
      FragmentLanesOut& out = batch.out[b];  // written in place (outputs the shader leaves alone are undefined)
      if constexpr (SoftglForm::DeclaresDepth()) out.depth = in.frag_coord.z;  // (read only then)
      out.discarded = false;
      self.Fragment(in, out);
      batch.live[b] &= ~out.discarded.Bits();
    }
  }

  // 16 primitives per call, their vertices gathered into lanes; what they emit goes to batch.records.
  void GeometryLanesRun(const GeometryBatch& batch) const {
    if constexpr (SoftglForm::DeclaresGeometry()) {
      const Derived& self = static_cast<const Derived&>(*this);
      constexpr int kIn = SoftglForm::Floats();
      GeometryLanes<Varyings> in;
      in.textures = batch.textures;
      in.vertices = batch.vertices;
      in.invocation_id = Int(batch.invocation);
      shader_detail::GeometrySink sink;
      sink.stride = batch.stride;
      sink.max_vertices = batch.max_vertices;
      alignas(64) float rows[5 + kIn][kLanes];
      alignas(64) std::int32_t ids[2][kLanes];
      for (int base = 0; base < batch.count; base += kLanes) {
        const int n = batch.count - base < kLanes ? batch.count - base : kLanes;
        for (int k = 0; k < batch.vertices; ++k) {
          for (int l = 0; l < kLanes; ++l) {  // lanes past the batch repeat its last primitive
            const int p = base + (l < n ? l : n - 1);
            const std::uint32_t v = batch.vertex_index[std::size_t(p) * std::size_t(batch.vertices) + std::size_t(k)];
            const glm::vec4& pos = batch.positions[v];
            for (int c = 0; c < 4; ++c) rows[c][l] = pos[c];
            rows[4][l] = batch.point_sizes[v];
            for (int f = 0; f < kIn; ++f) rows[5 + f][l] = batch.varyings[std::size_t(v) * kIn + std::size_t(f)];
          }
          GeometryVertexLanes<Varyings>& dst = in.vertex[k];
          dst.position = vec4(Float::Load(rows[0]), Float::Load(rows[1]), Float::Load(rows[2]), Float::Load(rows[3]));
          dst.point_size = Float::Load(rows[4]);
          if constexpr (kIn > 0) {
            Float* var = reinterpret_cast<Float*>(static_cast<void*>(&dst.varyings));
            for (int f = 0; f < kIn; ++f) var[f] = Float::Load(rows[5 + f]);
          }
        }
        for (int l = 0; l < kLanes; ++l) {
          const int p = base + (l < n ? l : n - 1);
          ids[0][l] = batch.primitive_ids[p];
          ids[1][l] = batch.instance_ids[p];
        }
        in.primitive_id = Int::Load(ids[0]);
        in.instance_id = Int::Load(ids[1]);
        sink.records = batch.records + std::size_t(base) * std::size_t(batch.max_vertices) * std::size_t(batch.stride);
        sink.lanes = n == kLanes ? 0xFFFFu : (1u << n) - 1u;
        sink.cut = 0xFFFFu;
        for (int l = 0; l < kLanes; ++l) sink.count[l] = 0;
        GeometryLanesOut<FragmentVaryings> out(sink);
        out.primitive_id = in.primitive_id;
        self.Geometry(in, out);
        for (int l = 0; l < n; ++l) batch.emitted[base + l] = sink.count[l];
      }
    } else {
      (void)batch;
    }
  }

#if defined(SOFTGL_HAS_DISPATCH)
  SOFTGL_TARGET_AVX512 void GeometryAvx512(const GeometryBatch& batch) const { GeometryLanesRun(batch); }
  SOFTGL_TARGET_AVX2 void GeometryAvx2(const GeometryBatch& batch) const { GeometryLanesRun(batch); }
  SOFTGL_TARGET_AVX512 void VerticesAvx512(const VertexBatch& batch) const { VertexLanesRun(batch); }
  SOFTGL_TARGET_AVX2 void VerticesAvx2(const VertexBatch& batch) const { VertexLanesRun(batch); }
  SOFTGL_TARGET_AVX512 void BlocksAvx512(const BlockBatch& batch) const { BlockLanesRun(batch); }
  SOFTGL_TARGET_AVX2 void BlocksAvx2(const BlockBatch& batch) const { BlockLanesRun(batch); }
#endif
  SOFTGL_TARGET_BASE void VerticesBase(const VertexBatch& batch) const { VertexLanesRun(batch); }
  SOFTGL_TARGET_BASE void GeometryBase(const GeometryBatch& batch) const { GeometryLanesRun(batch); }
  SOFTGL_TARGET_BASE void BlocksBase(const BlockBatch& batch) const { BlockLanesRun(batch); }

  // ---- The scalar form, lane by lane ----
  void ScalarBlocks(const BlockBatch& batch) const {
    const Derived& self = static_cast<const Derived&>(*this);
    Varyings quad[4]{};  // one 2x2 quad's lanes (lane = x&1 + 2*(y&1))
    QuadSamples<Varyings> samples;
    for (int b = 0; b < batch.count; ++b) {
      const float* soa = batch.varyings + std::size_t(b) * kBlockVaryingFloats;
      const float* fc = batch.frag_coord + std::size_t(b) * 4 * kLanes;
      FragmentLanesOut& lanes_out = batch.out[b];
      for (int q = 0; q < 4; ++q) {
        if (!((batch.live[b] >> (4 * q)) & 0xFu)) continue;
        if constexpr (SoftglForm::Floats() > 0) {
          for (int k = 0; k < 4; ++k) {
            float lanes[SoftglForm::Floats()];
            for (int v = 0; v < SoftglForm::Floats(); ++v) lanes[v] = soa[v * kLanes + q * 4 + k];
            std::memcpy(static_cast<void*>(&quad[k]), lanes, sizeof(Varyings));
          }
        }
        samples.count = 0;
        for (int k = 0; k < 4; ++k) {
          const int l = q * 4 + k;
          if (!((batch.live[b] >> l) & 1u)) continue;
          FragmentIn<Varyings> in{quad[k], glm::vec4(fc[l], fc[kLanes + l], fc[2 * kLanes + l], fc[3 * kLanes + l]),
                                  batch.front_facing, quad, k, batch.textures, &samples};
          if (batch.point_coord) {
            const float* pc = batch.point_coord + std::size_t(b) * 2 * kLanes;
            in.point_coord = glm::vec2(pc[l], pc[kLanes + l]);
          }
          FragmentOut out{};  // outputs the shader leaves alone read 0
          out.depth = in.frag_coord.z;
          if (!self.Fragment(in, out)) batch.live[b] &= ~(1u << l);
          for (int o = 0; o < batch.outputs; ++o)
            for (int c = 0; c < 4; ++c) lanes_out.color[o][c].v.Set(l, out.color[o][c]);
          if constexpr (SoftglForm::DeclaresDepth()) lanes_out.depth.v.Set(l, out.depth);
        }
      }
    }
  }
};

template <class Derived, class Varyings, class FragmentVaryings>
void Shader<Derived, Varyings, FragmentVaryings>::ShadeVertices(const VertexBatch& batch) const {
  static_assert(SoftglForm::Check());
  if constexpr (SoftglForm::WideVertex()) {
#if defined(SOFTGL_HAS_DISPATCH)
    if (batch.simd == 2) return VerticesAvx512(batch);
    if (batch.simd == 1) return VerticesAvx2(batch);
#endif
    VerticesBase(batch);
  } else {
    const Derived& self = static_cast<const Derived&>(*this);
    glm::vec4 attrib[kMaxVertexAttribs];
    for (int i = 0; i < batch.count; ++i) {
      for (int a = 0; a < kMaxVertexAttribs; ++a) {  // vertex i's attributes from the rows
        const float* row = batch.attribs + std::size_t(a) * 4 * std::size_t(batch.stride) + i;
        if ((batch.enabled >> a) & 1u)
          for (int c = 0; c < 4; ++c) attrib[a][c] = row[std::size_t(c) * std::size_t(batch.stride)];
        else
          attrib[a] = batch.current[a];
      }
      VertexOut<Varyings> out;
      self.Vertex(VertexIn{attrib, batch.vertex_ids[i], batch.textures, batch.instance_id}, out);
      batch.positions[i] = out.position;
      batch.point_sizes[i] = out.point_size;
      if constexpr (SoftglForm::DeclaresLayer())
        if (batch.layers) batch.layers[i] = out.layer;
      if constexpr (SoftglForm::Floats() > 0)
        std::memcpy(batch.varyings + std::size_t(i) * SoftglForm::Floats(), &out.varyings, sizeof(Varyings));
    }
  }
}

template <class Derived, class Varyings, class FragmentVaryings>
void Shader<Derived, Varyings, FragmentVaryings>::ShadeGeometry(const GeometryBatch& batch) const {
  static_assert(SoftglForm::Check());
#if defined(SOFTGL_HAS_DISPATCH)
  if (batch.simd == 2) return GeometryAvx512(batch);
  if (batch.simd == 1) return GeometryAvx2(batch);
#endif
  GeometryBase(batch);
}

template <class Derived, class Varyings, class FragmentVaryings>
void Shader<Derived, Varyings, FragmentVaryings>::ShadeBlocks(const BlockBatch& batch) const {
  static_assert(SoftglForm::Check());
  if constexpr (SoftglForm::WideFragment()) {
#if defined(SOFTGL_HAS_DISPATCH)
    if (batch.simd == 2) return BlocksAvx512(batch);
    if (batch.simd == 1) return BlocksAvx2(batch);
#endif
    BlocksBase(batch);
  } else {
    ScalarBlocks(batch);
  }
}

}  // namespace softgl

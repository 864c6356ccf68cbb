// softgl/shader.h — the programmable stages: write a shader by subclassing softgl::Shader.
//
// A shader is a C++ class. Its uniforms are ordinary members; its varyings are a plain struct of floats and GLM
// float vectors that the vertex stage writes and the fragment stage reads, interpolated perspective-correctly.
//
//     struct Vary { glm::vec3 color; };
//     struct ColorShader : softgl::Shader<ColorShader, Vary> {
//       glm::mat4 mvp{1.0f};                                   // a uniform
//       void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Vary>& out) const {
//         out.position = mvp * in.attrib[0];                   // gl_Position, clip space
//         out.varyings.color = glm::vec3(in.attrib[1]);
//       }
//       bool Fragment(const softgl::FragmentIn<Vary>& in, softgl::FragmentOut& out) const {
//         out.color[0] = glm::vec4(in.varyings.color, 1.0f);   // return false to discard
//         return true;
//       }
//     };
//
// The pipeline calls a shader through softgl::Program, once per batch of vertices and once per batch of 2x2
// fragment quads; inside a batch, Shader<> calls your Vertex() and Fragment() directly (no virtual call per vertex
// or fragment), so the compiler can inline them. A quad always holds the four fragments of an aligned 2x2 pixel
// block; lanes not covered by the primitive are "helper" lanes whose varyings are still interpolated, so that
// FragmentIn::dFdx / dFdy give screen-space derivatives, as in GLSL.
//
// Vertex() and Fragment() run on the context's worker threads, several at once on the same shader object: they
// must only read the shader's members. The vertex stage runs during the draw call; the fragment stage runs later,
// when the context renders (ReadPixels, Finish, ...), on a copy of the shader taken at the draw (Snapshot), so
// changing uniforms between draws works as in OpenGL.
#pragma once

#include <softgl/config.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <typeinfo>
#include <type_traits>

#include <glm/glm.hpp>
#include <softgl/texture.h>

namespace softgl {

/// Number of vertex attribute locations (GL_MAX_VERTEX_ATTRIBS).
inline constexpr int kMaxVertexAttribs = 16;
/// Largest varyings struct, in floats: 16 vec4 (GL_MAX_VARYING_COMPONENTS = 64).
inline constexpr int kMaxVaryingFloats = 64;
/// Number of colour outputs a fragment shader may write (color[0] goes to the default framebuffer).
inline constexpr int kMaxColorOutputs = 4;

/// What the vertex stage reads: the fetched attributes of one vertex.
struct VertexIn {
  /// attrib[i] is the value of attribute location i, converted to float as OpenGL does (normalized or not);
  /// missing components are filled from (0, 0, 0, 1); a disabled attribute reads its current value, by default
  /// (0, 0, 0, 1).
  const glm::vec4* attrib;
  /// gl_VertexID: the index of this vertex (the element value for DrawElement).
  int vertex_id;
  /// The textures bound for this draw (SampleLod only: there are no derivatives in the vertex stage).
  const Textures* textures;
};

/// What the vertex stage writes.
template <class Varyings>
struct VertexOut {
  glm::vec4 position{0.0f, 0.0f, 0.0f, 1.0f};  ///< gl_Position, in clip space.
  float point_size = 1.0f;  ///< gl_PointSize, used when PROGRAM_POINT_SIZE is enabled.
  Varyings varyings{};      ///< Interpolated across the primitive for the fragment stage.
};

/// What the fragment stage writes.
struct FragmentOut {
  glm::vec4 color[kMaxColorOutputs];  ///< Colour outputs; color[0] is written to the colour buffer.
  float depth;                        ///< gl_FragDepth, preset to frag_coord.z (see Shader<>::kWritesDepth).
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

/// What the fragment stage reads for one fragment.
template <class Varyings>
struct FragmentIn {
  const Varyings& varyings;  ///< Perspective-correct interpolated varyings.
  glm::vec4 frag_coord;      ///< gl_FragCoord: window x, y (pixel centre at +0.5), depth z, and 1/w.
  bool front_facing;         ///< gl_FrontFacing.
  const Varyings* quad;      ///< The four lanes of this fragment's 2x2 quad (lane = x&1 + 2*(y&1)).
  int lane;                  ///< This fragment's lane in quad.
  const Textures* textures;  ///< The textures bound for this draw.
  QuadSamples<Varyings>* samples = nullptr;  ///< This quad's samples so far (null: sample lane by lane).

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

  /// Screen-space derivative of a varying along x (GLSL dFdx, coarse within the 2x2 quad).
  template <class T>
  T dFdx(T Varyings::*member) const {
    const int left = lane & ~1;
    return quad[left + 1].*member - quad[left].*member;
  }
  /// Screen-space derivative of a varying along y (GLSL dFdy, coarse within the 2x2 quad).
  template <class T>
  T dFdy(T Varyings::*member) const {
    const int bottom = lane & ~2;
    return quad[bottom + 2].*member - quad[bottom].*member;
  }
};

/// A batch of vertices handed to the vertex stage. Filled by the pipeline.
struct VertexBatch {
  int count = 0;
  const glm::vec4* attribs = nullptr;  ///< [count][kMaxVertexAttribs]
  const int* vertex_ids = nullptr;     ///< [count]
  glm::vec4* positions = nullptr;      ///< out: [count] clip-space positions
  float* point_sizes = nullptr;        ///< out: [count]
  float* varyings = nullptr;           ///< out: [count][VaryingFloats()]
  const Textures* textures = nullptr;
};

/// A batch of 2x2 fragment quads handed to the fragment stage. Filled by the pipeline.
struct QuadBatch {
  int count = 0;                          ///< Number of quads; lanes are count * 4.
  const float* varyings = nullptr;        ///< [count * 4][VaryingFloats()] interpolated varyings
  const glm::vec4* frag_coord = nullptr;  ///< [count * 4]
  bool front_facing = true;
  FragmentOut* out = nullptr;  ///< [count * 4]
  std::uint8_t* live = nullptr;  ///< [count * 4] in: 1 for covered lanes; out: 0 where the shader discarded
  const Textures* textures = nullptr;
};

/// The interface the pipeline uses to run a shader. Subclass Shader<> rather than this.
class Program {
 public:
  virtual ~Program() = default;
  /// Size of the varyings struct in floats (0 to kMaxVaryingFloats).
  virtual int VaryingFloats() const = 0;
  /// Runs the vertex stage on every vertex of the batch.
  virtual void ShadeVertices(const VertexBatch& batch) const = 0;
  /// Runs the fragment stage on every live lane of the batch.
  virtual void ShadeQuads(const QuadBatch& batch) const = 0;
  /// A copy of this shader as it is now (its uniforms), which the fragment stage of a draw uses: fragments are
  /// shaded later, when the context renders its recorded draws, and the shader may have changed by then. Null
  /// when the shader cannot be copied: the context then renders each draw before the call returns.
  virtual std::shared_ptr<const Program> Snapshot() const { return nullptr; }
  /// Whether the fragment stage writes FragmentOut::depth (gl_FragDepth). When it does not, the depth test may run
  /// before the shader (early depth test), where that cannot change the result.
  virtual bool WritesDepth() const { return true; }
};

/// Base class of user shaders (CRTP): `struct MyShader : softgl::Shader<MyShader, MyVaryings> { ... }`.
///
/// Derived must define
///   void Vertex(const VertexIn&, VertexOut<Varyings>&) const;
///   bool Fragment(const FragmentIn<Varyings>&, FragmentOut&) const;   // false discards the fragment
/// A Fragment() that writes out.depth (gl_FragDepth) must say so with `static constexpr bool kWritesDepth = true;`
/// in Derived, as GLSL knows from the source; otherwise out.depth is ignored (the fragment keeps frag_coord.z)
/// and the depth test may run before the shader.
/// Varyings must be a trivially copyable struct made only of floats (float, glm::vecN, glm::matN), at most
/// kMaxVaryingFloats of them; an empty struct means no varyings.
template <class Derived, class Varyings>
class Shader : public Program {
  static constexpr int kFloats = std::is_empty_v<Varyings> ? 0 : int(sizeof(Varyings) / sizeof(float));
  static_assert(std::is_trivially_copyable_v<Varyings>, "varyings must be trivially copyable");
  static_assert(std::is_empty_v<Varyings> || sizeof(Varyings) % sizeof(float) == 0,
                "varyings must be made of floats");
  static_assert(kFloats <= kMaxVaryingFloats, "at most kMaxVaryingFloats floats of varyings");

  // Derived declares `static constexpr bool kWritesDepth = true;` when its Fragment() writes out.depth.
  static constexpr bool DeclaresDepth() {
    if constexpr (requires { Derived::kWritesDepth; }) {
      return bool(Derived::kWritesDepth);
    } else {
      return false;
    }
  }

 public:
  int VaryingFloats() const final { return kFloats; }

  bool WritesDepth() const final { return DeclaresDepth(); }

  std::shared_ptr<const Program> Snapshot() const override {
    if constexpr (std::is_copy_constructible_v<Derived>) {
      // Only a shader whose class is Derived itself is copied (a class derived from it again would be sliced).
      if (typeid(*this) == typeid(Derived)) return std::make_shared<Derived>(static_cast<const Derived&>(*this));
    }
    return nullptr;
  }

  void ShadeVertices(const VertexBatch& batch) const final {
    const Derived& self = static_cast<const Derived&>(*this);
    for (int i = 0; i < batch.count; ++i) {
      VertexOut<Varyings> out;
      self.Vertex(VertexIn{batch.attribs + std::size_t(i) * kMaxVertexAttribs, batch.vertex_ids[i], batch.textures},
                  out);
      batch.positions[i] = out.position;
      batch.point_sizes[i] = out.point_size;
      if constexpr (kFloats > 0)
        std::memcpy(batch.varyings + std::size_t(i) * kFloats, &out.varyings, sizeof(Varyings));
    }
  }

  void ShadeQuads(const QuadBatch& batch) const final {
    const Derived& self = static_cast<const Derived&>(*this);
    Varyings lanes[4]{};
    QuadSamples<Varyings> samples;
    for (int q = 0; q < batch.count; ++q) {
      const int base = q * 4;
      samples.count = 0;
      if constexpr (kFloats > 0)
        std::memcpy(static_cast<void*>(lanes), batch.varyings + std::size_t(base) * kFloats,
                    sizeof(Varyings) * 4);
      for (int lane = 0; lane < 4; ++lane) {
        if (!batch.live[base + lane]) continue;
        const FragmentIn<Varyings> in{lanes[lane], batch.frag_coord[base + lane], batch.front_facing, lanes, lane,
                                      batch.textures, &samples};
        FragmentOut& out = batch.out[base + lane];
        out.depth = in.frag_coord.z;
        if (!self.Fragment(in, out)) batch.live[base + lane] = 0;
        if constexpr (!DeclaresDepth()) out.depth = in.frag_coord.z;  // undeclared depth writes are ignored
      }
    }
  }
};

}  // namespace softgl

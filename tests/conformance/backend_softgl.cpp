// backend_softgl.cpp — the conformance backend on softgl, with the scene shaders in C++.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <softgl/softgl.h>

#include "../color_shader.h"
#include "backend.h"

namespace conformance {

namespace {

using testing::ColorShader;

struct UvVaryings {
  glm::vec2 uv;
};

struct UvShader : softgl::Shader<UvShader, UvVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<UvVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = glm::vec2(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<UvVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = glm::vec4(in.varyings.uv, 0.5f, 1.0f);
    return true;
  }
};

struct LitVaryings {
  glm::vec3 normal;
};

struct LitShader : softgl::Shader<LitShader, LitVaryings> {
  Uniforms u;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<LitVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.normal = glm::vec3(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<LitVaryings>& in, softgl::FragmentOut& out) const {
    const glm::vec3 n = glm::normalize(in.varyings.normal);
    const float diffuse = std::max(glm::dot(n, u.light_dir), 0.0f);
    const float specular = std::pow(std::max(glm::dot(n, u.half_vector), 0.0f), 32.0f);
    out.color[0] = glm::vec4(glm::vec3(u.tint) * (0.2f + 0.8f * diffuse) + glm::vec3(0.3f * specular), u.tint.a);
    return true;
  }
};

struct TexVaryings {
  glm::vec2 uv;
};

struct TextureShader : softgl::Shader<TextureShader, TexVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<TexVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = glm::vec2(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<TexVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.Texture(0, &TexVaryings::uv);
    return true;
  }
};

struct DirVaryings {
  glm::vec3 dir;
};

struct CubeShader : softgl::Shader<CubeShader, DirVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<DirVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.dir = glm::vec3(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<DirVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.TextureCube(1, &DirVaryings::dir);
    return true;
  }
};

struct ShadowVaryings {
  glm::vec3 coord;
};

struct ShadowShader : softgl::Shader<ShadowShader, ShadowVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<ShadowVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.coord = glm::vec3(in.attrib[2]);
  }
  bool Fragment(const softgl::FragmentIn<ShadowVaryings>& in, softgl::FragmentOut& out) const {
    const glm::vec3 c = in.varyings.coord;
    out.color[0] = glm::vec4(in.textures->SampleShadow(2, glm::vec2(c), c.z, {}, {}), 0.0f, 0.0f, 1.0f);
    return true;
  }
};

struct LayerVaryings {
  glm::vec4 coord;
};

// kArray, kVolume and kArrayShadow: texture(unit 3, 4 or 5, extra); kTexture1D and kTexture1DArray: unit 7.
struct LayeredShader : softgl::Shader<LayeredShader, LayerVaryings> {
  softgl::Enum target = softgl::TEXTURE_2D_ARRAY;
  bool shadow = false;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<LayerVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.coord = in.attrib[2];
  }
  bool Fragment(const softgl::FragmentIn<LayerVaryings>& in, softgl::FragmentOut& out) const {
    const glm::vec4 c = in.varyings.coord;
    const glm::vec2 dx(in.dFdx(&LayerVaryings::coord)), dy(in.dFdy(&LayerVaryings::coord));
    if (shadow)
      out.color[0] = glm::vec4(in.textures->SampleArrayShadow(5, glm::vec3(c), c.w, dx, dy), 0.0f, 0.0f, 1.0f);
    else if (target == softgl::TEXTURE_1D)
      out.color[0] = in.textures->Sample1D(7, c.x, dx.x, dy.x);
    else if (target == softgl::TEXTURE_1D_ARRAY)
      out.color[0] = in.textures->Sample1DArray(7, glm::vec2(c), dx.x, dy.x);
    else if (target == softgl::TEXTURE_3D)
      out.color[0] = in.textures->Sample3D(4, glm::vec3(c), glm::vec3(in.dFdx(&LayerVaryings::coord)),
                                           glm::vec3(in.dFdy(&LayerVaryings::coord)));
    else
      out.color[0] = in.textures->SampleArray(3, glm::vec3(c), dx, dy);
    return true;
  }
};

// The wide programs whose fragment stage reads attribute 2 (extra), and gl_FragCoord.
struct FetchSampleVaryings {
  softgl::vec4 extra;
};
template <class Derived>
struct ExtraShader : softgl::Shader<Derived, FetchSampleVaryings> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<FetchSampleVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.extra = in.attrib[2];
  }
};

// kFetchSample, in the wide form: texelFetch of the multisample texture on unit 6.
struct FetchSampleShader : ExtraShader<FetchSampleShader> {
  void Fragment(const softgl::FragmentLanes<FetchSampleVaryings>& in, softgl::FragmentLanesOut& out) const {
    using softgl::Int;
    const softgl::vec4& e = in.varyings.extra;
    out.color[0] = in.TexelFetchMS(6, Int(in.frag_coord.x) - Int(e.x), Int(in.frag_coord.y) - Int(e.y), Int(e.z));
  }
};

// kFetchSampleArray, in the wide form: texelFetch of the multisample array on unit 6.
struct FetchSampleArrayShader : ExtraShader<FetchSampleArrayShader> {
  void Fragment(const softgl::FragmentLanes<FetchSampleVaryings>& in, softgl::FragmentLanesOut& out) const {
    using softgl::Int;
    const softgl::vec4& e = in.varyings.extra;
    out.color[0] = in.TexelFetchMSArray(6, Int(in.frag_coord.x) - Int(e.x), Int(in.frag_coord.y) - Int(e.y), Int(e.w),
                                        Int(e.z));
  }
};

// kTextureBuffer, in the wide form: texelFetch of the buffer texture on unit 0, or its textureSize.
struct TextureBufferShader : ExtraShader<TextureBufferShader> {
  void Fragment(const softgl::FragmentLanes<FetchSampleVaryings>& in, softgl::FragmentLanesOut& out) const {
    using softgl::Int;
    const softgl::vec4& e = in.varyings.extra;
    const Int x(in.frag_coord.x), y(in.frag_coord.y);
    const softgl::vec4 texel = in.TexelFetchBuffer(0, Int(e.x) + y / 4 % 16 * 16 + x / 4 % 16);
    const softgl::vec4 size(float(in.TextureSizeBuffer(0)) / 1024.0f, 0.0f, 0.0f, 1.0f);
    out.color[0] = softgl::select(e.y > 0.5f, size, texel);
  }
};

// DrawIntegerTarget's stages: integer outputs from a flat attribute 2 (uint(extra) where `is_unsigned`: values
// from 2^31 up taken as their bits), and an integer texture's texel on unit 0 shown as bytes.
struct IntegerOutputVaryings {
  softgl::Flat<softgl::vec4> value;
};
struct IntegerOutputShader : softgl::Shader<IntegerOutputShader, IntegerOutputVaryings> {
  bool is_unsigned = false;
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<IntegerOutputVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.value = in.attrib[2];
  }
  void Fragment(const softgl::FragmentLanes<IntegerOutputVaryings>& in, softgl::FragmentLanesOut& out) const {
    const auto integer = [this](const softgl::Float& f) {
      return softgl::Int(is_unsigned ? softgl::select(f >= 2147483648.0f, f - 4294967296.0f, f) : f);
    };
    const softgl::vec4& v = in.varyings.value;
    out.SetColorI(0, softgl::ivec4(integer(v.x), integer(v.y), integer(v.z), integer(v.w)));
  }
};
struct IntegerTextureShader : ExtraShader<IntegerTextureShader> {
  void Fragment(const softgl::FragmentLanes<FetchSampleVaryings>& in, softgl::FragmentLanesOut& out) const {
    using softgl::Float;
    const softgl::ivec4 t = in.ITexture(0, softgl::vec2(in.varyings.extra.x, in.varyings.extra.y));
    out.color[0] = softgl::vec4(Float(t.x & 255) / 255.0f, Float(t.y & 255) / 255.0f,
                                Float((t.z + t.w * 64) & 255) / 255.0f, 1.0f);
  }
};

// kPointCoord, in the wide form: gl_PointCoord and the colour's blue.
struct PointCoordVaryings {
  softgl::Float blue;
};
struct PointCoordShader : softgl::Shader<PointCoordShader, PointCoordVaryings> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<PointCoordVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.blue = in.attrib[1].z;
  }
  void Fragment(const softgl::FragmentLanes<PointCoordVaryings>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = softgl::vec4(in.point_coord.x, in.point_coord.y, in.varyings.blue, softgl::Float(1.0f));
  }
};

// kOutputs, in the wide form: four colour outputs.
struct OutputsVaryings {
  softgl::vec4 color;
  softgl::vec4 extra;
};
struct OutputsShader : softgl::Shader<OutputsShader, OutputsVaryings> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<OutputsVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.varyings.extra = in.attrib[2];
  }
  void Fragment(const softgl::FragmentLanes<OutputsVaryings>& in, softgl::FragmentLanesOut& out) const {
    const softgl::vec4& c = in.varyings.color;
    const softgl::vec4& e = in.varyings.extra;
    out.color[0] = c;
    out.color[1] = softgl::vec4(e.x, e.y, softgl::Float(0.5f), c.w);
    out.color[2] = c * 2.0f - 0.5f;
    out.color[3] = softgl::vec4(e.z, e.w, c.y, c.w);
  }
};

// The instanced program, in the wide form (gl_InstanceID is an Int lane).
struct InstancedVaryings {
  softgl::vec4 color;
};

struct InstancedShader : softgl::Shader<InstancedShader, InstancedVaryings> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<InstancedVaryings>& out) const {
    out.position = in.attrib[0] + softgl::vec4(in.attrib[3].x, in.attrib[3].y, 0.0f, 0.0f);
    const softgl::Float k = softgl::Float(in.instance_id % 8);
    out.varyings.color = in.attrib[1] * softgl::vec4(softgl::vec3(1.0f - 0.125f * k), 1.0f);
  }
  void Fragment(const softgl::FragmentLanes<InstancedVaryings>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};

// The integer program: colour = vec4(a & 255) / 255 of integer attribute 3.
struct IntegerShader : softgl::Shader<IntegerShader, InstancedVaryings> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<InstancedVaryings>& out) const {
    out.position = in.attrib[0];
    const auto byte = [&](int c) { return softgl::Float(in.AttribI(3, c) & 255) / 255.0f; };
    out.varyings.color = softgl::vec4(byte(0), byte(1), byte(2), byte(3));
  }
  void Fragment(const softgl::FragmentLanes<InstancedVaryings>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};

struct FeedbackVaryings {
  glm::vec4 color;
  glm::vec4 extra;
};

// kFeedback: what transform feedback records (extra = attribute 2 * 2 - position).
struct FeedbackShader : softgl::Shader<FeedbackShader, FeedbackVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<FeedbackVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.varyings.extra = in.attrib[2] * 2.0f - in.attrib[0];
  }
  bool Fragment(const softgl::FragmentIn<FeedbackVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.color;
    return true;
  }
};

// kLayer: gl_Layer from attribute 2's w.
struct LayerShader : softgl::Shader<LayerShader, InstancedVaryings> {
  static constexpr bool kWritesLayer = true;
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<InstancedVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.layer = softgl::Int(in.attrib[2].w);
  }
  void Fragment(const softgl::FragmentLanes<InstancedVaryings>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};

// The programs with a geometry stage: the vertex stage passes colour and extra on; the fragment stage writes the
// colour the geometry stage emitted.
struct GeometryIn {
  softgl::vec4 color;
  softgl::vec4 extra;
};
struct GeometryOut {
  softgl::vec4 color;
};
template <class Derived>
struct GeometryProgram : softgl::Shader<Derived, GeometryIn, GeometryOut> {
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<GeometryIn>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
    out.varyings.extra = in.attrib[2];
  }
  void Fragment(const softgl::FragmentLanes<GeometryOut>& in, softgl::FragmentLanesOut& out) const {
    out.color[0] = in.varyings.color;
  }
};
using GeometryLanes = softgl::GeometryLanes<GeometryIn>;
using GeometryLanesOut = softgl::GeometryLanesOut<GeometryOut>;

// kGeometryShrink.
struct ShrinkShader : GeometryProgram<ShrinkShader> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::TRIANGLE_STRIP, 6, 2};
  void Geometry(const GeometryLanes& in, GeometryLanesOut& out) const {
    using namespace softgl;
    const Bool first = in.invocation_id == Int(0);
    const Float s = select(first, Float(0.5f), Float(0.25f));
    const Float tint = Float(in.primitive_id & Int(3)) * 0.2f;
    const vec4& p0 = in.vertex[0].position;
    for (int k = 0; k < 3; ++k) {
      out.position = p0 + (in.vertex[k].position - p0) * s;
      const vec4& c = in.vertex[k].varyings.color;
      out.varyings.color = select(first, c, vec4(tint, 1.0f - tint, c.z, 1.0f));
      out.EmitVertex();
    }
    out.EndPrimitive();
    const Bool second = (!first) & ((in.primitive_id & Int(1)) == Int(0));
    const vec4& p = in.vertex[2].position;
    for (int k = 0; k < 3; ++k) {
      out.position = p + vec4(k == 1 ? 0.125f : 0.0f, k == 2 ? 0.125f : 0.0f, 0.0f, 0.0f) * p.w;
      out.varyings.color = vec4(1.0f, 1.0f, 0.0f, 1.0f);
      out.EmitVertex(second);
    }
  }
};

// kGeometrySprites.
struct SpritesShader : GeometryProgram<SpritesShader> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::POINTS, softgl::TRIANGLE_STRIP, 8};
  void Geometry(const GeometryLanes& in, GeometryLanesOut& out) const {
    using namespace softgl;
    const vec4& p = in.vertex[0].position;
    const Float d = in.vertex[0].varyings.extra.x;
    const vec4& c = in.vertex[0].varyings.color;
    for (int k = 0; k < 4; ++k) {
      out.position = p + vec4((k & 1) ? d : -d, (k & 2) ? d : -d, Float(0.0f), Float(0.0f)) * p.w;
      out.varyings.color = c;
      out.EmitVertex();
    }
    const Bool twice = in.vertex[0].varyings.extra.y > 0.5f;
    out.EndPrimitive(twice);
    for (int k = 0; k < 4; ++k) {
      out.position = p + vec4(2.0f * d + ((k & 1) ? d : Float(0.0f)), (k & 2) ? d * 0.5f : -d * 0.5f, Float(0.0f),
                              Float(0.0f)) * p.w;
      out.varyings.color = vec4(1.0f - c.x, 1.0f - c.y, 1.0f - c.z, Float(1.0f));
      out.EmitVertex(twice);
    }
  }
};

// kGeometryAdjacency.
struct AdjacencyShader : GeometryProgram<AdjacencyShader> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES_ADJACENCY, softgl::TRIANGLE_STRIP, 3};
  void Geometry(const GeometryLanes& in, GeometryLanesOut& out) const {
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[2 * k].position;
      out.varyings.color = in.vertex[2 * k + 1].varyings.color;
      out.EmitVertex();
    }
  }
};

// kGeometryLineAdjacency.
struct LineAdjacencyShader : GeometryProgram<LineAdjacencyShader> {
  static constexpr softgl::GeometryLayout kGeometry{softgl::LINES_ADJACENCY, softgl::LINE_STRIP, 2};
  void Geometry(const GeometryLanes& in, GeometryLanesOut& out) const {
    for (int k = 0; k < 2; ++k) {
      out.position = in.vertex[1 + k].position;
      out.varyings.color = in.vertex[3 * k].varyings.color;
      out.EmitVertex();
    }
  }
};

// kGeometryLayer.
struct GeometryLayerShader : GeometryProgram<GeometryLayerShader> {
  static constexpr bool kWritesLayer = true;
  static constexpr softgl::GeometryLayout kGeometry{softgl::TRIANGLES, softgl::TRIANGLE_STRIP, 3, 3};
  void Geometry(const GeometryLanes& in, GeometryLanesOut& out) const {
    using namespace softgl;
    const Float scale = 1.0f - Float(in.invocation_id) * 0.25f;
    for (int k = 0; k < 3; ++k) {
      const vec4& c = in.vertex[k].varyings.color;
      out.position = in.vertex[k].position;
      out.varyings.color = vec4(c.x * scale, c.y * scale, c.z * scale, c.w);
      out.layer = Int(in.vertex[2].varyings.extra.w) + in.invocation_id;
      out.EmitVertex();
    }
  }
};

class SoftglBackend final : public Backend {
 public:
  SoftglBackend(int w, int h) : gl_(w, h), w_(w), h_(h) {
    volume_.target = softgl::TEXTURE_3D;
    texture_1d_.target = softgl::TEXTURE_1D;
    texture_1d_array_.target = softgl::TEXTURE_1D_ARRAY;
    array_shadow_.shadow = true;
    vao_ = gl_.GenVertexArray();
    vbo_ = gl_.GenBuffer();
    ebo_ = gl_.GenBuffer();
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(softgl::ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, ebo_);
    for (std::uint32_t i = 0; i < 3; ++i) {
      gl_.VertexAttributePointer(i, 4, softgl::FLOAT, false, sizeof(Vertex), i * sizeof(glm::vec4));
      gl_.EnableVertexAttribArray(i);
    }
  }
  std::string Name() const override { return "softgl"; }
  void Enable(Enum cap) override { gl_.Enable(cap); }
  void Disable(Enum cap) override { gl_.Disable(cap); }
  void Viewport(int x, int y, int w, int h) override { gl_.Viewport(x, y, w, h); }
  void DepthRange(double n, double f) override { gl_.DepthRange(n, f); }
  void CullFace(Enum mode) override { gl_.CullFace(mode); }
  void FrontFace(Enum mode) override { gl_.FrontFace(mode); }
  void PolygonMode(Enum mode) override { gl_.PolygonMode(softgl::FRONT_AND_BACK, mode); }
  void PointSize(float size) override { gl_.PointSize(size); }
  void LineWidth(float width) override { gl_.LineWidth(width); }
  void PointParameteri(Enum pname, int value) override { gl_.PointParameteri(pname, value); }
  void ColorMaski(std::uint32_t index, bool r, bool g, bool b, bool a) override { gl_.ColorMaski(index, r, g, b, a); }
  void Enablei(Enum cap, std::uint32_t index) override { gl_.Enablei(cap, index); }
  void Disablei(Enum cap, std::uint32_t index) override { gl_.Disablei(cap, index); }
  std::vector<bool> GetBooleansI(Enum target, std::uint32_t index, int count) override {
    bool v[4] = {true, true, true, true};
    gl_.GetBooleani_v(target, index, v);
    return std::vector<bool>(v, v + count);
  }
  std::vector<std::int64_t> GetIntegersI(Enum target, std::uint32_t index, int count) override {
    int v[4] = {-7, -7, -7, -7};
    gl_.GetIntegeri_v(target, index, v);
    return std::vector<std::int64_t>(v, v + count);
  }
  bool IsEnabledi(Enum cap, std::uint32_t index) override { return gl_.IsEnabledi(cap, index); }
  void DepthFunc(Enum func) override { gl_.DepthFunc(func); }
  void DepthMask(bool flag) override { gl_.DepthMask(flag); }
  void PolygonOffset(float factor, float units) override { gl_.PolygonOffset(factor, units); }
  void Scissor(int x, int y, int w, int h) override { gl_.Scissor(x, y, w, h); }
  void PrimitiveRestartIndex(std::uint32_t index) override { gl_.PrimitiveRestartIndex(index); }
  void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) override {
    gl_.StencilFuncSeparate(face, func, ref, mask);
  }
  void StencilOpSeparate(Enum face, Enum a, Enum b, Enum c) override { gl_.StencilOpSeparate(face, a, b, c); }
  void StencilMaskSeparate(Enum face, std::uint32_t mask) override { gl_.StencilMaskSeparate(face, mask); }
  void BlendFuncSeparate(Enum a, Enum b, Enum c, Enum d) override { gl_.BlendFuncSeparate(a, b, c, d); }
  void BlendEquationSeparate(Enum rgb, Enum alpha) override { gl_.BlendEquationSeparate(rgb, alpha); }
  void BlendColor(float r, float g, float b, float a) override { gl_.BlendColor(r, g, b, a); }
  void LogicOp(Enum op) override { gl_.LogicOp(op); }
  void ClearBufferfv(Enum buffer, int drawbuffer, const float* value) override { gl_.ClearBufferfv(buffer, drawbuffer, value); }
  void ClearBufferiv(Enum buffer, int drawbuffer, const int* value) override { gl_.ClearBufferiv(buffer, drawbuffer, value); }
  void ClearBufferfi(Enum buffer, int drawbuffer, float depth, int stencil) override {
    gl_.ClearBufferfi(buffer, drawbuffer, depth, stencil);
  }
  void ColorMask(bool r, bool g, bool b, bool a) override { gl_.ColorMask(r, g, b, a); }
  void ClearColor(float r, float g, float b, float a) override { gl_.ClearColor(r, g, b, a); }
  void ClearDepth(double d) override { gl_.ClearDepth(d); }
  void ClearStencil(int s) override { gl_.ClearStencil(s); }
  void Clear(std::uint32_t mask) override { gl_.Clear(mask); }

  void Draw(Enum mode, const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
            Program program, const Uniforms& uniforms) override {
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(Vertex)), vertices.data());
    lit_.u = uniforms;
    switch (program) {
      case Program::kColor: gl_.UseProgram(color_); break;
      case Program::kUv: gl_.UseProgram(uv_); break;
      case Program::kLit: gl_.UseProgram(lit_); break;
      case Program::kTexture: gl_.UseProgram(texture_); break;
      case Program::kCube: gl_.UseProgram(cube_); break;
      case Program::kShadow: gl_.UseProgram(shadow_); break;
      case Program::kArray: gl_.UseProgram(array_); break;
      case Program::kVolume: gl_.UseProgram(volume_); break;
      case Program::kTexture1D: gl_.UseProgram(texture_1d_); break;
      case Program::kTexture1DArray: gl_.UseProgram(texture_1d_array_); break;
      case Program::kArrayShadow: gl_.UseProgram(array_shadow_); break;
      case Program::kFetchSample: gl_.UseProgram(fetch_sample_); break;
      case Program::kTextureBuffer: gl_.UseProgram(texture_buffer_); break;
      case Program::kFetchSampleArray: gl_.UseProgram(fetch_sample_array_); break;
      case Program::kOutputs: gl_.UseProgram(outputs_); break;
      case Program::kPointCoord: gl_.UseProgram(point_coord_); break;
      case Program::kLayer: gl_.UseProgram(layer_); break;
      case Program::kGeometryShrink: gl_.UseProgram(shrink_); break;
      case Program::kGeometrySprites: gl_.UseProgram(sprites_); break;
      case Program::kGeometryAdjacency: gl_.UseProgram(adjacency_); break;
      case Program::kGeometryLineAdjacency: gl_.UseProgram(line_adjacency_); break;
      case Program::kGeometryLayer: gl_.UseProgram(geometry_layer_); break;
      case Program::kFeedback:  // (UseProgram is an error while transform feedback records, even of the same one)
        if (!Recording()) gl_.UseProgram(feedback_);
        break;
    }
    if (indices.empty()) {
      gl_.DrawArrays(mode, 0, int(vertices.size()));
    } else {
      gl_.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * sizeof(std::uint32_t)),
                     indices.data());
      gl_.DrawElement(mode, int(indices.size()), softgl::UNSIGNED_INT, 0);
    }
  }

  void DrawVariants(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                    const std::vector<DrawVariant>& calls) override {
    gl_.UseProgram(color_);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(Vertex)), vertices.data());
    gl_.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * sizeof(std::uint32_t)),
                   indices.data());
    auto at = [](int first) { return std::size_t(first) * sizeof(std::uint32_t); };
    for (const DrawVariant& c : calls) {
      switch (c.call) {
        case DrawVariant::Call::kElementsBaseVertex:
          gl_.DrawElementsBaseVertex(c.mode, c.count[0], softgl::UNSIGNED_INT, at(c.first[0]), c.basevertex);
          break;
        case DrawVariant::Call::kRangeElements:
          gl_.DrawRangeElements(c.mode, c.start, c.end, c.count[0], softgl::UNSIGNED_INT, at(c.first[0]));
          break;
        case DrawVariant::Call::kMultiElements: {
          std::vector<std::size_t> offsets;
          for (int f : c.first) offsets.push_back(at(f));
          gl_.MultiDrawElements(c.mode, c.count.data(), softgl::UNSIGNED_INT, offsets.data(), int(c.count.size()));
          break;
        }
        case DrawVariant::Call::kMultiArrays:
          gl_.MultiDrawArrays(c.mode, c.first.data(), c.count.data(), int(c.count.size()));
          break;
        default: break;  // the instanced calls: DrawInstanced
      }
    }
  }

  void DrawInstanced(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                     const std::vector<glm::vec4>& instance_data, const std::vector<DrawVariant>& calls) override {
    gl_.UseProgram(instanced_);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(Vertex)), vertices.data());
    gl_.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * sizeof(std::uint32_t)),
                   indices.data());
    const std::uint32_t instance_vbo = gl_.GenBuffer();
    gl_.BindBuffer(softgl::ARRAY_BUFFER, instance_vbo);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(instance_data.size() * sizeof(glm::vec4)),
                   instance_data.data());
    gl_.EnableVertexAttribArray(3);
    auto at = [](int first) { return std::size_t(first) * sizeof(std::uint32_t); };
    for (const DrawVariant& c : calls) {
      gl_.VertexAttributePointer(3, 4, softgl::FLOAT, false, 0, std::size_t(c.instance_first) * sizeof(glm::vec4));
      gl_.VertexAttribDivisor(3, c.divisor);
      switch (c.call) {
        case DrawVariant::Call::kArraysInstanced:
          gl_.DrawArraysInstanced(c.mode, c.first[0], c.count[0], c.instances);
          break;
        case DrawVariant::Call::kElementsInstanced:
          gl_.DrawElementsInstanced(c.mode, c.count[0], softgl::UNSIGNED_INT, at(c.first[0]), c.instances);
          break;
        case DrawVariant::Call::kElementsInstancedBaseVertex:
          gl_.DrawElementsInstancedBaseVertex(c.mode, c.count[0], softgl::UNSIGNED_INT, at(c.first[0]), c.instances,
                                              c.basevertex);
          break;
        default: break;
      }
    }
    gl_.DisableVertexAttribArray(3);
    gl_.VertexAttribDivisor(3, 0);
    gl_.BindBuffer(softgl::ARRAY_BUFFER, vbo_);
    gl_.DeleteBuffer(instance_vbo);
  }

  int DrawIntegerAttribs(const std::vector<Vertex>& vertices, int size, Enum type, int stride,
                         const std::vector<std::uint8_t>& bytes, glm::ivec4 current) override {
    gl_.UseProgram(integer_);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(Vertex)), vertices.data());
    const std::uint32_t ints = gl_.GenBuffer();
    gl_.BindBuffer(softgl::ARRAY_BUFFER, ints);
    if (bytes.empty()) {
      gl_.DisableVertexAttribArray(3);
      gl_.VertexAttribI4i(3, current.x, current.y, current.z, current.w);
    } else {
      gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(bytes.size()), bytes.data());
      gl_.VertexAttribIPointer(3, size, type, stride, 0);
      gl_.EnableVertexAttribArray(3);
    }
    int integer = -1;
    gl_.GetVertexAttribiv(3, softgl::VERTEX_ATTRIB_ARRAY_INTEGER, &integer);
    gl_.DrawArrays(softgl::POINTS, 0, int(vertices.size()));
    gl_.DisableVertexAttribArray(3);
    gl_.VertexAttributePointer(3, 4, softgl::FLOAT, false, 0, 0);
    gl_.BindBuffer(softgl::ARRAY_BUFFER, vbo_);
    gl_.DeleteBuffer(ints);
    return integer;
  }

  void DrawIntegerTarget(Enum format, int w, int h, const glm::ivec4& clear, const std::vector<IntegerDraw>& draws,
                         Enum wrap, const glm::ivec4& border, const std::vector<Vertex>& quad) override {
    const bool is_signed = IsSignedInteger(format);
    const std::uint32_t tex = gl_.GenTexture(), fbo = gl_.GenFramebuffer();
    gl_.ActiveTexture(softgl::TEXTURE0);
    gl_.BindTexture(softgl::TEXTURE_2D, tex);
    gl_.TexImage2D(softgl::TEXTURE_2D, 0, format, w, h, 0, softgl::RGBA_INTEGER, softgl::INT, nullptr);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, softgl::NEAREST);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, int(wrap));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, int(wrap));
    gl_.TexParameterIiv(softgl::TEXTURE_2D, softgl::TEXTURE_BORDER_COLOR, &border.x);
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
    gl_.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, tex, 0);
    gl_.Viewport(0, 0, w, h);
    if (is_signed) gl_.ClearBufferiv(softgl::COLOR, 0, &clear.x);
    else gl_.ClearBufferuiv(softgl::COLOR, 0, reinterpret_cast<const std::uint32_t*>(&clear.x));
    integer_output_.is_unsigned = !is_signed;
    gl_.UseProgram(integer_output_);
    for (const IntegerDraw& d : draws) {
      if (d.logic) {
        gl_.Enable(softgl::COLOR_LOGIC_OP);
        gl_.LogicOp(d.logic);
      }
      gl_.ColorMask(d.mask & 1u, (d.mask >> 1) & 1u, (d.mask >> 2) & 1u, (d.mask >> 3) & 1u);
      gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(d.triangles.size() * sizeof(Vertex)), d.triangles.data());
      gl_.DrawArrays(softgl::TRIANGLES, 0, int(d.triangles.size()));
      gl_.Disable(softgl::COLOR_LOGIC_OP);
      gl_.ColorMask(true, true, true, true);
    }
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, 0);
    gl_.Viewport(0, 0, w_, h_);
    gl_.UseProgram(integer_texture_);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(quad.size() * sizeof(Vertex)), quad.data());
    gl_.DrawArrays(softgl::TRIANGLES, 0, int(quad.size()));
    gl_.DeleteFramebuffer(fbo);
    gl_.DeleteTexture(tex);
  }

  std::vector<Vertex> DrawThroughBufferCalls(Enum mode, const std::vector<Vertex>& vertices, int mapped) override {
    const std::ptrdiff_t size = std::ptrdiff_t(vertices.size() * sizeof(Vertex)), head = mapped * std::ptrdiff_t(sizeof(Vertex));
    gl_.UseProgram(color_);
    gl_.BufferData(softgl::ARRAY_BUFFER, size, nullptr, softgl::DYNAMIC_DRAW);
    void* p = gl_.MapBufferRange(softgl::ARRAY_BUFFER, 0, head,
                                 softgl::MAP_WRITE_BIT | softgl::MAP_INVALIDATE_RANGE_BIT | softgl::MAP_FLUSH_EXPLICIT_BIT);
    if (p != nullptr) std::memcpy(p, vertices.data(), std::size_t(head));
    gl_.FlushMappedBufferRange(softgl::ARRAY_BUFFER, 0, head);
    gl_.UnmapBuffer(softgl::ARRAY_BUFFER);
    const std::uint32_t staging = gl_.GenBuffer();
    gl_.BindBuffer(softgl::COPY_READ_BUFFER, staging);
    gl_.BufferData(softgl::COPY_READ_BUFFER, size - head, vertices.data() + mapped, softgl::STREAM_COPY);
    gl_.CopyBufferSubData(softgl::COPY_READ_BUFFER, softgl::ARRAY_BUFFER, 0, head, size - head);
    gl_.DeleteBuffer(staging);
    int stored = 0;
    gl_.GetBufferParameteriv(softgl::ARRAY_BUFFER, softgl::BUFFER_SIZE, &stored);
    gl_.DrawArrays(mode, 0, stored / int(sizeof(Vertex)));
    std::vector<Vertex> back(std::size_t(stored) / sizeof(Vertex));
    gl_.GetBufferSubData(softgl::ARRAY_BUFFER, 0, std::ptrdiff_t(back.size() * sizeof(Vertex)), back.data());
    return back;
  }

  void SetTexture(const TextureDesc& d) override {
    const std::uint32_t tex = gl_.GenTexture();
    gl_.BindTexture(softgl::TEXTURE_2D, tex);
    gl_.PixelStore(softgl::UNPACK_ALIGNMENT, 1);
    for (std::size_t l = 0; l < d.levels.size(); ++l)
      if (d.compressed)
        gl_.CompressedTexImage2D(softgl::TEXTURE_2D, int(l), d.compressed, d.levels[l].width, d.levels[l].height, 0,
                                 int(d.levels[l].blocks.size()), d.levels[l].blocks.data());
      else
      gl_.TexImage2D(softgl::TEXTURE_2D, int(l), d.internal_format, d.levels[l].width, d.levels[l].height, 0, softgl::RGBA,
                     d.type, d.type == softgl::UNSIGNED_BYTE ? static_cast<const void*>(d.levels[l].rgba.data())
                                                             : static_cast<const void*>(d.levels[l].shorts.data()));
    if (d.generate_mipmap) gl_.GenerateMipmap(softgl::TEXTURE_2D);
    else gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_LEVEL, int(d.levels.size()) - 1);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, int(d.min_filter));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, int(d.mag_filter));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, int(d.wrap_s));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, int(d.wrap_t));
    gl_.TexParameterfv(softgl::TEXTURE_2D, softgl::TEXTURE_BORDER_COLOR, &d.border[0]);
    if (d.max_anisotropy != 1.0f) gl_.TexParameterf(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_ANISOTROPY, d.max_anisotropy);
  }

  void BindNewTexture(Enum target) override { gl_.BindTexture(target, gl_.GenTexture()); }

  std::uint32_t NewBufferTexture(Enum internal_format, const std::vector<std::uint8_t>& bytes) override {
    gl_.BindTexture(softgl::TEXTURE_BUFFER, gl_.GenTexture());
    const std::uint32_t buffer = gl_.GenBuffer();
    gl_.BindBuffer(softgl::TEXTURE_BUFFER, buffer);
    gl_.BufferData(softgl::TEXTURE_BUFFER, std::ptrdiff_t(bytes.size()), bytes.data());
    gl_.TexBuffer(softgl::TEXTURE_BUFFER, internal_format, buffer);
    return buffer;
  }

  void BufferSubDataTexture(std::uint32_t buffer, int offset, const std::vector<std::uint8_t>& bytes) override {
    gl_.BindBuffer(softgl::TEXTURE_BUFFER, buffer);
    gl_.BufferSubData(softgl::TEXTURE_BUFFER, offset, std::ptrdiff_t(bytes.size()), bytes.data());
  }

  void TexBuffer(Enum target, Enum internal_format, std::uint32_t buffer) override {
    gl_.TexBuffer(target, internal_format, buffer);
  }

  void DeleteBuffer(std::uint32_t buffer) override { gl_.DeleteBuffer(buffer); }

  void CompressedTexImage(int dims, Enum target, int level, Enum format, int w, int h, int d, int image_size,
                          const void* data) override {
    if (dims == 1) gl_.CompressedTexImage1D(target, level, format, w, 0, image_size, data);
    else if (dims == 2) gl_.CompressedTexImage2D(target, level, format, w, h, 0, image_size, data);
    else gl_.CompressedTexImage3D(target, level, format, w, h, d, 0, image_size, data);
  }

  void CompressedTexSubImage(int dims, Enum target, int level, int x, int y, int z, int w, int h, int d, Enum format,
                             int image_size, const void* data) override {
    if (dims == 1) gl_.CompressedTexSubImage1D(target, level, x, w, format, image_size, data);
    else if (dims == 2) gl_.CompressedTexSubImage2D(target, level, x, y, w, h, format, image_size, data);
    else gl_.CompressedTexSubImage3D(target, level, x, y, z, w, h, d, format, image_size, data);
  }

  std::vector<std::uint8_t> GetCompressedTexImage(Enum target, int level, int bytes) override {
    std::vector<std::uint8_t> out(std::size_t(bytes), 0xCD);
    gl_.GetCompressedTexImage(target, level, out.data());
    return out;
  }

  std::vector<float> GetTexImageFloats(Enum target, int level, int floats) override {
    std::vector<float> out(std::size_t(floats), -9.0f);
    gl_.PixelStore(softgl::PACK_ALIGNMENT, 4);
    gl_.GetTexImage(target, level, softgl::RGBA, softgl::FLOAT, out.data());
    return out;
  }

  int GetTexLevelParameter(Enum target, int level, Enum pname) override {
    int v = -1;
    gl_.GetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }

  void TexImage2D(Enum target, int level, Enum internal_format, int w, int h) override {
    gl_.TexImage2D(target, level, internal_format, w, h, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  }

  void TexSubImage2D(Enum target, int level, int x, int y, int w, int h, const std::uint8_t* rgba) override {
    gl_.PixelStore(softgl::UNPACK_ALIGNMENT, 1);
    gl_.TexSubImage2D(target, level, x, y, w, h, softgl::RGBA, softgl::UNSIGNED_BYTE, rgba);
  }

  void GenerateMipmap(Enum target) override { gl_.GenerateMipmap(target); }

  void SetCubeTexture(int size, const std::vector<std::uint8_t> faces[6]) override {
    gl_.ActiveTexture(softgl::TEXTURE0 + 1);
    gl_.BindTexture(softgl::TEXTURE_CUBE_MAP, gl_.GenTexture());
    gl_.PixelStore(softgl::UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f)
      gl_.TexImage2D(softgl::TEXTURE_CUBE_MAP_POSITIVE_X + softgl::Enum(f), 0, softgl::RGBA8, size, size, 0,
                     softgl::RGBA, softgl::UNSIGNED_BYTE, faces[f].data());
    gl_.GenerateMipmap(softgl::TEXTURE_CUBE_MAP);
    gl_.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
    gl_.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
    gl_.TexParameteri(softgl::TEXTURE_CUBE_MAP, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);
    gl_.ActiveTexture(softgl::TEXTURE0);
  }

  void SetShadowTexture(int size, const std::vector<float>& depth, Enum func, Enum filter) override {
    gl_.ActiveTexture(softgl::TEXTURE0 + 2);
    gl_.BindTexture(softgl::TEXTURE_2D, gl_.GenTexture());
    gl_.TexImage2D(softgl::TEXTURE_2D, 0, softgl::DEPTH_COMPONENT, size, size, 0, softgl::DEPTH_COMPONENT,
                   softgl::FLOAT, depth.data());
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, int(filter));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, int(filter));
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_COMPARE_MODE, softgl::COMPARE_REF_TO_TEXTURE);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_COMPARE_FUNC, int(func));
    gl_.ActiveTexture(softgl::TEXTURE0);
  }

  void SetLayeredTexture(const LayeredDesc& d) override {
    const bool depth = !d.depth.empty();
    const bool one_d = d.target == softgl::TEXTURE_1D || d.target == softgl::TEXTURE_1D_ARRAY;
    gl_.ActiveTexture(softgl::TEXTURE0 + (one_d ? 7 : depth ? 5 : d.target == softgl::TEXTURE_3D ? 4 : 3));
    gl_.BindTexture(d.target, gl_.GenTexture());
    gl_.PixelStore(softgl::UNPACK_ALIGNMENT, 1);
    if (d.target == softgl::TEXTURE_1D)
      gl_.TexImage1D(d.target, 0, softgl::RGBA8, d.width, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, d.rgba.data());
    else if (d.target == softgl::TEXTURE_1D_ARRAY)
      gl_.TexImage2D(d.target, 0, softgl::RGBA8, d.width, d.depth_or_layers, 0, softgl::RGBA, softgl::UNSIGNED_BYTE,
                     d.rgba.data());
    else if (depth)
      gl_.TexImage3D(d.target, 0, softgl::DEPTH_COMPONENT32F, d.width, d.height, d.depth_or_layers, 0,
                     softgl::DEPTH_COMPONENT, softgl::FLOAT, d.depth.data());
    else
      gl_.TexImage3D(d.target, 0, softgl::RGBA8, d.width, d.height, d.depth_or_layers, 0, softgl::RGBA,
                     softgl::UNSIGNED_BYTE, d.rgba.data());
    if (d.generate_mipmap) gl_.GenerateMipmap(d.target);
    gl_.TexParameteri(d.target, softgl::TEXTURE_MIN_FILTER, int(d.min_filter));
    gl_.TexParameteri(d.target, softgl::TEXTURE_MAG_FILTER, int(d.mag_filter));
    gl_.TexParameteri(d.target, softgl::TEXTURE_WRAP_S, int(d.wrap_s));
    gl_.TexParameteri(d.target, softgl::TEXTURE_WRAP_T, int(d.wrap_t));
    gl_.TexParameteri(d.target, softgl::TEXTURE_WRAP_R, int(d.wrap_r));
    if (depth) {
      gl_.TexParameteri(d.target, softgl::TEXTURE_COMPARE_MODE, softgl::COMPARE_REF_TO_TEXTURE);
      gl_.TexParameteri(d.target, softgl::TEXTURE_COMPARE_FUNC, int(d.compare_func));
    }
    gl_.ActiveTexture(softgl::TEXTURE0);
  }

  void BeginRenderToTexture(int width, int height) override {
    rtt_color_ = gl_.GenTexture();
    const std::uint32_t depth = gl_.GenTexture(), fbo = gl_.GenFramebuffer();
    gl_.BindTexture(softgl::TEXTURE_2D, rtt_color_);
    gl_.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, width, height, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
    gl_.BindTexture(softgl::TEXTURE_2D, depth);
    gl_.TexImage2D(softgl::TEXTURE_2D, 0, softgl::DEPTH_COMPONENT, width, height, 0, softgl::DEPTH_COMPONENT,
                   softgl::FLOAT, nullptr);
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
    gl_.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, rtt_color_, 0);
    gl_.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::TEXTURE_2D, depth, 0);
    gl_.Viewport(0, 0, width, height);
  }

  void EndRenderToTexture() override {
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, 0);
    gl_.Viewport(0, 0, gl_.Width(), gl_.Height());
    gl_.BindTexture(softgl::TEXTURE_2D, rtt_color_);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR);
  }

  std::uint32_t GenFramebuffer() override { return gl_.GenFramebuffer(); }
  void BindFramebuffer(Enum target, std::uint32_t framebuffer) override { gl_.BindFramebuffer(target, framebuffer); }
  Enum CheckFramebufferStatus(Enum target) override { return gl_.CheckFramebufferStatus(target); }
  std::uint32_t GenRenderbuffer() override { return gl_.GenRenderbuffer(); }
  void BindRenderbuffer(std::uint32_t renderbuffer) override { gl_.BindRenderbuffer(softgl::RENDERBUFFER, renderbuffer); }
  void RenderbufferStorage(Enum internal_format, int width, int height) override {
    gl_.RenderbufferStorage(softgl::RENDERBUFFER, internal_format, width, height);
  }
  void RenderbufferStorageMultisample(int samples, Enum internal_format, int width, int height) override {
    gl_.RenderbufferStorageMultisample(softgl::RENDERBUFFER, samples, internal_format, width, height);
  }
  void SampleMask(std::uint32_t mask) override { gl_.SampleMaski(0, mask); }
  void MinSampleShading(float value) override { gl_.MinSampleShading(value); }
  void SampleCoverage(float value, bool invert) override { gl_.SampleCoverage(value, invert); }
  void FramebufferRenderbuffer(Enum target, Enum attachment, std::uint32_t renderbuffer) override {
    gl_.FramebufferRenderbuffer(target, attachment, softgl::RENDERBUFFER, renderbuffer);
  }
  void ReadBuffer(Enum src) override { gl_.ReadBuffer(src); }
  void DrawBuffers(int n, const Enum* bufs) override { gl_.DrawBuffers(n, bufs); }
  void BlitFramebuffer(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, std::uint32_t mask,
                       Enum filter) override {
    gl_.BlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
  }
  void AttachNewMultisampleTexture(Enum target, Enum attachment, int samples, Enum internal_format, int width,
                                   int height) override {
    const std::uint32_t tex = gl_.GenTexture();
    gl_.ActiveTexture(softgl::TEXTURE0 + 6);
    gl_.BindTexture(softgl::TEXTURE_2D_MULTISAMPLE, tex);
    gl_.TexImage2DMultisample(softgl::TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, true);
    gl_.ActiveTexture(softgl::TEXTURE0);
    gl_.FramebufferTexture2D(target, attachment, softgl::TEXTURE_2D_MULTISAMPLE, tex, 0);
  }

  void AttachNewTexture(Enum target, Enum attachment, Enum internal_format, int width, int height) override {
    const std::uint32_t tex = gl_.GenTexture();
    gl_.BindTexture(softgl::TEXTURE_2D, tex);
    const bool ds = internal_format == softgl::DEPTH24_STENCIL8 || internal_format == softgl::DEPTH32F_STENCIL8;
    const bool depth = softgl::DEPTH_COMPONENT24 == internal_format || softgl::DEPTH_COMPONENT32F == internal_format;
    const Enum format = ds ? softgl::DEPTH_STENCIL : depth ? softgl::DEPTH_COMPONENT : softgl::RGBA;
    const Enum type = internal_format == softgl::DEPTH32F_STENCIL8 ? softgl::FLOAT_32_UNSIGNED_INT_24_8_REV
                      : ds                                          ? softgl::UNSIGNED_INT_24_8
                      : depth                                       ? softgl::FLOAT
                                                                    : softgl::UNSIGNED_BYTE;
    gl_.TexImage2D(softgl::TEXTURE_2D, 0, internal_format, width, height, 0, format, type, nullptr);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
    gl_.FramebufferTexture2D(target, attachment, softgl::TEXTURE_2D, tex, 0);
  }

  std::uint32_t AttachLayered(Enum target, Enum attachment, Enum texture_target, Enum internal_format, int size,
                              int layers, int layer) override {
    const std::uint32_t tex = gl_.GenTexture();
    const bool depth = internal_format == softgl::DEPTH_COMPONENT32F;
    gl_.ActiveTexture(softgl::TEXTURE0 + (depth ? 7 : texture_target == softgl::TEXTURE_2D_ARRAY ? 3 : texture_target == softgl::TEXTURE_3D ? 4 : 1));
    gl_.BindTexture(texture_target, tex);
    const Enum format = depth ? softgl::DEPTH_COMPONENT : softgl::RGBA, type = depth ? softgl::FLOAT : softgl::UNSIGNED_BYTE;
    if (texture_target == softgl::TEXTURE_CUBE_MAP)
      for (int f = 0; f < layers; ++f)
        gl_.TexImage2D(softgl::TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, internal_format, size, size, 0, format, type, nullptr);
    else
      gl_.TexImage3D(texture_target, 0, internal_format, size, size, layers, 0, format, type, nullptr);
    gl_.TexParameteri(texture_target, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
    gl_.TexParameteri(texture_target, softgl::TEXTURE_MAG_FILTER, softgl::NEAREST);
    gl_.ActiveTexture(softgl::TEXTURE0);
    if (layer < 0) gl_.FramebufferTexture(target, attachment, tex, 0);
    else if (texture_target == softgl::TEXTURE_3D) gl_.FramebufferTexture3D(target, attachment, softgl::TEXTURE_3D, tex, 0, layer);
    else gl_.FramebufferTextureLayer(target, attachment, tex, 0, layer);
    return tex;
  }
  void FramebufferTexture(Enum target, Enum attachment, std::uint32_t texture, int level) override {
    gl_.FramebufferTexture(target, attachment, texture, level);
  }
  std::uint32_t NewMultisampleArray(int samples, Enum internal_format, int width, int height, int layers) override {
    const std::uint32_t tex = gl_.GenTexture();
    gl_.ActiveTexture(softgl::TEXTURE0 + 6);
    gl_.BindTexture(softgl::TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
    gl_.TexImage3DMultisample(softgl::TEXTURE_2D_MULTISAMPLE_ARRAY, samples, internal_format, width, height, layers, true);
    gl_.ActiveTexture(softgl::TEXTURE0);
    return tex;
  }
  void TexImage3DMultisample(Enum target, int samples, Enum internal_format, int width, int height,
                             int layers) override {
    gl_.TexImage3DMultisample(target, samples, internal_format, width, height, layers, true);
  }
  void FramebufferTextureLayer(Enum target, Enum attachment, std::uint32_t texture, int level, int layer) override {
    gl_.FramebufferTextureLayer(target, attachment, texture, level, layer);
  }
  void FramebufferTexture3D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level,
                            int zoffset) override {
    gl_.FramebufferTexture3D(target, attachment, textarget, texture, level, zoffset);
  }
  std::int64_t GetAttachmentParameter(Enum target, Enum attachment, Enum pname) override {
    int v = -12345;
    gl_.GetFramebufferAttachmentParameteriv(target, attachment, pname, &v);
    return v;
  }

  std::vector<std::int64_t> GetIntegers(Enum pname, int count) override {
    std::vector<std::int64_t> v(std::size_t(count), -12345);
    std::vector<int> i(std::size_t(count), -12345);
    gl_.GetIntegerv(pname, i.data());
    std::copy(i.begin(), i.end(), v.begin());
    return v;
  }
  std::vector<float> GetFloats(Enum pname, int count) override {
    std::vector<float> v(std::size_t(count), -12345.0f);
    gl_.GetFloatv(pname, v.data());
    return v;
  }
  std::vector<bool> GetBooleans(Enum pname, int count) override {
    bool b[4] = {false, false, false, false};
    gl_.GetBooleanv(pname, b);
    return std::vector<bool>(b, b + count);
  }
  Enum GetError() override { return gl_.GetError(); }
  void CopyToTexture(int x, int y, int w, int h, int dx, int dy, int sx, int sy, int sw, int sh) override {
    gl_.ActiveTexture(softgl::TEXTURE0);
    gl_.BindTexture(softgl::TEXTURE_2D, gl_.GenTexture());
    gl_.CopyTexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, x, y, w, h, 0);
    gl_.CopyTexSubImage2D(softgl::TEXTURE_2D, 0, dx, dy, sx, sy, sw, sh);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, softgl::NEAREST);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, softgl::CLAMP_TO_EDGE);
    gl_.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, softgl::CLAMP_TO_EDGE);
  }
  std::uint32_t GenSampler() override { return gl_.GenSampler(); }
  void BindSampler(int unit, std::uint32_t sampler) override { gl_.BindSampler(unit, sampler); }
  void SamplerParameteri(std::uint32_t sampler, Enum pname, int value) override { gl_.SamplerParameteri(sampler, pname, value); }
  void SamplerParameterfv(std::uint32_t sampler, Enum pname, const float* values) override {
    gl_.SamplerParameterfv(sampler, pname, values);
  }
  std::vector<std::int64_t> GetSamplerIntegers(std::uint32_t sampler, Enum pname, int count) override {
    std::vector<int> v(std::size_t(count), -12345);
    gl_.GetSamplerParameteriv(sampler, pname, v.data());
    return {v.begin(), v.end()};
  }
  std::vector<float> GetSamplerFloats(std::uint32_t sampler, Enum pname, int count) override {
    std::vector<float> v(std::size_t(count), -12345.0f);
    gl_.GetSamplerParameterfv(sampler, pname, v.data());
    return v;
  }
  std::vector<std::int64_t> GetVertexAttribIntegers(std::uint32_t index, Enum pname, int count) override {
    gl_.BindVertexArray(vao_);
    std::vector<int> v(std::size_t(count), -12345);
    gl_.GetVertexAttribiv(index, pname, v.data());
    return {v.begin(), v.end()};
  }
  std::vector<float> GetVertexAttribFloats(std::uint32_t index, Enum pname, int count) override {
    gl_.BindVertexArray(vao_);
    std::vector<float> v(std::size_t(count), -12345.0f);
    gl_.GetVertexAttribfv(index, pname, v.data());
    return v;
  }
  std::uint32_t GenQuery() override { return gl_.GenQuery(); }
  void BeginQuery(Enum target, std::uint32_t id) override { gl_.BeginQuery(target, id); }
  void EndQuery(Enum target) override { gl_.EndQuery(target); }
  void VertexAttribP(int components, std::uint32_t index, Enum type, bool normalized, std::uint32_t value) override {
    switch (components) {
      case 1: gl_.VertexAttribP1ui(index, type, normalized, value); break;
      case 2: gl_.VertexAttribP2ui(index, type, normalized, value); break;
      case 3: gl_.VertexAttribP3ui(index, type, normalized, value); break;
      case 4: gl_.VertexAttribP4ui(index, type, normalized, value); break;
      default: gl_.VertexAttribP4uiv(index, type, normalized, &value); break;
    }
  }
  void TexParameterI(Enum pname, const int* values, bool is_unsigned) override {
    gl_.ActiveTexture(softgl::TEXTURE0);
    if (is_unsigned) gl_.TexParameterIuiv(softgl::TEXTURE_2D, pname, reinterpret_cast<const std::uint32_t*>(values));
    else gl_.TexParameterIiv(softgl::TEXTURE_2D, pname, values);
  }
  std::vector<std::int64_t> GetTexParameterI(Enum pname, int count, bool is_unsigned) override {
    gl_.ActiveTexture(softgl::TEXTURE0);
    int v[4] = {-7, -7, -7, -7};
    if (is_unsigned) gl_.GetTexParameterIuiv(softgl::TEXTURE_2D, pname, reinterpret_cast<std::uint32_t*>(v));
    else gl_.GetTexParameterIiv(softgl::TEXTURE_2D, pname, v);
    std::vector<std::int64_t> out;
    for (int k = 0; k < count; ++k) out.push_back(is_unsigned ? std::int64_t(std::uint32_t(v[k])) : std::int64_t(v[k]));
    return out;
  }
  void BeginConditionalRender(std::uint32_t id, Enum mode) override { gl_.BeginConditionalRender(id, mode); }
  void EndConditionalRender() override { gl_.EndConditionalRender(); }
  const void* FenceSync(Enum condition, std::uint32_t flags) override { return gl_.FenceSync(condition, flags); }
  bool IsSync(const void* sync) override { return gl_.IsSync(Handle(sync)); }
  void DeleteSync(const void* sync) override { gl_.DeleteSync(Handle(sync)); }
  Enum ClientWaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) override {
    return gl_.ClientWaitSync(Handle(sync), flags, timeout);
  }
  void WaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) override { gl_.WaitSync(Handle(sync), flags, timeout); }
  int GetSynci(const void* sync, Enum pname) override {
    int v = -1;
    gl_.GetSynciv(Handle(sync), pname, 1, nullptr, &v);
    return v;
  }
  void ClampColor(Enum target, Enum clamp) override { gl_.ClampColor(target, clamp); }
  void FeedbackVaryings(const std::vector<int>& which, Enum buffer_mode) override {
    std::vector<softgl::FeedbackVarying> v;
    for (int w : which)
      v.push_back(w == 0   ? softgl::FeedbackVarying::Position()
                  : w == 1 ? FeedbackShader::Capture(&FeedbackVaryings::color, "v_color")
                           : FeedbackShader::Capture(&FeedbackVaryings::extra, "v_extra"));
    gl_.TransformFeedbackVaryings(feedback_, int(v.size()), v.data(), buffer_mode);
  }
  std::uint32_t NewFeedbackBuffer(int floats) override {
    const std::uint32_t id = gl_.GenBuffer();
    gl_.BindBuffer(softgl::TRANSFORM_FEEDBACK_BUFFER, id);
    const std::vector<float> fill(std::size_t(floats), -7.0f);
    gl_.BufferData(softgl::TRANSFORM_FEEDBACK_BUFFER, std::ptrdiff_t(fill.size() * sizeof(float)), fill.data(),
                   softgl::STREAM_READ);
    return id;
  }
  std::vector<float> ReadBufferFloats(std::uint32_t buffer, int floats) override {
    std::vector<float> out(static_cast<std::size_t>(floats), 0.0f);
    gl_.BindBuffer(softgl::COPY_READ_BUFFER, buffer);
    gl_.GetBufferSubData(softgl::COPY_READ_BUFFER, 0, std::ptrdiff_t(out.size() * sizeof(float)), out.data());
    return out;
  }
  void BindBufferBase(std::uint32_t index, std::uint32_t buffer) override {
    gl_.BindBufferBase(softgl::TRANSFORM_FEEDBACK_BUFFER, index, buffer);
  }
  void BindBufferRange(std::uint32_t index, std::uint32_t buffer, std::ptrdiff_t offset, std::ptrdiff_t size) override {
    gl_.BindBufferRange(softgl::TRANSFORM_FEEDBACK_BUFFER, index, buffer, offset, size);
  }
  void BeginTransformFeedback(Enum mode) override { gl_.BeginTransformFeedback(mode); }
  void EndTransformFeedback() override { gl_.EndTransformFeedback(); }
  void PauseTransformFeedback() override { gl_.PauseTransformFeedback(); }
  void ResumeTransformFeedback() override { gl_.ResumeTransformFeedback(); }
  std::uint32_t GenTransformFeedback() override { return gl_.GenTransformFeedback(); }
  void BindTransformFeedback(std::uint32_t id) override { gl_.BindTransformFeedback(softgl::TRANSFORM_FEEDBACK, id); }
  void DrawTransformFeedback(Enum mode, std::uint32_t id) override {
    gl_.UseProgram(feedback_);
    gl_.DrawTransformFeedback(mode, id);
  }
  void ProvokingVertex(Enum convention) override { gl_.ProvokingVertex(convention); }
  static softgl::Sync Handle(const void* sync) {
    return static_cast<softgl::Sync>(const_cast<void*>(sync));
  }
  std::uint64_t QueryResult(std::uint32_t id) override {
    std::uint64_t v = ~0ull;
    gl_.GetQueryObjectui64v(id, softgl::QUERY_RESULT, &v);
    return v;
  }

  Frame Read() override {
    Frame f;
    f.width = gl_.Width();
    f.height = gl_.Height();
    f.rgba.resize(std::size_t(f.width) * std::size_t(f.height) * 4);
    f.depth.resize(std::size_t(f.width) * std::size_t(f.height));
    f.stencil.resize(std::size_t(f.width) * std::size_t(f.height));
    gl_.PixelStore(softgl::PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, f.width, f.height, softgl::RGBA, softgl::UNSIGNED_BYTE, f.rgba.data());
    gl_.ReadPixels(0, 0, f.width, f.height, softgl::DEPTH_COMPONENT, softgl::FLOAT, f.depth.data());
    gl_.ReadPixels(0, 0, f.width, f.height, softgl::STENCIL_INDEX, softgl::UNSIGNED_BYTE, f.stencil.data());
    return f;
  }

  std::vector<std::uint8_t> ReadPixels(const PixelRead& r, std::size_t bytes) override {
    std::vector<std::uint8_t> out(bytes, 0xCD);
    gl_.PixelStore(softgl::PACK_ALIGNMENT, r.alignment);
    gl_.PixelStore(softgl::PACK_ROW_LENGTH, r.row_length);
    gl_.PixelStore(softgl::PACK_SKIP_ROWS, r.skip_rows);
    gl_.PixelStore(softgl::PACK_SKIP_PIXELS, r.skip_pixels);
    gl_.ReadPixels(r.x, r.y, r.width, r.height, r.format, r.type, out.data());
    gl_.PixelStore(softgl::PACK_ALIGNMENT, 4);
    gl_.PixelStore(softgl::PACK_ROW_LENGTH, 0);
    gl_.PixelStore(softgl::PACK_SKIP_ROWS, 0);
    gl_.PixelStore(softgl::PACK_SKIP_PIXELS, 0);
    return out;
  }

 private:
  softgl::Context gl_;
  std::uint32_t vao_, vbo_, ebo_;
  ColorShader color_;
  InstancedShader instanced_;
  UvShader uv_;
  LitShader lit_;
  TextureShader texture_;
  CubeShader cube_;
  ShadowShader shadow_;
  LayeredShader array_, volume_, array_shadow_, texture_1d_, texture_1d_array_;
  FetchSampleShader fetch_sample_;
  IntegerShader integer_;
  IntegerOutputShader integer_output_;
  int w_, h_;  // the default framebuffer's size
  IntegerTextureShader integer_texture_;
  TextureBufferShader texture_buffer_;
  FetchSampleArrayShader fetch_sample_array_;
  OutputsShader outputs_;
  PointCoordShader point_coord_;
  FeedbackShader feedback_;
  LayerShader layer_;
  ShrinkShader shrink_;
  SpritesShader sprites_;
  AdjacencyShader adjacency_;
  LineAdjacencyShader line_adjacency_;
  GeometryLayerShader geometry_layer_;
  bool Recording() {
    bool active = false, paused = false;
    gl_.GetBooleanv(softgl::TRANSFORM_FEEDBACK_BUFFER_ACTIVE, &active);
    gl_.GetBooleanv(softgl::TRANSFORM_FEEDBACK_BUFFER_PAUSED, &paused);
    return active && !paused;
  }
  std::uint32_t rtt_color_ = 0;
};

}  // namespace

std::unique_ptr<Backend> MakeSoftglBackend(int width, int height) {
  return std::make_unique<SoftglBackend>(width, height);
}

}  // namespace conformance

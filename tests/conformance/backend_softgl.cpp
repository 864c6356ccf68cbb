// backend_softgl.cpp — the conformance backend on softgl, with the scene shaders in C++.
#include <cmath>

#include <softgl/softgl.h>

#include "backend.h"

namespace conformance {

namespace {

struct ColorVaryings {
  glm::vec4 color;
};

struct ColorShader : softgl::Shader<ColorShader, ColorVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<ColorVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.color = in.attrib[1];
  }
  bool Fragment(const softgl::FragmentIn<ColorVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.varyings.color;
    return true;
  }
};

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

class SoftglBackend final : public Backend {
 public:
  SoftglBackend(int w, int h) : gl_(w, h) {
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
  void DepthFunc(Enum func) override { gl_.DepthFunc(func); }
  void DepthMask(bool flag) override { gl_.DepthMask(flag); }
  void PolygonOffset(float factor, float units) override { gl_.PolygonOffset(factor, units); }
  void Scissor(int x, int y, int w, int h) override { gl_.Scissor(x, y, w, h); }
  void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) override {
    gl_.StencilFuncSeparate(face, func, ref, mask);
  }
  void StencilOpSeparate(Enum face, Enum a, Enum b, Enum c) override { gl_.StencilOpSeparate(face, a, b, c); }
  void StencilMaskSeparate(Enum face, std::uint32_t mask) override { gl_.StencilMaskSeparate(face, mask); }
  void BlendFuncSeparate(Enum a, Enum b, Enum c, Enum d) override { gl_.BlendFuncSeparate(a, b, c, d); }
  void BlendEquationSeparate(Enum rgb, Enum alpha) override { gl_.BlendEquationSeparate(rgb, alpha); }
  void BlendColor(float r, float g, float b, float a) override { gl_.BlendColor(r, g, b, a); }
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
    }
    if (indices.empty()) {
      gl_.DrawArrays(mode, 0, int(vertices.size()));
    } else {
      gl_.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * sizeof(std::uint32_t)),
                     indices.data());
      gl_.DrawElement(mode, int(indices.size()), softgl::UNSIGNED_INT, 0);
    }
  }

  Frame Read() override {
    Frame f;
    f.width = gl_.Width();
    f.height = gl_.Height();
    for (int y = 0; y < f.height; ++y)
      for (int x = 0; x < f.width; ++x) {
        std::uint8_t px[4];
        gl_.ReadPixel(x, y, px);
        f.rgba.insert(f.rgba.end(), px, px + 4);
        f.depth.push_back(gl_.ReadDepth(x, y));
        f.stencil.push_back(gl_.ReadStencil(x, y));
      }
    return f;
  }

 private:
  softgl::Context gl_;
  std::uint32_t vao_, vbo_, ebo_;
  ColorShader color_;
  UvShader uv_;
  LitShader lit_;
};

}  // namespace

std::unique_ptr<Backend> MakeSoftglBackend(int width, int height) {
  return std::make_unique<SoftglBackend>(width, height);
}

}  // namespace conformance

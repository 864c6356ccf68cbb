// backend_gl.cpp — the conformance backend on Mesa (OSMesa, OpenGL 3.3 core), with the scene shaders in GLSL.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>

#include "backend.h"

namespace conformance {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_color;
layout(location = 2) in vec4 a_extra;
out vec4 v_color;
out vec4 v_extra;
void main() {
  gl_Position = a_pos;
  v_color = a_color;
  v_extra = a_extra;
}
)";

constexpr const char* kColorFragment = R"(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";

constexpr const char* kUvFragment = R"(#version 330 core
in vec4 v_extra;
out vec4 o_color;
void main() { o_color = vec4(v_extra.xy, 0.5, 1.0); }
)";

constexpr const char* kLitFragment = R"(#version 330 core
in vec4 v_extra;
uniform vec4 u_tint;
uniform vec3 u_light_dir;
uniform vec3 u_half_vector;
out vec4 o_color;
void main() {
  vec3 n = normalize(v_extra.xyz);
  float diffuse = max(dot(n, u_light_dir), 0.0);
  float specular = pow(max(dot(n, u_half_vector), 0.0), 32.0);
  o_color = vec4(u_tint.rgb * (0.2 + 0.8 * diffuse) + vec3(0.3 * specular), u_tint.a);
}
)";

GLuint Compile(GLenum type, const char* source, std::string* error) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    *error += log;
  }
  return s;
}

GLuint Link(const char* fragment, std::string* error) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, Compile(GL_VERTEX_SHADER, kVertexShader, error));
  glAttachShader(p, Compile(GL_FRAGMENT_SHADER, fragment, error));
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) *error += "link failed";
  return p;
}

class GlBackend final : public Backend {
 public:
  GlBackend(OSMesaContext ctx, int w, int h) : ctx_(ctx), w_(w), h_(h), buffer_(std::size_t(w) * h * 4) {}
  ~GlBackend() override { OSMesaDestroyContext(ctx_); }

  bool Init(std::string* error) {
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w_, h_)) {
      *error = "OSMesaMakeCurrent failed";
      return false;
    }
    programs_[0] = Link(kColorFragment, error);
    programs_[1] = Link(kUvFragment, error);
    programs_[2] = Link(kLitFragment, error);
    if (!error->empty()) return false;
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ebo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    for (GLuint i = 0; i < 3; ++i) {
      glVertexAttribPointer(i, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                            reinterpret_cast<const void*>(i * sizeof(glm::vec4)));
      glEnableVertexAttribArray(i);
    }
    glViewport(0, 0, w_, h_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    return glGetError() == GL_NO_ERROR;
  }

  std::string Name() const override { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
  void Enable(Enum cap) override { glEnable(cap); }
  void Disable(Enum cap) override { glDisable(cap); }
  void Viewport(int x, int y, int w, int h) override { glViewport(x, y, w, h); }
  void DepthRange(double n, double f) override { glDepthRange(n, f); }
  void CullFace(Enum mode) override { glCullFace(mode); }
  void FrontFace(Enum mode) override { glFrontFace(mode); }
  void PolygonMode(Enum mode) override { glPolygonMode(GL_FRONT_AND_BACK, mode); }
  void PointSize(float size) override { glPointSize(size); }
  void DepthFunc(Enum func) override { glDepthFunc(func); }
  void DepthMask(bool flag) override { glDepthMask(flag); }
  void PolygonOffset(float factor, float units) override { glPolygonOffset(factor, units); }
  void Scissor(int x, int y, int w, int h) override { glScissor(x, y, w, h); }
  void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) override {
    glStencilFuncSeparate(face, func, ref, mask);
  }
  void StencilOpSeparate(Enum face, Enum a, Enum b, Enum c) override { glStencilOpSeparate(face, a, b, c); }
  void StencilMaskSeparate(Enum face, std::uint32_t mask) override { glStencilMaskSeparate(face, mask); }
  void BlendFuncSeparate(Enum a, Enum b, Enum c, Enum d) override { glBlendFuncSeparate(a, b, c, d); }
  void BlendEquationSeparate(Enum rgb, Enum alpha) override { glBlendEquationSeparate(rgb, alpha); }
  void BlendColor(float r, float g, float b, float a) override { glBlendColor(r, g, b, a); }
  void ColorMask(bool r, bool g, bool b, bool a) override { glColorMask(r, g, b, a); }
  void ClearColor(float r, float g, float b, float a) override { glClearColor(r, g, b, a); }
  void ClearDepth(double d) override { glClearDepth(d); }
  void ClearStencil(int s) override { glClearStencil(s); }
  void Clear(std::uint32_t mask) override { glClear(mask); }

  void Draw(Enum mode, const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
            Program program, const Uniforms& u) override {
    const GLuint p = programs_[int(program)];
    glUseProgram(p);
    if (program == Program::kLit) {
      glUniform4f(glGetUniformLocation(p, "u_tint"), u.tint.r, u.tint.g, u.tint.b, u.tint.a);
      glUniform3f(glGetUniformLocation(p, "u_light_dir"), u.light_dir.x, u.light_dir.y, u.light_dir.z);
      glUniform3f(glGetUniformLocation(p, "u_half_vector"), u.half_vector.x, u.half_vector.y, u.half_vector.z);
    }
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    if (indices.empty()) {
      glDrawArrays(mode, 0, GLsizei(vertices.size()));
    } else {
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                   GL_STREAM_DRAW);
      glDrawElements(mode, GLsizei(indices.size()), GL_UNSIGNED_INT, nullptr);
    }
  }

  Frame Read() override {
    Frame f;
    f.width = w_;
    f.height = h_;
    f.rgba.resize(std::size_t(w_) * h_ * 4);
    f.depth.resize(std::size_t(w_) * h_);
    f.stencil.resize(std::size_t(w_) * h_);
    glFinish();
    glReadPixels(0, 0, w_, h_, GL_RGBA, GL_UNSIGNED_BYTE, f.rgba.data());
    glReadPixels(0, 0, w_, h_, GL_DEPTH_COMPONENT, GL_FLOAT, f.depth.data());
    glReadPixels(0, 0, w_, h_, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, f.stencil.data());
    return f;
  }

 private:
  OSMesaContext ctx_;
  int w_, h_;
  std::vector<std::uint8_t> buffer_;
  GLuint programs_[3] = {};
  GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
};

}  // namespace

std::unique_ptr<Backend> MakeGlBackend(int width, int height, std::string* error) {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx) {
    *error = "OSMesaCreateContextAttribs failed (no OpenGL 3.3 core context)";
    return nullptr;
  }
  auto backend = std::make_unique<GlBackend>(ctx, width, height);
  if (!backend->Init(error)) return nullptr;
  return backend;
}

}  // namespace conformance

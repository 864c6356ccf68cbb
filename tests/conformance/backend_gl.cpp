// backend_gl.cpp — the conformance backend on Mesa (OSMesa, OpenGL 3.3 core), with the scene shaders in GLSL.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "backend.h"

namespace conformance {

namespace {

// The declarations of the vertex shaders that read Vertex's three attributes (after #version and any #extension).
#define VERTEX_DECLARATIONS "\n" \
  "layout(location = 0) in vec4 a_pos;\n" \
  "layout(location = 1) in vec4 a_color;\n" \
  "layout(location = 2) in vec4 a_extra;\n" \
  "out vec4 v_color;\n" \
  "out vec4 v_extra;\n"

constexpr const char* kVertexShader = "#version 330 core" VERTEX_DECLARATIONS R"(
void main() {
  gl_Position = a_pos;
  v_color = a_color;
  v_extra = a_extra;
}
)";

constexpr const char* kInstancedVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_color;
layout(location = 3) in vec4 a_offset;
out vec4 v_color;
void main() {
  gl_Position = a_pos + vec4(a_offset.xy, 0.0, 0.0);
  float k = float(gl_InstanceID % 8);
  v_color = a_color * vec4(vec3(1.0 - 0.125 * k), 1.0);
}
)";

constexpr const char* kIntegerVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
layout(location = 3) in ivec4 a_int;
out vec4 v_color;
void main() {
  gl_Position = a_pos;
  v_color = vec4(a_int & 255) / 255.0;
}
)";

// DrawIntegerTarget's programs: integer outputs from a flat attribute 2, and an integer texture's texel shown as
// bytes. The fragment stages are written once and compiled unsigned or signed: IntegerFragment(true) defines I as
// "u" (uvec4, usampler2D, the mask 255u), IntegerFragment(false) as "i".
constexpr const char* kIntegerOutputVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_pos;
layout(location = 2) in vec4 a_extra;
flat out vec4 v_value;
void main() {
  gl_Position = a_pos;
  v_value = a_extra;
}
)";
constexpr const char* kIntegerOutputFragment = R"(
flat in vec4 v_value;
out IVEC4 o_color;
void main() { o_color = IVEC4(v_value); }
)";
constexpr const char* kIntegerTextureFragment = R"(
in vec4 v_extra;
uniform ISAMPLER2D u_int;
out vec4 o_color;
void main() {
  IVEC4 t = texture(u_int, v_extra.xy);
  o_color = vec4(vec3(IVEC3(t.r, t.g, t.b + IVEC4(64).x * t.a) & IVEC4(255).x) / 255.0, 1.0);
}
)";
std::string IntegerFragment(bool is_unsigned, const char* body) {
  const std::string i = is_unsigned ? "u" : "i";
  return "#version 330 core\n#define IVEC4 " + i + "vec4\n#define IVEC3 " + i + "vec3\n#define ISAMPLER2D " + i +
         "sampler2D\n" + body;
}

constexpr const char* kFeedbackVertexShader = "#version 330 core" VERTEX_DECLARATIONS R"(
void main() {
  gl_Position = a_pos;
  v_color = a_color;
  v_extra = a_extra * 2.0 - a_pos;
}
)";

constexpr const char* kLayerVertexShader =
    "#version 330 core\n#extension GL_ARB_shader_viewport_layer_array : require" VERTEX_DECLARATIONS R"(
void main() {
  gl_Position = a_pos;
  v_color = a_color;
  gl_Layer = int(a_extra.w);
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

constexpr const char* kTextureFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2D u_tex;
out vec4 o_color;
void main() { o_color = texture(u_tex, v_extra.xy); }
)";

constexpr const char* kCubeFragment = R"(#version 330 core
in vec4 v_extra;
uniform samplerCube u_cube;
out vec4 o_color;
void main() { o_color = texture(u_cube, v_extra.xyz); }
)";

constexpr const char* kShadowFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2DShadow u_shadow;
out vec4 o_color;
void main() { o_color = vec4(texture(u_shadow, v_extra.xyz), 0.0, 0.0, 1.0); }
)";

constexpr const char* kArrayFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2DArray u_array;
out vec4 o_color;
void main() { o_color = texture(u_array, v_extra.xyz); }
)";

constexpr const char* kTexture1DFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler1D u_1d;
out vec4 o_color;
void main() { o_color = texture(u_1d, v_extra.x); }
)";

constexpr const char* kTexture1DArrayFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler1DArray u_1d_array;
out vec4 o_color;
void main() { o_color = texture(u_1d_array, v_extra.xy); }
)";

constexpr const char* kTextureBufferFragment = R"(#version 330 core
in vec4 v_extra;
uniform samplerBuffer u_buffer;
out vec4 o_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = int(v_extra.x) + p.y / 4 % 16 * 16 + p.x / 4 % 16;
  o_color = v_extra.y > 0.5 ? vec4(float(textureSize(u_buffer)) / 1024.0, 0.0, 0.0, 1.0) : texelFetch(u_buffer, i);
}
)";

constexpr const char* kVolumeFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler3D u_volume;
out vec4 o_color;
void main() { o_color = texture(u_volume, v_extra.xyz); }
)";

constexpr const char* kArrayShadowFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2DArrayShadow u_shadow_array;
out vec4 o_color;
void main() { o_color = vec4(texture(u_shadow_array, v_extra), 0.0, 0.0, 1.0); }
)";

constexpr const char* kFetchSampleFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2DMS u_ms;
out vec4 o_color;
void main() { o_color = texelFetch(u_ms, ivec2(gl_FragCoord.xy) - ivec2(v_extra.xy), int(v_extra.z)); }
)";

constexpr const char* kFetchSampleArrayFragment = R"(#version 330 core
in vec4 v_extra;
uniform sampler2DMSArray u_ms_array;
out vec4 o_color;
void main() {
  o_color = texelFetch(u_ms_array, ivec3(ivec2(gl_FragCoord.xy) - ivec2(v_extra.xy), int(v_extra.w)), int(v_extra.z));
}
)";

constexpr const char* kPointCoordFragment = R"(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = vec4(gl_PointCoord, v_color.b, 1.0); }
)";

constexpr const char* kOutputsFragment = R"(#version 330 core
in vec4 v_color;
in vec4 v_extra;
layout(location = 0) out vec4 o_0;
layout(location = 1) out vec4 o_1;
layout(location = 2) out vec4 o_2;
layout(location = 3) out vec4 o_3;
void main() {
  o_0 = v_color;
  o_1 = vec4(v_extra.xy, 0.5, v_color.a);
  o_2 = v_color * 2.0 - 0.5;
  o_3 = vec4(v_extra.zw, v_color.g, v_color.a);
}
)";

// The fragment shader of the programs with a geometry stage: the colour it emits.
constexpr const char* kGeometryFragment = R"(#version 330 core
in vec4 g_color;
out vec4 o_color;
void main() { o_color = g_color; }
)";

// (Instanced geometry shaders are OpenGL 4.0's, ARB_gpu_shader5 on a 3.3 context.)
constexpr const char* kShrinkGeometry = R"(#version 330 core
#extension GL_ARB_gpu_shader5 : require
layout(triangles, invocations = 2) in;
layout(triangle_strip, max_vertices = 6) out;
in vec4 v_color[];
out vec4 g_color;
void main() {
  float s = gl_InvocationID == 0 ? 0.5 : 0.25;
  float tint = float(gl_PrimitiveIDIn % 4) * 0.2;
  for (int k = 0; k < 3; ++k) {
    gl_Position = gl_in[0].gl_Position + (gl_in[k].gl_Position - gl_in[0].gl_Position) * s;
    g_color = gl_InvocationID == 0 ? v_color[k] : vec4(tint, 1.0 - tint, v_color[k].b, 1.0);
    EmitVertex();
  }
  EndPrimitive();
  if (gl_InvocationID == 1 && gl_PrimitiveIDIn % 2 == 0) {
    vec4 p = gl_in[2].gl_Position;
    for (int k = 0; k < 3; ++k) {
      gl_Position = p + vec4(k == 1 ? 0.125 : 0.0, k == 2 ? 0.125 : 0.0, 0.0, 0.0) * p.w;
      g_color = vec4(1.0, 1.0, 0.0, 1.0);
      EmitVertex();
    }
  }
}
)";

constexpr const char* kSpritesGeometry = R"(#version 330 core
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;
in vec4 v_color[];
in vec4 v_extra[];
out vec4 g_color;
void main() {
  vec4 p = gl_in[0].gl_Position;
  float d = v_extra[0].x;
  for (int k = 0; k < 4; ++k) {
    gl_Position = p + vec4((k & 1) != 0 ? d : -d, (k & 2) != 0 ? d : -d, 0.0, 0.0) * p.w;
    g_color = v_color[0];
    EmitVertex();
  }
  if (v_extra[0].y > 0.5) {
    EndPrimitive();
    for (int k = 0; k < 4; ++k) {
      gl_Position = p + vec4(2.0 * d + ((k & 1) != 0 ? d : 0.0), (k & 2) != 0 ? d * 0.5 : -d * 0.5, 0.0, 0.0) * p.w;
      g_color = vec4(1.0 - v_color[0].rgb, 1.0);
      EmitVertex();
    }
  }
}
)";

constexpr const char* kAdjacencyGeometry = R"(#version 330 core
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 3) out;
in vec4 v_color[];
out vec4 g_color;
void main() {
  for (int k = 0; k < 3; ++k) {
    gl_Position = gl_in[2 * k].gl_Position;
    g_color = v_color[2 * k + 1];
    EmitVertex();
  }
}
)";

constexpr const char* kLineAdjacencyGeometry = R"(#version 330 core
layout(lines_adjacency) in;
layout(line_strip, max_vertices = 2) out;
in vec4 v_color[];
out vec4 g_color;
void main() {
  for (int k = 0; k < 2; ++k) {
    gl_Position = gl_in[1 + k].gl_Position;
    g_color = v_color[3 * k];
    EmitVertex();
  }
}
)";

constexpr const char* kLayerGeometry = R"(#version 330 core
#extension GL_ARB_gpu_shader5 : require
layout(triangles, invocations = 3) in;
layout(triangle_strip, max_vertices = 3) out;
in vec4 v_color[];
in vec4 v_extra[];
out vec4 g_color;
void main() {
  for (int k = 0; k < 3; ++k) {
    gl_Position = gl_in[k].gl_Position;
    g_color = vec4(v_color[k].rgb * (1.0 - float(gl_InvocationID) * 0.25), v_color[k].a);
    gl_Layer = int(v_extra[2].w) + gl_InvocationID;
    EmitVertex();
  }
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

GLuint Link(const char* fragment, std::string* error, const char* vertex = kVertexShader,
            const char* geometry = nullptr) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, Compile(GL_VERTEX_SHADER, vertex, error));
  if (geometry) glAttachShader(p, Compile(GL_GEOMETRY_SHADER, geometry, error));
  glAttachShader(p, Compile(GL_FRAGMENT_SHADER, fragment, error));
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) *error += "link failed";
  return p;
}

// One new object name from a glGen* call.
std::uint32_t GenOne(void (*gen)(GLsizei, GLuint*)) {
  GLuint id = 0;
  gen(1, &id);
  return id;
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
    programs_[3] = Link(kTextureFragment, error);
    programs_[4] = Link(kCubeFragment, error);
    programs_[5] = Link(kShadowFragment, error);
    programs_[6] = Link(kArrayFragment, error);
    programs_[7] = Link(kVolumeFragment, error);
    programs_[8] = Link(kArrayShadowFragment, error);
    programs_[9] = Link(kFetchSampleFragment, error);
    programs_[10] = Link(kOutputsFragment, error);
    programs_[11] = Link(kPointCoordFragment, error);
    programs_[12] = Link(kColorFragment, error, kFeedbackVertexShader);
    {  // (softpipe has no ARB_shader_viewport_layer_array: without it, kLayer draws nothing there)
      std::string layer_error;
      programs_[13] = Link(kColorFragment, &layer_error, kLayerVertexShader);
      if (!layer_error.empty()) programs_[13] = 0;
    }
    programs_[19] = Link(kTexture1DFragment, error);
    programs_[20] = Link(kTexture1DArrayFragment, error);
    programs_[21] = Link(kTextureBufferFragment, error);
    programs_[22] = Link(kFetchSampleArrayFragment, error);
    programs_[15] = Link(kGeometryFragment, error, kVertexShader, kSpritesGeometry);
    programs_[16] = Link(kGeometryFragment, error, kVertexShader, kAdjacencyGeometry);
    programs_[17] = Link(kGeometryFragment, error, kVertexShader, kLineAdjacencyGeometry);
    for (int k : {14, 18}) {  // (a renderer without ARB_gpu_shader5 draws nothing with these)
      std::string instanced_error;
      programs_[k] = Link(kGeometryFragment, &instanced_error, kVertexShader, k == 14 ? kShrinkGeometry : kLayerGeometry);
      if (!instanced_error.empty()) programs_[k] = 0;
    }
    instanced_ = Link(kColorFragment, error, kInstancedVertexShader);
    integer_ = Link(kColorFragment, error, kIntegerVertexShader);
    for (int is_signed = 0; is_signed < 2; ++is_signed) {
      integer_output_[is_signed] =
          Link(IntegerFragment(!is_signed, kIntegerOutputFragment).c_str(), error, kIntegerOutputVertexShader);
      integer_texture_[is_signed] = Link(IntegerFragment(!is_signed, kIntegerTextureFragment).c_str(), error);
    }
    glUseProgram(programs_[4]);
    glUniform1i(glGetUniformLocation(programs_[4], "u_cube"), 1);
    glUseProgram(programs_[5]);
    glUniform1i(glGetUniformLocation(programs_[5], "u_shadow"), 2);
    glUseProgram(programs_[6]);
    glUniform1i(glGetUniformLocation(programs_[6], "u_array"), 3);
    glUseProgram(programs_[7]);
    glUniform1i(glGetUniformLocation(programs_[7], "u_volume"), 4);
    glUseProgram(programs_[8]);
    glUniform1i(glGetUniformLocation(programs_[8], "u_shadow_array"), 5);
    glUseProgram(programs_[9]);
    glUniform1i(glGetUniformLocation(programs_[9], "u_ms"), 6);
    glUseProgram(programs_[22]);
    glUniform1i(glGetUniformLocation(programs_[22], "u_ms_array"), 6);
    glUseProgram(programs_[19]);
    glUniform1i(glGetUniformLocation(programs_[19], "u_1d"), 7);
    glUseProgram(programs_[20]);
    glUniform1i(glGetUniformLocation(programs_[20], "u_1d_array"), 7);
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
  void LineWidth(float width) override { glLineWidth(width); }
  void PointParameteri(Enum pname, int value) override { glPointParameteri(pname, value); }
  void ColorMaski(std::uint32_t index, bool r, bool g, bool b, bool a) override { glColorMaski(index, r, g, b, a); }
  void Enablei(Enum cap, std::uint32_t index) override { glEnablei(cap, index); }
  void Disablei(Enum cap, std::uint32_t index) override { glDisablei(cap, index); }
  std::vector<bool> GetBooleansI(Enum target, std::uint32_t index, int count) override {
    GLboolean v[4] = {7, 7, 7, 7};
    glGetBooleani_v(target, index, v);
    return std::vector<bool>(v, v + count);
  }
  std::vector<std::int64_t> GetIntegersI(Enum target, std::uint32_t index, int count) override {
    GLint v[4] = {-7, -7, -7, -7};
    glGetIntegeri_v(target, index, v);
    return std::vector<std::int64_t>(v, v + count);
  }
  bool IsEnabledi(Enum cap, std::uint32_t index) override { return glIsEnabledi(cap, index) == GL_TRUE; }
  void DepthFunc(Enum func) override { glDepthFunc(func); }
  void DepthMask(bool flag) override { glDepthMask(flag); }
  void PolygonOffset(float factor, float units) override { glPolygonOffset(factor, units); }
  void Scissor(int x, int y, int w, int h) override { glScissor(x, y, w, h); }
  void PrimitiveRestartIndex(std::uint32_t index) override { glPrimitiveRestartIndex(index); }
  void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) override {
    glStencilFuncSeparate(face, func, ref, mask);
  }
  void StencilOpSeparate(Enum face, Enum a, Enum b, Enum c) override { glStencilOpSeparate(face, a, b, c); }
  void StencilMaskSeparate(Enum face, std::uint32_t mask) override { glStencilMaskSeparate(face, mask); }
  void BlendFuncSeparate(Enum a, Enum b, Enum c, Enum d) override { glBlendFuncSeparate(a, b, c, d); }
  void BlendEquationSeparate(Enum rgb, Enum alpha) override { glBlendEquationSeparate(rgb, alpha); }
  void BlendColor(float r, float g, float b, float a) override { glBlendColor(r, g, b, a); }
  void LogicOp(Enum op) override { glLogicOp(op); }
  void ClearBufferfv(Enum buffer, int drawbuffer, const float* value) override { glClearBufferfv(buffer, drawbuffer, value); }
  void ClearBufferiv(Enum buffer, int drawbuffer, const int* value) override { glClearBufferiv(buffer, drawbuffer, value); }
  void ClearBufferfi(Enum buffer, int drawbuffer, float depth, int stencil) override {
    glClearBufferfi(buffer, drawbuffer, depth, stencil);
  }
  void ColorMask(bool r, bool g, bool b, bool a) override { glColorMask(r, g, b, a); }
  void ClearColor(float r, float g, float b, float a) override { glClearColor(r, g, b, a); }
  void ClearDepth(double d) override { glClearDepth(d); }
  void ClearStencil(int s) override { glClearStencil(s); }
  void Clear(std::uint32_t mask) override { glClear(mask); }

  void Draw(Enum mode, const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
            Program program, const Uniforms& u) override {
    const GLuint p = programs_[int(program)];
    GLint current = 0;  // (UseProgram is an error while transform feedback records, even of the same program)
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) != p) glUseProgram(p);
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

  void DrawVariants(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                    const std::vector<DrawVariant>& calls) override {
    glUseProgram(programs_[int(Program::kColor)]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STREAM_DRAW);
    auto at = [](int first) { return reinterpret_cast<const void*>(std::uintptr_t(first) * sizeof(std::uint32_t)); };
    for (const DrawVariant& c : calls) {
      switch (c.call) {
        case DrawVariant::Call::kElementsBaseVertex:
          glDrawElementsBaseVertex(c.mode, c.count[0], GL_UNSIGNED_INT, const_cast<void*>(at(c.first[0])),
                                   c.basevertex);
          break;
        case DrawVariant::Call::kRangeElements:
          glDrawRangeElements(c.mode, c.start, c.end, c.count[0], GL_UNSIGNED_INT, at(c.first[0]));
          break;
        case DrawVariant::Call::kMultiElements: {
          std::vector<const void*> offsets;
          for (int f : c.first) offsets.push_back(at(f));
          glMultiDrawElements(c.mode, c.count.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(c.count.size()));
          break;
        }
        case DrawVariant::Call::kMultiArrays:
          glMultiDrawArrays(c.mode, c.first.data(), c.count.data(), GLsizei(c.count.size()));
          break;
        default: break;  // the instanced calls: DrawInstanced
      }
    }
  }

  void DrawInstanced(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
                     const std::vector<glm::vec4>& instance_data, const std::vector<DrawVariant>& calls) override {
    glUseProgram(instanced_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STREAM_DRAW);
    GLuint instance_vbo = 0;
    glGenBuffers(1, &instance_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, instance_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(instance_data.size() * sizeof(glm::vec4)), instance_data.data(),
                 GL_STREAM_DRAW);
    glEnableVertexAttribArray(3);
    auto at = [](int first) { return reinterpret_cast<const void*>(std::uintptr_t(first) * sizeof(std::uint32_t)); };
    for (const DrawVariant& c : calls) {
      glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 0,
                            reinterpret_cast<const void*>(std::uintptr_t(c.instance_first) * sizeof(glm::vec4)));
      glVertexAttribDivisor(3, c.divisor);
      switch (c.call) {
        case DrawVariant::Call::kArraysInstanced:
          glDrawArraysInstanced(c.mode, c.first[0], c.count[0], c.instances);
          break;
        case DrawVariant::Call::kElementsInstanced:
          glDrawElementsInstanced(c.mode, c.count[0], GL_UNSIGNED_INT, at(c.first[0]), c.instances);
          break;
        case DrawVariant::Call::kElementsInstancedBaseVertex:
          glDrawElementsInstancedBaseVertex(c.mode, c.count[0], GL_UNSIGNED_INT, const_cast<void*>(at(c.first[0])),
                                            c.instances, c.basevertex);
          break;
        default: break;
      }
    }
    glDisableVertexAttribArray(3);
    glVertexAttribDivisor(3, 0);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glDeleteBuffers(1, &instance_vbo);
  }

  int DrawIntegerAttribs(const std::vector<Vertex>& vertices, int size, Enum type, int stride,
                         const std::vector<std::uint8_t>& bytes, glm::ivec4 current) override {
    glUseProgram(integer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STREAM_DRAW);
    GLuint ints = 0;
    glGenBuffers(1, &ints);
    glBindBuffer(GL_ARRAY_BUFFER, ints);
    if (bytes.empty()) {
      glDisableVertexAttribArray(3);
      glVertexAttribI4i(3, current.x, current.y, current.z, current.w);
    } else {
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes.size()), bytes.data(), GL_STREAM_DRAW);
      glVertexAttribIPointer(3, size, type, stride, nullptr);
      glEnableVertexAttribArray(3);
    }
    GLint integer = -1;
    glGetVertexAttribiv(3, GL_VERTEX_ATTRIB_ARRAY_INTEGER, &integer);
    glDrawArrays(GL_POINTS, 0, GLsizei(vertices.size()));
    glDisableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glDeleteBuffers(1, &ints);
    return integer;
  }

  void DrawIntegerTarget(Enum format, int w, int h, const glm::ivec4& clear, const std::vector<IntegerDraw>& draws,
                         Enum wrap, const glm::ivec4& border, const std::vector<Vertex>& quad) override {
    const bool is_signed = IsSignedInteger(format);
    GLuint tex = 0, fbo = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), w, h, 0, GL_RGBA_INTEGER, GL_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
    glTexParameterIiv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &border.x);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    glViewport(0, 0, w, h);
    if (is_signed) glClearBufferiv(GL_COLOR, 0, &clear.x);
    else glClearBufferuiv(GL_COLOR, 0, reinterpret_cast<const GLuint*>(&clear.x));
    glUseProgram(integer_output_[is_signed]);
    for (const IntegerDraw& d : draws) {
      if (d.logic) {
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(d.logic);
      }
      glColorMask(d.mask & 1u, (d.mask >> 1) & 1u, (d.mask >> 2) & 1u, (d.mask >> 3) & 1u);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(d.triangles.size() * sizeof(Vertex)), d.triangles.data(), GL_STREAM_DRAW);
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(d.triangles.size()));
      glDisable(GL_COLOR_LOGIC_OP);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w_, h_);
    glUseProgram(integer_texture_[is_signed]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(quad.size() * sizeof(Vertex)), quad.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(quad.size()));
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
  }

  std::vector<Vertex> DrawThroughBufferCalls(Enum mode, const std::vector<Vertex>& vertices, int mapped) override {
    const GLsizeiptr size = GLsizeiptr(vertices.size() * sizeof(Vertex)), head = mapped * GLsizeiptr(sizeof(Vertex));
    glUseProgram(programs_[int(Program::kColor)]);
    glBufferData(GL_ARRAY_BUFFER, size, nullptr, GL_DYNAMIC_DRAW);
    void* p = glMapBufferRange(GL_ARRAY_BUFFER, 0, head,
                               GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    if (p != nullptr) std::memcpy(p, vertices.data(), std::size_t(head));
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, head);
    glUnmapBuffer(GL_ARRAY_BUFFER);
    GLuint staging = 0;
    glGenBuffers(1, &staging);
    glBindBuffer(GL_COPY_READ_BUFFER, staging);
    glBufferData(GL_COPY_READ_BUFFER, size - head, vertices.data() + mapped, GL_STREAM_COPY);
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_ARRAY_BUFFER, 0, head, size - head);
    glDeleteBuffers(1, &staging);
    GLint stored = 0;
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &stored);
    glDrawArrays(mode, 0, stored / GLint(sizeof(Vertex)));
    std::vector<Vertex> back(std::size_t(stored) / sizeof(Vertex));
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(back.size() * sizeof(Vertex)), back.data());
    return back;
  }

  void SetTexture(const TextureDesc& d) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t l = 0; l < d.levels.size(); ++l)
      if (d.compressed)
        glCompressedTexImage2D(GL_TEXTURE_2D, GLint(l), GLenum(d.compressed), d.levels[l].width, d.levels[l].height, 0,
                               GLsizei(d.levels[l].blocks.size()), d.levels[l].blocks.data());
      else
      glTexImage2D(GL_TEXTURE_2D, GLint(l), GLint(d.internal_format), d.levels[l].width, d.levels[l].height, 0, GL_RGBA,
                   GLenum(d.type),
                   d.type == softgl::UNSIGNED_BYTE ? static_cast<const void*>(d.levels[l].rgba.data())
                                                   : static_cast<const void*>(d.levels[l].shorts.data()));
    if (d.generate_mipmap) glGenerateMipmap(GL_TEXTURE_2D);
    else glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(d.levels.size()) - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(d.min_filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(d.mag_filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(d.wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(d.wrap_t));
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &d.border[0]);
    if (d.max_anisotropy != 1.0f) glTexParameterf(GL_TEXTURE_2D, 0x84FE, d.max_anisotropy);  // TEXTURE_MAX_ANISOTROPY
    glUseProgram(programs_[3]);
    glUniform1i(glGetUniformLocation(programs_[3], "u_tex"), 0);
  }

  std::uint32_t NewBufferTexture(Enum internal_format, const std::vector<std::uint8_t>& bytes) override {
    GLuint tex = 0, buffer = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_BUFFER, tex);
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes.size()), bytes.data(), GL_STATIC_DRAW);
    glTexBuffer(GL_TEXTURE_BUFFER, GLenum(internal_format), buffer);
    return buffer;
  }

  void BufferSubDataTexture(std::uint32_t buffer, int offset, const std::vector<std::uint8_t>& bytes) override {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferSubData(GL_TEXTURE_BUFFER, offset, GLsizeiptr(bytes.size()), bytes.data());
  }

  void TexBuffer(Enum target, Enum internal_format, std::uint32_t buffer) override {
    glTexBuffer(GLenum(target), GLenum(internal_format), buffer);
  }

  void DeleteBuffer(std::uint32_t buffer) override { glDeleteBuffers(1, &buffer); }

  void BindNewTexture(Enum target) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GLenum(target), tex);
  }

  void CompressedTexImage(int dims, Enum target, int level, Enum format, int w, int h, int d, int image_size,
                          const void* data) override {
    if (dims == 1) glCompressedTexImage1D(GLenum(target), level, GLenum(format), w, 0, image_size, data);
    else if (dims == 2) glCompressedTexImage2D(GLenum(target), level, GLenum(format), w, h, 0, image_size, data);
    else glCompressedTexImage3D(GLenum(target), level, GLenum(format), w, h, d, 0, image_size, data);
  }

  void CompressedTexSubImage(int dims, Enum target, int level, int x, int y, int z, int w, int h, int d, Enum format,
                             int image_size, const void* data) override {
    if (dims == 1) glCompressedTexSubImage1D(GLenum(target), level, x, w, GLenum(format), image_size, data);
    else if (dims == 2) glCompressedTexSubImage2D(GLenum(target), level, x, y, w, h, GLenum(format), image_size, data);
    else glCompressedTexSubImage3D(GLenum(target), level, x, y, z, w, h, d, GLenum(format), image_size, data);
  }

  std::vector<std::uint8_t> GetCompressedTexImage(Enum target, int level, int bytes) override {
    std::vector<std::uint8_t> out(std::size_t(bytes), 0xCD);
    glGetCompressedTexImage(GLenum(target), level, out.data());
    return out;
  }

  std::vector<float> GetTexImageFloats(Enum target, int level, int floats) override {
    std::vector<float> out(std::size_t(floats), -9.0f);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GLenum(target), level, GL_RGBA, GL_FLOAT, out.data());
    return out;
  }

  int GetTexLevelParameter(Enum target, int level, Enum pname) override {
    GLint v = -1;
    glGetTexLevelParameteriv(GLenum(target), level, GLenum(pname), &v);
    return v;
  }

  void TexImage2D(Enum target, int level, Enum internal_format, int w, int h) override {
    glTexImage2D(GLenum(target), level, GLint(internal_format), w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  }

  void TexSubImage2D(Enum target, int level, int x, int y, int w, int h, const std::uint8_t* rgba) override {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GLenum(target), level, x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  }

  void GenerateMipmap(Enum target) override { glGenerateMipmap(GLenum(target)); }

  void SetCubeTexture(int size, const std::vector<std::uint8_t> faces[6]) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f)
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(f), 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   faces[f].data());
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glActiveTexture(GL_TEXTURE0);
  }

  void SetShadowTexture(int size, const std::vector<float>& depth, Enum func, Enum filter) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GLint(func));
    glActiveTexture(GL_TEXTURE0);
  }

  void SetLayeredTexture(const LayeredDesc& d) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    const bool depth = !d.depth.empty();
    const GLenum target = GLenum(d.target);
    const bool one_d = d.target == softgl::TEXTURE_1D || d.target == softgl::TEXTURE_1D_ARRAY;
    glActiveTexture(GL_TEXTURE0 + (one_d ? 7 : depth ? 5 : d.target == softgl::TEXTURE_3D ? 4 : 3));
    glBindTexture(target, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (d.target == softgl::TEXTURE_1D)
      glTexImage1D(target, 0, GL_RGBA8, d.width, 0, GL_RGBA, GL_UNSIGNED_BYTE, d.rgba.data());
    else if (d.target == softgl::TEXTURE_1D_ARRAY)
      glTexImage2D(target, 0, GL_RGBA8, d.width, d.depth_or_layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, d.rgba.data());
    else if (depth)
      glTexImage3D(target, 0, GL_DEPTH_COMPONENT32F, d.width, d.height, d.depth_or_layers, 0, GL_DEPTH_COMPONENT,
                   GL_FLOAT, d.depth.data());
    else
      glTexImage3D(target, 0, GL_RGBA8, d.width, d.height, d.depth_or_layers, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   d.rgba.data());
    if (d.generate_mipmap) glGenerateMipmap(target);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GLint(d.min_filter));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GLint(d.mag_filter));
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GLint(d.wrap_s));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GLint(d.wrap_t));
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GLint(d.wrap_r));
    if (depth) {
      glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
      glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GLint(d.compare_func));
    }
    glActiveTexture(GL_TEXTURE0);
  }

  void BeginRenderToTexture(int width, int height) override {
    GLuint depth = 0, fbo = 0;
    glGenTextures(1, &rtt_color_);
    glBindTexture(GL_TEXTURE_2D, rtt_color_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenTextures(1, &depth);
    glBindTexture(GL_TEXTURE_2D, depth);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rtt_color_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    glViewport(0, 0, width, height);
  }

  void EndRenderToTexture() override {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w_, h_);
    glBindTexture(GL_TEXTURE_2D, rtt_color_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glUseProgram(programs_[3]);
    glUniform1i(glGetUniformLocation(programs_[3], "u_tex"), 0);
  }

  std::uint32_t GenFramebuffer() override { return GenOne(glGenFramebuffers); }
  void BindFramebuffer(Enum target, std::uint32_t framebuffer) override { glBindFramebuffer(target, framebuffer); }
  Enum CheckFramebufferStatus(Enum target) override { return glCheckFramebufferStatus(target); }
  std::uint32_t GenRenderbuffer() override { return GenOne(glGenRenderbuffers); }
  void BindRenderbuffer(std::uint32_t renderbuffer) override { glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer); }
  void RenderbufferStorage(Enum internal_format, int width, int height) override {
    glRenderbufferStorage(GL_RENDERBUFFER, internal_format, width, height);
  }
  void RenderbufferStorageMultisample(int samples, Enum internal_format, int width, int height) override {
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internal_format, width, height);
  }
  void SampleMask(std::uint32_t mask) override { glSampleMaski(0, mask); }
  void MinSampleShading(float value) override { glMinSampleShading(value); }  // (ARB_sample_shading in 3.3)
  void SampleCoverage(float value, bool invert) override { glSampleCoverage(value, invert ? GL_TRUE : GL_FALSE); }
  void FramebufferRenderbuffer(Enum target, Enum attachment, std::uint32_t renderbuffer) override {
    glFramebufferRenderbuffer(target, attachment, GL_RENDERBUFFER, renderbuffer);
  }
  void ReadBuffer(Enum src) override { glReadBuffer(src); }
  void DrawBuffers(int n, const Enum* bufs) override {
    std::vector<GLenum> b(bufs, bufs + n);
    glDrawBuffers(n, b.data());
  }
  void BlitFramebuffer(int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, std::uint32_t mask,
                       Enum filter) override {
    glBlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
  }
  void AttachNewMultisampleTexture(Enum target, Enum attachment, int samples, Enum internal_format, int width,
                                   int height) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    glFramebufferTexture2D(target, attachment, GL_TEXTURE_2D_MULTISAMPLE, tex, 0);
  }

  void AttachNewTexture(Enum target, Enum attachment, Enum internal_format, int width, int height) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    const bool ds = internal_format == GL_DEPTH24_STENCIL8 || internal_format == GL_DEPTH32F_STENCIL8;
    const bool depth = internal_format == GL_DEPTH_COMPONENT24 || internal_format == GL_DEPTH_COMPONENT32F;
    const GLenum format = ds ? GL_DEPTH_STENCIL : depth ? GL_DEPTH_COMPONENT : GL_RGBA;
    const GLenum type = internal_format == GL_DEPTH32F_STENCIL8 ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV
                        : ds                                     ? GL_UNSIGNED_INT_24_8
                        : depth                                  ? GL_FLOAT
                                                                 : GL_UNSIGNED_BYTE;
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glFramebufferTexture2D(target, attachment, GL_TEXTURE_2D, tex, 0);
  }

  std::uint32_t AttachLayered(Enum target, Enum attachment, Enum texture_target, Enum internal_format, int size,
                              int layers, int layer) override {
    const GLuint tex = GenOne(glGenTextures);
    const bool depth = internal_format == GL_DEPTH_COMPONENT32F;
    glActiveTexture(GL_TEXTURE0 + (depth ? 7 : texture_target == GL_TEXTURE_2D_ARRAY ? 3 : texture_target == GL_TEXTURE_3D ? 4 : 1));
    glBindTexture(texture_target, tex);
    const GLenum format = depth ? GL_DEPTH_COMPONENT : GL_RGBA, type = depth ? GL_FLOAT : GL_UNSIGNED_BYTE;
    if (texture_target == GL_TEXTURE_CUBE_MAP)
      for (int f = 0; f < layers; ++f)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(f), 0, internal_format, size, size, 0, format, type, nullptr);
    else
      glTexImage3D(texture_target, 0, internal_format, size, size, layers, 0, format, type, nullptr);
    glTexParameteri(texture_target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(texture_target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
    if (layer < 0) glFramebufferTexture(target, attachment, tex, 0);
    else if (texture_target == GL_TEXTURE_3D) glFramebufferTexture3D(target, attachment, GL_TEXTURE_3D, tex, 0, layer);
    else glFramebufferTextureLayer(target, attachment, tex, 0, layer);
    return tex;
  }
  void FramebufferTexture(Enum target, Enum attachment, std::uint32_t texture, int level) override {
    glFramebufferTexture(target, attachment, texture, level);
  }
  std::uint32_t NewMultisampleArray(int samples, Enum internal_format, int width, int height, int layers) override {
    const GLuint tex = GenOne(glGenTextures);
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
    glTexImage3DMultisample(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, samples, internal_format, width, height, layers, GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    return tex;
  }
  void TexImage3DMultisample(Enum target, int samples, Enum internal_format, int width, int height,
                             int layers) override {
    glTexImage3DMultisample(target, samples, internal_format, width, height, layers, GL_TRUE);
  }
  void FramebufferTextureLayer(Enum target, Enum attachment, std::uint32_t texture, int level, int layer) override {
    glFramebufferTextureLayer(target, attachment, texture, level, layer);
  }
  void FramebufferTexture3D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level,
                            int zoffset) override {
    glFramebufferTexture3D(target, attachment, textarget, texture, level, zoffset);
  }
  std::int64_t GetAttachmentParameter(Enum target, Enum attachment, Enum pname) override {
    GLint v = -12345;
    glGetFramebufferAttachmentParameteriv(target, attachment, pname, &v);
    return v;
  }

  std::vector<std::int64_t> GetIntegers(Enum pname, int count) override {
    std::vector<std::int64_t> v(std::size_t(count), -12345);
    std::vector<GLint> i(std::size_t(count), -12345);
    glGetIntegerv(pname, i.data());
    std::copy(i.begin(), i.end(), v.begin());
    return v;
  }
  std::vector<float> GetFloats(Enum pname, int count) override {
    std::vector<float> v(std::size_t(count), -12345.0f);
    glGetFloatv(pname, v.data());
    return v;
  }
  std::vector<bool> GetBooleans(Enum pname, int count) override {
    GLboolean b[4] = {};
    glGetBooleanv(pname, b);
    std::vector<bool> v;
    for (int k = 0; k < count; ++k) v.push_back(b[k] != GL_FALSE);
    return v;
  }
  Enum GetError() override { return glGetError(); }
  void CopyToTexture(int x, int y, int w, int h, int dx, int dy, int sx, int sy, int sw, int sh) override {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, x, y, w, h, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, dx, dy, sx, sy, sw, sh);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glUseProgram(programs_[3]);
    glUniform1i(glGetUniformLocation(programs_[3], "u_tex"), 0);
  }
  std::uint32_t GenSampler() override { return GenOne(glGenSamplers); }
  void BindSampler(int unit, std::uint32_t sampler) override { glBindSampler(GLuint(unit), sampler); }
  void SamplerParameteri(std::uint32_t sampler, Enum pname, int value) override { glSamplerParameteri(sampler, pname, value); }
  void SamplerParameterfv(std::uint32_t sampler, Enum pname, const float* values) override {
    glSamplerParameterfv(sampler, pname, values);
  }
  std::vector<std::int64_t> GetSamplerIntegers(std::uint32_t sampler, Enum pname, int count) override {
    std::vector<GLint> v(std::size_t(count), -12345);
    glGetSamplerParameteriv(sampler, pname, v.data());
    return {v.begin(), v.end()};
  }
  std::vector<float> GetSamplerFloats(std::uint32_t sampler, Enum pname, int count) override {
    std::vector<float> v(std::size_t(count), -12345.0f);
    glGetSamplerParameterfv(sampler, pname, v.data());
    return v;
  }
  std::vector<std::int64_t> GetVertexAttribIntegers(std::uint32_t index, Enum pname, int count) override {
    glBindVertexArray(vao_);
    std::vector<GLint> v(std::size_t(count), -12345);
    glGetVertexAttribiv(index, pname, v.data());
    return {v.begin(), v.end()};
  }
  std::vector<float> GetVertexAttribFloats(std::uint32_t index, Enum pname, int count) override {
    glBindVertexArray(vao_);
    std::vector<float> v(std::size_t(count), -12345.0f);
    glGetVertexAttribfv(index, pname, v.data());
    return v;
  }
  std::uint32_t GenQuery() override { return GenOne(glGenQueries); }
  void BeginQuery(Enum target, std::uint32_t id) override { glBeginQuery(target, id); }
  void EndQuery(Enum target) override { glEndQuery(target); }
  void VertexAttribP(int components, std::uint32_t index, Enum type, bool normalized, std::uint32_t value) override {
    switch (components) {
      case 1: glVertexAttribP1ui(index, type, normalized, value); break;
      case 2: glVertexAttribP2ui(index, type, normalized, value); break;
      case 3: glVertexAttribP3ui(index, type, normalized, value); break;
      case 4: glVertexAttribP4ui(index, type, normalized, value); break;
      default: glVertexAttribP4uiv(index, type, normalized, &value); break;
    }
  }
  void TexParameterI(Enum pname, const int* values, bool is_unsigned) override {
    glActiveTexture(GL_TEXTURE0);
    if (is_unsigned) glTexParameterIuiv(GL_TEXTURE_2D, pname, reinterpret_cast<const GLuint*>(values));
    else glTexParameterIiv(GL_TEXTURE_2D, pname, values);
  }
  std::vector<std::int64_t> GetTexParameterI(Enum pname, int count, bool is_unsigned) override {
    glActiveTexture(GL_TEXTURE0);
    GLint v[4] = {-7, -7, -7, -7};
    if (is_unsigned) glGetTexParameterIuiv(GL_TEXTURE_2D, pname, reinterpret_cast<GLuint*>(v));
    else glGetTexParameterIiv(GL_TEXTURE_2D, pname, v);
    std::vector<std::int64_t> out;
    for (int k = 0; k < count; ++k) out.push_back(is_unsigned ? std::int64_t(std::uint32_t(v[k])) : std::int64_t(v[k]));
    return out;
  }
  void BeginConditionalRender(std::uint32_t id, Enum mode) override { glBeginConditionalRender(id, mode); }
  void EndConditionalRender() override { glEndConditionalRender(); }
  const void* FenceSync(Enum condition, std::uint32_t flags) override { return glFenceSync(condition, flags); }
  bool IsSync(const void* sync) override { return glIsSync(Handle(sync)) == GL_TRUE; }
  void DeleteSync(const void* sync) override { glDeleteSync(Handle(sync)); }
  Enum ClientWaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) override {
    return glClientWaitSync(Handle(sync), flags, timeout);
  }
  void WaitSync(const void* sync, std::uint32_t flags, std::uint64_t timeout) override { glWaitSync(Handle(sync), flags, timeout); }
  int GetSynci(const void* sync, Enum pname) override {
    GLint v = -1;
    glGetSynciv(Handle(sync), pname, 1, nullptr, &v);
    return v;
  }
  void ClampColor(Enum target, Enum clamp) override { glClampColor(target, clamp); }
  void FeedbackVaryings(const std::vector<int>& which, Enum buffer_mode) override {
    static const char* const kNames[] = {"gl_Position", "v_color", "v_extra"};
    std::vector<const char*> names;
    for (int w : which) names.push_back(kNames[w]);
    const GLuint p = programs_[int(Program::kFeedback)];
    glTransformFeedbackVaryings(p, GLsizei(names.size()), names.data(), buffer_mode);
    if (glGetError() == GL_NO_ERROR) glLinkProgram(p);
    else glTransformFeedbackVaryings(p, -1, nullptr, buffer_mode);  // the error again, for the caller to read
  }
  std::uint32_t NewFeedbackBuffer(int floats) override {
    const GLuint id = GenOne(glGenBuffers);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, id);
    const std::vector<float> fill(std::size_t(floats), -7.0f);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(fill.size() * sizeof(float)), fill.data(), GL_STREAM_READ);
    return id;
  }
  std::vector<float> ReadBufferFloats(std::uint32_t buffer, int floats) override {
    std::vector<float> out(static_cast<std::size_t>(floats), 0.0f);
    glBindBuffer(GL_COPY_READ_BUFFER, buffer);
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
    return out;
  }
  void BindBufferBase(std::uint32_t index, std::uint32_t buffer) override {
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, index, buffer);
  }
  void BindBufferRange(std::uint32_t index, std::uint32_t buffer, std::ptrdiff_t offset, std::ptrdiff_t size) override {
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, index, buffer, offset, size);
  }
  void BeginTransformFeedback(Enum mode) override { glBeginTransformFeedback(mode); }
  void EndTransformFeedback() override { glEndTransformFeedback(); }
  void PauseTransformFeedback() override { glPauseTransformFeedback(); }
  void ResumeTransformFeedback() override { glResumeTransformFeedback(); }
  std::uint32_t GenTransformFeedback() override { return GenOne(glGenTransformFeedbacks); }
  void BindTransformFeedback(std::uint32_t id) override { glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, id); }
  void DrawTransformFeedback(Enum mode, std::uint32_t id) override {
    glUseProgram(programs_[int(Program::kFeedback)]);
    glDrawTransformFeedback(mode, id);
  }
  void ProvokingVertex(Enum convention) override { glProvokingVertex(convention); }
  static GLsync Handle(const void* sync) { return static_cast<GLsync>(const_cast<void*>(sync)); }
  std::uint64_t QueryResult(std::uint32_t id) override {
    GLuint v = ~0u;  // (OSMesa exports the 32-bit form; the counts here are small)
    glGetQueryObjectuiv(id, GL_QUERY_RESULT, &v);
    return v;
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

  std::vector<std::uint8_t> ReadPixels(const PixelRead& r, std::size_t bytes) override {
    std::vector<std::uint8_t> out(bytes, 0xCD);
    glPixelStorei(GL_PACK_ALIGNMENT, r.alignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, r.row_length);
    glPixelStorei(GL_PACK_SKIP_ROWS, r.skip_rows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, r.skip_pixels);
    glReadPixels(r.x, r.y, r.width, r.height, r.format, r.type, out.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);  // as Init leaves it
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    return out;
  }

 private:
  OSMesaContext ctx_;
  int w_, h_;
  std::vector<std::uint8_t> buffer_;
  GLuint programs_[23] = {};
  GLuint instanced_ = 0, integer_ = 0;
  GLuint integer_output_[2] = {}, integer_texture_[2] = {};  // [0] unsigned, [1] signed
  GLuint rtt_color_ = 0;
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

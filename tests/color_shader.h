// color_shader.h — the per-vertex colour shader that the unit tests and the conformance backend share. Public API
// only (softgl/softgl.h), so that any test program can include it.
#pragma once

#include <softgl/softgl.h>

namespace testing {

struct ColorVaryings {
  glm::vec4 color;
};

/// Position from attribute 0, colour from attribute 1 (interpolated as the shader's declared varyings are).
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

}  // namespace testing

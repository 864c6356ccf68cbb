// A wide vertex stage with a scalar fragment stage: one shader is written in one form. The control's fragment
// stage is wide too.
#include <softgl/softgl.h>

using namespace softgl;

struct NoVaryings {};

struct Mixed : Shader<Mixed, NoVaryings> {
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
#ifdef SOFTGL_MISUSE
  bool Fragment(const FragmentIn<NoVaryings>&, FragmentOut& out) const {
    out.color[0] = glm::vec4(1.0f);
    return true;
  }
#else
  void Fragment(const FragmentLanes<NoVaryings>&, FragmentLanesOut& out) const { out.color[0] = vec4(1.0f); }
#endif
};

int main() {
  Context gl(4, 4);
  Mixed shader;
  gl.UseProgram(shader);
  return 0;
}

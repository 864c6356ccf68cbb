// A wide shader with 68 floats of varyings (17 vec4): past kMaxVaryingFloats (64), the limit OpenGL calls
// GL_MAX_VARYING_COMPONENTS. The control has 16 vec4 (64 floats, the limit itself).
#include <softgl/softgl.h>

using namespace softgl;

struct Varyings {
#ifdef SOFTGL_MISUSE
  vec4 v[17];
#else
  vec4 v[16];
#endif
};

struct Heavy : Shader<Heavy, Varyings> {
  void Vertex(const VertexLanes& in, VertexLanesOut<Varyings>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<Varyings>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.v[0]; }
};

int main() {
  Context gl(4, 4);
  Heavy shader;
  gl.UseProgram(shader);
  return 0;
}

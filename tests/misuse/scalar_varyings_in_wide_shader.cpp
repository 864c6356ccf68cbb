// A wide shader whose varyings are GLM's one-lane vectors (a glm::vec3): they must be lane types (Float, vec2,
// vec3, vec4). The control declares softgl::vec3.
#include <softgl/softgl.h>

using namespace softgl;

struct Varyings {
#ifdef SOFTGL_MISUSE
  glm::vec3 normal;
#else
  vec3 normal;
#endif
};

struct Lit : Shader<Lit, Varyings> {
  void Vertex(const VertexLanes& in, VertexLanesOut<Varyings>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<Varyings>&, FragmentLanesOut& out) const { out.color[0] = vec4(1.0f); }
};

int main() {
  Context gl(4, 4);
  Lit shader;
  gl.UseProgram(shader);
  return 0;
}

// A fragment stage that reads other varyings than the vertex stage writes, with no geometry stage to make them.
// The control reads the vertex stage's.
#include <softgl/softgl.h>

using namespace softgl;

struct FromVertex {
  vec4 color;
};
struct Other {
  vec3 normal;
};
#ifdef SOFTGL_MISUSE
using FragmentReads = Other;
#else
using FragmentReads = FromVertex;
#endif

struct NoGeometry : Shader<NoGeometry, FromVertex, FragmentReads> {
  void Vertex(const VertexLanes& in, VertexLanesOut<FromVertex>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<FragmentReads>&, FragmentLanesOut& out) const { out.color[0] = vec4(1.0f); }
};

int main() {
  Context gl(4, 4);
  NoGeometry shader;
  gl.UseProgram(shader);
  return 0;
}

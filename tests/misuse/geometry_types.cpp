// A geometry stage whose output is not what the fragment stage reads: the program's stages do not fit, as a GLSL
// program whose stages' interfaces differ does not link. The control's geometry stage emits the fragment stage's
// varyings.
#include <softgl/softgl.h>

using namespace softgl;

struct FromVertex {
  vec4 color;
};
struct ToFragment {
  vec3 normal;
};

struct Mismatch : Shader<Mismatch, FromVertex, ToFragment> {
  static constexpr GeometryLayout kGeometry{TRIANGLES, TRIANGLE_STRIP, 3};
  void Vertex(const VertexLanes& in, VertexLanesOut<FromVertex>& out) const { out.position = in.attrib[0]; }
#ifdef SOFTGL_MISUSE
  void Geometry(const GeometryLanes<FromVertex>& in, GeometryLanesOut<FromVertex>& out) const {
#else
  void Geometry(const GeometryLanes<FromVertex>& in, GeometryLanesOut<ToFragment>& out) const {
#endif
    for (int k = 0; k < 3; ++k) {
      out.position = in.vertex[k].position;
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<ToFragment>& in, FragmentLanesOut& out) const {
    out.color[0] = vec4(in.varyings.normal, 1.0f);
  }
};

int main() {
  Context gl(4, 4);
  Mismatch shader;
  gl.UseProgram(shader);
  return 0;
}

// oom_check — run under a memory limit (ulimit -v, see tests/CMakeLists.txt): allocations too large for memory
// must come back as OUT_OF_MEMORY, never a crash, and the context must stay usable.
#include <cstdio>
#include <vector>

#include <softgl/softgl.h>

namespace {
int failures = 0;
void Expect(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}
struct Flat {};
struct FlatShader : softgl::Shader<FlatShader, Flat> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Flat>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const softgl::FragmentIn<Flat>&, softgl::FragmentOut& out) const {
    out.color[0] = glm::vec4(1.0f);
    return true;
  }
};
}  // namespace

int main() {
  using namespace softgl;
  Context huge(kMaxFramebufferSize, kMaxFramebufferSize);  // 2.4 GB: more than the limit
  Expect(huge.GetError() == OUT_OF_MEMORY, "a 16384 x 16384 framebuffer reports OUT_OF_MEMORY");
  Expect(huge.Width() == 0 && huge.Height() == 0, "and leaves a 0 x 0 framebuffer");

  Context gl(8, 8);
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, std::ptrdiff_t(3) << 30, nullptr);  // 3 GB
  Expect(gl.GetError() == OUT_OF_MEMORY, "a 3 GB buffer reports OUT_OF_MEMORY");
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  gl.TexImage2D(TEXTURE_2D, 0, RGBA32F, kMaxTextureSize, kMaxTextureSize, 0, RGBA, FLOAT, nullptr);  // 4 GB
  Expect(gl.GetError() == OUT_OF_MEMORY, "a 16384 x 16384 RGBA32F texture reports OUT_OF_MEMORY");

  // Still usable afterwards.
  const float tri[] = {-1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1};
  gl.BufferData(ARRAY_BUFFER, sizeof tri, tri);
  gl.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  FlatShader shader;
  gl.UseProgram(shader);
  gl.DrawArrays(TRIANGLES, 0, 3);
  std::uint8_t px[4];
  gl.ReadPixel(4, 4, px);
  Expect(gl.GetError() == NO_ERROR && px[0] == 255, "the context draws afterwards");
  std::printf("%d failed\n", failures);
  return failures ? 1 : 0;
}

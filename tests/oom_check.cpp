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

  // Deferred rendering keeps what a draw bins until it is rendered: 40,000 slivers along the diagonal of a
  // 512 x 512 framebuffer, whose bounding boxes cover all 64 tiles, with 64 floats of varyings, must fit in the
  // same limit: each tile list holds a 16-byte reference to such a primitive, not a copy of its 800 bytes of
  // vertices (copies would need 2 GB).
  struct Wide {
    float v[64];
  };
  struct WideShader : softgl::Shader<WideShader, Wide> {
    void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Wide>& out) const {
      out.position = in.attrib[0];
      for (int i = 0; i < 64; ++i) out.varyings.v[i] = in.attrib[0].x * float(i);
    }
    bool Fragment(const softgl::FragmentIn<Wide>& in, softgl::FragmentOut& out) const {
      out.color[0] = glm::vec4(in.varyings.v[63] > -1e9f ? 1.0f : 0.0f, 0.0f, 0.0f, 1.0f);
      return true;
    }
  };
  Context big(512, 512);
  std::vector<float> slivers;
  for (int i = 0; i < 40000; ++i) slivers.insert(slivers.end(), {-1, -1, 0, 1, 1, 1, 0, 1, 1, 0.98f, 0, 1});
  big.BindVertexArray(big.GenVertexArray());
  big.BindBuffer(ARRAY_BUFFER, big.GenBuffer());
  big.BufferData(ARRAY_BUFFER, std::ptrdiff_t(slivers.size() * sizeof(float)), slivers.data());
  big.VertexAttributePointer(0, 4, FLOAT, false, 0, 0);
  big.EnableVertexAttribArray(0);
  WideShader wide;
  big.UseProgram(wide);
  big.DrawArrays(TRIANGLES, 0, 120000);
  big.ReadPixel(500, 496, px);  // inside the sliver near its right end
  Expect(big.GetError() == NO_ERROR && px[0] == 255, "40,000 slivers over every tile, 64 varyings each, in bounded memory");

  std::printf("%d failed\n", failures);
  return failures ? 1 : 0;
}

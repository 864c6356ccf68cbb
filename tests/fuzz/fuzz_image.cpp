// fuzz_image — image decoding from random bytes (PNG, JPEG, TGA, BMP, HDR, ... through stb_image) into a texture,
// then mipmaps and sampling.
#include <softgl/softgl.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace softgl;
  Context gl(4, 4);
  gl.BindTexture(TEXTURE_2D, gl.GenTexture());
  std::string error;
  if (gl.TexImage2DFromMemory(TEXTURE_2D, data, size, size % 2 == 0, &error)) {
    gl.GenerateMipmap(TEXTURE_2D);
    gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  }
  (void)gl.GetError();
  return 0;
}

// fuzz_image — image decoding from random bytes (PNG, JPEG, TGA, BMP, HDR, ... through stb_image) into a texture,
// then mipmaps and sampling.
#include <softgl/softgl.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace softgl;
  // Images declaring more than a million pixels are skipped, as a server would: decoding a 16384 x 16384 image that
  // a few bytes declare is legitimate, only slow (ReadImageInfo is how a caller sets such a budget).
  int w = 0, h = 0, n = 0;
  if (ReadImageInfo(data, size, &w, &h, &n) && std::int64_t(w) * h > (1 << 20)) return 0;
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

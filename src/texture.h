// texture.h — texture objects: levels and faces, formats, uploads, mipmap generation and completeness.
// Every level stores RGBA floats (a depth texture keeps depth in r); fixed-point formats hold exact k/255 values.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/enums.h>
#include <softgl/texture.h>

namespace softgl::detail {

inline constexpr int kMaxLevels = 15;  // 16384 x 16384 down to 1 x 1

struct TextureLevel {
  Enum format = 0;  // internal format; 0: not defined
  int width = 0, height = 0;
  std::vector<float> texels;  // [height][width][4]
  bool Defined() const { return format != 0 && width > 0 && height > 0; }
  const float* At(int i, int j) const { return texels.data() + (std::size_t(j) * std::size_t(width) + std::size_t(i)) * 4; }
};

struct SamplerParams {
  Enum min_filter = NEAREST_MIPMAP_LINEAR;
  Enum mag_filter = LINEAR;
  Enum wrap_s = REPEAT, wrap_t = REPEAT, wrap_r = REPEAT;
  glm::vec4 border{0.0f};
  int base_level = 0, max_level = 1000;
  float min_lod = -1000.0f, max_lod = 1000.0f, lod_bias = 0.0f;
  Enum compare_mode = NONE, compare_func = LEQUAL;
};

struct TextureObject {
  Enum target = 0;  // TEXTURE_2D or TEXTURE_CUBE_MAP, fixed by the first bind
  TextureLevel levels[6][kMaxLevels];  // [face][level]; a 2D texture uses face 0
  SamplerParams params;
  int Faces() const { return target == TEXTURE_CUBE_MAP ? 6 : 1; }
};

/// A texture as one draw samples it: completeness and the levels in use resolved once.
struct TextureView {
  const TextureObject* texture = nullptr;
  bool complete = false;
  bool depth = false;  // a DEPTH_COMPONENT format
  int base = 0;        // level_base
  int q = 0;           // the last level mipmapped filtering may use
  // The common case, which Textures::Sample takes without re-deciding per sample: a 2D colour texture with
  // REPEAT in s and t on power-of-two sizes, LINEAR magnification, and LINEAR or LINEAR_MIPMAP_LINEAR
  // minification, no depth comparison.
  enum class Fast : unsigned char { kNone, kRepeatLinear, kRepeatTrilinear };
  Fast fast = Fast::kNone;
};

/// Resolves a texture for sampling (OpenGL 4.6, section 8.17, texture completeness).
TextureView MakeView(const TextureObject& texture);

/// Number of colour or depth channels of an internal format, 0 if softgl does not support it.
int FormatComponents(Enum internal_format);
bool IsDepthFormat(Enum internal_format);
bool IsNormalizedFormat(Enum internal_format);  // fixed point: RGBA8, RGB8, RG8, R8
/// Channels of a pixel transfer format (RED 1, RG 2, RGB 3, RGBA 4, DEPTH_COMPONENT 1), 0 if unknown.
int TransferComponents(Enum format);

/// Converts client pixels (format, type UNSIGNED_BYTE or FLOAT, rows aligned to `alignment`) into RGBA floats
/// for `internal_format`, writing rect (x, y, w, h) of `level` (already sized). Null pixels leave zeros.
void UploadPixels(TextureLevel& level, int x, int y, int w, int h, Enum format, Enum type, int alignment,
                  const void* pixels);

/// Fills levels base+1 .. the 1 x 1 level of each face from the base level: each texel is the bilinear sample of
/// the level above at its centre (the 2 x 2 box average for even sizes), in the base level's format.
void GenerateMipmaps(TextureObject& texture);

}  // namespace softgl::detail

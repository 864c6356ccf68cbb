// texture.cpp — texture storage: formats, uploads, mipmap generation, completeness.
#include "texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "framebuffer.h"

namespace softgl::detail {

int FormatComponents(Enum f) {
  switch (f) {
    case R8:
    case R32F:
    case DEPTH_COMPONENT:
    case DEPTH_COMPONENT24:
    case DEPTH_COMPONENT32F: return 1;
    case RG8: return 2;
    case RGB8: return 3;
    case RGBA8:
    case RGBA32F: return 4;
    default: return 0;
  }
}

bool IsDepthFormat(Enum f) { return f == DEPTH_COMPONENT || f == DEPTH_COMPONENT24 || f == DEPTH_COMPONENT32F; }

bool IsNormalizedFormat(Enum f) { return f == R8 || f == RG8 || f == RGB8 || f == RGBA8; }

int TransferComponents(Enum format) {
  switch (format) {
    case RED:
    case DEPTH_COMPONENT: return 1;
    case RG: return 2;
    case RGB: return 3;
    case RGBA: return 4;
    default: return 0;
  }
}

namespace {

// A value as the internal format stores it: fixed point clamped and rounded to k/255, depth clamped to [0, 1].
float Quantize(Enum internal_format, float v) {
  if (std::isnan(v)) v = 0.0f;
  if (IsNormalizedFormat(internal_format)) return float(FloatToUnorm8(v)) / 255.0f;
  if (IsDepthFormat(internal_format)) return std::clamp(v, 0.0f, 1.0f);
  return v;
}

// The stored texel of a format with n components: missing ones read (0, 0, 0, 1).
void StoreTexel(Enum internal_format, const float in[4], float* out) {
  const int n = FormatComponents(internal_format);
  const float defaults[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int c = 0; c < 4; ++c) out[c] = c < n ? Quantize(internal_format, in[c]) : defaults[c];
}

}  // namespace

void UploadPixels(TextureLevel& level, int x, int y, int w, int h, Enum format, Enum type, int alignment,
                  const void* pixels) {
  if (pixels == nullptr || w <= 0 || h <= 0) return;
  const int n = TransferComponents(format);
  const std::size_t csize = type == FLOAT ? 4 : 1;
  std::size_t row = std::size_t(w) * std::size_t(n) * csize;
  row = (row + std::size_t(alignment) - 1) / std::size_t(alignment) * std::size_t(alignment);
  const auto* bytes = static_cast<const std::uint8_t*>(pixels);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::uint8_t* p = bytes + std::size_t(j) * row + std::size_t(i) * std::size_t(n) * csize;
      float in[4] = {0.0f, 0.0f, 0.0f, 1.0f};
      for (int c = 0; c < n; ++c) {
        if (type == FLOAT) std::memcpy(&in[c], p + 4 * c, 4);
        else in[c] = float(p[c]) / 255.0f;
      }
      float* dst = level.texels.data() + (std::size_t(y + j) * std::size_t(level.width) + std::size_t(x + i)) * 4;
      StoreTexel(level.format, in, dst);
    }
}

void GenerateMipmaps(TextureObject& texture) {
  const int base = std::clamp(texture.params.base_level, 0, kMaxLevels - 1);
  for (int face = 0; face < texture.Faces(); ++face) {
    for (int l = base + 1; l < kMaxLevels; ++l) {
      const TextureLevel& src = texture.levels[face][l - 1];
      if (src.width == 1 && src.height == 1) {
        for (int k = l; k < kMaxLevels; ++k) texture.levels[face][k] = TextureLevel{};
        break;
      }
      TextureLevel& dst = texture.levels[face][l];
      dst.format = src.format;
      dst.width = std::max(1, src.width / 2);
      dst.height = std::max(1, src.height / 2);
      dst.texels.assign(std::size_t(dst.width) * std::size_t(dst.height) * 4, 0.0f);
      for (int j = 0; j < dst.height; ++j)
        for (int i = 0; i < dst.width; ++i) {
          // Bilinear sample of src at this texel's centre, clamped to the edge.
          const float u = (float(i) + 0.5f) * float(src.width) / float(dst.width) - 0.5f;
          const float v = (float(j) + 0.5f) * float(src.height) / float(dst.height) - 0.5f;
          const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
          const float a = u - float(i0), b = v - float(j0);
          float sum[4] = {0, 0, 0, 0};
          for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) {
              const float wgt = (di ? a : 1.0f - a) * (dj ? b : 1.0f - b);
              const float* t = src.At(std::clamp(i0 + di, 0, src.width - 1), std::clamp(j0 + dj, 0, src.height - 1));
              for (int c = 0; c < 4; ++c) sum[c] += wgt * t[c];
            }
          StoreTexel(dst.format, sum, dst.texels.data() + (std::size_t(j) * std::size_t(dst.width) + std::size_t(i)) * 4);
        }
    }
  }
}

TextureView MakeView(const TextureObject& texture) {
  TextureView view;
  view.texture = &texture;
  const SamplerParams& p = texture.params;
  view.base = p.base_level;
  if (p.base_level < 0 || p.base_level >= kMaxLevels || p.base_level > p.max_level) return view;
  const TextureLevel& base = texture.levels[0][p.base_level];
  if (!base.Defined()) return view;
  view.depth = IsDepthFormat(base.format);
  // q: the last level of the chain, level_base + floor(log2(max size)), but at most level_max.
  int levels = 0;
  for (int size = std::max(base.width, base.height); size > 1; size >>= 1) ++levels;
  view.q = std::min({p.base_level + levels, p.max_level, kMaxLevels - 1});
  const bool mipmapped = p.min_filter != NEAREST && p.min_filter != LINEAR;
  const int last = mipmapped ? view.q : p.base_level;
  for (int face = 0; face < texture.Faces(); ++face) {
    for (int l = p.base_level; l <= last; ++l) {
      const TextureLevel& lv = texture.levels[face][l];
      const int shift = l - p.base_level;
      if (lv.format != base.format || lv.width != std::max(1, base.width >> shift) ||
          lv.height != std::max(1, base.height >> shift))
        return view;
    }
  }
  if (texture.target == TEXTURE_CUBE_MAP && base.width != base.height) return view;
  view.complete = true;
  const bool pow2 = (base.width & (base.width - 1)) == 0 && (base.height & (base.height - 1)) == 0;
  if (texture.target == TEXTURE_2D && !view.depth && pow2 && p.wrap_s == REPEAT && p.wrap_t == REPEAT &&
      p.mag_filter == LINEAR && p.compare_mode == NONE) {
    if (p.min_filter == LINEAR) view.fast = TextureView::Fast::kRepeatLinear;
    if (p.min_filter == LINEAR_MIPMAP_LINEAR) view.fast = TextureView::Fast::kRepeatTrilinear;
  }
  return view;
}

}  // namespace softgl::detail

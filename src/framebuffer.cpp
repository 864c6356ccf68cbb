// framebuffer.cpp — storage, format conversion on store, and clears.
#include "framebuffer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

namespace softgl::detail {

std::uint8_t FloatToUnorm8(float f) {
  if (!(f > 0.0f)) return 0;  // also NaN
  if (f >= 1.0f) return 255;
  return std::uint8_t(std::lrint(f * 255.0f));
}

glm::vec4 ColorBuffer::Load(int x, int y) const {
  glm::vec4 raw = RawTexel(layout, At(x, y));
  if (rgb_only) raw.a = 255.0f;
  if (srgb) return glm::vec4(SrgbDecode8(std::uint8_t(raw.r)), SrgbDecode8(std::uint8_t(raw.g)),
                             SrgbDecode8(std::uint8_t(raw.b)), raw.a / 255.0f);
  return raw / StorageScale(layout);
}

void ColorBuffer::Store(int x, int y, const glm::vec4& c, const bool mask[4]) const {
  std::uint8_t* p = At(x, y);
  switch (layout) {
    case TexelLayout::kUnorm8x4:
    case TexelLayout::kUnorm8x2:
    case TexelLayout::kUnorm8x1: {
      const int n = layout == TexelLayout::kUnorm8x4 ? (rgb_only ? 3 : 4) : layout == TexelLayout::kUnorm8x2 ? 2 : 1;
      for (int k = 0; k < n; ++k)
        if (mask[k]) p[k] = srgb && k < 3 ? SrgbEncode8(c[k]) : FloatToUnorm8(c[k]);
      return;
    }
    case TexelLayout::kFloat32x4:
      for (int k = 0; k < 4; ++k)
        if (mask[k]) std::memcpy(p + 4 * k, &c[k], 4);
      return;
    case TexelLayout::kFloat32x1:
      if (mask[0]) std::memcpy(p, &c[0], 4);
      return;
    default: {  // the other float layouts: the masked channels replaced, the texel encoded again
      glm::vec4 v = RawTexel(layout, p);
      for (int k = 0; k < 4; ++k)
        if (mask[k]) v[k] = c[k];
      StoreSmallFloatTexel(layout, p, v);
      return;
    }
  }
}

void RenderTarget::ClearColor(const Rect& r, const glm::vec4& value, const bool mask[4]) const {
  for (const ColorBuffer& cb : color) {
    if (!cb.Present() || r.Empty()) continue;
    if (cb.layout == TexelLayout::kUnorm8x4) {
      // The pixel is converted once, then stored row by row as 32-bit words through the mask.
      std::uint8_t px[4], keep_bytes[4];
      for (int k = 0; k < 4; ++k) {
        px[k] = cb.srgb && k < 3 ? SrgbEncode8(value[k]) : FloatToUnorm8(value[k]);
        keep_bytes[k] = mask[k] && !(k == 3 && cb.rgb_only) ? 0x00 : 0xFF;
      }
      std::uint32_t word, keep;
      std::memcpy(&word, px, 4);
      std::memcpy(&keep, keep_bytes, 4);
      std::uint8_t run[64];  // 16 pixels
      for (int k = 0; k < 16; ++k) std::memcpy(run + 4 * k, &word, 4);
      const int width = r.x1 - r.x0;
      for (int y = r.y0; y < r.y1; ++y) {
        std::uint8_t* row = cb.At(r.x0, y);
        if (keep == 0) {  // every channel written: copies of 16 pixels, then the rest
          int x = 0;
          for (; x + 16 <= width; x += 16) std::memcpy(row + 4 * x, run, 64);
          std::memcpy(row + 4 * x, run, std::size_t(4 * (width - x)));
          continue;
        }
        for (int x = 0; x < width; ++x) {
          std::uint32_t old;
          std::memcpy(&old, row + 4 * x, 4);
          const std::uint32_t out = (old & keep) | (word & ~keep);
          std::memcpy(row + 4 * x, &out, 4);
        }
      }
      continue;
    }
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) cb.Store(x, y, value, mask);
  }
}

void RenderTarget::ClearDepth(const Rect& r, float value) const {
  if (!depth || r.Empty()) return;
  for (int y = r.y0; y < r.y1; ++y) std::fill_n(&Depth(r.x0, y), r.x1 - r.x0, value);
}

void RenderTarget::ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask) const {
  if (!stencil || r.Empty()) return;
  for (int y = r.y0; y < r.y1; ++y) {
    if (write_mask == 0xFF) {  // every bit written: a fill of the row
      std::memset(&Stencil(r.x0, y), value, std::size_t(r.x1 - r.x0));
      continue;
    }
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = Stencil(x, y);
      s = std::uint8_t((s & ~write_mask) | (value & write_mask));
    }
  }
}

namespace {

// Where destination pixels [d0, d1) along one axis read: the source coordinate of each pixel centre, for the
// rectangles' edges s0, s1 (source) and e0, e1 (destination).
struct BlitAxis {
  int d0 = 0, d1 = 0;  // destination pixels written, clipped
  double s0 = 0, scale = 0, e0 = 0;
  double At(int d) const { return s0 + (double(d) + 0.5 - e0) * scale; }
};
BlitAxis MakeAxis(int s0, int s1, int e0, int e1, int clip0, int clip1) {
  BlitAxis a;
  a.s0 = s0;
  a.e0 = e0;
  a.scale = (double(s1) - double(s0)) / (double(e1) - double(e0));
  a.d0 = std::max(std::min(e0, e1), clip0);
  a.d1 = std::min(std::max(e0, e1), clip1);
  return a;
}

// The pixel index holding coordinate c, or -1 outside [0, size).
int PixelAt(double c, int size) {
  if (!(c >= 0.0) || c >= double(size)) return -1;
  return int(c);
}

}  // namespace

void Blit(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r) {
  if (r.src[0] == r.src[2] || r.src[1] == r.src[3] || r.dst[0] == r.dst[2] || r.dst[1] == r.dst[3]) return;
  const BlitAxis ax =
      MakeAxis(r.src[0], r.src[2], r.dst[0], r.dst[2], std::max(r.clip.x0, 0), std::min(r.clip.x1, dst.width));
  const BlitAxis ay =
      MakeAxis(r.src[1], r.src[3], r.dst[1], r.dst[3], std::max(r.clip.y0, 0), std::min(r.clip.y1, dst.height));
  if (ax.d0 >= ax.d1 || ay.d0 >= ay.d1) return;
  const bool all[4] = {true, true, true, true};
  for (int y = ay.d0; y < ay.d1; ++y) {
    const double sy = ay.At(y);
    const int py = PixelAt(sy, src.height);
    if (py < 0) continue;
    for (int x = ax.d0; x < ax.d1; ++x) {
      const double sx = ax.At(x);
      const int px = PixelAt(sx, src.width);
      if (px < 0) continue;
      if (r.color) {
        glm::vec4 c;
        if (r.linear) {  // bilinear between pixel centres, clamped to the edge
          const double u = sx - 0.5, v = sy - 0.5;
          const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
          const float a = float(u - i0), b = float(v - j0);
          const int i1 = std::min(i0 + 1, src.width - 1), j1 = std::min(j0 + 1, src.height - 1);
          const int ic = std::max(i0, 0), jc = std::max(j0, 0);
          const ColorBuffer& cb = src.color[0];
          c = (1.0f - b) * ((1.0f - a) * cb.Load(ic, jc) + a * cb.Load(i1, jc)) +
              b * ((1.0f - a) * cb.Load(ic, j1) + a * cb.Load(i1, j1));
        } else {
          c = src.color[0].Load(px, py);
        }
        for (const ColorBuffer& cb : dst.color)
          if (cb.Present()) cb.Store(x, y, c, all);
      }
      if (r.depth) dst.Depth(x, y) = src.Depth(px, py);
      if (r.stencil) dst.Stencil(x, y) = src.Stencil(px, py);
    }
  }
}

bool Framebuffer::Allocate(int w, int h) {
  width = height = 0;
  color.clear();
  depth.clear();
  stencil.clear();
  const std::size_t n = std::size_t(w) * std::size_t(h);
  try {
    color.assign(n * std::size_t(BytesPerTexel(layout)), 0);
    depth.assign(n, 1.0f);
    stencil.assign(n, 0);
  } catch (const std::bad_alloc&) {
    color = {};
    depth = {};
    stencil = {};
    return false;
  }
  width = w;
  height = h;
  return true;
}

RenderTarget Framebuffer::Target(bool srgb_enabled) {
  RenderTarget t;
  t.width = width;
  t.height = height;
  if (width > 0 && height > 0) {
    t.color[0].data = color.data();
    t.color[0].layout = layout;
    t.color[0].srgb = srgb && srgb_enabled;
    t.color[0].pitch = width;
    t.depth = depth.data();
    t.depth_pitch = width;
    t.stencil = stencil.data();
    t.stencil_pitch = width;
  }
  return t;
}

}  // namespace softgl::detail

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
  const std::size_t i = Index(x, y);
  if (rgba8) {
    const std::uint8_t* p = rgba8 + i * 4;
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  }
  const float* p = texels + i * 4;
  return glm::vec4(p[0], p[1], p[2], p[3]);
}

void ColorBuffer::Store(int x, int y, const glm::vec4& c, const bool mask[4]) const {
  const std::size_t i = Index(x, y);
  if (rgba8) {
    std::uint8_t* p = rgba8 + i * 4;
    for (int k = 0; k < 4; ++k)
      if (mask[k]) p[k] = FloatToUnorm8(c[k]);
    return;
  }
  float* p = texels + i * 4;
  for (int k = 0; k < components; ++k)
    if (mask[k]) p[k] = normalized ? float(FloatToUnorm8(c[k])) / 255.0f : c[k];
}

void RenderTarget::ClearColor(const Rect& r, const glm::vec4& value, const bool mask[4]) const {
  for (const ColorBuffer& cb : color) {
    if (!cb.Present() || r.Empty()) continue;
    if (cb.rgba8) {
      // The pixel is converted once, then stored row by row as 32-bit words through the mask.
      std::uint8_t px[4], keep_bytes[4];
      for (int k = 0; k < 4; ++k) {
        px[k] = FloatToUnorm8(value[k]);
        keep_bytes[k] = mask[k] ? 0x00 : 0xFF;
      }
      std::uint32_t word, keep;
      std::memcpy(&word, px, 4);
      std::memcpy(&keep, keep_bytes, 4);
      for (int y = r.y0; y < r.y1; ++y) {
        std::uint8_t* row = cb.rgba8 + cb.Index(r.x0, y) * 4;
        for (int x = 0; x < r.x1 - r.x0; ++x) {
          std::uint32_t old = 0;
          if (keep) std::memcpy(&old, row + 4 * x, 4);
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
  if (!depth) return;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) Depth(x, y) = value;
}

void RenderTarget::ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask) const {
  if (!stencil) return;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = Stencil(x, y);
      s = std::uint8_t((s & ~write_mask) | (value & write_mask));
    }
}

bool Framebuffer::Allocate(int w, int h) {
  width = height = 0;
  color.clear();
  depth.clear();
  stencil.clear();
  const std::size_t n = std::size_t(w) * std::size_t(h);
  try {
    color.assign(n * 4, 0);
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

RenderTarget Framebuffer::Target() {
  RenderTarget t;
  t.width = width;
  t.height = height;
  if (width > 0 && height > 0) {
    t.color[0].rgba8 = color.data();
    t.color[0].pitch = width;
    t.depth = depth.data();
    t.depth_pitch = width;
    t.stencil = stencil.data();
  }
  return t;
}

}  // namespace softgl::detail

// framebuffer.cpp — storage and clears.
#include "framebuffer.h"

#include <algorithm>
#include <cstring>
#include <new>

namespace softgl::detail {

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

void Framebuffer::ClearColor(const Rect& r, const std::uint8_t rgba[4], const bool mask[4]) {
  const bool all = mask[0] && mask[1] && mask[2] && mask[3];
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t* px = &color[Index(x, y) * 4];
      if (all) {
        std::memcpy(px, rgba, 4);
      } else {
        for (int c = 0; c < 4; ++c)
          if (mask[c]) px[c] = rgba[c];
      }
    }
}

void Framebuffer::ClearDepth(const Rect& r, float value) {
  for (int y = r.y0; y < r.y1; ++y) std::fill(&depth[Index(r.x0, y)], &depth[Index(r.x0, y)] + (r.x1 - r.x0), value);
}

void Framebuffer::ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask) {
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = stencil[Index(x, y)];
      s = std::uint8_t((s & ~write_mask) | (value & write_mask));
    }
}

}  // namespace softgl::detail

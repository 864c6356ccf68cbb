// framebuffer.h — the offscreen framebuffer: RGBA8 colour, 32-bit float depth, 8-bit stencil.
// Row 0 is the bottom row, as in OpenGL's window coordinates.
#pragma once

#include <cstdint>
#include <vector>

#include "types.h"

namespace softgl::detail {

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> color;  // [height][width][4]
  std::vector<float> depth;         // [height][width]
  std::vector<std::uint8_t> stencil;

  /// Allocates width x height pixels (colour 0, depth 1, stencil 0). Returns false, leaving a 0 x 0 framebuffer,
  /// if the memory cannot be had.
  bool Allocate(int w, int h);
  std::size_t Index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
  Rect Bounds() const { return Rect{0, 0, width, height}; }

  /// Clears rectangle r (inside the framebuffer) of the colour buffer, writing only the channels in mask.
  void ClearColor(const Rect& r, const std::uint8_t rgba[4], const bool mask[4]);
  void ClearDepth(const Rect& r, float value);
  /// Clears the stencil bits of write_mask in rectangle r.
  void ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask);
};

}  // namespace softgl::detail

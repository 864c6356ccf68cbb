// snap_wide.h — the rasterizer's snapping of window positions to its subpixel grid (rasterizer.h), W positions
// per instruction: for the front end's verdict on groups of triangles (culling.cpp) and the rasterizer's set-up of
// groups of triangles (rasterizer.cpp). Included only by units compiled with -Wno-psabi (wide.h).
#pragma once

#include "rasterizer.h"
#include "wide.h"

namespace softgl::detail {

/// x and y snapped to 1/2^kSubpixelBits pixel, rounded to nearest even as the rasterizer's one-triangle snapping
/// (llrint) rounds them: x * 256 is exact in float, and adding then subtracting 1.5 * 2^23 rounds it to an
/// integer, for |x * 256| < 2^22 (16384 pixels). Returns the lanes where both lie in that range; the others (NaN
/// included) get 0, so that no conversion overflows.
template <int W>
SOFTGL_WIDE typename V<W>::I SnapLanes(typename V<W>::F x, typename V<W>::F y, typename V<W>::I& X,
                                       typename V<W>::I& Y) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  static_assert(kSubpixelBits == 8, "the range below is 2^22 / 2^8 pixels");
  constexpr float kRound = 12582912.0f;  // 1.5 * 2^23
  F sx = x * 256.0f, sy = y * 256.0f;
  const I in_range = I(sx < 4194304.0f) & I(sx > -4194304.0f) & I(sy < 4194304.0f) & I(sy > -4194304.0f);
  sx = F(I(sx) & in_range);
  sy = F(I(sy) & in_range);
  X = __builtin_convertvector((sx + kRound) - kRound, I);
  Y = __builtin_convertvector((sy + kRound) - kRound, I);
  return in_range;
}

}  // namespace softgl::detail

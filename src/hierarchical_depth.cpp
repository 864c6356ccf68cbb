// hierarchical_depth.cpp — the coarse depth bounds of a tile and the test against them (see the header).
#include "hierarchical_depth.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "wide.h"

namespace softgl::detail {

void HierarchicalDepth::Refresh(int index) {
  const RenderTarget& t = *target;
  const int x0 = tile.x0 + (index % kPerRow) * kBlock, y0 = tile.y0 + (index / kPerRow) * kBlock;
  const int x1 = std::min(x0 + kBlock, t.width), y1 = std::min(y0 + kBlock, t.height);
  // Stored values outside [0, 1] (a depth texture's upload may hold them) take part as they are; NaN, which no
  // fragment passes against, is left out by the comparisons. No pixel: +inf and -inf (no fragment comes there).
  float l = INFINITY, h = -INFINITY;
  if (x1 - x0 == kBlock && y1 > y0) {  // whole rows, eight values at a time
    // A row's samples: one run of kBlock * step values (a multiple of 8) in each sample plane, or in the one plane
    // where each pixel's samples lie side by side (interleaved).
    const int planes = t.interleaved ? 1 : t.samples, run = kBlock * t.step;
    if (!t.depth16) {
      using F4 = V<4>::F;  // (two of them: the baseline's vectors)
      F4 vl0 = F4{} + INFINITY, vh0 = F4{} - INFINITY, vl1 = vl0, vh1 = vh0;
      for (int s = 0; s < planes; ++s)
        for (int y = y0; y < y1; ++y) {
          const float* row = t.depth + t.DepthIndex(x0, y, s);
          for (int k = 0; k < run; k += 8) {
            const F4 a = LoadVec<F4>(row + k), b = LoadVec<F4>(row + k + 4);
            vl0 = a < vl0 ? a : vl0;
            vh0 = a > vh0 ? a : vh0;
            vl1 = b < vl1 ? b : vl1;
            vh1 = b > vh1 ? b : vh1;
          }
        }
      for (int k = 0; k < 4; ++k) {
        l = vl0[k] < l ? vl0[k] : l;
        l = vl1[k] < l ? vl1[k] : l;
        h = vh0[k] > h ? vh0[k] : h;
        h = vh1[k] > h ? vh1[k] : h;
      }
    } else {  // the least and greatest stored integers, then their values k / 65535 (DepthAt's)
      using U8 = std::uint16_t __attribute__((vector_size(16)));
      U8 vl = U8{} + 0xFFFF, vh = U8{};
      for (int s = 0; s < planes; ++s)
        for (int y = y0; y < y1; ++y) {
          const std::uint16_t* row = t.depth16 + t.DepthIndex(x0, y, s);
          for (int k = 0; k < run; k += 8) {
            U8 v;
            std::memcpy(&v, row + k, sizeof v);
            vl = v < vl ? v : vl;
            vh = v > vh ? v : vh;
          }
        }
      unsigned ml = 0xFFFF, mh = 0;
      for (int k = 0; k < 8; ++k) {
        ml = vl[k] < ml ? vl[k] : ml;
        mh = vh[k] > mh ? vh[k] : mh;
      }
      l = float(ml) / 65535.0f;
      h = float(mh) / 65535.0f;
    }
  } else {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
        for (int s = 0; s < t.samples; ++s) {  // (every sample of a multisampled buffer)
          const float v = t.DepthAt(x, y, s);
          l = v < l ? v : l;
          h = v > h ? v : h;
        }
  }
  lo[index] = l;
  hi[index] = h;
  stale[index] = 0;
  asks[index] = 0;
}

bool HierarchicalDepth::Hides(const Plane& z, float x0, float y0, int px0, int py0, int px1, int py1) {
  const bool nearer = func == LESS || func == LEQUAL;
  if ((nearer && hi_wrong) || (!nearer && lo_wrong)) TouchAll();
  // The plane's least (greatest) value over the pixels' area (every centre and sample in it), less (plus) the most
  // that the fragments' evaluation (a0 + dx rx) + dy ry, rx = (x + 0.5) - x0 rounded, and this one can differ from
  // the exact value: some ten roundings, each within 2^-24 of the terms' magnitude m, against a margin of 2^-16 m
  // (and a little more for values near the smallest floats).
  const float ax = float(px0) - x0, bx = float(px1 + 1) - x0, ay = float(py0) - y0, by = float(py1 + 1) - y0;
  const float tx0 = z.dx * ax, tx1 = z.dx * bx, ty0 = z.dy * ay, ty1 = z.dy * by;
  const float m = std::fabs(z.a0) + std::max(std::fabs(tx0), std::fabs(tx1)) + std::max(std::fabs(ty0), std::fabs(ty1));
  const float margin = m * 0x1p-16f + 0x1p-100f;
  const float bound = nearer ? (z.a0 + std::min(tx0, tx1)) + std::min(ty0, ty1) - margin
                             : (z.a0 + std::max(tx0, tx1)) + std::max(ty0, ty1) + margin;
  if (!(bound == bound)) return false;  // NaN: no bound (such fragments fail the test anyway)
  // The fragments' depths as the test sees them: clamped to [0, 1] (an infinite bound too), as the buffer keeps
  // them; both monotonic, so the bound stays a bound.
  const float d = target->StoredDepth(bound > 0.0f ? (bound < 1.0f ? bound : 1.0f) : 0.0f);
  // The nearest and farthest stored depths under the pixels. A stale block is read now; one due to be read again
  // (kAsks asks since) only if the bounds as they stand do not hide the plane: they are bounds still, only looser,
  // so a plane they hide stays hidden, and the reading is saved.
  const int bx0 = (px0 - tile.x0) / kBlock, bx1 = (px1 - tile.x0) / kBlock;
  const int by0 = (py0 - tile.y0) / kBlock, by1 = (py1 - tile.y0) / kBlock;
  std::uint64_t due = 0;  // (one bit per block: kBlocks is 64)
  auto hidden = [&] {
    float stored_lo = INFINITY, stored_hi = -INFINITY;
    for (int row = by0; row <= by1; ++row)
      for (int col = bx0; col <= bx1; ++col) {
        const int i = row * kPerRow + col;
        stored_lo = std::min(stored_lo, lo[i]);
        stored_hi = std::max(stored_hi, hi[i]);
      }
    switch (func) {
      case LESS: return d >= stored_hi;
      case LEQUAL: return d > stored_hi;
      case GREATER: return d <= stored_lo;
      default: return d < stored_lo;  // GEQUAL
    }
  };
  for (int row = by0; row <= by1; ++row)
    for (int col = bx0; col <= bx1; ++col) {
      const int i = row * kPerRow + col;
      if (stale[i]) Refresh(i);
      else if (++asks[i] >= kAsks) due |= std::uint64_t(1) << i;
    }
  if (hidden()) return true;
  if (!due) return false;
  for (; due; due &= due - 1) Refresh(std::countr_zero(due));
  return hidden();
}

}  // namespace softgl::detail

// rasterizer.cpp — coverage and interpolation for triangles, lines and points.
#include "rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#if defined(__SSE2__)
#include <xmmintrin.h>
#include <emmintrin.h>
#endif

namespace softgl::detail {

namespace {

constexpr std::int64_t kOne = std::int64_t(1) << kSubpixelBits;
constexpr std::int64_t kHalf = kOne / 2;

std::int64_t FloorDiv(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// Makes room for one more quad: flushes a full buffer, or one holding quads of the other facing.
void Reserve(QuadBuffer& quads, const QuadSink& sink, bool front_facing, int nvar) {
  if (quads.count == QuadBuffer::kCapacity || (quads.count > 0 && quads.front_facing != front_facing))
    sink.Flush(quads);
  quads.front_facing = front_facing;
  quads.nvar = nvar;
}

// Appends the quad with origin (qx, qy) and coverage `mask` (bit = lane); `eval(lane, px, py, frag, var)` fills
// every lane, helper lanes included, so that the fragment stage can take derivatives.
template <class Eval>
void EmitQuad(QuadBuffer& quads, const QuadSink& sink, bool front_facing, int nvar, int qx, int qy, unsigned mask,
              Eval&& eval) {
  Reserve(quads, sink, front_facing, nvar);
  const int q = quads.count++;
  quads.qx[q] = qx;
  quads.qy[q] = qy;
  for (int lane = 0; lane < 4; ++lane) {
    const int l = q * 4 + lane;
    quads.live[l] = (mask >> lane) & 1u;
    eval(qx + (lane & 1), qy + (lane >> 1), quads.frag_coord[l], quads.varyings + std::size_t(l) * nvar);
  }
}

unsigned BoundsMask(const Rect& bounds, int qx, int qy) {
  unsigned mask = 0;
  for (int lane = 0; lane < 4; ++lane) {
    const int px = qx + (lane & 1), py = qy + (lane >> 1);
    if (px >= bounds.x0 && px < bounds.x1 && py >= bounds.y0 && py < bounds.y1) mask |= 1u << lane;
  }
  return mask;
}

// a + dx * x + dy * y: an attribute's plane in window space, relative to vertex 0.
struct Plane {
  float a0, dx, dy;
  float At(float x, float y) const { return a0 + dx * x + dy * y; }
};

// gl_FragCoord and perspective-correct varyings for the four lanes of a quad, every lane (helpers included):
// with r = pixel centre - vertex 0, q = 1/w = oow(r), varying = plane(r) / q. The four lanes are computed side
// by side with the same operations in the same order as one lane at a time.
struct QuadInterpolator {
  float x0, y0;
  Plane z, oow;
  const Plane* var;
  int nvar;

  void Quad(int qx, int qy, glm::vec4* frag, float* out) const {
#if defined(__SSE2__)
    const __m128 fx = _mm_add_ps(_mm_setr_ps(float(qx), float(qx + 1), float(qx), float(qx + 1)), _mm_set1_ps(0.5f));
    const __m128 fy = _mm_add_ps(_mm_setr_ps(float(qy), float(qy), float(qy + 1), float(qy + 1)), _mm_set1_ps(0.5f));
    const __m128 rx = _mm_sub_ps(fx, _mm_set1_ps(x0)), ry = _mm_sub_ps(fy, _mm_set1_ps(y0));
    auto at = [&](const Plane& p) {
      return _mm_add_ps(_mm_add_ps(_mm_set1_ps(p.a0), _mm_mul_ps(_mm_set1_ps(p.dx), rx)),
                        _mm_mul_ps(_mm_set1_ps(p.dy), ry));
    };
    const __m128 q = at(oow);
    __m128 c0 = fx, c1 = fy, c2 = at(z), c3 = q;
    _MM_TRANSPOSE4_PS(c0, c1, c2, c3);
    _mm_storeu_ps(&frag[0].x, c0);
    _mm_storeu_ps(&frag[1].x, c1);
    _mm_storeu_ps(&frag[2].x, c2);
    _mm_storeu_ps(&frag[3].x, c3);
    if (nvar == 0) return;
    const __m128 w = _mm_div_ps(_mm_set1_ps(1.0f), q);
    int i = 0;
    for (; i + 4 <= nvar; i += 4) {
      __m128 v0 = _mm_mul_ps(at(var[i]), w), v1 = _mm_mul_ps(at(var[i + 1]), w);
      __m128 v2 = _mm_mul_ps(at(var[i + 2]), w), v3 = _mm_mul_ps(at(var[i + 3]), w);
      _MM_TRANSPOSE4_PS(v0, v1, v2, v3);  // now lane-major
      _mm_storeu_ps(out + i, v0);
      _mm_storeu_ps(out + nvar + i, v1);
      _mm_storeu_ps(out + 2 * nvar + i, v2);
      _mm_storeu_ps(out + 3 * nvar + i, v3);
    }
    for (; i < nvar; ++i) {
      alignas(16) float lanes[4];
      _mm_store_ps(lanes, _mm_mul_ps(at(var[i]), w));
      for (int lane = 0; lane < 4; ++lane) out[lane * nvar + i] = lanes[lane];
    }
#else
    for (int lane = 0; lane < 4; ++lane) {
      const float fx = float(qx + (lane & 1)) + 0.5f, fy = float(qy + (lane >> 1)) + 0.5f;
      const float rx = fx - x0, ry = fy - y0;
      const float q = oow.At(rx, ry);
      const float w = 1.0f / q;
      frag[lane] = glm::vec4(fx, fy, z.At(rx, ry), q);
      for (int i = 0; i < nvar; ++i) out[lane * nvar + i] = var[i].At(rx, ry) * w;
    }
#endif
  }
};

}  // namespace

float PolygonOffset(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, float factor, float units) {
  const float dx1 = b.win.x - a.win.x, dy1 = b.win.y - a.win.y, dz1 = b.win.z - a.win.z;
  const float dx2 = c.win.x - a.win.x, dy2 = c.win.y - a.win.y, dz2 = c.win.z - a.win.z;
  const float det = dx1 * dy2 - dx2 * dy1;
  float m = 0.0f;
  if (det != 0.0f) {
    const float dzdx = (dz1 * dy2 - dz2 * dy1) / det, dzdy = (dz2 * dx1 - dz1 * dx2) / det;
    m = std::max(std::fabs(dzdx), std::fabs(dzdy));
  }
  const float zmax = std::max({std::fabs(a.win.z), std::fabs(b.win.z), std::fabs(c.win.z)});
  int e = 0;
  std::frexp(zmax, &e);  // zmax = f * 2^e with f in [0.5, 1): the IEEE exponent is e - 1
  const float r = zmax > 0.0f ? std::ldexp(1.0f, e - 1 - 23) : std::ldexp(1.0f, -126);
  const float offset = m * factor + r * units;
  return std::isfinite(offset) ? offset : 0.0f;
}

void RasterizeTriangle(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2, bool front_facing,
                       const RasterTarget& target, QuadBuffer& quads, const QuadSink& sink) {
  const WindowVertex* v[3] = {&v0, &v1, &v2};
  std::int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) {
    const float x = v[i]->win.x, y = v[i]->win.y;
    // The clipper's guard band keeps finite window coordinates far inside this range.
    if (!(std::fabs(x) < 1e7f) || !(std::fabs(y) < 1e7f)) return;
    X[i] = std::llrint(double(x) * double(kOne));
    Y[i] = std::llrint(double(y) * double(kOne));
  }
  std::int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return;
  if (area < 0) {  // make the vertex order counter-clockwise (y up): the interior is left of every edge
    std::swap(v[1], v[2]);
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
    area = -area;
  }

  // Edge i runs from vertex i to vertex i+1; E(p) = A (px - Xa) + B (py - Ya) is > 0 inside.
  std::int64_t A[3], B[3], C[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    A[i] = -dy;
    B[i] = dx;
    // E at the origin of the fixed-point grid, with the tie rule folded in: left and bottom edges own centres
    // that lie exactly on them; for the others, E must be strictly positive.
    const bool owns_ties = dy < 0 || (dy == 0 && dx > 0);
    C[i] = -A[i] * X[i] - B[i] * Y[i] - (owns_ties ? 0 : 1);
  }

  // Pixel range whose centres lie in the snapped bounding box, clipped to the target bounds.
  const std::int64_t minX = std::min({X[0], X[1], X[2]}), maxX = std::max({X[0], X[1], X[2]});
  const std::int64_t minY = std::min({Y[0], Y[1], Y[2]}), maxY = std::max({Y[0], Y[1], Y[2]});
  const std::int64_t px0 = std::max<std::int64_t>(-FloorDiv(-(minX - kHalf), kOne), target.bounds.x0);
  const std::int64_t px1 = std::min<std::int64_t>(FloorDiv(maxX - kHalf, kOne), target.bounds.x1 - 1);
  const std::int64_t py0 = std::max<std::int64_t>(-FloorDiv(-(minY - kHalf), kOne), target.bounds.y0);
  const std::int64_t py1 = std::min<std::int64_t>(FloorDiv(maxY - kHalf, kOne), target.bounds.y1 - 1);
  if (px0 > px1 || py0 > py1) return;

  // Interpolation planes from the unsnapped float positions, relative to vertex 0.
  const float x0 = v[0]->win.x, y0 = v[0]->win.y;
  float dx1 = v[1]->win.x - x0, dy1 = v[1]->win.y - y0;
  float dx2 = v[2]->win.x - x0, dy2 = v[2]->win.y - y0;
  float det = dx1 * dy2 - dx2 * dy1;
  if (!(det > 0.0f)) {  // float rounding disagrees with the exact area: use the snapped positions
    dx1 = float(X[1] - X[0]) / kOne;
    dy1 = float(Y[1] - Y[0]) / kOne;
    dx2 = float(X[2] - X[0]) / kOne;
    dy2 = float(Y[2] - Y[0]) / kOne;
    det = float(area) / float(kOne * kOne);
  }
  const float inv_det = 1.0f / det;
  auto make_plane = [&](float a0, float a1, float a2) {
    const float da1 = a1 - a0, da2 = a2 - a0;
    return Plane{a0, (da1 * dy2 - da2 * dy1) * inv_det, (da2 * dx1 - da1 * dx2) * inv_det};
  };
  const int nvar = target.nvar;
  Plane z = make_plane(v[0]->win.z, v[1]->win.z, v[2]->win.z);
  z.a0 += target.depth_offset;
  const Plane oow = make_plane(v[0]->win.w, v[1]->win.w, v[2]->win.w);
  Plane var[kMaxVaryingFloats];
  for (int i = 0; i < nvar; ++i) var[i] = make_plane(v[0]->var[i], v[1]->var[i], v[2]->var[i]);

  // Hierarchical traversal: 8x8 pixel blocks first. An edge function is linear, so over a block it is largest and
  // smallest at the block's corner pixel centres: a block some edge excludes at all four corners is skipped, a
  // block every edge includes at all four corners is covered whole, and only the others are tested per pixel,
  // from edge values stepped incrementally across the block. Every pixel's coverage is the same exact integer
  // test as a pixel-by-pixel walk; quads come out block by block (each pixel of a triangle once, so the order
  // does not change the image).
  constexpr int kBlock = 8;
  std::int64_t step_x[3], step_y[3];  // E(px + 1) - E(px), E(py + 1) - E(py)
  for (int e = 0; e < 3; ++e) {
    step_x[e] = A[e] * kOne;
    step_y[e] = B[e] * kOne;
  }
  auto edge_at = [&](int e, std::int64_t px, std::int64_t py) {
    return A[e] * (px * kOne + kHalf) + B[e] * (py * kOne + kHalf) + C[e];
  };
  const Rect& bounds = target.bounds;
  QuadInterpolator interp{x0, y0, z, oow, var, nvar};
  for (std::int64_t by = py0 & ~std::int64_t(kBlock - 1); by <= py1; by += kBlock) {
    for (std::int64_t bx = px0 & ~std::int64_t(kBlock - 1); bx <= px1; bx += kBlock) {
      bool skip = false, whole = true;
      for (int e = 0; e < 3 && !skip; ++e) {
        const std::int64_t c00 = edge_at(e, bx, by), dx = step_x[e] * (kBlock - 1), dy = step_y[e] * (kBlock - 1);
        const std::int64_t lo = std::min({c00, c00 + dx, c00 + dy, c00 + dx + dy});
        const std::int64_t hi = std::max({c00, c00 + dx, c00 + dy, c00 + dx + dy});
        if (hi < 0) skip = true;
        if (lo < 0) whole = false;
      }
      if (skip) continue;
      const std::int64_t qy0 = std::max(by, py0 & ~std::int64_t(1)), qy1 = std::min(by + kBlock - 1, py1);
      const std::int64_t qx0 = std::max(bx, px0 & ~std::int64_t(1)), qx1 = std::min(bx + kBlock - 1, px1);
      for (std::int64_t qy = qy0; qy <= qy1; qy += 2) {
        std::int64_t row[3];
        for (int e = 0; e < 3; ++e) row[e] = edge_at(e, qx0, qy);
        for (std::int64_t qx = qx0; qx <= qx1; qx += 2) {
          unsigned mask = 0xFu;
          if (!whole) {
            mask = 0;
            for (int lane = 0; lane < 4; ++lane) {
              bool inside = true;
              for (int e = 0; e < 3; ++e)
                inside = inside && row[e] + (lane & 1) * step_x[e] + (lane >> 1) * step_y[e] >= 0;
              if (inside) mask |= 1u << lane;
            }
            for (int e = 0; e < 3; ++e) row[e] += 2 * step_x[e];
          }
          if (qx < bounds.x0 || qx + 1 >= bounds.x1 || qy < bounds.y0 || qy + 1 >= bounds.y1)
            mask &= BoundsMask(bounds, int(qx), int(qy));
          if (!mask) continue;
          Reserve(quads, sink, front_facing, nvar);
          const int q = quads.count++;
          quads.qx[q] = int(qx);
          quads.qy[q] = int(qy);
          for (int lane = 0; lane < 4; ++lane) quads.live[q * 4 + lane] = (mask >> lane) & 1u;
          interp.Quad(int(qx), int(qy), quads.frag_coord + q * 4, quads.varyings + std::size_t(q) * 4 * nvar);
        }
      }
    }
  }
}

void RasterizeLine(const WindowVertex& a, const WindowVertex& b, bool front_facing, const RasterTarget& target,
                   QuadBuffer& quads, const QuadSink& sink) {
  const float ax = a.win.x, ay = a.win.y, dx = b.win.x - ax, dy = b.win.y - ay;
  if (!(std::fabs(ax) < 1e7f && std::fabs(ay) < 1e7f && std::fabs(dx) < 1e7f && std::fabs(dy) < 1e7f)) return;
  const float len2 = dx * dx + dy * dy;
  if (len2 == 0.0f) return;
  const int nvar = target.nvar;

  // Varyings at the point of the segment nearest to the pixel centre (OpenGL's t, section 14.5.1).
  auto eval = [&](int px, int py, glm::vec4& frag, float* out) {
    const float fx = float(px) + 0.5f, fy = float(py) + 0.5f;
    const float t = std::clamp(((fx - ax) * dx + (fy - ay) * dy) / len2, 0.0f, 1.0f);
    const float q = a.win.w + t * (b.win.w - a.win.w);
    const float w = 1.0f / q;
    frag = glm::vec4(fx, fy, a.win.z + t * (b.win.z - a.win.z) + target.depth_offset, q);
    for (int i = 0; i < nvar; ++i) out[i] = (a.var[i] + t * (b.var[i] - a.var[i])) * w;
  };

  // The diamond-exit rule (OpenGL 4.6, section 14.5.1): pixel f is drawn when the segment leaves its diamond
  // |x - xf| + |y - yf| < 1/2. Along the major axis u that is one fragment per pixel centre u_c in the half-open
  // span [u_start, u_end) (in the direction of travel); besides, a start point strictly inside its pixel's diamond
  // draws that pixel, and an end point strictly inside its diamond does not.
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  const float u0 = x_major ? ax : ay, du = x_major ? dx : dy;
  const float v0 = x_major ? ay : ax, dv = x_major ? dy : dx;
  auto inside_diamond = [](float x, float y) {
    return std::fabs(x - std::floor(x) - 0.5f) + std::fabs(y - std::floor(y) - 0.5f) < 0.5f;
  };
  long first, last;  // inclusive range of major-axis pixel indices, in increasing order
  if (du > 0.0f) {
    first = long(std::ceil(u0 - 0.5f));
    last = long(std::ceil(u0 + du - 0.5f)) - 1;
    if (inside_diamond(ax, ay)) first = std::min(first, long(std::floor(u0)));
    if (inside_diamond(b.win.x, b.win.y)) last = std::min(last, long(std::floor(u0 + du)) - 1);
  } else {
    first = long(std::floor(u0 + du - 0.5f)) + 1;
    last = long(std::floor(u0 - 0.5f));
    if (inside_diamond(ax, ay)) last = std::max(last, long(std::floor(u0)));
    if (inside_diamond(b.win.x, b.win.y)) first = std::max(first, long(std::floor(u0 + du)) + 1);
  }
  // Keep the walk inside the target bounds.
  const long lo = x_major ? target.bounds.x0 : target.bounds.y0, hi = (x_major ? target.bounds.x1 : target.bounds.y1) - 1;
  first = std::max(first, lo);
  last = std::min(last, hi);
  // Where the line passes exactly between two pixel centres of a column (row), the pixel on the side that a
  // one-pixel-wide parallelogram around the line owns under the fill rule is taken: for x-major lines the upper
  // one when the line rises, else the lower one; for y-major lines the left one.
  const bool upper_on_tie = x_major && dv > 0.0f;
  int last_quad = -1;  // the last quad this line emitted, while it is still in the buffer
  for (long i = first; i <= last; ++i) {
    const float uc = float(i) + 0.5f;
    const float vc = v0 + (uc - u0) * dv / du;
    const long j = upper_on_tie ? long(std::floor(vc)) : long(std::ceil(vc)) - 1;
    const int px = int(x_major ? i : j), py = int(x_major ? j : i);
    if (px < target.bounds.x0 || px >= target.bounds.x1 || py < target.bounds.y0 || py >= target.bounds.y1) continue;
    const int qx = px & ~1, qy = py & ~1;
    const unsigned bit = 1u << ((px & 1) + 2 * (py & 1));
    // Neighbouring fragments of the same 2x2 block share one quad.
    if (last_quad >= 0 && last_quad == quads.count - 1 && quads.qx[last_quad] == qx && quads.qy[last_quad] == qy) {
      quads.live[(quads.count - 1) * 4 + ((px & 1) + 2 * (py & 1))] = 1;
      continue;
    }
    EmitQuad(quads, sink, front_facing, nvar, qx, qy, bit, eval);
    last_quad = quads.count - 1;
  }
}

void RasterizePoint(const WindowVertex& v, float size, bool front_facing, const RasterTarget& target,
                    QuadBuffer& quads, const QuadSink& sink) {
  if (!(size > 0.0f) || !(std::fabs(v.win.x) < 1e7f) || !(std::fabs(v.win.y) < 1e7f)) return;
  const float half = std::min(size, 1e6f) * 0.5f;
  const long x0 = std::max<long>(long(std::ceil(v.win.x - half - 0.5f)), target.bounds.x0);
  const long x1 = std::min<long>(long(std::ceil(v.win.x + half - 0.5f)) - 1, target.bounds.x1 - 1);
  const long y0 = std::max<long>(long(std::ceil(v.win.y - half - 0.5f)), target.bounds.y0);
  const long y1 = std::min<long>(long(std::ceil(v.win.y + half - 0.5f)) - 1, target.bounds.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const int nvar = target.nvar;
  const float w = 1.0f / v.win.w;
  auto eval = [&](int px, int py, glm::vec4& frag, float* out) {
    frag = glm::vec4(float(px) + 0.5f, float(py) + 0.5f, v.win.z + target.depth_offset, v.win.w);
    for (int i = 0; i < nvar; ++i) out[i] = v.var[i] * w;
  };
  for (long qy = y0 & ~1L; qy <= y1; qy += 2) {
    for (long qx = x0 & ~1L; qx <= x1; qx += 2) {
      unsigned mask = 0;
      for (int lane = 0; lane < 4; ++lane) {
        const long px = qx + (lane & 1), py = qy + (lane >> 1);
        if (px >= x0 && px <= x1 && py >= y0 && py <= y1) mask |= 1u << lane;
      }
      if (mask) EmitQuad(quads, sink, front_facing, nvar, int(qx), int(qy), mask, eval);
    }
  }
}

}  // namespace softgl::detail

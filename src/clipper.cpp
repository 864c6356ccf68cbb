// clipper.cpp — Sutherland-Hodgman in homogeneous coordinates.
#include "clipper.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "simd.h"
#include "wide.h"

namespace softgl::detail {

namespace {

constexpr int kPlaneCount = 7;
constexpr float kExactLimit = 1048576.0f;

// Signed distance of p to plane i; inside is >= 0.
float Distance(int plane, const glm::vec4& p, const ClipPlanes& planes) {
  switch (plane) {
    case 0: return p.x + planes.guard_x * p.w;
    case 1: return planes.guard_x * p.w - p.x;
    case 2: return p.y + planes.guard_y * p.w;
    case 3: return planes.guard_y * p.w - p.y;
    case 4: return p.z + p.w;
    case 5: return p.w - p.z;
    default: return p.w - kMinW;
  }
}

// The vertex where edge (out, in) crosses `plane`, `out` being the vertex outside it, at t = d_out / (d_out - d_in)
// from `out`: new = out + t * (in - out), in float, for the position and every varying. This is Mesa's
// formulation (draw_pipe_clip.c), so that clipped vertices, and the pixels along the edges they make, match
// llvmpipe's exactly; and since it depends only on which vertex is outside, an edge shared by two triangles
// yields the same vertex in both.
// Coordinates beyond kExactLimit (vertices at 1e30, say) would lose the result to cancellation in float: there the
// position is recomputed in double and the clipped coordinate put exactly on the plane.
void Intersect(const ClipVertex& out, const ClipVertex& in, float d_out, float d_in, int nvar, int plane,
               const ClipPlanes& planes, ClipVertex& dst) {
  const float t = d_out / (d_out - d_in);
  dst.pos = out.pos + t * (in.pos - out.pos);
  for (int i = 0; i < nvar; ++i) dst.var[i] = out.var[i] + t * (in.var[i] - out.var[i]);
  float extent = 0.0f;
  for (int c = 0; c < 4; ++c) extent = std::max({extent, std::fabs(out.pos[c]), std::fabs(in.pos[c])});
  if (plane <= 3 && extent > kExactLimit) {
    const double td = double(d_in) / (double(d_in) - double(d_out));  // from the inside vertex
    for (int c = 0; c < 4; ++c)
      dst.pos[c] = float(double(in.pos[c]) + td * (double(out.pos[c]) - double(in.pos[c])));
    const float g = plane <= 1 ? planes.guard_x : planes.guard_y;
    const float on_plane = (plane % 2 == 0 ? -g : g) * dst.pos.w;
    if (plane <= 1) dst.pos.x = on_plane;
    else dst.pos.y = on_plane;
  } else if (plane == 6) {
    dst.pos.w = std::max(dst.pos.w, kMinW);  // never divide by zero or a negative w
  }
}

void Copy(const ClipVertex& src, int nvar, ClipVertex& dst) {
  dst.pos = src.pos;
  std::memcpy(dst.var, src.var, sizeof(float) * std::size_t(nvar));
}

}  // namespace

unsigned ClipCodes(const glm::vec4& p, const ClipPlanes& planes) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w))
    return kClipNonFinite;
  unsigned codes = 0;
  for (int i = 0; i < kPlaneCount; ++i)
    if (Distance(i, p, planes) < 0.0f) codes |= 1u << i;
  return codes;
}

namespace {

// ClipCodes of positions p[0 .. W - 1], W per instruction: the same distances, in the same float operations.
template <int W>
SOFTGL_WIDE void ClipCodesLanes(const glm::vec4* p, const ClipPlanes& planes, unsigned* codes) {
  using F = typename V<W>::F;
  using I = typename V<W>::I;
  F xyzw[4];
  LoadComponents<W>(p, xyzw);
  const F x = xyzw[0], y = xyzw[1], z = xyzw[2], w = xyzw[3];
  // Infinite or NaN: every exponent bit set.
  const I exponent = I{} + 0x7F800000;
  const I non_finite = ((I(x) & exponent) == exponent) | ((I(y) & exponent) == exponent) |
                       ((I(z) & exponent) == exponent) | ((I(w) & exponent) == exponent);
  const F gx = planes.guard_x * w, gy = planes.guard_y * w;
  const I c = (I(x + gx < 0.0f) & std::int32_t(kClipLeft)) | (I(gx - x < 0.0f) & std::int32_t(kClipRight)) |
              (I(y + gy < 0.0f) & std::int32_t(kClipBottom)) | (I(gy - y < 0.0f) & std::int32_t(kClipTop)) |
              (I(z + w < 0.0f) & std::int32_t(kClipNear)) | (I(w - z < 0.0f) & std::int32_t(kClipFar)) |
              (I(w - kMinW < 0.0f) & std::int32_t(kClipW));
  StoreVec(codes, (non_finite & std::int32_t(kClipNonFinite)) | (~non_finite & c));
}

template <int W>
SOFTGL_WIDE void ClipCodesOf(const glm::vec4* p, int n, const ClipPlanes& planes, unsigned* codes) {
  int i = 0;
  for (; i + W <= n; i += W) ClipCodesLanes<W>(p + i, planes, codes + i);
  if (i < n) {  // the last few through a padded copy (a small draw has only these)
    glm::vec4 in[W];
    unsigned out[W];
    for (int l = 0; l < W; ++l) in[l] = p[std::min(i + l, n - 1)];
    ClipCodesLanes<W>(in, planes, out);
    for (int l = 0; i + l < n; ++l) codes[i + l] = out[l];
  }
}

using ClipCodesFn = void (*)(const glm::vec4*, int, const ClipPlanes&, unsigned*);
SOFTGL_TARGET_BASE void ClipCodesOfBase(const glm::vec4* p, int n, const ClipPlanes& planes, unsigned* codes) {
  ClipCodesOf<4>(p, n, planes, codes);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void ClipCodesOfAvx2(const glm::vec4* p, int n, const ClipPlanes& planes, unsigned* codes) {
  ClipCodesOf<8>(p, n, planes, codes);
}
// 8 lanes on AVX-512 too: GCC 12 compiles this unit's 16-lane comparisons lane by lane (see simd.h).
SOFTGL_TARGET_AVX512 void ClipCodesOfAvx512(const glm::vec4* p, int n, const ClipPlanes& planes, unsigned* codes) {
  ClipCodesOf<8>(p, n, planes, codes);
}
#endif

}  // namespace

void ClipCodesOfVertices(const glm::vec4* positions, int count, const ClipPlanes& planes, unsigned* codes) {
  static const ClipCodesFn fn = SOFTGL_CHOOSE(ClipCodesOf);
  fn(positions, count, planes, codes);
}

void ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int nvar,
                  const ClipPlanes& planes, ClipPolygon& out) {
  out.count = 0;
  const unsigned ga = ClipCodes(a.pos, planes), gb = ClipCodes(b.pos, planes), gc = ClipCodes(c.pos, planes);
  if ((ga | gb | gc) & kClipNonFinite) return;
  if (ga & gb & gc) return;  // all three outside one plane
  Copy(a, nvar, out.v[0]);
  Copy(b, nvar, out.v[1]);
  Copy(c, nvar, out.v[2]);
  out.count = 3;
  if ((ga | gb | gc) == 0) return;  // inside the guard band: no clipping
  // Clipping is needed: then against every plane of the view volume that a vertex is outside of, as llvmpipe
  // does (its guard band decides whether to clip, not where).
  const ClipPlanes volume;
  const unsigned crossing = ClipCodes(a.pos, volume) | ClipCodes(b.pos, volume) | ClipCodes(c.pos, volume);

  ClipPolygon scratch;
  ClipPolygon* src = &out;
  ClipPolygon* dst = &scratch;
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (!(crossing & (1u << plane))) continue;
    dst->count = 0;
    for (int i = 0; i < src->count; ++i) {
      const ClipVertex& prev = src->v[(i + src->count - 1) % src->count];
      const ClipVertex& cur = src->v[i];
      const float dp = Distance(plane, prev.pos, volume);
      const float dc = Distance(plane, cur.pos, volume);
      if (dp >= 0.0f && dc >= 0.0f) {
        Copy(cur, nvar, dst->v[dst->count++]);
      } else if (dp >= 0.0f) {
        Intersect(cur, prev, dc, dp, nvar, plane, volume, dst->v[dst->count++]);
      } else if (dc >= 0.0f) {
        Intersect(prev, cur, dp, dc, nvar, plane, volume, dst->v[dst->count++]);
        Copy(cur, nvar, dst->v[dst->count++]);
      }
    }
    std::swap(src, dst);
    if (src->count < 3) {
      out.count = 0;
      return;
    }
  }
  if (src != &out) {
    out.count = src->count;
    for (int i = 0; i < src->count; ++i) Copy(src->v[i], nvar, out.v[i]);
  }
}

bool ClipLine(const ClipVertex& a, const ClipVertex& b, int nvar, const ClipPlanes& planes, ClipVertex& out_a,
              ClipVertex& out_b) {
  const unsigned ga = ClipCodes(a.pos, planes), gb = ClipCodes(b.pos, planes);
  if ((ga | gb) & kClipNonFinite) return false;
  if (ga & gb) return false;
  if ((ga | gb) == 0) {  // inside the guard band: no clipping
    Copy(a, nvar, out_a);
    Copy(b, nvar, out_b);
    return true;
  }
  const ClipPlanes volume;  // as for triangles: clip against the view volume itself
  const unsigned ca = ClipCodes(a.pos, volume), cb = ClipCodes(b.pos, volume);
  if (ca & cb) return false;
  // As Mesa does: the part cut from a's end is ta (from a towards b), from b's end tb (from b towards a), each the
  // largest over the planes that end is outside of.
  float ta = 0.0f, tb = 0.0f;
  int plane_a = -1, plane_b = -1;
  float da_at = 0.0f, db_at = 0.0f, da_other = 0.0f, db_other = 0.0f;
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (!((ca | cb) & (1u << plane))) continue;
    const float da = Distance(plane, a.pos, volume), db = Distance(plane, b.pos, volume);
    if (da < 0.0f && da / (da - db) > ta) {
      ta = da / (da - db);
      plane_a = plane;
      da_at = da;
      da_other = db;
    }
    if (db < 0.0f && db / (db - da) > tb) {
      tb = db / (db - da);
      plane_b = plane;
      db_at = db;
      db_other = da;
    }
  }
  if (ta + tb >= 1.0f) return false;
  if (plane_a >= 0) Intersect(a, b, da_at, da_other, nvar, plane_a, volume, out_a);
  else Copy(a, nvar, out_a);
  if (plane_b >= 0) Intersect(b, a, db_at, db_other, nvar, plane_b, volume, out_b);
  else Copy(b, nvar, out_b);
  return true;
}

}  // namespace softgl::detail

// clipper.cpp — Sutherland-Hodgman in homogeneous coordinates.
#include "clipper.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace softgl::detail {

namespace {

constexpr int kPlaneCount = 7;

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

// The point at parameter t from `in` (inside) towards `out`, put exactly on `plane`. Always interpolating from the
// inside vertex makes an edge shared by two triangles produce the same new vertex in both. Positions are
// interpolated in double, and the coordinate the plane fixes is set exactly, so that vertices far outside the view
// volume (1e30) still yield clipped vertices on the planes instead of rounding noise.
void Lerp(const ClipVertex& in, const ClipVertex& out, float t, int nvar, int plane, const ClipPlanes& planes,
          ClipVertex& dst) {
  const double td = t;
  for (int c = 0; c < 4; ++c) dst.pos[c] = float(double(in.pos[c]) + td * (double(out.pos[c]) - double(in.pos[c])));
  switch (plane) {
    case 0: dst.pos.x = -planes.guard_x * dst.pos.w; break;
    case 1: dst.pos.x = planes.guard_x * dst.pos.w; break;
    case 2: dst.pos.y = -planes.guard_y * dst.pos.w; break;
    case 3: dst.pos.y = planes.guard_y * dst.pos.w; break;
    case 4: dst.pos.z = -dst.pos.w; break;
    case 5: dst.pos.z = dst.pos.w; break;
    default: dst.pos.w = std::max(dst.pos.w, kMinW); break;
  }
  for (int i = 0; i < nvar; ++i) dst.var[i] = in.var[i] + t * (out.var[i] - in.var[i]);
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

void ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int nvar,
                  const ClipPlanes& planes, ClipPolygon& out) {
  const unsigned ca = ClipCodes(a.pos, planes), cb = ClipCodes(b.pos, planes), cc = ClipCodes(c.pos, planes);
  out.count = 0;
  if ((ca | cb | cc) & kClipNonFinite) return;
  if (ca & cb & cc) return;  // all three outside one plane
  Copy(a, nvar, out.v[0]);
  Copy(b, nvar, out.v[1]);
  Copy(c, nvar, out.v[2]);
  out.count = 3;
  const unsigned crossing = ca | cb | cc;
  if (crossing == 0) return;

  ClipPolygon scratch;
  ClipPolygon* src = &out;
  ClipPolygon* dst = &scratch;
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (!(crossing & (1u << plane))) continue;
    dst->count = 0;
    for (int i = 0; i < src->count; ++i) {
      const ClipVertex& prev = src->v[(i + src->count - 1) % src->count];
      const ClipVertex& cur = src->v[i];
      const float dp = Distance(plane, prev.pos, planes);
      const float dc = Distance(plane, cur.pos, planes);
      if (dp >= 0.0f && dc >= 0.0f) {
        Copy(cur, nvar, dst->v[dst->count++]);
      } else if (dp >= 0.0f) {
        Lerp(prev, cur, dp / (dp - dc), nvar, plane, planes, dst->v[dst->count++]);
      } else if (dc >= 0.0f) {
        Lerp(cur, prev, dc / (dc - dp), nvar, plane, planes, dst->v[dst->count++]);
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
  const unsigned ca = ClipCodes(a.pos, planes), cb = ClipCodes(b.pos, planes);
  if ((ca | cb) & kClipNonFinite) return false;
  if (ca & cb) return false;
  float t0 = 0.0f, t1 = 1.0f;  // the visible part is [t0, t1] along a -> b
  int plane0 = -1, plane1 = -1;  // the planes that set t0 and t1
  for (int plane = 0; plane < kPlaneCount; ++plane) {
    if (!((ca | cb) & (1u << plane))) continue;
    const float da = Distance(plane, a.pos, planes), db = Distance(plane, b.pos, planes);
    const float t = da / (da - db);
    if (da < 0.0f && t > t0) {
      t0 = t;
      plane0 = plane;
    } else if (da >= 0.0f && t < t1) {
      t1 = t;
      plane1 = plane;
    }
  }
  if (t0 > t1) return false;
  if (plane0 >= 0) Lerp(a, b, t0, nvar, plane0, planes, out_a);
  else Copy(a, nvar, out_a);
  if (plane1 >= 0) Lerp(a, b, t1, nvar, plane1, planes, out_b);
  else Copy(b, nvar, out_b);
  return true;
}

}  // namespace softgl::detail

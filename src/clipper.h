// clipper.h — stage 4: Sutherland-Hodgman clipping in homogeneous clip space.
//
// Primitives are clipped against the six planes of the view volume, -w <= x, y, z <= w, plus w >= kMinW (which
// removes geometry at or behind the eye). The x and y planes may be widened to a guard band
// (-g*w <= x <= g*w): pixels outside the viewport are then discarded by the rasterizer's bounds instead, which
// gives the same image while creating fewer new vertices. New vertices carry linearly interpolated varyings
// (linear in clip space is perspective-correct once divided by w).
#pragma once

#include <cstdint>

#include "types.h"

namespace softgl::detail {

inline constexpr float kMinW = 1e-6f;
inline constexpr int kMaxPolygonVertices = 16;  // 3 + one per plane (7) is the most clipping can produce

enum ClipPlane : unsigned {
  kClipLeft = 1u << 0,
  kClipRight = 1u << 1,
  kClipBottom = 1u << 2,
  kClipTop = 1u << 3,
  kClipNear = 1u << 4,
  kClipFar = 1u << 5,
  kClipW = 1u << 6,
  kClipNonFinite = 1u << 7,  // a coordinate is NaN or infinite: the primitive is discarded
};

struct ClipPlanes {
  float guard_x = 1.0f;  // x planes at +-guard_x * w (1 = the view volume itself)
  float guard_y = 1.0f;
};

struct ClipPolygon {
  int count = 0;
  ClipVertex v[kMaxPolygonVertices];
};

/// Bitmask of the planes that `p` is outside of (kClipNonFinite for NaN or infinite coordinates).
unsigned ClipCodes(const glm::vec4& p, const ClipPlanes& planes);

/// codes[i] = ClipCodes(positions[i], planes) for i < count, several positions per instruction.
void ClipCodesOfVertices(const glm::vec4* positions, int count, const ClipPlanes& planes, unsigned* codes);

/// Clips triangle (a, b, c) and writes the resulting convex polygon (0 or 3..kMaxPolygonVertices vertices) to out.
void ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int nvar,
                  const ClipPlanes& planes, ClipPolygon& out);

/// Clips segment (a, b). Returns false when nothing is left; otherwise writes the clipped end points.
bool ClipLine(const ClipVertex& a, const ClipVertex& b, int nvar, const ClipPlanes& planes, ClipVertex& out_a,
              ClipVertex& out_b);

}  // namespace softgl::detail

// culling.h — stage 6: facing and face culling, decided from the signed area in window space.
#pragma once

#include <cstdint>

#include <softgl/enums.h>

#include "types.h"

namespace softgl::detail {

/// Twice the signed area of a window-space polygon (positive when counter-clockwise with y up).
float SignedArea(const WindowVertex* v, int count);

/// Whether a polygon of signed area `area` is front-facing for front_face CCW or CW.
bool IsFrontFacing(float area, Enum front_face);

/// Whether culling (when enabled) removes a polygon of this facing; cull_face FRONT, BACK or FRONT_AND_BACK.
bool IsCulled(bool front_facing, Enum cull_face);

/// Up to 16 filled triangles inside the guard band, by their window positions: x[k][t], y[k][t] for vertex k of
/// triangle t.
struct TriangleGroup {
  static constexpr int kSize = 16;
  int count = 0;
  float x[3][kSize] = {}, y[3][kSize] = {};
};

/// What decides whether a filled triangle draws anything, besides its vertices.
struct CullState {
  bool cull_enabled = false;
  Enum cull_face = BACK;
  Enum front_face = CCW;
  Rect bounds;  // the draw's bounds (viewport, framebuffer, scissor)
};

/// Bit t set for each triangle t of the group that certainly draws nothing, decided 4, 8 or 16 triangles per
/// instruction with the scalar path's own arithmetic: a zero or culled SignedArea (the same float operations), or
/// no pixel centre inside `bounds` in the box of its vertices snapped to 1/256 pixel (as TriangleCentreBox
/// snaps: exact here for coordinates below 16384 pixels, and a triangle beyond that is left unmarked). A triangle
/// left unmarked goes through the scalar path, which decides the same way.
std::uint32_t DrawsNothing(const TriangleGroup& group, const CullState& state);

}  // namespace softgl::detail

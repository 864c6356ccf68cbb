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
  // A multisampled target's sample span (SampleSpan, in 1/256 pixel): the boxes hold the pixels with some sample
  // position inside, as TriangleCentreBox's for that count; the 2 x 2 coverage test is for pixel centres only.
  int span_x0 = 128, span_x1 = 128, span_y0 = 128, span_y1 = 128;
  // The positions the 2 x 2 coverage test tries in each pixel, in 1/256 pixel from its bottom-left corner: the
  // centre when single-sampled, else each sample's (SamplePositions); `samples` of them.
  int samples = 1;
  std::int32_t sample_x[kMaxSamples] = {128}, sample_y[kMaxSamples] = {128};
  /// Sets the spans and the positions for a target of `samples` (1, 2, 4 or 8) whose coverage triangles compute.
  void SetSamples(int samples);
};

/// What the scalar path decides for the triangles of a group, found 4, 8 or 16 triangles per instruction with its
/// own arithmetic.
struct GroupVerdict {
  /// Bit t: triangle t certainly draws nothing. Its SignedArea (the same float operations) is zero or culled; or
  /// its vertices snapped to 1/256 pixel (as TriangleCentreBox snaps: exact here for coordinates below 16384
  /// pixels; a triangle beyond that is left unmarked) have no pixel centre (sample, for a multisampled state)
  /// inside `bounds` in their box, or, for a triangle less than 128 pixels across, no area; or, for one whose box
  /// holds at most 2 x 2 pixels, none of their centres (their samples' positions, multisampled) passes the
  /// rasterizer's edge test (RasterizeTriangle's, tie rule included).
  std::uint32_t nothing = 0;
  /// Bit t: triangle t is not marked, is less than 128 pixels across and has its coordinates in the exact range;
  /// then bit t of `front` is its facing (IsFrontFacing of its SignedArea), and x0..y1[t] its TriangleCentreBox.
  std::uint32_t known = 0;
  std::uint32_t front = 0;
  std::int32_t x0[TriangleGroup::kSize], y0[TriangleGroup::kSize], x1[TriangleGroup::kSize], y1[TriangleGroup::kSize];
  Rect Box(int t) const { return Rect{x0[t], y0[t], x1[t], y1[t]}; }
};

/// The verdict on each triangle of the group. A triangle left unmarked and unknown goes through the scalar path,
/// which decides the same way.
void JudgeTriangles(const TriangleGroup& group, const CullState& state, GroupVerdict& verdict);

/// JudgeTriangles' `nothing`: bit t set for each triangle t of the group that certainly draws nothing.
std::uint32_t DrawsNothing(const TriangleGroup& group, const CullState& state);

}  // namespace softgl::detail

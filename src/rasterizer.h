// rasterizer.h — stage 7: turn window-space triangles, lines and points into 4x4 fragment blocks.
//
// Rules, all OpenGL's (4.6 specification, chapter 14) with the conventions of Mesa's llvmpipe where OpenGL leaves
// a choice:
// - Pixel (i, j) is sampled at its centre (i + 0.5, j + 0.5), window y pointing up.
// - Triangles: vertex positions are snapped to 1/256 pixel (kSubpixelBits); coverage uses exact integer edge
//   functions. A centre exactly on an edge belongs to the triangle when the edge is a left edge (interior to
//   its right) or a bottom edge (horizontal, interior above), so triangles sharing an edge cover every pixel
//   once.
// - Varyings are interpolated perspective-correctly (v/w and 1/w are linear in window space), depth linearly;
//   noperspective varyings linearly in window space, flat ones not at all (the caller gives every vertex the
//   provoking vertex's value, and the window vertices of noperspective and flat varyings hold the value itself).
// - Lines: one pixel wide, one fragment per column (x-major) or row (y-major) whose centre lies in the half-open
//   span [start, end), the diamond-exit rule for end points at pixel centres. A wider line (LineWidth w, rounded)
//   takes the same columns (rows), each w fragments high (wide) centred on the line: the parallelogram between the
//   line moved w/2 down and up (left and right), its sides owning centres as a triangle's edges do. Multisampled,
//   a line is the rectangle of width w (unrounded) along the segment.
// - Points: squares of the point size; pixels whose centres lie in [x - s/2, x + s/2) x [y - s/2, y + s/2).
// Only pixels inside `bounds` (viewport, framebuffer, scissor) are marked live.
#pragma once

#include "types.h"

namespace softgl::detail {

inline constexpr int kSubpixelBits = 8;

struct HierarchicalDepth;

struct RasterTarget {
  Rect bounds;  // viewport, framebuffer and scissor rectangle intersected
  int nvar = 0;
  float depth_offset = 0.0f;  // polygon offset added to every fragment's depth
  const Interpolation* interpolation = nullptr;  // per varying (null: all smooth)
  // Samples whose coverage triangles compute (a multisampled target with MULTISAMPLE enabled): each at its own
  // position (SamplePositions), with the same edge functions and tie rule as a pixel centre; a pixel is emitted
  // when some sample is covered, and its lanes' sample masks say which. 1: the pixel centre alone.
  int samples = 1;
  // The tile's coarse depth (draws whose depth test may run early): a triangle, or an 8x8 region of one, that
  // cannot pass the depth test there is dropped. Null: every triangle is rasterized.
  HierarchicalDepth* depth_bounds = nullptr;
  bool point_lower_left = false;  // POINT_SPRITE_COORD_ORIGIN is LOWER_LEFT (gl_PointCoord's t grows upwards)
  float line_width = 1.0f;        // LineWidth, clamped to ALIASED_LINE_WIDTH_RANGE
};

/// The smallest and largest offsets of a pixel's sample positions (SamplePositions) in x and y, in subpixels
/// (1 / 2^kSubpixelBits pixel) from its bottom-left corner: the centre's for one sample.
struct SampleSpan {
  std::int64_t x0 = 128, x1 = 128, y0 = 128, y1 = 128;
  explicit SampleSpan(int samples);
  /// The span of each supported count (1, 2, 4, 8), made once.
  static const SampleSpan& Of(int samples);
};
static_assert(kSubpixelBits == 8, "SampleSpan's default is the centre in 1/256 pixel");

/// OpenGL's polygon offset for the plane through a, b, c: m * factor + r * units, with m the larger of
/// |dz/dx| and |dz/dy| and r the smallest resolvable difference of the depth buffer: of the 32-bit float buffer at
/// the largest depth of the polygon, 2^(e - 23), or of a 16-bit fixed-point one (`fixed16`), 1 / 65535 (OpenGL 4.6,
/// section 14.6.5).
float PolygonOffset(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, float factor, float units,
                    bool fixed16 = false);

/// The pixels whose centres RasterizeTriangle may cover of the filled triangle a, b, c (window positions) inside
/// `bounds`: the centres inside its snapped bounding box, cut to `bounds` (half-open). Empty when the snapped
/// triangle has no area, lies beyond the rasterizer's range or holds no pixel centre. The front end bins a triangle
/// by this box, and drops it when the box is empty (at 1280x720 a third of a detailed model's triangles). With
/// `samples` > 1, the pixels with some sample position (SamplePositions) inside the snapped bounding box.
Rect TriangleCentreBox(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const Rect& bounds,
                       int samples = 1);

void RasterizeTriangle(const VertexView& v0, const VertexView& v1, const VertexView& v2, bool front_facing,
                       const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink);

inline constexpr int kTriangleGroup = 16;

/// Filled triangles waiting to be rasterized together (RasterizeTriangles), in order: their vertices' window
/// positions as rows of kTriangleGroup lanes, where their varyings are (which must stay there), their polygon
/// offsets and facings.
struct TriangleQueue {
  int count = 0;
  float x[3][kTriangleGroup], y[3][kTriangleGroup], z[3][kTriangleGroup], w[3][kTriangleGroup];
  const float* var[3][kTriangleGroup];
  float depth_offset[kTriangleGroup];
  bool front_facing[kTriangleGroup];
  /// Adds a triangle; true when the queue is then full.
  bool Add(const VertexView& a, const VertexView& b, const VertexView& c, float offset, bool front) {
    const int t = count++;
    const VertexView* v[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      x[k][t] = v[k]->win.x;
      y[k][t] = v[k]->win.y;
      z[k][t] = v[k]->win.z;
      w[k][t] = v[k]->win.w;
      var[k][t] = v[k]->var;
    }
    depth_offset[t] = offset;
    front_facing[t] = front;
    return count == kTriangleGroup;
  }
};

/// RasterizeTriangle on each triangle of the queue, in order, with target.depth_offset taken from each: the same
/// quads in the same order. Their set-up (snapping, orientation, pixel box, the depth and 1/w planes, a small
/// triangle's edges) is computed several triangles per instruction, for those whose vertices lie within 16384
/// pixels of the origin and whose sides are shorter than 128 pixels; the others one by one. Empties the queue.
void RasterizeTriangles(TriangleQueue& queue, const RasterTarget& target, BlockBuffer& blocks, const BlockSink& sink);

void RasterizeLine(const WindowVertex& a, const WindowVertex& b, bool front_facing, const RasterTarget& target,
                   BlockBuffer& blocks, const BlockSink& sink);

void RasterizePoint(const WindowVertex& v, float size, bool front_facing, const RasterTarget& target,
                    BlockBuffer& blocks, const BlockSink& sink);

/// The varyings of the live quads of `blocks` whose triangle's planes they reference (the rasterizer leaves them
/// for this, so that quads the early depth test drops are never interpolated).
void InterpolateVaryings(BlockBuffer& blocks);

/// After InterpolateVaryings, into a multisampled target: the centroid varyings (`modes`, the draw's qualifiers) of
/// each live lane with centroid[b][lane] = s >= 0 taken again at sample s (the lane's first covered sample, where
/// not all are covered) instead of the pixel centre. Lanes of lines and points keep the centre's.
void InterpolateCentroids(BlockBuffer& blocks, const std::int8_t (*centroid)[kLanes], const Interpolation* modes);
/// Every varying of every lane of the blocks' quads evaluated at sample s's position in the lane's pixel (divided
/// by w where it is interpolated with perspective; flat ones constant): the inputs of a shader run per sample.
void InterpolateAtSample(BlockBuffer& blocks, int s);

}  // namespace softgl::detail

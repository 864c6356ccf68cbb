// scenes.h — the example scenes, shared by the example programs (which write PNGs) and the image tests
// (which compare them with golden images).
#pragma once

#include <softgl/softgl.h>

namespace scenes {

/// A triangle with red, green and blue corners, colours interpolated across it (DrawArrays, two buffers).
softgl::Image Triangle(int width, int height);

/// A lit cube with per-face colours, rotated by `angle` radians about a tilted axis (DrawElement, interleaved
/// vertex buffer with normalized unsigned-byte colours, depth test, back-face culling).
softgl::Image Cube(int width, int height, float angle);

/// A torus drawn with PolygonMode(LINE) over a filled, dimmed copy, and its vertices as points.
softgl::Image Wireframe(int width, int height);

/// A camera standing on a checkered floor that runs behind it, with a cube crossing the near plane: triangles are
/// clipped by the near plane and the side planes, and the checks show perspective-correct interpolation.
softgl::Image Clipped(int width, int height);

}  // namespace scenes

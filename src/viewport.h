// viewport.h — stage 5: perspective divide and the viewport transform (clip space -> window space).
#pragma once

#include "clipper.h"
#include "types.h"

namespace softgl::detail {

/// OpenGL's viewport transform as scale and translation: window = ndc * scale + translate.
/// x: scale w/2, translate x + w/2; y likewise; z: scale (f - n)/2, translate (n + f)/2.
struct ViewportTransform {
  glm::vec3 scale{0.0f};
  glm::vec3 translate{0.0f};
  Rect rect;  // the viewport rectangle in pixels
};

ViewportTransform MakeViewportTransform(int x, int y, int width, int height, double n, double f);

/// Clip planes for this viewport: x and y widened to a guard band of kGuardBandPixels around it, so that window
/// coordinates always stay small enough for the rasterizer's fixed-point arithmetic.
inline constexpr float kGuardBandPixels = 32768.0f;
ClipPlanes GuardBandPlanes(const ViewportTransform& vp);

/// Perspective divide then viewport mapping; varyings are divided by w for perspective-correct interpolation.
void ToWindow(const ClipVertex& in, int nvar, const ViewportTransform& vp, WindowVertex& out);

/// ToWindow's position (x, y, z in window space, then 1/w) of clip[i] for i < count, several per instruction.
/// Positions with w = 0 or non-finite coordinates give non-finite results (callers use only the unclipped ones).
void WindowPositions(const glm::vec4* clip, int count, const ViewportTransform& vp, glm::vec4* window);

}  // namespace softgl::detail

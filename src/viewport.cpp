// viewport.cpp — perspective divide and viewport mapping.
#include "viewport.h"

#include <algorithm>

namespace softgl::detail {

ViewportTransform MakeViewportTransform(int x, int y, int width, int height, double n, double f) {
  ViewportTransform vp;
  vp.scale = glm::vec3(float(width) * 0.5f, float(height) * 0.5f, float((f - n) * 0.5));
  vp.translate = glm::vec3(float(x) + float(width) * 0.5f, float(y) + float(height) * 0.5f, float((n + f) * 0.5));
  vp.rect = Rect{x, y, x + width, y + height};
  return vp;
}

ClipPlanes GuardBandPlanes(const ViewportTransform& vp) {
  ClipPlanes planes;
  planes.guard_x = vp.scale.x > 0.0f ? 1.0f + kGuardBandPixels / vp.scale.x : 1.0f;
  planes.guard_y = vp.scale.y > 0.0f ? 1.0f + kGuardBandPixels / vp.scale.y : 1.0f;
  return planes;
}

void ToWindow(const ClipVertex& in, int nvar, const ViewportTransform& vp, WindowVertex& out) {
  const float oow = 1.0f / in.pos.w;
  out.win.x = in.pos.x * oow * vp.scale.x + vp.translate.x;
  out.win.y = in.pos.y * oow * vp.scale.y + vp.translate.y;
  out.win.z = in.pos.z * oow * vp.scale.z + vp.translate.z;
  out.win.w = oow;
  for (int i = 0; i < nvar; ++i) out.var[i] = in.var[i] * oow;
}

}  // namespace softgl::detail

// viewport.cpp — perspective divide and viewport mapping.
#include "viewport.h"

#include <algorithm>

#include "simd.h"
#include "wide.h"

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

namespace {

// ToWindow's position for p[0 .. W - 1], W per instruction: the same float operations in the same order.
template <int W>
SOFTGL_WIDE void WindowPositionLanes(const glm::vec4* p, const ViewportTransform& vp, glm::vec4* win) {
  using F = typename V<W>::F;
  F c[4];
  LoadComponents<W>(p, c);
  F x = c[0], y = c[1], z = c[2];
  const F w = c[3];
  const F oow = 1.0f / w;
  x = x * oow * vp.scale.x + vp.translate.x;
  y = y * oow * vp.scale.y + vp.translate.y;
  z = z * oow * vp.scale.z + vp.translate.z;
  for (int l = 0; l < W; ++l) win[l] = glm::vec4(x[l], y[l], z[l], oow[l]);
}

template <int W>
SOFTGL_WIDE void WindowPositionsOf(const glm::vec4* p, int n, const ViewportTransform& vp, glm::vec4* win) {
  int i = 0;
  for (; i + W <= n; i += W) WindowPositionLanes<W>(p + i, vp, win + i);
  if (i < n) {  // the last few through a padded copy
    glm::vec4 in[W], out[W];
    for (int l = 0; l < W; ++l) in[l] = p[std::min(i + l, n - 1)];
    WindowPositionLanes<W>(in, vp, out);
    for (int l = 0; i + l < n; ++l) win[i + l] = out[l];
  }
}

using WindowPositionsFn = void (*)(const glm::vec4*, int, const ViewportTransform&, glm::vec4*);
SOFTGL_TARGET_BASE void WindowPositionsOfBase(const glm::vec4* p, int n, const ViewportTransform& vp, glm::vec4* win) {
  WindowPositionsOf<4>(p, n, vp, win);
}
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void WindowPositionsOfAvx2(const glm::vec4* p, int n, const ViewportTransform& vp, glm::vec4* win) {
  WindowPositionsOf<8>(p, n, vp, win);
}
// 8 lanes on AVX-512 too: with 16, LoadComponents gathers the positions lane by lane.
SOFTGL_TARGET_AVX512 void WindowPositionsOfAvx512(const glm::vec4* p, int n, const ViewportTransform& vp,
                                                  glm::vec4* win) {
  WindowPositionsOf<8>(p, n, vp, win);
}
#endif

}  // namespace

void WindowPositions(const glm::vec4* clip, int count, const ViewportTransform& vp, glm::vec4* window) {
  static const WindowPositionsFn fn = SOFTGL_CHOOSE(WindowPositionsOf);
  fn(clip, count, vp, window);
}

}  // namespace softgl::detail

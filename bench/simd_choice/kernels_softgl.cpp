// kernels_softgl.cpp — the kernel with softgl's lane types, compiled three times by the target attributes
// softgl's shader entry points use, in a unit built with the baseline flags (as a user's shader is).
#include <algorithm>
#include <cmath>

#include <softgl/lanes.h>

#include "kernels.h"

namespace simd_choice {
namespace {

using namespace softgl;

// The kernel body; Lanes types from softgl/lanes.h.
inline void Body(const Fragments& f) {
  const vec3 light(0.267f, 0.802f, 0.534f), eye(0.0f, 1.0f, 3.0f);
  for (std::size_t i = 0; i < f.n; i += kLanes) {
    const vec3 n = normalize(vec3(Float::Load(f.nx + i), Float::Load(f.ny + i), Float::Load(f.nz + i)));
    const vec3 p(Float::Load(f.px + i), Float::Load(f.py + i), Float::Load(f.pz + i));
    const vec3 v = normalize(eye - p);
    const vec3 h = normalize(light + v);
    const Float d = max(dot(n, light), 0.0f);
    Float s = max(dot(n, h), 0.0f);
    for (int k = 0; k < 5; ++k) s = s * s;  // ^32
    const Float lit = d * 0.8f + 0.1f;
    const vec3 c = select(d > 0.0f, vec3(lit) + vec3(s), vec3(0.1f, 0.1f, 0.2f));
    c.x.Store(f.r + i);
    c.y.Store(f.g + i);
    c.z.Store(f.b + i);
  }
}

SOFTGL_TARGET_BASE void Base(const Fragments& f) { Body(f); }
#if defined(SOFTGL_HAS_DISPATCH)
SOFTGL_TARGET_AVX2 void Avx2(const Fragments& f) { Body(f); }
SOFTGL_TARGET_AVX512 void Avx512(const Fragments& f) { Body(f); }
#endif

}  // namespace

void ShadeSoftgl(const Fragments& f, int isa) {
#if defined(SOFTGL_HAS_DISPATCH)
  if (isa == 2) return Avx512(f);
  if (isa == 1) return Avx2(f);
#endif
  (void)isa;
  Base(f);
}

void ShadeScalar(const Fragments& f) {
  const float l[3] = {0.267f, 0.802f, 0.534f}, e[3] = {0.0f, 1.0f, 3.0f};
  for (std::size_t i = 0; i < f.n; ++i) {
    float n[3] = {f.nx[i], f.ny[i], f.nz[i]}, v[3] = {e[0] - f.px[i], e[1] - f.py[i], e[2] - f.pz[i]}, h[3];
    const float in = 1.0f / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const float iv = 1.0f / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k) {
      n[k] *= in;
      v[k] *= iv;
      h[k] = l[k] + v[k];
    }
    const float ih = 1.0f / std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (float& c : h) c *= ih;
    const float d = std::max(n[0] * l[0] + n[1] * l[1] + n[2] * l[2], 0.0f);
    float s = std::max(n[0] * h[0] + n[1] * h[1] + n[2] * h[2], 0.0f);
    for (int k = 0; k < 5; ++k) s = s * s;
    const float lit = d * 0.8f + 0.1f;
    f.r[i] = d > 0.0f ? lit + s : 0.1f;
    f.g[i] = d > 0.0f ? lit + s : 0.1f;
    f.b[i] = d > 0.0f ? lit + s : 0.2f;
  }
}

}  // namespace simd_choice

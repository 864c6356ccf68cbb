// primitive_assembly.cpp — OpenGL's primitive modes as index lists.
#include "primitive_assembly.h"

namespace softgl::detail {

int VerticesPerPrimitive(Enum mode) {
  switch (mode) {
    case POINTS: return 1;
    case LINES:
    case LINE_STRIP:
    case LINE_LOOP: return 2;
    case TRIANGLES:
    case TRIANGLE_STRIP:
    case TRIANGLE_FAN: return 3;
    default: return 0;
  }
}

void AssemblePrimitives(Enum mode, int count, Primitives& out, bool first_vertex_convention) {
  out.vertices_per_primitive = VerticesPerPrimitive(mode);
  auto& idx = out.indices;
  idx.clear();
  if (count <= 0) return;
  const std::uint32_t n = std::uint32_t(count);
  switch (mode) {
    case POINTS:
      idx.reserve(n);
      for (std::uint32_t i = 0; i < n; ++i) idx.push_back(i);
      break;
    case LINES:
      idx.reserve(n & ~1u);
      for (std::uint32_t i = 0; i + 1 < n; i += 2) idx.insert(idx.end(), {i, i + 1});
      break;
    case LINE_STRIP:
    case LINE_LOOP:
      if (n < 2) break;
      idx.reserve(2 * n);
      for (std::uint32_t i = 0; i + 1 < n; ++i) idx.insert(idx.end(), {i, i + 1});
      if (mode == LINE_LOOP) idx.insert(idx.end(), {n - 1, 0u});
      break;
    case TRIANGLES:
      idx.reserve(n / 3 * 3);
      for (std::uint32_t i = 0; i + 2 < n; i += 3) idx.insert(idx.end(), {i, i + 1, i + 2});
      break;
    case TRIANGLE_STRIP:
      if (n < 3) break;
      idx.reserve(3 * (n - 2));
      for (std::uint32_t i = 0; i + 2 < n; ++i) {
        if (i % 2 == 0) idx.insert(idx.end(), {i, i + 1, i + 2});
        else if (first_vertex_convention) idx.insert(idx.end(), {i, i + 2, i + 1});  // (i + 1, i, i + 2) rotated
        else idx.insert(idx.end(), {i + 1, i, i + 2});
      }
      break;
    case TRIANGLE_FAN:
      if (n < 3) break;
      idx.reserve(3 * (n - 2));
      for (std::uint32_t i = 1; i + 1 < n; ++i) {
        if (first_vertex_convention) idx.insert(idx.end(), {i, i + 1, 0u});  // provoking vertex i, as table 13.2
        else idx.insert(idx.end(), {0u, i, i + 1});
      }
      break;
    default: break;
  }
}

}  // namespace softgl::detail

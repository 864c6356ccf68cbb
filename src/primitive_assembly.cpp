// primitive_assembly.cpp — OpenGL's primitive modes as index lists.
#include "primitive_assembly.h"

#include <cstddef>
#include <numeric>

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

namespace {

// Appends the primitives of `count` vertices at positions b .. b + count - 1.
void AssembleRun(Enum mode, std::uint32_t b, int count, std::vector<std::uint32_t>& idx, bool first_vertex_convention) {
  if (count <= 0) return;
  const std::uint32_t n = b + std::uint32_t(count);  // one past the run's last position
  if (mode == POINTS || mode == LINES || mode == TRIANGLES) {  // lists: the run's positions, whole primitives only
    const int per = mode == POINTS ? 1 : mode == LINES ? 2 : 3;
    const std::size_t at = idx.size();
    idx.resize(at + std::size_t(count / per * per));
    std::iota(idx.begin() + std::ptrdiff_t(at), idx.end(), b);
    return;
  }
  switch (mode) {
    case LINE_STRIP:
    case LINE_LOOP:
      if (count < 2) break;
      for (std::uint32_t i = b; i + 1 < n; ++i) idx.insert(idx.end(), {i, i + 1});
      if (mode == LINE_LOOP) idx.insert(idx.end(), {n - 1, b});
      break;
    case TRIANGLE_STRIP:
      if (count < 3) break;
      for (std::uint32_t i = b; i + 2 < n; ++i) {
        if ((i - b) % 2 == 0) idx.insert(idx.end(), {i, i + 1, i + 2});
        else if (first_vertex_convention) idx.insert(idx.end(), {i, i + 2, i + 1});  // (i + 1, i, i + 2) rotated
        else idx.insert(idx.end(), {i + 1, i, i + 2});
      }
      break;
    case TRIANGLE_FAN:
      if (count < 3) break;
      for (std::uint32_t i = b + 1; i + 1 < n; ++i) {
        if (first_vertex_convention) idx.insert(idx.end(), {i, i + 1, b});  // provoking vertex i, as table 13.2
        else idx.insert(idx.end(), {b, i, i + 1});
      }
      break;
    default: break;
  }
}

// How many primitives AssembleRun makes of `count` vertices.
std::uint64_t RunCount(Enum mode, std::int64_t count) {
  if (count <= 0) return 0;
  switch (mode) {
    case POINTS: return std::uint64_t(count);
    case LINES: return std::uint64_t(count / 2);
    case LINE_STRIP: return count < 2 ? 0 : std::uint64_t(count - 1);
    case LINE_LOOP: return count < 2 ? 0 : std::uint64_t(count);
    case TRIANGLES: return std::uint64_t(count / 3);
    case TRIANGLE_STRIP:
    case TRIANGLE_FAN: return count < 3 ? 0 : std::uint64_t(count - 2);
    default: return 0;
  }
}

}  // namespace

std::uint64_t PrimitiveCount(Enum mode, int count, const std::uint32_t* restarts, int restart_count) {
  if (count <= 0) return 0;
  std::uint64_t n = 0;
  std::int64_t begin = 0;
  for (int r = 0; r < restart_count; ++r) {
    n += RunCount(mode, std::int64_t(restarts[r]) - begin);
    begin = std::int64_t(restarts[r]) + 1;
  }
  return n + RunCount(mode, std::int64_t(count) - begin);
}

void AssemblePrimitives(Enum mode, int count, Primitives& out, bool first_vertex_convention) {
  AssemblePrimitives(mode, count, nullptr, 0, out, first_vertex_convention);
}

void AssemblePrimitives(Enum mode, int count, const std::uint32_t* restarts, int restart_count, Primitives& out,
                        bool first_vertex_convention) {
  out.vertices_per_primitive = VerticesPerPrimitive(mode);
  out.indices.clear();
  if (count <= 0) return;
  out.indices.reserve(std::size_t(count) * 3);  // enough for any mode (a loop adds one line per run)
  std::uint32_t begin = 0;
  for (int r = 0; r < restart_count; ++r) {
    AssembleRun(mode, begin, int(restarts[r] - begin), out.indices, first_vertex_convention);
    begin = restarts[r] + 1;
  }
  AssembleRun(mode, begin, count - int(begin), out.indices, first_vertex_convention);
}

}  // namespace softgl::detail

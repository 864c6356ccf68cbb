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
    case LINE_LOOP:
    case LINES_ADJACENCY:
    case LINE_STRIP_ADJACENCY: return 2;
    case TRIANGLES:
    case TRIANGLE_STRIP:
    case TRIANGLE_FAN:
    case TRIANGLES_ADJACENCY:
    case TRIANGLE_STRIP_ADJACENCY: return 3;
    default: return 0;
  }
}

bool IsAdjacency(Enum mode) {
  return mode == LINES_ADJACENCY || mode == LINE_STRIP_ADJACENCY || mode == TRIANGLES_ADJACENCY ||
         mode == TRIANGLE_STRIP_ADJACENCY;
}

namespace {

// Triangle i of a TRIANGLE_STRIP_ADJACENCY run of n triangles from position b (OpenGL 4.6, table 10.1, counted from
// 0 here): its three vertices, then the vertices beyond its edges 1-2, 2-3 and 3-1. Odd triangles take their first
// two vertices swapped, which keeps the strip's winding.
void StripAdjacencyTriangle(std::uint32_t b, std::uint32_t i, std::uint32_t n, std::uint32_t (&t)[3],
                            std::uint32_t (&adj)[3]) {
  const std::uint32_t v = b + 2 * i;
  const bool odd = (i & 1u) != 0;
  t[0] = odd ? v + 2 : v;
  t[1] = odd ? v : v + 2;
  t[2] = v + 4;
  adj[0] = i == 0 ? b + 1 : v - 2;  // across the edge shared with the triangle before (or the strip's own)
  const std::uint32_t next = i + 1 == n ? v + 5 : v + 6;  // the next triangle's new vertex, or the strip's last
  const std::uint32_t own = v + 3;                        // the adjacent vertex the strip gives this triangle
  adj[1] = odd ? own : next;
  adj[2] = odd ? next : own;
  if (i == 0 && n == 1) {
    adj[1] = v + 5;
    adj[2] = v + 3;
  } else if (i == 0) {
    adj[1] = v + 6;
    adj[2] = v + 3;
  }
}

// Appends the primitives of a run with adjacency, in their full form (`full`: each primitive's vertices in a
// geometry stage's order, 4 for a line, 6 for a triangle) or as the lines and triangles they draw without one.
void AssembleAdjacencyRun(Enum mode, std::uint32_t b, int count, std::vector<std::uint32_t>& idx, bool full,
                          bool first_vertex_convention) {
  const std::uint32_t c = std::uint32_t(count);
  switch (mode) {
    case LINES_ADJACENCY:
    case LINE_STRIP_ADJACENCY: {
      const bool strip = mode == LINE_STRIP_ADJACENCY;
      const std::uint32_t lines = strip ? (c < 4 ? 0 : c - 3) : c / 4;
      for (std::uint32_t i = 0; i < lines; ++i) {
        const std::uint32_t v = b + (strip ? i : 4 * i);
        if (full) idx.insert(idx.end(), {v, v + 1, v + 2, v + 3});
        else idx.insert(idx.end(), {v + 1, v + 2});
      }
      break;
    }
    case TRIANGLES_ADJACENCY:
      for (std::uint32_t v = b; v + 6 <= b + c; v += 6) {
        if (full) idx.insert(idx.end(), {v, v + 1, v + 2, v + 3, v + 4, v + 5});
        else idx.insert(idx.end(), {v, v + 2, v + 4});
      }
      break;
    case TRIANGLE_STRIP_ADJACENCY: {
      const std::uint32_t n = c < 6 ? 0 : (c - 4) / 2;
      for (std::uint32_t i = 0; i < n; ++i) {
        std::uint32_t t[3], adj[3];
        StripAdjacencyTriangle(b, i, n, t, adj);
        if (full) idx.insert(idx.end(), {t[0], adj[0], t[1], adj[1], t[2], adj[2]});
        else if (first_vertex_convention && (i & 1u)) idx.insert(idx.end(), {t[1], t[2], t[0]});  // vertex 2i first
        else idx.insert(idx.end(), {t[0], t[1], t[2]});
      }
      break;
    }
    default: break;
  }
}

// Appends the primitives of `count` vertices at positions b .. b + count - 1.
void AssembleRun(Enum mode, std::uint32_t b, int count, std::vector<std::uint32_t>& idx, bool first_vertex_convention,
                 bool adjacency) {
  if (count <= 0) return;
  if (IsAdjacency(mode)) return AssembleAdjacencyRun(mode, b, count, idx, adjacency, first_vertex_convention);
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
    case LINES_ADJACENCY: return std::uint64_t(count / 4);
    case LINE_STRIP_ADJACENCY: return count < 4 ? 0 : std::uint64_t(count - 3);
    case TRIANGLES_ADJACENCY: return std::uint64_t(count / 6);
    case TRIANGLE_STRIP_ADJACENCY: return count < 6 ? 0 : std::uint64_t((count - 4) / 2);
    default: return 0;
  }
}

}  // namespace

void AppendPrimitives(Enum mode, std::uint32_t begin, int count, std::vector<std::uint32_t>& indices,
                      bool first_vertex_convention) {
  AssembleRun(mode, begin, count, indices, first_vertex_convention, false);
}

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

void AssemblePrimitives(Enum mode, int count, Primitives& out, bool first_vertex_convention, bool adjacency) {
  AssemblePrimitives(mode, count, nullptr, 0, out, first_vertex_convention, adjacency);
}

void AssemblePrimitives(Enum mode, int count, const std::uint32_t* restarts, int restart_count, Primitives& out,
                        bool first_vertex_convention, bool adjacency) {
  const bool full = adjacency && IsAdjacency(mode);
  out.vertices_per_primitive = full ? 2 * VerticesPerPrimitive(mode) : VerticesPerPrimitive(mode);
  out.indices.clear();
  if (count <= 0) return;
  // Enough for any mode: a loop adds one line per run; a strip with adjacency 6 vertices per 2 of its own.
  out.indices.reserve(std::size_t(count) * (full ? 6 : 3));
  std::uint32_t begin = 0;
  for (int r = 0; r < restart_count; ++r) {
    AssembleRun(mode, begin, int(restarts[r] - begin), out.indices, first_vertex_convention, full);
    begin = restarts[r] + 1;
  }
  AssembleRun(mode, begin, count - int(begin), out.indices, first_vertex_convention, full);
}

}  // namespace softgl::detail

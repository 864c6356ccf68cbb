// primitive_assembly.h — stage 3: turn a draw's vertex sequence into points, lines or triangles.
#pragma once

#include <cstdint>
#include <vector>

#include <softgl/enums.h>

namespace softgl::detail {

/// The primitives of one draw, as positions in the draw's vertex sequence (0 .. count-1).
struct Primitives {
  // 1 points, 2 lines, 3 triangles; 4 lines and 6 triangles with adjacency in full (a geometry stage's input); 0
  // for an invalid mode
  int vertices_per_primitive = 0;
  std::vector<std::uint32_t> indices;  // vertices_per_primitive entries per primitive
  int Count() const { return vertices_per_primitive ? int(indices.size()) / vertices_per_primitive : 0; }
};

/// Assembles `count` vertices of `mode` following OpenGL's rules: incomplete trailing primitives are dropped;
/// TRIANGLE_STRIP keeps every triangle's winding consistent with the first one (odd triangles swap their first two
/// vertices); LINE_LOOP closes back to vertex 0. Each primitive's provoking vertex (OpenGL 4.6, table 13.2) is its
/// last for the last-vertex convention, its first when `first_vertex_convention` (strip and fan triangles are then
/// rotated, which keeps their winding, to bring it first). The modes with adjacency make, with `adjacency`, each
/// primitive's vertices in the order a geometry stage reads them (OpenGL 4.6, section 10.1 and table 10.1: for a
/// triangle, its vertices at 0, 2, 4 and the adjacent ones at 1, 3, 5), and otherwise the lines and triangles they
/// draw without a geometry stage.
void AssemblePrimitives(Enum mode, int count, Primitives& out, bool first_vertex_convention = false,
                        bool adjacency = false);

/// As AssemblePrimitives, with primitive restart: the positions restarts[0 .. restart_count) (ascending) are no
/// vertices; each run of positions between them is assembled on its own, as if it were a draw of its own.
void AssemblePrimitives(Enum mode, int count, const std::uint32_t* restarts, int restart_count, Primitives& out,
                        bool first_vertex_convention = false, bool adjacency = false);

/// Appends to `indices` the primitives of one run of `count` vertices at positions begin .. begin + count - 1, as
/// AssemblePrimitives makes them (without adjacency).
void AppendPrimitives(Enum mode, std::uint32_t begin, int count, std::vector<std::uint32_t>& indices,
                      bool first_vertex_convention);

/// The number of primitives AssemblePrimitives makes, without making them (for any count, in constant memory).
std::uint64_t PrimitiveCount(Enum mode, int count, const std::uint32_t* restarts = nullptr, int restart_count = 0);

/// 1, 2 or 3 for a valid mode (the kind of primitive it draws: points, lines, triangles), 0 otherwise.
int VerticesPerPrimitive(Enum mode);

/// Whether `mode` is one of the four modes with adjacency.
bool IsAdjacency(Enum mode);

}  // namespace softgl::detail

// geometry_stage.h — stage 3b: the program's geometry stage, between primitive assembly and clipping. It reads the
// assembled primitives with the vertex stage's outputs and makes new vertices and primitives in their place.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <softgl/shader.h>

#include "primitive_assembly.h"
#include "types.h"
#include "worker_pool.h"

namespace softgl::detail {

/// The assembled primitives of one piece of a draw, as the geometry stage reads them: `count` primitives of
/// `layout.InputVertices()` vertices; primitive p is primitive q = p % per_instance of the piece's instance
/// p / per_instance, its vertices at positions prims.indices[q * per ..], shaded vertices map[position] +
/// instance * unique of `vertices` (the vertex stage's outputs, before clipping).
struct GeometryInput {
  const GeometryLayout* layout = nullptr;
  const Primitives* prims = nullptr;
  std::size_t per_instance = 0, count = 0;
  std::uint32_t unique = 0;
  const std::uint32_t* map = nullptr;
  const ShadedVertices* vertices = nullptr;
  std::uint32_t first_instance = 0;  // gl_InstanceID of the piece's first instance
  std::uint32_t primitive_base = 0;  // gl_PrimitiveIDIn of the piece's first primitive
  const Textures* textures = nullptr;
  bool provoking_first = false;  // FIRST_VERTEX_CONVENTION: output triangle strips rotated as assembly does
};

/// Memory the geometry stage reuses from draw to draw.
struct GeometryScratch {
  std::vector<std::uint32_t> vertex_index;
  std::vector<std::int32_t> primitive_ids, instance_ids;
  std::vector<float> records;
  std::vector<int> emitted;
  ShadedVertices input;        // the vertex stage's outputs while the geometry stage reads them
  Primitives input_primitives;
  std::vector<std::uint32_t> input_map;
};

/// Input primitives handled per RunGeometry call: as many as fit kGeometryVertexBudget emitted vertices.
inline constexpr std::size_t kGeometryVertexBudget = std::size_t(1) << 15;
std::size_t GeometryGroup(const GeometryLayout& layout);

/// Runs the program's geometry stage, every invocation, on input primitives [begin, end), in parallel batches of
/// 16 primitives, and writes what they emit, in order (by primitive, then invocation, then as emitted), to `out`
/// (position, point size, varyings, and the layer when `layers`) and the primitives those vertices make to
/// `out_prims` (points, lines or triangles, as AssemblePrimitives makes them of each strip).
void RunGeometry(const Program& program, const GeometryInput& in, std::size_t begin, std::size_t end, bool layers,
                 WorkerPool& pool, GeometryScratch& scratch, ShadedVertices& out, Primitives& out_prims);

}  // namespace softgl::detail

// pipeline.h — one draw call through every stage: fetch -> vertex shader -> assembly -> clip -> divide/viewport
// -> cull -> rasterize -> fragment shader -> fragment operations -> framebuffer.
//
// The context validates the call and resolves its objects into a FetchPlan and a DrawState; from there the draw
// flows forward through the stages in plain structs (types.h), and only the framebuffer is written.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <softgl/shader.h>

#include "fragment_ops.h"
#include "framebuffer.h"
#include "primitive_assembly.h"
#include "types.h"
#include "vertex_fetch.h"
#include "viewport.h"

namespace softgl::detail {

inline constexpr float kMaxPointSize = 255.0f;
/// Largest number of vertices shaded at once; larger draws go through in pieces (a multiple of 6, so that pieces of
/// point, line and triangle lists hold whole primitives).
inline constexpr int kDrawChunk = 6 * 8192;

/// How primitives are turned into fragments: the context keeps one and copies it into each draw.
struct PrimitiveState {
  bool cull_enabled = false;
  Enum cull_face = BACK;
  Enum front_face = CCW;
  Enum polygon_mode = FILL;
  bool program_point_size = false;
  float point_size = 1.0f;
  bool offset_fill = false, offset_line = false, offset_point = false;  // POLYGON_OFFSET_FILL / _LINE / _POINT
  float offset_factor = 0.0f, offset_units = 0.0f;
};

/// Everything a draw needs from the context's state, resolved at draw time.
struct DrawState {
  const Program* program = nullptr;
  ViewportTransform viewport;
  Rect bounds;  // viewport, framebuffer and (when enabled) scissor rectangle intersected
  PrimitiveState primitive;
  FragmentOpsState ops;
  const Textures* textures = nullptr;  // what the shader stages sample
};

/// The vertices a draw reads: either `count` consecutive vertices from `first`, or `count` element indices.
struct DrawCall {
  Enum mode = TRIANGLES;
  int count = 0;
  std::uint32_t first = 0;
  const std::uint32_t* elements = nullptr;  // null for DrawArrays
};

/// Per-context memory reused from draw to draw, so that drawing allocates only when a draw is bigger than any
/// before it.
struct Scratch {
  std::vector<std::uint32_t> shade_indices;  // vertex index of each vertex to shade
  std::vector<std::uint32_t> element_to_shaded;
  std::vector<glm::vec4> attribs;
  std::vector<int> vertex_ids;
  ShadedVertices shaded;
  Primitives primitives;
  std::unique_ptr<QuadBuffer> quads = std::make_unique<QuadBuffer>();
};

/// Runs one draw. May throw std::bad_alloc for a draw too large for memory; nothing else is thrown.
void Draw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const RenderTarget& target,
          Scratch& scratch);

}  // namespace softgl::detail

// types.h — the plain structs that flow between pipeline stages, in pipeline order.
//
//   vertex fetch  -> glm::vec4 attribs[kMaxVertexAttribs] per vertex
//   vertex shader -> ShadedVertices (clip-space positions, point sizes, varyings)
//   assembly      -> Primitives (indices into ShadedVertices)
//   clipper       -> ClipPolygon (ClipVertex)
//   divide/viewport -> WindowVertex
//   culling       -> facing decision
//   rasterizer    -> QuadBuffer (2x2 quads with coverage and interpolated varyings)
//   fragment shader -> FragmentOut per lane
//   fragment ops  -> Framebuffer
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/shader.h>

namespace softgl::detail {

/// Output of the vertex stage for one draw: one entry per shaded vertex.
struct ShadedVertices {
  int count = 0;
  int nvar = 0;  // floats of varyings per vertex
  std::vector<glm::vec4> position;
  std::vector<float> point_size;
  std::vector<float> varyings;  // [count][nvar]
  const float* Varyings(int i) const { return varyings.data() + std::size_t(i) * nvar; }
  // Computed once per vertex beside the shader, for primitives that need no clipping: the vertex's guard-band
  // clip codes and, where they are 0, its window position and varyings divided by w (what ToWindow gives).
  std::vector<unsigned> clip_codes;
  std::vector<glm::vec4> window;
  std::vector<float> window_varyings;  // [count][nvar]
};

/// A vertex in homogeneous clip space with its varyings (input and output of clipping).
struct ClipVertex {
  glm::vec4 pos;
  float var[kMaxVaryingFloats];
};

/// A vertex after the perspective divide and the viewport transform.
struct WindowVertex {
  glm::vec4 win;                   // window x, y; depth z in [n, f]; w = 1 / w_clip
  float var[kMaxVaryingFloats];    // varyings divided by w_clip, ready for perspective-correct interpolation
};

/// Half-open pixel rectangle [x0, x1) x [y0, y1) in window coordinates.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool Empty() const { return x0 >= x1 || y0 >= y1; }
};

/// Rasterizer output: a batch of 2x2 quads ready for the fragment stage. Lane order within a quad:
/// (x, y), (x+1, y), (x, y+1), (x+1, y+1), with (x, y) even.
struct QuadBuffer {
  static constexpr int kCapacity = 64;
  int count = 0;
  int nvar = 0;
  bool front_facing = true;
  int qx[kCapacity];
  int qy[kCapacity];
  std::uint8_t live[kCapacity * 4];           // coverage; cleared by discard
  glm::vec4 frag_coord[kCapacity * 4];
  float varyings[kCapacity * 4 * kMaxVaryingFloats];  // [lane][nvar], lanes packed with stride nvar
  FragmentOut out[kCapacity * 4];
};

/// Where the rasterizer sends a full (or final) QuadBuffer: the fragment stage and per-fragment operations.
struct QuadSink {
  void (*flush)(void* user, QuadBuffer& quads) = nullptr;
  void* user = nullptr;
  void Flush(QuadBuffer& quads) const {
    if (quads.count > 0) flush(user, quads);
    quads.count = 0;
  }
};

}  // namespace softgl::detail

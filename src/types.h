// types.h — the plain structs that flow between pipeline stages, in pipeline order.
//
//   vertex fetch  -> glm::vec4 attribs[kMaxVertexAttribs] per vertex
//   vertex shader -> ShadedVertices (clip-space positions, point sizes, varyings)
//   assembly      -> Primitives (indices into ShadedVertices)
//   clipper       -> ClipPolygon (ClipVertex)
//   divide/viewport -> WindowVertex
//   culling       -> facing decision
//   rasterizer    -> BlockBuffer (4x4 blocks with coverage and interpolated varyings)
//   fragment shader -> colours and depth per lane, in the BlockBuffer
//   fragment ops  -> Framebuffer
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/shader.h>

namespace softgl::detail {

/// Most samples a pixel has (MAX_SAMPLES): multisampled buffers have 2, 4 or 8.
inline constexpr int kMaxSamples = 8;
/// The standard sample positions (those of Direct3D and Vulkan, which llvmpipe uses) of a pixel with `samples`
/// samples (2, 4 or 8; any other count: the centre), in 1/16 pixel from the pixel's lower left corner, x then y:
/// sample s of pixel (i, j) lies at (i + x / 16, j + y / 16). Defined with the rasterizer.
const std::uint8_t (*SamplePositions(int samples))[2];

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
  // [count][4 + nvar]: each vertex's window position, then its varyings divided by w (a binned primitive's vertex
  // as the tiles read it: BinnedBatch's tables).
  std::vector<float> window_vertices;
  int WindowStride() const { return 4 + nvar; }
  const float* WindowVertexAt(std::uint32_t i) const {
    return window_vertices.data() + std::size_t(i) * std::size_t(WindowStride());
  }
  // While transform feedback records: the values it records of each vertex, as the vertex stage wrote them
  // ([count][FeedbackLayout::floats]).
  std::vector<float> feedback;
  // Drawn into a layered framebuffer by a program that writes gl_Layer: each vertex's layer.
  std::vector<int> layer;
};

/// gl_PrimitiveID as the two flat varyings that carry it to the fragment stage (Program::ReadsPrimitiveId): its
/// low and high 16 bits, each exact as a float.
inline void PrimitiveIdFloats(std::uint32_t id, float* out) {
  out[0] = float(id & 0xFFFFu);
  out[1] = float(id >> 16);
}

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

/// A window vertex read where it is stored (a tile's list, a WindowVertex): its position and its varyings.
struct VertexView {
  glm::vec4 win;
  const float* var = nullptr;
  VertexView() = default;
  VertexView(const glm::vec4& position, const float* varyings) : win(position), var(varyings) {}
  VertexView(const WindowVertex& v) : win(v.win), var(v.var) {}  // implicit: a WindowVertex is read as it stands
};

/// Half-open pixel rectangle [x0, x1) x [y0, y1) in window coordinates.
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool Empty() const { return x0 >= x1 || y0 >= y1; }
};

/// a0 + dx * x + dy * y: an attribute's plane in window space, relative to vertex 0.
struct Plane {
  float a0, dx, dy;
};

/// What interpolating a triangle's fragments needs: its planes, relative to vertex 0 at (x0, y0).
struct TrianglePlanes {
  float x0 = 0.0f, y0 = 0.0f;
  Plane z, oow;
  int nvar = 0;
  // The varyings' planes, a0 + dx * x + dy * y for varying i, as rows (computed and read four or more at a time).
  alignas(16) float a0[kMaxVaryingFloats], dx[kMaxVaryingFloats], dy[kMaxVaryingFloats];
  bool perspective[kMaxVaryingFloats];  // smooth: divided by w (the others are taken as they are)
  // A multisampled triangle's change of depth from a pixel's centre to each of its samples (z.dx ox + z.dy oy, the
  // sample's offset (ox, oy) from the centre), for the samples' depth tests; set only for a multisampled triangle.
  float sample_dz[kMaxSamples];
};

/// A point as gl_PointCoord sees it: its centre in window coordinates, 1 / its size, and t's direction (+1:
/// POINT_SPRITE_COORD_ORIGIN LOWER_LEFT, t grows upwards; -1: UPPER_LEFT, downwards). For a fragment at (x, y)
/// (gl_FragCoord), gl_PointCoord = (0.5 + (x - cx) / size, 0.5 + t_sign * (y - cy) / size) (OpenGL 4.6, 14.4.1).
struct PointSprite {
  float cx = 0.0f, cy = 0.0f, inv_size = 1.0f, t_sign = -1.0f;
};

/// Rasterizer output: a batch of blocks ready for the fragment stage, with their coverage and interpolated values,
/// and the fragment stage's outputs. A block is 16 fragments: four 2x2 quads anywhere in the target (of one draw and
/// one facing, possibly of different primitives, never two at the same place), lane = quad * 4 + (x & 1) +
/// 2 * (y & 1). Every lane is filled (helper lanes too), so that the fragment stage can take derivatives; a block
/// with fewer than four quads repeats its first quad in the others, never live.
struct BlockBuffer {
  static constexpr int kCapacity = 16;
  int count = 0;
  int nvar = 0;
  bool front_facing = true;
  int quads[kCapacity];   // quads in each block (1 to 4)
  int qx[kCapacity][4];   // quad origins (even coordinates)
  int qy[kCapacity][4];
  std::uint32_t live[kCapacity];  // coverage bits; cleared by the early depth test and discard
  // A multisampled target's coverage: `samples` (its sample count; 1: none) and, for sample s of block b, the
  // lanes whose pixel has sample s covered (a lane is live while some sample is). The rasterizer gives every
  // quad it emits all samples of its live lanes unless it computes them itself (a multisampled triangle).
  int samples = 1;
  std::uint32_t sample_live[kCapacity][kMaxSamples];
  // A triangle's quads have their varyings interpolated after the early depth test, from its planes: each quad
  // refers to its triangle's planes here (null: the varyings are already there, as for lines and points). One entry
  // per triangle with a quad in the buffer, so never more than the buffer has quads.
  static constexpr int kPlanes = kCapacity * 4;
  TrianglePlanes planes[kPlanes];
  int plane_count = 0;
  int epoch = 0;  // counts flushes: a triangle's entry in `planes` is valid in the epoch it was made
  const TrianglePlanes* quad_planes[kCapacity][4];
  alignas(64) float frag_coord[kCapacity][4][kLanes];                  // x, y, z, 1/w
  // Points: while `points` is set, every quad of the buffer belongs to a point, which AddQuad records for it from
  // `point` (the one being rasterized); the fragment stage makes gl_PointCoord of each lane from it and the lane's
  // gl_FragCoord. Points and other primitives never share the buffer.
  bool points = false;
  PointSprite point;
  PointSprite quad_point[kCapacity][4];
  alignas(64) float point_coord[kCapacity][2][kLanes];  // gl_PointCoord (s, t), made by the fragment stage
  alignas(64) float varyings[kCapacity * kBlockVaryingFloats];         // block b: [nvar][16] at b * kBlockVaryingFloats
  FragmentLanesOut out[kCapacity];  // the fragment shader's outputs (it writes them here)
  float* Varyings(int b) { return varyings + std::size_t(b) * kBlockVaryingFloats; }
  /// Lanes of output o's channel c (or of the depth) of block b, as 16 floats.
  const float* Color(int b, int o, int c) const { return reinterpret_cast<const float*>(&out[b].color[o][c].v); }
  const float* Depth(int b) const { return reinterpret_cast<const float*>(&out[b].depth.v); }
  const float* Varyings(int b) const { return varyings + std::size_t(b) * kBlockVaryingFloats; }
  /// The pixel of lane `lane` of block b.
  int X(int b, int lane) const { return qx[b][lane >> 2] + (lane & 1); }
  int Y(int b, int lane) const { return qy[b][lane >> 2] + ((lane >> 1) & 1); }
  /// Fills the unused quads of the last block from its first (positions and values, never live).
  void CloseLast() {
    if (count == 0) return;
    const int b = count - 1;
    for (int q = quads[b]; q < 4; ++q) {
      qx[b][q] = qx[b][0];
      qy[b][q] = qy[b][0];
      quad_planes[b][q] = quad_planes[b][0];
      quad_point[b][q] = quad_point[b][0];
      if (!quad_planes[b][0])  // (from planes, gl_FragCoord is interpolated after this, for every quad)
        for (int c = 0; c < 4; ++c)
          for (int k = 0; k < 4; ++k) frag_coord[b][c][q * 4 + k] = frag_coord[b][c][k];
      float* v = Varyings(b);
      for (int i = 0; i < nvar; ++i)
        for (int k = 0; k < 4; ++k) v[i * kLanes + q * 4 + k] = v[i * kLanes + k];
    }
  }
};

/// gl_FragCoord of the quads that refer to a triangle's planes (rasterizer.cpp): the rasterizer leaves them for
/// this pass, which takes a block's four quads at once where they share planes.
void InterpolateFragCoords(BlockBuffer& blocks);

/// Where the rasterizer sends a full (or final) BlockBuffer: the fragment stage and per-fragment operations.
struct BlockSink {
  void (*flush)(void* user, BlockBuffer& blocks) = nullptr;
  void* user = nullptr;
  void Flush(BlockBuffer& blocks) const {
    if (blocks.count > 0) {
      blocks.CloseLast();
      InterpolateFragCoords(blocks);
      flush(user, blocks);
    }
    blocks.count = 0;
    blocks.plane_count = 0;
    ++blocks.epoch;
  }
};

}  // namespace softgl::detail

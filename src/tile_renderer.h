// tile_renderer.h — deferred, tile-based rendering: the commands recorded for one render target (clears and
// binned draws) and the back end that plays them tile by tile on the worker pool.
//
// Each tile is rasterized, shaded and written by one thread, taking the commands in submission order and, within
// a draw, its primitives in order; tiles share no pixels, so the image is the same whatever the thread count.
// A Frame is rendered (and emptied) when the context needs its pixels or changes what it refers to: ReadPixels,
// Finish, a framebuffer switch, a texture change, or when the recorded data outgrows a memory budget.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <softgl/shader.h>
#include <softgl/texture.h>

#include "binner.h"
#include "fragment_ops.h"
#include "framebuffer.h"
#include "texture.h"
#include "worker_pool.h"

namespace softgl::detail {

/// A draw as the back end needs it, captured when the draw is recorded.
struct DrawPacket {
  std::shared_ptr<const Program> snapshot;  // copy of the shader taken at draw time (null: `program` is live)
  const Program* program = nullptr;
  FragmentOpsState ops;
  Rect bounds;  // viewport, target and scissor
  int nvar = 0;
  const Interpolation* interpolation = nullptr;  // the program's varying qualifiers (null: all smooth)
  bool shader_depth = false;  // the program writes gl_FragDepth
  bool early_depth = false;  // EarlyDepthTestApplies
  TextureView views[2][kMaxTextureUnits];  // [2D, cube][unit]
  Textures textures;                       // points into views
  std::vector<BinnedBatch*> batches;
  std::shared_ptr<OcclusionCounter> occlusion[2];  // keeps ops.occlusion's counters alive until rendered

  DrawPacket() = default;
  DrawPacket(const DrawPacket& other) { *this = other; }
  /// Copies everything but the batches, pointing textures at this packet's own views.
  DrawPacket& operator=(const DrawPacket& other);
};

/// Clear(mask) as recorded: the area (target and scissor) and the values, masks applied.
struct ClearPacket {
  Rect area;
  bool color = false, depth = false, stencil = false;
  glm::vec4 color_value{0.0f};
  bool color_mask[4] = {true, true, true, true};
  float depth_value = 1.0f;
  std::uint8_t stencil_value = 0, stencil_mask = 0xFF;
};

/// Memory one worker thread reuses from tile to tile.
struct TileScratch {
  std::unique_ptr<BlockBuffer> blocks = std::make_unique<BlockBuffer>();
};

class Frame {
 public:
  bool Empty() const { return commands_.empty(); }
  /// Whether commands for `target` can join this frame (it is empty, or already draws into the same buffers).
  bool Accepts(const RenderTarget& target) const;
  const TileGrid& Grid() const { return grid_; }

  void AddClear(const RenderTarget& target, const ClearPacket& clear);
  /// A new draw command, a copy of `proto`; fill its batches with NewBatch().
  DrawPacket& AddDraw(const RenderTarget& target, const DrawPacket& proto);
  /// An empty batch owned by the frame (reused from frame to frame).
  BinnedBatch& NewBatch(int nvar);
  /// Lists the last draw added in the tiles its batches touch, once its batches are filled: a tile renders only
  /// the commands listed in it.
  void ListLastDraw();

  /// Memory held by recorded batches, in bytes: the sum of what AddBytes was told since the frame began.
  std::size_t Bytes() const { return bytes_; }
  /// Counts `bytes` more held by the frame's batches (each batch counted once, when it is filled).
  void AddBytes(std::size_t bytes) { bytes_ += bytes; }
  /// Renders every tile on the pool, then empties the frame. Throws std::bad_alloc when memory runs out.
  void Render(WorkerPool& pool, std::vector<TileScratch>& scratch);
  /// Forgets the recorded commands without rendering them.
  void Reset();

 private:
  void Begin(const RenderTarget& target);
  void RenderTile(int tile, TileScratch& scratch) const;

  struct Command {
    bool draw;
    std::size_t index;  // into draws_ or clears_
  };
  RenderTarget target_;
  TileGrid grid_;
  std::vector<Command> commands_;
  std::vector<std::vector<std::uint32_t>> tile_commands_;  // per tile: the commands touching it, in order
  std::vector<std::unique_ptr<DrawPacket>> draws_;  // draws_used_ of them recorded, the others kept for reuse
  std::size_t draws_used_ = 0;
  static constexpr std::size_t kKeptDraws = 4096;  // packets kept from frame to frame, at most
  std::vector<ClearPacket> clears_;
  std::vector<std::unique_ptr<BinnedBatch>> batches_;
  std::size_t batches_used_ = 0;
  std::size_t bytes_ = 0;
};

}  // namespace softgl::detail

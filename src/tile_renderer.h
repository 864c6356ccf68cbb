// tile_renderer.h — deferred, tile-based rendering: the commands recorded for one render target (clears and
// binned draws) and the back end that plays them tile by tile on the worker pool.
//
// Each tile is rasterized, shaded and written by one thread, taking the commands in submission order and, within
// a draw, its primitives in order; tiles share no pixels, so the image is the same whatever the thread count.
// A Frame is rendered (and emptied) when the context needs its pixels or changes what it refers to: ReadPixels,
// Finish, a framebuffer switch, a texture change, or when the recorded data outgrows a memory budget.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

#include <softgl/shader.h>
#include <softgl/texture.h>

#include "binner.h"
#include "fragment_ops.h"
#include "framebuffer.h"
#include "hierarchical_depth.h"
#include "texture.h"
#include "worker_pool.h"

namespace softgl::detail {

/// The textures of the bound units resolved for draws: a copy of each bound unit's view, and the Textures the
/// shader samples through, pointing at them.
struct DrawTextures {
  TextureView views[kTextureKinds][kMaxTextureUnits];  // [TextureKind][unit]
  Textures textures;  // points into views (null for a unit with nothing bound)
  /// Whether any unit has a texture bound.
  static bool Any(const Textures& t);
  /// Whether `t` binds the same units to the same views as this.
  bool Same(const Textures& t) const;
  /// Copies the views of `t`'s bound units, pointing textures at the copies.
  void CopyFrom(const Textures& t);
};

/// Whether two render targets are the same buffers (size, samples, depth, stencil and colour buffers): commands
/// for both can be recorded into one frame.
bool SameBuffers(const RenderTarget& a, const RenderTarget& b);

/// A draw as the back end needs it, captured when the draw is recorded. Small, and kept in one array: a frame of
/// many small draws reads them one after another.
struct DrawPacket {
  std::shared_ptr<const Program> snapshot;  // copy of the shader taken at draw time (null: `program` is live)
  const Program* program = nullptr;
  const Textures* textures = nullptr;  // the frame's copy of the bound units (the prototype: the context's own)
  FragmentOpsState ops;
  Rect bounds;  // viewport, target and scissor
  int nvar = 0;
  const Interpolation* interpolation = nullptr;  // the program's varying qualifiers (null: all smooth)
  bool shader_depth = false;  // the program writes gl_FragDepth
  bool early_depth = false;  // EarlyDepthTestApplies
  bool point_lower_left = false;  // POINT_SPRITE_COORD_ORIGIN is LOWER_LEFT
  float line_width = 1.0f;        // LineWidth, clamped to kMaxLineWidth
  // The draw's batches: the frame's batches first_batch .. first_batch + batch_count. A shared batch (one, holding
  // the primitives of consecutive small draws) has the draw's primitives at indices prim_lo .. prim_hi.
  bool shared = false;
  std::uint32_t first_batch = 0, batch_count = 0;
  std::uint32_t prim_lo = 0, prim_hi = 0;
  std::shared_ptr<OcclusionCounter> occlusion[2];  // keeps ops.occlusion's counters alive until rendered
};

/// Clear(mask) as recorded: the area (target and scissor) and the values, masks applied.
struct ClearPacket {
  Rect area;
  bool color = false, depth = false, stencil = false;
  std::uint32_t color_buffers = ~0u;  // the draw buffers whose colour is cleared (bit i: draw buffer i)
  glm::vec4 color_value{0.0f};
  bool color_mask[4] = {true, true, true, true};
  float depth_value = 1.0f;
  std::uint8_t stencil_value = 0, stencil_mask = 0xFF;
};

/// Memory one worker thread reuses from tile to tile.
struct TileScratch {
  std::unique_ptr<BlockBuffer> blocks = std::make_unique<BlockBuffer>();
  HierarchicalDepth depth_bounds;  // the coarse depth of the tile being rendered, and its statistics
};

class Frame {
 public:
  bool Empty() const { return commands_.empty(); }
  /// Whether commands for `target` can join this frame (it is empty, or already draws into the same buffers).
  bool Accepts(const RenderTarget& target) const;
  const TileGrid& Grid() const { return grid_; }

  void AddClear(const RenderTarget& target, const ClearPacket& clear);
  /// A new draw command, a copy of `proto` (with a copy of its textures); give it batches with NewBatches() or
  /// SharedBatch().
  DrawPacket& AddDraw(const RenderTarget& target, const DrawPacket& proto);
  /// Gives the last draw added `count` empty batches of its own (reused from frame to frame); fill each with
  /// Batch(k), then Finish it.
  void NewBatches(int count, int nvar);
  BinnedBatch& Batch(const DrawPacket& draw, int k) { return *batches_[draw.first_batch + std::uint32_t(k)]; }
  /// The batch the last draw added appends its primitives to when it has few: one shared with the draws before
  /// it while they are consecutive commands with the same varyings. Call EndShared() once the draw is binned.
  /// When the draw before renders with the same state (SameState: the same shader copy, textures, operations
  /// and bounds), the last draw is merged into it: its record and command are removed, and the draw before
  /// becomes the last draw added, its primitives extended by the ones appended now.
  BinnedBatch& SharedBatch(int nvar);
  void EndShared();
  /// Lists the last draw added in the tiles its batches touch, once its batches are filled: a tile renders only
  /// the commands listed in it.
  void ListLastDraw();

  /// Keeps `vertices` (the window runs of a draw's shaded vertices, which its batches' tables point into) until
  /// the frame is rendered or reset, counting its bytes; `vertices` gets in exchange a vector an earlier frame
  /// kept (its storage reused, so a steady sequence of draws allocates nothing).
  void KeepVertices(std::vector<float>& vertices);
  /// Memory held by recorded batches, in bytes: the sum of what AddBytes was told since the frame began.
  std::size_t Bytes() const { return bytes_; }
  /// Counts `bytes` more held by the frame's batches (each batch counted once, when it is filled).
  void AddBytes(std::size_t bytes) { bytes_ += bytes; }
  /// Renders every tile on the pool, then empties the frame. Throws std::bad_alloc when memory runs out.
  void Render(WorkerPool& pool, std::vector<TileScratch>& scratch);
  /// Forgets the recorded commands without rendering them.
  void Reset();
  /// Counts, while `counts` is not null, the primitives each tile renders into counts[tile], across frames; a
  /// frame of another grid than `grid` (columns, rows) starts them from zero.
  void CountTilePrimitives(std::vector<std::uint32_t>* counts, glm::ivec2* grid) {
    counts_ = counts;
    count_grid_ = grid;
  }
  /// Whether tiles drop triangles and regions by their coarse depth (HierarchicalDepth); on by default.
  void UseHierarchicalDepth(bool on) { hierarchical_depth_ = on; }

 private:
  void Begin(const RenderTarget& target);
  void RenderTile(int tile, TileScratch& scratch) const;
  void CloseShared();
  void List(int tile, std::uint32_t index);

  struct Command {
    bool draw;
    std::size_t index;  // into draws_ or clears_
  };
  RenderTarget target_;
  TileGrid grid_;
  std::vector<Command> commands_;
  std::vector<std::vector<std::uint32_t>> tile_commands_;  // per tile: the commands touching it, in order
  std::vector<DrawPacket> draws_;  // draws_used_ of them recorded, the others kept for reuse
  std::size_t draws_used_ = 0;
  static constexpr std::size_t kKeptDraws = 16384;  // packets kept from frame to frame, at most
  std::vector<std::unique_ptr<DrawTextures>> textures_;  // textures_used_ of them recorded, the others kept
  std::size_t textures_used_ = 0;
  std::vector<ClearPacket> clears_;
  std::vector<std::unique_ptr<BinnedBatch>> batches_;
  std::size_t batches_used_ = 0;
  std::vector<std::vector<float>> kept_vertices_;  // KeepVertices: kept_used_ of them held by this frame
  std::size_t kept_used_ = 0;
  // The open shared batch: its index in batches_, the last command that used it, and where the last draw's part
  // of it began.
  static constexpr std::uint32_t kNone = ~0u;
  static constexpr std::uint32_t kSharedPrimitives = 4096;  // a shared batch is closed once it holds this many
  std::uint32_t open_ = kNone;
  std::size_t open_command_ = 0;
  BinnedBatch::Mark open_mark_;
  std::size_t bytes_ = 0;
  std::unique_ptr<std::atomic<bool>[]> claimed_;  // Render's tiles taken, claimed_count_ of them
  int claimed_count_ = 0;
  std::vector<std::uint32_t>* counts_ = nullptr;  // CountTilePrimitives
  glm::ivec2* count_grid_ = nullptr;
  bool hierarchical_depth_ = true;
};

}  // namespace softgl::detail

// tile_renderer.cpp — plays recorded clears and draws, one tile per job.
#include "tile_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "rasterizer.h"
#include "simd.h"
#include "wide.h"

namespace softgl::detail {

namespace {
// The units that may have a texture bound in `t` (those past t.units are null).
int UnitsOf(const Textures& t) { return std::clamp(t.units, 0, kMaxTextureUnits); }
}  // namespace

bool DrawTextures::Any(const Textures& t) {
  std::uintptr_t any = 0;  // (no early exit: a loop the compiler vectorizes)
  const int units = UnitsOf(t);
  for (UnitViews kind : kKindUnits)
    for (int u = 0; u < units; ++u) any |= reinterpret_cast<std::uintptr_t>((t.*kind)[u]);
  return any != 0;
}

bool DrawTextures::Same(const Textures& t) const {
  const auto same = [](const TextureView* a, const TextureView* b) { return a ? b && *a == *b : !b; };
  const int units = std::max(UnitsOf(textures), UnitsOf(t));  // (past its own count, each is null)
  for (UnitViews kind : kKindUnits)
    for (int u = 0; u < units; ++u)
      if (!same((textures.*kind)[u], (t.*kind)[u])) return false;
  return true;
}

void DrawTextures::CopyFrom(const Textures& t) {
  const int units = UnitsOf(t), before = UnitsOf(textures);
  for (int k = 0; k < kTextureKinds; ++k)  // only the views of the units in use: the others are never read
    for (int u = 0; u < std::max(units, before); ++u) {
      const TextureView* v = u < units ? (t.*kKindUnits[k])[u] : nullptr;
      (textures.*kKindUnits[k])[u] = v ? &(views[k][u] = *v) : nullptr;
    }
  textures.units = units;
}

bool SameBuffers(const RenderTarget& a, const RenderTarget& b) {
  if (std::memcmp(&a, &b, sizeof a) == 0) return true;  // (a copy of the other: the common case, one compare)
  if (a.width != b.width || a.height != b.height || a.samples != b.samples || a.depth != b.depth || a.depth_pitch != b.depth_pitch ||
      a.stencil != b.stencil || a.stencil_pitch != b.stencil_pitch || a.depth16 != b.depth16 || a.tiles != b.tiles)
    return false;
  for (int i = 0; i < kMaxColorOutputs; ++i) {
    const ColorBuffer &x = a.color[i], &y = b.color[i];
    if (x.data != y.data) return false;
    if (x.data == nullptr) continue;  // (nothing reads the rest of an absent buffer)
    if (x.layout != y.layout || x.rgb_only != y.rgb_only || x.srgb != y.srgb || x.pitch != y.pitch) return false;
  }
  return true;
}

namespace {

Rect Intersect(const Rect& a, const Rect& b) {
  return Rect{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The depth of each sample of a batch's lanes: the pixel centre's plus the change of the triangle's depth plane from
// the centre to the sample (a line's or point's fragments have one depth; with MULTISAMPLE disabled, `at_samples`
// false, every sample takes the centre's); in element order into an interleaved target, where the vector operations
// compute the same depths themselves (ElementDepths in fragment_ops.cpp), so that only a batch with some block off
// their path needs them (`fill`).
template <int S>
void FillSampleDepths(const BlockBuffer& blocks, bool at_samples, bool interleaved, SampleDepths& depths) {
  using F4 = V<4>::F;
  for (int b = 0; b < blocks.count; ++b) {
    for (int q = 0; q < 4; ++q) {
      const TrianglePlanes* p = blocks.quad_planes[b][q];
      const F4 centre = LoadVec<F4>(&blocks.frag_coord[b][2][4 * q]);
      float delta[S] = {};
      if (p && at_samples && ((blocks.live[b] >> (4 * q)) & 0xFu))
        for (int s = 0; s < S; ++s) delta[s] = p->sample_dz[s];
      if (!interleaved) {
        for (int s = 0; s < S; ++s) StoreVec(&depths.z[b][s][4 * q], centre + delta[s]);
        continue;
      }
      float* ze = &depths.ze[b][4 * q * S];  // the quad's lanes, each with its S samples
      if constexpr (S == 2) {
        const F4 d{delta[0], delta[1], delta[0], delta[1]};
        StoreVec(ze, __builtin_shufflevector(centre, centre, 0, 0, 1, 1) + d);
        StoreVec(ze + 4, __builtin_shufflevector(centre, centre, 2, 2, 3, 3) + d);
      } else {
        for (int g = 0; g < S / 4; ++g) {
          const F4 d = LoadVec<F4>(delta + 4 * g);
          for (int k = 0; k < 4; ++k) StoreVec(ze + k * S + 4 * g, (F4{} + centre[k]) + d);
        }
      }
    }
  }
}
void FillSampleDepths(const BlockBuffer& blocks, int samples, bool at_samples, bool interleaved, bool fill,
                      SampleDepths& depths) {
  depths.interleaved = interleaved;
  depths.at_samples = at_samples;
  depths.samples = samples;
  depths.filled = fill;
  if (!fill) return;
  switch (samples) {
    case 2: return FillSampleDepths<2>(blocks, at_samples, interleaved, depths);
    case 4: return FillSampleDepths<4>(blocks, at_samples, interleaved, depths);
    default: return FillSampleDepths<8>(blocks, at_samples, interleaved, depths);
  }
}

// The fragment shader, then the per-fragment operations, on a full batch of blocks.
struct FragmentStage {
  const DrawPacket* draw;
  const RenderTarget* target;
  int outputs;  // colour outputs the target keeps
  int simd;
  const FragmentOpsPlan* plan;
  bool has_centroid;  // the draw has Centroid<> varyings

  static void Run(void* user, BlockBuffer& blocks) {
    const auto* self = static_cast<const FragmentStage*>(user);
    if (self->target->samples > 1) return self->RunSamples(blocks);
    if (self->draw->early_depth && !EarlyDepthTest(self->draw->ops, blocks, *self->target)) return;
    InterpolateVaryings(blocks);
    self->Shade(blocks);
    ApplyFragmentOps(self->draw->ops, *self->plan, blocks, self->draw->shader_depth, *self->target);
  }

  // Into a multisampled target: the depth test (early and late) and the operations after the shader run on each
  // sample a lane covers, in that sample's plane, with the depth interpolated at its position; the shader runs once
  // per pixel.
  void RunSamples(BlockBuffer& blocks) const {
    const int samples = target->samples;
    const FragmentOpsState& ops = draw->ops;
    SampleDepths depths;
    // Into the context's framebuffer (interleaved), every block of an even-sized RGBA8 target takes the vector
    // operations, which compute the depths themselves.
    const bool vector_only = target->interleaved && plan->wide_target && ((target->width | target->height) & 1) == 0;
    FillSampleDepths(blocks, samples, ops.multisample.multisample, target->interleaved, !vector_only, depths);
    // Centroid varyings: each lane's first covered sample where the rasterizer did not cover them all.
    std::int8_t centroid[BlockBuffer::kCapacity][kLanes];
    if (has_centroid && ops.multisample.multisample) {
      const std::uint32_t all = (std::uint32_t(1) << samples) - 1;
      for (int b = 0; b < blocks.count; ++b)
        for (int lane = 0; lane < kLanes; ++lane) {
          std::uint32_t covered = 0;
          for (int s = 0; s < samples; ++s) covered |= ((blocks.sample_live[b][s] >> lane) & 1u) << s;
          centroid[b][lane] = std::int8_t(covered == all || covered == 0 ? -1 : __builtin_ctz(covered));
        }
    }
    if (draw->early_depth && !EarlyDepthTestSamples(ops, blocks, *target, depths)) return;
    const MultisampleState& ms = ops.multisample;
    if (ms.multisample && ms.sample_shading && std::ceil(ms.min_sample_shading * float(samples)) > 1.0f)
      return ShadeEachSample(blocks, depths);
    InterpolateVaryings(blocks);
    if (has_centroid && ops.multisample.multisample) InterpolateCentroids(blocks, centroid, draw->interpolation);
    Shade(blocks);
    CoverageOps(blocks);
    ApplyFragmentOpsSamples(ops, *plan, blocks, draw->shader_depth, *target, depths);
  }

  // Sample shading (MinSampleShading): the shader once for each sample, its inputs interpolated there, its colour
  // through the operations of that sample alone.
  void ShadeEachSample(BlockBuffer& blocks, const SampleDepths& depths) const {
    const int samples = target->samples;
    std::uint32_t live[BlockBuffer::kCapacity], sample_live[BlockBuffer::kCapacity][kMaxSamples];
    for (int b = 0; b < blocks.count; ++b) {
      live[b] = blocks.live[b];
      for (int s = 0; s < samples; ++s) sample_live[b][s] = blocks.sample_live[b][s];
    }
    for (int s = 0; s < samples; ++s) {
      std::uint32_t any = 0;
      for (int b = 0; b < blocks.count; ++b) {
        blocks.live[b] = live[b] & sample_live[b][s];
        for (int t = 0; t < samples; ++t) blocks.sample_live[b][t] = t == s ? blocks.live[b] : 0u;
        any |= blocks.live[b];
      }
      if (!any) continue;
      InterpolateAtSample(blocks, s);
      Shade(blocks);
      CoverageOps(blocks);
      ApplyFragmentOpsSamples(draw->ops, *plan, blocks, draw->shader_depth, *target, depths);
    }
  }

  // SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_COVERAGE and SAMPLE_MASK narrow each lane's samples, and SAMPLE_ALPHA_TO_ONE
  // then sets every output's alpha to 1 (while MULTISAMPLE is enabled: section 17.3.1).
  void CoverageOps(BlockBuffer& blocks) const {
    const int samples = target->samples;
    const MultisampleState& ms = draw->ops.multisample;
    std::uint32_t keep = (std::uint32_t(1) << samples) - 1;
    if (ms.multisample && ms.sample_coverage) keep &= CoverageMask(ms, samples);
    if (ms.multisample && ms.sample_mask) keep &= ms.mask;
    const bool narrows = ms.multisample && (keep != (std::uint32_t(1) << samples) - 1 || ms.alpha_to_coverage);
    for (int b = 0; b < blocks.count && narrows; ++b) {
      for (int s = 0; s < samples; ++s)
        if (!((keep >> s) & 1u)) blocks.sample_live[b][s] = 0;
      if (!ms.alpha_to_coverage) continue;
      const float* alpha = blocks.Color(b, 0, 3);
      for (int lane = 0; lane < kLanes; ++lane) {
        if (!((blocks.live[b] >> lane) & 1u)) continue;
        const std::uint32_t m = AlphaToCoverageMask(alpha[lane], samples);
        for (int s = 0; s < samples; ++s)
          if (!((m >> s) & 1u)) blocks.sample_live[b][s] &= ~(1u << lane);
      }
    }
    if (ms.multisample && ms.alpha_to_one)  // (after alpha to coverage has read the alpha)
      for (int b = 0; b < blocks.count; ++b)
        for (int o = 0; o < outputs; ++o) blocks.out[b].color[o].w = Float(1.0f);
  }

  // gl_PointCoord of every lane of a buffer of points, from its gl_FragCoord and its quad's point.
  static void PointCoords(BlockBuffer& blocks) {
    for (int b = 0; b < blocks.count; ++b)
      for (int lane = 0; lane < kLanes; ++lane) {
        const PointSprite& p = blocks.quad_point[b][lane >> 2];
        blocks.point_coord[b][0][lane] = 0.5f + (blocks.frag_coord[b][0][lane] - p.cx) * p.inv_size;
        blocks.point_coord[b][1][lane] = 0.5f + p.t_sign * (blocks.frag_coord[b][1][lane] - p.cy) * p.inv_size;
      }
  }

  void Shade(BlockBuffer& blocks) const {
    const FragmentStage* self = this;
    BlockBatch batch;
    batch.count = blocks.count;
    batch.outputs = self->outputs;
    batch.front_facing = blocks.front_facing;
    batch.simd = self->simd;
    batch.varyings = blocks.varyings;
    batch.frag_coord = &blocks.frag_coord[0][0][0];
    if (blocks.points) {
      PointCoords(blocks);
      batch.point_coord = &blocks.point_coord[0][0][0];
    }
    batch.live = blocks.live;
    batch.out = blocks.out;
    batch.textures = self->draw->textures;
    self->draw->program->ShadeBlocks(batch);
  }
};

// Whether draws a and b render their fragments with the same state: the same shader object (a copy used
// again), textures, operations and bounds. Their primitives can then be rendered as one draw's.
bool SameState(const DrawPacket& a, const DrawPacket& b) {
  return a.program == b.program && a.textures == b.textures && a.ops == b.ops && a.bounds.x0 == b.bounds.x0 &&
         a.bounds.y0 == b.bounds.y0 && a.bounds.x1 == b.bounds.x1 && a.bounds.y1 == b.bounds.y1 &&
         a.nvar == b.nvar && a.interpolation == b.interpolation && a.shader_depth == b.shader_depth &&
         a.early_depth == b.early_depth && a.point_lower_left == b.point_lower_left && a.line_width == b.line_width;
}

}  // namespace

bool Frame::Accepts(const RenderTarget& target) const { return Empty() || SameBuffers(target, target_); }

void Frame::Begin(const RenderTarget& target) {
  if (!Empty()) return;
  target_ = target;
  grid_ = TileGrid::For(target.width, target.height);
  if (tile_commands_.size() < std::size_t(grid_.Count())) tile_commands_.resize(std::size_t(grid_.Count()));
}

void Frame::AddClear(const RenderTarget& target, const ClearPacket& clear) {
  Begin(target);
  clears_.push_back(clear);
  commands_.push_back(Command{false, clears_.size() - 1});
  const auto index = std::uint32_t(commands_.size() - 1);
  for (int t = 0; t < grid_.Count(); ++t)
    if (!Intersect(clear.area, grid_.TileRect(t)).Empty()) List(t, index);
}

void Frame::List(int tile, std::uint32_t index) {
  std::vector<std::uint32_t>& list = tile_commands_[std::size_t(tile)];
  if (!list.empty() && list.back() == index) return;
  list.push_back(index);
  bytes_ += sizeof(index);
}

void Frame::ListLastDraw() {
  const DrawPacket& draw = draws_[draws_used_ - 1];
  const auto index = std::uint32_t(commands_.size() - 1);
  if (draw.shared) {  // the tiles its own primitives were noted in
    batches_[draw.first_batch]->TilesSince(open_mark_, grid_, [&](int t) { List(t, index); });
    return;
  }
  Rect box;  // the union of the batches' boxes: only the tiles under it can have anything
  for (std::uint32_t k = 0; k < draw.batch_count; ++k) {
    const Rect& r = batches_[draw.first_batch + k]->Box();
    if (r.Empty()) continue;
    box = box.Empty() ? r : Rect{std::min(box.x0, r.x0), std::min(box.y0, r.y0), std::max(box.x1, r.x1),
                                 std::max(box.y1, r.y1)};
  }
  if (box.Empty()) return;
  const int tx0 = box.x0 / kTileSize, tx1 = (box.x1 - 1) / kTileSize;
  const int ty0 = box.y0 / kTileSize, ty1 = (box.y1 - 1) / kTileSize;
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) {
      const int t = ty * grid_.cols + tx;
      const Rect rect = grid_.TileRect(t);
      for (std::uint32_t k = 0; k < draw.batch_count; ++k)
        if (batches_[draw.first_batch + k]->Touches(t, rect)) {
          List(t, index);
          break;
        }
    }
}

DrawPacket& Frame::AddDraw(const RenderTarget& target, const DrawPacket& proto) {
  Begin(target);
  if (draws_used_ == draws_.size()) draws_.emplace_back();
  DrawPacket& packet = draws_[draws_used_++];
  packet = proto;
  packet.shared = false;
  packet.first_batch = packet.batch_count = 0;
  packet.prim_lo = packet.prim_hi = 0;
  // The textures: none, the same as the draw before, or a copy of the bound units' views.
  static const Textures kNoTextures;
  if (!proto.textures || !DrawTextures::Any(*proto.textures)) {
    packet.textures = &kNoTextures;
  } else if (textures_used_ > 0 && textures_[textures_used_ - 1]->Same(*proto.textures)) {
    packet.textures = &textures_[textures_used_ - 1]->textures;
  } else {
    if (textures_used_ == textures_.size()) textures_.push_back(std::make_unique<DrawTextures>());
    DrawTextures& copy = *textures_[textures_used_++];
    copy.CopyFrom(*proto.textures);
    packet.textures = &copy.textures;
    bytes_ += sizeof(DrawTextures);
  }
  bytes_ += sizeof(DrawPacket);
  commands_.push_back(Command{true, draws_used_ - 1});
  return packet;
}

void Frame::NewBatches(int count, int nvar) {
  DrawPacket& draw = draws_[draws_used_ - 1];
  draw.first_batch = std::uint32_t(batches_used_);
  draw.batch_count = std::uint32_t(count);
  for (int k = 0; k < count; ++k) {
    if (batches_used_ == batches_.size()) batches_.push_back(std::make_unique<BinnedBatch>());
    batches_[batches_used_++]->Reset(nvar);
  }
}

BinnedBatch& Frame::SharedBatch(int nvar) {
  DrawPacket& draw = draws_[draws_used_ - 1];
  const std::size_t command = commands_.size() - 1;
  // Draws share a batch only as consecutive commands: a tile walks it once, from draw to draw.
  if (open_ != kNone && (open_command_ + 1 != command || batches_[open_]->Nvar() != nvar ||
                         batches_[open_]->Position().primitives >= kSharedPrimitives))
    CloseShared();
  if (open_ != kNone && SameState(draws_[commands_[open_command_].index], draw)) {
    // The draw before takes this draw's primitives as its own, and this draw's record goes: the two render as
    // one draw of both primitive sequences, in order, which is what they are.
    draw.snapshot.reset();
    for (auto& o : draw.occlusion) o.reset();
    --draws_used_;
    commands_.pop_back();
    bytes_ -= sizeof(DrawPacket);
    BinnedBatch& batch = *batches_[open_];
    open_mark_ = batch.Position();
    return batch;
  }
  if (open_ == kNone) {
    NewBatches(1, nvar);
    open_ = draw.first_batch;
  }
  BinnedBatch& batch = *batches_[open_];
  open_command_ = command;
  open_mark_ = batch.Position();
  draw.shared = true;
  draw.first_batch = open_;
  draw.batch_count = 1;
  draw.prim_lo = open_mark_.primitives;
  return batch;
}

void Frame::EndShared() {
  DrawPacket& draw = draws_[draws_used_ - 1];
  draw.prim_hi = batches_[open_]->Position().primitives;
}

void Frame::CloseShared() {
  if (open_ == kNone) return;
  BinnedBatch& batch = *batches_[open_];
  batch.Finish(grid_);
  bytes_ += batch.Bytes();
  open_ = kNone;
}

void Frame::Reset() {
  commands_.clear();
  for (auto& list : tile_commands_) list.clear();
  // Keep the packets for the next frame, but not what they refer to: the shader copies and query counters go now.
  for (std::size_t i = 0; i < draws_used_; ++i) {
    DrawPacket& d = draws_[i];
    d.snapshot.reset();
    d.program = nullptr;
    for (auto& o : d.occlusion) o.reset();
  }
  draws_used_ = 0;
  if (draws_.size() > kKeptDraws) {
    draws_.resize(kKeptDraws);
    draws_.shrink_to_fit();
  }
  textures_used_ = 0;
  if (textures_.size() > kKeptDraws) textures_.resize(kKeptDraws);
  clears_.clear();
  // Keep the batches' memory for the next frame, but not an unusually large amount of it.
  for (std::size_t i = 0; i < batches_.size(); ++i) {
    batches_[i]->Reset(0);
    if (batches_[i]->Bytes() > (std::size_t(8) << 20)) batches_[i] = std::make_unique<BinnedBatch>();
  }
  batches_used_ = 0;
  for (std::vector<float>& kept : kept_vertices_)
    if (kept.capacity() * sizeof(float) > (std::size_t(8) << 20)) std::vector<float>().swap(kept);
  kept_used_ = 0;
  open_ = kNone;
  bytes_ = 0;
}

void Frame::KeepVertices(std::vector<float>& vertices) {
  if (kept_used_ == kept_vertices_.size()) kept_vertices_.emplace_back();
  std::vector<float>& kept = kept_vertices_[kept_used_++];
  kept.swap(vertices);
  bytes_ += kept.capacity() * sizeof(float);
}

static_assert(SampleTiles::kSize == kTileSize, "SampleTiles follows the tile renderer's grid");

void Frame::RenderTile(int tile, TileScratch& scratch) const {
  const Rect rect = grid_.TileRect(tile);
  BlockBuffer& blocks = *scratch.blocks;
  int outputs = 1;
  for (int o = 0; o < kMaxColorOutputs; ++o)
    if (target_.color[o].Present()) outputs = o + 1;
  const int simd = int(CpuSimdLevel());
  WindowVertex v[3];
  // Filled triangles wait here to be set up many at a time (RasterizeTriangles), in their order; any other
  // primitive and the end of the draw let them go first.
  TriangleQueue queue;
  FragmentOpsPlan plan;  // for the operations at `planned`
  const FragmentOpsState* planned = nullptr;
  const BinnedBatch* shared = nullptr;  // the shared batch `cursor` walks
  BinnedBatch::Cursor cursor;
  const std::vector<std::uint32_t>& list = tile_commands_[std::size_t(tile)];
  if (list.empty()) return;
  // The context's multisampled framebuffer: whole-tile clears deferred, stored when a primitive first reaches
  // the tile; the tile's colour resolved at the end (SampleTiles).
  SampleTiles* const lazy = target_.tiles;
  SampleTiles::Tile* const lazy_tile = lazy ? &lazy->tiles[std::size_t(tile)] : nullptr;
  if (lazy) lazy_tile->stale = kAllBuffers;
  // The coarse depth of the tile, read from its depth buffer as triangles ask.
  HierarchicalDepth* const hz = hierarchical_depth_ && target_.HasDepth() ? &scratch.depth_bounds : nullptr;
  if (hz) hz->Begin(target_, rect);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Command& c = commands_[list[i]];
    if (i + 2 < list.size()) {  // a tile's draws lie apart in draws_: fetch the next one's record early
      const Command& next = commands_[list[i + 2]];
      if (next.draw) {
        const char* at = reinterpret_cast<const char*>(&draws_[next.index]);
        for (std::size_t b = 0; b < sizeof(DrawPacket); b += 64) __builtin_prefetch(at + b);
      }
    }
    if (!c.draw) {
      const ClearPacket& clear = clears_[c.index];
      const Rect r = Intersect(clear.area, rect);
      if (r.Empty()) continue;
      bool color = clear.color, depth = clear.depth, stencil = clear.stencil;
      if (lazy) {
        if (r.x0 == rect.x0 && r.y0 == rect.y0 && r.x1 == rect.x1 && r.y1 == rect.y1) {  // the whole tile
          const bool* m = clear.color_mask;
          if (color && m[0] && m[1] && m[2] && m[3] && (clear.color_buffers & 1u)) {  // (its one colour buffer)
            lazy->NoteColor(target_, tile, clear.color_value);
            color = false;
          }
          if (depth) lazy->NoteDepth(tile, clear.depth_value);
          if (stencil && clear.stencil_mask == 0xFF) {
            lazy->NoteStencil(tile, clear.stencil_value);
            stencil = false;
          }
          depth = false;
        }
        // A clear of part of the tile, or through a mask, changes what a deferred clear left.
        lazy->Store(target_, tile, (color ? kColorBit : 0u) | (depth ? kDepthBit : 0u) | (stencil ? kStencilBit : 0u));
      }
      if (color) target_.ClearColor(r, clear.color_value, clear.color_mask, clear.color_buffers);
      if (depth) target_.ClearDepth(r, clear.depth_value);
      if (clear.depth && hz) {  // (also where the tile only noted it: Store takes it first)
        if (r.x0 == rect.x0 && r.y0 == rect.y0 && r.x1 == rect.x1 && r.y1 == rect.y1)
          hz->Cleared(target_.StoredDepth(clear.depth_value));
        else
          hz->TouchAll();
      }
      if (stencil) target_.ClearStencil(r, clear.stencil_value, clear.stencil_mask);
      continue;
    }
    const DrawPacket& draw = draws_[c.index];
    RasterTarget rt;
    rt.bounds = Intersect(draw.bounds, rect);
    rt.nvar = draw.nvar;
    rt.interpolation = draw.interpolation;
    rt.samples = target_.samples > 1 && draw.ops.multisample.multisample ? target_.samples : 1;
    rt.point_lower_left = draw.point_lower_left;
    rt.line_width = draw.line_width;
    if (rt.bounds.Empty()) continue;
    // The depth test is the early one: triangles and regions that cannot pass it may go.
    if (hz && draw.early_depth) {
      hz->func = draw.ops.depth_func;
      rt.depth_bounds = hz;
    }
    if (!planned || !(draw.ops == *planned)) {  // consecutive draws mostly share their operations
      plan = PlanFragmentOps(draw.ops, target_);
      planned = &draw.ops;
    }
    bool has_centroid = false;
    for (int i = 0; draw.interpolation && i < draw.nvar; ++i)
      has_centroid = has_centroid || draw.interpolation[i] == Interpolation::kCentroid;
    FragmentStage stage{&draw, &target_, outputs, simd, &plan, has_centroid};
    const BlockSink sink{&FragmentStage::Run, &stage};
    blocks.count = 0;
    blocks.samples = target_.samples;
    const auto rasterize = [&](const BinnedBatch& batch) {
      return [&](const BinnedPrimitive& p, const VertexRuns& vertices) {
        if (counts_) ++(*counts_)[std::size_t(tile)];  // (each tile is rendered by one thread)
        if (lazy && lazy_tile->cleared) lazy->Store(target_, tile, kAllBuffers);  // the first primitive here
        if (p.kind == PrimitiveKind::kTriangle) {  // read in place
          if (queue.Add(BinnedBatch::View(vertices, 0), BinnedBatch::View(vertices, 1), BinnedBatch::View(vertices, 2),
                        p.depth_offset, p.front_facing))
            RasterizeTriangles(queue, rt, blocks, sink);
          return;
        }
        RasterizeTriangles(queue, rt, blocks, sink);
        rt.depth_offset = p.depth_offset;
        for (int k = 0; k < int(p.kind); ++k) batch.Vertex(vertices, k, v[k]);
        if (p.kind == PrimitiveKind::kLine)
          RasterizeLine(v[0], v[1], p.front_facing, rt, blocks, sink);
        else
          RasterizePoint(v[0], p.point_size, p.front_facing, rt, blocks, sink);
      };
    };
    if (draw.shared) {  // its part of a batch shared with the draws before it, walked on from where they left it
      const BinnedBatch& batch = *batches_[draw.first_batch];
      if (&batch != shared) {
        shared = &batch;
        cursor = BinnedBatch::Cursor{};
      }
      batch.ForEachInTile(tile, rect, cursor, draw.prim_lo, draw.prim_hi, rasterize(batch));
    } else {
      const auto* own = &batches_[draw.first_batch];
      const std::uint32_t n = draw.batch_count;
      for (std::uint32_t k = 0; k < n; ++k) {
        for (std::uint32_t stage = 0; stage < 3; ++stage)  // the batches ahead, nearer ones further along
          if (k + 3 - stage < n) own[k + 3 - stage]->Prefetch(int(stage), tile);
        const BinnedBatch& batch = *own[k];
        batch.ForEachInTile(tile, rect, rasterize(batch));
      }
    }
    RasterizeTriangles(queue, rt, blocks, sink);
    sink.Flush(blocks);
    if (hz && draw.ops.depth_test && draw.ops.depth_write) hz->Wrote(draw.ops.depth_func);
  }
  if (lazy) lazy->Resolve(target_, tile, kColorBit);  // while the tile's samples are in cache
}

void Frame::Render(WorkerPool& pool, std::vector<TileScratch>& scratch) {
  if (Empty()) return;
  if (scratch.size() < std::size_t(pool.Threads())) scratch.resize(std::size_t(pool.Threads()));
  try {
    CloseShared();
    // Each thread renders a band of tiles of its own first, the same band from frame to frame (so that a tile's
    // pixels tend to be in the cache of the thread that rendered them last), then takes what is left of the
    // others' bands from their far ends. A tile is claimed once, by whichever thread gets to it first.
    const int tiles = grid_.Count(), threads = pool.Threads();
    if (claimed_count_ < tiles) {
      claimed_ = std::make_unique<std::atomic<bool>[]>(std::size_t(tiles));
      claimed_count_ = tiles;
    }
    for (int t = 0; t < tiles; ++t) claimed_[std::size_t(t)].store(false, std::memory_order_relaxed);
    if (counts_ && (count_grid_->x != grid_.cols || count_grid_->y != grid_.rows)) {
      counts_->assign(std::size_t(tiles), 0u);
      *count_grid_ = {grid_.cols, grid_.rows};
    }
    pool.Run(threads, [&](int, int worker) {
      auto take = [&](int t) {
        if (!claimed_[std::size_t(t)].exchange(true, std::memory_order_relaxed))
          RenderTile(t, scratch[std::size_t(worker)]);
      };
      const int begin = int(std::int64_t(tiles) * worker / threads);
      const int end = int(std::int64_t(tiles) * (worker + 1) / threads);
      for (int t = begin; t < end; ++t) take(t);
      for (int t = tiles - 1; t >= 0; --t) take(t);
    });
  } catch (...) {
    Reset();
    throw;
  }
  Reset();
}

}  // namespace softgl::detail

// pipeline.cpp — drives one draw through the stages.
#include "pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "clipper.h"
#include "culling.h"
#include "rasterizer.h"

namespace softgl::detail {

namespace {

constexpr int kVertexBatch = 64;

// Stage 1-2: fetch and shade every vertex the draw references, once each where indices repeat.
void ShadeVertices(const DrawCall& call, const FetchPlan& fetch, const Program& program, const Textures* textures,
                   Scratch& s) {
  const int count = call.count;
  auto& to_shade = s.shade_indices;
  auto& map = s.element_to_shaded;
  to_shade.clear();
  map.resize(std::size_t(count));
  if (call.elements == nullptr) {
    to_shade.resize(std::size_t(count));
    for (int i = 0; i < count; ++i) {
      to_shade[i] = call.first + std::uint32_t(i);
      map[i] = std::uint32_t(i);
    }
  } else {
    const auto [lo, hi] = std::minmax_element(call.elements, call.elements + count);
    const std::uint64_t range = std::uint64_t(*hi) - *lo + 1;
    if (range <= std::uint64_t(count) * 2 + 64) {  // dense indices: shade the range once
      to_shade.resize(std::size_t(range));
      for (std::uint64_t i = 0; i < range; ++i) to_shade[i] = *lo + std::uint32_t(i);
      for (int i = 0; i < count; ++i) map[i] = call.elements[i] - *lo;
    } else {  // sparse indices: shade per element
      to_shade.assign(call.elements, call.elements + count);
      for (int i = 0; i < count; ++i) map[i] = std::uint32_t(i);
    }
  }

  const int n = int(to_shade.size());
  ShadedVertices& out = s.shaded;
  out.count = n;
  out.nvar = program.VaryingFloats();
  out.position.resize(std::size_t(n));
  out.point_size.resize(std::size_t(n));
  out.varyings.resize(std::size_t(n) * std::size_t(out.nvar));
  s.attribs.resize(std::size_t(kVertexBatch) * kMaxVertexAttribs);
  s.vertex_ids.resize(kVertexBatch);
  for (int base = 0; base < n; base += kVertexBatch) {
    const int m = std::min(kVertexBatch, n - base);
    FetchVertices(fetch, to_shade.data() + base, m, s.attribs.data());
    for (int i = 0; i < m; ++i) s.vertex_ids[i] = int(to_shade[base + i]);
    VertexBatch batch;
    batch.count = m;
    batch.attribs = s.attribs.data();
    batch.vertex_ids = s.vertex_ids.data();
    batch.positions = out.position.data() + base;
    batch.point_sizes = out.point_size.data() + base;
    batch.varyings = out.varyings.data() + std::size_t(base) * out.nvar;
    batch.textures = textures;
    program.ShadeVertices(batch);
  }
}

void ToClipVertex(const ShadedVertices& sv, std::uint32_t i, ClipVertex& out) {
  out.pos = sv.position[i];
  if (sv.nvar > 0) std::memcpy(out.var, sv.Varyings(int(i)), sizeof(float) * std::size_t(sv.nvar));
}

struct FragmentStage {
  const Program* program;
  const FragmentOpsState* ops;
  const RenderTarget* target;
  const Textures* textures;

  // Stages 8-9 on a full batch of quads: the fragment shader, then the per-fragment operations.
  static void Run(void* user, QuadBuffer& quads) {
    auto* self = static_cast<FragmentStage*>(user);
    QuadBatch batch;
    batch.count = quads.count;
    batch.varyings = quads.varyings;
    batch.frag_coord = quads.frag_coord;
    batch.front_facing = quads.front_facing;
    batch.out = quads.out;
    batch.live = quads.live;
    batch.textures = self->textures;
    self->program->ShadeQuads(batch);
    ApplyFragmentOps(*self->ops, quads, *self->target);
  }
};

class PrimitiveRunner {
 public:
  PrimitiveRunner(const DrawState& state, const ShadedVertices& sv, QuadBuffer& quads, const QuadSink& sink)
      : state_(state), sv_(sv), quads_(quads), sink_(sink), planes_(GuardBandPlanes(state.viewport)) {
    target_.bounds = state.bounds;
    target_.nvar = sv.nvar;
  }

  void Point(std::uint32_t i) {
    ToClipVertex(sv_, i, clip_[0]);
    // A point is kept only when its centre lies inside the view volume itself (OpenGL 4.6, section 13.7.1).
    if (ClipCodes(clip_[0].pos, ClipPlanes{}) != 0) return;
    ToWindow(clip_[0], sv_.nvar, state_.viewport, win_[0]);
    RasterizePoint(win_[0], PointSizeOf(i), true, target_, quads_, sink_);
  }

  void Line(std::uint32_t i0, std::uint32_t i1, bool front_facing = true) {
    ToClipVertex(sv_, i0, clip_[0]);
    ToClipVertex(sv_, i1, clip_[1]);
    if (!ClipLine(clip_[0], clip_[1], sv_.nvar, planes_, clip_[2], clip_[3])) return;
    ToWindow(clip_[2], sv_.nvar, state_.viewport, win_[0]);
    ToWindow(clip_[3], sv_.nvar, state_.viewport, win_[1]);
    RasterizeLine(win_[0], win_[1], front_facing, target_, quads_, sink_);
  }

  void Triangle(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
    ToClipVertex(sv_, i0, clip_[0]);
    ToClipVertex(sv_, i1, clip_[1]);
    ToClipVertex(sv_, i2, clip_[2]);
    ClipTriangle(clip_[0], clip_[1], clip_[2], sv_.nvar, planes_, poly_);
    if (poly_.count < 3) return;
    for (int k = 0; k < poly_.count; ++k) ToWindow(poly_.v[k], sv_.nvar, state_.viewport, win_[k]);
    const float area = SignedArea(win_, poly_.count);
    if (area == 0.0f) return;
    const bool front = IsFrontFacing(area, state_.primitive.front_face);
    if (state_.primitive.cull_enabled && IsCulled(front, state_.primitive.cull_face)) return;
    const bool offset = state_.primitive.polygon_mode == LINE    ? state_.primitive.offset_line
                        : state_.primitive.polygon_mode == POINT ? state_.primitive.offset_point
                                                       : state_.primitive.offset_fill;
    target_.depth_offset =
        offset ? PolygonOffset(win_[0], win_[1], win_[2], state_.primitive.offset_factor, state_.primitive.offset_units) : 0.0f;
    switch (state_.primitive.polygon_mode) {
      case LINE:  // the triangle's own edges, each clipped as a line
        Line(i0, i1, front);
        Line(i1, i2, front);
        Line(i2, i0, front);
        break;
      case POINT:
        for (std::uint32_t i : {i0, i1, i2}) {
          ToClipVertex(sv_, i, clip_[0]);
          if (ClipCodes(clip_[0].pos, ClipPlanes{}) != 0) continue;
          ToWindow(clip_[0], sv_.nvar, state_.viewport, win_[0]);
          RasterizePoint(win_[0], PointSizeOf(i), front, target_, quads_, sink_);
        }
        break;
      default:
        for (int k = 1; k + 1 < poly_.count; ++k)
          RasterizeTriangle(win_[0], win_[k], win_[k + 1], front, target_, quads_, sink_);
        break;
    }
    target_.depth_offset = 0.0f;
  }

 private:
  float PointSizeOf(std::uint32_t i) const {
    const float size = state_.primitive.program_point_size ? sv_.point_size[i] : state_.primitive.point_size;
    return std::isnan(size) ? 1.0f : std::clamp(size, 1.0f, kMaxPointSize);
  }

  const DrawState& state_;
  const ShadedVertices& sv_;
  QuadBuffer& quads_;
  const QuadSink& sink_;
  ClipPlanes planes_;
  RasterTarget target_;
  ClipVertex clip_[4];
  ClipPolygon poly_;
  WindowVertex win_[kMaxPolygonVertices];
};

}  // namespace

namespace {

// One draw small enough to hold all its shaded vertices at once.
void DrawChunk(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const RenderTarget& target,
               Scratch& scratch) {
  ShadeVertices(call, fetch, *state.program, state.textures, scratch);

  Primitives& prims = scratch.primitives;
  AssemblePrimitives(call.mode, call.count, prims);

  FragmentStage fragment{state.program, &state.ops, &target, state.textures};
  const QuadSink sink{&FragmentStage::Run, &fragment};
  QuadBuffer& quads = *scratch.quads;
  quads.count = 0;
  auto runner = std::make_unique<PrimitiveRunner>(state, scratch.shaded, quads, sink);
  const auto& map = scratch.element_to_shaded;
  const auto& idx = prims.indices;
  const std::size_t n = idx.size();
  switch (prims.vertices_per_primitive) {
    case 1:
      for (std::size_t i = 0; i < n; ++i) runner->Point(map[idx[i]]);
      break;
    case 2:
      for (std::size_t i = 0; i + 1 < n; i += 2) runner->Line(map[idx[i]], map[idx[i + 1]]);
      break;
    case 3:
      for (std::size_t i = 0; i + 2 < n; i += 3) runner->Triangle(map[idx[i]], map[idx[i + 1]], map[idx[i + 2]]);
      break;
    default: break;
  }
  sink.Flush(quads);
}

}  // namespace

void Draw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const RenderTarget& target,
          Scratch& scratch) {
  if (call.count <= 0 || state.program == nullptr || state.bounds.Empty()) return;
  if (call.count <= kDrawChunk) return DrawChunk(call, fetch, state, target, scratch);

  // A large draw goes through in pieces of at most kDrawChunk vertices, so that memory stays bounded whatever the
  // count. Each piece is an explicit element list of the draw's own vertex indices (gl_VertexID is kept); strips
  // overlap by the vertices their primitives share, with an even step so that strip triangles keep their winding;
  // fans repeat vertex 0; a loop's closing segment is drawn last as a line.
  auto element = [&](std::int64_t k) { return call.elements ? call.elements[k] : call.first + std::uint32_t(k); };
  const std::int64_t count = call.count;
  Enum piece_mode = call.mode;
  std::int64_t step = kDrawChunk, begin = 0;
  switch (call.mode) {
    case LINE_STRIP:
    case LINE_LOOP:
      piece_mode = LINE_STRIP;
      step = kDrawChunk - 1;
      break;
    case TRIANGLE_STRIP: step = kDrawChunk - 2; break;
    case TRIANGLE_FAN:
      step = kDrawChunk - 2;
      begin = 1;
      break;
    default: break;  // POINTS, LINES, TRIANGLES: kDrawChunk is a multiple of 6
  }
  std::vector<std::uint32_t> piece;
  piece.reserve(std::size_t(kDrawChunk));
  for (std::int64_t s = begin; s < count; s += step) {
    piece.clear();
    if (call.mode == TRIANGLE_FAN) piece.push_back(element(0));
    const std::int64_t room = kDrawChunk - std::int64_t(piece.size());
    for (std::int64_t k = s; k < std::min(count, s + room); ++k) piece.push_back(element(k));
    DrawCall sub;
    sub.mode = piece_mode;
    sub.count = int(piece.size());
    sub.elements = piece.data();
    DrawChunk(sub, fetch, state, target, scratch);
    if (s + room >= count) break;
  }
  if (call.mode == LINE_LOOP) {
    const std::uint32_t closing[2] = {element(count - 1), element(0)};
    DrawCall sub;
    sub.mode = LINES;
    sub.count = 2;
    sub.elements = closing;
    DrawChunk(sub, fetch, state, target, scratch);
  }
}

}  // namespace softgl::detail

// pipeline.cpp — drives one draw through the stages.
#include "pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "clipper.h"
#include "culling.h"
#include "geometry_stage.h"
#include "binner.h"
#include "rasterizer.h"  // PolygonOffset, TriangleCentreBox
#include "simd.h"
#include "wide.h"

namespace softgl::detail {

namespace {

constexpr int kVertexBatch = 64;
constexpr int kVertexJob = 16 * kVertexBatch;
constexpr std::size_t kBinJob = 1024;     // primitives clipped and binned per job, at least
constexpr std::size_t kBinJobMax = 4096;  // and at most

// Whether any of the program's `nvar` varyings is noperspective.
bool AnyNoPerspective(const Interpolation* interpolation, int nvar) {
  bool any = false;
  for (int k = 0; interpolation && k < nvar; ++k) any = any || interpolation[k] == Interpolation::kNoPerspective;
  return any;
}

// What the stages after the last one before rasterization need of vertices [base, base + m) of `out`: what
// transform feedback records (`record`), clip codes, and the window position of each vertex (the divide and
// viewport transform of ToWindow, done once per vertex rather than once per primitive using it), several vertices
// per instruction; the varyings divided by w for the vertices inside the guard band. Noperspective varyings are
// multiplied by the clip-space w here, so that clipping (linear in clip space) and the divide by w give each window
// vertex the varying's own value, which the rasterizer interpolates linearly.
// (Inlined into its callers: a draw of a few vertices pays for the call otherwise.)
[[gnu::always_inline]] inline void FinishVertices(ShadedVertices& out, int base, int m, const ClipPlanes& planes,
                                                  const ViewportTransform& viewport, const Interpolation* interpolation,
                                                  bool noperspective, const FeedbackLayout* record) {
  if (record)  // what transform feedback records, before anything below changes the varyings
    for (int i = base; i < base + m; ++i) {
      float* dst = out.feedback.data() + std::size_t(i) * std::size_t(record->floats);
      const float* var = out.varyings.data() + std::size_t(i) * out.nvar;
      for (const FeedbackLayout::Item& item : record->items) {
        const float* src = item.first < 0 ? &out.position[std::size_t(i)].x : var + item.first;
        std::memcpy(dst, src, sizeof(float) * std::size_t(item.components));
        dst += item.components;
      }
    }
  ClipCodesOfVertices(&out.position[std::size_t(base)], m, planes, &out.clip_codes[std::size_t(base)]);
  WindowPositions(&out.position[std::size_t(base)], m, viewport, &out.window[std::size_t(base)]);
  // (Everything read once into locals: the vector stores below may alias anything, and the compiler would read
  // the arrays' places again after each.)
  const int nvar = out.nvar;
  const std::size_t stride = std::size_t(out.WindowStride());
  const glm::vec4* const position = out.position.data();
  const glm::vec4* const window = out.window.data();
  const unsigned* const codes = out.clip_codes.data();
  float* const varyings = out.varyings.data();
  float* const runs = out.window_vertices.data();
  using F4 = V<4>::F;
  if (nvar == 0) {  // the runs are the window positions (those of vertices outside the guard band unread)
    std::memcpy(runs + std::size_t(base) * 4, window + base, sizeof(glm::vec4) * std::size_t(m));
    return;
  }
  for (int i = base; i < base + m; ++i) {
    float* v = varyings + std::size_t(i) * std::size_t(nvar);
    if (noperspective) {
      const float w = position[i].w;
      for (int k = 0; k < nvar; ++k)
        if (interpolation[k] == Interpolation::kNoPerspective) v[k] *= w;
    }
    if (codes[i] != 0) continue;
    const F4 win = LoadVec<F4>(&window[i]);
    const float oow = win[3];
    float* run = runs + std::size_t(i) * stride;
    StoreVec(run, win);
    // Four varyings to a vector, then the last one to three (a loop of the varyings' count, which is short, costs
    // more in its set-up than in its multiplications).
    int k = 0;
    for (; k + 4 <= nvar; k += 4) StoreVec(run + 4 + k, LoadVec<F4>(v + k) * oow);
    switch (nvar - k) {  // (not a loop: the compiler would vectorize it too, at a set-up's cost)
      case 3: run[6 + k] = v[k + 2] * oow; [[fallthrough]];
      case 2: run[5 + k] = v[k + 1] * oow; [[fallthrough]];
      case 1: run[4 + k] = v[k] * oow; break;
      default: break;
    }
  }
}

// The arrays FinishVertices fills, sized for out.count vertices.
[[gnu::always_inline]] inline void SizeFinished(ShadedVertices& out, const FeedbackLayout* record) {
  const std::size_t n = std::size_t(out.count);
  out.clip_codes.resize(n);
  out.window.resize(n);
  out.window_vertices.resize(n * std::size_t(out.WindowStride()));
  if (record) out.feedback.resize(n * std::size_t(record->floats));
}

// The vertices a draw references, each once where indices repeat: s.shade_indices[0 .. returned count) holds the
// vertex index of each vertex to shade (in the order of first use; for indices packed close together, the whole
// range between the lowest and the highest, in order), and s.element_to_shaded the slot of each of the call's
// elements.
int UniqueVertices(const DrawCall& call, Scratch& s) {
  const int count = call.count;
  auto& to_shade = s.shade_indices;
  auto& map = s.element_to_shaded;
  // Both only grow (growing fills with zeros, which every draw would otherwise pay for again).
  if (to_shade.size() < std::size_t(count)) to_shade.resize(std::size_t(count));
  if (map.size() < std::size_t(count)) map.resize(std::size_t(count));
  if (call.elements == nullptr) {
    for (int i = 0; i < count; ++i) {
      to_shade[i] = call.first + std::uint32_t(i);
      map[i] = std::uint32_t(i);
    }
    return count;
  }
  std::uint32_t lo = call.elements[0], hi = lo;  // values, not positions: a loop the compiler vectorizes
  for (int i = 1; i < count; ++i) {
    lo = std::min(lo, call.elements[i]);
    hi = std::max(hi, call.elements[i]);
  }
  const std::uint64_t range = std::uint64_t(hi) - lo + 1;
  if (range > std::max<std::uint64_t>(std::uint64_t(count) * 8, std::uint64_t(1) << 16)) {
    // Indices spread far apart: shaded per element.
    std::copy(call.elements, call.elements + count, to_shade.begin());
    for (int i = 0; i < count; ++i) map[i] = std::uint32_t(i);
    return count;
  }
  if (range * 3 <= std::uint64_t(count)) {
    // Indices packed close together, as a mesh's are (each vertex used by about six triangles): every vertex of
    // the range shaded, in index order, and an element's slot is its index less the lowest; two loops the compiler
    // vectorizes. The range's unused vertices (at most a third of the elements) cost less to shade than the table
    // below costs per element.
    for (std::uint32_t j = 0; j < std::uint32_t(range); ++j) to_shade[j] = lo + j;
    for (int i = 0; i < count; ++i) map[i] = call.elements[i] - lo;
    return int(range);
  }
  // Each distinct index shaded once, in the order of first use: a table over the index range gives each vertex
  // its slot (a large mesh drawn in pieces has indices spread over the whole mesh in every piece). The table holds
  // kUnseen between draws: only the entries a draw set are reset after it.
  constexpr std::uint32_t kUnseen = 0xFFFFFFFFu;
  auto& slot = s.first_use;
  if (slot.size() < range) slot.resize(std::size_t(range), kUnseen);
  std::uint32_t seen = 0;
  const std::uint32_t low = lo;
  std::uint32_t* shade = to_shade.data();
  for (int i = 0; i < count; ++i) {
    const std::uint32_t e = call.elements[i];
    std::uint32_t& k = slot[e - low];
    if (k == kUnseen) {
      k = seen;
      shade[seen++] = e;
    }
    map[i] = k;
  }
  for (std::uint32_t j = 0; j < seen; ++j) slot[shade[j] - low] = kUnseen;
  return int(seen);
}

// Stages 1-2 for vertices to_shade[0 .. m), m <= kVertexBatch, of `instance`: fetched into vs and shaded into
// out's arrays from `base` on (its layers too when `layers`).
[[gnu::always_inline]] inline void ShadeBatch(const FetchPlan& fetch, const Program& program, const Textures* textures,
                                              const std::uint32_t* to_shade, int m, std::uint32_t instance, int simd,
                                              bool layers, VertexScratch& vs, ShadedVertices& out, int base) {
  FetchVertices(fetch, to_shade, m, instance, vs.attribs.data(), kVertexBatch);
  for (int i = 0; i < m; ++i) vs.vertex_ids[i] = int(to_shade[i]);
  VertexBatch batch;
  batch.count = m;
  batch.attribs = vs.attribs.data();
  batch.stride = kVertexBatch;
  batch.enabled = fetch.enabled;
  batch.current = fetch.current;
  batch.simd = simd;
  batch.vertex_ids = vs.vertex_ids.data();
  batch.instance_id = int(instance);
  batch.positions = out.position.data() + base;
  batch.point_sizes = out.point_size.data() + base;
  batch.layers = layers ? out.layer.data() + base : nullptr;
  batch.varyings = out.varyings.data() + std::size_t(base) * out.nvar;
  batch.textures = textures;
  program.ShadeVertices(batch);
}

// A worker's vertex scratch, sized for ShadeBatch.
VertexScratch& VertexScratchOf(Scratch& s, int worker) {
  VertexScratch& vs = s.vertex[std::size_t(worker)];
  vs.attribs.resize(std::size_t(kVertexBatch) * kMaxVertexAttribs * 4);
  vs.vertex_ids.resize(kVertexBatch);
  return vs;
}

// Stage 1-2: fetch and shade every vertex the draw references, once each where indices repeat. With `geometry`
// (a geometry stage reads them), only shaded: nothing FinishVertices does.
void ShadeVertices(const DrawCall& call, const FetchPlan& fetch, const Program& program, const Textures* textures,
                   const Interpolation* interpolation, const ViewportTransform& viewport,
                   const FeedbackLayout* record, bool layers, bool geometry, WorkerPool& pool, Scratch& s) {
  const int unique = UniqueVertices(call, s);  // the vertices to shade: s.shade_indices[0 .. unique)
  const std::uint32_t* to_shade = s.shade_indices.data();

  // An instanced piece shades the vertices once per instance: shaded vertex j is vertex to_shade[j % unique] of
  // instance call.instance + j / unique.
  const int n = unique * call.instances;
  ShadedVertices& out = s.shaded;
  out.count = n;
  out.nvar = program.VertexVaryingFloats();
  out.position.resize(std::size_t(n));
  out.point_size.resize(std::size_t(n));
  out.varyings.resize(std::size_t(n) * std::size_t(out.nvar));
  if (!geometry) SizeFinished(out, record);
  if (layers) out.layer.resize(std::size_t(n));
  const ClipPlanes planes = GuardBandPlanes(viewport);
  if (s.vertex.size() < std::size_t(pool.Threads())) s.vertex.resize(std::size_t(pool.Threads()));
  const int simd = int(CpuSimdLevel());
  const bool noperspective = AnyNoPerspective(interpolation, out.nvar);
  // Jobs of kVertexJob vertices, shaded in batches of kVertexBatch; every vertex is written by one job only.
  const int jobs = (n + kVertexJob - 1) / kVertexJob;
  pool.Run(jobs, [&](int job, int worker) {
    VertexScratch& vs = VertexScratchOf(s, worker);
    const int end = std::min(n, (job + 1) * kVertexJob);
    for (int base = job * kVertexJob, m = 0; base < end; base += m) {
      // A batch never spans two instances.
      const int k0 = base % unique;
      m = std::min({kVertexBatch, end - base, unique - k0});
      const std::uint32_t instance = call.instance + std::uint32_t(base / unique);
      ShadeBatch(fetch, program, textures, to_shade + k0, m, instance, simd, layers, vs, out, base);
      if (!geometry) FinishVertices(out, base, m, planes, viewport, interpolation, noperspective, record);
    }
  });
}

void ToClipVertex(const ShadedVertices& sv, std::uint32_t i, ClipVertex& out) {
  out.pos = sv.position[i];
  if (sv.nvar > 0) std::memcpy(out.var, sv.Varyings(int(i)), sizeof(float) * std::size_t(sv.nvar));
}

class PrimitiveRunner {
 public:
  PrimitiveRunner(const DrawState& state, const ShadedVertices& sv, BinnedBatch& bins, const TileGrid& grid,
                  PrimitiveScratch& mem)
      : state_(state), sv_(sv), bins_(bins), grid_(grid), clip_(mem.clip), poly_(mem.poly), win_(mem.win),
        planes_(GuardBandPlanes(state.viewport)),
        cull_{state.primitive.cull_enabled, state.primitive.cull_face, state.primitive.front_face, state.bounds} {
    cull_.SetSamples(state.samples);
    for (int k = 0; state.interpolation && k < sv.nvar; ++k)
      if (state.interpolation[k] == Interpolation::kFlat) flat_[flat_count_++] = k;
    // gl_PrimitiveID, which the fragment stage reads from the last two varyings: each primitive's number, unless a
    // geometry stage wrote it into its vertices.
    ids_ = state.primitive_ids && state.geometry == nullptr;
  }

  // The number of the primitives that follow (gl_PrimitiveID), when the runner sets it.
  void SetPrimitiveId(std::uint32_t id) { id_ = id; }

  void Point(std::uint32_t i) { Point(i, i, true); }

  // The verdict on the filled triangles v[t] (vertices 0 to 2), t < n, that lie inside the guard band, many
  // triangles per instruction (JudgeTriangles): bit t of `nothing` for those that certainly draw nothing (culled,
  // of no area or covering no pixel centre); bit t of `known` for those whose facing and pixel box are decided
  // there, to be binned by Known(). Triangle() would decide each of them the same way; the others go through it.
  void Judge(const std::uint32_t (*v)[4], int n, GroupVerdict& verdict) const {
    verdict.nothing = verdict.known = 0;
    if (state_.primitive.polygon_mode != FILL) return;
    TriangleGroup group;
    group.count = n;
    std::uint32_t inside = 0;
    const unsigned* codes = sv_.clip_codes.data();
    for (int t = 0; t < n; ++t) {
      if ((codes[v[t][0]] | codes[v[t][1]] | codes[v[t][2]]) != 0) continue;
      inside |= 1u << t;
      for (int k = 0; k < 3; ++k) {
        const glm::vec4& w = sv_.window[v[t][k]];
        group.x[k][t] = w.x;
        group.y[k][t] = w.y;
      }
    }
    if (!inside) return;
    JudgeTriangles(group, cull_, verdict);
    verdict.nothing &= inside;
    verdict.known &= flat_count_ == 0 ? inside : 0u;  // flat varyings take Triangle()'s copy
  }

  // A filled triangle inside the guard band, without flat varyings, whose facing and TriangleCentreBox (not empty)
  // Judge() found.
  void Known(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2, bool front_facing, const Rect& box) {
    front_ = front_facing;
    BinTriangle(i0, i1, i2, box);
  }

  // Whether filled triangles that need no clipping are binned by their vertices' numbers in sv.window_vertices
  // (which the frame then keeps: BinnedBatch::AddIndexed), not with copies of them.
  void UseTable(bool on) { table_ = on; }

  // A line between shaded vertices i0 and i1 whose flat varyings come from vertex `provoking`.
  void Line(std::uint32_t i0, std::uint32_t i1, std::uint32_t provoking, bool front_facing = true) {
    ToClipVertex(sv_, i0, clip_[0]);
    ToClipVertex(sv_, i1, clip_[1]);
    // Multisampled, a line covers a rectangle around its segment, whose ends are where clipping puts them: such
    // lines are clipped against the view volume itself, not a guard band.
    if (!ClipLine(clip_[0], clip_[1], sv_.nvar, state_.samples > 1 ? ClipPlanes{} : planes_, clip_[2], clip_[3])) return;
    ToWindow(clip_[2], sv_.nvar, state_.viewport, win_[0]);
    ToWindow(clip_[3], sv_.nvar, state_.viewport, win_[1]);
    Flat(win_, 2, provoking);
    BinnedPrimitive p;
    p.kind = PrimitiveKind::kLine;
    p.front_facing = front_facing;
    p.depth_offset = depth_offset_;
    bins_.Add(p, win_, LineBox(win_[0], win_[1], state_.bounds, std::min(state_.primitive.line_width, kMaxLineWidth)), grid_);
  }

  void Triangle(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2, std::uint32_t provoking) {
    int count = 3;
    const unsigned* codes = sv_.clip_codes.data();
    if ((codes[i0] | codes[i1] | codes[i2]) == 0) {
      // Inside the guard band: no clipping, and the window positions are already there. The varyings are
      // copied only if the triangle survives culling.
      const std::uint32_t idx[3] = {i0, i1, i2};
      for (int k = 0; k < 3; ++k) win_[k].win = sv_.window[idx[k]];
      if (!Facing(count)) return;
      // A filled triangle that covers no pixel centre draws nothing: not binned at all.
      const bool fill = state_.primitive.polygon_mode == FILL;
      const Rect box =
          fill ? TriangleCentreBox(win_[0].win, win_[1].win, win_[2].win, state_.bounds, state_.samples) : Rect{};
      if (fill && box.Empty()) return;
      if (fill && flat_count_ == 0) {  // binned from where the varyings are
        BinTriangle(i0, i1, i2, box);
        return;
      }
      const std::size_t nvar = std::size_t(sv_.nvar);
      for (int k = 0; k < 3; ++k)
        if (nvar > 0) std::memcpy(win_[k].var, sv_.WindowVertexAt(idx[k]) + 4, sizeof(float) * nvar);
    } else {
      ToClipVertex(sv_, i0, clip_[0]);
      ToClipVertex(sv_, i1, clip_[1]);
      ToClipVertex(sv_, i2, clip_[2]);
      ClipTriangle(clip_[0], clip_[1], clip_[2], sv_.nvar, planes_, poly_);
      if (poly_.count < 3) return;
      count = poly_.count;
      for (int k = 0; k < count; ++k) ToWindow(poly_.v[k], sv_.nvar, state_.viewport, win_[k]);
      if (!Facing(count)) return;
    }
    Flat(win_, count, provoking);
    Emit(i0, i1, i2, provoking, count);
  }

 private:
  // Facing and culling of the polygon win_[0 .. count): false when it is dropped (no area, or culled).
  bool Facing(int count) {
    const float area = SignedArea(win_, count);
    if (area == 0.0f) return false;
    front_ = IsFrontFacing(area, state_.primitive.front_face);
    return !(state_.primitive.cull_enabled && IsCulled(front_, state_.primitive.cull_face));
  }

  // Flat varyings: every vertex of the primitive takes the provoking vertex's value, as the vertex stage wrote it.
  void Flat(WindowVertex* v, int count, std::uint32_t provoking) {
    if (flat_count_ == 0) return;
    const float* value = sv_.Varyings(int(provoking));
    for (int k = 0; k < count; ++k)
      for (int f = 0; f < flat_count_; ++f) v[k].var[flat_[f]] = value[flat_[f]];
    if (ids_)
      for (int k = 0; k < count; ++k) PrimitiveIdFloats(id_, v[k].var + sv_.nvar - 2);
  }

  void Point(std::uint32_t i, std::uint32_t provoking, bool front_facing) {
    ToClipVertex(sv_, i, clip_[0]);
    // A point is kept only when its centre lies inside the view volume itself (OpenGL 4.6, section 13.7.1).
    if (ClipCodes(clip_[0].pos, ClipPlanes{}) != 0) return;
    ToWindow(clip_[0], sv_.nvar, state_.viewport, win_[0]);
    Flat(win_, 1, provoking);
    AddPoint(win_[0], PointSizeOf(i), front_facing);
  }

  // A filled triangle of shaded vertices i0, i1, i2, inside the guard band, whose pixel centres lie in `box`
  // (TriangleCentreBox), with the facing in front_: by their numbers (UseTable), or with copies of them.
  void BinTriangle(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2, const Rect& box) {
    BinnedPrimitive p;
    p.kind = PrimitiveKind::kTriangle;
    p.front_facing = front_;
    if (state_.primitive.offset_fill)
      p.depth_offset = PolygonOffset(sv_.window[i0], sv_.window[i1], sv_.window[i2], state_.primitive.offset_factor,
                                     state_.primitive.offset_units, state_.depth16);
    if (table_) {
      const std::uint32_t index[3] = {i0, i1, i2};
      bins_.AddIndexed(p, index, box, grid_);
      return;
    }
    const VertexView view[3] = {VertexView(sv_.window[i0], sv_.WindowVertexAt(i0) + 4),
                                VertexView(sv_.window[i1], sv_.WindowVertexAt(i1) + 4),
                                VertexView(sv_.window[i2], sv_.WindowVertexAt(i2) + 4)};
    bins_.Add(p, view, box, grid_);
  }

  // The surviving polygon win_[0 .. count) of triangle (i0, i1, i2), filled, as lines or as points.
  void Emit(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2, std::uint32_t provoking, int count) {
    const bool front = front_;
    const bool offset = state_.primitive.polygon_mode == LINE    ? state_.primitive.offset_line
                        : state_.primitive.polygon_mode == POINT ? state_.primitive.offset_point
                                                       : state_.primitive.offset_fill;
    depth_offset_ =
        offset ? PolygonOffset(win_[0].win, win_[1].win, win_[2].win, state_.primitive.offset_factor,
                             state_.primitive.offset_units, state_.depth16)
               : 0.0f;
    switch (state_.primitive.polygon_mode) {
      case LINE:  // the triangle's own edges, each clipped as a line
        Line(i0, i1, provoking, front);
        Line(i1, i2, provoking, front);
        Line(i2, i0, provoking, front);
        break;
      case POINT:
        for (std::uint32_t i : {i0, i1, i2}) Point(i, provoking, front);
        break;
      default:
        for (int k = 1; k + 1 < count; ++k) {  // the fan's triangles (0, k, k+1), in order
          const VertexView fan[3] = {win_[0], win_[k], win_[k + 1]};
          BinnedPrimitive p;
          p.kind = PrimitiveKind::kTriangle;
          p.front_facing = front;
          p.depth_offset = depth_offset_;
          bins_.Add(p, fan, TriangleCentreBox(fan[0].win, fan[1].win, fan[2].win, state_.bounds, state_.samples),
                    grid_);
        }
        break;
    }
    depth_offset_ = 0.0f;
  }

  float PointSizeOf(std::uint32_t i) const {
    const float size = state_.primitive.program_point_size ? sv_.point_size[i] : state_.primitive.point_size;
    return std::isnan(size) ? 1.0f : std::clamp(size, 1.0f, kMaxPointSize);
  }

  void AddPoint(const WindowVertex& v, float size, bool front_facing) {
    BinnedPrimitive p;
    p.kind = PrimitiveKind::kPoint;
    p.front_facing = front_facing;
    p.depth_offset = depth_offset_;
    p.point_size = size;
    bins_.Add(p, &v, PointBox(v, size, state_.bounds), grid_);
  }

  const DrawState& state_;
  const ShadedVertices& sv_;
  BinnedBatch& bins_;
  const TileGrid& grid_;
  ClipVertex (&clip_)[4];  // the worker's PrimitiveScratch
  ClipPolygon& poly_;
  WindowVertex (&win_)[kMaxPolygonVertices];
  ClipPlanes planes_;
  CullState cull_;
  float depth_offset_ = 0.0f;
  bool front_ = true;  // facing of the polygon in win_
  int flat_[kMaxVaryingFloats];  // the varyings that are flat
  int flat_count_ = 0;
  bool ids_ = false;  // primitives carry their number to the fragment stage
  std::uint32_t id_ = 0;
  bool table_ = false;  // UseTable
};

}  // namespace

namespace {

// Transform feedback: the vertices of primitives [0, count) (primitive q of instance g at index q of the assembled
// primitives, its shaded vertices g * unique further on) written in order, each primitive whole into every buffer
// or, once one has no room for it, neither it nor any after it.
void RecordFeedback(const Primitives& prims, std::size_t per_instance, std::size_t count, std::uint32_t unique,
                    const std::vector<std::uint32_t>& map, const ShadedVertices& sv, FeedbackCapture& out) {
  const FeedbackLayout& layout = *out.layout;
  const int per = prims.vertices_per_primitive;
  const int buffers = layout.Buffers();
  std::size_t vertex_bytes[FeedbackCapture::kMaxBuffers] = {};
  int offset[FeedbackCapture::kMaxBuffers] = {};  // each buffer's first float in a vertex's recorded values
  for (int b = 0, at = 0; b < buffers; ++b) {
    const int floats = layout.separate ? layout.items[std::size_t(b)].components : layout.floats;
    vertex_bytes[b] = sizeof(float) * std::size_t(floats);
    offset[b] = at;
    at += floats;
  }
  for (std::size_t p = 0; p < count; ++p) {
    for (int b = 0; b < buffers; ++b)
      if (out.room[b] - out.written[b] < vertex_bytes[b] * std::size_t(per)) return;
    const std::size_t q = p % per_instance;
    const std::uint32_t shift = std::uint32_t(p / per_instance) * unique;
    for (int k = 0; k < per; ++k) {
      const std::uint32_t v = map[prims.indices[q * std::size_t(per) + std::size_t(k)]] + shift;
      const float* values = sv.feedback.data() + std::size_t(v) * std::size_t(layout.floats);
      for (int b = 0; b < buffers; ++b) {
        std::memcpy(out.data[b] + out.written[b], values + offset[b], vertex_bytes[b]);
        out.written[b] += vertex_bytes[b];
      }
    }
    ++out.primitives;
    out.vertices += std::uint64_t(per);
  }
}

// The primitives of one piece, shaded and assembled: `count` of `per` vertices, primitive q of instance g at index
// q of scratch.primitives with its shaded vertices g * unique further on.
struct AssembledPiece {
  int per = 0;
  std::size_t per_instance = 0, count = 0;
  std::uint32_t unique = 0;
  std::uint32_t primitive_base = 0;  // gl_PrimitiveID of primitive 0 of each instance
};

// Transform feedback and the PRIMITIVES_GENERATED query take the primitives of a piece, in order.
void CountAndRecord(const AssembledPiece& a, const DrawState& state, Scratch& scratch) {
  if (state.primitives_generated) *state.primitives_generated += a.count;
  if (state.feedback && a.per_instance > 0)
    RecordFeedback(scratch.primitives, a.per_instance, a.count, a.unique, scratch.element_to_shaded, scratch.shaded,
                   *state.feedback);
}

// The program's geometry stage on the primitives the vertex stage's outputs make (in scratch.geometry), in groups
// of input primitives; each group's output, finished as ShadeVertices finishes vertices, replaces scratch.shaded and
// scratch.primitives (with element_to_shaded the identity), is counted and recorded, and goes to bin(piece).
template <class Bin>
void Geometry(const DrawCall& call, const DrawState& state, const AssembledPiece& input, WorkerPool& pool,
              Scratch& scratch, Bin&& bin) {
  const Program& program = *state.program;
  GeometryScratch& g = scratch.geometry;
  std::swap(g.input, scratch.shaded);
  std::swap(g.input_primitives, scratch.primitives);
  std::swap(g.input_map, scratch.element_to_shaded);
  GeometryInput in;
  in.layout = state.geometry;
  in.prims = &g.input_primitives;
  in.per_instance = input.per_instance;
  in.count = input.count;
  in.unique = input.unique;
  in.map = g.input_map.data();
  in.vertices = &g.input;
  in.first_instance = call.instance;
  in.primitive_base = call.primitive_base;
  in.textures = state.textures;
  in.provoking_first = state.primitive.provoking_first;
  const FeedbackLayout* record = state.feedback ? state.feedback->layout : nullptr;
  const ClipPlanes planes = GuardBandPlanes(state.viewport);
  const bool noperspective = AnyNoPerspective(state.interpolation, program.VaryingFloats());
  const std::size_t group = GeometryGroup(*in.layout);
  for (std::size_t begin = 0; begin < input.count; begin += group) {
    const std::size_t end = std::min(input.count, begin + group);
    ShadedVertices& out = scratch.shaded;
    RunGeometry(program, in, begin, end, state.layers > 1, pool, g, out, scratch.primitives);
    SizeFinished(out, record);
    constexpr int kFinishJob = 4096;
    pool.Run((out.count + kFinishJob - 1) / kFinishJob, [&](int job, int) {
      const int base = job * kFinishJob;
      FinishVertices(out, base, std::min(kFinishJob, out.count - base), planes, state.viewport, state.interpolation,
                     noperspective, record);
    });
    std::vector<std::uint32_t>& map = scratch.element_to_shaded;
    if (map.size() < std::size_t(out.count)) map.resize(std::size_t(out.count));
    for (std::uint32_t i = 0; i < std::uint32_t(out.count); ++i) map[i] = i;
    AssembledPiece a;
    a.per = scratch.primitives.vertices_per_primitive;
    a.per_instance = a.count = scratch.primitives.indices.size() / std::size_t(a.per);
    a.unique = std::uint32_t(out.count);
    CountAndRecord(a, state, scratch);
    if (a.count > 0) bin(a);
  }
}

// The front half of a piece: vertices shaded, primitives assembled (and, with a geometry stage, made anew), counted
// and recorded by transform feedback; each set of primitives to bin goes to bin(piece), with scratch.shaded,
// scratch.primitives and scratch.element_to_shaded holding them.
template <class Bin>
void ShadeAndAssemble(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, WorkerPool& pool,
                      Scratch& scratch, Bin&& bin) {
  const bool geometry = state.geometry != nullptr;
  ShadeVertices(call, fetch, *state.program, state.textures, state.interpolation, state.viewport,
                state.feedback ? state.feedback->layout : nullptr, state.layers > 1 && !geometry, geometry, pool,
                scratch);
  Primitives& prims = scratch.primitives;
  AssemblePrimitives(call.mode, call.count, call.restarts, call.restart_count, prims, state.primitive.provoking_first,
                     geometry);
  AssembledPiece a;
  a.per = prims.vertices_per_primitive;
  if (a.per < 1) return;
  a.per_instance = prims.indices.size() / std::size_t(a.per);
  a.count = a.per_instance * std::size_t(call.instances);
  a.unique = std::uint32_t(scratch.shaded.count / call.instances);
  a.primitive_base = call.primitive_base;
  if (geometry) return a.count > 0 ? Geometry(call, state, a, pool, scratch, bin) : void();
  CountAndRecord(a, state, scratch);
  if (a.count > 0) bin(a);
}

// The back half: the primitives clipped and binned into `packet`'s batches in jobs of kBinJob to kBinJobMax
// primitives, each job into its own batch, the batches kept in primitive order. With `layer` >= 0 (a layered
// framebuffer), only the primitives scratch.primitive_layer sends to that layer.
void BinPrimitives(const AssembledPiece& a, const DrawState& state, DrawPacket& packet, Frame& frame,
                   WorkerPool& pool, Scratch& scratch, int layer = -1, bool keep_vertices = false) {
  const Primitives& prims = scratch.primitives;
  const int per = a.per;
  const std::size_t per_instance = a.per_instance, count = a.count;
  const std::uint32_t unique = a.unique;
  // Every tile walks every batch of the draw, so fewer, larger batches render faster; but each thread should still
  // have about two jobs to bin.
  const std::size_t threads = std::size_t(pool.Threads());
  const std::size_t job_size =
      count <= kBinJob ? kBinJob : std::clamp((count + 2 * threads - 1) / (2 * threads), kBinJob, kBinJobMax);
  const int jobs = int((count + job_size - 1) / job_size);
  if (jobs == 0) return;
  // A draw of one job's primitives goes into a batch shared with the small draws before it; a larger one into
  // batches of its own, one per job.
  const bool shared = jobs == 1;
  BinnedBatch* shared_batch = shared ? &frame.SharedBatch(scratch.shaded.nvar) : nullptr;
  if (!shared) frame.NewBatches(jobs, scratch.shaded.nvar);
  // A draw with batches of its own and shaded vertices that stay as they are (`keep_vertices`: no other binning
  // of them follows) bins its filled triangles inside the guard band by their vertices' numbers, and the frame
  // keeps the shaded vertices' window runs for its tiles to read: nothing copied per triangle or per tile. Only
  // where its primitives share vertices (each used twice at least, on average), as a mesh's do: a tile then reads
  // runs near each other. Primitives each with vertices of their own are copied into the tiles' lists, which a
  // tile reads in order; read by number, they would lie all over the draw's vertices.
  const bool indexed =
      keep_vertices && !shared && std::uint64_t(unique) * 2 <= std::uint64_t(per_instance) * std::uint64_t(per);
  const float* table = scratch.shaded.window_vertices.data();
  const auto& map = scratch.element_to_shaded;
  const auto& idx = prims.indices;
  const TileGrid& grid = frame.Grid();
  const bool first = state.primitive.provoking_first;
  while (scratch.primitive.size() < std::size_t(pool.Threads()))
    scratch.primitive.push_back(std::make_unique<PrimitiveScratch>());
  pool.Run(jobs, [&](int job, int worker) {
    BinnedBatch& bins = shared ? *shared_batch : frame.Batch(packet, job);
    PrimitiveRunner runner(state, scratch.shaded, bins, grid, *scratch.primitive[std::size_t(worker)]);
    if (indexed) {
      bins.SetTable(table);
      runner.UseTable(true);
    }
    const std::size_t end = std::min(count, std::size_t(job + 1) * job_size);
    // Primitive p is primitive q of instance g: q and the instance's shift advance with p (no division per
    // primitive).
    std::size_t q = per_instance ? std::size_t(job) * job_size % per_instance : 0;
    std::uint32_t shift = per_instance ? std::uint32_t(std::size_t(job) * job_size / per_instance) * unique : 0;
    // In groups of up to 16 primitives: the triangles of a group that certainly draw nothing, and the facing and
    // pixel box of most others, are found together.
    std::uint32_t v[TriangleGroup::kSize][4];  // each primitive's vertices, then its provoking vertex
    std::uint32_t id[TriangleGroup::kSize];    // and its gl_PrimitiveID (when the fragment stage reads it)
    const bool ids = state.primitive_ids && !state.geometry;
    GroupVerdict verdict;
    const int* layer_of = layer >= 0 ? scratch.primitive_layer.data() : nullptr;
    for (std::size_t p = std::size_t(job) * job_size; p < end;) {
      int n = 0;
      for (; n < TriangleGroup::kSize && p < end; ++p, ++q) {
        if (q == per_instance) {
          q = 0;
          shift += unique;
        }
        if (layer_of && layer_of[p] != layer) continue;
        const std::size_t i = q * std::size_t(per);
        // The provoking vertex: the first of the primitive or its last (OpenGL 4.6, table 13.2; assembly put it there).
        const std::size_t provoking = i + (first ? 0 : std::size_t(per - 1));
        for (int k = 0; k < per; ++k) v[n][k] = map[idx[i + std::size_t(k)]] + shift;
        v[n][3] = map[idx[provoking]] + shift;
        if (ids) id[n] = a.primitive_base + std::uint32_t(q);
        ++n;
      }
      if (per == 3) runner.Judge(v, n, verdict);
      for (int t = 0; t < n; ++t) {
        if ((verdict.nothing >> t) & 1u) continue;
        if ((verdict.known >> t) & 1u) {
          runner.Known(v[t][0], v[t][1], v[t][2], (verdict.front >> t) & 1u, verdict.Box(t));
          continue;
        }
        if (ids) runner.SetPrimitiveId(id[t]);
        switch (per) {
          case 1: runner.Point(v[t][0]); break;
          case 2: runner.Line(v[t][0], v[t][1], v[t][3]); break;
          default: runner.Triangle(v[t][0], v[t][1], v[t][2], v[t][3]); break;
        }
      }
    }
    if (!shared) bins.Finish(grid);
  });
  if (shared) {
    frame.EndShared();
    return;
  }
  for (int j = 0; j < jobs; ++j) frame.AddBytes(frame.Batch(packet, j).Bytes());
  if (indexed) frame.KeepVertices(scratch.shaded.window_vertices);  // (its data, `table`, moves with it)
}

// Primitives drawn into a layered framebuffer whose program writes gl_Layer: each binned into a draw command of its
// layer's buffers (its provoking vertex's layer; one past the last goes to the last, as does a negative one, as
// llvmpipe has it), layer after layer, the frame rendered between layers.
void BinLayered(const AssembledPiece& a, const DrawState& state, const DrawPacket& proto, Frame& frame,
                WorkerPool& pool, Scratch& scratch) {
  const Primitives& prims = scratch.primitives;
  const std::size_t provoking = state.primitive.provoking_first ? 0 : std::size_t(a.per - 1);
  std::vector<int>& layer_of = scratch.primitive_layer;
  layer_of.resize(a.count);
  std::vector<bool> used(std::size_t(state.layers), false);
  for (std::size_t p = 0; p < a.count; ++p) {
    const std::size_t q = p % a.per_instance;
    const std::uint32_t v = scratch.element_to_shaded[prims.indices[q * std::size_t(a.per) + provoking]] +
                            std::uint32_t(p / a.per_instance) * a.unique;
    const unsigned l = std::min(unsigned(scratch.shaded.layer[v]), unsigned(state.layers - 1));
    layer_of[p] = int(l);
    used[l] = true;
  }
  for (int l = 0; l < state.layers; ++l) {
    if (!used[std::size_t(l)]) continue;
    const RenderTarget& target = state.layer_targets[l];
    if (!frame.Accepts(target) || frame.Bytes() > kFrameBudgetBytes) frame.Render(pool, scratch.tiles);
    DrawPacket& packet = frame.AddDraw(target, proto);
    BinPrimitives(a, state, packet, frame, pool, scratch, l);
    frame.ListLastDraw();
  }
}

// Records one piece of a draw: shaded, assembled, and its primitives binned into a command of their own (a copy
// of the prototype packet; with a geometry stage, one per group of its output), the frame rendered first when what
// is recorded already exceeds the budget. With nothing to rasterize, only shaded, counted and recorded by
// transform feedback.
void RecordPiece(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& proto,
                 const RenderTarget& target, Frame& frame, WorkerPool& pool, Scratch& scratch) {
  if (state.discard || state.bounds.Empty())
    return ShadeAndAssemble(call, fetch, state, pool, scratch, [](const AssembledPiece&) {});
  if (state.layers > 1) {
    return ShadeAndAssemble(call, fetch, state, pool, scratch, [&](const AssembledPiece& a) {
      BinLayered(a, state, proto, frame, pool, scratch);
    });
  }
  if (state.geometry) {  // a command per group of the geometry stage's output
    return ShadeAndAssemble(call, fetch, state, pool, scratch, [&](const AssembledPiece& a) {
      if (frame.Bytes() > kFrameBudgetBytes) frame.Render(pool, scratch.tiles);
      DrawPacket& packet = frame.AddDraw(target, proto);
      BinPrimitives(a, state, packet, frame, pool, scratch);
      frame.ListLastDraw();
    });
  }
  if (frame.Bytes() > kFrameBudgetBytes) frame.Render(pool, scratch.tiles);
  DrawPacket& packet = frame.AddDraw(target, proto);
  ShadeAndAssemble(call, fetch, state, pool, scratch,
                   [&](const AssembledPiece& a) { BinPrimitives(a, state, packet, frame, pool, scratch, -1, true); });
  frame.ListLastDraw();
}

// A large draw with primitive restart: its runs (the element sequences between restart positions) in order, runs
// shorter than kDrawChunk gathered into pieces of several runs (a restart between each two), longer ones drawn
// on their own, each in pieces.
void RecordRestartRuns(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& packet,
                       const RenderTarget& target, Frame& frame, WorkerPool& pool, Scratch& scratch) {
  std::vector<std::uint32_t> group, group_restarts;
  // gl_PrimitiveIDIn counts on across restarts: the primitives of the runs before, and before the group.
  std::uint32_t done = call.primitive_base, group_base = done;
  auto flush = [&] {
    if (group.empty()) return;
    DrawCall sub = call;
    sub.primitive_base = group_base;
    sub.elements = group.data();
    sub.count = int(group.size());
    sub.restarts = group_restarts.empty() ? nullptr : group_restarts.data();
    sub.restart_count = int(group_restarts.size());
    RecordPiece(sub, fetch, state, packet, target, frame, pool, scratch);
    group.clear();
    group_restarts.clear();
  };
  std::uint32_t begin = 0;
  for (int r = 0; r <= call.restart_count; ++r) {
    const std::uint32_t end = r < call.restart_count ? call.restarts[r] : std::uint32_t(call.count);
    const int length = int(end - begin);
    if (length > kDrawChunk) {  // a run of its own, in pieces
      flush();
      DrawCall sub = call;
      sub.elements = call.elements + begin;
      sub.count = length;
      sub.restarts = nullptr;
      sub.restart_count = 0;
      sub.primitive_base = done;
      RecordDraw(sub, fetch, state, packet, target, frame, pool, scratch);
    } else if (length > 0) {
      if (group.size() + std::size_t(length) + 1 > std::size_t(kDrawChunk)) flush();
      if (group.empty()) group_base = done;
      if (!group.empty()) {  // a restart position between runs, holding a copy of the run's first element
        group_restarts.push_back(std::uint32_t(group.size()));
        group.push_back(call.elements[begin]);
      }
      group.insert(group.end(), call.elements + begin, call.elements + end);
    }
    done += std::uint32_t(PrimitiveCount(call.mode, length));
    begin = end + 1;
  }
  flush();
}

}  // namespace

void RecordDraw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& packet,
                const RenderTarget& target, Frame& frame, WorkerPool& pool, Scratch& scratch) {
  if (call.count <= 0 || call.instances <= 0 || state.program == nullptr) return;
  const GeometryLayout* geometry = state.geometry;
  if ((state.bounds.Empty() || state.discard) && !state.feedback && (!geometry || !state.primitives_generated)) {
    // Nothing can be drawn; the primitives are still generated, and counted (a geometry stage's primitives are
    // counted by running it).
    if (state.primitives_generated)
      *state.primitives_generated +=
          PrimitiveCount(call.mode, call.count, call.restarts, call.restart_count) * std::uint64_t(call.instances);
    return;
  }
  if (call.count <= kDrawChunk) {
    // Whole instances together, as many as kDrawChunk vertices hold, in instance order.
    const int group = std::max(1, kDrawChunk / call.count);
    DrawCall sub = call;
    for (std::int64_t g = 0; g < call.instances; g += group) {
      sub.instance = call.instance + std::uint32_t(g);
      sub.instances = int(std::min<std::int64_t>(group, call.instances - g));
      RecordPiece(sub, fetch, state, packet, target, frame, pool, scratch);
    }
    return;
  }
  if (call.instances > 1) {  // one instance at a time, each in pieces
    DrawCall sub = call;
    sub.instances = 1;
    for (int g = 0; g < call.instances; ++g) {
      sub.instance = call.instance + std::uint32_t(g);
      RecordDraw(sub, fetch, state, packet, target, frame, pool, scratch);
    }
    return;
  }
  if (call.mode == LINE_STRIP_ADJACENCY || call.mode == TRIANGLE_STRIP_ADJACENCY) {
    // A strip with adjacency, whose first and last primitives take their adjacent vertices otherwise than the
    // others, is drawn as the list its primitives make (with a geometry stage; without one, as LINES or
    // TRIANGLES), in pieces.
    Primitives list;
    AssemblePrimitives(call.mode, call.count, call.restarts, call.restart_count, list,
                       state.primitive.provoking_first, geometry != nullptr);
    for (std::uint32_t& e : list.indices) e = call.elements ? call.elements[e] : call.first + e;
    DrawCall sub = call;
    sub.mode = geometry ? (call.mode == LINE_STRIP_ADJACENCY ? LINES_ADJACENCY : TRIANGLES_ADJACENCY)
                        : (call.mode == LINE_STRIP_ADJACENCY ? LINES : TRIANGLES);
    sub.elements = list.indices.data();
    sub.count = int(list.indices.size());
    sub.restarts = nullptr;
    sub.restart_count = 0;
    if (sub.count > 0) RecordDraw(sub, fetch, state, packet, target, frame, pool, scratch);
    return;
  }
  if (call.restart_count > 0) return RecordRestartRuns(call, fetch, state, packet, target, frame, pool, scratch);

  // A large draw goes through in pieces of at most kDrawChunk vertices, so that memory stays bounded whatever the
  // count. Each piece is an explicit element list of the draw's own vertex indices (gl_VertexID is kept), or for
  // DrawArrays a range of them; strips overlap by the vertices their primitives share, with an even step so that
  // strip triangles keep their winding; fans repeat vertex 0; a loop's closing segment is drawn last as a line.
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
    default: break;  // lists: kDrawChunk is a multiple of 4 and 6
  }
  // Vertices per primitive of a list, for gl_PrimitiveIDIn of each piece's first primitive.
  const int list = call.mode == LINES_ADJACENCY ? 4 : call.mode == TRIANGLES_ADJACENCY ? 6 : VerticesPerPrimitive(call.mode);
  const bool strip = call.mode == LINE_STRIP || call.mode == LINE_LOOP || call.mode == TRIANGLE_STRIP;
  std::vector<std::uint32_t>& piece = scratch.piece;
  piece.reserve(std::size_t(kDrawChunk));
  for (std::int64_t s = begin; s < count; s += step) {
    piece.clear();
    if (call.mode == TRIANGLE_FAN) piece.push_back(element(0));
    const std::int64_t room = kDrawChunk - std::int64_t(piece.size());
    const std::int64_t stop = std::min(count, s + room);
    DrawCall sub;
    sub.instance = call.instance;
    sub.mode = piece_mode;
    sub.primitive_base = call.primitive_base + std::uint32_t(call.mode == TRIANGLE_FAN ? s - 1 : strip ? s : s / list);
    if (!call.elements && piece.empty()) {  // consecutive vertices: a DrawArrays piece of its own
      sub.first = call.first + std::uint32_t(s);
      sub.count = int(stop - s);
    } else if (piece.empty()) {  // consecutive elements: read where they are
      sub.elements = call.elements + s;
      sub.count = int(stop - s);
    } else {
      if (call.elements) piece.insert(piece.end(), call.elements + s, call.elements + stop);
      else
        for (std::int64_t k = s; k < stop; ++k) piece.push_back(call.first + std::uint32_t(k));
      sub.count = int(piece.size());
      sub.elements = piece.data();
    }
    RecordPiece(sub, fetch, state, packet, target, frame, pool, scratch);
    if (s + room >= count) break;
  }
  if (call.mode == LINE_LOOP) {
    const std::uint32_t closing[2] = {element(count - 1), element(0)};
    DrawCall sub;
    sub.instance = call.instance;
    sub.primitive_base = call.primitive_base + std::uint32_t(count - 1);
    sub.mode = LINES;
    sub.count = 2;
    sub.elements = closing;
    RecordPiece(sub, fetch, state, packet, target, frame, pool, scratch);
  }
}


void PendingDraws::Reset() {
  draws = 0;
  packet.snapshot.reset();
  for (auto& o : packet.occlusion) o.reset();
}

bool SmallDrawApplies(const DrawCall& call, const DrawState& state, const DrawPacket& packet) {
  const bool mode = call.mode == POINTS || call.mode == LINES || call.mode == LINE_STRIP || call.mode == TRIANGLES ||
                    call.mode == TRIANGLE_STRIP || call.mode == TRIANGLE_FAN;
  return mode && call.count > 0 && call.count <= kSmallDrawElements && call.instances == 1 &&
         call.restart_count == 0 && packet.snapshot != nullptr && state.geometry == nullptr && !state.primitive_ids &&
         state.feedback == nullptr && state.primitives_generated == nullptr && !state.discard &&
         !state.bounds.Empty() && state.layers <= 1;
}

namespace {

bool SameRect(const Rect& a, const Rect& b) { return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1; }

// The same fragment operations: the same bytes (both copies of the context's state: the common case, one compare
// of the whole), else the same values member by member (a copy whose padding differs, or zeros of either sign).
bool SameOps(const FragmentOpsState& a, const FragmentOpsState& b) {
  return std::memcmp(&a, &b, sizeof a) == 0 || a == b;
}

bool SamePrimitiveState(const PrimitiveState& a, const PrimitiveState& b) {
  return a.cull_enabled == b.cull_enabled && a.cull_face == b.cull_face && a.front_face == b.front_face &&
         a.polygon_mode == b.polygon_mode && a.program_point_size == b.program_point_size &&
         a.point_size == b.point_size && a.line_width == b.line_width && a.point_lower_left == b.point_lower_left &&
         a.offset_fill == b.offset_fill && a.offset_line == b.offset_line && a.offset_point == b.offset_point &&
         a.offset_factor == b.offset_factor && a.offset_units == b.offset_units &&
         a.provoking_first == b.provoking_first;
}

}  // namespace

bool JoinsPending(const PendingDraws& pending, const DrawCall& call, const DrawState& state, const DrawPacket& packet,
                  const RenderTarget& target) {
  const DrawPacket& p = pending.packet;
  const DrawState& s = pending.state;
  const ViewportTransform &v = s.viewport, &w = state.viewport;
  return pending.vertices + call.count <= kPendingVertices && VerticesPerPrimitive(call.mode) == pending.per &&
         p.snapshot == packet.snapshot && p.nvar == packet.nvar && p.interpolation == packet.interpolation &&
         p.shader_depth == packet.shader_depth && p.early_depth == packet.early_depth &&
         p.point_lower_left == packet.point_lower_left && p.line_width == packet.line_width &&
         SameRect(p.bounds, packet.bounds) && SameOps(p.ops, packet.ops) && v.scale == w.scale &&
         v.translate == w.translate && SameRect(v.rect, w.rect) && s.samples == state.samples &&
         s.depth16 == state.depth16 && SamePrimitiveState(s.primitive, state.primitive) &&
         SameBuffers(pending.target, target) && pending.textures.Same(*packet.textures);
}

void ShadeSmallDraw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& packet,
                    const RenderTarget& target, PendingDraws& pending, Scratch& scratch) {
  ShadedVertices& out = scratch.shaded;
  std::vector<std::uint32_t>& list = scratch.primitives.indices;
  const Program& program = *state.program;
  if (pending.Empty()) {
    pending.per = VerticesPerPrimitive(call.mode);
    pending.packet = packet;
    pending.textures.CopyFrom(*packet.textures);
    pending.packet.textures = &pending.textures.textures;
    pending.state = state;
    pending.state.program = packet.program;
    pending.state.textures = &pending.textures.textures;
    pending.target = target;
    out.count = 0;
    out.nvar = program.VertexVaryingFloats();
    list.clear();
    // Room for every vertex the held draws may have.
    const std::size_t room = std::size_t(kPendingVertices);
    if (out.position.size() < room) out.position.resize(room);
    if (out.point_size.size() < room) out.point_size.resize(room);
    if (out.varyings.size() < room * std::size_t(out.nvar)) out.varyings.resize(room * std::size_t(out.nvar));
  }
  const int unique = UniqueVertices(call, scratch);
  const int base = out.count;
  if (scratch.vertex.empty()) scratch.vertex.resize(1);
  VertexScratch& vs = VertexScratchOf(scratch, 0);
  const int simd = int(CpuSimdLevel());
  for (int k = 0, m = 0; k < unique; k += m) {
    m = std::min(kVertexBatch, unique - k);
    ShadeBatch(fetch, program, state.textures, scratch.shade_indices.data() + k, m, call.instance, simd, false, vs,
               out, base + k);
  }
  const std::uint32_t* map = scratch.element_to_shaded.data();
  if (call.mode == POINTS || call.mode == LINES || call.mode == TRIANGLES) {
    // A list is its own assembly: its elements in order, an incomplete last primitive dropped.
    const int whole = call.count - call.count % pending.per;
    for (int i = 0; i < whole; ++i) list.push_back(std::uint32_t(base) + map[i]);
  } else {
    AssemblePrimitives(call.mode, call.count, pending.assembled, state.primitive.provoking_first);
    for (const std::uint32_t i : pending.assembled.indices) list.push_back(std::uint32_t(base) + map[i]);
  }
  out.count = pending.vertices = base + unique;
  ++pending.draws;
}

void RecordPending(PendingDraws& pending, Frame& frame, WorkerPool& pool, Scratch& scratch) {
  if (pending.Empty()) return;
  const DrawState& state = pending.state;
  ShadedVertices& out = scratch.shaded;
  const int n = out.count;
  SizeFinished(out, nullptr);
  FinishVertices(out, 0, n, GuardBandPlanes(state.viewport), state.viewport, state.interpolation,
                 AnyNoPerspective(state.interpolation, out.nvar), nullptr);
  // The held draws as one piece of a list, each element its own shaded vertex.
  scratch.primitives.vertices_per_primitive = pending.per;
  auto& map = scratch.element_to_shaded;
  if (map.size() < std::size_t(n)) map.resize(std::size_t(n));
  for (int i = 0; i < n; ++i) map[std::size_t(i)] = std::uint32_t(i);
  AssembledPiece a;
  a.per = pending.per;
  a.per_instance = a.count = scratch.primitives.indices.size() / std::size_t(a.per);
  a.unique = std::uint32_t(n);
  pending.draws = 0;  // (recorded from here on, or dropped if this throws)
  if (a.count > 0) {
    if (frame.Bytes() > kFrameBudgetBytes) frame.Render(pool, scratch.tiles);
    DrawPacket& packet = frame.AddDraw(pending.target, pending.packet);
    BinPrimitives(a, state, packet, frame, pool, scratch);
    frame.ListLastDraw();
  }
  pending.Reset();
}

}  // namespace softgl::detail

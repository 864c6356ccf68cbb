// context_draw.cpp — the draw calls: validation, index reading and primitive restart, and ContextState::Draw,
// which resolves the bound objects into plain structs (FetchPlan, DrawState, DrawPacket) for the pipeline.
#include "context_state.h"
#include "vertex_fetch.h"
#include "viewport.h"

#include <bit>

namespace softgl {

// ---- Drawing -------------------------------------------------------------------------------------------------

void ContextState::Draw(const detail::DrawCall& call) {
  detail::FetchPlan& plan = fetch_plan;  // every field a fetch reads is set here
  std::copy(std::begin(current_attrib), std::end(current_attrib), plan.current);
  plan.enabled = vao->enabled;
  for (std::uint32_t bits = vao->enabled; bits != 0; bits &= bits - 1) {  // (the disabled ones are not read)
    const int i = std::countr_zero(bits);
    const AttribBinding& a = vao->attrib[i];
    detail::AttribSource& src = plan.attrib[i];
    src.data = a.buffer ? a.buffer->data.data() : nullptr;
    src.size = a.buffer ? a.buffer->data.size() : 0;
    src.offset = a.offset;
    src.components = a.size;
    src.type = a.type;
    src.normalized = a.normalized;
    src.bgra = a.bgra;
    src.integer = a.integer;
    src.divisor = a.divisor;
    src.stride = a.stride ? std::size_t(a.stride) : detail::AttributeBytes(a.type, a.size);
  }

  // The draw's target: the context's framebuffer's as kept from draw to draw, or the framebuffer object's.
  if (draw_fbo && !DrawTarget(fbo_draw_target, true)) return;
  const detail::RenderTarget& target = draw_fbo ? fbo_draw_target : fb.KeptFrameTarget(framebuffer_srgb);
  if (condition_discards) return;  // BeginConditionalRender's query counted nothing

  // The fragment stage's state, captured now: the shader's uniforms (a copy), the textures of every unit resolved
  // once, the per-fragment operations.
  // (The context's own packet, reused from draw to draw: every field is set here, the views of the bound units
  // only, and what it holds is released at the end.)
  detail::DrawPacket& packet = draw_packet;
  detail::DrawTextures& tex = draw_textures;
  for (int u = 0; u < units_used; ++u)  // (the units past those stay null)
    for (int k = 0; k < detail::kTextureKinds; ++k) {
      const detail::TextureObject* t = units[u].bound[k].get();
      (tex.textures.*detail::kKindUnits[k])[u] = t ? &(tex.views[k][u] = detail::MakeView(*t, units[u].sampler.get())) : nullptr;
    }
  tex.textures.units = units_used;
  packet.textures = &tex.textures;
  packet.ops = ops;
  for (int k = 0; k < 2; ++k)  // the active occlusion queries count this draw's fragments
    if (active_query[k]) {
      packet.occlusion[k] = queries.at(active_query[k])->counter;
      packet.ops.occlusion[k] = packet.occlusion[k].get();
    }
  packet.nvar = program->VaryingFloats();
  packet.interpolation = program->VaryingInterpolation();
  packet.shader_depth = program->WritesDepth();
  packet.point_lower_left = primitive.point_lower_left;
  packet.line_width = std::min(primitive.line_width, detail::kMaxLineWidth);

  detail::DrawState ds;
  ds.program = program;
  ds.geometry = program->GeometryStage();
  ds.primitive_ids = program->ReadsPrimitiveId();
  ds.textures = &tex.textures;
  ds.interpolation = packet.interpolation;
  ds.viewport = detail::MakeViewportTransform(viewport[0], viewport[1], viewport[2], viewport[3], depth_near,
                                              depth_far);
  const detail::Rect fbr = ClearArea(target);  // draw target and scissor
  ds.bounds = detail::Rect{std::max(ds.viewport.rect.x0, fbr.x0), std::max(ds.viewport.rect.y0, fbr.y0),
                           std::min(ds.viewport.rect.x1, fbr.x1), std::min(ds.viewport.rect.y1, fbr.y1)};
  ds.primitive = primitive;
  ds.samples = target.samples > 1 && ops.multisample.multisample ? target.samples : 1;
  ds.depth16 = target.depth16 != nullptr;
  if (active_query[2]) ds.primitives_generated = &queries.at(active_query[2])->count;
  ds.discard = rasterizer_discard;
  if (draw_fbo && program->WritesLayer() && DrawLayers() > 1) {  // each primitive into the layer it names
    layer_targets.resize(std::size_t(DrawLayers()));
    for (std::size_t l = 0; l < layer_targets.size(); ++l) layer_targets[l] = l == 0 ? target : DrawLayer(int(l));
    ds.layer_targets = layer_targets.data();
    ds.layers = int(layer_targets.size());
  }
  // Transform feedback: each buffer's store from its write position on (a store replaced since may have shrunk).
  detail::FeedbackCapture capture;
  TransformFeedbackObject& xfb = *feedback;
  if (xfb.Recording()) {
    capture.layout = xfb.layout.get();
    for (int b = 0; b < capture.layout->Buffers(); ++b) {
      const FeedbackBinding& binding = xfb.binding[b];
      if (binding.buffer) BeforeStoreChange(*binding.buffer, __func__);  // the draw writes it as it is made
      const std::size_t room = binding.Room();
      capture.room[b] = room > xfb.written[b] ? room - xfb.written[b] : 0;
      capture.data[b] = capture.room[b] ? binding.buffer->data.data() + binding.offset + xfb.written[b] : nullptr;
    }
    ds.feedback = &capture;
  }
  packet.bounds = ds.bounds;
  try {
    if (last_snapshot && program->SnapshotIs(*last_snapshot)) {
      packet.snapshot = last_snapshot;
    } else {
      last_snapshot.reset();
      packet.snapshot = program->Snapshot();
      last_snapshot = packet.snapshot;
    }
    packet.program = packet.snapshot ? packet.snapshot.get() : program;
    packet.early_depth = detail::EarlyDepthTestApplies(ops, packet.program->WritesDepth());
    // A small draw joins the small draws held before it when it can (the same state): its vertices are shaded
    // now, the rest of its front end runs with theirs. Any other draw records the held ones first.
    const bool small = detail::SmallDrawApplies(call, ds, packet);
    const bool joins = small && !pending.Empty() && detail::JoinsPending(pending, call, ds, packet, target);
    if (!joins) {  // (a draw that joins has the held draws' target, which the frame accepts)
      detail::RecordPending(pending, frame, *pool, scratch);
      if (!frame.Accepts(target)) Sync(__func__);
    }
    if (small) detail::ShadeSmallDraw(call, plan, ds, packet, target, pending, scratch);
    else detail::RecordDraw(call, plan, ds, packet, target, frame, *pool, scratch);
  } catch (const std::bad_alloc&) {
    pending.Reset();
    frame.Reset();
    SetError(OUT_OF_MEMORY, __func__, "out of memory (recorded draws not yet rendered are dropped)");
  } catch (const std::length_error&) {
    pending.Reset();
    frame.Reset();
    SetError(OUT_OF_MEMORY, __func__, "out of memory (recorded draws not yet rendered are dropped)");
  }
  if (ds.feedback) {
    for (int b = 0; b < capture.layout->Buffers(); ++b) xfb.written[b] += capture.written[b];
    xfb.vertices += capture.vertices;
    if (active_query[4]) queries.at(active_query[4])->count += capture.primitives;
  }
  // A shader that cannot be copied is used as it is: render before the caller can change it.
  const bool copied = packet.snapshot != nullptr;
  packet.snapshot.reset();
  for (auto& o : packet.occlusion) o.reset();
  if (!copied) Sync(__func__);
}

namespace {

// OpenGL 3.3 (2.9.3): reading a mapped buffer is INVALID_OPERATION. False, with the error set, when an enabled
// attribute array's buffer (or, for indexed draws, the element buffer) is mapped. Needs a bound vertex array.
bool CheckNotMapped(ContextState& s, const char* what, bool elements) {
  bool mapped = elements && s.vao->element_buffer && s.vao->element_buffer->mapped;
  for (std::uint32_t bits = s.vao->enabled; bits != 0; bits &= bits - 1) {
    const AttribBinding& a = s.vao->attrib[std::countr_zero(bits)];
    mapped = mapped || (a.buffer && a.buffer->mapped);
  }
  if (mapped) return s.SetError(INVALID_OPERATION, what, "a buffer the draw reads (an enabled attribute array's or the element buffer) is mapped"), false;
  return true;
}

// The draw's mode against the program's geometry stage (OpenGL 4.6, section 11.3.1: a mode that does not make the
// primitives it takes is INVALID_OPERATION) and, while transform feedback records (section 13.3), against
// BeginTransformFeedback's: primitives of another kind (the geometry stage's output, with one), or a buffer being
// recorded into mapped, are INVALID_OPERATION. False with the error set. Needs a program.
bool CheckModes(ContextState& s, const char* what, Enum mode) {
  const GeometryLayout* g = s.program->GeometryStage();
  if (g && !g->Accepts(mode)) return s.SetError(INVALID_OPERATION, what, "the draw's mode does not make the primitives the program's geometry stage takes (kGeometry.input)"), false;
  const TransformFeedbackObject& t = *s.feedback;
  if (!t.Recording()) return true;
  const int kind = g ? (g->output == POINTS ? 1 : g->output == LINE_STRIP ? 2 : 3) : detail::VerticesPerPrimitive(mode);
  if (kind != detail::VerticesPerPrimitive(t.mode)) return s.SetError(INVALID_OPERATION, what, "the draw makes primitives of another kind than BeginTransformFeedback was given"), false;
  for (int b = 0; b < t.layout->Buffers(); ++b)
    if (t.binding[b].buffer && t.binding[b].buffer->mapped) return s.SetError(INVALID_OPERATION, what, "a buffer transform feedback records into is mapped"), false;
  return true;
}

void DrawArraysChecked(ContextState& s, const char* what, Enum mode, int first, int count, int instances) {
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, what, "mode is not a primitive mode");
  if (first < 0 || count < 0) return s.SetError(INVALID_VALUE, what, "first or count is negative");
  if (instances < 0) return s.SetError(INVALID_VALUE, what, "instancecount is negative");
  if (s.vao == nullptr || s.program == nullptr) return s.SetError(INVALID_OPERATION, what, "needs a bound vertex array and a shader (UseProgram)");
  if (!CheckNotMapped(s, what, false) || !CheckModes(s, what, mode)) return;
  if (instances == 0) return;
  detail::DrawCall call;
  call.mode = mode;
  call.count = count;
  call.first = std::uint32_t(first);
  call.instances = instances;
  s.Draw(call);
}

}  // namespace

void Context::DrawArrays(Enum mode, int first, int count) { DrawArraysChecked(*state_, __func__, mode, first, count, 1); }

void Context::DrawArraysInstanced(Enum mode, int first, int count, int instancecount) {
  DrawArraysChecked(*state_, __func__, mode, first, count, instancecount);
}

namespace {

// The checks DrawElement and its variants share (OpenGL 3.3, section 2.8.3): an error set, and false, when the
// draw must not happen. `what` names the call in the error.
bool CheckElements(ContextState& s, const char* what, Enum mode, Enum type) {
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, what, "mode is not a primitive mode"), false;
  if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT) return s.SetError(INVALID_ENUM, what, "index type must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"), false;
  return true;
}
bool CheckElementsBound(ContextState& s, const char* what, Enum mode) {
  if (s.vao == nullptr || s.program == nullptr || !s.vao->element_buffer) return s.SetError(INVALID_OPERATION, what, "needs a bound vertex array with an element buffer, and a shader (UseProgram)"), false;
  return CheckNotMapped(s, what, true) && CheckModes(s, what, mode);
}
bool CheckElementRange(ContextState& s, const char* what, int count, Enum type, std::size_t offset) {
  const auto& store = s.vao->element_buffer->data;
  const std::size_t bytes = std::size_t(count) * detail::TypeSize(type);
  if (offset > store.size() || bytes > store.size() - offset) return s.SetError(INVALID_OPERATION, what, "the indices would be read past the end of the element buffer"), false;
  return true;
}

// Draws count indices of `type` at byte `offset` of the bound element buffer, each plus `basevertex` (checked
// already). An index whose sum with basevertex falls outside 0 .. 2^32 - 1 (undefined in OpenGL) becomes 2^32 - 1:
// past the end of every buffer, so its attributes read (0, 0, 0, 1).
void DrawIndexed(ContextState& s, const char* what, Enum mode, int count, Enum type, std::size_t offset,
                 int basevertex, int instances = 1) {
  if (count == 0 || instances == 0) return;
  std::vector<std::uint32_t>& elements = s.scratch.elements;  // reused: no allocation (and page faults) per draw
  try {
    elements.resize(std::size_t(count));
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, what, "out of memory");
  }
  detail::ReadIndices(type, s.vao->element_buffer->data.data() + offset, count, elements.data());
  // Primitive restart: the positions of the restart index, compared before basevertex is added (OpenGL 4.6,
  // section 10.3.6); PRIMITIVE_RESTART_FIXED_INDEX (2^N - 1 for N-bit indices) takes precedence. Each marker then
  // takes its neighbour's value, so that it widens the range of indices shaded by nothing.
  std::vector<std::uint32_t>& restarts = s.scratch.restarts;
  restarts.clear();
  if (s.primitive_restart || s.primitive_restart_fixed) {
    const std::uint32_t marker = !s.primitive_restart_fixed ? s.restart_index
                                 : type == UNSIGNED_BYTE    ? 0xFFu
                                 : type == UNSIGNED_SHORT   ? 0xFFFFu
                                                            : 0xFFFFFFFFu;
    try {
      for (int i = 0; i < count; ++i)
        if (elements[std::size_t(i)] == marker) restarts.push_back(std::uint32_t(i));
    } catch (const std::bad_alloc&) {
      return s.SetError(OUT_OF_MEMORY, what, "out of memory");
    }
    if (restarts.size() == std::size_t(count)) return;  // nothing but restarts
    for (std::uint32_t i : restarts) {  // the previous element (already replaced), or the first non-marker
      if (i > 0) {
        elements[i] = elements[i - 1];
      } else {
        std::size_t k = 0;
        while (elements[k] == marker) ++k;
        elements[0] = elements[k];
      }
    }
  }
  if (basevertex != 0)
    for (std::uint32_t& e : elements) {
      const std::int64_t v = std::int64_t(e) + basevertex;
      e = (v < 0 || v > std::int64_t(UINT32_MAX)) ? UINT32_MAX : std::uint32_t(v);
    }
  detail::DrawCall call;
  call.mode = mode;
  call.count = count;
  call.elements = elements.data();
  call.instances = instances;
  call.restarts = restarts.empty() ? nullptr : restarts.data();
  call.restart_count = int(restarts.size());
  s.Draw(call);
}

void DrawElementsChecked(ContextState& s, const char* what, Enum mode, int count, Enum type, std::size_t offset,
                         int basevertex, int instances = 1) {
  if (!CheckElements(s, what, mode, type)) return;
  if (count < 0) return s.SetError(INVALID_VALUE, what, "count is negative");
  if (instances < 0) return s.SetError(INVALID_VALUE, what, "instancecount is negative");
  if (!CheckElementsBound(s, what, mode) || !CheckElementRange(s, what, count, type, offset)) return;
  DrawIndexed(s, what, mode, count, type, offset, basevertex, instances);
}

}  // namespace

void Context::DrawElement(Enum mode, int count, Enum type, std::size_t offset) {
  DrawElementsChecked(*state_, __func__, mode, count, type, offset, 0);
}

void Context::DrawElementsBaseVertex(Enum mode, int count, Enum type, std::size_t offset, int basevertex) {
  DrawElementsChecked(*state_, __func__, mode, count, type, offset, basevertex);
}

void Context::DrawElementsInstanced(Enum mode, int count, Enum type, std::size_t offset, int instancecount) {
  DrawElementsChecked(*state_, __func__, mode, count, type, offset, 0, instancecount);
}

void Context::DrawElementsInstancedBaseVertex(Enum mode, int count, Enum type, std::size_t offset, int instancecount,
                                              int basevertex) {
  DrawElementsChecked(*state_, __func__, mode, count, type, offset, basevertex, instancecount);
}

namespace {

void DrawRangeChecked(ContextState& s, const char* what, Enum mode, std::uint32_t start, std::uint32_t end, int count,
                      Enum type, std::size_t offset, int basevertex) {
  if (!CheckElements(s, what, mode, type)) return;
  if (count < 0) return s.SetError(INVALID_VALUE, what, "count is negative");
  if (end < start) return s.SetError(INVALID_VALUE, what, "end is less than start");
  if (!CheckElementsBound(s, what, mode) || !CheckElementRange(s, what, count, type, offset)) return;
  DrawIndexed(s, what, mode, count, type, offset, basevertex);
}

// MultiDrawElements and MultiDrawElementsBaseVertex: every draw checked before any is made.
void MultiDrawChecked(ContextState& s, const char* what, Enum mode, const int* count, Enum type,
                      const std::size_t* offsets, int drawcount, const int* basevertex) {
  if (!CheckElements(s, what, mode, type)) return;
  if (drawcount < 0) return s.SetError(INVALID_VALUE, what, "drawcount is negative");
  if (drawcount > 0 && (count == nullptr || offsets == nullptr)) return s.SetError(INVALID_VALUE, what, "count or offsets is null");
  for (int i = 0; i < drawcount; ++i)
    if (count[i] < 0) return s.SetError(INVALID_VALUE, what, "a count is negative");
  if (!CheckElementsBound(s, what, mode)) return;
  for (int i = 0; i < drawcount; ++i)
    if (!CheckElementRange(s, what, count[i], type, offsets[i])) return;
  for (int i = 0; i < drawcount; ++i) DrawIndexed(s, what, mode, count[i], type, offsets[i], basevertex ? basevertex[i] : 0);
}

}  // namespace

void Context::DrawRangeElements(Enum mode, std::uint32_t start, std::uint32_t end, int count, Enum type,
                                std::size_t offset) {
  DrawRangeChecked(*state_, __func__, mode, start, end, count, type, offset, 0);
}

void Context::DrawRangeElementsBaseVertex(Enum mode, std::uint32_t start, std::uint32_t end, int count, Enum type,
                                          std::size_t offset, int basevertex) {
  DrawRangeChecked(*state_, __func__, mode, start, end, count, type, offset, basevertex);
}

void Context::MultiDrawArrays(Enum mode, const int* first, const int* count, int drawcount) {
  auto& s = *state_;
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, __func__, "mode is not a primitive mode");
  if (drawcount < 0) return s.SetError(INVALID_VALUE, __func__, "drawcount is negative");
  if (drawcount > 0 && (first == nullptr || count == nullptr)) return s.SetError(INVALID_VALUE, __func__, "first or count is null");
  for (int i = 0; i < drawcount; ++i)
    if (first[i] < 0 || count[i] < 0) return s.SetError(INVALID_VALUE, __func__, "a first or count is negative");
  if (s.vao == nullptr || s.program == nullptr) return s.SetError(INVALID_OPERATION, __func__, "needs a bound vertex array and a shader (UseProgram)");
  if (!CheckNotMapped(s, __func__, false) || !CheckModes(s, __func__, mode)) return;
  for (int i = 0; i < drawcount; ++i) DrawArrays(mode, first[i], count[i]);
}

void Context::DrawTransformFeedback(Enum mode, std::uint32_t id) {
  auto& s = *state_;
  const TransformFeedbackObject* t = id == 0 ? &s.default_feedback : nullptr;
  if (auto it = s.feedbacks.find(id); id != 0 && it != s.feedbacks.end() && it->second->bound) t = it->second.get();
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, __func__, "mode is not a primitive mode");
  if (t == nullptr) return s.SetError(INVALID_VALUE, __func__, "not a transform feedback object (made by GenTransformFeedback and bound since, not deleted)");
  if (!t->ended) return s.SetError(INVALID_OPERATION, __func__, "EndTransformFeedback has never been called on the object");
  DrawArraysChecked(s, __func__, mode, 0, int(std::min<std::uint64_t>(t->drawable, INT32_MAX)), 1);
}

void Context::MultiDrawElements(Enum mode, const int* count, Enum type, const std::size_t* offsets, int drawcount) {
  MultiDrawChecked(*state_, __func__, mode, count, type, offsets, drawcount, nullptr);
}

void Context::MultiDrawElementsBaseVertex(Enum mode, const int* count, Enum type, const std::size_t* offsets,
                                          int drawcount, const int* basevertex) {
  if (drawcount > 0 && basevertex == nullptr) return state_->SetError(INVALID_VALUE, __func__, "basevertex is null");
  MultiDrawChecked(*state_, __func__, mode, count, type, offsets, drawcount, basevertex);
}

}  // namespace softgl

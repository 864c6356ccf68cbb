// context_queries.cpp — state queries (GetIntegerv and its kin, GetString) and query objects (occlusion,
// primitives generated, time elapsed).
#include "context_state.h"
#include "texture_compression.h"

#include <cmath>

namespace softgl {

// ---- State queries -------------------------------------------------------------------------------------------

namespace {

// One piece of state as OpenGL's Get* calls see it: up to 4 values of one kind. kNormalized values (colours and
// depths in [0, 1] or [-1, 1]) map to integers linearly rather than by rounding (OpenGL 4.6, section 2.2.2).
struct StateValue {
  enum class Kind { kBool, kInt, kFloat, kNormalized } kind = Kind::kInt;
  double v[4] = {0, 0, 0, 0};
  int count = 0;
};

// The value of `pname`, or false when it is not a name the context keeps (the caller sets INVALID_ENUM).
bool QueryState(ContextState& s, Enum pname, StateValue& out) {
  using Kind = StateValue::Kind;
  auto put = [&](Kind kind, std::initializer_list<double> values) {
    out.kind = kind;
    out.count = 0;
    for (double d : values) out.v[out.count++] = d;
    return true;
  };
  auto integer = [&](double v) { return put(Kind::kInt, {v}); };
  auto boolean = [&](bool v) { return put(Kind::kBool, {v ? 1.0 : 0.0}); };
  if (bool* flag = CapFlag(s, pname)) return boolean(*flag);
  if (pname == BLEND) return boolean(s.ops.BlendEnabled(0));  // (draw buffer 0's)
  if (pname >= DRAW_BUFFER0 && pname < DRAW_BUFFER0 + kMaxColorOutputs) {
    const int i = int(pname - DRAW_BUFFER0);
    // The context's own framebuffer has one colour buffer, which output 0 writes (BACK, as a double-buffered
    // OpenGL context would say; the others NONE).
    return integer(s.draw_fbo ? s.draw_fbo->draw_buffers[i] : i == 0 ? Enum(0x0405) : NONE);
  }
  const detail::StencilFace& f = s.ops.front;
  const detail::StencilFace& b = s.ops.back;
  const detail::BlendState& blend = s.ops.blend;
  switch (pname) {
    case ARRAY_BUFFER_BINDING: return integer(IdOf(s.buffers, s.array_buffer.get()));
    case ELEMENT_ARRAY_BUFFER_BINDING: return integer(s.vao ? IdOf(s.buffers, s.vao->element_buffer.get()) : 0);
    case COPY_READ_BUFFER_BINDING: return integer(IdOf(s.buffers, s.copy_read_buffer.get()));
    case COPY_WRITE_BUFFER_BINDING: return integer(IdOf(s.buffers, s.copy_write_buffer.get()));
    case TEXTURE_BUFFER: return integer(IdOf(s.buffers, s.texture_buffer.get()));  // the buffer binding
    case TRANSFORM_FEEDBACK_BUFFER_BINDING: return integer(IdOf(s.buffers, s.feedback_buffer.get()));
    case TRANSFORM_FEEDBACK_BINDING: return integer(s.feedback_id);
    case TRANSFORM_FEEDBACK_BUFFER_ACTIVE: return boolean(s.feedback->active);
    case TRANSFORM_FEEDBACK_BUFFER_PAUSED: return boolean(s.feedback->paused);
    case MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS: return integer(kMaxFeedbackComponents);
    case MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS:
    case MAX_TRANSFORM_FEEDBACK_BUFFERS: return integer(kMaxFeedbackBuffers);
    case MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS: return integer(kMaxFeedbackSeparateComponents);
    case VERTEX_ARRAY_BINDING: return integer(s.vao_id);
    case ACTIVE_TEXTURE: return integer(TEXTURE0 + Enum(s.active_unit));
    case TIMESTAMP: return integer(std::int64_t(TimestampNs()));
    case TEXTURE_BINDING_2D: return integer(IdOf(s.textures, s.Bound(TEXTURE_2D)));
    case TEXTURE_BINDING_CUBE_MAP: return integer(IdOf(s.textures, s.Bound(TEXTURE_CUBE_MAP)));
    case TEXTURE_BINDING_2D_ARRAY: return integer(IdOf(s.textures, s.Bound(TEXTURE_2D_ARRAY)));
    case TEXTURE_BINDING_3D: return integer(IdOf(s.textures, s.Bound(TEXTURE_3D)));
    case TEXTURE_BINDING_1D: return integer(IdOf(s.textures, s.Bound(TEXTURE_1D)));
    case TEXTURE_BINDING_1D_ARRAY: return integer(IdOf(s.textures, s.Bound(TEXTURE_1D_ARRAY)));
    case TEXTURE_BINDING_BUFFER: return integer(IdOf(s.textures, s.Bound(TEXTURE_BUFFER)));
    case TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY: return integer(IdOf(s.textures, s.Bound(TEXTURE_2D_MULTISAMPLE_ARRAY)));
    case TEXTURE_BINDING_2D_MULTISAMPLE: return integer(IdOf(s.textures, s.Bound(TEXTURE_2D_MULTISAMPLE)));
    case SAMPLER_BINDING: return integer(IdOf(s.samplers, s.units[s.active_unit].sampler.get()));
    case DRAW_FRAMEBUFFER_BINDING: return integer(IdOf(s.framebuffers, s.draw_fbo));
    case DRAW_BUFFER: return QueryState(s, DRAW_BUFFER0, out);
    case READ_BUFFER: return integer(s.read_fbo ? s.read_fbo->read_buffer : s.default_read_buffer);
    case RENDERBUFFER_BINDING: return integer(IdOf(s.renderbuffers, s.renderbuffer.get()));
    case READ_FRAMEBUFFER_BINDING: return integer(IdOf(s.framebuffers, s.read_fbo));
    case VIEWPORT: return put(Kind::kInt, {double(s.viewport[0]), double(s.viewport[1]), double(s.viewport[2]), double(s.viewport[3])});
    case SCISSOR_BOX: return put(Kind::kInt, {double(s.scissor[0]), double(s.scissor[1]), double(s.scissor[2]), double(s.scissor[3])});
    case DEPTH_RANGE: {  // rounded to floats, as Mesa keeps them (volatile: GCC 12 folds the round trip away)
      const volatile float n = float(s.depth_near), f = float(s.depth_far);
      return put(Kind::kNormalized, {n, f});
    }
    case CULL_FACE_MODE: return integer(s.primitive.cull_face);
    case FRONT_FACE: return integer(s.primitive.front_face);
    case POLYGON_MODE: return put(Kind::kInt, {double(s.primitive.polygon_mode), double(s.primitive.polygon_mode)});
    case POINT_SIZE: return put(Kind::kFloat, {s.primitive.point_size});
    case LINE_WIDTH: return put(Kind::kFloat, {s.primitive.line_width});
    case POINT_SPRITE_COORD_ORIGIN: return integer(s.primitive.point_lower_left ? LOWER_LEFT : UPPER_LEFT);
    case POINT_FADE_THRESHOLD_SIZE: return put(Kind::kFloat, {s.primitive.point_fade_threshold});
    case PROVOKING_VERTEX: return integer(s.primitive.provoking_first ? FIRST_VERTEX_CONVENTION : LAST_VERTEX_CONVENTION);
    case POLYGON_OFFSET_FACTOR: return put(Kind::kFloat, {s.primitive.offset_factor});
    case POLYGON_OFFSET_UNITS: return put(Kind::kFloat, {s.primitive.offset_units});
    case PRIMITIVE_RESTART_INDEX: return integer(s.restart_index);
    case DEPTH_FUNC: return integer(s.ops.depth_func);
    case DEPTH_WRITEMASK: return boolean(s.ops.depth_write);
    case DEPTH_CLEAR_VALUE: return put(Kind::kNormalized, {s.clear_depth});
    case STENCIL_FUNC: return integer(f.func);
    case STENCIL_REF: return integer(std::clamp(f.ref, 0, 255));  // clamped to the stencil buffer's range
    case STENCIL_VALUE_MASK: return integer(f.value_mask);
    case STENCIL_FAIL: return integer(f.sfail);
    case STENCIL_PASS_DEPTH_FAIL: return integer(f.dpfail);
    case STENCIL_PASS_DEPTH_PASS: return integer(f.dppass);
    case STENCIL_WRITEMASK: return integer(f.write_mask);
    case STENCIL_BACK_FUNC: return integer(b.func);
    case STENCIL_BACK_REF: return integer(std::clamp(b.ref, 0, 255));
    case STENCIL_BACK_VALUE_MASK: return integer(b.value_mask);
    case STENCIL_BACK_FAIL: return integer(b.sfail);
    case STENCIL_BACK_PASS_DEPTH_FAIL: return integer(b.dpfail);
    case STENCIL_BACK_PASS_DEPTH_PASS: return integer(b.dppass);
    case STENCIL_BACK_WRITEMASK: return integer(b.write_mask);
    case STENCIL_CLEAR_VALUE: return integer(s.clear_stencil);
    case BLEND_SRC_RGB: return integer(blend.src_rgb);
    case BLEND_DST_RGB: return integer(blend.dst_rgb);
    case BLEND_SRC_ALPHA: return integer(blend.src_alpha);
    case BLEND_DST_ALPHA: return integer(blend.dst_alpha);
    case BLEND_EQUATION_RGB: return integer(blend.eq_rgb);
    case BLEND_EQUATION_ALPHA: return integer(blend.eq_alpha);
    case LOGIC_OP_MODE: return integer(s.ops.logic_mode);
    case BLEND_COLOR: return put(Kind::kNormalized, {blend.color.r, blend.color.g, blend.color.b, blend.color.a});
    case COLOR_CLEAR_VALUE: return put(Kind::kNormalized, {s.clear_color[0], s.clear_color[1], s.clear_color[2], s.clear_color[3]});
    case COLOR_WRITEMASK: {  // draw buffer 0's
      bool m[4];
      s.ops.Mask(0, m);
      return put(Kind::kBool, {double(m[0]), double(m[1]), double(m[2]), double(m[3])});
    }
    case CLAMP_READ_COLOR: return integer(s.clamp_read_color);
    case MAX_SERVER_WAIT_TIMEOUT: return integer(0);  // WaitSync never waits
    case UNPACK_ALIGNMENT: return integer(s.unpack.alignment);
    case UNPACK_ROW_LENGTH: return integer(s.unpack.row_length);
    case UNPACK_IMAGE_HEIGHT: return integer(s.unpack.image_height);
    case UNPACK_SKIP_PIXELS: return integer(s.unpack.skip_pixels);
    case UNPACK_SKIP_ROWS: return integer(s.unpack.skip_rows);
    case UNPACK_SKIP_IMAGES: return integer(s.unpack.skip_images);
    case UNPACK_SWAP_BYTES: return boolean(s.unpack.swap_bytes);
    case UNPACK_LSB_FIRST: return boolean(s.unpack_lsb_first);
    case PACK_ALIGNMENT: return integer(s.pack.alignment);
    case PACK_ROW_LENGTH: return integer(s.pack.row_length);
    case PACK_IMAGE_HEIGHT: return integer(s.pack.image_height);
    case PACK_SKIP_PIXELS: return integer(s.pack.skip_pixels);
    case PACK_SKIP_ROWS: return integer(s.pack.skip_rows);
    case PACK_SKIP_IMAGES: return integer(s.pack.skip_images);
    case PACK_SWAP_BYTES: return boolean(s.pack.swap_bytes);
    case PACK_LSB_FIRST: return boolean(s.pack_lsb_first);
    // Limits.
    case MAX_VERTEX_ATTRIBS: return integer(kMaxVertexAttribs);
    case MAX_TEXTURE_SIZE:
    case MAX_CUBE_MAP_TEXTURE_SIZE: return integer(kMaxTextureSize);
    case MAX_3D_TEXTURE_SIZE: return integer(kMax3DTextureSize);
    case MAX_ARRAY_TEXTURE_LAYERS: return integer(kMaxArrayTextureLayers);
    case MAX_TEXTURE_BUFFER_SIZE: return integer(kMaxTextureBufferSize);
    case MAX_TEXTURE_IMAGE_UNITS:
    case MAX_VERTEX_TEXTURE_IMAGE_UNITS:
    case MAX_COMBINED_TEXTURE_IMAGE_UNITS: return integer(kMaxTextureUnits);
    case MAX_DRAW_BUFFERS:
    case MAX_COLOR_ATTACHMENTS: return integer(kMaxColorOutputs);
    case MAX_SAMPLES:
    case MAX_COLOR_TEXTURE_SAMPLES:
    case MAX_DEPTH_TEXTURE_SAMPLES: return integer(detail::kMaxSamples);
    case MAX_INTEGER_SAMPLES: return integer(kMaxIntegerSamples);
    case MAX_SAMPLE_MASK_WORDS: return integer(1);
    case SAMPLE_COVERAGE_VALUE: return put(Kind::kFloat, {s.ops.multisample.coverage_value});
    case SAMPLE_COVERAGE_INVERT: return boolean(s.ops.multisample.coverage_invert);
    case MIN_SAMPLE_SHADING_VALUE: return put(Kind::kFloat, {s.ops.multisample.min_sample_shading});
    case SAMPLE_MASK_VALUE: return integer(std::int32_t(s.ops.multisample.mask));  // the bits as a GLint (all: -1)
    case SAMPLES:
    case SAMPLE_BUFFERS: {  // of the draw framebuffer (an incomplete one reports 0)
      int samples = s.fb.samples;
      if (s.draw_fbo)
        samples = FramebufferStatus(*s.draw_fbo) == FRAMEBUFFER_COMPLETE ? FramebufferTarget(*s.draw_fbo).samples : 1;
      return integer(pname == SAMPLES ? (samples > 1 ? samples : 0) : (samples > 1 ? 1 : 0));
    }
    case MAX_TEXTURE_MAX_ANISOTROPY: return put(Kind::kFloat, {double(detail::kMaxAnisotropy)});
    case MAX_RENDERBUFFER_SIZE: return integer(kMaxFramebufferSize);
    case NUM_COMPRESSED_TEXTURE_FORMATS: return integer(4);
    case COMPRESSED_TEXTURE_FORMATS: {
      const Enum* f = detail::kListedCompressedFormats;
      return put(Kind::kInt, {double(f[0]), double(f[1]), double(f[2]), double(f[3])});
    }
    case MAX_VIEWPORT_DIMS: return put(Kind::kInt, {double(kMaxFramebufferSize), double(kMaxFramebufferSize)});
    case MAX_VARYING_COMPONENTS: return integer(kMaxVaryingFloats);
    case MAX_GEOMETRY_INPUT_COMPONENTS:
    case MAX_GEOMETRY_OUTPUT_COMPONENTS: return integer(kMaxVaryingFloats);
    case MAX_GEOMETRY_OUTPUT_VERTICES: return integer(kMaxGeometryOutputVertices);
    case MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS: return integer(kMaxGeometryTotalOutputFloats);
    case MAX_GEOMETRY_SHADER_INVOCATIONS: return integer(kMaxGeometryInvocations);
    case MAX_ELEMENTS_VERTICES:
    case MAX_ELEMENTS_INDICES: return integer(detail::kDrawChunk);  // larger draws work, in pieces
    case POINT_SIZE_RANGE: return put(Kind::kFloat, {1.0, double(detail::kMaxPointSize)});
    case ALIASED_LINE_WIDTH_RANGE: return put(Kind::kFloat, {1.0, double(detail::kMaxLineWidth)});
    case SUBPIXEL_BITS: return integer(8);  // vertices snap to 1/256 pixel
    case MAJOR_VERSION: return integer(3);
    case MINOR_VERSION: return integer(3);
    case NUM_EXTENSIONS: return integer(0);
    case CONTEXT_PROFILE_MASK: return integer(1);  // CONTEXT_CORE_PROFILE_BIT
    default: return false;
  }
}

// The indexed state `pname` at `index` (GetBooleani_v and its kin): BLEND and COLOR_WRITEMASK of draw buffer
// index, SAMPLE_MASK_VALUE of mask word index (one word), TRANSFORM_FEEDBACK_BUFFER_BINDING, _START and _SIZE of
// the bound transform feedback object's binding index. False with the error set: INVALID_ENUM for another name,
// INVALID_VALUE for an index past the name's last.
bool QueryIndexed(ContextState& s, const char* what, Enum pname, std::uint32_t index, StateValue& out) {
  using Kind = StateValue::Kind;
  const bool feedback = pname == TRANSFORM_FEEDBACK_BUFFER_BINDING || pname == TRANSFORM_FEEDBACK_BUFFER_START ||
                        pname == TRANSFORM_FEEDBACK_BUFFER_SIZE;
  const std::uint32_t count = pname == SAMPLE_MASK_VALUE ? 1u
                              : feedback                 ? std::uint32_t(kMaxFeedbackBuffers)
                                                         : std::uint32_t(kMaxColorOutputs);
  if (pname != BLEND && pname != COLOR_WRITEMASK && pname != SAMPLE_MASK_VALUE && !feedback) return s.SetError(INVALID_ENUM, what, "target must be BLEND, COLOR_WRITEMASK, SAMPLE_MASK_VALUE or TRANSFORM_FEEDBACK_BUFFER_BINDING, _START or _SIZE (the indexed state softgl keeps)"), false;
  if (index >= count) return s.SetError(INVALID_VALUE, what, "index is past the last of the state's values (a draw buffer, mask word 0, or a transform feedback binding)"), false;
  out = StateValue{};
  if (feedback) {
    const FeedbackBinding& b = s.feedback->binding[index];
    out.kind = Kind::kInt;
    out.v[out.count++] = pname == TRANSFORM_FEEDBACK_BUFFER_BINDING ? double(IdOf(s.buffers, b.buffer.get()))
                         : pname == TRANSFORM_FEEDBACK_BUFFER_START ? double(b.offset)
                                                                    : double(b.size);
  } else if (pname == SAMPLE_MASK_VALUE) {
    out.kind = Kind::kInt;
    out.v[out.count++] = double(std::int32_t(s.ops.multisample.mask));  // the bits as a GLint, as GetIntegerv
  } else if (pname == BLEND) {
    out.kind = Kind::kBool;
    out.v[out.count++] = s.ops.BlendEnabled(int(index)) ? 1.0 : 0.0;
  } else {
    out.kind = Kind::kBool;
    for (int c = 0; c < 4; ++c) out.v[out.count++] = s.ops.Writes(int(index), c) ? 1.0 : 0.0;
  }
  return true;
}

bool Query(ContextState& s, const char* what, Enum pname, StateValue& out) {
  if (QueryState(s, pname, out)) return true;
  s.SetError(INVALID_ENUM, what, "not a state name the Get calls know");
  return false;
}

// OpenGL 4.6, section 2.2.2: a normalized value c (a colour or depth) maps linearly onto the integers,
// clamp(c, -1, 1) * (2^31 - 1) truncated toward 0 (Mesa's conversion: 0 stays 0, 1 is the largest int); other
// values round to the nearest integer.
std::int64_t ToInteger(const StateValue& v, int i) {
  const double d = v.v[i];
  if (std::isnan(d)) return 0;  // (a colour or value set to NaN: std::clamp would pass it on to the conversion)
  if (v.kind == StateValue::Kind::kNormalized) return std::int64_t(std::clamp(d, -1.0, 1.0) * 2147483647.0);
  return std::llround(std::clamp(d, -9.2e18, 9.2e18));
}

}  // namespace

void Context::GetIntegerv(Enum pname, int* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = int(std::clamp<std::int64_t>(ToInteger(v, i), INT32_MIN, INT32_MAX));
}

void Context::GetInteger64v(Enum pname, std::int64_t* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = ToInteger(v, i);
}

void Context::GetFloatv(Enum pname, float* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = float(v.v[i]);
}

void Context::GetDoublev(Enum pname, double* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = v.v[i];
}

void Context::GetBooleanv(Enum pname, bool* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = v.v[i] != 0.0;
}

void Context::GetBooleani_v(Enum target, std::uint32_t index, bool* data) const {
  StateValue v;
  if (!QueryIndexed(*state_, __func__, target, index, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = v.v[i] != 0.0;
}

void Context::GetIntegeri_v(Enum target, std::uint32_t index, int* data) const {
  StateValue v;
  if (!QueryIndexed(*state_, __func__, target, index, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = int(std::clamp<std::int64_t>(ToInteger(v, i), INT32_MIN, INT32_MAX));
}

void Context::GetInteger64i_v(Enum target, std::uint32_t index, std::int64_t* data) const {
  StateValue v;
  if (!QueryIndexed(*state_, __func__, target, index, v) || !NotNull(*state_, __func__, data, "data")) return;
  for (int i = 0; i < v.count; ++i) data[i] = ToInteger(v, i);
}

const char* Context::GetString(Enum name) const {
  switch (name) {
    case VENDOR: return "softgl";
    case RENDERER: return "softgl (software rasterizer)";
    case VERSION: return "3.3 softgl " SOFTGL_VERSION_STRING;
    case SHADING_LANGUAGE_VERSION: return "none (shaders are C++ classes)";
    default: return state_->SetError(INVALID_ENUM, __func__, "name must be VENDOR, RENDERER, VERSION or SHADING_LANGUAGE_VERSION"), nullptr;
  }
}

// ---- Query objects ---------------------------------------------------------------------------------------------

std::uint32_t Context::GenQuery() {
  return NewId(state_->queries, state_->next_query, [] { return std::make_unique<QueryObject>(); });
}

void Context::GenQueries(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenQuery(); });
}

void Context::DeleteQueries(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteQuery(id); });
}

void Context::DeleteQuery(std::uint32_t id) {
  auto& s = *state_;
  auto it = s.queries.find(id);
  if (it == s.queries.end()) return;
  for (std::uint32_t& active : s.active_query)  // an active query ends as it is deleted
    if (active == id) active = 0;
  s.queries.erase(it);  // recorded draws keep its counter alive until they are rendered
}

bool Context::IsQuery(std::uint32_t id) const { return state_->queries.count(id) != 0; }

void Context::BeginQuery(Enum target, std::uint32_t id) {
  auto& s = *state_;
  const int slot = QuerySlot(target);
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED, TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN or TIME_ELAPSED");
  if (s.active_query[slot]) return s.SetError(INVALID_OPERATION, __func__, "a query is already active on target");
  if (slot < 2 && s.active_query[1 - slot]) return s.SetError(INVALID_OPERATION, __func__, "an occlusion query of the other kind is active (one occlusion query at a time)");
  auto it = s.queries.find(id);
  if (it == s.queries.end()) return s.SetError(INVALID_OPERATION, __func__, "not a query id made by GenQuery (or it was deleted)");
  QueryObject& q = *it->second;
  if (q.active) return s.SetError(INVALID_OPERATION, __func__, "the query is active on another target");
  if (q.target != 0 && q.target != target) return s.SetError(INVALID_OPERATION, __func__, "the query was begun with another target");
  q.target = target;
  q.active = true;
  s.active_query[slot] = id;
  switch (slot) {
    case 0:
    case 1: q.counter = std::make_shared<detail::OcclusionCounter>(); break;  // draws of earlier runs keep theirs
    case 2:
    case 4: q.count = 0; break;
    default:  // the time of the work between BeginQuery and EndQuery, rendering included
      s.Sync(__func__);
      q.start = std::chrono::steady_clock::now();
      break;
  }
}

void Context::EndQuery(Enum target) {
  auto& s = *state_;
  const int slot = QuerySlot(target);
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED, TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN or TIME_ELAPSED");
  if (!s.active_query[slot]) return s.SetError(INVALID_OPERATION, __func__, "no query is active on target");
  QueryObject& q = *s.queries.at(s.active_query[slot]);
  s.active_query[slot] = 0;
  q.active = false;
  q.end_mark = s.WorkMark();
  if (slot == 3) {
    s.Sync(__func__);
    q.elapsed_ns = std::uint64_t(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - q.start).count());
  }
}

void Context::QueryCounter(std::uint32_t id, Enum target) {
  auto& s = *state_;
  if (target != TIMESTAMP) return s.SetError(INVALID_ENUM, __func__, "target must be TIMESTAMP");
  auto it = s.queries.find(id);
  if (it == s.queries.end()) return s.SetError(INVALID_OPERATION, __func__, "not a query id made by GenQuery (or it was deleted)");
  QueryObject& q = *it->second;
  if (q.active) return s.SetError(INVALID_OPERATION, __func__, "the query is active");
  if (q.target != 0 && q.target != TIMESTAMP) return s.SetError(INVALID_OPERATION, __func__, "the query was begun with another target");
  q.target = TIMESTAMP;
  s.Sync(__func__);  // the time when everything before it has been rendered
  q.elapsed_ns = TimestampNs();
}

void Context::GetQueryiv(Enum target, Enum pname, int* params) const {
  auto& s = *state_;
  if (target == TIMESTAMP) {  // (it has a counter, never an active query)
    if (pname != QUERY_COUNTER_BITS) return s.SetError(INVALID_ENUM, __func__, "TIMESTAMP takes QUERY_COUNTER_BITS only");
    if (NotNull(s, __func__, params, "params")) *params = 64;
    return;
  }
  const int slot = QuerySlot(target);
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED, TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN or TIME_ELAPSED");
  if (pname != CURRENT_QUERY && pname != QUERY_COUNTER_BITS) return s.SetError(INVALID_ENUM, __func__, "pname must be CURRENT_QUERY or QUERY_COUNTER_BITS");
  if (NotNull(s, __func__, params, "params")) *params = pname == CURRENT_QUERY ? int(s.active_query[slot]) : 64;
}

namespace {

// QUERY_RESULT or QUERY_RESULT_AVAILABLE of query `id`, or false with the error set. Results are made available by
// rendering what was recorded: asking for one renders the recorded draws first.
bool QueryResult(ContextState& s, const char* what, std::uint32_t id, Enum pname, std::uint64_t& out) {
  if (pname != QUERY_RESULT && pname != QUERY_RESULT_AVAILABLE) return s.SetError(INVALID_ENUM, what, "pname must be QUERY_RESULT or QUERY_RESULT_AVAILABLE"), false;
  auto it = s.queries.find(id);
  if (it == s.queries.end() || it->second->target == 0) return s.SetError(INVALID_OPERATION, what, "not a query that has been begun"), false;
  const QueryObject& q = *it->second;
  if (q.active) return s.SetError(INVALID_OPERATION, what, "the query is active"), false;
  s.Sync(what);
  if (pname == QUERY_RESULT_AVAILABLE) return out = 1, true;
  switch (QuerySlot(q.target)) {
    case 0: out = q.counter ? q.counter->passed.load() : 0; break;
    case 1: out = q.counter && q.counter->passed.load() != 0; break;
    case 2:
    case 4: out = q.count; break;
    default: out = q.elapsed_ns; break;
  }
  return true;
}

}  // namespace

// ---- Conditional rendering ----------------------------------------------------------------------------------

void Context::BeginConditionalRender(std::uint32_t id, Enum mode) {
  auto& s = *state_;
  if (mode != QUERY_WAIT && mode != QUERY_NO_WAIT && mode != QUERY_BY_REGION_WAIT && mode != QUERY_BY_REGION_NO_WAIT)
    return s.SetError(INVALID_ENUM, __func__, "mode must be QUERY_WAIT, QUERY_NO_WAIT, QUERY_BY_REGION_WAIT or QUERY_BY_REGION_NO_WAIT");
  auto it = s.queries.find(id);
  if (it == s.queries.end()) return s.SetError(INVALID_VALUE, __func__, "not a query id made by GenQuery (or it was deleted)");
  if (s.condition_query) return s.SetError(INVALID_OPERATION, __func__, "conditional rendering is already on");
  const QueryObject& q = *it->second;
  if (q.target != SAMPLES_PASSED && q.target != ANY_SAMPLES_PASSED) return s.SetError(INVALID_OPERATION, __func__, "the query is not an occlusion query (SAMPLES_PASSED or ANY_SAMPLES_PASSED) that has been begun");
  if (q.active) return s.SetError(INVALID_OPERATION, __func__, "the query is active");
  const bool wait = mode == QUERY_WAIT || mode == QUERY_BY_REGION_WAIT;
  if (wait) s.Sync(__func__);
  s.condition_query = id;
  // Without waiting, a result still waiting for its draws to be rendered draws everything (OpenGL allows it).
  s.condition_discards = s.WorkDone(q.end_mark) && (!q.counter || q.counter->passed.load() == 0);
}

void Context::EndConditionalRender() {
  auto& s = *state_;
  if (!s.condition_query) return s.SetError(INVALID_OPERATION, __func__, "conditional rendering is not on");
  s.condition_query = 0;
  s.condition_discards = false;
}

// ---- Sync objects ------------------------------------------------------------------------------------------------

namespace {

// The fence behind handle `sync`, or null (the handle is only compared, never read through).
const SyncObject* FindSync(const ContextState& s, Sync sync) {
  auto it = s.syncs.find(sync);
  return it == s.syncs.end() ? nullptr : it->second.get();
}

}  // namespace

Sync Context::FenceSync(Enum condition, Bitfield flags) {
  auto& s = *state_;
  if (condition != SYNC_GPU_COMMANDS_COMPLETE) return s.SetError(INVALID_ENUM, __func__, "condition must be SYNC_GPU_COMMANDS_COMPLETE"), nullptr;
  if (flags != 0) return s.SetError(INVALID_VALUE, __func__, "flags must be 0"), nullptr;
  try {
    auto fence = std::make_unique<SyncObject>();
    fence->mark = s.WorkMark();
    SyncObject* handle = fence.get();
    s.syncs.emplace(handle, std::move(fence));
    return handle;
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory"), nullptr;
  }
}

bool Context::IsSync(Sync sync) const { return FindSync(*state_, sync) != nullptr; }

void Context::DeleteSync(Sync sync) {
  auto& s = *state_;
  if (sync == nullptr) return;
  if (s.syncs.erase(sync) == 0) s.SetError(INVALID_VALUE, __func__, "not a fence made by FenceSync (or it was deleted)");
}

Enum Context::ClientWaitSync(Sync sync, Bitfield flags, std::uint64_t timeout) {
  auto& s = *state_;
  const SyncObject* fence = FindSync(s, sync);
  if (!fence) return s.SetError(INVALID_VALUE, __func__, "not a fence made by FenceSync (or it was deleted)"), WAIT_FAILED;
  if (flags & ~SYNC_FLUSH_COMMANDS_BIT) return s.SetError(INVALID_VALUE, __func__, "flags may only have SYNC_FLUSH_COMMANDS_BIT"), WAIT_FAILED;
  if (s.WorkDone(fence->mark)) return ALREADY_SIGNALED;
  if (timeout == 0) {
    if (flags & SYNC_FLUSH_COMMANDS_BIT) s.Sync(__func__);  // as Flush: the next wait finds it signalled
    return TIMEOUT_EXPIRED;
  }
  s.Sync(__func__);
  return CONDITION_SATISFIED;
}

void Context::WaitSync(Sync sync, Bitfield flags, std::uint64_t timeout) {
  auto& s = *state_;
  if (!FindSync(s, sync)) return s.SetError(INVALID_VALUE, __func__, "not a fence made by FenceSync (or it was deleted)");
  if (flags != 0) return s.SetError(INVALID_VALUE, __func__, "flags must be 0");
  if (timeout != TIMEOUT_IGNORED) return s.SetError(INVALID_VALUE, __func__, "timeout must be TIMEOUT_IGNORED");
}

void Context::GetSynciv(Sync sync, Enum pname, int bufSize, int* length, int* values) const {
  auto& s = *state_;
  const SyncObject* fence = FindSync(s, sync);
  if (!fence) return s.SetError(INVALID_VALUE, __func__, "not a fence made by FenceSync (or it was deleted)");
  int value = 0;
  switch (pname) {
    case OBJECT_TYPE: value = int(SYNC_FENCE); break;
    case SYNC_STATUS: value = int(s.WorkDone(fence->mark) ? SIGNALED : UNSIGNALED); break;
    case SYNC_CONDITION: value = int(SYNC_GPU_COMMANDS_COMPLETE); break;
    case SYNC_FLAGS: value = 0; break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname must be OBJECT_TYPE, SYNC_STATUS, SYNC_CONDITION or SYNC_FLAGS");
  }
  if (bufSize < 0) return s.SetError(INVALID_VALUE, __func__, "bufSize is negative");
  if (bufSize > 0) {
    if (!NotNull(s, __func__, values, "values")) return;
    values[0] = value;
  }
  if (length) *length = bufSize > 0 ? 1 : 0;
}

void Context::GetQueryObjectiv(std::uint32_t id, Enum pname, int* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && NotNull(*state_, __func__, params, "params")) *params = int(std::min<std::uint64_t>(v, INT32_MAX));
}

void Context::GetQueryObjectuiv(std::uint32_t id, Enum pname, std::uint32_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && NotNull(*state_, __func__, params, "params")) *params = std::uint32_t(std::min<std::uint64_t>(v, UINT32_MAX));
}

void Context::GetQueryObjecti64v(std::uint32_t id, Enum pname, std::int64_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && NotNull(*state_, __func__, params, "params")) *params = std::int64_t(std::min<std::uint64_t>(v, INT64_MAX));
}

void Context::GetQueryObjectui64v(std::uint32_t id, Enum pname, std::uint64_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && NotNull(*state_, __func__, params, "params")) *params = v;
}

}  // namespace softgl

// context.cpp — the Context itself (construction, errors, Finish) and its fixed-function state: shader binding,
// viewport, enables, rasterization state, the per-fragment operations' state and Clear.
//
// Every entry point checks its arguments first, records the first error and returns without changing anything
// when one fails. The other families of entry points live in context_*.cpp beside this file.
#include "context_state.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <utility>

namespace softgl {

Context::Context(int width, int height) : Context(width, height, Options{}) {}

Context::Context(int width, int height, const Options& options) : state_(std::make_unique<ContextState>()) {
  state_->pool = std::make_unique<detail::WorkerPool>(options.threads > 0 ? options.threads
                                                                          : detail::DefaultThreadCount());
  for (auto& a : state_->current_attrib) a = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);  // (as floats: current_integer 0)
  if (width < 0 || height < 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize) {
    state_->SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
    width = height = 0;
  }
  if (options.color_format == RGB565) {
    state_->fb.layout = detail::TexelLayout::kUnorm565;
  } else if (options.color_format == SRGB8_ALPHA8) {
    state_->fb.srgb = true;
  } else if (options.color_format != RGBA8) {
    state_->SetError(INVALID_ENUM, __func__, "Options::color_format must be RGBA8, SRGB8_ALPHA8 or RGB565");
  }
  if (options.depth_format == DEPTH_COMPONENT16) {
    state_->fb.depth16 = true;
  } else if (options.depth_format != DEPTH_COMPONENT32F) {
    state_->SetError(INVALID_ENUM, __func__, "Options::depth_format must be DEPTH_COMPONENT32F or DEPTH_COMPONENT16");
  }
  if (options.samples < 0 || options.samples > detail::kMaxSamples)
    state_->SetError(INVALID_VALUE, __func__, "Options::samples must be 0 to 8");
  else
    state_->fb.samples = detail::SupportedSamples(options.samples <= 1 ? 0 : options.samples);
  if (!state_->fb.Allocate(width, height)) {
    state_->SetError(OUT_OF_MEMORY, __func__, "out of memory");
    width = height = 0;
  }
  state_->viewport[2] = state_->scissor[2] = width;
  state_->viewport[3] = state_->scissor[3] = height;
}

Context::~Context() = default;

int Context::Width() const { return state_->fb.width; }
int Context::Height() const { return state_->fb.height; }
int Context::Threads() const { return state_->pool->Threads(); }

void Context::Finish() { state_->Sync(__func__); }

void Context::Flush() { state_->Sync(__func__); }

void Context::CountTilePrimitives(bool on) {
  ContextState& s = *state_;
  s.Sync(__func__);  // what was recorded before counts (or not) as it was asked when it was drawn
  s.tile_counts.clear();
  s.tile_count_grid = {0, 0};
  s.frame.CountTilePrimitives(on ? &s.tile_counts : nullptr, on ? &s.tile_count_grid : nullptr);
}

std::vector<std::uint32_t> Context::TilePrimitiveCounts(int* columns, int* rows) {
  ContextState& s = *state_;
  s.Sync(__func__);
  if (columns) *columns = s.tile_count_grid.x;
  if (rows) *rows = s.tile_count_grid.y;
  return s.tile_counts;
}

void Context::UseHierarchicalDepth(bool on) {
  ContextState& s = *state_;
  s.Sync(__func__);  // what was recorded before renders as it was asked
  s.frame.UseHierarchicalDepth(on);
}

Context::HierarchicalDepthCounts Context::TakeHierarchicalDepthCounts() {
  ContextState& s = *state_;
  s.Sync(__func__);
  HierarchicalDepthCounts c;
  for (detail::TileScratch& t : s.scratch.tiles) {
    detail::HierarchicalDepth& h = t.depth_bounds;
    c.triangles_tested += std::exchange(h.triangles_tested, 0);
    c.triangles_hidden += std::exchange(h.triangles_hidden, 0);
    c.regions_tested += std::exchange(h.regions_tested, 0);
    c.regions_hidden += std::exchange(h.regions_hidden, 0);
  }
  return c;
}

void Context::DebugMessageCallback(DebugCallback callback) { state_->debug_callback = std::move(callback); }

Enum Context::GetError() {
  const Enum e = state_->error;
  state_->error = NO_ERROR;
  return e;
}


// ---- Shaders and fixed-function state ------------------------------------------------------------------------

void Context::UseProgram(const Program& program) {
  if (program.VaryingFloats() < 0 || program.VaryingFloats() > kMaxVaryingFloats)
    return state_->SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (state_->feedback->Recording()) return state_->SetError(INVALID_OPERATION, __func__, "transform feedback is active (and not paused)");
  state_->program = &program;
}

void Context::UseProgram(std::nullptr_t) {
  if (state_->feedback->Recording()) return state_->SetError(INVALID_OPERATION, __func__, "transform feedback is active (and not paused)");
  state_->program = nullptr;
}

void Context::Viewport(int x, int y, int width, int height) {
  auto& s = *state_;
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE, __func__, "width or height is negative");
  s.viewport[0] = std::clamp(x, -32768, 32767);
  s.viewport[1] = std::clamp(y, -32768, 32767);
  s.viewport[2] = std::min(width, kMaxFramebufferSize);
  s.viewport[3] = std::min(height, kMaxFramebufferSize);
}

void Context::DepthRange(double n, double f) {
  // NaN clamps to 0 here, never reaching the pipeline.
  state_->depth_near = n >= 0.0 ? std::min(n, 1.0) : 0.0;
  state_->depth_far = f >= 0.0 ? std::min(f, 1.0) : 0.0;
}

bool* CapFlag(ContextState& s, Enum cap) {
  switch (cap) {
    case CULL_FACE: return &s.primitive.cull_enabled;
    case DEPTH_TEST: return &s.ops.depth_test;
    case PROGRAM_POINT_SIZE: return &s.primitive.program_point_size;
    case SCISSOR_TEST: return &s.scissor_enabled;
    case FRAMEBUFFER_SRGB: return &s.framebuffer_srgb;
    case STENCIL_TEST: return &s.ops.stencil_test;
    case COLOR_LOGIC_OP: return &s.ops.logic_op;
    case POLYGON_OFFSET_FILL: return &s.primitive.offset_fill;
    case POLYGON_OFFSET_LINE: return &s.primitive.offset_line;
    case POLYGON_OFFSET_POINT: return &s.primitive.offset_point;
    case PRIMITIVE_RESTART: return &s.primitive_restart;
    case PRIMITIVE_RESTART_FIXED_INDEX: return &s.primitive_restart_fixed;
    case MULTISAMPLE: return &s.ops.multisample.multisample;
    case SAMPLE_ALPHA_TO_COVERAGE: return &s.ops.multisample.alpha_to_coverage;
    case SAMPLE_ALPHA_TO_ONE: return &s.ops.multisample.alpha_to_one;
    case SAMPLE_COVERAGE: return &s.ops.multisample.sample_coverage;
    case SAMPLE_MASK: return &s.ops.multisample.sample_mask;
    case SAMPLE_SHADING: return &s.ops.multisample.sample_shading;
    case RASTERIZER_DISCARD: return &s.rasterizer_discard;
    default: return nullptr;
  }
}

void Context::Enable(Enum cap) {
  if (cap == BLEND) return void(state_->ops.blend_buffers = 0xFF);  // every draw buffer's
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM, __func__, "not a capability Enable/Disable/IsEnabled knows");
  *flag = true;
}

void Context::Disable(Enum cap) {
  if (cap == BLEND) return void(state_->ops.blend_buffers = 0);
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM, __func__, "not a capability Enable/Disable/IsEnabled knows");
  *flag = false;
}

bool Context::IsEnabled(Enum cap) {
  if (cap == BLEND) return state_->ops.BlendEnabled(0);  // (draw buffer 0's, as IsEnabledi(BLEND, 0))
  bool* flag = CapFlag(*state_, cap);
  if (!flag) {
    state_->SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
    return false;
  }
  return *flag;
}

namespace {

// Enablei, Disablei and IsEnabledi's checks: cap BLEND (else INVALID_ENUM), index a draw buffer (else
// INVALID_VALUE). False with the error set.
bool IndexedCap(ContextState& s, const char* what, Enum cap, std::uint32_t index) {
  if (cap != BLEND) return s.SetError(INVALID_ENUM, what, "cap must be BLEND (the one capability with a value per draw buffer)"), false;
  if (index >= std::uint32_t(kMaxColorOutputs)) return s.SetError(INVALID_VALUE, what, "index is not a draw buffer (0 to MAX_DRAW_BUFFERS - 1)"), false;
  return true;
}

}  // namespace

void Context::Enablei(Enum cap, std::uint32_t index) {
  if (IndexedCap(*state_, __func__, cap, index)) state_->ops.blend_buffers |= std::uint8_t(1u << index);
}

void Context::Disablei(Enum cap, std::uint32_t index) {
  if (IndexedCap(*state_, __func__, cap, index)) state_->ops.blend_buffers &= std::uint8_t(~(1u << index));
}

bool Context::IsEnabledi(Enum cap, std::uint32_t index) {
  return IndexedCap(*state_, __func__, cap, index) && state_->ops.BlendEnabled(int(index));
}

void Context::PrimitiveRestartIndex(std::uint32_t index) { state_->restart_index = index; }

void Context::SampleCoverage(float value, bool invert) {
  state_->ops.multisample.coverage_value = value >= 0.0f ? std::min(value, 1.0f) : 0.0f;  // NaN as 0
  state_->ops.multisample.coverage_invert = invert;
}

void Context::MinSampleShading(float value) {
  state_->ops.multisample.min_sample_shading = value >= 0.0f ? std::min(value, 1.0f) : 0.0f;  // NaN as 0
}

void Context::SampleMaski(std::uint32_t index, Bitfield mask) {
  if (index >= 1) return state_->SetError(INVALID_VALUE, __func__, "index must be below MAX_SAMPLE_MASK_WORDS (1)");
  state_->ops.multisample.mask = mask;
}

void Context::GetMultisamplefv(Enum pname, std::uint32_t index, float* val) {
  auto& s = *state_;
  if (pname != SAMPLE_POSITION) return s.SetError(INVALID_ENUM, __func__, "pname must be SAMPLE_POSITION");
  const int samples = s.draw_fbo ? FramebufferTarget(*s.draw_fbo).samples : s.fb.samples;
  if (index >= std::uint32_t(samples)) return s.SetError(INVALID_VALUE, __func__, "index is not below the draw framebuffer's sample count");
  const std::uint8_t* p = detail::SamplePositions(samples)[index];
  if (NotNull(s, __func__, val, "val")) {
    val[0] = float(p[0]) / 16.0f;
    val[1] = float(p[1]) / 16.0f;
  }
}

void Context::CullFace(Enum mode) {
  if (mode != FRONT && mode != BACK && mode != FRONT_AND_BACK) return state_->SetError(INVALID_ENUM, __func__, "mode must be FRONT, BACK or FRONT_AND_BACK");
  state_->primitive.cull_face = mode;
}

void Context::FrontFace(Enum mode) {
  if (mode != CW && mode != CCW) return state_->SetError(INVALID_ENUM, __func__, "mode must be CW or CCW");
  state_->primitive.front_face = mode;
}

void Context::PolygonMode(Enum face, Enum mode) {
  if (face != FRONT_AND_BACK || (mode != POINT && mode != LINE && mode != FILL))
    return state_->SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
  state_->primitive.polygon_mode = mode;
}

void Context::LineWidth(float width) {
  if (!(width > 0.0f)) return state_->SetError(INVALID_VALUE, __func__, "width must be positive");
  state_->primitive.line_width = width;
}

void Context::PointSize(float size) {
  if (!(size > 0.0f)) return state_->SetError(INVALID_VALUE, __func__, "size must be positive");
  state_->primitive.point_size = size;
}

namespace {

// PointParameter's forms: `value` the first of the values given (an int or a float, exact as a double).
void SetPointParameter(ContextState& s, const char* what, Enum pname, const void* params, double value) {
  if (pname != POINT_SPRITE_COORD_ORIGIN && pname != POINT_FADE_THRESHOLD_SIZE) return s.SetError(INVALID_ENUM, what, "pname must be POINT_SPRITE_COORD_ORIGIN or POINT_FADE_THRESHOLD_SIZE");
  if (!NotNull(s, what, params, "params")) return;
  if (pname == POINT_FADE_THRESHOLD_SIZE) {
    if (!(value >= 0.0)) return s.SetError(INVALID_VALUE, what, "POINT_FADE_THRESHOLD_SIZE must be 0 or more");
    s.primitive.point_fade_threshold = float(value);
    return;
  }
  if (value != double(LOWER_LEFT) && value != double(UPPER_LEFT)) return s.SetError(INVALID_ENUM, what, "POINT_SPRITE_COORD_ORIGIN must be LOWER_LEFT or UPPER_LEFT");
  s.primitive.point_lower_left = value == double(LOWER_LEFT);
}

}  // namespace

void Context::PointParameterf(Enum pname, float param) { SetPointParameter(*state_, __func__, pname, &param, param); }

void Context::PointParameterfv(Enum pname, const float* params) {
  SetPointParameter(*state_, __func__, pname, params, params ? double(params[0]) : 0.0);
}

void Context::PointParameteri(Enum pname, int param) { SetPointParameter(*state_, __func__, pname, &param, param); }

void Context::PointParameteriv(Enum pname, const int* params) {
  SetPointParameter(*state_, __func__, pname, params, params ? double(params[0]) : 0.0);
}

void Context::ProvokingVertex(Enum mode) {
  if (mode != FIRST_VERTEX_CONVENTION && mode != LAST_VERTEX_CONVENTION)
    return state_->SetError(INVALID_ENUM, __func__, "mode must be FIRST_VERTEX_CONVENTION or LAST_VERTEX_CONVENTION");
  state_->primitive.provoking_first = mode == FIRST_VERTEX_CONVENTION;
}

void Context::DepthFunc(Enum func) {
  if (func < NEVER || func > ALWAYS) return state_->SetError(INVALID_ENUM, __func__, "not a comparison function");
  state_->ops.depth_func = func;
}

void Context::DepthMask(bool flag) { state_->ops.depth_write = flag; }

void Context::PolygonOffset(float factor, float units) {
  state_->primitive.offset_factor = factor;
  state_->primitive.offset_units = units;
}

// ---- Per-fragment operations ---------------------------------------------------------------------------------

namespace {

bool IsCompareFunc(Enum func) { return func >= NEVER && func <= ALWAYS; }

bool IsStencilOp(Enum op) {
  switch (op) {
    case KEEP:
    case ZERO:
    case REPLACE:
    case INCR:
    case DECR:
    case INVERT:
    case INCR_WRAP:
    case DECR_WRAP: return true;
    default: return false;
  }
}

bool IsBlendFactor(Enum f) {
  return f == ZERO || f == ONE || (f >= SRC_COLOR && f <= SRC_ALPHA_SATURATE) ||
         (f >= CONSTANT_COLOR && f <= ONE_MINUS_CONSTANT_ALPHA);
}

bool IsBlendEquation(Enum e) {
  return e == FUNC_ADD || e == FUNC_SUBTRACT || e == FUNC_REVERSE_SUBTRACT || e == MIN || e == MAX;
}

bool IsFace(Enum face) { return face == FRONT || face == BACK || face == FRONT_AND_BACK; }

// Applies `set` to the stencil state of the faces that `face` names.
template <class F>
void ForFaces(detail::FragmentOpsState& ops, Enum face, F&& set) {
  if (face != BACK) set(ops.front);
  if (face != FRONT) set(ops.back);
}

}  // namespace

void Context::Scissor(int x, int y, int width, int height) {
  auto& s = *state_;
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE, __func__, "width or height is negative");
  s.scissor[0] = x;
  s.scissor[1] = y;
  s.scissor[2] = width;
  s.scissor[3] = height;
}

void Context::StencilFunc(Enum func, int ref, std::uint32_t mask) { StencilFuncSeparate(FRONT_AND_BACK, func, ref, mask); }

void Context::StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) {
  if (!IsFace(face) || !IsCompareFunc(func)) return state_->SetError(INVALID_ENUM, __func__, "face must be FRONT, BACK or FRONT_AND_BACK and func a comparison function");
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) {
    f.func = func;
    f.ref = ref;
    f.value_mask = mask;
  });
}

void Context::StencilOp(Enum sfail, Enum dpfail, Enum dppass) { StencilOpSeparate(FRONT_AND_BACK, sfail, dpfail, dppass); }

void Context::StencilOpSeparate(Enum face, Enum sfail, Enum dpfail, Enum dppass) {
  if (!IsFace(face) || !IsStencilOp(sfail) || !IsStencilOp(dpfail) || !IsStencilOp(dppass))
    return state_->SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) {
    f.sfail = sfail;
    f.dpfail = dpfail;
    f.dppass = dppass;
  });
}

void Context::StencilMask(std::uint32_t mask) { StencilMaskSeparate(FRONT_AND_BACK, mask); }

void Context::StencilMaskSeparate(Enum face, std::uint32_t mask) {
  if (!IsFace(face)) return state_->SetError(INVALID_ENUM, __func__, "face must be FRONT, BACK or FRONT_AND_BACK");
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) { f.write_mask = mask; });
}

void Context::BlendFunc(Enum src, Enum dst) { BlendFuncSeparate(src, dst, src, dst); }

void Context::BlendFuncSeparate(Enum src_rgb, Enum dst_rgb, Enum src_alpha, Enum dst_alpha) {
  if (!IsBlendFactor(src_rgb) || !IsBlendFactor(dst_rgb) || !IsBlendFactor(src_alpha) || !IsBlendFactor(dst_alpha))
    return state_->SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
  auto& b = state_->ops.blend;
  b.src_rgb = src_rgb;
  b.dst_rgb = dst_rgb;
  b.src_alpha = src_alpha;
  b.dst_alpha = dst_alpha;
}

void Context::BlendEquation(Enum mode) { BlendEquationSeparate(mode, mode); }

void Context::BlendEquationSeparate(Enum mode_rgb, Enum mode_alpha) {
  if (!IsBlendEquation(mode_rgb) || !IsBlendEquation(mode_alpha)) return state_->SetError(INVALID_ENUM, __func__, "not a blend equation");
  state_->ops.blend.eq_rgb = mode_rgb;
  state_->ops.blend.eq_alpha = mode_alpha;
}

void Context::BlendColor(float r, float g, float b, float a) { state_->ops.blend.color = glm::vec4(r, g, b, a); }

void Context::LogicOp(Enum opcode) {
  if (opcode < CLEAR || opcode > SET) return state_->SetError(INVALID_ENUM, __func__, "opcode must be one of the sixteen logic operations, CLEAR to SET");
  state_->ops.logic_mode = opcode;
}

void Context::ColorMask(bool r, bool g, bool b, bool a) {
  for (std::uint8_t& m : state_->ops.color_masks) m = std::uint8_t(r | g << 1 | b << 2 | a << 3);
}

void Context::ColorMaski(std::uint32_t index, bool r, bool g, bool b, bool a) {
  if (index >= std::uint32_t(kMaxColorOutputs)) return state_->SetError(INVALID_VALUE, __func__, "index is not a draw buffer (0 to MAX_DRAW_BUFFERS - 1)");
  state_->ops.color_masks[index] = std::uint8_t(r | g << 1 | b << 2 | a << 3);
}

// ---- Clearing ------------------------------------------------------------------------------------------------

void Context::ClearColor(float r, float g, float b, float a) {
  const float c[4] = {r, g, b, a};
  for (int i = 0; i < 4; ++i) state_->clear_color[i] = c[i];
}

void Context::ClearDepth(double depth) { state_->clear_depth = depth >= 0.0 ? std::min(depth, 1.0) : 0.0; }

void Context::ClearStencil(int s) { state_->clear_stencil = s; }

namespace {
void RecordClear(ContextState& s, const detail::RenderTarget& target, const detail::ClearPacket& clear,
                 const char* what);
}  // namespace

void Context::Clear(Bitfield mask) {
  auto& s = *state_;
  if (mask & ~(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT)) return s.SetError(INVALID_VALUE, __func__, "mask has bits other than COLOR_, DEPTH_ and STENCIL_BUFFER_BIT");
  detail::RenderTarget target;
  if (!s.DrawTarget(target, true)) return;
  const detail::Rect area = s.ClearArea(target);
  if (area.Empty()) return;
  detail::ClearPacket clear;
  clear.area = area;
  clear.color = (mask & COLOR_BUFFER_BIT) != 0;
  clear.color_value = glm::vec4(s.clear_color[0], s.clear_color[1], s.clear_color[2], s.clear_color[3]);
  clear.depth = (mask & DEPTH_BUFFER_BIT) && s.ops.depth_write;
  clear.depth_value = float(s.clear_depth);
  clear.stencil = (mask & STENCIL_BUFFER_BIT) != 0;
  clear.stencil_value = std::uint8_t(s.clear_stencil & 0xFF);
  clear.stencil_mask = std::uint8_t(s.ops.front.write_mask);
  // Each draw buffer through its own colour mask: one packet per distinct mask (one, unless ColorMaski made them
  // differ), the depth and stencil with the first.
  // (An integer buffer is left as it is: OpenGL leaves Clear's result there undefined; ClearBufferiv and uiv clear
  // it. Mesa leaves it too.)
  std::uint32_t left = 0;
  for (int o = 0; o < kMaxColorOutputs && clear.color; ++o)
    if (!detail::IsIntegerLayout(target.color[o].layout)) left |= 1u << o;
  clear.color = left != 0;
  do {
    const int first = left ? std::countr_zero(left) : 0;
    const std::uint8_t m = s.ops.color_masks[first];
    clear.color_buffers = 0;
    for (int o = first; o < kMaxColorOutputs; ++o)
      if (((left >> o) & 1u) && s.ops.color_masks[o] == m) clear.color_buffers |= 1u << o;
    left &= ~clear.color_buffers;
    for (int c = 0; c < 4; ++c) clear.color_mask[c] = (m >> c) & 1u;
    RecordClear(s, target, clear, __func__);
    clear.depth = clear.stencil = false;
  } while (left);
}

namespace {

// The rest of every clear call: records `clear` (nothing when it clears nothing, under conditional rendering
// that discards, or with RASTERIZER_DISCARD enabled: OpenGL 4.6, section 14.1).
void RecordClear(ContextState& s, const detail::RenderTarget& target, const detail::ClearPacket& clear,
                 const char* what) {
  if ((!clear.color && !clear.depth && !clear.stencil) || s.condition_discards || s.rasterizer_discard) return;
  // A layered framebuffer object: every layer of each attachment (OpenGL 4.6, section 17.4.3), `target` being
  // layer 0's.
  s.RecordPending(what);  // the draws before it first
  const int layers = s.DrawLayers();
  for (int l = 0; l < layers; ++l) {
    const detail::RenderTarget t = l == 0 ? target : s.DrawLayer(l);
    if (!s.frame.Accepts(t)) s.Sync(what);
    try {
      s.frame.AddClear(t, clear);
    } catch (const std::bad_alloc&) {
      return s.SetError(OUT_OF_MEMORY, what, "out of memory");
    }
  }
}

// ClearBuffer*'s checks and the clear they make: `buffer` one of `accepted` (else INVALID_ENUM), `drawbuffer` a draw
// buffer of COLOR (0 to kMaxColorOutputs - 1) and 0 for the others (else INVALID_VALUE), a complete draw
// framebuffer. False, with the error recorded, where there is nothing to clear.
bool ClearBufferPacket(ContextState& s, const char* what, Enum buffer, int drawbuffer, std::initializer_list<Enum> accepted,
                       detail::RenderTarget& target, detail::ClearPacket& clear) {
  if (std::find(accepted.begin(), accepted.end(), buffer) == accepted.end())
    return s.SetError(INVALID_ENUM, what, "buffer is not one this call clears (COLOR, DEPTH, STENCIL or DEPTH_STENCIL, as the call's type allows)"), false;
  if (buffer == COLOR ? drawbuffer < 0 || drawbuffer >= kMaxColorOutputs : drawbuffer != 0)
    return s.SetError(INVALID_VALUE, what, buffer == COLOR ? "drawbuffer is not a draw buffer (0 to MAX_DRAW_BUFFERS - 1)" : "drawbuffer must be 0 for DEPTH, STENCIL and DEPTH_STENCIL"), false;
  if (!s.DrawTarget(target, true)) return false;
  clear.area = s.ClearArea(target);
  if (clear.area.Empty()) return false;
  const int o = buffer == COLOR ? drawbuffer : 0;
  for (int c = 0; c < 4; ++c) clear.color_mask[c] = s.ops.Writes(o, c);
  clear.color_buffers = std::uint32_t(1) << o;
  clear.stencil_mask = std::uint8_t(s.ops.front.write_mask);
  return true;
}

// ClearBufferiv's and uiv's colour for buffer `cb`: an integer buffer's integers as the floats' bits (stored
// clamped to its channels' range), another buffer's the numbers as floats (OpenGL leaves that case undefined).
template <class T>
glm::vec4 ClearValue(const detail::ColorBuffer& cb, const T* value) {
  if (!detail::IsIntegerLayout(cb.layout)) return glm::vec4(float(value[0]), float(value[1]), float(value[2]), float(value[3]));
  glm::vec4 bits;
  std::memcpy(&bits.x, value, 16);
  return bits;
}

}  // namespace

void Context::ClearBufferfv(Enum buffer, int drawbuffer, const float* value) {
  auto& s = *state_;
  detail::RenderTarget target;
  detail::ClearPacket clear;
  if (!ClearBufferPacket(s, __func__, buffer, drawbuffer, {COLOR, DEPTH}, target, clear) || !NotNull(s, __func__, value, "value")) return;
  if (buffer == COLOR) {
    clear.color = target.color[drawbuffer].Present();
    clear.color_value = glm::vec4(value[0], value[1], value[2], value[3]);
  } else {
    clear.depth = s.ops.depth_write && target.HasDepth();
    clear.depth_value = value[0] >= 0.0f ? std::min(value[0], 1.0f) : 0.0f;  // (NaN as 0)
  }
  RecordClear(s, target, clear, __func__);
}

void Context::ClearBufferiv(Enum buffer, int drawbuffer, const int* value) {
  auto& s = *state_;
  detail::RenderTarget target;
  detail::ClearPacket clear;
  if (!ClearBufferPacket(s, __func__, buffer, drawbuffer, {COLOR, STENCIL}, target, clear) || !NotNull(s, __func__, value, "value")) return;
  if (buffer == COLOR) {
    clear.color = target.color[drawbuffer].Present();
    clear.color_value = ClearValue(target.color[drawbuffer], value);
  } else {
    clear.stencil = target.stencil != nullptr;
    clear.stencil_value = std::uint8_t(value[0] & 0xFF);
  }
  RecordClear(s, target, clear, __func__);
}

void Context::ClearBufferuiv(Enum buffer, int drawbuffer, const std::uint32_t* value) {
  auto& s = *state_;
  detail::RenderTarget target;
  detail::ClearPacket clear;
  if (!ClearBufferPacket(s, __func__, buffer, drawbuffer, {COLOR}, target, clear) || !NotNull(s, __func__, value, "value")) return;
  clear.color = target.color[drawbuffer].Present();
  clear.color_value = ClearValue(target.color[drawbuffer], value);
  RecordClear(s, target, clear, __func__);
}

void Context::ClearBufferfi(Enum buffer, int drawbuffer, float depth, int stencil) {
  auto& s = *state_;
  detail::RenderTarget target;
  detail::ClearPacket clear;
  if (!ClearBufferPacket(s, __func__, buffer, drawbuffer, {DEPTH_STENCIL}, target, clear)) return;
  clear.depth = s.ops.depth_write && target.HasDepth();
  clear.depth_value = depth >= 0.0f ? std::min(depth, 1.0f) : 0.0f;
  clear.stencil = target.stencil != nullptr;
  clear.stencil_value = std::uint8_t(stencil & 0xFF);
  RecordClear(s, target, clear, __func__);
}

}  // namespace softgl

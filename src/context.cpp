// context.cpp — the API boundary: object tables, state, validation with OpenGL's error codes.
//
// Every entry point checks its arguments first, records the first error and returns without changing anything
// when one fails. Drawing resolves the bound objects into plain structs (FetchPlan, DrawState) and hands them to
// the pipeline.
#include <softgl/context.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <unordered_map>
#include <vector>

#include "framebuffer.h"
#include "pipeline.h"
#include "primitive_assembly.h"
#include "vertex_fetch.h"
#include "viewport.h"

namespace softgl {

namespace {

struct Buffer {
  std::vector<std::uint8_t> data;
};

struct AttribBinding {
  bool enabled = false;
  std::shared_ptr<Buffer> buffer;  // keeps a deleted buffer's store alive while referenced, as OpenGL does
  std::size_t offset = 0;
  int size = 4;
  Enum type = FLOAT;
  bool normalized = false;
  int stride = 0;
};

struct VertexArray {
  AttribBinding attrib[kMaxVertexAttribs];
  std::shared_ptr<Buffer> element_buffer;
};

bool IsUsage(Enum usage) { return usage >= 0x88E0 && usage <= 0x88EA && (usage & 3) != 3; }

}  // namespace

struct ContextState {
  Enum error = NO_ERROR;
  detail::Framebuffer fb;

  std::unordered_map<std::uint32_t, std::shared_ptr<Buffer>> buffers;
  std::uint32_t next_buffer = 1;
  std::unordered_map<std::uint32_t, std::unique_ptr<VertexArray>> arrays;
  std::uint32_t next_array = 1;

  std::shared_ptr<Buffer> array_buffer;
  VertexArray* vao = nullptr;
  std::uint32_t vao_id = 0;
  glm::vec4 current_attrib[kMaxVertexAttribs];
  const Program* program = nullptr;

  int viewport[4] = {0, 0, 0, 0};
  double depth_near = 0.0, depth_far = 1.0;
  bool cull_enabled = false;
  bool program_point_size = false;
  Enum cull_face = BACK;
  Enum front_face = CCW;
  Enum polygon_mode = FILL;
  float point_size = 1.0f;
  bool scissor_enabled = false;
  int scissor[4] = {0, 0, 0, 0};
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0.0f, offset_units = 0.0f;
  detail::FragmentOpsState ops;

  float clear_color[4] = {0, 0, 0, 0};
  float clear_depth = 1.0f;
  std::uint8_t clear_stencil = 0;

  detail::Scratch scratch;

  void SetError(Enum e) {
    if (error == NO_ERROR) error = e;
  }

  std::shared_ptr<Buffer>* BindingFor(Enum target) {
    if (target == ARRAY_BUFFER) return &array_buffer;
    if (target == ELEMENT_ARRAY_BUFFER && vao) return &vao->element_buffer;
    return nullptr;
  }

  // The framebuffer, cut to the scissor rectangle while the scissor test is enabled.
  detail::Rect ClearArea() const {
    detail::Rect r = fb.Bounds();
    if (!scissor_enabled) return r;
    const std::int64_t x1 = std::int64_t(scissor[0]) + scissor[2], y1 = std::int64_t(scissor[1]) + scissor[3];
    r.x0 = std::max(r.x0, scissor[0]);
    r.y0 = std::max(r.y0, scissor[1]);
    r.x1 = int(std::min<std::int64_t>(r.x1, x1));
    r.y1 = int(std::min<std::int64_t>(r.y1, y1));
    return r;
  }

  void Draw(const detail::DrawCall& call);
};

Context::Context(int width, int height) : state_(std::make_unique<ContextState>()) {
  for (auto& a : state_->current_attrib) a = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  if (width < 0 || height < 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize) {
    state_->SetError(INVALID_VALUE);
    width = height = 0;
  }
  if (!state_->fb.Allocate(width, height)) {
    state_->SetError(OUT_OF_MEMORY);
    width = height = 0;
  }
  state_->viewport[2] = state_->scissor[2] = width;
  state_->viewport[3] = state_->scissor[3] = height;
}

Context::~Context() = default;

int Context::Width() const { return state_->fb.width; }
int Context::Height() const { return state_->fb.height; }

Enum Context::GetError() {
  const Enum e = state_->error;
  state_->error = NO_ERROR;
  return e;
}

// ---- Buffers -------------------------------------------------------------------------------------------------

std::uint32_t Context::GenBuffer() {
  const std::uint32_t id = state_->next_buffer++;
  state_->buffers[id] = std::make_shared<Buffer>();
  return id;
}

void Context::GenBuffers(int n, std::uint32_t* ids) {
  if (n < 0) return state_->SetError(INVALID_VALUE);
  for (int i = 0; i < n; ++i) ids[i] = GenBuffer();
}

void Context::DeleteBuffer(std::uint32_t buffer) {
  auto& s = *state_;
  auto it = s.buffers.find(buffer);
  if (it == s.buffers.end()) return;
  const Buffer* dead = it->second.get();
  if (s.array_buffer.get() == dead) s.array_buffer.reset();
  if (s.vao) {  // only the bound vertex array forgets it (OpenGL 4.6, section 5.1.2)
    if (s.vao->element_buffer.get() == dead) s.vao->element_buffer.reset();
    for (auto& a : s.vao->attrib)
      if (a.buffer.get() == dead) a.buffer.reset();
  }
  s.buffers.erase(it);
}

bool Context::IsBuffer(std::uint32_t buffer) const { return state_->buffers.count(buffer) != 0; }

void Context::BindBuffer(Enum target, std::uint32_t buffer) {
  auto& s = *state_;
  if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER) return s.SetError(INVALID_ENUM);
  std::shared_ptr<Buffer> object;
  if (buffer != 0) {
    auto it = s.buffers.find(buffer);
    if (it == s.buffers.end()) return s.SetError(INVALID_OPERATION);
    object = it->second;
  }
  auto* binding = s.BindingFor(target);
  if (binding == nullptr) return s.SetError(INVALID_OPERATION);  // element buffer with no vertex array bound
  *binding = std::move(object);
}

void Context::BufferData(Enum target, std::ptrdiff_t size, const void* data, Enum usage) {
  auto& s = *state_;
  if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER) return s.SetError(INVALID_ENUM);
  if (!IsUsage(usage)) return s.SetError(INVALID_ENUM);
  if (size < 0) return s.SetError(INVALID_VALUE);
  auto* binding = s.BindingFor(target);
  if (binding == nullptr || !*binding) return s.SetError(INVALID_OPERATION);
  try {
    std::vector<std::uint8_t> store(std::size_t(size), 0);
    if (data != nullptr && size > 0) std::memcpy(store.data(), data, std::size_t(size));
    (*binding)->data = std::move(store);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY);
  } catch (const std::length_error&) {
    s.SetError(OUT_OF_MEMORY);
  }
}

void Context::BufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data) {
  auto& s = *state_;
  if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER) return s.SetError(INVALID_ENUM);
  auto* binding = s.BindingFor(target);
  if (binding == nullptr || !*binding) return s.SetError(INVALID_OPERATION);
  if (offset < 0 || size < 0) return s.SetError(INVALID_VALUE);
  auto& store = (*binding)->data;
  if (std::size_t(offset) > store.size() || std::size_t(size) > store.size() - std::size_t(offset))
    return s.SetError(INVALID_VALUE);
  if (data != nullptr && size > 0) std::memcpy(store.data() + offset, data, std::size_t(size));
}

// ---- Vertex arrays -------------------------------------------------------------------------------------------

std::uint32_t Context::GenVertexArray() {
  const std::uint32_t id = state_->next_array++;
  state_->arrays[id] = std::make_unique<VertexArray>();
  return id;
}

void Context::GenVertexArrays(int n, std::uint32_t* ids) {
  if (n < 0) return state_->SetError(INVALID_VALUE);
  for (int i = 0; i < n; ++i) ids[i] = GenVertexArray();
}

void Context::DeleteVertexArray(std::uint32_t array) {
  auto& s = *state_;
  auto it = s.arrays.find(array);
  if (it == s.arrays.end()) return;
  if (s.vao == it->second.get()) {
    s.vao = nullptr;
    s.vao_id = 0;
  }
  s.arrays.erase(it);
}

bool Context::IsVertexArray(std::uint32_t array) const { return state_->arrays.count(array) != 0; }

void Context::BindVertexArray(std::uint32_t array) {
  auto& s = *state_;
  if (array == 0) {
    s.vao = nullptr;
    s.vao_id = 0;
    return;
  }
  auto it = s.arrays.find(array);
  if (it == s.arrays.end()) return s.SetError(INVALID_OPERATION);
  s.vao = it->second.get();
  s.vao_id = array;
}

void Context::VertexAttributePointer(std::uint32_t index, int size, Enum type, bool normalized, int stride,
                                     std::size_t offset) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs) || size < 1 || size > 4 || stride < 0)
    return s.SetError(INVALID_VALUE);
  if (detail::TypeSize(type) == 0) return s.SetError(INVALID_ENUM);
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION);
  if (!s.array_buffer && offset != 0) return s.SetError(INVALID_OPERATION);
  AttribBinding& a = s.vao->attrib[index];
  a.buffer = s.array_buffer;
  a.offset = offset;
  a.size = size;
  a.type = type;
  a.normalized = normalized;
  a.stride = stride;
}

void Context::EnableVertexAttribArray(std::uint32_t index) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE);
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION);
  s.vao->attrib[index].enabled = true;
}

void Context::DisableVertexAttribArray(std::uint32_t index) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE);
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION);
  s.vao->attrib[index].enabled = false;
}

void Context::VertexAttrib4f(std::uint32_t index, float x, float y, float z, float w) {
  if (index >= std::uint32_t(kMaxVertexAttribs)) return state_->SetError(INVALID_VALUE);
  state_->current_attrib[index] = glm::vec4(x, y, z, w);
}

// ---- Shaders and fixed-function state ------------------------------------------------------------------------

void Context::UseProgram(const Program& program) {
  if (program.VaryingFloats() < 0 || program.VaryingFloats() > kMaxVaryingFloats)
    return state_->SetError(INVALID_VALUE);
  state_->program = &program;
}

void Context::UseProgram(std::nullptr_t) { state_->program = nullptr; }

void Context::Viewport(int x, int y, int width, int height) {
  auto& s = *state_;
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE);
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

namespace {
bool* CapFlag(ContextState& s, Enum cap) {
  switch (cap) {
    case CULL_FACE: return &s.cull_enabled;
    case DEPTH_TEST: return &s.ops.depth_test;
    case PROGRAM_POINT_SIZE: return &s.program_point_size;
    case SCISSOR_TEST: return &s.scissor_enabled;
    case STENCIL_TEST: return &s.ops.stencil_test;
    case BLEND: return &s.ops.blend.enabled;
    case POLYGON_OFFSET_FILL: return &s.offset_fill;
    case POLYGON_OFFSET_LINE: return &s.offset_line;
    case POLYGON_OFFSET_POINT: return &s.offset_point;
    default: return nullptr;
  }
}
}  // namespace

void Context::Enable(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM);
  *flag = true;
}

void Context::Disable(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM);
  *flag = false;
}

bool Context::IsEnabled(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) {
    state_->SetError(INVALID_ENUM);
    return false;
  }
  return *flag;
}

void Context::CullFace(Enum mode) {
  if (mode != FRONT && mode != BACK && mode != FRONT_AND_BACK) return state_->SetError(INVALID_ENUM);
  state_->cull_face = mode;
}

void Context::FrontFace(Enum mode) {
  if (mode != CW && mode != CCW) return state_->SetError(INVALID_ENUM);
  state_->front_face = mode;
}

void Context::PolygonMode(Enum face, Enum mode) {
  if (face != FRONT_AND_BACK || (mode != POINT && mode != LINE && mode != FILL))
    return state_->SetError(INVALID_ENUM);
  state_->polygon_mode = mode;
}

void Context::PointSize(float size) {
  if (!(size > 0.0f)) return state_->SetError(INVALID_VALUE);
  state_->point_size = size;
}

void Context::DepthFunc(Enum func) {
  if (func < NEVER || func > ALWAYS) return state_->SetError(INVALID_ENUM);
  state_->ops.depth_func = func;
}

void Context::DepthMask(bool flag) { state_->ops.depth_write = flag; }

void Context::PolygonOffset(float factor, float units) {
  state_->offset_factor = factor;
  state_->offset_units = units;
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
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE);
  s.scissor[0] = x;
  s.scissor[1] = y;
  s.scissor[2] = width;
  s.scissor[3] = height;
}

void Context::StencilFunc(Enum func, int ref, std::uint32_t mask) { StencilFuncSeparate(FRONT_AND_BACK, func, ref, mask); }

void Context::StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask) {
  if (!IsFace(face) || !IsCompareFunc(func)) return state_->SetError(INVALID_ENUM);
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) {
    f.func = func;
    f.ref = ref;
    f.value_mask = mask;
  });
}

void Context::StencilOp(Enum sfail, Enum dpfail, Enum dppass) { StencilOpSeparate(FRONT_AND_BACK, sfail, dpfail, dppass); }

void Context::StencilOpSeparate(Enum face, Enum sfail, Enum dpfail, Enum dppass) {
  if (!IsFace(face) || !IsStencilOp(sfail) || !IsStencilOp(dpfail) || !IsStencilOp(dppass))
    return state_->SetError(INVALID_ENUM);
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) {
    f.sfail = sfail;
    f.dpfail = dpfail;
    f.dppass = dppass;
  });
}

void Context::StencilMask(std::uint32_t mask) { StencilMaskSeparate(FRONT_AND_BACK, mask); }

void Context::StencilMaskSeparate(Enum face, std::uint32_t mask) {
  if (!IsFace(face)) return state_->SetError(INVALID_ENUM);
  ForFaces(state_->ops, face, [&](detail::StencilFace& f) { f.write_mask = mask; });
}

void Context::BlendFunc(Enum src, Enum dst) { BlendFuncSeparate(src, dst, src, dst); }

void Context::BlendFuncSeparate(Enum src_rgb, Enum dst_rgb, Enum src_alpha, Enum dst_alpha) {
  if (!IsBlendFactor(src_rgb) || !IsBlendFactor(dst_rgb) || !IsBlendFactor(src_alpha) || !IsBlendFactor(dst_alpha))
    return state_->SetError(INVALID_ENUM);
  auto& b = state_->ops.blend;
  b.src_rgb = src_rgb;
  b.dst_rgb = dst_rgb;
  b.src_alpha = src_alpha;
  b.dst_alpha = dst_alpha;
}

void Context::BlendEquation(Enum mode) { BlendEquationSeparate(mode, mode); }

void Context::BlendEquationSeparate(Enum mode_rgb, Enum mode_alpha) {
  if (!IsBlendEquation(mode_rgb) || !IsBlendEquation(mode_alpha)) return state_->SetError(INVALID_ENUM);
  state_->ops.blend.eq_rgb = mode_rgb;
  state_->ops.blend.eq_alpha = mode_alpha;
}

void Context::BlendColor(float r, float g, float b, float a) { state_->ops.blend.color = glm::vec4(r, g, b, a); }

void Context::ColorMask(bool r, bool g, bool b, bool a) {
  bool* m = state_->ops.color_mask;
  m[0] = r;
  m[1] = g;
  m[2] = b;
  m[3] = a;
}

// ---- Clearing ------------------------------------------------------------------------------------------------

void Context::ClearColor(float r, float g, float b, float a) {
  const float c[4] = {r, g, b, a};
  for (int i = 0; i < 4; ++i) state_->clear_color[i] = c[i];
}

void Context::ClearDepth(double depth) { state_->clear_depth = depth >= 0.0 ? float(std::min(depth, 1.0)) : 0.0f; }

void Context::ClearStencil(int s) { state_->clear_stencil = std::uint8_t(s & 0xFF); }

void Context::Clear(Bitfield mask) {
  auto& s = *state_;
  if (mask & ~(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT)) return s.SetError(INVALID_VALUE);
  const detail::Rect area = s.ClearArea();
  if (area.Empty()) return;
  if (mask & COLOR_BUFFER_BIT) {
    std::uint8_t rgba[4];
    for (int i = 0; i < 4; ++i) rgba[i] = detail::FloatToUnorm8(s.clear_color[i]);
    s.fb.ClearColor(area, rgba, s.ops.color_mask);
  }
  if ((mask & DEPTH_BUFFER_BIT) && s.ops.depth_write) s.fb.ClearDepth(area, s.clear_depth);
  if (mask & STENCIL_BUFFER_BIT) s.fb.ClearStencil(area, s.clear_stencil, std::uint8_t(s.ops.front.write_mask));
}

// ---- Drawing -------------------------------------------------------------------------------------------------

void ContextState::Draw(const detail::DrawCall& call) {
  detail::FetchPlan plan;
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const AttribBinding& a = vao->attrib[i];
    detail::AttribSource& src = plan.attrib[i];
    src.current = current_attrib[i];
    src.enabled = a.enabled;
    if (!a.enabled) continue;
    src.data = a.buffer ? a.buffer->data.data() : nullptr;
    src.size = a.buffer ? a.buffer->data.size() : 0;
    src.offset = a.offset;
    src.components = a.size;
    src.type = a.type;
    src.normalized = a.normalized;
    src.stride = a.stride ? std::size_t(a.stride) : std::size_t(a.size) * detail::TypeSize(a.type);
  }

  detail::DrawState ds;
  ds.program = program;
  ds.viewport = detail::MakeViewportTransform(viewport[0], viewport[1], viewport[2], viewport[3], depth_near,
                                              depth_far);
  const detail::Rect fbr = ClearArea();  // framebuffer and scissor
  ds.bounds = detail::Rect{std::max(ds.viewport.rect.x0, fbr.x0), std::max(ds.viewport.rect.y0, fbr.y0),
                           std::min(ds.viewport.rect.x1, fbr.x1), std::min(ds.viewport.rect.y1, fbr.y1)};
  ds.cull_enabled = cull_enabled;
  ds.cull_face = cull_face;
  ds.front_face = front_face;
  ds.polygon_mode = polygon_mode;
  ds.program_point_size = program_point_size;
  ds.point_size = point_size;
  ds.offset_fill = offset_fill;
  ds.offset_line = offset_line;
  ds.offset_point = offset_point;
  ds.offset_factor = offset_factor;
  ds.offset_units = offset_units;
  ds.ops = ops;
  try {
    detail::Draw(call, plan, ds, fb, scratch);
  } catch (const std::bad_alloc&) {
    SetError(OUT_OF_MEMORY);
  } catch (const std::length_error&) {
    SetError(OUT_OF_MEMORY);
  }
}

void Context::DrawArrays(Enum mode, int first, int count) {
  auto& s = *state_;
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM);
  if (first < 0 || count < 0) return s.SetError(INVALID_VALUE);
  if (s.vao == nullptr || s.program == nullptr) return s.SetError(INVALID_OPERATION);
  detail::DrawCall call;
  call.mode = mode;
  call.count = count;
  call.first = std::uint32_t(first);
  s.Draw(call);
}

void Context::DrawElement(Enum mode, int count, Enum type, std::size_t offset) {
  auto& s = *state_;
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM);
  if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT) return s.SetError(INVALID_ENUM);
  if (count < 0) return s.SetError(INVALID_VALUE);
  if (s.vao == nullptr || s.program == nullptr || !s.vao->element_buffer) return s.SetError(INVALID_OPERATION);
  const auto& store = s.vao->element_buffer->data;
  const std::size_t bytes = std::size_t(count) * detail::TypeSize(type);
  if (offset > store.size() || bytes > store.size() - offset) return s.SetError(INVALID_OPERATION);
  if (count == 0) return;
  std::vector<std::uint32_t> elements;
  try {
    elements.resize(std::size_t(count));
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY);
  }
  detail::ReadIndices(type, store.data() + offset, count, elements.data());
  detail::DrawCall call;
  call.mode = mode;
  call.count = count;
  call.elements = elements.data();
  s.Draw(call);
}

// ---- Reading back --------------------------------------------------------------------------------------------

Image Context::ReadPixels() const {
  const auto& fb = state_->fb;
  Image image;
  image.width = fb.width;
  image.height = fb.height;
  image.rgba.resize(fb.color.size());
  const std::size_t row = std::size_t(fb.width) * 4;
  for (int y = 0; y < fb.height; ++y)
    std::memcpy(image.rgba.data() + std::size_t(fb.height - 1 - y) * row, fb.color.data() + std::size_t(y) * row,
                row);
  return image;
}

void Context::ReadPixel(int x, int y, std::uint8_t rgba[4]) const {
  const auto& fb = state_->fb;
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) {
    std::memset(rgba, 0, 4);
    return;
  }
  std::memcpy(rgba, &fb.color[fb.Index(x, y) * 4], 4);
}

float Context::ReadDepth(int x, int y) const {
  const auto& fb = state_->fb;
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return 0.0f;
  return fb.depth[fb.Index(x, y)];
}

std::uint8_t Context::ReadStencil(int x, int y) const {
  const auto& fb = state_->fb;
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return 0;
  return fb.stencil[fb.Index(x, y)];
}

}  // namespace softgl

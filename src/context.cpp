// context.cpp — the API boundary: object tables, state, validation with OpenGL's error codes.
//
// Every entry point checks its arguments first, records the first error and returns without changing anything
// when one fails. Drawing resolves the bound objects into plain structs (FetchPlan, DrawState) and hands them to
// the pipeline.
#include <softgl/context.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <new>
#include <unordered_map>
#include <vector>

#include "framebuffer.h"
#include "image_io.h"
#include "pipeline.h"
#include "primitive_assembly.h"
#include "texture.h"
#include "tile_renderer.h"
#include "vertex_fetch.h"
#include "viewport.h"
#include "worker_pool.h"

namespace softgl {

namespace {

struct Buffer {
  std::vector<std::uint8_t> data;
  Enum usage = STATIC_DRAW;
  // While mapped (MapBufferRange), bytes [map_offset, map_offset + map_length) are the caller's through the pointer
  // it was given; the store is not reallocated until it is unmapped.
  bool mapped = false;
  Bitfield access_flags = 0;
  std::size_t map_offset = 0, map_length = 0;
  // Whether bytes [offset, offset + size) meet the mapped range.
  bool MappedOverlaps(std::size_t offset, std::size_t size) const {
    return mapped && offset < map_offset + map_length && map_offset < offset + size;
  }
  void Unmap() {
    mapped = false;
    access_flags = 0;
    map_offset = map_length = 0;
  }
};

struct AttribBinding {
  bool enabled = false;
  std::shared_ptr<Buffer> buffer;  // keeps a deleted buffer's store alive while referenced, as OpenGL does
  std::size_t offset = 0;
  int size = 4;
  Enum type = FLOAT;
  bool normalized = false;
  int stride = 0;
  std::uint32_t divisor = 0;  // VertexAttribDivisor
};

struct VertexArray {
  AttribBinding attrib[kMaxVertexAttribs];
  std::shared_ptr<Buffer> element_buffer;
};

bool IsUsage(Enum usage) { return usage >= 0x88E0 && usage <= 0x88EA && (usage & 3) != 3; }

// A renderbuffer object (GenRenderbuffers): one image that drawing can render to and blits and reads can use.
struct Renderbuffer {
  detail::TextureLevel image;  // in its sized format (an unsized one resolved), with its stencil plane
  Enum internal_format = RGBA;  // as RenderbufferStorage was given it (RENDERBUFFER_INTERNAL_FORMAT)
};

// What a framebuffer attachment point holds: a texture's level (of one cube face), a renderbuffer, or nothing.
struct Attachment {
  std::shared_ptr<detail::TextureObject> texture;  // keeps the storage alive, as OpenGL does
  std::shared_ptr<Renderbuffer> renderbuffer;
  int face = 0;
  int level = 0;
  bool Present() const { return texture || renderbuffer; }
  const detail::TextureLevel* Level() const {
    return texture ? &texture->levels[face][level] : renderbuffer ? &renderbuffer->image : nullptr;
  }
};

struct FramebufferObject {
  Attachment color[kMaxColorOutputs];
  Attachment depth, stencil;  // DEPTH_STENCIL_ATTACHMENT sets both
  Enum draw_buffers[kMaxColorOutputs] = {COLOR_ATTACHMENT0, NONE, NONE, NONE};
  Enum read_buffer = COLOR_ATTACHMENT0;  // ReadBuffer: COLOR_ATTACHMENT0 + i or NONE
};

// A query object (GenQueries). Its target is fixed by its first BeginQuery.
struct QueryObject {
  Enum target = 0;
  bool active = false;
  std::shared_ptr<detail::OcclusionCounter> counter;  // SAMPLES_PASSED, ANY_SAMPLES_PASSED: tiles add to it
  std::uint64_t count = 0;                            // PRIMITIVES_GENERATED, counted as draws are recorded
  std::chrono::steady_clock::time_point start;        // TIME_ELAPSED
  std::uint64_t elapsed_ns = 0;
};

// The slot of each query target: 0 SAMPLES_PASSED, 1 ANY_SAMPLES_PASSED, 2 PRIMITIVES_GENERATED, 3 TIME_ELAPSED.
int QuerySlot(Enum target) {
  switch (target) {
    case SAMPLES_PASSED: return 0;
    case ANY_SAMPLES_PASSED: return 1;
    case PRIMITIVES_GENERATED: return 2;
    case TIME_ELAPSED: return 3;
    default: return -1;
  }
}

struct TextureUnit {
  std::shared_ptr<detail::TextureObject> tex_2d, cube;
};

int CubeFaceIndex(Enum target) {
  return target >= TEXTURE_CUBE_MAP_POSITIVE_X && target <= TEXTURE_CUBE_MAP_NEGATIVE_Z
             ? int(target - TEXTURE_CUBE_MAP_POSITIVE_X)
             : -1;
}

bool IsTexImageTarget(Enum target) { return target == TEXTURE_2D || CubeFaceIndex(target) >= 0; }

// Section 9.4: why a framebuffer object cannot be drawn to, or FRAMEBUFFER_COMPLETE. Depth and stencil may be
// separate images (OpenGL allows it; llvmpipe answers FRAMEBUFFER_UNSUPPORTED there).
Enum FramebufferStatus(const FramebufferObject& f) {
  bool any = false;
  for (const Attachment& a : f.color) {
    if (!a.Present()) continue;
    any = true;
    const detail::TextureLevel* l = a.Level();
    if (!l->Defined() || detail::IsDepthFormat(l->format) || detail::HasStencil(l->format))
      return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (f.depth.Present()) {
    any = true;
    const detail::TextureLevel* l = f.depth.Level();
    if (!l->Defined() || !detail::IsDepthFormat(l->format)) return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (f.stencil.Present()) {
    any = true;
    const detail::TextureLevel* l = f.stencil.Level();
    if (!l->Defined() || !detail::HasStencil(l->format)) return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (!any) return FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  for (Enum b : f.draw_buffers)
    if (b != NONE && !f.color[b - COLOR_ATTACHMENT0].Present()) return FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
  return FRAMEBUFFER_COMPLETE;
}

// The buffers of a complete framebuffer object, drawn through its draw buffers; its size is the intersection of
// its attachments'.
detail::RenderTarget FramebufferTarget(const FramebufferObject& f) {
  detail::RenderTarget t;
  t.width = t.height = 1 << 30;
  auto fit = [&](const Attachment& a) {
    if (!a.Present()) return;
    t.width = std::min(t.width, a.Level()->width);
    t.height = std::min(t.height, a.Level()->height);
  };
  for (const Attachment& a : f.color) fit(a);
  fit(f.depth);
  fit(f.stencil);
  for (int i = 0; i < kMaxColorOutputs; ++i) {
    if (f.draw_buffers[i] == NONE) continue;
    const Attachment& a = f.color[f.draw_buffers[i] - COLOR_ATTACHMENT0];
    if (!a.Present()) continue;
    detail::ColorBuffer& cb = t.color[i];
    cb.data = const_cast<std::uint8_t*>(a.Level()->data.data());
    cb.layout = a.Level()->layout;
    cb.rgb_only = a.Level()->format == RGB8;
    cb.pitch = a.Level()->width;
  }
  if (f.depth.Present()) {
    t.depth = reinterpret_cast<float*>(const_cast<std::uint8_t*>(f.depth.Level()->data.data()));
    t.depth_pitch = f.depth.Level()->width;
  }
  if (f.stencil.Present()) {
    t.stencil = const_cast<std::uint8_t*>(f.stencil.Level()->stencil.data());
    t.stencil_pitch = f.stencil.Level()->width;
  }
  return t;
}

}  // namespace

struct ContextState {
  Enum error = NO_ERROR;
  detail::Framebuffer fb;

  std::unordered_map<std::uint32_t, std::shared_ptr<Buffer>> buffers;
  std::uint32_t next_buffer = 1;
  std::unordered_map<std::uint32_t, std::unique_ptr<VertexArray>> arrays;
  std::uint32_t next_array = 1;

  std::shared_ptr<Buffer> array_buffer;
  std::shared_ptr<Buffer> copy_read_buffer, copy_write_buffer;
  VertexArray* vao = nullptr;
  std::uint32_t vao_id = 0;
  glm::vec4 current_attrib[kMaxVertexAttribs];
  const Program* program = nullptr;

  std::unordered_map<std::uint32_t, std::shared_ptr<detail::TextureObject>> textures;
  std::uint32_t next_texture = 1;
  TextureUnit units[kMaxTextureUnits];
  int active_unit = 0;
  int unpack_alignment = 4;
  int pack_alignment = 4, pack_row_length = 0, pack_skip_rows = 0, pack_skip_pixels = 0;
  std::unordered_map<std::uint32_t, std::unique_ptr<FramebufferObject>> framebuffers;
  std::uint32_t next_framebuffer = 1;
  std::unordered_map<std::uint32_t, std::shared_ptr<Renderbuffer>> renderbuffers;
  std::uint32_t next_renderbuffer = 1;
  std::shared_ptr<Renderbuffer> renderbuffer;  // bound to RENDERBUFFER
  Enum default_read_buffer = BACK;             // ReadBuffer while the context's own framebuffer is read: or NONE
  std::unordered_map<std::uint32_t, std::unique_ptr<QueryObject>> queries;
  std::uint32_t next_query = 1;
  std::uint32_t active_query[4] = {0, 0, 0, 0};  // by QuerySlot: the id active on each target (0: none)
  FramebufferObject* draw_fbo = nullptr;
  FramebufferObject* read_fbo = nullptr;

  int viewport[4] = {0, 0, 0, 0};
  double depth_near = 0.0, depth_far = 1.0;
  detail::PrimitiveState primitive;
  bool scissor_enabled = false;
  int scissor[4] = {0, 0, 0, 0};
  bool primitive_restart = false, primitive_restart_fixed = false;
  std::uint32_t restart_index = 0;  // PrimitiveRestartIndex
  // The stencil masks start as the stencil buffer's 8 bits (OpenGL says all ones: the same for 8 bits, and what
  // Mesa reports).
  detail::FragmentOpsState ops = [] {
    detail::FragmentOpsState o;
    o.front.value_mask = o.front.write_mask = o.back.value_mask = o.back.write_mask = 0xFFu;
    return o;
  }();

  float clear_color[4] = {0, 0, 0, 0};
  double clear_depth = 1.0;  // clamped to [0, 1]
  int clear_stencil = 0;  // as given; its low 8 bits are used

  detail::Scratch scratch;
  std::unique_ptr<detail::WorkerPool> pool;
  detail::Frame frame;  // recorded clears and draws, not yet rendered

  Context::DebugCallback debug_callback;

  // Records `e` if no error is pending (OpenGL keeps the first), and reports every error to the debug callback.
  void SetError(Enum e, const char* call, const char* message) {
    if (error == NO_ERROR) error = e;
    if (debug_callback) debug_callback(e, call, message);
  }

  std::shared_ptr<Buffer>* BindingFor(Enum target) {
    if (target == ARRAY_BUFFER) return &array_buffer;
    if (target == COPY_READ_BUFFER) return &copy_read_buffer;
    if (target == COPY_WRITE_BUFFER) return &copy_write_buffer;
    if (target == ELEMENT_ARRAY_BUFFER && vao) return &vao->element_buffer;
    return nullptr;
  }

  // The buffer bound to `target`, or null with the error set: a target that is not a buffer target (INVALID_ENUM),
  // nothing bound there (INVALID_OPERATION).
  Buffer* BoundBuffer(const char* what, Enum target) {
    if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER && target != COPY_READ_BUFFER &&
        target != COPY_WRITE_BUFFER)
      return SetError(INVALID_ENUM, what, "target must be ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER or COPY_WRITE_BUFFER"), nullptr;
    auto* binding = BindingFor(target);
    if (binding == nullptr || !*binding) return SetError(INVALID_OPERATION, what, "no buffer is bound to target"), nullptr;
    return binding->get();
  }

  // The draw target's area, cut to the scissor rectangle while the scissor test is enabled.
  detail::Rect ClearArea(const detail::RenderTarget& target) const {
    detail::Rect r = target.Bounds();
    if (!scissor_enabled) return r;
    const std::int64_t x1 = std::int64_t(scissor[0]) + scissor[2], y1 = std::int64_t(scissor[1]) + scissor[3];
    r.x0 = std::max(r.x0, scissor[0]);
    r.y0 = std::max(r.y0, scissor[1]);
    r.x1 = int(std::min<std::int64_t>(r.x1, x1));
    r.y1 = int(std::min<std::int64_t>(r.y1, y1));
    return r;
  }

  // What drawing writes to: the context's framebuffer or the bound framebuffer object. False (with
  // INVALID_FRAMEBUFFER_OPERATION recorded) when that object is incomplete.
  bool DrawTarget(detail::RenderTarget& target) {
    if (!draw_fbo) {
      target = fb.Target();
      return true;
    }
    if (FramebufferStatus(*draw_fbo) != FRAMEBUFFER_COMPLETE) {
      SetError(INVALID_FRAMEBUFFER_OPERATION, __func__, "the framebuffer bound for drawing is not complete");
      return false;
    }
    target = FramebufferTarget(*draw_fbo);
    return true;
  }

  // The texture bound to `target` of the active unit (a cube face target selects the cube map), and the face.
  detail::TextureObject* Bound(Enum target, int* face = nullptr) {
    TextureUnit& u = units[active_unit];
    if (face) *face = 0;
    if (target == TEXTURE_2D) return u.tex_2d.get();
    if (target == TEXTURE_CUBE_MAP) return u.cube.get();
    const int f = CubeFaceIndex(target);
    if (f < 0) return nullptr;
    if (face) *face = f;
    return u.cube.get();
  }

  void Draw(const detail::DrawCall& call);

  // Renders what is recorded, so that the buffers hold it: before the buffers are read, before anything a
  // recorded draw refers to (textures, framebuffer attachments) changes, and before drawing elsewhere.
  void Sync(const char* call) {
    try {
      frame.Render(*pool, scratch.tiles);
    } catch (const std::bad_alloc&) {
      SetError(OUT_OF_MEMORY, call, "out of memory while rendering recorded draws (they are dropped)");
    }
  }
};

Context::Context(int width, int height) : Context(width, height, Options{}) {}

Context::Context(int width, int height, const Options& options) : state_(std::make_unique<ContextState>()) {
  state_->pool = std::make_unique<detail::WorkerPool>(options.threads > 0 ? options.threads
                                                                          : detail::DefaultThreadCount());
  for (auto& a : state_->current_attrib) a = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  if (width < 0 || height < 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize) {
    state_->SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
    width = height = 0;
  }
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

void Context::DebugMessageCallback(DebugCallback callback) { state_->debug_callback = std::move(callback); }

Enum Context::GetError() {
  const Enum e = state_->error;
  state_->error = NO_ERROR;
  return e;
}

// ---- Object ids --------------------------------------------------------------------------------------------

namespace {

// A new id (never 0) for a new object in `table`.
template <class Table, class Make>
std::uint32_t NewId(Table& table, std::uint32_t& next, Make&& make) {
  const std::uint32_t id = next++;
  table[id] = make();
  return id;
}

// The Gen*s(n, ids) form of a Gen* call.
template <class Gen>
void GenMany(ContextState& s, const char* call, int n, std::uint32_t* ids, Gen&& gen) {
  if (n < 0) return s.SetError(INVALID_VALUE, call, "n is negative");
  for (int i = 0; i < n; ++i) ids[i] = gen();
}

}  // namespace

// ---- Buffers -------------------------------------------------------------------------------------------------

std::uint32_t Context::GenBuffer() {
  return NewId(state_->buffers, state_->next_buffer, [] { return std::make_shared<Buffer>(); });
}

void Context::GenBuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenBuffer(); });
}

void Context::DeleteBuffer(std::uint32_t buffer) {
  auto& s = *state_;
  auto it = s.buffers.find(buffer);
  if (it == s.buffers.end()) return;
  Buffer* dead = it->second.get();
  dead->Unmap();  // deleting a mapped buffer unmaps it
  if (s.array_buffer.get() == dead) s.array_buffer.reset();
  if (s.copy_read_buffer.get() == dead) s.copy_read_buffer.reset();
  if (s.copy_write_buffer.get() == dead) s.copy_write_buffer.reset();
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
  if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER && target != COPY_READ_BUFFER &&
      target != COPY_WRITE_BUFFER)
    return s.SetError(INVALID_ENUM, __func__, "target must be ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER or COPY_WRITE_BUFFER");
  std::shared_ptr<Buffer> object;
  if (buffer != 0) {
    auto it = s.buffers.find(buffer);
    if (it == s.buffers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a buffer id made by GenBuffer (or it was deleted)");
    object = it->second;
  }
  auto* binding = s.BindingFor(target);
  if (binding == nullptr) return s.SetError(INVALID_OPERATION, __func__, "ELEMENT_ARRAY_BUFFER needs a bound vertex array");  // element buffer with no vertex array bound
  *binding = std::move(object);
}

void Context::BufferData(Enum target, std::ptrdiff_t size, const void* data, Enum usage) {
  auto& s = *state_;
  if (target != ARRAY_BUFFER && target != ELEMENT_ARRAY_BUFFER && target != COPY_READ_BUFFER &&
      target != COPY_WRITE_BUFFER)
    return s.SetError(INVALID_ENUM, __func__, "target must be ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER or COPY_WRITE_BUFFER");
  if (!IsUsage(usage)) return s.SetError(INVALID_ENUM, __func__, "not a buffer usage");
  if (size < 0) return s.SetError(INVALID_VALUE, __func__, "size is negative");
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  try {
    std::vector<std::uint8_t> store(std::size_t(size), 0);
    if (data != nullptr && size > 0) std::memcpy(store.data(), data, std::size_t(size));
    buffer->Unmap();  // a new store unmaps the old one, as OpenGL does
    buffer->data = std::move(store);
    buffer->usage = usage;
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  } catch (const std::length_error&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

namespace {

// Whether [offset, offset + size) lies inside a store of `store` bytes (offset and size already non-negative).
bool InStore(std::size_t store, std::ptrdiff_t offset, std::ptrdiff_t size) {
  return std::size_t(offset) <= store && std::size_t(size) <= store - std::size_t(offset);
}

}  // namespace

void Context::BufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "offset or size is negative");
  if (!InStore(buffer->data.size(), offset, size)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the buffer's store");
  if (buffer->MappedOverlaps(std::size_t(offset), std::size_t(size))) return s.SetError(INVALID_OPERATION, __func__, "the range is mapped");
  if (data != nullptr && size > 0) std::memcpy(buffer->data.data() + offset, data, std::size_t(size));
}

namespace {

void* MapRange(ContextState& s, const char* what, Enum target, std::ptrdiff_t offset, std::ptrdiff_t length,
               Bitfield access) {
  Buffer* buffer = s.BoundBuffer(what, target);
  if (buffer == nullptr) return nullptr;
  constexpr Bitfield kKnown = MAP_READ_BIT | MAP_WRITE_BIT | MAP_INVALIDATE_RANGE_BIT | MAP_INVALIDATE_BUFFER_BIT |
                              MAP_FLUSH_EXPLICIT_BIT | MAP_UNSYNCHRONIZED_BIT;
  if (offset < 0 || length < 0) return s.SetError(INVALID_VALUE, what, "offset or length is negative"), nullptr;
  if (!InStore(buffer->data.size(), offset, length)) return s.SetError(INVALID_VALUE, what, "the range is outside the buffer's store"), nullptr;
  if (access & ~kKnown) return s.SetError(INVALID_VALUE, what, "access has bits other than the MAP_*_BIT ones"), nullptr;
  if (length == 0) return s.SetError(INVALID_OPERATION, what, "length is zero"), nullptr;
  if (buffer->mapped) return s.SetError(INVALID_OPERATION, what, "the buffer is already mapped"), nullptr;
  if (!(access & (MAP_READ_BIT | MAP_WRITE_BIT))) return s.SetError(INVALID_OPERATION, what, "access has neither MAP_READ_BIT nor MAP_WRITE_BIT"), nullptr;
  if ((access & MAP_READ_BIT) && (access & (MAP_INVALIDATE_RANGE_BIT | MAP_INVALIDATE_BUFFER_BIT | MAP_UNSYNCHRONIZED_BIT)))
    return s.SetError(INVALID_OPERATION, what, "MAP_READ_BIT with an INVALIDATE or UNSYNCHRONIZED bit"), nullptr;
  if ((access & MAP_FLUSH_EXPLICIT_BIT) && !(access & MAP_WRITE_BIT)) return s.SetError(INVALID_OPERATION, what, "MAP_FLUSH_EXPLICIT_BIT without MAP_WRITE_BIT"), nullptr;
  // Draws read their vertices when they are made, so the store holds everything earlier calls wrote: the caller's
  // view of it is the store itself (invalidated bytes keep their old values, which OpenGL allows).
  buffer->mapped = true;
  buffer->access_flags = access;
  buffer->map_offset = std::size_t(offset);
  buffer->map_length = std::size_t(length);
  return buffer->data.data() + offset;
}

}  // namespace

void* Context::MapBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length, Bitfield access) {
  return MapRange(*state_, __func__, target, offset, length, access);
}

void* Context::MapBuffer(Enum target, Enum access) {
  auto& s = *state_;
  const Bitfield bits = access == READ_ONLY ? MAP_READ_BIT : access == WRITE_ONLY ? MAP_WRITE_BIT
                        : access == READ_WRITE ? MAP_READ_BIT | MAP_WRITE_BIT : 0;
  if (bits == 0) return s.SetError(INVALID_ENUM, __func__, "access must be READ_ONLY, WRITE_ONLY or READ_WRITE"), nullptr;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return nullptr;
  if (buffer->data.empty()) return s.SetError(INVALID_OPERATION, __func__, "the buffer has no store"), nullptr;
  return MapRange(s, __func__, target, 0, std::ptrdiff_t(buffer->data.size()), bits);
}

void Context::FlushMappedBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || length < 0) return s.SetError(INVALID_VALUE, __func__, "offset or length is negative");
  if (!buffer->mapped || !(buffer->access_flags & MAP_FLUSH_EXPLICIT_BIT)) return s.SetError(INVALID_OPERATION, __func__, "the buffer is not mapped with MAP_FLUSH_EXPLICIT_BIT");
  if (!InStore(buffer->map_length, offset, length)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the mapped range");
  // The mapping is the store: flushed bytes are already in place.
}

bool Context::UnmapBuffer(Enum target) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return false;
  if (!buffer->mapped) return s.SetError(INVALID_OPERATION, __func__, "the buffer is not mapped"), false;
  buffer->Unmap();
  return true;
}

void Context::CopyBufferSubData(Enum read_target, Enum write_target, std::ptrdiff_t read_offset,
                                std::ptrdiff_t write_offset, std::ptrdiff_t size) {
  auto& s = *state_;
  Buffer* src = s.BoundBuffer(__func__, read_target);
  if (src == nullptr) return;
  Buffer* dst = s.BoundBuffer(__func__, write_target);
  if (dst == nullptr) return;
  if (read_offset < 0 || write_offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "an offset or the size is negative");
  if (!InStore(src->data.size(), read_offset, size) || !InStore(dst->data.size(), write_offset, size))
    return s.SetError(INVALID_VALUE, __func__, "a range is outside its buffer's store");
  if (src == dst && read_offset < write_offset + size && write_offset < read_offset + size)
    return s.SetError(INVALID_VALUE, __func__, "the ranges overlap within one buffer");
  if (src->mapped || dst->mapped) return s.SetError(INVALID_OPERATION, __func__, "a buffer is mapped");
  if (size > 0) std::memmove(dst->data.data() + write_offset, src->data.data() + read_offset, std::size_t(size));
}

void Context::GetBufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, void* data) const {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "offset or size is negative");
  if (!InStore(buffer->data.size(), offset, size)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the buffer's store");
  if (buffer->MappedOverlaps(std::size_t(offset), std::size_t(size))) return s.SetError(INVALID_OPERATION, __func__, "the range is mapped");
  if (data != nullptr && size > 0) std::memcpy(data, buffer->data.data() + offset, std::size_t(size));
}

namespace {

// The value of buffer parameter `pname`, or false with the error set.
bool BufferParameter(ContextState& s, const char* what, Enum target, Enum pname, std::int64_t& v) {
  Buffer* buffer = s.BoundBuffer(what, target);
  if (buffer == nullptr) return false;
  const Bitfield flags = buffer->access_flags;
  switch (pname) {
    case BUFFER_SIZE: v = std::int64_t(buffer->data.size()); break;
    case BUFFER_USAGE: v = buffer->usage; break;
    case BUFFER_MAPPED: v = buffer->mapped; break;
    case BUFFER_ACCESS_FLAGS: v = flags; break;
    case BUFFER_MAP_OFFSET: v = std::int64_t(buffer->map_offset); break;
    case BUFFER_MAP_LENGTH: v = std::int64_t(buffer->map_length); break;
    case BUFFER_ACCESS:  // READ_WRITE when not mapped, as OpenGL's initial value
      v = (flags & MAP_READ_BIT) && !(flags & MAP_WRITE_BIT) ? READ_ONLY
          : (flags & MAP_WRITE_BIT) && !(flags & MAP_READ_BIT) ? WRITE_ONLY
                                                                 : READ_WRITE;
      break;
    default: return s.SetError(INVALID_ENUM, what, "not a buffer parameter name"), false;
  }
  return true;
}

}  // namespace

void Context::GetBufferParameteri64v(Enum target, Enum pname, std::int64_t* params) const {
  std::int64_t v = 0;
  if (BufferParameter(*state_, __func__, target, pname, v) && params != nullptr) *params = v;
}

void Context::GetBufferParameteriv(Enum target, Enum pname, int* params) const {
  std::int64_t v = 0;
  // Sizes beyond the int range read as the largest int (OpenGL's conversion of integer state to a smaller type).
  if (BufferParameter(*state_, __func__, target, pname, v) && params != nullptr)
    *params = int(std::clamp<std::int64_t>(v, INT32_MIN, INT32_MAX));
}

void Context::GetBufferPointerv(Enum target, Enum pname, void** params) const {
  auto& s = *state_;
  if (pname != BUFFER_MAP_POINTER) return s.SetError(INVALID_ENUM, __func__, "pname must be BUFFER_MAP_POINTER");
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (params != nullptr) *params = buffer->mapped ? buffer->data.data() + buffer->map_offset : nullptr;
}

// ---- Vertex arrays -------------------------------------------------------------------------------------------

std::uint32_t Context::GenVertexArray() {
  return NewId(state_->arrays, state_->next_array, [] { return std::make_unique<VertexArray>(); });
}

void Context::GenVertexArrays(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenVertexArray(); });
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
  if (it == s.arrays.end()) return s.SetError(INVALID_OPERATION, __func__, "not a vertex array id made by GenVertexArray (or it was deleted)");
  s.vao = it->second.get();
  s.vao_id = array;
}

void Context::VertexAttributePointer(std::uint32_t index, int size, Enum type, bool normalized, int stride,
                                     std::size_t offset) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs) || size < 1 || size > 4 || stride < 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (detail::TypeSize(type) == 0) return s.SetError(INVALID_ENUM, __func__, "not an attribute type");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  if (!s.array_buffer && offset != 0) return s.SetError(INVALID_OPERATION, __func__, "no buffer bound to ARRAY_BUFFER (client-side arrays do not exist in a core profile)");
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
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->attrib[index].enabled = true;
}

void Context::DisableVertexAttribArray(std::uint32_t index) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->attrib[index].enabled = false;
}

void Context::VertexAttribDivisor(std::uint32_t index, std::uint32_t divisor) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->attrib[index].divisor = divisor;
}

void Context::VertexAttrib4f(std::uint32_t index, float x, float y, float z, float w) {
  if (index >= std::uint32_t(kMaxVertexAttribs)) return state_->SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  state_->current_attrib[index] = glm::vec4(x, y, z, w);
}

// ---- Shaders and fixed-function state ------------------------------------------------------------------------

void Context::UseProgram(const Program& program) {
  if (program.VaryingFloats() < 0 || program.VaryingFloats() > kMaxVaryingFloats)
    return state_->SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  state_->program = &program;
}

void Context::UseProgram(std::nullptr_t) { state_->program = nullptr; }

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

namespace {
bool* CapFlag(ContextState& s, Enum cap) {
  switch (cap) {
    case CULL_FACE: return &s.primitive.cull_enabled;
    case DEPTH_TEST: return &s.ops.depth_test;
    case PROGRAM_POINT_SIZE: return &s.primitive.program_point_size;
    case SCISSOR_TEST: return &s.scissor_enabled;
    case STENCIL_TEST: return &s.ops.stencil_test;
    case BLEND: return &s.ops.blend.enabled;
    case POLYGON_OFFSET_FILL: return &s.primitive.offset_fill;
    case POLYGON_OFFSET_LINE: return &s.primitive.offset_line;
    case POLYGON_OFFSET_POINT: return &s.primitive.offset_point;
    case PRIMITIVE_RESTART: return &s.primitive_restart;
    case PRIMITIVE_RESTART_FIXED_INDEX: return &s.primitive_restart_fixed;
    default: return nullptr;
  }
}
}  // namespace

void Context::Enable(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM, __func__, "not a capability Enable/Disable/IsEnabled knows");
  *flag = true;
}

void Context::Disable(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) return state_->SetError(INVALID_ENUM, __func__, "not a capability Enable/Disable/IsEnabled knows");
  *flag = false;
}

bool Context::IsEnabled(Enum cap) {
  bool* flag = CapFlag(*state_, cap);
  if (!flag) {
    state_->SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
    return false;
  }
  return *flag;
}

void Context::PrimitiveRestartIndex(std::uint32_t index) { state_->restart_index = index; }

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

void Context::PointSize(float size) {
  if (!(size > 0.0f)) return state_->SetError(INVALID_VALUE, __func__, "size must be positive");
  state_->primitive.point_size = size;
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

void Context::ClearDepth(double depth) { state_->clear_depth = depth >= 0.0 ? std::min(depth, 1.0) : 0.0; }

void Context::ClearStencil(int s) { state_->clear_stencil = s; }

void Context::Clear(Bitfield mask) {
  auto& s = *state_;
  if (mask & ~(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT)) return s.SetError(INVALID_VALUE, __func__, "mask has bits other than COLOR_, DEPTH_ and STENCIL_BUFFER_BIT");
  detail::RenderTarget target;
  if (!s.DrawTarget(target)) return;
  const detail::Rect area = s.ClearArea(target);
  if (area.Empty()) return;
  detail::ClearPacket clear;
  clear.area = area;
  clear.color = (mask & COLOR_BUFFER_BIT) != 0;
  clear.color_value = glm::vec4(s.clear_color[0], s.clear_color[1], s.clear_color[2], s.clear_color[3]);
  for (int i = 0; i < 4; ++i) clear.color_mask[i] = s.ops.color_mask[i];
  clear.depth = (mask & DEPTH_BUFFER_BIT) && s.ops.depth_write;
  clear.depth_value = float(s.clear_depth);
  clear.stencil = (mask & STENCIL_BUFFER_BIT) != 0;
  clear.stencil_value = std::uint8_t(s.clear_stencil & 0xFF);
  clear.stencil_mask = std::uint8_t(s.ops.front.write_mask);
  if (!clear.color && !clear.depth && !clear.stencil) return;
  if (!s.frame.Accepts(target)) s.Sync(__func__);
  try {
    s.frame.AddClear(target, clear);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
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
    src.divisor = a.divisor;
    src.stride = a.stride ? std::size_t(a.stride) : std::size_t(a.size) * detail::TypeSize(a.type);
  }

  detail::RenderTarget target;
  if (!DrawTarget(target)) return;

  // The fragment stage's state, captured now: the shader's uniforms (a copy), the textures of every unit resolved
  // once, the per-fragment operations.
  detail::DrawPacket packet;
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    if (units[u].tex_2d) {
      packet.views[0][u] = detail::MakeView(*units[u].tex_2d);
      packet.textures.unit_2d[u] = &packet.views[0][u];
    }
    if (units[u].cube) {
      packet.views[1][u] = detail::MakeView(*units[u].cube);
      packet.textures.unit_cube[u] = &packet.views[1][u];
    }
  }
  packet.ops = ops;
  for (int k = 0; k < 2; ++k)  // the active occlusion queries count this draw's fragments
    if (active_query[k]) {
      packet.occlusion[k] = queries.at(active_query[k])->counter;
      packet.ops.occlusion[k] = packet.occlusion[k].get();
    }
  packet.nvar = program->VaryingFloats();
  packet.interpolation = program->VaryingInterpolation();
  packet.shader_depth = program->WritesDepth();

  detail::DrawState ds;
  ds.program = program;
  ds.textures = &packet.textures;
  ds.interpolation = packet.interpolation;
  ds.viewport = detail::MakeViewportTransform(viewport[0], viewport[1], viewport[2], viewport[3], depth_near,
                                              depth_far);
  const detail::Rect fbr = ClearArea(target);  // draw target and scissor
  ds.bounds = detail::Rect{std::max(ds.viewport.rect.x0, fbr.x0), std::max(ds.viewport.rect.y0, fbr.y0),
                           std::min(ds.viewport.rect.x1, fbr.x1), std::min(ds.viewport.rect.y1, fbr.y1)};
  ds.primitive = primitive;
  if (active_query[2]) ds.primitives_generated = &queries.at(active_query[2])->count;
  packet.bounds = ds.bounds;
  if (!frame.Accepts(target)) Sync(__func__);
  try {
    packet.snapshot = program->Snapshot();
    packet.program = packet.snapshot ? packet.snapshot.get() : program;
    packet.early_depth = detail::EarlyDepthTestApplies(ops, packet.program->WritesDepth());
    detail::RecordDraw(call, plan, ds, packet, target, frame, *pool, scratch);
  } catch (const std::bad_alloc&) {
    frame.Reset();
    SetError(OUT_OF_MEMORY, __func__, "out of memory (recorded draws not yet rendered are dropped)");
  } catch (const std::length_error&) {
    frame.Reset();
    SetError(OUT_OF_MEMORY, __func__, "out of memory (recorded draws not yet rendered are dropped)");
  }
  // A shader that cannot be copied is used as it is: render before the caller can change it.
  if (!packet.snapshot) Sync(__func__);
}

namespace {

// OpenGL 3.3 (2.9.3): reading a mapped buffer is INVALID_OPERATION. False, with the error set, when an enabled
// attribute array's buffer (or, for indexed draws, the element buffer) is mapped. Needs a bound vertex array.
bool CheckNotMapped(ContextState& s, const char* what, bool elements) {
  bool mapped = elements && s.vao->element_buffer && s.vao->element_buffer->mapped;
  for (const AttribBinding& a : s.vao->attrib) mapped = mapped || (a.enabled && a.buffer && a.buffer->mapped);
  if (mapped) return s.SetError(INVALID_OPERATION, what, "a buffer the draw reads (an enabled attribute array's or the element buffer) is mapped"), false;
  return true;
}

void DrawArraysChecked(ContextState& s, const char* what, Enum mode, int first, int count, int instances) {
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, what, "mode is not a primitive mode");
  if (first < 0 || count < 0) return s.SetError(INVALID_VALUE, what, "first or count is negative");
  if (instances < 0) return s.SetError(INVALID_VALUE, what, "instancecount is negative");
  if (s.vao == nullptr || s.program == nullptr) return s.SetError(INVALID_OPERATION, what, "needs a bound vertex array and a shader (UseProgram)");
  if (!CheckNotMapped(s, what, false)) return;
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
bool CheckElementsBound(ContextState& s, const char* what) {
  if (s.vao == nullptr || s.program == nullptr || !s.vao->element_buffer) return s.SetError(INVALID_OPERATION, what, "needs a bound vertex array with an element buffer, and a shader (UseProgram)"), false;
  return CheckNotMapped(s, what, true);
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
  if (!CheckElementsBound(s, what) || !CheckElementRange(s, what, count, type, offset)) return;
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

void Context::DrawRangeElements(Enum mode, std::uint32_t start, std::uint32_t end, int count, Enum type,
                                std::size_t offset) {
  auto& s = *state_;
  if (!CheckElements(s, __func__, mode, type)) return;
  if (count < 0) return s.SetError(INVALID_VALUE, __func__, "count is negative");
  if (end < start) return s.SetError(INVALID_VALUE, __func__, "end is less than start");
  if (!CheckElementsBound(s, __func__) || !CheckElementRange(s, __func__, count, type, offset)) return;
  DrawIndexed(s, __func__, mode, count, type, offset, 0);
}

void Context::MultiDrawArrays(Enum mode, const int* first, const int* count, int drawcount) {
  auto& s = *state_;
  if (detail::VerticesPerPrimitive(mode) == 0) return s.SetError(INVALID_ENUM, __func__, "mode is not a primitive mode");
  if (drawcount < 0) return s.SetError(INVALID_VALUE, __func__, "drawcount is negative");
  if (drawcount > 0 && (first == nullptr || count == nullptr)) return s.SetError(INVALID_VALUE, __func__, "first or count is null");
  for (int i = 0; i < drawcount; ++i)
    if (first[i] < 0 || count[i] < 0) return s.SetError(INVALID_VALUE, __func__, "a first or count is negative");
  if (s.vao == nullptr || s.program == nullptr) return s.SetError(INVALID_OPERATION, __func__, "needs a bound vertex array and a shader (UseProgram)");
  if (!CheckNotMapped(s, __func__, false)) return;
  for (int i = 0; i < drawcount; ++i) DrawArrays(mode, first[i], count[i]);
}

void Context::MultiDrawElements(Enum mode, const int* count, Enum type, const std::size_t* offsets, int drawcount) {
  auto& s = *state_;
  if (!CheckElements(s, __func__, mode, type)) return;
  if (drawcount < 0) return s.SetError(INVALID_VALUE, __func__, "drawcount is negative");
  if (drawcount > 0 && (count == nullptr || offsets == nullptr)) return s.SetError(INVALID_VALUE, __func__, "count or offsets is null");
  for (int i = 0; i < drawcount; ++i)
    if (count[i] < 0) return s.SetError(INVALID_VALUE, __func__, "a count is negative");
  if (!CheckElementsBound(s, __func__)) return;
  for (int i = 0; i < drawcount; ++i)
    if (!CheckElementRange(s, __func__, count[i], type, offsets[i])) return;
  for (int i = 0; i < drawcount; ++i) DrawIndexed(s, __func__, mode, count[i], type, offsets[i], 0);
}

// ---- State queries -------------------------------------------------------------------------------------------

namespace {

// One piece of state as OpenGL's Get* calls see it: up to 4 values of one kind. kNormalized values (colours and
// depths in [0, 1] or [-1, 1]) map to integers linearly rather than by rounding (OpenGL 4.6, section 2.2.2).
struct StateValue {
  enum class Kind { kBool, kInt, kFloat, kNormalized } kind = Kind::kInt;
  double v[4] = {0, 0, 0, 0};
  int count = 0;
};

template <class Map, class Ptr>
std::uint32_t IdOf(const Map& map, const Ptr* object) {
  if (object == nullptr) return 0;
  for (const auto& [id, held] : map)
    if (held.get() == object) return id;
  return 0;
}

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
    case VERTEX_ARRAY_BINDING: return integer(s.vao_id);
    case ACTIVE_TEXTURE: return integer(TEXTURE0 + Enum(s.active_unit));
    case TEXTURE_BINDING_2D: return integer(IdOf(s.textures, s.units[s.active_unit].tex_2d.get()));
    case TEXTURE_BINDING_CUBE_MAP: return integer(IdOf(s.textures, s.units[s.active_unit].cube.get()));
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
    case BLEND_COLOR: return put(Kind::kNormalized, {blend.color.r, blend.color.g, blend.color.b, blend.color.a});
    case COLOR_CLEAR_VALUE: return put(Kind::kNormalized, {s.clear_color[0], s.clear_color[1], s.clear_color[2], s.clear_color[3]});
    case COLOR_WRITEMASK: {
      const bool* m = s.ops.color_mask;
      return put(Kind::kBool, {double(m[0]), double(m[1]), double(m[2]), double(m[3])});
    }
    case UNPACK_ALIGNMENT: return integer(s.unpack_alignment);
    case PACK_ALIGNMENT: return integer(s.pack_alignment);
    case PACK_ROW_LENGTH: return integer(s.pack_row_length);
    case PACK_SKIP_ROWS: return integer(s.pack_skip_rows);
    case PACK_SKIP_PIXELS: return integer(s.pack_skip_pixels);
    // Limits.
    case MAX_VERTEX_ATTRIBS: return integer(kMaxVertexAttribs);
    case MAX_TEXTURE_SIZE:
    case MAX_CUBE_MAP_TEXTURE_SIZE: return integer(kMaxTextureSize);
    case MAX_TEXTURE_IMAGE_UNITS:
    case MAX_VERTEX_TEXTURE_IMAGE_UNITS:
    case MAX_COMBINED_TEXTURE_IMAGE_UNITS: return integer(kMaxTextureUnits);
    case MAX_DRAW_BUFFERS:
    case MAX_COLOR_ATTACHMENTS: return integer(kMaxColorOutputs);
    case MAX_SAMPLES: return integer(1);  // no multisampling
    case MAX_RENDERBUFFER_SIZE: return integer(kMaxFramebufferSize);
    case MAX_VIEWPORT_DIMS: return put(Kind::kInt, {double(kMaxFramebufferSize), double(kMaxFramebufferSize)});
    case MAX_VARYING_COMPONENTS: return integer(kMaxVaryingFloats);
    case MAX_ELEMENTS_VERTICES:
    case MAX_ELEMENTS_INDICES: return integer(detail::kDrawChunk);  // larger draws work, in pieces
    case POINT_SIZE_RANGE: return put(Kind::kFloat, {1.0, double(detail::kMaxPointSize)});
    case ALIASED_LINE_WIDTH_RANGE: return put(Kind::kFloat, {1.0, 1.0});
    case SUBPIXEL_BITS: return integer(8);  // vertices snap to 1/256 pixel
    case MAJOR_VERSION: return integer(3);
    case MINOR_VERSION: return integer(3);
    case NUM_EXTENSIONS: return integer(0);
    case CONTEXT_PROFILE_MASK: return integer(1);  // CONTEXT_CORE_PROFILE_BIT
    default: return false;
  }
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
  if (v.kind == StateValue::Kind::kNormalized) return std::int64_t(std::clamp(d, -1.0, 1.0) * 2147483647.0);
  return std::llround(std::clamp(d, -9.2e18, 9.2e18));
}

}  // namespace

void Context::GetIntegerv(Enum pname, int* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || data == nullptr) return;
  for (int i = 0; i < v.count; ++i) data[i] = int(std::clamp<std::int64_t>(ToInteger(v, i), INT32_MIN, INT32_MAX));
}

void Context::GetInteger64v(Enum pname, std::int64_t* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || data == nullptr) return;
  for (int i = 0; i < v.count; ++i) data[i] = ToInteger(v, i);
}

void Context::GetFloatv(Enum pname, float* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || data == nullptr) return;
  for (int i = 0; i < v.count; ++i) data[i] = float(v.v[i]);
}

void Context::GetBooleanv(Enum pname, bool* data) const {
  StateValue v;
  if (!Query(*state_, __func__, pname, v) || data == nullptr) return;
  for (int i = 0; i < v.count; ++i) data[i] = v.v[i] != 0.0;
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
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED or TIME_ELAPSED");
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
    case 2: q.count = 0; break;
    default:  // the time of the work between BeginQuery and EndQuery, rendering included
      s.Sync(__func__);
      q.start = std::chrono::steady_clock::now();
      break;
  }
}

void Context::EndQuery(Enum target) {
  auto& s = *state_;
  const int slot = QuerySlot(target);
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED or TIME_ELAPSED");
  if (!s.active_query[slot]) return s.SetError(INVALID_OPERATION, __func__, "no query is active on target");
  QueryObject& q = *s.queries.at(s.active_query[slot]);
  s.active_query[slot] = 0;
  q.active = false;
  if (slot == 3) {
    s.Sync(__func__);
    q.elapsed_ns = std::uint64_t(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - q.start).count());
  }
}

void Context::GetQueryiv(Enum target, Enum pname, int* params) const {
  auto& s = *state_;
  const int slot = QuerySlot(target);
  if (slot < 0) return s.SetError(INVALID_ENUM, __func__, "target must be SAMPLES_PASSED, ANY_SAMPLES_PASSED, PRIMITIVES_GENERATED or TIME_ELAPSED");
  if (pname != CURRENT_QUERY && pname != QUERY_COUNTER_BITS) return s.SetError(INVALID_ENUM, __func__, "pname must be CURRENT_QUERY or QUERY_COUNTER_BITS");
  if (params != nullptr) *params = pname == CURRENT_QUERY ? int(s.active_query[slot]) : 64;
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
    case 2: out = q.count; break;
    default: out = q.elapsed_ns; break;
  }
  return true;
}

}  // namespace

void Context::GetQueryObjectiv(std::uint32_t id, Enum pname, int* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && params) *params = int(std::min<std::uint64_t>(v, INT32_MAX));
}

void Context::GetQueryObjectuiv(std::uint32_t id, Enum pname, std::uint32_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && params) *params = std::uint32_t(std::min<std::uint64_t>(v, UINT32_MAX));
}

void Context::GetQueryObjecti64v(std::uint32_t id, Enum pname, std::int64_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && params) *params = std::int64_t(std::min<std::uint64_t>(v, INT64_MAX));
}

void Context::GetQueryObjectui64v(std::uint32_t id, Enum pname, std::uint64_t* params) {
  std::uint64_t v = 0;
  if (QueryResult(*state_, __func__, id, pname, v) && params) *params = v;
}

// ---- Reading back --------------------------------------------------------------------------------------------

namespace {

// What ReadPixels and friends read: the context's framebuffer, or the framebuffer object bound for reading (its
// read buffer as color[0], depth and stencil; nothing when it is incomplete). color[0] is absent when the read
// buffer is NONE or names an empty attachment.
detail::RenderTarget ReadTarget(ContextState& s) {
  if (!s.read_fbo) {
    detail::RenderTarget t = s.fb.Target();
    if (s.default_read_buffer == NONE) t.color[0] = detail::ColorBuffer{};
    return t;
  }
  if (FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return {};
  FramebufferObject reading = *s.read_fbo;  // reads the read buffer whatever the draw buffers say
  reading.draw_buffers[0] = reading.read_buffer;
  for (int i = 1; i < kMaxColorOutputs; ++i) reading.draw_buffers[i] = NONE;
  return FramebufferTarget(reading);
}
}  // namespace

Image Context::ReadPixels() const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_);
  Image image;
  if (!t.color[0].Present() || t.width <= 0 || t.height <= 0) return image;
  image.width = t.width;
  image.height = t.height;
  image.rgba.resize(std::size_t(t.width) * std::size_t(t.height) * 4);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x) {
      const glm::vec4 c = t.color[0].Load(x, y);
      std::uint8_t* dst = image.rgba.data() + (std::size_t(t.height - 1 - y) * std::size_t(t.width) + x) * 4;
      for (int k = 0; k < 4; ++k) dst[k] = detail::FloatToUnorm8(c[k]);
    }
  return image;
}

void Context::ReadPixel(int x, int y, std::uint8_t rgba[4]) const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_);
  std::memset(rgba, 0, 4);
  if (!t.color[0].Present() || x < 0 || y < 0 || x >= t.width || y >= t.height) return;
  const glm::vec4 c = t.color[0].Load(x, y);
  for (int k = 0; k < 4; ++k) rgba[k] = detail::FloatToUnorm8(c[k]);
}

namespace {

// How ReadPixels lays out one pixel: which RGBA channels, in order (-1 ends), or depth and/or stencil.
struct PixelLayout {
  int channels[4] = {-1, -1, -1, -1};
  int count = 0;  // components per pixel (DEPTH_STENCIL with UNSIGNED_INT_24_8: one 32-bit word)
  bool depth = false, stencil = false;
};

bool LayoutOf(Enum format, PixelLayout& l) {
  auto set = [&](std::initializer_list<int> c) {
    for (int k : c) l.channels[l.count++] = k;
    return true;
  };
  switch (format) {
    case RED: return set({0});
    case GREEN: return set({1});
    case BLUE: return set({2});
    case RG: return set({0, 1});
    case RGB: return set({0, 1, 2});
    case BGR: return set({2, 1, 0});
    case RGBA: return set({0, 1, 2, 3});
    case BGRA: return set({2, 1, 0, 3});
    case DEPTH_COMPONENT: l.depth = true; l.count = 1; return true;
    case STENCIL_INDEX: l.stencil = true; l.count = 1; return true;
    case DEPTH_STENCIL: l.depth = l.stencil = true; l.count = 1; return true;
    default: return false;
  }
}

// Writes normalized value v (clamped to [0, 1]) or, for stencil indices, the integer value as `type`.
void PutComponent(Enum type, double v, bool integer, std::uint8_t* dst) {
  switch (type) {
    case UNSIGNED_BYTE: {
      const auto b = std::uint8_t(integer ? v : std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
      *dst = b;
      break;
    }
    case UNSIGNED_SHORT: {
      const auto h = std::uint16_t(integer ? v : std::lround(std::clamp(v, 0.0, 1.0) * 65535.0));
      std::memcpy(dst, &h, 2);
      break;
    }
    case UNSIGNED_INT: {
      const auto u = std::uint32_t(integer ? v : std::llround(std::clamp(v, 0.0, 1.0) * 4294967295.0));
      std::memcpy(dst, &u, 4);
      break;
    }
    default: {  // FLOAT
      const auto f = float(v);
      std::memcpy(dst, &f, 4);
      break;
    }
  }
}

// OpenGL's pack layout: rows of PACK_ROW_LENGTH (or width) pixels, each row aligned to PACK_ALIGNMENT when a
// component is smaller than the alignment, starting PACK_SKIP_ROWS rows and PACK_SKIP_PIXELS pixels in.
struct PackLayout {
  std::uint8_t* out;
  std::size_t stride, pixel, component;
  std::uint8_t* At(int i, int j) const { return out + std::size_t(j) * stride + std::size_t(i) * pixel; }
};
PackLayout Pack(const ContextState& s, int width, const PixelLayout& l, Enum type, void* pixels) {
  PackLayout p;
  p.component = type == UNSIGNED_BYTE ? 1 : type == UNSIGNED_SHORT ? 2 : 4;
  p.pixel = p.component * std::size_t(l.count);
  p.stride = std::size_t(s.pack_row_length > 0 ? s.pack_row_length : width) * p.pixel;
  const std::size_t align = std::size_t(s.pack_alignment);
  if (p.component < align) p.stride = (p.stride + align - 1) / align * align;
  p.out = static_cast<std::uint8_t*>(pixels) + std::size_t(s.pack_skip_rows) * p.stride +
          std::size_t(s.pack_skip_pixels) * p.pixel;
  return p;
}

}  // namespace

void Context::ReadPixels(int x, int y, int width, int height, Enum format, Enum type, void* pixels) const {
  auto& s = *state_;
  PixelLayout l;
  if (!LayoutOf(format, l)) return s.SetError(INVALID_ENUM, __func__, "not a pixel format ReadPixels knows");
  if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT && type != FLOAT &&
      type != UNSIGNED_INT_24_8)
    return s.SetError(INVALID_ENUM, __func__, "type must be UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT or UNSIGNED_INT_24_8");
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE, __func__, "width or height is negative");
  if ((format == DEPTH_STENCIL) != (type == UNSIGNED_INT_24_8)) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL goes with UNSIGNED_INT_24_8, and only it");
  if (s.read_fbo && FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return s.SetError(INVALID_FRAMEBUFFER_OPERATION, __func__, "the read framebuffer is not complete");
  s.Sync(__func__);
  const detail::RenderTarget t = ReadTarget(s);
  if ((l.depth && !t.depth) || (l.stencil && !t.stencil) || (l.count > 0 && !l.depth && !l.stencil && !t.color[0].Present()))
    return s.SetError(INVALID_OPERATION, __func__, "the read framebuffer has no buffer of that kind");
  if (pixels == nullptr || width == 0 || height == 0) return;
  const PackLayout pack = Pack(s, width, l, type, pixels);
  const std::size_t component = pack.component;
  // Only pixels inside the read buffer are written (the others are undefined in OpenGL: left as they are).
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = int(std::min<std::int64_t>(std::int64_t(x) + width, t.width));
  const int y1 = int(std::min<std::int64_t>(std::int64_t(y) + height, t.height));
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px) {
      std::uint8_t* dst = pack.At(px - x, py - y);
      if (format == DEPTH_STENCIL) {
        const double d = std::clamp(double(t.Depth(px, py)), 0.0, 1.0);
        const std::uint32_t word = std::uint32_t(std::llround(d * 16777215.0)) << 8 | t.Stencil(px, py);
        std::memcpy(dst, &word, 4);
      } else if (l.depth) {
        PutComponent(type, double(t.Depth(px, py)), false, dst);
      } else if (l.stencil) {
        PutComponent(type, double(t.Stencil(px, py)), true, dst);
      } else {
        const glm::vec4 c = t.color[0].Load(px, py);
        // A fixed-point buffer's b / 255 gives back b for UNSIGNED_BYTE; a float buffer's values are clamped only
        // when converted to a normalized type.
        for (int k = 0; k < l.count; ++k)
          PutComponent(type, double(c[l.channels[k]]), false, dst + std::size_t(k) * component);
      }
    }
}

void Context::GetTexImage(Enum target, int level, Enum format, Enum type, void* pixels) const {
  auto& s = *state_;
  if (!IsTexImageTarget(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  PixelLayout l;
  if (!LayoutOf(format, l) || (l.stencil && !l.depth)) return s.SetError(INVALID_ENUM, __func__, "format must be a colour format, DEPTH_COMPONENT or DEPTH_STENCIL");
  if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT && type != FLOAT && type != UNSIGNED_INT_24_8)
    return s.SetError(INVALID_ENUM, __func__, "type must be UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT or UNSIGNED_INT_24_8");
  if ((format == DEPTH_STENCIL) != (type == UNSIGNED_INT_24_8)) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL goes with UNSIGNED_INT_24_8, and only it");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  const detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  const detail::TextureLevel& lv = tex->levels[face][level];
  if (!lv.Defined() || pixels == nullptr) return;  // an undefined level has no texels to return
  if (detail::IsDepthFormat(lv.format) != l.depth) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_COMPONENT for a colour texture, or the reverse");
  if (l.stencil && lv.stencil.empty()) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL for a texture without stencil");
  s.Sync(__func__);  // a texture being rendered into holds its texels once the recorded draws are rendered
  const PackLayout pack = Pack(s, lv.width, l, type, pixels);
  for (int j = 0; j < lv.height; ++j)
    for (int i = 0; i < lv.width; ++i) {
      const glm::vec4 c = lv.Texel(i, j);
      std::uint8_t* dst = pack.At(i, j);
      if (l.stencil) {
        const double d = std::clamp(double(c.r), 0.0, 1.0);
        const std::uint32_t word = std::uint32_t(std::llround(d * 16777215.0)) << 8 |
                                   lv.stencil[std::size_t(j) * std::size_t(lv.width) + std::size_t(i)];
        std::memcpy(dst, &word, 4);
      } else if (l.depth) {
        PutComponent(type, double(c.r), false, dst);
      } else {
        for (int k = 0; k < l.count; ++k)
          PutComponent(type, double(c[l.channels[k]]), false, dst + std::size_t(k) * pack.component);
      }
    }
}

namespace {

// The checks CopyTexImage2D and CopyTexSubImage2D share about the read framebuffer: complete, and holding the kind
// of buffer the texture needs. False with the error set otherwise.
bool CheckCopySource(ContextState& s, const char* what, bool depth) {
  if (s.read_fbo && FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return s.SetError(INVALID_FRAMEBUFFER_OPERATION, what, "the read framebuffer is not complete"), false;
  const detail::RenderTarget t = ReadTarget(s);
  if (depth ? !t.depth : !t.color[0].Present()) return s.SetError(INVALID_OPERATION, what, "the read framebuffer has no buffer of the texture's kind"), false;
  return true;
}

// Copies the read framebuffer's rectangle (x, y, w, h) into level `lv` at (xo, yo); checked already. Pixels outside
// the framebuffer (undefined in OpenGL) copy as zero.
void CopyToLevel(ContextState& s, const char* what, detail::TextureLevel& lv, int xo, int yo, int x, int y, int w, int h) {
  s.Sync(what);
  const detail::RenderTarget t = ReadTarget(s);
  const bool depth = detail::IsDepthFormat(lv.format);
  std::vector<float> rect(std::size_t(w) * std::size_t(h) * (depth ? 1 : 4), 0.0f);  // read first: the
  for (int j = 0; j < h; ++j)                                                          // source may be lv itself
    for (int i = 0; i < w; ++i) {
      const int px = x + i, py = y + j;
      if (px < 0 || py < 0 || px >= t.width || py >= t.height) continue;
      float* dst = rect.data() + (std::size_t(j) * std::size_t(w) + std::size_t(i)) * (depth ? 1 : 4);
      if (depth) {
        *dst = t.Depth(px, py);
      } else {
        const glm::vec4 c = t.color[0].Load(px, py);
        for (int k = 0; k < 4; ++k) dst[k] = c[k];
      }
    }
  detail::UploadPixels(lv, xo, yo, w, h, depth ? DEPTH_COMPONENT : RGBA, FLOAT, 4, rect.data());
  if (lv.stencil.empty() || !t.stencil) return;  // a depth-stencil texture takes the stencil indices too
  std::vector<std::uint8_t> indices(std::size_t(w) * std::size_t(h), 0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const int px = x + i, py = y + j;
      if (px >= 0 && py >= 0 && px < t.width && py < t.height)
        indices[std::size_t(j) * std::size_t(w) + std::size_t(i)] = t.Stencil(px, py);
    }
  for (int j = 0; j < h; ++j)
    std::memcpy(lv.stencil.data() + std::size_t(yo + j) * std::size_t(lv.width) + std::size_t(xo),
                indices.data() + std::size_t(j) * std::size_t(w), std::size_t(w));
}

}  // namespace

void Context::CopyTexSubImage2D(Enum target, int level, int xoffset, int yoffset, int x, int y, int width,
                                int height) {
  auto& s = *state_;
  if (!IsTexImageTarget(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex || !tex->levels[face][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[face][level];
  if (xoffset < 0 || yoffset < 0 || width < 0 || height < 0 || std::int64_t(xoffset) + width > lv.width ||
      std::int64_t(yoffset) + height > lv.height)
    return s.SetError(INVALID_VALUE, __func__, "the rectangle is outside the level");
  if (!CheckCopySource(s, __func__, detail::IsDepthFormat(lv.format))) return;
  try {
    CopyToLevel(s, __func__, lv, xoffset, yoffset, x, y, width, height);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::CopyTexImage2D(Enum target, int level, Enum internal_format, int x, int y, int width, int height,
                             int border) {
  auto& s = *state_;
  if (!IsTexImageTarget(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || height < 0 || width > kMaxTextureSize ||
      height > kMaxTextureSize || border != 0 || detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (CubeFaceIndex(target) >= 0 && width != height) return s.SetError(INVALID_VALUE, __func__, "cube map faces must be square");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  if (!CheckCopySource(s, __func__, detail::IsDepthFormat(internal_format))) return;
  try {
    s.Sync(__func__);  // the old level may be what recorded draws sample or render into
    detail::TextureLevel next;
    next.Allocate(internal_format, width, height);
    CopyToLevel(s, __func__, next, 0, 0, x, y, width, height);
    tex->levels[face][level] = std::move(next);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

float Context::ReadDepth(int x, int y) const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_);
  if (!t.depth || x < 0 || y < 0 || x >= t.width || y >= t.height) return 0.0f;
  return t.Depth(x, y);
}

std::uint8_t Context::ReadStencil(int x, int y) const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_);
  if (!t.stencil || x < 0 || y < 0 || x >= t.width || y >= t.height) return 0;
  return t.Stencil(x, y);
}

// ---- Textures ------------------------------------------------------------------------------------------------

std::uint32_t Context::GenTexture() {
  return NewId(state_->textures, state_->next_texture, [] { return std::make_shared<detail::TextureObject>(); });
}

void Context::GenTextures(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenTexture(); });
}

void Context::DeleteTexture(std::uint32_t texture) {
  state_->Sync(__func__);
  auto& s = *state_;
  auto it = s.textures.find(texture);
  if (it == s.textures.end()) return;
  const detail::TextureObject* dead = it->second.get();
  for (TextureUnit& u : s.units) {
    if (u.tex_2d.get() == dead) u.tex_2d.reset();
    if (u.cube.get() == dead) u.cube.reset();
  }
  for (FramebufferObject* f : {s.draw_fbo, s.read_fbo}) {
    if (!f) continue;
    for (Attachment& a : f->color)
      if (a.texture.get() == dead) a = Attachment{};
    if (f->depth.texture.get() == dead) f->depth = Attachment{};
    if (f->stencil.texture.get() == dead) f->stencil = Attachment{};
  }
  s.textures.erase(it);
}

bool Context::IsTexture(std::uint32_t texture) const { return state_->textures.count(texture) != 0; }

void Context::ActiveTexture(Enum unit) {
  if (unit < TEXTURE0 || unit >= TEXTURE0 + kMaxTextureUnits) return state_->SetError(INVALID_ENUM, __func__, "unit must be TEXTURE0 + i with i below kMaxTextureUnits");
  state_->active_unit = int(unit - TEXTURE0);
}

void Context::BindTexture(Enum target, std::uint32_t texture) {
  auto& s = *state_;
  if (target != TEXTURE_2D && target != TEXTURE_CUBE_MAP) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or TEXTURE_CUBE_MAP");
  std::shared_ptr<detail::TextureObject> object;
  if (texture != 0) {
    auto it = s.textures.find(texture);
    if (it == s.textures.end()) return s.SetError(INVALID_OPERATION, __func__, "not a texture id made by GenTexture (or it was deleted)");
    if (it->second->target != 0 && it->second->target != target) return s.SetError(INVALID_OPERATION, __func__, "the texture was first bound to the other target");
    it->second->target = target;
    object = it->second;
  }
  TextureUnit& u = s.units[s.active_unit];
  (target == TEXTURE_2D ? u.tex_2d : u.cube) = std::move(object);
}

namespace {

// TexImage2D's and TexSubImage2D's client data: RED, RG, RGB, RGBA or DEPTH_COMPONENT as UNSIGNED_BYTE or FLOAT,
// or DEPTH_STENCIL as UNSIGNED_INT_24_8 or FLOAT_32_UNSIGNED_INT_24_8_REV. False with the error recorded otherwise.
bool CheckTransfer(ContextState& s, const char* what, Enum format, Enum type) {
  const bool packed = type == UNSIGNED_INT_24_8 || type == FLOAT_32_UNSIGNED_INT_24_8_REV;
  if (detail::TransferComponents(format) == 0 || (type != UNSIGNED_BYTE && type != FLOAT && !packed))
    return s.SetError(INVALID_ENUM, what, "format must be RED, RG, RGB, RGBA, DEPTH_COMPONENT or DEPTH_STENCIL and type UNSIGNED_BYTE, FLOAT, UNSIGNED_INT_24_8 or FLOAT_32_UNSIGNED_INT_24_8_REV"), false;
  if ((format == DEPTH_STENCIL) != packed)
    return s.SetError(INVALID_OPERATION, what, "DEPTH_STENCIL data goes with UNSIGNED_INT_24_8 or FLOAT_32_UNSIGNED_INT_24_8_REV, and only it"), false;
  return true;
}

bool IsDepthTransfer(Enum format) { return format == DEPTH_COMPONENT || format == DEPTH_STENCIL; }

}  // namespace

void Context::TexImage2D(Enum target, int level, Enum internal_format, int width, int height, int border,
                         Enum format, Enum type, const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!IsTexImageTarget(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || height < 0 || width > kMaxTextureSize ||
      height > kMaxTextureSize || border != 0 || detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (detail::IsDepthFormat(internal_format) != IsDepthTransfer(format)) return s.SetError(INVALID_OPERATION, __func__, "depth data for a colour format, or the reverse");
  if (CubeFaceIndex(target) >= 0 && width != height) return s.SetError(INVALID_VALUE, __func__, "cube map faces must be square");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  detail::TextureLevel next;
  try {
    next.Allocate(internal_format, width, height);
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
  detail::UploadPixels(next, 0, 0, width, height, format, type, s.unpack_alignment, pixels);
  tex->levels[face][level] = std::move(next);
}

void Context::TexSubImage2D(Enum target, int level, int x, int y, int width, int height, Enum format, Enum type,
                            const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!IsTexImageTarget(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex || !tex->levels[face][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[face][level];
  if (detail::IsDepthFormat(lv.format) != IsDepthTransfer(format)) return s.SetError(INVALID_OPERATION, __func__, "depth data for a colour texture, or the reverse");
  if (x < 0 || y < 0 || width < 0 || height < 0 || std::int64_t(x) + width > lv.width ||
      std::int64_t(y) + height > lv.height)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  detail::UploadPixels(lv, x, y, width, height, format, type, s.unpack_alignment, pixels);
}

namespace {

// Defines level 0 of the texture bound to target from a decoded image: 1 to 4 channels as R8, RG8, RGB8, RGBA8,
// HDR as RGBA32F.
bool TexImageFromLoaded(Context& gl, ContextState& s, Enum target, const detail::LoadedImage& img,
                        const std::string& name, std::string* error) {
  if (img.width > kMaxTextureSize || img.height > kMaxTextureSize || img.channels < 1 || img.channels > 4) {
    s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
    if (error) *error = name + ": larger than kMaxTextureSize, or an unsupported channel count";
    return false;
  }
  static constexpr Enum kFormats[4] = {RED, RG, RGB, RGBA};
  static constexpr Enum kInternal[4] = {R8, RG8, RGB8, RGBA8};
  const Enum format = kFormats[img.channels - 1];
  const Enum internal = img.hdr ? RGBA32F : kInternal[img.channels - 1];
  const int saved_alignment = s.unpack_alignment;
  s.unpack_alignment = 1;
  const Enum before = s.error;
  gl.TexImage2D(target, 0, internal, img.width, img.height, 0, format, img.hdr ? FLOAT : UNSIGNED_BYTE,
                img.hdr ? static_cast<const void*>(img.floats.data()) : static_cast<const void*>(img.bytes.data()));
  s.unpack_alignment = saved_alignment;
  if (s.error != before) {
    if (error) *error = name + ": the texture could not be defined";
    return false;
  }
  return true;
}

}  // namespace

namespace {

// TexImage2DFromFile and TexImage2DFromMemory: checks the target and binding, decodes with `decode`, defines level 0.
template <class Decode>
bool TexImageFromDecoded(Context& gl, ContextState& s, Enum target, const std::string& name, std::string* error,
                         const char* call, Decode&& decode) {
  auto refuse = [&](Enum code, const char* message) {
    s.SetError(code, call, message);
    if (error) *error = message;
    return false;
  };
  if (!IsTexImageTarget(target)) return refuse(INVALID_ENUM, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (!s.Bound(target)) return refuse(INVALID_OPERATION, "no texture is bound to that target of the active unit");
  detail::LoadedImage img;
  try {
    if (!decode(img)) return false;
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, call, "out of memory");
    if (error) *error = name + ": out of memory";
    return false;
  }
  return TexImageFromLoaded(gl, s, target, img, name, error);
}

}  // namespace

bool Context::TexImage2DFromFile(Enum target, const std::string& path, bool flip_vertically, std::string* error) {
  return TexImageFromDecoded(*this, *state_, target, path, error, __func__, [&](detail::LoadedImage& img) {
    return detail::LoadImageFile(path, flip_vertically, img, error);
  });
}

bool Context::TexImage2DFromMemory(Enum target, const void* data, std::size_t size, bool flip_vertically,
                                   std::string* error) {
  const std::string name = "image in memory";
  return TexImageFromDecoded(*this, *state_, target, name, error, __func__, [&](detail::LoadedImage& img) {
    return detail::LoadImageMemory(data, size, name, flip_vertically, img, error);
  });
}

void Context::GenerateMipmap(Enum target) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_2D && target != TEXTURE_CUBE_MAP) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or TEXTURE_CUBE_MAP");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  const int base = tex->params.base_level;
  if (base < 0 || base >= detail::kMaxLevels) return s.SetError(INVALID_OPERATION, __func__, "the base level is out of range");
  for (int f = 0; f < tex->Faces(); ++f) {
    const detail::TextureLevel& b = tex->levels[f][base];
    const detail::TextureLevel& b0 = tex->levels[0][base];
    if (!b.Defined() || b.width != b0.width || b.height != b0.height || b.format != b0.format)
      return s.SetError(INVALID_OPERATION, __func__, "not allowed in the current state");
  }
  try {
    detail::GenerateMipmaps(*tex);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

namespace {

bool IsMinFilter(int v) {
  return v == NEAREST || v == LINEAR || v == NEAREST_MIPMAP_NEAREST || v == LINEAR_MIPMAP_NEAREST ||
         v == NEAREST_MIPMAP_LINEAR || v == LINEAR_MIPMAP_LINEAR;
}
bool IsWrap(int v) { return v == REPEAT || v == MIRRORED_REPEAT || v == CLAMP_TO_EDGE || v == CLAMP_TO_BORDER; }

}  // namespace

void Context::TexParameterfv(Enum target, Enum pname, const float* values) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_2D && target != TEXTURE_CUBE_MAP) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or TEXTURE_CUBE_MAP");
  if (values == nullptr) return s.SetError(INVALID_VALUE, __func__, "values is null");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  detail::SamplerParams& p = tex->params;
  const float v = values[0];
  const int iv = std::isfinite(v) ? int(std::clamp(v, -2e9f, 2e9f)) : -1;
  switch (pname) {
    case TEXTURE_MIN_FILTER:
      if (!IsMinFilter(iv)) return s.SetError(INVALID_ENUM, __func__, "not a minification filter");
      p.min_filter = Enum(iv);
      break;
    case TEXTURE_MAG_FILTER:
      if (iv != NEAREST && iv != LINEAR) return s.SetError(INVALID_ENUM, __func__, "magnification filter must be NEAREST or LINEAR");
      p.mag_filter = Enum(iv);
      break;
    case TEXTURE_WRAP_S:
    case TEXTURE_WRAP_T:
    case TEXTURE_WRAP_R:
      if (!IsWrap(iv)) return s.SetError(INVALID_ENUM, __func__, "wrap mode must be REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE or CLAMP_TO_BORDER");
      (pname == TEXTURE_WRAP_S ? p.wrap_s : pname == TEXTURE_WRAP_T ? p.wrap_t : p.wrap_r) = Enum(iv);
      break;
    case TEXTURE_BASE_LEVEL:
    case TEXTURE_MAX_LEVEL:
      if (iv < 0) return s.SetError(INVALID_VALUE, __func__, "level is negative");
      (pname == TEXTURE_BASE_LEVEL ? p.base_level : p.max_level) = iv;
      break;
    case TEXTURE_MIN_LOD:
    case TEXTURE_MAX_LOD:
    case TEXTURE_LOD_BIAS:
      if (std::isnan(v)) return s.SetError(INVALID_VALUE, __func__, "value is NaN");
      (pname == TEXTURE_MIN_LOD ? p.min_lod : pname == TEXTURE_MAX_LOD ? p.max_lod : p.lod_bias) = v;
      break;
    case TEXTURE_COMPARE_MODE:
      if (iv != int(NONE) && iv != int(COMPARE_REF_TO_TEXTURE)) return s.SetError(INVALID_ENUM, __func__, "compare mode must be NONE or COMPARE_REF_TO_TEXTURE");
      p.compare_mode = Enum(iv);
      break;
    case TEXTURE_COMPARE_FUNC:
      if (iv < int(NEVER) || iv > int(ALWAYS)) return s.SetError(INVALID_ENUM, __func__, "not a comparison function");
      p.compare_func = Enum(iv);
      break;
    case TEXTURE_BORDER_COLOR: p.border = glm::vec4(values[0], values[1], values[2], values[3]); break;
    default: return s.SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
  }
}

void Context::TexParameteri(Enum target, Enum pname, int value) {
  state_->Sync(__func__);
  if (pname == TEXTURE_BORDER_COLOR) return state_->SetError(INVALID_ENUM, __func__, "TEXTURE_BORDER_COLOR takes four values: use TexParameterfv");  // four values: use TexParameterfv
  const float v = float(value);
  TexParameterfv(target, pname, &v);
}

void Context::TexParameterf(Enum target, Enum pname, float value) {
  state_->Sync(__func__);
  if (pname == TEXTURE_BORDER_COLOR) return state_->SetError(INVALID_ENUM, __func__, "TEXTURE_BORDER_COLOR takes four values: use TexParameterfv");
  TexParameterfv(target, pname, &value);
}

void Context::PixelStore(Enum pname, int value) {
  auto& s = *state_;
  switch (pname) {
    case UNPACK_ALIGNMENT:
    case PACK_ALIGNMENT:
      if (value != 1 && value != 2 && value != 4 && value != 8) return s.SetError(INVALID_VALUE, __func__, "alignment must be 1, 2, 4 or 8");
      (pname == PACK_ALIGNMENT ? s.pack_alignment : s.unpack_alignment) = value;
      return;
    case PACK_ROW_LENGTH:
    case PACK_SKIP_ROWS:
    case PACK_SKIP_PIXELS:
      if (value < 0) return s.SetError(INVALID_VALUE, __func__, "value is negative");
      (pname == PACK_ROW_LENGTH ? s.pack_row_length : pname == PACK_SKIP_ROWS ? s.pack_skip_rows : s.pack_skip_pixels) = value;
      return;
    default: return s.SetError(INVALID_ENUM, __func__, "pname must be UNPACK_ALIGNMENT, PACK_ALIGNMENT, PACK_ROW_LENGTH, PACK_SKIP_ROWS or PACK_SKIP_PIXELS");
  }
}

// ---- Framebuffer objects -------------------------------------------------------------------------------------

std::uint32_t Context::GenFramebuffer() {
  return NewId(state_->framebuffers, state_->next_framebuffer, [] { return std::make_unique<FramebufferObject>(); });
}

void Context::GenFramebuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenFramebuffer(); });
}

void Context::DeleteFramebuffer(std::uint32_t framebuffer) {
  state_->Sync(__func__);
  auto& s = *state_;
  auto it = s.framebuffers.find(framebuffer);
  if (it == s.framebuffers.end()) return;
  if (s.draw_fbo == it->second.get()) s.draw_fbo = nullptr;
  if (s.read_fbo == it->second.get()) s.read_fbo = nullptr;
  s.framebuffers.erase(it);
}

bool Context::IsFramebuffer(std::uint32_t framebuffer) const { return state_->framebuffers.count(framebuffer) != 0; }

void Context::BindFramebuffer(Enum target, std::uint32_t framebuffer) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != FRAMEBUFFER && target != DRAW_FRAMEBUFFER && target != READ_FRAMEBUFFER)
    return s.SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
  FramebufferObject* f = nullptr;
  if (framebuffer != 0) {
    auto it = s.framebuffers.find(framebuffer);
    if (it == s.framebuffers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a framebuffer id made by GenFramebuffer (or it was deleted)");
    f = it->second.get();
  }
  if (target != READ_FRAMEBUFFER) s.draw_fbo = f;
  if (target != DRAW_FRAMEBUFFER) s.read_fbo = f;
}

namespace {

// The attachment points an attachment enum names in f (two for DEPTH_STENCIL_ATTACHMENT), or none with
// INVALID_ENUM recorded.
int AttachmentSlots(ContextState& s, const char* what, FramebufferObject& f, Enum attachment, Attachment* slots[2]) {
  if (attachment >= COLOR_ATTACHMENT0 && attachment < COLOR_ATTACHMENT0 + kMaxColorOutputs) {
    slots[0] = &f.color[attachment - COLOR_ATTACHMENT0];
    return 1;
  }
  switch (attachment) {
    case DEPTH_ATTACHMENT: slots[0] = &f.depth; return 1;
    case STENCIL_ATTACHMENT: slots[0] = &f.stencil; return 1;
    case DEPTH_STENCIL_ATTACHMENT: slots[0] = &f.depth; slots[1] = &f.stencil; return 2;
    default:
      s.SetError(INVALID_ENUM, what, "attachment must be COLOR_ATTACHMENT0..3, DEPTH_ATTACHMENT, STENCIL_ATTACHMENT or DEPTH_STENCIL_ATTACHMENT");
      return 0;
  }
}

// The attachment points `attachment` names in the framebuffer object bound to `target` (two for
// DEPTH_STENCIL_ATTACHMENT), or 0 with the error recorded: a bad target or attachment (INVALID_ENUM, checked
// first), the context's own framebuffer bound (INVALID_OPERATION).
int TargetAttachment(ContextState& s, const char* what, Enum target, Enum attachment, Attachment* slots[2]) {
  if (target != FRAMEBUFFER && target != DRAW_FRAMEBUFFER && target != READ_FRAMEBUFFER)
    return s.SetError(INVALID_ENUM, what, "target must be FRAMEBUFFER, DRAW_FRAMEBUFFER or READ_FRAMEBUFFER"), 0;
  FramebufferObject probe;
  if (AttachmentSlots(s, what, probe, attachment, slots) == 0) return 0;
  FramebufferObject* f = target == READ_FRAMEBUFFER ? s.read_fbo : s.draw_fbo;
  if (!f) return s.SetError(INVALID_OPERATION, what, "no framebuffer object is bound to target"), 0;
  return AttachmentSlots(s, what, *f, attachment, slots);
}

}  // namespace

void Context::FramebufferTexture2D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level) {
  state_->Sync(__func__);
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  const int n = TargetAttachment(s, __func__, target, attachment, slots);
  if (n == 0) return;
  if (texture == 0) {
    for (int k = 0; k < n; ++k) *slots[k] = Attachment{};
    return;
  }
  if (!IsTexImageTarget(textarget)) return s.SetError(INVALID_ENUM, __func__, "textarget must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  auto it = s.textures.find(texture);
  if (it == s.textures.end()) return s.SetError(INVALID_OPERATION, __func__, "not a texture id made by GenTexture (or it was deleted)");
  const Enum kind = textarget == TEXTURE_2D ? TEXTURE_2D : TEXTURE_CUBE_MAP;
  if (it->second->target != kind) return s.SetError(INVALID_OPERATION, __func__, "textarget does not match the texture (2D or cube map)");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  for (int k = 0; k < n; ++k) {
    *slots[k] = Attachment{};
    slots[k]->texture = it->second;
    slots[k]->face = kind == TEXTURE_2D ? 0 : CubeFaceIndex(textarget);
    slots[k]->level = level;
  }
}

void Context::FramebufferRenderbuffer(Enum target, Enum attachment, Enum renderbuffer_target,
                                      std::uint32_t renderbuffer) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (renderbuffer_target != RENDERBUFFER) return s.SetError(INVALID_ENUM, __func__, "renderbuffer_target must be RENDERBUFFER");
  Attachment* slots[2] = {nullptr, nullptr};
  const int n = TargetAttachment(s, __func__, target, attachment, slots);
  if (n == 0) return;
  std::shared_ptr<Renderbuffer> object;
  if (renderbuffer != 0) {
    auto it = s.renderbuffers.find(renderbuffer);
    if (it == s.renderbuffers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a renderbuffer id made by GenRenderbuffer (or it was deleted)");
    object = it->second;
  }
  for (int k = 0; k < n; ++k) {
    *slots[k] = Attachment{};
    slots[k]->renderbuffer = object;
  }
}

void Context::GetFramebufferAttachmentParameteriv(Enum target, Enum attachment, Enum pname, int* params) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  const int n = TargetAttachment(s, __func__, target, attachment, slots);
  if (n == 0) return;
  const Attachment& a = *slots[0];
  if (n == 2 && (a.texture != slots[1]->texture || a.renderbuffer != slots[1]->renderbuffer || a.level != slots[1]->level || a.face != slots[1]->face))
    return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL_ATTACHMENT asked while depth and stencil hold different images");
  int v = 0;
  switch (pname) {
    case FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: v = int(a.texture ? TEXTURE : a.renderbuffer ? RENDERBUFFER : NONE); break;
    case FRAMEBUFFER_ATTACHMENT_OBJECT_NAME:
      v = int(a.texture ? IdOf(s.textures, a.texture.get()) : IdOf(s.renderbuffers, a.renderbuffer.get()));
      break;
    case FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL:
    case FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
      if (!a.texture) return s.SetError(a.Present() ? INVALID_ENUM : INVALID_OPERATION, __func__, "no texture is attached there");
      v = pname == FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL ? a.level
          : a.texture->target == TEXTURE_CUBE_MAP     ? int(TEXTURE_CUBE_MAP_POSITIVE_X) + a.face
                                                      : 0;
      break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname must be FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, _OBJECT_NAME, _TEXTURE_LEVEL or _TEXTURE_CUBE_MAP_FACE");
  }
  if (params) *params = v;
}

// ---- Renderbuffers -------------------------------------------------------------------------------------------

namespace {

// The sized format RenderbufferStorage stores for `f` (an unsized base format takes its 8-bit or 24-bit size, as
// Mesa does), or 0 when drawing cannot render to it.
Enum SizedRenderbufferFormat(Enum f) {
  switch (f) {
    case RGBA: return RGBA8;
    case RGB: return RGB8;
    case RG: return RG8;
    case RED: return R8;
    case DEPTH_COMPONENT: return DEPTH_COMPONENT24;
    case DEPTH_STENCIL: return DEPTH24_STENCIL8;
    case STENCIL_INDEX: return STENCIL_INDEX8;
    case RGBA8: case RGB8: case RG8: case R8: case RGBA32F: case R32F: case DEPTH_COMPONENT16:
    case DEPTH_COMPONENT24: case DEPTH_COMPONENT32F: case DEPTH24_STENCIL8: case DEPTH32F_STENCIL8:
    case STENCIL_INDEX8: return f;
    default: return 0;
  }
}

// Bits of a sized format's red, green, blue, alpha, depth and stencil, as OpenGL reports them.
struct FormatBits {
  int r = 0, g = 0, b = 0, a = 0, depth = 0, stencil = 0;
};
FormatBits BitsOf(Enum f) {
  switch (f) {
    case RGBA8: return {8, 8, 8, 8, 0, 0};
    case RGB8: return {8, 8, 8, 0, 0, 0};
    case RG8: return {8, 8, 0, 0, 0, 0};
    case R8: return {8, 0, 0, 0, 0, 0};
    case RGBA32F: return {32, 32, 32, 32, 0, 0};
    case R32F: return {32, 0, 0, 0, 0, 0};
    case DEPTH_COMPONENT16: return {0, 0, 0, 0, 16, 0};
    case DEPTH_COMPONENT:
    case DEPTH_COMPONENT24: return {0, 0, 0, 0, 24, 0};
    case DEPTH_COMPONENT32F: return {0, 0, 0, 0, 32, 0};
    case DEPTH24_STENCIL8: return {0, 0, 0, 0, 24, 8};
    case DEPTH32F_STENCIL8: return {0, 0, 0, 0, 32, 8};
    case STENCIL_INDEX8: return {0, 0, 0, 0, 0, 8};
    default: return {};
  }
}

Renderbuffer* BoundRenderbuffer(ContextState& s, const char* what, Enum target) {
  if (target != RENDERBUFFER) return s.SetError(INVALID_ENUM, what, "target must be RENDERBUFFER"), nullptr;
  if (!s.renderbuffer) return s.SetError(INVALID_OPERATION, what, "no renderbuffer is bound"), nullptr;
  return s.renderbuffer.get();
}

}  // namespace

std::uint32_t Context::GenRenderbuffer() {
  return NewId(state_->renderbuffers, state_->next_renderbuffer, [] { return std::make_shared<Renderbuffer>(); });
}

void Context::GenRenderbuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenRenderbuffer(); });
}

void Context::DeleteRenderbuffer(std::uint32_t renderbuffer) {
  state_->Sync(__func__);
  auto& s = *state_;
  auto it = s.renderbuffers.find(renderbuffer);
  if (it == s.renderbuffers.end()) return;
  const Renderbuffer* dead = it->second.get();
  if (s.renderbuffer.get() == dead) s.renderbuffer.reset();
  for (FramebufferObject* f : {s.draw_fbo, s.read_fbo}) {
    if (!f) continue;
    for (Attachment* a : {&f->color[0], &f->color[1], &f->color[2], &f->color[3], &f->depth, &f->stencil})
      if (a->renderbuffer.get() == dead) *a = Attachment{};
  }
  s.renderbuffers.erase(it);
}

bool Context::IsRenderbuffer(std::uint32_t renderbuffer) const {
  return state_->renderbuffers.count(renderbuffer) != 0;
}

void Context::BindRenderbuffer(Enum target, std::uint32_t renderbuffer) {
  auto& s = *state_;
  if (target != RENDERBUFFER) return s.SetError(INVALID_ENUM, __func__, "target must be RENDERBUFFER");
  std::shared_ptr<Renderbuffer> object;
  if (renderbuffer != 0) {
    auto it = s.renderbuffers.find(renderbuffer);
    if (it == s.renderbuffers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a renderbuffer id made by GenRenderbuffer (or it was deleted)");
    object = it->second;
  }
  s.renderbuffer = std::move(object);
}

void Context::RenderbufferStorage(Enum target, Enum internal_format, int width, int height) {
  auto& s = *state_;
  Renderbuffer* rb = BoundRenderbuffer(s, __func__, target);
  if (!rb) return;
  const Enum sized = SizedRenderbufferFormat(internal_format);
  if (sized == 0) return s.SetError(INVALID_ENUM, __func__, "internal_format is not a colour, depth or stencil format drawing can render to");
  if (width < 0 || height < 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize)
    return s.SetError(INVALID_VALUE, __func__, "width or height is negative or above MAX_RENDERBUFFER_SIZE");
  s.Sync(__func__);  // recorded draws may render into the old image
  detail::TextureLevel next;
  try {
    next.Allocate(sized, width, height);
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
  rb->image = std::move(next);
  rb->internal_format = internal_format;
}

void Context::GetRenderbufferParameteriv(Enum target, Enum pname, int* params) {
  auto& s = *state_;
  const Renderbuffer* rb = BoundRenderbuffer(s, __func__, target);
  if (!rb) return;
  const FormatBits bits = BitsOf(rb->image.format);
  int v = 0;
  switch (pname) {
    case RENDERBUFFER_WIDTH: v = rb->image.width; break;
    case RENDERBUFFER_HEIGHT: v = rb->image.height; break;
    case RENDERBUFFER_INTERNAL_FORMAT: v = int(rb->internal_format); break;
    case RENDERBUFFER_RED_SIZE: v = bits.r; break;
    case RENDERBUFFER_GREEN_SIZE: v = bits.g; break;
    case RENDERBUFFER_BLUE_SIZE: v = bits.b; break;
    case RENDERBUFFER_ALPHA_SIZE: v = bits.a; break;
    case RENDERBUFFER_DEPTH_SIZE: v = bits.depth; break;
    case RENDERBUFFER_STENCIL_SIZE: v = bits.stencil; break;
    case RENDERBUFFER_SAMPLES: v = 0; break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname is not a renderbuffer parameter");
  }
  if (params) *params = v;
}

// ---- Read buffer and blits -----------------------------------------------------------------------------------

void Context::ReadBuffer(Enum src) {
  auto& s = *state_;
  const bool attachment = src >= COLOR_ATTACHMENT0 && src < COLOR_ATTACHMENT0 + 32;
  const bool window = src == FRONT || src == BACK || src == LEFT || src == FRONT_LEFT || src == BACK_LEFT ||
                      src == FRONT_AND_BACK;
  const bool right = src == RIGHT || src == FRONT_RIGHT || src == BACK_RIGHT;
  if (src != NONE && !attachment && !window && !right) return s.SetError(INVALID_ENUM, __func__, "src must be NONE, a colour buffer of the context's framebuffer or COLOR_ATTACHMENTi");
  if (s.read_fbo) {
    if (window || right) return s.SetError(INVALID_OPERATION, __func__, "a framebuffer object is bound for reading: src must be NONE or COLOR_ATTACHMENTi");
    if (attachment && src >= COLOR_ATTACHMENT0 + kMaxColorOutputs) return s.SetError(INVALID_OPERATION, __func__, "COLOR_ATTACHMENTi with i at or above MAX_COLOR_ATTACHMENTS");
    s.read_fbo->read_buffer = src;
    return;
  }
  if (attachment || right) return s.SetError(INVALID_OPERATION, __func__, "the context's framebuffer has one colour buffer (FRONT, BACK, LEFT ...), no attachments or right buffers");
  s.default_read_buffer = src;
}

namespace {

// The depth and stencil formats BlitFramebuffer compares (OpenGL requires them to match): the bits of the read or
// draw framebuffer's depth buffer and stencil buffer, 0 where there is none. The context's framebuffer counts as
// DEPTH24_STENCIL8 (its depth is stored as float, as every depth format is).
FormatBits DepthStencilBits(const FramebufferObject* f) {
  if (!f) return BitsOf(DEPTH24_STENCIL8);
  FormatBits b;
  if (f->depth.Present()) b.depth = BitsOf(f->depth.Level()->format).depth;
  if (f->stencil.Present()) b.stencil = BitsOf(f->stencil.Level()->format).stencil;
  if (b.depth == 32) b.r = 1;  // float depth: a kind of its own (r marks it)
  return b;
}

}  // namespace

void Context::BlitFramebuffer(int src_x0, int src_y0, int src_x1, int src_y1, int dst_x0, int dst_y0, int dst_x1,
                              int dst_y1, Bitfield mask, Enum filter) {
  auto& s = *state_;
  if ((mask & ~(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT)) != 0)
    return s.SetError(INVALID_VALUE, __func__, "mask has bits other than COLOR_BUFFER_BIT, DEPTH_BUFFER_BIT and STENCIL_BUFFER_BIT");
  if (filter != NEAREST && filter != LINEAR) return s.SetError(INVALID_ENUM, __func__, "filter must be NEAREST or LINEAR");
  if (filter == LINEAR && (mask & (DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT)) != 0)
    return s.SetError(INVALID_OPERATION, __func__, "depth and stencil are blitted with NEAREST only");
  if ((s.read_fbo && FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) ||
      (s.draw_fbo && FramebufferStatus(*s.draw_fbo) != FRAMEBUFFER_COMPLETE))
    return s.SetError(INVALID_FRAMEBUFFER_OPERATION, __func__, "the read or draw framebuffer is not complete");
  s.Sync(__func__);
  const detail::RenderTarget src = ReadTarget(s);
  detail::RenderTarget dst;
  s.DrawTarget(dst);
  // A buffer missing from either framebuffer is skipped without an error (OpenGL 4.6, section 18.3.1).
  const bool depth = (mask & DEPTH_BUFFER_BIT) != 0 && src.depth && dst.depth;
  const bool stencil = (mask & STENCIL_BUFFER_BIT) != 0 && src.stencil && dst.stencil;
  if (depth || stencil) {
    const FormatBits a = DepthStencilBits(s.read_fbo), b = DepthStencilBits(s.draw_fbo);
    const bool depth_differs = a.depth != b.depth || a.r != b.r;
    if ((depth && depth_differs) || (stencil && (a.stencil != b.stencil || (a.depth && b.depth && depth_differs))))
      return s.SetError(INVALID_OPERATION, __func__, "the read and draw framebuffers' depth or stencil formats differ");
  }
  const bool color = (mask & COLOR_BUFFER_BIT) != 0 && src.color[0].Present();
  bool same = (depth && src.depth == dst.depth) || (stencil && src.stencil == dst.stencil);
  for (const detail::ColorBuffer& cb : dst.color) same = same || (color && cb.Present() && cb.data == src.color[0].data);
  // OpenGL leaves a copy between overlapping rectangles of one buffer undefined: it is refused, as OpenGL ES 3.0
  // refuses any blit within one buffer.
  auto overlaps = [](int a0, int a1, int b0, int b1) {
    return std::max(std::min(a0, a1), std::min(b0, b1)) < std::min(std::max(a0, a1), std::max(b0, b1));
  };
  if (same && overlaps(src_x0, src_x1, dst_x0, dst_x1) && overlaps(src_y0, src_y1, dst_y0, dst_y1))
    return s.SetError(INVALID_OPERATION, __func__, "the source and destination rectangles overlap in the same buffer (undefined in OpenGL)");
  detail::BlitRegion r;
  r.src[0] = src_x0, r.src[1] = src_y0, r.src[2] = src_x1, r.src[3] = src_y1;
  r.dst[0] = dst_x0, r.dst[1] = dst_y0, r.dst[2] = dst_x1, r.dst[3] = dst_y1;
  r.clip = s.ClearArea(dst);  // the draw buffers' area cut to the scissor box
  r.color = color;
  r.depth = depth;
  r.stencil = stencil;
  r.linear = filter == LINEAR;
  try {
    detail::Blit(src, dst, r);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

Enum Context::CheckFramebufferStatus(Enum target) {
  auto& s = *state_;
  if (target != FRAMEBUFFER && target != DRAW_FRAMEBUFFER && target != READ_FRAMEBUFFER) {
    s.SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
    return 0;
  }
  const FramebufferObject* f = target == READ_FRAMEBUFFER ? s.read_fbo : s.draw_fbo;
  return f ? FramebufferStatus(*f) : FRAMEBUFFER_COMPLETE;
}

void Context::DrawBuffers(int n, const Enum* bufs) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (n < 0 || n > kMaxColorOutputs) return s.SetError(INVALID_VALUE, __func__, "n must be 0 to kMaxColorOutputs");
  if (!s.draw_fbo) return s.SetError(INVALID_OPERATION, __func__, "the context's own framebuffer has no draw buffers to choose: bind a framebuffer object");
  Enum next[kMaxColorOutputs] = {NONE, NONE, NONE, NONE};
  for (int i = 0; i < n; ++i) {
    const Enum b = bufs[i];
    if (b != NONE && (b < COLOR_ATTACHMENT0 || b >= COLOR_ATTACHMENT0 + kMaxColorOutputs))
      return s.SetError(INVALID_ENUM, __func__, "an enum argument is not one this call accepts");
    for (int k = 0; k < i; ++k)
      if (b != NONE && next[k] == b) return s.SetError(INVALID_OPERATION, __func__, "an attachment appears twice");  // one attachment, one output
    next[i] = b;
  }
  std::copy(next, next + kMaxColorOutputs, s.draw_fbo->draw_buffers);
}

}  // namespace softgl

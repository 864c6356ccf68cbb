// context_state.h — the API layer's shared state: the objects created through a Context (buffers, vertex arrays,
// renderbuffers, framebuffer objects, queries), the helpers every API file needs, and ContextState, which the
// Context owns. Only the context_*.cpp files include it; each holds one family of entry points.
#pragma once

#include <softgl/context.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <new>
#include <unordered_map>
#include <vector>

#include "fragment_ops.h"
#include "framebuffer.h"
#include "pipeline.h"
#include "primitive_assembly.h"
#include "texture.h"
#include "tile_renderer.h"
#include "worker_pool.h"

namespace softgl {

struct Buffer {
  std::vector<std::uint8_t> data;
  Enum usage = STATIC_DRAW;
  // Whether a buffer texture has read this store (TexBuffer named the buffer): recorded draws may sample it, so
  // they are rendered before it changes (ContextState::BeforeStoreChange).
  bool texture_store = false;
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
  std::shared_ptr<Buffer> buffer;  // keeps a deleted buffer's store alive while referenced, as OpenGL does
  std::size_t offset = 0;
  int size = 4;
  Enum type = FLOAT;
  bool normalized = false;
  bool bgra = false;  // size BGRA (4 components, red and blue swapped)
  bool integer = false;  // VertexAttribIPointer: integers handed on as integers
  int stride = 0;
  std::uint32_t divisor = 0;  // VertexAttribDivisor
};

struct VertexArray {
  AttribBinding attrib[kMaxVertexAttribs];
  std::uint32_t enabled = 0;  // bit i: attribute array i enabled (EnableVertexAttribArray)
  std::shared_ptr<Buffer> element_buffer;
};

inline bool IsUsage(Enum usage) { return usage >= 0x88E0 && usage <= 0x88EA && (usage & 3) != 3; }

// A renderbuffer object (GenRenderbuffers): one image that drawing can render to and blits and reads can use.
struct Renderbuffer {
  detail::TextureLevel image;  // in its sized format (an unsized one resolved), with its stencil plane
  Enum internal_format = RGBA;  // as RenderbufferStorage was given it (RENDERBUFFER_INTERNAL_FORMAT)
  int samples = 0;              // RENDERBUFFER_SAMPLES: 0, or the count image has (2, 4 or 8)
};

// What a framebuffer attachment point holds: a texture's level (of one cube face), a renderbuffer, or nothing.
struct Attachment {
  std::shared_ptr<detail::TextureObject> texture;  // keeps the storage alive, as OpenGL does
  std::shared_ptr<Renderbuffer> renderbuffer;
  int face = 0;
  int level = 0;
  int layer = 0;  // FramebufferTextureLayer: the layer (or 3D slice) drawn to
  // FramebufferTexture of a cube map, array or 3D texture: every layer (cube face) is attached; drawing renders into
  // layer 0 (face and layer are 0), clears clear them all (AtLayer).
  bool layered = false;
  bool Present() const { return texture || renderbuffer; }
  /// The layers of a layered attachment: 6 for a cube map, the level's layers or slices otherwise (1 when not
  /// layered).
  int Layers() const {
    if (!layered) return 1;
    return texture->target == TEXTURE_CUBE_MAP ? 6 : Level()->depth;
  }
  /// Layer `l` of a layered attachment as an attachment of that one layer (absent past its last); itself when not
  /// layered.
  Attachment AtLayer(int l) const {
    if (!layered) return *this;
    if (l >= Layers()) return Attachment{};
    Attachment a = *this;
    a.layered = false;
    (texture->target == TEXTURE_CUBE_MAP ? a.face : a.layer) = l;
    return a;
  }
  /// Where the attached image starts in its level's planes, in texels (its layer's plane; a multisample array's
  /// layer is `samples` planes).
  std::size_t PlaneOffset() const {
    const detail::TextureLevel* l = Level();
    return l ? std::size_t(layer) * std::size_t(l->samples) * std::size_t(l->width) * std::size_t(l->height) : 0;
  }
  const detail::TextureLevel* Level() const {
    return texture ? &texture->levels[face][level] : renderbuffer ? &renderbuffer->image : nullptr;
  }
};

struct FramebufferObject {
  Attachment color[kMaxColorOutputs];
  Attachment depth, stencil;  // DEPTH_STENCIL_ATTACHMENT sets both
  Enum draw_buffers[kMaxColorOutputs] = {COLOR_ATTACHMENT0};  // the others NONE
  Enum read_buffer = COLOR_ATTACHMENT0;  // ReadBuffer: COLOR_ATTACHMENT0 + i or NONE
};

// Transform feedback's buffer bindings (MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS) and the floats a vertex may record
// interleaved (MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS) or per separate varying.
inline constexpr int kMaxFeedbackBuffers = detail::FeedbackCapture::kMaxBuffers;
inline constexpr int kMaxFeedbackComponents = 64;
inline constexpr int kMaxFeedbackSeparateComponents = 4;

// One indexed TRANSFORM_FEEDBACK_BUFFER binding: a buffer's bytes [offset, offset + size) (BindBufferRange), or its
// whole store as it is at each draw (BindBufferBase: range false, offset and size 0).
struct FeedbackBinding {
  std::shared_ptr<Buffer> buffer;
  std::size_t offset = 0, size = 0;
  bool range = false;
  // Bytes of the store recording may use from the binding's start (0 if none is bound).
  std::size_t Room() const {
    if (!buffer || offset > buffer->data.size()) return 0;
    const std::size_t left = buffer->data.size() - offset;
    return range ? std::min(size, left) : left;
  }
};

// A transform feedback object (GenTransformFeedbacks; 0 is the context's own): its bindings and its recording.
struct TransformFeedbackObject {
  FeedbackBinding binding[kMaxFeedbackBuffers];
  bool active = false, paused = false;
  bool ended = false;  // EndTransformFeedback has been called on it (DrawTransformFeedback may draw it)
  bool bound = false;  // it has been bound: only then is it an object (IsTransformFeedback, DrawTransformFeedback)
  Enum mode = POINTS;  // BeginTransformFeedback's primitive mode
  std::shared_ptr<const detail::FeedbackLayout> layout;  // the program's, at Begin
  const Program* program = nullptr;                      // the program recorded from
  std::size_t written[kMaxFeedbackBuffers] = {};         // bytes written into each binding since Begin
  std::uint64_t vertices = 0;                            // vertices written since Begin
  std::uint64_t drawable = 0;                            // vertices written between the last Begin and End
  bool Recording() const { return active && !paused; }
};

// A query object (GenQueries). Its target is fixed by its first BeginQuery.
struct QueryObject {
  Enum target = 0;
  bool active = false;
  std::shared_ptr<detail::OcclusionCounter> counter;  // SAMPLES_PASSED, ANY_SAMPLES_PASSED: tiles add to it
  std::uint64_t count = 0;                            // PRIMITIVES_GENERATED, counted as draws are recorded
  std::chrono::steady_clock::time_point start;        // TIME_ELAPSED
  std::uint64_t elapsed_ns = 0;  // TIME_ELAPSED; TIMESTAMP: the time QueryCounter recorded (TimestampNs)
  std::uint64_t end_mark = 0;    // ContextState::WorkMark() at EndQuery: the result is final once it is done
};

// A fence (FenceSync): signalled once what was recorded before it has been rendered.
struct SyncObject {
  std::uint64_t mark = 0;  // ContextState::WorkMark() when it was made
};

// TIMESTAMP's clock: nanoseconds since the first time it was read in the process (a steady clock).
inline std::uint64_t TimestampNs() {
  static const auto epoch = std::chrono::steady_clock::now();
  return std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - epoch).count());
}

// The slot of each query target: 0 SAMPLES_PASSED, 1 ANY_SAMPLES_PASSED, 2 PRIMITIVES_GENERATED, 3 TIME_ELAPSED,
// 4 TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN.
inline constexpr int kQuerySlots = 5;
inline int QuerySlot(Enum target) {
  switch (target) {
    case SAMPLES_PASSED: return 0;
    case ANY_SAMPLES_PASSED: return 1;
    case PRIMITIVES_GENERATED: return 2;
    case TIME_ELAPSED: return 3;
    case TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN: return 4;
    default: return -1;
  }
}

struct TextureUnit {
  std::shared_ptr<detail::TextureObject> bound[detail::kTextureKinds];  // by detail::TextureKind
  std::shared_ptr<detail::SamplerParams> sampler;  // BindSampler's sampler object (null: the textures' own state)
};

inline int CubeFaceIndex(Enum target) {
  return target >= TEXTURE_CUBE_MAP_POSITIVE_X && target <= TEXTURE_CUBE_MAP_NEGATIVE_Z
             ? int(target - TEXTURE_CUBE_MAP_POSITIVE_X)
             : -1;
}

inline bool IsTexImageTarget(Enum target) { return target == TEXTURE_2D || CubeFaceIndex(target) >= 0; }

// Section 9.4: why a framebuffer object cannot be drawn to, or FRAMEBUFFER_COMPLETE (context_framebuffers.cpp).
Enum FramebufferStatus(const FramebufferObject& f);
// The buffers of a complete framebuffer object, drawn through its draw buffers; its size is the intersection of
// its attachments'. With `srgb` (FRAMEBUFFER_SRGB enabled) its sRGB colour buffers convert (ColorBuffer::srgb).
// `layer`: of a layered framebuffer, that layer of each layered attachment (those with fewer layers absent).
detail::RenderTarget FramebufferTarget(const FramebufferObject& f, bool srgb = false, int layer = 0);
// The most layers of a layered attachment of `f` (1 when none is layered).
int FramebufferLayers(const FramebufferObject& f);

struct ContextState {
  Enum error = NO_ERROR;
  detail::Framebuffer fb;

  std::unordered_map<std::uint32_t, std::shared_ptr<Buffer>> buffers;
  std::uint32_t next_buffer = 1;
  std::unordered_map<std::uint32_t, std::unique_ptr<VertexArray>> arrays;
  std::uint32_t next_array = 1;

  std::shared_ptr<Buffer> array_buffer;
  std::shared_ptr<Buffer> copy_read_buffer, copy_write_buffer;
  std::shared_ptr<Buffer> texture_buffer;  // the TEXTURE_BUFFER buffer binding (TexBuffer does not read it)
  std::shared_ptr<Buffer> feedback_buffer;  // TRANSFORM_FEEDBACK_BUFFER (the generic binding)
  // Transform feedback objects; `feedback` is the bound one (feedback_id's, or default_feedback for 0).
  std::unordered_map<std::uint32_t, std::unique_ptr<TransformFeedbackObject>> feedbacks;
  std::uint32_t next_feedback = 1;
  TransformFeedbackObject default_feedback;
  TransformFeedbackObject* feedback = &default_feedback;
  std::uint32_t feedback_id = 0;
  bool rasterizer_discard = false;  // RASTERIZER_DISCARD
  VertexArray* vao = nullptr;
  std::uint32_t vao_id = 0;
  glm::vec4 current_attrib[kMaxVertexAttribs];
  // How each current value was given: 0 as floats (VertexAttrib4f, VertexAttribP*), 1 as signed integers, 2 as
  // unsigned integers (VertexAttribI*: current_attrib then holds their bits, detail::IntegerAttrib).
  std::uint8_t current_integer[kMaxVertexAttribs] = {};
  const Program* program = nullptr;

  std::unordered_map<std::uint32_t, std::shared_ptr<detail::TextureObject>> textures;
  std::uint32_t next_texture = 1;
  TextureUnit units[kMaxTextureUnits];
  int units_used = 0;  // units from here on have never had a texture bound (BindTexture raises it)
  int active_unit = 0;
  std::unordered_map<std::uint32_t, std::shared_ptr<detail::SamplerParams>> samplers;  // sampler objects
  std::uint32_t next_sampler = 1;
  // PixelStore: where client pixels lie for uploads (UNPACK_*) and read-backs (PACK_*); LSB_FIRST is kept for the
  // queries alone (it concerns bitmaps, which OpenGL 3.3 core has none of).
  detail::ClientLayout unpack, pack;
  bool unpack_lsb_first = false, pack_lsb_first = false;
  std::unordered_map<std::uint32_t, std::unique_ptr<FramebufferObject>> framebuffers;
  std::uint32_t next_framebuffer = 1;
  std::unordered_map<std::uint32_t, std::shared_ptr<Renderbuffer>> renderbuffers;
  std::uint32_t next_renderbuffer = 1;
  std::shared_ptr<Renderbuffer> renderbuffer;  // bound to RENDERBUFFER
  Enum default_read_buffer = BACK;             // ReadBuffer while the context's own framebuffer is read: or NONE
  std::unordered_map<std::uint32_t, std::unique_ptr<QueryObject>> queries;
  std::uint32_t next_query = 1;
  std::uint32_t active_query[kQuerySlots] = {};  // by QuerySlot: the id active on each target (0: none)
  // Conditional rendering: the query id between BeginConditionalRender and EndConditionalRender (0: none), and
  // whether its result discards the draws and clears meanwhile.
  std::uint32_t condition_query = 0;
  bool condition_discards = false;
  // Fences, by their handles (the address of each object: never read through a handle the caller gives).
  std::unordered_map<const SyncObject*, std::unique_ptr<SyncObject>> syncs;
  // The number of times the recorded work has been rendered (Sync): a mark WorkMark() gave is done once it is
  // reached.
  std::uint64_t renders = 0;
  Enum clamp_read_color = FIXED_ONLY;  // ClampColor(CLAMP_READ_COLOR)
  FramebufferObject* draw_fbo = nullptr;
  FramebufferObject* read_fbo = nullptr;

  int viewport[4] = {0, 0, 0, 0};
  double depth_near = 0.0, depth_far = 1.0;
  detail::PrimitiveState primitive;
  bool scissor_enabled = false;
  bool framebuffer_srgb = false;  // FRAMEBUFFER_SRGB
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
  detail::PendingDraws pending;  // small draws in a row, shaded but not yet recorded into `frame`
  detail::RenderTarget fbo_draw_target;  // Draw's target when a framebuffer object is bound (reused from draw to draw)
  std::vector<std::uint32_t> tile_counts;  // CountTilePrimitives: primitives per tile (empty when off)
  glm::ivec2 tile_count_grid{0, 0};        // the tiles' columns and rows
  detail::FetchPlan fetch_plan;  // Draw's resolution of the vertex array (a disabled attribute: its current value)
  detail::DrawPacket draw_packet;  // Draw's prototype of the packets it records
  detail::DrawTextures draw_textures;  // the prototype's textures: the bound units resolved at the last draw
  std::vector<detail::RenderTarget> layer_targets;  // Draw's buffers of each layer of a layered framebuffer
  // The last shader copy taken (Snapshot), used again by the draws after it while the shader is unchanged.
  std::shared_ptr<const Program> last_snapshot;

  Context::DebugCallback debug_callback;

  // Records `e` if no error is pending (OpenGL keeps the first), and reports every error to the debug callback.
  void SetError(Enum e, const char* call, const char* message) {
    if (error == NO_ERROR) error = e;
    if (debug_callback) debug_callback(e, call, message);
  }

  static bool IsBufferTarget(Enum target) {
    return target == ARRAY_BUFFER || target == ELEMENT_ARRAY_BUFFER || target == COPY_READ_BUFFER ||
           target == COPY_WRITE_BUFFER || target == TRANSFORM_FEEDBACK_BUFFER || target == TEXTURE_BUFFER;
  }
  static constexpr const char* kBufferTargets =
      "target must be ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER, COPY_WRITE_BUFFER, TRANSFORM_FEEDBACK_BUFFER "
      "or TEXTURE_BUFFER";

  std::shared_ptr<Buffer>* BindingFor(Enum target) {
    if (target == ARRAY_BUFFER) return &array_buffer;
    if (target == TRANSFORM_FEEDBACK_BUFFER) return &feedback_buffer;
    if (target == COPY_READ_BUFFER) return &copy_read_buffer;
    if (target == COPY_WRITE_BUFFER) return &copy_write_buffer;
    if (target == TEXTURE_BUFFER) return &texture_buffer;
    if (target == ELEMENT_ARRAY_BUFFER && vao) return &vao->element_buffer;
    return nullptr;
  }

  // The buffer bound to `target`, or null with the error set: a target that is not a buffer target (INVALID_ENUM),
  // nothing bound there (INVALID_OPERATION).
  Buffer* BoundBuffer(const char* what, Enum target) {
    if (!IsBufferTarget(target)) return SetError(INVALID_ENUM, what, kBufferTargets), nullptr;
    auto* binding = BindingFor(target);
    if (binding == nullptr || !*binding) return SetError(INVALID_OPERATION, what, "no buffer is bound to target"), nullptr;
    return binding->get();
  }

  // Before a call changes the store of `buffer`: when a buffer texture reads it, the draws recorded so far are
  // rendered first, so that they sample it as it was when they were made.
  void BeforeStoreChange(const Buffer& buffer, const char* what) {
    if (buffer.texture_store) Sync(what);
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
  // INVALID_FRAMEBUFFER_OPERATION recorded) when that object is incomplete. `frame`: for commands recorded into
  // the frame (draws and clears), which may leave the context's multisampled framebuffer's clears deferred.
  // Anything else that writes it gets its samples with every clear stored.
  bool DrawTarget(detail::RenderTarget& target, bool frame = false) {
    if (!draw_fbo) {
      target = frame ? fb.FrameTarget(framebuffer_srgb) : fb.Target(framebuffer_srgb);
      return true;
    }
    if (FramebufferStatus(*draw_fbo) != FRAMEBUFFER_COMPLETE) {
      SetError(INVALID_FRAMEBUFFER_OPERATION, __func__, "the framebuffer bound for drawing is not complete");
      return false;
    }
    target = FramebufferTarget(*draw_fbo, framebuffer_srgb);
    return true;
  }
  // The layers a clear of the draw framebuffer clears (1 unless a layered framebuffer object is bound), and layer
  // l's buffers (a complete framebuffer is bound: DrawTarget said so).
  int DrawLayers() const { return draw_fbo ? FramebufferLayers(*draw_fbo) : 1; }
  detail::RenderTarget DrawLayer(int l) const { return FramebufferTarget(*draw_fbo, framebuffer_srgb, l); }

  // The texture bound to `target` of the active unit (a cube face target selects the cube map), and the face.
  detail::TextureObject* Bound(Enum target, int* face = nullptr) {
    TextureUnit& u = units[active_unit];
    if (face) *face = 0;
    if (const int kind = detail::TextureKind(target); kind >= 0) return u.bound[kind].get();
    const int f = CubeFaceIndex(target);
    if (f < 0) return nullptr;
    if (face) *face = f;
    return u.bound[1].get();
  }

  void Draw(const detail::DrawCall& call);

  // A mark for the work recorded so far: WorkDone(mark) once it has all been rendered (0 when there is none).
  std::uint64_t WorkMark() const { return frame.Empty() && pending.Empty() ? 0 : renders + 1; }
  bool WorkDone(std::uint64_t mark) const { return mark <= renders; }

  // Renders what is recorded, so that the buffers hold it: before the buffers are read, before anything a
  // recorded draw refers to (textures, framebuffer attachments) changes, and before drawing elsewhere.
  void Sync(const char* call) {
    ++renders;
    try {
      detail::RecordPending(pending, frame, *pool, scratch);
      frame.Render(*pool, scratch.tiles);
      last_snapshot.reset();  // the next frame's draws take a copy of their own
    } catch (const std::bad_alloc&) {
      pending.Reset();
      SetError(OUT_OF_MEMORY, call, "out of memory while rendering recorded draws (they are dropped)");
    }
  }

  // Records the small draws held (PendingDraws) into the frame: before anything else is recorded into it.
  void RecordPending(const char* call) {
    if (pending.Empty()) return;
    try {
      detail::RecordPending(pending, frame, *pool, scratch);
    } catch (const std::bad_alloc&) {
      pending.Reset();
      frame.Reset();
      SetError(OUT_OF_MEMORY, call, "out of memory (recorded draws not yet rendered are dropped)");
    }
  }
};

// ---- Object ids --------------------------------------------------------------------------------------------

// A new id (never 0) for a new object in `table`.
template <class Table, class Make>
std::uint32_t NewId(Table& table, std::uint32_t& next, Make&& make) {
  const std::uint32_t id = next++;
  table[id] = make();
  return id;
}

// The number of mipmap levels a texture target has: 1 + log2 of its largest size (OpenGL 3.3, section 3.8.3: a
// level above that is INVALID_VALUE), 12 for TEXTURE_3D (2048), 15 for the others (16384).
constexpr int LevelCount(Enum target) {
  int levels = 1;
  for (int size = target == TEXTURE_3D ? kMax3DTextureSize : kMaxTextureSize; size > 1; size /= 2) ++levels;
  return levels;
}
static_assert(LevelCount(TEXTURE_3D) == 12 && LevelCount(TEXTURE_2D) == detail::kMaxLevels);

// The rule for pointers (docs/guide.md, "Null pointers"): a null pointer through which a call would read or write
// at least one value sets INVALID_VALUE ("NAME is null") and the call changes nothing. False then.
inline bool NotNull(ContextState& s, const char* call, const void* p, const char* name) {
  if (p != nullptr) return true;
  char message[64];
  std::snprintf(message, sizeof message, "%s is null", name);
  s.SetError(INVALID_VALUE, call, message);
  return false;
}

// The Gen*s(n, ids) form of a Gen* call.
template <class Gen>
void GenMany(ContextState& s, const char* call, int n, std::uint32_t* ids, Gen&& gen) {
  if (n < 0) return s.SetError(INVALID_VALUE, call, "n is negative");
  if (n > 0 && !NotNull(s, call, ids, "ids")) return;
  for (int i = 0; i < n; ++i) ids[i] = gen();
}

// The Delete*s(n, ids) form of a Delete* call.
template <class Delete>
void DeleteMany(ContextState& s, const char* call, int n, const std::uint32_t* ids, Delete&& del) {
  if (n < 0) return s.SetError(INVALID_VALUE, call, "n is negative");
  if (n > 0 && !NotNull(s, call, ids, "ids")) return;
  for (int i = 0; i < n; ++i) del(ids[i]);
}

// Bits of a sized format's red, green, blue, alpha, depth and stencil, as OpenGL reports them
// (context_framebuffers.cpp).
struct FormatBits {
  int r = 0, g = 0, b = 0, a = 0, depth = 0, stencil = 0;
};
FormatBits BitsOf(Enum internal_format);

// The id under which `map` holds `object` (0 for none).
template <class Map, class Ptr>
std::uint32_t IdOf(const Map& map, const Ptr* object) {
  if (object == nullptr) return 0;
  for (const auto& [id, held] : map)
    if (held.get() == object) return id;
  return 0;
}

// The flag of an Enable capability, or null for a name that is not one (context.cpp).
bool* CapFlag(ContextState& s, Enum cap);

}  // namespace softgl

// pipeline.h — one draw call through every stage: fetch -> vertex shader -> assembly -> clip -> divide/viewport
// -> cull -> bin, recorded now; then, per tile when the frame is rendered (tile_renderer.h): rasterize ->
// fragment shader -> fragment operations -> framebuffer.
//
// The context validates the call and resolves its objects into a FetchPlan, a DrawState and a DrawPacket; from
// there the draw flows forward through the stages in plain structs (types.h), and only the framebuffer is
// written.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <softgl/shader.h>

#include "framebuffer.h"
#include "geometry_stage.h"
#include "primitive_assembly.h"
#include "tile_renderer.h"
#include "types.h"
#include "vertex_fetch.h"
#include "worker_pool.h"
#include "viewport.h"

namespace softgl::detail {

inline constexpr float kMaxPointSize = 255.0f;
inline constexpr float kMaxLineWidth = 255.0f;  // ALIASED_LINE_WIDTH_RANGE's upper end
/// Largest number of vertices shaded at once; larger draws go through in pieces (a multiple of 6, so that pieces of
/// point, line and triangle lists hold whole primitives).
inline constexpr int kDrawChunk = 6 * 8192;

/// How primitives are turned into fragments: the context keeps one and copies it into each draw.
struct PrimitiveState {
  bool cull_enabled = false;
  Enum cull_face = BACK;
  Enum front_face = CCW;
  Enum polygon_mode = FILL;
  bool program_point_size = false;
  float point_size = 1.0f;
  float line_width = 1.0f;             // LineWidth as given (queries); drawing clamps it to kMaxLineWidth
  bool point_lower_left = false;       // POINT_SPRITE_COORD_ORIGIN is LOWER_LEFT
  float point_fade_threshold = 1.0f;   // POINT_FADE_THRESHOLD_SIZE (kept for the queries)
  bool offset_fill = false, offset_line = false, offset_point = false;  // POLYGON_OFFSET_FILL / _LINE / _POINT
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool provoking_first = false;  // ProvokingVertex(FIRST_VERTEX_CONVENTION)
};

/// What transform feedback records of each vertex (a program's TransformFeedbackVaryings).
struct FeedbackLayout {
  struct Item {
    std::string name;
    int first = 0;       // float of the varyings, or FeedbackVarying::kPosition
    int components = 4;  // 1 to 4
  };
  std::vector<Item> items;
  bool separate = false;  // SEPARATE_ATTRIBS: item i into buffer i; else all into buffer 0, a vertex after another
  int floats = 0;         // the items' components together
  int Buffers() const { return separate ? int(items.size()) : 1; }
};

/// Where a draw's transform feedback writes: for each buffer the layout uses, the store from the binding's write
/// position on and its room in bytes. The pipeline adds what it wrote.
struct FeedbackCapture {
  static constexpr int kMaxBuffers = 4;
  const FeedbackLayout* layout = nullptr;
  std::uint8_t* data[kMaxBuffers] = {};
  std::size_t room[kMaxBuffers] = {};
  std::size_t written[kMaxBuffers] = {};  // out: bytes written into each
  std::uint64_t primitives = 0;           // out: primitives written
  std::uint64_t vertices = 0;             // out: vertices written
};

/// Everything the front end of a draw needs from the context's state, resolved at draw time.
struct DrawState {
  const Program* program = nullptr;
  const GeometryLayout* geometry = nullptr;  // the program's geometry stage (Program::GeometryStage), or none
  bool primitive_ids = false;  // the fragment stage reads gl_PrimitiveID (Program::ReadsPrimitiveId)
  ViewportTransform viewport;
  Rect bounds;  // viewport, framebuffer and (when enabled) scissor rectangle intersected
  PrimitiveState primitive;
  const Textures* textures = nullptr;  // what the vertex stage samples
  const Interpolation* interpolation = nullptr;  // the program's varying qualifiers (null: all smooth)
  std::uint64_t* primitives_generated = nullptr;  // counts the assembled primitives (PRIMITIVES_GENERATED query)
  FeedbackCapture* feedback = nullptr;  // transform feedback records the draw's primitives (null: it does not)
  bool discard = false;  // RASTERIZER_DISCARD: nothing is rasterized (the primitives are still counted and recorded)
  // A layered framebuffer whose layers the program's gl_Layer chooses: each layer's buffers (layers > 1), or none.
  const RenderTarget* layer_targets = nullptr;
  int layers = 0;
  int samples = 1;  // samples whose coverage triangles compute (RasterTarget::samples)
  bool depth16 = false;  // the target's depth buffer is 16-bit fixed point (polygon offset's unit is 1 / 65535)
};

/// The vertices a draw reads: either `count` consecutive vertices from `first`, or `count` element indices.
struct DrawCall {
  Enum mode = TRIANGLES;
  int count = 0;
  std::uint32_t first = 0;
  const std::uint32_t* elements = nullptr;  // null for DrawArrays
  std::uint32_t instance = 0;  // gl_InstanceID of the first instance drawn
  int instances = 1;           // instances drawn, in order: instance, instance + 1, ...
  // Primitive restart: positions in `elements` (ascending) that end one primitive sequence and start the next;
  // the elements there are not vertices of any primitive.
  const std::uint32_t* restarts = nullptr;
  int restart_count = 0;
  std::uint32_t primitive_base = 0;  // gl_PrimitiveIDIn of the first primitive (a piece of a larger draw's)
};

/// Memory one worker thread reuses while shading vertices.
struct VertexScratch {
  std::vector<float> attribs;  // rows of lanes (VertexBatch::attribs)
  std::vector<int> vertex_ids;
};

/// Memory one worker thread reuses while clipping and binning primitives.
struct PrimitiveScratch {
  ClipVertex clip[4];
  ClipPolygon poly;
  WindowVertex win[kMaxPolygonVertices];
};

/// Per-context memory reused from draw to draw, so that drawing allocates only when a draw is bigger than any
/// before it.
struct Scratch {
  std::vector<std::uint32_t> elements;       // DrawElement's indices, read from the element buffer
  std::vector<std::uint32_t> restarts;       // positions of the primitive restart index among them
  std::vector<std::uint32_t> piece;          // the indices of one piece of a large draw
  std::vector<std::uint32_t> shade_indices;  // vertex index of each vertex to shade
  std::vector<std::uint32_t> element_to_shaded;
  std::vector<std::uint32_t> first_use;      // per vertex of an indexed draw's index range: its shaded slot
  std::vector<int> primitive_layer;          // a layered draw's layer of each primitive
  ShadedVertices shaded;
  Primitives primitives;
  std::vector<VertexScratch> vertex;  // per worker
  std::vector<std::unique_ptr<PrimitiveScratch>> primitive;  // per worker
  std::vector<TileScratch> tiles;     // per worker
  GeometryScratch geometry;
};

/// Draws of at most this many elements may be held as small draws (PendingDraws).
inline constexpr int kSmallDrawElements = 128;
/// Shaded vertices the held small draws may have together.
inline constexpr int kPendingVertices = 1024;

/// Small draws in a row with the same state, not yet recorded into the frame. Each one's vertices are fetched and
/// shaded when it is made, as any draw's are (the vertex stage sees the shader, buffers and textures as they are
/// then), and its primitives are kept as a list of those shaded vertices; the rest of the front end (clip codes,
/// divide and viewport, culling, binning) runs once for all of them (RecordPending), when a draw that cannot join
/// them comes, or before anything else is recorded into the frame or the frame is rendered. A frame of many small
/// draws then pays for that part once per run of draws, not once per draw.
///
/// While draws are held, the context's Scratch holds their shaded vertices (`shaded`, with room for
/// kPendingVertices) and their primitive list (`primitives.indices`, `per` slots each, in draw order): nothing else
/// uses them until RecordPending.
struct PendingDraws {
  int draws = 0;
  int per = 0;  // vertices per primitive of the list
  int vertices = 0;  // shaded so far
  DrawState state;     // the first draw's (program: its shader copy; textures: `textures`)
  DrawPacket packet;   // the first draw's (textures: `textures`)
  RenderTarget target;
  DrawTextures textures;  // a copy of the bound units' views at the first draw
  Primitives assembled;   // one draw's primitives, as AssemblePrimitives gives them (reused from draw to draw)
  bool Empty() const { return draws == 0; }
  /// Forgets the held draws (and releases the shader copy and query counters they keep).
  void Reset();
};

/// Whether a draw may be held as a small draw: few elements, one instance, no primitive restart, a point, line or
/// triangle mode other than LINE_LOOP and the adjacency modes, no geometry stage, transform feedback,
/// PRIMITIVES_GENERATED query, RASTERIZER_DISCARD, gl_PrimitiveID or layered target, something to draw into, and a
/// copy of the shader (packet.snapshot).
bool SmallDrawApplies(const DrawCall& call, const DrawState& state, const DrawPacket& packet);

/// Whether a small draw (SmallDrawApplies) can join the held draws `pending` (not empty): the same shader copy,
/// textures, operations, viewport, bounds, primitive state and target, primitives of the same kind, and room.
bool JoinsPending(const PendingDraws& pending, const DrawCall& call, const DrawState& state, const DrawPacket& packet,
                  const RenderTarget& target);

/// Shades a small draw's vertices (stages 1-2) and adds its assembled primitives to `pending`, which it starts
/// when empty (then with copies of `state`, `packet`, `target` and the textures). `state.program` is the shader
/// the vertex stage runs (the live one); the held draws keep `packet.program`, the copy.
void ShadeSmallDraw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& packet,
                    const RenderTarget& target, PendingDraws& pending, Scratch& scratch);

/// Records the held draws into `frame` as one draw (the rest of the front end, then binning), and empties
/// `pending`; nothing when it is empty. May throw std::bad_alloc (`pending` is then to be Reset).
void RecordPending(PendingDraws& pending, Frame& frame, WorkerPool& pool, Scratch& scratch);

/// Recorded data beyond which a frame is rendered before recording goes on (between pieces of a draw).
inline constexpr std::size_t kFrameBudgetBytes = std::size_t(64) << 20;

/// Runs the front end of one draw (vertex fetch and shading, assembly, clipping, divide and viewport, culling,
/// binning), in parallel batches on `pool`, and records it into `frame` as a copy of `packet` (the fragment
/// stage's state); rasterization and everything after it happen when the frame is rendered. A draw whose
/// recorded data outgrows kFrameBudgetBytes renders the frame between its pieces. May throw std::bad_alloc;
/// nothing else is thrown.
void RecordDraw(const DrawCall& call, const FetchPlan& fetch, const DrawState& state, const DrawPacket& packet,
                const RenderTarget& target, Frame& frame, WorkerPool& pool, Scratch& scratch);

}  // namespace softgl::detail

// softgl/context.h — the rendering context: OpenGL's state machine over an offscreen framebuffer.
//
// A Context owns an offscreen framebuffer (RGBA8 colour, 32-bit float depth, 8-bit stencil), the objects
// created through it (buffers and vertex arrays, addressed by integer ids as in OpenGL) and all rendering state.
// Calls act on what is bound, with OpenGL's meaning. Every call validates its arguments; a call that fails records
// OpenGL's error code (the first one since the last GetError()) and changes nothing.
//
// A Context is not thread-safe: use one context per thread (several contexts may render at once).
//
// Rendering is deferred and parallel. A draw call runs the vertex stage at once and records the draw's primitives,
// sorted into 64 x 64 pixel tiles; the recorded draws are rendered (rasterized, shaded, tested, blended) tile by
// tile on the context's worker threads when their pixels are needed: ReadPixels and the other reads, Finish, a
// framebuffer switch, a texture change, or when the recorded data grows large. Each tile is rendered by one thread
// in submission order, so the image is the same whatever the number of threads.
#pragma once

#include <softgl/config.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>

#include <softgl/enums.h>
#include <softgl/image.h>
#include <softgl/shader.h>
#include <softgl/texture.h>

#include <string>

namespace softgl {

/// Largest framebuffer width or height, and largest viewport size (GL_MAX_VIEWPORT_DIMS).
inline constexpr int kMaxFramebufferSize = 16384;

struct ContextState;  // defined in src/, never seen by users

struct SyncObject;  // defined in src/, never seen by users
/// A fence made by FenceSync (OpenGL's GLsync): an opaque handle; null is none.
using Sync = SyncObject*;

class Context {
 public:
  /// Creates a context whose framebuffer is width x height pixels. 0 x 0 is allowed (every draw is then a no-op).
  /// A negative size or one larger than kMaxFramebufferSize gives a 0 x 0 framebuffer and INVALID_VALUE; a
  /// framebuffer that cannot be allocated gives a 0 x 0 one and OUT_OF_MEMORY. The viewport starts as the
  /// whole framebuffer.
  Context(int width, int height);
  /// Options for a context.
  struct Options {
    /// Threads that render, the calling thread included; 0 (the default) takes SOFTGL_THREADS from the
    /// environment when it is set to a number from 1 to 256, else the machine's hardware thread count.
    int threads = 0;
    /// The context's colour buffer: RGBA8 (4 bytes a pixel, the default); SRGB8_ALPHA8 (the same bytes, sRGB-encoded:
    /// while FRAMEBUFFER_SRGB is enabled, drawing, clears and blits encode linear colours into it, and blending
    /// decodes first); or RGB565 (2 bytes a pixel, for small memory: red and blue kept to 5 bits, green to 6, no
    /// alpha). All three take the vector path of the fragment operations, multisampled or not. Anything else:
    /// RGBA8, and INVALID_ENUM recorded.
    Enum color_format = RGBA8;
    /// The context's depth buffer: DEPTH_COMPONENT32F (4 bytes a pixel, float, the default) or DEPTH_COMPONENT16
    /// (2 bytes a pixel, for small memory: depth kept as round(d * 65535), the fragment's depth converted so before
    /// the test, a polygon offset unit of 1 / 65535).
    /// Anything else: DEPTH_COMPONENT32F, and INVALID_ENUM recorded.
    Enum depth_format = DEPTH_COMPONENT32F;
    /// Samples per pixel of the context's framebuffer: 0 (the default) or 1 for one, 2, 4 or 8 for a multisampled
    /// framebuffer (3 gives 4, 5 to 7 give 8). Drawing then covers, tests and stores each sample (the fragment
    /// shader still runs once per pixel), and every read (ReadPixels, the copies, blits from it) sees the resolved
    /// image: colour the average of the samples, depth and stencil those of sample 0. A multisampled framebuffer
    /// takes `samples` times the memory of a single-sampled one, plus one resolved image. Below 0 or above 8:
    /// single-sampled, and INVALID_VALUE recorded.
    int samples = 0;
  };
  Context(int width, int height, const Options& options);
  /// Recorded draws not yet rendered are dropped.
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int Width() const;
  int Height() const;
  /// Number of threads rendering for this context (the calling thread included).
  int Threads() const;

  /// glFinish: renders every recorded draw and clear, so that the buffers hold their results.
  void Finish();
  /// glFlush: OpenGL lets commands start; softgl renders what is recorded now, as Finish does.
  void Flush();

  /// Binning statistics, for learning and tuning (softgl's own; OpenGL has none): while counting is on, every
  /// 64 x 64 pixel tile counts the primitives that binning gave it (points, lines and triangles after clipping and
  /// culling: a triangle goes to each tile that the box of the pixel centres it may cover overlaps). Turning it on
  /// or off starts the counts again from zero. Off by default.
  void CountTilePrimitives(bool on);
  /// Renders what is recorded (as Finish does), then returns the counts per tile since counting was turned on,
  /// for the tiles of the framebuffer rendered last, row by row from the bottom (tile (col, row) at
  /// row * columns + col); the counts start again from zero when a framebuffer of another size is rendered.
  /// Empty when counting is off. `columns` and `rows` (either may be null) receive the grid's size (0 when empty).
  std::vector<std::uint32_t> TilePrimitiveCounts(int* columns = nullptr, int* rows = nullptr);

  /// Hierarchical depth (softgl's own; the image is the same with it on or off): each 64 x 64 tile keeps the
  /// nearest and farthest depth of every 8 x 8 block of the depth buffer (over all samples of a multisampled one),
  /// and a triangle, or an 8 x 8 region of a larger one, whose depths cannot pass the depth test there is dropped
  /// before coverage, interpolation and shading. It applies where the depth test runs before the shader (LESS,
  /// LEQUAL, GREATER or GEQUAL, no stencil test, a shader without kWritesDepth). On by default; off, for comparing,
  /// every triangle is tested fragment by fragment.
  void UseHierarchicalDepth(bool on);
  /// What hierarchical depth tested and dropped since the last call (all threads together).
  struct HierarchicalDepthCounts {
    std::uint64_t triangles_tested = 0, triangles_hidden = 0;  // triangles, against the blocks under their box
    std::uint64_t regions_tested = 0, regions_hidden = 0;      // 8 x 8 regions of triangles larger than one
  };
  /// Renders what is recorded (as Finish does), then returns the counts and starts them again from zero.
  HierarchicalDepthCounts TakeHierarchicalDepthCounts();

  // ---- Errors ------------------------------------------------------------------------------------------------
  /// Returns the first error recorded since the last call, and clears it (NO_ERROR when there was none).
  Enum GetError();
  /// Called for every error a call records (not only the first), with the call's name and a readable message,
  /// e.g. (INVALID_OPERATION, "BindBuffer", "not a buffer id made by GenBuffer (or it was deleted)"). Runs on the
  /// calling thread, inside the failing call; an empty function removes it.
  using DebugCallback = std::function<void(Enum error, const char* call, const char* message)>;
  void DebugMessageCallback(DebugCallback callback);

  // ---- Buffer objects ----------------------------------------------------------------------------------------
  /// Creates a buffer object and returns its id (never 0).
  std::uint32_t GenBuffer();
  /// Creates n buffer objects, writing their ids to ids. n < 0: INVALID_VALUE.
  void GenBuffers(int n, std::uint32_t* ids);
  /// Deletes a buffer; it is unbound from every target, from the bound vertex array's element binding and from the
  /// bound transform feedback object's bindings.
  /// Attribute bindings in other vertex arrays keep the storage alive, as OpenGL does. 0 and unknown ids are ignored.
  void DeleteBuffer(std::uint32_t buffer);
  /// DeleteBuffer of each of ids[0 .. n). n < 0: INVALID_VALUE. (Each Delete*s call below is so.)
  void DeleteBuffers(int n, const std::uint32_t* ids);
  bool IsBuffer(std::uint32_t buffer) const;
  /// Binds buffer (0 unbinds) to target ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, COPY_READ_BUFFER, COPY_WRITE_BUFFER,
  /// TRANSFORM_FEEDBACK_BUFFER or TEXTURE_BUFFER (the buffer calls below take each of them). The ELEMENT_ARRAY_BUFFER binding is part of the bound vertex array (INVALID_OPERATION if
  /// none is bound). Bad target: INVALID_ENUM; an id not made by GenBuffer: INVALID_OPERATION.
  void BindBuffer(Enum target, std::uint32_t buffer);
  /// Replaces the store of the buffer bound to target with size bytes copied from data (zeros if data is null),
  /// unmapping it first if it is mapped. size < 0: INVALID_VALUE; bad target or usage: INVALID_ENUM; nothing
  /// bound: INVALID_OPERATION; allocation failure: OUT_OF_MEMORY.
  void BufferData(Enum target, std::ptrdiff_t size, const void* data, Enum usage = STATIC_DRAW);
  /// Overwrites bytes [offset, offset + size) of the bound buffer. Range outside the store: INVALID_VALUE; a range
  /// that meets the buffer's mapped range: INVALID_OPERATION.
  void BufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data);
  /// Gives the caller bytes [offset, offset + length) of the buffer bound to target to read or write directly, until
  /// UnmapBuffer. access: MAP_READ_BIT and/or MAP_WRITE_BIT, with MAP_INVALIDATE_RANGE_BIT,
  /// MAP_INVALIDATE_BUFFER_BIT (the bytes may then read as anything; softgl keeps them), MAP_FLUSH_EXPLICIT_BIT
  /// (see FlushMappedBufferRange), MAP_UNSYNCHRONIZED_BIT (no effect: draws read their vertices when they are
  /// made). Returns null on error: offset or length negative, the range outside the store, an unknown access bit:
  /// INVALID_VALUE; length 0, the buffer already mapped, neither READ nor WRITE, READ with an INVALIDATE or
  /// UNSYNCHRONIZED bit, FLUSH_EXPLICIT without WRITE: INVALID_OPERATION. While mapped, BufferSubData and
  /// GetBufferSubData on the mapped bytes, CopyBufferSubData on the buffer and draws that read it (an enabled
  /// attribute array's buffer, or the element buffer of an indexed draw) are INVALID_OPERATION; BufferData and
  /// DeleteBuffer unmap it first. The pointer is valid until then.
  void* MapBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length, Bitfield access);
  /// The whole store: access READ_ONLY, WRITE_ONLY or READ_WRITE (else INVALID_ENUM). An empty store:
  /// INVALID_OPERATION.
  void* MapBuffer(Enum target, Enum access);
  /// Says that bytes [offset, offset + length) of a mapping made with MAP_FLUSH_EXPLICIT_BIT (offset relative to
  /// the mapping) were written. Not mapped so: INVALID_OPERATION; outside the mapping: INVALID_VALUE.
  void FlushMappedBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length);
  /// Ends the mapping; returns true (the store is never lost). Not mapped: INVALID_OPERATION and false.
  bool UnmapBuffer(Enum target);
  /// Copies size bytes from read_offset of the buffer bound to read_target to write_offset of the one bound to
  /// write_target (any two buffer targets; COPY_READ_BUFFER and COPY_WRITE_BUFFER exist for this). Negative
  /// values, a range outside its store, overlapping ranges of one buffer: INVALID_VALUE; nothing bound or either
  /// buffer mapped: INVALID_OPERATION.
  void CopyBufferSubData(Enum read_target, Enum write_target, std::ptrdiff_t read_offset, std::ptrdiff_t write_offset,
                         std::ptrdiff_t size);
  /// Copies bytes [offset, offset + size) of the bound buffer to data. Errors as BufferSubData.
  void GetBufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, void* data) const;
  /// BUFFER_SIZE, BUFFER_USAGE, BUFFER_ACCESS (READ_WRITE unless mapped otherwise), BUFFER_MAPPED,
  /// BUFFER_ACCESS_FLAGS, BUFFER_MAP_OFFSET, BUFFER_MAP_LENGTH of the bound buffer; another name: INVALID_ENUM.
  /// The int form clamps values beyond its range.
  void GetBufferParameteriv(Enum target, Enum pname, int* params) const;
  void GetBufferParameteri64v(Enum target, Enum pname, std::int64_t* params) const;
  /// BUFFER_MAP_POINTER: the pointer MapBufferRange returned, or null when not mapped.
  void GetBufferPointerv(Enum target, Enum pname, void** params) const;

  // ---- Vertex array objects ----------------------------------------------------------------------------------
  /// Creates a vertex array object and returns its id (never 0). A vertex array records the attribute
  /// bindings and the ELEMENT_ARRAY_BUFFER binding.
  std::uint32_t GenVertexArray();
  void GenVertexArrays(int n, std::uint32_t* ids);
  /// Deletes a vertex array; if it is bound, 0 becomes bound. 0 and unknown ids are ignored.
  void DeleteVertexArray(std::uint32_t array);
  void DeleteVertexArrays(int n, const std::uint32_t* ids);
  bool IsVertexArray(std::uint32_t array) const;
  /// Binds a vertex array (0: none, as in an OpenGL core profile). Unknown id: INVALID_OPERATION.
  void BindVertexArray(std::uint32_t array);
  /// Sets attribute `index` of the bound vertex array to read `size` (1-4) components of `type` (BYTE,
  /// UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, INT, UNSIGNED_INT, HALF_FLOAT, FLOAT, DOUBLE, or the packed
  /// INT_2_10_10_10_REV and UNSIGNED_INT_2_10_10_10_REV with size 4) from the buffer now bound to ARRAY_BUFFER,
  /// starting at byte `offset`, every `stride` bytes (0 means tightly packed). Integer types are converted to
  /// float; with `normalized` they map to [0, 1] (unsigned) or [-1, 1] (signed, max(c / (2^(b-1) - 1), -1));
  /// doubles become the nearest float. Size BGRA reads four normalized components of UNSIGNED_BYTE or a packed
  /// type stored blue first, as red, green, blue, alpha. index >= kMaxVertexAttribs, size neither 1-4 nor BGRA,
  /// or stride < 0: INVALID_VALUE; bad type: INVALID_ENUM; a packed type with size 1-3, BGRA with another type or
  /// not normalized, no vertex array bound, or no ARRAY_BUFFER bound with offset != 0: INVALID_OPERATION.
  void VertexAttributePointer(std::uint32_t index, int size, Enum type, bool normalized, int stride,
                              std::size_t offset);
  /// Attribute `index` reads integers: `size` (1 to 4) components of BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT,
  /// INT or UNSIGNED_INT from the buffer bound to ARRAY_BUFFER, as VertexAttributePointer reads them, but kept as
  /// integers (sign- or zero-extended to 32 bits, missing components 0, 0, 0 and 1): the vertex stage reads them by
  /// VertexLanes::AttribI (VertexIn::AttribI), GLSL's `in ivec4` / `in uvec4`. index >= kMaxVertexAttribs, size
  /// not 1 to 4, or stride < 0: INVALID_VALUE; another type: INVALID_ENUM; no vertex array bound, or no
  /// ARRAY_BUFFER bound with offset != 0: INVALID_OPERATION.
  void VertexAttribIPointer(std::uint32_t index, int size, Enum type, int stride, std::size_t offset);
  void EnableVertexAttribArray(std::uint32_t index);
  void DisableVertexAttribArray(std::uint32_t index);
  /// How attribute `index` of the bound vertex array advances: 0 (the default) once per vertex; d > 0 once per d
  /// instances, so that instance i of an instanced draw reads element i / d for all its vertices (DrawArrays and
  /// the other draws are instance 0). index >= kMaxVertexAttribs: INVALID_VALUE; no vertex array bound:
  /// INVALID_OPERATION.
  void VertexAttribDivisor(std::uint32_t index, std::uint32_t divisor);
  /// The current value of a generic attribute, read by the vertex stage while its array is disabled.
  void VertexAttrib4f(std::uint32_t index, float x, float y, float z, float w);
  /// glVertexAttribP1ui ... P4ui (and the uiv forms, which read one word): the current value from one packed word
  /// of `type` INT_2_10_10_10_REV or UNSIGNED_INT_2_10_10_10_REV (x in bits 0-9, y 10-19, z 20-29, w 30-31),
  /// normalized or not as VertexAttributePointer converts them; the first 1 to 4 components are taken, the others
  /// are (0, 0, 1). Another type: INVALID_ENUM; index >= kMaxVertexAttribs: INVALID_VALUE.
  void VertexAttribP1ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value);
  void VertexAttribP2ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value);
  void VertexAttribP3ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value);
  void VertexAttribP4ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value);
  void VertexAttribP1uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value);
  void VertexAttribP2uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value);
  void VertexAttribP3uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value);
  void VertexAttribP4uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value);
  /// glVertexAttribI*: the current value of attribute `index` as integers (signed for the i, b and s forms,
  /// unsigned for the ui, ub and us forms; the components a form does not give are (0, 0, 1)), read by
  /// VertexLanes::AttribI while the array is disabled. index >= kMaxVertexAttribs: INVALID_VALUE; v null:
  /// INVALID_VALUE.
  void VertexAttribI1i(std::uint32_t index, int x);
  void VertexAttribI2i(std::uint32_t index, int x, int y);
  void VertexAttribI3i(std::uint32_t index, int x, int y, int z);
  void VertexAttribI4i(std::uint32_t index, int x, int y, int z, int w);
  void VertexAttribI1ui(std::uint32_t index, std::uint32_t x);
  void VertexAttribI2ui(std::uint32_t index, std::uint32_t x, std::uint32_t y);
  void VertexAttribI3ui(std::uint32_t index, std::uint32_t x, std::uint32_t y, std::uint32_t z);
  void VertexAttribI4ui(std::uint32_t index, std::uint32_t x, std::uint32_t y, std::uint32_t z, std::uint32_t w);
  void VertexAttribI1iv(std::uint32_t index, const int* v);
  void VertexAttribI2iv(std::uint32_t index, const int* v);
  void VertexAttribI3iv(std::uint32_t index, const int* v);
  void VertexAttribI4iv(std::uint32_t index, const int* v);
  void VertexAttribI1uiv(std::uint32_t index, const std::uint32_t* v);
  void VertexAttribI2uiv(std::uint32_t index, const std::uint32_t* v);
  void VertexAttribI3uiv(std::uint32_t index, const std::uint32_t* v);
  void VertexAttribI4uiv(std::uint32_t index, const std::uint32_t* v);
  void VertexAttribI4bv(std::uint32_t index, const std::int8_t* v);
  void VertexAttribI4sv(std::uint32_t index, const std::int16_t* v);
  void VertexAttribI4ubv(std::uint32_t index, const std::uint8_t* v);
  void VertexAttribI4usv(std::uint32_t index, const std::uint16_t* v);
  /// Attribute `index`'s state in the bound vertex array: VERTEX_ATTRIB_ARRAY_ENABLED, _SIZE (1 to 4, or BGRA),
  /// _STRIDE (as given: 0 for tightly packed), _TYPE, _NORMALIZED, _INTEGER (1 for VertexAttribIPointer's
  /// arrays), _DIVISOR, _BUFFER_BINDING (the buffer's id; 0 once deleted, while the array still reads its store);
  /// and CURRENT_VERTEX_ATTRIB, the four values of VertexAttrib4f or VertexAttribI* (no vertex array needed). The
  /// integer forms give float values rounded to integers, and all forms clamp to their type. index >=
  /// kMaxVertexAttribs: INVALID_VALUE; another name: INVALID_ENUM; an array state with no vertex array bound:
  /// INVALID_OPERATION.
  void GetVertexAttribdv(std::uint32_t index, Enum pname, double* params) const;
  void GetVertexAttribfv(std::uint32_t index, Enum pname, float* params) const;
  void GetVertexAttribiv(std::uint32_t index, Enum pname, int* params) const;
  void GetVertexAttribIiv(std::uint32_t index, Enum pname, int* params) const;
  void GetVertexAttribIuiv(std::uint32_t index, Enum pname, std::uint32_t* params) const;
  /// VERTEX_ATTRIB_ARRAY_POINTER: the offset VertexAttributePointer was given, as a pointer. Errors as above.
  void GetVertexAttribPointerv(std::uint32_t index, Enum pname, void** pointer) const;

  // ---- Shaders -----------------------------------------------------------------------------------------------
  /// Makes `program` (usually a softgl::Shader subclass) the current shader. The context keeps a pointer: the
  /// shader must outlive its use, and changes to its members (uniforms) are seen by later draws.
  void UseProgram(const Program& program);
  /// Unbinds the current shader; draws then record INVALID_OPERATION. (Either form while transform feedback is
  /// active and not paused: INVALID_OPERATION.)
  void UseProgram(std::nullptr_t);

  // ---- Transform feedback --------------------------------------------------------------------------------------
  /// What transform feedback records from each vertex `program`'s vertex stage writes: varyings[0 .. count), in
  /// order, into one buffer (INTERLEAVED_ATTRIBS: binding 0, each vertex's values one after the other) or each
  /// into its own (SEPARATE_ATTRIBS: varying i into binding i). Takes effect at once (there is no link step); count
  /// 0 records nothing. Bad buffer_mode: INVALID_ENUM; count < 0, more than MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS
  /// (4) separate varyings, more than MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS (64) floats interleaved, a
  /// varying with components outside 1-4 or floats past the program's VaryingFloats(), a null name or array:
  /// INVALID_VALUE; the program is the one transform feedback is recording from: INVALID_OPERATION.
  void TransformFeedbackVaryings(Program& program, int count, const FeedbackVarying* varyings, Enum buffer_mode);
  /// Varying `index` of `program`'s list: its name (up to buf_size - 1 characters and a terminating 0, its length
  /// without it in *length), *size 1 and *type FLOAT, FLOAT_VEC2, FLOAT_VEC3 or FLOAT_VEC4. Any of the pointers may
  /// be null. index past the list or buf_size < 0: INVALID_VALUE.
  void GetTransformFeedbackVarying(const Program& program, std::uint32_t index, int buf_size, int* length, int* size,
                                   Enum* type, char* name) const;
  /// Binds `buffer` to binding `index` (0 to MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS - 1) of the bound transform
  /// feedback object, and to the TRANSFORM_FEEDBACK_BUFFER target, for recording into bytes [offset, offset + size)
  /// (Range) or into the whole store as it is at each draw (Base). target other than TRANSFORM_FEEDBACK_BUFFER:
  /// INVALID_ENUM; index out of range, size <= 0 or offset < 0 or either not a multiple of 4 (Range, buffer not
  /// 0): INVALID_VALUE; an id not made by GenBuffer, or transform feedback active: INVALID_OPERATION.
  void BindBufferRange(Enum target, std::uint32_t index, std::uint32_t buffer, std::ptrdiff_t offset,
                       std::ptrdiff_t size);
  void BindBufferBase(Enum target, std::uint32_t index, std::uint32_t buffer);
  /// Starts recording: every draw until EndTransformFeedback writes the current program's varyings of each vertex
  /// of each primitive, in order (strips, fans and loops as separate primitives, as assembled), at the bound
  /// buffers' write positions, which start at the bindings' offsets. primitive_mode POINTS, LINES or TRIANGLES (else
  /// INVALID_ENUM); draws must then use a mode of that kind (INVALID_OPERATION). A primitive that does not fit in
  /// every buffer's room is not recorded, nor anything after it, and is not counted by
  /// TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN. Already active, no current program, a program with no varyings to
  /// record, or a binding it writes with no buffer: INVALID_OPERATION. Draws while a buffer being recorded into is
  /// mapped: INVALID_OPERATION. Enable(RASTERIZER_DISCARD) discards the primitives after recording them (and
  /// Clear and ClearBuffer* do nothing).
  void BeginTransformFeedback(Enum primitive_mode);
  /// Ends recording (not active: INVALID_OPERATION). DrawTransformFeedback then draws what was recorded.
  void EndTransformFeedback();
  /// Suspends and resumes recording, keeping the write positions; while paused, draws record nothing and may use any
  /// mode, and the program and bindings may change. Pause when not active or already paused, Resume when not
  /// paused: INVALID_OPERATION.
  void PauseTransformFeedback();
  void ResumeTransformFeedback();
  /// Transform feedback objects (OpenGL 4.0): each holds the bindings above, the active and paused state and the
  /// count of vertices last recorded. 0 is the context's own. A name from Gen becomes an object when first bound
  /// (IsTransformFeedback is false until then). Bind of an unknown id, or while active and not paused:
  /// INVALID_OPERATION; target other than TRANSFORM_FEEDBACK: INVALID_ENUM. Deleting an active object:
  /// INVALID_OPERATION; the bound one rebinds 0.
  std::uint32_t GenTransformFeedback();
  void GenTransformFeedbacks(int n, std::uint32_t* ids);
  void DeleteTransformFeedbacks(int n, const std::uint32_t* ids);
  bool IsTransformFeedback(std::uint32_t id) const;
  void BindTransformFeedback(Enum target, std::uint32_t id);
  /// DrawArrays(mode, 0, count) with count the vertices object `id` recorded between its last Begin and End. An
  /// id that is no object (unknown, or never bound): INVALID_VALUE; an object never ended: INVALID_OPERATION; other errors as DrawArrays.
  void DrawTransformFeedback(Enum mode, std::uint32_t id);

  // ---- Textures ----------------------------------------------------------------------------------------------
  /// Creates a texture object and returns its id (never 0). Its target is fixed by its first BindTexture.
  std::uint32_t GenTexture();
  void GenTextures(int n, std::uint32_t* ids);
  /// Deletes a texture: it is unbound from every unit and detached from the bound framebuffer objects; a framebuffer
  /// object not bound keeps using its storage, as in OpenGL. 0 and unknown ids are ignored.
  void DeleteTexture(std::uint32_t texture);
  void DeleteTextures(int n, const std::uint32_t* ids);
  bool IsTexture(std::uint32_t texture) const;
  /// Selects the texture unit that BindTexture, TexImage2D, TexParameter and GenerateMipmap act on: TEXTURE0 + i,
  /// i < kMaxTextureUnits (else INVALID_ENUM).
  void ActiveTexture(Enum unit);
  /// Binds texture (0 unbinds) to TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY,
  /// TEXTURE_3D, TEXTURE_2D_MULTISAMPLE, TEXTURE_2D_MULTISAMPLE_ARRAY or TEXTURE_BUFFER of the active unit
  /// (each unit holds one texture of each target). Bad target: INVALID_ENUM;
  /// unknown id, or a texture first bound to the other target: INVALID_OPERATION. There is no default texture
  /// object: texture calls with nothing bound record INVALID_OPERATION.
  void BindTexture(Enum target, std::uint32_t texture);
  /// Defines level `level` of the bound texture: target TEXTURE_2D or a TEXTURE_CUBE_MAP_* face; internal_format
  /// RGBA8, RGB8, RG8, R8, SRGB8_ALPHA8, SRGB8 (decoded to linear when sampled), RGB565, RGBA4, RGB5_A1, RGB10_A2
  /// (10 bits a colour channel, 2 of alpha, in 32), RGBA16,
  /// RG16, R16 (16-bit normalized), RGBA32F,
  /// RG32F, R32F, RGBA16F, RG16F, R16F, R11F_G11F_B10F, DEPTH_COMPONENT16 (2 bytes a texel, k / 65535),
  /// DEPTH_COMPONENT (also DEPTH_COMPONENT24/32F: stored as float), DEPTH24_STENCIL8 or DEPTH32F_STENCIL8 (depth,
  /// sampled as a depth texture, and a stencil index each);
  /// pixels of any of OpenGL 3.3's formats and types (tables 3.2 to 3.5): `format` RED, GREEN, BLUE, RG, RGB, BGR,
  /// RGBA, BGRA or DEPTH_COMPONENT with `type` UNSIGNED_BYTE, BYTE, UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT
  /// (normalized: unsigned c / (2^b - 1), signed max(c / (2^(b-1) - 1), -1)), HALF_FLOAT (IEEE binary16) or FLOAT,
  /// or with a packed type of its component count (UNSIGNED_SHORT_5_6_5, UNSIGNED_INT_2_10_10_10_REV, ...,
  /// UNSIGNED_INT_10F_11F_11F_REV, UNSIGNED_INT_5_9_9_9_REV: see enums.h); DEPTH_STENCIL with UNSIGNED_INT_24_8
  /// or FLOAT_32_UNSIGNED_INT_24_8_REV. Rows bottom first, laid out by the UNPACK_ settings (PixelStore); null
  /// pixels leave the level zero. Errors: bad target, format or type, DEPTH_STENCIL with another type:
  /// INVALID_ENUM; unsupported internal format, negative or too large size, level out of range, border != 0, a
  /// non-square cube face: INVALID_VALUE; depth data for a colour format or the reverse, a packed type with a format
  /// of another component count, an integer format (RED_INTEGER ...: softgl has no integer textures), nothing
  /// bound: INVALID_OPERATION; no memory: OUT_OF_MEMORY.
  /// Target TEXTURE_1D_ARRAY: `height` layers (up to kMaxArrayTextureLayers) of `width` texels, row j of the
  /// image layer j, all kept at every mipmap level.
  void TexImage2D(Enum target, int level, Enum internal_format, int width, int height, int border, Enum format,
                  Enum type, const void* pixels);
  /// Replaces the rectangle (x, y, width, height) of a defined level (of a TEXTURE_1D_ARRAY: layers y .. y +
  /// height - 1). Outside the level: INVALID_VALUE; level not defined: INVALID_OPERATION.
  void TexSubImage2D(Enum target, int level, int x, int y, int width, int height, Enum format, Enum type,
                     const void* pixels);
  /// Defines level `level` of the bound TEXTURE_1D: a row of `width` texels, with TexImage2D's formats, types,
  /// unpacking and errors (another target: INVALID_ENUM). A 1D texture samples as a 2D one a texel high at its
  /// middle (TEXTURE_WRAP_T unused): FragmentLanes::Texture1D, Texture1DLod, TextureSize1D.
  void TexImage1D(Enum target, int level, Enum internal_format, int width, int border, Enum format, Enum type,
                  const void* pixels);
  /// Replaces texels x .. x + width - 1 of a defined level of the bound TEXTURE_1D, as TexSubImage2D.
  void TexSubImage1D(Enum target, int level, int x, int width, Enum format, Enum type, const void* pixels);
  /// CopyTexImage2D for TEXTURE_1D: the read framebuffer's row y, columns x .. x + width - 1.
  void CopyTexImage1D(Enum target, int level, Enum internal_format, int x, int y, int width, int border);
  /// CopyTexSubImage2D for TEXTURE_1D: into texels xoffset .. xoffset + width - 1.
  void CopyTexSubImage1D(Enum target, int level, int xoffset, int x, int y, int width);
  /// Defines level `level` of the bound TEXTURE_2D_ARRAY (depth layers, all kept at every mipmap level) or
  /// TEXTURE_3D (depth slices, halved with each level as width and height are): the internal formats, pixel
  /// formats and types of TexImage2D; `pixels` holds `depth` images of height rows one after another (layer or
  /// slice 0 first). Errors as TexImage2D's, and: target neither: INVALID_ENUM; a size beyond kMaxTextureSize
  /// (width and height of an array), kMaxArrayTextureLayers (layers) or kMax3DTextureSize (each size of a 3D
  /// texture): INVALID_VALUE; a depth format for TEXTURE_3D: INVALID_OPERATION; more texels than one level may
  /// hold (kMaxTextureSize squared of RGBA32F) or no memory: OUT_OF_MEMORY.
  void TexImage3D(Enum target, int level, Enum internal_format, int width, int height, int depth, int border,
                  Enum format, Enum type, const void* pixels);
  /// Replaces the box (x, y, z, width, height, depth) of a defined level of the bound TEXTURE_2D_ARRAY or
  /// TEXTURE_3D. Outside the level: INVALID_VALUE; level not defined: INVALID_OPERATION.
  void TexSubImage3D(Enum target, int level, int x, int y, int z, int width, int height, int depth, Enum format,
                     Enum type, const void* pixels);
  /// Defines level `level` of the bound texture from compressed data: `image_size` bytes of 4 x 4 blocks in one of
  /// the S3TC formats (COMPRESSED_RGB_S3TC_DXT1_EXT ... COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT) or the RGTC ones
  /// (COMPRESSED_RED_RGTC1 ... COMPRESSED_SIGNED_RG_RGTC2), ceil(width / 4) * ceil(height / 4) blocks an image, rows
  /// of blocks bottom first. softgl decodes them at once (8 bits a channel; signed RGTC as floats) and keeps the
  /// blocks too, for GetCompressedTexImage and TEXTURE_COMPRESSED_IMAGE_SIZE; sampling reads the decoded texels as it
  /// reads any level's. CompressedTexImage2D takes TEXTURE_2D or a cube face, CompressedTexImage3D TEXTURE_2D_ARRAY
  /// (`depth` layers, one image after another). Errors: bad target, a format that is not one of those (the generic
  /// COMPRESSED_RGBA and its kin are for TexImage*), TEXTURE_1D_ARRAY or TEXTURE_3D (the formats are
  /// two-dimensional): INVALID_ENUM; nothing bound: INVALID_OPERATION; sizes as TexImage2D's, `image_size` not the
  /// blocks' bytes, null data for a non-empty image: INVALID_VALUE; no memory: OUT_OF_MEMORY. A 0 x 0 image makes
  /// an empty level that keeps its compressed format (TEXTURE_INTERNAL_FORMAT, TEXTURE_COMPRESSED).
  /// TexImage*, TexSubImage*, CopyTex(Sub)Image* and GenerateMipmap do not compress: with a specific compressed format, or on a
  /// compressed level, they answer INVALID_OPERATION.
  void CompressedTexImage2D(Enum target, int level, Enum internal_format, int width, int height, int border,
                            int image_size, const void* data);
  void CompressedTexImage3D(Enum target, int level, Enum internal_format, int width, int height, int depth,
                            int border, int image_size, const void* data);
  /// OpenGL 3.3 has no one-dimensional compressed format: every call answers INVALID_ENUM (bad target or format).
  void CompressedTexImage1D(Enum target, int level, Enum internal_format, int width, int border, int image_size,
                            const void* data);
  /// Replaces the blocks of region (x, y, width, height) (and layers z .. z + depth - 1) of a compressed level.
  /// Errors: bad target: INVALID_ENUM; level out of range, the region outside the level, `image_size` not the
  /// region's blocks' bytes: INVALID_VALUE; no texture or level, `format` not the level's compressed format, x or
  /// y not a multiple of 4, a width or height that is not one and does not reach the level's edge:
  /// INVALID_OPERATION. The 1D form always fails with INVALID_ENUM (no 1D level is compressed).
  void CompressedTexSubImage2D(Enum target, int level, int x, int y, int width, int height, Enum format,
                               int image_size, const void* data);
  void CompressedTexSubImage3D(Enum target, int level, int x, int y, int z, int width, int height, int depth,
                               Enum format, int image_size, const void* data);
  void CompressedTexSubImage1D(Enum target, int level, int x, int width, Enum format, int image_size,
                               const void* data);
  /// Writes the blocks of compressed level `level` of the bound texture (TEXTURE_COMPRESSED_IMAGE_SIZE bytes) to
  /// `data`. Errors: bad target: INVALID_ENUM; level out of range or not defined: INVALID_VALUE; nothing bound, a
  /// level that is not compressed: INVALID_OPERATION.
  void GetCompressedTexImage(Enum target, int level, void* data) const;
  /// Loads an image file (PNG, TGA, BMP, HDR through stb_image; JPEG through libjpeg-turbo) into level 0 of the
  /// texture bound to target (TEXTURE_2D or a cube face): 1 to 4 channels become R8, RG8, RGB8, RGBA8; HDR becomes
  /// RGBA32F.
  /// `encoding` SRGB marks colour images as sRGB-encoded (3 channels SRGB8, 4 SRGB8_ALPHA8: sampling decodes them
  /// to linear before filtering), as colour maps and photographs are; LINEAR (the default) keeps them as they are,
  /// for data such as normal maps. Image files store the top row first; flip_vertically puts the bottom row at
  /// t = 0, OpenGL's convention. Returns false with a message in `error` for a missing or corrupt file (the texture
  /// is unchanged, no GL error), or an image too large (INVALID_VALUE); `encoding` neither LINEAR nor SRGB:
  /// INVALID_ENUM.
  /// A DDS file of S3TC, RGTC or BC7 blocks (FourCC DXT1 ... DXT5, ATI1, ATI2, BC4U/S, BC5U/S, or a DX10 header
  /// with BC1 ... BC5 or BC7) defines every mipmap level it holds with CompressedTexImage2D, blocks as they are
  /// (sRGB where the file or `encoding` says so), and sets TEXTURE_MAX_LEVEL to its last level; flip_vertically
  /// reorders the blocks (each level's height a multiple of 4, or below 4; BC7 blocks cannot be reordered, so a
  /// BC7 file must be loaded unflipped). BC6H, cube map, volume, array and uncompressed DDS files are refused with a
  /// message.
  bool TexImage2DFromFile(Enum target, const std::string& path, bool flip_vertically, std::string* error = nullptr,
                          Enum encoding = LINEAR);
  /// As TexImage2DFromFile, for an encoded image (PNG, JPEG, ...) already in memory, such as one embedded in a model.
  bool TexImage2DFromMemory(Enum target, const void* data, std::size_t size, bool flip_vertically,
                            std::string* error = nullptr, Enum encoding = LINEAR);
  /// Copies the rectangle (x, y, width, height) of the read framebuffer (its COLOR_ATTACHMENT0 or colour buffer, or
  /// its depth buffer for a depth texture) into level `level` of the bound texture at (xoffset, yoffset), converted
  /// to the level's format; pixels outside the framebuffer (undefined in OpenGL) copy as zero. Errors: bad target:
  /// INVALID_ENUM; level out of range, a rectangle outside the level: INVALID_VALUE; nothing bound, level not
  /// defined, no buffer of the texture's kind to read: INVALID_OPERATION; incomplete read framebuffer:
  /// INVALID_FRAMEBUFFER_OPERATION.
  /// Into a TEXTURE_1D_ARRAY, each row of the rectangle goes to one layer, from layer yoffset on.
  void CopyTexSubImage2D(Enum target, int level, int xoffset, int yoffset, int x, int y, int width, int height);
  /// CopyTexSubImage2D into layer `zoffset` of level `level` of the bound TEXTURE_2D_ARRAY (a slice of a
  /// TEXTURE_3D). Errors as CopyTexSubImage2D's; another target: INVALID_ENUM; zoffset outside the level's layers
  /// (slices): INVALID_VALUE.
  void CopyTexSubImage3D(Enum target, int level, int xoffset, int yoffset, int zoffset, int x, int y, int width,
                         int height);
  /// Defines level `level` of the bound texture as width x height of `internal_format` (as TexImage2D, with its
  /// errors) holding the read framebuffer's rectangle (x, y, width, height), as CopyTexSubImage2D copies it (a
  /// TEXTURE_1D_ARRAY of `height` layers, a row each).
  void CopyTexImage2D(Enum target, int level, Enum internal_format, int x, int y, int width, int height, int border);
  /// Writes level `level` of the bound texture (TEXTURE_1D, TEXTURE_2D, a cube face, TEXTURE_1D_ARRAY,
  /// TEXTURE_2D_ARRAY or TEXTURE_3D) to `pixels`, rows bottom first, laid out by the PACK_ settings as ReadPixels
  /// lays them out (a 1D array as one image, a layer a row; a 2D array's layers or a 3D texture's slices one image
  /// after another, each `height` rows): the formats and types ReadPixels takes,
  /// but not STENCIL_INDEX; DEPTH_COMPONENT for a depth texture, DEPTH_STENCIL for a depth-stencil one. An
  /// undefined level writes nothing. Errors: bad target, format or type, DEPTH_STENCIL with another type:
  /// INVALID_ENUM; level out of range: INVALID_VALUE; nothing bound, DEPTH_COMPONENT for a colour texture or the
  /// reverse, DEPTH_STENCIL for a texture without stencil, a mismatched packed type or an integer format:
  /// INVALID_OPERATION.
  void GetTexImage(Enum target, int level, Enum format, Enum type, void* pixels) const;
  /// Builds levels base+1 .. 1x1 of the bound texture from its base level (each texel the bilinear sample of the
  /// level above at its centre: the 2x2 average for even sizes; a 2D array layer by layer, a 3D texture down to
  /// 1x1x1 by 2x2x2 averages). Base level undefined: INVALID_OPERATION.
  void GenerateMipmap(Enum target);
  /// Sampling state of the texture bound to target (TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_2D_ARRAY or
  /// TEXTURE_3D): TEXTURE_MIN_FILTER (NEAREST, LINEAR, NEAREST_MIPMAP_NEAREST,
  /// LINEAR_MIPMAP_NEAREST, NEAREST_MIPMAP_LINEAR (default), LINEAR_MIPMAP_LINEAR), TEXTURE_MAG_FILTER (NEAREST,
  /// LINEAR (default)), TEXTURE_WRAP_S/T/R (REPEAT (default), MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER),
  /// TEXTURE_BASE_LEVEL, TEXTURE_MAX_LEVEL, TEXTURE_MIN_LOD, TEXTURE_MAX_LOD, TEXTURE_LOD_BIAS,
  /// TEXTURE_MAX_ANISOTROPY (1, the default, to 16: anisotropic filtering of 2D textures),
  /// TEXTURE_COMPARE_MODE (NONE, COMPARE_REF_TO_TEXTURE), TEXTURE_COMPARE_FUNC (the eight comparisons).
  /// Bad name or value: INVALID_ENUM; negative base or max level, TEXTURE_MAX_ANISOTROPY below 1: INVALID_VALUE.
  void TexParameteri(Enum target, Enum pname, int value);
  void TexParameterf(Enum target, Enum pname, float value);
  /// TEXTURE_BORDER_COLOR (four floats), or any single-valued name.
  void TexParameterfv(Enum target, Enum pname, const float* values);
  /// As TexParameterfv; TEXTURE_BORDER_COLOR's integers map to [-1, 1] as OpenGL maps signed normalized values
  /// (i / (2^31 - 1)).
  void TexParameteriv(Enum target, Enum pname, const int* values);
  /// The sampling state of the bound texture, by the names TexParameter takes (TEXTURE_BORDER_COLOR: four values;
  /// as integers, mapped back from [-1, 1]). Bad target or name: INVALID_ENUM; nothing bound: INVALID_OPERATION.
  void GetTexParameterfv(Enum target, Enum pname, float* params) const;
  void GetTexParameteriv(Enum target, Enum pname, int* params) const;
  /// glTexParameterIiv / Iuiv: TEXTURE_BORDER_COLOR's four numbers kept as they are, for integer textures (the
  /// queries below give them back; sampling, with no integer textures yet, takes them as floats); any other name
  /// as TexParameteriv.
  void TexParameterIiv(Enum target, Enum pname, const int* values);
  void TexParameterIuiv(Enum target, Enum pname, const std::uint32_t* values);
  /// glGetTexParameterIiv / Iuiv: the border colour as the I forms set it (else its floats rounded and clamped to
  /// the type); any other name as GetTexParameteriv.
  void GetTexParameterIiv(Enum target, Enum pname, int* params) const;
  void GetTexParameterIuiv(Enum target, Enum pname, std::uint32_t* params) const;

  // ---- Sampler objects (OpenGL 3.3, section 3.8.2) ----
  // A sampler object holds the sampling state TexParameter sets, but the levels: bound to a unit, it is used in
  // place of the state of every texture bound to that unit (TEXTURE_BASE_LEVEL and TEXTURE_MAX_LEVEL stay the
  // texture's), completeness included (a sampler that does not mipmap makes a texture of one level complete).

  /// Creates a sampler object, with TexParameter's defaults, and returns its id (never 0).
  std::uint32_t GenSampler();
  void GenSamplers(int n, std::uint32_t* ids);
  /// Deletes a sampler object: every unit it is bound to has 0 bound instead. 0 and unknown ids are ignored.
  void DeleteSampler(std::uint32_t sampler);
  void DeleteSamplers(int n, const std::uint32_t* ids);
  bool IsSampler(std::uint32_t sampler) const;
  /// Binds a sampler object to texture unit `unit` (0 to kMaxTextureUnits - 1: a number, not TEXTURE0 + i; 0
  /// unbinds). Unit out of range: INVALID_VALUE; an id not made by GenSampler: INVALID_OPERATION. Draws recorded
  /// before keep the state they were recorded with. GetIntegerv(SAMPLER_BINDING) gives the active unit's.
  void BindSampler(int unit, std::uint32_t sampler);
  /// A sampler object's state, by TexParameter's names and values but TEXTURE_BASE_LEVEL and TEXTURE_MAX_LEVEL
  /// (INVALID_ENUM): TEXTURE_MIN_FILTER, TEXTURE_MAG_FILTER, TEXTURE_WRAP_S/T/R, TEXTURE_MIN_LOD, TEXTURE_MAX_LOD,
  /// TEXTURE_LOD_BIAS, TEXTURE_MAX_ANISOTROPY, TEXTURE_COMPARE_MODE, TEXTURE_COMPARE_FUNC, TEXTURE_BORDER_COLOR (the
  /// vector forms only). Not a sampler object: INVALID_OPERATION; the other errors as TexParameter's.
  void SamplerParameteri(std::uint32_t sampler, Enum pname, int value);
  void SamplerParameterf(std::uint32_t sampler, Enum pname, float value);
  void SamplerParameterfv(std::uint32_t sampler, Enum pname, const float* values);
  /// As SamplerParameterfv; TEXTURE_BORDER_COLOR's integers map to [-1, 1] as TexParameteriv maps them.
  void SamplerParameteriv(std::uint32_t sampler, Enum pname, const int* values);
  /// The integer forms: TEXTURE_BORDER_COLOR's four integers (signed, or unsigned) kept as the numbers they are,
  /// for the integer textures that would read them (softgl's textures are not integer ones, and sample the
  /// border colour as those floats); any other name as SamplerParameteriv.
  void SamplerParameterIiv(std::uint32_t sampler, Enum pname, const int* values);
  void SamplerParameterIuiv(std::uint32_t sampler, Enum pname, const std::uint32_t* values);
  /// A sampler object's state, by the names SamplerParameter takes (TEXTURE_BORDER_COLOR: four values; iv maps
  /// them back from [-1, 1], Iiv and Iuiv give them as numbers). Not a sampler object: INVALID_OPERATION; another
  /// name: INVALID_ENUM.
  void GetSamplerParameterfv(std::uint32_t sampler, Enum pname, float* params) const;
  void GetSamplerParameteriv(std::uint32_t sampler, Enum pname, int* params) const;
  void GetSamplerParameterIiv(std::uint32_t sampler, Enum pname, int* params) const;
  void GetSamplerParameterIuiv(std::uint32_t sampler, Enum pname, std::uint32_t* params) const;

  /// One level of the bound texture (target TEXTURE_2D, a cube face, TEXTURE_2D_ARRAY, TEXTURE_3D or
  /// TEXTURE_2D_MULTISAMPLE): TEXTURE_WIDTH, TEXTURE_HEIGHT, TEXTURE_DEPTH (layers or slices; 1 for 2D),
  /// TEXTURE_SAMPLES (0 but for a multisample texture), TEXTURE_FIXED_SAMPLE_LOCATIONS (1),
  /// TEXTURE_INTERNAL_FORMAT, TEXTURE_RED_SIZE, _GREEN_SIZE, _BLUE_SIZE, _ALPHA_SIZE, TEXTURE_DEPTH_SIZE,
  /// TEXTURE_STENCIL_SIZE (the format's bits; all 0 for an undefined level, whose internal format reads RGBA).
  /// Bad target or name: INVALID_ENUM; level out of range: INVALID_VALUE; nothing bound: INVALID_OPERATION.
  void GetTexLevelParameteriv(Enum target, int level, Enum pname, int* params) const;
  void GetTexLevelParameterfv(Enum target, int level, Enum pname, float* params) const;
  /// Where client pixels lie in memory (OpenGL 3.3, tables 3.1 and 4.5): the UNPACK_ parameters for
  /// TexImage2D/3D and TexSubImage2D/3D, the PACK_ ones for ReadPixels and GetTexImage. _ALIGNMENT: 1, 2, 4
  /// (default) or 8, else INVALID_VALUE; _ROW_LENGTH (pixels a row, 0: the width), _IMAGE_HEIGHT (rows an image of
  /// a 3D or array texture, 0: the height), _SKIP_PIXELS, _SKIP_ROWS, _SKIP_IMAGES: >= 0 (default 0), else
  /// INVALID_VALUE; _SWAP_BYTES: non-zero reverses the bytes of each 2- and 4-byte component; _LSB_FIRST is kept
  /// and queried only (it concerns bitmaps). Another name: INVALID_ENUM.
  void PixelStore(Enum pname, int value);

  // ---- Framebuffer objects -----------------------------------------------------------------------------------
  std::uint32_t GenFramebuffer();
  void GenFramebuffers(int n, std::uint32_t* ids);
  /// Deletes a framebuffer object; where it is bound, 0 (the context's own framebuffer) becomes bound.
  void DeleteFramebuffer(std::uint32_t framebuffer);
  void DeleteFramebuffers(int n, const std::uint32_t* ids);
  bool IsFramebuffer(std::uint32_t framebuffer) const;
  /// Binds a framebuffer object (0: the context's own) to FRAMEBUFFER (both), DRAW_FRAMEBUFFER or READ_FRAMEBUFFER.
  void BindFramebuffer(Enum target, std::uint32_t framebuffer);
  /// Attaches level `level` of a 2D texture (textarget TEXTURE_2D), a cube face (TEXTURE_CUBE_MAP_*) or the image
  /// of a TEXTURE_2D_MULTISAMPLE texture (level 0) to
  /// COLOR_ATTACHMENT0 .. COLOR_ATTACHMENT0 + 3, DEPTH_ATTACHMENT, STENCIL_ATTACHMENT or DEPTH_STENCIL_ATTACHMENT
  /// (both of the last two) of the framebuffer bound to target; texture 0 detaches. A DEPTH24_STENCIL8 or
  /// DEPTH32F_STENCIL8 texture at DEPTH_STENCIL_ATTACHMENT gives rendering into a texture a stencil buffer.
  /// Errors: bad target or attachment: INVALID_ENUM; framebuffer 0 bound, unknown texture, textarget not the
  /// texture's: INVALID_OPERATION; level out of range: INVALID_VALUE.
  void FramebufferTexture2D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level);
  /// Level `level` of a TEXTURE_1D texture, as FramebufferTexture2D attaches a 2D one (a framebuffer one pixel
  /// high). textarget not TEXTURE_1D: INVALID_ENUM; the texture not a 1D one: INVALID_OPERATION. A TEXTURE_1D_ARRAY's
  /// layer attaches by FramebufferTextureLayer, all of them by FramebufferTexture.
  void FramebufferTexture1D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level);
  /// Attaches one layer of level `level` of a TEXTURE_2D_ARRAY (or one slice of a TEXTURE_3D) as
  /// FramebufferTexture2D attaches a 2D level: drawing renders into that layer alone. A layer the level does not
  /// have leaves the framebuffer FRAMEBUFFER_INCOMPLETE_ATTACHMENT. Errors: bad target or attachment:
  /// INVALID_ENUM; framebuffer 0 bound, unknown texture, a texture of another target: INVALID_OPERATION; level
  /// out of range, negative layer or one beyond kMaxArrayTextureLayers (kMax3DTextureSize): INVALID_VALUE.
  void FramebufferTextureLayer(Enum target, Enum attachment, std::uint32_t texture, int level, int layer);
  /// Attaches level `level` of any texture: a 2D (or 2D multisample) one as FramebufferTexture2D does; a cube map,
  /// 2D array or 3D texture with all its faces, layers or slices (a layered attachment). A layered framebuffer
  /// draws each primitive into the layer its provoking vertex's gl_Layer names (VertexLanesOut::layer, with
  /// kWritesLayer; else layer 0; past the last or below 0: the last); Clear and ClearBuffer* clear every layer;
  /// reads and blits read layer 0. Layered and unlayered attachments in one
  /// framebuffer, or layered colour attachments of different texture targets, make it
  /// FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS; a layered cube map whose six faces differ,
  /// FRAMEBUFFER_INCOMPLETE_ATTACHMENT. Errors as FramebufferTexture2D's, but for an unknown texture or one never
  /// bound: INVALID_VALUE (as OpenGL says for this call).
  void FramebufferTexture(Enum target, Enum attachment, std::uint32_t texture, int level);
  /// Slice `zoffset` of level `level` of a TEXTURE_3D texture, as FramebufferTextureLayer attaches it. textarget
  /// or the texture not TEXTURE_3D: INVALID_OPERATION; other errors as FramebufferTextureLayer's.
  void FramebufferTexture3D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level,
                            int zoffset);
  /// Attaches a renderbuffer (renderbuffer_target RENDERBUFFER; 0 detaches) to an attachment point as
  /// FramebufferTexture2D does. Errors: bad target, attachment or renderbuffer_target: INVALID_ENUM; framebuffer 0
  /// bound, unknown renderbuffer: INVALID_OPERATION.
  void FramebufferRenderbuffer(Enum target, Enum attachment, Enum renderbuffer_target, std::uint32_t renderbuffer);
  /// What an attachment point holds: FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE (NONE, TEXTURE or RENDERBUFFER),
  /// _OBJECT_NAME, _TEXTURE_LEVEL, _TEXTURE_CUBE_MAP_FACE (0 but for a cube map), _TEXTURE_LAYER (0 but for
  /// FramebufferTextureLayer), _LAYERED (whether FramebufferTexture attached every layer). Errors: bad target, attachment or pname, a texture name asked of a renderbuffer:
  /// INVALID_ENUM; framebuffer 0 bound, a texture name asked of an empty point, DEPTH_STENCIL_ATTACHMENT while
  /// depth and stencil hold different images: INVALID_OPERATION.
  void GetFramebufferAttachmentParameteriv(Enum target, Enum attachment, Enum pname, int* params);
  /// FRAMEBUFFER_COMPLETE, or why not: INCOMPLETE_ATTACHMENT (an attachment's image is not defined or has no size,
  /// or its format cannot be rendered to that point: colour formats at colour points, depth formats at
  /// DEPTH_ATTACHMENT, formats with stencil at STENCIL_ATTACHMENT), INCOMPLETE_MISSING_ATTACHMENT (none),
  /// INCOMPLETE_DRAW_BUFFER (a draw buffer names an empty attachment), INCOMPLETE_LAYER_TARGETS (see
  /// FramebufferTexture). Attachments of different sizes are allowed,
  /// as in OpenGL 3.0 and later: drawing covers their intersection; depth and stencil may be separate images. The
  /// read buffer is checked when it is read (INVALID_OPERATION), as in OpenGL 4.1 and later. Draws and clears on an
  /// incomplete framebuffer record INVALID_FRAMEBUFFER_OPERATION. Bad target: INVALID_ENUM and 0.
  Enum CheckFramebufferStatus(Enum target);
  /// Which attachment fragment output i writes: bufs[i] is COLOR_ATTACHMENT0 + k or NONE (default: output 0 to
  /// COLOR_ATTACHMENT0, the others NONE). For the bound draw framebuffer object; n > 4: INVALID_VALUE.
  void DrawBuffers(int n, const Enum* bufs);
  /// Which colour buffer ReadPixels, CopyTex(Sub)Image2D and BlitFramebuffer read: for a framebuffer object
  /// COLOR_ATTACHMENT0 + i (default COLOR_ATTACHMENT0) or NONE; for the context's framebuffer, whose one colour
  /// buffer FRONT, BACK (the default), LEFT, FRONT_LEFT, BACK_LEFT and FRONT_AND_BACK all name, or NONE. Reading
  /// colour from NONE or an empty attachment records INVALID_OPERATION. Errors: not a buffer name: INVALID_ENUM;
  /// a buffer the bound read framebuffer cannot have (COLOR_ATTACHMENTi of the context's framebuffer, i >= 4, BACK
  /// of a framebuffer object, the RIGHT buffers): INVALID_OPERATION.
  void ReadBuffer(Enum src);
  /// Copies the rectangle (src_x0, src_y0) - (src_x1, src_y1) of the read framebuffer into the rectangle
  /// (dst_x0, dst_y0) - (dst_x1, dst_y1) of the draw framebuffer (lower bounds inclusive, upper exclusive),
  /// scaling to fit and mirroring where a rectangle is reversed. A multisampled read framebuffer is resolved
  /// (colour averaged over the samples, depth and stencil from sample 0); a multisampled draw framebuffer takes
  /// the value in every sample, or sample by sample from a read framebuffer of as many samples. mask: COLOR_BUFFER_BIT (the read buffer into
  /// every draw buffer, converted to each one's format), DEPTH_BUFFER_BIT, STENCIL_BUFFER_BIT. filter: NEAREST,
  /// or LINEAR (bilinear, colour only) for a scaled copy. Each destination pixel whose centre lies in the
  /// destination rectangle takes the source at the matching point; pixels whose point lies outside the read
  /// buffer, and pixels outside the scissor box while the scissor test is enabled, are not written; write masks do
  /// not apply. A buffer that either framebuffer lacks is skipped. Errors (nothing is copied): other mask bits:
  /// INVALID_VALUE; bad filter: INVALID_ENUM; LINEAR with depth or stencil, depth or stencil formats that differ
  /// (the context's framebuffer counts as DEPTH24_STENCIL8), rectangles that overlap while one buffer is both
  /// source and destination (undefined in OpenGL), either framebuffer multisampled and rectangles of different
  /// sizes, both multisampled with different sample counts: INVALID_OPERATION; an incomplete read or draw framebuffer:
  /// INVALID_FRAMEBUFFER_OPERATION.
  void BlitFramebuffer(int src_x0, int src_y0, int src_x1, int src_y1, int dst_x0, int dst_y0, int dst_x1, int dst_y1,
                       Bitfield mask, Enum filter);

  // ---- Renderbuffers -----------------------------------------------------------------------------------------
  /// Creates a renderbuffer object (an image to render into, never sampled) and returns its id (never 0).
  std::uint32_t GenRenderbuffer();
  void GenRenderbuffers(int n, std::uint32_t* ids);
  /// Deletes a renderbuffer: unbound from RENDERBUFFER and detached from the bound framebuffer objects (others keep
  /// using its storage, as in OpenGL). 0 and unknown ids are ignored.
  void DeleteRenderbuffer(std::uint32_t renderbuffer);
  void DeleteRenderbuffers(int n, const std::uint32_t* ids);
  bool IsRenderbuffer(std::uint32_t renderbuffer) const;
  /// Binds a renderbuffer (0 unbinds) to RENDERBUFFER. Bad target: INVALID_ENUM; unknown id: INVALID_OPERATION.
  void BindRenderbuffer(Enum target, std::uint32_t renderbuffer);
  /// Gives the bound renderbuffer width x height pixels of internal_format: RGBA8, RGB8, RG8, R8, SRGB8_ALPHA8,
  /// SRGB8, RGB565, RGBA4, RGB5_A1, RGB10_A2, RGBA16, RG16, R16, RGBA32F, RG32F, R32F, RGBA16F, RG16F, R16F,
  /// R11F_G11F_B10F,
  /// DEPTH_COMPONENT16 (16-bit fixed point: the depth test compares depths converted to 16 bits),
  /// DEPTH_COMPONENT24/32F (float), DEPTH24_STENCIL8, DEPTH32F_STENCIL8, STENCIL_INDEX8, or the unsized RGBA, RGB, RG,
  /// RED, DEPTH_COMPONENT, DEPTH_STENCIL, STENCIL_INDEX (stored as RGBA8, ..., DEPTH24_STENCIL8, STENCIL_INDEX8), or
  /// DEPTH_COMPONENT32 and STENCIL_INDEX1/4/16, which OpenGL does not require at their sizes (stored as
  /// DEPTH_COMPONENT24 and STENCIL_INDEX8).
  /// Contents start zero. Errors: target not RENDERBUFFER, another format: INVALID_ENUM; size negative or above
  /// MAX_RENDERBUFFER_SIZE (kMaxFramebufferSize): INVALID_VALUE; nothing bound: INVALID_OPERATION; no memory:
  /// OUT_OF_MEMORY.
  void RenderbufferStorage(Enum target, Enum internal_format, int width, int height);
  /// RenderbufferStorage with `samples` samples per pixel: 0 is single-sampled; 1 to 8 give the smallest count of
  /// 2, 4 and 8 not below it (RENDERBUFFER_SAMPLES reports it). A multisampled renderbuffer is drawn into sample by
  /// sample, resolved by BlitFramebuffer into a single-sampled framebuffer, and cannot be read otherwise
  /// (ReadPixels and CopyTex(Sub)Image2D from it record INVALID_OPERATION). All attachments of a framebuffer
  /// object must have the same sample count, else it is FRAMEBUFFER_INCOMPLETE_MULTISAMPLE. Errors as
  /// RenderbufferStorage, and samples < 0 or above MAX_SAMPLES (8): INVALID_VALUE (OpenGL 3.3's code; 4.2 made the
  /// latter INVALID_OPERATION).
  void RenderbufferStorageMultisample(Enum target, int samples, Enum internal_format, int width, int height);
  /// Defines the image of the TEXTURE_2D_MULTISAMPLE texture bound to the active unit: width x height of
  /// `internal_format` (as RenderbufferStorage takes it) with `samples` samples a pixel, rounded up as
  /// RenderbufferStorageMultisample rounds them (all zero). Drawn into through FramebufferTexture2D(...,
  /// TEXTURE_2D_MULTISAMPLE, texture, 0) and resolved by BlitFramebuffer as a multisampled renderbuffer is, it can
  /// also be read sample by sample in a shader (texelFetch: Textures::FetchSample, FragmentLanes::TexelFetchMS).
  /// The samples sit at the standard positions whatever fixed_sample_locations says. It has no levels and no
  /// sampling state: TexParameter and GenerateMipmap on it record INVALID_ENUM. Errors: target not
  /// TEXTURE_2D_MULTISAMPLE, a format drawing cannot render to: INVALID_ENUM; samples below 1, a size negative or
  /// above MAX_TEXTURE_SIZE: INVALID_VALUE; samples above MAX_COLOR_TEXTURE_SAMPLES (8), nothing bound:
  /// INVALID_OPERATION; no memory: OUT_OF_MEMORY.
  void TexImage2DMultisample(Enum target, int samples, Enum internal_format, int width, int height,
                             bool fixed_sample_locations);
  /// Defines the image of the TEXTURE_2D_MULTISAMPLE_ARRAY texture bound to the active unit: `depth` layers of
  /// width x height, each as TexImage2DMultisample defines its one image. A layer is drawn into through
  /// FramebufferTextureLayer(..., texture, 0, layer), every layer through FramebufferTexture (a layered framebuffer:
  /// gl_Layer picks the layer), and read sample by sample in a shader (FragmentLanes::TexelFetchMSArray,
  /// Textures::FetchSampleArray). Errors as TexImage2DMultisample's, and target not TEXTURE_2D_MULTISAMPLE_ARRAY:
  /// INVALID_ENUM; depth negative or above MAX_ARRAY_TEXTURE_LAYERS: INVALID_VALUE.
  void TexImage3DMultisample(Enum target, int samples, Enum internal_format, int width, int height, int depth,
                             bool fixed_sample_locations);
  /// Makes the store of `buffer` (0: none) the texels of the TEXTURE_BUFFER texture bound to the active unit, read
  /// in place as `internal_format`: one row of size / bytes-per-texel texels (at most MAX_TEXTURE_BUFFER_SIZE,
  /// kMaxTextureBufferSize), as the store is when a draw's stage reads it; later BufferData, BufferSubData,
  /// MapBuffer(Range) for writing, CopyBufferSubData and transform feedback into the buffer are seen by the draws
  /// made after them, not by those made before. Shaders read it by texelFetch (FragmentLanes::TexelFetchBuffer,
  /// VertexLanes::TexelFetchBuffer, Textures::FetchBuffer) and textureSize (TextureSizeBuffer); it has no levels
  /// and no sampling state (TexParameter, GenerateMipmap, TexImage* on it: INVALID_ENUM) and cannot be attached to
  /// a framebuffer (INVALID_OPERATION). GetTexLevelParameter(TEXTURE_BUFFER, 0, ...) gives TEXTURE_WIDTH (the
  /// texels), TEXTURE_INTERNAL_FORMAT (R8 before any TexBuffer) and TEXTURE_BUFFER_DATA_STORE_BINDING (the buffer;
  /// a deleted buffer's store stays the texture's until TexBuffer replaces it). Formats: R8, R16, R16F, R32F, RG8,
  /// RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F (OpenGL 3.3's, less the integer ones). Errors: target
  /// not TEXTURE_BUFFER, another format: INVALID_ENUM; buffer neither 0 nor a buffer's id, or no texture bound:
  /// INVALID_OPERATION.
  void TexBuffer(Enum target, Enum internal_format, std::uint32_t buffer);
  /// RENDERBUFFER_WIDTH, _HEIGHT, _INTERNAL_FORMAT (as given, RGBA before any storage), _RED_SIZE, _GREEN_SIZE,
  /// _BLUE_SIZE, _ALPHA_SIZE, _DEPTH_SIZE, _STENCIL_SIZE (the format's bits, as OpenGL reports them), _SAMPLES (0,
  /// or the multisampled renderbuffer's count) of the bound renderbuffer. Errors: bad target or pname: INVALID_ENUM; nothing bound: INVALID_OPERATION.
  void GetRenderbufferParameteriv(Enum target, Enum pname, int* params);

  // ---- Fixed-function state ----------------------------------------------------------------------------------
  /// Maps normalized device coordinates to window pixels. width or height < 0: INVALID_VALUE. Sizes are
  /// clamped to kMaxFramebufferSize. Fragments outside the viewport rectangle are never written.
  void Viewport(int x, int y, int width, int height);
  /// Maps NDC depth [-1, 1] to [n, f]; both clamped to [0, 1].
  void DepthRange(double n, double f);
  /// cap: CULL_FACE, DEPTH_TEST, STENCIL_TEST, SCISSOR_TEST, BLEND, POLYGON_OFFSET_FILL, POLYGON_OFFSET_LINE,
  /// POLYGON_OFFSET_POINT, PROGRAM_POINT_SIZE, PRIMITIVE_RESTART, PRIMITIVE_RESTART_FIXED_INDEX or FRAMEBUFFER_SRGB
  /// (draws, clears and blits into SRGB8_ALPHA8 and SRGB8 attachments encode linear colours, blending decodes the
  /// stored colour first), MULTISAMPLE (enabled by default: into a multisampled framebuffer, triangles cover each
  /// sample at its own position; disabled, a pixel's coverage at its centre goes to all its samples),
  /// SAMPLE_ALPHA_TO_COVERAGE, SAMPLE_ALPHA_TO_ONE, SAMPLE_COVERAGE, SAMPLE_MASK (see SampleCoverage,
  /// SampleMaski); otherwise INVALID_ENUM. All but MULTISAMPLE start disabled.
  /// BLEND is kept per draw buffer: Enable and Disable set every draw buffer's, IsEnabled reads draw buffer 0's.
  void Enable(Enum cap);
  void Disable(Enum cap);
  bool IsEnabled(Enum cap);
  /// glEnablei / glDisablei / glIsEnabledi: BLEND for draw buffer `index` alone (the blend equations and factors
  /// are shared). Another cap: INVALID_ENUM; index >= MAX_DRAW_BUFFERS: INVALID_VALUE.
  void Enablei(Enum cap, std::uint32_t index);
  void Disablei(Enum cap, std::uint32_t index);
  bool IsEnabledi(Enum cap, std::uint32_t index);
  /// The index value that, while PRIMITIVE_RESTART is enabled, ends the primitive sequence of an indexed draw
  /// (DrawElement and its variants) and starts a new one, as if the draw ended there and another began after it
  /// (default 0). It is compared with the index as read, before any base vertex is added. While
  /// PRIMITIVE_RESTART_FIXED_INDEX is enabled the index is instead 2^N - 1 for N-bit indices (255, 65535 or
  /// 2^32 - 1). Draws without indices (DrawArrays and its variants) never restart.
  void PrimitiveRestartIndex(std::uint32_t index);
  /// Which faces CULL_FACE removes: FRONT, BACK (default) or FRONT_AND_BACK.
  void CullFace(Enum mode);
  /// Which winding is front-facing in window coordinates: CCW (default) or CW.
  void FrontFace(Enum mode);
  /// How polygons are rasterized: FILL (default), LINE (edges) or POINT (vertices). face must be
  /// FRONT_AND_BACK, as in an OpenGL core profile.
  void PolygonMode(Enum face, Enum mode);
  /// The width of lines in pixels (default 1; width <= 0 or NaN: INVALID_VALUE), clamped when drawing to
  /// ALIASED_LINE_WIDTH_RANGE, [1, 255]. A line w wide (rounded to an integer) covers, in each column an
  /// x-major line crosses (row for y-major), the w pixels centred on it: OpenGL's wide lines, which llvmpipe
  /// draws the same. Into a multisampled framebuffer with MULTISAMPLE enabled, the samples inside the rectangle of
  /// width w (not rounded) along the segment. Lines drawn by PolygonMode(LINE) are as wide.
  void LineWidth(float width);
  /// Point diameter in pixels when PROGRAM_POINT_SIZE is disabled. size <= 0: INVALID_VALUE.
  void PointSize(float size);
  /// glPointParameter: POINT_SPRITE_COORD_ORIGIN, UPPER_LEFT (the default: gl_PointCoord's t is 0 at the point's
  /// top) or LOWER_LEFT (0 at its bottom), else INVALID_ENUM; POINT_FADE_THRESHOLD_SIZE, a size >= 0 (else
  /// INVALID_VALUE), kept for the queries: OpenGL lets multisampled points below it fade, and softgl draws every
  /// point at its own size without fading. Another pname: INVALID_ENUM; a null pointer: INVALID_VALUE.
  void PointParameterf(Enum pname, float param);
  void PointParameterfv(Enum pname, const float* params);
  void PointParameteri(Enum pname, int param);
  void PointParameteriv(Enum pname, const int* params);
  /// Which vertex of each primitive gives the value of flat varyings (Flat<> in shader.h): FIRST_VERTEX_CONVENTION
  /// or LAST_VERTEX_CONVENTION (the default), as OpenGL 4.6's table 13.2 defines them per mode. Other values:
  /// INVALID_ENUM.
  void ProvokingVertex(Enum mode);
  /// The depth comparison: NEVER, LESS (default), EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS.
  void DepthFunc(Enum func);
  /// Whether depth is written when the depth test is enabled (and by Clear).
  void DepthMask(bool flag);
  /// Depth offset for polygons when POLYGON_OFFSET_FILL (or _LINE, _POINT for PolygonMode LINE, POINT) is enabled:
  /// factor * max(|dz/dx|, |dz/dy|) + units * r, r being the depth buffer's resolution: of a float buffer at the
  /// polygon's largest depth (2^(e - 23) for its exponent e), of a DEPTH_COMPONENT16 one 1 / 65535.
  void PolygonOffset(float factor, float units);

  // ---- Per-fragment operations -------------------------------------------------------------------------------
  // In OpenGL's order: scissor test, stencil test, depth test, stencil update, blending, colour mask.

  /// The scissor rectangle used while SCISSOR_TEST is enabled (also by Clear). width or height < 0:
  /// INVALID_VALUE. Starts as the whole framebuffer.
  void Scissor(int x, int y, int width, int height);
  /// Stencil test for both faces: passes when (ref & mask) func (stencil & mask); ref is clamped to [0, 255].
  /// func: NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS (default ALWAYS, 0, all ones).
  void StencilFunc(Enum func, int ref, std::uint32_t mask);
  /// As StencilFunc for face FRONT, BACK or FRONT_AND_BACK. Points, lines and front-facing polygons use FRONT.
  void StencilFuncSeparate(Enum face, Enum func, int ref, std::uint32_t mask);
  /// What happens to the stencil value when the stencil test fails (sfail), when it passes but the depth test
  /// fails (dpfail), and when both pass or there is no depth test (dppass): KEEP, ZERO, REPLACE, INCR, INCR_WRAP,
  /// DECR, DECR_WRAP, INVERT (default KEEP for all).
  void StencilOp(Enum sfail, Enum dpfail, Enum dppass);
  void StencilOpSeparate(Enum face, Enum sfail, Enum dpfail, Enum dppass);
  /// The stencil bits that drawing and Clear may write (default all).
  void StencilMask(std::uint32_t mask);
  void StencilMaskSeparate(Enum face, std::uint32_t mask);
  /// Blend factors for colour and alpha: ZERO, ONE, SRC_COLOR, ONE_MINUS_SRC_COLOR, DST_COLOR, ONE_MINUS_DST_COLOR,
  /// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, DST_ALPHA, ONE_MINUS_DST_ALPHA, CONSTANT_COLOR, ONE_MINUS_CONSTANT_COLOR,
  /// CONSTANT_ALPHA, ONE_MINUS_CONSTANT_ALPHA, SRC_ALPHA_SATURATE (default ONE, ZERO).
  void BlendFunc(Enum src, Enum dst);
  void BlendFuncSeparate(Enum src_rgb, Enum dst_rgb, Enum src_alpha, Enum dst_alpha);
  /// FUNC_ADD (default), FUNC_SUBTRACT, FUNC_REVERSE_SUBTRACT, MIN, MAX (the last two ignore the factors).
  void BlendEquation(Enum mode);
  void BlendEquationSeparate(Enum mode_rgb, Enum mode_alpha);
  /// The constant colour of the CONSTANT_* factors (clamped to [0, 1] when used).
  void BlendColor(float r, float g, float b, float a);
  /// Which colour channels drawing and Clear write (default all), for every draw buffer.
  void ColorMask(bool r, bool g, bool b, bool a);
  /// glColorMaski: the channels draw buffer `index` writes (index >= MAX_DRAW_BUFFERS: INVALID_VALUE). Clear and
  /// ClearBuffer go through each buffer's own mask.
  void ColorMaski(std::uint32_t index, bool r, bool g, bool b, bool a);
  /// The logic operation drawing applies while COLOR_LOGIC_OP is enabled (default disabled): CLEAR, AND,
  /// AND_REVERSE, COPY (default), AND_INVERTED, NOOP, XOR, OR, NOR, EQUIV, INVERT, OR_REVERSE, COPY_INVERTED,
  /// OR_INVERTED, NAND, SET; another enum: INVALID_ENUM. It takes the bits of the fragment's colour, converted to
  /// the buffer's fixed-point channels as a write would convert it, and of the stored channels, and writes the
  /// result through the colour mask. While it is enabled no draw buffer blends; float buffers (and sRGB-encoded
  /// ones under FRAMEBUFFER_SRGB) take the colour as it is. Clear and ClearBuffer ignore it.
  void LogicOp(Enum opcode);

  // ---- Multisampling -----------------------------------------------------------------------------------------
  // Into a multisampled framebuffer with MULTISAMPLE enabled, the samples a fragment covers are narrowed after
  // the fragment shader, in OpenGL's order (section 17.3.1), by: SAMPLE_ALPHA_TO_COVERAGE (output 0's alpha keeps
  // sample s where alpha > s / samples: 0 keeps none, 1 all; llvmpipe's mapping), SAMPLE_COVERAGE (the first
  // floor(value * samples) samples, or the others when inverted; Mesa's choice) and SAMPLE_MASK (bit s keeps
  // sample s). SAMPLE_ALPHA_TO_ONE then sets the alpha of every colour output to 1. Each kept sample then goes
  // through the stencil and depth tests, blending and the write on its own.
  // Into a single-sampled framebuffer, or with MULTISAMPLE disabled, they do nothing.
  /// SampleCoverage's value (clamped to [0, 1]; default 1) and whether its mask is inverted (default false).
  void SampleCoverage(float value, bool invert);
  /// With SAMPLE_SHADING enabled (OpenGL 4.0's sample shading), the fraction of a pixel's samples the fragment
  /// shader runs for on its own (clamped to [0, 1]; default 0; query MIN_SAMPLE_SHADING_VALUE). When
  /// ceil(value * samples) > 1, softgl runs the shader once for each covered sample, its inputs interpolated at the
  /// sample's position (flat ones as they are), and each run's colour goes to that sample alone. With value *
  /// samples <= 1, or SAMPLE_SHADING or MULTISAMPLE disabled, the shader runs once per pixel.
  void MinSampleShading(float value);
  /// Word `index` of the sample mask (default all ones): bit s for sample s. index >= MAX_SAMPLE_MASK_WORDS (1):
  /// INVALID_VALUE.
  void SampleMaski(std::uint32_t index, Bitfield mask);
  /// SAMPLE_POSITION of sample `index` of the draw framebuffer: x and y in [0, 1) from the pixel's lower left
  /// corner (the standard positions; the centre for a single-sampled framebuffer). Bad pname: INVALID_ENUM; index
  /// not below its sample count: INVALID_VALUE.
  void GetMultisamplefv(Enum pname, std::uint32_t index, float* val);

  // ---- Clearing ----------------------------------------------------------------------------------------------
  void ClearColor(float r, float g, float b, float a);
  void ClearDepth(double depth);
  void ClearStencil(int s);
  /// Clears the buffers named by mask (COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT); any other bit:
  /// INVALID_VALUE. Honours the scissor test, ColorMask, DepthMask and the front StencilMask, as OpenGL does.
  void Clear(Bitfield mask);
  /// Clears one buffer of the draw framebuffer to the value given, as Clear does (the scissor test, ColorMask,
  /// DepthMask and the front StencilMask honoured): COLOR clears draw buffer `drawbuffer` (0 to MAX_DRAW_BUFFERS - 1;
  /// the attachment DrawBuffers sent it to, nothing where that is NONE) to value[0..3] (sRGB-encoded under
  /// FRAMEBUFFER_SRGB); DEPTH to value[0] clamped to [0, 1]; STENCIL to value[0]'s low 8 bits; DEPTH_STENCIL
  /// (ClearBufferfi) both. fv takes COLOR and DEPTH, iv COLOR and STENCIL, uiv COLOR, fi DEPTH_STENCIL; another
  /// buffer: INVALID_ENUM. drawbuffer out of range, or not 0 for DEPTH, STENCIL and DEPTH_STENCIL: INVALID_VALUE;
  /// value null: INVALID_VALUE; an incomplete framebuffer object: INVALID_FRAMEBUFFER_OPERATION. softgl's colour
  /// buffers are not integer ones: iv and uiv's colours are taken as the floats of those numbers (1 is full).
  void ClearBufferfv(Enum buffer, int drawbuffer, const float* value);
  void ClearBufferiv(Enum buffer, int drawbuffer, const int* value);
  void ClearBufferuiv(Enum buffer, int drawbuffer, const std::uint32_t* value);
  void ClearBufferfi(Enum buffer, int drawbuffer, float depth, int stencil);

  // ---- Drawing -----------------------------------------------------------------------------------------------
  /// Draws vertices [first, first + count) of the bound vertex array. mode: POINTS, LINES, LINE_STRIP, LINE_LOOP,
  /// TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN (else INVALID_ENUM). first or count < 0: INVALID_VALUE. No vertex
  /// array or no shader, an enabled array's buffer mapped: INVALID_OPERATION. Attribute reads past the end of a
  /// buffer read (0, 0, 0, 1).
  void DrawArrays(Enum mode, int first, int count);
  /// Draws count vertices whose indices of `type` (UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT) are read from the
  /// bound vertex array's element buffer at byte `offset`. No element buffer, the element buffer mapped, or
  /// indices past its end: INVALID_OPERATION (nothing is drawn); otherwise as DrawArrays.
  void DrawElement(Enum mode, int count, Enum type, std::size_t offset);
  /// DrawElement with `basevertex` added to every index before it is used (gl_VertexID included). An index whose
  /// sum falls outside 0 .. 2^32 - 1 (undefined in OpenGL) reads (0, 0, 0, 1) for every attribute.
  void DrawElementsBaseVertex(Enum mode, int count, Enum type, std::size_t offset, int basevertex);
  /// DrawElement with the promise that the indices lie in [start, end] (not relied on: any index is read as
  /// DrawElement reads it). end < start: INVALID_VALUE.
  void DrawRangeElements(Enum mode, std::uint32_t start, std::uint32_t end, int count, Enum type, std::size_t offset);
  /// DrawRangeElements with `basevertex` added to every index, as DrawElementsBaseVertex adds it.
  void DrawRangeElementsBaseVertex(Enum mode, std::uint32_t start, std::uint32_t end, int count, Enum type,
                                   std::size_t offset, int basevertex);
  /// DrawArrays `instancecount` times, in order, instance i with gl_InstanceID = i (VertexLanes::instance_id) and
  /// its divisor attributes at element i / divisor. instancecount < 0: INVALID_VALUE; 0 draws nothing.
  void DrawArraysInstanced(Enum mode, int first, int count, int instancecount);
  /// DrawElement `instancecount` times, as DrawArraysInstanced does DrawArrays.
  void DrawElementsInstanced(Enum mode, int count, Enum type, std::size_t offset, int instancecount);
  /// DrawElementsInstanced with `basevertex` added to every index (not to the instance's divisor attributes).
  void DrawElementsInstancedBaseVertex(Enum mode, int count, Enum type, std::size_t offset, int instancecount,
                                       int basevertex);
  /// DrawArrays(mode, first[i], count[i]) for i in [0, drawcount). drawcount, a first or a count negative:
  /// INVALID_VALUE, and nothing is drawn.
  void MultiDrawArrays(Enum mode, const int* first, const int* count, int drawcount);
  /// DrawElement(mode, count[i], type, offsets[i]) for i in [0, drawcount). drawcount or a count negative:
  /// INVALID_VALUE; a list that would read past the end of the element buffer: INVALID_OPERATION; on any error
  /// nothing is drawn.
  void MultiDrawElements(Enum mode, const int* count, Enum type, const std::size_t* offsets, int drawcount);
  /// MultiDrawElements with basevertex[i] added to the indices of draw i. basevertex null (with drawcount > 0):
  /// INVALID_VALUE.
  void MultiDrawElementsBaseVertex(Enum mode, const int* count, Enum type, const std::size_t* offsets, int drawcount,
                                   const int* basevertex);

  // ---- Query objects -------------------------------------------------------------------------------------------
  /// Creates a query object and returns its id (never 0).
  std::uint32_t GenQuery();
  void GenQueries(int n, std::uint32_t* ids);
  /// Deletes a query object (an active one ends first). 0 and unknown ids are ignored.
  void DeleteQuery(std::uint32_t id);
  void DeleteQueries(int n, const std::uint32_t* ids);
  bool IsQuery(std::uint32_t id) const;
  /// Starts counting into query `id` for target: SAMPLES_PASSED (fragments that pass every per-fragment test),
  /// ANY_SAMPLES_PASSED (whether any did), PRIMITIVES_GENERATED (primitives assembled from the draws' vertices,
  /// before clipping and culling), TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN (primitives transform feedback recorded)
  /// or TIME_ELAPSED (nanoseconds of the work between BeginQuery and EndQuery,
  /// rendering included: both render what was recorded before them). Errors: bad target: INVALID_ENUM; a query
  /// already active on target (SAMPLES_PASSED and ANY_SAMPLES_PASSED count as one), an id not made by GenQuery, a query active elsewhere or begun before with another
  /// target: INVALID_OPERATION.
  void BeginQuery(Enum target, std::uint32_t id);
  /// Stops the query active on target (none: INVALID_OPERATION).
  void EndQuery(Enum target);
  /// Records in query `id` the time (TIMESTAMP: nanoseconds, the clock GetInteger64v(TIMESTAMP) reads) once
  /// everything before it has been rendered: it renders what was recorded. Errors: target not TIMESTAMP:
  /// INVALID_ENUM; an id not made by GenQuery, an active query or one begun with another target: INVALID_OPERATION.
  void QueryCounter(std::uint32_t id, Enum target);
  /// CURRENT_QUERY (the id active on target, or 0) or QUERY_COUNTER_BITS (64); TIMESTAMP takes QUERY_COUNTER_BITS
  /// alone.
  void GetQueryiv(Enum target, Enum pname, int* params) const;
  /// QUERY_RESULT (the count, or 0 / 1 for ANY_SAMPLES_PASSED, or nanoseconds) or QUERY_RESULT_AVAILABLE (true:
  /// asking renders the recorded draws the result depends on, so it is always available). The smaller types clamp
  /// the value. A query never begun, or active: INVALID_OPERATION; another pname: INVALID_ENUM.
  void GetQueryObjectiv(std::uint32_t id, Enum pname, int* params);
  void GetQueryObjectuiv(std::uint32_t id, Enum pname, std::uint32_t* params);
  void GetQueryObjecti64v(std::uint32_t id, Enum pname, std::int64_t* params);
  void GetQueryObjectui64v(std::uint32_t id, Enum pname, std::uint64_t* params);

  // ---- Conditional rendering -----------------------------------------------------------------------------------
  /// glBeginConditionalRender: until EndConditionalRender, draws and clears (Clear, ClearBuffer*) are dropped when
  /// occlusion query `id` (SAMPLES_PASSED or ANY_SAMPLES_PASSED) counted nothing. QUERY_WAIT and
  /// QUERY_BY_REGION_WAIT render what was recorded before, so that the result is known; QUERY_NO_WAIT and
  /// QUERY_BY_REGION_NO_WAIT use the result if the draws it counted have already been rendered (Finish, a read
  /// back, a query's result) and otherwise draw unconditionally, as OpenGL allows. The result is taken once, here.
  /// Errors: bad mode: INVALID_ENUM; an id that is not a query: INVALID_VALUE; conditional rendering already on, a
  /// query never begun, of another target, or active: INVALID_OPERATION.
  void BeginConditionalRender(std::uint32_t id, Enum mode);
  /// Ends conditional rendering (not on: INVALID_OPERATION).
  void EndConditionalRender();

  // ---- Sync objects --------------------------------------------------------------------------------------------
  /// glFenceSync: a fence, signalled once everything recorded before it has been rendered (Finish, Flush, a read
  /// back, ClientWaitSync). condition must be SYNC_GPU_COMMANDS_COMPLETE (else INVALID_ENUM) and flags 0 (else
  /// INVALID_VALUE); null on error.
  Sync FenceSync(Enum condition, Bitfield flags);
  /// Whether `sync` is a fence FenceSync made and DeleteSync has not deleted.
  bool IsSync(Sync sync) const;
  /// Deletes a fence. Null is ignored; anything else that is not a fence: INVALID_VALUE.
  void DeleteSync(Sync sync);
  /// glClientWaitSync: ALREADY_SIGNALED when the fence is signalled already; else with timeout 0 it renders
  /// nothing (unless flags has SYNC_FLUSH_COMMANDS_BIT, which renders as Flush does) and returns TIMEOUT_EXPIRED;
  /// with a timeout above 0 it renders what was recorded, however long that takes, and returns
  /// CONDITION_SATISFIED. Not a fence, or flags other than SYNC_FLUSH_COMMANDS_BIT: INVALID_VALUE, WAIT_FAILED.
  Enum ClientWaitSync(Sync sync, Bitfield flags, std::uint64_t timeout);
  /// glWaitSync: commands run in order, so there is nothing to wait for; it checks its arguments (not a fence,
  /// flags not 0, timeout not TIMEOUT_IGNORED: INVALID_VALUE).
  void WaitSync(Sync sync, Bitfield flags, std::uint64_t timeout);
  /// glGetSynciv: OBJECT_TYPE (SYNC_FENCE), SYNC_STATUS (SIGNALED or UNSIGNALED), SYNC_CONDITION
  /// (SYNC_GPU_COMMANDS_COMPLETE), SYNC_FLAGS (0), one value written to `values` if bufSize > 0, and 1 to `length`
  /// unless it is null. Not a fence, negative bufSize: INVALID_VALUE; another pname: INVALID_ENUM.
  void GetSynciv(Sync sync, Enum pname, int bufSize, int* length, int* values) const;

  // ---- State queries -----------------------------------------------------------------------------------------
  /// glGet*: the state named by pname, converted as OpenGL converts it (booleans to 0 / 1; floats to integers by
  /// rounding, except colours and depths, which map [-1, 1] linearly onto the integer range; GetIntegerv clamps to
  /// int). Names: the Enable capabilities; the bindings (ARRAY_BUFFER_BINDING, ELEMENT_ARRAY_BUFFER_BINDING,
  /// COPY_READ/WRITE_BUFFER_BINDING, VERTEX_ARRAY_BINDING, ACTIVE_TEXTURE, TEXTURE_BINDING_2D/CUBE_MAP and
  /// SAMPLER_BINDING of the active unit, DRAW/READ_FRAMEBUFFER_BINDING, RENDERBUFFER_BINDING, DRAW_BUFFER0 + i (DRAW_BUFFER: the first),
  /// READ_BUFFER); VIEWPORT, SCISSOR_BOX (4 values), DEPTH_RANGE
  /// (2); CULL_FACE_MODE, FRONT_FACE, POLYGON_MODE (2), POINT_SIZE, LINE_WIDTH, PROVOKING_VERTEX, POLYGON_OFFSET_FACTOR/UNITS,
  /// PRIMITIVE_RESTART_INDEX; DEPTH_FUNC, DEPTH_WRITEMASK, DEPTH_CLEAR_VALUE; STENCIL_FUNC, _REF, _VALUE_MASK,
  /// _FAIL, _PASS_DEPTH_FAIL, _PASS_DEPTH_PASS, _WRITEMASK and their STENCIL_BACK_ forms, STENCIL_CLEAR_VALUE;
  /// BLEND_SRC/DST_RGB/ALPHA, BLEND_EQUATION_RGB/ALPHA, BLEND_COLOR (4), LOGIC_OP_MODE, COLOR_CLEAR_VALUE (4),
  /// COLOR_WRITEMASK (4); UNPACK_ALIGNMENT and the PACK_ settings; the limits MAX_VERTEX_ATTRIBS, MAX_TEXTURE_SIZE,
  /// MAX_CUBE_MAP_TEXTURE_SIZE, MAX_TEXTURE_IMAGE_UNITS (and the VERTEX_ and COMBINED_ forms), MAX_DRAW_BUFFERS,
  /// MAX_COLOR_ATTACHMENTS, MAX_SAMPLES (8, one value), MAX_RENDERBUFFER_SIZE, MAX_VIEWPORT_DIMS (2), MAX_VARYING_COMPONENTS,
  /// MAX_ELEMENTS_VERTICES/INDICES, POINT_SIZE_RANGE (2), ALIASED_LINE_WIDTH_RANGE (2, [1, 255]), SUBPIXEL_BITS,
  /// MAJOR_VERSION, MINOR_VERSION (3.3), NUM_EXTENSIONS (0), CONTEXT_PROFILE_MASK (core). `data` must hold as many
  /// values as the name has. Another name: INVALID_ENUM, data untouched.
  void GetIntegerv(Enum pname, int* data) const;
  void GetInteger64v(Enum pname, std::int64_t* data) const;
  void GetFloatv(Enum pname, float* data) const;
  void GetDoublev(Enum pname, double* data) const;
  void GetBooleanv(Enum pname, bool* data) const;
  /// glGetBooleani_v / glGetIntegeri_v / glGetInteger64i_v: indexed state, BLEND (1 value) and COLOR_WRITEMASK (4)
  /// of draw buffer `index`, SAMPLE_MASK_VALUE of mask word `index` (0 only). Another name: INVALID_ENUM; an index
  /// past the last: INVALID_VALUE. (COLOR_WRITEMASK and BLEND through the plain Get calls: draw buffer 0's.)
  void GetBooleani_v(Enum target, std::uint32_t index, bool* data) const;
  void GetIntegeri_v(Enum target, std::uint32_t index, int* data) const;
  void GetInteger64i_v(Enum target, std::uint32_t index, std::int64_t* data) const;
  /// VENDOR, RENDERER, VERSION ("3.3 softgl" and softgl's version) or SHADING_LANGUAGE_VERSION; another name:
  /// INVALID_ENUM and null.
  const char* GetString(Enum name) const;

  // ---- Reading back ------------------------------------------------------------------------------------------
  // From the framebuffer bound to READ_FRAMEBUFFER: the context's own, or a framebuffer object's read buffer
  // (ReadBuffer; COLOR_ATTACHMENT0 unless changed), depth and stencil attachments.

  /// glReadPixels: the rectangle (x, y, width, height) of the read framebuffer (y from the bottom, rows bottom
  /// first) into `pixels`, laid out by PACK_ALIGNMENT, PACK_ROW_LENGTH, PACK_SKIP_ROWS and PACK_SKIP_PIXELS
  /// (PixelStore). format: RED, GREEN, BLUE, RG, RGB, BGR, RGBA, BGRA (from the read buffer), DEPTH_COMPONENT,
  /// STENCIL_INDEX, DEPTH_STENCIL; type: every type of OpenGL 3.3 (as TexImage2D lists them): UNSIGNED_BYTE,
  /// UNSIGNED_SHORT, UNSIGNED_INT (round(clamp(v, 0, 1) * (2^b - 1))), BYTE, SHORT, INT (round(clamp(v, -1, 1) *
  /// (2^(b-1) - 1))), HALF_FLOAT and FLOAT (as stored), the packed types (each field as the unsigned ones; the
  /// two packed float types encoded), stencil indices masked to the type's bits; DEPTH_STENCIL with
  /// UNSIGNED_INT_24_8 (depth in the high 24 bits, stencil in the low 8) or FLOAT_32_UNSIGNED_INT_24_8_REV.
  /// Pixels of the rectangle outside the framebuffer are not written; colours are clamped to [0, 1] first where
  /// ClampColor says so. Errors: bad format or type, DEPTH_STENCIL
  /// with another type: INVALID_ENUM; negative size: INVALID_VALUE; a packed type with another format, an integer
  /// format, no buffer of the kind asked: INVALID_OPERATION; incomplete read framebuffer:
  /// INVALID_FRAMEBUFFER_OPERATION.
  void ReadPixels(int x, int y, int width, int height, Enum format, Enum type, void* pixels) const;
  /// glClampColor(CLAMP_READ_COLOR, clamp): whether ReadPixels clamps colours to [0, 1] before converting them:
  /// true (1) clamps; false (0) does not; FIXED_ONLY (the default) clamps values read from fixed-point buffers only,
  /// which hold [0, 1] already, so float buffers read as stored. Query CLAMP_READ_COLOR. Errors: another target or
  /// clamp: INVALID_ENUM.
  void ClampColor(Enum target, Enum clamp);
  /// The colour buffer, top row first (ready for WritePng).
  Image ReadPixels() const;
  /// The colour of window pixel (x, y), y counted from the bottom as in OpenGL; {0,0,0,0} outside.
  void ReadPixel(int x, int y, std::uint8_t rgba[4]) const;
  /// The depth buffer value at window pixel (x, y); 0 outside.
  float ReadDepth(int x, int y) const;
  /// The stencil buffer value at window pixel (x, y); 0 outside.
  std::uint8_t ReadStencil(int x, int y) const;

 private:
  std::unique_ptr<ContextState> state_;
};

}  // namespace softgl

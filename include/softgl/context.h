// softgl/context.h — the rendering context: OpenGL's state machine over an offscreen framebuffer.
//
// A Context owns an offscreen framebuffer (RGBA8 colour, 32-bit float depth, 8-bit stencil), the objects
// created through it (buffers and vertex arrays, addressed by integer ids as in OpenGL) and all rendering state.
// Calls act on what is bound, with OpenGL's meaning. Every call validates its arguments; a call that fails records
// OpenGL's error code (the first one since the last GetError()) and changes nothing.
//
// A Context is not thread-safe: use one context per thread (several contexts may render at once).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include <softgl/enums.h>
#include <softgl/image.h>
#include <softgl/shader.h>

namespace softgl {

/// Largest framebuffer width or height, and largest viewport size (GL_MAX_VIEWPORT_DIMS).
inline constexpr int kMaxFramebufferSize = 16384;

struct ContextState;  // defined in src/, never seen by users

class Context {
 public:
  /// Creates a context whose framebuffer is width x height pixels. 0 x 0 is allowed (every draw is then a no-op).
  /// A negative size or one larger than kMaxFramebufferSize gives a 0 x 0 framebuffer and INVALID_VALUE; a
  /// framebuffer that cannot be allocated gives a 0 x 0 one and OUT_OF_MEMORY. The viewport starts as the
  /// whole framebuffer.
  Context(int width, int height);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int Width() const;
  int Height() const;

  // ---- Errors ------------------------------------------------------------------------------------------------
  /// Returns the first error recorded since the last call, and clears it (NO_ERROR when there was none).
  Enum GetError();

  // ---- Buffer objects ----------------------------------------------------------------------------------------
  /// Creates a buffer object and returns its id (never 0).
  std::uint32_t GenBuffer();
  /// Creates n buffer objects, writing their ids to ids. n < 0: INVALID_VALUE.
  void GenBuffers(int n, std::uint32_t* ids);
  /// Deletes a buffer; it is unbound from ARRAY_BUFFER and from the bound vertex array's element binding.
  /// Attribute bindings in other vertex arrays keep the storage alive, as OpenGL does. 0 and unknown ids are ignored.
  void DeleteBuffer(std::uint32_t buffer);
  bool IsBuffer(std::uint32_t buffer) const;
  /// Binds buffer (0 unbinds) to target ARRAY_BUFFER or ELEMENT_ARRAY_BUFFER. The ELEMENT_ARRAY_BUFFER binding
  /// is part of the bound vertex array (INVALID_OPERATION if none is bound). Bad target: INVALID_ENUM; an id not
  /// made by GenBuffer: INVALID_OPERATION.
  void BindBuffer(Enum target, std::uint32_t buffer);
  /// Replaces the store of the buffer bound to target with size bytes copied from data (zeros if data is null).
  /// size < 0: INVALID_VALUE; bad target or usage: INVALID_ENUM; nothing bound: INVALID_OPERATION;
  /// allocation failure: OUT_OF_MEMORY.
  void BufferData(Enum target, std::ptrdiff_t size, const void* data, Enum usage = STATIC_DRAW);
  /// Overwrites bytes [offset, offset + size) of the bound buffer. Range outside the store: INVALID_VALUE.
  void BufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data);

  // ---- Vertex array objects ----------------------------------------------------------------------------------
  /// Creates a vertex array object and returns its id (never 0). A vertex array records the attribute
  /// bindings and the ELEMENT_ARRAY_BUFFER binding.
  std::uint32_t GenVertexArray();
  void GenVertexArrays(int n, std::uint32_t* ids);
  /// Deletes a vertex array; if it is bound, 0 becomes bound. 0 and unknown ids are ignored.
  void DeleteVertexArray(std::uint32_t array);
  bool IsVertexArray(std::uint32_t array) const;
  /// Binds a vertex array (0: none, as in an OpenGL core profile). Unknown id: INVALID_OPERATION.
  void BindVertexArray(std::uint32_t array);
  /// Sets attribute `index` of the bound vertex array to read `size` (1-4) components of `type` (BYTE,
  /// UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, INT, UNSIGNED_INT, FLOAT) from the buffer now bound to ARRAY_BUFFER,
  /// starting at byte `offset`, every `stride` bytes (0 means tightly packed). Integer types are converted to
  /// float; with `normalized` they map to [0, 1] (unsigned) or [-1, 1] (signed, max(c / (2^(b-1) - 1), -1)).
  /// index >= kMaxVertexAttribs, size outside 1-4 or stride < 0: INVALID_VALUE; bad type: INVALID_ENUM;
  /// no vertex array bound, or no ARRAY_BUFFER bound with offset != 0: INVALID_OPERATION.
  void VertexAttributePointer(std::uint32_t index, int size, Enum type, bool normalized, int stride,
                              std::size_t offset);
  void EnableVertexAttribArray(std::uint32_t index);
  void DisableVertexAttribArray(std::uint32_t index);
  /// The current value of a generic attribute, read by the vertex stage while its array is disabled.
  void VertexAttrib4f(std::uint32_t index, float x, float y, float z, float w);

  // ---- Shaders -----------------------------------------------------------------------------------------------
  /// Makes `program` (usually a softgl::Shader subclass) the current shader. The context keeps a pointer: the
  /// shader must outlive its use, and changes to its members (uniforms) are seen by later draws.
  void UseProgram(const Program& program);
  /// Unbinds the current shader; draws then record INVALID_OPERATION.
  void UseProgram(std::nullptr_t);

  // ---- Fixed-function state ----------------------------------------------------------------------------------
  /// Maps normalized device coordinates to window pixels. width or height < 0: INVALID_VALUE. Sizes are
  /// clamped to kMaxFramebufferSize. Fragments outside the viewport rectangle are never written.
  void Viewport(int x, int y, int width, int height);
  /// Maps NDC depth [-1, 1] to [n, f]; both clamped to [0, 1].
  void DepthRange(double n, double f);
  /// cap: CULL_FACE, DEPTH_TEST, STENCIL_TEST, SCISSOR_TEST, BLEND, POLYGON_OFFSET_FILL, POLYGON_OFFSET_LINE,
  /// POLYGON_OFFSET_POINT or PROGRAM_POINT_SIZE; otherwise INVALID_ENUM. All start disabled.
  void Enable(Enum cap);
  void Disable(Enum cap);
  bool IsEnabled(Enum cap);
  /// Which faces CULL_FACE removes: FRONT, BACK (default) or FRONT_AND_BACK.
  void CullFace(Enum mode);
  /// Which winding is front-facing in window coordinates: CCW (default) or CW.
  void FrontFace(Enum mode);
  /// How polygons are rasterized: FILL (default), LINE (edges) or POINT (vertices). face must be
  /// FRONT_AND_BACK, as in an OpenGL core profile.
  void PolygonMode(Enum face, Enum mode);
  /// Point diameter in pixels when PROGRAM_POINT_SIZE is disabled. size <= 0: INVALID_VALUE.
  void PointSize(float size);
  /// The depth comparison: NEVER, LESS (default), EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS.
  void DepthFunc(Enum func);
  /// Whether depth is written when the depth test is enabled (and by Clear).
  void DepthMask(bool flag);
  /// Depth offset for polygons when POLYGON_OFFSET_FILL (or _LINE, _POINT for PolygonMode LINE, POINT) is enabled:
  /// factor * max(|dz/dx|, |dz/dy|) + units * r, r being the depth buffer's resolution at the polygon's
  /// largest depth (2^(e - 23) for its exponent e; the depth buffer is 32-bit float).
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
  /// Which colour channels drawing and Clear write (default all).
  void ColorMask(bool r, bool g, bool b, bool a);

  // ---- Clearing ----------------------------------------------------------------------------------------------
  void ClearColor(float r, float g, float b, float a);
  void ClearDepth(double depth);
  void ClearStencil(int s);
  /// Clears the buffers named by mask (COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT | STENCIL_BUFFER_BIT); any other bit:
  /// INVALID_VALUE. Honours the scissor test, ColorMask, DepthMask and the front StencilMask, as OpenGL does.
  void Clear(Bitfield mask);

  // ---- Drawing -----------------------------------------------------------------------------------------------
  /// Draws vertices [first, first + count) of the bound vertex array. mode: POINTS, LINES, LINE_STRIP, LINE_LOOP,
  /// TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN (else INVALID_ENUM). first or count < 0: INVALID_VALUE. No vertex
  /// array or no shader: INVALID_OPERATION. Attribute reads past the end of a buffer read (0, 0, 0, 1).
  void DrawArrays(Enum mode, int first, int count);
  /// Draws count vertices whose indices of `type` (UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT) are read from the
  /// bound vertex array's element buffer at byte `offset`. No element buffer, or indices past its end:
  /// INVALID_OPERATION (nothing is drawn); otherwise as DrawArrays.
  void DrawElement(Enum mode, int count, Enum type, std::size_t offset);

  // ---- Reading back ------------------------------------------------------------------------------------------
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

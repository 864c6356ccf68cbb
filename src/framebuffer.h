// framebuffer.h — where fragments go: the context's own framebuffer (RGBA8, SRGB8_ALPHA8 or RGB565 colour, 32-bit
// float depth, 8-bit stencil) and RenderTarget, the view of whatever is bound for drawing (that framebuffer, or a
// framebuffer object's texture attachments) that the per-fragment operations write through. Row 0 is the bottom
// row, as in OpenGL.
#pragma once

#include <cmath>
#include <cstdint>
#include <new>
#include <vector>

#include <softgl/shader.h>

#include "texture.h"
#include "types.h"

namespace softgl::detail {

/// One colour buffer: the default framebuffer's RGBA8 bytes, or a texture level's texels in their own layout.
struct ColorBuffer {
  std::uint8_t* data = nullptr;
  TexelLayout layout = TexelLayout::kNone;
  bool rgb_only = false;  // RGB8, SRGB8: alpha is not stored (reads 1)
  int pitch = 0;          // texels from one row to the next
  // An sRGB buffer (SRGB8_ALPHA8, SRGB8) while FRAMEBUFFER_SRGB is enabled: Store encodes the colour channels from
  // linear, Load decodes them (OpenGL 4.6, section 17.3.7). Else an sRGB buffer's bytes are taken as they are.
  bool srgb = false;
  std::size_t plane = 0;  // texels from one sample's plane to the next (a multisampled buffer)
  int step = 1;           // texels from one pixel to the next in a row (samples side by side: the sample count)
  bool Present() const { return data != nullptr; }
  bool Rgba8() const { return layout == TexelLayout::kUnorm8x4 && !rgb_only && !srgb; }
  int Bytes() const { return BytesPerTexel(layout); }
  std::size_t Index(int x, int y) const {
    return std::size_t(y) * std::size_t(pitch) + std::size_t(x) * std::size_t(step);
  }
  std::uint8_t* At(int x, int y) const { return data + Index(x, y) * std::size_t(Bytes()); }
  /// The pixel as RGBA floats (fixed point divided by 255, sRGB decoded when `srgb`; channels the format lacks read
  /// (0, 0, 0, 1)).
  glm::vec4 Load(int x, int y) const;
  /// Stores `c` through `mask` with the format's conversion (clamp and round for fixed point, sRGB encoded when
  /// `srgb`).
  void Store(int x, int y, const glm::vec4& c, const bool mask[4]) const;
  /// Whether stored values are fixed point (clamped to [0, 1] before blending).
  bool Normalized() const { return IsUnorm8(layout); }
};

/// The sample count a buffer asked for `requested` samples gets: 0 gives 1 (single-sampled); 1 and 2 give 2, 3 and
/// 4 give 4, 5 to 8 give 8 (the smallest supported count not below the request, as OpenGL requires).
int SupportedSamples(int requested);

struct SampleTiles;

/// The buffers drawing writes to; color[i] receives fragment output i (draw buffers already applied).
/// A multisampled target keeps each buffer either as `samples` planes of width x height, one per sample, one after
/// another (a framebuffer object's attachments), or with each pixel's samples side by side (`interleaved`, the
/// context's own framebuffer: plane 1, step and row pitch in samples). Sample(s) is the single-sampled view of
/// sample s either way (strided when interleaved).
struct RenderTarget {
  // The context's multisampled framebuffer as the tile renderer draws into it: its tiles' deferred clears and
  // resolve state (see SampleTiles). Null for every other target, and for every other user of this one.
  SampleTiles* tiles = nullptr;
  int width = 0, height = 0;
  int samples = 1;                  // 1, 2, 4 or 8
  // Every buffer holds a pixel's samples side by side, one after another: values (x, y, s) at y pitch + x samples
  // + s, so that a quad row's samples are one run (the tile renderer's vector operations read them so).
  bool interleaved = false;
  int step = 1;                     // depth and stencil values from one pixel to the next in a row
  std::size_t depth_plane = 0;      // depth values from one sample's plane to the next
  std::size_t stencil_plane = 0;    // stencil values from one sample's plane to the next
  ColorBuffer color[kMaxColorOutputs];
  // The depth buffer: 32-bit floats (`depth`), or 16-bit fixed point (`depth16`, DEPTH_COMPONENT16: k / 65535);
  // neither: no depth buffer (the depth test then always passes).
  float* depth = nullptr;
  std::uint16_t* depth16 = nullptr;
  int depth_pitch = 0;              // depth values from one row to the next
  std::uint8_t* stencil = nullptr;  // null: no stencil buffer (the stencil test then always passes)
  int stencil_pitch = 0;            // stencil values from one row to the next
  Rect Bounds() const { return Rect{0, 0, width, height}; }
  bool HasDepth() const { return depth || depth16; }
  std::size_t DepthIndex(int x, int y, int s) const {
    return depth_plane * std::size_t(s) + std::size_t(y) * std::size_t(depth_pitch) + std::size_t(x) * std::size_t(step);
  }
  /// The depth stored at (x, y) of sample plane s, in [0, 1].
  float DepthAt(int x, int y, int s = 0) const {
    return depth16 ? float(depth16[DepthIndex(x, y, s)]) / 65535.0f : depth[DepthIndex(x, y, s)];
  }
  /// Stores d, a value StoredDepth gave, at (x, y) of sample plane s.
  void SetDepth(int x, int y, float d, int s = 0) const {
    if (depth16) depth16[DepthIndex(x, y, s)] = Depth16(d);
    else depth[DepthIndex(x, y, s)] = d;
  }
  /// A fragment's depth d in [0, 1] as the buffer keeps it, for the depth test: the 16-bit buffer's nearest
  /// k / 65535 (OpenGL converts to the buffer's fixed point before the test), the float buffer's d.
  float StoredDepth(float d) const { return depth16 ? float(Depth16(d)) / 65535.0f : d; }
  /// d in [0, 1] to 16 bits: round(d * 65535), ties to even.
  static std::uint16_t Depth16(float d) { return std::uint16_t(std::nearbyint(d * 65535.0f)); }
  std::uint8_t& Stencil(int x, int y) const {
    return stencil[std::size_t(y) * std::size_t(stencil_pitch) + std::size_t(x) * std::size_t(step)];
  }

  /// Plane s of every buffer, as a single-sampled target.
  RenderTarget Sample(int s) const;
  /// An interleaved target as a single-sampled one of width x samples, each sample a pixel of its own: sample s of
  /// pixel x is pixel x samples + s of the row (for the operations that fill runs of every sample).
  RenderTarget Flat() const;

  /// Clears rectangle r (inside the target) of every colour buffer in `buffers` (bit i: color[i], draw buffer i)
  /// through `mask` (every sample).
  void ClearColor(const Rect& r, const glm::vec4& value, const bool mask[4], std::uint32_t buffers = ~0u) const;
  void ClearDepth(const Rect& r, float value) const;
  /// Clears the stencil bits of write_mask in rectangle r.
  void ClearStencil(const Rect& r, std::uint8_t value, std::uint8_t write_mask) const;
};

/// Buffer bits for SampleTiles.
inline constexpr unsigned kColorBit = 1, kDepthBit = 2, kStencilBit = 4, kAllBuffers = 7;

/// The context's multisampled framebuffer in the tile renderer's tiles (kSize squares, row by row from the
/// bottom, as TileGrid lays them): what its samples and its resolved image hold, tile by tile.
///
/// A clear that covers a whole tile through every mask is only noted here (`cleared` and the value): the samples
/// of that buffer keep what they held, and take the value when a primitive first reaches the tile (Store), or when
/// anything but the tile renderer and the resolve asks for the samples (Framebuffer::Target stores every tile's).
/// The resolve fills such a tile of the resolved image from the value without reading a sample. So the tiles that a
/// frame clears but no primitive reaches cost neither the samples' clear nor the resolve's reads.
///
/// `stale` marks the buffers whose resolved image of the tile is out of date: the tile renderer sets them for each
/// tile it renders, and resolves colour there at the end of the tile while its samples are in cache.
/// Each tile's entry is touched by the one thread that renders the tile.
struct SampleTiles {
  static constexpr int kSize = 64;
  struct Tile {
    std::uint8_t cleared = 0;  // buffers (kColorBit, ...) whose samples all hold the value below, not yet stored
    std::uint8_t stale = 0;    // buffers whose resolved image of this tile is out of date
    std::uint8_t color[16] = {};  // the clear colour as the buffer stores a texel
    float depth = 1.0f;
    std::uint8_t stencil = 0;
  };
  int cols = 0, rows = 0;
  std::vector<Tile> tiles;
  RenderTarget resolved;  // the single-sampled image reads see (set by Framebuffer::FrameTarget)

  /// Resets the grid for a width x height framebuffer: nothing deferred, nothing stale.
  void Reset(int width, int height);
  /// The pixels of tile t in a width x height target.
  Rect TileRect(int t, int width, int height) const;
  /// Notes a clear of tile t's colour (through every mask), depth or stencil to `value`, as the samples of
  /// `target` (the framebuffer's) would store it.
  void NoteColor(const RenderTarget& target, int t, const glm::vec4& value);
  void NoteDepth(int t, float value);
  void NoteStencil(int t, std::uint8_t value);
  /// Writes the deferred clears of `buffers` in tile t into the samples of `target`.
  void Store(const RenderTarget& target, int t, unsigned buffers);
  /// Brings the resolved image of tile t up to date for the stale buffers among `buffers`, from the samples of
  /// `target` (or the deferred clear's value).
  void Resolve(const RenderTarget& target, int t, unsigned buffers);
};

/// Storage whose first value starts a 64-byte cache line (so that a row whose pitch is a whole number of lines
/// starts one too, and the vector operations' runs never straddle two).
template <class T>
struct LineAligned {
  using value_type = T;
  static constexpr std::align_val_t kAlign{64};
  LineAligned() = default;
  template <class U>
  LineAligned(const LineAligned<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlign)); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, kAlign); }
  template <class U>
  bool operator==(const LineAligned<U>&) const { return true; }
};
template <class T>
using LineVector = std::vector<T, LineAligned<T>>;

/// The context's own framebuffer. With samples > 1 the buffers drawing writes hold each pixel's `samples` samples
/// side by side (an interleaved RenderTarget), and `resolved` the single-sampled image reads see, made by Resolve.
struct Framebuffer {
  int width = 0;
  int height = 0;
  int samples = 1;
  TexelLayout layout = TexelLayout::kUnorm8x4;  // of the colour buffer: kUnorm8x4 (RGBA8) or kUnorm565 (RGB565)
  bool srgb = false;  // the colour buffer is SRGB8_ALPHA8: it converts while FRAMEBUFFER_SRGB is enabled
  bool depth16 = false;  // the depth buffer is DEPTH_COMPONENT16 (`depth16_data`), else float (`depth`)
  LineVector<std::uint8_t> color;  // [height][RowPitch: width][samples][bytes of the layout]
  LineVector<float> depth;         // [height][RowPitch: width][samples]
  LineVector<std::uint16_t> depth16_data;
  LineVector<std::uint8_t> stencil;
  struct Resolved {
    LineVector<std::uint8_t> color;
    LineVector<float> depth;
    LineVector<std::uint16_t> depth16_data;
    LineVector<std::uint8_t> stencil;
  } resolved;  // samples > 1: the image as read (colour the samples' average, depth and stencil sample 0's)
  SampleTiles sample_tiles;  // samples > 1: deferred clears and what of `resolved` is out of date

  /// Allocates width x height pixels of `samples` samples each (colour 0, depth 1, stencil 0). Returns false,
  /// leaving a 0 x 0 framebuffer, if the memory cannot be had.
  bool Allocate(int w, int h);
  /// The buffers as they are: no deferred clear stored, nothing marked.
  RenderTarget Samples(bool srgb_enabled);
  std::size_t Index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
  /// Values from one row to the next in the buffers drawing writes, for a row of w pixels: w samples, rounded up
  /// to an odd number of 16 (an odd number of 64-byte lines for 4-byte values), so that a tile's rows fall in
  /// different cache sets (rows a multiple of 4 KiB apart would all compete for the same few).
  int RowPitch(int w) const;
  /// The buffers as a render target; `srgb_enabled`: FRAMEBUFFER_SRGB (an sRGB colour buffer then converts).
  /// Multisampled, the samples hold every deferred clear (stored now), and the whole resolved image counts as out
  /// of date, since the caller may write them.
  RenderTarget Target(bool srgb_enabled = false);
  /// The target the tile renderer draws into: Target without storing the deferred clears, carrying sample_tiles
  /// (multisampled only; else Target).
  RenderTarget FrameTarget(bool srgb_enabled = false);
  /// The single-sampled image reads take: Target itself when samples is 1, else `resolved`, its stale tiles of
  /// `buffers` (kColorBit, ...) brought up to date first.
  RenderTarget ReadTarget(bool srgb_enabled = false, unsigned buffers = kAllBuffers);
  /// FrameTarget(srgb_enabled), kept from call to call while the buffers stay the same: what a draw reads, without
  /// building the target again for each draw.
  const RenderTarget& KeptFrameTarget(bool srgb_enabled);

 private:
  // What a kept target was made from: the buffers' storage and the sample tiles', size and format.
  struct TargetKey {
    const void* buffers[4] = {};
    int width = -1, height = -1, samples = 0;
    TexelLayout layout = TexelLayout::kNone;
    bool srgb = false, depth16 = false;
    bool operator==(const TargetKey&) const = default;
  };
  struct KeptTarget {
    RenderTarget target;
    TargetKey key;
  };
  KeptTarget kept_[2];  // by srgb_enabled
};

/// Averages the samples of pixel (x, y) of a multisampled colour buffer (as Load reads them).
glm::vec4 LoadResolved(const ColorBuffer& cb, int samples, int x, int y);

/// One BlitFramebuffer, checked: rectangles (x0, y0, x1, y1) of the source and the destination (either may be
/// reversed, which mirrors the image), the destination pixels that may be written, and which buffers go.
struct BlitRegion {
  int src[4] = {0, 0, 0, 0};
  int dst[4] = {0, 0, 0, 0};
  Rect clip;  // the draw buffers' area cut to the scissor box
  bool color = false, depth = false, stencil = false;
  bool linear = false;  // colour only
};

/// Copies src's color[0] into each of dst's colour buffers, and depth and stencil, as BlitFramebuffer does
/// (OpenGL 4.6, section 18.3.1). A multisampled source is resolved (colour averaged, depth and stencil of sample 0;
/// the caller has checked that the rectangles are the same size), a multisampled destination takes the value in
/// every sample (or, from a source of as many samples, sample by sample): each destination pixel whose centre lies in the destination rectangle takes the
/// source at the corresponding point (scaled and mirrored by the two rectangles): with NEAREST the pixel holding
/// that point, with LINEAR (colour only) the bilinear mix of the four nearest pixel centres, clamped to the read
/// buffer's edge. A destination pixel whose point lies outside the read buffer is not written (the blit is
/// clipped), nor is one outside r.clip. Write masks do not apply. Where source and destination are one buffer the
/// rectangles must not overlap (the caller refuses such a blit).
void Blit(const RenderTarget& src, const RenderTarget& dst, const BlitRegion& r);

/// OpenGL's float-to-normalized-fixed conversion for 8 bits: clamp to [0, 1], then round(f * 255).
std::uint8_t FloatToUnorm8(float f);

/// Pixels [x, x + n) of row y of `cb` as Load reads them (LoadResolved's averages when `samples` > 1): four floats a
/// pixel into rgba, a row's decoding chosen once (RGBA8, RGBA32F, RGBA16F and the packed formats in vector form).
void LoadRow(const ColorBuffer& cb, int samples, int x, int n, int y, float* rgba);
/// n pixels of four floats from rgba stored at [x, x + n) of row y of `cb`, as Store stores them through a mask of
/// every channel (RGBA8, RGBA32F and RGBA16F in vector form).
void StoreRow(const ColorBuffer& cb, int x, int n, int y, const float* rgba);

}  // namespace softgl::detail

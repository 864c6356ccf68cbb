// context_framebuffers.cpp — framebuffer objects and renderbuffers (attachments, completeness), the read buffer,
// reading back (ReadPixels and its pack layout, CopyTexImage2D, GetTexImage), and BlitFramebuffer.
#include "context_state.h"
#include "pixel_transfer.h"
#include "texture_compression.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace softgl {

// Section 9.4: why a framebuffer object cannot be drawn to, or FRAMEBUFFER_COMPLETE. Depth and stencil may be
// separate images (OpenGL allows it; llvmpipe answers FRAMEBUFFER_UNSUPPORTED there).
Enum FramebufferStatus(const FramebufferObject& f) {
  bool any = false;
  for (const Attachment& a : f.color) {
    if (!a.Present()) continue;
    any = true;
    const detail::TextureLevel* l = a.Level();
    if (!l->Defined() || detail::IsDepthFormat(l->format) || detail::HasStencil(l->format) || a.layer >= l->depth ||
        l->compressed != 0 ||  // (a compressed format is not colour-renderable, nor an RGB integer one)
        (detail::IsIntegerInternalFormat(l->format) && detail::FormatComponents(l->format) == 3))
      return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (f.depth.Present()) {
    any = true;
    const detail::TextureLevel* l = f.depth.Level();
    if (!l->Defined() || !detail::IsDepthFormat(l->format) || f.depth.layer >= l->depth)
      return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (f.stencil.Present()) {
    any = true;
    const detail::TextureLevel* l = f.stencil.Level();
    if (!l->Defined() || !detail::HasStencil(l->format) || f.stencil.layer >= l->depth)
      return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
  }
  if (!any) return FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  // A layered cube map attachment needs all six faces' images alike.
  for (const Attachment* a : {&f.color[0], &f.color[1], &f.color[2], &f.color[3], &f.color[4], &f.color[5],
                              &f.color[6], &f.color[7], &f.depth, &f.stencil}) {
    if (!a->layered || a->texture->target != TEXTURE_CUBE_MAP) continue;
    const detail::TextureLevel& first = a->texture->levels[0][a->level];
    for (int face = 1; face < 6; ++face) {
      const detail::TextureLevel& l = a->texture->levels[face][a->level];
      if (!l.Defined() || l.width != first.width || l.height != first.height || l.format != first.format)
        return FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    }
  }
  int samples = 0;  // every image must have as many samples (section 9.4.2)
  int layered = -1;  // every attachment layered or none, the layered ones of one texture target (section 9.4.2)
  Enum layer_target = 0;
  for (const Attachment* a : {&f.color[0], &f.color[1], &f.color[2], &f.color[3], &f.color[4], &f.color[5],
                              &f.color[6], &f.color[7], &f.depth, &f.stencil}) {
    if (!a->Present()) continue;
    if (samples != 0 && a->Level()->samples != samples) return FRAMEBUFFER_INCOMPLETE_MULTISAMPLE;
    samples = a->Level()->samples;
    if (layered >= 0 && int(a->layered) != layered) return FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS;
    layered = int(a->layered);
    if (a->layered && a != &f.depth && a != &f.stencil) {
      if (layer_target != 0 && a->texture->target != layer_target) return FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS;
      layer_target = a->texture->target;
    }
  }
  for (Enum b : f.draw_buffers)
    if (b != NONE && !f.color[b - COLOR_ATTACHMENT0].Present()) return FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
  return FRAMEBUFFER_COMPLETE;
}

// The buffers of a complete framebuffer object, drawn through its draw buffers; its size is the intersection of
// its attachments'.
int FramebufferLayers(const FramebufferObject& f) {
  int layers = 1;
  for (const Attachment& a : f.color) layers = std::max(layers, a.Layers());
  return std::max({layers, f.depth.Layers(), f.stencil.Layers()});
}

detail::RenderTarget FramebufferTarget(const FramebufferObject& f, bool srgb, int layer) {
  bool layered = f.depth.layered || f.stencil.layered;
  for (const Attachment& a : f.color) layered = layered || a.layered;
  if (layered) {  // the one layer's images, as attachments of their own
    FramebufferObject one = f;
    for (Attachment& a : one.color) a = a.AtLayer(layer);
    one.depth = f.depth.AtLayer(layer);
    one.stencil = f.stencil.AtLayer(layer);
    return FramebufferTarget(one, srgb, 0);
  }
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
  for (const Attachment& a : f.color)
    if (a.Present()) t.samples = a.Level()->samples;
  for (const Attachment* a : {&f.depth, &f.stencil})
    if (a->Present()) t.samples = a->Level()->samples;
  for (int i = 0; i < kMaxColorOutputs; ++i) {
    if (f.draw_buffers[i] == NONE) continue;
    const Attachment& a = f.color[f.draw_buffers[i] - COLOR_ATTACHMENT0];
    if (!a.Present()) continue;
    detail::ColorBuffer& cb = t.color[i];
    cb.data = const_cast<std::uint8_t*>(a.Level()->data.data()) + a.PlaneOffset() * std::size_t(a.Level()->bytes);
    cb.layout = a.Level()->layout;
    cb.rgb_only = detail::NoStoredAlpha(a.Level()->format);
    cb.srgb = srgb && a.Level()->srgb;
    cb.pitch = a.Level()->width;
    cb.plane = std::size_t(a.Level()->width) * std::size_t(a.Level()->height);
  }
  if (f.depth.Present()) {
    std::uint8_t* data = const_cast<std::uint8_t*>(f.depth.Level()->data.data());
    if (f.depth.Level()->layout == detail::TexelLayout::kUnorm16x1)  // DEPTH_COMPONENT16
      t.depth16 = reinterpret_cast<std::uint16_t*>(data) + f.depth.PlaneOffset();
    else
      t.depth = reinterpret_cast<float*>(data) + f.depth.PlaneOffset();
    t.depth_pitch = f.depth.Level()->width;
    t.depth_plane = std::size_t(f.depth.Level()->width) * std::size_t(f.depth.Level()->height);
  }
  if (f.stencil.Present()) {
    t.stencil = const_cast<std::uint8_t*>(f.stencil.Level()->stencil.data()) + f.stencil.PlaneOffset();
    t.stencil_pitch = f.stencil.Level()->width;
    t.stencil_plane = std::size_t(f.stencil.Level()->width) * std::size_t(f.stencil.Level()->height);
  }
  return t;
}

// ---- Reading back --------------------------------------------------------------------------------------------

namespace {

// What ReadPixels and friends read: the context's framebuffer, or the framebuffer object bound for reading (its
// read buffer as color[0], depth and stencil; nothing when it is incomplete). color[0] is absent when the read
// buffer is NONE or names an empty attachment. With `srgb` an sRGB read buffer decodes (BlitFramebuffer while
// FRAMEBUFFER_SRGB is enabled); ReadPixels and the copies return the stored values. A multisampled context
// framebuffer reads as its resolved image (brought up to date once the recorded commands are rendered), unless
// `samples` asks for the samples themselves (BlitFramebuffer); a multisampled framebuffer object reads as its
// samples. `buffers` (detail::kColorBit, ...): the buffers the caller reads, the only ones a resolve brings up to
// date.
detail::RenderTarget ReadTarget(ContextState& s, bool srgb = false, bool samples = false,
                               unsigned buffers = detail::kAllBuffers) {
  if (!s.read_fbo) {
    detail::RenderTarget t =
        s.fb.samples > 1 && s.frame.Empty() && s.pending.Empty() && !samples ? s.fb.ReadTarget(srgb, buffers) : s.fb.Target(srgb);
    if (s.default_read_buffer == NONE) t.color[0] = detail::ColorBuffer{};
    return t;
  }
  if (FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return {};
  FramebufferObject reading = *s.read_fbo;  // reads the read buffer whatever the draw buffers say
  reading.draw_buffers[0] = reading.read_buffer;
  for (int i = 1; i < kMaxColorOutputs; ++i) reading.draw_buffers[i] = NONE;
  return FramebufferTarget(reading, srgb);
}
// Whether `t`, read from the context's own framebuffer, is empty (a 0 x N or N x 0 context) where a buffer of the
// kind asked for would be: that framebuffer's buffers exist, as OpenGL's default framebuffer's do, with no pixels
// in them to read (colour: unless ReadBuffer(NONE)).
bool EmptyDefaultRead(const ContextState& s, const detail::RenderTarget& t, bool colour) {
  return !s.read_fbo && (t.width == 0 || t.height == 0) && (!colour || s.default_read_buffer != NONE);
}
// The sample count of the (complete) framebuffer object bound for reading; 1 when none is bound.
int ReadFboSamples(ContextState& s) {
  if (!s.read_fbo) return 1;
  return ReadTarget(s).samples;
}

}  // namespace

Image Context::ReadPixels() const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_, false, false, detail::kColorBit);
  Image image;
  if (!t.color[0].Present() || t.width <= 0 || t.height <= 0) return image;
  image.width = t.width;
  image.height = t.height;
  image.rgba.resize(std::size_t(t.width) * std::size_t(t.height) * 4);
  // Row by row, top row first: an RGBA8 buffer's bytes as they are (b / 255 converts back to b), any other the
  // row's floats (LoadRow) stored as RGBA8 (StoreRow: FloatToUnorm8 a channel).
  const detail::ColorBuffer& cb = t.color[0];
  detail::ColorBuffer out;
  out.data = image.rgba.data();
  out.layout = detail::TexelLayout::kUnorm8x4;
  out.pitch = t.width;
  const bool bytes = t.samples == 1 && cb.Rgba8() && cb.step == 1;
  std::vector<float> row(bytes ? 0 : std::size_t(t.width) * 4);
  for (int y = 0; y < t.height; ++y) {
    if (bytes) {
      std::memcpy(out.At(0, t.height - 1 - y), cb.At(0, y), std::size_t(t.width) * 4);
    } else {
      detail::LoadRow(cb, t.samples, 0, t.width, y, row.data());
      detail::StoreRow(out, 0, t.width, t.height - 1 - y, row.data());
    }
  }
  return image;
}

void Context::ReadPixel(int x, int y, std::uint8_t rgba[4]) const {
  if (!NotNull(*state_, __func__, rgba, "rgba")) return;
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_, false, false, detail::kColorBit);
  std::memset(rgba, 0, 4);
  if (!t.color[0].Present() || x < 0 || y < 0 || x >= t.width || y >= t.height) return;
  const glm::vec4 c = detail::LoadResolved(t.color[0], t.samples, x, y);
  for (int k = 0; k < 4; ++k) rgba[k] = detail::FloatToUnorm8(c[k]);
}

namespace {

// OpenGL's pack layout (section 4.3.2): rows of PACK_ROW_LENGTH (or width) pixels, each row aligned to
// PACK_ALIGNMENT when a component is smaller than the alignment, starting PACK_SKIP_ROWS rows and PACK_SKIP_PIXELS
// pixels in; for the images of a 3D or array texture (`layered`), images of PACK_IMAGE_HEIGHT (or height) rows,
// starting PACK_SKIP_IMAGES images in. With PACK_SWAP_BYTES each component's bytes are reversed (Swap).
struct PackLayout {
  std::uint8_t* out;
  std::size_t stride, image, pixel, element;
  bool swap = false;
  std::uint8_t* At(int i, int j, int k = 0) const {
    return out + std::size_t(k) * image + std::size_t(j) * stride + std::size_t(i) * pixel;
  }
  void Swap(std::uint8_t* p) const {
    if (!swap || element == 1) return;
    for (std::size_t e = 0; e < pixel; e += element) std::reverse(p + e, p + e + element);
  }
};
PackLayout Pack(const ContextState& s, int width, int height, bool layered, Enum format, Enum type, void* pixels) {
  const detail::ClientLayout& c = s.pack;
  PackLayout p;
  p.element = detail::TransferElementBytes(type);
  p.pixel = detail::TransferPixelBytes(format, type);
  p.stride = std::size_t(c.row_length > 0 ? c.row_length : width) * p.pixel;
  const std::size_t align = std::size_t(c.alignment);
  if (p.element < align) p.stride = (p.stride + align - 1) / align * align;
  p.image = p.stride * std::size_t(c.image_height > 0 ? c.image_height : height);
  p.out = static_cast<std::uint8_t*>(pixels) + (layered ? std::size_t(c.skip_images) * p.image : 0) +
          std::size_t(c.skip_rows) * p.stride + std::size_t(c.skip_pixels) * p.pixel;
  p.swap = c.swap_bytes;
  return p;
}

// ReadPixels' colour: columns [x0, x1) of rows [y0, y1) of `cb` (single-sampled) into `pack`, buffer pixel (x0, y0)
// at client pixel (i0, j0), a row at a time. UNSIGNED_BYTE from an 8-bit buffer takes the stored bytes (b / 255
// converts back to b; a channel the buffer lacks reads 0, alpha 255), a whole row at once for RGBA from RGBA8;
// RGBA as FLOAT the row's floats (LoadRow) written where they go; any other pair the row's floats converted by
// PackColorRow. A fixed-point buffer's values are in [0, 1]; a float buffer's are clamped only when converted to a
// normalized type.
// `clamp`: ClampColor's clamping to [0, 1] (NaN to 0), before the conversion to `type`.
void ReadColorRows(const detail::ColorBuffer& cb, Enum format, Enum type, const PackLayout& pack, int i0, int j0,
                   int x0, int x1, int y0, int y1, bool clamp) {
  const int n = x1 - x0;
  int ch[4];
  const int channels = detail::FormatChannels(format, ch);
  const bool bytes = type == UNSIGNED_BYTE && detail::IsUnorm8(cb.layout) && !cb.srgb;
  const int stored = cb.Bytes() - (cb.rgb_only ? 1 : 0);  // the channels the buffer stores, red first
  const bool whole = bytes && channels == 4 && ch[0] == 0 && ch[1] == 1 && ch[2] == 2 && ch[3] == 3 &&
                     stored == 4 && cb.step == 1;
  const bool floats = type == FLOAT && channels == 4 && ch[0] == 0 && ch[1] == 1 && ch[2] == 2 && ch[3] == 3 &&
                      reinterpret_cast<std::uintptr_t>(pack.At(i0, j0)) % alignof(float) == 0 && pack.stride % 4 == 0;
  if (detail::IsIntegerLayout(cb.layout)) {  // integers, clamped to the type's range (PackInteger)
    for (int y = y0; y < y1; ++y) {
      std::uint8_t* out = pack.At(i0, j0 + (y - y0));
      for (int x = x0; x < x1; ++x, out += pack.pixel) {
        detail::PackIntegerTexel(cb.layout, cb.At(x, y), format, type, out);
        pack.Swap(out);
      }
    }
    return;
  }
  std::vector<float> row(bytes || floats ? 0 : std::size_t(n) * 4);
  for (int y = y0; y < y1; ++y) {
    std::uint8_t* out = pack.At(i0, j0 + (y - y0));
    if (whole) {
      std::memcpy(out, cb.At(x0, y), std::size_t(n) * 4);
    } else if (bytes) {
      const std::uint8_t* in = cb.At(x0, y);
      const std::size_t in_step = std::size_t(cb.step) * std::size_t(cb.Bytes());
      for (int i = 0; i < n; ++i, in += in_step, out += pack.pixel)
        for (int k = 0; k < channels; ++k) out[k] = ch[k] < stored ? in[ch[k]] : (ch[k] == 3 ? 255 : 0);
    } else if (floats) {  // RGBA floats decoded straight into the client's row, then PackPlain's NaNs made quiet
      float* f = reinterpret_cast<float*>(out);
      detail::LoadRow(cb, 1, x0, n, y, f);
      for (int i = 0; i < 4 * n; ++i)
        if (clamp) f[i] = f[i] > 0.0f ? std::min(f[i], 1.0f) : 0.0f;
        else if (f[i] != f[i]) f[i] = float(double(f[i]));
      for (int i = 0; i < n; ++i, out += pack.pixel) pack.Swap(out);
    } else {
      detail::LoadRow(cb, 1, x0, n, y, row.data());
      if (clamp)
        for (float& v : row) v = v > 0.0f ? std::min(v, 1.0f) : 0.0f;
      detail::PackColorRow(format, type, row.data(), n, out, pack.pixel);
      for (int i = 0; i < n; ++i, out += pack.pixel) pack.Swap(out);
    }
  }
}

}  // namespace

void Context::ClampColor(Enum target, Enum clamp) {
  auto& s = *state_;
  if (target != CLAMP_READ_COLOR) return s.SetError(INVALID_ENUM, __func__, "target must be CLAMP_READ_COLOR");
  if (clamp != 0 && clamp != 1 && clamp != FIXED_ONLY) return s.SetError(INVALID_ENUM, __func__, "clamp must be true, false or FIXED_ONLY");
  s.clamp_read_color = clamp;
}

void Context::ReadPixels(int x, int y, int width, int height, Enum format, Enum type, void* pixels) const {
  auto& s = *state_;
  const char* why = "";
  const Enum check = detail::CheckPixelTransfer(format, type, detail::TransferCall::kReadPixels, why);
  if (check == INVALID_ENUM) return s.SetError(check, __func__, why);
  if (width < 0 || height < 0) return s.SetError(INVALID_VALUE, __func__, "width or height is negative");
  if (check != NO_ERROR) return s.SetError(check, __func__, why);
  if (s.read_fbo && FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return s.SetError(INVALID_FRAMEBUFFER_OPERATION, __func__, "the read framebuffer is not complete");
  if (ReadFboSamples(s) > 1) return s.SetError(INVALID_OPERATION, __func__, "the read framebuffer object is multisampled: resolve it with BlitFramebuffer first");
  s.Sync(__func__);
  const bool depth = format == DEPTH_COMPONENT || format == DEPTH_STENCIL;
  const bool stencil = format == STENCIL_INDEX || format == DEPTH_STENCIL;
  const unsigned buffers = depth || stencil ? (depth ? detail::kDepthBit : 0u) | (stencil ? detail::kStencilBit : 0u)
                                            : detail::kColorBit;
  const detail::RenderTarget t = ReadTarget(s, false, false, buffers);
  if (!EmptyDefaultRead(s, t, !depth && !stencil) &&
      ((depth && !t.HasDepth()) || (stencil && !t.stencil) || (!depth && !stencil && !t.color[0].Present())))
    return s.SetError(INVALID_OPERATION, __func__, "the read framebuffer has no buffer of that kind");
  if (!depth && !stencil && t.color[0].Present() &&
      detail::IsIntegerLayout(t.color[0].layout) != detail::IsIntegerTransfer(format))
    return s.SetError(INVALID_OPERATION, __func__, "an integer read buffer is read with an integer format (RED_INTEGER ...) only, and the reverse");
  if (width == 0 || height == 0 || !NotNull(s, __func__, pixels, "pixels")) return;
  const PackLayout pack = Pack(s, width, height, false, format, type, pixels);
  // Only pixels inside the read buffer are written (the others are undefined in OpenGL: left as they are).
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = int(std::min<std::int64_t>(std::int64_t(x) + width, t.width));
  const int y1 = int(std::min<std::int64_t>(std::int64_t(y) + height, t.height));
  if (!depth && !stencil) {
    // (x0 - x and y0 - y, the first pixel's place in the client rows, only for a rectangle that reaches inside:
    // x or y may be INT_MIN.)
    if (x0 < x1 && y0 < y1) ReadColorRows(t.color[0], format, type, pack, x0 - x, y0 - y, x0, x1, y0, y1, s.clamp_read_color == 1);
    return;
  }
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px) {
      std::uint8_t* dst = pack.At(px - x, py - y);
      if (depth && stencil) {
        detail::PackDepthStencil(type, t.DepthAt(px, py), std::uint8_t(t.Stencil(px, py)), dst);
      } else if (depth) {
        detail::PackColor(DEPTH_COMPONENT, type, glm::vec4(t.DepthAt(px, py)), dst);
      } else {
        detail::PackStencil(type, std::uint32_t(t.Stencil(px, py)), dst);
      }
      pack.Swap(dst);
    }
}

void Context::GetTexImage(Enum target, int level, Enum format, Enum type, void* pixels) const {
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_2D_ARRAY && target != TEXTURE_3D && target != TEXTURE_1D &&
      target != TEXTURE_1D_ARRAY)
    return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D, TEXTURE_2D, a TEXTURE_CUBE_MAP_* face, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D");
  const char* why = "";
  const Enum check = detail::CheckPixelTransfer(format, type, detail::TransferCall::kGetTexImage, why);
  if (check == INVALID_ENUM) return s.SetError(check, __func__, why);
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  if (check != NO_ERROR) return s.SetError(check, __func__, why);
  int face = 0;
  const detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  const detail::TextureLevel& lv = tex->levels[face][level];
  if (!lv.Defined()) return;  // an undefined level has no texels to return
  if (!NotNull(s, __func__, pixels, "pixels")) return;
  const bool depth = format == DEPTH_COMPONENT || format == DEPTH_STENCIL, stencil = format == DEPTH_STENCIL;
  if (detail::IsDepthFormat(lv.format) != depth) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_COMPONENT for a colour texture, or the reverse");
  if (stencil && lv.stencil.empty()) return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL for a texture without stencil");
  const bool integer = detail::IsIntegerInternalFormat(lv.format);
  if (integer != detail::IsIntegerTransfer(format)) return s.SetError(INVALID_OPERATION, __func__, "an integer texture is read with an integer format (RED_INTEGER ...) only, and the reverse");
  s.Sync(__func__);  // a texture being rendered into holds its texels once the recorded draws are rendered
  const bool layered = target == TEXTURE_2D_ARRAY || target == TEXTURE_3D;
  // (A 1D array goes out as one image whose rows are its layers, each of its planes being one row.)
  const PackLayout pack = Pack(s, lv.width, target == TEXTURE_1D_ARRAY ? lv.depth : lv.height, layered, format, type,
                               pixels);
  // A 2D array's layers or a 3D texture's slices one image after another (PACK_IMAGE_HEIGHT rows apart); the
  // level stores image k's row j as its row k * height + j.
  for (int j = 0; j < lv.height * lv.depth; ++j)
    for (int i = 0; i < lv.width; ++i) {
      std::uint8_t* dst = target == TEXTURE_1D_ARRAY ? pack.At(i, j, 0) : pack.At(i, j % lv.height, j / lv.height);
      if (integer) {
        detail::PackIntegerTexel(lv.layout, lv.At(i, j), format, type, dst);
        pack.Swap(dst);
        continue;
      }
      const glm::vec4 c = lv.Texel(i, j);
      if (stencil)
        detail::PackDepthStencil(type, c.r, lv.stencil[std::size_t(j) * std::size_t(lv.width) + std::size_t(i)], dst);
      else
        detail::PackColor(depth ? DEPTH_COMPONENT : format, type, c, dst);
      pack.Swap(dst);
    }
}

namespace {

// The checks CopyTexImage2D and CopyTexSubImage2D share about the read framebuffer: complete, and holding the kind
// of buffer the texture needs. False with the error set otherwise.
bool CheckCopySource(ContextState& s, const char* what, Enum internal_format) {
  const bool depth = detail::IsDepthFormat(internal_format);
  if (s.read_fbo && FramebufferStatus(*s.read_fbo) != FRAMEBUFFER_COMPLETE) return s.SetError(INVALID_FRAMEBUFFER_OPERATION, what, "the read framebuffer is not complete"), false;
  if (ReadFboSamples(s) > 1) return s.SetError(INVALID_OPERATION, what, "the read framebuffer object is multisampled: resolve it with BlitFramebuffer first"), false;
  const detail::RenderTarget t = ReadTarget(s);
  if (!EmptyDefaultRead(s, t, !depth) && (depth ? !t.HasDepth() : !t.color[0].Present()))
    return s.SetError(INVALID_OPERATION, what, "the read framebuffer has no buffer of the texture's kind"), false;
  if (!depth && t.color[0].Present() &&
      detail::IsIntegerLayout(t.color[0].layout) != detail::IsIntegerInternalFormat(internal_format))
    return s.SetError(INVALID_OPERATION, what, "an integer texture copies from an integer read buffer only, and the reverse"), false;
  return true;
}

// Copies the read framebuffer's rectangle (x, y, w, h) into level `lv` at (xo, yo); checked already. Pixels outside
// the framebuffer (undefined in OpenGL) copy as zero.
void CopyToLevel(ContextState& s, const char* what, detail::TextureLevel& lv, int xo, int yo, int x, int y, int w, int h) {
  s.Sync(what);
  const detail::RenderTarget t = ReadTarget(s);
  const bool depth = detail::IsDepthFormat(lv.format);
  if (detail::IsIntegerLayout(lv.layout)) {  // integers copied as they are, clamped to the level's channels
    std::vector<std::int64_t> values(std::size_t(w) * std::size_t(h) * 4, 0);  // read first: lv may be the source
    const detail::ColorBuffer& cb = t.color[0];
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const std::int64_t px = std::int64_t(x) + i, py = std::int64_t(y) + j;
        if (px < 0 || py < 0 || px >= t.width || py >= t.height) continue;
        const glm::ivec4 v = detail::IntegerTexel(cb.layout, cb.At(int(px), int(py)));
        for (int c = 0; c < 4; ++c)
          values[(std::size_t(j) * std::size_t(w) + std::size_t(i)) * 4 + std::size_t(c)] = detail::IntegerValue(cb.layout, v[c]);
      }
    const bool rgb_only = detail::FormatComponents(lv.format) == 3;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        detail::StoreIntegerTexel(lv.layout, lv.At(xo + i, yo + j),
                                  &values[(std::size_t(j) * std::size_t(w) + std::size_t(i)) * 4], rgb_only);
    return;
  }
  std::vector<float> rect(std::size_t(w) * std::size_t(h) * (depth ? 1 : 4), 0.0f);  // read first: the
                                                                                       // source may be lv itself
  // The columns inside the framebuffer, [i0, i1) of each row (in 64 bits: x and y may be anything up to INT_MAX,
  // and x + i past it is outside); colour a row at a time as Load reads it (LoadRow).
  const int i0 = int(std::clamp<std::int64_t>(-std::int64_t(x), 0, w));
  const int i1 = int(std::clamp<std::int64_t>(std::int64_t(t.width) - x, i0, w));
  for (int j = 0; j < h && i0 < i1; ++j) {
    const std::int64_t py64 = std::int64_t(y) + j;
    if (py64 < 0 || py64 >= t.height) continue;
    const int py = int(py64);
    float* row = rect.data() + std::size_t(j) * std::size_t(w) * (depth ? 1 : 4);
    if (depth) {
      for (int i = i0; i < i1; ++i) row[i] = t.DepthAt(x + i, py);
    } else {
      detail::LoadRow(t.color[0], 1, x + i0, i1 - i0, py, row + std::size_t(i0) * 4);
    }
  }
  detail::UploadPixels(lv, xo, yo, w, h, depth ? DEPTH_COMPONENT : RGBA, FLOAT, detail::ClientLayout{}, rect.data());
  if (lv.stencil.empty() || !t.stencil) return;  // a depth-stencil texture takes the stencil indices too
  std::vector<std::uint8_t> indices(std::size_t(w) * std::size_t(h), 0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::int64_t px = std::int64_t(x) + i, py = std::int64_t(y) + j;
      if (px >= 0 && py >= 0 && px < t.width && py < t.height)
        indices[std::size_t(j) * std::size_t(w) + std::size_t(i)] = t.Stencil(int(px), int(py));
    }
  for (int j = 0; j < h; ++j)
    std::memcpy(lv.stencil.data() + std::size_t(yo + j) * std::size_t(lv.width) + std::size_t(xo),
                indices.data() + std::size_t(j) * std::size_t(w), std::size_t(w));
}

}  // namespace

void Context::CopyTexSubImage2D(Enum target, int level, int xoffset, int yoffset, int x, int y, int width,
                                int height) {
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_1D_ARRAY) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D, a TEXTURE_CUBE_MAP_* face or TEXTURE_1D_ARRAY");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex || !tex->levels[face][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[face][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (xoffset < 0 || yoffset < 0 || width < 0 || height < 0 || std::int64_t(xoffset) + width > lv.width ||
      std::int64_t(yoffset) + height > std::int64_t(lv.height) * lv.depth)  // (a 1D array's rows are its layers)
    return s.SetError(INVALID_VALUE, __func__, "the rectangle is outside the level");
  if (!CheckCopySource(s, __func__, lv.format)) return;
  try {
    CopyToLevel(s, __func__, lv, xoffset, yoffset, x, y, width, height);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::CopyTexSubImage3D(Enum target, int level, int xoffset, int yoffset, int zoffset, int x, int y, int width,
                                int height) {
  auto& s = *state_;
  if (target != TEXTURE_2D_ARRAY && target != TEXTURE_3D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D_ARRAY or TEXTURE_3D");
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex || !tex->levels[0][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[0][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (xoffset < 0 || yoffset < 0 || zoffset < 0 || width < 0 || height < 0 ||
      std::int64_t(xoffset) + width > lv.width || std::int64_t(yoffset) + height > lv.height || zoffset >= lv.depth)
    return s.SetError(INVALID_VALUE, __func__, "the rectangle is outside the level, or the layer beyond its depth");
  if (!CheckCopySource(s, __func__, lv.format)) return;
  try {  // layer (slice) zoffset's rows follow the layers below it
    CopyToLevel(s, __func__, lv, xoffset, zoffset * lv.height + yoffset, x, y, width, height);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::CopyTexImage2D(Enum target, int level, Enum internal_format, int x, int y, int width, int height,
                             int border) {
  auto& s = *state_;
  internal_format = detail::UncompressedForGeneric(internal_format);
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "softgl does not compress: define a compressed level from its blocks with CompressedTexImage*");
  const bool rows_of_layers = target == TEXTURE_1D_ARRAY;
  if (!IsTexImageTarget(target) && !rows_of_layers) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D, a TEXTURE_CUBE_MAP_* face or TEXTURE_1D_ARRAY");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || height < 0 || width > kMaxTextureSize ||
      height > (rows_of_layers ? kMaxArrayTextureLayers : kMaxTextureSize) || border != 0 ||
      detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (CubeFaceIndex(target) >= 0 && width != height) return s.SetError(INVALID_VALUE, __func__, "cube map faces must be square");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  if (!CheckCopySource(s, __func__, internal_format)) return;
  try {
    s.Sync(__func__);  // the old level may be what recorded draws sample or render into
    detail::TextureLevel next;
    if (rows_of_layers) next.Allocate(internal_format, width, 1, 1, height);  // each row a layer
    else next.Allocate(internal_format, width, height);
    CopyToLevel(s, __func__, next, 0, 0, x, y, width, height);
    if (rows_of_layers && height == 0) next = detail::TextureLevel{};
    tex->levels[face][level] = std::move(next);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::CopyTexImage1D(Enum target, int level, Enum internal_format, int x, int y, int width, int border) {
  auto& s = *state_;
  internal_format = detail::UncompressedForGeneric(internal_format);
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "softgl does not compress: define a compressed level from its blocks with CompressedTexImage*");
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || width > kMaxTextureSize || border != 0 ||
      detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  if (!CheckCopySource(s, __func__, internal_format)) return;
  try {
    s.Sync(__func__);
    detail::TextureLevel next;
    next.Allocate(internal_format, width, 1);
    CopyToLevel(s, __func__, next, 0, 0, x, y, width, 1);
    tex->levels[0][level] = std::move(next);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::CopyTexSubImage1D(Enum target, int level, int xoffset, int x, int y, int width) {
  auto& s = *state_;
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex || !tex->levels[0][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[0][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (xoffset < 0 || width < 0 || std::int64_t(xoffset) + width > lv.width) return s.SetError(INVALID_VALUE, __func__, "the span is outside the level");
  if (!CheckCopySource(s, __func__, lv.format)) return;
  try {
    CopyToLevel(s, __func__, lv, xoffset, 0, x, y, width, 1);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

float Context::ReadDepth(int x, int y) const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_, false, false, detail::kDepthBit);
  if (!t.HasDepth() || x < 0 || y < 0 || x >= t.width || y >= t.height) return 0.0f;
  return t.DepthAt(x, y);
}

std::uint8_t Context::ReadStencil(int x, int y) const {
  state_->Sync(__func__);
  const detail::RenderTarget t = ReadTarget(*state_, false, false, detail::kStencilBit);
  if (!t.stencil || x < 0 || y < 0 || x >= t.width || y >= t.height) return 0;
  return t.Stencil(x, y);
}


// ---- Framebuffer objects -------------------------------------------------------------------------------------

std::uint32_t Context::GenFramebuffer() {
  return NewId(state_->framebuffers, state_->next_framebuffer, [] { return std::make_unique<FramebufferObject>(); });
}

void Context::GenFramebuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenFramebuffer(); });
}

void Context::DeleteFramebuffers(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteFramebuffer(id); });
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

namespace {
// The attachment points FramebufferTexture2D and FramebufferTextureLayer set (see TargetAttachment), after
// detaching them when `texture` is 0; 0 when there is nothing more to do.
int TextureSlots(ContextState& s, const char* what, Enum target, Enum attachment, std::uint32_t texture,
                 Attachment* slots[2]) {
  const int n = TargetAttachment(s, what, target, attachment, slots);
  if (n == 0 || texture != 0) return n;
  for (int k = 0; k < n; ++k) *slots[k] = Attachment{};
  return 0;
}

// The start of every FramebufferTexture call: renders what was recorded (attachments are about to change), then
// TextureSlots.
int AttachmentSlots(ContextState& s, const char* what, Enum target, Enum attachment, std::uint32_t texture,
                    Attachment* slots[2]) {
  s.Sync(what);
  return TextureSlots(s, what, target, attachment, texture, slots);
}

// The texture named `texture`, or null with `missing` recorded when there is none (or, `bound`, when it has never
// been bound).
const std::shared_ptr<detail::TextureObject>* AttachedTexture(ContextState& s, const char* what, std::uint32_t texture,
                                                              Enum missing, bool bound = false) {
  auto it = s.textures.find(texture);
  if (it == s.textures.end() || (bound && it->second->target == 0)) return s.SetError(missing, what, "not a texture id made by GenTexture (or it was deleted, or never bound)"), nullptr;
  return &it->second;
}

// AttachmentSlots, then AttachedTexture: null when there is nothing more to do (n points found, 0 if none).
const std::shared_ptr<detail::TextureObject>* SlotsAndTexture(ContextState& s, const char* what, Enum target,
                                                              Enum attachment, std::uint32_t texture,
                                                              Attachment* slots[2], int& n, Enum missing,
                                                              bool bound = false) {
  n = AttachmentSlots(s, what, target, attachment, texture, slots);
  return n == 0 ? nullptr : AttachedTexture(s, what, texture, missing, bound);
}

// Attaches `texture`'s level at the n points of `slots` (what TextureSlots found).
void AttachTexture(Attachment* const* slots, int n, const std::shared_ptr<detail::TextureObject>& texture, int level,
                   int face, int layer, bool layered) {
  for (int k = 0; k < n; ++k) {
    *slots[k] = Attachment{};
    slots[k]->texture = texture;
    slots[k]->level = level;
    slots[k]->face = face;
    slots[k]->layer = layer;
    slots[k]->layered = layered;
  }
}
}  // namespace

void Context::FramebufferTexture2D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  const int n = AttachmentSlots(s, __func__, target, attachment, texture, slots);
  if (n == 0) return;
  if (!IsTexImageTarget(textarget) && textarget != TEXTURE_2D_MULTISAMPLE) return s.SetError(INVALID_ENUM, __func__, "textarget must be TEXTURE_2D, a TEXTURE_CUBE_MAP_* face or TEXTURE_2D_MULTISAMPLE");
  const auto* it = AttachedTexture(s, __func__, texture, INVALID_OPERATION);
  if (!it) return;
  const Enum kind = CubeFaceIndex(textarget) >= 0 ? TEXTURE_CUBE_MAP : textarget;
  if ((*it)->target != kind) return s.SetError(INVALID_OPERATION, __func__, "textarget does not match the texture (2D, cube map or 2D multisample)");
  if (level < 0 || level >= detail::kMaxLevels || (kind == TEXTURE_2D_MULTISAMPLE && level != 0)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level (a multisample texture has level 0 alone)");
  AttachTexture(slots, n, (*it), level, kind == TEXTURE_CUBE_MAP ? CubeFaceIndex(textarget) : 0, 0, false);
}

void Context::FramebufferTextureLayer(Enum target, Enum attachment, std::uint32_t texture, int level, int layer) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  int n = 0;
  const auto* it = SlotsAndTexture(s, __func__, target, attachment, texture, slots, n, INVALID_OPERATION);
  if (!it) return;
  const Enum kind = (*it)->target;
  if (!(*it)->Layered()) return s.SetError(INVALID_OPERATION, __func__, "the texture is not a TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY, TEXTURE_2D_MULTISAMPLE_ARRAY or TEXTURE_3D");
  if (level < 0 || level >= detail::kMaxLevels || (kind == TEXTURE_2D_MULTISAMPLE_ARRAY && level != 0))
    return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level (a multisample array has level 0 alone)");
  if (layer < 0 || layer >= (kind == TEXTURE_3D ? kMax3DTextureSize : kMaxArrayTextureLayers))
    return s.SetError(INVALID_VALUE, __func__, "layer is negative or beyond the most layers a texture has");
  AttachTexture(slots, n, (*it), level, 0, layer, false);
}

void Context::FramebufferTexture(Enum target, Enum attachment, std::uint32_t texture, int level) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  int n = 0;
  // (OpenGL 4.6, section 9.2.8: INVALID_VALUE here, where the other FramebufferTexture calls say INVALID_OPERATION.)
  const auto* it = SlotsAndTexture(s, __func__, target, attachment, texture, slots, n, INVALID_VALUE, true);
  if (!it) return;
  const Enum kind = (*it)->target;
  if (kind == TEXTURE_BUFFER) return s.SetError(INVALID_OPERATION, __func__, "a buffer texture cannot be attached");
  if (level < 0 || level >= LevelCount(kind) || (detail::IsMultisampleTarget(kind) && level != 0)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the texture's largest mipmap level");
  AttachTexture(slots, n, (*it), level, 0, 0, kind == TEXTURE_CUBE_MAP || (*it)->Layered());
}

void Context::FramebufferTexture1D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  const int n = AttachmentSlots(s, __func__, target, attachment, texture, slots);
  if (n == 0) return;
  if (textarget != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "textarget must be TEXTURE_1D");
  const auto* it = AttachedTexture(s, __func__, texture, INVALID_OPERATION);
  if (!it) return;
  if ((*it)->target != TEXTURE_1D) return s.SetError(INVALID_OPERATION, __func__, "the texture is not a TEXTURE_1D");
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  AttachTexture(slots, n, (*it), level, 0, 0, false);
}

void Context::FramebufferTexture3D(Enum target, Enum attachment, Enum textarget, std::uint32_t texture, int level,
                                   int zoffset) {
  auto& s = *state_;
  Attachment* slots[2] = {nullptr, nullptr};
  int n = 0;
  const auto* it = SlotsAndTexture(s, __func__, target, attachment, texture, slots, n, INVALID_OPERATION);
  if (!it) return;
  if (textarget != TEXTURE_3D || (*it)->target != TEXTURE_3D) return s.SetError(INVALID_OPERATION, __func__, "textarget and the texture must be TEXTURE_3D");
  if (level < 0 || level >= LevelCount(TEXTURE_3D)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  if (zoffset < 0 || zoffset >= kMax3DTextureSize) return s.SetError(INVALID_VALUE, __func__, "zoffset is negative or beyond the most slices a texture has");
  AttachTexture(slots, n, (*it), level, 0, zoffset, false);
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
  if (n == 2 && (a.texture != slots[1]->texture || a.renderbuffer != slots[1]->renderbuffer || a.level != slots[1]->level || a.face != slots[1]->face ||
                 a.layer != slots[1]->layer || a.layered != slots[1]->layered))
    return s.SetError(INVALID_OPERATION, __func__, "DEPTH_STENCIL_ATTACHMENT asked while depth and stencil hold different images");
  int v = 0;
  switch (pname) {
    case FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: v = int(a.texture ? TEXTURE : a.renderbuffer ? RENDERBUFFER : NONE); break;
    case FRAMEBUFFER_ATTACHMENT_OBJECT_NAME:
      v = int(a.texture ? IdOf(s.textures, a.texture.get()) : IdOf(s.renderbuffers, a.renderbuffer.get()));
      break;
    case FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL:
    case FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
    case FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER:
      if (!a.texture) return s.SetError(a.Present() ? INVALID_ENUM : INVALID_OPERATION, __func__, "no texture is attached there");
      v = pname == FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL  ? a.level
          : pname == FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER ? a.layer
          : a.texture->target == TEXTURE_CUBE_MAP        ? int(TEXTURE_CUBE_MAP_POSITIVE_X) + a.face
                                                         : 0;
      break;
    case FRAMEBUFFER_ATTACHMENT_LAYERED:
      if (!a.texture) return s.SetError(a.Present() ? INVALID_ENUM : INVALID_OPERATION, __func__, "no texture is attached there");
      v = a.layered ? 1 : 0;
      break;
    case FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING:
      if (!a.Present()) return s.SetError(INVALID_OPERATION, __func__, "nothing is attached there");
      v = int(a.Level()->srgb ? SRGB : LINEAR);
      break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname must be FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, _OBJECT_NAME, _TEXTURE_LEVEL, _TEXTURE_CUBE_MAP_FACE, _TEXTURE_LAYER, _LAYERED or _COLOR_ENCODING");
  }
  if (NotNull(s, __func__, params, "params")) *params = v;
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
    // Accepted by OpenGL 3.3 but not required at their sizes (section 4.4.2.1): the nearest softgl stores.
    case DEPTH_COMPONENT32: return DEPTH_COMPONENT24;
    case STENCIL_INDEX1: case STENCIL_INDEX4: case STENCIL_INDEX16: return STENCIL_INDEX8;
    case RGBA8: case RGB8: case RG8: case R8: case SRGB8_ALPHA8: case SRGB8: case RGBA32F: case RG32F: case R32F:
    case RGBA16F: case RG16F: case R16F: case R11F_G11F_B10F: case RGB565: case RGBA4: case RGB5_A1: case RGB10_A2: case DEPTH_COMPONENT16:
    case RGBA16: case RG16: case R16:
    case DEPTH_COMPONENT24: case DEPTH_COMPONENT32F: case DEPTH24_STENCIL8: case DEPTH32F_STENCIL8:
    case STENCIL_INDEX8: return f;
    case R8I: case R8UI: case R16I: case R16UI: case R32I: case R32UI: case RG8I: case RG8UI: case RG16I: case RG16UI:
    case RG32I: case RG32UI: case RGBA8I: case RGBA8UI: case RGBA16I: case RGBA16UI: case RGBA32I: case RGBA32UI:
    case RGB10_A2UI: return f;
    default: return 0;
  }
}


Renderbuffer* BoundRenderbuffer(ContextState& s, const char* what, Enum target) {
  if (target != RENDERBUFFER) return s.SetError(INVALID_ENUM, what, "target must be RENDERBUFFER"), nullptr;
  if (!s.renderbuffer) return s.SetError(INVALID_OPERATION, what, "no renderbuffer is bound"), nullptr;
  return s.renderbuffer.get();
}

}  // namespace

FormatBits BitsOf(Enum f) {
  switch (f) {
    case RGBA8:
    case SRGB8_ALPHA8: return {8, 8, 8, 8, 0, 0};
    case RGB8:
    case SRGB8: return {8, 8, 8, 0, 0, 0};
    case RG8: return {8, 8, 0, 0, 0, 0};
    case R8: return {8, 0, 0, 0, 0, 0};
    case RGBA32F: return {32, 32, 32, 32, 0, 0};
    case RG32F: return {32, 32, 0, 0, 0, 0};
    case R32F: return {32, 0, 0, 0, 0, 0};
    case RGBA16F: return {16, 16, 16, 16, 0, 0};
    case RG16F: return {16, 16, 0, 0, 0, 0};
    case R16F: return {16, 0, 0, 0, 0, 0};
    case R11F_G11F_B10F: return {11, 11, 10, 0, 0, 0};
    case RGB565: return {5, 6, 5, 0, 0, 0};
    case RGBA4: return {4, 4, 4, 4, 0, 0};
    case RGB5_A1: return {5, 5, 5, 1, 0, 0};
    case RGB10_A2: return {10, 10, 10, 2, 0, 0};
    case RGBA16: return {16, 16, 16, 16, 0, 0};
    case RG16: return {16, 16, 0, 0, 0, 0};
    case R16: return {16, 0, 0, 0, 0, 0};
    case DEPTH_COMPONENT16: return {0, 0, 0, 0, 16, 0};
    case DEPTH_COMPONENT:
    case DEPTH_COMPONENT24: return {0, 0, 0, 0, 24, 0};
    case DEPTH_COMPONENT32F: return {0, 0, 0, 0, 32, 0};
    case DEPTH24_STENCIL8: return {0, 0, 0, 0, 24, 8};
    case DEPTH32F_STENCIL8: return {0, 0, 0, 0, 32, 8};
    case STENCIL_INDEX8: return {0, 0, 0, 0, 0, 8};
    case RGB10_A2UI: return {10, 10, 10, 2, 0, 0};
    default: {
      if (!detail::IsIntegerInternalFormat(f)) return {};
      const int n = detail::FormatComponents(f), bits = 8 * detail::IntegerLayoutOf(detail::LayoutOf(f)).bytes;
      return {bits, n > 1 ? bits : 0, n > 2 ? bits : 0, n > 3 ? bits : 0, 0, 0};
    }
  }
}

std::uint32_t Context::GenRenderbuffer() {
  return NewId(state_->renderbuffers, state_->next_renderbuffer, [] { return std::make_shared<Renderbuffer>(); });
}

void Context::GenRenderbuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenRenderbuffer(); });
}

void Context::DeleteRenderbuffers(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteRenderbuffer(id); });
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

namespace {

// RenderbufferStorage(Multisample): `samples` as given (0 for RenderbufferStorage).
void Storage(ContextState& s, const char* what, Enum target, int samples, Enum internal_format, int width, int height) {
  Renderbuffer* rb = BoundRenderbuffer(s, what, target);
  if (!rb) return;
  const Enum sized = SizedRenderbufferFormat(internal_format);
  if (sized == 0) return s.SetError(INVALID_ENUM, what, "internal_format is not a colour, depth or stencil format drawing can render to");
  if (width < 0 || height < 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize)
    return s.SetError(INVALID_VALUE, what, "width or height is negative or above MAX_RENDERBUFFER_SIZE");
  // OpenGL 3.3 (section 4.4.2.1) makes samples above MAX_SAMPLES INVALID_VALUE; OpenGL 4.2 and later (and Mesa)
  // INVALID_OPERATION. softgl is OpenGL 3.3.
  if (samples < 0 || samples > detail::kMaxSamples) return s.SetError(INVALID_VALUE, what, "samples is negative or above MAX_SAMPLES");
  const bool integer = detail::IsIntegerInternalFormat(sized);
  if (integer && samples > kMaxIntegerSamples) return s.SetError(INVALID_OPERATION, what, "an integer format is not multisampled: samples is above MAX_INTEGER_SAMPLES (1)");
  s.Sync(what);  // recorded draws may render into the old image
  detail::TextureLevel next;
  try {
    next.Allocate(sized, width, height, integer ? 1 : detail::SupportedSamples(samples));
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, what, "out of memory");
  }
  rb->image = std::move(next);
  rb->internal_format = internal_format;
  rb->samples = samples > 0 ? rb->image.samples : 0;
}

}  // namespace

namespace {

// TexImage2DMultisample (`layers` 0) and TexImage3DMultisample: the image of the multisample texture bound to
// `target`, `layers` layers of width x height (a 2D one: none).
void MultisampleImage(ContextState& s, const char* what, Enum target, Enum want, int samples, Enum internal_format,
                      int width, int height, int layers) {
  if (target != want)
    return s.SetError(INVALID_ENUM, what, want == TEXTURE_2D_MULTISAMPLE ? "target must be TEXTURE_2D_MULTISAMPLE" : "target must be TEXTURE_2D_MULTISAMPLE_ARRAY");
  const Enum sized = SizedRenderbufferFormat(internal_format);
  if (sized == 0) return s.SetError(INVALID_ENUM, what, "internal_format is not a colour, depth or stencil format drawing can render to");
  if (samples < 1 || width < 0 || height < 0 || width > kMaxTextureSize || height > kMaxTextureSize)
    return s.SetError(INVALID_VALUE, what, "samples below 1, or width or height negative or above MAX_TEXTURE_SIZE");
  if (layers < 0 || layers > kMaxArrayTextureLayers) return s.SetError(INVALID_VALUE, what, "depth is negative or above MAX_ARRAY_TEXTURE_LAYERS");
  if (samples > detail::kMaxSamples) return s.SetError(INVALID_OPERATION, what, "samples is above MAX_COLOR_TEXTURE_SAMPLES");
  const bool integer = detail::IsIntegerInternalFormat(sized);
  if (integer && samples > kMaxIntegerSamples) return s.SetError(INVALID_OPERATION, what, "an integer format is not multisampled: samples is above MAX_INTEGER_SAMPLES (1)");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, what, "no texture is bound to that target of the active unit");
  s.Sync(what);  // recorded draws may render into or sample the old image
  const bool empty = want == TEXTURE_2D_MULTISAMPLE_ARRAY && layers == 0;  // (no layers: an empty image)
  detail::TextureLevel next;
  try {
    next.Allocate(sized, width, empty ? 0 : height, integer ? 1 : detail::SupportedSamples(samples), std::max(layers, 1));
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, what, "out of memory");
  }
  tex->levels[0][0] = std::move(next);
}

}  // namespace

void Context::TexImage2DMultisample(Enum target, int samples, Enum internal_format, int width, int height,
                                    bool fixed_sample_locations) {
  (void)fixed_sample_locations;  // the standard positions, whatever is asked
  MultisampleImage(*state_, __func__, target, TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, 0);
}

void Context::TexImage3DMultisample(Enum target, int samples, Enum internal_format, int width, int height, int depth,
                                    bool fixed_sample_locations) {
  (void)fixed_sample_locations;  // the standard positions, whatever is asked
  MultisampleImage(*state_, __func__, target, TEXTURE_2D_MULTISAMPLE_ARRAY, samples, internal_format, width, height,
                   depth);
}

void Context::RenderbufferStorage(Enum target, Enum internal_format, int width, int height) {
  Storage(*state_, __func__, target, 0, internal_format, width, height);
}

void Context::RenderbufferStorageMultisample(Enum target, int samples, Enum internal_format, int width, int height) {
  Storage(*state_, __func__, target, samples, internal_format, width, height);
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
    case RENDERBUFFER_SAMPLES: v = rb->samples; break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname is not a renderbuffer parameter");
  }
  if (NotNull(s, __func__, params, "params")) *params = v;
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
// DEPTH24_STENCIL8 (its depth is stored as float, as DEPTH_COMPONENT24's is), or with 16-bit depth
// (Options::depth_format) as DEPTH_COMPONENT16 with 8 stencil bits.
FormatBits DepthStencilBits(const FramebufferObject* f, bool default_depth16) {
  if (!f) {
    FormatBits b = BitsOf(DEPTH24_STENCIL8);
    if (default_depth16) b.depth = 16;
    return b;
  }
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
  const detail::RenderTarget src = ReadTarget(s, s.framebuffer_srgb, true);
  detail::RenderTarget dst;
  s.DrawTarget(dst);
  // Multisampled buffers are copied sample by sample or resolved, never scaled (OpenGL 4.6, section 18.3.1).
  if (src.samples > 1 && dst.samples > 1 && src.samples != dst.samples)
    return s.SetError(INVALID_OPERATION, __func__, "the read and draw framebuffers have different sample counts");
  if ((src.samples > 1 || dst.samples > 1) &&
      (std::abs(std::int64_t(src_x1) - src_x0) != std::abs(std::int64_t(dst_x1) - dst_x0) ||
       std::abs(std::int64_t(src_y1) - src_y0) != std::abs(std::int64_t(dst_y1) - dst_y0)))
    return s.SetError(INVALID_OPERATION, __func__, "a blit from or to a multisampled framebuffer cannot scale: the rectangles must be the same size");
  // A buffer missing from either framebuffer is skipped without an error (OpenGL 4.6, section 18.3.1).
  const bool depth = (mask & DEPTH_BUFFER_BIT) != 0 && src.HasDepth() && dst.HasDepth();
  const bool stencil = (mask & STENCIL_BUFFER_BIT) != 0 && src.stencil && dst.stencil;
  if (depth || stencil) {
    const FormatBits a = DepthStencilBits(s.read_fbo, s.fb.depth16), b = DepthStencilBits(s.draw_fbo, s.fb.depth16);
    const bool depth_differs = a.depth != b.depth || a.r != b.r;
    if ((depth && depth_differs) || (stencil && (a.stencil != b.stencil || (a.depth && b.depth && depth_differs))))
      return s.SetError(INVALID_OPERATION, __func__, "the read and draw framebuffers' depth or stencil formats differ");
  }
  const bool color = (mask & COLOR_BUFFER_BIT) != 0 && src.color[0].Present();
  if (color) {  // integers go to integer buffers only, unfiltered (OpenGL 3.3, section 4.3.2)
    const bool integer = detail::IsIntegerLayout(src.color[0].layout);
    for (const detail::ColorBuffer& cb : dst.color)
      if (cb.Present() && detail::IsIntegerLayout(cb.layout) != integer)
        return s.SetError(INVALID_OPERATION, __func__, "integer colour is blitted between integer buffers only");
    if (integer && filter == LINEAR) return s.SetError(INVALID_OPERATION, __func__, "integer colour is blitted with NEAREST only");
  }
  bool same = (depth && src.depth == dst.depth && src.depth16 == dst.depth16) || (stencil && src.stencil == dst.stencil);
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
    // Bands of destination rows on the context's threads: each writes only its own rows. Within one buffer only
    // with NEAREST, which reads inside the source rectangle alone (refused above where it overlaps the
    // destination); LINEAR's taps may reach a row past it, which another band may be writing.
    const int rows = std::max(0, std::min(r.clip.y1, dst.height) - std::max(r.clip.y0, 0));
    const int bands = rows >= 256 && !(same && r.linear) ? std::min(s.pool->Threads(), rows / 128) : 1;
    if (bands <= 1) {
      detail::Blit(src, dst, r);
    } else {
      const int y0 = std::max(r.clip.y0, 0);
      s.pool->Run(bands, [&](int band, int) {
        detail::BlitRegion part = r;
        part.clip.y0 = y0 + int(std::int64_t(rows) * band / bands);
        part.clip.y1 = y0 + int(std::int64_t(rows) * (band + 1) / bands);
        detail::Blit(src, dst, part);
      });
    }
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
  if (n > 0 && !NotNull(s, __func__, bufs, "bufs")) return;
  Enum next[kMaxColorOutputs] = {};  // NONE
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

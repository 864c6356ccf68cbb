// context_textures.cpp — texture objects: binding, TexImage2D and TexSubImage2D, image files, mipmaps, sampling
// parameters and pixel unpacking.
#include "context_state.h"
#include "image_io.h"
#include "pixel_transfer.h"
#include "texture_compression.h"

#include <climits>
#include <cmath>
#include <cstring>
#include <limits>

namespace softgl {

// ---- Textures ------------------------------------------------------------------------------------------------

std::uint32_t Context::GenTexture() {
  return NewId(state_->textures, state_->next_texture, [] { return std::make_shared<detail::TextureObject>(); });
}

void Context::GenTextures(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenTexture(); });
}

void Context::DeleteTextures(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteTexture(id); });
}

void Context::DeleteTexture(std::uint32_t texture) {
  state_->Sync(__func__);
  auto& s = *state_;
  auto it = s.textures.find(texture);
  if (it == s.textures.end()) return;
  const detail::TextureObject* dead = it->second.get();
  for (TextureUnit& u : s.units)
    for (auto& bound : u.bound)
      if (bound.get() == dead) bound.reset();
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
  const int kind = detail::TextureKind(target);
  if (kind < 0) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_2D_MULTISAMPLE, TEXTURE_2D_MULTISAMPLE_ARRAY or TEXTURE_BUFFER");
  std::shared_ptr<detail::TextureObject> object;
  if (texture != 0) {
    auto it = s.textures.find(texture);
    if (it == s.textures.end()) return s.SetError(INVALID_OPERATION, __func__, "not a texture id made by GenTexture (or it was deleted)");
    if (it->second->target != 0 && it->second->target != target) return s.SetError(INVALID_OPERATION, __func__, "the texture was first bound to the other target");
    it->second->target = target;
    object = it->second;
  }
  TextureUnit& u = s.units[s.active_unit];
  u.bound[kind] = std::move(object);
  s.units_used = std::max(s.units_used, s.active_unit + 1);
}

namespace {

// The client data of TexImage* and TexSubImage*: OpenGL 3.3's formats and types (pixel_transfer.h), without
// STENCIL_INDEX. False with the error recorded otherwise.
bool CheckTransfer(ContextState& s, const char* what, Enum format, Enum type) {
  const char* why = "";
  const Enum error = detail::CheckPixelTransfer(format, type, detail::TransferCall::kUnpack, why);
  if (error != NO_ERROR) return s.SetError(error, what, why), false;
  return true;
}

bool IsDepthTransfer(Enum format) { return format == DEPTH_COMPONENT || format == DEPTH_STENCIL; }

// Whether client data of `format` suits a level of `internal_format`: depth data for the depth formats and integer
// data (RED_INTEGER ...) for the integer ones, and neither for the others (OpenGL 3.3, section 3.8.3). False with
// the error recorded otherwise.
bool DataSuits(ContextState& s, const char* what, Enum internal_format, Enum format) {
  if (detail::IsDepthFormat(internal_format) != IsDepthTransfer(format))
    return s.SetError(INVALID_OPERATION, what, "depth data for a colour format, or the reverse"), false;
  if (detail::IsIntegerInternalFormat(internal_format) != detail::IsIntegerTransfer(format))
    return s.SetError(INVALID_OPERATION, what, "integer data (RED_INTEGER ...) for a format that is not integer, or the reverse"), false;
  return true;
}

}  // namespace

void Context::TexImage2D(Enum target, int level, Enum internal_format, int width, int height, int border,
                         Enum format, Enum type, const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  internal_format = detail::UncompressedForGeneric(internal_format);
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "softgl does not compress: define a compressed level from its blocks with CompressedTexImage*");
  const bool rows_of_layers = target == TEXTURE_1D_ARRAY;  // each row of the image a layer
  if (!IsTexImageTarget(target) && !rows_of_layers) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D, a TEXTURE_CUBE_MAP_* face or TEXTURE_1D_ARRAY");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || height < 0 || width > kMaxTextureSize ||
      height > (rows_of_layers ? kMaxArrayTextureLayers : kMaxTextureSize) || border != 0 ||
      detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (!DataSuits(s, __func__, internal_format, format)) return;
  if (CubeFaceIndex(target) >= 0 && width != height) return s.SetError(INVALID_VALUE, __func__, "cube map faces must be square");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  detail::TextureLevel next;
  try {
    // (A 1D array's layers are planes one texel high: its texel (i, layer) is row `layer`, as the image's is.)
    if (rows_of_layers) next.Allocate(internal_format, width, 1, 1, height);
    else next.Allocate(internal_format, width, height);
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
  detail::UploadPixels(next, 0, 0, width, height, format, type, s.unpack, pixels);
  if (rows_of_layers && height == 0) next = detail::TextureLevel{};  // (no layers: the level is not defined)
  tex->levels[face][level] = std::move(next);
}

void Context::TexImage1D(Enum target, int level, Enum internal_format, int width, int border, Enum format, Enum type,
                         const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  internal_format = detail::UncompressedForGeneric(internal_format);
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "softgl does not compress: define a compressed level from its blocks with CompressedTexImage*");
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  if (level < 0 || level >= detail::kMaxLevels || width < 0 || width > kMaxTextureSize || border != 0 ||
      detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (!DataSuits(s, __func__, internal_format, format)) return;
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  detail::TextureLevel next;
  try {
    next.Allocate(internal_format, width, 1);
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
  detail::UploadPixels(next, 0, 0, width, 1, format, type, s.unpack, pixels);
  tex->levels[0][level] = std::move(next);
}

void Context::TexSubImage1D(Enum target, int level, int x, int width, Enum format, Enum type, const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (level < 0 || level >= detail::kMaxLevels) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex || !tex->levels[0][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[0][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (!DataSuits(s, __func__, lv.format, format)) return;
  if (x < 0 || width < 0 || std::int64_t(x) + width > lv.width) return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (width == 0 || !NotNull(s, __func__, pixels, "pixels")) return;
  detail::UploadPixels(lv, x, 0, width, 1, format, type, s.unpack, pixels);
}

void Context::TexSubImage2D(Enum target, int level, int x, int y, int width, int height, Enum format, Enum type,
                            const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_1D_ARRAY) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D, a TEXTURE_CUBE_MAP_* face or TEXTURE_1D_ARRAY");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex || !tex->levels[face][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[face][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (!DataSuits(s, __func__, lv.format, format)) return;
  // (A 1D array's rows are its layers.)
  if (x < 0 || y < 0 || width < 0 || height < 0 || std::int64_t(x) + width > lv.width ||
      std::int64_t(y) + height > std::int64_t(lv.height) * lv.depth)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (width == 0 || height == 0 || !NotNull(s, __func__, pixels, "pixels")) return;
  detail::UploadPixels(lv, x, y, width, height, format, type, s.unpack, pixels);
}

void Context::TexImage3D(Enum target, int level, Enum internal_format, int width, int height, int depth, int border,
                         Enum format, Enum type, const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  internal_format = detail::UncompressedForGeneric(internal_format);
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "softgl does not compress: define a compressed level from its blocks with CompressedTexImage*");
  if (target != TEXTURE_2D_ARRAY && target != TEXTURE_3D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D_ARRAY or TEXTURE_3D");
  const bool volume = target == TEXTURE_3D;
  const int max_size = volume ? kMax3DTextureSize : kMaxTextureSize;
  const int max_depth = volume ? kMax3DTextureSize : kMaxArrayTextureLayers;
  if (level < 0 || level >= LevelCount(target) || width < 0 || height < 0 || depth < 0 || width > max_size ||
      height > max_size || depth > max_depth || border != 0 || detail::FormatComponents(internal_format) == 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (!DataSuits(s, __func__, internal_format, format)) return;
  if (volume && detail::IsDepthFormat(internal_format)) return s.SetError(INVALID_OPERATION, __func__, "a 3D texture cannot have a depth format");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  detail::TextureLevel next;
  try {
    next.Allocate(internal_format, width, height, 1, depth);
  } catch (const std::bad_alloc&) {
    return s.SetError(OUT_OF_MEMORY, __func__, "out of memory (or more than a 16384 x 16384 RGBA32F level's bytes)");
  }
  if (width > 0 && height > 0 && depth > 0)
    detail::UploadImages(next, 0, 0, 0, width, height, depth, format, type, s.unpack, pixels);
  if (depth == 0) next = detail::TextureLevel{};  // (no texels: the level is not defined)
  tex->levels[0][level] = std::move(next);
}

void Context::TexSubImage3D(Enum target, int level, int x, int y, int z, int width, int height, int depth,
                            Enum format, Enum type, const void* pixels) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_2D_ARRAY && target != TEXTURE_3D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D_ARRAY or TEXTURE_3D");
  if (!CheckTransfer(s, __func__, format, type)) return;
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex || !tex->levels[0][level].Defined()) return s.SetError(INVALID_OPERATION, __func__, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[0][level];
  if (lv.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the level is compressed: replace its blocks with CompressedTexSubImage*");
  if (!DataSuits(s, __func__, lv.format, format)) return;
  if (x < 0 || y < 0 || z < 0 || width < 0 || height < 0 || depth < 0 || std::int64_t(x) + width > lv.width ||
      std::int64_t(y) + height > lv.height || std::int64_t(z) + depth > lv.depth)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
  if (width == 0 || height == 0 || depth == 0 || !NotNull(s, __func__, pixels, "pixels")) return;
  detail::UploadImages(lv, x, y, z, width, height, depth, format, type, s.unpack, pixels);
}

// ---- Compressed textures (texture_compression.h) ---------------------------------------------------------

namespace {

// The checks every CompressedTexImage* call makes on its format, in OpenGL's order after the target's: the format
// (INVALID_ENUM unless one softgl decodes), then where the format may go (INVALID_ENUM too: S3TC and RGTC are
// 2D-block formats, for TEXTURE_2D, cube faces and TEXTURE_2D_ARRAY only; BPTC goes into TEXTURE_3D as well, a
// slice's blocks after another's). Null with the error set.
const detail::CompressedFormat* CompressedFormatFor(ContextState& s, const char* what, Enum target, Enum format) {
  const detail::CompressedFormat* f = detail::CompressedFormatOf(format);
  if (!f) return s.SetError(INVALID_ENUM, what, "internalformat is not a compressed format softgl decodes (the S3TC, RGTC and BPTC formats)"), nullptr;
  const bool volume = target == TEXTURE_3D && f->kind == detail::CompressedFormat::Kind::kBc7;
  if (!IsTexImageTarget(target) && target != TEXTURE_2D_ARRAY && !volume)
    return s.SetError(INVALID_ENUM, what, "S3TC and RGTC images are two-dimensional: TEXTURE_2D, a cube face or TEXTURE_2D_ARRAY only (BPTC: TEXTURE_3D too)"), nullptr;
  return f;
}

// Defines level `level` of the texture bound to target (face `face` found by the caller) from blocks: the part
// of CompressedTexImage2D and 3D after their target checks.
void DefineCompressed(ContextState& s, const char* what, Enum target, int level, Enum internal_format, int w, int h,
                      int d, int border, int image_size, const void* data) {
  const detail::CompressedFormat* f = CompressedFormatFor(s, what, target, internal_format);
  if (!f) return;
  const int max_depth = target == TEXTURE_2D_ARRAY ? kMaxArrayTextureLayers : target == TEXTURE_3D ? kMax3DTextureSize : 1;
  const int max_size = target == TEXTURE_3D ? kMax3DTextureSize : kMaxTextureSize;
  if (level < 0 || level >= LevelCount(target) || w < 0 || h < 0 || d < 0 || w > max_size || h > max_size ||
      d > max_depth || border != 0)
    return s.SetError(INVALID_VALUE, what, "a numeric argument is out of range");
  if (CubeFaceIndex(target) >= 0 && w != h) return s.SetError(INVALID_VALUE, what, "cube map faces must be square");
  const std::uint64_t bytes = detail::CompressedImageBytes(*f, w, h, d);
  if (image_size < 0 || std::uint64_t(image_size) != bytes) return s.SetError(INVALID_VALUE, what, "imageSize is not the bytes of the image's blocks (ceil(width / 4) * ceil(height / 4) * depth blocks of 8 or 16 bytes)");
  if (bytes > 0 && !NotNull(s, what, data, "data")) return;
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, what, "no texture is bound to that target of the active unit");
  detail::TextureLevel next;
  next.compressed = f->format;  // (an empty image too is a compressed level: OpenGL keeps its format)
  if (w > 0 && h > 0 && d > 0) {
    try {
      next.Allocate(f->decoded, w, h, 1, d);
      next.blocks.resize(std::size_t(bytes));
    } catch (const std::bad_alloc&) {
      return s.SetError(OUT_OF_MEMORY, what, "out of memory");
    }
    detail::DecodeRegion(*f, static_cast<const std::uint8_t*>(data), 0, 0, 0, w, h, d, next);
  }
  tex->levels[face][level] = std::move(next);
}

// Replaces blocks of a compressed level: the part of CompressedTexSubImage2D and 3D after their target checks.
void ReplaceCompressed(ContextState& s, const char* what, Enum target, int level, int x, int y, int z, int w, int h,
                       int d, Enum format, int image_size, const void* data) {
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, what, "level is negative or beyond the largest mipmap level");
  int face = 0;
  detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex || !tex->levels[face][level].Defined()) return s.SetError(INVALID_OPERATION, what, "no texture bound, or that level is not defined");
  detail::TextureLevel& lv = tex->levels[face][level];
  if (lv.compressed == 0 || lv.compressed != format) return s.SetError(INVALID_OPERATION, what, "format is not the level's compressed format (or the level is not compressed)");
  const detail::CompressedFormat* f = detail::CompressedFormatOf(format);
  if (x < 0 || y < 0 || z < 0 || w < 0 || h < 0 || d < 0 || std::int64_t(x) + w > lv.width ||
      std::int64_t(y) + h > lv.height || std::int64_t(z) + d > lv.depth)
    return s.SetError(INVALID_VALUE, what, "the region is outside the level");
  if (x % 4 != 0 || y % 4 != 0 || (w % 4 != 0 && x + w != lv.width) || (h % 4 != 0 && y + h != lv.height))
    return s.SetError(INVALID_OPERATION, what, "the region is not whole 4 x 4 blocks (offsets multiples of 4; sizes too, unless they reach the level's edge)");
  const std::uint64_t bytes = detail::CompressedImageBytes(*f, w, h, d);
  if (image_size < 0 || std::uint64_t(image_size) != bytes) return s.SetError(INVALID_VALUE, what, "imageSize is not the bytes of the region's blocks");
  if (bytes == 0 || !NotNull(s, what, data, "data")) return;
  detail::DecodeRegion(*f, static_cast<const std::uint8_t*>(data), x, y, z, w, h, d, lv);
}

}  // namespace

void Context::CompressedTexImage1D(Enum target, int level, Enum internal_format, int width, int border, int image_size,
                                   const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  (void)level, (void)width, (void)border, (void)image_size, (void)data;
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  if (detail::CompressedFormatOf(internal_format)) return s.SetError(INVALID_ENUM, __func__, "OpenGL 3.3 has no one-dimensional compressed format: S3TC, RGTC and BPTC are 2D-block formats");
  s.SetError(INVALID_ENUM, __func__, "internalformat is not a compressed format");
}

void Context::CompressedTexImage2D(Enum target, int level, Enum internal_format, int width, int height, int border,
                                   int image_size, const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_1D_ARRAY) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  DefineCompressed(s, __func__, target, level, internal_format, width, height, 1, border, image_size, data);
}

void Context::CompressedTexImage3D(Enum target, int level, Enum internal_format, int width, int height, int depth,
                                   int border, int image_size, const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_2D_ARRAY && target != TEXTURE_3D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D_ARRAY or (BPTC) TEXTURE_3D");
  DefineCompressed(s, __func__, target, level, internal_format, width, height, depth, border, image_size, data);
}

void Context::CompressedTexSubImage1D(Enum target, int level, int x, int width, Enum format, int image_size,
                                      const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  (void)level, (void)x, (void)width, (void)format, (void)image_size, (void)data;
  if (target != TEXTURE_1D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D");
  s.SetError(INVALID_ENUM, __func__, "OpenGL 3.3 has no one-dimensional compressed format: S3TC, RGTC and BPTC are 2D-block formats");
}

void Context::CompressedTexSubImage2D(Enum target, int level, int x, int y, int width, int height, Enum format,
                                      int image_size, const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_1D_ARRAY) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  ReplaceCompressed(s, __func__, target, level, x, y, 0, width, height, 1, format, image_size, data);
}

void Context::CompressedTexSubImage3D(Enum target, int level, int x, int y, int z, int width, int height, int depth,
                                      Enum format, int image_size, const void* data) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (target != TEXTURE_2D_ARRAY && target != TEXTURE_3D) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_2D_ARRAY");
  ReplaceCompressed(s, __func__, target, level, x, y, z, width, height, depth, format, image_size, data);
}

void Context::GetCompressedTexImage(Enum target, int level, void* data) const {
  auto& s = *state_;
  if (!IsTexImageTarget(target) && target != TEXTURE_2D_ARRAY && target != TEXTURE_3D && target != TEXTURE_1D &&
      target != TEXTURE_1D_ARRAY)
    return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D, TEXTURE_2D, a TEXTURE_CUBE_MAP_* face, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D");
  if (level < 0 || level >= LevelCount(target)) return s.SetError(INVALID_VALUE, __func__, "level is negative or beyond the largest mipmap level");
  int face = 0;
  const detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  const detail::TextureLevel& lv = tex->levels[face][level];
  if (lv.compressed == 0) {
    if (!lv.Defined()) return s.SetError(INVALID_VALUE, __func__, "the level is not defined");
    return s.SetError(INVALID_OPERATION, __func__, "the level is not compressed");
  }
  if (lv.blocks.empty() || !NotNull(s, __func__, data, "data")) return;
  std::memcpy(data, lv.blocks.data(), lv.blocks.size());
}

namespace {

// Defines level 0 of the texture bound to target from a decoded image: 1 to 4 channels as R8, RG8, RGB8, RGBA8
// (with `srgb` 3 and 4 channels as SRGB8, SRGB8_ALPHA8), HDR as RGBA32F.
bool TexImageFromLoaded(Context& gl, ContextState& s, Enum target, const detail::LoadedImage& img,
                        const std::string& name, std::string* error, bool srgb) {
  if (img.compressed != 0) {  // a DDS file: every level it holds, as its blocks
    const Enum before = s.error;
    for (std::size_t l = 0; l < img.levels.size() && s.error == before; ++l) {
      const detail::CompressedImageLevel& lv = img.levels[l];
      gl.CompressedTexImage2D(target, int(l), img.compressed, lv.width, lv.height, 0, int(lv.blocks.size()),
                              lv.blocks.data());
    }
    if (s.error != before) {
      if (error) *error = name + ": the texture could not be defined";
      return false;
    }
    s.Bound(target)->params.max_level = int(img.levels.size()) - 1;  // (a chain that stops early stays complete)
    return true;
  }
  if (img.width > kMaxTextureSize || img.height > kMaxTextureSize || img.channels < 1 || img.channels > 4) {
    s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range");
    if (error) *error = name + ": larger than kMaxTextureSize, or an unsupported channel count";
    return false;
  }
  static constexpr Enum kFormats[4] = {RED, RG, RGB, RGBA};
  static constexpr Enum kInternal[2][4] = {{R8, RG8, RGB8, RGBA8}, {R8, RG8, SRGB8, SRGB8_ALPHA8}};
  const Enum format = kFormats[img.channels - 1];
  const Enum internal = img.hdr ? RGBA32F : kInternal[srgb ? 1 : 0][img.channels - 1];
  const detail::ClientLayout saved = s.unpack;  // the image's rows as they are in memory
  s.unpack = detail::ClientLayout{};
  s.unpack.alignment = 1;
  const Enum before = s.error;
  gl.TexImage2D(target, 0, internal, img.width, img.height, 0, format, img.hdr ? FLOAT : UNSIGNED_BYTE,
                img.hdr ? static_cast<const void*>(img.floats.data()) : static_cast<const void*>(img.bytes.data()));
  s.unpack = saved;
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
                         Enum encoding, const char* call, Decode&& decode) {
  auto refuse = [&](Enum code, const char* message) {
    s.SetError(code, call, message);
    if (error) *error = message;
    return false;
  };
  if (!IsTexImageTarget(target)) return refuse(INVALID_ENUM, "target must be TEXTURE_2D or a TEXTURE_CUBE_MAP_* face");
  if (encoding != LINEAR && encoding != SRGB) return refuse(INVALID_ENUM, "encoding must be LINEAR or SRGB");
  if (!s.Bound(target)) return refuse(INVALID_OPERATION, "no texture is bound to that target of the active unit");
  detail::LoadedImage img;
  try {
    if (!decode(img)) return false;
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, call, "out of memory");
    if (error) *error = name + ": out of memory";
    return false;
  }
  return TexImageFromLoaded(gl, s, target, img, name, error, encoding == SRGB);
}

}  // namespace

bool Context::TexImage2DFromFile(Enum target, const std::string& path, bool flip_vertically, std::string* error,
                                 Enum encoding) {
  return TexImageFromDecoded(*this, *state_, target, path, error, encoding, __func__, [&](detail::LoadedImage& img) {
    return detail::LoadImageFile(path, flip_vertically, img, error, encoding == SRGB);
  });
}

bool Context::TexImage2DFromMemory(Enum target, const void* data, std::size_t size, bool flip_vertically,
                                   std::string* error, Enum encoding) {
  const std::string name = "image in memory";
  return TexImageFromDecoded(*this, *state_, target, name, error, encoding, __func__, [&](detail::LoadedImage& img) {
    return detail::LoadImageMemory(data, size, name, flip_vertically, img, error, encoding == SRGB);
  });
}

void Context::TexBuffer(Enum target, Enum internal_format, std::uint32_t buffer) {
  auto& s = *state_;
  if (target != TEXTURE_BUFFER) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_BUFFER");
  if (!detail::IsBufferTextureFormat(internal_format))
    return s.SetError(INVALID_ENUM, __func__, "internal_format must be R8, R16, R16F, R32F, RG8, RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F, or an integer R, RG or RGBA format (R8I ... RGBA32UI)");
  std::shared_ptr<Buffer> object;
  if (buffer != 0) {
    auto it = s.buffers.find(buffer);
    if (it == s.buffers.end()) return s.SetError(INVALID_OPERATION, __func__, "buffer is neither 0 nor a buffer id made by GenBuffer (or it was deleted)");
    object = it->second;
  }
  detail::TextureObject* tex = s.Bound(TEXTURE_BUFFER);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to TEXTURE_BUFFER of the active unit");
  s.Sync(__func__);  // recorded draws may sample the texture as it was
  tex->buffer_format = internal_format;
  tex->buffer_id = buffer;
  if (object) object->texture_store = true;
  // (The store, kept alive by its buffer: the aliasing form shares the buffer's ownership.)
  tex->buffer_store = object ? std::shared_ptr<const std::vector<std::uint8_t>>(object, &object->data) : nullptr;
}

void Context::GenerateMipmap(Enum target) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!detail::HasLevelsAndSampling(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D (a multisample or buffer texture has no levels or sampling state)");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  const int base = tex->params.base_level;
  if (base < 0 || base >= detail::kMaxLevels) return s.SetError(INVALID_OPERATION, __func__, "the base level is out of range");
  for (int f = 0; f < tex->Faces(); ++f) {
    const detail::TextureLevel& b = tex->levels[f][base];
    const detail::TextureLevel& b0 = tex->levels[0][base];
    if (!b.Defined() || b.width != b0.width || b.height != b0.height || b.format != b0.format)
      return s.SetError(INVALID_OPERATION, __func__, "not allowed in the current state");
    if (b.compressed != 0) return s.SetError(INVALID_OPERATION, __func__, "the base level is compressed, and softgl does not compress the levels it would make: define each with CompressedTexImage*");
    if (detail::IsIntegerInternalFormat(b.format)) return s.SetError(INVALID_OPERATION, __func__, "an integer texture is not filterable: its levels are not generated");
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

namespace {

// Sets sampling parameter `pname` of `p` (a texture's, or with `levels` false a sampler object's, which has no
// levels) from `values` (four for TEXTURE_BORDER_COLOR); the error set where it is not taken.
void SetSamplerParameter(ContextState& s, const char* what, detail::SamplerParams& p, Enum pname, const float* values,
                         bool levels) {
  if (values == nullptr) return s.SetError(INVALID_VALUE, what, "values is null");
  const float v = values[0];
  const int iv = std::isfinite(v) ? int(std::clamp(v, -2e9f, 2e9f)) : -1;
  switch (pname) {
    case TEXTURE_MIN_FILTER:
      if (!IsMinFilter(iv)) return s.SetError(INVALID_ENUM, what, "not a minification filter");
      p.min_filter = Enum(iv);
      break;
    case TEXTURE_MAG_FILTER:
      if (iv != NEAREST && iv != LINEAR) return s.SetError(INVALID_ENUM, what, "magnification filter must be NEAREST or LINEAR");
      p.mag_filter = Enum(iv);
      break;
    case TEXTURE_WRAP_S:
    case TEXTURE_WRAP_T:
    case TEXTURE_WRAP_R:
      if (!IsWrap(iv)) return s.SetError(INVALID_ENUM, what, "wrap mode must be REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE or CLAMP_TO_BORDER");
      (pname == TEXTURE_WRAP_S ? p.wrap_s : pname == TEXTURE_WRAP_T ? p.wrap_t : p.wrap_r) = Enum(iv);
      break;
    case TEXTURE_BASE_LEVEL:
    case TEXTURE_MAX_LEVEL:
      if (!levels) return s.SetError(INVALID_ENUM, what, "a sampler object has no levels: TEXTURE_BASE_LEVEL and TEXTURE_MAX_LEVEL are the texture's");
      if (iv < 0) return s.SetError(INVALID_VALUE, what, "level is negative");
      (pname == TEXTURE_BASE_LEVEL ? p.base_level : p.max_level) = iv;
      break;
    case TEXTURE_MIN_LOD:
    case TEXTURE_MAX_LOD:
    case TEXTURE_LOD_BIAS:
      if (std::isnan(v)) return s.SetError(INVALID_VALUE, what, "value is NaN");
      (pname == TEXTURE_MIN_LOD ? p.min_lod : pname == TEXTURE_MAX_LOD ? p.max_lod : p.lod_bias) = v;
      break;
    case TEXTURE_MAX_ANISOTROPY:
      if (!(v >= 1.0f)) return s.SetError(INVALID_VALUE, what, "TEXTURE_MAX_ANISOTROPY is below 1 (or NaN)");
      p.max_anisotropy = v;
      break;
    case TEXTURE_COMPARE_MODE:
      if (iv != int(NONE) && iv != int(COMPARE_REF_TO_TEXTURE)) return s.SetError(INVALID_ENUM, what, "compare mode must be NONE or COMPARE_REF_TO_TEXTURE");
      p.compare_mode = Enum(iv);
      break;
    case TEXTURE_COMPARE_FUNC:
      if (iv < int(NEVER) || iv > int(ALWAYS)) return s.SetError(INVALID_ENUM, what, "not a comparison function");
      p.compare_func = Enum(iv);
      break;
    case TEXTURE_BORDER_COLOR:
      p.border = glm::vec4(values[0], values[1], values[2], values[3]);
      p.border_integer = 0;
      break;
    default: return s.SetError(INVALID_ENUM, what, "an enum argument is not one this call accepts");
  }
}

// TEXTURE_BORDER_COLOR's integers of TexParameteriv and SamplerParameteriv, mapped to [-1, 1] as OpenGL maps signed
// normalized values (i / (2^31 - 1)).
void BorderOfIntegers(const int* values, float out[4]) {
  for (int k = 0; k < 4; ++k) out[k] = float(std::max(double(values[k]) / 2147483647.0, -1.0));
}

}  // namespace

void Context::TexParameterfv(Enum target, Enum pname, const float* values) {
  state_->Sync(__func__);
  auto& s = *state_;
  if (!detail::HasLevelsAndSampling(target)) return s.SetError(INVALID_ENUM, __func__, "target must be TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D (a multisample or buffer texture has no levels or sampling state)");
  if (values == nullptr) return s.SetError(INVALID_VALUE, __func__, "values is null");
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, __func__, "no texture is bound to that target of the active unit");
  SetSamplerParameter(s, __func__, tex->params, pname, values, true);
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

void Context::TexParameteriv(Enum target, Enum pname, const int* values) {
  if (values == nullptr) return state_->SetError(INVALID_VALUE, __func__, "values is null");
  if (pname != TEXTURE_BORDER_COLOR) return TexParameteri(target, pname, values[0]);
  float v[4];
  BorderOfIntegers(values, v);
  TexParameterfv(target, pname, v);
}

namespace {

bool SamplerParameterValues(ContextState& s, const char* what, const detail::SamplerParams& p, Enum pname,
                            float out[4], int& n, bool levels);

// GetTexParameteriv's and GetSamplerParameteriv's integers of the values `v`: the border colour maps [-1, 1] onto
// the integers, rounded (OpenGL 4.6, equation 2.4), so that what TexParameteriv set reads back as it was (-1 is
// stored as -1 / (2^31 - 1), which truncation would read as 0); the others round. NaN reads as 0.
void IntegersOfValues(Enum pname, const float* v, int n, int* params) {
  for (int k = 0; k < n; ++k)
    params[k] = std::isnan(v[k]) ? 0 : pname == TEXTURE_BORDER_COLOR ? int(std::lround(std::clamp(double(v[k]), -1.0, 1.0) * 2147483647.0))
                                              : int(std::lround(std::clamp(double(v[k]), -2147483648.0, 2147483647.0)));
}

// The sampling state `pname` of the texture bound to target, as up to four floats; false with the error set.
bool TexParameterValues(ContextState& s, const char* what, Enum target, Enum pname, float out[4], int& n) {
  if (!detail::HasLevelsAndSampling(target)) return s.SetError(INVALID_ENUM, what, "target must be TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D (a multisample or buffer texture has no sampling state)"), false;
  const detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, what, "no texture is bound to that target of the active unit"), false;
  return SamplerParameterValues(s, what, tex->params, pname, out, n, true);
}

// The value of sampling parameter `pname` of `p` (a texture's, or with `levels` false a sampler object's) as up to
// four floats; false with the error set.
bool SamplerParameterValues(ContextState& s, const char* what, const detail::SamplerParams& p, Enum pname,
                            float out[4], int& n, bool levels) {
  n = 1;
  if (!levels && (pname == TEXTURE_BASE_LEVEL || pname == TEXTURE_MAX_LEVEL))
    return s.SetError(INVALID_ENUM, what, "a sampler object has no levels: TEXTURE_BASE_LEVEL and TEXTURE_MAX_LEVEL are the texture's"), false;
  switch (pname) {
    case TEXTURE_MIN_FILTER: out[0] = float(p.min_filter); return true;
    case TEXTURE_MAG_FILTER: out[0] = float(p.mag_filter); return true;
    case TEXTURE_WRAP_S: out[0] = float(p.wrap_s); return true;
    case TEXTURE_WRAP_T: out[0] = float(p.wrap_t); return true;
    case TEXTURE_WRAP_R: out[0] = float(p.wrap_r); return true;
    case TEXTURE_BASE_LEVEL: out[0] = float(p.base_level); return true;
    case TEXTURE_MAX_LEVEL: out[0] = float(p.max_level); return true;
    case TEXTURE_MIN_LOD: out[0] = p.min_lod; return true;
    case TEXTURE_MAX_LOD: out[0] = p.max_lod; return true;
    case TEXTURE_LOD_BIAS: out[0] = p.lod_bias; return true;
    case TEXTURE_MAX_ANISOTROPY: out[0] = p.max_anisotropy; return true;
    case TEXTURE_COMPARE_MODE: out[0] = float(p.compare_mode); return true;
    case TEXTURE_COMPARE_FUNC: out[0] = float(p.compare_func); return true;
    case TEXTURE_BORDER_COLOR:
      n = 4;
      for (int k = 0; k < 4; ++k) out[k] = p.border[k];
      return true;
    default: return s.SetError(INVALID_ENUM, what, "pname is not a texture parameter"), false;
  }
}

// The value `pname` of level `level` of the texture bound to target (a 2D texture, a cube face, a 2D array or a 3D
// texture); false with the
// error set.
bool TexLevelValue(ContextState& s, const char* what, Enum target, int level, Enum pname, int& out) {
  if (!IsTexImageTarget(target) && target != TEXTURE_2D_ARRAY && target != TEXTURE_3D && !detail::IsMultisampleTarget(target) &&
      target != TEXTURE_1D && target != TEXTURE_1D_ARRAY && target != TEXTURE_BUFFER)
    return s.SetError(INVALID_ENUM, what, "target must be TEXTURE_1D, TEXTURE_2D, a TEXTURE_CUBE_MAP_* face, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_2D_MULTISAMPLE, TEXTURE_2D_MULTISAMPLE_ARRAY or TEXTURE_BUFFER"), false;
  if (level < 0 || level >= LevelCount(target) || ((target == TEXTURE_BUFFER || target == TEXTURE_2D_MULTISAMPLE_ARRAY) && level != 0))
    return s.SetError(INVALID_VALUE, what, "level is negative or beyond the largest mipmap level (a buffer texture and a multisample array have level 0 alone)"), false;
  int face = 0;
  const detail::TextureObject* tex = s.Bound(target, &face);
  if (!tex) return s.SetError(INVALID_OPERATION, what, "no texture is bound to that target of the active unit"), false;
  if (target == TEXTURE_BUFFER) {  // one row of texels, as many as the buffer's store holds; without a buffer, none
    const detail::TextureView view = detail::MakeView(*tex);
    const bool image = tex->buffer_store != nullptr;
    const FormatBits bits = BitsOf(image ? tex->buffer_format : 0);
    switch (pname) {
      case TEXTURE_WIDTH: out = view.buffer_texels; return true;
      case TEXTURE_HEIGHT:
      case TEXTURE_DEPTH: out = image ? 1 : 0; return true;
      case TEXTURE_INTERNAL_FORMAT: out = int(tex->buffer_format); return true;
      case TEXTURE_BUFFER_DATA_STORE_BINDING: out = int(tex->buffer_id); return true;
      case TEXTURE_SAMPLES:
      case TEXTURE_COMPRESSED: out = 0; return true;
      case TEXTURE_RED_SIZE: out = bits.r; return true;
      case TEXTURE_GREEN_SIZE: out = bits.g; return true;
      case TEXTURE_BLUE_SIZE: out = bits.b; return true;
      case TEXTURE_ALPHA_SIZE: out = bits.a; return true;
      case TEXTURE_DEPTH_SIZE:
      case TEXTURE_STENCIL_SIZE: out = 0; return true;
      default: return s.SetError(INVALID_ENUM, what, "pname is not a level parameter of a buffer texture"), false;
    }
  }
  const detail::TextureLevel& lv = tex->levels[face][level];
  const FormatBits bits = BitsOf(lv.Defined() ? lv.format : 0);
  switch (pname) {
    case TEXTURE_WIDTH: out = lv.Defined() ? lv.width : 0; return true;
    // (A 1D array's layers are its height, as OpenGL counts them.)
    case TEXTURE_HEIGHT: out = lv.Defined() ? (tex->target == TEXTURE_1D_ARRAY ? lv.depth : lv.height) : 0; return true;
    case TEXTURE_DEPTH: out = lv.Defined() ? (tex->target == TEXTURE_1D_ARRAY ? 1 : lv.depth) : 0; return true;
    case TEXTURE_SAMPLES: out = lv.Defined() && detail::IsMultisampleTarget(tex->target) ? lv.samples : 0; return true;
    case TEXTURE_FIXED_SAMPLE_LOCATIONS: out = 1; return true;  // the standard positions, always
    // (A compressed level keeps its format even when it is empty, as OpenGL keeps it.)
    case TEXTURE_INTERNAL_FORMAT: out = int(lv.compressed != 0 ? lv.compressed : lv.Defined() ? lv.format : RGBA); return true;
    case TEXTURE_COMPRESSED: out = lv.compressed != 0; return true;
    case TEXTURE_COMPRESSED_IMAGE_SIZE:
      if (lv.compressed == 0) return s.SetError(INVALID_OPERATION, what, "the level is not compressed"), false;
      out = int(std::min<std::size_t>(lv.blocks.size(), INT_MAX));
      return true;
    case TEXTURE_RED_SIZE: out = bits.r; return true;
    case TEXTURE_GREEN_SIZE: out = bits.g; return true;
    case TEXTURE_BLUE_SIZE: out = bits.b; return true;
    case TEXTURE_ALPHA_SIZE: out = bits.a; return true;
    case TEXTURE_DEPTH_SIZE: out = bits.depth; return true;
    case TEXTURE_STENCIL_SIZE: out = bits.stencil; return true;
    default: return s.SetError(INVALID_ENUM, what, "pname is not a texture level parameter"), false;
  }
}

}  // namespace

void Context::GetTexParameterfv(Enum target, Enum pname, float* params) const {
  float v[4];
  int n = 0;
  if (!TexParameterValues(*state_, __func__, target, pname, v, n) || !NotNull(*state_, __func__, params, "params")) return;
  std::copy(v, v + n, params);
}

void Context::GetTexParameteriv(Enum target, Enum pname, int* params) const {
  float v[4];
  int n = 0;
  if (!TexParameterValues(*state_, __func__, target, pname, v, n) || !NotNull(*state_, __func__, params, "params")) return;
  IntegersOfValues(pname, v, n, params);
}

void Context::GetTexLevelParameteriv(Enum target, int level, Enum pname, int* params) const {
  int v = 0;
  if (TexLevelValue(*state_, __func__, target, level, pname, v) && NotNull(*state_, __func__, params, "params")) *params = v;
}

void Context::GetTexLevelParameterfv(Enum target, int level, Enum pname, float* params) const {
  int v = 0;
  if (TexLevelValue(*state_, __func__, target, level, pname, v) && NotNull(*state_, __func__, params, "params")) *params = float(v);
}

void Context::PixelStore(Enum pname, int value) {
  auto& s = *state_;
  switch (pname) {
    case UNPACK_ALIGNMENT:
    case PACK_ALIGNMENT:
      if (value != 1 && value != 2 && value != 4 && value != 8) return s.SetError(INVALID_VALUE, __func__, "alignment must be 1, 2, 4 or 8");
      (pname == PACK_ALIGNMENT ? s.pack : s.unpack).alignment = value;
      return;
    case UNPACK_SWAP_BYTES: s.unpack.swap_bytes = value != 0; return;
    case PACK_SWAP_BYTES: s.pack.swap_bytes = value != 0; return;
    case UNPACK_LSB_FIRST: s.unpack_lsb_first = value != 0; return;
    case PACK_LSB_FIRST: s.pack_lsb_first = value != 0; return;
    default: break;
  }
  int* field = nullptr;
  switch (pname) {
    case UNPACK_ROW_LENGTH: field = &s.unpack.row_length; break;
    case UNPACK_IMAGE_HEIGHT: field = &s.unpack.image_height; break;
    case UNPACK_SKIP_PIXELS: field = &s.unpack.skip_pixels; break;
    case UNPACK_SKIP_ROWS: field = &s.unpack.skip_rows; break;
    case UNPACK_SKIP_IMAGES: field = &s.unpack.skip_images; break;
    case PACK_ROW_LENGTH: field = &s.pack.row_length; break;
    case PACK_IMAGE_HEIGHT: field = &s.pack.image_height; break;
    case PACK_SKIP_PIXELS: field = &s.pack.skip_pixels; break;
    case PACK_SKIP_ROWS: field = &s.pack.skip_rows; break;
    case PACK_SKIP_IMAGES: field = &s.pack.skip_images; break;
    default: return s.SetError(INVALID_ENUM, __func__, "pname must be one of the UNPACK_ or PACK_ parameters of OpenGL 3.3 (table 3.1)");
  }
  if (value < 0) return s.SetError(INVALID_VALUE, __func__, "value is negative");
  *field = value;
}

// ---- Sampler objects ------------------------------------------------------------------------------------------

std::uint32_t Context::GenSampler() {
  return NewId(state_->samplers, state_->next_sampler, [] { return std::make_shared<detail::SamplerParams>(); });
}

void Context::GenSamplers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenSampler(); });
}

void Context::DeleteSamplers(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteSampler(id); });
}

void Context::DeleteSampler(std::uint32_t sampler) {
  auto& s = *state_;
  auto it = s.samplers.find(sampler);
  if (it == s.samplers.end()) return;
  for (TextureUnit& u : s.units)  // (recorded draws hold copies of its state)
    if (u.sampler == it->second) u.sampler.reset();
  s.samplers.erase(it);
}

bool Context::IsSampler(std::uint32_t sampler) const { return state_->samplers.count(sampler) != 0; }

void Context::BindSampler(int unit, std::uint32_t sampler) {
  auto& s = *state_;
  if (unit < 0 || unit >= kMaxTextureUnits) return s.SetError(INVALID_VALUE, __func__, "unit must be 0 to kMaxTextureUnits - 1 (a number, not TEXTURE0 + i)");
  std::shared_ptr<detail::SamplerParams> object;
  if (sampler != 0) {
    auto it = s.samplers.find(sampler);
    if (it == s.samplers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a sampler id made by GenSampler (or it was deleted)");
    object = it->second;
  }
  s.units[unit].sampler = std::move(object);
}

namespace {

// The sampler object `sampler`; null with INVALID_OPERATION set when there is none.
detail::SamplerParams* SamplerOf(ContextState& s, const char* what, std::uint32_t sampler) {
  auto it = s.samplers.find(sampler);
  if (it == s.samplers.end()) return s.SetError(INVALID_OPERATION, what, "not a sampler id made by GenSampler (or it was deleted)"), nullptr;
  return it->second.get();
}

}  // namespace

void Context::SamplerParameterfv(std::uint32_t sampler, Enum pname, const float* values) {
  auto& s = *state_;
  if (detail::SamplerParams* p = SamplerOf(s, __func__, sampler)) SetSamplerParameter(s, __func__, *p, pname, values, false);
}

void Context::SamplerParameteri(std::uint32_t sampler, Enum pname, int value) {
  if (pname == TEXTURE_BORDER_COLOR) return state_->SetError(INVALID_ENUM, __func__, "TEXTURE_BORDER_COLOR takes four values: use SamplerParameterfv");
  const float v = float(value);
  auto& s = *state_;
  if (detail::SamplerParams* p = SamplerOf(s, __func__, sampler)) SetSamplerParameter(s, __func__, *p, pname, &v, false);
}

void Context::SamplerParameterf(std::uint32_t sampler, Enum pname, float value) {
  if (pname == TEXTURE_BORDER_COLOR) return state_->SetError(INVALID_ENUM, __func__, "TEXTURE_BORDER_COLOR takes four values: use SamplerParameterfv");
  auto& s = *state_;
  if (detail::SamplerParams* p = SamplerOf(s, __func__, sampler)) SetSamplerParameter(s, __func__, *p, pname, &value, false);
}

void Context::SamplerParameteriv(std::uint32_t sampler, Enum pname, const int* values) {
  auto& s = *state_;
  detail::SamplerParams* p = SamplerOf(s, __func__, sampler);
  if (!p) return;
  if (values == nullptr) return s.SetError(INVALID_VALUE, __func__, "values is null");
  float v[4] = {float(values[0]), 0.0f, 0.0f, 0.0f};
  if (pname == TEXTURE_BORDER_COLOR) BorderOfIntegers(values, v);
  SetSamplerParameter(s, __func__, *p, pname, v, false);
}

namespace {

// SamplerParameterI*v and TexParameterI*v on state `p` (a texture's when `levels`): the border colour's four numbers
// kept as they are (`kind` 1 signed, 2 unsigned), as floats for sampling; any other name as the iv forms.
template <class T>
void SetParameterI(ContextState& s, const char* what, detail::SamplerParams& p, Enum pname, const T* values, int kind,
                   bool levels) {
  if (values == nullptr) return s.SetError(INVALID_VALUE, what, "values is null");
  if (pname != TEXTURE_BORDER_COLOR) {
    const float v = float(values[0]);
    return SetSamplerParameter(s, what, p, pname, &v, levels);
  }
  for (int k = 0; k < 4; ++k) {
    p.border[k] = float(values[k]);
    p.border_bits[k] = std::uint32_t(values[k]);
  }
  p.border_integer = kind;
}

// GetSamplerParameterI*v and GetTexParameterI*v of `p`, whose value of `pname` is `v` (n values): the border
// colour's numbers as the integer forms set them (else its floats, rounded and clamped to T's range); any other
// name as the iv forms.
template <class T>
void ParameterI(const detail::SamplerParams& p, Enum pname, const float* v, int n, T* params) {
  for (int k = 0; k < n; ++k) {
    if (pname == TEXTURE_BORDER_COLOR && p.border_integer != 0) {
      params[k] = T(p.border_bits[k]);
      continue;
    }
    const double lo = double(std::numeric_limits<T>::min()), hi = double(std::numeric_limits<T>::max());
    params[k] = std::isnan(v[k]) ? T(0) : T(std::llround(std::clamp(double(v[k]), lo, hi)));
  }
}

template <class T>
void SetSamplerParameterI(ContextState& s, const char* what, std::uint32_t sampler, Enum pname, const T* values, int kind) {
  if (detail::SamplerParams* p = SamplerOf(s, what, sampler)) SetParameterI(s, what, *p, pname, values, kind, false);
}

template <class T>
void SamplerParameterI(ContextState& s, const char* what, std::uint32_t sampler, Enum pname, T* params) {
  const detail::SamplerParams* p = SamplerOf(s, what, sampler);
  float v[4];
  int n = 0;
  if (!p || !SamplerParameterValues(s, what, *p, pname, v, n, false) || !NotNull(s, what, params, "params")) return;
  ParameterI(*p, pname, v, n, params);
}

// The texture bound to `target` for TexParameterI*v, or null with the error set.
detail::TextureObject* TexParameterTarget(ContextState& s, const char* what, Enum target) {
  s.Sync(what);
  if (!detail::HasLevelsAndSampling(target)) return s.SetError(INVALID_ENUM, what, "target must be TEXTURE_1D, TEXTURE_2D, TEXTURE_CUBE_MAP, TEXTURE_1D_ARRAY, TEXTURE_2D_ARRAY or TEXTURE_3D (a multisample or buffer texture has no levels or sampling state)"), nullptr;
  detail::TextureObject* tex = s.Bound(target);
  if (!tex) return s.SetError(INVALID_OPERATION, what, "no texture is bound to that target of the active unit"), nullptr;
  return tex;
}

template <class T>
void TexParameterI(ContextState& s, const char* what, Enum target, Enum pname, T* params) {
  float v[4];
  int n = 0;
  if (!TexParameterValues(s, what, target, pname, v, n) || !NotNull(s, what, params, "params")) return;
  ParameterI(s.Bound(target)->params, pname, v, n, params);
}

}  // namespace

void Context::SamplerParameterIiv(std::uint32_t sampler, Enum pname, const int* values) {
  SetSamplerParameterI(*state_, __func__, sampler, pname, values, 1);
}

void Context::SamplerParameterIuiv(std::uint32_t sampler, Enum pname, const std::uint32_t* values) {
  SetSamplerParameterI(*state_, __func__, sampler, pname, values, 2);
}

void Context::TexParameterIiv(Enum target, Enum pname, const int* values) {
  if (detail::TextureObject* tex = TexParameterTarget(*state_, __func__, target)) SetParameterI(*state_, __func__, tex->params, pname, values, 1, true);
}

void Context::TexParameterIuiv(Enum target, Enum pname, const std::uint32_t* values) {
  if (detail::TextureObject* tex = TexParameterTarget(*state_, __func__, target)) SetParameterI(*state_, __func__, tex->params, pname, values, 2, true);
}

void Context::GetTexParameterIiv(Enum target, Enum pname, int* params) const { TexParameterI(*state_, __func__, target, pname, params); }

void Context::GetTexParameterIuiv(Enum target, Enum pname, std::uint32_t* params) const {
  TexParameterI(*state_, __func__, target, pname, params);
}

void Context::GetSamplerParameterfv(std::uint32_t sampler, Enum pname, float* params) const {
  auto& s = *state_;
  const detail::SamplerParams* p = SamplerOf(s, __func__, sampler);
  float v[4];
  int n = 0;
  if (!p || !SamplerParameterValues(s, __func__, *p, pname, v, n, false) || !NotNull(s, __func__, params, "params")) return;
  std::copy(v, v + n, params);
}

void Context::GetSamplerParameteriv(std::uint32_t sampler, Enum pname, int* params) const {
  auto& s = *state_;
  const detail::SamplerParams* p = SamplerOf(s, __func__, sampler);
  float v[4];
  int n = 0;
  if (!p || !SamplerParameterValues(s, __func__, *p, pname, v, n, false) || !NotNull(s, __func__, params, "params")) return;
  IntegersOfValues(pname, v, n, params);
}

void Context::GetSamplerParameterIiv(std::uint32_t sampler, Enum pname, int* params) const {
  SamplerParameterI(*state_, __func__, sampler, pname, params);
}

void Context::GetSamplerParameterIuiv(std::uint32_t sampler, Enum pname, std::uint32_t* params) const {
  SamplerParameterI(*state_, __func__, sampler, pname, params);
}

}  // namespace softgl

// pixel_transfer.h — client pixel data as OpenGL 3.3 defines it (section 3.7.2 and tables 3.2 to 3.5 for unpacking,
// section 4.3.2 for packing): which format and type pairs a transfer takes, how many bytes a pixel has, and the
// conversions between one client pixel and RGBA, depth and stencil values. TexImage*, TexSubImage*, ReadPixels and
// GetTexImage all go through here; where the rectangle's rows lie (PixelStore) is texture.h's ClientLayout.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>
#include <softgl/enums.h>

namespace softgl::detail {

/// A T from client memory at p, which need not be aligned for T (a memcpy, as C++ allows), and back.
template <class T>
T LoadUnaligned(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class T>
void StoreUnaligned(std::uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

/// Which call a transfer serves: they take different formats (STENCIL_INDEX only ReadPixels).
enum class TransferCall { kUnpack, kReadPixels, kGetTexImage };

/// OpenGL 3.3's answer to `format` with `type`: NO_ERROR; INVALID_ENUM for a format or type the call does not take,
/// or DEPTH_STENCIL with a type other than UNSIGNED_INT_24_8 and FLOAT_32_UNSIGNED_INT_24_8_REV (section 4.3.1);
/// INVALID_OPERATION for a packed type with another format than its own (table 3.5), and for an integer format
/// (RED_INTEGER ...) with a float type. (Whether integer data suits the texture or buffer is the caller's check.)
/// `why` is set to a message when the answer is an error.
Enum CheckPixelTransfer(Enum format, Enum type, TransferCall call, const char*& why);

/// Bytes of one client pixel of a valid (format, type).
std::size_t TransferPixelBytes(Enum format, Enum type);

/// Bytes of one element of `type`: what UNPACK_ALIGNMENT compares with and SWAP_BYTES reverses (a packed type's
/// whole value; each of FLOAT_32_UNSIGNED_INT_24_8_REV's two words).
std::size_t TransferElementBytes(Enum type);

/// The client pixel at p as RGBA: the format's components in their channels (BGR and BGRA reordered, GREEN into
/// green ...), absent ones 0 and alpha 1. Unsigned normalized components are c / (2^b - 1), signed ones
/// max(c / (2^(b-1) - 1), -1) (OpenGL 4.2's rule, which Mesa also follows; 3.3 has (2c + 1) / (2^b - 1)),
/// HALF_FLOAT, FLOAT and the packed float types their values. DEPTH_COMPONENT's depth is in red.
glm::vec4 UnpackColor(Enum format, Enum type, const std::uint8_t* p);

/// RED_INTEGER ... BGRA_INTEGER.
bool IsIntegerTransfer(Enum format);

/// An integer client pixel at p (an integer format with an integer or packed type): the format's components as
/// the numbers they are (signed or unsigned by the type; a packed type's fields), absent ones 0 and alpha 1.
void UnpackInteger(Enum format, Enum type, const std::uint8_t* p, std::int64_t out[4]);
/// Writes integers v (RGBA) as a client pixel of an integer format at p: each clamped to the type's range (a
/// packed field's), as Mesa packs them.
void PackInteger(Enum format, Enum type, const std::int64_t v[4], std::uint8_t* p);

/// A DEPTH_STENCIL client pixel (UNSIGNED_INT_24_8: depth in the high 24 bits; FLOAT_32_UNSIGNED_INT_24_8_REV: a
/// float, then a word with the stencil in its low 8 bits).
void UnpackDepthStencil(Enum type, const std::uint8_t* p, float& depth, std::uint8_t& stencil);

/// Writes c as a client pixel of `format` and `type` at p (OpenGL 3.3, section 4.3.2, "Final conversion"):
/// unsigned normalized types take each component clamped to [0, 1], signed ones to [-1, 1] (NaN as 0), times the
/// largest value, rounded; HALF_FLOAT and FLOAT take it as it is; UNSIGNED_INT_10F_11F_11F_REV and
/// UNSIGNED_INT_5_9_9_9_REV encode it as their small and shared-exponent floats. DEPTH_COMPONENT writes c.r.
void PackColor(Enum format, Enum type, const glm::vec4& c, std::uint8_t* p);
/// PackColor for n pixels of four floats each (rgba), the client pixels `pixel` bytes apart from p: the conversion
/// chosen once (UNSIGNED_BYTE and FLOAT written directly), the bytes PackColor gives pixel by pixel.
void PackColorRow(Enum format, Enum type, const float* rgba, int n, std::uint8_t* p, std::size_t pixel);
/// The channels (0 red to 3 alpha) of a client format's components in client order, and their count (0 for an
/// unknown format; depth and stencil formats have one, channel 0).
int FormatChannels(Enum format, int ch[4]);

/// Writes a stencil index as `type`: masked to the type's bits for the integer types, converted for the floats.
void PackStencil(Enum type, std::uint32_t stencil, std::uint8_t* p);

/// Writes a DEPTH_STENCIL pixel (depth in [0, 1]; NaN as 0).
void PackDepthStencil(Enum type, float depth, std::uint8_t stencil, std::uint8_t* p);

/// RGB as UNSIGNED_INT_5_9_9_9_REV (OpenGL 3.3, section 3.8.1's RGB9_E5 encoding: each channel clamped to
/// [0, 65408], NaN as 0), and back.
std::uint32_t EncodeRgb9e5(const glm::vec3& rgb);
glm::vec3 DecodeRgb9e5(std::uint32_t v);

}  // namespace softgl::detail

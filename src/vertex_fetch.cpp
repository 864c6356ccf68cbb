// vertex_fetch.cpp — attribute and index reads with OpenGL's integer-to-float conversions.
#include "vertex_fetch.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "pixel_transfer.h"
#include "texture.h"

namespace softgl::detail {

std::size_t TypeSize(Enum type) {
  switch (type) {
    case BYTE:
    case UNSIGNED_BYTE: return 1;
    case SHORT:
    case UNSIGNED_SHORT: return 2;
    case HALF_FLOAT: return 2;
    case INT:
    case UNSIGNED_INT:
    case FLOAT:
    case INT_2_10_10_10_REV:
    case UNSIGNED_INT_2_10_10_10_REV: return 4;
    case DOUBLE: return 8;
    default: return 0;
  }
}

bool IsPackedAttribType(Enum type) { return type == INT_2_10_10_10_REV || type == UNSIGNED_INT_2_10_10_10_REV; }

std::size_t AttributeBytes(Enum type, int components) {
  return IsPackedAttribType(type) ? 4 : TypeSize(type) * std::size_t(components);
}

namespace {

// A double as the nearest float (to nearest, ties to even): beyond the largest float by half a unit or more it is
// infinity (a plain conversion of such a value is undefined in C++).
float DoubleToFloat(double d) {
  const double largest = double(std::numeric_limits<float>::max());
  if (!(std::abs(d) > largest)) return float(d);  // (NaN too)
  const bool rounds_down = std::abs(d) < largest + std::ldexp(1.0, 103);  // half a unit at 2^127 is 2^103
  const float to = rounds_down ? std::numeric_limits<float>::max() : std::numeric_limits<float>::infinity();
  return d < 0.0 ? -to : to;
}

// OpenGL 4.2+ conversions (section 2.3.5.1 of the 4.6 specification): unsigned c / (2^b - 1);
// signed max(c / (2^(b-1) - 1), -1). `normalized` does not apply to the float types.
float Component(Enum type, bool normalized, const std::uint8_t* p) {
  switch (type) {
    case FLOAT: return LoadUnaligned<float>(p);
    case HALF_FLOAT: return HalfToFloat(LoadUnaligned<std::uint16_t>(p));
    case DOUBLE: return DoubleToFloat(LoadUnaligned<double>(p));
    case UNSIGNED_BYTE: {
      const float c = LoadUnaligned<std::uint8_t>(p);
      return normalized ? c / 255.0f : c;
    }
    case BYTE: {
      const float c = LoadUnaligned<std::int8_t>(p);
      return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case UNSIGNED_SHORT: {
      const float c = LoadUnaligned<std::uint16_t>(p);
      return normalized ? c / 65535.0f : c;
    }
    case SHORT: {
      const float c = LoadUnaligned<std::int16_t>(p);
      return normalized ? std::max(c / 32767.0f, -1.0f) : c;
    }
    case UNSIGNED_INT: {
      const std::uint32_t c = LoadUnaligned<std::uint32_t>(p);
      return normalized ? float(double(c) / 4294967295.0) : float(c);
    }
    case INT: {
      const std::int32_t c = LoadUnaligned<std::int32_t>(p);
      return normalized ? float(std::max(double(c) / 2147483647.0, -1.0)) : float(c);
    }
    default: return 0.0f;
  }
}

}  // namespace

glm::vec4 Packed2101010(Enum type, bool normalized, std::uint32_t word) {
  glm::vec4 v;
  for (int k = 0; k < 4; ++k) {
    const int bits = k == 3 ? 2 : 10;
    const std::uint32_t field = (word >> (10 * k)) & ((1u << bits) - 1u);
    if (type == INT_2_10_10_10_REV) {
      const int c = int(field) - (field >> (bits - 1) ? 1 << bits : 0);  // two's complement of `bits` bits
      v[k] = normalized ? std::max(float(c) / float((1 << (bits - 1)) - 1), -1.0f) : float(c);
    } else {
      v[k] = normalized ? float(field) / float((1u << bits) - 1u) : float(field);
    }
  }
  return v;
}

namespace {

// An enabled attribute resolved for many reads: element i starts at base + stride * i and exists for i <= last
// (last < 0: no element fits in the buffer).
struct Resolved {
  const std::uint8_t* base = nullptr;
  std::size_t stride = 0;
  long long last = -1;
  std::size_t csize = 0;
};
Resolved Resolve(const AttribSource& src) {
  Resolved r;
  const std::size_t csize = TypeSize(src.type), bytes = AttributeBytes(src.type, src.components);
  r.csize = csize;
  // Overflow-safe bounds: start = offset + stride * index, end = start + bytes <= size.
  if (src.data == nullptr || src.offset > src.size) return r;
  const std::size_t room = src.size - src.offset;
  if (bytes > room) return r;
  r.base = src.data + src.offset;
  r.stride = src.stride;
  r.last = src.stride == 0 ? std::numeric_limits<long long>::max()
                           : (long long)(std::min<std::size_t>((room - bytes) / src.stride, std::size_t(1) << 40));
  return r;
}
// An integer attribute's element at p: each component sign- or zero-extended as its type says.
glm::vec4 ReadInteger(const AttribSource& src, const std::uint8_t* p) {
  glm::ivec4 v(0, 0, 0, 1);
  for (int c = 0; c < src.components; ++c) {
    const std::uint8_t* q = p + TypeSize(src.type) * std::size_t(c);
    switch (src.type) {
      case BYTE: v[c] = LoadUnaligned<std::int8_t>(q); break;
      case UNSIGNED_BYTE: v[c] = LoadUnaligned<std::uint8_t>(q); break;
      case SHORT: v[c] = LoadUnaligned<std::int16_t>(q); break;
      case UNSIGNED_SHORT: v[c] = LoadUnaligned<std::uint16_t>(q); break;
      default: v[c] = LoadUnaligned<std::int32_t>(q); break;  // INT, UNSIGNED_INT (the same bits)
    }
  }
  return IntegerAttrib(v);
}

glm::vec4 Read(const AttribSource& src, const Resolved& r, std::uint32_t index) {
  glm::vec4 v(0.0f, 0.0f, 0.0f, 1.0f);
  if ((long long)index > r.last) return src.integer ? IntegerAttrib(glm::ivec4(0, 0, 0, 1)) : v;
  const std::uint8_t* p = r.base + r.stride * std::size_t(index);
  if (src.integer) return ReadInteger(src, p);
  if (src.type == FLOAT) {  // the common case: fixed-size copies (glm::vec4 is four floats)
    switch (src.components) {
      case 1: std::memcpy(static_cast<void*>(&v), p, 4); break;
      case 2: std::memcpy(static_cast<void*>(&v), p, 8); break;
      case 3: std::memcpy(static_cast<void*>(&v), p, 12); break;
      default: std::memcpy(static_cast<void*>(&v), p, 16); break;
    }
    return v;
  }
  if (IsPackedAttribType(src.type)) v = Packed2101010(src.type, src.normalized, LoadUnaligned<std::uint32_t>(p));
  else
    for (int c = 0; c < src.components; ++c) v[c] = Component(src.type, src.normalized, p + r.csize * c);
  if (src.bgra) std::swap(v.x, v.z);  // size BGRA: the element holds blue, green, red, alpha
  return v;
}

}  // namespace

glm::vec4 FetchAttribute(const AttribSource& src, std::uint32_t index) { return Read(src, Resolve(src), index); }

glm::vec4 IntegerAttrib(const glm::ivec4& v) {
  glm::vec4 f;
  std::memcpy(static_cast<void*>(&f), &v, sizeof f);
  return f;
}

void FetchVertices(const FetchPlan& plan, const std::uint32_t* indices, int count, std::uint32_t instance,
                   float* out, int stride) {
  if (count <= 0) return;
  const int padded = (count + 15) & ~15;
  const std::size_t row = std::size_t(stride);
  for (std::uint32_t bits = plan.enabled; bits != 0; bits &= bits - 1) {
    const int a = std::countr_zero(bits);
    const AttribSource& src = plan.attrib[a];
    float* x = out + std::size_t(a) * 4 * row;
    float *y = x + row, *z = y + row, *w = z + row;
    const Resolved r = Resolve(src);
    auto put = [&](int i, const glm::vec4& v) {
      x[i] = v.x;
      y[i] = v.y;
      z[i] = v.z;
      w[i] = v.w;
    };
    if (src.divisor != 0) {  // one element for the whole instance
      const glm::vec4 v = Read(src, r, instance / src.divisor);
      for (int i = 0; i < padded; ++i) put(i, v);
      continue;
    }
    if (src.type == FLOAT && !src.integer && r.last >= 0) {  // the common case: floats straight into the rows
      const int n = src.components;
      for (int i = 0; i < count; ++i) {
        if ((long long)indices[i] > r.last) {
          put(i, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // (not an integer attribute: FLOAT is not an integer type)
          continue;
        }
        const std::uint8_t* p = r.base + r.stride * std::size_t(indices[i]);
        float c[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        std::memcpy(c, p, 4);
        if (n > 1) std::memcpy(c + 1, p + 4, 4);
        if (n > 2) std::memcpy(c + 2, p + 8, 4);
        if (n > 3) std::memcpy(c + 3, p + 12, 4);
        x[i] = c[0];
        y[i] = c[1];
        z[i] = c[2];
        w[i] = c[3];
      }
    } else {
      for (int i = 0; i < count; ++i) put(i, Read(src, r, indices[i]));
    }
    for (float* r : {x, y, z, w}) {  // the last group of 16, whole (a loop the compiler vectorizes)
      float* g = r + (padded - 16);
      const float last = r[count - 1];
      const int keep = count - (padded - 16);
      for (int i = 0; i < 16; ++i) g[i] = i < keep ? g[i] : last;
    }
  }
}

void ReadIndices(Enum type, const std::uint8_t* data, int count, std::uint32_t* out) {
  auto read = [&](auto zero) {  // one loop per index type (the type decided once, not per index)
    using T = decltype(zero);
    for (int i = 0; i < count; ++i) out[i] = LoadUnaligned<T>(data + sizeof(T) * std::size_t(i));
  };
  switch (type) {
    case UNSIGNED_BYTE: read(std::uint8_t{}); break;
    case UNSIGNED_SHORT: read(std::uint16_t{}); break;
    default: read(std::uint32_t{}); break;
  }
}

}  // namespace softgl::detail

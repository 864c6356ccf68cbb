// vertex_fetch.h — stage 1: read vertex attributes and indices from buffer memory, with OpenGL's conversions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <softgl/enums.h>
#include <softgl/shader.h>

namespace softgl::detail {

/// Where one attribute comes from, resolved from the vertex array and buffer objects at draw time.
struct AttribSource {
  const std::uint8_t* data = nullptr;  // start of the buffer's store
  std::size_t size = 0;                // bytes in the store
  std::size_t offset = 0;              // byte offset of element 0
  std::size_t stride = 0;              // bytes between elements (already resolved: never 0 when enabled)
  int components = 4;                  // 1..4
  Enum type = FLOAT;
  bool normalized = false;
  bool bgra = false;                   // size BGRA: red and blue swapped (4 components)
  // VertexAttribIPointer: the components are integers, kept as integers (sign- or zero-extended to 32 bits) and
  // handed on as the bits of the floats they occupy (missing ones 0, 0, 0 and 1 as integers).
  bool integer = false;
  std::uint32_t divisor = 0;           // VertexAttribDivisor: 0 reads per vertex, d > 0 element instance / d
};

struct FetchPlan {
  AttribSource attrib[kMaxVertexAttribs];
  std::uint32_t enabled = 0;  // bit a: attrib[a].enabled (the only attributes FetchVertices reads)
  glm::vec4 current[kMaxVertexAttribs];  // the value a disabled attribute reads (VertexAttrib4f), (0, 0, 0, 1) at first
  FetchPlan() {
    for (glm::vec4& c : current) c = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  }
};

/// Size in bytes of one component of an attribute or index type (BYTE ... DOUBLE; the packed 2_10_10_10 types 4,
/// their whole element); 0 for an unknown type.
std::size_t TypeSize(Enum type);

/// INT_2_10_10_10_REV and UNSIGNED_INT_2_10_10_10_REV: four components in one 32-bit element.
bool IsPackedAttribType(Enum type);

/// The four components of a packed element (INT_2_10_10_10_REV or UNSIGNED_INT_2_10_10_10_REV): x in bits 0-9, y
/// 10-19, z 20-29, w 30-31 (OpenGL 3.3, section 2.8, table 2.5), signed fields two's complement, normalized or not
/// as the other integer types are converted.
glm::vec4 Packed2101010(Enum type, bool normalized, std::uint32_t word);

/// Bytes of one attribute element of `components` components of `type` (a packed type's 4 whatever the count).
std::size_t AttributeBytes(Enum type, int components);

/// Reads attribute `src` of vertex `index` (an enabled attribute). Missing components come from (0, 0, 0, 1); an
/// element that lies (even partly) outside the buffer reads as (0, 0, 0, 1). An integer attribute's components are
/// 32-bit integers in the floats' bits (IntegerAttrib makes such a value).
glm::vec4 FetchAttribute(const AttribSource& src, std::uint32_t index);

/// Fetches all attributes of `count` vertices of instance `instance` into rows of lanes, as VertexBatch::attribs
/// lays them out: component c of attribute a of vertex i at out[(a * 4 + c) * stride + i], each enabled attribute's
/// rows padded up to a multiple of 16 (stride at least that) with the last vertex's value. An attribute with divisor
/// d > 0 reads element instance / d for every vertex (OpenGL 3.3, section 2.8.2), the others the vertex's index.
/// Only the enabled attributes (plan.enabled) are written: a disabled one's value is plan.current, which the vertex
/// stage reads from there (VertexBatch::current).
void FetchVertices(const FetchPlan& plan, const std::uint32_t* indices, int count, std::uint32_t instance,
                   float* out, int stride);

/// The floats whose bits are the integers v (an integer attribute's value, or VertexAttribI*'s current value).
glm::vec4 IntegerAttrib(const glm::ivec4& v);

/// Reads `count` indices of `type` (UNSIGNED_BYTE/SHORT/INT) from `data`. The caller has checked the range.
void ReadIndices(Enum type, const std::uint8_t* data, int count, std::uint32_t* out);

}  // namespace softgl::detail

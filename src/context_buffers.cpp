// context_buffers.cpp — buffer objects (data, mapping, copies, parameters) and vertex arrays (attribute pointers,
// divisors, current attribute values).
#include "context_state.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace softgl {

// ---- Buffers -------------------------------------------------------------------------------------------------

std::uint32_t Context::GenBuffer() {
  return NewId(state_->buffers, state_->next_buffer, [] { return std::make_shared<Buffer>(); });
}

void Context::GenBuffers(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenBuffer(); });
}

void Context::DeleteBuffers(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteBuffer(id); });
}

void Context::DeleteBuffer(std::uint32_t buffer) {
  auto& s = *state_;
  auto it = s.buffers.find(buffer);
  if (it == s.buffers.end()) return;
  Buffer* dead = it->second.get();
  dead->Unmap();  // deleting a mapped buffer unmaps it
  if (s.array_buffer.get() == dead) s.array_buffer.reset();
  if (s.copy_read_buffer.get() == dead) s.copy_read_buffer.reset();
  if (s.copy_write_buffer.get() == dead) s.copy_write_buffer.reset();
  if (s.texture_buffer.get() == dead) s.texture_buffer.reset();
  if (s.feedback_buffer.get() == dead) s.feedback_buffer.reset();
  for (FeedbackBinding& b : s.feedback->binding)  // the bound transform feedback object's (as the vertex array's)
    if (b.buffer.get() == dead) b = FeedbackBinding{};
  if (s.vao) {  // only the bound vertex array forgets it (OpenGL 4.6, section 5.1.2)
    if (s.vao->element_buffer.get() == dead) s.vao->element_buffer.reset();
    for (auto& a : s.vao->attrib)
      if (a.buffer.get() == dead) a.buffer.reset();
  }
  s.buffers.erase(it);
}

bool Context::IsBuffer(std::uint32_t buffer) const { return state_->buffers.count(buffer) != 0; }

void Context::BindBuffer(Enum target, std::uint32_t buffer) {
  auto& s = *state_;
  if (!ContextState::IsBufferTarget(target)) return s.SetError(INVALID_ENUM, __func__, ContextState::kBufferTargets);
  std::shared_ptr<Buffer> object;
  if (buffer != 0) {
    auto it = s.buffers.find(buffer);
    if (it == s.buffers.end()) return s.SetError(INVALID_OPERATION, __func__, "not a buffer id made by GenBuffer (or it was deleted)");
    object = it->second;
  }
  auto* binding = s.BindingFor(target);
  if (binding == nullptr) return s.SetError(INVALID_OPERATION, __func__, "ELEMENT_ARRAY_BUFFER needs a bound vertex array");  // element buffer with no vertex array bound
  *binding = std::move(object);
}

void Context::BufferData(Enum target, std::ptrdiff_t size, const void* data, Enum usage) {
  auto& s = *state_;
  if (!ContextState::IsBufferTarget(target)) return s.SetError(INVALID_ENUM, __func__, ContextState::kBufferTargets);
  if (!IsUsage(usage)) return s.SetError(INVALID_ENUM, __func__, "not a buffer usage");
  if (size < 0) return s.SetError(INVALID_VALUE, __func__, "size is negative");
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  try {
    std::vector<std::uint8_t> store(std::size_t(size), 0);
    if (data != nullptr && size > 0) std::memcpy(store.data(), data, std::size_t(size));
    s.BeforeStoreChange(*buffer, __func__);
    buffer->Unmap();  // a new store unmaps the old one, as OpenGL does
    buffer->data = std::move(store);
    buffer->usage = usage;
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  } catch (const std::length_error&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

namespace {

// Whether [offset, offset + size) lies inside a store of `store` bytes (offset and size already non-negative).
bool InStore(std::size_t store, std::ptrdiff_t offset, std::ptrdiff_t size) {
  return std::size_t(offset) <= store && std::size_t(size) <= store - std::size_t(offset);
}

}  // namespace

void Context::BufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, const void* data) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "offset or size is negative");
  if (!InStore(buffer->data.size(), offset, size)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the buffer's store");
  // OpenGL 3.3 (sections 2.9.2 and 6.1.13): an error whenever the buffer is mapped, whatever range is written.
  if (buffer->mapped) return s.SetError(INVALID_OPERATION, __func__, "the buffer is mapped");
  if (size == 0 || !NotNull(s, __func__, data, "data")) return;
  s.BeforeStoreChange(*buffer, __func__);
  std::memcpy(buffer->data.data() + offset, data, std::size_t(size));
}

namespace {

void* MapRange(ContextState& s, const char* what, Enum target, std::ptrdiff_t offset, std::ptrdiff_t length,
               Bitfield access) {
  Buffer* buffer = s.BoundBuffer(what, target);
  if (buffer == nullptr) return nullptr;
  constexpr Bitfield kKnown = MAP_READ_BIT | MAP_WRITE_BIT | MAP_INVALIDATE_RANGE_BIT | MAP_INVALIDATE_BUFFER_BIT |
                              MAP_FLUSH_EXPLICIT_BIT | MAP_UNSYNCHRONIZED_BIT;
  if (offset < 0 || length < 0) return s.SetError(INVALID_VALUE, what, "offset or length is negative"), nullptr;
  if (!InStore(buffer->data.size(), offset, length)) return s.SetError(INVALID_VALUE, what, "the range is outside the buffer's store"), nullptr;
  if (access & ~kKnown) return s.SetError(INVALID_VALUE, what, "access has bits other than the MAP_*_BIT ones"), nullptr;
  if (length == 0) return s.SetError(INVALID_OPERATION, what, "length is zero"), nullptr;
  if (buffer->mapped) return s.SetError(INVALID_OPERATION, what, "the buffer is already mapped"), nullptr;
  if (!(access & (MAP_READ_BIT | MAP_WRITE_BIT))) return s.SetError(INVALID_OPERATION, what, "access has neither MAP_READ_BIT nor MAP_WRITE_BIT"), nullptr;
  if ((access & MAP_READ_BIT) && (access & (MAP_INVALIDATE_RANGE_BIT | MAP_INVALIDATE_BUFFER_BIT | MAP_UNSYNCHRONIZED_BIT)))
    return s.SetError(INVALID_OPERATION, what, "MAP_READ_BIT with an INVALIDATE or UNSYNCHRONIZED bit"), nullptr;
  if ((access & MAP_FLUSH_EXPLICIT_BIT) && !(access & MAP_WRITE_BIT)) return s.SetError(INVALID_OPERATION, what, "MAP_FLUSH_EXPLICIT_BIT without MAP_WRITE_BIT"), nullptr;
  // Draws read their vertices when they are made, so the store holds everything earlier calls wrote: the caller's
  // view of it is the store itself (invalidated bytes keep their old values, which OpenGL allows).
  if (access & MAP_WRITE_BIT) s.BeforeStoreChange(*buffer, what);  // the caller may write through the pointer
  buffer->mapped = true;
  buffer->access_flags = access;
  buffer->map_offset = std::size_t(offset);
  buffer->map_length = std::size_t(length);
  return buffer->data.data() + offset;
}

}  // namespace

void* Context::MapBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length, Bitfield access) {
  return MapRange(*state_, __func__, target, offset, length, access);
}

void* Context::MapBuffer(Enum target, Enum access) {
  auto& s = *state_;
  const Bitfield bits = access == READ_ONLY ? MAP_READ_BIT : access == WRITE_ONLY ? MAP_WRITE_BIT
                        : access == READ_WRITE ? MAP_READ_BIT | MAP_WRITE_BIT : 0;
  if (bits == 0) return s.SetError(INVALID_ENUM, __func__, "access must be READ_ONLY, WRITE_ONLY or READ_WRITE"), nullptr;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return nullptr;
  if (buffer->data.empty()) return s.SetError(INVALID_OPERATION, __func__, "the buffer has no store"), nullptr;
  return MapRange(s, __func__, target, 0, std::ptrdiff_t(buffer->data.size()), bits);
}

void Context::FlushMappedBufferRange(Enum target, std::ptrdiff_t offset, std::ptrdiff_t length) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || length < 0) return s.SetError(INVALID_VALUE, __func__, "offset or length is negative");
  if (!buffer->mapped || !(buffer->access_flags & MAP_FLUSH_EXPLICIT_BIT)) return s.SetError(INVALID_OPERATION, __func__, "the buffer is not mapped with MAP_FLUSH_EXPLICIT_BIT");
  if (!InStore(buffer->map_length, offset, length)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the mapped range");
  // The mapping is the store: flushed bytes are already in place.
}

bool Context::UnmapBuffer(Enum target) {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return false;
  if (!buffer->mapped) return s.SetError(INVALID_OPERATION, __func__, "the buffer is not mapped"), false;
  buffer->Unmap();
  return true;
}

void Context::CopyBufferSubData(Enum read_target, Enum write_target, std::ptrdiff_t read_offset,
                                std::ptrdiff_t write_offset, std::ptrdiff_t size) {
  auto& s = *state_;
  Buffer* src = s.BoundBuffer(__func__, read_target);
  if (src == nullptr) return;
  Buffer* dst = s.BoundBuffer(__func__, write_target);
  if (dst == nullptr) return;
  if (read_offset < 0 || write_offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "an offset or the size is negative");
  if (!InStore(src->data.size(), read_offset, size) || !InStore(dst->data.size(), write_offset, size))
    return s.SetError(INVALID_VALUE, __func__, "a range is outside its buffer's store");
  if (src == dst && read_offset < write_offset + size && write_offset < read_offset + size)
    return s.SetError(INVALID_VALUE, __func__, "the ranges overlap within one buffer");
  if (src->mapped || dst->mapped) return s.SetError(INVALID_OPERATION, __func__, "a buffer is mapped");
  if (size == 0) return;
  s.BeforeStoreChange(*dst, __func__);
  std::memmove(dst->data.data() + write_offset, src->data.data() + read_offset, std::size_t(size));
}

void Context::GetBufferSubData(Enum target, std::ptrdiff_t offset, std::ptrdiff_t size, void* data) const {
  auto& s = *state_;
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (offset < 0 || size < 0) return s.SetError(INVALID_VALUE, __func__, "offset or size is negative");
  if (!InStore(buffer->data.size(), offset, size)) return s.SetError(INVALID_VALUE, __func__, "the range is outside the buffer's store");
  if (buffer->mapped) return s.SetError(INVALID_OPERATION, __func__, "the buffer is mapped");
  if (size == 0 || !NotNull(s, __func__, data, "data")) return;
  std::memcpy(data, buffer->data.data() + offset, std::size_t(size));
}

namespace {

// The value of buffer parameter `pname`, or false with the error set.
bool BufferParameter(ContextState& s, const char* what, Enum target, Enum pname, std::int64_t& v) {
  Buffer* buffer = s.BoundBuffer(what, target);
  if (buffer == nullptr) return false;
  const Bitfield flags = buffer->access_flags;
  switch (pname) {
    case BUFFER_SIZE: v = std::int64_t(buffer->data.size()); break;
    case BUFFER_USAGE: v = buffer->usage; break;
    case BUFFER_MAPPED: v = buffer->mapped; break;
    case BUFFER_ACCESS_FLAGS: v = flags; break;
    case BUFFER_MAP_OFFSET: v = std::int64_t(buffer->map_offset); break;
    case BUFFER_MAP_LENGTH: v = std::int64_t(buffer->map_length); break;
    case BUFFER_ACCESS:  // READ_WRITE when not mapped, as OpenGL's initial value
      v = (flags & MAP_READ_BIT) && !(flags & MAP_WRITE_BIT) ? READ_ONLY
          : (flags & MAP_WRITE_BIT) && !(flags & MAP_READ_BIT) ? WRITE_ONLY
                                                                 : READ_WRITE;
      break;
    default: return s.SetError(INVALID_ENUM, what, "not a buffer parameter name"), false;
  }
  return true;
}

}  // namespace

void Context::GetBufferParameteri64v(Enum target, Enum pname, std::int64_t* params) const {
  std::int64_t v = 0;
  if (BufferParameter(*state_, __func__, target, pname, v) && NotNull(*state_, __func__, params, "params")) *params = v;
}

void Context::GetBufferParameteriv(Enum target, Enum pname, int* params) const {
  std::int64_t v = 0;
  // Sizes beyond the int range read as the largest int (OpenGL's conversion of integer state to a smaller type).
  if (BufferParameter(*state_, __func__, target, pname, v) && NotNull(*state_, __func__, params, "params"))
    *params = int(std::clamp<std::int64_t>(v, INT32_MIN, INT32_MAX));
}

void Context::GetBufferPointerv(Enum target, Enum pname, void** params) const {
  auto& s = *state_;
  if (pname != BUFFER_MAP_POINTER) return s.SetError(INVALID_ENUM, __func__, "pname must be BUFFER_MAP_POINTER");
  Buffer* buffer = s.BoundBuffer(__func__, target);
  if (buffer == nullptr) return;
  if (NotNull(s, __func__, params, "params")) *params = buffer->mapped ? buffer->data.data() + buffer->map_offset : nullptr;
}

// ---- Vertex arrays -------------------------------------------------------------------------------------------

std::uint32_t Context::GenVertexArray() {
  return NewId(state_->arrays, state_->next_array, [] { return std::make_unique<VertexArray>(); });
}

void Context::GenVertexArrays(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenVertexArray(); });
}

void Context::DeleteVertexArrays(int n, const std::uint32_t* ids) {
  DeleteMany(*state_, __func__, n, ids, [this](std::uint32_t id) { DeleteVertexArray(id); });
}

void Context::DeleteVertexArray(std::uint32_t array) {
  auto& s = *state_;
  auto it = s.arrays.find(array);
  if (it == s.arrays.end()) return;
  if (s.vao == it->second.get()) {
    s.vao = nullptr;
    s.vao_id = 0;
  }
  s.arrays.erase(it);
}

bool Context::IsVertexArray(std::uint32_t array) const { return state_->arrays.count(array) != 0; }

void Context::BindVertexArray(std::uint32_t array) {
  auto& s = *state_;
  if (array == 0) {
    s.vao = nullptr;
    s.vao_id = 0;
    return;
  }
  auto it = s.arrays.find(array);
  if (it == s.arrays.end()) return s.SetError(INVALID_OPERATION, __func__, "not a vertex array id made by GenVertexArray (or it was deleted)");
  s.vao = it->second.get();
  s.vao_id = array;
}

namespace {

// VertexAttributePointer and VertexAttribIPointer once their arguments are checked: attribute `index` of the bound
// vertex array reads the buffer bound to ARRAY_BUFFER.
void SetAttribArray(ContextState& s, const char* what, std::uint32_t index, int size, Enum type, bool normalized,
                    bool bgra, bool integer, int stride, std::size_t offset) {
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, what, "no vertex array is bound");
  if (!s.array_buffer && offset != 0) return s.SetError(INVALID_OPERATION, what, "no buffer bound to ARRAY_BUFFER (client-side arrays do not exist in a core profile)");
  AttribBinding& a = s.vao->attrib[index];
  a.buffer = s.array_buffer;
  a.offset = offset;
  a.size = size;
  a.bgra = bgra;
  a.integer = integer;
  a.type = type;
  a.normalized = normalized;
  a.stride = stride;
}

}  // namespace

void Context::VertexAttributePointer(std::uint32_t index, int size, Enum type, bool normalized, int stride,
                                     std::size_t offset) {
  auto& s = *state_;
  const bool bgra = size == int(BGRA);
  if (index >= std::uint32_t(kMaxVertexAttribs) || ((size < 1 || size > 4) && !bgra) || stride < 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range (size is 1 to 4 or BGRA)");
  if (detail::TypeSize(type) == 0) return s.SetError(INVALID_ENUM, __func__, "not an attribute type");
  // OpenGL 3.3, section 2.8: the packed types hold four components; BGRA is four normalized components of one of
  // them or of UNSIGNED_BYTE.
  const bool packed = detail::IsPackedAttribType(type);
  if (packed && size != 4 && !bgra) return s.SetError(INVALID_OPERATION, __func__, "the 2_10_10_10 types take size 4 or BGRA");
  if (bgra && ((!packed && type != UNSIGNED_BYTE) || !normalized))
    return s.SetError(INVALID_OPERATION, __func__, "size BGRA takes UNSIGNED_BYTE or a 2_10_10_10 type, normalized");
  SetAttribArray(s, __func__, index, bgra ? 4 : size, type, normalized, bgra, false, stride, offset);
}

void Context::VertexAttribIPointer(std::uint32_t index, int size, Enum type, int stride, std::size_t offset) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs) || size < 1 || size > 4 || stride < 0)
    return s.SetError(INVALID_VALUE, __func__, "a numeric argument is out of range (size is 1 to 4)");
  if (type != BYTE && type != UNSIGNED_BYTE && type != SHORT && type != UNSIGNED_SHORT && type != INT && type != UNSIGNED_INT)
    return s.SetError(INVALID_ENUM, __func__, "type must be BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, INT or UNSIGNED_INT");
  SetAttribArray(s, __func__, index, size, type, false, false, true, stride, offset);
}

void Context::EnableVertexAttribArray(std::uint32_t index) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->enabled |= 1u << index;
}

void Context::DisableVertexAttribArray(std::uint32_t index) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->enabled &= ~(1u << index);
}

void Context::VertexAttribDivisor(std::uint32_t index, std::uint32_t divisor) {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  s.vao->attrib[index].divisor = divisor;
}

void Context::VertexAttrib4f(std::uint32_t index, float x, float y, float z, float w) {
  if (index >= std::uint32_t(kMaxVertexAttribs)) return state_->SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  state_->current_attrib[index] = glm::vec4(x, y, z, w);
  state_->current_integer[index] = 0;
}

namespace {

// VertexAttribI*: the first `components` of v (the others (0, 0, 1)) as attribute `index`'s current value,
// integers of the kind `kind` says (1 signed, 2 unsigned).
template <class T>
void SetIntegerAttrib(ContextState& s, const char* what, std::uint32_t index, const T* v, int components, int kind) {
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, what, "attribute index is kMaxVertexAttribs or more");
  if (!NotNull(s, what, v, "v")) return;
  glm::ivec4 current(0, 0, 0, 1);
  for (int k = 0; k < components; ++k) current[k] = std::int32_t(v[k]);  // (unsigned: the same bits)
  s.current_attrib[index] = detail::IntegerAttrib(current);
  s.current_integer[index] = std::uint8_t(kind);
}

}  // namespace

void Context::VertexAttribI1i(std::uint32_t index, int x) { VertexAttribI4i(index, x, 0, 0, 1); }
void Context::VertexAttribI2i(std::uint32_t index, int x, int y) { VertexAttribI4i(index, x, y, 0, 1); }
void Context::VertexAttribI3i(std::uint32_t index, int x, int y, int z) { VertexAttribI4i(index, x, y, z, 1); }
void Context::VertexAttribI4i(std::uint32_t index, int x, int y, int z, int w) {
  const int v[4] = {x, y, z, w};
  SetIntegerAttrib(*state_, __func__, index, v, 4, 1);
}
void Context::VertexAttribI1ui(std::uint32_t index, std::uint32_t x) { VertexAttribI4ui(index, x, 0, 0, 1); }
void Context::VertexAttribI2ui(std::uint32_t index, std::uint32_t x, std::uint32_t y) { VertexAttribI4ui(index, x, y, 0, 1); }
void Context::VertexAttribI3ui(std::uint32_t index, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  VertexAttribI4ui(index, x, y, z, 1);
}
void Context::VertexAttribI4ui(std::uint32_t index, std::uint32_t x, std::uint32_t y, std::uint32_t z, std::uint32_t w) {
  const std::uint32_t v[4] = {x, y, z, w};
  SetIntegerAttrib(*state_, __func__, index, v, 4, 2);
}
void Context::VertexAttribI1iv(std::uint32_t index, const int* v) { SetIntegerAttrib(*state_, __func__, index, v, 1, 1); }
void Context::VertexAttribI2iv(std::uint32_t index, const int* v) { SetIntegerAttrib(*state_, __func__, index, v, 2, 1); }
void Context::VertexAttribI3iv(std::uint32_t index, const int* v) { SetIntegerAttrib(*state_, __func__, index, v, 3, 1); }
void Context::VertexAttribI4iv(std::uint32_t index, const int* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 1); }
void Context::VertexAttribI1uiv(std::uint32_t index, const std::uint32_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 1, 2); }
void Context::VertexAttribI2uiv(std::uint32_t index, const std::uint32_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 2, 2); }
void Context::VertexAttribI3uiv(std::uint32_t index, const std::uint32_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 3, 2); }
void Context::VertexAttribI4uiv(std::uint32_t index, const std::uint32_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 2); }
void Context::VertexAttribI4bv(std::uint32_t index, const std::int8_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 1); }
void Context::VertexAttribI4sv(std::uint32_t index, const std::int16_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 1); }
void Context::VertexAttribI4ubv(std::uint32_t index, const std::uint8_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 2); }
void Context::VertexAttribI4usv(std::uint32_t index, const std::uint16_t* v) { SetIntegerAttrib(*state_, __func__, index, v, 4, 2); }

namespace {

// VertexAttribP*: the first `components` components of a packed word as attribute `index`'s current value.
void SetPackedAttrib(ContextState& s, const char* what, std::uint32_t index, Enum type, bool normalized,
                     const std::uint32_t* value, int components) {
  if (!detail::IsPackedAttribType(type)) return s.SetError(INVALID_ENUM, what, "type must be INT_2_10_10_10_REV or UNSIGNED_INT_2_10_10_10_REV");
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, what, "attribute index is kMaxVertexAttribs or more");
  if (!NotNull(s, what, value, "value")) return;
  const glm::vec4 v = detail::Packed2101010(type, normalized, *value);
  glm::vec4 current(0.0f, 0.0f, 0.0f, 1.0f);
  for (int k = 0; k < components; ++k) current[k] = v[k];
  s.current_attrib[index] = current;
  s.current_integer[index] = 0;
}

}  // namespace

void Context::VertexAttribP1ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, &value, 1);
}
void Context::VertexAttribP2ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, &value, 2);
}
void Context::VertexAttribP3ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, &value, 3);
}
void Context::VertexAttribP4ui(std::uint32_t index, Enum type, bool normalized, std::uint32_t value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, &value, 4);
}
void Context::VertexAttribP1uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, value, 1);
}
void Context::VertexAttribP2uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, value, 2);
}
void Context::VertexAttribP3uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, value, 3);
}
void Context::VertexAttribP4uiv(std::uint32_t index, Enum type, bool normalized, const std::uint32_t* value) {
  SetPackedAttrib(*state_, __func__, index, type, normalized, value, 4);
}

}  // namespace softgl

namespace softgl {

namespace {

// GetVertexAttrib*'s value `pname` of attribute `index`, as up to four doubles (CURRENT_VERTEX_ATTRIB: four); false
// with the error set.
bool VertexAttribValues(ContextState& s, const char* what, std::uint32_t index, Enum pname, double out[4], int& n) {
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, what, "attribute index is kMaxVertexAttribs or more"), false;
  n = 1;
  if (pname == CURRENT_VERTEX_ATTRIB) {
    n = 4;
    glm::ivec4 bits;
    std::memcpy(&bits, &s.current_attrib[index], sizeof bits);
    for (int c = 0; c < 4; ++c)  // (integers given by VertexAttribI*: their values, signed or not)
      out[c] = s.current_integer[index] == 0   ? double(s.current_attrib[index][c])
               : s.current_integer[index] == 1 ? double(bits[c])
                                               : double(std::uint32_t(bits[c]));
    return true;
  }
  const bool array_state = pname == VERTEX_ATTRIB_ARRAY_ENABLED || pname == VERTEX_ATTRIB_ARRAY_SIZE ||
                           pname == VERTEX_ATTRIB_ARRAY_STRIDE || pname == VERTEX_ATTRIB_ARRAY_TYPE ||
                           pname == VERTEX_ATTRIB_ARRAY_NORMALIZED || pname == VERTEX_ATTRIB_ARRAY_INTEGER ||
                           pname == VERTEX_ATTRIB_ARRAY_DIVISOR || pname == VERTEX_ATTRIB_ARRAY_BUFFER_BINDING;
  if (!array_state) return s.SetError(INVALID_ENUM, what, "pname is not a vertex attribute state"), false;
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, what, "no vertex array is bound"), false;
  const AttribBinding& a = s.vao->attrib[index];
  switch (pname) {
    case VERTEX_ATTRIB_ARRAY_ENABLED: out[0] = (s.vao->enabled >> index) & 1u; break;
    case VERTEX_ATTRIB_ARRAY_SIZE: out[0] = a.bgra ? double(BGRA) : double(a.size); break;
    case VERTEX_ATTRIB_ARRAY_STRIDE: out[0] = a.stride; break;
    case VERTEX_ATTRIB_ARRAY_TYPE: out[0] = double(a.type); break;
    case VERTEX_ATTRIB_ARRAY_NORMALIZED: out[0] = a.normalized ? 1.0 : 0.0; break;
    case VERTEX_ATTRIB_ARRAY_INTEGER: out[0] = a.integer ? 1.0 : 0.0; break;
    case VERTEX_ATTRIB_ARRAY_DIVISOR: out[0] = double(a.divisor); break;
    default: out[0] = double(IdOf(s.buffers, a.buffer.get())); break;  // VERTEX_ATTRIB_ARRAY_BUFFER_BINDING
  }
  return true;
}

// The values as integers of type T: rounded to nearest (halves away from 0) and clamped to T's range (NaN as 0).
template <class T>
void VertexAttribIntegers(ContextState& s, const char* what, std::uint32_t index, Enum pname, T* params) {
  double v[4];
  int n = 0;
  if (!VertexAttribValues(s, what, index, pname, v, n) || !NotNull(s, what, params, "params")) return;
  const double lo = double(std::numeric_limits<T>::min()), hi = double(std::numeric_limits<T>::max());
  for (int k = 0; k < n; ++k) params[k] = std::isnan(v[k]) ? T(0) : T(std::llround(std::clamp(v[k], lo, hi)));
}

}  // namespace

void Context::GetVertexAttribdv(std::uint32_t index, Enum pname, double* params) const {
  auto& s = *state_;
  double v[4];
  int n = 0;
  if (VertexAttribValues(s, __func__, index, pname, v, n) && NotNull(s, __func__, params, "params")) std::copy(v, v + n, params);
}

void Context::GetVertexAttribfv(std::uint32_t index, Enum pname, float* params) const {
  auto& s = *state_;
  double v[4];
  int n = 0;
  if (!VertexAttribValues(s, __func__, index, pname, v, n) || !NotNull(s, __func__, params, "params")) return;
  for (int k = 0; k < n; ++k) params[k] = float(v[k]);
}

void Context::GetVertexAttribiv(std::uint32_t index, Enum pname, int* params) const {
  VertexAttribIntegers(*state_, __func__, index, pname, params);
}

void Context::GetVertexAttribIiv(std::uint32_t index, Enum pname, int* params) const {
  VertexAttribIntegers(*state_, __func__, index, pname, params);
}

void Context::GetVertexAttribIuiv(std::uint32_t index, Enum pname, std::uint32_t* params) const {
  VertexAttribIntegers(*state_, __func__, index, pname, params);
}

void Context::GetVertexAttribPointerv(std::uint32_t index, Enum pname, void** pointer) const {
  auto& s = *state_;
  if (index >= std::uint32_t(kMaxVertexAttribs)) return s.SetError(INVALID_VALUE, __func__, "attribute index is kMaxVertexAttribs or more");
  if (pname != VERTEX_ATTRIB_ARRAY_POINTER) return s.SetError(INVALID_ENUM, __func__, "pname must be VERTEX_ATTRIB_ARRAY_POINTER");
  if (s.vao == nullptr) return s.SetError(INVALID_OPERATION, __func__, "no vertex array is bound");
  if (NotNull(s, __func__, pointer, "pointer"))
    *pointer = reinterpret_cast<void*>(static_cast<std::uintptr_t>(s.vao->attrib[index].offset));
}

}  // namespace softgl

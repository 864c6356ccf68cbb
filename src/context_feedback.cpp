// context_feedback.cpp — transform feedback: the varyings a program records, the indexed buffer bindings, Begin /
// End / Pause / Resume and transform feedback objects. The recording itself is the pipeline's (RecordDraw, given a
// FeedbackCapture by ContextState::Draw).
#include "context_state.h"

#include <cstring>

namespace softgl {

void Context::TransformFeedbackVaryings(Program& program, int count, const FeedbackVarying* varyings,
                                        Enum buffer_mode) {
  auto& s = *state_;
  if (buffer_mode != INTERLEAVED_ATTRIBS && buffer_mode != SEPARATE_ATTRIBS) return s.SetError(INVALID_ENUM, __func__, "buffer_mode must be INTERLEAVED_ATTRIBS or SEPARATE_ATTRIBS");
  if (count < 0) return s.SetError(INVALID_VALUE, __func__, "count is negative");
  if (buffer_mode == SEPARATE_ATTRIBS && count > kMaxFeedbackBuffers) return s.SetError(INVALID_VALUE, __func__, "more separate varyings than MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS (4)");
  if (count > 0 && !NotNull(s, __func__, varyings, "varyings")) return;
  if (s.feedback->active && s.feedback->program == &program) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is recording from this program");
  int floats = 0;
  for (int i = 0; i < count; ++i) {
    const FeedbackVarying& v = varyings[i];
    if (v.name == nullptr) return s.SetError(INVALID_VALUE, __func__, "a varying's name is null");
    if (v.components < 1 || v.components > 4) return s.SetError(INVALID_VALUE, __func__, "a varying's components are not 1 to 4");
    const bool position = v.first == FeedbackVarying::kPosition;
    if (!position && (v.first < 0 || v.first + v.components > program.VaryingFloats())) return s.SetError(INVALID_VALUE, __func__, "a varying's floats are not among the program's varyings");
    floats += v.components;
  }
  if (buffer_mode == INTERLEAVED_ATTRIBS && floats > kMaxFeedbackComponents) return s.SetError(INVALID_VALUE, __func__, "more floats than MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS (64)");
  try {
    auto layout = std::make_shared<detail::FeedbackLayout>();
    layout->separate = buffer_mode == SEPARATE_ATTRIBS;
    layout->floats = floats;
    for (int i = 0; i < count; ++i)
      layout->items.push_back({varyings[i].name, varyings[i].first, varyings[i].components});
    program.feedback_ = std::move(layout);
  } catch (const std::bad_alloc&) {
    s.SetError(OUT_OF_MEMORY, __func__, "out of memory");
  }
}

void Context::GetTransformFeedbackVarying(const Program& program, std::uint32_t index, int buf_size, int* length,
                                          int* size, Enum* type, char* name) const {
  auto& s = *state_;
  const detail::FeedbackLayout* layout = program.feedback_.get();
  if (!layout || index >= layout->items.size()) return s.SetError(INVALID_VALUE, __func__, "index is past the program's transform feedback varyings");
  if (buf_size < 0) return s.SetError(INVALID_VALUE, __func__, "buf_size is negative");
  const detail::FeedbackLayout::Item& item = layout->items[index];
  const std::size_t n = buf_size > 0 ? std::min(item.name.size(), std::size_t(buf_size) - 1) : 0;
  if (name && buf_size > 0) {
    std::memcpy(name, item.name.data(), n);
    name[n] = '\0';
  }
  if (length) *length = int(n);
  if (size) *size = 1;
  constexpr Enum kTypes[] = {FLOAT, FLOAT_VEC2, FLOAT_VEC3, FLOAT_VEC4};
  if (type) *type = kTypes[item.components - 1];
}

namespace {

// BindBufferRange and BindBufferBase: binding `index` of the bound object, and the generic binding.
void BindIndexed(ContextState& s, const char* what, Enum target, std::uint32_t index, std::uint32_t buffer,
                 std::ptrdiff_t offset, std::ptrdiff_t size, bool range) {
  if (target != TRANSFORM_FEEDBACK_BUFFER) return s.SetError(INVALID_ENUM, what, "target must be TRANSFORM_FEEDBACK_BUFFER (the one indexed buffer target)");
  if (index >= std::uint32_t(kMaxFeedbackBuffers)) return s.SetError(INVALID_VALUE, what, "index is not a transform feedback binding (0 to MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS - 1)");
  if (s.feedback->active) return s.SetError(INVALID_OPERATION, what, "transform feedback is active");
  std::shared_ptr<Buffer> object;
  if (buffer != 0) {
    if (range && (size <= 0 || offset < 0)) return s.SetError(INVALID_VALUE, what, "size is not positive or offset is negative");
    if (range && (offset % 4 != 0 || size % 4 != 0)) return s.SetError(INVALID_VALUE, what, "offset or size is not a multiple of 4");
    auto it = s.buffers.find(buffer);
    if (it == s.buffers.end()) return s.SetError(INVALID_OPERATION, what, "not a buffer id made by GenBuffer (or it was deleted)");
    object = it->second;
  }
  FeedbackBinding& b = s.feedback->binding[index];
  b.buffer = object;
  b.range = range && object;
  b.offset = b.range ? std::size_t(offset) : 0;
  b.size = b.range ? std::size_t(size) : 0;
  s.feedback_buffer = std::move(object);
}

}  // namespace

void Context::BindBufferRange(Enum target, std::uint32_t index, std::uint32_t buffer, std::ptrdiff_t offset,
                              std::ptrdiff_t size) {
  BindIndexed(*state_, __func__, target, index, buffer, offset, size, true);
}

void Context::BindBufferBase(Enum target, std::uint32_t index, std::uint32_t buffer) {
  BindIndexed(*state_, __func__, target, index, buffer, 0, 0, false);
}

void Context::BeginTransformFeedback(Enum primitive_mode) {
  auto& s = *state_;
  if (primitive_mode != POINTS && primitive_mode != LINES && primitive_mode != TRIANGLES) return s.SetError(INVALID_ENUM, __func__, "primitive_mode must be POINTS, LINES or TRIANGLES");
  TransformFeedbackObject& t = *s.feedback;
  if (t.active) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is already active");
  if (!s.program || !s.program->feedback_ || s.program->feedback_->items.empty()) return s.SetError(INVALID_OPERATION, __func__, "the current program records no varyings (TransformFeedbackVaryings)");
  const detail::FeedbackLayout& layout = *s.program->feedback_;
  for (int b = 0; b < layout.Buffers(); ++b)
    if (!t.binding[b].buffer) return s.SetError(INVALID_OPERATION, __func__, "a transform feedback binding the program records into has no buffer");
  t.active = true;
  t.paused = false;
  t.mode = primitive_mode;
  t.layout = s.program->feedback_;
  t.program = s.program;
  std::fill(std::begin(t.written), std::end(t.written), std::size_t(0));
  t.vertices = 0;
}

void Context::EndTransformFeedback() {
  auto& s = *state_;
  TransformFeedbackObject& t = *s.feedback;
  if (!t.active) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is not active");
  t.active = t.paused = false;
  t.ended = true;
  t.drawable = t.vertices;
  t.layout.reset();
  t.program = nullptr;
}

void Context::PauseTransformFeedback() {
  auto& s = *state_;
  if (!s.feedback->Recording()) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is not active, or already paused");
  s.feedback->paused = true;
}

void Context::ResumeTransformFeedback() {
  auto& s = *state_;
  if (!s.feedback->active || !s.feedback->paused) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is not paused");
  // OpenGL 4.6 (section 13.3): the program must be the one Begin recorded from.
  if (s.program != s.feedback->program) return s.SetError(INVALID_OPERATION, __func__, "the current program is not the one transform feedback began with");
  s.feedback->paused = false;
}

std::uint32_t Context::GenTransformFeedback() {
  return NewId(state_->feedbacks, state_->next_feedback, [] { return std::make_unique<TransformFeedbackObject>(); });
}

void Context::GenTransformFeedbacks(int n, std::uint32_t* ids) {
  GenMany(*state_, __func__, n, ids, [this] { return GenTransformFeedback(); });
}

void Context::DeleteTransformFeedbacks(int n, const std::uint32_t* ids) {
  auto& s = *state_;
  if (n < 0) return s.SetError(INVALID_VALUE, __func__, "n is negative");
  if (n > 0 && !NotNull(s, __func__, ids, "ids")) return;
  for (int i = 0; i < n; ++i) {  // (OpenGL: an active object is an error, and nothing is deleted)
    auto it = s.feedbacks.find(ids[i]);
    if (it != s.feedbacks.end() && it->second->active) return s.SetError(INVALID_OPERATION, __func__, "a transform feedback object is active");
  }
  for (int i = 0; i < n; ++i) {
    auto it = s.feedbacks.find(ids[i]);
    if (it == s.feedbacks.end()) continue;
    if (s.feedback == it->second.get()) {
      s.feedback = &s.default_feedback;
      s.feedback_id = 0;
    }
    s.feedbacks.erase(it);
  }
}

bool Context::IsTransformFeedback(std::uint32_t id) const {
  auto it = state_->feedbacks.find(id);
  return it != state_->feedbacks.end() && it->second->bound;  // a name becomes an object when first bound
}

void Context::BindTransformFeedback(Enum target, std::uint32_t id) {
  auto& s = *state_;
  if (target != TRANSFORM_FEEDBACK) return s.SetError(INVALID_ENUM, __func__, "target must be TRANSFORM_FEEDBACK");
  if (s.feedback->Recording()) return s.SetError(INVALID_OPERATION, __func__, "transform feedback is active (and not paused)");
  TransformFeedbackObject* object = &s.default_feedback;
  if (id != 0) {
    auto it = s.feedbacks.find(id);
    if (it == s.feedbacks.end()) return s.SetError(INVALID_OPERATION, __func__, "not a transform feedback id made by GenTransformFeedback (or it was deleted)");
    object = it->second.get();
  }
  object->bound = true;
  s.feedback = object;
  s.feedback_id = id;
}

}  // namespace softgl

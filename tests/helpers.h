// helpers.h — shaders and small drawing helpers shared by the tests.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <softgl/softgl.h>

#include "types.h"

namespace testing {

struct NoVaryings {};

/// Checks that a texture target without levels or sampling state (a multisample or buffer texture) refuses them
/// with INVALID_ENUM: TexParameteri of a filter, GenerateMipmap, and defining a level by TexImage2D or (`layered`)
/// TexImage3D.
inline void CheckRefusesLevelsAndSampling(softgl::Context& gl, softgl::Enum target, bool layered = false) {
  gl.TexParameteri(target, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  CHECK(gl.GetError() == softgl::INVALID_ENUM);
  gl.GenerateMipmap(target);
  CHECK(gl.GetError() == softgl::INVALID_ENUM);
  if (layered) gl.TexImage3D(target, 0, softgl::RGBA8, 8, 8, 2, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  else gl.TexImage2D(target, 0, softgl::RGBA8, 8, 8, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  CHECK(gl.GetError() == softgl::INVALID_ENUM);
}

/// Passes attribute 0 through as the clip-space position and writes a constant colour.
struct SolidShader : softgl::Shader<SolidShader, NoVaryings> {
  glm::vec4 color{1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  bool Fragment(const softgl::FragmentIn<NoVaryings>&, softgl::FragmentOut& out) const {
    out.color[0] = color;
    return true;
  }
};

struct Vec4Varyings {
  glm::vec4 value;
};

/// Position from attribute 0, varying from attribute 1; the fragment stage records every fragment's varying and
/// gl_FragCoord by pixel, and counts how often each pixel was shaded. The record is shared by the shader and the
/// copies draws take of it (Program::Snapshot), and guarded for the worker threads; read it after Finish().
struct CaptureShader : softgl::Shader<CaptureShader, Vec4Varyings> {
  struct Sample {
    glm::vec4 value;
    glm::vec4 frag_coord;
    bool front_facing;
    int hits = 0;
  };
  struct Record {
    std::mutex mutex;
    std::map<std::pair<int, int>, Sample> samples;
  };
  std::shared_ptr<Record> record = std::make_shared<Record>();
  std::map<std::pair<int, int>, Sample>& samples = record->samples;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<Vec4Varyings>& out) const {
    out.position = in.attrib[0];
    out.varyings.value = in.attrib[1];
  }
  bool Fragment(const softgl::FragmentIn<Vec4Varyings>& in, softgl::FragmentOut& out) const {
    std::lock_guard<std::mutex> lock(record->mutex);
    Sample& s = samples[{int(in.frag_coord.x), int(in.frag_coord.y)}];
    s.value = in.varyings.value;
    s.frag_coord = in.frag_coord;
    s.front_facing = in.front_facing;
    ++s.hits;
    out.color[0] = glm::vec4(1.0f);
    return true;
  }
};

/// Makes a vertex array whose attribute 0 reads vec4 positions and attribute 1 vec4 values from one buffer.
inline std::uint32_t MakeVertexArray(softgl::Context& gl, const std::vector<glm::vec4>& positions,
                                     const std::vector<glm::vec4>& values = {}) {
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  std::vector<glm::vec4> data = positions;
  data.insert(data.end(), values.begin(), values.end());
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(data.size() * sizeof(glm::vec4)), data.data());
  gl.VertexAttributePointer(0, 4, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  if (!values.empty()) {
    gl.VertexAttributePointer(1, 4, softgl::FLOAT, false, 0, positions.size() * sizeof(glm::vec4));
    gl.EnableVertexAttribArray(1);
  }
  return vao;
}

/// Clip-space position of window pixel coordinate (x, y) for a viewport of width x height at the origin.
inline glm::vec4 WindowToClip(float x, float y, int width, int height, float z = 0.0f) {
  return glm::vec4(x / float(width) * 2.0f - 1.0f, y / float(height) * 2.0f - 1.0f, z, 1.0f);
}

/// Counts, per pixel, how many live fragments the rasterizer emits (collects BlockBuffers through a BlockSink).
struct CoverageCounter {
  int width, height;
  std::vector<int> hits;
  CoverageCounter(int w, int h) : width(w), height(h), hits(std::size_t(w) * std::size_t(h), 0) {}
  static void Flush(void* user, softgl::detail::BlockBuffer& blocks) {
    auto* self = static_cast<CoverageCounter*>(user);
    for (int b = 0; b < blocks.count; ++b)
      for (int lane = 0; lane < softgl::kLanes; ++lane)
        if ((blocks.live[b] >> lane) & 1u) {
          const int x = blocks.X(b, lane), y = blocks.Y(b, lane);
          if (x >= 0 && y >= 0 && x < self->width && y < self->height) ++self->hits[std::size_t(y) * self->width + x];
        }
  }
  softgl::detail::BlockSink Sink() { return {&CoverageCounter::Flush, this}; }
  int At(int x, int y) const { return hits[std::size_t(y) * width + x]; }
};

}  // namespace testing

// Tests of the context's control of when work counts: conditional rendering on an occlusion query, sync objects
// (fences), and ClampColor's clamping of reads.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "helpers.h"

using namespace softgl;
using testing::MakeVertexArray;
using testing::SolidShader;

namespace {

// A context with SolidShader in use and a vertex array of two quads: vertices 0-3 the whole screen at depth 0,
// vertices 4-7 the left half at depth 0.5 (behind the first where the depth test is on).
struct Scene {
  Context gl;
  SolidShader shader;
  explicit Scene(int threads = 1) : gl(32, 32, Context::Options{threads}) {
    gl.UseProgram(shader);
    MakeVertexArray(gl, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}, {1, 1, 0, 1},
                         {-1, -1, 0.5f, 1}, {0, -1, 0.5f, 1}, {-1, 1, 0.5f, 1}, {0, 1, 0.5f, 1}});
  }
  // An occlusion query over a draw of the left half with the depth test on: it passes when the depth buffer was
  // cleared (true) and fails behind the full quad (false). The colour buffer is left alone; the draws are left
  // recorded, not rendered.
  std::uint32_t Occlusion(Enum target, bool visible) {
    const std::uint32_t q = gl.GenQuery();
    gl.Enable(DEPTH_TEST);
    gl.Clear(DEPTH_BUFFER_BIT);
    gl.ColorMask(false, false, false, false);
    if (!visible) gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    gl.BeginQuery(target, q);
    gl.DrawArrays(TRIANGLE_STRIP, 4, 4);
    gl.EndQuery(target);
    gl.ColorMask(true, true, true, true);
    gl.Disable(DEPTH_TEST);
    return q;
  }
  glm::u8vec4 Pixel(int x, int y) const {
    std::uint8_t p[4];
    gl.ReadPixel(x, y, p);
    return {p[0], p[1], p[2], p[3]};
  }
};

}  // namespace

TEST_CASE("conditional rendering: draws and clears are dropped when the query counted nothing", "[sync]") {
  for (int threads : {1, 3})
    for (Enum target : {SAMPLES_PASSED, ANY_SAMPLES_PASSED})
      for (Enum mode : {QUERY_WAIT, QUERY_BY_REGION_WAIT})
        for (bool visible : {false, true}) {
          INFO(threads << " threads, target " << target << ", mode " << mode << ", visible " << visible);
          Scene s(threads);
          s.gl.ClearColor(0, 0, 1, 1);
          s.gl.Clear(COLOR_BUFFER_BIT);
          const std::uint32_t q = s.Occlusion(target, visible);
          s.gl.BeginConditionalRender(q, mode);
          s.shader.color = {1, 0, 0, 1};
          s.gl.DrawArrays(TRIANGLE_STRIP, 4, 4);  // left half red
          s.gl.ClearColor(0, 1, 0, 1);
          s.gl.Enable(SCISSOR_TEST);
          s.gl.Scissor(16, 0, 16, 32);
          s.gl.Clear(COLOR_BUFFER_BIT);  // right half green
          const float white[4] = {1, 1, 1, 1};
          s.gl.Scissor(16, 0, 16, 8);
          s.gl.ClearBufferfv(COLOR, 0, white);  // the right half's bottom white
          s.gl.Disable(SCISSOR_TEST);
          s.gl.EndConditionalRender();
          s.shader.color = {1, 1, 0, 1};
          s.gl.Enable(SCISSOR_TEST);
          s.gl.Scissor(0, 24, 32, 8);
          s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);  // after the end: the top rows yellow, always
          s.gl.Disable(SCISSOR_TEST);
          CHECK(s.gl.GetError() == NO_ERROR);
          const glm::u8vec4 blue(0, 0, 255, 255), red(255, 0, 0, 255), green(0, 255, 0, 255), yellow(255, 255, 0, 255);
          CHECK(s.Pixel(4, 12) == (visible ? red : blue));
          CHECK(s.Pixel(24, 12) == (visible ? green : blue));
          CHECK(s.Pixel(24, 2) == (visible ? glm::u8vec4(255) : blue));
          CHECK(s.Pixel(4, 28) == yellow);
          CHECK(s.Pixel(24, 28) == yellow);
        }
}

TEST_CASE("conditional rendering without waiting: the result once rendered, else everything is drawn", "[sync]") {
  for (Enum mode : {QUERY_NO_WAIT, QUERY_BY_REGION_NO_WAIT}) {
    INFO("mode " << mode);
    Scene s;
    s.shader.color = {1, 0, 0, 1};
    // The query's draws are still recorded: the result is not waited for, so the draw is made.
    std::uint32_t q = s.Occlusion(SAMPLES_PASSED, false);
    s.gl.BeginConditionalRender(q, mode);
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    s.gl.EndConditionalRender();
    CHECK(s.Pixel(8, 8) == glm::u8vec4(255, 0, 0, 255));
    // Rendered (Finish) before: the result is known, and the draw is dropped.
    s.gl.ClearColor(0, 0, 0, 0);
    s.gl.Clear(COLOR_BUFFER_BIT);
    q = s.Occlusion(SAMPLES_PASSED, false);
    s.gl.Finish();
    s.gl.BeginConditionalRender(q, mode);
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    s.gl.EndConditionalRender();
    CHECK(s.Pixel(8, 8) == glm::u8vec4(0, 0, 0, 0));
    // The result of a query that passed, once rendered: drawn.
    q = s.Occlusion(ANY_SAMPLES_PASSED, true);
    std::uint32_t any = 0;
    s.gl.GetQueryObjectuiv(q, QUERY_RESULT, &any);
    CHECK(any == 1);
    s.gl.BeginConditionalRender(q, mode);
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    s.gl.EndConditionalRender();
    CHECK(s.Pixel(8, 8) == glm::u8vec4(255, 0, 0, 255));
    CHECK(s.gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("conditional rendering: the result is taken at Begin, dropped draws generate no primitives", "[sync]") {
  Scene s;
  const std::uint32_t q = s.Occlusion(SAMPLES_PASSED, false);
  const std::uint32_t prims = s.gl.GenQuery();
  s.gl.BeginConditionalRender(q, QUERY_WAIT);
  s.gl.BeginQuery(PRIMITIVES_GENERATED, prims);
  s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  s.gl.EndConditionalRender();
  s.gl.BeginQuery(PRIMITIVES_GENERATED, prims);
  s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  std::uint32_t n = 99;
  s.gl.GetQueryObjectuiv(prims, QUERY_RESULT, &n);
  CHECK(n == 2);  // the second run only
  // Deleting the query while conditional rendering is on changes nothing until the end.
  s.gl.Clear(COLOR_BUFFER_BIT);
  s.gl.BeginConditionalRender(q, QUERY_WAIT);
  s.gl.DeleteQuery(q);
  s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  s.gl.EndConditionalRender();
  CHECK(s.Pixel(8, 8) == glm::u8vec4(0, 0, 0, 0));
  s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
  CHECK(s.Pixel(8, 8) == glm::u8vec4(255));
  CHECK(s.gl.GetError() == NO_ERROR);
}

TEST_CASE("conditional rendering: the errors", "[sync][errors]") {
  Scene s;
  const std::uint32_t q = s.Occlusion(SAMPLES_PASSED, true);
  s.gl.BeginConditionalRender(q, QUERY_RESULT);
  CHECK(s.gl.GetError() == INVALID_ENUM);
  s.gl.BeginConditionalRender(q + 100, QUERY_WAIT);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.BeginConditionalRender(0, QUERY_WAIT);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  const std::uint32_t fresh = s.gl.GenQuery();  // never begun
  s.gl.BeginConditionalRender(fresh, QUERY_WAIT);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.BeginQuery(PRIMITIVES_GENERATED, fresh);  // another target
  s.gl.EndQuery(PRIMITIVES_GENERATED);
  s.gl.BeginConditionalRender(fresh, QUERY_WAIT);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  const std::uint32_t active = s.gl.GenQuery();
  s.gl.BeginQuery(SAMPLES_PASSED, active);
  s.gl.BeginConditionalRender(active, QUERY_WAIT);
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.EndQuery(SAMPLES_PASSED);
  s.gl.EndConditionalRender();  // not on
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.BeginConditionalRender(q, QUERY_WAIT);
  CHECK(s.gl.GetError() == NO_ERROR);
  s.gl.BeginConditionalRender(q, QUERY_WAIT);  // already on
  CHECK(s.gl.GetError() == INVALID_OPERATION);
  s.gl.EndConditionalRender();
  CHECK(s.gl.GetError() == NO_ERROR);
}

TEST_CASE("fences are signalled once the work before them has been rendered", "[sync]") {
  for (int threads : {1, 3}) {
    INFO(threads << " threads");
    Scene s(threads);
    Sync idle = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);  // nothing recorded: signalled at once
    REQUIRE(idle != nullptr);
    CHECK(s.gl.IsSync(idle));
    CHECK(s.gl.ClientWaitSync(idle, 0, 0) == ALREADY_SIGNALED);

    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    Sync a = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);
    int status = 0, length = -1;
    s.gl.GetSynciv(a, SYNC_STATUS, 1, &length, &status);
    CHECK(status == int(UNSIGNALED));
    CHECK(length == 1);
    CHECK(s.gl.ClientWaitSync(a, 0, 0) == TIMEOUT_EXPIRED);  // a poll renders nothing
    CHECK(s.gl.ClientWaitSync(a, 0, 0) == TIMEOUT_EXPIRED);
    CHECK(s.gl.ClientWaitSync(a, 0, 1000000000) == CONDITION_SATISFIED);  // a wait renders
    CHECK(s.gl.ClientWaitSync(a, 0, 0) == ALREADY_SIGNALED);
    s.gl.GetSynciv(a, SYNC_STATUS, 1, nullptr, &status);
    CHECK(status == int(SIGNALED));

    // A poll with SYNC_FLUSH_COMMANDS_BIT renders, so a polling loop ends; so do Finish and reads.
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    Sync b = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    Sync c = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);
    int polls = 0;
    while (s.gl.ClientWaitSync(b, SYNC_FLUSH_COMMANDS_BIT, 0) == TIMEOUT_EXPIRED) ++polls;
    CHECK(polls == 1);
    CHECK(s.gl.ClientWaitSync(c, 0, 0) == ALREADY_SIGNALED);  // (rendered with b's work)
    s.gl.DrawArrays(TRIANGLE_STRIP, 0, 4);
    Sync d = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);
    (void)s.Pixel(0, 0);
    CHECK(s.gl.ClientWaitSync(d, 0, 0) == ALREADY_SIGNALED);
    s.gl.WaitSync(d, 0, TIMEOUT_IGNORED);

    int values[2] = {0, 0};
    s.gl.GetSynciv(d, OBJECT_TYPE, 2, &length, values);
    CHECK(values[0] == int(SYNC_FENCE));
    CHECK(length == 1);
    s.gl.GetSynciv(d, SYNC_CONDITION, 1, nullptr, values);
    CHECK(values[0] == int(SYNC_GPU_COMMANDS_COMPLETE));
    values[0] = 7;
    s.gl.GetSynciv(d, SYNC_FLAGS, 1, nullptr, values);
    CHECK(values[0] == 0);
    values[0] = 7;
    s.gl.GetSynciv(d, SYNC_FLAGS, 0, &length, values);  // bufSize 0: nothing written
    CHECK(values[0] == 7);
    CHECK(length == 0);
    int timeout = -1;
    s.gl.GetIntegerv(MAX_SERVER_WAIT_TIMEOUT, &timeout);
    CHECK(timeout == 0);
    CHECK(s.gl.GetError() == NO_ERROR);
    for (Sync f : {idle, a, b, c, d}) s.gl.DeleteSync(f);
    CHECK_FALSE(s.gl.IsSync(a));
    CHECK(s.gl.GetError() == NO_ERROR);
  }
}

TEST_CASE("sync objects: the errors", "[sync][errors]") {
  Scene s;
  CHECK(s.gl.FenceSync(SYNC_FENCE, 0) == nullptr);
  CHECK(s.gl.GetError() == INVALID_ENUM);
  CHECK(s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 1) == nullptr);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  Sync f = s.gl.FenceSync(SYNC_GPU_COMMANDS_COMPLETE, 0);
  // A handle that is not a fence is never read through: an address of something else, and a deleted fence.
  int local = 0;
  Sync bogus = reinterpret_cast<Sync>(&local);
  CHECK_FALSE(s.gl.IsSync(bogus));
  CHECK_FALSE(s.gl.IsSync(nullptr));
  CHECK(s.gl.ClientWaitSync(bogus, 0, 0) == WAIT_FAILED);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  CHECK(s.gl.ClientWaitSync(f, 2, 0) == WAIT_FAILED);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.WaitSync(bogus, 0, TIMEOUT_IGNORED);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.WaitSync(f, 1, TIMEOUT_IGNORED);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.WaitSync(f, 0, 0);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  int v = 5;
  s.gl.GetSynciv(bogus, SYNC_STATUS, 1, nullptr, &v);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.GetSynciv(f, QUERY_RESULT, 1, nullptr, &v);
  CHECK(s.gl.GetError() == INVALID_ENUM);
  s.gl.GetSynciv(f, SYNC_STATUS, -1, nullptr, &v);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.GetSynciv(f, SYNC_STATUS, 1, nullptr, nullptr);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  CHECK(v == 5);
  s.gl.DeleteSync(bogus);
  CHECK(s.gl.GetError() == INVALID_VALUE);
  s.gl.DeleteSync(nullptr);  // ignored
  CHECK(s.gl.GetError() == NO_ERROR);
  s.gl.DeleteSync(f);
  s.gl.DeleteSync(f);  // deleted already
  CHECK(s.gl.GetError() == INVALID_VALUE);
  CHECK(s.gl.ClientWaitSync(f, 0, 0) == WAIT_FAILED);
  CHECK(s.gl.GetError() == INVALID_VALUE);
}

TEST_CASE("ClampColor: reads of a float buffer clamped to [0, 1] when asked, as stored otherwise", "[sync]") {
  Context gl(4, 4);
  const std::uint32_t fbo = gl.GenFramebuffer(), rb = gl.GenRenderbuffer();
  gl.BindRenderbuffer(RENDERBUFFER, rb);
  gl.RenderbufferStorage(RENDERBUFFER, RGBA32F, 4, 4);
  gl.BindFramebuffer(FRAMEBUFFER, fbo);
  gl.FramebufferRenderbuffer(FRAMEBUFFER, COLOR_ATTACHMENT0, RENDERBUFFER, rb);
  const float value[4] = {2.5f, -0.75f, 0.25f, std::numeric_limits<float>::quiet_NaN()};
  gl.ClearBufferfv(COLOR, 0, value);
  int clamp = -1;
  gl.GetIntegerv(CLAMP_READ_COLOR, &clamp);
  CHECK(clamp == int(FIXED_ONLY));
  float f[4];
  std::uint8_t b[4];
  short sh[4];
  gl.ReadPixels(1, 1, 1, 1, RGBA, FLOAT, f);  // FIXED_ONLY: a float buffer reads as stored
  CHECK(f[0] == 2.5f);
  CHECK(f[1] == -0.75f);
  CHECK(std::isnan(f[3]));
  gl.ReadPixels(1, 1, 1, 1, RGBA, SHORT, sh);  // (the signed type's own clamp to [-1, 1])
  CHECK(sh[1] == -24575);
  gl.ClampColor(CLAMP_READ_COLOR, 1);
  gl.GetIntegerv(CLAMP_READ_COLOR, &clamp);
  CHECK(clamp == 1);
  gl.ReadPixels(1, 1, 1, 1, RGBA, FLOAT, f);
  CHECK(f[0] == 1.0f);
  CHECK(f[1] == 0.0f);
  CHECK(f[2] == 0.25f);
  CHECK(f[3] == 0.0f);
  gl.ReadPixels(1, 1, 1, 1, RGBA, SHORT, sh);
  CHECK(sh[0] == 32767);
  CHECK(sh[1] == 0);
  gl.ReadPixels(1, 1, 1, 1, RGBA, UNSIGNED_BYTE, b);
  CHECK(b[0] == 255);
  CHECK(b[2] == 64);
  gl.ClampColor(CLAMP_READ_COLOR, 0);
  gl.ReadPixels(1, 1, 1, 1, RGBA, FLOAT, f);
  CHECK(f[0] == 2.5f);
  CHECK(gl.GetError() == NO_ERROR);
  gl.ClampColor(CLAMP_READ_COLOR, 2);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.ClampColor(CLAMP_TO_EDGE, 1);
  CHECK(gl.GetError() == INVALID_ENUM);
  gl.GetIntegerv(CLAMP_READ_COLOR, &clamp);
  CHECK(clamp == 0);
}

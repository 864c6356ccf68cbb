// scenes_tour.cpp — the pictures of docs/tour.md: each stage of the pipeline made visible by a shader, drawn
// through the public API like any other scene.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene_kit.h"
#include "scenes.h"

namespace scenes {

using namespace kit;
using softgl::Bool;
using softgl::Int;

namespace {

// ---- Helpers shared by the pictures --------------------------------------------------------------------------

// A new vertex array (left bound) of interleaved floats, `sizes[i]` of them for attribute i, and, when given, an
// element buffer of unsigned bytes.
void BindInterleaved(softgl::Context& gl, const std::vector<float>& v, std::initializer_list<int> sizes,
                     const std::vector<std::uint8_t>& indices = {}) {
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(v.size() * sizeof(float)), v.data());
  int stride = 0;
  for (int n : sizes) stride += n;
  std::uint32_t attribute = 0;
  std::size_t offset = 0;
  for (int n : sizes) {
    gl.VertexAttributePointer(attribute, n, softgl::FLOAT, false, stride * int(sizeof(float)), offset * sizeof(float));
    gl.EnableVertexAttribArray(attribute++);
    offset += std::size_t(n);
  }
  if (!indices.empty()) {
    gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size()), indices.data());
  }
}

// Vertices of x, y, z, r, g, b, drawn with ColorShader (attribute 0 position, 1 colour) through `mvp`.
void DrawColored(softgl::Context& gl, const glm::mat4& mvp, softgl::Enum mode, const std::vector<float>& v) {
  BindInterleaved(gl, v, {3, 3});
  ColorShader shader;
  shader.mvp = mvp;
  gl.UseProgram(shader);
  gl.DrawArrays(mode, 0, int(v.size() / 6));
}

void Push(std::vector<float>& v, glm::vec3 p, glm::vec3 c) { v.insert(v.end(), {p.x, p.y, p.z, c.x, c.y, c.z}); }

// An image as a texture, rows flipped to OpenGL's order (row 0 at the bottom), sampled NEAREST.
std::uint32_t UploadImage(softgl::Context& gl, const softgl::Image& image) {
  std::vector<std::uint8_t> rows(image.rgba.size());
  const std::size_t row = std::size_t(image.width) * 4;
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.rgba.begin() + std::ptrdiff_t(std::size_t(image.height - 1 - y) * row), row,
                rows.begin() + std::ptrdiff_t(std::size_t(y) * row));
  const std::uint32_t tex = gl.GenTexture();
  gl.BindTexture(softgl::TEXTURE_2D, tex);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, image.width, image.height, 0, softgl::RGBA,
                softgl::UNSIGNED_BYTE, rows.data());
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, softgl::NEAREST);
  return tex;
}

struct NoVaryings {};

// A small image magnified `scale` times: each texel a square with a grey border, its centre marked by a dot
// (black on a drawn pixel, grey on the background, which is `background`), and, with `diamonds`, the diamond
// |x - xc| + |y - yc| < 1/2 that the line rule uses. Reads texture unit 0 by texelFetch at gl_FragCoord / scale.
struct PixelGridShader : softgl::Shader<PixelGridShader, NoVaryings> {
  float scale = 32.0f;
  glm::vec3 background{1.0f};
  bool diamonds = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVaryings>& in, FragmentLanesOut& out) const {
    const vec2 p = vec2(in.frag_coord.x, in.frag_coord.y) / scale;  // in pixels of the small image
    const vec2 cell = floor(p), f = p - cell;
    const vec4 texel = in.TexelFetch(0, Int(cell.x), Int(cell.y));
    const Bool empty = abs(texel.x - background.x) + abs(texel.y - background.y) + abs(texel.z - background.z) < 0.01f;
    vec3 c = vec3(texel);
    if (diamonds) {
      const Float d = abs(f.x - 0.5f) + abs(f.y - 0.5f);
      c = select(abs(d - 0.5f) * scale < 0.6f, mix(c, vec3(0.45f), Float(0.6f)), c);
    }
    const Float edge = min(min(f.x, f.y), min(1.0f - f.x, 1.0f - f.y)) * scale;
    c = select(edge < 0.75f, vec3(0.55f), c);
    const Float centre = length(f - 0.5f) * scale;
    c = select(centre < 2.6f, select(empty, vec3(0.62f), vec3(0.0f)), c);
    out.color[0] = vec4(c, 1.0f);
  }
};

// Draws `small` magnified into the whole of `gl`'s framebuffer (its size times scale).
void DrawMagnified(softgl::Context& gl, const softgl::Image& small, float scale, glm::vec3 background,
                   bool diamonds = false) {
  gl.ActiveTexture(softgl::TEXTURE0);
  UploadImage(gl, small);
  MakeScreenTriangle(gl);
  PixelGridShader grid;
  grid.scale = scale;
  grid.background = background;
  grid.diamonds = diamonds;
  gl.UseProgram(grid);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
}

// The projection that maps window coordinates of a w x h framebuffer onto clip space: geometry given in the small
// image's pixels lands on the magnified picture of it.
glm::mat4 PixelSpace(int w, int h) { return glm::ortho(0.0f, float(w), 0.0f, float(h), -1.0f, 1.0f); }

}  // namespace

// ---- 1. Clipping ----------------------------------------------------------------------------------------------

namespace {

// The diagram's floor triangle, coloured by what near-plane clipping keeps: a fragment at eye-space position p is
// kept when its clip-space z >= -w under the camera's projection (the inequality the clipper tests at vertices).
struct ClipVaryings {
  vec3 eye;
};
struct NearPlaneShader : softgl::Shader<NearPlaneShader, ClipVaryings> {
  glm::mat4 mvp{1.0f};          // how the picture is drawn
  glm::mat4 projection{1.0f};   // the camera whose near plane clips
  bool checks = false;          // checks on the floor (the camera's view)
  void Vertex(const VertexLanes& in, VertexLanesOut<ClipVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.eye = vec3(in.attrib[0]);
  }
  void Fragment(const FragmentLanes<ClipVaryings>& in, FragmentLanesOut& out) const {
    const vec4 clip = projection * vec4(in.varyings.eye, 1.0f);
    const Bool kept = clip.z >= -clip.w;
    vec3 c = select(kept, vec3(glm::vec3(0.25f, 0.5f, 0.95f)), vec3(glm::vec3(0.95f, 0.3f, 0.25f)));
    if (checks) {
      const Int cells = Int(floor(in.varyings.eye.x * 2.0f)) + Int(floor(in.varyings.eye.z * 2.0f));
      c = select((cells & 1) != 0, c * 0.75f, c);
    }
    out.color[0] = vec4(c, 1.0f);
  }
};

}  // namespace

softgl::Image TourClipping(int width, int height) {
  softgl::Context gl(width, height);
  const int half = width / 2;
  // The camera at the origin looking down -z, 90 degrees wide, near plane at 1; a floor triangle 0.6 below the
  // eye with one corner behind the camera.
  const glm::mat4 projection = glm::perspective(glm::radians(90.0f), float(half) / float(height), 1.0f, 20.0f);
  const glm::vec3 a(-3.0f, -0.6f, -6.0f), b(2.5f, -0.6f, -5.0f), c(-0.2f, -0.6f, 0.8f);
  const std::vector<float> floor_tri = {a.x, a.y, a.z, 0, 0, 0, b.x, b.y, b.z, 0, 0, 0, c.x, c.y, c.z, 0, 0, 0};

  // Sutherland-Hodgman against the near plane, as the clipper does it: each vertex's distance d = z + w in clip
  // space, and a new vertex at t = d0 / (d0 - d1) on every edge whose ends have opposite signs.
  const glm::vec3 corners[3] = {a, b, c};
  std::vector<glm::vec3> kept;
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 p = corners[i], q = corners[(i + 1) % 3];
    const glm::vec4 cp = projection * glm::vec4(p, 1.0f), cq = projection * glm::vec4(q, 1.0f);
    const float dp = cp.z + cp.w, dq = cq.z + cq.w;
    if (dp >= 0.0f) kept.push_back(p);
    if ((dp >= 0.0f) != (dq >= 0.0f)) kept.push_back(p + (q - p) * (dp / (dp - dq)));
  }

  gl.ClearColor(0.08f, 0.09f, 0.12f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.PointSize(7.0f);

  // Left: the scene from above (eye-space x to the right, -z up), the view volume's side planes, near and far.
  gl.Viewport(0, 0, half, height);
  const float aspect = float(half) / float(height);
  const glm::mat4 top = glm::ortho(-4.5f * aspect, 4.5f * aspect, -2.5f, 6.5f, -10.0f, 10.0f) *
                        glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, -1, 0, 0),
                                  glm::vec4(0, 0, 0, 1));  // (x, y, z) -> (x, -z, -y)
  NearPlaneShader diagram;
  diagram.mvp = top;
  diagram.projection = projection;
  BindInterleaved(gl, floor_tri, {3, 3});
  gl.UseProgram(diagram);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  const float far_half = 7.0f * std::tan(glm::radians(45.0f)) * aspect;  // the side planes at z = -7
  const float near_half = std::tan(glm::radians(45.0f)) * aspect;
  std::vector<float> lines;
  const glm::vec3 grey(0.6f), yellow(1.0f, 0.85f, 0.2f), white(1.0f);
  Push(lines, {0, 0, 0}, grey), Push(lines, {-far_half, 0, -7}, grey);
  Push(lines, {0, 0, 0}, grey), Push(lines, {far_half, 0, -7}, grey);
  Push(lines, {-near_half * 2.0f, 0, -1}, yellow), Push(lines, {near_half * 2.0f, 0, -1}, yellow);  // near plane
  for (std::size_t i = 0; i < kept.size(); ++i)  // the polygon the clipper keeps
    Push(lines, kept[i], white), Push(lines, kept[(i + 1) % kept.size()], white);
  DrawColored(gl, top, softgl::LINES, lines);
  std::vector<float> points;
  Push(points, {0, 0, 0}, yellow);  // the eye
  for (const glm::vec3& p : kept) Push(points, p, white);
  Push(points, c, glm::vec3(0.95f, 0.3f, 0.25f));  // the corner clipping removes
  DrawColored(gl, top, softgl::POINTS, points);

  // Right: what the camera sees: the part of the triangle in front of the near plane, checked per fragment, and
  // the kept polygon's corners (the two new ones lie on the near plane, at the bottom of the picture).
  gl.Viewport(half, 0, width - half, height);
  const glm::mat4 camera = projection;
  NearPlaneShader view = diagram;
  view.mvp = camera;
  view.checks = true;
  BindInterleaved(gl, floor_tri, {3, 3});
  gl.UseProgram(view);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  points.clear();
  for (const glm::vec3& p : kept) Push(points, p + glm::vec3(0.0f, 0.0f, -0.02f), white);  // (just inside)
  DrawColored(gl, camera, softgl::POINTS, points);
  return gl.ReadPixels();
}

// ---- 2. Coverage and the tie rule -----------------------------------------------------------------------------

namespace {

constexpr int kGridW = 20, kGridH = 10;

// Four triangles around a shared corner, whose shared edges run through pixel centres (window coordinates of a
// 20 x 10 framebuffer).
std::vector<float> CoverageFan() {
  const glm::vec3 centre(9.5f, 4.5f, 0), left(1.5f, 4.5f, 0), up(13.5f, 8.5f, 0), right(18.5f, 4.5f, 0),
      down(5.5f, 0.5f, 0), top_left(4.2f, 9.6f, 0);
  const glm::vec3 red(0.9f, 0.2f, 0.2f), green(0.2f, 0.75f, 0.25f), blue(0.2f, 0.35f, 0.9f), gold(0.85f, 0.65f, 0.1f);
  std::vector<float> v;
  Push(v, left, red), Push(v, centre, red), Push(v, up, red);
  Push(v, centre, green), Push(v, right, green), Push(v, up, green);
  Push(v, left, blue), Push(v, down, blue), Push(v, centre, blue);
  Push(v, down, gold), Push(v, right, gold), Push(v, centre, gold);
  Push(v, left, red * 0.6f), Push(v, up, red * 0.6f), Push(v, top_left, red * 0.6f);
  return v;
}

std::vector<float> EdgesOf(const std::vector<float>& triangles, glm::vec3 colour) {
  std::vector<float> lines;
  for (std::size_t t = 0; t + 18 <= triangles.size(); t += 18)
    for (int k = 0; k < 3; ++k) {
      const float* p = &triangles[t + std::size_t(k) * 6];
      const float* q = &triangles[t + std::size_t((k + 1) % 3) * 6];
      Push(lines, {p[0], p[1], 0}, colour), Push(lines, {q[0], q[1], 0}, colour);
    }
  return lines;
}

}  // namespace

softgl::Image TourCoverage(int width, int height) {
  // The triangles into a 20 x 10 framebuffer, added (ONE, ONE): a pixel two triangles both took would show their
  // sum; the tie rule gives every pixel centre on a shared edge to exactly one of them.
  softgl::Context small(kGridW, kGridH);
  small.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);  // (the triangles add onto black; the black left is made white)
  small.Clear(softgl::COLOR_BUFFER_BIT);
  small.Enable(softgl::BLEND);
  small.BlendFunc(softgl::ONE, softgl::ONE);
  const std::vector<float> fan = CoverageFan();
  DrawColored(small, PixelSpace(kGridW, kGridH), softgl::TRIANGLES, fan);
  softgl::Image pixels = small.ReadPixels();
  for (std::size_t i = 0; i < pixels.rgba.size(); i += 4)
    if (pixels.rgba[i] == 0 && pixels.rgba[i + 1] == 0 && pixels.rgba[i + 2] == 0)
      pixels.rgba[i] = pixels.rgba[i + 1] = pixels.rgba[i + 2] = 255;

  softgl::Context gl(width, height);
  DrawMagnified(gl, pixels, float(width) / float(kGridW), glm::vec3(1.0f));
  DrawColored(gl, PixelSpace(kGridW, kGridH), softgl::LINES, EdgesOf(fan, glm::vec3(0.1f)));
  return gl.ReadPixels();
}

// ---- 3. Barycentric weights -----------------------------------------------------------------------------------

namespace {

struct BaryVaryings {
  vec3 smooth_weights;                       // perspective-correct
  softgl::NoPerspective<vec3> screen_weights;  // linear in window space
};

// The weights of the three corners as red, green and blue, with a dark line every 0.1 of each weight.
struct BarycentricShader : softgl::Shader<BarycentricShader, BaryVaryings> {
  glm::mat4 mvp{1.0f};
  bool perspective = true;
  void Vertex(const VertexLanes& in, VertexLanesOut<BaryVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.smooth_weights = vec3(in.attrib[1]);
    out.varyings.screen_weights = vec3(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<BaryVaryings>& in, FragmentLanesOut& out) const {
    const vec3 w = perspective ? in.varyings.smooth_weights : vec3(in.varyings.screen_weights);
    Float line = 1.0f;
    for (const Float& x : {w.x, w.y, w.z}) {
      const Float f = fract(x * 10.0f + 0.5f) - 0.5f;  // distance to the nearest multiple of 0.1, in tenths
      line = min(line, abs(f) / max(fwidth(x * 10.0f), 1e-6f));
    }
    const vec3 c = w * 0.85f + 0.1f;
    out.color[0] = vec4(select(line < 0.8f, c * 0.35f, c), 1.0f);
  }
};

}  // namespace

softgl::Image TourBarycentric(int width, int height) {
  softgl::Context gl(width, height);
  gl.ClearColor(0.95f, 0.95f, 0.95f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  const int half = width / 2;
  const glm::mat4 proj = Projection(half, height, 50.0f, 0.1f, 50.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.8f, 2.6f), glm::vec3(0.0f, 0.0f, -1.8f), glm::vec3(0, 1, 0));
  // A triangle lying on the ground, its far corner 7 units away and its near ones 1.5.
  std::vector<float> tri;
  Push(tri, {-1.3f, 0, -0.3f}, {1, 0, 0}), Push(tri, {1.3f, 0, -0.3f}, {0, 1, 0}), Push(tri, {0.0f, 0, -6.0f}, {0, 0, 1});
  BindInterleaved(gl, tri, {3, 3});
  BarycentricShader shader;
  shader.mvp = proj * view;
  for (int side = 0; side < 2; ++side) {  // left: in window space; right: perspective-correct
    gl.Viewport(side * half, 0, half, height);
    shader.perspective = side == 1;
    gl.UseProgram(shader);
    gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  }
  return gl.ReadPixels();
}

// ---- The viewport ----------------------------------------------------------------------------------------------

softgl::Image TourViewport(int width, int height) {
  // The same drawing in normalized device coordinates (the square [-1, 1]^2 with grid lines every 0.25, its axes,
  // and the README's triangle) through three viewports: a square one, a wide one and a tall one.
  softgl::Context gl(width, height);
  gl.ClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  std::vector<float> triangle;
  Push(triangle, {-0.8f, -0.7f, 0}, {1, 0, 0}), Push(triangle, {0.8f, -0.7f, 0}, {0, 1, 0});
  Push(triangle, {0.0f, 0.8f, 0}, {0, 0, 1});
  const int rects[3][4] = {{16, 16, height - 32, height - 32},
                           {height + 8, height / 2 + 8, width - height - 24, height / 2 - 24},
                           {height + 8, 16, (width - height) / 3, height / 2 - 24}};
  for (const auto& v : rects) {
    // The border of [-1, 1]^2 (yellow) drawn half a pixel inside, where the pixel centres of its edge rows are.
    const float ix = 1.0f - 1.0f / float(v[2]), iy = 1.0f - 1.0f / float(v[3]);
    std::vector<float> lines;
    for (int k = -4; k <= 4; ++k) {
      const float t = float(k) * 0.25f, tx = k == -4 || k == 4 ? t * ix : t, ty = k == -4 || k == 4 ? t * iy : t;
      const glm::vec3 c = k == 0 ? glm::vec3(0.9f) : k == -4 || k == 4 ? glm::vec3(0.95f, 0.85f, 0.2f) : glm::vec3(0.35f);
      Push(lines, {tx, -1, 0}, c), Push(lines, {tx, 1, 0}, c);
      Push(lines, {-1, ty, 0}, c), Push(lines, {1, ty, 0}, c);
    }
    gl.Viewport(v[0], v[1], v[2], v[3]);
    DrawColored(gl, glm::mat4(1.0f), softgl::TRIANGLES, triangle);
    DrawColored(gl, glm::mat4(1.0f), softgl::LINES, lines);
  }
  return gl.ReadPixels();
}

// ---- 4. The depth buffer --------------------------------------------------------------------------------------

namespace {

struct ShowDepthShader : softgl::Shader<ShowDepthShader, NoVaryings> {
  int mode = 0;  // 0: the colour texture (unit 0), 1: window depth as stored, 2: eye depth from it
  int left = 0;  // the panel's first column
  float near_plane = 1.0f, far_plane = 10.0f;
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVaryings>& in, FragmentLanesOut& out) const {
    const Int x = Int(in.frag_coord.x) - left, y = Int(in.frag_coord.y);
    if (mode == 0) {
      out.color[0] = in.TexelFetch(0, x, y);
      return;
    }
    const Float d = in.TexelFetch(1, x, y).x;  // window z in [0, 1]
    if (mode == 1) {
      out.color[0] = vec4(vec3(d), 1.0f);
      return;
    }
    // Undo the projection: z_ndc = 2 d - 1, eye distance n f / (f - z_ndc (f - n)) ... written for depth range
    // [0, 1]: n f / (f - d (f - n)).
    const Float eye = near_plane * far_plane / (far_plane - d * (far_plane - near_plane));
    const Float t = clamp((eye - near_plane) / (far_plane - near_plane), 0.0f, 1.0f);
    out.color[0] = vec4(vec3(t), 1.0f);
  }
};

}  // namespace

softgl::Image TourDepth(int width, int height) {
  softgl::Context gl(width, height);
  const int third = width / 3;
  const float near_plane = 1.0f, far_plane = 12.0f;
  // The scene into a framebuffer object of a colour texture and a DEPTH_COMPONENT32F texture.
  const std::uint32_t fbo = gl.GenFramebuffer(), colour = gl.GenTexture(), depth = gl.GenTexture();
  gl.ActiveTexture(softgl::TEXTURE0);
  gl.BindTexture(softgl::TEXTURE_2D, colour);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, third, height, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);  // (one level: complete)
  gl.ActiveTexture(softgl::TEXTURE0 + 1);
  gl.BindTexture(softgl::TEXTURE_2D, depth);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::DEPTH_COMPONENT32F, third, height, 0, softgl::DEPTH_COMPONENT,
                softgl::FLOAT, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, colour, 0);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::TEXTURE_2D, depth, 0);
  gl.Viewport(0, 0, third, height);
  gl.Enable(softgl::DEPTH_TEST);
  gl.ClearColor(0.55f, 0.7f, 0.9f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const glm::mat4 proj = Projection(third, height, 60.0f, near_plane, far_plane);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 2.0f, 3.5f), glm::vec3(0.0f, 0.3f, -2.0f), glm::vec3(0, 1, 0));
  LitShader lit;
  const std::uint8_t floor_colour[4] = {200, 190, 160, 255};
  const Mesh meshes[] = {MakeQuad(6.0f, floor_colour), MakeTorus(48, 24, 0.8f, 0.3f), MakeCube(), MakeSphere(32, 16, 0.7f)};
  const glm::mat4 models[] = {
      glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -2.0f)),
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-0.9f, 0.6f, 0.2f)), 1.1f, glm::vec3(1, 0, 0.3f)),
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, 0.5f, -1.5f)), 0.6f, glm::vec3(0, 1, 0)),
      glm::translate(glm::mat4(1.0f), glm::vec3(-0.4f, 0.7f, -5.0f))};
  for (int i = 0; i < 4; ++i) {
    UploadLitMesh(gl, meshes[i]);
    lit.model = models[i];
    lit.mvp = proj * view * models[i];
    gl.UseProgram(lit);
    DrawMesh(gl, meshes[i]);
  }
  // The three panels: colour, the depth buffer as stored, and eye distance recovered from it.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.Disable(softgl::DEPTH_TEST);
  MakeScreenTriangle(gl);
  ShowDepthShader show;
  show.near_plane = near_plane;
  show.far_plane = far_plane;
  for (int panel = 0; panel < 3; ++panel) {
    gl.Viewport(panel * third, 0, third, height);
    show.mode = panel;
    show.left = panel * third;
    gl.UseProgram(show);
    gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  }
  return gl.ReadPixels();
}

// ---- 5. Affine versus perspective-correct ---------------------------------------------------------------------

namespace {

struct UvVaryings {
  vec2 uv;                                 // perspective-correct
  softgl::NoPerspective<vec2> affine_uv;   // linear in window space
};

struct UvShader : softgl::Shader<UvShader, UvVaryings> {
  glm::mat4 mvp{1.0f};
  bool perspective = true;
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = vec2(in.attrib[1]);
    out.varyings.affine_uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    const vec2 uv = perspective ? in.varyings.uv : vec2(in.varyings.affine_uv);
    out.color[0] = in.Texture(0, uv);
  }
};

}  // namespace

softgl::Image TourPerspective(int width, int height) {
  softgl::Context gl(width, height);
  gl.ClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  // An 8 x 8 checkerboard with a stripe along the diagonal from (0, 1) to (1, 0), mipmapped.
  constexpr int kN = 128;
  std::vector<std::uint8_t> px(std::size_t(kN) * kN * 4);
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const bool dark = ((x / 16) + (y / 16)) % 2 != 0;
      std::uint8_t* p = &px[(std::size_t(y) * kN + std::size_t(x)) * 4];
      const glm::u8vec3 c = dark ? glm::u8vec3(40, 60, 110) : glm::u8vec3(235, 225, 200);
      p[0] = c.x, p[1] = c.y, p[2] = c.z, p[3] = 255;
      if (std::abs(x + y - (kN - 1)) < 3) p[0] = 220, p[1] = 60, p[2] = 40;
    }
  gl.ActiveTexture(softgl::TEXTURE0);
  gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, kN, kN, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, px.data());
  gl.GenerateMipmap(softgl::TEXTURE_2D);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
  // One square of two triangles, lying on the ground and running away from the camera.
  const std::vector<float> quad = {-1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, -6, 1, 1, -1, 0, -6, 0, 1};
  BindInterleaved(gl, quad, {3, 2}, {0, 1, 2, 0, 2, 3});
  const int half = width / 2;
  const glm::mat4 proj = Projection(half, height, 60.0f, 0.1f, 50.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.9f, 2.0f), glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(0, 1, 0));
  UvShader shader;
  shader.mvp = proj * view;
  for (int side = 0; side < 2; ++side) {  // left: affine; right: perspective-correct
    gl.Viewport(side * half, 0, half, height);
    shader.perspective = side == 1;
    gl.UseProgram(shader);
    gl.DrawElement(softgl::TRIANGLES, 6, softgl::UNSIGNED_BYTE, 0);
  }
  return gl.ReadPixels();
}

// ---- 6. Face culling ------------------------------------------------------------------------------------------

namespace {

// Front faces lit blue, back faces orange (gl_FrontFacing); the cap facing the camera cut away by discard, so
// that the inside shows where nothing culls it.
struct FacingShader : softgl::Shader<FacingShader, LitVaryings> {
  glm::mat4 mvp{1.0f};
  glm::vec3 cut_axis{0.0f, 0.0f, 1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<LitVaryings>& out) const {
    out.position = mvp * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = vec3(in.attrib[1]);
    out.varyings.color = vec3(in.attrib[0]);  // the object-space position
  }
  void Fragment(const FragmentLanes<LitVaryings>& in, FragmentLanesOut& out) const {
    const vec3 n = normalize(in.varyings.normal);
    const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.8f, 0.6f));
    const vec3 front = vec3(glm::vec3(0.3f, 0.5f, 0.95f)) * (0.3f + 0.7f * max(dot(n, light), 0.0f));
    const vec3 back = vec3(glm::vec3(0.95f, 0.55f, 0.15f)) * (0.45f + 0.55f * max(-dot(n, light), 0.0f));
    out.color[0] = vec4(in.front_facing ? front : back, 1.0f);
    out.Discard(dot(in.varyings.color, cut_axis) > 0.6f);
  }
};

}  // namespace

softgl::Image TourCulling(int width, int height) {
  softgl::Context gl(width, height);
  gl.ClearColor(0.12f, 0.12f, 0.14f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  const int half = width / 2;
  const glm::mat4 proj = Projection(half, height, 45.0f, 0.5f, 20.0f);
  const glm::vec3 eye(1.2f, 1.6f, 3.6f);
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  const Mesh sphere = MakeSphere(48, 24, 1.0f), torus = MakeTorus(48, 24, 1.0f, 0.35f);
  FacingShader shader;
  shader.cut_axis = glm::normalize(eye);
  for (int side = 0; side < 2; ++side) {  // left: no culling; right: CullFace(BACK)
    gl.Viewport(side * half, 0, half, height);
    if (side == 1) gl.Enable(softgl::CULL_FACE);
    const glm::mat4 models[2] = {glm::translate(glm::mat4(1.0f), glm::vec3(-0.55f, 0.0f, 0.4f)),
                                 glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, -0.2f, -1.0f)), 1.2f,
                                             glm::vec3(1, 0, 0))};
    const Mesh* meshes[2] = {&sphere, &torus};
    for (int i = 0; i < 2; ++i) {
      UploadLitMesh(gl, *meshes[i]);
      shader.mvp = proj * view * models[i];
      // The cut faces the camera: its axis in the object's own space.
      shader.cut_axis = glm::normalize(glm::vec3(glm::inverse(models[i]) * glm::vec4(eye, 1.0f)));
      gl.UseProgram(shader);
      DrawMesh(gl, *meshes[i]);
    }
  }
  return gl.ReadPixels();
}

// ---- 7. Tiles and binning -------------------------------------------------------------------------------------

namespace {

// The count of primitives binned to each 64 x 64 tile (unit 0: an R32F texture of one texel per tile) as a heat
// colour over the dimmed scene (unit 1), the tile's borders, and the count written in a 3 x 5 pixel font.
struct TileHeatShader : softgl::Shader<TileHeatShader, NoVaryings> {
  float most = 1.0f;  // the largest count
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  static Float Glyph(const Int& digit, const Int& gx, const Int& gy) {
    // Rows of each digit, top to bottom, 3 bits a row, as one 15-bit number.
    static constexpr int kFont[10] = {0x7B6F, 0x2C97, 0x73E7, 0x73CF, 0x5BC9, 0x79CF, 0x79EF, 0x7249, 0x7BEF, 0x7BCF};
    Int bits = kFont[0];
    for (int d = 1; d < 10; ++d) bits = select(digit == d, Int(kFont[d]), bits);
    const Int bit = (4 - gy) * 3 + (2 - gx);
    Int set = 0;
    for (int b = 0; b < 15; ++b) set = select(bit == b, (bits >> b) & 1, set);
    return select(set != 0, Float(1.0f), Float(0.0f));
  }
  void Fragment(const FragmentLanes<NoVaryings>& in, FragmentLanesOut& out) const {
    const Int px = Int(in.frag_coord.x), py = Int(in.frag_coord.y);
    const Int tx = px >> 6, ty = py >> 6, lx = px & 63, ly = py & 63;
    const Float count = in.TexelFetch(0, tx, ty).x;
    const vec3 scene = vec3(in.TexelFetch(1, px, py));
    const Float t = sqrt(clamp(count / most, 0.0f, 1.0f));
    const vec3 heat = select(count == 0.0f, vec3(0.0f),
                             mix(vec3(glm::vec3(0.1f, 0.2f, 0.8f)), vec3(glm::vec3(1.0f, 0.25f, 0.1f)), t));
    vec3 c = mix(scene * 0.55f, heat, select(count == 0.0f, Float(0.0f), Float(0.55f)));
    c = select(lx == 0 || ly == 0, vec3(0.85f), c);
    // The count, up to four digits, at the tile's top left, each font pixel 2 x 2.
    const Int gx = (lx - 3) / 2, gy = (63 - 3 - ly) / 2;  // font pixels from the top left corner
    const Int digit_at = gx / 4, in_x = gx - digit_at * 4;
    Int digits = 1;
    for (int p = 10; p <= 1000; p *= 10) digits = digits + select(count >= float(p), Int(1), Int(0));
    const Bool in_box = lx >= 3 && gy >= 0 && gy < 5 && in_x < 3 && digit_at < digits && (63 - 3 - ly) >= 0;
    Float place = 1.0f;  // 10^(digits - 1 - digit_at)
    for (int k = 1; k < 4; ++k) place = select(digits - 1 - digit_at >= k, place * 10.0f, place);
    const Int digit = Int(mod(floor(count / place), 10.0f));
    const Float ink = select(in_box, Glyph(digit, in_x, gy), Float(0.0f));
    c = mix(c, vec3(1.0f), ink);
    out.color[0] = vec4(c, 1.0f);
  }
};

}  // namespace

softgl::Image TourTiles(int width, int height) {
  softgl::Context gl(width, height);
  // The scene into a texture, counting what binning gives each tile.
  const std::uint32_t fbo = gl.GenFramebuffer(), colour = gl.GenTexture(), depth = gl.GenRenderbuffer();
  gl.ActiveTexture(softgl::TEXTURE0 + 1);
  gl.BindTexture(softgl::TEXTURE_2D, colour);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, width, height, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);  // (one level: complete)
  gl.BindRenderbuffer(softgl::RENDERBUFFER, depth);
  gl.RenderbufferStorage(softgl::RENDERBUFFER, softgl::DEPTH_COMPONENT24, width, height);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, colour, 0);
  gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::DEPTH_ATTACHMENT, softgl::RENDERBUFFER, depth);
  gl.CountTilePrimitives(true);
  gl.Enable(softgl::DEPTH_TEST);
  gl.Enable(softgl::CULL_FACE);
  gl.ClearColor(0.55f, 0.7f, 0.9f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  const glm::mat4 proj = Projection(width, height, 50.0f, 0.5f, 40.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 2.2f, 5.0f), glm::vec3(0.3f, 0.4f, 0.0f), glm::vec3(0, 1, 0));
  LitShader lit;
  const std::uint8_t floor_colour[4] = {200, 190, 160, 255};
  const Mesh meshes[] = {MakeQuad(8.0f, floor_colour), MakeTorus(96, 48, 1.0f, 0.4f), MakeSphere(24, 12, 0.6f)};
  const glm::mat4 models[] = {
      glm::mat4(1.0f),
      glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-0.7f, 1.0f, 0.0f)), 1.2f, glm::vec3(1, 0, 0.2f)),
      glm::translate(glm::mat4(1.0f), glm::vec3(1.8f, 0.6f, 0.8f))};
  for (int i = 0; i < 3; ++i) {
    UploadLitMesh(gl, meshes[i]);
    lit.model = models[i];
    lit.mvp = proj * view * models[i];
    gl.UseProgram(lit);
    DrawMesh(gl, meshes[i]);
  }
  int cols = 0, rows = 0;
  const std::vector<std::uint32_t> counts = gl.TilePrimitiveCounts(&cols, &rows);
  gl.CountTilePrimitives(false);

  // The counts as a texture of one texel a tile, then the picture.
  std::vector<float> texels(counts.begin(), counts.end());
  TileHeatShader heat;
  for (std::uint32_t n : counts) heat.most = std::max(heat.most, float(n));
  gl.ActiveTexture(softgl::TEXTURE0);
  gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::R32F, cols, rows, 0, softgl::RED, softgl::FLOAT, texels.data());
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.Disable(softgl::DEPTH_TEST);
  gl.Disable(softgl::CULL_FACE);
  MakeScreenTriangle(gl);
  gl.UseProgram(heat);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  return gl.ReadPixels();
}

// ---- 8. Mipmap levels -----------------------------------------------------------------------------------------

softgl::Image TourMipmapLevels(int width, int height) {
  softgl::Context gl(width, height);
  gl.ClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  // A 256 x 256 texture whose every level is one colour, with thin lines at its texel grid of 32.
  const glm::u8vec3 level_colours[9] = {{230, 60, 50},  {240, 150, 40}, {235, 220, 60}, {90, 200, 70}, {50, 190, 190},
                                        {60, 110, 230}, {150, 80, 220}, {220, 90, 180}, {200, 200, 200}};
  const softgl::Enum filters[3] = {softgl::NEAREST_MIPMAP_NEAREST, softgl::LINEAR_MIPMAP_LINEAR,
                                   softgl::LINEAR_MIPMAP_LINEAR};
  std::uint32_t textures[3];
  for (int t = 0; t < 3; ++t) {
    textures[t] = gl.GenTexture();
    gl.BindTexture(softgl::TEXTURE_2D, textures[t]);
    for (int level = 0, size = 256; size >= 1; ++level, size /= 2) {
      std::vector<std::uint8_t> px(std::size_t(size) * std::size_t(size) * 4);
      const glm::u8vec3 c = level_colours[level];
      for (std::size_t i = 0; i < px.size(); i += 4) px[i] = c.x, px[i + 1] = c.y, px[i + 2] = c.z, px[i + 3] = 255;
      gl.TexImage2D(softgl::TEXTURE_2D, level, softgl::RGBA8, size, size, 0, softgl::RGBA, softgl::UNSIGNED_BYTE,
                    px.data());
    }
    gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, int(filters[t]));
    if (t == 2) gl.TexParameterf(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_ANISOTROPY, 16.0f);
  }
  // The ground, 12 texture repeats deep, seen at a low angle; thirds of the picture by the scissor.
  const std::vector<float> quad = {-30, 0, 10, 0, 0, 30, 0, 10, 4, 0, 30, 0, -80, 4, 12, -30, 0, -80, 0, 12};
  BindInterleaved(gl, quad, {3, 2}, {0, 1, 2, 0, 2, 3});
  UvShader shader;
  shader.mvp = Projection(width, height, 60.0f, 0.1f, 200.0f) *
               glm::lookAt(glm::vec3(0.0f, 2.5f, 4.0f), glm::vec3(0.0f, 0.0f, -8.0f), glm::vec3(0, 1, 0));
  gl.Enable(softgl::SCISSOR_TEST);
  gl.ActiveTexture(softgl::TEXTURE0);
  for (int t = 0; t < 3; ++t) {
    gl.Scissor(t * width / 3, 0, (t + 1) * width / 3 - t * width / 3 - (t < 2 ? 2 : 0), height);
    gl.BindTexture(softgl::TEXTURE_2D, textures[t]);
    gl.UseProgram(shader);
    gl.DrawElement(softgl::TRIANGLES, 6, softgl::UNSIGNED_BYTE, 0);
  }
  return gl.ReadPixels();
}

// ---- 9. Lines: the diamond-exit rule ---------------------------------------------------------------------------

softgl::Image TourLines(int width, int height) {
  // Two copies of one segment in a 20 x 10 framebuffer: above, drawn by softgl (LINES, the diamond-exit rule);
  // below, the same end points given to the classic Bresenham loop (each end rounded to a pixel, both drawn), its
  // pixels drawn as POINTS.
  softgl::Context small(kGridW, kGridH);
  small.ClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  small.Clear(softgl::COLOR_BUFFER_BIT);
  const glm::vec2 a(1.3f, 6.2f), b(18.45f, 9.4f), down(0.0f, -5.0f);
  const glm::vec3 blue(0.2f, 0.35f, 0.9f), red(0.9f, 0.3f, 0.2f);
  std::vector<float> line;
  Push(line, {a, 0}, blue), Push(line, {b, 0}, blue);
  DrawColored(small, PixelSpace(kGridW, kGridH), softgl::LINES, line);
  std::vector<float> points;
  const glm::ivec2 p0(glm::floor(a + down)), p1(glm::floor(b + down));
  const int dx = std::abs(p1.x - p0.x), dy = -std::abs(p1.y - p0.y), sx = p0.x < p1.x ? 1 : -1, sy = p0.y < p1.y ? 1 : -1;
  int err = dx + dy;
  for (glm::ivec2 p = p0;;) {
    Push(points, {float(p.x) + 0.5f, float(p.y) + 0.5f, 0}, red);
    if (p == p1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, p.x += sx;
    if (e2 <= dx) err += dx, p.y += sy;
  }
  DrawColored(small, PixelSpace(kGridW, kGridH), softgl::POINTS, points);
  const softgl::Image pixels = small.ReadPixels();

  softgl::Context gl(width, height);
  DrawMagnified(gl, pixels, float(width) / float(kGridW), glm::vec3(1.0f), true);
  std::vector<float> segments;
  const glm::vec3 ink(0.1f);
  Push(segments, {a, 0}, ink), Push(segments, {b, 0}, ink);
  Push(segments, {a + down, 0}, ink), Push(segments, {b + down, 0}, ink);
  DrawColored(gl, PixelSpace(kGridW, kGridH), softgl::LINES, segments);
  return gl.ReadPixels();
}

// ---- 10. Multisample coverage --------------------------------------------------------------------------------

namespace {

// The magnified pixels of a resolved image (unit 0) with, at each of the 4 sample positions of every pixel, a dot
// in that sample's own colour (unit 1, a TEXTURE_2D_MULTISAMPLE, read by texelFetch).
constexpr int kMsW = 12, kMsH = 6;

struct SampleDotsShader : softgl::Shader<SampleDotsShader, NoVaryings> {
  float scale = 32.0f;
  glm::vec2 positions[4];
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const { out.position = in.attrib[0]; }
  void Fragment(const FragmentLanes<NoVaryings>& in, FragmentLanesOut& out) const {
    const vec2 p = vec2(in.frag_coord.x, in.frag_coord.y) / scale;
    const vec2 cell = floor(p), f = p - cell;
    const Int x = Int(cell.x), y = Int(cell.y);
    vec3 c = vec3(in.TexelFetch(0, x, y));
    const Float edge = min(min(f.x, f.y), min(1.0f - f.x, 1.0f - f.y)) * scale;
    c = select(edge < 0.75f, vec3(0.55f), c);
    for (int s = 0; s < 4; ++s) {
      const Float r = length(f - vec2(positions[s])) * scale;
      const vec3 sample = vec3(in.TexelFetchMS(1, x, y, Int(s)));
      const Bool drawn = sample.x < 0.99f;  // (the background is white)
      c = select(r < 4.5f, sample, select(r < 6.0f, select(drawn, vec3(0.0f), vec3(0.6f)), c));
    }
    out.color[0] = vec4(c, 1.0f);
  }
};

}  // namespace

softgl::Image TourMultisample(int width, int height) {
  softgl::Context gl(width, height);
  // A triangle into a 12 x 6 framebuffer object of 4 samples a pixel (a TEXTURE_2D_MULTISAMPLE), resolved by
  // BlitFramebuffer into an ordinary texture.
  const std::uint32_t ms_fbo = gl.GenFramebuffer(), ms_tex = gl.GenTexture();
  gl.ActiveTexture(softgl::TEXTURE0 + 1);
  gl.BindTexture(softgl::TEXTURE_2D_MULTISAMPLE, ms_tex);
  gl.TexImage2DMultisample(softgl::TEXTURE_2D_MULTISAMPLE, 4, softgl::RGBA8, kMsW, kMsH, true);
  gl.BindFramebuffer(softgl::FRAMEBUFFER, ms_fbo);
  gl.FramebufferTexture2D(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D_MULTISAMPLE, ms_tex, 0);
  SampleDotsShader dots;
  for (int s = 0; s < 4; ++s) gl.GetMultisamplefv(softgl::SAMPLE_POSITION, std::uint32_t(s), &dots.positions[s].x);
  gl.Viewport(0, 0, kMsW, kMsH);
  gl.ClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT);
  std::vector<float> tri;
  const glm::vec3 blue(0.2f, 0.35f, 0.9f);
  Push(tri, {0.6f, 0.5f, 0}, blue), Push(tri, {11.6f, 1.9f, 0}, blue), Push(tri, {3.7f, 5.7f, 0}, blue);
  DrawColored(gl, PixelSpace(kMsW, kMsH), softgl::TRIANGLES, tri);
  const std::uint32_t resolve_fbo = gl.GenFramebuffer(), resolved = gl.GenTexture();
  gl.ActiveTexture(softgl::TEXTURE0);
  gl.BindTexture(softgl::TEXTURE_2D, resolved);
  gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA8, kMsW, kMsH, 0, softgl::RGBA, softgl::UNSIGNED_BYTE, nullptr);
  gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
  gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, resolve_fbo);
  gl.FramebufferTexture2D(softgl::DRAW_FRAMEBUFFER, softgl::COLOR_ATTACHMENT0, softgl::TEXTURE_2D, resolved, 0);
  gl.BlitFramebuffer(0, 0, kMsW, kMsH, 0, 0, kMsW, kMsH, softgl::COLOR_BUFFER_BIT, softgl::NEAREST);

  // The picture: the resolved pixels magnified, each sample a dot, the triangle's edges as lines.
  gl.BindFramebuffer(softgl::FRAMEBUFFER, 0);
  gl.Viewport(0, 0, width, height);
  MakeScreenTriangle(gl);
  dots.scale = float(width) / float(kMsW);
  gl.UseProgram(dots);
  gl.DrawArrays(softgl::TRIANGLES, 0, 3);
  DrawColored(gl, PixelSpace(kMsW, kMsH), softgl::LINES, EdgesOf(tri, glm::vec3(0.1f)));
  return gl.ReadPixels();
}

}  // namespace scenes

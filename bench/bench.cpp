// bench — softgl against Mesa's llvmpipe (OSMesa, OpenGL 3.3 core) on the same scenes, same size, in one run.
//
//   bench [--threads N] [--frames N] [--png DIR] [--scene TEXT] [--softgl-only 1] [--scalar 0] [--depth16 1]
//   (--png DIR: also write each scene's last frame to DIR, softgl's and llvmpipe's)
//
// llvmpipe runs with LP_NUM_THREADS = N (0 for --threads 1: rendering on the calling thread alone); softgl with
// Context::Options::threads = N (the calling thread and N - 1 workers). Each scene is set up once per renderer
// (buffers, textures, shaders compiled), two frames are drawn to warm up (llvmpipe compiles its shaders then), then
// --frames frames are timed; a frame ends when its pixels are ready (Finish for softgl, glFinish for OpenGL).
// Prints the median ms/frame per renderer and softgl's time over llvmpipe's (below 1: softgl is faster); with N > 1
// threads, also softgl's speedup over itself on one thread, measured in the same run right after.
//
//   --scene TEXT       only the scenes whose name contains TEXT (ending in $: whose name ends in TEXT)
//   --softgl-only 1    skip llvmpipe (for profiling softgl alone)
//   --scalar 0         skip the runs with each scene's shader in the scalar form (by default they follow each
//                      scene, and the last columns give their time and the wide form's gain over them)
//   --depth16 1        softgl's contexts with a 16-bit depth buffer (Options::depth_format DEPTH_COMPONENT16)
//   --hierarchical-depth 0   softgl's contexts without hierarchical depth (Context::UseHierarchicalDepth)
//   --hiz-counts 1     after each scene's timed frames, one more softgl frame whose hierarchical depth counts
//                      (triangles and regions tested and dropped) go to stderr
//   --cpu-time 1       softgl's mean wall and process CPU time per timed frame to stderr, and how busy its threads
//                      were (CPU / (wall x threads)); with --threads N > 1 for the one-thread run too: where N
//                      threads spend more CPU time than one on the same frames, each thread ran slower
//   --matrix 1         the sampler matrix instead of the scenes: every target x wrap mode x filter x format (below,
//                      integer formats NEAREST only);
//                      --scene TEXT then picks its rows ("2D 256^2, RGBA8, NEAREST"), --softgl-only 1 its ms
//   --formats 1        the colour format matrix instead: every colour format (and a G-buffer of four) x opaque or
//                      blended x depth format (below); --scene and --softgl-only as for --matrix; with --odd 1
//                      at 1279 x 719 instead of 1280 x 720 (a target of odd size)
//   --fetch 1          the texel fetch matrix instead: texelFetch from a 2D texture, a buffer texture, a multisample
//                      texture and a multisample array x texel format (below); --scene and --softgl-only as for
//                      --matrix
//   --msaa-pairs N     also the model scene's softgl frame without and with 4x MSAA in turn, N pairs, in two
//                      contexts side by side: each pair's ratio is taken a few milliseconds apart, so that a shared
//                      machine's drifts in speed weigh on both frames of a pair alike; prints the median ratio
//
// The last row is the model scene's peak memory: each renderer runs the scene (warm-up and one frame) in a process
// of its own that loads the model and nothing else (this program with --rss-child), which reports its VmHWM.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <memory>
#include <vector>

#include <unistd.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <softgl/softgl.h>

namespace {

// ---- Scene data, shared by both renderers -------------------------------------------------------------------

struct Geometry {
  std::vector<float> vertices;  // interleaved, `floats` per vertex
  int floats = 3;
  int position = 3;  // floats of the position (attribute 0): 3 (w = 1 in the shader) or 4, clip space
  std::vector<std::uint32_t> indices;
};

Geometry SmallTriangles(int count) {
  Geometry g;
  g.floats = 3;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> pos(-1.0f, 1.0f), jitter(-0.006f, 0.006f), depth(-0.9f, 0.9f);
  for (int i = 0; i < count; ++i) {
    const float x = pos(rng), y = pos(rng), z = depth(rng);
    for (int k = 0; k < 3; ++k) g.vertices.insert(g.vertices.end(), {x + jitter(rng), y + jitter(rng), z});
  }
  return g;
}

Geometry FullScreenQuads(int count, float uv_scale, bool farther = false) {
  Geometry g;
  g.floats = 5;  // x, y, z, u, v
  const float c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int q = 0; q < count; ++q)
    for (int i : {0, 1, 2, 0, 2, 3}) {
      const float z = farther ? 0.7f + 0.01f * float(q) : 0.9f - 0.01f * float(q);  // each nearer (or farther)
      g.vertices.insert(g.vertices.end(), {c[i][0], c[i][1], z, (c[i][0] * 0.5f + 0.5f) * uv_scale,
                                           (c[i][1] * 0.5f + 0.5f) * uv_scale});
    }
  return g;
}

// A ground plane seen from 1 unit above it, from under the camera to the horizon, 1280 x 720: clip-space positions
// (x, y, z, w) and texture coordinates repeating `repeats` times across it, so that one frame reads every level of
// a mip chain.
Geometry GroundPlane(float repeats) {
  Geometry g;
  g.floats = 6;
  g.position = 4;
  const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1280.0f / 720.0f, 0.1f, 500.0f) *
                       glm::lookAt(glm::vec3(0, 1, 0), glm::vec3(0, 0.2f, -10), glm::vec3(0, 1, 0));
  const float c[4][2] = {{-100, 0.5f}, {100, 0.5f}, {100, -200}, {-100, -200}};
  for (int i : {0, 1, 2, 0, 2, 3}) {
    const glm::vec4 clip = vp * glm::vec4(c[i][0], 0.0f, c[i][1], 1.0f);
    g.vertices.insert(g.vertices.end(), {clip.x, clip.y, clip.z, clip.w, (c[i][0] + 100) / 200 * repeats,
                                         (0.5f - c[i][1]) / 200 * repeats});
  }
  return g;
}

// A model with node transforms applied: positions and normals, one index list.
bool LoadModel(const std::string& path, Geometry& g, glm::mat4& view_proj, float aspect) {
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                 aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices);
  if (!s) return false;
  g.floats = 6;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    const aiMesh* mesh = s->mMeshes[m];
    const auto base = std::uint32_t(g.vertices.size() / 6);
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D p = mesh->mVertices[i];
      const aiVector3D n = mesh->mNormals ? mesh->mNormals[i] : aiVector3D(0, 1, 0);
      g.vertices.insert(g.vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
      lo = glm::min(lo, glm::vec3(p.x, p.y, p.z));
      hi = glm::max(hi, glm::vec3(p.x, p.y, p.z));
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        for (int k = 0; k < 3; ++k) g.indices.push_back(base + mesh->mFaces[f].mIndices[k]);
  }
  const glm::vec3 center = (lo + hi) * 0.5f;
  const float radius = glm::length(hi - lo) * 0.5f, distance = radius / std::sin(glm::radians(20.0f));
  const glm::vec3 eye = center + distance * glm::normalize(glm::vec3(0.6f, 0.4f, 0.7f));
  view_proj = glm::perspective(glm::radians(40.0f), aspect, distance - radius * 1.2f, distance + radius * 1.2f) *
              glm::lookAt(eye, center, glm::vec3(0, 1, 0));
  return true;
}

// A textured OBJ: position, normal, uv, tangent (with handedness), 12 floats a vertex, v flipped for OpenGL.
bool LoadTexturedModel(const std::string& path, Geometry& g) {
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                 aiProcess_CalcTangentSpace | aiProcess_JoinIdenticalVertices);
  if (!s) return false;
  g.floats = 12;
  for (unsigned m = 0; m < s->mNumMeshes; ++m) {
    const aiMesh* mesh = s->mMeshes[m];
    const auto base = std::uint32_t(g.vertices.size() / 12);
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      const aiVector3D p = mesh->mVertices[i], n = mesh->mNormals[i];
      const aiVector3D uv = mesh->mTextureCoords[0] ? mesh->mTextureCoords[0][i] : aiVector3D(0, 0, 0);
      const aiVector3D t = mesh->mTangents ? mesh->mTangents[i] : aiVector3D(1, 0, 0);
      const aiVector3D b = mesh->mBitangents ? mesh->mBitangents[i] : aiVector3D(0, 1, 0);
      const glm::vec3 nn(n.x, n.y, n.z), tt(t.x, t.y, t.z), bb(b.x, b.y, b.z);
      const float w = glm::dot(glm::cross(nn, tt), bb) < 0.0f ? -1.0f : 1.0f;
      g.vertices.insert(g.vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y, t.x, t.y, t.z, w});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        for (int k = 0; k < 3; ++k) g.indices.push_back(base + mesh->mFaces[f].mIndices[k]);
  }
  return true;
}

// A w x h RGBA8 image: 16-texel checks in red, ramps in green (x) and blue (y).
std::vector<std::uint8_t> PatternImage(int w, int h) {
  std::vector<std::uint8_t> px(std::size_t(w) * std::size_t(h) * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &px[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
      const bool check = ((x / 16) + (y / 16)) % 2 == 0;
      p[0] = check ? 230 : 40;
      p[1] = std::uint8_t(x * 255 / w);
      p[2] = std::uint8_t(y * 255 / h);
      p[3] = 255;
    }
  return px;
}
std::vector<std::uint8_t> PatternTexture(int n) { return PatternImage(n, n); }

// The sampler matrix's quad: the whole screen, in perspective (w 1 at the bottom edge, 8 at the top), (u, v) from
// (-1.5, 0) at the bottom left to (2.5, 8) at the top right: magnified near the bottom, minified about 8 times more
// towards the top, and outside [0, 1] on both sides so that the wrap modes matter.
Geometry PerspectiveQuad() {
  Geometry g;
  g.floats = 6;
  g.position = 4;
  const float c[4][3] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 8}, {-1, 1, 8}};  // x, y, w
  const float uv[4][2] = {{-1.5f, 0}, {2.5f, 0}, {2.5f, 8}, {-1.5f, 8}};
  for (int i : {0, 1, 2, 0, 2, 3})
    g.vertices.insert(g.vertices.end(), {c[i][0] * c[i][2], c[i][1] * c[i][2], 0.0f, c[i][2], uv[i][0], uv[i][1]});
  return g;
}

// ---- softgl shaders ------------------------------------------------------------------------------------------
//
// Each scene's shader in the wide form (16 lanes per call, what applications write), and in the scalar form (one
// vertex or fragment per call, softgl 0.1's), so that the gain of the wide path is measured in the same run.

namespace wide {
using namespace softgl;

struct NoVaryings {};
struct FlatShader : Shader<FlatShader, NoVaryings> {
  glm::vec4 color{0.2f, 0.6f, 0.9f, 1.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<NoVaryings>& out) const {
    out.position = vec4(vec3(in.attrib[0]), 1.0f);
  }
  void Fragment(const FragmentLanes<NoVaryings>&, FragmentLanesOut& out) const { out.color[0] = color; }
};

// Each point a square of side 2 * half_size (clip units) in its colour, made by a geometry stage.
struct ColourVaryings {
  vec4 color;
};
struct SquaresShader : Shader<SquaresShader, ColourVaryings> {
  static constexpr GeometryLayout kGeometry{POINTS, TRIANGLE_STRIP, 4};
  glm::vec2 half_size{0.004f, 0.007f};
  void Vertex(const VertexLanes& in, VertexLanesOut<ColourVaryings>& out) const {
    out.position = vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.color = vec4(abs(in.attrib[0].x), abs(in.attrib[0].y), 0.5f, 1.0f);
  }
  void Geometry(const GeometryLanes<ColourVaryings>& in, GeometryLanesOut<ColourVaryings>& out) const {
    for (int k = 0; k < 4; ++k) {
      out.position = in.vertex[0].position + vec4((k & 1) ? half_size.x : -half_size.x,
                                                  (k & 2) ? half_size.y : -half_size.y, 0.0f, 0.0f);
      out.varyings.color = in.vertex[0].varyings.color;
      out.EmitVertex();
    }
  }
  void Fragment(const FragmentLanes<ColourVaryings>& in, FragmentLanesOut& out) const { out.color[0] = in.varyings.color; }
};

struct UvVaryings {
  vec2 uv;
};
struct TextureShader : Shader<TextureShader, UvVaryings> {
  bool fetch = false;  // texelFetch(tex, ivec2(gl_FragCoord.xy), 0) instead
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    if (fetch) out.color[0] = in.TexelFetch(0, Int(in.frag_coord.x), Int(in.frag_coord.y));
    else out.color[0] = in.Texture(0, in.varyings.uv);
  }
};

// TextureShader for clip-space positions of four floats (GroundPlane).
struct PlaneShader : Shader<PlaneShader, UvVaryings> {
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    out.color[0] = in.Texture(0, in.varyings.uv);
  }
};

// The sampler matrix's lookups on PerspectiveQuad's (u, v): a 2D texture (mode 0), a cube map at (u - 1/2, 1/2,
// v - 4) (1: several faces), a 2D array at (u, v, u + 1) (2: layers 0 to 3), a 3D texture at (u, v, u / 2) (3), a
// 2D shadow map at (u, v) with reference v / 8 (4). With `integer` the texture is an unsigned integer one (usampler*),
// its integers over 255 the colour.
struct MatrixShader : Shader<MatrixShader, UvVaryings> {
  int mode = 0;
  bool integer = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    const vec2 t = in.varyings.uv;
    if (integer) {
      ivec4 k;
      switch (mode) {
        case 0: k = in.ITexture(0, t); break;
        case 1: k = in.ITextureCube(0, vec3(t.x - 0.5f, Float(0.5f), t.y - 4.0f)); break;
        case 2: k = in.ITextureArray(0, vec3(t.x, t.y, t.x + 1.0f)); break;
        default: k = in.ITexture3D(0, vec3(t.x, t.y, t.x * 0.5f)); break;
      }
      out.color[0] = vec4(Float(k.x), Float(k.y), Float(k.z), Float(k.w)) * (1.0f / 255.0f);
      return;
    }
    switch (mode) {
      case 0: out.color[0] = in.Texture(0, t); break;
      case 1: out.color[0] = in.TextureCube(0, vec3(t.x - 0.5f, Float(0.5f), t.y - 4.0f)); break;
      case 2: out.color[0] = in.TextureArray(0, vec3(t.x, t.y, t.x + 1.0f)); break;
      case 3: out.color[0] = in.Texture3D(0, vec3(t.x, t.y, t.x * 0.5f)); break;
      default: out.color[0] = vec4(vec3(in.TextureShadow(0, vec3(t.x, t.y, t.y * 0.125f))), 1.0f); break;
    }
  }
};

// The colour format matrix's fragments: (u, v, 0.5, 0.35) from FullScreenQuads' coordinates into each of
// `outputs` draw buffers (each output a little different).
struct FormatShader : Shader<FormatShader, UvVaryings> {
  int outputs = 1;
  bool integer = false;  // integer outputs (uvec4 / ivec4) for integer buffers: (uv * 1000, o, 7)
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    const vec2 t = in.varyings.uv;
    for (int o = 0; o < outputs; ++o) {
      if (integer) out.SetColorI(o, softgl::ivec4(Int(t.x * 1000.0f), Int(t.y * 1000.0f), o, 7));
      else out.color[o] = vec4(t.x, t.y, Float(0.5f) + 0.1f * float(o), Float(0.35f));
    }
  }
};

// The texel fetch matrix's fragments: texelFetch at the pixel from a 2D texture (mode 0), a buffer texture of the
// screen's pixels row by row (1), a multisample texture, sample (x + y) & 3 (2), or a multisample array, layer x & 1
// (3). With `integer` the texture is an unsigned integer one, its integers over 255 the colour.
struct FetchShader : Shader<FetchShader, UvVaryings> {
  int mode = 0;
  bool integer = false;
  void Vertex(const VertexLanes& in, VertexLanesOut<UvVaryings>& out) const {
    out.position = vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = vec2(in.attrib[1]);
  }
  void Fragment(const FragmentLanes<UvVaryings>& in, FragmentLanesOut& out) const {
    const Int x(in.frag_coord.x), y(in.frag_coord.y);
    vec4 t;
    switch (mode) {
      case 0: t = in.TexelFetch(0, x, y); break;
      case 1: t = in.TexelFetchBuffer(0, x + y * 1280); break;
      case 2: t = in.TexelFetchMS(0, x, y, (x + y) & 3); break;
      default: t = in.TexelFetchMSArray(0, x, y, x & 1, (x + y) & 3); break;
    }
    if (integer) {
      const softgl::ivec4 k = softgl::ivec4::FromBits(t);
      t = vec4(Float(k.x), Float(k.y), Float(k.z), Float(k.w)) * (1.0f / 255.0f);
    }
    out.color[0] = t;
  }
};

// The ground plane with a cube map (mode 0: direction (u - 20, 1, v - 2): the top face near the camera, the
// sides towards the horizon), a 2D array (mode 1: (u, v), layer u / 10) or a shadow map (mode 2: (u, v) / 40,
// reference u / 40).
struct DirVaryings {
  vec3 dir;
};
struct DirShader : Shader<DirShader, DirVaryings> {
  int mode = 0;
  void Vertex(const VertexLanes& in, VertexLanesOut<DirVaryings>& out) const {
    out.position = in.attrib[0];
    const vec2 t = vec2(in.attrib[1]);
    out.varyings.dir = mode == 0   ? vec3(t.x - 20.0f, Float(1.0f), t.y - 2.0f)
                       : mode == 2 ? vec3(t.x, t.y, t.x) / 40.0f
                                   : vec3(t.x, t.y, t.x * 0.1f);
  }
  void Fragment(const FragmentLanes<DirVaryings>& in, FragmentLanesOut& out) const {
    if (mode == 2) out.color[0] = vec4(vec3(in.TextureShadow(0, in.varyings.dir)), 1.0f);
    else if (mode == 3) out.color[0] = in.Texture3D(0, in.varyings.dir);
    else out.color[0] = mode == 0 ? in.TextureCube(0, in.varyings.dir) : in.TextureArray(0, in.varyings.dir);
  }
};

struct PhongVaryings {
  vec3 normal;
  vec3 world;
};
struct PhongShader : Shader<PhongShader, PhongVaryings> {
  glm::mat4 view_proj{1.0f};
  glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.8f, 0.5f));
  glm::vec3 eye{0.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<PhongVaryings>& out) const {
    out.position = view_proj * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = vec3(in.attrib[1]);
    out.varyings.world = vec3(in.attrib[0]);
  }
  void Fragment(const FragmentLanes<PhongVaryings>& in, FragmentLanesOut& out) const {
    const vec3 n = normalize(in.varyings.normal);
    const vec3 h = normalize(light + normalize(eye - in.varyings.world));
    const Float d = max(dot(n, light), 0.0f), s = pow(max(dot(n, h), 0.0f), 32.0f);
    out.color[0] = vec4(glm::vec3(0.7f, 0.72f, 0.75f) * (0.15f + d) + vec3(0.3f * s), 1.0f);
  }
};

struct HeadVaryings {
  vec3 normal;
  vec3 world;
  vec2 uv;
  vec4 tangent;
};
// Diffuse, tangent-space normal map and specular map on units 0, 1, 2; Blinn-Phong.
struct HeadShader : Shader<HeadShader, HeadVaryings> {
  glm::mat4 view_proj{1.0f};
  glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.6f, 0.8f));
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  void Vertex(const VertexLanes& in, VertexLanesOut<HeadVaryings>& out) const {
    out.position = view_proj * vec4(vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = vec3(in.attrib[1]);
    out.varyings.world = vec3(in.attrib[0]);
    out.varyings.uv = vec2(in.attrib[2]);
    out.varyings.tangent = in.attrib[3];
  }
  void Fragment(const FragmentLanes<HeadVaryings>& in, FragmentLanesOut& out) const {
    const vec3 n0 = normalize(in.varyings.normal);
    const vec3 tangent = in.varyings.tangent.xyz();
    const vec3 t = normalize(tangent - n0 * dot(n0, tangent));
    const vec3 b = cross(n0, t) * in.varyings.tangent.w;
    const vec3 m = in.Texture(1, in.varyings.uv).xyz() * 2.0f - 1.0f;
    const vec3 n = normalize(t * m.x + b * m.y + n0 * m.z);
    const vec3 h = normalize(light + normalize(eye - in.varyings.world));
    const Float d = max(dot(n, light), 0.0f);
    const Float s = pow(max(dot(n, h), 0.0f), 24.0f) * in.Texture(2, in.varyings.uv).x;
    out.color[0] = vec4(in.Texture(0, in.varyings.uv).xyz() * (0.15f + d) + vec3(s), 1.0f);
  }
};
}  // namespace wide

namespace scalar {

struct NoVaryings {};
struct FlatShader : softgl::Shader<FlatShader, NoVaryings> {
  glm::vec4 color{0.2f, 0.6f, 0.9f, 1.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<NoVaryings>& out) const {
    out.position = glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
  }
  bool Fragment(const softgl::FragmentIn<NoVaryings>&, softgl::FragmentOut& out) const {
    out.color[0] = color;
    return true;
  }
};

struct UvVaryings {
  glm::vec2 uv;
};
struct TextureShader : softgl::Shader<TextureShader, UvVaryings> {
  bool fetch = false;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<UvVaryings>& out) const {
    out.position = glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.uv = glm::vec2(in.attrib[1]);
  }
  bool Fragment(const softgl::FragmentIn<UvVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = fetch ? in.textures->Fetch(0, glm::ivec2(in.frag_coord), 0) : in.Texture(0, &UvVaryings::uv);
    return true;
  }
};

struct PlaneShader : softgl::Shader<PlaneShader, UvVaryings> {
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<UvVaryings>& out) const {
    out.position = in.attrib[0];
    out.varyings.uv = glm::vec2(in.attrib[1]);
  }
  bool Fragment(const softgl::FragmentIn<UvVaryings>& in, softgl::FragmentOut& out) const {
    out.color[0] = in.Texture(0, &UvVaryings::uv);
    return true;
  }
};

struct DirVaryings {
  glm::vec3 dir;
};
struct DirShader : softgl::Shader<DirShader, DirVaryings> {
  int mode = 0;
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<DirVaryings>& out) const {
    out.position = in.attrib[0];
    const glm::vec2 t(in.attrib[1]);
    out.varyings.dir = mode == 0   ? glm::vec3(t.x - 20.0f, 1.0f, t.y - 2.0f)
                       : mode == 2 ? glm::vec3(t.x, t.y, t.x) / 40.0f
                                   : glm::vec3(t.x, t.y, t.x * 0.1f);
  }
  bool Fragment(const softgl::FragmentIn<DirVaryings>& in, softgl::FragmentOut& out) const {
    if (mode == 2) {
      const glm::vec3 d = in.varyings.dir;
      const float lit = in.textures->SampleShadow(0, glm::vec2(d), d.z, glm::vec2(in.dFdx(&DirVaryings::dir)),
                                                  glm::vec2(in.dFdy(&DirVaryings::dir)));
      out.color[0] = glm::vec4(glm::vec3(lit), 1.0f);
    } else if (mode == 3) {
      out.color[0] = in.Texture3D(0, &DirVaryings::dir);
    } else {
      out.color[0] = mode == 0 ? in.TextureCube(0, &DirVaryings::dir) : in.TextureArray(0, &DirVaryings::dir);
    }
    return true;
  }
};

struct PhongVaryings {
  glm::vec3 normal;
  glm::vec3 world;
};
struct PhongShader : softgl::Shader<PhongShader, PhongVaryings> {
  glm::mat4 view_proj{1.0f};
  glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.8f, 0.5f));
  glm::vec3 eye{0.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<PhongVaryings>& out) const {
    out.position = view_proj * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::vec3(in.attrib[1]);
    out.varyings.world = glm::vec3(in.attrib[0]);
  }
  bool Fragment(const softgl::FragmentIn<PhongVaryings>& in, softgl::FragmentOut& out) const {
    const glm::vec3 n = glm::normalize(in.varyings.normal);
    const glm::vec3 h = glm::normalize(light + glm::normalize(eye - in.varyings.world));
    const float d = std::max(glm::dot(n, light), 0.0f), s = std::pow(std::max(glm::dot(n, h), 0.0f), 32.0f);
    out.color[0] = glm::vec4(glm::vec3(0.7f, 0.72f, 0.75f) * (0.15f + d) + glm::vec3(0.3f * s), 1.0f);
    return true;
  }
};

struct HeadVaryings {
  glm::vec3 normal;
  glm::vec3 world;
  glm::vec2 uv;
  glm::vec4 tangent;
};
// Diffuse, tangent-space normal map and specular map on units 0, 1, 2; Blinn-Phong.
struct HeadShader : softgl::Shader<HeadShader, HeadVaryings> {
  glm::mat4 view_proj{1.0f};
  glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.6f, 0.8f));
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  void Vertex(const softgl::VertexIn& in, softgl::VertexOut<HeadVaryings>& out) const {
    out.position = view_proj * glm::vec4(glm::vec3(in.attrib[0]), 1.0f);
    out.varyings.normal = glm::vec3(in.attrib[1]);
    out.varyings.world = glm::vec3(in.attrib[0]);
    out.varyings.uv = glm::vec2(in.attrib[2]);
    out.varyings.tangent = in.attrib[3];
  }
  bool Fragment(const softgl::FragmentIn<HeadVaryings>& in, softgl::FragmentOut& out) const {
    const glm::vec3 n0 = glm::normalize(in.varyings.normal);
    const glm::vec3 t = glm::normalize(glm::vec3(in.varyings.tangent) - n0 * glm::dot(n0, glm::vec3(in.varyings.tangent)));
    const glm::vec3 b = glm::cross(n0, t) * in.varyings.tangent.w;
    const glm::vec3 m = glm::vec3(in.Texture(1, &HeadVaryings::uv)) * 2.0f - 1.0f;
    const glm::vec3 n = glm::normalize(t * m.x + b * m.y + n0 * m.z);
    const glm::vec3 h = glm::normalize(light + glm::normalize(eye - in.varyings.world));
    const float d = std::max(glm::dot(n, light), 0.0f);
    const float s = std::pow(std::max(glm::dot(n, h), 0.0f), 24.0f) * in.Texture(2, &HeadVaryings::uv).r;
    out.color[0] = glm::vec4(glm::vec3(in.Texture(0, &HeadVaryings::uv)) * (0.15f + d) + glm::vec3(s), 1.0f);
    return true;
  }
};

}  // namespace scalar

// ---- GLSL ----------------------------------------------------------------------------------------------------

const char* kFlatVs = "#version 330 core\nlayout(location=0) in vec3 p; void main(){ gl_Position = vec4(p, 1.0); }";
const char* kFlatFs = "#version 330 core\nuniform vec4 color; out vec4 o; void main(){ o = color; }";
const char* kTexVs =
    "#version 330 core\nlayout(location=0) in vec3 p; layout(location=1) in vec2 t; out vec2 uv;"
    "void main(){ gl_Position = vec4(p, 1.0); uv = t; }";
const char* kPlaneVs =
    "#version 330 core\nlayout(location=0) in vec4 p; layout(location=1) in vec2 t; out vec2 uv;"
    "void main(){ gl_Position = p; uv = t; }";
const char* kTexFs = "#version 330 core\nin vec2 uv; uniform sampler2D tex; out vec4 o; void main(){ o = texture(tex, uv); }";
const char* kFetchFs = "#version 330 core\nin vec2 uv; uniform sampler2D tex; out vec4 o;"
                       "void main(){ o = texelFetch(tex, ivec2(gl_FragCoord.xy), 0); }";
const char* kCubeFs = "#version 330 core\nin vec2 uv; uniform samplerCube tex; out vec4 o;"
                      "void main(){ o = texture(tex, vec3(uv.x - 20.0, 1.0, uv.y - 2.0)); }";
const char* kArrayFs = "#version 330 core\nin vec2 uv; uniform sampler2DArray tex; out vec4 o;"
                       "void main(){ o = texture(tex, vec3(uv, uv.x * 0.1)); }";
const char* k3DFs = "#version 330 core\nin vec2 uv; uniform sampler3D tex; out vec4 o;"
                    "void main(){ o = texture(tex, vec3(uv, uv.x * 0.1)); }";
// FormatShader in GLSL, for 1 to 4 outputs; `integer` 1 for uvec4 outputs, 2 for ivec4.
std::string FormatFs(int outputs, int integer = 0) {
  const std::string type = integer == 1 ? "uvec4" : integer == 2 ? "ivec4" : "vec4";
  std::string fs = "#version 330 core\nin vec2 uv;";
  for (int o = 0; o < outputs; ++o)
    fs += " layout(location=" + std::to_string(o) + ") out " + type + " o" + std::to_string(o) + ";";
  fs += " void main(){";
  for (int o = 0; o < outputs; ++o) {
    const std::string n = std::to_string(o);
    if (integer) fs += " o" + n + " = " + type + "(ivec4(ivec2(uv * 1000.0), " + n + ", 7));";
    else fs += " o" + n + " = vec4(uv, 0.5 + 0.1 * " + n + ".0, 0.35);";
  }
  return fs + " }";
}
// MatrixShader's lookups in GLSL, by mode.
const char* const kMatrixFs[5] = {
    "#version 330 core\nin vec2 uv; uniform sampler2D tex; out vec4 o; void main(){ o = texture(tex, uv); }",
    "#version 330 core\nin vec2 uv; uniform samplerCube tex; out vec4 o;"
    "void main(){ o = texture(tex, vec3(uv.x - 0.5, 0.5, uv.y - 4.0)); }",
    "#version 330 core\nin vec2 uv; uniform sampler2DArray tex; out vec4 o;"
    "void main(){ o = texture(tex, vec3(uv, uv.x + 1.0)); }",
    "#version 330 core\nin vec2 uv; uniform sampler3D tex; out vec4 o;"
    "void main(){ o = texture(tex, vec3(uv, uv.x * 0.5)); }",
    "#version 330 core\nin vec2 uv; uniform sampler2DShadow tex; out vec4 o;"
    "void main(){ o = vec4(vec3(texture(tex, vec3(uv, uv.y * 0.125))), 1.0); }"};
// Their integer forms (modes 0 to 3), for unsigned integer textures.
const char* const kMatrixIntegerFs[4] = {
    "#version 330 core\nin vec2 uv; uniform usampler2D tex; out vec4 o; void main(){ o = vec4(texture(tex, uv)) / 255.0; }",
    "#version 330 core\nin vec2 uv; uniform usamplerCube tex; out vec4 o;"
    "void main(){ o = vec4(texture(tex, vec3(uv.x - 0.5, 0.5, uv.y - 4.0))) / 255.0; }",
    "#version 330 core\nin vec2 uv; uniform usampler2DArray tex; out vec4 o;"
    "void main(){ o = vec4(texture(tex, vec3(uv, uv.x + 1.0))) / 255.0; }",
    "#version 330 core\nin vec2 uv; uniform usampler3D tex; out vec4 o;"
    "void main(){ o = vec4(texture(tex, vec3(uv, uv.x * 0.5))) / 255.0; }"};
// FetchShader's lookups in GLSL, by mode: the sampler's type (with a "u" before it for an integer texture), then
// the texel it reads.
const char* const kFetchSamplers[4] = {"sampler2D", "samplerBuffer", "sampler2DMS", "sampler2DMSArray"};
const char* const kFetchTexels[4] = {"texelFetch(tex, p, 0)", "texelFetch(tex, p.x + p.y * 1280)",
                                     "texelFetch(tex, p, (p.x + p.y) & 3)",
                                     "texelFetch(tex, ivec3(p, p.x & 1), (p.x + p.y) & 3)"};
std::string FetchFs(int mode, bool integer) {
  return std::string("#version 330 core\nin vec2 uv; uniform ") + (integer ? "u" : "") + kFetchSamplers[mode] +
         " tex; out vec4 o; void main(){ ivec2 p = ivec2(gl_FragCoord.xy); o = vec4(" + kFetchTexels[mode] + ")" +
         (integer ? " / 255.0" : "") + "; }";
}
const char* kShadowFs = "#version 330 core\nin vec2 uv; uniform sampler2DShadow tex; out vec4 o;"
                        "void main(){ o = vec4(vec3(texture(tex, vec3(uv, uv.x) / 40.0)), 1.0); }";
const char* kPhongVs =
    "#version 330 core\nlayout(location=0) in vec3 p; layout(location=1) in vec3 n; uniform mat4 vp;"
    "out vec3 normal; out vec3 world; void main(){ gl_Position = vp * vec4(p, 1.0); normal = n; world = p; }";
const char* kPhongFs =
    "#version 330 core\nin vec3 normal; in vec3 world; uniform vec3 light; uniform vec3 eye; out vec4 o;"
    "void main(){ vec3 n = normalize(normal); vec3 h = normalize(light + normalize(eye - world));"
    "float d = max(dot(n, light), 0.0); float s = pow(max(dot(n, h), 0.0), 32.0);"
    "o = vec4(vec3(0.7, 0.72, 0.75) * (0.15 + d) + vec3(0.3 * s), 1.0); }";

const char* kHeadVs =
    "#version 330 core\nlayout(location=0) in vec3 p; layout(location=1) in vec3 n; layout(location=2) in vec2 t;"
    "layout(location=3) in vec4 tg; uniform mat4 vp; out vec3 normal; out vec3 world; out vec2 uv; out vec4 tangent;"
    "void main(){ gl_Position = vp * vec4(p, 1.0); normal = n; world = p; uv = t; tangent = tg; }";
const char* kHeadFs =
    "#version 330 core\nin vec3 normal; in vec3 world; in vec2 uv; in vec4 tangent; uniform sampler2D diffuse_map;"
    "uniform sampler2D normal_map; uniform sampler2D spec_map; uniform vec3 light; uniform vec3 eye; out vec4 o;"
    "void main(){ vec3 n0 = normalize(normal); vec3 t = normalize(tangent.xyz - n0 * dot(n0, tangent.xyz));"
    "vec3 b = cross(n0, t) * tangent.w; vec3 m = texture(normal_map, uv).xyz * 2.0 - 1.0;"
    "vec3 n = normalize(t * m.x + b * m.y + n0 * m.z); vec3 h = normalize(light + normalize(eye - world));"
    "float d = max(dot(n, light), 0.0); float s = pow(max(dot(n, h), 0.0), 24.0) * texture(spec_map, uv).r;"
    "o = vec4(texture(diffuse_map, uv).rgb * (0.15 + d) + vec3(s), 1.0); }";

// The geometry stage of wide::SquaresShader.
constexpr const char* kSquaresVs =
    "#version 330 core\nlayout(location = 0) in vec3 pos; out vec4 v_color;"
    "void main(){ gl_Position = vec4(pos, 1.0); v_color = vec4(abs(pos.x), abs(pos.y), 0.5, 1.0); }";
constexpr const char* kSquaresGs =
    "#version 330 core\nlayout(points) in; layout(triangle_strip, max_vertices = 4) out; in vec4 v_color[];"
    "out vec4 g_color; uniform vec2 half_size;"
    "void main(){ for (int k = 0; k < 4; ++k) { gl_Position = gl_in[0].gl_Position + vec4((k & 1) != 0 ?"
    " half_size.x : -half_size.x, (k & 2) != 0 ? half_size.y : -half_size.y, 0.0, 0.0); g_color = v_color[0];"
    " EmitVertex(); } }";
constexpr const char* kSquaresFs = "#version 330 core\nin vec4 g_color; out vec4 o; void main(){ o = g_color; }";

GLuint Program(const char* vs, const char* fs, const char* gs = nullptr) {
  const GLuint p = glCreateProgram();
  for (auto [type, src] : {std::pair{GLenum(GL_VERTEX_SHADER), vs}, std::pair{GLenum(GL_FRAGMENT_SHADER), fs},
                           std::pair{GLenum(GL_GEOMETRY_SHADER), gs}}) {
    if (!src) continue;
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    glAttachShader(p, s);
  }
  glLinkProgram(p);
  glUseProgram(p);
  return p;
}

// ---- Running -------------------------------------------------------------------------------------------------

std::string g_png_dir;  // --png
softgl::Context::Options g_options;  // --threads, --depth16
bool g_scalar = false;  // run the scalar form of the scenes' shaders
bool g_hierarchical_depth = true;  // --hierarchical-depth
bool g_hiz_counts = false;         // --hiz-counts
bool g_cpu_time = false;           // --cpu-time
// The timed frames of the last MedianMs: wall and process CPU time per frame (all threads' CPU time together).
double g_last_wall_ms = 0.0, g_last_cpu_ms = 0.0;

double ProcessCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Runs body with the scene's shader in the wide form, or in the scalar form when g_scalar.
template <class Wide, class Scalar, class Body>
double WithShader(Body&& body) {
  if (g_scalar) {
    Scalar shader;
    return body(shader);
  }
  Wide shader;
  return body(shader);
}

double MedianMs(int frames, const std::function<void()>& frame) {
  frame();  // warm-up: llvmpipe compiles its shaders on first use
  frame();
  std::vector<double> ms;
  const double cpu0 = ProcessCpuMs();
  for (int i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    frame();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  g_last_cpu_ms = (ProcessCpuMs() - cpu0) / frames;
  g_last_wall_ms = 0.0;
  for (const double m : ms) g_last_wall_ms += m / frames;
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

// One frame of a scene: clear colour (and depth), one draw of `count` vertices (indexed or not), then wait for the
// pixels. `png` names the file --png writes softgl's last frame to (and llvmpipe's, prefixed llvmpipe_).
struct FrameSpec {
  bool depth;
  bool indexed;
  int count;
  const char* png;
  int samples = 0;  // > 1: into a multisampled framebuffer, resolved every frame
  // The colour buffer's format: softgl's context takes it (Options::color_format), llvmpipe's multisampled
  // framebuffer object; SRGB8_ALPHA8 with FRAMEBUFFER_SRGB enabled on both.
  softgl::Enum color_format = softgl::RGBA8;
};

double TimeSoftgl(int n, softgl::Context& gl, const FrameSpec& f) {
  const double ms = MedianMs(n, [&] {
    gl.Clear(softgl::COLOR_BUFFER_BIT | (f.depth ? softgl::DEPTH_BUFFER_BIT : 0));
    if (f.indexed) {
      gl.DrawElement(softgl::TRIANGLES, f.count, softgl::UNSIGNED_INT, 0);
    } else {
      gl.DrawArrays(softgl::TRIANGLES, 0, f.count);
    }
    gl.Finish();
    if (f.samples > 1) {  // a read resolves the multisampled framebuffer
      std::uint8_t px[4];
      gl.ReadPixel(0, 0, px);
    }
  });
  if (g_hiz_counts) {
    gl.TakeHierarchicalDepthCounts();
    gl.Clear(softgl::COLOR_BUFFER_BIT | (f.depth ? softgl::DEPTH_BUFFER_BIT : 0));
    if (f.indexed) gl.DrawElement(softgl::TRIANGLES, f.count, softgl::UNSIGNED_INT, 0);
    else gl.DrawArrays(softgl::TRIANGLES, 0, f.count);
    const softgl::Context::HierarchicalDepthCounts c = gl.TakeHierarchicalDepthCounts();
    std::fprintf(stderr, "hierarchical depth, %s: triangles %llu of %llu dropped, regions %llu of %llu dropped\n",
                 f.png, static_cast<unsigned long long>(c.triangles_hidden),
                 static_cast<unsigned long long>(c.triangles_tested), static_cast<unsigned long long>(c.regions_hidden),
                 static_cast<unsigned long long>(c.regions_tested));
  }
  if (!g_png_dir.empty()) softgl::WritePng(g_png_dir + "/" + f.png, gl.ReadPixels());
  return ms;
}

double TimeGl(int n, const FrameSpec& f) {
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  GLuint fbo = 0;
  if (f.samples > 1) {  // a framebuffer object of that many samples, resolved into the context's by a blit
    GLuint rb[2];
    glGenRenderbuffers(2, rb);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, f.samples, f.color_format, vp[2], vp[3]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, f.samples, GL_DEPTH24_STENCIL8, vp[2], vp[3]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  }
  if (f.color_format == softgl::SRGB8_ALPHA8) glEnable(GL_FRAMEBUFFER_SRGB);
  const double ms = MedianMs(n, [&] {
    glClear(GL_COLOR_BUFFER_BIT | (f.depth ? GL_DEPTH_BUFFER_BIT : 0));
    if (f.indexed) {
      glDrawElements(GL_TRIANGLES, GLsizei(f.count), GL_UNSIGNED_INT, nullptr);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(f.count));
    }
    if (fbo) {
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
      glBlitFramebuffer(0, 0, vp[2], vp[3], 0, 0, vp[2], vp[3], GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    }
    glFinish();
  });
  if (fbo) glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_FRAMEBUFFER_SRGB);
  if (!g_png_dir.empty()) {  // llvmpipe's last frame beside softgl's, top row first
    softgl::Image img;
    img.width = vp[2];
    img.height = vp[3];
    img.rgba.resize(std::size_t(img.width) * std::size_t(img.height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    const std::size_t row = std::size_t(img.width) * 4;
    for (int y = 0; y < img.height / 2; ++y)
      std::swap_ranges(img.rgba.begin() + std::ptrdiff_t(std::size_t(y) * row),
                       img.rgba.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                       img.rgba.begin() + std::ptrdiff_t(std::size_t(img.height - 1 - y) * row));
    softgl::WritePng(g_png_dir + "/llvmpipe_" + f.png, img);
  }
  return ms;
}

// One cell of a matrix: softgl's time over llvmpipe's and, in brackets, over its own in the first cell (which
// `first_ms` keeps); with softgl_only, softgl's ms.
void PrintCell(bool softgl_only, double sg_ms, double gl_ms, double& first_ms) {
  if (first_ms == 0.0) first_ms = sg_ms;
  if (softgl_only) std::printf(" %.2f ms |", sg_ms);
  else std::printf(" %.2f (%.1f) |", sg_ms / gl_ms, sg_ms / first_ms);
  std::fflush(stdout);
}

struct Scene {
  const char* name;
  int width, height;
  const char* unit;  // what to report besides time
  double units;      // per frame (triangles, pixels)
  std::function<double(int)> softgl_ms, gl_ms;
};

// A /proc/self/status field in KiB (VmRSS, VmHWM), or -1.
long StatusKiB(const char* field) {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long value = -1;
  const std::size_t n = std::strlen(field);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, field, n) == 0 && line[n] == ':') value = std::atol(line + n + 1);
  std::fclose(f);
  return value;
}

// Runs this program again as `--rss-child RENDERER` (the model scene alone, nothing else loaded) and returns the
// peak resident memory (VmHWM) that process reports, in MiB; -1 on failure.
double ModelScenePeakMiB(const char* self, const char* renderer, int threads) {
  const std::string cmd = std::string(self) + " --rss-child " + renderer + " --threads " + std::to_string(threads);
  std::FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1.0;
  long kib = -1;
  if (std::fscanf(p, "%ld", &kib) != 1) kib = -1;
  pclose(p);
  return kib < 0 ? -1.0 : double(kib) / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  int threads = 1, frames = 5;
  std::string only;          // --scene TEXT: run only scenes whose name contains TEXT
  bool softgl_only = false;  // --softgl-only 1: skip llvmpipe (for profiling)
  bool with_scalar = true;   // --scalar 0: skip the scalar-shader runs
  std::string rss_child;     // --rss-child softgl|llvmpipe: run the model scene once, print peak RSS in KiB
  int msaa_pairs = 0;        // --msaa-pairs N
  bool matrix = false;       // --matrix 1
  bool format_matrix = false;  // --formats 1
  bool fetch_matrix = false;   // --fetch 1
  bool odd_size = false;       // --odd 1
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--threads")) threads = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--frames")) frames = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--png")) g_png_dir = argv[i + 1];
    if (!std::strcmp(argv[i], "--scene")) only = argv[i + 1];
    if (!std::strcmp(argv[i], "--softgl-only")) softgl_only = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--scalar")) with_scalar = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--depth16") && std::atoi(argv[i + 1]) != 0)
      g_options.depth_format = softgl::DEPTH_COMPONENT16;
    if (!std::strcmp(argv[i], "--rss-child")) rss_child = argv[i + 1];
    if (!std::strcmp(argv[i], "--hierarchical-depth")) g_hierarchical_depth = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--hiz-counts")) g_hiz_counts = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--cpu-time")) g_cpu_time = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--msaa-pairs")) msaa_pairs = std::max(0, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--matrix")) matrix = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--formats")) format_matrix = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--fetch")) fetch_matrix = std::atoi(argv[i + 1]) != 0;
    if (!std::strcmp(argv[i], "--odd")) odd_size = std::atoi(argv[i + 1]) != 0;
  }
  const std::string lp_threads = std::to_string(threads == 1 ? 0 : threads);
  setenv("LP_NUM_THREADS", lp_threads.c_str(), 1);
  g_options.threads = threads;
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);

  const bool all_data = rss_child.empty();  // a memory-measuring child loads the model alone
  const Geometry tris = all_data ? SmallTriangles(1000000) : Geometry{};
  const Geometry blend_quads = FullScreenQuads(50, 1.0f), tex_quads = FullScreenQuads(20, 3.0f);
  const Geometry sorted_quads_near = FullScreenQuads(20, 1.0f), sorted_quads_far = FullScreenQuads(20, 1.0f, true);
  const std::vector<std::uint8_t> texture = all_data ? PatternTexture(1024) : std::vector<std::uint8_t>{};
  Geometry engine;
  glm::mat4 engine_vp(1.0f);
  const bool have_engine = LoadModel("/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                                     engine, engine_vp, 1280.0f / 720.0f);
  const glm::vec3 engine_eye = glm::vec3(glm::inverse(engine_vp) * glm::vec4(0, 0, -1, 1));

  // softgl: one context per scene; attributes 0, 1 from the interleaved buffer.
  auto softgl_setup = [](softgl::Context& gl, const Geometry& g) {
    gl.UseHierarchicalDepth(g_hierarchical_depth);
    gl.BindVertexArray(gl.GenVertexArray());
    gl.BindBuffer(softgl::ARRAY_BUFFER, gl.GenBuffer());
    gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(g.vertices.size() * 4), g.vertices.data());
    gl.VertexAttributePointer(0, g.position, softgl::FLOAT, false, g.floats * 4, 0);
    gl.EnableVertexAttribArray(0);
    if (g.floats == 12) {  // position, normal, uv, tangent
      gl.VertexAttributePointer(1, 3, softgl::FLOAT, false, 48, 12);
      gl.VertexAttributePointer(2, 2, softgl::FLOAT, false, 48, 24);
      gl.VertexAttributePointer(3, 4, softgl::FLOAT, false, 48, 32);
      for (std::uint32_t a = 1; a < 4; ++a) gl.EnableVertexAttribArray(a);
    } else if (g.floats > g.position) {
      gl.VertexAttributePointer(1, g.floats - g.position, softgl::FLOAT, false, g.floats * 4, g.position * 4);
      gl.EnableVertexAttribArray(1);
    }
    if (!g.indices.empty()) {
      gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, gl.GenBuffer());
      gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(g.indices.size() * 4), g.indices.data());
    }
  };
  auto gl_setup = [](const Geometry& g) {
    GLuint vao, vbo, ebo;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(g.vertices.size() * 4), g.vertices.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, g.position, GL_FLOAT, GL_FALSE, g.floats * 4, nullptr);
    glEnableVertexAttribArray(0);
    if (g.floats == 12) {
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 48, reinterpret_cast<void*>(12));
      glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 48, reinterpret_cast<void*>(24));
      glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, 48, reinterpret_cast<void*>(32));
      for (GLuint a = 1; a < 4; ++a) glEnableVertexAttribArray(a);
    } else if (g.floats > g.position) {
      glVertexAttribPointer(1, g.floats - g.position, GL_FLOAT, GL_FALSE, g.floats * 4,
                            reinterpret_cast<void*>(std::size_t(g.position) * 4));
      glEnableVertexAttribArray(1);
    }
    if (!g.indices.empty()) {
      glGenBuffers(1, &ebo);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(g.indices.size() * 4), g.indices.data(), GL_STATIC_DRAW);
    }
  };
  auto with_osmesa = [&](int w, int h, const std::function<double()>& body) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                           OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    std::vector<std::uint8_t> buffer(std::size_t(w) * h * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h)) return -1.0;
    glViewport(0, 0, w, h);
    const double ms = body();
    OSMesaDestroyContext(ctx);
    return ms;
  };

  // --matrix 1: the sampler matrix. Each cell one full-screen draw (PerspectiveQuad, 1280 x 720) that samples once
  // per fragment, timed for softgl and for llvmpipe in the same run. Targets: a 256^2 2D texture, a 1000 x 600 one,
  // a cube map of 256^2 faces, a 2D array of four 256^2 layers, a 64^3 3D texture (each from PatternImage, uploaded
  // as RGBA bytes and converted to the cell's format; RGBA8UI and RGBA32UI take them as integers, NEAREST only),
  // and a 2048^2 DEPTH_COMPONENT32F shadow map compared with
  // LEQUAL (its own format; NEAREST and bilinear only). Filters: NEAREST (NEAREST / NEAREST), bilinear (LINEAR /
  // LINEAR), trilinear (LINEAR_MIPMAP_LINEAR / LINEAR), and trilinear with 16x anisotropy. Prints softgl's time
  // over llvmpipe's per cell, and in brackets softgl's time over its own in the first cell (2D 256^2, RGBA8,
  // trilinear, REPEAT).
  if (matrix) {
    using softgl::Enum;
    struct MatrixTarget {
      const char* name;
      int mode;  // MatrixShader's
      Enum target;
      int w, h, d;
    };
    namespace sg = softgl;
    const MatrixTarget targets[] = {{"2D 256^2", 0, sg::TEXTURE_2D, 256, 256, 1},
                                    {"2D 1000x600", 0, sg::TEXTURE_2D, 1000, 600, 1},
                                    {"cube 256^2", 1, sg::TEXTURE_CUBE_MAP, 256, 256, 1},
                                    {"2D array 256^2 x 4", 2, sg::TEXTURE_2D_ARRAY, 256, 256, 4},
                                    {"3D 64^3", 3, sg::TEXTURE_3D, 64, 64, 64},
                                    {"shadow 2048^2", 4, sg::TEXTURE_2D, 2048, 2048, 1}};
    const std::pair<const char*, Enum> formats[] = {
        {"RGBA8", sg::RGBA8},     {"SRGB8_ALPHA8", sg::SRGB8_ALPHA8}, {"RGBA16F", sg::RGBA16F},
        {"RGBA32F", sg::RGBA32F}, {"RGBA8UI", sg::RGBA8UI},           {"RGBA32UI", sg::RGBA32UI}};
    struct MatrixFilter {
      const char* name;
      Enum min, mag;
      float anisotropy;
    };
    const MatrixFilter filters[] = {{"trilinear", sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, 1.0f},
                                    {"bilinear", sg::LINEAR, sg::LINEAR, 1.0f},
                                    {"NEAREST", sg::NEAREST, sg::NEAREST, 1.0f},
                                    {"trilinear, 16x aniso", sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, 16.0f}};
    const Enum wraps[] = {sg::REPEAT, sg::MIRRORED_REPEAT, sg::CLAMP_TO_EDGE, sg::CLAMP_TO_BORDER};
    const Geometry quad = PerspectiveQuad();
    const char* const png[5] = {"bench_matrix_2d.png", "bench_matrix_cube.png", "bench_matrix_array.png",
                                "bench_matrix_3d.png", "bench_matrix_shadow.png"};  // (--png: each target's last cell)
    const float border[4] = {0.2f, 0.4f, 0.6f, 1.0f};
    const std::uint32_t border_integer[4] = {51, 102, 153, 255};  // (an integer texture's, the same colour)
    std::vector<float> depths;
    for (int y = 0; y < 2048; ++y)
      for (int x = 0; x < 2048; ++x)
        depths.push_back(0.5f + 0.25f * std::sin(float(x) * 0.02f) + 0.2f * std::cos(float(y) * 0.013f));
    std::printf("Sampler matrix, %d thread(s), %d frames a cell: softgl / llvmpipe (softgl ms / ms of the first "
                "cell)\n\n| target | format | filter | REPEAT | MIRRORED_REPEAT | CLAMP_TO_EDGE | CLAMP_TO_BORDER |\n"
                "|---|---|---|---|---|---|---|\n",
                threads, frames);
    double first_ms = 0.0;
    for (const MatrixTarget& mt : targets) {
      const bool shadow = mt.mode == 4;
      std::vector<std::uint8_t> pixels;
      if (!shadow) {
        const std::vector<std::uint8_t> plane = PatternImage(mt.w, mt.h);
        for (int k = 0; k < (mt.mode == 1 ? 1 : mt.d); ++k)  // (each layer or slice a shade brighter)
          for (std::size_t i = 0; i < plane.size(); ++i)
            pixels.push_back(std::uint8_t(plane[i] + (i % 4 == 3 ? 0 : 4 * k)));
      }
      for (const auto& [format_name, format] : formats) {
        if (shadow && format != sg::RGBA8) continue;  // (one row set: DEPTH_COMPONENT32F)
        // (An integer texture: NEAREST only, its other filters leave it incomplete; its texels the bytes as integers.)
        const bool integer = format == sg::RGBA8UI || format == sg::RGBA32UI;
        const Enum client = integer ? sg::RGBA_INTEGER : sg::RGBA;
        for (const MatrixFilter& mf : filters) {
          if (shadow && (mf.min != sg::NEAREST && mf.min != sg::LINEAR)) continue;
          if (integer && mf.min != sg::NEAREST) continue;
          const std::string row = std::string(mt.name) + ", " + (shadow ? "DEPTH_COMPONENT32F" : format_name) + ", " +
                                  mf.name;  // (--scene TEXT: the rows whose name contains TEXT)
          if (row.find(only) == std::string::npos) continue;
          std::printf("| %s | %s | %s |", mt.name, shadow ? "DEPTH_COMPONENT32F" : format_name, mf.name);
          std::fflush(stdout);
          for (const Enum wrap : wraps) {
            const bool mipmapped = mf.min != sg::NEAREST && mf.min != sg::LINEAR;
            const double sg_ms = [&] {
              wide::MatrixShader shader;
              shader.mode = mt.mode;
              shader.integer = integer;
              softgl::Context gl(1280, 720, g_options);
              softgl_setup(gl, quad);
              gl.BindTexture(mt.target, gl.GenTexture());
              if (shadow) {
                gl.TexImage2D(mt.target, 0, sg::DEPTH_COMPONENT32F, mt.w, mt.h, 0, sg::DEPTH_COMPONENT, sg::FLOAT,
                              depths.data());
                gl.TexParameteri(mt.target, sg::TEXTURE_COMPARE_MODE, sg::COMPARE_REF_TO_TEXTURE);
                gl.TexParameteri(mt.target, sg::TEXTURE_COMPARE_FUNC, sg::LEQUAL);
              } else if (mt.mode == 1) {
                for (int f = 0; f < 6; ++f)
                  gl.TexImage2D(sg::TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, format, mt.w, mt.h, 0, client,
                                sg::UNSIGNED_BYTE, pixels.data());
              } else if (mt.d > 1) {
                gl.TexImage3D(mt.target, 0, format, mt.w, mt.h, mt.d, 0, client, sg::UNSIGNED_BYTE, pixels.data());
              } else {
                gl.TexImage2D(mt.target, 0, format, mt.w, mt.h, 0, client, sg::UNSIGNED_BYTE, pixels.data());
              }
              if (mipmapped) gl.GenerateMipmap(mt.target);
              gl.TexParameteri(mt.target, sg::TEXTURE_MIN_FILTER, mf.min);
              gl.TexParameteri(mt.target, sg::TEXTURE_MAG_FILTER, mf.mag);
              for (const Enum pname : {sg::TEXTURE_WRAP_S, sg::TEXTURE_WRAP_T, sg::TEXTURE_WRAP_R})
                gl.TexParameteri(mt.target, pname, wrap);
              if (integer) gl.TexParameterIuiv(mt.target, sg::TEXTURE_BORDER_COLOR, border_integer);
              else gl.TexParameterfv(mt.target, sg::TEXTURE_BORDER_COLOR, border);
              gl.TexParameterf(mt.target, sg::TEXTURE_MAX_ANISOTROPY, mf.anisotropy);
              gl.UseProgram(shader);
              return TimeSoftgl(frames, gl, FrameSpec{false, false, 6, png[mt.mode]});
            }();
            const double gl_ms = softgl_only ? 1.0 : with_osmesa(1280, 720, [&] {
              gl_setup(quad);
              const GLenum t = GLenum(mt.target);
              GLuint tex;
              glGenTextures(1, &tex);
              glBindTexture(t, tex);
              if (shadow) {
                glTexImage2D(t, 0, GL_DEPTH_COMPONENT32F, mt.w, mt.h, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                             depths.data());
                glTexParameteri(t, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
                glTexParameteri(t, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
              } else if (mt.mode == 1) {
                for (int f = 0; f < 6; ++f)
                  glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GLint(format), mt.w, mt.h, 0,
                               GLenum(client), GL_UNSIGNED_BYTE, pixels.data());
              } else if (mt.d > 1) {
                glTexImage3D(t, 0, GLint(format), mt.w, mt.h, mt.d, 0, GLenum(client), GL_UNSIGNED_BYTE, pixels.data());
              } else {
                glTexImage2D(t, 0, GLint(format), mt.w, mt.h, 0, GLenum(client), GL_UNSIGNED_BYTE, pixels.data());
              }
              if (mipmapped) glGenerateMipmap(t);
              glTexParameteri(t, GL_TEXTURE_MIN_FILTER, GLint(mf.min));
              glTexParameteri(t, GL_TEXTURE_MAG_FILTER, GLint(mf.mag));
              for (const GLenum pname : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
                glTexParameteri(t, pname, GLint(wrap));
              if (integer) glTexParameterIuiv(t, GL_TEXTURE_BORDER_COLOR, border_integer);
              else glTexParameterfv(t, GL_TEXTURE_BORDER_COLOR, border);
              if (mf.anisotropy > 1.0f) glTexParameterf(t, GL_TEXTURE_MAX_ANISOTROPY_EXT, mf.anisotropy);
              Program(kPlaneVs, integer ? kMatrixIntegerFs[mt.mode] : kMatrixFs[mt.mode]);
              return TimeGl(frames, FrameSpec{false, false, 6, png[mt.mode]});
            });
            PrintCell(softgl_only, sg_ms, gl_ms, first_ms);
          }
          std::printf("\n");
        }
      }
    }
    return 0;
  }

  // --formats 1: the colour format matrix. Each cell 20 full-screen quads (FullScreenQuads, each nearer than the
  // last, so every fragment passes the depth test LESS), 1280 x 720, into a framebuffer object of renderbuffers:
  // the row's colour buffers (FRAMEBUFFER_SRGB enabled for SRGB8_ALPHA8) and the column's depth buffer, cleared
  // each frame; opaque, or blended with SRC_ALPHA, ONE_MINUS_SRC_ALPHA. The fragments are FormatShader's. Prints
  // softgl's time over llvmpipe's per cell, and in brackets softgl's time over its own in the first cell (RGBA8,
  // opaque, DEPTH24_STENCIL8).
  if (format_matrix) {
    const int fw = odd_size ? 1279 : 1280, fh = odd_size ? 719 : 720;
    using softgl::Enum;
    namespace sg = softgl;
    struct FormatRow {
      const char* name;
      std::vector<Enum> colour;
      int integer = 0;  // 1: unsigned integer buffers, 2: signed ones (FormatShader's integer outputs)
    };
    const FormatRow rows[] = {{"RGBA8", {sg::RGBA8}},
                              {"SRGB8_ALPHA8", {sg::SRGB8_ALPHA8}},
                              {"RGBA16F", {sg::RGBA16F}},
                              {"RG16F", {sg::RG16F}},
                              {"R16F", {sg::R16F}},
                              {"RGBA32F", {sg::RGBA32F}},
                              {"RG32F", {sg::RG32F}},
                              {"R32F", {sg::R32F}},
                              {"R11F_G11F_B10F", {sg::R11F_G11F_B10F}},
                              {"RGB565", {sg::RGB565}},
                              {"RGBA4", {sg::RGBA4}},
                              {"RGB5_A1", {sg::RGB5_A1}},
                              {"RGB10_A2", {sg::RGB10_A2}},
                              {"RG8", {sg::RG8}},
                              {"R8", {sg::R8}},
                              {"G-buffer RGBA8 + RGBA16F x 2 + R32F", {sg::RGBA8, sg::RGBA16F, sg::RGBA16F, sg::R32F}},
                              {"R32UI", {sg::R32UI}, 1},
                              {"RG16UI", {sg::RG16UI}, 1},
                              {"RGBA8UI", {sg::RGBA8UI}, 1},
                              {"RGBA32I", {sg::RGBA32I}, 2}};
    const std::pair<const char*, Enum> depths[] = {{"DEPTH24_STENCIL8", sg::DEPTH24_STENCIL8},
                                                   {"DEPTH_COMPONENT16", sg::DEPTH_COMPONENT16},
                                                   {"DEPTH_COMPONENT32F", sg::DEPTH_COMPONENT32F},
                                                   {"DEPTH32F_STENCIL8", sg::DEPTH32F_STENCIL8}};
    const Geometry quads = FullScreenQuads(20, 1.0f);
    const FrameSpec frame{true, false, 120, "bench_formats.png"};
    std::printf("Colour format matrix, %d x %d, %d thread(s), %d frames a cell: softgl / llvmpipe (softgl ms / ms of "
                "the first cell)\n\n| colour | blend | DEPTH24_STENCIL8 | DEPTH_COMPONENT16 | DEPTH_COMPONENT32F | "
                "DEPTH32F_STENCIL8 |\n|---|---|---|---|---|---|\n",
                fw, fh, threads, frames);
    double first_ms = 0.0;
    for (const FormatRow& row : rows)
      for (const bool blend : {false, true}) {
        const std::string name = std::string(row.name) + ", " + (blend ? "blended" : "opaque");
        if (name.find(only) == std::string::npos) continue;
        std::printf("| %s | %s |", row.name, blend ? "blended" : "opaque");
        std::fflush(stdout);
        const int n = int(row.colour.size());
        const bool srgb = row.colour[0] == sg::SRGB8_ALPHA8;
        for (const auto& [depth_name, depth] : depths) {
          const double sg_ms = [&] {
            wide::FormatShader shader;
            shader.outputs = n;
            shader.integer = row.integer != 0;
            softgl::Context gl(fw, fh, g_options);
            softgl_setup(gl, quads);
            gl.BindFramebuffer(sg::FRAMEBUFFER, gl.GenFramebuffer());
            Enum bufs[4];
            for (int o = 0; o < n; ++o) {
              const std::uint32_t rb = gl.GenRenderbuffer();
              gl.BindRenderbuffer(sg::RENDERBUFFER, rb);
              gl.RenderbufferStorage(sg::RENDERBUFFER, row.colour[std::size_t(o)], fw, fh);
              gl.FramebufferRenderbuffer(sg::FRAMEBUFFER, sg::COLOR_ATTACHMENT0 + Enum(o), sg::RENDERBUFFER, rb);
              bufs[o] = sg::COLOR_ATTACHMENT0 + Enum(o);
            }
            gl.DrawBuffers(n, bufs);
            const std::uint32_t rb = gl.GenRenderbuffer();
            gl.BindRenderbuffer(sg::RENDERBUFFER, rb);
            gl.RenderbufferStorage(sg::RENDERBUFFER, depth, fw, fh);
            const bool stencil = depth == sg::DEPTH24_STENCIL8 || depth == sg::DEPTH32F_STENCIL8;
            gl.FramebufferRenderbuffer(sg::FRAMEBUFFER, stencil ? sg::DEPTH_STENCIL_ATTACHMENT : sg::DEPTH_ATTACHMENT,
                                       sg::RENDERBUFFER, rb);
            if (srgb) gl.Enable(sg::FRAMEBUFFER_SRGB);
            gl.Enable(sg::DEPTH_TEST);
            if (blend) {
              gl.Enable(sg::BLEND);
              gl.BlendFunc(sg::SRC_ALPHA, sg::ONE_MINUS_SRC_ALPHA);
            }
            gl.UseProgram(shader);
            return TimeSoftgl(frames, gl, frame);
          }();
          const double gl_ms = softgl_only ? 1.0 : with_osmesa(fw, fh, [&] {
            gl_setup(quads);
            GLuint fbo;
            glGenFramebuffers(1, &fbo);
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            GLenum bufs[4];
            for (int o = 0; o < n; ++o) {
              GLuint rb;
              glGenRenderbuffers(1, &rb);
              glBindRenderbuffer(GL_RENDERBUFFER, rb);
              glRenderbufferStorage(GL_RENDERBUFFER, GLenum(row.colour[std::size_t(o)]), fw, fh);
              glFramebufferRenderbuffer(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + o), GL_RENDERBUFFER, rb);
              bufs[o] = GLenum(GL_COLOR_ATTACHMENT0 + o);
            }
            glDrawBuffers(n, bufs);
            GLuint rb;
            glGenRenderbuffers(1, &rb);
            glBindRenderbuffer(GL_RENDERBUFFER, rb);
            glRenderbufferStorage(GL_RENDERBUFFER, GLenum(depth), fw, fh);
            const bool stencil = depth == sg::DEPTH24_STENCIL8 || depth == sg::DEPTH32F_STENCIL8;
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                      GL_RENDERBUFFER, rb);
            if (srgb) glEnable(GL_FRAMEBUFFER_SRGB);
            glEnable(GL_DEPTH_TEST);
            if (blend) {
              glEnable(GL_BLEND);
              glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            }
            const std::string fs = FormatFs(n, row.integer);
            Program(kTexVs, fs.c_str());
            return TimeGl(frames, frame);
          });
          PrintCell(softgl_only, sg_ms, gl_ms, first_ms);
        }
        std::printf("\n");
      }
    return 0;
  }

  // --fetch 1: the texel fetch matrix. Each cell 4 full-screen quads (FullScreenQuads, no depth test), 1280 x 720,
  // whose fragments read one texel each (FetchShader): from a 1280 x 720 2D texture (PatternImage's bytes in the
  // row's format), a buffer texture holding the same texels, a 4-sample multisample texture and a 4-sample
  // multisample array of two layers (as the API leaves them: zero). Formats RGBA8, RGBA16F, RGBA32F and RGBA8UI
  // (not multisampled: at most one sample for integer formats). Prints softgl's time over llvmpipe's per cell, and
  // in brackets softgl's time over its own in the first cell (2D, RGBA8).
  if (fetch_matrix) {
    using softgl::Enum;
    namespace sg = softgl;
    const std::pair<const char*, Enum> formats[] = {
        {"RGBA8", sg::RGBA8}, {"RGBA16F", sg::RGBA16F}, {"RGBA32F", sg::RGBA32F}, {"RGBA8UI", sg::RGBA8UI}};
    const Geometry quads = FullScreenQuads(4, 1.0f);
    const FrameSpec frame{false, false, 24, "bench_fetch.png"};
    const std::vector<std::uint8_t> pattern = PatternImage(1280, 720);
    std::printf("Texel fetch matrix, %d thread(s), %d frames a cell: softgl / llvmpipe (softgl ms / ms of the first "
                "cell)\n\n| format | 2D | buffer | multisample | multisample array |\n|---|---|---|---|---|\n",
                threads, frames);
    double first_ms = 0.0;
    for (const auto& [format_name, format] : formats) {
      if (std::string(format_name).find(only) == std::string::npos) continue;
      const bool integer = format == sg::RGBA8UI;
      // The buffer texture's store: the pattern's texels in the format (halves, floats, or the bytes).
      std::vector<std::uint8_t> store;
      for (const std::uint8_t b : pattern) {
        if (format == sg::RGBA16F) {
          const std::uint16_t h = glm::packHalf1x16(float(b) / 255.0f);
          store.insert(store.end(), {std::uint8_t(h & 0xFF), std::uint8_t(h >> 8)});
        } else if (format == sg::RGBA32F) {
          const float f = float(b) / 255.0f;
          std::uint8_t bytes[4];
          std::memcpy(bytes, &f, 4);
          store.insert(store.end(), bytes, bytes + 4);
        } else {
          store.push_back(b);
        }
      }
      const Enum client = integer ? sg::RGBA_INTEGER : sg::RGBA;
      std::printf("| %s |", format_name);
      std::fflush(stdout);
      for (int mode = 0; mode < 4; ++mode) {
        if (integer && mode >= 2) {
          std::printf(" - |");
          continue;
        }
        const double sg_ms = [&] {
          wide::FetchShader shader;
          shader.mode = mode;
          shader.integer = integer;
          softgl::Context gl(1280, 720, g_options);
          softgl_setup(gl, quads);
          const std::uint32_t tex = gl.GenTexture();
          if (mode == 0) {
            gl.BindTexture(sg::TEXTURE_2D, tex);
            gl.TexImage2D(sg::TEXTURE_2D, 0, format, 1280, 720, 0, client, sg::UNSIGNED_BYTE, pattern.data());
            gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_MIN_FILTER, sg::NEAREST);
            gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_MAG_FILTER, sg::NEAREST);
          } else if (mode == 1) {
            const std::uint32_t buf = gl.GenBuffer();
            gl.BindBuffer(sg::TEXTURE_BUFFER, buf);
            gl.BufferData(sg::TEXTURE_BUFFER, std::ptrdiff_t(store.size()), store.data(), sg::STATIC_DRAW);
            gl.BindTexture(sg::TEXTURE_BUFFER, tex);
            gl.TexBuffer(sg::TEXTURE_BUFFER, format, buf);
          } else if (mode == 2) {
            gl.BindTexture(sg::TEXTURE_2D_MULTISAMPLE, tex);
            gl.TexImage2DMultisample(sg::TEXTURE_2D_MULTISAMPLE, 4, format, 1280, 720, true);
          } else {
            gl.BindTexture(sg::TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
            gl.TexImage3DMultisample(sg::TEXTURE_2D_MULTISAMPLE_ARRAY, 4, format, 1280, 720, 2, true);
          }
          gl.UseProgram(shader);
          return TimeSoftgl(frames, gl, frame);
        }();
        const double gl_ms = softgl_only ? 1.0 : with_osmesa(1280, 720, [&] {
          gl_setup(quads);
          GLuint tex;
          glGenTextures(1, &tex);
          if (mode == 0) {
            glBindTexture(GL_TEXTURE_2D, tex);
            glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), 1280, 720, 0, GLenum(client), GL_UNSIGNED_BYTE,
                         pattern.data());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
          } else if (mode == 1) {
            GLuint buf;
            glGenBuffers(1, &buf);
            glBindBuffer(GL_TEXTURE_BUFFER, buf);
            glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(store.size()), store.data(), GL_STATIC_DRAW);
            glBindTexture(GL_TEXTURE_BUFFER, tex);
            glTexBuffer(GL_TEXTURE_BUFFER, GLenum(format), buf);
          } else if (mode == 2) {
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
            glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GLenum(format), 1280, 720, GL_TRUE);
          } else {
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, tex);
            glTexImage3DMultisample(GL_TEXTURE_2D_MULTISAMPLE_ARRAY, 4, GLenum(format), 1280, 720, 2, GL_TRUE);
          }
          const std::string fs = FetchFs(mode, integer);
          Program(kTexVs, fs.c_str());
          return TimeGl(frames, frame);
        });
        PrintCell(softgl_only, sg_ms, gl_ms, first_ms);
      }
      std::printf("\n");
    }
    return 0;
  }

  const FrameSpec engine_frame{true, true, int(engine.indices.size()), "bench_engine.png"};
  const FrameSpec small_frame{true, false, 3000000, "bench_small.png"};
  const FrameSpec fill_frame{false, false, 300, "bench_fill.png"};
  const FrameSpec overdraw_frame{false, false, 120, "bench_overdraw.png"};
  std::vector<Scene> scenes;
  // A model drawn with the Blinn-Phong shader, one indexed draw with depth test and back-face culling.
  auto add_phong_scene = [&](const char* name, int w, int h, const Geometry& g, const glm::mat4& vp,
                             const glm::vec3& eye, const FrameSpec& frame) {
    scenes.push_back({name, w, h, "Mtri/s", double(g.indices.size() / 3),
                      [&g, &vp, &eye, &frame, w, h, &softgl_setup](int n) {
                        return WithShader<wide::PhongShader, scalar::PhongShader>([&](auto& shader) {
                          softgl::Context::Options options = g_options;
                          options.samples = frame.samples;
                          options.color_format = frame.color_format;
                          softgl::Context gl(w, h, options);
                          if (frame.color_format == softgl::SRGB8_ALPHA8) gl.Enable(softgl::FRAMEBUFFER_SRGB);
                          softgl_setup(gl, g);
                          shader.view_proj = vp;
                          shader.eye = eye;
                          gl.UseProgram(shader);
                          gl.Enable(softgl::DEPTH_TEST);
                          gl.Enable(softgl::CULL_FACE);
                          return TimeSoftgl(n, gl, frame);
                        });
                      },
                      [&g, &vp, &eye, &frame, w, h, &with_osmesa, &gl_setup](int n) {
                        return with_osmesa(w, h, [&] {
                          gl_setup(g);
                          const GLuint p = Program(kPhongVs, kPhongFs);
                          glUniformMatrix4fv(glGetUniformLocation(p, "vp"), 1, GL_FALSE, &vp[0][0]);
                          const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.8f, 0.5f));
                          glUniform3fv(glGetUniformLocation(p, "light"), 1, &light[0]);
                          glUniform3fv(glGetUniformLocation(p, "eye"), 1, &eye[0]);
                          glEnable(GL_DEPTH_TEST);
                          glEnable(GL_CULL_FACE);
                          return TimeGl(n, frame);
                        });
                      }});
  };
  FrameSpec engine_msaa_frame = engine_frame;
  engine_msaa_frame.samples = 4;
  engine_msaa_frame.png = "bench_engine_msaa.png";
  // The context's own multisampled framebuffer in its two other colour formats (llvmpipe: a framebuffer object of
  // the format, resolved into its RGBA8 context).
  FrameSpec engine_msaa_srgb_frame = engine_msaa_frame, engine_msaa_565_frame = engine_msaa_frame;
  engine_msaa_srgb_frame.color_format = softgl::SRGB8_ALPHA8;
  engine_msaa_srgb_frame.png = "bench_engine_msaa_srgb.png";
  engine_msaa_565_frame.color_format = softgl::RGB565;
  engine_msaa_565_frame.png = "bench_engine_msaa_565.png";
  if (have_engine) {
    add_phong_scene("model: 2CylinderEngine, Blinn-Phong", 1280, 720, engine, engine_vp, engine_eye, engine_frame);
    add_phong_scene("model: 2CylinderEngine, Blinn-Phong, 4x MSAA", 1280, 720, engine, engine_vp, engine_eye,
                    engine_msaa_frame);
    add_phong_scene("model: 2CylinderEngine, Blinn-Phong, 4x MSAA, SRGB8_ALPHA8", 1280, 720, engine, engine_vp,
                    engine_eye, engine_msaa_srgb_frame);
    add_phong_scene("model: 2CylinderEngine, Blinn-Phong, 4x MSAA, RGB565", 1280, 720, engine, engine_vp,
                    engine_eye, engine_msaa_565_frame);
  }
  // The subdivided Suzanne (251,904 triangles, assimp-testmodels' BLEND/SuzanneSubdiv_252.blend) at 1920x1080.
  Geometry suzanne;
  glm::mat4 suzanne_vp(1.0f);
  const bool have_suzanne = all_data && LoadModel("/usr/share/assimp/models/BLEND/SuzanneSubdiv_252.blend", suzanne,
                                                  suzanne_vp, 1920.0f / 1080.0f);
  const glm::vec3 suzanne_eye = glm::vec3(glm::inverse(suzanne_vp) * glm::vec4(0, 0, -1, 1));
  const FrameSpec suzanne_frame{true, true, int(suzanne.indices.size()), "bench_suzanne.png"};
  if (have_suzanne)
    add_phong_scene("model: SuzanneSubdiv_252, Blinn-Phong", 1920, 1080, suzanne, suzanne_vp, suzanne_eye,
                    suzanne_frame);
  const std::string head_dir = "../shared/assets/african_head";
  Geometry head;
  const bool have_head = all_data && LoadTexturedModel(head_dir + "/african_head.obj", head);
  const glm::vec3 head_eye(0.6f, 0.3f, 2.6f);
  const glm::mat4 head_vp = glm::perspective(glm::radians(40.0f), 1280.0f / 720.0f, 0.5f, 10.0f) *
                            glm::lookAt(head_eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  const char* maps[3] = {"/african_head_diffuse.tga", "/african_head_nm_tangent.tga", "/african_head_spec.tga"};
  const FrameSpec head_frame{true, true, int(head.indices.size()), "bench_head.png"};
  if (have_head)
    scenes.push_back({"textured model: african_head, diffuse + normal + specular maps, trilinear", 1280, 720, "Mtri/s",
                      double(head.indices.size() / 3),
                      [&](int n) {
                        return WithShader<wide::HeadShader, scalar::HeadShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, head);
                          for (int u = 0; u < 3; ++u) {
                            gl.ActiveTexture(softgl::TEXTURE0 + softgl::Enum(u));
                            gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
                            gl.TexImage2DFromFile(softgl::TEXTURE_2D, head_dir + maps[u], true);
                            gl.GenerateMipmap(softgl::TEXTURE_2D);
                            gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER,
                                             softgl::LINEAR_MIPMAP_LINEAR);
                          }
                          shader.view_proj = head_vp;
                          shader.eye = head_eye;
                          gl.UseProgram(shader);
                          gl.Enable(softgl::DEPTH_TEST);
                          gl.Enable(softgl::CULL_FACE);
                          return TimeSoftgl(n, gl, head_frame);
                        });
                      },
                      [&](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(head);
                          const GLuint p = Program(kHeadVs, kHeadFs);
                          const char* names[3] = {"diffuse_map", "normal_map", "spec_map"};
                          for (int u = 0; u < 3; ++u) {
                            // The same texels: decoded by stb_image (softgl::ReadImage), rows flipped bottom first.
                            softgl::Image img;
                            softgl::ReadImage(head_dir + maps[u], img);
                            std::vector<std::uint8_t> flipped(img.rgba.size());
                            const std::size_t row = std::size_t(img.width) * 4;
                            for (int y = 0; y < img.height; ++y)
                              std::memcpy(&flipped[std::size_t(y) * row], &img.rgba[std::size_t(img.height - 1 - y) * row], row);
                            GLuint tex;
                            glGenTextures(1, &tex);
                            glActiveTexture(GL_TEXTURE0 + GLenum(u));
                            glBindTexture(GL_TEXTURE_2D, tex);
                            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                                         flipped.data());
                            glGenerateMipmap(GL_TEXTURE_2D);
                            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                            glUniform1i(glGetUniformLocation(p, names[u]), u);
                          }
                          glUniformMatrix4fv(glGetUniformLocation(p, "vp"), 1, GL_FALSE, &head_vp[0][0]);
                          const glm::vec3 light = glm::normalize(glm::vec3(0.4f, 0.6f, 0.8f));
                          glUniform3fv(glGetUniformLocation(p, "light"), 1, &light[0]);
                          glUniform3fv(glGetUniformLocation(p, "eye"), 1, &head_eye[0]);
                          glEnable(GL_DEPTH_TEST);
                          glEnable(GL_CULL_FACE);
                          return TimeGl(n, head_frame);
                        });
                      }});
  // The small triangles' set-up, shared by the scene that draws them at once and the one that draws them one by one.
  auto small_softgl = [&](softgl::Context& gl, const softgl::Program& shader) {
    softgl_setup(gl, tris);
    gl.UseProgram(shader);
    gl.Enable(softgl::DEPTH_TEST);
  };
  auto small_gl = [&] {
    gl_setup(tris);
    const GLuint p = Program(kFlatVs, kFlatFs);
    glUniform4f(glGetUniformLocation(p, "color"), 0.2f, 0.6f, 0.9f, 1.0f);
    glEnable(GL_DEPTH_TEST);
  };
  scenes.push_back({"many small triangles: 1,000,000, flat, depth test", 1280, 720, "Mtri/s", 1e6,
                    [&](int n) {
                      return WithShader<wide::FlatShader, scalar::FlatShader>([&](auto& shader) {
                        softgl::Context gl(1280, 720, g_options);
                        small_softgl(gl, shader);
                        return TimeSoftgl(n, gl, small_frame);
                      });
                    },
                    [&](int n) {
                      return with_osmesa(1280, 720, [&] {
                        small_gl();
                        return TimeGl(n, small_frame);
                      });
                    }});
  // The geometry stage: 200,000 points, each made a square of about 5 x 5 pixels (two triangles) by a geometry
  // stage, depth-tested: the stage's cost per primitive beside what drawing the squares costs.
  constexpr int kSquares = 200000;
  std::vector<float> square_points;
  {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-0.98f, 0.98f);
    for (int i = 0; i < kSquares; ++i) square_points.insert(square_points.end(), {u(rng), u(rng), u(rng)});
  }
  scenes.push_back({"geometry stage: 200,000 points made squares", 1280, 720, "Mprim/s", double(kSquares),
                    [&](int n) {
                      softgl::Context gl(1280, 720, g_options);
                      gl.BindVertexArray(gl.GenVertexArray());
                      gl.BindBuffer(softgl::ARRAY_BUFFER, gl.GenBuffer());
                      gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(square_points.size() * 4), square_points.data());
                      gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, 12, 0);
                      gl.EnableVertexAttribArray(0);
                      gl.Enable(softgl::DEPTH_TEST);
                      wide::SquaresShader shader;
                      gl.UseProgram(shader);
                      return MedianMs(n, [&] {
                        gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
                        gl.DrawArrays(softgl::POINTS, 0, kSquares);
                        gl.Finish();
                      });
                    },
                    [&](int n) {
                      return with_osmesa(1280, 720, [&] {
                        GLuint vao = 0, vbo = 0;
                        glGenVertexArrays(1, &vao);
                        glBindVertexArray(vao);
                        glGenBuffers(1, &vbo);
                        glBindBuffer(GL_ARRAY_BUFFER, vbo);
                        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(square_points.size() * 4), square_points.data(), GL_STATIC_DRAW);
                        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
                        glEnableVertexAttribArray(0);
                        glEnable(GL_DEPTH_TEST);
                        const GLuint p = Program(kSquaresVs, kSquaresFs, kSquaresGs);
                        glUniform2f(glGetUniformLocation(p, "half_size"), 0.004f, 0.007f);
                        return MedianMs(n, [&] {
                          glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                          glDrawArrays(GL_POINTS, 0, kSquares);
                          glFinish();
                        });
                      });
                    }});
  // The per-draw cost: the first 10,000 of those triangles, one draw call each (a scene of many small objects);
  // then the same draws with the shader's colour changed before each, as a scene of many objects changes a uniform
  // per object (no two consecutive draws can then share a shader copy or render as one).
  constexpr int kDraws = 10000;
  auto draw_colour = [](int i) { return glm::vec4(float(i % 7) / 6.0f, float(i % 5) / 4.0f, 0.5f, 1.0f); };
  auto add_draws_scene = [&](const char* name, bool change_uniform) {
    scenes.push_back({name, 1280, 720, "Mdraw/s", double(kDraws),
                      [&, change_uniform](int n) {
                        return WithShader<wide::FlatShader, scalar::FlatShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          small_softgl(gl, shader);
                          return MedianMs(n, [&] {
                            gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
                            for (int i = 0; i < kDraws; ++i) {
                              if (change_uniform) shader.color = draw_colour(i);
                              gl.DrawArrays(softgl::TRIANGLES, 3 * i, 3);
                            }
                            gl.Finish();
                          });
                        });
                      },
                      [&, change_uniform](int n) {
                        return with_osmesa(1280, 720, [&] {
                          small_gl();
                          GLint program = 0;
                          glGetIntegerv(GL_CURRENT_PROGRAM, &program);
                          const GLint colour = glGetUniformLocation(GLuint(program), "color");
                          return MedianMs(n, [&] {
                            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                            for (int i = 0; i < kDraws; ++i) {
                              if (change_uniform) {
                                const glm::vec4 c = draw_colour(i);
                                glUniform4f(colour, c.r, c.g, c.b, c.a);
                              }
                              glDrawArrays(GL_TRIANGLES, 3 * i, 3);
                            }
                            glFinish();
                          });
                        });
                      }});
  };
  add_draws_scene("many draws: 10,000 draw calls of one small triangle each", false);
  add_draws_scene("many draws, a uniform changed before each", true);
  // The same 10,000 triangles as 10,000 objects of their own: each its own vertex array over its own buffer, bound
  // before its draw (how a scene of many separately loaded meshes draws).
  auto vertex_of_draw = [&](int i) { return tris.vertices.data() + std::size_t(i) * 3 * std::size_t(tris.floats); };
  scenes.push_back({"many draws, each its own vertex array", 1280, 720, "Mdraw/s", double(kDraws),
                    [&](int n) {
                      return WithShader<wide::FlatShader, scalar::FlatShader>([&](auto& shader) {
                        softgl::Context gl(1280, 720, g_options);
                        small_softgl(gl, shader);
                        std::vector<std::uint32_t> arrays(kDraws);
                        for (int i = 0; i < kDraws; ++i) {
                          arrays[std::size_t(i)] = gl.GenVertexArray();
                          gl.BindVertexArray(arrays[std::size_t(i)]);
                          gl.BindBuffer(softgl::ARRAY_BUFFER, gl.GenBuffer());
                          gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(3 * tris.floats * 4), vertex_of_draw(i));
                          gl.VertexAttributePointer(0, tris.position, softgl::FLOAT, false, tris.floats * 4, 0);
                          gl.EnableVertexAttribArray(0);
                        }
                        return MedianMs(n, [&] {
                          gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
                          for (int i = 0; i < kDraws; ++i) {
                            gl.BindVertexArray(arrays[std::size_t(i)]);
                            gl.DrawArrays(softgl::TRIANGLES, 0, 3);
                          }
                          gl.Finish();
                        });
                      });
                    },
                    [&](int n) {
                      return with_osmesa(1280, 720, [&] {
                        small_gl();
                        std::vector<GLuint> arrays(kDraws), buffers(kDraws);
                        glGenVertexArrays(kDraws, arrays.data());
                        glGenBuffers(kDraws, buffers.data());
                        for (int i = 0; i < kDraws; ++i) {
                          glBindVertexArray(arrays[std::size_t(i)]);
                          glBindBuffer(GL_ARRAY_BUFFER, buffers[std::size_t(i)]);
                          glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(3 * tris.floats * 4), vertex_of_draw(i), GL_STATIC_DRAW);
                          glVertexAttribPointer(0, tris.position, GL_FLOAT, GL_FALSE, tris.floats * 4, nullptr);
                          glEnableVertexAttribArray(0);
                        }
                        return MedianMs(n, [&] {
                          glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                          for (int i = 0; i < kDraws; ++i) {
                            glBindVertexArray(arrays[std::size_t(i)]);
                            glDrawArrays(GL_TRIANGLES, 0, 3);
                          }
                          glFinish();
                        });
                      });
                    }});
  scenes.push_back({"fill rate: 50 blended full-screen quads", 1920, 1080, "Mpixel/s", 50.0 * 1920 * 1080,
                    [&](int n) {
                      return WithShader<wide::FlatShader, scalar::FlatShader>([&](auto& shader) {
                        softgl::Context gl(1920, 1080, g_options);
                        softgl_setup(gl, blend_quads);
                        shader.color = glm::vec4(0.9f, 0.5f, 0.2f, 0.1f);
                        gl.UseProgram(shader);
                        gl.Enable(softgl::BLEND);
                        gl.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
                        return TimeSoftgl(n, gl, fill_frame);
                      });
                    },
                    [&](int n) {
                      return with_osmesa(1920, 1080, [&] {
                        gl_setup(blend_quads);
                        const GLuint p = Program(kFlatVs, kFlatFs);
                        glUniform4f(glGetUniformLocation(p, "color"), 0.9f, 0.5f, 0.2f, 0.1f);
                        glEnable(GL_BLEND);
                        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                        return TimeGl(n, fill_frame);
                      });
                    }});
  // Depth-sorted opaque quads (FlatShader, depth test LESS), 1280 x 720: front to back (each quad farther than the
  // last: all but the first hidden, what hierarchical depth drops), and back to front (each nearer: every fragment
  // passes, nothing to drop; what its upkeep costs).
  for (const bool front_to_back : {true, false}) {
    const Geometry& quads = front_to_back ? sorted_quads_far : sorted_quads_near;
    const FrameSpec frame{true, false, int(quads.vertices.size() / 5), "bench_sorted.png"};
    scenes.push_back({front_to_back ? "depth-sorted quads: 20 full-screen, front to back"
                                    : "depth-sorted quads: 20 full-screen, back to front",
                      1280, 720, "Mpixel/s", 20.0 * 1280 * 720,
                      [&, frame](int n) {
                        return WithShader<wide::FlatShader, scalar::FlatShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, quads);
                          gl.UseProgram(shader);
                          gl.Enable(softgl::DEPTH_TEST);
                          return TimeSoftgl(n, gl, frame);
                        });
                      },
                      [&, frame](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(quads);
                          Program(kFlatVs, kFlatFs);
                          glEnable(GL_DEPTH_TEST);
                          return TimeGl(n, frame);
                        });
                      }});
  }
  // Blits into 1920 x 1080, each timed alone (ten a frame): a copy of a framebuffer object's RGBA8 renderbuffer into
  // the context's framebuffer (NEAREST, the same rectangle), resolves of 4-sample renderbuffers into single-sampled
  // ones of the same format (RGBA8, RGBA16F, RGB565), as an HDR or small-memory pipeline ends its frame; then the
  // blits that are not plain copies: an image turned upside down (a y-down convention), a 1280 x 720 frame scaled to
  // the window (NEAREST and LINEAR), framebuffer objects of other formats into the RGBA8 window, and a LINEAR halving
  // of an RGBA16F image (a bloom chain's first step).
  struct BlitCase {
    const char* name;
    softgl::Enum format;
    int samples;          // of the source; 0: single-sampled
    int src_w, src_h;     // the source's size (the destination is 1920 x 1080)
    bool flip;            // the destination rectangle upside down
    softgl::Enum filter;
    softgl::Enum into;    // the destination's format; 0: the context's framebuffer (RGBA8)
  };
  static const BlitCase kBlits[] = {
      {"blit: RGBA8 framebuffer object copied to the window, 1920x1080", softgl::RGBA8, 0, 1920, 1080, false,
       softgl::NEAREST, 0},
      {"blit: 4x MSAA RGBA8 resolved, 1920x1080", softgl::RGBA8, 4, 1920, 1080, false, softgl::NEAREST, softgl::RGBA8},
      {"blit: 4x MSAA RGBA16F resolved, 1920x1080", softgl::RGBA16F, 4, 1920, 1080, false, softgl::NEAREST,
       softgl::RGBA16F},
      {"blit: 4x MSAA RGB565 resolved, 1920x1080", softgl::RGB565, 4, 1920, 1080, false, softgl::NEAREST,
       softgl::RGB565},
      {"blit: RGBA8 turned upside down into the window, 1920x1080", softgl::RGBA8, 0, 1920, 1080, true,
       softgl::NEAREST, 0},
      {"blit: RGBA8 1280x720 scaled to the window, NEAREST, 1920x1080", softgl::RGBA8, 0, 1280, 720, false,
       softgl::NEAREST, 0},
      {"blit: RGBA8 1280x720 scaled to the window, LINEAR, 1920x1080", softgl::RGBA8, 0, 1280, 720, false,
       softgl::LINEAR, 0},
      {"blit: RGBA16F into the RGBA8 window, 1920x1080", softgl::RGBA16F, 0, 1920, 1080, false, softgl::NEAREST, 0},
      {"blit: RGB565 into the RGBA8 window, 1920x1080", softgl::RGB565, 0, 1920, 1080, false, softgl::NEAREST, 0},
      {"blit: RGBA16F 3840x2160 halved, LINEAR, into RGBA16F 1920x1080", softgl::RGBA16F, 0, 3840, 2160, false,
       softgl::LINEAR, softgl::RGBA16F}};
  for (const BlitCase& bc : kBlits) {
    constexpr int kW = 1920, kH = 1080, kBlitsPerFrame = 10;
    scenes.push_back({bc.name, kW, kH, "Mpixel/s", double(kBlitsPerFrame) * kW * kH,
                      [&bc](int n) {
                        softgl::Context gl(kW, kH, g_options);
                        std::uint32_t fbo[2] = {gl.GenFramebuffer(), gl.GenFramebuffer()};
                        for (int k = 0; k < (bc.into ? 2 : 1); ++k) {
                          const std::uint32_t rb = gl.GenRenderbuffer();
                          gl.BindRenderbuffer(softgl::RENDERBUFFER, rb);
                          gl.RenderbufferStorageMultisample(softgl::RENDERBUFFER, k == 0 ? bc.samples : 0,
                                                            k == 0 ? bc.format : bc.into, k == 0 ? bc.src_w : kW,
                                                            k == 0 ? bc.src_h : kH);
                          gl.BindFramebuffer(softgl::FRAMEBUFFER, fbo[k]);
                          gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0,
                                                     softgl::RENDERBUFFER, rb);
                          gl.ClearColor(0.25f * float(k + 1), 0.5f, 0.75f, 1.0f);
                          gl.Clear(softgl::COLOR_BUFFER_BIT);
                        }
                        gl.BindFramebuffer(softgl::READ_FRAMEBUFFER, fbo[0]);
                        gl.BindFramebuffer(softgl::DRAW_FRAMEBUFFER, bc.into ? fbo[1] : 0);
                        return MedianMs(n, [&] {
                          for (int i = 0; i < kBlitsPerFrame; ++i)
                            gl.BlitFramebuffer(0, 0, bc.src_w, bc.src_h, 0, bc.flip ? kH : 0, kW, bc.flip ? 0 : kH,
                                               softgl::COLOR_BUFFER_BIT, bc.filter);
                          gl.Finish();
                        });
                      },
                      [&bc, &with_osmesa](int n) {
                        return with_osmesa(kW, kH, [&] {
                          GLuint fbo[2], rb[2];
                          glGenFramebuffers(2, fbo);
                          glGenRenderbuffers(2, rb);
                          for (int k = 0; k < (bc.into ? 2 : 1); ++k) {
                            glBindRenderbuffer(GL_RENDERBUFFER, rb[k]);
                            glRenderbufferStorageMultisample(GL_RENDERBUFFER, k == 0 ? bc.samples : 0,
                                                             k == 0 ? bc.format : bc.into, k == 0 ? bc.src_w : kW,
                                                             k == 0 ? bc.src_h : kH);
                            glBindFramebuffer(GL_FRAMEBUFFER, fbo[k]);
                            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[k]);
                            glClearColor(0.25f * float(k + 1), 0.5f, 0.75f, 1.0f);
                            glClear(GL_COLOR_BUFFER_BIT);
                          }
                          glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
                          glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bc.into ? fbo[1] : 0);
                          const double ms = MedianMs(n, [&] {
                            for (int i = 0; i < kBlitsPerFrame; ++i)
                              glBlitFramebuffer(0, 0, bc.src_w, bc.src_h, 0, bc.flip ? kH : 0, kW, bc.flip ? 0 : kH,
                                                GL_COLOR_BUFFER_BIT, bc.filter);
                            glFinish();
                          });
                          glBindFramebuffer(GL_FRAMEBUFFER, 0);
                          return ms;
                        });
                      }});
  }
  // Reading back 1920 x 1080 with ReadPixels, ten reads a frame: the RGBA8 window as RGBA bytes (what every program
  // that saves its image does) and as floats, and an RGBA16F framebuffer object as floats and as bytes.
  struct ReadCase {
    const char* name;
    softgl::Enum source;  // 0: the context's framebuffer (RGBA8), else a renderbuffer of that format
    softgl::Enum type;
  };
  static const ReadCase kReads[] = {
      {"read back: ReadPixels of the RGBA8 window as RGBA, UNSIGNED_BYTE, 1920x1080", 0, softgl::UNSIGNED_BYTE},
      {"read back: ReadPixels of the RGBA8 window as RGBA, FLOAT, 1920x1080", 0, softgl::FLOAT},
      {"read back: ReadPixels of RGBA16F as RGBA, FLOAT, 1920x1080", softgl::RGBA16F, softgl::FLOAT},
      {"read back: ReadPixels of RGBA16F as RGBA, UNSIGNED_BYTE, 1920x1080", softgl::RGBA16F, softgl::UNSIGNED_BYTE}};
  for (const ReadCase& rc : kReads) {
    constexpr int kW = 1920, kH = 1080, kReadsPerFrame = 10;
    const std::size_t bytes = std::size_t(kW) * kH * 4 * (rc.type == softgl::FLOAT ? 4 : 1);
    scenes.push_back({rc.name, kW, kH, "Mpixel/s", double(kReadsPerFrame) * kW * kH,
                      [&rc, bytes](int n) {
                        softgl::Context gl(kW, kH, g_options);
                        if (rc.source) {
                          gl.BindFramebuffer(softgl::FRAMEBUFFER, gl.GenFramebuffer());
                          const std::uint32_t rb = gl.GenRenderbuffer();
                          gl.BindRenderbuffer(softgl::RENDERBUFFER, rb);
                          gl.RenderbufferStorage(softgl::RENDERBUFFER, rc.source, kW, kH);
                          gl.FramebufferRenderbuffer(softgl::FRAMEBUFFER, softgl::COLOR_ATTACHMENT0,
                                                     softgl::RENDERBUFFER, rb);
                        }
                        gl.ClearColor(0.25f, 0.5f, 0.75f, 1.0f);
                        gl.Clear(softgl::COLOR_BUFFER_BIT);
                        std::vector<std::uint8_t> out(bytes);
                        return MedianMs(n, [&] {
                          for (int i = 0; i < kReadsPerFrame; ++i)
                            gl.ReadPixels(0, 0, kW, kH, softgl::RGBA, rc.type, out.data());
                        });
                      },
                      [&rc, bytes, &with_osmesa](int n) {
                        return with_osmesa(kW, kH, [&] {
                          GLuint fbo = 0, rb = 0;
                          if (rc.source) {
                            glGenFramebuffers(1, &fbo);
                            glGenRenderbuffers(1, &rb);
                            glBindRenderbuffer(GL_RENDERBUFFER, rb);
                            glRenderbufferStorage(GL_RENDERBUFFER, rc.source, kW, kH);
                            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
                            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
                          }
                          glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
                          glClear(GL_COLOR_BUFFER_BIT);
                          std::vector<std::uint8_t> out(bytes);
                          const double ms = MedianMs(n, [&] {
                            for (int i = 0; i < kReadsPerFrame; ++i)
                              glReadPixels(0, 0, kW, kH, GL_RGBA, rc.type, out.data());
                          });
                          glBindFramebuffer(GL_FRAMEBUFFER, 0);
                          return ms;
                        });
                      }});
  }
  // Loading a texture: TexImage2D of a 1024 x 1024 image, then GenerateMipmap, as a model loader does for each of
  // its textures (one a frame).
  struct UploadCase {
    const char* name;
    softgl::Enum internal, format, type;
  };
  static const UploadCase kUploads[] = {
      {"upload: TexImage2D and GenerateMipmap, RGBA8 from RGBA bytes, 1024^2", softgl::RGBA8, softgl::RGBA,
       softgl::UNSIGNED_BYTE},
      {"upload: TexImage2D and GenerateMipmap, SRGB8_ALPHA8 from RGBA bytes, 1024^2", softgl::SRGB8_ALPHA8,
       softgl::RGBA, softgl::UNSIGNED_BYTE},
      {"upload: TexImage2D and GenerateMipmap, RGB8 from RGB bytes, 1024^2", softgl::RGB8, softgl::RGB,
       softgl::UNSIGNED_BYTE},
      {"upload: TexImage2D and GenerateMipmap, RGBA16F from RGBA floats, 1024^2", softgl::RGBA16F, softgl::RGBA,
       softgl::FLOAT}};
  constexpr int kSize = 1024;
  // The client image: random bytes, or (FLOAT) floats in [0, 1.3).
  static const auto UploadData = [](softgl::Enum type) {
    std::vector<std::uint8_t> data(std::size_t(kSize) * kSize * 16);
    std::uint32_t seed = 1;
    for (std::uint8_t& b : data) b = std::uint8_t((seed = seed * 1664525u + 1013904223u) >> 24);
    if (type == softgl::FLOAT)
      for (std::size_t i = 0; i < data.size() / 4; ++i) {
        const float v = float(data[i]) / 200.0f;
        std::memcpy(&data[4 * i], &v, 4);
      }
    return data;
  };
  for (const UploadCase& uc : kUploads) {
    scenes.push_back({uc.name, kSize, kSize, "Mtexel/s", double(kSize) * kSize,
                      [&uc](int n) {
                        const std::vector<std::uint8_t> data = UploadData(uc.type);
                        softgl::Context gl(64, 64, g_options);
                        gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
                        return MedianMs(n, [&] {
                          gl.TexImage2D(softgl::TEXTURE_2D, 0, uc.internal, kSize, kSize, 0, uc.format, uc.type,
                                        data.data());
                          gl.GenerateMipmap(softgl::TEXTURE_2D);
                          gl.Finish();
                        });
                      },
                      [&uc, &with_osmesa](int n) {
                        return with_osmesa(64, 64, [&] {
                          const std::vector<std::uint8_t> data = UploadData(uc.type);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_2D, tex);
                          const double ms = MedianMs(n, [&] {
                            glTexImage2D(GL_TEXTURE_2D, 0, GLint(uc.internal), kSize, kSize, 0, uc.format, uc.type,
                                         data.data());
                            glGenerateMipmap(GL_TEXTURE_2D);
                            glFinish();
                          });
                          glDeleteTextures(1, &tex);
                          return ms;
                        });
                      }});
  }
  // Textured overdraw with an RGBA8 texture, and the same with an sRGB one (texels decoded before filtering).
  for (const bool srgb : {false, true}) {
    scenes.push_back({srgb ? "textured overdraw, sRGB texture: 20 quads, trilinear, 1024^2"
                           : "textured overdraw: 20 quads, trilinear, 1024^2",
                      1920, 1080, "Mpixel/s", 20.0 * 1920 * 1080,
                      [&, srgb](int n) {
                        return WithShader<wide::TextureShader, scalar::TextureShader>([&](auto& shader) {
                          softgl::Context gl(1920, 1080, g_options);
                          softgl_setup(gl, tex_quads);
                          gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
                          gl.TexImage2D(softgl::TEXTURE_2D, 0, srgb ? softgl::SRGB8_ALPHA8 : softgl::RGBA8, 1024, 1024, 0,
                                        softgl::RGBA, softgl::UNSIGNED_BYTE, texture.data());
                          gl.GenerateMipmap(softgl::TEXTURE_2D);
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::LINEAR_MIPMAP_LINEAR);
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, overdraw_frame);
                        });
                      },
                      [&, srgb](int n) {
                        return with_osmesa(1920, 1080, [&] {
                          gl_setup(tex_quads);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_2D, tex);
                          glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, 1024, 1024, 0, GL_RGBA,
                                       GL_UNSIGNED_BYTE, texture.data());
                          glGenerateMipmap(GL_TEXTURE_2D);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                          Program(kTexVs, kTexFs);
                          return TimeGl(n, overdraw_frame);
                        });
                      }});
  }

  // texelFetch: four full-screen quads each reading its pixel of a 1280 x 720 RGBA16F texture (a deferred
  // renderer's G-buffer read).
  {
    const Geometry fetch_quads = FullScreenQuads(4, 1.0f);
    const FrameSpec fetch_frame{false, false, 24, "bench_fetch.png"};
    std::vector<std::uint8_t> gbuffer;
    for (int i = 0; i < 1280 * 720 && all_data; ++i)
      gbuffer.insert(gbuffer.end(), {std::uint8_t(i), std::uint8_t(i >> 8), std::uint8_t(i >> 16), 255});
    scenes.push_back({"texelFetch: 4 full-screen quads, RGBA16F 1280x720", 1280, 720, "Mpixel/s", 4.0 * 1280 * 720,
                      [&, fetch_quads, fetch_frame, gbuffer](int n) {
                        return WithShader<wide::TextureShader, scalar::TextureShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, fetch_quads);
                          gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
                          gl.TexImage2D(softgl::TEXTURE_2D, 0, softgl::RGBA16F, 1280, 720, 0, softgl::RGBA,
                                        softgl::UNSIGNED_BYTE, gbuffer.data());
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, softgl::NEAREST);
                          shader.fetch = true;
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, fetch_frame);
                        });
                      },
                      [&, fetch_quads, fetch_frame, gbuffer](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(fetch_quads);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_2D, tex);
                          glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, 1280, 720, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                                       gbuffer.data());
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
                          Program(kTexVs, kFetchFs);
                          return TimeGl(n, fetch_frame);
                        });
                      }});
  }

  // Sampler states: a textured ground plane in perspective (GroundPlane), 1280 x 720, a 256 x 256 texture with its
  // mip chain (250 x 250 in one row), only the state changing from row to row.
  using softgl::Enum;
  struct SamplerState {
    const char* name;  // the scene's
    Enum format;
    int size;
    Enum min_filter, mag_filter, wrap;
    float anisotropy;
  };
  namespace sg = softgl;
  static const SamplerState kSamplerStates[] = {
      {"sampler: REPEAT, trilinear", sg::RGBA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::REPEAT, 1},
      {"sampler: CLAMP_TO_EDGE, trilinear", sg::RGBA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::CLAMP_TO_EDGE, 1},
      {"sampler: MIRRORED_REPEAT, trilinear", sg::RGBA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR,
       sg::MIRRORED_REPEAT, 1},
      {"sampler: REPEAT, trilinear, 250 x 250", sg::RGBA8, 250, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::REPEAT, 1},
      {"sampler: REPEAT, LINEAR / LINEAR", sg::RGBA8, 256, sg::LINEAR, sg::LINEAR, sg::REPEAT, 1},
      {"sampler: CLAMP_TO_BORDER, trilinear", sg::RGBA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR,
       sg::CLAMP_TO_BORDER, 1},
      {"sampler: REPEAT, NEAREST_MIPMAP_NEAREST / NEAREST", sg::RGBA8, 256, sg::NEAREST_MIPMAP_NEAREST, sg::NEAREST,
       sg::REPEAT, 1},
      {"sampler: REPEAT, LINEAR_MIPMAP_NEAREST / LINEAR", sg::RGBA8, 256, sg::LINEAR_MIPMAP_NEAREST, sg::LINEAR,
       sg::REPEAT, 1},
      {"sampler: CLAMP_TO_EDGE, trilinear, 16x anisotropic", sg::RGBA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR,
       sg::CLAMP_TO_EDGE, 16},
      {"sampler: SRGB8_ALPHA8, MIRRORED_REPEAT, trilinear", sg::SRGB8_ALPHA8, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR,
       sg::MIRRORED_REPEAT, 1},
      {"sampler: RGBA16F, REPEAT, trilinear", sg::RGBA16F, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::REPEAT, 1},
      {"sampler: RGBA32F, REPEAT, trilinear", sg::RGBA32F, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::REPEAT, 1},
      {"sampler: RGB565, REPEAT, trilinear", sg::RGB565, 256, sg::LINEAR_MIPMAP_LINEAR, sg::LINEAR, sg::REPEAT, 1},
  };
  const Geometry plane = GroundPlane(40.0f);
  const FrameSpec plane_frame{false, false, 6, "bench_sampler.png"};
  for (const SamplerState& st : kSamplerStates) {
    const std::vector<std::uint8_t> pixels = all_data ? PatternTexture(st.size) : std::vector<std::uint8_t>{};
    scenes.push_back({st.name, 1280, 720, "Mpixel/s", 1280.0 * 720 / 2,
                      [&, st, pixels](int n) {
                        return WithShader<wide::PlaneShader, scalar::PlaneShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, plane);
                          gl.BindTexture(softgl::TEXTURE_2D, gl.GenTexture());
                          gl.TexImage2D(softgl::TEXTURE_2D, 0, st.format, st.size, st.size, 0, softgl::RGBA,
                                        softgl::UNSIGNED_BYTE, pixels.data());
                          gl.GenerateMipmap(softgl::TEXTURE_2D);
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MIN_FILTER, st.min_filter);
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_MAG_FILTER, st.mag_filter);
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_S, st.wrap);
                          gl.TexParameteri(softgl::TEXTURE_2D, softgl::TEXTURE_WRAP_T, st.wrap);
                          gl.TexParameterf(softgl::TEXTURE_2D, softgl::TEXTURE_MAX_ANISOTROPY, st.anisotropy);
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, plane_frame);
                        });
                      },
                      [&, st, pixels](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(plane);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_2D, tex);
                          glTexImage2D(GL_TEXTURE_2D, 0, GLint(st.format), st.size, st.size, 0, GL_RGBA,
                                       GL_UNSIGNED_BYTE, pixels.data());
                          glGenerateMipmap(GL_TEXTURE_2D);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(st.min_filter));
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(st.mag_filter));
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(st.wrap));
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(st.wrap));
                          if (st.anisotropy > 1.0f)
                            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, st.anisotropy);
                          Program(kPlaneVs, kTexFs);
                          return TimeGl(n, plane_frame);
                        });
                      }});
  }
  // The same plane with a cube map (six 256 x 256 faces, CLAMP_TO_EDGE) and a 2D array (four 256 x 256 layers,
  // REPEAT), RGBA8, trilinear.
  for (const bool cube : {true, false}) {
    const std::vector<std::uint8_t> pixels = all_data ? PatternTexture(256) : std::vector<std::uint8_t>{};
    std::vector<std::uint8_t> layers;
    for (int i = 0; i < 4 && all_data; ++i) layers.insert(layers.end(), pixels.begin(), pixels.end());
    const Enum target = cube ? sg::TEXTURE_CUBE_MAP : sg::TEXTURE_2D_ARRAY;
    scenes.push_back({cube ? "sampler: cube map, CLAMP_TO_EDGE, trilinear" : "sampler: 2D array, REPEAT, trilinear",
                      1280, 720, "Mpixel/s", 1280.0 * 720 / 2,
                      [&, cube, pixels, layers, target](int n) {
                        return WithShader<wide::DirShader, scalar::DirShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, plane);
                          gl.BindTexture(target, gl.GenTexture());
                          if (cube) {
                            for (int f = 0; f < 6; ++f)
                              gl.TexImage2D(sg::TEXTURE_CUBE_MAP_POSITIVE_X + Enum(f), 0, sg::RGBA8, 256, 256, 0,
                                            sg::RGBA, sg::UNSIGNED_BYTE, pixels.data());
                          } else {
                            gl.TexImage3D(target, 0, sg::RGBA8, 256, 256, 4, 0, sg::RGBA, sg::UNSIGNED_BYTE,
                                          layers.data());
                          }
                          gl.GenerateMipmap(target);
                          gl.TexParameteri(target, sg::TEXTURE_MIN_FILTER, sg::LINEAR_MIPMAP_LINEAR);
                          const Enum wrap = cube ? sg::CLAMP_TO_EDGE : sg::REPEAT;
                          gl.TexParameteri(target, sg::TEXTURE_WRAP_S, wrap);
                          gl.TexParameteri(target, sg::TEXTURE_WRAP_T, wrap);
                          shader.mode = cube ? 0 : 1;
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, plane_frame);
                        });
                      },
                      [&, cube, pixels, layers](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(plane);
                          const GLenum t = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY;
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(t, tex);
                          if (cube) {
                            for (int f = 0; f < 6; ++f)
                              glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA8, 256, 256, 0,
                                           GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
                          } else {
                            glTexImage3D(t, 0, GL_RGBA8, 256, 256, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, layers.data());
                          }
                          glGenerateMipmap(t);
                          glTexParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                          const GLint wrap = cube ? GL_CLAMP_TO_EDGE : GL_REPEAT;
                          glTexParameteri(t, GL_TEXTURE_WRAP_S, wrap);
                          glTexParameteri(t, GL_TEXTURE_WRAP_T, wrap);
                          Program(kPlaneVs, cube ? kCubeFs : kArrayFs);
                          return TimeGl(n, plane_frame);
                        });
                      }});
  }
  // The same plane with a 64^3 RGBA8 3D texture: with its mip chain, REPEAT, trilinear (eight texels a level,
  // sixteen a lookup), and as a colour-grading table is used, LINEAR without mipmaps, CLAMP_TO_EDGE.
  struct VolumeState {
    const char* name;
    Enum min_filter, wrap;
  };
  static const VolumeState kVolumeStates[] = {
      {"sampler: 3D 64^3, REPEAT, trilinear", sg::LINEAR_MIPMAP_LINEAR, sg::REPEAT},
      {"sampler: 3D 64^3, CLAMP_TO_EDGE, LINEAR / LINEAR", sg::LINEAR, sg::CLAMP_TO_EDGE}};
  for (const VolumeState& st : kVolumeStates) {
    std::vector<std::uint8_t> voxels;
    const std::vector<std::uint8_t> slice = all_data ? PatternTexture(64) : std::vector<std::uint8_t>{};
    for (int z = 0; z < 64 && all_data; ++z)
      for (std::size_t i = 0; i < slice.size(); ++i)
        voxels.push_back(std::uint8_t(slice[i] + (i % 4 == 3 ? 0 : 4 * z)));
    scenes.push_back({st.name, 1280, 720, "Mpixel/s", 1280.0 * 720 / 2,
                      [&, st, voxels](int n) {
                        return WithShader<wide::DirShader, scalar::DirShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, plane);
                          gl.BindTexture(sg::TEXTURE_3D, gl.GenTexture());
                          gl.TexImage3D(sg::TEXTURE_3D, 0, sg::RGBA8, 64, 64, 64, 0, sg::RGBA, sg::UNSIGNED_BYTE,
                                        voxels.data());
                          gl.GenerateMipmap(sg::TEXTURE_3D);
                          gl.TexParameteri(sg::TEXTURE_3D, sg::TEXTURE_MIN_FILTER, st.min_filter);
                          for (const Enum wrap : {sg::TEXTURE_WRAP_S, sg::TEXTURE_WRAP_T, sg::TEXTURE_WRAP_R})
                            gl.TexParameteri(sg::TEXTURE_3D, wrap, st.wrap);
                          shader.mode = 3;
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, plane_frame);
                        });
                      },
                      [&, st, voxels](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(plane);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_3D, tex);
                          glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 64, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                                       voxels.data());
                          glGenerateMipmap(GL_TEXTURE_3D);
                          glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GLint(st.min_filter));
                          for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
                            glTexParameteri(GL_TEXTURE_3D, wrap, GLint(st.wrap));
                          Program(kPlaneVs, k3DFs);
                          return TimeGl(n, plane_frame);
                        });
                      }});
  }
  // A 2048 x 2048 DEPTH_COMPONENT32F shadow map over the plane, LINEAR (four comparisons a lookup), LEQUAL.
  {
    std::vector<float> depths;
    for (int y = 0; y < 2048 && all_data; ++y)
      for (int x = 0; x < 2048; ++x)
        depths.push_back(0.5f + 0.25f * std::sin(float(x) * 0.02f) + 0.2f * std::cos(float(y) * 0.013f));
    scenes.push_back({"sampler: shadow map 2048^2, LINEAR, LEQUAL", 1280, 720, "Mpixel/s", 1280.0 * 720 / 2,
                      [&, depths](int n) {
                        return WithShader<wide::DirShader, scalar::DirShader>([&](auto& shader) {
                          softgl::Context gl(1280, 720, g_options);
                          softgl_setup(gl, plane);
                          gl.BindTexture(sg::TEXTURE_2D, gl.GenTexture());
                          gl.TexImage2D(sg::TEXTURE_2D, 0, sg::DEPTH_COMPONENT32F, 2048, 2048, 0,
                                        sg::DEPTH_COMPONENT, sg::FLOAT, depths.data());
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_MIN_FILTER, sg::LINEAR);
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_MAG_FILTER, sg::LINEAR);
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_WRAP_S, sg::CLAMP_TO_EDGE);
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_WRAP_T, sg::CLAMP_TO_EDGE);
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_COMPARE_MODE, sg::COMPARE_REF_TO_TEXTURE);
                          gl.TexParameteri(sg::TEXTURE_2D, sg::TEXTURE_COMPARE_FUNC, sg::LEQUAL);
                          shader.mode = 2;
                          gl.UseProgram(shader);
                          return TimeSoftgl(n, gl, plane_frame);
                        });
                      },
                      [&, depths](int n) {
                        return with_osmesa(1280, 720, [&] {
                          gl_setup(plane);
                          GLuint tex;
                          glGenTextures(1, &tex);
                          glBindTexture(GL_TEXTURE_2D, tex);
                          glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2048, 2048, 0, GL_DEPTH_COMPONENT,
                                       GL_FLOAT, depths.data());
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
                          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
                          Program(kPlaneVs, kShadowFs);
                          return TimeGl(n, plane_frame);
                        });
                      }});
  }

  if (!rss_child.empty()) {  // the memory-measuring child: the model scene once, then the peak
    if (!have_engine) return 1;
    (rss_child == "softgl" ? scenes[0].softgl_ms : scenes[0].gl_ms)(1);
    std::printf("%ld\n", StatusKiB("VmHWM"));
    return 0;
  }
  // Peak memory of the model scene: each renderer in a process of its own that loads the model and nothing else.
  double rss_softgl = -1.0, rss_gl = -1.0;
  // Whether a scene's name matches --scene.
  auto chosen = [&only](const std::string& name) {
    if (only.empty()) return true;
    if (only.back() != '$') return name.find(only) != std::string::npos;
    const std::string tail = only.substr(0, only.size() - 1);
    return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (have_engine && chosen(scenes[0].name)) {
    rss_softgl = ModelScenePeakMiB(argv[0], "softgl", threads);
    if (!softgl_only) rss_gl = ModelScenePeakMiB(argv[0], "llvmpipe", threads);
  }

  std::printf("| scene | size | threads | softgl ms/frame | llvmpipe ms/frame | softgl / llvmpipe | softgl rate | "
              "softgl speedup over 1 thread | scalar-shader ms/frame | wide gain |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Scene& s : scenes) {
    if (!chosen(s.name)) continue;
    // --cpu-time: softgl's mean wall and CPU ms per frame, and how busy its threads were (CPU / (wall x threads)).
    auto cpu_report = [&](int n) {
      if (g_cpu_time)
        std::fprintf(stderr, "cpu time, %s, %d thread%s: wall %.2f ms/frame, cpu %.2f ms/frame, busy %.2f\n", s.name,
                     n, n > 1 ? "s" : "", g_last_wall_ms, g_last_cpu_ms, g_last_cpu_ms / (g_last_wall_ms * n));
    };
    const double a = s.softgl_ms(frames);
    cpu_report(threads);
    const double b = softgl_only ? 0.0 : s.gl_ms(frames);
    // softgl's own scaling, measured in this run: the scene again on one thread, right after.
    double one = a;
    if (threads > 1) {
      g_options.threads = 1;
      one = s.softgl_ms(frames);
      cpu_report(1);
      g_options.threads = threads;
    }
    // The same scene with the scalar form of its shader, right after: what the wide form gains.
    g_scalar = true;
    const double scalar = with_scalar ? s.softgl_ms(frames) : 0.0;
    g_scalar = false;
    const double rate = s.units / (a * 1e3);  // per microsecond = millions per second
    char speedup[32] = "", gain[32] = "", scalar_ms[32] = "";
    if (threads > 1) std::snprintf(speedup, sizeof speedup, "%.2f", one / a);
    if (with_scalar) {
      std::snprintf(scalar_ms, sizeof scalar_ms, "%.1f", scalar);
      std::snprintf(gain, sizeof gain, "%.2f", scalar / a);
    }
    std::printf("| %s | %dx%d | %d | %.1f | %.1f | %.2f | %.2f %s | %s | %s | %s |\n", s.name, s.width, s.height,
                threads, a, b, b > 0 ? a / b : 0.0, rate, s.unit, speedup, scalar_ms, gain);
    std::fflush(stdout);
  }
  if (msaa_pairs > 0 && have_engine) {
    // The model scene at 1 and 4 samples, a frame of each in turn (which goes first alternates).
    std::vector<std::unique_ptr<softgl::Context>> contexts;
    wide::PhongShader shader;
    shader.view_proj = engine_vp;
    shader.eye = engine_eye;
    for (int samples : {0, 4}) {
      softgl::Context::Options options = g_options;
      options.samples = samples;
      contexts.push_back(std::make_unique<softgl::Context>(1280, 720, options));
      softgl::Context& gl = *contexts.back();
      softgl_setup(gl, engine);
      gl.UseProgram(shader);
      gl.Enable(softgl::DEPTH_TEST);
      gl.Enable(softgl::CULL_FACE);
    }
    auto frame_ms = [&](int k) {  // as TimeSoftgl's frame
      softgl::Context& gl = *contexts[std::size_t(k)];
      const auto t0 = std::chrono::steady_clock::now();
      gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
      gl.DrawElement(softgl::TRIANGLES, int(engine.indices.size()), softgl::UNSIGNED_INT, 0);
      gl.Finish();
      std::uint8_t px[4];
      gl.ReadPixel(0, 0, px);
      return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    };
    for (int k = 0; k < 4; ++k) frame_ms(k % 2);  // warm-up
    std::vector<double> ratios, one, four;
    for (int i = 0; i < msaa_pairs; ++i) {
      double t[2];
      const int first = i % 2;
      t[first] = frame_ms(first);
      t[1 - first] = frame_ms(1 - first);
      one.push_back(t[0]);
      four.push_back(t[1]);
      ratios.push_back(t[1] / t[0]);
    }
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    std::printf("| model: 2CylinderEngine, 4x MSAA over 1x, %d pairs of frames in turn: median ratio %.2f "
                "(1x %.1f ms, 4x %.1f ms) | 1280x720 | %d | | | | | | | |\n",
                msaa_pairs, median(ratios), median(one), median(four), threads);
  }
  if (rss_softgl >= 0.0)
    std::printf("| model scene: peak RSS of the process, MiB | 1280x720 | %d | %.1f | %.1f | %.2f | | |\n", threads,
                rss_softgl, rss_gl,
                rss_gl > 0 ? rss_softgl / rss_gl : 0.0);
  if (!have_engine) std::printf("(model scene skipped: install assimp-testmodels)\n");
  if (!have_head) std::printf("(textured model scene skipped: %s not found)\n", head_dir.c_str());
  return 0;
}

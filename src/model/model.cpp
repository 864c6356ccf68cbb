// model.cpp — loading models through assimp into softgl objects, drawing their node hierarchy, the camera helper.
#include <softgl/model.h>

#if defined(__unix__)
#include <fcntl.h>
#if defined(__linux__)
#include <malloc.h>
#endif
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>
#include <thread>
#include <utility>

#include <assimp/GltfMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/matrix_transform.hpp>

#include "pixel_store.h"

namespace softgl {

namespace {

struct ModelVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 tangent;
  glm::vec4 color;
};

glm::mat4 ToGlm(const aiMatrix4x4& m) {
  // assimp matrices are row-major; glm is column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

bool Finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

class Loader {
 public:
  Loader(Context& gl, Model& model, const aiScene& scene, std::filesystem::path dir)
      : gl_(gl), model_(model), scene_(scene), dir_(std::move(dir)) {}

  void Materials() {
    for (unsigned i = 0; i < scene_.mNumMaterials; ++i) model_.materials.push_back(MakeMaterial(*scene_.mMaterials[i]));
    if (model_.materials.empty()) model_.materials.emplace_back();
  }

  void Meshes() {
    for (unsigned i = 0; i < scene_.mNumMeshes; ++i) model_.meshes.push_back(Upload(*scene_.mMeshes[i]));
  }

  // The node tree, copied breadth-first without recursion (a hostile file may nest deeply).
  void Nodes() {
    std::vector<std::pair<const aiNode*, int>> queue{{scene_.mRootNode, -1}};
    for (std::size_t q = 0; q < queue.size() && queue.size() < 1000000; ++q) {
      const auto [node, parent] = queue[q];
      const int index = int(model_.nodes.size());
      ModelNode n;
      n.name = node->mName.C_Str();
      n.transform = ToGlm(node->mTransformation);
      if (!Finite(n.transform)) n.transform = glm::mat4(1.0f);
      for (unsigned m = 0; m < node->mNumMeshes; ++m)
        if (node->mMeshes[m] < model_.meshes.size()) n.meshes.push_back(int(node->mMeshes[m]));
      model_.nodes.push_back(std::move(n));
      if (parent >= 0) model_.nodes[std::size_t(parent)].children.push_back(index);
      for (unsigned c = 0; c < node->mNumChildren; ++c) queue.push_back({node->mChildren[c], index});
    }
  }

  // Bounds and triangle count over every drawn instance.
  void Measure(const std::vector<std::pair<glm::vec3, glm::vec3>>& mesh_boxes) {
    bool any = false;
    std::vector<std::pair<int, glm::mat4>> stack{{0, model_.nodes[0].transform}};
    std::size_t visited = 0;
    while (!stack.empty() && visited++ < 10000000) {
      const auto [index, world] = stack.back();
      stack.pop_back();
      const ModelNode& node = model_.nodes[std::size_t(index)];
      for (int m : node.meshes) {
        const ModelMesh& mesh = model_.meshes[std::size_t(m)];
        if (mesh.index_count == 0) continue;
        if (mesh.mode == POINTS) model_.points_drawn += mesh.index_count;
        else if (mesh.mode == LINES) model_.lines_drawn += mesh.index_count / 2;
        else model_.triangles_drawn += mesh.index_count / 3;
        const auto& [lo, hi] = mesh_boxes[std::size_t(m)];
        for (int corner = 0; corner < 8; ++corner) {
          const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
          const glm::vec3 w = glm::vec3(world * glm::vec4(p, 1.0f));
          model_.bounds.min = any ? glm::min(model_.bounds.min, w) : w;
          model_.bounds.max = any ? glm::max(model_.bounds.max, w) : w;
          any = true;
        }
      }
      for (int c : node.children) stack.push_back({c, world * model_.nodes[std::size_t(c)].transform});
    }
  }

  std::vector<std::pair<glm::vec3, glm::vec3>> mesh_boxes;

 private:
  Material MakeMaterial(const aiMaterial& m) {
    Material out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    aiColor4D c;
    if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
      out.base_color = glm::vec4(c.r, c.g, c.b, c.a);
    if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) out.specular = glm::vec3(c.r, c.g, c.b);
    if (m.Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) out.emissive = glm::vec3(c.r, c.g, c.b);
    float f = 0.0f;
    if (m.Get(AI_MATKEY_SHININESS, f) == AI_SUCCESS && f > 0.0f) out.shininess = std::min(f, 1024.0f);
    if (m.Get(AI_MATKEY_METALLIC_FACTOR, f) == AI_SUCCESS) {
      out.metallic = std::clamp(f, 0.0f, 1.0f);
      out.pbr = true;
    }
    if (m.Get(AI_MATKEY_ROUGHNESS_FACTOR, f) == AI_SUCCESS) {
      out.roughness = std::clamp(f, 0.0f, 1.0f);
      out.pbr = true;
    }
    if (m.Get(AI_MATKEY_OPACITY, f) == AI_SUCCESS && f < 1.0f) {
      out.base_color.a *= std::clamp(f, 0.0f, 1.0f);
      out.alpha_mode = Material::AlphaMode::kBlend;
    }
    aiString mode;
    if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS) {
      const std::string s = mode.C_Str();
      out.alpha_mode = s == "MASK"    ? Material::AlphaMode::kMask
                       : s == "BLEND" ? Material::AlphaMode::kBlend
                                      : Material::AlphaMode::kOpaque;
    }
    if (m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, f) == AI_SUCCESS) out.alpha_cutoff = f;
    int two_sided = 0;
    if (m.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) out.double_sided = two_sided != 0;
    out.base_color = glm::clamp(out.base_color, 0.0f, 1.0f);

    // Colour maps (base colour, emission) hold sRGB-encoded colours, as glTF says and image files have them: they
    // load as sRGB textures. The others hold data (normals, factors, occlusion) and load as they are.
    out.base_color_texture = Texture(m, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}, true);
    out.normal_texture = Texture(m, {aiTextureType_NORMALS, aiTextureType_NORMAL_CAMERA});
    out.metallic_roughness_texture = Texture(m, {aiTextureType_METALNESS, aiTextureType_UNKNOWN});
    if (out.metallic_roughness_texture) out.pbr = true;
    out.emissive_texture = Texture(m, {aiTextureType_EMISSIVE, aiTextureType_EMISSION_COLOR}, true);
    if (out.emissive_texture && out.emissive == glm::vec3(0.0f)) out.emissive = glm::vec3(1.0f);
    out.occlusion_texture = Texture(m, {aiTextureType_LIGHTMAP, aiTextureType_AMBIENT_OCCLUSION});
    out.specular_texture = Texture(m, {aiTextureType_SPECULAR});
    return out;
  }

  // The first texture of the given types, loaded once per path and encoding: a file beside the model, or embedded
  // in it; `srgb` loads its colours as sRGB-encoded.
  std::uint32_t Texture(const aiMaterial& m, std::initializer_list<aiTextureType> types, bool srgb = false) {
    for (aiTextureType type : types) {
      aiString path;
      if (m.GetTextureCount(type) == 0 || m.GetTexture(type, 0, &path) != AI_SUCCESS) continue;
      const std::string key = path.C_Str();
      if (key.empty()) continue;
      const std::string cache_key = (srgb ? "srgb:" : "linear:") + key;
      if (auto it = cache_.find(cache_key); it != cache_.end()) return it->second;
      const std::uint32_t id = LoadTexture(key, srgb);
      cache_[cache_key] = id;
      return id;
    }
    return 0;
  }

  std::uint32_t LoadTexture(const std::string& key, bool srgb) {
    const Enum encoding = srgb ? SRGB : LINEAR;
    const std::uint32_t id = gl_.GenTexture();
    gl_.BindTexture(TEXTURE_2D, id);
    std::string error;
    bool ok = false;
    if (const aiTexture* embedded = scene_.GetEmbeddedTexture(key.c_str())) {
      if (embedded->mHeight == 0) {  // a compressed image (PNG, JPEG, ...) of mWidth bytes
        ok = gl_.TexImage2DFromMemory(TEXTURE_2D, embedded->pcData, embedded->mWidth, true, &error, encoding);
      } else if (embedded->mWidth <= unsigned(kMaxTextureSize) && embedded->mHeight <= unsigned(kMaxTextureSize)) {
        std::vector<std::uint8_t> rgba;  // aiTexel is BGRA, rows top first
        const unsigned w = embedded->mWidth, h = embedded->mHeight;
        rgba.reserve(std::size_t(w) * h * 4);
        for (unsigned y = 0; y < h; ++y)
          for (unsigned x = 0; x < w; ++x) {
            const aiTexel& t = embedded->pcData[std::size_t(h - 1 - y) * w + x];
            rgba.insert(rgba.end(), {t.r, t.g, t.b, t.a});
          }
        const model_detail::DefaultPixelStore tight(gl_);  // rgba's rows as they are
        gl_.TexImage2D(TEXTURE_2D, 0, srgb ? SRGB8_ALPHA8 : RGBA8, int(w), int(h), 0, RGBA, UNSIGNED_BYTE, rgba.data());
        ok = gl_.GetError() == NO_ERROR;
      }
    } else {
      std::string relative = key;
      std::replace(relative.begin(), relative.end(), '\\', '/');
      std::filesystem::path file = dir_ / relative;
      std::error_code ec;
      if (!std::filesystem::exists(file, ec)) file = dir_ / std::filesystem::path(relative).filename();
      ok = gl_.TexImage2DFromFile(TEXTURE_2D, file.string(), true, &error, encoding);
    }
    if (!ok) {
      model_.warnings.push_back(error.empty() ? key + ": cannot load texture" : error);
      gl_.DeleteTexture(id);
      return 0;
    }
    gl_.GenerateMipmap(TEXTURE_2D);
    gl_.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
    gl_.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR);
    ++model_.textures_loaded;
    return id;
  }

  ModelMesh Upload(const aiMesh& mesh) {
    ModelMesh out;
    out.material = mesh.mMaterialIndex < model_.materials.size() ? int(mesh.mMaterialIndex) : 0;
    // Sorted by primitive type on import, a mesh holds one kind: triangles, or else lines, or else points.
    const unsigned per = (mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) ? 3
                         : (mesh.mPrimitiveTypes & aiPrimitiveType_LINE)   ? 2
                         : (mesh.mPrimitiveTypes & aiPrimitiveType_POINT)  ? 1
                                                                           : 3;
    out.mode = per == 1 || mesh.mNumFaces == 0 ? POINTS : per == 2 ? LINES : TRIANGLES;
    out.has_normals = mesh.mNormals != nullptr && out.mode == TRIANGLES;  // points and lines have no surface to light
    std::vector<ModelVertex> vertices(mesh.mNumVertices);
    glm::vec3 lo(0.0f), hi(0.0f);
    bool any_finite = false;
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
      ModelVertex& v = vertices[i];
      const aiVector3D& p = mesh.mVertices[i];
      v.position = glm::vec3(p.x, p.y, p.z);  // a NaN or infinite one makes the pipeline drop its triangles
      v.normal = mesh.mNormals ? glm::vec3(mesh.mNormals[i].x, mesh.mNormals[i].y, mesh.mNormals[i].z)
                               : glm::vec3(0.0f, 1.0f, 0.0f);
      v.uv = mesh.mTextureCoords[0] ? glm::vec2(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y) : glm::vec2(0.0f);
      v.tangent = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
      if (mesh.mTangents && mesh.mBitangents) {
        const glm::vec3 t(mesh.mTangents[i].x, mesh.mTangents[i].y, mesh.mTangents[i].z);
        const glm::vec3 b(mesh.mBitangents[i].x, mesh.mBitangents[i].y, mesh.mBitangents[i].z);
        v.tangent = glm::vec4(t, glm::dot(glm::cross(v.normal, t), b) < 0.0f ? -1.0f : 1.0f);
      }
      v.color = mesh.mColors[0] ? glm::vec4(mesh.mColors[0][i].r, mesh.mColors[0][i].g, mesh.mColors[0][i].b,
                                            mesh.mColors[0][i].a)
                                : glm::vec4(1.0f);
      if (std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z)) {
        lo = any_finite ? glm::min(lo, v.position) : v.position;
        hi = any_finite ? glm::max(hi, v.position) : v.position;
        any_finite = true;
      }
    }
    mesh_boxes.push_back({lo, hi});
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(mesh.mNumFaces) * 3);
    if (mesh.mNumFaces == 0 || mesh.mFaces == nullptr)  // vertices alone: a point each
      for (unsigned i = 0; i < mesh.mNumVertices; ++i) indices.push_back(i);
    for (unsigned f = 0; mesh.mFaces != nullptr && f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != per) continue;  // a primitive of another kind (not in a sorted mesh)
      bool valid = true;
      for (unsigned k = 0; k < per; ++k) valid = valid && face.mIndices[k] < mesh.mNumVertices;
      if (valid) indices.insert(indices.end(), face.mIndices, face.mIndices + per);
    }
    out.vertex_count = int(vertices.size());
    out.index_count = int(indices.size());
    out.vertex_array = gl_.GenVertexArray();
    const std::uint32_t vbo = gl_.GenBuffer(), ebo = gl_.GenBuffer();
    out.vertex_buffer = vbo;
    out.index_buffer = ebo;
    gl_.BindVertexArray(out.vertex_array);
    gl_.BindBuffer(ARRAY_BUFFER, vbo);
    gl_.BufferData(ARRAY_BUFFER, std::ptrdiff_t(vertices.size() * sizeof(ModelVertex)), vertices.data());
    gl_.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
    gl_.BufferData(ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(indices.size() * sizeof(std::uint32_t)), indices.data());
    const int stride = sizeof(ModelVertex);
    gl_.VertexAttributePointer(kAttribPosition, 3, FLOAT, false, stride, offsetof(ModelVertex, position));
    gl_.VertexAttributePointer(kAttribNormal, 3, FLOAT, false, stride, offsetof(ModelVertex, normal));
    gl_.VertexAttributePointer(kAttribUv, 2, FLOAT, false, stride, offsetof(ModelVertex, uv));
    gl_.VertexAttributePointer(kAttribTangent, 4, FLOAT, false, stride, offsetof(ModelVertex, tangent));
    gl_.VertexAttributePointer(kAttribColor, 4, FLOAT, false, stride, offsetof(ModelVertex, color));
    for (std::uint32_t a = 0; a <= kAttribColor; ++a) gl_.EnableVertexAttribArray(a);
    gl_.BindVertexArray(0);
    return out;
  }

  Context& gl_;
  Model& model_;
  const aiScene& scene_;
  std::filesystem::path dir_;
  std::map<std::string, std::uint32_t> cache_;
};

// Whether the file is a PLY file (its first word "ply", as assimp reads it) whose header never ends: assimp 5.2.5's
// PLY reader keeps looking for a line that starts with the word "end_header" past the end of such a file and does
// not return (fuzz_model found such files, tests/fuzz/corpus/fuzz_model/regression_ply_*). The file is read in
// pieces until that line is found, which for a well-formed file is within its first lines. A line starts after
// '\n' or '\r' and any spaces or tabs; the word must be followed by a space, a tab, a line end, a zero byte or the
// end of the file ("end_header*" is not the word).
bool PlyHeaderUnterminated(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  constexpr std::size_t kPiece = 1 << 16;
  constexpr std::string_view kEnd = "end_header";
  std::string text(kPiece, '\0');
  in.read(text.data(), std::streamsize(kPiece));
  text.resize(std::size_t(in.gcount()));
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || text.compare(start, 3, "ply") != 0) return false;
  std::size_t matched = 0;  // characters of the word matched at the start of the current line; npos: none
  constexpr std::size_t kNone = std::string::npos;
  while (!text.empty()) {
    for (const char c : text) {
      const bool line_end = c == '\n' || c == '\r';
      if (matched == kEnd.size()) {
        if (line_end || c == ' ' || c == '\t' || c == '\0') return false;
        matched = kNone;
      }
      if (line_end) matched = 0;
      else if (matched == 0 && (c == ' ' || c == '\t')) continue;  // spaces before the line's first word
      else if (matched != kNone && c == kEnd[matched]) ++matched;
      else matched = kNone;
    }
    text.assign(kPiece, '\0');
    in.read(text.data(), std::streamsize(kPiece));
    text.resize(std::size_t(in.gcount()));
  }
  return matched != kEnd.size();  // the word at the very end of the file ends the header too
}

// The import: assimp's reading of the file with softgl's post-processing steps. Null, with the reason in `why`, when
// assimp cannot read it.
const aiScene* Import(Assimp::Importer& importer, const std::string& path, std::string& why) {
  constexpr unsigned kSteps = aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_CalcTangentSpace |
                              aiProcess_JoinIdenticalVertices | aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path, kSteps | aiProcess_ValidateDataStructure);
  if (!scene) {
    why = importer.GetErrorString();
    if (why.find("contains no faces") == std::string::npos) return nullptr;
    // A point cloud without point elements (an OBJ of vertices alone) fails assimp's validation: read again
    // without it; Upload checks every index and draws a mesh without faces as one point per vertex.
    scene = importer.ReadFile(path, kSteps);
    if (!scene) why = importer.GetErrorString();
  }
  return scene;
}

#if defined(__unix__)
// The resident memory of the process whose statm file is `statm` that no file backs (resident less shared pages:
// what allocations take, not the code it runs); 0 if unreadable.
std::int64_t ResidentBytes(const std::string& statm) {
  std::int64_t size = 0, resident = 0, shared = 0;
  if (std::ifstream f(statm); !(f >> size >> resident >> shared)) return 0;
  return (resident - shared) * std::int64_t(sysconf(_SC_PAGESIZE));
}
#endif

// The import of `path` tried in a child process within the limits. Empty when it finished there (read or
// refused: the calling process then imports the file itself), else why it was stopped.
std::string TryImport(const std::string& path, const LoadOptions& options) {
#if defined(__unix__)
  constexpr int kOutOfMemory = 3;
  int report[2] = {-1, -1};  // the child's resident memory before the import, child to parent
  if (options.memory_budget > 0) {
    if (pipe(report) != 0) return "cannot start the import process";
    fcntl(report[0], F_SETFD, FD_CLOEXEC);  // (not inherited by programs the caller starts meanwhile)
    fcntl(report[1], F_SETFD, FD_CLOEXEC);
  }
  const std::string budget = std::to_string(options.memory_budget >> 20) + " MiB";
  const pid_t child = fork();
  if (child < 0) {
    if (report[0] >= 0) close(report[0]), close(report[1]);
    return "cannot start the import process";
  }
  if (child == 0) {
    // The child: the import alone, then _exit (no exit handlers of the parent's run in it).
    if (options.memory_budget > 0) {
      // The budget limits the address space the import adds (here) and the memory it makes resident (the parent
      // watches that). Memory the process freed before stays in its allocator's heaps, reserved address space
      // the import can grow into without adding any: it is handed back first, so that using it again shows.
#if defined(__GLIBC__)
      malloc_trim(0);
#endif
      long pages = 0;
      if (std::ifstream statm("/proc/self/statm"); !(statm >> pages)) pages = 0;
      const rlim_t now = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE));
      const rlimit limit{now + options.memory_budget, now + options.memory_budget};
      setrlimit(RLIMIT_AS, &limit);
      const std::int64_t resident = ResidentBytes("/proc/self/statm");
      close(report[0]);
      if (write(report[1], &resident, sizeof resident) != ssize_t(sizeof resident)) _exit(kOutOfMemory);
      close(report[1]);
    }
    int status = 0;
    try {
      Assimp::Importer importer;
      std::string why;
      if (!Import(importer, path, why) && why.find("bad_alloc") != std::string::npos) status = kOutOfMemory;
    } catch (const std::bad_alloc&) {
      status = kOutOfMemory;
    } catch (...) {
    }
    _exit(status);
  }
  // The parent: waits for the child until the deadline, polling with growing pauses of at most 10 ms, and stops
  // it once its resident memory exceeds what it had before the import by the budget.
  std::int64_t resident_limit = 0;
  if (options.memory_budget > 0) {
    close(report[1]);
    std::int64_t before = 0;
    ssize_t got = 0;
    while ((got = read(report[0], &before, sizeof before)) < 0 && errno == EINTR) {
    }
    close(report[0]);
    if (got == ssize_t(sizeof before) && before > 0) resident_limit = before + std::int64_t(options.memory_budget);
  }
  const std::string child_statm = "/proc/" + std::to_string(child) + "/statm";
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(options.timeout_seconds);
  auto pause = std::chrono::microseconds(50);
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) return "lost the import process";
    if (resident_limit > 0 && ResidentBytes(child_statm) > resident_limit) {
      kill(child, SIGKILL);
      while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
      }
      return "import stopped: it needed more than the memory budget of " + budget;
    }
    if (options.timeout_seconds > 0.0 && Clock::now() >= deadline) {
      kill(child, SIGKILL);
      while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
      }
      char limit[64];
      std::snprintf(limit, sizeof limit, "%g", options.timeout_seconds);
      return std::string("import stopped: it took longer than the time limit of ") + limit + " s";
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(10000));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemory)
    return "import stopped: it needed more than the memory budget of " + budget;
  if (WIFSIGNALED(status))
    return "import failed: the importer crashed (signal " + std::to_string(WTERMSIG(status)) + ")";
  return "import failed: the importer stopped with status " + std::to_string(WEXITSTATUS(status)) +
         (options.memory_budget > 0 ? " (out of memory within the budget of " + budget + "?)" : std::string());
#else
  (void)path;
  (void)options;
  return {};
#endif
}

}  // namespace

bool Model::Load(Context& gl, const std::string& path, std::string* error) {
  return Load(gl, path, LoadOptions{}, error);
}

bool Model::Load(Context& gl, const std::string& path, const LoadOptions& options, std::string* error) {
  *this = Model{};
  auto fail = [&](const std::string& message) {
    if (error) *error = path + ": " + message;
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("no such file");
  if (PlyHeaderUnterminated(path)) return fail("cannot read: a PLY header without end_header");
  if (options.timeout_seconds > 0.0 || options.memory_budget > 0)
    if (const std::string stopped = TryImport(path, options); !stopped.empty()) return fail(stopped);
  Assimp::Importer importer;
  std::string why;
  const aiScene* scene = Import(importer, path, why);
  if (!scene) return fail("cannot read: " + why);
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) return fail("incomplete scene");
  Loader loader(gl, *this, *scene, std::filesystem::path(path).parent_path());
  loader.Materials();
  loader.Meshes();
  loader.Nodes();
  if (!nodes.empty()) loader.Measure(loader.mesh_boxes);
  if (triangles_drawn == 0 && lines_drawn == 0 && points_drawn == 0) {  // what was made goes again
    const std::string why = nodes.empty() ? "no nodes" : "no geometry (nothing to draw)";
    Release(gl);
    return fail(why);
  }
  return true;
}

void Model::Release(Context& gl) {
  std::vector<std::uint32_t> textures;
  for (const Material& m : materials)
    for (std::uint32_t id : {m.base_color_texture, m.normal_texture, m.metallic_roughness_texture, m.emissive_texture,
                             m.occlusion_texture, m.specular_texture})
      if (id != 0 && std::find(textures.begin(), textures.end(), id) == textures.end()) textures.push_back(id);
  for (std::uint32_t id : textures) gl.DeleteTexture(id);
  for (const ModelMesh& mesh : meshes) {
    if (mesh.vertex_array) gl.DeleteVertexArray(mesh.vertex_array);
    if (mesh.vertex_buffer) gl.DeleteBuffer(mesh.vertex_buffer);
    if (mesh.index_buffer) gl.DeleteBuffer(mesh.index_buffer);
  }
  *this = Model{};
}

bool Model::CanRead(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext.size() > 1 && Assimp::Importer().IsExtensionSupported(ext);
}

void Model::Draw(Context& gl, MaterialProgram& program, const glm::mat4& view_proj, const glm::mat4& world) const {
  if (nodes.empty()) return;
  const bool cull_was = gl.IsEnabled(CULL_FACE), blend_was = gl.IsEnabled(BLEND);
  gl.UseProgram(program.GetProgram());
  for (int pass = 0; pass < 2; ++pass) {  // 0: opaque and masked; 1: blended
    if (pass == 1) {
      gl.Enable(BLEND);
      gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
      gl.DepthMask(false);
    }
    std::vector<std::pair<int, glm::mat4>> stack{{0, world * nodes[0].transform}};
    while (!stack.empty()) {
      const auto [index, transform] = stack.back();
      stack.pop_back();
      const ModelNode& node = nodes[std::size_t(index)];
      for (int m : node.meshes) {
        const ModelMesh& mesh = meshes[std::size_t(m)];
        const Material& mat = materials[std::size_t(mesh.material)];
        if (mesh.index_count == 0 || (mat.alpha_mode == Material::AlphaMode::kBlend) != (pass == 1)) continue;
        const std::pair<int, std::uint32_t> bindings[] = {
            {kUnitBaseColor, mat.base_color_texture}, {kUnitNormal, mat.normal_texture},
            {kUnitMetallicRoughness, mat.metallic_roughness_texture}, {kUnitEmissive, mat.emissive_texture},
            {kUnitOcclusion, mat.occlusion_texture}, {kUnitSpecular, mat.specular_texture}};
        for (const auto& [unit, id] : bindings) {
          gl.ActiveTexture(TEXTURE0 + Enum(unit));
          gl.BindTexture(TEXTURE_2D, id);
        }
        if (mat.double_sided) gl.Disable(CULL_FACE);
        else gl.Enable(CULL_FACE);
        program.SetMaterial(mat);
        program.SetMesh(mesh);
        program.SetTransforms(transform, view_proj);
        gl.BindVertexArray(mesh.vertex_array);
        gl.DrawElement(mesh.mode, mesh.index_count, UNSIGNED_INT, 0);
      }
      for (int c : node.children) stack.push_back({c, transform * nodes[std::size_t(c)].transform});
    }
  }
  gl.DepthMask(true);
  gl.ActiveTexture(TEXTURE0);
  gl.BindVertexArray(0);
  if (cull_was) gl.Enable(CULL_FACE);
  else gl.Disable(CULL_FACE);
  if (blend_was) gl.Enable(BLEND);
  else gl.Disable(BLEND);
}

glm::mat4 Camera::View() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::Projection(float aspect) const {
  return glm::perspective(glm::radians(fovy_degrees), aspect > 0.0f ? aspect : 1.0f, near_plane, far_plane);
}

Camera Camera::Orbit(glm::vec3 target, float distance, float azimuth_degrees, float elevation_degrees,
                     float fovy_degrees) {
  Camera c;
  const float az = glm::radians(azimuth_degrees), el = glm::radians(std::clamp(elevation_degrees, -89.0f, 89.0f));
  c.target = target;
  c.eye = target + distance * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  c.fovy_degrees = fovy_degrees;
  c.near_plane = std::max(distance * 0.01f, 1e-4f);
  c.far_plane = std::max(distance * 10.0f, c.near_plane * 2.0f);
  return c;
}

Camera Camera::Frame(const Bounds& bounds, float aspect, float azimuth_degrees, float elevation_degrees,
                     float fovy_degrees) {
  const float radius = std::max(bounds.Radius(), 1e-6f);
  const float half_y = glm::radians(fovy_degrees) * 0.5f;
  const float half_x = std::atan(std::tan(half_y) * (aspect > 0.0f ? aspect : 1.0f));
  const float distance = radius / std::sin(std::min(half_x, half_y)) * 1.05f;
  Camera c = Orbit(bounds.Center(), distance, azimuth_degrees, elevation_degrees, fovy_degrees);
  c.near_plane = std::max(distance - radius * 1.5f, distance * 0.01f);
  c.far_plane = distance + radius * 1.5f;
  return c;
}

}  // namespace softgl

// softgl-render — renders model files to PNG: `softgl-render MODEL... -o OUT [options]`.
//
// Exit status: 0 done; 1 a model cannot be loaded (missing file, unreadable format, nothing to draw) or, in a batch,
// any model failed; 2 bad command line; 3 the image cannot be written.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

#if defined(SOFTGL_RENDER_HAS_WEBP)
#include <webp/encode.h>
#include <webp/mux.h>
#endif

namespace {

constexpr const char* kDescription =
    "Renders model files that assimp reads (OBJ, glTF/GLB, FBX, COLLADA, PLY, STL, 3DS, ...)\n"
    "with a camera framing each model's bounding box and three-point lighting.\n\n"
    "  softgl-render MODEL -o OUT.png [options]\n"
    "  softgl-render MODEL... -o DIR/ [options]   (several models, or directories of them: DIR/NAME.png each)\n"
    "  softgl-render MODEL --info\n";
constexpr const char* kFooter =
    "Exit status: 0 done; 1 a model cannot be loaded, or in a batch any model failed;\n"
    "2 bad command line; 3 the image cannot be written.";

struct Options {
  std::vector<std::string> models;
  std::string output;
  int width = 800, height = 600;
  float azimuth = 30.0f, elevation = 20.0f, fov = 40.0f;
  std::optional<float> distance;
  std::optional<glm::vec3> eye, target;
  std::string shader = "auto", tonemap = "auto";
  float exposure = 0.0f;
  glm::vec3 background{0.16f, 0.17f, 0.2f};
  bool background_env = false;  // --background env: the environment image behind the model
  std::string env;              // --env FILE.hdr
  bool wireframe = false, quiet = false, info = false, shadow = false;
  int supersample = 1, turntable = 0, fps = 24;
  int msaa = 4;  // samples per pixel (1: none)
  int sheet_cols = 0, sheet_rows = 0;  // --sheet; 0: none
  float point_size = 3.0f;
  double timeout = 30.0;   // seconds an import may take; 0: no limit
  int import_memory = 4096;  // MiB an import may take; 0: no limit
};

bool ParseFloats(const std::string& s, int n, float* out) {
  const char* p = s.c_str();
  for (int i = 0; i < n; ++i) {
    char* end = nullptr;
    out[i] = std::strtof(p, &end);
    if (end == p || !std::isfinite(out[i])) return false;
    p = end;
    if (i + 1 < n) {
      if (*p != ',') return false;
      ++p;
    }
  }
  return *p == '\0';
}

bool ParseInt(const std::string& s, int lo, int hi, int& out) {
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (end == s.c_str() || *end != '\0' || v < lo || v > hi) return false;
  out = int(v);
  return true;
}

// "AxB" with both from 1 to hi.
bool ParsePair(const std::string& s, int hi, int& a, int& b) {
  const auto x = s.find('x');
  return x != std::string::npos && ParseInt(s.substr(0, x), 1, hi, a) && ParseInt(s.substr(x + 1), 1, hi, b);
}

// An option whose value `parse` checks and stores; `message` is the error when it returns false.
template <class Parse>
CLI::Option* AddChecked(CLI::App& app, const std::string& name, const std::string& type, const std::string& help,
                        const std::string& message, Parse parse) {
  return app
      .add_option_function<std::string>(
          name,
          [name, message, parse](const std::string& v) {
            if (!parse(v)) throw CLI::ValidationError(name, message + ", not '" + v + "'");
          },
          help)
      ->type_name(type);
}

// The command line into `o`; the options' checks that involve several of them last. Throws CLI::ParseError (and
// its --help and --version calls).
void Parse(CLI::App& app, int argc, char** argv, Options& o) {
  app.add_option("MODEL", o.models, "model files, or directories whose model files are all rendered")
      ->required()
      ->type_name("");
  app.add_option("-o,--output", o.output,
                 "the PNG to write; with --turntable N: FILE_000.png ... or\n"
                 "one animated FILE.webp; with several models: a directory, DIR/")
      ->type_name("OUT");
  AddChecked(app, "--size", "WxH", "image size in pixels (default 800x600)", "wants WxH with both from 1 to 8192",
             [&o](const std::string& v) { return ParsePair(v, 8192, o.width, o.height); });
  auto number = [&app](const std::string& name, const std::string& help, const std::string& message, float lo,
                       float hi, auto store) {
    AddChecked(app, name, "DEG", help, message, [=](const std::string& v) {
      float f = 0.0f;
      if (!ParseFloats(v, 1, &f) || !(f >= lo && f <= hi)) return false;
      store(f);
      return true;
    });
  };
  constexpr float kHuge = 1e30f;
  number("--azimuth", "camera angle around the model, from the front (default 30)", "wants a number",
         -kHuge, kHuge, [&o](float f) { o.azimuth = f; });
  number("--elevation", "camera angle above the horizon (default 20)", "wants a number", -kHuge, kHuge,
         [&o](float f) { o.elevation = f; });
  number("--fov", "vertical field of view (default 40)", "wants degrees between 1 and 179", 1.0001f, 178.999f,
         [&o](float f) { o.fov = f; });
  AddChecked(app, "--distance", "D", "camera distance from the centre (default: framing the bounding sphere)",
             "wants a positive number", [&o](const std::string& v) {
               float f = 0.0f;
               if (!ParseFloats(v, 1, &f) || f <= 0.0f) return false;
               o.distance = f;
               return true;
             });
  AddChecked(app, "--look-at", "EX,EY,EZ,TX,TY,TZ",
             "explicit camera position and target (overrides the orbit options)",
             "wants EX,EY,EZ,TX,TY,TZ with the eye apart from the target", [&o](const std::string& v) {
               float f[6];
               if (!ParseFloats(v, 6, f)) return false;
               o.eye = glm::vec3(f[0], f[1], f[2]);
               o.target = glm::vec3(f[3], f[4], f[5]);
               return *o.eye != *o.target;
             });
  app.add_option("--shader", o.shader,
                 "auto (default): pbr for metallic-roughness materials, else phong")
      ->check(CLI::IsMember({"auto", "pbr", "phong", "unlit"}))
      ->type_name("NAME");
  app.add_option("--tonemap", o.tonemap,
                 "how colours above 1 come into range: pbr-neutral (default\n"
                 "with the pbr shader), aces, none (default otherwise)")
      ->check(CLI::IsMember({"auto", "pbr-neutral", "aces", "none"}))
      ->type_name("CURVE");
  AddChecked(app, "--exposure", "EV", "exposure in stops: colours times 2^EV before tone mapping\n"
             "(-16 to 16, default 0)", "wants a number from -16 to 16", [&o](const std::string& v) {
               return ParseFloats(v, 1, &o.exposure) && o.exposure >= -16.0f && o.exposure <= 16.0f;
             });
  app.add_option("--env", o.env,
                 "an equirectangular HDR image (.hdr) that lights the PBR shader's\n"
                 "materials instead of the studio environment and the lamps")
      ->type_name("FILE");
  AddChecked(app, "--background", "R,G,B|env",
             "background colour, components in [0, 1] (default 0.16,0.17,0.2),\n"
             "or env: the --env image", "wants R,G,B or env", [&o](const std::string& v) {
               o.background_env = v == "env";
               if (o.background_env) return true;
               float f[3];
               if (!ParseFloats(v, 3, f)) return false;
               o.background = glm::clamp(glm::vec3(f[0], f[1], f[2]), 0.0f, 1.0f);
               return true;
             });
  app.add_flag("--wireframe", o.wireframe, "draw the triangle edges over the shaded model");
  app.add_flag("--shadow", o.shadow, "a ground plane under the model with its shadow from the key light");
  AddChecked(app, "--point-size", "PX", "diameter of the points of point meshes (1 to 64, default 3)",
             "wants 1 to 64 pixels", [&o](const std::string& v) {
               return ParseFloats(v, 1, &o.point_size) && o.point_size >= 1.0f && o.point_size <= 64.0f;
             });
  AddChecked(app, "--msaa", "N", "multisampling: N samples a pixel, 1 (off), 2, 4 (default) or 8",
             "wants 1, 2, 4 or 8", [&o](const std::string& v) {
               return ParseInt(v, 1, 8, o.msaa) && (o.msaa == 1 || o.msaa == 2 || o.msaa == 4 || o.msaa == 8);
             });
  AddChecked(app, "--supersample", "N", "render N times larger and average down (1 to 4, default 1)",
             "wants 1 to 4", [&o](const std::string& v) { return ParseInt(v, 1, 4, o.supersample); });
  AddChecked(app, "--turntable", "N", "N frames going once around the model (1 to 3600)",
             "wants 1 to 3600 frames", [&o](const std::string& v) { return ParseInt(v, 1, 3600, o.turntable); });
  AddChecked(app, "--fps", "N", "frames per second of an animated WebP turntable (1 to 100, default 24)",
             "wants 1 to 100", [&o](const std::string& v) { return ParseInt(v, 1, 100, o.fps); });
  AddChecked(app, "--sheet", "COLSxROWS",
             "one PNG of COLS x ROWS views going once around the model, left\n"
             "to right and top to bottom, each of --size (not with --turntable)",
             "wants COLSxROWS with both from 1 to 64",
             [&o](const std::string& v) { return ParsePair(v, 64, o.sheet_cols, o.sheet_rows); });
  AddChecked(app, "--timeout", "SECONDS", "the most time one model's import may take (default 30; 0: no limit)",
             "wants seconds from 0 to 86400", [&o](const std::string& v) {
               float f = 0.0f;
               if (!ParseFloats(v, 1, &f) || f < 0.0f || f > 86400.0f) return false;
               o.timeout = f;
               return true;
             });
  AddChecked(app, "--max-import-memory", "MIB",
             "the most memory one model's import may take (default 4096; 0: no limit)",
             "wants MiB from 0 to 1048576", [&o](const std::string& v) { return ParseInt(v, 0, 1 << 20, o.import_memory); });
  app.add_flag("--info", o.info,
               "print what the file holds (meshes, vertex and triangle counts,\n"
               "materials and their maps, bounding box, import time); render nothing");
  app.add_flag("-q,--quiet", o.quiet, "no progress bar, no summary");
  app.set_help_flag("-h,--help", "this text");
  app.set_version_flag("--version", "softgl-render " SOFTGL_RENDER_VERSION, "print the version");
  app.parse(argc, argv);

  if (o.output.empty() && !o.info) throw CLI::ValidationError("no output file given (-o OUT.png)");
  if (o.background_env && o.env.empty()) throw CLI::ValidationError("--background env needs --env FILE.hdr");
  if (o.sheet_cols > 0 && o.turntable > 0) throw CLI::ValidationError("--sheet and --turntable do not go together");
  if (o.sheet_cols > 0 &&
      (std::int64_t(o.width) * o.sheet_cols > 16384 || std::int64_t(o.height) * o.sheet_rows > 16384))
    throw CLI::ValidationError("--sheet: the sheet would be larger than 16384 pixels a side");
  if (std::int64_t(o.width) * o.supersample > softgl::kMaxFramebufferSize ||
      std::int64_t(o.height) * o.supersample > softgl::kMaxFramebufferSize)
    throw CLI::ValidationError("--size times --supersample is larger than " +
                               std::to_string(softgl::kMaxFramebufferSize));
}

// Whether `path` ends in .webp (any case).
bool IsWebp(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".webp";
}

#if defined(SOFTGL_RENDER_HAS_WEBP)
constexpr bool kHasWebp = true;

// The frames as one looping animated WebP (lossy, quality 90) at `fps`, through libwebp's animation encoder. The
// file is written whole or not at all.
bool WriteAnimatedWebp(const std::string& path, const std::vector<softgl::Image>& frames, int fps) {
  if (frames.empty()) return false;
  const int w = frames[0].width, h = frames[0].height;
  WebPAnimEncoderOptions options;
  WebPConfig config;
  if (!WebPAnimEncoderOptionsInit(&options) || !WebPConfigInit(&config)) return false;
  options.anim_params.loop_count = 0;  // forever
  config.quality = 90.0f;
  WebPAnimEncoder* encoder = WebPAnimEncoderNew(w, h, &options);
  if (!encoder) return false;
  bool ok = true;
  int timestamp = 0, index = 0;
  for (const softgl::Image& frame : frames) {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) {
      ok = false;
      break;
    }
    picture.use_argb = 1;
    picture.width = w;
    picture.height = h;
    ok = WebPPictureImportRGBA(&picture, frame.rgba.data(), w * 4) &&
         WebPAnimEncoderAdd(encoder, &picture, timestamp, &config);
    WebPPictureFree(&picture);
    if (!ok) break;
    timestamp = int(std::lround(1000.0 * ++index / fps));  // in milliseconds, without drift
  }
  WebPData data;
  WebPDataInit(&data);
  ok = ok && WebPAnimEncoderAdd(encoder, nullptr, timestamp, nullptr) && WebPAnimEncoderAssemble(encoder, &data);
  WebPAnimEncoderDelete(encoder);
  if (ok) {
    std::ofstream out(path, std::ios::binary);
    ok = out && out.write(reinterpret_cast<const char*>(data.bytes), std::streamsize(data.size)) && out.flush();
    if (!ok) {
      out.close();
      std::error_code ec;
      if (std::filesystem::is_regular_file(path, ec)) std::filesystem::remove(path, ec);
    }
  }
  WebPDataClear(&data);
  return ok;
}
#else
constexpr bool kHasWebp = false;
bool WriteAnimatedWebp(const std::string&, const std::vector<softgl::Image>&, int) { return false; }
#endif

// Averages factor x factor blocks.
softgl::Image Downsample(const softgl::Image& big, int factor) {
  if (factor == 1) return big;
  softgl::Image out;
  out.width = big.width / factor;
  out.height = big.height / factor;
  out.rgba.resize(std::size_t(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx) sum += big.At(x * factor + dx, y * factor + dy)[c];
        out.rgba[(std::size_t(y) * out.width + x) * 4 + c] = std::uint8_t((sum + factor * factor / 2) / (factor * factor));
      }
  return out;
}

// One colour for the wireframe overlay.
struct NoVaryings {};
struct FlatShader : softgl::Shader<FlatShader, NoVaryings>, softgl::MaterialProgram {
  glm::mat4 mvp{1.0f};
  glm::vec4 color{0.05f, 0.05f, 0.05f, 1.0f};
  const softgl::Program& GetProgram() const override { return *this; }
  void SetTransforms(const glm::mat4& m, const glm::mat4& vp) override { mvp = vp * m; }
  void SetMaterial(const softgl::Material&) override {}
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<NoVaryings>& out) const {
    out.position = mvp * softgl::vec4(softgl::vec3(in.attrib[softgl::kAttribPosition]), 1.0f);
  }
  void Fragment(const softgl::FragmentLanes<NoVaryings>&, softgl::FragmentLanesOut& out) const {
    out.color[0] = color;
  }
};

// The environment seen behind the model: a triangle over the whole viewport at the far plane, each fragment's
// view direction looked up in the environment cube map, shown with the model's exposure and tone curve.
struct SkyVaryings {
  softgl::vec2 ndc;
};
struct SkyShader : softgl::Shader<SkyShader, SkyVaryings> {
  glm::mat4 inverse_view_proj{1.0f};
  glm::vec3 eye{0.0f};
  softgl::ToneMap tone_map = softgl::ToneMap::kClamp;
  float exposure = 0.0f;
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<SkyVaryings>& out) const {
    const softgl::vec2 p(in.attrib[0]);
    out.position = softgl::vec4(p.x, p.y, softgl::Float(1.0f), softgl::Float(1.0f));
    out.varyings.ndc = p;
  }
  void Fragment(const softgl::FragmentLanes<SkyVaryings>& in, softgl::FragmentLanesOut& out) const {
    const softgl::vec4 far = inverse_view_proj * softgl::vec4(in.varyings.ndc.x, in.varyings.ndc.y, 1.0f, 1.0f);
    const softgl::vec3 dir = softgl::vec3(far) / far.w - eye;
    const softgl::vec3 radiance(in.TextureCubeLod(softgl::kUnitEnvironment, dir, 0.0f));
    out.color[0] = softgl::vec4(softgl::DisplayColor(radiance, tone_map, exposure, true), 1.0f);
  }
};

// The ground under the model (--shadow): a disc of neutral grey lit by the key light, shadowed through the shadow
// map on unit 0 (3 x 3 comparison taps, each a bilinear 2 x 2 comparison), fading out towards its rim.
struct GroundVaryings {
  softgl::vec3 world;
  softgl::vec4 light_pos;
};
struct GroundShader : softgl::Shader<GroundShader, GroundVaryings> {
  glm::mat4 view_proj{1.0f}, light_vp{1.0f};
  glm::vec3 centre{0.0f};
  float radius = 1.0f, texel = 1.0f / 2048.0f, key = 1.0f;  // key: the key light's n.l on the ground
  softgl::ToneMap tone_map = softgl::ToneMap::kClamp;
  float exposure = 0.0f;
  void Vertex(const softgl::VertexLanes& in, softgl::VertexLanesOut<GroundVaryings>& out) const {
    const softgl::vec4 world(softgl::vec3(in.attrib[0]), 1.0f);
    out.position = view_proj * world;
    out.varyings.world = softgl::vec3(world);
    out.varyings.light_pos = light_vp * world;
  }
  void Fragment(const softgl::FragmentLanes<GroundVaryings>& in, softgl::FragmentLanesOut& out) const {
    using softgl::Float;
    const softgl::vec3 p = softgl::vec3(in.varyings.light_pos) / in.varyings.light_pos.w * 0.5f + 0.5f;
    Float lit = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        lit += in.TextureShadow(0, softgl::vec3(softgl::vec2(p) + glm::vec2(dx, dy) * texel, p.z));
    lit = lit * (1.0f / 9.0f);
    const Float dx = in.varyings.world.x - centre.x, dz = in.varyings.world.z - centre.z;
    const Float fade = 1.0f - softgl::smoothstep(0.55f * radius, radius, softgl::sqrt(dx * dx + dz * dz));
    const softgl::vec3 color = softgl::vec3(0.42f, 0.42f, 0.4f) * (0.35f + 0.65f * key * lit);
    out.color[0] = softgl::vec4(softgl::DisplayColor(color, tone_map, exposure, false), fade);
  }
};

// --info: what Model::Load made of the file, on stdout.
void PrintInfo(const std::string& path, const softgl::Model& model, double import_seconds) {
  long long vertices = 0, triangles = 0;
  for (const softgl::ModelMesh& m : model.meshes) {
    vertices += m.vertex_count;
    if (m.mode == softgl::TRIANGLES) triangles += m.index_count / 3;
  }
  std::printf("file: %s\nimport: %.3f s\n", path.c_str(), import_seconds);
  std::printf("meshes: %zu, %lld triangles, %lld vertices\n", model.meshes.size(), triangles, vertices);
  for (std::size_t i = 0; i < model.meshes.size(); ++i) {
    const softgl::ModelMesh& m = model.meshes[i];
    const int per = m.mode == softgl::POINTS ? 1 : m.mode == softgl::LINES ? 2 : 3;
    const char* kind = per == 1 ? "points" : per == 2 ? "lines" : "triangles";
    std::printf("  mesh %zu: %d %s, %d vertices, material %d%s\n", i, m.index_count / per, kind, m.vertex_count,
                m.material, m.has_normals ? "" : ", no normals (drawn unlit)");
  }
  std::printf("nodes: %zu; drawn (each mesh once per node that uses it): %d triangles, %d lines, %d points\n",
              model.nodes.size(), model.triangles_drawn, model.lines_drawn, model.points_drawn);
  std::printf("materials: %zu (textures loaded: %d)\n", model.materials.size(), model.textures_loaded);
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const softgl::Material& m = model.materials[i];
    std::string maps;
    const std::pair<std::uint32_t, const char*> named[] = {
        {m.base_color_texture, "base colour"}, {m.normal_texture, "normal"},
        {m.metallic_roughness_texture, "metallic-roughness"}, {m.emissive_texture, "emissive"},
        {m.occlusion_texture, "occlusion"}, {m.specular_texture, "specular"}};
    for (const auto& [id, name] : named)
      if (id != 0) maps += std::string(maps.empty() ? "" : ", ") + name;
    const char* alpha = m.alpha_mode == softgl::Material::AlphaMode::kBlend  ? "blend"
                        : m.alpha_mode == softgl::Material::AlphaMode::kMask ? "mask"
                                                                             : "opaque";
    std::printf("  material %zu \"%s\": %s, base colour (%.3g, %.3g, %.3g, %.3g), %s%s, maps: %s\n", i,
                m.name.c_str(), m.pbr ? "metallic-roughness" : "Phong", m.base_color.r, m.base_color.g,
                m.base_color.b, m.base_color.a, alpha, m.double_sided ? ", double-sided" : "",
                maps.empty() ? "none" : maps.c_str());
  }
  const glm::vec3 lo = model.bounds.min, hi = model.bounds.max, size = hi - lo;
  std::printf("bounds: min (%g, %g, %g), max (%g, %g, %g), size (%g, %g, %g)\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z,
              size.x, size.y, size.z);
  for (const std::string& w : model.warnings) std::printf("warning: %s\n", w.c_str());
}

void Progress(int done, int total, double seconds) {
  constexpr int kWidth = 40;
  const int filled = total ? done * kWidth / total : kWidth;
  std::fprintf(stderr, "\r[%.*s%*s] %d/%d  %.1f s", filled, "########################################",
               kWidth - filled, "", done, total, seconds);
  std::fflush(stderr);
}

// The model files the arguments name: files as given; a directory's regular files that assimp has a reader for,
// sorted by name (not its subdirectories). Arguments that name nothing are kept, for Load to report.
std::vector<std::string> ModelFiles(const std::vector<std::string>& args, bool& any_directory) {
  std::vector<std::string> files;
  any_directory = false;
  for (const std::string& a : args) {
    std::error_code ec;
    if (!std::filesystem::is_directory(a, ec)) {
      files.push_back(a);
      continue;
    }
    any_directory = true;
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(a, ec))
      if (entry.is_regular_file(ec) && softgl::Model::CanRead(entry.path().string()))
        found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

// `path` with `suffix` before its extension (or at its end when it has none).
std::string WithSuffix(const std::string& path, const std::string& suffix) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

enum Status { kOk = 0, kLoadFailed = 1, kWriteFailed = 3 };

// The context's framebuffer: --msaa samples a pixel (--info draws nothing: one sample).
softgl::Context::Options ContextOptions(const Options& o) {
  softgl::Context::Options options;
  options.samples = o.info || o.msaa <= 1 ? 0 : o.msaa;
  return options;
}

// Renders models, one after another, into one context (and its threads).
class Renderer {
 public:
  Renderer(const Options& o, int w, int h) : o_(o), w_(w), h_(h), gl_(w, h, ContextOptions(o)) {}
  bool Ready() { return gl_.GetError() == softgl::NO_ERROR; }

  // The --env image as the PBR shader's environment (and the triangle that shows it behind the model); false
  // with a message when it cannot be read.
  bool LoadEnvironment(const std::string& path) {
    std::string error;
    pbr_.environment_levels = softgl::LoadEnvironment(gl_, path, 128, &error);
    if (pbr_.environment_levels == 0.0f) {
      std::fprintf(stderr, "softgl-render: %s\n", error.empty() ? (path + ": cannot read").c_str() : error.c_str());
      return false;
    }
    pbr_.environment_hdr = true;
    const float corners[] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};  // one triangle over the viewport
    sky_vao_ = gl_.GenVertexArray();
    gl_.BindVertexArray(sky_vao_);
    gl_.BindBuffer(softgl::ARRAY_BUFFER, gl_.GenBuffer());
    gl_.BufferData(softgl::ARRAY_BUFFER, sizeof corners, corners);
    gl_.VertexAttributePointer(0, 2, softgl::FLOAT, false, 0, 0);
    gl_.EnableVertexAttribArray(0);
    gl_.BindVertexArray(0);
    return true;
  }

  // Loads `file` and writes its image(s) to `output`: the PNG, the turntable's frames or WebP, or the sheet.
  Status Render(const std::string& file, const std::string& output) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    softgl::Model model;
    std::string error;
    softgl::LoadOptions limits;
    limits.timeout_seconds = o_.timeout;
    limits.memory_budget = std::size_t(o_.import_memory) << 20;
    if (!model.Load(gl_, file, limits, &error)) {
      std::fprintf(stderr, "softgl-render: %s\n", error.c_str());
      return kLoadFailed;
    }
    const double load_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (o_.info) {
      PrintInfo(file, model, load_seconds);
      model.Release(gl_);
      return kOk;
    }
    for (const std::string& warning : model.warnings)
      std::fprintf(stderr, "softgl-render: warning: %s: %s\n", file.c_str(), warning.c_str());
    const auto render_start = Clock::now();
    std::string shader_name;
    const Status status = Frames(model, output, shader_name);
    const double render_seconds = std::chrono::duration<double>(Clock::now() - render_start).count();
    const int frames = std::max(1, o_.sheet_cols > 0 ? o_.sheet_cols * o_.sheet_rows : o_.turntable);
    if (status == kOk && !o_.quiet)
      std::fprintf(stderr,
                   "softgl-render: %s: %d triangles, %d lines, %d points, %zu meshes, %zu materials, %d textures, "
                   "shader %s; load %.2f s, render %d frame%s of %dx%d in %.2f s (%.1f ms/frame)\n",
                   file.c_str(), model.triangles_drawn, model.lines_drawn, model.points_drawn, model.meshes.size(),
                   model.materials.size(), model.textures_loaded, shader_name.c_str(), load_seconds, frames,
                   frames == 1 ? "" : "s", w_, h_, render_seconds, 1000.0 * render_seconds / frames);
    model.Release(gl_);
    return status;
  }

 private:
  Status Frames(const softgl::Model& model, const std::string& output, std::string& shader_name) {
    using Clock = std::chrono::steady_clock;
    bool any_pbr = false;
    for (const softgl::Material& m : model.materials) any_pbr = any_pbr || m.pbr;
    shader_name = o_.shader == "auto" ? (any_pbr ? "pbr" : "phong") : o_.shader;
    if (shader_name == "pbr" && pbr_.environment_levels == 0.0f && o_.env.empty())
      pbr_.environment_levels = softgl::MakeStudioEnvironment(gl_, 64);
    softgl::MaterialProgram* program = shader_name == "pbr"     ? static_cast<softgl::MaterialProgram*>(&pbr_)
                                       : shader_name == "phong" ? static_cast<softgl::MaterialProgram*>(&phong_)
                                                                : static_cast<softgl::MaterialProgram*>(&unlit_);
    const std::string curve = o_.tonemap == "auto" ? (shader_name == "pbr" ? "pbr-neutral" : "none") : o_.tonemap;
    const softgl::ToneMap tone_map = curve == "pbr-neutral" ? softgl::ToneMap::kPbrNeutral
                                     : curve == "aces"      ? softgl::ToneMap::kAces
                                                            : softgl::ToneMap::kClamp;
    pbr_.tone_map = phong_.tone_map = unlit_.tone_map = tone_map;
    pbr_.exposure = phong_.exposure = unlit_.exposure = o_.exposure;

    const bool webp = o_.turntable > 0 && IsWebp(output);
    const int views = o_.sheet_cols > 0 ? o_.sheet_cols * o_.sheet_rows : o_.turntable;  // around the model
    const int frames = std::max(1, views);
    softgl::Image sheet;
    if (o_.sheet_cols > 0) {
      sheet.width = o_.width * o_.sheet_cols;
      sheet.height = o_.height * o_.sheet_rows;
      sheet.rgba.assign(std::size_t(sheet.width) * std::size_t(sheet.height) * 4, 0);
    }
    std::vector<softgl::Image> animation;
    const bool progress = !o_.quiet && isatty(fileno(stderr)) && frames > 1;
    const auto render_start = Clock::now();
    auto failed = [&](const std::string& path) {  // the writers leave no partial file behind
      if (progress) std::fputc('\n', stderr);
      std::fprintf(stderr, "softgl-render: cannot write %s\n", path.c_str());
      return kWriteFailed;
    };
    for (int frame = 0; frame < frames; ++frame) {
      const float azimuth = o_.azimuth + (views ? 360.0f * float(frame) / float(frames) : 0.0f);
      const softgl::Image image = Draw(model, *program, azimuth);
      if (progress) Progress(frame + 1, frames, std::chrono::duration<double>(Clock::now() - render_start).count());
      if (o_.sheet_cols > 0) {  // into its cell; the sheet is written after the last view
        const int cx = frame % o_.sheet_cols, cy = frame / o_.sheet_cols;
        const std::size_t row = std::size_t(image.width) * 4;
        for (int y = 0; y < image.height; ++y)
          std::memcpy(&sheet.rgba[(std::size_t(cy * image.height + y) * std::size_t(sheet.width) +
                                   std::size_t(cx * image.width)) * 4],
                      &image.rgba[std::size_t(y) * row], row);
        continue;
      }
      if (webp) {
        animation.push_back(image);
        continue;
      }
      char suffix[16];
      std::snprintf(suffix, sizeof suffix, "_%03d", frame);
      const std::string path = o_.turntable ? WithSuffix(output, suffix) : output;
      if (!softgl::WritePng(path, image)) return failed(path);
      if (!progress && !o_.quiet) std::printf("%s\n", path.c_str());
    }
    if (progress) std::fputc('\n', stderr);
    if (o_.sheet_cols > 0) {
      if (!softgl::WritePng(output, sheet)) return failed(output);
      if (!o_.quiet) std::printf("%s\n", output.c_str());
    }
    if (webp) {
      if (!WriteAnimatedWebp(output, animation, o_.fps)) return failed(output);
      if (!o_.quiet) std::printf("%s\n", output.c_str());
    }
    return kOk;
  }

  // One view of the model from `azimuth`, downsampled.
  softgl::Image Draw(const softgl::Model& model, softgl::MaterialProgram& program, float azimuth) {
    const float aspect = float(w_) / float(h_);
    softgl::Camera cam = softgl::Camera::Frame(model.bounds, aspect, azimuth, o_.elevation, o_.fov);
    if (o_.distance) {
      cam = softgl::Camera::Orbit(model.bounds.Center(), *o_.distance, azimuth, o_.elevation, o_.fov);
      const float r = model.bounds.Radius();
      cam.near_plane = std::max(*o_.distance - r * 1.5f, *o_.distance * 0.01f);
      cam.far_plane = *o_.distance + r * 1.5f;
    }
    if (o_.eye) {
      cam.eye = *o_.eye;
      cam.target = *o_.target;
      const float d = glm::length(cam.eye - model.bounds.Center());
      cam.near_plane = std::max(d - model.bounds.Radius() * 1.5f, d * 0.01f);
      cam.far_plane = d + model.bounds.Radius() * 1.5f;
    }
    const glm::mat4 view_proj = cam.Projection(aspect) * cam.View();
    const softgl::Lighting lighting = softgl::Lighting::ThreePoint(cam.eye, cam.target);
    pbr_.lighting = phong_.lighting = unlit_.lighting = lighting;
    if (!o_.env.empty()) pbr_.lighting.count = 0;  // the environment is the PBR materials' only light

    gl_.ClearColor(o_.background.r, o_.background.g, o_.background.b, 1.0f);
    gl_.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
    if (o_.background_env) {
      SkyShader sky;
      sky.inverse_view_proj = glm::inverse(view_proj);
      sky.eye = cam.eye;
      sky.tone_map = pbr_.tone_map;
      sky.exposure = pbr_.exposure;
      gl_.BindVertexArray(sky_vao_);
      gl_.UseProgram(sky);
      gl_.DrawArrays(softgl::TRIANGLES, 0, 3);
      gl_.BindVertexArray(0);
    }
    gl_.Enable(softgl::DEPTH_TEST);
    if (o_.shadow) Ground(model, view_proj, lighting.lights[0].direction);
    gl_.PointSize(o_.point_size * float(o_.supersample));
    if (o_.wireframe) {  // the shaded surface a little behind its edges
      gl_.Enable(softgl::POLYGON_OFFSET_FILL);
      gl_.PolygonOffset(1.0f, 1.0f);
    }
    model.Draw(gl_, program, view_proj);
    if (o_.wireframe) {
      gl_.Disable(softgl::POLYGON_OFFSET_FILL);
      gl_.PolygonMode(softgl::FRONT_AND_BACK, softgl::LINE);
      gl_.DepthFunc(softgl::LEQUAL);
      FlatShader flat;
      const float sum = o_.background.r + o_.background.g + o_.background.b;
      flat.color = glm::vec4(glm::vec3(sum > 1.5f ? 0.1f : 0.9f), 1.0f);
      model.Draw(gl_, flat, view_proj);
      gl_.PolygonMode(softgl::FRONT_AND_BACK, softgl::FILL);
      gl_.DepthFunc(softgl::LESS);
    }
    return Downsample(gl_.ReadPixels(), o_.supersample);
  }

  // --shadow: the model's depth from the key light (direction `to_light`) into the shadow map, then the ground
  // under its bounding box, blended over the background.
  void Ground(const softgl::Model& model, const glm::mat4& view_proj, const glm::vec3& to_light) {
    constexpr int kShadowSize = 2048;
    const glm::vec3 centre = model.bounds.Center();
    const float r = std::max(model.bounds.Radius(), 1e-6f);
    const float ground_y = model.bounds.min.y - 1e-3f * r;
    const float extent = 1.4f * r;  // the disc's radius: inside the camera's far plane (1.5 r past the centre)
    if (!shadow_.framebuffer) {
      shadow_ = softgl::MakeShadowMap(gl_, kShadowSize);
      ground_vao_ = gl_.GenVertexArray();  // its buffer is filled for each model
      gl_.BindVertexArray(ground_vao_);
      ground_vbo_ = gl_.GenBuffer();
      gl_.BindBuffer(softgl::ARRAY_BUFFER, ground_vbo_);
      gl_.VertexAttributePointer(0, 3, softgl::FLOAT, false, 0, 0);
      gl_.EnableVertexAttribArray(0);
      gl_.BindVertexArray(0);
    }
    // The light's orthographic view of the bounding sphere, from 3 radii away.
    const glm::vec3 l = glm::normalize(to_light);
    const glm::vec3 up = std::abs(l.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 light_vp = glm::ortho(-r, r, -r, r, r, 9.0f * r) * glm::lookAt(centre + l * 3.0f * r, centre, up);
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, shadow_.framebuffer);
    gl_.Viewport(0, 0, kShadowSize, kShadowSize);
    gl_.Clear(softgl::DEPTH_BUFFER_BIT);
    gl_.Enable(softgl::POLYGON_OFFSET_FILL);  // keeps the contact from shadowing itself (acne)
    gl_.PolygonOffset(2.0f, 4.0f);
    FlatShader depth;
    model.Draw(gl_, depth, light_vp);
    gl_.Disable(softgl::POLYGON_OFFSET_FILL);
    gl_.BindFramebuffer(softgl::FRAMEBUFFER, 0);
    gl_.Viewport(0, 0, w_, h_);

    // The ground: a square of two triangles around the disc, in world space.
    const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    std::vector<float> world;
    for (int i = 0; i < 6; ++i)
      world.insert(world.end(), {centre.x + corners[2 * i] * extent, ground_y, centre.z + corners[2 * i + 1] * extent});
    gl_.BindBuffer(softgl::ARRAY_BUFFER, ground_vbo_);
    gl_.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(world.size() * sizeof(float)), world.data());
    GroundShader ground;
    ground.view_proj = view_proj;
    ground.light_vp = light_vp;
    ground.centre = centre;
    ground.radius = extent;
    ground.texel = 1.0f / float(kShadowSize);
    ground.key = std::max(l.y, 0.0f);
    ground.tone_map = phong_.tone_map;  // the same curve and exposure in every shader
    ground.exposure = phong_.exposure;
    gl_.ActiveTexture(softgl::TEXTURE0);
    gl_.BindTexture(softgl::TEXTURE_2D, shadow_.texture);
    gl_.Enable(softgl::BLEND);
    gl_.BlendFunc(softgl::SRC_ALPHA, softgl::ONE_MINUS_SRC_ALPHA);
    gl_.DepthMask(false);  // the model is drawn after: the ground never hides it
    gl_.BindVertexArray(ground_vao_);
    gl_.UseProgram(ground);
    gl_.DrawArrays(softgl::TRIANGLES, 0, 6);
    gl_.BindVertexArray(0);
    gl_.DepthMask(true);
    gl_.Disable(softgl::BLEND);
  }

  const Options& o_;
  int w_, h_;
  softgl::Context gl_;
  softgl::PbrShader pbr_;
  softgl::PhongShader phong_;
  softgl::UnlitShader unlit_;
  std::uint32_t sky_vao_ = 0;
  softgl::ShadowMap shadow_;
  std::uint32_t ground_vao_ = 0, ground_vbo_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app(kDescription, "softgl-render");
  app.footer(kFooter);
  try {
    Parse(app, argc, argv, o);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return 0;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "softgl-render: %s\nsoftgl-render --help lists the options\n", e.what());
    return 2;
  }
  bool any_directory = false;
  const std::vector<std::string> files = ModelFiles(o.models, any_directory);
  const bool batch = files.size() > 1 || any_directory;
  std::error_code ec;
  if (batch && !o.info) {
    if (o.output.back() != '/' && !std::filesystem::is_directory(o.output, ec)) {
      std::fprintf(stderr, "softgl-render: with several models -o names a directory (DIR/), not '%s'\n",
                   o.output.c_str());
      return 2;
    }
    std::filesystem::create_directories(o.output, ec);
    if (!std::filesystem::is_directory(o.output, ec)) {
      std::fprintf(stderr, "softgl-render: cannot make the directory %s\n", o.output.c_str());
      return 3;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "softgl-render: no model files in %s\n", o.models.front().c_str());
    return 1;
  }
  if (o.turntable > 0 && IsWebp(batch ? "" : o.output) && !kHasWebp) {
    std::fprintf(stderr, "softgl-render: this build has no WebP output (libwebp was not found); write PNG frames\n");
    return 2;
  }
  // --info renders nothing: a 1x1 context holds the models' objects.
  const int w = o.info ? 1 : o.width * o.supersample, h = o.info ? 1 : o.height * o.supersample;
  Renderer renderer(o, w, h);
  if (!renderer.Ready()) {
    std::fprintf(stderr, "softgl-render: cannot make a %dx%d framebuffer\n", w, h);
    return 2;
  }
  if (!o.env.empty() && !o.info && !renderer.LoadEnvironment(o.env)) return 1;
  if (!batch) return renderer.Render(files.front(), o.output);

  // A batch: one image per model in the directory, named after the model (NAME.png, or NAME_2.png for the second
  // model of that name); a model that fails is reported and the others still rendered.
  int failures = 0;
  std::vector<std::string> used;
  for (const std::string& file : files) {
    std::string name = std::filesystem::path(file).stem().string();
    const int seen = int(std::count(used.begin(), used.end(), name));
    used.push_back(name);
    if (seen > 0) name += "_" + std::to_string(seen + 1);
    const std::string output = (std::filesystem::path(o.output) / (name + ".png")).string();
    if (renderer.Render(file, output) != kOk) ++failures;
  }
  std::fprintf(stderr, "softgl-render: %zu models: %zu done, %d failed\n", files.size(), files.size() - failures,
               failures);
  return failures > 0 ? 1 : 0;
}

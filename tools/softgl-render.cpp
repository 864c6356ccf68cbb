// softgl-render — renders a model file to PNG: `softgl-render MODEL -o out.png [options]`.
//
// Exit status: 0 done; 1 the model cannot be loaded (missing file, unreadable format, nothing to draw); 2 bad command
// line; 3 the image cannot be written.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

namespace {

constexpr const char* kUsage = R"(usage: softgl-render MODEL -o OUT.png [options]
       softgl-render MODEL --info

Renders any model file assimp reads (OBJ, glTF/GLB, FBX, COLLADA, PLY, STL, 3DS, ...) with a camera framing
its bounding box and three-point lighting.

options:
  -o, --output FILE       the PNG to write (with --turntable: FILE_000.png, FILE_001.png, ...)
  --size WxH              image size in pixels (default 800x600)
  --azimuth DEG           camera angle around the model, from the front (default 30)
  --elevation DEG         camera angle above the horizon (default 20)
  --distance D            camera distance from the centre (default: framing the bounding sphere)
  --fov DEG               vertical field of view (default 40)
  --look-at EX,EY,EZ,TX,TY,TZ   explicit camera position and target (overrides the orbit options)
  --shader NAME           auto (default: pbr for metallic-roughness materials, else phong), pbr, phong, unlit
  --background R,G,B      background colour, components in [0, 1] (default 0.16,0.17,0.2)
  --wireframe             draw the triangle edges over the shaded model
  --point-size PX         diameter of the points of point meshes (1 to 64, default 3)
  --supersample N         render N times larger and average down (1 to 4, default 1)
  --turntable N           write N frames going once around the model
  --sheet COLSxROWS       one PNG of COLS x ROWS views going once around the model, left to right and top to
                          bottom, each of --size (not with --turntable)
  --info                  print what the file holds (meshes, vertex and triangle counts, materials and their
                          maps, bounding box, import time) and render nothing
  -q, --quiet             no progress bar
  -h, --help              this text
)";

struct Options {
  std::string model, output;
  int width = 800, height = 600;
  float azimuth = 30.0f, elevation = 20.0f, fov = 40.0f;
  std::optional<float> distance;
  std::optional<glm::vec3> eye, target;
  std::string shader = "auto";
  glm::vec3 background{0.16f, 0.17f, 0.2f};
  bool wireframe = false, quiet = false, info = false;
  int supersample = 1, turntable = 0;
  int sheet_cols = 0, sheet_rows = 0;  // --sheet; 0: none
  float point_size = 3.0f;
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

// Returns an error message, or empty when the options are good.
std::string Parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& v) {
      if (i + 1 >= argc) return false;
      v = argv[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help") return "help";
    if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "--wireframe") {
      o.wireframe = true;
    } else if (a == "--info") {
      o.info = true;
    } else if (a == "-o" || a == "--output") {
      if (!value(o.output)) return "-o needs a file name";
    } else if (a == "--size") {
      if (!value(v)) return "--size needs WxH";
      if (!ParsePair(v, 8192, o.width, o.height)) return "--size wants WxH with both from 1 to 8192, not '" + v + "'";
    } else if (a == "--azimuth" || a == "--elevation" || a == "--distance" || a == "--fov") {
      float f = 0.0f;
      if (!value(v) || !ParseFloats(v, 1, &f)) return a + " needs a number";
      if (a == "--azimuth") o.azimuth = f;
      else if (a == "--elevation") o.elevation = f;
      else if (a == "--fov") {
        if (f <= 1.0f || f >= 179.0f) return "--fov wants degrees between 1 and 179";
        o.fov = f;
      } else {
        if (f <= 0.0f) return "--distance must be positive";
        o.distance = f;
      }
    } else if (a == "--look-at") {
      float f[6];
      if (!value(v) || !ParseFloats(v, 6, f)) return "--look-at needs EX,EY,EZ,TX,TY,TZ";
      o.eye = glm::vec3(f[0], f[1], f[2]);
      o.target = glm::vec3(f[3], f[4], f[5]);
      if (*o.eye == *o.target) return "--look-at: the eye and the target are the same point";
    } else if (a == "--shader") {
      if (!value(o.shader) || (o.shader != "auto" && o.shader != "pbr" && o.shader != "phong" && o.shader != "unlit"))
        return "--shader is one of auto, pbr, phong, unlit";
    } else if (a == "--background") {
      float f[3];
      if (!value(v) || !ParseFloats(v, 3, f)) return "--background needs R,G,B";
      o.background = glm::clamp(glm::vec3(f[0], f[1], f[2]), 0.0f, 1.0f);
    } else if (a == "--point-size") {
      float f = 0.0f;
      if (!value(v) || !ParseFloats(v, 1, &f) || f < 1.0f || f > 64.0f) return "--point-size is 1 to 64 pixels";
      o.point_size = f;
    } else if (a == "--supersample") {
      if (!value(v) || !ParseInt(v, 1, 4, o.supersample)) return "--supersample is 1 to 4";
    } else if (a == "--sheet") {
      if (!value(v)) return "--sheet needs COLSxROWS";
      if (!ParsePair(v, 64, o.sheet_cols, o.sheet_rows))
        return "--sheet wants COLSxROWS with both from 1 to 64, not '" + v + "'";
    } else if (a == "--turntable") {
      if (!value(v) || !ParseInt(v, 1, 3600, o.turntable)) return "--turntable is 1 to 3600 frames";
    } else if (!a.empty() && a[0] == '-') {
      return "unknown option " + a;
    } else if (o.model.empty()) {
      o.model = a;
    } else {
      return "one model at a time (got '" + o.model + "' and '" + a + "')";
    }
  }
  if (o.model.empty()) return "no model file given";
  if (o.output.empty() && !o.info) return "no output file given (-o OUT.png)";
  if (o.sheet_cols > 0 && o.turntable > 0) return "--sheet and --turntable do not go together";
  if (o.sheet_cols > 0 &&
      (std::int64_t(o.width) * o.sheet_cols > 16384 || std::int64_t(o.height) * o.sheet_rows > 16384))
    return "--sheet: the sheet would be larger than 16384 pixels a side";
  if (std::int64_t(o.width) * o.supersample > softgl::kMaxFramebufferSize ||
      std::int64_t(o.height) * o.supersample > softgl::kMaxFramebufferSize)
    return "--size times --supersample is larger than " + std::to_string(softgl::kMaxFramebufferSize);
  return {};
}

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

}  // namespace

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Options o;
  if (const std::string err = Parse(argc, argv, o); !err.empty()) {
    if (err == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    std::fprintf(stderr, "softgl-render: %s\n\n%s", err.c_str(), kUsage);
    return 2;
  }
  // --info renders nothing: a 1x1 context holds the model's objects.
  const int w = o.info ? 1 : o.width * o.supersample, h = o.info ? 1 : o.height * o.supersample;
  softgl::Context gl(w, h);
  if (gl.GetError() != softgl::NO_ERROR) {
    std::fprintf(stderr, "softgl-render: cannot make a %dx%d framebuffer\n", w, h);
    return 2;
  }
  softgl::Model model;
  std::string error;
  if (!model.Load(gl, o.model, &error)) {
    std::fprintf(stderr, "softgl-render: %s\n", error.c_str());
    return 1;
  }
  const double load_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (o.info) {
    PrintInfo(o.model, model, load_seconds);
    return 0;
  }
  for (const std::string& warning : model.warnings)
    std::fprintf(stderr, "softgl-render: warning: %s\n", warning.c_str());

  bool any_pbr = false;
  for (const softgl::Material& m : model.materials) any_pbr = any_pbr || m.pbr;
  const std::string shader_name = o.shader == "auto" ? (any_pbr ? "pbr" : "phong") : o.shader;
  softgl::PbrShader pbr;
  softgl::PhongShader phong;
  softgl::UnlitShader unlit;
  if (shader_name == "pbr") pbr.environment_levels = softgl::MakeStudioEnvironment(gl, 64);
  softgl::MaterialProgram* program = shader_name == "pbr" ? static_cast<softgl::MaterialProgram*>(&pbr)
                                     : shader_name == "phong" ? static_cast<softgl::MaterialProgram*>(&phong)
                                                              : static_cast<softgl::MaterialProgram*>(&unlit);
  const int views = o.sheet_cols > 0 ? o.sheet_cols * o.sheet_rows : o.turntable;  // around the model
  const int frames = std::max(1, views);
  softgl::Image sheet;
  if (o.sheet_cols > 0) {
    sheet.width = o.width * o.sheet_cols;
    sheet.height = o.height * o.sheet_rows;
    sheet.rgba.assign(std::size_t(sheet.width) * std::size_t(sheet.height) * 4, 0);
  }
  const bool progress = !o.quiet && isatty(fileno(stderr)) && frames > 1;
  const auto render_start = Clock::now();
  for (int frame = 0; frame < frames; ++frame) {
    const float aspect = float(w) / float(h);
    const float azimuth = o.azimuth + (views ? 360.0f * float(frame) / float(frames) : 0.0f);
    softgl::Camera cam = softgl::Camera::Frame(model.bounds, aspect, azimuth, o.elevation, o.fov);
    if (o.distance) {
      cam = softgl::Camera::Orbit(model.bounds.Center(), *o.distance, azimuth, o.elevation, o.fov);
      const float r = model.bounds.Radius();
      cam.near_plane = std::max(*o.distance - r * 1.5f, *o.distance * 0.01f);
      cam.far_plane = *o.distance + r * 1.5f;
    }
    if (o.eye) {
      cam.eye = *o.eye;
      cam.target = *o.target;
      const float d = glm::length(cam.eye - model.bounds.Center());
      cam.near_plane = std::max(d - model.bounds.Radius() * 1.5f, d * 0.01f);
      cam.far_plane = d + model.bounds.Radius() * 1.5f;
    }
    const glm::mat4 view_proj = cam.Projection(aspect) * cam.View();
    const softgl::Lighting lighting = softgl::Lighting::ThreePoint(cam.eye, cam.target);
    pbr.lighting = phong.lighting = unlit.lighting = lighting;

    gl.ClearColor(o.background.r, o.background.g, o.background.b, 1.0f);
    gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
    gl.Enable(softgl::DEPTH_TEST);
    gl.PointSize(o.point_size * float(o.supersample));
    if (o.wireframe) {  // the shaded surface a little behind its edges
      gl.Enable(softgl::POLYGON_OFFSET_FILL);
      gl.PolygonOffset(1.0f, 1.0f);
    }
    model.Draw(gl, *program, view_proj);
    if (o.wireframe) {
      gl.Disable(softgl::POLYGON_OFFSET_FILL);
      gl.PolygonMode(softgl::FRONT_AND_BACK, softgl::LINE);
      gl.DepthFunc(softgl::LEQUAL);
      FlatShader flat;
      flat.color = glm::vec4(glm::vec3(o.background.r + o.background.g + o.background.b > 1.5f ? 0.1f : 0.9f), 1.0f);
      model.Draw(gl, flat, view_proj);
      gl.PolygonMode(softgl::FRONT_AND_BACK, softgl::FILL);
      gl.DepthFunc(softgl::LESS);
    }
    const softgl::Image image = Downsample(gl.ReadPixels(), o.supersample);
    if (o.sheet_cols > 0) {  // into its cell; the sheet is written after the last view
      const int cx = frame % o.sheet_cols, cy = frame / o.sheet_cols;
      const std::size_t row = std::size_t(image.width) * 4;
      for (int y = 0; y < image.height; ++y)
        std::memcpy(&sheet.rgba[(std::size_t(cy * image.height + y) * std::size_t(sheet.width) +
                                 std::size_t(cx * image.width)) * 4],
                    &image.rgba[std::size_t(y) * row], row);
      if (progress) Progress(frame + 1, frames, std::chrono::duration<double>(Clock::now() - render_start).count());
      if (frame + 1 < frames) continue;
    }
    const softgl::Image& written = o.sheet_cols > 0 ? sheet : image;
    std::string path = o.output;
    if (o.turntable) {
      char suffix[16];
      std::snprintf(suffix, sizeof suffix, "_%03d", frame);
      const auto dot = path.rfind('.');
      path = dot == std::string::npos || dot < path.find_last_of('/') + 1 ? path + suffix + ".png"
                                                                         : path.substr(0, dot) + suffix + path.substr(dot);
    }
    if (!softgl::WritePng(path, written)) {
      if (progress) std::fputc('\n', stderr);
      std::fprintf(stderr, "softgl-render: cannot write %s\n", path.c_str());
      return 3;
    }
    if (progress && o.sheet_cols == 0)
      Progress(frame + 1, frames, std::chrono::duration<double>(Clock::now() - render_start).count());
    else if (!progress && !o.quiet)
      std::printf("%s\n", path.c_str());
  }
  if (progress) std::fputc('\n', stderr);
  const double render_seconds = std::chrono::duration<double>(Clock::now() - render_start).count();
  if (!o.quiet)
    std::fprintf(stderr,
                 "softgl-render: %s: %d triangles, %d lines, %d points, %zu meshes, %zu materials, %d textures, "
                 "shader %s; load %.2f s, render %d frame%s of %dx%d in %.2f s (%.1f ms/frame)\n",
                 o.model.c_str(), model.triangles_drawn, model.lines_drawn, model.points_drawn, model.meshes.size(),
                 model.materials.size(),
                 model.textures_loaded, shader_name.c_str(), load_seconds, frames, frames == 1 ? "" : "s", w, h,
                 render_seconds, 1000.0 * render_seconds / frames);
  return 0;
}

// The Python module softgl._softgl: OpenGL's model (Context, buffers, vertex arrays, textures, framebuffers, the
// built-in shaders, models) and the high-level Renderer, with numpy arrays in and out.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

#include "arrays.h"
#include "renderer.h"

namespace py = pybind11;
using namespace softgl_python;

namespace {

/// An OpenGL error from a call, as GLError in Python: the error's name, the call and softgl's message.
struct GlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* ErrorName(softgl::Enum e) {
  switch (e) {
    case softgl::INVALID_ENUM: return "INVALID_ENUM";
    case softgl::INVALID_VALUE: return "INVALID_VALUE";
    case softgl::INVALID_OPERATION: return "INVALID_OPERATION";
    case softgl::OUT_OF_MEMORY: return "OUT_OF_MEMORY";
    case softgl::INVALID_FRAMEBUFFER_OPERATION: return "INVALID_FRAMEBUFFER_OPERATION";
    default: return "NO_ERROR";
  }
}

// A Context and what Python needs beside it: the last error message (from the debug callback) and a lock, so that
// two threads calling into one context take turns (each context renders on its own threads).
struct ContextBox {
  ContextBox(int width, int height, const softgl::Context::Options& options) : gl(width, height, options) {
    gl.DebugMessageCallback([this](softgl::Enum, const char* call, const char* text) {
      message = std::string(call ? call : "") + ": " + (text ? text : "");
    });
  }
  softgl::Context gl;
  std::string message;
  std::mutex mutex;
  // Raises GLError if the call just made recorded an error.
  void Check(const char* call) {
    const softgl::Enum e = gl.GetError();
    if (e == softgl::NO_ERROR) return;
    throw GlError(std::string(ErrorName(e)) + " in " + call + (message.empty() ? "" : " (" + message + ")"));
  }
};

// Runs fn(gl) under the context's lock and raises the error it recorded, if any.
template <class Fn>
auto Call(ContextBox& c, const char* name, Fn&& fn) {
  std::lock_guard<std::mutex> lock(c.mutex);
  c.message.clear();
  if constexpr (std::is_void_v<decltype(fn(c.gl))>) {
    fn(c.gl);
    c.Check(name);
  } else {
    auto result = fn(c.gl);
    c.Check(name);
    return result;
  }
}

// Bytes of a buffer-protocol object (bytes, bytearray, numpy array...), which must be C-contiguous.
py::buffer_info Bytes(const py::buffer& data, const char* arg) {
  py::buffer_info info = data.request();
  std::ptrdiff_t expected = info.itemsize;
  for (py::ssize_t i = info.ndim - 1; i >= 0; --i) {
    if (info.shape[std::size_t(i)] > 1 && info.strides[std::size_t(i)] != expected)
      throw py::value_error(std::string(arg) + ": the data must be C-contiguous (numpy.ascontiguousarray makes it so)");
    expected *= info.shape[std::size_t(i)];
  }
  return info;
}

std::size_t ByteSize(const py::buffer_info& info) { return std::size_t(info.size) * std::size_t(info.itemsize); }

py::array_t<float> ToNumpy(const glm::mat4& m) {
  py::array_t<float> a({4, 4});
  auto r = a.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = m[j][i];
  return a;
}

std::vector<float> FloatList(const py::handle& values, const char* arg, std::size_t n) {
  std::vector<float> out;
  for (const py::handle v : values) out.push_back(v.cast<float>());
  if (out.size() != n) throw py::value_error(std::string(arg) + ": " + std::to_string(n) + " numbers are needed");
  for (float f : out)
    if (!std::isfinite(f)) throw py::value_error(std::string(arg) + ": holds NaN or infinity");
  return out;
}

// The pixel type and channel count of an image array for TexImage2D: its dtype and last dimension.
void PixelLayout(const py::array& a, softgl::Enum& format, softgl::Enum& type, int& width, int& height) {
  const char kind = a.dtype().kind();
  const int size = int(a.itemsize());
  if (kind == 'u' && size == 1) type = softgl::UNSIGNED_BYTE;
  else if (kind == 'u' && size == 2) type = softgl::UNSIGNED_SHORT;
  else if (kind == 'f' && size == 4) type = softgl::FLOAT;
  else if (kind == 'f' && size == 2) type = softgl::HALF_FLOAT;
  else throw py::type_error("image: dtype must be uint8, uint16, float16 or float32, got " + py::str(a.dtype()).cast<std::string>());
  if (!(a.ndim() == 2 || (a.ndim() == 3 && a.shape(2) >= 1 && a.shape(2) <= 4)))
    throw py::value_error("image: shape must be (H, W) or (H, W, C) with C 1 to 4, got " + ShapeText(a));
  const int channels = a.ndim() == 2 ? 1 : int(a.shape(2));
  const softgl::Enum formats[4] = {softgl::RED, softgl::RG, softgl::RGB, softgl::RGBA};
  format = formats[channels - 1];
  height = int(a.shape(0));
  width = int(a.shape(1));
  if (!(a.flags() & py::array::c_style))
    throw py::value_error("image: the array must be C-contiguous (numpy.ascontiguousarray makes it so)");
}

softgl::ToneMap ToneMapOf(const std::string& name) {
  if (name == "clamp" || name == "none") return softgl::ToneMap::kClamp;
  if (name == "pbr-neutral") return softgl::ToneMap::kPbrNeutral;
  if (name == "aces") return softgl::ToneMap::kAces;
  throw py::value_error("tone_map: must be 'clamp', 'pbr-neutral' or 'aces', got '" + name + "'");
}
std::string ToneMapName(softgl::ToneMap t) {
  return t == softgl::ToneMap::kPbrNeutral ? "pbr-neutral" : t == softgl::ToneMap::kAces ? "aces" : "clamp";
}

std::string CheckFile(const std::string& path, const char* arg) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    PyErr_SetString(PyExc_FileNotFoundError, (std::string(arg) + ": no such file: " + path).c_str());
    throw py::error_already_set();
  }
  return path;
}

// The built-in surface shaders: uniforms as properties.
template <class S>
py::class_<S> BindSurfaceShader(py::module_& m, const char* name, const char* doc) {
  auto cls = py::class_<S>(m, name, doc);
  cls.def(py::init<>())
      .def("set_transforms",
           [](S& s, const py::handle& model, const py::handle& view_proj) {
             s.SetTransforms(Matrix4(model, "model"), Matrix4(view_proj, "view_proj"));
           },
           py::arg("model"), py::arg("view_proj"),
           "The object's world transform and the camera's projection x view (4 x 4, row-major as numpy holds them).")
      .def_property_readonly("model", [](const S& s) { return ToNumpy(s.model); })
      .def_property_readonly("view_proj", [](const S& s) { return ToNumpy(s.view_proj); })
      .def_property(
          "base_color", [](const S& s) { return std::vector<float>{s.material.base_color.r, s.material.base_color.g, s.material.base_color.b, s.material.base_color.a}; },
          [](S& s, const py::handle& v) {
            const auto c = FloatList(v, "base_color", 4);
            s.material.base_color = glm::vec4(c[0], c[1], c[2], c[3]);
          },
          "RGBA factor of the surface (times the vertex colour and the base colour texture)")
      .def_property(
          "emissive", [](const S& s) { return std::vector<float>{s.material.emissive.r, s.material.emissive.g, s.material.emissive.b}; },
          [](S& s, const py::handle& v) { s.material.emissive = Vec3(v, "emissive"); })
      .def_property(
          "specular", [](const S& s) { return std::vector<float>{s.material.specular.r, s.material.specular.g, s.material.specular.b}; },
          [](S& s, const py::handle& v) { s.material.specular = Vec3(v, "specular"); })
      .def_property("shininess", [](const S& s) { return s.material.shininess; },
                    [](S& s, double v) { s.material.shininess = Positive(v, "shininess", true); })
      .def_property("metallic", [](const S& s) { return s.material.metallic; },
                    [](S& s, double v) { s.material.metallic = Positive(v, "metallic", true); })
      .def_property("roughness", [](const S& s) { return s.material.roughness; },
                    [](S& s, double v) { s.material.roughness = Positive(v, "roughness", true); })
      .def_property("base_color_texture", [](const S& s) { return s.material.base_color_texture; },
                    [](S& s, std::uint32_t id) { s.material.base_color_texture = id; },
                    "texture id read on unit 0 (bind it there), sampled as an sRGB colour map; 0: none")
      .def_property(
          "alpha_mode",
          [](const S& s) {
            return std::string(s.material.alpha_mode == softgl::Material::AlphaMode::kMask    ? "mask"
                               : s.material.alpha_mode == softgl::Material::AlphaMode::kBlend ? "blend"
                                                                                                : "opaque");
          },
          [](S& s, const std::string& mode) {
            if (mode == "opaque") s.material.alpha_mode = softgl::Material::AlphaMode::kOpaque;
            else if (mode == "mask") s.material.alpha_mode = softgl::Material::AlphaMode::kMask;
            else if (mode == "blend") s.material.alpha_mode = softgl::Material::AlphaMode::kBlend;
            else throw py::value_error("alpha_mode: must be 'opaque', 'mask' or 'blend', got '" + mode + "'");
          },
          "glTF's alpha mode: 'opaque' (alpha taken as 1), 'mask' (discarded below alpha_cutoff) or 'blend'")
      .def_property("alpha_cutoff", [](const S& s) { return s.material.alpha_cutoff; },
                    [](S& s, double v) { s.material.alpha_cutoff = Positive(v, "alpha_cutoff", true); })
      .def_property("tone_map", [](const S& s) { return ToneMapName(s.tone_map); },
                    [](S& s, const std::string& t) { s.tone_map = ToneMapOf(t); })
      .def_property("exposure", [](const S& s) { return s.exposure; },
                    [](S& s, double e) {
                      if (!std::isfinite(e)) throw py::value_error("exposure: must be finite");
                      s.exposure = float(e);
                    })
      .def_property("lit", [](const S& s) { return s.lit; }, [](S& s, bool lit) { s.lit = lit; })
      .def_property("shadows", [](const S& s) { return s.shadows; }, [](S& s, bool on) { s.shadows = on; },
                    "the first light shadowed through the shadow map on unit UNIT_SHADOW (see make_shadow_map)")
      .def_property("shadow_matrix", [](const S& s) { return ToNumpy(s.shadow_matrix); },
                    [](S& s, const py::handle& m) { s.shadow_matrix = Matrix4(m, "shadow_matrix"); },
                    "world to the shadow map's texture coordinates and depth, all in [0, 1]")
      .def_property("shadow_bias", [](const S& s) { return s.shadow_bias; },
                    [](S& s, double b) {
                      if (!std::isfinite(b)) throw py::value_error("shadow_bias: must be finite");
                      s.shadow_bias = float(b);
                    })
      .def_property("hdr_output", [](const S& s) { return s.hdr_output; }, [](S& s, bool on) { s.hdr_output = on; },
                    "for a float colour buffer: the colour unclamped, without tone curve or sRGB encoding")
      .def(
          "set_lights",
          [](S& s, const py::list& lights, const py::handle& ambient, const py::handle& eye) {
            if (lights.size() > std::size_t(softgl::Lighting::kMaxLights))
              throw py::value_error("lights: at most " + std::to_string(softgl::Lighting::kMaxLights) + " lights");
            softgl::Lighting l;
            l.count = 0;
            for (const py::handle item : lights) {
              const py::tuple t = item.cast<py::tuple>();
              if (t.size() != 2) throw py::value_error("lights: each light is (direction, color)");
              const glm::vec3 d = Vec3(t[0], "lights: direction");
              if (glm::length(d) == 0.0f) throw py::value_error("lights: a direction must not be zero");
              l.lights[l.count++] = {glm::normalize(d), Vec3(t[1], "lights: color")};
            }
            l.ambient = Vec3(ambient, "ambient");
            l.eye = Vec3(eye, "eye");
            s.lighting = l;
          },
          py::arg("lights"), py::arg("ambient") = std::vector<float>{0.08f, 0.08f, 0.08f},
          py::arg("eye") = std::vector<float>{0.0f, 0.0f, 3.0f},
          "Directional lights as (direction towards the light, colour) pairs (up to 4), the ambient colour, and the "
          "camera's position (for specular light).")
      .def(
          "set_three_point_lighting",
          [](S& s, const py::handle& eye, const py::handle& target) {
            s.lighting = softgl::Lighting::ThreePoint(Vec3(eye, "eye"), Vec3(target, "target"));
          },
          py::arg("eye"), py::arg("target"), "Key, fill and rim lights placed around the view from eye to target.");
  return cls;
}

// Per-vertex colours as RGBA floats: (N, 3) or (N, 4), float in [0, 1] or uint8.
std::vector<float> ColorRows(const py::handle& colors, std::size_t n) {
  const py::array a = AsArray(colors, "colors");
  const int cols = a.ndim() == 2 ? int(a.shape(1)) : 0;
  if (cols != 3 && cols != 4) throw py::value_error("colors: shape must be (N, 3) or (N, 4), got " + ShapeText(a));
  std::vector<float> c;
  if (a.dtype().is(py::dtype::of<std::uint8_t>())) {
    if (!(a.flags() & py::array::c_style))
      throw py::value_error("colors: the array must be C-contiguous (numpy.ascontiguousarray makes it so)");
    const auto* p = static_cast<const std::uint8_t*>(a.data());
    for (py::ssize_t i = 0; i < a.size(); ++i) c.push_back(float(p[i]) / 255.0f);
  } else {
    c = FloatRows(colors, "colors", cols);
  }
  if (c.size() / std::size_t(cols) != n)
    throw py::value_error("colors: one row per vertex is needed (" + std::to_string(n) + "), got " +
                          std::to_string(c.size() / std::size_t(cols)));
  std::vector<float> out;
  out.reserve(n * 4);
  for (std::size_t v = 0; v < n; ++v)
    for (int k = 0; k < 4; ++k) out.push_back(k < cols ? c[v * std::size_t(cols) + std::size_t(k)] : 1.0f);
  return out;
}

std::int64_t ObjectId(const py::object& object_id) {
  if (object_id.is_none()) return -1;
  const std::int64_t id = object_id.cast<std::int64_t>();
  if (id < 0 || id > 0xFFFFFFFFll) throw py::value_error("object_id: must be 0 to 2**32 - 1");
  return id;
}

// Points (POINTS) or line segments (LINES) from arrays.
int AddShape(Renderer& r, softgl::Enum mode, const py::handle& positions, const py::handle& segments,
             const py::handle& colors, double size, const py::handle& pose, const py::object& object_id,
             const py::handle& color) {
  MeshData mesh;
  mesh.mode = mode;
  mesh.positions = FloatRows(positions, "positions", 3);
  const std::size_t n = mesh.positions.size() / 3;
  const bool lines = mode == softgl::LINES;
  if (n == 0 || n > std::size_t(std::numeric_limits<int>::max()))
    throw py::value_error("positions: 1 to 2**31 - 1 vertices are needed, got " + std::to_string(n));
  if (!segments.is_none()) {
    mesh.faces = IndexRows(segments, "segments", 2, n);
    if (mesh.faces.empty()) throw py::value_error("segments: no segment (0 rows)");
    if (mesh.faces.size() > std::size_t(std::numeric_limits<int>::max())) throw py::value_error("segments: too many");
  } else if (lines && n % 2 != 0) {
    throw py::value_error("positions: without segments, the positions are pairs: their count (" + std::to_string(n) +
                          ") must be even");
  }
  if (!colors.is_none()) mesh.colors = ColorRows(colors, n);
  const float max_size = lines ? 255.0f : 2047.0f;
  if (!(size >= 1.0 && size <= max_size))
    throw py::value_error(std::string(lines ? "width" : "size") + ": must be 1 to " + std::to_string(int(max_size)) + " pixels");
  mesh.size = float(size);
  Surface surface;
  const auto c = FloatList(color, "color", 4);
  surface.base_color = glm::vec4(c[0], c[1], c[2], c[3]);
  const glm::mat4 p = pose.is_none() ? glm::mat4(1.0f) : Matrix4(pose, "pose");
  const std::int64_t id = ObjectId(object_id);
  py::gil_scoped_release release;
  return r.AddMesh(mesh, surface, p, id, false);
}

}  // namespace

PYBIND11_MODULE(_softgl, m) {
  m.doc() = "softgl: a software rasterizer with OpenGL's model, and a renderer of meshes to numpy arrays";
  py::register_exception<GlError>(m, "GLError", PyExc_RuntimeError);

#define X(name) m.attr(#name) = softgl::name;
#include "enum_names.inc"
#undef X
  for (int i = 1; i < softgl::kMaxColorOutputs; ++i)  // (C++ writes COLOR_ATTACHMENT0 + i)
    m.attr(("COLOR_ATTACHMENT" + std::to_string(i)).c_str()) = softgl::COLOR_ATTACHMENT0 + softgl::Enum(i);
  m.attr("MAX_FRAMEBUFFER_SIZE") = softgl::kMaxFramebufferSize;
  m.attr("UNIT_BASE_COLOR") = int(softgl::kUnitBaseColor);
  m.attr("UNIT_ENVIRONMENT") = int(softgl::kUnitEnvironment);
  m.attr("UNIT_SHADOW") = int(softgl::kUnitShadow);
  m.attr("ATTRIB_POSITION") = int(softgl::kAttribPosition);
  m.attr("ATTRIB_NORMAL") = int(softgl::kAttribNormal);
  m.attr("ATTRIB_UV") = int(softgl::kAttribUv);
  m.attr("ATTRIB_TANGENT") = int(softgl::kAttribTangent);
  m.attr("ATTRIB_COLOR") = int(softgl::kAttribColor);

  // ---- The built-in shaders ----
  BindSurfaceShader<softgl::UnlitShader>(m, "UnlitShader", "Base colour only (vertex colour x base_color x texture).");
  BindSurfaceShader<softgl::PhongShader>(m, "PhongShader", "Blinn-Phong per fragment, with directional lights.");
  BindSurfaceShader<softgl::PbrShader>(m, "PbrShader",
                                       "glTF metallic-roughness (Cook-Torrance, GGX), with image-based ambient light.")
      .def_readwrite("environment_levels", &softgl::PbrShader::environment_levels)
      .def_readwrite("environment_strength", &softgl::PbrShader::environment_strength)
      .def_readwrite("environment_hdr", &softgl::PbrShader::environment_hdr);

  // ---- Context ----
  py::class_<ContextBox>(m, "Context", "An OpenGL-style context with its own framebuffer (OpenGL 3.3's model).")
      .def(py::init([](int width, int height, int samples, int threads, softgl::Enum color_format,
                       softgl::Enum depth_format) {
             if (width < 0 || height < 0 || width > softgl::kMaxFramebufferSize || height > softgl::kMaxFramebufferSize)
               throw py::value_error("width, height: must be 0 to " + std::to_string(softgl::kMaxFramebufferSize));
             if (threads < 0 || threads > 256) throw py::value_error("threads: must be 0 (all) to 256");
             softgl::Context::Options o;
             o.samples = samples;
             o.threads = threads;
             o.color_format = color_format;
             o.depth_format = depth_format;
             auto c = std::make_unique<ContextBox>(width, height, o);
             c->Check("Context");
             return c;
           }),
           py::arg("width"), py::arg("height"), py::arg("samples") = 0, py::arg("threads") = 0,
           py::arg("color_format") = softgl::RGBA8, py::arg("depth_format") = softgl::DEPTH_COMPONENT32F)
      .def_property_readonly("width", [](ContextBox& c) { return c.gl.Width(); })
      .def_property_readonly("height", [](ContextBox& c) { return c.gl.Height(); })
      .def_property_readonly("threads", [](ContextBox& c) { return c.gl.Threads(); })
      .def("get_error", [](ContextBox& c) { return c.gl.GetError(); },
           "The error flag (GetError); calls raise GLError themselves, so this is normally NO_ERROR.")
      .def("finish", [](ContextBox& c) { Call(c, "finish", [](softgl::Context& gl) { gl.Finish(); }); },
           py::call_guard<py::gil_scoped_release>())
      .def("flush", [](ContextBox& c) { Call(c, "flush", [](softgl::Context& gl) { gl.Flush(); }); },
           py::call_guard<py::gil_scoped_release>())
      // Buffers
      .def("gen_buffer", [](ContextBox& c) { return Call(c, "gen_buffer", [](softgl::Context& gl) { return gl.GenBuffer(); }); })
      .def("delete_buffer", [](ContextBox& c, std::uint32_t id) { Call(c, "delete_buffer", [&](softgl::Context& gl) { gl.DeleteBuffer(id); }); })
      .def("bind_buffer", [](ContextBox& c, softgl::Enum target, std::uint32_t id) {
             Call(c, "bind_buffer", [&](softgl::Context& gl) { gl.BindBuffer(target, id); });
           }, py::arg("target"), py::arg("buffer"))
      .def("buffer_data", [](ContextBox& c, softgl::Enum target, const py::buffer& data, softgl::Enum usage) {
             const py::buffer_info info = Bytes(data, "data");
             Call(c, "buffer_data", [&](softgl::Context& gl) {
               gl.BufferData(target, std::ptrdiff_t(ByteSize(info)), info.ptr, usage);
             });
           }, py::arg("target"), py::arg("data"), py::arg("usage") = softgl::STATIC_DRAW,
           "BufferData with the bytes of `data` (a numpy array, bytes, ...; C-contiguous).")
      .def("buffer_storage_size", [](ContextBox& c, softgl::Enum target, std::ptrdiff_t size, softgl::Enum usage) {
             Call(c, "buffer_data", [&](softgl::Context& gl) { gl.BufferData(target, size, nullptr, usage); });
           }, py::arg("target"), py::arg("size"), py::arg("usage") = softgl::STATIC_DRAW,
           "BufferData(target, size, NULL, usage): `size` bytes of undefined contents.")
      .def("buffer_sub_data", [](ContextBox& c, softgl::Enum target, std::ptrdiff_t offset, const py::buffer& data) {
             const py::buffer_info info = Bytes(data, "data");
             Call(c, "buffer_sub_data", [&](softgl::Context& gl) {
               gl.BufferSubData(target, offset, std::ptrdiff_t(ByteSize(info)), info.ptr);
             });
           }, py::arg("target"), py::arg("offset"), py::arg("data"))
      .def("get_buffer_sub_data", [](ContextBox& c, softgl::Enum target, std::ptrdiff_t offset, std::ptrdiff_t size) {
             if (size < 0) throw py::value_error("size: must be >= 0");
             py::array_t<std::uint8_t> out(size);
             Call(c, "get_buffer_sub_data", [&](softgl::Context& gl) { gl.GetBufferSubData(target, offset, size, out.mutable_data()); });
             return out;
           }, py::arg("target"), py::arg("offset"), py::arg("size"), "The bytes as a uint8 array.")
      // Vertex arrays
      .def("gen_vertex_array", [](ContextBox& c) { return Call(c, "gen_vertex_array", [](softgl::Context& gl) { return gl.GenVertexArray(); }); })
      .def("delete_vertex_array", [](ContextBox& c, std::uint32_t id) { Call(c, "delete_vertex_array", [&](softgl::Context& gl) { gl.DeleteVertexArray(id); }); })
      .def("bind_vertex_array", [](ContextBox& c, std::uint32_t id) { Call(c, "bind_vertex_array", [&](softgl::Context& gl) { gl.BindVertexArray(id); }); })
      .def("vertex_attribute_pointer", [](ContextBox& c, std::uint32_t index, int size, softgl::Enum type, bool normalized, int stride, std::size_t offset) {
             Call(c, "vertex_attribute_pointer", [&](softgl::Context& gl) { gl.VertexAttributePointer(index, size, type, normalized, stride, offset); });
           }, py::arg("index"), py::arg("size"), py::arg("type"), py::arg("normalized") = false, py::arg("stride") = 0, py::arg("offset") = 0)
      .def("vertex_attrib_i_pointer", [](ContextBox& c, std::uint32_t index, int size, softgl::Enum type, int stride, std::size_t offset) {
             Call(c, "vertex_attrib_i_pointer", [&](softgl::Context& gl) { gl.VertexAttribIPointer(index, size, type, stride, offset); });
           }, py::arg("index"), py::arg("size"), py::arg("type"), py::arg("stride") = 0, py::arg("offset") = 0)
      .def("enable_vertex_attrib_array", [](ContextBox& c, std::uint32_t i) { Call(c, "enable_vertex_attrib_array", [&](softgl::Context& gl) { gl.EnableVertexAttribArray(i); }); })
      .def("disable_vertex_attrib_array", [](ContextBox& c, std::uint32_t i) { Call(c, "disable_vertex_attrib_array", [&](softgl::Context& gl) { gl.DisableVertexAttribArray(i); }); })
      .def("vertex_attrib_divisor", [](ContextBox& c, std::uint32_t i, std::uint32_t d) { Call(c, "vertex_attrib_divisor", [&](softgl::Context& gl) { gl.VertexAttribDivisor(i, d); }); })
      .def("vertex_attrib4f", [](ContextBox& c, std::uint32_t i, float x, float y, float z, float w) {
             Call(c, "vertex_attrib4f", [&](softgl::Context& gl) { gl.VertexAttrib4f(i, x, y, z, w); });
           }, "The current value of attribute i (read while its array is disabled).")
      // Shaders
      .def("use_program", [](ContextBox& c, softgl::UnlitShader& s) { Call(c, "use_program", [&](softgl::Context& gl) { gl.UseProgram(s); }); }, py::keep_alive<1, 2>())
      .def("use_program", [](ContextBox& c, softgl::PhongShader& s) { Call(c, "use_program", [&](softgl::Context& gl) { gl.UseProgram(s); }); }, py::keep_alive<1, 2>())
      .def("use_program", [](ContextBox& c, softgl::PbrShader& s) { Call(c, "use_program", [&](softgl::Context& gl) { gl.UseProgram(s); }); }, py::keep_alive<1, 2>())
      .def("use_program", [](ContextBox& c, py::none) { Call(c, "use_program", [&](softgl::Context& gl) { gl.UseProgram(nullptr); }); })
      // Textures
      .def("gen_texture", [](ContextBox& c) { return Call(c, "gen_texture", [](softgl::Context& gl) { return gl.GenTexture(); }); })
      .def("delete_texture", [](ContextBox& c, std::uint32_t id) { Call(c, "delete_texture", [&](softgl::Context& gl) { gl.DeleteTexture(id); }); })
      .def("active_texture", [](ContextBox& c, softgl::Enum unit) { Call(c, "active_texture", [&](softgl::Context& gl) { gl.ActiveTexture(unit); }); })
      .def("bind_texture", [](ContextBox& c, softgl::Enum target, std::uint32_t id) { Call(c, "bind_texture", [&](softgl::Context& gl) { gl.BindTexture(target, id); }); },
           py::arg("target"), py::arg("texture"))
      .def("tex_image_2d", [](ContextBox& c, softgl::Enum target, int level, softgl::Enum internal_format, const py::handle& image, bool flip) {
             const py::array a = AsArray(image, "image");
             softgl::Enum format, type;
             int width, height;
             PixelLayout(a, format, type, width, height);
             const std::size_t row = std::size_t(a.strides(0));
             std::vector<std::uint8_t> flipped;
             const void* pixels = a.data();
             if (flip) {
               flipped.resize(row * std::size_t(height));
               for (int y = 0; y < height; ++y)
                 std::memcpy(flipped.data() + std::size_t(y) * row, static_cast<const std::uint8_t*>(a.data()) + std::size_t(height - 1 - y) * row, row);
               pixels = flipped.data();
             }
             Call(c, "tex_image_2d", [&](softgl::Context& gl) {
               gl.PixelStore(softgl::UNPACK_ALIGNMENT, 1);
               gl.TexImage2D(target, level, internal_format, width, height, 0, format, type, pixels);
             });
           }, py::arg("target"), py::arg("level"), py::arg("internal_format"), py::arg("image"), py::arg("flip") = false,
           "TexImage2D from an array of shape (H, W) or (H, W, C): uint8, uint16, float16 or float32, C-contiguous. "
           "Its first row is the texture's bottom row, as OpenGL takes it; flip=True takes the array's last row first "
           "(an image as files and numpy hold it, top row first).")
      .def("tex_image_2d_empty", [](ContextBox& c, softgl::Enum target, int level, softgl::Enum internal_format, int width, int height, softgl::Enum format, softgl::Enum type) {
             Call(c, "tex_image_2d", [&](softgl::Context& gl) { gl.TexImage2D(target, level, internal_format, width, height, 0, format, type, nullptr); });
           }, py::arg("target"), py::arg("level"), py::arg("internal_format"), py::arg("width"), py::arg("height"),
           py::arg("format") = softgl::RGBA, py::arg("type") = softgl::UNSIGNED_BYTE,
           "TexImage2D with no data (a render target's storage).")
      .def("tex_parameter", [](ContextBox& c, softgl::Enum target, softgl::Enum pname, const py::handle& value) {
             Call(c, "tex_parameter", [&](softgl::Context& gl) {
               if (py::isinstance<py::float_>(value)) gl.TexParameterf(target, pname, value.cast<float>());
               else if (py::isinstance<py::int_>(value)) gl.TexParameteri(target, pname, value.cast<int>());
               else {
                 const auto v = FloatList(value, "value", 4);
                 gl.TexParameterfv(target, pname, v.data());
               }
             });
           }, py::arg("target"), py::arg("pname"), py::arg("value"),
           "TexParameteri (an int), TexParameterf (a float) or TexParameterfv (four numbers: TEXTURE_BORDER_COLOR).")
      .def("generate_mipmap", [](ContextBox& c, softgl::Enum target) { Call(c, "generate_mipmap", [&](softgl::Context& gl) { gl.GenerateMipmap(target); }); })
      // Framebuffers and renderbuffers
      .def("gen_framebuffer", [](ContextBox& c) { return Call(c, "gen_framebuffer", [](softgl::Context& gl) { return gl.GenFramebuffer(); }); })
      .def("delete_framebuffer", [](ContextBox& c, std::uint32_t id) { Call(c, "delete_framebuffer", [&](softgl::Context& gl) { gl.DeleteFramebuffer(id); }); })
      .def("bind_framebuffer", [](ContextBox& c, softgl::Enum target, std::uint32_t id) { Call(c, "bind_framebuffer", [&](softgl::Context& gl) { gl.BindFramebuffer(target, id); }); },
           py::arg("target"), py::arg("framebuffer"))
      .def("framebuffer_texture_2d", [](ContextBox& c, softgl::Enum target, softgl::Enum attachment, softgl::Enum textarget, std::uint32_t texture, int level) {
             Call(c, "framebuffer_texture_2d", [&](softgl::Context& gl) { gl.FramebufferTexture2D(target, attachment, textarget, texture, level); });
           }, py::arg("target"), py::arg("attachment"), py::arg("textarget"), py::arg("texture"), py::arg("level") = 0)
      .def("framebuffer_renderbuffer", [](ContextBox& c, softgl::Enum target, softgl::Enum attachment, softgl::Enum rb_target, std::uint32_t rb) {
             Call(c, "framebuffer_renderbuffer", [&](softgl::Context& gl) { gl.FramebufferRenderbuffer(target, attachment, rb_target, rb); });
           })
      .def("check_framebuffer_status", [](ContextBox& c, softgl::Enum target) { return Call(c, "check_framebuffer_status", [&](softgl::Context& gl) { return gl.CheckFramebufferStatus(target); }); })
      .def("draw_buffers", [](ContextBox& c, const std::vector<softgl::Enum>& bufs) {
             Call(c, "draw_buffers", [&](softgl::Context& gl) { gl.DrawBuffers(int(bufs.size()), bufs.data()); });
           })
      .def("read_buffer", [](ContextBox& c, softgl::Enum src) { Call(c, "read_buffer", [&](softgl::Context& gl) { gl.ReadBuffer(src); }); })
      .def("blit_framebuffer", [](ContextBox& c, int sx0, int sy0, int sx1, int sy1, int dx0, int dy0, int dx1, int dy1, softgl::Bitfield mask, softgl::Enum filter) {
             Call(c, "blit_framebuffer", [&](softgl::Context& gl) { gl.BlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter); });
           }, py::call_guard<py::gil_scoped_release>())
      .def("gen_renderbuffer", [](ContextBox& c) { return Call(c, "gen_renderbuffer", [](softgl::Context& gl) { return gl.GenRenderbuffer(); }); })
      .def("delete_renderbuffer", [](ContextBox& c, std::uint32_t id) { Call(c, "delete_renderbuffer", [&](softgl::Context& gl) { gl.DeleteRenderbuffer(id); }); })
      .def("bind_renderbuffer", [](ContextBox& c, softgl::Enum target, std::uint32_t id) { Call(c, "bind_renderbuffer", [&](softgl::Context& gl) { gl.BindRenderbuffer(target, id); }); })
      .def("renderbuffer_storage", [](ContextBox& c, softgl::Enum target, softgl::Enum format, int w, int h) {
             Call(c, "renderbuffer_storage", [&](softgl::Context& gl) { gl.RenderbufferStorage(target, format, w, h); });
           })
      .def("renderbuffer_storage_multisample", [](ContextBox& c, softgl::Enum target, int samples, softgl::Enum format, int w, int h) {
             Call(c, "renderbuffer_storage_multisample", [&](softgl::Context& gl) { gl.RenderbufferStorageMultisample(target, samples, format, w, h); });
           })
      // State
      .def("viewport", [](ContextBox& c, int x, int y, int w, int h) { Call(c, "viewport", [&](softgl::Context& gl) { gl.Viewport(x, y, w, h); }); })
      .def("scissor", [](ContextBox& c, int x, int y, int w, int h) { Call(c, "scissor", [&](softgl::Context& gl) { gl.Scissor(x, y, w, h); }); })
      .def("enable", [](ContextBox& c, softgl::Enum cap) { Call(c, "enable", [&](softgl::Context& gl) { gl.Enable(cap); }); })
      .def("disable", [](ContextBox& c, softgl::Enum cap) { Call(c, "disable", [&](softgl::Context& gl) { gl.Disable(cap); }); })
      .def("is_enabled", [](ContextBox& c, softgl::Enum cap) { return Call(c, "is_enabled", [&](softgl::Context& gl) { return gl.IsEnabled(cap); }); })
      .def("depth_func", [](ContextBox& c, softgl::Enum f) { Call(c, "depth_func", [&](softgl::Context& gl) { gl.DepthFunc(f); }); })
      .def("depth_mask", [](ContextBox& c, bool flag) { Call(c, "depth_mask", [&](softgl::Context& gl) { gl.DepthMask(flag); }); })
      .def("depth_range", [](ContextBox& c, double n, double f) { Call(c, "depth_range", [&](softgl::Context& gl) { gl.DepthRange(n, f); }); })
      .def("cull_face", [](ContextBox& c, softgl::Enum mode) { Call(c, "cull_face", [&](softgl::Context& gl) { gl.CullFace(mode); }); })
      .def("front_face", [](ContextBox& c, softgl::Enum mode) { Call(c, "front_face", [&](softgl::Context& gl) { gl.FrontFace(mode); }); })
      .def("polygon_mode", [](ContextBox& c, softgl::Enum face, softgl::Enum mode) { Call(c, "polygon_mode", [&](softgl::Context& gl) { gl.PolygonMode(face, mode); }); })
      .def("polygon_offset", [](ContextBox& c, float factor, float units) { Call(c, "polygon_offset", [&](softgl::Context& gl) { gl.PolygonOffset(factor, units); }); })
      .def("line_width", [](ContextBox& c, float w) { Call(c, "line_width", [&](softgl::Context& gl) { gl.LineWidth(w); }); })
      .def("point_size", [](ContextBox& c, float s) { Call(c, "point_size", [&](softgl::Context& gl) { gl.PointSize(s); }); })
      .def("blend_func", [](ContextBox& c, softgl::Enum s, softgl::Enum d) { Call(c, "blend_func", [&](softgl::Context& gl) { gl.BlendFunc(s, d); }); })
      .def("blend_func_separate", [](ContextBox& c, softgl::Enum a, softgl::Enum b, softgl::Enum d, softgl::Enum e) {
             Call(c, "blend_func_separate", [&](softgl::Context& gl) { gl.BlendFuncSeparate(a, b, d, e); });
           })
      .def("blend_equation", [](ContextBox& c, softgl::Enum mode) { Call(c, "blend_equation", [&](softgl::Context& gl) { gl.BlendEquation(mode); }); })
      .def("blend_color", [](ContextBox& c, float r, float g, float b, float a) { Call(c, "blend_color", [&](softgl::Context& gl) { gl.BlendColor(r, g, b, a); }); })
      .def("color_mask", [](ContextBox& c, bool r, bool g, bool b, bool a) { Call(c, "color_mask", [&](softgl::Context& gl) { gl.ColorMask(r, g, b, a); }); })
      .def("stencil_func", [](ContextBox& c, softgl::Enum f, int ref, std::uint32_t mask) { Call(c, "stencil_func", [&](softgl::Context& gl) { gl.StencilFunc(f, ref, mask); }); })
      .def("stencil_op", [](ContextBox& c, softgl::Enum a, softgl::Enum b, softgl::Enum d) { Call(c, "stencil_op", [&](softgl::Context& gl) { gl.StencilOp(a, b, d); }); })
      .def("stencil_mask", [](ContextBox& c, std::uint32_t mask) { Call(c, "stencil_mask", [&](softgl::Context& gl) { gl.StencilMask(mask); }); })
      .def("clear_color", [](ContextBox& c, float r, float g, float b, float a) { Call(c, "clear_color", [&](softgl::Context& gl) { gl.ClearColor(r, g, b, a); }); })
      .def("clear_depth", [](ContextBox& c, double d) { Call(c, "clear_depth", [&](softgl::Context& gl) { gl.ClearDepth(d); }); })
      .def("clear_stencil", [](ContextBox& c, int s) { Call(c, "clear_stencil", [&](softgl::Context& gl) { gl.ClearStencil(s); }); })
      .def("clear", [](ContextBox& c, softgl::Bitfield mask) { Call(c, "clear", [&](softgl::Context& gl) { gl.Clear(mask); }); })
      // (No pixel_store: tex_image_2d and read_pixels lay the pixels out as their arrays are, rows packed tight; a
      // row length or skip set from Python would make them read or write past the array.)
      // Draws (recorded; rendered by finish, a read back or a query)
      .def("draw_arrays", [](ContextBox& c, softgl::Enum mode, int first, int count) { Call(c, "draw_arrays", [&](softgl::Context& gl) { gl.DrawArrays(mode, first, count); }); },
           py::arg("mode"), py::arg("first"), py::arg("count"))
      .def("draw_element", [](ContextBox& c, softgl::Enum mode, int count, softgl::Enum type, std::size_t offset) {
             Call(c, "draw_element", [&](softgl::Context& gl) { gl.DrawElement(mode, count, type, offset); });
           }, py::arg("mode"), py::arg("count"), py::arg("type"), py::arg("offset") = 0,
           "DrawElement (glDrawElements): `count` indices of `type` from byte `offset` of the bound element array buffer.")
      .def("draw_arrays_instanced", [](ContextBox& c, softgl::Enum mode, int first, int count, int instances) {
             Call(c, "draw_arrays_instanced", [&](softgl::Context& gl) { gl.DrawArraysInstanced(mode, first, count, instances); });
           })
      .def("draw_elements_instanced", [](ContextBox& c, softgl::Enum mode, int count, softgl::Enum type, std::size_t offset, int instances) {
             Call(c, "draw_elements_instanced", [&](softgl::Context& gl) { gl.DrawElementsInstanced(mode, count, type, offset, instances); });
           })
      // Reading back
      .def("read_pixels", [](ContextBox& c, int x, int y, py::object width_obj, py::object height_obj, softgl::Enum format, softgl::Enum type, bool flip) {
             const int width = width_obj.is_none() ? c.gl.Width() - x : width_obj.cast<int>();
             const int height = height_obj.is_none() ? c.gl.Height() - y : height_obj.cast<int>();
             if (width < 0 || height < 0) throw py::value_error("width, height: must be >= 0");
             int channels = 0;
             switch (format) {
               case softgl::RED: case softgl::GREEN: case softgl::BLUE: case softgl::RED_INTEGER: case softgl::DEPTH_COMPONENT: case softgl::STENCIL_INDEX: channels = 1; break;
               case softgl::RG: case softgl::RG_INTEGER: channels = 2; break;
               case softgl::RGB: case softgl::BGR: case softgl::RGB_INTEGER: channels = 3; break;
               case softgl::RGBA: case softgl::BGRA: case softgl::RGBA_INTEGER: channels = 4; break;
               default: throw py::value_error("format: read_pixels takes RED, GREEN, BLUE, RG, RGB, BGR, RGBA, BGRA, their _INTEGER forms, DEPTH_COMPONENT or STENCIL_INDEX");
             }
             py::dtype dtype;
             switch (type) {
               case softgl::UNSIGNED_BYTE: dtype = py::dtype::of<std::uint8_t>(); break;
               case softgl::BYTE: dtype = py::dtype::of<std::int8_t>(); break;
               case softgl::UNSIGNED_SHORT: dtype = py::dtype::of<std::uint16_t>(); break;
               case softgl::SHORT: dtype = py::dtype::of<std::int16_t>(); break;
               case softgl::UNSIGNED_INT: dtype = py::dtype::of<std::uint32_t>(); break;
               case softgl::INT: dtype = py::dtype::of<std::int32_t>(); break;
               case softgl::FLOAT: dtype = py::dtype::of<float>(); break;
               case softgl::HALF_FLOAT: dtype = py::dtype("float16"); break;
               default: throw py::value_error("type: read_pixels takes UNSIGNED_BYTE, BYTE, UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT, HALF_FLOAT or FLOAT");
             }
             std::vector<py::ssize_t> shape{height, width};
             if (channels > 1) shape.push_back(channels);
             py::array out(dtype, shape);
             const std::size_t row = std::size_t(width) * std::size_t(channels) * std::size_t(dtype.itemsize());
             std::vector<std::uint8_t> rows(flip ? row * std::size_t(height) : 0);
             void* target = flip ? static_cast<void*>(rows.data()) : out.mutable_data();
             {
               py::gil_scoped_release release;
               Call(c, "read_pixels", [&](softgl::Context& gl) {
                 gl.PixelStore(softgl::PACK_ALIGNMENT, 1);
                 gl.ReadPixels(x, y, width, height, format, type, target);
               });
               if (flip)
                 for (int r = 0; r < height; ++r)
                   std::memcpy(static_cast<std::uint8_t*>(out.mutable_data()) + std::size_t(r) * row, rows.data() + std::size_t(height - 1 - r) * row, row);
             }
             return out;
           },
           py::arg("x") = 0, py::arg("y") = 0, py::arg("width") = py::none(), py::arg("height") = py::none(),
           py::arg("format") = softgl::RGBA, py::arg("type") = softgl::UNSIGNED_BYTE, py::arg("flip") = true,
           "ReadPixels into a new array of shape (height, width[, channels]) and the type's dtype. flip=True (the "
           "default) gives the top row first, as images are held; flip=False OpenGL's order, bottom row first.")
      .def("get_integer", [](ContextBox& c, softgl::Enum pname, int count) {
             if (count < 1 || count > 16) throw py::value_error("count: 1 to 16 values");
             std::vector<int> v(std::size_t(count), 0);
             Call(c, "get_integer", [&](softgl::Context& gl) { gl.GetIntegerv(pname, v.data()); });
             return count == 1 ? py::object(py::int_(v[0])) : py::object(py::cast(v));
           }, py::arg("pname"), py::arg("count") = 1, "GetIntegerv: one value, or a list of `count`.")
      .def("get_string", [](ContextBox& c, softgl::Enum name) {
             return Call(c, "get_string", [&](softgl::Context& gl) { const char* s = gl.GetString(name); return std::string(s ? s : ""); });
           });

  // ---- Models and environments (softgl::model) ----
  py::class_<softgl::Model>(m, "Model", "A model file (anything assimp reads) loaded into a context.")
      .def_static("load", [](ContextBox& c, const std::string& path) {
             CheckFile(path, "path");
             auto model = std::make_unique<softgl::Model>();
             std::string error;
             bool ok;
             {
               py::gil_scoped_release release;
               std::lock_guard<std::mutex> lock(c.mutex);
               ok = model->Load(c.gl, path, &error);
               c.gl.GetError();
             }
             if (!ok) throw py::value_error("path: " + error);
             return model;
           }, py::arg("context"), py::arg("path"), py::keep_alive<0, 1>())
      .def("draw", [](const softgl::Model& model, ContextBox& c, py::object shader, const py::handle& view_proj, const py::handle& world) {
             softgl::MaterialProgram* program = nullptr;
             if (py::isinstance<softgl::UnlitShader>(shader)) program = &shader.cast<softgl::UnlitShader&>();
             else if (py::isinstance<softgl::PhongShader>(shader)) program = &shader.cast<softgl::PhongShader&>();
             else if (py::isinstance<softgl::PbrShader>(shader)) program = &shader.cast<softgl::PbrShader&>();
             else throw py::type_error("shader: an UnlitShader, PhongShader or PbrShader is needed");
             const glm::mat4 vp = Matrix4(view_proj, "view_proj");
             const glm::mat4 w = world.is_none() ? glm::mat4(1.0f) : Matrix4(world, "world");
             Call(c, "Model.draw", [&](softgl::Context& gl) { model.Draw(gl, *program, vp, w); });
             // The context keeps a pointer to the shader: it must live while its draws are pending.
             c.gl.Finish();
           }, py::arg("context"), py::arg("shader"), py::arg("view_proj"), py::arg("world") = py::none(),
           "Draws every node with the shader (its uniforms set per mesh), then renders.")
      .def_property_readonly("bounds", [](const softgl::Model& model) {
             return py::make_tuple(std::vector<float>{model.bounds.min.x, model.bounds.min.y, model.bounds.min.z},
                                   std::vector<float>{model.bounds.max.x, model.bounds.max.y, model.bounds.max.z});
           }, "(min, max) of the vertices drawn, node transforms applied")
      .def_readonly("triangles", &softgl::Model::triangles_drawn)
      .def_readonly("textures_loaded", &softgl::Model::textures_loaded)
      .def_readonly("warnings", &softgl::Model::warnings)
      .def_property_readonly("mesh_count", [](const softgl::Model& model) { return model.meshes.size(); });
  m.def("make_studio_environment", [](ContextBox& c, int size) {
          return Call(c, "make_studio_environment", [&](softgl::Context& gl) { return softgl::MakeStudioEnvironment(gl, size); });
        }, py::arg("context"), py::arg("size") = 64,
        "A soft studio cube map bound to unit UNIT_ENVIRONMENT; returns its level count (PbrShader.environment_levels).");
  m.def("make_shadow_map", [](ContextBox& c, int size) {
          if (size < 1 || size > softgl::kMaxFramebufferSize) throw py::value_error("size: must be 1 to " + std::to_string(softgl::kMaxFramebufferSize));
          const softgl::ShadowMap map = Call(c, "make_shadow_map", [&](softgl::Context& gl) { return softgl::MakeShadowMap(gl, size); });
          return py::make_tuple(map.texture, map.framebuffer);
        }, py::arg("context"), py::arg("size"),
        "A size x size depth texture compared with LEQUAL and a framebuffer that draws into it, both left bound: "
        "returns (texture, framebuffer). Bind the texture to unit UNIT_SHADOW for the shaders' `shadows`.");
  m.def("load_environment", [](ContextBox& c, const std::string& path, int size) {
          CheckFile(path, "path");
          std::string error;
          const float levels = Call(c, "load_environment", [&](softgl::Context& gl) { return softgl::LoadEnvironment(gl, path, size, &error); });
          if (levels == 0.0f) throw py::value_error("path: " + error);
          return levels;
        }, py::arg("context"), py::arg("path"), py::arg("size") = 128,
        "An equirectangular HDR image as the PBR environment (set environment_levels to the result and environment_hdr).");

  m.def("write_png", [](const std::string& path, const py::handle& image) {
          int channels = 0;
          const py::array a = ImageArray(image, "image", channels);
          softgl::Image img;
          img.height = int(a.shape(0));
          img.width = int(a.shape(1));
          img.rgba.resize(std::size_t(img.width) * std::size_t(img.height) * 4);
          const auto* p = static_cast<const std::uint8_t*>(a.data());
          for (std::size_t i = 0; i < std::size_t(img.width) * std::size_t(img.height); ++i) {
            const std::uint8_t* s = p + i * std::size_t(channels);
            img.rgba[4 * i] = s[0];
            img.rgba[4 * i + 1] = channels >= 3 ? s[1] : s[0];
            img.rgba[4 * i + 2] = channels >= 3 ? s[2] : s[0];
            img.rgba[4 * i + 3] = channels == 4 ? s[3] : channels == 2 ? s[1] : 255;
          }
          bool ok;
          {
            py::gil_scoped_release release;
            ok = softgl::WritePng(path, img);
          }
          if (!ok) {
            PyErr_SetString(PyExc_OSError, ("path: cannot write " + path).c_str());
            throw py::error_already_set();
          }
        }, py::arg("path"), py::arg("image"),
        "Writes a uint8 image (H, W) or (H, W, C), C 1 to 4, top row first, to a PNG file.");

  // ---- The high-level renderer ----
  py::class_<Renderer>(m, "Renderer", "Meshes and models in, numpy images out: colour, depth, normals and ids.")
      .def(py::init<int, int, int, const std::string&, int>(), py::arg("width"), py::arg("height"), py::arg("msaa") = 4,
           py::arg("shader") = "phong", py::arg("threads") = 0)
      .def_property_readonly("width", &Renderer::Width)
      .def_property_readonly("height", &Renderer::Height)
      .def_property_readonly("object_count", &Renderer::ObjectCount)
      .def("add_mesh", [](Renderer& r, const py::handle& positions, const py::handle& faces, const py::handle& normals,
                           const py::handle& colors, const py::handle& uvs, const py::handle& texture, const py::handle& pose,
                           const py::object& object_id_obj, const py::handle& color, double metallic, double roughness, bool cull_back_faces) {
             const std::int64_t object_id = object_id_obj.is_none() ? -1 : object_id_obj.cast<std::int64_t>();
             MeshData mesh;
             mesh.positions = FloatRows(positions, "positions", 3);
             const std::size_t n = mesh.positions.size() / 3;
             if (n == 0) throw py::value_error("positions: the mesh is empty (0 vertices)");
             // A draw counts its vertices in an int (as OpenGL's GLsizei).
             constexpr std::size_t kMaxCount = std::size_t(std::numeric_limits<int>::max());
             if (n > kMaxCount) throw py::value_error("positions: more than 2**31 - 1 vertices");
             if (!faces.is_none()) {
               mesh.faces = IndexRows(faces, "faces", 3, n);
               if (mesh.faces.empty()) throw py::value_error("faces: the mesh has no triangles (0 faces)");
               if (mesh.faces.size() > kMaxCount) throw py::value_error("faces: more than (2**31 - 1) / 3 faces");
             } else if (n % 3 != 0 || n < 3) {
               throw py::value_error("positions: without faces, the positions are a triangle list: their count (" +
                                     std::to_string(n) + ") must be a multiple of 3");
             }
             auto per_vertex = [&](const char* arg, std::size_t rows) {
               if (rows != n) throw py::value_error(std::string(arg) + ": one row per vertex is needed (" + std::to_string(n) + "), got " + std::to_string(rows));
             };
             if (!normals.is_none()) {
               mesh.normals = FloatRows(normals, "normals", 3);
               per_vertex("normals", mesh.normals.size() / 3);
             }
             if (!colors.is_none()) mesh.colors = ColorRows(colors, n);
             if (!uvs.is_none()) {
               mesh.uvs = FloatRows(uvs, "uvs", 2);
               per_vertex("uvs", mesh.uvs.size() / 2);
             }
             if (!texture.is_none()) {
               if (uvs.is_none()) throw py::value_error("texture: needs uvs");
               int channels = 0;
               const py::array img = ImageArray(texture, "texture", channels);
               mesh.texture_height = int(img.shape(0));
               mesh.texture_width = int(img.shape(1));
               if (mesh.texture_width > 16384 || mesh.texture_height > 16384) throw py::value_error("texture: at most 16384 x 16384");
               mesh.texture.resize(std::size_t(mesh.texture_width) * std::size_t(mesh.texture_height) * 4);
               const auto* p = static_cast<const std::uint8_t*>(img.data());
               for (int y = 0; y < mesh.texture_height; ++y)  // rows bottom first: uv (0, 0) is the image's bottom left
                 for (int x = 0; x < mesh.texture_width; ++x) {
                   const std::uint8_t* s = p + (std::size_t(mesh.texture_height - 1 - y) * std::size_t(mesh.texture_width) + std::size_t(x)) * std::size_t(channels);
                   std::uint8_t* d = &mesh.texture[(std::size_t(y) * std::size_t(mesh.texture_width) + std::size_t(x)) * 4];
                   d[0] = s[0];
                   d[1] = channels >= 3 ? s[1] : s[0];
                   d[2] = channels >= 3 ? s[2] : s[0];
                   d[3] = channels == 4 ? s[3] : channels == 2 ? s[1] : 255;
                 }
             }
             Surface surface;
             const auto c = FloatList(color, "color", 4);
             surface.base_color = glm::vec4(c[0], c[1], c[2], c[3]);
             surface.metallic = Positive(metallic, "metallic", true);
             surface.roughness = Positive(roughness, "roughness", true);
             if (!object_id_obj.is_none() && (object_id < 0 || object_id > 0xFFFFFFFFll))
               throw py::value_error("object_id: must be 0 to 2**32 - 1");
             const glm::mat4 p = pose.is_none() ? glm::mat4(1.0f) : Matrix4(pose, "pose");
             py::gil_scoped_release release;
             return r.AddMesh(mesh, surface, p, object_id, cull_back_faces);
           },
           py::arg("positions"), py::arg("faces") = py::none(), py::arg("normals") = py::none(), py::arg("colors") = py::none(),
           py::arg("uvs") = py::none(), py::arg("texture") = py::none(), py::arg("pose") = py::none(),
           py::arg("object_id") = py::none(), py::arg("color") = std::vector<float>{1.0f, 1.0f, 1.0f, 1.0f},
           py::arg("metallic") = 0.0, py::arg("roughness") = 0.5, py::arg("cull_back_faces") = false,
           "Adds a triangle mesh; returns its handle (1, 2, ...). positions (N, 3) float32/float64; faces (M, 3) of "
           "any integer dtype (None: the positions are a triangle list); normals (N, 3) (None: smooth normals from "
           "the faces); colors (N, 3) or (N, 4), float in [0, 1] or uint8; uvs (N, 2), (0, 0) the texture's bottom "
           "left; texture (H, W[, C]) uint8, top row first, an sRGB colour map; pose 4 x 4 model to world; "
           "object_id the value in the 'ids' image (None: the handle); color the base colour factor (RGBA).")
      .def("add_points", [](Renderer& r, const py::handle& positions, const py::handle& colors, double size,
                             const py::handle& pose, const py::object& object_id_obj, const py::handle& color) {
             return AddShape(r, softgl::POINTS, positions, py::none(), colors, size, pose, object_id_obj, color);
           },
           py::arg("positions"), py::arg("colors") = py::none(), py::arg("size") = 1.0, py::arg("pose") = py::none(),
           py::arg("object_id") = py::none(), py::arg("color") = std::vector<float>{1.0f, 1.0f, 1.0f, 1.0f},
           "Adds a point cloud; returns its handle. positions (N, 3); colors (N, 3) or (N, 4), float or uint8; "
           "each point a square of `size` pixels, unlit (its colour as given), with depth and id like a mesh's "
           "(normals 0).")
      .def("add_lines", [](Renderer& r, const py::handle& positions, const py::handle& segments, const py::handle& colors,
                            double width, const py::handle& pose, const py::object& object_id_obj, const py::handle& color) {
             return AddShape(r, softgl::LINES, positions, segments, colors, width, pose, object_id_obj, color);
           },
           py::arg("positions"), py::arg("segments") = py::none(), py::arg("colors") = py::none(), py::arg("width") = 1.0,
           py::arg("pose") = py::none(), py::arg("object_id") = py::none(),
           py::arg("color") = std::vector<float>{1.0f, 1.0f, 1.0f, 1.0f},
           "Adds line segments; returns the handle. segments (M, 2) of vertex indices (None: the positions in "
           "pairs); `width` pixels wide, unlit.")
      .def("add_model", [](Renderer& r, const std::string& path, const py::handle& pose, const py::object& object_id_obj) {
             CheckFile(path, "path");
             const std::int64_t object_id = object_id_obj.is_none() ? -1 : object_id_obj.cast<std::int64_t>();
             if (!object_id_obj.is_none() && (object_id < 0 || object_id > 0xFFFFFFFFll))
               throw py::value_error("object_id: must be 0 to 2**32 - 1");
             const glm::mat4 p = pose.is_none() ? glm::mat4(1.0f) : Matrix4(pose, "pose");
             try {
               py::gil_scoped_release release;
               return r.AddModel(path, p, object_id);
             } catch (const std::runtime_error& e) {
               throw py::value_error(std::string("path: ") + e.what());
             }
           },
           py::arg("path"), py::arg("pose") = py::none(), py::arg("object_id") = py::none(),
           "Adds a model file (anything assimp reads: glTF, OBJ, PLY, STL, FBX, ...) with its materials and "
           "textures; returns its handle.")
      .def("set_pose", [](Renderer& r, int handle, const py::handle& pose) { r.SetPose(handle, Matrix4(pose, "pose")); },
           py::arg("handle"), py::arg("pose"), "The object's model-to-world transform (4 x 4).")
      .def("remove", &Renderer::Remove, py::arg("handle"))
      .def("bounds", [](const Renderer& r) -> py::object {
             glm::vec3 lo, hi;
             if (!r.Bounds(lo, hi)) return py::none();
             return py::make_tuple(std::vector<float>{lo.x, lo.y, lo.z}, std::vector<float>{hi.x, hi.y, hi.z});
           }, "(min, max) of every object's bounding box with its pose, or None with no object.")
      .def("look_at", [](Renderer& r, const py::handle& eye, const py::handle& target, const py::handle& up, double fov_y, double near, double far) {
             r.LookAt(Vec3(eye, "eye"), Vec3(target, "target"), Vec3(up, "up"), float(fov_y), float(near), float(far));
           }, py::arg("eye"), py::arg("target"), py::arg("up") = std::vector<float>{0.0f, 1.0f, 0.0f}, py::arg("fov_y") = 45.0,
           py::arg("near") = 0.1, py::arg("far") = 100.0,
           "A look-at camera with a vertical field of view in degrees (OpenGL's convention: y up).")
      .def("set_intrinsics", [](Renderer& r, double fx, double fy, double cx, double cy, double near, double far, const py::handle& world_to_camera) {
             const glm::mat4 extrinsics = world_to_camera.is_none() ? glm::mat4(1.0f) : Matrix4(world_to_camera, "world_to_camera");
             r.Intrinsics(float(fx), float(fy), float(cx), float(cy), float(near), float(far), extrinsics);
           }, py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("near") = 0.1, py::arg("far") = 100.0,
           py::arg("world_to_camera") = py::none(),
           "A pinhole camera in OpenCV's convention: u = fx X / Z + cx, v = fy Y / Z + cy for a point (X, Y, Z) in the "
           "camera's frame (x right, y down, z forward; (0, 0) the centre of the top-left pixel); world_to_camera is "
           "the 4 x 4 extrinsic matrix [R | t] (identity when omitted).")
      .def("frame", [](Renderer& r, double azimuth, double elevation, double fov_y) {
             glm::vec3 lo, hi;
             if (!r.Bounds(lo, hi)) throw py::value_error("frame: there is no object to frame");
             softgl::Bounds b;
             b.min = lo;
             b.max = hi;
             if (!(fov_y > 0.0 && fov_y < 180.0)) throw py::value_error("fov_y: must be between 0 and 180 degrees");
             const softgl::Camera cam = softgl::Camera::Frame(b, float(r.Width()) / float(r.Height()), float(azimuth),
                                                              float(elevation), float(fov_y));
             r.LookAt(cam.eye, cam.target, cam.up, cam.fovy_degrees, cam.near_plane, cam.far_plane);
           }, py::arg("azimuth") = 30.0, py::arg("elevation") = 20.0, py::arg("fov_y") = 40.0,
           "A look-at camera orbiting the objects' bounding box (azimuth about +y from +z, elevation above the xz "
           "plane, in degrees) at the distance where it fills the view, near and far fitted around it.")
      .def_property_readonly("view_matrix", [](const Renderer& r) { return ToNumpy(r.View()); })
      .def_property_readonly("projection_matrix", [](const Renderer& r) { return ToNumpy(r.Projection()); })
      .def_property_readonly("eye", [](const Renderer& r) { const glm::vec3 e = r.Eye(); return std::vector<float>{e.x, e.y, e.z}; })
      .def("set_lights", [](Renderer& r, const py::handle& lights, const py::handle& ambient) {
             std::vector<softgl::DirectionalLight> list;
             if (!lights.is_none())
               for (const py::handle item : lights) {
                 const py::tuple t = item.cast<py::tuple>();
                 if (t.size() != 2) throw py::value_error("lights: each light is (direction, color)");
                 list.push_back({Vec3(t[0], "lights: direction"), Vec3(t[1], "lights: color")});
               }
             r.SetLights(list, Vec3(ambient, "ambient"), lights.is_none());
           }, py::arg("lights"), py::arg("ambient") = std::vector<float>{0.08f, 0.08f, 0.08f},
           "Directional lights as (direction towards the light, colour) pairs in world space, up to 4; None: "
           "three-point lighting placed from the camera at each render (the default).")
      .def("set_environment", [](Renderer& r, const std::string& path, double strength) {
             CheckFile(path, "path");
             try {
               r.SetEnvironment(path, Positive(strength, "strength", true));
             } catch (const std::runtime_error& e) {
               throw py::value_error(std::string("path: ") + e.what());
             }
           }, py::arg("path"), py::arg("strength") = 1.0,
           "An equirectangular HDR image (Radiance .hdr) as the PBR shader's light and reflections.")
      .def("set_tone_map", [](Renderer& r, const std::string& name, double exposure) {
             if (!std::isfinite(exposure)) throw py::value_error("exposure: must be finite");
             r.SetToneMap(ToneMapOf(name), float(exposure));
           }, py::arg("tone_map"), py::arg("exposure") = 0.0,
           "'clamp', 'pbr-neutral' or 'aces', after scaling colours by 2**exposure.")
      .def_property("shader", &Renderer::ShaderName, &Renderer::SetShader, "'unlit', 'phong' or 'pbr'")
      .def("set_shadows", [](Renderer& r, bool on, int size, double bias) { r.SetShadows(on, size, float(bias)); },
           py::arg("enabled") = true, py::arg("size") = 2048, py::arg("bias") = 0.002,
           "Shadows of the first light (the key light by default), with the Phong and PBR shaders: a size x size "
           "shadow map fitted around the objects at each render. bias is subtracted from a fragment's depth in the "
           "map, whose [0, 1] spans the objects' bounding sphere (the map is drawn with a polygon offset too; the "
           "default keeps the edges of lit faces from shadowing themselves).")
      .def("set_background", [](Renderer& r, const py::handle& color) {
             const auto c = FloatList(color, "color", 4);
             r.SetBackground(glm::vec4(c[0], c[1], c[2], c[3]));
           }, py::arg("color"), "The clear colour, RGBA in [0, 1].")
      .def("render", [](Renderer& r, bool color, bool depth, bool normals, bool ids, bool alpha, bool hdr) {
             const py::ssize_t h = r.Height(), w = r.Width();
             py::dict out;
             Frame frame;
             frame.alpha = alpha;
             if (color && hdr) {
               py::array a(py::dtype::of<float>(), std::vector<py::ssize_t>{h, w, alpha ? 4 : 3});
               frame.color_hdr = static_cast<float*>(a.mutable_data());
               out["color"] = a;
             } else if (color) {
               py::array a(py::dtype::of<std::uint8_t>(), std::vector<py::ssize_t>{h, w, alpha ? 4 : 3});
               frame.color = static_cast<std::uint8_t*>(a.mutable_data());
               out["color"] = a;
             }
             if (depth) {
               py::array a(py::dtype::of<float>(), std::vector<py::ssize_t>{h, w});
               frame.depth = static_cast<float*>(a.mutable_data());
               out["depth"] = a;
             }
             if (normals) {
               py::array a(py::dtype::of<float>(), std::vector<py::ssize_t>{h, w, 3});
               frame.normals = static_cast<float*>(a.mutable_data());
               out["normals"] = a;
             }
             if (ids) {
               py::array a(py::dtype::of<std::uint32_t>(), std::vector<py::ssize_t>{h, w});
               frame.ids = static_cast<std::uint32_t*>(a.mutable_data());
               out["ids"] = a;
             }
             {
               py::gil_scoped_release release;
               r.Render(frame);
             }
             return out;
           }, py::arg("color") = true, py::arg("depth") = false, py::arg("normals") = false, py::arg("ids") = false,
           py::arg("alpha") = false, py::arg("hdr") = false,
           "Renders the objects: a dict of the arrays asked for, top row first. 'color': uint8 (H, W, 3), or "
           "(H, W, 4) with alpha; with hdr=True float32, the shaders' colours before any tone curve, clamp or sRGB "
           "encoding (scaled by 2**exposure; linear light with the 'pbr' shader), multisampled as the uint8 "
           "colour; 'depth': float32 (H, W), the distance along the optical axis in scene units, 0 "
           "where nothing is drawn; 'normals': float32 (H, W, 3), unit world-space normals facing the camera, 0 "
           "elsewhere; 'ids': uint32 (H, W), each pixel's object_id, 0 where nothing is drawn.");
}

// scenes_models.cpp — a model from a file, framed and lit, with one of the built-in shaders.
#include <cmath>
#include <fstream>

#include <softgl/model.h>
#include <softgl/shaders.h>

#include "scenes.h"

namespace scenes {

softgl::Image ModelView(const std::string& path, const std::string& shader, int width, int height, float azimuth,
                        float elevation, std::string* error, float point_size) {
  softgl::Context::Options options;
  options.samples = 4;  // multisampled: the model's silhouette and creases without staircases
  softgl::Context gl(width, height, options);
  softgl::Model model;
  if (!model.Load(gl, path, error)) return {};
  const float aspect = float(width) / float(height);
  const softgl::Camera cam = softgl::Camera::Frame(model.bounds, aspect, azimuth, elevation);
  const glm::mat4 view_proj = cam.Projection(aspect) * cam.View();
  softgl::PbrShader pbr;
  softgl::PhongShader phong;
  softgl::UnlitShader unlit;
  softgl::MaterialProgram* program = &phong;
  if (shader == "pbr") {
    pbr.environment_levels = softgl::MakeStudioEnvironment(gl, 64);
    program = &pbr;
  } else if (shader == "unlit") {
    program = &unlit;
  }
  pbr.lighting = phong.lighting = unlit.lighting = softgl::Lighting::ThreePoint(cam.eye, cam.target);
  gl.ClearColor(0.16f, 0.17f, 0.2f, 1.0f);
  gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
  gl.Enable(softgl::DEPTH_TEST);
  gl.PointSize(point_size);
  model.Draw(gl, *program, view_proj);
  return gl.ReadPixels();
}

bool WritePointCloudPly(const std::string& path) {
  constexpr int kPoints = 20000;
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex " << kPoints
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  std::uint32_t state = 12345u;  // a fixed sequence: the same file every time
  auto random = [&state] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (int i = 0; i < kPoints; ++i) {
    // Two arms of a logarithmic spiral, scattered more towards the rim, in a thin disc with a bulge.
    const float r = 0.05f + 0.95f * std::pow(random(), 0.7f);
    const float arm = (i % 2) * 3.14159265f;
    const float angle = arm + 2.8f * std::log(r * 20.0f) + 0.5f * (random() - 0.5f) / r * 0.2f;
    const float spread = 0.08f * (random() - 0.5f);
    const float x = r * std::cos(angle) + spread, z = r * std::sin(angle) + spread;
    const float y = (random() - 0.5f) * 0.12f * std::exp(-3.0f * r);
    // Warm yellow at the centre to blue at the rim.
    const float t = std::min(1.0f, r * 1.2f);
    const int red = int(255.0f * (1.0f - 0.6f * t)), green = int(255.0f * (0.85f - 0.35f * t));
    const int blue = int(255.0f * (0.5f + 0.5f * t));
    out << x << ' ' << y << ' ' << z << ' ' << red << ' ' << green << ' ' << blue << '\n';
  }
  return bool(out.flush());
}

bool WriteTorusKnotObj(const std::string& path) {
  constexpr int kSegments = 720, kP = 3, kQ = 7;
  std::ofstream out(path);
  out << "# a (" << kP << ", " << kQ << ") torus knot as one closed polyline\n";
  for (int i = 0; i < kSegments; ++i) {
    const float t = 2.0f * 3.14159265f * float(i) / float(kSegments);
    const float r = 2.0f + std::cos(float(kQ) * t);
    out << "v " << r * std::cos(float(kP) * t) << ' ' << -std::sin(float(kQ) * t) << ' '
        << r * std::sin(float(kP) * t) << '\n';
  }
  out << 'l';
  for (int i = 1; i <= kSegments; ++i) out << ' ' << i;
  out << " 1\n";
  return bool(out.flush());
}

}  // namespace scenes

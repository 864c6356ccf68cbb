// The frame python/bench/overhead.py times through the Python module, drawn through the C++ API: a model framed by
// Camera::Frame, three-point lighting, PhongShader, 4x multisampling, read back as an image. Prints the median
// milliseconds of `frames` frames (after one frame of warm-up).
//
//   softgl_python_frame MODEL WIDTH HEIGHT FRAMES
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: softgl_python_frame MODEL WIDTH HEIGHT FRAMES\n");
    return 2;
  }
  const int width = std::atoi(argv[2]), height = std::atoi(argv[3]), frames = std::max(1, std::atoi(argv[4]));
  softgl::Context::Options options;
  options.samples = 4;
  softgl::Context gl(width, height, options);
  softgl::Model model;
  std::string error;
  if (!model.Load(gl, argv[1], &error)) {
    std::fprintf(stderr, "softgl_python_frame: %s\n", error.c_str());
    return 1;
  }
  const float aspect = float(width) / float(height);
  const softgl::Camera camera = softgl::Camera::Frame(model.bounds, aspect, 30.0f, 20.0f, 40.0f);
  const glm::mat4 view_proj = camera.Projection(aspect) * camera.View();
  softgl::PhongShader shader;
  shader.lighting = softgl::Lighting::ThreePoint(camera.eye, camera.target);
  std::vector<double> ms;
  std::size_t checksum = 0;
  for (int f = 0; f <= frames; ++f) {
    const auto start = std::chrono::steady_clock::now();
    gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl.Enable(softgl::DEPTH_TEST);
    gl.Clear(softgl::COLOR_BUFFER_BIT | softgl::DEPTH_BUFFER_BIT);
    model.Draw(gl, shader, view_proj);
    const softgl::Image image = gl.ReadPixels();
    checksum += image.rgba[image.rgba.size() / 2];
    if (f > 0) ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%.3f\n", ms[ms.size() / 2]);
  return checksum == std::size_t(-1) ? 1 : 0;
}

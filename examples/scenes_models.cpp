// scenes_models.cpp — a model from a file, framed and lit, with one of the built-in shaders.
#include <softgl/model.h>
#include <softgl/shaders.h>

#include "scenes.h"

namespace scenes {

softgl::Image ModelView(const std::string& path, const std::string& shader, int width, int height, float azimuth,
                        float elevation, std::string* error) {
  softgl::Context gl(width, height);
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
  model.Draw(gl, *program, view_proj);
  return gl.ReadPixels();
}

}  // namespace scenes

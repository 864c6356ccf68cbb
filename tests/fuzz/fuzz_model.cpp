// fuzz_model — model loading from random bytes: the bytes are written to a file with an extension chosen by the
// first byte (OBJ, PLY, STL, glTF, GLB, ...), loaded through assimp into softgl within time and memory limits, and
// drawn when they load.
#include <unistd.h>

#include <cstdio>
#include <string>

#include <softgl/model.h>
#include <softgl/shaders.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".obj", ".ply", ".stl", ".gltf", ".glb", ".off", ".dae", ".3ds"};
  const std::string path = "/tmp/softgl_fuzz_model_" + std::to_string(getpid()) + kExtensions[data[0] % 8];
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  } else {
    return 0;
  }
  softgl::Context gl(16, 16);
  softgl::Model model;
  std::string error;
  // Bounded, as softgl-render imports: an importer that spins or allocates without end on a mutated file is
  // stopped in its own process (within libFuzzer's 20 s per input, the import being done twice).
  softgl::LoadOptions limits;
  limits.timeout_seconds = 5.0;
  limits.memory_budget = std::size_t(2048) << 20;
  if (model.Load(gl, path, limits, &error)) {
    softgl::PhongShader shader;
    const softgl::Camera cam = softgl::Camera::Frame(model.bounds, 1.0f);
    model.Draw(gl, shader, cam.Projection(1.0f) * cam.View());
  }
  std::remove(path.c_str());
  return 0;
}

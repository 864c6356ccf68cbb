// environment.cpp — the studio environment cube map for image-based ambient light.
#include <cmath>
#include <vector>

#include <softgl/shaders.h>

namespace softgl {

float MakeStudioEnvironment(Context& gl, int size) {
  size = std::max(1, std::min(size, 1024));
  const std::uint32_t tex = gl.GenTexture();
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitEnvironment));
  gl.BindTexture(TEXTURE_CUBE_MAP, tex);
  std::vector<float> texels(std::size_t(size) * std::size_t(size) * 4);
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const float sc = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f, tc = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
        // The direction through this texel (OpenGL's face orientations).
        const glm::vec3 dirs[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
        const glm::vec3 d = glm::normalize(dirs[face]);
        const float up = d.y * 0.5f + 0.5f;
        glm::vec3 c = glm::mix(glm::vec3(0.18f, 0.17f, 0.16f), glm::vec3(0.95f, 0.95f, 1.0f), std::pow(up, 1.5f));
        // Two soft boxes, as in a photo studio.
        const glm::vec3 box1 = glm::normalize(glm::vec3(0.7f, 0.6f, 0.4f)), box2 = glm::normalize(glm::vec3(-0.8f, 0.4f, -0.3f));
        c += glm::vec3(std::pow(std::max(glm::dot(d, box1), 0.0f), 24.0f) * 0.8f);
        c += glm::vec3(std::pow(std::max(glm::dot(d, box2), 0.0f), 24.0f) * 0.4f);
        float* p = &texels[(std::size_t(j) * std::size_t(size) + std::size_t(i)) * 4];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = 1.0f;
      }
    gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(face), 0, RGBA8, size, size, 0, RGBA, FLOAT, texels.data());
  }
  gl.GenerateMipmap(TEXTURE_CUBE_MAP);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_S, CLAMP_TO_EDGE);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_T, CLAMP_TO_EDGE);
  gl.ActiveTexture(TEXTURE0);
  int levels = 1;
  for (int s = size; s > 1; s >>= 1) ++levels;
  return float(levels);
}

}  // namespace softgl

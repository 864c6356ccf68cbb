// environment.cpp — environment cube maps for image-based light: the studio one, and one from an HDR image.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <softgl/shaders.h>

namespace softgl {

namespace {

// The direction through texel (i, j) of a size x size cube face (OpenGL's face orientations).
glm::vec3 CubeDirection(int face, int i, int j, int size) {
  const float sc = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f, tc = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
  const glm::vec3 dirs[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
  return glm::normalize(dirs[face]);
}

// An equirectangular image of linear RGB, rows from the top (+y) down, longitude 0 at -z.
struct Panorama {
  int width = 0, height = 0;
  std::vector<glm::vec3> texels;

  glm::vec3 At(int x, int y) const {
    x = ((x % width) + width) % width;
    y = std::clamp(y, 0, height - 1);
    return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
  // Bilinear, wrapping around in longitude.
  glm::vec3 Sample(const glm::vec3& d) const {
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * 3.14159265f);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / 3.14159265f;
    const float x = u * float(width) - 0.5f, y = v * float(height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    return glm::mix(glm::mix(At(x0, y0), At(x0 + 1, y0), fx), glm::mix(At(x0, y0 + 1), At(x0 + 1, y0 + 1), fx), fy);
  }
  // Averages of factor x factor blocks.
  Panorama Shrunk(int factor) const {
    Panorama out;
    out.width = std::max(1, width / factor);
    out.height = std::max(1, height / factor);
    out.texels.assign(std::size_t(out.width) * std::size_t(out.height), glm::vec3(0.0f));
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x) {
        glm::vec3 sum(0.0f);
        int n = 0;
        for (int dy = 0; dy < factor && y * factor + dy < height; ++dy)
          for (int dx = 0; dx < factor && x * factor + dx < width; ++dx, ++n) sum += At(x * factor + dx, y * factor + dy);
        out.texels[std::size_t(y) * std::size_t(out.width) + std::size_t(x)] = sum / float(std::max(n, 1));
      }
    return out;
  }
};

// Uploads one cube map (bound to TEXTURE_CUBE_MAP) face by face from `texel(face, i, j)` (RGB) in the internal
// format `format`, edges clamped.
template <class Texel>
void UploadCube(Context& gl, int size, Enum format, Texel texel) {
  std::vector<float> data(std::size_t(size) * std::size_t(size) * 4);
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const glm::vec3 c = texel(face, i, j);
        float* p = &data[(std::size_t(j) * std::size_t(size) + std::size_t(i)) * 4];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = 1.0f;
      }
    gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(face), 0, format, size, size, 0, RGBA, FLOAT, data.data());
  }
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_S, CLAMP_TO_EDGE);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_WRAP_T, CLAMP_TO_EDGE);
}

// Mip levels of a size x size texture, down to 1 x 1.
float LevelCount(int size) {
  int levels = 1;
  for (int s = size; s > 1; s >>= 1) ++levels;
  return float(levels);
}

}  // namespace

float LoadEnvironment(Context& gl, const std::string& path, int size, std::string* error) {
  size = std::clamp(size, 1, 1024);
  // The image through a 2D texture (softgl's image loading), read back as floats.
  const std::uint32_t image = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, image);
  Panorama pano;
  if (!gl.TexImage2DFromFile(TEXTURE_2D, path, false, error)) {
    gl.DeleteTexture(image);
    return 0.0f;
  }
  int w = 0, h = 0;
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_WIDTH, &w);
  gl.GetTexLevelParameteriv(TEXTURE_2D, 0, TEXTURE_HEIGHT, &h);
  std::vector<float> rgba(std::size_t(w) * std::size_t(h) * 4);
  gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, rgba.data());
  gl.DeleteTexture(image);
  pano.width = w;
  pano.height = h;
  pano.texels.resize(std::size_t(w) * std::size_t(h));
  for (std::size_t i = 0; i < pano.texels.size(); ++i) {
    const glm::vec3 c(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]);
    const bool finite = std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
    pano.texels[i] = finite ? glm::max(c, 0.0f) : glm::vec3(0.0f);  // no NaN or infinite light
  }

  // The radiance cube map: each texel looks its direction up in the panorama (shrunk first so that a texel
  // covers about one panorama texel), then box-filtered levels.
  const Panorama source = pano.Shrunk(std::max(1, w / (4 * size)));
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitEnvironment));
  gl.BindTexture(TEXTURE_CUBE_MAP, gl.GenTexture());
  UploadCube(gl, size, RGBA32F, [&](int face, int i, int j) { return source.Sample(CubeDirection(face, i, j, size)); });
  gl.GenerateMipmap(TEXTURE_CUBE_MAP);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);

  // Irradiance: E(n) = 1/pi * integral of L(w) max(n.w, 0) dw, summed over a 64 x 32 panorama (each texel's solid
  // angle (2 pi / W)(pi / H) sin(polar angle)).
  const Panorama coarse = pano.Shrunk(std::max(1, w / 64));
  std::vector<std::pair<glm::vec3, glm::vec3>> samples;  // direction, radiance times solid angle
  for (int y = 0; y < coarse.height; ++y) {
    const float polar = (float(y) + 0.5f) / float(coarse.height) * 3.14159265f;
    const float solid = (2.0f * 3.14159265f / float(coarse.width)) * (3.14159265f / float(coarse.height)) * std::sin(polar);
    for (int x = 0; x < coarse.width; ++x) {
      const float azimuth = ((float(x) + 0.5f) / float(coarse.width) - 0.5f) * 2.0f * 3.14159265f;
      const glm::vec3 d(std::sin(polar) * std::sin(azimuth), std::cos(polar), -std::sin(polar) * std::cos(azimuth));
      samples.push_back({d, coarse.At(x, y) * solid});
    }
  }
  constexpr int kIrradianceSize = 16;
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitIrradiance));
  gl.BindTexture(TEXTURE_CUBE_MAP, gl.GenTexture());
  UploadCube(gl, kIrradianceSize, RGBA32F, [&](int face, int i, int j) {
    const glm::vec3 n = CubeDirection(face, i, j, kIrradianceSize);
    glm::vec3 sum(0.0f);
    for (const auto& [d, l] : samples) sum += l * std::max(glm::dot(n, d), 0.0f);
    return sum / 3.14159265f;
  });
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR);
  gl.ActiveTexture(TEXTURE0);
  return LevelCount(size);
}

float MakeStudioEnvironment(Context& gl, int size) {
  size = std::max(1, std::min(size, 1024));
  const std::uint32_t tex = gl.GenTexture();
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitEnvironment));
  gl.BindTexture(TEXTURE_CUBE_MAP, tex);
  UploadCube(gl, size, RGBA8, [size](int face, int i, int j) {
    const glm::vec3 d = CubeDirection(face, i, j, size);
    const float up = d.y * 0.5f + 0.5f;
    glm::vec3 c = glm::mix(glm::vec3(0.18f, 0.17f, 0.16f), glm::vec3(0.95f, 0.95f, 1.0f), std::pow(up, 1.5f));
    // Two soft boxes, as in a photo studio.
    const glm::vec3 box1 = glm::normalize(glm::vec3(0.7f, 0.6f, 0.4f)), box2 = glm::normalize(glm::vec3(-0.8f, 0.4f, -0.3f));
    c += glm::vec3(std::pow(std::max(glm::dot(d, box1), 0.0f), 24.0f) * 0.8f);
    c += glm::vec3(std::pow(std::max(glm::dot(d, box2), 0.0f), 24.0f) * 0.4f);
    return c;
  });
  gl.GenerateMipmap(TEXTURE_CUBE_MAP);
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  gl.ActiveTexture(TEXTURE0);
  return LevelCount(size);
}

}  // namespace softgl

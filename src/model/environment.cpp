// environment.cpp — environment cube maps for image-based light: the studio one, and one from an HDR image.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <softgl/shaders.h>

#include "pixel_store.h"

namespace softgl {

namespace {

// The direction through texel (i, j) of a size x size cube face (OpenGL's face orientations).
glm::vec3 CubeDirection(int face, int i, int j, int size) {
  const float sc = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f, tc = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
  const glm::vec3 dirs[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc}, {sc, -1, -tc}, {sc, -tc, 1}, {-sc, -tc, -1}};
  return glm::normalize(dirs[face]);
}

constexpr float kPi = 3.14159265f;

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
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
    const float x = u * float(width) - 0.5f, y = v * float(height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    return glm::mix(glm::mix(At(x0, y0), At(x0 + 1, y0), fx), glm::mix(At(x0, y0 + 1), At(x0 + 1, y0 + 1), fx), fy);
  }
  // Every texel as a direction, its radiance and its solid angle, (2 pi / W)(pi / H) sin(polar angle), with the
  // index of its row.
  struct Texel {
    glm::vec3 direction, radiance;
    float solid;
    int row;
  };
  std::vector<Texel> Texels() const {
    std::vector<Texel> out;
    out.reserve(texels.size());
    for (int y = 0; y < height; ++y) {
      const float polar = (float(y) + 0.5f) / float(height) * kPi;
      const float solid = (2.0f * kPi / float(width)) * (kPi / float(height)) * std::sin(polar);
      for (int x = 0; x < width; ++x) {
        const float azimuth = ((float(x) + 0.5f) / float(width) - 0.5f) * 2.0f * kPi;
        const glm::vec3 d(std::sin(polar) * std::sin(azimuth), std::cos(polar), -std::sin(polar) * std::cos(azimuth));
        out.push_back({d, At(x, y), solid, y});
      }
    }
    return out;
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
void UploadCube(Context& gl, int size, Enum format, Texel texel, int level = 0) {
  std::vector<float> data(std::size_t(size) * std::size_t(size) * 4);
  const model_detail::DefaultPixelStore tight(gl);  // data's rows as they are
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
    gl.TexImage2D(TEXTURE_CUBE_MAP_POSITIVE_X + Enum(face), level, format, size, size, 0, RGBA, FLOAT, data.data());
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
  {
    const model_detail::DefaultPixelStore tight(gl);  // rgba's rows as they are
    gl.GetTexImage(TEXTURE_2D, 0, RGBA, FLOAT, rgba.data());
  }
  gl.DeleteTexture(image);
  pano.width = w;
  pano.height = h;
  pano.texels.resize(std::size_t(w) * std::size_t(h));
  for (std::size_t i = 0; i < pano.texels.size(); ++i) {
    const glm::vec3 c(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]);
    const bool finite = std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
    pano.texels[i] = finite ? glm::max(c, 0.0f) : glm::vec3(0.0f);  // no NaN or infinite light
  }

  // The radiance cube map. Level 0 looks each texel's direction up in the panorama (shrunk first so that a
  // texel covers about one panorama texel). Level L is prefiltered for roughness L / (levels - 1), the level
  // PbrShader reads for that roughness: with the view along the normal (the split-sum approximation), each texel
  // is the GGX-weighted mean of the panorama around its direction n, weight D(h) max(n.w, 0) dw for a direction w
  // with h = normalize(n + w), over a panorama of about twice the level's resolution. Only rows within the lobe's
  // angle (where D falls below 1/1000 of its peak) are summed.
  const int last = int(LevelCount(size)) - 1;
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitEnvironment));
  gl.BindTexture(TEXTURE_CUBE_MAP, gl.GenTexture());
  const Panorama source = pano.Shrunk(std::max(1, w / (4 * size)));
  UploadCube(gl, size, RGBA32F, [&](int face, int i, int j) { return source.Sample(CubeDirection(face, i, j, size)); });
  for (int level = 1; level <= last; ++level) {
    const int s = std::max(1, size >> level);
    const Panorama lower = pano.Shrunk(std::max(1, w / std::max(32, 4 * s)));
    const std::vector<Panorama::Texel> samples = lower.Texels();
    const float roughness = float(level) / float(last), a = roughness * roughness, a2 = std::max(a * a, 1e-8f);
    // tan of the half-vector angle where D(h) is 1/1000 of D(n): a sqrt(sqrt(1000) - 1); the lobe's angle around
    // n is twice that.
    const float lobe = std::min(kPi, 2.0f * std::atan(a * std::sqrt(std::sqrt(1000.0f) - 1.0f)));
    const float cos_lobe = std::cos(std::min(lobe, kPi / 2.0f)), row_angle = kPi / float(lower.height);
    UploadCube(gl, s, RGBA32F, [&](int face, int i, int j) {
      const glm::vec3 n = CubeDirection(face, i, j, s);
      const float polar = std::acos(std::clamp(n.y, -1.0f, 1.0f));
      const int row0 = std::max(0, int((polar - lobe) / row_angle) - 1);
      const int row1 = std::min(lower.height - 1, int((polar + lobe) / row_angle) + 1);
      glm::vec3 sum(0.0f);
      float weight = 0.0f;
      for (auto it = samples.begin() + std::ptrdiff_t(row0) * lower.width;
           it != samples.end() && it->row <= row1; ++it) {
        const float ndl = glm::dot(n, it->direction);
        if (ndl < cos_lobe) continue;
        const glm::vec3 h = glm::normalize(n + it->direction);
        const float ndh = glm::dot(n, h), d = ndh * ndh * (a2 - 1.0f) + 1.0f;
        const float wgt = a2 / (d * d) * ndl * it->solid;  // D(h) up to its constant factor
        sum += it->radiance * wgt;
        weight += wgt;
      }
      return weight > 0.0f ? sum / weight : source.Sample(n);
    }, level);
  }
  gl.TexParameteri(TEXTURE_CUBE_MAP, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);

  // Irradiance: E(n) = 1/pi * integral of L(w) max(n.w, 0) dw, summed over a 64 x 32 panorama.
  const std::vector<Panorama::Texel> coarse = pano.Shrunk(std::max(1, w / 64)).Texels();
  constexpr int kIrradianceSize = 16;
  gl.ActiveTexture(TEXTURE0 + Enum(kUnitIrradiance));
  gl.BindTexture(TEXTURE_CUBE_MAP, gl.GenTexture());
  UploadCube(gl, kIrradianceSize, RGBA32F, [&](int face, int i, int j) {
    const glm::vec3 n = CubeDirection(face, i, j, kIrradianceSize);
    glm::vec3 sum(0.0f);
    for (const Panorama::Texel& sample : coarse)
      sum += sample.radiance * (sample.solid * std::max(glm::dot(n, sample.direction), 0.0f));
    return sum / kPi;
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

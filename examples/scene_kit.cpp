// scene_kit.cpp — meshes and helpers for the example scenes.
#include "scene_kit.h"

#include <algorithm>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

namespace scenes::kit {

Mesh MakeCube() {
  Mesh m;
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::uint8_t colors[6][4] = {{230, 80, 60, 255},  {60, 170, 230, 255}, {240, 200, 60, 255},
                                     {120, 200, 90, 255}, {200, 100, 220, 255}, {250, 150, 50, 255}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 n = normals[f];
    // u, v span the face with cross(u, v) = n, so the corners below run counter-clockwise seen from outside.
    const glm::vec3 u = std::fabs(n.x) > 0.0f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 v = glm::cross(n, u);
    const auto base = std::uint32_t(m.vertices.size());
    const glm::vec3 corners[4] = {n - u - v, n + u - v, n + u + v, n - u + v};
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k)
      m.vertices.push_back({corners[k] * 0.5f, n, {colors[f][0], colors[f][1], colors[f][2], colors[f][3]}, uvs[k]});
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

Mesh MakeTorus(int rings, int sides, float major, float minor) {
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const float a = 2.0f * kPi * float(i) / float(rings);
    for (int j = 0; j <= sides; ++j) {
      const float b = 2.0f * kPi * float(j) / float(sides);
      const glm::vec3 center(std::cos(a) * major, 0.0f, std::sin(a) * major);
      const glm::vec3 n(std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b));
      const auto shade = std::uint8_t(120 + 120 * float(j) / float(sides));
      m.vertices.push_back({center + n * minor, n, {shade, std::uint8_t(90 + i % 2 * 60), 200, 255},
                            {float(i) / float(rings), float(j) / float(sides)}});
    }
  }
  const int row = sides + 1;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const auto a = std::uint32_t(i * row + j), b = std::uint32_t((i + 1) * row + j);
      m.indices.insert(m.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
    }
  return m;
}

std::uint32_t UploadLitMesh(softgl::Context& gl, const Mesh& mesh) {
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer(), ebo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, std::ptrdiff_t(mesh.vertices.size() * sizeof(LitVertex)),
                mesh.vertices.data());
  gl.BindBuffer(softgl::ELEMENT_ARRAY_BUFFER, ebo);
  gl.BufferData(softgl::ELEMENT_ARRAY_BUFFER, std::ptrdiff_t(mesh.indices.size() * sizeof(std::uint32_t)),
                mesh.indices.data());
  gl.VertexAttributePointer(0, 3, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, position));
  gl.VertexAttributePointer(1, 3, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, normal));
  gl.VertexAttributePointer(2, 4, softgl::UNSIGNED_BYTE, true, sizeof(LitVertex), offsetof(LitVertex, color));
  gl.VertexAttributePointer(3, 2, softgl::FLOAT, false, sizeof(LitVertex), offsetof(LitVertex, uv));
  for (std::uint32_t i = 0; i < 4; ++i) gl.EnableVertexAttribArray(i);
  return vao;
}

std::uint32_t MakeScreenTriangle(softgl::Context& gl) {
  static const float kScreenTriangle[] = {-1, -1, 3, -1, -1, 3};
  const std::uint32_t vao = gl.GenVertexArray(), vbo = gl.GenBuffer();
  gl.BindVertexArray(vao);
  gl.BindBuffer(softgl::ARRAY_BUFFER, vbo);
  gl.BufferData(softgl::ARRAY_BUFFER, sizeof kScreenTriangle, kScreenTriangle);
  gl.VertexAttributePointer(0, 2, softgl::FLOAT, false, 0, 0);
  gl.EnableVertexAttribArray(0);
  return vao;
}

glm::mat4 Projection(int width, int height, float fovy_degrees, float near_plane, float far_plane) {
  const float aspect = height > 0 ? float(width) / float(height) : 1.0f;
  return glm::perspective(glm::radians(fovy_degrees), aspect, near_plane, far_plane);
}

Mesh MakeSphere(int slices, int stacks, float radius) {
  Mesh m;
  for (int j = 0; j <= stacks; ++j) {
    const float v = float(j) / float(stacks), phi = kPi * v;
    for (int i = 0; i <= slices; ++i) {
      const float u = float(i) / float(slices), theta = 2.0f * kPi * u;
      const glm::vec3 n(std::sin(phi) * std::cos(theta), -std::cos(phi), std::sin(phi) * std::sin(theta));
      m.vertices.push_back({n * radius, n, {220, 220, 220, 255}, {u, v}});
    }
  }
  const int row = slices + 1;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto a = std::uint32_t(j * row + i), b = std::uint32_t((j + 1) * row + i);
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  return m;
}

Mesh MakeQuad(float half, const std::uint8_t color[4]) {
  Mesh m;
  const glm::vec3 corners[4] = {{-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half}};
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k)
    m.vertices.push_back({corners[k], {0, 1, 0}, {color[0], color[1], color[2], color[3]}, uvs[k]});
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// ---- Compressed images ----------------------------------------------------------------------------------------

namespace {

// An alpha or RGTC block of 16 values (0..255, or -128..127 for the signed formats).
void EncodeValues(const int v[16], std::vector<std::uint8_t>& out) {
  const int hi = *std::max_element(v, v + 16), lo = *std::min_element(v, v + 16);
  out.push_back(std::uint8_t(hi));
  out.push_back(std::uint8_t(lo));
  std::uint64_t bits = 0;
  for (int t = 0; t < 16; ++t) {
    int best = 0, best_d = 1 << 30;
    for (int i = 0; i < 8; ++i) {
      const int value = i == 0 ? hi : i == 1 ? lo : hi > lo ? ((8 - i) * hi + (i - 1) * lo) / 7 : hi;
      if (std::abs(value - v[t]) < best_d) best = i, best_d = std::abs(value - v[t]);
    }
    bits |= std::uint64_t(best) << (3 * t);
  }
  for (int k = 0; k < 6; ++k) out.push_back(std::uint8_t(bits >> (8 * k)));
}

// An S3TC colour block of the 16 texels' RGB; with `punch`, texels of alpha < 128 become DXT1's transparent black.
void EncodeColours(const std::uint8_t rgba[16][4], bool punch, std::vector<std::uint8_t>& out) {
  int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
  bool any_clear = false;
  for (int t = 0; t < 16; ++t) {
    any_clear |= punch && rgba[t][3] < 128;
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], int(rgba[t][c])), hi[c] = std::max(hi[c], int(rgba[t][c]));
  }
  auto word = [](const int c[3]) { return std::uint16_t((c[0] >> 3) << 11 | (c[1] >> 2) << 5 | (c[2] >> 3)); };
  std::uint16_t w0 = word(hi), w1 = word(lo);
  if (any_clear ? w0 > w1 : w0 < w1) std::swap(w0, w1);  // three colours and black, or four
  auto widen = [](std::uint16_t w, int c) {
    const int r = w >> 11, g = (w >> 5) & 63, b = w & 31;
    return c == 0 ? (r << 3 | r >> 2) : c == 1 ? (g << 2 | g >> 4) : (b << 3 | b >> 2);
  };
  std::uint32_t bits = 0;
  for (int t = 0; t < 16; ++t) {
    int best = 0, best_d = 1 << 30;
    if (any_clear && rgba[t][3] < 128) {
      best = 3;
    } else {
      for (int i = 0; i < (any_clear ? 3 : 4); ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c) {
          const int a = widen(w0, c), b = widen(w1, c);
          const int value = i == 0 ? a : i == 1 ? b : any_clear ? (a + b) / 2 : i == 2 ? (2 * a + b) / 3 : (a + 2 * b) / 3;
          d += (value - rgba[t][c]) * (value - rgba[t][c]);
        }
        if (d < best_d) best = i, best_d = d;
      }
    }
    bits |= std::uint32_t(best) << (2 * t);
  }
  for (int k = 0; k < 2; ++k) out.push_back(std::uint8_t(w0 >> (8 * k)));
  for (int k = 0; k < 2; ++k) out.push_back(std::uint8_t(w1 >> (8 * k)));
  for (int k = 0; k < 4; ++k) out.push_back(std::uint8_t(bits >> (8 * k)));
}

}  // namespace

std::vector<std::uint8_t> EncodeBlocks(const std::uint8_t* rgba, int w, int h, softgl::Enum format) {
  std::vector<std::uint8_t> out;
  for (int by = 0; by < (h + 3) / 4; ++by)
    for (int bx = 0; bx < (w + 3) / 4; ++bx) {
      std::uint8_t t[16][4];
      for (int k = 0; k < 16; ++k) {
        const int x = std::min(bx * 4 + k % 4, w - 1), y = std::min(by * 4 + k / 4, h - 1);
        for (int c = 0; c < 4; ++c) t[k][c] = rgba[std::size_t((y * w + x) * 4 + c)];
      }
      int v[16];
      auto channel = [&](int c, int offset) {
        for (int k = 0; k < 16; ++k) v[k] = t[k][c] - offset;
      };
      const bool is_signed = format == softgl::COMPRESSED_SIGNED_RED_RGTC1 || format == softgl::COMPRESSED_SIGNED_RG_RGTC2;
      switch (format) {
        case softgl::COMPRESSED_RGB_S3TC_DXT1_EXT:
        case softgl::COMPRESSED_SRGB_S3TC_DXT1_EXT: EncodeColours(t, false, out); break;
        case softgl::COMPRESSED_RGBA_S3TC_DXT1_EXT:
        case softgl::COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT: EncodeColours(t, true, out); break;
        case softgl::COMPRESSED_RGBA_S3TC_DXT3_EXT:
        case softgl::COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT:
          for (int k = 0; k < 16; k += 2) out.push_back(std::uint8_t(t[k][3] >> 4 | (t[k + 1][3] >> 4) << 4));
          EncodeColours(t, false, out);
          break;
        case softgl::COMPRESSED_RGBA_S3TC_DXT5_EXT:
        case softgl::COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT:
          channel(3, 0);
          EncodeValues(v, out);
          EncodeColours(t, false, out);
          break;
        default:  // RGTC: red, and green for RGTC2
          channel(0, is_signed ? 128 : 0);
          EncodeValues(v, out);
          if (format == softgl::COMPRESSED_RG_RGTC2 || format == softgl::COMPRESSED_SIGNED_RG_RGTC2) {
            channel(1, is_signed ? 128 : 0);
            EncodeValues(v, out);
          }
          break;
      }
    }
  return out;
}


std::vector<std::uint8_t> MakeDds(softgl::Enum format, int w, int h,
                                  const std::vector<std::vector<std::uint8_t>>& levels) {
  std::vector<std::uint8_t> f(128, 0);
  auto put = [&](std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) f[at + std::size_t(k)] = std::uint8_t(v >> (8 * k));
  };
  const char* four_cc = "DXT5";
  bool alpha = true;
  switch (format) {
    case softgl::COMPRESSED_RGB_S3TC_DXT1_EXT:
    case softgl::COMPRESSED_SRGB_S3TC_DXT1_EXT: four_cc = "DXT1", alpha = false; break;
    case softgl::COMPRESSED_RGBA_S3TC_DXT1_EXT:
    case softgl::COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT: four_cc = "DXT1"; break;
    case softgl::COMPRESSED_RGBA_S3TC_DXT3_EXT:
    case softgl::COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT: four_cc = "DXT3"; break;
    case softgl::COMPRESSED_RED_RGTC1: four_cc = "ATI1", alpha = false; break;
    case softgl::COMPRESSED_SIGNED_RED_RGTC1: four_cc = "BC4S", alpha = false; break;
    case softgl::COMPRESSED_RG_RGTC2: four_cc = "ATI2", alpha = false; break;
    case softgl::COMPRESSED_SIGNED_RG_RGTC2: four_cc = "BC5S", alpha = false; break;
    default: break;
  }
  f[0] = 'D', f[1] = 'D', f[2] = 'S', f[3] = ' ';
  put(4, 124);                // the header's size
  put(8, 0x1007 | 0x20000);   // DDSD_CAPS, HEIGHT, WIDTH, PIXELFORMAT, MIPMAPCOUNT
  put(12, std::uint32_t(h));
  put(16, std::uint32_t(w));
  put(28, std::uint32_t(levels.size()));
  put(76, 32);                         // the pixel format's size
  put(80, 0x4 | (alpha ? 0x1 : 0x0));  // DDPF_FOURCC, DDPF_ALPHAPIXELS
  for (int k = 0; k < 4; ++k) f[std::size_t(84 + k)] = std::uint8_t(four_cc[k]);
  put(108, 0x1000 | (levels.size() > 1 ? 0x400008 : 0));  // DDSCAPS_TEXTURE, MIPMAP, COMPLEX
  for (const std::vector<std::uint8_t>& level : levels) f.insert(f.end(), level.begin(), level.end());
  return f;
}

}  // namespace scenes::kit

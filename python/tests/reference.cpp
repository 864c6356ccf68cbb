// The scene of python/tests/test_context.py's byte comparison, drawn through the C++ API: a textured, lit quad and a
// blended triangle in front of it, with a depth test. Writes the framebuffer's RGBA bytes (ReadPixels: bottom row
// first) to the file named by its argument.
#include <cstdio>
#include <vector>

#include <softgl/model.h>
#include <softgl/shaders.h>
#include <softgl/softgl.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: softgl_python_reference OUT.rgba\n");
    return 2;
  }
  using namespace softgl;
  Context gl(96, 64);
  // x y z, normal, u v, r g b a
  const float vertices[] = {
      -0.9f, -0.8f, -0.5f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f,
      0.8f,  -0.9f, -0.7f, 0.0f, 0.6f, 0.8f, 2.0f, 0.0f, 1.0f, 0.5f, 0.5f, 1.0f,
      0.9f,  0.9f,  -0.9f, 0.6f, 0.0f, 0.8f, 2.0f, 2.0f, 0.5f, 1.0f, 0.5f, 1.0f,
      -0.8f, 0.8f,  -0.6f, 0.0f, 0.0f, 1.0f, 0.0f, 2.0f, 0.5f, 0.5f, 1.0f, 1.0f,
      -0.5f, -0.6f, -0.2f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.2f, 0.1f, 0.5f,
      0.7f,  -0.2f, -0.3f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.1f, 1.0f, 0.2f, 0.5f,
      -0.1f, 0.7f,  -1.2f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.2f, 0.1f, 1.0f, 0.5f,
  };
  const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6};
  const std::uint32_t vao = gl.GenVertexArray();
  gl.BindVertexArray(vao);
  const std::uint32_t vbo = gl.GenBuffer(), ebo = gl.GenBuffer();
  gl.BindBuffer(ARRAY_BUFFER, vbo);
  gl.BufferData(ARRAY_BUFFER, sizeof vertices, vertices);
  gl.BindBuffer(ELEMENT_ARRAY_BUFFER, ebo);
  gl.BufferData(ELEMENT_ARRAY_BUFFER, sizeof indices, indices);
  gl.VertexAttributePointer(kAttribPosition, 3, FLOAT, false, 48, 0);
  gl.VertexAttributePointer(kAttribNormal, 3, FLOAT, false, 48, 12);
  gl.VertexAttributePointer(kAttribUv, 2, FLOAT, false, 48, 24);
  gl.VertexAttributePointer(kAttribColor, 4, FLOAT, false, 48, 32);
  for (std::uint32_t i : {0u, 1u, 2u, 4u}) gl.EnableVertexAttribArray(i);
  gl.VertexAttrib4f(kAttribTangent, 0.0f, 0.0f, 0.0f, 1.0f);

  // An 8 x 4 texture: texel (x, y) = (32 x, 60 y, 255 - 30 x, 255), first row the bottom.
  std::vector<std::uint8_t> texels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x)
      texels.insert(texels.end(), {std::uint8_t(32 * x), std::uint8_t(60 * y), std::uint8_t(255 - 30 * x), 255});
  const std::uint32_t texture = gl.GenTexture();
  gl.ActiveTexture(TEXTURE0);
  gl.BindTexture(TEXTURE_2D, texture);
  gl.PixelStore(UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(TEXTURE_2D, 0, SRGB8_ALPHA8, 8, 4, 0, RGBA, UNSIGNED_BYTE, texels.data());
  gl.GenerateMipmap(TEXTURE_2D);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR);

  // A perspective projection with simple coefficients (the same floats in both programs).
  glm::mat4 view_proj(0.0f);
  view_proj[0][0] = 1.25f;
  view_proj[1][1] = 1.5f;
  view_proj[2][2] = -1.25f;
  view_proj[3][2] = -0.5f;
  view_proj[2][3] = -1.0f;
  view_proj[3][3] = 0.5f;

  PhongShader shader;
  shader.SetTransforms(glm::mat4(1.0f), view_proj);
  shader.material.base_color = glm::vec4(1.0f, 0.9f, 0.8f, 1.0f);
  shader.material.base_color_texture = texture;
  shader.material.shininess = 16.0f;
  shader.lighting.count = 2;
  shader.lighting.lights[0] = {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.9f, 0.85f, 0.8f)};
  shader.lighting.lights[1] = {glm::vec3(0.6f, 0.0f, 0.8f), glm::vec3(0.25f, 0.3f, 0.5f)};
  shader.lighting.ambient = glm::vec3(0.1f, 0.1f, 0.12f);
  shader.lighting.eye = glm::vec3(0.0f, 0.0f, 2.0f);
  gl.UseProgram(shader);

  gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  gl.Enable(DEPTH_TEST);
  gl.Clear(COLOR_BUFFER_BIT | DEPTH_BUFFER_BIT);
  gl.DrawElement(TRIANGLES, 6, UNSIGNED_SHORT, 0);
  UnlitShader unlit;
  unlit.SetTransforms(glm::mat4(1.0f), view_proj);
  unlit.material.base_color = glm::vec4(1.0f, 1.0f, 1.0f, 0.75f);
  unlit.material.alpha_mode = Material::AlphaMode::kBlend;
  gl.UseProgram(unlit);
  gl.Enable(BLEND);
  gl.BlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA);
  gl.DrawElement(TRIANGLES, 3, UNSIGNED_SHORT, 12);

  std::vector<std::uint8_t> pixels(96 * 64 * 4);
  gl.ReadPixels(0, 0, 96, 64, RGBA, UNSIGNED_BYTE, pixels.data());
  if (gl.GetError() != NO_ERROR) return 1;
  std::FILE* f = std::fopen(argv[1], "wb");
  if (!f) return 1;
  const bool ok = std::fwrite(pixels.data(), 1, pixels.size(), f) == pixels.size();
  return std::fclose(f) == 0 && ok ? 0 : 1;
}

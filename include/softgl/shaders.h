// softgl/shaders.h — built-in material shaders for models: unlit, Blinn-Phong with normal mapping, and glTF
// metallic-roughness PBR with image-based ambient light from a cube map. Use them as they are, or subclass.
//
// All read the vertex layout of softgl::Model (ModelAttribute) and the textures Model::Draw binds
// (MaterialUnit); they implement MaterialProgram, so `model.Draw(gl, shader, view_proj)` just works.
#pragma once

#include <softgl/config.h>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <softgl/model.h>
#include <softgl/shader.h>

namespace softgl {

/// A directional light: `direction` points from the surface towards the light.
struct DirectionalLight {
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  glm::vec3 color{1.0f};
};

struct Lighting {
  static constexpr int kMaxLights = 4;
  DirectionalLight lights[kMaxLights];
  int count = 0;
  glm::vec3 ambient{0.08f};
  glm::vec3 eye{0.0f, 0.0f, 3.0f};  // camera position, for specular terms

  /// Key, fill and rim lights placed around the view direction from `eye` to `target`.
  static Lighting ThreePoint(glm::vec3 eye, glm::vec3 target) {
    Lighting l;
    l.eye = eye;
    const glm::vec3 f = glm::normalize(target - eye);
    glm::vec3 r = glm::cross(f, glm::vec3(0.0f, 1.0f, 0.0f));
    r = glm::length(r) > 1e-4f ? glm::normalize(r) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::cross(r, f);
    l.lights[0] = {glm::normalize(-f + 0.8f * r + 0.9f * u), glm::vec3(1.0f, 0.97f, 0.92f) * 1.1f};  // key
    l.lights[1] = {glm::normalize(-f - 1.0f * r + 0.2f * u), glm::vec3(0.75f, 0.8f, 1.0f) * 0.35f};  // fill
    l.lights[2] = {glm::normalize(f + 0.4f * r + 0.9f * u), glm::vec3(1.0f) * 0.6f};                 // rim
    l.count = 3;
    return l;
  }
};

/// The varyings all built-in shaders share.
struct SurfaceVaryings {
  glm::vec3 world_pos;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 tangent;
  glm::vec4 color;
};

/// Common base: transforms, material, lighting, and the surface helpers (base colour with alpha test, normal
/// with normal map). Derived defines Fragment.
template <class Derived>
class SurfaceShader : public Shader<Derived, SurfaceVaryings>, public MaterialProgram {
 public:
  using Varyings = SurfaceVaryings;
  using In = FragmentIn<SurfaceVaryings>;

  glm::mat4 model{1.0f};
  glm::mat4 view_proj{1.0f};
  glm::mat3 normal_matrix{1.0f};
  Material material;
  Lighting lighting = Lighting::ThreePoint(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f));

  const Program& GetProgram() const override { return *this; }
  void SetTransforms(const glm::mat4& m, const glm::mat4& vp) override {
    model = m;
    view_proj = vp;
    normal_matrix = glm::transpose(glm::inverse(glm::mat3(m)));
  }
  void SetMaterial(const Material& m) override { material = m; }

  void Vertex(const VertexIn& in, VertexOut<SurfaceVaryings>& out) const {
    const glm::vec4 world = model * glm::vec4(glm::vec3(in.attrib[kAttribPosition]), 1.0f);
    out.position = view_proj * world;
    out.varyings.world_pos = glm::vec3(world);
    out.varyings.normal = normal_matrix * glm::vec3(in.attrib[kAttribNormal]);
    out.varyings.uv = glm::vec2(in.attrib[kAttribUv]);
    const glm::vec4 t = in.attrib[kAttribTangent];
    out.varyings.tangent = glm::vec4(glm::mat3(model) * glm::vec3(t), t.w);
    out.varyings.color = in.attrib[kAttribColor];
  }

 protected:
  /// Base colour (factor x vertex colour x texture); false when alpha-masked away.
  bool BaseColor(const In& in, glm::vec4& color) const {
    color = material.base_color * in.varyings.color;
    if (material.base_color_texture) color *= in.Texture(kUnitBaseColor, &SurfaceVaryings::uv);
    if (material.alpha_mode == Material::AlphaMode::kMask && color.a < material.alpha_cutoff) return false;
    if (material.alpha_mode == Material::AlphaMode::kOpaque) color.a = 1.0f;
    return true;
  }

  /// The shading normal: interpolated, turned towards the viewer for back faces, perturbed by the normal map.
  glm::vec3 Normal(const In& in) const {
    glm::vec3 n = in.varyings.normal;
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    if (!in.front_facing) n = -n;
    const glm::vec3 t3 = glm::vec3(in.varyings.tangent);
    if (material.normal_texture && glm::dot(t3, t3) > 1e-12f) {
      const glm::vec3 t = glm::normalize(t3 - n * glm::dot(n, t3));
      const glm::vec3 b = glm::cross(n, t) * (in.varyings.tangent.w < 0.0f ? -1.0f : 1.0f);
      const glm::vec3 m = glm::vec3(in.Texture(kUnitNormal, &SurfaceVaryings::uv)) * 2.0f - 1.0f;
      const glm::vec3 p = t * m.x + b * m.y + n * m.z;
      if (glm::dot(p, p) > 1e-12f) n = glm::normalize(p);
    }
    return n;
  }

  glm::vec3 Emissive(const In& in) const {
    glm::vec3 e = material.emissive;
    if (material.emissive_texture) e *= glm::vec3(in.Texture(kUnitEmissive, &SurfaceVaryings::uv));
    return e;
  }
};

/// Base colour only.
struct UnlitShader : SurfaceShader<UnlitShader> {
  bool Fragment(const In& in, FragmentOut& out) const {
    glm::vec4 c;
    if (!BaseColor(in, c)) return false;
    out.color[0] = glm::vec4(glm::vec3(c) + Emissive(in), c.a);
    return true;
  }
};

/// Blinn-Phong per fragment: diffuse from the base colour, specular colour (times the specular map's red),
/// shininess, normal mapping, emissive, ambient (times the occlusion map).
struct PhongShader : SurfaceShader<PhongShader> {
  bool Fragment(const In& in, FragmentOut& out) const {
    glm::vec4 base;
    if (!BaseColor(in, base)) return false;
    const glm::vec3 n = Normal(in);
    const glm::vec3 v = glm::normalize(lighting.eye - in.varyings.world_pos);
    glm::vec3 spec_color = material.specular;
    if (material.specular_texture) spec_color *= in.Texture(kUnitSpecular, &SurfaceVaryings::uv).r;
    float ao = 1.0f;
    if (material.occlusion_texture) ao = in.Texture(kUnitOcclusion, &SurfaceVaryings::uv).r;
    glm::vec3 c = lighting.ambient * glm::vec3(base) * ao;
    for (int i = 0; i < lighting.count; ++i) {
      const DirectionalLight& l = lighting.lights[i];
      const float ndl = glm::dot(n, l.direction);
      if (ndl <= 0.0f) continue;
      const glm::vec3 h = glm::normalize(l.direction + v);
      const float spec = std::pow(std::max(glm::dot(n, h), 0.0f), material.shininess);
      c += l.color * (glm::vec3(base) * ndl + spec_color * spec);
    }
    out.color[0] = glm::vec4(c + Emissive(in), base.a);
    return true;
  }
};

/// glTF 2.0 metallic-roughness: Cook-Torrance with the GGX distribution, Smith-Schlick geometry and Schlick
/// Fresnel; base colour and emissive textures read as sRGB; ambient light from the cube map on kUnitEnvironment
/// when `environment_levels` > 0 (diffuse from its last level, specular from the level matching the roughness),
/// else the flat ambient colour; output gamma-encoded.
struct PbrShader : SurfaceShader<PbrShader> {
  float environment_levels = 0.0f;  // number of mip levels of the environment cube map; 0: none
  float environment_strength = 1.0f;

  static glm::vec3 ToLinear(glm::vec3 c) { return glm::pow(glm::max(c, 0.0f), glm::vec3(2.2f)); }

  bool Fragment(const In& in, FragmentOut& out) const {
    glm::vec4 base = material.base_color * in.varyings.color;
    if (material.base_color_texture) {
      const glm::vec4 t = in.Texture(kUnitBaseColor, &SurfaceVaryings::uv);
      base *= glm::vec4(ToLinear(glm::vec3(t)), t.a);
    }
    if (material.alpha_mode == Material::AlphaMode::kMask && base.a < material.alpha_cutoff) return false;
    if (material.alpha_mode == Material::AlphaMode::kOpaque) base.a = 1.0f;
    float metallic = material.metallic, roughness = material.roughness, ao = 1.0f;
    if (material.metallic_roughness_texture) {
      const glm::vec4 mr = in.Texture(kUnitMetallicRoughness, &SurfaceVaryings::uv);
      roughness *= mr.g;
      metallic *= mr.b;
    }
    if (material.occlusion_texture) ao = in.Texture(kUnitOcclusion, &SurfaceVaryings::uv).r;
    roughness = std::clamp(roughness, 0.04f, 1.0f);
    const glm::vec3 albedo(base);
    const glm::vec3 n = Normal(in);
    const glm::vec3 v = glm::normalize(lighting.eye - in.varyings.world_pos);
    const float ndv = std::max(glm::dot(n, v), 1e-4f);
    const glm::vec3 f0 = glm::mix(glm::vec3(0.04f), albedo, metallic);
    const float a = roughness * roughness, a2 = a * a;
    const float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
    glm::vec3 color(0.0f);
    for (int i = 0; i < lighting.count; ++i) {
      const DirectionalLight& l = lighting.lights[i];
      const float ndl = glm::dot(n, l.direction);
      if (ndl <= 0.0f) continue;
      const glm::vec3 h = glm::normalize(l.direction + v);
      const float ndh = std::max(glm::dot(n, h), 0.0f), vdh = std::max(glm::dot(v, h), 0.0f);
      const float d_denom = ndh * ndh * (a2 - 1.0f) + 1.0f;
      const float d = a2 / (3.14159265f * d_denom * d_denom);
      const float g = (ndl / (ndl * (1.0f - k) + k)) * (ndv / (ndv * (1.0f - k) + k));
      const glm::vec3 f = f0 + (1.0f - f0) * std::pow(1.0f - vdh, 5.0f);
      const glm::vec3 specular = d * g * f / (4.0f * ndl * ndv);
      const glm::vec3 kd = (1.0f - f) * (1.0f - metallic);
      color += (kd * albedo / 3.14159265f + specular) * l.color * ndl * 3.14159265f;
    }
    glm::vec3 ambient = lighting.ambient * albedo;
    if (environment_levels > 0.0f) {
      const float last = environment_levels - 1.0f;
      const glm::vec3 r = glm::reflect(-v, n);
      const glm::vec3 irradiance = ToLinear(glm::vec3(in.textures->SampleCubeLod(kUnitEnvironment, n, last)));
      const glm::vec3 prefiltered = ToLinear(glm::vec3(in.textures->SampleCubeLod(kUnitEnvironment, r, roughness * last)));
      // Analytic approximation of the split-sum environment BRDF.
      const glm::vec4 c0(-1.0f, -0.0275f, -0.572f, 0.022f), c1(1.0f, 0.0425f, 1.04f, -0.04f);
      const glm::vec4 rr = roughness * c0 + c1;
      const float a004 = std::min(rr.x * rr.x, std::exp2(-9.28f * ndv)) * rr.x + rr.y;
      const glm::vec2 ab = glm::vec2(-1.04f, 1.04f) * a004 + glm::vec2(rr.z, rr.w);
      const glm::vec3 spec_env = prefiltered * (f0 * ab.x + ab.y);
      const glm::vec3 kd = (1.0f - f0) * (1.0f - metallic);
      ambient = (kd * albedo * irradiance + spec_env) * environment_strength;
    }
    color += ambient * ao;
    glm::vec3 emissive = material.emissive;
    if (material.emissive_texture)
      emissive *= ToLinear(glm::vec3(in.Texture(kUnitEmissive, &SurfaceVaryings::uv)));
    color += emissive;
    out.color[0] = glm::vec4(glm::pow(glm::clamp(color, 0.0f, 1.0f), glm::vec3(1.0f / 2.2f)), base.a);
    return true;
  }
};

/// A soft studio environment for PbrShader: a cube map (size x size per face, mipmapped) of a bright sky fading
/// to a dim floor, made in `gl` and bound to kUnitEnvironment. Returns the number of levels (for
/// PbrShader::environment_levels).
float MakeStudioEnvironment(Context& gl, int size = 64);

}  // namespace softgl

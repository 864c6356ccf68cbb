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
#include <softgl/lanes.h>
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

/// How the built-in shaders bring their colour into the framebuffer's range [0, 1], after scaling it by
/// 2^exposure.
enum class ToneMap {
  kClamp,       ///< none: colours above 1 are clipped (a bright highlight turns flat white)
  kPbrNeutral,  ///< Khronos PBR Neutral: colours below about 0.8 kept as they are, highlights rolled off towards
                ///< white, hue kept; the glTF viewers' choice for product shots
  kAces,        ///< Krzysztof Narkowicz's fit of the ACES filmic curve: more contrast, saturated highlights whiten
};

/// sRGB's transfer functions (IEC 61966-2-1, as OpenGL's sRGB formats use them), per lane and channel; inputs
/// are taken in [0, 1].
inline Float SrgbToLinear(Float c) {
  return select(c <= 0.04045f, c * (1.0f / 12.92f), pow(max(c + 0.055f, 0.0f) * (1.0f / 1.055f), 2.4f));
}
inline Float LinearToSrgb(Float c) {
  return select(c <= 0.0031308f, c * 12.92f, pow(max(c, 0.0f), 1.0f / 2.4f) * 1.055f - 0.055f);
}
inline vec3 SrgbToLinear(const vec3& c) { return vec3(SrgbToLinear(c.x), SrgbToLinear(c.y), SrgbToLinear(c.z)); }
inline vec3 LinearToSrgb(const vec3& c) { return vec3(LinearToSrgb(c.x), LinearToSrgb(c.y), LinearToSrgb(c.z)); }

/// The tone curves of ToneMap, per lane, on colours >= 0; both give values in [0, 1].
inline vec3 ToneMapPbrNeutral(vec3 c) {
  constexpr float kStart = 0.8f - 0.04f, kDesaturation = 0.15f, kD = 1.0f - kStart;
  const Float x = min(min(c.x, c.y), c.z);
  const Float offset = select(x < 0.08f, x - 6.25f * x * x, Float(0.04f));
  c = c - offset;
  const Float peak = max(max(c.x, c.y), c.z);
  const Float new_peak = 1.0f - kD * kD / (peak + kD - kStart);
  const vec3 compressed = c * (new_peak / max(peak, 1e-6f));
  const Float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
  return clamp(select(peak < kStart, c, mix(compressed, vec3(new_peak), g)), 0.0f, 1.0f);
}
inline vec3 ToneMapAces(const vec3& c) {
  return clamp((c * (c * 2.51f + 0.03f)) / (c * (c * 2.43f + 0.59f) + 0.14f), 0.0f, 1.0f);
}

/// A colour as the framebuffer gets it: scaled by 2^exposure, tone-mapped, clamped to [0, 1], then sRGB-encoded
/// when `encode` (for colours in linear light).
inline vec3 DisplayColor(vec3 c, ToneMap tone_map, float exposure, bool encode) {
  if (exposure != 0.0f) c = c * std::exp2(exposure);
  c = max(c, 0.0f);
  if (tone_map == ToneMap::kPbrNeutral) c = ToneMapPbrNeutral(c);
  else if (tone_map == ToneMap::kAces) c = ToneMapAces(c);
  c = clamp(c, 0.0f, 1.0f);
  return encode ? LinearToSrgb(c) : c;
}

/// The varyings all built-in shaders share.
struct SurfaceVaryings {
  vec3 world_pos;
  vec3 normal;
  vec2 uv;
  vec4 tangent;
  vec4 color;
};

/// Common base: transforms, material, lighting, and the surface helpers (base colour with alpha test, normal
/// with normal map). Derived defines Fragment. Wide shaders (shader.h): each call shades 16 fragments.
template <class Derived>
class SurfaceShader : public Shader<Derived, SurfaceVaryings>, public MaterialProgram {
 public:
  using Varyings = SurfaceVaryings;
  using In = FragmentLanes<SurfaceVaryings>;
  using Out = FragmentLanesOut;

  glm::mat4 model{1.0f};
  glm::mat4 view_proj{1.0f};
  glm::mat3 normal_matrix{1.0f};
  Material material;
  Lighting lighting = Lighting::ThreePoint(glm::vec3(0.0f, 0.0f, 3.0f), glm::vec3(0.0f));
  bool lit = true;  // false for a mesh without normals (points, lines): Phong and PBR draw it unlit
  ToneMap tone_map = ToneMap::kClamp;
  float exposure = 0.0f;  // in stops: the colour is scaled by 2^exposure before tone mapping
  /// For a float colour buffer: the colour as shaded (PbrShader's in linear light, Unlit's and Phong's as the
  /// file's colours are, encoded), scaled by 2^exposure, with no tone curve, clamp or sRGB encoding.
  bool hdr_output = false;
  /// Shadows of the first light (lighting.lights[0], the key light of ThreePoint): while `shadows` is set, its light
  /// reaches a fragment in the proportion TextureShadow gives on texture unit kUnitShadow (a ShadowMap's depth
  /// texture: compared with LEQUAL, LINEAR filtering, so four comparisons) at shadow_matrix * world position (world
  /// to the map's texture coordinates and depth, all in [0, 1]), less shadow_bias from the depth. The other lights
  /// and ambient light are not shadowed.
  bool shadows = false;
  glm::mat4 shadow_matrix{1.0f};
  float shadow_bias = 0.0f;

  const Program& GetProgram() const override { return *this; }
  void SetTransforms(const glm::mat4& m, const glm::mat4& vp) override {
    model = m;
    view_proj = vp;
    normal_matrix = glm::transpose(glm::inverse(glm::mat3(m)));
  }
  void SetMaterial(const Material& m) override { material = m; }
  void SetMesh(const ModelMesh& mesh) override { lit = mesh.has_normals; }

  void Vertex(const VertexLanes& in, VertexLanesOut<SurfaceVaryings>& out) const {
    const vec4 world = model * vec4(vec3(in.attrib[kAttribPosition]), 1.0f);
    out.position = view_proj * world;
    out.varyings.world_pos = vec3(world);
    out.varyings.normal = normal_matrix * vec3(in.attrib[kAttribNormal]);
    out.varyings.uv = vec2(in.attrib[kAttribUv]);
    const vec4 t = in.attrib[kAttribTangent];
    out.varyings.tangent = vec4(glm::mat3(model) * vec3(t), t.w);
    out.varyings.color = in.attrib[kAttribColor];
  }

 protected:
  /// Base colour (factor x vertex colour x texture) as the file gives it, sRGB-encoded, for the shaders that
  /// shade encoded colours (Unlit, Phong); lanes below the alpha cutoff of a masked material are discarded. The
  /// model library loads colour maps as sRGB textures, which sample decoded to linear: the sample is encoded again.
  vec4 BaseColor(const In& in, Out& out) const {
    vec4 color = material.base_color * in.varyings.color;
    if (material.base_color_texture) {
      const vec4 t = in.Texture(kUnitBaseColor, in.varyings.uv);
      color *= vec4(LinearToSrgb(vec3(t)), t.w);
    }
    if (material.alpha_mode == Material::AlphaMode::kMask) out.Discard(color.w < material.alpha_cutoff);
    if (material.alpha_mode == Material::AlphaMode::kOpaque) color.w = 1.0f;
    return color;
  }

  /// The shading normal: interpolated, turned towards the viewer for back faces, perturbed by the normal map.
  vec3 Normal(const In& in) const {
    const vec3 interpolated = in.varyings.normal;
    const Float len = length(interpolated);
    vec3 n = select(len > 0.0f, interpolated / len, vec3(0.0f, 0.0f, 1.0f));
    if (!in.front_facing) n = -n;
    const vec3 t3 = vec3(in.varyings.tangent);
    const Bool has_tangent = dot(t3, t3) > 1e-12f;
    if (material.normal_texture && any(has_tangent)) {
      const vec3 t = normalize(t3 - n * dot(n, t3));
      const vec3 b = cross(n, t) * select(in.varyings.tangent.w < 0.0f, Float(-1.0f), Float(1.0f));
      const vec3 m = vec3(in.Texture(kUnitNormal, in.varyings.uv)) * 2.0f - 1.0f;
      const vec3 p = t * m.x + b * m.y + n * m.z;
      n = select(has_tangent && dot(p, p) > 1e-12f, normalize(p), n);
    }
    return n;
  }

  /// The share of light i that reaches the fragment: 1, or the first light's shadow test (`shadows`).
  Float LightShare(const In& in, int i) const {
    if (!shadows || i != 0) return Float(1.0f);
    const vec4 p = shadow_matrix * vec4(in.varyings.world_pos, 1.0f);
    return in.TextureShadow(kUnitShadow, vec3(p.x, p.y, p.z - shadow_bias));
  }

  /// A colour as the framebuffer gets it: scaled by 2^exposure, tone-mapped, then sRGB-encoded when `encode`
  /// (PbrShader works in linear light; Unlit and Phong take the file's colours as they are, already encoded).
  vec3 Display(const vec3& c, bool encode) const {
    if (hdr_output) return exposure != 0.0f ? c * std::exp2(exposure) : c;
    if (tone_map == ToneMap::kClamp && exposure == 0.0f && !encode) return c;  // the store clamps
    return DisplayColor(c, tone_map, exposure, encode);
  }

  /// Emission as the file gives it, sRGB-encoded (the emissive map's sample encoded again, as in BaseColor).
  vec3 Emissive(const In& in) const {
    vec3 e = material.emissive;
    if (material.emissive_texture) e *= LinearToSrgb(vec3(in.Texture(kUnitEmissive, in.varyings.uv)));
    return e;
  }
};

/// Base colour only.
struct UnlitShader : SurfaceShader<UnlitShader> {
  void Fragment(const In& in, Out& out) const {
    const vec4 c = BaseColor(in, out);
    out.color[0] = vec4(Display(vec3(c) + Emissive(in), false), c.w);
  }
};

/// Blinn-Phong per fragment: diffuse from the base colour, specular colour (times the specular map's red),
/// shininess, normal mapping, emissive, ambient (times the occlusion map).
struct PhongShader : SurfaceShader<PhongShader> {
  void Fragment(const In& in, Out& out) const {
    const vec4 base = BaseColor(in, out);
    if (!lit) {
      out.color[0] = vec4(Display(vec3(base) + Emissive(in), false), base.w);
      return;
    }
    const vec3 n = Normal(in);
    const vec3 v = normalize(lighting.eye - in.varyings.world_pos);
    vec3 spec_color = material.specular;
    if (material.specular_texture) spec_color *= in.Texture(kUnitSpecular, in.varyings.uv).x;
    Float ao = 1.0f;
    if (material.occlusion_texture) ao = in.Texture(kUnitOcclusion, in.varyings.uv).x;
    vec3 c = lighting.ambient * vec3(base) * ao;
    for (int i = 0; i < lighting.count; ++i) {
      const DirectionalLight& l = lighting.lights[i];
      const Float ndl = dot(n, l.direction);
      const Bool lit = ndl > 0.0f;
      if (!any(lit)) continue;
      const vec3 h = normalize(l.direction + v);
      const Float spec = pow(max(dot(n, h), 0.0f), material.shininess);
      c += select(lit, l.color * (vec3(base) * ndl + spec_color * spec) * LightShare(in, i), vec3(0.0f));
    }
    out.color[0] = vec4(Display(c + Emissive(in), false), base.w);
  }
};

/// glTF 2.0 metallic-roughness: Cook-Torrance with the GGX distribution, Smith-Schlick geometry and Schlick
/// Fresnel; base colour and emissive textures read as sRGB; ambient light from the cube map on kUnitEnvironment
/// when `environment_levels` > 0 (diffuse from its last level, specular from the level matching the roughness),
/// else the flat ambient colour; shaded in linear light, then exposure, tone map (`tone_map`) and sRGB encoding.
struct PbrShader : SurfaceShader<PbrShader> {
  float environment_levels = 0.0f;  // number of mip levels of the environment cube map; 0: none
  float environment_strength = 1.0f;
  /// The environment holds linear radiance (LoadEnvironment's HDR cube maps) rather than sRGB colours, and
  /// diffuse light comes from the irradiance cube map on kUnitIrradiance.
  bool environment_hdr = false;

  static vec3 ToLinear(const vec3& c) { return SrgbToLinear(clamp(c, 0.0f, 1.0f)); }
  vec3 LinearEmissive(const In& in) const {  // the emissive map is an sRGB texture: it samples linear
    vec3 e = material.emissive;
    if (material.emissive_texture) e *= vec3(in.Texture(kUnitEmissive, in.varyings.uv));
    return e;
  }

  void Fragment(const In& in, Out& out) const {
    vec4 base = material.base_color * in.varyings.color;
    if (material.base_color_texture) {
      const vec4 t = in.Texture(kUnitBaseColor, in.varyings.uv);
      base *= t;  // an sRGB texture: decoded to linear before filtering
    }
    if (material.alpha_mode == Material::AlphaMode::kMask) out.Discard(base.w < material.alpha_cutoff);
    if (material.alpha_mode == Material::AlphaMode::kOpaque) base.w = 1.0f;
    Float metallic = material.metallic, roughness = material.roughness, ao = 1.0f;
    if (material.metallic_roughness_texture) {
      const vec4 mr = in.Texture(kUnitMetallicRoughness, in.varyings.uv);
      roughness *= mr.y;
      metallic *= mr.z;
    }
    if (material.occlusion_texture) ao = in.Texture(kUnitOcclusion, in.varyings.uv).x;
    roughness = clamp(roughness, 0.04f, 1.0f);
    const vec3 albedo = vec3(base);
    if (!lit) {  // the base colour as it is (encoded back), plus emission
      out.color[0] = vec4(Display(albedo + LinearEmissive(in), true), base.w);
      return;
    }
    const vec3 n = Normal(in);
    const vec3 v = normalize(lighting.eye - in.varyings.world_pos);
    const Float ndv = max(dot(n, v), 1e-4f);
    const vec3 f0 = mix(vec3(0.04f), albedo, metallic);
    const Float a = roughness * roughness, a2 = a * a;
    const Float k = (roughness + 1.0f) * (roughness + 1.0f) / 8.0f;
    vec3 color(0.0f);
    for (int i = 0; i < lighting.count; ++i) {
      const DirectionalLight& l = lighting.lights[i];
      const Float ndl = dot(n, l.direction);
      const Bool lit = ndl > 0.0f;
      if (!any(lit)) continue;
      const vec3 h = normalize(l.direction + v);
      const Float ndh = max(dot(n, h), 0.0f), vdh = max(dot(v, h), 0.0f);
      const Float d_denom = ndh * ndh * (a2 - 1.0f) + 1.0f;
      const Float d = a2 / (3.14159265f * d_denom * d_denom);
      const Float g = (ndl / (ndl * (1.0f - k) + k)) * (ndv / (ndv * (1.0f - k) + k));
      const vec3 f = f0 + (1.0f - f0) * pow(1.0f - vdh, 5.0f);
      const vec3 specular = d * g * f / (4.0f * ndl * ndv);
      const vec3 kd = (1.0f - f) * (1.0f - metallic);
      color += select(lit, (kd * albedo / 3.14159265f + specular) * l.color * ndl * 3.14159265f * LightShare(in, i),
                      vec3(0.0f));
    }
    vec3 ambient = lighting.ambient * albedo;
    if (environment_levels > 0.0f) {
      const float last = environment_levels - 1.0f;
      const vec3 r = reflect(-v, n);
      const vec3 irradiance = environment_hdr ? vec3(in.TextureCubeLod(kUnitIrradiance, n, 0.0f))
                                              : ToLinear(vec3(in.TextureCubeLod(kUnitEnvironment, n, last)));
      const vec4 reflected = in.TextureCubeLod(kUnitEnvironment, r, roughness * last);
      const vec3 prefiltered = environment_hdr ? vec3(reflected) : ToLinear(vec3(reflected));
      // Analytic approximation of the split-sum environment BRDF.
      const Float rr_x = roughness * -1.0f + 1.0f, rr_y = roughness * -0.0275f + 0.0425f;
      const Float rr_z = roughness * -0.572f + 1.04f, rr_w = roughness * 0.022f + -0.04f;
      const Float a004 = min(rr_x * rr_x, exp2(-9.28f * ndv)) * rr_x + rr_y;
      const Float ab_x = -1.04f * a004 + rr_z, ab_y = 1.04f * a004 + rr_w;
      const vec3 spec_env = prefiltered * (f0 * ab_x + ab_y);
      const vec3 kd = (1.0f - f0) * (1.0f - metallic);
      ambient = (kd * albedo * irradiance + spec_env) * environment_strength;
    }
    color += ambient * ao;
    color += LinearEmissive(in);
    out.color[0] = vec4(Display(color, true), base.w);
  }
};

// The stages of the three shaders above are compiled once, into softgl::model (src/model/shaders.cpp), rather than
// in every program that draws with them (each is three builds of the wide code, one per instruction set).
extern template void Shader<UnlitShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
extern template void Shader<UnlitShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;
extern template void Shader<PhongShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
extern template void Shader<PhongShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;
extern template void Shader<PbrShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
extern template void Shader<PbrShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;

/// A soft studio environment for PbrShader: a cube map (size x size per face, mipmapped) of a bright sky fading
/// to a dim floor, made in `gl` and bound to kUnitEnvironment. Returns the number of levels (for
/// PbrShader::environment_levels).
float MakeStudioEnvironment(Context& gl, int size = 64);

/// A depth-only render target for shadow mapping: a size x size DEPTH_COMPONENT (float) texture, filtered LINEAR,
/// clamped to a border of depth 1 (nothing outside the map shadows anything), compared with LEQUAL so that
/// TextureShadow reads it, and attached as the depth buffer of a new framebuffer that has no colour buffer. Both
/// are left bound (the texture to TEXTURE_2D on the active unit, the framebuffer to FRAMEBUFFER).
struct ShadowMap {
  std::uint32_t texture = 0, framebuffer = 0;
  int size = 0;
};
ShadowMap MakeShadowMap(Context& gl, int size);

/// An environment from an equirectangular HDR image (Radiance .hdr, or any image ReadImage reads; longitude 0 at
/// -z, the top row up): a float cube map of size x size per face bound to kUnitEnvironment whose level L is
/// prefiltered for roughness L / (levels - 1) with the GGX distribution (the level PbrShader reads for that
/// roughness; level 0 the image itself), and a 16 x 16 cube map of its diffuse irradiance (cosine-weighted over
/// the hemisphere, divided by pi) bound to kUnitIrradiance, both holding linear radiance. Set the PbrShader's
/// environment_levels to the result and environment_hdr to true. Returns 0, with a message in `error`, when the
/// image cannot be read.
float LoadEnvironment(Context& gl, const std::string& path, int size = 128, std::string* error = nullptr);

}  // namespace softgl

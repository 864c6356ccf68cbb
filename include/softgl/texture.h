// softgl/texture.h — textures as the shader stages see them: sampling by texture unit.
//
// A draw hands its shader a `Textures`: for each of the kMaxTextureUnits units, the TEXTURE_2D, TEXTURE_CUBE_MAP,
// TEXTURE_2D_ARRAY, TEXTURE_3D, TEXTURE_2D_MULTISAMPLE, TEXTURE_2D_MULTISAMPLE_ARRAY, TEXTURE_1D, TEXTURE_1D_ARRAY
// and TEXTURE_BUFFER textures bound to it and their sampling state.
// Filtering, wrapping and the level of detail follow the OpenGL 4.6 specification (section 8.14): texel centres at
// +0.5, wrap applied per texel, lambda from the screen-space derivatives of the texture coordinates. Sampling a
// unit with no texture, or an incomplete one, returns (0, 0, 0, 1), as OpenGL does.
//
// In a fragment shader use FragmentLanes::Texture(unit, uv) (wide shaders: derivatives taken across the block) or
// FragmentIn::Texture(unit, &Varyings::uv) (derivatives across the 2x2 quad), or pass derivatives yourself; the
// vertex stage has only the Lod forms.
#pragma once

#include <softgl/config.h>

#include <glm/glm.hpp>

namespace softgl {

/// Number of texture units: GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, OpenGL 3.3's minimum (every unit can be sampled
/// from either stage, so MAX_TEXTURE_IMAGE_UNITS and MAX_VERTEX_TEXTURE_IMAGE_UNITS are the same).
inline constexpr int kMaxTextureUnits = 48;
/// Largest texture width or height (GL_MAX_TEXTURE_SIZE).
inline constexpr int kMaxTextureSize = 16384;
/// Largest width, height or depth of a 3D texture (GL_MAX_3D_TEXTURE_SIZE).
inline constexpr int kMax3DTextureSize = 2048;
/// Most layers of a 2D array texture (GL_MAX_ARRAY_TEXTURE_LAYERS).
inline constexpr int kMaxArrayTextureLayers = 2048;
/// Most texels a buffer texture reads from its buffer (GL_MAX_TEXTURE_BUFFER_SIZE): texels past it are outside.
inline constexpr int kMaxTextureBufferSize = 1 << 27;
/// Most samples of an integer renderbuffer or multisample texture (GL_MAX_INTEGER_SAMPLES, OpenGL 3.3's minimum):
/// integer images are single-sampled.
inline constexpr int kMaxIntegerSamples = 1;

namespace detail {
struct TextureView;  // a bound texture resolved for one draw; defined in src/
}

/// The textures a draw samples, unit by unit, and their lookups. An integer texture's (R8UI ... RGBA32I) samples
/// are its integers carried as the floats' bits (FragmentLanes::ITexture and its kin read them so).
class Textures {
 public:
  /// texture(sampler2D, uv): filtered sample of unit's 2D texture; duv_dx, duv_dy are the derivatives of uv along
  /// window x and y, bias is added to the level of detail.
  glm::vec4 Sample(int unit, glm::vec2 uv, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias = 0.0f) const;
  /// Sample() for the four lanes of a 2x2 quad at once: out[l] is exactly Sample(unit, uv[l], duv_dx[l],
  /// duv_dy[l], bias), computed side by side where the processor allows (FragmentIn::Texture uses it).
  void SampleQuad(int unit, const glm::vec2 uv[4], const glm::vec2 duv_dx[4], const glm::vec2 duv_dy[4], float bias,
                  glm::vec4 out[4]) const;
  /// textureLod(sampler2D, uv, lod).
  glm::vec4 SampleLod(int unit, glm::vec2 uv, float lod) const;
  /// texture(samplerCube, dir): face chosen by the major axis of dir, then as Sample on that face.
  glm::vec4 SampleCube(int unit, glm::vec3 dir, glm::vec3 ddir_dx, glm::vec3 ddir_dy, float bias = 0.0f) const;
  /// textureLod(samplerCube, dir, lod).
  glm::vec4 SampleCubeLod(int unit, glm::vec3 dir, float lod) const;
  /// texture(sampler2DShadow, vec3(uv, ref)): each texel the filter uses is compared with ref by the texture's
  /// TEXTURE_COMPARE_FUNC (1 if it passes, 0 if not) and the results are filtered: percentage-closer filtering.
  /// Needs TEXTURE_COMPARE_MODE = COMPARE_REF_TO_TEXTURE on a depth texture; otherwise returns 0.
  float SampleShadow(int unit, glm::vec2 uv, float ref, glm::vec2 duv_dx, glm::vec2 duv_dy) const;
  /// textureSize(sampler2D, level): the size of a level of unit's 2D texture, (0, 0) if there is none.
  glm::ivec2 Size(int unit, int level = 0) const;

  /// texture(sampler2DArray, vec3(uv, layer)): Sample on one layer of unit's TEXTURE_2D_ARRAY, the layer
  /// floor(layer + 0.5) clamped to the texture's layers (OpenGL 4.6, section 8.14.2). The level of detail comes
  /// from uv alone.
  glm::vec4 SampleArray(int unit, glm::vec3 uv_layer, glm::vec2 duv_dx, glm::vec2 duv_dy, float bias = 0.0f) const;
  /// textureLod(sampler2DArray, vec3(uv, layer), lod).
  glm::vec4 SampleArrayLod(int unit, glm::vec3 uv_layer, float lod) const;
  /// texture(sampler2DArrayShadow, vec4(uv, layer, ref)): SampleShadow on the layer of a depth texture array.
  float SampleArrayShadow(int unit, glm::vec3 uv_layer, float ref, glm::vec2 duv_dx, glm::vec2 duv_dy) const;
  /// texture(sampler3D, str): filtered sample of unit's TEXTURE_3D: LINEAR interpolates between 8 texels (two
  /// slices, wrapped by TEXTURE_WRAP_R), and the level of detail comes from the derivatives of all of (s, t, r).
  glm::vec4 Sample3D(int unit, glm::vec3 str, glm::vec3 dstr_dx, glm::vec3 dstr_dy, float bias = 0.0f) const;
  /// textureLod(sampler3D, str, lod).
  glm::vec4 Sample3DLod(int unit, glm::vec3 str, float lod) const;
  /// textureSize(sampler2DArray, level): width, height and layers; (0, 0, 0) if there is none.
  glm::ivec3 SizeArray(int unit, int level = 0) const;
  /// textureSize(sampler3D, level): width, height and depth; (0, 0, 0) if there is none.
  glm::ivec3 Size3D(int unit, int level = 0) const;

  /// texture(sampler1D, s): filtered sample of unit's TEXTURE_1D (a row of texels: as a 2D texture one texel high
  /// sampled at its middle, TEXTURE_WRAP_T unused); the level of detail from s's derivatives.
  glm::vec4 Sample1D(int unit, float s, float ds_dx, float ds_dy, float bias = 0.0f) const;
  /// textureLod(sampler1D, s, lod).
  glm::vec4 Sample1DLod(int unit, float s, float lod) const;
  /// texture(sampler1DArray, vec2(s, layer)): Sample1D on one layer of unit's TEXTURE_1D_ARRAY, the layer
  /// floor(layer + 0.5) clamped to the texture's layers.
  glm::vec4 Sample1DArray(int unit, glm::vec2 s_layer, float ds_dx, float ds_dy, float bias = 0.0f) const;
  /// textureLod(sampler1DArray, vec2(s, layer), lod).
  glm::vec4 Sample1DArrayLod(int unit, glm::vec2 s_layer, float lod) const;
  /// textureSize(sampler1D, level): the width of a level, 0 if there is none.
  int Size1D(int unit, int level = 0) const;
  /// textureSize(sampler1DArray, level): width and layers; (0, 0) if there is none.
  glm::ivec2 Size1DArray(int unit, int level = 0) const;

  /// texelFetch(sampler2D, texel, level): texel (x, y) of a level of unit's 2D texture, unfiltered (an sRGB colour
  /// decoded); (0, 0, 0, 0) outside the level, for a level the texture does not have, or an incomplete texture.
  glm::vec4 Fetch(int unit, glm::ivec2 texel, int level = 0) const;
  /// texelFetch(sampler2DMS, texel, sample): one sample of unit's TEXTURE_2D_MULTISAMPLE texture;
  /// (0, 0, 0, 0) outside the image or for a sample it does not have.
  glm::vec4 FetchSample(int unit, glm::ivec2 texel, int sample) const;
  /// textureSize(sampler2DMS) and textureSamples(sampler2DMS): (0, 0) and 0 when there is none.
  glm::ivec2 SizeMultisample(int unit) const;
  int Samples(int unit) const;
  /// texelFetch(sampler2DMSArray, ivec3(texel, layer), sample): one sample of a layer of unit's
  /// TEXTURE_2D_MULTISAMPLE_ARRAY texture; (0, 0, 0, 0) outside the image, for a layer or a sample it does not have.
  glm::vec4 FetchSampleArray(int unit, glm::ivec3 texel_layer, int sample) const;
  /// textureSize(sampler2DMSArray) (width, height, layers) and its samples: zero when there is none.
  glm::ivec3 SizeMultisampleArray(int unit) const;
  int SamplesArray(int unit) const;
  /// texelFetch(samplerBuffer, index): texel `index` of unit's buffer texture, read from its buffer's store as it
  /// is when the draw's stage runs, in the texture's format (Context::TexBuffer), unfiltered: channels the format
  /// lacks read (0, 0, 1). An index outside the store reads a texel of zero bytes ((0, 0, 0, 1) for a format
  /// without alpha); a texture without a buffer, or no buffer texture, reads (0, 0, 0, 0).
  glm::vec4 FetchBuffer(int unit, int index) const;
  /// textureSize(samplerBuffer): the texels in the buffer's store (its bytes over the texel's, at most
  /// kMaxTextureBufferSize); 0 when there is none.
  int SizeBuffer(int unit) const;

  /// Coordinates and their screen-space derivatives for 16 lanes (a wide shader's block of fragments).
  struct Lanes {
    float s[16], t[16], r[16];  ///< (s, t), and r: a cube map direction's z, or a shadow lookup's reference
    float ds_dx[16], dt_dx[16], dr_dx[16];
    float ds_dy[16], dt_dy[16], dr_dy[16];
  };
  /// The wide forms of the calls above, for 16 lanes at once; out[c][lane] is channel c of each lane's sample,
  /// lane for lane the same floats as the one-lane call. FragmentLanes and VertexLanes (shader.h) call them.
  void SampleLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;           ///< Sample
  void SampleLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;  ///< SampleLod (s, t)
  void SampleCubeLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;       ///< SampleCube (s, t, r)
  void SampleCubeLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;
  void SampleShadowLanes(int unit, const Lanes& c, float out[16]) const;  ///< SampleShadow, r the reference
  void SampleArrayLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;  ///< SampleArray, r the layer
  void SampleArrayLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;
  /// SampleArrayShadow: r the layer, ref the references.
  void SampleArrayShadowLanes(int unit, const Lanes& c, const float ref[16], float out[16]) const;
  void Sample3DLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;  ///< Sample3D
  void Sample3DLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;
  /// Sample1D and Sample1DLod: s the coordinate (t and r unread).
  void Sample1DLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;
  void Sample1DLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;
  /// Sample1DArray and Sample1DArrayLod: s the coordinate, t the layer (r unread).
  void Sample1DArrayLanes(int unit, const Lanes& c, float bias, float out[4][16]) const;
  void Sample1DArrayLodLanes(int unit, const Lanes& c, const float lod[16], float out[4][16]) const;
  /// Fetch and FetchSample, lane by lane: texel (x[l], y[l]) at level[l] (or sample[l]).
  void FetchLanes(int unit, const int x[16], const int y[16], const int level[16], float out[4][16]) const;
  void FetchSampleLanes(int unit, const int x[16], const int y[16], const int sample[16], float out[4][16]) const;
  /// FetchSampleArray for 16 lanes: texel (x[l], y[l]) of layer layer[l], sample sample[l].
  void FetchSampleArrayLanes(int unit, const int x[16], const int y[16], const int layer[16], const int sample[16],
                             float out[4][16]) const;
  /// FetchBuffer for 16 lanes: texel index[l] in lane l.
  void FetchBufferLanes(int unit, const int index[16], float out[4][16]) const;

  const detail::TextureView* unit_2d[kMaxTextureUnits] = {};
  const detail::TextureView* unit_cube[kMaxTextureUnits] = {};
  const detail::TextureView* unit_2d_array[kMaxTextureUnits] = {};
  const detail::TextureView* unit_3d[kMaxTextureUnits] = {};
  const detail::TextureView* unit_2d_ms[kMaxTextureUnits] = {};
  const detail::TextureView* unit_1d[kMaxTextureUnits] = {};
  const detail::TextureView* unit_1d_array[kMaxTextureUnits] = {};
  const detail::TextureView* unit_buffer[kMaxTextureUnits] = {};
  const detail::TextureView* unit_2d_ms_array[kMaxTextureUnits] = {};
  /// Units from this one on have no texture bound (their entries above are null): what a draw copies and compares
  /// stops here.
  int units = kMaxTextureUnits;
};

}  // namespace softgl

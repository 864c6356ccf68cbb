// shadow_map.cpp — the depth texture and framebuffer of a shadow map.
#include <softgl/shaders.h>

namespace softgl {

ShadowMap MakeShadowMap(Context& gl, int size) {
  ShadowMap map;
  map.size = size;
  map.texture = gl.GenTexture();
  gl.BindTexture(TEXTURE_2D, map.texture);
  gl.TexImage2D(TEXTURE_2D, 0, DEPTH_COMPONENT, size, size, 0, DEPTH_COMPONENT, FLOAT, nullptr);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MIN_FILTER, LINEAR);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_MAG_FILTER, LINEAR);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_WRAP_S, CLAMP_TO_BORDER);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_WRAP_T, CLAMP_TO_BORDER);
  const float far_border[4] = {1, 1, 1, 1};
  gl.TexParameterfv(TEXTURE_2D, TEXTURE_BORDER_COLOR, far_border);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_COMPARE_MODE, COMPARE_REF_TO_TEXTURE);
  gl.TexParameteri(TEXTURE_2D, TEXTURE_COMPARE_FUNC, LEQUAL);
  map.framebuffer = gl.GenFramebuffer();
  gl.BindFramebuffer(FRAMEBUFFER, map.framebuffer);
  gl.FramebufferTexture2D(FRAMEBUFFER, DEPTH_ATTACHMENT, TEXTURE_2D, map.texture, 0);
  const Enum no_color = NONE;
  gl.DrawBuffers(1, &no_color);
  return map;
}

}  // namespace softgl

// scenes.h — the named conformance scenes and what each must match.
#pragma once

#include <vector>

#include "backend.h"

namespace conformance {

/// The model scene's file, from Debian's assimp-testmodels.
inline constexpr const char* kModelPath = "/usr/share/assimp/models/OBJ/spider.obj";

enum class Check {
  kExact,             // colour identical
  kExactWithDepth,    // colour identical, depth within the 24-bit depth buffer's resolution
  kExactWithStencil,  // colour and stencil identical
  kExactWithDepthStencil,  // colour and stencil identical, depth within the 24-bit depth buffer's resolution
  kColor,             // colour within +-1 per channel
  kCoverage,          // the same pixels drawn (against a black background); colours reported, not compared
  kTexture,           // colour within +-1 on at least 99.5% of the pixels (texture filtering, sRGB conversion)
  kStep4,             // colour within one step of a 4-bit channel (+-17): 16-bit targets, whose rounding to
                      // 4, 5 or 6 bits differs between llvmpipe and OpenGL's formula by a step
};

/// The largest colour difference a check allows (kCoverage: any).
inline int Tolerance(Check c) {
  return c == Check::kColor || c == Check::kTexture ? 1 : c == Check::kStep4 ? 17 : c == Check::kCoverage ? 255 : 0;
}

struct SceneInfo {
  const char* name;
  int width, height;
  Check check;
  void (*run)(Backend&);
};

const std::vector<SceneInfo>& Scenes();

}  // namespace conformance

// culling.cpp — OpenGL's facing rule (section 14.6.1 of the 4.6 specification).
#include "culling.h"

namespace softgl::detail {

float SignedArea(const WindowVertex* v, int count) {
  // A fan of cross products around vertex 0: exact for a triangle's orientation up to float rounding, and
  // free of the cancellation that absolute coordinates would bring far from the origin.
  float area = 0.0f;
  for (int i = 1; i + 1 < count; ++i) {
    const glm::vec2 a = glm::vec2(v[i].win) - glm::vec2(v[0].win);
    const glm::vec2 b = glm::vec2(v[i + 1].win) - glm::vec2(v[0].win);
    area += a.x * b.y - b.x * a.y;
  }
  return area;
}

bool IsFrontFacing(float area, Enum front_face) { return front_face == CW ? area < 0.0f : area > 0.0f; }

bool IsCulled(bool front_facing, Enum cull_face) {
  switch (cull_face) {
    case FRONT_AND_BACK: return true;
    case FRONT: return front_facing;
    default: return !front_facing;
  }
}

}  // namespace softgl::detail

// culling.h — stage 6: facing and face culling, decided from the signed area in window space.
#pragma once

#include <softgl/enums.h>

#include "types.h"

namespace softgl::detail {

/// Twice the signed area of a window-space polygon (positive when counter-clockwise with y up).
float SignedArea(const WindowVertex* v, int count);

/// Whether a polygon of signed area `area` is front-facing for front_face CCW or CW.
bool IsFrontFacing(float area, Enum front_face);

/// Whether culling (when enabled) removes a polygon of this facing; cull_face FRONT, BACK or FRONT_AND_BACK.
bool IsCulled(bool front_facing, Enum cull_face);

}  // namespace softgl::detail

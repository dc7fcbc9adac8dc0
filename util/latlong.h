// The latitude-longitude mapping of environment maps, one for every renderer (the path
// tracer's EnvironmentMap, the baked sky, the preview's background): u ∈ [0, 1) around the
// y axis from −z, v ∈ [0, 1] from +y (top row) to −y.
#pragma once

#include <algorithm>

#include "util/fast_trig.h"
#include "util/math.h"

namespace phellem {

inline Vec2f direction_to_latlong(const Vec3f& d) {
  float u = 0.5f + fast_atan2(d.x(), -d.z()) * (0.5f * kInvPi);
  if (u >= 1.0f) u -= 1.0f;
  if (u < 0.0f) u = 0.0f;
  const float v = fast_acos(std::clamp(d.y(), -1.0f, 1.0f)) * kInvPi;
  return Vec2f(u, v);
}

inline Vec3f latlong_to_direction(const Vec2f& uv) {
  float sp, cp, st, ct;
  fast_sincos((uv.x() - 0.5f) * kTwoPi, &sp, &cp);
  fast_sincos(uv.y() * kPi, &st, &ct);
  return Vec3f(st * sp, ct, -st * cp);
}

}  // namespace phellem

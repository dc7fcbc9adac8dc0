#include "preview/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace phellem::preview {

OrbitCamera::OrbitCamera(const CameraDesc& start) : base_(start), target_(start.look_at) {
  const Vec3f d = start.position - start.look_at;
  distance_ = std::max(1e-4f, d.norm());
  yaw_ = std::atan2(d.x(), d.z());
  pitch_ = std::asin(std::clamp(d.y() / distance_, -1.0f, 1.0f));
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw_ -= 0.005f * dx;
  pitch_ = std::clamp(pitch_ + 0.005f * dy, -1.5f, 1.5f);
}

void OrbitCamera::pan(float dx, float dy, int height) {
  const CameraDesc c = desc();
  const Vec3f f = (c.look_at - c.position).normalized(), r = f.cross(Vec3f::UnitY()).normalized(), u = r.cross(f);
  const float metres_per_pixel = 2 * distance_ * std::tan(radians(c.fov_deg) / 2) / float(std::max(1, height));
  target_ += (-dx * r + dy * u) * metres_per_pixel;
}

void OrbitCamera::zoom(float steps) { distance_ = std::max(1e-3f, distance_ * std::pow(0.9f, steps)); }

CameraDesc OrbitCamera::desc() const {
  CameraDesc c = base_;
  c.look_at = target_;
  c.position = target_ + distance_ * Vec3f(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_));
  c.up = Vec3f::UnitY();
  return c;
}

}  // namespace phellem::preview

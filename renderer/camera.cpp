#include "renderer/camera.h"

#include "renderer/sampling.h"

namespace phellem {

Camera::Camera(const CameraDesc& c, int width, int height) : pos_(c.position), width_(width), height_(height) {
  forward_ = (c.look_at - c.position).normalized();
  right_ = forward_.cross(c.up.normalized()).normalized();
  up_ = right_.cross(forward_);
  tan_half_fov_ = std::tan(radians(c.fov_deg) * 0.5f);
  aspect_ = float(width) / float(height);
  aperture_ = c.aperture_radius;
  focus_ = c.focus_distance > 0 ? c.focus_distance : (c.look_at - c.position).norm();
}

Ray Camera::generate(const Vec2f& film, const Vec2f& lens) const {
  const float sx = (2.0f * film.x() / width_ - 1.0f) * tan_half_fov_ * aspect_;
  const float sy = (1.0f - 2.0f * film.y() / height_) * tan_half_fov_;
  Vec3f d = (forward_ + sx * right_ + sy * up_);
  if (aperture_ <= 0) return {pos_, d.normalized()};
  // Thin lens: all rays through the lens meet on the plane of focus (distance along forward).
  const Vec3f focus_point = pos_ + d * focus_;
  const Vec2f l = sample_concentric_disk(lens) * aperture_;
  const Vec3f o = pos_ + right_ * l.x() + up_ * l.y();
  return {o, (focus_point - o).normalized()};
}

CameraDesc Camera::orbit(const CameraDesc& c, float degrees) {
  CameraDesc out = c;
  const Eigen::AngleAxisf rot(radians(degrees), Vec3f::UnitY());
  out.position = c.look_at + rot * (c.position - c.look_at);
  out.up = rot * c.up;
  return out;
}

}  // namespace phellem

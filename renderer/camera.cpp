#include "renderer/camera.h"

#include "renderer/sampling.h"

namespace phellem {

Camera::Camera(const CameraDesc& c, int width, int height)
    : model_(c, width, height),
      aperture_(c.aperture_radius),
      focus_(c.focus_distance > 0 ? c.focus_distance : (c.look_at - c.position).norm()) {}

Ray Camera::generate(const Vec2f& film, const Vec2f& lens) const {
  const Vec3f d = model_.direction(film);
  if (aperture_ <= 0) return {model_.position(), d.normalized()};
  // Thin lens: all rays through the lens meet on the plane of focus (distance along forward).
  const Vec3f focus_point = model_.position() + d * focus_;
  const Vec2f l = sample_concentric_disk(lens) * aperture_;
  const Vec3f o = model_.position() + model_.right() * l.x() + model_.up() * l.y();
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

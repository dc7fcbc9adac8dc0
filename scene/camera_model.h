// The pinhole camera both renderers share (issue 23): the path tracer's primary rays and the
// OpenGL preview's view and projection matrices come from this one model, so a pixel centre
// (x + ½, y + ½), rows top-down, sees the same point in both.
#pragma once

#include <Eigen/Core>

#include "scene/scene_desc.h"
#include "util/math.h"

namespace phellem {

class CameraModel {
 public:
  CameraModel(const CameraDesc& desc, int width, int height);
  // The (unnormalized) direction through a raster position in pixels, (0, 0) the top-left
  // corner of the image.
  Vec3f direction(const Vec2f& film) const {
    const float sx = (2.0f * film.x() / float(width_) - 1.0f) * tan_half_fov_ * aspect_;
    const float sy = (1.0f - 2.0f * film.y() / float(height_)) * tan_half_fov_;
    return forward_ + sx * right_ + sy * up_;
  }
  // OpenGL's matrices (column vectors, right-handed eye space looking down −z, clip depth
  // [−1, 1]): a point on direction(film) lands at window position (film.x, height − film.y).
  Eigen::Matrix4f view() const;
  Eigen::Matrix4f projection(float near, float far) const;

  const Vec3f& position() const { return pos_; }
  const Vec3f& forward() const { return forward_; }
  const Vec3f& right() const { return right_; }
  const Vec3f& up() const { return up_; }
  float tan_half_fov() const { return tan_half_fov_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Vec3f pos_, forward_, right_, up_;
  float tan_half_fov_, aspect_;
  int width_, height_;
};

}  // namespace phellem

#include "scene/camera_model.h"

#include <cmath>

namespace phellem {

CameraModel::CameraModel(const CameraDesc& c, int width, int height) : pos_(c.position), width_(width), height_(height) {
  forward_ = (c.look_at - c.position).normalized();
  right_ = forward_.cross(c.up.normalized()).normalized();
  up_ = right_.cross(forward_);
  tan_half_fov_ = std::tan(radians(c.fov_deg) * 0.5f);
  aspect_ = float(width) / float(height);
}

Eigen::Matrix4f CameraModel::view() const {
  Eigen::Matrix4f v = Eigen::Matrix4f::Identity();
  v.block<1, 3>(0, 0) = right_.transpose();
  v.block<1, 3>(1, 0) = up_.transpose();
  v.block<1, 3>(2, 0) = -forward_.transpose();
  v(0, 3) = -right_.dot(pos_);
  v(1, 3) = -up_.dot(pos_);
  v(2, 3) = forward_.dot(pos_);
  return v;
}

Eigen::Matrix4f CameraModel::projection(float near, float far) const {
  Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
  p(0, 0) = 1.0f / (tan_half_fov_ * aspect_);
  p(1, 1) = 1.0f / tan_half_fov_;
  p(2, 2) = -(far + near) / (far - near);
  p(2, 3) = -2.0f * far * near / (far - near);
  p(3, 2) = -1.0f;
  return p;
}

}  // namespace phellem

#include "bark/growth/texture_transport.h"

#include <cmath>

#include <Eigen/Dense>

#include "bark/geometry/uv_seams.h"

namespace phellem::bark {

namespace {

// A face's edges from its first corner (columns) and their UV differences, each taken to the
// nearest whole period (a face across a wrapped seam counts as the short stretch it is).
struct FaceJacobianParts {
  Eigen::Matrix<double, 3, 2> e;
  Eigen::Matrix2d t;
};
FaceJacobianParts face_parts(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& uv,
                             const std::array<uint32_t, 3>& f) {
  FaceJacobianParts p;
  p.e.col(0) = points[f[1]] - points[f[0]];
  p.e.col(1) = points[f[2]] - points[f[0]];
  p.t.col(0) = wrapped_uv_delta(uv[f[0]], uv[f[1]]);
  p.t.col(1) = wrapped_uv_delta(uv[f[0]], uv[f[2]]);
  return p;
}

}  // namespace

std::vector<TextureGradient> texture_gradients(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<Eigen::Vector2d>& uv,
                                               const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<TextureGradient> sum(points.size(), TextureGradient::Zero());
  std::vector<double> weight(points.size(), 0.0);
  for (const auto& f : faces) {
    const auto [e, t] = face_parts(points, uv, f);
    const Eigen::Matrix2d ete = e.transpose() * e;
    const double area2 = std::sqrt(std::max(0.0, ete.determinant()));  // twice the face's area
    if (!(area2 > 1e-20)) continue;
    const TextureGradient g = t * ete.inverse() * e.transpose();
    if (!g.allFinite()) continue;
    for (uint32_t v : f) sum[v] += area2 * g, weight[v] += area2;
  }
  for (size_t v = 0; v < sum.size(); ++v)
    if (weight[v] > 0) sum[v] /= weight[v];
  return sum;
}

std::vector<TextureAxes> texture_axes(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& uv,
                                      const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<TextureAxes> axes(points.size());
  for (const auto& f : faces) {
    const auto [e, t] = face_parts(points, uv, f);
    const double area2 = e.col(0).cross(e.col(1)).norm();  // twice the face's area
    if (!(area2 > 1e-20) || !(std::abs(t.determinant()) > 1e-300)) continue;
    const Eigen::Matrix<double, 3, 2> j = e * t.inverse();  // ∂x/∂u, ∂x/∂v
    const double lu = j.col(0).norm(), lv = j.col(1).norm();
    if (!(lu > 0 && lv > 0) || !j.allFinite()) continue;
    for (uint32_t p : f) {
      axes[p].u += area2 / lu * j.col(0);
      axes[p].v += area2 / lv * j.col(1);
    }
  }
  for (auto& a : axes) {
    if (a.u.squaredNorm() > 0) a.u.normalize();
    if (a.v.squaredNorm() > 0) a.v.normalize();
  }
  return axes;
}

Eigen::Vector3d texture_direction(const TextureAxes& axes, const Eigen::Vector2d& d) {
  const Eigen::Vector3d s = d.x() * axes.u + d.y() * axes.v;
  const double len = s.norm();
  return len > 1e-300 ? Eigen::Vector3d(s * (d.norm() / len)) : Eigen::Vector3d::Zero();
}

Eigen::Vector2d transported_uv(const Eigen::Vector2d& uv, const TextureGradient& g, const Eigen::Vector3d& move,
                               const Eigen::Vector3d& normal) {
  const Eigen::Vector3d tangential = move - move.dot(normal) * normal;
  return uv + g * tangential;
}

}  // namespace phellem::bark

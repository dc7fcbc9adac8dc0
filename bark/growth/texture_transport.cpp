#include "bark/growth/texture_transport.h"

#include <cmath>

#include <Eigen/Dense>

#include "bark/geometry/uv_seams.h"

namespace phellem::bark {

std::vector<TextureGradient> texture_gradients(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<Eigen::Vector2d>& uv,
                                               const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<TextureGradient> sum(points.size(), TextureGradient::Zero());
  std::vector<double> weight(points.size(), 0.0);
  for (const auto& f : faces) {
    Eigen::Matrix<double, 3, 2> e;
    e.col(0) = points[f[1]] - points[f[0]];
    e.col(1) = points[f[2]] - points[f[0]];
    Eigen::Matrix2d t;
    t.col(0) = wrapped_uv_delta(uv[f[0]], uv[f[1]]);
    t.col(1) = wrapped_uv_delta(uv[f[0]], uv[f[2]]);
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

Eigen::Vector2d transported_uv(const Eigen::Vector2d& uv, const TextureGradient& g, const Eigen::Vector3d& move,
                               const Eigen::Vector3d& normal) {
  const Eigen::Vector3d tangential = move - move.dot(normal) * normal;
  return uv + g * tangential;
}

}  // namespace phellem::bark

#include "bark/geometry/generalized_cylinder.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace phellem::bark {

namespace {

// Centripetal Catmull-Rom (Barry–Goldman pyramid) between p1 and p2, t ∈ [0, 1].
Eigen::Vector3d catmull_rom(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& p3, double t) {
  auto knot = [](double ti, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return ti + std::max(1e-9, std::sqrt((b - a).norm()));
  };
  const double t0 = 0, t1 = knot(t0, p0, p1), t2 = knot(t1, p1, p2), t3 = knot(t2, p2, p3);
  const double u = t1 + (t2 - t1) * t;
  const Eigen::Vector3d a1 = (t1 - u) / (t1 - t0) * p0 + (u - t0) / (t1 - t0) * p1;
  const Eigen::Vector3d a2 = (t2 - u) / (t2 - t1) * p1 + (u - t1) / (t2 - t1) * p2;
  const Eigen::Vector3d a3 = (t3 - u) / (t3 - t2) * p2 + (u - t2) / (t3 - t2) * p3;
  const Eigen::Vector3d b1 = (t2 - u) / (t2 - t0) * a1 + (u - t0) / (t2 - t0) * a2;
  const Eigen::Vector3d b2 = (t3 - u) / (t3 - t1) * a2 + (u - t1) / (t3 - t1) * a3;
  return (t2 - u) / (t2 - t1) * b1 + (u - t1) / (t2 - t1) * b2;
}

}  // namespace

GeneralizedCylinder::GeneralizedCylinder(const std::vector<Eigen::Vector3d>& axis, std::vector<double> radius,
                                         const Eigen::Vector3d& start_normal)
    : radius_(std::move(radius)) {
  if (axis.size() < 2) throw std::invalid_argument("GeneralizedCylinder: axis needs >= 2 points");
  if (radius_.empty()) throw std::invalid_argument("GeneralizedCylinder: empty radius profile");
  if (radius_.size() == 1) radius_.push_back(radius_[0]);

  // Dense samples of the spline; end points are mirrored to give end tangents.
  const size_t n = axis.size();
  std::vector<Eigen::Vector3d> ext;
  ext.push_back(2 * axis[0] - axis[1]);
  ext.insert(ext.end(), axis.begin(), axis.end());
  ext.push_back(2 * axis[n - 1] - axis[n - 2]);
  const int per_segment = 128;
  std::vector<Eigen::Vector3d> pts;
  for (size_t seg = 0; seg + 1 < n; ++seg)
    for (int k = 0; k < per_segment; ++k)
      pts.push_back(catmull_rom(ext[seg], ext[seg + 1], ext[seg + 2], ext[seg + 3], double(k) / per_segment));
  pts.push_back(axis.back());

  samples_.resize(pts.size());
  arc_.assign(pts.size(), 0.0);
  for (size_t i = 0; i < pts.size(); ++i) {
    samples_[i].p = pts[i];
    const Eigen::Vector3d d = (i + 1 < pts.size()) ? pts[i + 1] - pts[i] : pts[i] - pts[i - 1];
    samples_[i].t = d.normalized();
    if (i > 0) arc_[i] = arc_[i - 1] + (pts[i] - pts[i - 1]).norm();
  }
  // Initial normal: requested direction, else any direction perpendicular to the tangent.
  Eigen::Vector3d t0 = samples_[0].t;
  Eigen::Vector3d n0 = start_normal - start_normal.dot(t0) * t0;
  if (n0.norm() < 1e-8) {
    n0 = std::abs(t0.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ();
    n0 = (n0 - n0.dot(t0) * t0);
  }
  samples_[0].n = n0.normalized();
  // Rotation-minimizing frames by double reflection (Wang, Jüttler, Zheng, Liu 2008).
  for (size_t i = 0; i + 1 < samples_.size(); ++i) {
    const Eigen::Vector3d v1 = samples_[i + 1].p - samples_[i].p;
    const double c1 = v1.squaredNorm();
    if (c1 < 1e-20) {
      samples_[i + 1].n = samples_[i].n;
      continue;
    }
    const Eigen::Vector3d rL = samples_[i].n - (2 / c1) * v1.dot(samples_[i].n) * v1;
    const Eigen::Vector3d tL = samples_[i].t - (2 / c1) * v1.dot(samples_[i].t) * v1;
    const Eigen::Vector3d v2 = samples_[i + 1].t - tL;
    const double c2 = v2.squaredNorm();
    Eigen::Vector3d r = c2 < 1e-20 ? rL : Eigen::Vector3d(rL - (2 / c2) * v2.dot(rL) * v2);
    r -= r.dot(samples_[i + 1].t) * samples_[i + 1].t;
    samples_[i + 1].n = r.normalized();
  }
}

void GeneralizedCylinder::locate(double s, size_t& i, double& f) const {
  const double target = std::clamp(s, 0.0, 1.0) * length();
  auto it = std::upper_bound(arc_.begin(), arc_.end(), target);
  i = std::min<size_t>(std::max<ptrdiff_t>(0, (it - arc_.begin()) - 1), arc_.size() - 2);
  const double seg = arc_[i + 1] - arc_[i];
  f = seg > 0 ? std::clamp((target - arc_[i]) / seg, 0.0, 1.0) : 0.0;
}

double GeneralizedCylinder::radius(double s, double theta) const {
  const double x = std::clamp(s, 0.0, 1.0) * double(radius_.size() - 1);
  const size_t i = std::min<size_t>(size_t(x), radius_.size() - 2);
  const double f = x - double(i);
  const double r = radius_[i] * (1 - f) + radius_[i + 1] * f;
  return modulation_ ? r * (1.0 + modulation_(s, theta)) : r;
}

Eigen::Vector3d GeneralizedCylinder::axis_point(double s) const {
  size_t i;
  double f;
  locate(s, i, f);
  return samples_[i].p * (1 - f) + samples_[i + 1].p * f;
}

Eigen::Matrix3d GeneralizedCylinder::frame(double s) const {
  size_t i;
  double f;
  locate(s, i, f);
  const Eigen::Vector3d t = (samples_[i].t * (1 - f) + samples_[i + 1].t * f).normalized();
  Eigen::Vector3d n = samples_[i].n * (1 - f) + samples_[i + 1].n * f;
  n = (n - n.dot(t) * t).normalized();
  Eigen::Matrix3d m;
  m.col(0) = t;
  m.col(1) = n;
  m.col(2) = t.cross(n);
  return m;
}

Eigen::Vector3d GeneralizedCylinder::position(double s, double theta) const {
  const Eigen::Matrix3d f = frame(s);
  return axis_point(s) + radius(s, theta) * (std::cos(theta) * f.col(1) + std::sin(theta) * f.col(2));
}

Eigen::Vector3d GeneralizedCylinder::normal(double s, double theta) const {
  // Outward normal of a tube whose radius changes along the axis: the radial direction tilted
  // back along the tangent by the slope dr/dL (exact for a straight axis).
  const Eigen::Matrix3d f = frame(s);
  const Eigen::Vector3d radial = std::cos(theta) * f.col(1) + std::sin(theta) * f.col(2);
  const double h = 1e-4;
  const double s0 = std::max(0.0, s - h), s1 = std::min(1.0, s + h);
  const double slope = (radius(s1, theta) - radius(s0, theta)) / ((s1 - s0) * length());
  return (radial - slope * f.col(0)).normalized();
}

}  // namespace phellem::bark

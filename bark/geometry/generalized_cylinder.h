// GeneralizedCylinder: a tube around a smooth spline axis with a radius profile r(s, θ).
// Lefebvre & Neyret 2002, sec. 6 ("mapped bark"): strips live on such cylinders, in the
// (s, θ) parameter space, s ∈ [0, 1] along the axis (arc length), θ ∈ [0, 2π) around it.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace phellem::bark {

class GeneralizedCylinder {
 public:
  // axis: #A×3 control points (A ≥ 2), interpolated by a centripetal Catmull-Rom spline;
  // radius: #R radii (R ≥ 1), equally spaced in normalized arc length, linearly interpolated.
  // `start_normal`, if non-zero, fixes the direction of θ = 0 at s = 0 (projected).
  GeneralizedCylinder(const std::vector<Eigen::Vector3d>& axis, std::vector<double> radius,
                      const Eigen::Vector3d& start_normal = Eigen::Vector3d::Zero());

  double length() const { return arc_.back(); }
  double radius(double s, double theta) const;
  Eigen::Vector3d axis_point(double s) const;
  // Rotation-minimizing frame at s (Wang et al. 2008, double reflection): columns are
  // tangent, normal (θ = 0), binormal (θ = π/2).
  Eigen::Matrix3d frame(double s) const;
  // Surface point and outward unit normal of the undisplaced surface.
  Eigen::Vector3d position(double s, double theta) const;
  Eigen::Vector3d normal(double s, double theta) const;

  // Optional angular modulation r(s, θ) = r(s) * (1 + modulation(s, θ)).
  void set_radius_modulation(std::function<double(double, double)> m) { modulation_ = std::move(m); }

 private:
  struct Sample {
    Eigen::Vector3d p, t, n;  // point, tangent, normal of the RMF
  };
  void locate(double s, size_t& i, double& f) const;
  std::vector<Sample> samples_;
  std::vector<double> arc_;  // cumulative arc length at each sample
  std::vector<double> radius_;
  std::function<double(double, double)> modulation_;
};

}  // namespace phellem::bark

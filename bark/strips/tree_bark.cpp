#include "bark/strips/tree_bark.h"

#include <algorithm>
#include <cmath>

namespace phellem::bark {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Closest point of the cylinder's surface to p, searched from arc length s0 (m): the axis
// parameter by a few projection steps, then the angle in the local frame. Returns the signed
// distance of p from the surface (positive outside); beyond an end of the axis the distance
// includes the overshoot along it.
double surface_coords(const GeneralizedCylinder& c, const Eigen::Vector3d& p, double s0, double* s_out, double* theta_out) {
  const double L = c.length();
  double s = std::clamp(s0, 0.0, L);
  for (int it = 0; it < 6; ++it) {
    const Eigen::Matrix3d f = c.frame(s / L);
    s = std::clamp(s + (p - c.axis_point(s / L)).dot(f.col(0)), 0.0, L);
  }
  const Eigen::Matrix3d f = c.frame(s / L);
  Eigen::Vector3d r = p - c.axis_point(s / L);
  const double axial = r.dot(f.col(0));  // non-zero only beyond an end of the axis
  r -= f.col(0) * axial;
  double theta = std::atan2(r.dot(f.col(2)), r.dot(f.col(1)));
  if (theta < 0) theta += kTwoPi;
  *s_out = s;
  *theta_out = theta;
  const double radial = r.norm() - c.radius(s / L, theta);
  return std::copysign(std::hypot(radial, axial), radial);
}

size_t strip_at(const StripModel& m, double s) { return m.strip_coords(s, 0.0).first; }

}  // namespace

TreeStripBark::TreeStripBark(std::vector<TreeCylinder> cylinders, const StripParams& params) : cylinders_(std::move(cylinders)) {
  for (size_t k = 0; k < cylinders_.size(); ++k) {
    StripParams p = params;
    // Every limb is its own instance of the bark; scripted fractures are placed on the trunk.
    p.seed = params.seed ^ (uint64_t(k) * 0x9e3779b97f4a7c15ULL);
    if (k > 0) p.scripted.clear();
    models_.push_back(std::make_unique<StripModel>(oriented_domain(*cylinders_[k].cylinder, p), p));
  }
  // Horizontal fractures run around each limb and end there: no junction transfer.
  if (params.orientation == FractureOrientation::Horizontal) return;
  for (size_t k = 0; k < cylinders_.size(); ++k) {
    const TreeCylinder& c = cylinders_[k];
    if (c.parent < 0) continue;
    const GeneralizedCylinder& P = *cylinders_[size_t(c.parent)].cylinder;
    const GeneralizedCylinder& C = *c.cylinder;
    const double cos_a = std::abs(P.frame(c.attach).col(0).dot(C.frame(0).col(0)));
    const double sin_a = std::max(0.2, std::sqrt(std::max(0.0, 1 - cos_a * cos_a)));
    double rp = 0, rc = 0;
    for (int i = 0; i < 8; ++i) {
      rp = std::max(rp, P.radius(c.attach, kTwoPi * i / 8));
      rc = std::max(rc, C.radius(0, kTwoPi * i / 8));
    }
    const StripModel& pm = *models_[size_t(c.parent)];
    const StripModel& cm = *models_[k];
    const double wp = pm.domain().strip_width, wc = cm.domain().strip_width;
    const double sp = c.attach * P.length(), half = rc / sin_a + 2 * wp;
    Junction j;
    j.parent = c.parent;
    j.child = int(k);
    j.parent_first = strip_at(pm, sp - half);
    j.parent_last = strip_at(pm, sp + half) + 1;
    j.child_last = strip_at(cm, (rp + rc) / sin_a + 2 * wc) + 1;
    junctions_.push_back(std::move(j));
  }
}

void TreeStripBark::transfer(Junction& j, bool parent_to_child) {
  const int from = parent_to_child ? j.parent : j.child, to = parent_to_child ? j.child : j.parent;
  const StripModel& src = *models_[size_t(from)];
  StripModel& dst = *models_[size_t(to)];
  const GeneralizedCylinder& A = *cylinders_[size_t(from)].cylinder;
  const GeneralizedCylinder& B = *cylinders_[size_t(to)].cylinder;
  const double tol = 1.5 * std::max(src.domain().strip_width, dst.domain().strip_width);
  const double s_guess = parent_to_child ? 0.0 : cylinders_[size_t(j.child)].attach * B.length();
  std::set<int32_t>& sent = parent_to_child ? j.sent_to_child : j.sent_to_parent;
  const size_t first = parent_to_child ? j.parent_first : 0, last = parent_to_child ? j.parent_last : j.child_last;
  for (const FractureTip& tip : src.sharp_tips(first, last)) {
    if (sent.count(tip.root)) continue;
    const double s_tip = src.domain().strips[tip.strip].s;
    const Eigen::Vector3d p = A.position(s_tip / A.length(), tip.theta);
    double s, theta;
    if (std::abs(surface_coords(B, p, s_guess, &s, &theta)) > tol) continue;
    // A fracture that itself came across here must not bounce back.
    bool echo = false;
    for (const JunctionCrossing& c : crossings_)
      echo = echo || (std::min(c.from, c.to) == std::min(from, to) && std::max(c.from, c.to) == std::max(from, to) &&
                      std::min((c.at_from - p).norm(), (c.at_to - p).norm()) < 2 * tol);
    if (echo) continue;
    sent.insert(tip.root);
    const size_t strip = strip_at(dst, s);
    dst.queue_arrival(strip, theta);
    crossings_.push_back({from, to, p, B.position(dst.domain().strips[strip].s / B.length(), theta), src.steps_done()});
  }
}

void TreeStripBark::step() {
  for (auto& m : models_) m->step();
  for (Junction& j : junctions_) {
    transfer(j, true);
    transfer(j, false);
  }
}

void TreeStripBark::settle() {
  for (auto& m : models_) m->settle();
}

void TreeStripBark::run(const std::function<void(int, int)>& progress) {
  if (models_.empty()) return;
  const int total = models_[0]->steps_total();
  while (models_[0]->steps_done() < total) {
    step();
    if (progress) progress(models_[0]->steps_done(), total);
  }
}

}  // namespace phellem::bark

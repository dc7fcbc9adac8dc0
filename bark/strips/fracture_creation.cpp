// Fracture creation and refracture (Lefebvre & Neyret 2002, sec. 3.2.3 and Figure 9).
#include <algorithm>
#include <cmath>

#include "bark/strips/strip_equilibrium.h"
#include "bark/strips/strip_model.h"

namespace phellem::bark {

namespace {
constexpr double kTwoPi = 6.283185307179586;
// No piece shorter than this fraction of element_length is made (the model's resolution):
// it bounds the work of one step and keeps element stiffness R·l_ref/l0 at most 20 R, so that
// position round-off stays far below the forces.
constexpr double kMinPiece = 0.05;
}  // namespace

bool StripModel::break_element(size_t j, size_t i, double f, int32_t* fe_out, int step) {
  // The fracture element ends up at index i + 1 (callers rely on it).
  // Figure 6: a split element of stiffness K becomes pieces f·l0 and (1 − f)·l0 of stiffness
  // K/f and K/(1 − f) (still K in series); a zero-rest-length fracture element opens between.
  Strip& s = strips_[j];
  const Element e = s.elements[i];
  if (e.kind != ElementKind::Epidermis || e.rest < 2 * kMinPiece * params_.element_length) return false;
  f = std::clamp(f, kMinPiece * params_.element_length / e.rest, 1.0 - kMinPiece * params_.element_length / e.rest);
  const double xb = s.x[i] + f * s.length(i);
  Element left = e, right = e, frac;
  left.rest = f * e.rest;
  left.stiffness = e.stiffness / f;
  right.rest = (1 - f) * e.rest;
  right.stiffness = e.stiffness / (1 - f);
  // Material coordinate (UV0) runs over the original epidermis, E0 long.
  ElementCold right_cold = s.cold[i];
  right_cold.material += e.level == 0 ? f * e.rest / epidermis0_[j] : 0.0;
  frac.kind = ElementKind::Fracture;
  frac.level = e.level;
  frac.rest = 0;
  frac.stiffness = params_.fracture_stiffness_at(0);
  frac.fracture = int32_t(s.fractures.size());
  FractureElement fe;
  fe.birth = step;
  fe.uv0 = right_cold.material - std::floor(right_cold.material);
  s.fractures.push_back(fe);
  s.elements[i] = left;
  s.elements.insert(s.elements.begin() + long(i) + 1, {frac, right});
  s.cold.insert(s.cold.begin() + long(i) + 1, {ElementCold{right_cold.material, 1.0}, right_cold});
  s.x.insert(s.x.begin() + long(i) + 1, {xb, xb});
  s.anchor.insert(s.anchor.begin() + long(i) + 1, {xb, xb});
  const bool eliminated = factors_[j].valid;
  // Not the last element of a cyclic strip, nor either end element of an open one (whose end
  // nodes are fixed).
  const bool inside = i + 3 < s.size() && (s.cyclic || i > 0);
  if (inside && params_.attachment > 0) {
    // Only nodes i..i+3 change: each holds the shares of the elements either side (the sums
    // update_attachment makes).
    s.attach.insert(s.attach.begin() + long(i) + 1, {0.0, 0.0});
    for (size_t node = i; node <= i + 3; ++node)
      s.attach[node] = attachment_share(s, node == 0 ? s.size() - 1 : node - 1) + attachment_share(s, node);
  } else {
    update_attachment(j);
  }
  // Rows before node i of the eliminated matrix are unchanged (elements and attachment before
  // element i are), unless the break is at either end of a cyclic strip (rows 0 and n-1 hold
  // its corners); an open strip's row r is node r + 1.
  factors_[j].valid = false;
  factors_[j].kept = eliminated && inside && i > 0 ? (s.cyclic ? i : i - 1) : 0;
  solve(j);
  ++breaks_[j];
  for (FreeEnd& t : tips_[j])
    if (size_t(t.element) > i) t.element += 2;
  tips_[j].push_back({frac.fracture, int32_t(i) + 1});
  touched_[j] = 1;
  for (int32_t& k : element_of_[j])
    if (size_t(k) > i) k += 2;
  element_of_[j].push_back(int32_t(i) + 1);
  if (fe_out) *fe_out = frac.fracture;
  return true;
}

void StripModel::break_strip(size_t j, int step) {
  Strip& s = strips_[j];
  StreamRng rng(params_.seed, j, uint64_t(step));
  // Scripted fractures (the paper's interactive picking) of this step on this strip.
  for (const ScriptedFracture& sf : params_.scripted) {
    if (sf.step != step) continue;
    const auto [strip, theta] = strip_coords(sf.s, sf.theta);
    if (strip == j) scripted_[j] += trigger_at(j, theta, nullptr, step) ? 1 : 0;
  }
  for (double theta : arrivals_[j]) arrived_[j] += trigger_at(j, theta, nullptr, step) ? 1 : 0;
  arrivals_[j].clear();
  if (!over_[j] && scripted_[j] == 0 && arrived_[j] == 0) return;  // nothing exceeded its threshold after growth
  // Figure 8: while an element obeys the criterion L / l0 > S_i, break the most strained one
  // at its weakest point and solve again. S above its lower bound (validated) makes every
  // break relax the element; the cap only guards against floating-point pathologies.
  const long long cap = 4 * (long long)s.size() + 16;
  for (long long iter = 0;; ++iter) {
    if (iter == cap) {
      ++capped_[j];
      break;
    }
    double worst = 1.0;
    size_t at = s.size();
    for (size_t i = 0; i < s.size(); ++i) {
      const Element& e = s.elements[i];
      if (e.kind != ElementKind::Epidermis || e.rest < 2 * kMinPiece * params_.element_length) continue;
      const double r = s.length(i) / (e.rest * e.threshold);
      if (r > worst) {
        worst = r;
        at = i;
      }
    }
    if (at == s.size()) break;
    // Fracture location: jitter around the element's middle; with a weakness map, the
    // weakest of a few jittered candidates.
    const double spread = params_.location_jitter;
    double f = 0.5 + 0.5 * spread * rng.symmetric();
    if (!params_.weakness.empty()) {
      double best = -1;
      for (int c = 0; c < 4; ++c) {
        const double fc = 0.5 + 0.5 * spread * rng.symmetric();
        const double th = theta_of(j, s.x[at] + fc * s.length(at));
        const Eigen::Vector2d uv = surface_uv(j, th);
        const double w = params_.weakness.sample(uv.x(), uv.y());
        if (w > best) {
          best = w;
          f = fc;
        }
      }
    }
    if (!break_element(j, at, f, nullptr, step)) break;
  }
}

bool StripModel::trigger(size_t j, double theta, int32_t* fe_out) { return trigger_at(j, theta, fe_out, step_); }

bool StripModel::trigger_at(size_t j, double theta, int32_t* fe_out, int step) {
  Strip& s = strips_[j];
  const double x = x_of(j, theta);
  const size_t i = element_at(j, x);
  if (s.elements[i].kind != ElementKind::Epidermis) return false;
  double off = x - s.x[i];
  if (s.cyclic) off -= std::floor(off / s.circumference) * s.circumference;
  const double L = s.length(i);
  return break_element(j, i, L > 0 ? off / L : 0.5, fe_out, step);
}

void StripModel::assign_new_fracture_ids(size_t j, Sweep& sw) {
  // In sweep order within the half: ids do not depend on the thread count.
  Strip& s = strips_[j];
  for (FractureElement& fe : s.fractures)
    if (fe.id < 0) fe.id = sw.make_id();
  for (size_t i = 0; i < s.size(); ++i) {
    Element& e = s.elements[i];
    if (e.kind != ElementKind::Fracture) continue;
    // A break not yet given an id is a new fracture of one element. (Elements that
    // propagation made carry the id of the fracture they continue and were counted then;
    // that id need not be a root, so its count entry says nothing.)
    const bool fresh = e.id < 0;
    e.id = s.fractures[size_t(e.fracture)].id;
    if (fresh) {
      sw.count[size_t(e.id)] = 1;
      sw.width[size_t(e.id)] = s.length(i);
      born_[j].emplace_back(e.id, s.length(i));
    }
  }
}

OpeningMode StripModel::draw_opening_mode(int32_t id) const {
  // sec. 3.3: the mix of opening modes, drawn per fracture id.
  const Eigen::Vector3d& w = params_.opening_mix;
  StreamRng rng(params_.seed ^ 0x6f70656eULL, uint64_t(id), 0);
  const double u = rng.uniform() * w.sum();
  return u < w[0] ? OpeningMode::Axis : u < w[0] + w[1] ? OpeningMode::OneSide : OpeningMode::Both;
}

void StripModel::refracture(size_t j, int step) {
  // Figure 9 / 2001 sec. 4.1: wide old fracture surface hardens into softer bark of the next
  // level, where new fractures then appear.
  if (params_.refracture_width <= 0) return;
  Strip& s = strips_[j];
  StreamRng rng(params_.seed ^ 0x72656672ULL, j, uint64_t(step));
  bool changed = false;
  for (size_t i = 0; i < s.size(); ++i) {
    Element& e = s.elements[i];
    if (e.kind != ElementKind::Fracture || s.length(i) <= params_.refracture_width) continue;
    s.fractures[size_t(e.fracture)].active = false;
    const double theta = theta_of(j, s.x[i] + 0.5 * s.length(i));
    e.kind = ElementKind::Epidermis;
    e.level = uint8_t(std::min(255, e.level + 1));
    e.rest = s.length(i);
    e.stiffness = epidermis_stiffness(j, theta, e.rest, e.level);
    s.cold[i].width_factor = width_factor(j, theta);
    e.threshold = jittered_threshold(j, theta, rng);
    ++hardened_[j];
    changed = true;
  }
  if (changed) update_attachment(j);
}

}  // namespace phellem::bark

// One strip's share of a growth step (Lefebvre & Neyret 2002, Figure 8): the previous step's
// plasticity, growth of the substrate, the new equilibrium (sec. 5.1), and the scan that tells
// the sweep whether the strip must break and which fracture ends may propagate.
//
// The common case — a cyclic strip on a homogeneously growing cylinder whose stiffnesses did
// not change since its matrix was eliminated — is done in three passes over the elements
// instead of six; it computes exactly what the general path (plasticity, grow_strip, solve,
// scan_strip) computes, in the same order, so the bits are the same.
#include <algorithm>
#include <initializer_list>

#include "bark/strips/strip_equilibrium.h"
#include "bark/strips/strip_model.h"

namespace phellem::bark {

namespace {
constexpr size_t kAhead = 16;  // elements fetched ahead in the first pass
}  // namespace

void StripModel::advance_strip(size_t j, int grower, int step, bool count_widths) {
  // By fracture id: roots are found in measure_fractures (the sweep may merge meanwhile).
  InglisSums* sums = count_widths ? &sums_[grower] : nullptr;
  if (pending_[j]) {
    refracture(j, step - 1);  // hardening changes elements, and then invalidates the factor
    const Strip& s = strips_[j];
    if (s.cyclic && s.size() >= 3 && factors_[j].valid && domain_.strips[j].exponent.empty() &&
        params_.fracture_stiffness.size() == 1 && !check_) {
      advance_settled(j, sums);
      pending_[j] = 0;
      return;
    }
  }
  grow_strip(j, sums);  // the previous step's plasticity, if owed, then growth
  solve(j);
  scan_strip(j);
}

PHELLEM_FMA_CLONES void StripModel::advance_settled(size_t j, InglisSums* sums) {
  Strip& s = strips_[j];
  const EquilibriumFactor& f = factors_[j];
  const size_t n = s.size();
  // Each array of the strip is an allocation of its own, last touched a step ago: ask for
  // the first lines of all of them at once (the loop below fetches ahead from there), and
  // for the free-end list pass 3 writes.
  for (const double* v : std::initializer_list<const double*>{s.x.data(), s.anchor.data(), f.inv.data(), f.u.data()})
    __builtin_prefetch(v);
  for (size_t i = 0; i < std::min<size_t>(n, 4); ++i) __builtin_prefetch(&s.elements[i]);
  __builtin_prefetch(&s.elements[n - 1]);
  __builtin_prefetch(&s.x[n - 1]);
  __builtin_prefetch(tips_[j].data(), 1);
  const double g = params_.growth_rate;
  const double c_old = s.circumference;
  const double c_new = scale_metric(j, g);
  double* x = s.x.data();
  double* a = s.anchor.data();
  Element* e = s.elements.data();
  thread_local std::vector<double> rhs;
  rhs.resize(n);
  double* r = rhs.data();

  // Pass 1, plasticity (sec. 5.1): the attachment springs restart at zero length at the grown
  // substrate (a = g x) and new material fills the fractures, whose rest length becomes their
  // width; with it, the right-hand side (differences of the anchor tensions
  // T_i = K_i (a_{i+1} - a_i - l0_i)) and the forward elimination.
  if (e[n - 1].kind == ElementKind::Fracture) e[n - 1].rest = std::max(0.0, x[0] + c_old - x[n - 1]);
  const double a_last = x[n - 1] * g;
  const double t_last = e[n - 1].stiffness * (x[0] * g + c_new - a_last - e[n - 1].rest);
  const double* inv = f.inv.data();
  double prev = t_last, p = 0;
  double a_next = x[0] * g;
  const double* u = f.u.data();
  for (size_t i = 0; i + 1 < n; ++i) {
    // The elimination chain leaves the loads time, but not a memory latency's worth: fetch
    // ahead what this pass and the next two read (the strip was last touched a step ago).
    if (i + kAhead < n) {
      __builtin_prefetch(&e[i + kAhead]);
      if ((i & 7) == 0) {  // eight doubles to a cache line
        __builtin_prefetch(&x[i + kAhead]);
        __builtin_prefetch(&inv[i + kAhead]);
        __builtin_prefetch(&a[i + kAhead], 1);
        __builtin_prefetch(&u[i + kAhead]);
      }
    }
    const double a_i = a_next;
    a_next = x[i + 1] * g;
    a[i] = a_i;
    // A select, not a branch: which elements are fractures follows no pattern a branch
    // predictor could learn (an epidermis element's rest length is stored back unchanged).
    const double width = std::max(0.0, x[i + 1] - x[i]);
    e[i].rest = e[i].kind == ElementKind::Fracture ? width : e[i].rest;
    const double t = e[i].stiffness * (a_next - a_i - e[i].rest);
    r[i] = p = i == 0 ? (t - prev) * inv[0] : forward_row(t - prev, e[i - 1].stiffness, inv[i], p);
    prev = t;
  }
  a[n - 1] = a_last;
  r[n - 1] = p = forward_row(t_last - prev, e[n - 2].stiffness, inv[n - 1], p);

  // Pass 2: back substitution.
  for (size_t i = n - 1; i-- > 0;) r[i] = p = back_row(r[i], -e[i].stiffness * inv[i], p);

  // Pass 3: positions (the Sherman–Morrison correction of the cyclic system) and the scan: is
  // any epidermis element beyond its threshold, which fracture elements have a free end, and
  // the fracture widths (their rest lengths since pass 1) for the Inglis ratios.
  const double beta = -e[n - 1].stiffness;
  const double fact = (r[0] + beta * r[n - 1] / f.gamma) / f.denominator;
  std::vector<FreeEnd>& tips = tips_[j];
  tips.clear();
  bool over = false;
  auto scan = [&](size_t i, double length) {
    if (e[i].kind == ElementKind::Epidermis)
      over |= length > e[i].rest * e[i].threshold;
    else {
      if (e[i].free_end()) tips.push_back(free_end(j, e[i], i, x[i], length));
      if (sums && e[i].id >= 0) sums->add(e[i].id, e[i].rest);  // (a break not yet given an id is counted at birth)
    }
  };
  x[0] = a[0] + (r[0] - fact * u[0]);
  for (size_t i = 1; i < n; ++i) {
    x[i] = a[i] + (r[i] - fact * u[i]);
    scan(i - 1, x[i] - x[i - 1]);
  }
  scan(n - 1, x[0] + c_new - x[n - 1]);
  over_[j] = over;
  touched_[j] = 0;
}

}  // namespace phellem::bark

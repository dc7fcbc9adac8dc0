#include "bark/strips/strip_model.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <sstream>
#include <thread>

#include "bark/strips/strip_equilibrium.h"

namespace phellem::bark {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}

StripModel::StripModel(StripDomain domain, StripParams params) : domain_(std::move(domain)), params_(std::move(params)) {
  if (auto e = validate(params_)) throw *e;
  const size_t n = domain_.strips.size();
  // Elements at the final size, before fractures add theirs (about as many again): refused
  // beyond a budget rather than exhausting memory.
  double final_elements = 0;
  for (const StripMetric& m : domain_.strips)
    for (double b : m.bin_length) final_elements += b / params_.element_length;
  if (!(final_elements <= kMaxElements)) {
    std::ostringstream m;
    m << "must be at least " << params_.element_length * final_elements / kMaxElements << " m here: " << n
      << " strips of this bark would hold " << final_elements << " elements of " << params_.element_length
      << " m at their final size, more than the " << kMaxElements << " a simulation allows";
    throw StripParamError{"element_length", m.str()};
  }
  strips_.resize(n);
  cum_.resize(n);
  epidermis0_.resize(n);
  breaks_.assign(n, 0);
  scripted_.assign(n, 0);
  arrived_.assign(n, 0);
  arrivals_.resize(n);
  hardened_.assign(n, 0);
  capped_.assign(n, 0);
  residual_.assign(n, 0.0);
  over_.assign(n, 0);
  pending_.assign(n, 0);
  uniform_.assign(n, 0);
  tips_.resize(n);
  touched_.assign(n, 0);
  element_of_.resize(n);
  born_.resize(n);
  factors_.resize(n);
  strip_totals_.resize(n);
  owner_.assign(n, 0);
  tbb::parallel_for(size_t(0), n, [&](size_t j) { init_strip(j); });
  // sec. 3.2.3: check S against the softest element actually built (strips narrower than
  // nominal on the concave side of bent limbs are softer).
  double softest = 1e300;
  for (const Strip& s : strips_)
    for (const Element& e : s.elements) softest = std::min(softest, e.stiffness);
  const ThresholdRange r = valid_threshold_range(params_, softest);
  if (!(params_.S() > r.low)) throw threshold_error(params_, r, softest);
}

void StripModel::solve(size_t j) {
  solve_equilibrium(strips_[j], &factors_[j]);
  if (check_) residual_[j] = std::max(residual_[j], equilibrium_residual(strips_[j]));
}

double StripModel::max_residual() const {
  double m = 0;
  for (double r : residual_) m = std::max(m, r);
  return m;
}

double StripModel::scale_at_step(int t) const { return std::pow(params_.growth_rate, -double(params_.steps - t)); }

double StripModel::width_factor(size_t j, double theta) const {
  const auto& w = domain_.strips[j].width;
  const int m = int(w.size());
  double u = theta / kTwoPi;
  u -= std::floor(u);
  return w[size_t(std::min(m - 1, int(u * m)))];
}

double StripModel::epidermis_stiffness(size_t j, double theta, double rest, uint8_t level) const {
  // sec. 5.3: K = R w / l0, here relative to the reference element (nominal width,
  // element_length), so that K = R for it. Hardened fracture surface is softer (Figure 9).
  const double R = params_.stiffness * (level > 0 ? params_.refracture_stiffness : 1.0);
  return R * width_factor(j, theta) * params_.element_length / rest;
}

double StripModel::jittered_threshold(size_t j, double theta, StreamRng& rng) const {
  // sec. 3.2.3: jittered threshold; the weakness map lowers it where the user painted.
  double excess = (params_.S() - 1.0) * (1.0 + params_.threshold_noise * rng.symmetric());
  if (!params_.weakness.empty()) {
    const Eigen::Vector2d uv = surface_uv(j, theta);
    excess *= 1.0 - params_.weakness_strength * params_.weakness.sample(uv.x(), uv.y());
  }
  // Our extension (issue 22): a smooth procedural weakness, irregular fracture spacing.
  if (params_.weakness_noise > 0) excess *= 1.0 + params_.weakness_noise * smooth_noise(j, theta, params_.weakness_noise_size, 0x7765616bULL);
  return 1.0 + excess;
}

std::pair<size_t, double> StripModel::strip_coords(double s, double theta) const {
  const long n = long(strips_.size());
  if (domain_.along_axis) {
    const double u = theta / kTwoPi - std::floor(theta / kTwoPi);
    return {size_t(std::clamp(long(u * double(n)), 0L, n - 1)), kTwoPi * s / domain_.axis_length};
  }
  return {size_t(std::clamp(long(std::floor(s / domain_.strip_width)), 0L, n - 1)), theta};
}

Eigen::Vector2d StripModel::surface_uv(size_t j, double theta) const {
  const double along = theta / kTwoPi, across = domain_.strips[j].s / domain_.length;
  return domain_.along_axis ? Eigen::Vector2d(across, along) : Eigen::Vector2d(along, across);
}

double StripModel::x_of(size_t j, double theta) const {
  // A uniform strip maps through its circumference alone (its cumulative table is not kept).
  if (uniform_[j]) return theta / kTwoPi * strips_[j].circumference;
  const auto& c = cum_[j];
  const int m = int(c.size()) - 1;
  const double turns = std::floor(theta / kTwoPi);
  const double u = (theta / kTwoPi - turns) * m;
  const int k = std::min(m - 1, int(u));
  return turns * c[size_t(m)] + c[size_t(k)] + (u - k) * (c[size_t(k) + 1] - c[size_t(k)]);
}

double StripModel::theta_of(size_t j, double x) const {
  if (uniform_[j]) return kTwoPi * (x / strips_[j].circumference);
  const auto& c = cum_[j];
  const int m = int(c.size()) - 1;
  const double C = c[size_t(m)];
  const double turns = std::floor(x / C);
  const double r = x - turns * C;
  // The bin with c[k] <= r < c[k + 1] (k <= m - 1): bins are nearly even, so start from the
  // proportional guess and walk.
  int k = std::clamp(int(r / C * m), 0, m - 1);
  while (k > 0 && c[size_t(k)] > r) --k;
  while (k < m - 1 && c[size_t(k) + 1] <= r) ++k;
  const double len = c[size_t(k) + 1] - c[size_t(k)];
  const double f = len > 0 ? (r - c[size_t(k)]) / len : 0.0;
  return kTwoPi * (turns + (k + f) / m);
}

size_t StripModel::element_at(size_t j, double x) const {
  const Strip& s = strips_[j];
  const long n = long(s.size());
  // The last node at or before x (0 if none): start from the proportional guess (the fraction
  // of the strip before x) and walk.
  double guess = 0;
  if (s.cyclic) {
    const double C = s.circumference, turns = (x - s.x[0]) / C, whole = std::floor(turns);
    x = s.x[0] + (x - s.x[0]) - whole * C;
    guess = turns - whole;
  } else if (const double span = s.x[size_t(n)] - s.x[0]; span > 0) {
    guess = (x - s.x[0]) / span;
  }
  long i = std::min(long(std::clamp(guess, 0.0, 1.0) * double(n)), n - 1);
  while (i > 0 && s.x[size_t(i)] > x) --i;
  while (i + 1 < n && s.x[size_t(i) + 1] <= x) ++i;
  return size_t(i);
}

void StripModel::init_strip(size_t j) {
  const StripMetric& m = domain_.strips[j];
  const int M = int(m.bin_length.size());
  auto& c = cum_[j];
  c.assign(size_t(M) + 1, 0.0);
  // A strip whose bins are all alike (a straight cylinder) maps θ ↔ x linearly.
  const auto [lo, hi] = std::minmax_element(m.bin_length.begin(), m.bin_length.end());
  uniform_[j] = m.exponent.empty() && M > 0 && *hi - *lo <= 1e-12 * *hi;
  const double g = std::log(params_.growth_rate) * params_.steps;
  for (int k = 0; k < M; ++k) {
    const double e = m.exponent.empty() ? 1.0 : m.exponent[size_t(k)];
    c[size_t(k) + 1] = c[size_t(k)] + m.bin_length[size_t(k)] * std::exp(-g * e);
  }
  Strip& s = strips_[j];
  s.cyclic = domain_.cyclic;
  s.width = domain_.strip_width;
  s.circumference = c.back();
  epidermis0_[j] = s.circumference;
  const int n = std::max(3, int(std::ceil(s.circumference / params_.element_length - 1e-9)));  // l0 <= element_length
  const double l = s.circumference / n;
  StreamRng rng(params_.seed, j, ~0ULL);
  s.elements.resize(size_t(n));
  s.cold.resize(size_t(n));
  s.x.resize(s.cyclic ? size_t(n) : size_t(n) + 1);
  for (int i = 0; i < n; ++i) {
    Element& e = s.elements[size_t(i)];
    const double theta = theta_of(j, (i + 0.5) * l);
    e.rest = l;
    e.stiffness = epidermis_stiffness(j, theta, l, 0);
    s.cold[size_t(i)].width_factor = width_factor(j, theta);
    e.threshold = jittered_threshold(j, theta, rng);
    s.cold[size_t(i)].material = double(i) / n;
    s.x[size_t(i)] = i * l;
  }
  if (!s.cyclic) s.x[size_t(n)] = s.circumference;
  s.anchor = s.x;
  update_attachment(j);
}

void StripModel::update_attachment(size_t j) {
  // sec. 5.1: zero-rest-length springs glue the epidermis to the substrate; each node holds
  // half of the epidermis on either side (fracture elements are not glued bark).
  Strip& s = strips_[j];
  const size_t n = s.size(), nodes = s.nodes();
  factors_[j].valid = false;  // called whenever elements change
  factors_[j].kept = 0;
  s.attach.assign(nodes, 0.0);
  if (params_.attachment <= 0) return;
  for (size_t i = 0; i < n; ++i) {
    const double a = attachment_share(s, i);
    s.attach[i] += a;
    s.attach[(i + 1) % nodes] += a;
  }
  if (!s.cyclic) s.attach.front() = s.attach.back() = 0;  // fixed ends
}

double StripModel::attachment_share(const Strip& s, size_t i) const {
  // Half of an epidermis element's springs (sec. 5.1), held by each of its two nodes.
  const Element& e = s.elements[i];
  return e.kind == ElementKind::Epidermis ? 0.5 * (params_.attachment / params_.element_length) * e.rest * s.cold[i].width_factor
                                          : 0.0;
}

void StripModel::settle() {
  // The end of the last step's Figure 8 for every strip that owes it (nothing has touched
  // them since), in strip order on this thread: it adds to the sweep's Inglis sums (one step's
  // worth of plasticity is not worth a second set).
  for (size_t j = 0; j < strips_.size(); ++j) {
    if (!pending_[j]) continue;
    refracture(j, step_ - 1);
    plasticity(j, &sums_[0]);
    pending_[j] = 0;
  }
  for (long long& h : hardened_) {
    stats_.refractured += h;
    h = 0;
  }
}

double StripModel::scale_metric(size_t j, double g) {
  // θ ∝ x on a uniform strip: its circumference is all there is (its table is not kept).
  Strip& s = strips_[j];
  if (uniform_[j]) {
    s.circumference *= g;
  } else {
    for (double& v : cum_[j]) v *= g;
    s.circumference = cum_[j].back();
  }
  return s.circumference;
}

void StripModel::grow_strip(size_t j, InglisSums* sums) {
  // The substrate grows from step t to t + 1 (shrinking strategy seen forwards, sec. 5.2): each
  // anchor keeps its substrate point θ. Stiffnesses and attachment are unchanged: plasticity
  // already gave the fracture elements K_f of their rest length.
  Strip& s = strips_[j];
  const StripMetric& m = domain_.strips[j];
  auto& c = cum_[j];
  if (m.exponent.empty()) {
    const double g = params_.growth_rate;
    if (pending_[j])
      plasticity(j, sums, g);  // in the old metric; the new anchors come out grown
    else
      for (double& a : s.anchor) a *= g;
    scale_metric(j, g);
  } else {
    if (pending_[j]) plasticity(j, sums);
    std::vector<double> theta(s.anchor.size());
    for (size_t i = 0; i < theta.size(); ++i) theta[i] = theta_of(j, s.anchor[i]);
    const double lg = std::log(params_.growth_rate);
    std::vector<double> next(c.size(), 0.0);
    for (size_t k = 0; k + 1 < c.size(); ++k) next[k + 1] = next[k] + (c[k + 1] - c[k]) * std::exp(lg * m.exponent[k]);
    c.swap(next);
    for (size_t i = 0; i < theta.size(); ++i) s.anchor[i] = x_of(j, theta[i]);
    s.circumference = c.back();
  }
  pending_[j] = 0;
  if (!s.cyclic) {  // the solve moves every free node; open strips keep their ends on the substrate
    s.x.front() = 0;
    s.x.back() = s.circumference;
  }
}

StripModel::FreeEnd StripModel::free_end(size_t j, const Element& e, size_t i, double left, double length) const {
  // θ as centre_theta() computes it from the same positions.
  return {e.fracture, int32_t(i), e.id, e.up < 0, e.down < 0, theta_of(j, left + 0.5 * length)};
}

void StripModel::scan_strip(size_t j) {
  // Which strips need the break loop, and the free ends propagation will look at.
  const Strip& s = strips_[j];
  const size_t n = s.size();
  std::vector<FreeEnd>& tips = tips_[j];
  tips.clear();
  bool over = false;
  const double* x = s.x.data();
  for (size_t i = 0; i < n; ++i) {
    const Element& e = s.elements[i];
    const double length = (i + 1 < n ? x[i + 1] : s.right(i)) - x[i];
    if (e.kind == ElementKind::Epidermis) {
      over |= length > e.rest * e.threshold;
    } else if (e.free_end()) {  // a fracture element is always active (hardening makes it epidermis)
      tips.push_back(free_end(j, e, i, x[i], length));
    }
  }
  touched_[j] = 0;
  over_[j] = over;
}

void StripModel::plasticity(size_t j, InglisSums* sums, double growth) {
  // Long-term plasticity (sec. 5.1): the attachment springs restart at zero length; new
  // material fills the fractures, whose rest length becomes their current width.
  // Also adds each fracture element's width to the grower's Inglis sums by fracture id.
  // `growth`: the next step's homogeneous growth applied to the new anchors in the same pass.
  Strip& s = strips_[j];
  const size_t n = s.size();
  s.anchor.resize(s.x.size());
  const bool constant_kf = params_.fracture_stiffness.size() == 1;
  bool refactor = false;
  const double* x = s.x.data();
  double* anchor = s.anchor.data();
  for (size_t i = 0; i < n; ++i) {
    anchor[i] = x[i] * growth;
    Element& e = s.elements[i];
    if (e.kind != ElementKind::Fracture) continue;
    e.rest = std::max(0.0, (i + 1 < n ? x[i + 1] : s.right(i)) - x[i]);
    if (!constant_kf) {
      const double k = params_.fracture_stiffness_at(e.rest);
      refactor |= k != e.stiffness;
      e.stiffness = k;
    }
    if (sums && e.id >= 0) sums->add(e.id, e.rest);  // (a break not yet given an id is counted at birth)
  }
  if (!s.cyclic) anchor[n] = x[n] * growth;
  if (refactor) factors_[j].valid = false;
}

void StripModel::prefetch_positions(size_t j) const {
  // The sweep is about to aim free ends at strip j, which the helper grew on the other core:
  // ask for its positions (where element_at() searches) all at once.
  const std::vector<double>& x = strips_[j].x;
  for (size_t i = 0; i < x.size(); i += 8) __builtin_prefetch(&x[i]);
}

void StripModel::step() {
  if (step_ >= params_.steps) return;
  const size_t n = strips_.size();
  exits_.clear();
  int steps = 1;
  if (domain_.wrap_s && n > 1) {
    sweep_step();
  } else {
    // Blocks start at multiples of kBlockSteps, whoever calls: the same blocks for a still and
    // for a growth sequence that stops between them.
    steps = std::min(kBlockSteps - step_ % kBlockSteps, params_.steps - step_);
    sweep_block(steps);
  }
  // Hardening and plasticity of the last step are applied to each strip when the next step
  // grows it (its data is then in cache), or by settle().
  std::fill(pending_.begin(), pending_.end(), char(1));
  measure_fractures();
  for (size_t j = 0; j < n; ++j) fold_counts(j);
  for (StripStats& t : strip_totals_) {
    stats_.created += t.created;
    stats_.scripted += t.scripted;
    stats_.arrived += t.arrived;
    stats_.refractured += t.refractured;
    stats_.max_breaks_per_strip_step = std::max(stats_.max_breaks_per_strip_step, t.max_breaks_per_strip_step);
    stats_.capped += t.capped;
    t = StripStats{};
  }
  step_ += steps;
  if (step_ == params_.steps) settle();
}

void StripModel::fold_counts(size_t j) {
  // One strip's counts of the step just ended on it, into its totals (each strip's are touched
  // by one thread at a time).
  StripStats& t = strip_totals_[j];
  t.created += breaks_[j];
  t.scripted += scripted_[j];
  t.arrived += arrived_[j];
  t.refractured += hardened_[j];
  t.max_breaks_per_strip_step = std::max(t.max_breaks_per_strip_step, breaks_[j]);
  t.capped += capped_[j];
  breaks_[j] = scripted_[j] = hardened_[j] = capped_[j] = arrived_[j] = 0;
}

void StripModel::start_sweep(Sweep& sw, int half, int halves) {
  sw.half = half;
  sw.skeleton = skeleton_;
  sw.count = fracture_count_;
  sw.width = fracture_width_;
  sw.count.resize(skeleton_.ids(), 0.0);
  sw.width.resize(skeleton_.ids(), 0.0);
  sw.base = int32_t(skeleton_.ids());
  sw.stride = halves;
  sw.made = 0;
  sw.merges.clear();
  sw.crossings.clear();
  sw.exits.clear();
  sw.propagated = sw.joined = sw.forked = 0;
}

void StripModel::join_sweeps(int halves) {
  // The halves' new fracture ids interleave (base + k·halves + half): make them all, unused
  // ones included, then every merge either half made (the components do not depend on the
  // order; the older id stays the root), then the crossings in order.
  int32_t made = 0;
  for (int h = 0; h < halves; ++h) made = std::max(made, sweeps_[h].made);
  skeleton_.extend(size_t(sweeps_[0].base) + size_t(made) * size_t(halves));
  for (size_t id = modes_.size(); id < skeleton_.ids(); ++id) modes_.push_back(draw_opening_mode(int32_t(id)));
  for (int h = 0; h < halves; ++h) {
    const Sweep& sw = sweeps_[h];
    for (const auto& [a, b] : sw.merges) stats_.merged += skeleton_.merge(a, b) ? 1 : 0;
    stats_.propagated += sw.propagated;
    stats_.joined += sw.joined;
    stats_.forked += sw.forked;
    exits_.insert(exits_.end(), sw.exits.begin(), sw.exits.end());
  }
  if (halves < 2) return;
  // The replay works on the joined skeleton itself; its Inglis measure is not consulted (a
  // crossing was sharp when its half listed it) and measure_fractures() redoes it after.
  Sweep& r = replay_;
  std::swap(r.skeleton, skeleton_);
  r.count.assign(r.skeleton.ids(), 0.0);
  r.width.assign(r.skeleton.ids(), 0.0);
  r.merges.clear();
  r.propagated = r.joined = r.forked = 0;
  for (int h = 0; h < halves; ++h)
    for (const Crossing& c : sweeps_[h].crossings) cross(c, r);
  std::swap(r.skeleton, skeleton_);
  stats_.merged += long(r.merges.size());
  stats_.propagated += r.propagated;
  stats_.joined += r.joined;
  stats_.forked += r.forked;
}

void StripModel::sweep_step() {
  // One step, the sweep alternating direction every step: for strips that wrap around (a
  // tileable sample, strips along the axis around a limb), where a block's wavefront would
  // meet itself. A strip is grown (after the previous step's hardening and plasticity, owed
  // since) and solved before the sweep reaches its neighbour, then broken and propagated from
  // in its turn. Growing a strip touches nothing but that strip, so a helper task grows
  // strips ahead of the sweep while this thread sweeps; whoever claims a strip first grows
  // it, so the result does not depend on the thread count (with one thread, the sweep grows
  // every strip itself).
  const size_t n = strips_.size();
  const int step = step_;
  const bool upward = step % 2 == 0;
  const bool wrap = domain_.wrap_s && n > 1;
  auto strip_at = [&](size_t k) { return upward ? k : n - 1 - k; };
  Sweep& sw = sweeps_[0];  // (owner_ stays all 0: a model that wraps never splits)
  start_sweep(sw, 0, 1);
  sw.step = step;
  const auto claimed = std::make_unique<std::atomic<char>[]>(n), grown = std::make_unique<std::atomic<char>[]>(n);
  // The flags are read before they are claimed: a read-modify-write takes the cache line from
  // the other core even when the strip is already taken.
  auto try_grow = [&](size_t k, int grower) {
    if (claimed[k].load(std::memory_order_relaxed) || claimed[k].exchange(1, std::memory_order_acq_rel)) return false;
    advance_strip(strip_at(k), grower, step, true);
    grown[k].store(1, std::memory_order_release);
    return true;
  };
  size_t ahead = 0;  // the sweep's look-ahead for strips to grow while it waits
  auto ensure_grown = [&](size_t k) {
    if (grown[k].load(std::memory_order_acquire) || try_grow(k, 0)) return;
    // The helper is on it: grow a strip further ahead meanwhile rather than idle.
    ahead = std::max(ahead, k + 1);
    while (!grown[k].load(std::memory_order_acquire)) {
      while (ahead < n && claimed[ahead].load(std::memory_order_relaxed)) ++ahead;
      if (ahead >= n || !try_grow(ahead, 0)) std::this_thread::yield();
    }
  };
  if (wrap) ensure_grown(n - 1);  // the first strip propagates into the last
  std::atomic<bool> stop{false};
  tbb::task_group helper;
  helper.run([&] {
    for (size_t k = 0; k < n && !stop.load(std::memory_order_relaxed); ++k) try_grow(k, 1);
  });
  for (size_t k = 0; k < n; ++k) {
    ensure_grown(k);
    if (k + 1 < n) {
      ensure_grown(k + 1);
      prefetch_positions(strip_at(k + 1));
    }
    const size_t j = strip_at(k);
    break_strip(j, step);
    if (breaks_[j] > 0) assign_new_fracture_ids(j, sw);
    propagate_from(j, sw);
  }
  stop.store(true, std::memory_order_relaxed);
  helper.wait();
  join_sweeps(1);
}

void StripModel::sweep_half(int half, size_t first, size_t count, int K) {
  // K steps of one half's strips (sweep positions [first, first + count), wrapping) as one
  // wavefront on this thread: step s reaches the half's strip q right after step s - 1 has
  // passed strip q + 2 (strip q is final for step s - 1 once step s - 1 has propagated from
  // q + 1, and step s then grows it, and q + 1, before propagating from q). A strip's K steps
  // are thus done while its data is still in this core's cache, instead of once per pass over
  // the whole trunk.
  constexpr long kLag = 2;
  Sweep& sw = sweeps_[half];
  const size_t n = strips_.size();
  const int base = step_;
  const bool upward = (base / kBlockSteps) % 2 == 0;
  auto strip_at = [&](long q) {
    const size_t p = (first + size_t(q)) % n;
    return upward ? p : n - 1 - p;
  };
  std::vector<int>& grown = grown_step_[half];
  grown.assign(count, base - 1);
  auto grow = [&](long q, int s) {
    if (grown[size_t(q)] >= base + s) return;
    const size_t j = strip_at(q);
    if (s > 0) {
      fold_counts(j);
      pending_[j] = 1;  // step s - 1's hardening and plasticity
    }
    // The Inglis sums are those of the block's last step (the widths measured at its end).
    const bool last = s == K - 1;
    if (last) born_[j].clear();  // births of earlier steps are in those sums now
    advance_strip(j, half, base + s, last);
    grown[size_t(q)] = base + s;
  };
  for (long w = 0; w < long(count) + kLag * (K - 1); ++w)
    for (int s = 0; s < K; ++s) {
      const long q = w - kLag * s;
      if (q < 0 || q >= long(count)) continue;
      grow(q, s);
      if (q + 1 < long(count)) grow(q + 1, s);
      const size_t j = strip_at(q);
      sw.step = base + s;
      break_strip(j, sw.step);
      if (breaks_[j] > 0) assign_new_fracture_ids(j, sw);
      propagate_from(j, sw);
    }
}

void StripModel::sweep_block(int K) {
  // K steps (Figure 8 each), every step sweeping in the same direction (the direction
  // alternates from block to block), split in two halves of consecutive strips, one per core:
  // each half sweeps its strips as a wavefront over the K steps with its own view of the
  // fracture bookkeeping (the block's start plus its own merges and new fractures), so the
  // halves share nothing while they run. A fracture reaching the other half waits for the
  // block's end, when the crossings are replayed in a fixed order; the boundary is drawn anew
  // for every block (from the seed), so no height of the trunk is special. Running the halves
  // one after the other gives the same bits. A model of few strips is swept whole.
  //
  // So is a block that starts while more than 1 strip in 20 is intact. Bark that has not
  // fractured yet is strained alike everywhere and breaks everywhere within a few steps (the
  // first wave: on the trunk of scenes/strips_fissured.json, half of the furrowed preset's
  // fractures appear in its first 20 steps). A sweep lets the first fractures run along the
  // axis and relieve the strips ahead of them; with a boundary between halves, both sides
  // would break on their own near it and the fractures would stop there, a horizontal seam of
  // fracture ends across the trunk (bench/strip_ends.cpp counts them: 47-54 ends in 3 strips
  // on the fissured trunk, against 5-9 for a whole sweep). Once every strip holds fractures,
  // breaks are rare and scattered and the halves meet no such wave.
  constexpr size_t kSplitStrips = 16;
  const size_t n = strips_.size();
  size_t intact = 0;
  for (const Strip& st : strips_) intact += st.fractures.empty();
  const int halves = n >= kSplitStrips && intact * 20 < n ? 2 : 1;
  const size_t first =
      halves == 2 ? size_t(StreamRng(params_.seed ^ 0x73706c6974ULL, 0, uint64_t(step_ / kBlockSteps)).uniform() * double(n)) % n
                  : 0;
  const size_t count0 = halves == 2 ? n / 2 : n;
  const bool upward = (step_ / kBlockSteps) % 2 == 0;
  for (size_t q = 0; q < n; ++q) {
    const size_t p = (first + q) % n;
    owner_[upward ? p : n - 1 - p] = q < count0 ? 0 : 1;
  }
  for (int h = 0; h < halves; ++h) start_sweep(sweeps_[h], h, halves);
  // The widths counted for the block's measure are those of its last step's growth: drop what
  // settle() summed since the last measure (the next measure would count those elements twice).
  if (K > 1)
    for (InglisSums& t : sums_) t.clear();
  if (halves == 2) {
#if defined(__SANITIZE_THREAD__)
    // ThreadSanitizer does not see TBB's synchronisation (libtbb is not instrumented): the
    // second half runs on a thread whose start and join it sees, so that what it reports
    // between the halves is real.
    std::thread second([&] { sweep_half(1, first + count0, n - count0, K); });
    sweep_half(0, first, count0, K);
    second.join();
#else
    tbb::parallel_invoke([&] { sweep_half(0, first, count0, K); }, [&] { sweep_half(1, first + count0, n - count0, K); });
#endif
  } else {
    sweep_half(0, first, count0, K);
  }
  join_sweeps(halves);
}

}  // namespace phellem::bark

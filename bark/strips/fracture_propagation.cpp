// Fracture propagation between strips (Lefebvre & Neyret 2002, sec. 3.2.4 and 5.3).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bark/strips/strip_equilibrium.h"
#include "bark/strips/strip_model.h"

namespace phellem::bark {

namespace {
constexpr double kTwoPi = 6.283185307179586;
constexpr double kPi = 3.141592653589793;
// Fractures this many elements either side of a tip's target are tested for influence.
constexpr size_t kInfluenceElements = 6;

double wrap_angle(double a) { return a - kTwoPi * std::floor((a + kPi) / kTwoPi); }  // to [-π, π)
}  // namespace

double StripModel::centre_theta(size_t j, size_t i) const {
  const Strip& s = strips_[j];
  return theta_of(j, s.x[i] + 0.5 * s.length(i));
}

void StripModel::measure_fractures() {
  // Each fracture's element count and summed width: its length is count × strip width, its
  // mean width the Inglis ratio's denominator (sec. 3.2.4: "we used the mean fracture width").
  // Measured at the end of a step from the sums plasticity made by fracture id as the step
  // grew each strip (the previous step's widths), and from the elements born during the step;
  // kept up to date through the next step's sweep as fractures are created, extended and
  // merged. Counts are exact; widths lag by a step (0.1 % of growth). The settled widths are
  // summed as integers (whatever thread settled a strip, the total is the same), per root,
  // then the births in strip order.
  skeleton_.compress();
  const size_t ids = skeleton_.ids();
  fracture_count_.assign(ids, 0.0);
  fracture_width_.assign(ids, 0.0);
  root_width_.assign(ids, 0);
  for (const InglisSums& sums : sums_)
    for (size_t id = 0; id < sums.count.size(); ++id) {
      const size_t r = size_t(skeleton_.compressed_root(int32_t(id)));
      fracture_count_[r] += double(sums.count[id]);
      root_width_[r] += sums.width[id];
    }
  for (size_t r = 0; r < ids; ++r) fracture_width_[r] = double(root_width_[r]) * 0x1p-40;
  for (auto& born : born_) {
    for (const auto& [id, w] : born) {
      const size_t r = size_t(skeleton_.compressed_root(id));
      fracture_count_[r] += 1;
      fracture_width_[r] += w;
    }
    born.clear();
  }
  for (InglisSums& s : sums_) {
    s.width.assign(ids, 0);
    s.count.assign(ids, 0);
  }
}

namespace {
// Inglis: the stress at a tip grows with the fracture's length-to-width ratio (mean width;
// sec. 3.2.4: "we used the mean fracture width"). count and width are by root.
bool inglis_sharp(const FractureSkeleton& skeleton, const std::vector<double>& count, const std::vector<double>& width,
                  int32_t id, double strip_width, double inglis_threshold) {
  const size_t root = size_t(skeleton.find(id));
  if (root >= count.size()) return false;
  const double c = count[root], mean_width = width[root] / std::max(1.0, c);
  return c * strip_width > inglis_threshold * mean_width;
}
}  // namespace

bool StripModel::sharp(int32_t id) const {
  return inglis_sharp(skeleton_, fracture_count_, fracture_width_, id, domain_.strip_width, params_.inglis_threshold);
}

bool StripModel::Sweep::sharp(int32_t id, double strip_width, double inglis_threshold) const {
  return inglis_sharp(skeleton, count, width, id, strip_width, inglis_threshold);
}

std::vector<FractureTip> StripModel::sharp_tips(size_t first, size_t last) const {
  std::vector<FractureTip> out;
  for (size_t j = first; j < std::min(last, strips_.size()); ++j) {
    const Strip& s = strips_[j];
    for (size_t i = 0; i < s.size(); ++i) {
      if (s.elements[i].kind != ElementKind::Fracture) continue;
      const FractureElement& fe = s.fractures[size_t(s.elements[i].fracture)];
      if (!fe.active || fe.id < 0 || !sharp(fe.id)) continue;
      // Unsettled: an element about to harden (settle()) is no longer a fracture.
      if (pending_[j] && params_.refracture_width > 0 && s.length(i) > params_.refracture_width) continue;
      const int32_t root = skeleton_.find(fe.id);
      if (fe.up < 0) out.push_back({j, centre_theta(j, i), root, true});
      if (fe.down < 0) out.push_back({j, centre_theta(j, i), root, false});
    }
  }
  return out;
}

void StripModel::queue_arrival(size_t strip, double theta) {
  if (strip < arrivals_.size()) arrivals_[strip].push_back(theta);
}

double StripModel::influence_distance(const Strip& s, size_t i, double x) const {
  // sec. 3.2.4: a fracture of width w influences points closer than w / a' to it (the
  // threshold form of f(a'·dist/width)). A fracture element is always active: hardening
  // turns it back into epidermis.
  if (s.elements[i].kind != ElementKind::Fracture) return std::numeric_limits<double>::infinity();
  const double w = s.length(i);
  double d = std::abs(s.x[i] + 0.5 * w - x);
  if (s.cyclic) {
    if (d >= s.circumference) d -= std::floor(d / s.circumference) * s.circumference;
    d = std::min(d, s.circumference - d);
  }
  return w > 0 && params_.influence * d < w ? d : std::numeric_limits<double>::infinity();
}

bool StripModel::strained(const Strip& s, size_t i) const {
  // Strain at least propagation_tension of the way from rest to the element's threshold.
  const Element& e = s.elements[i];
  return !(s.length(i) < e.rest * (1.0 + params_.propagation_tension * (e.threshold - 1.0)));
}

void StripModel::aim(size_t j, PropagationSide& side) const {
  // Whether a free end of strip j advances into its neighbour strip side.target, and where it
  // would cut it (sec. 3.2.4); pure.
  const Strip& st = strips_[side.target];
  const size_t ts = side.target;
  const double ws = domain_.strip_width;
  // Inglis: the stress concentrates at the tip, so the tip advances only if the bark straight
  // across it is in tension, or if a fracture there or beside it draws it (its influence
  // reaches the tip).
  const double x_straight = x_of(ts, side.theta);
  const size_t ne = st.size(), at = element_at(ts, x_straight);
  const size_t left = at == 0 ? ne - 1 : at - 1, right = at + 1 == ne ? 0 : at + 1;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  side.advances = st.elements[at].kind == ElementKind::Fracture || strained(st, at) ||
                  influence_distance(st, left, x_straight) < kNone || influence_distance(st, right, x_straight) < kNone;
  side.lands = false;
  if (!side.advances) return;
  // Base direction: parallel to the nearest fracture of the target strip whose influence
  // reaches the tip; otherwise along the grain (the axis, or the spiral_deg helix).
  double best = kNone;
  size_t nearest = SIZE_MAX;
  const size_t reach = std::min<size_t>(ne, 2 * kInfluenceElements + 1);
  size_t gi = at + ne - std::min(kInfluenceElements, ne / 2);
  if (gi >= ne) gi -= ne;
  for (size_t k = 0; k < reach; ++k, gi = gi + 1 == ne ? 0 : gi + 1) {
    const double d = influence_distance(st, gi, x_straight);
    if (d < best) {
      best = d;
      nearest = gi;
    }
  }
  // The influencing fracture's own direction, from its element back in our strip, if it
  // continues there (and is still a fracture there).
  const double radius = st.circumference / kTwoPi;
  // dθ/ds (radians per metre). The spiral's: the growth still to come stretches the bark
  // around the trunk, not along it, so a tip takes the slope that lands at spiral_deg on the
  // grown trunk (radius / scale): dθ/ds = tan(spiral) / final radius.
  double base_slope = std::tan(params_.spiral_deg * kPi / 180.0) * scale_at_step(step_) / radius;
  if (nearest != SIZE_MAX) {
    const int32_t back = side.up ? st.elements[nearest].down : st.elements[nearest].up;
    if (back >= 0) {
      const size_t bi = size_t(element_of_[j][size_t(back)]);
      if (strips_[j].elements[bi].kind == ElementKind::Fracture)
        base_slope = wrap_angle(centre_theta(ts, nearest) - centre_theta(j, bi)) / ws * (side.up ? 1.0 : -1.0);
    }
  }
  // Jitter the direction by the user angle (sec. 3.2.4); slopes in arc length on the target.
  // tan(atan(t) + b) = (t + tan b) / (1 - t tan b): the jittered slope without the atan.
  const double ta = base_slope * radius, tb = std::tan(side.jitter);
  const double dtheta = (ta + tb) / (1.0 - ta * tb) * ws / radius * (side.up ? 1.0 : -1.0);
  side.x = x_of(ts, side.theta + dtheta);
  side.element = element_at(ts, side.x);
  side.lands = st.elements[side.element].kind == ElementKind::Fracture || strained(st, side.element);
}

void StripModel::propagate_from(size_t j, Sweep& sw) {
  const size_t n = strips_.size();
  const double jitter = params_.propagation_jitter_deg * kPi / 180.0;
  auto neighbour = [&](bool up) -> long {
    if (up) return j + 1 < n ? long(j + 1) : (domain_.wrap_s ? 0 : -1);
    return j > 0 ? long(j - 1) : (domain_.wrap_s ? long(n - 1) : -1);
  };
  const long up_strip = neighbour(true), down_strip = neighbour(false);
  auto sharp = [&](int32_t id) { return sw.sharp(id, domain_.strip_width, params_.inglis_threshold); };
  StreamRng rng(params_.seed ^ 0x70726f70ULL, j, uint64_t(sw.step));
  // The irregular-fissure extension draws from its own stream, and only when it is on: the
  // paper's streams (and results) stay as they were.
  const bool irregular = params_.anastomosis > 0 || params_.fork_probability > 0;
  StreamRng rng_irregular(params_.seed ^ 0x69727265ULL, j, uint64_t(sw.step));
  // aim() looks up the elements of this strip that fractures in the neighbours link back to;
  // the record → element table was last touched a step ago: fetch it now, all at once.
  {
    const std::vector<int32_t>& table = element_of_[j];
    for (size_t k = 0; k < table.size(); k += 16) __builtin_prefetch(&table[k]);
  }
  // The free sides of the sharp free ends of this strip (listed after growth, plus those made
  // since in the sweep), each with its random draw. Nothing below changes strip j's elements
  // or links (breaks and links go to the neighbours), so the list holds through the loop.
  // Sides aimed at the other half's strips wait for the step's end.
  std::vector<PropagationSide>& sides = sw.sides;
  sides.clear();
  const bool fresh = !touched_[j];
  for (const FreeEnd& listed : tips_[j]) {
    // Listed fracture elements stay fracture elements through the sweep (hardening waits).
    FreeEnd f = listed;
    if (!fresh) {  // the copies may be stale: read the element
      const Element& e = strips_[j].elements[size_t(f.element)];
      f.id = e.id;
      f.up_free = e.up < 0;
      f.down_free = e.down < 0;
    }
    if (!(f.up_free || f.down_free) || !sharp(f.id)) continue;
    const double theta = fresh ? f.theta : centre_theta(j, size_t(f.element));
    for (bool up : {true, false}) {
      if (!(up ? f.up_free : f.down_free)) continue;
      PropagationSide side;
      side.tip = size_t(f.element);
      side.fe = f.fracture;
      side.id = f.id;
      side.up = up;
      side.theta = theta;
      side.jitter = jitter * rng.symmetric();  // drawn for every side: stable streams
      if (irregular) {
        side.join = rng_irregular.uniform();
        side.fork = rng_irregular.uniform();
      }
      const long t = up ? up_strip : down_strip;
      side.target = t < 0 || size_t(t) == j ? SIZE_MAX : size_t(t);
      if (side.target != SIZE_MAX && owner_[side.target] != sw.half)
        sw.crossings.push_back({j, side.target, side.fe, up, side.jitter, side.join, side.fork, sw.step});
      else
        sides.push_back(side);
    }
  }
  // Each side's cut on its neighbour, computed for all sides first (independent computations
  // overlap in the processor), and again for a side whose target strip an earlier side changed.
  for (PropagationSide& side : sides)
    if (side.target != SIZE_MAX) aim_side(j, side, sw);
  bool changed_up = false, changed_down = false;
  for (PropagationSide& side : sides) {
    // Most sides change nothing (their tip is not drawn across, or would cut bark that is not
    // in tension): unless an earlier side changed their target strip, that is known already.
    if (side.target != SIZE_MAX && !(side.up ? changed_up : changed_down) && !side.lands) continue;
    // Tested again: a merge earlier in this loop may have changed the fracture.
    if (!sharp(side.id)) continue;
    if (side.up ? up_strip < 0 : down_strip < 0) {
      sw.exits.push_back({int(j), side.up, side.theta});
      continue;
    }
    if (side.target == SIZE_MAX) continue;
    if (side.up ? changed_up : changed_down) aim_side(j, side, sw);
    if (!side.advances || !land(j, side, sw)) continue;
    // The target strip changed (a break moves its elements, a link its back links): later
    // sides aimed at it are aimed again. (Both neighbours are one strip when there are two.)
    changed_up |= long(side.target) == up_strip;
    changed_down |= long(side.target) == down_strip;
  }
}

bool StripModel::land(size_t j, PropagationSide& side, Sweep& sw) {
  const size_t ts = side.target, root = size_t(sw.skeleton.find(side.id));
  Strip& st = strips_[ts];
  const size_t i = side.element;
  const Element& e = st.elements[i];
  int32_t g = -1;
  const bool e_was_bark = e.kind != ElementKind::Fracture;
  size_t i_target = i;  // the fracture element linked to: met, or made by the break
  if (e.kind == ElementKind::Fracture) {
    // Fractures that meet merge (2001 sec. 4: the skeleton becomes a graph).
    g = e.fracture;
    const size_t other = size_t(sw.skeleton.find(e.id));
    if (other != root && sw.skeleton.merge(int32_t(root), int32_t(other))) {
      sw.merges.emplace_back(int32_t(root), int32_t(other));
      if (side.deviated) ++sw.joined;
      const size_t r = size_t(sw.skeleton.find(int32_t(root))), o = r == root ? other : root;
      sw.count[r] += sw.count[o];
      sw.width[r] += sw.width[o];
    }
  } else {
    // Inglis' iso-strain curves run parallel to fractures: only bark in tension breaks. Our
    // extension: tough spots arrest the tip for good (its angle does not change).
    if (!strained(st, i)) return false;
    if (params_.toughness_fraction > 0 && tough(ts, side.theta)) return false;
    double off = side.x - st.x[i];
    if (st.cyclic) off -= std::floor(off / st.circumference) * st.circumference;
    const double L = st.length(i);
    const long long before = breaks_[ts];
    if (!break_element(ts, i, L > 0 ? off / L : 0.5, &g, sw.step)) return false;
    breaks_[ts] = before;  // a propagation, not a new fracture
    FractureElement& ng = st.fractures[size_t(g)];
    ng.id = side.id;
    i_target = i + 1;
    st.elements[i_target].id = side.id;
    ++sw.propagated;
    const size_t r = size_t(sw.skeleton.find(side.id));
    sw.count[r] += 1;
    sw.width[r] += st.length(i + 1);  // break_element put the fracture element at i + 1
    born_[ts].emplace_back(side.id, st.length(i + 1));
  }
  // Link both ways, in the fracture records and their copies in the elements.
  FractureElement& src2 = strips_[j].fractures[size_t(side.fe)];
  Element& src_e = strips_[j].elements[side.tip];
  FractureElement& ge2 = st.fractures[size_t(g)];
  Element& ge_e = st.elements[i_target];
  (side.up ? src2.up : src2.down) = (side.up ? src_e.up : src_e.down) = g;
  if ((side.up ? ge2.down : ge2.up) < 0) (side.up ? ge2.down : ge2.up) = (side.up ? ge_e.down : ge_e.up) = side.fe;
  touched_[ts] = 1;
  if (e_was_bark && side.fork < params_.fork_probability) fork(side, sw);
  return true;
}

void StripModel::cross(const Crossing& c, Sweep& sw) {
  // A side that reached the other half of the sweep, at the step's end: aimed at its target as
  // it is now, and landed if it still can (its side may have been linked since).
  const int32_t tip = element_of_[c.strip][size_t(c.fe)];
  const Element& e = strips_[c.strip].elements[size_t(tip)];
  if (e.kind != ElementKind::Fracture || (c.up ? e.up : e.down) >= 0) return;
  PropagationSide side;
  side.tip = size_t(tip);
  side.fe = c.fe;
  side.id = e.id;
  side.up = c.up;
  side.theta = centre_theta(c.strip, size_t(tip));
  side.jitter = c.jitter;
  side.join = c.join;
  side.fork = c.fork;
  side.target = c.target;
  sw.step = c.step;
  aim_side(c.strip, side, sw);
  if (side.advances && side.lands) land(c.strip, side, sw);
}

}  // namespace phellem::bark

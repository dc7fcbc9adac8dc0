// Irregular fissures: our extension of Lefebvre & Neyret 2002 (issue 22), not in the paper.
//
// The paper's tips (sec. 3.2.4) advance while the bark across them is strained, steered
// parallel to nearby fractures, so on a sample grown long enough every fissure crosses it and
// they settle at a near-constant pitch. Real bark's fissures end, fork, meet and interlace
// (anastomose), with short ones between long ones. Four knobs, all off by default (the
// paper's model then runs unchanged, draw for draw):
// - tough spots (toughness_fraction): bark that arrests a propagating tip, so fissures end at
//   varying places; the spot still breaks by creation (sec. 3.2.3) when strained enough, which
//   starts an offset fissure, en échelon;
// - anastomosis: an advancing tip deviates sideways to meet another fracture, which then merge
//   (the skeleton graph of 2001 sec. 4, merges sought out rather than met by chance);
// - forking: a tip that cuts its neighbour strip cuts it again a little to the side;
// - weakness_noise: a low-frequency procedural weakness map (sec. 3.2.3's threshold jitter made
//   spatially coherent), so fissures start at irregular spacings.

#include <algorithm>
#include <cmath>
#include <limits>

#include "bark/strips/strip_model.h"

namespace phellem::bark {

namespace {
constexpr double kTwoPi = 6.283185307179586;

double lattice(uint64_t seed, long a, long b) { return StreamRng(seed, uint64_t(a), uint64_t(b)).symmetric(); }
double smoothstep(double t) { return t * t * (3 - 2 * t); }
long wrap(long a, long n) { return n > 0 ? ((a % n) + n) % n : a; }
}  // namespace

double StripModel::final_circumference(size_t j) const {
  double c = 0;
  for (double b : domain_.strips[j].bin_length) c += b;
  return c;
}

double StripModel::smooth_noise(size_t j, double theta, double size, uint64_t salt) const {
  // Value noise on a lattice of `size` metres along the strips (a whole number of cells
  // around a cyclic strip, so it has no seam) and 4·size across them (along the fractures:
  // weak bands run with the fissures); across, it wraps when propagation does.
  const size_t n = strips_.size();
  const double circ = final_circumference(j);
  const long na = domain_.cyclic ? std::max(1L, long(std::lround(circ / size))) : 0;
  const double a = domain_.cyclic ? theta / kTwoPi * double(na) : theta / kTwoPi * circ / size;
  const double across = 4 * size;
  const long nb = domain_.wrap_s ? std::max(1L, long(std::lround(domain_.length / across))) : 0;
  const double b = (double(j) + 0.5) / double(n) * (domain_.wrap_s ? double(nb) : domain_.length / across);
  const long a0 = long(std::floor(a)), b0 = long(std::floor(b));
  const double ta = smoothstep(a - double(a0)), tb = smoothstep(b - double(b0));
  const uint64_t seed = params_.seed ^ salt;
  auto v = [&](long da, long db) { return lattice(seed, wrap(a0 + da, na), wrap(b0 + db, nb)); };
  return (1 - tb) * ((1 - ta) * v(0, 0) + ta * v(1, 0)) + tb * ((1 - ta) * v(0, 1) + ta * v(1, 1));
}

bool StripModel::tough(size_t j, double theta) const {
  // A spot is one strip across and toughness_size along it; a fraction of them are tough.
  const double circ = final_circumference(j);
  const long na = domain_.cyclic ? std::max(1L, long(std::lround(circ / params_.toughness_size))) : 0;
  const double a = domain_.cyclic ? theta / kTwoPi * double(na) : theta / kTwoPi * circ / params_.toughness_size;
  const long cell = wrap(long(std::floor(a)), na);
  StreamRng rng(params_.seed ^ 0x746f7567ULL, j, uint64_t(cell));
  return rng.uniform() < params_.toughness_fraction;
}

void StripModel::aim_side(size_t j, PropagationSide& side, const Sweep& sw) const {
  aim(j, side);
  side.deviated = false;
  if (!(side.advances && side.join < params_.anastomosis)) return;
  // Anastomosis: the nearest element of another fracture within reach of the cut, on the
  // target strip, draws the tip (reach scaled to the strip's current size).
  const Strip& st = strips_[side.target];
  const size_t ne = st.size();
  const double reach = params_.anastomosis_reach * st.circumference / final_circumference(side.target);
  const int32_t own = sw.skeleton.find(side.id);
  double best = std::numeric_limits<double>::infinity();
  size_t found = SIZE_MAX;
  constexpr size_t kMostElements = 24;  // each way
  for (int dir : {-1, 1}) {
    size_t k = side.element;
    for (size_t step = 0; step < std::min(kMostElements, ne / 2); ++step) {
      if (dir < 0)
        k = k == 0 ? (st.cyclic ? ne - 1 : SIZE_MAX) : k - 1;
      else
        k = k + 1 == ne ? (st.cyclic ? 0 : SIZE_MAX) : k + 1;
      if (k == SIZE_MAX) break;
      double d = std::abs(st.x[k] + 0.5 * st.length(k) - side.x);
      if (st.cyclic) {
        d -= std::floor(d / st.circumference) * st.circumference;
        d = std::min(d, st.circumference - d);
      }
      if (d > reach + st.length(k)) break;
      const Element& e = st.elements[k];
      if (e.kind != ElementKind::Fracture || e.id < 0 || d > reach || d >= best) continue;
      if (sw.skeleton.find(e.id) == own) continue;
      best = d;
      found = k;
    }
  }
  if (found == SIZE_MAX) return;
  side.element = found;
  side.x = st.x[found] + 0.5 * st.length(found);
  side.lands = true;
  side.deviated = true;
}

void StripModel::fork(PropagationSide& side, Sweep& sw) {
  // The tip just cut strip side.target at side.x: cut it again fork_offset × [0.5, 1] to one
  // side (side.fork / fork_probability, uniform in [0, 1), gives the side and the distance).
  const size_t ts = side.target;
  Strip& st = strips_[ts];
  const double u = side.fork / params_.fork_probability;
  const double frac = 2 * u - std::floor(2 * u);
  const double off = params_.fork_offset * (0.5 + 0.5 * frac) * st.circumference / final_circumference(ts);
  double x = side.x + (u < 0.5 ? -off : off);
  if (st.cyclic)
    x -= std::floor(x / st.circumference) * st.circumference;
  else if (x <= 0 || x >= st.circumference)
    return;
  const size_t i = element_at(ts, x);
  if (st.elements[i].kind != ElementKind::Epidermis || !strained(st, i)) return;
  double o = x - st.x[i];
  if (st.cyclic) o -= std::floor(o / st.circumference) * st.circumference;
  const double L = st.length(i);
  int32_t g = -1;
  const long long before = breaks_[ts];
  if (!break_element(ts, i, L > 0 ? o / L : 0.5, &g, sw.step)) return;
  breaks_[ts] = before;  // a branch of the propagating fracture, not a new one
  st.fractures[size_t(g)].id = side.id;
  st.elements[i + 1].id = side.id;
  const size_t r = size_t(sw.skeleton.find(side.id));
  sw.count[r] += 1;
  sw.width[r] += st.length(i + 1);
  born_[ts].emplace_back(side.id, st.length(i + 1));
  ++sw.forked;
}

}  // namespace phellem::bark

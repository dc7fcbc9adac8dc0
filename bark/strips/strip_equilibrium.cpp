#include "bark/strips/strip_equilibrium.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace phellem::bark {

namespace {

void solve_uniform_tension(Strip& s) {
  // No attachment: every element carries the same tension (sec. 3.2.2).
  const size_t n = s.size();
  double rest = 0, compliance = 0;
  for (const Element& e : s.elements) {
    rest += e.rest;
    compliance += 1.0 / e.stiffness;
  }
  const double total = s.cyclic ? s.circumference : s.x.back() - s.x.front();
  const double T = (total - rest) / compliance;
  double pos = 0;
  std::vector<double>& x = s.x;
  const double x0 = x[0];
  for (size_t i = 0; i < n; ++i) {
    x[i] = pos;
    pos += s.elements[i].rest + T / s.elements[i].stiffness;
  }
  if (!s.cyclic) {
    for (size_t i = 0; i < n; ++i) x[i] += x0;  // x[n] (the fixed right end) is untouched
    return;
  }
  double mean = 0;
  for (size_t i = 0; i < n; ++i) mean += x[i] - s.anchor[i];
  mean /= double(n);
  for (size_t i = 0; i < n; ++i) x[i] -= mean;
}

// Eliminates the cyclic matrix: diagonal K_{j-1} + K_j + K_a,j, off-diagonals -K_j between
// nodes j and j+1, corners -K_{n-1}. Sherman–Morrison: A = A' + u vᵀ with
// u = (γ, 0, …, 0, α), v = (1, 0, …, 0, β/γ), α = β = -K_{n-1}, γ = -A[0][0]; A' is
// tridiagonal with A'[0][0] = A[0][0] - γ and A'[n-1][n-1] = A[n-1][n-1] - αβ/γ.
void factor_cyclic(const Strip& s, EquilibriumFactor& f) {
  const size_t n = s.size();
  auto k = [&](size_t i) { return s.elements[i].stiffness; };
  f.inv.resize(n);
  f.u.assign(n, 0.0);
  auto cprime = [&](size_t i) { return -k(i) * f.inv[i]; };
  const double alpha = -k(n - 1), beta = alpha;
  const double gamma = -(k(n - 1) + k(0) + s.attach[0]);
  auto diag = [&](size_t j) {
    double d = (j == 0 ? k(n - 1) : k(j - 1)) + k(j) + s.attach[j];
    if (j == 0) d -= gamma;
    if (j == n - 1) d -= alpha * beta / gamma;
    return d;
  };
  const size_t first = std::min(f.kept, n - 1);  // row 0 and the last row depend on γ
  if (first == 0) f.inv[0] = 1.0 / diag(0);
  for (size_t i = std::max<size_t>(first, 1); i < n; ++i) {
    const double l = -k(i - 1);  // symmetric: sub-diagonal equals the super-diagonal
    f.inv[i] = 1.0 / (diag(i) - l * cprime(i - 1));
  }
  f.u[0] = gamma;
  f.u[n - 1] = alpha;
  f.u[0] *= f.inv[0];
  for (size_t i = 1; i < n; ++i) f.u[i] = (f.u[i] - -k(i - 1) * f.u[i - 1]) * f.inv[i];
  for (size_t i = n - 1; i-- > 0;) f.u[i] -= cprime(i) * f.u[i + 1];
  f.denominator = 1.0 + f.u[0] + beta * f.u[n - 1] / gamma;
  f.gamma = gamma;
}

// Eliminates the open strip's matrix over the free nodes 1..n-1 (row r = node r + 1).
void factor_open(const Strip& s, EquilibriumFactor& f) {
  const size_t m = s.size() - 1;
  auto k = [&](size_t i) { return s.elements[i].stiffness; };
  f.inv.resize(m);
  for (size_t r = std::min(f.kept, m); r < m; ++r) {
    const double d = k(r) + k(r + 1) + s.attach[r + 1];
    f.inv[r] = 1.0 / (r == 0 ? d : d + k(r) * (-k(r) * f.inv[r - 1]));  // c'_{r-1} = -K_r inv_{r-1}
  }
}

}  // namespace

double Strip::original_epidermis() const {
  double sum = 0;
  for (const Element& e : elements)
    if (e.kind == ElementKind::Epidermis && e.level == 0) sum += e.rest;
  return sum;
}

double element_tension(const Strip& s, size_t i) {
  const Element& e = s.elements[i];
  return e.stiffness * (s.length(i) - e.rest);
}

namespace {

// Tension at the anchors, T^a_i = K_i (a_{i+1} - a_i - l0_i) (element n-1 of a cyclic strip
// closes by C).
double anchor_tension(const Strip& s, size_t i) {
  const double next = i + 1 < s.anchor.size() ? s.anchor[i + 1] : s.anchor[0] + s.circumference;
  return s.elements[i].stiffness * (next - s.anchor[i] - s.elements[i].rest);
}

// Whether the strip takes the general path (an eliminated cyclic or open system) rather than a
// special case (no attachment, fewer than 3 elements), which is then solved here.
bool solve_special_case(Strip& s) {
  const size_t n = s.size();
  if (n == 0) return true;
  if (std::none_of(s.attach.begin(), s.attach.end(), [](double a) { return a > 0; })) {
    solve_uniform_tension(s);
    return true;
  }
  if (s.cyclic && n <= 2) {
    // Node 0 and node 1 are each other's left and right neighbour: assemble 2×2 (or 1×1).
    if (n == 1) {
      s.x[0] = s.anchor[0];  // the single element closes on itself: tension is fixed by C
      return true;
    }
    const double k0 = s.elements[0].stiffness, k1 = s.elements[1].stiffness, a0 = s.attach[0], a1 = s.attach[1];
    const double m00 = k0 + k1 + a0, m11 = k0 + k1 + a1, m01 = -(k0 + k1);
    const double t0 = anchor_tension(s, 0), t1 = anchor_tension(s, 1);
    const double r0 = t0 - t1, r1 = t1 - t0;
    const double det = m00 * m11 - m01 * m01;
    s.x[0] = s.anchor[0] + (r0 * m11 - m01 * r1) / det;
    s.x[1] = s.anchor[1] + (m00 * r1 - m01 * r0) / det;
    return true;
  }
  return !s.cyclic && n < 2;  // an open strip of one element: both nodes fixed
}

void ensure_factor(const Strip& s, EquilibriumFactor& f, bool keep) {
  if (keep && f.valid) return;
  if (s.cyclic)
    factor_cyclic(s, f);
  else
    factor_open(s, f);
  f.valid = keep;
  f.kept = 0;
}

// The right-hand side in displacements u_j = x_j - a_j (better conditioned than x): the
// differences of the anchor tensions at each free node, the fixed ends of an open strip
// entering through their known displacements. Returns the number of unknowns.
size_t assemble_open(const Strip& s, std::vector<double>& rhs) {
  const size_t n = s.size();
  const size_t m = n - 1;
  rhs.resize(m);
  for (size_t r = 0; r < m; ++r) rhs[r] = anchor_tension(s, r + 1) - anchor_tension(s, r);
  rhs[0] += s.elements[0].stiffness * (s.x[0] - s.anchor[0]);
  rhs[m - 1] += s.elements[n - 1].stiffness * (s.x[n] - s.anchor[n]);
  return m;
}

// Back substitution from the last row, whose value p is already in r[m - 1]; row i's
// super-diagonal entry is -K of e[i] (c'_i = -K inv_i).
PHELLEM_FMA_CLONES void back_substitute(double* r, const double* inv, const Element* e, size_t m, double p) {
  for (size_t i = m - 1; i-- > 0;) r[i] = p = back_row(r[i], -e[i].stiffness * inv[i], p);
}

// Open strips: forward elimination and back substitution on the eliminated matrix (row r's
// sub-diagonal entry is -K_r, the element left of node r + 1). The running value is carried
// in a register: the chains are bound by latency, not by memory.
PHELLEM_FMA_CLONES void substitute_open(const Strip& s, const EquilibriumFactor& f, std::vector<double>& rhs, size_t m) {
  double* r = rhs.data();
  const double* inv = f.inv.data();
  double p = r[0] * inv[0];
  r[0] = p;
  for (size_t i = 1; i < m; ++i) r[i] = p = forward_row(r[i], s.elements[i].stiffness, inv[i], p);
  back_substitute(r, inv, s.elements.data() + 1, m, p);  // row r's super-diagonal: element r + 1
}

// Cyclic strips: the right-hand side (the differences of the anchor tensions) and the forward
// elimination in one pass over the elements (row i's sub-diagonal entry is -K_{i-1}).
PHELLEM_FMA_CLONES void assemble_and_eliminate_cyclic(const Strip& s, const EquilibriumFactor& f, std::vector<double>& rhs) {
  const size_t n = s.size();
  rhs.resize(n);
  double* r = rhs.data();
  const double* a = s.anchor.data();
  const double* inv = f.inv.data();
  const Element* e = s.elements.data();
  const double last = e[n - 1].stiffness * (a[0] + s.circumference - a[n - 1] - e[n - 1].rest);
  double prev = e[0].stiffness * (a[1] - a[0] - e[0].rest);
  double p = (prev - last) * inv[0];
  r[0] = p;
  for (size_t i = 1; i + 1 < n; ++i) {
    const double t = e[i].stiffness * (a[i + 1] - a[i] - e[i].rest);
    r[i] = p = forward_row(t - prev, e[i - 1].stiffness, inv[i], p);
    prev = t;
  }
  p = forward_row(last - prev, e[n - 2].stiffness, inv[n - 1], p);
  r[n - 1] = p;
  back_substitute(r, inv, e, n, p);
}

// Node positions from the solution (cyclic strips: the Sherman–Morrison correction).
void write_positions(Strip& s, const EquilibriumFactor& f, const std::vector<double>& rhs) {
  const size_t n = s.size();
  if (s.cyclic) {
    const double beta = -s.elements[n - 1].stiffness;
    const double gamma = -(s.elements[n - 1].stiffness + s.elements[0].stiffness + s.attach[0]);
    const double fact = (rhs[0] + beta * rhs[n - 1] / gamma) / f.denominator;
    const double* a = s.anchor.data();
    const double* r = rhs.data();
    const double* u = f.u.data();
    double* x = s.x.data();
    for (size_t j = 0; j < n; ++j) x[j] = a[j] + (r[j] - fact * u[j]);
    return;
  }
  for (size_t r = 0; r + 1 < n; ++r) s.x[r + 1] = s.anchor[r + 1] + rhs[r];
}

}  // namespace

PHELLEM_FMA_CLONES void solve_equilibrium(Strip& s, EquilibriumFactor* factor) {
  // A valid factor means the stiffnesses are those of the last general solve.
  if (!(factor && factor->valid) && solve_special_case(s)) return;
  thread_local EquilibriumFactor scratch_factor;
  thread_local std::vector<double> rhs;
  EquilibriumFactor& f = factor ? *factor : scratch_factor;
  ensure_factor(s, f, factor != nullptr);
  if (s.cyclic) {
    assemble_and_eliminate_cyclic(s, f, rhs);
  } else {
    const size_t m = assemble_open(s, rhs);
    substitute_open(s, f, rhs, m);
  }
  write_positions(s, f, rhs);
}

double equilibrium_residual(const Strip& s) {
  const size_t n = s.size();
  double worst = 0, scale = 1e-300;
  const size_t first = s.cyclic ? 0 : 1, last = n;  // free nodes [first, last)
  for (size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(element_tension(s, i)));
  for (size_t j = first; j < last; ++j) {
    const size_t left = s.cyclic ? (j + n - 1) % n : j - 1;
    const double fa = s.attach[j] * (s.x[j] - s.anchor[j]);
    scale = std::max(scale, std::abs(fa));
    worst = std::max(worst, std::abs(element_tension(s, j) - element_tension(s, left) - fa));
  }
  if (!s.cyclic && n < 2) return 0;
  return worst / scale;
}

}  // namespace phellem::bark

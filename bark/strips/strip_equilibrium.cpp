#include "bark/strips/strip_equilibrium.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace phellem::bark {

namespace {

struct Scratch {
  std::vector<double> lower, diag, upper, rhs, cprime;  // tridiagonal system and elimination
  std::vector<double> ta, u;  // cyclic strips: anchor tensions T^a_i, Sherman–Morrison vector u
};

// Thomas algorithm for a tridiagonal system (lower[0] and upper[n-1] unused); the matrix is
// symmetric positive definite here, so no pivoting is needed. Solves in place into `rhs`.
void thomas(const std::vector<double>& lower, const std::vector<double>& diag, const std::vector<double>& upper,
            std::vector<double>& rhs, std::vector<double>& cprime, size_t n) {
  cprime.resize(n);
  double denom = diag[0];
  cprime[0] = upper[0] / denom;
  rhs[0] /= denom;
  for (size_t i = 1; i < n; ++i) {
    denom = diag[i] - lower[i] * cprime[i - 1];
    cprime[i] = upper[i] / denom;
    rhs[i] = (rhs[i] - lower[i] * rhs[i - 1]) / denom;
  }
  for (size_t i = n - 1; i-- > 0;) rhs[i] -= cprime[i] * rhs[i + 1];
}

// Anchor of node j for a cyclic strip, unwrapped: a_{j+n} = a_j + C.
double anchor_at(const Strip& s, long j) {
  const long n = long(s.anchor.size());
  long k = j % n;
  if (k < 0) k += n;
  return s.anchor[size_t(k)] + double((j - k) / n) * s.circumference;
}

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

void solve_equilibrium(Strip& s) {
  const size_t n = s.size();
  if (n == 0) return;
  bool attached = false;
  for (double a : s.attach) attached |= a > 0;
  if (!attached) {
    solve_uniform_tension(s);
    return;
  }
  thread_local Scratch w;
  // Unknowns: displacements u_j = x_j - a_j of the free nodes (better conditioned than x).
  // Tension at the anchors, T^a_i = K_i (a_{i+1} - a_i - l0_i), gives the right-hand side
  // T^a_i - T^a_{i-1}; the matrix has K_{i-1} + K_i + K_a on its diagonal and -K on the
  // off-diagonals.
  auto K = [&](size_t i) { return s.elements[i].stiffness; };
  if (s.cyclic) {
    auto Ta = [&](long i) {
      const size_t k = size_t((i + long(n)) % long(n));
      return K(k) * (anchor_at(s, i + 1) - anchor_at(s, i) - s.elements[k].rest);
    };
    if (n <= 2) {
      // Node 0 and node 1 are each other's left and right neighbour: assemble 2×2 (or 1×1).
      if (n == 1) {
        s.x[0] = s.anchor[0];  // the single element closes on itself: tension is fixed by C
        return;
      }
      const double k0 = K(0), k1 = K(1), a0 = s.attach[0], a1 = s.attach[1];
      const double m00 = k0 + k1 + a0, m11 = k0 + k1 + a1, m01 = -(k0 + k1);
      const double r0 = Ta(0) - Ta(-1), r1 = Ta(1) - Ta(0);
      const double det = m00 * m11 - m01 * m01;
      s.x[0] = s.anchor[0] + (r0 * m11 - m01 * r1) / det;
      s.x[1] = s.anchor[1] + (m00 * r1 - m01 * r0) / det;
      return;
    }
    // Assembly without modulo: Ta[i] = T^a_i for i = 0..n-1 (element n-1 closes by C).
    w.ta.resize(n);  // T^a_i
    for (size_t i = 0; i + 1 < n; ++i) w.ta[i] = K(i) * (s.anchor[i + 1] - s.anchor[i] - s.elements[i].rest);
    w.ta[n - 1] = K(n - 1) * (s.anchor[0] + s.circumference - s.anchor[n - 1] - s.elements[n - 1].rest);
    w.diag.resize(n);
    w.rhs.resize(n);
    w.upper.resize(n);  // off-diagonal -K_j between nodes j and j+1
    for (size_t j = 0; j < n; ++j) w.upper[j] = -K(j);
    w.diag[0] = K(n - 1) + K(0) + s.attach[0];
    w.rhs[0] = w.ta[0] - w.ta[n - 1];
    for (size_t j = 1; j < n; ++j) {
      w.diag[j] = K(j - 1) + K(j) + s.attach[j];
      w.rhs[j] = w.ta[j] - w.ta[j - 1];
    }
    // Sherman–Morrison: A = A' + u vᵀ with the corner entries A[0][n-1] = A[n-1][0] = -K_{n-1};
    // u = (γ, 0, …, 0, α), v = (1, 0, …, 0, β/γ). One elimination of A' serves both right-hand
    // sides (r and u).
    const double alpha = w.upper[n - 1], beta = alpha;
    const double gamma = -w.diag[0];
    w.diag[0] -= gamma;
    w.diag[n - 1] -= alpha * beta / gamma;
    w.cprime.resize(n);
    w.u.resize(n);  // second right-hand side u
    std::fill(w.u.begin(), w.u.end(), 0.0);
    w.u[0] = gamma;
    w.u[n - 1] = alpha;
    double inv = 1.0 / w.diag[0];
    w.cprime[0] = w.upper[0] * inv;
    w.rhs[0] *= inv;
    w.u[0] *= inv;
    for (size_t i = 1; i < n; ++i) {
      const double l = w.upper[i - 1];  // symmetric: sub-diagonal equals the super-diagonal
      inv = 1.0 / (w.diag[i] - l * w.cprime[i - 1]);
      w.cprime[i] = w.upper[i] * inv;
      w.rhs[i] = (w.rhs[i] - l * w.rhs[i - 1]) * inv;
      w.u[i] = (w.u[i] - l * w.u[i - 1]) * inv;
    }
    for (size_t i = n - 1; i-- > 0;) {
      w.rhs[i] -= w.cprime[i] * w.rhs[i + 1];
      w.u[i] -= w.cprime[i] * w.u[i + 1];
    }
    const double fact = (w.rhs[0] + beta * w.rhs[n - 1] / gamma) / (1.0 + w.u[0] + beta * w.u[n - 1] / gamma);
    for (size_t j = 0; j < n; ++j) s.x[j] = s.anchor[j] + (w.rhs[j] - fact * w.u[j]);
    return;
  }
  // Open strip: nodes 0 and n are fixed; unknowns are nodes 1..n-1.
  if (n < 2) return;
  const size_t m = n - 1;
  w.lower.assign(m, 0);
  w.diag.assign(m, 0);
  w.upper.assign(m, 0);
  w.rhs.assign(m, 0);
  // Fixed ends enter through the anchors: u_0 = x_0 - a_0 and u_n = x_n - a_n are known.
  const double u0 = s.x[0] - s.anchor[0], un = s.x[n] - s.anchor[n];
  auto Ta = [&](size_t i) { return K(i) * (s.anchor[i + 1] - s.anchor[i] - s.elements[i].rest); };
  for (size_t j = 1; j <= m; ++j) {
    const size_t r = j - 1;
    w.diag[r] = K(j - 1) + K(j) + s.attach[j];
    w.lower[r] = -K(j - 1);
    w.upper[r] = -K(j);
    w.rhs[r] = Ta(j) - Ta(j - 1);
  }
  w.rhs[0] += K(0) * u0;
  w.rhs[m - 1] += K(n - 1) * un;
  thomas(w.lower, w.diag, w.upper, w.rhs, w.cprime, m);
  for (size_t j = 1; j <= m; ++j) s.x[j] = s.anchor[j] + w.rhs[j - 1];
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

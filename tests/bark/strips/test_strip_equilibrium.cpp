// Strip equilibrium (Lefebvre & Neyret 2002, sec. 4.2): the elements' tensions balance,
// checked against hand-computed and dense solutions of the paper's equations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "bark/strips/strip_equilibrium.h"

using namespace phellem::bark;

namespace {

Strip make_strip(bool cyclic, const std::vector<double>& rest, const std::vector<double>& K, double total,
                 const std::vector<double>& attach = {}) {
  Strip s;
  s.cyclic = cyclic;
  s.circumference = total;
  for (size_t i = 0; i < rest.size(); ++i) {
    Element e;
    e.rest = rest[i];
    e.stiffness = K[i];
    s.elements.push_back(e);
  }
  const size_t nodes = cyclic ? rest.size() : rest.size() + 1;
  for (size_t i = 0; i < nodes; ++i) s.x.push_back(total * double(i) / double(rest.size()));
  s.anchor = s.x;
  s.attach = attach.empty() ? std::vector<double>(nodes, 0.0) : attach;
  return s;
}

}  // namespace

TEST(StripEquilibrium, HandComputedThreeElementsWithoutAttachment) {
  // sec. 3.2.2: K_i e_i equal for all i and Σ e_i = L − Σ l0. K = 1, 2, 4; l0 = 1 each; L = 3.7:
  // T = 0.7 / (1 + 1/2 + 1/4) = 0.4, e = 0.4, 0.2, 0.1.
  Strip s = make_strip(false, {1, 1, 1}, {1, 2, 4}, 3.7);
  solve_equilibrium(s);
  EXPECT_DOUBLE_EQ(s.x[0], 0.0);
  EXPECT_NEAR(s.x[1], 1.4, 1e-15);
  EXPECT_NEAR(s.x[2], 2.6, 1e-15);
  EXPECT_DOUBLE_EQ(s.x[3], 3.7);
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(element_tension(s, i), 0.4, 1e-15);
}

TEST(StripEquilibrium, HandComputedThreeElementsWithAttachment) {
  // Open strip 0 — 3 with l0 = 1, K = 1, interior nodes glued (K_a = 1) at anchors 1.2 and 2.1.
  // Node 1: (x2 − x1 − 1) − (x1 − 0 − 1) − (x1 − 1.2) = 0 → −3 x1 + x2 = −1.2
  // Node 2: (3 − x2 − 1) − (x2 − x1 − 1) − (x2 − 2.1) = 0 → x1 − 3 x2 = −5.1
  // x1 = (3.6 + 5.1) / 8 = 1.0875, x2 = 2.0625.
  Strip s = make_strip(false, {1, 1, 1}, {1, 1, 1}, 3.0, {0, 1, 1, 0});
  s.anchor = {0, 1.2, 2.1, 3.0};
  s.x = s.anchor;
  solve_equilibrium(s);
  EXPECT_NEAR(s.x[1], 1.0875, 1e-14);
  EXPECT_NEAR(s.x[2], 2.0625, 1e-14);
  EXPECT_LT(equilibrium_residual(s), 1e-12);
}

TEST(StripEquilibrium, CyclicMatchesDenseSolveOfThePaperEquations) {
  // sec. 5.1 equations for a cyclic strip, assembled densely and solved by Eigen's LU,
  // against the O(n) Sherman–Morrison solver.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.2, 2.0);
  for (int n : {1, 2, 3, 4, 7, 40}) {
    std::vector<double> rest(static_cast<size_t>(n)), K(static_cast<size_t>(n)), A(static_cast<size_t>(n));
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      rest[size_t(i)] = u(rng);
      K[size_t(i)] = u(rng);
      A[size_t(i)] = 0.3 * u(rng);
      sum += rest[size_t(i)];
    }
    const double C = 1.3 * sum;
    Strip s = make_strip(true, rest, K, C, A);
    for (double& a : s.anchor) a += 0.05 * u(rng);
    s.x = s.anchor;
    solve_equilibrium(s);
    EXPECT_LT(equilibrium_residual(s), 1e-12) << "n = " << n;
    if (n < 3) continue;
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) {
      const int l = (i + n - 1) % n, r = (i + 1) % n;
      // −K_{i-1}(x_i − x_{i−1} − l_{i−1}) + K_i(x_{i+1} − x_i − l_i) − K_a(x_i − a_i) = 0
      const double wl = i == 0 ? -C : 0.0, wr = i == n - 1 ? C : 0.0;  // unwrapping
      M(i, i) += -K[size_t(l)] - K[size_t(i)] - A[size_t(i)];
      M(i, l) += K[size_t(l)];
      M(i, r) += K[size_t(i)];
      b(i) += -K[size_t(l)] * (rest[size_t(l)] + wl) + K[size_t(i)] * (rest[size_t(i)] - wr) - A[size_t(i)] * s.anchor[size_t(i)];
    }
    const Eigen::VectorXd x = M.lu().solve(b);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(s.x[size_t(i)], x(i), 1e-11) << "n = " << n << " node " << i;
  }
}

TEST(StripEquilibrium, ResumedEliminationGivesTheBitsOfAFreshOne) {
  // A break changes the elements from index i on: the eliminated rows before it are kept
  // (rows [0, i) of a cyclic strip, [0, i - 1) of an open one, whose row r is node r + 1) and
  // elimination resumes there. The solve must be the one a fresh elimination gives.
  for (bool cyclic : {true, false}) {
    const size_t n = 16, nodes = cyclic ? n : n + 1, i = 7;
    std::vector<double> rest(n), K(n), attach(nodes);
    for (size_t k = 0; k < n; ++k) rest[k] = 0.01 * (1.0 + 0.1 * double(k % 3)), K[k] = 1.0 + 0.37 * double(k % 5);
    for (size_t k = 0; k < nodes; ++k) attach[k] = 0.2 + 0.05 * double(k % 4);
    if (!cyclic) attach.front() = attach.back() = 0;
    Strip s = make_strip(cyclic, rest, K, 0.2, attach);
    for (size_t k = 0; k < nodes; ++k) s.anchor[k] += 0.001 * std::sin(double(k));
    EquilibriumFactor f;
    solve_equilibrium(s, &f);
    ASSERT_TRUE(f.valid);
    // Split element i in two stiffer halves with a soft element between (what a break does).
    Element left = s.elements[i], right = left, middle;
    left.rest = right.rest = 0.5 * s.elements[i].rest;
    left.stiffness = right.stiffness = 2 * s.elements[i].stiffness;
    middle.kind = ElementKind::Fracture;
    middle.stiffness = 0.3;
    s.elements[i] = left;
    s.elements.insert(s.elements.begin() + long(i) + 1, {middle, right});
    const double xb = s.x[i] + 0.5 * (s.x[i + 1] - s.x[i]);
    s.x.insert(s.x.begin() + long(i) + 1, {xb, xb});
    s.anchor.insert(s.anchor.begin() + long(i) + 1, {xb, xb});
    s.attach.insert(s.attach.begin() + long(i) + 1, {0.0, 0.0});
    s.attach[i + 1] = 0.15;
    s.attach[i + 2] = 0.15;  // nodes from i on may change; those before may not
    Strip fresh = s;
    f.valid = false;
    f.kept = cyclic ? i : i - 1;
    solve_equilibrium(s, &f);
    solve_equilibrium(fresh);
    ASSERT_EQ(s.x.size(), fresh.x.size());
    for (size_t k = 0; k < s.x.size(); ++k) EXPECT_EQ(s.x[k], fresh.x[k]) << (cyclic ? "cyclic" : "open") << " node " << k;
    EXPECT_LT(equilibrium_residual(s), 1e-12);
  }
}

TEST(StripEquilibrium, UniformTensionWhenNothingIsAttached) {
  Strip s = make_strip(true, {0.3, 0.2, 0.4, 0.1}, {1, 3, 0.5, 2}, 1.2);
  solve_equilibrium(s);
  const double T = (1.2 - 1.0) / (1 + 1.0 / 3 + 2 + 0.5);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(element_tension(s, i), T, 1e-14);
  double mean = 0;
  for (size_t i = 0; i < 4; ++i) mean += s.x[i] - s.anchor[i];
  EXPECT_NEAR(mean, 0.0, 1e-14);  // the free rotation is fixed
}

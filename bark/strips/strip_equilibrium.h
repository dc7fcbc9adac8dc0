// Quasi-static equilibrium of one strip (Lefebvre & Neyret 2002, sec. 3.2.2 and 5.1).
#pragma once

#include <cmath>
#include <vector>

#include "bark/strips/strip.h"

namespace phellem::bark {

// The elimination of one strip's equilibrium matrix, kept between solves. The matrix depends
// only on the element and attachment stiffnesses, which change when a strip breaks, hardens
// or (with a non-constant K_f curve) when its fractures open; growth and plasticity only move
// the anchors, i.e. the right-hand side. Whoever changes a stiffness clears `valid`; a solve
// with a valid factor gives the same bits as one that eliminates again.
struct EquilibriumFactor {
  // 1 / pivot of each row. The eliminated super-diagonal c'_i = -K_i / pivot_i is not kept: it
  // is recomputed as -K · inv (the same product the elimination makes, so the same bits), one
  // array fewer for every step to stream.
  std::vector<double> inv;
  std::vector<double> u;   // cyclic strips: A'^-1 u of Sherman–Morrison
  double denominator = 0;  // cyclic strips: 1 + vᵀ A'^-1 u
  double gamma = 0;        // cyclic strips: γ = -A[0][0]
  bool valid = false;
  // When not valid: rows [0, kept) of inv still hold (their
  // elements and attachment did not change, e.g. before a break further along the strip), so
  // elimination resumes there; the Sherman–Morrison vector is redone in full.
  size_t kept = 0;
};

// Moves the nodes of `strip` to the exact equilibrium of its elements and attachment springs
// (sec. 5.1):  -K_i (x_i - x_{i-1} - l0_i) + K_{i+1} (x_{i+1} - x_i - l0_{i+1}) - K_a (x_i - a_i) = 0
// for every free node. (The paper writes +K_a(x_i - a_i); a spring pulling the node back to
// its substrate point enters with the opposite sign of its displacement.)
// Cyclic strips: x_{i+n} = x_i + C; a cyclic tridiagonal system solved by Sherman–Morrison
// and two Thomas sweeps, O(n). Without any attachment the equilibrium has one uniform
// tension T = (C - Σ l0) / Σ 1/K (sec. 3.2.2) and the rigid rotation is fixed by keeping
// the mean displacement from the anchors zero. Open strips keep both end nodes fixed.
// `factor` (optional) is used if valid, and built (and marked valid) otherwise.
void solve_equilibrium(Strip& strip, EquilibriumFactor* factor = nullptr);

// The two recurrences of a solve with an eliminated matrix, written so that the chain through
// the running value p is one fused multiply-add (the rest does not wait for p): a forward row
// (rhs + K_left p) / pivot, with inv = 1 / pivot, and a back row r - c' p. std::fma is exactly
// rounded, so the bits are the same on every machine, with or without an FMA unit.
inline double forward_row(double rhs, double k_left, double inv, double p) { return std::fma(k_left * inv, p, rhs * inv); }
inline double back_row(double r, double cprime, double p) { return std::fma(-cprime, p, r); }

// Where the processor has FMA instructions (x86-64-v3), the hot solves are compiled a second
// time to use them, chosen when the program loads; elsewhere std::fma is done in software.
// (The build turns off implicit contraction, so both compilations give the same bits.)
// Not under ThreadSanitizer: it instruments the clones' resolver, which the loader runs
// before the sanitizer's runtime is up (the program then crashes at load).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__SANITIZE_THREAD__)
#define PHELLEM_FMA_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define PHELLEM_FMA_CLONES
#endif

// Largest nodal force imbalance relative to the largest force in the strip (element tension
// or attachment force); 0 for a strip without free nodes.
double equilibrium_residual(const Strip& strip);

// Tension K (L - l0) of element i at the strip's current node positions.
double element_tension(const Strip& strip, size_t i);

}  // namespace phellem::bark

// Relaxation of the stress field (Spicker 2014 sec. 3.1.4, eqs. 7–9): stress flows from
// regions of high stress to regions of low stress through the virtual displacement the forces
// would cause; the vertices do not move.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "bark/stress/stress_forces.h"

namespace phellem::bark {

// One relaxation step with time step Δt (stress in units of the membrane modulus, so Δt is
// dimensionless): Δp_n = Δt F_n / k_n (eq. 7), Δσ = ∂ε/∂p_n Δp_n (eq. 8) with
// ∂ε_ij/∂p_[n]r = ½(β_ni Σ_m p_[m]r β_mj + β_nj Σ_m p_[m]r β_mi) (eq. 9). `forces` must be those of
// the current σ. Adds Δp to `displacement` (per vertex, the virtual displacement of
// sec. 3.1.6) when given. Faces in parallel; the result does not depend on the thread count.
//
// k_n = Σ_{faces t ∋ n} A_t |∇b_n|² (dimensionless, ≈ 3.5 at a vertex of a regular mesh) is
// the vertex's stiffness: eq. 7 taken literally is an explicit step whose stability depends on
// the ratio of neighbouring triangle sizes, and it diverges as soon as a crack puts a small
// triangle next to large ones (the thesis's κ clamp only delays it). With the per-vertex time
// step Δt / k_n (Jacobi scaling) the step's stability no longer depends on the triangle sizes
// (measured stable at Δt = 0.5 on cracked jittered meshes, diverging at 1), and the stress
// energy still falls monotonically.
// `stiffness`: vertex_stiffness(m) if the caller has it (it changes only with the mesh).
void relax(StressMesh& m, const StressTopology& t, const ForceField& forces, double dt,
           std::vector<Eigen::Vector3d>* displacement = nullptr, const std::vector<double>* stiffness = nullptr);

// k_n per vertex (see relax()).
std::vector<double> vertex_stiffness(const StressMesh& m, const StressTopology& t);

// Σ_faces A ‖σ‖²_F: relaxation lowers it (by 2Δt Σ_n |F_n|² / k_n to first order in Δt).
double stress_energy(const StressMesh& m);

}  // namespace phellem::bark

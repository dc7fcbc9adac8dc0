// Nodal forces of the stress field (Spicker 2014 sec. 3.1.2, after Iben & O'Brien 2006 and
// O'Brien & Hodgins 1999): eq. 1 for each face, the tensile/compressive split of eqs. 2–3.
#pragma once

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

#include "bark/stress/stress_mesh.h"
#include "bark/stress/stress_topology.h"

namespace phellem::bark {

// Eqs. 2–3: σ⁺ = Σ max(0, vᵢ) n̂ᵢn̂ᵢᵀ and σ⁻ = Σ min(0, vᵢ) n̂ᵢn̂ᵢᵀ over σ's eigenpairs.
std::pair<Eigen::Matrix2d, Eigen::Matrix2d> split_stress(const Eigen::Matrix2d& sigma);

// Eq. 1: the force σ applies to each vertex of face f (in vertices(f) order):
// f_i = −A Σ_j p_j Σ_k Σ_l β_jl β_ik σ_kl.
std::array<Eigen::Vector3d, 3> nodal_forces(const StressMesh& m, FaceId f, const Eigen::Matrix2d& sigma);

// The forces of every face at every corner, and their sums per vertex.
struct ForceField {
  // Per slot 3f + i: the tensile (σ⁺) and compressive (σ⁻) force of face f on its vertex i.
  // (Without the split: `tensile` holds the total force of σ.)
  std::vector<Eigen::Vector3d> tensile, compressive;
  // Per vertex (v.idx()): F = Σ over adjacent faces of f⁺ + f⁻, the force of eq. 7.
  std::vector<Eigen::Vector3d> total;
};
// Faces in parallel, then vertices in parallel (each sums its corners in a fixed order): the
// result does not depend on the thread count. `split`: also the tensile/compressive parts
// (the separation tensor needs them; relaxation needs only the totals).
void compute_forces(const StressMesh& m, const StressTopology& t, ForceField& out, bool split = true);

}  // namespace phellem::bark

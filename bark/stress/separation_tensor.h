// The separation tensor ς of a vertex (Spicker 2014 eq. 4, after O'Brien & Hodgins 1999):
// how strongly the adjacent faces pull the vertex apart, and in which direction.
#pragma once

#include <Eigen/Core>

#include "bark/stress/stress_forces.h"

namespace phellem::bark {

// Eq. 4: ς = ½(−m(f⁺) + Σ_{f∈{f⁺}} m(f) + m(f⁻) − Σ_{f∈{f⁻}} m(f)), f⁺ and f⁻ the sums of the
// adjacent faces' tensile and compressive forces on v. Symmetric by construction. m(a) =
// a aᵀ / |a| (0 for a = 0) is O'Brien & Hodgins' outer product, which keeps ς in force units.
// (The thesis writes the bare outer product; with it τ would be a squared force.)
Eigen::Matrix3d separation_tensor(const StressTopology& t, const ForceField& forces, uint32_t v);

}  // namespace phellem::bark

// One step of the cambium's motion (Kratt et al., Woodification, Eq. 1: ẋ = s(x, t)·n(x)):
// every interface vertex of a TetComplex moves along its normal (the area-weighted normal of
// its interface faces) by the growth function's thickening over the step, and every
// tetrahedron stays positively oriented (CGAL's exact predicate): a move that would invert
// one is halved, up to kMaxHalvings times, then dropped (the vertex is clamped for this
// step). Afterwards the free vertices (neither on the interface nor on the box) are smoothed
// towards their neighbours' mean where that keeps every tetrahedron positive, making room
// for the next step.
// Not yet here (issue 24, to come): the local repair of deformable simplicial complexes
// (flips, splits, collapses) that keeps interface edges in a length band, obstacles and
// contact, rings, UVs and crack coupling.
#pragma once

#include "bark/growth/tet_complex.h"
#include "bark/growth/weibull_growth.h"

namespace phellem::bark {

struct InterfaceStepStats {
  long moved = 0;       // interface vertices that moved their full distance
  long shortened = 0;   // ... that moved part of it (halved)
  long clamped = 0;     // ... that could not move without inverting a tetrahedron
  long smoothed = 0;    // free vertices moved by the smoothing
};

// The area-weighted outward normals of the interface faces at each point (0 elsewhere), from
// `faces` = c.interface_faces() when the caller has them already.
std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces);
std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c);

// Moves the interface from age t0 to age t1 (years). Deterministic: the same complex and
// ages give the same result.
InterfaceStepStats advance_interface(TetComplex& c, const GrowthFunction& growth, double t0, double t1);

}  // namespace phellem::bark

// One step of the cambium's motion (Kratt et al., Woodification, Eq. 1: ẋ = s(x, t)·n(x)):
// every interface vertex of a TetComplex moves along its normal (the area-weighted normal of
// its interface faces) by the growth function's thickening over the step, and every
// tetrahedron stays positively oriented (CGAL's exact predicate): a move that would invert
// one is halved, up to kMaxHalvings times, then dropped (the vertex is clamped for this
// step). A move that would flatten or invert a tetrahedron first goes as far as it can, then
// the DSC's local retessellation (tet_flips.h: flips of outside tetrahedra, relocation of free
// vertices) removes what blocks it and the motion continues, for a few rounds (sec. 3: "the
// vertex motion is temporarily limited to the point where it yields a degenerate (flat)
// tetrahedron, which is removed by a local retesselation allowing the vertex motion to
// continue"). Afterwards the free vertices near the interface (within two rings of it) are
// smoothed towards their neighbours' mean where that keeps every tetrahedron positive and does
// not lower their worst quality, making room for the next step.
// The rest of the step's repair (splits, collapses, quality flips) is growth_repair_step
// (complex_repair.h); obstacles and contact are growth_contact.h, cracks growth_cracks.h.
// Strokes with a direction and painted directions (sec. 4.4, TetComplex::direction) turn a vertex's move off its normal; its UV then moves
// with the tangential part through the texture Jacobian (sec. 4.6, texture_transport.h).
#pragma once

#include "bark/growth/tet_adjacency.h"
#include "bark/growth/weibull_growth.h"

namespace phellem::bark {

struct InterfaceStepStats {
  long moved = 0;       // interface vertices that moved their full distance
  long shortened = 0;   // ... that moved part of it (halved)
  long clamped = 0;     // ... that could not move without inverting a tetrahedron
  long smoothed = 0;    // free vertices moved by the smoothing
  long flips = 0;       // 2-3 and 3-2 flips made to unblock moves
  long relocated = 0;   // free vertices moved to unblock moves
  long removed = 0;     // free vertices collapsed away to unblock moves
  bool upkeep = true;   // the free rings were carried and smoothed this step (VolumeUpkeep)
  // Where the time goes (s): carrying the free rings, the moves, unblocking them, smoothing.
  double carry_s = 0, moves_s = 0, unblock_s = 0, smooth_s = 0;
};

// The area-weighted outward normals of the interface faces at each point (0 elsewhere), from
// `faces` = c.interface_faces() when the caller has them already.
std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces);
std::vector<Eigen::Vector3d> interface_normals(const TetComplex& c);

// Moves the interface from age t0 to age t1 (years). Deterministic: the same complex and
// ages give the same result.
InterfaceStepStats advance_interface(TetComplex& c, const GrowthFunction& growth, double t0, double t1);
// The same, keeping an adjacency the caller goes on using in step.
InterfaceStepStats advance_interface(TetComplex& c, TetAdjacency& adj, const GrowthFunction& growth, double t0, double t1);
// The same with the interface faces (interface_faces(c, adj)) the caller has already: the
// motion moves points and retessellates only outside tetrahedra, so they hold after it too.
// With `owed` (one value per point, grown with the points, new points 0), a vertex whose move
// was shortened or clamped owes the rest, in metres along its growth direction, and catches up
// by at most its own step's thickening on each later step: a move blocked for a while by the
// mesh, not by an obstacle, leaves no lasting pit, and the surface converges to the offset the
// growth function integrates to.
//
// With `upkeep`, the upkeep of the volume in front of the interface (carrying its free rings
// ahead of it, smoothing them) runs once for several steps instead of every step: it carries
// the rings as far ahead as that many steps of this one's thickening, as many as fit within
// upkeep->reach (at least one, at most VolumeUpkeep::kMaxSteps), and the steps in between only
// move the interface into the room made. InterfaceStepStats::upkeep says which steps ran it.
struct VolumeUpkeep {
  static constexpr int kMaxSteps = 8;
  double reach = 0;    // m: how far ahead of the front a carry may go (0: one step, every step)
  int steps_left = 0;  // steps the last carry still covers
};
InterfaceStepStats advance_interface(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                     const GrowthFunction& growth, double t0, double t1, std::vector<double>* owed = nullptr,
                                     VolumeUpkeep* upkeep = nullptr);

}  // namespace phellem::bark

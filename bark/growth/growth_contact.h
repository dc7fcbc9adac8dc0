// Contact of the growing front (Kratt et al., Woodification, sec. 4.5): "the DSC propagates
// each moving front vertex until it reaches a tetrahedral face. If this face is also the face
// of an obstacle ... that vertex is 'frozen' at the point of collision", and when the front
// meets itself (or another front) it keeps "precise contact after self collision ... by a
// similar freezing procedure", creating a crease wound "that realistically persists through
// future growth iterations".
// Here the motion (interface_motion.h) never lets a vertex cross a face of the complex, because
// every tetrahedron stays positive and obstacle points are frozen; freeze_contacts, called by
// the integrator after each motion step, freezes the interface vertices that came within `gap`
// of an obstacle or of another part of the interface, so that they stay put from then on
// (frozen is never cleared): the fronts stop in contact, a gap below `gap` apart, and never
// merge or pass through each other.
#pragma once

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

struct ContactStats {
  long obstacle = 0;  // interface vertices newly frozen against an obstacle face
  long front = 0;     // ... against another part of the interface (another front or a crease)
};

// Freezes every interface vertex that is not frozen yet and lies closer than `gap` (m, > 0) to
//  - a face of an obstacle (boundary_faces(kObstacle)), or
//  - an interface face that faces it (the face's normal and the vertex's normal make more than
//    a right angle) and has no corner near it along the interface: neither within two edges
//    of it nor within kNearGaps × gap of it along interface edges (so the vertex's own sheet,
//    however finely split, never counts; a distant part of the same front does: a crease).
// Decisions are taken on the complex as it is on entry and applied together: the result does
// not depend on vertex order or thread count. Distances through a CGAL AABB tree.
ContactStats freeze_contacts(TetComplex& c, double gap);
// The same with the interface faces (sorted, as TetComplex::interface_faces() gives them) and
// the obstacles' boundary faces the caller has already.
ContactStats freeze_contacts(TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces,
                             const std::vector<std::array<uint32_t, 3>>& obstacle_faces, double gap);

inline constexpr double kNearGaps = 4.0;

}  // namespace phellem::bark

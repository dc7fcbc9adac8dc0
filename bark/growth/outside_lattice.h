// Steiner points that grade the volume around the surface before TetGen refines it (Kratt et
// al., Woodification, sec. 3: the surface is embedded in a tetrahedralized box whose exterior
// mesh the interface grows into). Without them TetGen starts from the box's 8 corners and the
// surface: its first Delaunay mesh is all needles from the surface to the far corners, whose
// circumspheres are huge, so each quality (q) Steiner point's cavity holds a large part of the
// mesh and the refinement is quadratic (10.9 s of set-up at 8000 triangles, 52 s at 20000).
// Lattice points in shells around the surface, their spacing doubling with the distance (an
// octree's grading), start it from well-shaped tetrahedra at every scale: the refinement only
// has the thin band next to the surface left to fill.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// Points of the body-centred cubic lattices of spacing h = spacing·2^l (l = 0, 1, ...; aligned
// at lo) inside the box [lo, hi], at least h/2 from its faces, whose distance d to the nearest
// triangle of `meshes` lies in [h, 2h) (the coarsest level: every d ≥ h), each nudged by up to
// 1 % of h on each axis so that no four are exactly coplanar. Deterministic, in lattice order.
std::vector<Eigen::Vector3d> outside_lattice(const std::vector<const TriMesh*>& meshes, const Eigen::Vector3d& lo,
                                             const Eigen::Vector3d& hi, double spacing);

}  // namespace phellem::bark

// CGAL Surface_mesh from and to Phellem's TriMesh in an order that depends on the geometry
// alone: CGAL's corefinement numbers what it makes in an order that depends on where its boxes
// were allocated (it breaks ties between boxes by address), so the same inputs came out in
// different orders from call to call, and every step after it (stitching, remeshing, caps,
// the output's order) follows that numbering. Shared by the tree junctions and the
// procedural branch junction.
#pragma once

#include <optional>

#include "bark/geometry/tri_mesh.h"
#include "bark/stress/stress_mesh.h"

namespace phellem::bark {

// Vertices welded by exact position (a diced tube or a log repeats its seam column);
// degenerate faces and faces that would make the surface non-manifold are left out.
SurfaceMesh welded_surface_mesh(const TriMesh& t);

// The mesh rebuilt with its vertices in lexicographic order of position and its faces in
// order of their corners (each turned to start at its smallest, orientation kept), keeping
// the edges flagged in `flag` (which is replaced by the new mesh's map of the same name).
// Empty if the faces do not make a manifold surface again.
std::optional<SurfaceMesh> canonical(const SurfaceMesh& m, SurfaceMesh::Property_map<EdgeId, bool>& flag);

}  // namespace phellem::bark

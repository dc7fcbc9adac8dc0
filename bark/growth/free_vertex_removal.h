// Removal of free vertices (deformable simplicial complexes, Misztal and Bærentzen; Kratt et
// al., Woodification, sec. 3): a growing interface pushes the free vertices in front of it
// together, and their tetrahedra flatten between it and them until every move is blocked. No
// flip removes a vertex; collapsing it into one of its neighbours does: the tetrahedra around
// the edge w–u disappear and every other tetrahedron around w takes u instead (a cone from u
// over the boundary of w's star, which tiles the star exactly when every new tetrahedron is
// positive, by the exact predicate).
#pragma once

#include "bark/growth/tet_flips.h"

namespace phellem::bark {

// Collapses free vertex w (not on the interface, the box, or frozen; every tetrahedron around
// it of one label, not an obstacle) into the neighbour that leaves the best worst quality
// (measured with the probe), if every new tetrahedron is positive, none has four interface
// corners, no new edge joins two interface points through the outside, and the worst quality
// rises. True if it did (w is then unused); counted in stats.removed.
bool remove_free_vertex(TetComplex& c, TetAdjacency& adj, uint32_t w, const Probe& probe, FlipStats& stats);

}  // namespace phellem::bark

// Re-tetrahedralization of the growth volume around the interface as it is now. The local
// repair of deformable simplicial complexes (complex_repair.h) keeps the tetrahedra next to
// the interface positive, but over a growth of several edge lengths the volume in front of
// the front is pushed together and the volume behind it stretched, until most moves are
// blocked and the blocked vertices lag as pits (measured on a jittered log grown to twice its
// radius: 60 % of the moves shortened by the last step, a worst lag of 70 mm). TetGen run
// again on the interface (and the obstacles) gives well-shaped tetrahedra at once; the
// interface itself does not change: switch Y keeps its vertices and triangles.
#pragma once

#include <string>
#include <vector>

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

// Replaces the tetrahedra of c by TetGen's of its current interface and `obstacles` (as given
// to tetrahedralize_surface). The interface points keep their indices, positions and every
// per-point attribute (uv, source vertex, speed, frozen, crack flags and parents), so vertex
// identity holds across it (thesis sec. 5); TetGen's other points take the indices of the
// points that were not on the interface, then new ones. The labels follow the interface's
// orientation. False, with c unchanged, when TetGen refuses the interface or would change it
// (a point lying on one of its triangles: the interface folded onto itself).
bool retetrahedralize(TetComplex& c, const std::vector<GrowthObstacle>& obstacles, const TetSettings& settings,
                      const std::string& file, const std::string& where);

}  // namespace phellem::bark

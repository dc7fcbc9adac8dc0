// Joining a tree's tubes into one surface at their branchings, so that what runs over the
// bark (stress-field cracks) can cross a junction instead of stopping where two separately
// diced tubes pass through each other.
#pragma once

#include <string>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

struct JoinedTubes {
  TriMesh mesh;  // one vertex per triangle corner (a corner's UV is its own part's)
  // Branches that could not be joined (no closed intersection with their parent, or CGAL
  // refused the meshes), with the reason; those are kept as separate tubes.
  std::vector<std::string> not_joined;
  int caps = 0;  // open ends closed
};

// `parts[0]` is the trunk; part k > 0 leaves `parts[parent[k]]` (parent[k] < k) with its base
// inside it. Each branch is cut along its intersection with the surface built so far (CGAL
// corefinement); the branch's piece inside and the surface's piece inside the branch are
// dropped, and the two are stitched along the intersection curve; the open ends are closed
// with flat caps refined to the density around them. Each output corner takes
// its UV from the part its face lies on, through that part's triangle under the face's centre
// (extrapolated), so UV seams stay seams and the junction curve becomes one.
JoinedTubes join_tubes(const std::vector<TriMesh>& parts, const std::vector<int>& parent);

}  // namespace phellem::bark

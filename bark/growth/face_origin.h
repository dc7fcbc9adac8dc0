// Where a grown face came from: the nearest face of the surface before growth to its centre
// (CGAL's AABB tree). Growth moves the surface along its normals, so for growth that is small
// against the features of the input the nearest input face is the one it grew from; used to
// keep the materials a mesh file gives its parts (glTF primitives) on the grown surface.
#pragma once

#include <cstdint>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// Per face of `grown`, the index of the face of `input` nearest to its centroid (the same at any
// thread count: the tree is built alike every time and each face is its own query).
std::vector<uint32_t> nearest_input_faces(const TriMesh& input, const TriMesh& grown);

}  // namespace phellem::bark

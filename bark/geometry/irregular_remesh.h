// Preprocessing for the stress model (Spicker 2014 sec. 3.1.4: "regular meshes result in
// unnatural regular crack patterns and pre-existing sliver triangles can pose problems"): an
// isotropic remesh (CGAL) to well-shaped triangles of a target edge length, then a random
// tangential jitter of the vertices, projected back onto the input surface (onto the smooth
// surface its triangles sample, not their flat facets). UV seams, sharp
// edges and borders are kept as constrained polylines, and each new corner takes its UV from
// the input face of its own UV chart that it projects onto, so seams stay seams and textures
// do not slide.
#pragma once

#include <cstdint>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

struct RemeshOptions {
  double edge_length = 0;       // target (m); 0: the input's mean edge length
  double jitter = 0.3;          // tangential jitter, fraction of the edge length
  double sharp_angle_deg = 60;  // dihedral angles sharper than this are kept as features
  int iterations = 3;
  bool smooth = true;  // move the vertices onto the smooth (Phong, α = ½) surface of the input's triangles
  uint64_t seed = 1;
};

inline constexpr long long kMaxRemeshTriangles = 20'000'000;

// Throws MeshError (bark/stress/stress_mesh.h) for a mesh that cannot be processed, or (where
// "edge_length") when the edge length would make more than kMaxRemeshTriangles triangles.
TriMesh irregular_remesh(const TriMesh& in, const RemeshOptions& o);

}  // namespace phellem::bark

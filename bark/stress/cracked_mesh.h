// CrackedMesh: the output of the stress-field cracking model (DESIGN.md, bark/stress): the
// triangle mesh with the crack edges inserted, and per vertex the crack width (Algorithm 1),
// the crack component and the virtual displacement (sec. 3.1.6).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

struct CrackedMesh {
  TriMesh mesh;                                      // vertices split where UVs disagree (seams)
  std::vector<std::array<uint32_t, 2>> crack_edges;  // indices into mesh.positions
  std::vector<float> crack_width;                    // per vertex: Algorithm 1, in crack edges (0 off cracks)
  std::vector<int32_t> component;                    // per vertex: crack component, −1 off cracks
  std::vector<Eigen::Vector3f> displacement;         // per vertex: summed virtual displacement
  double crack_length() const;                       // total length of the crack edges (m)
};

}  // namespace phellem::bark

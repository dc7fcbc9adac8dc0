// Test fixture shared by the dressing tests: a 10 cm square in z = 0 with one crack edge of
// Algorithm 1 width 1 across it along x = 0 (vertices 4 and 5), nothing displaced.
#pragma once

#include "bark/stress/cracked_mesh.h"

namespace phellem::test {

inline bark::CrackedMesh cracked_square() {
  bark::CrackedMesh c;
  c.mesh.positions = {{-0.05, -0.05, 0}, {0.05, -0.05, 0}, {0.05, 0.05, 0}, {-0.05, 0.05, 0}, {0.0, -0.05, 0}, {0.0, 0.05, 0}};
  c.mesh.triangles = {{0, 4, 5}, {0, 5, 3}, {4, 1, 2}, {4, 2, 5}};
  c.crack_edges = {{4, 5}};
  c.crack_width = {0, 0, 0, 0, 1, 1};
  c.component = {-1, -1, -1, -1, 0, 0};
  c.displacement.assign(6, Eigen::Vector3f::Zero());
  return c;
}

}  // namespace phellem::test

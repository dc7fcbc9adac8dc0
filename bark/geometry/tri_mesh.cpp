#include "bark/geometry/tri_mesh.h"

#include <Eigen/Geometry>

namespace phellem::bark {

double TriMesh::area() const {
  double a = 0;
  for (const auto& t : triangles)
    a += 0.5 * (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).norm();
  return a;
}

}  // namespace phellem::bark

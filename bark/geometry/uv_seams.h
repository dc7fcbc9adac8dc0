// UV seams of a closed mesh held with one texture coordinate per position (as cambial growth
// holds it: bark/growth/tet_complex.h). A face across a seam of a wrapped parametrization (a
// log's u going from 0.99 to 0.01) would stretch the whole texture backwards over that one
// face; cutting the seam open gives those corners copies of their vertices whose coordinates
// are shifted by whole texture periods, so the face spans a short stretch of a repeating
// texture as its neighbours do.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// A copy of `m` in which every face's texture coordinates lie within half a period (0.5) of
// its first corner's along each axis, corners moved by whole periods onto copies of their
// vertices (one copy per vertex and shift). `source`, when given, receives for every vertex of
// the result the vertex of `m` it copies (the identity on the first m.positions.size()).
// A mesh without UVs is returned as is.
TriMesh cut_uv_seams(const TriMesh& m, std::vector<uint32_t>* source = nullptr);

// b − a the short way across a wrapped seam: each axis shifted by whole periods into [−½, ½].
inline Eigen::Vector2d wrapped_uv_delta(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Eigen::Vector2d d = b - a;
  d.x() -= std::round(d.x());
  d.y() -= std::round(d.y());
  return d;
}

}  // namespace phellem::bark

// What a surface must be for TetGen's labelled volume to have it as its interface (Kratt et
// al., sec. 3: the mesh bounds the wood): closed, a 2-manifold, wound with its normals outwards
// and free of self-intersections. An inside-out surface would label the wood as the outside and
// grow it inwards; a self-intersecting one ("bow-tie") has no consistent inside at all, and
// TetGen may loop for minutes on it. Each is refused as a UserError before TetGen runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

// Throws UserError(file, where, ...) unless every edge of `m` is used exactly once in each
// direction (closed and consistently oriented) and every index names a vertex. `what` names
// the mesh in the message ("the surface to grow", "an obstacle").
void require_closed(const TriMesh& m, const std::string& file, const std::string& where,
                    const std::string& what = "the surface to grow");

// require_closed, then throws UserError(file, where, ...) when a vertex's triangles form more
// than one fan, a connected component encloses a negative volume (inside out), a triangle has
// no area or two triangles intersect (CGAL's exact self-intersection test). Triangles are
// named by `input_face[t]` when given (their index in the mesh the user wrote), else by t.
void require_growable(const TriMesh& m, const std::string& file, const std::string& where,
                      const std::vector<uint32_t>& input_face = {});

}  // namespace phellem::bark

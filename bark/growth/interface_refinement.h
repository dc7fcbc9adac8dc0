// Refinement of the growing interface (deformable simplicial complexes, after Misztal and
// Bærentzen; Kratt et al., sec. 3): as the cambium expands its edges stretch, and an interface
// edge longer than the band's upper bound is split. Every tetrahedron around the edge splits in
// two with its label. The new vertex goes where the ends' normals say the smooth surface is
// (half of Phong tessellation's pull to their tangent planes), or on the chord's midpoint —
// which leaves both halves of a positive tetrahedron positive — when that would invert one.
// Coarsening is in interface_coarsening.h, flips in tet_flips.h, the step's order in complex_repair.h.
#pragma once

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

// Splits interface edges longer than `max_length` (m), longest first, until none is or
// `max_splits` were made; returns the number of splits. Deterministic.
long split_long_interface_edges(TetComplex& c, double max_length, long max_splits = 1000000);
// The same, keeping an adjacency the caller goes on using in step.
long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, double max_length, long max_splits = 1000000);
// The same from the interface faces the caller already has (interface_faces(c, adj) of the
// current complex, in its order).
long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double max_length, long max_splits = 1000000);
// The same, and `edges` becomes the interface's edges afterwards (each once, {a < b}, in no
// particular order): those of `faces` less the split ones, plus the ones the splits made.
long split_long_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                                double max_length, std::vector<std::array<uint32_t, 2>>& edges,
                                long max_splits = 1000000);

// The same where every interface edge longer than `max_length` has an end among `points`
// (after a coarsening, the points its collapses touched): found from their stars, not from a
// scan of the whole interface, with the same result.
long split_long_interface_edges_at(TetComplex& c, TetAdjacency& adj, std::vector<uint32_t> points, double max_length);

// The interface's edges (each once, smaller index first).
std::vector<std::array<uint32_t, 2>> interface_edges(const TetComplex& c);

}  // namespace phellem::bark

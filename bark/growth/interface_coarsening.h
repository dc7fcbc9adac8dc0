// Coarsening of the interface (deformable simplicial complexes, after Misztal and Bærentzen;
// Kratt et al., Woodification, sec. 3: "we can adaptively refine and coarsen the surface mesh"):
// an interface edge shorter than the band's lower bound is collapsed — one end (the removed
// point) merges into the other (the survivor), the tetrahedra around the edge disappear and the
// others keep their labels. A collapse is made only when
//  - the link condition holds in the tetrahedral complex (the result is still a simplicial
//    complex) and on the interface (it stays a closed 2-manifold: the two ends share exactly
//    the two neighbours across the edge),
//  - every resulting tetrahedron is positive (exact predicate) and not much worse in quality,
//  - no frozen or box point moves or disappears, nor a point on a crack (crack coupling: an
//    edge off the crack may still collapse into its crack end).
// Points are never renumbered (vertex identity matters across steps): the removed point stays
// in `points`, used by no tetrahedron, with on_interface cleared.
#pragma once

#include <limits>

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

// Collapses interface edges shorter than `min_length` (m), shortest first (ties by index),
// until none is or none can be, never making an interface edge longer than `max_length`;
// returns the number of collapses. Deterministic.
// With `stretched` given, a collapse that the upper bound refuses is made anyway if no edge
// comes out longer than kStretchedCollapse × `max_length`, and counted there; the caller then
// splits the long edges it made (growth_repair_step does, so every edge ends a step inside the
// band). Where the surface stretches fast (the rims of a log's flat ends, which round into a
// torus as they grow) every edge around a short one is close to the upper bound: refusing its
// collapse left it shrinking step by step until its triangles folded over (the close-up, 60
// steps: 14.4k refusals of edges under 3 mm for the length alone, the first inverted
// interface face at step 23, stuck vertices and pleats from there on).
long collapse_short_interface_edges(TetComplex& c, double min_length,
                                    double max_length = std::numeric_limits<double>::infinity());
long collapse_short_interface_edges(TetComplex& c, TetAdjacency& adj, double min_length,
                                    double max_length = std::numeric_limits<double>::infinity());
// The same from the interface's edges the caller has (each once, {a < b}, any order; e.g. from
// split_long_interface_edges) instead of a scan of every tetrahedron for them. With `touched`
// given, the corners of the tetrahedra around each collapse's ends, before and after it, are
// appended there (repeats included): every edge a collapse made or moved has an end among them.
long collapse_short_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 2>>& edges,
                                    double min_length, double max_length = std::numeric_limits<double>::infinity(),
                                    long* stretched = nullptr, std::vector<uint32_t>* touched = nullptr);
constexpr double kStretchedCollapse = 1.5;

// Collapses the interface edge a–b if the conditions above hold, the removed point merging
// into the survivor (placed at the midpoint when both may move); true if it did.
bool collapse_interface_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b,
                             double max_length = std::numeric_limits<double>::infinity());

}  // namespace phellem::bark

// Local retessellation of deformable simplicial complexes (Kratt et al., Woodification,
// sec. 3: "the vertex motion is temporarily limited to the point where it yields a degenerate
// (flat) tetrahedron, which is removed by a local retesselation allowing the vertex motion to
// continue ... smoothing of the interior/exterior meshes improves performance"; after Misztal
// and Bærentzen). The operations, all on the tetrahedra around the interface:
//  - 2-3 flips (a face shared by two tetrahedra becomes an edge shared by three) and
//  - 3-2 flips (the reverse) and their generalisation, edge removal (4-4, 5-6, 6-8), only
//    among tetrahedra of one label (outside, or inside: the inside stretches behind a growing
//    front as the outside is pushed together in front of it): the union of the flipped
//    tetrahedra keeps its boundary, so no interface face appears or disappears and no label
//    boundary is crossed;
//  - removal of free vertices pressed against the rest (free_vertex_removal.h);
//  - relocation of free vertices (neither on the interface, nor on the box, nor frozen);
//  - splits of long edges of poor outside tetrahedra that are not interface edges (TetGen
//    leaves the outside coarse: needles from an interface face to a far vertex, which no flip
//    or move improves, until new free vertices come near the interface).
// Every result is checked with the exact orientation predicate; an operation is kept only when
// it raises the worst quality (tet_quality) of the tetrahedra it replaces — measured, when an
// interface vertex is blocked, as if that vertex already stood at its destination (a Probe),
// which is what lets the blocked motion continue.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

// Quality is measured as if point v stood at x (no probe: v = kNone).
struct Probe {
  static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  uint32_t v = kNone;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
};

struct FlipStats {
  long flips23 = 0;
  long flips32 = 0;
  long relocated = 0;
  long splits = 0;
  long edge_removals = 0;  // edges of 4 to 6 tetrahedra removed (4-4, 5-6, 6-8 flips)
  long removed = 0;        // free vertices collapsed into a neighbour (free_vertex_removal.h)
};

double probe_quality(const TetComplex& c, const std::array<uint32_t, 4>& t, const Probe& probe);

// The ring of edge a–b from the tetrahedra around it (adj.edge_tets): its vertices in order
// round the edge, tetrahedron ring_tet[i] joining ring[i] to ring[i + 1] (cyclically). False
// unless they close once round the edge through distinct vertices.
bool edge_ring(const TetComplex& c, const std::vector<uint32_t>& around_ab, uint32_t a, uint32_t b,
               std::vector<uint32_t>& ring, std::vector<uint32_t>& ring_tet);

// Replaces the tetrahedra `old` (indices) by `made` (labels[i] for made[i]): the old slots are
// reused in ascending order, then the rest of `made` appended or the rest of the slots erased
// (the last first, so the indices left stay valid).
void replace_tets(TetComplex& c, TetAdjacency& adj, std::span<const uint32_t> old, std::span<const std::array<uint32_t, 4>> made,
                  std::span<const uint8_t> labels);

// The 2-3 flip of the face opposite corner f of tetrahedron t; false (nothing changed) unless
// both tetrahedra have one label (not obstacle), the three new ones are positive and the
// worst quality rises (outside, no new edge may join two interface points).
bool flip_23(TetComplex& c, TetAdjacency& adj, uint32_t t, int f, const Probe& probe, FlipStats& stats);
// The 3-2 flip removing edge a–b; false unless exactly three tetrahedra of one label surround it,
// the two new ones are positive and the worst quality rises.
bool flip_32(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, const Probe& probe, FlipStats& stats);
// Edge removal, the 3-2 flip's generalisation: the n ≤ max_ring tetrahedra of one label around
// edge a–b become 2(n − 2) (a fan of the ring from its best vertex, joined to a and to b);
// false unless they close around the edge, all new ones are positive, none has four interface
// corners (nor, outside, joins two interface points by a new edge), and the worst quality rises.
bool remove_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, const Probe& probe, FlipStats& stats,
                 int max_ring = 6);
// Moves a free vertex to the best of a few candidates (its neighbours' mean, pushes away from
// its worst tetrahedron's opposite face) if that raises its worst quality.
bool relocate_free_vertex(TetComplex& c, TetAdjacency& adj, uint32_t v, const Probe& probe, FlipStats& stats);

// Removes the tetrahedra around interface vertex v that keep it from reaching `target`
// (those that would be flat or inverted there): flips their faces and edges opposite v,
// removes or relocates their free vertices. True if anything changed.
bool unblock_vertex(TetComplex& c, TetAdjacency& adj, uint32_t v, const Eigen::Vector3d& target, FlipStats& stats);

// Splits the edge a–b of the complex at its midpoint (every tetrahedron around it in two, with
// its label); the new point is free. For edges that are not interface edges and not both on
// the box. Returns the new point.
uint32_t split_free_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, FlipStats& stats);

// Quality repair around the given points (sorted): the tetrahedra (not obstacles) that use them and
// whose quality is below `threshold` are improved, worst first, by flips, else by splitting
// their longest edge that is not between interface points if it is longer than `max_length`,
// else (with `relocate`) by relocation; for up to `passes` passes. Deterministic.
FlipStats improve_tets_near(TetComplex& c, TetAdjacency& adj, const std::vector<uint32_t>& points, double threshold,
                            double max_length, int passes = 2, bool relocate = false);

}  // namespace phellem::bark

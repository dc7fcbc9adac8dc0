// Interface edge flips of the deformable simplicial complex (Kratt et al., Woodification,
// sec. 3; after Misztal and Bærentzen, whose DSC improves the interface's triangles by
// flipping its edges as well as splitting and collapsing them).
// The interface edge a–b between faces a–b–p and b–a–q becomes the edge p–q: the tetrahedra
// around a–b are made again as two fans, one of the inside part of the edge's ring (from p
// through the inside to q) and one of its outside part (from q through the outside back to
// p), each joined to a and to b. The diagonal p–q closes both parts, so the faces a–p–q and
// b–q–p lie between an inside and an outside tetrahedron: they are the new interface faces.
// Splits of long edges leave flat triangles where the surface stretches unevenly (the rims of
// a log, stretched round and across at once); a flat triangle's tetrahedra flatten with it and
// block the motion, and its edges cannot collapse. Flipping the edge opposite the obtuse
// angle is the cure planar meshing uses (the Delaunay flip), made here only where the two faces
// are nearly coplanar, so the surface keeps its shape.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

struct InterfaceFlipSettings {
  double min_opposite_deg = 240;  // the angles opposite a–b must sum to more than this
  double max_turn_deg = 40;       // the two faces' normals at most this far apart
  double max_gap = 0.05;          // the two diagonals at most this × the shorter apart
  // How far a flip may move the surface inwards (cutting a ridge) and outwards (filling a
  // valley), in metres, plus half the least distance its four corners moved this step when
  // `moved` is given (per point). Growth keeps each step's surface outside the last one's (its
  // rings nest): CambialGrowth gives max_inward 0 and the step's moves, so a ridge is cut only
  // by half of what its corners have just grown (reversed growth: the same outwards).
  double max_inward = std::numeric_limits<double>::infinity();
  double max_outward = std::numeric_limits<double>::infinity();
  const std::vector<double>* moved = nullptr;
};

// Flips interface edge a–b if the faces on it are nearly coplanar (max_turn_deg, and the
// diagonals a–b and p–q at most max_gap × the shorter apart), the angles
// opposite it sum past min_opposite_deg, the new edge is at most max_length long and not yet
// an edge, neither end is fixed (frozen, or on a crack), and every new tetrahedron is positive
// (exact predicate), has a corner off the interface and a quality of at least the worst it
// replaces or 0.05. False, and nothing changed, otherwise.
bool flip_interface_edge(TetComplex& c, TetAdjacency& adj, uint32_t a, uint32_t b, double max_length,
                         const InterfaceFlipSettings& settings = {});

// Tries every edge of `faces` (the interface faces, as interface_faces gives them) whose faces
// meet the angle tests, the flattest first (largest opposite angles; ties by index), skipping
// edges whose faces an earlier flip of this call changed. Returns the flips made.
// Deterministic.
long flip_interface_edges(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                          double max_length, const InterfaceFlipSettings& settings = {});

}  // namespace phellem::bark

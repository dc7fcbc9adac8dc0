// Crack insertion (Spicker 2014 sec. 3.1.3, Figure 13): crack edges from a crack vertex in
// the crack direction to the boundary of the face each starts in, with the additional edges a
// valid triangulation needs, snapping onto an existing edge below the snap angle.
#pragma once

#include <Eigen/Core>
#include <array>

#include "bark/stress/stress_mesh.h"

namespace phellem::bark {

struct CrackInsertOptions {
  double snap_angle = 0.17;       // ESA (radians)
  double stress_alleviation = 0;  // SA: the faces a split creates keep SA × their parent's stress
  double max_beta_sv = 1e300;     // κ × the initial maximum: new faces' β singular values are clamped to it
};

struct CrackSide {
  bool added = false;             // a new crack edge (false: no face in that direction, or the edge was a crack already)
  bool snapped = false;           // onto an existing edge
  bool split = false;             // an edge was split: `tip` is a new vertex on it
  VertexId tip;                   // the crack's end on this side
  VertexId split_from, split_to;  // split: the edge's ends; the tip is at split_t between them
  double split_t = 0;
};

// Inserts the crack through v along ±dir (dir tangent to the surface at v, any length).
// Keeps the mesh a consistently oriented manifold; new faces get their geometry, β (clamped)
// and their parent's stress × SA; UVs are interpolated per face, so UV seams stay seams.
std::array<CrackSide, 2> insert_crack(StressMesh& m, VertexId v, const Eigen::Vector3d& dir, const CrackInsertOptions& o);

// Clamps the singular values of β to at most `max_sv` (the κ dampening of sec. 3.1.4).
void clamp_beta(FaceState& s, double max_sv);

// Smallest interior angle of the triangle (a, b, c), radians.
double min_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace phellem::bark

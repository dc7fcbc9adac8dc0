// The point → tetrahedra adjacency of a TetComplex, the one structure the local operations of
// deformable simplicial complexes (Kratt et al., Woodification, sec. 3; after Misztal and
// Bærentzen) walk: motion checks a vertex's tetrahedra, splits, collapses and flips rewrite
// them. Built in one linear pass (a flat, compressed row per point, in tetrahedron order);
// a row that an operation changes is copied out once into its own vector, so a step that
// touches the few tetrahedra near the interface pays nothing for the rest of the volume.
// Also here: the exact orientation test and the tetrahedron quality every operation uses,
// and the interface faces found through the adjacency (a linear scan, no map).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "bark/growth/tet_complex.h"

namespace phellem::bark {

// The face opposite corner f of a tetrahedron, oriented outwards when the tetrahedron is
// positive.
inline constexpr int kTetFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// orient3d(a, b, c, d) > 0 by CGAL's exact (filtered) predicate.
bool positive_tet_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d);
// The same, decided first in double precision where Shewchuk's static error bound for orient3d
// (its o3derrboundA) makes the sign certain, else by CGAL: the same answer, and most of the
// millions of tests a growth step makes never leave this header.
inline bool positive_tet(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d) {
  const double bx = b.x() - a.x(), by = b.y() - a.y(), bz = b.z() - a.z();
  const double cx = c.x() - a.x(), cy = c.y() - a.y(), cz = c.z() - a.z();
  const double dx = d.x() - a.x(), dy = d.y() - a.y(), dz = d.z() - a.z();
  const double cxdy = cx * dy, dxcy = dx * cy, dxby = dx * by, bxdy = bx * dy, bxcy = bx * cy, cxby = cx * by;
  const double det = bz * (cxdy - dxcy) + cz * (dxby - bxdy) + dz * (bxcy - cxby);
  const double permanent = (std::abs(cxdy) + std::abs(dxcy)) * std::abs(bz) + (std::abs(dxby) + std::abs(bxdy)) * std::abs(cz) +
                           (std::abs(bxcy) + std::abs(cxby)) * std::abs(dz);
  constexpr double kEpsilon = 0x1p-53;  // half an ulp of 1
  constexpr double kBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
  if (det > kBound * permanent) return true;
  if (det < -kBound * permanent) return false;
  return positive_tet_exact(a, b, c, d);
}
inline bool positive_tet(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  return positive_tet(c.points[t[0]], c.points[t[1]], c.points[t[2]], c.points[t[3]]);
}

// Shape quality of a tetrahedron: 6√2·V / ℓ_rms³, 1 for the regular tetrahedron, 0 when flat,
// negative when inverted (the volume–length measure of mesh optimisation).
// Inline: the repair evaluates it millions of times a step (the same operations as out of
// line under -ffp-contract=off, so the same bits).
inline double tet_quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                          const Eigen::Vector3d& d) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ad = d - a;
  const double v = ab.cross(ac).dot(ad) / 6.0;
  const double l2 = (ab.squaredNorm() + ac.squaredNorm() + ad.squaredNorm() + (c - b).squaredNorm() +
                     (d - b).squaredNorm() + (d - c).squaredNorm()) / 6.0;
  if (!(l2 > 0)) return 0;
  return 6.0 * std::sqrt(2.0) * v / (l2 * std::sqrt(l2));
}
inline double tet_quality(const TetComplex& c, const std::array<uint32_t, 4>& t) {
  return tet_quality(c.points[t[0]], c.points[t[1]], c.points[t[2]], c.points[t[3]]);
}

class TetAdjacency {
 public:
  explicit TetAdjacency(const TetComplex& c);

  // The tetrahedra that use point p (in a deterministic order).
  std::span<const uint32_t> around(uint32_t p) const {
    if (p < own_.size() && owned_[p]) return own_[p];
    if (p + 1 >= offset_.size()) return {};
    return {flat_.data() + offset_[p], flat_.data() + offset_[p + 1]};
  }
  bool unused(uint32_t p) const { return around(p).empty(); }

  // Book-keeping of a change of c.tets[t]: call unlink before the tetrahedron's corners change
  // (or it is removed) and link after (or once it is appended). New points need nothing.
  void link(uint32_t t, const std::array<uint32_t, 4>& corners);
  void unlink(uint32_t t, const std::array<uint32_t, 4>& corners);

  // The tetrahedron across the face opposite corner f of tetrahedron t, or −1 (the box).
  // Remembers each answer as a hint for (t, f) and for the face seen from the other side; a
  // hint is used only when it still holds the face (in a complex every face has at most two
  // tetrahedra, so a tetrahedron other than t that holds it is the answer): the result never
  // depends on what an operation left stale, nor on the thread that asked first.
  long across(const TetComplex& c, uint32_t t, int f) const;
  // The tetrahedra that contain both a and b.
  void edge_tets(const TetComplex& c, uint32_t a, uint32_t b, std::vector<uint32_t>& out) const;
  bool has_edge(const TetComplex& c, uint32_t a, uint32_t b) const;

  // Removes tetrahedron t from the complex by moving the last one into its slot (labels
  // follow), keeping the adjacency in step.
  void erase_tet(TetComplex& c, uint32_t t);
  // Replaces tetrahedron t's corners, keeping the adjacency in step.
  void set_tet(TetComplex& c, uint32_t t, const std::array<uint32_t, 4>& corners);
  // Appends a tetrahedron with a label; returns its index.
  uint32_t add_tet(TetComplex& c, const std::array<uint32_t, 4>& corners, uint8_t label);
  // Splits every tetrahedron of `shared` (those around edge a–b) in two at the new point m on
  // the edge, with its label: the half at a's end keeps the slot, the half at b's end is
  // appended.
  void split_edge_tets(TetComplex& c, uint32_t a, uint32_t b, uint32_t m, const std::vector<uint32_t>& shared);

 private:
  std::vector<uint32_t> offset_, flat_;  // compressed rows as built
  std::vector<std::vector<uint32_t>> own_;
  std::vector<uint8_t> owned_;
  // 4 per tetrahedron, read and written through std::atomic_ref (callers ask in parallel);
  // kNoHint where none is known. Grown by add_tet only (never while others read).
  mutable std::vector<uint32_t> hint_;
  static constexpr uint32_t kNoHint = UINT32_MAX;
  std::vector<uint32_t>& row(uint32_t p);
  void hint(uint32_t t, int f, uint32_t u) const;
};

// Whether splitting each tetrahedron of `shared` (those around edge a–b) at the point x leaves
// both halves positive (exact predicate); false when `shared` is empty.
bool split_keeps_positive(const TetComplex& c, uint32_t a, uint32_t b, const Eigen::Vector3d& x,
                          const std::vector<uint32_t>& shared);

// The faces between labels, oriented outwards from the inside (from the tetrahedron with the
// non-zero label; between two non-zero labels, from the later tetrahedron): the same set as
// TetComplex::interface_faces(), in tetrahedron order rather than sorted. Relies on
// c.on_interface being up to date (every operation here keeps it so).
std::vector<std::array<uint32_t, 3>> interface_faces(const TetComplex& c, const TetAdjacency& adj);
// The faces of interface_faces(c, adj) with corner v, in its order, found from v's star.
void interface_faces_at(const TetComplex& c, const TetAdjacency& adj, uint32_t v, std::vector<std::array<uint32_t, 3>>& out);

}  // namespace phellem::bark

// The labelled tetrahedral volume of cambial growth (Kratt et al., Woodification, sec. 3;
// deformable simplicial complexes): TetGen (AGPL-3.0, used through its library interface and
// only here in bark/growth/) tetrahedralizes the region around a closed surface and a padded
// bounding box, keeping the surface's vertices and triangles (switch Y); each tetrahedron is
// labelled inside (1) or outside (0) the surface, and the bark surface is the set of faces
// between the two labels. Orientation is decided by CGAL's exact predicates.
// Obstacles (sec. 4.5): closed meshes embedded in the same volume ("this external tetrahedral
// mesh also conforms to the boundaries of any obstacles"); their tetrahedra are labelled
// obstacle (2) and every corner of an obstacle tetrahedron is frozen, so obstacle faces never
// move. The bark interface is the set of faces between an inside tetrahedron and any other
// label; faces between the outside and an obstacle are not part of it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bark/geometry/tri_mesh.h"

namespace phellem::bark {

struct TetSettings {
  // The box around the surface and every obstacle (their common bounding box), padded on every
  // side by `padding` × the surface's largest extent: an obstacle reaching beyond the surface's
  // padded box enlarges the box so that it lies wholly inside.
  double padding = 0.5;
  double quality = 1.5;          // TetGen's radius-edge bound (switch q)
  double max_volume = 0;         // m³ per tetrahedron (switch a; 0: none)
  // Steiner points TetGen starts from (outside_lattice.h): graded lattices from `lattice` ×
  // the padding away from the surface, which make its set-up near linear (0: none).
  double lattice = 0.2;
  // Seconds TetGen may take for one tetrahedralization (the set-up, or a re-tetrahedralization
  // while growing): past it the set-up is refused and a re-tetrahedralization skipped.
  double time_limit = 120;
};

struct TetComplex {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<uint32_t, 4>> tets;  // positively oriented (orient3d > 0)
  std::vector<uint8_t> label;                 // per tet: kInside, kOutside (or kObstacle)
  std::vector<uint8_t> on_interface;          // per point: 1 if a vertex of an interface face
  std::vector<uint8_t> on_box;                // per point: 1 on the padding box's boundary
  std::vector<uint8_t> frozen;                // per point: 1 if it no longer moves (obstacle, contact)
  // Per point: the texture coordinates carried by the interface (sec. 4.6; empty when the
  // surface has none), and the input surface's vertex it started as (−1 for points TetGen or
  // the refinement added): vertex identity across steps (thesis sec. 5).
  std::vector<Eigen::Vector2d> uv;
  std::vector<int32_t> source_vertex;
  // Per point: the user's speed factor (sec. 4.4, a painted map; empty: 1 everywhere).
  std::vector<float> speed;
  // Per point: a painted growth direction (sec. 4.4; its length, up to 1, is how far it turns
  // the growth from the normal; empty or zero: the normal).
  std::vector<Eigen::Vector3f> direction;
  // Per point, for crack coupling (thesis sec. 5; empty unless cracks are coupled): 1 on a
  // crack edge, so coarsening never collapses it away; and the two points whose edge a split
  // made it on (kNoParent for TetGen's and the input's points), so that a crack edge split by
  // the refinement can be followed to its halves.
  std::vector<uint8_t> on_crack;
  std::vector<std::array<uint32_t, 2>> parents;  // sized lazily: points beyond its end have none
  static constexpr uint32_t kNoParent = 0xffffffffu;

  static constexpr uint8_t kOutside = 0, kInside = 1, kObstacle = 2;

  // The texture coordinates at parameter s from a's to b's: across a wrapped seam (a
  // difference of more than half a period) the short way, so a point split or collapsed there
  // gets a UV next to its neighbours' (possibly outside [0, 1]; textures repeat).
  static Eigen::Vector2d uv_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double s);

  // Appends a point on the segment a–b at parameter s (0: a), interpolating the per-point
  // attributes (uv) and taking the flags both ends share, with a and b as its parents; returns
  // its index. Every change of
  // the complex that adds points goes through here so no per-point array falls out of step.
  uint32_t add_point_between(uint32_t a, uint32_t b, double s);

  // The faces between an inside tetrahedron and one of any other label (outside or obstacle),
  // oriented outwards from the inside (the bark surface), sorted.
  std::vector<std::array<uint32_t, 3>> interface_faces() const;
  // The faces between a tetrahedron labelled `which` and one of another label, oriented
  // outwards from `which`, sorted (boundary_faces(kObstacle): the obstacles' surfaces).
  std::vector<std::array<uint32_t, 3>> boundary_faces(uint8_t which) const;
  // The same, looking only at faces whose three corners have a non-zero `corner` flag (one
  // per point): the same result when every such face has them (on_interface for the
  // interface, frozen for the obstacles), from the few tetrahedra with three such corners
  // instead of all of them.
  std::vector<std::array<uint32_t, 3>> boundary_faces(uint8_t which, const std::vector<uint8_t>& corner) const;
  double volume(uint8_t which) const;  // summed volume of the tetrahedra with that label
  // The first tetrahedron that is not positively oriented by the exact predicate, or −1.
  long first_inverted() const;
};

// An obstacle of growth (sec. 4.5): a closed, consistently oriented mesh (either orientation)
// and where it comes from (a JSON path, e.g. /objects/0/growth/obstacles/1) for errors.
struct GrowthObstacle {
  TriMesh mesh;
  std::string where;
};

// Throws UserError(file, where, ...) when the surface is not closed or TetGen refuses it
// (self-intersections): `where` names the object. With obstacles, throws
// UserError(file, obstacle.where, ...) when an obstacle is not closed, touches, intersects,
// contains or lies inside the surface, or touches, intersects, contains or lies inside an
// earlier obstacle (checked with CGAL's exact predicates before TetGen runs).
TetComplex tetrahedralize_surface(const TriMesh& surface, const std::vector<GrowthObstacle>& obstacles,
                                  const TetSettings& settings, const std::string& file, const std::string& where);
TetComplex tetrahedralize_surface(const TriMesh& surface, const TetSettings& settings, const std::string& file,
                                  const std::string& where);

}  // namespace phellem::bark

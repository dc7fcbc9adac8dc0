// Cambial growth of a closed surface (Kratt et al., Woodification; Spicker 2014 ch. 5): the
// surface becomes the interface of a labelled TetGen volume (tet_complex.h) with the
// obstacles as fixed regions, and each step moves it along its normals by the growth
// function's thickening over the step (Eq. 1–3, interface_motion.h), freezes the vertices
// that reached an obstacle or another front (sec. 4.5, growth_contact.h), then repairs the
// volume in the manner of deformable simplicial complexes (complex_repair.h: splits and
// collapses keep interface edges inside their length band, interface edge flips its triangles
// and other flips the outside well shaped). Every
// `ring_interval` steps the interface is recorded as a growth ring. Reversed growth (sec. 4.3)
// runs the ages backwards: the surface shrinks by the thickening it would have grown.
//
// The stepper holds the complex between steps so callers can look at each step (time-lapse
// frames, crack coupling); it never runs a step by itself.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bark/geometry/tri_mesh.h"
#include "bark/growth/growth_cracks.h"
#include "bark/growth/growth_rings.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/tet_adjacency.h"
#include "bark/growth/tet_complex.h"
#include "bark/growth/weibull_growth.h"

namespace phellem::bark {

struct CambialGrowthSettings {
  GrowthFunction function;
  double age_start = 0, age_end = 1;  // years: the ages of step 0 and of the last step
  int steps = 50;
  double edge_min = 0, edge_max = 0;  // m: the interface's edge-length band (0: from the input's mean edge)
  int ring_interval = 10;             // steps between recorded rings (0: none)
  TetSettings tet;
  bool reverse = false;  // sec. 4.3: shrink from the surface at age_end back to age_start
  double curvature = 0.2;  // forwards: the share of the outward normal Laplacian each step adds (pits catch up)
  // After a step in which more than this share of the interface's moves were shortened or
  // clamped, the volume is tetrahedralized again around the interface (volume_remesh.h; 0:
  // never, the local repair alone), at most once per edge_max of thickening.
  double remesh_blocked = 0.02;
  // The volume's upkeep (VolumeUpkeep in interface_motion.h): the free rings in front of the
  // interface are carried at most this share of the band's lower bound ahead of it, once for
  // as many steps as that covers (0: every step, one step ahead). The tree close-up's steps
  // take half as long at 0.6 as at 0, with fewer blocked moves. Much further than 0.6 is
  // unsafe: a log grown with its rings carried 1.4 of the band's lower bound ahead broke up.
  double upkeep_reach = 0.6;
};

struct CambialGrowthStats {
  size_t vertices_start = 0, vertices_end = 0;  // interface vertices
  size_t tets_start = 0, tets_end = 0;
  long moved = 0, shortened = 0, clamped = 0, splits = 0, collapses = 0, flips = 0, interface_flips = 0;
  long frozen_obstacle = 0, frozen_contact = 0;  // interface vertices stopped by an obstacle, by another front
  double setup_s = 0, steps_s = 0;  // TetGen; all steps (without the crack coupling)
  double cracks_s = 0;              // the crack coupling, all steps
  long remeshes = 0;                // re-tetrahedralizations (volume_remesh.h)
  long remesh_refused = 0;          // ... TetGen refused (the interface touching itself)
  double remesh_s = 0;              // their time (part of steps_s)
  // Where steps_s goes: the interface motion (advance_interface), the curvature term and
  // contact, the local repair; with remesh_s, these add up to steps_s but for book-keeping.
  double motion_s = 0, contact_s = 0, repair_s = 0;
  // Their parts, all steps (interface_motion.h, complex_repair.h); contact_s's curvature term.
  double carry_s = 0, moves_s = 0, unblock_s = 0, smooth_s = 0;
  double flips_s = 0, band_s = 0, removal_s = 0, improve_s = 0;
  double curvature_s = 0;
  long upkeep_steps = 0;  // steps that carried and smoothed the free rings (VolumeUpkeep)
};

// The interface as a compact triangle mesh (outwards), with its UVs when the input had them,
// and for each of its vertices the complex's point (vertex identity across steps).
struct GrowthSurface {
  TriMesh mesh;
  std::vector<uint32_t> point;
};
GrowthSurface extract_interface(const TetComplex& c);
// The same from the interface's faces the caller has, sorted: interface_faces(c, adj) sorted
// are the same faces as c.boundary_faces(kInside, c.on_interface) (test_growth_cracks.cpp
// checks it on a growing log).
GrowthSurface extract_interface(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces);

// The mean edge length of a mesh's triangles (each edge counted once).
double mean_edge_length(const TriMesh& m);

class CambialGrowth {
 public:
  // `surface`: closed and consistently oriented (UserError at file/where otherwise);
  // `obstacles`: closed meshes that do not grow, apart from the surface and each other;
  // `vertex_speed`: empty, or a factor per surface vertex (sec. 4.4's painted map), carried by
  // the interface's points (interpolated where edges split); `vertex_direction`: empty, or a
  // painted growth direction per surface vertex (TetComplex::direction), carried the same way.
  CambialGrowth(const TriMesh& surface, const std::vector<GrowthObstacle>& obstacles, const CambialGrowthSettings& s,
                const std::string& file, const std::string& where, const std::vector<float>& vertex_speed = {},
                const std::vector<Eigen::Vector3f>& vertex_direction = {});

  // Couples the stress-field cracking to the growth (growth_cracks.h): the initial interface
  // cracks now, then again after every step. Throws StressParamError for a parameter the
  // cracking model refuses on this surface.
  void couple_cracks(const StressParams& params, const CrackCouplingSettings& settings);
  // The coupled cracks, or null.
  const GrowthCracks* cracks() const { return cracks_.get(); }

  // One step; false when every step has run.
  bool step();
  int steps_done() const { return step_; }
  int steps_total() const { return settings_.steps; }
  // The age the surface has now (years).
  double age() const;

  const TetComplex& complex() const { return complex_; }
  const std::vector<GrowthRing>& rings() const { return rings_; }
  const CambialGrowthStats& stats() const { return stats_; }
  const CambialGrowthSettings& settings() const { return settings_; }

 private:
  double age_at(int step) const;

  CambialGrowthSettings settings_;
  std::string file_, where_;  // for errors found while stepping
  TetComplex complex_;
  std::unique_ptr<GrowthCracks> cracks_;
  std::optional<TetAdjacency> adjacency_;  // of complex_, kept in step by every operation
  std::vector<double> owed_;               // by point: what blocked moves left (advance_interface)
  std::vector<GrowthObstacle> obstacles_;  // welded, as TetGen had them first (for re-tetrahedralizing)
  std::vector<std::array<uint32_t, 3>> obstacle_faces_;
  std::vector<GrowthRing> rings_;
  CambialGrowthStats stats_;
  int step_ = 0;
  VolumeUpkeep upkeep_;
  double grown_since_remesh_ = 0;  // m: the most thickening since the volume was last made
};

}  // namespace phellem::bark

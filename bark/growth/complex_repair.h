// The repair of the deformable simplicial complex after each motion of the interface
// (Kratt et al., Woodification, sec. 3; Misztal and Bærentzen): in this order
//  0. interface edges opposite an obtuse angle, between nearly coplanar faces, are flipped
//     (interface_flips.h),
//  1. interface edges longer than the band's upper bound are split (interface_refinement.h),
//  2. interface edges shorter than its lower bound are collapsed (interface_coarsening.h),
//  3. the free vertices next to the interface with a poor tetrahedron are removed where that
//     improves it (free_vertex_removal.h),
//  4. the poor tetrahedra around the interface (outside and inside) are flipped, their long
//     free edges split and their free vertices relocated (tet_flips.h), so that the next
//     motion is not blocked.
// When that no longer keeps moves from blocking, CambialGrowth tetrahedralizes the volume
// again (volume_remesh.h).
// A growth step is
//   advance_interface(c, growth, t0, t1);
//   growth_repair_step(c, band_min, band_max);
// Every operation keeps every tetrahedron positive (exact predicate), the labels, and the
// interface a closed oriented 2-manifold. Deterministic, whatever the thread count.
#pragma once

#include "bark/growth/interface_flips.h"
#include "bark/growth/tet_adjacency.h"

namespace phellem::bark {

struct RepairStats {
  long splits = 0;
  long collapses = 0;
  long interface_flips = 0;  // interface edges flipped (interface_flips.h)
  long flips23 = 0;
  long flips32 = 0;      // 3-2 flips and edge removals (4-4, 5-6, 6-8)
  long relocated = 0;
  long removed = 0;      // free vertices collapsed away (free_vertex_removal.h)
  long free_splits = 0;  // splits of long non-interface edges of poor outside tetrahedra
  // Where the time goes (s): interface flips, splits and collapses into the band, removals of
  // pressed free vertices, improving poor tetrahedra.
  double flips_s = 0, band_s = 0, removal_s = 0, improve_s = 0;
};

struct RepairSettings {
  double quality_threshold = 0.01;  // outside tetrahedra below this tet_quality are improved
  int quality_passes = 2;
  // Free vertices next to the interface whose worst tetrahedron is below this are removed
  // (free_vertex_removal.h) where that raises it.
  double removal_quality = 0.1;
  // × max_length: longer free edges of poor tetrahedra are split (0: none; splitting the
  // needles of a coarse outside made the lag worse in the sphere test, so it is off).
  double free_split_length = 0;
  // Interface edge flips (interface_flips.h), with their settings (CambialGrowth sets how far
  // a flip may move the surface against the growth).
  bool interface_flips = true;
  InterfaceFlipSettings flips;
  // The volume's upkeep: removing pressed free vertices and improving poor tetrahedra (off on
  // the steps between two of the motion's upkeep steps, VolumeUpkeep).
  bool upkeep = true;
};

// Band: min_length < max_length / 2 keeps a split edge's halves above the lower bound.
RepairStats growth_repair_step(TetComplex& c, double min_length, double max_length, const RepairSettings& settings = {});
RepairStats growth_repair_step(TetComplex& c, TetAdjacency& adj, double min_length, double max_length,
                               const RepairSettings& settings = {});
// The same from the interface faces the caller already has (interface_faces(c, adj) of the
// current complex, in its order): a growth step finds them once for curvature, contact and
// the splits.
RepairStats growth_repair_step(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                               double min_length, double max_length, const RepairSettings& settings = {});

}  // namespace phellem::bark

#include "bark/growth/complex_repair.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "bark/growth/free_vertex_removal.h"
#include "bark/growth/interface_coarsening.h"
#include "bark/growth/interface_flips.h"
#include "bark/growth/interface_refinement.h"
#include "bark/growth/point_marks.h"
#include "bark/growth/tet_flips.h"
#include "util/stopwatch.h"

namespace phellem::bark {

RepairStats growth_repair_step(TetComplex& c, double min_length, double max_length, const RepairSettings& settings) {
  TetAdjacency adj(c);
  return growth_repair_step(c, adj, min_length, max_length, settings);
}

RepairStats growth_repair_step(TetComplex& c, TetAdjacency& adj, double min_length, double max_length,
                               const RepairSettings& settings) {
  return growth_repair_step(c, adj, interface_faces(c, adj), min_length, max_length, settings);
}

RepairStats growth_repair_step(TetComplex& c, TetAdjacency& adj, const std::vector<std::array<uint32_t, 3>>& faces,
                               double min_length, double max_length, const RepairSettings& settings) {
  RepairStats st;
  Stopwatch clock;
  // The flips first, on the faces as the motion left them: an edge a flip removed is no longer
  // found by the splits and collapses below (they check each edge against the tetrahedra), and
  // the flip's new edge is inside the band's upper bound.
  if (settings.interface_flips) st.interface_flips = flip_interface_edges(c, adj, faces, max_length, settings.flips);
  st.flips_s = clock.lap();
  std::vector<std::array<uint32_t, 2>> edges;  // the interface's edges after the splits
  st.splits = split_long_interface_edges(c, adj, faces, max_length, edges);
  long stretched = 0;
  std::vector<uint32_t> touched;
  st.collapses = collapse_short_interface_edges(c, adj, edges, min_length, max_length, &stretched, &touched);
  // Short edges may collapse into edges past the upper bound (interface_coarsening.h): those
  // are split again, so every interface edge ends the step inside the band. Only edges at the
  // collapses can be long: they are found there.
  if (stretched > 0) st.splits += split_long_interface_edges_at(c, adj, std::move(touched), max_length);
  st.band_s = clock.lap();
  // The volume's upkeep, on the steps that run it (VolumeUpkeep). The free vertices the front
  // pressed against the interface (a poor tetrahedron around them):
  // removed, in index order, where that raises their worst quality. Their worst qualities
  // first, in parallel (a pure read); a removal changes only the tetrahedra around the removed
  // vertex, so only its neighbours' are taken again.
  FlipStats removal, fs;
  if (settings.upkeep) {
    const std::vector<uint32_t> interface = marked(c.on_interface, 1);
    std::vector<uint8_t> near(c.points.size(), 0);
    mark_next_to(c, near, 1, [&](uint32_t p) { return c.on_interface[p] != 0; },
                 [&](uint32_t w) { return !c.on_interface[w] && !c.on_box[w] && !c.frozen[w]; });
    std::vector<uint32_t> candidates;
    for (uint32_t w = 0; w < near.size(); ++w)
      if (near[w] && !adj.unused(w)) candidates.push_back(w);
    auto worst_around = [&](uint32_t w) {
      double worst = 1e300;
      for (uint32_t t : adj.around(w)) worst = std::min(worst, tet_quality(c, c.tets[t]));
      return worst;
    };
    std::vector<double> worst(candidates.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, candidates.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) worst[i] = worst_around(candidates[i]);
    });
    std::vector<uint8_t> changed(c.points.size(), 0);
    std::vector<uint32_t> star_points;
    for (size_t i = 0; i < candidates.size(); ++i) {
      const uint32_t w = candidates[i];
      if (!((changed[w] ? worst_around(w) : worst[i]) < settings.removal_quality)) continue;
      star_points.clear();
      for (uint32_t t : adj.around(w)) star_points.insert(star_points.end(), c.tets[t].begin(), c.tets[t].end());
      if (remove_free_vertex(c, adj, w, Probe{}, removal))
        for (uint32_t x : star_points) changed[x] = 1;
    }
    st.removal_s = clock.lap();
    fs = improve_tets_near(c, adj, interface, settings.quality_threshold, settings.free_split_length * max_length,
                           settings.quality_passes);
    st.improve_s = clock.lap();
  }
  st.flips23 = fs.flips23;
  st.flips32 = fs.flips32 + fs.edge_removals;
  st.relocated = fs.relocated;
  st.removed = fs.removed + removal.removed;
  st.free_splits = fs.splits;
  return st;
}

}  // namespace phellem::bark

// Cracks and stress through time (Spicker 2014 ch. 5, "transferred to the new mesh by vertex
// identity"; Kratt et al., Woodification, sec. 5): the stress-field cracking of bark/stress
// runs between growth steps on the grown interface itself.
//
// The interface of the growth volume IS the stress mesh. After each growth step (its caps
// removed first, interface_caps.h):
//  1. the crack edges of the last step are found again on the interface: an edge the
//     refinement split is followed to its halves through the points' parents (coarsening
//     never collapses a point on a crack, and flips never touch the interface);
//  2. each face takes the stress it had by vertex identity (its three points): unchanged
//     faces exactly, moved faces plus the stretch — `stretch_stress` × |magnitude| × the
//     Green strain of the face between the two steps, so the bark tears as the trunk widens;
//     new faces (splits, collapses) take the area-weighted mean of the known faces around
//     their points;
//  3. `iterations_per_step` iterations of the cracking model run (new cracks where the stress
//     now exceeds τ — τ fixed at the first step — and existing cracks lengthening);
//  4. each edge split the crack insertion made is made again in the volume (the tetrahedra
//     around the edge split at the same point), so the interface stays the stress mesh and
//     every crack vertex is a point of the volume that moves with the growth.
// Crack widths (Algorithm 1, in crack edges) never decrease: a point keeps the widest it has
// been, so a crack that a younger branch joins does not narrow.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bark/growth/tet_adjacency.h"
#include "bark/stress/cracked_mesh.h"
#include "bark/stress/stress_cracker.h"
#include "bark/stress/stress_params.h"

namespace phellem::bark {

struct CrackCouplingSettings {
  int iterations_per_step = 1;  // stress iterations after each growth step (0: transfer only)
  double stretch_stress = 4.0;  // stress per unit of Green strain, in units of |magnitude|
};

struct CrackCouplingStats {
  long steps = 0;
  long splits_mirrored = 0;  // crack splits made again in the volume
  long splits_moved = 0;     // ... at the edge's midpoint, because the crack's point would flatten a tetrahedron
  long splits_lost = 0;      // ... not at all (no positive split): the crack stops there
  long caps_removed = 0;     // flattened interface triangles removed (interface_caps.h)
  long edges_lost = 0;       // crack edges no longer on the interface (nothing removes one: expected 0)
  long crack_edges = 0;      // on the interface now
  double seconds = 0;
};

// A face's stress as the last step left it, by its points in frame order.
struct FaceStressRecord {
  std::array<uint32_t, 3> points{};  // the face's points in the order of its local frame
  Eigen::Matrix2d sigma = Eigen::Matrix2d::Zero();
  Eigen::Matrix3d world = Eigen::Matrix3d::Zero();
};

class GrowthCracks {
 public:
  GrowthCracks(StressParams params, CrackCouplingSettings settings);

  // Steps 1–4 above on the complex's current interface (the adjacency kept in step). Throws
  // UserError(file, where, ...) when the interface cannot carry stress (pinched by contact).
  void step(TetComplex& c, TetAdjacency& adj, const std::string& file, const std::string& where);

  // The cracked interface of the last step (world space; widths the running maximum). Made
  // from the last step's cracker on the first call after the step (most steps nobody asks),
  // until release_cracker(); null after it unless asked for before.
  std::shared_ptr<const CrackedMesh> result() const;
  // Frees the last step's cracker (its stress mesh: tens of MB on a large interface), which
  // only result() needs: CambialGrowth::step calls it first, so that two crackers never live
  // at once and none through a re-tetrahedralization.
  void release_cracker();
  // The crack edges on the interface (points, smaller first) and each point's width.
  const std::set<std::pair<uint32_t, uint32_t>>& crack_edges() const { return edges_; }
  const std::vector<float>& width() const { return width_; }
  // Each interface face's stress, keyed by its sorted points.
  struct KeyHash {
    size_t operator()(const std::array<uint32_t, 3>& k) const {
      return (size_t(k[0]) * 73856093u) ^ (size_t(k[1]) * 19349663u) ^ (size_t(k[2]) * 83492791u);
    }
  };
  using FaceStress = std::unordered_map<std::array<uint32_t, 3>, FaceStressRecord, KeyHash>;
  const FaceStress& face_stress() const { return faces_; }
  const CrackCouplingStats& stats() const { return stats_; }
  // The settings from the next step on (e.g. a schedule of iterations).
  void set_settings(const CrackCouplingSettings& s) { settings_ = s; }
  double absolute_threshold() const { return tau_; }
  // Per point, as the last step left them: the eq. 6 residual a crack tip carries into the next
  // iteration, and the summed virtual displacement (zero for points the cracking never saw).
  // Carried by vertex identity like the stress, so a tip that had not yet cracked keeps its
  // surplus across a growth step and the displacement keeps summing.
  const std::vector<Eigen::Matrix3d>& residual() const { return residual_; }
  const std::vector<Eigen::Vector3d>& displacement() const { return displacement_; }

 private:
  // `interface_edges`: the interface's edges (smaller point first), sorted, each once.
  void follow_splits(const TetComplex& c, const std::vector<std::pair<uint32_t, uint32_t>>& interface_edges,
                     const std::map<uint32_t, uint32_t>& merged);

  StressParams params_;
  CrackCouplingSettings settings_;
  double tau_ = 0;
  bool started_ = false;
  std::set<std::pair<uint32_t, uint32_t>> edges_;
  std::vector<float> width_;                // per point
  std::vector<Eigen::Matrix3d> residual_;   // per point
  std::vector<Eigen::Vector3d> displacement_;  // per point
  std::vector<Eigen::Vector3d> positions_;  // the points as the last step left them
  size_t points_seen_ = 0;                  // points the last step knew
  FaceStress faces_;
  mutable std::shared_ptr<const CrackedMesh> result_;  // made by result() from the two below
  std::unique_ptr<StressCracker> last_;                 // the last step's cracker
  std::vector<uint32_t> last_point_of_;                 // its vertices' points
  CrackCouplingStats stats_;
};

}  // namespace phellem::bark

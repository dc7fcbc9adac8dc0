// StressCracker: the stress-field surface cracking model on a triangle mesh (Spicker 2014
// sec. 3, after Iben & O'Brien 2006; Figure 8): initialize the stress field, then each
// iteration compute the forces and separation tensors (eqs. 1–4), crack the vertices whose
// largest tensile eigenvalue exceeds τ (at most CPI, in order of that eigenvalue; eqs. 5–6,
// sec. 3.2), and relax the stress RPI times (eqs. 7–9).
//
// Forces, separation tensors and relaxation run in parallel (TBB) with fixed summation
// orders; cracking is sequential and its random draws depend on (seed, iteration, crack):
// the result is bit-identical for any thread count.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "bark/stress/crack_insertion.h"
#include "bark/stress/cracked_mesh.h"
#include "bark/stress/stress_forces.h"
#include "bark/stress/stress_mesh.h"
#include "bark/stress/stress_params.h"
#include "bark/stress/stress_topology.h"

namespace phellem::bark {

struct StressStats {
  long long cracks = 0;       // crack events that added at least one crack edge
  long long crack_edges = 0;  // edges marked as cracks now
  long long snapped = 0;      // crack sides that snapped onto an existing edge
  long long splits = 0;       // edges split by crack insertion
  int iterations = 0;
};

// An edge split made by crack insertion: the new vertex `tip` at parameter t on from–to, in
// the order the splits were made (crack coupling replays them in the growth volume).
struct CrackSplit {
  VertexId from, to, tip;
  double t = 0;
};

class StressCracker {
 public:
  // Throws StressParamError for a parameter out of range, or a UV stroke or stress image on a
  // mesh without texture coordinates.
  StressCracker(StressMesh mesh, StressParams params);
  // The same without setting up the pattern's stress (initialize_stress): for a caller that
  // gives every face its stress itself before the first iteration (crack coupling carries
  // the last growth step's). The faces' stress is then whatever the mesh held.
  enum class InitialStress { kPattern, kGiven };
  StressCracker(StressMesh mesh, StressParams params, InitialStress initial);

  void iterate();
  // All remaining iterations; `progress(done, total)` after each.
  void run(const std::function<void(int, int)>& progress = {});

  const StressMesh& mesh() const { return mesh_; }
  StressMesh& mesh() { return mesh_; }
  const StressParams& params() const { return params_; }
  const StressStats& stats() const;
  // τ in force units: threshold × |magnitude| × the initial mean edge length.
  double absolute_threshold() const { return tau_; }
  // Replaces τ (force units): crack coupling keeps the first growth step's τ for all steps.
  void set_absolute_threshold(double tau) { tau_ = tau; }
  // Every edge split so far, in order.
  const std::vector<CrackSplit>& splits() const { return splits_; }
  // Separation tensors of the last force computation, per vertex (eq. 4, plus residuals).
  const std::vector<Eigen::Matrix3d>& separation() const { return separation_; }

  // Per vertex: the residual of eq. 6 a tip that did not crack takes into the next iteration,
  // and the summed virtual displacement of the relaxations (sec. 3.1.4).
  const std::vector<Eigen::Matrix3d>& residual() const { return residual_; }
  const std::vector<Eigen::Vector3d>& displacement() const { return displacement_; }
  // Both as an earlier cracker left them, one per vertex of this mesh: crack coupling
  // (bark/growth/growth_cracks.h) runs a new cracker on each grown surface and carries them.
  void carry_over(std::vector<Eigen::Matrix3d> residual, std::vector<Eigen::Vector3d> displacement);

  // Post-processing (sec. 3.1.6, 4.2): components, Algorithm 1 widths, virtual displacement.
  // `source` (if given) receives each output vertex's mesh vertex.
  CrackedMesh result(std::vector<VertexId>* source_out = nullptr) const;

 private:
  void apply_growth_hooks();
  void crack_step();

  StressMesh mesh_;
  StressParams params_;
  double tau_ = 0;
  CrackInsertOptions insert_;
  ForceField forces_;
  // Connectivity of the mesh as of the last crack step (a crack step only ever adds faces
  // and vertices, so matching counts mean it is current).
  StressTopology topology_;
  std::vector<Eigen::Matrix3d> separation_, residual_;  // per vertex
  std::vector<Eigen::Vector3d> displacement_;           // per vertex
  std::vector<CrackSplit> splits_;
  mutable StressStats stats_;
};

}  // namespace phellem::bark

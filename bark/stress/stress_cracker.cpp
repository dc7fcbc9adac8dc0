#include "bark/stress/stress_cracker.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <queue>

#include "bark/stress/crack_width.h"
#include "bark/stress/separation_tensor.h"
#include "bark/stress/stress_patterns.h"
#include "bark/stress/stress_relaxation.h"
#include "util/random.h"

namespace phellem::bark {

namespace {
constexpr double kPi = 3.141592653589793;

// Largest eigenvalue of a symmetric 3×3 tensor and its eigenvector (closed form).
std::pair<double, Eigen::Vector3d> largest(const Eigen::Matrix3d& s) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(s);
  return {es.eigenvalues()[2], es.eigenvectors().col(2)};
}
}  // namespace

double CrackedMesh::crack_length() const {
  double l = 0;
  for (const auto& e : crack_edges) l += (mesh.positions[e[0]] - mesh.positions[e[1]]).norm();
  return l;
}

StressCracker::StressCracker(StressMesh mesh, StressParams params)
    : StressCracker(std::move(mesh), std::move(params), InitialStress::kPattern) {}

StressCracker::StressCracker(StressMesh mesh, StressParams params, InitialStress initial)
    : mesh_(std::move(mesh)), params_(std::move(params)) {
  if (auto e = validate(params_)) throw *e;
  if (!mesh_.has_uvs()) {  // what lives in UV space needs texture coordinates
    if (!params_.image.empty())
      throw StressParamError{"stress_image", "needs a mesh with texture coordinates (this one has none)"};
    for (const StressStroke& s : params_.strokes)
      if (s.in_uv)
        throw StressParamError{"strokes",
                               "a \"uv\" stroke needs a mesh with texture coordinates (this one has none); give 3D \"points\""};
  }
  const SurfaceMesh& g = mesh_.mesh();
  double mean_edge = 0;
  for (EdgeId e : g.edges()) mean_edge += (mesh_.point(g.vertex(e, 0)) - mesh_.point(g.vertex(e, 1))).norm();
  mean_edge /= double(std::max<size_t>(1, g.number_of_edges()));
  tau_ = params_.threshold * std::max(std::abs(params_.magnitude), 1e-300) * mean_edge;
  insert_.snap_angle = params_.snap_angle_deg * kPi / 180.0;
  insert_.stress_alleviation = params_.stress_alleviation;
  insert_.max_beta_sv = params_.kappa * mesh_.max_beta_singular_value();  // sec. 3.1.4
  if (initial == InitialStress::kPattern) initialize_stress(mesh_, params_);
}

const StressStats& StressCracker::stats() const {
  const SurfaceMesh& g = mesh_.mesh();
  stats_.crack_edges = 0;
  for (EdgeId e : g.edges()) stats_.crack_edges += mesh_.crack(e);
  return stats_;
}

void StressCracker::apply_growth_hooks() {
  // Woodification sec. 5: growth adds stress each step; curvature adds a term along the
  // surface's principal curvature directions.
  const bool growth = !params_.growth_increment.isZero(), curvature = params_.curvature_stress != 0;
  if (!growth && !curvature) return;
  SurfaceMesh& g = mesh_.mesh();
  tbb::parallel_for(size_t(0), size_t(g.number_of_faces()), [&](size_t k) {
    const FaceId f(static_cast<SurfaceMesh::size_type>(k));
    FaceState& s = mesh_.face(f);
    if (growth) {
      const auto [h, v] = horizontal_vertical(s.normal);
      Eigen::Matrix<double, 3, 2> HV;
      HV << h, v;
      const Eigen::Matrix<double, 2, 2> R = s.frame.transpose() * HV;  // (h, v) → local frame
      s.sigma += R * params_.growth_increment * R.transpose();
    }
    if (curvature) s.sigma += params_.curvature_stress * face_curvature(mesh_, f);
  });
}

void StressCracker::crack_step() {
  SurfaceMesh& g = mesh_.mesh();
  const size_t nv = g.number_of_vertices();
  // The mesh has not changed since the last relaxation built its topology (growth hooks
  // change stresses only).
  if (topology_.faces() != g.number_of_faces() || topology_.vertices() != nv) topology_ = StressTopology::build(mesh_);
  const StressTopology& topology = topology_;
  compute_forces(mesh_, topology, forces_);
  separation_.resize(nv);
  residual_.resize(nv, Eigen::Matrix3d::Zero());
  std::vector<double> top(nv);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t k = r.begin(); k != r.end(); ++k) {
      // Eq. 4 (+ eq. 6 from the last iteration), restricted to the tangent plane: on a curved
      // surface the membrane forces have normal components (Laplace's pressure) that pull no
      // crack open in the surface, and would otherwise dominate ς where curvature is high.
      Eigen::Vector3d n = Eigen::Vector3d::Zero();  // area-weighted, as StressMesh::vertex_normal
      for (uint32_t i = topology.vertex_begin[k]; i < topology.vertex_begin[k + 1]; ++i) {
        const FaceState& f = mesh_.face(FaceId(topology.vertex_slots[i] / 3));
        n += f.area * f.normal;
      }
      n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
      const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
      separation_[k] = P * (separation_tensor(topology, forces_, uint32_t(k)) + residual_[k]) * P;
      residual_[k].setZero();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
      es.computeDirect(separation_[k], Eigen::EigenvaluesOnly);
      top[k] = es.eigenvalues()[2];
    }
  });
  // Priority queue on the largest tensile eigenvalue (ties: lower vertex index first).
  using Entry = std::pair<double, uint32_t>;
  auto later = [](const Entry& a, const Entry& b) { return a.first < b.first || (a.first == b.first && a.second > b.second); };
  std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
  for (size_t k = 0; k < nv; ++k)
    if (top[k] > tau_) queue.emplace(top[k], uint32_t(k));
  std::vector<char> cracked(nv, 0);  // tried this iteration (1), and cracked (2)
  int made = 0;
  StreamRng rng(params_.seed ^ 0x637261636bULL, uint64_t(stats_.iterations), 0);
  while (!queue.empty() && made < params_.cracks_per_iteration) {
    const uint32_t vi = queue.top().second;  // (a tip pushed again with more stress is met first)
    queue.pop();
    if (cracked[vi]) continue;
    const auto [l, n_plus] = largest(separation_[vi]);
    if (!(l > tau_)) continue;
    const VertexId v(vi);
    // The crack runs perpendicular to the eigenvector, in the tangent plane, optionally
    // rotated about the normal by a random angle.
    const Eigen::Vector3d n_v = mesh_.vertex_normal(v);
    Eigen::Vector3d dir = n_v.cross(n_plus);
    const double jitter = params_.crack_rotation * 0.5 * kPi * rng.symmetric();
    if (!(dir.norm() > 1e-9)) continue;  // ς pulls along the normal only: no in-surface crack
    dir = Eigen::AngleAxisd(jitter, n_v) * dir.normalized();
    const auto sides = insert_crack(mesh_, v, dir, insert_);
    cracked[vi] = 1;
    if (!sides[0].added && !sides[1].added) continue;
    cracked[vi] = 2;
    ++made;
    ++stats_.cracks;
    // New vertices: their separation tensor interpolates the split edge's ends.
    const size_t n_now = g.number_of_vertices();
    separation_.resize(n_now, Eigen::Matrix3d::Zero());
    residual_.resize(n_now, Eigen::Matrix3d::Zero());
    cracked.resize(n_now, 0);
    // Eqs. 5–6: the surplus over τ, weighted by α, goes to the crack tips.
    const Eigen::Matrix3d surplus = params_.alpha * (l - tau_) * n_plus * n_plus.transpose();
    for (const CrackSide& s : sides) {
      if (!s.added) continue;
      stats_.snapped += s.snapped;
      stats_.splits += s.split;
      if (s.split) splits_.push_back({s.split_from, s.split_to, s.tip, s.split_t});
      const size_t t = s.tip.idx();
      if (s.split) separation_[t] = (1 - s.split_t) * separation_[s.split_from.idx()] + s.split_t * separation_[s.split_to.idx()];
      separation_[t] += surplus;
      residual_[t] += surplus;
      if (!cracked[t])
        if (const double lt = largest(separation_[t]).first; lt > tau_) queue.emplace(lt, uint32_t(t));
    }
  }
  // Residuals of vertices that cracked this iteration are spent; a tip that did not crack
  // keeps its residual for the next iteration (eq. 6).
  for (size_t k = 0; k < cracked.size(); ++k)
    if (cracked[k] == 2) residual_[k].setZero();
}

void StressCracker::carry_over(std::vector<Eigen::Matrix3d> residual, std::vector<Eigen::Vector3d> displacement) {
  const size_t nv = mesh_.mesh().number_of_vertices();
  if (residual.size() != nv || displacement.size() != nv)
    throw std::invalid_argument("StressCracker::carry_over: one residual and one displacement per vertex");
  residual_ = std::move(residual);
  displacement_ = std::move(displacement);
}

void StressCracker::iterate() {
  apply_growth_hooks();
  crack_step();
  topology_ = StressTopology::build(mesh_);  // the crack step changed the mesh
  if (params_.relaxations_per_iteration > 0) {
    const std::vector<double> stiffness = vertex_stiffness(mesh_, topology_);
    for (int r = 0; r < params_.relaxations_per_iteration; ++r) {
      compute_forces(mesh_, topology_, forces_, false);
      relax(mesh_, topology_, forces_, params_.time_step, &displacement_, &stiffness);
    }
  }
  ++stats_.iterations;
}

void StressCracker::run(const std::function<void(int, int)>& progress) {
  while (stats_.iterations < params_.iterations) {
    iterate();
    if (progress) progress(stats_.iterations, params_.iterations);
  }
}

CrackedMesh StressCracker::result(std::vector<VertexId>* source_out) const {
  const SurfaceMesh& g = mesh_.mesh();
  const size_t nv = g.number_of_vertices();
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (EdgeId e : g.edges())
    if (mesh_.crack(e)) edges.emplace_back(g.vertex(e, 0).idx(), g.vertex(e, 1).idx());
  const CrackGraph graph = CrackGraph::from_edges(nv, edges);
  const std::vector<int32_t> comp = crack_components(graph), width = crack_widths(graph);
  CrackedMesh out;
  std::vector<VertexId> source;
  out.mesh = mesh_.to_trimesh(&source);
  // Crack edges between output vertices: a crack vertex split at a UV seam keeps one copy per
  // side; the edge uses the copies of a face that holds it.
  std::vector<std::vector<uint32_t>> copies(nv);
  for (uint32_t k = 0; k < source.size(); ++k) copies[source[k].idx()].push_back(k);
  for (const auto& [a, b] : edges) out.crack_edges.push_back({copies[a].front(), copies[b].front()});
  out.crack_width.resize(source.size());
  out.component.resize(source.size());
  out.displacement.resize(source.size(), Eigen::Vector3f::Zero());
  for (size_t k = 0; k < source.size(); ++k) {
    const size_t v = source[k].idx();
    out.crack_width[k] = float(width[v]);
    out.component[k] = comp[v];
    if (v < displacement_.size()) out.displacement[k] = displacement_[v].cast<float>();
  }
  if (source_out) *source_out = std::move(source);
  return out;
}

}  // namespace phellem::bark

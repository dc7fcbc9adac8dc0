#include "bark/growth/growth_cracks.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>

#include "bark/growth/cambial_growth.h"
#include "bark/growth/interface_caps.h"
#include "bark/stress/crack_width.h"
#include "bark/stress/stress_cracker.h"
#include "util/errors.h"

namespace phellem::bark {

namespace {

constexpr uint32_t kNone = 0xffffffffu;
constexpr double kMaxCapAngle = 2.8;  // radians (160°)

std::array<uint32_t, 3> sorted(std::array<uint32_t, 3> k) {
  std::sort(k.begin(), k.end());
  return k;
}

std::pair<uint32_t, uint32_t> edge_key(uint32_t a, uint32_t b) { return std::minmax(a, b); }

// The in-plane orthonormal frame (u along a→b) of a triangle, as the stress mesh builds it.
Eigen::Matrix<double, 3, 2> triangle_frame(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d u = (b - a).normalized(), n = (b - a).cross(c - a).normalized();
  Eigen::Matrix<double, 3, 2> E;
  E << u, n.cross(u);
  return E;
}

// The Green strain E = ½(FᵀF − I) of the triangle between its old and new corners, in world
// space (in the old triangle's plane): F maps the old triangle's edges onto the new one's.
Eigen::Matrix3d green_strain(const std::array<Eigen::Vector3d, 3>& old_p, const std::array<Eigen::Vector3d, 3>& new_p) {
  const Eigen::Matrix<double, 3, 2> Eo = triangle_frame(old_p[0], old_p[1], old_p[2]);
  const Eigen::Matrix<double, 3, 2> En = triangle_frame(new_p[0], new_p[1], new_p[2]);
  Eigen::Matrix<double, 3, 2> Do, Dn;
  Do << old_p[1] - old_p[0], old_p[2] - old_p[0];
  Dn << new_p[1] - new_p[0], new_p[2] - new_p[0];
  const Eigen::Matrix2d Xo = Eo.transpose() * Do, Xn = En.transpose() * Dn;
  if (!(std::abs(Xo.determinant()) > 0)) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix2d F = Xn * Xo.inverse();
  const Eigen::Matrix2d E = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
  return Eo * E * Eo.transpose();
}

using Clock = std::chrono::steady_clock;

}  // namespace

GrowthCracks::GrowthCracks(StressParams params, CrackCouplingSettings settings)
    : params_(std::move(params)), settings_(settings) {
  if (settings_.iterations_per_step < 0 || !(settings_.stretch_stress >= 0) || !std::isfinite(settings_.stretch_stress))
    throw std::invalid_argument("GrowthCracks: iterations_per_step >= 0 and a finite stretch_stress >= 0");
}

void GrowthCracks::follow_splits(const TetComplex& c, const std::vector<std::pair<uint32_t, uint32_t>>& interface_edges,
                                 const std::map<uint32_t, uint32_t>& merged) {
  auto survivor = [&](uint32_t q) {
    for (auto it = merged.find(q); it != merged.end(); it = merged.find(q)) q = it->second;
    return q;
  };
  // The points added since the last step, by the edge they split.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> child;
  for (size_t p = points_seen_; p < c.parents.size(); ++p)
    if (c.parents[p][0] != TetComplex::kNoParent) child.emplace(edge_key(c.parents[p][0], c.parents[p][1]), uint32_t(p));
  std::set<std::pair<uint32_t, uint32_t>> now;
  std::vector<std::pair<uint32_t, uint32_t>> todo(edges_.begin(), edges_.end());
  while (!todo.empty()) {
    const auto e = todo.back();
    todo.pop_back();
    if (std::binary_search(interface_edges.begin(), interface_edges.end(), e)) {
      now.insert(e);
    } else if (const auto it = child.find(e); it != child.end()) {
      const uint32_t m = survivor(it->second);  // a cap's split point merged into the cap vertex
      if (m != e.first) todo.push_back(edge_key(e.first, m));
      if (m != e.second) todo.push_back(edge_key(m, e.second));
    } else {
      ++stats_.edges_lost;  // neither an edge nor split: nothing removes a crack edge, so never expected
    }
  }
  edges_ = std::move(now);
}

std::shared_ptr<const CrackedMesh> GrowthCracks::result() const {
  if (!result_ && last_) {
    std::vector<VertexId> source;
    auto out = std::make_shared<CrackedMesh>(last_->result(&source));
    for (size_t k = 0; k < source.size(); ++k) {
      const uint32_t q = last_point_of_[source[k].idx()];
      if (q != kNone) out->crack_width[k] = width_[q];
    }
    result_ = std::move(out);
  }
  return result_;
}

void GrowthCracks::release_cracker() {
  last_.reset();
  last_point_of_ = {};
}

void GrowthCracks::step(TetComplex& c, TetAdjacency& adj, const std::string& file, const std::string& where) {
  release_cracker();
  const auto t0 = Clock::now();
  const std::string at_step = " (crack coupling, growth step " + std::to_string(stats_.steps) + ")";
  // Lagging vertices flatten triangles into caps, which the stress mesh cannot take.
  std::map<uint32_t, uint32_t> merged;
  std::vector<std::array<uint32_t, 3>> faces;  // the interface's, sorted
  if (!c.on_crack.empty()) {
    CapStats caps = remove_interface_caps(c, adj, kMaxCapAngle);
    stats_.caps_removed += caps.removed;
    merged.insert(caps.merged.begin(), caps.merged.end());
    faces = std::move(caps.faces);
  } else {
    faces = interface_faces(c, adj);
    std::sort(faces.begin(), faces.end());
  }
  // The interface as the stress mesh: vertex k of the stress mesh is point surface.point[k]
  // (extract_interface lists each point once, and distinct points never share a position).
  const GrowthSurface surface = extract_interface(c, faces);
  std::vector<std::pair<uint32_t, uint32_t>> interface_edges;
  interface_edges.reserve(3 * surface.mesh.triangles.size());
  for (const auto& t : surface.mesh.triangles)
    for (int e = 0; e < 3; ++e)
      interface_edges.push_back(edge_key(surface.point[t[size_t(e)]], surface.point[t[size_t(e + 1) % 3]]));
  std::sort(interface_edges.begin(), interface_edges.end());
  interface_edges.erase(std::unique(interface_edges.begin(), interface_edges.end()), interface_edges.end());
  follow_splits(c, interface_edges, merged);

  std::optional<StressMesh> mesh;
  try {
    mesh.emplace(StressMesh::from(surface.mesh));
  } catch (const MeshError& e) {
    throw UserError(file, where, "the grown surface cannot carry stress" + at_step + ": " + e.where + " " + e.what());
  }
  if (mesh->mesh().number_of_vertices() != surface.point.size())
    throw UserError(file, where, "the grown surface has two points at one position" + at_step);
  std::vector<uint32_t> point_of(surface.point);  // stress vertex → point (grows with the crack splits)
  std::vector<uint32_t> vertex_of(c.points.size(), kNone);
  for (size_t k = 0; k < point_of.size(); ++k) vertex_of[point_of[k]] = uint32_t(k);
  SurfaceMesh& g = mesh->mesh();
  for (const auto& [a, b] : edges_) {
    const auto h = CGAL::halfedge(VertexId(vertex_of[a]), VertexId(vertex_of[b]), g);
    if (h.second) mesh->set_crack(g.edge(h.first), true);
  }

  // Step 2: the stress by vertex identity.
  StressParams p = params_;
  p.seed = params_.seed + 0x9e3779b97f4a7c15ULL * uint64_t(stats_.steps + 1);  // fresh draws each step
  if (started_) {
    const double k = settings_.stretch_stress * std::abs(params_.magnitude);
    std::vector<Eigen::Matrix3d> sum(point_of.size(), Eigen::Matrix3d::Zero());
    std::vector<double> weight(point_of.size(), 0.0);
    // Each known face's stress on its own (in parallel; the stress mesh is fresh, so its
    // faces are 0 .. n−1), then summed at the vertices in face order.
    const size_t n_faces = g.number_of_faces();
    std::vector<char> known(n_faces, 0);
    std::vector<Eigen::Matrix3d> world(n_faces);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n_faces, 512), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const FaceId f{uint32_t(i)};
        const auto vs = mesh->vertices(f);
        const std::array<uint32_t, 3> pts{point_of[vs[0].idx()], point_of[vs[1].idx()], point_of[vs[2].idx()]};
        const auto it = faces_.find(sorted(pts));
        if (it == faces_.end()) continue;
        const FaceStressRecord& r = it->second;
        FaceState& s = mesh->face(f);
        bool same = r.points == pts;
        for (uint32_t q : pts) same = same && positions_[q] == c.points[q];
        if (same) {
          s.sigma = r.sigma;  // an unchanged face keeps its stress exactly
        } else {
          // The record's corners in its own order, old and new.
          std::array<Eigen::Vector3d, 3> was, is;
          for (size_t j = 0; j < 3; ++j) {
            was[j] = positions_[r.points[j]];
            is[j] = c.points[r.points[j]];
          }
          mesh->set_world_stress(f, r.world + k * green_strain(was, is));
        }
        known[i] = 1;
        world[i] = mesh->world_stress(f);
      }
    });
    for (FaceId f : g.faces()) {
      if (!known[f.idx()]) continue;
      const double area = mesh->face(f).area;
      for (VertexId v : mesh->vertices(f)) {
        sum[v.idx()] += area * world[f.idx()];
        weight[v.idx()] += area;
      }
    }
    Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
    double total = 0;
    for (size_t v = 0; v < sum.size(); ++v) {
      mean += sum[v];
      total += weight[v];
    }
    if (total > 0) mean /= total;
    for (FaceId f : g.faces()) {
      if (known[f.idx()]) continue;
      Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
      double wt = 0;
      for (VertexId v : mesh->vertices(f)) {
        w += sum[v.idx()];
        wt += weight[v.idx()];
      }
      mesh->set_world_stress(f, wt > 0 ? Eigen::Matrix3d(w / wt) : mean);
    }
  }
  // The cracker sets up the first step's stress from the pattern; later steps keep the
  // transferred field the mesh's faces hold.
  // Throws StressParamError: the caller names the key.
  auto cracker = std::make_unique<StressCracker>(
      std::move(*mesh), p, started_ ? StressCracker::InitialStress::kGiven : StressCracker::InitialStress::kPattern);
  SurfaceMesh& cg = cracker->mesh().mesh();
  if (started_) {
    cracker->set_absolute_threshold(tau_);
    // The residuals and virtual displacement by vertex identity, as the stress.
    std::vector<Eigen::Matrix3d> residual(point_of.size(), Eigen::Matrix3d::Zero());
    std::vector<Eigen::Vector3d> displacement(point_of.size(), Eigen::Vector3d::Zero());
    for (size_t v = 0; v < point_of.size(); ++v)
      if (point_of[v] < residual_.size()) {
        residual[v] = residual_[point_of[v]];
        displacement[v] = displacement_[point_of[v]];
      }
    cracker->carry_over(std::move(residual), std::move(displacement));
  } else {
    tau_ = cracker->absolute_threshold();
    started_ = true;
  }

  // Step 3.
  for (int i = 0; i < settings_.iterations_per_step; ++i) cracker->iterate();

  // Step 4: the crack splits again in the volume, in the order they were made.
  for (const CrackSplit& s : cracker->splits()) {
    const size_t tip = s.tip.idx();
    if (point_of.size() <= tip) point_of.resize(tip + 1, kNone);
    const uint32_t a = point_of[s.from.idx()], b = point_of[s.to.idx()];
    if (a == kNone || b == kNone) {
      ++stats_.splits_lost;
      continue;
    }
    std::vector<uint32_t> shared;
    adj.edge_tets(c, a, b, shared);
    auto splits_positive = [&](double t) {
      return split_keeps_positive(c, a, b, (1 - t) * c.points[a] + t * c.points[b], shared);
    };
    double t = s.t;
    if (!splits_positive(t)) {
      t = 0.5;
      if (!splits_positive(t)) {
        ++stats_.splits_lost;
        continue;
      }
      ++stats_.splits_moved;
    }
    const uint32_t m = c.add_point_between(a, b, t);
    adj.split_edge_tets(c, a, b, m, shared);
    point_of[tip] = m;
    ++stats_.splits_mirrored;
  }

  // What the next step starts from: crack edges and widths by point, stress by face.
  const StressMesh& sm = cracker->mesh();
  point_of.resize(cg.number_of_vertices(), kNone);  // every vertex the cracker made was a split tip; to be sure
  edges_.clear();
  std::vector<std::pair<uint32_t, uint32_t>> graph_edges;
  for (EdgeId e : cg.edges()) {
    if (!sm.crack(e)) continue;
    const uint32_t u = cg.vertex(e, 0).idx(), v = cg.vertex(e, 1).idx();
    graph_edges.emplace_back(u, v);
    if (point_of[u] != kNone && point_of[v] != kNone) edges_.insert(edge_key(point_of[u], point_of[v]));
  }
  residual_.assign(c.points.size(), Eigen::Matrix3d::Zero());
  displacement_.assign(c.points.size(), Eigen::Vector3d::Zero());
  for (size_t v = 0; v < point_of.size(); ++v)
    if (point_of[v] != kNone) {
      if (v < cracker->residual().size()) residual_[point_of[v]] = cracker->residual()[v];
      if (v < cracker->displacement().size()) displacement_[point_of[v]] = cracker->displacement()[v];
    }
  c.on_crack.assign(c.points.size(), 0);
  for (const auto& [a, b] : edges_) c.on_crack[a] = c.on_crack[b] = 1;
  const std::vector<int32_t> alg1 = crack_widths(CrackGraph::from_edges(cg.number_of_vertices(), graph_edges));
  width_.resize(c.points.size(), 0.0f);
  for (size_t v = 0; v < point_of.size(); ++v)
    if (point_of[v] != kNone) width_[point_of[v]] = std::max(width_[point_of[v]], float(alg1[v]));
  faces_.clear();
  faces_.reserve(cg.number_of_faces());
  for (FaceId f : cg.faces()) {
    const auto vs = sm.vertices(f);
    const std::array<uint32_t, 3> pts{point_of[vs[0].idx()], point_of[vs[1].idx()], point_of[vs[2].idx()]};
    if (pts[0] == kNone || pts[1] == kNone || pts[2] == kNone) continue;
    faces_[sorted(pts)] = {pts, sm.face(f).sigma, sm.world_stress(f)};
  }
  result_.reset();
  last_ = std::move(cracker);
  last_point_of_ = std::move(point_of);
  positions_ = c.points;
  points_seen_ = c.points.size();
  stats_.crack_edges = long(edges_.size());
  ++stats_.steps;
  stats_.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace phellem::bark

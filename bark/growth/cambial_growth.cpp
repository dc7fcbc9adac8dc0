#include "bark/growth/cambial_growth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include "bark/growth/complex_repair.h"
#include "bark/growth/growable_surface.h"
#include "bark/growth/growth_contact.h"
#include "bark/growth/interface_curvature.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/volume_remesh.h"
#include "util/errors.h"

namespace phellem::bark {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The surface as one closed index mesh: vertices at the same position (split at UV seams)
// welded into the first of them, which keeps its UV; vertices no triangle uses dropped (TetGen
// would see them as loose points on top of the used ones). `face_of`: each kept triangle's
// index in `in` (triangles that weld to a line or a point are dropped), for errors.
TriMesh welded(const TriMesh& in, std::vector<int64_t>* first_of = nullptr, std::vector<uint32_t>* face_of = nullptr) {
  std::map<std::array<double, 3>, uint32_t> at;
  TriMesh out;
  if (first_of) first_of->clear();
  if (face_of) face_of->clear();
  for (uint32_t i = 0; i < in.triangles.size(); ++i) {
    const auto& t = in.triangles[i];
    std::array<uint32_t, 3> g{};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = in.positions[t[size_t(k)]];
      const auto [it, added] = at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, uint32_t(out.positions.size()));
      if (added) {
        if (first_of) first_of->push_back(int64_t(t[size_t(k)]));
        out.positions.push_back(p);
        if (in.has_uvs()) out.uvs.push_back(in.uvs[t[size_t(k)]]);
      }
      g[size_t(k)] = it->second;
    }
    if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2]) {
      out.triangles.push_back(g);
      if (face_of) face_of->push_back(i);
    }
  }
  return out;
}

size_t interface_vertex_count(const TetComplex& c) {  // points an operation removed have on_interface 0
  size_t n = 0;
  for (uint8_t f : c.on_interface) n += f;
  return n;
}

}  // namespace

double mean_edge_length(const TriMesh& m) {
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e)
      edges.insert(std::minmax(t[size_t(e)], t[size_t(e + 1) % 3]));
  double sum = 0;
  for (const auto& [a, b] : edges) sum += (m.positions[a] - m.positions[b]).norm();
  return edges.empty() ? 0 : sum / double(edges.size());
}

GrowthSurface extract_interface(const TetComplex& c) {
  return extract_interface(c, c.boundary_faces(TetComplex::kInside, c.on_interface));
}

GrowthSurface extract_interface(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces) {
  GrowthSurface s;
  std::vector<uint8_t> used(c.points.size(), 0);
  for (const auto& f : faces)
    for (uint32_t v : f) used[v] = 1;
  std::vector<uint32_t> index(c.points.size(), 0);  // the points in ascending order
  for (uint32_t p = 0; p < c.points.size(); ++p) {
    if (!used[p]) continue;
    index[p] = uint32_t(s.point.size());
    s.point.push_back(p);
    s.mesh.positions.push_back(c.points[p]);
    if (!c.uv.empty()) s.mesh.uvs.push_back(c.uv[p]);
  }
  for (const auto& f : faces) s.mesh.triangles.push_back({index[f[0]], index[f[1]], index[f[2]]});
  return s;
}

CambialGrowth::CambialGrowth(const TriMesh& surface, const std::vector<GrowthObstacle>& obstacles, const CambialGrowthSettings& s,
                             const std::string& file, const std::string& where, const std::vector<float>& vertex_speed,
                             const std::vector<Eigen::Vector3f>& vertex_direction)
    : settings_(s), file_(file), where_(where) {
  if (!vertex_speed.empty() && vertex_speed.size() != surface.positions.size())
    throw std::invalid_argument("CambialGrowth: one speed per surface vertex");
  if (!vertex_direction.empty() && vertex_direction.size() != surface.positions.size())
    throw std::invalid_argument("CambialGrowth: one direction per surface vertex");
  std::vector<int64_t> first_of;  // welded vertex -> the input vertex it was made from
  std::vector<uint32_t> face_of;  // welded triangle -> the input triangle
  const TriMesh input = welded(surface, &first_of, &face_of);
  require_growable(input, file, where, face_of);
  const double mean = mean_edge_length(input);
  if (settings_.edge_max <= 0) settings_.edge_max = 1.5 * mean;
  if (settings_.edge_min <= 0) settings_.edge_min = 0.4 * settings_.edge_max;
  const auto t0 = Clock::now();
  for (const auto& o : obstacles) obstacles_.push_back({welded(o.mesh), o.where});
  complex_ = tetrahedralize_surface(input, obstacles_, settings_.tet, file, where);
  if (!vertex_speed.empty()) {
    // TetGen keeps the input points first and in order; its own points (off the interface) get 1.
    complex_.speed.assign(complex_.points.size(), 1.0f);
    for (size_t i = 0; i < first_of.size(); ++i) complex_.speed[i] = vertex_speed[size_t(first_of[i])];
  }
  if (!vertex_direction.empty()) {
    complex_.direction.assign(complex_.points.size(), Eigen::Vector3f::Zero());
    for (size_t i = 0; i < first_of.size(); ++i) complex_.direction[i] = vertex_direction[size_t(first_of[i])];
  }
  adjacency_.emplace(complex_);
  // Obstacle tetrahedra never change, and all their corners are frozen.
  obstacle_faces_ = complex_.boundary_faces(TetComplex::kObstacle, complex_.frozen);
  stats_.setup_s = since(t0);
  stats_.vertices_start = stats_.vertices_end = interface_vertex_count(complex_);
  stats_.tets_start = stats_.tets_end = complex_.tets.size();
  if (settings_.ring_interval > 0) rings_.push_back(record_ring(complex_, 0));
}

double CambialGrowth::age_at(int k) const {
  const double a = settings_.age_start + (settings_.age_end - settings_.age_start) * double(k) / settings_.steps;
  // Reversed growth walks the ages from the end back to the start.
  return settings_.reverse ? settings_.age_end + settings_.age_start - a : a;
}

double CambialGrowth::age() const { return age_at(step_); }

void CambialGrowth::couple_cracks(const StressParams& params, const CrackCouplingSettings& settings) {
  const auto t0 = Clock::now();
  auto cracks = std::make_unique<GrowthCracks>(params, settings);
  cracks->step(complex_, *adjacency_, file_, where_ + "/cracks");
  cracks_ = std::move(cracks);
  stats_.cracks_s += since(t0);
  stats_.vertices_end = interface_vertex_count(complex_);
  stats_.tets_end = complex_.tets.size();
}

bool CambialGrowth::step() {
  if (step_ >= settings_.steps) return false;
  if (cracks_) cracks_->release_cracker();  // the last step's result() was taken, or is not wanted
  const auto t0 = Clock::now();
  // Eq. (1) over [age(k), age(k+1)]: reversed, the second age is the younger one and the
  // thickening negative (the surface moves inwards).
  // The interface faces once (the motion moves points and retessellates the outside only, not
  // the faces), in tet order: for the motion, the curvature term, contact and the repair.
  const std::vector<std::array<uint32_t, 3>> step_faces = interface_faces(complex_, *adjacency_);
  const std::vector<Eigen::Vector3d> before = complex_.points;  // how far each point moves: for the flips
  upkeep_.reach = settings_.upkeep_reach * settings_.edge_min;
  const InterfaceStepStats st = advance_interface(complex_, *adjacency_, step_faces, settings_.function, age_at(step_),
                                                  age_at(step_ + 1), &owed_, &upkeep_);
  stats_.upkeep_steps += st.upkeep;
  const auto t_contact = Clock::now();
  stats_.motion_s += std::chrono::duration<double>(t_contact - t0).count();
  stats_.moved += st.moved;
  stats_.shortened += st.shortened;
  stats_.clamped += st.clamped;
  stats_.carry_s += st.carry_s;
  stats_.moves_s += st.moves_s;
  stats_.unblock_s += st.unblock_s;
  stats_.smooth_s += st.smooth_s;
  // Sec. 4.3: reversed growth is the negated speed plus a small curvature term, which keeps a
  // shrinking surface from folding where it is concave.
  // Forwards, the same term (weaker) lets a vertex that a blocked move left behind catch up
  // with its neighbours instead of staying a pit.
  // Sorted as TetComplex::interface_faces() returns them: for the curvature term and contact.
  std::vector<std::array<uint32_t, 3>> faces = step_faces;
  std::sort(faces.begin(), faces.end());
  if (settings_.reverse)
    smooth_interface_curvature(complex_, *adjacency_, faces, 0.1);
  else if (settings_.curvature > 0)
    smooth_interface_curvature(complex_, *adjacency_, faces, settings_.curvature, true, &owed_);  // its lift repays what is owed
  stats_.curvature_s += since(t_contact);
  // Sec. 4.5: vertices that came within half the step's thickening of an obstacle or of
  // another part of the front stop there for good (a crease wound where fronts meet).
  const double step_thickening = std::abs(settings_.function.cumulative(age_at(step_ + 1)) -
                                          settings_.function.cumulative(age_at(step_))) *
                                 (1 + std::abs(double(settings_.function.eccentricity)));
  const ContactStats contact =
      freeze_contacts(complex_, faces, obstacle_faces_, std::max(0.5 * step_thickening, 0.02 * settings_.edge_min));
  stats_.frozen_obstacle += contact.obstacle;
  stats_.frozen_contact += contact.front;
  const auto t_repair = Clock::now();
  stats_.contact_s += std::chrono::duration<double>(t_repair - t_contact).count();
  // Curvature and contact moved and froze points only: the faces, in tet order, still hold.
  // Interface flips may move the surface against the growth (inwards growing, outwards
  // shrinking) by half of what the flipped faces' corners moved this step: rings nest.
  std::vector<double> moved(before.size());
  for (size_t v = 0; v < before.size(); ++v) moved[v] = (complex_.points[v] - before[v]).norm();
  RepairSettings repair_settings;
  (settings_.reverse ? repair_settings.flips.max_outward : repair_settings.flips.max_inward) = 0;
  repair_settings.flips.moved = &moved;
  repair_settings.upkeep = st.upkeep;
  const RepairStats repair =
      growth_repair_step(complex_, *adjacency_, step_faces, settings_.edge_min, settings_.edge_max, repair_settings);
  stats_.splits += repair.splits;
  stats_.collapses += repair.collapses;
  stats_.interface_flips += repair.interface_flips;
  stats_.flips += repair.flips23 + repair.flips32;
  stats_.repair_s += since(t_repair);
  stats_.flips_s += repair.flips_s;
  stats_.band_s += repair.band_s;
  stats_.removal_s += repair.removal_s;
  stats_.improve_s += repair.improve_s;
  // Most moves blocked: the volume around the interface has worn out; TetGen makes it anew
  // (the interface and its points unchanged).
  const long tried = st.moved + st.shortened + st.clamped;
  // At most once per edge length of thickening: the volume wears out over about two of them,
  // and each re-tetrahedralization costs as much as tens of steps.
  grown_since_remesh_ += step_thickening;
  if (settings_.remesh_blocked > 0 && tried > 0 && grown_since_remesh_ >= settings_.edge_max &&
      double(st.shortened + st.clamped) > settings_.remesh_blocked * double(tried)) {
    grown_since_remesh_ = 0;
    const auto tr = Clock::now();
    // A re-tetrahedralization takes about as long as the set-up did; one that takes ten times
    // as long (at least 10 s) has met an input TetGen loops on, and is skipped like a refusal.
    TetSettings tet = settings_.tet;
    tet.time_limit = std::min(tet.time_limit, std::max(10.0, 10 * stats_.setup_s));
    if (retetrahedralize(complex_, obstacles_, tet, file_, where_)) {
      adjacency_.emplace(complex_);
      obstacle_faces_ = complex_.boundary_faces(TetComplex::kObstacle, complex_.frozen);
      upkeep_.steps_left = 0;  // the room carried ahead went with the old volume
      ++stats_.remeshes;
    } else {
      ++stats_.remesh_refused;
    }
    stats_.remesh_s += since(tr);
  }
  ++step_;
  stats_.steps_s += since(t0);
  if (cracks_) {  // thesis sec. 5: the stress and cracks carried to the grown surface, then cracking
    const auto tc = Clock::now();
    cracks_->step(complex_, *adjacency_, file_, where_ + "/cracks");
    stats_.cracks_s += since(tc);
  }
  stats_.vertices_end = interface_vertex_count(complex_);
  stats_.tets_end = complex_.tets.size();
  if (settings_.ring_interval > 0 && (step_ % settings_.ring_interval == 0 || step_ == settings_.steps)) {
    faces = interface_faces(complex_, *adjacency_);
    std::sort(faces.begin(), faces.end());
    rings_.push_back(record_ring(complex_, faces, step_));
  }
  return true;
}

}  // namespace phellem::bark

#include "bark/stress/crack_insertion.h"

#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

namespace phellem::bark {

namespace {

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// Splits the edge of halfedge h_ab (a → b, in the face v → a → b) at parameter t, connects the
// new vertex to v and to the far face's third vertex, and fixes up the four faces. Returns the
// new vertex and the halfedge q → v.
std::pair<VertexId, HalfedgeId> split_and_connect(StressMesh& m, HalfedgeId h_ab, double t, const CrackInsertOptions& o) {
  SurfaceMesh& g = m.mesh();
  const HalfedgeId h_bv = g.next(h_ab), h_va = g.next(h_bv);
  const HalfedgeId o_ba = g.opposite(h_ab);
  const bool far = !g.is_border(o_ba);
  const VertexId v = g.target(h_bv), a = g.source(h_ab), b = g.target(h_ab);
  // What the new faces inherit: per-face UVs at the corners, and the parents' stress.
  const Eigen::Vector2d uv_fv = m.uv(h_bv), uv_fa = m.uv(h_va), uv_fb = m.uv(h_ab);
  const FaceId f = g.face(h_ab);
  const Eigen::Matrix3d sigma_f = m.world_stress(f);
  Eigen::Vector2d uv_ga = Eigen::Vector2d::Zero(), uv_gb = uv_ga, uv_gc = uv_ga;
  Eigen::Matrix3d sigma_g = Eigen::Matrix3d::Zero();
  VertexId c;
  if (far) {
    const HalfedgeId o_ac = g.next(o_ba);
    uv_ga = m.uv(o_ba);
    uv_gc = m.uv(o_ac);
    uv_gb = m.uv(g.next(o_ac));
    c = g.target(o_ac);
    sigma_g = m.world_stress(g.face(o_ba));
  }
  const bool was_crack = m.crack(g.edge(h_ab));
  const Eigen::Vector3d pq = (1 - t) * m.point(a) + t * m.point(b);

  const HalfedgeId h_aq = CGAL::Euler::split_edge(h_ab, g);  // a → q, then h_ab is q → b
  const VertexId q = g.target(h_aq);
  g.point(q) = StressKernel::Point_3(pq.x(), pq.y(), pq.z());
  m.set_crack(g.edge(h_aq), was_crack);
  const HalfedgeId h_qv = CGAL::Euler::split_face(h_aq, h_bv, g);  // faces v a q | q b v
  m.set_crack(g.edge(h_qv), false);
  std::array<FaceId, 4> faces{g.face(h_aq), g.face(g.opposite(h_qv)), SurfaceMesh::null_face(), SurfaceMesh::null_face()};
  if (far) {
    const HalfedgeId h_bq = g.opposite(h_ab), h_qa = g.opposite(h_aq);
    const HalfedgeId h_qc = CGAL::Euler::split_face(h_bq, g.next(h_qa), g);  // faces q a c | b q c
    faces[2] = g.face(h_qc);
    faces[3] = g.face(g.opposite(h_qc));
  }
  for (size_t k = 0; k < 4; ++k) {
    const FaceId nf = faces[k];
    if (nf == SurfaceMesh::null_face()) continue;
    const bool near = k < 2;
    for (HalfedgeId h : CGAL::halfedges_around_face(g.halfedge(nf), g)) {
      const VertexId w = g.target(h);
      if (near)
        m.uv(h) = w == v ? uv_fv : w == a ? uv_fa : w == b ? uv_fb : Eigen::Vector2d((1 - t) * uv_fa + t * uv_fb);
      else
        m.uv(h) = w == c ? uv_gc : w == a ? uv_ga : w == b ? uv_gb : Eigen::Vector2d((1 - t) * uv_ga + t * uv_gb);
    }
    m.update_geometry(nf);
    clamp_beta(m.face(nf), o.max_beta_sv);
    m.set_world_stress(nf, o.stress_alleviation * (near ? sigma_f : sigma_g));  // sec. 3.2
  }
  return {q, h_qv};
}

CrackSide insert_side(StressMesh& m, VertexId v, const Eigen::Vector3d& n_v, const Eigen::Vector3d& d,
                      const CrackInsertOptions& o) {
  SurfaceMesh& g = m.mesh();
  CrackSide out;
  const Eigen::Vector3d pv = m.point(v);
  // Snap onto an existing edge closer in angle than ESA (Figure 13, centre and right).
  double best_angle = std::numeric_limits<double>::infinity();
  HalfedgeId best_edge;
  for (HalfedgeId h : CGAL::halfedges_around_source(v, g)) {
    Eigen::Vector3d e = m.point(g.target(h)) - pv;
    e -= e.dot(n_v) * n_v;
    const double ang = angle_between(e, d);
    if (ang < best_angle) {
      best_angle = ang;
      best_edge = h;
    }
  }
  auto snap = [&](HalfedgeId h) {
    out.snapped = true;
    out.tip = g.target(h);
    out.added = !m.crack(g.edge(h));
    m.set_crack(g.edge(h), true);
    return out;
  };
  if (best_angle < o.snap_angle) return snap(best_edge);
  // The face whose corner at v contains the direction.
  HalfedgeId wedge;  // the halfedge a → b opposite v in that face
  double wedge_margin = -std::numeric_limits<double>::infinity();
  for (HalfedgeId h : CGAL::halfedges_around_target(g.halfedge(v), g)) {
    if (g.is_border(h)) continue;
    const FaceState& fs = m.face(g.face(h));
    const HalfedgeId h_va = g.next(h), h_ab = g.next(h_va);
    const Eigen::Vector3d ea = (m.point(g.target(h_va)) - pv).normalized(), eb = (m.point(g.target(h_ab)) - pv).normalized();
    const Eigen::Vector3d df = (d - d.dot(fs.normal) * fs.normal).normalized();
    const double margin = std::min(ea.cross(df).dot(fs.normal), df.cross(eb).dot(fs.normal));
    if (margin > wedge_margin) {
      wedge_margin = margin;
      wedge = h_ab;
    }
  }
  if (!(wedge_margin >= 0)) return out;  // the direction leaves the surface (v on its boundary)
  // Ray v + s·d against the segment a–b, in the face's plane.
  const FaceState& fs = m.face(g.face(wedge));
  const VertexId a = g.source(wedge), b = g.target(wedge);
  const Eigen::Vector3d pa = m.point(a), pb = m.point(b);
  const Eigen::Vector3d df = d - d.dot(fs.normal) * fs.normal;
  const double den = df.cross(pb - pa).dot(fs.normal);
  double t = den != 0 ? (pa - pv).cross(df).dot(fs.normal) / den : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  const Eigen::Vector3d pq = pa + t * (pb - pa);
  // Would the split create an angle below ESA? Then snap to the nearer end instead.
  double worst = std::min(min_angle(pv, pa, pq), min_angle(pv, pq, pb));
  const HalfedgeId o_ba = g.opposite(wedge);
  if (!g.is_border(o_ba)) {
    const Eigen::Vector3d pc = m.point(g.target(g.next(o_ba)));
    worst = std::min({worst, min_angle(pq, pa, pc), min_angle(pb, pq, pc)});
  }
  if (!(worst >= o.snap_angle)) {
    const HalfedgeId to_a = g.prev(wedge), to_b = g.next(wedge);  // v → a, b → v
    return snap(t < 0.5 ? to_a : g.opposite(to_b));
  }
  const auto [q, h_qv] = split_and_connect(m, wedge, t, o);
  m.set_crack(g.edge(h_qv), true);
  out.added = out.split = true;
  out.tip = q;
  out.split_from = a;
  out.split_to = b;
  out.split_t = t;
  return out;
}

}  // namespace

double min_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return std::min({angle_between(b - a, c - a), angle_between(a - b, c - b), angle_between(a - c, b - c)});
}

void clamp_beta(FaceState& s, double max_sv) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(s.beta, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sv = svd.singularValues();
  if (!(sv[0] > max_sv)) return;
  sv = sv.cwiseMin(max_sv);
  s.beta = svd.matrixU() * sv.asDiagonal() * svd.matrixV().transpose();
}

std::array<CrackSide, 2> insert_crack(StressMesh& m, VertexId v, const Eigen::Vector3d& dir, const CrackInsertOptions& o) {
  const Eigen::Vector3d n_v = m.vertex_normal(v);
  Eigen::Vector3d d = dir - dir.dot(n_v) * n_v;
  if (!(d.norm() > 0)) return {};
  d.normalize();
  std::array<CrackSide, 2> sides;
  sides[0] = insert_side(m, v, n_v, d, o);
  sides[1] = insert_side(m, v, n_v, -d, o);
  return sides;
}

}  // namespace phellem::bark

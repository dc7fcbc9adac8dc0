// Stress-field cracking model (Spicker 2014 sec. 3): the equations on cases with known
// answers — nodal forces (eq. 1), the tensile/compressive split (eqs. 2–3), the separation
// tensor (eq. 4), relaxation (eqs. 7–9), Algorithm 1 — and the parameter checks.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "bark/geometry/procedural_meshes.h"
#include "bark/stress/crack_insertion.h"
#include "bark/stress/crack_width.h"
#include "bark/stress/separation_tensor.h"
#include "bark/stress/stress_forces.h"
#include "bark/stress/stress_params.h"
#include "bark/stress/stress_relaxation.h"
#include "util/random.h"

using namespace phellem::bark;

namespace {

TriMesh one_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  TriMesh t;
  t.positions = {a, b, c};
  t.triangles = {{0, 1, 2}};
  return t;
}

FaceId first_face(const StressMesh& m) { return *m.mesh().faces().begin(); }

}  // namespace

TEST(StressForces, RightTriangleMatchesEquationOne) {
  // p0 = 0, p1 = x, p2 = y: b1 = x, b2 = y, b0 = 1 − x − y, A = ½, so f_i = −A σ ∇b_i with σ
  // given in world axes (the face's own frame may start at any of its edges).
  StressMesh m = StressMesh::from(one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  const FaceId f = first_face(m);
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  w.topLeftCorner<2, 2>() << 2.0, 0.5, 0.5, -1.0;
  m.set_world_stress(f, w);
  const auto forces = nodal_forces(m, f, m.face(f).sigma);
  const auto vs = m.vertices(f);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d p = m.point(vs[size_t(k)]);
    const Eigen::Vector3d grad = p.x() == 1   ? Eigen::Vector3d(1, 0, 0)
                                 : p.y() == 1 ? Eigen::Vector3d(0, 1, 0)
                                              : Eigen::Vector3d(-1, -1, 0);
    const Eigen::Vector3d expect = -0.5 * w * grad;
    EXPECT_LT((forces[size_t(k)] - expect).norm(), 1e-14) << "vertex " << k;
  }
}

TEST(StressForces, UniformTensionPullsEachVertexTowardsTheOppositeEdge) {
  // σ = s·I: |f_i| = s × (opposite edge)/2, directed from the vertex to its opposite edge,
  // whatever the triangle's shape and placement in space.
  const Eigen::Vector3d a(0.3, -0.2, 1.0), b(1.4, 0.5, 0.7), c(-0.1, 0.9, 0.2);
  StressMesh m = StressMesh::from(one_triangle(a, b, c));
  const FaceId f = first_face(m);
  const double s = 1.7;
  const auto forces = nodal_forces(m, f, s * Eigen::Matrix2d::Identity());
  const auto vs = m.vertices(f);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d p = m.point(vs[size_t(k)]), q = m.point(vs[size_t((k + 1) % 3)]), r = m.point(vs[size_t((k + 2) % 3)]);
    EXPECT_NEAR(forces[size_t(k)].norm(), s * (r - q).norm() / 2, 1e-12);
    // Perpendicular to the opposite edge, pointing away from the vertex.
    EXPECT_NEAR(forces[size_t(k)].dot(r - q), 0.0, 1e-12);
    EXPECT_LT(forces[size_t(k)].dot(p - q), 0.0);
    sum += forces[size_t(k)];
  }
  EXPECT_LT(sum.norm(), 1e-12);
}

TEST(StressForces, ClosedMeshForcesSumToZeroAndUniformTensionGivesLaplacePressure) {
  // Tension s in a sphere's skin: the net force on each vertex points inwards, and in all it
  // is Laplace's pressure 2s/R over the area (per vertex within the discretisation's error,
  // largest at the twelve vertices of valence 5).
  const double R = 2.0, s = 0.8;
  StressMesh m = StressMesh::from(icosphere(4, R));
  for (FaceId f : m.mesh().faces()) m.face(f).sigma = s * Eigen::Matrix2d::Identity();
  ForceField ff;
  compute_forces(m, StressTopology::build(m), ff);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double inward = 0, area_all = 0;
  for (VertexId v : m.mesh().vertices()) {
    total += ff.total[v.idx()];
    double area = 0;
    for (FaceId f : CGAL::faces_around_target(m.mesh().halfedge(v), m.mesh())) area += m.face(f).area / 3;
    const Eigen::Vector3d n = m.point(v).normalized();
    const double expect = 2 * s / R * area;
    EXPECT_NEAR(-ff.total[v.idx()].dot(n), expect, 0.2 * expect);
    EXPECT_LT((ff.total[v.idx()] - ff.total[v.idx()].dot(n) * n).norm(), 0.05 * expect);
    inward -= ff.total[v.idx()].dot(n);
    area_all += area;
  }
  EXPECT_LT(total.norm(), 1e-9);
  EXPECT_NEAR(inward / (2 * s / R * area_all), 1.0, 0.01);
}

TEST(StressForces, SplitIntoTensileAndCompressiveParts) {
  Eigen::Matrix2d s;
  s << 0.3, 1.1, 1.1, -0.4;  // one positive, one negative eigenvalue
  const auto [plus, minus] = split_stress(s);
  EXPECT_LT((plus + minus - s).norm(), 1e-14);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> ep(plus), em(minus);
  EXPECT_GE(ep.eigenvalues().minCoeff(), -1e-14);
  EXPECT_LE(em.eigenvalues().maxCoeff(), 1e-14);
  EXPECT_NEAR(ep.eigenvalues().maxCoeff(), Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(s).eigenvalues()[1], 1e-14);
  // A purely compressive tensor has no tensile part.
  EXPECT_TRUE(split_stress(-Eigen::Matrix2d::Identity()).first.isZero());
}

TEST(SeparationTensor, RegularFanUnderUniformTension) {
  // Six equilateral triangles of side e around a vertex, σ = s·I: each pulls the centre with
  // s·e/2 towards its far edge; the pulls cancel (f⁺ = 0) and ς = ½ Σ m(f) = ¾ s e in the plane.
  TriMesh fan;
  const double e = 0.5, s = 2.0;
  fan.positions.push_back({0, 0, 0});
  for (int k = 0; k < 6; ++k) fan.positions.push_back({e * std::cos(k * M_PI / 3), e * std::sin(k * M_PI / 3), 0});
  for (uint32_t k = 0; k < 6; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  StressMesh m = StressMesh::from(fan);
  for (FaceId f : m.mesh().faces()) m.face(f).sigma = s * Eigen::Matrix2d::Identity();
  ForceField ff;
  compute_forces(m, StressTopology::build(m), ff);
  const VertexId centre = *m.mesh().vertices().begin();
  ASSERT_NEAR(m.point(centre).norm(), 0.0, 0.0);
  const Eigen::Matrix3d z = separation_tensor(StressTopology::build(m), ff, uint32_t(centre.idx()));
  EXPECT_LT((z - z.transpose()).norm(), 1e-15);
  EXPECT_NEAR(z(0, 0), 0.75 * s * e, 1e-12);
  EXPECT_NEAR(z(1, 1), 0.75 * s * e, 1e-12);
  EXPECT_NEAR(z(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(z(2, 2), 0.0, 1e-12);
  // Compression instead: no tensile separation at all.
  for (FaceId f : m.mesh().faces()) m.face(f).sigma = -s * Eigen::Matrix2d::Identity();
  compute_forces(m, StressTopology::build(m), ff);
  EXPECT_LE(
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(separation_tensor(StressTopology::build(m), ff, uint32_t(centre.idx())))
          .eigenvalues()
          .maxCoeff(),
      1e-12);
}

TEST(SeparationTensor, SymmetricForRandomStress) {
  StressMesh m = StressMesh::from(jittered_sheet(8, 8, 1, 1, 0.3, 7));
  uint64_t k = 0;
  for (FaceId f : m.mesh().faces()) {
    phellem::StreamRng rng(3, k++, 0);
    Eigen::Matrix2d s;
    s << rng.symmetric(), rng.symmetric(), 0, rng.symmetric();
    s(1, 0) = s(0, 1);
    m.face(f).sigma = s;
  }
  ForceField ff;
  compute_forces(m, StressTopology::build(m), ff);
  for (VertexId v : m.mesh().vertices()) {
    const Eigen::Matrix3d z = separation_tensor(StressTopology::build(m), ff, uint32_t(v.idx()));
    EXPECT_LT((z - z.transpose()).norm(), 1e-14 * (1 + z.norm()));
  }
}

TEST(StressRelaxation, LowersStressEnergyMonotonicallyAndSpreadsAHotSpot) {
  StressMesh m = StressMesh::from(jittered_sheet(12, 12, 1, 1, 0.3, 11));
  FaceId hot;
  double best = 1e9;
  for (FaceId f : m.mesh().faces()) {
    const auto vs = m.vertices(f);
    const Eigen::Vector3d c = (m.point(vs[0]) + m.point(vs[1]) + m.point(vs[2])) / 3;
    if (const double d = (c - Eigen::Vector3d(0.5, 0.5, 0)).norm(); d < best) {
      best = d;
      hot = f;
    }
  }
  m.face(hot).sigma = Eigen::Vector2d(3.0, 1.0).asDiagonal();
  ForceField ff;
  double energy = stress_energy(m);
  const double dt = 0.1;
  for (int it = 0; it < 40; ++it) {
    compute_forces(m, StressTopology::build(m), ff);
    double F2 = 0;
    const std::vector<double> k = vertex_stiffness(m, StressTopology::build(m));
    for (size_t i = 0; i < k.size(); ++i) F2 += ff.total[i].squaredNorm() / k[i];
    relax(m, StressTopology::build(m), ff, dt);
    const double now = stress_energy(m);
    EXPECT_LT(now, energy) << "iteration " << it;
    // First order: ΔE = −2Δt Σ|F|²/k.
    if (it == 0) {
      EXPECT_NEAR((now - energy) / (-2 * dt * F2), 1.0, 0.1);
    }
    energy = now;
  }
  EXPECT_LT(m.face(hot).sigma.norm(), 0.9 * Eigen::Vector2d(3.0, 1.0).norm());
  // A neighbour of the hot face took some of its stress.
  const HalfedgeId h = m.mesh().opposite(m.mesh().halfedge(hot));
  EXPECT_GT(m.face(m.mesh().face(h)).sigma.norm(), 1e-3);
}

TEST(StressRelaxation, KappaClampBoundsBetaSingularValues) {
  // A sliver: huge β singular values, clamped to the bound.
  StressMesh m = StressMesh::from(one_triangle({0, 0, 0}, {1, 0, 0}, {0.5, 1e-3, 0}));
  FaceState& s = m.face(first_face(m));
  const double before = Eigen::JacobiSVD<Eigen::Matrix3d>(s.beta).singularValues()[0];
  ASSERT_GT(before, 100);
  clamp_beta(s, 10.0);
  EXPECT_LE(Eigen::JacobiSVD<Eigen::Matrix3d>(s.beta).singularValues()[0], 10.0 * (1 + 1e-12));
  // A well-shaped face under the bound is left alone.
  StressMesh w = StressMesh::from(one_triangle({0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0}));
  const Eigen::Matrix3d b = w.face(first_face(w)).beta;
  clamp_beta(w.face(first_face(w)), 1e6);
  EXPECT_EQ(w.face(first_face(w)).beta, b);
}

TEST(CrackWidth, AlgorithmOneOnAPathAStarAndACycle) {
  // Path 0-1-2-3-4: distances to the nearest end 0 1 2 1 0.
  auto path = CrackGraph::from_edges(5, {{0, 1}, {1, 2}, {2, 3}, {3, 4}});
  EXPECT_EQ(crack_widths(path), (std::vector<int32_t>{0, 1, 2, 1, 0}));
  // Star: centre 0 with three arms of two edges (0-1-2, 0-3-4, 0-5-6): ends 0, middles 1, centre 2.
  auto star = CrackGraph::from_edges(7, {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {0, 5}, {5, 6}});
  EXPECT_EQ(crack_widths(star), (std::vector<int32_t>{2, 1, 0, 1, 0, 1, 0}));
  // A closed crack of 6 vertices: no ends; the search from any vertex finds new vertices up
  // to distance 3. Plus an isolated vertex 6: width 0, no component.
  auto cycle = CrackGraph::from_edges(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}});
  EXPECT_EQ(crack_widths(cycle), (std::vector<int32_t>{3, 3, 3, 3, 3, 3, 0}));
  // A cycle of 5 with a tail 0-5-6: distances to the end 6.
  auto lasso = CrackGraph::from_edges(7, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}, {0, 5}, {5, 6}});
  EXPECT_EQ(crack_widths(lasso), (std::vector<int32_t>{2, 3, 4, 4, 3, 1, 0}));
}

TEST(CrackWidth, ComponentsNumberConnectedCracks) {
  auto g = CrackGraph::from_edges(8, {{0, 1}, {1, 2}, {4, 5}, {6, 5}});
  EXPECT_EQ(crack_components(g), (std::vector<int32_t>{0, 0, 0, -1, 1, 1, 1, -1}));
}

TEST(StressParams, RefusesOutOfRangeSettings) {
  StressParams p;
  EXPECT_FALSE(validate(p).has_value());
  auto bad = [](auto mutate, const std::string& key) {
    StressParams q;
    mutate(q);
    const auto e = validate(q);
    ASSERT_TRUE(e.has_value()) << key;
    EXPECT_EQ(e->key, key);
    EXPECT_FALSE(e->message.empty());
  };
  bad([](StressParams& q) { q.alpha = 1.5; }, "alpha");
  bad([](StressParams& q) { q.stress_alleviation = -0.1; }, "stress_alleviation");
  bad([](StressParams& q) { q.iterations = -1; }, "iterations");
  bad([](StressParams& q) { q.cracks_per_iteration = -2; }, "cracks_per_iteration");
  bad([](StressParams& q) { q.relaxations_per_iteration = 5000; }, "relaxations_per_iteration");
  bad([](StressParams& q) { q.threshold = 0; }, "threshold");
  bad([](StressParams& q) { q.time_step = 1.0; }, "time_step");
  bad([](StressParams& q) { q.kappa = 0.5; }, "kappa");
  bad([](StressParams& q) { q.snap_angle_deg = 60; }, "snap_angle");
  bad([](StressParams& q) { q.random_rotation = std::nan(""); }, "random_rotation");
  bad([](StressParams& q) { q.pattern = StressPattern::Image; }, "pattern");
}

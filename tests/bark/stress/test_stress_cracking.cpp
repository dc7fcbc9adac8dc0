// Stress-field cracking (Spicker 2014 sec. 3.1.3, 3.2, 3.3): crack insertion keeps the mesh
// a valid oriented manifold with continuous UVs and no sliver without snapping; the stress
// patterns steer the cracks; strokes crack along the stroke; determinism across thread
// counts; malformed meshes are refused.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "bark/geometry/irregular_remesh.h"
#include "bark/geometry/procedural_meshes.h"

#include <map>
#include "bark/stress/crack_insertion.h"
#include "bark/stress/stress_cracker.h"
#include "bark/stress/stress_mesh.h"
#include "bark/stress/stress_patterns.h"

using namespace phellem::bark;

namespace {

constexpr double kPi = 3.141592653589793;

// Angle of each crack edge from the +X axis folded into [0°, 90°] on a sheet in the XY plane,
// weighted by length: returns the length fraction closer to vertical (> 45°).
double vertical_fraction(const StressMesh& m) {
  const SurfaceMesh& g = m.mesh();
  double vert = 0, total = 0;
  for (EdgeId e : g.edges()) {
    if (!m.crack(e)) continue;
    const Eigen::Vector3d d = m.point(g.vertex(e, 1)) - m.point(g.vertex(e, 0));
    const double a = std::atan2(std::abs(d.y()), std::abs(d.x()));
    total += d.norm();
    if (a > kPi / 4) vert += d.norm();
  }
  return total > 0 ? vert / total : 0.5;
}

StressParams sheet_params(StressPattern pattern) {
  StressParams p;
  p.pattern = pattern;
  p.iterations = 20;
  p.cracks_per_iteration = 6;
  p.relaxations_per_iteration = 1;
  p.alpha = 0.3;
  p.threshold = 0.4;
  p.seed = 5;
  return p;
}

}  // namespace

TEST(CrackInsertion, KeepsAClosedMeshValidOrientedAndWatertight) {
  StressMesh m = StressMesh::from(icosphere(3, 1.0));
  const size_t v0 = m.mesh().number_of_vertices(), f0 = m.mesh().number_of_faces();
  CrackInsertOptions o;
  o.snap_angle = 10 * kPi / 180;
  int k = 0;
  for (VertexId v : std::vector<VertexId>(m.mesh().vertices().begin(), m.mesh().vertices().end())) {
    if (k++ % 7) continue;
    const Eigen::Vector3d n = m.point(v).normalized();
    const Eigen::Vector3d dir = n.cross(Eigen::Vector3d(std::sin(k), std::cos(3 * k), 0.5).normalized());
    insert_crack(m, v, dir, o);
  }
  const SurfaceMesh& g = m.mesh();
  EXPECT_TRUE(g.is_valid(false));
  EXPECT_GT(g.number_of_vertices(), v0);
  EXPECT_GT(g.number_of_faces(), f0);
  for (HalfedgeId h : g.halfedges()) EXPECT_FALSE(g.is_border(h));  // still closed
  // Euler characteristic of a sphere, and every face still facing outwards.
  EXPECT_EQ(long(g.number_of_vertices()) - long(g.number_of_edges()) + long(g.number_of_faces()), 2);
  for (FaceId f : g.faces()) {
    const auto vs = m.vertices(f);
    const Eigen::Vector3d c = (m.point(vs[0]) + m.point(vs[1]) + m.point(vs[2])) / 3;
    EXPECT_GT(m.face(f).normal.dot(c), 0.0);
  }
}

TEST(CrackInsertion, NoSliverWithoutSnappingAndUVsStayContinuous) {
  // A sheet whose UVs are a linear function of position: after cracking, every corner's UV
  // must still be that function of its vertex (interpolated, not copied). No new face may have
  // an angle below the snap angle unless it existed before (splits that would make one snap).
  TriMesh sheet = jittered_sheet(10, 10, 1.0, 1.0, 0.25, 3);
  StressMesh m = StressMesh::from(sheet);
  double initial_min = kPi;
  for (FaceId f : m.mesh().faces()) {
    const auto vs = m.vertices(f);
    initial_min = std::min(initial_min, min_angle(m.point(vs[0]), m.point(vs[1]), m.point(vs[2])));
  }
  CrackInsertOptions o;
  o.snap_angle = std::min(12 * kPi / 180, initial_min);
  int splits = 0, snaps = 0, k = 0;
  for (VertexId v : std::vector<VertexId>(m.mesh().vertices().begin(), m.mesh().vertices().end())) {
    const double a = 0.7 * k++;
    for (const CrackSide& s : insert_crack(m, v, Eigen::Vector3d(std::cos(a), std::sin(a), 0), o)) {
      splits += s.split;
      snaps += s.snapped;
    }
  }
  EXPECT_GT(splits, 20);
  EXPECT_GT(snaps, 0);
  const SurfaceMesh& g = m.mesh();
  EXPECT_TRUE(g.is_valid(false));
  for (FaceId f : g.faces()) {
    const auto vs = m.vertices(f);
    EXPECT_GE(min_angle(m.point(vs[0]), m.point(vs[1]), m.point(vs[2])), o.snap_angle * (1 - 1e-9));
    EXPECT_GT(m.face(f).normal.z(), 0.0);
    for (HalfedgeId h : CGAL::halfedges_around_face(g.halfedge(f), g)) {
      const Eigen::Vector3d p = m.point(g.target(h));
      EXPECT_NEAR(m.uv(h).x(), p.x(), 1e-12);
      EXPECT_NEAR(m.uv(h).y(), p.y(), 1e-12);
    }
  }
}

TEST(StressCracker, HorizontalStressCracksVerticallyAndViceVersa) {
  const TriMesh sheet = jittered_sheet(30, 30, 1.0, 1.0, 0.3, 9);
  StressCracker h(StressMesh::from(sheet), sheet_params(StressPattern::Horizontal));
  h.run();
  StressCracker v(StressMesh::from(sheet), sheet_params(StressPattern::Vertical));
  v.run();
  ASSERT_GT(h.stats().crack_edges, 30);
  ASSERT_GT(v.stats().crack_edges, 30);
  EXPECT_GT(vertical_fraction(h.mesh()), 0.75);
  EXPECT_LT(vertical_fraction(v.mesh()), 0.25);
}

TEST(StressCracker, StrokeCracksAlongTheStroke) {
  // No stress but a diagonal UV stroke: the cracks lie near the stroke and run along it.
  const TriMesh sheet = jittered_sheet(30, 30, 1.0, 1.0, 0.3, 4);
  StressParams p = sheet_params(StressPattern::Strokes);
  StressStroke s;
  s.points = {{0.2, 0.2, 0}, {0.8, 0.8, 0}};
  p.strokes = {s};
  StressCracker c(StressMesh::from(sheet), p);
  c.run();
  const StressMesh& m = c.mesh();
  const SurfaceMesh& g = m.mesh();
  const Eigen::Vector3d along = Eigen::Vector3d(1, 1, 0).normalized();
  double length = 0, parallel = 0;
  for (EdgeId e : g.edges()) {
    if (!m.crack(e)) continue;
    const Eigen::Vector3d a = m.point(g.vertex(e, 0)), b = m.point(g.vertex(e, 1)), mid = 0.5 * (a + b);
    // Distance from the stroke's line.
    EXPECT_LT(std::abs(mid.x() - mid.y()) / std::sqrt(2.0), 0.12);
    length += (b - a).norm();
    parallel += std::abs((b - a).dot(along));
  }
  ASSERT_GT(length, 0.3);
  EXPECT_GT(parallel / length, 0.8);
}

TEST(StressCracker, SameResultOnOneAndTwoThreads) {
  const TriMesh cyl = cylinder_mesh(0.2, 1.0, 40, 30, 0.3, 2);
  StressParams p = sheet_params(StressPattern::Horizontal);
  p.crack_rotation = 0.2;
  p.random_rotation = 0.1;
  p.stress_alleviation = 0.3;
  p.relaxations_per_iteration = 2;
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    StressCracker c(StressMesh::from(cyl), p);
    c.run();
    return c.result();
  };
  const CrackedMesh a = run(1), b = run(2);
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  ASSERT_EQ(a.crack_edges, b.crack_edges);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  for (size_t k = 0; k < a.mesh.positions.size(); ++k) {
    EXPECT_EQ(a.mesh.positions[k], b.mesh.positions[k]);
    EXPECT_EQ(a.displacement[k], b.displacement[k]);
  }
  EXPECT_FALSE(a.crack_edges.empty());
}

TEST(StressCracker, NewFacesRespectTheKappaClamp) {
  const TriMesh sheet = jittered_sheet(20, 20, 1.0, 1.0, 0.3, 6);
  StressParams p = sheet_params(StressPattern::UniformTension);
  p.kappa = 1.5;
  StressMesh m = StressMesh::from(sheet);
  const double bound = p.kappa * m.max_beta_singular_value();
  StressCracker c(std::move(m), p);
  c.run();
  ASSERT_GT(c.stats().splits, 0);
  for (FaceId f : c.mesh().mesh().faces())
    EXPECT_LE(Eigen::JacobiSVD<Eigen::Matrix3d>(c.mesh().face(f).beta).singularValues()[0], bound * (1 + 1e-9));
}

TEST(StressPatterns, GrowthPullsAroundATubeOfAnyOrientation) {
  // A cylinder of radius 0.2 tilted 60° from +Y: outward growth stretches it around its girth
  // only (normal curvature 1/r around, 0 along), so each face's stress is about s·g gᵀ with g
  // the girth direction; the "horizontal" pattern, tied to +Y, is not.
  TriMesh cyl = cylinder_mesh(0.2, 1.0, 48, 40, 0.0, 1);
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(kPi / 3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (auto& p : cyl.positions) p = tilt * p;
  const Eigen::Vector3d axis = tilt * Eigen::Vector3d::UnitY();
  auto girth_alignment = [&](StressPattern pattern, const StressImage* image = nullptr) {
    StressMesh m = StressMesh::from(cyl);
    StressParams p;
    p.pattern = pattern;
    if (image) p.image = *image;
    p.magnitude = 2.0;
    p.random_rotation = 0;
    initialize_stress(m, p);
    double worst = 0, mean_tension = 0;
    int faces = 0;
    for (FaceId f : m.mesh().faces()) {
      const FaceState& st = m.face(f);
      if (std::abs(st.normal.dot(axis)) > 1e-6) continue;  // (none on this open tube)
      const Eigen::Matrix3d w = st.frame * st.sigma * st.frame.transpose();
      const Eigen::Vector3d girth = axis.cross(st.normal).normalized();
      worst = std::max({worst, std::abs(axis.dot(w * axis)), std::abs(girth.dot(w * axis))});
      mean_tension += girth.dot(w * girth);
      ++faces;
    }
    return std::pair{worst, mean_tension / faces};
  };
  const auto [growth_off, growth_tension] = girth_alignment(StressPattern::Growth);
  EXPECT_LT(growth_off, 0.05 * 2.0);      // nothing along the axis, no shear
  EXPECT_NEAR(growth_tension, 2.0, 0.1);  // the median face carries the magnitude
  // A one-channel stress image scales it like any pattern.
  StressImage half;
  half.width = half.height = half.channels = 1;
  half.values = {0.5f};
  const auto [scaled_off, scaled_tension] = girth_alignment(StressPattern::Growth, &half);
  EXPECT_NEAR(scaled_tension, 1.0, 0.05);
  const auto [horizontal_off, horizontal_tension] = girth_alignment(StressPattern::Horizontal);
  EXPECT_GT(horizontal_off, 0.3 * 2.0) << "the horizontal pattern does not follow a tilted tube";
  // A flat sheet does not stretch when it grows outward.
  StressMesh sheet = StressMesh::from(jittered_sheet(8, 8, 1.0, 1.0, 0.2, 3));
  StressParams p;
  p.pattern = StressPattern::Growth;
  initialize_stress(sheet, p);
  for (FaceId f : sheet.mesh().faces()) EXPECT_LT(sheet.face(f).sigma.norm(), 1e-12);
}

TEST(StressMesh, RefusesMalformedMeshes) {
  auto refused = [](const TriMesh& t, const std::string& where, const std::string& what) {
    try {
      (void)StressMesh::from(t);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const MeshError& e) {
      EXPECT_EQ(e.where, where);
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  TriMesh empty;
  refused(empty, "mesh", "no triangles");
  TriMesh t;
  t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  t.triangles = {{0, 1, 7}};
  refused(t, "triangle 0", "out of range");
  t.triangles = {{0, 1, 1}};
  refused(t, "triangle 0", "degenerate");
  TriMesh line = t;
  line.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  line.triangles = {{0, 1, 2}};
  refused(line, "triangle 0", "zero area");
  // Three triangles on one edge.
  t.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  refused(t, "triangle 2", "non-manifold");
  TriMesh nan = line;
  nan.positions[1].x() = std::nan("");
  refused(nan, "vertex 1", "non-finite");
}

TEST(IrregularRemesh, WellShapedIrregularAndUVsFollowTheSurface) {
  // A regular sheet with UV = (x, y): after remeshing every corner's UV is still its position,
  // triangles are well shaped, and the valences are no longer all six.
  const TriMesh sheet = jittered_sheet(20, 20, 1.0, 1.0, 0.0, 1);
  RemeshOptions o;
  o.edge_length = 0.04;
  const TriMesh r = irregular_remesh(sheet, o);
  ASSERT_FALSE(r.triangles.empty());
  StressMesh m = StressMesh::from(r);  // valid manifold
  EXPECT_TRUE(m.mesh().is_valid(false));
  double edge = 0;
  for (EdgeId e : m.mesh().edges()) edge += (m.point(m.mesh().vertex(e, 0)) - m.point(m.mesh().vertex(e, 1))).norm();
  edge /= double(m.mesh().number_of_edges());
  EXPECT_NEAR(edge, 0.04, 0.01);
  int slivers = 0;
  for (const auto& t : r.triangles)
    slivers += min_angle(r.positions[t[0]], r.positions[t[1]], r.positions[t[2]]) < 15 * kPi / 180;
  EXPECT_LT(slivers, int(r.triangles.size() / 50));
  for (size_t k = 0; k < r.positions.size(); ++k) {
    EXPECT_NEAR(r.uvs[k].x(), r.positions[k].x(), 1e-9);
    EXPECT_NEAR(r.uvs[k].y(), r.positions[k].y(), 1e-9);
    EXPECT_NEAR(r.positions[k].z(), 0.0, 1e-12);
  }
  std::map<size_t, int> valence;
  for (VertexId v : m.mesh().vertices())
    if (!m.mesh().is_border(v)) ++valence[m.mesh().degree(v)];
  EXPECT_LT(valence[6], int(0.8 * double(m.mesh().number_of_vertices())));
}

TEST(IrregularRemesh, KeepsTheUVSeamOfACylinder) {
  // The cylinder is welded around but its UVs jump from 1 back to 0: no face may interpolate
  // across the jump, and the corners on the seam carry both values.
  const TriMesh cyl = cylinder_mesh(0.2, 1.0, 24, 20, 0.0, 1);
  RemeshOptions o;
  o.edge_length = 0.05;
  const TriMesh r = irregular_remesh(cyl, o);
  int seam_low = 0, seam_high = 0;
  for (const auto& t : r.triangles) {
    double lo = 1e9, hi = -1e9;
    for (uint32_t k : t) {
      lo = std::min(lo, r.uvs[k].x());
      hi = std::max(hi, r.uvs[k].x());
      const double theta = std::atan2(-r.positions[k].z(), r.positions[k].x());  // cylinder_mesh: u = θ / 2π
      const double u = theta < -1e-9 ? theta / (2 * kPi) + 1 : theta / (2 * kPi);
      // (u is linear along each facet's chord: within 2e-3 of θ / 2π on this 24-sided prism.)
      EXPECT_TRUE(std::abs(r.uvs[k].x() - u) < 2e-3 || std::abs(r.uvs[k].x() - u - 1) < 2e-3 ||
                  std::abs(r.uvs[k].x() - u + 1) < 2e-3)
          << r.uvs[k].x() << " vs " << u;
      seam_low += r.uvs[k].x() < 1e-9;
      seam_high += r.uvs[k].x() > 1 - 1e-9;
    }
    EXPECT_LT(hi - lo, 0.5);
  }
  EXPECT_GT(seam_low, 0);
  EXPECT_GT(seam_high, 0);
}

TEST(IrregularRemesh, VerticesLieOnTheSmoothSurfaceNotOnTheInputFacets) {
  // A 24-sided prism samples a cylinder of radius 0.2 with a sagitta of 1.7 mm; a 2-times
  // subdivided icosahedron samples the unit sphere. Remeshed vertices land on the flat facets
  // (up to a sagitta inside) unless moved onto the smooth surface (Phong, α = ½).
  const double sagitta = 0.2 * (1 - std::cos(kPi / 24));
  auto worst_cylinder = [&](bool smooth) {
    RemeshOptions o;
    o.edge_length = 0.04;
    o.smooth = smooth;
    const TriMesh r = irregular_remesh(cylinder_mesh(0.2, 1.0, 24, 20, 0.0, 1), o);
    double worst = 0;
    for (const auto& p : r.positions) worst = std::max(worst, std::abs(std::hypot(p.x(), p.z()) - 0.2));
    return worst;
  };
  EXPECT_GT(worst_cylinder(false), 0.3 * sagitta) << "the flat facets are not where the test expects";
  EXPECT_LT(worst_cylinder(true), 0.03 * sagitta);
  // On the sphere (faces of unequal size, normals averaged over five or six of them) the
  // mean distance falls about 18-fold and the worst 7-fold.
  auto sphere_error = [](bool smooth) {
    RemeshOptions o;
    o.edge_length = 0.15;
    o.smooth = smooth;
    const TriMesh r = irregular_remesh(icosphere(2, 1.0), o);
    double worst = 0, mean = 0;
    for (const auto& p : r.positions) {
      worst = std::max(worst, std::abs(p.norm() - 1));
      mean += std::abs(p.norm() - 1) / double(r.positions.size());
    }
    return std::pair{worst, mean};
  };
  const auto [flat_worst, flat_mean] = sphere_error(false);
  const auto [smooth_worst, smooth_mean] = sphere_error(true);
  EXPECT_LT(smooth_worst, 0.25 * flat_worst);
  EXPECT_LT(smooth_mean, 0.1 * flat_mean);
}

TEST(IrregularRemesh, SharpFeaturesStayFlat) {
  // A unit cube: its corners' averaged normals are 55° off every face, so no face is curved;
  // every vertex stays on the cube's surface.
  TriMesh box;
  for (int k = 0; k < 8; ++k) box.positions.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  RemeshOptions o;
  o.edge_length = 0.2;
  const TriMesh r = irregular_remesh(box, o);
  ASSERT_GT(r.positions.size(), 50u);
  for (const auto& p : r.positions) {
    const double outside = std::max({std::abs(p.x() - 0.5), std::abs(p.y() - 0.5), std::abs(p.z() - 0.5)});
    EXPECT_NEAR(outside, 0.5, 1e-9) << p.transpose();
  }
}

TEST(StressCracker, UVStrokesAndImagesNeedTextureCoordinates) {
  TriMesh sheet = jittered_sheet(6, 6, 1.0, 1.0, 0.2, 1);
  sheet.uvs.clear();
  StressParams p = sheet_params(StressPattern::Strokes);
  StressStroke s;
  s.points = {{0.2, 0.2, 0}, {0.8, 0.8, 0}};
  p.strokes = {s};
  try {
    StressCracker c(StressMesh::from(sheet), p);
    ADD_FAILURE() << "a UV stroke on a mesh without UVs was accepted";
  } catch (const StressParamError& e) {
    EXPECT_EQ(e.key, "strokes");
  }
  p.strokes[0].in_uv = false;  // the same stroke as 3D points is fine
  StressCracker ok(StressMesh::from(sheet), p);
  ok.run();
  EXPECT_GT(ok.stats().crack_edges, 0);
}

TEST(StressCracker, GivenStressIsKeptAndThePatternsIsSetWithoutIt) {
  // Crack coupling gives every face its stress itself (InitialStress::kGiven): the cracker
  // must keep it, not overwrite it with the pattern's.
  const TriMesh sheet = jittered_sheet(8, 8, 1.0, 1.0, 0.3, 2);
  const StressParams p = sheet_params(StressPattern::Horizontal);
  StressMesh given = StressMesh::from(sheet), patterned = StressMesh::from(sheet);
  std::vector<Eigen::Matrix2d> sigma;
  for (StressMesh* m : {&given, &patterned}) {
    sigma.clear();
    for (FaceId f : m->mesh().faces()) {
      m->face(f).sigma << 0.25 + 0.01 * f.idx(), 0.5, 0.5, -1.0;
      sigma.push_back(m->face(f).sigma);
    }
  }
  const StressCracker kept(std::move(given), p, StressCracker::InitialStress::kGiven);
  const StressCracker set(std::move(patterned), p);
  size_t i = 0, differ = 0;
  for (FaceId f : kept.mesh().mesh().faces()) {
    EXPECT_EQ(kept.mesh().face(f).sigma, sigma[i]) << "face " << i;
    differ += set.mesh().face(f).sigma != sigma[i];
    ++i;
  }
  EXPECT_EQ(differ, i);  // the pattern replaced every face's
}

TEST(StressMesh, LargestBetaSingularValueIsTheMaximumOverTheFaces) {
  // Taken in parallel over the face indices, removed faces skipped: the same as the serial
  // maximum, also after crack insertion has added faces.
  const TriMesh sheet = jittered_sheet(30, 30, 1.0, 1.0, 0.3, 4);
  StressCracker c(StressMesh::from(sheet), sheet_params(StressPattern::UniformTension));
  for (int k = 0; k < 3; ++k) c.iterate();
  ASSERT_GT(c.stats().splits, 0);
  double serial = 0;
  for (FaceId f : c.mesh().mesh().faces())
    serial = std::max(serial, Eigen::JacobiSVD<Eigen::Matrix3d>(c.mesh().face(f).beta).singularValues()[0]);
  EXPECT_EQ(c.mesh().max_beta_singular_value(), serial);
  EXPECT_GT(serial, 0);
}

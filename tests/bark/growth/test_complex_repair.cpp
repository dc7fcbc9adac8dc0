// The repair of the deformable simplicial complex (bark/growth/complex_repair.h and its parts:
// tet_adjacency.h, interface_coarsening.h, tet_flips.h; Kratt et al., Woodification, sec. 3):
// collapses keep the interface a closed oriented manifold, flips never touch the interface,
// and a sphere grown 1.6× with splits, collapses and flips every step stays a sphere of the
// right radius with no inverted tetrahedron, whatever the thread count.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "bark/geometry/procedural_meshes.h"
#include "bark/growth/cambial_growth.h"
#include "bark/growth/complex_repair.h"
#include "bark/growth/interface_coarsening.h"
#include "bark/growth/interface_flips.h"
#include "bark/growth/interface_motion.h"
#include "bark/growth/interface_refinement.h"
#include "bark/growth/tet_flips.h"
#include "tests/support/closed_surface.h"

using namespace phellem;
using namespace phellem::bark;
using phellem::test::closed_manifold;

namespace {

GrowthFunction growth_of(double thickness) {
  GrowthFunction g;
  g.weibull_c = 1;
  g.thickness = float(thickness);
  return g;
}

std::vector<std::array<uint32_t, 3>> sorted(std::vector<std::array<uint32_t, 3>> f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Each face rotated to start at its smallest point (its orientation kept), sorted.
std::vector<std::array<uint32_t, 3>> rotated(std::vector<std::array<uint32_t, 3>> f) {
  for (auto& t : f) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(f.begin(), f.end());
  return f;
}

std::pair<double, double> edge_range(const TetComplex& c) {
  double lo = 1e300, hi = 0;
  for (const auto& e : interface_edges(c)) {
    const double l = (c.points[e[0]] - c.points[e[1]]).norm();
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return {lo, hi};
}

// The labels are those the interface says: every point the interface uses is flagged, no
// other point is, and no point without tetrahedra is.
void expect_consistent_flags(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces) {
  std::vector<uint8_t> used(c.points.size(), 0), on(c.points.size(), 0);
  for (const auto& t : c.tets)
    for (uint32_t v : t) used[v] = 1;
  for (const auto& f : faces)
    for (uint32_t v : f) on[v] = 1;
  for (size_t i = 0; i < c.points.size(); ++i) {
    ASSERT_EQ(c.on_interface[i], on[i]) << "point " << i;
    if (!used[i]) {
      ASSERT_EQ(c.on_interface[i], 0) << "point " << i;
    }
  }
  for (uint8_t l : c.label) ASSERT_TRUE(l == TetComplex::kInside || l == TetComplex::kOutside);
}

struct GrowthRun {
  double lag = 0;          // the worst |r − (R₀ + thickening)| of an interface vertex at the end
  double volume_ratio = 0;  // the inside volume over the sphere's
  double band_max = 0;
  long shortened = 0, clamped = 0;
  long short_edges = 0;  // the most interface edges below the band's lower bound after a step
};

// A 0.5 m icosphere(3) grown to 0.8 m over 20 steps; `repair`: the DSC step (collapses and
// flips too), else only the splits (as before the repair existed).
GrowthRun grow_sphere(bool repair, bool check_every_step) {
  const double r0 = 0.5;
  TetComplex c = tetrahedralize_surface(icosphere(3, r0), TetSettings{}, "s.json", "/objects/0");
  GrowthRun run;
  run.band_max = edge_range(c).second;
  const double band_min = 0.4 * run.band_max;
  const GrowthFunction g = growth_of(1.0);
  const double t_end = -std::log(0.7);  // thickening 1 − exp(−t) = 0.3 m
  const int steps = 20;
  for (int k = 0; k < steps; ++k) {
    const InterfaceStepStats st = advance_interface(c, g, t_end * k / steps, t_end * (k + 1) / steps);
    run.shortened += st.shortened;
    run.clamped += st.clamped;
    if (repair) {
      const RepairStats rs = growth_repair_step(c, band_min, run.band_max);
      if (check_every_step)
        std::printf("step %d: %ld moved, %ld shortened, %ld clamped, %ld flips; repair %ld splits, %ld collapses, %ld+%ld flips, %ld relocated, %ld free splits\n",
                    k, st.moved, st.shortened, st.clamped, st.flips, rs.splits, rs.collapses, rs.flips23, rs.flips32, rs.relocated, rs.free_splits);
    }
    else
      split_long_interface_edges(c, run.band_max);
    if (!check_every_step) continue;
    EXPECT_EQ(c.first_inverted(), -1) << "step " << k;
    const auto faces = c.interface_faces();
    EXPECT_TRUE(closed_manifold(faces)) << "step " << k;
    EXPECT_EQ(sorted(interface_faces(c, TetAdjacency(c))), faces) << "step " << k;
    expect_consistent_flags(c, faces);
    // Every edge below the band's upper bound; below its lower bound only the few whose
    // collapse the link condition or the positivity refuses (not yet flipped away: at most 1%).
    long edges = 0, short_edges = 0;
    for (const auto& e : interface_edges(c)) {
      const double l = (c.points[e[0]] - c.points[e[1]]).norm();
      ++edges;
      short_edges += l < band_min;
      EXPECT_LE(l, run.band_max) << "step " << k;
    }
    EXPECT_LE(short_edges, edges / 100) << "step " << k;
    run.short_edges = std::max(run.short_edges, short_edges);
  }
  const double r = r0 + g.cumulative(t_end);
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) run.lag = std::max(run.lag, std::abs(c.points[i].norm() - r));
  run.volume_ratio = c.volume(TetComplex::kInside) / (4.0 / 3.0 * M_PI * r * r * r);
  return run;
}

}  // namespace

TEST(TetAdjacency, InterfaceFacesMatchTheMapBasedScan) {
  const TetComplex c = tetrahedralize_surface(icosphere(2, 0.5), TetSettings{}, "s.json", "/objects/0");
  const TetAdjacency adj(c);
  EXPECT_EQ(sorted(interface_faces(c, adj)), c.interface_faces());
  for (uint32_t p = 0; p < c.points.size(); ++p)
    for (uint32_t t : adj.around(p)) EXPECT_NE(std::find(c.tets[t].begin(), c.tets[t].end(), p), c.tets[t].end());
}

TEST(TetAdjacency, TheFilteredOrientationTestAgreesWithCGALsExactOne) {
  // Random tetrahedra (the filter decides nearly all), and flat ones: a fourth point on the
  // plane of three, exactly (integer coordinates) and then nudged by single ulps off it, where
  // the double determinant is below its error bound and CGAL decides. Both signs occur.
  uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1p-53;
  };
  auto point = [&] { return Eigen::Vector3d(next() - 0.5, next() - 0.5, next() - 0.5); };
  long positive = 0, negative = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d a = point(), b = point(), c = point(), d = point();
    const bool exact = positive_tet_exact(a, b, c, d);
    ASSERT_EQ(positive_tet(a, b, c, d), exact) << i;
    (exact ? positive : negative) += 1;
  }
  EXPECT_GT(positive, 5000);
  EXPECT_GT(negative, 5000);
  long flat_positive = 0, flat_negative = 0, flat_zero = 0;
  for (int i = 0; i < 2000; ++i) {
    auto lattice = [&] { return Eigen::Vector3d(std::floor(next() * 64), std::floor(next() * 64), std::floor(next() * 64)); };
    const Eigen::Vector3d a = lattice(), b = lattice(), c = lattice();
    const double s = std::floor(next() * 8) - 3, t = std::floor(next() * 8) - 3;
    Eigen::Vector3d d = a + s * (b - a) + t * (c - a);  // exact: small integers
    const int k = i % 3;
    if (i % 5 != 0) d[k] = std::nextafter(d[k], (i % 2) ? 1e9 : -1e9);
    const Eigen::Vector3d shift(0.1, 0.2, 0.3);  // off the integers: rounding in the differences
    const bool exact = positive_tet_exact(a + shift, b + shift, c + shift, d + shift);
    ASSERT_EQ(positive_tet(a + shift, b + shift, c + shift, d + shift), exact) << i;
    ASSERT_EQ(positive_tet(a, b, c, d), positive_tet_exact(a, b, c, d)) << i;
    if (i % 5 == 0)
      flat_zero += !positive_tet_exact(a, b, c, d) && !positive_tet_exact(a, c, b, d);
    else
      (exact ? flat_positive : flat_negative) += 1;
  }
  EXPECT_GT(flat_zero, 300);  // exactly flat: positive neither way round
  EXPECT_GT(flat_positive, 100);
  EXPECT_GT(flat_negative, 100);
}

TEST(TetAdjacency, RememberedNeighboursNeverChangeAnAnswerAfterTheComplexChanges) {
  // A sphere grown and repaired for some steps through one adjacency, whose hints the splits,
  // collapses and flips leave stale: every face's neighbour is still what a fresh adjacency
  // finds by walking.
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  TetAdjacency adj(c);
  const double band_max = edge_range(c).second;
  const GrowthFunction g = growth_of(0.15);
  RepairStats total;
  for (int k = 0; k < 6; ++k) {
    advance_interface(c, adj, g, 1.0 * k / 6, 1.0 * (k + 1) / 6);
    const RepairStats st = growth_repair_step(c, adj, 0.4 * band_max, band_max);
    total.splits += st.splits;
    total.collapses += st.collapses;
  }
  ASSERT_GT(total.splits, 0);
  const TetAdjacency fresh(c);
  for (uint32_t t = 0; t < c.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) ASSERT_EQ(adj.across(c, t, f), fresh.across(c, t, f)) << t << " " << f;
  // And the interface faces at a point are those of the whole scan at it, in its order.
  const auto faces = interface_faces(c, adj);
  std::vector<std::array<uint32_t, 3>> at;
  for (uint32_t v = 0; v < c.points.size(); ++v) {
    if (!c.on_interface[v]) continue;
    std::vector<std::array<uint32_t, 3>> expected;
    for (const auto& f : faces)
      if (std::find(f.begin(), f.end(), v) != f.end()) expected.push_back(f);
    interface_faces_at(c, adj, v, at);
    ASSERT_EQ(at, expected) << v;
  }
}

TEST(InterfaceRefinement, SplittingAtTheCollapsesIsSplittingTheWholeInterface) {
  // Collapses of short edges that may stretch others past the upper bound (as the repair
  // makes them), then the long edges split: found from the collapses' stars, or from a scan
  // of the whole interface, the complexes come out bit for bit the same.
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  const auto [lo, hi] = edge_range(c);
  TetAdjacency adj(c);
  long stretched = 0;
  std::vector<uint32_t> touched;
  const auto edges = interface_edges(c);
  const long collapses = collapse_short_interface_edges(c, adj, edges, 0.5 * (lo + hi), hi, &stretched, &touched);
  ASSERT_GT(collapses, 0);
  ASSERT_GT(stretched, 0);
  TetComplex whole = c, local = c;
  TetAdjacency whole_adj(whole), local_adj(local);
  const long whole_splits = split_long_interface_edges(whole, whole_adj, interface_faces(whole, whole_adj), hi);
  const long local_splits = split_long_interface_edges_at(local, local_adj, touched, hi);
  EXPECT_GT(whole_splits, 0);
  EXPECT_EQ(local_splits, whole_splits);
  EXPECT_EQ(local.points, whole.points);
  EXPECT_EQ(local.tets, whole.tets);
  EXPECT_EQ(local.label, whole.label);
  EXPECT_EQ(split_long_interface_edges_at(local, local_adj, {}, hi), 0);
}

TEST(InterfaceCoarsening, ShortEdgesCollapseKeepingAClosedManifoldAndPositiveTetrahedra) {
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  const auto [lo, hi] = edge_range(c);
  const double v0 = c.volume(TetComplex::kInside);
  const double min_length = 0.5 * (lo + hi);  // about half the edges are "short"
  long short_before = 0;
  for (const auto& e : interface_edges(c)) short_before += (c.points[e[0]] - c.points[e[1]]).norm() < min_length;
  const auto box_before = [&] {
    std::vector<Eigen::Vector3d> b;
    for (size_t i = 0; i < c.points.size(); ++i)
      if (c.on_box[i]) b.push_back(c.points[i]);
    return b;
  }();
  const size_t faces_before = c.interface_faces().size();
  const long collapses = collapse_short_interface_edges(c, min_length);
  EXPECT_GT(collapses, 50);
  EXPECT_EQ(c.first_inverted(), -1);
  const auto faces = c.interface_faces();
  EXPECT_TRUE(closed_manifold(faces));
  EXPECT_EQ(faces.size(), faces_before - 2 * size_t(collapses));  // each collapse removes two faces
  expect_consistent_flags(c, faces);
  long short_after = 0;
  for (const auto& e : interface_edges(c)) short_after += (c.points[e[0]] - c.points[e[1]]).norm() < min_length;
  EXPECT_LT(short_after, short_before / 4) << short_before << " short edges before";
  size_t k = 0;
  for (size_t i = 0; i < c.points.size(); ++i)
    if (c.on_box[i]) {
      EXPECT_EQ(c.points[i], box_before[k++]);
    }
  // A coarser polyhedron inscribed in the same sphere: a little less volume, not much.
  EXPECT_LT(c.volume(TetComplex::kInside), v0 * 1.0001);
  EXPECT_GT(c.volume(TetComplex::kInside), v0 * 0.95);
}

TEST(InterfaceCoarsening, AShortEdgeAmongLongOnesCollapsesIntoEdgesTheRepairSplitsAgain) {
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  const double band_max = edge_range(c).second;
  // Pull an interface vertex most of the way to a neighbour, as a log's rim does to the points
  // its splits make: a short edge whose collapse would make edges past the upper bound.
  const auto edges = interface_edges(c);
  const auto [a, b] = edges[edges.size() / 2];
  c.points[b] = c.points[a] + 0.12 * (c.points[b] - c.points[a]);
  ASSERT_EQ(c.first_inverted(), -1);
  const double short_length = (c.points[a] - c.points[b]).norm();
  const double min_length = 0.4 * band_max;
  ASSERT_LT(short_length, min_length);
  TetAdjacency adj(c);
  // The upper bound refuses it as it is (the collapse lands near a, far from b's other neighbours)...
  TetComplex probe = c;
  TetAdjacency probe_adj(probe);
  EXPECT_FALSE(collapse_interface_edge(probe, probe_adj, a, b, band_max));
  // ... and the repair collapses it all the same, then splits what came out too long.
  const size_t faces_before = c.interface_faces().size();
  const RepairStats st = growth_repair_step(c, adj, min_length, band_max);
  EXPECT_GT(st.collapses, 0);
  EXPECT_GT(st.splits, 0);
  EXPECT_EQ(c.first_inverted(), -1);
  const auto faces = c.interface_faces();
  EXPECT_TRUE(closed_manifold(faces));
  expect_consistent_flags(c, faces);
  EXPECT_TRUE(!c.on_interface[a] || !c.on_interface[b] || !adj.has_edge(c, a, b)) << "the short edge is gone";
  for (const auto& e : interface_edges(c)) EXPECT_LE((c.points[e[0]] - c.points[e[1]]).norm(), band_max);
  EXPECT_GT(faces.size(), faces_before - 8);
}

TEST(TetFlips, QualityRepairNeverTouchesTheInterfaceNorLowersTheWorstOutsideTetrahedron) {
  TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
  // Squash and split the outside: grow the interface a few steps with splits but no repair.
  const GrowthFunction g = growth_of(1.0);
  const double band_max = edge_range(c).second;
  for (int k = 0; k < 2; ++k) {
    advance_interface(c, g, 0.03 * k, 0.03 * (k + 1));
    split_long_interface_edges(c, band_max);
  }
  const auto faces = c.interface_faces();
  std::vector<Eigen::Vector3d> interface_points;
  std::vector<uint32_t> interface;
  for (uint32_t i = 0; i < c.points.size(); ++i)
    if (c.on_interface[i]) {
      interface.push_back(i);
      interface_points.push_back(c.points[i]);
    }
  auto worst_outside_near = [&] {
    const TetAdjacency adj(c);
    double q = 1e300;
    for (uint32_t v : interface)
      for (uint32_t t : adj.around(v))
        if (c.label[t] == TetComplex::kOutside) q = std::min(q, tet_quality(c, c.tets[t]));
    return q;
  };
  const double worst_before = worst_outside_near();
  const double inside_before = c.volume(TetComplex::kInside), outside_before = c.volume(TetComplex::kOutside);
  TetAdjacency adj(c);
  const FlipStats fs = improve_tets_near(c, adj, interface, 0.3, 0, 3);
  EXPECT_GT(fs.flips23 + fs.flips32, 0);
  EXPECT_EQ(c.first_inverted(), -1);
  // The same oriented triangles (flips of inside tetrahedra may report one from another corner).
  EXPECT_EQ(rotated(c.interface_faces()), rotated(faces));
  for (size_t k = 0; k < interface.size(); ++k) EXPECT_EQ(c.points[interface[k]], interface_points[k]);
  EXPECT_GE(worst_outside_near(), worst_before);
  EXPECT_NEAR(c.volume(TetComplex::kInside), inside_before, 1e-12);
  EXPECT_NEAR(c.volume(TetComplex::kOutside), outside_before, 1e-9);
  for (uint32_t p = 0; p < c.points.size(); ++p)
    for (uint32_t t : adj.around(p)) ASSERT_NE(std::find(c.tets[t].begin(), c.tets[t].end(), p), c.tets[t].end());
}

TEST(ComplexRepair, ASphereGrown16TimesStaysOnItsRadiusWithEveryStepValid) {
  const GrowthRun before = grow_sphere(false, false);
  const GrowthRun after = grow_sphere(true, true);
  std::printf("lag with splits only: %.4f m (%ld shortened, %ld clamped); with the repair: %.4f m (%ld, %ld); band max %.4f m, at most %ld short edges\n",
              before.lag, before.shortened, before.clamped, after.lag, after.shortened, after.clamped, after.band_max, after.short_edges);
  // Within one edge (the requirement), and within the aim of a quarter of one: measured
  // 0.0112 m = 0.14 of the band's upper bound. Until the motion retried its blocked moves once
  // every vertex had moved (interface_motion.cpp) it was 0.048 m, and the splits alone left
  // 0.119 m, so this test asserted the repair halved the splits' lag; with the retry the
  // splits alone leave 0.0102 m, and what the repair adds is a volume in front that blocks
  // fewer moves (48 shortened against 125).
  EXPECT_LT(after.lag, 0.25 * after.band_max) << after.short_edges << " short edges at most";
  EXPECT_LT(after.shortened + after.clamped, before.shortened + before.clamped);
  EXPECT_NEAR(after.volume_ratio, 1.0, 0.02);
}

TEST(ComplexRepair, StepsAreBitIdenticalAtOneAndTwoThreads) {
  auto run = [](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    TetComplex c = tetrahedralize_surface(icosphere(3, 0.5), TetSettings{}, "s.json", "/objects/0");
    const double band_max = edge_range(c).second;
    const GrowthFunction g = growth_of(1.0);
    for (int k = 0; k < 6; ++k) {
      advance_interface(c, g, 0.02 * k, 0.02 * (k + 1));
      growth_repair_step(c, 0.4 * band_max, band_max);
    }
    return c;
  };
  const TetComplex one = run(1), two = run(2);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.tets, two.tets);
  EXPECT_EQ(one.label, two.label);
  EXPECT_EQ(one.on_interface, two.on_interface);
}

namespace {

// How many interface edges have opposite angles summing past the flips' threshold (not
// Delaunay on the surface: one of their triangles is very obtuse there).
long obtuse_edges(const TetComplex& c, const std::vector<std::array<uint32_t, 3>>& faces) {
  std::map<std::pair<uint32_t, uint32_t>, double> sum;
  for (const auto& f : faces)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = f[size_t(e)], b = f[size_t(e + 1) % 3], p = f[size_t(e + 2) % 3];
      const Eigen::Vector3d u = c.points[a] - c.points[p], v = c.points[b] - c.points[p];
      sum[std::minmax(a, b)] += std::atan2(u.cross(v).norm(), u.dot(v));
    }
  long n = 0;
  for (const auto& [e, s] : sum) n += s > InterfaceFlipSettings{}.min_opposite_deg * M_PI / 180;
  return n;
}

}  // namespace

TEST(InterfaceFlips, ObtuseTrianglesOfAJitteredLogFlipToTheOtherDiagonalKeepingAValidComplex) {
  // A log's jittered side: many of its quads' diagonals join the obtuse corners.
  CambialGrowthSettings s;  // only for the set-up: the log welded at its seam and tetrahedralized
  s.ring_interval = 0;
  TetComplex c = CambialGrowth(log_mesh(0.15, 0.6, 48, 24, 0.4, 3), {}, s, "s.json", "/objects/0").complex();
  const auto faces_before = c.interface_faces();
  const std::vector<uint8_t> on_before = c.on_interface;
  const double v0 = c.volume(TetComplex::kInside);
  const long obtuse_before = obtuse_edges(c, faces_before);
  ASSERT_GT(obtuse_before, 20) << "the jitter should leave edges to flip";
  TetAdjacency adj(c);
  long flips = 0;
  for (int pass = 0; pass < 4; ++pass) flips += flip_interface_edges(c, adj, interface_faces(c, adj), 1.0);
  EXPECT_GT(flips, obtuse_before / 2);
  EXPECT_EQ(c.first_inverted(), -1);
  const auto faces = c.interface_faces();
  EXPECT_TRUE(closed_manifold(faces));
  EXPECT_EQ(faces.size(), faces_before.size());  // a flip trades two faces for two
  EXPECT_EQ(sorted(interface_faces(c, TetAdjacency(c))), faces);
  EXPECT_NE(rotated(faces), rotated(faces_before));
  expect_consistent_flags(c, faces);
  EXPECT_EQ(c.on_interface, on_before);  // the same points: only the edges between them change
  // Far fewer obtuse edges; the shape kept (the faces flipped are within 40° of coplanar and
  // the side is a gentle curve: the volume moves by the slivers between old and new faces).
  EXPECT_LT(obtuse_edges(c, faces), obtuse_before / 4) << obtuse_before << " before";
  EXPECT_NEAR(c.volume(TetComplex::kInside), v0, 0.002 * v0);
}

// The preview's tessellation pipeline on llvmpipe (issue 23): the evaluation shader displaces
// exactly as the C++ BarkSurface does (transform feedback), symmetric edge levels leave no
// holes while per-patch levels do (so the test can see holes), and crack-aware levels put
// the triangles near the cracks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bark/dressing/crack_bark_surface.h"
#include "preview/preview_renderer.h"
#include "preview/preview_scene.h"
#include "tests/preview/gl_context_for_tests.h"

using namespace phellem;
using namespace phellem::preview;

namespace {

// A 1 m square sheet of 20 × 20 cells, tilted so no normal is axis-aligned, with one crack
// running across it along the middle row of vertices (a gentle zigzag).
struct Sheet {
  bark::CrackedMesh mesh;
  Mat3f rotation;
  std::vector<std::pair<Vec3f, Vec3f>> crack;  // segments, for distances
};

Sheet tilted_sheet() {
  Sheet s;
  s.rotation = (Eigen::AngleAxisf(0.4f, Vec3f::UnitX()) * Eigen::AngleAxisf(-0.3f, Vec3f::UnitY())).toRotationMatrix();
  const int n = 20;
  auto& m = s.mesh.mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = -0.5f + float(i) / n, y = -0.5f + float(j) / n + (j == n / 2 ? 0.012f * float(i % 2) : 0.0f);
      const Vec3f p = s.rotation * Vec3f(x, y, 0);
      m.positions.emplace_back(p.x(), p.y(), p.z());
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  const size_t nv = m.positions.size();
  s.mesh.crack_width.assign(nv, 0.0f);
  s.mesh.component.assign(nv, -1);
  s.mesh.displacement.assign(nv, Eigen::Vector3f::Zero());
  for (int i = 2; i < n - 2; ++i) {
    const uint32_t a = uint32_t((n / 2) * (n + 1) + i);
    s.mesh.crack_edges.push_back({a, a + 1});
    s.mesh.crack_width[a] = s.mesh.crack_width[a + 1] = float(std::min(i - 1, n - 2 - i));  // widest in the middle
    s.mesh.component[a] = s.mesh.component[a + 1] = 0;
    s.crack.emplace_back(m.positions[a].cast<float>(), m.positions[a + 1].cast<float>());
  }
  return s;
}

CrackLook rough_look() {
  CrackLook l;
  l.width_per_edge = 0.0015f;
  l.min_width = 0.002f;
  l.max_width = 0.01f;
  l.max_depth = 0.012f;
  l.noise = 0.3f;
  l.shoulder = 0.4f;
  l.shoulder_width = 0.01f;
  l.detail = 0.4f;  // relief everywhere: mismatched edges would open
  l.detail_size = 0.03f;
  l.wall_noise = 0.2f;
  return l;
}

PreviewScene sheet_scene(const Sheet& s, const CrackLook& look) {
  PreviewScene scene;
  auto surface = std::make_shared<const bark::CrackBarkSurface>(s.mesh, look, 7u);
  scene.objects.push_back(stress_preview_object(s.mesh, surface));
  return scene;
}

// Looking at the sheet from its front, obliquely, close enough that it fills the frame.
CameraModel oblique_camera(const Sheet& s, int size) {
  CameraDesc c;
  const Vec3f n = s.rotation * Vec3f(0, 0, 1), side = s.rotation * Vec3f(1, 0, 0);
  c.look_at = Vec3f(0, 0, 0);
  c.position = 0.45f * n + 0.3f * side;
  c.up = s.rotation * Vec3f(0, 1, 0);
  c.fov_deg = 40;
  return CameraModel(c, size, size);
}

float distance_to_crack(const Sheet& s, const Vec3f& p) {
  float best = std::numeric_limits<float>::infinity();
  for (const auto& [a, b] : s.crack) {
    const Vec3f ab = b - a;
    const float t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

}  // namespace

TEST(PreviewTessellation, EvaluationShaderDisplacesExactlyAsTheCppBarkSurface) {
  PHELLEM_REQUIRE_GL();
  const Sheet sheet = tilted_sheet();
  const PreviewScene scene = sheet_scene(sheet, rough_look());
  PreviewRenderer renderer(scene);
  const auto fb = renderer.capture(0, oblique_camera(sheet, 256), PreviewSettings{});
  ASSERT_GT(fb.base.size(), 3000u);
  const Vec3f n = sheet.rotation * Vec3f(0, 0, 1);
  const auto& surface = *scene.objects[0].surface;
  double worst = 0;
  int in_cracks = 0;
  for (size_t k = 0; k < fb.base.size(); ++k) {
    bark::SurfacePoint p;
    p.position = fb.base[k];
    p.normal = n;
    const bark::BarkDisplacement d = surface.displace(p);
    const Vec3f expected = fb.base[k] + d.offset * n;
    const double err = (fb.displaced[k] - expected).norm() / std::max(1e-3f, expected.norm());
    worst = std::max(worst, err);
    in_cracks += d.attributes.y() > 0;
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(in_cracks, 100);  // the comparison covers the V-profiles, not just the relief
}

TEST(PreviewTessellation, SymmetricLevelsLeaveNoHolesAndPerPatchLevelsDo) {
  PHELLEM_REQUIRE_GL();
  const Sheet sheet = tilted_sheet();
  const PreviewScene scene = sheet_scene(sheet, rough_look());
  PreviewRenderer renderer(scene);
  const CameraModel camera = oblique_camera(sheet, 384);
  auto background = [&](bool asymmetric) {
    PreviewSettings s;
    s.asymmetric_levels = asymmetric;
    s.target_far_px = 12;
    const PreviewFrame f = renderer.render(camera, s);
    int n = 0;
    for (float d : f.distance) n += std::isinf(d);
    return n;
  };
  // The sheet covers the whole frame: any background pixel is a hole.
  EXPECT_EQ(background(false), 0);
  EXPECT_GT(background(true), 10);
}

TEST(PreviewTessellation, CrackAwareLevelsPutMoreTrianglesNearCracksWithinTheBudget) {
  PHELLEM_REQUIRE_GL();
  const Sheet sheet = tilted_sheet();
  CrackLook look = rough_look();
  look.detail = 0;  // only the cracks displace
  const PreviewScene scene = sheet_scene(sheet, look);
  PreviewRenderer renderer(scene);
  PreviewScene blind_scene = sheet_scene(sheet, look);  // the same patches, no vertex marked near a crack
  std::fill(blind_scene.objects[0].crack_near.begin(), blind_scene.objects[0].crack_near.end(), 0.0f);
  PreviewRenderer blind(blind_scene);
  const CameraModel camera = oblique_camera(sheet, 256);
  PreviewSettings settings;  // micro-edges of 3 px near cracks, 24 px elsewhere
  settings.target_near_px = 3;
  settings.target_far_px = 24;
  // Triangles per m² within 2 cm of the crack over those beyond.
  auto density_ratio = [&](const PreviewRenderer::Feedback& fb) {
    double area[2] = {0, 0};
    long long count[2] = {0, 0};
    for (size_t k = 0; k + 2 < fb.base.size(); k += 3) {
      const Vec3f c = (fb.base[k] + fb.base[k + 1] + fb.base[k + 2]) / 3;
      const int near = distance_to_crack(sheet, c) < 0.02f ? 1 : 0;
      area[near] += 0.5 * (fb.base[k + 1] - fb.base[k]).cross(fb.base[k + 2] - fb.base[k]).norm();
      ++count[near];
    }
    EXPECT_GT(count[0], 0);
    EXPECT_GT(count[1], 0);
    return (count[1] / area[1]) / (count[0] / area[0]);
  };
  const auto fb = renderer.capture(0, camera, settings);
  const double aware = density_ratio(fb), crack_blind = density_ratio(blind.capture(0, camera, settings));
  EXPECT_GT(aware, 4.0);
  EXPECT_GT(aware, 2.0 * crack_blind) << aware << " vs " << crack_blind << " without crack-aware levels";
  // The budget: at the default levels, at most 4 triangles a pixel of the frame.
  const long long triangles = (long long)(fb.base.size() / 3);
  EXPECT_LE(triangles, 4LL * 256 * 256);
  EXPECT_EQ(renderer.render(camera, settings).primitives, triangles);  // the primitive query counts the same
}

TEST(PreviewOverlay, TheStatusLineIsDrawnInTheTopLeftCorner) {
  PHELLEM_REQUIRE_GL();
  const Sheet sheet = tilted_sheet();
  const PreviewScene scene = sheet_scene(sheet, rough_look());
  PreviewRenderer renderer(scene);
  const CameraModel camera = oblique_camera(sheet, 360);
  PreviewSettings s;
  const PreviewFrame plain = renderer.render(camera, s);
  s.overlay = "72.7 ms | 0.07M triangles";
  const PreviewFrame text = renderer.render(camera, s);
  // Glyph pixels (light yellow) appear inside the text's box, top-left, and nowhere else.
  int lit = 0, outside = 0;
  for (int y = 0; y < 360; ++y)
    for (int x = 0; x < 360; ++x) {
      const size_t p = 4 * (size_t(y) * 360 + size_t(x));
      const bool changed = text.rgba[p] != plain.rgba[p] || text.rgba[p + 2] != plain.rgba[p + 2];
      const bool glyph = text.rgba[p] == 255 && text.rgba[p + 1] == 255 && text.rgba[p + 2] < 230;
      const bool in_box = y >= 3 && y < 12 && x >= 3 && x < 4 + 26 * 6 + 2;
      lit += glyph && in_box;
      outside += changed && !in_box;
    }
  EXPECT_GT(lit, 100);
  EXPECT_EQ(outside, 0);
  // The AOVs under the text say "nothing hit", not the bark.
  EXPECT_TRUE(std::isinf(text.distance[size_t(6) * 360 + 10]));
}

TEST(PreviewTints, TheFragmentStageTintsPlatesAndCracksAsTheCppShade) {
  PHELLEM_REQUIRE_GL();
  const Sheet sheet = tilted_sheet();
  CrackLook look = rough_look();
  look.detail = 0;
  look.shoulder = 0;
  look.darkening = 0;
  look.ridge_tints = {Eigen::Vector3f(0.5f, 0.6f, 0.7f), Eigen::Vector3f(0.9f, 0.8f, 0.6f), Eigen::Vector3f(0.7f, 0.9f, 0.8f)};
  look.fissure_tints = {Eigen::Vector3f(0.6f, 0.5f, 0.5f), Eigen::Vector3f(0.9f, 0.9f, 0.7f)};
  look.tint_size = 0.05f;
  PreviewScene scene = sheet_scene(sheet, look);
  scene.objects[0].base_color = Vec3f(1, 1, 1);
  scene.sun_color = Vec3f::Zero();  // lit by a white ambient only: the colour is the albedo
  scene.sky_color = scene.ground_color = Vec3f::Ones();
  PreviewRenderer renderer(scene);
  const CameraModel camera = oblique_camera(sheet, 200);
  PreviewSettings s;
  s.target_near_px = 1.5f;
  const PreviewFrame f = renderer.render(camera, s);
  const auto& surface = *scene.objects[0].surface;
  auto srgb = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return 255.0f * (c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1 / 2.4f) - 0.055f);
  };
  int close = 0, compared = 0, distinct_tints = 0;
  float previous = -1;
  for (int y = 0; y < 200; y += 3)
    for (int x = 0; x < 200; x += 3) {
      const size_t p = size_t(y) * 200 + size_t(x);
      if (!std::isfinite(f.distance[p]) || f.mask[p] > 0) continue;  // plates only: away from cracks
      const Vec3f d = camera.direction(Vec2f(float(x) + 0.5f, float(y) + 0.5f)).normalized();
      bark::SurfacePoint sp;
      sp.position = camera.position() + f.distance[p] * d;  // on the undisplaced sheet (no relief)
      sp.normal = sheet.rotation * Vec3f(0, 0, 1);
      const bark::BarkShade sh = surface.shade(surface.displace(sp).attributes, sp.position);
      ++compared;
      bool ok = true;
      for (int c = 0; c < 3; ++c) ok = ok && std::abs(float(f.rgba[4 * p + size_t(c)]) - srgb(sh.tint[c])) <= 3.0f;
      close += ok;
      if (sh.tint.x() != previous) ++distinct_tints;
      previous = sh.tint.x();
    }
  ASSERT_GT(compared, 2000);
  EXPECT_GT(distinct_tints, 50);  // many plates in view
  EXPECT_GT(close, compared * 97 / 100) << close << " of " << compared;
}

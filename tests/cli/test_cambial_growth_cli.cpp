// Cambial growth from the command line: the scene's `"growth"` block is validated at its JSON
// paths (exit 2), `simulate` writes the grown surface, its rings and stats with the growth
// counts, the result is the same at 1 and 2 threads, and `slice` draws the rings.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

// A small closed log growing; `growth` and `extra` spliced in.
std::string log_scene(const std::string& growth, const std::string& shape = "log", const std::string& extra = "") {
  return R"({"objects": [{"type": "mesh", "name": "trunk", "procedural": {"shape": ")" + shape +
         R"(", "triangles": 600, "radius": 0.1, "height": 0.3}, "growth": )" + growth + "}" + extra + "]}";
}

struct Case {
  std::string growth, shape, extra, where, says;
};

TEST(CambialGrowthCli, BadGrowthBlocksAreRefusedAtTheirJsonPath) {
  const std::string dir = test::temp_dir("cambial_growth_bad");
  const std::string scene = dir + "/scene.json";
  const std::vector<Case> cases = {
      {R"({"age_scale": -1})", "log", "", "/objects/0/growth/age_scale", "age_scale must lie in (0, 1e6]"},
      {R"({"steps": 0})", "log", "", "/objects/0/growth/steps", "[1, 100000]"},
      {R"({"eccentricity": 1})", "log", "", "/objects/0/growth/eccentricity", "[-0.99, 0.99]"},
      {R"({"thickness": NaN})", "log", "", "", ""},  // not JSON: a syntax error (checked below)
      {R"({"obstacles": ["fence"]})", "log", "", "/objects/0/growth/obstacles/0", "no object named \"fence\""},
      {R"({"obstacles": ["trunk"]})", "log", "", "/objects/0/growth/obstacles/0", "its own obstacle"},
      {R"({"obstacles": ["p"]})", "log", R"(, {"type": "plane", "name": "p"})", "/objects/0/growth/obstacles/0",
       "must be a mesh or sphere object"},
      {R"({"edge_length": [0.01, 0.015]})", "log", "", "/objects/0/growth/edge_length", "2 min < max"},
      {R"({"tetrahedra": {"quality": 1.0}})", "log", "", "/objects/0/growth/tetrahedra/quality", "[1.1, 10]"},
      {R"({"speed": 2})", "log", "", "/objects/0/growth/speed", ""},
      {R"({"speed_map": {"file": "nope.png"}})", "log", "", "/objects/0/growth/speed_map/file", "nope.png"},
      {R"({"speed_map": {"file": "nope.png", "scale": -1}})", "log", "", "/objects/0/growth/speed_map/file", ""},
      {R"({"steps": 2})", "trunk", "", "/objects/0/growth", "must be closed"},
      {R"({"crack_iterations": -1})", "log", "", "/objects/0/growth/crack_iterations", ""},
      {R"({"stretch_stress": -1})", "log", "", "/objects/0/growth/stretch_stress", "stretch_stress must lie in [0, 1e6]"},
      {R"({"strokes": [{"point": [0, 0, 0], "direction": [0, 0, 0]}]})", "log", "", "/objects/0/growth/strokes/0/direction",
       "direction must be a non-zero vector"},
      {R"({"speed_map": {"attribute": "COLOR_0"}})", "log", "", "/objects/0/growth/speed_map/attribute", "procedural mesh has none"},
      {R"({"texture_cells": 1})", "log", "", "/objects/0/growth/texture_cells", ""},
      {R"({"tetrahedra": {"remesh_blocked": 1.5}})", "log", "", "/objects/0/growth/tetrahedra/remesh_blocked", "[0, 1]"},
      {R"({"tetrahedra": {"upkeep_reach": -0.5}})", "log", "", "/objects/0/growth/tetrahedra/upkeep_reach", "[0, 4]"},
      {R"({"tetrahedra": {"time_limit": 0}})", "log", "", "/objects/0/growth/tetrahedra/time_limit", "[1, 86400]"},
      {R"({"steps": 2, "obstacles": ["s"]})", "log", R"(, {"type": "sphere", "name": "s", "center": [0.1, 0.15, 0], "radius": 0.05})",
       "/objects/0/growth/obstacles/0", "intersects"},
  };
  for (const Case& c : cases) {
    if (c.where.empty()) continue;
    test::write_text(scene, log_scene(c.growth, c.shape, c.extra));
    const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out --quiet", 8192, 120);
    EXPECT_EQ(r.exit_code, 2) << c.growth << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": " + c.where + ": ", 0), 0u) << c.growth << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.growth << "\n" << r.output;
  }
}

// 8-bit RGB pixels as floats in [0, 1], row 0 at the top.
std::vector<float> read_rgb(const std::string& path, int& width) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  width = in->spec().width;
  std::vector<float> px(size_t(in->spec().width) * size_t(in->spec().height) * 3);
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

TEST(CambialGrowthCli, AGrowthTooLargeForTheMemoryIsRefusedBeforeTetGenRuns) {
  // 100 m of thickening on a 0.1 m log at its own edge length: about 10^6 times its area.
  const std::string dir = test::temp_dir("cambial_growth_memory");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, log_scene(R"({"thickness": 100, "steps": 10})"));
  for (const std::string& command : {"simulate " + scene + " -o " + dir + "/out", "slice " + scene + " -o " + dir + "/s.png"}) {
    const auto r = test::run_phellem_limited(command + " --quiet", 8192, 60);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/growth/edge_length: needs about ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("raise the growth's edge_length band"), std::string::npos) << r.output;
  }
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  return nlohmann::json::parse(f);
}

TEST(CambialGrowthCli, SimulateWritesTheGrownSurfaceRingsAndStatsTheSameAtAnyThreadCount) {
  const std::string dir = test::temp_dir("cambial_growth_sim");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, log_scene(R"({"steps": 8, "years": 10, "age_scale": 10, "weibull_c": 1, "thickness": 0.03, "ring_interval": 4})"));
  std::string glb[2];
  for (int threads : {1, 2}) {
    const std::string out = dir + "/out" + std::to_string(threads);
    const auto r = test::run_phellem_limited("simulate " + scene + " -o " + out + " --stats " + out + "_stats.json --quiet --threads " +
                                                 std::to_string(threads),
                                             8192, 300);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json stats = read_json(out + "_stats.json");
    EXPECT_EQ(stats["growth"]["steps"], 8);
    EXPECT_GT(stats["growth"]["vertices_start"].get<long>(), 100);
    // The surface grew (0.03 × (1 − e^−1) = 19 mm on a 0.1 m radius): its edges were split.
    EXPECT_GT(stats["growth"]["vertices_end"].get<long>(), stats["growth"]["vertices_start"].get<long>());
    EXPECT_GT(stats["time_s"]["growth"].get<double>(), 0.0);
    // Where the steps' time went: each part spent some, together not more than the whole.
    double parts = 0;
    for (const char* part : {"growth_motion", "growth_contact", "growth_repair", "growth_remesh"}) {
      ASSERT_TRUE(stats["time_s"].contains(part)) << part;
      if (std::string(part) != "growth_remesh") {
        EXPECT_GT(stats["time_s"][part].get<double>(), 0.0) << part;
      }
      parts += stats["time_s"][part].get<double>();
    }
    EXPECT_LE(parts, stats["time_s"]["growth"].get<double>());
    const nlohmann::json summary = read_json(out + "/trunk.json");
    EXPECT_EQ(summary["rings"], 3);  // steps 0, 4 and 8
    glb[threads - 1] = test::read_text(out + "/trunk.glb");
    EXPECT_GT(test::read_text(out + "/trunk_rings.glb").size(), 1000u);
  }
  EXPECT_GT(glb[0].size(), 1000u);
  EXPECT_TRUE(glb[0] == glb[1]) << "the grown surface differs between 1 and 2 threads";
}

TEST(CambialGrowthCli, CracksOpenAsTheSurfaceGrowsTheSameAtAnyThreadCount) {
  // Stress bark on a growing log: the cracks are carried from step to step (thesis sec. 5).
  const std::string dir = test::temp_dir("cambial_growth_cracks");
  const std::string scene = dir + "/scene.json";
  const std::string bark = R"(, "bark": {"model": "stress", "pattern": "horizontal", "threshold": 0.6, "cracks_per_iteration": 4})";
  std::string text = log_scene(R"({"steps": 6, "years": 10, "age_scale": 10, "weibull_c": 1, "thickness": 0.05, "crack_iterations": 2})");
  text.insert(text.find(R"(, "growth")"), bark);
  test::write_text(scene, text);
  std::string glb[2];
  for (int threads : {1, 2}) {
    const std::string out = dir + "/out" + std::to_string(threads);
    const auto r = test::run_phellem_limited("simulate " + scene + " -o " + out + " --quiet --threads " + std::to_string(threads), 8192, 300);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json summary = read_json(out + "/trunk.json");
    EXPECT_GT(summary["crack_length_m"].get<double>(), 0.05);
    EXPECT_GT(summary["time_s"]["crack"].get<double>(), 0.0);
    glb[threads - 1] = test::read_text(out + "/trunk.glb");
  }
  EXPECT_GT(glb[0].size(), 1000u);
  EXPECT_TRUE(glb[0] == glb[1]) << "the cracked grown surface differs between 1 and 2 threads";
}

TEST(CambialGrowthCli, SliceDrawsTheRingsAndRefusesAPlaneThatMissesTheWood) {
  const std::string dir = test::temp_dir("cambial_growth_slice");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, log_scene(R"({"steps": 4, "years": 10, "age_scale": 10, "weibull_c": 1, "thickness": 0.03, "ring_interval": 2})"));
  const auto miss = test::run_phellem_limited("slice " + scene + " -o " + dir + "/s.png --plane y=5 --quiet", 8192, 120);
  EXPECT_EQ(miss.exit_code, 2) << miss.output;
  EXPECT_EQ(miss.output.rfind("phellem: error: <command line>: --plane: ", 0), 0u) << miss.output;
  const auto bad = test::run_phellem_limited("slice " + scene + " -o " + dir + "/s.png --plane w=5", 8192, 120);
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  const auto r = test::run_phellem_limited("slice " + scene + " -o " + dir + "/s.png --plane y=0.15 --res 200x200 --quiet", 8192, 120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int width = 0;
  const std::vector<float> px = read_rgb(dir + "/s.png", width);
  ASSERT_EQ(width, 200);
  ASSERT_EQ(px.size(), size_t(200 * 200 * 3));
  // The centre is wood (brown: red above blue), the corner background (grey).
  const float* centre = &px[size_t(3 * (100 * 200 + 100))];
  const float* corner = &px[0];
  EXPECT_GT(centre[0], centre[2] + 0.15f);
  EXPECT_NEAR(corner[0], corner[2], 0.05f);
}

// An octahedron as an OBJ file: `flip` winds every face the wrong way; `fold` pulls its top
// vertex through the middle and out beside the bottom one, so the faces around it cross the
// bottom ones (a closed, consistently wound "bow-tie").
std::string octahedron_obj(bool flip, bool fold) {
  std::string obj = "v 0.1 0 0\nv -0.1 0 0\nv " + std::string(fold ? "0.2 -0.05 0.2" : "0 0.1 0") +
                    "\nv 0 -0.1 0\nv 0 0 0.1\nv 0 0 -0.1\n";
  const int faces[8][3] = {{1, 3, 5}, {5, 3, 2}, {2, 3, 6}, {6, 3, 1}, {1, 5, 4}, {5, 2, 4}, {2, 6, 4}, {6, 1, 4}};
  for (const auto& f : faces)
    obj += "f " + std::to_string(f[0]) + " " + std::to_string(flip ? f[2] : f[1]) + " " + std::to_string(flip ? f[1] : f[2]) + "\n";
  return obj;
}

TEST(CambialGrowthCli, InsideOutAndSelfIntersectingMeshesAreRefusedBeforeTetGen) {
  const std::string dir = test::temp_dir("cambial_growth_hostile_mesh");
  const std::string scene = dir + "/scene.json";
  // The limit keeps TetGen from looping for its default 120 s on the folded mesh (the old code's fate).
  test::write_text(scene, R"({"objects": [{"type": "mesh", "name": "gem", "file": "gem.obj",
                                          "growth": {"steps": 2, "thickness": 0.01, "tetrahedra": {"time_limit": 5}}}]})");
  struct MeshCase {
    bool flip, fold;
    std::string says;
  };
  for (const MeshCase& c : {MeshCase{true, false, "the mesh is inside out (faces wound clockwise seen from outside)"},
                            MeshCase{false, true, "the surface to grow intersects itself: faces "}}) {
    test::write_text(dir + "/gem.obj", octahedron_obj(c.flip, c.fold));
    const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 60);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/growth: " + c.says, 0), 0u) << r.output;
  }
  // The same octahedron wound outwards grows.
  test::write_text(dir + "/gem.obj", octahedron_obj(false, false));
  const auto ok = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 120);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(CambialGrowthCli, ATorusKnotGrowsWhenItsTubeClearsItsOtherStrands) {
  const std::string dir = test::temp_dir("cambial_growth_knot");
  const std::string scene = dir + "/scene.json";
  const std::string growth = R"({"steps": 3, "thickness": 0.004, "ring_interval": 0})";
  // The default tube (0.06 m on a 0.15 m knot) passes through the strand it crosses: the
  // refusal says so at the tube, instead of TetGen failing on it.
  test::write_text(scene, R"({"objects": [{"type": "mesh", "name": "knot", "procedural": {"shape": "torus_knot", "triangles": 3000},
                                          "growth": )" + growth + "}]}");
  const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 120);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/procedural/tube: a growing torus knot must not intersect itself", 0), 0u)
      << r.output;
  EXPECT_NE(r.output.find("must be thinner than 0.0416 m"), std::string::npos) << r.output;
  // A thinner tube is a closed surface without self-intersections: it grows.
  test::write_text(scene, R"({"objects": [{"type": "mesh", "name": "knot", "procedural": {"shape": "torus_knot", "triangles": 3000,
                                          "tube": 0.03}, "growth": )" + growth + "}]}");
  const auto ok = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 300);
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  const nlohmann::json stats = nlohmann::json::parse(test::read_text(dir + "/out/knot.json"));
  EXPECT_EQ(stats["steps"], 3);
  EXPECT_GT(stats["vertices_end"].get<double>(), 0);
}

}  // namespace
}  // namespace phellem

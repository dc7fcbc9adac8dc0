// `phellem simulate` with the stress model on mesh objects: the CrackedMesh .glb (read back,
// custom attributes, crack edges), the JSON summary and --stats keys, determinism, and the
// documented errors (bad parameters at their JSON path, malformed meshes named, exit code 2,
// earlier outputs untouched).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/cracked_mesh_io.h"
#include "io/mesh_io.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string scene_with(const std::string& object) { return R"({"render": {"seed": 4}, "objects": [)" + object + "]}"; }

const char* kTrunk =
    R"({"type": "mesh", "name": "trunk", "procedural": {"shape": "trunk", "triangles": 3000, "radius": 0.1, "height": 0.6},
    "bark": {"model": "stress", "preset": "pine", "iterations": 25})";

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  return nlohmann::json::parse(f);
}

}  // namespace

TEST(SimulateStressCli, WritesACrackedMeshThatReadsBackAndASummary) {
  const std::string dir = test::temp_dir("stress_ok");
  test::write_text(dir + "/scene.json", scene_with(std::string(kTrunk) + "}"));
  const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet --stats " + dir + "/stats.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const bark::CrackedMesh c = read_cracked_glb(dir + "/out/trunk.glb");
  ASSERT_FALSE(c.crack_edges.empty());
  EXPECT_EQ(c.crack_width.size(), c.mesh.positions.size());
  EXPECT_EQ(c.mesh.uvs.size(), c.mesh.positions.size());
  // Crack vertices have a component and ends of width 0; others have neither.
  int ends = 0;
  for (const auto& e : c.crack_edges)
    for (uint32_t v : e) {
      EXPECT_GE(c.component[v], 0);
      ends += c.crack_width[v] == 0;
    }
  EXPECT_GT(ends, 0);
  for (size_t k = 0; k < c.component.size(); ++k) {
    if (c.component[k] < 0) {
      EXPECT_EQ(c.crack_width[k], 0.0f);
    }
  }
  // The renderer's loader takes the file as an ordinary mesh (the lines are skipped).
  const LoadedModel m = load_mesh_file(dir + "/out/trunk.glb");
  ASSERT_EQ(m.meshes.size(), 1u);
  EXPECT_EQ(m.meshes[0].triangle_count(), c.mesh.triangles.size());
  const nlohmann::json s = read_json(dir + "/out/trunk.json");
  EXPECT_EQ(s["model"], "stress");
  EXPECT_EQ(s["crack_edges"].get<size_t>(), c.crack_edges.size());
  EXPECT_EQ(s["triangles_out"].get<size_t>(), c.mesh.triangles.size());
  EXPECT_EQ(s["iterations"], 25);
  const nlohmann::json st = read_json(dir + "/stats.json");
  for (const char* key : {"model", "triangles_in", "triangles_out", "iterations", "cracks", "crack_edges"})
    EXPECT_TRUE(st.contains(key)) << key;
  EXPECT_TRUE(st["time_s"].contains("preprocess"));
  EXPECT_TRUE(st["time_s"].contains("simulate"));
  EXPECT_GT(st["triangles_out"].get<long>(), st["triangles_in"].get<long>());
}

TEST(SimulateStressCli, SameFileOnOneAndTwoThreads) {
  const std::string dir = test::temp_dir("stress_det");
  test::write_text(dir + "/scene.json", scene_with(std::string(kTrunk) + "}"));
  for (int t : {1, 2}) {
    const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out" + std::to_string(t) +
                                     " --quiet --threads " + std::to_string(t));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  auto bytes = [](const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  const std::string a = bytes(dir + "/out1/trunk.glb"), b = bytes(dir + "/out2/trunk.glb");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b);
}

TEST(SimulateStressCli, BadSettingsAndMeshesAreRefusedAndOutputsKept) {
  const std::string dir = test::temp_dir("stress_bad");
  // A good run first: its outputs must survive the failed runs below.
  test::write_text(dir + "/scene.json", scene_with(std::string(kTrunk) + "}"));
  ASSERT_EQ(test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet").exit_code, 0);
  const auto before = std::filesystem::last_write_time(dir + "/out/trunk.glb");
  struct Case {
    std::string bark, expect;
  };
  const Case cases[] = {
      {R"({"model": "stress", "alpha": 2})", "/objects/0/bark/alpha"},
      {R"({"model": "stress", "time_step": 0.9})", "unstable"},
      {R"({"model": "stress", "pattern": "zigzag"})", "allowed: uniform, horizontal"},
      {R"({"model": "stress", "preset": "oak"})", "allowed: birch, pine, palm"},
      {R"({"model": "strips"})", "needs a tree object"},
      {R"({"model": "stress", "strokes": [{"uv": [[0.1, 0.1]]}]})", "at least 2 points"},
      {R"({"model": "stress", "cracks_per_iteration": -3})", "cracks_per_iteration"},
  };
  for (const Case& c : cases) {
    test::write_text(
        dir + "/scene.json",
        scene_with(R"({"type": "mesh", "name": "trunk", "procedural": {"shape": "trunk", "triangles": 500}, "bark": )" + c.bark +
                   "}"));
    const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet");
    EXPECT_EQ(r.exit_code, 2) << c.bark;
    EXPECT_NE(r.output.find("phellem: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.bark << "\n" << r.output;
  }
  // A non-manifold mesh file: three triangles on one edge, named in the error.
  const std::string obj = dir + "/fin.obj";
  test::write_text(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  test::write_text(dir + "/scene.json",
                   scene_with(R"({"type": "mesh", "name": "trunk", "file": "fin.obj", "bark": {"model": "stress"}})"));
  const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("fin.obj: triangle 2: makes the mesh non-manifold"), std::string::npos) << r.output;
  EXPECT_EQ(std::filesystem::last_write_time(dir + "/out/trunk.glb"), before);
}

}  // namespace phellem

namespace phellem {

TEST(SimulateStressCli, TreeObjectsAreTessellatedAndCracked) {
  // A trunk and a branch: one welded mesh per part, cracked together; UVs come along.
  const std::string dir = test::temp_dir("stress_tree");
  test::write_text(dir + "/scene.json", R"({"render": {"seed": 2}, "objects": [{"type": "tree", "name": "t",
      "axis": [[0, 0, 0], [0, 0.5, 0]], "radius": [0.06, 0.05],
      "branches": [{"attach": 0.6, "length": 0.2, "radius": [0.025, 0.02]}],
      "bark": {"model": "stress", "preset": "pine", "iterations": 20, "preprocess": {"edge_length": 0.01}}}]})");
  const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const bark::CrackedMesh c = read_cracked_glb(dir + "/out/t.glb");
  EXPECT_FALSE(c.crack_edges.empty());
  EXPECT_EQ(c.mesh.uvs.size(), c.mesh.positions.size());
  // Both parts are there: vertices on the trunk (|x|, |z| ≤ 0.06) and out on the branch.
  double far = 0;
  for (const auto& p : c.mesh.positions) far = std::max(far, std::hypot(p.x(), p.z()));
  EXPECT_GT(far, 0.1);
}

}  // namespace phellem

namespace phellem {

TEST(SimulateStressCli, AnEdgeLengthThatWouldExplodeTheMeshIsRefused) {
  const std::string dir = test::temp_dir("stress_edge");
  test::write_text(dir + "/scene.json",
                   scene_with(R"({"type": "mesh", "name": "m", "procedural": {"shape": "trunk", "triangles": 500},
      "bark": {"model": "stress", "preprocess": {"edge_length": 0.00001}}})"));
  const auto r = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("/objects/0/bark/preprocess/edge_length"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("at most 20000000"), std::string::npos) << r.output;
  test::write_text(dir + "/scene.json", R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 1, 0]], "radius": 0.1,
      "bark": {"model": "stress", "preprocess": {"edge_length": 0.00001}}}]})");
  const auto t = test::run_phellem("simulate " + dir + "/scene.json -o " + dir + "/out --quiet");
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_NE(t.output.find("/objects/0/bark/preprocess/edge_length"), std::string::npos) << t.output;
}

}  // namespace phellem

// Output paths: every command checks all its outputs before any work (folder exists, not a
// folder where a file goes, no two outputs the same file), and a run's outputs are committed
// together at its end, so a failed run leaves earlier outputs untouched.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

const char* kSphere = R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
                          "lights": [{"type": "environment", "color": [1, 1, 1]}]})";

// A small strip-bark tree (a trunk and a branch), quick to simulate and to grow.
const char* kStripTree =
    R"({"render": {"seed": 3}, "camera": {"position": [0, 0.15, 0.6], "look_at": [0, 0.15, 0], "fov_deg": 30},
    "lights": [{"type": "environment", "color": [1, 1, 1]}],
    "objects": [{"type": "tree", "name": "t", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05, 0.04],
                 "bark": {"model": "strips", "preset": "fissured", "steps": 60, "growth_rate": 1.01, "strip_width": 0.01}})";

struct Refusal {
  std::string args;    // after "render SCENE"
  std::string expect;  // in the error message
};

void expect_refused(const std::string& command, const Refusal& c) {
  const auto r = test::run_phellem(command + " " + c.args);
  EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + c.expect), std::string::npos) << c.args << "\n" << r.output;
}

}  // namespace

TEST(OutputPathsCli, RenderChecksEveryOutputBeforeAnyWork) {
  const std::string d = test::temp_dir("outputs_render");
  test::write_text(d + "/scene.json", kSphere);
  test::write_text(d + "/a.exr", "old exr");
  test::write_text(d + "/file.txt", "a file, not a folder");
  fs::create_directories(d + "/sub");
  const std::string render = "render " + d + "/scene.json --res 16x16 --spp 1";
  const std::vector<Refusal> cases = {
      {"-o " + d + "/a.exr --png " + d + "/nofolder/x.png", d + "/nofolder/x.png: --png: folder does not exist"},
      {"-o " + d + "/a.exr --stats " + d + "/nofolder/s.json", d + "/nofolder/s.json: --stats: folder does not exist"},
      {"-o " + d + "/nofolder/b.exr", d + "/nofolder/b.exr: -o: folder does not exist"},
      {"-o " + d + "/a.exr --png " + d + "/file.txt/x.png", d + "/file.txt/x.png: --png: " + d + "/file.txt is not a folder"},
      {"-o " + d + "/a.exr --stats " + d + "/sub", d + "/sub: --stats: is a folder, not a file"},
      {"--png " + d + "/file.txt/x.png", d + "/file.txt/x.png: --png: "},
      {"-o " + d + "/a.exr --stats " + d + "/a.exr", d + "/a.exr: --stats: the same file as -o"},
      {"-o " + d + "/a.exr --png " + d + "/a.png --stats " + d + "/a.png", d + "/a.png: --stats: the same file as --png"},
      {"-o " + d + "/a.exr --stats " + d + "/sub/../a.exr", d + "/sub/../a.exr: --stats: the same file as -o"},
  };
  for (const Refusal& c : cases) {
    expect_refused(render, c);
    EXPECT_EQ(test::read_text(d + "/a.exr"), "old exr") << c.args;
    EXPECT_FALSE(fs::exists(d + "/a.png")) << c.args;
    EXPECT_FALSE(fs::exists(d + "/nofolder")) << c.args;
    EXPECT_TRUE(test::leftover_temporaries(d).empty()) << c.args;
  }
  // And a good run replaces all of them.
  const auto r = test::run_phellem(render + " -o " + d + "/a.exr --png " + d + "/a.png --stats " + d + "/s.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(test::read_text(d + "/a.exr"), "old exr");
  EXPECT_TRUE(fs::exists(d + "/a.png"));
  EXPECT_EQ(nlohmann::json::parse(test::read_text(d + "/s.json"))["spp"], 1);
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

TEST(OutputPathsCli, SimulateChecksItsOutputsBeforeAnyWork) {
  const std::string d = test::temp_dir("outputs_simulate");
  test::write_text(d + "/scene.json", kStripTree);
  test::write_text(d + "/file.txt", "a file, not a folder");
  const std::string simulate = "simulate " + d + "/scene.json --res 16x24 --no-mesh";
  const std::vector<Refusal> cases = {
      {"-o " + d + "/out --stats " + d + "/nofolder/s.json", d + "/nofolder/s.json: --stats: folder does not exist"},
      {"-o " + d + "/out --stats " + d + "/file.txt/s.json", d + "/file.txt/s.json: --stats: " + d + "/file.txt is not a folder"},
      {"-o " + d + "/file.txt", d + "/file.txt: -o: is a file, not a folder"},
      {"-o " + d + "/nofolder/out", d + "/nofolder/out: -o: parent folder does not exist"},
      {"-o " + d + "/out --stats " + d, d + ": --stats: is a folder, not a file"},
  };
  for (const Refusal& c : cases) {
    expect_refused(simulate, c);
    EXPECT_FALSE(fs::exists(d + "/out")) << c.args;
    EXPECT_FALSE(fs::exists(d + "/nofolder")) << c.args;
    EXPECT_TRUE(test::leftover_temporaries(d).empty()) << c.args;
  }
}

TEST(OutputPathsCli, ASimulationThatFailsHalfwayKeepsTheEarlierOutputs) {
  // The strip tree is simulated and written first; the stress mesh after it is non-manifold
  // and fails the run: the tree's new field must not replace the earlier one.
  const std::string d = test::temp_dir("outputs_halfway");
  const std::string tree = R"({"type": "tree", "name": "t", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05, 0.04],
      "bark": {"model": "strips", "preset": "fissured", "steps": 60, "growth_rate": 1.01, "strip_width": 0.01}})";
  test::write_text(d + "/scene.json", R"({"objects": [)" + tree + "]}");
  const std::string simulate = "simulate " + d + "/scene.json -o " + d + "/out --res 16x24 --stats " + d + "/stats.json";
  ASSERT_EQ(test::run_phellem(simulate + " --seed 1").exit_code, 0);
  const std::string field = test::read_text(d + "/out/t_trunk.exr"), mesh = test::read_text(d + "/out/t_trunk.glb"),
                    stats = test::read_text(d + "/stats.json");
  ASSERT_FALSE(field.empty());
  test::write_text(d + "/fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
  test::write_text(
      d + "/scene.json",
      R"({"objects": [)" + tree + R"(, {"type": "mesh", "name": "fin", "file": "fin.obj", "bark": {"model": "stress"}}]})");
  const auto r = test::run_phellem(simulate + " --seed 2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("non-manifold"), std::string::npos) << r.output;
  EXPECT_EQ(test::read_text(d + "/out/t_trunk.exr"), field);
  EXPECT_EQ(test::read_text(d + "/out/t_trunk.glb"), mesh);
  EXPECT_EQ(test::read_text(d + "/stats.json"), stats);
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

TEST(OutputPathsCli, FrameSequencesCheckTheirOutputsBeforeAnyWork) {
  const std::string d = test::temp_dir("outputs_frames");
  test::write_text(d + "/sphere.json", kSphere);
  test::write_text(d + "/tree.json", kStripTree);
  test::write_text(d + "/file.txt", "a file, not a folder");
  fs::create_directories(d + "/f_01.exr");
  const std::vector<std::pair<std::string, Refusal>> cases = {
      {"turntable " + d + "/sphere.json",
       {"-o " + d + "/nofolder/f_%02d.exr", d + "/nofolder/f_00.exr: -o: folder does not exist"}},
      {"turntable " + d + "/sphere.json",
       {"-o " + d + "/file.txt/f_%02d.exr --png", d + "/file.txt/f_00.exr: -o: " + d + "/file.txt is not a folder"}},
      {"turntable " + d + "/sphere.json", {"-o " + d + "/f_%02d.exr", d + "/f_01.exr: -o: is a folder, not a file"}},
      {"growth " + d + "/tree.json", {"-o " + d + "/nofolder/f_%02d.exr", d + "/nofolder/f_00.exr: -o: folder does not exist"}},
  };
  for (const auto& [command, c] : cases) {
    expect_refused(command + " --frames 2 --res 16x16 --spp 1", c);
    EXPECT_FALSE(fs::exists(d + "/nofolder")) << c.args;
    EXPECT_FALSE(fs::exists(d + "/f_00.exr")) << c.args;
    EXPECT_TRUE(test::leftover_temporaries(d).empty()) << c.args;
  }
}

TEST(OutputPathsCli, FrameSequencesCommitEveryFrameTogether) {
  const std::string d = test::temp_dir("outputs_frames_ok");
  test::write_text(d + "/sphere.json", kSphere);
  const auto r =
      test::run_phellem("turntable " + d + "/sphere.json --frames 3 --res 16x16 --spp 1 --png -o " + d + "/f_%02d.exr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"f_00.exr", "f_01.exr", "f_02.exr", "f_00.png", "f_01.png", "f_02.png"})
    EXPECT_TRUE(fs::is_regular_file(d + "/" + f)) << f;
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

}  // namespace phellem

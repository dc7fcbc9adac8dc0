// Every documented scene error: exit code 2 and a message naming the file and JSON path.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scene/scene_parser.h"
#include "tests/support/scene_errors.h"
#include "tests/support/test_util.h"
#include "util/errors.h"

namespace phellem {
namespace {

using test::error_of;

TEST(SceneErrors, UnknownKeyNamesItsPath) {
  const auto msg = error_of(R"({"objects": [{"type": "sphere", "radius": 1, "radiuss": 2}]})");
  EXPECT_NE(msg.find("scene.json: /objects/0/radiuss: unknown key"), std::string::npos) << msg;
  const auto top = error_of(R"({"camra": {}})");
  EXPECT_NE(top.find("/camra: unknown key"), std::string::npos) << top;
}

TEST(SceneErrors, WrongTypes) {
  EXPECT_NE(error_of(R"({"render": {"spp": "many"}})").find("/render/spp: must be an integer in [1, 1048576], found string"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"position": [1, 2]}})").find("/camera/position: expected 3 numbers"), std::string::npos);
  EXPECT_NE(error_of(R"({"objects": {}})").find("/objects: expected an array"), std::string::npos);
}

TEST(SceneErrors, NegativeAndNonFiniteNumbers) {
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "radius": -1}]})").find("/objects/0/radius: must be > 0"),
            std::string::npos);
  // JSON has no NaN; a literal that overflows a double is refused at its path with the range.
  EXPECT_NE(error_of(R"({"camera": {"fov_deg": 1e999}})").find("/camera/fov_deg: number out of range: 1e999"), std::string::npos);
  EXPECT_NE(error_of(R"({"lights": [{"type": "sun", "direction": [0, 1, 0], "irradiance": -2}]})")
                .find("/lights/0/irradiance: must be >= 0"),
            std::string::npos);
}

TEST(SceneErrors, MissingFilesAndNames) {
  EXPECT_NE(error_of(R"({"objects": [{"type": "mesh", "file": "nope.glb"}]})").find("/objects/0/file: file not found"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"objects": [{"type": "sphere", "radius": 1, "material": "oak"}]})").find("no material named \"oak\""),
            std::string::npos);
  EXPECT_NE(error_of(R"({"lights": [{"type": "environment", "file": "sky.exr"}]})").find("/lights/0/file: file not found"),
            std::string::npos);
}

TEST(SceneErrors, SyntaxErrorsGiveLineAndColumn) {
  const auto msg = error_of("{\n  \"camera\": {\n    \"fov_deg\": 40,\n  }\n}");
  EXPECT_NE(msg.find("scene.json: line 4, column"), std::string::npos) << msg;
}

TEST(SceneErrors, ValidRangesAreChecked) {
  EXPECT_NE(error_of(R"({"render": {"resolution": [0, 10]}})").find("/render/resolution"), std::string::npos);
  EXPECT_NE(error_of(R"({"lights": [{"type": "sky", "turbidity": 30, "sun_direction": [0,1,0]}]})")
                .find("turbidity must lie in [1.7, 10]"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"lights": [{"type": "sky"}]})").find("needs a sun_direction or a sun light"), std::string::npos);
  EXPECT_NE(error_of(R"({"materials": {"m": {"type": "diffuse", "base_color": [2, 0, 0]}}})").find("must lie in [0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"camera": {"position": [0,0,0], "look_at": [0,0,0]}})").find("must differ from position"),
            std::string::npos);
}

TEST(SceneErrors, DefaultSceneParses) {
  const SceneDesc d = default_scene();
  ASSERT_EQ(d.objects.size(), 2u);
  EXPECT_EQ(d.objects[0].type, ObjectType::Tree);
  EXPECT_EQ(d.objects[0].tree.branches.size(), 3u);
  EXPECT_TRUE(d.objects[0].tree.strip_bark);  // simulated bark
}

TEST(Cli, BadSceneExitsTwoAndLeavesNoOutput) {
  const std::string dir = test::temp_dir("cli_errors");
  test::write_text(dir + "/bad.json", R"({"objects": [{"type": "sphere", "radius": -1}]})");
  const auto r = test::run_phellem("render " + dir + "/bad.json -o " + dir + "/out.exr --png " + dir + "/out.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("phellem: error: " + dir + "/bad.json: /objects/0/radius: must be > 0"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.png"));
  for (const auto& e : std::filesystem::directory_iterator(dir)) EXPECT_EQ(e.path().extension(), ".json") << e.path();
}

TEST(Cli, FailedRunLeavesEarlierOutputUntouched) {
  const std::string dir = test::temp_dir("cli_keep");
  test::write_text(dir + "/out.exr", "previous render");
  test::write_text(dir + "/bad.json", R"({"render": {"spp": 0}})");
  const auto r = test::run_phellem("render " + dir + "/bad.json -o " + dir + "/out.exr");
  EXPECT_EQ(r.exit_code, 2);
  std::ifstream in(dir + "/out.exr");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "previous render");
}

TEST(Cli, TreeTooLargeForItsStripBarkExitsTwoAtOnce) {
  // A radius in millimetres where metres were meant: refused with the JSON path, not a hang.
  const std::string dir = test::temp_dir("cli_huge_tree");
  test::write_text(dir + "/huge.json", R"({"objects": [{"type": "tree", "axis": [[0, 0, 0], [0, 2, 0]], "radius": [300],
                                          "bark": {"model": "strips", "preset": "furrowed"}}]})");
  const auto r = test::run_phellem("simulate " + dir + "/huge.json -o " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("huge.json: /objects/0/bark/element_length: element_length: must be at least"), std::string::npos)
      << r.output;
}

TEST(Cli, FilmLargerThanMemoryIsRefusedBeforeRendering) {
  // 32768 x 32768 pixels of 18 floats, and the EXR's copy: 148 GiB, more than 75 % of the
  // memory of any machine this runs on (the default budget, scene/memory_estimate.h).
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (0.75 * physical > 32768.0 * 32768.0 * 140.0) GTEST_SKIP() << "this machine has the memory for the film";
  const auto r = test::run_phellem("render --res 32768x32768 --spp 1 -o /tmp/phellem_never.exr --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("phellem: error: <command line>: --res: needs about 148.0 GiB for the 32768x32768 film"),
            std::string::npos)
      << r.output;
  const std::string dir = test::temp_dir("cli_big_film");
  test::write_text(dir + "/big.json", R"({"render": {"resolution": [32768, 32768], "spp": 1}})");
  const auto s = test::run_phellem("render " + dir + "/big.json -o " + dir + "/out.exr --quiet");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.output.find(dir + "/big.json: /render/resolution: needs about 148.0 GiB for the 32768x32768 film"),
            std::string::npos)
      << s.output;
}

TEST(Errors, PrintableEscapesWhatATerminalCannotShow) {
  EXPECT_EQ(printable("θ × ≤ 1\tok\n"), "θ × ≤ 1\tok\n");        // valid UTF-8, tab and newline pass
  EXPECT_EQ(printable("key\xEF'"), "key\\xEF'");                 // a lone lead byte
  EXPECT_EQ(printable("\x1B[31mred"), "\\x1B[31mred");           // a terminal escape
  EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");                // an overlong '/'
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");       // a UTF-16 surrogate
  EXPECT_EQ(printable("end\xE2\x88"), "end\\xE2\\x88");          // a sequence cut short
  EXPECT_EQ(printable("\xF0\x9F\x8C\xB3"), "\xF0\x9F\x8C\xB3");  // U+1F333 passes
}

TEST(Cli, ErrorQuotingABrokenFileIsPrintable) {
  // A glTF whose JSON holds a byte that is not UTF-8: the parser's message quotes it.
  const std::string dir = test::temp_dir("cli_bad_bytes");
  test::write_text(dir + "/m.gltf",
                   "{\"asset\": {\"version\": \"2.0\"}, \"buf\xEF"
                   "fers\": []}");
  test::write_text(dir + "/s.json", R"({"objects": [{"type": "mesh", "file": "m.gltf"}]})");
  const auto r = test::run_phellem("render " + dir + "/s.json -o " + dir + "/o.exr --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("phellem: error: " + dir + "/m.gltf"), std::string::npos) << r.output;
  EXPECT_EQ(printable(r.output), r.output) << "not printable: " << printable(r.output);
  EXPECT_NE(r.output.find("\\xEF"), std::string::npos) << r.output;
}

TEST(Cli, BadOptionsExitTwo) {
  EXPECT_EQ(test::run_phellem("render --spp zero").exit_code, 2);
  EXPECT_EQ(test::run_phellem("render --res 100").exit_code, 2);
  EXPECT_EQ(test::run_phellem("render --frobnicate").exit_code, 2);
  EXPECT_EQ(test::run_phellem("explode").exit_code, 2);
  EXPECT_EQ(test::run_phellem("render /nonexistent/scene.json").exit_code, 2);
  EXPECT_EQ(test::run_phellem("render --view NoSuchView --png x.png").exit_code, 2);
  const auto t = test::run_phellem("turntable " PHELLEM_SOURCE_DIR "/scenes/default.json --frames 2 -o /tmp/frame.exr");
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_NE(t.output.find("frame number field"), std::string::npos) << t.output;
  // A wrong output name is refused before the render, not after it.
  const auto png = test::run_phellem("render -o /tmp/phellem_never.png");
  EXPECT_EQ(png.exit_code, 2);
  EXPECT_NE(png.output.find("phellem: error: <command line>: -o: expected a .exr file name, got \"/tmp/phellem_never.png\""),
            std::string::npos)
      << png.output;
  EXPECT_NE(test::run_phellem("render --png /tmp/phellem_never.exr").output.find("expected a .png file name"), std::string::npos);
  EXPECT_EQ(test::run_phellem("turntable " PHELLEM_SOURCE_DIR "/scenes/default.json --frames 2 -o /tmp/f_%04d.tif").exit_code, 2);
  EXPECT_EQ(
      test::run_phellem("turntable " PHELLEM_SOURCE_DIR "/scenes/default.json --frames 2 -o /tmp/f_%04d.exr --mp4 /tmp/t.gif")
          .exit_code,
      2);
}

}  // namespace
}  // namespace phellem

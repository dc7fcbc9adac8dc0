// Issue 43, outputs: names from a scene stay in their folder, no output replaces an input,
// links are written through and devices refused, a full disk is an error (never a success with
// a truncated file), a killed run's temporaries are cleaned by the next one, and the command
// line's own mistakes (an option twice, a path too long, more threads than the system can run)
// are exit 2.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "tests/support/height_fields.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

const char* kSphere = R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
                          "lights": [{"type": "environment", "color": [1, 1, 1]}]})";

// A small strip-bark tree whose object is named `name` (JSON-escaped by the caller).
std::string strip_tree(const std::string& name) {
  return R"({"lights": [{"type": "environment", "color": [1, 1, 1]}],
    "objects": [{"type": "tree", "name": ")" +
         name + R"(", "axis": [[0, 0, 0], [0, 0.3, 0]], "radius": [0.05, 0.04],
                 "bark": {"model": "strips", "preset": "fissured", "steps": 20, "growth_rate": 1.01, "strip_width": 0.01}}]})";
}

void expect_exit2(const test::CommandResult& r, const std::string& message, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << what << "\n" << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + message), std::string::npos) << what << "\n" << r.output;
}

TEST(HostileOutputsCli, ObjectNamesCannotLeadOutOfTheOutputFolder) {
  const std::string d = test::temp_dir("hostile_names");
  fs::create_directories(d + "/out");
  for (const char* name : {"../escape", "/tmp/phellem_escape", "sub/dir", ".hidden", "..", "a\\nb"}) {
    test::write_text(d + "/scene.json", strip_tree(name));
    const auto r = test::run_phellem("simulate " + d + "/scene.json -o " + d + "/out --no-mesh");
    expect_exit2(r, d + "/scene.json: /objects/0/name: the name", name);
    EXPECT_NE(r.output.find("names are used as file names in the output folder"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(d + "/escape_trunk.exr"));
  EXPECT_FALSE(fs::exists("/tmp/phellem_escape_trunk.exr"));
  EXPECT_TRUE(fs::is_empty(d + "/out"));
  // A plain name is written inside the folder, as before.
  test::write_text(d + "/scene.json", strip_tree("oak 1"));
  const auto ok = test::run_phellem("simulate " + d + "/scene.json -o " + d + "/out --no-mesh");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_TRUE(fs::exists(d + "/out/oak 1_trunk.exr"));
}

TEST(HostileOutputsCli, NoOutputReplacesAnInput) {
  const std::string d = test::temp_dir("hostile_inputs");
  test::write_text(d + "/scene.json", kSphere);
  expect_exit2(test::run_phellem("render " + d + "/scene.json --res 8x8 --spp 1 -o " + d + "/a.exr --stats " + d + "/scene.json"),
               d + "/scene.json: --stats: is the input SCENE names", "--stats over the scene");
  fs::create_symlink(d + "/scene.json", d + "/link.json");
  expect_exit2(test::run_phellem("render " + d + "/scene.json --res 8x8 --spp 1 -o " + d + "/a.exr --stats " + d + "/link.json"),
               d + "/link.json: --stats: is the input SCENE names", "--stats over the scene through a link");
  EXPECT_EQ(test::read_text(d + "/scene.json"), kSphere);
  // A mesh the scene names.
  test::write_text(d + "/mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_text(d + "/mesh_scene.json", R"({"objects": [{"type": "mesh", "file": "mesh.obj"}],
                                               "lights": [{"type": "environment", "color": [1, 1, 1]}]})");
  expect_exit2(test::run_phellem("render " + d + "/mesh_scene.json --res 8x8 --spp 1 -o " + d + "/a.exr --stats " + d + "/mesh.obj"),
               d + "/mesh.obj: --stats: is the input " + d + "/mesh_scene.json names", "--stats over the scene's mesh");
  // compare's inputs, and fit's.
  const test::Heights bark = test::fissured_bark(12, 12, 5, 3);
  test::write_height_png16(d + "/a.png", bark);
  test::write_height_png16(d + "/b.png", bark);
  const std::string compare = "compare " + d + "/a.png " + d + "/b.png --scale A=5 --scale B=5";
  expect_exit2(test::run_phellem(compare + " -o " + d + "/a.png"), d + "/a.png: -o: is the input A names", "compare -o A");
  expect_exit2(test::run_phellem(compare + " --json " + d + "/b.png"), d + "/b.png: --json: is the input B names", "compare --json B");
  fs::create_directories(d + "/fit");
  fs::copy_file(d + "/a.png", d + "/fit/report.json");  // an input with the name of one of fit's outputs
  expect_exit2(test::run_phellem("fit " + d + "/fit/report.json --scale 5 --model strips --max-evals 1 -o " + d + "/fit"),
               d + "/fit/report.json: -o: is the input HEIGHT_IMAGE names", "fit -o over its input");
  EXPECT_EQ(test::read_text(d + "/fit/report.json"), test::read_text(d + "/a.png"));
}

TEST(HostileOutputsCli, LinksAreWrittenThroughDevicesAndFifosRefused) {
  const std::string d = test::temp_dir("hostile_links");
  test::write_text(d + "/scene.json", kSphere);
  const std::string render = "render " + d + "/scene.json --res 8x8 --spp 1 ";
  fs::create_symlink("/dev/full", d + "/full.png");
  expect_exit2(test::run_phellem(render + "--png " + d + "/full.png"),
               d + "/full.png: --png: is a character device (through a symbolic link)", "--png to /dev/full");
  ASSERT_EQ(mkfifo((d + "/fifo.exr").c_str(), 0600), 0);
  expect_exit2(test::run_phellem_limited(render + "-o " + d + "/fifo.exr", 4096, 60), d + "/fifo.exr: -o: is a FIFO",
               "-o to a FIFO");
  expect_exit2(test::run_phellem(render + "--stats /dev/null"), "/dev/null: --stats: is a character device", "--stats /dev/null");
  // compare -o through a link: the link stays and the file it points to holds the report.
  const test::Heights bark = test::fissured_bark(30, 30, 5, 3);
  test::write_height_png16(d + "/a.png", bark);
  fs::create_directories(d + "/reports");
  test::write_text(d + "/reports/r.html", "old");
  fs::create_symlink(d + "/reports/r.html", d + "/r.html");
  const auto r = test::run_phellem("compare " + d + "/a.png " + d + "/a.png --scale A=5 --scale B=5 -o " + d + "/r.html");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(d + "/r.html"));
  EXPECT_NE(test::read_text(d + "/reports/r.html").find("<html"), std::string::npos);
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

// A full disk, as a file-size limit (SIGXFSZ ignored, so writes fail with EFBIG) and, where
// this process may mount, as a 64 KiB tmpfs (ENOSPC): exit 2 at "write", earlier outputs whole.
TEST(HostileOutputsCli, AFullDiskIsAnErrorAndTheEarlierFilesStay) {
  const std::string d = test::temp_dir("hostile_full");
  test::write_text(d + "/scene.json", kSphere);
  test::write_text(d + "/a.png", "old png");
  test::write_text(d + "/a.exr", "old exr");
  const std::string render = std::string(PHELLEM_BINARY) + " render " + d + "/scene.json --res 256x256 --spp 1 --quiet ";
  for (const std::string& out : {"--png " + d + "/a.png", "-o " + d + "/a.exr"}) {
    const auto r = test::run_command("ulimit -f 1 && trap '' XFSZ && exec " + render + out + " 2>&1");
    EXPECT_EQ(r.exit_code, 2) << out << "\n" << r.output;
    EXPECT_NE(r.output.find(": write: wrote "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  }
  EXPECT_EQ(test::read_text(d + "/a.png"), "old png");
  EXPECT_EQ(test::read_text(d + "/a.exr"), "old exr");
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
  // A real full file system, in a mount namespace of its own.
  if (test::run_command("unshare -m true 2>&1").exit_code != 0) GTEST_SKIP() << "cannot make a mount namespace here";
  // The folder `full` is a 64 KiB file system holding an earlier a.png, then filled to the brim.
  fs::create_directories(d + "/full");
  const auto full = test::run_command("unshare -m sh -c 'mount -t tmpfs -o size=64k tmpfs " + d + "/full && echo old > " + d +
                                      "/full/a.png && (head -c 1000000 /dev/zero > " + d + "/full/filler 2>/dev/null; " + render +
                                      "--png " + d + "/full/a.png 2>&1; echo exit=$?; cat " + d + "/full/a.png; ls -a " + d +
                                      "/full)'");
  EXPECT_NE(full.output.find(": write: "), std::string::npos) << full.output;
  EXPECT_NE(full.output.find("No space left on device"), std::string::npos) << full.output;
  EXPECT_NE(full.output.find("exit=2"), std::string::npos) << full.output;
  EXPECT_NE(full.output.find("\nold\n"), std::string::npos) << full.output;
  EXPECT_EQ(full.output.find(".tmp"), std::string::npos) << full.output;
}

TEST(HostileOutputsCli, TheNextRunRemovesTheTemporariesOfAKilledOne) {
  const std::string d = test::temp_dir("hostile_stale");
  test::write_text(d + "/scene.json", kSphere);
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0);
  const std::string stale = d + "/.a.tmp" + std::to_string(child) + ".png";
  test::write_text(stale, "left by a SIGKILLed run");
  const auto r = test::run_phellem("render " + d + "/scene.json --res 8x8 --spp 1 --png " + d + "/a.png");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

TEST(HostileOutputsCli, CommandLineMistakesAreExit2) {
  const std::string d = test::temp_dir("hostile_cmdline");
  test::write_text(d + "/scene.json", kSphere);
  const std::string render = "render " + d + "/scene.json --res 8x8 --spp 1 ";
  expect_exit2(test::run_phellem(render + "-o " + d + "/a.exr -o " + d + "/b.exr"), "<command line>: -o: given twice",
               "-o twice");
  expect_exit2(test::run_phellem(render + "-o " + d + "/a.exr --output " + d + "/b.exr"), "<command line>: --output: given twice",
               "-o and --output");
  expect_exit2(test::run_phellem(render + "--spp 2"), "<command line>: --spp: given twice", "--spp twice");
  const test::Heights bark = test::fissured_bark(12, 12, 5, 3);
  test::write_height_png16(d + "/a.png", bark);
  expect_exit2(test::run_phellem("compare " + d + "/a.png " + d + "/a.png --scale A=5 --scale B=5 --scale A=6"),
               "<command line>: --scale A: given twice", "compare --scale A twice");
  expect_exit2(test::run_phellem("compare " + d + "/a.png " + d + "/a.png --scale A=5 --scale B=5 -o " + d + "/r.html -o " + d +
                                 "/s.html"),
               "<command line>: -o: given twice", "compare -o twice");
  // A 4090-byte output path: the limit is named, not an internal error.
  std::string deep = d;
  while (deep.size() < 3900) deep += "/" + std::string(200, 'd');
  const auto r = test::run_phellem(render + "-o " + deep + "/" + std::string(180, 'f') + ".exr");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(": -o: the path is "), std::string::npos) << r.output;
}

// More threads than the process may start (here its address space holds too few 4 MiB stacks)
// is refused with the count, never a signal.
TEST(HostileOutputsCli, MoreThreadsThanTheSystemCanStartIsExit2) {
  const std::string d = test::temp_dir("hostile_threads");
  test::write_text(d + "/scene.json", kSphere);
  const auto r = test::run_phellem_limited("render " + d + "/scene.json --res 8x8 --spp 1 -o " + d + "/a.exr --threads 1024", 2048, 120);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: <command line>: --threads: this system cannot run 1024 threads now"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(d + "/a.exr"));
  const auto ok = test::run_phellem("render " + d + "/scene.json --res 8x8 --spp 1 -o " + d + "/a.exr --threads 64");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

}  // namespace
}  // namespace phellem

// Only a regular scene file of at most 64 MiB is read: /dev/zero, a folder, a FIFO (which
// would wait for a writer for ever) or an oversized file is an exit-2 error before any
// byte is read, never an allocation failure or a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene_parser.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

const char* kScene = R"({"render": {"resolution": [8, 8], "spp": 1}})";

// Runs `phellem render <scene>` in a 4 GiB address space for at most 60 s (a build that reads
// /dev/zero whole or opens a FIFO fails the test instead of taking the machine's memory or
// hanging).
test::CommandResult render(const std::string& scene, const std::string& dir) {
  return test::run_phellem_limited("render " + scene + " -o " + dir + "/out.exr", 4096, 60);
}

void expect_refused(const test::CommandResult& r, const std::string& scene, const std::string& says) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
}

TEST(SceneFileCli, DevZeroIsRefusedBeforeReading) {
  const std::string dir = test::temp_dir("scene_dev_zero");
  expect_refused(render("/dev/zero", dir), "/dev/zero", "is not a regular file (a character device)");
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.exr"));
}

TEST(SceneFileCli, AFolderIsRefused) {
  const std::string dir = test::temp_dir("scene_folder");
  std::filesystem::create_directories(dir + "/scene.json");
  expect_refused(render(dir + "/scene.json", dir), dir + "/scene.json", "is a folder, not a scene file");
}

TEST(SceneFileCli, AFifoIsRefusedWithoutWaitingForAWriter) {
  const std::string dir = test::temp_dir("scene_fifo");
  const std::string fifo = dir + "/scene.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(render(fifo, dir), fifo, "is not a regular file (a FIFO)");
}

TEST(SceneFileCli, AFileOverSixtyFourMebibytesIsRefused) {
  const std::string dir = test::temp_dir("scene_big");
  // A valid scene followed by NUL bytes up to one byte past the limit (sparse: no disk used).
  const std::string big = dir + "/big.json";
  test::write_text(big, kScene);
  std::filesystem::resize_file(big, kMaxSceneFileBytes + 1);
  expect_refused(render(big, dir), big, "the scene file is 67108865 bytes; at most 67108864 (64 MiB) are read");
}

TEST(SceneFileCli, RegularFilesAndLinksToThemAreRead) {
  const std::string dir = test::temp_dir("scene_regular");
  test::write_text(dir + "/scene.json", kScene);
  std::filesystem::create_symlink(dir + "/scene.json", dir + "/link.json");
  for (const char* name : {"/scene.json", "/link.json"}) {
    const auto r = render(dir + name, dir);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.output;
  }
  // A missing file is named too.
  expect_refused(render(dir + "/missing.json", dir), dir + "/missing.json", "cannot open scene file");
}

}  // namespace
}  // namespace phellem

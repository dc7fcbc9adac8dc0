// write_atomically: the target appears only when complete, and a failure says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/test_util.h"
#include "util/atomic_file.h"
#include "util/errors.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

size_t entries(const std::string& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesTheTargetThroughATemporary) {
  const std::string dir = test::temp_dir("atomic_ok");
  const std::string target = dir + "/out.json";
  std::string seen;
  write_atomically(target, [&](const std::string& tmp) {
    seen = tmp;
    std::ofstream(tmp) << "new";
    EXPECT_FALSE(fs::exists(target));
  });
  EXPECT_NE(seen, target);
  EXPECT_EQ(fs::path(seen).parent_path(), fs::path(target).parent_path());
  EXPECT_EQ(fs::path(seen).extension(), ".json");
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "new");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicFile, AFailedRenameSaysWhyAndLeavesNoTemporary) {
  // A folder in the target's place: rename(2) fails with EISDIR, and the message must say so
  // (it said "Success" when the error was overwritten by the temporary's removal).
  const std::string dir = test::temp_dir("atomic_rename");
  const std::string target = dir + "/out.exr";
  fs::create_directories(target + "/inside");
  try {
    write_atomically(target, [&](const std::string& tmp) { std::ofstream(tmp) << "new"; });
    FAIL() << "a rename over a folder succeeded";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find("Success"), std::string::npos) << what;
    EXPECT_NE(what.find(std::error_code(EISDIR, std::generic_category()).message()), std::string::npos) << what;
    EXPECT_NE(what.find(target), std::string::npos) << what;
  }
  EXPECT_EQ(entries(dir), 1u);  // only the folder: the temporary is gone
}

TEST(AtomicFile, AFailedWriteRemovesTheTemporaryAndKeepsTheOldFile) {
  const std::string dir = test::temp_dir("atomic_throw");
  const std::string target = dir + "/out.txt";
  test::write_text(target, "old");
  EXPECT_THROW(write_atomically(target,
                                [&](const std::string& tmp) {
                                  std::ofstream(tmp) << "partial";
                                  throw UserError(target, "", "disk full");
                                }),
               UserError);
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
  EXPECT_EQ(entries(dir), 1u);
}

}  // namespace
}  // namespace phellem

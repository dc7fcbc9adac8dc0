// OutputSet: outputs checked before any work, staged beside their targets, committed together,
// and removed without a trace when the run fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/test_util.h"
#include "util/errors.h"
#include "util/output_set.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

// The message of the UserError `f` throws ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputSet, RefusesAMissingFolderAFileForAFolderAndAFolderForAFile) {
  const std::string d = test::temp_dir("output_set_checks");
  test::write_text(d + "/file.txt", "x");
  fs::create_directories(d + "/sub");
  OutputSet out;
  EXPECT_EQ(error_of([&] { out.expect_file("--png", d + "/no/x.png"); }), d + "/no/x.png: --png: folder does not exist");
  EXPECT_EQ(error_of([&] { out.expect_file("--png", d + "/file.txt/x.png"); }),
            d + "/file.txt/x.png: --png: " + d + "/file.txt is not a folder");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/sub"); }), d + "/sub: --stats: is a folder, not a file");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/new/"); }), d + "/new/: --stats: is a folder, not a file");
  EXPECT_EQ(error_of([&] { out.expect_folder("-o", d + "/file.txt"); }), d + "/file.txt: -o: is a file, not a folder");
  EXPECT_EQ(error_of([&] { out.expect_folder("-o", d + "/no/out"); }), d + "/no/out: -o: parent folder does not exist");
  EXPECT_EQ(error_of([&] { out.expect_folder("-o", d + "/sub/"); }), "");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/sub/s.json"); }), "");
}

TEST(OutputSet, TwoOutputsNamingOneFileAreRefused) {
  const std::string d = test::temp_dir("output_set_same");
  fs::create_directories(d + "/sub");
  fs::create_symlink(d + "/sub", d + "/link");
  OutputSet out;
  out.expect_file("-o", d + "/a.exr");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/a.exr"); }), d + "/a.exr: --stats: the same file as -o");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/sub/../a.exr"); }),
            d + "/sub/../a.exr: --stats: the same file as -o");
  out.expect_file("--png", d + "/sub/a.png");
  EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/link/a.png"); }), d + "/link/a.png: --stats: the same file as --png");
  EXPECT_EQ(error_of([&] { out.expect_file("-o", d + "/./a.exr"); }), d + "/./a.exr: -o: named twice by -o");
  // A file staged under another option than the one that expected it, or staged twice.
  EXPECT_EQ(error_of([&] { out.stage("--stats", d + "/a.exr"); }), d + "/a.exr: --stats: the same file as -o");
  out.stage("-o", d + "/a.exr");
  EXPECT_NE(error_of([&] { out.stage("-o", d + "/a.exr"); }).find("written twice"), std::string::npos);
}

TEST(OutputSet, CommitReplacesEveryTargetTogether) {
  const std::string d = test::temp_dir("output_set_commit");
  test::write_text(d + "/a.txt", "old a");
  test::write_text(d + "/b.txt", "old b");
  OutputSet out;
  out.expect_file("-o", d + "/a.txt");
  out.expect_file("--stats", d + "/b.txt");
  const std::string ta = out.stage("-o", d + "/a.txt"), tb = out.stage("--stats", d + "/b.txt");
  EXPECT_EQ(fs::path(ta).parent_path(), fs::path(d));
  EXPECT_EQ(fs::path(ta).extension(), ".txt");
  test::write_text(ta, "new a");
  test::write_text(tb, "new b");
  EXPECT_EQ(test::read_text(d + "/a.txt"), "old a");  // nothing moves before the commit
  out.commit();
  EXPECT_EQ(test::read_text(d + "/a.txt"), "new a");
  EXPECT_EQ(test::read_text(d + "/b.txt"), "new b");
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

TEST(OutputSet, AFailedRunRemovesItsTemporariesAndTheFolderItMade) {
  const std::string d = test::temp_dir("output_set_fail");
  test::write_text(d + "/a.txt", "old a");
  {
    OutputSet out;
    out.expect_file("-o", d + "/a.txt");
    out.expect_folder("--dir", d + "/made");
    test::write_text(out.stage("-o", d + "/a.txt"), "new a");
    test::write_text(out.stage("--dir", d + "/made/x.txt"), "x");  // made at the first file in it
    EXPECT_TRUE(fs::is_directory(d + "/made"));
    // No commit: the run failed.
  }
  EXPECT_EQ(test::read_text(d + "/a.txt"), "old a");
  EXPECT_FALSE(fs::exists(d + "/made"));
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
  {
    OutputSet out;
    out.expect_folder("--dir", d + "/made");
    test::write_text(out.stage("--dir", d + "/made/x.txt"), "x");
    out.commit();
  }
  EXPECT_EQ(test::read_text(d + "/made/x.txt"), "x");
}

TEST(OutputSet, ACommitOverAFolderFailsBeforeRenamingAnything) {
  const std::string d = test::temp_dir("output_set_race");
  test::write_text(d + "/a.txt", "old a");
  OutputSet out;
  test::write_text(out.stage("-o", d + "/a.txt"), "new a");
  test::write_text(out.stage("--stats", d + "/b.txt"), "new b");
  fs::create_directories(d + "/b.txt");  // appears during the run
  EXPECT_EQ(error_of([&] { out.commit(); }), d + "/b.txt: --stats: is a folder, not a file");
  EXPECT_EQ(test::read_text(d + "/a.txt"), "old a");
}

}  // namespace
}  // namespace phellem

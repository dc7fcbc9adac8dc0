// util/input_file.h: what is not a regular file is named before anything opens it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "tests/support/test_util.h"
#include "util/errors.h"
#include "util/input_file.h"

namespace phellem {
namespace {

TEST(InputFile, OnlyRegularFilesAndLinksToThemAreInputs) {
  const std::string dir = test::temp_dir("input_file_kinds");
  test::write_text(dir + "/a.txt", "a");
  std::filesystem::create_symlink(dir + "/a.txt", dir + "/link.txt");
  std::filesystem::create_symlink(dir + "/gone.txt", dir + "/dangling.txt");
  ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
  EXPECT_EQ(input_file_problem(dir + "/a.txt"), std::nullopt);
  EXPECT_EQ(input_file_problem(dir + "/link.txt"), std::nullopt);
  EXPECT_EQ(input_file_problem(dir + "/fifo"), "is not a regular file (a FIFO)");
  EXPECT_EQ(input_file_problem("/dev/zero"), "is not a regular file (a character device)");
  EXPECT_EQ(input_file_problem(dir), "is a folder");
  EXPECT_EQ(input_file_problem(dir + "/missing"), "does not exist");
  EXPECT_EQ(input_file_problem(dir + "/dangling.txt"), "does not exist");
}

TEST(InputFile, MessagesNameThePathUnlessTheErrorDoes) {
  const std::string dir = test::temp_dir("input_file_messages");
  const std::string fifo = dir + "/lib.mtl";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(input_file_message(fifo, "a material library"),
            fifo + " is not a regular file (a FIFO); a material library is read from a regular file");
  EXPECT_EQ(input_file_message(dir + "/no.png", "an image"), "file not found: " + dir + "/no.png");
  test::expect_user_error([&] { require_input_file(fifo, "model.obj", "mtllib lib.mtl", "a material library"); }, "other file",
                          "model.obj", "mtllib lib.mtl", fifo + " is not a regular file (a FIFO); a material library");
  test::expect_user_error([&] { require_input_file(fifo, fifo, "open", "a scene"); }, "itself", fifo, "open",
                          "is not a regular file (a FIFO); a scene is read from a regular file");
  EXPECT_NO_THROW(require_input_file("/etc/hostname", "x", "y", "a file"));
}

}  // namespace
}  // namespace phellem

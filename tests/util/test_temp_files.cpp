// The registry of live temporaries: a termination signal removes them and still ends the
// process by that signal; during a commit it waits for the commit's end.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "tests/support/test_util.h"
#include "util/temp_files.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

// Runs `child` in a forked process with the handler installed; returns its wait status.
template <class F>
int in_child(F&& child) {
  const pid_t pid = fork();
  if (pid == 0) {
    signal(SIGTERM, SIG_DFL);
    remove_temp_files_on_termination();
    child();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

TEST(TempFiles, ASignalRemovesTheLiveTemporariesAndEndsTheProcessByIt) {
  const std::string d = test::temp_dir("temp_files_signal");
  const int status = in_child([&] {
    const LiveTempFile folder(d + "/made", LiveTempFile::Kind::Folder);
    fs::create_directory(d + "/made");
    const LiveTempFile a(d + "/made/.a.tmp1.exr"), b(d + "/.b.tmp1.png");
    LiveTempFile released(d + "/kept.txt");
    test::write_text(d + "/made/.a.tmp1.exr", "a");
    test::write_text(d + "/.b.tmp1.png", "b");
    test::write_text(d + "/kept.txt", "renamed into place: no longer a temporary");
    released.release();
    raise(SIGTERM);
    _exit(3);  // not reached
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_FALSE(fs::exists(d + "/made"));
  EXPECT_FALSE(fs::exists(d + "/.b.tmp1.png"));
  EXPECT_EQ(test::read_text(d + "/kept.txt"), "renamed into place: no longer a temporary");
}

TEST(TempFiles, ASignalDuringACommitWaitsForItsEnd) {
  const std::string d = test::temp_dir("temp_files_commit");
  const int status = in_child([&] {
    const LiveTempFile left(d + "/.left.tmp1.txt");
    test::write_text(d + "/.left.tmp1.txt", "x");
    {
      const TerminationDeferral commit;
      raise(SIGTERM);
      test::write_text(d + "/committed.txt", "the commit finished");
    }
    _exit(3);  // not reached: the signal ends the process when the commit ends
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(test::read_text(d + "/committed.txt"), "the commit finished");
  EXPECT_FALSE(fs::exists(d + "/.left.tmp1.txt"));
}

TEST(TempFiles, AnIgnoredSignalStaysIgnored) {
  const int status = in_child([] {
    signal(SIGHUP, SIG_IGN);
    remove_temp_files_on_termination();
    raise(SIGHUP);
  });
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(TempFiles, SlotsAreReusedAcrossManyTemporaries) {
  const std::string d = test::temp_dir("temp_files_many");
  const int status = in_child([&] {
    for (int i = 0; i < 10000; ++i) LiveTempFile t(d + "/.x" + std::to_string(i) + ".tmp");
    const LiveTempFile last(d + "/.last.tmp1.txt");
    test::write_text(d + "/.last.tmp1.txt", "x");
    raise(SIGTERM);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

}  // namespace
}  // namespace phellem

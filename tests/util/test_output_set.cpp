// OutputSet: outputs checked before any work, staged beside their targets, committed together,
// and removed without a trace when the run fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include "tests/support/test_util.h"
#include "util/errors.h"
#include "util/output_set.h"
#include "util/temp_files.h"

namespace phellem {

// The commit with a hook after each rename (OutputSet's friend).
struct OutputSetCommitProbe {
  static void commit_with(OutputSet& out, const std::function<void(size_t)>& after_rename) { out.commit_with(after_rename); }
};

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


// Issue 43: an output that resolves to one of the run's inputs is refused, whichever is declared
// first and through a symbolic link too.
TEST(OutputSet, AnOutputThatIsAnInputIsRefused) {
  const std::string d = test::temp_dir("output_set_input");
  test::write_text(d + "/scene.json", "{}");
  fs::create_symlink(d + "/scene.json", d + "/link.json");
  {
    OutputSet out;
    out.expect_input("SCENE", d + "/scene.json");
    EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/scene.json"); }),
              d + "/scene.json: --stats: is the input SCENE names; an output must not replace an input");
    EXPECT_EQ(error_of([&] { out.expect_file("--stats", d + "/link.json"); }),
              d + "/link.json: --stats: is the input SCENE names; an output must not replace an input");
    EXPECT_EQ(error_of([&] { out.stage("-o", d + "/./scene.json"); }),
              d + "/./scene.json: -o: is the input SCENE names; an output must not replace an input");
  }
  {
    OutputSet out;
    out.expect_file("-o", d + "/link.json");
    EXPECT_EQ(error_of([&] { out.expect_input("A", d + "/scene.json"); }),
              d + "/link.json: -o: is the input A names; an output must not replace an input");
  }
  EXPECT_EQ(test::read_text(d + "/scene.json"), "{}");
}

// Issue 43: a symbolic link is written through (the link stays, its file is replaced
// atomically); devices, FIFOs and links to nothing are refused before any work.
TEST(OutputSet, LinksAreWrittenThroughAndDevicesAndFifosRefused) {
  const std::string d = test::temp_dir("output_set_links");
  fs::create_directories(d + "/real");
  test::write_text(d + "/real/report.html", "old");
  fs::create_symlink(d + "/real/report.html", d + "/report.html");
  fs::create_symlink("/dev/full", d + "/full.png");
  fs::create_symlink(d + "/nothing.json", d + "/dangling.json");
  ASSERT_EQ(mkfifo((d + "/fifo.exr").c_str(), 0600), 0);
  OutputSet out;
  EXPECT_EQ(error_of([&] { out.expect_file("--png", d + "/full.png"); }),
            d + "/full.png: --png: is a character device (through a symbolic link); an output is a new name, a regular file or a link to one");
  EXPECT_EQ(error_of([&] { out.expect_file("-o", d + "/fifo.exr"); }),
            d + "/fifo.exr: -o: is a FIFO; an output is a new name, a regular file or a link to one");
  EXPECT_EQ(error_of([&] { out.expect_file("--json", "/dev/null"); }),
            "/dev/null: --json: is a character device; an output is a new name, a regular file or a link to one");
  EXPECT_EQ(error_of([&] { out.expect_file("--json", d + "/dangling.json"); }),
            d + "/dangling.json: --json: is a symbolic link to a missing file; an output is a new name, a regular file or a link to one");
  out.expect_file("-o", d + "/report.html");
  const std::string tmp = out.stage("-o", d + "/report.html");
  EXPECT_EQ(fs::path(tmp).parent_path(), fs::path(d + "/real"));  // beside the file, so the rename is atomic
  test::write_text(tmp, "new");
  out.commit();
  EXPECT_TRUE(fs::is_symlink(d + "/report.html"));
  EXPECT_EQ(test::read_text(d + "/real/report.html"), "new");
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

// Issue 43: the temporaries of a run killed by SIGKILL (its process id in their names) are
// removed by the next run writing into the same folder; a live process's and other files stay.
TEST(OutputSet, TemporariesOfDeadProcessesAreRemovedByTheNextRun) {
  const std::string d = test::temp_dir("output_set_stale");
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0);  // its process id names no process now
  const std::string dead = std::to_string(child), live = std::to_string(getppid());
  const std::vector<std::string> stale = {"/.render.tmp" + dead + ".exr", "/..render.tmp" + dead + ".tmp" + dead + ".exr",
                                          "/.other.tmp" + dead + ".png"};
  const std::vector<std::string> kept = {"/.render.tmp" + live + ".exr", "/notes.tmp" + dead + ".txt",
                                         "/.render.tmpx" + dead + ".exr", "/render.exr"};
  for (const auto& f : stale) test::write_text(d + f, "stale");
  for (const auto& f : kept) test::write_text(d + f, "keep");
  OutputSet out;
  test::write_text(out.stage("-o", d + "/render.exr"), "new");
  for (const auto& f : stale) EXPECT_FALSE(fs::exists(d + f)) << f;
  for (const auto& f : kept) EXPECT_TRUE(fs::exists(d + f)) << f;
}

// Issue 43: a path too long for its temporary is a UserError naming the limit, not an internal
// error ("temporary path too long").
TEST(OutputSet, APathTooLongForItsTemporaryIsAUserError) {
  const std::string d = test::temp_dir("output_set_long");
  std::string deep = d;
  while (deep.size() < 3900) deep += "/" + std::string(200, 'd');
  OutputSet out;
  const std::string e = error_of([&] { out.expect_file("-o", deep + "/" + std::string(190, 'f') + ".exr"); });
  EXPECT_NE(e.find(": -o: the path is "), std::string::npos) << e;
  EXPECT_NE(e.find("bytes long; at most"), std::string::npos) << e;
  const std::string name = error_of([&] { out.expect_file("-o", d + "/" + std::string(250, 'n') + ".exr"); });
  EXPECT_NE(name.find(": -o: the file name is 254 bytes long; at most"), std::string::npos) << name;
}

// Issue 43: names taken from a scene stay inside the output folder.
TEST(OutputSet, FileNameProblemRefusesNamesThatLeaveTheFolder) {
  for (const std::string& bad : std::vector<std::string>{"../escape", "/etc/passwd", "a/b", ".", "..", ".hidden", std::string("a\nb"),
                                std::string("nul\0x", 5), std::string(201, 'x')})
    EXPECT_NE(file_name_problem(bad), "") << bad;
  for (const std::string& good : std::vector<std::string>{"trunk", "Trunk 2 (old)", "ствол", std::string(200, 'x'), "a..b"})
    EXPECT_EQ(file_name_problem(good), "") << good;
}

// Issue 43: bytes go to disk through checked writes; a file-size limit (as a full disk) is a
// UserError at "write", and the earlier file stays as it was.
TEST(OutputSet, AWriteThatDoesNotFitFailsAndLeavesTheEarlierFile) {
  const std::string d = test::temp_dir("output_set_full");
  test::write_text(d + "/a.json", "old");
  struct rlimit old_limit;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  struct sigaction ignore {}, old_action{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGXFSZ, &ignore, &old_action);
  struct rlimit small = old_limit;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string e;
  {
    OutputSet out;
    e = error_of([&] { out.write_bytes("--stats", d + "/a.json", std::string(100000, 'x')); });
  }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  sigaction(SIGXFSZ, &old_action, nullptr);
  EXPECT_EQ(e, d + "/a.json: write: wrote 4096 of 100000 bytes: File too large");
  EXPECT_EQ(test::read_text(d + "/a.json"), "old");
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}


// Issue 43: a failed rename, or a termination signal between two renames (it waits for the
// commit's end), puts every earlier output back: never a mix, never an output replaced by a run
// that was killed (it had been replaced after a SIGHUP).
TEST(OutputSet, AFailedRenameInTheCommitPutsTheEarlierOutputsBack) {
  const std::string d = test::temp_dir("output_set_restore");
  test::write_text(d + "/a.txt", "old a");
  std::string e;
  {
    OutputSet out;
    out.write_bytes("-o", d + "/a.txt", "new a");
    out.write_bytes("--json", d + "/new.json", "new");
    out.write_bytes("--stats", d + "/b.txt", "new b");
    e = error_of([&] {
      OutputSetCommitProbe::commit_with(out, [&](size_t renamed) {
        if (renamed == 2) fs::create_directories(d + "/b.txt/x");  // a folder appears where the last output goes
      });
    });
  }
  EXPECT_EQ(e.rfind(d + "/b.txt: --stats: cannot move the written file into place: ", 0), 0u) << e;
  EXPECT_NE(e.find("the earlier outputs are as they were"), std::string::npos) << e;
  EXPECT_EQ(test::read_text(d + "/a.txt"), "old a");
  EXPECT_FALSE(fs::exists(d + "/new.json"));
  EXPECT_TRUE(test::leftover_temporaries(d).empty());
}

TEST(OutputSet, ASignalDuringTheCommitPutsTheEarlierOutputsBackAndEndsTheRun) {
  for (const int sig : {SIGHUP, SIGTERM, SIGINT}) {
    const std::string d = test::temp_dir("output_set_signal_" + std::to_string(sig));
    test::write_text(d + "/a.exr", "old a");
    test::write_text(d + "/b.png", "old b");
    const pid_t child = fork();
    if (child == 0) {
      signal(sig, SIG_DFL);  // a test runner may have it ignored
      remove_temp_files_on_termination();
      OutputSet out;
      out.write_bytes("-o", d + "/a.exr", "new a");
      out.write_bytes("--json", d + "/new.json", "new");
      out.write_bytes("--png", d + "/b.png", "new b");
      OutputSetCommitProbe::commit_with(out, [&](size_t renamed) {
        if (renamed == 2) raise(sig);
      });
      _exit(0);  // not reached: the signal ends the process once the commit is undone
    }
    ASSERT_GT(child, 0);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "signal " << sig << ", status " << status;
    EXPECT_EQ(test::read_text(d + "/a.exr"), "old a") << sig;
    EXPECT_EQ(test::read_text(d + "/b.png"), "old b") << sig;
    EXPECT_FALSE(fs::exists(d + "/new.json")) << sig;
    EXPECT_EQ(test::leftover_temporaries(d), std::vector<std::string>{}) << sig;
  }
}

}  // namespace
}  // namespace phellem

// `--mp4` with a stand-in ffmpeg on PATH (the real one is not needed, and not in CI): the
// frames reach it as a pattern of the PNG temporaries and its output is committed with them;
// a missing ffmpeg is refused before any frame, a failing one is an error that writes
// nothing, and a termination signal during the encoding ends ffmpeg too and leaves no
// temporary. File names reach ffmpeg as they are (no shell): a quote in a name is harmless.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

// Puts an executable `ffmpeg` with the shell body `script` first on PATH for this process and
// the phellem it starts; restores PATH when it goes.
class FakeFfmpeg {
 public:
  FakeFfmpeg(const std::string& dir, const std::string& script) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    fs::create_directories(dir);
    test::write_text(dir + "/ffmpeg", "#!/bin/sh\n" + script);
    chmod((dir + "/ffmpeg").c_str(), 0755);
    setenv("PATH", (dir + ":" + old_).c_str(), 1);
  }
  ~FakeFfmpeg() { setenv("PATH", old_.c_str(), 1); }

 private:
  std::string old_;
};

const char* kScene = R"({"render": {"resolution": [16, 16], "spp": 1},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}], "lights": [{"type": "environment", "color": [1, 1, 1]}]})";

// The last argument is the output; "-i" is followed by the frames' pattern.
const char* kWritesTheMp4 = R"(for a; do last="$a"; done
prev=""; for a; do [ "$prev" = "-i" ] && pattern="$a"; prev="$a"; done
first=$(printf "$pattern" 0)
[ -f "$first" ] && echo "frame 0 present" > "$last" || echo "frame 0 missing: $first" > "$last"
)";

TEST(Mp4Cli, FramesReachFfmpegAndItsOutputIsCommittedWithThem) {
  const std::string d = test::temp_dir("mp4_ok");
  const FakeFfmpeg fake(d + "/bin", kWritesTheMp4);
  test::write_text(d + "/scene.json", kScene);
  const std::string out = d + "/it's out";  // a quote: no shell parses the names
  fs::create_directories(out);
  const auto r =
      test::run_phellem("turntable " + d + "/scene.json --frames 2 -o \"" + out + "/f_%04d.exr\" --mp4 \"" + out + "/turn.mp4\"");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::read_text(out + "/turn.mp4"), "frame 0 present\n");
  EXPECT_TRUE(fs::exists(out + "/f_0000.png"));
  EXPECT_TRUE(fs::exists(out + "/f_0001.exr"));
  EXPECT_TRUE(test::leftover_temporaries(out).empty());
}

TEST(Mp4Cli, MissingFfmpegIsRefusedBeforeAnyFrame) {
  const std::string d = test::temp_dir("mp4_missing");
  fs::create_directories(d + "/empty");
  const std::string old = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", (d + "/empty").c_str(), 1);
  test::write_text(d + "/scene.json", kScene);
  const auto r = test::run_phellem("turntable " + d + "/scene.json --frames 2 -o " + d + "/f_%04d.exr --mp4 " + d + "/t.mp4");
  setenv("PATH", old.c_str(), 1);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + d + "/t.mp4: --mp4: ffmpeg is not installed"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d + "/f_0000.exr"));
}

TEST(Mp4Cli, AFailingFfmpegIsAnErrorAndNothingIsWritten) {
  const std::string d = test::temp_dir("mp4_fails");
  const FakeFfmpeg fake(d + "/bin", "exit 3\n");
  test::write_text(d + "/scene.json", kScene);
  fs::create_directories(d + "/out");
  const auto r =
      test::run_phellem("turntable " + d + "/scene.json --frames 2 -o " + d + "/out/f_%04d.exr --mp4 " + d + "/out/t.mp4");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(d + "/out/t.mp4: --mp4: ffmpeg failed to encode the frames (exit code 3)"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_empty(d + "/out")) << "frames, the MP4 and temporaries are all withheld";
}

TEST(Mp4Cli, ATerminationSignalWhileEncodingEndsFfmpegToo) {
  const std::string d = test::temp_dir("mp4_signal");
  // The stand-in records its pid and then waits (exec keeps the pid).
  const FakeFfmpeg fake(d + "/bin", "echo $$ > " + d + "/ffmpeg.pid\nexec sleep 60\n");
  test::write_text(d + "/scene.json", kScene);
  fs::create_directories(d + "/out");
  const pid_t pid = test::start_phellem(
      {"turntable", d + "/scene.json", "--frames", "2", "-o", d + "/out/f_%04d.exr", "--mp4", d + "/out/t.mp4", "--quiet"});
  ASSERT_GT(pid, 0);
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(d + "/ffmpeg.pid") && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the pid file is written before exec
  ASSERT_TRUE(fs::exists(d + "/ffmpeg.pid"));
  const pid_t ffmpeg = pid_t(std::stol(test::read_text(d + "/ffmpeg.pid")));
  ASSERT_EQ(kill(ffmpeg, 0), 0) << "the stand-in runs";
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_NE(kill(ffmpeg, 0), 0) << "ffmpeg outlived the run";
  EXPECT_TRUE(fs::is_empty(d + "/out")) << "no frame, MP4 or temporary is left";
}

}  // namespace
}  // namespace phellem

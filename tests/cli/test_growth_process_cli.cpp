// Cambial growth's process hygiene and time (issue 43): TetGen's child process dies with
// `phellem simulate` however that ends (SIGTERM, SIGINT, SIGKILL), and a growth estimated to
// take hours is refused at once, naming its steps and the --time-limit that allows it, while
// with the limit raised it prints its estimate and starts.
#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

using Clock = std::chrono::steady_clock;

// A process's state letter and parent from /proc/PID/stat ('\0' when it does not exist).
struct ProcState {
  char state = '\0';
  pid_t parent = 0;
};

ProcState proc_state(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return {};
  const size_t close = line.rfind(')');  // the command name may hold spaces and parentheses
  if (close == std::string::npos) return {};
  std::istringstream rest(line.substr(close + 1));
  ProcState s;
  rest >> s.state >> s.parent;
  return s;
}

// A live (not zombie) child of `parent`, or 0.
pid_t child_of(pid_t parent) {
  DIR* d = opendir("/proc");
  if (!d) return 0;
  pid_t found = 0;
  while (dirent* e = readdir(d)) {
    const pid_t p = pid_t(std::atol(e->d_name));
    if (p <= 0) continue;
    const ProcState s = proc_state(p);
    if (s.parent == parent && s.state != 'Z' && s.state != '\0') {
      found = p;
      break;
    }
  }
  closedir(d);
  return found;
}

bool gone(pid_t pid) {
  const char s = proc_state(pid).state;
  return s == '\0' || s == 'Z' || s == 'X';  // a zombie has ended (init reaps it when it does)
}

// A sphere of 81920 triangles whose set-up TetGen takes long over (no graded lattice to
// start from: tens of seconds).
constexpr const char* kSlowTetgenScene =
    R"({"objects": [{"type": "mesh", "name": "ball", "procedural": {"shape": "sphere", "triangles": 82000, "radius": 0.5},
        "growth": {"steps": 2, "ring_interval": 0, "tetrahedra": {"lattice": 0}}}]})";

class TetgenChild : public ::testing::TestWithParam<int> {};

TEST_P(TetgenChild, DiesWithPhellem) {
  const int signal = GetParam();
  const std::string dir = test::temp_dir("tetgen_child_" + std::to_string(signal));
  test::write_text(dir + "/scene.json", kSlowTetgenScene);
  const pid_t pid = test::start_phellem({"simulate", dir + "/scene.json", "-o", dir + "/out", "--quiet"}, dir + "/err.txt");
  ASSERT_GT(pid, 0);
  pid_t child = 0;
  int status = 0;
  bool ended = false;
  for (const auto deadline = Clock::now() + std::chrono::seconds(120); Clock::now() < deadline && child == 0;) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      ended = true;
      break;
    }
    child = child_of(pid);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!ended && child == 0) kill(pid, SIGKILL);
  ASSERT_FALSE(ended) << "phellem ended before TetGen's process started: " << test::read_text(dir + "/err.txt");
  ASSERT_GT(child, 0) << "no TetGen process appeared";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // well into TetGen
  ASSERT_FALSE(gone(child)) << "TetGen finished too soon for the test";
  const auto t0 = Clock::now();
  kill(pid, signal);
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
  while (!gone(child) && Clock::now() - t0 < std::chrono::seconds(2)) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const double after = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_TRUE(gone(child)) << "TetGen's process " << child << " outlived phellem by 2 s";
  std::printf("signal %d: TetGen's process gone %.3f s after it was sent\n", signal, after);
  if (!gone(child)) kill(child, SIGKILL);  // the old behaviour: do not leave it running
  EXPECT_EQ(test::leftover_temporaries(dir), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(Signals, TetgenChild, ::testing::Values(SIGTERM, SIGINT, SIGKILL),
                         [](const ::testing::TestParamInfo<int>& i) {
                           return std::string(i.param == SIGTERM ? "Sigterm" : i.param == SIGINT ? "Sigint" : "Sigkill");
                         });

// A log of 20000 triangles (about 10k interface vertices) growing for 100000 steps: hours.
std::string long_growth_scene() {
  return R"({"objects": [{"type": "mesh", "name": "trunk", "procedural": {"shape": "log", "triangles": 20000, "radius": 0.1,
             "height": 0.3}, "growth": {"steps": 100000, "ring_interval": 0}}]})";
}

TEST(GrowthTime, AGrowthOfHoursIsRefusedAtOnceNamingItsStepsAndTheLimit) {
  const std::string dir = test::temp_dir("growth_time_refused");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, long_growth_scene());
  const auto t0 = Clock::now();
  const auto r = test::run_phellem_limited("simulate " + scene + " -o " + dir + "/out", 8192, 30);
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("phellem: error: " + scene + ": /objects/0/growth/steps: the growth of trunk would take about ", 0), 0u)
      << r.output;
  EXPECT_NE(r.output.find("100000 steps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("over the time limit of 1 h"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--time-limit"), std::string::npos) << r.output;
  EXPECT_LT(s, 5.0) << "the refusal should come before any work";
  // A malformed limit is refused as an option.
  const auto bad = test::run_phellem("simulate " + scene + " -o " + dir + "/out --time-limit 5x");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_EQ(bad.output.rfind("phellem: error: <command line>: --time-limit: must be a duration", 0), 0u) << bad.output;
}

TEST(GrowthTime, WithTheLimitRaisedItPrintsTheEstimateAndStarts) {
  const std::string dir = test::temp_dir("growth_time_raised");
  const std::string scene = dir + "/scene.json";
  test::write_text(scene, long_growth_scene());
  const std::string err = dir + "/err.txt";
  const pid_t pid = test::start_phellem({"simulate", scene, "-o", dir + "/out", "--time-limit", "2d"}, err);
  ASSERT_GT(pid, 0);
  std::string text;
  int status = 0;
  bool ended = false;
  for (const auto deadline = Clock::now() + std::chrono::seconds(60); Clock::now() < deadline;) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      ended = true;
      break;
    }
    text = test::read_text(err);
    if (text.find("\n") != std::string::npos && child_of(pid) != 0) break;  // the estimate printed, TetGen started
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!ended) {
    kill(pid, SIGTERM);
    waitpid(pid, &status, 0);
  }
  EXPECT_FALSE(ended) << "it should still be working: " << test::read_text(err);
  text = test::read_text(err);
  EXPECT_EQ(text.rfind("growth of trunk: about ", 0), 0u) << text;
  EXPECT_NE(text.find(" h"), std::string::npos) << "hours expected: " << text;
  EXPECT_NE(text.find("for 100000 steps of ~"), std::string::npos) << text;
  EXPECT_NE(text.find("k interface vertices\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace phellem

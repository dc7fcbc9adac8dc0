// A run killed by SIGTERM, SIGINT or SIGHUP while it writes its outputs removes its temporaries, leaves
// the earlier outputs as they were (never a new EXR beside an old PNG) and dies by the signal.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/test_util.h"

namespace phellem {
namespace {

namespace fs = std::filesystem;

// True once a temporary whose name ends in `ext` exists in `dir`.
bool temporary_with(const std::string& dir, const std::string& ext) {
  for (const std::string& t : test::leftover_temporaries(dir))
    if (t.size() >= ext.size() && t.compare(t.size() - ext.size(), ext.size(), ext) == 0) return true;
  return false;
}

struct Kill {
  int signal;
  const char* when;  // the extension of the temporary whose appearance triggers the signal
};

void PrintTo(const Kill& k, std::ostream* os) { *os << "signal " << k.signal << " at the first " << k.when << " temporary"; }

class InterruptedRun : public ::testing::TestWithParam<Kill> {};

TEST_P(InterruptedRun, LeavesNoTemporaryAndTheEarlierOutputsWhole) {
  const Kill k = GetParam();
  const std::string d = test::temp_dir("interrupted_" + std::to_string(k.signal) + "_" + (k.when + 1));
  test::write_text(d + "/scene.json", R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
                                          "lights": [{"type": "environment", "color": [1, 1, 1]}]})");
  const std::vector<std::string> outputs = {d + "/a.exr", d + "/a.png", d + "/s.json"};
  for (const std::string& f : outputs) test::write_text(f, "old");
  // Large enough that writing the EXR and the PNG takes a while; the signal is sent as soon as
  // the temporary appears.
  const pid_t pid = test::start_phellem({"render", d + "/scene.json", "-o", outputs[0], "--png", outputs[1], "--stats", outputs[2],
                                   "--res", "1600x1200", "--spp", "1", "--threads", "2", "--quiet"});
  ASSERT_GT(pid, 0);
  bool sent = false;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (std::chrono::steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    if (!sent && temporary_with(d, k.when)) {
      kill(pid, k.signal);
      sent = true;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  if (!WIFEXITED(status) && !WIFSIGNALED(status)) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "phellem did not end";
  }
  ASSERT_TRUE(sent) << "the run ended before a " << k.when << " temporary appeared";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == k.signal)
      << "expected death by signal " << k.signal << ", got status " << status;
  EXPECT_EQ(test::leftover_temporaries(d), std::vector<std::string>{});
  // All old, or (a signal during the final renames waits for them) all new: never a mix.
  int old = 0;
  for (const std::string& f : outputs) old += test::read_text(f) == "old";
  EXPECT_TRUE(old == 0 || old == 3) << old << " of 3 outputs are the earlier ones";
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptedRun,
                         ::testing::Values(Kill{SIGTERM, ".exr"}, Kill{SIGTERM, ".png"}, Kill{SIGINT, ".exr"},
                                           Kill{SIGINT, ".png"}, Kill{SIGHUP, ".exr"}, Kill{SIGHUP, ".png"}),
                         [](const ::testing::TestParamInfo<Kill>& i) {
                           const int s = i.param.signal;
                           return std::string(s == SIGTERM ? "Sigterm" : s == SIGINT ? "Sigint" : "Sighup") + "While" +
                                  (std::string(i.param.when) == ".exr" ? "Exr" : "Png");
                         });

}  // namespace
}  // namespace phellem

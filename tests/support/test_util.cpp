#include "tests/support/test_util.h"

#include "util/base64.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>
#include "util/errors.h"

extern char** environ;

namespace phellem::test {
namespace {
// The temporary directories this test process made, removed when it exits (set
// PHELLEM_KEEP_TEST_FILES=1 to keep them for a look).
struct TempDirs {
  std::vector<std::filesystem::path> dirs;
  ~TempDirs() {
    if (std::getenv("PHELLEM_KEEP_TEST_FILES")) return;
    std::error_code ec;
    for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
  }
};
TempDirs& temp_dirs() {
  static TempDirs dirs;
  return dirs;
}
}  // namespace
CommandResult run_command(const std::string& cmd) {
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}
void expect_user_error(const std::function<void()>& load, const std::string& name, const std::string& file,
                       const std::string& where, const std::string& detail) {
  try {
    load();
    ADD_FAILURE() << name << ": accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.file(), file) << name;
    EXPECT_EQ(e.where(), where) << name << ": " << e.what();
    EXPECT_NE(e.detail().find(detail), std::string::npos) << name << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << ": not a UserError: " << e.what();
  }
}

CommandResult run_phellem(const std::string& args) {
  return run_command(std::string(PHELLEM_BINARY) + " " + args + " --quiet 2>&1");
}
CommandResult run_phellem_limited(const std::string& args, int memory_mib, int seconds) {
  return run_command("ulimit -v " + std::to_string(memory_mib * 1024) + " && exec timeout -k 5 " + std::to_string(seconds) + " " +
                     PHELLEM_BINARY + " " + args + " --quiet 2>&1");
}
int start_phellem(const std::vector<std::string>& args, const std::string& err) {
  std::vector<std::string> argv_s = {PHELLEM_BINARY};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, sig);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int e = posix_spawn(&pid, argv[0], &files, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  return e == 0 ? int(pid) : -1;
}

std::string temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("phellem_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  temp_dirs().dirs.push_back(d);
  return d.string();
}
std::string base64(const std::vector<unsigned char>& in) { return phellem::base64(in.data(), in.size()); }

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
std::string lying_hdr(const std::string& path, int width, int height) {
  std::ofstream f(path, std::ios::binary);
  f << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
  f << std::string(64, '\x01');
  return path;
}
std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}
std::vector<std::string> leftover_temporaries(const std::string& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
    if (it->path().filename().string().find(".tmp") != std::string::npos) found.push_back(it->path().string());
  return found;
}
}  // namespace phellem::test

#include "test_util.h"
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
namespace phellem::test {
CommandResult run_phellem(const std::string& args) {
  const std::string cmd = std::string(PHELLEM_BINARY) + " " + args + " --quiet 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}
std::string temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("phellem_test_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}
void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
}

#pragma once
#include <functional>
#include <string>
#include <vector>
namespace phellem::test {
struct CommandResult {
  int exit_code;
  std::string output;
};
// Runs the phellem binary with `args` (shell-quoted by the caller), capturing stderr+stdout.
CommandResult run_phellem(const std::string& args);
// Calls `load`, which must throw a UserError naming `file` and `where` whose detail contains
// `detail`; `name` labels the failures.
void expect_user_error(const std::function<void()>& load, const std::string& name, const std::string& file,
                       const std::string& where, const std::string& detail);
// Runs a shell command line, capturing its standard output (add 2>&1 for stderr too).
CommandResult run_command(const std::string& cmd);
// The same with the address space limited to `memory_mib` MiB and the run to `seconds`
// (exit code 124 when it timed out): for inputs that could make a broken build allocate
// without end or wait for ever.
CommandResult run_phellem_limited(const std::string& args, int memory_mib, int seconds);
// Starts phellem with `args` and returns at once with its pid (−1 when it could not start):
// SIGINT, SIGTERM and SIGHUP at their default action (a test runner may start us with one
// ignored), no signal blocked, stdout to /dev/null and stderr to `err`.
int start_phellem(const std::vector<std::string>& args, const std::string& err = "/dev/null");
std::string temp_dir(const std::string& name);
// Standard base64 (RFC 4648, padded), for data: URIs in test glTF files.
std::string base64(const std::vector<unsigned char>& in);
void write_text(const std::string& path, const std::string& text);
// A Radiance .hdr at `path` whose header claims width × height pixels, followed by a few
// bytes (image size limits are checked from the header); returns `path`.
std::string lying_hdr(const std::string& path, int width, int height);
// The whole file as bytes ("" if it cannot be read).
std::string read_text(const std::string& path);
// Files anywhere under `dir` whose name holds ".tmp": temporaries a run left behind.
std::vector<std::string> leftover_temporaries(const std::string& dir);
}  // namespace phellem::test

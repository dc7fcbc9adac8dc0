#pragma once
#include <string>
namespace phellem::test {
struct CommandResult { int exit_code; std::string output; };
// Runs the phellem binary with `args` (shell-quoted by the caller), capturing stderr+stdout.
CommandResult run_phellem(const std::string& args);
std::string temp_dir(const std::string& name);
void write_text(const std::string& path, const std::string& text);
}

// `phellem compare A B [--scale A=PX_PER_CM] [--albedo A=FILE] [-o report.html] [--json out.json]`
#pragma once

#include <string>
#include <vector>

namespace phellem {

// `args` without the leading "compare". Returns the exit code; UserError escapes to main.
int run_compare(const std::vector<std::string>& args);
std::string compare_usage();

}  // namespace phellem

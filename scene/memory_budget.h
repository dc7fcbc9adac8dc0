// The memory a run may use (75 % of physical memory, --memory-limit, PHELLEM_MEMORY_LIMIT) and
// the check of a MemoryEstimate against it: a scene over budget is refused at the knob of its
// largest part before any stage runs.
#pragma once

#include <string>

#include "scene/memory_estimate.h"

namespace phellem {

struct MemoryBudget {
  double bytes = 0;
  std::string source;  // how it was set, for messages: "75% of the 23.5 GiB of physical memory"
};

// "6G", "6GiB", "512M", "1.5T", "4096" (bytes), "50%" (of physical memory); K, M, G, T are
// powers of 1024. Throws std::invalid_argument.
double parse_memory_size(const std::string& text);
// `option`: the value of --memory-limit (empty: not given), else PHELLEM_MEMORY_LIMIT, else
// kDefaultMemoryShare of physical memory; never more than the address space the process may
// still map under RLIMIT_AS (`ulimit -v`), where allocating more fails in bad_alloc. A bad value
// is a UserError at its option / variable.
MemoryBudget memory_budget(const std::string& option);
inline constexpr double kDefaultMemoryShare = 0.75;

// Throws UserError at the knob of the largest item held at the peak, when the peak exceeds the
// budget.
void check_memory(const MemoryEstimate& estimate, const MemoryBudget& budget);
// The estimate as a table (phellem ... --memory-estimate).
std::string describe(const MemoryEstimate& estimate, const MemoryBudget& budget);
// "9.1 GiB", "640 MiB".
std::string format_bytes(double bytes);

}  // namespace phellem

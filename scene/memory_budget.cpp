#include "scene/memory_budget.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "util/errors.h"
#include "util/memory.h"

namespace phellem {

double parse_memory_size(const std::string& text) {
  size_t used = 0;
  double x = 0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    throw std::invalid_argument(text);
  }
  std::string unit = text.substr(used);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (!(x > 0) || !std::isfinite(x)) throw std::invalid_argument(text);
  if (unit == "%") {
    if (x > 100) throw std::invalid_argument(text);
    return x / 100 * physical_memory();
  }
  static const std::map<std::string, double> units = {{"", 1},
                                                      {"B", 1},
                                                      {"K", 1024.0},
                                                      {"KB", 1024.0},
                                                      {"KIB", 1024.0},
                                                      {"M", 1048576.0},
                                                      {"MB", 1048576.0},
                                                      {"MIB", 1048576.0},
                                                      {"G", 1073741824.0},
                                                      {"GB", 1073741824.0},
                                                      {"GIB", 1073741824.0},
                                                      {"T", 1099511627776.0},
                                                      {"TB", 1099511627776.0},
                                                      {"TIB", 1099511627776.0}};
  auto it = units.find(unit);
  if (it == units.end()) throw std::invalid_argument(text);
  return x * it->second;
}

namespace {

// Under an address-space limit (`ulimit -v`) an allocation beyond it fails (bad_alloc) whatever
// the budget says, so the budget is at most what the process may still map. Conservative: the
// estimates count resident bytes, and the program's own mappings are in both.
MemoryBudget within_address_space(MemoryBudget b) {
  const AddressSpace a = address_space();
  const double left = std::max(0.0, a.limit - a.mapped);
  if (left >= b.bytes) return b;
  return {left, b.source + ", capped at the " + format_bytes(left) + " of address space left under this process's limit of " +
                    format_bytes(a.limit) + " (ulimit -v)"};
}

MemoryBudget configured_budget(const std::string& option) {
  const char* env = std::getenv("PHELLEM_MEMORY_LIMIT");
  const bool from_option = !option.empty();
  if (from_option || (env && *env)) {
    const std::string text = from_option ? option : std::string(env);
    try {
      return {parse_memory_size(text), (from_option ? "--memory-limit " : "PHELLEM_MEMORY_LIMIT=") + text};
    } catch (const std::invalid_argument&) {
      const std::string what = "expected a memory size such as 6G, 512M, 1.5T or 50% (of physical memory), got \"" + text + "\"";
      if (from_option) throw UserError("", "--memory-limit", what);
      throw UserError("", "PHELLEM_MEMORY_LIMIT", what);
    }
  }
  const double physical = physical_memory();
  char source[160];
  std::snprintf(source, sizeof source, "%.0f%% of this machine's %s; --memory-limit or PHELLEM_MEMORY_LIMIT sets another",
                kDefaultMemoryShare * 100, format_bytes(physical).c_str());
  return {kDefaultMemoryShare * physical, source};
}

}  // namespace

MemoryBudget memory_budget(const std::string& option) { return within_address_space(configured_budget(option)); }

std::string format_bytes(double bytes) {
  char buf[64];
  if (bytes >= 1073741824.0 * 0.95)
    std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / 1073741824.0);
  else
    std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / 1048576.0);
  return buf;
}

void check_memory(const MemoryEstimate& estimate, const MemoryBudget& budget) {
  const MemoryMoment& peak = estimate.peak();
  const double total = peak.bytes();
  if (total <= budget.bytes) return;
  const MemoryItem* largest = nullptr;
  for (const auto& i : peak.items)
    if (!i.where.empty() && (!largest || i.bytes > largest->bytes)) largest = &i;
  const std::string allowed = ", more than the " + format_bytes(budget.bytes) + " allowed (" + budget.source + ")";
  if (!largest) throw UserError("", "--memory-limit", "needs about " + format_bytes(total) + " while " + peak.stage + allowed);
  std::string what = "needs about " + format_bytes(largest->bytes) + " for " + largest->what;
  if (largest->bytes < 0.9 * total) what += " (" + format_bytes(total) + " in all while " + peak.stage + ")";
  throw UserError(largest->file, largest->where, what + allowed + "; " + largest->advice);
}

std::string describe(const MemoryEstimate& estimate, const MemoryBudget& budget) {
  std::ostringstream s;
  for (const auto& m : estimate.moments) {
    s << m.stage << ": " << format_bytes(m.bytes()) << "\n";
    for (const auto& i : m.items) {
      char line[32];
      std::snprintf(line, sizeof line, "  %10s  ", format_bytes(i.bytes).c_str());
      s << line << i.what;
      if (!i.where.empty()) s << "  [" << i.where << "]";
      s << "\n";
    }
  }
  const MemoryMoment& peak = estimate.peak();
  s << "peak: about " << format_bytes(peak.bytes()) << " while " << peak.stage << "; allowed: " << format_bytes(budget.bytes)
    << " (" << budget.source << ")\n";
  return s.str();
}

}  // namespace phellem

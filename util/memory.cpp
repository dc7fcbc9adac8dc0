#include "util/memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <limits>
#include <string>

namespace phellem {

double physical_memory() {
  double total = 0;
  std::ifstream in("/proc/meminfo");
  std::string key;
  double value = 0;
  std::string unit;
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemTotal:") {
      total = value * 1024.0;
      break;
    }
  }
  if (!(total > 0)) total = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  // A container's limit (cgroup v2, then v1) when it is smaller.
  for (const char* f : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream c(f);
    double limit = 0;
    if (c >> limit && limit > 0 && limit < total) total = limit;
  }
  return total;
}

AddressSpace address_space() {
  AddressSpace a;
  rlimit r{};
  a.limit = getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY ? double(r.rlim_cur)
                                                                        : std::numeric_limits<double>::infinity();
  std::ifstream statm("/proc/self/statm");  // the first figure: pages mapped
  double pages = 0;
  if (statm >> pages) a.mapped = pages * double(sysconf(_SC_PAGE_SIZE));
  return a;
}

}  // namespace phellem

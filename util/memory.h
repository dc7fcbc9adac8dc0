// This machine's memory, for the limits that bound what a run may allocate.
#pragma once

namespace phellem {

// Physical memory (MemTotal; a smaller cgroup limit wins), in bytes.
double physical_memory();

// The address-space limit of this process (RLIMIT_AS, `ulimit -v`) and what it has mapped
// already, in bytes; limit is +inf without one.
struct AddressSpace {
  double limit = 0, mapped = 0;
};
AddressSpace address_space();

}  // namespace phellem

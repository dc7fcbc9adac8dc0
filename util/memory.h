// This machine's memory, for the limits that bound what a run may allocate.
#pragma once

namespace phellem {

// Physical memory (MemTotal; a smaller cgroup limit wins), in bytes.
double physical_memory();

}  // namespace phellem

// Whether the system lets this process start as many threads as `--threads` asks for. TBB
// starts its workers lazily, inside its own threads, and a worker it cannot start ends the
// process with a signal (seen: SIGSEGV after "Resource temporarily unavailable" under a process
// limit or `ulimit -v`), so the command checks first and refuses with the number it could start.
#pragma once

#include <cstddef>

namespace phellem {

// The stack TBB gives each worker on 64-bit systems (oneTBB's ThreadStackSize).
constexpr size_t kWorkerStackBytes = size_t(4) << 20;

// UserError("", option, ...) unless `threads` - 1 threads with stacks of `stack_bytes` can run
// at once beside this one: they are started, held until all are up, and ended again.
void require_startable_threads(const char* option, int threads, size_t stack_bytes = kWorkerStackBytes);

}  // namespace phellem

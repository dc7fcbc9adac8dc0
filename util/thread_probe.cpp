#include "util/thread_probe.h"

#include <pthread.h>
#include <unistd.h>

#include <cstring>
#include <string>
#include <vector>

#include "util/errors.h"

namespace phellem {

namespace {

// A probe thread: waits until the write end of the pipe closes, then ends.
extern "C" void* wait_for_close(void* fd) {
  char c;
  while (::read(*static_cast<int*>(fd), &c, 1) < 0) {
  }
  return nullptr;
}

}  // namespace

void require_startable_threads(const char* option, int threads, size_t stack_bytes) {
  int fds[2];
  if (threads <= 1 || ::pipe(fds) != 0) return;
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, stack_bytes);
  std::vector<pthread_t> started;
  started.reserve(size_t(threads));
  int err = 0;
  while (int(started.size()) + 1 < threads) {
    pthread_t t;
    if ((err = pthread_create(&t, &attr, wait_for_close, &fds[0])) != 0) break;
    started.push_back(t);
  }
  pthread_attr_destroy(&attr);
  ::close(fds[1]);
  for (pthread_t t : started) pthread_join(t, nullptr);
  ::close(fds[0]);
  if (err != 0)
    throw UserError("", option,
                    "this system cannot run " + std::to_string(threads) + " threads now (" + std::strerror(err) +
                        " after starting " + std::to_string(started.size() + 1) +
                        ", each with a " + std::to_string(stack_bytes >> 20) + " MiB stack); give a smaller " + option);
}

}  // namespace phellem

#include "util/temp_files.h"

#include <limits.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace phellem {

// The registry is a list of slots that only grows (the handler may walk it at any moment, so
// nothing in it is ever freed). A slot's version is odd while it holds a live path; the handler
// reads a path as a seqlock reader and skips it if the version changed meanwhile.
struct Slot {
  std::atomic<unsigned> version{0};
  std::atomic<LiveTempFile::Kind> kind{LiveTempFile::Kind::File};
  size_t capacity = 0;
  std::unique_ptr<std::atomic<char>[]> path;
  Slot* next = nullptr;  // set before the slot is published, never changed
};

namespace {

static_assert(std::atomic<unsigned>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
                  std::atomic<char>::is_always_lock_free && std::atomic<Slot*>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

std::atomic<Slot*> g_slots{nullptr};
std::mutex g_claim;         // claiming and freeing slots; the handler never takes it
std::vector<Slot*> g_free;  // slots free for reuse (under g_claim)

// What a termination signal does now: end the process, wait for a commit, or nothing (the
// process is already ending on another thread).
enum Phase : int { kRunning, kCommitting, kDying };
std::atomic<int> g_phase{kRunning};
std::atomic<int> g_deferred{0};  // a signal that arrived during a commit
std::atomic<int> g_child{0};     // a child process to end first (LiveChild), or 0

Slot* claim(const std::string& path, LiveTempFile::Kind kind) {
  std::lock_guard<std::mutex> lock(g_claim);
  Slot* s = nullptr;
  if (!g_free.empty() && g_free.back()->capacity > path.size()) {
    s = g_free.back();
    g_free.pop_back();
  } else {
    s = new Slot;  // never freed: see Slot
    s->capacity = std::max<size_t>(path.size() + 1, 256);
    s->path.reset(new std::atomic<char>[s->capacity]);
    s->next = g_slots.load();
    g_slots.store(s);
  }
  std::atomic_thread_fence(std::memory_order_release);
  s->kind.store(kind, std::memory_order_relaxed);
  for (size_t i = 0; i <= path.size(); ++i) s->path[i].store(path.c_str()[i], std::memory_order_relaxed);
  return s;
}

// Async-signal-safe: atomics, unlink and rmdir only.
void remove_live(LiveTempFile::Kind kind) {
  char copy[PATH_MAX];
  for (Slot* s = g_slots.load(); s != nullptr; s = s->next) {
    const unsigned v = s->version.load(std::memory_order_acquire);
    if (v % 2 == 0) continue;
    const LiveTempFile::Kind k = s->kind.load(std::memory_order_relaxed);
    size_t n = 0;
    while (n + 1 < sizeof copy && n < s->capacity && (copy[n] = s->path[n].load(std::memory_order_relaxed)) != 0) ++n;
    copy[n] = 0;
    std::atomic_thread_fence(std::memory_order_acquire);
    if (s->version.load(std::memory_order_relaxed) != v || k != kind) continue;
    if (kind == LiveTempFile::Kind::File)
      unlink(copy);
    else
      rmdir(copy);
  }
}

[[noreturn]] void die_by(int sig) {
  if (const int child = g_child.exchange(0); child > 0) {  // kill and waitpid are async-signal-safe
    kill(child, SIGKILL);
    while (waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  remove_live(LiveTempFile::Kind::File);
  remove_live(LiveTempFile::Kind::Folder);  // after the files in them
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, nullptr);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  sigprocmask(SIG_UNBLOCK, &set, nullptr);
  raise(sig);
  _exit(128 + sig);
}

extern "C" void on_termination(int sig) {
  for (;;) {
    int phase = kRunning;
    if (g_phase.compare_exchange_strong(phase, kDying)) die_by(sig);
    if (phase == kDying)
      for (;;) pause();  // another thread is removing the temporaries and ending the process
    // A commit is renaming outputs: it takes the signal when it ends.
    g_deferred.store(sig);
    if (g_phase.load() == kCommitting) return;
    // The commit ended meanwhile and may have missed it: take it back (unless it did not).
    if (g_deferred.exchange(0) == 0) return;
  }
}

}  // namespace

LiveTempFile::LiveTempFile(const std::string& path, Kind kind) {
  if (path.size() + 1 > PATH_MAX) throw std::length_error("temporary path too long: " + path);
  Slot* s = claim(path, kind);
  s->version.fetch_add(1, std::memory_order_release);  // odd: live
  slot_ = s;
}

LiveTempFile& LiveTempFile::operator=(LiveTempFile&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = nullptr;
  }
  return *this;
}

void LiveTempFile::release() noexcept {
  if (slot_ == nullptr) return;
  slot_->version.fetch_add(1, std::memory_order_release);  // even: free
  try {
    std::lock_guard<std::mutex> lock(g_claim);
    g_free.push_back(slot_);
  } catch (...) {
    // Out of memory: the slot is simply not reused.
  }
  slot_ = nullptr;
}

void remove_temp_files_on_termination() {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
    struct sigaction sa {};
    sa.sa_handler = on_termination;
    sigfillset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(sig, &sa, nullptr);
  }
}

LiveChild::LiveChild(int pid) {
  int none = 0;
  if (!g_child.compare_exchange_strong(none, pid)) throw std::logic_error("LiveChild: one at a time");
}

LiveChild::~LiveChild() { g_child.store(0); }

TerminationDeferral::TerminationDeferral() {
  int phase = kRunning;
  if (g_phase.compare_exchange_strong(phase, kCommitting)) return;
  if (phase == kCommitting) throw std::logic_error("TerminationDeferral: one at a time");
  for (;;) pause();  // a signal is ending the process: commit nothing
}

bool TerminationDeferral::signal_pending() const { return g_deferred.load() != 0; }

TerminationDeferral::~TerminationDeferral() {
  g_phase.store(kRunning);
  if (const int sig = g_deferred.exchange(0)) on_termination(sig);
}

}  // namespace phellem

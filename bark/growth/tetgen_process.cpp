#include "bark/growth/tetgen_process.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>

#include "util/temp_files.h"

namespace phellem::bark {

namespace {

constexpr uint64_t kMagic = 0x74657467656e3135ull;  // "tetgen15"

bool write_all(int fd, const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= size_t(w);
  }
  return true;
}

// The child's first act: it must not outlive Phellem (TetGen may run for minutes, or loop until
// its time limit). The kernel kills it when the thread that forked it ends, which is when the
// process ends: that thread waits for the child in tetrahedralize_in_child (or kills it on the
// way out, ChildGuard) and so cannot end before it. A parent that died before the request took
// effect has already left the child with another parent. The termination handler the child
// inherited (util/temp_files.h) would remove the parent's temporaries: the default action
// instead, so a signal sent to the whole process group just ends the child.
void die_with_parent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(6);
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) ::signal(sig, SIG_DFL);
  }
}

// The child: never returns. Exit 0 with the mesh written; 3 with TetGen's error code written.
[[noreturn]] void run_child(int fd, const std::string& switches, tetgenio& in) {
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {  // TetGen prints its own reports ("BUG Report!") even when quiet
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  tetgenio out;
  std::vector<char> sw(switches.begin(), switches.end());
  sw.push_back('\0');
  try {
    tetrahedralize(sw.data(), &in, &out);
  } catch (int code) {
    const int64_t header[2] = {int64_t(kMagic), int64_t(code)};
    write_all(fd, header, sizeof header);
    ::_exit(3);
  } catch (...) {
    ::_exit(4);
  }
  const int64_t header[5] = {int64_t(kMagic), 0, out.numberofpoints, out.numberoftetrahedra, out.numberoftetrahedronattributes};
  bool ok = write_all(fd, header, sizeof header);
  ok = ok && write_all(fd, out.pointlist, sizeof(double) * 3 * size_t(out.numberofpoints));
  ok = ok && write_all(fd, out.tetrahedronlist, sizeof(int) * 4 * size_t(out.numberoftetrahedra));
  ok = ok && write_all(fd, out.tetrahedronattributelist,
                       sizeof(double) * size_t(out.numberoftetrahedronattributes) * size_t(out.numberoftetrahedra));
  ::_exit(ok ? 0 : 5);
}

// Kills and reaps the child unless it was reaped: an exception on the parent's side (out of
// memory while reading the mesh) must not leave TetGen running, nor its forking thread gone
// while it runs.
class ChildGuard {
 public:
  explicit ChildGuard(pid_t pid) : pid_(pid) {
    try {
      live_.emplace(int(pid));  // a termination signal kills it before Phellem dies
    } catch (const std::logic_error&) {
      // Another child is registered (one at a time): the kernel's parent-death signal still ends it.
    }
  }
  ~ChildGuard() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    wait();
  }
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  // Waits for the child's end; its status.
  int wait() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = 0;
    live_.reset();
    return status;
  }

 private:
  pid_t pid_;
  std::optional<LiveChild> live_;
};

}  // namespace

TetgenMesh tetrahedralize_in_child(const std::string& switches, tetgenio& in, double time_limit_s) {
  int fds[2];
  if (::pipe(fds) != 0) throw TetgenFailure(std::string("cannot open a pipe to TetGen: ") + std::strerror(errno));
  // The forking thread holds the standard streams' locks across fork: a stream another thread
  // was writing cannot reach the child locked (or half-updated) for ever. TetGen prints to
  // them on its error paths, even when quiet.
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t parent = ::getpid();
  ::flockfile(stdout);
  ::flockfile(stderr);
  const pid_t pid = ::fork();
  ::funlockfile(stderr);
  ::funlockfile(stdout);
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw TetgenFailure(std::string("cannot start TetGen's process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    die_with_parent(parent);
    ::close(fds[0]);
    run_child(fds[1], switches, in);
  }
  ChildGuard child(pid);
  ::close(fds[1]);
  std::vector<char> bytes;
  char buffer[1 << 16];
  // TetGen may also loop for ever on a degenerate input (a grown interface folded within
  // rounding did): past the time limit the child is killed.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(time_limit_s);
  bool late = false;
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      late = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, int(std::min(left * 1000 + 1, 60000.0)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t r = ::read(fds[0], buffer, sizeof buffer);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    bytes.insert(bytes.end(), buffer, buffer + r);
  }
  ::close(fds[0]);
  if (late) ::kill(pid, SIGKILL);
  const int status = child.wait();
  if (late) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", time_limit_s);
    throw TetgenFailure(std::string("TetGen did not finish within ") + limit + " s", true);
  }
  if (WIFSIGNALED(status))
    throw TetgenFailure("TetGen stopped on signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) +
                        ", an internal assertion)");
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  int64_t header[5] = {0, 0, 0, 0, 0};
  if (bytes.size() >= 2 * sizeof(int64_t)) std::memcpy(header, bytes.data(), std::min(bytes.size(), sizeof header));
  if (code == 3 && header[0] == int64_t(kMagic)) throw TetgenFailure("TetGen error code " + std::to_string(header[1]));
  if (code != 0 || header[0] != int64_t(kMagic) || bytes.size() < sizeof header)
    throw TetgenFailure("TetGen's process ended without a mesh (exit " + std::to_string(code) + ")");
  const int64_t np = header[2], nt = header[3], na = header[4];
  // Sizes from the child are checked against what arrived before anything is allocated.
  const size_t need = sizeof header + sizeof(double) * 3 * size_t(np) + sizeof(int) * 4 * size_t(nt) +
                      sizeof(double) * size_t(na) * size_t(nt);
  if (np < 0 || nt < 0 || na < 1 || na > 16 || bytes.size() != need)
    throw TetgenFailure("TetGen's process sent a malformed mesh");
  TetgenMesh m;
  m.attributes_per_tet = int(na);
  m.points.resize(3 * size_t(np));
  m.tets.resize(4 * size_t(nt));
  m.attributes.resize(size_t(na) * size_t(nt));
  const char* p = bytes.data() + sizeof header;
  std::memcpy(m.points.data(), p, sizeof(double) * m.points.size());
  p += sizeof(double) * m.points.size();
  std::memcpy(m.tets.data(), p, sizeof(int) * m.tets.size());
  p += sizeof(int) * m.tets.size();
  std::memcpy(m.attributes.data(), p, sizeof(double) * m.attributes.size());
  for (int v : m.tets)
    if (v < 0 || v >= np) throw TetgenFailure("TetGen's process sent a tetrahedron with a point out of range");
  return m;
}

}  // namespace phellem::bark

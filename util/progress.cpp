#include "util/progress.h"

#include <unistd.h>

#include <cstdio>

namespace phellem {

bool Progress::terminal_attached() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, long long total, bool enabled)
    : label_(std::move(label)), total_(std::max(1LL, total)), enabled_(enabled && terminal_attached()),
      start_(std::chrono::steady_clock::now()), last_(start_) {
  if (enabled_) draw(0, false);  // the stage shows as soon as it starts
}

Progress::~Progress() { finish(); }

void Progress::advance(long long n) {
  const long long done = (done_ += n);
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw(done, false);
}

void Progress::set_label(std::string label) {
  std::lock_guard<std::mutex> lock(mutex_);
  label_ = std::move(label);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  draw(done_.load(), true);
  std::fputc('\n', stderr);
}

void Progress::draw(long long done, bool final) {
  const double frac = std::min(1.0, double(done) / double(total_));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int width = 30, filled = int(frac * width);
  char bar[width + 1];
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
  bar[width] = 0;
  char eta[32];
  if (final)
    std::snprintf(eta, sizeof eta, "%.1fs", elapsed);
  else if (frac > 0.01)
    std::snprintf(eta, sizeof eta, "ETA %.0fs", elapsed / frac - elapsed);
  else
    std::snprintf(eta, sizeof eta, "ETA --");
  std::fprintf(stderr, "\r%s [%s] %3d%% %s   ", label_.c_str(), bar, int(frac * 100), eta);
  std::fflush(stderr);
}

}  // namespace phellem

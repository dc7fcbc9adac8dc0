// A progress bar with ETA on stderr, only when stderr is a terminal and not --quiet.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace phellem {

class Progress {
 public:
  Progress(std::string label, long long total, bool enabled);
  ~Progress();
  void advance(long long n = 1);
  void finish();
  // Replaces the label (e.g. "fit (best 0.143)"); shown at the next redraw.
  void set_label(std::string label);
  static bool terminal_attached();

 private:
  void draw(long long done, bool final);
  std::string label_;  // guarded by mutex_
  long long total_;
  bool enabled_;
  bool finished_ = false;
  std::atomic<long long> done_{0};
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mutex_;
};

}  // namespace phellem

// The temporary files (and folders) alive in this process, and a handler for SIGTERM, SIGINT
// and SIGHUP that removes them before the signal ends the process: a run killed while it
// writes leaves no temporary behind and its earlier outputs as they were.
#pragma once

#include <string>

namespace phellem {

// Registers `path` as a temporary for as long as this object lives: the handler removes it
// (unlink, or rmdir for a folder, which removes only an empty one). Destroy or release() it
// once the temporary is renamed into place or removed.
class LiveTempFile {
 public:
  enum class Kind { File, Folder };
  LiveTempFile() = default;
  explicit LiveTempFile(const std::string& path, Kind kind = Kind::File);
  ~LiveTempFile() { release(); }
  LiveTempFile(LiveTempFile&& other) noexcept : slot_(other.slot_) { other.slot_ = nullptr; }
  LiveTempFile& operator=(LiveTempFile&& other) noexcept;
  LiveTempFile(const LiveTempFile&) = delete;
  LiveTempFile& operator=(const LiveTempFile&) = delete;
  void release() noexcept;

 private:
  struct Slot* slot_ = nullptr;
};

// While one lives, a termination signal first kills process `pid` (a child writing one of the
// run's temporaries, such as ffmpeg encoding the MP4) and waits for it, so it cannot write a
// temporary after the handler removed it, nor outlive the run. One at a time.
class LiveChild {
 public:
  explicit LiveChild(int pid);
  ~LiveChild();
  LiveChild(const LiveChild&) = delete;
  LiveChild& operator=(const LiveChild&) = delete;
};

// Installs the handler for SIGTERM, SIGINT and SIGHUP (a signal the parent left ignored stays
// ignored). It unlinks the live temporaries, then re-raises the signal with its default action,
// so the exit status still tells which signal ended the process.
void remove_temp_files_on_termination();

// While one lives, a termination signal waits for its end: the renames that commit a run's
// outputs happen all or none. One at a time.
class TerminationDeferral {
 public:
  TerminationDeferral();
  ~TerminationDeferral();
  TerminationDeferral(const TerminationDeferral&) = delete;
  TerminationDeferral& operator=(const TerminationDeferral&) = delete;
  // Whether a termination signal arrived meanwhile: the process ends by it when this goes.
  bool signal_pending() const;
};

}  // namespace phellem

// The outputs of one run, all or none. Checked before any work (each file's folder exists and
// is writable, no file is a folder, no two outputs are the same file, no output is one of the
// run's inputs), written to temporaries beside their targets, and renamed into place together
// by commit() at the end. An OutputSet destroyed before commit() (the run failed) removes its
// temporaries, so the earlier outputs stay as they were; a termination signal removes them too
// (util/temp_files.h).
//
// What an output may be: a new name, or an existing regular file, which is replaced. A symbolic
// link is written through: the temporary goes beside the file the link points to, is renamed
// over it, and the link stays. Anything else (a device such as /dev/full, a FIFO, a socket, a
// link to a missing file) is refused before work starts.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "util/temp_files.h"

namespace phellem {

// Why `name`, taken from a scene (an object's name), cannot name a file inside an output folder,
// or "" when it can: it must be one plain file name that stays in the folder — not empty, no
// '/', no control character, not starting with '.' (which also keeps "." and ".." and the
// run's hidden temporaries out), at most kMaxDerivedNameBytes bytes (suffixes are added).
constexpr size_t kMaxDerivedNameBytes = 200;
std::string file_name_problem(const std::string& name);

class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // A file the run will write, named by `option` in errors: UserError(path, option, ...) unless
  // its folder exists and is writable, it is not a folder and no other output is the same file.
  void expect_file(const std::string& option, const std::string& path);
  // A file the run reads (`option` names it in errors): no output may resolve to it, links
  // followed. Declare inputs before or after the outputs.
  void expect_input(const std::string& option, const std::string& path);
  // A folder the run writes files into: a writable folder, or missing with a writable parent
  // (then made when the first file is staged in it, and removed again if the run fails).
  void expect_folder(const std::string& option, const std::string& path);
  // The temporary to write `path` to now. A file not expected yet is checked as expect_file()
  // checks it; it may lie in an expected folder.
  std::string stage(const std::string& option, const std::string& path);
  // Stages `path` and calls write(temporary). A UserError from the writer is reported at
  // `path` (the target the user named), with the temporaries' names in its message replaced
  // by it.
  void write(const std::string& option, const std::string& path, const std::function<void(const std::string& tmp)>& write);
  // Stages `path` and writes `bytes` to it, every write checked (util/checked_write.h).
  void write_bytes(const std::string& option, const std::string& path, std::string_view bytes);
  // Renames every staged temporary over its target. A failed rename, or a termination signal
  // that arrives meanwhile (it waits for the end), puts every earlier output back first.
  void commit();

 private:
  struct File {
    std::string option, path, key;
    std::string target;  // where the bytes go: `path`, or the file a symbolic link at `path` points to
    std::string tmp;     // empty once renamed into place
    LiveTempFile live;
    bool staged = false;
  };
  struct Folder {
    std::string option, path, key;
    LiveTempFile made;  // registered while it exists only because of this run
    bool made_here = false;
  };
  friend struct OutputSetCommitProbe;  // tests: a signal between two renames
  void commit_with(const std::function<void(size_t renamed)>& after_rename);
  Folder* find_folder(const std::string& key);
  // Checks a file not in the set yet and adds it.
  File& add_file(const std::string& option, const std::string& path, const std::string& key);

  std::vector<File> files_;                          // in the order they are committed
  std::unordered_map<std::string, size_t> file_at_;  // key -> index in files_
  std::vector<Folder> folders_;
  struct Input {
    std::string option, path, key;
  };
  std::vector<Input> inputs_;
  std::set<std::string> cleaned_folders_;  // folders whose stale temporaries are gone (keys)
  bool committed_ = false;
};

}  // namespace phellem

// The outputs of one run, all or none. Checked before any work (each file's folder exists and
// is writable, no file is a folder, no two outputs are the same file), written to temporaries
// beside their targets, and renamed into place together by commit() at the end. An OutputSet
// destroyed before commit() (the run failed) removes its temporaries, so the earlier outputs
// stay as they were; a termination signal removes them too (util/temp_files.h).
#pragma once

#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "util/temp_files.h"

namespace phellem {

class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // A file the run will write, named by `option` in errors: UserError(path, option, ...) unless
  // its folder exists and is writable, it is not a folder and no other output is the same file.
  void expect_file(const std::string& option, const std::string& path);
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
  // Renames every staged temporary over its target (a termination signal waits for the end).
  void commit();

 private:
  struct File {
    std::string option, path, key, tmp;  // tmp: empty once renamed into place
    LiveTempFile live;
    bool staged = false;
  };
  struct Folder {
    std::string option, path, key;
    LiveTempFile made;  // registered while it exists only because of this run
    bool made_here = false;
  };
  Folder* find_folder(const std::string& key);
  // Checks a file not in the set yet and adds it.
  File& add_file(const std::string& option, const std::string& path, const std::string& key);

  std::vector<File> files_;                          // in the order they are committed
  std::unordered_map<std::string, size_t> file_at_;  // key -> index in files_
  std::vector<Folder> folders_;
  bool committed_ = false;
};

}  // namespace phellem

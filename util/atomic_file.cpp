#include "util/atomic_file.h"

#include <unistd.h>

#include <filesystem>

#include "util/errors.h"
#include "util/temp_files.h"

namespace phellem {

namespace fs = std::filesystem;

void ensure_parent_dir(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent))
    throw UserError(path, "output folder",
                    "cannot create " + parent.string() + ": " + (ec ? ec.message() : "a file of that name is in the way"));
}

std::string temp_path_beside(const std::string& path) {
  const fs::path target(path);
  std::string name(1, '.');
  name += target.stem().string();
  name += ".tmp";
  name += std::to_string(getpid());
  name += target.extension().string();
  return (target.parent_path() / name).string();
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  ensure_parent_dir(path);
  const fs::path target(path);
  const fs::path tmp = temp_path_beside(path);
  const LiveTempFile live(tmp.string());  // removed if a signal ends the process meanwhile
  try {
    write(tmp.string());
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    // The reason is the rename's: the removal below must not overwrite it.
    const std::string why = ec.message();
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw UserError(path, "rename", "cannot move the written file into place: " + why);
  }
}

}  // namespace phellem

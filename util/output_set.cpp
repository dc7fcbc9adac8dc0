#include "util/output_set.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/atomic_file.h"
#include "util/errors.h"

namespace phellem {

namespace fs = std::filesystem;

namespace {

// One name per file: absolute, with `.`, `..` and the symbolic links of its existing part resolved.
std::string key_of(const fs::path& path) {
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec);
  if (ec) return path.lexically_normal().string();
  const fs::path canonical = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal().string() : canonical.string();
}

// `path` without a trailing separator ("out/" -> "out").
fs::path trimmed(const std::string& path) {
  fs::path p(path);
  return p.has_filename() || !p.has_parent_path() ? p : p.parent_path();
}

fs::path folder_of(const fs::path& path) {
  const fs::path parent = path.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// UserError(path, option, ...) unless `folder` is a folder this process may write in.
void require_writable_folder(const std::string& path, const std::string& option, const fs::path& folder,
                             const std::string& missing) {
  std::error_code ec;
  const fs::file_status st = fs::status(folder, ec);
  if (st.type() == fs::file_type::not_found) throw UserError(path, option, missing);
  if (ec) throw UserError(path, option, "cannot reach folder " + folder.string() + ": " + ec.message());
  if (!fs::is_directory(st)) throw UserError(path, option, folder.string() + " is not a folder");
  if (access(folder.c_str(), W_OK | X_OK) != 0)
    throw UserError(path, option, "cannot write in folder " + folder.string() + ": " + std::strerror(errno));
}

}  // namespace

OutputSet::~OutputSet() {
  std::error_code ec;
  for (File& f : files_)
    if (f.staged && !f.tmp.empty()) {
      fs::remove(f.tmp, ec);
      f.live.release();
    }
  if (committed_) return;
  for (auto d = folders_.rbegin(); d != folders_.rend(); ++d)
    if (d->made_here) {
      fs::remove(d->path, ec);  // only if empty: a failed run leaves no folder of its own
      d->made.release();
    }
}

OutputSet::Folder* OutputSet::find_folder(const std::string& key) {
  for (Folder& d : folders_)
    if (d.key == key) return &d;
  return nullptr;
}

OutputSet::File& OutputSet::add_file(const std::string& option, const std::string& path, const std::string& key) {
  std::error_code ec;
  if (!fs::path(path).has_filename() || fs::is_directory(path, ec)) throw UserError(path, option, "is a folder, not a file");
  if (const Folder* d = find_folder(key)) throw UserError(path, option, "the same path as the folder of " + d->option);
  const fs::path folder = folder_of(path);
  // A folder the run makes itself need not exist yet.
  if (!find_folder(key_of(folder)) || fs::exists(folder, ec))
    require_writable_folder(path, option, folder, "folder does not exist");
  files_.push_back(File{option, path, key, {}, {}, false});
  file_at_[key] = files_.size() - 1;
  return files_.back();
}

void OutputSet::expect_file(const std::string& option, const std::string& path) {
  const std::string key = key_of(path);
  if (const auto it = file_at_.find(key); it != file_at_.end()) {
    const std::string& other = files_[it->second].option;
    throw UserError(path, option, other == option ? "named twice by " + option : "the same file as " + other);
  }
  add_file(option, path, key);
}

void OutputSet::expect_folder(const std::string& option, const std::string& path) {
  const fs::path p = trimmed(path);
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);
  if (st.type() != fs::file_type::not_found && !ec) {
    if (!fs::is_directory(st)) throw UserError(path, option, "is a file, not a folder");
    require_writable_folder(path, option, p, "folder does not exist");
  } else {
    require_writable_folder(path, option, folder_of(p), "parent folder does not exist");
  }
  const std::string key = key_of(p);
  if (const auto it = file_at_.find(key); it != file_at_.end())
    throw UserError(path, option, "the same path as the file of " + files_[it->second].option);
  folders_.push_back(Folder{option, path, key, {}, false});
}

void OutputSet::write(const std::string& option, const std::string& path,
                      const std::function<void(const std::string& tmp)>& write) {
  const std::string tmp = stage(option, path);
  try {
    write(tmp);
  } catch (const UserError& e) {
    // Writers that write atomically themselves use a temporary of the temporary.
    std::string detail = e.detail();
    for (const std::string& name : {temp_path_beside(tmp), tmp})
      for (size_t at = detail.find(name); at != std::string::npos; at = detail.find(name, at + path.size()))
        detail.replace(at, name.size(), path);
    throw UserError(path, e.where(), detail);
  }
}

std::string OutputSet::stage(const std::string& option, const std::string& path) {
  const std::string key = key_of(path);
  File* f = nullptr;
  if (const auto it = file_at_.find(key); it == file_at_.end()) {
    f = &add_file(option, path, key);
  } else {
    f = &files_[it->second];
    if (f->option != option) throw UserError(path, option, "the same file as " + f->option);
    if (f->staged) throw UserError(path, option, "written twice in one run (two outputs of " + option + " have this name)");
  }
  // An expected folder that does not exist yet is made now, registered first so a signal
  // removes it with the temporaries.
  const fs::path folder = folder_of(path);
  std::error_code ec;
  if (Folder* d = find_folder(key_of(folder)); d != nullptr && !fs::exists(folder, ec)) {
    LiveTempFile made(folder.string(), LiveTempFile::Kind::Folder);
    if (!fs::create_directory(folder, ec) && ec) throw UserError(d->path, d->option, "cannot make the folder: " + ec.message());
    d->made = std::move(made);
    d->made_here = true;
  }
  f->tmp = temp_path_beside(path);
  f->live = LiveTempFile(f->tmp);
  f->staged = true;
  return f->tmp;
}

void OutputSet::commit() {
  std::error_code ec;
  for (const File& f : files_)
    if (f.staged && fs::is_directory(f.path, ec)) throw UserError(f.path, f.option, "is a folder, not a file");
  {
    const TerminationDeferral hold;
    for (File& f : files_) {
      if (!f.staged || f.tmp.empty()) continue;
      fs::rename(f.tmp, f.path, ec);
      if (ec) throw UserError(f.path, f.option, "cannot write: " + ec.message());
      f.tmp.clear();
      f.live.release();
    }
  }
  for (Folder& d : folders_) d.made.release();
  committed_ = true;
}

}  // namespace phellem

#include "util/output_set.h"

#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/atomic_file.h"
#include "util/checked_write.h"
#include "util/errors.h"
#include "util/input_file.h"

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

// Where the bytes of output `path` go: `path` itself, or the file a symbolic link there points
// to. UserError unless that is a new name or a regular file.
std::string output_target(const std::string& option, const std::string& path) {
  std::error_code ec;
  std::string target = path;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    const fs::path resolved = fs::canonical(path, ec);
    if (ec)
      throw UserError(path, option,
                      "is a symbolic link to a missing file; an output is a new name, a regular file or a link to one");
    target = resolved.string();
  }
  // (A status that cannot be read, e.g. a path too long, is left to the checks that follow.)
  struct stat st;
  if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw UserError(path, option,
                    std::string("is ") + file_kind(st.st_mode) + (target == path ? "" : " (through a symbolic link)") +
                        "; an output is a new name, a regular file or a link to one");
  return target;
}

// UserError unless the temporary of `target` can be named on Linux: a path of at most
// PATH_MAX - 1 bytes and a file name of at most NAME_MAX bytes.
void require_nameable(const std::string& option, const std::string& path, const std::string& target) {
  const std::string tmp = temp_path_beside(target);
  const size_t name = fs::path(tmp).filename().string().size(), extra = tmp.size() - target.size();
  if (tmp.size() >= PATH_MAX)
    throw UserError(path, option,
                    "the path is " + std::to_string(target.size()) + " bytes long; at most " +
                        std::to_string(PATH_MAX - 1 - extra) + " (the run writes a temporary name beside it first)");
  if (name > NAME_MAX)
    throw UserError(path, option,
                    "the file name is " + std::to_string(fs::path(target).filename().string().size()) + " bytes long; at most " +
                        std::to_string(NAME_MAX - extra) + " (the run writes a temporary name beside it first)");
}

// The process id in a temporary's name as temp_path_beside() makes it, ".NAME.tmpPID.EXT" (a
// temporary's temporary: "..NAME.tmpPID.tmpPID.EXT"), or 0 for any other name.
pid_t temporary_owner(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return 0;
  for (size_t at = name.find(".tmp", 1); at != std::string::npos; at = name.find(".tmp", at + 1)) {
    size_t end = at + 4;
    while (end < name.size() && end - at - 4 < 10 && name[end] >= '0' && name[end] <= '9') ++end;
    const bool ends = end == name.size() || name[end] == '.';
    if (end > at + 4 && end - at - 4 < 10 && ends && at > 1) return pid_t(std::stol(name.substr(at + 4, end - at - 4)));
  }
  return 0;
}

// Removes from `folder` the temporaries that runs killed by SIGKILL left behind: regular files
// named as temp_path_beside() names them whose process is gone. Temporaries of live processes
// and every other file stay.
void remove_stale_temporaries(const fs::path& folder) {
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t pid = temporary_owner(it->path().filename().string());
    if (pid <= 0 || pid == getpid() || kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    if (fs::is_regular_file(fs::symlink_status(it->path(), ignored))) fs::remove(it->path(), ignored);
  }
}

}  // namespace

std::string file_name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name[0] == '.') return "starts with '.'";
  if (name.size() > kMaxDerivedNameBytes)
    return "is " + std::to_string(name.size()) + " bytes long; at most " + std::to_string(kMaxDerivedNameBytes);
  for (const char c : name) {
    if (c == '/') return "holds a '/'";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) return "holds a control character";
  }
  return "";
}

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
  for (const Input& in : inputs_)
    if (in.key == key) throw UserError(path, option, "is the input " + in.option + " names; an output must not replace an input");
  require_nameable(option, path, path);
  const std::string target = output_target(option, path);
  if (target != path) require_nameable(option, path, target);
  const fs::path folder = folder_of(target);
  // A folder the run makes itself need not exist yet.
  if (!find_folder(key_of(folder)) || fs::exists(folder, ec))
    require_writable_folder(path, option, folder, "folder does not exist");
  files_.push_back(File{option, path, key, target, {}, {}, false});
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

void OutputSet::expect_input(const std::string& option, const std::string& path) {
  const std::string key = key_of(path);
  if (const auto it = file_at_.find(key); it != file_at_.end())
    throw UserError(files_[it->second].path, files_[it->second].option,
                    "is the input " + option + " names; an output must not replace an input");
  inputs_.push_back(Input{option, path, key});
}

void OutputSet::write_bytes(const std::string& option, const std::string& path, std::string_view bytes) {
  const std::string tmp = stage(option, path);
  write_file_checked(path, tmp, bytes);
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
  if (const fs::path in = folder_of(fs::path(f->target)); cleaned_folders_.insert(key_of(in)).second) remove_stale_temporaries(in);
  f->tmp = temp_path_beside(f->target);
  f->live = LiveTempFile(f->tmp);
  f->staged = true;
  return f->tmp;
}

void OutputSet::commit() { commit_with({}); }

void OutputSet::commit_with(const std::function<void(size_t renamed)>& after_rename) {
  std::error_code ec;
  for (const File& f : files_)
    if (f.staged && fs::is_directory(f.target, ec)) throw UserError(f.path, f.option, "is a folder, not a file");
  const TerminationDeferral hold;
  // Each replaced target is kept as a hard link until every rename is done, so that a failed
  // rename, or a termination signal that arrives meanwhile, puts back every earlier output.
  struct Replaced {
    std::string target, saved;  // saved: "" for a target that did not exist
    LiveTempFile live;          // a SIGKILL leaves `saved` as a stale temporary for the next run
  };
  std::vector<Replaced> done;
  bool restorable = true;  // false once a replaced target could not be kept (no hard links there)
  // Puts the earlier outputs back if it can, and drops the kept links in any case.
  auto restore = [&] {
    for (auto r = done.rbegin(); r != done.rend(); ++r) {
      std::error_code ignored;
      if (!restorable)
        fs::remove(r->saved, ignored);
      else if (r->saved.empty())
        fs::remove(r->target, ignored);
      else
        fs::rename(r->saved, r->target, ignored);
    }
  };
  for (File& f : files_) {
    if (!f.staged || f.tmp.empty()) continue;
    Replaced r{f.target, "", {}};
    bool kept = true;
    if (fs::exists(fs::symlink_status(f.target, ec))) {
      r.saved = temp_path_beside(fs::path(f.target).replace_extension(".kept" + fs::path(f.target).extension().string()).string());
      r.live = LiveTempFile(r.saved);
      kept = ::link(f.target.c_str(), r.saved.c_str()) == 0;
      if (!kept) r.saved.clear();
    }
    fs::rename(f.tmp, f.target, ec);
    if (ec) {
      const std::string why = ec.message();
      if (kept && !r.saved.empty()) fs::remove(r.saved, ec);  // this target was not replaced
      restore();
      throw UserError(f.path, f.option, "cannot move the written file into place: " + why +
                                            (restorable ? "; the earlier outputs are as they were" : ""));
    }
    restorable = restorable && kept;
    f.tmp.clear();
    f.live.release();
    done.push_back(std::move(r));
    if (after_rename) after_rename(done.size());
  }
  if (hold.signal_pending()) {
    restore();  // the signal ends the process when `hold` goes: with the earlier outputs if it could
    return;
  }
  for (Replaced& r : done)
    if (!r.saved.empty()) fs::remove(r.saved, ec);
  for (Folder& d : folders_) d.made.release();
  committed_ = true;
}

}  // namespace phellem

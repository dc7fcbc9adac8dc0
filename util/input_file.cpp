#include "util/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "util/errors.h"

namespace phellem {

const char* file_kind(unsigned mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

namespace {

constexpr const char* kMissing = "does not exist";

// `named`: the path as the message shows it ("" when the error names the file already).
std::optional<std::string> message(const std::string& path, const std::string& named, const std::string& kind) {
  const auto why = input_file_problem(path);
  if (!why) return std::nullopt;
  if (*why == kMissing) return named.empty() ? std::string("file not found") : "file not found: " + named;
  return (named.empty() ? "" : named + " ") + *why + "; " + kind + " is read from a regular file";
}

}  // namespace

std::optional<std::string> input_file_problem(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return std::string(kMissing);
    return std::string("cannot be opened: ") + std::strerror(errno);
  }
  if (S_ISREG(st.st_mode)) return std::nullopt;
  if (S_ISDIR(st.st_mode)) return std::string("is a folder");
  return std::string("is not a regular file (") + file_kind(st.st_mode) + ")";
}

std::optional<std::string> input_file_message(const std::string& path, const std::string& kind) {
  return message(path, printable(path), kind);
}

void require_input_file(const std::string& path, const std::string& file, const std::string& where, const std::string& kind) {
  if (auto m = message(path, path == file ? std::string() : printable(path), kind)) throw UserError(file, where, *m);
}

}  // namespace phellem

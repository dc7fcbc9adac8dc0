#include "util/cache_dir.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "util/atomic_file.h"
#include "util/input_file.h"

namespace phellem {

namespace fs = std::filesystem;

namespace {

// Whether `file` is a regular file whose bytes are `bytes`, compared in full: a cache entry
// is never trusted on its name alone.
bool holds_bytes(const fs::path& file, std::span<const unsigned char> bytes) {
  if (input_file_problem(file.string())) return false;
  std::error_code ec;
  if (fs::file_size(file, ec) != bytes.size() || ec) return false;
  std::ifstream in(file, std::ios::binary);
  std::vector<char> chunk(size_t(1) << 16);
  for (size_t done = 0; done < bytes.size();) {
    in.read(chunk.data(), std::streamsize(std::min(chunk.size(), bytes.size() - done)));
    const auto n = size_t(std::max<std::streamsize>(in.gcount(), 0));
    if (n == 0 || std::memcmp(chunk.data(), bytes.data() + done, n) != 0) return false;
    done += n;
  }
  return in.peek() == std::char_traits<char>::eof();
}

[[noreturn]] void write_failed(const std::string& entry, int error, const Location& where) {
  throw UserError(where.file, where.path,
                  "write: cannot write " + entry + " in the texture cache: " + std::strerror(error) +
                      " (make room on its disk, or set XDG_CACHE_HOME to a folder with room)");
}

// Writes `bytes` to `tmp`, checking every write and the close (a full disk fails either).
void write_bytes(const std::string& tmp, std::span<const unsigned char> bytes, const std::string& entry,
                 const Location& where) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) write_failed(entry, errno, where);
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      write_failed(entry, error, where);
    }
    done += size_t(n);
  }
  if (::close(fd) != 0) write_failed(entry, errno, where);
}

}  // namespace

std::string texture_cache_dir() {
  fs::path dir;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    dir = fs::path(x) / "phellem" / "textures";
  else if (const char* h = std::getenv("HOME"); h && *h)
    dir = fs::path(h) / ".cache" / "phellem" / "textures";
  else
    dir = fs::temp_directory_path() / "phellem-textures";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    dir = fs::temp_directory_path() / "phellem-textures";
    fs::create_directories(dir, ec);
  }
  return dir.string();
}

std::string cache_entry_with_bytes(const std::string& name, std::span<const unsigned char> bytes, const Location& where) {
  const fs::path entry = fs::path(texture_cache_dir()) / name;
  if (holds_bytes(entry, bytes)) return entry.string();
  std::error_code ec;
  if (fs::is_directory(entry, ec)) fs::remove(entry, ec);  // an empty folder in the way; rename replaces files
  write_atomically(entry.string(), [&](const std::string& tmp) { write_bytes(tmp, bytes, entry.string(), where); });
  return entry.string();
}

}  // namespace phellem

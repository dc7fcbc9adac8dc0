#include "util/cache_dir.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "util/atomic_file.h"
#include "util/checked_write.h"
#include "util/errors.h"
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

// Writes `bytes` to `tmp` with every write checked (a full disk fails it), reported at the
// glTF's image that the entry caches.
void write_bytes(const std::string& tmp, std::span<const unsigned char> bytes, const std::string& entry,
                 const Location& where) {
  try {
    write_file_checked(entry, tmp, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } catch (const UserError& e) {
    throw UserError(where.file, where.path,
                    "write: cannot write " + entry + " in the texture cache: " + e.detail() +
                        " (make room on its disk, or set XDG_CACHE_HOME to a folder with room)");
  }
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

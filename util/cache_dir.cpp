#include "util/cache_dir.h"

#include <cstdlib>
#include <filesystem>

namespace phellem {

namespace fs = std::filesystem;

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

}  // namespace phellem

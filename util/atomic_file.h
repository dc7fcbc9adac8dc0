// Atomic outputs: write to a temporary name in the target's folder, rename when complete,
// remove the temporary on failure. A failed run leaves earlier outputs untouched.
#pragma once

#include <functional>
#include <string>

namespace phellem {

// Calls write(tmp_path); on success renames tmp_path to `path`. The temporary keeps the
// target's extension so format-by-extension writers (OpenImageIO) still work.
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp)>& write);

// The temporary name write_atomically and OutputSet use for `path`: hidden, beside it, with the
// process id and the target's extension: DIR/.NAME.tmpPID.EXT.
std::string temp_path_beside(const std::string& path);

// Ensures the folder of `path` exists; UserError naming the path if it cannot be made.
void ensure_parent_dir(const std::string& path);

}  // namespace phellem

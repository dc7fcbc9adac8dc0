// Where converted textures are cached between runs ($XDG_CACHE_HOME/phellem/textures,
// ~/.cache/phellem/textures, or a temporary folder), and the entries that hold given bytes.
#pragma once

#include <span>
#include <string>

#include "util/errors.h"

namespace phellem {

std::string texture_cache_dir();

// The path of the texture cache's file `name`, holding exactly `bytes` (an image a glTF file
// embeds, for readers that take a file name). An existing entry is used only when its bytes
// are `bytes`; one that holds anything else (truncated by a run that ran out of disk space,
// or not a regular file) is written again. Writes go to a temporary beside the entry, every
// write and the close checked, and are renamed into place (util/atomic_file.h), so an entry
// is never seen half written. Throws UserError(where.file, where.path, "write: ...") when the
// entry cannot be written.
std::string cache_entry_with_bytes(const std::string& name, std::span<const unsigned char> bytes, const Location& where);

}  // namespace phellem

// Where converted textures are cached between runs ($XDG_CACHE_HOME/phellem/textures,
// ~/.cache/phellem/textures, or a temporary folder).
#pragma once

#include <string>

namespace phellem {

std::string texture_cache_dir();

}  // namespace phellem

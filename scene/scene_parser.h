// Parse and validate a scene file (docs/scene-format.md) into a SceneDesc.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene_desc.h"

namespace phellem {

// The largest scene file read (64 MiB): a scene names its meshes and images, it does not hold them.
constexpr uint64_t kMaxSceneFileBytes = uint64_t(64) << 20;

// Reads and parses a scene file; every problem is a UserError naming the file and JSON path.
// Only a regular file (or a symbolic link to one) of at most kMaxSceneFileBytes is read.
SceneDesc load_scene_file(const std::string& path);

// Parses scene JSON text. `file` names it in messages; relative paths resolve against base_dir.
SceneDesc parse_scene(const std::string& text, const std::string& file, const std::filesystem::path& base_dir);

// The embedded default scene: a bark-textured trunk on a ground plane under daylight.
SceneDesc default_scene();
const char* default_scene_text();

}  // namespace phellem

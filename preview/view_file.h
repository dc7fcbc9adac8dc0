// The preview's camera key (issue 23): the scene with the window's camera in place of its own,
// written beside the scene as <stem>_view.json (relative paths in it stay valid), or as
// ./default_view.json for the embedded default scene, so `phellem render` renders exactly
// the view on screen. Every other key of the scene is kept as it was.
#pragma once

#include <string>

#include "scene/scene_desc.h"

namespace phellem::preview {

// `scene_path` empty: the embedded default scene. Returns the file written; throws
// std::runtime_error (or a UserError for an unreadable scene) when it cannot.
std::string write_view_scene(const std::string& scene_path, const CameraDesc& camera);

}  // namespace phellem::preview

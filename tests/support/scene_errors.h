// The message of the UserError a scene's JSON text raises, or "<no error>"; or where it
// points, for a scene read as if from `file` in `dir`, or "(accepted)".
#pragma once

#include <string>

#include "scene/scene_parser.h"
#include "util/errors.h"

namespace phellem::test {

inline std::string error_of(const std::string& json) {
  try {
    parse_scene(json, "scene.json", ".");
  } catch (const UserError& e) {
    return e.what();
  }
  return "<no error>";
}

inline std::string where_refused(const std::string& json, const std::string& file, const std::string& dir) {
  try {
    parse_scene(json, file, dir);
  } catch (const UserError& e) {
    return e.where();
  }
  return "(accepted)";
}

}  // namespace phellem::test

// The message of the UserError a scene's JSON text raises, or "<no error>".
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

}  // namespace phellem::test

#include "preview/view_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "scene/scene_parser.h"
#include "util/atomic_file.h"
#include "util/checked_write.h"
#include "util/errors.h"

namespace phellem::preview {

std::string write_view_scene(const std::string& scene_path, const CameraDesc& c) {
  std::string text;
  if (scene_path.empty()) {
    text = default_scene_text();
  } else {
    std::ifstream in(scene_path, std::ios::binary);
    if (!in) throw UserError(scene_path, "", "cannot read the scene again to write its view");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  nlohmann::json j = nlohmann::json::parse(text);
  nlohmann::json& cam = j["camera"];
  cam["position"] = {c.position.x(), c.position.y(), c.position.z()};
  cam["look_at"] = {c.look_at.x(), c.look_at.y(), c.look_at.z()};
  cam["up"] = {c.up.x(), c.up.y(), c.up.z()};
  cam["fov_deg"] = c.fov_deg;
  const std::filesystem::path p(scene_path);
  const std::string out = scene_path.empty() ? "default_view.json" : (p.parent_path() / (p.stem().string() + "_view.json")).string();
  const std::string bytes = j.dump(2) + "\n";
  write_atomically(out, [&](const std::string& tmp) { write_file_checked(out, tmp, bytes); });
  return out;
}

}  // namespace phellem::preview

#include "preview/shaders.h"

#include <map>
#include <stdexcept>

namespace phellem::preview {

// Generated from shaders/*.glsl (cmake/shader_sources.cmake).
const std::map<std::string, std::string>& embedded_shader_files();

const std::string& shader_file(const std::string& name) {
  const auto& files = embedded_shader_files();
  const auto it = files.find(name);
  if (it == files.end()) throw std::logic_error("no shader file " + name + " embedded");
  return it->second;
}

std::vector<std::string> stage_files(Stage s) {
  switch (s) {
    case Stage::Vertex:
      return {"common.glsl", "bark.vert"};
    case Stage::TessControl:
      return {"common.glsl", "bark.tesc"};
    case Stage::TessEvaluation:
      return {"common.glsl", "noise.glsl", "crack_profile.glsl", "fracture_field.glsl", "displacement_map.glsl", "bark.tese"};
    case Stage::Fragment:
      return {"common.glsl", "noise.glsl", "fracture_field.glsl", "bark_tints.glsl", "bark.frag"};
  }
  return {};
}

std::string bark_defines(int bark_kind, bool tints, bool image_displacement) {
  return "#define BARK_KIND " + std::to_string(bark_kind) + "\n#define BARK_TINTS " + (tints ? "1" : "0") +
         "\n#define IMAGE_DISPLACEMENT " + (image_displacement ? "1" : "0") + "\n";
}

std::string stage_source(Stage s, const std::string& defines) {
  std::string src = "#version 450 core\n" + defines;
  for (const auto& f : stage_files(s)) src += "#line 1\n" + shader_file(f) + "\n";
  return src;
}

std::string screen_source(Stage s, const std::string& fragment_file) {
  return "#version 450 core\n#line 1\n" + shader_file(s == Stage::Vertex ? "background.vert" : fragment_file) + "\n";
}

const char* stage_extension(Stage s) {
  switch (s) {
    case Stage::Vertex:
      return "vert";
    case Stage::TessControl:
      return "tesc";
    case Stage::TessEvaluation:
      return "tese";
    case Stage::Fragment:
      return "frag";
  }
  return "";
}

}  // namespace phellem::preview

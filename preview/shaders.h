// The preview's GLSL (the repository's top-level shaders/), embedded in the program at build
// time so `phellem preview` needs no files beside it. GLSL has no #include: each stage is the
// version line, the shared files and the stage's own file, in that order; the same
// assembly is what the offline glslangValidator check validates.
#pragma once

#include <string>
#include <vector>

namespace phellem::preview {

enum class Stage { Vertex, TessControl, TessEvaluation, Fragment };

// The text of one file of shaders/ (e.g. "noise.glsl"); throws std::logic_error if absent.
const std::string& shader_file(const std::string& name);
// The names of the files one stage is assembled from, in order.
std::vector<std::string> stage_files(Stage s);
// The whole source of a stage, starting with "#version 450 core" and the variant's `defines`
// (e.g. "#define BARK_KIND 1\n", shaders/common.glsl).
std::string stage_source(Stage s, const std::string& defines = "");
// The defines of a variant of the bark program: its bark kind, whether stress bark is tinted,
// whether an image displacement adds to the bark's offset.
std::string bark_defines(int bark_kind, bool tints, bool image_displacement = false);
// A full-screen pass: background.vert and the given fragment file (background.frag, overlay.frag).
std::string screen_source(Stage s, const std::string& fragment_file);
// glslangValidator's file extension for a stage (.vert, .tesc, .tese, .frag).
const char* stage_extension(Stage s);

}  // namespace phellem::preview

#include "preview/gl_program.h"

#include <stdexcept>
#include <vector>

#include "preview/shaders.h"

namespace phellem::preview {

namespace {

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::Vertex:
      return "vertex";
    case Stage::TessControl:
      return "tessellation control";
    case Stage::TessEvaluation:
      return "tessellation evaluation";
    case Stage::Fragment:
      return "fragment";
  }
  return "";
}

GLenum gl_stage(Stage s) {
  switch (s) {
    case Stage::Vertex:
      return GL_VERTEX_SHADER;
    case Stage::TessControl:
      return GL_TESS_CONTROL_SHADER;
    case Stage::TessEvaluation:
      return GL_TESS_EVALUATION_SHADER;
    case Stage::Fragment:
      return GL_FRAGMENT_SHADER;
  }
  return 0;
}

GLuint compile(Stage s, const std::string& src) {
  const GLuint sh = glCreateShader(gl_stage(s));
  const char* text = src.c_str();
  glShaderSource(sh, 1, &text, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::max(len, 1)), '\0');
    glGetShaderInfoLog(sh, len, nullptr, log.data());
    glDeleteShader(sh);
    throw std::runtime_error(std::string("the preview's ") + stage_name(s) + " shader does not compile: " + log);
  }
  return sh;
}

}  // namespace

GlProgram::GlProgram(const std::string& defines, const std::vector<std::string>& feedback_varyings) {
  build(defines, feedback_varyings);
}

GlProgram::GlProgram(ScreenTag, const std::string& fragment_file) {
  link({compile(Stage::Vertex, screen_source(Stage::Vertex, fragment_file)),
        compile(Stage::Fragment, screen_source(Stage::Fragment, fragment_file))},
       {});
}

std::unique_ptr<GlProgram> GlProgram::screen(const std::string& fragment_file) {
  return std::unique_ptr<GlProgram>(new GlProgram(ScreenTag{}, fragment_file));
}

void GlProgram::build(const std::string& defines, const std::vector<std::string>& varyings) {
  std::vector<GLuint> shaders;
  for (Stage s : {Stage::Vertex, Stage::TessControl, Stage::TessEvaluation, Stage::Fragment})
    shaders.push_back(compile(s, stage_source(s, defines)));
  link(shaders, varyings);
}

void GlProgram::link(const std::vector<GLuint>& shaders, const std::vector<std::string>& varyings) {
  id_ = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(id_, s);
  if (!varyings.empty()) {
    std::vector<const char*> names;
    for (const auto& v : varyings) names.push_back(v.c_str());
    glTransformFeedbackVaryings(id_, GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
  }
  glLinkProgram(id_);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(std::max(len, 1)), '\0');
    glGetProgramInfoLog(id_, len, nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error("the preview's shaders do not link: " + log);
  }
}

GlProgram::~GlProgram() {
  if (id_) glDeleteProgram(id_);
}

}  // namespace phellem::preview

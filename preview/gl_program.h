// A linked GLSL program of the preview's four stages (preview/shaders.h). Compile and link
// errors are internal failures (the shaders ship with the program): std::runtime_error with
// the driver's log and the stage's name.
#pragma once

#include <epoxy/gl.h>

#include <memory>
#include <string>
#include <vector>

#include "util/math.h"

namespace phellem::preview {

class GlProgram {
 public:
  // The bark program (vertex, tessellation control and evaluation, fragment) of the variant
  // `defines` (preview/shaders.h bark_defines), with transform feedback capturing `varyings`
  // when any (rasterization then discarded by the caller).
  explicit GlProgram(const std::string& defines, const std::vector<std::string>& feedback_varyings = {});
  // A full-screen pass (vertex and fragment stages only): "background.frag" or "overlay.frag".
  static std::unique_ptr<GlProgram> screen(const std::string& fragment_file);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  void use() const { glUseProgram(id_); }
  GLint location(const char* name) const { return glGetUniformLocation(id_, name); }
  void set(const char* name, int v) const { glProgramUniform1i(id_, location(name), v); }
  void set(const char* name, unsigned v) const { glProgramUniform1ui(id_, location(name), v); }
  void set(const char* name, float v) const { glProgramUniform1f(id_, location(name), v); }
  void set(const char* name, const Vec2f& v) const { glProgramUniform2f(id_, location(name), v.x(), v.y()); }
  void set(const char* name, const Vec3f& v) const { glProgramUniform3f(id_, location(name), v.x(), v.y(), v.z()); }
  void set(const char* name, const Eigen::Vector3i& v) const { glProgramUniform3i(id_, location(name), v.x(), v.y(), v.z()); }
  void set(const char* name, const Eigen::Matrix4f& m) const {
    glProgramUniformMatrix4fv(id_, location(name), 1, GL_FALSE, m.data());
  }

 private:
  struct ScreenTag {};
  GlProgram(ScreenTag, const std::string& fragment_file);
  void build(const std::string& defines, const std::vector<std::string>& feedback_varyings);
  void link(const std::vector<GLuint>& shaders, const std::vector<std::string>& feedback_varyings);
  GLuint id_ = 0;
};

}  // namespace phellem::preview

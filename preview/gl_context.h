// An OpenGL 4.5 core context without a window (issue 23): EGL's surfaceless platform, which
// Mesa's llvmpipe provides on machines with no GPU and no display (CI). Rendering goes to
// framebuffer objects. The context is current on the creating thread for its lifetime.
#pragma once

#include <memory>
#include <string>

namespace phellem::preview {

class HeadlessGl {
 public:
  // nullptr, with the reason in `why`, when no OpenGL 4.5 core context can be made.
  static std::unique_ptr<HeadlessGl> create(std::string* why);
  ~HeadlessGl();
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  int max_tessellation_level() const;
  // The largest frame the preview can draw into: the smaller of the texture, renderbuffer and
  // viewport limits.
  int max_framebuffer_size() const;

 private:
  HeadlessGl() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace phellem::preview

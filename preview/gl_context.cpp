#include "preview/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>

namespace phellem::preview {

std::unique_ptr<HeadlessGl> HeadlessGl::create(std::string* why) {
  auto fail = [&](const std::string& w) -> std::unique_ptr<HeadlessGl> {
    if (why) *why = w;
    return nullptr;
  };
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
    return fail("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
    return fail("eglInitialize failed on the surfaceless platform");
  std::unique_ptr<HeadlessGl> gl(new HeadlessGl());  // private constructor: make_unique cannot reach it
  gl->display_ = display;
  if (!epoxy_has_egl_extension(display, "EGL_KHR_no_config_context") || !eglBindAPI(EGL_OPENGL_API))
    return fail("EGL cannot make desktop OpenGL contexts without a config here");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) return fail("no OpenGL 4.5 core context (eglCreateContext failed)");
  gl->context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) return fail("eglMakeCurrent failed");
  if (epoxy_gl_version() < 45) return fail("the context is OpenGL " + std::to_string(epoxy_gl_version()) + ", not 4.5");
  return gl;
}

HeadlessGl::~HeadlessGl() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

std::string HeadlessGl::renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }

int HeadlessGl::max_tessellation_level() const {
  GLint m = 0;
  glGetIntegerv(GL_MAX_TESS_GEN_LEVEL, &m);
  return m;
}

int HeadlessGl::max_framebuffer_size() const {
  GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0}, width = 0, height = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &width);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &height);
  return std::min({texture, renderbuffer, viewport[0], viewport[1], width, height});
}

}  // namespace phellem::preview

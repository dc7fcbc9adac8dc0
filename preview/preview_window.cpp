#include "preview/preview_window.h"

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "preview/edge_length.h"
#include "preview/orbit_camera.h"
#include "preview/preview_renderer.h"
#include "scene/camera_model.h"
#include "util/errors.h"

namespace phellem::preview {

namespace {

using Clock = std::chrono::steady_clock;

struct State {
  OrbitCamera camera;
  PreviewSettings settings;
  PreviewScene* scene = nullptr;
  double last_x = 0, last_y = 0;
  bool orbiting = false, panning = false;
  int height = 1;
  std::string message;  // shown in the title for a while (the saved file)
  std::function<std::string(const CameraDesc&)> save;
};

State* state_of(GLFWwindow* w) { return static_cast<State*>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  State& s = *state_of(w);
  switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
      glfwSetWindowShouldClose(w, GLFW_TRUE);
      break;
    case GLFW_KEY_W:
      s.settings.wireframe = !s.settings.wireframe;
      break;
    case GLFW_KEY_M:
      s.settings.show_mask = !s.settings.show_mask;
      break;
    case GLFW_KEY_D:
      s.settings.darkening = !s.settings.darkening;
      break;
    case GLFW_KEY_T:
      s.settings.tints = !s.settings.tints;
      break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:  // finer: shorter micro-edges
      s.settings.target_near_px = std::max(kMinEdgePx, s.settings.target_near_px / 1.5f);
      s.settings.target_far_px = std::max(4.0f, s.settings.target_far_px / 1.5f);
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      s.settings.target_near_px = std::min(64.0f, s.settings.target_near_px * 1.5f);
      s.settings.target_far_px = std::min(512.0f, s.settings.target_far_px * 1.5f);
      break;
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT: {
      const float a = key == GLFW_KEY_LEFT ? 0.15f : -0.15f;
      s.scene->sun_direction = Eigen::AngleAxisf(a, Vec3f::UnitY()) * s.scene->sun_direction;
      break;
    }
    case GLFW_KEY_C:
      if (s.save) s.message = "camera written to " + s.save(s.camera.desc());
      break;
    default:
      break;
  }
}

void on_button(GLFWwindow* w, int button, int action, int) {
  State& s = *state_of(w);
  glfwGetCursorPos(w, &s.last_x, &s.last_y);
  const bool down = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) s.orbiting = down;
  if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) s.panning = down;
}

void on_cursor(GLFWwindow* w, double x, double y) {
  State& s = *state_of(w);
  const float dx = float(x - s.last_x), dy = float(y - s.last_y);
  if (s.orbiting) s.camera.orbit(dx, dy);
  if (s.panning) s.camera.pan(dx, dy, s.height);
  s.last_x = x;
  s.last_y = y;
}

void on_scroll(GLFWwindow* w, double, double dy) { state_of(w)->camera.zoom(float(dy)); }

struct Glfw {
  Glfw() : ok(glfwInit() == GLFW_TRUE) {}
  ~Glfw() {
    if (ok) glfwTerminate();
  }
  bool ok;
};

}  // namespace

WindowStats run_window(PreviewScene scene, const CameraDesc& start, const WindowOptions& o) {
  Glfw glfw;
  if (!glfw.ok)
    throw UserError("", "preview", "no display to open a window on (is DISPLAY or WAYLAND_DISPLAY set?); "
                                   "--snapshot OUT.png renders a frame without one");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  std::unique_ptr<GLFWwindow, void (*)(GLFWwindow*)> window(glfwCreateWindow(o.width, o.height, "Phellem preview", nullptr, nullptr),
                                                            glfwDestroyWindow);
  if (!window) throw UserError("", "preview", "cannot open an OpenGL 4.5 core window on this display");
  glfwMakeContextCurrent(window.get());
  glfwSwapInterval(0);
  State s{OrbitCamera(start), PreviewSettings{}, &scene, 0, 0, false, false, 1, {}, {}};
  s.settings.tints = o.tints;
  s.settings.target_far_px *= o.edge_px / s.settings.target_near_px;
  s.settings.target_near_px = o.edge_px;
  GLint max_level = 64;
  glGetIntegerv(GL_MAX_TESS_GEN_LEVEL, &max_level);
  s.settings.max_level = std::min(o.max_level, int(max_level));
  s.save = o.save_camera;
  glfwSetWindowUserPointer(window.get(), &s);
  glfwSetKeyCallback(window.get(), on_key);
  glfwSetMouseButtonCallback(window.get(), on_button);
  glfwSetCursorPosCallback(window.get(), on_cursor);
  glfwSetScrollCallback(window.get(), on_scroll);

  PreviewRenderer renderer(scene);
  WindowStats stats;
  std::vector<double> ms;
  double last_ms = 0;  // shown on the next frame (this one's time is known only after it)
  while (!glfwWindowShouldClose(window.get())) {
    const auto t0 = Clock::now();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window.get(), &w, &h);
    if (w > 0 && h > 0) {
      s.height = h;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, w, h);
      glClearColor(scene.sky_color.x(), scene.sky_color.y(), scene.sky_color.z(), 1);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      char status[96];
      std::snprintf(status, sizeof status, "%.1f ms | %.2fM triangles | edge %.1f px%s", last_ms, double(stats.triangles) * 1e-6,
                    s.settings.target_near_px, s.settings.tints ? " | tints" : "");
      s.settings.overlay = status;
      stats.triangles = renderer.draw(CameraModel(s.camera.desc(), w, h), s.settings);
      glfwSwapBuffers(window.get());
    }
    const double frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    last_ms = frame_ms;
    if (stats.frames == 0) stats.first_frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - o.start).count();
    ms.push_back(frame_ms);
    ++stats.frames;
    char title[512];
    std::snprintf(title, sizeof title, "Phellem preview — %.1f ms, %lld triangles, edges %.1f px%s%s%s", frame_ms,
                  stats.triangles, s.settings.target_near_px, s.settings.wireframe ? ", wireframe" : "",
                  s.message.empty() ? "" : " — ", s.message.c_str());
    glfwSetWindowTitle(window.get(), title);
    if (o.frames > 0 && stats.frames >= o.frames) break;
    glfwPollEvents();
  }
  std::sort(ms.begin(), ms.end());
  stats.median_ms = ms.empty() ? 0 : ms[ms.size() / 2];
  return stats;
}

}  // namespace phellem::preview

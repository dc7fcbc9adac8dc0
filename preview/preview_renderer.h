// Draws a PreviewScene with the tessellation pipeline of shaders/ into an offscreen frame
// (colour, and an AOV target with the crack mask, the normalized crack depth and the
// distance from the camera), and reads it back with rows top-down, as the path tracer's
// images are. Needs a current OpenGL 4.5 core context (HeadlessGl or a window's).
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "preview/gl_program.h"
#include "preview/preview_scene.h"
#include "scene/camera_model.h"

namespace phellem::preview {

struct PreviewSettings {
  float target_near_px = 6.0f;  // micro-edge length near cracks (pixels; a snapshot uses 2)
  float target_far_px = 48.0f;  // elsewhere
  int max_level = 64;           // the tessellation budget (≤ the hardware's maximum)
  bool wireframe = false;
  bool show_mask = false;
  bool darkening = true;
  bool asymmetric_levels = false;  // tests only: levels that differ per patch (makes holes)
  bool cull = true;                // patches outside the view or facing away are not tessellated
  std::string overlay;             // a status line over the top-left corner (the window's), or none
  // Stress bark's per-plate and per-crack tints (their Voronoi lookup is most of a frame's
  // fragment work on llvmpipe: the window starts without them, T turns them on).
  bool tints = true;
};

struct PreviewFrame {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;           // sRGB, rows top-down
  std::vector<float> mask, crack_depth;  // per pixel
  std::vector<float> distance;         // from the camera (m); +inf where nothing was hit
  long long primitives = 0;            // triangles the tessellator generated
  double milliseconds = 0;             // GPU time of the draw (a timer query)
};

class PreviewRenderer {
 public:
  explicit PreviewRenderer(const PreviewScene& scene);
  ~PreviewRenderer();
  PreviewRenderer(const PreviewRenderer&) = delete;
  PreviewRenderer& operator=(const PreviewRenderer&) = delete;

  PreviewFrame render(const CameraModel& camera, const PreviewSettings& settings);
  // Draws into the offscreen frame and waits for it (glFinish) without reading it back: the
  // cost of a frame on screen. Returns the triangles generated.
  long long draw_offscreen(const CameraModel& camera, const PreviewSettings& settings);
  // Draws into the currently bound framebuffer (a window) without reading anything back.
  long long draw(const CameraModel& camera, const PreviewSettings& settings);

  // A status line over the top-left corner of the bound framebuffer (a built-in 5×7 font,
  // `scale` pixels a font pixel; digits, space, ".,|-" and the letters of "ms triangles dpx kMf").
  void draw_text(const std::string& text, int framebuffer_height, int scale) const;

  // Transform feedback of one object's tessellated vertices (tests): per generated triangle
  // vertex, the undisplaced point (object space), the displaced one and the interpolated base
  // normal (world space, not normalized), the texcoords an image displacement was looked up at
  // and the patch parameters (a tree part's (u, v)).
  struct Feedback {
    std::vector<Vec3f> base, displaced, normal;
    std::vector<Vec2f> texcoord, param;
  };
  Feedback capture(size_t object, const CameraModel& camera, const PreviewSettings& settings);

  size_t objects() const { return meshes_.size(); }

 private:
  struct GpuMesh {
    GLuint vao = 0, vbo[5] = {}, ibo = 0, ssbo[3] = {}, tex[2] = {};
    GLuint image = 0;        // an image displacement's map (R32F), or none
    float image_reach = 0;   // the most it moves a point (m): the culling's margin
    GLsizei count = 0;
  };
  void set_uniforms(const GlProgram& p, const CameraModel& camera, const PreviewSettings& s) const;
  void bind_object(const GlProgram& p, size_t k) const;
  void draw_background(const CameraModel& camera) const;
  void ensure_targets(int width, int height);
  void clear_offscreen(int width, int height);
  void release_targets();

  const PreviewScene& scene_;
  std::vector<GpuMesh> meshes_;
  // The program's defines for this object's bark (tints only where it has them and they are on).
  static std::string variant(const PreviewObject& o, bool tints);
  const GlProgram& program_for(const PreviewObject& o, bool tints);
  std::map<std::string, std::unique_ptr<GlProgram>> programs_;  // by variant
  std::unique_ptr<GlProgram> background_, overlay_;
  GLuint environment_ = 0, empty_vao_ = 0;
  GLuint fbo_ = 0, color_ = 0, aov_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
  float near_ = 0.01f, far_ = 100.0f;
};

}  // namespace phellem::preview

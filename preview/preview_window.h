// `phellem preview SCENE.json`: the interactive window (GLFW 3.3, OpenGL 4.5 core). Mouse:
// left drag orbits, right or middle drag pans, the wheel zooms. Keys: W wireframe, M crack
// mask, D depth darkening, T stress bark's per-plate and per-crack tints, + / − finer / coarser tessellation, ← / → turn the sun, C writes
// the current camera into a copy of the scene (so `phellem render` renders this view), Esc
// or Q quits. A status line over the top-left corner (and the title) shows the frame time,
// the triangles of the last frame and the micro-edge length.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "preview/preview_scene.h"
#include "scene/scene_desc.h"

namespace phellem::preview {

struct WindowOptions {
  int width = 1280, height = 720;
  int frames = 0;  // quit after this many frames (0: when the user closes the window)
  float edge_px = 6.0f;
  int max_level = 64;
  bool tints = false;  // stress bark's tints from the first frame (T toggles them)
  bool quiet = false;
  // Called with the camera when C is pressed; returns the file written (shown in the title).
  std::function<std::string(const CameraDesc&)> save_camera;
  // When the command started: the first frame's time is counted from here.
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

struct WindowStats {
  int frames = 0;
  double median_ms = 0;        // wall time a frame, swap included
  long long triangles = 0;     // of the last frame
  double first_frame_ms = 0;   // from options.start to the first frame shown
};

// Throws UserError (exit 2) when no window can be opened (no display).
WindowStats run_window(PreviewScene scene, const CameraDesc& camera, const WindowOptions& options);

}  // namespace phellem::preview

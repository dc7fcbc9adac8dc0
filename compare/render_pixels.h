// Which pixels of a render EXR `compare` measures (docs/compare.md, "Renders"): those fully
// covered (beauty.A) by one object (object_id; by default the one covering most pixels) whose
// surface faces the camera within an angle, cropped to the largest rectangle of them; the
// scale comes from the position layer over that rectangle.
#pragma once

#include <optional>
#include <string>

#include "compare/maximal_rectangle.h"
#include "io/height_image.h"

namespace phellem {

inline constexpr double kDefaultFacingDeg = 30;

// What the user chose (`--object A=ID`, `--facing-deg A=DEG`).
struct RenderChoice {
  std::optional<int> object_id;          // default: the object covering most pixels
  double facing_deg = kDefaultFacingDeg;  // (0, 180]; 180 keeps every pixel whatever way it faces
};
// A pixel is covered when this share of its samples hit (beauty.A is the share that hit).
inline constexpr float kFullCoverage = 0.999f;
// The facing test reads the normal averaged over a box of ±this (cm) around the pixel, among
// the object's pixels: the walls of a fissure face sideways, the bark around them does not.
inline constexpr double kFacingWindowCm = 1.0;

struct RenderSelection {
  int render_width = 0, render_height = 0;  // the whole render
  int object_id = 0;
  bool object_chosen = false;     // --object, rather than the object covering most pixels
  long long object_pixels = 0;    // pixels fully covered by the object
  long long mask_pixels = 0;      // ... whose surface faces the camera within facing_deg
  double facing_deg = kDefaultFacingDeg;
  bool camera_known = false;      // the header states the camera (needed below 180°)
  PixelRect rect;                 // the largest rectangle of mask pixels: what is measured
  // The median world distance between horizontally (x) and vertically (y) adjacent pixels of
  // the rectangle, as pixels per centimetre.
  double position_px_per_cm_x = 0, position_px_per_cm_y = 0;
};

struct SelectedRender {
  HeightImage image;  // the rectangle's displacement, stating position_px_per_cm as its scale
  std::optional<RgbImage> albedo;  // the rectangle's albedo layer, when the render has one
  RenderSelection selection;
};

// The mask, its largest rectangle and the rectangle's scale, without the size check (tests).
// `render` is a HeightImage read from a render EXR; UserError as below, but for the size.
RenderSelection render_selection(const HeightImage& render, const RenderChoice& choice, const std::string& path,
                                 const std::string& label);

// `render` is a HeightImage read from a render EXR (its `render` layers present); `path` and
// `label` ("A") name it in errors. `px_per_cm`: the user's --scale, used for the size check
// instead of the position layer's. Throws UserError when no pixel qualifies, the object chosen
// is not in the render, the camera is unknown (below 180°), the positions do not change between
// neighbours, or the rectangle is under compare's minimum size (kCompareParams).
SelectedRender select_render_pixels(const HeightImage& render, const RenderChoice& choice, const std::string& path,
                                    const std::string& label, std::optional<double> px_per_cm = std::nullopt);

}  // namespace phellem

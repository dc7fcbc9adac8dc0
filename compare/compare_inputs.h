// The two sides of `phellem compare` (and the photo of `phellem fit`): read, given a scale,
// and brought to one physical scale.
#pragma once

#include <optional>
#include <string>

#include "compare/compare_score.h"
#include "compare/fissure_statistics.h"
#include "compare/height_field.h"
#include "compare/render_pixels.h"
#include "io/height_image.h"

namespace phellem {

// One input as the user named it.
struct CompareSource {
  std::string label;                // "A" or "B": how --scale and --albedo name it
  std::string path;                 // height map, FractureField EXR, render EXR or patch.exr
  std::optional<double> px_per_cm;  // --scale (overrides the file's own scale)
  std::string albedo_path;          // --albedo (optional)
};

// Where an input's scale came from, for the report.
enum class ScaleOrigin { option, header, render_positions };

struct LoadedInput {
  CompareSource source;
  HeightImage image;  // a render: its largest rectangle of bark pixels only
  double px_per_cm_x = 0, px_per_cm_y = 0;  // resolved: --scale, else the file's (a render's: its positions')
  ScaleOrigin scale_origin = ScaleOrigin::option;
  std::optional<RgbImage> albedo;
  bool albedo_from_render = false;         // the render's albedo layer (no --albedo given)
  std::optional<RenderSelection> render;  // which pixels of a render are measured
};

// Reads the height (and albedo) and resolves the scale; a render is cropped to its bark
// (compare/render_pixels.h), its albedo layer is the albedo unless --albedo is given, and its
// scale is its positions' unless --scale is. UserError when a plain image has no --scale, is a
// colour photo (chroma above kColourPhotoChroma), or the albedo's size differs from the
// height map's.
// `render`: --object and --facing-deg, for a render.
LoadedInput load_input(const CompareSource& source, const RenderChoice& render = {});
// The same for a height image already read from source.path.
LoadedInput load_input(const CompareSource& source, HeightImage image, const RenderChoice& render = {});

// An input at one isotropic scale (never finer than its own: the caller picks the coarser).
struct PreparedInput {
  CompareSource source;
  double source_px_per_cm_x = 0, source_px_per_cm_y = 0;
  ScaleOrigin scale_origin = ScaleOrigin::option;
  HeightField field;
  std::optional<AlbedoField> albedo;
  bool albedo_from_render = false;
  std::optional<RenderSelection> render;
};
PreparedInput at_scale(const LoadedInput& input, double px_per_cm);

// The coarsest of the inputs' scales (both axes).
double common_scale(const LoadedInput& a, const LoadedInput& b);

struct CompareReport {
  PreparedInput a, b;
  FissureAnalysis analysis_a, analysis_b;
  Comparison comparison;
  double px_per_cm = 0;  // the common scale
};

// Brings both to the common scale, measures them and compares.
CompareReport compare_inputs(const LoadedInput& a, const LoadedInput& b);

}  // namespace phellem

// The light rig of `phellem compare --lit` (issue 44 item 2): a flat patch of bark seen straight
// on at the comparison's scale, under a 0.53° sun at 30° elevation that rakes across the fissures
// (they run along the trunk, the image's vertical, so the sun comes from the side) and a Preetham
// sky that follows it; one exposure for every side. Both sides of a comparison are rendered by
// the same rig, so what differs between the pictures is the bark.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/height_field.h"
#include "compare/lit_statistics.h"
#include "io/film.h"
#include "scene/scene_desc.h"

namespace phellem {

struct LitRig {
  double sun_elevation_deg = 30;  // above the patch's plane
  double sun_irradiance = 3;      // on a surface facing the sun (the sky takes the same scale)
  bool sky = true;                // false: the sun alone (closed-form tests)
  // A scene's own lights instead of the sun and sky (`compare --lit --lights SCENE`), with the
  // patch turned to face that scene's camera: `facing` is the patch's normal and `up` its v
  // direction, in the lights' world frame.
  std::vector<LightDesc> lights;
  Vec3f facing{0, 0, 1}, up{0, 1, 0};
  int spp = 16;
  int max_depth = 4;
  uint64_t seed = 1;
};

// What the rig renders: heights in metres (high = high) at `height.px_per_cm`, and an albedo
// (linear Rec.709) at the same pixels, or none for a neutral kLitDefaultAlbedo.
struct LitSubject {
  std::string label;  // names the side in errors and progress ("A", "B")
  HeightField height;
  std::optional<AlbedoField> albedo;
};
inline constexpr float kLitDefaultAlbedo = 0.3f;
inline constexpr int kLitMargin = 1;  // pixels of the patch's border left out of the picture

struct LitRender {
  LitImage image;  // (width − 2·margin) × (height − 2·margin) px at the subject's scale
  Film film;       // the render itself (every layer)
  long long triangles = 0;
  double seconds = 0;
};

// Renders `subject` under the rig (`threads` 0: all cores). An albedo of one colour is the
// material's colour; any other is a texture kept in the texture cache under a name made from
// its content (util/cache_dir.h). Throws UserError when the subject is too small to frame.
LitRender render_lit(const LitSubject& subject, const LitRig& rig, int threads = 0);

}  // namespace phellem

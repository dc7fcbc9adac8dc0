#include "scene/stress_bark_desc.h"

#include <cmath>
#include <cstdio>

#include "bark/stress/stress_presets.h"
#include "scene/bark_look_keys.h"
#include "scene/bark_photo.h"
#include "scene/json_reader.h"
#include "scene/scene_image.h"

namespace phellem {

namespace {

// A stress image: 1 channel (magnitude) or 3 (σ_uu, σ_vv, σ_uv); values as stored (no colour
// transform: they are numbers, not colours). Row 0 is the image's top, v = 0 (glTF).
bark::StressImage read_stress_image(const JsonValue& v, const std::string& base_dir) {
  const SceneImage in = read_scene_image(v, base_dir);
  bark::StressImage img;
  img.width = in.width;
  img.height = in.height;
  img.channels = in.channels >= 3 ? 3 : 1;
  img.values.resize(size_t(in.width) * in.height * size_t(img.channels));
  for (size_t i = 0; i < size_t(in.width) * in.height; ++i)
    for (int c = 0; c < img.channels; ++c) {
      const float x = in.pixels[i * size_t(in.channels) + size_t(c)];
      if (!std::isfinite(x)) v.fail("image " + in.path + " holds a non-finite value");
      img.values[i * size_t(img.channels) + size_t(c)] = x;
    }
  return img;
}

bark::StressStroke read_stroke(JsonObject o) {
  bark::StressStroke s;
  const bool uv = o.has("uv"), points = o.has("points");
  if (uv == points)
    o.fail(uv ? "points" : "", "a stroke has either \"uv\" (2D points in texture space) or \"points\" (3D points on the mesh)");
  s.in_uv = uv;
  auto list = o.at(uv ? "uv" : "points");
  for (auto& e : list.array()) {
    if (uv) {
      const Vec2f q = e.vec2();
      s.points.emplace_back(q.x(), q.y(), 0.0);
    } else {
      const Vec3f q = e.vec3();
      s.points.emplace_back(q.x(), q.y(), q.z());
    }
  }
  if (s.points.size() < 2) list.fail("a stroke needs at least 2 points");
  if (auto v = o.get("magnitude")) {
    s.magnitude = v->number();
    if (!(s.magnitude >= 0 && s.magnitude <= 1e9))
      v->fail("magnitude must be in [0, 1e9] (the stroke's stress magnitude; negative values have no meaning)");
  }
  if (auto v = o.get("smoothing")) {
    s.smoothing = v->integer();
    if (s.smoothing < 0 || s.smoothing > 1000) v->fail("smoothing must be an integer in [0, 1000]");
  }
  if (auto v = o.get("radius")) s.radius = v->non_negative();
  o.finish();
  return s;
}

}  // namespace

StressBarkDesc parse_stress_bark(JsonObject o, const std::string& base_dir, uint64_t default_seed) {
  StressBarkDesc d;
  const std::string model = o.string("model");
  if (model != "stress") o.fail("model", "unknown bark model \"" + model + "\"; allowed: strips, stress");
  d.preset = o.string("preset", "woodification");
  auto preset = bark::stress_preset(d.preset);
  if (!preset) {
    std::string names;
    for (const auto& n : bark::stress_preset_names()) names += (names.empty() ? "" : ", ") + n;
    o.fail("preset", "unknown preset \"" + d.preset + "\"; allowed: " + names);
  }
  bark::StressParams& p = d.params;
  p = *preset;
  p.seed = default_seed;
  if (auto v = o.get("pattern")) {
    const std::string s = v->string();
    if (s == "uniform")
      p.pattern = bark::StressPattern::UniformTension;
    else if (s == "horizontal")
      p.pattern = bark::StressPattern::Horizontal;
    else if (s == "vertical")
      p.pattern = bark::StressPattern::Vertical;
    else if (s == "mixed")
      p.pattern = bark::StressPattern::Mixed;
    else if (s == "image")
      p.pattern = bark::StressPattern::Image;
    else if (s == "strokes")
      p.pattern = bark::StressPattern::Strokes;
    else if (s == "growth")
      p.pattern = bark::StressPattern::Growth;
    else
      v->fail("unknown stress pattern \"" + s + "\"; allowed: uniform, horizontal, vertical, mixed, image, strokes, growth");
  }
  if (auto v = o.get("iterations")) p.iterations = v->integer();
  if (auto v = o.get("cracks_per_iteration")) p.cracks_per_iteration = v->integer();
  if (auto v = o.get("relaxations_per_iteration")) p.relaxations_per_iteration = v->integer();
  if (auto v = o.get("alpha")) p.alpha = v->number();
  if (auto v = o.get("stress_alleviation")) p.stress_alleviation = v->number();
  if (auto v = o.get("random_rotation")) p.random_rotation = v->number();
  if (auto v = o.get("crack_rotation")) p.crack_rotation = v->number();
  if (auto v = o.get("snap_angle")) p.snap_angle_deg = v->number();
  if (auto v = o.get("threshold")) p.threshold = v->number();
  if (auto v = o.get("time_step")) p.time_step = v->number();
  if (auto v = o.get("kappa")) p.kappa = v->number();
  if (auto v = o.get("magnitude")) p.magnitude = v->number();
  if (auto v = o.get("mix_ratio")) p.mix_ratio = v->number();
  if (auto v = o.get("stress_image")) p.image = read_stress_image(*v, base_dir);
  if (auto v = o.get("strokes"))
    for (auto& e : v->array()) p.strokes.push_back(read_stroke(e.object()));
  if (auto v = o.get("growth_increment")) {
    const Vec3f g = v->vec3();  // (horizontal, vertical, shear)
    p.growth_increment << g.x(), g.z(), g.z(), g.y();
  }
  if (auto v = o.get("curvature_stress")) p.curvature_stress = v->number();
  if (auto v = o.get("seed")) p.seed = v->seed();
  if (auto v = o.get("preprocess")) {
    if (v->is_bool()) {
      d.preprocess.enabled = v->boolean();
    } else {
      JsonObject m = v->object();
      if (auto w = m.get("edge_length")) d.preprocess.edge_length = w->non_negative();
      if (auto w = m.get("jitter")) {
        d.preprocess.jitter = w->non_negative();
        if (d.preprocess.jitter > 0.45f) w->fail("jitter must lie in [0, 0.45] (fraction of the edge length)");
      }
      m.finish();
    }
  }
  if (auto v = o.get("crack")) {
    JsonObject m = v->object();
    CrackLook& l = d.look;
    if (auto w = m.get("width_per_edge")) l.width_per_edge = w->non_negative();
    if (auto w = m.get("min_width")) l.min_width = w->non_negative();
    if (auto w = m.get("max_width")) l.max_width = w->positive();
    if (auto w = m.get("depth_per_width")) l.depth_per_width = w->non_negative();
    if (auto w = m.get("max_depth")) l.max_depth = w->non_negative();
    if (auto w = m.get("noise")) {
      l.noise = w->non_negative();
      if (l.noise > 1) w->fail("noise must lie in [0, 1]");
    }
    if (auto w = m.get("darkening")) {
      l.darkening = w->non_negative();
      if (l.darkening > 1) w->fail("darkening must lie in [0, 1]");
    }
    if (auto w = m.get("gap")) l.gap = w->non_negative();
    if (auto w = m.get("relief")) parse_crack_relief(w->object(), &l);
    if (auto w = m.get("roughness")) {
      JsonObject r = w->object();
      if (r.has("noise_size"))
        r.fail("noise_size", "stress bark's roughness varies per plate and per crack: its size is crack.variation.size");
      l.roughness = parse_bark_roughness(std::move(r), uint32_t(p.seed ^ (p.seed >> 32)) + 7);
    }
    // A photo first: explicit variation below overrides its tints.
    if (auto w = m.get("photo")) {
      const BarkPhoto ph = read_bark_photo(w->object(), base_dir);
      l.colored = true;
      l.ridge_color = ph.ridge;
      l.fissure_color = ph.fissure;
      l.ridge_tints = ph.ridge_tints;
      l.fissure_tints = ph.fissure_tints;
    }
    if (auto w = m.get("variation")) parse_crack_variation(w->object(), &l);
    if (l.min_width > l.max_width) {
      char what[160];
      std::snprintf(what, sizeof what, "min_width (%g m) must not exceed max_width (%g m%s)", l.min_width, l.max_width,
                    m.has("max_width") ? "" : ", the default");
      m.fail("min_width", what);
    }
    m.finish();
  }
  if (auto e = bark::validate(p)) o.fail(o.has(e->key) ? e->key : "", e->key + ": " + e->message);
  o.finish();
  return d;
}

}  // namespace phellem

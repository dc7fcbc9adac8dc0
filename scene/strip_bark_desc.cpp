#include "scene/strip_bark_desc.h"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "bark/strips/presets.h"
#include "scene/bark_look_keys.h"
#include "scene/bark_photo.h"
#include "scene/json_reader.h"
#include "scene/scene_image.h"

namespace phellem {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

bark::ParamImage read_weakness_map(const JsonValue& v, const std::string& base_dir) {
  const SceneImage in = read_scene_image(v, base_dir);
  const size_t nc = size_t(in.channels);
  bark::ParamImage img;
  img.width = in.width;
  img.height = in.height;
  img.values.resize(size_t(in.width) * in.height);
  // Row 0 of the image is its top: the top of the trunk (s = length) is v = 1.
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x)
      img.values[size_t(in.height - 1 - y) * in.width + x] = std::clamp(in.pixels[(size_t(y) * in.width + x) * nc], 0.0f, 1.0f);
  return img;
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// A dressing sample: {"color", "variation", "grain"} (procedural) or {"image", "size"}.
// Integer images are sRGB-encoded and linearized; float images (EXR) are scene-linear.
bark::ColorSample read_sample(JsonObject o, const std::string& base_dir, bark::ColorSample s) {
  if (auto v = o.get("color")) {
    const Color c = v->color();
    s.base = Eigen::Vector3f(c[0], c[1], c[2]);
  }
  if (auto v = o.get("variation")) s.variation = v->non_negative();
  if (auto v = o.get("grain")) s.grain = v->positive();
  if (auto v = o.get("image")) {
    const SceneImage in = read_scene_image(*v, base_dir);
    const bool encoded = in.encoded;
    s.width = in.width;
    s.height = in.height;
    s.rgb.resize(size_t(in.width) * in.height * 3);
    for (size_t i = 0; i < size_t(in.width) * in.height; ++i)
      for (int c = 0; c < 3; ++c) {
        const float x = std::max(0.0f, in.pixels[i * size_t(in.channels) + size_t(std::min(c, in.channels - 1))]);
        s.rgb[i * 3 + size_t(c)] = encoded ? srgb_to_linear(x) : x;
      }
    const Vec2f size = o.at("size").vec2();
    if (size.x() <= 0 || size.y() <= 0) o.fail("size", "size must be two positive lengths (m) that the image covers");
    s.size_x = size.x();
    s.size_y = size.y();
  } else if (o.has("size")) {
    o.fail("size", "size belongs with an image");
  }
  o.finish();
  return s;
}

}  // namespace

StripBarkDesc parse_strip_bark(JsonObject o, const std::string& base_dir, uint64_t default_seed) {
  StripBarkDesc d;
  const std::string model = o.string("model");
  if (model != "strips") o.fail("model", "unknown bark model \"" + model + "\"; allowed: strips");
  d.preset = o.string("preset", "furrowed");
  auto preset = bark::strip_preset(d.preset);
  if (!preset) {
    std::string names;
    for (const auto& n : bark::strip_preset_names()) names += (names.empty() ? "" : ", ") + n;
    o.fail("preset", "unknown preset \"" + d.preset + "\"; allowed: " + names);
  }
  bark::StripParams& p = d.params;
  p = *preset;
  p.seed = default_seed;
  if (auto v = o.get("orientation")) {
    const std::string s = v->string();
    if (s == "vertical")
      p.orientation = bark::FractureOrientation::Vertical;
    else if (s == "horizontal")
      p.orientation = bark::FractureOrientation::Horizontal;
    else
      o.fail("orientation", "unknown orientation \"" + s + "\"; allowed: vertical, horizontal");
  }
  if (auto v = o.get("strip_width")) p.strip_width = v->positive();
  if (auto v = o.get("element_length")) p.element_length = v->positive();
  if (auto v = o.get("steps")) p.steps = v->integer();
  if (auto v = o.get("growth_rate")) p.growth_rate = v->number();
  if (auto v = o.get("stiffness")) p.stiffness = v->positive();
  if (auto v = o.get("fracture_stiffness")) {
    p.fracture_stiffness.clear();
    if (v->is_number()) {
      p.fracture_stiffness.push_back({0.0, v->positive()});
    } else {
      for (auto& e : v->array()) {
        const Vec2f q = e.vec2();
        p.fracture_stiffness.push_back({q.x(), q.y()});
      }
    }
  }
  if (auto v = o.get("attachment")) p.attachment = v->non_negative();
  if (auto v = o.get("threshold")) p.threshold = v->number();
  if (auto v = o.get("threshold_noise")) p.threshold_noise = v->number();
  if (auto v = o.get("location_jitter")) p.location_jitter = v->number();
  if (auto v = o.get("weakness_map")) p.weakness = read_weakness_map(*v, base_dir);
  if (auto v = o.get("weakness_strength")) p.weakness_strength = v->number();
  if (auto v = o.get("inglis_threshold")) p.inglis_threshold = v->positive();
  if (auto v = o.get("influence")) p.influence = v->non_negative();
  if (auto v = o.get("propagation_jitter_deg")) p.propagation_jitter_deg = v->number();
  if (auto v = o.get("spiral_deg")) p.spiral_deg = v->number();
  if (auto v = o.get("propagation_tension")) p.propagation_tension = v->number();
  if (auto v = o.get("toughness_fraction")) p.toughness_fraction = v->number();
  if (auto v = o.get("toughness_size")) p.toughness_size = v->number();
  if (auto v = o.get("anastomosis")) p.anastomosis = v->number();
  if (auto v = o.get("anastomosis_reach")) p.anastomosis_reach = v->number();
  if (auto v = o.get("fork_probability")) p.fork_probability = v->number();
  if (auto v = o.get("fork_offset")) p.fork_offset = v->number();
  if (auto v = o.get("weakness_noise")) p.weakness_noise = v->number();
  if (auto v = o.get("weakness_noise_size")) p.weakness_noise_size = v->number();
  if (auto v = o.get("opening")) {
    JsonObject m = v->object();
    p.opening_mix = {m.number("axis", 0.0f), m.number("one_side", 0.0f), m.number("both", 0.0f)};
    m.finish();
  }
  if (auto v = o.get("refracture_width")) p.refracture_width = v->non_negative();
  if (auto v = o.get("refracture_stiffness")) p.refracture_stiffness = v->number();
  if (auto v = o.get("dilatation"))
    for (auto& e : v->array()) {
      JsonObject b = e.object();
      bark::DilatationBulge g;
      g.s = b.number("s");
      g.theta = b.number("theta_deg", 0.0f) * kDeg;
      if (auto w = b.get("sigma_s")) g.sigma_s = w->positive();
      if (auto w = b.get("sigma_theta_deg")) g.sigma_theta = w->positive() * kDeg;
      g.amount = b.number("amount", 1.0f);
      if (g.amount <= -1.0) b.fail("amount", "must be > -1 (a bulge cannot shrink the bark)");
      b.finish();
      p.dilatation.push_back(g);
    }
  if (auto v = o.get("fractures"))
    for (auto& e : v->array()) {
      JsonObject f = e.object();
      bark::ScriptedFracture sf;
      sf.s = f.at("s").non_negative();
      sf.theta = f.number("theta_deg", 0.0f) * kDeg;
      sf.step = f.integer("step", 0);
      f.finish();
      p.scripted.push_back(sf);
    }
  if (auto v = o.get("seed")) p.seed = v->seed();
  if (auto v = o.get("field_resolution")) {
    const Vec2f r = v->vec2();
    if (r.x() < 8 || r.y() < 8 || r.x() > 16384 || r.y() > 16384 || r.x() != std::floor(r.x()) || r.y() != std::floor(r.y()))
      v->fail("field_resolution must be two integers in [8, 16384]");
    d.field_width = int(r.x());
    d.field_height = int(r.y());
  }
  if (auto v = o.get("depth")) {
    JsonObject m = v->object();
    const std::string shape = m.string("profile", "u");
    if (shape == "v")
      d.depth.shape = bark::DepthProfileShape::V;
    else if (shape == "u")
      d.depth.shape = bark::DepthProfileShape::U;
    else if (shape == "box")
      d.depth.shape = bark::DepthProfileShape::Box;
    else if (shape == "round")
      d.depth.shape = bark::DepthProfileShape::Round;
    else if (shape == "power")
      d.depth.shape = bark::DepthProfileShape::Power;
    else
      m.fail("profile", "unknown depth profile \"" + shape + "\"; allowed: v, u, box, round, power");
    if (auto w = m.get("exponent")) {
      if (d.depth.shape != bark::DepthProfileShape::Power) w->fail("exponent applies to the \"power\" profile only");
      d.depth.exponent = w->number();
      if (!(d.depth.exponent >= 0.25 && d.depth.exponent <= 8)) w->fail("must be in [0.25, 8]");
    }
    if (auto w = m.get("max_depth")) d.depth.max_depth = w->positive();
    if (auto w = m.get("depth_per_width")) d.depth.depth_per_width = w->positive();
    m.finish();
  }
  if (auto v = o.get("dressing")) {
    JsonObject m = v->object();
    // A photo first: explicit samples below override what it derives.
    if (auto w = m.get("photo")) {
      const BarkPhoto ph = read_bark_photo(w->object(), base_dir);
      bark::FieldColors& c = d.colors;
      c.epidermis.base = ph.ridge;
      c.epidermis.variation = std::min(1.0f, ph.ridge_variation);
      c.fracture.base = ph.fissure;
      c.fracture.variation = std::min(1.0f, ph.fissure_variation);
      c.hardened.base = 0.5f * (ph.ridge + ph.fissure);
      c.ridge_tints = ph.ridge_tints;
      c.fissure_tints = ph.fissure_tints;
    }
    // Seeds of the look's noise follow the scene's seed (the 64-bit seed folded to 32 bits).
    const uint32_t look_seed = uint32_t(p.seed ^ (p.seed >> 32));
    if (auto w = m.get("relief")) d.relief = parse_strip_relief(w->object(), look_seed + 5);
    if (auto w = m.get("roughness")) d.colors.roughness = parse_bark_roughness(w->object(), look_seed + 7);
    if (auto w = m.get("epidermis")) d.colors.epidermis = read_sample(w->object(), base_dir, d.colors.epidermis);
    if (auto w = m.get("fracture")) d.colors.fracture = read_sample(w->object(), base_dir, d.colors.fracture);
    if (auto w = m.get("hardened")) d.colors.hardened = read_sample(w->object(), base_dir, d.colors.hardened);
    if (auto w = m.get("depth_darkening")) {
      d.colors.depth_darkening = w->non_negative();
      if (d.colors.depth_darkening > 1) w->fail("depth_darkening must lie in [0, 1]");
    }
    if (auto w = m.get("interior_darkening")) {
      d.colors.interior_darkening = w->non_negative();
      if (d.colors.interior_darkening > 1) w->fail("interior_darkening must lie in [0, 1]");
    }
    m.finish();
  }
  if (auto e = bark::validate(p)) o.fail(o.has(e->key) ? e->key : "", e->key + ": " + e->message);
  o.finish();
  return d;
}

}  // namespace phellem

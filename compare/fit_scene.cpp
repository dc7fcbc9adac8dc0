#include "compare/fit_scene.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "scene/scene_parser.h"

namespace phellem {

namespace {

using json = nlohmann::ordered_json;

const char* profile_name(bark::DepthProfileShape s) {
  switch (s) {
    case bark::DepthProfileShape::V:
      return "v";
    case bark::DepthProfileShape::U:
      return "u";
    case bark::DepthProfileShape::Box:
      return "box";
    case bark::DepthProfileShape::Round:
      return "round";
    case bark::DepthProfileShape::Power:
      return "power";
  }
  return "u";
}

const char* pattern_name(bark::StressPattern p) {
  switch (p) {
    case bark::StressPattern::UniformTension:
      return "uniform";
    case bark::StressPattern::Horizontal:
      return "horizontal";
    case bark::StressPattern::Vertical:
      return "vertical";
    case bark::StressPattern::Mixed:
      return "mixed";
    case bark::StressPattern::Growth:
      return "growth";
    default:
      throw std::logic_error("fitted_scene_json: a stress pattern the fit does not use");
  }
}

json strip_bark(const StripPatchParams& s, const std::string& preset, uint64_t seed) {
  const bark::StripParams& p = s.params;
  json b;
  b["model"] = "strips";
  b["preset"] = preset;
  b["orientation"] = "vertical";
  b["strip_width"] = p.strip_width;
  b["element_length"] = p.element_length;
  b["steps"] = p.steps;
  b["growth_rate"] = p.growth_rate;
  b["stiffness"] = p.stiffness;
  json k = json::array();
  for (const auto& q : p.fracture_stiffness) k.push_back({q.x(), q.y()});
  b["fracture_stiffness"] = k;
  b["attachment"] = p.attachment;
  b["threshold"] = p.S();
  b["threshold_noise"] = p.threshold_noise;
  b["location_jitter"] = p.location_jitter;
  b["inglis_threshold"] = p.inglis_threshold;
  b["influence"] = p.influence;
  b["propagation_jitter_deg"] = p.propagation_jitter_deg;
  b["propagation_tension"] = p.propagation_tension;
  b["spiral_deg"] = p.spiral_deg;
  b["opening"] = {{"axis", p.opening_mix.x()}, {"one_side", p.opening_mix.y()}, {"both", p.opening_mix.z()}};
  b["refracture_width"] = p.refracture_width;
  b["refracture_stiffness"] = p.refracture_stiffness;
  b["toughness_fraction"] = p.toughness_fraction;
  b["toughness_size"] = p.toughness_size;
  b["anastomosis"] = p.anastomosis;
  b["anastomosis_reach"] = p.anastomosis_reach;
  b["fork_probability"] = p.fork_probability;
  b["fork_offset"] = p.fork_offset;
  b["weakness_noise"] = p.weakness_noise;
  b["weakness_noise_size"] = p.weakness_noise_size;
  b["seed"] = seed;
  b["depth"] = {{"profile", profile_name(s.depth.shape)},
                {"max_depth", s.depth.max_depth},
                {"depth_per_width", s.depth.depth_per_width}};
  if (s.depth.shape == bark::DepthProfileShape::Power) b["depth"]["exponent"] = s.depth.exponent;
  if (s.relief.enabled && s.relief.ridges)
    b["dressing"]["relief"] = {{"depth_ratio", s.relief.depth_ratio}, {"shoulder_width", s.relief.shoulder_width},
                               {"detail", s.relief.detail},           {"detail_size", s.relief.detail_size},
                               {"wall_noise", s.relief.wall_noise},   {"wall_size", s.relief.wall_size}};
  else if (s.relief.enabled)
    b["dressing"]["relief"] = {{"ridges", false}, {"wall_noise", s.relief.wall_noise}, {"wall_size", s.relief.wall_size}};
  return b;
}

json stress_bark(const StressPatchParams& s, const std::string& preset, uint64_t seed) {
  const bark::StressParams& p = s.params;
  json b;
  b["model"] = "stress";
  b["preset"] = preset;
  b["pattern"] = pattern_name(p.pattern);
  b["iterations"] = p.iterations;
  b["cracks_per_iteration"] = p.cracks_per_iteration;
  b["relaxations_per_iteration"] = p.relaxations_per_iteration;
  b["alpha"] = p.alpha;
  b["stress_alleviation"] = p.stress_alleviation;
  b["threshold"] = p.threshold;
  b["mix_ratio"] = p.mix_ratio;
  b["seed"] = seed;
  b["preprocess"] = {{"edge_length", s.edge_length}, {"jitter", s.jitter}};
  const CrackLook& l = s.look;
  b["crack"] = {{"width_per_edge", l.width_per_edge}, {"min_width", l.min_width}, {"max_width", l.max_width},
                {"depth_per_width", l.depth_per_width}, {"max_depth", l.max_depth}, {"noise", l.noise},
                {"darkening", l.darkening}};
  return b;
}

// The `photo` key of the strip dressing and of the stress crack look alike.
json photo_key(const FitPhotoColours& p) { return {{"albedo", p.albedo}, {"height", p.height}, {"px_per_cm", p.px_per_cm}}; }

}  // namespace

std::string fitted_scene_json(const FitCandidate& c, const std::string& preset, uint64_t seed, const FitPhotoColours* photo) {
  json scene;
  scene["camera"] = {{"position", {0.0, 1.1, 2.2}}, {"look_at", {0.0, 1.0, 0.0}}, {"fov_deg", 40}};
  scene["render"] = {{"resolution", {960, 640}}, {"spp", 64}, {"max_depth", 6}, {"seed", 11}};
  scene["lights"] = {{{"type", "sun"}, {"direction", {0.5, 0.6, 0.62}}, {"irradiance", 3.0}, {"angle_deg", 0.53}},
                     {{"type", "sky"}, {"turbidity", 3.0}}};
  scene["materials"] = {
      {"bark", {{"type", "bark"}, {"base_color", {0.3, 0.25, 0.2}}, {"roughness", 0.75}, {"specular", 0.3}}},
      {"ground", {{"type", "diffuse"}, {"base_color", {0.22, 0.2, 0.16}}}}};
  json trunk;
  if (c.model == FitModel::strips) {
    trunk = {{"type", "tree"},
             {"name", "trunk"},
             {"material", "bark"},
             {"axis", {{0, -0.05, 0}, {0.02, 1.0, 0.01}, {0.0, 2.0, 0.02}}},
             {"radius", {0.3, 0.24, 0.2}},
             {"bark", strip_bark(c.strips, preset, seed)}};
    if (photo)
      trunk["bark"]["dressing"]["photo"] = photo_key(*photo);
  } else {
    scene["camera"] = {{"position", {0.0, 0.62, 0.85}}, {"look_at", {0.0, 0.55, 0.0}}, {"fov_deg", 42}};
    trunk = {{"type", "mesh"},
             {"name", "trunk"},
             {"material", "bark"},
             {"procedural", {{"shape", "trunk"}, {"triangles", 7852}, {"radius", 0.16}, {"height", 1.3}}},
             {"bark", stress_bark(c.stress, preset, seed)}};
    if (photo)
      trunk["bark"]["crack"]["photo"] = photo_key(*photo);
  }
  scene["objects"] = {trunk, {{"type", "plane"},
                              {"name", "ground"},
                              {"material", "ground"},
                              {"point", {0, 0, 0}},
                              {"normal", {0, 1, 0}},
                              {"size", 100}}};
  return scene.dump(2) + "\n";
}

namespace {

void expect_near(const char* key, double parsed, double fitted) {
  if (!(std::abs(parsed - fitted) <= 1e-6 * std::max(1.0, std::abs(fitted))))
    throw std::logic_error(std::string("fitted.json: ") + key + " parses as " + std::to_string(parsed) + ", the fit has " +
                           std::to_string(fitted));
}

}  // namespace

void check_fitted_scene(const std::string& text, const FitCandidate& c, const std::string& base_dir) {
  const SceneDesc d = parse_scene(text, "fitted.json", base_dir);
  const ObjectDesc* trunk = nullptr;
  for (const ObjectDesc& o : d.objects)
    if (o.name == "trunk") trunk = &o;
  if (!trunk) throw std::logic_error("fitted.json: no trunk");
  if (c.model == FitModel::strips) {
    if (!trunk->tree.strip_bark) throw std::logic_error("fitted.json: the trunk has no strip bark");
    const bark::StripParams& a = trunk->tree.strip_bark->params;
    const bark::StripParams& b = c.strips.params;
    expect_near("strip_width", a.strip_width, b.strip_width);
    expect_near("growth_rate", a.growth_rate, b.growth_rate);
    expect_near("attachment", a.attachment, b.attachment);
    expect_near("threshold", a.S(), b.S());
    expect_near("threshold_noise", a.threshold_noise, b.threshold_noise);
    expect_near("inglis_threshold", a.inglis_threshold, b.inglis_threshold);
    expect_near("propagation_jitter_deg", a.propagation_jitter_deg, b.propagation_jitter_deg);
    expect_near("spiral_deg", a.spiral_deg, b.spiral_deg);
    expect_near("toughness_fraction", a.toughness_fraction, b.toughness_fraction);
    expect_near("weakness_noise", a.weakness_noise, b.weakness_noise);
    expect_near("fracture_stiffness", a.max_fracture_stiffness(), b.max_fracture_stiffness());
    expect_near("depth/depth_per_width", trunk->tree.strip_bark->depth.depth_per_width, c.strips.depth.depth_per_width);
    if (trunk->tree.strip_bark->depth.shape != c.strips.depth.shape) throw std::logic_error("fitted.json: the depth profile parses other than the fit's");
    if (c.strips.depth.shape == bark::DepthProfileShape::Power)
      expect_near("depth/exponent", trunk->tree.strip_bark->depth.exponent, c.strips.depth.exponent);
    const bark::ReliefLook& ra = trunk->tree.strip_bark->relief;
    const bark::ReliefLook& rb = c.strips.relief;
    if (ra.enabled != rb.enabled || (rb.enabled && ra.ridges != rb.ridges))
      throw std::logic_error("fitted.json: the relief parses other than the fit's");
    if (rb.enabled) {
      expect_near("relief/wall_noise", ra.wall_noise, rb.wall_noise);
      expect_near("relief/wall_size", ra.wall_size, rb.wall_size);
      if (rb.ridges) {
        expect_near("relief/depth_ratio", ra.depth_ratio, rb.depth_ratio);
        expect_near("relief/shoulder_width", ra.shoulder_width, rb.shoulder_width);
        expect_near("relief/detail", ra.detail, rb.detail);
        expect_near("relief/detail_size", ra.detail_size, rb.detail_size);
      }
    }
  } else {
    if (!trunk->stress_bark) throw std::logic_error("fitted.json: the trunk has no stress bark");
    const bark::StressParams& a = trunk->stress_bark->params;
    expect_near("threshold", a.threshold, c.stress.params.threshold);
    expect_near("mix_ratio", a.mix_ratio, c.stress.params.mix_ratio);
    expect_near("iterations", a.iterations, c.stress.params.iterations);
    expect_near("preprocess/edge_length", trunk->stress_bark->preprocess.edge_length, c.stress.edge_length);
    expect_near("crack/max_width", trunk->stress_bark->look.max_width, c.stress.look.max_width);
  }
}

}  // namespace phellem

#include "scene/bark_look_keys.h"

#include "scene/json_reader.h"

namespace phellem {

namespace {

float unit_interval(JsonObject& o, const std::string& key, float fallback) {
  auto v = o.get(key);
  if (!v) return fallback;
  const float x = v->non_negative();
  if (x > 1) v->fail(key + " must lie in [0, 1]");
  return x;
}

float positive(JsonObject& o, const std::string& key, float fallback) {
  auto v = o.get(key);
  return v ? v->positive() : fallback;
}

}  // namespace

bark::BarkRoughness parse_bark_roughness(JsonObject o, uint32_t seed) {
  bark::BarkRoughness r;
  r.ridge = unit_interval(o, "ridge", 0.8f);
  r.fissure = unit_interval(o, "fissure", 0.55f);
  r.noise = unit_interval(o, "noise", 0.2f);
  r.noise_size = positive(o, "noise_size", 0.01f);
  r.seed = seed;
  o.finish();
  return r;
}

bark::ReliefLook parse_strip_relief(JsonObject o, uint32_t seed) {
  bark::ReliefLook r;
  r.enabled = true;
  r.seed = seed;
  r.ridges = o.boolean("ridges", true);
  if (auto v = o.get("depth_ratio")) {
    r.depth_ratio = v->positive();
    if (r.depth_ratio < 0.25 || r.depth_ratio > 20) v->fail("depth_ratio must lie in [0.25, 20] (real bark: about 1 to 2)");
  }
  r.shoulder_width = positive(o, "shoulder_width", float(r.shoulder_width));
  r.detail = unit_interval(o, "detail", float(r.detail));
  r.detail_size = positive(o, "detail_size", float(r.detail_size));
  r.wall_noise = unit_interval(o, "wall_noise", float(r.wall_noise));
  r.wall_size = positive(o, "wall_size", float(r.wall_size));
  o.finish();
  return r;
}

void parse_crack_relief(JsonObject o, CrackLook* l) {
  l->shoulder = o.number("shoulder", 0.4f);
  if (!(l->shoulder >= 0 && l->shoulder <= 2)) o.fail("shoulder", "shoulder must lie in [0, 2] (× max_depth)");
  l->shoulder_width = positive(o, "shoulder_width", 0.006f);
  l->detail = unit_interval(o, "detail", 0.15f);
  l->detail_size = positive(o, "detail_size", l->detail_size);
  l->wall_noise = unit_interval(o, "wall_noise", 0.2f);
  l->wall_size = positive(o, "wall_size", l->wall_size);
  o.finish();
}

void parse_crack_variation(JsonObject o, CrackLook* l) {
  // A grey ramp of 9 tints from 1 − v to 1 + v (bark/dressing/bark_tints.h); 0 takes the
  // variation away.
  auto ramp = [](float v) {
    std::vector<Eigen::Vector3f> r;
    for (int i = 0; v > 0 && i < 9; ++i) r.push_back(Eigen::Vector3f::Constant(1 - v + 2 * v * float(i) / 8));
    return r;
  };
  if (o.has("ridge")) l->ridge_tints = ramp(unit_interval(o, "ridge", 0));
  if (o.has("fissure")) l->fissure_tints = ramp(unit_interval(o, "fissure", 0));
  l->tint_size = positive(o, "size", l->tint_size);
  if (!(l->tint_size >= 1e-4f && l->tint_size <= 10)) o.fail("size", "size must lie in [0.0001, 10] m (a plate's size)");
  o.finish();
}

}  // namespace phellem

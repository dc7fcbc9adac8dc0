// The scene keys of the bark surfaces' look shared by both bark models (issue 22):
//   "roughness": {"ridge": 0.8, "fissure": 0.55, "noise": 0.2, "noise_size": 0.01}
//   strips' "relief": {"depth_ratio": 1.5, "shoulder_width": 0.012, "detail": 0.4,
//                      "detail_size": 0.008, "wall_noise": 0.15, "wall_size": 0.004}
//   stress' "relief": {"shoulder": 0.4, "shoulder_width": 0.006, "detail": 0.15,
//                      "detail_size": 0.008, "wall_noise": 0.2, "wall_size": 0.004}
//   stress' "variation": {"ridge": 0.15, "fissure": 0.2, "size": 0.04} (brightness × 1 ± value
//                        per plate and per crack; replaces a photo's tints)
// Every value is checked with its range at its JSON path.
#pragma once

#include <cstdint>

#include "bark/dressing/bark_relief.h"
#include "bark/dressing/bark_roughness.h"
#include "bark/dressing/crack_profile.h"

namespace phellem {

class JsonObject;

bark::BarkRoughness parse_bark_roughness(JsonObject o, uint32_t seed);
bark::ReliefLook parse_strip_relief(JsonObject o, uint32_t seed);
void parse_crack_relief(JsonObject o, CrackLook* look);
void parse_crack_variation(JsonObject o, CrackLook* look);

}  // namespace phellem

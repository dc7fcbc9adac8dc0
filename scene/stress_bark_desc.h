// The `"bark": {"model": "stress", ...}` object of a scene mesh or tree: stress-model
// parameters (bark/stress/stress_params.h) from a preset plus overrides, the preprocessing,
// and how the cracks are rendered (Spicker 2014 sec. 4.2).
#pragma once

#include <string>

#include "bark/dressing/crack_profile.h"
#include "bark/stress/stress_params.h"

namespace phellem {

class JsonObject;

// Preprocessing (sec. 3.1.4: remove regularity and slivers before cracking).
struct StressPreprocess {
  bool enabled = true;
  float edge_length = 0;  // target edge length (m); 0: the input's mean edge length
  float jitter = 0.3f;    // random tangential displacement, fraction of the edge length
};

struct StressBarkDesc {
  std::string preset;
  bark::StressParams params;
  StressPreprocess preprocess;
  CrackLook look;
};

// Parses and validates (every StressParamError is reported at its JSON path). `base_dir`
// resolves the stress image's file name.
StressBarkDesc parse_stress_bark(JsonObject o, const std::string& base_dir, uint64_t default_seed);

}  // namespace phellem

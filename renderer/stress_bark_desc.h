// The `"bark": {"model": "stress", ...}` object of a scene mesh or tree: stress-model
// parameters (bark/stress/stress_params.h) from a preset plus overrides, the preprocessing,
// and how the cracks are rendered (Spicker 2014 sec. 4.2).
#pragma once

#include <string>

#include "bark/stress/stress_params.h"

namespace phellem {

class JsonObject;

// Crack geometry for rendering (sec. 4.2 as real geometry): a V-profile whose half-width grows
// with the Algorithm 1 width and whose depth grows with the half-width, both modulated by noise.
struct CrackLook {
  float width_per_edge = 0.0008f;  // half-width (m) per crack edge of Algorithm 1 width
  float min_width = 0.0008f;       // half-width at the crack's ends (m)
  float max_width = 0.006f;        // half-width cap (m)
  float depth_per_width = 1.2f;    // depth / half-width
  float max_depth = 0.012f;        // depth cap (m)
  float noise = 0.3f;              // relative modulation of width and depth
  float darkening = 0.7f;          // albedo × (1 − darkening × normalized depth)
  // The visible gap (sec. 3.1.6, Figure 19): the half-width also grows by gap × the crack
  // vertex's summed virtual displacement from the relaxation (still capped at max_width).
  float gap = 0.0f;
};

// Preprocessing (sec. 3.1.4: remove regularity and slivers before cracking).
struct StressPreprocess {
  bool enabled = true;
  float edge_length = 0;   // target edge length (m); 0: the input's mean edge length
  float jitter = 0.3f;     // random tangential displacement, fraction of the edge length
};

struct StressBarkDesc {
  std::string preset;
  bark::StressParams params;
  StressPreprocess preprocess;
  CrackLook look;
};

// Parses and validates (every StressParamError is reported at its JSON path). `base_dir`
// resolves the stress image's file name.
StressBarkDesc parse_stress_bark(JsonObject o, const std::string& base_dir, uint32_t default_seed);

}  // namespace phellem

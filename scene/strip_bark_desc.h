// The `"bark": {"model": "strips", ...}` object of a scene tree: strip-model parameters
// (bark/strips/strip_params.h) from a preset plus overrides, and how the result is dressed.
#pragma once

#include <string>

#include "bark/dressing/bark_relief.h"
#include "bark/dressing/field_color.h"
#include "bark/strips/fracture_field.h"
#include "bark/strips/strip_params.h"

namespace phellem {

class JsonObject;

struct StripBarkDesc {
  std::string preset;
  bark::StripParams params;
  bark::DepthProfile depth;
  bark::FieldColors colors;               // dressing samples and depth darkening
  bark::ReliefLook relief;                // ridge relief and rough walls (off by default)
  int field_width = 0, field_height = 0;  // FractureField resolution per cylinder (0: automatic)
};

// Parses and validates (every StripParamError is reported at its JSON path). `base_dir`
// resolves the weakness map's file name.
StripBarkDesc parse_strip_bark(JsonObject o, const std::string& base_dir, uint64_t default_seed);

}  // namespace phellem

// patch.exr: a fitted patch's heights (one float channel `Y`, high = high, row 0 at the top)
// with its scale in the attribute `phellem:px_per_cm` (read back by io/height_image.h).
#pragma once

#include <string>

#include "compare/height_field.h"

namespace phellem {

// Throws UserError(path) when the file cannot be written.
void write_patch_exr(const HeightField& field, const std::string& path);

}  // namespace phellem

#pragma once
#include <string>

#include "io/film.h"
#include "renderer/integrator.h"

namespace phellem::test {

// Parses `json`, compiles it and renders it; `threads` 0 = all.
RenderResult render_json(const std::string& json, int threads = 0, const std::string& base_dir = ".");

// Whether pixel (x, y) and its 8 neighbours are fully covered (alpha 1): keeps pixels that
// are partly background out of per-pixel geometric checks.
bool interior_pixel(const Film& f, int x, int y);

// Mean of channel c of the beauty over pixels whose coverage (alpha) equals `alpha`
// (and whose 8 neighbours do too, keeping filter-blended edges out).
double mean_beauty(const Film& f, int c, float alpha);

}  // namespace phellem::test

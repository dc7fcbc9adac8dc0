// The Preetham et al. 1999 analytic daylight sky, for every renderer: its radiance in a
// direction, and the latitude-longitude image the path tracer samples and the preview draws.
// Radiance (scene units) = intensity × Y / 100 kcd m⁻², so that a sun of irradiance 1
// corresponds to about 100 klux; the lower hemisphere is ground_albedo × the horizon.
#pragma once

#include <vector>

#include "util/math.h"

namespace phellem {

// The sky's RGB radiance (before scaling) in direction d.
Color preetham_radiance(const Vec3f& sun_direction, float turbidity, const Vec3f& d);
// width × width/2 texels of linear RGB, rows from +y down (util/latlong.h).
std::vector<float> preetham_sky_image(const Vec3f& sun_direction, float turbidity, float intensity, float ground_albedo,
                                      int width);

}  // namespace phellem

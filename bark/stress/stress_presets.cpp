#include "bark/stress/stress_presets.h"

namespace phellem::bark {

std::vector<std::string> stress_preset_names() { return {"birch", "pine", "palm", "bunny", "mouse", "woodification"}; }

std::optional<StressParams> stress_preset(const std::string& name) {
  StressParams p;
  // Table 1: TI, CPI, RPI, α, SA, RR (π).
  auto row = [&](int ti, int cpi, int rpi, double alpha, double sa, double rr) {
    p.iterations = ti;
    p.cracks_per_iteration = cpi;
    p.relaxations_per_iteration = rpi;
    p.alpha = alpha;
    p.stress_alleviation = sa;
    p.random_rotation = rr;
  };
  if (name == "birch") {
    // Birch: thin horizontal lenticel-like cracks: tension along the trunk.
    row(50, 5, 1, 0.0, 0.0, 0.0);
    p.pattern = StressPattern::Vertical;
  } else if (name == "pine") {
    // Pine: plates bounded by cracks in both directions, the vertical ones longer.
    row(120, 8, 5, 0.15, 0.25, 0.0);
    p.pattern = StressPattern::Mixed;
    p.mix_ratio = 0.6;
  } else if (name == "palm") {
    // Palm: long rings around the stem (strong residual carries each crack on).
    row(100, 8, 2, 0.3, 0.0, 0.0);
    p.pattern = StressPattern::Vertical;
  } else if (name == "bunny") {
    row(75, 8, 3, 0.1, 0.3, 0.0);
    p.pattern = StressPattern::UniformTension;
  } else if (name == "mouse") {
    row(250, 15, 2, 0.0, 0.1, 0.0);
    p.pattern = StressPattern::UniformTension;
  } else if (name == "woodification") {
    // Long vertical furrows (horizontal tension, as a growing trunk's girth): a strong residual
    // carries each crack on, rotations let neighbouring furrows wander into each other.
    row(150, 10, 3, 0.6, 0.5, 0.1);
    p.pattern = StressPattern::Horizontal;
    p.crack_rotation = 0.1;
  } else {
    return std::nullopt;
  }
  return p;
}

}  // namespace phellem::bark

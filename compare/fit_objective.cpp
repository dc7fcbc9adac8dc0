#include "compare/fit_objective.h"

#include "bark/stress/stress_mesh.h"
#include "util/errors.h"
#include "util/hash.h"

namespace phellem {

uint64_t fit_simulation_seed(uint64_t seed, int replicate) {
  return replicate == 0 ? seed : mix64(seed ^ (0x5eed0000ULL + uint64_t(replicate)));
}

std::optional<HeightField> try_simulate_candidate(const FitCandidate& c, const PatchSize& size, uint64_t seed) {
  try {
    return simulate_candidate(c, size, seed);
  } catch (const bark::StripParamError&) {
  } catch (const bark::StressParamError&) {
  } catch (const bark::MeshError&) {
  }
  return std::nullopt;
}

FitScore score_field(const HeightField& field, const FissureStats& target) {
  FitScore s;
  try {
    const FissureAnalysis a = analyse_fissures(field, nullptr, "<fit candidate>");
    s.comparison = compare_fissures(target, a.stats);
    s.f = fit_objective_value(s.comparison);
    s.valid = true;
  } catch (const UserError&) {  // the patch's relief is constant (no fissure at all)
  }
  return s;
}

FitScore score_candidate(const FitCandidate& c, const FissureStats& target, const PatchSize& size, uint64_t seed) {
  const std::optional<HeightField> field = try_simulate_candidate(c, size, seed);
  return field ? score_field(*field, target) : FitScore{};
}

}  // namespace phellem

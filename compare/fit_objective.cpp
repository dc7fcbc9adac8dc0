#include "compare/fit_objective.h"

#include "bark/stress/stress_mesh.h"
#include "util/errors.h"
#include "util/hash.h"

namespace phellem {

uint64_t fit_simulation_seed(uint64_t seed, int replicate) {
  return replicate == 0 ? seed : mix64(seed ^ (0x5eed0000ULL + uint64_t(replicate)));
}

FitScore score_candidate(const FitCandidate& c, const FissureStats& target, const PatchSize& size, uint64_t seed) {
  FitScore s;
  try {
    const HeightField field = simulate_candidate(c, size, seed);
    const FissureAnalysis a = analyse_fissures(field, nullptr, "<fit candidate>");
    s.comparison = compare_fissures(target, a.stats);
    s.f = fit_objective_value(s.comparison);
    s.valid = true;
  } catch (const bark::StripParamError&) {
  } catch (const bark::StressParamError&) {
  } catch (const bark::MeshError&) {
  } catch (const UserError&) {  // the patch's relief is constant (no fissure at all)
  }
  return s;
}

}  // namespace phellem

// `phellem compare --lit A B`: both sides rendered as flat patches under one light rig
// (cli/lit_rig.h) and their pictures compared (compare/lit_statistics.h, compare/lit_score.h).
// A is the reference, B the candidate: the words say what B does differently.
#pragma once

#include <optional>
#include <string>

#include "compare/compare_inputs.h"
#include "util/output_set.h"

namespace phellem {

struct LitOptions {
  bool on = false;
  // --relief X=M: metres per unit of X's heights. Required for plain images (code values
  // 0..1); 1 for inputs in metres (FractureField, render, patch.exr), which it scales.
  std::optional<double> relief_a, relief_b;
  int spp = 16;
  bool no_sky = false;  // --no-sky: the sun alone
  std::string lights;   // --lights SCENE.json: that scene's lights, the patch facing its camera
};

inline constexpr int kMaxLitSpp = 4096;
inline constexpr double kMaxRelief = 10;  // metres per unit

// Renders, measures and compares; writes the report (HTML) and JSON through `out`, prints the
// summary unless `quiet`. UserError (exit 2) for a plain image without --relief.
int run_compare_lit(const LoadedInput& a, const LoadedInput& b, const LitOptions& lit, OutputSet& out, const std::string& html,
                    const std::string& json, bool quiet, int threads);

}  // namespace phellem

#include "cli/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "cli/fit_memory.h"
#include "cli/fit_report.h"
#include "compare/common_scale.h"
#include "compare/compare_inputs.h"
#include "compare/fit_objective.h"
#include "lookdev/lit_objective.h"
#include "compare/fit_parameters.h"
#include "compare/fit_relief.h"
#include "compare/fit_scene.h"
#include "compare/fit_search.h"
#include "compare/patch_exr.h"
#include "io/height_image.h"
#include "util/errors.h"
#include "util/output_set.h"
#include "util/progress.h"

namespace phellem {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The search simulates and measures candidates at this scale at most: the statistics are
// lengths in cm measured at the common scale, so a coarser evaluation affords more evaluations
// (bench/fit_eval; docs/compare.md has the figures).
constexpr double kEvalPxPerCm = 5.0;
// But the coarse scale hides detail that the report, at the photo's scale, sees: a pine
// candidate with rough walls 4 mm across scored 0.03–0.06 at 5 px/cm and 0.15–0.18 at 10,
// where its walls read as more fissures (spacing 3.9 cm against 4.7). So the search's best
// kChoicePoints distinct points are scored again on the whole photo at its scale (at most
// kFinalPxPerCm) on kFinalSeeds seeds, the lowest wins, and the relief stage runs at that
// scale too. (Searching at 10 px/cm on a 512² patch instead was too noisy: one candidate's
// mean over 4 seeds ranged 0.14–0.38.)
constexpr double kFinalPxPerCm = 10.0;
constexpr int kChoicePoints = 6;
constexpr int kFinalSeeds = 2;
constexpr double kDefaultTimeBudgetS = 600;
// Each evaluation is the mean over this many simulation seeds: one realization's statistics
// vary by about ±0.04 in score, and a search on few seeds picks lucky realizations (measured
// on bark_brown_01 with 1 seed: the best point scored 0.19–0.26 over three seeds; on the pine
// scan with 2: 0.18–0.37). With 4 the pine fit reached 0.104 where 2 reached 0.137.
constexpr int kSeedsPerEvaluation = 4;
// The relief stage (compare/fit_relief.h, on kFinalSeeds seeds at the photo's scale): its share
// of the time budget and its evaluations without a budget.
constexpr double kReliefShare = 0.1;
constexpr int kReliefMaxEvals = 80;
// The fissures' lean is all but measured on the photo (its mean orientation): the strip fit
// searches the spiral within this many degrees of the lean it measures, which is at most
// kMaxLeanDeg (a photo held askew by more is the user's to rotate).
constexpr double kSpiralSearchDeg = 4;
constexpr double kMaxLeanDeg = 12;

// The photo as a height field at one scale (its own: --scale, or what the file states).
HeightField photo_field(const cli::Options& o, const HeightImage& img) {
  double sx = img.px_per_cm_x, sy = img.px_per_cm_y;
  if (o.scale) sx = sy = *o.scale;
  if (!(sx > 0) || !(sy > 0)) throw UserError(o.scene, "--scale", "this image states no scale: give it in pixels per cm");
  HeightField f;
  f.width = img.width;
  f.height = img.height;
  f.px_per_cm = sx;
  f.z = img.z;
  if (sx != sy) f = resample(f, sx, sy, std::min(sx, sy));
  return f;
}

FitModel model_of(const std::string& name) { return name == "stress" ? FitModel::stress : FitModel::strips; }

// The photo's size at scale `s` (at most its own), rounded up as `resample` rounds it.
PatchSize at_scale(const HeightField& photo, double s) {
  const double f = std::min(1.0, s / photo.px_per_cm);
  auto n = [&](int pixels) { return std::max(1, int(std::ceil(pixels * f - 1e-9))); };
  return {n(photo.width), n(photo.height), std::min(s, photo.px_per_cm)};
}

// What the stages below hold at their peaks (cli/fit_memory.h).
FitMemoryRequest memory_request(const cli::Options& o, const HeightField& photo) {
  FitMemoryRequest r;
  r.photo = o.scene;
  r.full = {photo.width, photo.height, photo.px_per_cm};
  r.eval = at_scale(photo, kEvalPxPerCm);
  r.final = at_scale(photo, kFinalPxPerCm);
  r.stress = model_of(o.model) == FitModel::stress;
  // The choice simulates its points on every thread (strips only); the relief stage one field
  // per seed.
  const int threads = o.threads.value_or(tbb::this_task_arena::max_concurrency());
  r.final_parallel = r.stress ? 0 : std::clamp(threads, kFinalSeeds, kChoicePoints * kFinalSeeds);
  return r;
}

}  // namespace

int run_fit(const cli::Options& o) {
  const auto t0 = Clock::now();
  // Every output is checked before any work.
  const std::filesystem::path dir(o.exr);
  OutputSet out;
  out.expect_input("HEIGHT_IMAGE", o.scene);
  if (!o.albedo.empty()) out.expect_input("--albedo", o.albedo);
  out.expect_folder("-o", o.exr);
  const std::string fitted = (dir / "fitted.json").string(), patch_path = (dir / "patch.exr").string();
  for (const std::string& f : {fitted, patch_path, (dir / "report.html").string(), (dir / "report.json").string()})
    out.expect_file("-o", f);
  HeightImage photo_image = read_height_image(o.scene);
  // A render is fitted over the bark `compare` would measure (compare/render_pixels.h, defaults).
  if (photo_image.render) photo_image = select_render_pixels(photo_image, {}, o.scene, "A", o.scale).image;
  const HeightField photo = photo_field(o, photo_image);
  check_fit_memory(memory_request(o, photo), o.memory_limit);
  // The photo as `phellem compare` reads it (with its albedo: a missing, unreadable or
  // mismatched one is refused here, before any work).
  const LoadedInput photo_in = load_input(CompareSource{"A", o.scene, o.scale, o.albedo}, std::move(photo_image));
  const double s_eval = std::min(kEvalPxPerCm, photo.px_per_cm);
  const HeightField photo_eval = s_eval < photo.px_per_cm ? resample(photo, photo.px_per_cm, photo.px_per_cm, s_eval) : photo;
  const FissureAnalysis target = analyse_fissures(photo_eval, nullptr, o.scene);
  const PatchSize eval_size{photo_eval.width, photo_eval.height, photo_eval.px_per_cm};
  const double s_final = std::min(kFinalPxPerCm, photo.px_per_cm);
  const HeightField photo_final = s_final < photo.px_per_cm ? resample(photo, photo.px_per_cm, photo.px_per_cm, s_final) : photo;
  const FissureAnalysis target_final = s_final == s_eval ? target : analyse_fissures(photo_final, nullptr, o.scene);
  const PatchSize final_size{photo_final.width, photo_final.height, photo_final.px_per_cm};

  FitSpace space = fit_space(model_of(o.model));
  if (space.model == FitModel::strips) {
    // Mean orientation above 90° (image y down): the fissures lean left going up, θ falls.
    const double lean = std::clamp(90.0 - target.stats.orientation_mean_deg, -kMaxLeanDeg, kMaxLeanDeg);
    narrow_row(space, "spiral_deg", lean, kSpiralSearchDeg);
  }
  // With --albedo, the bark takes its colours from the photo (absolute paths: fitted.json
  // renders from wherever it is moved on this machine). The dressing reads the photo now, on
  // the start's scene, so that a photo it cannot use is refused before the search.
  std::optional<FitPhotoColours> colours;
  if (!o.albedo.empty()) {
    colours = FitPhotoColours{std::filesystem::absolute(o.albedo).lexically_normal().string(),
                              std::filesystem::absolute(o.scene).lexically_normal().string(), photo.px_per_cm};
    const FitCandidate start = space.candidate(space.starts.front());
    try {
      check_fitted_scene(fitted_scene_json(start, space.preset, 1, &*colours), start);
    } catch (const UserError& e) {  // the dressing's reasons, at the option that gave the photo
      throw UserError(o.albedo, "--albedo", e.detail());
    }
  }
  const uint64_t seed = o.seed.value_or(1);
  FitSearchOptions so;
  so.seed = seed;
  so.max_evals = o.max_evals.value_or(0);
  so.samples_per_dimension = 6;
  so.time_budget_s = o.time_budget ? *o.time_budget : o.max_evals ? 0.0 : kDefaultTimeBudgetS;
  // Keep back time for the relief stage, the final patch at the photo's scale and the outputs.
  const bool relief_stage = space.model == FitModel::strips;
  const double relief_budget = relief_stage && so.time_budget_s > 0 ? std::clamp(kReliefShare * so.time_budget_s, 5.0, 120.0) : 0.0;
  // The choice at the photo's scale (strips only: a stress patch at 1024², 10 px/cm takes
  // 20 s): about 1.5 s per simulation at 1024², 10 px/cm, two at a time.
  // With a lit objective the search's winner is kept: the choice re-scores by height alone.
  const int choice_points = space.model == FitModel::strips && o.objective == "height" ? kChoicePoints : 1;
  const double choice_budget = choice_points == 1 ? 0.0 : 0.8 * kChoicePoints * kFinalSeeds * double(final_size.width) * final_size.height / (1024.0 * 1024.0);
  if (so.time_budget_s > 0)
    so.time_budget_s = std::max(1.0, so.time_budget_s - since(t0) - 15.0 - relief_budget - choice_budget);
  // --objective lit|both: the relief lit by the rig of `compare --lit`, the photo's rendered once
  // at the evaluation scale (lookdev/lit_objective.h).
  std::optional<LitObjective> lit;
  if (o.objective != "height") {
    HeightField photo_m = photo_eval;
    for (float& z : photo_m.z) z = float(z * *o.relief);
    std::optional<AlbedoField> albedo_eval;
    if (photo_in.albedo) albedo_eval = at_scale(photo_in, s_eval).albedo;
    if (!o.quiet) std::fprintf(stderr, "phellem: fit: lighting the photo's relief (%d×%d px)\n", photo_m.width, photo_m.height);
    lit = make_lit_objective(photo_m, albedo_eval ? &*albedo_eval : nullptr, o.scene);
  }
  const bool timed = so.max_evals == 0;
  Progress bar("fit", timed ? (long long)(so.time_budget_s * 10) : so.max_evals, !o.quiet);
  const auto search_start = Clock::now();
  long long shown = 0;
  const FitSearchResult r = fit_search(
      space.dimension(),
      [&](const std::vector<double>& x, int replicate) {
        const FitCandidate cand = space.candidate(x);
        double f = 0;
        for (int k = 0; k < kSeedsPerEvaluation; ++k) {
          const uint64_t sim_seed = fit_simulation_seed(seed, replicate * kSeedsPerEvaluation + k);
          if (!lit) {
            f += score_candidate(cand, target.stats, eval_size, sim_seed).f;
            continue;
          }
          const std::optional<HeightField> field = try_simulate_candidate(cand, eval_size, sim_seed);
          const FitScore height = field ? score_field(*field, target.stats) : FitScore{};
          if (!height.valid) {  // refused by the model, or no relief at all: nothing to light
            f += kFitPenalty;
            continue;
          }
          const double lit_f = lit_objective_value(*lit, *field);
          f += o.objective == "lit" ? lit_f : height.f + lit_f;
        }
        return f / kSeedsPerEvaluation;
      },
      space.starts, so,
      [&](long long evals, double best) {
        char label[64];
        std::snprintf(label, sizeof label, "fit (best %.3f)", best);
        bar.set_label(label);
        const long long now = timed ? (long long)(since(search_start) * 10) : evals;
        bar.advance(now - shown);
        shown = now;
      });
  bar.finish();

  // The choice at the photo's scale among the search's best distinct points.
  std::vector<const FitEvaluation*> ranked;
  for (const FitEvaluation& e : r.history)
    if (e.replicate == 0) ranked.push_back(&e);
  std::stable_sort(ranked.begin(), ranked.end(), [](const FitEvaluation* a, const FitEvaluation* b) { return a->f < b->f; });
  std::vector<std::vector<double>> choices{r.x};
  for (const FitEvaluation* e : ranked) {
    if (int(choices.size()) >= choice_points) break;
    if (std::find(choices.begin(), choices.end(), e->x) == choices.end()) choices.push_back(e->x);
  }
  std::vector<uint64_t> final_seeds;
  for (int k = 0; k < kFinalSeeds; ++k) final_seeds.push_back(fit_simulation_seed(seed, k));
  size_t chosen = 0;
  nlohmann::json choice_json = {{"points", 0}};  // no choice: the search's winner
  if (choices.size() > 1) {
    const size_t ns = final_seeds.size();
    if (!o.quiet) std::fprintf(stderr, "phellem: fit: the best %zu points again at %g px/cm (%zu seeds)\n", choices.size(), s_final, ns);
    std::vector<double> f(choices.size() * ns);
    tbb::parallel_for(size_t(0), f.size(), [&](size_t i) {
      f[i] = score_candidate(space.candidate(choices[i / ns]), target_final.stats, final_size, final_seeds[i % ns]).f;
    });
    std::vector<double> mean(choices.size(), 0.0);
    for (size_t i = 0; i < f.size(); ++i) mean[i / ns] += f[i] / double(ns);
    chosen = size_t(std::min_element(mean.begin(), mean.end()) - mean.begin());
    choice_json = {{"px_per_cm", s_final}, {"points", choices.size()}, {"seeds", ns},
                   {"objectives", mean},   {"chosen", chosen},         {"search_best_objective", mean[0]}};
  }
  const std::vector<double>& x_best = choices[chosen];

  // Stage 2: the ridge relief, on the chosen geometry, at the photo's scale.
  FitCandidate best = space.candidate(x_best);
  nlohmann::json relief_json = {{"fitted", false}};
  if (relief_stage) {
    ReliefFitOptions ro;
    ro.max_evals = o.max_evals ? std::max(1, int(*o.max_evals / 10)) : kReliefMaxEvals;
    ro.time_budget_s = relief_budget;
    if (!o.quiet)
      std::fprintf(stderr, "phellem: fit: the ridge relief on the best fissures (%d seeds, %d candidates at most%s)\n", kFinalSeeds,
                   ro.max_evals, relief_budget > 0 ? (", " + std::to_string(int(relief_budget)) + " s").c_str() : "");
    const ReliefFitResult rr = fit_relief(best.strips, target_final.stats, final_size, final_seeds, ro);
    best.strips.relief = rr.look;
    relief_json = {{"fitted", true},   {"ridges", rr.look.enabled && rr.look.ridges}, {"objective_without", rr.f_off},
                   {"objective", rr.f}, {"evaluations", rr.evaluations}, {"seeds", kFinalSeeds}};
    if (rr.look.enabled && rr.look.ridges)
      for (const FitParameter& row : relief_fit_rows()) relief_json["parameters"][row.key] = row.read(best);
  }

  // The best fit at the photo's size and scale, compared as `phellem compare` would.
  const uint64_t best_seed = fit_simulation_seed(seed, 0);
  const HeightField patch = simulate_candidate(best, {photo.width, photo.height, photo.px_per_cm}, best_seed);
  // The compare report of patch.exr vs the photo, as `phellem compare` gives it.
  LoadedInput patch_in;
  patch_in.source = CompareSource{"B", patch_path, patch.px_per_cm, ""};
  patch_in.image.kind = HeightImage::Kind::patch;
  patch_in.image.width = patch.width;
  patch_in.image.height = patch.height;
  patch_in.image.z = patch.z;
  patch_in.image.px_per_cm_x = patch_in.image.px_per_cm_y = patch_in.px_per_cm_x = patch_in.px_per_cm_y = patch.px_per_cm;
  const CompareReport report = compare_inputs(photo_in, patch_in);
  nlohmann::json params;
  const std::vector<double> values = space.values(x_best);
  for (size_t i = 0; i < space.table.size(); ++i) params[space.table[i].key] = values[i];
  nlohmann::json lit_json = nullptr;
  if (lit) {  // the winner at the evaluation scale, lit as the search saw it
    LitComparison lc;
    const std::optional<HeightField> field = try_simulate_candidate(best, eval_size, best_seed);
    if (field) {
      const double v = lit_objective_value(*lit, *field, &lc);
      lit_json = {{"relief_m", *o.relief}, {"objective", v}, {"score", lc.score}, {"verdict", lc.verdict}, {"words", lc.words}};
    }
  }
  const nlohmann::json fit = {{"model", o.model},
             {"objective_kind", o.objective},
             {"lit", lit_json},
             {"seed", seed},
             {"evaluations", r.history.size()},
             {"seeds_per_evaluation", kSeedsPerEvaluation},
             {"time_budget_stopped", r.budget_stopped},
             {"objective", {{"mean", r.f}, {"min", r.f_min}, {"max", r.f_max}, {"seeds", r.replicates}}},
             {"eval_px_per_cm", s_eval},
             {"choice", choice_json},
             {"parameters", params},
             {"relief", relief_json},
             {"wall_s", since(t0)}};

  const std::string scene_text = fitted_scene_json(best, space.preset, best_seed, colours ? &*colours : nullptr);
  check_fitted_scene(scene_text, best);
  out.write_bytes("-o", fitted, scene_text);
  out.write("-o", patch_path, [&](const std::string& tmp) { write_patch_exr(patch, tmp); });
  write_fit_reports(out, o.exr, report, fit);
  out.commit();
  if (!o.quiet)
    std::fprintf(stderr, "phellem: fit %s: score %.3f, orientation EMD %.1f deg (%s), %zu evaluations, %.0fs\n", o.model.c_str(),
                 report.comparison.score, report.comparison.orientation_emd_deg, report.comparison.verdict.c_str(), r.history.size(),
                 since(t0));
  return 0;
}

}  // namespace phellem

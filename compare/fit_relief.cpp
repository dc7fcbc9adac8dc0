#include "compare/fit_relief.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <nlopt.hpp>

#include "compare/fit_objective.h"
#include "compare/strip_patch.h"
#include "util/errors.h"

namespace phellem {

namespace {

using RL = bark::ReliefLook;

constexpr double kReliefStartDetail = 0.1;

}  // namespace

const std::vector<FitParameter>& relief_fit_rows() {
  static const std::vector<FitParameter> rows{
      relief_row("depth_ratio", 0.5, 20, true, &RL::depth_ratio),  relief_row("shoulder_width", 0.003, 0.03, true, &RL::shoulder_width),
      relief_row("detail", 0, 1, false, &RL::detail),              relief_row("detail_size", 0.003, 0.03, true, &RL::detail_size),
      relief_row("wall_noise", 0, 0.5, false, &RL::wall_noise),    relief_row("wall_size", 0.002, 0.03, true, &RL::wall_size)};
  return rows;
}

ReliefFitResult fit_relief(const StripPatchParams& geometry, const FissureStats& target, const PatchSize& size,
                           const std::vector<uint64_t>& seeds, const ReliefFitOptions& options) {
  if (seeds.empty()) throw std::logic_error("fit_relief: no seeds");
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<bark::FractureField> fields(seeds.size());
  StripPatchParams g = geometry;
  g.params.orientation = bark::FractureOrientation::Vertical;
  tbb::parallel_for(size_t(0), seeds.size(), [&](size_t i) { fields[i] = strip_patch_field(g, size, seeds[i]); });

  // The mean objective over the seeds with this relief (per-seed scores summed in seed order).
  auto score_look = [&](const bark::ReliefLook& look) {
    StripPatchParams p = g;
    p.relief = look;
    std::vector<double> f(seeds.size(), kFitPenalty);
    tbb::parallel_for(size_t(0), seeds.size(), [&](size_t i) {
      try {
        const FissureAnalysis a = analyse_fissures(strip_patch_heights(fields[i], p, size, seeds[i]), nullptr, "<fit candidate>");
        f[i] = fit_objective_value(compare_fissures(target, a.stats));
      } catch (const UserError&) {  // no fissure left to measure
      }
    });
    double sum = 0;
    for (double v : f) sum += v;
    return sum / double(f.size());
  };

  ReliefFitResult res;
  res.look = g.relief;
  res.f_off = res.f = score_look(g.relief);
  if (options.max_evals <= 0) return res;

  const auto& rows = relief_fit_rows();
  // From the geometry's own relief (its shoulder and walls) with a little detail.
  FitCandidate start;
  if (g.relief.enabled && g.relief.ridges) start.strips.relief = g.relief;
  start.strips.relief.enabled = start.strips.relief.ridges = true;
  start.strips.relief.detail = kReliefStartDetail;
  std::vector<double> x;
  for (const FitParameter& row : rows) x.push_back(row.normalized(row.read(start)));

  // One relief candidate: the rows applied at x (rounded to float as fitted.json keeps them).
  std::function<double(const std::vector<double>&)> evaluate = [&](const std::vector<double>& xv) {
    FitCandidate c = start;
    for (size_t i = 0; i < rows.size(); ++i) rows[i].apply(double(float(rows[i].value(xv[i]))), c);
    const double f = score_look(c.strips.relief);
    ++res.evaluations;
    if (f < res.f) {
      res.f = f;
      res.look = c.strips.relief;
    }
    return f;
  };
  struct Ctx {
    std::function<double(const std::vector<double>&)>* evaluate;
    const ReliefFitOptions* o;
    std::chrono::steady_clock::time_point t0;
    nlopt::opt* opt;
  };
  nlopt::opt opt(nlopt::LN_SBPLX, unsigned(x.size()));
  Ctx ctx{&evaluate, &options, t0, &opt};
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
  opt.set_initial_step(0.2);
  opt.set_xtol_rel(1e-3);
  opt.set_maxeval(options.max_evals);
  opt.set_min_objective(
      [](unsigned n, const double* xp, double*, void* data) -> double {
        Ctx& c = *static_cast<Ctx*>(data);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - c.t0).count();
        if (c.o->time_budget_s > 0 && elapsed > c.o->time_budget_s) {
          c.opt->force_stop();
          return std::numeric_limits<double>::max();
        }
        return (*c.evaluate)(std::vector<double>(xp, xp + n));
      },
      &ctx);
  double fmin = 0;
  try {
    opt.optimize(x, fmin);
  } catch (const nlopt::forced_stop&) {
  } catch (const nlopt::roundoff_limited&) {
  }
  return res;
}

}  // namespace phellem

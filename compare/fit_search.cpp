#include "compare/fit_search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <nlopt.hpp>
#include <numeric>
#include <thread>

#include "util/random.h"

namespace phellem {

namespace {

using Clock = std::chrono::steady_clock;

// Runs a() on a new thread and b() on this one; rethrows the first exception (a's first).
void run_pair(const std::function<void()>& a, const std::function<void()>& b) {
  std::exception_ptr ea, eb;
  std::thread t([&] {
    try {
      a();
    } catch (...) {
      ea = std::current_exception();
    }
  });
  try {
    b();
  } catch (...) {
    eb = std::current_exception();
  }
  t.join();
  if (ea) std::rethrow_exception(ea);
  if (eb) std::rethrow_exception(eb);
}

// A scrambled Latin hypercube: every dimension's N strata each hold one point.
std::vector<std::vector<double>> latin_hypercube(size_t n, size_t count, uint64_t seed) {
  std::vector<std::vector<double>> pts(count, std::vector<double>(n));
  for (size_t d = 0; d < n; ++d) {
    StreamRng rng(seed, 0x4c48530000ULL + d, 0);
    std::vector<size_t> perm(count);
    std::iota(perm.begin(), perm.end(), size_t(0));
    for (size_t i = count; i > 1; --i) std::swap(perm[i - 1], perm[size_t(rng.uniform() * double(i))]);
    for (size_t i = 0; i < count; ++i) pts[i][d] = (double(perm[i]) + rng.uniform()) / double(count);
  }
  return pts;
}

class Search {
 public:
  Search(size_t n, const FitObjective& f, const FitSearchOptions& o, const FitProgress& progress)
      : n_(n), f_(f), o_(o), progress_(progress), start_(Clock::now()) {
    const long long rescore = (long long)o.rescore_points * o.rescore_replicates;
    rescore_evals_ = o.max_evals > 0 ? std::min(rescore, o.max_evals / 5 / std::max(1, o.rescore_replicates) *
                                                             std::max(1, o.rescore_replicates))
                                     : rescore;
    search_evals_ = o.max_evals > 0 ? o.max_evals - rescore_evals_ : std::numeric_limits<long long>::max();
  }

  FitSearchResult run(const std::vector<std::vector<double>>& starts) {
    phase_a(starts);
    phase_b();
    return finish();
  }

 private:
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  // Whether the time budget still allows another pair of evaluations before the re-scoring.
  bool time_left() {
    if (o_.time_budget_s <= 0) return true;
    std::lock_guard<std::mutex> lock(mutex_);
    const double per_pair = pairs_ > 0 ? pair_seconds_ / double(pairs_) : 0.0;
    const double reserve = per_pair * (double(rescore_evals_ + 1) / 2.0 + 1.0);
    return elapsed() + reserve < o_.time_budget_s;
  }
  long long evals() const { return (long long)history_.size(); }

  void record(std::vector<FitEvaluation> evs) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& e : evs) {
      if (e.replicate == 0 && e.f < best_f_) {
        best_f_ = e.f;
        best_x_ = e.x;
      }
      history_.push_back(std::move(e));
      if (progress_) progress_(evals(), best_f_);
    }
  }

  // Evaluates the points two at a time, in order, while the budgets allow.
  void evaluate_all(const std::vector<std::vector<double>>& pts, int replicate, long long cap) {
    for (size_t i = 0; i < pts.size(); i += 2) {
      const long long left = cap - evals();
      if (left <= 0) return;
      if (!time_left()) {
        budget_stopped_ = true;
        return;
      }
      const bool two = i + 1 < pts.size() && left >= 2;
      double fa = 0, fb = 0;
      const auto t0 = Clock::now();
      if (two)
        run_pair([&] { fa = f_(pts[i], replicate); }, [&] { fb = f_(pts[i + 1], replicate); });
      else
        fa = f_(pts[i], replicate);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        pair_seconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
        ++pairs_;
      }
      std::vector<FitEvaluation> evs{{pts[i], fa, replicate}};
      if (two) evs.push_back({pts[i + 1], fb, replicate});
      record(std::move(evs));
    }
  }

  void phase_a(const std::vector<std::vector<double>>& starts) {
    std::vector<std::vector<double>> pts;
    for (const auto& s : starts)
      if (s.size() == n_) pts.push_back(s);
    for (auto& p : latin_hypercube(n_, size_t(o_.samples_per_dimension) * n_, o_.seed)) pts.push_back(std::move(p));
    // Phase A takes at most half of a limited search budget (the starts always run).
    const long long cap =
        o_.max_evals > 0 ? std::max<long long>((long long)std::min(starts.size(), pts.size()), search_evals_ / 2) : search_evals_;
    evaluate_all(pts, 0, std::min(cap, search_evals_));
    ranked_ = history_;
    std::stable_sort(ranked_.begin(), ranked_.end(), [](const auto& a, const auto& b) { return a.f < b.f; });
  }

  // One Subplex run from x0; its evaluations in order. Stops at `cap` evaluations, at xtol,
  // or when the time budget runs out.
  std::vector<FitEvaluation> local(std::vector<double> x0, double step, long long cap, std::exception_ptr& error) {
    std::vector<FitEvaluation> evs;
    if (cap <= 0) return evs;
    nlopt::opt opt(nlopt::LN_SBPLX, unsigned(n_));
    struct Ctx {
      Search* self;
      nlopt::opt* opt;
      std::vector<FitEvaluation>* evs;
      std::exception_ptr* error;
    } ctx{this, &opt, &evs, &error};
    opt.set_lower_bounds(0.0);
    opt.set_upper_bounds(1.0);
    opt.set_initial_step(step);
    opt.set_xtol_rel(o_.xtol_rel);
    opt.set_maxeval(int(std::min<long long>(cap, std::numeric_limits<int>::max())));
    opt.set_min_objective(
        [](unsigned n, const double* x, double*, void* data) -> double {
          Ctx& c = *static_cast<Ctx*>(data);
          if (!c.self->time_left()) {
            c.self->budget_stopped_ = true;
            c.opt->force_stop();
            return std::numeric_limits<double>::max();
          }
          try {
            std::vector<double> p(x, x + n);
            const auto t0 = Clock::now();
            const double f = c.self->f_(p, 0);
            {
              std::lock_guard<std::mutex> lock(c.self->mutex_);
              // Two searches run at once: a pair of evaluations takes about one's wall time.
              c.self->pair_seconds_ += 0.5 * std::chrono::duration<double>(Clock::now() - t0).count();
              c.self->pairs_ += 1;
            }
            c.evs->push_back({p, f, 0});
            c.self->record({c.evs->back()});
            return f;
          } catch (...) {
            *c.error = std::current_exception();
            c.opt->force_stop();
            return std::numeric_limits<double>::max();
          }
        },
        &ctx);
    for (double& v : x0) v = std::clamp(v, 0.0, 1.0);
    double fmin = 0;
    try {
      opt.optimize(x0, fmin);
    } catch (const nlopt::forced_stop&) {
    } catch (const nlopt::roundoff_limited&) {
    } catch (const std::runtime_error&) {  // NLopt's generic failure
      if (!error) throw;
    }
    return evs;
  }

  void phase_b() {
    size_t next_start = 0;
    for (int round = 0;; ++round) {
      if (o_.max_evals <= 0 && o_.time_budget_s <= 0 && round >= o_.rounds) return;
      const long long left = search_evals_ - evals();
      if (left < 2 || best_x_.empty() || !time_left()) return;
      std::vector<double> a = best_x_, b;
      while (next_start < ranked_.size() && b.empty()) {
        if (ranked_[next_start].x != a) b = ranked_[next_start].x;
        ++next_start;
      }
      const double step = o_.initial_step * std::pow(0.5, double(round % 4));
      const long long cap_a = b.empty() ? left : left - left / 2, cap_b = b.empty() ? 0 : left / 2;
      std::exception_ptr ea, eb;
      std::vector<FitEvaluation> ra, rb;
      const long long before = evals();
      // The searches' own histories are recorded as they go (for the progress); put them
      // back in the deterministic order afterwards.
      run_pair([&] { ra = local(a, step, cap_a, ea); }, [&] { rb = b.empty() ? rb : local(b, step, cap_b, eb); });
      if (ea) std::rethrow_exception(ea);
      if (eb) std::rethrow_exception(eb);
      history_.resize(size_t(before));
      for (auto* r : {&ra, &rb})
        for (auto& e : *r) history_.push_back(std::move(e));
      // The best point in that order (ties between the searches go to the first).
      best_f_ = std::numeric_limits<double>::infinity();
      for (const auto& e : history_)
        if (e.replicate == 0 && e.f < best_f_) best_f_ = e.f, best_x_ = e.x;
      if (evals() == before) return;  // both converged at once: nothing more to learn
    }
  }

  FitSearchResult finish() {
    FitSearchResult res;
    // The best distinct points of the search replicate.
    std::vector<FitEvaluation> sorted;
    for (const auto& e : history_)
      if (e.replicate == 0) sorted.push_back(e);
    std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.f < b.f; });
    std::vector<FitEvaluation> top;
    for (const auto& e : sorted) {
      if ((int)top.size() >= o_.rescore_points) break;
      if (std::none_of(top.begin(), top.end(), [&](const auto& t) { return t.x == e.x; })) top.push_back(e);
    }
    if (top.empty()) throw std::runtime_error("fit_search: no evaluation within the budget");
    const int reps = rescore_evals_ > 0 ? o_.rescore_replicates : 0;
    std::vector<std::vector<double>> scores(top.size());
    for (size_t i = 0; i < top.size(); ++i) scores[i].push_back(top[i].f);
    if (reps > 0) {
      std::vector<std::pair<size_t, int>> jobs;
      for (size_t i = 0; i < top.size(); ++i)
        for (int r = 1; r <= reps; ++r) jobs.push_back({i, r});
      for (size_t k = 0; k < jobs.size(); k += 2) {
        double fa = 0, fb = 0;
        const bool two = k + 1 < jobs.size();
        auto eval = [&](size_t j, double& out) { out = f_(top[jobs[j].first].x, jobs[j].second); };
        if (two)
          run_pair([&] { eval(k, fa); }, [&] { eval(k + 1, fb); });
        else
          eval(k, fa);
        std::vector<FitEvaluation> evs{{top[jobs[k].first].x, fa, jobs[k].second}};
        scores[jobs[k].first].push_back(fa);
        if (two) {
          evs.push_back({top[jobs[k + 1].first].x, fb, jobs[k + 1].second});
          scores[jobs[k + 1].first].push_back(fb);
        }
        record(std::move(evs));
      }
    }
    size_t best = 0;
    auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()); };
    for (size_t i = 1; i < top.size(); ++i)
      if (mean(scores[i]) < mean(scores[best])) best = i;
    res.x = top[best].x;
    res.f = mean(scores[best]);
    res.f_min = *std::min_element(scores[best].begin(), scores[best].end());
    res.f_max = *std::max_element(scores[best].begin(), scores[best].end());
    res.replicates = int(scores[best].size());
    res.history = std::move(history_);
    res.budget_stopped = budget_stopped_;
    return res;
  }

  size_t n_;
  const FitObjective& f_;
  FitSearchOptions o_;
  const FitProgress& progress_;
  Clock::time_point start_;
  long long rescore_evals_ = 0, search_evals_ = 0;
  std::mutex mutex_;
  std::vector<FitEvaluation> history_, ranked_;
  double best_f_ = std::numeric_limits<double>::infinity();
  std::vector<double> best_x_;
  double pair_seconds_ = 0;
  long long pairs_ = 0;
  std::atomic<bool> budget_stopped_{false};
};

}  // namespace

FitSearchResult fit_search(size_t n, const FitObjective& f, const std::vector<std::vector<double>>& starts,
                           const FitSearchOptions& options, const FitProgress& progress) {
  if (n == 0) throw std::logic_error("fit_search: no parameters");
  nlopt::srand(options.seed);  // Subplex draws nothing, but a stochastic method would
  Search s(n, f, options, progress);
  return s.run(starts);
}

}  // namespace phellem

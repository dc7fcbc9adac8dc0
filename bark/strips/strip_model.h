// StripModel: the strips of one cylinder (or flat sample) through growth.
// Lefebvre & Neyret 2002: Figure 8 (per-step algorithm), sec. 3.2 (fracture creation,
// propagation, opening), sec. 5 (attachment, mapped strips, dilatation), Figure 9 (refracture).
//
// Each step, as in the paper's Figure 8, a sweep over the strips grows each strip (its anchors
// follow the substrate), brings it to equilibrium, breaks it while an element exceeds its
// threshold and propagates its fractures into the neighbours before they are visited, so a
// young sharp fracture can run along the axis within one step (brittle fracture is fast next
// to growth) and relieve the strips it crosses. Wide fractures then harden into bark, and
// plasticity resets the attachment springs and the fracture rest lengths; nothing touches a
// strip between its neighbours' propagation and the next step's growth, so this last stage
// is done as the next step grows the strip (settle() does it at once).
//
// Steps are swept in blocks of kBlockSteps, all in one direction, the direction alternating
// from block to block so that neither end is favoured. A block is split into two halves of
// consecutive strips, one per core, and each half runs its K steps as a wavefront (step s
// reaches a strip right after step s - 1 has passed the strip two further on), so a strip's
// steps are done while its data is in that core's cache: a trunk's strips do not fit in the
// caches, and a sweep of one step at a time over all of them ran at memory speed. Each half
// sees the fracture bookkeeping (skeleton, Inglis measures) as the block began plus its own
// changes; a fracture that reaches the other half is continued at the block's end, when the
// crossings are replayed in a fixed order, and the boundary between the halves is drawn anew
// for every block, so no height of the trunk is special. While bark is still intact (more
// than 1 strip in 20 without a fracture) a block is swept whole instead: the first wave of
// fractures, which breaks unfractured bark everywhere within a few steps, would otherwise
// leave a seam of fracture ends at the boundary. Strips that wrap around (tileable
// samples, strips along a limb's axis) are swept one step at a time, alternating direction,
// with a helper task growing strips ahead of the sweep. Random draws depend on (seed, strip,
// step) only and the halves share nothing while they run: the result is bit-identical for
// any thread count.
#pragma once

#include <algorithm>
#include <cassert>
#include <functional>
#include <vector>

#include "bark/strips/fracture_skeleton.h"
#include "bark/strips/strip.h"
#include "bark/strips/strip_domain.h"
#include "bark/strips/strip_equilibrium.h"
#include "bark/strips/strip_params.h"
#include "util/random.h"

namespace phellem::bark {

struct StripStats {
  // created counts every break that started a fracture, scripted ones included.
  long long created = 0, scripted = 0, propagated = 0, merged = 0, refractured = 0;
  long long arrived = 0;                    // fractures continued from another cylinder (queue_arrival)
  long long max_breaks_per_strip_step = 0;  // largest number of breaks in one strip in one step
  long long capped = 0;                     // break loops stopped by the safety cap instead of the criterion (should stay 0)
  // Our extension (issue 22): tips that deviated to meet another fracture (anastomosis), and
  // second cuts made by forking tips.
  long long joined = 0, forked = 0;
};

// A location on another surface that fractures propagating off this one should continue
// into (sec. 5.3, Figure 20): set by a caller that owns several models (a tree).
struct PropagationExit;

// The free end of a fracture sharp enough to propagate (Inglis, sec. 3.2.4).
struct FractureTip {
  size_t strip = 0;
  double theta = 0;  // final-shape angle of the fracture element's centre
  int32_t root = 0;  // skeleton component
  bool up = true;    // free on the strip's upper (s+) side (else lower)
};

struct PropagationExit {
  int strip = 0;     // strip on this model from which a fracture leaves
  bool up = true;    // leaving through the strip's upper (s+) side
  double theta = 0;  // where it leaves
};

// Most epidermis elements a model may have at its final size (fractures add about as many
// again): about 6 GB of memory, at the ~320 bytes per final-size element measured on the
// benchmark trunk (peak RSS 170 MB for its 1000 strips, 155 MB for 500; 9.4·10^4 elements).
inline constexpr double kMaxElements = 2e7;

// Steps swept together as one wavefront (StripModel::step() advances by a block; blocks start
// at multiples of this). Every strip's data is visited once per block instead of once per
// step, which is what keeps a trunk's strips in cache.
inline constexpr int kBlockSteps = 8;

class StripModel {
 public:
  // Throws StripParamError when a parameter is outside its valid range, or when the strips
  // would hold more than kMaxElements elements.
  StripModel(StripDomain domain, StripParams params);

  // One block of growth steps (kBlockSteps, the last block shorter; one step for strips that
  // wrap around): Figure 8 for every strip, then propagation; steps_done() tells where it
  // stands. The last step's last stage, hardening and plasticity (refracture, attachment
  // reset, fracture rest lengths), is applied to each strip when the next step grows it, while
  // its data is in cache; settle() applies it now (done automatically after the last step;
  // growth frames call it). Positions and the skeleton are those of the step either way;
  // settling changes no later result.
  void step();
  void settle();
  int steps_done() const { return step_; }
  int steps_total() const { return params_.steps; }
  // Growth factor of the substrate at the current step relative to the final shape.
  double scale_at_step(int t) const;

  const StripDomain& domain() const { return domain_; }
  const StripParams& params() const { return params_; }
  const std::vector<Strip>& strips() const { return strips_; }
  const FractureSkeleton& skeleton() const { return skeleton_; }
  const StripStats& stats() const { return stats_; }
  OpeningMode opening_mode(int32_t fracture_id) const { return modes_[size_t(fracture_id)]; }

  // Current substrate arc position on strip j of the final-shape angle θ, and back.
  double x_of(size_t j, double theta) const;
  double theta_of(size_t j, double x) const;
  // Index of the element of strip j that contains arc position x (cyclic strips wrap x).
  size_t element_at(size_t j, double x) const;

  // The strip and strip angle of a point (s metres along the axis, θ around it) of the bark's
  // parameter space, and the bark's (u = θ / 2π, v = s / length) of a strip point: the two
  // differ when the strips run along the axis.
  std::pair<size_t, double> strip_coords(double s, double theta) const;
  Eigen::Vector2d surface_uv(size_t strip, double theta) const;

  // Starts a fracture at (strip, θ) in the current state, linked to nothing; returns false if
  // the location is already fractured. Used for scripted fractures, and meant for a tree to
  // continue fractures arriving from another cylinder (sec. 5.3, branchings). `fe_out`
  // receives the new fracture element's index in the strip.
  bool trigger(size_t strip, double theta, int32_t* fe_out = nullptr);

  // When on, every equilibrium solve is followed by a residual check; max_residual() is the
  // largest relative force residual seen since (the tests' equilibrium invariant).
  void set_check_equilibrium(bool on) { check_ = on; }
  double max_residual() const;

  // The Inglis measure of fracture `id`'s component as the sweep sees it: its number of
  // fracture elements (exact) and their summed width (as measured at the end of the last step,
  // then kept up to date through the sweep).
  std::pair<double, double> inglis_measure(int32_t id) const {
    const size_t root = size_t(skeleton_.find(id));
    return root < fracture_count_.size() ? std::pair{fracture_count_[root], fracture_width_[root]} : std::pair{0.0, 0.0};
  }
  // Sharp free ends on strips [first, last) in the current state.
  std::vector<FractureTip> sharp_tips(size_t first, size_t last) const;
  // A fracture arriving from another cylinder (a tree's branching, sec. 5.3 / Figure 20): it
  // starts at (strip, θ) in the next step's sweep, before the strip's own breaks, and then
  // propagates like any other. Counted in stats().arrived (and created).
  void queue_arrival(size_t strip, double theta);

  // Fractures that tried to propagate past the first or last strip during the last step.
  const std::vector<PropagationExit>& exits() const { return exits_; }

 private:
  void init_strip(size_t j);
  // One strip's share of a step before the sweep reaches it: the previous step's hardening
  // and plasticity if owed, growth, equilibrium and the scan (strip_advance.cpp).
  // `grower`: 0 for the sweep's thread, 1 for the helper (whose Inglis sums it adds to).
  // `step`: the step it grows for; `count_widths`: whether its fracture widths go to the
  // grower's Inglis sums (the last step before a measure) or are not counted.
  void advance_strip(size_t j, int grower, int step, bool count_widths);
  struct InglisSums;
  // `sums`: where the fracture widths are counted (nullptr: nowhere).
  void advance_settled(size_t j, InglisSums* sums);
  void grow_strip(size_t j, InglisSums* sums);
  // A step of the sweep alternating direction every step (strips that wrap around), and a block
  // of K steps swept as a wavefront (all other strips); see strip_model.cpp.
  void sweep_step();
  void sweep_block(int K);
  void fold_counts(size_t j);
  // Homogeneous growth of strip j's substrate metric and circumference by g; returns the new
  // circumference.
  double scale_metric(size_t j, double g);
  void update_attachment(size_t j);
  double attachment_share(const Strip& s, size_t i) const;  // of element i
  void break_strip(size_t j, int step);
  bool break_element(size_t j, size_t i, double f, int32_t* fe_out, int step);
  bool trigger_at(size_t j, double theta, int32_t* fe_out, int step);
  double epidermis_stiffness(size_t j, double theta, double rest, uint8_t level) const;
  double jittered_threshold(size_t j, double theta, StreamRng& rng) const;
  struct Sweep;
  void assign_new_fracture_ids(size_t j, Sweep& sw);
  void measure_fractures();
  void propagate_from(size_t j, Sweep& sw);
  double centre_theta(size_t j, size_t element) const;
  void refracture(size_t j, int step);
  void plasticity(size_t j, InglisSums* sums, double growth = 1.0);
  double width_factor(size_t j, double theta) const;

  StripDomain domain_;
  StripParams params_;
  std::vector<Strip> strips_;
  std::vector<std::vector<double>> cum_;  // per strip: #M+1 cumulative substrate arc length now
  std::vector<char>
      uniform_;  // per strip: all bins alike and no dilatation (θ ∝ x through the circumference; cum_ not kept current)
  std::vector<double> epidermis0_;  // per strip: original epidermis length E0
  // Per strip, for the current step: breaks (created + scripted), scripted breaks, hardened
  // fracture elements. Summed into stats_ after the parallel phases.
  std::vector<long long> breaks_, scripted_, hardened_, capped_, arrived_;
  std::vector<std::vector<double>> arrivals_;  // per strip: queued arrival angles
  FractureSkeleton skeleton_;
  std::vector<OpeningMode> modes_;
  StripStats stats_;
  std::vector<PropagationExit> exits_;
  // Per fracture id (valid at roots): number of fracture elements and their summed width,
  // for the Inglis ratio; kept up to date through one step's sweep.
  std::vector<double> fracture_count_, fracture_width_;
  // Per grower (0: the sweep's thread, 1: the helper; settle() uses 0): the fracture elements'
  // number and summed width per fracture id as strips settle (plasticity), for the next
  // measure_fractures(). Integers (widths in units of 2^-40 m, ~1e-12 m: a model's fractures can
  // hold 8·10^6 m of width in all before a sum overflows), so that the totals do not depend on
  // which thread settled which strip; sized to the ids at the last measure, which are all a
  // strip being settled can hold.
  struct InglisSums {
    std::vector<int64_t> width;
    std::vector<int32_t> count;
    // Makes room up to `id`: a fracture made since the last measure (out of line: add() is
    // inlined in the growth pass).
    [[gnu::noinline]] void cover(int32_t id) {
      width.resize(size_t(id) + 1, 0);
      count.resize(size_t(id) + 1, 0);
    }
    void add(int32_t id, double w) {
      assert(id >= 0);
      if (size_t(id) >= width.size()) [[unlikely]]
        cover(id);
      width[size_t(id)] += int64_t(w * 0x1p40 + 0.5);  // w >= 0
      count[size_t(id)] += 1;
    }
    void clear() {
      std::fill(width.begin(), width.end(), 0);
      std::fill(count.begin(), count.end(), 0);
    }
  };
  InglisSums sums_[2];
  std::vector<StripStats> strip_totals_;  // per strip: its counts since the last step() returned
  std::vector<int64_t> root_width_;       // measure_fractures(): scratch
  int step_ = 0;
  bool check_ = false;
  std::vector<double> residual_;            // per strip, when check_
  std::vector<EquilibriumFactor> factors_;  // per strip: reused while its stiffnesses are unchanged
  std::vector<char> over_;                  // per strip: an element exceeded its threshold after growth
  std::vector<char> pending_;               // per strip: the last step's hardening and plasticity are owed
  // Per strip: fracture elements with a free end this step and their element index (kept
  // current by break_element, the only place elements are inserted during the sweep), with
  // what propagation reads of them as the scan saw them: the sweep reads this list rather than
  // the elements, which another thread just wrote, unless the strip was touched since.
  struct FreeEnd {
    int32_t fracture;
    int32_t element;
    int32_t id = -1;
    bool up_free = true, down_free = true;
    double theta = 0;  // centre_theta() at the scan
  };
  std::vector<std::vector<FreeEnd>> tips_;
  // Per strip: broken or linked into since its scan (its FreeEnd copies are then stale).
  std::vector<char> touched_;
  FreeEnd free_end(size_t j, const Element& e, size_t i, double left, double length) const;
  // Per strip: element index of each fracture record (kept current by break_element).
  std::vector<std::vector<int32_t>> element_of_;
  // Per strip, for the Inglis ratios: (fracture id, width) of the fracture elements born since
  // the last measure, at birth (those settled since are in sums_). measure_fractures() sums them.
  std::vector<std::vector<std::pair<int32_t, double>>> born_;
  bool sharp(int32_t id) const;  // as the last measure left it (sharp_tips)
  // One free side of a fracture end about to propagate (sec. 3.2.4), and where it would cut
  // its neighbour strip (aim()).
  struct PropagationSide {
    size_t tip = 0;            // fracture element (index in its strip)
    int32_t fe = -1;           // its fracture record
    int32_t id = -1;           // its fracture id
    bool up = true;            // towards the next strip (s+), else the previous
    double theta = 0;          // final-shape angle of the tip
    double jitter = 0;         // random angle added to the direction (radians)
    size_t target = SIZE_MAX;  // neighbour strip (SIZE_MAX: none)
    bool advances = false;     // aim(): strained bark or a fracture's influence lets the tip advance
    double x = 0;              // aim(): arc position of the cut on the target strip
    size_t element = 0;        // aim(): the target element containing it
    // aim(): it advances onto a fracture (a merge) or onto bark in tension (a break); any other
    // side changes nothing.
    bool lands = false;
    // Draws for the irregular-fissure extension (1: never), in [0, 1).
    double join = 1, fork = 1;
    bool deviated = false;  // aim_side(): drawn to another fracture (anastomosis)
  };
  // Epidermis element i of `s` strained enough for a fracture tip to cut it.
  bool strained(const Strip& s, size_t i) const;
  // Distance from arc position x to fracture element i of `s` if its influence reaches x,
  // else +∞.
  double influence_distance(const Strip& s, size_t i, double x) const;
  void aim(size_t j, PropagationSide& side) const;
  // The irregular-fissure extension (fracture_irregularity.cpp; our own, not the paper's).
  // Final arc length of strip j (m).
  double final_circumference(size_t j) const;
  // Smooth value noise in [-1, 1] at strip j, angle θ, cells `size` metres along the strips and
  // 4 × size across (weakness_noise).
  double smooth_noise(size_t j, double theta, double size, uint64_t salt) const;
  // Bark at strip j, angle θ is a tough spot that arrests propagating tips (toughness_fraction).
  bool tough(size_t j, double theta) const;
  // aim(), then anastomosis: a side that advances may deviate to meet another fracture.
  void aim_side(size_t j, PropagationSide& side, const Sweep& sw) const;
  // Forking: a second cut on the target strip after a side broke it at side.x.
  void fork(PropagationSide& side, Sweep& sw);
  // A side of a free end aimed at a strip of the other half of the sweep: replayed at the
  // block's end (cross()).
  struct Crossing {
    size_t strip = 0, target = 0;
    int32_t fe = -1;  // its fracture record (element indices may shift before the replay)
    bool up = true;
    double jitter = 0;
    double join = 1, fork = 1;
    int step = 0;
  };
  // One half of a block's sweep: what it changes of the fracture bookkeeping, kept apart from
  // the other half's until the block's end.
  struct Sweep {
    int half = 0;
    int step = 0;                      // the step being swept (draws, births, scripted fractures)
    FractureSkeleton skeleton;         // the block's start + this half's merges and new ids
    std::vector<double> count, width;  // Inglis measure by root, as this half sees it
    int32_t made = 0;                  // new fracture ids made: base + made·stride + half
    int32_t base = 0, stride = 1;
    std::vector<std::pair<int32_t, int32_t>> merges;  // replayed on skeleton_ at the block's end
    std::vector<Crossing> crossings;
    std::vector<PropagationExit> exits;
    std::vector<PropagationSide> sides;  // propagate_from's scratch list
    long long propagated = 0, joined = 0, forked = 0;
    int32_t make_id() {
      const int32_t id = base + made++ * stride + half;
      skeleton.extend(size_t(id) + 1);
      count.resize(size_t(id) + 1, 0.0);
      width.resize(size_t(id) + 1, 0.0);
      return id;
    }
    bool sharp(int32_t id, double strip_width, double inglis_threshold) const;
  };
  Sweep sweeps_[2];
  Sweep replay_;                    // the block's end: crossings replayed on the joined skeleton
  std::vector<char> owner_;         // per strip: the half sweeping it in this block
  std::vector<int> grown_step_[2];  // per half, per strip of its run: the last step grown for
  void start_sweep(Sweep& sw, int half, int halves);
  void join_sweeps(int halves);
  void sweep_half(int half, size_t first, size_t count, int K);
  // Aims a prepared side and, if it lands, breaks or merges into its target and links both
  // ways (sec. 3.2.4); true when the target strip changed.
  bool land(size_t j, PropagationSide& side, Sweep& sw);
  void cross(const Crossing& c, Sweep& sw);
  OpeningMode draw_opening_mode(int32_t id) const;
  void scan_strip(size_t j);
  void prefetch_positions(size_t j) const;
  void solve(size_t j);
};

}  // namespace phellem::bark

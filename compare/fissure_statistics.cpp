#include "compare/fissure_statistics.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "compare/colour_statistics.h"
#include "compare/distance_transform.h"
#include "compare/fissure_mask.h"
#include "compare/fissure_spacing.h"
#include "compare/orientation_histogram.h"
#include "compare/percentile.h"
#include "compare/skeleton.h"
#include "compare/structure_tensor.h"
#include "util/errors.h"

namespace phellem {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Plan §3.0: refuse what cannot be measured, saying what is wrong and what is allowed.
void check_measurable(const HeightField& f, const std::string& name, const CompareParams& p) {
  if (f.width <= 0 || f.height <= 0 || f.z.size() != size_t(f.width) * size_t(f.height))
    throw UserError(name, "", "the height field has no pixels (or fewer than width × height values)");
  if (!(f.px_per_cm >= p.min_px_per_cm) || !std::isfinite(f.px_per_cm))
    throw UserError(name, "",
                    "the scale is " + fmt(f.px_per_cm) + " px/cm; compare needs at least " + fmt(p.min_px_per_cm) +
                        " px/cm to see the fissures");
  const double w_cm = f.width / f.px_per_cm, h_cm = f.height / f.px_per_cm;
  if (f.width < p.min_size_px || f.height < p.min_size_px || w_cm < p.min_size_cm || h_cm < p.min_size_cm)
    throw UserError(name, "",
                    "the image is " + std::to_string(f.width) + "×" + std::to_string(f.height) + " px (" + fmt(w_cm) + "×" +
                        fmt(h_cm) + " cm at " + fmt(f.px_per_cm) + " px/cm); compare needs at least " +
                        std::to_string(p.min_size_px) + " px and " + fmt(p.min_size_cm) + " cm on each side");
  for (float v : f.z)
    if (!std::isfinite(v)) throw UserError(name, "", "the heights hold a NaN or infinite value; all must be finite");
  const auto [lo, hi] = std::minmax_element(f.z.begin(), f.z.end());
  if (*lo == *hi)
    throw UserError(name, "",
                    "the relief is constant (every height is " + fmt(*lo) + "); compare needs a height field with fissures");
}

}  // namespace

FissureAnalysis analyse_fissures(const HeightField& field, const AlbedoField* albedo, const std::string& name) {
  const CompareParams& p = kCompareParams;
  check_measurable(field, name, p);
  if (albedo && (albedo->width != field.width || albedo->height != field.height || albedo->rgb.size() != 3 * field.z.size()))
    throw UserError(name, "",
                    "the albedo is " + std::to_string(albedo->width) + "×" + std::to_string(albedo->height) +
                        " px but the heights are " + std::to_string(field.width) + "×" + std::to_string(field.height) +
                        "; they must cover the same pixels");
  const int W = field.width, H = field.height;
  const double s = field.px_per_cm;
  const size_t n = field.z.size();

  // §3.0: z ← (z − mean)/std, the mean and std in double, the heights then in float (every
  // later figure is a percentile or a ratio; float moves none of them by 1e-6). So the figures do
  // not change under z → a·z + b (a > 0).
  const MeanStd m = mean_std(field.z);
  std::vector<float> z(n);
  for (size_t i = 0; i < n; ++i) z[i] = float((double(field.z[i]) - m.mean) / m.std);

  FissureAnalysis out;
  out.field = field;
  FissureMask fm = fissure_mask(z, W, H, s, p);
  FissureStats& st = out.stats;
  st.components = fm.components.count;

  // §3.2
  size_t area = 0;
  for (uint8_t v : fm.mask) area += v;
  st.fissure_fraction = double(area) / double(n);

  // The statistics below only read the mask, its components and hp/hs: four independent
  // tasks, so the serial ones (spacing, extents, ridge and percentiles) overlap the parallel
  // skeleton, structure tensor and distance transform. Each task writes its own fields of st.
  std::vector<uint8_t> ridge;
  tbb::parallel_invoke(
      [&] {
        // §3.3: orientation of the smoothed high-pass at the skeleton pixels, length-weighted.
        const std::vector<uint8_t> skeleton = zhang_suen_skeleton(fm.mask, W, H);
        std::vector<size_t> skeleton_pixels;
        for (size_t i = 0; i < n; ++i)
          if (skeleton[i]) skeleton_pixels.push_back(i);
        const std::vector<double> angles = fissure_angles_deg(fm.hs, W, H, p.tensor_sigma_cm * s, p.blur_border, skeleton_pixels);
        const OrientationSummary o = orientation_summary(angles, p.vertical_halfwidth_deg);
        std::copy(o.histogram.begin(), o.histogram.end(), st.orientation_hist.begin());
        st.vertical_fraction = o.vertical_fraction;
        st.orientation_mean_deg = o.mean_deg;
        st.skeleton_length_cm = o.total_weight / s;

        // §3.5: mean width = area / skeleton length (exact for long stripes); the spread from the
        // distance transform on the skeleton, 2·EDT − 1 (exact for odd widths, 1 px low for even).
        if (o.total_weight > 0) st.width_mean = double(area) / o.total_weight / s;
        const std::vector<double> edt = euclidean_distance_transform(fm.mask, W, H);
        for (size_t i : skeleton_pixels) st.widths_cm.push_back((2 * edt[i] - 1) / s);
        st.width_std = mean_std(st.widths_cm).std;
      },
      [&] {
        // §3.4: spacing along rows and along columns.
        std::vector<double> gaps_h = run_spacings_px(fm.mask, W, H, true), gaps_v = run_spacings_px(fm.mask, W, H, false);
        for (double& g : gaps_h) g /= s;
        for (double& g : gaps_v) g /= s;
        const MeanStd sh = mean_std(gaps_h), sv = mean_std(gaps_v);
        st.spacing_h_mean = sh.mean;
        st.spacing_h_std = sh.std;
        st.spacing_v_mean = sv.mean;
        st.spacing_v_std = sv.std;
        st.spacings_h_cm = std::move(gaps_h);
      },
      [&] {
        // §3.6: the vertical extent of each component (bounding-box height). A component cut by the
        // image border is kept with its truncated extent.
        std::vector<int> top(size_t(fm.components.count) + 1, H), bottom(size_t(fm.components.count) + 1, -1);
        for (int y = 0; y < H; ++y)
          for (int x = 0; x < W; ++x) {
            const auto l = size_t(fm.components.label[size_t(y) * size_t(W) + size_t(x)]);
            if (!l) continue;
            top[l] = std::min(top[l], y);
            bottom[l] = std::max(bottom[l], y);
          }
        std::vector<double> extents;
        for (size_t l = 1; l < top.size(); ++l) extents.push_back((bottom[l] - top[l] + 1) / s);
        st.length_median = median(extents);
      },
      [&] {
        // §3.7: how deep the fissures are against the relief of the ridges between them.
        ridge = ridge_mask(fm.mask, W, H, s, p);
        std::vector<float> hp_ridge, hp_mask;
        for (size_t i = 0; i < n; ++i) {
          if (ridge[i]) hp_ridge.push_back(fm.hp[i]);
          if (fm.mask[i]) hp_mask.push_back(fm.hp[i]);
        }
        if (!hp_ridge.empty() && !hp_mask.empty()) {
          const std::vector<double> q = percentiles(std::move(hp_ridge), {10, 50, 90});
          const double depth = q[1] - median(std::move(hp_mask));
          const double relief = q[2] - q[0];
          st.depth_ratio = depth / std::max(relief, 1e-12);
        }
      });

  // §3.8 (optional, not scored).
  if (albedo) st.colour = colour_statistics(*albedo, fm.mask, ridge);
  out.mask = std::move(fm.mask);
  return out;
}

}  // namespace phellem

#include "compare/report_json.h"

#include "compare/statistic_names.h"

namespace phellem {

namespace {

const char* origin_name(ScaleOrigin o) {
  switch (o) {
    case ScaleOrigin::option: return "--scale";
    case ScaleOrigin::header: return "header";
    case ScaleOrigin::render_positions: return "position layer";
  }
  return "";
}

// Which pixels of a render were measured.
nlohmann::json render_json(const RenderSelection& r) {
  return {{"render_size_px", {r.render_width, r.render_height}},
          {"rect", {{"x", r.rect.x}, {"y", r.rect.y}, {"w", r.rect.width}, {"h", r.rect.height}}},
          {"object_id", r.object_id},
          {"object_from", r.object_chosen ? "--object" : "most pixels"},
          {"object_pixels", r.object_pixels},
          {"mask_pixels", r.mask_pixels},
          {"facing_deg", r.facing_deg},
          {"position_px_per_cm", {r.position_px_per_cm_x, r.position_px_per_cm_y}}};
}

nlohmann::json input_json(const PreparedInput& in, const FissureAnalysis& an) {
  nlohmann::json j;
  j["file"] = in.source.path;
  if (!in.source.albedo_path.empty()) j["albedo"] = in.source.albedo_path;
  else if (in.albedo_from_render) j["albedo"] = "albedo layer";
  j["source_px_per_cm"] = {in.source_px_per_cm_x, in.source_px_per_cm_y};
  j["source_px_per_cm_from"] = origin_name(in.scale_origin);
  if (in.render) j["render"] = render_json(*in.render);
  j["size_px"] = {in.field.width, in.field.height};
  j["size_cm"] = {in.field.width / in.field.px_per_cm, in.field.height / in.field.px_per_cm};
  nlohmann::json stats = nlohmann::json::object();
  for (const NamedStatistic& s : named_statistics(an.stats)) stats[s.name] = s.value;
  j["statistics"] = stats;
  j["orientation_histogram"] = an.stats.orientation_hist;
  return j;
}

nlohmann::json params_json() {
  const CompareParams& p = kCompareParams;
  return {{"highpass_sigma_cm", p.highpass_sigma_cm},
          {"smooth_sigma_cm", p.smooth_sigma_cm},
          {"threshold_percentile", p.threshold_percentile},
          {"min_component_cm2", p.min_component_cm2},
          {"tensor_sigma_cm", p.tensor_sigma_cm},
          {"vertical_halfwidth_deg", p.vertical_halfwidth_deg},
          {"ridge_dilation_cm", p.ridge_dilation_cm},
          {"min_size_cm", p.min_size_cm},
          {"min_size_px", p.min_size_px},
          {"min_px_per_cm", p.min_px_per_cm},
          {"orientation_bins", kOrientationBins}};
}

}  // namespace

nlohmann::json report_json(const CompareReport& r) {
  nlohmann::json j;
  j["score"] = r.comparison.score;
  j["orientation_emd_deg"] = r.comparison.orientation_emd_deg;
  j["verdict"] = r.comparison.verdict;
  j["same_bark_score"] = kSameBarkScore;
  j["close_score"] = kCloseScore;
  j["px_per_cm"] = r.px_per_cm;
  nlohmann::json diff = nlohmann::json::object();
  for (const StatisticDifference& d : r.comparison.core) diff[d.name] = d.difference;
  j["differences"] = diff;
  j["inputs"] = {{r.a.source.label, input_json(r.a, r.analysis_a)}, {r.b.source.label, input_json(r.b, r.analysis_b)}};
  j["parameters"] = params_json();
  return j;
}

}  // namespace phellem

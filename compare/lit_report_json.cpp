#include "compare/lit_report_json.h"

#include "compare/lit_statistic_names.h"

namespace phellem {
namespace {

nlohmann::json side_json(const LitStatistics& s) {
  nlohmann::json stats = nlohmann::json::object();
  for (const NamedStatistic& n : named_lit_statistics(s)) stats[n.name] = n.value;
  return {{"size_px", {s.width, s.height}},
          {"px_per_cm", s.px_per_cm},
          {"valid_pixels", s.valid_pixels},
          {"statistics", stats},
          {"orientation_histogram", s.orientation_hist}};
}

}  // namespace

nlohmann::json lit_comparison_json(const LitStatistics& reference, const LitStatistics& candidate, const LitComparison& c,
                                   const LitThresholds& t) {
  nlohmann::json j;
  j["score"] = c.score;
  j["verdict"] = c.verdict;
  j["words"] = c.words;
  j["orientation_emd_deg"] = c.orientation_emd_deg;
  nlohmann::json groups = nlohmann::json::object();
  for (const LitGroupScore& g : c.groups) groups[g.group] = g.score;
  j["groups"] = groups;
  nlohmann::json diff = nlohmann::json::object();
  for (const LitDifference& d : c.differences)
    diff[d.name] = {{"group", d.group},
                    {"reference", d.reference},
                    {"candidate", d.candidate},
                    {"signed_difference", d.signed_difference},
                    {"difference", d.difference}};
  j["differences"] = diff;
  j["thresholds"] = {{"same_score", t.same_score},
                     {"close_score", t.close_score},
                     {"word", t.word},
                     {"cast_delta_e", t.cast_delta_e},
                     {"orientation_emd_deg", t.orientation_emd_deg},
                     {"fine_band_cycles_per_cm", t.fine_band_cycles_per_cm}};
  j["reference"] = side_json(reference);
  j["candidate"] = side_json(candidate);
  return j;
}

}  // namespace phellem

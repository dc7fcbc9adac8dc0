// STAND-IN until branch `report22` lands: a plain JSON and a minimal HTML table. At the merge,
// write_fit_reports calls the compare report writers (compare/report_json.h, report_html.h)
// and adds the `fit` object.
#include "cli/fit_report.h"

#include <filesystem>
#include <fstream>

#include "cli/outputs.h"
#include "util/errors.h"

namespace phellem {

namespace {

nlohmann::json stats_json(const FissureStats& s) {
  return {{"fissure_fraction", s.fissure_fraction}, {"vertical_fraction", s.vertical_fraction},
          {"orientation_mean_deg", s.orientation_mean_deg}, {"spacing_h_mean", s.spacing_h_mean},
          {"spacing_h_std", s.spacing_h_std}, {"spacing_v_mean", s.spacing_v_mean}, {"spacing_v_std", s.spacing_v_std},
          {"width_mean", s.width_mean}, {"width_std", s.width_std}, {"length_median", s.length_median},
          {"depth_ratio", s.depth_ratio}};
}

}  // namespace

void write_fit_reports(OutputSet& out, const std::string& dir, const FitReportInputs& in) {
  const std::filesystem::path d(dir);
  nlohmann::json j;
  j["a"] = {{"name", in.photo_name}, {"stats", stats_json(in.photo->stats)}};
  j["b"] = {{"name", in.patch_name}, {"stats", stats_json(in.patch->stats)}};
  j["score"] = in.comparison.score;
  j["orientation_emd_deg"] = in.comparison.orientation_emd_deg;
  j["verdict"] = in.comparison.verdict;
  for (const auto& c : in.comparison.core) j["core"].push_back({{"name", c.name}, {"a", c.a}, {"b", c.b}, {"difference", c.difference}});
  j["fit"] = in.fit;
  write_json_output(out, "-o", (d / "report.json").string(), j);
  const std::string html = (d / "report.html").string();
  out.write("-o", html, [&](const std::string& tmp) {
    std::ofstream f(tmp);
    f << "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>phellem fit</title></head><body>\n"
      << "<h1>phellem fit: " << in.comparison.verdict << "</h1><p>score " << in.comparison.score << ", orientation EMD "
      << in.comparison.orientation_emd_deg << "&deg;</p>\n<table><tr><th>statistic</th><th>photo</th><th>fit</th><th>difference</th></tr>\n";
    for (const auto& c : in.comparison.core)
      f << "<tr><td>" << c.name << "</td><td>" << c.a << "</td><td>" << c.b << "</td><td>" << c.difference << "</td></tr>\n";
    f << "</table></body></html>\n";
    f.close();
    if (!f) throw UserError(html, "-o", "cannot write");
  });
}

}  // namespace phellem

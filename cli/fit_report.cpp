#include "cli/fit_report.h"

#include <filesystem>

#include "cli/outputs.h"
#include "compare/report_html.h"
#include "compare/report_json.h"

namespace phellem {

void write_fit_reports(OutputSet& out, const std::string& dir, const CompareReport& report, const nlohmann::json& fit) {
  const std::filesystem::path d(dir);
  nlohmann::json j = report_json(report);
  j["fit"] = fit;
  write_json_output(out, "-o", (d / "report.json").string(), j);
  const std::string html = (d / "report.html").string(), text = report_html(report);
  out.write_bytes("-o", html, text);
}

}  // namespace phellem

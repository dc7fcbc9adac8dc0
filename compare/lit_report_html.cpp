#include "compare/lit_report_html.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "compare/html_text.h"
#include "compare/report_images.h"
#include "io/png_encode.h"

namespace phellem {

namespace {

constexpr int kMaxShownWidth = 640;  // CSS px of the wider render

double luminance(const LitImage& im, size_t p) {
  return 0.2126 * im.rgb[p * 3] + 0.7152 * im.rgb[p * 3 + 1] + 0.0722 * im.rgb[p * 3 + 2];
}

// Signed log-luminance difference B − A over the pixels both pictures have (top left aligned):
// blue where the candidate is darker, red where it is lighter, white where they agree; ±1.5
// (a factor 4.5) saturates.
std::vector<unsigned char> difference_png(const LitImage& a, const LitImage& b, double floor) {
  const int w = std::min(a.width, b.width), h = std::min(a.height, b.height);
  std::vector<uint8_t> px(size_t(w) * size_t(h) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double ya = luminance(a, size_t(y) * size_t(a.width) + size_t(x)), yb = luminance(b, size_t(y) * size_t(b.width) + size_t(x));
      const double d = std::clamp(std::log(std::max(yb, floor)) - std::log(std::max(ya, floor)), -1.5, 1.5) / 1.5;
      uint8_t* o = &px[(size_t(y) * size_t(w) + size_t(x)) * 3];
      const double keep = 1.0 - std::abs(d);
      o[0] = uint8_t(std::lround(255 * (d > 0 ? 1.0 : keep)));
      o[1] = uint8_t(std::lround(255 * keep));
      o[2] = uint8_t(std::lround(255 * (d < 0 ? 1.0 : keep)));
    }
  return encode_png(w, h, 3, px.data());
}

std::string group_title(const std::string& g) {
  if (g == "tone") return "Tone: log-luminance percentiles relative to the median";
  if (g == "dark") return "Near-black pixels (below 3 % of the median)";
  if (g == "orientation") return "Gradient orientation";
  if (g == "spectrum") return "Power spectrum of log-luminance (share per octave, cycles/cm)";
  if (g == "contrast") return "Local contrast (std of log-luminance per scale)";
  if (g == "colour") return "Colour in CIELAB (cast and spread)";
  return g;
}

std::string verdict_class(const std::string& v) { return v == "same look" ? "same" : v == "close" ? "close" : "different"; }

}  // namespace

std::vector<unsigned char> lit_render_png(const LitImage& image, double exposure) {
  AlbedoField f;
  f.width = image.width;
  f.height = image.height;
  f.rgb = image.rgb;
  for (float& v : f.rgb) v = float(v * exposure);
  return albedo_png(f, std::max(image.width, image.height));
}

std::string lit_report_html(const LitReportSide& ref, const LitReportSide& cand, const LitComparison& c, const std::string& rig) {
  const double exposure = 0.18 / std::max(ref.stats->median_luminance, 1e-12);
  const int widest = std::max(ref.image->width, cand.image->width);
  const double css = std::min(1.0, double(kMaxShownWidth) / widest);  // the same CSS px per render px for both
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>phellem compare --lit: " << html_escape(ref.path)
    << " vs " << html_escape(cand.path) << "</title><style>\n"
    << "body{font-family:sans-serif;margin:24px;color:#222;max-width:1400px}h1{font-size:22px;margin:0 0 6px}"
       "h2{font-size:17px;margin:26px 0 8px;border-bottom:1px solid #ddd}h3{font-size:14px;margin:16px 0 4px}"
       ".verdict{font-size:28px;font-weight:bold;padding:10px 16px;border-radius:6px;display:inline-block}"
       ".same{background:#d9f0d9;color:#1f5f1f}.close{background:#f7e7c6;color:#7a5208}.different{background:#f5d3d3;color:#7d1f1f}"
       ".words{font-size:20px;margin:12px 0}.words li{margin:4px 0}"
       ".pair{display:flex;gap:16px;flex-wrap:wrap;align-items:flex-start}.pair figure{margin:0}"
       ".pair img{border:1px solid #bbb;image-rendering:auto}figcaption{font-size:12px;color:#444;margin-top:4px;max-width:640px}"
       "table{border-collapse:collapse;font-size:13px}td,th{padding:3px 8px;border-bottom:1px solid #eee;text-align:left}"
       ".bar{display:inline-block;height:9px;vertical-align:middle}.a{background:#3b6fb6}.b{background:#d9822b}"
       ".note{font-size:12px;color:#555}\n"
    << "</style></head><body>\n";
  s << "<h1>phellem compare --lit</h1><div class=\"verdict " << verdict_class(c.verdict) << "\" id=\"verdict\">"
    << html_escape(c.verdict) << " — score " << html_fixed(c.score, 3) << "</div>";
  s << "<ul class=\"words\" id=\"words\">";
  if (c.words.empty()) s << "<li>nothing stands out</li>";
  for (const std::string& w : c.words) s << "<li>" << html_escape(w) << "</li>";
  s << "</ul><p>" << html_escape(rig) << " Both renders at " << html_fixed(ref.image->px_per_cm, 2)
    << " px/cm, one exposure (the reference's median luminance shown as middle grey).</p>";

  s << "<h2>Renders at their true relative size</h2><div class=\"pair\">";
  for (const LitReportSide* side : {&ref, &cand}) {
    const LitImage& im = *side->image;
    const std::string style = "style=\"width:" + html_fixed(im.width * css, 1) + "px;height:" + html_fixed(im.height * css, 1) + "px\"";
    s << "<figure>" << html_img(lit_render_png(im, exposure), side->label + " render", style + " class=\"render\"")
      << "<figcaption><b>" << html_escape(side->label) << (side == &ref ? " (reference)" : " (candidate)") << "</b>: "
      << html_escape(side->path) << "<br>" << im.width << "×" << im.height << " px = " << html_fixed(im.width / im.px_per_cm, 1)
      << "×" << html_fixed(im.height / im.px_per_cm, 1) << " cm. " << html_escape(side->note) << "</figcaption></figure>";
  }
  s << "</div>";
  const LitImage& a = *ref.image;
  const LitImage& b = *cand.image;
  const double floor = 1e-4 * std::max(ref.stats->median_luminance, 1e-12);
  s << "<h2>Difference (log-luminance, B − A, over the pixels both have)</h2><div class=\"pair\"><figure>"
    << html_img(difference_png(a, b, floor), "difference",
                "style=\"width:" + html_fixed(std::min(a.width, b.width) * css, 1) + "px\"")
    << "<figcaption>Blue: the candidate is darker; red: lighter; white: equal (saturates at a factor of 4.5). Two different "
       "pieces of bark differ pixel by pixel; the statistics below say whether they differ in kind.</figcaption></figure></div>";

  s << "<h2>Statistics</h2><p class=\"note\"><span class=\"bar a\" style=\"width:12px\"></span> A (reference) "
       "<span class=\"bar b\" style=\"width:12px\"></span> B (candidate). Each difference is (B − A) / max(|A|, |B|, floor); "
       "the score is the mean over the groups of each group's mean |difference|.</p>";
  for (const LitGroupScore& g : c.groups) {
    s << "<h3>" << html_escape(group_title(g.group)) << " — " << html_fixed(g.score, 3) << "</h3><table><tr><th>statistic</th><th>A</th><th>B</th><th></th><th>difference</th></tr>";
    for (const LitDifference& d : c.differences) {
      if (d.group != g.group) continue;
      const double scale = std::max({std::abs(d.reference), std::abs(d.candidate), 1e-12});
      s << "<tr><td>" << html_escape(d.name) << "</td><td>" << html_fixed(d.reference, 4) << "</td><td>" << html_fixed(d.candidate, 4)
        << "</td><td><span class=\"bar a\" style=\"width:" << html_fixed(120 * std::abs(d.reference) / scale, 1)
        << "px\"></span><br><span class=\"bar b\" style=\"width:" << html_fixed(120 * std::abs(d.candidate) / scale, 1)
        << "px\"></span></td><td>" << html_fixed(d.signed_difference, 3) << "</td></tr>";
    }
    s << "</table>";
  }
  s << "<p class=\"note\">Orientation distance (earth mover's, edge directions): " << html_fixed(c.orientation_emd_deg, 1)
    << "°. See docs/compare.md, \"Lit statistics\".</p></body></html>\n";
  return s.str();
}

}  // namespace phellem

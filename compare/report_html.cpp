#include "compare/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "compare/html_text.h"
#include "compare/report_images.h"
#include "compare/statistic_names.h"

namespace phellem {

namespace {

constexpr const char* kColourA = "#2f6db5";  // input A in every chart
constexpr const char* kColourB = "#d9822b";  // input B

// The shared pieces (compare/html_text.h) under this file's short names.
std::string escape(const std::string& text) { return html_escape(text); }
std::string fixed(double v, int digits) { return html_fixed(v, digits); }
std::string img(const std::vector<unsigned char>& png, const std::string& alt) { return html_img(png, alt); }

// Orientation rose: one wedge per 10° bin, mirrored (a fissure direction is an axis), radius
// ∝ √share so that wedge area reads as share of fissure length. 90° points up.
std::string rose(const FissureStats& a, const FissureStats& b) {
  const double cx = 130, cy = 130, r_max = 115;
  double peak = 1e-12;
  for (int i = 0; i < kOrientationBins; ++i) peak = std::max({peak, a.orientation_hist[i], b.orientation_hist[i]});
  std::ostringstream s;
  s << "<svg class=\"chart\" viewBox=\"0 0 260 260\" width=\"260\" height=\"260\" role=\"img\">";
  for (double f : {0.25, 0.5, 0.75, 1.0})
    s << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << r_max * std::sqrt(f)
      << "\" fill=\"none\" stroke=\"#ccc\" stroke-width=\"0.7\"/>";
  s << "<line x1=\"" << cx << "\" y1=\"5\" x2=\"" << cx << "\" y2=\"255\" stroke=\"#bbb\" stroke-width=\"0.7\"/>";
  s << "<line x1=\"5\" y1=\"" << cy << "\" x2=\"255\" y2=\"" << cy << "\" stroke=\"#bbb\" stroke-width=\"0.7\"/>";
  auto wedges = [&](const FissureStats& st, const char* colour) {
    for (int i = 0; i < kOrientationBins; ++i) {
      const double r = r_max * std::sqrt(st.orientation_hist[i] / peak);
      if (r < 0.5) continue;
      for (double base : {0.0, 180.0}) {
        const double a0 = (base + 10.0 * i - 5.0) * std::numbers::pi / 180.0;
        const double a1 = (base + 10.0 * i + 5.0) * std::numbers::pi / 180.0;
        s << "<path d=\"M" << cx << "," << cy << " L" << fixed(cx + r * std::cos(a0), 2) << ","
          << fixed(cy - r * std::sin(a0), 2) << " A" << fixed(r, 2) << "," << fixed(r, 2) << " 0 0 0 "
          << fixed(cx + r * std::cos(a1), 2) << "," << fixed(cy - r * std::sin(a1), 2) << " Z\" fill=\"" << colour
          << "\" fill-opacity=\"0.45\" stroke=\"" << colour << "\" stroke-width=\"0.8\"/>";
      }
    }
  };
  wedges(a, kColourA);
  wedges(b, kColourB);
  s << "<text x=\"" << cx + 4 << "\" y=\"14\" font-size=\"10\" fill=\"#666\">90° (along the trunk)</text>";
  s << "<text x=\"212\" y=\"" << cy - 4 << "\" font-size=\"10\" fill=\"#666\">0°</text>";
  s << "</svg>";
  return s.str();
}

// Histogram of two samples on shared bins, as shares of each sample.
std::string histogram(const std::vector<double>& a, const std::vector<double>& b, const std::string& unit) {
  constexpr int kBins = 24;
  const double w = 520, h = 200, left = 40, bottom = 30;
  std::vector<double> all = a;
  all.insert(all.end(), b.begin(), b.end());
  std::ostringstream s;
  s << "<svg class=\"chart\" viewBox=\"0 0 " << w << " " << h << "\" width=\"" << w << "\" height=\"" << h << "\" role=\"img\">";
  if (all.empty()) {
    s << "<text x=\"20\" y=\"100\" font-size=\"12\">no samples</text></svg>";
    return s.str();
  }
  std::sort(all.begin(), all.end());
  const double top = std::max(all[std::min(all.size() - 1, size_t(double(all.size()) * 0.99))], 1e-9);
  auto shares = [&](const std::vector<double>& v) {
    std::vector<double> c(kBins, 0.0);
    for (double x : v) c[std::clamp(int(x / top * kBins), 0, kBins - 1)] += 1.0;
    for (double& x : c) x /= std::max<double>(1.0, double(v.size()));
    return c;
  };
  const auto ca = shares(a), cb = shares(b);
  const double peak = std::max(*std::max_element(ca.begin(), ca.end()), *std::max_element(cb.begin(), cb.end()));
  const double plot_w = w - left - 10, plot_h = h - bottom - 10, bar = plot_w / kBins;
  for (int i = 0; i < kBins; ++i) {
    const double ha = peak > 0 ? ca[i] / peak * plot_h : 0, hb = peak > 0 ? cb[i] / peak * plot_h : 0;
    s << "<rect x=\"" << fixed(left + i * bar, 2) << "\" y=\"" << fixed(10 + plot_h - ha, 2) << "\" width=\""
      << fixed(bar / 2, 2) << "\" height=\"" << fixed(ha, 2) << "\" fill=\"" << kColourA << "\"/>";
    s << "<rect x=\"" << fixed(left + i * bar + bar / 2, 2) << "\" y=\"" << fixed(10 + plot_h - hb, 2) << "\" width=\""
      << fixed(bar / 2, 2) << "\" height=\"" << fixed(hb, 2) << "\" fill=\"" << kColourB << "\"/>";
  }
  s << "<line x1=\"" << left << "\" y1=\"" << 10 + plot_h << "\" x2=\"" << w - 10 << "\" y2=\"" << 10 + plot_h
    << "\" stroke=\"#444\"/>";
  for (int t = 0; t <= 4; ++t)
    s << "<text x=\"" << fixed(left + plot_w * t / 4 - (t == 4 ? 12 : 0), 1) << "\" y=\"" << h - 10 << "\" font-size=\"11\" text-anchor=\"middle\">"
      << fixed(top * t / 4, 1) << (t == 4 ? " " + unit : std::string()) << "</text>";
  s << "</svg>";
  return s.str();
}

const char* verdict_class(const std::string& verdict) {
  if (verdict == "same bark") return "same";
  if (verdict == "close") return "close";
  return "different";
}

// The difference as a bar on [0, 1] with the same-bark band marked.
std::string difference_bar(double d) {
  std::ostringstream s;
  const double w = 160;
  s << "<svg viewBox=\"0 0 " << w << " 14\" width=\"" << w << "\" height=\"14\">"
    << "<rect x=\"0\" y=\"2\" width=\"" << w * kSameBarkScore << "\" height=\"10\" fill=\"#cfe8cf\"/>"
    << "<rect x=\"0\" y=\"5\" width=\"" << fixed(w * std::clamp(d, 0.0, 1.0), 2) << "\" height=\"4\" fill=\""
    << (d <= kSameBarkScore ? "#3c8d3c" : d <= kCloseScore ? "#c98b1a" : "#b83a3a") << "\"/></svg>";
  return s.str();
}

std::string statistics_table(const CompareReport& r) {
  const auto sa = named_statistics(r.analysis_a.stats), sb = named_statistics(r.analysis_b.stats);
  std::ostringstream s;
  s << "<table><tr><th>statistic</th><th>" << escape(r.a.source.label) << "</th><th>" << escape(r.b.source.label)
    << "</th><th>difference</th><th>against the same-bark band (≤ " << fixed(kSameBarkScore, 2)
    << ")</th><th>meaning</th></tr>";
  for (size_t i = 0; i < sa.size(); ++i) {
    const NamedStatistic& a = sa[i];
    const double b = i < sb.size() && sb[i].name == a.name ? sb[i].value : NAN;
    const auto d = std::find_if(r.comparison.core.begin(), r.comparison.core.end(),
                                [&](const StatisticDifference& x) { return x.name == a.name; });
    s << "<tr" << (a.core ? " class=\"core\"" : "") << "><td><code>" << a.name << "</code>" << (a.core ? " ●" : "")
      << "</td><td>" << fixed(a.value, 3) << " " << a.unit << "</td><td>" << fixed(b, 3) << " " << a.unit << "</td>";
    if (d != r.comparison.core.end())
      s << "<td>" << fixed(d->difference, 3) << "</td><td>" << difference_bar(d->difference) << "</td>";
    else
      s << "<td></td><td></td>";
    s << "<td>" << escape(a.description) << "</td></tr>";
  }
  s << "</table><p class=\"note\">● in the score: the mean of |a − b| / max(|a|, |b|) over these. "
       "Two halves of one scan score 0.03–0.13 (the green band): below "
    << fixed(kSameBarkScore, 2) << " is “same bark”, below " << fixed(kCloseScore, 2)
    << " “close”. Every statistic is described in docs/compare.md.</p>";
  return s.str();
}

const char* origin_text(ScaleOrigin o) {
  switch (o) {
    case ScaleOrigin::option: return "given by --scale";
    case ScaleOrigin::header: return "stated by the file";
    case ScaleOrigin::render_positions:
      return "from the position layer: the median distance between adjacent pixels of the rectangle";
  }
  return "";
}

// Which pixels of a render were measured, and why.
std::string render_caption(const PreparedInput& in) {
  const RenderSelection& r = *in.render;
  std::ostringstream s;
  s << "<br>render " << r.render_width << "×" << r.render_height << " px; measured: the rectangle x " << r.rect.x << ", y "
    << r.rect.y << ", " << r.rect.width << "×" << r.rect.height << " px, the largest of the " << r.mask_pixels
    << " pixels fully covered by object " << r.object_id << " (" << (r.object_chosen ? "--object" : "the object covering most pixels")
    << ", " << r.object_pixels << " px)";
  if (r.facing_deg < 180) s << " whose surface faces the camera within " << fixed(r.facing_deg, 0) << "°";
  s << "; position layer " << fixed(r.position_px_per_cm_x, 2);
  if (r.position_px_per_cm_y != r.position_px_per_cm_x) s << "×" << fixed(r.position_px_per_cm_y, 2);
  s << " px/cm";
  if (in.albedo_from_render) s << "; albedo from its albedo layer";
  return s.str();
}

std::string input_caption(const PreparedInput& in) {
  std::ostringstream s;
  s << "<b>" << escape(in.source.label) << "</b>: " << escape(in.source.path) << "<br>" << in.field.width << "×"
    << in.field.height << " px = " << fixed(in.field.width / in.field.px_per_cm, 1) << "×"
    << fixed(in.field.height / in.field.px_per_cm, 1) << " cm (source " << fixed(in.source_px_per_cm_x, 2);
  if (in.source_px_per_cm_y != in.source_px_per_cm_x) s << "×" << fixed(in.source_px_per_cm_y, 2);
  s << " px/cm, " << origin_text(in.scale_origin) << ")";
  if (in.render) s << render_caption(in);
  return s.str();
}

// The two pictures of a pair drawn to scale: each figure's width is its share of the two
// physical widths (the gap aside), so centimetres are as long on both sides; the heights
// follow from the pictures' aspect.
std::string scaled_figure_open(const PreparedInput& in, const PreparedInput& a, const PreparedInput& b) {
  const double wa = a.field.width / a.field.px_per_cm, wb = b.field.width / b.field.px_per_cm;
  const double w = in.field.width / in.field.px_per_cm;
  char style[160];
  std::snprintf(style, sizeof style, "flex:0 0 calc((100%% - 16px) * %.6f)", w / (wa + wb));
  return "<figure class=\"to-scale\" data-width-cm=\"" + fixed(w, 3) + "\" style=\"" + style + "\">";
}

std::string size_cm(const PreparedInput& in) {
  return fixed(in.field.width / in.field.px_per_cm, 1) + " cm wide × " + fixed(in.field.height / in.field.px_per_cm, 1) +
         " cm high";
}

}  // namespace

int report_image_count(const CompareReport& r) { return 4 + (r.a.albedo ? 1 : 0) + (r.b.albedo ? 1 : 0); }

std::string report_html(const CompareReport& r) {
  const Comparison& c = r.comparison;
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>phellem compare: " << escape(r.a.source.path)
    << " vs " << escape(r.b.source.path) << "</title><style>\n"
    << "body{font-family:sans-serif;margin:24px;color:#222;max-width:1400px}"
       "h1{font-size:22px;margin:0 0 6px}h2{font-size:17px;margin:26px 0 8px;border-bottom:1px solid #ddd}"
       ".verdict{font-size:28px;font-weight:bold;padding:10px 16px;border-radius:6px;display:inline-block}"
       ".same{background:#d9f0d9;color:#1f5f1f}.close{background:#f7e7c6;color:#7a5208}.different{background:#f5d3d3;color:#7d1f1f}"
       ".pair{display:flex;gap:16px;flex-wrap:wrap}.pair figure{margin:0;flex:1 1 480px}"
       ".pair img{width:100%;height:auto;image-rendering:auto;border:1px solid #bbb}"
       "figcaption{font-size:12px;color:#444;margin-top:4px;word-break:break-all}"
       "table{border-collapse:collapse;font-size:13px}td,th{padding:4px 8px;border-bottom:1px solid #eee;text-align:left}"
       "tr.core{background:#fafaf4}.note{font-size:12px;color:#555}.key span{display:inline-block;width:12px;height:12px;"
       "margin:0 4px 0 12px;vertical-align:middle}.charts{display:flex;gap:24px;flex-wrap:wrap;align-items:flex-start}\n"
    << "</style></head><body>\n";
  s << "<h1>phellem compare</h1><div class=\"verdict " << verdict_class(c.verdict) << "\">" << escape(c.verdict)
    << " — score " << fixed(c.score, 3) << "</div>";
  s << "<p>Orientation distance (earth mover's) " << fixed(c.orientation_emd_deg, 1) << "°. Measured at a common scale of "
    << fixed(r.px_per_cm, 2) << " px/cm. The same-bark band is 0.03–" << fixed(kSameBarkScore, 2)
    << " (two halves of one scan).</p>";
  s << "<p class=\"key\"><span style=\"background:" << kColourA << "\"></span>" << escape(r.a.source.label) << ": "
    << escape(r.a.source.path) << "<span style=\"background:" << kColourB << "\"></span>" << escape(r.b.source.label) << ": "
    << escape(r.b.source.path) << "</p>";

  s << "<h2>Heights at the common scale</h2><p class=\"note\">Drawn to scale: a centimetre is as long in both.</p>"
       "<div class=\"pair\">";
  for (const PreparedInput* in : {&r.a, &r.b})
    s << scaled_figure_open(*in, r.a, r.b) << img(height_png(in->field), in->source.label + " height") << "<figcaption>"
      << size_cm(*in) << "<br>" << input_caption(*in) << "</figcaption></figure>";
  s << "</div><h2>Fissure masks</h2><div class=\"pair\">";
  const FissureAnalysis* an[2] = {&r.analysis_a, &r.analysis_b};
  const PreparedInput* ins[2] = {&r.a, &r.b};
  for (int i = 0; i < 2; ++i)
    s << scaled_figure_open(*ins[i], r.a, r.b) << img(mask_overlay_png(an[i]->field, an[i]->mask), ins[i]->source.label + " fissure mask")
      << "<figcaption>" << size_cm(*ins[i]) << "<br>" << escape(ins[i]->source.label) << ": fissures tinted ("
      << fixed(100 * an[i]->stats.fissure_fraction, 1) << " % of the area)</figcaption></figure>";
  s << "</div>";
  if (r.a.albedo || r.b.albedo) {
    s << "<h2>Albedo</h2><div class=\"pair\">";
    for (const PreparedInput* in : ins)
      if (in->albedo)
        s << "<figure>" << img(albedo_png(*in->albedo), in->source.label + " albedo") << "<figcaption>"
          << escape(in->source.label) << ": "
          << (in->albedo_from_render ? "the albedo layer of " + escape(in->source.path) : escape(in->source.albedo_path))
          << "</figcaption></figure>";
    s << "</div>";
  }
  s << "<h2>Orientation, spacing and width</h2><div class=\"charts\"><figure>" << rose(r.analysis_a.stats, r.analysis_b.stats)
    << "<figcaption>fissure direction, weighted by length (EMD " << fixed(c.orientation_emd_deg, 1)
    << "°)</figcaption></figure><figure>" << histogram(r.analysis_a.stats.spacings_h_cm, r.analysis_b.stats.spacings_h_cm, "cm")
    << "<figcaption>spacing of fissures across the trunk (share of gaps)</figcaption></figure><figure>"
    << histogram(r.analysis_a.stats.widths_cm, r.analysis_b.stats.widths_cm, "cm")
    << "<figcaption>fissure width (share of skeleton length)</figcaption></figure></div>";
  s << "<h2>Statistics</h2>" << statistics_table(r);
  s << "\n</body></html>\n";
  return s.str();
}

}  // namespace phellem

// The compare report in a real browser (Debian's chromium, headless): the page renders to a
// picture that is not blank, and every embedded image decodes. Without chromium the tests
// skip, except in CI (CI set), where the set-up script installs it and they must run.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "tests/support/height_fields.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

bool have_chromium() { return test::run_command("command -v chromium >/dev/null 2>&1").exit_code == 0; }

void require_chromium() {
  if (have_chromium()) return;
  if (std::getenv("CI")) FAIL() << "chromium is not installed but CI is set: scripts/setup.sh test installs it";
  GTEST_SKIP() << "chromium is not installed (scripts/setup.sh test installs it)";
}

std::string chromium(const std::string& dir, const std::string& what, const std::string& page) {
  return "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run "
         "--user-data-dir=" +
         dir + "/profile --hide-scrollbars --window-size=1400,2400 --virtual-time-budget=5000 " + what + " file://" + page +
         " 2>/dev/null";
}

// A report of fissured bark with albedo on both sides: 6 images.
struct Report {
  std::string dir, html;
};
const Report& report() {
  static const Report r = [] {
    Report r;
    r.dir = test::temp_dir("compare_browser");
    const float ridge[3] = {0.55f, 0.42f, 0.3f}, fissure[3] = {0.12f, 0.08f, 0.05f};
    const auto a = test::fissured_bark(40, 40, 10, 3), b = test::fissured_bark(40, 40, 8, 4);
    test::write_height_png16(r.dir + "/a.png", a);
    test::write_height_png16(r.dir + "/b.png", b);
    test::write_albedo_png(r.dir + "/a_albedo.png", a, ridge, fissure);
    test::write_albedo_png(r.dir + "/b_albedo.png", b, ridge, fissure);
    r.html = r.dir + "/report.html";
    const auto run = test::run_phellem("compare " + r.dir + "/a.png " + r.dir + "/b.png --scale A=10 --scale B=8 --albedo A=" +
                                       r.dir + "/a_albedo.png --albedo B=" + r.dir + "/b_albedo.png -o " + r.html + " --quiet");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return r;
  }();
  return r;
}

// The page with a script that marks, once everything has loaded (or failed to), how many of
// its images decoded.
std::string decoded_images(const std::string& html_text, const std::string& dir, const std::string& name) {
  const std::string probe = dir + "/" + name;
  test::write_text(probe, html_text +
                              "<script>addEventListener('load',()=>{const i=[...document.images];"
                              "document.body.setAttribute('data-decoded',"
                              "i.filter(x=>x.complete&&x.naturalWidth>0).length+'/'+i.length)})</script>");
  const auto r = test::run_command(chromium(dir, "--dump-dom", probe));
  const auto at = r.output.find("data-decoded=\"");
  if (at == std::string::npos) return "no mark (" + r.output.substr(0, 200) + ")";
  return r.output.substr(at + 14, r.output.find('"', at + 14) - at - 14);
}

TEST(CompareReportBrowser, EveryEmbeddedImageDecodes) {
  require_chromium();
  const Report& r = report();
  const std::string html = test::read_text(r.html);
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.find("http://"), std::string::npos) << "the report must not load anything";
  EXPECT_EQ(html.find("https://"), std::string::npos) << "the report must not load anything";
  EXPECT_EQ(decoded_images(html, r.dir, "probe.html"), "6/6");
  // The probe can see a broken image: spoil the second PNG's signature.
  std::string broken = html;
  const auto first = broken.find("iVBORw0KGgo");
  const auto second = broken.find("iVBORw0KGgo", first + 1);
  ASSERT_NE(second, std::string::npos);
  broken.replace(second, 11, "AAAAAAAAAAA");
  EXPECT_EQ(decoded_images(broken, r.dir, "broken.html"), "5/6");
}

TEST(CompareReportBrowser, RendersAPageThatIsNotBlank) {
  require_chromium();
  const Report& r = report();
  const std::string shot = r.dir + "/shot.png";
  test::run_command(chromium(r.dir, "--screenshot=" + shot, r.html));
  auto in = OIIO::ImageInput::open(shot);
  ASSERT_TRUE(in) << "no screenshot";
  const OIIO::ImageSpec spec = in->spec();
  EXPECT_EQ(spec.width, 1400);
  EXPECT_EQ(spec.height, 2400);
  std::vector<float> px(size_t(spec.width) * spec.height * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  std::set<int> colours;
  double sum[3] = {0, 0, 0}, sq[3] = {0, 0, 0};
  for (size_t p = 0; p < px.size() / 3; ++p) {
    int key = 0;
    for (int c = 0; c < 3; ++c) {
      const float v = px[p * 3 + c];
      key = key * 32 + std::min(31, int(v * 32));
      sum[c] += v;
      sq[c] += double(v) * v;
    }
    colours.insert(key);
  }
  EXPECT_GE(colours.size(), 500u) << "a blank or text-only page has few colours";
  const double n = double(px.size() / 3);
  for (int c = 0; c < 3; ++c) EXPECT_GT(std::sqrt(std::max(0.0, sq[c] / n - (sum[c] / n) * (sum[c] / n))), 0.03) << c;
}

}  // namespace
}  // namespace phellem

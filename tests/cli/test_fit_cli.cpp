// `phellem fit`: every mistake on the command line, in the input or in the output folder is a
// UserError (exit 2, `phellem: error: <file>: <where>: <what>`), found before any work, and
// leaves nothing behind.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/test_util.h"

namespace phellem {

namespace {

// A small 8-bit grey image of vertical stripes.
std::string stripes_png(const std::string& dir) {
  const std::string path = dir + "/stripes.png";
  const int W = 256, H = 256;
  std::vector<unsigned char> px(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) px[size_t(y) * W + x] = (x % 32) < 5 ? 40 : 200;
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(W, H, 1, OIIO::TypeDesc::UINT8);
  EXPECT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close());
  return path;
}

// size² of V-shaped grooves every 32 px: heights over a continuous range.
std::string grooves_png(const std::string& dir, int size = 256) {
  const std::string path = dir + "/grooves" + std::to_string(size) + ".png";
  const int W = size, H = size;
  std::vector<unsigned char> px(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) px[size_t(y) * W + x] = (unsigned char)(40 + 160 * std::min(1.0, std::abs(x % 32 - 16) / 10.0));
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(W, H, 1, OIIO::TypeDesc::UINT8);
  EXPECT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close());
  return path;
}

// A W×H RGB image of one colour.
std::string flat_rgb_png(const std::string& path, int W, int H) {
  std::vector<unsigned char> px(size_t(W) * H * 3);
  for (size_t i = 0; i < px.size(); i += 3) px[i] = 120, px[i + 1] = 90, px[i + 2] = 60;
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(W, H, 3, OIIO::TypeDesc::UINT8);
  EXPECT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close());
  return path;
}

void expect_error(const std::string& args, const std::string& message) {
  const auto r = test::run_phellem(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  EXPECT_NE(r.output.find("phellem: error: " + message), std::string::npos) << args << "\n" << r.output;
}

}  // namespace

TEST(FitCli, CommandLineMistakes) {
  const std::string d = test::temp_dir("fit_cli_args");
  const std::string img = stripes_png(d), out = " -o " + d + "/out";
  const std::string fit = "fit " + img + " --model strips" + out;
  for (const char* bad : {"0", "-3", "nan", "inf", "abc", "1e400", "''"})
    expect_error(fit + " --scale " + bad, "<command line>: --scale: ");
  for (const char* bad : {"0", "-1", "inf", "nan", "ten"})
    expect_error(fit + " --scale 10 --time-budget " + bad, "<command line>: --time-budget: ");
  expect_error(fit + " --scale 10 --max-evals 0", "<command line>: --max-evals: ");
  expect_error("fit " + img + " --scale 10 --model oak" + out, "<command line>: --model: unknown model \"oak\"");
  expect_error("fit " + img + " --scale 10" + out, "<command line>: --model: required");
  expect_error("fit " + img + " --scale 10 --model strips", "<command line>: -o: required");
  expect_error("fit --scale 10 --model strips" + out, "<command line>: fit: a height image is required");
  expect_error(fit + " --scale 10 --spp 4", "<command line>: --spp: ");
  expect_error(fit + " --scale 10 " + img, "<command line>: " + img + ": more than one height image given");
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

TEST(FitCli, MissingInput) {
  const std::string d = test::temp_dir("fit_cli_input");
  expect_error("fit " + d + "/missing.png --scale 10 --model strips -o " + d + "/out", d + "/missing.png: ");
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

TEST(FitCli, PlainImageNeedsAScale) {
  const std::string d = test::temp_dir("fit_cli_scale");
  const std::string img = stripes_png(d);
  expect_error("fit " + img + " --model strips -o " + d + "/out", img + ": --scale: this image states no scale");
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

TEST(FitCli, UnwritableOutputFolderIsFoundBeforeAnyWork) {
  const std::string d = test::temp_dir("fit_cli_output");
  test::write_text(d + "/file", "x");
  // The input is missing too: the output folder is checked first.
  const std::string missing = d + "/missing.png";
  expect_error("fit " + missing + " --scale 10 --model strips -o " + d + "/file", d + "/file: -o: is a file, not a folder");
  expect_error("fit " + missing + " --scale 10 --model strips -o " + d + "/file/sub", d + "/file/sub: -o: ");
  expect_error("fit " + missing + " --scale 10 --model strips -o " + d + "/no/such/dir", d + "/no/such/dir: -o: ");
  std::filesystem::create_directories(d + "/out/report.json");  // an output name taken by a folder
  expect_error("fit " + missing + " --scale 10 --model strips -o " + d + "/out", d + "/out/report.json: -o: is a folder");
}

TEST(FitCli, AlbedoMistakesAreFoundBeforeAnyWork) {
  const std::string d = test::temp_dir("fit_cli_albedo");
  const std::string img = stripes_png(d), fit = "fit " + img + " --scale 10 --model strips -o " + d + "/out --albedo ";
  expect_error(fit + d + "/missing.jpg", d + "/missing.jpg: ");
  const std::string small = flat_rgb_png(d + "/small.png", 128, 256);
  expect_error(fit + small, small + ": --albedo A: the albedo is 128×256 pixels but its height map");
  // Two height levels only: the dressing cannot tell ridges from fissures between its
  // percentiles. Refused at once (not after the search), at --albedo.
  const std::string albedo = flat_rgb_png(d + "/albedo.png", 256, 256);
  const auto t0 = std::chrono::steady_clock::now();
  expect_error(fit + albedo + " --time-budget 600", albedo + ": --albedo: the height map " + img + " is flat between its percentiles");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30.0);
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

// The fit's patches, their statistics and the report are estimated from the photo's size and
// scale before any work (cli/fit_memory.h): over the budget, the fit is refused at the photo
// with the budget named and what to change. It used to ignore --memory-limit, and under an
// address-space limit to die in std::bad_alloc (exit 1) in its first evaluations.
TEST(FitCli, AFitOverTheMemoryBudgetIsRefusedBeforeAnyWork) {
  const std::string d = test::temp_dir("fit_cli_memory");
  const std::string img = grooves_png(d, 1024);
  const std::string fit = "fit " + img + " --scale 10 --model strips -o " + d + "/out --max-evals 2";
  const auto t0 = std::chrono::steady_clock::now();
  expect_error(fit + " --memory-limit 200M", img + ": HEIGHT_IMAGE: needs about ");
  const auto r = test::run_phellem(fit + " --memory-limit 200M");
  EXPECT_NE(r.output.find("allowed (--memory-limit 200M); fit a smaller crop of the photo (now 1024×1024 px at 10 px/cm)"),
            std::string::npos)
      << r.output;
  // Under a 900 MiB address-space limit (about 400 MiB left once the libraries and threads are
  // mapped) and no --memory-limit: refused, never bad_alloc.
  const auto limited = test::run_phellem_limited(fit, 900, 60);
  EXPECT_EQ(limited.exit_code, 2) << limited.output;
  EXPECT_NE(limited.output.find("phellem: error: " + img + ": HEIGHT_IMAGE: needs about "), std::string::npos) << limited.output;
  EXPECT_NE(limited.output.find("(ulimit -v)"), std::string::npos) << limited.output;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30.0);
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

// With --albedo the fitted scene takes its colours from the photo (the dressing's `photo`
// key, absolute paths), it renders from anywhere, and the report measures the photo's colours.
TEST(FitCli, AlbedoColoursTheFittedScene) {
  const std::string d = test::temp_dir("fit_cli_albedo_run");
  const std::string img = grooves_png(d), albedo = flat_rgb_png(d + "/albedo.png", 256, 256);
  const auto r = test::run_phellem("fit " + img + " --scale 10 --model strips -o " + d + "/out --albedo " + albedo +
                                   " --max-evals 6 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto scene = nlohmann::json::parse(test::read_text(d + "/out/fitted.json"));
  nlohmann::json photo;
  for (const auto& o : scene["objects"])
    if (o["name"] == "trunk") photo = o["bark"]["dressing"]["photo"];
  ASSERT_TRUE(photo.is_object()) << scene.dump(1);
  EXPECT_EQ(photo["albedo"], std::filesystem::absolute(albedo).lexically_normal().string());
  EXPECT_EQ(photo["height"], std::filesystem::absolute(img).lexically_normal().string());
  EXPECT_DOUBLE_EQ(photo["px_per_cm"].get<double>(), 10.0);
  const auto report = nlohmann::json::parse(test::read_text(d + "/out/report.json"));
  ASSERT_TRUE(report["inputs"]["A"]["statistics"].contains("colour_L_mean")) << report["inputs"]["A"].dump(1);
  EXPECT_FALSE(report["inputs"]["B"]["statistics"].contains("colour_L_mean"));
  // The choice at the photo's scale: the lowest of the points scored again wins.
  const auto& choice = report["fit"]["choice"];
  EXPECT_DOUBLE_EQ(choice["px_per_cm"].get<double>(), 10.0);
  const auto objectives = choice["objectives"].get<std::vector<double>>();
  ASSERT_FALSE(objectives.empty());
  EXPECT_EQ(choice["chosen"].get<size_t>(), size_t(std::min_element(objectives.begin(), objectives.end()) - objectives.begin()));
  // Vertical grooves lean 0°: the spiral is searched within 4° of it.
  EXPECT_LE(std::abs(report["fit"]["parameters"]["spiral_deg"].get<double>()), 4.0 + 1e-6);
  for (const auto& o : scene["objects"])
    if (o["name"] == "trunk") {
      EXPECT_EQ(o["bark"]["depth"]["profile"], "power");
      EXPECT_NEAR(o["bark"]["depth"]["exponent"].get<double>(), report["fit"]["parameters"]["depth/exponent"].get<double>(), 1e-6);
    }
  // The scene parses from another working directory (the paths are absolute).
  const std::string moved = test::temp_dir("fit_cli_albedo_moved") + "/fitted.json";
  std::filesystem::copy_file(d + "/out/fitted.json", moved);
  const auto check = test::run_phellem("render " + moved + " --memory-estimate");
  EXPECT_EQ(check.exit_code, 0) << check.output;
}

}  // namespace phellem

namespace phellem {
namespace {

// --objective lit|both (issue 44): the relief is lit by compare --lit's rig; the photo's relief
// must be given in metres, and the report says which objective ran and how the winner lights.
TEST(FitCli, LitObjectiveMistakes) {
  const std::string d = test::temp_dir("fit_cli_lit_args");
  const std::string fit = "fit " + grooves_png(d) + " --scale 10 --model strips -o " + d + "/out";
  expect_error(fit + " --objective lit", "<command line>: --relief: required with --objective lit");
  expect_error(fit + " --objective both", "<command line>: --relief: required with --objective both");
  expect_error(fit + " --relief 0.02", "<command line>: --relief: only with --objective lit or both");
  expect_error(fit + " --objective shade --relief 0.02", "<command line>: --objective: unknown objective \"shade\"");
  for (const char* bad : {"0", "-0.01", "nan", "11"})
    expect_error(fit + " --objective lit --relief " + std::string(bad), "<command line>: --relief: ");
  EXPECT_FALSE(std::filesystem::exists(d + "/out"));
}

TEST(FitCli, LitObjectiveSearchesAndReportsTheLitScore) {
  const std::string d = test::temp_dir("fit_cli_lit_run");
  const auto r = test::run_phellem("fit " + grooves_png(d) + " --scale 10 --model strips -o " + d +
                                   "/out --objective both --relief 0.01 --max-evals 4 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto report = nlohmann::json::parse(test::read_text(d + "/out/report.json"));
  const auto& fit = report["fit"];
  EXPECT_EQ(fit["objective_kind"], "both");
  ASSERT_TRUE(fit["lit"].is_object()) << fit.dump(1);
  const double lit = fit["lit"]["objective"].get<double>();
  EXPECT_GT(lit, 0.0);
  EXPECT_LE(lit, 1.0);
  // "both" adds the lit objective to the height objective: the search's best is at least the lit part.
  EXPECT_GE(fit["objective"]["min"].get<double>(), 0.0);
  EXPECT_TRUE(fit["lit"]["verdict"].is_string());
  EXPECT_DOUBLE_EQ(fit["lit"]["relief_m"].get<double>(), 0.01);
}

}  // namespace
}  // namespace phellem

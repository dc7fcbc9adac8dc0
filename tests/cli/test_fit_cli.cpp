// `phellem fit`: every mistake on the command line, in the input or in the output folder is a
// UserError (exit 2, `phellem: error: <file>: <where>: <what>`), found before any work, and
// leaves nothing behind.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>

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

}  // namespace phellem

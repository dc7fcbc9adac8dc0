// compare/fissure_statistics: every refusal of analyse_fissures (plan §3.0) is a UserError
// naming the input and saying what is wrong and what is allowed; the limits themselves pass.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "compare/fissure_statistics.h"
#include "tests/compare/synthetic_fields.h"
#include "tests/support/test_util.h"

namespace phellem {
namespace {

using test::expect_user_error;

HeightField stripes_of(int w, int h, double s) {
  HeightField f = test::stripes(std::max(w, h), s, 32, 5);
  HeightField out{w, h, s, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.z.push_back(f.at(x, y));
  return out;
}

TEST(AnalyseErrors, TooFewPixelsOnASide) {
  expect_user_error([] { analyse_fissures(stripes_of(120, 600, 5), nullptr, "a.png"); }, "120 px wide", "a.png", "",
                    "the image is 120×600 px (24×120 cm at 5 px/cm); compare needs at least 128 px and 20 cm on each side");
}

TEST(AnalyseErrors, TooFewCentimetresOnASide) {
  expect_user_error([] { analyse_fissures(stripes_of(300, 300, 20), nullptr, "b.exr"); }, "15 cm", "b.exr", "",
                    "(15×15 cm at 20 px/cm); compare needs at least 128 px and 20 cm on each side");
}

TEST(AnalyseErrors, TooCoarse) {
  expect_user_error([] { analyse_fissures(stripes_of(512, 512, 1.5), nullptr, "c.png"); }, "1.5 px/cm", "c.png", "",
                    "the scale is 1.5 px/cm; compare needs at least 2 px/cm");
}

TEST(AnalyseErrors, ConstantRelief) {
  HeightField flat{256, 256, 10, std::vector<float>(256 * 256, 0.25f)};
  expect_user_error([&] { analyse_fissures(flat, nullptr, "flat.png"); }, "constant", "flat.png", "",
                    "the relief is constant (every height is 0.25); compare needs a height field with fissures");
}

TEST(AnalyseErrors, NonFiniteHeights) {
  HeightField f = stripes_of(256, 256, 10);
  f.z[1000] = std::numeric_limits<float>::quiet_NaN();
  expect_user_error([&] { analyse_fissures(f, nullptr, "nan.exr"); }, "NaN", "nan.exr", "", "NaN or infinite");
}

TEST(AnalyseErrors, AlbedoOfAnotherSize) {
  AlbedoField albedo{100, 100, std::vector<float>(100 * 100 * 3, 0.5f)};
  expect_user_error([&] { analyse_fissures(stripes_of(256, 256, 10), &albedo, "h.png"); }, "albedo", "h.png", "",
                    "the albedo is 100×100 px but the heights are 256×256");
}

TEST(AnalyseErrors, TheLimitsThemselvesAreAccepted) {
  EXPECT_NO_THROW(analyse_fissures(stripes_of(200, 200, 10), nullptr, "20cm.png"));        // 20 cm, 200 px
  EXPECT_NO_THROW(analyse_fissures(stripes_of(128, 128, 6.4), nullptr, "128px.png"));      // 128 px, 20 cm
  EXPECT_NO_THROW(analyse_fissures(stripes_of(128, 128, 2), nullptr, "2pxcm.png"));        // 2 px/cm
}

}  // namespace
}  // namespace phellem
